"""The live rod-ratio slider in a real browser (headless Chromium, as tests/test_render_player_browser.py drives it).

For several rod ratios the slider is moved and every interpolated coordinate
the page shows is compared with a fresh build at that rod ratio (what
``construct replay --rod-ratio v`` draws: ``Construction.figure`` and the
player's own drawing, fitted to the same view), which the page's data never
saw: the values are chosen off the grid.
"""

from __future__ import annotations

import math
import re

import pytest

from construct.constructions import get
from construct.constructions.live import drawn_numbers, live_data, live_sweep, player_page
from construct.render.live import with_live
from construct.render.output import write_replay
from construct.render.styles import STYLES


NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
#: Off-grid rod ratios across the domain, the books' 4 to 6 among them.
VALUES = (1.07, 1.9, 3.3, 4.37, 5.55, 7.1, 23.0, 410.0)


@pytest.fixture(scope="module")
def live_player(tmp_path_factory):
    c = get("crank")
    fig = c.figure(parts=3, rod_ratio=5.0)
    out = tmp_path_factory.mktemp("live")
    write_replay(c, fig, out, style="teaching", frames="none")
    live = live_sweep(c, fig, "rod_ratio")
    page = out / "live.html"
    page.write_text(with_live((out / "player.html").read_text(), live_data(live)))
    return c, live, page


def _page_numbers(page, keys):
    return page.evaluate("""keys => keys.map(k => {
        if (k[0] === '#zoom') return '';  // the views are not held to 0.5 px (live.py)
        const el = k[0] ? document.getElementById(k[0]) : document.getElementById('figure');
        return k[1] === 'viewBox' ? el.getAttribute('data-full') : el.getAttribute(k[1]); })""", keys)


def test_the_slider_draws_what_a_fresh_replay_draws(browser, live_player):  # noqa: F811
    c, live, path = live_player
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    errors: list[str] = []
    page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.goto(path.as_uri())
    page.evaluate("window.constructLive.ready")
    slider = page.locator('input[type="range"][name="rod_ratio"]')
    assert float(slider.get_attribute("min")) == pytest.approx(math.log10(1.05))
    assert float(slider.get_attribute("max")) == pytest.approx(3.0)
    keys = [list(k) for k in live.keys]
    assert any(k[1] == "cx" for k in keys) and any(k[1] == "d" for k in keys)
    worst = 0.0
    for v in VALUES:
        assert not any(a <= v <= b for a, b in live.jumps), v
        page.evaluate("v => window.constructLive.set(v)", v)
        assert page.locator("#live-value").text_content() == f"{v:.4g}".replace(".", ",")
        title = page.locator("h1").text_content()  # the title names it too, as the book writes the rod
        assert any(f"{form}{v:.4g}".replace(".", ",") in title for form in ("L/r = ", "r/L = 1/")), title
        shown = _page_numbers(page, keys)
        fresh_keys, fresh, _ = drawn_numbers(player_page(c, c.figure(parts=3, rod_ratio=v), STYLES["teaching"]))
        at, expect = 0, {}
        for k in fresh_keys:
            n = k[2].count("#")
            expect[k] = fresh[at:at + n]
            at += n
        for k, text in zip(live.keys, shown):
            if k[0] == "#zoom" or k in live.snapped:  # views frame the figure (blended where they jump; live.py)
                continue
            got = [float(x) for x in NUMBER.findall(text)]
            want = expect[k]
            assert len(got) == len(want), (v, k)
            d = max((abs(a - b) for a, b in zip(got, want)), default=0.0)
            assert d <= 0.5, f"L/r = {v}: {k[0]} {k[1]} off by {d:.3f} px"
            worst = max(worst, d)
        rows = page.locator("#live-checks tbody tr")
        assert rows.count() == len(c.checks(c.figure(parts=3, rod_ratio=v)))
    assert not errors, errors
    assert worst > 0.0  # the comparison compared something that moved
    page.close()
