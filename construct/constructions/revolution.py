"""Tangential pressure over a whole revolution, for one crank or several (seed 004's engines, seed 002 § 146).

Baumann (seed 004) draws the tangential-pressure diagram for the forward
stroke and assumes "die Tangentialdruckdiagramme des Hin- und Rückganges
gleich"; his tables compare single-cylinder, tandem and compound engines.
Seed 002 sets two cranks at 90°.  This module carries the construction of
:mod:`construct.constructions.tangential` round the revolution:

* **the return stroke.**  A crank point 180° + ω′ below the stroke line is the
  mirror image of the point 180° − ω′ above it; the crosshead is the same, so
  the rod line through it meets the perpendicular through O at the mirror
  image of that point's K.  A unit force acting in the direction of motion on
  the return stroke therefore has the tangential pressure OK(180° − ω′)/r:
  the return stroke's ordinates are the forward stroke's OK, taken in the
  reverse order and carried with the compass.  (For the finite rod this is
  not the forward diagram repeated: sin(ω′ − β)/cos β instead of
  sin(ω′ + β)/cos β -- the rod term changes sign.)
* **the revolution unrolled.**  The dividers step the chord of one division
  2n times along the base line; each crank position of the revolution has its
  ordinate.
* **several cranks.**  A crank set θ ahead of the first (θ a multiple of the
  division, 180°/n) has at the first crank's position j the ordinate of
  position j + θ/(180°/n) of the one-crank diagram; each crank's diagram is
  drawn, and the summed diagram is built by adding the ordinates with the
  dividers, one on top of the other ("Ordinaten addiert").  In a tandem
  engine two cylinders push one rod: their forces are added before the crank,
  so each ordinate is laid off twice.
* **mean line and excess areas.**  The planimeter gives the mean height over
  the unrolled revolution; the regions between the summed curve and the mean
  line alternate in sign; the work the flywheel must store is the greatest
  swing of their running sum (for one crank and a unit force this is the
  excess area of each stroke; for cranks at 90° the four small lobes of
  seed 002's Fig. 566).

>>> parse_cranks("0, 90")
(0.0, 90.0)
>>> MACHINES["compound"].cranks, MACHINES["tandem"].cylinders
((0.0, 90.0), 2)
>>> [round(float(unit_t(math.radians(a), 0.2)), 12) for a in (90.0, 270.0)]
[1.0, 1.0]
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping, NamedTuple, Sequence

import numpy as np

from ..kernel.errors import InvalidParameter
from ..kernel.instruments import Builder
from ..kernel.protocol import Provenance
from .analytic import tangential_factor
from .checking import EUCLIDEAN_TOLERANCE, Check
from .crank import crank_angle, point_name
from .domain import CRANK_COUNT, CRANK_OFFSET

__all__ = ["Machine", "MACHINES", "parse_cranks", "crank_shifts", "build_revolution", "unit_t", "summed_unit_t",
           "revolution_model", "revolution_ordinate", "engine_t", "engine_cylinders", "revolution_mean", "excess_lobes", "excess_work",
           "revolution_checks", "REVOLUTION_PLATE", "dead_centres", "drawn_revolution", "revolution_rows",
           "unroll_by_chords", "Unrolled"]


@dataclass(frozen=True)
class Machine:
    """A named engine type: where its cranks stand and how many cylinders push each rod."""

    name: str
    cranks: tuple[float, ...]
    cylinders: int
    description: str


#: The engine types of seed 004's tables ("Eincylinder-, Tandem-, Verbundmaschinen").
MACHINES = {
    "single": Machine("single", (0.0,), 1, "one cylinder on each crank (cranks as --cranks says, default one)"),
    "tandem": Machine("tandem", (0.0,), 2, "two cylinders on one rod: their forces are added before the crank"),
    "compound": Machine("compound", (0.0, 90.0), 1, "high- and low-pressure cylinder on cranks at 90 degrees"),
}

#: What the plate of the revolution shows: the unrolled base, each crank's diagram, the sum, the mean line, the
#: hatched excess areas.
REVOLUTION_PLATE = (r"tbase", r"U\d+", r"u\d+", r"S\d+", r"c\d+\.curve", r"tcurve", r"M0|Mn", r"mean", r"excess")


def parse_cranks(text: Any) -> tuple[float, ...]:
    """Crank offsets in degrees ahead of the first crank, from "0,90" (the first is 0 by definition).

    >>> parse_cranks("0,120,240")
    (0.0, 120.0, 240.0)
    >>> parse_cranks("0,90,90")
    Traceback (most recent call last):
    ...
    construct.kernel.errors.InvalidParameter: --cranks: the offset 90 degrees is given twice
    """
    if isinstance(text, (tuple, list)):
        items = list(text)
    else:
        items = [t.strip() for t in str(text).split(",")]
    out: list[float] = []
    for item in items:
        try:
            v = float(item)
        except (TypeError, ValueError):
            raise InvalidParameter(f"--cranks takes crank offsets in degrees separated by commas (e.g. 0,90), "
                                   f"got {item!r}") from None
        CRANK_OFFSET.check("--cranks: crank offset in degrees", v)
        if v == 360.0:
            raise InvalidParameter("--cranks: an offset of 360 degrees is the first crank again; give 0 .. <360")
        if v in out:
            raise InvalidParameter(f"--cranks: the offset {v:g} degrees is given twice")
        out.append(v + 0.0)
    if not out or out[0] != 0.0:
        raise InvalidParameter(f"--cranks: the first crank is the one the angle is measured on: start with 0, "
                               f"got {text!r}")
    CRANK_COUNT.check("--cranks: number of cranks", float(len(out)))
    return tuple(out)


def crank_shifts(offsets: Sequence[float], n: int) -> tuple[int, ...]:
    """Each offset in divisions of the semicircle (180/n degrees); an offset between divisions is refused.

    >>> crank_shifts((0.0, 90.0), 18)
    (0, 9)
    """
    step = 180.0 / n
    out = []
    for v in offsets:
        s = round(v / step)
        if abs(s * step - v) > 1e-9 * max(1.0, v):
            raise InvalidParameter(f"--cranks: the offset {v:g} degrees is not a multiple of the division "
                                   f"180/{n} = {step:g} degrees; choose --parts so that it is")
        out.append(s % (2 * n))
    return tuple(out)


def dead_centres(shifts: Sequence[int], n: int) -> tuple[int, ...]:
    """The positions 1..2n-1 of the revolution where some crank stands at a dead centre: the diagram's corners.

    >>> dead_centres((0, 9), 18)
    (9, 18, 27)
    """
    return tuple(j for j in range(1, 2 * n) if any((j + s) % n == 0 for s in shifts))


# --------------------------------------------------------------------------
# Building.
# --------------------------------------------------------------------------



class Unrolled(NamedTuple):
    """The crank circle unrolled on a base line (:func:`unroll_by_chords`)."""

    start: str  # U0
    base: str
    marks: list[str]  # U0 .. U<count>
    ordinates: list[str]  # u0 .. u<count>
    provenance: Provenance  # the stepping's, the chord's combined in


def unroll_by_chords(b: Builder, D0: str, P1: str, count: int, provenance: Provenance, start: tuple[str, str],
                     label: Any) -> Unrolled:
    """The crank circle unrolled on a base line: the dividers set to the chord D0–P1 of one division and stepped
    off *count* times from U0, and the compass erecting an ordinate at every mark (about each mark through its
    neighbour: small circles, whatever the count).  *provenance* is the stepping's (the chord's is combined in),
    *start* U0's caption (German, English), ``label(k)`` the letter of the k-th mark or None.

    The marks' provenance (returned with them) is *provenance* combined with the chord's.
    """
    U0 = b.given_point("U0", 2.6, -1.2, unit="r", de=start[0], en=start[1], label="0")
    base = b.given_line("tbase", U0, angle_deg=0.0, de="Grundlinie: abgewickelter Kurbelkreis",
                        en="base line: the unrolled crank circle")
    chord = b.length_of("chord", D0, P1, de="Stechzirkel auf die Sehne eines Teils gestellt",
                        en="dividers set to the chord of one division")
    prov = provenance.combine(b.provenance[chord])
    marks = [U0]
    for k in range(1, count + 1):
        name = f"U{k}"
        text = label(k)
        b.record("dividers", "step_off", (base, marks[-1], chord), (name,),
                 {"rule": ("toward", U0, None, 1.0, 0.0), "both": False},
                 f"Sehne zum {k}. Mal abgetragen", f"chord stepped off for the {k}th time", provenance=prov,
                 role="result", labels={name: text} if text is not None else None)
        marks.append(name)
    ords = [b.erect_perpendicular(f"u{k}", mk, base, marks[1] if k == 0 else marks[k - 1])
            for k, mk in enumerate(marks)]
    return Unrolled(U0, base, marks, ords, prov)


def engine_cylinders(shifts: Sequence[int], cylinders: int, machine: str, own_low: bool) -> list[tuple[int, int]]:
    """Each cylinder as (its crank's shift, which diagram drives it: 0 the first, 1 the low-pressure one).

    Cylinders are listed crank by crank.  With *own_low* a compound engine's second crank and a tandem's second
    cylinder have the low-pressure diagram; otherwise every cylinder has the first.

    >>> engine_cylinders((0, 9), 1, "compound", True), engine_cylinders((0,), 2, "tandem", False)
    ([(0, 0), (9, 1)], [(0, 0), (0, 0)])
    """
    out = []
    for i, s in enumerate(shifts):
        for c in range(cylinders):
            low = own_low and ((machine == "compound" and i == 1) or (machine == "tandem" and c == 1))
            out.append((s, 1 if low else 0))
    return out


def build_revolution(b: Builder, f: Mapping[str, str], points: Sequence[str], n: int,
                     heights: Mapping[int, tuple[str, str]], shifts: Sequence[int], cylinders: int,
                     return_heights: Mapping[int, tuple[str, str]] | None = None,
                     low: tuple[Mapping[int, tuple[str, str]], Mapping[int, tuple[str, str]] | None] | None = None,
                     machine: str = "single") -> None:
    """The revolution unrolled, each crank's diagram, the sum by the dividers, the mean line and excess areas.

    *heights* maps a forward division k (1..n-1) to the segment (H_k, Q_k) whose
    length is that crank position's tangential pressure.  *low*: the low-pressure
    cylinder's (heights, return heights) of a compound or tandem *machine*, already
    in the force unit of the first (its pressures times its piston area over the first's).
    """
    r = b.givens["r"]
    m = 2 * n
    shortfall = 2.0 * r * (math.pi - 2.0 * n * math.sin(math.pi / (2.0 * n)))

    sets = [(heights, return_heights)] + ([low] if low is not None else [])
    layout = engine_cylinders(shifts, cylinders, machine, low is not None)

    def one_crank(j: int, which: int = 0) -> tuple[str, str] | None:
        fwd, ret = sets[which]
        j %= m
        if j in (0, n):
            return None  # a dead centre: no tangential pressure
        if j < n:
            return fwd[j]
        if ret is not None:  # a force of the return stroke's own, at the mirrored crank point
            return ret[m - j]
        return fwd[m - j]  # the return stroke: OK of the mirrored crank point 360° - w

    with b.group("the whole revolution unrolled with the dividers", "Die ganze Umdrehung mit dem Stechzirkel abgewickelt"):
        U0, base, marks, ords, prov = unroll_by_chords(
            b, f["D0"], points[1], m,
            Provenance("approximate", f"dividers stepping the chord 2r·sin(π/2n) 2n times (n = {n}): the unrolled "
                       f"revolution falls short of 2πr by 2r(π − 2n·sin(π/2n))", shortfall),
            ("Anfang der Abwicklung (Deckeltotpunkt)", "start of the unrolled revolution (head-end dead centre)"),
            lambda k: f"{round(180 * k / n)}°" if k in (n // 2, n, n + n // 2, m) and n % 2 == 0 else None)

    def carry(name: str, foot: str, j: int, seg: tuple[str, str], de: str, en: str, role: str = "construction") -> str:
        H, Q = seg
        k = b.circle_segment(f"{name}.k", foot, H, Q, de="mit dem Zirkel übertragen", en="carried with the compass")
        return b.intersect(name, ords[j], k, rule=("toward", H, Q), de=de, en=en, role=role)

    several = len(shifts) > 1 or cylinders > 1
    distinct = list(dict.fromkeys(layout))  # each diagram drawn once: a tandem's equal cylinders share one
    names = {0: ("", ""), 1: (" (Niederdruck)", " (low pressure)")} if low is not None else {0: ("", "")}
    with b.group("each crank's tangential pressures on the unrolled revolution",
                 "Die Tangentialdrücke jeder Kurbel auf der Abwicklung"):
        for i, (s, which) in enumerate(distinct):
            crank = shifts.index(s) + 1
            de_w, en_w = names[which]
            curve = []
            for j in range(m + 1):
                seg = one_crank(j + s, which)
                if seg is None:
                    curve.append(marks[j])
                    continue
                stroke = "Hingang" if (j + s) % m < n else "Rückgang"
                curve.append(carry(f"c{i}.{j}", marks[j], j, seg,
                                   de=f"Kurbel {crank}{de_w} bei {j}: Tangentialdruck ({stroke})",
                                   en=f"crank {crank}{en_w} at {j}: tangential pressure "
                                      f"({'forward' if stroke == 'Hingang' else 'return'} stroke)",
                                   role="construction" if several else "result"))
            if several:
                b.french_curve(f"c{i}.curve", base, curve, {}, role="construction", corners=dead_centres([s], n),
                               de=f"Tangentialdrucklinie der Kurbel {crank}{de_w}",
                               en=f"tangential-pressure line of crank {crank}{en_w}")
            else:
                summed = curve
    if several:
        with b.group("the summed diagram: ordinates added with the dividers",
                     "Die Summenlinie: Ordinaten mit dem Stechzirkel addiert"):
            summed = []
            for j in range(m + 1):
                top = marks[j]
                steps = [(shifts.index(s), one_crank(j + s, which), c % cylinders)
                         for c, (s, which) in enumerate(layout)]
                steps = [(i, seg, c) for i, seg, c in steps if seg is not None]
                for t, (i, seg, c) in enumerate(steps):
                    last = t == len(steps) - 1
                    name = f"S{j}" if last else f"S{j}.{t}"
                    top = carry(name, top, j, seg, de=f"Ordinate der Kurbel {i + 1} aufgesetzt" +
                                (f" (Zylinder {c + 1})" if cylinders > 1 else ""),
                                en=f"crank {i + 1}'s ordinate added above the sum so far" + (f" (cylinder {c + 1})" if cylinders > 1 else ""),
                                role="result" if last else "construction")
                summed.append(top)
    with b.group("summed curve, mean line and excess areas", "Summenlinie, Ausgleichende und Überschussflächen"):
        b.french_curve("tcurve", base, summed, {}, corners=dead_centres(shifts, n),
                       de="Tangentialdrucklinie mit dem Curvenlineal, an den Totpunkten abgesetzt",
                       en="tangential-pressure line with the French curve, laid anew at the dead centres")
        plan = Provenance("approximate", "planimeter: area under the drawn curve over the drawn base, divided by the "
                          "base length", 1e-6)
        b.area_between("under", "tcurve", base, U0, marks[m], role="auxiliary",
                       de="Fläche unter der Tangentialdrucklinie", en="area under the tangential-pressure line")
        b.record("planimeter", "planimeter_height", ("under", U0, marks[m]), ("hm",), {},
                 "Planimeter: mittlere Höhe = Fläche / Länge", "planimeter: mean height = area / length",
                 provenance=plan.combine(prov))
        up = ("toward", None, None, 0.0, 1.0)
        for end, mark, ordinate in (("M0", U0, ords[0]), ("Mn", marks[m], ords[m])):
            k = b.circle_radius(f"{end}.k", mark, "hm", de="mittlere Höhe mit dem Zirkel angetragen",
                                en="mean height set off with the compass")
            b.intersect(end, ordinate, k, rule=up, de=f"{end}: mittlere Höhe über der Grundlinie",
                        en=f"{end}: mean height above the base", provenance=plan.combine(prov))
        b.line("mean", "M0", "Mn", role="result", de="Ausgleichende MM über die ganze Umdrehung",
               en="mean line MM over the whole revolution")
        b.area_between("excess", "tcurve", "mean", U0, marks[m], hatch_deg=90.0, role="result",
                       de="Überschuss- (über) und Fehlflächen (unter der Ausgleichenden), schraffiert",
                       en="excess areas (above) and deficit areas (below the mean line), hatched")


# --------------------------------------------------------------------------
# Measurements on the figure.
# --------------------------------------------------------------------------


def _unit(fig: Any) -> float:
    g = fig.replay.givens
    return g["r"] if fig.params["force"] == "unit" else g["pressure_unit"]


def revolution_ordinate(fig: Any, j: int) -> float:
    """The summed diagram's ordinate at crank position j (0..2n) of the revolution, over the force unit."""
    n = fig.params["parts"]
    several = len(fig.params["offsets"]) > 1 or fig.params["cylinders"] > 1
    pushing = [i for i, s in enumerate(fig.params["shifts"]) if (j + s) % (2 * n) not in (0, n)]
    if not pushing:  # every crank at a dead centre: the ordinate is the base point itself
        p = fig.replay[f"U{j}"]
    else:
        p = fig.replay[f"S{j}" if several else f"c0.{j}"]
    return (p[1] - fig.replay[f"U{j}"][1]) / _unit(fig)


def revolution_mean(fig: Any) -> float:
    """The mean line's height over the base (planimeter), over the force unit."""
    return (fig.replay["M0"][1] - fig.replay["U0"][1]) / _unit(fig)


def excess_lobes(fig: Any) -> list[float]:
    """The signed areas between the summed curve and the mean line, in order along the base (force unit x r).

    The abscissae are the chord-stepped ones: an area reads in (force unit) x
    (drawn length), which is r x angle up to the dividers' shortfall.
    """
    g = fig.replay.givens
    pieces = fig.replay["excess"].signed_pieces()
    pieces.sort(key=lambda sp: sp[1].bounds[0])
    scale = _unit(fig) * g["r"]
    return [s * poly.area / scale for s, poly in pieces]


def excess_work(fig: Any) -> float:
    """The greatest swing of the running sum of the lobes: the work the flywheel stores and gives back."""
    return _swing(excess_lobes(fig))


def _swing(lobes: Sequence[float]) -> float:
    run, lo, hi = 0.0, 0.0, 0.0
    for a in lobes:
        run += a
        lo, hi = min(lo, run), max(hi, run)
    return hi - lo


# --------------------------------------------------------------------------
# The analytic model.
# --------------------------------------------------------------------------


def unit_t(w: Any, lam: float) -> Any:
    """T for a unit piston force acting in the direction of motion, at crank angle w (radians, whole turn).

    sin(w + β)/cos β with sin β = λ sin w on the forward stroke; its negative
    (the force reverses with the motion) on the return: |sin(w + β)/cos β|.
    """
    return np.abs(tangential_factor(np.asarray(w, dtype=float), lam))


def summed_unit_t(w: Any, lam: float, offsets_deg: Sequence[float], cylinders: int = 1, force: Any = None) -> Any:
    """Σ over cranks set θ ahead of the first: unit_t(w + θ), times the cylinders on each rod.

    *force*: the piston force along the motion as a function of the crank angle (an array of angles in, over
    the whole turn); None for the unit force.
    """
    total = 0.0
    for t in offsets_deg:
        wt = np.asarray(w, dtype=float) + math.radians(t)
        total = total + unit_t(wt, lam) * (1.0 if force is None else force(np.mod(wt, 2.0 * math.pi)))
    return cylinders * total


def engine_t(w: Any, lam: float, engine: Sequence[tuple[float, Any]]) -> Any:
    """Σ over the cylinders (offset θ in degrees, force along the motion or None for the unit force) of
    F(w + θ)·|sin(w + θ + β)/cos β|: each cylinder with a diagram of its own."""
    total = 0.0
    for t, force in engine:
        wt = np.asarray(w, dtype=float) + math.radians(t)
        total = total + unit_t(wt, lam) * (1.0 if force is None else force(np.mod(wt, 2.0 * math.pi)))
    return total


def _engine_list(offsets_deg: Sequence[float], cylinders: int, force: Any,
                 engine: Sequence[tuple[float, Any]] | None) -> list[tuple[float, Any]]:
    return list(engine) if engine is not None else [(t, force) for t in offsets_deg for _ in range(cylinders)]


def revolution_model(lam: float, offsets_deg: Sequence[float], cylinders: int = 1, samples: int = 200_000,
                     force: Any = None, engine: Sequence[tuple[float, Any]] | None = None) -> dict[str, float]:
    """Mean, and the greatest swing of ∫(T − T_m) dw, of the summed diagram (trapezoids on a fine grid).

    For the unit force the mean is exactly 2/π per cylinder (4r of piston path per turn over 2πr).  *engine*
    (offset, force) per cylinder, when the cylinders have diagrams of their own.
    """
    engine = _engine_list(offsets_deg, cylinders, force, engine)
    w = np.linspace(0.0, 2.0 * math.pi, samples + 1)
    t = engine_t(w, lam, engine)
    if all(fn is None for _, fn in engine):
        mean = 2.0 / math.pi * len(engine)
    else:
        mean = float(np.sum((t[1:] + t[:-1]) * 0.5 * np.diff(w)) / (2.0 * math.pi))
    run = np.concatenate(([0.0], np.cumsum((t[1:] + t[:-1] - 2.0 * mean) * 0.5 * np.diff(w))))
    return {"mean": mean, "excess": float(run.max() - run.min())}


def drawn_revolution(lam: float, offsets_deg: Sequence[float], cylinders: int, n: int,
                     force: Any = None, engine: Sequence[tuple[float, Any]] | None = None) -> dict[str, float]:
    """The method on exact data: the French curve through the exact summed ordinates, read as the figure is."""
    from ..kernel.areas import area_between
    from ..kernel.geometry import SCALAR, Line, Point
    from ..kernel.ops import OPS

    m = 2 * n
    ws = [math.pi * k / n for k in range(m + 1)]
    engine = _engine_list(offsets_deg, cylinders, force, engine)
    pts = [Point(w, float(engine_t(w, lam, engine))) for w in ws]
    base = Line(Point(0.0, 0.0), Point(2 * math.pi, 0.0))
    shifts = crank_shifts(offsets_deg, n)
    curve, = OPS["french_curve"].fn((base, *pts), {"points": m + 1, "tangent_at": (),
                                                   "corners": dead_centres(shifts, n)}, {}, (), SCALAR)
    mean = area_between(curve, base, 0.0, 2 * math.pi).signed_area() / (2 * math.pi)
    line = Line(Point(0.0, mean), Point(2 * math.pi, mean))
    pieces = area_between(curve, line, 0.0, 2 * math.pi).signed_pieces()
    pieces.sort(key=lambda sp: sp[1].bounds[0])
    return {"mean": mean, "excess": _swing([s * p.area for s, p in pieces])}


# --------------------------------------------------------------------------
# Checks.
# --------------------------------------------------------------------------


def revolution_checks(fig: Any, force: Any = None, scale: float = 1.0,
                      engine: Sequence[tuple[float, Any]] | None = None) -> list[Check]:
    """The summed ordinates against Σ F(w + θ) sin(w + θ + β)/cos β (F = 1 for the unit force, else *force*, in
    units of *scale*; or each cylinder's own force, *engine* = (offset θ, force) per cylinder), the mean line
    (2/π per cylinder for the unit force), the excess work."""
    g = fig.replay.givens
    n = fig.params["parts"]
    lam = 1.0 / g["rod_ratio"]
    offsets = fig.params["offsets"]
    cyl = fig.params["cylinders"]
    count = len(offsets) * cyl
    # each crank's position as drawn (its division point's angle; the return stroke's mirrored): the division's
    # error drops out, and what is left is the float chain of the straightedge and compass steps
    drawn_w = [crank_angle(fig, point_name(fig, k)) for k in range(n + 1)]
    checks: list[Check] = []
    engine = _engine_list(offsets, cyl, force, engine)
    unit = "P" if all(fn is None for _, fn in engine) else "at"
    shift_of = {t: s for t, s in zip(offsets, fig.params["shifts"])}
    for j in range(2 * n + 1):
        expected = 0.0
        for t, fn in engine:
            m = (j + shift_of[t]) % (2 * n)
            w = drawn_w[m] if m <= n else 2.0 * math.pi - drawn_w[2 * n - m]
            expected += float(engine_t(w, lam, [(0.0, fn)]))
        checks.append(Check(f"summed T at {j} ({180 * j / n:g} deg)", revolution_ordinate(fig, j), expected,
                            count * 20 * EUCLIDEAN_TOLERANCE * scale,
                            "OK by straightedge, carried and added with the compass: Euclidean", unit))
    model = revolution_model(lam, offsets, cyl, engine=engine)
    drawn = drawn_revolution(lam, offsets, cyl, n, engine=engine)
    why = "the French curve through 2n + 1 points (twice its error on exact data) and the planimeter (1e-6)"
    checks.append(Check("mean height over the revolution (planimeter)", revolution_mean(fig), model["mean"],
                        2.0 * abs(drawn["mean"] - model["mean"]) + 1e-6 * count * scale, why, unit))
    chord_factor = 2 * n * math.sin(math.pi / (2 * n)) / math.pi
    tol_e = 2.0 * abs(drawn["excess"] - model["excess"]) + model["excess"] * (1.0 - chord_factor) + 1e-5 * count * scale
    checks.append(Check("excess work (greatest swing of the excess areas)", excess_work(fig), model["excess"], tol_e,
                        why + "; unrolled by chords: area scaled by n·chord/πr", f"{unit}·r"))
    return checks


def revolution_rows(fig: Any) -> list[dict[str, float]]:
    """crank_angle_deg (read off the crank circle; 360° less the mirrored point's on the return) and T_over_P.

    >>> from construct.constructions import get
    >>> fig = get("tangential-pressure").figure(force="unit", revolution=True, parts=2, rod_ratio=5.0)
    >>> [(round(r["crank_angle_deg"], 9), round(r["T_over_P"], 12)) for r in revolution_rows(fig)]
    [(0.0, 0.0), (90.0, 1.0), (180.0, 0.0), (270.0, 1.0), (360.0, 0.0)]
    """
    n = fig.params["parts"]
    rows = []
    for j in range(2 * n + 1):
        k = j if j <= n else 2 * n - j
        w = math.degrees(crank_angle(fig, point_name(fig, k)))
        rows.append({"crank_angle_deg": w if j <= n else 360.0 - w, "T_over_P": revolution_ordinate(fig, j)})
    return rows
