"""Hostile sizes: a caption of megabytes, SVGs of a million elements.

No test here is timed (speed is in ``construct bench``).  Linear cost is held
by what can be counted -- look-ups made, lines returned, bytes written -- and
by inputs whose quadratic handling would not finish.
"""

from __future__ import annotations

import glob
import json
import os
import random
import re
import textwrap

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import construct
from construct import Builder
from construct.render import captions
from construct.render.captions import CAPTION_LIMIT, Reader, displayed
from construct.render.svg import wrap as wrap_px
from construct.render.wrapping import shorten, wrap

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MB = 1_000_000


# -- captions: the wrapper gives textwrap's lines ------------------------------------------

def _gallery_texts() -> list[str]:
    """Every step caption and group title of the gallery's protocols, as stored."""
    texts: set[str] = set()
    for path in sorted(glob.glob(os.path.join(ROOT, "gallery", "*", "protocol.json"))):
        with open(path, encoding="utf-8") as f:
            p = json.load(f)
        for s in p["steps"]:
            texts.update((s["caption"]["de"], s["caption"]["en"]))
        for path in p.get("groups") or ():
            texts.update(path)
        texts.update((p.get("params", {}).get("group_titles") or {}).values())
    return sorted(texts)


GALLERY_TEXTS = _gallery_texts()


def test_the_gallery_has_captions_to_compare():
    assert len(GALLERY_TEXTS) > 1000
    assert max(map(len, GALLERY_TEXTS)) < CAPTION_LIMIT / 4  # the limit leaves the books' captions whole


def test_wrap_gives_textwraps_lines_for_every_gallery_caption():
    # the widths the renderers use: the styles' caption lines (116, 125, 135 characters) and
    # the storyboard's tiles (shortened to 110, wrapped at 48 and 54); 30 to make every caption wrap
    for text in GALLERY_TEXTS:
        for t in (text, f"Schritt 117 von 362: {text}"):
            for width in (30, 116, 125, 135):
                assert wrap(t, width) == textwrap.wrap(t, width, break_long_words=True, break_on_hyphens=False), t
            for width in (30, 48, 54):
                assert wrap(t, width, break_on_hyphens=True) == textwrap.wrap(t, width), t
            assert shorten(t, 110, placeholder=" …") == textwrap.shorten(t, 110, placeholder=" …"), t


_TEXT = st.text(alphabet="ab-— \t\n\u2009\u00a0.", max_size=60)


@settings(max_examples=400, deadline=None)
@given(_TEXT, st.integers(1, 14), st.booleans(), st.sampled_from([None, 1, 2, 3]),
       st.sampled_from([" …", " [...]", "…", "  x "]))
def test_wrap_equals_textwrap_on_any_text(text, width, hyphens, max_lines, placeholder):
    def run(f, *a, **k):
        try:
            return f(*a, **k)
        except ValueError as exc:  # the same refusal (placeholder wider than a line)
            return str(exc)

    assert (run(wrap, text, width, break_on_hyphens=hyphens, max_lines=max_lines, placeholder=placeholder)
            == run(textwrap.wrap, text, width, break_on_hyphens=hyphens, max_lines=max_lines,
                   placeholder=placeholder))
    assert run(shorten, text, width, placeholder=placeholder) == run(textwrap.shorten, text, width,
                                                                     placeholder=placeholder)


def test_wrap_breaks_a_word_of_megabytes_into_full_lines():
    # textwrap copies the rest of the word for every line: n²/width, 12 s for these 3 MB at width 125
    lines = wrap("x" * (3 * MB), 125)
    assert len(lines) == 3 * MB // 125 == 24_000
    assert set(map(len, lines)) == {125}
    lines = wrap("ab-" * MB, 48, break_on_hyphens=True)
    assert len(lines) == MB // 16 and set(lines) == {"ab-" * 16}  # broken after the last hyphen that fits
    assert len(wrap_px("x" * MB, 912, 13)) == MB // 125  # the plain style's caption: 125 characters a line


def test_shorten_reads_a_word_of_megabytes_once():
    assert shorten("x" * (3 * MB), 110, placeholder=" …") == "…"  # textwrap's answer: no whole word fits


# -- captions: what a figure shows is bounded ----------------------------------------------

def test_displayed_cuts_with_an_ellipsis():
    assert displayed("x" * CAPTION_LIMIT) == "x" * CAPTION_LIMIT
    cut = displayed("x" * (CAPTION_LIMIT + 1))
    assert len(cut) == CAPTION_LIMIT and cut.endswith("…")


class _CountingSet(set):
    """A set that counts the look-ups made in it."""

    looks = 0

    def __contains__(self, item):
        type(self).looks += 1
        return super().__contains__(item)


def test_a_caption_that_is_one_long_name_is_not_sliced_at_every_character():
    # Before: _split tried every cut of the token, a slice and a look-up each (27 s for 300 k).
    r = Reader({"P1": ("point", "1", None, ()), "D0": ("point", "A", None, ())})
    r.points = _CountingSet(r.points)
    _CountingSet.looks = 0
    out = r.text("X" * 200_000 + "1", "de")
    assert _CountingSet.looks <= 4
    assert len(out) == CAPTION_LIMIT and out.endswith("…")
    assert r.text("P1D0 und D0P1", "de") == "1–A und A–1"  # names written together still split


def test_a_caption_of_many_names_reads_each_name_locally():
    # every word an object's name: before, each looked at the whole rest (and the whole start) of the caption
    r = Reader({"axis": ("line", None, "line", ()), "O": ("point", "O", None, ())})
    text = "durch axis " * 100_000
    out = r.text(text, "de")
    assert len(out) <= CAPTION_LIMIT and out.endswith("…")
    assert out.startswith("durch Hubachse durch Hubachse")


@settings(max_examples=500, deadline=None)
@given(st.text(alphabet="ab um through \t\n\u2009-KCircle", max_size=40), st.data())
def test_the_neighbour_words_are_read_as_before(text, data):
    start = data.draw(st.integers(0, len(text)))
    end = data.draw(st.integers(start, len(text)))
    before = text[:start].rstrip().rsplit(" ", 1)[-1].lower() in captions._SLOTS and text[end:end + 1] != "-"
    assert Reader._names_slot(text, start, end) == before
    assert ((captions._NEXT_WORD.match(text, end).group(1).lower() in captions._NOUNS)
            == (text[end:].lstrip().split(" ", 1)[0].lower() in captions._NOUNS))


@settings(max_examples=300, deadline=None)
@given(st.lists(st.text(alphabet="AB1.", min_size=1, max_size=4), max_size=6),
       st.text(alphabet="AB1.", min_size=1, max_size=9))
def test_names_written_together_split_as_before(points, token):
    r = Reader({p: ("point", None, None, ()) for p in points})
    old = None
    if not (token[1:].islower() and "." not in token and not any(c.isdigit() for c in token)):
        old = next(((token[:i], token[i:]) for i in range(1, len(token))
                    if token[:i] in r.points and token[i:] in r.points), None)
    assert r._split(token) == old


# -- a figure whose step caption is one word of 3 MB ---------------------------------------

def _figure_with_caption(caption: str, group: str | None = None) -> construct.Figure:
    b = Builder("long caption", givens={})
    b.given_point("A", 0.0, 0.0)
    b.record("given", "given_point", (), ("B",), {"x": 1.0, "y": 2.0, "unit": None}, caption, caption)
    with b.group(group or "the line"):
        b.line("AB", "A", "B", role="result")
    return b.figure()


@pytest.fixture(scope="module")
def word_figure():
    return _figure_with_caption("X" * (3 * MB), group="Y" * (3 * MB))


def test_a_three_megabyte_caption_renders_a_bounded_svg(word_figure):
    assert len(word_figure.protocol.steps[1].caption.de) == 3 * MB  # the protocol keeps the text
    for upto in (None, 1, 2, 3):
        svg = construct.svg(word_figure, "teaching", upto=upto)
        assert len(svg) < 20_000
    frame = word_figure.svg("plain", upto=2)
    lines = re.findall(r'class="cap de"[^>]*>([^<]*)<', frame)
    assert "".join(lines) == "Schritt 2 von 3: " + "X" * (CAPTION_LIMIT - 1) + "…"
    assert len(lines) == 4


def test_a_three_megabyte_caption_writes_bounded_outputs(word_figure, tmp_path):
    out = tmp_path / "out"
    construct.write_replay(word_figure, out, style="teaching", frames="all")
    sizes = {p.relative_to(out).as_posix(): p.stat().st_size for p in out.rglob("*") if p.is_file()}
    assert {"final.svg", "player.html", "animated.svg", "storyboard.svg", "steps/002.svg"} <= set(sizes)
    assert sizes.pop("protocol.json") > 6 * MB  # the whole caption and group, kept
    assert max(sizes.values()) < 50_000, sizes


def test_a_three_megabyte_title_is_shown_bounded(tmp_path):
    b = Builder("T" * (3 * MB), givens={})
    b.given_point("A", 0.0, 0.0)
    b.given_point("B", 1.0, 0.0)
    b.line("AB", "A", "B", role="result")
    out = tmp_path / "out"
    construct.write_replay(b.figure(), out, style="teaching", frames="all")
    sizes = {p.name: p.stat().st_size for p in out.rglob("*") if p.is_file()}
    assert sizes.pop("protocol.json") > 3 * MB
    assert max(sizes.values()) < 50_000, sizes


def test_captions_of_many_short_words_are_wrapped_and_cut():
    words = " ".join(random.Random(4).choice(["Kreis", "um", "durch", "A", "B"]) for _ in range(200_000))
    svg = _figure_with_caption(words).svg("plain", upto=2)
    lines = re.findall(r'<text[^>]*class="cap de"[^>]*>([^<]*)<', svg)
    assert 2 <= len(lines) <= 5 and lines[-1].endswith("…")
    assert len(svg) < 20_000
