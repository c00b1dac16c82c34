"""The checks of the four-stroke diagrams: the constructed pressures and volumes against the model (:mod:`.model`).

>>> from construct.constructions.four_stroke import FOUR_STROKE
>>> fig = FOUR_STROKE.figure(parts=4, steps=4, over_pressure=False)
>>> round(volume(fig, "Ov"), 12), round(pressure(fig, "Ov"), 12)
(0.0, 0.0)
>>> all(c.ok for c in four_stroke_checks(fig))
True
"""

from __future__ import annotations

import math

from ..checking import EUCLIDEAN_TOLERANCE, Check
from .. import Figure
from ..analytic import inertia_two_term, piston_fraction
from .model import STROKES, model_pressure

__all__ = ["four_stroke_checks", "volume", "pressure"]


# --------------------------------------------------------------------------
# Measurements and checks.
# --------------------------------------------------------------------------


def volume(fig: Figure, point: str) -> float:
    """V of a point of the p-V diagram in strokes, measured from its origin O along the zero line."""
    rp = fig.replay
    return (rp[point][0] - rp["Ov"][0]) / (2.0 * rp.givens["r"])


def pressure(fig: Figure, point: str) -> float:
    """Absolute pressure (at) of a point of the p-V diagram: its height over the zero line."""
    rp = fig.replay
    return (rp[point][1] - rp["Ov"][1]) / rp.givens["pressure_unit"]


def _height(fig: Figure, point: str) -> float:
    rp = fig.replay
    return (rp[point][1] - rp["T0"][1]) / rp.givens["pressure_unit"]


def _curve_tolerance(fig: Figure, points: list[tuple[float, float]], xs: list[float], fn) -> list[float]:
    """The method on exact data: how far the French curve through the exact points strays at each x (at)."""
    from ...kernel.geometry import SCALAR, Line, Point
    from ...kernel.ops import OPS

    pts = [Point(v, p) for v, p in points]
    base = Line(Point(0.0, 0.0), Point(1.0, 0.0))
    curve, = OPS["french_curve"].fn((base, *pts), {"points": len(pts), "tangent_at": ()}, {}, (), SCALAR)
    return [abs(curve.y_at(x) - fn(x)) for x in xs]


def four_stroke_checks(fig: Figure) -> list[Check]:
    rp = fig.replay
    g = rp.givens
    engine, n, m = fig.params["engine"], fig.params["parts"], fig.params["steps"]
    vc, nexp, eps = g["clearance"], g["exponent"], g["compression_ratio"]
    scale = max(1.0, g.get("max_pressure", g["suction"] * eps ** nexp) * g["pressure_unit"] / g["r"])
    tol_p = 50 * EUCLIDEAN_TOLERANCE * scale * g["r"] / g["pressure_unit"]
    tol_v = 50 * EUCLIDEAN_TOLERANCE * scale
    checks: list[Check] = []
    c0 = g["suction"] * (1.0 + vc) ** nexp
    for j in range(m + 1):
        checks.append(Check(f"compression point {j}: p V^n", pressure(fig, f"cP{j}") * volume(fig, f"cP{j}") ** nexp, c0,
                            tol_p * (1.0 + vc) ** nexp * 2.0, "Brauer's construction: Euclidean after the two rays",
                            "at·stroke^n"))
    checks.append(Check("compression ends on the clearance V_c", volume(fig, f"cP{m}"), vc, tol_v,
                        "m steps of 1 + tg α = ε^(1/m)", "stroke"))
    checks.append(Check("compression end p_a ε^n", pressure(fig, f"cP{m}"), g["suction"] * eps ** nexp, tol_p * eps ** nexp,
                        "Euclidean", "at"))
    if engine == "explosion":
        v_d, p_d = vc, g["max_pressure"]
        checks.append(Check("maximum pressure (the handbook: about 25 at)", pressure(fig, "eP0"), g["max_pressure"], tol_p,
                            "laid off on the pressure axis", "at"))
    else:
        v_d, p_d = g["cutoff"] * vc, g["suction"] * eps ** nexp
        checks.append(Check("combustion at constant pressure: d at p_c", pressure(fig, "eP0"), p_d, tol_p * eps ** nexp,
                            "the horizontal through c", "at"))
        checks.append(Check("cut-off volume ρ V_c", volume(fig, "eP0"), v_d, tol_v, "laid off on the volume axis", "stroke"))
    e0 = p_d * v_d ** nexp
    for j in range(m + 1):
        checks.append(Check(f"expansion point {j}: p V^n", pressure(fig, f"eP{j}") * volume(fig, f"eP{j}") ** nexp, e0,
                            tol_p * max(1.0, v_d ** nexp) * 4.0 + abs(e0) * 1e-12,
                            "Brauer's construction: Euclidean after the two rays", "at·stroke^n"))
    xe = g["release"]
    checks.append(Check("expansion ends at the release e (x_e)" if xe < 1.0 else
                        "expansion ends on the crank-end dead centre", volume(fig, f"eP{m}"), vc + xe, tol_v,
                        "m steps of 1 + tg α = (V_e/V_d)^(1/m)", "stroke"))
    checks.append(Check("release e: p_d (V_d/V_e)^n", pressure(fig, f"eP{m}"), p_d * (v_d / (vc + xe)) ** nexp,
                        tol_p * eps ** nexp * 4.0, "the last Brauer point", "at"))
    if not fig.params.get("over_pressure", True):   # Abb. 1056/1057 alone: no readings, no 720° diagram
        return checks
    # readings on the ordinates and the 720 degree diagram
    xk = {k: volume(fig, f"F{k}") - vc for k in range(n + 1)}
    comp_pts = [(volume(fig, f"cP{j}"), pressure(fig, f"cP{j}")) for j in range(m + 1)]
    comp_exact = [(v, c0 / v ** nexp) for v, _ in comp_pts]
    exp_pts = [(volume(fig, f"eP{j}"), pressure(fig, f"eP{j}")) for j in range(m + 1)]
    exp_exact = [(v, e0 / v ** nexp) for v, _ in exp_pts]
    inner = [k for k in range(1, n)]
    dev_c = dict(zip(inner, _curve_tolerance(fig, sorted(comp_exact), [vc + xk[k] for k in inner],
                                             lambda v: c0 / v ** nexp)))
    on_exp = [k for k in inner if (engine == "explosion" or vc + xk[k] > g["cutoff"] * vc) and xk[k] <= xe]
    dev_e = dict(zip(on_exp, _curve_tolerance(fig, exp_exact, [vc + xk[k] for k in on_exp], lambda v: e0 / v ** nexp)))
    lam = 1.0 / g["rod_ratio"]
    for s in range(4):
        for i in range(n + 1):
            t = s * n + i
            k = i if s % 2 == 0 else n - i
            theta = math.pi * t / n
            x = piston_fraction(theta, lam)
            want = model_pressure(s, x, g, engine)
            if s == 1 and i == n:
                want = model_pressure(1, 0.0, g, engine)
            dev = {1: dev_c, 2: dev_e}.get(s, {}).get(k, 0.0)
            tol = 2.0 * dev + tol_p * eps ** nexp * 4.0 + 1e-9 * want
            a = _height(fig, f"A{s}.{i}")
            checks.append(Check(f"a-a at {180 * t / n:g} deg ({STROKES[s]})", a, want, tol,
                                "read on the French curve at the piston position (the same curve through the exact "
                                "points strays by " f"{dev:.2e} at), carried with the compass" if dev else
                                "a straight line or a constructed point, carried with the compass", "at"))
            mass = inertia_two_term(theta, lam, g["pressure_ratio"])
            checks.append(Check(f"b-b at {180 * t / n:g} deg: a-a less q(cos θ + r/L cos 2θ)",
                                a - _height(fig, f"B{s}.{i}"), mass, tol_p * 10.0 + 1e-9 * abs(mass),
                                "the inertia ordinate of Anhang II (Euclidean), taken off with the compass", "at"))
    checks.append(Check("piston position X_k against the exact law (stroke)", max(
        abs(xk[k] - piston_fraction(math.pi * k / n, lam)) for k in range(n + 1)), 0.0,
        1e-9, "rod arcs; the division of the circle", "stroke"))
    return checks


#: Command-line help for the givens (book terms).
