"""Sweeps: a protocol replayed over arrays of givens equals scalar replays, and every check holds across it.

The property tests run every registered construction over 1000 rod ratios
in (1.01, 50] with one sweep each, then check every set of givens with the
construction's own checks (the analytic formulas), and watch every
intersection for a branch switch between neighbouring ratios.

The checks of a sweep run through ``Construction.sweep_checks``: what they
integrate from the givens (the exact model) is computed for all 1000 sets in
one numpy pass, what they measure is read off each set.  Another test holds
the checks of a sweep of the sampled ratios equal to each set's own scalar checks.  The sweeps are
made once per session (``rod_ratio_sweep`` in conftest.py).
"""

from __future__ import annotations

import numpy as np
import pytest

from construct import Figure, get, names
from construct.kernel.geometry import ARRAY, Circle, Line, circle_circle, line_circle, take
from construct.kernel.instruments import unlettered
from construct.kernel.rules import as_rule

RATIOS = np.linspace(1.01, 50.0, 1001)[1:]  # 1000 ratios in (1.01, 50]
with unlettered():  # (the givens only: a build without its letters, a fifth of the cost, in every worker's collection)
    SWEPT = [n for n in names() if get(n).rod_ratio_sweep(get(n).figure().replay.givens, RATIOS[:1]) is not None]
SAMPLED = (0, 1, 137, 500, 998, 999)


def test_every_construction_with_a_rod_is_swept():
    assert {"crank", "crank-angle", "inertia-curve", "piston-force", "tangential-pressure", "two-cranks"} <= set(SWEPT)


def _stroke(fig) -> float:
    g = fig.replay.givens
    return 2.0 * fig.replay["O"].distance(fig.replay["D0"]) if "O" in fig.replay and "D0" in fig.replay else 2.0 * g["r"]


@pytest.fixture(scope="module")
def swept_checks(rod_ratio_sweep):
    """The checks of every set of the 1,000-ratio sweep, per construction: the model in one numpy pass."""
    made = {}

    def checks(name):
        if name not in made:
            c, fig, sweep = rod_ratio_sweep(name, RATIOS)
            made[name] = c.sweep_checks(Figure(fig.protocol, sweep))
        return made[name]

    return checks


@pytest.mark.parametrize("name", SWEPT)
def test_every_check_holds_over_a_thousand_rod_ratios(name, swept_checks):
    per_set = swept_checks(name)
    assert len(per_set) == RATIOS.size
    failed = []
    for i, checks in enumerate(per_set):
        assert checks, f"L/r = {RATIOS[i]:.4f}: no checks"
        for ch in checks:
            if not ch.ok:
                failed.append(f"L/r = {RATIOS[i]:.4f}: {ch.name} error {ch.error:.3g} > {ch.tolerance:.3g}")
    assert not failed, f"{len(failed)} checks fail, e.g. {failed[:5]}"


@pytest.mark.parametrize("name", SWEPT)
def test_a_sweeps_checks_are_the_checks_of_each_set(name, rod_ratio_sweep):
    """The sweep's model (arrays, one pass) gives, set by set, the checks the set's own figure gives (scalars).

    The sweep is of the sampled ratios of the 1,000 (both ends among them): the model is computed set by set on
    arrays whatever their length, and the test then does not need the 1,000 sets' checks in whichever worker
    process runs it."""
    c, fig, sweep = rod_ratio_sweep(name, RATIOS[list(SAMPLED)])
    per_set = c.sweep_checks(Figure(fig.protocol, sweep))
    for i in range(len(SAMPLED)):
        single = c.check(Figure(fig.protocol, sweep.take(i)))
        assert [ch.name for ch in per_set[i]] == [ch.name for ch in single], i
        for a, b in zip(per_set[i], single):
            assert a.measured == b.measured or abs(a.measured - b.measured) <= 1e-12 * max(1.0, abs(b.measured)), \
                (i, b.name)
            for x, y in ((a.expected, b.expected), (a.tolerance, b.tolerance)):
                assert x == y or abs(x - y) <= 1e-12 * max(1.0, abs(y)), (i, b.name, x, y)
            assert (a.ok, a.unit) == (b.ok, b.unit), (i, b.name)


@pytest.mark.parametrize("name", SWEPT)
def test_sweep_equals_scalar_replays_at_sampled_points(name, rod_ratio_sweep):
    c, fig, sweep = rod_ratio_sweep(name, RATIOS)
    stroke = _stroke(fig)
    givens = c.rod_ratio_sweep(dict(fig.replay.givens), RATIOS)
    for i in SAMPLED:
        single = fig.protocol.replay({k: take(v, i) for k, v in givens.items()})
        set_i = sweep.take(i)
        for obj_name, value in single.items():
            swept = set_i[obj_name]
            for a, b in zip(_coords(value), _coords(swept)):
                assert abs(a - b) <= 1e-12 * stroke, (obj_name, i, a, b)


def _coords(v):
    if isinstance(v, float):
        return [v]
    if hasattr(v, "x") and hasattr(v, "y"):
        return [v.x, v.y]
    if isinstance(v, Line):
        return [*_coords(v.p), *_coords(v.q)]
    if isinstance(v, Circle):
        return [*_coords(v.center), v.radius]
    if hasattr(v, "value"):
        return [v.value]
    if hasattr(v, "points"):
        return [c for p in v.points for c in _coords(p)]
    if hasattr(v, "pieces"):
        return [c for _, ring in v.pieces for p in ring for c in _coords(p)]
    raise TypeError(type(v))


def branch_jumps(protocol, sweep, scale):
    """Where a chosen intersection jumps to the other candidate between neighbouring sets of givens.

    The two candidates are recomputed, independently of the rule, from the
    swept curves.  Where the chosen point changes from one candidate to the
    other, the change must be a crossing -- the two candidates meet in between
    (an ordinate passing through zero, a tangency) and the point moves no more
    than at the neighbouring steps -- not a jump across the chord.
    """
    xp = type(ARRAY)(sweep.size)
    ones = np.ones(sweep.size)
    problems, checked = [], 0
    for step in protocol.steps:
        if step.op != "intersect":
            continue
        c1, c2 = (sweep[n] for n in step.inputs)
        if not all(isinstance(o, (Line, Circle)) for o in (c1, c2)) or isinstance(c1, Line) and isinstance(c2, Line):
            continue
        if isinstance(c1, Circle) and isinstance(c2, Circle):
            a, b = circle_circle(c1, c2, xp)
        else:
            line, circle = (c1, c2) if isinstance(c1, Line) else (c2, c1)
            a, b = line_circle(line, circle, xp)
        chosen = sweep[step.outputs[0]]
        cx, cy = chosen.x * ones, chosen.y * ones
        side = np.hypot(cx - a.x, cy - a.y) > np.hypot(cx - b.x, cy - b.y)  # True: the chosen point is b
        jump = np.hypot(np.diff(cx), np.diff(cy))
        for i in np.flatnonzero(side[1:] != side[:-1]):
            around = max(jump[i - 1] if i > 0 else 0.0, jump[i + 1] if i + 1 < jump.size else 0.0)
            if jump[i] > 4.0 * around + 1e-12 * scale:
                problems.append(f"step {step.index} ({step.caption.en}) jumps by {jump[i]:.3g} "
                                f"(neighbours {around:.3g}) at set {i}")
        checked += 1
    return problems, checked


@pytest.mark.parametrize("name", SWEPT)
def test_no_intersection_switches_branch_between_neighbouring_ratios(name, rod_ratio_sweep):
    c, fig, sweep = rod_ratio_sweep(name, np.linspace(1.02, 50.0, 2000))
    problems, checked = branch_jumps(fig.protocol, sweep, _stroke(fig))
    assert checked > 0
    assert not problems, problems[:3]


def test_the_branch_test_finds_a_jump():
    """A rule whose reference crosses the line of centres makes the point jump across the chord: seen."""
    from construct import Builder, nearer

    b = Builder("jumping", givens={"k": 1.0})
    b.given_point("O", 0.0, 0.0)
    b.given_point("Q", 1.0, 0.0)
    b.given_point("R", 0.5, 1.0, unit="k")  # above the line of centres for k > 0, below for k < 0
    b.circle_through("k1", "O", "Q")
    b.circle_through("k2", "Q", "O")
    b.intersect("X", "k1", "k2", rule=nearer("R"))
    proto = b.protocol()
    problems, checked = branch_jumps(proto, proto.replay({"k": np.linspace(-1.0, 1.0, 400)}), 1.0)
    assert checked == 1 and problems
    smooth, _ = branch_jumps(proto, proto.replay({"k": np.linspace(0.1, 1.0, 400)}), 1.0)
    assert not smooth


def test_sweep_accepts_lists_and_validates_in_construction_replay():
    c = get("crank")
    fig = c.figure(parts=6)
    swept = c.replay(fig.protocol, rod_ratio=[3.0, 4.0, 5.0])
    assert swept.replay.size == 3
    with pytest.raises(Exception, match="greater than 1"):
        c.replay(fig.protocol, rod_ratio=[3.0, 0.5])


def test_a_sweep_names_the_step_and_the_failing_set_when_circles_do_not_meet():
    from construct.kernel.errors import NoIntersection

    fig = get("crank").figure(parts=6)
    g = dict(fig.replay.givens)
    with pytest.raises(NoIntersection, match=r"step \d+ .*first at index 1"):
        # a rod of 0.5 r cannot reach the stroke line from the top of the crank circle
        fig.protocol.replay({**g, "rod_ratio": np.array([4.0, 0.5, 3.0])})


def test_rules_choose_element_by_element():
    rule = as_rule(["left", "A", "B"])
    assert rule.name == "left" and rule.refs == ("A", "B")


def test_a_set_taken_from_a_sweep_holds_every_object_of_that_set(rod_ratio_sweep):
    """Replay.take looks objects up lazily: the set still has every name, each object equal to its own take,
    and it pickles and compares as a plain replay of its objects."""
    import pickle

    c, fig, sweep = rod_ratio_sweep("crank", RATIOS)
    one = sweep.take(137)
    assert set(one) == set(sweep) and len(one) == len(sweep)
    for name in sweep:
        assert one[name] == take(sweep[name], 137), name
    assert "no such object" not in one and one.get("no such object") is None
    again = pickle.loads(pickle.dumps(one))
    assert dict(again.items()) == dict(one.items()) and again.givens == one.givens


# -- every op on arrays -----------------------------------------------------------------------------------------

#: Each book construction, and the variants that reach the ops its default figure does not (the dividers'
#: trial, the marked ruler, the revolution's corners): every op of the table a book construction uses.
BOOK_FIGURES = [(n, {}) for n in names()] + [
    ("crank", {"parts": 7, "method": "dividers"}), ("crank", {"parts": 9, "method": "neusis"}),
    ("inertia-curve", {"parts": 7, "method": "dividers"}), ("tangential-pressure", {"revolution": True}),
    ("piston-force", {"revolution": True}),
]


def _few_sets(c, fig):
    """Givens for a sweep of four sets: rod ratios far apart (the order of points changes) and, where the figure
    has a unit r, other units (the dividers' trial and the marked ruler work on the crank circle)."""
    givens = dict(fig.replay.givens)
    swept = c.rod_ratio_sweep(givens, [1.3, 3.0, 7.5, 60.0]) or givens
    return {**swept, "r": np.array([0.8, 1.0, 1.7, 3.0]) * givens["r"]} if "r" in givens else swept


def assert_sets_equal_their_replays(protocol, givens):
    """Each set of the sweep of *givens* holds every object its own scalar replay makes, to 1e-12 of the largest
    number that replay holds (a coordinate, or an area's reading); return the sweep."""
    sweep = protocol.replay(givens)
    for i in range(sweep.size):
        single = protocol.replay({k: take(v, i) for k, v in givens.items()})
        set_i = sweep.take(i)
        assert set(set_i) == set(single)
        numbers = {name: _coords(value) for name, value in single.items()}
        scale = max((abs(c) for cs in numbers.values() for c in cs), default=1.0)
        for name, a in numbers.items():
            b = _coords(set_i[name])
            assert len(a) == len(b), (name, i)
            worst = max((abs(x - y) for x, y in zip(a, b)), default=0.0)
            assert worst <= 1e-12 * scale, (name, i, worst, scale)
    return sweep


@pytest.mark.parametrize("name, params", BOOK_FIGURES, ids=[f"{n}{'-' + '-'.join(map(str, p.values())) if p else ''}"
                                                          for n, p in BOOK_FIGURES])
def test_every_op_of_a_book_figure_runs_on_arrays_and_gives_each_sets_replay(name, params):
    """No op of a book construction runs element by element in a sweep (Replay.elementwise names those that do);
    each op's array form gives, set by set, what the scalar replay of that set gives."""
    c = get(name)
    fig = c.figure(**params)
    givens = _few_sets(c, fig)
    sweep = assert_sets_equal_their_replays(fig.protocol, givens)
    assert sweep.elementwise == (), f"ran element by element in a sweep: {', '.join(sweep.elementwise)}"


def test_an_op_without_an_array_form_runs_element_by_element_and_is_named():
    """What Replay.elementwise reports: an op marked vector=False runs once per set, and the sweep says which."""
    import dataclasses

    from construct.kernel import ops

    from construct.kernel.protocol import Protocol

    text = get("crank").figure(parts=6).protocol.to_json()
    with pytest.MonkeyPatch.context() as mp:
        mp.setitem(ops.OPS, "polyline", dataclasses.replace(ops.OPS["polyline"], vector=False))
        proto = Protocol.from_json(text)  # compiled with the op table as it is now
        sweep = assert_sets_equal_their_replays(proto, {"r": 1.0, "rod_ratio": np.array([3.0, 5.0])})
    assert sweep.elementwise == ("polyline",)


def _builder_sweep(build, values):
    """A small protocol built by *build* (a Builder with the given k), replayed over k = *values*."""
    from construct import Builder

    b = Builder("probe", givens={"k": float(values[0])})
    build(b)
    return assert_sets_equal_their_replays(b.protocol(), {"k": np.asarray(values, dtype=float)})


def test_a_french_curve_whose_points_change_their_order_along_the_axis():
    """The points are sorted along the axis in each set on its own: P passes Q as k grows."""
    from construct import nearer

    def build(b):
        b.given_point("O", 0.0, 0.0)
        b.given_point("X", 1.0, 0.0)
        axis = b.line("axis", "O", "X")
        pts = [b.given_point("A", 0.0, 0.0), b.given_point("P", 0.5, 1.0, unit="k"), b.given_point("Q", 1.5, 0.5),
               b.given_point("B", 3.0, 0.2)]
        b.french_curve("curve", axis, pts, {})
        b.given_point("T", 1.0, -1.0)
        b.given_point("U", 1.0, 3.0)
        b.line("cut", "T", "U")
        b.intersect("Y", "curve", "cut", rule=nearer("U"))

    _builder_sweep(build, [0.5, 1.0, 2.0, 3.5, 5.0])


def test_curves_crossed_where_their_pieces_meet_and_both_crossings():
    """A line through a point where two pieces of a curve meet finds it once (a polyline's vertex, a French
    curve's point ends one Bézier segment and starts the next), so that ``both`` gives the other crossing, in
    each set as in its replay."""
    from construct import toward

    def build(b):
        b.given_point("O", 0.0, 0.0)
        b.given_point("X", 1.0, 0.0)
        b.line("axis", "O", "X")
        pts = [b.given_point("A", 0.0, 0.0), b.given_point("B", 1.0, 1.0, unit="k"), b.given_point("C", 2.0, 0.0),
               b.given_point("D", 3.0, 1.0)]
        b.polyline("zigzag", pts)
        b.french_curve("wave", "axis", pts, {})
        b.given_point("Z", 3.5, 0.2)
        b.line("through_B", "B", "Z")  # through B exactly: B is a vertex, and a point of the French curve
        left = toward(dx=-1.0, dy=0.0)
        b.intersect(("P1", "P2"), "zigzag", "through_B", rule=left)  # B first, then the next crossing
        b.intersect(("W1", "W2"), "wave", "through_B", rule=left)

    sweep = _builder_sweep(build, [0.6, 0.8, 1.0])  # B the first crossing from the left (at 1.2 it is not)
    for name in ("P", "W"):  # the second crossing is another point, not B found again
        b_x, second_x = sweep["B"].x, sweep[f"{name}2"].x
        assert np.all(np.abs(second_x - b_x) > 0.1), (name, b_x, second_x)


def test_a_sweep_names_the_first_set_where_a_drawn_curve_misses_its_line():
    from construct import Builder, nearer
    from construct.kernel.errors import NoIntersection

    b = Builder("probe", givens={"k": 0.5})
    pts = [b.given_point("A", 0.0, 0.0), b.given_point("B", 1.0, 1.0), b.given_point("C", 2.0, 0.0)]
    b.polyline("roof", pts)
    b.given_point("L", -1.0, 1.0, unit="k")
    b.given_point("R", 3.0, 1.0, unit="k")
    b.line("level", "L", "R")  # at height k: above the roof's ridge for k > 1
    b.intersect("X", "roof", "level", rule=nearer("L"))
    with pytest.raises(NoIntersection, match=r"step \d+ .*for 2 of 4 sets of givens, first at index 2"):
        b.protocol().replay({"k": np.array([0.25, 0.5, 1.5, 2.0])})
