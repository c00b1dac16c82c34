"""The piston-force model the checks compare with: eq. (297) and (298) over the exact piston path, J, the
zero of the cards' force, the model's acceleration and deceleration areas."""

from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from .. import analytic
from ..indicator_parts import back_pressure as model_back
from ..indicator_parts import steam_pressure as model_steam
from ..indicator_card import card_pair
from .build import mass_force_scale

__all__ = ["card_force_zero", "j_abscissa", "model_areas", "piston_areas", "forward_force", "return_force"]


def card_force_zero(g: Mapping[str, float]) -> float | None:
    """The last x where the cards' forward piston force F p' − F p'' passes from pushing to braking (on the
    straight lines between the digitised points), or None."""
    xs = sorted({x for c in card_pair(g) for x in c.forward[0]} | {0.0, 1.0})
    zero = None
    for lo, hi in zip(xs, xs[1:]):
        if forward_force(lo, g) > 0.0 >= forward_force(hi, g):
            zero = analytic.bisect(lambda x: forward_force(x, g), lo, hi)
    return zero


def j_abscissa(g: Mapping[str, float]) -> float:
    """Where (P + P0)(s1 + s0)/(x + s0) = P0 (s3 + s0)/(s - x + s0), x as a fraction of the stroke."""
    c1 = (g["admission"] + g["back_pressure"]) * (g["filling"] + g["clearance"])
    c2 = g["back_pressure"] * (g["compression"] + g["clearance"])
    return (1.0 + 2.0 * g["clearance"]) * c1 / (c1 + c2) - g["clearance"]


def model_areas(g: Mapping[str, Any]) -> dict[str, Any]:
    """The areas of the models (eq. 298 and the exact kinematics) over the exact piston path, in kg m: each
    acceleration from the dead centre to its zero, the deceleration from there to the other dead centre.

    Givens that are arrays (a sweep's) give arrays: every integral and zero is computed for all sets at once.
    """
    lam = np.asarray(g["crank_radius"] / g["rod_length"], dtype=float)
    scale = mass_force_scale(g) * 2.0 * np.asarray(g["crank_radius"], dtype=float)  # (G/g) omega^2 R, times the stroke
    lam_row = lam[..., None]  # one row of quadrature nodes per set of givens
    out = {}
    for name, law in (("two_term", analytic.inertia_two_term), ("exact", analytic.inertia_exact)):
        zero = analytic.bisect(lambda w: law(w, lam), np.zeros_like(lam), np.full_like(lam, math.pi))
        work = lambda w: law(w, lam_row) * analytic.piston_rate(w, lam_row)  # noqa: E731
        out[f"{name}_acceleration"] = scale * analytic.gauss_legendre(work, 0.0, zero)
        out[f"{name}_deceleration"] = -scale * analytic.gauss_legendre(work, zero, math.pi)
    return {k: float(v) if np.ndim(v) == 0 else v for k, v in out.items()}


def piston_areas(g: Mapping[str, float]) -> tuple[float, float]:
    if "piston_area_cover" in g:
        return g["piston_area_cover"], g["piston_area_crank"]
    return g["piston_area"], g["piston_area"]


def forward_force(x: float, g: Mapping[str, float]) -> float:
    """The piston force on the forward stroke (kg): F p_ü with one area, F' p' - F'' p'' with both sides'."""
    if "card.x0" in g:  # the cards' lines, straight between their points
        cover, crank = card_pair(g)
        f1, f2 = piston_areas(g)
        return f1 * cover.pressure(x, "forward") - f2 * crank.pressure(x, "forward")
    if "piston_area_cover" in g:
        return g["piston_area_cover"] * model_steam(x, g) - g["piston_area_crank"] * model_back(x, g)
    return g["piston_area"] * (model_steam(x, g) - model_back(x, g))


def return_force(x: float, g: Mapping[str, float]) -> float:
    """F'' p'' - F' p' on the return stroke at piston position x: the crank side's diagram is the cover side's
    mirrored."""
    if "card.x0" in g:
        cover, crank = card_pair(g)
        f1, f2 = piston_areas(g)
        return f2 * crank.pressure(x, "return") - f1 * cover.pressure(x, "return")
    return g["piston_area_crank"] * model_steam(1.0 - x, g) - g["piston_area_cover"] * model_back(1.0 - x, g)
