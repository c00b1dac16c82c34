"""Baumann's error analysis (seed 004, "Bestimmung des Fehlers"), recomputed from his own equations.

He draws the diagrams once for the admission pressure P and scales them by
k = P/p for another pressure p; the piston forces are then not exactly
proportional (the back pressure P0 = p0 is not scaled).  The error ordinate
in the steam diagram is x = (s1 − sa)/(sa + s0)·(P0 − k p0), its area over
the expansion

    f_x = (k p0 − P0)·[1 − (1 + ln ε)/ε]·(s + s0),   ε = (s + s0)/(s1 + s0).

In the tangential diagram (rod ratio 5, his series sin α + sin 2α/(10 − 0.2
sin²α) for sin(α + β)/cos β and sa = s/2·(1 − cos α + 0.1 sin²α)) the
error ordinate integrates in closed form, c = cos α:

    r(P0 − k p0)·[c + A ln|c − c2| + B ln|c − c1| + C ln(c² + 49) + D arctg(c/7)],

c1,2 = −5 ± √(36 + 20 s0/s) (his 1.08 and −11.08).  Everything here uses
his model (λ = 0.2 series forms, κ = P/B_max, B = P/(1.2κ)(cos α + 0.2 cos 2α)),
lengths as fractions of the stroke s = 1.

>>> round(error_area(0.805, 0.15, 0.15, 0.10, 0.05), 6)
-0.017787
>>> c = integral_coefficients(0.10, 0.05)
>>> round(c["A"], 4), round(c["B"], 4), round(c["C"], 3), round(c["D"], 4)
(-0.0875, 0.2998, 4.894, 0.2436)
"""

from __future__ import annotations

import math
from typing import Mapping

from ...constructions.analytic import bisect, inertia_two_term

__all__ = ["epsilon", "error_area", "cutoff_angle", "compression_angle", "integral_coefficients", "antiderivative",
           "tangential_error", "book_t", "crossings", "LAMBDA"]

LAMBDA = 0.2  #: his rod ratio r/L = 1/5 (the 0.1 sin²α and 0.2 cos 2α)


def epsilon(s1: float, s0: float) -> float:
    """Expansion ratio ε = (s + s0)/(s1 + s0), s = 1."""
    return (1.0 + s0) / (s1 + s0)


def error_area(k: float, p0: float, P0: float, s1: float, s0: float) -> float:
    """f_x = (k p0 − P0)[1 − (1 + ln ε)/ε](s + s0), s = 1 (at times stroke)."""
    eps = epsilon(s1, s0)
    return (k * p0 - P0) * (1.0 - (1.0 + math.log(eps)) / eps) * (1.0 + s0)


def _series_path(a: float) -> float:
    return 0.5 * (1.0 - math.cos(a) + 0.5 * LAMBDA * math.sin(a) ** 2)


def cutoff_angle(s1: float) -> float:
    """Where sa = s1 in his series: cos α = −5 + √(36 − 20 s1/s) (radians)."""
    return math.acos(-5.0 + math.sqrt(36.0 - 20.0 * s1))


def compression_angle(s3: float) -> float:
    """Where sa = s − s3 in his series: cos α = −5 + √(16 + 20 s3/s) (radians)."""
    return math.acos(-5.0 + math.sqrt(16.0 + 20.0 * s3))


def integral_coefficients(s1: float, s0: float) -> dict[str, float]:
    """A, B, C, D and the roots c1 > c2 of his closed-form integral (partial fractions, exact)."""
    S = s1 + s0
    root = math.sqrt(36.0 + 20.0 * s0)
    c1, c2 = -5.0 + root, -5.0 - root
    # ∫ (1 + 20S/Q)(1 + 10c/(c² + 49)) dc, Q = (c − c1)(c − c2)
    a1 = 200.0 * S * c1 / ((2 * c1 + 10.0) * (c1 * c1 + 49.0))
    a2 = 200.0 * S * c2 / ((2 * c2 + 10.0) * (c2 * c2 + 49.0))

    def rest(c: float) -> float:  # (β c + γ) left over after the two simple poles
        return (200.0 * S * c / ((c - c1) * (c - c2) * (c * c + 49.0)) - a1 / (c - c1) - a2 / (c - c2)) * (c * c + 49.0)

    gamma = rest(0.0)
    beta = rest(1.0) - gamma
    simple = 20.0 * S / (c1 - c2)
    return {"c1": c1, "c2": c2, "A": a2 - simple, "B": a1 + simple, "C": 5.0 + beta / 2.0, "D": gamma / 7.0}


def antiderivative(c: float, coef: Mapping[str, float]) -> float:
    return (c + coef["A"] * math.log(abs(c - coef["c2"])) + coef["B"] * math.log(abs(c - coef["c1"]))
            + coef["C"] * math.log(c * c + 49.0) + coef["D"] * math.atan(c / 7.0))


def tangential_error(a: float, b: float, *, r: float, k: float, p0: float, P0: float, s1: float, s0: float) -> float:
    """r ∫_a^b t'_a dα: the error area in the tangential diagram between the crank angles a and b."""
    coef = integral_coefficients(s1, s0)
    return r * (P0 - k * p0) * (antiderivative(math.cos(b), coef) - antiderivative(math.cos(a), coef))


def book_t(a: float, kappa: float, g: Mapping[str, float]) -> float:
    """T_a by his equations 1)–3): P_a less P/(1.2κ)(cos α + 0.2 cos 2α), times his series factor."""
    P, P0, s1, s0, s3 = g["admission"], g["back_pressure"], g["filling"], g["clearance"], g["compression"]
    x = _series_path(a)
    steam = P + P0 if x <= s1 else (P + P0) * (s1 + s0) / (x + s0)
    back = P0 if x <= 1.0 - s3 else P0 * (s3 + s0) / (1.0 - x + s0)
    acc = P / ((1.0 + LAMBDA) * kappa) * inertia_two_term(a, LAMBDA)
    return (steam - back - acc) * (math.sin(a) + math.sin(2 * a) / (10.0 - 0.2 * math.sin(a) ** 2))


def crossings(kappa: float, g: Mapping[str, float], steps: int = 20000) -> dict[str, float]:
    """Mean height (1/π)∫T dα and the first and last crossing α1, α2 of his T_a with it (Simpson, bisection)."""
    h = math.pi / steps
    ys = [book_t(i * h, kappa, g) for i in range(steps + 1)]
    area = h / 3.0 * (ys[0] + ys[-1] + 4.0 * sum(ys[1:-1:2]) + 2.0 * sum(ys[2:-1:2]))
    mean = area / math.pi
    found = []
    for i in range(steps):
        if (ys[i] - mean) * (ys[i + 1] - mean) < 0.0:
            found.append(bisect(lambda a: book_t(a, kappa, g) - mean, i * h, (i + 1) * h))
    return {"mean": mean, "alpha1": found[0], "alpha2": found[-1]}
