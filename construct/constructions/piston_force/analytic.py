"""The piston-force model the checks compare with: eq. (297) and (298) over the exact piston path, J, the
zero of the cards' force, the model's acceleration and deceleration areas."""

from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from .. import analytic
from ..indicator import back_pressure as model_back
from ..indicator import steam_pressure as model_steam
from ..indicator_card import card_pair
from .build import mass_force_scale

__all__ = ["card_force_zero", "j_abscissa", "two_term", "exact_acceleration", "exact_path", "model_areas",
           "model_areas_sweep", "piston_areas", "forward_force", "return_force"]


def card_force_zero(g: Mapping[str, float]) -> float | None:
    """The last x where the cards' forward piston force F p' − F p'' passes from pushing to braking (bisection
    on the straight lines between the digitised points), or None."""
    xs = sorted({x for c in card_pair(g) for x in c.forward[0]} | {0.0, 1.0})
    zero = None
    for lo, hi in zip(xs, xs[1:]):
        if forward_force(lo, g) > 0.0 >= forward_force(hi, g):
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if forward_force(mid, g) > 0.0 else (lo, mid)
            zero = 0.5 * (lo + hi)
    return zero


def j_abscissa(g: Mapping[str, float]) -> float:
    """Where (P + P0)(s1 + s0)/(x + s0) = P0 (s3 + s0)/(s - x + s0), x as a fraction of the stroke."""
    c1 = (g["admission"] + g["back_pressure"]) * (g["filling"] + g["clearance"])
    c2 = g["back_pressure"] * (g["compression"] + g["clearance"])
    return (1.0 + 2.0 * g["clearance"]) * c1 / (c1 + c2) - g["clearance"]


def two_term(w: float, lam: float) -> float:
    return math.cos(w) + lam * math.cos(2.0 * w)


def exact_acceleration(w: float, lam: float) -> float:
    """Exact piston acceleration over omega^2 R for the finite rod (+ = towards the crank end)."""
    return analytic.inertia_exact(w, lam)


def _two_term_array(w: Any, lam: float) -> Any:
    """:func:`two_term` on an array of angles."""
    return np.cos(w) + lam * np.cos(2.0 * w)


def _exact_accel_array(w: Any, lam: float) -> Any:
    """:func:`exact_acceleration` (analytic.inertia_exact) on an array of angles."""
    s2 = np.sin(w) ** 2
    return np.cos(w) + lam * (np.cos(2.0 * w) + lam * lam * s2 * s2) / (1.0 - lam * lam * s2) ** 1.5


def _dx_dw_array(w: Any, lam: float) -> Any:
    """:func:`_dx_dw` on an array of angles."""
    s = np.sin(w)
    return (s + lam * s * np.cos(w) / np.sqrt(1.0 - lam * lam * s * s)) / 2.0


def exact_path(w: float, lam: float) -> float:
    """Piston path over the stroke (exact)."""
    return (1.0 - math.cos(w) + (1.0 - math.sqrt(1.0 - lam * lam * math.sin(w) ** 2)) / lam) / 2.0


def _dx_dw(w: float, lam: float) -> float:
    s = math.sin(w)
    return (s + lam * s * math.cos(w) / math.sqrt(1.0 - lam * lam * s * s)) / 2.0


def _gauss(fn, a: float, b: float, pieces: int = 16, order: int = 20) -> float:
    """Gauss-Legendre of *order* on *pieces* equal pieces of [a, b]; *fn* takes an array of angles."""
    xs, ws = _LEGGAUSS[order] if order in _LEGGAUSS else np.polynomial.legendre.leggauss(order)
    h = (b - a) / pieces
    nodes = (a + h * np.arange(pieces))[:, None] + (xs + 1.0) * h / 2.0  # (piece, node)
    return float(((fn(nodes) * ws).sum(axis=1) * h / 2.0).sum())


_LEGGAUSS = {20: np.polynomial.legendre.leggauss(20)}


def _zero(fn, a: float, b: float) -> float:
    fa = fn(a)
    for _ in range(200):
        m = 0.5 * (a + b)
        if (fn(m) > 0) == (fa > 0):
            a, fa = m, fn(m)
        else:
            b = m
    return 0.5 * (a + b)


def model_areas(g: Mapping[str, float]) -> dict[str, float]:
    """The areas of the models (eq. 298 and the exact kinematics) over the exact piston path, in kg m."""
    lam = g["crank_radius"] / g["rod_length"]
    A = mass_force_scale(g)
    stroke_m = 2.0 * g["crank_radius"]
    w0 = _zero(lambda w: two_term(w, lam), 0.0, math.pi)
    two_acc = A * stroke_m * _gauss(lambda w: _two_term_array(w, lam) * _dx_dw_array(w, lam), 0.0, w0)
    two_dec = -A * stroke_m * _gauss(lambda w: _two_term_array(w, lam) * _dx_dw_array(w, lam), w0, math.pi)
    we = _zero(lambda w: exact_acceleration(w, lam), 0.0, math.pi)
    exact_acc = A * stroke_m * _gauss(lambda w: _exact_accel_array(w, lam) * _dx_dw_array(w, lam), 0.0, we)
    exact_dec = -A * stroke_m * _gauss(lambda w: _exact_accel_array(w, lam) * _dx_dw_array(w, lam), we, math.pi)
    return {"two_term_acceleration": two_acc, "two_term_deceleration": two_dec,
            "exact_acceleration": exact_acc, "exact_deceleration": exact_dec}


def model_areas_sweep(g: Mapping[str, Any]) -> dict[str, Any]:
    """The model areas of :func:`area_balance` for a sweep's givens (arrays) in one numpy pass.

    The same rules as for one set of givens: the zeros by the same bisection,
    the same Gauss-Legendre rule, with one row of nodes per set of givens.
    Element i equals the areas of set i to rounding (the tests hold them equal).
    """
    lam = np.atleast_1d(np.asarray(g["crank_radius"] / g["rod_length"], dtype=float))
    n = lam.size
    A = np.broadcast_to(mass_force_scale(g), (n,))
    stroke_m = np.broadcast_to(2.0 * np.asarray(g["crank_radius"], dtype=float), (n,))
    L = lam[:, None]

    def zero(fn):  # _zero, one bisection per set of givens
        a, b = np.zeros(n), np.full(n, math.pi)
        fa = fn(a)
        for _ in range(200):
            m = 0.5 * (a + b)
            fm = fn(m)
            same = (fm > 0) == (fa > 0)
            a, fa, b = np.where(same, m, a), np.where(same, fm, fa), np.where(same, b, m)
        return 0.5 * (a + b)

    def gauss(fn, a, b, pieces: int = 16, order: int = 20):  # _gauss, one row of nodes per set of givens
        xs, ws = _LEGGAUSS[order]
        a, b = np.broadcast_to(a, (n,)), np.broadcast_to(b, (n,))
        h = (b - a) / pieces
        nodes = (a[:, None] + h[:, None] * np.arange(pieces))[:, :, None] + (xs + 1.0) * h[:, None, None] / 2.0
        return ((fn(nodes.reshape(n, -1)).reshape(nodes.shape) * ws).sum(axis=2) * (h / 2.0)[:, None]).sum(axis=1)

    two = lambda w: _two_term_array(w, L) * _dx_dw_array(w, L)  # noqa: E731
    exact = lambda w: _exact_accel_array(w, L) * _dx_dw_array(w, L)  # noqa: E731
    w0 = zero(lambda w: _two_term_array(w, lam))
    we = zero(lambda w: _exact_accel_array(w, lam))
    return {"two_term_acceleration": A * stroke_m * gauss(two, 0.0, w0),
            "two_term_deceleration": -A * stroke_m * gauss(two, w0, math.pi),
            "exact_acceleration": A * stroke_m * gauss(exact, 0.0, we),
            "exact_deceleration": -A * stroke_m * gauss(exact, we, math.pi)}


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
    """F'' p'' - F' p' on the return stroke at piston position x: the crank side's diagram is the cover side's mirrored."""
    if "card.x0" in g:
        cover, crank = card_pair(g)
        f1, f2 = piston_areas(g)
        return f2 * crank.pressure(x, "return") - f1 * cover.pressure(x, "return")
    return g["piston_area_crank"] * model_steam(1.0 - x, g) - g["piston_area_cover"] * model_back(1.0 - x, g)
