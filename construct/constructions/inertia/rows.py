"""Tables measured on the inertia construction (for ``construct table``): Tabelle 1 and the characteristic points."""

from __future__ import annotations

import math
from typing import Any

from ...kernel.errors import InvalidParameter
from ...kernel.division import MAX_PARTS
from .. import Figure, get, positive
from ..crank import crank_angle, point_name
from .measure import offset, abscissa, ordinate

__all__ = ["acceleration_rows", "characteristic_point_rows", "q_at_crank_angle_rows"]


# --------------------------------------------------------------------------
# Tables measured on the construction (for 'construct table').
# --------------------------------------------------------------------------


def _table_figure(rod_ratio: float, parts: int) -> Figure:
    """The construction for F/f = 1 with 1 kg/cm^2 drawn as long as the crank radius."""
    return get("inertia-curve").figure(rod_ratio=rod_ratio, parts=parts, pressure_ratio=1.0, pressure_unit=1.0, r=1.0)


def _first(fig: Figure, *names: str) -> str:
    return next(n for n in names if n in fig.replay)


def acceleration_rows(rod_ratio: float, step_deg: float = 10.0) -> list[dict[str, Any]]:
    """Tabelle 1 for one rod ratio, every value read off the construction (F/f = 1).

    cos w and cos 2w are the feet of the crank point and of the doubled-angle
    point (where the angle puts that point on the stroke line or on the
    perpendicular through O, the point itself is read); r/L cos 2w is read on
    the proportional angle's scale line r; q is the ordinate of the curve point.

    >>> rows = acceleration_rows(4.0, 30.0)
    >>> [(row["omega_deg"], round(row["q"], 4)) for row in rows][:3]
    [(0.0, 1.25), (30.0, 0.991), (60.0, 0.375)]
    """
    step = positive("angle step", step_deg)
    n = round(180.0 / step)
    if n > MAX_PARTS:  # said before the construction would complain of "parts" the caller did not give
        raise InvalidParameter(f"the angle step must be at least {180 / MAX_PARTS:g} degrees (180/step parts of "
                               f"the semicircle, at most {MAX_PARTS}), got {step_deg!r}")
    if n < 1 or abs(n * step - 180.0) > 1e-9:
        raise InvalidParameter(f"the angle step must divide 180 degrees, got {step_deg!r}")
    fig = _table_figure(rod_ratio, n)
    r = fig.replay.givens["r"]
    ratio = fig.replay["S"].distance(fig.replay["gr.U"]) / fig.replay["S"].distance(fig.replay["O"])
    rows = []
    for k in range(n + 1):
        P = point_name(fig, k)
        foot = _first(fig, f"Y{k}", {0: "D0", n: "D1"}.get(k, P))
        double = _first(fig, f"G{k}", f"N{k}", "D0")
        if f"W{k}" in fig.replay:
            lam_cos = offset(fig, f"W{k}", "gr.U") / r
        else:  # the doubled point lies on the leg of the proportional angle: its ray is the leg itself
            lam_cos = offset(fig, double, "O") / r * ratio
        rows.append({"rod_ratio": float(rod_ratio), "omega_deg": 180.0 * k / n,
                     "cos_omega": offset(fig, foot, "O") / r, "cos_2omega": offset(fig, double, "O") / r,
                     "lambda_cos_2omega": lam_cos, "q": ordinate(fig, f"K{k}") / fig.replay.givens["pressure_unit"]})
    return rows


def _characteristic_names(n: int) -> tuple[tuple[str, str, str], ...]:
    """(label, crank point, point of the curve) for q1..q7."""
    return (("q1", "D0", "K0"), ("q2", "D1", f"K{n}"), ("q3", "c45", "q3"), ("q4", "c135", "q4"),
            ("q5", "top", "q5"), ("q6", "c6.P", "X.c6"), ("q7", "c7.P", "q7"))


def characteristic_point_rows(rod_ratio: float) -> list[dict[str, Any]]:
    """The seven characteristic points (seed 000 c) measured on the construction, F/f = 1.

    >>> rows = characteristic_point_rows(5.0)   # the book prints .4558 and .3689 (last digit off)
    >>> [(row["point"], round(row["x"], 4), round(row["q"], 4)) for row in rows][5:]
    [('q6', 0.4557, 0.0), ('q7', 0.3688, 0.2)]
    """
    fig = _table_figure(rod_ratio, 6)
    u = fig.replay.givens["pressure_unit"]
    return [{"point": label, "omega_deg": math.degrees(crank_angle(fig, crank_point)), "x": abscissa(fig, point),
             "q": ordinate(fig, point) / u} for label, crank_point, point in _characteristic_names(6)]


def q_at_crank_angle_rows(rod_ratio: float, divisions: int = 10) -> list[dict[str, Any]]:
    """Tabelle 2: q (F/f = 1) at each division of the stroke, read off the proportional angle's F/f line.

    >>> [round(row["q"], 4) for row in q_at_crank_angle_rows(5.0, 10)][:3]
    [1.2, 0.9073, 0.6299]
    """
    fig = get("inertia-stroke-fractions").figure(rod_ratio=rod_ratio, divisions=divisions, pressure_ratio=1.0, pressure_unit=1.0, r=1.0)
    u = fig.replay.givens["pressure_unit"]
    marks = ["D0"] + [f"x{j}" for j in range(1, divisions)] + ["D1"]
    return [{"x": abscissa(fig, mark), "q": offset(fig, f"Vt{j}", "gf.U") / u} for j, mark in enumerate(marks)]
