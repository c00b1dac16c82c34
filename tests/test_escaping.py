"""Captions and labels are text, never markup: in every SVG and in the HTML player.

A construction whose captions, group titles and point letters carry
``<script>alert(1)</script> & "x"`` must show exactly that string as text:
the SVGs parse with a strict XML parser and the text nodes read back equal to
the string; the player page holds no element the protocol smuggled in.
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from html.parser import HTMLParser

import pytest

from construct.kernel.instruments import Builder
from construct.render.animate import animated_svg
from construct.render.player import json_for_script, player_html
from construct.render.scene import build_scene
from construct.render.styles import STYLES
from construct.render.svg import Drawing

NASTY = '<script>alert(1)</script> & "x"'
SVG = "{http://www.w3.org/2000/svg}"


class _Fig:
    def __init__(self, protocol, replay):
        self.protocol, self.replay = protocol, replay


def nasty_figure():
    b = Builder("nasty", givens={"r": 1.0})
    with b.group(NASTY, NASTY):
        O = b.given_point("O", 0.0, 0.0, de=NASTY, en=NASTY, label=NASTY)
        A = b.given_point("A", 1.0, 0.0, de=NASTY, en=NASTY, label="A")
        b.circle_through("k", O, A, de=NASTY, en=NASTY)
    p = b.protocol()
    return _Fig(p, p.replay())


@pytest.fixture(scope="module")
def scene():
    return build_scene(nasty_figure(), title=(NASTY, NASTY))


def _texts(svg: str) -> list[str]:
    root = ET.fromstring(svg.encode("utf-8"))  # strict: any unescaped '<' or '&' raises
    assert root.find(f".//{SVG}script") is None
    return ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]


@pytest.mark.parametrize("style", sorted(STYLES))
def test_frames_and_final_show_the_text_as_text(scene, style):
    d = Drawing(scene, STYLES[style])
    for k in range(len(scene.steps) + 1):
        texts = _texts(d.frame(k))
        if k >= 1:
            assert any(t.endswith(NASTY) for t in texts), texts  # caption "Schritt k von N: <nasty>"
            assert NASTY in texts  # the point's letter
    final = _texts(d.final())
    assert any(NASTY in t for t in final)


@pytest.mark.parametrize("style", sorted(STYLES))
def test_animated_svg_shows_the_text_as_text(scene, style):
    texts = _texts(animated_svg(scene, STYLES[style]))
    assert NASTY in texts
    assert sum(t.endswith(NASTY) for t in texts) >= len(scene.steps)


class _Collect(HTMLParser):
    def __init__(self):
        super().__init__()
        self.tags: list[str] = []
        self.text: list[str] = []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)

    def handle_data(self, data):
        self.text.append(data)


def test_player_page_holds_no_injected_markup(scene):
    page = player_html(scene, STYLES["teaching"], givens={NASTY: NASTY}, title=(NASTY, NASTY))
    p = _Collect()
    p.feed(page)
    assert p.tags.count("script") == 2  # the JSON data and the player's own script
    assert "img" not in p.tags
    text = "".join(p.text)
    assert NASTY in text  # the title, the givens and the step list show it as text
    # the embedded JSON reads back to the very string, with no '<' in the page source of the data
    start = page.index('<script type="application/json" id="data">') + len('<script type="application/json" id="data">')
    raw = page[start:page.index("</script>", start)]
    assert "<" not in raw and "&" not in raw
    data = json.loads(raw)
    assert data["steps"][0]["de"] == NASTY


def test_json_for_script_round_trips():
    value = {"a": NASTY, "b": "</script><!-- \u2028"}
    assert json.loads(json_for_script(value)) == value
    assert "</" not in json_for_script(value) and "<!--" not in json_for_script(value)
