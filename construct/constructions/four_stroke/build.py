"""Building the four-stroke diagrams by Brauer's construction: the givens, the p-V diagram, the crank circle, the
720° diagram with the over-pressure, and the plate."""

from __future__ import annotations

from typing import Any, Mapping

from ...kernel.errors import InvalidParameter, did_you_mean
from ...kernel.division import check_parts, divide_semicircle
from ...kernel.instruments import Builder
from .. import Figure, bounded, rod_ratio_param
from ..crank import build_frame, rod_arcs
from ..domain import (COMPRESSION_RATIO, CUTOFF_RATIO, DRAWN_LENGTH, ENGINE_PRESSURE, EXHAUST_PRESSURE,
                      POLYTROPE_EXPONENT, PRESSURE_RATIO, RELEASE, SUCTION_PRESSURE)
from ..indicator_parts import square
from ..scales import scale_furniture
from ..inertia.build import inertia_scale, inertia_value, value_kind
from .model import COMPRESSION_RATIOS, ENGINES, STROKES, brauer_tangents

__all__ = ["build_four_stroke", "four_stroke_givens", "validate_four_stroke", "four_stroke_plate", "over_pressure_furniture",
           "PLATE", "PV_PLATE", "PV_ZERO", "T0_AT"]

#: Where the two diagrams stand (units of r): the p-V diagram's zero line above the crank circle, the 720°
#: diagram to the right.
PV_ZERO = 1.4
#: The 720° diagram beside the p-V diagram, its peak level with the other's (not on one zero line: a horizontal of
#: the one diagram would run on through the points of the other at its height).
T0_AT = (2.6, PV_ZERO - 0.3)


# --------------------------------------------------------------------------
# Givens.
# --------------------------------------------------------------------------


def four_stroke_givens(engine: str, r: Any, rod_ratio: Any, compression_ratio: Any, suction: Any, exhaust: Any,
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


def validate_four_stroke(givens: Mapping[str, float]) -> None:
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
    givens = four_stroke_givens(engine, r, rod_ratio, compression_ratio, suction, exhaust, max_pressure, cutoff, exponent,
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
        Z = b.given_point("Z", -1.0, PV_ZERO, unit="r", de="Nulllinie des Diagramms (absolutes Vakuum)",
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
    return Figure(proto, b.replay(proto, givens))


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
        T0 = b.given_point("T0", T0_AT[0], T0_AT[1], unit="r", de="Anfang der 720°-Grundlinie (Nulllinie)",
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
            "furniture": letters + (over_pressure_furniture(fig) if "T0" in R else [])}


#: The plate of Abb. 1056 or 1057 alone: the p-V diagram with Brauer's rays and points over the stroke.
PV_PLATE = (r"pvbase", r"paxis", r"Ov", r"OMe?|ONe?", r"[ce]P\d+", r"compression|expansion",
            r"ignition|suction|release|exhaust", r"atm|suct|exh|pmax", r"[abfg]")
#: The plate (Abb. 1056–1058): the p-V diagram with Brauer's rays and points, the crank circle with the piston
#: positions, the 720° diagram with a-a and b-b.
PLATE = (r"pvbase", r"paxis", r"Ov", r"OMe?|ONe?", r"[ce]P\d+", r"compression|expansion", r"ignition|suction|release|exhaust",
         r"atm|suct|exh|pmax", r"[abfg]", r"crank", r"D[01]", r"X\d+", r"tbase", r"tatm", r"T[01]|T\.(q1|h|q3)",
         r"aa\d|bb\d",
         r"aa\.j\d|bb\.j\d|aa2\.\w+|bb2\.\w+", r"A\d\.\d+|B\d\.\d+")


def over_pressure_furniture(fig: Figure) -> list[dict]:
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
