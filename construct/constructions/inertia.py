"""The curve of the inertia pressures ("Darstellung der Massendrücke"), seed 000, Anhang II.

Over the stroke D0-D1 (abscissa: the piston path from the rod arcs, as in
Fig. 77) the ordinate at each crank position is the inertia pressure of
Gl. (4_1), q = (F/f)(cos w + lam cos 2w), drawn in the pressure scale (the
given length ``pressure_unit`` stands for 1 kg/cm^2), up = positive.  Every
ordinate is *constructed*:

* r cos w is the foot of the crank point on the stroke line (the chord to its
  mirror image, as for the infinite rod);
* r cos 2w is the foot of the doubled-angle point (the chord D0-P stepped on
  once more round the crank circle);
* lam r cos 2w comes out of the proportional angle (module
  :mod:`construct.kernel.proportional`): its vertex S lies on the perpendicular to
  the stroke through O with SO = L, and its scale line ``gr`` at the distance
  r from S: the ray from S through a point of the stroke line meets ``gr``
  at lam times its offset;
* the two are added on ``gr`` by carrying lengths with the compass, and the
  same proportional angle carries the sum onto the scale line ``gf`` at the
  distance F/f (in the pressure scale) from S: the ordinate, taken with the
  compass to the perpendicular at the piston position.

Then the book's quick method (Anhang II c, d): the seven characteristic
points q1..q7 (the square roots in the positions of q6 and q7 by
Pythagoras), the infinite-rod line, the point D on both end tangents, the
tangents at 0, 90 and 180 degrees, and the curve a draftsman draws through
points and tangents (and the parabola enveloped by E-D-F), checked against
the analytic curve.

>>> fig = INERTIA.figure(rod_ratio=4.0, parts=6)
>>> round(ordinate(fig, "K0") / fig.replay.givens["pressure_unit"], 12)   # q1 = (F/f)(1 + r/L)
1.25
>>> round(ordinate(fig, "q5") / fig.replay.givens["pressure_unit"], 12)   # q5 = -m
-0.25
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from typing import Any, Mapping, Sequence

from .. import analytic
from ..checks import EUCLIDEAN_TOLERANCE, Check
from ..kernel.division import check_parts, divide_semicircle
from ..errors import DegenerateObject, GeometryError, InvalidParameter
from ..kernel.geometry import Line, Point
from ..kernel.instruments import Builder
from ..kernel.proportional import ProportionalAngle, Scale, carry_across, scale_line, vertex_on
from ..kernel.curves import _frame_of
from ..kernel.protocol import Caption
from . import Construction, Figure, positive, register, rod_ratio_param
from .crank import angle_tolerance, build_frame, crank_angle, point_name, rod_arcs

__all__ = [
    "INERTIA",
    "build_inertia",
    "inertia_checks",
    "ordinate",
    "abscissa",
    "curve_deviation",
    "acceleration_rows",
    "characteristic_point_rows",
    "q_at_crank_angle_rows",
]

# --------------------------------------------------------------------------
# The construction.
# --------------------------------------------------------------------------


@dataclass(frozen=True)
class _Ctx:
    O: str
    axis: str
    crank: str
    D0: str
    D1: str
    r: str
    L: str
    Ff: str
    vert: str
    top: str
    angle: ProportionalAngle
    gr: Scale
    gf: Scale


def _givens(r: Any, rod_ratio: Any, pressure_ratio: Any, pressure_unit: Any) -> dict[str, float]:
    return {"r": positive("crank radius r", r), "rod_ratio": rod_ratio_param(rod_ratio),
            "pressure_ratio": positive("pressure ratio F/f", pressure_ratio),
            "pressure_unit": positive("pressure-scale unit (drawn length of 1 kg/cm2)", pressure_unit)}


def _validate(givens: Mapping[str, float]) -> None:
    _givens(givens["r"], givens["rod_ratio"], givens["pressure_ratio"], givens["pressure_unit"])


def _setup(b: Builder, f: Mapping[str, str]) -> _Ctx:
    """The givens in the pressure scale, and the proportional angle with its vertex below O."""
    Ff = b.given_length("Ff", product=("pressure_ratio", "pressure_unit"),
                        de="F/f im Höhenmaßstabe der Dampfdrücke", en="F/f in the pressure scale")
    with b.group("proportional angle for r/L and F/f", "Proportionswinkel für r/L und F/f"):
        vert = b.perpendicular_bisector("vert", f["D0"], f["D1"])
        top = b.intersect("top", vert, f["circle"], rule=("toward", f["O"], None, 0.0, 1.0),
                          de="Kurbelstellung ω = 90°", en="crank at 90 degrees", labels={"top": "90°"})
        angle = vertex_on(b, "S", origin=f["O"], leg=vert, length=f["L"], rule=("toward", f["O"], None, 0.0, -1.0),
                          de="Scheitel S des Proportionswinkels: SO = L",
                          en="vertex S of the proportional angle: SO = L")
        gr = scale_line(b, angle, "gr", length=f["r"], toward=("toward", "S", f["O"]),
                        de="Marke r von S aus: Maßlinie für r/L", en="mark r from S: scale line for r/L")
        gf = scale_line(b, angle, "gf", length=Ff, toward=("toward", "S", f["O"]),
                        de="Marke F/f von S aus: Maßlinie für F/f", en="mark F/f from S: scale line for F/f")
    return _Ctx(f["O"], f["axis"], f["circle"], f["D0"], f["D1"], f["r"], f["L"], Ff, vert, top, angle, gr, gf)


def _project(b: Builder, c: _Ctx, name: str, Q: str, dc: str, what: str) -> str:
    """The foot of Q on the stroke line: the chord from Q to its mirror image (circle about a dead centre)."""
    k = b.circle_through(f"{name}.k", dc, Q, de=f"Kreis um den Totpunkt durch {what}",
                         en=f"circle about the dead centre through {what}")
    m = b.intersect(f"{name}.Q", k, c.crank, rule=("farther", Q), de=f"Spiegelpunkt von {what}",
                    en=f"mirror image of {what} in the stroke line")
    g = b.line(f"{name}.g", Q, m, de=f"Lot von {what} auf die Hubachse", en=f"perpendicular from {what} to the stroke line")
    return b.intersect(name, g, c.axis, rule=("only",), de=f"Fußpunkt {name}", en=f"foot {name}")


def _ordinate_line(b: Builder, c: _Ctx, name: str, X: str) -> str:
    """The perpendicular to the stroke line at X: a circle about X cuts it twice, their bisector."""
    with b.group(f"ordinate at {X}", f"Ordinate in {X}"):
        k = b.circle_radius(f"{name}.k", X, c.r, de=f"Kreis um {X} mit r", en=f"circle about {X} with radius r")
        a, a2 = b.intersect((f"{name}.A", f"{name}.B"), c.axis, k, rule=("toward", c.O, None, -1.0, 0.0))
        return b.perpendicular_bisector(name, a, a2)


def _value(b: Builder, c: _Ctx, tag: str, P: str, kind: str, dc_p: str, dc_2: str | None) -> str:
    """Construct (F/f)(cos w + lam cos 2w) for the crank point P; return its point on the F/f scale line.

    *kind* tells what the nominal angle makes exactly zero or a dead centre:
    "start" (P = D0), "end" (P = D1), "quarter" (90 degrees: no cos w term,
    the doubled point is D1), "octant" (45 or 135 degrees: no cos 2w term),
    "generic".
    """
    O, gr = c.O, c.gr
    Y = G = None
    with b.group(f"ordinate value at crank point {tag}", f"Ordinatenwert zum Kurbelpunkt {tag}"):
        # r cos w: the foot of the crank point.
        if kind == "start":
            Y = c.D0
        elif kind == "end":
            Y = c.D1
        elif kind != "quarter":
            Y = _project(b, c, f"Y{tag}", P, dc_p, tag)
        # r cos 2w: the doubled-angle point, then its foot.
        if kind in ("start", "end"):
            G = c.D0
        else:
            k = b.circle_segment(f"N{tag}.k", P, c.D0, P, de=f"Sehne A–{tag} von {tag} aus nochmals abgetragen",
                                 en=f"chord A–{tag} stepped on once more from {tag}")
            N = b.intersect(f"N{tag}", c.crank, k, rule=("farther", c.D0), de=f"Punkt N{tag} zum doppelten Winkel 2ω",
                            en=f"point N{tag} at the doubled angle 2w")
            if kind == "quarter":
                G = N  # 2w = 180 degrees: the doubled point is the dead centre itself
            elif kind != "octant":
                if dc_2 is None:  # angle not known in advance: the dead centre nearer to N as drawn now
                    dc_2 = c.D0 if b[N][0] * _dir(b, c) < b[c.O][0] * _dir(b, c) else c.D1
                G = _project(b, c, f"G{tag}", N, dc_2, f"N{tag}")
        A = W = None
        if Y is not None:
            kA = b.circle_segment(f"A{tag}.k", gr.origin, O, Y, de=f"r·cos ω = O{Y} auf die Maßlinie r getragen",
                                  en=f"r cos w = O{Y} carried to the scale line r")
            A = b.intersect(f"A{tag}", gr.line, kA, rule=("toward", O, Y), de=f"A{tag}: r·cos ω", en=f"A{tag}: r cos w")
        if G is not None:
            W = carry_across(b, c.angle, f"W{tag}", G, gr, de=f"W{tag}: r/L · r·cos 2ω (Proportionswinkel)",
                             en=f"W{tag}: r/L times r cos 2w (proportional angle)")
        if A is not None and W is not None:
            kZ = b.circle_segment(f"Z{tag}.k", A, gr.origin, W, de="r/L·r·cos 2ω mit dem Zirkel angesetzt",
                                  en="r/L r cos 2w added with the compass")
            Z = b.intersect(f"Z{tag}", gr.line, kZ, rule=("toward", gr.origin, W),
                            de=f"Z{tag}: r (cos ω + r/L cos 2ω)", en=f"Z{tag}: r (cos w + r/L cos 2w)")
        else:
            Z = A if A is not None else W
        assert Z is not None
        return carry_across(b, c.angle, f"V{tag}", Z, c.gf, de=f"V{tag}: F/f-mal genommen (Proportionswinkel)",
                            en=f"V{tag}: multiplied by F/f (proportional angle)")


def _dir(b: Builder, c: _Ctx) -> float:
    """+1 if the stroke line runs from D0 towards increasing x (the layout of :func:`crank.build_frame`)."""
    return 1.0 if b[c.D1][0] > b[c.D0][0] else -1.0


def _lay_off(b: Builder, c: _Ctx, tag: str, X: str, V: str, label: str | None = None) -> str:
    """Take the ordinate from the F/f scale line to the perpendicular at the piston position X."""
    ordl = _ordinate_line(b, c, f"ord{tag}", X)
    k = b.circle_segment(f"K{tag}.k", X, c.gf.origin, V, de=f"Ordinate mit dem Zirkel nach {X} getragen",
                         en=f"ordinate carried to {X} with the compass")
    return b.intersect(f"K{tag}", ordl, k, rule=("left", V, c.gf.origin), role="result",
                       de=f"Curvenpunkt K{tag} (oben positiv)", en=f"curve point K{tag} (up = positive)",
                       labels={f"K{tag}": label} if label else None)


def _piston(b: Builder, c: _Ctx, tag: str, P: str, *, label: str | None = None, role: str = "construction") -> str:
    """Rod arcs from one crank point (as in :func:`crank.rod_arcs`): its piston position."""
    with b.group(f"rod arcs from {tag}", f"Schubstangenbögen von {tag}"):
        arc = b.circle_radius(f"rod.{tag}", P, c.L, de=f"Bogen um {P} mit der Schubstangenlänge L",
                              en=f"arc about {P} with the rod length L")
        C = b.intersect(f"C.{tag}", arc, c.axis, rule=("toward", c.O, None, -1.0, 0.0), de="Kreuzkopf", en="crosshead")
        back = b.circle_radius(f"back.{tag}", C, c.L, de="mit L zurück auf den Hub", en="with L back onto the stroke")
        return b.intersect(f"X.{tag}", back, c.axis, rule=("toward", c.O, None, 1.0, 0.0), role=role,
                           de=f"Kolbenstellung zu {P}", en=f"piston position for {P}",
                           labels={f"X.{tag}": label} if label else None)


def _kind(k: int, n: int) -> str:
    if k == 0:
        return "start"
    if k == n:
        return "end"
    if 2 * k == n:
        return "quarter"
    if 4 * k == n or 4 * k == 3 * n:
        return "octant"
    return "generic"


def _root_point(b: Builder, c: _Ctx, tag: str, H: str, what: tuple[str, str]) -> str:
    """r cos w = (sqrt(L^2 + OH^2) - L) / 4 as a crank point: hypotenuse SH, less SO = L, halved twice."""
    O = c.O
    with b.group(f"crank angle of {tag}: {what[1]}", f"Kurbelwinkel zu {tag}: {what[0]}"):
        k = b.circle_through(f"{tag}.h", c.angle.vertex, H, de=f"Kreis um S durch {H}: S{H} = √(L² + O{H}²)",
                             en=f"circle about S through {H}: S{H} = sqrt(L^2 + O{H}^2)")
        N = b.intersect(f"{tag}.N", c.vert, k, rule=("toward", O, None, 0.0, 1.0),
                        de="ON = SH − L", en="ON = SH - L")
        half = b.midpoint(f"{tag}.N2", O, N, through=c.vert)
        quarter = b.midpoint(f"{tag}.N4", O, half, through=c.vert)
        kf = b.circle_through(f"{tag}.fk", O, quarter, de="ein Viertel davon auf die Hubachse",
                              en="a quarter of it onto the stroke line")
        foot = b.intersect(f"{tag}.F", c.axis, kf, rule=("toward", O, c.D0), de="Fußpunkt: r·cos ω",
                           en="foot: r cos w")
        perp = _ordinate_line(b, c, f"{tag}.p", foot)
        q = "q" + tag[1:]  # the crank point of the characteristic point q6 (q7)
        return b.intersect(f"{tag}.P", perp, c.crank, rule=("toward", O, None, 0.0, 1.0),
                           de=f"Kurbelpunkt zu {q}", en=f"crank point for {q}", labels={f"{tag}.P": f"ω{tag[1:]}"})


#: What Fig. 78/79 show (regular expressions over object names): the stroke
#: with its dead centres and piston positions, the ordinates and the curve
#: points on them, the infinite-rod line, the characteristic points, D and the
#: three tangents, and the curve.  The crank circle, the proportional angle and
#: every helper stay in the frames and the player.
PLATE = (
    "axis", "D0", "D1", r"X\d+", r"ord\d+", r"K\d+", "inf", "Einf", "Finf", r"q\d", r"X\.c6", "D",
    r"tan\d+", "curve",
)

def build_inertia(*, rod_ratio: float, parts: int, method: str, r: float, pressure_ratio: float,
                  pressure_unit: float) -> Figure:
    givens = _givens(r, rod_ratio, pressure_ratio, pressure_unit)
    used = check_parts(parts, method)
    b = Builder("inertia-curve", givens, {"parts": parts, "method": used, "requested_method": method,
                                          "plate": PLATE})
    f = build_frame(b, result_circle=False)
    c = _setup(b, f)
    points = divide_semicircle(b, O=f["O"], D0=f["D0"], D1=f["D1"], circle=f["circle"], axis=f["axis"],
                               n=parts, method=used)
    for k, p in enumerate(points[1:-1], start=1):
        b.set_label(p, str(k))  # numbered as on the crank figure; the dead centres are A and B
    rod_arcs(b, f, points)
    n = parts
    # a) The ordinates by construction, one crank point after the other.
    with b.group(f"ordinates at all {n + 1} piston positions", f"Ordinaten an allen {n + 1} Kolbenstellungen"):
        for k, P in enumerate(points):
            kind = _kind(k, n)
            dc_p = c.D0 if 2 * k <= n else c.D1
            dc_2 = c.D0 if (4 * k < n or 4 * k > 3 * n) else c.D1  # the dead centre nearer to the doubled point
            with b.group(f"ordinate at point {k}", f"Ordinate zu Punkt {k}"):
                V = _value(b, c, str(k), P, kind, dc_p, dc_2)
                _lay_off(b, c, str(k), f"X{k}", V, {0: "q1", n: "q2"}.get(k))
    _characteristic(b, c, n)
    proto = b.protocol()
    return Figure(proto, proto.replay(givens))


def _characteristic(b: Builder, c: _Ctx, n: int) -> None:
    O = c.O
    down, up = ("toward", O, None, 0.0, -1.0), ("toward", O, None, 0.0, 1.0)
    with b.group("straight line for the infinite rod", "Gerade für unendliche Schubstangenlänge"):
        kE = b.circle_radius("Einf.k", c.D0, c.Ff, de="F/f in A aufgetragen", en="F/f laid off at A")
        Einf = b.intersect("Einf", "ord0", kE, rule=up, de="Anfangsordinate F/f bei unendlicher Stange",
                           en="initial ordinate F/f for the infinite rod", labels={"Einf": "E∞"})
        kF = b.circle_radius("Finf.k", c.D1, c.Ff, de="F/f in B aufgetragen", en="F/f laid off at B")
        Finf = b.intersect("Finf", f"ord{n}", kF, rule=down, de="Endordinate −F/f bei unendlicher Stange",
                           en="final ordinate −F/f for the infinite rod", labels={"Finf": "F∞"})
        inf = b.line("inf", Einf, Finf, role="result", de="Gerade der Massendrücke für unendliche Stangenlänge",
                     en="inertia pressures for the infinite rod: a straight line")
    with b.group("m = r/L · F/f", "m = r/L · F/f"):
        m = carry_across(b, c.angle, "Vm", "W0", c.gf, de="m = r/L·F/f: r/L·r (W0) F/f-mal genommen",
                         en="m = r/L F/f: r/L r (W0) multiplied by F/f")
    with b.group("characteristic points q3 and q4 (45 and 135 degrees)", "Charakteristische Punkte q3 und q4 (45°, 135°)"):
        for tag, (a, z), dc, label in (("c45", (c.D0, c.top), c.D0, "q3"), ("c135", (c.top, c.D1), c.D1, "q4")):
            P = b.bisect_arc(tag, O, a, z, c.crank)
            b.set_label(P, tag[1:] + "°")
            X = _piston(b, c, tag, P)
            foot = _project(b, c, f"{tag}.Y", P, dc, tag)
            I = b.intersect(f"{tag}.I", f"{tag}.Y.g", inf, rule=("only",),
                            de="Ordinate für unendliche Stange (hier gleich)", en="ordinate for the infinite rod (equal here)")
            ordl = _ordinate_line(b, c, f"{tag}.o", X)
            k = b.circle_segment(f"{label}.k", X, foot, I, de="Ordinate nach der Kolbenstellung getragen",
                                 en="ordinate carried to the piston position")
            b.intersect(label, ordl, k, rule=("toward", foot, I), role="result", labels={label: label},
                        de=f"{label} = F/f·cos ω", en=f"{label} = F/f cos w")
    with b.group("characteristic point q5 = -m (90 degrees)", "Charakteristischer Punkt q5 = −m (90°)"):
        X = _piston(b, c, "c90", c.top)
        ordl = _ordinate_line(b, c, "c90.o", X)
        k = b.circle_segment("q5.k", X, c.gf.origin, m, de="m nach unten aufgetragen", en="m laid off downwards")
        q5 = b.intersect("q5", ordl, k, rule=down, role="result", labels={"q5": "q5"}, de="q5 = −m", en="q5 = -m")
    with b.group("characteristic point q6 = 0", "Charakteristischer Punkt q6 = 0"):
        k = b.circle_segment("h2.k", O, c.D0, c.top, de="Kreis um O mit der Sehne r√2", en="circle about O with the chord r sqrt 2")
        h2 = b.intersect("h2", c.axis, k, rule=("toward", O, None, 1.0, 0.0))
        k = b.circle_through("h8.k", h2, O, de="verdoppelt: 2√2·r", en="doubled: 2 sqrt 2 r")
        h8 = b.intersect("h8", c.axis, k, rule=("farther", O))
        P6 = _root_point(b, c, "c6", h8, ("cos ω = (√(L² + 8r²) − L)/4r", "cos w = (sqrt(L^2 + 8 r^2) - L) / 4r"))
        _piston(b, c, "c6", P6, label="q6", role="result")
    with b.group("characteristic point q7 = +m", "Charakteristischer Punkt q7 = +m"):
        k = b.circle_segment("h4.k", O, c.D0, c.D1, de="Kreis um O mit dem Hub 2r", en="circle about O with the stroke 2r")
        h4 = b.intersect("h4", c.axis, k, rule=("toward", O, None, 1.0, 0.0))
        k = b.circle_through("h16.k", h4, O, de="verdoppelt: 4r", en="doubled: 4r")
        h16 = b.intersect("h16", c.axis, k, rule=("farther", O))
        P7 = _root_point(b, c, "c7", h16, ("cos ω = (√(L² + 16r²) − L)/4r", "cos w = (sqrt(L^2 + 16 r^2) - L) / 4r"))
        X = _piston(b, c, "c7", P7)
        ordl = _ordinate_line(b, c, "c7.o", X)
        k = b.circle_segment("q7.k", X, c.gf.origin, m, de="m nach oben aufgetragen", en="m laid off upwards")
        b.intersect("q7", ordl, k, rule=up, role="result", labels={"q7": "q7"}, de="q7 = +m", en="q7 = +m")
    with b.group("point D and the tangents at 0, 90 and 180 degrees", "Punkt D und die Tangenten bei 0°, 90° und 180°"):
        E, F = "K0", f"K{n}"
        ef = b.line("EF", E, F, de="EF ist parallel zur Geraden für unendliche Stange",
                    en="EF is parallel to the infinite-rod line")
        Dx = b.intersect("Dx", ef, c.axis, rule=("only",), de="EF schneidet die Achse bei x = (1 + r/L)·r",
                         en="EF crosses the axis at x = (1 + r/L) r")
        ordD = _ordinate_line(b, c, "ordD", Dx)
        I = b.intersect("D.I", ordD, inf, rule=("only",), de="dort hat die Gerade die Ordinate −m",
                        en="there the infinite-rod line has the ordinate -m")
        k = b.circle_segment("D.k1", I, c.gf.origin, m, de="nochmals m", en="m once more")
        D2 = b.intersect("D.2", ordD, k, rule=("farther", Dx))
        k = b.circle_segment("D.k2", D2, c.gf.origin, m, de="und nochmals m", en="and m once more")
        D = b.intersect("D", ordD, k, rule=("farther", I), role="result", labels={"D": "D"},
                        de="D: Ordinate −3m, auf beiden Endtangenten", en="D: ordinate -3m, on both end tangents")
        t0 = b.line("tan0", E, D, role="result", de="Tangente in q1 (ω = 0°)", en="tangent at q1 (w = 0)")
        t180 = b.line("tan180", D, F, role="result", de="Tangente in q2 (ω = 180°)", en="tangent at q2 (w = 180)")
        t90 = b.parallel_through("tan90", q5, "Einf", "Finf", role="result")
    with b.group("the curve drawn through points and tangents", "Die Curve durch Punkte und Tangenten gezogen"):
        pts = [f"K{k}" for k in range(n + 1)]
        tangents = {0: t0, n: t180}
        if n % 2 == 0:
            tangents[n // 2] = t90
        b.french_curve("curve", c.axis, pts, tangents, role="result",
                     de="Curve der Massendrücke durch die Punkte K mit dem Curvenlineal",
                     en="curve of the inertia pressures through the points K with a French curve")
        seven = ["K0", "q3", "q7", "X.c6", "q5", "q4", F]
        b.french_curve("curve7", c.axis, seven, {0: t0, 4: t90, 6: t180}, role="construction",
                     de="Curve durch die sieben charakteristischen Punkte und drei Tangenten",
                     en="curve through the seven characteristic points along the three tangents")
        b.record("curve", "parabola_envelope", (E, D, F), ("parabola",), {},
                 "Parabel als Einhüllende auf q1–D–q2", "parabola enveloped by q1–D–q2", role="construction")


# --------------------------------------------------------------------------
# Measurements on the figure.
# --------------------------------------------------------------------------


def _axis_frame(fig: Figure) -> tuple[Point, float, float, float, float]:
    o = fig.replay["D0"]
    ux, uy, nx, ny = _frame_of(fig.replay["axis"])
    return o, ux, uy, nx, ny


def ordinate(fig: Figure, name: str) -> float:
    """Signed distance of a point from the stroke line (up = positive), measured on the figure."""
    o, ux, uy, nx, ny = _axis_frame(fig)
    p = fig.replay[name]
    return (p[0] - o[0]) * nx + (p[1] - o[1]) * ny


def abscissa(fig: Figure, name: str) -> float:
    """Distance of a point's foot from the head-end dead centre along the stroke, as a fraction of the stroke."""
    o, ux, uy, nx, ny = _axis_frame(fig)
    p = fig.replay[name]
    return ((p[0] - o[0]) * ux + (p[1] - o[1]) * uy) / o.distance(fig.replay["D1"])


def _slope(fig: Figure, line: str) -> float:
    """dy/dx of a drawn line in the frame of the stroke line."""
    _, ux, uy, nx, ny = _axis_frame(fig)
    (px, py), (qx, qy) = fig.replay[line]
    return ((qx - px) * nx + (qy - py) * ny) / ((qx - px) * ux + (qy - py) * uy)


def _offset(fig: Figure, point: str, origin: str) -> float:
    """Signed offset of a point on a scale line from its origin, positive towards the head end (like r cos w)."""
    _, ux, uy, _, _ = _axis_frame(fig)
    p, o = fig.replay[point], fig.replay[origin]
    return -((p[0] - o[0]) * ux + (p[1] - o[1]) * uy)


def curve_deviation(fig: Figure, curve: str, per_segment: int = 64) -> float:
    """Largest vertical distance between a drawn curve and the analytic curve, in units of F/f.

    The drawn curve is sampled densely along its own parameter (*per_segment*
    points per Bézier segment, ends included); at each sample's abscissa the
    analytic curve has the ordinate of Gl. (4_1) at the crank angle of
    Gl. (h) for that piston path.  numpy does all samples at once.
    """
    g = fig.replay.givens
    r, L = g["r"], g["rod_ratio"] * g["r"]
    lam = r / L
    Ff = g["pressure_ratio"] * g["pressure_unit"]
    o, ux, uy, nx, ny = _axis_frame(fig)
    t = np.linspace(0.0, 1.0, per_segment + 1)[:, None]
    s = 1.0 - t
    weights = np.hstack([s ** 3, 3.0 * s * s * t, 3.0 * s * t * t, t ** 3])  # Bernstein basis
    segs = np.array([[(p.x, p.y) for p in seg] for seg in fig.replay[curve].segments()])  # (k, 4, 2)
    pts = np.einsum("tj,kjd->ktd", weights, segs).reshape(-1, 2)
    x = (pts[:, 0] - o.x) * ux + (pts[:, 1] - o.y) * uy
    y = (pts[:, 0] - o.x) * nx + (pts[:, 1] - o.y) * ny
    x = np.clip(x, 0.0, 2.0 * r)
    c = (x / (2.0 * r)) * (2.0 * L - x) / (x - r - L) + 1.0  # Gl. (h), as analytic.crank_angle_from_path
    w = np.arccos(np.clip(c, -1.0, 1.0))
    return float(np.max(np.abs(y - Ff * (np.cos(w) + lam * np.cos(2.0 * w)))) / Ff)


# --------------------------------------------------------------------------
# Checks.
# --------------------------------------------------------------------------


def _euclid(scale: float) -> float:
    return EUCLIDEAN_TOLERANCE * max(1.0, scale)


def inertia_checks(fig: Figure) -> list[Check]:
    n = fig.params["parts"]
    g = fig.replay.givens
    r, K = g["r"], g["rod_ratio"]
    lam, L = 1.0 / K, K * r
    Ff = g["pressure_ratio"] * g["pressure_unit"]
    stroke = 2.0 * r
    # Ordinates are compared in units of the stroke (the chain's float error is a fraction of the
    # figure's size) and in units of F/f (the pressure the ordinate means).
    q_scale = max(1.0, Ff * (1.0 + lam) / stroke)
    per_ff = max(1.0, stroke / Ff)
    checks: list[Check] = []
    made_by = fig.replay.made_by()
    for k in range(n + 1):
        w = math.pi * k / n
        tol_w, why_w = angle_tolerance(fig, point_name(fig, k), made_by)
        dq = Ff * (1.0 + 4.0 * lam) / stroke  # |dq/dw| <= (F/f)(1 + 4 lam), in strokes
        checks.append(Check(f"ordinate {k} (Gl. 4_1)", ordinate(fig, f"K{k}") / stroke,
                            Ff * analytic.inertia_two_term(w, lam) / stroke,
                            _euclid(q_scale) + dq * tol_w, f"Euclidean chain; {why_w} times |dq/dw|", "stroke"))
        checks.append(Check(f"abscissa {k} (rod arcs)", abscissa(fig, f"K{k}"),
                            analytic.piston_path_exact(w, r, L) / stroke,
                            EUCLIDEAN_TOLERANCE + 0.5 * (1.0 + lam) * tol_w,
                            "rod arcs are Euclidean; division error times |dx/dw|", "stroke"))
        bound = 2.5 * lam ** 3 / (1.0 - lam * lam) ** 2.5
        checks.append(Check(f"ordinate {k} vs exact acceleration (information)", ordinate(fig, f"K{k}") / Ff,
                            analytic.inertia_exact(w, lam), bound + _euclid(per_ff) + (1.0 + 4.0 * lam) * tol_w,
                            "Gl. (4_1) drops the lam^3 terms: |exact - two-term| <= 2.5 lam^3 / (1 - lam^2)^2.5",
                            "F/f"))
    c6 = analytic.zero_crossing_cos(lam)
    c7 = analytic.plus_m_cos(lam)
    points = (("q1", "D0", "K0", 0.0, 1.0 + lam), ("q2", "D1", f"K{n}", math.pi, -(1.0 - lam)),
              ("q3", "c45", "q3", math.pi / 4, math.sqrt(0.5)), ("q4", "c135", "q4", 3 * math.pi / 4, -math.sqrt(0.5)),
              ("q5", "top", "q5", math.pi / 2, -lam), ("q6", "c6.P", "X.c6", math.acos(c6), 0.0),
              ("q7", "c7.P", "q7", math.acos(c7), lam))
    for label, crank_point, point, w, q in points:
        checks.append(Check(f"{label} crank angle", crank_angle(fig, crank_point), w, 10 * EUCLIDEAN_TOLERANCE,
                            "Euclidean (square roots by Pythagoras); the angle is read off a foot", "rad"))
        checks.append(Check(f"{label} position", abscissa(fig, point), analytic.piston_path_exact(w, r, L) / stroke,
                            EUCLIDEAN_TOLERANCE, "Euclidean: rod arcs from the constructed crank point", "stroke"))
        checks.append(Check(f"{label} ordinate", ordinate(fig, point) / Ff, q, _euclid(per_ff),
                            "Euclidean chain; the book's value for F/f = 1", "F/f"))
    # Tangents (Gl. i with its sign), as r dq/dx in units of F/f: the book's "r tg beta".
    slope_tol = 10 * _euclid(per_ff)  # positions to 1e-12 of the stroke over bases of at least a tenth of it
    for line, w in (("tan0", 0.0), ("tan90", math.pi / 2), ("tan180", math.pi)):
        checks.append(Check(f"tangent at {round(math.degrees(w))} deg (r tg beta)", _slope(fig, line) * r / Ff,
                            analytic.inertia_slope(w, r, lam) * r, slope_tol,
                            "Euclidean; Gl. (i): r tg beta = -(F/f)(1 + 4 lam cos w)/(1 + lam cos w)", "F/f"))
    checks.append(Check("EF parallel to the infinite-rod line (r tg beta)", _slope(fig, "EF") * r / Ff, -1.0, slope_tol,
                        "E and F differ by 2 F/f over the stroke", "F/f"))
    checks.append(Check("D abscissa", abscissa(fig, "D"), (1.0 + lam) / 2.0, EUCLIDEAN_TOLERANCE,
                        "EF crosses the axis at x = (1 + lam) r", "stroke"))
    checks.append(Check("D ordinate", ordinate(fig, "D") / Ff, -3.0 * lam, _euclid(per_ff),
                        "D lies on both end tangents at -3m", "F/f"))
    checks.append(Check("m (proportional angle)", fig.replay["gf.U"].distance(fig.replay["Vm"]) / Ff, lam,
                        _euclid(per_ff), "r/L then F/f through the proportional angle", "F/f"))
    checks.append(Check("m (dead-centre ordinates, finite less infinite rod)",
                        fig.replay["Einf"].distance(fig.replay["K0"]) / Ff, lam, _euclid(per_ff),
                        "q1 - F/f = m (seed 000 c)", "F/f"))
    # The curves as drawn: how far they stray from the analytic curve.
    para = _parabola_bound(lam)
    checks.append(Check("parabola E-D-F vs analytic curve (max, F/f)", curve_deviation(fig, "parabola"), 0.0,
                        para + 1e-9,
                        f"the parabola is exactly the curve over Gl. (1); the rod arcs differ by <= lam^3 r/(8(1 - lam^2)), "
                        f"times the largest slope: {para:.2e}", "F/f"))
    checks.append(Check("seven-point curve vs analytic curve (max, F/f)", curve_deviation(fig, "curve7"), 0.0,
                        max(DRAWING_ACCURACY, 3.0 * para), SEVEN_POINT_WHY, "F/f"))
    checks.append(Check(f"curve through the {n + 1} points vs analytic curve (max, F/f)", curve_deviation(fig, "curve"),
                        0.0, _division_curve_tolerance(n, lam), DIVISION_CURVE_WHY, "F/f"))
    return checks


def _steepest(lam: float) -> float:
    """The largest |r dq/dx| / (F/f) on the curve: (1 + 4 lam c)/(1 + lam c) is monotone in c = cos w."""
    return max((1.0 + 4.0 * lam) / (1.0 + lam), abs(1.0 - 4.0 * lam) / (1.0 - lam))


def _parabola_bound(lam: float) -> float:
    """Largest vertical gap between the E-D-F parabola and the curve over the exact piston path, in F/f.

    Over the piston path of Gl. (1) the curve (x(c), q(c)), c = cos w, is
    quadratic in c: a parabola through E and F touching ED and DF, i.e. the
    parabola itself.  The exact path differs by at most lam^3 r / (8 (1 - lam^2))
    (series remainder); by the mean value theorem the ordinates then differ by
    at most that times the largest slope, (1 + 4 lam c)/(1 + lam c) at c = +-1.
    """
    return _steepest(lam) * lam ** 3 / (8.0 * (1.0 - lam * lam))


#: What a plate of this kind is read to: a quarter of a millimetre on an F/f of 25 mm.
DRAWING_ACCURACY = 0.01
SEVEN_POINT_WHY = ("no a-priori bound (interior slopes guessed from neighbours, as with a French curve); "
                   "it cannot beat its own parabola: 3 times the parabola's bound, never below the drawing "
                   "accuracy 1/100 F/f (measured ratio to that bound 1.1-3 for L/r = 4-12)")
DIVISION_CURVE_WHY = ("estimate, not a proof: a cubic through points pi/n apart errs like (pi/n)^3 times the "
                      "steepness of the curve; factor 2 margin (measured 5-400 times smaller for L/r 1.01-6)")


def _division_curve_tolerance(n: int, lam: float) -> float:
    return 2.0 * (math.pi / n) ** 3 * _steepest(lam)


def inertia_plate(fig: Figure) -> dict:
    """Fig. 78/79: the curve heavy, tangents thin, the infinite-rod line dash-dotted and lettered,
    F/f and m dimensioned, the pressure scale beside the diagram, the signs of the zones.

    Positions are the constructed points; the scale bar is the given drawn length of 1 kg/cm².
    """
    R = fig.replay
    n = fig.params["parts"]
    D0, D1, O = R["D0"], R["D1"], R["O"]
    r = O.distance(D1)
    E, F = R["Einf"], R["Finf"]
    unit = fig.replay.givens["pressure_unit"]
    foot5 = R["X.c90"]
    q5 = R["q5"]
    t = 0.42
    on_inf = (E[0] + t * (F[0] - E[0]), E[1] + t * (F[1] - E[1]))
    slope = math.degrees(math.atan2(F[1] - E[1], F[0] - E[0]))
    up, down = R[f"K{max(1, n // 6)}"], R[f"K{n - max(1, n // 6)}"]
    furniture = [
        {"kind": "dimension", "a": tuple(D0), "b": tuple(E), "text": "F/f", "offset": 0.12 * r},
        {"kind": "dimension", "a": tuple(foot5), "b": tuple(q5), "text": "m", "offset": -0.1 * r},
        {"kind": "lettering", "at": (on_inf[0] + 0.06 * r, on_inf[1] + 0.09 * r), "text": "L = ∞", "angle": slope},
        {"kind": "scale", "origin": (D1[0] + 0.2 * r, 0.0), "end": (D1[0] + 0.2 * r, unit), "text": "1 kg/cm²"},
        {"kind": "sign", "at": (up[0], 0.4 * up[1]), "text": "+"},
        {"kind": "sign", "at": (down[0], 0.4 * down[1]), "text": "−"},
    ]
    looks = {"curve": "heavy", "tan0": "thin", "tan90": "thin", "tan180": "thin", "inf": "dashdot"}
    return {"looks": looks, "furniture": furniture}


INERTIA = register(Construction(
    name="inertia-curve",
    title=Caption("Curve der Massendrücke", "Curve of the inertia pressures"),
    source="seed 000, Anhang II a, c, d (Gl. 4_1, Tabelle 1, Fig. 78/79)",
    build=lambda rod_ratio, parts, method, r, pressure_ratio, pressure_unit: build_inertia(
        rod_ratio=rod_ratio, parts=parts, method=method, r=r, pressure_ratio=pressure_ratio,
        pressure_unit=pressure_unit),
    checks=inertia_checks,
    defaults={"rod_ratio": 5.0, "parts": 18, "method": "auto", "r": 1.0, "pressure_ratio": 1.0, "pressure_unit": 0.8},
    book_params=({"rod_ratio": 4.0}, {"rod_ratio": 5.0}, {"rod_ratio": 6.0}),
    structural=("parts", "method"),
    extra={"plate": inertia_plate},
), validate=_validate)


# --------------------------------------------------------------------------
# Tables measured on the construction (for 'construct table').
# --------------------------------------------------------------------------


def _table_figure(rod_ratio: float, parts: int) -> Figure:
    """The construction for F/f = 1 with 1 kg/cm^2 drawn as long as the crank radius."""
    return INERTIA.figure(rod_ratio=rod_ratio, parts=parts, pressure_ratio=1.0, pressure_unit=1.0, r=1.0)


def _first(fig: Figure, *names: str) -> str:
    return next(n for n in names if n in fig.replay)


def acceleration_rows(rod_ratio: float, step_deg: float = 10.0) -> list[dict[str, Any]]:
    """Tabelle 1 for one rod ratio, every value read off the construction (F/f = 1).

    cos w and cos 2w are the feet of the crank point and of the doubled-angle
    point (where the angle puts that point on the stroke line or on the
    perpendicular through O, the point itself is read); r/L cos 2w is read on
    the proportional angle's scale line r; q is the ordinate of the curve point.

    >>> rows = acceleration_rows(4.0, 30.0)
    >>> [(row["omega_deg"], round(row["q"], 4)) for row in rows][:3]
    [(0.0, 1.25), (30.0, 0.991), (60.0, 0.375)]
    """
    step = positive("angle step", step_deg)
    n = round(180.0 / step)
    if n < 1 or abs(n * step - 180.0) > 1e-9:
        raise InvalidParameter(f"the angle step must divide 180 degrees, got {step_deg!r}")
    fig = _table_figure(rod_ratio, n)
    r = fig.replay.givens["r"]
    ratio = fig.replay["S"].distance(fig.replay["gr.U"]) / fig.replay["S"].distance(fig.replay["O"])
    rows = []
    for k in range(n + 1):
        P = point_name(fig, k)
        foot = _first(fig, f"Y{k}", {0: "D0", n: "D1"}.get(k, P))
        double = _first(fig, f"G{k}", f"N{k}", "D0")
        if f"W{k}" in fig.replay:
            lam_cos = _offset(fig, f"W{k}", "gr.U") / r
        else:  # the doubled point lies on the leg of the proportional angle: its ray is the leg itself
            lam_cos = _offset(fig, double, "O") / r * ratio
        rows.append({"rod_ratio": float(rod_ratio), "omega_deg": 180.0 * k / n,
                     "cos_omega": _offset(fig, foot, "O") / r, "cos_2omega": _offset(fig, double, "O") / r,
                     "lambda_cos_2omega": lam_cos, "q": ordinate(fig, f"K{k}") / fig.replay.givens["pressure_unit"]})
    return rows


def _characteristic_names(n: int) -> tuple[tuple[str, str, str], ...]:
    """(label, crank point, point of the curve) for q1..q7."""
    return (("q1", "D0", "K0"), ("q2", "D1", f"K{n}"), ("q3", "c45", "q3"), ("q4", "c135", "q4"),
            ("q5", "top", "q5"), ("q6", "c6.P", "X.c6"), ("q7", "c7.P", "q7"))


def characteristic_point_rows(rod_ratio: float) -> list[dict[str, Any]]:
    """The seven characteristic points (seed 000 c) measured on the construction, F/f = 1.

    >>> rows = characteristic_point_rows(5.0)   # the book prints .4558 and .3689 (last digit off)
    >>> [(row["point"], round(row["x"], 4), round(row["q"], 4)) for row in rows][5:]
    [('q6', 0.4557, 0.0), ('q7', 0.3688, 0.2)]
    """
    fig = _table_figure(rod_ratio, 6)
    u = fig.replay.givens["pressure_unit"]
    return [{"point": label, "omega_deg": math.degrees(crank_angle(fig, crank_point)), "x": abscissa(fig, point),
             "q": ordinate(fig, point) / u} for label, crank_point, point in _characteristic_names(6)]


def build_q_at_stroke_fractions(*, rod_ratio: float, divisions: int, r: float = 1.0, pressure_ratio: float = 1.0,
                                pressure_unit: float = 1.0) -> Figure:
    """Tabelle 2: the stroke in equal parts, the rod swung back to the crank circle, q constructed there."""
    givens = _givens(r, rod_ratio, pressure_ratio, pressure_unit)
    if isinstance(divisions, bool) or not isinstance(divisions, int) or not 1 <= divisions <= 1000:
        raise InvalidParameter(f"number of stroke divisions must be a whole number from 1 to 1000, got {divisions!r}")
    b = Builder("inertia-stroke-fractions", givens, {"divisions": divisions})
    f = build_frame(b)
    c = _setup(b, f)
    m = divisions
    with b.group(f"stroke divided into {m} equal parts", f"Hub in {m} gleiche Teile geteilt"):
        marks = [c.D0] + (b.divide_segment("x", c.D0, c.D1, m, line=c.axis) if m > 1 else []) + [c.D1]
    for j, x in enumerate(marks):
        with b.group(f"q at {j}/{m} of the stroke", f"q zu {j}/{m} Hub"):
            if j in (0, m):
                P, kind = (c.D0, "start") if j == 0 else (c.D1, "end")
            else:
                arc = b.circle_radius(f"cross{j}.k", x, c.L, de=f"Bogen um {j}/{m} mit L", en=f"arc about mark {j}/{m} with L")
                C = b.intersect(f"C{j}", arc, c.axis, rule=("toward", c.O, None, -1.0, 0.0), de="Kreuzkopf", en="crosshead")
                back = b.circle_radius(f"rod{j}", C, c.L, de="mit L auf den Kurbelkreis", en="with L onto the crank circle")
                P = b.intersect(f"W{j}", back, c.crank, rule=("left", c.D0, c.D1), de=f"Kurbelstellung W{j}",
                                en=f"crank position W{j}")
                kind = "generic"
            dc_p = c.D0 if b[P][0] * _dir(b, c) < b[c.O][0] * _dir(b, c) else c.D1
            _value(b, c, f"t{j}", P, kind, dc_p, None)
    proto = b.protocol()
    return Figure(proto, proto.replay(givens))


def q_at_crank_angle_rows(rod_ratio: float, divisions: int = 10) -> list[dict[str, Any]]:
    """Tabelle 2: q (F/f = 1) at each division of the stroke, read off the proportional angle's F/f line.

    >>> [round(row["q"], 4) for row in q_at_crank_angle_rows(5.0, 10)][:3]
    [1.2, 0.9073, 0.6299]
    """
    fig = build_q_at_stroke_fractions(rod_ratio=rod_ratio, divisions=divisions)
    u = fig.replay.givens["pressure_unit"]
    marks = ["D0"] + [f"x{j}" for j in range(1, divisions)] + ["D1"]
    return [{"x": abscissa(fig, mark), "q": _offset(fig, f"Vt{j}", "gf.U") / u} for j, mark in enumerate(marks)]
