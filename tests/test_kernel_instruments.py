"""Composite steps made of compass and straightedge only, checked against plain coordinates."""

import math

import pytest

from construct.kernel.instruments import Builder

PRIMITIVE_TOOLS = {"given", "straightedge", "compass", "intersect"}


def builder_with(**points):
    b = Builder("demo", givens={})
    for name, (x, y) in points.items():
        b.given_point(name, x, y)
    return b


@pytest.mark.parametrize("n", [2, 3, 5, 7, 10])
def test_divide_segment_by_the_intercept_theorem(n):
    b = builder_with(A=(0.3, -1.2), B=(4.1, 2.2))
    pts = b.divide_segment("T", "A", "B", n)
    for k, name in enumerate(pts, start=1):
        assert b[name].x == pytest.approx(0.3 + 3.8 * k / n, abs=1e-12)
        assert b[name].y == pytest.approx(-1.2 + 3.4 * k / n, abs=1e-12)
    assert {s.tool for s in b.steps} <= PRIMITIVE_TOOLS


def test_midpoint_and_perpendicular_bisector():
    b = builder_with(A=(1.0, 1.0), B=(5.0, 3.0))
    m = b.midpoint("M", "A", "B")
    assert (b[m].x, b[m].y) == pytest.approx((3.0, 2.0), abs=1e-12)


def test_erect_perpendicular_is_perpendicular():
    b = builder_with(A=(0.0, 0.0), B=(3.0, 1.0))
    g = b.line("g", "A", "B")
    mid = b.divide_segment("T", "A", "B", 3, line=g, only=[1])[0]
    perp = b.erect_perpendicular("p", mid, g, "A")
    (px, py), (qx, qy) = b[perp]
    assert (qx - px) * 3.0 + (qy - py) * 1.0 == pytest.approx(0.0, abs=1e-12)


def test_parallel_through_a_point():
    b = builder_with(A=(0.0, 0.0), B=(2.0, 1.0), P=(0.5, 3.0))
    par = b.parallel_through("q", "P", "A", "B")
    (px, py), (qx, qy) = b[par]
    assert (qx - px) * 1.0 - (qy - py) * 2.0 == pytest.approx(0.0, abs=1e-12)
    assert (px, py) == (0.5, 3.0)


def test_bisect_arc_and_copy_arc():
    b = Builder("demo", givens={"r": 1.0})
    O = b.given_point("O", 0.0, 0.0)
    r = b.given_length("r", product=("r",))
    k = b.circle_radius("k", O, r)
    b.given_point("A", 1.0, 0.0)
    b.given_point("B", math.cos(1.0), math.sin(1.0))
    m = b.bisect_arc("M", O, "A", "B", k)
    assert math.atan2(b[m].y, b[m].x) == pytest.approx(0.5, abs=1e-12)
    c = b.copy_arc("C", k, "B", "A", "B", away_from="A")
    assert math.atan2(b[c].y, b[c].x) == pytest.approx(2.0, abs=1e-12)


def test_bisect_angle():
    b = builder_with(V=(1.0, 1.0), A=(4.0, 1.0), B=(1.0 + 2 * math.cos(1.2), 1.0 + 2 * math.sin(1.2)))
    w = b.bisect_angle("w", "V", "A", "B")
    (px, py), (qx, qy) = b[w]
    assert math.atan2(qy - py, qx - px) == pytest.approx(0.6, abs=1e-12)


def test_dividers_step_off_pricks_a_point_at_the_opening():
    b = Builder("demo", givens={"r": 1.0, "e": 0.3})
    O = b.given_point("O", 0.0, 0.0)
    k = b.circle_radius("k", O, b.given_length("r", product=("r",)))
    b.given_point("A", -1.0, 0.0)
    b.given_point("B", 1.0, 0.0)
    e = b.given_length("e", product=("e",))
    p = b.step_off("P", k, "A", e, rule=("left", "A", "B"))
    assert b[p].distance(b["A"]) == pytest.approx(0.3, abs=1e-15) and b[p].y > 0
    assert b.steps[-1].tool == "dividers"


def test_drop_perpendicular_and_its_foot():
    b = builder_with(A=(0.0, 0.0), B=(4.0, 2.0), P=(1.0, 3.0))
    g = b.line("g", "A", "B")
    perp, foot = b.drop_perpendicular("l", "P", g, "A", "B")
    # foot of (1, 3) on the line through (0, 0) in direction (2, 1): t = (2 + 3) / 5 = 1 -> (2, 1)
    assert (b[foot].x, b[foot].y) == pytest.approx((2.0, 1.0), abs=1e-12)
    (px, py), (qx, qy) = b[perp]
    assert (qx - px) * 2.0 + (qy - py) * 1.0 == pytest.approx(0.0, abs=1e-12)
    assert {s.tool for s in b.steps} <= PRIMITIVE_TOOLS


def test_dropping_a_perpendicular_from_a_point_on_the_line_names_the_step():
    from construct.kernel.errors import StepError

    b = builder_with(A=(0.0, 0.0), B=(4.0, 2.0), P=(2.0, 1.0))
    g = b.line("g", "A", "B")
    with pytest.raises(StepError, match="step"):
        b.drop_perpendicular("l", "P", g, "A", "B")


def test_a_parallel_is_called_by_what_its_direction_is():
    """Brauer's steps draw parallels to the 45° line O′W, whose W lies far off: the step says "to the 45 degree
    line", not a point the view does not show."""
    b = builder_with(O=(0.0, 0.0), W=(1.0, 1.0), P=(3.0, 0.5))
    par = b.parallel_through("s", "P", "O", "W", along=("zur 45°-Linie", "to the 45 degree line"))
    made = [s for s in b.steps if s.outputs == (par,)][0]
    assert made.group[-1] == "parallel to the 45 degree line through P"
    b.intersect("X", par, b.line("g", "O", "P"), rule=("only",))
    assert b.protocol().steps[-1].caption.en == "X where the parallel to the 45 degree line through P meets the line OP"
    plain = b.parallel_through("t", "P", "O", "W")
    assert [s for s in b.steps if s.outputs == (plain,)][0].group[-1] == "parallel to OW through P"


def test_a_builders_replay_at_its_own_givens_is_what_it_made_bit_for_bit():
    """Builder.replay hands back the built objects instead of running the steps again: they must be the replay's
    own, to the last bit, for every construction (its first book figure), and other givens are replayed."""
    import pickle

    from construct.constructions import get, names

    for name in names():
        c = get(name)
        fig = c.figure(**dict((c.book_params or ({},))[0]))
        again = fig.protocol.replay(dict(fig.replay.givens))
        assert list(fig.replay) == list(again), name
        assert pickle.dumps(dict(fig.replay)) == pickle.dumps(dict(again)), name
        assert dict(fig.replay.givens) == dict(again.givens), name
    b = Builder("demo", givens={"s": 2.0})
    b.given_point("A", 0.0, 0.0)
    b.given_length("s", product=("s",))
    b.circle_radius("k", "A", "s")
    p = b.protocol()
    assert b.replay(p)["k"].radius == 2.0 and "program" not in p.__dict__  # (nothing compiled: the built objects)
    assert b.replay(p, {"s": 3.0})["k"].radius == 3.0  # other givens: replayed
    other = builder_with(A=(0.0, 0.0)).protocol()
    assert b.replay(other) is not None and list(b.replay(other)) == ["A"]  # another builder's protocol: replayed


def test_an_unlettered_builds_protocol_replays_a_sweep_of_its_givens():
    """An unlettered build's protocol is a live player's piece (construct.live.sweep.pieces): swept over arrays of
    its givens it replays them, as a lettered build's does (its own givens: what the build made)."""
    import numpy as np

    from construct.kernel.instruments import unlettered

    def build():
        b = Builder("demo", givens={"s": 2.0})
        b.given_point("A", 0.0, 0.0)
        b.given_point("B", 1.0, 0.0, unit="s")
        b.circle_through("k", "A", "B")
        return b.protocol()

    with unlettered():
        sketch = build()
    radii = sketch.replay({"s": np.array([1.5, 3.0])})["k"].radius
    assert list(radii) == [1.5, 3.0]  # |AB| = s
    assert sketch.replay({"s": 2.0})["k"].radius == 2.0 == sketch.replay()["k"].radius
