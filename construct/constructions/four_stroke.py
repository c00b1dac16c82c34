"""Four-stroke engines: pressure over two revolutions and the piston over-pressure (seed 001 c, Abb. 1056–1058).

Seed 001 describes the explosion engine ("Viertakt-Verpuffungsmaschine",
Abb. 1056): suction c–b under a slight vacuum, compression b–c, ignition in c
"unter rascher Steigerung des Druckes" -- idealised at constant volume --,
expansion c–d–e, release in e, exhaust f–g; "der höchste Druck ... pflegt bei
25 at zu liegen".  The compression-ignition engine (Diesel, Abb. 1057) burns at
constant pressure instead.  Abb. 1058 shows the piston over-pressure a–a
without and b–b with the mass forces.

The idealised cycle (absolute pressures in at, volumes in strokes):

* suction at ``suction`` p_a, exhaust at ``exhaust`` p_g (horizontal lines);
* compression p V^n = p_a (1 + V_c)^n from the crank-end dead centre to the
  clearance V_c = 1/(ε − 1) (ε the ``compression_ratio``);
* explosion: ignition at constant volume to ``max_pressure``, expansion
  p V^n = const; Diesel: combustion at constant pressure (the compression-end
  pressure p_a ε^n) to the ``cutoff`` volume ρ·V_c, then expansion;
* release early, as the handbook has it: "In *e* wurde die Auslaßöffnung
  freigegeben, durch welche die verbrannten Gase während des vierten, des
  Auspuffhubes, von *f* bis *g* vom Kolben hinausgeschoben werden" -- the
  expansion ends at e, the piston path ``release`` (x_e/s, default 0.9, about
  37° before the crank-end dead centre at L/r = 5), and the pressure falls
  along the straight line e–f to the exhaust line at the dead centre f
  (``release`` 1 releases at the dead centre, at constant volume).

The compression ratio is the engine's own unless given: ε = 5 for the explosion
engine, 14 for the Diesel (gas engines 4 to 7, Diesel 12 to 16).

**The polytropes by Brauer's construction** (E. Brauer, 1885; the period
graphical method for p V^n = const): two rays from the origin O of the
p–V diagram, OM below the volume axis at α and ON to the left of the pressure
axis at β, with 1 + tg β = (1 + tg α)^n.  From a point (V, p) of the curve
the next is (V(1 + tg α), p/(1 + tg β)): the vertical through V meets OM, the
45° line from there meets the volume axis at V(1 + tg α); the 45° line from
p on the pressure axis meets ON at the height p/(1 + tg β).  Inward (the
compression) the steps run backwards.  Every point so found lies on
p V^n = const exactly -- the rays are the method's givens: tg α = R^(1/m) − 1
(m steps across the volume ratio R, so that the last point lands on the
dead-centre ordinate) and tg β = R^(n/m) − 1, numbers a draftsman took from
a table of powers or the slide rule; they are laid off as lengths (tg α·r
under r), and every step after them is straightedge, compass and a 45° line
drawn as a parallel.  The curve is drawn through the points with the French
curve (its straying from the polytrope is checked against the same curve
through the exact points).

**Over 720°** (Abb. 1058, which the handbook draws for the engine with
self-ignition: ``over_pressure`` defaults to the Diesel's, and the explosion
engine's plate is Abb. 1056's diagram alone unless asked): the crank circle is divided, the piston positions come from
the rod arcs; each position's ordinate in the p–V diagram meets the branch of
its stroke (suction, compression, expansion, exhaust), and the compass
carries the height to the ordinate of that crank angle in the 720° diagram
(abscissae: a length 8r divided into 4N equal parts).  Measured from its
atmospheric line (1 at) the curve is the piston over-pressure a–a of a
single-acting engine (open crank side).  b–b takes off the mass force per unit
of piston area, q (cos θ + (r/L) cos 2θ), q = m ω² r/F in at (``pressure_ratio``),
constructed as the inertia ordinates of seed 000 (the proportional angle for
r/L and q).

>>> fig = FOUR_STROKE.figure(parts=4, steps=4, over_pressure=True)
>>> g = fig.replay.givens
>>> round(pressure(fig, "cP4"), 10) == round(g["suction"] * g["compression_ratio"] ** g["exponent"], 10)
True
>>> round(volume(fig, "cP4"), 12) == round(g["clearance"], 12)     # the last Brauer point lands on V_c
True
"""

from __future__ import annotations

import math
from typing import Any, Mapping

from .checking import EUCLIDEAN_TOLERANCE, Check
from ..kernel.errors import InvalidParameter, did_you_mean
from ..kernel.division import NAMES as DIVISION_NAMES
from ..kernel.division import check_parts, divide_semicircle
from ..kernel.instruments import Builder
from ..kernel.protocol import Caption
from . import Construction, Figure, bounded, register, rod_ratio_param
from .crank import build_frame, rod_arcs
from .domain import (COMPRESSION_RATIO, CUTOFF_RATIO, DRAWN_LENGTH, ENGINE_PRESSURE, EXHAUST_PRESSURE,
                     POLYTROPE_EXPONENT, PRESSURE_RATIO, RELEASE, SUCTION_PRESSURE)
from .indicator_parts import square
from .scales import scale_furniture
from .inertia.build import inertia_scale, inertia_value, value_kind
from .phrases import COMBUSTION, Cite, number, ratio

__all__ = ["FOUR_STROKE", "ENGINES", "COMPRESSION_RATIOS", "build_four_stroke", "four_stroke_checks",
           "model_pressure", "pressure", "volume", "brauer_tangents", "STROKES"]

ENGINES = ("explosion", "diesel")
#: Each engine's compression ratio when none is given (explosion engines 4..7, Diesel 12..16).
COMPRESSION_RATIOS = {"explosion": 5.0, "diesel": 14.0}
#: The four strokes in order, from the head-end dead centre (top dead centre) at 0°.
STROKES = ("suction", "compression", "expansion", "exhaust")

#: Where the two diagrams stand (units of r): the p-V diagram's zero line above the crank circle, the 720°
#: diagram to the right.
_PV_ZERO = 1.4
#: The 720° diagram beside the p-V diagram, its peak level with the other's (not on one zero line: a horizontal of
#: the one diagram would run on through the points of the other at its height).
_T0 = (2.6, _PV_ZERO - 0.3)


# --------------------------------------------------------------------------
# The model (for the checks only).
# --------------------------------------------------------------------------


def brauer_tangents(ratio: float, exponent: float, steps: int) -> tuple[float, float]:
    """tg α and tg β of Brauer's rays for *steps* steps across the volume ratio *ratio*.

    >>> ta, tb = brauer_tangents(5.0, 1.3, 8)
    >>> round((1 + ta) ** 8, 12), round((1 + tb) - (1 + ta) ** 1.3, 15)
    (5.0, 0.0)
    """
    return ratio ** (1.0 / steps) - 1.0, ratio ** (exponent / steps) - 1.0


def _piston(theta: float, rod_ratio: float) -> float:
    """Piston path from the head-end dead centre, fraction of the stroke (exact law)."""
    s = math.sin(theta)
    return 0.5 * (1.0 - math.cos(theta) + rod_ratio - math.sqrt(rod_ratio * rod_ratio - s * s))


def model_pressure(stroke: int, x: float, g: Mapping[str, float], engine: str) -> float:
    """Absolute pressure (at) of the idealised cycle on *stroke* (0..3) at piston path x (fraction of the stroke).

    On the expansion stroke beyond the release point x_e (``release``) the pressure falls on the straight
    line from e to the exhaust pressure at the dead centre.

    >>> g = {"suction": 0.9, "exhaust": 1.1, "compression_ratio": 5.0, "clearance": 0.25, "exponent": 1.3,
    ...      "max_pressure": 25.0, "cutoff": 2.0, "release": 1.0}
    >>> round(model_pressure(1, 0.0, g, "explosion"), 6), round(model_pressure(2, 1.0, g, "explosion"), 6)
    (7.292955, 3.085169)
    >>> g["release"] = 0.9
    >>> round(model_pressure(2, 0.9, g, "explosion"), 6), model_pressure(2, 1.0, g, "explosion")
    (3.438388, 1.1)
    """
    vc, n = g["clearance"], g["exponent"]
    if stroke == 0:
        return g["suction"]
    if stroke == 3:
        return g["exhaust"]
    if stroke == 1:
        return g["suction"] * ((1.0 + vc) / (vc + x)) ** n
    xe = g["release"]
    if x > xe:  # released: the straight line e-f
        pe = model_pressure(2, xe, g, engine)
        return pe + (g["exhaust"] - pe) * (x - xe) / (1.0 - xe)
    v = vc + x
    if engine == "explosion":
        return g["max_pressure"] * (vc / v) ** n
    pc = g["suction"] * g["compression_ratio"] ** n
    vd = g["cutoff"] * vc
    return pc if v <= vd else pc * (vd / v) ** n


# --------------------------------------------------------------------------
# Givens.
# --------------------------------------------------------------------------


def _givens(engine: str, r: Any, rod_ratio: Any, compression_ratio: Any, suction: Any, exhaust: Any,
            max_pressure: Any, cutoff: Any, exponent: Any, pressure_unit: Any, pressure_ratio: Any, release: Any,
            steps: int) -> dict[str, float]:
    if engine not in ENGINES:
        raise InvalidParameter(f"engine must be one of {', '.join(ENGINES)}, got {engine!r}{did_you_mean(engine, ENGINES)}")
    if compression_ratio is None:
        compression_ratio = COMPRESSION_RATIOS[engine]
    g = {"r": bounded("crank radius r", r, DRAWN_LENGTH), "rod_ratio": rod_ratio_param(rod_ratio),
         "compression_ratio": bounded("compression ratio ε", compression_ratio, COMPRESSION_RATIO),
         "release": bounded("release x_e/s", release, RELEASE),
         "suction": bounded("suction pressure p_a (at)", suction, SUCTION_PRESSURE),
         "exhaust": bounded("exhaust pressure p_g (at)", exhaust, EXHAUST_PRESSURE),
         "exponent": bounded("polytropic exponent n", exponent, POLYTROPE_EXPONENT),
         "pressure_unit": bounded("pressure-scale unit (drawn length of 1 at)", pressure_unit, DRAWN_LENGTH),
         "pressure_ratio": bounded("mass pressure q = m ω² r/F (at)", pressure_ratio, PRESSURE_RATIO)}
    eps, n = g["compression_ratio"], g["exponent"]
    g["clearance"] = 1.0 / (eps - 1.0)
    pc = g["suction"] * eps ** n
    g["tan_alpha"], g["tan_beta"] = brauer_tangents(eps, n, steps)
    v_e = g["clearance"] + g["release"]   # the volume at release e
    if engine == "explosion":
        g["max_pressure"] = bounded("maximum pressure (at)", max_pressure, ENGINE_PRESSURE)
        if g["max_pressure"] <= pc:
            raise InvalidParameter(f"maximum pressure {g['max_pressure']:g} at must exceed the compression end "
                                   f"p_a ε^n = {pc:.4g} at (ignition raises the pressure)")
        v_d = g["clearance"]
    else:
        g["cutoff"] = bounded("cut-off ratio ρ = V_d/V_c", cutoff, CUTOFF_RATIO)
        v_d = g["cutoff"] * g["clearance"]
        if v_e / v_d < 1.05:
            raise InvalidParameter(f"cut-off ratio ρ = {g['cutoff']:g} must leave room for the expansion: ρ V_c "
                                   f"below V_e/1.05 = {v_e / 1.05:.4g} strokes (combustion ends before the release "
                                   f"e at x_e = {g['release']:g} s)")
        ENGINE_PRESSURE.check("compression-end pressure p_a ε^n (at)", pc)
    # the expansion's own rays: from d (V_d) to the release e (V_e) in the same number of steps
    g["tan_alpha_e"], g["tan_beta_e"] = brauer_tangents(v_e / v_d, n, steps)
    return g


def _validate(givens: Mapping[str, float]) -> None:
    engine = "diesel" if "cutoff" in givens else "explosion"
    bounded("crank radius r", givens["r"], DRAWN_LENGTH)
    RELEASE.check("release x_e/s", givens["release"])
    rod_ratio_param(givens["rod_ratio"])
    COMPRESSION_RATIO.check("compression ratio ε", givens["compression_ratio"])
    POLYTROPE_EXPONENT.check("polytropic exponent n", givens["exponent"])
    if engine == "explosion":
        ENGINE_PRESSURE.check("maximum pressure (at)", givens["max_pressure"])


# --------------------------------------------------------------------------
# The construction.
# --------------------------------------------------------------------------


def _ray(b: Builder, name: str, O: str, U: str, perp: str, length: str, rule: tuple, what: tuple[str, str]) -> str:
    """A ray from O through the point *length* off U along *perp* (the perpendicular at U): tg = length/r."""
    k = b.circle_radius(f"{name}.k", U, length, de=f"{what[0]} an r angetragen", en=f"{what[1]} laid off at r")
    # Brauer's rays OM and ON: their far points are the book's M and N
    T = b.intersect(f"{name}.{name[1]}", perp, k, rule=rule)
    return b.line(name, O, T, de=f"Strahl {O}–{T} ({what[0]})", en=f"ray {O}–{T} ({what[1]})")


def _brauer(b: Builder, tag: str, *, O: str, OM: str, ON: str, d45: tuple, vdir: tuple, hdir: tuple, base: str,
            paxis: str, V0: str, v0: str, p0: str, h0: str, steps: int, outward: bool,
            what: tuple[str, str]) -> list[str]:
    """m steps of Brauer's construction from the curve point on the vertical *v0* (foot *V0*) and the
    horizontal *h0* (its mark *p0* on the pressure axis); returns the curve points, first the start.  *d45*,
    *vdir*, *hdir*: the directions of the parallels (two points and what the line is, German, English)."""
    first = b.intersect(f"{tag}0", v0, h0, rule=("only",), role="result", de=f"{what[0]}: Anfangspunkt",
                        en=f"{what[1]}: starting point")
    pts = [first]
    V, v, p, h = V0, v0, p0, h0
    for j in range(1, steps + 1):
        with b.group(f"{what[1]}: Brauer step {j}", f"{what[0]}: Brauersche Konstruktion, Schritt {j}"):
            if outward:
                Q = b.intersect(f"{tag}q{j}", v, OM, rule=("only",), de=f"Senkrechte trifft den Strahl {O}–{OM}.M",
                                en=f"the vertical meets the ray {O}–{OM}.M")
                s = b.parallel_through(f"{tag}s{j}", Q, *d45[:2], along=d45[2])
                V = b.intersect(f"{tag}V{j}", s, base, rule=("only",), de="45°-Linie: V(1 + tg α)",
                                en="45 degree line: V(1 + tan alpha)")
                v = b.parallel_through(f"{tag}v{j}", V, *vdir[:2], along=vdir[2])
                t = b.parallel_through(f"{tag}t{j}", p, *d45[:2], along=d45[2])
                R = b.intersect(f"{tag}r{j}", t, ON, rule=("only",), de=f"45°-Linie trifft den Strahl {O}–{ON}.N",
                                en=f"the 45 degree line meets the ray {O}–{ON}.N")
                h = b.parallel_through(f"{tag}h{j}", R, *hdir[:2], along=hdir[2])
                p = b.intersect(f"{tag}p{j}", h, paxis, rule=("only",), de="p/(1 + tg β) auf der Druckachse",
                                en="p/(1 + tan beta) on the pressure axis")
            else:
                s = b.parallel_through(f"{tag}s{j}", V, *d45[:2], along=d45[2])
                Q = b.intersect(f"{tag}q{j}", s, OM, rule=("only",), de=f"45°-Linie trifft den Strahl {O}–{OM}.M",
                                en=f"the 45 degree line meets the ray {O}–{OM}.M")
                v = b.parallel_through(f"{tag}v{j}", Q, *vdir[:2], along=vdir[2])
                V = b.intersect(f"{tag}V{j}", v, base, rule=("only",), de="V/(1 + tg α) auf der Volumenachse",
                                en="V/(1 + tan alpha) on the volume axis")
                R = b.intersect(f"{tag}r{j}", h, ON, rule=("only",), de=f"Waagerechte trifft den Strahl {O}–{ON}.N",
                                en=f"the horizontal meets the ray {O}–{ON}.N")
                t = b.parallel_through(f"{tag}t{j}", R, *d45[:2], along=d45[2])
                p = b.intersect(f"{tag}p{j}", t, paxis, rule=("only",), de="p(1 + tg β) auf der Druckachse",
                                en="p(1 + tan beta) on the pressure axis")
                h = b.parallel_through(f"{tag}h{j}", p, *hdir[:2], along=hdir[2])
            pts.append(b.intersect(f"{tag}{j}", v, h, rule=("only",), role="result",
                                   de=f"{what[0]}: Punkt {j}", en=f"{what[1]}: point {j}"))
    return pts


def build_four_stroke(*, engine: str, rod_ratio: float, parts: int, method: str, r: float,
                      compression_ratio: float | None, suction: float, exhaust: float, max_pressure: float,
                      cutoff: float, exponent: float, pressure_unit: float, pressure_ratio: float, release: float,
                      over_pressure: bool | None, steps: int) -> Figure:
    if isinstance(steps, bool) or not isinstance(steps, int) or not 2 <= steps <= 40:
        raise InvalidParameter(f"Brauer steps per polytrope must be a whole number from 2 to 40, got {steps!r}")
    givens = _givens(engine, r, rod_ratio, compression_ratio, suction, exhaust, max_pressure, cutoff, exponent,
                     pressure_unit, pressure_ratio, release, steps)
    if over_pressure is None:   # Abb. 1058 is the Diesel's
        over_pressure = engine == "diesel"
    if not isinstance(over_pressure, bool):
        raise InvalidParameter(f"over_pressure must be true or false, got {over_pressure!r}")
    used = check_parts(parts, method)
    n = parts
    # Which ordinates of the expansion stroke lie on the constant-pressure line and which beyond the release is
    # decided here: the cut-off and the release are structural.
    b = Builder("four-stroke", givens, {"engine": engine, "parts": n, "method": used, "requested_method": method,
                                        "steps": steps, "plate": PLATE if over_pressure else PV_PLATE,
                                        "release": givens["release"],
                                        "over_pressure": over_pressure,
                                        **({"cutoff": givens["cutoff"]} if engine == "diesel" else {})})
    f = build_frame(b)
    # the piston positions are read where the 720° diagram needs them: Abb. 1056's diagram alone needs the dead
    # centres only (its Brauer points are constructed in the p-V plane)
    upper: list[str] = []
    if over_pressure:
        upper = divide_semicircle(b, O=f["O"], D0=f["D0"], D1=f["D1"], circle=f["circle"], axis=f["axis"], n=n,
                                  method=used)
        rod_arcs(b, f, upper)
    positions = range(n + 1) if over_pressure else (0, n)
    unit = "pressure_unit"
    with b.group("p-V diagram: zero line, clearance, pressure axis", "p-V-Diagramm: Nulllinie, Verdichtungsraum, Druckachse"):
        Z = b.given_point("Z", -1.0, _PV_ZERO, unit="r", de="Nulllinie des Diagramms (absolutes Vakuum)",
                          en="zero line of the diagram (absolute vacuum)", label="")
        base = b.given_line("pvbase", Z, angle_deg=0.0, de="Nulllinie (Volumenachse)", en="zero line (volume axis)",
                            role="result")
        ords: dict[int, str] = {}
        feet: dict[int, str] = {}
        for k in positions:
            at = f"X{k}" if over_pressure else (f["D0"] if k == 0 else f["D1"])
            o = b.erect_perpendicular(f"o{k}", at, f["axis"], f["O"] if k not in (0, n) else
                                      (f["D1"] if k == 0 else f["D0"]))
            ords[k] = o
            feet[k] = b.intersect(f"F{k}", o, base, rule=("only",), de=f"Kolbenstellung {k} auf der Volumenachse",
                                  en=f"piston position {k} on the volume axis")
        vc = b.given_length("Vc", product=("clearance", "r"), factor=2.0, de="Verdichtungsraum V_c = s/(ε − 1)",
                            en="clearance volume V_c = s/(epsilon - 1)")
        k = b.circle_radius("O'.k", feet[0], vc, de="V_c vor dem Deckeltotpunkt", en="V_c beyond the head-end dead centre")
        Ov = b.intersect("Ov", base, k, rule=("farther", feet[n]), role="result", labels={"Ov": "O′"},
                         de="Ursprung O des p-V-Diagramms", en="origin O of the p-V diagram")
        paxis = b.erect_perpendicular("paxis", Ov, base, feet[0])
        ku = b.circle_radius("U.k", Ov, f["r"], de="r auf der Volumenachse", en="r on the volume axis")
        U = b.intersect("U", base, ku, rule=("toward", Ov, feet[0]))
        vert_u = b.erect_perpendicular("u.v", U, base, Ov)
        kw = b.circle_radius("W.k", U, f["r"], de="r über U", en="r above U")
        W = b.intersect("W", vert_u, kw, rule=("toward", U, None, 0.0, 1.0))
        b.line("d45", Ov, W, de="45°-Linie (Dreieck)", en="45 degree line (set square)")
        kp = b.circle_radius("U'.k", Ov, f["r"], de="r auf der Druckachse", en="r on the pressure axis")
        Up = b.intersect("U'", paxis, kp, rule=("toward", Ov, None, 0.0, 1.0))
        hor_u = b.erect_perpendicular("u.h", Up, paxis, Ov)
    # the three directions Brauer's steps draw parallels to, by what they are (W, U' and U lie far off)
    d45, vdir, hdir = ((Ov, W, ("zur 45°-Linie", "to the 45 degree line")),
                       (Ov, Up, ("zur Druckachse", "to the pressure axis")), (Ov, U, ("zur Volumenachse", "to the volume axis")))

    def rays(tag: str, ta: str, tb: str) -> tuple[str, str]:
        with b.group(f"Brauer's rays{tag and ' for the expansion'}", f"Brauersche Strahlen{tag and ' der Expansion'}"):
            la = b.given_length(f"ta{tag}", product=(ta, "r"), de="tg α·r", en="tan alpha r")
            lb = b.given_length(f"tb{tag}", product=(tb, "r"), de="tg β·r", en="tan beta r")
            OM = _ray(b, f"OM{tag}", Ov, U, vert_u, la, ("toward", U, None, 0.0, -1.0), ("tg α", "tan alpha"))
            ON = _ray(b, f"ON{tag}", Ov, Up, hor_u, lb, ("toward", Up, None, -1.0, 0.0), ("tg β", "tan beta"))
        return OM, ON

    OM, ON = rays("", "tan_alpha", "tan_beta")
    OMe, ONe = rays("e", "tan_alpha_e", "tan_beta_e")

    def level(name: str, given: str, what: tuple[str, str]) -> tuple[str, str]:
        ln = b.given_length(f"{name}.l", product=(given, unit), de=f"{what[0]} im Druckmaßstab",
                            en=f"{what[1]} in the pressure scale")
        kk = b.circle_radius(f"{name}.k", Ov, ln, de=f"{what[0]} auf der Druckachse", en=f"{what[1]} on the pressure axis")
        mark = b.intersect(f"{name}.p", paxis, kk, rule=("toward", Ov, None, 0.0, 1.0))
        return mark, b.erect_perpendicular(name, mark, paxis, Ov)

    with b.group("suction, exhaust and atmospheric lines", "Saug-, Auspuff- und atmosphärische Linie"):
        b.given_length("one", product=(unit,), de="1 at im Druckmaßstab", en="1 at in the pressure scale")
        ka = b.circle_radius("atm.k", Ov, "one", de="1 at auf der Druckachse", en="1 at on the pressure axis")
        atm_p = b.intersect("atm.p", paxis, ka, rule=("toward", Ov, None, 0.0, 1.0))
        b.erect_perpendicular("atm", atm_p, paxis, Ov)
        pa, suction_line = level("suct", "suction", ("Saugdruck p_a", "suction pressure p_a"))
        pg, exhaust_line = level("exh", "exhaust", ("Auspuffdruck p_g", "exhaust pressure p_g"))
    comp = _brauer(b, "cP", O=Ov, OM=OM, ON=ON, d45=d45, vdir=vdir, hdir=hdir, base=base, paxis=paxis, V0=feet[n],
                   v0=ords[n], p0=pa, h0=suction_line, steps=steps, outward=False,
                   what=("Verdichtungslinie", "compression line"))
    c = comp[-1]
    b.set_label(c, "c")
    b.set_label(comp[0], "b")
    if engine == "explosion":
        with b.group("ignition at constant volume: the maximum pressure", "Zündung bei gleichem Volumen: Höchstdruck"):
            pd, hd = level("pmax", "max_pressure", ("Höchstdruck", "maximum pressure"))
        exp_ = _brauer(b, "eP", O=Ov, OM=OMe, ON=ONe, d45=d45, vdir=vdir, hdir=hdir, base=base, paxis=paxis,
                       V0=feet[0], v0=ords[0], p0=pd, h0=hd, steps=steps, outward=True,
                       what=("Expansionslinie", "expansion line"))
    else:
        with b.group("combustion at constant pressure to the cut-off", "Verbrennung bei gleichem Druck bis zur Füllung"):
            comb_line = f"cPh{steps}"   # the horizontal through c
            lv = b.given_length("Vd", product=("cutoff", "clearance", "r"), factor=2.0, de="ρ·V_c", en="rho V_c")
            kd = b.circle_radius("Vd.k", Ov, lv, de="ρ·V_c auf der Volumenachse", en="rho V_c on the volume axis")
            Vd = b.intersect("Vd.V", base, kd, rule=("toward", Ov, feet[0]))
            vd = b.parallel_through("vd", Vd, *vdir[:2], along=vdir[2])
            pc_mark = f"cPp{steps}"
        exp_ = _brauer(b, "eP", O=Ov, OM=OMe, ON=ONe, d45=d45, vdir=vdir, hdir=hdir, base=base, paxis=paxis,
                       V0=Vd, v0=vd, p0=pc_mark, h0=comb_line, steps=steps, outward=True,
                       what=("Expansionslinie", "expansion line"))
    b.set_label(exp_[0], "d")
    b.set_label(exp_[-1], "e")
    early = givens["release"] < 1.0
    diesel = engine == "diesel"
    with b.group("the curves and the closed diagram", "Die Linien und das geschlossene Diagramm"):
        b.french_curve("compression", base, comp, de="Verdichtungslinie (Kurvenlineal)", en="compression line (French curve)")
        a = b.intersect("a", ords[0], suction_line, rule=("only",), labels={"a": "a"}, de="Saugbeginn a", en="start of suction a")
        fpt = b.intersect("f", ords[n], exhaust_line, rule=("only",), labels={"f": "f"}, de="Auspuffbeginn f",
                          en="start of exhaust f")
        gpt = b.intersect("g", ords[0], exhaust_line, rule=("only",), labels={"g": "g"}, de="Auspuffende g",
                          en="end of exhaust g")
        # The working stroke's line drawn in one: (the Diesel's constant-pressure line c-d,) the curve d..e and
        # (released early) the straight drop e-f, laid anew at each corner, so that every ordinate meets it
        # wherever the rod ratio puts the piston.
        pts = ([c] if diesel else []) + list(exp_) + ([fpt] if early else [])
        corners = ([1] if diesel else []) + ([len(pts) - 2] if early else [])
        b.french_curve("expansion", base, pts, corners=corners,
                       de="Arbeitslinie: " + ("Verbrennung c–d, " if diesel else "") + "Expansion d–e (Kurvenlineal)"
                          + (", Auslass e–f" if early else ""),
                       en="working line: " + ("combustion c-d, " if diesel else "") + "expansion d-e (French curve)"
                          + (", release e-f" if early else ""))
        if not diesel:
            b.polyline("ignition", [c, exp_[0]], de="Verpuffung c–d bei gleichem Volumen",
                       en="explosion c-d at constant volume")
        if not early:
            b.polyline("release", [exp_[-1], fpt], de="Auslass im Totpunkt e–f", en="release at the dead centre e-f")
        b.polyline("suction", [a, comp[0]], de="Sauglinie a–b", en="suction line a-b")
        b.polyline("exhaust", [fpt, gpt], de="Auspufflinie f–g", en="exhaust line f-g")
    if over_pressure:
        _readings_and_over_pressure(b, f, engine, givens, upper, n, ords, feet, a, c, comp, exp_, fpt, gpt, early,
                                    suction_line, exhaust_line)
    proto = b.protocol()
    return Figure(proto, proto.replay(givens))


def _readings_and_over_pressure(b: Builder, f: Mapping[str, str], engine: str, givens: Mapping[str, float],
                                upper: list[str], n: int, ords: Mapping[int, str], feet: Mapping[int, str], a: str,
                                c: str, comp: list[str], exp_: list[str], fpt: str, gpt: str, early: bool,
                                suction_line: str, exhaust_line: str) -> None:
    """The pressures read on every piston position's ordinate, stroke by stroke, and Abb. 1058 from them."""
    readings: dict[tuple[int, int], str] = {}
    on_line_count = 0   # Diesel: how many ordinates of the expansion stroke stand on the constant-pressure line
    released_count = 0  # how many stand beyond the release e, on the line e-f
    with b.group("pressures at the piston positions", "Drücke in den Kolbenstellungen"):
        for k in range(n + 1):
            readings[0, k] = a if k == 0 else comp[0] if k == n else b.intersect(
                f"S{k}", ords[k], suction_line, rule=("only",), de=f"Saughub bei {k}", en=f"suction stroke at {k}")
            readings[3, k] = gpt if k == 0 else fpt if k == n else b.intersect(
                f"G{k}", ords[k], exhaust_line, rule=("only",), de=f"Auspuffhub bei {k}", en=f"exhaust stroke at {k}")
            readings[1, k] = c if k == 0 else comp[0] if k == n else b.intersect(
                f"K{k}", ords[k], "compression", rule=("only",), de=f"Verdichtungslinie bei {k}",
                en=f"compression line at {k}")
            if k == 0:
                readings[2, k] = exp_[0] if engine == "explosion" else c
                on_line_count += engine == "diesel"
            elif k == n:
                readings[2, k] = fpt if early else exp_[-1]
                released_count += early
            else:
                x = (b[f"X{k}"][0] - b[f["D0"]][0]) / (2.0 * givens["r"])
                on_line = engine == "diesel" and givens["clearance"] + x <= givens["cutoff"] * givens["clearance"]
                released = x > givens["release"]
                on_line_count += on_line
                released_count += released
                what = (("Verbrennungslinie", "combustion line") if on_line else
                        ("Auslasslinie e–f", "release line e-f") if released else ("Expansionslinie", "expansion line"))
                readings[2, k] = b.intersect(f"P{k}x", ords[k], "expansion", rule=("only",), de=f"{what[0]} bei {k}",
                                             en=f"{what[1]} at {k}")
    _over_pressure(b, f, upper, n, feet, readings, on_line_count, released_count)


def _over_pressure(b: Builder, f: Mapping[str, str], upper: list[str], n: int, feet: Mapping[int, str],
                   readings: Mapping[tuple[int, int], str], on_line_count: int, released_count: int) -> None:
    """Abb. 1058: the pressures carried to the 720° diagram (a–a) and less the mass pressures (b–b)."""
    # -- the 720° diagram
    with b.group("720 degree diagram: base, divisions, atmospheric line",
                 "Diagramm über 720°: Grundlinie, Teilung, atmosphärische Linie"):
        T0 = b.given_point("T0", _T0[0], _T0[1], unit="r", de="Anfang der 720°-Grundlinie (Nulllinie)",
                           en="start of the 720 degree base (zero line)", label="0°")
        tbase = b.given_line("tbase", T0, angle_deg=0.0, de="Nulllinie über zwei Umdrehungen",
                             en="zero line over two revolutions", role="result")
        b.call(tbase, "Nulllinie", "the zero line")
        span = b.given_length("span", product=("r",), factor=8.0, de="720° als 8 r", en="720 degrees as 8 r")
        ks = b.circle_radius("T1.k", T0, span, de="8 r abgetragen", en="8 r laid off")
        T1 = b.intersect("T1", tbase, ks, rule=("toward", T0, None, 1.0, 0.0), labels={"T1": "720°"})
        # 180° per stroke: the span halved twice, each stroke divided into N parts (a short auxiliary ray each)
        half = b.midpoint("T.h", T0, T1, through=tbase)
        quarters = [T0, b.midpoint("T.q1", T0, half, through=tbase), half, b.midpoint("T.q3", half, T1, through=tbase), T1]
        for q, deg in ((1, "180°"), (2, "360°"), (3, "540°")):  # the dead centres, where the strokes change
            b.set_label(quarters[q], deg)
        marks = [T0]
        for q in range(4):  # each stroke's division points go by a letter of their own: u1…, v1…, w1…, y1…
            marks += (b.divide_segment("uvwy"[q], quarters[q], quarters[q + 1], n, line=tbase) if n > 1 else [])
            marks.append(quarters[q + 1])
        opening = b.given_length("open", product=("r",), factor=0.1, de="Zirkelöffnung für die Senkrechten (r/10)",
                                 en="compass opening for the perpendiculars (r/10)")
        tords = [square(b, f"to{t}", m, tbase, opening) for t, m in enumerate(marks)]
        ka = b.circle_radius("tatm.k", T0, "one", de="1 at", en="1 at")
        tatm_p = b.intersect("tatm.p", tords[0], ka, rule=("toward", T0, None, 0.0, 1.0))
        b.erect_perpendicular("tatm", tatm_p, tords[0], T0)
    ctx = inertia_scale(b, f)
    values = {}
    with b.group("mass pressures q(cos θ + r/L cos 2θ) at the crank points",
                 "Massendrücke q(cos θ + r/L cos 2θ) in den Kurbelpunkten"):
        for k in range(n + 1):
            dc_p = ctx.D0 if 2 * k <= n else ctx.D1
            dc_2 = ctx.D0 if (4 * k < n or 4 * k > 3 * n) else ctx.D1
            values[k] = inertia_value(b, ctx, f"m{k}", upper[k], value_kind(k, n), dc_p, dc_2)
    aa: dict[int, list[str]] = {}
    bb: dict[int, list[str]] = {}
    for s in range(4):
        aa[s], bb[s] = [], []
        with b.group(f"{STROKES[s]} stroke carried over ({180 * s}..{180 * (s + 1)} degrees)",
                     f"{('Saug', 'Verdichtungs', 'Arbeits', 'Auspuff')[s]}hub übertragen ({180 * s}..{180 * (s + 1)}°)"):
            for i in range(n + 1):
                t = s * n + i
                k = i if s % 2 == 0 else n - i
                src = readings[s, k]
                kk = b.circle_segment(f"A{s}.{i}.k", marks[t], feet[k], src, de="Druckhöhe mit dem Zirkel übertragen",
                                      en="pressure height carried with the compass")
                A = b.intersect(f"A{s}.{i}", tords[t], kk, rule=("toward", marks[t], None, 0.0, 1.0), role="result",
                                de=f"a–a bei {t}/{4 * n} von 720°", en=f"a-a at {t}/{4 * n} of 720 degrees")
                aa[s].append(A)
                km = b.circle_segment(f"B{s}.{i}.k", A, ctx.gf.origin, values[k],
                                      de="Massendruck abgezogen", en="mass pressure taken off")
                bb[s].append(b.intersect(f"B{s}.{i}", tords[t], km, rule=("left", ctx.gf.origin, values[k]),
                                         role="result", de=f"b–b bei {t}/{4 * n} von 720°",
                                         en=f"b-b at {t}/{4 * n} of 720 degrees"))
    with b.group("over-pressure lines a-a and b-b", "Überdrucklinien a–a und b–b"):
        for s in range(4):
            for name, pts in ((f"aa{s}", aa[s]), (f"bb{s}", bb[s])):
                line = "a–a" if name.startswith("aa") else "b–b"
                cut = on_line_count if s == 2 else 0
                rel = released_count if s == 2 else 0
                if cut:
                    # Diesel: the constant-pressure part with the straightedge, then a chord across the cut-off
                    # (a corner no French curve follows), then the curve along the expansion.
                    if cut >= 2:
                        b.polyline(f"{name}.line", pts[:cut], de=f"{line}, Verbrennung bei gleichem Druck",
                                   en=f"{line}, combustion at constant pressure")
                    b.polyline(f"{name}.cut", pts[cut - 1:cut + 1], de=f"{line}, über die Füllung hinweg",
                               en=f"{line}, across the cut-off")
                    pts = pts[cut:]
                if rel:
                    # the release e between two ordinates: a corner again, so the pressure drop is its own curve
                    after = pts[len(pts) - rel:]
                    pts = pts[:len(pts) - rel]
                    b.polyline(f"{name}.rel", [pts[-1], after[0]], de=f"{line}, über den Auslass e hinweg",
                               en=f"{line}, across the release e")
                    if len(after) >= 2:
                        b.french_curve(f"{name}.drop", tbase, after, de=f"{line}, Druckabfall nach e",
                                       en=f"{line}, pressure drop after e")
                if len(pts) >= 2:
                    b.french_curve(name, tbase, pts, de=f"{line}, {STROKES[s]}", en=f"{line}, {STROKES[s]} stroke")
        for s in range(3):
            b.polyline(f"aa.j{s}", [aa[s][-1], aa[s + 1][0]], de="Sprung im Totpunkt", en="jump at the dead centre")
            b.polyline(f"bb.j{s}", [bb[s][-1], bb[s + 1][0]], de="Sprung im Totpunkt", en="jump at the dead centre")
        b.set_label(aa[0][0], "a")
        b.set_label(aa[3][-1], "a")
        b.set_label(bb[0][0], "b")
        b.set_label(bb[3][-1], "b")


def four_stroke_plate(fig: Figure) -> dict:
    """Abb. 1056–1058 as a plate.  b and f stand at the crank-end dead centre a few tenths of an atmosphere apart (the suction and the
    exhaust line): both lettered right of the dead centre, the lower one well below the upper, clear of each
    other, of e above them and of the curves that leave them to the left."""
    R = fig.replay
    # a letter's size follows the whole plate's width: the p-V diagram alone, or with the 720° diagram beside it
    d = 0.03 * abs(R["Ov"][0] - R["f"][0]) * (2.6 if "T1" in R else 1.0)
    b_, f_ = R["cP0"], R["f"]
    upper, lower = (b_, f_) if b_[1] >= f_[1] else (f_, b_)
    letters = [{"kind": "lettering", "at": (upper[0] + 1.6 * d, upper[1] + 0.2 * d), "text": "b" if upper is b_ else "f"},
               {"kind": "lettering", "at": (lower[0] + 1.6 * d, lower[1] - 2.6 * d), "text": "f" if lower is f_ else "b"}]
    # the 720° diagram's scale, dead centres and strokes where the figure draws Abb. 1058 (the Diesel's)
    return {"looks": {"cP0": "unlettered", "f": "unlettered"},
            "furniture": letters + (_over_pressure_furniture(fig) if "T0" in R else [])}


#: The plate of Abb. 1056 or 1057 alone: the p-V diagram with Brauer's rays and points over the stroke.
PV_PLATE = (r"pvbase", r"paxis", r"Ov", r"OMe?|ONe?", r"[ce]P\d+", r"compression|expansion",
            r"ignition|suction|release|exhaust", r"atm|suct|exh|pmax", r"[abfg]")
#: The plate (Abb. 1056–1058): the p-V diagram with Brauer's rays and points, the crank circle with the piston
#: positions, the 720° diagram with a-a and b-b.
PLATE = (r"pvbase", r"paxis", r"Ov", r"OMe?|ONe?", r"[ce]P\d+", r"compression|expansion", r"ignition|suction|release|exhaust",
         r"atm|suct|exh|pmax", r"[abfg]", r"crank", r"D[01]", r"X\d+", r"tbase", r"tatm", r"T[01]|T\.(q1|h|q3)",
         r"aa\d|bb\d",
         r"aa\.j\d|bb\.j\d|aa2\.\w+|bb2\.\w+", r"A\d\.\d+|B\d\.\d+")


# --------------------------------------------------------------------------
# Measurements and checks.
# --------------------------------------------------------------------------


def volume(fig: Figure, point: str) -> float:
    """V of a point of the p-V diagram in strokes, measured from its origin O along the zero line."""
    rp = fig.replay
    return (rp[point][0] - rp["Ov"][0]) / (2.0 * rp.givens["r"])


def pressure(fig: Figure, point: str) -> float:
    """Absolute pressure (at) of a point of the p-V diagram: its height over the zero line."""
    rp = fig.replay
    return (rp[point][1] - rp["Ov"][1]) / rp.givens["pressure_unit"]


def _height(fig: Figure, point: str) -> float:
    rp = fig.replay
    return (rp[point][1] - rp["T0"][1]) / rp.givens["pressure_unit"]


def _curve_tolerance(fig: Figure, points: list[tuple[float, float]], xs: list[float], fn) -> list[float]:
    """The method on exact data: how far the French curve through the exact points strays at each x (at)."""
    from ..kernel.geometry import SCALAR, Line, Point
    from ..kernel.ops import OPS

    pts = [Point(v, p) for v, p in points]
    base = Line(Point(0.0, 0.0), Point(1.0, 0.0))
    curve, = OPS["french_curve"].fn((base, *pts), {"points": len(pts), "tangent_at": ()}, {}, (), SCALAR)
    return [abs(curve.y_at(x) - fn(x)) for x in xs]


def four_stroke_checks(fig: Figure) -> list[Check]:
    rp = fig.replay
    g = rp.givens
    engine, n, m = fig.params["engine"], fig.params["parts"], fig.params["steps"]
    vc, nexp, eps = g["clearance"], g["exponent"], g["compression_ratio"]
    scale = max(1.0, g.get("max_pressure", g["suction"] * eps ** nexp) * g["pressure_unit"] / g["r"])
    tol_p = 50 * EUCLIDEAN_TOLERANCE * scale * g["r"] / g["pressure_unit"]
    tol_v = 50 * EUCLIDEAN_TOLERANCE * scale
    checks: list[Check] = []
    c0 = g["suction"] * (1.0 + vc) ** nexp
    for j in range(m + 1):
        checks.append(Check(f"compression point {j}: p V^n", pressure(fig, f"cP{j}") * volume(fig, f"cP{j}") ** nexp, c0,
                            tol_p * (1.0 + vc) ** nexp * 2.0, "Brauer's construction: Euclidean after the two rays",
                            "at·stroke^n"))
    checks.append(Check("compression ends on the clearance V_c", volume(fig, f"cP{m}"), vc, tol_v,
                        "m steps of 1 + tg α = ε^(1/m)", "stroke"))
    checks.append(Check("compression end p_a ε^n", pressure(fig, f"cP{m}"), g["suction"] * eps ** nexp, tol_p * eps ** nexp,
                        "Euclidean", "at"))
    if engine == "explosion":
        v_d, p_d = vc, g["max_pressure"]
        checks.append(Check("maximum pressure (the handbook: about 25 at)", pressure(fig, "eP0"), g["max_pressure"], tol_p,
                            "laid off on the pressure axis", "at"))
    else:
        v_d, p_d = g["cutoff"] * vc, g["suction"] * eps ** nexp
        checks.append(Check("combustion at constant pressure: d at p_c", pressure(fig, "eP0"), p_d, tol_p * eps ** nexp,
                            "the horizontal through c", "at"))
        checks.append(Check("cut-off volume ρ V_c", volume(fig, "eP0"), v_d, tol_v, "laid off on the volume axis", "stroke"))
    e0 = p_d * v_d ** nexp
    for j in range(m + 1):
        checks.append(Check(f"expansion point {j}: p V^n", pressure(fig, f"eP{j}") * volume(fig, f"eP{j}") ** nexp, e0,
                            tol_p * max(1.0, v_d ** nexp) * 4.0 + abs(e0) * 1e-12,
                            "Brauer's construction: Euclidean after the two rays", "at·stroke^n"))
    xe = g["release"]
    checks.append(Check("expansion ends at the release e (x_e)" if xe < 1.0 else
                        "expansion ends on the crank-end dead centre", volume(fig, f"eP{m}"), vc + xe, tol_v,
                        "m steps of 1 + tg α = (V_e/V_d)^(1/m)", "stroke"))
    checks.append(Check("release e: p_d (V_d/V_e)^n", pressure(fig, f"eP{m}"), p_d * (v_d / (vc + xe)) ** nexp,
                        tol_p * eps ** nexp * 4.0, "the last Brauer point", "at"))
    if not fig.params.get("over_pressure", True):   # Abb. 1056/1057 alone: no readings, no 720° diagram
        return checks
    # readings on the ordinates and the 720 degree diagram
    xk = {k: volume(fig, f"F{k}") - vc for k in range(n + 1)}
    comp_pts = [(volume(fig, f"cP{j}"), pressure(fig, f"cP{j}")) for j in range(m + 1)]
    comp_exact = [(v, c0 / v ** nexp) for v, _ in comp_pts]
    exp_pts = [(volume(fig, f"eP{j}"), pressure(fig, f"eP{j}")) for j in range(m + 1)]
    exp_exact = [(v, e0 / v ** nexp) for v, _ in exp_pts]
    inner = [k for k in range(1, n)]
    dev_c = dict(zip(inner, _curve_tolerance(fig, sorted(comp_exact), [vc + xk[k] for k in inner],
                                             lambda v: c0 / v ** nexp)))
    on_exp = [k for k in inner if (engine == "explosion" or vc + xk[k] > g["cutoff"] * vc) and xk[k] <= xe]
    dev_e = dict(zip(on_exp, _curve_tolerance(fig, exp_exact, [vc + xk[k] for k in on_exp], lambda v: e0 / v ** nexp)))
    lam = 1.0 / g["rod_ratio"]
    for s in range(4):
        for i in range(n + 1):
            t = s * n + i
            k = i if s % 2 == 0 else n - i
            theta = math.pi * t / n
            x = _piston(theta, g["rod_ratio"])
            want = model_pressure(s, x, g, engine)
            if s == 1 and i == n:
                want = model_pressure(1, 0.0, g, engine)
            dev = {1: dev_c, 2: dev_e}.get(s, {}).get(k, 0.0)
            tol = 2.0 * dev + tol_p * eps ** nexp * 4.0 + 1e-9 * want
            a = _height(fig, f"A{s}.{i}")
            checks.append(Check(f"a-a at {180 * t / n:g} deg ({STROKES[s]})", a, want, tol,
                                "read on the French curve at the piston position (the same curve through the exact "
                                "points strays by " f"{dev:.2e} at), carried with the compass" if dev else
                                "a straight line or a constructed point, carried with the compass", "at"))
            mass = g["pressure_ratio"] * (math.cos(theta) + lam * math.cos(2.0 * theta))
            checks.append(Check(f"b-b at {180 * t / n:g} deg: a-a less q(cos θ + r/L cos 2θ)",
                                a - _height(fig, f"B{s}.{i}"), mass, tol_p * 10.0 + 1e-9 * abs(mass),
                                "the inertia ordinate of Anhang II (Euclidean), taken off with the compass", "at"))
    checks.append(Check("piston position X_k against the exact law (stroke)", max(
        abs(xk[k] - _piston(math.pi * k / n, g["rod_ratio"])) for k in range(n + 1)), 0.0,
        1e-9, "rod arcs; the division of the circle", "stroke"))
    return checks


#: Command-line help for the givens (book terms).
OPTION_HELP = {
    "engine": "four-stroke: explosion (Abb. 1056, ignition at constant volume) or diesel (Abb. 1057, constant pressure)",
    "compression_ratio": "four-stroke: compression ratio epsilon = (V_c + V_h)/V_c (default: explosion 5, Diesel 14)",
    "release": "four-stroke: piston path x_e/s where the exhaust opens (the handbook: early, at e; default 0.9; 1 "
               "releases at the dead centre)",
    "over_pressure": "four-stroke: draw the over-pressure a-a, b-b over 720 degrees (Abb. 1058; default: the "
                     "Diesel's, as the handbook)",
    "suction": "four-stroke: suction pressure p_a, at absolute (0.9)",
    "exhaust": "four-stroke: exhaust pressure p_g, at absolute (1.1)",
    "max_pressure": "four-stroke, explosion: maximum pressure after ignition, at (the handbook: about 25)",
    "cutoff": "four-stroke, diesel: cut-off ratio rho = V_d/V_c of the combustion at constant pressure (2)",
    "exponent": "four-stroke: polytropic exponent n of compression and expansion (1.3)",
    "steps": "four-stroke: Brauer steps per polytrope (12: the French curve then strays by a thousandth of the diagram)",
}


def _over_pressure_furniture(fig: Figure) -> list[dict]:
    """Abb. 1058 as a plate: beside the 720° diagram its scale of the over-pressure in at (0 on the
    atmospheric line, as a–a is read), a tick at each dead centre under its degree mark, and the strokes
    named between them."""
    R = fig.replay
    T0, T1, atm = R["T0"], R["T1"], R["tatm.p"]
    unit = R.givens["pressure_unit"]
    span = T1[0] - T0[0]
    top = max(R[n][1] for n in R if n[:1] in "AB" and "." in n and n[1:2].isdigit() and not n.endswith(".k"))
    step = 5.0
    values = [i * step for i in range(int((top - atm[1]) / unit / step + 1e-9) + 1)]
    tick = 0.008 * span
    out = scale_furniture(x=T0[0] - 0.07 * span, zero=atm[1], unit=unit, values=values, tick=tick, text="at")
    marks = [T0, R["T.q1"], R["T.h"], R["T.q3"], T1]
    for m in marks:
        out.append({"kind": "stroke", "a": (m[0], m[1] - 1.5 * tick), "b": (m[0], m[1] + 1.5 * tick), "look": "medium"})
    names = ("Ansaugen", "Verdichten", "Arbeiten", "Auspuffen")
    low = min(R[n][1] for n in R if n[:1] == "B" and "." in n and n[1:2].isdigit() and not n.endswith(".k"))
    for (a, b_), name in zip(zip(marks, marks[1:]), names):
        out.append({"kind": "lettering", "at": ((a[0] + b_[0]) / 2, min(low, T0[1]) - 0.07 * span / 4), "text": name,
                    "size": 0.85})
    return out


def four_stroke_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as the handbook writes them: the engine, ε and n, its peak pressure or ρ, the release, the rod,
    and -- where the figure draws Abb. 1058's over-pressure -- a–a, b–b and q."""
    g = fig.replay.givens
    de = lang == "de"
    diesel = fig.params.get("engine") == "diesel"
    out = [("Gleichdruckmaschine" if de else "compression-ignition engine") if diesel
           else ("Verpuffungsmaschine" if de else "explosion engine"),
           f"ε = {number(g['compression_ratio'], lang)}", f"n = {number(g['exponent'], lang)}"]
    out.append(f"ρ = {number(fig.params.get('cutoff', 2.0), lang)}" if diesel
               else ("Höchstdruck " if de else "peak pressure ") + f"{number(g['max_pressure'], lang)} at")
    release = g.get("release", 1.0)
    out.append(("Auslass bei " if de else "release at ") + f"{number(release, lang)} s" if release < 1.0 else
               ("Auslass im Totpunkt" if de else "release at the dead centre"))
    out.append(ratio("r/L", g["rod_ratio"], lang))
    if fig.params.get("over_pressure", True):   # a protocol from before the option drew a-a and b-b
        out += [("Kolbenüberdruck a–a, b–b über zwei Umdrehungen" if de else
                 "piston over-pressure a–a, b–b over two turns"), f"q = {number(g['pressure_ratio'], lang)} at"]
    return out


FOUR_STROKE = register(Construction(
    name="four-stroke",
    title=Caption("Druckverlauf im Viertakt", "Four-stroke pressures"),
    source="seed 001 c, Abb. 1056-1058",
    build=build_four_stroke,
    checks=four_stroke_checks,
    defaults={"engine": "explosion", "rod_ratio": 5.0, "parts": 12, "method": "auto", "r": 1.0,
              "compression_ratio": None, "suction": 0.9, "exhaust": 1.1, "max_pressure": 25.0, "cutoff": 2.0,
              "exponent": 1.3, "pressure_unit": 0.1, "pressure_ratio": 6.0, "release": 0.9, "over_pressure": None,
              "steps": 12},
    book_params=({}, {"engine": "diesel"}),
    structural=("engine", "parts", "method", "steps", "cutoff", "release", "over_pressure"),
    cites=(Cite(COMBUSTION, "Abb. 1056–1058"),),
    wording=four_stroke_wording,
    plate=four_stroke_plate,
    methods=DIVISION_NAMES,
    validator=_validate,
    help=OPTION_HELP,
    extra={"switches": ("over_pressure",)},
))
