"""Both strokes of the piston-force construction (seed 001, eq. (298) with its ±, Tafel I's F' and F'').

References: eq. (298) with the + sign forward and, on the return stroke, with the angle from the crank-end dead
centre and the minus sign, evaluated with mpmath; Tafel I's printed areas F' = 1546,25 cm² and F'' = 1511,89 cm²;
Baumann's steam-diagram model written out here (cover side forward, the mirrored diagram for the crank side);
the exact kinematics' area balance by mpmath quadrature -- never this code's own output.
"""

import csv
import io
import math

import mpmath
import pytest

from construct.cli import main
from construct.constructions import get
from construct.constructions.crank import crank_angle, point_name
from construct.constructions.piston_force import (
    abscissa,
    area_balance,
    piston_area_sides,
    piston_force,
    return_mass_force,
    return_piston_force,
)

mpmath.mp.dps = 30
PF = get("piston-force")
G, N, R, L = 830, 50, mpmath.mpf("0.4"), mpmath.mpf("2.0")
LAM = R / L
#: Tafel I as printed (seed 001): F' = 1546,25 cm², F'' = 1511,89 cm²
F1, F2 = mpmath.mpf("1546.25"), mpmath.mpf("1511.89")
#: the plate's high-pressure diagram (piston_force.HP_DIAGRAM), written out: admission P over P0 absolute
P, P0, S1, S0, S3 = 7, 2, mpmath.mpf("0.3"), mpmath.mpf("0.08"), mpmath.mpf("0.15")


def A_mp():
    v = 2 * mpmath.pi * R * N / 60
    return mpmath.mpf(G) / mpmath.mpf("9.81") * v ** 2 / R


def steam_mp(x):
    return P + P0 if x <= S1 else (P + P0) * (S1 + S0) / (x + S0)


def back_mp(x):
    return P0 if x <= 1 - S3 else P0 * (S3 + S0) / (1 - x + S0)


@pytest.fixture(scope="module")
def fig():
    return PF.figure(revolution=True, parts=18)


def test_tafel_i_areas():
    f1, f2 = piston_area_sides()
    assert f1 == pytest.approx(float(F1), abs=0.005) and f2 == pytest.approx(float(F2), abs=0.005)


def test_return_mass_forces_are_298_with_the_minus_sign(fig):
    n = fig.params["parts"]
    for k in range(n + 1):
        w_fwd = mpmath.mpf(crank_angle(fig, point_name(fig, k)))
        w_back = mpmath.pi - w_fwd                   # the angle from the crank-end dead centre on the return
        expected = A_mp() * (mpmath.cos(w_back) - LAM * mpmath.cos(2 * w_back))
        assert return_mass_force(fig, k) == pytest.approx(float(expected), abs=1e-8)


def test_piston_forces_of_both_sides(fig):
    n = fig.params["parts"]
    for k in range(n + 1):
        x = mpmath.mpf(abscissa(fig, f"K{k}"))
        forward = F1 * steam_mp(x) - F2 * back_mp(x)
        # going back the crank side works (its diagram is the cover side's mirrored) against the cover side
        back = F2 * steam_mp(1 - x) - F1 * back_mp(1 - x)
        # Tafel I's areas are printed to 0.01 cm²: the pressures (at most 9 at) times 0.005 cm²
        assert piston_force(fig, k) == pytest.approx(float(forward), abs=0.1)
        assert return_piston_force(fig, k) == pytest.approx(float(back), abs=0.1)


def test_areas_of_each_stroke_against_mpmath(fig):
    """∫P_b dx over each stroke: acceleration and deceleration areas (eq. 298 over the exact path), mpmath."""
    A, lam = A_mp(), LAM

    def path(w):
        return (1 - mpmath.cos(w) + (1 - mpmath.sqrt(1 - lam ** 2 * mpmath.sin(w) ** 2)) / lam) / 2

    def f(w):  # P_b dx/dw on the forward stroke
        return A * (mpmath.cos(w) + lam * mpmath.cos(2 * w)) * mpmath.diff(path, w) * 2 * R

    w0 = mpmath.findroot(lambda w: mpmath.cos(w) + lam * mpmath.cos(2 * w), 1.6)
    acc, dec = mpmath.quad(f, [0, w0]), -mpmath.quad(f, [w0, mpmath.pi])
    fwd, ret = area_balance(fig), area_balance(fig, stroke="return")
    tol = 2 * (math.pi / 18) ** 3 * (1 + 4 * float(lam)) * float(A * 2 * R)   # the French curve's stated bound
    assert fwd["drawn_acceleration"] == pytest.approx(float(acc), abs=tol)
    assert fwd["drawn_deceleration"] == pytest.approx(float(dec), abs=tol)
    assert ret["drawn_acceleration"] == pytest.approx(float(dec), abs=tol)   # going back: accelerated near the crank end
    assert ret["drawn_deceleration"] == pytest.approx(float(acc), abs=tol)


def test_all_checks_pass(fig):
    bad = [c.name for c in PF.checks(fig) if not c.ok]
    assert not bad


def test_mass_forces_table_over_the_revolution(capsys):
    assert main(["table", "mass-forces", "--weight", "830", "--rpm", "50", "--crank-radius", "0.4", "--rod-length",
                 "2", "--revolution", "--parts", "6", "--format", "csv"]) == 0
    rows = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert list(rows[0]) == ["crank_angle_deg", "stroke", "x", "P_b"]
    assert [r["stroke"] for r in rows] == ["forward"] * 7 + ["return"] * 7
    assert [float(r["crank_angle_deg"]) for r in rows] == pytest.approx(
        [0, 30, 60, 90, 120, 150, 180, 180, 210, 240, 270, 300, 330, 360], abs=1e-6)
    A = A_mp()
    for r in rows:
        w = mpmath.radians(mpmath.mpf(r["crank_angle_deg"]))
        sign = 1 if r["stroke"] == "forward" else -1
        x = (1 - mpmath.cos(w) + (1 - mpmath.sqrt(1 - LAM ** 2 * mpmath.sin(w) ** 2)) / LAM) / 2
        assert float(r["x"]) == pytest.approx(float(x), abs=1e-6)
        assert float(r["P_b"]) == pytest.approx(float(sign * A * (mpmath.cos(w) + LAM * mpmath.cos(2 * w))), abs=1e-2)
    # the book's maximum, 1115 kg at the head-end dead centre, and at the end of the return stroke the same, reversed
    assert float(rows[0]["P_b"]) == pytest.approx(1115, rel=2e-3)
    assert float(rows[-1]["P_b"]) == pytest.approx(-1115, rel=2e-3)


def test_replay_and_check_cli(tmp_path, capsys):
    assert main(["check", "piston-force", "--revolution", "--parts", "6"]) == 0
    assert main(["replay", "piston-force", "--revolution", "--parts", "6", "--frames", "none",
                 "--out", str(tmp_path / "pf")]) == 0
    assert (tmp_path / "pf" / "final.svg").exists()


STRAIGHT = "x,p\n0,8\n0.5,5\n1,2\n1,1\n0.5,1\n0,1\n0,8\n"


def test_piston_force_from_a_card_against_closed_form(tmp_path):
    """A straight card (cover side 8 - 6x forward, 1 at back; crank side mirrored): F'p' - F''p'' both strokes."""
    card = tmp_path / "card.csv"
    card.write_text(STRAIGHT)
    fig = PF.figure(indicator=str(card), revolution=True, parts=6, method="exact")
    for k in range(7):
        x = mpmath.mpf(abscissa(fig, f"K{k}"))
        forward = F1 * (8 - 6 * x) - F2 * 1          # crank side exhausts at 1 at (the cover's back line mirrored)
        back = F2 * (8 - 6 * (1 - x)) - F1 * 1       # the crank side's steam line is the cover's mirrored
        assert piston_force(fig, k) == pytest.approx(float(forward), abs=0.1)
        assert return_piston_force(fig, k) == pytest.approx(float(back), abs=0.1)
    assert not [c.name for c in PF.checks(fig) if not c.ok]
    # forward stroke alone: one area, seed 001's P = F p_ü
    fig = PF.figure(indicator=str(card), parts=6, method="exact")
    F = (F1 + F2) / 2
    for k in range(7):
        x = mpmath.mpf(abscissa(fig, f"K{k}"))
        assert piston_force(fig, k) == pytest.approx(float(F * (8 - 6 * x - 1)), abs=0.1)
