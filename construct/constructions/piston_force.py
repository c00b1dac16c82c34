"""The piston-force line with the mass forces ("Einfluß der Massenkräfte"), seed 001, Abb. 1054/1055.

Seed 001 draws the over-pressure p_ü on the high-pressure piston over the
stroke (Abb. 1054: cover-side steam line less the crank-side back pressure at
the same piston position), carries it to the crank positions of a semicircle
over the stroke divided "vorteilhafterweise in 9 oder 18 Teile" through the
connecting-rod arcs, multiplies by the piston area, P = F p_ü (297), and
superposes the mass forces of eq. (298),

    P_b = (G/g)(v^2/R)(cos phi ± (R/L) cos 2 phi),

"welche während der Beschleunigungszeit von den Kolbenkräften aufgebracht
werden müssen, während der Verzögerungszeit aber wieder frei werden"; the
free forces are hatched vertically (Abb. 1055); J is the pressure change.

The construction, on one sheet:

* the crank circle over the stroke (drawing scale ``scale`` per metre), the
  semicircle divided into ``parts``, the rod arcs to the piston positions X_k;
* on the stroke line as absolute-zero line the idealised indicator diagram
  (module :mod:`construct.constructions.indicator`, Baumann's model) drawn
  in the force scale -- 1 at is drawn as F times ``force_unit`` (drawn length
  per kg), so every over-pressure reads directly as piston force;
* below, on a parallel base line (the "Kolbenweglinie" of Abb. 1055), at each
  X_k the piston force K_k (the segment back pressure -> steam line carried
  with the compass, sign kept) and the mass force M_k constructed as the
  inertia curve is (:mod:`construct.constructions.inertia`: r cos phi, the
  doubled angle, r/L by the proportional angle, then scaled to
  (G/g) omega^2 R in the force scale);
* the lines drawn through the points (the piston-force line in three pieces, its
  corners at the cut-off and the start of compression), the free forces between it
  and the mass-force line as hatched areas, the mass-force areas above and below the
  base read with the planimeter, and J, the zero of p_ü: the steam and compression hyperbolas cross where
  the distance between the clearance corners is divided in the ratio of the
  two rectangles (P + P0)(s1 + s0) : P0 (s3 + s0) -- a fourth proportional
  and the intercept theorem.

The mass forces and the area balance use the book's numbers (Tafel I: G = 830 kg
high-pressure side, n = 50/min, R = 0.4 m, L = 2.0 m; piston area the mean of
F' and F'' from the diameters 45 cm, 7.5 cm and 10 cm).  Tafel I's indicator
diagram is not in the seed: the over-pressure line is Baumann's idealised
diagram with an illustrative high-pressure setting (:data:`HP_DIAGRAM`).

>>> fig = PISTON_FORCE.figure(parts=6)
>>> round(mass_force(fig, 0), 3)        # P_b at phi = 0: (G/g) omega^2 R (1 + R/L); the book prints 1115
1113.391
"""

from __future__ import annotations

import math
import re
from typing import Any, Mapping, Sequence

import numpy as np

from . import analytic
from .checking import EUCLIDEAN_TOLERANCE, Check
from ..kernel.errors import InvalidParameter
from ..kernel.geometry import Point
from ..kernel.division import NAMES as DIVISION_NAMES
from ..kernel.division import check_parts, divide_semicircle
from ..kernel.instruments import Builder
from ..kernel.proportional import carry_across, fourth_proportional, scale_line, vertex_on
from ..kernel.protocol import Caption
from . import Construction, Figure, bounded, register
from .domain import DRAWING_SCALE, DRAWN_MASS_FORCE, FORCE_UNIT, LENGTH_M, PISTON_AREA, ROD_RATIO, RPM, WEIGHT
from .crank import angle_tolerance, build_frame, crank_angle, point_name, rod_arcs
from .indicator import back_pressure as model_back
from .indicator import indicator_frame, indicator_givens, pressures_at, square
from .indicator import steam_pressure as model_steam
from .indicator_card import card_givens, card_pair, draw_card, load_indicator
from .ordinates import OrdinateFrame, ordinate_line, ordinate_value, point_kind
from .phrases import BAUMANN_1902, HANDBOOK, Cite, card, division, metres, number, percent

__all__ = ["PISTON_FORCE", "TAFEL_I", "HP_DIAGRAM", "GRAVITY", "piston_area_mean", "build_piston_force",
           "piston_force_checks", "mass_force", "piston_force", "abscissa", "mass_force_rows", "area_balance",
           "model_areas_sweep",
           "mass_force_scale", "j_abscissa", "card_force_zero", "card_crossing_chords", "piston_area_sides", "return_mass_force", "return_piston_force",
           "revolution_mass_force_rows", "PISTON_AREA_COVER", "PISTON_AREA_CRANK"]

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


def _validate(g: Mapping[str, float]) -> None:
    if "card.x0" in g:  # drawn from a card: the idealised diagram's givens are not in the protocol
        g = {**HP_DIAGRAM, **g}
    _givens(**{k: g[k] for k in ("weight", "rpm", "crank_radius", "rod_length", "piston_area", "filling",
                                 "clearance", "admission", "back_pressure", "compression", "scale", "force_unit")},
            **{k: g[k] for k in ("piston_area_cover", "piston_area_crank") if k in g})
    if "card.x0" in g:
        card_pair(g)  # the card in the givens, checked as a file is


# --------------------------------------------------------------------------
# Building.
# --------------------------------------------------------------------------

#: What Abb. 1055 shows: the base line, the piston-force line, the mass-force curve, the free forces
#: hatched vertically, J; the ordinates' feet as the stroke's division.
PLATE = (r"fbase", r"F\d+", r"K\d+|Ks[12]", r"M\d+", r"ord\d+", r"force[abc]", r"mass", r"J", r"free\.[abc]")


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


def piston_force_plate(fig: Figure) -> dict:
    """Abb. 1055 as a plate: the piston-force line and the mass-force line heavy over a thin piston-path
    line, lettered as the book letters them -- J where the piston force changes sign, C the end of the
    force line and O the end of the piston-path line ("zwischen J und C negativ", "von J bis O") -- the
    lines named (P = F·pü, Pb the mass forces, eq. 297/298), and a force scale in kg beside the diagram.

    The two-sided plate (``--revolution``) is laid out in landscape, as a book sets a cover-side and a
    crank-side diagram side by side (:func:`_revolution_panels`): the forward stroke on the left (the cover
    side's indicator diagram over its force diagram), the return stroke on the right (the crank side's over
    its own), the two force diagrams on one level, so that one kg scale serves both.

    Every position is a constructed point; the scale's divisions are the given drawn length per kg.
    """
    R = fig.replay
    n = fig.params["parts"]
    F0, Fn, Kn = R["F0"], R[f"F{n}"], R[f"K{n}"]
    s = abs(Fn[0] - F0[0])
    unit = R.givens["force_unit"]
    two_sided = bool(fig.params.get("revolution"))
    panels = _revolution_panels(fig) if two_sided else []
    fdy = panels[1]["shift"][1] if panels else 0.0  # the forward force diagram's shift on the sheet
    y0 = F0[1] + fdy
    ks = [R[f"K{k}"][1] for k in range(n + 1)] + [R[f"M{k}"][1] for k in range(n + 1)]
    step = 2000.0
    lo = int(math.floor((min(ks) - F0[1]) / unit / step))
    hi = int(math.floor((max(ks) - F0[1]) / unit / step + 1e-9))
    # the scale stands clear of the piston-path line's end (which reaches a little past F0), so that no
    # line strikes its figures
    x = F0[0] - (0.25 if two_sided else 0.07) * s
    tick = 0.012 * s
    furniture: list[dict] = [{"kind": "stroke", "a": (x, y0 + lo * step * unit), "b": (x, y0 + hi * step * unit),
                              "look": "medium"}]
    size = 1.0 if two_sided else 0.8
    for i in range(lo, hi + 1):
        y = y0 + i * step * unit
        furniture.append({"kind": "stroke", "a": (x - tick, y), "b": (x, y), "look": "medium"})
        furniture.append({"kind": "lettering", "at": (x - 2.2 * tick, y), "text": f"{int(i * step)}".replace("-", "−"),
                          "anchor": "end", "size": size})
    # "kg" under the scale on the two-sided plate: the admission line runs past its top
    kg_at = (x, y0 + (lo - 0.8) * step * unit) if two_sided else (x, y0 + (hi + 0.6) * step * unit)
    furniture.append({"kind": "lettering", "at": kg_at, "text": "kg", "size": 1.0 if two_sided else 0.85})
    d = 0.035 * s
    if not two_sided:  # the book's O and C end its one diagram; the two-sided plate is not the book's
        furniture += [
            {"kind": "lettering", "at": (Fn[0] + 0.45 * d, Fn[1] + 0.5 * d), "text": "O"},
            {"kind": "lettering", "at": (Kn[0] + 0.5 * d, Kn[1] - 0.2 * d), "text": "C"},
        ]
    # the names of the lines, beside a quarter of the way along each
    kq, mq = R[f"K{max(1, (3 * n) // 8)}"], R[f"M{max(1, n // 6)}"]
    furniture += [
        {"kind": "lettering", "at": (kq[0] + 1.8 * d, kq[1] + fdy + 1.2 * d), "text": "P = F·pü", "anchor": "start"},
        {"kind": "lettering", "at": (mq[0] + 0.5 * d, mq[1] + fdy + 1.3 * d), "text": "Pb", "anchor": "start"},
    ]
    looks = {"forcea": "heavy", "forceb": "heavy", "forcec": "heavy", "mass": "heavy", "fbase": "thin"}
    if two_sided:
        (rx, ry) = panels[3]["shift"]
        # the return stroke runs from the crank end: its lines named a quarter of the way from there
        rk, rm = R[f"rK{n - max(1, (3 * n) // 8)}"], R[f"rM{n - max(1, n // 6)}"]
        furniture += [
            {"kind": "lettering", "at": (rk[0] + rx - 1.8 * d, rk[1] + ry + 1.2 * d), "text": "P = F·pü",
             "anchor": "end"},
            {"kind": "lettering", "at": (rm[0] + rx - 0.5 * d, rm[1] + ry + 1.3 * d), "text": "Pb", "anchor": "end"},
        ]
        # each column named under its force diagram
        bottom = min(y0 + (lo - 1.6) * step * unit, min(R[f"rK{k}"][1] + ry for k in range(n + 1)) - 3 * d)
        furniture += [
            {"kind": "lettering", "at": ((F0[0] + Fn[0]) / 2, bottom), "text": "Hingang (Deckelseite)"},
            {"kind": "lettering", "at": ((F0[0] + Fn[0]) / 2 + rx, bottom), "text": "Rückgang (Kurbelseite)"},
        ]
        looks.update({"rforcea": "heavy", "rforceb": "heavy", "rforcec": "heavy", "rmass": "heavy", "rbase": "thin"})
        # the clearance ends Z, Z' lettered over the stroke line, where nothing else stands: under it, the dead
        # centres' numbers would crowd them at the landscape sheet's scale
        letters = {n: t for st in fig.protocol.steps for n, t in st.labels}
        for name in ("ind.Z0", "ind.Z1"):
            if name in R and name in letters:
                Z = R[name]
                looks[name] = "unlettered"
                furniture.append({"kind": "lettering", "at": (Z[0], Z[1] + 2.2 * d), "text": letters[name]})
    return {"looks": looks, "furniture": furniture, "panels": panels}


#: The two-sided plate's panels: each side's indicator diagram over its stroke's force diagram.  The stroke
#: line, its dead centres and the ordinates stand in both columns.
_COVER = (r"axis", r"D[01]", r"ord\d+", r"ind\..*", r"card\..*")
_FORWARD = (r"ord\d+", r"fbase", r"F\d+", r"K\d+|Ks[12]", r"M\d+", r"force[abc]", r"mass", r"free\.[abc]", r"J")
_CRANK_SIDE = (r"axis", r"D[01]", r"ord\d+", r"crk\..*", r"crank\..*")
_RETURN = (r"ord\d+", r"rbase", r"rF\d+", r"rK\d+|rKs[12]", r"rM\d+", r"rforce[abc]", r"rmass", r"rfree\.[abc]")


def _revolution_panels(fig: Figure) -> list[dict]:
    """Where the two-sided plate puts its four diagrams (drawing units): the cover side's indicator diagram
    where it was constructed, its force diagram moved up under it, the crank side's diagram and the return
    stroke's force diagram a stroke and a half to the right, the two force diagrams' base lines on one level
    and the two indicator diagrams on one band.  Only whole diagrams move: every ordinate is read from its
    own base line, so no value on the plate changes."""
    R = fig.replay
    s = abs(R["D1"][0] - R["D0"][0])
    shown = [re.compile(p) for p in fig.params["plate"]]  # what the plate draws of each panel's objects

    def box(patterns: tuple[str, ...], skip: tuple[str, ...] = (r"ord\d+", r"axis")) -> tuple[float, ...]:
        pats = [re.compile(p) for p in patterns if p not in skip]
        pts = []
        for name, obj in R.items():
            if not (any(p.fullmatch(name) for p in pats) and any(p.fullmatch(name) for p in shown)):
                continue
            if hasattr(obj, "curve_points"):
                pts.extend(obj.curve_points())
            elif hasattr(obj, "rings"):
                pts.extend(q for ring in obj.rings() for q in ring)
            elif isinstance(obj, Point):
                pts.append(obj)
        return (min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts), max(p[1] for p in pts))

    cover, forward, crank = box(_COVER), box(_FORWARD), box(_CRANK_SIDE)
    gap = 0.35 * s  # under the stroke line: its letters (Z, 0, 18, Z')
    fdy = cover[1] - gap - forward[3]
    cdy = cover[1] - crank[1]  # the crank side's diagram on the cover side's band
    rdy = R["F0"][1] + fdy - R["rF0"][1]  # the base lines on one level
    dx = cover[2] - crank[0] + 0.5 * s
    return [{"names": _COVER, "shift": (0.0, 0.0)}, {"names": _FORWARD, "shift": (0.0, fdy)},
            {"names": _CRANK_SIDE, "shift": (dx, cdy)}, {"names": _RETURN, "shift": (dx, rdy)}]


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
                       en=f"piston force K{tag} = F p_ü (back pressure to steam line)")
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
    return Figure(proto, proto.replay(givens))


#: What the two-sided plate adds: the crank side's diagram below the stroke line, the return stroke's base line,
#: piston forces, mass forces, lines and hatched free forces.
REVOLUTION_PLATE = (r"rbase", r"rF\d+", r"rK\d+|rKs[12]", r"rM\d+", r"rforce[abc]", r"rmass", r"rfree\.[abc]",
                    r"axis", r"D[01]", r"(ind|crk)\.(steam|backline)", r"(ind|crk)\.[ER]r?\d+", r"ind\.Z[01]")


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


#: What a figure drawn from cards adds: each card's points and its two strokes' straightedge lines.
CARD_PLATE = (r"(card|crank)\.C\d+", r"(card|crank)\.(fwd|back|loop)", r"axis", r"D[01]")


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
    return {"cover.fwd": cover.forward, "cover.back": cover.back, "crank.fwd": crank.forward, "crank.back": crank.back,
            "cover.fwd.points": cover.forward_points, "crank.fwd.points": crank.forward_points}


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

    >>> card_crossing_chords([(0, 8), (1, 2)], [(0, 1), (0.9, 1), (1, 3)])
    (0, 1)
    >>> card_crossing_chords([(0, 8), (1, 5)], [(0, 1), (1, 1)]) is None
    True
    """
    found = None
    for i, (a, b) in enumerate(zip(cover, cover[1:])):
        for j, (c, e) in enumerate(zip(crank, crank[1:])):
            lo, hi = max(a[0], c[0]), min(b[0], e[0])
            if hi <= lo:
                continue

            def gap(x: float) -> float:  # cover above crank (positive) at x, both chords straight
                yc = a[1] + (b[1] - a[1]) * (x - a[0]) / (b[0] - a[0])
                yk = c[1] + (e[1] - c[1]) * (x - c[0]) / (e[0] - c[0])
                return yc - yk

            if gap(lo) > 0.0 >= gap(hi) or (gap(lo) == 0.0 and gap(hi) < 0.0 and found is None):
                found = (i, j)
    return found


def _card_pressure_change(b: Builder, f: Mapping[str, str], d: Mapping[str, Any], fbase: str) -> None:
    """J from the cards: the chords of the two forward lines that cross (read off the figure when the step is
    recorded, as the branch of an envelope is), each extended with the straightedge, their crossing J', and the
    perpendicular from it to the stroke line carried down to the force diagram's base.  Both cards are drawn in
    their piston area's scale, so J' is where F p' = F p'': the piston force's zero."""
    cover, crank = d["cover.fwd.points"], d["crank.fwd.points"]
    up = 1.0 if b[f["D1"]][0] > b[f["D0"]][0] else -1.0
    pts = lambda names: [(up * b[p][0], b[p][1]) for p in names]  # noqa: E731  (x along the stroke)
    chords = card_crossing_chords(pts(cover), pts(crank))
    if chords is None:
        return  # the piston force does not change sign: no J to draw (the caption's givens show why)
    i, j = chords
    with b.group("pressure change J: where the cards' forward lines cross", "Druckwechsel J: Schnitt der Linien "
                 "des Hinganges beider Diagramme"):
        g1 = b.line("J.g1", cover[i], cover[i + 1], de="Sehne der Deckelseite verlängert",
                    en="the cover side's chord extended")
        g2 = b.line("J.g2", crank[j], crank[j + 1], de="Sehne der Kurbelseite verlängert",
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


def _mass_areas(b: Builder, p: str, fbase: str, n: int) -> None:
    """The region between the mass-force line and the base (acceleration above, deceleration below), and the
    planimeter's reading round it: the same two steps for a drawn diagram and a digitised card's."""
    b.area_between(f"{p}massarea", f"{p}mass", fbase, f"{p}M0", f"{p}M{n}", role="construction",
                   de="Beschleunigungsfläche über, Verzögerungsfläche unter der Kolbenweglinie",
                   en="acceleration area above, deceleration area below the piston-path line")
    b.planimeter(f"{p}balance", f"{p}massarea",
                 de="mit dem Planimeter umfahren: Beschleunigungs- weniger Verzögerungsfläche",
                 en="planimeter round it: acceleration less deceleration area")


# --------------------------------------------------------------------------
# Measurements.
# --------------------------------------------------------------------------


def _base_frame(fig: Figure, prefix: str = "") -> tuple[float, float, float, float, float, float]:
    (ax, ay), (bx, by) = fig.replay[f"{prefix}F0"], fig.replay[f"{prefix}F{fig.params['parts']}"]
    s = math.hypot(bx - ax, by - ay)
    return ax, ay, (bx - ax) / s, (by - ay) / s, s, fig.replay.givens["force_unit"]


def abscissa(fig: Figure, point: str) -> float:
    """Piston path of a point as a fraction of the stroke, measured along the force diagram's base."""
    ax, ay, ux, uy, s, _ = _base_frame(fig)
    p = fig.replay[point]
    return ((p[0] - ax) * ux + (p[1] - ay) * uy) / s


def _force(fig: Figure, point: str, prefix: str = "") -> float:
    ax, ay, ux, uy, _, unit = _base_frame(fig, prefix)
    p = fig.replay[point]
    return ((p[0] - ax) * -uy + (p[1] - ay) * ux) / unit


def mass_force(fig: Figure, k: int) -> float:
    """P_b at division point k in kg, read off the force diagram (up = the masses are accelerated)."""
    return _force(fig, f"M{k}")


def piston_force(fig: Figure, tag: int | str) -> float:
    """F p_ü in kg at division point k (or "s1", "s2"), read off the force diagram."""
    return _force(fig, f"K{tag}")


def return_mass_force(fig: Figure, k: int) -> float:
    """P_b on the return stroke at the piston position of division point k, in kg (up = accelerated going back)."""
    return _force(fig, f"rM{k}", "r")


def return_piston_force(fig: Figure, tag: int | str) -> float:
    """F'' p'' - F' p' on the return stroke at division point k (or "s1", "s2"), in kg (+ = towards the head end)."""
    return _force(fig, f"rK{tag}", "r")


def card_force_zero(g: Mapping[str, float]) -> float | None:
    """The last x where the cards' forward piston force F p' − F p'' passes from pushing to braking (bisection
    on the straight lines between the digitised points), or None."""
    xs = sorted({x for c in card_pair(g) for x in c.forward[0]} | {0.0, 1.0})
    zero = None
    for lo, hi in zip(xs, xs[1:]):
        if _forward_force(lo, g) > 0.0 >= _forward_force(hi, g):
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if _forward_force(mid, g) > 0.0 else (lo, mid)
            zero = 0.5 * (lo + hi)
    return zero


def j_abscissa(g: Mapping[str, float]) -> float:
    """Where (P + P0)(s1 + s0)/(x + s0) = P0 (s3 + s0)/(s - x + s0), x as a fraction of the stroke."""
    c1 = (g["admission"] + g["back_pressure"]) * (g["filling"] + g["clearance"])
    c2 = g["back_pressure"] * (g["compression"] + g["clearance"])
    return (1.0 + 2.0 * g["clearance"]) * c1 / (c1 + c2) - g["clearance"]


def _two_term(w: float, lam: float) -> float:
    return math.cos(w) + lam * math.cos(2.0 * w)


def _exact_accel(w: float, lam: float) -> float:
    """Exact piston acceleration over omega^2 R for the finite rod (+ = towards the crank end)."""
    return analytic.inertia_exact(w, lam)


def _two_term_array(w: Any, lam: float) -> Any:
    """:func:`_two_term` on an array of angles."""
    return np.cos(w) + lam * np.cos(2.0 * w)


def _exact_accel_array(w: Any, lam: float) -> Any:
    """:func:`_exact_accel` (analytic.inertia_exact) on an array of angles."""
    s2 = np.sin(w) ** 2
    return np.cos(w) + lam * (np.cos(2.0 * w) + lam * lam * s2 * s2) / (1.0 - lam * lam * s2) ** 1.5


def _dx_dw_array(w: Any, lam: float) -> Any:
    """:func:`_dx_dw` on an array of angles."""
    s = np.sin(w)
    return (s + lam * s * np.cos(w) / np.sqrt(1.0 - lam * lam * s * s)) / 2.0


def _exact_path(w: float, lam: float) -> float:
    """Piston path over the stroke (exact)."""
    return (1.0 - math.cos(w) + (1.0 - math.sqrt(1.0 - lam * lam * math.sin(w) ** 2)) / lam) / 2.0


def _dx_dw(w: float, lam: float) -> float:
    s = math.sin(w)
    return (s + lam * s * math.cos(w) / math.sqrt(1.0 - lam * lam * s * s)) / 2.0


def _gauss(fn, a: float, b: float, pieces: int = 16, order: int = 20) -> float:
    """Gauss-Legendre of *order* on *pieces* equal pieces of [a, b]; *fn* takes an array of angles."""
    xs, ws = _LEGGAUSS[order] if order in _LEGGAUSS else np.polynomial.legendre.leggauss(order)
    h = (b - a) / pieces
    nodes = (a + h * np.arange(pieces))[:, None] + (xs + 1.0) * h / 2.0  # (piece, node)
    return float(((fn(nodes) * ws).sum(axis=1) * h / 2.0).sum())


_LEGGAUSS = {20: np.polynomial.legendre.leggauss(20)}


def _zero(fn, a: float, b: float) -> float:
    fa = fn(a)
    for _ in range(200):
        m = 0.5 * (a + b)
        if (fn(m) > 0) == (fa > 0):
            a, fa = m, fn(m)
        else:
            b = m
    return 0.5 * (a + b)


def _model_areas(g: Mapping[str, float]) -> dict[str, float]:
    """The areas of the models (eq. 298 and the exact kinematics) over the exact piston path, in kg m."""
    lam = g["crank_radius"] / g["rod_length"]
    A = mass_force_scale(g)
    stroke_m = 2.0 * g["crank_radius"]
    w0 = _zero(lambda w: _two_term(w, lam), 0.0, math.pi)
    two_acc = A * stroke_m * _gauss(lambda w: _two_term_array(w, lam) * _dx_dw_array(w, lam), 0.0, w0)
    two_dec = -A * stroke_m * _gauss(lambda w: _two_term_array(w, lam) * _dx_dw_array(w, lam), w0, math.pi)
    we = _zero(lambda w: _exact_accel(w, lam), 0.0, math.pi)
    exact_acc = A * stroke_m * _gauss(lambda w: _exact_accel_array(w, lam) * _dx_dw_array(w, lam), 0.0, we)
    exact_dec = -A * stroke_m * _gauss(lambda w: _exact_accel_array(w, lam) * _dx_dw_array(w, lam), we, math.pi)
    return {"two_term_acceleration": two_acc, "two_term_deceleration": two_dec,
            "exact_acceleration": exact_acc, "exact_deceleration": exact_dec}


def model_areas_sweep(g: Mapping[str, Any]) -> dict[str, Any]:
    """The model areas of :func:`area_balance` for a sweep's givens (arrays) in one numpy pass.

    The same rules as for one set of givens: the zeros by the same bisection,
    the same Gauss-Legendre rule, with one row of nodes per set of givens.
    Element i equals the areas of set i to rounding (the tests hold them equal).
    """
    lam = np.atleast_1d(np.asarray(g["crank_radius"] / g["rod_length"], dtype=float))
    n = lam.size
    A = np.broadcast_to(mass_force_scale(g), (n,))
    stroke_m = np.broadcast_to(2.0 * np.asarray(g["crank_radius"], dtype=float), (n,))
    L = lam[:, None]

    def zero(fn):  # _zero, one bisection per set of givens
        a, b = np.zeros(n), np.full(n, math.pi)
        fa = fn(a)
        for _ in range(200):
            m = 0.5 * (a + b)
            fm = fn(m)
            same = (fm > 0) == (fa > 0)
            a, fa, b = np.where(same, m, a), np.where(same, fm, fa), np.where(same, b, m)
        return 0.5 * (a + b)

    def gauss(fn, a, b, pieces: int = 16, order: int = 20):  # _gauss, one row of nodes per set of givens
        xs, ws = _LEGGAUSS[order]
        a, b = np.broadcast_to(a, (n,)), np.broadcast_to(b, (n,))
        h = (b - a) / pieces
        nodes = (a[:, None] + h[:, None] * np.arange(pieces))[:, :, None] + (xs + 1.0) * h[:, None, None] / 2.0
        return ((fn(nodes.reshape(n, -1)).reshape(nodes.shape) * ws).sum(axis=2) * (h / 2.0)[:, None]).sum(axis=1)

    two = lambda w: _two_term_array(w, L) * _dx_dw_array(w, L)  # noqa: E731
    exact = lambda w: _exact_accel_array(w, L) * _dx_dw_array(w, L)  # noqa: E731
    w0 = zero(lambda w: _two_term_array(w, lam))
    we = zero(lambda w: _exact_accel_array(w, lam))
    return {"two_term_acceleration": A * stroke_m * gauss(two, 0.0, w0),
            "two_term_deceleration": -A * stroke_m * gauss(two, w0, math.pi),
            "exact_acceleration": A * stroke_m * gauss(exact, 0.0, we),
            "exact_deceleration": -A * stroke_m * gauss(exact, we, math.pi)}


def area_balance(fig: Figure, model: Mapping[str, float] | None = None, stroke: str = "forward") -> dict[str, float]:
    """Acceleration area above the base and deceleration area below it, in kg m (= mkg of work).

    ``drawn_*``: the region between the mass-force line as drawn and the base line (an Area of the
    figure), measured; ``planimeter_balance`` the planimeter's reading round it (acceleration less
    deceleration);
    ``two_term_*``: eq. (298) over the exact piston path (Gauss quadrature);
    ``exact_*``: the exact kinematics, (G/g) v_max^2 / 2 on each side.
    *model*: the ``two_term_*`` and ``exact_*`` areas already computed for these givens (a sweep's, by
    :func:`model_areas_sweep`).
    """
    g = fig.replay.givens
    stroke_m = 2.0 * g["crank_radius"]
    p = "" if stroke == "forward" else "r"
    _, _, _, _, s, unit = _base_frame(fig, p)
    to_kgm = stroke_m / s / unit  # drawn area: length along the base -> m, height -> kg
    pieces = fig.replay[f"{p}massarea"].signed_pieces()  # the region between the drawn line and the base, split
    drawn_acc = sum(p.area for sign, p in pieces if sign > 0) * to_kgm
    drawn_dec = sum(p.area for sign, p in pieces if sign < 0) * to_kgm
    drawn_balance = float(fig.replay[f"{p}balance"]) * to_kgm  # the planimeter's reading
    models = _model_areas(g) if model is None else {k: float(v) for k, v in model.items()}
    if stroke != "forward":  # going back the masses are accelerated where they were decelerated coming
        models = {"two_term_acceleration": models["two_term_deceleration"],
                  "two_term_deceleration": models["two_term_acceleration"],
                  "exact_acceleration": models["exact_deceleration"],
                  "exact_deceleration": models["exact_acceleration"]}
    return {"drawn_acceleration": drawn_acc, "drawn_deceleration": drawn_dec, "planimeter_balance": drawn_balance,
            **models}


# --------------------------------------------------------------------------
# Checks.
# --------------------------------------------------------------------------


def piston_force_checks(fig: Figure, model: Mapping[str, float] | None = None) -> list[Check]:
    """The checks of a piston-force figure; *model*: the model areas of :func:`area_balance`, if known."""
    n = fig.params["parts"]
    g = fig.replay.givens
    lam = g["crank_radius"] / g["rod_length"]
    A = mass_force_scale(g)
    F = g["piston_area"]
    unit = g["force_unit"]
    stroke = 2.0 * g["crank_radius"] * g["scale"]
    # Euclidean float error ~1e-12 of the figure, read in kg: divide by the force unit.
    if "card.x0" in g:
        top = max(p for c in card_pair(g) for p in c.forward[1] + c.back[1])
        F = max(_areas(g))
    else:
        top = g["admission"] + g["back_pressure"]
    size = max(stroke, top * F * unit, A * unit, 1.0)
    kg_tol = EUCLIDEAN_TOLERANCE * size / unit
    made_by = fig.replay.made_by()
    checks: list[Check] = []
    for k in range(n + 1):
        w = math.pi * k / n
        tol_w, why_w = angle_tolerance(fig, point_name(fig, k), made_by)
        w_measured = crank_angle(fig, point_name(fig, k))
        x = abscissa(fig, f"M{k}")
        checks.append(Check(f"abscissa {k} (rod arcs)", x, _exact_path(w, lam), EUCLIDEAN_TOLERANCE + 0.5 * (1 + lam) * tol_w,
                            "rod arcs are Euclidean; division error times |dx/dw|", "stroke"))
        checks.append(Check(f"mass force {k} (eq. 298)", mass_force(fig, k), A * _two_term(w, lam),
                            kg_tol + A * (1.0 + 4.0 * lam) * tol_w, f"Euclidean chain as the inertia curve; {why_w}", "kg"))
        checks.append(Check(f"mass force {k} at the drawn angle (eq. 298)", mass_force(fig, k),
                            A * _two_term(w_measured, lam), kg_tol, "Euclidean chain: float rounding only", "kg"))
        bound = 2.5 * lam ** 3 / (1.0 - lam * lam) ** 2.5
        checks.append(Check(f"mass force {k} vs exact kinematics (information)", mass_force(fig, k),
                            A * _exact_accel(w, lam), A * bound + kg_tol + A * (1.0 + 4.0 * lam) * tol_w,
                            "eq. (298) drops the (R/L)^3 terms: |exact - two-term| <= 2.5 lam^3/(1 - lam^2)^2.5", "kg"))
        xk = abscissa(fig, f"K{k}")
        force = _forward_force(xk, g)
        checks.append(Check(f"piston force {k} (F p_ü, eq. 297)", piston_force(fig, k), force, kg_tol,
                            "Euclidean: ray-constructed hyperbolas, compass transfer", "kg"))
        checks.append(Check(f"free force {k}", piston_force(fig, k) - mass_force(fig, k),
                            force - A * _two_term(w_measured, lam), 2 * kg_tol, "difference of two Euclidean ordinates",
                            "kg"))
    cards = "card.x0" in g
    for tag, x in () if cards else (("s1", g["filling"]), ("s2", 1.0 - g["compression"])):
        checks.append(Check(f"piston force at {tag}", piston_force(fig, tag), _forward_force(x, g),
                            kg_tol, "Euclidean", "kg"))
    if fig.params.get("revolution"):
        return checks + _return_checks(fig, kg_tol, lam, A, made_by)
    xj = None if cards else j_abscissa(g)
    if not cards:  # J is constructed from the model's hyperbolas; a card has none
        checks.append(Check("pressure change J (abscissa)", abscissa(fig, "J"), xj, EUCLIDEAN_TOLERANCE * 10,
                            "fourth proportional and intercept theorem: Euclidean", "stroke"))
    elif "J" in fig.replay:  # the cards' straight lines: their forward force's last change of sign
        xj = card_force_zero(g)
        checks.append(Check("pressure change J (abscissa)", abscissa(fig, "J"), xj, EUCLIDEAN_TOLERANCE * 10,
                            "two chords extended and crossed, the perpendicular dropped: Euclidean", "stroke"))
        checks.append(Check("piston force at J", _forward_force(abscissa(fig, "J"), g), 0.0, kg_tol,
                            "J is the zero of F p' - F p'' on the cards' lines", "kg"))
    if not cards and g["filling"] < xj < 1.0 and xj > 1.0 - g["compression"]:
        checks.append(Check("p_ü at J", model_steam(xj, g) - model_back(xj, g), 0.0, 1e-12 * (g["admission"] + 1),
                            "J is the zero of the over-pressure", "at"))
    # the area balance: reported, not assumed
    a = area_balance(fig, model)
    curve_tol = _curve_area_tolerance(n, lam) * A * 2.0 * g["crank_radius"]
    for side in ("acceleration", "deceleration"):
        checks.append(Check(f"{side} area as drawn vs eq. (298) over the exact path", a[f"drawn_{side}"],
                            a[f"two_term_{side}"], curve_tol,
                            "French curve through the points: height error <= 2 (pi/n)^3 (1 + 4 lam) (G/g) omega^2 R "
                            "(estimate), times the stroke", "kg m"))
        checks.append(Check(f"{side} area, eq. (298) vs exact kinematics (information)", a[f"two_term_{side}"],
                            a[f"exact_{side}"], A * 2.0 * g["crank_radius"] * 2.5 * lam ** 3 / (1 - lam * lam) ** 2.5,
                            "eq. (298) drops the (R/L)^3 terms", "kg m"))
    checks.append(Check("area balance, exact kinematics (acceleration - deceleration)",
                        a["exact_acceleration"] - a["exact_deceleration"], 0.0, 1e-9 * A,
                        "the masses start and end the stroke at rest: the work balances exactly", "kg m"))
    checks.append(Check("area balance, eq. (298) over the exact path (information)",
                        a["two_term_acceleration"] - a["two_term_deceleration"], 0.0,
                        A * 2.0 * g["crank_radius"] * lam ** 3,
                        "eq. (298) is exact for the path of Gl. (1), not for the rod arcs: residue O(lam^3)", "kg m"))
    checks.append(Check("planimeter reading = acceleration - deceleration area", a["planimeter_balance"],
                        a["drawn_acceleration"] - a["drawn_deceleration"], 1e-9 * A * 2.0 * g["crank_radius"],
                        "the same drawn region, measured whole and piece by piece", "kg m"))
    checks.append(Check("area balance as drawn (information)", a["drawn_acceleration"] - a["drawn_deceleration"], 0.0,
                        2 * curve_tol + A * 2.0 * g["crank_radius"] * lam ** 3,
                        "drawing error of the curve plus the O(lam^3) residue", "kg m"))
    return checks


def _areas(g: Mapping[str, float]) -> tuple[float, float]:
    if "piston_area_cover" in g:
        return g["piston_area_cover"], g["piston_area_crank"]
    return g["piston_area"], g["piston_area"]


def _forward_force(x: float, g: Mapping[str, float]) -> float:
    """The piston force on the forward stroke (kg): F p_ü with one area, F' p' - F'' p'' with both sides'."""
    if "card.x0" in g:  # the cards' lines, straight between their points
        cover, crank = card_pair(g)
        f1, f2 = _areas(g)
        return f1 * cover.pressure(x, "forward") - f2 * crank.pressure(x, "forward")
    if "piston_area_cover" in g:
        return g["piston_area_cover"] * model_steam(x, g) - g["piston_area_crank"] * model_back(x, g)
    return g["piston_area"] * (model_steam(x, g) - model_back(x, g))


def _return_force(x: float, g: Mapping[str, float]) -> float:
    """F'' p'' - F' p' on the return stroke at piston position x: the crank side's diagram is the cover side's mirrored."""
    if "card.x0" in g:
        cover, crank = card_pair(g)
        f1, f2 = _areas(g)
        return f2 * crank.pressure(x, "return") - f1 * cover.pressure(x, "return")
    return g["piston_area_crank"] * model_steam(1.0 - x, g) - g["piston_area_cover"] * model_back(1.0 - x, g)


def _return_checks(fig: Figure, kg_tol: float, lam: float, A: float, made_by: Mapping[str, Any]) -> list[Check]:
    """The return stroke against (298) with the minus sign and the mirrored diagram, and its area balance."""
    n = fig.params["parts"]
    g = fig.replay.givens
    checks: list[Check] = []
    for k in range(n + 1):
        w = math.pi * k / n
        tol_w, why_w = angle_tolerance(fig, point_name(fig, k), made_by)
        w_measured = crank_angle(fig, point_name(fig, k))
        checks.append(Check(f"return mass force {k} (eq. 298, minus sign)", return_mass_force(fig, k),
                            -A * _two_term(w, lam), kg_tol + A * (1.0 + 4.0 * lam) * tol_w,
                            f"the forward ordinate carried the other way; {why_w}", "kg"))
        checks.append(Check(f"return mass force {k} = -(forward)", return_mass_force(fig, k), -mass_force(fig, k),
                            2 * kg_tol, "the same compass opening laid off the other way", "kg"))
        checks.append(Check(f"return mass force {k} at the drawn angle", return_mass_force(fig, k),
                            -A * _two_term(w_measured, lam), kg_tol, "Euclidean chain: float rounding only", "kg"))
        x = abscissa(fig, f"rK{k}")
        checks.append(Check(f"return piston force {k} (F''p'' - F'p')", return_piston_force(fig, k),
                            _return_force(x, g), 2 * kg_tol,
                            "Euclidean: mirrored diagram, proportional angle for F'/F'', compass transfer", "kg"))
    for tag, x in () if "card.x0" in g else (("s1", 1.0 - g["filling"]), ("s2", g["compression"])):
        checks.append(Check(f"return piston force at {tag}", return_piston_force(fig, tag), _return_force(x, g),
                            2 * kg_tol, "Euclidean", "kg"))
    curve_tol = _curve_area_tolerance(n, lam) * A * 2.0 * g["crank_radius"]
    fwd, ret = area_balance(fig), area_balance(fig, stroke="return")
    for side in ("acceleration", "deceleration"):
        checks.append(Check(f"return stroke: {side} area as drawn vs eq. (298)", ret[f"drawn_{side}"],
                            ret[f"two_term_{side}"], curve_tol, "French curve through the points (estimate), times "
                            "the stroke", "kg m"))
    checks.append(Check("return acceleration area = forward deceleration area (as drawn)", ret["drawn_acceleration"],
                        fwd["drawn_deceleration"], 1e-9 * A * 2.0 * g["crank_radius"],
                        "the same curve, mirrored in the base line", "kg m"))
    checks.append(Check("return planimeter reading = acceleration - deceleration area", ret["planimeter_balance"],
                        ret["drawn_acceleration"] - ret["drawn_deceleration"], 1e-9 * A * 2.0 * g["crank_radius"],
                        "the same drawn region, measured whole and piece by piece", "kg m"))
    return checks


def _curve_area_tolerance(n: int, lam: float) -> float:
    return 2.0 * (math.pi / n) ** 3 * (1.0 + 4.0 * lam)


def piston_force_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as Tafel I writes them (G, n, R, L, F; F′ and F″ over both strokes), Baumann's diagram or a
    digitised card's, and the semicircle's division."""
    g = fig.replay.givens
    de = lang == "de"
    out = [f"G = {number(g['weight'], lang)} kg", f"n = {number(g['rpm'], lang)}/min",
           f"R = {metres(g['crank_radius'], lang)} m", f"L = {metres(g['rod_length'], lang)} m",
           f"F = {number(g['piston_area'], lang, 5)} cm²"]
    if "admission" in g:  # Baumann's idealised diagram (a digitised card says itself, below)
        out += [f"p₁ = {number(g['admission'], lang)} at", f"p₂ = {number(g['back_pressure'], lang)} at",
                ("Füllung " if de else "cut-off ") + percent(g["filling"], lang),
                ("schädlicher Raum " if de else "clearance ") + percent(g["clearance"], lang),
                ("Kompression " if de else "compression ") + percent(g["compression"], lang)]
    out.append(division(fig, lang))
    if fig.params.get("revolution"):  # both sides, each with its own area (Tafel I: F', F'')
        out[4] = (f"F′ = {number(g['piston_area_cover'], lang, 6)} cm² (Deckelseite), "
                  f"F″ = {number(g['piston_area_crank'], lang, 6)} cm² (Kurbelseite), Hin- und Rückgang" if de else
                  f"F′ = {number(g['piston_area_cover'], lang, 6)} cm² (cover side), "
                  f"F″ = {number(g['piston_area_crank'], lang, 6)} cm² (crank side), both strokes")
    return out + card(fig, lang)


def piston_force_note(fig: Figure, lang: str) -> str:
    """What the 990-kg plate must say beyond its givens: it shows the high-pressure side's diagram."""
    if fig.replay.givens.get("weight") == 990.0:
        return ("Massen der Niederdruckseite (990 kg) über dem Dampfdiagramm der Hochdruckseite" if lang == "de" else
                "low-pressure side's masses (990 kg) over the high-pressure side's steam diagram")
    return ""


PISTON_FORCE = register(Construction(
    name="piston-force",
    title=Caption("Kolbenüberdrucklinie mit den Massenkräften", "Piston-force line with the mass forces"),
    source="seed 001, Abb. 1054/1055, Gl. (297)-(299), Tafel I; seed 004 (Baumann's idealised diagram)",
    build=lambda parts, method, **v: build_piston_force(parts=parts, method=method, **v),
    checks=piston_force_checks,
    sweep_model=lambda g, params: model_areas_sweep(g),
    defaults={"parts": 18, "method": "auto", **TAFEL_I, **HP_DIAGRAM, "scale": 2.5, "force_unit": 1.2e-4,
              "piston_area_cover": PISTON_AREA_COVER, "piston_area_crank": PISTON_AREA_CRANK, "revolution": False,
              "indicator": "", "indicator_crank_side": ""},
    # Tafel I: high-pressure and low-pressure side; and both strokes of the high-pressure side, F' and F''
    book_params=({}, {"weight": 990.0}, {"revolution": True}),
    structural=("parts", "method", "filling", "compression", "revolution", "indicator", "indicator_crank_side"),
    sweep=lambda g, ratios: {**g, "rod_length": ratios * g["crank_radius"]},  # L = (L/R) R
    cites=(Cite(HANDBOOK, "Abb. 1054/1055"), Cite(BAUMANN_1902, "Fig. 25")),
    wording=piston_force_wording,
    note=piston_force_note,
    methods=DIVISION_NAMES,
    plate=piston_force_plate,
    validator=_validate,
    help={
        "weight": "weight G of the reciprocating parts in kg (Tafel I: 830 high-pressure, 990 low-pressure side)",
        "rpm": "revolutions per minute n (Tafel I: 50)",
        "crank_radius": "crank radius R in m (Tafel I: 0.4)",
        "rod_length": "connecting-rod length L in m (Tafel I: 2.0)",
        "piston_area": "piston area F in cm^2 (Tafel I: (F' + F'')/2 = 1529.07)",
        "piston_area_cover": "piston-force --revolution: F' of the cover side in cm^2 (Tafel I: 1546.25)",
        "piston_area_crank": "piston-force --revolution: F'' of the crank side, less the rod, in cm^2 (Tafel I: 1511.89)",
        "scale": "drawn length per metre of stroke (piston-force; default 2.5)",
        "force_unit": "drawn length per kg of force (piston-force; default 1.2e-4)",
    },
))


# --------------------------------------------------------------------------
# Table: the mass forces measured on the construction.
# --------------------------------------------------------------------------


def mass_force_rows(*, weight: float, rpm: float, crank_radius: float, rod_length: float,
                    parts: int = 18) -> list[dict[str, Any]]:
    """crank_angle_deg, x (fraction of the stroke) and P_b (kg, + = masses accelerated), read off the figure.

    >>> rows = mass_force_rows(weight=830, rpm=50, crank_radius=0.4, rod_length=2.0, parts=2)
    >>> [(round(r["crank_angle_deg"], 9), round(r["x"], 9), round(r["P_b"], 3)) for r in rows]
    [(0.0, 0.0, 1113.391), (90.0, 0.550510257, -185.565), (180.0, 1.0, -742.26)]
    """
    fig = PISTON_FORCE.figure(weight=weight, rpm=rpm, crank_radius=crank_radius, rod_length=rod_length, parts=parts)
    return [{"crank_angle_deg": math.degrees(crank_angle(fig, point_name(fig, k))), "x": abscissa(fig, f"M{k}"),
             "P_b": mass_force(fig, k)} for k in range(parts + 1)]


def revolution_mass_force_rows(*, weight: float, rpm: float, crank_radius: float, rod_length: float,
                               parts: int = 18) -> list[dict[str, Any]]:
    """Both strokes: crank_angle_deg 0..360, stroke, x (from the head-end dead centre) and P_b (kg), measured.

    P_b is positive where the masses take up force in the direction of the current stroke: eq. (298) forward,
    and on the return (298) with the angle from the crank-end dead centre and the minus sign.  The dead
    centres belong to both strokes: 180° closes the forward stroke (its row ``forward``) and opens the return
    (``return``); 0° opens the forward stroke, 360° closes the return.

    >>> rows = revolution_mass_force_rows(weight=830, rpm=50, crank_radius=0.4, rod_length=2.0, parts=2)
    >>> [(round(r["crank_angle_deg"], 9), r["stroke"], round(r["x"], 9), round(r["P_b"], 3)) for r in rows]
    ... # doctest: +NORMALIZE_WHITESPACE
    [(0.0, 'forward', 0.0, 1113.391), (90.0, 'forward', 0.550510257, -185.565), (180.0, 'forward', 1.0, -742.26),
     (180.0, 'return', 1.0, 742.26), (270.0, 'return', 0.550510257, 185.565), (360.0, 'return', 0.0, -1113.391)]
    """
    fig = PISTON_FORCE.figure(weight=weight, rpm=rpm, crank_radius=crank_radius, rod_length=rod_length, parts=parts,
                              revolution=True)
    rows = []
    for k in range(parts + 1):
        rows.append({"crank_angle_deg": math.degrees(crank_angle(fig, point_name(fig, k))), "stroke": "forward",
                     "x": abscissa(fig, f"M{k}"), "P_b": mass_force(fig, k)})
    for k in range(parts, -1, -1):
        rows.append({"crank_angle_deg": 360.0 - math.degrees(crank_angle(fig, point_name(fig, k))), "stroke": "return",
                     "x": abscissa(fig, f"rM{k}"), "P_b": return_mass_force(fig, k)})
    return rows
