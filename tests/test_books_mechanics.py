"""Seed 002's printed numbers (§ 146) against values computed here with mpmath, and their verdicts."""

import json
from pathlib import Path

import mpmath
import pytest

from construct.cli.main import main
from construct.books.errata import CLASSES, errata_of
from construct.books.mechanics.errata import entries
from construct.books.mechanics import printed as seed002

_HERE = Path(__file__).resolve()
SEEDS = next((p for p in (_HERE.parents[2] / "shared" / "seeds", _HERE.parents[3] / "shared" / "seeds")
              if p.is_dir()), None)


def _alpha1():
    return mpmath.asin((4 / mpmath.pi) ** 2 - 1) / 2


def reference(quantity):
    """The claim of each printed number, solved independently (40 digits)."""
    with mpmath.workdps(40):
        a1 = _alpha1()
        if quantity == "sin_2alpha":
            return float((4 / mpmath.pi) ** 2 - 1)
        if quantity == "alpha1":
            return float(mpmath.degrees(a1))
        if quantity == "alpha2":
            return float(90 - mpmath.degrees(a1))
        if quantity == "vmin_coefficient":  # -(1 + sin a1 - cos a1 - 4 a1 / pi)
            return float(-(1 + mpmath.sin(a1) - mpmath.cos(a1) - 4 * a1 / mpmath.pi))
        if quantity == "equal_speed_spacing":  # 1 + sin a - cos a = 4a/pi between the extremes
            return float(mpmath.degrees(mpmath.findroot(lambda a: 1 + mpmath.sin(a) - mpmath.cos(a) - 4 * a / mpmath.pi,
                                                        mpmath.pi / 4 + mpmath.mpf("0.01"))))
    raise KeyError(quantity)


def test_true_values_match_an_independent_computation():
    by_row = {e.row: e for e in entries()}
    for p in seed002.PRINTED:
        e = by_row[p.row]
        assert e.true == pytest.approx(reference(p.quantity), abs=1e-9), p.quantity
        assert e.source == seed002.SOURCE == "mechanics"


@pytest.mark.parametrize("quantity, units", [
    ("sin_2alpha", (0.6211 - 0.62113894) / 1e-4),    # -0.39: correctly rounded
    ("alpha1", (19 * 60 + 12 - 19.19967678 * 60)),    # +0.02 minutes
    ("alpha2", (70 * 60 + 48 - 70.80032322 * 60)),    # -0.02 minutes
    ("vmin_coefficient", (0.0422 - 0.04217639) / 1e-4),  # +0.24
])
def test_verdicts(quantity, units):
    e = next(e for e in entries() if seed002.PRINTED[[p.quantity for p in seed002.PRINTED].index(quantity)].row == e.row)
    assert e.units == pytest.approx(units, abs=1e-3)
    assert e.class_ == "agrees"


def test_constructed_angles_are_in_the_notes():
    notes = {e.row: e.note for e in entries()}
    assert "19°12.11′" in notes["α₁ (kleinste Geschwindigkeit)"]   # Kochański: 8 seconds of arc too large
    assert "70°47.89′" in notes["α₂ (größte Geschwindigkeit)"]


@pytest.mark.skipif(SEEDS is None, reason="the shared seed folder is not next to the repository")
def test_printed_strings_are_in_the_seed():
    text = next(SEEDS.glob("002_*.txt")).read_text(encoding="utf-8")
    for p in seed002.PRINTED:
        latex = p.text.replace("° ", "^\\circ ")
        assert p.text in text or latex in text, p.text


def test_errata_command_lists_seed_002(capsys):
    assert main(["errata", "--book", "mechanics", "--format", "json"]) == 0
    records = json.loads(capsys.readouterr().out)
    assert len(records) == len(seed002.PRINTED)
    assert {r["class"] for r in records} <= set(CLASSES)
    assert all(r["source"] == seed002.SOURCE for r in records)
    assert len(errata_of("all")) == sum(len(errata_of(book)) for book in ("anhang-ii", "handbook", "mechanics", "baumann"))


def test_errata_command_rejects_an_unknown_book(capsys):
    assert main(["errata", "--book", "kinematics"]) == 2
    assert main(["errata", "--seed", "003"]) == 2
