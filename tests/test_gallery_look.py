"""The look of the gallery's figures: letters that matter, captions a reader can follow, plates' values.

Expectations come from the protocol (which objects are results, which letters
the construction gave them), from the books (Tabelle 2) and from the printed
formula Gl. (h) computed here — never from the renderer's own output.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import pytest

from construct.constructions import get
from construct.gallery import DISPLAY_PX, gallery_plan
from construct.kernel.geometry import Point
from construct.books.anhang_ii.printed import TABLE_2
from construct.regress.lint import lint_svg
from construct.render.output import plate_caption, printed_caption, scene_for
from construct.render.scene import plate_names
from construct.render.styles import STYLES
from construct.render.svg import render_svg

SVG = "{http://www.w3.org/2000/svg}"
PLAN = gallery_plan()
IDS = [f"{n}-{'-'.join(f'{k}{v:g}' if isinstance(v, float) else f'{k}{v}' for k, v in sorted(p.items()))}"
       for n, p in PLAN]


@pytest.fixture(scope="module")
def figures(gallery_figure):
    """Each figure of the plan by its id, built when first asked for (a worker builds only those it tests)."""

    class Figures(dict):
        def __missing__(self, key):
            self[key] = got = gallery_figure(*PLAN[IDS.index(key)])
            return got

    return Figures()


@pytest.fixture(scope="module")
def finals(gallery_drawing):
    """The letters and words of each figure's teaching final, by its id (the drawing shared with the other
    modules that read the gallery's figures)."""

    class Finals(dict):
        def __missing__(self, key):
            self[key] = got = set(_texts(gallery_drawing(*PLAN[IDS.index(key)]).final()))
            return got

    return Finals()


@pytest.fixture(scope="module")
def plates(figures):
    """Each figure's plate, drawn when first asked for (several tests read the same plates)."""

    class Plates(dict):
        def __missing__(self, key):
            c, fig = figures[key]
            self[key] = got = _plate_svg(c, fig)
            return got

    return Plates()


def _texts(svg: str) -> list[str]:
    """The letters and words of an SVG (not the paper-coloured halos beneath them)."""
    root = ET.fromstring(svg.encode("utf-8"))
    return ["".join(t.itertext()) for t in root.iter(f"{SVG}text") if "halo" not in (t.get("class") or "")]


def _result_letters(fig, names=None) -> set[str]:
    """The letters the construction gave its result points (optionally only those in *names*)."""
    out = set()
    for s in fig.protocol.steps:
        if s.role != "result":
            continue
        for name, text in s.labels:
            if isinstance(fig.replay.get(name), Point) and (names is None or name in names):
                out.add(text.replace("'", "′"))  # drawn with the books' prime (the protocol writes 1')
    return out


def _plate_svg(c, fig) -> str:
    return render_svg(scene_for(c, fig, plate=True), style=STYLES["historical"], caption=printed_caption(c, fig, 1))


def test_the_gallery_has_the_books_figures():
    assert set(IDS) >= set([
        "crank-angle-rod_ratio4", "crank-angle-rod_ratio5", "crank-angle-rod_ratio6",
        "crank-parts18-rod_ratio5", "crank-parts9-rod_ratio5",
        "inertia-curve-rod_ratio4", "inertia-curve-rod_ratio5", "inertia-curve-rod_ratio6"])


@pytest.mark.parametrize("key", IDS)
def test_every_result_letter_is_in_the_teaching_final(figures, finals, key):
    c, fig = figures[key]
    texts = finals[key]
    want = _result_letters(fig)
    assert want and want <= texts, sorted(want - texts)


@pytest.mark.parametrize("key", IDS)
def test_every_result_letter_is_on_the_plate(figures, plates, key):
    c, fig = figures[key]
    texts = set(_texts(plates[key]))
    want = _result_letters(fig, plate_names(fig.protocol, fig.replay))
    assert want and want <= texts, sorted(want - texts)


@pytest.mark.parametrize("key", IDS)
def test_a_plate_prints_one_caption_as_a_book_does(figures, plates, key):
    # one language (the book's), upright, the number once, at most three lines, none broken in a number or
    # formula (construct lint's caption checks); the givens it leaves out are in the whole caption it carries
    root = ET.fromstring(plates[key].encode("utf-8"))
    lines = ["".join(t.itertext()) for t in root.iter(f"{SVG}text") if "cap" in (t.get("class") or "").split()]
    text = " ".join(lines)
    assert 1 <= len(lines) <= 3
    assert text.startswith("Fig. 1. ") and text.count("Fig. 1.") == 1
    c, fig = figures[key]
    title = re.sub(r" \(Fig\. \d+\)$", "", c.title.de.rstrip("."))  # the book's figure named once, in the citation
    assert title in text and c.title.en.rstrip(".") not in text
    assert "font-style:italic" not in re.search(r"\.cap\{[^}]*\}", plates[key]).group(0)
    assert [f.line() for f in lint_svg(plates[key], key) if f.kind.startswith("caption")] == []


@pytest.mark.parametrize("key", IDS)
def test_no_plate_runs_a_line_through_a_letter(plates, key):
    # a book sets a letter beside its line or breaks the line for it (construct lint's plate checks)
    found = [f.line() for f in lint_svg(plates[key], key) if f.kind == "through"]
    assert found == []


@pytest.mark.parametrize("key", [k for k in IDS if k.startswith("inertia-curve")])
def test_inertia_finals_carry_the_seven_characteristic_points(finals, plates, key):
    """Seed 000 c: $q_1$ ... $q_7$ (set below the line, as the book sets them), both in the teaching final and on
    the plate."""
    want = {"q" + "₁₂₃₄₅₆₇"[i] for i in range(7)}
    assert want <= finals[key]
    assert want <= set(_texts(plates[key]))


@pytest.mark.parametrize("key", [k for k in IDS if k.startswith("crank-parts")])
def test_crank_finals_carry_every_piston_position(figures, finals, plates, key):
    """Seed 001: the piston positions 1′ ... (n-1)′ to the division points 1 ... n-1."""
    c, fig = figures[key]
    n = fig.params["parts"]
    want = {f"{k}′" for k in range(1, n)} | {str(k) for k in range(1, n)}
    assert want <= finals[key]
    assert want <= set(_texts(plates[key]))


#: Names of the code that must never reach a reader (internal names, Python words, snake_case).
CODE_WORDS = re.compile(r"EinfFinf|\bc45\b|\bc135\b|D0top|\bMr1\b|\bMk1\b|_|\bsqrt\b|\blam\b|\bvert\b|\btop\b")
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*(?:\.[A-Za-z0-9_]+)*[′']*")  # a letter may carry primes (J′)


@pytest.mark.parametrize("key", IDS)
def test_captions_name_only_what_the_figure_letters(figures, key):
    """Every name in a step's caption is a letter of the figure so far, or a tag the frame shows, or the
    letter of a point a later step makes (what the step's group sets out to make: "crank point for q7").

    The frame tags the points of the current step, of its instrument's inputs and those
    its caption names (:meth:`Scene.tagged`); the letters are the labels of the steps so far.  A name of the protocol that is
    neither (P12 where the figure says 12, T7.G.Mr1, EinfFinf) must not be in the caption.
    """
    c, fig = figures[key]
    sc = scene_for(c, fig)
    names = {m.name for m in sc.marks}  # what is drawn (a length such as L is not)
    letters: set[str] = set()
    by_step: dict[int, list] = {}
    first: dict[str, int] = {}  # each letter or tag: the step that makes the first point it names
    for m in sc.marks:
        by_step.setdefault(m.step, []).append(m)
        if m.kind == "point":
            first.setdefault(m.label or sc.display_name(m.name), m.step)
    bad = []
    for k in range(1, len(sc.steps) + 1):
        letters.update(m.label for m in by_step.get(k, ()) if m.label)
        tags = {sc.display_name(n) for n in sc.tagged(k)}
        for text in sc.caption(k):
            if CODE_WORDS.search(text):
                bad.append((k, text))
                continue
            for letter in sorted((x for x in letters if not (x.isalnum() and x.isascii())), key=len, reverse=True):
                text = text.replace(letter, " ")  # a letter of several words ("O (l = ∞)") is the figure's own
            for tok in _NAME.findall(text):
                if tok in letters or tok in tags or first.get(tok, 0) > k:
                    continue
                tok = tok.rstrip("′'")
                if tok in names and tok not in letters and tok not in tags and not (tok.isalpha() and tok.islower()):
                    bad.append((k, tok, text))
    assert not bad, bad[:10]


@pytest.mark.parametrize("key", IDS)
def test_english_captions_use_the_books_symbols(figures, key):
    c, fig = figures[key]
    sc = scene_for(c, fig)
    for k in range(1, len(sc.steps) + 1):
        en = sc.caption(k)[1]
        assert not re.search(r"(?<![A-Za-z])w(?![A-Za-z])|\^2|sqrt|Gl\. \d", en), (k, en)


def _minutes(text: str) -> int:
    m = re.fullmatch(r"(\d+)°\s*(\d+)[′']", text.strip())
    assert m, text
    return int(m.group(1)) * 60 + int(m.group(2))


@pytest.mark.parametrize("ratio", [4, 5, 6])
def test_crank_angle_plate_carries_each_angle(ratio):
    """Tabelle 2's crank angles, on the plate: each found position's angle in degrees and minutes.

    Compared with the book's table (printed to the minute; it is off by one minute at
    0.5 and 0.6 for L/r = 5) and with Gl. (h), cos ω = x/2r (2L - x)/(x - r - L) + 1,
    evaluated here as printed.
    """
    c = get("crank-angle")
    fig = c.figure(rod_ratio=float(ratio))
    texts = _texts(_plate_svg(c, fig))
    values = [t for t in texts if re.fullmatch(r"\d+°\d\d′", t)]
    m = fig.params["divisions"]
    assert len(values) == m - 1
    col = ratio - 4
    r, L = 1.0, float(ratio)
    for j in range(1, m):
        x = 2 * r * j / m
        w = math.degrees(math.acos(x / (2 * r) * (2 * L - x) / (x - r - L) + 1))
        want = round(w * 60)
        assert want in {_minutes(v) for v in values}, (j, w)
        printed = _minutes(TABLE_2[j][1][col])
        assert abs(want - printed) <= 1, (j, want, printed)


def test_inertia_plate_marks_m_the_scale_and_the_zones(figures):
    c, fig = figures["inertia-curve-rod_ratio5"]
    texts = set(_texts(_plate_svg(c, fig)))
    assert {"m", "F/f", "1 at", "+", "−", "L = ∞"} <= texts  # "1 Kilogr. per 1 cm² = 1 Atm."


def test_crank_plate_dimensions_stroke_radius_and_rod(figures):
    c, fig = figures["crank-parts18-rod_ratio5"]
    svg = _plate_svg(c, fig)
    texts = set(_texts(svg))
    assert {"s = 2r", "r", "L = 5 r"} <= texts
    assert svg.count('class="arrow"') >= 4  # two dimensions, two heads each


def test_plate_captions_are_in_the_books_notation(figures):
    for key in IDS:
        de, en = plate_caption(*figures[key], 1)
        for text in (de, en):
            assert "rod_ratio" not in text and "method =" not in text and "4_1" not in text, text
    de, en = plate_caption(*figures["crank-parts18-rod_ratio5"], 1)
    assert "r/L = 1/5" in de and "Dürer" in en  # seed 000 writes the rod ratio r/L


def _font_sizes(svg: str) -> list[float]:
    return [float(v) for v in re.findall(r"font-size:([\d.]+)px", svg)]


@pytest.mark.parametrize("style", ["historical", "teaching"])
def test_gallery_page_letters_are_at_least_9px_as_displayed(figures, style):
    """index.html and README.md show a figure at most DISPLAY_PX wide, one per row."""
    c, fig = figures["inertia-curve-rod_ratio5"]
    sc = scene_for(c, fig, plate=style == "historical")
    svg = render_svg(sc, style=STYLES[style])
    width = float(re.search(r'width="([\d.]+)"', svg).group(1))
    shown = min(DISPLAY_PX, width) / width
    assert min(_font_sizes(svg)) * shown >= 9.0


@pytest.mark.parametrize("key", IDS)
def test_a_figure_letters_its_rod_one_way(figures, key):
    """The rod length is L in the figures after Anhang II and "Einfluß der Massenkräfte" (r/L) and l in those
    after § 146 (r/l): one letter in a figure's title, its steps' captions and its groups' titles alike (the
    crank's captions wrote l where the figure letters L: the length's letter was taken for a helper's)."""
    c, fig = figures[key]
    sc = scene_for(c, fig)
    texts = list(sc.title) + [t for k in range(1, len(sc.steps) + 1) for t in sc.caption(k)]
    texts += list(sc.group_captions.values())
    rods = {m.group(1) for t in texts for m in re.finditer(r"(?:r/|[Ss]chubstangenlänge |rod length )([Ll])(?!\w)", t)}
    assert len(rods) <= 1, rods


def test_words_of_a_title_stay_words_and_an_equation_keeps_its_parentheses(figures):
    """A word of the title that is also an object's name ("back" of the back-pressure line) is left a word
    where it runs on into a phrase, and "(Gl. 298)" reads "(Gl. (298))", both parentheses closed."""
    c, fig = figures[IDS[PLAN.index(("indicator-diagram", {}))]]
    sc = scene_for(c, fig)
    assert sc.readable("indicator diagram: clearance, admission and back pressure", "en") == \
        "indicator diagram: clearance, admission and back pressure"
    c, fig = figures[IDS[PLAN.index(("piston-force", {}))]]
    sc = scene_for(c, fig)
    titles = [t for t in sc.group_captions.values() if "Gl." in t]
    assert titles and all(t.count("(") == t.count(")") for t in titles), titles
