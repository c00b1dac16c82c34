"""Dividing the semicircle: exact, Dürer, neusis, dividers -- each to its own stated accuracy."""

import math

import mpmath
import pytest

from construct.constructions import get
from construct.constructions.crank import crank_angle, point_name
from construct.kernel.division import check_parts, choose_method, durer_error_bound, euclidean_constructible
from construct.kernel.errors import InvalidParameter


def durer_error_mp(theta_deg):
    """Dürer's trisection of a unit-circle arc 0..theta, computed independently in mpmath."""
    with mpmath.workdps(40):
        th = mpmath.radians(theta_deg)
        A = mpmath.matrix([1, 0])
        B = mpmath.matrix([mpmath.cos(th), mpmath.sin(th)])
        C = A + (B - A) / 3
        u = (B - A) / mpmath.norm(B - A)
        n = mpmath.matrix([u[1], -u[0]])  # outward normal (away from O)
        if (n.T * ((A + B) / 2))[0] < 0:
            n = -n
        cn = (C.T * n)[0]
        t = -cn + mpmath.sqrt(cn ** 2 - (C.T * C)[0] + 1)
        E = C + t * n
        F = A + mpmath.norm(E - A) * u
        G = C + (F - C) * 2 / 3
        angle = 2 * mpmath.asin(mpmath.norm(G - A) / 2)
        return float(angle - th / 3)


def test_durer_errors_are_the_known_ones():
    # DESIGN.md: about -3.4e-8 rad for a 30 degree arc and -4.4e-6 rad for 60 degrees.
    assert durer_error_mp(30) == pytest.approx(-3.4e-8, rel=0.02)
    assert durer_error_mp(60) == pytest.approx(-4.4e-6, rel=0.02)
    for deg in (10, 20, 30, 45, 60):
        assert abs(durer_error_mp(deg)) <= durer_error_bound(math.radians(deg))


@pytest.mark.parametrize("parts,arc", [(18, 30), (9, 60)])
def test_constructed_durer_points_match_the_independent_computation(parts, arc):
    fig = get("crank").figure(parts=parts, method="durer")
    err = durer_error_mp(arc)
    for k in range(parts + 1):
        w = crank_angle(fig, point_name(fig, k))
        nominal = math.pi * k / parts
        expected = {0: 0.0, 1: err, 2: -err}[k % 3]  # the second point is stepped back from the arc's end
        assert w - nominal == pytest.approx(expected, abs=1e-13), k


@pytest.mark.parametrize("parts", [1, 2, 3, 4, 5, 6, 8, 10, 12, 15, 16, 20, 24, 30, 40, 60, 64, 120])
def test_exact_divisions_are_exact_to_rounding(parts):
    fig = get("crank").figure(parts=parts, method="exact")
    for k in range(parts + 1):
        assert crank_angle(fig, point_name(fig, k)) == pytest.approx(math.pi * k / parts, abs=1e-12)
    assert all(s.provenance.kind in ("given", "exact") for s in fig.protocol.steps)


@pytest.mark.parametrize("parts", [7, 11, 18])
def test_dividers_by_trial_close_to_their_tolerance(parts):
    fig = get("crank").figure(parts=parts, method="dividers")
    for k in range(parts + 1):
        assert crank_angle(fig, point_name(fig, k)) == pytest.approx(math.pi * k / parts, abs=1e-10)
    assert any(s.provenance.kind == "trial" for s in fig.protocol.steps)


def test_neusis_is_exact_but_marked_as_neusis():
    fig = get("crank").figure(parts=18, method="neusis")
    for k in range(19):
        assert crank_angle(fig, point_name(fig, k)) == pytest.approx(math.pi * k / 18, abs=1e-12)
    assert any(s.tool == "neusis" and s.provenance.kind == "neusis" for s in fig.protocol.steps)


def test_auto_picks_the_honest_method():
    assert choose_method(18) == "durer"  # 10 degrees: not constructible; exact 30 degree frame + Dürer
    assert choose_method(24) == "exact"
    assert choose_method(7) == "dividers"
    assert not euclidean_constructible(9) and euclidean_constructible(17)


@pytest.mark.parametrize("parts,method,match", [
    (18, "exact", "no compass-and-straightedge construction"),
    (17, "exact", "constructible \\(Gauss\\)"),
    (7, "durer", "n/3"),
    (0, "auto", "between 1 and 3600"),
    (3601, "auto", "between 1 and 3600"),
    (18, "guess", "unknown division method"),
    (2.5, "auto", "whole number"),
])
def test_impossible_requests_are_refused_clearly(parts, method, match):
    with pytest.raises(InvalidParameter, match=match):
        check_parts(parts, method)
