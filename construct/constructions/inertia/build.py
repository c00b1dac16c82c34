"""The inertia curve's construction steps (seed 000, Anhang II): every ordinate by compass and proportional angle.

See :mod:`construct.constructions.inertia` for the method as a whole.
"""

from __future__ import annotations


from typing import Any, Mapping

from ...kernel.division import check_parts, divide_semicircle
from ...kernel.instruments import Builder
from ...kernel.letters import lowered
from ...kernel.proportional import carry_across
from .. import Figure, bounded, rod_ratio_param
from ..domain import DRAWN_LENGTH, DRAWN_M, DRAWN_PRESSURE_RATIO, PRESSURE_RATIO
from ..crank import build_frame, rod_arcs
# The shared ordinate steps, under the names this package has always used for them.
from ..ordinates import OrdinateFrame as _Ctx
from ..ordinates import inertia_setup as _setup
from ..ordinates import ordinate_line as _ordinate_line
from ..ordinates import ordinate_value as _value
from ..ordinates import point_kind as _kind
from ..ordinates import project as _project

__all__ = ["build_inertia", "PLATE"]

# --------------------------------------------------------------------------
# The construction.
# --------------------------------------------------------------------------


def inertia_givens(r: Any, rod_ratio: Any, pressure_ratio: Any, pressure_unit: Any) -> dict[str, float]:
    g = {"r": bounded("crank radius r", r, DRAWN_LENGTH), "rod_ratio": rod_ratio_param(rod_ratio),
         "pressure_ratio": bounded("pressure ratio F/f", pressure_ratio, PRESSURE_RATIO),
         "pressure_unit": bounded("pressure-scale unit (drawn length of 1 kg/cm2)", pressure_unit, DRAWN_LENGTH)}
    DRAWN_PRESSURE_RATIO.check("drawn F/f over r (pressure_ratio x pressure_unit / r)",
                               g["pressure_ratio"] * g["pressure_unit"] / g["r"])
    ff, r = g["pressure_ratio"] * g["pressure_unit"], g["r"]
    DRAWN_M.check("q5's offset from the infinite-rod line over its length (m r / (2 (r^2 + (F/f)^2)), "
                  "m = F/f / rod_ratio)", ff / g["rod_ratio"] * r / (2.0 * (r * r + ff * ff)))
    return g


def validate_inertia(givens: Mapping[str, float]) -> None:
    inertia_givens(givens["r"], givens["rod_ratio"], givens["pressure_ratio"], givens["pressure_unit"])


def _lay_off(b: Builder, c: _Ctx, tag: str, X: str, V: str, label: str | None = None) -> str:
    """Take the ordinate from the F/f scale line to the perpendicular at the piston position X."""
    ordl = _ordinate_line(b, c, f"ord{tag}", X)
    k = b.circle_segment(f"K{tag}.k", X, c.gf.origin, V, de=f"Ordinate mit dem Zirkel nach {X} getragen",
                         en=f"ordinate carried to {X} with the compass")
    return b.intersect(f"K{tag}", ordl, k, rule=("left", V, c.gf.origin), role="result",
                       de=f"Curvenpunkt K{tag} (oben positiv)", en=f"curve point K{tag} (up = positive)",
                       labels={f"K{tag}": lowered(label)} if label else None)


def _piston(b: Builder, c: _Ctx, tag: str, P: str, *, label: str | None = None, role: str = "construction") -> str:
    """Rod arcs from one crank point (as in :func:`crank.rod_arcs`): its piston position."""
    with b.group(f"rod arcs from {tag}", f"Schubstangenbögen von {tag}"):
        arc = b.circle_radius(f"rod.{tag}", P, c.L, de=f"Bogen um {P} mit der Schubstangenlänge L",
                              en=f"arc about {P} with the rod length L")
        C = b.intersect(f"C.{tag}", arc, c.axis, rule=("toward", c.O, None, -1.0, 0.0), de="Kreuzkopf", en="crosshead")
        back = b.circle_radius(f"back.{tag}", C, c.L, de="mit L zurück auf den Hub", en="with L back onto the stroke")
        return b.intersect(f"X.{tag}", back, c.axis, rule=("toward", c.O, None, 1.0, 0.0), role=role,
                           de=f"Kolbenstellung zu {P}", en=f"piston position for {P}",
                           labels={f"X.{tag}": lowered(label)} if label else None)


def _root_point(b: Builder, c: _Ctx, tag: str, H: str, what: tuple[str, str]) -> str:
    """r cos w = (sqrt(L^2 + OH^2) - L) / 4 as a crank point: hypotenuse SH, less SO = L, halved twice."""
    O = c.O
    with b.group(f"crank angle of q{tag[1:]}: {what[1]}", f"Kurbelwinkel zu q{tag[1:]}: {what[0]}"):
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
                           labels={f"{tag}.P": lowered(f"ω{tag[1:]}")})  # the crank position of q6 (q7)


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
    givens = inertia_givens(r, rod_ratio, pressure_ratio, pressure_unit)
    used = check_parts(parts, method)
    b = Builder("inertia-curve", givens, {"parts": parts, "method": used, "requested_method": method,
                                          "plate": PLATE})
    # the crank circle stays in every teaching view (the points 1...17 stand on it; as a helper it faded
    # after the frame's group, leaving the points in the air); the plate names what it shows (PLATE)
    f = build_frame(b)
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
    return Figure(proto, b.replay(proto, givens))


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
            b.intersect(label, ordl, k, rule=("toward", foot, I), role="result", labels={label: lowered(label)},
                        de=f"{label} = F/f·cos ω", en=f"{label} = F/f cos w")
    with b.group("characteristic point q5 = -m (90 degrees)", "Charakteristischer Punkt q5 = −m (90°)"):
        X = _piston(b, c, "top", c.top)  # the piston position of the crank at 90°: X(90°)
        ordl = _ordinate_line(b, c, "top.o", X)
        k = b.circle_segment("q5.k", X, c.gf.origin, m, de="m nach unten aufgetragen", en="m laid off downwards")
        q5 = b.intersect("q5", ordl, k, rule=down, role="result", labels={"q5": "q₅"}, de="q5 = −m", en="q5 = -m")
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
        b.intersect("q7", ordl, k, rule=up, role="result", labels={"q7": "q₇"}, de="q7 = +m", en="q7 = +m")
    with b.group("point D and the tangents at 0, 90 and 180 degrees", "Punkt D und die Tangenten bei 0°, 90° und 180°"):
        E, F = "K0", f"K{n}"
        ef = b.line("EF", E, F, de="EF ist parallel zur Geraden für unendliche Stange",
                    en="EF is parallel to the infinite-rod line")
        Dx = b.intersect("D.1", ef, c.axis, rule=("only",), de="EF schneidet die Achse bei x = (1 + r/L)·r",
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
