"""The piston-force line with mass forces (seed 001, Abb. 1055): constructed values against mpmath and the book.

References: eq. (298) and the exact crank kinematics evaluated with mpmath (quadrature, root
finding), the seed's printed numbers (P_b,max ≈ 1115 kg and 1330 kg), Baumann's model of the
steam diagram -- never this code's own output.
"""

import csv
import io

import mpmath
import pytest

from construct.constructions.checking import all_ok
from construct.cli import main
from construct.constructions import get
from construct.constructions.crank import crank_angle, point_name
from construct.constructions.piston_force import (
    abscissa,
    area_balance,
    mass_force,
    piston_force,
)
from construct.kernel.errors import InvalidParameter

mpmath.mp.dps = 30
PF = get("piston-force")
G_HP, G_LP, N, R, L = 830, 990, 50, mpmath.mpf("0.4"), mpmath.mpf("2.0")


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
    for row in rows:
        w = mpmath.radians(mpmath.mpf(row["crank_angle_deg"]))
        assert float(row["P_b"]) == pytest.approx(float(A * two_term_mp(w, R / L)), abs=1e-8)
        assert float(row["x"]) == pytest.approx(float(path_mp(w, R / L)), abs=1e-12)
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


def test_the_area_integrals_on_arrays_equal_the_scalar_integrands_point_by_point():
    """area_balance integrates on an array of Gauss nodes; the same rule summed node by node with the scalar
    formulas (math, one angle at a time) gives the same areas, and the exact acceleration area is the
    kinetic energy at the greatest speed, found independently by mpmath's derivative of the piston path."""
    import math

    import numpy as np

    from construct.constructions import piston_force as pf

    xs, ws = np.polynomial.legendre.leggauss(20)
    for lam in (1 / 1.05, 0.2, 0.02):
        for scalar, array in ((pf._two_term, pf._two_term_array), (pf._exact_accel, pf._exact_accel_array)):
            def one(w, f=scalar):
                return f(w, lam) * pf._dx_dw(w, lam)
            h = math.pi / 16
            by_node = sum(w * one(i * h + (x + 1.0) * h / 2.0) for i in range(16) for x, w in zip(xs, ws)) * h / 2
            on_array = pf._gauss(lambda w, f=array: f(w, lam) * pf._dx_dw_array(w, lam), 0.0, math.pi)
            assert abs(on_array - by_node) <= 1e-14, (lam, scalar.__name__)
        we = pf._zero(lambda w: pf._exact_accel(w, lam), 0.0, math.pi)
        acc = pf._gauss(lambda w: pf._exact_accel_array(w, lam) * pf._dx_dw_array(w, lam), 0.0, we)
        x = lambda w: (1 - mpmath.cos(w) + (1 - mpmath.sqrt(1 - lam ** 2 * mpmath.sin(w) ** 2)) / lam) / 2  # noqa: E731
        v_max = mpmath.diff(x, we)  # the speed dx/dw is greatest where the acceleration changes sign
        # a is d2(x R)/dw2 over R = 2 d2x/dw2 (x in strokes): the integral of a dx is (2 v)^2 / 4 = v^2
        assert abs(acc - float(v_max) ** 2) <= 1e-12, lam


def test_the_sweeps_model_areas_equal_the_areas_of_each_set():
    """model_areas_sweep (one numpy pass over many rods) gives, set by set, the model areas of area_balance."""
    import numpy as np

    from construct.constructions import piston_force as pf

    g = dict(PF.figure(parts=6).replay.givens)
    lengths = g["crank_radius"] * np.array([1.05, 1.3, 2.0, 5.0, 12.0, 50.0])
    swept = pf.model_areas_sweep({**g, "rod_length": lengths})
    for i, length in enumerate(lengths):
        one = pf._model_areas({**g, "rod_length": float(length)})
        for key, value in one.items():
            assert abs(swept[key][i] - value) <= 1e-13 * abs(value), (length, key)
