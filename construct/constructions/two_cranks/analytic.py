"""The law of two cranks at 90° (seed 002, § 146–147): piston travel, excess work, its extremes, Kochański's π -- what the checks compare with, never used to build."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ...kernel.errors import InvalidParameter, did_you_mean
from ..analytic import piston_fraction, piston_rate


#: Where the first crank starts: § 146's B1 (the crank-end dead centre, the rod correction subtracting in the
#: forward stroke: the default) or the head-end dead centre of the other books.
DEAD_CENTRES = ("crank-end", "head-end")
#: Who drives whom (§ 146): the rods drive the shaft ("wenn ... der Antrieb von den Kolbenstangen ausgeht", the
#: default), or the shaft drives pumps ("würde das Gegentheil stattfinden": the masses take up -e, the least and
#: greatest speeds change places).  The sign of the excess work in the masses' balance.
DRIVES = {"engine": 1.0, "pump": -1.0}


def drive_sign(drive: str) -> float:
    """+1 when the rods drive the shaft (an engine), −1 when the shaft drives the rods (pumps).

    >>> drive_sign("engine"), drive_sign("pump")
    (1.0, -1.0)
    """
    if drive not in DRIVES:
        raise InvalidParameter(f"drive must be one of {', '.join(DRIVES)}, got {drive!r}{did_you_mean(drive, DRIVES)}")
    return DRIVES[drive]


def drive_of(sign: float) -> str:
    """The drive a sign stands for (a protocol's given ``drive``): "engine" or "pump".

    >>> drive_of(1.0), drive_of(-1.0)
    ('engine', 'pump')
    """
    return "engine" if sign > 0 else "pump"

# --------------------------------------------------------------------------
# The analytic side (used by the checks only, never to build).
# --------------------------------------------------------------------------

#: Kochański's segment for r = 1: sqrt(4 + (3 - tan 30°)²) = sqrt(40/3 - 2 sqrt 3).
KOCHANSKI_RHO = math.sqrt(40.0 / 3.0 - 2.0 * math.sqrt(3.0))
#: How far it falls short of π (in units of r): the rectification's known error.
KOCHANSKI_ERROR = math.pi - KOCHANSKI_RHO


def _lam(rod_ratio: Any) -> Any:
    """r/l of a rod ratio l/r (None: the infinite rod, r/l = 0)."""
    return 0.0 if rod_ratio is None else 1.0 / np.asarray(rod_ratio, dtype=float)


def _position(w: Any, rod_ratio: Any) -> Any:
    """Piston position from the head-end dead centre, units of r (exact law; None: infinite rod)."""
    return 2.0 * piston_fraction(w, _lam(rod_ratio))


def piston_travel(theta: float, rod_ratio: float | None) -> float:
    """Distance a piston has travelled while its crank turns from 0 to *theta* >= 0 (units of r).

    >>> round(piston_travel(2 * math.pi, 5.0), 12), round(piston_travel(1.5 * math.pi, None), 12)
    (4.0, 3.0)
    """
    n = math.floor(theta / math.pi)
    rem = theta - n * math.pi
    if n % 2 == 0:
        return 2.0 * n + _position(rem, rod_ratio)
    return 2.0 * n + 2.0 - _position(math.pi - rem, rod_ratio)


def excess_exact(alpha: float, rod_ratio: float | None) -> float:
    """The excess work e(α)/(Q·r): both rods' work minus (4/π)·α, from the first crank's head-end dead centre.

    >>> a = math.radians(30.0)
    >>> round(excess_exact(a, None) - (1 + math.sin(a) - math.cos(a) - 4 * a / math.pi), 14)
    0.0
    """
    half = 0.5 * math.pi
    return (piston_travel(alpha, rod_ratio) + piston_travel(alpha + half, rod_ratio)
            - piston_travel(half, rod_ratio) - 4.0 * alpha / math.pi)


def start_angle(dead_centre: str) -> float:
    """The first crank's starting angle from the head-end dead centre."""
    if dead_centre not in DEAD_CENTRES:
        raise InvalidParameter(f"dead centre must be one of {', '.join(DEAD_CENTRES)}, got {dead_centre!r}{did_you_mean(dead_centre, DEAD_CENTRES)}")
    return math.pi if dead_centre == "crank-end" else 0.0


def excess_from(alpha: Any, rod_ratio: float | None, dead_centre: str = "crank-end") -> Any:
    """e(α)/(Q·r) with α counted from the given dead centre of the first crank (§ 146: the crank end, B1).

    From the crank end it is the head-end excess turned half a revolution: e(π + α) − e(π).  At 180° § 146's
    formula (upper sign in the Hingang) gives 2 − 4 + the rod terms; the exact law +0.2020 Q·r at L/r = 5.
    An array of angles gives the array of e, in one numpy pass (:func:`excess_exact_array`: a figure's checks
    read e at every point of the division, and a sweep's checks at every point of every set).

    >>> round(excess_from(math.pi, 5.0), 6), round(excess_from(math.pi, 5.0, "head-end"), 6)
    (0.202041, -0.202041)
    >>> excess_from(np.array([0.0, math.pi]), 5.0).round(6).tolist()
    [0.0, 0.202041]
    """
    a0 = start_angle(dead_centre)
    if np.ndim(alpha):
        return excess_exact_array(a0 + np.asarray(alpha, dtype=float), rod_ratio) - excess_exact(a0, rod_ratio)
    return excess_exact(a0 + alpha, rod_ratio) - excess_exact(a0, rod_ratio)


def extreme_angles_exact() -> tuple[float, float]:
    """α1, α2 of § 146 (radians): sin 2α = (4/π)² − 1."""
    a = 0.5 * math.asin((4.0 / math.pi) ** 2 - 1.0)
    return a, 0.5 * math.pi - a


def _alpha1_of(rho: float) -> float:
    return 0.5 * math.asin(16.0 / (rho * rho) - 1.0)


def kochanski_angle_error() -> float:
    """The error Kochański's rectification puts into α1 (and, with the other sign, into α2), radians."""
    return abs(_alpha1_of(KOCHANSKI_RHO) - _alpha1_of(math.pi))


def excess_exact_array(alpha: Any, rod_ratio: Any) -> Any:
    """:func:`excess_exact` on arrays: angles *alpha* and rod ratios (None: infinite rod) broadcast together.

    The same law with numpy, for a grid of angles or a sweep of rod ratios in
    one pass (held equal to the scalar function by the tests).
    """
    alpha = np.asarray(alpha, dtype=float)
    half = 0.5 * math.pi

    def position(w):
        return _position(w, rod_ratio)

    def travel(theta):  # piston_travel: forward half turns from the dead centre, back ones from the other
        n = np.floor(theta / math.pi)
        rem = theta - n * math.pi
        even = np.mod(n, 2.0) == 0.0
        p = position(np.where(even, rem, math.pi - rem))
        return np.where(even, 2.0 * n + p, 2.0 * n + 2.0 - p)  # summed as piston_travel sums, to the last bit

    return travel(alpha) + travel(alpha + half) - position(half) - 4.0 * alpha / math.pi


def quadrant_extremes(rod_ratio: Any, samples: int = 2000, dead_centre: str = "head-end") -> list[dict[str, Any]]:
    """Per quadrant: where e is least and greatest, and by how much it rises and falls (exact law).

    Measured from the quadrant's start (§ 147: v1 there is the speed at its
    beginning); ``rise`` = max − start, ``fall`` = start − min.  Golden-section
    refinement of a dense sample, all quadrants (and, for an array of rod
    ratios, all of them: the values are then arrays) in one numpy pass.

    >>> q = quadrant_extremes(None)[0]
    >>> round(math.degrees(q["alpha_min"]), 5), abs(q["rise"] - q["fall"]) < 1e-12
    (19.19968, True)
    """
    scalar = rod_ratio is None or np.ndim(rod_ratio) == 0
    a_s = start_angle(dead_centre)

    ratio = None if rod_ratio is None else np.asarray(rod_ratio, dtype=float).reshape(-1, 1, 1)
    at_start = excess_exact_array(a_s, ratio)  # (the same for every probe: made once)

    def law(angle, r):  # e(α) with α counted from the chosen dead centre (excess_from, on arrays)
        return excess_exact_array(a_s + angle, r) - at_start
    step = 0.5 * math.pi / samples
    a0 = (0.5 * math.pi * np.arange(4.0)).reshape(1, 4, 1)
    grid = a0 + step * np.arange(samples + 1.0)  # (1, quadrant, sample)
    vals = law(grid, ratio)  # (ratio, quadrant, sample)
    start = vals[..., 0]
    # golden-section search about the least and greatest sample: (ratio, quadrant, min/max)
    i = np.stack([vals.argmin(axis=-1), vals.argmax(axis=-1)], axis=-1)
    a00 = a0[..., 0][..., None]
    lo = a00 + step * np.maximum(i - 1, 0)
    hi = a00 + step * np.minimum(i + 1, samples)
    sign = np.array([-1.0, 1.0])
    r3 = None if ratio is None else ratio.reshape(-1, 1, 1)
    g = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(80):
        a, b = hi - g * (hi - lo), lo + g * (hi - lo)
        ea, eb = law(np.stack([a, b]), r3)  # both probes in one pass
        left = sign * ea > sign * eb
        hi, lo = np.where(left, b, hi), np.where(left, lo, a)
    best = 0.5 * (lo + hi)
    e = law(best, r3)
    out = []
    for q in range(4):
        row = {"quadrant": q + 1, "start": start[:, q], "alpha_min": best[:, q, 0], "e_min": e[:, q, 0],
               "alpha_max": best[:, q, 1], "e_max": e[:, q, 1]}
        row["rise"], row["fall"] = row["e_max"] - row["start"], row["start"] - row["e_min"]
        out.append({k: (v if k == "quadrant" else float(v[0]) if scalar else v) for k, v in row.items()})
    return out


def max_magnification(rod_ratio: Any) -> Any:
    """The largest g = G·k for which every speed radius r ± g·e stays positive (exact law); arrays for a sweep.

    One bound for both drives and both dead centres: over a turn, e from the crank end takes the values of e
    from the head end mirrored (its least is minus the other's greatest, and the other way round), so the
    engine's lowest speed from one dead centre is the pump's from the other, and the head end's least e is the
    deepest drop of all four.

    >>> a = np.linspace(0.0, 2 * math.pi, 20001)
    >>> head, crank = excess_exact_array(a, 4.5), excess_exact_array(math.pi + a, 4.5) - excess_exact(math.pi, 4.5)
    >>> abs(float(crank.min() + head.max())) < 1e-12, abs(float(crank.max() + head.min())) < 1e-12
    (True, True)
    """
    if rod_ratio is None or np.ndim(rod_ratio) == 0:
        e_min = min(q["e_min"] for q in quadrant_extremes(rod_ratio, samples=400))
        return math.inf if e_min >= 0.0 else 1.0 / -e_min
    e_min = np.min([q["e_min"] for q in quadrant_extremes(rod_ratio, samples=400)], axis=0)
    with np.errstate(divide="ignore"):
        return np.where(e_min >= 0.0, math.inf, 1.0 / -e_min)



def piston_speed_factor(w: float, rod_ratio: float | None) -> float:
    """c/v: the piston's speed over the crank-pin speed at crank angle *w* (exact law; None: infinite rod).

    >>> round(piston_speed_factor(math.pi / 2, 5.0), 12), round(piston_speed_factor(math.pi / 4, 4.0), 6)
    (1.0, 0.834107)
    """
    return 2.0 * piston_rate(w, _lam(rod_ratio))
