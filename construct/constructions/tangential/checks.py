"""The checks of a tangential-pressure figure: every ordinate against the model, the unrolled length, the mean
height, the crossings and the excess area against the model drawn by the same method."""

from __future__ import annotations

import math
from typing import Mapping

from ...kernel.areas import area_between
from ...kernel.curves import crossings
from ...kernel.geometry import SCALAR, Line, Point
from ...kernel.ops import OPS
from ..checking import EUCLIDEAN_TOLERANCE, Check
from .. import Figure
from ..crank import angle_tolerance, crank_angle, point_name
from ..indicator_card import card_force, card_pair
from ..revolution import engine_cylinders, revolution_checks
from .. import analytic
from .analytic import baumann_force, low_force, model_force, model_summary, model_t
from .measure import crossing_angles, excess_area, free_force, mean_height, ok_over_r, return_free_force, t_over_unit

__all__ = ["drawn_model", "tangential_checks"]


def drawn_model(g: Mapping[str, float], force: str, n: int) -> dict[str, float]:
    """The method on exact data: the French curve through the model's n + 1 exact points, read as the figure is.

    Its distance from :func:`model_summary` is the error of drawing the curve
    through n + 1 points (the corner at the cut-off among it); the checks allow
    twice that.  Abscissae are π k/n here: the chord scale of the figure only
    stretches it uniformly (angles and mean height do not change; areas scale).
    """
    pts = [Point(math.pi * k / n, model_t(math.pi * k / n, g, force)) for k in range(n + 1)]
    base = Line(Point(0.0, 0.0), Point(math.pi, 0.0))
    curve, = OPS["french_curve"].fn((base, *pts), {"points": n + 1, "tangent_at": ()}, {}, (), SCALAR)
    mean_height = area_between(curve, base, 0.0, math.pi).signed_area() / math.pi
    found = crossings(curve, Line(Point(0.0, mean_height), Point(math.pi, mean_height)))
    a1, a2 = found[0], found[-1]
    mean = Line(Point(0.0, mean_height), Point(math.pi, mean_height))
    excess = area_between(curve, mean, a1.x, a2.x).signed_area()
    return {"mean": mean_height, "alpha1": a1.x, "alpha2": a2.x, "excess": excess}


def tangential_checks(fig: Figure, model: Mapping[str, float] | None = None) -> list[Check]:
    """The checks of a tangential-pressure figure; *model*: :func:`model_summary` of its givens, if known."""
    g = fig.replay.givens
    n = fig.params["parts"]
    force = fig.params["force"]
    lam = 1.0 / g["rod_ratio"]
    made_by = fig.replay.made_by()
    checks: list[Check] = []
    if force == "unit":
        scale = 1.0
    elif force == "indicator":
        scale = max(1.0, max(p for c in card_pair(g) for p in c.forward[1] + c.back[1]))
    else:
        scale = max(1.0, g["admission"] + g["back_pressure"])
    for k in range(1, n):
        w = crank_angle(fig, point_name(fig, k))  # the angle the point really has: the division's error drops out
        checks.append(Check(f"OK/r at {k}", ok_over_r(fig, k), analytic.tangential_factor(w, lam), EUCLIDEAN_TOLERANCE,
                            "rod line and perpendicular through O: straightedge steps", "r"))
        if force in ("baumann", "indicator"):
            tol = 10 * EUCLIDEAN_TOLERANCE * scale / g["pressure_unit"]
            why = ("the cards' straightedge lines met by the ordinate, compass" if force == "indicator" else
                   "hyperbola rays, inertia ordinate and compass")
            checks.append(Check(f"P' at {k}", free_force(fig, k), model_force(w, g, force), tol,
                                f"{why}: Euclidean, read in at", "at"))
            if not fig.params.get("revolution"):  # over a revolution the ordinates are checked as the sum's
                checks.append(Check(f"T at {k}", t_over_unit(fig, k), model_t(w, g, force), 2 * tol,
                                    "P'·OK/r by the intercept theorem: Euclidean, read in at", "at"))
        elif not fig.params.get("revolution"):  # over a revolution the ordinates are checked as the sum's
            checks.append(Check(f"T/P at {k}", t_over_unit(fig, k), analytic.tangential_factor(w, lam), EUCLIDEAN_TOLERANCE,
                                "proportional angle with P' = r: Euclidean", "P"))
    if fig.params.get("revolution"):
        if force == "unit":
            return checks + revolution_checks(fig)
        whole = card_force(g, lam) if force == "indicator" else baumann_force(g, lam)
        low = low_force(g, force, lam)
        if low is not None:  # the low-pressure cylinder's pressures, drawn times F_lp/F_hp
            lp_cards = card_pair(g, "lp.") if force == "indicator" else ()
            lp_top = max([p for c in lp_cards for p in c.forward[1] + c.back[1]]
                         or [g.get("lp.admission", 0.0) + g.get("lp.back_pressure", 0.0)])
            scale = max(scale, lp_top * g["area_ratio"])
        tol = 10 * EUCLIDEAN_TOLERANCE * scale / g["pressure_unit"]
        sides = [("", whole)] + ([("lp.", low)] if low is not None else [])
        for k in range(1, n):  # the return stroke's P' at the mirrored crank point 360° − ω_k
            w = crank_angle(fig, point_name(fig, k))
            for p, fn in sides:
                what = " (low pressure, times F_lp/F_hp)" if p else ""
                if p:
                    checks.append(Check(f"P' at {k}{what}", free_force(fig, k, p), float(fn(w)), tol,
                                        "the low-pressure lines met by the ordinate, compass: Euclidean, read in at",
                                        "at"))
                checks.append(Check(f"P' on the return stroke at {2 * n - k}{what}", return_free_force(fig, k, p),
                                    float(fn(2.0 * math.pi - w)), tol, "the crank side's lines met by the ordinate, "
                                    "compass: Euclidean, read in at", "at"))
        engine = None
        if low is not None:
            layout = engine_cylinders(fig.params["shifts"], fig.params["cylinders"], fig.params["machine"], True)
            by_shift = dict(zip(fig.params["shifts"], fig.params["offsets"]))
            engine = [(by_shift[sh], low if which else whole) for sh, which in layout]
        return checks + revolution_checks(fig, whole, scale / g["pressure_unit"], engine=engine)
    r = g["r"]
    prov = made_by[f"U{n}"].provenance
    length = fig.replay["U0"].distance(fig.replay[f"U{n}"])
    chord = fig.replay["D0"].distance(fig.replay[point_name(fig, 1)])
    tol_w, why_w = angle_tolerance(fig, point_name(fig, 1), made_by)
    # The dividers' shortfall π − 2n·sin(π/2n) is at most π³/(24n²) (sin x >= x − x³/6): half as much again is
    # the tolerance, a bound the method gives before anything is measured.
    checks.append(Check("unrolled length", length / r, math.pi, 1.5 * math.pi ** 3 / (24.0 * n * n) + n * tol_w,
                        f"{prov.method}; the shortfall is at most π³/(24n²) = {math.pi ** 3 / (24.0 * n * n):.3e} r, "
                        f"tolerance 1.5 times that; division error {why_w}", "r"))
    checks.append(Check("unrolled length (dividers)", length / r, n * chord / r, 10 * EUCLIDEAN_TOLERANCE,
                        "n equal steps of the chord as drawn: Euclidean once the opening is set", "r"))
    model = model_summary(g, force) if model is None else model
    drawn = drawn_model(g, force, n)
    unit = "P" if force == "unit" else "at"
    why = "the French curve through n + 1 points (twice its error on exact data) and the planimeter (1e-6)"
    tol_h = 2.0 * abs(drawn["mean"] - model["mean"]) + 1e-6 * scale
    checks.append(Check("mean height (planimeter)", mean_height(fig), model["mean"], tol_h, why, unit))
    a1, a2 = crossing_angles(fig)
    for name, measured in (("alpha1", a1), ("alpha2", a2)):
        tol = 2.0 * abs(drawn[name] - model[name]) + 1e-5
        checks.append(Check(name, measured, model[name], tol, why + "; read off the unrolled scale", "rad"))
    # The chord-stepped abscissae scale every area by n·chord/(πr).
    chord_factor = 2 * n * math.sin(math.pi / (2 * n)) / math.pi
    tol_e = 2.0 * abs(drawn["excess"] - model["excess"]) + abs(model["excess"]) * (1.0 - chord_factor) + 1e-5 * scale
    checks.append(Check("excess area", excess_area(fig), model["excess"], tol_e,
                        why + "; unrolled by chords: area scaled by n·chord/πr", f"{unit}·r"))
    return checks
