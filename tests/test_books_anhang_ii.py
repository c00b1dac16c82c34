"""The transcription of seed 000's printed numbers: complete, as printed, well formed.

The strongest test reads the seed text itself and compares every transcribed
string with what the seed prints; it is skipped only when the shared seed
folder is not next to the repository.
"""

from __future__ import annotations

import re
from collections import Counter
from decimal import Decimal
from pathlib import Path

import pytest

from construct.books.errata import read_printed
from construct.books.anhang_ii import printed as seed000

SEEDS = Path(__file__).resolve().parents[2] / "shared" / "seeds"


@pytest.fixture(scope="module")
def seed_text() -> str:
    files = sorted(SEEDS.glob("000_*.txt")) if SEEDS.is_dir() else []
    if not files:
        pytest.skip(f"seed 000 not found under {SEEDS} (the shared seed folder is not next to the repository)")
    return files[0].read_text(encoding="utf-8")


def _normalise(latex: str) -> str:
    """The seed's LaTeX spellings turned into the transcription's conventions."""
    text = latex.replace("\\cdot ", "·").replace("\\cdot", "·").replace("^\\circ", "°").replace("$", "")
    return re.sub(r"\\frac\{([^{}]*)\}\{([^{}]*)\}", r"\1/\2", text)


# --------------------------------------------------------------------------
# Against the seed text.


def test_table_1_equals_the_seed(seed_text):
    rows = [line.split("\t") for line in seed_text.splitlines() if re.match(r"^\d+°\t", line)]
    assert [(r[0], tuple(r[1:])) for r in rows] == list(seed000.TABLE_1)


def test_table_2_equals_the_seed(seed_text):
    rows = [line.split("\t") for line in seed_text.splitlines() if re.match(r"^(0|0\.\d|1\.0)\t.*°", line)]
    assert [(r[0], tuple(r[1:7]), r[7]) for r in rows] == list(seed000.TABLE_2)


def _line_containing(text: str, marker: str) -> str:
    lines = [line for line in text.splitlines() if marker in line]
    assert len(lines) == 1, f"expected one seed line with {marker!r}, found {len(lines)}"
    return _normalise(lines[0])


# Each row of section c) is found in the seed by a marker of its own line.
_POINT_LINES = {
    ("s5", "s5"): "s_5 =",
    ("q6", "q6_cos"): "$\\cos \\omega = \\cdot",
    ("q6", "q6_omega"): "wird\t$\\omega = ",
    ("q6", "q6_x"): "bei  $x = ",
    ("q7", "q7_cos"): "wird $\\cos \\omega =$",
    ("q7", "q7_omega"): "$\\omega =$\t",
    ("q7", "q7_x"): "q_7 = + m$  bei",
}


@pytest.mark.parametrize("row, column, quantity, printed", seed000.CHARACTERISTIC_POINTS)
def test_characteristic_points_equal_the_seed(seed_text, row, column, quantity, printed):
    line = _line_containing(seed_text, _POINT_LINES[row, quantity])
    if quantity.endswith("_omega"):
        found = re.findall(r"\d+°(?: \d+')?", line)
    else:
        found = re.findall(r"·\d+", line)
    assert tuple(found) == printed


def test_tangent_values_equal_the_seed(seed_text):
    # The OCR scrambled the layout of this little table, so compare what is printed
    # as a multiset; which L/r each value belongs to is checked by the errata tests.
    start = seed_text.index("Es wird für:")
    block = _normalise(seed_text[start : seed_text.index("Für die Kurbelstellung", start)])
    printed = re.findall(r"(\d+/\d+) = (\.?\d+(?:\.\d+)?)", block)
    printed_texts = [t for pair in printed for t in pair]
    assert re.search(r"= 0 \\text\{ mal \}", block), "the 0 at 180° for L/r = 4"
    transcribed = [v.text for v in seed000.tangent_values() if v.text not in ("0", "F/f")]
    assert Counter(transcribed) == Counter(printed_texts)
    # At 90° the general row prints r·tg β = F/f, valid for every L/r.
    row = next(line for line in seed_text.splitlines() if line.startswith("$r \\cdot \\operatorname{tg} \\beta =$"))
    assert row.split("\t")[2] == "$\\frac{F}{f}$"


# The seed's LaTeX for each printed formula the errata quote.
_FORMULA_SOURCES = {
    "b) Tabelle 2 header": "\\frac{q}{f} = \\cos \\omega + \\frac{r}{L} \\cos 2\\omega",
    "c) q7": "\\cos \\omega = \\frac{-L + \\sqrt{L^2 - 16r^2}}{4r}",
    "d) ∂y/∂ω": "\\frac{\\partial y}{\\partial \\omega} = \\frac{F}{f} \\left[ \\sin \\omega + 4 \\frac{r}{L} \\sin \\omega \\cos \\omega \\right]",
    "d) Gl. (i)": "\\frac{\\frac{F}{f} \\left( 1 + 4 \\frac{r}{L} \\cos \\omega \\right)}{r \\left( 1 + \\frac{r}{L} \\cos \\omega \\right)}",
    "d) Gl. (i₁) 90°": "$\\frac{F}{f} \\cdot \\frac{r}{L}$",
    "d) Gl. (i₁) 180°": "$\\frac{F}{f} \\left( 1 - \\frac{r}{L} \\right)$",
}


def test_printed_formulas_are_in_the_seed(seed_text):
    assert {f.row for f in seed000.printed_formulas()} == set(_FORMULA_SOURCES)
    for row, latex in _FORMULA_SOURCES.items():
        assert latex in seed_text, row
    y_row = next(line for line in seed_text.splitlines() if line.startswith("$y =$"))
    # y at 90° and 180° as printed: no minus sign in front of either.
    assert y_row.split("\t")[2:4] == [_FORMULA_SOURCES["d) Gl. (i₁) 90°"], _FORMULA_SOURCES["d) Gl. (i₁) 180°"]]


# --------------------------------------------------------------------------
# Shape of the transcription (independent of the seed file).


def test_counts_per_table():
    # Counted in the seed: Tabelle 1 has 19 rows (0° … 180° by 10°) × 8 numbers
    # (cos ω, cos 2ω, three r/L·cos 2ω, three sums); Tabelle 2 11 rows (0 … 1.0 of
    # the stroke) × 6 (three ω, three q), its two path columns being row labels;
    # section c) 7 rows × 3 rod ratios (s5; cos ω, ω, x for q6 and q7); section d)
    # 8/5 1.6 9/6 1.5 10/7 1.4 at 0°, F/f at 90°, 0 1/4 .25 2/5 .4 at 180°.
    assert len(seed000.table_1()) == 19 * 8
    assert len(seed000.table_2()) == 11 * 6
    assert len(seed000.characteristic_points()) == 7 * 3
    assert len(seed000.tangent_values()) == 6 + 1 + 5
    assert len(seed000.all_printed()) == 152 + 66 + 21 + 12


def test_every_printed_value_reads_as_a_number():
    for v in seed000.all_printed():
        reading = read_printed(v.text, v.resolution)
        assert reading.unit > 0, v


def test_labels_are_unique_and_say_what_each_number_is():
    keys = [(v.table, v.row, v.column) for v in seed000.all_printed()]
    assert len(keys) == len(set(keys))
    for v in seed000.all_printed():
        if v.quantity not in ("cos_omega", "cos_2omega") and not (v.quantity == "r_tg_beta" and v.row == "90°"):
            assert v.rod_ratio in seed000.ROD_RATIOS, v
            assert f"L/r={v.rod_ratio}" in v.column, v
        if v.table in ("Tabelle 1", "tangents"):
            assert v.omega_deg == float(v.row.rstrip("°"))
        if v.table == "Tabelle 2":
            assert v.stroke_fraction == float(v.row)


def test_table_2_return_column_counts_the_tenths_backwards():
    # "Für den Rückgang hätte die Zählung der Zehntel verkehrt zu erfolgen."
    for forward, _values, backward in seed000.TABLE_2:
        assert Decimal(forward) + Decimal(backward) == 1


def test_transcription_keeps_the_books_inconsistencies():
    # Never "fixed": Tabelle 1 truncates 1/6 to 0.1666, Tabelle 2 rounds it to 1.1667.
    t1 = {(v.row, v.column): v.text for v in seed000.table_1()}
    t2 = {(v.row, v.column): v.text for v in seed000.table_2()}
    assert t1["0°", "r/L·cos 2ω (L/r=6)"] == "0.1666"
    assert t1["180°", "cos ω + r/L·cos 2ω (L/r=6)"] == "-0.8334"
    assert t2["0", "q (L/r=6)"] == "1.1667"
    assert t2["1.0", "q (L/r=6)"] == "-0.8333"
