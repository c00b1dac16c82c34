"""Building the piston-force figure: its givens (Tafel I, the high-pressure diagram), the crank frame, the
indicator diagram in the force scale, the piston and mass forces at every piston position, their lines and
the free forces between them, J; over a revolution the return stroke too."""

from __future__ import annotations

import math
from typing import Any, Mapping, Sequence

import numpy as np

from ...kernel.errors import InvalidParameter
from ...kernel.division import check_parts, divide_semicircle
from ...kernel.instruments import Builder
from ...kernel.proportional import carry_across, fourth_proportional, scale_line, vertex_on
from .. import Figure, bounded, form_rows
from ..domain import DRAWING_SCALE, DRAWN_MASS_FORCE, FORCE_UNIT, LENGTH_M, PISTON_AREA, ROD_RATIO, RPM, WEIGHT
from ..crank import build_frame, rod_arcs
from ..indicator_parts import indicator_frame, indicator_givens, pressures_at, square
from ..indicator_card import card_givens, card_pair, draw_card, load_indicator
from ..ordinates import OrdinateFrame, ordinate_line, ordinate_value, point_kind
from .plate import CARD_PLATE, PLATE, REVOLUTION_PLATE

__all__ = ["GRAVITY", "piston_area_mean", "piston_area_sides", "PISTON_AREA_COVER", "PISTON_AREA_CRANK", "TAFEL_I",
           "HP_DIAGRAM", "mass_force_scale", "validate_piston_force", "build_piston_force", "card_crossing_chords"]


#: g as the book uses it ("830/9,81").
GRAVITY = 9.81


def piston_area_mean(bore_cm: float = 45.0, tail_rod_cm: float = 7.5, piston_rod_cm: float = 10.0) -> float:
    """F = (F' + F'')/2 in cm^2: cover side less the 7.5 cm tail rod, crank side less the 10 cm piston rod.

    >>> round(piston_area_mean(), 3)    # (1546.253 + 1511.892) / 2
    1529.072
    """
    f1 = math.pi / 4.0 * (bore_cm ** 2 - tail_rod_cm ** 2)
    f2 = math.pi / 4.0 * (bore_cm ** 2 - piston_rod_cm ** 2)
    return (f1 + f2) / 2.0


def piston_area_sides(bore_cm: float = 45.0, tail_rod_cm: float = 7.5, piston_rod_cm: float = 10.0) -> tuple[float, float]:
    """F' (cover side, less the tail rod) and F'' (crank side, less the piston rod) in cm^2.

    >>> [round(v, 2) for v in piston_area_sides()]    # Tafel I prints 1546,25 and 1511,89
    [1546.25, 1511.89]
    """
    return (math.pi / 4.0 * (bore_cm ** 2 - tail_rod_cm ** 2), math.pi / 4.0 * (bore_cm ** 2 - piston_rod_cm ** 2))


PISTON_AREA_COVER, PISTON_AREA_CRANK = piston_area_sides()


#: The book's example, Tafel I, high-pressure side (seed 001).
TAFEL_I = {"weight": 830.0, "rpm": 50.0, "crank_radius": 0.4, "rod_length": 2.0, "piston_area": piston_area_mean()}


#: An idealised high-pressure diagram (Baumann's model) standing in for Tafel I's, which the seed does not
#: print: admission 7 at over a receiver back pressure of 2 at absolute, 30 % filling, 8 % clearance,
#: 15 % compression -- enough compression for the pressure change J before the dead centre, as in Abb. 1055.
HP_DIAGRAM = {"filling": 0.30, "clearance": 0.08, "admission": 7.0, "back_pressure": 2.0, "compression": 0.15}


def mass_force_scale(g: Mapping[str, float]) -> float:
    """(G/g) v^2 / R = (G/g) omega^2 R in kg, omega = pi n / 30."""
    return g["weight"] / GRAVITY * (math.pi * g["rpm"] / 30.0) ** 2 * g["crank_radius"]


def _givens(*, weight: Any, rpm: Any, crank_radius: Any, rod_length: Any, piston_area: Any, filling: Any,
            clearance: Any, admission: Any, back_pressure: Any, compression: Any, scale: Any,
            force_unit: Any, piston_area_cover: Any = None, piston_area_crank: Any = None,
            revolution: bool = False, cards: Any = None) -> dict[str, float]:
    out = {"weight": bounded("weight G of the reciprocating parts (kg)", weight, WEIGHT),
           "rpm": bounded("revolutions per minute n", rpm, RPM),
           "crank_radius": bounded("crank radius R (m)", crank_radius, LENGTH_M),
           "rod_length": bounded("connecting-rod length L (m)", rod_length, LENGTH_M),
           "piston_area": bounded("piston area F (cm^2)", piston_area, PISTON_AREA),
           "scale": bounded("drawing scale (drawn length per metre)", scale, DRAWING_SCALE),
           "force_unit": bounded("force scale (drawn length per kg)", force_unit, FORCE_UNIT)}
    if out["rod_length"] <= out["crank_radius"]:
        raise InvalidParameter(f"rod length L = {rod_length!r} m must exceed the crank radius R = {crank_radius!r} m")
    ROD_RATIO.check("rod ratio L/R (rod length over crank radius)", out["rod_length"] / out["crank_radius"])
    DRAWN_MASS_FORCE.check("drawn mass force over drawn crank radius ((G/g) omega^2 R force_unit / (R scale))",
                           mass_force_scale(out) * out["force_unit"] / (out["crank_radius"] * out["scale"]))
    # the indicator diagram's pressure unit is F * force_unit: checked there as a product of positives
    out.update(indicator_givens(filling, clearance, admission, back_pressure, compression, 1.0))
    del out["pressure_unit"]
    # Both sides' piston areas (Tafel I: F' cover side, F'' crank side): checked always, kept for the revolution.
    sides = {key: bounded(what, value, PISTON_AREA) for key, what, value in (
        ("piston_area_cover", "piston area F' of the cover side (cm^2)", piston_area_cover),
        ("piston_area_crank", "piston area F'' of the crank side (cm^2)", piston_area_crank)) if value is not None}
    if cards is not None:  # a digitised card (and the crank side's own, if any): its points are givens
        out.update(card_givens(cards[0], "card."))
        if cards[1] is not None:
            out.update(card_givens(cards[1], "crank."))
        for key in HP_DIAGRAM:  # the idealised diagram's givens: the card replaces them
            del out[key]
    if revolution:
        out.update(sides)
        if cards is None and out["filling"] + out["compression"] >= 1.0:
            raise InvalidParameter(f"the compression must begin after the cut-off (s1 + s3 < s) for this figure, "
                                   f"got filling {filling!r} and compression {compression!r}")
    return out


def validate_piston_force(g: Mapping[str, float]) -> None:
    if "card.x0" in g:  # drawn from a card: the idealised diagram's givens are not in the protocol
        g = {**HP_DIAGRAM, **g}
    _givens(**{k: g[k] for k in ("weight", "rpm", "crank_radius", "rod_length", "piston_area", "filling",
                                 "clearance", "admission", "back_pressure", "compression", "scale", "force_unit")},
            **{k: g[k] for k in ("piston_area_cover", "piston_area_crank") if k in g})
    if "card.x0" in g:
        card_pair(g)  # the card in the givens, checked as a file is


def _frame(b: Builder) -> dict[str, str]:
    """The crank frame with r and L from metres and the drawing scale."""
    return build_frame(b, radius=("crank_radius", "scale"), rod=("rod_length", "scale"))


def _mass_setup(b: Builder, f: Mapping[str, str]) -> OrdinateFrame:
    """The proportional angle of the inertia curve, its F/f line replaced by (G/g) omega^2 R in the force scale."""
    factor = (math.pi / 30.0) ** 2 / GRAVITY
    Ff = b.given_length("Ff", product=("weight", "rpm", "rpm", "crank_radius", "force_unit"), factor=factor,
                        de="(G/g)·ω²·R im Kraftmaßstab", en="(G/g) omega^2 R in the force scale")
    with b.group("proportional angle for R/L and (G/g) omega^2 R", "Proportionswinkel für R/L und (G/g)·ω²·R"):
        vert = b.perpendicular_bisector("vert", f["D0"], f["D1"])
        top = b.intersect("top", vert, f["circle"], rule=("toward", f["O"], None, 0.0, 1.0),
                          de="Kurbelstellung φ = 90°", en="crank at 90 degrees")
        angle = vertex_on(b, "S", origin=f["O"], leg=vert, length=f["L"], rule=("toward", f["O"], None, 0.0, -1.0),
                          de="Scheitel S des Proportionswinkels: SO = L", en="vertex S of the proportional angle: SO = L")
        gr = scale_line(b, angle, "gr", length=f["r"], toward=("toward", "S", f["O"]),
                        de="Marke R von S aus: Maßlinie für R/L", en="mark R from S: scale line for R/L")
        gf = scale_line(b, angle, "gf", length=Ff, toward=("toward", "S", f["O"]),
                        de="Marke (G/g)ω²R von S aus", en="mark (G/g) omega^2 R from S")
    return OrdinateFrame(f["O"], f["axis"], f["circle"], f["D0"], f["D1"], f["r"], f["L"], Ff, vert, top, angle, gr, gf)


def _carry(b: Builder, name: str, foot: str, ordinate: str, a: str, z: str, *, de: str, en: str,
           role: str = "result", labels: Mapping[str, str] | None = None) -> str:
    """Carry the segment a -> z (on a line parallel to *ordinate*) to *foot* on the ordinate, direction kept."""
    k = b.circle_segment(f"{name}.k", foot, a, z, de="mit dem Zirkel übertragen", en="carried with the compass")
    return b.intersect(name, ordinate, k, rule=("toward", a, z), role=role, de=de, en=en, labels=labels)


def build_piston_force(*, parts: int, method: str, revolution: bool = False, indicator: str = "",
                       indicator_crank_side: str = "", **values: Any) -> Figure:
    cards = None
    if indicator_crank_side and not indicator:
        raise InvalidParameter("--indicator-crank-side goes with --indicator (the cover side's diagram)")
    if indicator:
        cards = (load_indicator(indicator), load_indicator(indicator_crank_side) if indicator_crank_side else None)
    givens = _givens(revolution=bool(revolution), cards=cards, **values)
    used = check_parts(parts, method)
    params = {"parts": parts, "method": used, "requested_method": method, "filling": values["filling"],
              "compression": values["compression"], "plate": PLATE}
    if revolution:
        params.update(revolution=True, plate=PLATE + REVOLUTION_PLATE)
    if cards is not None:
        del params["filling"], params["compression"]  # the card replaces the idealised diagram
        params.update(cards=True, plate=params["plate"] + CARD_PLATE)
        if cards[1] is None:
            params["mirrored"] = True
    b = Builder("piston-force", givens, params)
    f = _frame(b)
    c = _mass_setup(b, f)
    sides = _side_scales(b, c) if revolution else None
    n = parts
    points = divide_semicircle(b, O=f["O"], D0=f["D0"], D1=f["D1"], circle=f["circle"], axis=f["axis"],
                               n=n, method=used)
    for k, p in enumerate(points):
        b.set_label(p, str(k))
    rod_arcs(b, f, points)
    if cards is None:
        d = indicator_frame(b, base=f["axis"], head=f["D0"], crank=f["D1"], stroke=("crank_radius", "scale"),
                            prefix="ind.", pressure_scale=("piston_area_cover" if revolution else "piston_area",
                                                           "force_unit"))
    else:
        d = _draw_cards(b, f, cards, revolution)
    with b.group("base line of the force diagram (Abb. 1055)", "Grundlinie des Kraftdiagramms (Abb. 1055)"):
        Of = b.given_point("Of", 0.0, -1.5 if revolution else -0.8, unit="scale",
                           de="Punkt der Kolbenweglinie des Kraftdiagramms",
                           en="point of the force diagram's piston-path line")
        fbase = b.parallel_through("fbase", Of, f["D0"], f["D1"], role="result")
    ords: list[tuple[str, str]] = []
    with b.group(f"ordinates at all {n + 1} piston positions", f"Ordinaten an allen {n + 1} Kolbenstellungen"):
        for k in range(n + 1):
            o = ordinate_line(b, c, f"ord{k}", f"X{k}")
            ords.append((str(k), o))
    # the cut-off and the start of compression: where the force line has its corners
    corners = [("s1", d.cutoff_ordinate), ("s2", d.compression_ordinate)] if cards is None else []
    with b.group("piston forces from the steam diagram", "Kolbenkräfte aus dem Dampfdiagramm"):
        for tag, o in ords + corners:
            with b.group(f"piston force at {tag}", f"Kolbenkraft bei {tag}"):
                if cards is not None:  # both cards drawn in their own side's area scale: the forces read directly
                    pr = _card_points(b, d, o, tag, "forward")
                    foot = b.intersect(f"F{tag}", o, fbase, rule=("only",), de=f"Fußpunkt F{tag}", en=f"foot F{tag}",
                                       role="result")
                    _carry(b, f"K{tag}", foot, o, pr["back"], pr["steam"],
                           de=f"Kolbenkraft K{tag} = F′p′ − F″p″ (Kurbelseite bis Deckelseite)",
                           en=f"piston force K{tag} = F'p' - F''p'' (crank side to cover side)")
                    continue
                pr = pressures_at(b, d, o, tag, envelope=True)
                foot = b.intersect(f"F{tag}", o, fbase, rule=("only",), de=f"Fußpunkt F{tag}", en=f"foot F{tag}",
                                   role="result" if tag.isdigit() else "construction")
                back = pr["back"] if sides is None else _rescale(b, sides, f"bk{tag}", f"X{tag}" if tag.isdigit()
                                                                   else _foot_on_axis(b, f, o, tag), o, pr["back"],
                                                                   to_crank=True)
                _carry(b, f"K{tag}", foot, o, back, pr["steam"],
                       de=f"Kolbenkraft K{tag} = F·p_ü (Gegendruck bis Dampflinie)",
                       en=f"piston force K{tag} = F·p_ü (back pressure to steam line)")
    with b.group("mass forces (eq. 298) at all piston positions", "Massenkräfte (Gl. 298) an allen Kolbenstellungen"):
        for k, P in enumerate(points):
            kind = point_kind(k, n)
            dc_p = c.D0 if 2 * k <= n else c.D1
            dc_2 = c.D0 if (4 * k < n or 4 * k > 3 * n) else c.D1
            with b.group(f"mass force at point {k}", f"Massenkraft zu Punkt {k}"):
                V = ordinate_value(b, c, str(k), P, kind, dc_p, dc_2)
                k_ = b.circle_segment(f"M{k}.k", f"F{k}", c.gf.origin, V, de="Massenkraft mit dem Zirkel übertragen",
                                      en="mass force carried with the compass")
                b.intersect(f"M{k}", f"ord{k}", k_, rule=("left", V, c.gf.origin), role="result",
                            de=f"Massenkraft M{k} (oben: Beschleunigung)", en=f"mass force M{k} (up: acceleration)")
    if revolution:
        if cards is None:
            _diagram_lines(b, d, f["axis"], n, "", "der Deckelseite", "of the cover side")
        _return_stroke(b, f, c, sides, n, points, d if cards is not None else None)
    elif cards is None:  # J as seed 001 draws it: one piston area, the over-pressure's zero
        _pressure_change(b, d, fbase)
    else:  # J where the cards' forward lines cross: the piston force F p' - F p'' changes sign
        _card_pressure_change(b, f, d, fbase)
    _curves(b, n, fbase, smooth=cards is not None)
    if revolution:
        _curves(b, n, "rbase", prefix="r", forward=False, smooth=cards is not None)
    proto = b.protocol()
    return Figure(proto, b.replay(proto, givens))


def _side_scales(b: Builder, c: OrdinateFrame) -> dict[str, Any]:
    """F' and F'' in the force scale, as two more scale lines of the proportional angle: a height read in one
    side's pressure scale is carried across to the other's (intercept theorem)."""
    with b.group("the two piston areas on the proportional angle", "Die beiden Kolbenflächen am Proportionswinkel"):
        FA = b.given_length("FA", product=("piston_area_cover", "force_unit"),
                            de="F′ (Deckelseite) im Kraftmaßstab", en="F' (cover side) in the force scale")
        FB = b.given_length("FB", product=("piston_area_crank", "force_unit"),
                            de="F″ (Kurbelseite) im Kraftmaßstab", en="F'' (crank side) in the force scale")
        cover = scale_line(b, c.angle, "gA", length=FA, toward=("toward", "S", c.O),
                           de="Marke F′ von S aus", en="mark F' from S")
        crank = scale_line(b, c.angle, "gB", length=FB, toward=("toward", "S", c.O),
                           de="Marke F″ von S aus", en="mark F'' from S")
    return {"angle": c.angle, "cover": cover, "crank": crank}


def _rescale(b: Builder, sides: Mapping[str, Any], name: str, foot: str, ordinate: str, point: str, *,
             to_crank: bool) -> str:
    """The height foot -> point (a pressure drawn in one side's area scale) in the other side's scale, on the ordinate.

    The back pressure acts on the other side of the piston: on the forward stroke the crank side's (area F''),
    read on the cover side's diagram (drawn with F'); so its height is multiplied by F''/F' (and on the return
    by F'/F'') with the proportional angle.
    """
    src, dst = (sides["cover"], sides["crank"]) if to_crank else (sides["crank"], sides["cover"])
    what = ("F″/F′", "F''/F'") if to_crank else ("F′/F″", "F'/F''")
    with b.group(f"back pressure at {name} times {what[1]}", f"Gegendruck bei {name} mal {what[0]}"):
        k = b.circle_segment(f"{name}.k", src.origin, foot, point, de="Höhe auf die Maßlinie der einen Fläche getragen",
                             en="height carried to the scale line of the one area")
        a = b.intersect(f"{name}.a", src.line, k, rule=("toward", None, None, 1.0, 0.0),
                        de="Höhe auf der Maßlinie", en="height on the scale line")
        z = carry_across(b, sides["angle"], f"{name}.z", a, dst, de=f"mal {what[0]} (Strahlensatz)",
                         en=f"times {what[1]} (intercept theorem)")
        k2 = b.circle_segment(f"{name}.k2", foot, dst.origin, z, de="zurück auf die Ordinate", en="back onto the ordinate")
        return b.intersect(name, ordinate, k2, rule=("toward", foot, point),
                           de=f"Gegendruck der anderen Kolbenseite ({what[0]})",
                           en=f"back pressure of the other side of the piston ({what[1]})")


def _diagram_lines(b: Builder, d: Any, axis: str, n: int, tag: str, de: str, en: str) -> None:
    """The side's indicator diagram drawn through its points: the steam line (its corner at the cut-off) and the
    back-pressure line (its corner where the compression begins)."""
    p = d.prefix
    xs = {k: b[f"X{k}"][0] for k in range(n + 1)}
    eps = 1e-9 * abs(xs[n] - xs[0])
    with b.group(f"the indicator diagram {en} drawn through its points",
                 f"Das Indikatordiagramm {de} durch seine Punkte gezogen"):
        for line, letter, corner, what in (("steam", "E", "s1", ("Dampflinie", "steam line")),
                                           ("backline", "R", "s2", ("Gegendrucklinie", "back-pressure line"))):
            pts = [f"{p}{letter}{tag}{k}" for k in range(n + 1)]
            x_corner = b[f"{p}{letter}{tag}{corner}"][0]
            if all(abs(x_corner - x) > eps for x in xs.values()):  # a corner between the ordinates: a point of its own
                pts.append(f"{p}{letter}{tag}{corner}")
                corners = (len(pts) - 1,)
            else:  # the corner falls on an ordinate: that point is the corner
                corners = (min(range(n + 1), key=lambda k: abs(xs[k] - x_corner)),)
            b.french_curve(f"{p}{line}", axis, pts, {}, corners=corners, role="result",
                           de=f"{what[0]} {de}, an der Ecke abgesetzt", en=f"{what[1]} {en}, laid anew at its corner")


def _draw_cards(b: Builder, f: Mapping[str, str], cards: Any, revolution: bool) -> dict[str, str]:
    """The cover side's card and the crank side's (its own, or the cover side's mirrored), each in the scale of
    its piston area (F' and F'' over the revolution; the mean F on the forward stroke alone, as seed 001's P = F p)."""
    area = ("piston_area_cover", "piston_area_crank") if revolution else ("piston_area", "piston_area")
    stroke = ("crank_radius", "scale")
    cover = draw_card(b, cards[0], prefix="card.", head=f["D0"], crank=f["D1"], axis=f["axis"], stroke=stroke,
                      pressure_scale=(area[0], "force_unit"), de="der Deckelseite", en="of the cover side")
    if cards[1] is not None:
        crank = draw_card(b, cards[1], prefix="crank.", head=f["D0"], crank=f["D1"], axis=f["axis"], stroke=stroke,
                          pressure_scale=(area[1], "force_unit"), de="der Kurbelseite", en="of the crank side")
    else:
        crank = draw_card(b, cards[0], prefix="crank.", given_prefix="card.", head=f["D1"], crank=f["D0"],
                          axis=f["axis"], stroke=stroke, pressure_scale=(area[1], "force_unit"), mirrored=True,
                          up=(f["D0"], f["D1"]), de="der Kurbelseite (die der Deckelseite gespiegelt)",
                          en="of the crank side (the cover side's mirrored)")
    return {"cover.fwd": cover.forward, "cover.back": cover.back, "crank.fwd": crank.forward, "crank.back": crank.back}


def _card_points(b: Builder, d: Mapping[str, str], ordinate: str, tag: str, stroke: str) -> dict[str, str]:
    """Where the ordinate meets the working side's and the other side's line of this stroke."""
    up = ("toward", None, None, 0.0, 1.0)
    work, other = ("cover.fwd", "crank.fwd") if stroke == "forward" else ("crank.back", "cover.back")
    steam = b.intersect(f"E{tag}", ordinate, d[work], rule=up, de="Linie der arbeitenden Seite",
                        en="line of the working side")
    back = b.intersect(f"R{tag}", ordinate, d[other], rule=up, de="Linie der anderen Seite", en="line of the other side")
    return {"steam": steam, "back": back}


def _foot_on_axis(b: Builder, f: Mapping[str, str], ordinate: str, tag: str) -> str:
    return b.intersect(f"{tag}.X", ordinate, f["axis"], rule=("only",), de=f"Fußpunkt der Ordinate {tag}",
                       en=f"foot of the ordinate {tag}")


def _return_stroke(b: Builder, f: Mapping[str, str], c: OrdinateFrame, sides: Mapping[str, Any], n: int,
                   points: list[str], cards: Mapping[str, str] | None = None) -> None:
    """The return stroke: the crank side's diagram (the cover side's mirrored, drawn below the stroke line in the
    scale of F''), its piston forces F'' p'' - F' p' and the mass forces of (298) with the minus sign.  With
    *cards* (drawn cards, each in its own side's area scale) the forces are read between their return lines."""
    d = None if cards is not None else indicator_frame(
        b, base=f["axis"], head=f["D1"], crank=f["D0"], stroke=("crank_radius", "scale"), prefix="crk.",
        pressure_scale=("piston_area_crank", "force_unit"))
    with b.group("base line of the return stroke's force diagram", "Grundlinie des Kraftdiagramms für den Rückgang"):
        Or = b.given_point("Or", 0.0, -2.6, unit="scale", de="Punkt der Kolbenweglinie des Rückgangs",
                           en="point of the return stroke's piston-path line")
        rbase = b.parallel_through("rbase", Or, f["D0"], f["D1"], role="result")
    corners = [("s1", d.cutoff_ordinate), ("s2", d.compression_ordinate)] if d is not None else []
    with b.group("piston forces of the return stroke (crank side)", "Kolbenkräfte des Rückgangs (Kurbelseite)"):
        for tag, o in [(str(k), f"ord{k}") for k in range(n + 1)] + corners:
            with b.group(f"return-stroke piston force at {tag}", f"Kolbenkraft im Rückgang bei {tag}"):
                if d is None:
                    pr = _card_points(b, cards, o, f"r{tag}", "return")
                    rf = b.intersect(f"rF{tag}", o, rbase, rule=("only",), de=f"Fußpunkt rF{tag}", en=f"foot rF{tag}",
                                     role="result")
                    _carry(b, f"rK{tag}", rf, o, pr["back"], pr["steam"],
                           de=f"Kolbenkraft rK{tag} = F″p″ − F′p′ (oben: in Richtung des Rückgangs)",
                           en=f"piston force rK{tag} = F''p'' - F'p' (up: in the direction of the return stroke)")
                    continue
                pr = pressures_at(b, d, o, f"r{tag}", envelope=True)
                foot = f"X{tag}" if tag.isdigit() else _foot_on_axis(b, f, o, f"r{tag}")
                back = _rescale(b, sides, f"rbk{tag}", foot, o, pr["back"], to_crank=False)
                rf = b.intersect(f"rF{tag}", o, rbase, rule=("only",), de=f"Fußpunkt rF{tag}", en=f"foot rF{tag}",
                                 role="result" if tag.isdigit() else "construction")
                _carry(b, f"rK{tag}", rf, o, pr["steam"], back,
                       de=f"Kolbenkraft rK{tag} = F″p″ − F′p′ (oben: in Richtung des Rückgangs)",
                       en=f"piston force rK{tag} = F''p'' - F'p' (up: in the direction of the return stroke)")
    if d is not None:
        _diagram_lines(b, d, f["axis"], n, "r", "der Kurbelseite", "of the crank side")
    with b.group("mass forces of the return stroke: eq. (298) with the minus sign",
                 "Massenkräfte des Rückgangs: Gl. (298) mit dem Minuszeichen"):
        for k in range(n + 1):
            kk = b.circle_segment(f"rM{k}.k", f"rF{k}", c.gf.origin, f"V{k}",
                                  de="Massenkraft mit dem Zirkel übertragen, Richtung umgekehrt",
                                  en="mass force carried with the compass, direction reversed")
            b.intersect(f"rM{k}", f"ord{k}", kk, rule=("right", f"V{k}", c.gf.origin), role="result",
                        de=f"Massenkraft rM{k} (oben: Beschleunigung im Rückgang)",
                        en=f"mass force rM{k} (up: accelerated on the return stroke)")


def _pressure_change(b: Builder, d, fbase: str) -> None:
    """J: the steam and compression hyperbolas cross where Z0 J : J Z1 = (s1 + s0) : P0 (s3 + s0)/(P + P0)."""
    with b.group("pressure change J", "Druckwechsel J"):
        h1 = b.length_of("J.h1", d.head, "ind.A0", de="P + P0", en="P + P0")
        h2 = b.length_of("J.h2", d.head, "ind.B0", de="P0", en="P0")
        a2 = b.length_of("J.a2", "ind.S2", d.Z1, de="s3 + s0", en="s3 + s0")
        foot, top = fourth_proportional(b, "J.m", vertex=d.Z1, leg_point=d.crank, a=h1, b_=h2, c=a2)
        m = b.length_of("J.m'", foot, top, de="P0 (s3 + s0)/(P + P0)", en="P0 (s3 + s0)/(P + P0)")
        k = b.circle_through("J.k1", d.Z0, "ind.S1", de="s1 + s0 auf der Linie des schädlichen Raums",
                             en="s1 + s0 on the clearance line")
        M1 = b.intersect("J.M1", "ind.clear0", k, rule=_up(d), de="s1 + s0 nach oben", en="s1 + s0 upwards")
        k = b.circle_radius("J.k2", d.Z1, m, de="m′ auf der anderen Linie nach unten", en="m' downwards on the other")
        M2 = b.intersect("J.M2", "ind.clear1", k, rule=_down(d), de="m′ nach unten", en="m' downwards")
        g = b.line("J.g", M1, M2, de="Verbindungslinie teilt Z Z′ im Verhältnis", en="the joining line divides Z Z' in the ratio")
        Jx = b.intersect("Jx", g, d.base, rule=("only",), role="result", labels={"Jx": "J′"},
                         de="Schnitt der Expansions- und Kompressionslinie", en="where expansion and compression lines cross")
        o = square(b, "J.o", Jx, d.base, d.opening)
        b.intersect("J", o, fbase, rule=("only",), role="result", labels={"J": "J"},
                    de="Druckwechsel J: Kolbenkraft null", en="pressure change J: piston force zero")


def card_crossing_chords(cover: Sequence[Any], crank: Sequence[Any]) -> tuple[int, int] | None:
    """Of two polylines (points (x, y), x increasing), the chords (i, j) where the first passes from above the
    second to below it for the last time along the stroke: the piston force's last change of sign from
    pushing to braking.  None if it never does.

    Both lines are straight between their points, so their gap is straight between the points of either: its
    signs at those abscissae (numpy, thousands of points at once) find the last crossing.

    >>> card_crossing_chords([(0, 8), (1, 2)], [(0, 1), (0.9, 1), (1, 3)])
    (0, 1)
    >>> card_crossing_chords([(0, 8), (1, 5)], [(0, 1), (1, 1)]) is None
    True
    """
    a, c = np.asarray(cover, dtype=float), np.asarray(crank, dtype=float)
    lo, hi = max(a[0, 0], c[0, 0]), min(a[-1, 0], c[-1, 0])
    xs = np.union1d(a[:, 0], c[:, 0])
    xs = xs[(xs >= lo) & (xs <= hi)]
    if xs.size < 2:
        return None
    gap = np.interp(xs, a[:, 0], a[:, 1]) - np.interp(xs, c[:, 0], c[:, 1])
    down = np.flatnonzero((gap[:-1] > 0.0) & (gap[1:] <= 0.0))
    if down.size == 0:
        return None
    k = int(down[-1])
    mid = 0.5 * (xs[k] + xs[k + 1])   # inside one chord of each line
    i = int(np.searchsorted(a[:, 0], mid, side="right")) - 1
    j = int(np.searchsorted(c[:, 0], mid, side="right")) - 1
    return min(i, len(a) - 2), min(j, len(c) - 2)


def _card_pressure_change(b: Builder, f: Mapping[str, str], d: Mapping[str, Any], fbase: str) -> None:
    """J from the cards: the chords of the two forward lines that cross (read off the figure when the step is
    recorded, as the branch of an envelope is), each extended with the straightedge, their crossing J', and the
    perpendicular from it to the stroke line carried down to the force diagram's base.  Both cards are drawn in
    their piston area's scale, so J' is where F p' = F p'': the piston force's zero."""
    up = 1.0 if b[f["D1"]][0] > b[f["D0"]][0] else -1.0
    # the traced lines' points along the stroke (the crank side's mirrored line runs from the other end)
    lines = {side: [(up * p[0], p[1]) for p in b[d[f"{side}.fwd"]].points] for side in ("cover", "crank")}
    order = {side: (1 if pts[0][0] <= pts[-1][0] else -1) for side, pts in lines.items()}
    chords = card_crossing_chords(lines["cover"][::order["cover"]], lines["crank"][::order["crank"]])
    if chords is None:
        return  # the piston force does not change sign: no J to draw (the caption's givens show why)

    def chord_ends(side: str, k: int) -> tuple[str, str]:
        """The two points of the traced line's chord k (counted along the stroke), picked off the line."""
        n = len(lines[side])
        names = []
        for e in ((k, k + 1) if order[side] > 0 else (n - 1 - k, n - 2 - k)):
            b.record("curve", "vertex", (d[f"{side}.fwd"],), (f"J.{side}{e}",), {"index": e},
                     f"Punkt {e} der Linie", f"point {e} of the line")
            names.append(f"J.{side}{e}")
        return names[0], names[1]

    i, j = chords
    with b.group("pressure change J: where the cards' forward lines cross", "Druckwechsel J: Schnitt der Linien "
                 "des Hinganges beider Diagramme"):
        g1 = b.line("J.g1", *chord_ends("cover", i), de="Sehne der Deckelseite verlängert",
                    en="the cover side's chord extended")
        g2 = b.line("J.g2", *chord_ends("crank", j), de="Sehne der Kurbelseite verlängert",
                    en="the crank side's chord extended")
        Jx = b.intersect("Jx", g1, g2, rule=("only",), role="result", labels={"Jx": "J′"},
                         de="J′: die Drücke beider Seiten gleich", en="J': both sides' pressures equal")
        # the perpendicular from J' with the compass about the piston positions on either side of it (two
        # feet of the ordinates, near J': small circles, a view that stays on the diagram)
        along = sorted((abs(b[f"X{k}"][0] - b[Jx][0]), f"X{k}") for k in range(b.params["parts"] + 1))[:2]
        perp, _ = b.drop_perpendicular("J.o", Jx, f["axis"], along[0][1], along[1][1])
        b.intersect("J", perp, fbase, rule=("only",), role="result", labels={"J": "J"},
                    de="Druckwechsel J: Kolbenkraft null", en="pressure change J: piston force zero")


def _up(d) -> tuple[str, str, str]:
    return ("left", d.head, d.crank)


def _down(d) -> tuple[str, str, str]:
    return ("right", d.head, d.crank)


def _curves(b: Builder, n: int, fbase: str, *, prefix: str = "", corners: tuple[str, str] = ("s1", "s2"),
            forward: bool = True, smooth: bool = False) -> None:
    """The lines drawn through the points: piston force in three pieces (its corners at s1 and s2), mass forces.

    *prefix* names the stroke's points (``""`` forward, ``"r"`` return); on the return stroke the piece of the
    admission lies at the crank end, so the pieces are taken from that end (*forward* False).
    """
    p = prefix
    if smooth:  # a measured diagram: no corners known in advance, one line through the points
        with b.group("the lines drawn through the points", "Die Linien durch die Punkte gezogen"):
            b.french_curve(f"{p}forcea", fbase, [f"{p}K{k}" for k in range(n + 1)], {},
                           de="Kolbenkraftlinie", en="piston-force line")
            b.french_curve(f"{p}mass", fbase, [f"{p}M{k}" for k in range(n + 1)], {},
                           de="Linie der Massenkräfte", en="line of the mass forces")
        with b.group("free forces hatched vertically; the mass-force areas",
                     "Freie Kräfte senkrecht gestrichelt; Massenkraftflächen"):
            b.area_between(f"{p}free.a", f"{p}forcea", f"{p}mass", f"{p}M0", f"{p}M{n}", hatch_deg=90.0,
                           role="result", de="freie Kräfte zwischen Kolbenkraft- und Massenkraftlinie",
                           en="free forces between the piston-force line and the mass-force line")
            _mass_areas(b, p, fbase, n)
        return
    sign = 1.0 if forward else -1.0
    xs = {k: sign * b[f"X{k}"][0] for k in range(n + 1)}
    c1, c2 = f"{p}K{corners[0]}", f"{p}K{corners[1]}"
    x1, x2 = sign * b[c1][0], sign * b[c2][0]
    eps = 1e-9 * abs(xs[n] - xs[0])
    stroke = ("", "") if forward else (" (Rückgang)", " (return stroke)")
    with b.group("the lines drawn through the points" + stroke[1], "Die Linien durch die Punkte gezogen" + stroke[0]):
        # the points in the order the piston meets them on this stroke (on the return from the crank end)
        order = sorted(range(n + 1), key=lambda k: xs[k])
        first = [f"{p}K{k}" for k in order if xs[k] < x1 - eps] + [c1]
        mid = [c1] + [f"{p}K{k}" for k in order if x1 + eps < xs[k] < x2 - eps] + [c2]
        last = [c2] + [f"{p}K{k}" for k in order if xs[k] > x2 + eps]
        if x2 <= x1 + eps:
            raise InvalidParameter("the compression must begin after the cut-off (s1 + s3 < s) for this figure")
        b.line(f"{p}forcea", first[0], first[-1], role="result", de="Kolbenkraft während der Füllung: Gerade",
               en="piston force during admission: a straight line")
        b.french_curve(f"{p}forceb", fbase, mid, {}, de="Kolbenkraftlinie während der Expansion",
                       en="piston-force line during expansion")
        b.french_curve(f"{p}forcec", fbase, last, {}, de="Kolbenkraftlinie während der Kompression",
                       en="piston-force line during compression")
        b.french_curve(f"{p}mass", fbase, [f"{p}M{k}" for k in range(n + 1)], {},
                       de="Linie der Massenkräfte", en="line of the mass forces")
    with b.group("free forces hatched vertically; the mass-force areas" + stroke[1],
                 "Freie Kräfte senkrecht gestrichelt; Massenkraftflächen" + stroke[0]):
        for piece, (a, z) in zip(("forcea", "forceb", "forcec"), ((first[0], first[-1]), (mid[0], mid[-1]),
                                                                 (last[0], last[-1]))):
            a, z = (a, z) if forward else (z, a)  # along the base from left to right
            b.area_between(f"{p}free.{piece[-1]}", f"{p}{piece}", f"{p}mass", a, z, hatch_deg=90.0, role="result",
                           de="freie Kräfte zwischen Kolbenkraft- und Massenkraftlinie",
                           en="free forces between the piston-force line and the mass-force line")
        _mass_areas(b, p, fbase, n)


def force_line_form(replay: Any, params: Mapping[str, Any]) -> np.ndarray | None:
    """The choices of :func:`_curves` over a sweep (:attr:`~construct.constructions.Construction.form`): the order in
    which the piston meets the points and, for each, whether it lies before the cut-off's corner, between the
    corners or after the compression's (within 1e-9 of the stroke of a corner: none, the corner is the point), and
    whether the corners come in the wrong order (no figure).  None for a revolution or a card (the return stroke's
    and the cards' lines choose otherwise: fresh builds tell)."""
    if params.get("revolution") or params.get("cards"):
        return None
    n = params["parts"]
    xs = np.asarray(np.broadcast_arrays(*(replay[f"X{k}"][0] for k in range(n + 1))), dtype=float)
    x1, x2 = replay["Ks1"][0], replay["Ks2"][0]
    eps = 1e-9 * abs(xs[n] - xs[0])
    return form_rows(*np.argsort(xs, axis=0, kind="stable"), *(xs < x1 - eps), *((x1 + eps < xs) & (xs < x2 - eps)),
                     *(xs > x2 + eps), x2 <= x1 + eps)


def _mass_areas(b: Builder, p: str, fbase: str, n: int) -> None:
    """The region between the mass-force line and the base (acceleration above, deceleration below), and the
    planimeter's reading round it: the same two steps for a drawn diagram and a digitised card's."""
    b.area_between(f"{p}massarea", f"{p}mass", fbase, f"{p}M0", f"{p}M{n}", role="construction",
                   de="Beschleunigungsfläche über, Verzögerungsfläche unter der Kolbenweglinie",
                   en="acceleration area above, deceleration area below the piston-path line")
    b.planimeter(f"{p}balance", f"{p}massarea",
                 de="mit dem Planimeter umfahren: Beschleunigungs- weniger Verzögerungsfläche",
                 en="planimeter round it: acceleration less deceleration area")
