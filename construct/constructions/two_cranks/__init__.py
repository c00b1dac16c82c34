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

>>> import math
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

from typing import Any

from ...kernel.division import MAX_PARTS
from ...kernel.division import NAMES as DIVISION_NAMES
from ...kernel.errors import InvalidParameter
from ...kernel.protocol import Caption
from .. import Construction, Figure, positive, register
from ..phrases import MECHANICS, Cite, number, ratio
from .analytic import (DEAD_CENTRES, DRIVES, KOCHANSKI_ERROR, KOCHANSKI_RHO, drive_sign, excess_exact,
                       excess_exact_array, excess_from,
                       extreme_angles_exact, kochanski_angle_error, max_magnification, piston_speed_factor,
                       piston_travel, quadrant_extremes)
from .build import (auto_magnification, build_two_cranks, closed_curve, derived_givens, two_cranks_plate,
                    validate_two_cranks)
from .checks import two_cranks_checks, wave_extremes
from .measure import crank_angle, dead_centre_of, sense_of, speed_radius, speeds, work_excess

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
    "excess_exact_array",
    "closed_curve",
    "dead_centre_of",
    "validate_two_cranks",
    "wave_extremes",
    "sense_of",
    "DRIVES",
    "drive_sign",
    "speed_extremes_rows",
]


#: Where the first crank starts, named (the parameter dead_centre): § 146's B₁ or the other books' zero.
START = {
    "crank-end": Caption("ab der äußeren Totlage B₁ (§ 146)", "from the crank-end dead centre B₁ (§ 146)"),
    "head-end": Caption("ab der deckelseitigen Totlage", "from the head-end dead centre"),
}

#: Who drives whom (§ 146): the rods the shaft, or the shaft pumps ("das Gegentheil").
DRIVEN = {
    "engine": Caption("Antrieb durch die Kolbenstangen", "driven by the piston rods"),
    "pump": Caption("Pumpenantrieb: die Welle treibt die Stangen", "pumps: the shaft drives the rods"),
}


def two_cranks_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as § 146 writes them: the rods (r/l), where the first crank starts, Qr/((m₁ + m₂)v₁²), the
    magnification of the speed deviations, the circle's division."""
    g = fig.replay.givens
    de = lang == "de"
    rod = (("unendlich lange Schubstangen" if de else "infinitely long rods") if fig.params.get("infinite_rod")
           else ratio("r/l", g["rod_ratio"], lang))
    n = fig.params.get("parts")
    start = START["crank-end" if fig.params.get("dead_centre", "head-end") == "crank-end" else "head-end"]
    pump = [DRIVEN["pump"].de if de else DRIVEN["pump"].en] if g.get("sense", 1.0) < 0 else []
    return [rod, start.de if de else start.en, *pump, f"Qr/((m₁ + m₂)v₁²) = {number(g['fluctuation'], lang)}",
            (f"Schwankungen {number(g['magnify'], lang)}fach vergrößert" if de
             else f"speed deviations magnified {number(g['magnify'], lang)} times"),
            f"Kreis in {2 * int(n)} Teilen" if de else f"circle in {2 * int(n)} parts"]


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
              "fluctuation": 0.25, "magnify": None, "dead_centre": "crank-end", "drive": "engine"},
    book_params=({"rod_ratio": 5.0, "parts": 12}, {"infinite_rod": True, "parts": 12}),
    structural=("parts", "method", "infinite_rod", "dead_centre", "drive"),
    steady=("rod_ratio",),  # (a scan of 120 fresh builds over the rod finds one form at each book figure)
    cites=(Cite(MECHANICS, "Fig. 566"),),
    wording=two_cranks_wording,
    methods=DIVISION_NAMES,
    conventions={"dead_centre": START, "drive": DRIVEN},
    plate=two_cranks_plate,
    validator=validate_two_cranks,
    derived=derived_givens,
    help={"dead_centre": "where the first crank starts: crank-end (§ 146's B1, the default: upper sign "
                         "in the Hingang) or head-end (the other books' zero)",
          "drive": "two-cranks: engine (the rods drive the shaft, the default) or pump (the shaft drives "
                   "pumps: § 146, the least and greatest speeds change places)"},
    # A draftsman picks the magnification of the speed deviations for the rod he draws: so does a sweep.
    sweep=lambda g, ratios: {**g, "rod_ratio": ratios,
                             "magnify": auto_magnification(ratios, g["fluctuation"])},
))



def _figure(rod_ratio: float | None, parts: int, dead_centre: str, drive: str, fluctuation: float | None):
    rod = {"infinite_rod": True} if rod_ratio is None else {"rod_ratio": rod_ratio}
    return TWO_CRANKS.figure(parts=parts, dead_centre=dead_centre, drive=drive,
                             **rod, **({} if fluctuation is None else {"fluctuation": fluctuation}))


def speed_fluctuation_rows(*, rod_ratio: float | None, step_deg: float = 15.0, dead_centre: str = "crank-end",
                           drive: str = "engine", fluctuation: float | None = None,
                           crosshead_share: float | None = None) -> list[dict[str, Any]]:
    """e(α) in units of Q·r over 0…360° from the given dead centre (§ 146's B1 by default), off the work line.

    With *fluctuation* k = Qr/((m1 + m2)v1²) (and *crosshead_share* m2/(m1 + m2), default 0) the speeds v/v1
    beside it, as :func:`speeds` gives them: the book's linear law, its energy balance, with the crossheads'
    first-order term the book drops, and with the exact piston speeds; *drive* "pump" turns the sign of e in
    them (the shaft drives the rods: § 146, "das Gegentheil").

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
    if fluctuation is None and crosshead_share is not None:
        raise InvalidParameter("the crossheads' share m2/(m1 + m2) goes with the fluctuation k = Qr/((m1 + m2)v1²)")
    fig = _figure(rod_ratio, n, dead_centre, drive, fluctuation)
    if fluctuation is None:
        return [{"crank_angle_deg": 180.0 * j / n, "work_excess": work_excess(fig, j, infinite=rod_ratio is None)}
                for j in range(2 * n + 1)]
    return speeds(fig, infinite=None, crosshead_share=crosshead_share or 0.0)


def speed_extremes_rows(*, rod_ratio: float | None, parts: int = 12, dead_centre: str = "crank-end",
                        drive: str = "engine", fluctuation: float | None = None) -> list[dict[str, Any]]:
    """§ 147: where e is least and greatest in each quadrant and over the turn, by the exact law and read off
    the construction's drawn wave (the circles about O touching it), angles from the given dead centre.

    ``swing`` = e_max − e_min; with *fluctuation* k the degree of irregularity ``delta`` = k·swing (the
    book's linear law: (v_max − v_min)/v1).  With *drive* "pump" the least speed stands where e is greatest.

    >>> turn = speed_extremes_rows(rod_ratio=4.5)[-1]
    >>> turn["range"], round(turn["e_min"], 5), round(turn["alpha_min_deg"], 2), round(turn["e_max"], 5)
    ('turn', -0.0419, 19.07, 0.26694)
    >>> round(turn["alpha_max_deg"], 2), round(turn["swing"], 5)
    (250.93, 0.30884)
    """
    import math

    fig = _figure(rod_ratio, parts, dead_centre, drive, fluctuation)
    exact = quadrant_extremes(rod_ratio, dead_centre=dead_centre)
    # the first quadrant where the turn's extreme is reached (the infinite rod reaches it in every quadrant)
    low = next(q for q in exact if q["e_min"] <= min(q["e_min"] for q in exact) + 1e-12)
    high = next(q for q in exact if q["e_max"] >= max(q["e_max"] for q in exact) - 1e-12)
    ranges = [(f"quadrant {q['quadrant']}", q, q, ((q["quadrant"] - 1) * 0.5 * math.pi, q["quadrant"] * 0.5 * math.pi))
              for q in exact] + [("turn", low, high, None)]
    rows = []
    for name, lo, hi, window in ranges:
        drawn = wave_extremes(fig, within=window)
        row = {"range": name, "alpha_min_deg": math.degrees(lo["alpha_min"]), "e_min": lo["e_min"],
               "e_min_drawn": drawn["e_min"], "alpha_max_deg": math.degrees(hi["alpha_max"]), "e_max": hi["e_max"],
               "e_max_drawn": drawn["e_max"], "swing": hi["e_max"] - lo["e_min"]}
        if fluctuation is not None:
            row["delta"] = fig.replay.givens["fluctuation"] * row["swing"]
        rows.append(row)
    return rows
