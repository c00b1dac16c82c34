"""The styles: the paper colour as an option (white by default, the cream tint on the screen), pure black
ink for the historical plate, line weights in points for print."""

import re

import pytest

from construct.constructions import get
from construct.kernel.errors import InvalidParameter
from construct.render.output import write_replay
from construct.render.styles import HISTORICAL, MIN_LINE_PT, PRINT_STROKES, STYLES, LineWeights, paper_colour

#: Every colour a style sheet or an element attribute names.
COLOUR = re.compile(r"#[0-9a-fA-F]{3,6}\b")


def colours(svg: str) -> set[str]:
    return {c.lower() for c in COLOUR.findall(svg)}


def test_the_historical_plate_is_pure_black_on_white():
    """A plate for print: the paper white (no tint to print as a grey), every line and letter pure black."""
    svg = get("crank").figure(parts=6).svg("historical")
    assert colours(svg) <= {"#000000", "#ffffff"}
    assert re.search(r'<rect fill="#ffffff" height="[0-9.]+" id="background"', svg)


def test_the_cream_tint_is_for_the_screen(tmp_path):
    """The replay's screen pages (the player) show the paper's tone; final.svg, the printed plate, is white."""
    c = get("crank")
    write_replay(c, c.figure(parts=6), tmp_path / "out", style="historical")
    final = (tmp_path / "out" / "final.svg").read_text(encoding="utf-8")
    player = (tmp_path / "out" / "player.html").read_text(encoding="utf-8")
    assert "#f3ead6" not in final and "#ffffff" in final
    assert 'fill="#f3ead6"' in player and HISTORICAL.for_screen().paper == "#f3ead6"


def test_a_style_without_a_screen_paper_is_the_same_on_the_screen():
    assert STYLES["teaching"].for_screen() is STYLES["teaching"]


@pytest.mark.parametrize("value, expected", [("white", "#ffffff"), ("cream", "#f3ead6"), ("#AbC", "#abc")])
def test_paper_colours_by_name_or_hex(value, expected):
    assert paper_colour(value) == expected


@pytest.mark.parametrize("value", ["", "red", "#12345", "#ffffff;stroke:red", None, 3])
def test_a_paper_colour_that_is_not_one_is_refused(value):
    with pytest.raises(InvalidParameter, match="paper colour"):
        paper_colour(value)


@pytest.mark.parametrize("weight", [0.19, 0.0, -1.0, float("nan"), float("inf"), True, "0.5"])
def test_no_line_weight_under_the_finest_print_holds(weight):
    with pytest.raises(InvalidParameter, match="line weight heavy"):
        LineWeights(heavy=weight)


@pytest.mark.parametrize("style", sorted(STYLES))
def test_in_print_every_stroke_has_its_weight_in_points(style):
    """Laid out for a page, each stroked class of the sheet is drawn with its weight in points, none under 0.2 pt."""
    st = STYLES[style].for_print(340.16, 8.0)
    css = st.css()
    for selector, weight in PRINT_STROKES:
        rules = re.findall(re.escape(selector) + r"\{stroke-width:([0-9.]+)\}", css)
        assert rules, selector
        pt = float(rules[-1]) * st.print_pt
        assert pt == pytest.approx(getattr(st.weights, weight), abs=1e-3) and pt >= MIN_LINE_PT - 1e-3


@pytest.mark.parametrize("width, letter", [(0.0, 8.0), (-3.0, 8.0), (float("inf"), 8.0), (340.0, float("nan")),
                                           (340.0, 0.0)])
def test_a_print_layout_needs_a_positive_size(width, letter):
    with pytest.raises(InvalidParameter, match="positive number of points"):
        HISTORICAL.for_print(width, letter)
