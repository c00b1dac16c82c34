"""Sweeps: a protocol replayed over arrays of givens equals scalar replays, and every check holds across it.

The property tests run every registered construction over 1000 rod ratios
in (1.01, 50] with one sweep each, then check every set of givens with the
construction's own checks (the analytic formulas), and watch every
intersection for a branch switch between neighbouring ratios.

The checks of a sweep run through ``Construction.sweep_checks``: what they
integrate from the givens (the exact model) is computed for all 1000 sets in
one numpy pass, what they measure is read off each set.  Another test holds
those checks equal to each sampled set's own scalar checks.  The sweeps are
made once per session (``rod_ratio_sweep`` in conftest.py).
"""

from __future__ import annotations

import numpy as np
import pytest

from construct import Figure, get, names
from construct.kernel.geometry import ARRAY, Circle, Line, circle_circle, line_circle, take
from construct.kernel.rules import as_rule

RATIOS = np.linspace(1.01, 50.0, 1001)[1:]  # 1000 ratios in (1.01, 50]
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
def test_a_sweeps_checks_are_the_checks_of_each_set(name, rod_ratio_sweep, swept_checks):
    """The sweep's model (arrays, one pass) gives, set by set, the checks the set's own figure gives (scalars)."""
    c, fig, sweep = rod_ratio_sweep(name, RATIOS)
    per_set = swept_checks(name)
    for i in SAMPLED:
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
