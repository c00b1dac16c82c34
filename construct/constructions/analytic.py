"""The analytic formulas the constructions are checked against.

Nothing in here is used to *make* a construction: these functions are the
independent side of every check.  Angles are in radians, lengths in the
units of the crank radius ``r`` unless a function says otherwise.

Notation (DESIGN.md section 1): crank radius ``r``, rod length ``L``,
``lam = r/L``, crank angle ``omega`` measured from the head-end dead centre.

>>> round(piston_path_exact(math.pi / 2, 1.0, 4.0), 12)
1.127016653793
>>> piston_path_book(math.pi / 2, 1.0, 4.0)
1.125
>>> round(math.degrees(crank_angle_from_path(1.0, 1.0, 4.0)), 6)
82.819244
"""

from __future__ import annotations

import math

__all__ = [
    "piston_path_exact",
    "piston_path_book",
    "crank_angle_from_path",
    "inertia_two_term",
    "inertia_exact",
    "inertia_slope",
    "zero_crossing_cos",
    "plus_m_cos",
]


def piston_path_exact(omega: float, r: float, L: float) -> float:
    """Piston path from the head-end dead centre, exact: r(1 - cos w) + L - sqrt(L^2 - r^2 sin^2 w)."""
    s = r * math.sin(omega)
    # L - sqrt(L^2 - s^2) written as s^2 / (L + sqrt(...)) to avoid cancellation for long rods.
    return r * (1.0 - math.cos(omega)) + s * s / (L + math.sqrt(L * L - s * s))


def piston_path_book(omega: float, r: float, L: float) -> float:
    """The books' approximation, Gl. (1): r [1 - cos w + (r / 2L) sin^2 w]."""
    return r * (1.0 - math.cos(omega) + 0.5 * (r / L) * math.sin(omega) ** 2)


def crank_angle_from_path(x: float, r: float, L: float) -> float:
    """Crank angle for a piston path x on the forward stroke, Gl. (h) of seed 000 (exact).

    cos w = (x / 2r) (2L - x) / (x - r - L) + 1
    """
    c = (x / (2.0 * r)) * (2.0 * L - x) / (x - r - L) + 1.0
    return math.acos(max(-1.0, min(1.0, c)))


def inertia_two_term(omega: float, lam: float, pressure_ratio: float = 1.0) -> float:
    """Inertia pressure per unit area, Gl. (4_1): q = (F/f)(cos w + lam cos 2w)."""
    return pressure_ratio * (math.cos(omega) + lam * math.cos(2.0 * omega))


def inertia_exact(omega: float, lam: float, pressure_ratio: float = 1.0) -> float:
    """The exact piston acceleration in the same units as Gl. (4_1).

    cos w + lam (cos 2w + lam^2 sin^4 w) / (1 - lam^2 sin^2 w)^(3/2): the second
    derivative of the exact piston path; Gl. (4_1) is its first two terms.
    """
    s2 = math.sin(omega) ** 2
    return pressure_ratio * (
        math.cos(omega) + lam * (math.cos(2.0 * omega) + lam * lam * s2 * s2) / (1.0 - lam * lam * s2) ** 1.5
    )


def inertia_slope(omega: float, r: float, lam: float, pressure_ratio: float = 1.0) -> float:
    """Slope dq/dx of the curve q over the piston path of Gl. (1), Gl. (i) with its sign.

    dq/dx = -(F/f)/r * (1 + 4 lam cos w) / (1 + lam cos w)
    """
    c = math.cos(omega)
    return -pressure_ratio / r * (1.0 + 4.0 * lam * c) / (1.0 + lam * c)


def zero_crossing_cos(lam: float) -> float:
    """cos w where q = 0 (point q6): (-1 + sqrt(1 + 8 lam^2)) / (4 lam)."""
    return (-1.0 + math.sqrt(1.0 + 8.0 * lam * lam)) / (4.0 * lam)


def plus_m_cos(lam: float) -> float:
    """cos w where q = +m = +lam F/f (point q7): (-1 + sqrt(1 + 16 lam^2)) / (4 lam).

    Seed 000 prints (-L + sqrt(L^2 - 16 r^2)) / 4r; the sign under the root is a
    misprint (its own numbers, .4140 for L/r = 4, follow from the plus sign).
    """
    return (-1.0 + math.sqrt(1.0 + 16.0 * lam * lam)) / (4.0 * lam)
