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
from collections import Counter

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

import construct
from construct import Builder
from construct.kernel import letters as captions  # the rules behind construct.render.captions
from construct.render.captions import CAPTION_LIMIT, TITLE_LIMIT, Reader, displayed
from construct.render.captions import wrap as wrap_px
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


def test_the_limits_leave_the_gallerys_titles_whole():
    longest = 0
    for path in glob.glob(os.path.join(ROOT, "gallery", "*", "*", "final.svg")):
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for lang in ("de", "en"):
            lines = re.findall(rf'class="cap {lang}[^"]*"[^>]*>([^<]*)<', text)
            longest = max(longest, len(" ".join(lines)))
    # the compound engine's caption names both cylinders' diagrams (529 characters): 40 % to spare
    assert 300 < longest < 0.6 * TITLE_LIMIT


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
    # lower case: before the fix this took ~15 s and wrote megabytes (a capital word also hung the
    # caption reader, quadratic -- test_a_caption_that_is_one_long_name_... shows that on 200 k)
    return _figure_with_caption("x" * (3 * MB), group="y" * (3 * MB))


def test_a_three_megabyte_caption_renders_a_bounded_svg(word_figure):
    assert len(word_figure.protocol.steps[1].caption.de) == 3 * MB  # the protocol keeps the text
    for upto in (None, 1, 2, 3):
        svg = word_figure.svg("teaching", upto=upto)
        assert len(svg) < 20_000
    frame = word_figure.svg("plain", upto=2)
    lines = re.findall(r'class="cap de"[^>]*>([^<]*)<', frame)
    assert "".join(lines) == "Schritt 2 von 3: " + "x" * (CAPTION_LIMIT - 1) + "…"
    assert len(lines) == 4


def test_a_three_megabyte_caption_writes_bounded_outputs(word_figure, tmp_path):
    out = tmp_path / "out"
    word_figure.write(out, style="teaching", frames="all")
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
    b.figure().write(out, style="teaching", frames="all")
    sizes = {p.name: p.stat().st_size for p in out.rglob("*") if p.is_file()}
    assert sizes.pop("protocol.json") > 3 * MB
    assert max(sizes.values()) < 50_000, sizes
    title = re.findall(r'class="cap de"[^>]*>([^<]*)<', (out / "final.svg").read_text(encoding="utf-8"))
    assert "".join(title) == "T" * (TITLE_LIMIT - 1) + "…"


def test_captions_of_many_short_words_are_wrapped_and_cut():
    words = " ".join(random.Random(4).choice(["Kreis", "um", "durch", "A", "B"]) for _ in range(200_000))
    svg = _figure_with_caption(words).svg("plain", upto=2)
    lines = re.findall(r'<text[^>]*class="cap de"[^>]*>([^<]*)<', svg)
    assert 2 <= len(lines) <= 5 and lines[-1].endswith("…")
    assert len(svg) < 20_000


# -- the SVG diff: matching in near-linear time, the same meaning -------------------------------

from construct.regress.svgdiff import diff_svg, parse_svg  # noqa: E402
from construct.regress.svgdiff import match as svgmatch  # noqa: E402

_HEAD = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 1000 1000">'


def _svg(elements) -> str:
    return _HEAD + "".join(elements) + "</svg>"


def raw_circle(x, y, r=1.5, ident=None) -> str:
    return f'<circle{f" id={chr(34)}{ident}{chr(34)}" if ident else ""} cx="{x}" cy="{y}" r="{r}" class="pt"/>'


N = 3000  # anonymous elements enough that their alignment is past difflib's area (3000 x 3000 > 1 M pairs)


def test_one_moved_among_many_identical_circles_is_reported_once():
    same = [raw_circle(500, 500)] * N
    moved = list(same)
    moved[1234] = raw_circle(503, 500)
    d = diff_svg(_svg(same), _svg(moved))
    assert [(c.kind, c.key, c.matched_by) for c in d.changes] == [("moved", "circle[1234]", "key")]


def test_one_moved_among_circles_that_look_alike_but_for_their_place():
    a = [raw_circle(i % 97 * 10, i // 97 * 10) for i in range(N)]
    b = list(a)
    b[2000] = raw_circle(2000 % 97 * 10 + 0.5, 2000 // 97 * 10)
    d = diff_svg(_svg(a), _svg(b))
    assert [(c.kind, c.key) for c in d.changes] == [("moved", "circle[2000]")]
    assert d.changes[0].magnitude == pytest.approx(0.5)


def test_an_element_inserted_or_removed_among_duplicates_is_one_change():
    a = [raw_circle(500, 500)] * N
    inserted = a[:1500] + [raw_circle(500, 500)] + a[1500:]
    assert [c.kind for c in diff_svg(_svg(a), _svg(inserted)).changes] == ["extra"]
    assert [c.kind for c in diff_svg(_svg(inserted), _svg(a)).changes] == ["missing"]
    other = a[:700] + [raw_circle(10, 10, r=3)] + a[700:]  # a different one: extra, the duplicates all paired
    assert [(c.kind, c.key) for c in diff_svg(_svg(a), _svg(other)).changes] == [("extra", "circle[700]")]


def test_elements_within_the_tolerance_match():
    a = [raw_circle(i % 50 * 20, i // 50 * 20) for i in range(N)]
    b = [raw_circle(i % 50 * 20 + 0.004, i // 50 * 20 - 0.004) for i in range(N)]
    assert diff_svg(_svg(a), _svg(b), tolerance=0.01).equal
    b[5] = raw_circle(5 * 20 + 0.02, 0)
    d = diff_svg(_svg(a), _svg(b), tolerance=0.01)
    assert [(c.kind, c.key) for c in d.changes] == [("moved", "circle[5]")]
    assert not diff_svg(_svg(a), _svg(b)).equal  # the default tolerance, 1e-6, sees every one


def test_renamed_elements_are_paired_by_geometry_with_a_grid_not_all_pairs(monkeypatch):
    # Every element renamed and moved a little: nothing pairs by id, all by nearest geometry.
    # Before, 3000 x 3000 leftovers were more than the all-pairs search took (4 M): 6000 missing + extra.
    a = [raw_circle(i % 60 * 16, i // 60 * 16, ident=f"a{i}") for i in range(N)]
    b = [raw_circle(i % 60 * 16 + 0.3, i // 60 * 16, ident=f"b{i}") for i in range(N)]
    calls = 0
    distance = svgmatch._distance

    def counted(x, y):
        nonlocal calls
        calls += 1
        return distance(x, y)

    monkeypatch.setattr(svgmatch, "_distance", counted)
    d = diff_svg(_svg(a), _svg(b))
    kinds = Counter(c.kind for c in d.changes)
    assert kinds == {"renamed": N, "moved": N}
    assert all(c.matched_by == "geometry" and c.key[1:] == c.key_b[1:] for c in d.changes)
    assert calls <= 40 * N  # each element against its neighbourhood, not against all 3000


def test_a_dense_cluster_beyond_the_budget_is_left_unmatched_not_searched(monkeypatch):
    a = [raw_circle(500, 500 + i * 1e-3, ident=f"a{i}") for i in range(200)]
    b = [raw_circle(500, 500 + i * 1e-3, ident=f"b{i}") for i in range(200)]
    monkeypatch.setattr(svgmatch, "MATCH_BUDGET", 1000)
    d = diff_svg(_svg(a), _svg(b))
    # 200 neighbours each: the first five elements spend the budget, the other 195 stay unmatched
    assert Counter(c.kind for c in d.changes) == {"renamed": 5, "missing": 195, "extra": 195}
    monkeypatch.setattr(svgmatch, "MATCH_BUDGET", 4_000_000)
    assert Counter(c.kind for c in diff_svg(_svg(a), _svg(b)).changes) == {"renamed": 200}


_COORD = st.one_of(st.floats(-30, 30, allow_nan=False), st.sampled_from([0.0, 1.0, 2.0, -1.0, 1e400, -1e400]))


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.sampled_from(["circle", "line", "rect"]), _COORD, _COORD, st.floats(0, 3)),
                min_size=1, max_size=25),
       st.lists(st.tuples(st.sampled_from(["circle", "line", "rect"]), _COORD, _COORD, st.floats(0, 3)),
                min_size=1, max_size=25),
       st.sampled_from([0.0, 0.5, 1.0, 2.5]))
# found by hypothesis: corners 1.0 and -7e-29 are 1.0 apart in floating point, but landed two grid cells apart
@example([("rect", 1.0, 0.0, 0.0)], [("circle", 0.0, 0.0, 0.0), ("rect", -6.913952398153846e-29, 0.0, 0.0)], 1.0)
def test_the_grid_finds_every_pair_the_all_pairs_search_finds(xs, ys, limit):
    def shapes(items):
        out = []
        for tag, x, y, s in items:
            x, y = (("1e400" if v == 1e400 else "-1e400" if v == -1e400 else repr(v)) for v in (x, y))
            if tag == "circle":
                out.append(f'<circle cx="{x}" cy="{y}" r="{s}"/>')
            elif tag == "line":
                out.append(f'<line x1="{x}" y1="{y}" x2="{s}" y2="{y}"/>')
            else:
                out.append(f'<rect x="{x}" y="{y}" width="{s}" height="1"/>')
        return parse_svg(_svg(out)).shapes

    sa, sb = shapes(xs), shapes(ys)
    every = sorted((d, i, j) for i, x in enumerate(sa) for j, y in enumerate(sb)
                   if (d := svgmatch._distance(x, y)) <= limit)
    assert sorted(svgmatch._near_pairs(sa, sb, limit, 10**9)) == every


@settings(max_examples=200, deadline=None)
@given(st.lists(st.integers(0, 5), max_size=60), st.lists(st.integers(0, 5), max_size=60), st.data())
def test_the_alignment_pairs_equal_elements_in_order(fa, fb, data):
    # a small difflib area: the ends, the unique anchors and the repeated stretches are all exercised
    area = data.draw(st.sampled_from([0, 4, 30]))
    old, svgmatch._DIFFLIB_AREA = svgmatch._DIFFLIB_AREA, area
    try:
        pairs = sorted(svgmatch._align(fa, fb))
    finally:
        svgmatch._DIFFLIB_AREA = old
    assert all(fa[p] == fb[q] for p, q in pairs)
    assert all(p1 < p2 and q1 < q2 for (p1, q1), (p2, q2) in zip(pairs, pairs[1:]))
    if fb == fa[:3] + [9] + fa[3:]:  # one inserted: everything else paired
        assert len(pairs) == len(fa)


@settings(max_examples=100, deadline=None)
@given(st.lists(st.integers(0, 8), max_size=40), st.lists(st.integers(0, 8), max_size=40))
def test_small_sequences_align_as_difflib_aligns_them(fa, fb):
    import difflib

    blocks = difflib.SequenceMatcher(None, fa, fb, autojunk=False).get_matching_blocks()
    assert svgmatch._align(fa, fb) == [(b.a + k, b.b + k) for b in blocks for k in range(b.size)]


def test_the_diff_benchmark_drawings_differ_by_one_move():
    from construct.regress.diffbench import synthetic_svg

    for ids in (True, False):
        d = diff_svg(synthetic_svg(400, ids=ids), synthetic_svg(400, moved=201, ids=ids))
        assert [c.kind for c in d.changes] == ["moved"] and d.elements == (400, 400)
