"""Reading the piston-force figure: abscissae over the stroke, forces in kg off the force diagram, the areas."""

from __future__ import annotations

import math
from typing import Mapping

from .. import Figure
from .analytic import model_areas

__all__ = ["abscissa", "mass_force", "piston_force", "return_mass_force", "return_piston_force", "area_balance"]


def _base_frame(fig: Figure, prefix: str = "") -> tuple[float, float, float, float, float, float]:
    (ax, ay), (bx, by) = fig.replay[f"{prefix}F0"], fig.replay[f"{prefix}F{fig.params['parts']}"]
    s = math.hypot(bx - ax, by - ay)
    return ax, ay, (bx - ax) / s, (by - ay) / s, s, fig.replay.givens["force_unit"]


def abscissa(fig: Figure, point: str) -> float:
    """Piston path of a point as a fraction of the stroke, measured along the force diagram's base."""
    ax, ay, ux, uy, s, _ = _base_frame(fig)
    p = fig.replay[point]
    return ((p[0] - ax) * ux + (p[1] - ay) * uy) / s


def _force(fig: Figure, point: str, prefix: str = "") -> float:
    ax, ay, ux, uy, _, unit = _base_frame(fig, prefix)
    p = fig.replay[point]
    return ((p[0] - ax) * -uy + (p[1] - ay) * ux) / unit


def mass_force(fig: Figure, k: int) -> float:
    """P_b at division point k in kg, read off the force diagram (up = the masses are accelerated)."""
    return _force(fig, f"M{k}")


def piston_force(fig: Figure, tag: int | str) -> float:
    """F p_ü in kg at division point k (or "s1", "s2"), read off the force diagram."""
    return _force(fig, f"K{tag}")


def return_mass_force(fig: Figure, k: int) -> float:
    """P_b on the return stroke at the piston position of division point k, in kg (up = accelerated going back)."""
    return _force(fig, f"rM{k}", "r")


def return_piston_force(fig: Figure, tag: int | str) -> float:
    """F'' p'' - F' p' on the return stroke at division point k (or "s1", "s2"), in kg (+ = towards the head end)."""
    return _force(fig, f"rK{tag}", "r")


def area_balance(fig: Figure, model: Mapping[str, float] | None = None, stroke: str = "forward") -> dict[str, float]:
    """Acceleration area above the base and deceleration area below it, in kg m (= mkg of work).

    ``drawn_*``: the region between the mass-force line as drawn and the base line (an Area of the
    figure), measured; ``planimeter_balance`` the planimeter's reading round it (acceleration less
    deceleration);
    ``two_term_*``: eq. (298) over the exact piston path (Gauss quadrature);
    ``exact_*``: the exact kinematics, (G/g) v_max^2 / 2 on each side.
    *model*: the ``two_term_*`` and ``exact_*`` areas already computed for these givens (a sweep's, by
    :func:`~construct.constructions.piston_force.analytic.model_areas` of arrays).
    """
    g = fig.replay.givens
    stroke_m = 2.0 * g["crank_radius"]
    p = "" if stroke == "forward" else "r"
    _, _, _, _, s, unit = _base_frame(fig, p)
    to_kgm = stroke_m / s / unit  # drawn area: length along the base -> m, height -> kg
    pieces = fig.replay[f"{p}massarea"].signed_pieces()  # the region between the drawn line and the base, split
    drawn_acc = sum(p.area for sign, p in pieces if sign > 0) * to_kgm
    drawn_dec = sum(p.area for sign, p in pieces if sign < 0) * to_kgm
    drawn_balance = float(fig.replay[f"{p}balance"]) * to_kgm  # the planimeter's reading
    models = model_areas(g) if model is None else {k: float(v) for k, v in model.items()}
    if stroke != "forward":  # going back the masses are accelerated where they were decelerated coming
        models = {"two_term_acceleration": models["two_term_deceleration"],
                  "two_term_deceleration": models["two_term_acceleration"],
                  "exact_acceleration": models["exact_deceleration"],
                  "exact_deceleration": models["exact_acceleration"]}
    return {"drawn_acceleration": drawn_acc, "drawn_deceleration": drawn_dec, "planimeter_balance": drawn_balance,
            **models}
