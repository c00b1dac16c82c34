"""The idealised indicator diagram ("Dampfdiagramm"), seed 004 (Baumann 1902, Fig. 25) and DESIGN §5.

The model: stroke s, clearance s0 ("schädlicher Raum"), filling s1; on the
forward stroke the steam acts with the admission pressure P (over the back
pressure) up to s1, then expands on Mariotte's hyperbola

    (P + P0)(s1 + s0) = (Pa + P0)(sa + s0)

to the end of the stroke.  Behind the piston (crank side) the back pressure
P0 holds until s2 = s - s3, after which the crank side compresses on its own
hyperbola, P0 (s3 + s0) = p (s - sa + s0).  Pressures are drawn absolute:
the base line is the absolute-zero line ("Luftleere"), the clearance lines
stand s0 beyond either dead centre.

Every point of a hyperbola is drawn as the draftsman did, from a rectangle's
diagonal: with Z the corner of the zero line and the clearance line and K a
known point of the curve, the ordinate at x meets the horizontal through K in
B; the ray ZB meets the ordinate through K in C; the horizontal through C
meets the ordinate at x in the new point (similar triangles: the rectangles
under K and under the new point have the same area, pv = const).

The building part is reusable: :func:`indicator_frame` adds the diagram's
fixed lines to any :class:`~construct.kernel.instruments.Builder` whose
givens carry ``filling``, ``clearance``, ``admission``, ``back_pressure``,
``compression`` and ``pressure_unit``; :func:`pressures_at` then constructs
the steam-line point and the back-pressure point on any ordinate.

>>> fig = INDICATOR.figure()
>>> g = fig.replay.givens
>>> x = abscissa(fig, "E10")          # the end of the stroke
>>> round(pressure(fig, "E10"), 12)   # (P + P0)(s1 + s0)/(s + s0) = 8 * 0.15 / 1.05
1.142857142857
>>> round(pressure(fig, "R10"), 12)   # P0 (s3 + s0)/s0 = 0.15 * 0.35 / 0.05
1.05
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping, Sequence

import numpy as np

from .checking import EUCLIDEAN_TOLERANCE, Check
from ..kernel.errors import InvalidParameter
from ..kernel.instruments import Builder
from ..kernel.protocol import Caption
from . import Construction, Figure, bounded, positive, register
from .domain import CLEARANCE, DRAWN_LENGTH, PRESSURE, STROKE_FRACTION
from .phrases import BAUMANN_1902, Cite, card, diagram, scale
from .scales import scale_furniture

__all__ = ["INDICATOR", "IndicatorDiagram", "indicator_frame", "pressures_at", "hyperbola_point", "square",
           "indicator_givens", "BAUMANN", "abscissa", "pressure", "steam_pressure", "back_pressure"]

#: Baumann's worked case (seed 004, "Bestimmung des Fehlers"): the diagrams are drawn for the
#: admission piston pressure P = 7.85 at (k = 7.85/9.85), s1 = 10 %, s0 = 5 %, P0 = 0.15 at, and the
#: constant compression of 30 % ("für die konstante Kompression von 30 %").
BAUMANN = {"filling": 0.10, "clearance": 0.05, "admission": 7.85, "back_pressure": 0.15, "compression": 0.30}


def indicator_givens(filling: Any, clearance: Any, admission: Any, back_pressure: Any, compression: Any,
                     pressure_unit: Any) -> dict[str, float]:
    """The diagram's givens, checked: fractions of the stroke in (0, 1), pressures positive."""
    out = {"filling": positive("filling s1/s", filling), "clearance": positive("clearance s0/s", clearance),
           "admission": bounded("admission pressure P (at)", admission, PRESSURE),
           "back_pressure": bounded("back pressure P0 (at)", back_pressure, PRESSURE),
           "compression": positive("compression s3/s", compression),
           "pressure_unit": bounded("pressure-scale unit (drawn length of 1 at)", pressure_unit, DRAWN_LENGTH)}
    for key, what in (("filling", "filling s1/s"), ("compression", "compression s3/s")):
        if out[key] >= 1.0:
            raise InvalidParameter(f"{what} must be less than 1 (a fraction of the stroke), got {out[key]!r}")
    if out["clearance"] > 1.0:
        raise InvalidParameter(f"clearance s0/s must be at most 1, got {out['clearance']!r}")
    STROKE_FRACTION.check("filling s1/s", out["filling"])
    STROKE_FRACTION.check("compression s3/s", out["compression"])
    CLEARANCE.check("clearance s0/s", out["clearance"])
    return out


@dataclass(frozen=True)
class IndicatorDiagram:
    """Object names of a diagram's fixed parts (see :func:`indicator_frame`)."""

    prefix: str
    base: str        #: absolute-zero line ("Luftleere")
    head: str        #: head-end dead centre on the base (piston path 0)
    crank: str       #: crank-end dead centre on the base (piston path s)
    Z0: str          #: corner of the zero line and the head-end clearance line
    Z1: str          #: corner of the zero line and the crank-end clearance line
    admission: str   #: admission line, height P + P0
    back: str        #: back-pressure line, height P0
    cutoff: str      #: point of the cut-off (s1, P + P0): the known point of the expansion hyperbola
    cutoff_ordinate: str
    compression_start: str   #: point (s2, P0), s2 = s - s3: the known point of the compression hyperbola
    compression_ordinate: str
    opening: str     #: short compass opening for the perpendiculars
    filling: float   #: s1/s as built (decides which ordinates lie on the admission line)
    compression: float  #: s3/s as built


def _up(d_head: str, d_crank: str) -> tuple[str, str, str]:
    return ("left", d_head, d_crank)


def indicator_frame(b: Builder, *, base: str, head: str, crank: str, stroke: Sequence[str] = ("r",),
                    stroke_factor: float = 2.0, prefix: str = "",
                    pressure_scale: Sequence[str] = ("pressure_unit",), given_prefix: str = "") -> IndicatorDiagram:
    """Add the diagram's fixed lines: clearance corners, admission and back-pressure lines, cut-off, s2.

    *base* is the absolute-zero line through *head* and *crank* (the two dead
    centres, head end first; the diagram is drawn on the left of head -> crank);
    the stroke is the given product *stroke* times *stroke_factor* (``("r",), 2``:
    the stroke 2r of :func:`construct.constructions.crank.build_frame`), and
    must equal the distance head-crank.  The builder's givens must hold
    ``filling``, ``clearance``, ``admission``, ``back_pressure``, ``compression``
    (as fractions of the stroke and in at) and the givens of *pressure_scale*, whose
    product is the drawn length of 1 at (``pressure_unit``; or e.g. piston area times
    drawn length per kg, so that the diagram reads directly as piston force).  *given_prefix* names another
    cylinder's givens (``lp.filling`` ...: a compound engine's low-pressure diagram).
    """
    p = prefix
    q = given_prefix
    up = _up(head, crank)
    g = b.givens
    with b.group("indicator diagram: clearance, admission and back pressure",
                 "Dampfdiagramm: schädlicher Raum, Admissions- und Gegendrucklinie"):
        s0 = b.given_length(f"{p}s0", product=(f"{q}clearance", *stroke), factor=stroke_factor,
                            de="schädlicher Raum s0", en="clearance s0")
        s1 = b.given_length(f"{p}s1", product=(f"{q}filling", *stroke), factor=stroke_factor,
                            de="Füllung s1", en="filling s1")
        s3 = b.given_length(f"{p}s3", product=(f"{q}compression", *stroke), factor=stroke_factor,
                            de="Kompressionsweg s3 = s − s2", en="compression path s3 = s - s2")
        P0 = b.given_length(f"{p}P0", product=(f"{q}back_pressure", *pressure_scale),
                            de="Gegendruck P0 im Druckmaßstab", en="back pressure P0 in the pressure scale")
        opening = b.given_length(f"{p}open", product=stroke, factor=stroke_factor / 20.0,
                                 de="Zirkelöffnung für die Senkrechten (s/20)", en="compass opening for the perpendiculars (s/20)")
        P = b.given_length(f"{p}P", product=(f"{q}admission", *pressure_scale),
                           de="Admissionsdruck P (über dem Gegendruck)", en="admission pressure P (over the back pressure)")
        k = b.circle_radius(f"{p}Z0.k", head, s0, de="s0 vor dem Deckeltotpunkt", en="s0 beyond the head-end dead centre")
        Z0 = b.intersect(f"{p}Z0", base, k, rule=("farther", crank), role="result", labels={f"{p}Z0": "Z"},
                         de="Ecke Z von Nulllinie und Linie des schädlichen Raums",
                         en="corner Z of the zero line and the clearance line")
        k = b.circle_radius(f"{p}Z1.k", crank, s0, de="s0 hinter dem Kurbeltotpunkt", en="s0 beyond the crank-end dead centre")
        Z1 = b.intersect(f"{p}Z1", base, k, rule=("farther", head), role="result", labels={f"{p}Z1": "Z′"},
                         de="Ecke Z′ auf der Kurbelseite", en="corner Z' on the crank side")
        square(b, f"{p}clear0", Z0, base, opening)
        square(b, f"{p}clear1", Z1, base, opening)
        head_ord = square(b, f"{p}v.head", head, base, opening)
        crank_ord = square(b, f"{p}v.crank", crank, base, opening)
        k = b.circle_radius(f"{p}B0.k", head, P0, de="P0 aufgetragen", en="P0 laid off")
        B0 = b.intersect(f"{p}B0", head_ord, k, rule=up, de="Gegendruck P0 über der Nulllinie",
                         en="back pressure P0 above the zero line")
        k = b.circle_radius(f"{p}A0.k", B0, P, de="P darüber aufgetragen", en="P laid off above it")
        A0 = b.intersect(f"{p}A0", head_ord, k, rule=("farther", head), role="result",
                         de="Admissionsdruck P + P0 (absolut)", en="admission pressure P + P0 (absolute)")
        adm = square(b, f"{p}adm", A0, head_ord, opening)
        back = square(b, f"{p}back", B0, head_ord, opening)
        b.call(adm, "Admissionslinie", "the admission line")
        b.call(back, "Gegendrucklinie", "the back-pressure line")
        k = b.circle_radius(f"{p}S1.k", head, s1, de="Füllung s1 abgetragen", en="filling s1 laid off")
        S1 = b.intersect(f"{p}S1", base, k, rule=("toward", head, crank), labels={f"{p}S1": "s₁"},
                         de="Ende der Füllung auf der Nulllinie", en="end of the filling on the zero line")
        cut_ord = square(b, f"{p}v.s1", S1, base, opening)
        cutoff = b.intersect(f"{p}A1", adm, cut_ord, rule=("only",), role="result", labels={f"{p}A1": "A₁"},
                             de="Abschluss der Füllung A₁", en="cut-off A₁")
        k = b.circle_radius(f"{p}S2.k", crank, s3, de="s3 vom Kurbeltotpunkt zurück", en="s3 back from the crank-end dead centre")
        S2 = b.intersect(f"{p}S2", base, k, rule=("toward", crank, head), labels={f"{p}S2": "s₂"},
                         de="Beginn der Kompression s2 = s − s3", en="start of compression s2 = s - s3")
        comp_ord = square(b, f"{p}v.s2", S2, base, opening)
        cstart = b.intersect(f"{p}C2", back, comp_ord, rule=("only",), role="result", labels={f"{p}C2": "C₂"},
                             de="Beginn der Kompression C₂", en="start of compression C₂")
    del head_ord, crank_ord
    return IndicatorDiagram(p, base, head, crank, Z0, Z1, adm, back, cutoff, cut_ord, cstart, comp_ord,
                            opening, g[f"{q}filling"], g[f"{q}compression"])


def square(b: Builder, name: str, point: str, line: str, opening: str) -> str:
    """The perpendicular to *line* at its point *point*: a small circle cuts it twice, their bisector.

    (The opening is a short given length, so the construction stays near the point.)
    """
    with b.group(f"perpendicular at {point} to {line}", f"Senkrechte in {point} auf {line}"):
        k = b.circle_radius(f"{name}.o", point, opening, de=f"Kreis um {point}", en=f"circle about {point}")
        # Both crossings are equally near the centre: "nearer" could not decide, and float noise would pick a
        # side (a replay jumped).  A fixed slant direction orders them on a horizontal and a vertical line alike.
        a, z = b.intersect((f"{name}.a", f"{name}.z"), line, k, rule=("toward", None, None, 1.0, 1.0))
        perp = b.perpendicular_bisector(name, a, z)
    b.call(perp, f"Senkrechte in {point}", f"the perpendicular at {point}")
    return perp


def hyperbola_point(b: Builder, name: str, *, corner: str, known: str, known_horizontal: str, known_vertical: str,
                    ordinate: str, opening: str, what: tuple[str, str], role: str = "result") -> str:
    """The point of pv = const (origin *corner*) through *known* on *ordinate*: the rectangle's diagonal.

    B = ordinate x known horizontal; ray corner-B meets the known vertical in C;
    the perpendicular to the known vertical at C (a horizontal, made with the
    short compass *opening*) meets the ordinate.
    """
    with b.group(f"hyperbola point {name} by rays from {corner}", f"Hyperbelpunkt {name} durch Strahlen aus {corner}"):
        B = b.intersect(f"{name}.B", ordinate, known_horizontal, rule=("only",),
                        de="Ordinate trifft die Waagerechte durch den bekannten Punkt",
                        en="the ordinate meets the horizontal through the known point")
        ray = b.line(f"{name}.s", corner, B, de=f"Strahl aus {corner} (Diagonale des Rechtecks)",
                     en=f"ray from {corner} (the rectangle's diagonal)")
        C = b.intersect(f"{name}.C", ray, known_vertical, rule=("only",),
                        de="Strahl trifft die Senkrechte durch den bekannten Punkt",
                        en="the ray meets the vertical through the known point")
        h = square(b, f"{name}.h", C, known_vertical, opening)
        return b.intersect(name, h, ordinate, rule=("only",), role=role, de=what[0], en=what[1])


def _offset_on_base(b: Builder, d: IndicatorDiagram, ordinate: str) -> float:
    """Where the ordinate stands, as a fraction of the stroke, read off the figure as drawn now."""
    (ax, ay), (cx, cy) = b[d.head], b[d.crank]
    ln = b[ordinate]
    (px, py), (qx, qy) = ln
    # the foot of the ordinate on the base: solve along the base direction
    ux, uy = cx - ax, cy - ay
    s2 = ux * ux + uy * uy
    # a point of the ordinate projected on the base (the ordinate is perpendicular to it)
    return ((px - ax) * ux + (py - ay) * uy) / s2


def pressures_at(b: Builder, d: IndicatorDiagram, ordinate: str, tag: str, *, tangents: bool = False,
                 envelope: bool = False) -> dict[str, str]:
    """Construct the steam-line point and the back-pressure point on *ordinate* (perpendicular to the base).

    Returns ``{"steam": name, "back": name}`` (plus ``"steam_tangent"`` /
    ``"back_tangent"`` lines on the hyperbolas when *tangents*).  Which branch
    (admission line or expansion hyperbola; back-pressure line or compression
    hyperbola) is read off the figure when the step is recorded -- unless
    *envelope*: then both points are constructed on the ordinate and the
    steam line takes the lower (the hyperbola lies above the admission line
    before the cut-off), the back line the higher of its two, by a stored
    rule; a replay that moves the ordinate past the cut-off or the start of
    compression (another rod ratio) stays right.  Without it, filling and
    compression are structural parameters of a protocol using this.
    The over-pressure p_ü is the distance back -> steam (steam above = positive).
    """
    p = d.prefix
    x = _offset_on_base(b, d, ordinate)
    out: dict[str, str] = {}
    edge = 1e-9

    def admission(name: str) -> str:
        return b.intersect(name, ordinate, d.admission, rule=("only",), role="result" if not envelope else "construction",
                           de=f"Admissionslinie bei {tag}", en=f"admission line at {tag}")

    def expansion(name: str) -> str:
        return hyperbola_point(b, name, corner=d.Z0, known=d.cutoff, known_horizontal=d.admission,
                               known_vertical=d.cutoff_ordinate, ordinate=ordinate, opening=d.opening,
                               what=(f"Expansionslinie bei {tag}", f"expansion line at {tag}"),
                               role="construction" if envelope else "result")

    def back(name: str) -> str:
        return b.intersect(name, ordinate, d.back, rule=("only",), role="result" if not envelope else "construction",
                           de=f"Gegendrucklinie bei {tag}", en=f"back-pressure line at {tag}")

    def compression(name: str) -> str:
        return hyperbola_point(b, name, corner=d.Z1, known=d.compression_start, known_horizontal=d.back,
                               known_vertical=d.compression_ordinate, ordinate=ordinate, opening=d.opening,
                               what=(f"Kompressionslinie bei {tag}", f"compression line at {tag}"),
                               role="construction" if envelope else "result")

    if envelope:
        # "Up" is the side the diagram stands on: left of head -> crank (above a stroke line drawn left to right,
        # below one drawn right to left -- the crank side's mirrored diagram).
        side = 1.0 if b[d.crank][0] >= b[d.head][0] else -1.0
        down, up = ("toward", None, None, 0.0, -side), ("toward", None, None, 0.0, side)
        out["steam"] = b.pick(f"{p}E{tag}", admission(f"{p}Ea{tag}"), expansion(f"{p}Eh{tag}"), rule=down,
                              role="result", de=f"Dampflinie bei {tag}: die untere von Admissionslinie und Expansionslinie",
                              en=f"steam line at {tag}: the lower of admission line and expansion hyperbola")
        out["back"] = b.pick(f"{p}R{tag}", back(f"{p}Ra{tag}"), compression(f"{p}Rh{tag}"), rule=up,
                             role="result", de=f"Gegendrucklinie bei {tag}: die obere von Gegendruck- und Kompressionslinie",
                             en=f"back line at {tag}: the higher of back-pressure line and compression hyperbola")
        return out
    if x <= d.filling + edge:
        out["steam"] = admission(f"{p}E{tag}")
    else:
        out["steam"] = expansion(f"{p}E{tag}")
        if tangents:
            out["steam_tangent"] = _tangent(b, d, out["steam"], ordinate, d.Z0, f"{p}tE{tag}")
    if x <= 1.0 - d.compression + edge:
        out["back"] = back(f"{p}R{tag}")
    else:
        out["back"] = compression(f"{p}R{tag}")
        if tangents:
            out["back_tangent"] = _tangent(b, d, out["back"], ordinate, d.Z1, f"{p}tR{tag}")
    return out


def _tangent(b: Builder, d: IndicatorDiagram, point: str, ordinate: str, corner: str, name: str) -> str:
    """Tangent of pv = const at a point: it meets the zero line at twice the foot's distance from the corner."""
    foot = b.intersect(f"{name}.F", ordinate, d.base, rule=("only",), de="Fußpunkt", en="foot")
    k = b.circle_through(f"{name}.k", foot, corner, de="Abstand vom Eckpunkt verdoppelt",
                         en="distance from the corner doubled")
    T = b.intersect(f"{name}.T", d.base, k, rule=("farther", corner), de="Subtangente gleich der Abszisse",
                    en="subtangent equals the abscissa")
    return b.line(name, point, T, de="Tangente der Hyperbel", en="tangent of the hyperbola")


# --------------------------------------------------------------------------
# The construction 'indicator-diagram'.
# --------------------------------------------------------------------------

#: What the plate shows (regular expressions over object names): the zero line, the clearance
#: corners, the admission and back-pressure lines, the ordinates, every ray and rectangle of the
#: hyperbola construction, the curve points and the two curves.
PLATE = (r"base", r"A", r"B", r"Z[01]", r"A0|B0|A1|C2|S1|S2", r"T\d+", r"adm|back", r"v\d+",
         r"v\.(head|crank|s1|s2)", r"[ER]\d+", r"[ER]\d+\.[BCsh]", r"expansion|compression")


def build_indicator(*, r: float, filling: float, clearance: float, admission: float, back_pressure: float,
                    compression: float, pressure_unit: float, divisions: int) -> Figure:
    givens = {"r": bounded("stroke half r (drawing units)", r, DRAWN_LENGTH),
              **indicator_givens(filling, clearance, admission, back_pressure, compression, pressure_unit)}
    if isinstance(divisions, bool) or not isinstance(divisions, int) or not 2 <= divisions <= 200:
        raise InvalidParameter(f"divisions of the stroke must be a whole number from 2 to 200, got {divisions!r}")
    b = Builder("indicator-diagram", givens, {"divisions": divisions, "filling": givens["filling"],
                                               "compression": givens["compression"], "plate": PLATE})
    with b.group("stroke and zero line", "Hub und Nulllinie"):
        A = b.given_point("A", 0.0, 0.0, de="Deckeltotpunkt A", en="head-end dead centre A", label="0")
        B = b.given_point("B", 2.0, 0.0, unit="r", de="Kurbeltotpunkt B", en="crank-end dead centre B", label="s")
        base = b.line("base", A, B, role="result", de="Nulllinie (absolutes Vakuum) = Kolbenweglinie",
                      en="zero line (absolute vacuum) = piston-path line")
    d = indicator_frame(b, base=base, head=A, crank=B)
    n = divisions
    with b.group(f"stroke divided into {n} parts, ordinates", f"Hub in {n} Teile geteilt, Ordinaten"):
        marks = [A] + b.divide_segment("T", A, B, n, line=base) + [B]
        ords = []
        for k, m in enumerate(marks):
            if k == 0:
                ords.append("v.head")
            elif k == n:
                ords.append("v.crank")
            else:
                ords.append(square(b, f"v{k}", m, base, d.opening))
    exp_pts, exp_tan, comp_pts, comp_tan = [d.cutoff], {0: None}, [d.compression_start], {0: None}
    with b.group("expansion and compression lines by the ray construction",
                 "Expansions- und Kompressionslinie durch Strahlenkonstruktion"):
        for k, o in enumerate(ords):
            with b.group(f"pressures at {k}/{n} of the stroke", f"Drücke bei {k}/{n} Hub"):
                pts = pressures_at(b, d, o, str(k), tangents=True)
            if "steam_tangent" in pts:
                exp_tan[len(exp_pts)] = pts["steam_tangent"]
                exp_pts.append(pts["steam"])
            if "back_tangent" in pts:
                comp_tan[len(comp_pts)] = pts["back_tangent"]
                comp_pts.append(pts["back"])
        # the known points' own tangents
        exp_tan[0] = _tangent(b, d, d.cutoff, d.cutoff_ordinate, d.Z0, "tA1")
        comp_tan[0] = _tangent(b, d, d.compression_start, d.compression_ordinate, d.Z1, "tC2")
    with b.group("the curves drawn through the points", "Die Linien durch die Punkte gezogen"):
        b.french_curve("expansion", base, exp_pts, {i: t for i, t in exp_tan.items() if t},
                     de="Expansionslinie (Hyperbel) mit dem Curvenlineal", en="expansion line (hyperbola), French curve")
        b.french_curve("compression", base, comp_pts, {i: t for i, t in comp_tan.items() if t},
                     de="Kompressionslinie (Hyperbel) mit dem Curvenlineal", en="compression line (hyperbola), French curve")
    proto = b.protocol()
    return Figure(proto, proto.replay(givens))


# --------------------------------------------------------------------------
# Measurements and checks.
# --------------------------------------------------------------------------


def _frame(fig: Figure, head: str = "A", crank: str = "B") -> tuple[float, float, float, float, float, float]:
    (ax, ay), (bx, by) = fig.replay[head], fig.replay[crank]
    s = math.hypot(bx - ax, by - ay)
    ux, uy = (bx - ax) / s, (by - ay) / s
    return ax, ay, ux, uy, s, fig.replay.givens["pressure_unit"]


def abscissa(fig: Figure, point: str, head: str = "A", crank: str = "B") -> float:
    """Piston path of a point's foot as a fraction of the stroke, measured on the figure."""
    ax, ay, ux, uy, s, _ = _frame(fig, head, crank)
    p = fig.replay[point]
    return ((p[0] - ax) * ux + (p[1] - ay) * uy) / s


def pressure(fig: Figure, point: str, head: str = "A", crank: str = "B") -> float:
    """Absolute pressure (at) of a point: its height over the zero line in the pressure scale."""
    ax, ay, ux, uy, s, unit = _frame(fig, head, crank)
    p = fig.replay[point]
    return ((p[0] - ax) * -uy + (p[1] - ay) * ux) / unit


def steam_pressure(x: Any, g: Mapping[str, Any]) -> Any:
    """Absolute pressure on the cover side at piston path x (fraction of the stroke; numbers or arrays):
    Baumann's model, P + P0 up to the cut-off s1, then the hyperbola through it."""
    s1, s0, P, P0 = g["filling"], g["clearance"], g["admission"], g["back_pressure"]
    p = np.where(x <= s1, P + P0, (P + P0) * (s1 + s0) / (x + s0))
    return float(p) if np.ndim(p) == 0 else p


def back_pressure(x: Any, g: Mapping[str, Any]) -> Any:
    """Absolute pressure on the crank side at piston path x (numbers or arrays): P0, compressed from
    s2 = s - s3 on."""
    s3, s0, P0 = g["compression"], g["clearance"], g["back_pressure"]
    p = np.where(x <= 1.0 - s3, P0, P0 * (s3 + s0) / (1.0 - x + s0))
    return float(p) if np.ndim(p) == 0 else p


def _pressure_tolerance(g: Mapping[str, float], unit_scale: float) -> float:
    # Heights are read in at: the chain's float error (~1e-12 of the figure) divided by the pressure unit.
    size = max(2.0, (g["admission"] + g["back_pressure"]) * unit_scale)
    return EUCLIDEAN_TOLERANCE * size / unit_scale


def indicator_checks(fig: Figure) -> list[Check]:
    g = fig.replay.givens
    n = fig.params["divisions"]
    u = g["pressure_unit"]
    tol = _pressure_tolerance(g, u)
    s1, s0, P, P0, s3 = g["filling"], g["clearance"], g["admission"], g["back_pressure"], g["compression"]
    checks = [
        Check("cut-off abscissa s1/s", abscissa(fig, "A1"), s1, EUCLIDEAN_TOLERANCE, "Euclidean: s1 laid off", "stroke"),
        Check("cut-off pressure P + P0", pressure(fig, "A1"), P + P0, tol, "Euclidean: P0 and P laid off", "at"),
        Check("compression start s2/s", abscissa(fig, "C2"), 1.0 - s3, EUCLIDEAN_TOLERANCE, "Euclidean", "stroke"),
        Check("clearance corner Z", abscissa(fig, "Z0"), -s0, EUCLIDEAN_TOLERANCE, "Euclidean", "stroke"),
    ]
    c_exp = (P + P0) * (s1 + s0)
    c_comp = P0 * (s3 + s0)
    for k in range(n + 1):
        for kind, name, const, fn in (("steam", f"E{k}", c_exp, steam_pressure), ("back", f"R{k}", c_comp, back_pressure)):
            x = abscissa(fig, name)
            p = pressure(fig, name)
            checks.append(Check(f"{kind} pressure at {k}/{n} (model)", p, fn(k / n, g), tol + 10 * EUCLIDEAN_TOLERANCE * const,
                                "Euclidean ray construction; nominal abscissa k/n from the divided stroke", "at"))
            on_exp = kind == "steam" and x > s1 + 1e-9
            on_comp = kind == "back" and x > 1.0 - s3 + 1e-9
            if on_exp:
                checks.append(Check(f"(p + P0)(x + s0) at {k}/{n}", p * (x + s0), const, tol * 2.0,
                                    "Mariotte: (P + P0)(s1 + s0) = (Pa + P0)(sa + s0); Euclidean", "at·stroke"))
            if on_comp:
                checks.append(Check(f"p (s - x + s0) at {k}/{n}", p * (1.0 - x + s0), const, tol * 2.0,
                                    "compression hyperbola P0 (s3 + s0) = p (s - sa + s0); Euclidean", "at·stroke"))
    # the French curves against the hyperbolas (how a drawn curve strays, with the Hermite bound)
    exp_x = [s1] + [k / n for k in range(n + 1) if k / n > s1 + 1e-9]
    comp_x = [1.0 - s3] + [k / n for k in range(n + 1) if k / n > 1.0 - s3 + 1e-9]
    for curve, xs, fn, d4 in (("expansion", exp_x, steam_pressure, lambda a, e: c_exp * 24.0 / (a + s0) ** 5),
                              ("compression", comp_x, back_pressure, lambda a, e: c_comp * 24.0 / (1.0 - e + s0) ** 5)):
        worst = _curve_deviation(fig, curve, xs[0], xs[-1], fn)
        bound = max((e - a) ** 4 / 384.0 * d4(a, e) for a, e in zip(xs, xs[1:]))
        checks.append(Check(f"{curve} line as drawn vs hyperbola (max, at)", worst, 0.0, bound + tol,
                            "cubic Hermite pieces with the hyperbola's own (constructed) tangents: "
                            "error <= h^4 max|d4p/dx4| / 384 per piece", "at"))
    return checks


def _curve_deviation(fig: Figure, curve: str, lo: float, hi: float, fn, samples: int = 201) -> float:
    drawn = fig.replay[curve]
    ax, ay, ux, uy, s, unit = _frame(fig)
    g = fig.replay.givens
    worst = 0.0
    for i in range(samples):
        # the ends are the constructed points: stay a hair inside them (they carry float error)
        x = lo + (hi - lo) * (1e-9 + (1.0 - 2e-9) * i / (samples - 1))
        px = ax + x * s * ux  # the base is horizontal in this layout
        worst = max(worst, abs((drawn.y_at(px) - ay) / unit - fn(x, g)))
    return worst


#: Command-line help for the diagram's givens (book terms).
OPTION_HELP = {
    "filling": "filling s1/s, fraction of the stroke (indicator-diagram: Baumann's 0.10)",
    "clearance": "clearance s0/s, fraction of the stroke (indicator-diagram: Baumann's 0.05)",
    "admission": "admission pressure P in at over the back pressure (indicator-diagram: Baumann's 7.85)",
    "back_pressure": "back pressure P0 in at absolute (indicator-diagram: Baumann's 0.15)",
    "compression": "compression s3/s = (s - s2)/s (indicator-diagram: Baumann's 0.30)",
    "pressure_unit": "drawn length of 1 at (indicator-diagram; default 0.12)",
}


def indicator_plate(fig: Figure) -> dict:
    """Baumann's Fig. 25 as a plate: the diagram one closed outline at result weight -- admission line
    (P + P0 from 0 to A₁), expansion, exhaust at the end of the stroke, back-pressure line (C₂ back to
    the start), compression, and the admission vertical at the dead centre -- the construction thin, and
    a pressure scale in at (absolute, from the zero line) beside the clearance line.

    Every corner is a constructed point; the scale's divisions are the given drawn length of 1 at.
    """
    R = fig.replay
    if "card.x0" in R.givens:  # a digitised card: its traced lines are the outline, heavy; no idealised corners
        return {"looks": {"card.fwd": "heavy", "card.back": "heavy", "crank.fwd": "heavy", "crank.back": "heavy",
                          "card.loop": "thin", "crank.loop": "thin"}, "furniture": []}
    n = fig.params["divisions"]
    A0, A1, B0, C2 = R["A0"], R["A1"], R["B0"], R["C2"]
    end_exp, end_comp = R[f"E{n}"], R[f"R{n}"]
    Z = R["Z0"]
    s = R["A"].distance(R["B"])
    unit = R.givens["pressure_unit"]
    top = int(math.floor(A0[1] / unit + 1e-9))
    x = Z[0] - 0.06 * s
    tick = 0.012 * s
    furniture: list[dict] = [{"kind": "stroke", "a": tuple(a), "b": tuple(b), "look": "heavy"}
                             for a, b in ((B0, A0), (A0, A1), (end_exp, end_comp), (C2, B0))]
    furniture += scale_furniture(x=x, zero=0.0, unit=unit, values=range(top + 1), tick=tick, text="at")
    # C₂ lies on the heavy back-pressure line: lettered above it, clear of the line and the curve
    furniture.append({"kind": "lettering", "at": (C2[0] - 0.018 * s, C2[1] + 0.024 * s), "text": "C₂"})
    # what the caption gives, measured on the diagram: P over the back-pressure line and P₀ under it at the
    # head end, the clearance s₀ and the compression s₃ under the zero line
    A, B, S2 = R["A"], R["B"], R["S2"]
    off = -0.022 * s  # left of the admission vertical
    furniture.append({"kind": "dimension", "a": tuple(B0), "b": tuple(A0), "text": "P", "offset": -off,
                      "text_at": (B0[0] + off - 0.018 * s, (B0[1] + A0[1]) / 2)})
    # P₀ is a few pixels high: its arrows between the zero line and the back-pressure line a quarter of the way
    # along, its letter under the zero line
    x = A[0] + 0.23 * s
    furniture.append({"kind": "dimension", "a": (x, A[1]), "b": (x, B0[1]), "text": "P₀",
                      "text_at": (x, A[1] - 0.03 * s)})
    below = 0.06 * s
    furniture.append({"kind": "dimension", "a": tuple(Z), "b": tuple(A), "text": "s₀", "offset": -below})
    furniture.append({"kind": "dimension", "a": tuple(S2), "b": tuple(B), "text": "s₃", "offset": -below})
    looks = {"expansion": "heavy", "compression": "heavy", "base": "medium", "C2": "unlettered"}
    return {"looks": looks, "furniture": furniture}


def _validate(givens: Mapping[str, float]) -> None:
    bounded("stroke half r (drawing units)", givens["r"], DRAWN_LENGTH)
    if "card.x0" in givens:  # a digitised card in the protocol: checked as a file is
        from .indicator_card import card_pair

        bounded("pressure-scale unit (drawn length of 1 at)", givens["pressure_unit"], DRAWN_LENGTH)
        card_pair(givens)
        return
    indicator_givens(givens["filling"], givens["clearance"], givens["admission"], givens["back_pressure"],
                     givens["compression"], givens["pressure_unit"])


#: What a card's plate shows: the stroke, the cards' points and lines, the ordinates and the readings on them.
CARD_PLATE = (r"base", r"A", r"B", r"(card|crank)\.(fwd|back)", r"v\d+", r"[fr][EW]\d+")


def build_indicator_card(*, r: float, pressure_unit: float, divisions: int, indicator: str,
                         crank_side: str) -> Figure:
    """A digitised card (and the crank side's, or the cover side's mirrored) drawn with compass and straightedge,
    the stroke divided, and on every ordinate the pressures of both sides on both strokes read off the lines."""
    from .indicator_card import card_givens, draw_card, load_indicator

    if crank_side and not indicator:
        raise InvalidParameter("--indicator-crank-side goes with --indicator (the cover side's diagram)")
    cover = load_indicator(indicator)
    crank = load_indicator(crank_side) if crank_side else None
    givens = {"r": bounded("stroke half r (drawing units)", r, DRAWN_LENGTH),
              "pressure_unit": bounded("pressure-scale unit (drawn length of 1 at)", pressure_unit, DRAWN_LENGTH),
              **card_givens(cover, "card."), **(card_givens(crank, "crank.") if crank else {})}
    if isinstance(divisions, bool) or not isinstance(divisions, int) or not 2 <= divisions <= 200:
        raise InvalidParameter(f"divisions of the stroke must be a whole number from 2 to 200, got {divisions!r}")
    b = Builder("indicator-diagram", givens, {"divisions": divisions, "cards": True, "plate": CARD_PLATE,
                                               **({} if crank else {"mirrored": True})})
    with b.group("stroke and zero line", "Hub und Nulllinie"):
        A = b.given_point("A", 0.0, 0.0, de="Deckeltotpunkt A", en="head-end dead centre A", label="0")
        B = b.given_point("B", 2.0, 0.0, unit="r", de="Kurbeltotpunkt B", en="crank-end dead centre B", label="s")
        base = b.line("base", A, B, role="result", de="Nulllinie (absolutes Vakuum) = Kolbenweglinie",
                      en="zero line (absolute vacuum) = piston-path line")
    lines = draw_card(b, cover, prefix="card.", head=A, crank=B, axis=base, de="der Deckelseite", en="of the cover side")
    if crank is not None:
        other = draw_card(b, crank, prefix="crank.", head=A, crank=B, axis=base, de="der Kurbelseite",
                          en="of the crank side")
    else:
        other = draw_card(b, cover, prefix="crank.", given_prefix="card.", head=B, crank=A, axis=base, mirrored=True,
                          up=(A, B), de="der Kurbelseite (die der Deckelseite gespiegelt)",
                          en="of the crank side (the cover side's mirrored)")
    n = divisions
    up = ("toward", None, None, 0.0, 1.0)
    with b.group(f"stroke divided into {n} parts; the pressures read on every ordinate",
                 f"Hub in {n} Teile geteilt; die Drücke auf jeder Ordinate abgelesen"):
        marks = b.divide_segment("T", A, B, n, line=base)
        for k, m in enumerate(marks, start=1):
            o = b.erect_perpendicular(f"v{k}", m, base, A)
            for tag, line, what in (("fE", lines.forward, ("Deckelseite, Hingang", "cover side, forward stroke")),
                                    ("rW", lines.back, ("Deckelseite, Rückgang", "cover side, return stroke")),
                                    ("fW", other.forward, ("Kurbelseite, Hingang", "crank side, forward stroke")),
                                    ("rE", other.back, ("Kurbelseite, Rückgang", "crank side, return stroke"))):
                b.intersect(f"{tag}{k}", o, line, rule=up, role="result", de=f"Druck {what[0]} bei {k}/{n}",
                            en=f"pressure, {what[1]}, at {k}/{n}")
    proto = b.protocol()
    return Figure(proto, proto.replay(givens))


def card_checks(fig: Figure) -> list[Check]:
    """Every plotted point at its given (x, p); every reading on the straightedge line between two points."""
    from .indicator_card import card_pair

    g = fig.replay.givens
    n = fig.params["divisions"]
    cover, crank = card_pair(g)
    tol = EUCLIDEAN_TOLERANCE * max(1.0, max(p for c in (cover, crank) for p in c.forward[1] + c.back[1])) * 10
    checks = []
    for i, (x, p) in enumerate(cover.points):
        name = "card.C%d" % i
        if name not in fig.replay.made_by():
            continue  # a point on the zero line is its foot
        checks.append(Check(f"card point {i}: x", abscissa(fig, name), x, EUCLIDEAN_TOLERANCE,
                            "laid off with the compass from the dead centre", "stroke"))
        checks.append(Check(f"card point {i}: p", pressure(fig, name), p, tol, "laid off up the perpendicular", "at"))
    for k in range(1, n):
        x = abscissa(fig, f"fE{k}")
        for tag, side, stroke, what in (("fE", cover, "forward", "cover side forward"),
                                        ("rW", cover, "return", "cover side return"),
                                        ("fW", crank, "forward", "crank side forward"),
                                        ("rE", crank, "return", "crank side return")):
            checks.append(Check(f"{what} at {k}/{n}", pressure(fig, f"{tag}{k}"), side.pressure(x, stroke), tol,
                                "the ordinate meets the straightedge line between two digitised points", "at"))
    return checks


def indicator_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as Baumann writes them (P, P₀, s₁, s₀, s₃), or a digitised card's; the pressure scale."""
    g = fig.replay.givens
    if "admission" not in g:  # a digitised card, not Baumann's idealised diagram
        return card(fig, lang) + [scale(g, lang, "r")]
    return diagram(g, lang) + [scale(g, lang, "r")]


INDICATOR = register(Construction(
    name="indicator-diagram",
    title=Caption("Ideelles Dampfdiagramm mit Expansions- und Kompressionshyperbel",
                  "Idealised indicator diagram with expansion and compression hyperbolas"),
    source="seed 004 (Baumann 1902, Fig. 25); seed 001, Abb. 1054",
    build=lambda r, filling, clearance, admission, back_pressure, compression, pressure_unit, divisions, indicator,
    indicator_crank_side: build_indicator_card(r=r, pressure_unit=pressure_unit, divisions=divisions,
                                               indicator=indicator, crank_side=indicator_crank_side)
    if indicator or indicator_crank_side else build_indicator(
        r=r, filling=filling, clearance=clearance, admission=admission, back_pressure=back_pressure,
        compression=compression, pressure_unit=pressure_unit, divisions=divisions),
    checks=lambda fig: card_checks(fig) if fig.params.get("cards") else indicator_checks(fig),
    defaults={"r": 1.0, **BAUMANN, "pressure_unit": 0.12, "divisions": 10, "indicator": "",
              "indicator_crank_side": ""},
    book_params=({}, {"filling": 0.4}),  # Baumann's two worked cases: s1 = 10 % and 40 % (drawn for P = 7.85 at)
    structural=("divisions", "filling", "compression", "indicator", "indicator_crank_side"),
    cites=(Cite(BAUMANN_1902, "Fig. 25"),),
    wording=indicator_wording,
    plate=indicator_plate,
    validator=_validate,
    help=OPTION_HELP,
))
