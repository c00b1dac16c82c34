"""The checks of a piston-force figure: every constructed ordinate against eq. (297)/(298), the areas, J."""

from __future__ import annotations

import math
from typing import Any, Mapping

from ..checking import EUCLIDEAN_TOLERANCE, Check
from .. import Figure
from ..crank import angle_tolerance, crank_angle, point_name
from ..indicator_parts import back_pressure as model_back
from ..indicator_parts import steam_pressure as model_steam
from ..indicator_card import card_pair
from ..analytic import inertia_exact, inertia_two_term, inertia_two_term_bound, piston_fraction
from .analytic import card_force_zero, forward_force, j_abscissa, piston_areas, return_force
from .build import mass_force_scale
from .measure import abscissa, area_balance, mass_force, piston_force, return_mass_force, return_piston_force

__all__ = ["piston_force_checks"]


def piston_force_checks(fig: Figure, model: Mapping[str, float] | None = None) -> list[Check]:
    """The checks of a piston-force figure; *model*: the model areas of :func:`area_balance`, if known."""
    n = fig.params["parts"]
    g = fig.replay.givens
    lam = g["crank_radius"] / g["rod_length"]
    A = mass_force_scale(g)
    F = g["piston_area"]
    unit = g["force_unit"]
    stroke = 2.0 * g["crank_radius"] * g["scale"]
    # Euclidean float error ~1e-12 of the figure, read in kg: divide by the force unit.
    if "card.x0" in g:
        top = max(p for c in card_pair(g) for p in c.forward[1] + c.back[1])
        F = max(piston_areas(g))
    else:
        top = g["admission"] + g["back_pressure"]
    size = max(stroke, top * F * unit, A * unit, 1.0)
    kg_tol = EUCLIDEAN_TOLERANCE * size / unit
    made_by = fig.replay.made_by()
    checks: list[Check] = []
    for k in range(n + 1):
        w = math.pi * k / n
        tol_w, why_w = angle_tolerance(fig, point_name(fig, k), made_by)
        w_measured = crank_angle(fig, point_name(fig, k))
        x = abscissa(fig, f"M{k}")
        checks.append(Check(f"abscissa {k} (rod arcs)", x, piston_fraction(w, lam),
                            EUCLIDEAN_TOLERANCE + 0.5 * (1 + lam) * tol_w,
                            "rod arcs are Euclidean; division error times |dx/dw|", "stroke"))
        checks.append(Check(f"mass force {k} (eq. 298)", mass_force(fig, k), A * inertia_two_term(w, lam),
                            kg_tol + A * (1.0 + 4.0 * lam) * tol_w, f"Euclidean chain as the inertia curve; {why_w}", "kg"))
        checks.append(Check(f"mass force {k} at the drawn angle (eq. 298)", mass_force(fig, k),
                            A * inertia_two_term(w_measured, lam), kg_tol, "Euclidean chain: float rounding only",
                            "kg"))
        bound = inertia_two_term_bound(lam)
        checks.append(Check(f"mass force {k} vs exact kinematics (information)", mass_force(fig, k),
                            A * inertia_exact(w, lam), A * bound + kg_tol + A * (1.0 + 4.0 * lam) * tol_w,
                            "eq. (298) drops the (R/L)^3 terms: |exact - two-term| <= 2.5 lam^3/(1 - lam^2)^2.5", "kg"))
        xk = abscissa(fig, f"K{k}")
        force = forward_force(xk, g)
        checks.append(Check(f"piston force {k} (F p_ü, eq. 297)", piston_force(fig, k), force, kg_tol,
                            "Euclidean: ray-constructed hyperbolas, compass transfer", "kg"))
        checks.append(Check(f"free force {k}", piston_force(fig, k) - mass_force(fig, k),
                            force - A * inertia_two_term(w_measured, lam), 2 * kg_tol,
                            "difference of two Euclidean ordinates", "kg"))
    cards = "card.x0" in g
    for tag, x in () if cards else (("s1", g["filling"]), ("s2", 1.0 - g["compression"])):
        checks.append(Check(f"piston force at {tag}", piston_force(fig, tag), forward_force(x, g),
                            kg_tol, "Euclidean", "kg"))
    if fig.params.get("revolution"):
        return checks + _return_checks(fig, kg_tol, lam, A, made_by)
    xj = None if cards else j_abscissa(g)
    if not cards:  # J is constructed from the model's hyperbolas; a card has none
        checks.append(Check("pressure change J (abscissa)", abscissa(fig, "J"), xj, EUCLIDEAN_TOLERANCE * 10,
                            "fourth proportional and intercept theorem: Euclidean", "stroke"))
    elif "J" in fig.replay:  # the cards' straight lines: their forward force's last change of sign
        xj = card_force_zero(g)
        checks.append(Check("pressure change J (abscissa)", abscissa(fig, "J"), xj, EUCLIDEAN_TOLERANCE * 10,
                            "two chords extended and crossed, the perpendicular dropped: Euclidean", "stroke"))
        checks.append(Check("piston force at J", forward_force(abscissa(fig, "J"), g), 0.0, kg_tol,
                            "J is the zero of F p' - F p'' on the cards' lines", "kg"))
    if not cards and g["filling"] < xj < 1.0 and xj > 1.0 - g["compression"]:
        checks.append(Check("p_ü at J", model_steam(xj, g) - model_back(xj, g), 0.0, 1e-12 * (g["admission"] + 1),
                            "J is the zero of the over-pressure", "at"))
    # the area balance: reported, not assumed
    a = area_balance(fig, model)
    curve_tol = _curve_area_tolerance(n, lam) * A * 2.0 * g["crank_radius"]
    for side in ("acceleration", "deceleration"):
        checks.append(Check(f"{side} area as drawn vs eq. (298) over the exact path", a[f"drawn_{side}"],
                            a[f"two_term_{side}"], curve_tol,
                            "French curve through the points: height error <= 2 (pi/n)^3 (1 + 4 lam) (G/g) omega^2 R "
                            "(estimate), times the stroke", "kg m"))
        checks.append(Check(f"{side} area, eq. (298) vs exact kinematics (information)", a[f"two_term_{side}"],
                            a[f"exact_{side}"], A * 2.0 * g["crank_radius"] * inertia_two_term_bound(lam),
                            "eq. (298) drops the (R/L)^3 terms", "kg m"))
    checks.append(Check("area balance, exact kinematics (acceleration - deceleration)",
                        a["exact_acceleration"] - a["exact_deceleration"], 0.0, 1e-9 * A,
                        "the masses start and end the stroke at rest: the work balances exactly", "kg m"))
    checks.append(Check("area balance, eq. (298) over the exact path (information)",
                        a["two_term_acceleration"] - a["two_term_deceleration"], 0.0,
                        A * 2.0 * g["crank_radius"] * lam ** 3,
                        "eq. (298) is exact for the path of Gl. (1), not for the rod arcs: residue O(lam^3)", "kg m"))
    checks.append(Check("planimeter reading = acceleration - deceleration area", a["planimeter_balance"],
                        a["drawn_acceleration"] - a["drawn_deceleration"], 1e-9 * A * 2.0 * g["crank_radius"],
                        "the same drawn region, measured whole and piece by piece", "kg m"))
    checks.append(Check("area balance as drawn (information)", a["drawn_acceleration"] - a["drawn_deceleration"], 0.0,
                        2 * curve_tol + A * 2.0 * g["crank_radius"] * lam ** 3,
                        "drawing error of the curve plus the O(lam^3) residue", "kg m"))
    return checks


def _return_checks(fig: Figure, kg_tol: float, lam: float, A: float, made_by: Mapping[str, Any]) -> list[Check]:
    """The return stroke against (298) with the minus sign and the mirrored diagram, and its area balance."""
    n = fig.params["parts"]
    g = fig.replay.givens
    checks: list[Check] = []
    for k in range(n + 1):
        w = math.pi * k / n
        tol_w, why_w = angle_tolerance(fig, point_name(fig, k), made_by)
        w_measured = crank_angle(fig, point_name(fig, k))
        checks.append(Check(f"return mass force {k} (eq. 298, minus sign)", return_mass_force(fig, k),
                            -A * inertia_two_term(w, lam), kg_tol + A * (1.0 + 4.0 * lam) * tol_w,
                            f"the forward ordinate carried the other way; {why_w}", "kg"))
        checks.append(Check(f"return mass force {k} = -(forward)", return_mass_force(fig, k), -mass_force(fig, k),
                            2 * kg_tol, "the same compass opening laid off the other way", "kg"))
        checks.append(Check(f"return mass force {k} at the drawn angle", return_mass_force(fig, k),
                            -A * inertia_two_term(w_measured, lam), kg_tol, "Euclidean chain: float rounding only",
                            "kg"))
        x = abscissa(fig, f"rK{k}")
        checks.append(Check(f"return piston force {k} (F''p'' - F'p')", return_piston_force(fig, k),
                            return_force(x, g), 2 * kg_tol,
                            "Euclidean: mirrored diagram, proportional angle for F'/F'', compass transfer", "kg"))
    for tag, x in () if "card.x0" in g else (("s1", 1.0 - g["filling"]), ("s2", g["compression"])):
        checks.append(Check(f"return piston force at {tag}", return_piston_force(fig, tag), return_force(x, g),
                            2 * kg_tol, "Euclidean", "kg"))
    curve_tol = _curve_area_tolerance(n, lam) * A * 2.0 * g["crank_radius"]
    fwd, ret = area_balance(fig), area_balance(fig, stroke="return")
    for side in ("acceleration", "deceleration"):
        checks.append(Check(f"return stroke: {side} area as drawn vs eq. (298)", ret[f"drawn_{side}"],
                            ret[f"two_term_{side}"], curve_tol, "French curve through the points (estimate), times "
                            "the stroke", "kg m"))
    checks.append(Check("return acceleration area = forward deceleration area (as drawn)", ret["drawn_acceleration"],
                        fwd["drawn_deceleration"], 1e-9 * A * 2.0 * g["crank_radius"],
                        "the same curve, mirrored in the base line", "kg m"))
    checks.append(Check("return planimeter reading = acceleration - deceleration area", ret["planimeter_balance"],
                        ret["drawn_acceleration"] - ret["drawn_deceleration"], 1e-9 * A * 2.0 * g["crank_radius"],
                        "the same drawn region, measured whole and piece by piece", "kg m"))
    return checks


def _curve_area_tolerance(n: int, lam: float) -> float:
    return 2.0 * (math.pi / n) ** 3 * (1.0 + 4.0 * lam)
