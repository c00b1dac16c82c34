"""Two cranks at right angles: the speed fluctuation of the shaft and its polar diagram (seed 002, § 146–147).

One shaft is driven by two cranks set at 90°, each rod pushed with a
constant force Q along its motion.  From the head-end dead centre of the
first crank (the second 90° ahead) the rods have done the work Q·(s1 + s2),
s1, s2 the distances the pistons have travelled; the shaft has taken
(4/π)·Q·r·α on average.  The excess goes into the masses:
(m1 + m2)(v² − v1²)/2 = Q·r·e(α), and the book draws v as a radius on each
crank position (Fig. 566).

What is constructed (layout y up, crank centre O at the origin):

* the crank circle divided into 2N parts over the whole turn: the upper
  semicircle by :func:`~construct.kernel.division.divide_semicircle`, the
  lower half as mirror images (a circle about the nearer dead centre through
  a point meets the crank circle again at its mirror image);
* the piston positions: the rod arcs of :func:`~construct.constructions.crank.rod_arcs`
  for a finite rod, the ordinates (chord point–mirror image) for the
  infinite rod; a crank point and its mirror image give the same piston
  position;
* the work: on a *work line* both pistons' paths are stepped on with the
  compass, position by position (always forward: the force is along the
  motion), from W0; the mean work 4r·j/N (the shaft's (4/π)·r·α at
  α = jπ/N needs no π: a revolution is 8r) by dividers stepping the
  N/2-th part of the stroke; the mean marks start r/g behind W0, so the
  distance from mark to end is r/g + e, always positive while the speed is;
* the speed: a proportional angle with scale lines at r and g·r carries that
  distance to g·(r/g + e) = r + g·e, the radius of the speed point on the
  crank position (the book's law v = v1(1 + k·e/r), k = Qr/((m1 + m2)v1²),
  v1 drawn as the crank radius, deviations magnified G times: g = G·k);
* the wave curve through the speed points (a closed French curve);
* the extremes of § 146 for the infinite rod: π by Kochański's rectification
  (1685) of the half circle, (4/π)·r and (4/π)²·r by fourth proportionals,
  sin 2α = (4/π)² − 1 as a height in the crank circle, the two angles by
  bisecting the arcs.  Kochański's segment is 5.9·10⁻⁵ r short of π·r; the
  angles carry that error (3.9·10⁻⁵ rad), stated in their provenance.

With a finite rod the figure has both diagrams side by side: the finite rod
about O, the infinite rod about O' (§ 147: the quadrants differ).

**Which dead centre.**  § 146 starts at B1 and writes the piston path
s1 = r(1 − cos α) ∓ r² sin² α/2l, "the upper sign when the crank is in the
Hingang": from B1 the rod correction *subtracts*, so B1 is the crank-end dead
centre (the crank turned away from the cylinder).  That is the default,
``dead_centre="crank-end"``: e(180°) = +0.202 Q·r at L/r = 5.  The other
books (seeds 000, 001, 004) and this library's other constructions measure
from the head-end dead centre, where the correction adds;
``dead_centre="head-end"`` starts the first crank there, and the finite rod's
diagram is the other one turned half a revolution (e(180°) = −0.202 Q·r).
The first quadrant agrees in both, since the rod terms of the two cranks
cancel there to first order; with the infinite rod both are the same.  The
figure's caption names the dead centre.

>>> fig = TWO_CRANKS.figure(parts=4, rod_ratio=5.0)
>>> [round(work_excess(fig, j), 12) for j in range(0, 9, 2)]   # 0, 90, 180, 270, 360 degrees from B1
[0.0, 0.0, 0.202041028867, 0.202041028867, 0.0]
>>> fig = TWO_CRANKS.figure(parts=4, rod_ratio=5.0, dead_centre="head-end")
>>> [round(work_excess(fig, j), 12) for j in range(0, 9, 2)]
[0.0, 0.0, -0.202041028867, -0.202041028867, 0.0]
>>> round(math.degrees(crank_angle(fig, "K.M1")), 4), round(math.degrees(crank_angle(fig, "K.M2")), 4)
(19.2019, 70.7981)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping, Sequence

import numpy as np

from .checking import EUCLIDEAN_TOLERANCE, Check
from ..kernel.errors import InvalidParameter
from ..kernel.division import MAX_PARTS, check_parts, divide_semicircle
from ..kernel.geometry import Point
from ..kernel.instruments import Builder
from ..kernel.proportional import ProportionalAngle, carry_across, fourth_proportional, scale_line
from ..kernel.protocol import Caption, Provenance
from . import Construction, Figure, bounded, positive, register, rod_ratio_param
from .domain import DRAWN_LENGTH, FLUCTUATION, SPEED_GAIN
from .crank import angle_tolerance, build_frame, rod_arcs

__all__ = [
    "TWO_CRANKS",
    "build_two_cranks",
    "two_cranks_checks",
    "work_excess",
    "speed_radius",
    "crank_angle",
    "excess_exact",
    "piston_travel",
    "extreme_angles_exact",
    "KOCHANSKI_RHO",
    "KOCHANSKI_ERROR",
    "kochanski_angle_error",
    "quadrant_extremes",
    "speed_fluctuation_rows",
    "speeds",
    "piston_speed_factor",
    "max_magnification",
    "auto_magnification",
    "DEAD_CENTRES",
    "excess_from",
]

#: Where the first crank starts: § 146's B1 (the crank-end dead centre, the rod correction subtracting in the
#: forward stroke: the default) or the head-end dead centre of the other books.
DEAD_CENTRES = ("crank-end", "head-end")

# --------------------------------------------------------------------------
# The analytic side (used by the checks only, never to build).
# --------------------------------------------------------------------------

#: Kochański's segment for r = 1: sqrt(4 + (3 - tan 30°)²) = sqrt(40/3 - 2 sqrt 3).
KOCHANSKI_RHO = math.sqrt(40.0 / 3.0 - 2.0 * math.sqrt(3.0))
#: How far it falls short of π (in units of r): the rectification's known error.
KOCHANSKI_ERROR = math.pi - KOCHANSKI_RHO


def _position(w: float, rod_ratio: float | None) -> float:
    """Piston position from the head-end dead centre, units of r (exact law; None: infinite rod)."""
    if rod_ratio is None:
        return 1.0 - math.cos(w)
    s = math.sin(w)
    return 1.0 - math.cos(w) + s * s / (rod_ratio + math.sqrt(rod_ratio * rod_ratio - s * s))


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


def _start_angle(dead_centre: str) -> float:
    """The first crank's starting angle from the head-end dead centre."""
    if dead_centre not in DEAD_CENTRES:
        raise InvalidParameter(f"dead centre must be one of {', '.join(DEAD_CENTRES)}, got {dead_centre!r}")
    return math.pi if dead_centre == "crank-end" else 0.0


def excess_from(alpha: float, rod_ratio: float | None, dead_centre: str = "crank-end") -> float:
    """e(α)/(Q·r) with α counted from the given dead centre of the first crank (§ 146: the crank end, B1).

    From the crank end it is the head-end excess turned half a revolution: e(π + α) − e(π).  At 180° § 146's
    formula (upper sign in the Hingang) gives 2 − 4 + the rod terms; the exact law +0.2020 Q·r at L/r = 5.

    >>> round(excess_from(math.pi, 5.0), 6), round(excess_from(math.pi, 5.0, "head-end"), 6)
    (0.202041, -0.202041)
    """
    a0 = _start_angle(dead_centre)
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
        if rod_ratio is None:
            return 1.0 - np.cos(w)
        s = np.sin(w)
        return 1.0 - np.cos(w) + s * s / (rod_ratio + np.sqrt(rod_ratio * rod_ratio - s * s))

    def travel(theta):  # piston_travel: forward half turns from the dead centre, back ones from the other
        n = np.floor(theta / math.pi)
        rem = theta - n * math.pi
        even = np.mod(n, 2.0) == 0.0
        p = position(np.where(even, rem, math.pi - rem))
        return 2.0 * n + np.where(even, p, 2.0 - p)

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
    a_s = _start_angle(dead_centre)

    def law(angle, r):  # e(α) with α counted from the chosen dead centre (excess_from, on arrays)
        return excess_exact_array(a_s + angle, r) - excess_exact_array(a_s, r)

    ratio = None if rod_ratio is None else np.asarray(rod_ratio, dtype=float).reshape(-1, 1, 1)
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
    """The largest g = G·k for which every speed radius r + g·e stays positive (exact law); arrays for a sweep."""
    if rod_ratio is None or np.ndim(rod_ratio) == 0:
        e_min = min(q["e_min"] for q in quadrant_extremes(rod_ratio, samples=400))
        return math.inf if e_min >= 0.0 else 1.0 / -e_min
    e_min = np.min([q["e_min"] for q in quadrant_extremes(rod_ratio, samples=400)], axis=0)
    with np.errstate(divide="ignore"):
        return np.where(e_min >= 0.0, math.inf, 1.0 / -e_min)


# --------------------------------------------------------------------------
# The closed French curve through the speed points (op ``smooth_loop``, kernel/closed_curves.py).
# --------------------------------------------------------------------------


def closed_curve(b: Builder, name: str, points: Sequence[str], *, de: str, en: str, role: str = "result") -> str:
    """Record the drawing of a closed smooth curve through *points* (in order round the figure)."""
    b.record("curve", "smooth_loop", tuple(points), (name,), {"points": len(points)}, de, en, role=role)
    return name


# --------------------------------------------------------------------------
# The construction.
# --------------------------------------------------------------------------

_FWD = (1.0, 0.0)
_SUB = "₀₁₂₃₄₅₆₇₈₉"


@dataclass(frozen=True)
class _Part:
    """The object names of one crank circle with its diagram."""

    tag: str            # "" for the circle about O, "i" for the infinite rod beside it
    infinite: bool
    C: str
    D0: str
    D1: str
    circle: str
    crank_points: tuple[str, ...]    # index 0..2N-1 round the whole circle
    pistons: tuple[str, ...]         # piston position for index 0..2N-1
    W0: str = ""
    ends: tuple[str, ...] = ()       # E_j: end of the work stepped on, j = 0..2N
    means: tuple[str, ...] = ()      # M_j: mean-work marks (r/g behind), j = 0..2N
    radii: tuple[str, ...] = ()      # Z_j: speed points, j = 0..2N-1


def _givens(r: Any, rod_ratio: Any, fluctuation: Any, magnify: Any) -> dict[str, float]:
    g = {"r": bounded("crank radius r", r, DRAWN_LENGTH), "rod_ratio": rod_ratio_param(rod_ratio),
         "fluctuation": bounded("fluctuation Qr/((m1+m2) v1^2)", fluctuation, FLUCTUATION),
         "magnify": positive("magnification of the speed deviations", magnify)}
    SPEED_GAIN.check("magnify x fluctuation", g["magnify"] * g["fluctuation"])
    return g


def _validate(givens: Mapping[str, Any]) -> None:
    """The givens' domain; a sweep's (arrays) in one pass, the message naming its first set outside."""
    g = _givens(givens["r"], givens["rod_ratio"], givens["fluctuation"], givens["magnify"])
    limit = max_magnification(g["rod_ratio"])
    gain = g["fluctuation"] * g["magnify"]
    outside = np.flatnonzero(np.atleast_1d(gain >= limit))
    if outside.size:
        i = int(outside[0])
        at = lambda v: float(np.asarray(v).flat[i]) if np.ndim(v) else v  # noqa: E731  (set i of a sweep)
        gain_i, ratio_i, limit_i = at(gain), at(g["rod_ratio"]), at(limit)
        raise InvalidParameter(
            f"fluctuation x magnify = {gain_i:.6g} makes a speed radius r + g*e vanish "
            f"for L/r = {ratio_i:.6g} (e falls to {-1.0 / limit_i:.4g} Q r); keep --magnify times --fluctuation "
            f"below {limit_i:.4g}")


#: Magnifications a draftsman would pick for the speed deviations (largest first).
NICE_MAGNIFICATIONS = (8.0, 5.0, 4.0, 2.0, 1.0, 0.5, 0.25, 0.1)


def auto_magnification(rod_ratio: Any, fluctuation: float) -> Any:
    """The largest of :data:`NICE_MAGNIFICATIONS` that keeps every speed radius above 0.4 r.

    For an array of rod ratios (a sweep), an array of magnifications, in one pass.

    >>> auto_magnification(5.0, 0.25), auto_magnification(2.0, 0.25), auto_magnification(1.1, 0.25)
    (8.0, 4.0, 1.0)
    >>> auto_magnification(np.array([5.0, 2.0, 1.1]), 0.25).tolist()
    [8.0, 4.0, 1.0]
    """
    if rod_ratio is None or np.ndim(rod_ratio) == 0:
        e_min = min(q["e_min"] for q in quadrant_extremes(rod_ratio, samples=400))
        for m in NICE_MAGNIFICATIONS:
            if fluctuation * m * max(-e_min, 0.0) <= 0.6:
                return m
        return NICE_MAGNIFICATIONS[-1] * 0.6 / (fluctuation * -e_min) / 1.01
    e_min = np.min([q["e_min"] for q in quadrant_extremes(rod_ratio, samples=400)], axis=0)
    out = NICE_MAGNIFICATIONS[-1] * 0.6 / (fluctuation * -e_min) / 1.01
    for m in NICE_MAGNIFICATIONS[::-1]:  # the largest that fits is written last
        out = np.where(fluctuation * m * np.maximum(-e_min, 0.0) <= 0.6, m, out)
    return out


def _check_parts(parts: Any, method: str) -> str:
    used = check_parts(parts, method)
    if parts % 2:
        raise InvalidParameter(f"two cranks at 90 degrees need an even number of parts of the semicircle "
                               f"(90 degrees must be a division point), got {parts}")
    return used


def _mirror_points(b: Builder, tag: str, C: str, D0: str, D1: str, circle: str, upper: Sequence[str]) -> list[str]:
    """The lower half: each point's mirror image, found with a circle about the nearer dead centre."""
    n = len(upper) - 1
    lower = []
    with b.group("lower half: mirror images of the division points",
                 "untere Hälfte: Spiegelbilder der Teilpunkte"):
        for k in range(1, n):
            dc = D0 if 2 * k <= n else D1
            kc = b.circle_through(f"{tag}mir{k}.k", dc, upper[k], de=f"Kreis um den Totpunkt durch {k}",
                                  en=f"circle about the dead centre through point {k}")
            lower.append(b.intersect(f"{tag}Q{k}", kc, circle, rule=("right", D0, D1),
                                     de=f"Spiegelpunkt von {k}: Kurbelstellung {2 * n - k}",
                                     en=f"mirror image of point {k}: crank position {2 * n - k}"))
    return lower


def _copied_points(b: Builder, tag: str, C: str, D0: str, D1: str, circle: str,
                   source: Sequence[str], src_D0: str, src_D1: str) -> tuple[list[str], list[str]]:
    """The division carried to a second circle of the same radius: each chord from the nearer dead centre.

    The circle about the dead centre with the chord cuts the second circle in
    the point and its mirror image at once.
    """
    n = len(source) - 1
    upper, lower = [D0], []
    with b.group("division carried over with the compass", "Teilung mit dem Zirkel übertragen"):
        for k in range(1, n):
            near, src = (D0, src_D0) if 2 * k <= n else (D1, src_D1)
            kc = b.circle_segment(f"{tag}cp{k}.k", near, src, source[k], de=f"Sehne zu Punkt {k} übertragen",
                                  en=f"chord to point {k} carried over")
            p, q = b.intersect((f"{tag}P{k}", f"{tag}Q{k}"), kc, circle, rule=("left", D0, D1),
                               de=f"Kurbelstellungen {k} und {2 * n - k}", en=f"crank positions {k} and {2 * n - k}")
            upper.append(p)
            lower.append(q)
    return upper + [D1], lower


def _ordinates(b: Builder, tag: str, axis: str, upper: Sequence[str], lower: Sequence[str]) -> list[str]:
    """Infinite rod: the chord from a point to its mirror image cuts the stroke line at the piston."""
    n = len(upper) - 1
    feet = [upper[0]]
    with b.group("piston positions for the infinite rod (ordinates)",
                 "Kolbenstellungen bei unendlicher Stange (Ordinaten)"):
        for k in range(1, n):
            o = b.line(f"{tag}ord{k}", upper[k], lower[k - 1], de=f"Ordinate durch {k}", en=f"ordinate through {k}")
            feet.append(b.intersect(f"{tag}Y{k}", o, axis, rule=("only",), role="result",
                                    de=f"Kolbenstellung Y{k}", en=f"piston position Y{k}"))
    return feet + [upper[n]]


def _whole_circle(upper: Sequence[str], lower: Sequence[str], pistons_upper: Sequence[str]):
    """Crank points and piston positions for indices 0..2N-1 (lower index 2N-k mirrors k)."""
    n = len(upper) - 1
    points = list(upper) + [lower[k - 1] for k in range(n - 1, 0, -1)]
    pistons = list(pistons_upper) + [pistons_upper[k] for k in range(n - 1, 0, -1)]
    return tuple(points), tuple(pistons)


@dataclass(frozen=True)
class _Speed:
    angle: ProportionalAngle
    one: Any      # Scale at distance r
    gain: Any     # Scale at distance g r
    lead: str     # Length r/g


def _speed_angle(b: Builder, S_at: tuple[float, float]) -> _Speed:
    """The proportional angle with scale lines at r and g·r, and r/g read off it."""
    with b.group("proportional angle for the speed scale", "Proportionswinkel für den Geschwindigkeitsmaßstab"):
        S = b.given_point("S", S_at[0], S_at[1], unit="r", de="Scheitel S des Proportionswinkels",
                          en="vertex S of the proportional angle", label="S")
        leg = b.given_line("leg", S, angle_deg=0.0, de="Schenkel des Proportionswinkels",
                           en="leg of the proportional angle")
        b.given_length("gr", product=("magnify", "fluctuation", "r"),
                       de="g·r = G·k·r (Vergrößerung G mal Qr/((m1+m2)v1²))",
                       en="g r = G k r (magnification G times Qr/((m1+m2)v1^2))")
        ang = ProportionalAngle(S, leg)
        side = ("toward", S, None, 1.0, 0.0)
        one = scale_line(b, ang, "sr", length="r", toward=side)
        gain = scale_line(b, ang, "sg", length="gr", toward=side)
        k = b.circle_radius("sg.kR", gain.origin, "r", de="r auf der Maßlinie g·r", en="r on the scale line g r")
        R = b.intersect("sg.R", gain.line, k, rule=("toward", S, None, 0.0, -1.0))
        Rr = carry_across(b, ang, "sr.R", R, one, de="r/g auf der Maßlinie r", en="r/g on the scale line r")
        lead = b.length_of("lead", one.origin, Rr, de="Zirkel auf r/g", en="compass set to r/g")
    return _Speed(ang, one, gain, lead)


def _work(b: Builder, part: _Part, speed: _Speed, W_at: tuple[float, float], n: int, mstep: str,
          start: int = 0) -> _Part:
    """Both pistons' paths stepped on along the work line; the mean-work marks beside them."""
    tag = part.tag
    m = 2 * n
    half = n // 2
    with b.group(f"work of the rods and mean work{' (infinite rod)' if part.infinite else ''}",
                 f"Arbeit der Stangen und mittlere Arbeit{' (unendliche Stange)' if part.infinite else ''}"):
        W0 = b.given_point(f"{tag}W0", W_at[0], W_at[1], unit="r", de="Anfang W0 der Arbeitslinie",
                           en="start W0 of the work line", label="W₀")
        wl = b.given_line(f"{tag}work", W0, angle_deg=0.0, de="Arbeitslinie", en="work line")
        back = b.circle_radius(f"{tag}M0.k", W0, speed.lead, de="r/g hinter W0", en="r/g behind W0")
        means = [b.intersect(f"{tag}M0", wl, back, rule=("toward", W0, None, -1.0, 0.0),
                             de="Anfang der mittleren Arbeit, r/g vor W0", en="start of the mean work, r/g before W0")]
        ends = [W0]
        for j in range(1, m + 1):
            with b.group(f"crank position {j}: work stepped on", f"Kurbelstellung {j}: Arbeit abgetragen"):
                # *start* is the first crank's starting index (N: § 146's B1, the crank-end dead centre)
                a1, c1 = part.pistons[(start + j - 1) % m], part.pistons[(start + j) % m]
                a2, c2 = part.pistons[(start + j - 1 + half) % m], part.pistons[(start + j + half) % m]
                k1 = b.circle_segment(f"{tag}U{j}.k", ends[-1], a1, c1, de=f"Weg des ersten Kolbens, Schritt {j}",
                                      en=f"path of the first piston, step {j}")
                U = b.intersect(f"{tag}U{j}", wl, k1, rule=("toward", W0, None) + _FWD)
                k2 = b.circle_segment(f"{tag}E{j}.k", U, a2, c2, de=f"Weg des zweiten Kolbens, Schritt {j}",
                                      en=f"path of the second piston, step {j}")
                ends.append(b.intersect(f"{tag}E{j}", wl, k2, rule=("toward", W0, None) + _FWD,
                                        de=f"E{j}: Arbeit beider Stangen bis Stellung {j}",
                                        en=f"E{j}: work of both rods up to position {j}"))
                means.append(b.step_off(f"{tag}M{j}", wl, means[-1], mstep, rule=("toward", W0, None) + _FWD,
                                        de=f"M{j}: mittlere Arbeit (4/π)·r·α, um 4r/N weiter",
                                        en=f"M{j}: mean work (4/pi) r alpha, 4r/N further"))
    return _Part(**{**part.__dict__, "W0": W0, "ends": tuple(ends), "means": tuple(means)})


def _radii(b: Builder, part: _Part, speed: _Speed, n: int, start: int = 0) -> _Part:
    """For each crank position: M_j E_j = r/g + e carried to g·(r/g + e) = r + g e, laid on the crank position."""
    tag = part.tag
    m = 2 * n
    radii = []
    with b.group(f"speeds as radii on the crank positions{' (infinite rod)' if part.infinite else ''}",
                 f"Geschwindigkeiten als Halbmesser auf den Kurbelstellungen{' (unendliche Stange)' if part.infinite else ''}"):
        for j in range(m):
            with b.group(f"speed at crank position {j}", f"Geschwindigkeit in Kurbelstellung {j}"):
                k = b.circle_segment(f"{tag}V{j}.k", speed.one.origin, part.means[j], part.ends[j],
                                     de=f"M{j}E{j} auf die Maßlinie r", en=f"M{j}E{j} onto the scale line r")
                V = b.intersect(f"{tag}V{j}", speed.one.line, k, rule=("toward", speed.angle.vertex, None, 0.0, -1.0))
                Vg = carry_across(b, speed.angle, f"{tag}Vg{j}", V, speed.gain,
                                  de=f"auf die Maßlinie g·r: r + g·e{j}", en=f"onto the scale line g r: r + g e{j}")
                point = part.crank_points[(start + j) % m]
                ray = b.line(f"{tag}ray{j}", part.C, point, de=f"Kurbelstellung {j}", en=f"crank position {j}")
                kz = b.circle_segment(f"{tag}Z{j}.k", part.C, speed.gain.origin, Vg,
                                      de=f"Halbmesser r + g·e{j} um den Wellenmittelpunkt",
                                      en=f"radius r + g e{j} about the shaft centre")
                label = None
                if j % (n // 2) == 0:
                    label = "B" + _SUB[j // (n // 2) + 1]
                radii.append(b.intersect(f"{tag}Z{j}", ray, kz, rule=("toward", part.C, point),
                                         role="result", de=f"Geschwindigkeitspunkt {j}", en=f"speed point {j}",
                                         labels={f"{tag}Z{j}": label} if label else None))
        closed_curve(b, f"{tag}wave", radii, de="Wellenlinie der Geschwindigkeiten (Kurvenlineal)",
                     en="wave curve of the speeds (French curve)")
    return _Part(**{**part.__dict__, "radii": tuple(radii)})


def _kochanski(b: Builder, part: _Part, n: int) -> None:
    """π by Kochański's rectification; sin 2α = (4/π)² − 1 and the two extreme angles (§ 146)."""
    C, D0, D1, circle = part.C, part.D0, part.D1, part.circle
    top, bottom = part.crank_points[n // 2], part.crank_points[3 * n // 2]
    koch = Provenance("approximate", "Kochański's rectification (1685)", KOCHANSKI_ERROR)
    with b.group("half circle rectified (Kochański 1685)", "Halbkreis rektifiziert (Kochański 1685)"):
        d = b.line("K.d", bottom, top, de="senkrechter Durchmesser", en="vertical diameter")
        t = b.erect_perpendicular("K.t", top, d, bottom)
        k60 = b.circle_radius("K.k60", D0, "r", de="Kreis um den Totpunkt mit r", en="circle about the dead centre with r")
        E = b.intersect("K.E", k60, circle, rule=("left", D0, D1), de="Punkt bei 60°", en="the 60 degree point")
        g30 = b.line("K.g30", C, E, de="Strahl unter 30° zum Durchmesser", en="ray at 30 degrees to the diameter")
        start = b.intersect("K.C", g30, t, rule=("only",), de="auf der Tangente: r·tg 30°",
                            en="on the tangent: r tan 30 degrees")
        marks = [start]
        for i in (1, 2, 3):
            marks.append(b.step_off(f"K.{i}" if i < 3 else "K.D", t, marks[-1], "r", rule=("toward", C, None) + _FWD,
                                    de=f"r zum {i}. Mal abgetragen", en=f"r stepped off, {i} of 3"))
        b.set_label("K.D", "K")
        b.line("K.BD", bottom, "K.D", de="BK ≈ π·r (Kochański)", en="BK approximately pi r (Kochanski)", role="result")
        b.record("compass", "length_of", (bottom, "K.D"), ("BK",), {}, "Zirkel auf BK ≈ π·r",
                 "compass set to BK, approximately pi r", provenance=koch)
        b.length_of("2r", D0, D1, de="Zirkel auf den Hub 2r", en="compass set to the stroke 2r")
    with b.group("4/π and (4/π)² by fourth proportionals", "4/π und (4/π)² als vierte Proportionale"):
        o1, p1 = fourth_proportional(b, "K.t4", vertex=bottom, leg_point="K.D", a="BK", b_="2r", c="2r")
        b.length_of("4r/π", o1, p1, de="(4/π)·r = 2r·2r/(π r)", en="(4/pi) r = 2r 2r / (pi r)")
        o2, p2 = fourth_proportional(b, "K.u4", vertex=bottom, leg_point="K.D", a="r", b_="4r/π", c="4r/π")
        b.length_of("16r/π²", o2, p2, de="(4/π)²·r", en="(4/pi)^2 r")
    with b.group("sin 2α = (4/π)² − 1 and the extreme angles", "sin 2α = (4/π)² − 1 und die ausgezeichneten Winkel"):
        kh = b.circle_radius("K.kH", bottom, "16r/π²", de="(4/π)²·r vom tiefsten Punkt", en="(4/pi)^2 r from the lowest point")
        H = b.intersect("K.H", d, kh, rule=("toward", bottom, top), de="Höhe r·sin 2α über der Hubachse",
                        en="height r sin 2 alpha above the stroke line")
        hline = b.erect_perpendicular("K.h", H, d, bottom)
        b.intersect(("K.G1", "K.G2"), hline, circle, rule=("toward", C, D0), de="Punkte bei 2α₁ und 2α₂ = 180° − 2α₁",
                    en="points at 2 alpha1 and 2 alpha2 = 180 - 2 alpha1")
        err = kochanski_angle_error()
        angle_prov = Provenance("approximate", "Kochański's rectification (1685)", err)  # its error in the angle
        for i, (G, word) in enumerate((("K.G1", "kleinste"), ("K.G2", "größte")), start=1):
            name = f"K.M{i}"
            with b.group(f"arc {D0}{G} bisected: alpha{i}", f"Bogen {D0}{G} halbiert: α{i}"):
                ka = b.circle_through(b.fresh(f"{name}.k"), D0, G)
                kb = b.circle_through(b.fresh(f"{name}.k"), G, D0)
                s = b.intersect(b.fresh(f"{name}.S"), ka, kb, rule=("farther", C))
                w = b.line(b.fresh(f"{name}.w"), C, s)
                b.record("intersect", "intersect", (w, circle), (name,), {"rule": ("nearer", s), "both": False},
                         f"M{i}: α{i}, {word} Geschwindigkeit", f"M{i}: alpha{i}, the {'least' if i == 1 else 'greatest'} speed",
                         provenance=angle_prov, role="result")
    return None


def _label_extremes(b: Builder, part: _Part) -> None:
    """Rays to the extremes, lettered with the angles the construction gives (to the minute)."""
    with b.group("extremes marked", "ausgezeichnete Stellungen bezeichnet"):
        for i in (1, 2):
            name = f"K.M{i}"
            a = _angle_of(b[part.C], b[part.D0], b[name])
            minutes = round(math.degrees(a) * 60.0)
            ray = b.line(f"K.ray{i}", part.C, name, de=f"Strahl nach M{i}", en=f"ray to M{i}", role="result")
            b.intersect(f"K.W{i}", f"{part.tag}wave", ray, rule=("nearer", name), role="result",
                        de=f"M{i} auf der Wellenlinie: {'kleinste' if i == 1 else 'größte'} Geschwindigkeit",
                        en=f"M{i} on the wave curve: the {'least' if i == 1 else 'greatest'} speed",
                        labels={f"K.W{i}": f"M{_SUB[i]} {minutes // 60}°{minutes % 60}′"})


def _angle_of(o: Point, d0: Point, p: Point) -> float:
    """The angle from O-D0 to O-P, counter-clockwise as the crank turns over the top (0..2pi)."""
    ux, uy = d0[0] - o[0], d0[1] - o[1]
    vx, vy = p[0] - o[0], p[1] - o[1]
    # The crank turns clockwise in the y-up plane (from the left dead centre over the top).
    a = math.atan2(-(ux * vy - uy * vx), ux * vx + uy * vy)
    return a % (2.0 * math.pi)


def _scale_bar(b: Builder, at: tuple[float, float]) -> None:
    with b.group("speed scale", "Geschwindigkeitsmaßstab"):
        A = b.given_point("sc.A", at[0], at[1], unit="r", de="Maßstab", en="scale", label="0")
        line = b.given_line("sc.g", A, angle_deg=0.0, role="result", de="Maßstablinie", en="scale line")
        B = b.step_off("sc.B", line, A, "r", rule=("toward", A, None) + _FWD, de="r ≙ v₁", en="r stands for v1")
        b.set_label(B, "v₁")
        b.given_length("tenth", product=("magnify", "r"), factor=0.1, de="G·r/10 ≙ 0,1·v₁", en="G r / 10 stands for 0.1 v1")
        C = b.step_off("sc.C", line, B, "tenth", rule=("toward", A, None) + _FWD, de="0,1·v₁ vergrößert",
                       en="0.1 v1, magnified")
        b.set_label(C, "1,1 v₁")


def build_two_cranks(*, rod_ratio: float, infinite_rod: bool, parts: int, method: str, r: float,
                     fluctuation: float, magnify: float, dead_centre: str = "crank-end") -> Figure:
    infinite_rod = bool(infinite_rod)
    _start_angle(dead_centre)
    if magnify is None:
        magnify = auto_magnification(rod_ratio_param(rod_ratio),
                                     bounded("fluctuation Qr/((m1+m2) v1^2)", fluctuation, FLUCTUATION))
    givens = _givens(r, rod_ratio, fluctuation, magnify)
    _validate(givens)
    used = _check_parts(parts, method)
    n = parts
    b = Builder("two-cranks", givens, {"parts": n, "method": used, "requested_method": method,
                                       "infinite_rod": infinite_rod, "dead_centre": dead_centre})
    start = n if dead_centre == "crank-end" else 0
    f = build_frame(b)
    upper = divide_semicircle(b, O=f["O"], D0=f["D0"], D1=f["D1"], circle=f["circle"], axis=f["axis"], n=n,
                              method=used)
    lower = _mirror_points(b, "", f["O"], f["D0"], f["D1"], f["circle"], upper)
    if infinite_rod:
        feet = _ordinates(b, "", f["axis"], upper, lower)
        pts, pistons = _whole_circle(upper, lower, feet)
        parts_ = [_Part("", True, f["O"], f["D0"], f["D1"], f["circle"], pts, pistons)]
        inf = parts_[0]
        b.set_label(f["O"], "O (l = ∞)")
    else:
        rod_arcs(b, f, upper)
        pts, pistons = _whole_circle(upper, lower, [f["D0"]] + [f"X{k}" for k in range(1, n)] + [f["D1"]])
        fin = _Part("", False, f["O"], f["D0"], f["D1"], f["circle"], pts, pistons)
        with b.group("second crank circle for the infinite rod", "zweiter Kurbelkreis für unendliche Stange"):
            O2 = b.given_point("O'", 3.2, 0.0, unit="r", de="Wellenmittelpunkt O' (unendliche Stange)",
                               en="shaft centre O' (infinite rod)", label="O′ (l = ∞)")
            k2 = b.circle_radius("crank'", O2, f["r"], de="Kurbelkreis um O'", en="crank circle about O'", role="result")
            A2 = b.intersect("iD0", f["axis"], k2, rule=("toward", O2, None, -1.0, 0.0), labels={"iD0": "A′"})
            B2 = b.intersect("iD1", f["axis"], k2, rule=("toward", O2, None, 1.0, 0.0))
        up2, low2 = _copied_points(b, "i", O2, A2, B2, k2, upper, f["D0"], f["D1"])
        feet = _ordinates(b, "i", f["axis"], up2, low2)
        pts2, pistons2 = _whole_circle(up2, low2, feet)
        inf = _Part("i", True, O2, A2, B2, k2, pts2, pistons2)
        parts_ = [fin, inf]
    speed = _speed_angle(b, (-3.0, -3.3))
    with b.group("mean work per step: the stroke in N/2 parts", "mittlere Arbeit je Schritt: Hub in N/2 Teile"):
        if n // 2 >= 2:
            t1 = b.divide_segment("T", f["D0"], f["D1"], n // 2, line=f["axis"], only=[1])[0]
        else:
            t1 = f["D1"]
        b.length_of("mstep", f["D0"], t1, de="Zirkel auf 4r/N", en="compass set to 4r/N")
    built = []
    for i, part in enumerate(parts_):
        part = _work(b, part, speed, (-1.6, -1.6 - 0.5 * i), n, "mstep", start)
        built.append(_radii(b, part, speed, n, start))
    _kochanski(b, inf, n)
    _label_extremes(b, inf)
    _scale_bar(b, (-1.2 if infinite_rod else 2.0, -1.55 if infinite_rod else 1.55))
    for part in built:
        for j in range(2 * n + 1):
            if _ahead(b, part.means[j], part.ends[j]) <= 0.0:
                raise InvalidParameter(f"speed radius at crank position {j} would not be positive; "
                                       f"lower --magnify or the fluctuation")
    b.params["plate"] = _plate_patterns(infinite_rod, n)
    proto = b.protocol()
    return Figure(proto, proto.replay(givens))


def _ahead(b: Builder, a: str, c: str) -> float:
    """How far c lies ahead of a along the work line (drawn from left to right), read off the figure."""
    return b[c][0] - b[a][0]


def _plate_patterns(infinite_rod: bool, n: int = 0) -> list[str]:
    """Fig. 566: the crank circles, the crank positions, the speed points and the wave, the extremes.

    The rays along the stroke line (0 and n) are left to the plate's centre lines, one per diagram
    (:func:`two_cranks_plate`): drawn as rays they would run on across the gap between the diagrams.
    (The same patterns serve both layouts: names of the second circle simply do not occur without it.)
    """
    pats = [r"O", r"O'", r"crank", r"crank'", r"D0", r"D1", r"iD0", r"iD1", r"i?wave", r"i?Z\d+",
            rf"i?ray(?!(?:0|{n})$)\d+",
            r"K\.W[12]", r"K\.ray[12]", r"P\d+", r"iP\d+", r"i?Q\d+", r"sc\.[ABCg]"]
    return pats


def two_cranks_plate(fig: Figure) -> dict:
    """Fig. 566 as a plate: the speed curve heavy over a lighter crank circle (the reference of the
    mean speed), the stroke line and the vertical through each shaft centre dash-dotted as centre lines,
    each ending at its own diagram -- none runs across the gap between the two.

    Every position is a constructed point.
    """
    R = fig.replay
    n = fig.params["parts"]
    r = R["O"].distance(R["D1"])
    furniture = []
    looks = {"crank": "medium", "crank'": "medium", "wave": "heavy", "iwave": "heavy"}
    for centre, pre in (("O", ""), ("O'", "i")):
        if centre not in R:
            continue
        C = R[centre]
        furniture.append({"kind": "stroke", "a": (C[0] - 1.22 * r, C[1]), "b": (C[0] + 1.22 * r, C[1]),
                          "look": "centre"})
        for j in (n // 2, 3 * n // 2):
            looks[f"{pre}ray{j}"] = "centre"
    return {"looks": looks, "furniture": furniture}


# -- measurements on the figure ------------------------------------------------------


def crank_angle(fig: Figure, point: str, centre: str | None = None, d0: str | None = None) -> float:
    """The angle of a crank point from its circle's head-end dead centre, 0..2pi in the sense of rotation."""
    if centre is None:
        centre, d0 = ("O'", "iD0") if point.startswith("i") or (point.startswith("K.") and "O'" in fig.replay) \
            else ("O", "D0")
    return _angle_of(fig.replay[centre], fig.replay[d0], fig.replay[point])


def _prefix(fig: Figure, infinite: bool | None) -> str:
    """Object prefix of a diagram: None is the one about O (the figure's own rod), True the infinite rod."""
    if infinite is None:
        return ""
    if infinite and not fig.params["infinite_rod"]:
        return "i"
    if not infinite and fig.params["infinite_rod"]:
        raise InvalidParameter("this figure has the infinite rod only")
    return ""


def work_excess(fig: Figure, j: int, *, infinite: bool | None = None) -> float:
    """e at crank position j in units of Q·r, read off the work line: (M_j E_j − M_0 W_0) / r."""
    t = _prefix(fig, infinite)
    rp = fig.replay
    m0, w0, mj, ej = rp[f"{t}M0"], rp[f"{t}W0"], rp[f"{t}M{j}"], rp[f"{t}E{j}"] if j else rp[f"{t}W0"]
    return ((ej[0] - mj[0]) - (w0[0] - m0[0])) / fig.replay.givens["r"]


def speed_radius(fig: Figure, j: int, *, infinite: bool | None = None) -> float:
    """The drawn radius of speed point j over the crank radius: v/v1 by the book's law, deviation magnified G times."""
    t = _prefix(fig, infinite)
    centre = "O'" if t == "i" else "O"
    return fig.replay[centre].distance(fig.replay[f"{t}Z{j % (2 * fig.params['parts'])}"]) / fig.replay.givens["r"]


def dead_centre_of(fig: Figure) -> str:
    """The dead centre the figure's first crank starts from (a protocol from before the option: the head end)."""
    return str(fig.params.get("dead_centre", "head-end"))


def piston_speed_factor(w: float, rod_ratio: float | None) -> float:
    """c/v: the piston's speed over the crank-pin speed at crank angle *w* (exact law; None: infinite rod).

    >>> round(piston_speed_factor(math.pi / 2, 5.0), 12), round(piston_speed_factor(math.pi / 4, 4.0), 6)
    (1.0, 0.834107)
    """
    s, c = math.sin(w), math.cos(w)
    if rod_ratio is None:
        return s
    return s + s * c / math.sqrt(rod_ratio * rod_ratio - s * s)


def speeds(fig: Figure, *, infinite: bool | None = None, crosshead_share: float = 0.0) -> list[dict[str, float]]:
    """v/v1 at each crank position from the constructed excess work, with the book's simplifications and without.

    * ``v_book``  = 1 + k·e: § 146's "für große Massen" (linear in e);
    * ``v_exact`` = sqrt(1 + 2k·e): (m1 + m2)(v² − v1²)/2 = Q·r·e, the book's energy balance;
    * ``v_full``  drops the book's other simplification too (§ 146: "Bei der Kleinheit von m2 gegen m1
      und von r gegen l ..."): each crosshead (mass m2) moves at c = v·c/v(α), so
      v²(m1 + m2·S(α)) = v1²(m1 + m2·S(0)) + 2Q·r·e with S = (c1/v)² + (c2/v)², exact piston law.
      *crosshead_share* is m2/(m1 + m2); with 0, or for the infinite rod (S = 1), v_full = v_exact.

    k = Qr/((m1 + m2)v1²) is the figure's ``fluctuation``.
    """
    k = fig.replay.givens["fluctuation"]
    mu = float(crosshead_share)
    if not 0.0 <= mu < 1.0:
        raise InvalidParameter(f"crosshead share m2/(m1 + m2) must be in [0, 1), got {crosshead_share!r}")
    n = fig.params["parts"]
    t = _prefix(fig, infinite)
    ratio = None if (t == "i" or fig.params["infinite_rod"]) else fig.replay.givens["rod_ratio"]

    def S(a: float) -> float:
        return piston_speed_factor(a, ratio) ** 2 + piston_speed_factor(a + 0.5 * math.pi, ratio) ** 2

    out = []
    a0 = _start_angle(dead_centre_of(fig))
    for j in range(2 * n + 1):
        e = work_excess(fig, j, infinite=infinite)
        a = a0 + math.pi * j / n
        full = ((1.0 - mu) + mu * S(a0) + 2.0 * k * e) / ((1.0 - mu) + mu * S(a))
        out.append({"index": j, "crank_angle_deg": 180.0 * j / n, "work_excess": e, "v_book": 1.0 + k * e,
                    "v_exact": math.sqrt(1.0 + 2.0 * k * e) if 1.0 + 2.0 * k * e >= 0.0 else math.nan,
                    "v_full": math.sqrt(full) if full >= 0.0 else math.nan})
    return out


# -- checks ----------------------------------------------------------------------------


def two_cranks_checks(fig: Figure, model: Mapping[str, Any] | None = None) -> list[Check]:
    """The checks of a two-cranks figure; *model*: ``{"extremes": quadrant_extremes(rod ratio)}``, if known."""
    n = fig.params["parts"]
    dc = dead_centre_of(fig)
    g = fig.replay.givens
    K = g["rod_ratio"]
    gain = g["magnify"] * g["fluctuation"]
    made_by = fig.replay.made_by()
    checks: list[Check] = []
    kinds = [(True, None)] if fig.params["infinite_rod"] else [(False, K), (True, None)]
    for infinite, ratio in kinds:
        word = "infinite rod" if infinite else f"L/r = {K:g}"
        # The division's error moves a crank point; |de/dalpha| <= 2(1 + lam) + 4/pi.
        slope = 2.0 * (1.0 + (0.0 if ratio is None else 1.0 / ratio)) + 4.0 / math.pi
        err_w = max(angle_tolerance(fig, p, made_by)[0] for p in made_by if p.startswith("P") and p[1:].isdigit()) \
            if n > 1 else EUCLIDEAN_TOLERANCE
        # 4N compass transfers along the work line, each rounding at ~1e-16 of its 8r length.
        tol = max(EUCLIDEAN_TOLERANCE, 4e-15 * n) + slope * max(err_w - EUCLIDEAN_TOLERANCE, 0.0)
        why = ("Euclidean chain: rod arcs / ordinates, compass steps on the work line" if tol < 1e-10 else
               f"division of the circle not Euclidean ({fig.params['method']}): its angle error times |de/dalpha|")
        for j in range(2 * n + 1):
            alpha = math.pi * j / n
            e = work_excess(fig, j, infinite=infinite)
            checks.append(Check(f"work excess {j} ({word}, from the {dc} dead centre)", e,
                                excess_from(alpha, ratio, dc), tol, why, "Q r"))
            if j < 2 * n:
                checks.append(Check(f"speed radius {j} ({word})", speed_radius(fig, j, infinite=infinite),
                                    1.0 + gain * excess_from(alpha, ratio, dc), (1.0 + gain) * tol,
                                    "proportional angle and compass: the work excess times g, Euclidean", "r"))
        if infinite and n % 4 == 0:
            for j in range(0, 2 * n, n // 4):
                checks.append(Check(f"v = v1 at {180 * j // n} deg (infinite rod, § 146)",
                                    work_excess(fig, j, infinite=True), 0.0, tol,
                                    "the book: the same speed v1 every 45 degrees", "Q r"))
        if infinite:
            # The book's claim: v_max exceeds v1 as much as v_min falls short; the construction's wave
            # is antisymmetric about 45 degrees in every quadrant.
            for j in range(1, n // 2):
                checks.append(Check(f"e({180 * j / n:g}) + e({90 - 180 * j / n:g}) = 0 (infinite rod)",
                                    work_excess(fig, j, infinite=True) + work_excess(fig, n // 2 - j, infinite=True),
                                    0.0, 2 * tol, "§ 146: v_max - v1 = v1 - v_min; e(90 - a) = -e(a)", "Q r"))
        else:
            for q in (quadrant_extremes(ratio, dead_centre=dc) if model is None else model["extremes"]):
                # The grid's own rise and fall in each quadrant, against the exact law on the same grid.
                lo, hi = (q["quadrant"] - 1) * n // 2, q["quadrant"] * n // 2
                es = [work_excess(fig, j) for j in range(lo, hi + 1)]
                ex = [excess_from(math.pi * j / n, ratio, dc) for j in range(lo, hi + 1)]
                measured = (max(es) - es[0]) - (es[0] - min(es))
                checks.append(Check(f"quadrant {q['quadrant']}: rise - fall of e ({word})", measured,
                                    (max(ex) - ex[0]) - (ex[0] - min(ex)), 2 * tol,
                                    f"§ 147: the quadrants differ; exact law: rise {q['rise']:.5f}, "
                                    f"fall {q['fall']:.5f} Q r", "Q r"))
    checks += _extreme_checks(fig)
    return checks


def _extreme_checks(fig: Figure) -> list[Check]:
    rp = fig.replay
    r = rp.givens["r"]
    centre = "O'" if "O'" in rp else "O"
    koch = KOCHANSKI_ERROR
    rho = float(rp["BK"]) / r
    a1x, a2x = extreme_angles_exact()
    err = kochanski_angle_error()
    s2 = (16.0 / KOCHANSKI_RHO ** 2 - 1.0) - ((4.0 / math.pi) ** 2 - 1.0)
    a1 = crank_angle(fig, "K.M1")
    a2 = crank_angle(fig, "K.M2")
    height = (rp["K.G1"][1] - rp[centre][1]) / r
    out = [
        Check("Kochanski: BK / r against pi", rho, math.pi, 1.001 * koch + EUCLIDEAN_TOLERANCE,
              f"Kochański's rectification falls short of pi r by {koch:.3e} r", "r"),
        Check("(4/pi) r constructed", float(rp["4r/π"]) / r, 4.0 / math.pi,
              1.001 * abs(4.0 / KOCHANSKI_RHO - 4.0 / math.pi) + EUCLIDEAN_TOLERANCE,
              "Kochański's error carried: 4/BK - 4/pi", "r"),
        Check("sin 2 alpha = (4/pi)^2 - 1 constructed", height, (4.0 / math.pi) ** 2 - 1.0,
              1.001 * abs(s2) + EUCLIDEAN_TOLERANCE, f"Kochański's error carried: {s2:.3e}", ""),
        Check("extreme angle alpha1 (constructed, deg)", math.degrees(a1), math.degrees(a1x),
              math.degrees(1.001 * err + EUCLIDEAN_TOLERANCE),
              f"Kochański's error carried into the angle: {math.degrees(err) * 3600:.1f}\" ({err:.2e} rad)", "deg"),
        Check("extreme angle alpha2 (constructed, deg)", math.degrees(a2), math.degrees(a2x),
              math.degrees(1.001 * err + EUCLIDEAN_TOLERANCE),
              f"Kochański's error carried into the angle: {math.degrees(err) * 3600:.1f}\" ({err:.2e} rad)", "deg"),
        *_wave_checks(fig, centre),
        Check("alpha1 against the book's 19 deg 12'", math.degrees(a1), 19.2, 0.5 / 60.0,
              "printed to the minute: half a minute", "deg"),
        Check("alpha2 against the book's 70 deg 48'", math.degrees(a2), 70.8, 0.5 / 60.0,
              "printed to the minute: half a minute", "deg"),
    ]
    return out


def _wave_checks(fig: Figure, centre: str) -> list[Check]:
    """v_min and v_max read off the drawn wave where the rays to the extremes cross it."""
    rp = fig.replay
    g = rp.givens
    gain = g["magnify"] * g["fluctuation"]
    n = fig.params["parts"]
    amplitude = gain * -excess_exact(extreme_angles_exact()[0], None)
    tol = amplitude * (6.0 / n) ** 3
    out = []
    for i, word in ((1, "v_min"), (2, "v_max")):
        a = extreme_angles_exact()[i - 1]
        out.append(Check(f"{word} / v1 read off the wave at M{i} (infinite rod, drawn radius)",
                         rp[centre].distance(rp[f"K.W{i}"]) / g["r"], 1.0 + gain * excess_exact(a, None), tol,
                         f"a French curve through points {180 / n:g} deg apart: within (6/N)^3 of the wave's "
                         f"amplitude {amplitude:.4f} r (the radius is 1 + G k e, the book's law magnified)", "r"))
    return out


# -- the table ----------------------------------------------------------------------------


def speed_fluctuation_rows(*, rod_ratio: float | None, step_deg: float = 15.0,
                           dead_centre: str = "crank-end") -> list[dict[str, Any]]:
    """e(α) in units of Q·r over 0…360° from the given dead centre (§ 146's B1 by default), off the work line.

    >>> rows = speed_fluctuation_rows(rod_ratio=None, step_deg=45.0)
    >>> [row["crank_angle_deg"] for row in rows if abs(row["work_excess"]) < 1e-12]   # v = v1 every 45 degrees
    [0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0, 360.0]
    """
    step = positive("angle step", step_deg)
    n = round(180.0 / step)
    if n > MAX_PARTS:  # said before the construction would complain of "parts" the caller did not give
        raise InvalidParameter(f"the angle step must be at least {180 / MAX_PARTS:g} degrees (180/step parts of "
                               f"the semicircle, at most {MAX_PARTS}), got {step_deg!r}")
    if n < 2 or n % 2 or abs(n * step - 180.0) > 1e-9:
        raise InvalidParameter(f"the angle step must divide 90 degrees, got {step_deg!r}")
    if rod_ratio is None:
        fig = TWO_CRANKS.figure(parts=n, infinite_rod=True, dead_centre=dead_centre)
    else:
        fig = TWO_CRANKS.figure(parts=n, rod_ratio=rod_ratio, dead_centre=dead_centre)
    return [{"crank_angle_deg": 180.0 * j / n, "work_excess": work_excess(fig, j, infinite=rod_ratio is None)}
            for j in range(2 * n + 1)]


TWO_CRANKS = register(Construction(
    name="two-cranks",
    title=Caption("Zwei Kurbeln unter 90°: Geschwindigkeitsschwankung",
                  "Two cranks at 90°: speed fluctuation"),
    source="seed 002, § 146-147, Fig. 566",
    build=build_two_cranks,
    checks=two_cranks_checks,
    validates_sweeps=True,
    sweep_model=lambda g, params: {} if params["infinite_rod"] else {
        "extremes": quadrant_extremes(g["rod_ratio"], dead_centre=params.get("dead_centre", "head-end"))},
    defaults={"rod_ratio": 5.0, "infinite_rod": False, "parts": 12, "method": "auto", "r": 1.0,
              "fluctuation": 0.25, "magnify": None, "dead_centre": "crank-end"},
    book_params=({"rod_ratio": 5.0, "parts": 12}, {"infinite_rod": True, "parts": 12}),
    structural=("parts", "method", "infinite_rod", "dead_centre"),
    extra={"plate": two_cranks_plate,
           "help": {"dead_centre": "where the first crank starts: crank-end (§ 146's B1, the default: upper sign "
                                   "in the Hingang) or head-end (the other books' zero)"}},
    # A draftsman picks the magnification of the speed deviations for the rod he draws: so does a sweep.
    sweep=lambda g, ratios: {**g, "rod_ratio": ratios,
                             "magnify": auto_magnification(ratios, g["fluctuation"])},
), validate=_validate)
