"""The tangential-pressure model the checks compare with: T = P'·sin(ω + β)/cos β over the exact crank
mechanism, with P' from Baumann's model, a card or the unit force, its mean, crossings and excess area."""

from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from ..indicator import back_pressure as model_back_pressure
from ..indicator import steam_pressure as model_steam_pressure
from ..indicator_card import card_force, card_pair

__all__ = ["low_force", "factor", "piston_fraction", "model_force", "baumann_force", "model_t", "model_t_array",
           "model_summary", "model_summary_sweep"]


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


def _sin_beta(w: float, lam: float) -> float:
    return lam * math.sin(w)


def factor(w: float, lam: float) -> float:
    """sin(ω + β)/cos β: T/P' for the exact crank mechanism."""
    b = math.asin(_sin_beta(w, lam))
    return math.sin(w + b) / math.cos(b)


def piston_fraction(w: float, lam: float) -> float:
    """Exact piston path as a fraction of the stroke."""
    return 0.5 * (1.0 - math.cos(w) + (1.0 - math.sqrt(1.0 - (lam * math.sin(w)) ** 2)) / lam)


def model_force(w: float, g: Mapping[str, float], force: str) -> float:
    """P' at crank angle w: 1 (unit) or over-pressure less the acceleration force (at)."""
    if force == "unit":
        return 1.0
    lam = 1.0 / g["rod_ratio"]
    if force == "indicator":
        return float(card_force(g, lam)(w))
    x = piston_fraction(w, lam)
    return (model_steam_pressure(x, g) - model_back_pressure(x, g)
            - g["pressure_ratio"] * (math.cos(w) + lam * math.cos(2.0 * w)))


def baumann_force(g: Mapping[str, float], lam: float) -> Any:
    """P' (at) along the motion over the whole turn, Baumann's model on both strokes (arrays of crank angles).

    Forward: steam(x) − back(x) − c(cos ω + λ cos 2ω).  Return (his assumption: the crank side's diagram is
    the cover side's): the over-pressure at the distance 1 − x from the crank-end dead centre, and the mass
    force along the reversed motion, + c(cos ω + λ cos 2ω) -- eq. (298) with the minus sign, counted from
    the crank-end dead centre.  Written here from the formulas, not from the figure.

    >>> g = {"filling": 0.1, "clearance": 0.05, "admission": 7.85, "back_pressure": 0.15, "compression": 0.3,
    ...      "pressure_ratio": 0.0}
    >>> g["pressure_ratio"] = 0.9
    >>> long_rod = baumann_force(g, 1e-9)      # infinite rod: the return stroke repeats the forward one
    >>> bool(abs(long_rod(math.pi + 1.0) - long_rod(1.0)) < 1e-9)
    True
    >>> f = baumann_force(g, 0.2)              # L/r = 5: the rod's term changes sign with the stroke
    >>> round(float(f(math.pi + 1.0) - f(1.0)), 3) != 0.0
    True
    """
    s1, s0, P, P0, s3, c = (g["filling"], g["clearance"], g["admission"], g["back_pressure"], g["compression"],
                            g["pressure_ratio"])

    def over(x: Any) -> Any:
        steam = np.where(x <= s1, P + P0, (P + P0) * (s1 + s0) / (x + s0))
        back = np.where(x <= 1.0 - s3, P0, P0 * (s3 + s0) / (1.0 - x + s0))
        return steam - back

    def force(w: Any) -> Any:
        w = np.asarray(w, dtype=float)
        x = 0.5 * (1.0 - np.cos(w) + (1.0 - np.sqrt(1.0 - (lam * np.sin(w)) ** 2)) / lam)
        mass = c * (np.cos(w) + lam * np.cos(2.0 * w))
        return np.where(np.mod(w, 2.0 * math.pi) <= math.pi, over(x) - mass, over(1.0 - x) + mass)

    return force


def model_t(w: float, g: Mapping[str, float], force: str) -> float:
    return model_force(w, g, force) * factor(w, 1.0 / g["rod_ratio"])


def _kinks(g: Mapping[str, float], force: str) -> list[float]:
    """Crank angles where P' has a corner (cut-off, start of compression): integration breaks there."""
    if force == "unit":
        return []
    lam = 1.0 / g["rod_ratio"]
    out = []
    if force == "indicator":  # the cards' corners: every digitised point of the forward stroke's lines
        cover, crank = card_pair(g)
        corners = sorted({x for x in cover.forward[0] + crank.forward[0] if 0.0 < x < 1.0})
    else:
        corners = [g["filling"], 1.0 - g["compression"]]
    for x in corners:
        lo, hi = 0.0, math.pi
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if piston_fraction(mid, lam) < x else (lo, mid)
        out.append(0.5 * (lo + hi))
    return sorted(out)


#: Gauss-Legendre nodes and weights on [-1, 1] (order 20) and the pieces of each smooth stretch: the rule
#: integrates the model (smooth between its kinks) to rounding; the sweep's array path uses the same rule.
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(20)


_PIECES = 16


def _integrate(fn, a: float, b: float, breaks: list[float]) -> float:
    """Composite Gauss-Legendre on each smooth piece (the kinks are break points); *fn* takes an array of angles."""
    edges = [a] + [t for t in breaks if a < t < b] + [b]
    total = 0.0
    for lo, hi in zip(edges, edges[1:]):
        h = (hi - lo) / _PIECES
        xs = (lo + h * np.arange(_PIECES))[:, None] + (_NODES + 1.0) * h / 2.0
        total += float((fn(xs) * _WEIGHTS).sum() * h / 2.0)
    return total


def model_t_array(w: np.ndarray, g: Mapping[str, float], force: str) -> np.ndarray:
    """:func:`model_t` on an array of crank angles (the same formulas, with numpy)."""
    lam = 1.0 / g["rod_ratio"]
    beta = np.arcsin(lam * np.sin(w))
    factor_w = np.sin(w + beta) / np.cos(beta)
    if force == "unit":
        return factor_w
    if force == "indicator":
        return card_force(g, lam)(w) * factor_w
    x = 0.5 * (1.0 - np.cos(w) + (1.0 - np.sqrt(1.0 - (lam * np.sin(w)) ** 2)) / lam)
    s1, s0, P, P0, s3 = g["filling"], g["clearance"], g["admission"], g["back_pressure"], g["compression"]
    steam = np.where(x <= s1, P + P0, (P + P0) * (s1 + s0) / (x + s0))
    back = np.where(x <= 1.0 - s3, P0, P0 * (s3 + s0) / (1.0 - x + s0))
    force_w = steam - back - g["pressure_ratio"] * (np.cos(w) + lam * np.cos(2.0 * w))
    return force_w * factor_w


def model_summary(g: Mapping[str, float], force: str) -> dict[str, float]:
    """Mean height, crossings α1, α2 and excess ∫(T − T_m) dα of the exact model (not of the drawing)."""
    kinks = _kinks(g, force)
    t = lambda w: model_t(w, g, force)  # noqa: E731
    ts = lambda w: model_t_array(w, g, force)  # noqa: E731
    mean = _integrate(ts, 0.0, math.pi, kinks) / math.pi
    grid = np.linspace(0.0, math.pi, 3601)
    vals = (ts(grid) - mean).tolist()
    roots = []
    for i in range(len(grid) - 1):
        if vals[i] == 0.0 or vals[i] * vals[i + 1] < 0.0:
            lo, hi = float(grid[i]), float(grid[i + 1])
            for _ in range(80):
                mid = 0.5 * (lo + hi)
                if (t(lo) - mean) * (t(mid) - mean) <= 0.0:
                    hi = mid
                else:
                    lo = mid
            roots.append(0.5 * (lo + hi))
    a1, a2 = roots[0], roots[-1]
    excess = _integrate(lambda w: ts(w) - mean, a1, a2, kinks)
    return {"mean": mean, "alpha1": a1, "alpha2": a2, "excess": excess, "kinks": tuple(kinks)}


def model_summary_sweep(g: Mapping[str, Any], force: str) -> dict[str, Any]:
    """:func:`model_summary` for a sweep's givens (arrays) in one numpy pass: the same rules on 2-D arrays.

    Kinks by bisection, Gauss-Legendre on each smooth piece (a kink outside the range
    of an integral makes a piece of width 0), crossings of the mean line on
    the same 3,601-point grid, refined by the same bisection.  Element i
    equals model_summary of set i to rounding (the tests hold them equal).
    """
    sizes = {np.size(v) for v in g.values() if np.ndim(v)}
    n = max(sizes, default=1)
    col = {k: (np.broadcast_to(np.asarray(v, dtype=float), (n,)).reshape(n, 1) if np.ndim(v) else v)
           for k, v in g.items()}
    lam = 1.0 / col["rod_ratio"][:, 0] if np.ndim(col["rod_ratio"]) else np.full(n, 1.0 / col["rod_ratio"])
    ts = lambda w: model_t_array(w, col, force)  # noqa: E731  (w: one row of angles per set of givens)

    if force == "unit":
        kinks: list[Any] = []
    else:
        kinks = []
        for x in (np.broadcast_to(col["filling"], (n, 1))[:, 0], 1.0 - np.broadcast_to(col["compression"], (n, 1))[:, 0]):
            lo, hi = np.zeros(n), np.full(n, math.pi)
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                below = 0.5 * (1.0 - np.cos(mid) + (1.0 - np.sqrt(1.0 - (lam * np.sin(mid)) ** 2)) / lam) < x
                lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
            kinks.append(0.5 * (lo + hi))
        kinks = list(np.sort(np.stack(kinks), axis=0))

    def integrate(fn, a, b):  # _integrate, one row per set of givens
        a, b = np.broadcast_to(a, (n,)), np.broadcast_to(b, (n,))
        edges = [a] + [np.clip(t, a, b) for t in kinks] + [b]
        total = np.zeros(n)
        for lo, hi in zip(edges, edges[1:]):
            h = (hi - lo) / _PIECES
            xs = ((lo[:, None] + h[:, None] * np.arange(_PIECES))[:, :, None] + (_NODES + 1.0) * h[:, None, None] / 2.0)
            total += (fn(xs.reshape(n, -1)).reshape(xs.shape) * _WEIGHTS).sum(axis=(1, 2)) * h / 2.0
        return total

    mean = integrate(ts, 0.0, math.pi) / math.pi
    grid = np.linspace(0.0, math.pi, 3601)
    vals = ts(np.broadcast_to(grid, (n, grid.size))) - mean[:, None]
    crossing = (vals[:, :-1] == 0.0) | (vals[:, :-1] * vals[:, 1:] < 0.0)
    if not crossing.any(axis=1).all():
        raise ArithmeticError("the model's tangential pressure does not cross its mean line")
    roots = []
    for i in (crossing.argmax(axis=1), crossing.shape[1] - 1 - crossing[:, ::-1].argmax(axis=1)):
        lo, hi = grid[i], grid[i + 1]
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            left = (ts(lo[:, None])[:, 0] - mean) * (ts(mid[:, None])[:, 0] - mean) <= 0.0
            lo, hi = np.where(left, lo, mid), np.where(left, mid, hi)
        roots.append(0.5 * (lo + hi))
    a1, a2 = roots
    excess = integrate(lambda w: ts(w) - mean[:, None], a1, a2)
    return {"mean": mean, "alpha1": a1, "alpha2": a2, "excess": excess, "kinks": tuple(kinks)}
