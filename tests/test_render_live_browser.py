"""The live rod-ratio slider in a real browser (headless Chromium, as tests/test_render_player_browser.py drives it).

For several rod ratios the slider is moved and every interpolated coordinate
the page shows is compared with a fresh build at that rod ratio (what
``construct replay --rod-ratio v`` draws: ``Construction.figure`` and the
player's own drawing, fitted to the same view), which the page's data never
saw: the values are chosen off the grid.  The same for the committed
gallery's live players (the crank of 18 parts and the inertia curve).  And the
keys: arrows on the given's slider move the given, not the steps; on the step
slider or the page they step.
"""

from __future__ import annotations

import functools
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from construct.constructions import get
from construct.kernel.instruments import unlettered
from construct.live import live_data, live_givens, live_sweep, player_page
from construct.render.wire import canonical_arc, drawn_numbers, inflated
from construct.gallery import LIVE_PLAYERS, entry_slug, gallery_plan
from construct.render.live import with_live
from construct.render.output import write_replay
from construct.render.scene import MarkKind
from construct.render.styles import STYLES

REPO = Path(__file__).resolve().parents[1]
NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
#: Off-grid rod ratios across the domain, the books' 4 to 6 among them.
VALUES = (1.07, 1.9, 3.3, 4.37, 5.55, 7.1, 23.0, 410.0)


def _gallery_player(slug: str) -> Path:
    """The committed gallery's player of the entry *slug* (the test is skipped in a checkout without one)."""
    path = REPO / "gallery" / slug / "teaching" / "player.html"
    if not path.is_file():
        pytest.skip("no committed gallery in this checkout")
    return path


def _crank_live(tmp_path_factory, parts: int):
    """The page of the crank of *parts* parts built at L/r = 5 with its live rod-ratio slider."""
    c = get("crank")
    fig = c.figure(parts=parts, rod_ratio=5.0)
    out = tmp_path_factory.mktemp(f"crank{parts}")
    write_replay(c, fig, out, style="teaching", frames="none")
    page = out / "live.html"
    page.write_text(with_live((out / "player.html").read_text(), live_data(live_sweep(c, fig, "rod_ratio"))))
    return page


@pytest.fixture(scope="module")
def live_player(tmp_path_factory):
    return get("crank"), {}, _crank_live(tmp_path_factory, 3)


def _open(browser, path):
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    errors: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(path.as_uri())
    page.evaluate("window.constructLive.ready")
    return page, errors


def _live_data(page, given: str | None = None) -> dict:
    """The page's live data of *given* (the first given's without one)."""
    import json

    data = json.loads(page.locator("#live-data").text_content())
    givens = data.get("givens", [data])
    return next(d for d in givens if given in (None, d["given"]))


def _keys(page, given: str | None = None) -> tuple[list[list[str]], list[tuple]]:
    """The page's own keys (from its deflated data) and the marks it draws from the nearer grid value."""
    meta = inflated(_live_data(page, given)["meta_z"])
    flags = set(meta["flags"])
    keys, snapped, at = meta["keys"], [], 0
    for k in keys:
        n = k[2].count("#")
        # a snapped mark: every number of it taken from the nearer grid value (not just an arc's flag)
        if all(c in flags for c in range(at, at + n)):
            snapped.append(tuple(k))
        at += n
    return keys, snapped


def _page_numbers(page, keys):
    # (the keys in and the texts out as JSON strings: Playwright checks a structure value by value; the marks of
    # steps not shown, out of the document, are brought to the shown value when their step is shown: flush does
    # that now, for those alone -- what the page draws it drew in the frame)
    return json.loads(page.evaluate("""keys => { window.constructLive.flush(); return JSON.stringify(JSON.parse(keys).map(k => {
        if (k[0].charAt(0) === '#') return '';  // a step's view and ring: in the player's data, for the shown step
        // (the player keeps the groups a step hides out of the document: find looks there too)
        const el = k[0] ? window.constructPlayer.find(k[0]) : document.getElementById('figure');
        return k[1] === 'viewBox' ? el.getAttribute('data-full') : el.getAttribute(k[1]); })); }""", json.dumps(keys)))


def _compare(page, c, params, v, keys, snapped) -> float:
    """The largest distance (px) between what the page shows and a fresh build at *v*."""
    shown = _page_numbers(page, keys)
    fresh_keys, fresh, _ = drawn_numbers(player_page(c, c.figure(**{**params, "rod_ratio": v}), STYLES["teaching"]))
    at, expect = 0, {}
    for k in fresh_keys:
        n = k[2].count("#")
        expect[k] = fresh[at:at + n]
        at += n
    worst = 0.0
    for k, text in zip(keys, shown):
        k = tuple(k)
        if k[0][0] == "#" or k in snapped:  # views, rings and breaks: the player's data (and the break marks)
            continue
        got = [float(x) for x in NUMBER.findall(text)]
        want = expect[k]
        assert len(got) == len(want), (v, k)
        d = max((abs(a - b) for a, b in zip(got, want)), default=0.0)
        assert d <= 0.5, f"L/r = {v}: {k[0]} {k[1]} off by {d:.3f} px"
        worst = max(worst, d)
    return worst


def test_the_slider_draws_what_a_fresh_replay_draws(browser, live_player):
    c, params, path = live_player
    params = {"parts": 3}
    page, errors = _open(browser, path)
    slider = page.locator('input[type="range"][name="rod_ratio"]')
    assert float(slider.get_attribute("min")) == pytest.approx(math.log10(1.05))
    assert float(slider.get_attribute("max")) == pytest.approx(3.0)
    keys, snapped = _keys(page)
    assert any(k[1] == "cx" for k in keys) and any(k[1] == "d" for k in keys)
    worst = 0.0
    for v in VALUES:
        page.evaluate("v => window.constructLive.set(v)", v)
        assert page.locator("#live-value").text_content() == f"{v:.4g}".replace(".", ",")
        title = page.locator("h1").text_content()  # the title names it too, as the book writes the rod
        assert any(f"{form}{v:.4g}".replace(".", ",") in title for form in ("L/r = ", "r/L = 1/")), title
        # and the givens beside the figure
        rod = page.evaluate("""() => Array.from(document.querySelectorAll('#givens tr'))
            .filter(r => /^(r\\/L|r\\/l|L\\/r)$/.test(r.cells[0].textContent.trim())).map(r => r.cells[1].textContent)""")
        assert rod and all(t.endswith(f"{v:.4g}".replace(".", ",")) for t in rod), rod
        worst = max(worst, _compare(page, c, params, v, keys, snapped))
        rows = page.locator("#live-checks tbody tr")
        assert rows.count() == len(c.checks(c.figure(parts=3, rod_ratio=v)))
    assert not errors, errors
    assert worst > 0.0  # the comparison compared something that moved
    page.close()


def test_marks_of_later_steps_follow_when_their_step_is_shown(browser, live_player):
    """The page redraws the steps shown; a later step, shown after the slider moved, is at the slider's value."""
    c, _, path = live_player
    page, errors = _open(browser, path)
    keys, snapped = _keys(page)
    page.evaluate("() => { const s = document.getElementById('slider'); s.value = 1; s.oninput(); }")
    page.evaluate("v => window.constructLive.set(v)", 3.3)
    page.keyboard.press("End")  # the page has the focus: the last step
    assert page.locator("#figure").get_attribute("data-step") == page.locator("#slider").get_attribute("max")
    assert _compare(page, c, {"parts": 3}, 3.3, keys, snapped) > 0.0
    assert not errors, errors
    page.close()


def test_arrow_keys_move_the_given_on_its_slider_and_step_elsewhere(browser, live_player):
    _, _, path = live_player
    page, errors = _open(browser, path)
    step = lambda: int(page.locator("#figure").get_attribute("data-step"))  # noqa: E731
    given = page.locator('input[type="range"][name="rod_ratio"]')
    n = step()
    # the given's slider has the focus: the arrows move the given (the native range), the step stays
    given.focus()
    before = float(given.input_value())
    page.keyboard.press("ArrowLeft")
    page.keyboard.press("ArrowLeft")
    assert float(given.input_value()) < before and step() == n
    page.wait_for_function("document.getElementById('live-value').textContent !== '5'")  # drawn in the next frame
    page.keyboard.press("ArrowRight")
    assert step() == n
    moved = float(given.input_value())
    # the step slider has the focus: the arrows step, the given stays
    page.locator("#slider").focus()
    page.keyboard.press("ArrowLeft")
    page.keyboard.press("ArrowLeft")
    assert step() == n - 2 and float(given.input_value()) == moved
    # the page has the focus: the arrows step
    page.evaluate("document.activeElement.blur()")
    page.keyboard.press("ArrowRight")
    assert step() == n - 1 and float(given.input_value()) == moved
    assert not errors, errors
    page.close()


@functools.cache
def _gallery_players():
    """(name, params, given) of every live player of the gallery and each of its givens."""
    out = []
    for name, params in gallery_plan():
        if name in LIVE_PLAYERS and (name, params) == next((n, p) for n, p in gallery_plan() if n == name):
            c = get(name)
            with unlettered():  # (the givens only: a build without its letters, in every worker's collection)
                out += [(name, params, g.name) for g in live_givens(c, c.figure(**params))]
    return tuple(out)


#: Where on the slider a drag is compared with a fresh replay: both ends and eight places between (off the
#: grid: no grid value is a round fraction of the domain in log10).
SPOTS = (0.0, 0.071, 0.187, 0.309, 0.433, 0.551, 0.677, 0.793, 0.911, 1.0)


def _owners(path: Path) -> list[tuple[int, str]]:
    """Each label group of the built figure (by its place among the figure's g.lbg) and the point it names: its
    letter's id, or the point of its step that it stands on (a name tag), read off the SVG here, not from the
    page's script."""
    import xml.etree.ElementTree as ET

    text = path.read_text(encoding="utf-8")
    root = ET.fromstring(text[text.index("<svg"):text.index("</svg>") + 6])
    ns = "{http://www.w3.org/2000/svg}"
    step_of, at, out = {}, {}, []
    for g in root.iter(ns + "g"):
        for e in g:
            step_of[e] = g.get("data-step")
    for c in root.iter(ns + "circle"):
        if c.get("id") and "pt" in (c.get("class") or "").split():
            at.setdefault((c.get("cx"), c.get("cy")), []).append((c.get("id"), step_of.get(c)))
    # (the rod's length at a break names no point: the page writes its own, beside the break's marks)
    groups = [g for g in root.iter(ns + "g") if "lbg" in (g.get("class") or "").split()
              and "rodlen" not in (g.get("class") or "").split()]
    for i, g in enumerate(groups):
        m = re.match(r"translate\(([-0-9.e]+)[ ,]+([-0-9.e]+)\)", g.get("transform") or "")
        label = next((t.get("id")[:-6] for t in g.iter(ns + "text") if (t.get("id") or "").endswith("-label")), None)
        here = at.get((m.group(1), m.group(2)), []) if m else []
        step = step_of.get(g)
        own = label or next((p for p, s in here if s == step), here[0][0] if here else None)
        assert own is not None, f"{path.parent.parent.name}: label group {i} names no point"
        out.append((i, own))
    return out


# every point and label group of the figure, in the document or out of it (the groups of steps not shown, the
# letters and points the end state hides), found once and kept: they are the same elements as the given moves
_FIND = """() => { const p = window.constructPlayer, parts = p.groups().flatMap(s => p.parts(s));
    window.__pts = {}; parts.filter(e => e.matches('circle[id]')).forEach(c => { window.__pts[c.id] = c; });
    window.__lbg = parts.filter(e => e.matches('g.lbg')); }"""
_ANCHORS = """() => window.__lbg.map(g => {
    const m = /translate\\(([-0-9.e]+)[ ,]+([-0-9.e]+)\\)/.exec(g.getAttribute('transform')); return [+m[1], +m[2]]; })"""
_POINTS = """ids => ids.map(i => { const c = window.__pts[i]; return [+c.getAttribute('cx'), +c.getAttribute('cy')]; })"""
# a drag through *values* (``input`` events only, as _drag_to), each value drawn in its animation frame and its
# points (_POINTS) and letter anchors (_ANCHORS) read there (the page asks for its frame while the event is
# dispatched, so a frame asked for after it runs after the drawing, in the same frame: a page that drew a frame
# later would be read at the value before)
_DRAG_READING = f"""async ([g, values, ids]) => {{ const out = [], points = {_POINTS}, anchors = {_ANCHORS};
    const i = document.querySelector('#live input[name="' + g + '"]');
    for (const v of values) {{
      i.value = Math.log10(v); i.dispatchEvent(new Event('input'));
      await new Promise(r => requestAnimationFrame(r));
      window.constructLive.flush();  // (the steps not shown: as they are when shown; the shown ones untouched)
      out.push([points(ids), anchors()]);
    }}
    return JSON.stringify(out); }}"""  # (one string: Playwright checks a returned structure value by value)


@pytest.mark.parametrize("name,params,given", _gallery_players(),
                         ids=lambda x: x if isinstance(x, str) else "")
def test_a_drag_keeps_every_point_letter_and_leader_where_a_fresh_replay_draws_them(browser, name, params, given):
    """The committed gallery's live players, dragged as a teacher drags (``input`` events only, never let go)
    across the whole slider at a quarter, three fifths and the last of the steps: every point of the figure (in
    the window or not, of a step shown or not) within 0.5 px of a fresh replay at that value (the construction
    built afresh with the given there, drawn as the player draws it, on the page's own fit to the view), and
    every letter and name tag, with its leader, standing on the point it names (their offsets about it are the
    placer's: the page does not move them).  The checks beside the figure follow the slider."""
    path = _gallery_player(entry_slug(name, params))
    assert 'id="live-data"' in path.read_text(encoding="utf-8"), f"{path} has no slider: rebuild the gallery"
    assert path.stat().st_size <= 2e6
    c = get(name)
    owners = _owners(path)
    page, errors = _open(browser, path)
    data = _live_data(page, given)
    meta = inflated(data["meta_z"])
    lo, hi = math.log10(data["low"]), math.log10(data["high"])  # the slider's ends
    # off any cell across which the drawing jumps (a break appearing: the page draws the nearer side there)
    jumps = [(meta["grid"][j], meta["grid"][j + 1]) for j in meta["jumps"]]
    values = []
    for f in SPOTS:
        u = lo + (hi - lo) * f
        for a, b in jumps:
            if a < u < b:
                u = a if u - a > b - u else b
        values.append(min(data["high"], max(data["low"], 10 ** u)))
    # every point's centre, as a fresh replay at v draws it
    fresh = {v: {i: (float(a["cx"]), float(a["cy"])) for i, a in _fresh_marks(c, params, given, v, MarkKind.POINT).items()}
             for v in values}
    ids = sorted(fresh[values[0]])
    page.evaluate(_FIND)
    n = page.evaluate("window.constructPlayer.data.n")
    for frac in (0.25, 0.6, 1.0):
        k = max(1, round(frac * n))
        # (the camera's glide to the step's view: the drag's first frame takes the step's view at once)
        page.evaluate("k => { const s = document.getElementById('slider'); s.value = k; s.oninput(); }", k)
        # the drag through every value in one call, each drawn in its frame and read there
        for v, (points, anchors) in zip(values, json.loads(page.evaluate(_DRAG_READING, [given, values, ids]))):
            want = fresh[v]
            off = max((math.hypot(x - want[i][0], y - want[i][1]), i) for i, (x, y) in zip(ids, points))
            assert off[0] <= 0.5, f"{name}, {given} = {v:.5g}, step {k}: {off[1]} off by {off[0]:.2f} px"
            assert len(anchors) == len(owners)
            for (i, own), (x, y) in zip(owners, anchors):
                d = math.hypot(x - want[own][0], y - want[own][1])
                assert d <= 0.5, f"{name}, {given} = {v:.5g}, step {k}: the letter of {own} stands {d:.2f} px off it"
    # the checks beside the figure: the construction's at the nearest value swept
    rows = page.locator("#live-checks tbody tr")
    assert rows.count() == len(c.checks(c.figure(**{**params, given: values[-1]})))
    assert page.evaluate("window.constructLive.unowned") == 0
    assert not errors, errors
    page.close()


def test_letters_stay_with_their_points(browser, live_player):
    """Each letter group's anchor keeps its distance to the nearest point as the slider moves (a letter
    left where the built value put it would be far from every point)."""
    _, _, path = live_player
    page, errors = _open(browser, path)
    # (every mark at the shown value: the letters and points the step hides wait until it shows them; those of the
    # steps shown, the ones the end state keeps out of the document among them)
    near = """() => { window.constructLive.flush(); const p = window.constructPlayer;
      const parts = p.groups().filter(s => s.isConnected).flatMap(s => p.parts(s));
      const pts = parts.filter(e => e.matches('circle.pt[id]')).map(c => [+c.getAttribute('cx'), +c.getAttribute('cy')]);
      return parts.filter(e => e.matches('g.lbg:not(.rodlen)')).map(g => {
        const m = /translate\\(([-0-9.e]+)[ ,]+([-0-9.e]+)\\)/.exec(g.getAttribute('transform'));
        return Math.min(...pts.map(p => Math.hypot(p[0] - +m[1], p[1] - +m[2]))); }); }"""
    built = page.evaluate(near)
    assert len(built) > 10
    for v in (1.3, 2.5, 12.0):
        page.evaluate("v => window.constructLive.set(v)", v)
        moved = page.evaluate(near)
        off = [abs(a - b) for a, b in zip(built, moved) if a < 30]  # the letters placed at a point
        assert len(off) > 10 and max(off) <= 1.0, (v, max(off))
    assert not errors, errors
    page.close()


def test_angles_read_off_the_figure_are_written_as_read_at_the_nearer_grid_value(browser, tmp_path):
    """crank-angle letters each crank with the angle AOW read off the replayed figure (61°19′).  Between grid
    values a blend of two readings would print minutes the figure does not have: the page writes each reading as
    the sweep read it at the nearer grid value (at a grid value, what a fresh replay there writes), and says so;
    the plain letters stay.  The readings are found by the sweep itself: they are the labels whose protocol text
    reads an angle ("{∠A O B}")."""
    c = get("crank-angle")
    fig = c.figure(rod_ratio=4.0)
    write_replay(c, fig, tmp_path, style="teaching", frames="none")
    live = live_sweep(c, fig, "rod_ratio", max_values=12)  # a coarse grid: the readings are the point here
    reads = {name for s in fig.protocol.steps for name, text in s.labels if "{∠" in text}
    # (and the end state's furniture: the plate letters each angle too, fin-...)
    marks = [i for i in live.readings if not i.startswith("fin-")]
    plate = [i for i in live.readings if i.startswith("fin-")]
    assert reads and {i.split("-")[1] for i in marks} == reads and plate
    path = tmp_path / "live.html"
    path.write_text(with_live((tmp_path / "player.html").read_text(), live_data(live)))
    page, errors = _open(browser, path)
    # the step before the last: the last shows the end state, which letters the angles as the plate does
    page.evaluate("() => { const s = document.getElementById('slider'); s.value = +s.max - 1; "
                  "s.dispatchEvent(new Event('input')); }")
    said = """ids => ids.map(id => { const t = document.getElementById(id);
        return t && t.getClientRects().length > 0 && getComputedStyle(t).display !== 'none' ? t.textContent : null; })"""
    letters = marks + ["s0001-O-label"]
    built = page.evaluate(said, letters)
    assert all(built)
    for v in (1.3, 6.5, 40.0):
        g = float(live.grid[int(np.argmin(np.abs(np.log10(live.grid) - math.log10(v))))])
        fresh = drawn_numbers(player_page(c, c.figure(rod_ratio=g), STYLES["teaching"]))[2]["texts"]
        for at in (g, g * (1 + 1e-6)):  # at the grid value, and a hair past it (the nearer one's reading)
            page.evaluate("v => window.constructLive.set(v)", at)
            assert page.evaluate(said, letters) == [fresh[i] for i in letters], (v, at)
            page.keyboard.press("End")  # the end state: the plate's own lettering of the angles
            assert page.evaluate(said, plate) == [fresh[i] for i in plate], (v, at)
            page.keyboard.press("ArrowLeft")
        assert page.evaluate(said, letters) != built, v
    assert "nächsten gespeicherten Wert" in page.inner_text("#live")
    page.evaluate("v => window.constructLive.set(v)", 4.0)
    assert page.evaluate(said, letters) == built
    assert errors == []
    page.close()


def test_the_checks_table_keeps_its_rows_and_rewrites_their_cells(browser, live_player):
    """The checks beside the figure change in place: a table rebuilt on every nearer swept value is laid out
    anew at the cost of a frame.  The rows stay the same nodes, and every cell shows the value it shows when
    the slider comes straight to that value."""
    _, _, path = live_player
    page, errors = _open(browser, path)
    rows = "() => Array.from(document.querySelectorAll('#live-checks tbody tr')).map(r => Array.from(r.cells).map(c => c.textContent + '|' + c.className))"
    page.evaluate("v => window.constructLive.set(v)", 1.3)
    at_13 = page.evaluate(rows)
    page.evaluate("() => document.querySelectorAll('#live-checks tbody tr').forEach(r => { r.kept = true; })")
    page.evaluate("v => window.constructLive.set(v)", 41.0)
    at_41 = page.evaluate(rows)
    assert at_41 != at_13 and len(at_41) == len(at_13) > 0
    assert page.evaluate("() => Array.from(document.querySelectorAll('#live-checks tbody tr')).every(r => r.kept)")
    page.evaluate("v => window.constructLive.set(v)", 1.3)
    assert page.evaluate(rows) == at_13
    fresh, _ = _open(browser, path)  # the same value reached straight from the built one
    fresh.evaluate("v => window.constructLive.set(v)", 41.0)
    assert fresh.evaluate(rows) == at_41
    fresh.close()
    assert not errors, errors
    page.close()


def test_while_dragging_the_letters_keep_their_scale_within_a_band_and_take_the_exact_one_when_let_go(browser, live_player):
    """A new letter scale restyles and lays out every letter shown: while the given is dragged the camera keeps
    the shown scale while the letters stay between 4 % smaller (a 9.5 px letter above 9 px) and 20 % larger
    than exact, and a scale it must change it sets near the far side of that band from where the drag is
    heading (18 % larger while the figure grows on the screen, 3 % smaller while it shrinks); the exact one is
    set when the slider is let go.  The figure is shown whole in a low window, so that its height sets the
    scale (which then follows the box: 9.5 px letters)."""
    _, _, path = live_player
    page = browser.new_page(viewport={"width": 1400, "height": 600})
    errors: list[str] = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(path.as_uri())
    page.evaluate("window.constructLive.ready")
    page.evaluate("() => { const z = document.getElementById('zoom'); z.checked = false; z.onchange(); }")
    _glided(page)  # to the whole figure
    scale = "() => +getComputedStyle(document.querySelector('#figure .pt')).getPropertyValue('--ls')"
    grow = """([f, drag]) => { const p = window.constructPlayer; p.full[2] *= f; p.full[3] *= f; p.jump(drag); }"""
    built = page.evaluate(scale)
    assert built > 1.0  # letters at 9.5 px: the scale follows the view
    page.evaluate(grow, [1.02, True])  # a drag's frame: the letters 2 % small, kept
    assert page.evaluate(scale) == built
    page.evaluate(grow, [1.0, False])  # the same view drawn exactly
    exact = built * 1.02
    assert page.evaluate(scale) == pytest.approx(exact, abs=2e-4)
    page.evaluate(grow, [1.015, True])
    page.evaluate(grow, [1.015, True])  # 3 % small: kept
    assert page.evaluate(scale) == pytest.approx(exact, abs=2e-4)
    page.evaluate(grow, [1.015, True])  # 4.4 % small: set, 18 % large (the figure grows on the screen)
    exact *= 1.015 ** 3
    assert page.evaluate(scale) == pytest.approx(exact * 1.18, abs=2e-4)
    page.evaluate(grow, [0.99, True])  # the drag turns: 19.2 % large, kept
    assert page.evaluate(scale) == pytest.approx(exact * 1.18, abs=2e-4)
    page.evaluate(grow, [0.99, True])  # 20.4 % large: set, 3 % small (the figure shrinks on the screen)
    exact *= 0.99 ** 2
    assert page.evaluate(scale) == pytest.approx(exact * 0.97, abs=2e-4)
    # the live slider: dragged, then let go ('change'): the exact scale of the value (as set() draws it)
    page.evaluate("v => window.constructLive.set(v)", 3.3)
    exact = page.evaluate(scale)
    page.evaluate("v => window.constructLive.set(v, true)", 3.3)
    page.evaluate("() => { window.kept = window.constructPlayer.full.slice(); }")
    page.evaluate(grow, [0.975, False])  # an earlier frame of the drag drew a scale 2.5 % off
    page.evaluate("() => { window.kept.forEach((x, i) => { window.constructPlayer.full[i] = x; }); }")
    page.evaluate(grow, [1.0, True])  # the drag's last frame, at 3.3: kept
    assert page.evaluate(scale) == pytest.approx(exact * 0.975, abs=2e-4)
    page.evaluate("""() => new Promise(r => { const i = document.querySelector('#live input[type=range]');
        i.dispatchEvent(new Event('change')); requestAnimationFrame(() => requestAnimationFrame(r)); })""")
    assert page.evaluate(scale) == exact
    assert not errors, errors
    page.close()


def test_while_dragging_the_camera_and_the_zoom_level_stay_while_near_and_let_go_glides_to_the_step(browser, live_player):
    """A new view lays every letter out again for its screen scale and repaints the whole figure, and a new
    zoom level swaps the letters: while the given is dragged the camera keeps its view while the step's view
    lies inside it and fills more than two thirds of it, and keeps the zoom level while the magnification is
    within a fifth of that level's range; a new view leaves the step's view a little room (a tenth of its size
    each way: ahead of it on the side it moves to, half on each side where it keeps still or shrinks), so the
    step's view never leaves the window, and a view that leads the motion is left half as often.  Let go, the
    camera glides to the step's view
    and the level is the exact one.  (The step's view is moved here by hand, as the given would move it.)"""
    _, _, path = live_player
    page, errors = _open(browser, path)
    n = page.evaluate("window.constructPlayer.data.n")
    page.evaluate("() => { const s = document.getElementById('slider'); s.value = %d; s.oninput(); }" % (n // 2))
    _glided(page)
    # (the view shown: while a drag moves the camera, by the transform of the camera's group, the viewBox kept)
    state = """() => [window.constructPlayer.view().map(v => Math.round(v * 100) / 100),
                      document.getElementById('figure').getAttribute('class')]"""
    view, level = page.evaluate(state)
    step_view = """([dx, f]) => { const p = window.constructPlayer, k = +document.getElementById('figure').getAttribute('data-step');
        const v = p.data.views[p.data.steps[k - 1].v];
        v[0] += dx * v[2]; v[2] *= f; v[3] *= f; return v.slice(); }"""  # (and gives it)
    page.evaluate(step_view, [0.0, 0.8])  # shrunk to 80 % (inside): held, the level too
    page.evaluate("() => window.constructPlayer.jump(true)")
    assert page.evaluate(state) == [view, level]
    t = page.evaluate(step_view, [0.0, 0.8])  # to 64 %: the camera goes to it, with 5 % of room on each side
    page.evaluate("() => window.constructPlayer.jump(true)")
    moved, _ = page.evaluate(state)
    room = lambda t: [t[0] - 0.05 * t[2], t[1] - 0.05 * t[3], 1.1 * t[2], 1.1 * t[3]]  # noqa: E731
    assert moved == pytest.approx(room(t), abs=0.01)
    # and the figure is where that view puts it on the screen (centred in the figure's box, as a viewBox fits it),
    # every shown point within half a pixel, though the viewBox is the one the drag found
    where = """v => { const svg = document.getElementById('figure'), b = svg.getBoundingClientRect(), cs = getComputedStyle(svg);
        const x0 = b.left + svg.clientLeft + parseFloat(cs.paddingLeft), y0 = b.top + svg.clientTop + parseFloat(cs.paddingTop);
        const W = svg.clientWidth - parseFloat(cs.paddingLeft) - parseFloat(cs.paddingRight), H = svg.clientHeight
          - parseFloat(cs.paddingTop) - parseFloat(cs.paddingBottom), s = Math.min(W / v[2], H / v[3]);
        return [svg.getAttribute('viewBox'), Array.from(svg.querySelectorAll('circle.pt')).filter(c => c.getClientRects().length).map(c => {
          const r = c.getBoundingClientRect(), x = +c.getAttribute('cx'), y = +c.getAttribute('cy');
          return Math.hypot(r.left + r.width / 2 - (x0 + (W - s * v[2]) / 2 + s * (x - v[0])),
                            r.top + r.height / 2 - (y0 + (H - s * v[3]) / 2 + s * (y - v[1]))); })]; }"""
    box, off = page.evaluate(where, moved)
    assert len(off) >= 3 and max(off) <= 0.5, off
    assert [float(x) for x in box.split()] == pytest.approx(view, abs=0.01)  # (the drag's: not written)
    page.evaluate(step_view, [0.04, 1.0])  # moved by 4 % of its width, inside the room: held
    page.evaluate("() => window.constructPlayer.jump(true)")
    assert page.evaluate(state)[0] == moved
    target = page.evaluate(step_view, [0.02, 1.0])  # 6 % in all: it would leave the view, which goes with it
    page.evaluate("() => window.constructPlayer.jump(true)")
    # (moving right: the room ahead of it, on the right; still upright: half above, half below)
    ahead = [target[0], target[1] - 0.05 * target[3], 1.1 * target[2], 1.1 * target[3]]
    assert page.evaluate(state)[0] == pytest.approx(ahead, abs=0.01)
    page.evaluate("() => window.constructPlayer.move()")  # let go: a glide to the step's view
    _glided(page)
    shown = page.evaluate(state)
    assert shown[0] == pytest.approx(target, abs=0.01)
    page.evaluate("() => window.constructPlayer.jump(false)")  # the view and level exactly: as the glide left them
    assert page.evaluate(state)[1] == shown[1]
    assert not errors, errors
    page.close()


# a slow drag (15 ``input`` events, each drawn in its frame) from *a* to *b*, read at every frame: the camera's view,
# the step's view at the value (what letting go frames) and the crank circle's width on the screen (px; null where
# none is shown)
_CAMERA_DRAG = """async ([g, a, b]) => { const i = document.querySelector('#live input[name="' + g + '"]'), out = [];
    const svg = document.getElementById('figure'), p = window.constructPlayer;
    for (let j = 1; j <= 15; j++) {
      i.value = Math.log10(a) + (Math.log10(b) - Math.log10(a)) * j / 15; i.dispatchEvent(new Event('input'));
      await new Promise(r => requestAnimationFrame(r));
      const crank = Array.from(svg.querySelectorAll('g[data-step] circle[id$="-crank"]'))
        .filter(e => e.isConnected && getComputedStyle(e).display !== 'none')[0];
      out.push([Math.pow(10, +i.value), p.view(), p.target().slice(),
                crank ? crank.getBoundingClientRect().width : null]);
    }
    return out; }"""


@pytest.mark.parametrize("name,params,given", [g for g in _gallery_players() if g[0] in
                                               ("piston-force", "tangential-pressure", "two-cranks") and g[2] != "kappa"],
                         ids=lambda x: x if isinstance(x, str) else "")
def test_while_dragging_the_camera_keeps_what_the_step_frames_in_the_window(browser, name, params, given):
    """A teacher drags the given slowly from the book's value to the slider's low end and on to its high end, at a
    quarter, three fifths and the last of the steps: at every frame the camera's view holds the step's view at
    that value (what letting go frames: nothing the step frames leaves the window), and at the last step (the
    end state, the plate's figure) the crank circle keeps a sensible size (50 px across at least in a
    1400 × 1000 px window).  Let go, the camera frames the step's view."""
    path = _gallery_player(entry_slug(name, params))
    page, errors = _open(browser, path)
    data = _live_data(page, given)
    n = page.evaluate("window.constructPlayer.data.n")
    inside = lambda box, v, tol: (box[0] >= v[0] - tol and box[1] >= v[1] - tol  # noqa: E731
                                  and box[2] <= v[0] + v[2] + tol and box[3] <= v[1] + v[3] + tol)
    for frac in (0.25, 0.6, 1.0):
        k = max(1, round(frac * n))
        page.evaluate("k => { const s = document.getElementById('slider'); s.value = k; s.oninput(); }", k)
        _at_step_view(page)
        for a, b in ((data["initial"], data["low"]), (data["low"], data["high"])):
            for v, view, step, crank in page.evaluate(_CAMERA_DRAG, [given, a, b]):
                box = [step[0], step[1], step[0] + step[2], step[1] + step[3]]
                assert inside(box, view, 0.01), f"{name} step {k}, {given} = {v:.4g}: the step's view {step} leaves {view}"
                assert k < n or crank is None or crank >= 50, (name, k, v, crank)
        page.evaluate("() => document.querySelector('#live input[type=range]').dispatchEvent(new Event('change'))")
        _glided(page)
        view, step = page.evaluate("""() => [document.getElementById('figure').getAttribute('viewBox').split(' ')
            .map(Number), window.constructPlayer.target()]""")
        assert view == pytest.approx(step, abs=0.01), (name, k)
    assert not errors, errors
    page.close()


def test_a_drag_keeps_the_zoom_level_near_its_range_and_letting_go_makes_it_exact(browser):
    """The committed gallery's inertia curve at the step before its last (the last step frames the whole
    construction away from the book's value), dragged in legs across L/r = 4 ... 1.15 ... 9 (its
    view magnifies more as L/r falls towards 1, where the curve's points crowd the crank circle's ends): a drag
    keeps the shown zoom level while near its range (a new level swaps the letters, a frame of its own), and
    once the slider is let go the level is the one the step's view has."""
    path = _gallery_player("inertia-curve-rod-ratio-4")
    page, errors = _open(browser, path)
    page.keyboard.press("ArrowLeft")
    _at_step_view(page)
    level = "() => document.getElementById('figure').getAttribute('class')"
    drag = """([a, b]) => new Promise(res => { let j = 0; function f(){ j++;
        window.constructLive.set(a * Math.pow(b / a, j / 15), true); if (j < 15) requestAnimationFrame(f); else res(); }
      requestAnimationFrame(f); })"""
    let_go = "() => document.querySelector('#live input[type=range]').dispatchEvent(new Event('change'))"
    held = 0
    for a, b in [(4.0, 1.3), (1.3, 1.8), (1.8, 1.15), (1.15, 3.0), (3.0, 1.2), (1.2, 9.0)]:
        page.evaluate(drag, [a, b])
        dragged = page.evaluate(level)
        page.evaluate(let_go)
        _glided(page)
        after = page.evaluate(level)
        page.evaluate("() => window.constructPlayer.jump(false)")  # the exact view and level at once
        assert page.evaluate(level) == after, (a, b)
        held += dragged != after
    assert held >= 1  # some leg ended with a level kept by the drag
    assert not errors, errors
    page.close()


def test_a_drag_draws_every_mark_in_the_window_or_not_shown_or_not(browser, live_player):
    """A drag (``input`` events only, never let go) draws every mark at every moment: those in the window, those
    outside it and those of steps not shown yet (out of the document), each where a fresh replay draws it; a
    step shown next is right at once."""
    c, _, path = live_player
    page, errors = _open(browser, path)
    keys, snapped = _keys(page)
    page.evaluate("() => { const s = document.getElementById('slider'); s.value = 30; s.oninput(); }")
    _at_step_view(page)
    for v in (1.9, 3.3, 4.37, 7.1):
        _drag_to(page, "rod_ratio", v)
        assert _compare(page, c, {"parts": 3}, v, keys, snapped) > 0.0
    page.keyboard.press("End")
    assert _compare(page, c, {"parts": 3}, 7.1, keys, snapped) > 0.0
    assert not errors, errors
    page.close()


#: the camera at rest: the view shown is the one it glides to (the step's, or the whole figure's), the glide's
#: last frame drawn (that frame sets it to within rounding: from + (to - from) * 1)
_AT_REST = """() => { const p = window.constructPlayer, v = p.view(), t = p.target();
    return v.every((x, i) => Math.abs(x - t[i]) <= 1e-9 * (1 + Math.abs(t[i]))); }"""


def _glided(page) -> None:
    """Waits until the camera's glide (350 ms of animation frames) has ended where it goes: two frames for the
    page's own handlers first (the slider's let-go draws in the next frame, and starts the glide there), then
    until the view shown is the target.  A fixed wait past the glide's end (500-900 ms) left this worker and
    the browser both idle for the rest of it."""
    page.evaluate("() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")
    page.wait_for_function(_AT_REST, polling=50, timeout=10_000)


def _at_step_view(page) -> None:
    """The camera where its glide to the step's view ends (``jump(false)``: the view, letters and level exact), at
    once: a drag's frames start from there, without the glide's frames drawn and waited for first."""
    page.evaluate("() => window.constructPlayer.jump(false)")


def _drag_to(page, given: str, v: float) -> None:
    """The given's slider moved to *v* as a drag moves it: an ``input`` event (no ``change``), drawn in the next
    animation frame (awaited by a frame asked for after the page's, as in _DRAG_READING)."""
    page.evaluate("""([g, v]) => new Promise(r => { const i = document.querySelector('#live input[name="' + g + '"]');
        i.value = Math.log10(v); i.dispatchEvent(new Event('input'));
        requestAnimationFrame(r); })""", [given, v])


def _fresh_svg(c, params: dict, given: str, v: float):
    """The figure of a fresh replay's player page at *v*: its root (ElementTree)."""
    import xml.etree.ElementTree as ET

    page = player_page(c, c.figure(**{**params, given: v}), STYLES["teaching"])
    return ET.fromstring(page[page.index("<svg"):page.index("</svg>") + 6])


def _fresh_marks(c, params: dict, given: str, v: float, kind=None) -> dict[str, dict[str, str]]:
    """Every mark's attributes as a fresh replay's player page draws them, by element id: the construction built
    afresh at *v*, each mark drawn by the drawing's own code (``mark_geometry``) on the page's fit to the view, as
    :class:`construct.live.Measure` draws it (tests/test_live.py holds that to the page's numbers) -- without laying
    the page's letters out, nor reading the captions into the figure's letters, which these marks do not depend on
    (a tenth of a page's cost; an unlettered build, half of a build's).  *kind*: the marks of that kind only (an
    area: its outline, not its hatching)."""
    from construct.kernel.instruments import unlettered
    from construct.render.output import scene_for
    from construct.render.svg import mark_geometry
    from construct.render.viewport import Viewport

    st = STYLES["teaching"]
    with unlettered():
        scene = scene_for(c, c.figure(**{**params, given: v}))
    vp = Viewport.fit(scene.bbox, st, 0)
    return {m.id + suffix: attrs for m in scene.marks if kind in (None, m.kind)
            for suffix, _, attrs in mark_geometry(m, vp, st)[:1 if kind is not None else None]}


def _numbers(e, attrs) -> list[float]:
    return [float(x) for a in attrs for x in NUMBER.findall(e.get(a) or "")]


#: The last step shows the end state (the figure as the plate draws it: its own marks, class fo, and the plate's
#: furniture), swept as the rest; the step before it the construction's marks.
AT_STEPS = ["before-end", "end"]


def _at(page, at: str) -> None:
    """The player at its last step ('end': the end state) or at the step before it."""
    page.keyboard.press("End")
    if at == "before-end":
        page.keyboard.press("ArrowLeft")


@pytest.mark.parametrize("at", AT_STEPS)
def test_a_broken_rod_stays_broken_with_its_length_written(browser, live_player, at):
    """Past L/r = 4 the crank's long rod is broken out of the figure: while the slider is dragged the page draws
    the break's marks on every line that crosses it (the axis, the rod drawn to its crosshead), where a fresh
    replay draws them, and writes the rod's length at the break: the figure never claims a short rod."""
    c, _, path = live_player
    page, errors = _open(browser, path)
    _at(page, at)
    # (the marks of an end state's own line: drawn in the end state alone, as its line)
    # (shown as the browser computes it: the end state's style sheet shows its .fo groups, which outranks an
    # attribute display=none -- marks of a break the figure no longer has were seen at L/r = 1.5)
    marks = """() => Array.from(document.querySelectorAll('#figure .brkg > *'))
        .filter(e => e.isConnected && e.getClientRects().length && getComputedStyle(e.parentNode).display !== 'none')
        .map(e => [e.getAttribute('class'), e.tagName === 'path' ? e.getAttribute('d') :
          [e.getAttribute('x1'), e.getAttribute('y1'), e.getAttribute('x2'), e.getAttribute('y2')].join(' ')])"""
    label = """() => { const g = document.querySelector('#figure .rodlen'); return g && g.getAttribute('display') !== 'none'
        ? g.querySelector('text:last-of-type').textContent : null; }"""
    plate_rod = """() => { const t = Array.from(document.querySelectorAll('#furniture g.fo.end text.fur-text'))
        .find(t => t.textContent.startsWith('L =')); return t && t.getClientRects().length ? t.textContent : null; }"""
    for v in (3.5, 8.0, 50.0, 1.5):
        _drag_to(page, "rod_ratio", v)
        root = _fresh_svg(c, {"parts": 3}, "rod_ratio", v)
        # before the end the end state's own marks (group .fo, shown at the last step alone) are not drawn
        # and in it the marks of the lines it leaves out (group .nf) are not
        hidden = {d for g in root.iter() if ("nf" if at == "end" else "fo") in (g.get("class") or "").split()
                  for d in g.iter()}
        want = [e for e in root.iter() if (e.get("class") or "") in ("brk", "brkline") and e not in hidden]
        got = page.evaluate(marks)
        assert len(got) == len(want), (v, len(got), len(want))
        # the same marks, each within 0.5 px (matched by their numbers: the page draws each line's beside it)
        for cls, text in got:
            nums = [float(x) for x in NUMBER.findall(text)]
            best = min(max(abs(a - b) for a, b in zip(nums, _numbers(w, ("d", "x1", "y1", "x2", "y2"))))
                       for w in want if w.get("class") == cls)
            assert best <= 0.5, (v, cls, best)
        if at == "end":  # the plate's dimension writes it at every value (the page's own at the break is not shown)
            assert page.evaluate(plate_rod) == f"L = {v:g} r".replace(".", ",") and page.evaluate(label) is None, v
        else:
            assert page.evaluate(label) == (f"L = {v:g} r".replace(".", ",") if want else None)
    assert not errors, errors
    page.close()


@pytest.mark.parametrize("at", AT_STEPS)
def test_every_element_of_the_figure_is_where_a_fresh_replay_draws_it(browser, live_player, at):
    """The general form of 'every mark, every moment': while the slider is dragged, every element of the figure's
    steps -- marks, letters and name tags by their groups' anchors (the letters and leaders about an anchor are
    where the placer put them at the book's value: the page keeps them there) -- in the order of the figure,
    has the numbers of the same element of a fresh replay's page, within 0.5 px; the break marks (the page
    draws them beside their lines) and the rod's length at the break are held above."""

    c, _, path = live_player
    page, errors = _open(browser, path)
    _at(page, at)
    read = """() => { const out = []; window.constructLive.flush();
      window.constructPlayer.groups().forEach(s => window.constructPlayer.parts(s).forEach(e => {
        // (views: data, not drawn; a step's view box is out of the document while its step is not shown)
        if (e.closest('.brkg') || e.closest('.rodlen') || e.closest('#views') || e.classList.contains('view')) return;
        // a letter's or leader's place about its anchor is the placer's (kept): its group's anchor is compared
        // (a letter group or point the end state keeps out of the document has no parent)
        if (e.parentNode && e.parentNode.closest && e.parentNode.closest('g.lbg')) return;
        const t = e.getAttribute('transform') || '';
        out.push([e.tagName, ['cx', 'cy', 'r', 'x1', 'y1', 'x2', 'y2', 'd', 'x', 'y'].map(a => e.getAttribute(a) || '').join(' ') + ' ' + t]);
      })); return out; }"""
    for v in (1.6, 3.3, 7.1, 23.0):
        _drag_to(page, "rod_ratio", v)
        got = page.evaluate(read)
        root = _fresh_svg(c, {"parts": 3}, "rod_ratio", v)
        ns = "{http://www.w3.org/2000/svg}"
        want = []
        views = root.find(f".//{ns}g[@id='views']")
        skip = set(views.iter()) if views is not None else set()
        for s in root.iter(ns + "g"):
            if s.get("data-step") is None or s in skip:
                continue
            inside = {d for g in s.iter(ns + "g") if "lbg" in (g.get("class") or "").split() for d in g.iter() if d is not g}
            for e in s.iter():
                # (a break's marks: the page draws its own beside their lines, held above)
                if e is s or e in inside or e.get("class") in ("brk", "brkline", "lbg rodlen"):
                    continue
                t = e.get("transform") or ""
                want.append([e.tag[len(ns):], " ".join(e.get(a) or "" for a in ("cx", "cy", "r", "x1", "y1", "x2",
                                                                                  "y2", "d", "x", "y")) + " " + t])
        assert len(got) == len(want) and [g[0] for g in got] == [w[0] for w in want], v
        worst = (0.0, None)
        for (tag, a), (_, b) in zip(got, want):
            na, nb = [float(x) for x in NUMBER.findall(a)], [float(x) for x in NUMBER.findall(b)]
            assert len(na) == len(nb), (v, tag, a, b)
            if "A" in a and len(na) == 9:  # an arc: the page draws it counter-clockwise (render/wire.py canonical_arc)
                na, nb = canonical_arc(na), canonical_arc(nb)
            worst = max(worst, (max((abs(x - y) for x, y in zip(na, nb)), default=0.0), (tag, a, b)))
        assert worst[0] <= 0.5, (v, worst)
    assert not errors, errors
    page.close()


def test_the_end_state_follows_the_slider_with_its_furniture_and_the_rod_it_writes(browser, live_player):
    """The last step draws the figure as the book's plate draws it (class fin) at every value of a drag: its own
    marks (class fo) and the plate's furniture (the rod and the centre line it adds, its dimensions) each where a
    fresh replay's page draws it, within 0.5 px, and the rod's dimension says the rod's length at that value."""
    c, _, path = live_player
    page, errors = _open(browser, path)
    page.keyboard.press("End")
    fin = "() => document.getElementById('figure').classList.contains('fin')"
    read = """() => Array.from(document.querySelectorAll('#furniture > g.fo.end > [id]')).map(e => [e.id,
        ['x1', 'y1', 'x2', 'y2', 'cx', 'cy', 'r', 'd', 'x', 'y', 'transform'].map(a => e.getAttribute(a) || '').join(' '),
        e.tagName === 'text' ? e.textContent : '', getComputedStyle(e).display])"""
    assert page.evaluate(fin)
    for v in (1.6, 3.3, 8.0, 23.0):
        _drag_to(page, "rod_ratio", v)
        assert page.evaluate(fin), v
        got = page.evaluate(read)
        root = _fresh_svg(c, {"parts": 3}, "rod_ratio", v)
        want = {e.get("id"): e for e in root.iter() if (e.get("id") or "").startswith("fin-")}
        assert got and [g[0] for g in got] == list(want), v
        for ident, text, words, display in got:
            e = want[ident]
            assert display != "none", (v, ident)
            nums = [float(x) for x in NUMBER.findall(text)]
            fresh = _numbers(e, ("x1", "y1", "x2", "y2", "cx", "cy", "r", "d", "x", "y", "transform"))
            assert len(nums) == len(fresh) and max(abs(a - b) for a, b in zip(nums, fresh)) <= 0.5, (v, ident)
            if words.startswith("L ="):
                assert words == f"L = {v:g} r".replace(".", ","), (v, words)
            elif words:
                assert words == "".join(e.itertext()), (v, ident, words)
    assert not errors, errors
    page.close()


# every element of the connected step groups (the letters and points the end state keeps out of the document
# among them) with its numbers, and whether the page renders it (has a box)
_SHOWN_AND_HIDDEN = """() => window.constructPlayer.groups().filter(s => s.isConnected).flatMap(s => window.constructPlayer.parts(s))
    .filter(e => !e.closest('.brkg') && !e.closest('.rodlen') && !e.closest('#views') && !(e.parentNode && e.parentNode.closest && e.parentNode.closest('g.lbg')))
    .map(e => [e.getClientRects().length > 0, ['cx', 'cy', 'r', 'x1', 'y1', 'x2', 'y2', 'd', 'transform'].map(a => e.getAttribute(a) || '').join(' ')])"""


def test_a_drag_writes_what_the_page_shows_and_a_step_draws_what_it_shows_anew_before_it_is_seen(browser, live_player):
    """The end state (the last step drawn as the plate) hides most of the construction's letters and points: a
    drag writes what the page shows, each at the dragged value -- constructLive.flush(), which brings every mark to
    the shown value, moves none of them -- and leaves what the step hides (a number written into a hidden mark
    restyles it all the same: three of four elements a drag wrote at piston-force's end state were hidden), until
    a step shows it: the step before the end shows the letters again, at the dragged value before they are seen."""
    _, _, path = live_player
    page, errors = _open(browser, path)
    _at(page, "end")
    built = page.evaluate(_SHOWN_AND_HIDDEN)
    for v in (2.2, 7.1):
        _drag_to(page, "rod_ratio", v)
    dragged = page.evaluate(_SHOWN_AND_HIDDEN)
    assert [d[0] for d in dragged] == [b[0] for b in built]
    hidden = [i for i, (shown, _) in enumerate(built) if not shown]
    assert len(hidden) > 20 and sum(dragged[i][1] != built[i][1] for i, (shown, _) in enumerate(built) if shown) > 10
    assert all(dragged[i][1] == built[i][1] for i in hidden), "a hidden mark was written while dragging"
    page.evaluate("window.constructLive.flush()")
    flushed = page.evaluate(_SHOWN_AND_HIDDEN)
    assert [f for f in flushed if f[0]] == [d for d in dragged if d[0]], "a shown mark was not at the dragged value"
    assert any(flushed[i][1] != built[i][1] for i in hidden)
    # the hidden ones behind again (another value), then a step that shows them
    _drag_to(page, "rod_ratio", 3.3)
    page.keyboard.press("ArrowLeft")
    before = page.evaluate(_SHOWN_AND_HIDDEN)
    shown_now = [i for i, (shown, _) in enumerate(before) if shown]
    assert sum(1 for i in hidden if i < len(before) and before[i][0]) > 10  # (the letters the end state hid)
    page.evaluate("window.constructLive.flush()")
    after = page.evaluate(_SHOWN_AND_HIDDEN)
    assert all(after[i] == before[i] for i in shown_now), "a mark the step shows again was not at the shown value"
    assert not errors, errors
    page.close()


def test_a_drag_reads_no_layout_of_the_figure_before_it_writes(browser, live_player):
    """A drag's frame reads the figure's box from what the page kept, not from the element: the given's slider has
    just moved, and a read of the element's size then lays the page out once more in every frame, before anything is
    written.  The kept box follows the window (a resize reads it anew)."""
    _, _, path = live_player
    page, errors = _open(browser, path)
    _at(page, "end")
    page.evaluate("window.constructLive.set(4.0)")
    _at_step_view(page)
    # each read of the figure's size counted (the element's own getters before the prototype's)
    page.evaluate("""() => { const svg = document.getElementById('figure'); window.sizeReads = 0;
      ['clientWidth', 'clientHeight'].forEach(a => { const get = Object.getOwnPropertyDescriptor(Element.prototype, a).get;
        Object.defineProperty(svg, a, {configurable: true, get() { window.sizeReads++; return get.call(this); }}); }); }""")
    reads = page.evaluate("""async () => { window.sizeReads = 0;
      for (let i = 1; i <= 12; i++) await new Promise(r => requestAnimationFrame(() => { window.constructLive.set(4.0 + 0.01 * i, true); setTimeout(r, 0); }));
      return window.sizeReads; }""")
    assert reads == 0, f"a drag read the figure's size {reads} times in 12 frames"
    page.set_viewport_size({"width": 1100, "height": 900})
    page.evaluate("() => new Promise(r => requestAnimationFrame(() => setTimeout(r, 0)))")
    assert page.evaluate("window.sizeReads") > 0  # (a resize: the box read anew)
    assert not errors, errors
    page.close()


@pytest.mark.parametrize("at", ["end", "before-end"])
def test_a_new_letter_scale_restyles_the_letters_and_points_shown_and_not_those_hidden(browser, at):
    """The letter scale (--ls) is declared by one rule on the letters and points that read it; a new value restyles
    every element that rule matches, shown or hidden, in the frame it changes.  The piston-force's end state shows
    its plate's letters (.pf) and the points it keeps; the rule matched all 512 letters and points of the figure's
    steps there, 64 of them shown (4.5 ms of a drag's frame).  At the end state (and the step before it) every
    letter and point shown is matched (it keeps its size on the screen), and few that are hidden."""
    path = _gallery_player("piston-force")
    page, errors = _open(browser, path)
    _at(page, at)
    _glided(page)
    got = page.evaluate("""() => {
      const rule = Array.from(document.styleSheets).flatMap(s => Array.from(s.cssRules))
        .find(r => r.style && r.style.getPropertyValue('--ls'));
      const on = e => e.getClientRects().length > 0;
      const matched = Array.from(document.querySelectorAll(rule.selectorText));
      const shown = Array.from(document.querySelectorAll('#figure .lbg>*, #figure .pt')).filter(on);
      return {matched: matched.length, hidden: matched.filter(e => !on(e)).length, shown: shown.length,
              unmatched: shown.filter(e => !e.matches(rule.selectorText)).length}; }""")
    assert got["shown"] >= 20 and got["unmatched"] == 0, got
    if at == "end":
        # (hidden and matched: a point in a group the end state leaves out, whose own class does not say so)
        assert got["hidden"] <= 0.1 * got["matched"], got
    assert not errors, errors
    page.close()


# the elements a zoom level's rules style (the subjects of the rules the level's class on the figure selects by,
# .zl3 .lbg>.lb and the like), in the document, and how many of them the page shows
_ZOOM_MATCHED = """() => {
    const svg = document.getElementById('figure'), subjects = new Set(), hit = new Set();
    Array.from(document.styleSheets).flatMap(s => Array.from(s.cssRules)).forEach(r => (r.selectorText || '').split(',')
      .forEach(sel => { const m = /^\\.zl[0-9]+\\s+(.+)$/.exec(sel.trim()); if (m) subjects.add(m[1]); }));
    subjects.forEach(sel => svg.querySelectorAll(sel).forEach(e => hit.add(e)));
    const all = Array.from(hit);
    return {matched: all.length, shown: all.filter(e => e.getClientRects().length > 0).length}; }"""
# every point and label group of the step groups (in the document or out of it) in the figure's order: its anchor
# or centre, whether it is in the document, whether its step's group is, and whether the page shows it
_LETTERS_AND_POINTS = """() => { const p = window.constructPlayer;
    return JSON.stringify(p.groups().flatMap(s => p.parts(s).map(e => [s, e])).filter(([s, e]) => e.matches('g.lbg:not(.rodlen), circle.pt'))
      .map(([s, e]) => [e.tagName, e.getAttribute('id') || '', e.tagName === 'circle' ? e.getAttribute('cx') + ' ' + e.getAttribute('cy')
                 : e.getAttribute('transform'), e.isConnected, s.isConnected, e.getClientRects().length > 0])); }"""


def test_the_end_states_hidden_letters_and_points_leave_the_document_and_come_back_where_a_fresh_build_puts_them(
        browser, live_player):
    """The end state shows the plate's own letters and the points it keeps, and hides the steps' other letters and
    points (display: none), but a new zoom level's class restyles every element its rules match, shown or hidden:
    at piston-force's end state 627-661 of them a change, 63 shown, the worst frames of a drag over the domain.  While
    a given is live, the letters and points the end state hides are out of the document there: the zoom level's
    rules match only what is shown, at every level and every value of a drag.  A step before the end brings
    them back, each letter and point where a fresh build at the dragged value puts it (no flush: as drawn)."""
    c, _, path = live_player
    page, errors = _open(browser, path)
    _at(page, "end")
    _glided(page)
    built = json.loads(page.evaluate(_LETTERS_AND_POINTS))
    hidden = [e for e in built if not e[5]]
    assert len(hidden) > 20 and len(built) - len(hidden) >= 4, built
    assert not any(e[3] for e in hidden), "a letter or point the end state hides is in the document"
    # at every value of a drag, whichever zoom level the end state takes (each set on the figure in turn)
    for v in (1.07, 1.9, 3.3, 7.1, 23.0, 410.0):
        _drag_to(page, "rod_ratio", v)
        got = page.evaluate("""() => { const svg = document.getElementById('figure'), was = svg.getAttribute('class');
          const out = window.constructPlayer.data.levels.map((_, x) => { svg.setAttribute('class', 'zl' + x + ' fin'); return m(); });
          svg.setAttribute('class', was); return out; }""".replace("m()", "(" + _ZOOM_MATCHED + ")()"))
        assert all(g["shown"] >= 4 and g["matched"] == g["shown"] for g in got), (v, got)
    # back a step, at the dragged value: every letter and point of the steps in the document again, those shown where
    # a fresh build puts them
    page.keyboard.press("ArrowLeft")
    page.evaluate("() => new Promise(r => requestAnimationFrame(() => requestAnimationFrame(r)))")
    back = json.loads(page.evaluate(_LETTERS_AND_POINTS))
    assert len(back) == len(built) and all(e[3] for e in back if e[4]), "a letter or point was left out of its step"
    root = _fresh_svg(c, {"parts": 3}, "rod_ratio", 410.0)
    ns = "{http://www.w3.org/2000/svg}"
    views = root.find(f".//{ns}g[@id='views']")
    skip = set(views.iter()) if views is not None else set()
    fresh = [e for s in root.iter(ns + "g") if s.get("data-step") is not None and s not in skip for e in s.iter()
             if (e.tag == ns + "g" and "lbg" in (e.get("class") or "").split() and "rodlen" not in (e.get("class") or ""))
             or (e.tag == ns + "circle" and "pt" in (e.get("class") or "").split())]
    assert [e[1] for e in back] == [f.get("id") or "" for f in fresh]
    shown = 0
    for (tag, ident, at, _, _, on), f in zip(back, fresh):
        want = f"{f.get('cx')} {f.get('cy')}" if tag == "circle" else f.get("transform")
        got_xy, want_xy = [float(x) for x in NUMBER.findall(at)], [float(x) for x in NUMBER.findall(want)]
        if on:
            shown += 1
            d = max(abs(a - b) for a, b in zip(got_xy, want_xy))
            assert d <= 0.5, f"{tag} {ident} at {at}, a fresh build at L/r = 410 puts it at {want}"
    assert shown >= 20
    assert not errors, errors
    page.close()


def test_letters_that_come_to_lie_on_one_another_give_way(browser, live_player):
    """Near L/r = 1 the crank's piston points crowd the stroke's end: the page lets a later letter give way where
    it would lie on another (never a pile of letters), and at the book's value hides none."""
    _, _, path = live_player
    page, errors = _open(browser, path)
    page.keyboard.press("End")
    boxes = """() => Array.from(document.querySelectorAll('#figure g.lbg'))
        .filter(g => g.isConnected && g.getAttribute('visibility') !== 'hidden' && !g.closest('[display=none]'))
        .map(g => g.querySelector('text:last-of-type')).filter(t => t && t.getClientRects().length)
        .map(t => { const r = t.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom, t.textContent]; })"""
    hidden = "() => document.querySelectorAll('#figure g.lbg[visibility=hidden]').length"
    assert page.evaluate(hidden) == 0
    for v in (1.07, 1.2, 2.0):
        _drag_to(page, "rod_ratio", v)
        shown = page.evaluate(boxes)
        pile = [(a[4], b[4]) for i, a in enumerate(shown) for b in shown[i + 1:]
                if a[0] < b[2] - 1 and b[0] < a[2] - 1 and a[1] < b[3] - 1 and b[1] < a[3] - 1]
        assert not pile, (v, pile)
    _drag_to(page, "rod_ratio", 5.0)
    assert page.evaluate(hidden) == 0
    assert not errors, errors
    page.close()


def test_two_givens_move_one_at_a_time_and_the_page_says_which(browser):
    """Tangential-pressure takes the rod and Baumann's κ: each slider is named as in the protocol, moving one
    sets the other back to the book's value (each sweep is taken with the other there), and the title, the givens
    and the checks name the shown values."""
    path = _gallery_player(entry_slug("tangential-pressure", {"rod_ratio": 5.0, "parts": 18, "kappa": 8.0}))
    page, errors = _open(browser, path)
    kappa = page.locator('input[type="range"][name="kappa"]')
    rod = page.locator('input[type="range"][name="rod_ratio"]')
    assert kappa.count() == 1 and rod.count() == 1
    _drag_to(page, "rod_ratio", 3.0)
    assert "1/3" in page.locator("#givens").inner_text() and "r/L = 1/3" in page.locator("h1").inner_text()
    _drag_to(page, "kappa", 2.0)
    assert float(rod.input_value()) == pytest.approx(math.log10(5.0))  # the rod back at the book's value
    assert "r/L = 1/5" in page.locator("h1").inner_text() and "κ = P/Bₘₐₓ = 2" in page.locator("h1").inner_text()
    assert "P/Bₘₐₓ = 2" in page.locator("#givens").inner_text()
    assert "κ = " in page.locator("#live-at").inner_text()  # the checks at the nearest κ swept
    assert "einzeln" in page.locator("#live").inner_text()
    assert not errors, errors
    page.close()


def test_a_given_that_changes_the_steps_is_a_switch_between_the_books_figures(browser):
    """The indicator diagram's filling changes its steps (the division up to the cut-off): each of the book's
    figures has its player, and each player a switch to the others, saying why it is no slider."""
    plan = [p for n, p in gallery_plan() if n == "indicator-diagram"]
    paths = [_gallery_player(entry_slug("indicator-diagram", p)) for p in plan]
    assert len(paths) >= 2
    page, errors = _open_plain(browser, paths[0])
    switch = page.locator("#live.live-switch")
    assert switch.count() == 1 and "Schritte" in switch.inner_text() and "10 %" in switch.inner_text()
    assert page.locator('#live input[type="range"]').count() == 0
    page.locator("#live.live-switch a").first.click()
    page.wait_for_load_state()
    assert page.url.endswith(paths[1].relative_to(REPO / "gallery").as_posix())
    assert page.locator('#live b[aria-current="page"]').inner_text() == "40 %"
    assert not errors, errors
    page.close()


def _open_plain(browser, path):
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    errors: list[str] = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(path.as_uri())
    return page, errors


@pytest.mark.parametrize("name,params,given,values", [
    ("tangential-pressure", {"rod_ratio": 5.0, "parts": 18, "kappa": 8.0}, "kappa", (1.3, 27.0)),
    ("piston-force", {}, "rod_length", (0.9, 3.0, 7.0))])
def test_areas_are_drawn_from_the_curves_that_bound_them(browser, name, params, given, values):
    """An area between two curves (Baumann's excess area, Tafel I's free forces) has as many pieces, and as
    many points, as its curves' crossings and breakpoints make at each value: the page draws it anew from the
    curves it shows, and each area (its pieces together) is a fresh replay's within 0.5 px (their boundaries).
    A piece all of whose points lie within half a pixel (a crossing a hair from the area's end) is no piece one
    sees: it is left out on both sides.  (The pieces together: where two curves cross at a grazing angle, the
    corner between two pieces slides along them by ten times what the curves move.)  Its hatching is drawn anew
    with it: each area's hatch lines a fresh replay's, each end within 0.5 px (it was hidden away from the book's
    value)."""
    from shapely.geometry import Polygon
    from shapely.ops import unary_union

    path = _gallery_player(entry_slug(name, params))
    c = get(name)
    page, errors = _open(browser, path)
    read = """() => (window.constructLive.flush(), window.constructPlayer.groups()).flatMap(s => Array.from(s.querySelectorAll('path.area')))
        .filter(e => e.getAttribute('display') !== 'none').map(e => [e.id, e.getAttribute('d')])"""
    ring = lambda d: [tuple(p) for p in zip(*[iter(float(x) for x in NUMBER.findall(d))] * 2)]  # noqa: E731
    hatched = """() => window.constructPlayer.groups().flatMap(s => Array.from(s.querySelectorAll('path.hatch[id]')))
        .filter(e => e.style.display !== 'none' && e.getAttribute('d')).map(e => [e.id, e.getAttribute('d')])"""

    def areas(pieces) -> dict[str, list]:  # each area's pieces one sees, by the step that made it
        out: dict[str, list] = {}
        for i, d in pieces:
            q = Polygon(ring(d))
            if max(q.bounds[2] - q.bounds[0], q.bounds[3] - q.bounds[1]) > 0.5:
                out.setdefault(i.split("-")[0], []).append(q.buffer(0))
        return out

    def hatching(paths) -> dict[str, np.ndarray]:  # each area's hatch lines (x0, y0, x1, y1), by the step that made it
        out: dict[str, list] = {}
        for i, d in paths:
            xy = [float(x) for x in NUMBER.findall(d)]
            out.setdefault(i.split("-")[0], []).extend(zip(*[iter(xy)] * 4))
        return {k: np.asarray(v) for k, v in out.items()}

    for v in values:
        _drag_to(page, given, v)
        got = areas(page.evaluate(read))
        fresh = _fresh_marks(c, params, given, v)  # (every mark's, an area's hatching too)
        want = areas((i, a["d"]) for i, a in _fresh_marks(c, params, given, v, MarkKind.AREA).items())
        assert want and {k: len(p) for k, p in got.items()} == {k: len(p) for k, p in want.items()}, v
        for k, ps in want.items():
            gap = unary_union(got[k]).boundary.hausdorff_distance(unary_union(ps).boundary)
            assert gap <= 0.5, (name, v, k, gap)
        # an area's hatching drawn anew with it, as a fresh replay hatches it: the same lines, each end within
        # 0.5 px (a line a hair from a corner, under half a unit long, may be on one side only)
        lines, fresh_lines = hatching(page.evaluate(hatched)), hatching((i, a["d"]) for i, a in fresh.items()
                                                                        if i.endswith("-hatch"))
        assert fresh_lines and set(lines) == set(fresh_lines), (name, v, set(lines), set(fresh_lines))
        for k, w in fresh_lines.items():
            g = lines[k]
            assert abs(len(g) - len(w)) <= 2, (name, v, k, len(g), len(w))
            for a, b in ((g, w), (w, g)):  # each line beside one of the other side's (either way round)
                ends = lambda p, q: np.minimum(np.abs(p[:, None, :] - q[None, :, :]).max(-1),  # noqa: E731
                                               np.abs(p[:, None, :] - q[None, :, [2, 3, 0, 1]]).max(-1))
                near = ends(a, b).min(1)
                long = np.hypot(a[:, 2] - a[:, 0], a[:, 3] - a[:, 1]) > 1.0
                assert near[long].max() <= 0.5, (name, v, k, near.max())
    assert not errors, errors
    page.close()


def test_a_curve_through_the_points_between_its_corners_takes_the_points_a_fresh_build_takes(browser):
    """Tafel I's piston-force pieces b and c run through the points between their corners (s1, s2): which points
    those are depends on the rod, so a replay of the built protocol at another rod draws them through the wrong
    points (7 px off at L = 3 m).  The page sweeps each part of the domain where a fresh build takes the same
    steps apart (live.sweep.pieces), under one slider: at every value, on both sides of the parts' ends, its
    curves have a fresh build's pieces, each number within 0.5 px."""
    path = _gallery_player(entry_slug("piston-force", {}))
    c = get("piston-force")
    page, errors = _open(browser, path)
    page.keyboard.press("End")
    assert page.locator('#live input[type="range"]').count() == 1
    ends = sorted(g["piece"][0] for g in json.loads(page.locator("#live-data").text_content())["givens"])[1:]
    assert len(ends) >= 3
    read = """ids => (window.constructLive.flush(), ids).map(i => window.constructPlayer.find(i).getAttribute('d'))"""
    for v in [0.45, 0.9, 3.0, 7.0, 100.0] + [e * f for e in ends[-2:] for f in (0.999, 1.001)]:
        _drag_to(page, "rod_length", v)
        want = {i: a["d"] for i, a in _fresh_marks(c, {}, "rod_length", v).items()
                if i.endswith(("-forceb", "-forcec", "-mass"))}
        got = dict(zip(want, page.evaluate(read, list(want))))
        assert len(want) == 3
        for i, d in want.items():
            a, b = NUMBER.findall(got[i]), NUMBER.findall(d)
            assert got[i].count("C") == d.count("C") and len(a) == len(b), (v, i)
            worst = max(abs(float(x) - float(y)) for x, y in zip(a, b))
            assert worst <= 0.5, (v, i, worst)
    assert not errors, errors
    page.close()


def test_the_end_states_plate_lettering_keeps_the_letters_size_on_the_screen(browser):
    """The committed gallery's inertia curve at its last step (the end state, its plate lettering "1 at", "L = ∞"
    set for the letter scale of the book's value): dragged to L/r = 1.5 and 50, where the figure and so its view
    grow or shrink, an upright lettering of the plate stays as tall on the screen as the end state's letters (q₁,
    A, B: the player scales both by its letter scale) -- it was drawn at 0.64 of their height at 1.5.  So does a
    turned one (F/f, m along their dimensions, turned a right angle: their box's width is their height), about its
    turn: its box's middle stays where the attribute turns it (it kept the book value's size, half the letters' at
    1.5).  And the arrowheads and a scale's ticks, drawn at the letters' size, keep their size beside the letters
    (as long over a letter's height as at the book's value), each arrowhead's tip where the furniture puts it."""
    path = _gallery_player("inertia-curve-rod-ratio-4")
    page, errors = _open(browser, path)
    _at(page, "end")
    heights = """() => { const h = e => e.getBoundingClientRect().height, m = document.getElementById('figure').getScreenCTM();
        const on = e => e.getClientRects().length && getComputedStyle(e.parentNode).display !== 'none';
        const screen = (x, y) => [m.a * x + m.c * y + m.e, m.b * x + m.d * y + m.f];
        const fur = Array.from(document.querySelectorAll('#figure .fo.end text.fur-text:not([transform])'))
          .filter(t => on(t) && !t.firstElementChild && t.textContent.trim().length > 1);
        const lbs = Array.from(document.querySelectorAll('#figure .lbg.pf > text.lb:not(.halo)')).filter(on);
        const turned = Array.from(document.querySelectorAll('#figure .fo.end text.fur-text[transform]')).filter(on).map(t => {
          const r = t.getBoundingClientRect(), a = t.getAttribute('transform').match(/-?[0-9.]+/g).map(Number), c = screen(a[1], a[2]);
          return [Math.abs(Math.sin(a[0] * Math.PI / 180)) > 0.999 ? r.width : null, r.left + r.width / 2 - c[0], r.top + r.height / 2 - c[1]]; });
        // (an arrowhead's and a tick's size on the screen over its size in the figure's numbers: the scale the page
        // draws it at, which is to be the plate's lettering's; an arrowhead's tip where its numbers put it)
        const k = Math.hypot(m.a, m.b), span = p => Math.max(...p.filter((_, i) => i % 2 === 0)) - Math.min(...p.filter((_, i) => i % 2 === 0))
          || Math.max(...p.filter((_, i) => i % 2)) - Math.min(...p.filter((_, i) => i % 2));
        const arrows = Array.from(document.querySelectorAll('#figure .fo.end path.arrow')).filter(on).map(e => {
          const r = e.getBoundingClientRect(), d = e.getAttribute('d').match(/-?[0-9.]+/g).map(Number), tip = screen(d[0], d[1]);
          const vertical = Math.abs(d[0] - d[2]) < Math.abs(d[1] - d[3]);
          return [(vertical ? r.height : r.width) / (k * Math.abs(vertical ? d[1] - d[3] : d[0] - d[2])),
                  Math.hypot(tip[0] - Math.min(Math.max(tip[0], r.left), r.right), tip[1] - Math.min(Math.max(tip[1], r.top), r.bottom))
                  + Math.min(Math.abs(tip[0] - r.left), Math.abs(tip[0] - r.right), Math.abs(tip[1] - r.top), Math.abs(tip[1] - r.bottom))]; });
        const ticks = Array.from(document.querySelectorAll('#figure .fo.end line.sc')).filter(on).map(e => {
          const r = e.getBoundingClientRect(), p = ['x1', 'y1', 'x2', 'y2'].map(a => +e.getAttribute(a));
          return Math.max(r.width, r.height) / (k * span(p)); });
        const lettering = fur.length ? +getComputedStyle(fur[0]).scale : null;
        const med = a => a.slice().sort((x, y) => x - y)[Math.floor(a.length / 2)];
        return {fur: med(fur.map(h)), letter: med(lbs.map(h)), nf: fur.length, nl: lbs.length, turned: turned,
                lettering: lettering, arrows: arrows.map(a => a[0]), tips: arrows.map(a => a[1]), ticks: ticks}; }"""
    book = page.evaluate(heights)
    assert len(book["ticks"]) >= 2 and len(book["tips"]) >= 4, book
    for v in (1.5, 50.0):
        _drag_to(page, "rod_ratio", v)
        page.evaluate("() => document.querySelector('#live input[type=range]').dispatchEvent(new Event('change'))")
        _glided(page)
        got = page.evaluate(heights)
        fur, letter = got["fur"], got["letter"]
        assert got["nf"] >= 2 and got["nl"] >= 5, (v, got)
        # (as tall as the letters to a fifth: the plate's lettering is set at the letters' size)
        assert 0.8 <= fur / letter <= 1.25, (v, fur, letter)
        right = [t for t in got["turned"] if t[0] is not None]
        assert len(right) >= 2, (v, got["turned"])
        for height, dx, dy in right:
            assert 0.8 <= height / letter <= 1.25, (v, height, letter)
            # (its middle on its turn: the text is set about it, to a quarter of a letter's height)
            assert math.hypot(dx, dy) <= 0.25 * letter, (v, dx, dy, letter)
        # (each arrowhead and tick drawn at the lettering's scale, to a twentieth: their numbers are the furniture's
        # at the book's letter size, as the lettering's are)
        assert v != 1.5 or got["lettering"] > 1.2, got["lettering"]  # (the letters larger than the book value's)
        for what in ("arrows", "ticks"):
            assert got[what] and all(abs(x / got["lettering"] - 1) <= 0.05 for x in got[what]), (v, what, got[what])
        assert max(got["tips"]) <= 0.5, (v, got["tips"])
    assert not errors, errors
    page.close()


def test_the_rod_length_stands_on_a_break_the_shown_step_draws(browser):
    """The committed gallery's inertia curve at its last step (the end state), dragged slowly with ``input``
    events alone up to L/r = 50: the rod's length at a break is written only on a break whose marks the page
    shows, where a fresh replay's end state writes it -- at 50 the end state draws no break (the lines the axis
    break crosses are the construction's, which the end state leaves out), so nothing is written; it stood
    alone at the window's left edge ("L = 50 r" on the axis's break, far out of the end state's view)."""
    path = _gallery_player("inertia-curve-rod-ratio-4")
    c = get("inertia-curve")
    page, errors = _open(browser, path)
    _at(page, "end")
    _at_step_view(page)
    shown = """() => Array.from(document.querySelectorAll('#figure .rodlen text.lb:not(.halo)'))
        .filter(t => t.getClientRects().length && getComputedStyle(t).display !== 'none'
                     && getComputedStyle(t.parentNode).display !== 'none')
        .map(t => { const r = t.getBoundingClientRect(); return [t.textContent, r.left + r.width / 2, r.top + r.height / 2]; })"""
    marks = """() => Array.from(document.querySelectorAll('#figure .brkg > path.brk'))
        .filter(e => e.getClientRects().length && getComputedStyle(e.parentNode).display !== 'none')
        .map(e => { const r = e.getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2]; })"""
    for v in np.geomspace(4.0, 50.0, 16)[1:]:
        _drag_to(page, "rod_ratio", float(v))
    root = _fresh_svg(c, {}, "rod_ratio", 50.0)
    # (the fresh end state's break marks: those not in a group it leaves out, nf)
    hidden = {d for g in root.iter() if "nf" in (g.get("class") or "").split() for d in g.iter()}
    want = [e for e in root.iter() if e.get("class") == "brk" and e not in hidden]
    got, at = page.evaluate(shown), page.evaluate(marks)
    assert len(at) == len(want), (len(at), len(want))
    if not want:
        assert got == [], got
    for text, x, y in got:  # (on a break shown: within two letters of its marks' middle)
        assert text == "L = 50 r" and min(math.hypot(x - a, y - b) for a, b in at) <= 30, (text, x, y, at)
    assert not errors, errors
    page.close()


def test_the_end_step_frames_what_it_draws_as_kappa_moves(browser):
    """The committed gallery's tangential-pressure diagram (kappa = 8) at its last step: its plate's furniture
    (the scale, M, alpha) follows kappa, and the end step's view is carried with the figure the end state draws
    (as the camera frames it: camera.final_box).  Let go at kappa = 2 the camera frames the flat diagram as a
    fresh build at kappa = 2 does (within 1 px: the view carried with the end step's own few marks, the excess
    area, grew to 1.4 times that frame, the diagram across 56 % of the window), and back at the book's value the
    view is the built one (within 1.5 px)."""
    from construct.render.output import scene_for
    from construct.render.svg import Drawing

    params = {"rod_ratio": 5.0, "parts": 18, "kappa": 8.0}
    path = _gallery_player(entry_slug("tangential-pressure", params))
    page, errors = _open(browser, path)
    _at(page, "end")
    _at_step_view(page)
    view = "() => window.constructPlayer.view()"
    let_go = """() => { document.querySelector('#live input[name="kappa"]').dispatchEvent(new Event('change'));
        window.constructPlayer.jump(false); }"""
    built = page.evaluate(view)
    for v in np.geomspace(7.9, 2.0, 12):
        _drag_to(page, "kappa", float(v))
    page.evaluate(let_go)
    c = get("tangential-pressure")
    fresh = Drawing(scene_for(c, c.figure(**{**params, "kappa": 2.0}), ending=True), STYLES["teaching"])
    want = fresh.camera_view(fresh.scene.steps[-1].index)
    assert max(abs(a - b) for a, b in zip(page.evaluate(view), want)) <= 1.0, (page.evaluate(view), want)
    _drag_to(page, "kappa", 8.0)
    page.evaluate(let_go)
    # (the views are blended between grid values, not refined for: the book's value is no grid value here)
    assert max(abs(a - b) for a, b in zip(page.evaluate(view), built)) <= 1.5, (page.evaluate(view), built)
    assert not errors, errors
    page.close()


#: The furniture of an end state as the page shows it: each element's id, tag, text, numbers and whether it is shown.
_FURNITURE = """() => Array.from(document.querySelectorAll('#furniture > g.fo.end > [id]')).map(e => [e.id, e.tagName,
    e.tagName === 'text' ? e.textContent : '',
    ['x1', 'y1', 'x2', 'y2', 'cx', 'cy', 'r', 'd', 'x', 'y'].map(a => e.getAttribute(a) || '').join(' '),
    e.getClientRects().length > 0 && getComputedStyle(e).display !== 'none'])"""


def _set_off(elements: list[tuple[str, str]]) -> tuple[list[int], set[int]]:
    """Of a furniture's elements ((id, tag), in the order drawn): the indices of all but the leaders (a lettering
    set off from its place, ``fin-f`` lines: render/end_state.py end_furniture), and of the texts set off so."""
    kept, off, led = [], set(), False
    for i, (ident, tag) in enumerate(elements):
        if tag == "line" and ident.startswith("fin-f"):
            led = True
            continue
        if tag == "text" and led:
            off.add(len(kept))
        elif tag != "text":
            led = False
        kept.append(i)
    return kept, off


@pytest.mark.parametrize("name,params", [
    ("tangential-pressure", {"rod_ratio": 5.0, "parts": 18, "kappa": 8.0}),
    ("effective-work", {"rod_ratio": 5.0, "parts": 9, "kappa": 8.0})])
def test_the_plates_letters_and_lines_follow_kappa_and_only_the_scales_ticks_that_come_and_go_are_held(
        browser, name, params):
    """Baumann's force scale gains or loses ticks with the diagram's height (kappa), so the plate's furniture in
    the end state changes its form over kappa's domain: only what comes and goes (the ticks) follows the plate's
    form at the nearer grid value.  At kappa = 2 and 30, dragged there with ``input`` events, the page shows the
    elements a fresh build at that kappa draws -- every letter (M, A, B, D, alpha, the scale's numbers and unit)
    and line, in the same order -- each within 0.5 px of where that build puts it (a letter the fresh build sets
    off with a leader, where the page keeps the book's value's place for it, only by its text), and the page's
    note says which of the plate's items come and go."""
    path = _gallery_player(entry_slug(name, params))
    c = get(name)
    page, errors = _open(browser, path)
    _at(page, "end")
    for v in (2.0, 30.0):
        for u in np.geomspace(8.0, v, 8)[1:]:  # (a drag there)
            _drag_to(page, "kappa", float(u))
        shown = [g for g in page.evaluate(_FURNITURE) if g[4]]
        fresh = [e for e in _fresh_svg(c, params, "kappa", v).iter() if (e.get("id") or "").startswith("fin-")]
        mine, _ = _set_off([(g[0], g[1].lower()) for g in shown])
        theirs, off = _set_off([(e.get("id"), e.tag.rsplit("}", 1)[-1]) for e in fresh])
        shown, fresh = [shown[i] for i in mine], [fresh[i] for i in theirs]
        # the same elements, in the order drawn: the letters by their texts
        assert [(g[1].lower(), g[2]) for g in shown] == [(e.tag.rsplit("}", 1)[-1], "".join(e.itertext()) if
                                                          e.tag.endswith("text") else "") for e in fresh], v
        assert {"B", "0", "2", "at"} <= {g[2] for g in shown}, v  # (and M, A, D, alpha on the tangential plate)
        for j, (g, e) in enumerate(zip(shown, fresh)):
            if j in off:
                continue
            nums = [float(x) for x in NUMBER.findall(g[3])]
            want = _numbers(e, ("x1", "y1", "x2", "y2", "cx", "cy", "r", "d", "x", "y"))
            assert len(nums) == len(want) and max(abs(a - b) for a, b in zip(nums, want)) <= 0.5, (v, g, want)
    note = page.locator("#live .live-end")
    assert note.is_visible() and "„3“, „4“ und 2 Striche der Tafel nur, wo" in note.inner_text()
    _drag_to(page, "kappa", 8.0)
    assert not note.is_visible() and all(g[4] for g in page.evaluate(_FURNITURE))
    assert not errors, errors
    page.close()


def test_the_inset_magnifies_where_a_fresh_replay_magnifies_it_while_dragging(browser, tmp_path):
    """The 18-part crank at step 48 (the third tangent point G found beside C₁ and F, a pixel apart in the view):
    the player magnifies the cluster in an inset.  Dragged with ``input`` events alone to L/r = 3.3 and 7.1 the
    inset stays shown and magnifies the box a fresh replay's player magnifies there (within 0.5 px), its points
    drawn where the fresh replay draws them and on the page's own points; it was hidden away from the book's
    value, and its box and points were the book's."""
    import xml.etree.ElementTree as ET

    c, params, k = get("crank"), {"parts": 18}, 48
    fig = c.figure(**params, rod_ratio=5.0)
    write_replay(c, fig, tmp_path, style="teaching", frames="none")
    path = tmp_path / "live.html"
    path.write_text(with_live((tmp_path / "player.html").read_text(), live_data(live_sweep(c, fig, "rod_ratio"))))
    page, errors = _open(browser, path)
    page.eval_on_selector("#slider", f"(s) => {{ s.value = {k}; s.dispatchEvent(new Event('input')); }}")
    shown = """() => { const i = document.getElementById('inset');
        return JSON.stringify({display: getComputedStyle(i).display, box: i.getAttribute('viewBox').split(' ').map(Number),
          pts: Array.from(document.querySelectorAll('#inset-pts circle')).map(e => [+e.getAttribute('cx'), +e.getAttribute('cy')]),
          own: JSON.parse(document.getElementById('data').textContent).steps[%d].zp.map(p => {
            const e = typeof p[0] === 'string' && window.constructPlayer.find(p[0]);
            return e ? [+e.getAttribute('cx'), +e.getAttribute('cy')] : null; })}); }""" % (k - 1)
    assert json.loads(page.evaluate(shown))["display"] == "block"  # (at the book's value)
    was = 5.0
    for v in (3.3, 7.1):
        for u in np.geomspace(was, v, 6)[1:]:
            _drag_to(page, "rod_ratio", float(u))
        was = v
        got = json.loads(page.evaluate(shown))
        fresh = player_page(c, c.figure(**params, rod_ratio=v), STYLES["teaching"])
        at = fresh.index('<script type="application/json" id="data">')
        want = json.loads(fresh[fresh.index(">", at) + 1:fresh.index("</script>", at)])["steps"][k - 1]
        root = ET.fromstring(fresh[fresh.index("<svg"):fresh.index("</svg>") + 6])
        circles = {e.get("id"): e for e in root.iter("{http://www.w3.org/2000/svg}circle")}
        assert got["display"] == "block", v
        assert max(abs(a - b) for a, b in zip(got["box"], want["z"])) <= 0.5, (v, got["box"], want["z"])
        points = [(float(circles[p[0]].get("cx")), float(circles[p[0]].get("cy"))) for p in want["zp"]]
        assert len(got["pts"]) == len(points) == len(got["own"]) > 0, (v, got, points)
        for (x, y), (a, b), (ox, oy) in zip(got["pts"], points, got["own"]):
            assert math.hypot(x - a, y - b) <= 0.5 and (x, y) == (ox, oy), (v, (x, y), (a, b), (ox, oy))
    assert not errors, errors
    page.close()


def test_a_cluster_comes_and_goes_with_kappa_as_fresh_builds_show_it(browser):
    """Baumann's effective work (gallery player, κ slider), step 826 (T2 carried with the compass): at κ = 8 the
    step's finest detail needs 1.3 times the whole figure's magnification and its view gives 2.3, no inset; at
    κ = 2 it needs 4.4 against 2.5 and a fresh build magnifies it.  Dragged there with ``input`` events alone the
    page shows the inset a fresh build's player shows (its box within 0.5 px), and none again back at 8; it
    showed none at κ = 2 (only the book's value's insets were shown)."""
    path = _gallery_player("effective-work-kappa-8-parts-9-rod-ratio-5")
    c, params = get("effective-work"), {"parts": 9, "rod_ratio": 5}
    page, errors = _open(browser, path)
    inset = """() => { const i = document.getElementById('inset');
        return [getComputedStyle(i).display, i.getAttribute('viewBox').split(' ').map(Number)]; }"""
    for k, values in ((826, (4.0, 2.0, 4.0, 8.0)),):
        page.eval_on_selector("#slider", f"(s) => {{ s.value = {k}; s.dispatchEvent(new Event('input')); }}")
        for v in values:
            _drag_to(page, "kappa", v)
            shown, box = page.evaluate(inset)
            fresh = player_page(c, c.figure(**params, kappa=v), STYLES["teaching"])
            at = fresh.index('<script type="application/json" id="data">')
            want = json.loads(fresh[fresh.index(">", at) + 1:fresh.index("</script>", at)])["steps"][k - 1].get("z")
            assert (shown == "block") == (want is not None), (k, v, shown, want)
            if want is not None:
                assert max(abs(a - b) for a, b in zip(box, want)) <= 0.5, (k, v, box, want)
        _drag_to(page, "kappa", 8.0)
    assert not errors, errors
    page.close()



@pytest.mark.parametrize("slug, name, params, given, k, values", [
    ("inertia-stroke-fractions-rod-ratio-5", "inertia-stroke-fractions", {}, "rod_ratio", 211, (4.37, 5.0)),
    ("inertia-stroke-fractions-rod-ratio-5", "inertia-stroke-fractions", {}, "rod_ratio", 105, (5.55, 5.0)),
    ("effective-work-kappa-8-parts-9-rod-ratio-5", "effective-work", {"parts": 9, "rod_ratio": 5}, "kappa", 426,
     (6.0, 8.0))])
def test_a_compass_steps_inset_magnifies_what_a_fresh_build_magnifies_while_dragging(browser, slug, name, params,
                                                                                    given, k, values):
    """A step that carries a length with the compass strikes an arc as round as the span it is set to (Tafel 2's
    step 211: O-Y5 carried to U, 13.25 px; Baumann's effective work, step 426: U-V3 carried to E3, 4.33 px).  The
    inset magnifies the arc, at every value, in a fresh build and on the page alike.  The page, its points 0.2 px
    off a fresh build's, magnified the pair where a fresh build magnified the arc or the other way round: 530 px
    away at the book's L/r = 5 (368 px at κ = 8 after a drag there), and sized the box from the built one, 47-50 px
    off at L/r 4.37 and 5.55.  Dragged with ``input`` events alone, then let go: the inset's box is a fresh
    build's within 0.5 px, during the drag and after."""
    from construct.render.output import scene_for
    from construct.render.svg import Drawing

    c = get(name)
    page, errors = _open(browser, _gallery_player(slug))
    page.eval_on_selector("#slider", f"(s) => {{ s.value = {k}; s.dispatchEvent(new Event('input')); }}")
    _at_step_view(page)
    inset = """() => { const i = document.getElementById('inset');
        return [getComputedStyle(i).display, i.getAttribute('viewBox').split(' ').map(Number)]; }"""
    was = float(page.evaluate(f"() => 10 ** +document.querySelector('#live input[name=\"{given}\"]').value"))
    for v in values:
        for u in np.geomspace(was, v, 6)[1:]:
            _drag_to(page, given, float(u))
        was = v
        want = Drawing(scene_for(c, c.figure(**params, **{given: v}), ending=True), STYLES["teaching"]).insets[k - 1]
        for when in ("dragged", "let go"):
            if when == "let go":
                page.evaluate(f"""() => {{ document.querySelector('#live input[name="{given}"]')
                    .dispatchEvent(new Event('change')); window.constructPlayer.jump(false); }}""")
            shown, box = page.evaluate(inset)
            assert shown == "block" and want is not None, (k, v, when, shown, want)
            assert max(abs(a - b) for a, b in zip(box, want)) <= 0.5, (k, v, when, box, want)
    assert not errors, errors
    page.close()


# every value the plate writes in the end state (its decimal lettering, not its halos) that the page shows: its text
# and its box on the screen
_WRITTEN = """() => JSON.stringify(Array.from(document.querySelectorAll('#furniture text')).filter(t =>
    !t.classList.contains('halo') && t.getClientRects().length && /^[+\\u2212-]?[0-9]+,[0-9]+$/.test(t.textContent.trim()))
    .map(t => {
      const r = t.getBoundingClientRect(); return [t.textContent, r.left, r.top, r.right, r.bottom]; }))"""


@pytest.mark.parametrize("v", [1.05, 2.0, 1000.0])
def test_the_values_the_plate_writes_stay_clear_of_one_another_while_dragging(browser, v):
    """Tafel 2's end state writes the eleven inertia pressures beside their ordinates.  As L/r moves the ordinates
    crowd (at L/r 2 the last ones nearly equal): the page writes each value where a placing at that value sets it
    (where it stood at the book's value while there is room), so that no two overlap on the screen -- they were
    written on one another at L/r 2 while the page kept the book's value's offsets -- and each value belongs to
    its ordinate (its text a number)."""
    path = _gallery_player("inertia-stroke-fractions-rod-ratio-5")
    page, errors = _open(browser, path)
    _at(page, "end")
    _at_step_view(page)
    for u in np.geomspace(5.0, v, 13)[1:]:  # (a slow drag there)
        _drag_to(page, "rod_ratio", float(u))
    written = json.loads(page.evaluate(_WRITTEN))
    assert len(written) >= 11, written
    for i, a in enumerate(written):
        for b in written[i + 1:]:
            over = min(a[3], b[3]) - max(a[1], b[1]), min(a[4], b[4]) - max(a[2], b[2])
            assert min(over) <= 1.0, f"L/r = {v}: {a[0]} and {b[0]} overlap by {over[0]:.1f} x {over[1]:.1f} px"
    assert not errors, errors
    page.close()


@pytest.fixture(scope="module")
def crank6_live(tmp_path_factory):
    return _crank_live(tmp_path_factory, 6)


@pytest.mark.parametrize("k, v", [(30, 1.3), (46, 40.0)])
def test_a_step_frames_at_every_value_what_a_fresh_build_frames_there(browser, crank6_live, k, v):
    """Two of the crank's steps (at two and three fifths of the sequence: the rod's arcs struck onto the stroke line),
    dragged slowly (12 ``input`` events) from L/r = 5 to a value and let go: the view is the camera's
    view of a fresh build at that value (within 3 px of every edge), where the camera takes the same shot there.
    Carried from the book's value with all the marks of its steps (lines as long as the figure among them), the
    view was 292 px off at 1.3, 17 px at 40."""
    from construct.render.output import scene_for
    from construct.render.svg import Drawing

    c = get("crank")
    page, errors = _open(browser, crank6_live)
    page.evaluate("k => { const s = document.getElementById('slider'); s.value = k; s.oninput(); }", k)
    _at_step_view(page)
    for u in np.geomspace(5.0, v, 13)[1:]:
        _drag_to(page, "rod_ratio", float(u))
    page.evaluate("""() => { document.querySelector('#live input[name="rod_ratio"]').dispatchEvent(new Event('change'));
        window.constructPlayer.jump(false); }""")
    got = page.evaluate("() => window.constructPlayer.view()")
    fresh = Drawing(scene_for(c, c.figure(parts=6, rod_ratio=v), ending=True), STYLES["teaching"])
    want = fresh.camera_view(k)
    assert want != fresh.full_view
    assert max(abs(a - b) for a, b in zip(got, want)) <= 3.0, (v, got, want)
    assert not errors, errors
    page.close()


@pytest.mark.parametrize("v", [4.9, 5.0, 5.1])
def test_a_step_frames_about_the_book_value_what_a_fresh_build_frames_there(browser, v):
    """The gallery crank's 60 % step (219: the rod's arcs struck onto the stroke line), dragged (6 ``input`` events)
    from the book's L/r = 5 to a value beside it -- or away and back to 5 itself -- and let go: the view is a fresh
    build's camera view there (within 3 px of every edge).  The camera frames the step's shot whole below about
    L/r = 4.86 (it magnifies too little) and round its marks above: a blend of the grid values either side of that
    jump (4.71 and 5.24) put the view 188, 131 and 76 px off at 4.9, 5.0 (the book's own value) and 5.1."""
    from construct.render.output import scene_for
    from construct.render.svg import Drawing

    c, k = get("crank"), 219
    page, errors = _open(browser, _gallery_player("crank-parts-18-rod-ratio-5"))
    page.evaluate("k => { const s = document.getElementById('slider'); s.value = k; s.oninput(); }", k)
    _at_step_view(page)
    for u in (*np.geomspace(5.0, 4.6, 3)[1:], *np.geomspace(4.6, v, 4)[1:]) if v == 5.0 else np.geomspace(5.0, v, 7)[1:]:
        _drag_to(page, "rod_ratio", float(u))
    page.evaluate("""() => { document.querySelector('#live input[name="rod_ratio"]').dispatchEvent(new Event('change'));
        window.constructPlayer.jump(false); }""")
    got = page.evaluate("() => window.constructPlayer.view()")
    fresh = Drawing(scene_for(c, c.figure(parts=18, rod_ratio=v), ending=True), STYLES["teaching"])
    want = fresh.camera_view(k)
    assert want != fresh.full_view
    assert max(abs(a - b) for a, b in zip(got, want)) <= 3.0, (v, got, want)
    assert not errors, errors
    page.close()


@pytest.mark.parametrize("v", [1.05, 1.2, 3.0, 8.0, 1000.0])
def test_the_end_step_frames_the_end_state_at_every_value_as_a_fresh_build_does(browser, crank6_live, v):
    """The crank's last step (the end state: the figure as the plate draws it, with its furniture) dragged slowly
    (10 ``input`` events) to a value across the domain, both ends among them, and let go: the view frames what
    the end state draws there as a fresh build at that value frames it (its camera view, within 3 px of every
    edge), and the drag's view holds it.  Carried with its marks from the book's value, whose frame the plate's
    broken rod shaped, the view was the whole canvas below L/r = 2 (1.9 times the fresh frame's area at 1.05)."""
    from construct.render.output import scene_for
    from construct.render.svg import Drawing

    c, params = get("crank"), {"parts": 6}
    page, errors = _open(browser, crank6_live)
    _at(page, "end")
    _at_step_view(page)
    held = []
    for u in np.geomspace(5.0, v, 11)[1:]:
        _drag_to(page, "rod_ratio", float(u))
        held.append(page.evaluate("() => [window.constructPlayer.view(), window.constructPlayer.target().slice()]"))
    page.evaluate("""() => { document.querySelector('#live input[name="rod_ratio"]').dispatchEvent(new Event('change'));
        window.constructPlayer.jump(false); }""")
    got = page.evaluate("() => window.constructPlayer.view()")
    fresh = Drawing(scene_for(c, c.figure(**params, rod_ratio=v), ending=True), STYLES["teaching"])
    want = fresh.camera_view(fresh.scene.steps[-1].index)
    assert want != fresh.full_view
    assert max(abs(a - b) for a, b in zip(got, want)) <= 3.0, (v, got, want)
    view, step = held[-1]
    assert step[0] >= view[0] - 0.01 and step[1] >= view[1] - 0.01 and step[0] + step[2] <= view[0] + view[2] + 0.01 \
        and step[1] + step[3] <= view[1] + view[3] + 0.01, (v, view, step)
    assert not errors, errors
    page.close()


def test_the_checks_name_the_value_they_belong_to(browser, live_player):
    """Between the values the checks were computed at, the table's numbers are one such value's (a check's error is
    its point: a blend of two values' would claim a check nobody made): the heading names that value and says it
    is the nearest computed one to the slider's, and every row is what ``construct check`` at the named value
    gives, to the digits written.  At a value computed, the heading names it alone."""
    c, _, path = live_player
    page, errors = _open(browser, path)
    _drag_to(page, "rod_ratio", 3.3)
    head = page.locator("#live-at").inner_text()
    got = re.fullmatch(r"\(L/r = ([0-9,]+): nächster berechneter Wert zu 3,3 / the nearest computed value to 3\.3\)",
                       head)
    assert got, head
    at = float(got.group(1).replace(",", "."))
    assert at != 3.3
    fresh = c.checks(c.figure(parts=3, rod_ratio=at))
    # (the rows out of sight wait while dragging, until they come into sight: flush brings them up to date)
    rows = page.evaluate("""() => { window.constructLive.flush();
        return Array.from(document.querySelectorAll('#live-checks tbody tr')).map(r =>
          Array.from(r.cells).map(td => td.textContent)); }""")
    assert len(rows) == len(fresh)
    for row, ck in zip(rows, fresh):
        assert row[0] == ck.name
        # (the value named is written to four digits: the checks there to the digits the page writes, 8)
        for text, want in ((row[1], ck.measured), (row[2], ck.expected)):
            assert abs(float(text) - want) <= 5e-4 * max(abs(want), 1e-9), (ck.name, text, want)
    _drag_to(page, "rod_ratio", 5.0)
    assert page.locator("#live-at").inner_text() == "(L/r = 5)"
    assert not errors, errors
    page.close()

@pytest.mark.parametrize("frac", [0.6, 1.0])
def test_a_new_drag_after_letting_go_starts_from_the_view_let_go_at(browser, live_player, frac):
    """Let go, the camera frames the step's view exactly; a new drag that barely moves the given (a thousandth of
    a decade, either way) keeps that view on the screen (within 1 px, the step's view held), not a tenth larger:
    the drag's hold rule took any step's view that left the exact one by a hair as a new view with room, a step
    outward at the drag's first frame and back at the next let-go."""
    _, _, path = live_player
    page, errors = _open(browser, path)
    page.evaluate("f => { const s = document.getElementById('slider'); s.value = Math.round(f * s.max); s.oninput(); }", frac)
    _at_step_view(page)
    state = "() => [window.constructPlayer.view(), window.constructPlayer.target().slice()]"
    for sign in (1.0, -1.0):
        for u in np.geomspace(5.0, 3.0, 11)[1:]:
            _drag_to(page, "rod_ratio", float(u))
        page.evaluate("""() => new Promise(r => { document.querySelector('#live input[name="rod_ratio"]')
            .dispatchEvent(new Event('change')); setTimeout(r, 700); })""")
        let_go, step = page.evaluate(state)
        assert let_go == pytest.approx(step, abs=0.01)
        _drag_to(page, "rod_ratio", 3.0 * 10 ** (sign * 0.001))
        view, step = page.evaluate(state)
        assert step != let_go  # (the step's view moved)
        assert max(abs(a - b) for a, b in zip(view, let_go)) <= 1.0, (sign, let_go, view)
        assert step[0] >= view[0] - 0.01 and step[1] >= view[1] - 0.01 and step[0] + step[2] <= view[0] + view[2] + 0.01 \
            and step[1] + step[3] <= view[1] + view[3] + 0.01, (sign, view, step)
    assert not errors, errors
    page.close()


def _decimal(text: str) -> tuple[float, int]:
    """A value as the plate writes it ("+0,748", "−0,5"): its number and its decimals."""
    got = re.fullmatch(r"([+\u2212-]?)([0-9]+),([0-9]+)", text.strip())
    assert got, text
    return (-1 if got.group(1) in "\u2212-" and got.group(1) else 1) * float(f"{got.group(2)}.{got.group(3)}"), \
        len(got.group(3))


def test_the_values_the_plate_writes_belong_to_the_sliders_value(browser):
    """Tafel 2's end state writes each inertia pressure to three decimals.  Between the grid values the page holds,
    the nearer one's +0,748 stood for a fresh replay's +0,746 at L/r 2, three digits claimed, the last one wrong:
    each value written now belongs to the value the slider shows to the digits written (a fresh replay's value
    there, itself good to half a unit of its third decimal, within half a unit of the last digit written), every
    value with the same decimals (a plate writes its numbers alike: not +1,50 beside +0,093), and at the book's
    value every value has its three decimals."""
    path = _gallery_player("inertia-stroke-fractions-rod-ratio-5")
    c = get("inertia-stroke-fractions")
    page, errors = _open(browser, path)
    _at(page, "end")
    for v in (2.0, 3.3, 7.1):
        _drag_to(page, "rod_ratio", v)
        shown = [_decimal(t[0]) for t in json.loads(page.evaluate(_WRITTEN))]
        fresh = [_decimal("".join(e.itertext())) for e in _fresh_svg(c, {}, "rod_ratio", v).iter()
                 if e.tag.endswith("text") and (e.get("id") or "").startswith("fin-")
                 and "halo" not in (e.get("class") or "").split() and re.fullmatch(r"[+\u2212-]?[0-9]+,[0-9]+", "".join(e.itertext()).strip())]
        assert len(shown) == len(fresh) == 11, (v, shown, fresh)
        assert len({d for _, d in shown}) == 1, f"L/r = {v}: the plate writes {sorted({d for _, d in shown})} decimals"
        for (x, d), (want, _) in zip(shown, fresh):
            assert abs(x - want) <= 0.5 * 10.0 ** -d + 0.0005 + 1e-9, f"L/r = {v}: {x} written for {want}"
    _drag_to(page, "rod_ratio", 5.0)
    assert all(d == 3 for _, d in (_decimal(t[0]) for t in json.loads(page.evaluate(_WRITTEN))))
    assert not errors, errors
    page.close()

def test_the_rod_written_at_the_break_is_the_sliders_in_every_piece_of_the_domain(browser):
    """Tafel 2's construction changes its form along L/r, so its slider moves through pieces of the domain, each
    swept apart: dragged slowly from the book's L/r = 5 to 32.4 and 1000 (``input`` events only) at three fifths
    of the steps, the rod's length written at the axis's break is the slider's value (it was the value the first
    piece's sweep was left at: "L = 1,096 r" at L/r 32.4)."""
    path = _gallery_player("inertia-stroke-fractions-rod-ratio-5")
    page, errors = _open(browser, path)
    page.evaluate("() => { const s = document.getElementById('slider'); s.value = Math.round(0.6 * s.max); s.oninput(); }")
    _at_step_view(page)
    written = """() => Array.from(document.querySelectorAll('#figure .rodlen text.lb:not(.halo)'))
        .filter(t => t.getClientRects().length).map(t => t.textContent)"""
    was = 5.0
    for v, said in ((32.4, "L = 32,4 r"), (1000.0, "L = 1000 r")):
        for u in np.geomspace(was, v, 11)[1:]:
            _drag_to(page, "rod_ratio", float(u))
        was = v
        assert page.evaluate(written) == [said], (v, page.evaluate(written))
    assert not errors, errors
    page.close()


def test_every_rod_length_the_page_holds_is_the_sliders_hidden_or_not(browser, crank6_live):
    """At three fifths of the crank's steps, dragged (``input`` events only) from the book's L/r = 5, where the
    rod is broken, to 1.5 and 3, where it is not: every text of the figure that writes the rod's length -- the
    page's own at the break, hidden now, and the plate's dimension of the end state, not shown before the end --
    says the slider's value.  The hidden one kept "L = 5 r" (and after 8 -> 1.5, "L = 8 r"), a length no value
    shown had, in the document a screen reader or a test reads; shown again at a break, it says the value."""
    page, errors = _open(browser, crank6_live)
    page.evaluate("() => { const s = document.getElementById('slider'); s.value = Math.round(0.6 * s.max); s.oninput(); }")
    _at_step_view(page)
    rods = """() => Array.from(document.querySelectorAll('#figure text'))
        .filter(t => t.textContent.startsWith('L =')).map(t => [t.textContent, t.getClientRects().length > 0])"""
    for v, broken in ((1.5, False), (8.0, True), (3.0, False), (40.0, True)):
        _drag_to(page, "rod_ratio", v)
        said = f"L = {v:g} r".replace(".", ",")
        got = page.evaluate(rods)
        assert got and all(text == said for text, _ in got), (v, got)
        # (shown: the page's own label and its halo at the break, where the rod is broken, and nothing else)
        assert sum(shown for _, shown in got) == (2 if broken else 0), (v, got)
    assert not errors, errors
    page.close()
