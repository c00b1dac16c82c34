"""The inertia figure's checks: every constructed quantity against Gl. (4₁), the roots of section c and the tangents."""

from __future__ import annotations

import math

from .. import analytic
from ..checking import EUCLIDEAN_TOLERANCE, Check
from .. import Figure
from ..crank import angle_tolerance, crank_angle, point_name
from .measure import slope, abscissa, curve_deviation, ordinate

__all__ = ["inertia_checks"]


def _euclid(scale: float) -> float:
    return EUCLIDEAN_TOLERANCE * max(1.0, scale)


def inertia_checks(fig: Figure) -> list[Check]:
    n = fig.params["parts"]
    g = fig.replay.givens
    r, K = g["r"], g["rod_ratio"]
    lam, L = 1.0 / K, K * r
    Ff = g["pressure_ratio"] * g["pressure_unit"]
    stroke = 2.0 * r
    # Ordinates are compared in units of the stroke (the chain's float error is a fraction of the
    # figure's size) and in units of F/f (the pressure the ordinate means).
    q_scale = max(1.0, Ff * (1.0 + lam) / stroke)
    per_ff = max(1.0, stroke / Ff)
    checks: list[Check] = []
    made_by = fig.replay.made_by()
    for k in range(n + 1):
        w = math.pi * k / n
        tol_w, why_w = angle_tolerance(fig, point_name(fig, k), made_by)
        dq = Ff * (1.0 + 4.0 * lam) / stroke  # |dq/dw| <= (F/f)(1 + 4 lam), in strokes
        checks.append(Check(f"ordinate {k} (Gl. 4_1)", ordinate(fig, f"K{k}") / stroke,
                            Ff * analytic.inertia_two_term(w, lam) / stroke,
                            _euclid(q_scale) + dq * tol_w, f"Euclidean chain; {why_w} times |dq/dw|", "stroke"))
        checks.append(Check(f"abscissa {k} (rod arcs)", abscissa(fig, f"K{k}"),
                            analytic.piston_path_exact(w, r, L) / stroke,
                            EUCLIDEAN_TOLERANCE + 0.5 * (1.0 + lam) * tol_w,
                            "rod arcs are Euclidean; division error times |dx/dw|", "stroke"))
        bound = analytic.inertia_two_term_bound(lam)
        checks.append(Check(f"ordinate {k} vs exact acceleration (information)", ordinate(fig, f"K{k}") / Ff,
                            analytic.inertia_exact(w, lam), bound + _euclid(per_ff) + (1.0 + 4.0 * lam) * tol_w,
                            "Gl. (4_1) drops the lam^3 terms: |exact - two-term| <= 2.5 lam^3 / (1 - lam^2)^2.5",
                            "F/f"))
    c6 = analytic.zero_crossing_cos(lam)
    c7 = analytic.plus_m_cos(lam)
    points = (("q1", "D0", "K0", 0.0, 1.0 + lam), ("q2", "D1", f"K{n}", math.pi, -(1.0 - lam)),
              ("q3", "c45", "q3", math.pi / 4, math.sqrt(0.5)), ("q4", "c135", "q4", 3 * math.pi / 4, -math.sqrt(0.5)),
              ("q5", "top", "q5", math.pi / 2, -lam), ("q6", "c6.P", "X.c6", math.acos(c6), 0.0),
              ("q7", "c7.P", "q7", math.acos(c7), lam))
    for label, crank_point, point, w, q in points:
        checks.append(Check(f"{label} crank angle", crank_angle(fig, crank_point), w, 10 * EUCLIDEAN_TOLERANCE,
                            "Euclidean (square roots by Pythagoras); the angle is read off a foot", "rad"))
        checks.append(Check(f"{label} position", abscissa(fig, point), analytic.piston_path_exact(w, r, L) / stroke,
                            EUCLIDEAN_TOLERANCE, "Euclidean: rod arcs from the constructed crank point", "stroke"))
        checks.append(Check(f"{label} ordinate", ordinate(fig, point) / Ff, q, _euclid(per_ff),
                            "Euclidean chain; the book's value for F/f = 1", "F/f"))
    # Tangents (Gl. i with its sign), as r dq/dx in units of F/f: the book's "r tg beta".
    slope_tol = 10 * _euclid(per_ff)  # positions to 1e-12 of the stroke over bases of at least a tenth of it
    for line, w in (("tan0", 0.0), ("tan90", math.pi / 2), ("tan180", math.pi)):
        checks.append(Check(f"tangent at {round(math.degrees(w))} deg (r tg beta)", slope(fig, line) * r / Ff,
                            analytic.inertia_slope(w, r, lam) * r, slope_tol,
                            "Euclidean; Gl. (i): r tg beta = -(F/f)(1 + 4 lam cos w)/(1 + lam cos w)", "F/f"))
    checks.append(Check("EF parallel to the infinite-rod line (r tg beta)", slope(fig, "EF") * r / Ff, -1.0, slope_tol,
                        "E and F differ by 2 F/f over the stroke", "F/f"))
    checks.append(Check("D abscissa", abscissa(fig, "D"), (1.0 + lam) / 2.0, EUCLIDEAN_TOLERANCE,
                        "EF crosses the axis at x = (1 + lam) r", "stroke"))
    checks.append(Check("D ordinate", ordinate(fig, "D") / Ff, -3.0 * lam, _euclid(per_ff),
                        "D lies on both end tangents at -3m", "F/f"))
    checks.append(Check("m (proportional angle)", fig.replay["gf.U"].distance(fig.replay["Vm"]) / Ff, lam,
                        _euclid(per_ff), "r/L then F/f through the proportional angle", "F/f"))
    checks.append(Check("m (dead-centre ordinates, finite less infinite rod)",
                        fig.replay["Einf"].distance(fig.replay["K0"]) / Ff, lam, _euclid(per_ff),
                        "q1 - F/f = m (Anhang II c)", "F/f"))
    # The curves as drawn: how far they stray from the analytic curve.
    para = _parabola_bound(lam)
    checks.append(Check("parabola E-D-F vs analytic curve (max, F/f)", curve_deviation(fig, "parabola"), 0.0,
                        para + 1e-9,
                        f"the parabola is exactly the curve over Gl. (1); the rod arcs differ by <= lam^3 r/(8(1 - lam^2)), "
                        f"times the largest slope: {para:.2e}", "F/f"))
    checks.append(Check("seven-point curve vs analytic curve (max, F/f)", curve_deviation(fig, "curve7"), 0.0,
                        max(DRAWING_ACCURACY, 3.0 * para), SEVEN_POINT_WHY, "F/f"))
    checks.append(Check(f"curve through the {n + 1} points vs analytic curve (max, F/f)", curve_deviation(fig, "curve"),
                        0.0, _division_curve_tolerance(n, lam), DIVISION_CURVE_WHY, "F/f"))
    return checks


def _steepest(lam: float) -> float:
    """The largest |r dq/dx| / (F/f) on the curve: (1 + 4 lam c)/(1 + lam c) is monotone in c = cos w."""
    return max((1.0 + 4.0 * lam) / (1.0 + lam), abs(1.0 - 4.0 * lam) / (1.0 - lam))


def _parabola_bound(lam: float) -> float:
    """Largest vertical gap between the E-D-F parabola and the curve over the exact piston path, in F/f.

    Over the piston path of Gl. (1) the curve (x(c), q(c)), c = cos w, is
    quadratic in c: a parabola through E and F touching ED and DF, i.e. the
    parabola itself.  The exact path differs by at most lam^3 r / (8 (1 - lam^2))
    (series remainder); by the mean value theorem the ordinates then differ by
    at most that times the largest slope, (1 + 4 lam c)/(1 + lam c) at c = +-1.
    """
    return _steepest(lam) * analytic.piston_path_book_bound(math.pi / 2, lam)


#: What a plate of this kind is read to: a quarter of a millimetre on an F/f of 25 mm.
DRAWING_ACCURACY = 0.01
SEVEN_POINT_WHY = ("no a-priori bound (interior slopes guessed from neighbours, as with a French curve); "
                   "it cannot beat its own parabola: 3 times the parabola's bound, never below the drawing "
                   "accuracy 1/100 F/f (measured ratio to that bound 1.1-3 for L/r = 4-12)")
DIVISION_CURVE_WHY = ("estimate, not a proof: a cubic through points pi/n apart errs like (pi/n)^3 times the "
                      "steepness of the curve; factor 2 margin (measured 5-400 times smaller for L/r 1.01-6)")


def _division_curve_tolerance(n: int, lam: float) -> float:
    return 2.0 * (math.pi / n) ** 3 * _steepest(lam)
