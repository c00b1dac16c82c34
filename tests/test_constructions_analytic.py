"""The formulas and numerics the checks compare with (construct/constructions/analytic.py).

References: mpmath at 30 digits (its own quadrature, root finder and derivative, inside mpmath.workdps),
the closed forms the books print, and the quadrature rule summed node by node with the math module --
never this module's own output.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from construct.constructions import analytic as an

RATIOS = (1.05, 1.3, 2.0, 5.0, 12.0, 1000.0)


def _path_mp(w, lam):
    """The exact piston path over the stroke: ((1 - cos w) + (1 - sqrt(1 - lam^2 sin^2 w)) / lam) / 2."""
    w, lam = mpmath.mpf(w), mpmath.mpf(lam)
    return (1 - mpmath.cos(w) + (1 - mpmath.sqrt(1 - (lam * mpmath.sin(w)) ** 2)) / lam) / 2


@pytest.mark.parametrize("ratio", RATIOS)
def test_the_exact_slider_crank_against_mpmath(ratio):
    lam = 1.0 / ratio
    ws = np.linspace(0.0, 2.0 * math.pi, 37)
    with mpmath.workdps(30):
        path = [float(_path_mp(w, lam)) for w in ws]
        rate = [float(mpmath.diff(lambda t: _path_mp(t, lam), w)) for w in ws]
        accel = [float(2 * mpmath.diff(lambda t: _path_mp(t, lam), w, 2)) for w in ws]
        beta = [mpmath.asin(lam * mpmath.sin(w)) for w in ws]
        factor = [float(mpmath.sin(w + b) / mpmath.cos(b)) for w, b in zip(ws, beta)]
    # arrays and numbers alike, to a few units in the last place (long rods included: no cancellation)
    assert np.max(np.abs(an.piston_fraction(ws, lam) - path)) <= 4e-16
    assert max(abs(an.piston_fraction(float(w), lam) - p) for w, p in zip(ws, path)) <= 4e-16
    assert np.max(np.abs(an.piston_rate(ws, lam) - rate)) <= 2e-15
    assert np.max(np.abs(an.inertia_exact(ws, lam) - accel)) <= 1e-14
    assert np.max(np.abs(an.tangential_factor(ws, lam) - factor)) <= 1e-14
    # Gl. (h) inverts the path on the forward stroke
    fwd = ws[ws <= math.pi]
    assert np.max(np.abs(an.crank_angle_from_path(2.0 * an.piston_fraction(fwd, lam), 1.0, ratio) - fwd)) <= 2e-7


def test_the_quadrature_is_the_rule_summed_node_by_node():
    """Order 20 on 16 pieces, one angle at a time with the math module, gives what the array rule gives."""
    xs, ws = np.polynomial.legendre.leggauss(20)
    for lam in (1 / 1.05, 0.2, 0.02):
        def one(w):
            s = math.sin(w)
            return (math.cos(w) + lam * math.cos(2.0 * w)) * (s + lam * s * math.cos(w) / math.sqrt(1 - (lam * s) ** 2)) / 2
        h = math.pi / 16
        by_node = sum(wt * one(i * h + (x + 1.0) * h / 2.0) for i in range(16) for x, wt in zip(xs, ws)) * h / 2.0
        on_array = an.gauss_legendre(lambda w: an.inertia_two_term(w, lam) * an.piston_rate(w, lam), 0.0, math.pi)
        assert abs(on_array - by_node) <= 1e-14, lam


def test_the_exact_acceleration_area_is_the_kinetic_energy_at_the_greatest_speed():
    """The integral of the acceleration over the path, from the dead centre to where the acceleration changes
    sign, is v_max^2 (x in strokes, a = 2 d2x/dw2): mpmath's derivative of the path at that angle."""
    for lam in (1 / 1.05, 0.2, 0.02):
        we = an.bisect(lambda w: an.inertia_exact(w, lam), 0.0, math.pi)
        acc = an.gauss_legendre(lambda w: an.inertia_exact(w, lam) * an.piston_rate(w, lam), 0.0, we)
        with mpmath.workdps(30):
            v_max = mpmath.diff(lambda t: _path_mp(t, lam), we)
        assert abs(acc - float(v_max) ** 2) <= 1e-12, lam


def test_the_quadrature_breaks_at_corners_and_integrates_many_at_once():
    exact = 0.5 + (math.pi - 1.0) ** 2 / 2.0  # the integral of |w - 1| from 0 to pi, by hand
    assert an.gauss_legendre(lambda w: np.abs(w - 1.0), 0.0, math.pi, breaks=[1.0]) == pytest.approx(exact, abs=1e-15)
    # without the break the corner costs digits: the break is what makes the rule exact
    assert abs(an.gauss_legendre(lambda w: np.abs(w - 1.0), 0.0, math.pi) - exact) > 1e-7
    # n integrals at once, each with its own bounds and break (one outside its range: a piece of width 0)
    b = np.array([1.0, 2.0, 3.0])
    got = an.gauss_legendre(lambda w: np.abs(w - 1.5), 0.0, b, breaks=[np.full(3, 1.5)])
    assert got == pytest.approx([0.5 * (1.5 ** 2 - 0.5 ** 2), 0.5 * 1.5 ** 2 + 0.5 * 0.5 ** 2,
                                 0.5 * 1.5 ** 2 + 0.5 * 1.5 ** 2], abs=1e-14)


def test_bisection_finds_the_sign_change_to_the_last_bit():
    with mpmath.workdps(30):
        root = mpmath.findroot(lambda w: mpmath.cos(w) + mpmath.mpf(0.2) * mpmath.cos(2 * w), 1.6)
    got = an.bisect(lambda w: an.inertia_two_term(w, 0.2), 0.0, math.pi)
    assert abs(got - float(root)) <= 2 * math.ulp(float(root))
    arr = an.bisect(lambda w: an.inertia_two_term(w, np.array([0.2, 0.5])), np.zeros(2), np.full(2, math.pi))
    assert arr[0] == got and abs(an.inertia_two_term(arr[1], 0.5)) <= 1e-15
