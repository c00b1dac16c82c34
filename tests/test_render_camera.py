"""The teaching camera: the view of each step, the levels of detail and the label placer.

Expectations come from the protocol and the geometry (which points a group
makes and which its instruments are set on, where the viewport puts them),
from the font file's metrics and from the definition of the views -- never
from the renderer's own numbers.
"""

from __future__ import annotations

import itertools
import json
import math
import re
import xml.etree.ElementTree as ET

import pytest

from construct.constructions import get
from construct.kernel.geometry import Circle, Line, Point
from construct.render import camera, insets
from construct.render.output import scene_for, write_replay
from construct.render.player import player_html
from construct.render.styles import STYLES
from construct.render.lettering import segment_meets_box
from construct.render.svg import Drawing

SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def crank():
    c = get("crank")
    fig = c.figure(parts=6, rod_ratio=5.0)
    return c, fig, Drawing(scene_for(c, fig), STYLES["teaching"])


def _points_of(fig, steps) -> list[tuple[float, float]]:
    out = []
    for s in steps:
        for name in (*s.inputs, *s.outputs):
            obj = fig.replay.get(name)
            if isinstance(obj, Point):
                out.append((obj[0], obj[1]))
    return out


def _window_zoom(v, full) -> float:
    """How many times the player's window (998 x 630 px in a 1400 x 900 window, measured in Chromium) shows view
    *v* larger than the whole canvas: each fitted into the window keeping its aspect (preserveAspectRatio meet)."""
    ww, wh = 998.0, 630.0
    return min(ww / v[2], wh / v[3]) / min(ww / full[2], wh / full[3])


def test_views_are_boxes_of_the_canvas_in_the_windows_shape(crank):
    _c, fig, d = crank
    full = d.full_view
    views = d.views
    assert len(views) == len(fig.protocol.steps)
    assert views[0] == full  # the first step shows the whole figure
    for v in views:
        assert v[0] >= -0.01 and v[1] >= -0.01 and v[0] + v[2] <= full[2] + 0.01 and v[1] + v[3] <= full[3] + 0.01
        if v != full:
            assert v[3] / v[2] == pytest.approx(630 / 998, rel=2e-2) or v[3] == pytest.approx(full[3], abs=0.01)
        assert _window_zoom(v, full) <= camera.MAX_ZOOM + 1e-3
    assert any(_window_zoom(v, full) > 1.5 for v in views)  # some group is seen magnified (past the first level)


@pytest.mark.parametrize("name, params, last", [("crank-angle", {"rod_ratio": 4.0}, 3.0),
                                                ("inertia-stroke-fractions", {}, 1.5)])
def test_a_tall_figures_views_fill_the_players_window(name, params, last):
    """A tall figure (the window shows it at half its size) is seen in views of the window's shape, not
    letterboxed in views of its own; the zoom level every part of the page uses is the window's
    magnification.  Fails on views of the canvas's shape."""
    c = get(name)
    d = Drawing(scene_for(c, c.figure(**params)), STYLES["teaching"])
    full = d.full_view
    assert full[3] / full[2] > 1.2  # a tall figure
    zoomed = [v for v in d.views if v != full]
    assert zoomed
    for v in zoomed:
        # as wide as the window's shape asks, or the canvas's whole width
        assert v[2] == pytest.approx(min(v[3] * 998 / 630, full[2]), rel=2e-2)
        assert camera.zoom_of(v, full) == pytest.approx(_window_zoom(v, full), rel=1e-9)
    # the last frame, the clean figure of the results, fills the window (crank-angle: 2.6x in a view of the
    # canvas's shape, the crank circle between the window's top and bottom in one of the window's)
    assert _window_zoom(d.views[-1], full) > last


def _drawn_points(d, steps) -> list[tuple[float, float]]:
    """The points the steps make and are set on, where the figure draws them (a broken axis moves the far
    crossheads in), by the protocol's names."""
    at = {m.name: m.geom for m in d.scene.marks if m.kind == "point"}
    return [at[n] for s in steps for n in (*s.inputs, *s.outputs) if n in at]


def _inside(d, v, x: float, y: float) -> bool:
    px, py = d.vp.px(x, y)
    return v[0] <= px <= v[0] + v[2] and v[1] <= py <= v[1] + v[3]


def test_a_view_frames_its_steps_work(crank):
    """Every step's view holds what the step makes and the points its instrument is set on."""
    _c, fig, d = crank
    steps = fig.protocol.steps
    checked = 0
    for i, s in enumerate(steps[1:-1], start=2):
        v = d.camera_view(i)
        if v == d.full_view or not s.group:
            continue
        for x, y in _drawn_points(d, [s]):
            assert _inside(d, v, x, y), (i, s.caption.en)
        checked += 1
    assert checked > 5


def test_the_camera_holds_still_over_shots_and_never_swings_out_and_back(crank):
    """The picture holds still while the work stays in one place: the camera does not move at every
    step, and never goes somewhere for one step only to come back (a rod arc struck from the crank
    circle onto the far crosshead, then its crossing: the whole stage is seen, not swung between)."""
    _c, fig, d = crank
    views = d.views
    n = len(views)
    moves = sum(1 for k in range(1, n) if views[k] != views[k - 1])
    assert n / (moves + 1) >= 5  # steps per view, on the average
    assert not [k + 1 for k in range(1, n - 1) if views[k - 1] == views[k + 1] != views[k]]


@pytest.fixture(scope="module")
def tangential(gallery_figure, gallery_drawing):
    params = dict(rod_ratio=5.0, parts=18, kappa=8.0)  # the gallery's teaching figure (Baumann, Fig. 26/27)
    return (*gallery_figure("tangential-pressure", params), gallery_drawing("tangential-pressure", params))


def _point(fig, name: str) -> tuple[float, float]:
    p = fig.replay[name]
    assert isinstance(p, Point)
    return (p[0], p[1])


def test_a_group_in_far_apart_places_is_followed_where_it_works(tangential):
    """The ordinate at crank point b5 is one group working at the crank circle (Gb5 on the stroke) and at
    the proportional angle far below (vertex S); the step that takes Vb5 off the proportional angle is
    shot there, magnified, with S beside it -- not as the union of the group (the whole figure)."""
    _c, fig, d = tangential
    steps = fig.protocol.steps
    k = next(s.index for s in steps if "Vb5" in s.outputs)
    group = steps[k - 1].group
    # the geometry makes the point of the test: the group reaches from the stroke line to S, far below
    ys = [y for s in steps if s.group[:len(group)] == group for _x, y in _points_of(fig, [s])]
    x0, y0, x1, y1 = d.scene.bbox
    assert max(ys) - min(ys) > 0.4 * (y1 - y0)
    v, full = d.camera_view(k), d.full_view
    assert v[2] * v[3] <= 0.25 * full[2] * full[3]  # at least twice magnified
    for name in ("Vb5", "S", *[n for n in steps[k - 1].inputs if isinstance(fig.replay.get(n), Point)]):
        assert _inside(d, v, *_point(fig, name)), name
    assert not _inside(d, v, *_point(fig, "Gb5")) and not _inside(d, v, *_point(fig, "O"))


def _result_points(fig) -> list[str]:
    return [n for s in fig.protocol.steps if s.role in ("result", "given") for n in s.outputs
            if isinstance(fig.replay.get(n), Point)]


@pytest.mark.parametrize("name, params", [("tangential-pressure", dict(rod_ratio=5.0, parts=18, kappa=8.0)),
                                          ("inertia-curve", dict(rod_ratio=4.0))])
def test_the_last_frame_frames_the_results_not_a_far_helper(name, params, tangential):
    """The last teaching frame shows the results as a clean figure: every result and given point in view,
    the vertex S of the proportional angle (a helper far below them) left out, so the results are seen
    larger than in the whole figure; the whole figure is still the first step's view."""
    c = get(name)
    if name == "tangential-pressure":
        _c, fig, d = tangential
    else:
        fig = c.figure(**params)
        d = Drawing(scene_for(c, fig), STYLES["teaching"])
    n = len(fig.protocol.steps)
    last, full = d.camera_view(n), d.full_view
    results = _result_points(fig)
    assert len(results) > 10
    for r in results:
        assert _inside(d, last, *_point(fig, r)), r
    # S is a helper (not a result), and lies farther below the results than they are high
    assert "S" not in results
    ry = [_point(fig, r)[1] for r in results]
    sy = _point(fig, "S")[1]
    assert min(ry) - sy > 0.5 * (max(ry) - min(ry))
    assert not _inside(d, last, *_point(fig, "S"))
    assert last[2] < 0.8 * full[2]
    assert d.camera_view(1) == full


def test_the_camera_is_stored_with_the_step_in_the_layered_figure_and_the_player(tmp_path):
    c = get("crank")
    fig = c.figure(parts=6, rod_ratio=5.0)
    write_replay(c, fig, tmp_path, style="teaching")
    root = ET.parse(tmp_path / "final.svg").getroot()
    layer = next(g for g in root.iter(f"{SVG}g") if g.get("id") == "views")
    stored = {int(g.get("data-step")): tuple(float(r.get(a)) for a in ("x", "y", "width", "height"))
              for g in layer for r in g}
    html = (tmp_path / "player.html").read_text()
    data = json.loads(re.search(r'<script type="application/json" id="data">(.*?)</script>', html, re.S).group(1))
    views = [tuple(data["views"][st["v"]]) for st in data["steps"]]
    # a box where the view changes, the same box the player shows from that step on
    changes = [k for k in range(1, len(views) + 1) if k == 1 or views[k - 1] != views[k - 2]]
    assert sorted(stored) == changes
    for k in changes:
        assert stored[k] == pytest.approx(views[k - 1], abs=0.006)


def test_a_moved_camera_is_a_change_of_its_step(tmp_path):
    from construct.regress.svgdiff import changes_by_step, diff_svg

    c = get("crank")
    fig = c.figure(parts=6, rod_ratio=5.0)
    write_replay(c, fig, tmp_path, style="teaching")
    text = (tmp_path / "final.svg").read_text()
    root = ET.fromstring(text.encode())
    layer = next(g for g in root.iter(f"{SVG}g") if g.get("id") == "views")
    group = list(layer)[1]
    k = int(group.get("data-step"))
    rect = list(group)[0]
    old = f'<rect class="view" height="{rect.get("height")}" width="{rect.get("width")}" x="{rect.get("x")}"'
    assert old in text
    moved = text.replace(old, f'<rect class="view" height="{rect.get("height")}" width="{rect.get("width")}" '
                              f'x="{float(rect.get("x")) + 5:g}"', 1)  # (a later step may show the same view)
    diff = diff_svg(text, moved)
    assert not diff.equal
    assert list(changes_by_step(diff)) == [k]


def test_camera_work_grows_with_the_steps_not_their_square(monkeypatch):
    """The camera visits every mark and step a bounded number of times (counted, not timed)."""
    calls = itertools.count()
    real = camera.extreme_points

    def counting(m):
        next(calls)
        return real(m)

    monkeypatch.setattr(camera, "extreme_points", counting)
    counts = []
    for parts in (30, 120):  # 580 and 2,290 visits for 365 and 1,535 views; a square would be 16x
        fig = get("crank").figure(parts=parts)
        sc = scene_for(get("crank"), fig)
        before = next(calls)
        views = camera.step_views(sc, (0.0, 0.0, 960.0, 700.0), sc.bbox, lambda x, y: (x, -y), 1.0, collapse=True)
        counts.append((next(calls) - before, len(views)))
    (c1, n1), (c2, n2) = counts
    assert n2 > 3.5 * n1
    assert c2 / c1 < 1.5 * n2 / n1  # linear, not quadratic (that would be ~16x)


def test_finished_groups_collapse_to_their_results_in_the_style_sheet():
    css = STYLES["teaching"].css()
    assert ".done{display:none}" in css


def test_internal_names_are_never_shown_as_letters():
    for name, params in (("inertia-curve", {}), ("two-cranks", {"parts": 12})):
        c = get(name)
        fig = c.figure(**params)
        svg = Drawing(scene_for(c, fig), STYLES["teaching"]).layered()
        texts = {"".join(t.itertext()) for t in ET.fromstring(svg.encode()).iter(f"{SVG}text")}
        assert not {t for t in texts if re.fullmatch(r"c\d{2,}|Nb\d+|iP\d+", t)}, name


def test_a_storyboard_tile_takes_in_the_work_of_all_its_steps(tangential):
    """A tile of the storyboard shows the steps since the tile before (the animation's stage): every point
    they make is in the tile's view, not only the last step's working place."""
    from construct.render.storyboard import storyboard_steps, storyboard_svg

    _c, fig, d = tangential
    root = ET.fromstring(storyboard_svg(d).encode())
    tiles = [e for e in root.iter(f"{SVG}svg") if e is not root and e.get("viewBox")]
    ends = storyboard_steps(d.scene)
    assert len(tiles) == len(ends) > 3
    start = 2  # the first step shows the whole figure by convention, not for its work
    for tile, end in zip(tiles, ends):
        x, y, w, h = (float(t) for t in tile.get("viewBox").split())
        for px, py in (d.vp.px(*p) for p in _drawn_points(d, fig.protocol.steps[start - 1:end])):
            assert x - 0.01 <= px <= x + w + 0.01 and y - 0.01 <= py <= y + h + 0.01, (end, px, py)
        start = end + 1


def _struck_onto(fig, k: int) -> set[str]:
    """The lines and circles step k's arc is struck onto, from the protocol: those the next step taking up what
    step k makes cuts it with (where that step makes a point: the crossing)."""
    steps = fig.protocol.steps
    made = {n for n in steps[k - 1].outputs if isinstance(fig.replay.get(n), (Line, Circle))}
    for s in steps[k:] if made else ():
        if made & set(s.inputs):
            if all(isinstance(fig.replay.get(n), Point) for n in s.outputs):
                return {n for n in s.inputs if n not in made and isinstance(fig.replay.get(n), (Line, Circle))}
            return set()
    return set()


@pytest.mark.parametrize("name, params", __import__("construct.gallery", fromlist=["gallery_plan"]).gallery_plan(),
                         ids=lambda p: p if isinstance(p, str) else ",".join(f"{k}={v}" for k, v in p.items()))
def test_every_input_of_a_step_is_drawn_at_that_step(name, params, gallery_figure, gallery_drawing):
    """Levels of detail hide a finished group's helpers, never what the current step is set on, cuts or
    strikes its arc onto (tangential-pressure step 821 carries O–Yb7 onto the scale line r, which step 822
    cuts: the line was not drawn while the arc was struck onto it)."""
    c, fig = gallery_figure(name, params)
    d = gallery_drawing(name, params)
    made_by = {}
    for s in fig.protocol.steps:
        for n in s.outputs:
            made_by.setdefault(n, s.index)
    missing = []
    n = len(fig.protocol.steps)
    for s in fig.protocol.steps[:-1]:  # the last frame is the clean figure of the results
        k = s.index
        inputs = d.input_steps(k)
        for obj in set(s.inputs) | _struck_onto(fig, k):
            j = made_by.get(obj)
            if j is None or j >= k or d.scene.step_of(obj) is None:
                continue  # a given not drawn, or a length
            if d.step_class(j, k, mark_steps=True, inputs=inputs) == "done":
                missing.append((k, obj, j))
    assert not missing, f"{len(missing)} of {n} steps: {missing[:8]}"



def test_the_operands_of_a_step_are_tagged_in_its_view():
    """crank step 181 ('line through M1 and T2'): both operands carry their name tags in the step's view.  M1
    gave way there to tags never shown with it (the level's tags were checked all together), and was placed
    without regard to the tags placed at a lower level that are seen with it."""
    c = get("crank")
    fig = c.figure(parts=18, rod_ratio=5.0)
    d = Drawing(scene_for(c, fig), STYLES["teaching"])
    k = 181
    step = fig.protocol.steps[k - 1]
    assert step.caption.en == "line through M1 and T2"
    z = camera.zoom_of(d.camera_view(k), d.full_view)
    lvl = max(i for i, lv in enumerate(camera.ZOOM_LEVELS) if lv <= z * 1.001)
    svg = ET.fromstring(d.layered())
    tags = {}  # (text, point on the canvas) -> the classes of its letter group
    for g in svg.iter(f"{SVG}g"):
        m = re.fullmatch(r"translate\(([-\d.]+) ([-\d.]+)\)", g.get("transform") or "")
        for t in g.findall(f"{SVG}text"):
            cls = (t.get("class") or "").split()
            if m and "tag" in cls and "halo" not in cls:
                tags[("".join(t.itertext()), float(m.group(1)), float(m.group(2)))] = (g.get("class") or "").split()
    for name, letters in zip(step.inputs, ("M1", "T2")):
        px, py = d.vp.px(*fig.replay.get(name))
        got = [cls for (text, x, y), cls in tags.items() if text == letters and abs(x - px) < 0.02 and abs(y - py) < 0.02]
        assert got, (letters, px, py)
        assert f"h{lvl}" not in got[0], (letters, got[0])  # not hidden at the view's zoom level


def test_a_storyboard_tiles_letters_are_not_flooded_by_the_highlight(crank):
    """The highlight tints the current tile's new marks by flooding its colour through their alpha; letters
    drawn through it came out as blobs of that colour (their halos filled too).  They are drawn beside it."""
    from construct.render.storyboard import storyboard_svg

    _c, _fig, d = crank
    assert d.style.highlight
    root = ET.fromstring(storyboard_svg(d).encode())
    parent = {c: p for p in root.iter() for c in p}
    XLINK = "{http://www.w3.org/1999/xlink}href"
    letters = [u for u in root.iter(f"{SVG}use") if (u.get(XLINK) or u.get("href") or "").endswith("-labels")]
    assert letters
    for u in letters:
        p = parent.get(u)
        while p is not None:
            assert p.get("filter") is None, u.get(XLINK)
            p = parent.get(p)
    # the marks are still tinted
    assert any(g.get("filter") == "url(#now)" for g in root.iter(f"{SVG}g"))


# --------------------------------------------------------------------------- the end state

@pytest.fixture(scope="module")
def fractions(tmp_path_factory):
    """Tabelle 2 replayed in the teaching style (its layered final.svg and its player)."""
    c = get("inertia-stroke-fractions")
    fig = c.figure(rod_ratio=5.0)
    out = tmp_path_factory.mktemp("fractions")
    write_replay(c, fig, out, style="teaching", frames="none")
    return c, fig, out


def test_the_end_state_is_the_books_figure_with_the_values_the_construction_gives(fractions):
    """The last step (final.svg, the player's last step) shows Tabelle 2 as the book draws it: q₀ … q₁₀ as
    ordinates over the stroke with their values, on a sheet cropped to the drawing.  Each value is the
    constructed ordinate read in the pressure scale; it agrees with Gl. (4₁) at the crank angle of Gl. (h)
    for its tenth of the stroke to the three places printed."""
    from construct.constructions import analytic
    from construct.regress.lint import lint_path

    _c, fig, out = fractions
    root = ET.fromstring((out / "final.svg").read_bytes())
    assert "fin" in root.get("class").split()  # the file shows its end state
    # the values: the end state's own lettering (class fo, shown in the end state only)
    values = {"".join(t.itertext()) for g in root.iter(f"{SVG}g") if "fo" in g.get("class", "").split()
              for t in g.iter(f"{SVG}text")}
    lam = 1.0 / 5.0
    for j in range(11):
        w = analytic.crank_angle_from_path(2.0 * j / 10, 1.0, 5.0)
        q = analytic.inertia_two_term(w, lam, 1.0)
        assert f"{'−' if q < 0 else '+'}{abs(q):.3f}".replace(".", ",") in values, j
    # the vertex S of the proportional angle, far below, is a helper: not in the end state
    s = next(e for e in root.iter(f"{SVG}circle") if (e.get("id") or "").endswith("-S"))
    assert "nf" in s.get("class").split()
    # the sheet is the drawing's, and every view of it is legible: no finding at all
    assert lint_path(out / "final.svg").ok, lint_path(out / "final.svg").text()


def test_the_players_last_step_is_the_end_state(fractions):
    _c, fig, out = fractions
    page = (out / "player.html").read_text(encoding="utf-8")
    data = json.loads(re.search(r'<script type="application/json" id="data">(.*?)</script>', page, re.S).group(1))
    assert data["end"] == 1 and 'data.end && k === n ? " fin"' in page  # the script's class at the last step
    # the last view frames the end state, not the whole sheet with the proportional angle far below
    last = data["views"][data["steps"][-1]["v"]]
    full = [float(x) for x in re.search(r'data-full="([^"]+)"', page).group(1).split()]
    assert last[3] < 0.75 * full[3]


def test_the_end_states_file_shows_its_letters_and_points_without_css_variables(fractions):
    """final.svg shows the end state in a renderer without CSS variables or transform-origin (cairosvg): no
    element is scaled by var(--ls), and each point marker is drawn at the letter scale in its radius, at its place."""
    import cairosvg
    import numpy as np
    from PIL import Image

    _c, fig, out = fractions
    text = (out / "final.svg").read_text(encoding="utf-8")
    assert "var(--ls" not in text
    ls = float(re.search(r'style="--ls:([0-9.]+)"', text).group(1))
    radii = {float(r) for r in re.findall(r'<circle class="pt[^"]*"[^>]*? r="([0-9.]+)"', text)}
    # the markers' radii (2.4 and 1.6 canvas px: results and the rest) at the letter scale
    assert radii and all(min(abs(r - 2.4 * ls), abs(r - 1.6 * ls)) < 2e-3 for r in radii), (radii, ls)
    # rasterised, every point marker is drawn where it stands: ink at its centre
    png = out / "final.png"
    svg_w = float(re.search(r'<svg[^>]*? width="([0-9.]+)"', text).group(1))
    x0, y0 = (float(v) for v in re.search(r'viewBox="([-0-9.]+) ([-0-9.]+)', text).groups())
    vb_w = float(re.search(r'viewBox="[-0-9.]+ [-0-9.]+ ([0-9.]+)', text).group(1))
    cairosvg.svg2png(url=str(out / "final.svg"), write_to=str(png), output_width=round(svg_w))
    ink = np.asarray(Image.open(png).convert("L")) < 128
    k = svg_w / vb_w
    centres = [(float(x), float(y)) for x, y in re.findall(r'<circle class="pt result[^"]*" cx="([-0-9.]+)" cy="([-0-9.]+)"', text)]
    assert centres
    assert all(ink[round((y - y0) * k), round((x - x0) * k)] for x, y in centres)


def test_the_end_states_file_draws_its_lines_as_wide_as_the_player_without_vector_effect(fractions):
    """cairosvg, Inkscape and print workflows ignore ``vector-effect: non-scaling-stroke``: final.svg writes its
    lines' widths and dashes in its own units for its one view, so that each is as many screen px wide as the
    player draws it (the style's width in px), whatever renders it."""
    from construct.render.styles import STYLES

    _c, fig, out = fractions
    text = (out / "final.svg").read_text(encoding="utf-8")
    assert "vector-effect" not in text
    svg_w = float(re.search(r'<svg[^>]*? width="([0-9.]+)"', text).group(1))
    vb_w = float(re.search(r'viewBox="[-0-9.]+ [-0-9.]+ ([0-9.]+)', text).group(1))
    k = svg_w / vb_w  # screen px per unit of the file
    assert k > 1.2  # the end view magnifies: a line held at its screen width would be k times too heavy
    st = STYLES["teaching"]
    for sel, px in ((".result", st.result_width), (".construction,.auxiliary", st.construction_width)):
        got = float(re.search(re.escape(sel) + r"\{[^}]*?stroke-width:([0-9.]+)", text).group(1))
        assert got * k == pytest.approx(px, rel=2e-3), sel
    # a dash-dot centre line keeps its screen dashes too (14 px dash in the player)
    dashes = re.search(r"\.dashdot\{stroke-dasharray:([0-9. ]+)", text).group(1).split()
    assert float(dashes[0]) * k == pytest.approx(14.0, rel=2e-3)


@pytest.mark.parametrize("name, params", [("crank", dict(parts=18, rod_ratio=5.0)), ("flywheel-rim", {}),
                                          ("indicator-diagram", {})])
def test_fine_work_is_seen_magnified(name, params):
    """A step's finest detail -- the two closest points it works with, the smallest circle it strikes -- is at
    least 20 px on the player's screen: its view magnifies it so far, or an inset beside the view does.  A
    sliver (the disc of Fig. 28, 0,02 r₁ thick, seen over its whole length) gets an inset."""
    c = get(name)
    fig = c.figure(**params)
    d = Drawing(scene_for(c, fig, ending=True), STYLES["teaching"])
    sc, full = d.scene, d.full_view
    whole = camera.PLAYER_FIGURE_PX[0] / camera.Framing(full).span
    drawn = {m.name: m for m in sc.marks}
    fine_steps = 0
    for s in sc.steps[1:-1]:
        pts = sorted({tuple(round(v, 1) for v in d.vp.px(*drawn[n].geom)) for n in
                      set(s.outputs) | set(s.inputs) | sc.named(s.index) if n in drawn and drawn[n].kind == "point"})
        gaps = [((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2) ** 0.5 for a, b in itertools.combinations(pts, 2)]
        gaps = [g for g in gaps if g > 0.0]
        if not gaps or min(gaps) * whole >= camera.DETAIL_PX or not s.group:
            continue
        fine_steps += 1
        seen = min(gaps) * whole * camera.zoom_of(d.camera_view(s.index), full)
        inset = d.insets[s.index - 1]
        assert seen >= 0.79 * min(camera.DETAIL_PX, min(gaps) * whole * camera.ZOOM_LEVELS[-1]) or inset, \
            (s.index, sc.caption(s.index)[0], seen)
        if inset is not None and seen < 12.0:  # the inset shows the points apart (Dürer's thirds, 0.1 px apart)
            assert min(gaps) * insets.INSET_PX[0] / inset[2] >= 12.0, (s.index, sc.caption(s.index)[0])
    assert fine_steps > 3
    if name == "flywheel-rim":  # the ray of the rectangle's diagonal, over the sliver O r₁
        k = next(s.index for s in sc.steps if s.outputs == ("U6.s",))
        assert d.insets[k - 1] is not None


def test_a_rectangles_diagonal_is_drawn_with_its_rectangle():
    """Fig. 28's hyperbola point by the rectangle's diagonal: at the step that lays the ray from O through the
    corner B, the rectangle's sides through B -- the ordinate at 6/12 r₁ and the horizontal through the rim's
    corner K, b₁/2 off the mid-plane -- are drawn (as the step's inputs), and the inset that magnifies the
    sliver shows the corner B with both sides crossing in it, the mid-plane beneath."""
    c = get("flywheel-rim")
    d = Drawing(scene_for(c, c.figure()), STYLES["teaching"])
    sc = d.scene
    k = next(s.index for s in sc.steps if s.outputs == ("U6.s",))
    B = sc.steps[k - 1].inputs[1]
    sides = set(sc.steps[sc.step_of(B) - 1].inputs)
    assert len(sides) == 2
    assert {sc.step_of(n) for n in sides} <= d.input_steps(k)
    inset = d.insets[k - 1]
    assert inset is not None
    x, y, w, h = inset
    drawn = {m.name: m for m in sc.marks}
    bx, by = d.vp.px(*drawn[B].geom)
    assert x < bx < x + w and y < by < y + h
    for n in sides | {"mid"}:  # and the mid-plane, the rectangle's fourth side
        x0, y0 = d.vp.px(*drawn[n].geom[:2])
        x1, y1 = d.vp.px(*drawn[n].geom[2:4])
        assert segment_meets_box((x, y, x + w, y + h), (x0, y0, x1, y1)), n


def test_the_views_framed_over_arrays_are_the_cameras_own():
    """A live page frames a step at every value at once (:func:`camera.framed_rows`, :func:`edges.clear_edges_rows`):
    each view is the one the camera's scalar :meth:`camera.Framing.view` and :func:`edges.clear_edges` give for
    that canvas, region and letters (one rule in two forms: held equal here, so the faster copy cannot drift)."""
    import numpy as np

    from construct.render import edges

    rng = np.random.default_rng(27)
    n = 300
    W, H = rng.uniform(400, 1600, n), rng.uniform(300, 1600, n)
    x0, y0 = rng.uniform(0, 0.8, n) * W, rng.uniform(0, 0.8, n) * H
    x1 = np.minimum(x0 + rng.uniform(0.003, 0.6, n) * W, W)
    y1 = np.minimum(y0 + rng.uniform(0.003, 0.6, n) * H, H)
    most = rng.choice([1.5, 2.0, 4.0, 8.0], n)
    x0[:5] = np.nan  # (nothing to frame: the whole canvas)
    rows = camera.framed_rows((x0, y0, x1, y1), W, H, most)
    for i in range(n):
        full = (0.0, 0.0, float(W[i]), float(H[i]))
        b = None if np.isnan(x0[i]) else (float(x0[i]), float(y0[i]), float(x1[i]), float(y1[i]))
        want = camera.Framing(full).view(b, max_zoom=float(most[i])) if b is not None else full
        assert tuple(rows[:, i]) == pytest.approx(want, abs=0.011), (i, want)
    # a row of letters along a line across the canvas (the piston positions on the stroke line), the same
    # letters at every level, about views magnified up to the most
    letters = np.array([[x, 0.45 * 700.0, -9.0, -14.0, 9.0, 3.0] for x in np.linspace(30.0, 930.0, 24)])

    def at(lvl, i):
        return (np.repeat(letters[:, :1], len(i), axis=1), np.repeat(letters[:, 1:2], len(i), axis=1),
                letters[:, 2:])

    full = (0.0, 0.0, 960.0, 700.0)
    w = rng.uniform(0.15, 1.0, n) * 960.0
    views = [camera.clip_view(float(cx), 315.0 + float(dy), float(ww), float(ww) * 0.65, full)
             for cx, dy, ww in zip(rng.uniform(0, 960, n), rng.uniform(-60, 60, n), w)]
    grown = edges.clear_edges_rows(np.array(views).T, np.full(n, 960.0), np.full(n, 700.0), at)
    want = edges.clear_edges(views, full, lambda lvl: letters)
    assert sum(v != g for v, g in zip(views, want)) > n // 4  # (the test asks views that cut letters)
    for i in range(n):
        # (to 0.02 px: clear_edges asks each round of the view written to two decimals, the array form of the
        # unrounded one, so a round may grow it a hundredth of a pixel otherwise)
        assert tuple(grown[:, i]) == pytest.approx(want[i], abs=0.021), (i, views[i], want[i])


def test_a_clusters_inset_is_where_the_page_finds_it_and_holds_its_points():
    """A cluster's inset is found anew by the page about the step's finest detail, read off the page's own
    elements (the player's ``detail``: each point's cx, cy as written, to the nearest 0.1 px, halves up -- the
    script's ``Math.round`` --, each circle's or arc's radius as written).  Baumann's effective work at κ = 12,
    step 838 (the arc T8 about U8, 3.28 px round, beside H8 and Q8 at 271.53 and 268.25): read with halves to
    even, the drawing put the inset on the arc and lettered U8 in it while the page moved it to H8 and Q8 and
    drew it empty.  For every cluster's inset the page's box is the drawing's, and points stand in it."""
    c = get("effective-work")
    page = player_html(scene_for(c, c.figure(parts=9, rod_ratio=5, kappa=12), ending=True), STYLES["teaching"])
    data = json.loads(re.search(r'<script type="application/json" id="data">(.*?)</script>', page, re.S).group(1))
    circles = {i: (float(x), float(y), float(r)) for x, y, i, r in
               re.findall(r'<circle [^>]*?cx="([-0-9.]+)" cy="([-0-9.]+)" id="([^"]+)" r="([-0-9.]+)"', page)}
    arcs = {i: float(re.findall(r"-?[0-9.]+(?:e[-+]?[0-9]+)?", d)[2])
            for d, i in re.findall(r'<path [^>]*?d="([^"]+)" id="([^"]+)"', page)}
    tenth = lambda v: math.floor(10 * v + 0.5) / 10  # noqa: E731 (JavaScript's Math.round, to 0.1)
    clusters = [(k, st) for k, st in enumerate(data["steps"], start=1) if st.get("zd") and st.get("z")]
    assert len(clusters) > 20
    for k, st in clusters:
        ids, rounds, size = st["zd"]
        cands, spans = [], []
        for centre, mark, *span in rounds:
            cands.append((circles[mark][2] if mark in circles else arcs[mark], circles[centre][:2]))
            # (the two points the compass is set to: the circle's radius, not compared)
            spans += [sorted((tenth(circles[i][0]), tenth(circles[i][1])) for i in span)] if span else []
        pts = [(tenth(circles[i][0]), tenth(circles[i][1])) for i in ids]
        for a, b in itertools.combinations(pts, 2):
            if 0 < math.dist(a, b) and sorted((a, b)) not in spans:
                cands.append((math.dist(a, b), ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)))
        # (the finest's size, about the first within a tie of it: circles first, then pairs in order)
        fine = min(c[0] for c in cands)
        at = next(c[1] for c in cands if c[0] < fine + camera.DETAIL_TIE_PX)
        x, y, w, h = st["z"]
        assert fine == pytest.approx(size, abs=1e-4), k  # (written to 4 decimals)
        assert (x + w / 2, y + h / 2) == pytest.approx(at, abs=0.02), k
        inside = [p for p, *_ in st["zp"] if x <= circles[p][0] <= x + w and y <= circles[p][1] <= y + h]
        assert inside, (k, st["z"], st["zp"])


@pytest.mark.parametrize("name, params, ks", [
    ("effective-work", {"parts": 9, "rod_ratio": 5, "kappa": 8.0}, (426, 554, 682, 746, 838)),
    ("inertia-stroke-fractions", {"rod_ratio": 5.0}, (105, 149, 211, 233, 303, 311))])
def test_a_compass_steps_detail_is_its_circle_not_the_span_it_carries(name, params, ks):
    """A step that carries a length with the compass (Baumann's acceleration force taken off the steam line: the
    span U-V3 set on the compass, the arc struck about E3; Tafel 2's r·cos ω = O-Y5 carried to U) strikes an arc
    exactly as round as its two points are apart.  Read as the page reads them (points to 0.1 px, radii to 0.01)
    the pair came out 4.3 px apart and the arc 4.33 round, so the inset magnified the pair -- and a live page, its
    points 0.2 px off, the arc, 340 px away (530 px in Tafel 2).  The detail is the circle: the inset is centred on
    the point the compass is set on, the step's first input, at every such step."""
    c = get(name)
    d = Drawing(scene_for(c, c.figure(**params), ending=True), STYLES["teaching"])
    drawn = d.scene.marks_by_name
    for k in ks:
        s = d.scene.steps[k - 1]
        assert s.op == "circle_segment" and camera.compass_span(s) == s.inputs[1:3], k
        x, y, w, h = d.insets[k - 1]
        assert (x + w / 2, y + h / 2) == pytest.approx(d.vp.px(*drawn[s.inputs[0]].geom), abs=0.02), k
