"""The live given's data: linear interpolation on the swept grid draws within 0.5 px of a fresh build.

The reference is an independent fresh build at each rod ratio (``Construction.figure``, as ``construct replay
--rod-ratio v`` builds it) drawn by the player's own drawing; the values are off the grid and spread over the
whole domain.  The interpolation is done here as the page's script does it (decode, blend, flags from the
nearer end).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from construct.cli.main import main
from construct.constructions import get
from construct.live import live_data, live_givens, live_sweep, player_page
from construct.live.sweep import (MIN_CELL, QUANTUM_PX, REFINE_PX, SWITCH_CELL, VIEW_JUMP_PX, _switch_spots,
                                  _switch_views, _view_columns, pieces)
from construct.render.wire import arc_flags, blend, decode, drawn_numbers, inflated, radii
from construct.render.styles import STYLES


@pytest.fixture(scope="module")
def crank_live():
    c = get("crank")
    fig = c.figure(parts=3, rod_ratio=5.0)
    return c, live_sweep(c, fig, "rod_ratio")


def _interpolated(live, data, v: float) -> np.ndarray:
    meta = inflated(data["meta_z"])
    rows = decode(data, meta["grid"], data["rows"], data["cols"])
    u = math.log10(v)
    g = np.asarray(meta["grid"])
    j = int(np.clip(np.searchsorted(g, u, side="right") - 1, 0, len(g) - 2))
    t = (u - g[j]) / (g[j + 1] - g[j])
    flags = np.zeros(data["cols"], dtype=bool)
    flags[meta["flags"]] = True
    return np.where(flags, rows[j] if t < 0.5 else rows[j + 1], blend(rows[j], rows[j + 1], t, radii(live.keys)))


def test_interpolation_is_within_half_a_pixel_of_a_fresh_build(crank_live):
    c, live = crank_live
    data = live_data(live)
    # held to 0.5 px: every mark but the few drawn from the nearer grid value (they jump; see live.py)
    snapped = set(live.snapped)
    assert len(snapped) <= 0.03 * len(live.keys)
    drawn = np.asarray([k[0][0] != "#" and k not in snapped for k in live.keys for _ in range(k[2].count("#"))])
    rng = np.random.default_rng(20)
    values = 10 ** rng.uniform(math.log10(1.05), 3.0, 30)
    values = [v for v in values if not any(a <= v <= b for a, b in live.jumps)]
    assert len(values) >= 25
    worst = 0.0
    for v in values:
        keys, fresh, _ = drawn_numbers(player_page(c, c.figure(parts=3, rod_ratio=float(v)), STYLES["teaching"]))
        # the same marks, in the same order (the views, rings and breaks are the page's, not its figure's)
        assert [k for k in keys if k in set(live.keys) and k[0][0] != "#"] == [k for k in live.keys if k[0][0] != "#"]
        at, by_key = 0, {}
        for k in keys:
            n = k[2].count("#")
            by_key[k] = fresh[at:at + n]
            at += n
        want = np.asarray([x for k in live.keys for x in by_key.get(k, [0.0] * k[2].count("#"))])
        err = np.abs(_interpolated(live, data, float(v)) - want)[drawn]
        worst = max(worst, float(err.max()))
    assert 0.0 < worst <= 0.5
    assert live.bound + QUANTUM_PX / 2 < 0.5


def test_the_grid_spans_the_stated_domain_and_was_refined(crank_live):
    _, live = crank_live
    assert live.grid[0] == 1.05 and live.grid[-1] == 1000.0
    assert len(live.grid) > 9 and np.all(np.diff(live.grid) > 0)
    # the jumps are cells narrower than the refinement's floor, not gaps in the grid
    assert all(math.log10(b) - math.log10(a) < 2e-4 for a, b in live.jumps)


def test_checks_at_a_grid_value_are_the_checks_of_a_fresh_build(crank_live):
    c, live = crank_live
    i = sorted(live.checks)[len(live.checks) // 3]
    fresh = c.checks(c.figure(parts=3, rod_ratio=float(live.grid[i])))
    got = live.checks[i]
    assert [g[0] for g in got] == [f.name for f in fresh]
    for g, f in zip(got, fresh):
        assert g[2] == pytest.approx(f.expected, rel=1e-12, abs=1e-12)
        assert g[1] == pytest.approx(f.measured, rel=1e-9, abs=1e-9) and g[5] == f.ok


def test_arc_flags_are_the_large_arc_numbers():
    keys = [("a", "d", "M# #A# # # # # # #"), ("b", "cx", "#"), ("c", "d", "M# #A# # # # # # #")]
    assert arc_flags(keys).nonzero()[0].tolist() == [5, 15]


def test_the_rod_and_kappa_are_live():
    names = lambda c, **p: [g.name for g in live_givens(get(c), get(c).figure(**p))]  # noqa: E731
    assert names("crank", parts=3) == ["rod_ratio"] and names("tangential-pressure") == ["rod_ratio", "kappa"]
    assert names("piston-force") == ["rod_length"]  # Tafel I's L = 2 m beside R = 0.4 m
    assert names("indicator-diagram") == []  # its filling changes the steps: a switch, not a slider


def test_replay_live_without_a_rod_refuses_and_writes_nothing(tmp_path, capsys):
    out = tmp_path / "o"
    assert main(["replay", "indicator-diagram", "--live", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--live" in err and "Traceback" not in err
    assert not out.exists()


def test_replay_live_writes_a_player_with_the_slider(tmp_path):
    out = tmp_path / "o"
    assert main(["replay", "crank", "--parts", "3", "--live", "--style", "teaching", "--out", str(out)]) == 0
    page = (out / "player.html").read_text(encoding="utf-8")
    assert 'type="range" name="rod_ratio"' in page and 'id="live-data"' in page and "http" not in \
        page.replace("http://www.w3.org", "")
    # the live player is written with the replay: its manifest names the page as it is
    from construct.io.manifest import changed_files

    assert changed_files(out, "replay") == []


def test_the_page_has_the_checks_of_the_built_value(crank_live):
    """A teacher back at the book's L/r = 5 sees the checks of the figure built at 5, not of a neighbour."""
    c, live = crank_live
    table = inflated(live_data(live)["checks_z"])
    i = table["check_values"].index(5.0)
    fresh = c.checks(c.figure(parts=3, rod_ratio=5.0))
    assert [row[0] for row in table["checks"][i]] == [pytest.approx(f.expected, rel=1e-8, abs=1e-12) for f in fresh]
    # the constructed value: given, or the formula's plus the error, to the digits the page shows
    made = [row[3] if len(row) > 3 else row[0] + row[1] for row in table["checks"][i]]
    assert made == [pytest.approx(f.measured, rel=1e-8, abs=1e-12) for f in fresh]
    assert [row[2] for row in table["checks"][i]] == [f.ok for f in fresh]
    assert table["check_values"] == sorted(table["check_values"])


def test_bench_live_without_a_player_refuses_in_one_line(tmp_path, capsys):
    assert main(["bench", "--live", str(tmp_path / "none.html")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--live" in err and "none.html" in err and "Traceback" not in err


def test_the_checks_travel_evenly_over_the_slider(crank_live):
    """The page shows the checks at the nearest swept value: those are spread evenly over the slider (log10),
    not over the grid, which is dense where the drawing bends."""
    _, live = crank_live
    u = np.log10(inflated(live_data(live)["checks_z"])["check_values"])
    grid_gap = np.diff(np.log10(live.grid)).max()
    assert np.diff(u).max() <= max(2 * (u[-1] - u[0]) / 47, grid_gap) + 1e-12


def test_the_live_data_is_the_same_bytes_on_every_build():
    """A gallery is rebuilt byte for byte (tests/test_gallery.py), its live players too: the sweep, its
    refinement and the encoding depend on nothing but the figure (a coarse grid: the bytes are the point)."""
    import json

    c = get("crank")
    fig = c.figure(parts=3, rod_ratio=4.0)
    first, again = (json.dumps(live_data(live_sweep(c, fig, "rod_ratio", max_values=16)), sort_keys=True)
                    for _ in range(2))
    assert first == again and len(first) > 1000


def _by_key(keys, nums) -> dict:
    out, at = {}, 0
    for k in keys:
        n = k[2].count("#")
        out[k] = nums[at:at + n]
        at += n
    return out


@pytest.mark.parametrize("name, params", [("crank", {"parts": 6}), ("inertia-curve", {})])
def test_the_sweep_measures_what_the_player_page_draws(name, params):
    """The sweep does not lay a page out at every grid value: it reads the marks' numbers off the drawing's
    own geometry (Measure).  Held here against the page itself (drawn_numbers of player_page, the page
    ``construct replay --rod-ratio v`` writes) at the built value and at values across the domain: every
    mark's numbers, in the page's order, the fit and the letters' texts; the views at the built value are
    the camera's own."""
    from construct.live import Measure, player_page_and_fit
    from construct.render.output import scene_for
    from construct.render.svg import Drawing

    c = get(name)
    built = c.figure(**params)
    measure = Measure(c, built, STYLES["teaching"])
    for v in (None, 1.3, 3.1, 7.7, 40.0):
        fig = built if v is None else c.figure(**params, rod_ratio=v)
        keys, nums, fit, texts = measure(fig)
        page, page_fit = player_page_and_fit(c, fig, STYLES["teaching"])
        pkeys, pnums, extra = drawn_numbers(page)
        # the same elements, attributes and templates, in the same order (the views and rings are the built
        # value's steps'; where the figure is broken, the page's script draws from Measure's own "#break")
        figure = lambda ks: [k for k in ks if k[0][0] != "#"]  # noqa: E731
        assert figure(keys) == figure(pkeys)
        if v is None:
            assert [k for k in keys if k[0] != "#break"] == pkeys
        got, want = _by_key(keys, nums), _by_key(pkeys, pnums)
        # the end state's furniture (fin-...): its arrowheads, ticks and the room its texts take are as large as the
        # end state's letters, which a sweep keeps at the built value's size (as it keeps the letters' places);
        # where a page lays its end state out at another size, they differ by that alone
        own = Drawing(scene_for(c, fig, ending=True), STYLES["teaching"]).end.size == measure.end.size
        for k in keys:
            if (k[0][0] != "#" or (v is None and k[0] != "#break")) and (own or not k[0].startswith("fin-")):
                assert got[k] == want[k], (v, k)
        assert fit == pytest.approx(page_fit, rel=1e-12)
        # every letter the page shows, with its text (the sweep knows the letters the page had no room for too)
        assert all(texts.get(i) == t for i, t in extra["texts"].items())


@pytest.mark.parametrize("name, params", [("crank", {"parts": 6}), ("piston-force", {})])
def test_a_pieces_keys_alone_are_the_keys_of_its_measure(name, params):
    """Measure._form asks a piece's scene for its keys only (the views, rings, insets and breaks not framed):
    they are the keys the whole measure of that scene has, in its order (crank: views and rings; piston-force:
    breaks, a furniture, the live data's costliest pieces)."""
    from construct.live import Measure
    from construct.render.output import scene_for

    c = get(name)
    built = c.figure(**params)
    measure = Measure(c, built, STYLES["teaching"])
    assert measure.view_of and measure.rings
    scene = scene_for(c, built, ending=STYLES["teaching"].camera)
    whole = measure._measured(scene)
    alone = measure._measured(scene, keys_only=True)
    assert alone[0] == whole[0] and alone[2] == whole[2] and alone[3] == whole[3]
    assert whole[0][-2:] == [("#break", "0", "# #"), ("#break", "1", "# #")]


def test_the_edge_letters_points_found_once_are_those_found_anew():
    """Measure._letter_points finds the columns of the edge letters' points once per list of keys (every round
    of a piece asks with the same list): read again, and for another list, they are the points number_places
    gives."""
    from construct.live import Measure
    from construct.live.measure import number_places

    c = get("piston-force")
    built = c.figure()
    measure = Measure(c, built, STYLES["teaching"])
    assert measure.edge_letters
    keys = measure.keys
    nums = np.arange(2 * sum(k[2].count("#") for k in keys), dtype=float).reshape(2, -1)
    at = number_places(keys)
    for ks in (keys, keys, list(keys)):
        got = measure._letter_points(ks, nums)
        for lvl, (ids, _) in measure.edge_letters.items():
            for c_, a in zip(got[lvl], ("cx", "cy")):
                want = [[nums[v, at[(i, a)]] if (i, a) in at else np.nan for v in range(2)] for i in ids]
                np.testing.assert_array_equal(c_, np.asarray(want, dtype=float).reshape(len(ids), 2))
    assert any((i, "cx") in at for ids, _ in measure.edge_letters.values() for i in ids)


def test_a_figure_with_hatched_areas_is_measured_at_once_as_value_by_value(monkeypatch):
    """The page draws areas (hatching and all) from the curves that bound them, so a figure with hatched areas
    (Baumann's diagram, in a style that hatches) is measured over the whole sweep at once, not a scene per value
    -- and draws there what a scene per value draws."""
    from construct.figure import Figure
    from construct.live import Measure

    c = get("tangential-pressure")
    built = c.figure(parts=6)
    measure = Measure(c, built, STYLES["teaching"])
    values = np.array([1.3, 5.0, 40.0])
    replay = built.protocol.replay(c.given_sweep(dict(built.replay.givens), "rod_ratio", values, built.protocol.params))
    # (the plate's furniture in the end state changes its form with the rod here, its scale's ticks: held)
    assert not measure.furniture_keeps_form(built.protocol, replay, len(values))
    measure.furniture_live = False
    alone = [measure(Figure(built.protocol, replay.take(i, whole=True), c.check, c)) for i in range(len(values))]
    monkeypatch.setattr(Measure, "__call__", lambda *a: pytest.fail("a scene per value"))
    together = measure.frames(built.protocol, replay, len(values))
    assert [f[0] for f in together] == [f[0] for f in alone] and [f[3] for f in together] == [f[3] for f in alone]
    assert np.abs(np.array([f[1] for f in together]) - np.array([f[1] for f in alone])).max() <= 0.01
    assert np.allclose([f[2] for f in together], [f[2] for f in alone], rtol=1e-12)


def test_a_sweeps_frames_draw_a_values_furniture_when_it_is_read(monkeypatch):
    """What is drawn value by value (the end state's furniture, the plate's) is drawn for the values a reader
    reads, once each, not for every value of the sweep: the refinement reads about half of what a round draws
    ahead.  A value read is the value measured alone."""
    from construct.figure import Figure
    from construct.live import Measure

    c = get("tangential-pressure")
    built = c.figure(parts=6)
    measure = Measure(c, built, STYLES["teaching"])
    values = np.array([4.0, 5.0, 6.0])
    replay = built.protocol.replay(c.given_sweep(dict(built.replay.givens), "rod_ratio", values, built.protocol.params))
    assert measure.furniture_keeps_form(built.protocol, replay, len(values))
    measure.furniture_live = True
    alone = measure(Figure(built.protocol, replay.take(1, whole=True), c.check, c))
    drawn = []
    furniture_at = Measure._furniture_at
    monkeypatch.setattr(Measure, "_furniture_at", lambda self, fig, at_once, i, *keep: drawn.append(i) or
                        furniture_at(self, fig, at_once, i, *keep))
    frames = measure.frames(built.protocol, replay, len(values))
    assert drawn == [] and len(frames) == 3
    keys, nums, fit, texts = frames[1]
    assert frames[1][1] is nums and drawn == [1]  # (read again: the same frame, not drawn again)
    assert any(k[0].startswith("fin-") for k in keys)  # (the furniture among what it draws)
    assert keys == alone[0] and texts == alone[3]
    assert np.abs(np.asarray(nums) - np.asarray(alone[1])).max() <= 0.01


def test_a_carried_view_still_frames_its_marks():
    """Away from the built value each step's view is the built view carried along with the marks of the
    steps it shows: where the built view held those marks whole, the carried one does at every rod ratio
    (or is the whole figure), measured from the marks' numbers on the page at that value."""
    from construct.live import Measure

    c = get("crank")
    built = c.figure(parts=6)
    measure = Measure(c, built, STYLES["teaching"])

    def holds(view, box, slack=0.5):
        return (view[0] - slack <= box[0] and view[1] - slack <= box[1] and box[2] <= view[0] + view[2] + slack
                and box[3] <= view[1] + view[3] + slack)

    held = [j for j, (v, b) in enumerate(zip(measure.views, measure.boxes)) if b is not None and holds(v, b)]
    assert len(held) >= 0.8 * len(measure.views) and held
    for v in (1.2, 2.5, 12.0, 300.0):
        keys, nums, _, _ = measure(c.figure(parts=6, rod_ratio=v))
        got = _by_key(keys, nums)
        full = got[("figure", "viewBox", "# # # #")]
        pts = {}
        for k, ns in got.items():  # each mark's extreme numbers on the page: a point, a circle's box, line ends
            if k[1] in ("cx", "x1"):
                pts.setdefault(k[0], []).append(ns[0])
        for j in held:
            steps = [i for i, w in enumerate(measure.view_of) if w == j]
            view = got[("#zoom", str(steps[0]), "# # # #")]
            # the marks it frames, as drawn at v: circles by their box, lines and points by their ends
            xs, ys = [], []
            for mid in measure.framed[j]:
                cx, cy, r = (got.get((mid, a, "#"), [None])[0] for a in ("cx", "cy", "r"))
                if cx is not None:
                    xs += [cx - r, cx + r] if (mid, "r", "#") in got and r > 3 else [cx]
                    ys += [cy - r, cy + r] if (mid, "r", "#") in got and r > 3 else [cy]
                x1 = got.get((mid, "x1", "#"))
                if x1 is not None:
                    xs += [x1[0], got[(mid, "x2", "#")][0]]
                    ys += [got[(mid, "y1", "#")][0], got[(mid, "y2", "#")][0]]
            if xs and list(view) != [0.0, 0.0, full[2], full[3]]:
                assert holds(view, (min(xs), min(ys), max(xs), max(ys)), slack=1.0), (v, j)


@pytest.mark.parametrize("name", ["piston-force", "effective-work"])
def test_at_the_built_value_the_page_shows_every_step_in_the_drawings_own_view(name):
    """The live data's views at the built value are the camera's (render/camera.py), step by step.  A step that
    draws nothing of its own (piston-force's last step reads the planimeter off the end state) was carried
    with no marks and became the whole canvas: the finished figure a patch in its corner."""
    from construct.live import Measure
    from construct.render.output import scene_for
    from construct.render.svg import Drawing

    c = get(name)
    built = c.figure()
    drawing = Drawing(scene_for(c, built, ending=True), STYLES["teaching"])
    measure = Measure(c, built, STYLES["teaching"], drawing=drawing)
    got = _by_key(*measure(built)[:2])
    wrong = [(k, got[("#zoom", str(i), "# # # #")], drawing.camera_view(k)) for i, k in enumerate(measure.steps)
             if got[("#zoom", str(i), "# # # #")] != pytest.approx(drawing.camera_view(k), abs=0.011)]
    assert not wrong, wrong[:3]


def _steady() -> list[tuple[str, str]]:
    from construct.constructions import names

    return [(c.name, g) for c in map(get, names()) for g in c.steady]


def test_the_crank_and_baumanns_kappa_are_steady():
    assert set(_steady()) >= {("crank", "rod_ratio"), ("tangential-pressure", "kappa")}


# (one test a construction and given: the scans take 10 s of CPU between them, which two workers share)
@pytest.mark.parametrize("name, given", _steady())
def test_a_steady_given_is_one_piece_by_a_scan_of_fresh_builds(name, given):
    """A given a construction names steady (its value never changes which steps it takes) is swept without
    looking for pieces: held here by the scan it is spared -- fresh builds across its domain at the book's
    figures take the built figure's steps (test_the_scan_finds_tafel_is_pieces: the scan finds pieces where
    there are)."""
    from construct.live.sweep import reach, scan_pieces

    c = get(name)
    for params in c.book_params[:2] or ({},):
        fig = c.figure(**params)
        live = next(x for x in live_givens(c, fig) if x.name == given)
        domain = reach(c, fig, given, live.domain, float(fig.replay.givens[given]))
        assert [p.protocol for p in scan_pieces(c, fig, given, domain, scan=8)] == [fig.protocol], params


def test_the_scan_finds_tafel_is_pieces():
    """The scan that steady givens are spared finds Tafel I's pieces, which the piston force does not name
    steady."""
    from construct.live.sweep import scan_pieces

    c = get("piston-force")
    assert "rod_length" not in c.steady
    fig = c.figure()
    assert len(scan_pieces(c, fig, "rod_length", live_givens(c, fig)[0].domain, scan=8)) > 1


@pytest.mark.parametrize("name", ["piston-force", "inertia-stroke-fractions", "effective-work"])
def test_the_pieces_read_off_a_sweep_are_where_fresh_builds_change_their_steps(name):
    """A construction that reads its build's choices off a sweep (Construction.form) finds the pieces of its
    domain on arrays: fresh builds just inside either end of every piece take that piece's steps, and
    neighbouring pieces' steps differ (Tafel I's eight pieces, the stroke fractions' six, Fig. 27's two) -- and
    the fresh builds' own scan finds the same pieces (checked where it is quick: the stroke fractions)."""
    from construct.constructions import names
    from construct.kernel.instruments import unlettered
    from construct.live.sweep import FORM_TOL, _form, _keywords, form_pieces, reach, scan_pieces

    assert {n for n in names() if get(n).form is not None} >= {"piston-force", "inertia-stroke-fractions",
                                                                "effective-work"}
    c = get(name)
    fig = c.figure(**c.book_params[0])
    g = next(x for x in live_givens(c, fig) if x.name not in c.steady)
    domain = reach(c, fig, g.name, g.domain, float(fig.replay.givens[g.name]))
    found = form_pieces(c, fig, g.name, domain)
    assert found is not None and len(found) > 1
    kw = _keywords(c, fig)
    with unlettered():
        for p in found:
            step = 10 ** (FORM_TOL / 4)  # a quarter of the bisection's last cell inside each end
            for v in (p.low * step, p.high / step):
                assert _form(c.build(**{**kw, g.name: v}).protocol) == _form(p.protocol), (name, v)
    assert all(_form(a.protocol) != _form(b.protocol) for a, b in zip(found[:-1], found[1:]))
    assert sum(p.protocol is fig.protocol for p in found) == 1
    if name == "inertia-stroke-fractions":
        assert [(p.low, p.high, _form(p.protocol)) for p in scan_pieces(c, fig, g.name, domain)] == \
            [(p.low, p.high, _form(p.protocol)) for p in found]


def test_a_pieces_unlettered_protocol_draws_what_a_lettered_build_draws():
    """The pieces other than the built figure's are unlettered builds (their letters are a third of a build's
    time; their captions are left as written): what the player is sent of a piece is the same as from a
    lettered build there (the stroke fractions' shortest piece but the built one's)."""
    import json

    from construct.live.sweep import Piece, _keywords, reach

    c = get("inertia-stroke-fractions")
    fig = c.figure()
    g = live_givens(c, fig)[0]
    found = pieces(c, fig, g.name, reach(c, fig, g.name, g.domain, float(fig.replay.givens[g.name])))
    p = min((q for q in found if q.protocol is not fig.protocol), key=lambda q: q.high / q.low)
    lettered = c.build(**{**_keywords(c, fig), g.name: p.low}).protocol
    assert p.protocol.params.get("captions") != "letters" == lettered.params["captions"]
    sent = [json.dumps(live_data(live_sweep(c, fig, g.name, piece=q)), sort_keys=True, default=str)
            for q in (p, Piece(p.low, p.high, lettered))]
    assert sent[0] == sent[1]


def test_an_unlettered_build_takes_the_steps_of_a_lettered_one():
    """What pieces asks an unlettered build for (its steps' ops, inputs and outputs; what it made) is a lettered
    build's; only the captions are not yet in the figure's letters."""
    from construct.kernel.instruments import unlettered

    c = get("effective-work")  # (a build going on from another construction's figure)
    with unlettered():
        sketch = c.build(**{**c.defaults, "rod_ratio": 2.0})
    fig = c.build(**{**c.defaults, "rod_ratio": 2.0})
    form = lambda p: [(s.op, s.inputs, s.outputs) for s in p.steps]  # noqa: E731
    assert form(sketch.protocol) == form(fig.protocol)
    assert sketch.protocol.params.get("captions") != "letters" and fig.protocol.params["captions"] == "letters"
    assert [s.caption for s in sketch.protocol.steps] != [s.caption for s in fig.protocol.steps]
    again = fig.protocol.replay(dict(fig.replay.givens))
    assert list(sketch.replay) == list(again)
    for name in ("A1", "P.deficit.end", fig.protocol.steps[-1].outputs[0]):
        assert repr(sketch.replay[name]) == repr(again[name]), name


@pytest.fixture(scope="module")
def tafel_2_live():
    """Tafel 2's sweep over the piece of the domain its book value (L/r = 5) lies in, L/r 2.74 to 1000."""
    c = get("inertia-stroke-fractions")
    fig = c.figure()
    given = live_givens(c, fig)[0]
    piece = next(p for p in pieces(c, fig, "rod_ratio", given.domain) if p.low <= 20 <= p.high)
    return live_sweep(c, fig, "rod_ratio", piece=piece)


def test_tafel_2s_end_state_writes_the_inertia_pressures_of_every_rod_ratio(tafel_2_live):
    """The stroke fractions' end state is drawn mostly by the plate (57 ordinates, dots and values against 32
    marks): its values follow the slider, each the inertia pressure at its tenth of the stroke at that grid value --
    q = F/f (cos phi + r/L cos 2 phi) at the crank angle where the piston has gone k/10 of the stroke (its pin at X
    from the crank centre, cos phi = (X^2 + r^2 - L^2) / (2 X r)) -- not the book's at every value."""
    live = tafel_2_live
    assert not live.furniture_held
    ids = sorted((i for i, texts in live.reading_texts.items() if texts[0][:1] in "+−"), key=lambda i: int(i[5:]))
    k = np.arange(11) / 10
    for g, lr in enumerate(live.grid):
        written = [live.reading_texts[i][g] for i in ids]
        values = [float(t.replace("−", "-").replace(",", ".")) for a, t in enumerate(written) if a % 2 == 0]
        x = np.float64(2 * k)  # (r = 1: the piston's way from the outer dead centre)
        pin = lr + 1 - x
        cos = np.clip((pin ** 2 + 1 - lr ** 2) / (2 * pin), -1, 1)
        q = cos + (2 * cos ** 2 - 1) / lr
        assert len(values) == 11 and written[::2] == written[1::2], (lr, written)  # (each with its halo)
        assert np.abs(np.asarray(values) - q).max() <= 0.0015, (lr, values, np.round(q, 3).tolist())

def test_tafel_2s_lettering_switches_its_spots_at_grid_values_not_refined_down(tafel_2_live):
    """Tafel 2's values stand elsewhere about their ordinates where they would crowd (a choice among spots, not a
    coordinate): the refinement chased every such switch down to MIN_CELL, 413 grid values in this piece where the
    drawing needs about 130 (129 before the values moved).  Each switch now stands beside a grid value, a jump of
    the drawing no wider than MIN_CELL (or, a step's view jumping, one across which no mark moves by more than
    REFINE_PX: _switch_views), and the grid is the drawing's."""
    live = tafel_2_live
    assert len(live.grid) <= 160, len(live.grid)
    u = np.log10(live.grid)
    marks = ~_view_columns(live.keys)
    at = {float(v): i for i, v in enumerate(live.grid)}
    assert live.jumps and all(np.log10(b) - np.log10(a) <= MIN_CELL or np.abs(live.drawn[at[a], marks] -
                              live.drawn[at[b], marks]).max() <= REFINE_PX for a, b in live.jumps)
    assert all(a in live.grid and b in live.grid for a, b in live.jumps)
    assert np.diff(u).min() > 0


def test_a_switch_of_spots_is_put_where_both_sides_spots_are_clear():
    """_switch_spots on a cell whose ends write the lettering at spots S1 and S2, where S1 is clear below 0.6 and S2
    above 0.1 (log10 of the given), and a value placed anew takes S1 below 0.3: neither end's spots hold at the
    other end, so the cell is split at its midpoint (S2 there) and the switch put SWITCH_CELL below it, S1 written
    up to there (clear), a jump of the drawing; two rounds of frames, not a bisection down to MIN_CELL."""
    clear = {"S1": lambda u: u < 0.6, "S2": lambda u: u > 0.1}
    keys = [("fin-f0", "x", "#")]

    def frame(u: float, keep: str | None) -> tuple:
        spots = keep if keep is not None and clear[keep](u) else ("S1" if u < 0.3 else "S2")
        return keys, np.array([u]), (0.0, 0.0, 1.0), {"#spots": spots}

    rounds = []

    def frames(us, keep):
        rounds.append(len(us))
        return [frame(u, keep.get(i)) for i, u in enumerate(us)]

    data = {0.0: frame(0.0, None), 1.0: frame(1.0, None)}
    jumps: list[tuple[float, float]] = []
    values = lambda u: 10.0 ** np.asarray(u)  # noqa: E731
    _switch_spots(data, lambda u: data[u][3]["#spots"], jumps, values, frames)
    us = sorted(data)
    spots = [data[u][3]["#spots"] for u in us]
    assert us == [0.0, 0.5 - SWITCH_CELL, 0.5, 1.0] and spots == ["S1", "S1", "S2", "S2"]
    assert jumps == [(float(values(0.5 - SWITCH_CELL)), float(values(0.5)))]
    assert all(clear[s](u) for u, s in zip(us, spots)) and len(rounds) == 3


@pytest.mark.parametrize("at", [0.3, 0.77])
def test_a_view_that_jumps_inside_a_cell_switches_where_it_jumps(at):
    """_switch_views on a cell (0, 1) of the refined grid (log10 of the given) across which a step's view jumps by
    300 px at *at* (a shot framed whole from there on) while a mark moves 100 px smoothly: the page blended the
    view across the whole cell (150 px off at its midpoint).  The cell is halved where the view still jumps, each
    midpoint a grid value, down to a cell across which the mark moves by at most REFINE_PX, which straddles *at*
    and is a jump of the drawing (the page draws its nearer side: the mark within REFINE_PX / 2 of the blend);
    the view is exact at every grid value.  A view that moves smoothly (by 40 px across the cell) and one that
    jumps by less than VIEW_JUMP_PX are left blended (no value added to the grid); so is a cell far from the book's
    value (nothing drawn)."""
    keys = [("#zoom", "0", "# # # #"), ("p", "cx", "#")]

    def frame(u: float, jump: float = 300.0, slope: float = 0.0) -> tuple:
        w = 600.0 + slope * u + (jump if u >= at else 0.0)
        return keys, np.array([0.0, 0.0, w, w * 0.7, 100.0 * u]), (0.0, 0.0, 1.0), {}

    values = lambda u: 10.0 ** np.asarray(u)  # noqa: E731
    data = {0.0: frame(0.0), 1.0: frame(1.0)}
    jumps: list[tuple[float, float]] = []
    _switch_views(data, jumps, values, lambda us, keep: [frame(u) for u in us], 0.5)
    us = sorted(data)
    assert len(jumps) == 1
    a, b = (float(np.log10(x)) for x in jumps[0])
    assert a in data and b in data and a < at <= b and 100.0 * (b - a) <= REFINE_PX
    assert all(np.array_equal(data[u][1], frame(u)[1]) for u in us) and len(us) <= 12
    for kw in ({"jump": 0.0, "slope": 40.0}, {"jump": VIEW_JUMP_PX * 0.9}):
        data = {0.0: frame(0.0, **kw), 1.0: frame(1.0, **kw)}
        drawn: list[float] = []
        _switch_views(data, jumps := [], values, lambda us, keep: drawn.extend(us) or [frame(u, **kw) for u in us],
                      0.5)
        assert sorted(data) == [0.0, 1.0] and not jumps and len(drawn) <= 7, (kw, drawn)
    data, drawn = {0.0: frame(0.0), 1.0: frame(1.0)}, []
    _switch_views(data, jumps := [], values, lambda us, keep: drawn.extend(us) or [frame(u) for u in us], 2.0)
    assert sorted(data) == [0.0, 1.0] and not jumps and not drawn


def test_furniture_matched_once_per_pattern_as_matched_alone():
    """Measure._aligned matches a value's plate furniture to the built one's once for each pattern of its forms and
    texts (measure._pattern: the matcher compares items for equality only), not once for each value's texts: on
    random plates whose texts come and go (drawn from a few, so that patterns recur with other texts), the cached
    matching is _matched's own, value by value (fails when the pattern says only whether an item equals a built
    one, not which)."""
    from types import SimpleNamespace

    from construct.live.measure import Measure, _matched, _signs
    from construct.render.plate import Lettering, Stroke

    rng = np.random.default_rng(27)

    def plate(n: int) -> tuple:
        return tuple(Stroke((0.0, float(i)), (1.0, float(i))) if rng.random() < 0.4 else
                     Lettering((0.0, float(i)), str(rng.integers(0, 6))) for i in range(n))

    for _ in range(40):
        built = plate(int(rng.integers(3, 12)))
        first: dict = {}
        for i, s in enumerate(_signs(built)[1]):
            first.setdefault(s, i)
        m = SimpleNamespace(_items=built, _first=first, _matches={})
        for _ in range(30):
            items = plate(int(rng.integers(3, 12)))
            at = _matched(built, items)
            want = (tuple(items[at[i]] if i in at else it for i, it in enumerate(built)),
                    frozenset(range(len(built))) - set(at))
            assert Measure._aligned(m, items) == want
    # values that write other numbers at the same places (a scale's, read off the figure) are one pattern
    m = SimpleNamespace(_items=built, _first=first, _matches={})
    for k in range(5):
        items = tuple(Lettering(it.at, f"{it.text}.{k}") if isinstance(it, Lettering) else it for it in built)
        at = _matched(built, items)
        assert Measure._aligned(m, items)[0] == tuple(items[at[i]] if i in at else it for i, it in enumerate(built))
    assert len(m._matches) == 1
