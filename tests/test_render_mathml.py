"""The books' formulas as MathML (construct.render.mathml): what the OCR'd LaTeX and the Unicode forms become.

The expectations are MathML's own elements (MathML Core: msqrt for a root, mfrac for a fraction, msub for an
index, mn for a number) for formulas as the errata quote them from the texts.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import pytest

from construct.books.errata import all_errata
from construct.render.mathml import formula_html, to_mathml, with_subscripts


def _tree(mathml: str) -> ET.Element:
    return ET.fromstring(mathml)


def _tokens(mathml: str, tag: str) -> list[str]:
    return [e.text or "" for e in _tree(mathml).iter(tag)]


def test_a_decimal_comma_stays_inside_its_number():
    # Baumann: "P (1 - \frac{1}{1,2 κ} (cos α + 0,2 cos 2α))"
    got = to_mathml(r"P (1 - \frac{1}{1,2 κ} (cos α + 0,2 cos 2α))")
    assert {"1,2", "0,2"} <= set(_tokens(got, "mn"))
    assert "," not in _tokens(got, "mo")


def test_function_names_are_upright_words_not_three_letters():
    got = to_mathml("cos ω = (-L + √(L² + 16r²)) / 4r")  # Anhang II c), in Unicode
    assert "cos" in _tokens(got, "mi") and "c" not in _tokens(got, "mi")
    root = _tree(got).find(".//msqrt")
    assert root is not None  # √(…) is a root whose bar covers L² + 16r²
    inside = "".join(e.text or "" for e in root.iter())
    assert inside == "L2+16r2"
    assert "tg" in _tokens(to_mathml("tg β = ∂y/∂x"), "mo") + _tokens(to_mathml("tg β = ∂y/∂x"), "mi")


def test_indices_fractions_and_integrals_are_mathml_structure():
    got = to_mathml(r"f_x = (P_0 - k p_0) \int_{s_1}^{s} \frac{s_1 - s_a}{s_a + s_0} d s_a")
    tree = _tree(got)
    assert tree.find(".//mfrac") is not None and tree.find(".//msubsup") is not None
    subs = [("".join(c.text or "" for c in e)) for e in tree.iter("msub")]
    assert {"fx", "P0", "p0", "s1", "sa", "s0"} <= set(subs)


def test_words_in_a_formula_are_text():
    got = to_mathml(r"Kranzgewicht = G_{total} / (1 + 0,08075 v^2/k_z)")
    assert {"Kranzgewicht", "total"} <= set(_tokens(got, "mtext"))
    assert set(_tokens(got, "mi")) == {"G", "v", "k", "z"}  # not K, r, a, n, ... one italic letter each


@pytest.mark.parametrize("e", [e for e in all_errata() if e.table == "formula"], ids=lambda e: f"{e.source}-{e.row}")
def test_every_printed_formula_converts_without_leaving_latex(e):
    for text in (e.printed, e.true):
        got = formula_html(text)
        shown = re.sub(r"<[^>]+>", "", got)
        assert got.startswith("<math>") and not re.search(r"\\[A-Za-z]|[_^{}]", shown), shown


def test_a_long_formula_can_wrap_at_its_equals_signs():
    got = formula_html("tg β = ∂y/∂x = F/f (1 + 4 r/L cos ω) / (r (1 + r/L cos ω))")
    assert got.count("<math>") == 3 and got.count("</math> <math>") == 2
    # an equals sign inside brackets does not cut: (F/f = 1) is one piece
    assert formula_html("q = cos ω + r/L cos 2ω  (F/f = 1)").count("<math>") == 3


def test_names_in_running_text_get_their_subscripts():
    assert with_subscripts("Fehler f_x") == "Fehler f<sub>x</sub>"
    assert with_subscripts("P_b,max high-pressure side") == "P<sub>b,max</sub> high-pressure side"
    assert with_subscripts("G_{total} = G_1(1 + v²)") == "G<sub>total</sub> = G<sub>1</sub>(1 + v²)"
    assert with_subscripts("t'_a < 1") == "t'<sub>a</sub> &lt; 1"
