"""Baumann's Fig. 28 (seed 004): the disc of equal stress, hub and rim, against mpmath.

References: b = b1 r1/r (his "Hyperbeln"), the hub from r1/12 to r1/6 of length 4 b2 = 24 b1, his section
b1 r1 ln 6 (printed 1,79 b1 r1) and his ρ = 7/12 r1 (the radius halving ∫ b r dr), integrated with mpmath.
"""

import mpmath
import pytest

from construct.constructions import get
from construct.constructions.flywheel_rim import disc_half_width
from construct.kernel.errors import InvalidParameter


@pytest.fixture(scope="module")
def fig():
    return get("flywheel-rim").figure(b1=0.025)


def test_faces_are_baumanns_hyperbolas(fig):
    b1 = mpmath.mpf("0.025")
    for side in "UD":
        for j in range(2, 12):
            r = mpmath.mpf(j) / 12
            assert disc_half_width(fig, f"{side}{j}") == pytest.approx(float(b1 / r / 2), rel=1e-12)


def test_hub_and_the_halving_radius(fig):
    b1 = 0.025
    assert 2 * disc_half_width(fig, "U2") == pytest.approx(6 * b1, rel=1e-12)          # b2 = 6 b1
    assert disc_half_width(fig, "U.H3") + disc_half_width(fig, "D.H3") == pytest.approx(24 * b1, rel=1e-12)
    b = lambda r: 1 / r  # noqa: E731
    rho = mpmath.findroot(lambda p: mpmath.quad(lambda r: b(r) * r, [p, 1])
                          - mpmath.quad(lambda r: b(r) * r, [mpmath.mpf(1) / 6, p]), 0.5)
    x = fig.replay["rho"][0] - fig.replay["O"][0]
    assert x == pytest.approx(float(rho), abs=1e-12)                                     # 7/12


def test_planimetered_section_against_ln_6(fig):
    exact = 0.025 * float(mpmath.quad(lambda r: 1 / r, [mpmath.mpf(1) / 6, 1]))
    area = abs(fig.replay["section"].signed_area())
    # the French curve through 11 points of the hyperbola (steep at the hub): within 0.3 %; his 1,79 is 0.1 % off
    assert area == pytest.approx(exact, rel=3e-3)
    assert all(c.ok for c in get("flywheel-rim").checks(fig))


def test_bad_thickness_is_refused():
    with pytest.raises(InvalidParameter, match="disc thickness b1"):
        get("flywheel-rim").figure(b1=0.2)
