"""The piston-force line with mass forces (seed 001, Abb. 1055), one stroke and both: constructed values
against mpmath and the book.

References: eq. (298) and the exact crank kinematics evaluated with mpmath (quadrature, root
finding), the seed's printed numbers (P_b,max ≈ 1115 kg and 1330 kg), Baumann's model of the
steam diagram -- never this code's own output.  Both strokes: eq. (298) with the + sign forward and,
on the return stroke, with the angle from the crank-end dead centre and the minus sign; Tafel I's
printed areas F' = 1546,25 cm² and F'' = 1511,89 cm²; Baumann's steam-diagram model written out here
(cover side forward, the mirrored diagram for the crank side); the exact kinematics' area balance by
mpmath quadrature.
"""

import csv
import io
import math

import mpmath
import pytest

from construct.constructions.checking import all_ok
from construct.cli.main import main
from construct.constructions import get
from construct.constructions.crank import crank_angle, point_name
from construct.constructions.piston_force import (
    abscissa,
    area_balance,
    mass_force,
    piston_area_sides,
    piston_force,
    return_mass_force,
    return_piston_force,
)
from construct.kernel.errors import InvalidParameter

MPMATH_DPS = 30  # the digits of the mpmath references: each test runs under mpmath.workdps (conftest.py)
PF = get("piston-force")
with mpmath.workdps(MPMATH_DPS):  # the constants at the references' digits, the process's mpmath left alone
    G_HP, G_LP, N, R, L = 830, 990, 50, mpmath.mpf("0.4"), mpmath.mpf("2.0")
    LAM = R / L
    #: Tafel I as printed (seed 001): F' = 1546,25 cm², F'' = 1511,89 cm²
    F1, F2 = mpmath.mpf("1546.25"), mpmath.mpf("1511.89")
    #: the plate's high-pressure diagram (piston_force.HP_DIAGRAM), written out: admission P over P0 absolute
    P, P0, S1, S0, S3 = 7, 2, mpmath.mpf("0.3"), mpmath.mpf("0.08"), mpmath.mpf("0.15")


def A_mp():
    v = 2 * mpmath.pi * R * N / 60
    return mpmath.mpf(G_HP) / mpmath.mpf("9.81") * v ** 2 / R


def steam_mp(x):
    return P + P0 if x <= S1 else (P + P0) * (S1 + S0) / (x + S0)


def back_mp(x):
    return P0 if x <= 1 - S3 else P0 * (S3 + S0) / (1 - x + S0)


def scale_mp(G, n=N, R=R):
    """(G/g) v^2 / R with v = 2 pi R n / 60, g = 9.81 (the book's)."""
    v = 2 * mpmath.pi * R * n / 60
    return mpmath.mpf(G) / mpmath.mpf("9.81") * v ** 2 / R


def path_mp(w, lam):
    return (1 - mpmath.cos(w) + (1 - mpmath.sqrt(1 - lam ** 2 * mpmath.sin(w) ** 2)) / lam) / 2


def two_term_mp(w, lam):
    return mpmath.cos(w) + lam * mpmath.cos(2 * w)


@pytest.fixture(scope="module")
def fig():
    return PF.figure()


def test_book_maximum_mass_forces():
    # The book prints 1115 kg (high-pressure side) and 1330 kg (low-pressure side) at phi = 0.
    hp, lp = PF.figure(parts=2), PF.figure(parts=2, weight=G_LP)
    assert mass_force(hp, 0) == pytest.approx(1115, rel=2e-3)
    assert mass_force(lp, 0) == pytest.approx(1330, rel=2e-3)
    assert mass_force(hp, 0) == pytest.approx(float(scale_mp(G_HP) * (1 + R / L)), rel=1e-12)
    assert mass_force(lp, 0) == pytest.approx(float(scale_mp(G_LP) * (1 + R / L)), rel=1e-12)


def test_mass_forces_follow_eq_298_at_the_drawn_angles(fig):
    n = fig.params["parts"]
    A = scale_mp(G_HP)
    for k in range(n + 1):
        w = crank_angle(fig, point_name(fig, k))
        assert mass_force(fig, k) == pytest.approx(float(A * two_term_mp(w, R / L)), abs=1e-8), k
        assert abscissa(fig, f"M{k}") == pytest.approx(float(path_mp(w, R / L)), abs=1e-12), k


def test_piston_forces_follow_baumanns_model(fig):
    g = fig.replay.givens
    F = mpmath.mpf(g["piston_area"])
    P, P0, s1, s0, s3 = (mpmath.mpf(g[k]) for k in ("admission", "back_pressure", "filling", "clearance", "compression"))
    # F from the printed diameters 45, 7.5 and 10 cm
    assert F == pytest.approx(float(mpmath.pi / 8 * (2 * 45 ** 2 - mpmath.mpf("7.5") ** 2 - 10 ** 2)), rel=1e-14)
    for k in range(fig.params["parts"] + 1):
        x = mpmath.mpf(abscissa(fig, f"K{k}"))
        steam = P + P0 if x <= s1 else (P + P0) * (s1 + s0) / (x + s0)
        back = P0 if x <= 1 - s3 else P0 * (s3 + s0) / (1 - x + s0)
        assert piston_force(fig, k) == pytest.approx(float(F * (steam - back)), abs=1e-7), k


def test_pressure_change_J_is_where_the_hyperbolas_cross(fig):
    g = fig.replay.givens
    P, P0, s1, s0, s3 = (mpmath.mpf(g[k]) for k in ("admission", "back_pressure", "filling", "clearance", "compression"))
    xj = mpmath.findroot(lambda x: (P + P0) * (s1 + s0) / (x + s0) - P0 * (s3 + s0) / (1 - x + s0), 0.9)
    assert abscissa(fig, "J") == pytest.approx(float(xj), abs=1e-11)
    # the force line changes sign between the ordinates around J
    signs = [piston_force(fig, k) > 0 for k in range(fig.params["parts"] + 1)]
    assert signs[0] and not signs[-1] and signs.count(True) == sum(1 for k in range(len(signs))
                                                                     if abscissa(fig, f"K{k}") < xj)


def test_area_balance_is_reported_against_mpmath(fig):
    lam = R / L
    A = scale_mp(G_HP)
    stroke = 2 * R
    a = area_balance(fig)

    def dx(w):
        return mpmath.diff(lambda t: path_mp(t, lam), w)

    def exact_accel(w):  # second derivative of the exact path over omega^2 R, per stroke 2R -> times 2
        return 2 * mpmath.diff(lambda t: path_mp(t, lam), w, 2)

    w_e = mpmath.findroot(exact_accel, 1.4)
    exact_acc = A * stroke * mpmath.quad(lambda w: exact_accel(w) * dx(w), [0, w_e])
    exact_dec = -A * stroke * mpmath.quad(lambda w: exact_accel(w) * dx(w), [w_e, mpmath.pi])
    # the kinetic energy at the speed maximum: (G/g) v_max^2 / 2
    v_max = 2 * mpmath.pi * R * N / 60 * 2 * dx(w_e)
    assert exact_acc == pytest.approx(float(mpmath.mpf(G_HP) / mpmath.mpf("9.81") * v_max ** 2 / 2), rel=1e-12)
    assert a["exact_acceleration"] == pytest.approx(float(exact_acc), rel=1e-10)
    assert a["exact_deceleration"] == pytest.approx(float(exact_dec), rel=1e-10)
    w_0 = mpmath.findroot(lambda w: two_term_mp(w, lam), 1.4)
    two_acc = A * stroke * mpmath.quad(lambda w: two_term_mp(w, lam) * dx(w), [0, w_0])
    two_dec = -A * stroke * mpmath.quad(lambda w: two_term_mp(w, lam) * dx(w), [w_0, mpmath.pi])
    assert a["two_term_acceleration"] == pytest.approx(float(two_acc), rel=1e-10)
    assert a["two_term_deceleration"] == pytest.approx(float(two_dec), rel=1e-10)
    # eq. (298) over the rod-arc path does not balance exactly: about 0.4 kg m of 193 for R/L = 1/5
    assert float(two_acc - two_dec) == pytest.approx(0.403, abs=0.001)
    # the drawn curve, planimetered, is within a thousandth of its own formula
    assert a["drawn_acceleration"] == pytest.approx(float(two_acc), rel=1e-4)
    assert a["drawn_deceleration"] == pytest.approx(float(two_dec), rel=1e-4)


def test_all_checks_pass_for_both_sides_and_nine_parts(fig):
    assert all_ok(PF.checks(fig))
    for params in ({"weight": G_LP, "parts": 9}, {"rpm": 120, "rod_length": 1.6, "parts": 9}):
        assert all_ok(PF.checks(PF.figure(**params))), params


def test_replay_with_new_speed_keeps_the_steps(fig):
    again = PF.replay(fig.protocol, rpm=100.0)
    assert mass_force(again, 0) == pytest.approx(float(scale_mp(G_HP, n=100) * (1 + R / L)), rel=1e-12)


@pytest.mark.parametrize("bad", [{"rod_length": 0.3}, {"weight": 0}, {"rpm": float("nan")}])
def test_bad_givens_raise(bad):
    with pytest.raises(InvalidParameter):
        PF.figure(**bad)


def test_table_mass_forces_csv(capsys):
    assert main(["table", "mass-forces", "--weight", "830", "--rpm", "50", "--crank-radius", "0.4", "--rod-length",
                 "2.0", "--parts", "9", "--format", "csv"]) == 0
    rows = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert list(rows[0]) == ["crank_angle_deg", "x", "P_b"] and len(rows) == 10
    A = scale_mp(G_HP)
    # the rows are keyed by the division's angle (20 degrees), measured where Dürer's trisection put the point:
    # within his error bound of it, times the largest slope of P_b (A (1 + 4 r/L)) and of x (1/2 (1 + r/L))
    from construct.kernel.division import durer_error_bound

    dw = durer_error_bound(math.radians(60.0))
    assert [float(row["crank_angle_deg"]) for row in rows] == [20.0 * k for k in range(10)]
    for row in rows:
        w = mpmath.radians(mpmath.mpf(row["crank_angle_deg"]))
        assert float(row["P_b"]) == pytest.approx(float(A * two_term_mp(w, R / L)), abs=float(A) * 1.8 * dw)
        assert float(row["x"]) == pytest.approx(float(path_mp(w, R / L)), abs=0.6 * dw)
    assert float(rows[0]["P_b"]) > 0 > float(rows[-1]["P_b"])  # accelerated at the start, decelerated at the end


def test_table_mass_forces_needs_its_givens(capsys):
    assert main(["table", "mass-forces", "--weight", "830"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--rpm" in err


def test_cli_replay_with_book_terms(tmp_path, capsys):
    assert main(["check", "piston-force", "--weight", "990", "--rpm", "50", "--crank-radius", "0.4",
                 "--rod-length", "2.0", "--filling", "0.25", "--parts", "9"]) == 0
    assert main(["check", "piston-force", "--rod-length", "0.2"]) == 2
    assert "rod length" in capsys.readouterr().err


def test_replay_equals_a_fresh_build():
    base = PF.figure(parts=9)
    again = PF.replay(base.protocol, rpm=80.0, weight=990.0, admission=6.0)
    fresh = PF.figure(parts=9, rpm=80.0, weight=990.0, admission=6.0)
    for k in range(10):
        assert mass_force(again, k) == pytest.approx(mass_force(fresh, k), abs=1e-9)
        assert piston_force(again, k) == pytest.approx(piston_force(fresh, k), abs=1e-9)


def test_the_sweeps_model_areas_equal_the_areas_of_each_set():
    """model_areas of a sweep's givens (one numpy pass over many rods) gives, set by set, its areas of one set."""
    import numpy as np

    from construct.constructions.piston_force import analytic as pf

    g = dict(PF.figure(parts=6).replay.givens)
    lengths = g["crank_radius"] * np.array([1.05, 1.3, 2.0, 5.0, 12.0, 50.0])
    swept = pf.model_areas({**g, "rod_length": lengths})
    for i, length in enumerate(lengths):
        one = pf.model_areas({**g, "rod_length": float(length)})
        for key, value in one.items():
            assert abs(swept[key][i] - value) <= 1e-13 * abs(value), (length, key)


# -- both strokes: the whole revolution ---------------------------------------------------------------

@pytest.fixture(scope="module")
def revolution_fig():
    """Both strokes (the whole revolution) at 18 parts."""
    return PF.figure(revolution=True, parts=18)


def test_tafel_i_areas():
    f1, f2 = piston_area_sides()
    assert f1 == pytest.approx(float(F1), abs=0.005) and f2 == pytest.approx(float(F2), abs=0.005)


def test_return_mass_forces_are_298_with_the_minus_sign(revolution_fig):
    n = revolution_fig.params["parts"]
    for k in range(n + 1):
        w_fwd = mpmath.mpf(crank_angle(revolution_fig, point_name(revolution_fig, k)))
        w_back = mpmath.pi - w_fwd                   # the angle from the crank-end dead centre on the return
        expected = A_mp() * (mpmath.cos(w_back) - LAM * mpmath.cos(2 * w_back))
        assert return_mass_force(revolution_fig, k) == pytest.approx(float(expected), abs=1e-8)


def test_piston_forces_of_both_sides(revolution_fig):
    n = revolution_fig.params["parts"]
    for k in range(n + 1):
        x = mpmath.mpf(abscissa(revolution_fig, f"K{k}"))
        forward = F1 * steam_mp(x) - F2 * back_mp(x)
        # going back the crank side works (its diagram is the cover side's mirrored) against the cover side
        back = F2 * steam_mp(1 - x) - F1 * back_mp(1 - x)
        # Tafel I's areas are printed to 0.01 cm²: the pressures (at most 9 at) times 0.005 cm²
        assert piston_force(revolution_fig, k) == pytest.approx(float(forward), abs=0.1)
        assert return_piston_force(revolution_fig, k) == pytest.approx(float(back), abs=0.1)


def test_areas_of_each_stroke_against_mpmath(revolution_fig):
    """∫P_b dx over each stroke: acceleration and deceleration areas (eq. 298 over the exact path), mpmath."""
    A, lam = A_mp(), LAM

    def path(w):
        return (1 - mpmath.cos(w) + (1 - mpmath.sqrt(1 - lam ** 2 * mpmath.sin(w) ** 2)) / lam) / 2

    def f(w):  # P_b dx/dw on the forward stroke
        return A * (mpmath.cos(w) + lam * mpmath.cos(2 * w)) * mpmath.diff(path, w) * 2 * R

    w0 = mpmath.findroot(lambda w: mpmath.cos(w) + lam * mpmath.cos(2 * w), 1.6)
    acc, dec = mpmath.quad(f, [0, w0]), -mpmath.quad(f, [w0, mpmath.pi])
    fwd, ret = area_balance(revolution_fig), area_balance(revolution_fig, stroke="return")
    tol = 2 * (math.pi / 18) ** 3 * (1 + 4 * float(lam)) * float(A * 2 * R)   # the French curve's stated bound
    assert fwd["drawn_acceleration"] == pytest.approx(float(acc), abs=tol)
    assert fwd["drawn_deceleration"] == pytest.approx(float(dec), abs=tol)
    assert ret["drawn_acceleration"] == pytest.approx(float(dec), abs=tol)   # going back: accelerated near the crank end
    assert ret["drawn_deceleration"] == pytest.approx(float(acc), abs=tol)


def test_all_checks_pass_over_the_revolution(revolution_fig):
    bad = [c.name for c in PF.checks(revolution_fig) if not c.ok]
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


def test_replay_and_check_cli_over_the_revolution(tmp_path, capsys):
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


@pytest.mark.parametrize("prefix, start", [("", -1.0), ("r", 1.0)])
def test_the_free_forces_of_the_admission_are_hatched_over_the_whole_admission_on_both_strokes(revolution_fig,
                                                                                             prefix, start):
    """The hatched free forces of the admission reach from the dead centre the stroke starts at to the cut-off.

    The drawing spans the stroke from x = -1 (head end) to x = +1 (crank end); the filling (30 % of the stroke,
    Tafel I) ends 0.6 from the start -- at -0.4 forward, at +0.4 on the return.  On the return the pieces
    were once taken in the forward order, and only 0.40...0.43 was hatched.
    """
    filling = 0.30  # Tafel I: 30 % Füllung, the figure's default
    cut_off = start - 2.0 * filling * start
    area = revolution_fig.replay[f"{prefix}free.a"]
    xs = [p[0] for _, ring in area.pieces for p in ring]
    assert min(xs) == pytest.approx(min(start, cut_off), abs=1e-9)
    assert max(xs) == pytest.approx(max(start, cut_off), abs=1e-9)
