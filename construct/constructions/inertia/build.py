"""The inertia curve's construction steps (seed 000, Anhang II): every ordinate by compass and proportional angle.

See :mod:`construct.constructions.inertia` for the method as a whole.
"""

from __future__ import annotations

from dataclasses import dataclass

from typing import Any, Mapping

from ...kernel.division import check_parts, divide_semicircle
from ...kernel.instruments import Builder
from ...kernel.proportional import ProportionalAngle, Scale, carry_across, scale_line, vertex_on
from .. import Figure, bounded, rod_ratio_param
from ..domain import DRAWN_LENGTH, DRAWN_M, DRAWN_PRESSURE_RATIO, PRESSURE_RATIO
from ..crank import build_frame, rod_arcs

__all__ = ["build_inertia", "PLATE"]

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
    g = {"r": bounded("crank radius r", r, DRAWN_LENGTH), "rod_ratio": rod_ratio_param(rod_ratio),
         "pressure_ratio": bounded("pressure ratio F/f", pressure_ratio, PRESSURE_RATIO),
         "pressure_unit": bounded("pressure-scale unit (drawn length of 1 kg/cm2)", pressure_unit, DRAWN_LENGTH)}
    DRAWN_PRESSURE_RATIO.check("drawn F/f over r (pressure_ratio x pressure_unit / r)",
                               g["pressure_ratio"] * g["pressure_unit"] / g["r"])
    ff, r = g["pressure_ratio"] * g["pressure_unit"], g["r"]
    DRAWN_M.check("q5's offset from the infinite-rod line over its length (m r / (2 (r^2 + (F/f)^2)), "
                  "m = F/f / rod_ratio)", ff / g["rod_ratio"] * r / (2.0 * (r * r + ff * ff)))
    return g


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
        return b.intersect(f"{tag}.P", perp, c.crank, rule=("toward", O, None, 0.0, 1.0),
                           de=f"Kurbelpunkt zu q{tag[1:]}", en=f"crank point for q{tag[1:]}",
                           labels={f"{tag}.P": f"ω{tag[1:]}"})  # the crank position of q6 (q7)


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


#: Public names for the constructions that take the inertia ordinates over (four-stroke): the proportional
#: angle for r/L and F/f, the ordinate (F/f)(cos w + r/L cos 2w) of a crank point, and its kind.
inertia_scale = _setup
inertia_value = _value
value_kind = _kind
