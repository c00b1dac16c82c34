"""Errata of seed 001's worked example (Tafel I), against values recomputed here with mpmath.

The printed strings are read off the seed text; the true values are the formulas the text
names (F = pi/4 (D^2 - d^2), v = pi D n / 60, eq. (298) at phi = 0), evaluated with mpmath.
"""

import json

import mpmath
import pytest

from construct.cli.main import main
from construct.books.handbook.errata import entries
from construct.books.handbook import printed as seed001

MPMATH_DPS = 30  # the digits of the mpmath references: each test runs under mpmath.workdps (conftest.py)


@pytest.fixture(scope="module")
def by_row():
    return {e.row: e for e in entries()}


def test_reference_data_stays_as_printed():
    texts = {p.row: p.text for p in seed001.worked_example()}
    assert texts == {"F'": "1546.3", "F''": "1511.9", "G high-pressure side": "830", "G low-pressure side": "990",
                     "v": "2.095", "P_b,max high-pressure side": "1115", "P_b,max low-pressure side": "1330",
                     "9 parts": "20", "18 parts": "10"}
    assert seed001.PART_WEIGHTS["connecting_rod"] == 220.0


def test_agrees_piston_area_crank_side(by_row):
    e = by_row["F''"]
    true = mpmath.pi / 4 * (45 ** 2 - 10 ** 2)  # 1511.89 cm^2
    assert e.true == pytest.approx(float(true), rel=1e-15)
    assert e.class_ == "agrees" and abs(e.units) < 0.1


def test_agrees_weights_with_half_the_rod(by_row):
    # 122 + 122 + 282 + 190 + 220/2 = 826 -> "rund 830"; 282 + 122 + 282 + 190 + 110 = 986 -> "rund 990"
    assert by_row["G high-pressure side"].true == 826.0 and by_row["G high-pressure side"].class_ == "agrees"
    assert by_row["G low-pressure side"].true == 986.0 and by_row["G low-pressure side"].class_ == "agrees"


def test_slip_speed_from_pi_22_7(by_row):
    e = by_row["v"]
    true = mpmath.pi * mpmath.mpf("0.8") * 50 / 60
    assert e.true == pytest.approx(float(true), rel=1e-15)
    assert e.class_ == "slip" and e.units == pytest.approx(float((mpmath.mpf("2.095") - true) * 1000), abs=1e-9)
    assert "22/7" in e.note


def test_slip_largest_mass_force_high_pressure_side(by_row):
    e = by_row["P_b,max high-pressure side"]
    v = mpmath.pi * mpmath.mpf("0.8") * 50 / 60
    true = mpmath.mpf(830) / mpmath.mpf("9.81") * v ** 2 / mpmath.mpf("0.4") * (1 + mpmath.mpf("0.4") / 2)
    assert e.true == pytest.approx(float(true), rel=1e-14)  # 1113.39 kg
    assert e.class_ == "slip" and 1.5 < e.units < 1.7


def test_no_misprints_in_the_worked_example():
    # Read by hand: every printed number is within two units of its last place.
    assert {e.class_ for e in entries()} <= {"agrees", "slip"}


def test_source_names_the_book_in_the_cli(capsys):
    assert main(["errata", "--format", "json"]) == 0
    records = json.loads(capsys.readouterr().out)
    mine = [r for r in records if r["source"] == "handbook"]
    assert len(mine) == len(seed001.worked_example())
    assert {r["table"] for r in mine} == {"Tafel I", "semicircle"}


def test_transcription_is_in_the_seed_text():
    from pathlib import Path

    # the shared seed folder beside the repository (or beside the folder of worktrees)
    here = Path(__file__).resolve()
    seeds = next((d for d in (here.parents[2] / "shared" / "seeds", here.parents[3] / "shared" / "seeds")
                  if d.is_dir()), here.parents[2] / "shared" / "seeds")
    found = sorted(seeds.glob("001_*.txt")) if seeds.is_dir() else []
    if not found:
        pytest.skip(f"seed 001 not found under {seeds}")
    text = found[0].read_text(encoding="utf-8")
    for p in seed001.worked_example():
        assert p.text.replace(".", ",") in text, p
    for name, kg in seed001.PART_WEIGHTS.items():
        assert f"{kg:.0f} kg" in text, name
    assert "(45^2 - 7,5^2)" in text and "(45^2 - 10^2)" in text and "n = 50" in text
