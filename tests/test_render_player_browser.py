"""The HTML step player in a real browser: headless Chromium driven by Playwright.

At every step k exactly the objects made by steps 1..k must be visible, and
the caption must be step k's.  The expectation comes from the protocol (which
step made which drawable object), not from the player's own data.

Needs Debian's ``chromium`` and the ``playwright`` client (``.ci/install-browser.sh``).
Skips when they are missing, except under CI (``CI`` set), where it fails.
Set ``CONSTRUCT_SCREENSHOT=path.png`` to keep a screenshot for looking at.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from construct.constructions import get
from construct.kernel.geometry import Circle, Line, Point
from construct.kernel.geometry import Length
from construct.render.animate import STEP_SECONDS, step_seconds
from construct.render.output import write_replay

@pytest.fixture(scope="module")
def player(tmp_path_factory):
    c = get("crank")
    fig = c.figure(parts=3, rod_ratio=4.0)
    out = tmp_path_factory.mktemp("player")
    write_replay(c, fig, out, style="teaching", frames="none")
    return fig, out / "player.html"


def _expected_visible(fig, k: int) -> set[str]:
    """Names of the drawable objects made by steps 1..k, straight from the protocol."""
    names = set()
    for s in fig.protocol.steps[:k]:
        for name in s.outputs:
            if _drawable(fig.replay.get(name)):
                names.add(name)
    return names


def _drawable(obj) -> bool:
    """A point, a line, a circle, or a line joined by the straightedge (the crank, the rod of Fig. 1)."""
    return isinstance(obj, (Point, Line, Circle)) or hasattr(obj, "curve_points")


def _must_show(fig, k: int) -> set[str]:
    """What step k cannot do without (the levels of detail of the camera): step k's own objects and its inputs,
    every result and given, and the objects of every group still open at step k (its group at
    depth two, up to the end of that group's run); the helpers of finished groups may collapse.
    The last step shows the clean figure: every group finished, its results."""
    steps = fig.protocol.steps
    current = steps[k - 1]
    if k == len(steps):
        return {n for s in steps if s.role in ("result", "given") or not s.group for n in s.outputs
                if _drawable(fig.replay.get(n))}
    open_groups = {current.group[:2]} if current.group else set()
    names = set()
    for s in steps[:k]:
        keep = (s.index == k or s.role in ("result", "given") or not s.group or s.group[:2] in open_groups)
        for name in s.outputs:
            if keep and _drawable(fig.replay.get(name)):
                names.add(name)
    return names | {n for n in current.inputs if _drawable(fig.replay.get(n))}


def _shows_step(page, fig, k: int) -> None:
    """At step k the player shows what the step needs and nothing made later."""
    shown = _visible_names(page, fig)
    assert _must_show(fig, k) <= shown <= _expected_visible(fig, k), (
        f"step {k}: missing {sorted(_must_show(fig, k) - shown)}, too many {sorted(shown - _expected_visible(fig, k))}")


VISIBLE_JS = """() => Array.from(document.querySelectorAll('#figure [id^="s"]'))
    .filter(e => !e.id.endsWith('-label') && !e.id.endsWith('-lb') && !e.id.endsWith('-tag') && e.getBoundingClientRect().width + e.getBoundingClientRect().height > 0
                 && getComputedStyle(e).visibility !== 'hidden')
    .map(e => e.id)"""


def _visible_names(page, fig) -> set[str]:
    ids = page.evaluate(VISIBLE_JS)
    # ids are "s<step>-<name>" with unsafe characters made "-": map back through the protocol
    by_id = {}
    for s in fig.protocol.steps:
        for name in s.outputs:
            safe = "".join(ch if ch.isalnum() or ch in "-_" else "-" for ch in name)
            by_id[f"s{s.index:04d}-{safe}"] = name
    # (an end state's own mark is its object's mark drawn as the plate draws it: "<its id>-end")
    return {by_id[i] if i in by_id else by_id[i.removesuffix("-end")] for i in ids}


def test_player_steps_show_exactly_the_steps_so_far(browser, player):
    from construct.render.output import scene_for

    fig, path = player
    scene = scene_for(get("crank"), fig)
    n = len(fig.protocol.steps)
    page = browser.new_page(viewport={"width": 1400, "height": 900})
    errors: list[str] = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    requests: list[str] = []
    page.on("request", lambda r: requests.append(r.url))
    page.clock.install()
    page.goto(path.as_uri())
    page.keyboard.press("Home")
    assert _visible_names(page, fig) == set()
    for k in range(1, n + 1):
        page.keyboard.press("ArrowRight")
        assert page.get_attribute("#figure", "data-step") == str(k)
        if k < n:
            _shows_step(page, fig, k)
        else:  # the last step shows the end state: the result drawn as the plate draws it (some of it anew)
            assert "fin" in page.get_attribute("#figure", "class").split()
            assert _visible_names(page, fig) <= _expected_visible(fig, k)
        step = fig.protocol.steps[k - 1]
        de, en = scene.caption(k)  # the caption the frames print: in the figure's letters (tests/test_gallery_look.py)
        assert page.inner_text("#cap-de") == f"Schritt {k}: {de}"
        assert page.inner_text("#cap-en") == f"Step {k}: {en}"
    # back again with the other arrow key, and the slider to a middle step
    # the last step: finished groups have collapsed to their results (some helper is no longer drawn)
    assert _visible_names(page, fig) < _expected_visible(fig, n)
    page.keyboard.press("ArrowLeft")
    _shows_step(page, fig, n - 1)
    mid = n // 2
    page.eval_on_selector("#slider", f"(s) => {{ s.value = {mid}; s.dispatchEvent(new Event('input')); }}")
    _shows_step(page, fig, mid)
    # play advances by itself at the chosen pace, pause stops it (the page's clock is driven, not slept through)
    step = lambda: int(page.get_attribute("#figure", "data-step"))  # noqa: E731
    assert page.eval_on_selector("#speed", "s => +s.value") == STEP_SECONDS
    page.click("#play")
    page.clock.run_for(int(STEP_SECONDS * 1000) * 2 + 100)
    assert step() == mid + 2
    page.select_option("#speed", "0.5")
    page.clock.run_for(1100)  # a new pace takes effect at once: 0.5 s a step
    assert step() == mid + 4
    page.click("#play")
    stopped = step()
    page.clock.run_for(10_000)
    assert step() == stopped
    page.keyboard.press("-")  # slower: back to the next longer time per step
    assert page.eval_on_selector("#speed", "s => +s.value") == 1.0
    # the groups are collapsible and the givens are shown
    assert page.locator("#steps details").count() >= 3
    # in the book's symbols (seed 000 writes r/L), not the protocol's names
    assert "r/L" in page.inner_text("#givens") and "1/4" in page.inner_text("#givens")
    assert "rod_ratio" not in page.inner_text("#givens")
    shot = os.environ.get("CONSTRUCT_SCREENSHOT")
    page.keyboard.press("End")
    page.screenshot(path=shot or str(path.with_suffix(".png")), full_page=True)
    assert errors == []
    assert all(u.startswith("file:") or u.startswith("data:") for u in requests), requests
    page.close()


def test_stepping_scrolls_the_step_list_and_never_the_page(browser, player):
    """The list beside the figure follows the step; the page stays put, so the title and the figure do not
    jump under the teacher's pointer (scrollIntoView moved the window too, by a line at every step)."""
    fig, path = player
    page = browser.new_page(viewport={"width": 1400, "height": 420})  # a page taller than the window
    page.goto(path.as_uri())
    assert page.evaluate("document.documentElement.scrollHeight") > 420
    for key in ("End", "Home", "End", "ArrowLeft", "ArrowLeft"):
        page.keyboard.press(key)
        assert page.evaluate("window.scrollY") == 0
        inside = page.evaluate("""() => {
            const a = document.querySelector('#steps .current');
            if (!a) return true;  // step 0: no step is current
            const box = a.closest('aside');
            const r = a.getBoundingClientRect(), b = box.getBoundingClientRect();
            return r.top >= b.top - 0.5 && r.bottom <= b.bottom + 0.5; }""")
        assert inside, key
    page.close()


def test_animated_svg_plays_by_its_clock(browser, tmp_path):
    """The animated SVG, its SMIL clock set to moments of the play: at 1.5 s a step, steps 1..k show, then all.

    The document's own clock is paused and set (``setCurrentTime``), so the
    test sees the animation at any moment without waiting for it.
    """
    c = get("crank")
    fig = c.figure(parts=3, rod_ratio=4.0)
    write_replay(c, fig, tmp_path, style="teaching", frames="none")
    n = len(fig.protocol.steps)
    dt = step_seconds()
    assert dt >= 1.5
    page = browser.new_page(viewport={"width": 1000, "height": 800})
    page.goto((tmp_path / "animated.svg").as_uri())
    page.evaluate("() => document.documentElement.pauseAnimations()")

    def at(t: float) -> tuple[int, str]:
        page.evaluate(f"() => document.documentElement.setCurrentTime({t})")
        shown = page.evaluate("""() => Array.from(document.querySelectorAll('g[data-step]'))
            .filter(g => getComputedStyle(g).visibility !== 'hidden').map(g => +g.dataset.step)""")
        caption = page.evaluate("""() => Array.from(document.querySelectorAll('#step-captions > g'))
            .filter(g => getComputedStyle(g).visibility !== 'hidden').map(g => g.textContent).join('|')""")
        return max(shown, default=0), caption

    drawn = sorted({s.index for s in fig.protocol.steps if any(fig.replay.get(o) is not None and not
                                                                 isinstance(fig.replay.get(o), Length) for o in s.outputs)})
    for k in (drawn[0], drawn[len(drawn) // 2], n):
        latest, caption = at((k - 1) * dt + dt / 2)
        assert latest == max(j for j in drawn if j <= k), k
        assert caption.count("Schritt ") == 1 and f"Schritt {k} von {n}" in caption, caption
    # the camera: at a step whose view magnifies, the drawing is shown through that view
    from construct.render.output import scene_for
    from construct.render.styles import STYLES
    from construct.render.svg import Drawing

    d = Drawing(scene_for(c, fig), STYLES["teaching"])
    # the most magnified step (the clean figure of the last step: the crank, the rod to its crosshead)
    k = min(range(1, n + 1), key=lambda i: d.camera_view(i)[2])
    assert d.camera_view(k)[2] < 0.9 * d.full_view[2]
    page.evaluate(f"() => document.documentElement.setCurrentTime({(k - 1) * dt + dt / 2})")
    root_scale = page.evaluate("() => document.documentElement.getScreenCTM().a")
    cam_scale = page.evaluate("() => document.getElementById('camera').getScreenCTM().a")
    # (the view, of the player's window's shape, shown whole on the animation's stage of the canvas's shape)
    v, full = d.camera_view(k), d.full_view
    assert cam_scale / root_scale == pytest.approx(min(full[2] / v[2], full[3] / v[3]), rel=0.01)
    early = page.evaluate("() => { document.documentElement.setCurrentTime(0.1); return 0; }")
    first = page.screenshot(clip={"x": 0, "y": 0, "width": 960, "height": 600})
    page.evaluate(f"() => document.documentElement.setCurrentTime({n * dt + 1})")  # the hold at the end
    assert at(n * dt + 1)[0] == drawn[-1] and at(n * dt + 1)[1] == ""
    last = page.screenshot(clip={"x": 0, "y": 0, "width": 960, "height": 600})
    assert early == 0 and _ink(last) > 2 * _ink(first) > 0
    page.close()


def _ink(png: bytes) -> int:
    """Non-white pixels of a PNG screenshot (decoded by matplotlib, an independent reader)."""
    import io

    import matplotlib.image as mpimg
    import numpy as np

    img = mpimg.imread(io.BytesIO(png), format="png")
    return int(np.count_nonzero(img[..., :3].min(axis=2) < 0.9))


def test_player_shows_markup_in_captions_as_text(browser, tmp_path):
    """A caption '<script>alert(1)</script> & "x"' is shown as text and runs nothing."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("_escaping", Path(__file__).with_name("test_escaping.py"))
    escaping = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(escaping)
    NASTY, nasty_figure = escaping.NASTY, escaping.nasty_figure

    from construct.render.player import player_html
    from construct.render.scene import build_scene
    from construct.render.styles import STYLES

    fig = nasty_figure()
    path = tmp_path / "nasty.html"
    path.write_text(player_html(build_scene(fig, title=(NASTY, NASTY)), STYLES["teaching"], givens={NASTY: 1.0}),
                    encoding="utf-8")
    page = browser.new_page()
    dialogs: list[str] = []
    page.on("dialog", lambda d: (dialogs.append(d.message), d.dismiss()))
    page.goto(path.as_uri())
    page.keyboard.press("Home")
    page.keyboard.press("ArrowRight")
    assert page.inner_text("#cap-de") == f"Schritt 1: {NASTY}"
    assert page.inner_text("h1").startswith(NASTY)
    assert NASTY in page.inner_text("#givens")
    # the letter and its paper-coloured halo underneath: both the text itself, nothing parsed as markup
    shown = page.locator("#figure text", has_text=NASTY)
    assert shown.count() >= 1 and all(t == NASTY for t in shown.all_text_contents())
    assert page.evaluate("() => document.querySelectorAll('script').length") == 2
    assert dialogs == []
    page.close()


LETTERS_JS = """() => Array.from(document.querySelectorAll('#figure text.lb[id$="-label"]'))
    .filter(t => t.getBoundingClientRect().width > 0)
    .map(t => { const p = document.getElementById(t.id.slice(0, -6)); const a = t.getBoundingClientRect();
                const b = p.getBoundingClientRect();
                return [t.id, a.x + a.width / 2 - (b.x + b.width / 2), a.y + a.height / 2 - (b.y + b.height / 2), a.height]; })"""


def test_player_camera_keeps_letters_on_their_points(browser, tmp_path):
    """Through a magnifying view a letter keeps its screen size and its place beside its point."""
    import json
    import re

    c = get("crank")
    fig = c.figure(parts=6, rod_ratio=5.0)
    write_replay(c, fig, tmp_path, style="teaching", frames="none")
    html = (tmp_path / "player.html").read_text()
    data = json.loads(re.search(r'<script type="application/json" id="data">(.*?)</script>', html, re.S).group(1))
    full_w = float(re.search(r'data-full="0 0 ([\d.]+)', html).group(1))
    full_h = float(re.search(r'data-full="0 0 [\d.]+ ([\d.]+)', html).group(1))

    from construct.render.camera import PLAYER_FIGURE_PX

    ww, wh = PLAYER_FIGURE_PX

    def window_zoom(v):  # how many times the player's window shows view v larger than the whole figure
        return min(ww / v[2], wh / v[3]) / min(ww / full_w, wh / full_h)

    # the last step whose view magnifies at least 1.7 times (past a zoom level; by then many points are lettered)
    k = max(i for i, st in enumerate(data["steps"], start=1) if window_zoom(data["views"][st["v"]]) >= 1.7)
    z = window_zoom(data["views"][data["steps"][k - 1]["v"]])
    over = z / max(lv for lv in data["levels"] if lv <= z * 1.001)  # the level's picture magnified this much
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    page.clock.install()
    page.goto((tmp_path / "player.html").as_uri() + f"#{k}")
    page.clock.run_for(1000)  # the camera glides for 350 ms
    box = [float(v) for v in page.get_attribute("#figure", "viewBox").split()]
    assert box == pytest.approx(data["views"][data["steps"][k - 1]["v"]], abs=0.02)
    zoomed = {i: (dx, dy, h) for i, dx, dy, h in page.evaluate(LETTERS_JS)}
    page.click("#zoom")  # the magnifier off: the whole figure
    page.clock.run_for(1000)
    whole = {i: (dx, dy, h) for i, dx, dy, h in page.evaluate(LETTERS_JS)}
    common = set(zoomed) & set(whole)
    assert len(common) >= 2
    moved = 0
    for i in common:
        zx, zy, zh = zoomed[i]
        wx, wy, wh = whole[i]
        # the same size on the screen (the level's, magnified as the view is beyond its level)
        assert zh == pytest.approx(wh * over, rel=0.15), i
        assert (zx * zx + zy * zy) ** 0.5 < 4.5 * zh, i  # beside its point, not drifted away
        # placed again: another offset for its size (a view between two zoom levels shows the level's
        # picture magnified, letters and their offsets alike, by up to the ratio of the levels)
        moved += abs(zx / zh - wx / wh) > 0.125 or abs(zy / zh - wy / wh) > 0.125
    # letters move only where a zoom level placed them again (never all of them)
    assert moved < len(common)
    page.close()


SHOWN_LETTER_PX_JS = """() => Array.from(document.querySelectorAll('#figure text.lb:not(.halo)'))
    .filter(t => t.getClientRects().length && getComputedStyle(t).display !== 'none')
    .map(t => { const m = t.getScreenCTM();  // (Chromium's includes the letter's CSS scale)
                return [t.textContent, parseFloat(getComputedStyle(t).fontSize) * Math.hypot(m.a, m.b)]; })"""


def test_lint_measures_the_players_figure_as_the_page_shows_it(browser, tmp_path):
    """At a typical 1400 × 900 window the player's page shows its figure in the box lint measures the player's
    views in (and the camera shapes them for), and letters of a step whose work is spread over the figure's
    width (Fig. 28's b₁ = 0,02 r₁ worked along r₁) are at least lint's 9 px on the page."""
    from construct.regress.lint import MIN_LABEL_PX, VIEW
    from construct.regress.lint.views import player_window
    from construct.render.camera import PLAYER_FIGURE_PX

    c = get("flywheel-rim")
    write_replay(c, c.figure(), tmp_path, style="teaching", frames="none")
    page = browser.new_page(viewport={"width": 1400, "height": 900})
    page.clock.install()
    page.goto((tmp_path / "player.html").as_uri() + "#112")
    page.clock.run_for(1000)
    box = page.evaluate("() => { const f = document.getElementById('figure'); return [f.clientWidth, f.clientHeight]; }")
    assert VIEW == (1400.0, 900.0)
    assert tuple(box) == pytest.approx(player_window(VIEW), abs=1.0)
    assert player_window(VIEW) == PLAYER_FIGURE_PX
    sizes = {name: px for name, px in page.evaluate(SHOWN_LETTER_PX_JS)}
    page.close()
    assert {"O", "r₁"} <= set(sizes)
    assert min(sizes.values()) >= MIN_LABEL_PX, sizes


LEADERS_WITHOUT_LETTER_JS = """() => Array.from(document.querySelectorAll('#figure line.leader'))
  .filter(ln => ln.getClientRects().length && getComputedStyle(ln).display !== 'none')
  .filter(ln => !Array.from(ln.parentNode.querySelectorAll('text'))
                    .some(t => t.getClientRects().length && getComputedStyle(t).display !== 'none'))
  .map(ln => ln.parentNode.id)"""


def test_no_leader_line_is_drawn_without_its_letter(browser, tmp_path):
    """A leader ties a letter to its point: where the letter is not shown (a name tag after its step, a letter
    that gives way at a zoom level) its leader is not drawn either -- at every step of a crowded figure."""
    c = get("tangential-pressure")
    fig = c.figure(parts=6)
    write_replay(c, fig, tmp_path, style="teaching", frames="none")
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    page.goto((tmp_path / "player.html").as_uri())
    n = int(page.eval_on_selector("#slider", "s => s.max"))
    for k in sorted({1, n // 4, n // 2, 3 * n // 4, n - 1, n}):
        page.eval_on_selector("#slider", f"(s) => {{ s.value = {k}; s.dispatchEvent(new Event('input')); }}")
        page.wait_for_timeout(450)  # the camera's glide (350 ms)
        assert page.evaluate(LEADERS_WITHOUT_LETTER_JS) == [], f"step {k}"
    page.close()
