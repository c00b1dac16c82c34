"""Building the tangential-pressure figure: its givens (Baumann's κ and diagram, a digitised card, the
low-pressure cylinder), the crank frame, P'·OK/r at every crank position by the intercept theorem, the
unrolled crank circle with the ordinates, the curve, the mean line and the excess area; over a revolution the
return stroke and the other cylinders."""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any, Mapping

from ...kernel.errors import GeometryError, InvalidParameter, did_you_mean
from ...kernel.division import check_parts, divide_semicircle
from ...kernel.instruments import Builder
from ...kernel.letters import lowered
from ...kernel.proportional import scale_line
from ...kernel.protocol import Provenance
from .. import Figure, bounded, positive, rod_ratio_param
from ..domain import AREA_RATIO, DRAWN_LENGTH, KAPPA_RANGE
from ..crank import build_frame, rod_arcs
from ..indicator_parts import BAUMANN, indicator_frame, indicator_givens, pressures_at
from ..ordinates import inertia_setup, ordinate_value, point_kind
from ..indicator_card import card_givens, card_pair, draw_card, load_indicator
from ..revolution import MACHINES, REVOLUTION_PLATE, build_revolution, crank_shifts, parse_cranks, unroll_by_chords
from .plate import PLATE

__all__ = ["KAPPA", "FORCES", "LOW_PRESSURE", "validate_tangential", "chord_shortfall", "build_tangential",
           "derived_givens"]


#: Baumann's κ = P/B_max ("Verhältnis des Anfangsbeschleunigungsdrucks zum Anfangskolbendruck"), his first case.
KAPPA = 8.0


FORCES = ("baumann", "unit", "indicator")


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
    # kappa = P/B_max is a given of the protocol; c v^2/r follows from it (derived_givens)
    g.update(d, kappa=bounded("kappa = P/B_max", kappa, KAPPA_RANGE))
    return derived_givens(g)


def derived_givens(g: Mapping[str, Any]) -> dict[str, Any]:
    """The givens that follow from kappa = P/B_max and the rod: c v^2/r (at), the inertia ordinate's factor, so that
    B_max = (1 + r/L) c v^2/r = P/kappa (the low-pressure cylinder's likewise).  Givens that are arrays (a sweep's)
    give arrays; a protocol written before kappa was a given keeps its c v^2/r.

    >>> round(derived_givens({"rod_ratio": 5.0, "admission": 7.85, "kappa": 8.0})["pressure_ratio"], 9)
    0.817708333
    """
    out = dict(g)
    if "kappa" in out and "admission" in out:
        out["pressure_ratio"] = out["admission"] / (out["kappa"] * (1.0 + 1.0 / out["rod_ratio"]))
    if "lp.kappa" in out and "lp.admission" in out:
        out["lp.pressure_ratio"] = out["lp.admission"] / (out["lp.kappa"] * (1.0 + 1.0 / out["rod_ratio"]))
    return out


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
    out.update({f"lp.{key}": d[key] for key in ("filling", "clearance", "admission", "back_pressure", "compression")})
    out["lp.kappa"] = bounded("low-pressure kappa = P/B_max", low["lp_kappa"], KAPPA_RANGE)
    return derived_givens({**g, **out})


def validate_tangential(givens: Mapping[str, float]) -> None:
    bounded("crank radius r", givens["r"], DRAWN_LENGTH)
    rod_ratio_param(givens["rod_ratio"])
    if "card.x0" in givens:  # a digitised card: checked as a file is
        bounded("pressure-scale unit (drawn length of 1 at)", givens["pressure_unit"], DRAWN_LENGTH)
        card_pair(givens)
    if "admission" in givens:
        indicator_givens(givens["filling"], givens["clearance"], givens["admission"], givens["back_pressure"],
                         givens["compression"], givens["pressure_unit"])
        positive("c v^2/r (pressure_ratio)", givens["pressure_ratio"])
    if "kappa" in givens:
        bounded("kappa = P/B_max", givens["kappa"], KAPPA_RANGE)
    if "lp.kappa" in givens:
        bounded("low-pressure kappa = P/B_max", givens["lp.kappa"], KAPPA_RANGE)
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
                K = b.intersect(f"K{k}", rl, vert, rule=("only",), role="result", labels={f"K{k}": lowered(f"K{k}")},
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
    return Figure(proto, b.replay(proto, givens))


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
        V = ordinate_value(b, ctx, f"ND{k}" if p else f"b{k}", P, point_kind(k, n), dc_p, dc_2, number=str(k))
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
