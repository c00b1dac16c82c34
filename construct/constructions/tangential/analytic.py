"""The tangential-pressure model the checks compare with: T = P'·sin(ω + β)/cos β over the exact crank
mechanism, with P' from Baumann's model, a card or the unit force, its mean, crossings and excess area."""

from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from .. import analytic
from ..indicator_parts import back_pressure, steam_pressure
from ..indicator_card import card_force, card_pair

__all__ = ["low_force", "model_force", "baumann_force", "model_t", "kinks", "model_summary"]


def low_force(g: Mapping[str, float], force: str, lam: float) -> Any:
    """The low-pressure cylinder's force along the motion over the whole turn, in at of the first piston's area
    (its own pressures times F_lp/F_hp); None if the engine has no low-pressure diagram of its own."""
    if "area_ratio" not in g:
        return None
    ratio = g["area_ratio"]
    if force == "indicator":
        fn = card_force(g, lam, "lp.")
    else:
        fn = baumann_force({key: g[f"lp.{key}"] for key in ("filling", "clearance", "admission", "back_pressure",
                                                             "compression", "pressure_ratio")}, lam)
    return lambda w: ratio * fn(w)


def model_force(w: Any, g: Mapping[str, Any], force: str) -> Any:
    """P' at crank angle w (numbers or arrays): 1 (unit), the card's over-pressure, or Baumann's over-pressure
    less the acceleration force (at)."""
    if force == "unit":
        return 1.0 if np.ndim(w) == 0 else np.ones(np.shape(w))
    lam = 1.0 / g["rod_ratio"]
    if force == "indicator":
        p = card_force(g, lam)(w)
        return float(p) if np.ndim(w) == 0 else p
    x = analytic.piston_fraction(w, lam)
    return steam_pressure(x, g) - back_pressure(x, g) - analytic.inertia_two_term(w, lam, g["pressure_ratio"])


def baumann_force(g: Mapping[str, float], lam: float) -> Any:
    """P' (at) along the motion over the whole turn, Baumann's model on both strokes (arrays of crank angles).

    Forward: steam(x) − back(x) − c(cos ω + λ cos 2ω).  Return (his assumption: the crank side's diagram is
    the cover side's): the over-pressure at the distance 1 − x from the crank-end dead centre, and the mass
    force along the reversed motion, + c(cos ω + λ cos 2ω) -- eq. (298) with the minus sign, counted from
    the crank-end dead centre.  Written here from the formulas, not from the figure.

    >>> g = {"filling": 0.1, "clearance": 0.05, "admission": 7.85, "back_pressure": 0.15, "compression": 0.3,
    ...      "pressure_ratio": 0.0}
    >>> g["pressure_ratio"] = 0.9
    >>> long_rod = baumann_force(g, 0.0)       # infinite rod: the return stroke repeats the forward one
    >>> bool(abs(long_rod(math.pi + 1.0) - long_rod(1.0)) < 1e-12)
    True
    >>> f = baumann_force(g, 0.2)              # L/r = 5: the rod's term changes sign with the stroke
    >>> round(float(f(math.pi + 1.0) - f(1.0)), 3) != 0.0
    True
    """

    def force(w: Any) -> Any:
        w = np.asarray(w, dtype=float)
        x = analytic.piston_fraction(w, lam)
        over = lambda x: steam_pressure(x, g) - back_pressure(x, g)  # noqa: E731
        mass = analytic.inertia_two_term(w, lam, g["pressure_ratio"])
        return np.where(np.mod(w, 2.0 * math.pi) <= math.pi, over(x) - mass, over(1.0 - x) + mass)

    return force


def model_t(w: Any, g: Mapping[str, Any], force: str) -> Any:
    """T at crank angle w (numbers or arrays): P' times sin(ω + β)/cos β."""
    return model_force(w, g, force) * analytic.tangential_factor(w, 1.0 / g["rod_ratio"])


def kinks(g: Mapping[str, Any], force: str) -> list[Any]:
    """Crank angles where P' has a corner (cut-off, start of compression; a card's every point on the forward
    stroke): the integrals break there.  Gl. (h) at each corner's piston position; arrays for a sweep's rods."""
    if force == "unit":
        return []
    if force == "indicator":  # the cards' corners: every digitised point of the forward stroke's lines
        cover, crank = card_pair(g)
        corners = sorted({x for x in cover.forward[0] + crank.forward[0] if 0.0 < x < 1.0})
    else:
        corners = [g["filling"], 1.0 - g["compression"]]
    return [analytic.crank_angle_from_path(2.0 * x, 1.0, g["rod_ratio"]) for x in corners]


def model_summary(g: Mapping[str, Any], force: str) -> dict[str, Any]:
    """Mean height, crossings α1, α2 and excess ∫(T − T_m) dα of the exact model (not of the drawing).

    Gauss-Legendre on each smooth piece between the kinks, the crossings of the mean line found on a
    3,601-point grid and refined by bisection.  Givens that are arrays (a sweep's) give arrays: every
    integral and crossing is computed for all sets at once.
    """
    n = max((np.size(v) for v in g.values() if np.ndim(v)), default=0)
    # one row per set of givens (a single set: one row)
    col = {k: (np.broadcast_to(np.asarray(v, dtype=float), (n,)).reshape(n, 1) if np.ndim(v) else v)
           for k, v in g.items()}
    rows = max(n, 1)
    t = lambda w: np.broadcast_to(model_t(w, col, force), np.shape(w))  # noqa: E731  (w: a row per set)
    breaks = [np.broadcast_to(np.asarray(k, dtype=float).reshape(-1), (rows,)) for k in kinks(col, force)]
    mean = analytic.gauss_legendre(t, np.zeros(rows), np.full(rows, math.pi), breaks=breaks) / math.pi
    grid = np.linspace(0.0, math.pi, 3601)
    vals = t(np.broadcast_to(grid, (rows, grid.size))) - mean[:, None]
    crossing = (vals[:, :-1] == 0.0) | (vals[:, :-1] * vals[:, 1:] < 0.0)
    if not crossing.any(axis=1).all():
        raise ArithmeticError("the model's tangential pressure does not cross its mean line")
    a1, a2 = (analytic.bisect(lambda w: t(w[:, None])[:, 0] - mean, grid[i], grid[i + 1])
              for i in (crossing.argmax(axis=1), crossing.shape[1] - 1 - crossing[:, ::-1].argmax(axis=1)))
    excess = analytic.gauss_legendre(lambda w: t(w) - mean[:, None], a1, a2, breaks=breaks)
    out = {"mean": mean, "alpha1": a1, "alpha2": a2, "excess": excess, "kinks": tuple(breaks)}
    if n == 0:  # one set of givens as numbers: numbers
        out = {k: tuple(float(x[0]) for x in v) if k == "kinks" else float(v[0]) for k, v in out.items()}
    return out
