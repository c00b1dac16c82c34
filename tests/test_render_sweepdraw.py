"""The drawing over a whole sweep at once (render/sweepdraw.py) against the drawing one value at a time.

The reference is the scalar path: the scene of each value and the drawing's own mark geometry
(``Measure`` of construct.live, itself held to the player page in
tests/test_live.py).  The values spread over the whole stated domain of the rod ratio,
past the broken axis and close to L/r = 1.
"""

from __future__ import annotations

import numpy as np
import pytest

from construct.constructions import get
from construct.live import Measure
from construct.figure import Figure
from construct.render.output import scene_for
from construct.render.styles import STYLES
from construct.render.sweepdraw import SweepDrawing, SweepForm, _rows, sweep_drawable

VALUES = np.concatenate([10 ** np.linspace(np.log10(1.05), 3.0, 37), [1.06, 4.0, 5.0]])


def _sweep(name: str, params: dict):
    c = get(name)
    built = c.figure(**params)
    replay = built.protocol.replay(c.rod_ratio_sweep(dict(built.replay.givens), VALUES))
    return c, built, replay


class OneByOne:
    """What the drawing draws at a sweep's value measured alone (the scalar path: the value's scene, the drawing's
    mark geometry), made once per figure and value: both tests here read the same values of the same figures (a
    value's scene takes a fifth of a second, a figure's Measure a second)."""

    def __init__(self):
        self.measures: dict[tuple, Measure] = {}
        self.made: dict[tuple, tuple] = {}

    def measure(self, c, built) -> Measure:
        key = (c.name, repr(sorted(built.params.items())))
        if key not in self.measures:
            self.measures[key] = Measure(c, built, STYLES["teaching"])
        return self.measures[key]

    def at(self, c, built, replay, i: int) -> tuple:
        """The measure of the sweep *replay*'s value *i*, as a figure of its own."""
        one = replay.take(i, whole=True)
        key = (c.name, repr(sorted(built.params.items())), repr(sorted(one.givens.items())))
        if key not in self.made:
            self.made[key] = self.measure(c, built)(Figure(built.protocol, one, c.check))
        return self.made[key]


@pytest.fixture(scope="module")
def one_by_one() -> OneByOne:
    return OneByOne()


@pytest.mark.parametrize("kept", [False, True])
@pytest.mark.parametrize("name, params", [("crank", {"parts": 6}), ("crank", {"parts": 18}), ("inertia-curve", {}),
                                          ("piston-force", {}), ("tangential-pressure", {"parts": 6})])
def test_every_mark_is_drawn_where_the_drawing_draws_it_value_by_value(name, params, kept, one_by_one):
    """*kept*: with the form (what is drawn whatever the values) made from another sweep of the protocol, at other
    values (a live player's earlier round), as live.measure keeps it: what it draws at these values is still theirs."""
    c, built, replay = _sweep(name, params)
    scene, form = scene_for(c, built), None
    if kept:
        other = built.protocol.replay(c.rod_ratio_sweep(dict(built.replay.givens), np.array([1.3, 7.0, 300.0])))
        form = SweepForm(scene, built.protocol, other, STYLES["teaching"])
    drawn = SweepDrawing(scene, built.protocol, replay, len(VALUES), STYLES["teaching"], form=form)
    assert drawn.form is form or not kept
    assert drawn.ok.mean() >= 0.9  # where it is not sure (a mark changing its form), the caller draws
    for i in np.flatnonzero(drawn.ok):
        keys, nums, fit, _ = one_by_one.at(c, built, replay, int(i))
        at, by_mark = 0, {}
        for k in keys:
            n = k[2].count("#")
            by_mark.setdefault(k[0], []).extend(nums[at:at + n])
            at += n
        for mid, got in drawn.numbers.items():
            # numpy rounds x * 100, the writer the exact decimal: at most a unit of the last written digit
            assert np.abs(np.asarray(by_mark[mid]) - got[i]).max() <= 0.0101, (VALUES[i], mid)
        assert np.allclose(drawn.fit[i], fit, rtol=1e-12, atol=1e-9)
        assert by_mark["figure"][3] == pytest.approx(drawn.size[1][i], abs=0.0051)


@pytest.mark.parametrize("name, params", [("inertia-curve", {}), ("piston-force", {}), ("crank-angle", {})])
def test_a_sweeps_frames_are_the_frames_of_each_value(name, params, one_by_one):
    """Measure.frames (the sweep at once where it can, value by value where not) gives each value's frame:
    the same keys, numbers within the last written digit (views too: they are carried from the same
    boxes), the same fit and letters (crank-angle's are angles read off the figure, on its lettered lines)."""
    c = get(name)
    built = c.figure(**params)
    values = VALUES[::4]
    swept = c.rod_ratio_sweep(dict(built.replay.givens), values)
    if swept is None:
        pytest.skip(f"{name} has no rod ratio to sweep")
    replay = built.protocol.replay(swept)
    frames = one_by_one.measure(c, built).frames(built.protocol, replay, len(values))
    for i, (keys, nums, fit, texts) in enumerate(frames):
        want = one_by_one.at(c, built, replay, i)
        assert keys == want[0]
        assert np.abs(np.asarray(nums) - np.asarray(want[1])).max() <= 0.0101
        assert np.allclose(fit, want[2], rtol=1e-12, atol=1e-9)
        assert texts == want[3]


def test_a_figure_with_hatched_areas_is_left_to_the_drawing():
    """An area is drawn over the sweep as its ring of points; its hatching (a style that hatches) has as many
    lines as the area's size holds at each value: drawn value by value -- unless the caller draws no hatching
    (a live page draws its areas from their curves)."""
    c = get("tangential-pressure")
    scene = scene_for(c, c.figure(parts=6))
    assert not sweep_drawable(scene, STYLES["historical"]) and not sweep_drawable(scene, STYLES["teaching"])
    assert sweep_drawable(scene, STYLES["teaching"], hatching=False)
    assert sweep_drawable(scene_for(get("crank"), get("crank").figure(parts=3)))


def _walk(spans: list[tuple[float, float]]) -> tuple[float, float, float, float] | None:
    """The scalar walk of sheet._widest_gap, written out again: the spans sorted by start then end, each stretch
    past the running end a gap; (start, end, width, extent as the walk reads it) of the widest, or None."""
    ivals = sorted(spans)
    total = ivals[-1][1] - ivals[0][0]
    best, reach = None, ivals[0][1]
    for a, b in ivals[1:]:
        if a > reach and (best is None or a - reach > best[1] - best[0]):
            best = (reach, a)
        reach = max(reach, b)
    return None if best is None else (best[0], best[1], best[1] - best[0], total)


def test_the_widest_gaps_of_a_sweep_are_the_scalar_walks_to_the_bit():
    from construct.render.sweepdraw import _widest_gaps

    rng = np.random.default_rng(9)
    # 400 values of 30 spans: points, overlapping and nested spans, equal starts and equal ends (rounded to
    # tenths, so that ties are common), a few far apart (a gap to break)
    S = np.round(rng.random((30, 400)) * 10, 1) + np.where(rng.random((30, 1)) < 0.2, 40.0, 0.0)
    E = S + np.where(rng.random((30, 400)) < 0.3, 0.0, np.round(rng.random((30, 400)) * 3, 1))
    lo, hi, width, total = _widest_gaps(S, E)
    gaps = 0
    for i in range(S.shape[1]):
        want = _walk(list(zip(S[:, i].tolist(), E[:, i].tolist())))
        if want is None:
            assert not width[i] > 0
            continue
        gaps += 1
        assert (lo[i], hi[i], width[i], total[i]) == want
    assert gaps > 300  # (the spans far apart leave a gap at most values)


def test_the_boxes_stacked_are_each_marks_box_in_its_order():
    """extreme_rows (what a sweep's views read, every box at once) holds each mark's box of ``extremes``, row by row
    in its order: the two cranks' curves among the kinds' blocks (a row out of order would frame another mark)."""
    c = get("two-cranks")
    built = c.figure(parts=12)
    replay = built.protocol.replay(c.rod_ratio_sweep(dict(built.replay.givens), [3.0, 5.0, 40.0]))
    d = SweepDrawing(scene_for(c, built), built.protocol, replay, 3, STYLES["teaching"])
    assert any(m.kind.value == "curve" for m in d.curve_marks)
    for k in range(4):
        expected = np.array([box[k] for box in d.extremes.values()])
        np.testing.assert_array_equal(d.extreme_rows[k], expected)


@pytest.mark.parametrize("name, params, values", [("crank", {"parts": 6}, VALUES[::8]),
                                                  ("inertia-stroke-fractions", {}, np.array([3.0, 5.0, 12.0, 80.0, 900.0]))])
def test_the_end_states_marks_at_a_value_are_a_scenes_there(name, params, values):
    """The marks a value's plate lettering is placed among (the end state's: those of the figure it keeps and its
    own, on that value's broken sheet) are read off the sweep's arrays, not a scene built at every value: they are
    the marks a scene built there draws, each where it draws it (an arc's angles up to a whole turn)."""
    c = get(name)
    built = c.figure(**params)
    replay = built.protocol.replay(c.rod_ratio_sweep(dict(built.replay.givens), values))
    drawn = SweepDrawing(scene_for(c, built, ending=True), built.protocol, replay, len(values), STYLES["teaching"])
    assert drawn.ok.all()
    for i in range(len(values)):
        scene = scene_for(c, Figure(built.protocol, replay.take(i, whole=True), c.check, c), ending=True)
        want = [m for m in scene.end_drawn() if m.kind != "area"]
        got = drawn.end_marks_at(i)
        assert [(m.id, m.kind, m.label) for m in got] == [(m.id, m.kind, m.label) for m in want]
        for a, b in zip(got, want):
            x, y = np.asarray(a.geom, dtype=float).ravel(), np.asarray(b.geom, dtype=float).ravel()
            if a.kind == "arc":  # (its start angle a whole turn apart draws the same arc)
                x[3] += round((y[3] - x[3]) / (2 * np.pi)) * 2 * np.pi
            assert x == pytest.approx(y, rel=1e-9, abs=1e-9), (values[i], a.id)


def test_a_form_draws_only_the_sweeps_of_its_scene_protocol_and_style():
    """A kept form is used where its scene, protocol, style and the objects' names and kinds are the sweep's; another
    piece's protocol (Tafel I's pieces run through other points) or another style makes a form of its own, and draws
    what a fresh drawing draws."""
    from construct.live.sweep import live_givens, pieces
    c = get("piston-force")
    built = c.figure()
    given = live_givens(c, built)[0]
    parts = pieces(c, built, given.name, given.domain)
    given = given.name
    assert len(parts) > 1
    other = parts[0].protocol if parts[0].protocol is not built.protocol else parts[-1].protocol
    values = np.array([2.0, 3.0])
    sweep = lambda protocol: protocol.replay(c.given_sweep(dict(built.replay.givens), given, values, protocol.params))
    scene = scene_for(c, built)
    form = SweepForm(scene, built.protocol, sweep(built.protocol), STYLES["teaching"])
    assert form.fits(scene, built.protocol, sweep(built.protocol), STYLES["teaching"])
    assert not form.fits(scene, other, sweep(other), STYLES["teaching"])
    assert not form.fits(scene, built.protocol, sweep(built.protocol), STYLES["historical"])
    assert not form.fits(scene_for(c, built), built.protocol, sweep(built.protocol), STYLES["teaching"])
    mine = SweepDrawing(scene, other, sweep(other), 2, STYLES["teaching"], form=form)
    fresh = SweepDrawing(scene, other, sweep(other), 2, STYLES["teaching"])
    assert mine.form is not form
    assert mine.numbers.keys() == fresh.numbers.keys()
    for k, v in fresh.numbers.items():
        np.testing.assert_array_equal(mine.numbers[k], v)


def test_rows_of_coordinates_are_a_row_made_for_each():
    """_rows writes each coordinate into its row: the rows vec makes one by one (the sweep's own array, or a number
    for every value), to the bit; None where an array is not of floats (the caller keeps vec's)."""
    n = 5
    rng = np.random.default_rng(3)
    values = [float(rng.random()), rng.random(n), np.float64(rng.random()), np.asarray(rng.random()), rng.random(n),
              1, rng.random(n) * 1e300]
    vec = lambda v: v if type(v) is np.ndarray and v.shape == (n,) else np.full(n, float(v))  # noqa: E731
    want = np.array([vec(v) for v in values])
    got = _rows(values, n)
    assert got.dtype == want.dtype and got.shape == want.shape
    assert got.tobytes() == want.tobytes()
    assert _rows([np.arange(n, dtype=np.float32)], n) is None
    assert _rows([2.0, 3.0], n).tolist() == [[2.0] * n, [3.0] * n] and _rows([], n).shape == (0, n)


def test_the_angles_sorted_across_are_numpys_sort_to_the_bit():
    """_sorted_across (compare-exchange over whole arrays) puts the same numbers in the same places as np.sort along
    the marked points: ties, zeros and a full turn among them, NaN (np.sort's last) too, two to eight points."""
    from construct.render.sweepdraw import TWO_PI, _sorted_across

    rng = np.random.default_rng(11)
    for k in range(1, 9):
        a = np.round(rng.random((40, k, 30)) * TWO_PI, 1)  # (tenths: ties are common)
        a[rng.random(a.shape) < 0.1] = 0.0
        a[rng.random(a.shape) < 0.05] = TWO_PI
        want = np.sort(a, axis=1)
        assert _sorted_across(a).tobytes() == want.tobytes(), k
        a[0, 0, 0] = np.nan
        assert _sorted_across(a).tobytes() == np.sort(a, axis=1).tobytes(), k
