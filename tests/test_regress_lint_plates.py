"""``construct lint`` on plates: strokes through a letter's core, captions a book would not print.

The plates are written here by hand, each with one fault put where the test
knows it is (a tick through a numeral, a ray through a turned letter, a
caption broken after "Fig."), and beside each its mended twin (the letter
beside the tick, the tick broken for it); a letter's ink box is the font's
own (matplotlib's outlines), not the code's.
"""

from __future__ import annotations

import pytest

from construct.regress.lint import lint_svg
from construct.regress.lint.fonts import text_extents
from construct.regress.lint.plates import CORE_MARGIN, caption_breaks

FONT = "'DejaVu Serif', serif"
CSS = f""".lb{{fill:#000;stroke:none;font-family:{FONT};font-size:12px;font-style:italic;text-anchor:middle}}
.lb.halo{{fill:#fff;stroke:#fff;stroke-width:3.5px}}
.pt{{fill:#fff;stroke:#000;stroke-width:0.6}}
.result{{stroke:#000;stroke-width:1.5;fill:none}}
.construction{{stroke:#000;stroke-width:0.45;fill:none}}
.fur{{fill:none;stroke:#000;stroke-width:0.6px}}
.hidden{{display:none}}
.leader{{fill:none;stroke:#000;stroke-width:0.4px}}
.cap{{font-family:{FONT};font-size:12px}}"""


def plate(body: str, *, cls: str = "plate") -> str:
    return (f'<svg xmlns="http://www.w3.org/2000/svg" class="{cls}" viewBox="0 0 400 300">'
            f"<style>{CSS}</style>{body}</svg>")


def letter(text: str, x: float, y: float, ident: str = "", transform: str = "") -> str:
    turn = f' transform="{transform}"' if transform else ""
    own = f' id="{ident}"' if ident else ""
    return (f'<text class="lb halo"{turn} x="{x:g}" y="{y:g}">{text}</text>'
            f'<text class="lb"{own}{turn} x="{x:g}" y="{y:g}">{text}</text>')


def through(svg: str) -> list[tuple[str, ...]]:
    return [f.labels for f in lint_svg(svg, "plate.svg") if f.kind == "through"]


def ink(text: str, x: float, y: float) -> tuple[float, float, float, float]:
    """The ink box of *text* set centred at baseline (x, y), from the font's outlines."""
    (x0, y0, x1, y1), adv = text_extents(text, FONT, 12.0, "italic")
    return (x - adv / 2 + x0, y + y0, x - adv / 2 + x1, y + y1)


# --------------------------------------------------------------------------- a stroke through a letter's core

def test_a_tick_through_a_numeral_is_found_and_the_numeral_beside_it_is_not():
    # the rod arc's tail through the stroke numeral 1 (crank-angle): a thin line down the middle of the 1
    x0, y0, x1, y1 = ink("1", 100, 60)
    tick = f'<line class="construction" x1="{(x0 + x1) / 2:g}" y1="30" x2="{(x0 + x1) / 2:g}" y2="80"/>'
    assert through(plate(tick + letter("1", 100, 60, "s0060-x1-label"))) == [("1",)]
    # set beside the tick, clear of it by its ink: nothing
    assert through(plate(tick + letter("1", 100 + (x1 - x0) + 3, 60, "s0060-x1-label"))) == []


def test_a_line_broken_for_the_letter_does_not_pass_through_it():
    x0, y0, x1, y1 = ink("B", 200, 100)
    xm = (x0 + x1) / 2
    whole = f'<path class="result" d="M{xm:g} 40L{xm:g} 160"/>'
    # the engraver's gap: the stroke stops a little above the ink and goes on a little below it
    broken = f'<path class="result" d="M{xm:g} 40L{xm:g} {y0 - 2:g}M{xm:g} {y1 + 2:g}L{xm:g} 160"/>'
    assert through(plate(whole + letter("B", 200, 100))) == [("B",)]
    assert through(plate(broken + letter("B", 200, 100))) == []


def test_the_halo_does_not_hide_a_line_that_crosses_the_letter():
    # the paper-coloured halo round the glyphs still lets the line through the counters of the A: found
    x0, y0, x1, y1 = ink("A", 150, 150)
    ray = f'<line class="construction" x1="{x0 - 30:g}" y1="{(y0 + y1) / 2:g}" x2="{x1 + 30:g}" y2="{(y0 + y1) / 2:g}"/>'
    assert through(plate(ray + letter("A", 150, 150))) == [("A",)]


def test_a_line_grazing_the_edge_of_the_ink_is_not_through_the_core():
    x0, y0, x1, y1 = ink("7", 150, 150)
    inside = CORE_MARGIN * 12.0 / 2  # within the margin the core leaves round the ink
    graze = f'<line class="construction" x1="{x1 - inside:g}" y1="100" x2="{x1 - inside:g}" y2="200"/>'
    assert through(plate(graze + letter("7", 150, 150))) == []


def test_a_turned_letter_is_judged_in_its_own_frame():
    # "33°07′" turned 30° along its ray (crank-angle): a ray beside it, parallel, misses the turned core that its
    # axis-aligned box would reach; a ray across it is found
    t = "rotate(-30 200 150)"
    x0, y0, x1, y1 = ink("33°07′", 200, 150)
    import math

    def turned(x, y):
        a = math.radians(-30)
        dx, dy = x - 200, y - 150
        return 200 + dx * math.cos(a) - dy * math.sin(a), 150 + dx * math.sin(a) + dy * math.cos(a)

    (ax, ay), (bx, by) = turned(x0 - 40, y1 + 2.5), turned(x1 + 40, y1 + 2.5)  # 2.5 below the ink, along it
    beside = f'<line class="construction" x1="{ax:g}" y1="{ay:g}" x2="{bx:g}" y2="{by:g}"/>'
    (cx, cy), (dx, dy) = turned((x0 + x1) / 2, y0 - 40), turned((x0 + x1) / 2, y1 + 40)
    across = f'<line class="construction" x1="{cx:g}" y1="{cy:g}" x2="{dx:g}" y2="{dy:g}"/>'
    text = letter("33°07′", 200, 150, transform=t)
    assert through(plate(beside + text)) == []
    assert through(plate(across + text)) == [("33°07′",)]
    # without its turn the same line beside would cross the letter's box
    assert beside and min(ay, by) < y1 < max(ay, by)


def test_a_hidden_line_does_not_count_a_leader_does_where_it_runs_into_a_letter():
    x0, y0, x1, y1 = ink("q6", 200, 100)
    xm, ym = (x0 + x1) / 2, (y0 + y1) / 2
    hidden = f'<line class="result hidden" x1="{xm:g}" y1="50" x2="{xm:g}" y2="150"/>'
    assert through(plate(hidden + letter("q6", 200, 100))) == []

    def tied(end: float) -> str:  # q6 set off above its point (200, 130), its leader ending *end* under the baseline
        return (f'<g class="lbg" transform="translate(200 130)"><line class="leader" x1="0" y1="-4" x2="0" '
                f'y2="{end:g}"/><text class="lb halo" x="0" y="-30">q6</text>'
                f'<text class="lb" id="q6-label" x="0" y="-30">q6</text></g>')

    # its own leader stopping short of its white is no stroke through it; one run on into its middle is
    assert through(plate(tied(-27))) == []
    assert through(plate(tied(ym - 130))) == [("q6",)]
    other = (f'<g class="lbg" transform="translate(260 {ym:g})"><line class="leader" x1="-10" y1="0" x2="{xm - 270:g}" '
             f'y2="0"/><text class="lb" id="q4-label" x="12" y="4">q4</text></g>')
    assert through(plate(letter("q6", 200, 100) + other)) == [("q6",)]


def test_only_a_plate_is_asked():
    x0, y0, x1, y1 = ink("1", 100, 60)
    tick = f'<line class="construction" x1="{(x0 + x1) / 2:g}" y1="30" x2="{(x0 + x1) / 2:g}" y2="80"/>'
    assert through(plate(tick + letter("1", 100, 60), cls="")) == []


# --------------------------------------------------------------------------- the caption

def caption(*lines: str) -> str:
    return "".join(f'<text class="cap mid" x="200" y="{250 + 14 * i}">{t}</text>' for i, t in enumerate(lines))


def test_a_caption_over_three_lines_is_found():
    four = caption("Fig. 3. Kurbelwinkel aus den Zehnteln des Hubes.", "r/L = 1/4, Hub in 10 Teilen.",
                   "— nach Anhang II, Fig. 77, Tabelle 2.", "Fig. 3. Crank angles from tenths of the stroke.")
    found = lint_svg(plate(four), "plate.svg")
    assert [f.kind for f in found] == ["caption-lines"] and "4 lines" in found[0].message
    assert lint_svg(plate(caption("Fig. 3. Kurbelwinkel aus den Zehnteln des Hubes.", "r/L = 1/4.")), "p.svg") == []


@pytest.mark.parametrize("first, second", [
    ("… nach Anhang II, „Darstellung der Massendrücke“, Fig.", "77, Tabelle 2."),
    ("Fig. 3. Kurbelwinkel aus den Zehnteln des Hubes. r/L =", "1/4, Hub in 10 Teilen."),
    ("Fig. 7. Druckverlauf im Viertakt, Höchstdruck 25", "at, r/L = 1/5."),
    ("Massen der Niederdruckseite, G", "= 990 kg, n = 50/min."),
    ("Fig. 21. Zwei Kurbeln unter 90°, Qr/((m₁ +", "m₂)v₁²) = 0,25."),
    ("Fig. 15. Kolbenüberdrucklinie (Gl.", "(298))."),
])
def test_a_caption_broken_inside_a_number_or_a_formula_is_found(first, second):
    found = lint_svg(plate(caption(first, second)), "plate.svg")
    assert [f.kind for f in found] == ["caption-break"]
    assert found[0].labels == (first, second)


def test_a_caption_broken_between_words_or_inside_a_phrase_is_not():
    lines = ["Fig. 1. Kolbenwege aus dem Kurbelkreis, Halbkreis in 18 Teilen (Dürers",
             "Dreiteilung). — nach „Einfluß der Massenkräfte“, Abb. 1051/1054; Anhang II, Fig. 77.",
             "r/L = 1/5, 1 at als 0,8 r gezeichnet."]
    assert caption_breaks(lines) == []
    assert lint_svg(plate(caption(*lines)), "plate.svg") == []
