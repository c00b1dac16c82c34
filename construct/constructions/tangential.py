"""The tangential-pressure diagram ("Tangentialdruckdiagramm"), seed 004 (Baumann 1902, Fig. 26/27).

For each crank position P of the divided semicircle the rod line from the
crosshead C through P, extended, meets the perpendicular to the stroke
through O at K; by similar triangles the tangential pressure on the crank
pin is T = P'·OK/r (P' the free piston force: the piston force less the
acceleration force), and DESIGN §5 writes it T = P'·sin(ω + β)/cos β.  Steps:

* OK is swung onto the stroke line (a circle about O through K): the point H;
* P' stands as a compass opening on the vertical through the dead centre D1
  (at the distance r from O): the mark M, up = positive; the ray O–M meets the
  vertical through H at the height P'·OK/r (intercept theorem: the proportional
  angle at O, scale lines at r and at OK);
* that height is carried with the compass to the ordinate of the unrolled
  crank circle.

The unrolled circle is not a Euclidean step: the dividers step the chord of
one division n times along the base line, so the drawn length is
n·2r·sin(π/2n) instead of πr (the provenance of every abscissa says so and
states the shortfall).  Angles read off the unrolled scale are taken in
proportion to the drawn length, where the chord error cancels.

The free piston force P' comes, with ``force="baumann"``, from his model: the
over-pressure of the idealised indicator diagram (module
:mod:`construct.constructions.indicator`, hyperbolas by the ray construction)
less the acceleration force B = (c v²/r)(cos ω + (r/L) cos 2ω), constructed as
the inertia ordinates of seed 000 (:mod:`construct.constructions.inertia`),
with c v²/r = P/((1 + r/L) κ) for Baumann's κ = P/B_max.  With
``force="unit"`` P' is the crank radius r itself: the ordinates are OK.

Over a revolution (``revolution=True``, :mod:`construct.constructions.revolution`)
the return stroke's P' comes from the crank side's diagram: under Baumann's force
his diagram mirrored (drawn from the other dead centre, below the stroke line --
his assumption, and the caption says so) with the mass force of (298)'s minus
sign; with cards the crank side's card.  A compound or tandem engine's
low-pressure cylinder has its own diagram (``lp_*`` givens, or ``indicator_lp``)
drawn in the pressure scale times F_lp/F_hp (``area_ratio``), so that its
ordinates are forces in the high-pressure piston's unit and add with the dividers.

The curve is drawn through the points (French curve); the planimeter gives
the mean line ("Ausgleichende", height = area / drawn length, = 2 P_i/π for
the exact curve); where it crosses the curve are α1, α2; between them, above
the mean line, the excess area ("Überschussfläche", hatched), the work the
flywheel must take up.

>>> fig = TANGENTIAL.figure(force="unit", parts=6, rod_ratio=5.0)
>>> round(ok_over_r(fig, 3), 12)   # 90 degrees: sin(90° + β)/cos β = 1
1.0
>>> round(ok_over_r(fig, 2), 12) == round(math.sin(math.pi / 3 + math.asin(math.sin(math.pi / 3) / 5))
...                                         / math.cos(math.asin(math.sin(math.pi / 3) / 5)), 12)
True
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any, Mapping

import numpy as np

from .checking import EUCLIDEAN_TOLERANCE, Check
from ..kernel.errors import GeometryError, InvalidParameter, did_you_mean
from ..kernel.division import NAMES as DIVISION_NAMES
from ..kernel.division import check_parts, divide_semicircle
from ..kernel.instruments import Builder
from ..kernel.proportional import scale_line
from ..kernel.protocol import Caption, Provenance
from . import Construction, Figure, bounded, positive, register, rod_ratio_param
from .domain import AREA_RATIO, DRAWN_LENGTH, KAPPA_RANGE
from .crank import angle_tolerance, build_frame, crank_angle, point_name, rod_arcs
from .indicator import BAUMANN, indicator_frame, indicator_givens, pressures_at
from .indicator import back_pressure as model_back_pressure
from .indicator import steam_pressure as model_steam_pressure
from .ordinates import inertia_setup, ordinate_value, point_kind
from .indicator_card import card_force, card_givens, card_pair, draw_card, load_indicator
from .phrases import BAUMANN_1902, Cite, card, diagram, division, low_pressure, number, ratio, revolution, scale
from .revolution import (MACHINES, REVOLUTION_PLATE, build_revolution, crank_shifts, engine_cylinders, parse_cranks,
                         revolution_checks, unroll_by_chords)

__all__ = ["TANGENTIAL", "build_tangential", "tangential_checks", "ok_over_r", "t_over_unit", "free_force",
           "model_t", "baumann_force", "return_free_force", "drawn_model", "unrolled_angle", "mean_height",
           "excess_area", "crossing_angles", "model_summary", "model_summary_sweep", "KAPPA", "FORCES",
           "LOW_PRESSURE", "low_force"]

#: Baumann's κ = P/B_max ("Verhältnis des Anfangsbeschleunigungsdrucks zum Anfangskolbendruck"), his first case.
KAPPA = 8.0
FORCES = ("baumann", "unit", "indicator")

#: What the Fig. 26/27-like plate shows: the unrolled base, the ordinates and points of T, the curve,
#: the mean line, the crossings and the hatched excess area.
PLATE = (r"tbase", r"U\d+", r"u\d+", r"T\d+", r"tcurve", r"M0|Mn", r"mean", r"A1|A2", r"excess")


def _givens(r: Any, rod_ratio: Any, force: str, kappa: Any, pressure_unit: Any, cards: Any = None,
            **diagram: Any) -> dict[str, float]:
    g = {"r": bounded("crank radius r", r, DRAWN_LENGTH), "rod_ratio": rod_ratio_param(rod_ratio)}
    if force == "unit":
        return g
    if force == "indicator":
        g["pressure_unit"] = bounded("pressure-scale unit (drawn length of 1 at)", pressure_unit, DRAWN_LENGTH)
        cover, crank = cards
        g.update(card_givens(cover, "card."))
        if crank is not None:
            g.update(card_givens(crank, "crank."))
        return g
    d = indicator_givens(diagram["filling"], diagram["clearance"], diagram["admission"], diagram["back_pressure"],
                         diagram["compression"], pressure_unit)
    k = bounded("kappa = P/B_max", kappa, KAPPA_RANGE)
    # c v^2/r (at): the inertia ordinate's factor, so that B_max = (1 + r/L) c v^2/r = P/kappa.
    g.update(d, pressure_ratio=d["admission"] / (k * (1.0 + 1.0 / g["rod_ratio"])))
    return g


#: The low-pressure cylinder of a compound or tandem engine under Baumann's force: illustrative defaults (the
#: seeds print no compound's diagrams -- seed 004 gives only its totals): receiver admission 1.6 at over a
#: condenser's 0.15 at, filling 0.35, compression 0.30, its piston 2.5 times the high-pressure one's.
LOW_PRESSURE = {"lp_filling": 0.35, "lp_admission": 1.6, "lp_back_pressure": 0.15, "lp_compression": 0.30,
                "lp_kappa": KAPPA, "area_ratio": 2.5}


def _low_givens(g: Mapping[str, float], force: str, low: Mapping[str, Any], cards: Any = None) -> dict[str, float]:
    """The low-pressure cylinder's givens (``lp.``): its own diagram or cards and its piston area over the first's."""
    out = {"area_ratio": bounded("area ratio F_lp/F_hp", low["area_ratio"], AREA_RATIO)}
    if force == "indicator":
        cover, crank = cards
        out.update(card_givens(cover, "lp.card."))
        if crank is not None:
            out.update(card_givens(crank, "lp.crank."))
        return out
    try:
        d = indicator_givens(low["lp_filling"], g["clearance"], low["lp_admission"], low["lp_back_pressure"],
                             low["lp_compression"], g["pressure_unit"])
    except InvalidParameter as exc:  # the same rules as the first cylinder's, said of the low-pressure one
        raise InvalidParameter(f"the low-pressure cylinder (--lp-*): {exc}") from None
    k = bounded("low-pressure kappa = P/B_max", low["lp_kappa"], KAPPA_RANGE)
    out.update({f"lp.{key}": d[key] for key in ("filling", "clearance", "admission", "back_pressure", "compression")})
    out["lp.pressure_ratio"] = d["admission"] / (k * (1.0 + 1.0 / g["rod_ratio"]))
    return out


def low_force(g: Mapping[str, float], force: str, lam: float) -> Any:
    """The low-pressure cylinder's force along the motion over the whole turn, in at of the first piston's area
    (its own pressures times F_lp/F_hp); None if the engine has no low-pressure diagram of its own."""
    if "area_ratio" not in g:
        return None
    ratio = g["area_ratio"]
    if force == "indicator":
        fn = card_force(g, lam, "lp.")
    else:
        fn = baumann_force({key: g[f"lp.{key}"] for key in ("filling", "clearance", "admission", "back_pressure",
                                                             "compression", "pressure_ratio")}, lam)
    return lambda w: ratio * fn(w)


def _validate(givens: Mapping[str, float]) -> None:
    bounded("crank radius r", givens["r"], DRAWN_LENGTH)
    rod_ratio_param(givens["rod_ratio"])
    if "card.x0" in givens:  # a digitised card: checked as a file is
        bounded("pressure-scale unit (drawn length of 1 at)", givens["pressure_unit"], DRAWN_LENGTH)
        card_pair(givens)
    if "admission" in givens:
        indicator_givens(givens["filling"], givens["clearance"], givens["admission"], givens["back_pressure"],
                         givens["compression"], givens["pressure_unit"])
        positive("c v^2/r (pressure_ratio)", givens["pressure_ratio"])
    if "area_ratio" in givens:
        bounded("area ratio F_lp/F_hp", givens["area_ratio"], AREA_RATIO)
    if "lp.card.x0" in givens:
        card_pair(givens, "lp.")
    if "lp.admission" in givens:
        indicator_givens(givens["lp.filling"], givens["lp.clearance"], givens["lp.admission"],
                         givens["lp.back_pressure"], givens["lp.compression"], givens["pressure_unit"])
        positive("low-pressure c v^2/r (lp.pressure_ratio)", givens["lp.pressure_ratio"])


def _approx(method: str, error: float) -> Provenance:
    return Provenance("approximate", method, error)


def chord_shortfall(n: int, r: float = 1.0) -> float:
    """πr less n chords of 1/n of the semicircle: what the dividers lose on the unrolled circle."""
    return r * (math.pi - 2.0 * n * math.sin(math.pi / (2.0 * n)))


def _engine(revolution: Any, cranks: Any, machine: Any, force: str, parts: int) -> dict[str, Any]:
    """The revolution's params: crank offsets, their shifts in divisions, cylinders per rod (empty: forward stroke)."""
    if machine not in MACHINES:
        raise InvalidParameter(f"machine must be one of {', '.join(MACHINES)}, got {machine!r}"
                               f"{did_you_mean(machine, MACHINES)}")
    if not revolution:
        if cranks or machine != "single":
            raise InvalidParameter("--cranks and --machine draw the whole revolution: add --revolution")
        return {}
    m = MACHINES[machine]
    offsets = parse_cranks(cranks) if cranks else m.cranks
    if machine == "compound" and len(offsets) != 2:
        raise InvalidParameter(f"a compound engine has two cranks (high and low pressure), got --cranks {cranks!r}")
    return {"revolution": True, "machine": machine, "cranks": ", ".join(f"{v:g}" for v in offsets),
            "offsets": offsets, "shifts": crank_shifts(offsets, parts),
            "cylinders": m.cylinders, "plate": REVOLUTION_PLATE}


def build_tangential(*, rod_ratio: float, parts: int, method: str, r: float, force: str, kappa: float,
                     filling: float, clearance: float, admission: float, back_pressure: float, compression: float,
                     pressure_unit: float, revolution: bool = False, cranks: str = "", machine: str = "single",
                     indicator: str = "", indicator_crank_side: str = "", indicator_lp: str = "",
                     indicator_lp_crank_side: str = "", **low: Any) -> Figure:
    unknown = set(low) - set(LOW_PRESSURE)
    if unknown:
        raise InvalidParameter(f"tangential-pressure has no parameter {', '.join(sorted(unknown))}")
    low = {**LOW_PRESSURE, **low}
    if force not in FORCES:
        raise InvalidParameter(f"force must be one of {', '.join(FORCES)}, got {force!r}{did_you_mean(force, FORCES)}")
    cards = None
    if indicator_crank_side and not indicator:
        raise InvalidParameter("--indicator-crank-side goes with --indicator (the cover side's diagram)")
    if indicator:
        if force == "unit":
            raise InvalidParameter("--indicator gives the forces: leave out --force unit")
        force = "indicator"
        cards = (load_indicator(indicator), load_indicator(indicator_crank_side) if indicator_crank_side else None)
    elif force == "indicator":
        raise InvalidParameter("--force indicator needs --indicator FILE.csv")
    if indicator_lp_crank_side and not indicator_lp:
        raise InvalidParameter("--indicator-lp-crank-side goes with --indicator-lp (the low-pressure cover side's "
                               "diagram)")
    if indicator_lp and not indicator:
        raise InvalidParameter("--indicator-lp goes with --indicator (the high-pressure cylinder's diagram)")
    if indicator_lp and not (revolution and machine in ("compound", "tandem")):
        raise InvalidParameter("--indicator-lp is the low-pressure cylinder of a compound or tandem engine: add "
                               "--revolution --machine compound (or tandem)")
    low_cards = (load_indicator(indicator_lp), load_indicator(indicator_lp_crank_side)
                 if indicator_lp_crank_side else None) if indicator_lp else None
    givens = _givens(r, rod_ratio, force, kappa, pressure_unit, cards, filling=filling, clearance=clearance,
                     admission=admission, back_pressure=back_pressure, compression=compression)
    used = check_parts(parts, method)
    if parts < 2:
        raise InvalidParameter(f"the tangential-pressure diagram needs at least 2 parts, got {parts}")
    params = {"parts": parts, "method": used, "requested_method": method, "force": force, "plate": PLATE}
    engine = _engine(revolution, cranks, machine, force, parts)
    params.update(engine)
    # A compound or tandem engine's low-pressure cylinder has its own diagram: always under Baumann's force
    # (its own givens), with cards when --indicator-lp gives one.
    own_low = bool(engine) and machine in ("compound", "tandem") and (force == "baumann" or low_cards is not None)
    if own_low:
        givens.update(_low_givens(givens, force, low, low_cards))
        params["low_pressure"] = True
    else:  # a low-pressure given where there is no low-pressure cylinder of its own: say so, do not ignore it
        _low_givens({"clearance": BAUMANN["clearance"], "pressure_unit": 1.0, "rod_ratio": givens["rod_ratio"]},
                    "baumann", low)  # out of its domain first: named with its value
        stray = [k for k, v in low.items() if v != LOW_PRESSURE[k]]
        if stray:
            raise InvalidParameter(f"--{stray[0].replace('_', '-')} belongs to a compound or tandem engine's "
                                   f"low-pressure cylinder (--revolution --machine compound, under --force baumann "
                                   f"or with --indicator-lp)")
    if force == "baumann":
        params.update(filling=givens["filling"], compression=givens["compression"])
    b = Builder("tangential-pressure", givens, params)
    f = build_frame(b)
    n = parts
    points = divide_semicircle(b, O=f["O"], D0=f["D0"], D1=f["D1"], circle=f["circle"], axis=f["axis"],
                               n=n, method=used)
    rod_arcs(b, f, points)
    O, axis = f["O"], f["axis"]
    if force == "baumann":
        ctx = inertia_setup(b, f)  # vertical through O, 90° point, proportional angle for r/L and c v^2/r
        vert = ctx.vert
        d = indicator_frame(b, base=axis, head=f["D0"], crank=f["D1"], prefix="ind.")
        scale = d.prefix + "v.crank"
        # Baumann's assumption ("die Tangentialdruckdiagramme des Hin- und Rückganges gleich"): the crank side's
        # diagram is the cover side's, drawn from the other dead centre (below the stroke line).
        d_return = None
        if engine:
            with b.group("the crank side's diagram: the cover side's, mirrored (Baumann's assumption: the diagrams "
                         "of the forward and return strokes are equal)",
                         "Das Diagramm der Kurbelseite: das der Deckelseite gespiegelt (Baumanns Annahme: die "
                         "Diagramme des Hin- und Rückganges gleich)"):
                d_return = indicator_frame(b, base=axis, head=f["D1"], crank=f["D0"], prefix="rind.")
        return_heights = {}
        if own_low:
            with b.group("the low-pressure cylinder: its diagrams in the pressure scale times F_lp/F_hp",
                         "Der Niederdruckzylinder: seine Diagramme im Druckmaßstab mal F_nd/F_hd"):
                lp_Ff = b.given_length("lp.Ff", product=("lp.pressure_ratio", "pressure_unit", "area_ratio"),
                                       de="F/f des Niederdruckzylinders im Druckmaßstab",
                                       en="the low-pressure cylinder's F/f in the pressure scale")
                ctx_lp = replace(ctx, Ff=lp_Ff, gf=scale_line(
                    b, ctx.angle, "lp.gf", length=lp_Ff, toward=("toward", "S", O),
                    de="Marke F/f (Niederdruck) von S aus", en="mark F/f (low pressure) from S"))
                lp_scale = ("pressure_unit", "area_ratio")
                d_lp = indicator_frame(b, base=axis, head=f["D0"], crank=f["D1"], prefix="lp.ind.",
                                       pressure_scale=lp_scale, given_prefix="lp.")
                d_lp_return = indicator_frame(b, base=axis, head=f["D1"], crank=f["D0"], prefix="lp.rind.",
                                              pressure_scale=lp_scale, given_prefix="lp.")
    elif force == "indicator":
        with b.group("perpendicular to the stroke through O", "Senkrechte zum Hub durch O"):
            vert = b.perpendicular_bisector("vert", f["D0"], f["D1"])
        cover = draw_card(b, cards[0], prefix="card.", head=f["D0"], crank=f["D1"], axis=axis,
                          de="der Deckelseite", en="of the cover side")
        if cards[1] is not None:
            crank = draw_card(b, cards[1], prefix="crank.", head=f["D0"], crank=f["D1"], axis=axis,
                              de="der Kurbelseite", en="of the crank side")
        else:  # Baumann's assumption: the crank side's card is the cover side's, seen from the other dead centre
            crank = draw_card(b, cards[0], prefix="crank.", given_prefix="card.", head=f["D1"], crank=f["D0"],
                              axis=axis, mirrored=True, up=(f["D0"], f["D1"]),
                              de="der Kurbelseite (die der Deckelseite gespiegelt)",
                              en="of the crank side (the cover side's mirrored)")
        scale = b.erect_perpendicular("v.crank", f["D1"], axis, O)
        return_heights: dict[int, tuple[str, str]] = {}
        if own_low:
            lp_scale = ("pressure_unit", "area_ratio")
            lp_cover = draw_card(b, low_cards[0], prefix="lp.card.", head=f["D0"], crank=f["D1"], axis=axis,
                                 pressure_scale=lp_scale, de="der Niederdruck-Deckelseite (Druckmaßstab mal F_nd/F_hd)",
                                 en="of the low-pressure cover side (pressure scale times F_lp/F_hp)")
            if low_cards[1] is not None:
                lp_crank = draw_card(b, low_cards[1], prefix="lp.crank.", head=f["D0"], crank=f["D1"], axis=axis,
                                     pressure_scale=lp_scale, de="der Niederdruck-Kurbelseite",
                                     en="of the low-pressure crank side")
            else:
                lp_crank = draw_card(b, low_cards[0], prefix="lp.crank.", given_prefix="lp.card.", head=f["D1"],
                                     crank=f["D0"], axis=axis, mirrored=True, up=(f["D0"], f["D1"]),
                                     pressure_scale=lp_scale,
                                     de="der Niederdruck-Kurbelseite (die der Deckelseite gespiegelt)",
                                     en="of the low-pressure crank side (the cover side's mirrored)")
    else:
        with b.group("perpendicular to the stroke through O", "Senkrechte zum Hub durch O"):
            vert = b.perpendicular_bisector("vert", f["D0"], f["D1"])
        with b.group("unit force: the crank radius on the vertical through B", "Einheitskraft: r auf der Senkrechten in B"):
            scale = b.erect_perpendicular("v.crank", f["D1"], axis, O)
            k = b.circle_radius("M.k", f["D1"], f["r"], de="r in B aufgetragen", en="r laid off at B")
            unit_mark = b.intersect("M", scale, k, rule=("toward", O, None, 0.0, 1.0),
                                    de="Marke der Einheitskraft P′ = r", en="mark of the unit force P' = r")
            unit_ray = b.line("ray", O, unit_mark, de="Strahl O–M (Proportionswinkel)", en="ray O-M (proportional angle)")
    heights: dict[int, tuple[str, str]] = {}
    low_heights: dict[int, tuple[str, str]] = {}
    low_return: dict[int, tuple[str, str]] = {}
    with b.group(f"tangential pressure at all {n + 1} crank positions", f"Tangentialdruck an allen {n + 1} Kurbelstellungen"):
        for k in range(1, n):
            P = points[k]
            with b.group(f"crank position {k}", f"Kurbelstellung {k}"):
                rl = b.line(f"rl{k}", f"C{k}", P, de=f"Schubstange C{k}–{k} verlängert", en=f"rod line C{k}-{k} extended")
                K = b.intersect(f"K{k}", rl, vert, rule=("only",), role="result", labels={f"K{k}": f"K{k}"},
                                de=f"K{k} auf der Senkrechten durch O: T = P′·OK/r",
                                en=f"K{k} on the perpendicular through O: T = P'·OK/r")
                kH = b.circle_through(f"H{k}.k", O, K, de="OK auf die Hubachse geschlagen", en="OK swung onto the stroke line")
                H = b.intersect(f"H{k}", axis, kH, rule=("toward", f["D0"], f["D1"]), de="H: OH = OK", en="H: OH = OK")
                h = b.erect_perpendicular(f"h{k}", H, axis, O)
                if force == "baumann":
                    marks = _free_force_mark(b, f, ctx, d, scale, k, P, n, d_return)
                    ray = b.line(f"ray{k}", O, marks[0], de=f"Strahl O–M{k}", en=f"ray O-M{k}")
                    if engine:
                        return_heights[k] = _return_height(b, O, marks[1], h, k)
                    if own_low:
                        lm = _free_force_mark(b, f, ctx_lp, d_lp, scale, k, P, n, d_lp_return, prefix="lp.",
                                              ordinate=f"o{k}")
                        low_heights[k] = _low_height(b, O, lm[0], h, k)
                        low_return[k] = _return_height(b, O, lm[1], h, k, prefix="lp.")
                elif force == "indicator":
                    marks = _card_marks(b, f, cover, crank, scale, k, bool(engine))
                    ray = b.line(f"ray{k}", O, marks[0], de=f"Strahl O–M{k}", en=f"ray O-M{k}")
                    if engine:
                        return_heights[k] = _return_height(b, O, marks[1], h, k)
                    if own_low:
                        lm = _card_marks(b, f, lp_cover, lp_crank, scale, k, True, prefix="lp.", ordinate=f"o{k}")
                        low_heights[k] = _low_height(b, O, lm[0], h, k)
                        low_return[k] = _return_height(b, O, lm[1], h, k, prefix="lp.")
                else:
                    ray = unit_ray
                Q = b.intersect(f"Q{k}", ray, h, rule=("only",), de=f"Q{k}: P′·OK/r (Strahlensatz)",
                                en=f"Q{k}: P'·OK/r (intercept theorem)")
                heights[k] = (H, Q)
    if engine:
        build_revolution(b, f, points, n, heights, engine["shifts"], engine["cylinders"],
                         return_heights if force != "unit" else None,
                         low=(low_heights, low_return) if own_low else None, machine=machine)
    else:
        _unrolled(b, f, points, n, heights)
    proto = b.protocol()
    return Figure(proto, proto.replay(givens))


def _card_marks(b: Builder, f: Mapping[str, str], cover: Any, crank: Any, scale: str, k: int,
                both: bool, prefix: str = "", ordinate: str | None = None) -> tuple[str, str | None]:
    """The over-pressure at crank position k read on the cards' straightedge lines, marked over B (up = along
    the motion): forward the cover side's line less the crank side's; with *both*, also the return stroke's."""
    X = f"X{k}"
    p = prefix
    low = " (Niederdruck)" if p else ""
    with b.group(f"over-pressure at {k} from the indicator cards" + (" (low pressure)" if p else ""),
                 f"Überdruck bei {k} aus den Indikatordiagrammen{low}"):
        o = ordinate or b.erect_perpendicular(f"o{k}", X, f["axis"], f["O"])
        up = ("toward", None, None, 0.0, 1.0)
        out: list[str | None] = []
        for tag, work, against, de, en in (("", cover.forward, crank.forward, "Hingang", "forward stroke"),
                                            ("r", crank.back, cover.back, "Rückgang", "return stroke")):
            if tag and not both:
                out.append(None)
                continue
            E = b.intersect(f"{p}{tag}E{k}", o, work, rule=up, de=f"Druck der arbeitenden Seite ({de})",
                            en=f"pressure of the working side ({en})")
            R = b.intersect(f"{p}{tag}R{k}", o, against, rule=up, de=f"Druck der anderen Seite ({de})",
                            en=f"pressure of the other side ({en})")
            kM = b.circle_segment(f"{p}{tag}M{k}.k", f["D1"], R, E, de="Überdruck auf die Senkrechte in B getragen",
                                  en="over-pressure carried to the vertical through B")
            out.append(b.intersect(f"{p}{tag}M{k}", scale, kM, rule=("toward", R, E),
                                   de=f"{tag}M{k}: Überdruck über B (oben: in der Bewegungsrichtung)",
                                   en=f"{tag}M{k}: over-pressure above B (up: along the motion)"))
        return out[0], out[1]


def _low_height(b: Builder, O: str, mark: str, h: str, k: int) -> tuple[str, str]:
    """The low-pressure cylinder's P'·OK/r at crank position k (its P' already in the first piston's force unit)."""
    ray = b.line(f"lp.ray{k}", O, mark, de=f"Strahl O–M{k} (Niederdruck)", en=f"ray O-M{k} (low pressure)")
    Q = b.intersect(f"lp.Q{k}", ray, h, rule=("only",), de=f"Q{k}: P′·OK/r (Niederdruck)",
                    en=f"Q{k}: P'·OK/r (low pressure)")
    return f"H{k}", Q


def _return_height(b: Builder, O: str, mark: str, h: str, k: int, prefix: str = "") -> tuple[str, str]:
    """The return stroke's P'·OK/r at the mirrored crank point of k: the ray O–M′k meets the same ordinate h_k
    (the rod line of the mirrored point meets the perpendicular through O at K's mirror image: OK is the same)."""
    rray = b.line(f"{prefix}rray{k}", O, mark, de=f"Strahl O–M′{k} (Rückgang)", en=f"ray O-M'{k} (return stroke)")
    rQ = b.intersect(f"{prefix}rQ{k}", rray, h, rule=("only",), de=f"rQ{k}: P′·OK/r im Rückgang",
                     en=f"rQ{k}: P'·OK/r on the return stroke")
    return f"H{k}", rQ


def _free_force_mark(b: Builder, f: Mapping[str, str], ctx: Any, d: Any, scale: str, k: int, P: str, n: int,
                     d_return: Any = None, prefix: str = "", ordinate: str | None = None) -> tuple[str, str | None]:
    """P' at crank position k: over-pressure (indicator) less the acceleration force, marked on the r-scale line.

    With *d_return* (the crank side's diagram, drawn from the other dead centre below the stroke line) also
    the return stroke's P' at the mirrored crank point 360° − ω_k: the piston stands where it stood at k and
    its acceleration is the same, so the mass force along the (reversed) motion changes sign -- (298) with the
    minus sign.  Drawn, the crank side's pressures point down, and "less B along the motion" is the same
    drawn shift as on the forward stroke: the same compass step from its steam point.  Returns (M_k, M′_k).
    """
    X = f"X{k}"
    p = prefix
    low = (" (low pressure)", " (Niederdruck)") if p else ("", "")
    with b.group(f"free piston force at {k}{low[0]}", f"freie Kolbenkraft bei {k}{low[1]}"):
        o = ordinate or b.erect_perpendicular(f"o{k}", X, f["axis"], f["O"])
        pts = pressures_at(b, d, o, str(k), envelope=True)
        E, R = pts["steam"], pts["back"]
        dc_p = ctx.D0 if 2 * k <= n else ctx.D1
        dc_2 = ctx.D0 if (4 * k < n or 4 * k > 3 * n) else ctx.D1
        V = ordinate_value(b, ctx, f"ND{k}" if p else f"b{k}", P, point_kind(k, n), dc_p, dc_2)
        kF = b.circle_segment(f"{p}F{k}.k", E, ctx.gf.origin, V, de="Beschleunigungsdruck von der Dampflinie abgezogen",
                              en="acceleration force taken off the steam line")
        F = b.intersect(f"{p}F{k}", o, kF, rule=("left", ctx.gf.origin, V), role="result",
                        de=f"F{k}: Rückdruck–F{k} = P′ (freie Kolbenkraft)", en=f"F{k}: back line to F{k} = P' (free force)")
        kM = b.circle_segment(f"{p}M{k}.k", f["D1"], R, F, de="P′ auf die Senkrechte in B getragen",
                              en="P' carried to the vertical through B")
        M = b.intersect(f"{p}M{k}", scale, kM, rule=("toward", R, F), de=f"M{k}: P′ über B (oben positiv)",
                        en=f"M{k}: P' above B (up = positive)")
        if d_return is None:
            return M, None
    with b.group(f"free piston force on the return stroke at {k}{low[0]}", f"freie Kolbenkraft im Rückgang bei {k}{low[1]}"):
        pts = pressures_at(b, d_return, o, f"r{k}", envelope=True)
        E, R = pts["steam"], pts["back"]
        kF = b.circle_segment(f"{p}rF{k}.k", E, ctx.gf.origin, V,
                              de="Beschleunigungsdruck mit umgekehrtem Vorzeichen an der Dampflinie der Kurbelseite",
                              en="acceleration force, its sign reversed, at the crank side's steam line")
        F = b.intersect(f"{p}rF{k}", o, kF, rule=("left", ctx.gf.origin, V), role="result",
                        de=f"rF{k}: Rückdruck–rF{k} = P′ im Rückgang", en=f"rF{k}: back line to rF{k} = P' (return)")
        kM = b.circle_segment(f"{p}rM{k}.k", f["D1"], R, F, de="P′ des Rückgangs auf die Senkrechte in B getragen",
                              en="the return stroke's P' carried to the vertical through B")
        # the crank side's diagram stands below the stroke line: along the return motion is R -> F pointing down
        rM = b.intersect(f"{p}rM{k}", scale, kM, rule=("toward", F, R), de=f"rM{k}: P′ des Rückgangs über B (oben positiv)",
                         en=f"rM{k}: the return stroke's P' above B (up = positive)")
        return M, rM


def _unrolled(b: Builder, f: Mapping[str, str], points: list[str], n: int, heights: Mapping[int, tuple[str, str]]) -> None:
    r = b.givens["r"]
    shortfall = chord_shortfall(n, r)
    with b.group("the crank circle unrolled with the dividers", "Der Kurbelkreis mit dem Stechzirkel abgewickelt"):
        U0, base, marks, ords, prov = unroll_by_chords(
            b, f["D0"], points[1], n,
            _approx(f"dividers stepping the chord 2r·sin(π/2n) n times (n = {n}): the unrolled length falls "
                    f"short of πr by r(π − 2n·sin(π/2n))", shortfall),
            ("Anfang der Abwicklung", "start of the unrolled circle"), lambda k: str(k) if k in (n // 2, n) else None)
    with b.group("tangential pressures carried to the unrolled circle", "Tangentialdrücke auf die Abwicklung getragen"):
        curve_pts = [U0]
        for k in range(1, n):
            H, Q = heights[k]
            kT = b.circle_segment(f"T{k}.k", marks[k], H, Q, de=f"T{k} mit dem Zirkel übertragen",
                                  en=f"T{k} carried with the compass")
            curve_pts.append(b.intersect(f"T{k}", ords[k], kT, rule=("toward", H, Q), role="result",
                                         de=f"Tangentialdruck T{k}", en=f"tangential pressure T{k}"))
        curve_pts.append(marks[n])
    with b.group("curve, mean line and excess area", "Tangentialdrucklinie, Ausgleichende und Überschussfläche"):
        b.french_curve("tcurve", base, curve_pts, {}, de="Tangentialdrucklinie mit dem Curvenlineal",
                       en="tangential-pressure line with the French curve")
        plan = _approx("planimeter: area under the drawn curve over the drawn base, divided by the base length "
                       "(traced along 64 chords per curve segment)", 1e-6)
        b.area_between("under", "tcurve", base, U0, marks[n], role="auxiliary",
                       de="Fläche unter der Tangentialdrucklinie", en="area under the tangential-pressure line")
        try:
            b.record("planimeter", "planimeter_height", ("under", U0, marks[n]), ("hm",), {},
                     "Planimeter: mittlere Höhe = Fläche / Länge", "planimeter: mean height = area / length",
                     provenance=plan.combine(prov))
        except GeometryError as exc:
            # The step names itself; the user changed givens, so say which ones make the work negative.
            g = b.givens
            if "admission" not in g:  # the unit force: its work is r·2 > 0 always, so this is no user's doing
                raise
            raise InvalidParameter(
                f"with admission {g['admission']:g} at, filling {g['filling']:g} and back pressure "
                f"{g['back_pressure']:g} at the tangential pressures do negative work over the stroke (the "
                f"indicator diagram encloses negative work; the inertia forces do none over a stroke), so there is no mean line to draw: "
                f"raise --admission or --filling, or lower --back-pressure ({exc})") from None
        up = ("toward", None, None, 0.0, 1.0)
        for end, mark, ordinate in (("M0", U0, ords[0]), ("Mn", marks[n], ords[n])):
            k = b.circle_radius(f"{end}.k", mark, "hm", de="mittlere Höhe mit dem Zirkel angetragen",
                                en="mean height set off with the compass")
            b.intersect(end, ordinate, k, rule=up, de=f"{end}: mittlere Höhe über der Grundlinie",
                        en=f"{end}: mean height above the base", provenance=plan.combine(prov))
        b.line("mean", "M0", "Mn", role="result", de="Ausgleichende MM (Höhe 2Pᵢ/π)", en="mean line MM (height 2P_i/pi)")
        eye = _approx("crossings of the mean line with the drawn curve, read off the drawing", 1e-6)
        for name, rule, label in (("A1", ("toward", None, None, -1.0, 0.0), "α₁"),
                                  ("A2", ("toward", None, None, 1.0, 0.0), "α₂")):
            b.record("intersect", "intersect", ("tcurve", "mean"), (name,), {"rule": rule, "both": False},
                     f"{label}: die Ausgleichende schneidet die Tangentialdrucklinie ({'erster' if name == 'A1' else 'letzter'} Schnitt)",
                     f"{label}: where the mean line crosses the curve ({'first' if name == 'A1' else 'last'} crossing)",
                     provenance=eye.combine(plan).combine(prov), role="result", labels={name: label})
        b.area_between("excess", "tcurve", "mean", "A1", "A2", hatch_deg=90.0, role="result",
                       de="Überschussfläche zwischen α₁ und α₂ (schraffiert)",
                       en="excess area between α₁ and α₂ (hatched)")


def tangential_plate(fig: Figure) -> dict:
    """Baumann's Fig. 26 as a plate: the diagram ABCD heavy (A the start, B the top at the cut-off,
    D the end), the Ausgleichende MM lettered at both ends, and α₁, α₂ as he gives them -- abscissae,
    lettered at the foot of thin ordinates below the base line, so that no letter sits on the crossings
    or on the ends of the hatching.

    Every position is a constructed point.
    """
    R = fig.replay
    n = fig.params["parts"]
    if fig.params.get("revolution"):  # a revolution's diagrams are lettered by their own steps (each crank, the sum)
        return {"looks": {}, "furniture": _cylinder_letters(fig)}
    U0, Un, M0, Mn = R["U0"], R[f"U{n}"], R["M0"], R["Mn"]
    span = abs(Un[0] - U0[0])
    d = 0.018 * span
    top = max(range(1, n), key=lambda k: R[f"T{k}"][1])
    T = R[f"T{top}"]
    furniture: list[dict] = [
        {"kind": "lettering", "at": (U0[0] - 0.9 * d, U0[1] + 1.2 * d), "text": "A"},
        {"kind": "lettering", "at": (T[0], T[1] + 1.6 * d), "text": "B"},
        {"kind": "lettering", "at": (Un[0] + 0.9 * d, Un[1] + 1.4 * d), "text": "D"},
        {"kind": "lettering", "at": (M0[0] - 1.2 * d, M0[1] + 1.0 * d), "text": "M"},
        {"kind": "lettering", "at": (Mn[0] + 1.2 * d, Mn[1] + 1.0 * d), "text": "M"},
    ]
    for name, text in (("A1", "α₁"), ("A2", "α₂")):
        P = R[name]
        furniture.append({"kind": "stroke", "a": (P[0], P[1]), "b": (P[0], U0[1] - 1.0 * d), "look": "dashed thin"})
        furniture.append({"kind": "lettering", "at": (P[0], U0[1] - 2.2 * d), "text": text})
    looks = {"A1": "unlettered", "A2": "unlettered", "tcurve": "heavy", "mean": "medium", "tbase": "medium"}
    return {"looks": looks, "furniture": furniture}


def _cylinder_letters(fig: Figure) -> list[dict]:
    """HD and ND at a compound's (or tandem's) two cylinder curves, each where it stands clearest of the others."""
    if not fig.params.get("low_pressure"):
        return []
    R = fig.replay
    n = fig.params["parts"]
    m = 2 * n
    d = 0.018 * abs(R[f"U{m}"][0] - R["U0"][0])
    out = []
    for i, text in ((0, "HD"), (1, "ND")):
        best, spot = -1.0, None
        for j in range(2, m - 1):
            if f"c{i}.{j}" not in R or f"S{j}" not in R:
                continue
            x, y = R[f"c{i}.{j}"]
            others = [R[f"S{j}"][1], R[f"U{j}"][1], R["M0"][1]] + [R[f"c{o}.{j}"][1] for o in (0, 1)
                                                                    if o != i and f"c{o}.{j}" in R]
            clear = min(abs(y - v) for v in others)
            if clear > best:
                best, spot = clear, (x, y)
        if spot is not None:
            out.append({"kind": "lettering", "at": (spot[0], spot[1] - 1.4 * d), "text": text})
    return out


# --------------------------------------------------------------------------
# Measurements on the figure.
# --------------------------------------------------------------------------


def _up(fig: Figure, point: str, origin: str) -> float:
    """Signed height of *point* over *origin*, perpendicular to the stroke line (up positive)."""
    p, o = fig.replay[point], fig.replay[origin]
    return p[1] - o[1]


def ok_over_r(fig: Figure, k: int) -> float:
    """OK/r at crank position k, measured on the figure (0 at the dead centres)."""
    n = fig.params["parts"]
    if k in (0, n):
        return 0.0
    return _up(fig, f"K{k}", "O") / fig.replay.givens["r"]


def t_over_unit(fig: Figure, k: int) -> float:
    """The ordinate of T at k on the unrolled circle, over the force unit (r for a unit force, else 1 at)."""
    n = fig.params["parts"]
    g = fig.replay.givens
    unit = g["r"] if fig.params["force"] == "unit" else g["pressure_unit"]
    if k in (0, n):
        return 0.0
    return _up(fig, f"T{k}", f"U{k}") / unit


def free_force(fig: Figure, k: int, prefix: str = "") -> float:
    """P' at k in at (Baumann force), measured as the height of M_k over B (*prefix* ``lp.``: the low-pressure
    cylinder's, times F_lp/F_hp)."""
    return _up(fig, f"{prefix}M{k}", "D1") / fig.replay.givens["pressure_unit"]


def return_free_force(fig: Figure, k: int, prefix: str = "") -> float:
    """P' on the return stroke at the mirrored crank point of k, in at: the height of M′_k over B (*prefix*
    ``lp.``: the low-pressure cylinder's, times F_lp/F_hp)."""
    return _up(fig, f"{prefix}rM{k}", "D1") / fig.replay.givens["pressure_unit"]


def unrolled_angle(fig: Figure, point: str) -> float:
    """The crank angle of a point of the unrolled circle, read in proportion to the drawn length U0..Un."""
    n = fig.params["parts"]
    u0, un, p = fig.replay["U0"], fig.replay[f"U{n}"], fig.replay[point]
    return math.pi * (p[0] - u0[0]) / (un[0] - u0[0])


def mean_height(fig: Figure) -> float:
    """Height of the mean line over the base, in force units."""
    g = fig.replay.givens
    unit = g["r"] if fig.params["force"] == "unit" else g["pressure_unit"]
    return _up(fig, "M0", "U0") / unit


def crossing_angles(fig: Figure) -> tuple[float, float]:
    return unrolled_angle(fig, "A1"), unrolled_angle(fig, "A2")


def excess_area(fig: Figure) -> float:
    """The excess area as drawn, in force units times r (i.e. ∫(T − T_m) dα over (α1, α2) as drawn)."""
    g = fig.replay.givens
    unit = g["r"] if fig.params["force"] == "unit" else g["pressure_unit"]
    return fig.replay["excess"].signed_area() / (unit * g["r"])


# --------------------------------------------------------------------------
# The analytic model (for the checks).
# --------------------------------------------------------------------------


def _sin_beta(w: float, lam: float) -> float:
    return lam * math.sin(w)


def factor(w: float, lam: float) -> float:
    """sin(ω + β)/cos β: T/P' for the exact crank mechanism."""
    b = math.asin(_sin_beta(w, lam))
    return math.sin(w + b) / math.cos(b)


def piston_fraction(w: float, lam: float) -> float:
    """Exact piston path as a fraction of the stroke."""
    return 0.5 * (1.0 - math.cos(w) + (1.0 - math.sqrt(1.0 - (lam * math.sin(w)) ** 2)) / lam)


def model_force(w: float, g: Mapping[str, float], force: str) -> float:
    """P' at crank angle w: 1 (unit) or over-pressure less the acceleration force (at)."""
    if force == "unit":
        return 1.0
    lam = 1.0 / g["rod_ratio"]
    if force == "indicator":
        return float(card_force(g, lam)(w))
    x = piston_fraction(w, lam)
    return (model_steam_pressure(x, g) - model_back_pressure(x, g)
            - g["pressure_ratio"] * (math.cos(w) + lam * math.cos(2.0 * w)))


def baumann_force(g: Mapping[str, float], lam: float) -> Any:
    """P' (at) along the motion over the whole turn, Baumann's model on both strokes (arrays of crank angles).

    Forward: steam(x) − back(x) − c(cos ω + λ cos 2ω).  Return (his assumption: the crank side's diagram is
    the cover side's): the over-pressure at the distance 1 − x from the crank-end dead centre, and the mass
    force along the reversed motion, + c(cos ω + λ cos 2ω) -- eq. (298) with the minus sign, counted from
    the crank-end dead centre.  Written here from the formulas, not from the figure.

    >>> g = {"filling": 0.1, "clearance": 0.05, "admission": 7.85, "back_pressure": 0.15, "compression": 0.3,
    ...      "pressure_ratio": 0.0}
    >>> g["pressure_ratio"] = 0.9
    >>> long_rod = baumann_force(g, 1e-9)      # infinite rod: the return stroke repeats the forward one
    >>> bool(abs(long_rod(math.pi + 1.0) - long_rod(1.0)) < 1e-9)
    True
    >>> f = baumann_force(g, 0.2)              # L/r = 5: the rod's term changes sign with the stroke
    >>> round(float(f(math.pi + 1.0) - f(1.0)), 3) != 0.0
    True
    """
    s1, s0, P, P0, s3, c = (g["filling"], g["clearance"], g["admission"], g["back_pressure"], g["compression"],
                            g["pressure_ratio"])

    def over(x: Any) -> Any:
        steam = np.where(x <= s1, P + P0, (P + P0) * (s1 + s0) / (x + s0))
        back = np.where(x <= 1.0 - s3, P0, P0 * (s3 + s0) / (1.0 - x + s0))
        return steam - back

    def force(w: Any) -> Any:
        w = np.asarray(w, dtype=float)
        x = 0.5 * (1.0 - np.cos(w) + (1.0 - np.sqrt(1.0 - (lam * np.sin(w)) ** 2)) / lam)
        mass = c * (np.cos(w) + lam * np.cos(2.0 * w))
        return np.where(np.mod(w, 2.0 * math.pi) <= math.pi, over(x) - mass, over(1.0 - x) + mass)

    return force


def model_t(w: float, g: Mapping[str, float], force: str) -> float:
    return model_force(w, g, force) * factor(w, 1.0 / g["rod_ratio"])


def _kinks(g: Mapping[str, float], force: str) -> list[float]:
    """Crank angles where P' has a corner (cut-off, start of compression): integration breaks there."""
    if force == "unit":
        return []
    lam = 1.0 / g["rod_ratio"]
    out = []
    if force == "indicator":  # the cards' corners: every digitised point of the forward stroke's lines
        cover, crank = card_pair(g)
        corners = sorted({x for x in cover.forward[0] + crank.forward[0] if 0.0 < x < 1.0})
    else:
        corners = [g["filling"], 1.0 - g["compression"]]
    for x in corners:
        lo, hi = 0.0, math.pi
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if piston_fraction(mid, lam) < x else (lo, mid)
        out.append(0.5 * (lo + hi))
    return sorted(out)


#: Gauss-Legendre nodes and weights on [-1, 1] (order 20) and the pieces of each smooth stretch: the rule
#: integrates the model (smooth between its kinks) to rounding; the sweep's array path uses the same rule.
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(20)
_PIECES = 16


def _integrate(fn, a: float, b: float, breaks: list[float]) -> float:
    """Composite Gauss-Legendre on each smooth piece (the kinks are break points); *fn* takes an array of angles."""
    edges = [a] + [t for t in breaks if a < t < b] + [b]
    total = 0.0
    for lo, hi in zip(edges, edges[1:]):
        h = (hi - lo) / _PIECES
        xs = (lo + h * np.arange(_PIECES))[:, None] + (_NODES + 1.0) * h / 2.0
        total += float((fn(xs) * _WEIGHTS).sum() * h / 2.0)
    return total


def model_t_array(w: np.ndarray, g: Mapping[str, float], force: str) -> np.ndarray:
    """:func:`model_t` on an array of crank angles (the same formulas, with numpy)."""
    lam = 1.0 / g["rod_ratio"]
    beta = np.arcsin(lam * np.sin(w))
    factor_w = np.sin(w + beta) / np.cos(beta)
    if force == "unit":
        return factor_w
    if force == "indicator":
        return card_force(g, lam)(w) * factor_w
    x = 0.5 * (1.0 - np.cos(w) + (1.0 - np.sqrt(1.0 - (lam * np.sin(w)) ** 2)) / lam)
    s1, s0, P, P0, s3 = g["filling"], g["clearance"], g["admission"], g["back_pressure"], g["compression"]
    steam = np.where(x <= s1, P + P0, (P + P0) * (s1 + s0) / (x + s0))
    back = np.where(x <= 1.0 - s3, P0, P0 * (s3 + s0) / (1.0 - x + s0))
    force_w = steam - back - g["pressure_ratio"] * (np.cos(w) + lam * np.cos(2.0 * w))
    return force_w * factor_w


def model_summary(g: Mapping[str, float], force: str) -> dict[str, float]:
    """Mean height, crossings α1, α2 and excess ∫(T − T_m) dα of the exact model (not of the drawing)."""
    kinks = _kinks(g, force)
    t = lambda w: model_t(w, g, force)  # noqa: E731
    ts = lambda w: model_t_array(w, g, force)  # noqa: E731
    mean = _integrate(ts, 0.0, math.pi, kinks) / math.pi
    grid = np.linspace(0.0, math.pi, 3601)
    vals = (ts(grid) - mean).tolist()
    roots = []
    for i in range(len(grid) - 1):
        if vals[i] == 0.0 or vals[i] * vals[i + 1] < 0.0:
            lo, hi = float(grid[i]), float(grid[i + 1])
            for _ in range(80):
                mid = 0.5 * (lo + hi)
                if (t(lo) - mean) * (t(mid) - mean) <= 0.0:
                    hi = mid
                else:
                    lo = mid
            roots.append(0.5 * (lo + hi))
    a1, a2 = roots[0], roots[-1]
    excess = _integrate(lambda w: ts(w) - mean, a1, a2, kinks)
    return {"mean": mean, "alpha1": a1, "alpha2": a2, "excess": excess, "kinks": tuple(kinks)}


def model_summary_sweep(g: Mapping[str, Any], force: str) -> dict[str, Any]:
    """:func:`model_summary` for a sweep's givens (arrays) in one numpy pass: the same rules on 2-D arrays.

    Kinks by bisection, Gauss-Legendre on each smooth piece (a kink outside the range
    of an integral makes a piece of width 0), crossings of the mean line on
    the same 3,601-point grid, refined by the same bisection.  Element i
    equals model_summary of set i to rounding (the tests hold them equal).
    """
    sizes = {np.size(v) for v in g.values() if np.ndim(v)}
    n = max(sizes, default=1)
    col = {k: (np.broadcast_to(np.asarray(v, dtype=float), (n,)).reshape(n, 1) if np.ndim(v) else v)
           for k, v in g.items()}
    lam = 1.0 / col["rod_ratio"][:, 0] if np.ndim(col["rod_ratio"]) else np.full(n, 1.0 / col["rod_ratio"])
    ts = lambda w: model_t_array(w, col, force)  # noqa: E731  (w: one row of angles per set of givens)

    if force == "unit":
        kinks: list[Any] = []
    else:
        kinks = []
        for x in (np.broadcast_to(col["filling"], (n, 1))[:, 0], 1.0 - np.broadcast_to(col["compression"], (n, 1))[:, 0]):
            lo, hi = np.zeros(n), np.full(n, math.pi)
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                below = 0.5 * (1.0 - np.cos(mid) + (1.0 - np.sqrt(1.0 - (lam * np.sin(mid)) ** 2)) / lam) < x
                lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
            kinks.append(0.5 * (lo + hi))
        kinks = list(np.sort(np.stack(kinks), axis=0))

    def integrate(fn, a, b):  # _integrate, one row per set of givens
        a, b = np.broadcast_to(a, (n,)), np.broadcast_to(b, (n,))
        edges = [a] + [np.clip(t, a, b) for t in kinks] + [b]
        total = np.zeros(n)
        for lo, hi in zip(edges, edges[1:]):
            h = (hi - lo) / _PIECES
            xs = ((lo[:, None] + h[:, None] * np.arange(_PIECES))[:, :, None] + (_NODES + 1.0) * h[:, None, None] / 2.0)
            total += (fn(xs.reshape(n, -1)).reshape(xs.shape) * _WEIGHTS).sum(axis=(1, 2)) * h / 2.0
        return total

    mean = integrate(ts, 0.0, math.pi) / math.pi
    grid = np.linspace(0.0, math.pi, 3601)
    vals = ts(np.broadcast_to(grid, (n, grid.size))) - mean[:, None]
    crossing = (vals[:, :-1] == 0.0) | (vals[:, :-1] * vals[:, 1:] < 0.0)
    if not crossing.any(axis=1).all():
        raise ArithmeticError("the model's tangential pressure does not cross its mean line")
    roots = []
    for i in (crossing.argmax(axis=1), crossing.shape[1] - 1 - crossing[:, ::-1].argmax(axis=1)):
        lo, hi = grid[i], grid[i + 1]
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            left = (ts(lo[:, None])[:, 0] - mean) * (ts(mid[:, None])[:, 0] - mean) <= 0.0
            lo, hi = np.where(left, lo, mid), np.where(left, mid, hi)
        roots.append(0.5 * (lo + hi))
    a1, a2 = roots
    excess = integrate(lambda w: ts(w) - mean[:, None], a1, a2)
    return {"mean": mean, "alpha1": a1, "alpha2": a2, "excess": excess, "kinks": tuple(kinks)}


# --------------------------------------------------------------------------
# Checks.
# --------------------------------------------------------------------------


def drawn_model(g: Mapping[str, float], force: str, n: int) -> dict[str, float]:
    """The method on exact data: the French curve through the model's n + 1 exact points, read as the figure is.

    Its distance from :func:`model_summary` is the error of drawing the curve
    through n + 1 points (the corner at the cut-off among it); the checks allow
    twice that.  Abscissae are π k/n here: the chord scale of the figure only
    stretches it uniformly (angles and mean height do not change; areas scale).
    """
    from ..kernel.areas import area_between
    from ..kernel.curves import crossings
    from ..kernel.geometry import SCALAR, Line, Point
    from ..kernel.ops import OPS

    pts = [Point(math.pi * k / n, model_t(math.pi * k / n, g, force)) for k in range(n + 1)]
    base = Line(Point(0.0, 0.0), Point(math.pi, 0.0))
    curve, = OPS["french_curve"].fn((base, *pts), {"points": n + 1, "tangent_at": ()}, {}, (), SCALAR)
    mean_height = area_between(curve, base, 0.0, math.pi).signed_area() / math.pi
    found = crossings(curve, Line(Point(0.0, mean_height), Point(math.pi, mean_height)))
    a1, a2 = found[0], found[-1]
    mean = Line(Point(0.0, mean_height), Point(math.pi, mean_height))
    excess = area_between(curve, mean, a1.x, a2.x).signed_area()
    return {"mean": mean_height, "alpha1": a1.x, "alpha2": a2.x, "excess": excess}


def tangential_checks(fig: Figure, model: Mapping[str, float] | None = None) -> list[Check]:
    """The checks of a tangential-pressure figure; *model*: :func:`model_summary` of its givens, if known."""
    g = fig.replay.givens
    n = fig.params["parts"]
    force = fig.params["force"]
    lam = 1.0 / g["rod_ratio"]
    made_by = fig.replay.made_by()
    checks: list[Check] = []
    if force == "unit":
        scale = 1.0
    elif force == "indicator":
        scale = max(1.0, max(p for c in card_pair(g) for p in c.forward[1] + c.back[1]))
    else:
        scale = max(1.0, g["admission"] + g["back_pressure"])
    for k in range(1, n):
        w = crank_angle(fig, point_name(fig, k))  # the angle the point really has: the division's error drops out
        checks.append(Check(f"OK/r at {k}", ok_over_r(fig, k), factor(w, lam), EUCLIDEAN_TOLERANCE,
                            "rod line and perpendicular through O: straightedge steps", "r"))
        if force in ("baumann", "indicator"):
            tol = 10 * EUCLIDEAN_TOLERANCE * scale / g["pressure_unit"]
            why = ("the cards' straightedge lines met by the ordinate, compass" if force == "indicator" else
                   "hyperbola rays, inertia ordinate and compass")
            checks.append(Check(f"P' at {k}", free_force(fig, k), model_force(w, g, force), tol,
                                f"{why}: Euclidean, read in at", "at"))
            if not fig.params.get("revolution"):  # over a revolution the ordinates are checked as the sum's
                checks.append(Check(f"T at {k}", t_over_unit(fig, k), model_t(w, g, force), 2 * tol,
                                    "P'·OK/r by the intercept theorem: Euclidean, read in at", "at"))
        elif not fig.params.get("revolution"):  # over a revolution the ordinates are checked as the sum's
            checks.append(Check(f"T/P at {k}", t_over_unit(fig, k), factor(w, lam), EUCLIDEAN_TOLERANCE,
                                "proportional angle with P' = r: Euclidean", "P"))
    if fig.params.get("revolution"):
        if force == "unit":
            return checks + revolution_checks(fig)
        whole = card_force(g, lam) if force == "indicator" else baumann_force(g, lam)
        low = low_force(g, force, lam)
        if low is not None:  # the low-pressure cylinder's pressures, drawn times F_lp/F_hp
            lp_cards = card_pair(g, "lp.") if force == "indicator" else ()
            lp_top = max([p for c in lp_cards for p in c.forward[1] + c.back[1]]
                         or [g.get("lp.admission", 0.0) + g.get("lp.back_pressure", 0.0)])
            scale = max(scale, lp_top * g["area_ratio"])
        tol = 10 * EUCLIDEAN_TOLERANCE * scale / g["pressure_unit"]
        sides = [("", whole)] + ([("lp.", low)] if low is not None else [])
        for k in range(1, n):  # the return stroke's P' at the mirrored crank point 360° − ω_k
            w = crank_angle(fig, point_name(fig, k))
            for p, fn in sides:
                what = " (low pressure, times F_lp/F_hp)" if p else ""
                if p:
                    checks.append(Check(f"P' at {k}{what}", free_force(fig, k, p), float(fn(w)), tol,
                                        "the low-pressure lines met by the ordinate, compass: Euclidean, read in at",
                                        "at"))
                checks.append(Check(f"P' on the return stroke at {2 * n - k}{what}", return_free_force(fig, k, p),
                                    float(fn(2.0 * math.pi - w)), tol, "the crank side's lines met by the ordinate, "
                                    "compass: Euclidean, read in at", "at"))
        engine = None
        if low is not None:
            layout = engine_cylinders(fig.params["shifts"], fig.params["cylinders"], fig.params["machine"], True)
            by_shift = dict(zip(fig.params["shifts"], fig.params["offsets"]))
            engine = [(by_shift[sh], low if which else whole) for sh, which in layout]
        return checks + revolution_checks(fig, whole, scale / g["pressure_unit"], engine=engine)
    r = g["r"]
    prov = made_by[f"U{n}"].provenance
    length = fig.replay["U0"].distance(fig.replay[f"U{n}"])
    chord = fig.replay["D0"].distance(fig.replay[point_name(fig, 1)])
    tol_w, why_w = angle_tolerance(fig, point_name(fig, 1), made_by)
    # The dividers' shortfall π − 2n·sin(π/2n) is at most π³/(24n²) (sin x >= x − x³/6): half as much again is
    # the tolerance, a bound the method gives before anything is measured.
    checks.append(Check("unrolled length", length / r, math.pi, 1.5 * math.pi ** 3 / (24.0 * n * n) + n * tol_w,
                        f"{prov.method}; the shortfall is at most π³/(24n²) = {math.pi ** 3 / (24.0 * n * n):.3e} r, "
                        f"tolerance 1.5 times that; division error {why_w}", "r"))
    checks.append(Check("unrolled length (dividers)", length / r, n * chord / r, 10 * EUCLIDEAN_TOLERANCE,
                        "n equal steps of the chord as drawn: Euclidean once the opening is set", "r"))
    model = model_summary(g, force) if model is None else model
    drawn = drawn_model(g, force, n)
    unit = "P" if force == "unit" else "at"
    why = "the French curve through n + 1 points (twice its error on exact data) and the planimeter (1e-6)"
    tol_h = 2.0 * abs(drawn["mean"] - model["mean"]) + 1e-6 * scale
    checks.append(Check("mean height (planimeter)", mean_height(fig), model["mean"], tol_h, why, unit))
    a1, a2 = crossing_angles(fig)
    for name, measured in (("alpha1", a1), ("alpha2", a2)):
        tol = 2.0 * abs(drawn[name] - model[name]) + 1e-5
        checks.append(Check(name, measured, model[name], tol, why + "; read off the unrolled scale", "rad"))
    # The chord-stepped abscissae scale every area by n·chord/(πr).
    chord_factor = 2 * n * math.sin(math.pi / (2 * n)) / math.pi
    tol_e = 2.0 * abs(drawn["excess"] - model["excess"]) + abs(model["excess"]) * (1.0 - chord_factor) + 1e-5 * scale
    checks.append(Check("excess area", excess_area(fig), model["excess"], tol_e,
                        why + "; unrolled by chords: area scaled by n·chord/πr", f"{unit}·r"))
    return checks


def tangential_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as Baumann writes them: κ = P/Bmax, the rod, the diagram (or a digitised card), the scale and
    the division; over a revolution the machine, its cranks and the low-pressure cylinder."""
    g = fig.replay.givens
    if fig.params.get("force") == "unit":
        return [x for x in [ratio("r/L", g["rod_ratio"], lang), "P′ = r", *revolution(fig, lang), division(fig, lang),
                            *card(fig, lang)] if x]
    # κ = P/B_max (Baumann): the construction keeps c v²/r = P/((1 + r/L) κ) as its given.
    if "admission" not in g:  # a digitised card's force
        return [x for x in [ratio("r/L", g["rod_ratio"], lang), *revolution(fig, lang), division(fig, lang),
                            *card(fig, lang), *low_pressure(fig, lang)] if x]
    kappa = g["admission"] / (g["pressure_ratio"] * (1.0 + 1.0 / g["rod_ratio"]))
    out = ([f"κ = P/Bmax = {number(round(kappa, 9), lang)}", ratio("r/L", g["rod_ratio"], lang)]
           + diagram(g, lang) + [scale(g, lang), division(fig, lang)])
    if "lp.admission" in g:  # two cylinders, two diagrams: say whose the first givens are
        out[2] = ("Hochdruck: " if lang == "de" else "high pressure: ") + out[2]
    if fig.params.get("revolution"):  # the return stroke from the same diagram: Baumann's assumption, said
        out = [x for x in revolution(fig, lang) if x] + out + [
            "Rückgang: dasselbe Diagramm gespiegelt (Baumanns Annahme)" if lang == "de"
            else "return stroke: the same diagram mirrored (Baumann's assumption)"]
        out += low_pressure(fig, lang)
    return out


TANGENTIAL = register(Construction(
    name="tangential-pressure",
    title=Caption("Tangentialdruckdiagramm mit Ausgleichender und Überschussfläche",
                  "Tangential-pressure diagram with mean line and excess area"),
    source="seed 004 (Baumann 1902), Fig. 26/27",
    build=build_tangential,
    checks=tangential_checks,
    sweep_model=lambda g, params: model_summary_sweep(g, params["force"]),
    defaults={"rod_ratio": 5.0, "parts": 18, "method": "auto", "r": 1.0, "force": "baumann", "kappa": KAPPA,
              **BAUMANN, "pressure_unit": 0.2, "revolution": False, "cranks": "", "machine": "single",
              "indicator": "", "indicator_crank_side": "", "indicator_lp": "", "indicator_lp_crank_side": "",
              **LOW_PRESSURE},
    book_params=({"rod_ratio": 5.0, "parts": 18, "kappa": 8.0}, {"rod_ratio": 5.0, "parts": 18, "kappa": 2.0},
                 # a compound engine, cranks at 90 degrees, each cylinder with its own diagram (Baumann's for the
                 # high-pressure one, the low-pressure one's own, its piston 2.5 times as large): the summed
                 # diagram over a revolution and its excess areas
                 {"rod_ratio": 5.0, "parts": 18, "revolution": True, "machine": "compound"}),
    structural=("parts", "method", "force", "filling", "compression", "revolution", "cranks", "machine", "indicator",
                "indicator_crank_side", "indicator_lp", "indicator_lp_crank_side", "lp_filling", "lp_compression"),
    cites=(Cite(BAUMANN_1902, "Fig. 26/27"),),
    wording=tangential_wording,
    methods=DIVISION_NAMES,
    plate=tangential_plate,
    validator=_validate,
    help={
        "cranks": "tangential-pressure --revolution: crank offsets in degrees ahead of the first, e.g. 0,90 "
                  "(multiples of 180/parts; default: the machine's)",
        "machine": "tangential-pressure --revolution: single (default; cranks as --cranks says), tandem (two "
                   "cylinders on one rod, forces added before the crank), compound (cranks at 0,90)",
        "indicator": "tangential-pressure: a digitised indicator diagram of the cover side, CSV x,p (the loop in "
                     "drawing order; x from the head-end dead centre in strokes, p absolute in at)",
        "indicator_crank_side": "tangential-pressure: the crank side's diagram (default: the cover side's mirrored, "
                                "Baumann's assumption)",
        "indicator_lp": "tangential-pressure --revolution --machine compound|tandem: the low-pressure cylinder's "
                        "own cover-side diagram, CSV x,p as --indicator (default: every cylinder has --indicator's)",
        "indicator_lp_crank_side": "tangential-pressure: the low-pressure crank side's diagram (default: the "
                                   "low-pressure cover side's mirrored)",
        "area_ratio": "tangential-pressure, compound/tandem with diagrams of their own: low-pressure piston area "
                      "over the high-pressure one's, 0.1 .. 20 (default 2.5)",
        "lp_filling": "tangential-pressure --force baumann, compound/tandem: the low-pressure cylinder's filling "
                      "s1/s, 0.001 .. 1 (default 0.35, illustrative: the seeds print no compound's diagrams)",
        "lp_admission": "the low-pressure cylinder's admission pressure in at over its back pressure, 0.001 .. 1000 "
                        "(default 1.6, illustrative)",
        "lp_back_pressure": "the low-pressure cylinder's back pressure in at absolute, 0.001 .. 1000 (default 0.15)",
        "lp_compression": "the low-pressure cylinder's compression s3/s, 0.001 .. 1 (default 0.30)",
        "lp_kappa": "the low-pressure cylinder's kappa = P/B_max, 0.1 .. 10000 (default 8)",
    },
))
