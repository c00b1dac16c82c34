"""The indicator diagram's parts, shared by every construction that draws one (Baumann 1902, Fig. 25).

The indicator diagram (:mod:`construct.constructions.indicator`), the piston force, the tangential force and
the flywheel's rim draw the same diagram: :func:`indicator_frame` adds its fixed lines to any
:class:`~construct.kernel.instruments.Builder` whose givens carry ``filling``, ``clearance``, ``admission``,
``back_pressure``, ``compression`` and ``pressure_unit`` (:func:`indicator_givens` checks them);
:func:`pressures_at` then constructs the steam-line point and the back-pressure point on any ordinate, each
point of a hyperbola from a rectangle's diagonal (:func:`hyperbola_point`, pv = const), its tangent by the
doubled subtangent (:func:`hyperbola_tangent`).  :func:`steam_pressure` and :func:`back_pressure` are the
model the constructed pressures are checked against.

>>> g = {**BAUMANN, "pressure_unit": 0.12}
>>> round(steam_pressure(1.0, g), 12), round(back_pressure(1.0, g), 12)  # 8 * 0.15 / 1.05, 0.15 * 0.35 / 0.05
(1.142857142857, 1.05)
>>> indicator_givens(**{**g, "filling": 1.5})
Traceback (most recent call last):
construct.kernel.errors.InvalidParameter: filling s1/s must be less than 1 (a fraction of the stroke), got 1.5
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Mapping, Sequence

import numpy as np

from ..kernel.errors import InvalidParameter
from ..kernel.instruments import Builder
from . import bounded, positive
from .domain import CLEARANCE, DRAWN_LENGTH, PRESSURE, STROKE_FRACTION

__all__ = ["BAUMANN", "indicator_givens", "IndicatorDiagram", "indicator_frame", "square", "hyperbola_point",
           "pressures_at", "hyperbola_tangent", "steam_pressure", "back_pressure"]

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
            out["steam_tangent"] = hyperbola_tangent(b, d, out["steam"], ordinate, d.Z0, f"{p}tE{tag}")
    if x <= 1.0 - d.compression + edge:
        out["back"] = back(f"{p}R{tag}")
    else:
        out["back"] = compression(f"{p}R{tag}")
        if tangents:
            out["back_tangent"] = hyperbola_tangent(b, d, out["back"], ordinate, d.Z1, f"{p}tR{tag}")
    return out


def hyperbola_tangent(b: Builder, d: IndicatorDiagram, point: str, ordinate: str, corner: str, name: str) -> str:
    """Tangent of pv = const at a point: it meets the zero line at twice the foot's distance from the corner."""
    foot = b.intersect(f"{name}.F", ordinate, d.base, rule=("only",), de="Fußpunkt", en="foot")
    k = b.circle_through(f"{name}.k", foot, corner, de="Abstand vom Eckpunkt verdoppelt",
                         en="distance from the corner doubled")
    T = b.intersect(f"{name}.T", d.base, k, rule=("farther", corner), de="Subtangente gleich der Abszisse",
                    en="subtangent equals the abscissa")
    return b.line(name, point, T, de="Tangente der Hyperbel", en="tangent of the hyperbola")


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
