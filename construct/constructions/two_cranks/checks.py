"""The checks of two cranks at 90°: the constructed work, speeds and extremes against the exact law."""

from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from ..checking import EUCLIDEAN_TOLERANCE, Check
from .. import Figure
from ..crank import angle_tolerance
from .analytic import (KOCHANSKI_ERROR, KOCHANSKI_RHO, excess_exact, excess_from, extreme_angles_exact,
                       kochanski_angle_error, quadrant_extremes)
from .build import angle_at
from .measure import crank_angle, dead_centre_of, sense_of, speed_radius, work_excess

def two_cranks_checks(fig: Figure, model: Mapping[str, Any] | None = None) -> list[Check]:
    """The checks of a two-cranks figure; *model*: ``{"extremes": quadrant_extremes(rod ratio)}``, if known."""
    n = fig.params["parts"]
    dc = dead_centre_of(fig)
    g = fig.replay.givens
    K = g["rod_ratio"]
    gain = g["magnify"] * g["fluctuation"]
    sense = sense_of(fig)
    pm = "+" if sense > 0 else "-"
    made_by = fig.replay.made_by()
    if model is None and not fig.params["infinite_rod"]:  # the exact law's extremes, asked by two kinds of check
        model = {"extremes": quadrant_extremes(K, dead_centre=dc)}
    checks: list[Check] = []
    kinds = [(True, None)] if fig.params["infinite_rod"] else [(False, K), (True, None)]
    # how far the division may put a crank point off its angle (both diagrams share the division)
    err_w = max(angle_tolerance(fig, p, made_by)[0] for p in made_by if p.startswith("P") and p[1:].isdigit()) \
        if n > 1 else EUCLIDEAN_TOLERANCE
    for infinite, ratio in kinds:
        word = "infinite rod" if infinite else f"L/r = {K:g}"
        # The division's error moves a crank point; |de/dalpha| <= 2(1 + lam) + 4/pi.
        slope = 2.0 * (1.0 + (0.0 if ratio is None else 1.0 / ratio)) + 4.0 / math.pi
        # 4N compass transfers along the work line, each rounding at ~1e-16 of its 8r length.
        tol = max(EUCLIDEAN_TOLERANCE, 4e-15 * n) + slope * max(err_w - EUCLIDEAN_TOLERANCE, 0.0)
        why = ("Euclidean chain: rod arcs / ordinates, compass steps on the work line" if tol < 1e-10 else
               f"division of the circle not Euclidean ({fig.params['method']}): its angle error times |de/dalpha|")
        # e at every point of the division: read off the work line, and by the exact law (one numpy pass)
        measured_e = [work_excess(fig, j, infinite=infinite) for j in range(2 * n + 1)]
        exact_e = excess_from(math.pi * np.arange(2 * n + 1) / n, ratio, dc).tolist()
        for j in range(2 * n + 1):
            checks.append(Check(f"work excess {j} ({word}, from the {dc} dead centre)", measured_e[j],
                                exact_e[j], tol, why, "Q r"))
            if j < 2 * n:
                checks.append(Check(f"speed radius {j} ({word})", speed_radius(fig, j, infinite=infinite),
                                    1.0 + sense * gain * exact_e[j], (1.0 + gain) * tol,
                                    f"proportional angle and compass: r {pm} g e, Euclidean", "r"))
        if infinite and n % 4 == 0:
            for j in range(0, 2 * n, n // 4):
                checks.append(Check(f"v = v1 at {180 * j // n} deg (infinite rod, § 146)",
                                    measured_e[j], 0.0, tol,
                                    "the book: the same speed v1 every 45 degrees", "Q r"))
        if infinite:
            # The book's claim: v_max exceeds v1 as much as v_min falls short; the construction's wave
            # is antisymmetric about 45 degrees in every quadrant.
            for j in range(1, n // 2):
                checks.append(Check(f"e({180 * j / n:g}) + e({90 - 180 * j / n:g}) = 0 (infinite rod)",
                                    measured_e[j] + measured_e[n // 2 - j],
                                    0.0, 2 * tol, "§ 146: v_max - v1 = v1 - v_min; e(90 - a) = -e(a)", "Q r"))
        else:
            for q in model["extremes"]:
                # The grid's own rise and fall in each quadrant, against the exact law on the same grid.
                lo, hi = (q["quadrant"] - 1) * n // 2, q["quadrant"] * n // 2
                es, ex = measured_e[lo:hi + 1], exact_e[lo:hi + 1]
                measured = (max(es) - es[0]) - (es[0] - min(es))
                checks.append(Check(f"quadrant {q['quadrant']}: rise - fall of e ({word})", measured,
                                    (max(ex) - ex[0]) - (ex[0] - min(ex)), 2 * tol,
                                    f"§ 147: the quadrants differ; exact law: rise {q['rise']:.5f}, "
                                    f"fall {q['fall']:.5f} Q r", "Q r"))
            checks += _finite_wave_checks(fig, ratio, dc, sense, model)
    checks += _extreme_checks(fig)
    return checks


#: How much beyond the approximation's own error (its formula, worked out before anything is measured) a check
#: against the exact value allows: a construction that strays by half that error again fails.
METHOD_MARGIN = 1.5


def _extreme_checks(fig: Figure) -> list[Check]:
    """The extremes through Kochański's π: each quantity against Kochański's own value (float chain) and against
    the exact value within 1.5 times what his rectification's error formula carries into it."""
    rp = fig.replay
    r = rp.givens["r"]
    centre = "O'" if "O'" in rp else "O"
    koch = KOCHANSKI_ERROR
    rho = float(rp["BK"]) / r
    a1x, a2x = extreme_angles_exact()
    err = kochanski_angle_error()
    s2 = (16.0 / KOCHANSKI_RHO ** 2 - 1.0) - ((4.0 / math.pi) ** 2 - 1.0)
    a1k = 0.5 * math.asin(16.0 / KOCHANSKI_RHO ** 2 - 1.0)   # what the construction must give with his π
    a1 = crank_angle(fig, "K.M1")
    a2 = crank_angle(fig, "K.M2")
    height = (rp["K.G1"][1] - rp[centre][1]) / r
    m = METHOD_MARGIN
    koch_why = (f"Kochański's rectification falls short of pi r by pi - sqrt(40/3 - 2 sqrt 3) = {koch:.3e} r; "
                f"tolerance {m:g} times that")
    angle_why = (f"Kochański's error carried into the angle: {math.degrees(err) * 3600:.1f}\" ({err:.2e} rad); "
                 f"tolerance {m:g} times that")
    # the float chain: 1e-12 r on BK, the angles by the slope of asin at sin 2a = 0.62 (1/(2 cos 2a) < 1)
    out = [
        Check("Kochanski: BK / r (his construction)", rho, KOCHANSKI_RHO, EUCLIDEAN_TOLERANCE,
              "Euclidean: sqrt(4 + (3 - tan 30°)²)", "r"),
        Check("Kochanski: BK / r against pi", rho, math.pi, m * koch + EUCLIDEAN_TOLERANCE, koch_why, "r"),
        Check("(4/pi) r constructed (with his pi)", float(rp["4r/π"]) / r, 4.0 / KOCHANSKI_RHO, 10 * EUCLIDEAN_TOLERANCE,
              "Euclidean: the fourth proportional to BK, 4r and r", "r"),
        Check("(4/pi) r constructed", float(rp["4r/π"]) / r, 4.0 / math.pi,
              m * abs(4.0 / KOCHANSKI_RHO - 4.0 / math.pi) + EUCLIDEAN_TOLERANCE,
              f"Kochański's error carried: 4/BK - 4/pi; tolerance {m:g} times that", "r"),
        Check("sin 2 alpha = (4/pi)^2 - 1 constructed (with his pi)", height, 16.0 / KOCHANSKI_RHO ** 2 - 1.0,
              10 * EUCLIDEAN_TOLERANCE, "Euclidean: the height in the crank circle", ""),
        Check("sin 2 alpha = (4/pi)^2 - 1 constructed", height, (4.0 / math.pi) ** 2 - 1.0,
              m * abs(s2) + EUCLIDEAN_TOLERANCE, f"Kochański's error carried: {s2:.3e}; tolerance {m:g} times that", ""),
        Check("extreme angle alpha1 (with his pi, deg)", math.degrees(a1), math.degrees(a1k),
              math.degrees(10 * EUCLIDEAN_TOLERANCE), "Euclidean: the arc bisected", "deg"),
        Check("extreme angle alpha2 (with his pi, deg)", math.degrees(a2), 90.0 - math.degrees(a1k),
              math.degrees(10 * EUCLIDEAN_TOLERANCE), "Euclidean: the arc bisected", "deg"),
        Check("extreme angle alpha1 (constructed, deg)", math.degrees(a1), math.degrees(a1x),
              math.degrees(m * err + EUCLIDEAN_TOLERANCE), angle_why, "deg"),
        Check("extreme angle alpha2 (constructed, deg)", math.degrees(a2), math.degrees(a2x),
              math.degrees(m * err + EUCLIDEAN_TOLERANCE), angle_why, "deg"),
        *_wave_checks(fig, centre),
        Check("alpha1 against the book's 19 deg 12'", math.degrees(a1), 19.2, 0.5 / 60.0,
              "printed to the minute: half a minute", "deg"),
        Check("alpha2 against the book's 70 deg 48'", math.degrees(a2), 70.8, 0.5 / 60.0,
              "printed to the minute: half a minute", "deg"),
    ]
    return out


def _wave_checks(fig: Figure, centre: str) -> list[Check]:
    """v_min and v_max read off the drawn wave where the rays to the extremes cross it (for pumps the other
    way round: § 146, "das Gegentheil")."""
    rp = fig.replay
    g = rp.givens
    gain = g["magnify"] * g["fluctuation"]
    sense = sense_of(fig)
    n = fig.params["parts"]
    amplitude = gain * -excess_exact(extreme_angles_exact()[0], None)
    tol = amplitude * (6.0 / n) ** 3
    out = []
    for i in (1, 2):
        word = "v_min" if (i == 1) == (sense > 0) else "v_max"
        a = extreme_angles_exact()[i - 1]
        out.append(Check(f"{word} / v1 read off the wave at M{i} (infinite rod, drawn radius)",
                         rp[centre].distance(rp[f"K.W{i}"]) / g["r"], 1.0 + sense * gain * excess_exact(a, None), tol,
                         f"a French curve through points {180 / n:g} deg apart: within (6/N)^3 of the wave's "
                         f"amplitude {amplitude:.4f} r (the radius is 1 {'+' if sense > 0 else '-'} G k e, the "
                         f"book's law magnified)", "r"))
    return out


def _extremes_of(points, O, D0, r: float, gain: float, start: float, samples: int,
                 within: tuple[float, float] | None) -> dict[str, float]:
    """The least and greatest radius about O of the closed French curve through *points* (between the angles
    *within* from the first dead centre, if given): the radii, the angles and e read off them (a draftsman's
    circles about O touching the curve)."""
    from ...kernel.closed_curves import closed_french_curve_op
    from ...kernel.geometry import SCALAR

    curve, = closed_french_curve_op(tuple(points), {"points": len(points)}, {}, (), SCALAR)
    # the curve's points as (x, y) floats (curve_points' numbers, without a Point each: a sweep's checks read
    # 1,500 of them at every value)
    xs, ys = curve.sample(samples)
    turn = 2.0 * math.pi
    if within is not None:
        lo_a, hi_a = within
        keep = [lo_a - 1e-12 <= a <= hi_a + 1e-12 or (hi_a >= turn - 1e-12 and a < 1e-12)
                for a in ((angle_at(O, D0, p) - start) % turn for p in zip(xs.tolist(), ys.tolist()))]
        xs, ys = xs[keep], ys[keep]
    # O.distance(p) / r for every point (math.hypot, as Point.distance: numpy's hypot differs in the last bit)
    radii = np.fromiter(map(math.hypot, (xs - O.x).tolist(), (ys - O.y).tolist()), float, xs.size) / r
    lo, hi = int(radii.argmin()), int(radii.argmax())
    out = {"v_min": float(radii[lo]), "v_max": float(radii[hi])}
    # the least e sits at the least radius when the rods drive, at the greatest when the shaft drives pumps
    at_min, at_max = (lo, hi) if gain > 0 else (hi, lo)
    out["e_min"], out["e_max"] = (float(radii[at_min]) - 1.0) / gain, (float(radii[at_max]) - 1.0) / gain
    out["alpha_min"] = (angle_at(O, D0, (float(xs[at_min]), float(ys[at_min]))) - start) % turn
    out["alpha_max"] = (angle_at(O, D0, (float(xs[at_max]), float(ys[at_max]))) - start) % turn
    return out


def wave_extremes(fig: Figure, *, samples: int = 64, exact: bool = False,
                  within: tuple[float, float] | None = None) -> dict[str, float]:
    """The least and greatest speed of the finite rod's drawn wave, as a draftsman finds them: the circles about
    O that touch the curve from inside and outside (the curve sampled *samples* times between its points).

    Returns ``v_min``, ``v_max`` (the drawn radius over r: v/v1 with the deviations magnified G times),
    ``e_min``, ``e_max`` (Q r) and their angles ``alpha_min``, ``alpha_max`` (radians from the figure's
    first dead centre).  With *exact*, the same French curve through the exact law's speed points instead of
    the constructed ones: the method's own error, before anything is measured.  *within* (radians from the
    first dead centre, e.g. a quadrant) limits the search to that part of the turn.
    """
    from ...kernel.geometry import Point

    rp = fig.replay
    g = rp.givens
    gain = g["magnify"] * g["fluctuation"] * sense_of(fig)
    O, D0 = rp["O"], rp["D0"]
    dc = dead_centre_of(fig)
    start = math.pi if dc == "crank-end" else 0.0
    n = fig.params["parts"]
    if exact:   # the crank turns from the head-end dead centre D0 (left of O) over the top
        angles = math.pi * np.arange(2 * n) / n
        radii = g["r"] * (1.0 + gain * excess_from(angles, None if fig.params["infinite_rod"] else g["rod_ratio"], dc))
        pts = [Point(O.x - rad * math.cos(start + a), O.y + rad * math.sin(start + a))
               for a, rad in zip(angles.tolist(), radii.tolist())]
    else:
        pts = [rp[f"Z{j}"] for j in range(2 * n)]
    return _extremes_of(pts, O, D0, g["r"], gain, start, samples, within)


def _finite_wave_checks(fig: Figure, ratio: float, dc: str, sense: float, model: Mapping[str, Any]) -> list[Check]:
    """§ 147: the finite rod's least and greatest speed over the turn, read off its drawn wave.

    The tolerance is the method's own error worked out before anything is measured: the same French curve
    through the exact law's speed points, its extremes against the exact ones, twice that (and the float
    chain's 1e-9).
    """
    if fig.params.get("infinite_rod"):
        return []
    n = fig.params["parts"]
    qs = model["extremes"]
    low = min(qs, key=lambda q: q["e_min"])
    high = max(qs, key=lambda q: q["e_max"])
    drawn, on_exact = wave_extremes(fig), wave_extremes(fig, exact=True)
    why = (f"a French curve through points {180 / n:g} deg apart: twice what the same curve through the exact "
           f"speed points misses by")
    out = []
    for key, q in (("min", low), ("max", high)):
        speed = "least" if (key == "min") == (sense > 0) else "greatest"
        tol = 2.0 * abs(on_exact[f"e_{key}"] - q[f"e_{key}"]) + 1e-9
        out.append(Check(f"e_{key} over the turn, read off the wave (L/r = {ratio:g}, the {speed} speed)",
                         drawn[f"e_{key}"], q[f"e_{key}"], tol, why, "Q r"))
        a = q[f"alpha_{key}"]
        miss = abs((on_exact[f"alpha_{key}"] - a + math.pi) % (2.0 * math.pi) - math.pi)
        out.append(Check(f"angle of e_{key} from the {dc} dead centre (L/r = {ratio:g}, read off the wave, deg)",
                         math.degrees(a + (drawn[f"alpha_{key}"] - a + math.pi) % (2.0 * math.pi) - math.pi),
                         math.degrees(a), math.degrees(2.0 * miss + 1e-9), why, "deg"))
    swing = high["e_max"] - low["e_min"]
    out.append(Check(f"swing e_max - e_min over the turn (L/r = {ratio:g}, read off the wave)",
                     drawn["e_max"] - drawn["e_min"], swing,
                     2.0 * abs(on_exact["e_max"] - on_exact["e_min"] - swing) + 1e-9,
                     why + "; the degree of irregularity is k times the swing", "Q r"))
    return out
