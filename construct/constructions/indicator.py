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

The building part is reusable and has a module of its own
(:mod:`construct.constructions.indicator_parts`: :func:`indicator_frame`, :func:`pressures_at`, the model
pressures); this module is the construction 'indicator-diagram' and the digitised indicator card.

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
from typing import Mapping

from .checking import EUCLIDEAN_TOLERANCE, Check
from ..kernel.errors import InvalidParameter
from ..kernel.instruments import Builder
from ..kernel.protocol import Caption
from . import Construction, Figure, bounded, register
from .domain import DRAWN_LENGTH
from .indicator_parts import (BAUMANN, IndicatorDiagram, back_pressure, hyperbola_point, hyperbola_tangent,
                              indicator_frame, indicator_givens, pressures_at, square, steam_pressure)
from .phrases import BAUMANN_1902, Cite, card, diagram, scale
from .scales import scale_furniture

__all__ = ["INDICATOR", "IndicatorDiagram", "indicator_frame", "pressures_at", "hyperbola_point", "square",
           "indicator_givens", "BAUMANN", "abscissa", "pressure", "steam_pressure", "back_pressure"]

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
        exp_tan[0] = hyperbola_tangent(b, d, d.cutoff, d.cutoff_ordinate, d.Z0, "tA1")
        comp_tan[0] = hyperbola_tangent(b, d, d.compression_start, d.compression_ordinate, d.Z1, "tC2")
    with b.group("the curves drawn through the points", "Die Linien durch die Punkte gezogen"):
        b.french_curve("expansion", base, exp_pts, {i: t for i, t in exp_tan.items() if t},
                     de="Expansionslinie (Hyperbel) mit dem Curvenlineal", en="expansion line (hyperbola), French curve")
        b.french_curve("compression", base, comp_pts, {i: t for i, t in comp_tan.items() if t},
                     de="Kompressionslinie (Hyperbel) mit dem Curvenlineal", en="compression line (hyperbola), French curve")
    proto = b.protocol()
    return Figure(proto, b.replay(proto, givens))


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
    return Figure(proto, b.replay(proto, givens))


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
