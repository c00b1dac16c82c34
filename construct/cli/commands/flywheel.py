"""``construct flywheel``: from the excess work of the tangential-pressure diagram to the flywheel's weight.

Baumann's procedure (1902): the excess work E the flywheel takes up while
the crank runs ahead gives the rim weight G_s from E = (G_s/g)·v²·δ (g = 9.81),
v = π D n/60 the rim's mean speed and δ the degree of irregularity; his
coefficients add arms and hub (total G_s(1 + 0.06 v²/kz); the wheel's own
rim G_total/(1 + 0.08075 v²/kz), the rest arms and hub) and the moment is
G_s·D².  The excess work comes

* directly, ``--excess-work E`` (kg·m), or
* from a diagram: ``--diagram tangential-pressure`` builds that construction
  (its givens by ``--given NAME=VALUE``, e.g. ``--given kappa=2``) and measures its
  excess area (at of piston area × radian), times ``--piston-area`` (cm²) and
  ``--crank-radius`` (m);
* from your own indicator diagrams, ``--indicator FILE.csv`` (the cover side's card, CSV ``x,p`` as
  ``construct table tangential-pressure`` reads it; ``--indicator-crank-side``, else the card mirrored,
  Baumann's assumption) with ``--rod-ratio``: the tangential-pressure construction over a whole
  revolution (both strokes, each with its own card), the greatest swing of its excess areas
  (at·rad) times the piston area and the crank radius.  ``--machine compound`` or ``tandem`` with
  ``--indicator-lp`` and ``--area-ratio`` gives the low-pressure cylinder its own card;

or ``--rim-weight G_s`` skips it (Baumann's worked examples start there).

>>> from construct.cli import main
>>> main(["flywheel", "--rim-weight", "2130", "--diameter", "3.2", "--rpm", "120", "--format", "json"])
... # doctest: +ELLIPSIS
{
 "excess_work": null,
 "rim_weight": 2130.0,
 "arms_hub_weight": 648.0...,
 "total_weight": 2643.9...,
 "moment": 21811.2,
...
0
"""

from __future__ import annotations

import argparse
import json
import math

from ...books.baumann.flywheel import design, parse_fraction
from ...kernel.errors import InvalidParameter
from ..common import add_format_option, is_number, number

NAME = "flywheel"
HELP = ("size a flywheel by Baumann (1902): excess work (given, or measured on a diagram or your indicator cards) -> rim weight G_s (E = G_s v² δ/g), arms and hub, "
        "total weight and moment G·D²")

KEYS = ("excess_work", "rim_weight", "arms_hub_weight", "total_weight", "moment")
_MORE = ("rim_of_wheel", "rim_speed", "diameter", "rpm", "kz", "kz_rule", "fluctuation", "total_quotient")
DIAGRAMS = ("tangential-pressure",)


def _fraction(text: str) -> float:
    try:
        return parse_fraction(text)
    except InvalidParameter as e:
        raise argparse.ArgumentTypeError(str(e)) from None


def add_arguments(p) -> None:
    p.add_argument("--excess-work", type=number, metavar="E", help="excess work in kg·m")
    p.add_argument("--rim-weight", type=number, metavar="GS", help="the rim weight G_s itself, kg (instead of E)")
    p.add_argument("--diagram", choices=DIAGRAMS, help="measure E on this construction's excess area")
    p.add_argument("--given", action="append", default=[], metavar="NAME=VALUE",
                   help="a given of the --diagram construction (repeatable), e.g. --given kappa=2")
    p.add_argument("--revolution", action="store_true",
                   help="with --diagram: measure E over a whole revolution, the return stroke from his diagram "
                        "mirrored (the greatest swing of the excess areas), instead of the forward stroke's excess "
                        "area (Baumann's method, assuming both strokes equal)")
    p.add_argument("--piston-area", type=number, metavar="CM2",
                   help="piston area F in cm², 0.01 .. 1e7 (with --diagram or --indicator; the high-pressure "
                        "piston's for a compound)")
    p.add_argument("--crank-radius", type=number, metavar="M",
                   help="crank radius in m, 0.001 .. 1000 (with --diagram or --indicator)")
    p.add_argument("--indicator", metavar="FILE.csv",
                   help="measure E on the tangential-pressure construction over a revolution drawn from this "
                        "digitised indicator diagram of the cover side (CSV x,p: x from the head-end dead centre "
                        "in strokes, p absolute in at)")
    p.add_argument("--indicator-crank-side", metavar="FILE.csv",
                   help="with --indicator: the crank side's diagram (default: the cover side's mirrored, "
                        "Baumann's assumption)")
    p.add_argument("--rod-ratio", type=number, metavar="L/r",
                   help="with --indicator: connecting-rod length over crank radius, 1.05 .. 1000")
    p.add_argument("--machine", choices=("single", "tandem", "compound"), metavar="single|tandem|compound",
                   help="with --indicator: the engine (default single; compound: cranks at 0 and 90 degrees)")
    p.add_argument("--indicator-lp", metavar="FILE.csv",
                   help="with --indicator and --machine compound|tandem: the low-pressure cylinder's own cover-side "
                        "diagram (default: every cylinder has --indicator's)")
    p.add_argument("--area-ratio", type=number, metavar="F_lp/F_hp",
                   help="with --indicator-lp: low-pressure piston area over the high-pressure one's, 0.1 .. 20 "
                        "(default 2.5)")
    p.add_argument("--rpm", type=number, required=True, metavar="N", help="revolutions per minute")
    p.add_argument("--fluctuation", type=_fraction, metavar="DELTA",
                   help="degree of irregularity δ = (v_max − v_min)/v_mean, e.g. 1/80 (Ungleichförmigkeitsgrad)")
    p.add_argument("--diameter", type=number, metavar="D", help="mean diameter of the rim in m")
    p.add_argument("--v", type=number, metavar="M_S", help="rim speed in m/s (instead of --diameter)")
    p.add_argument("--kz", type=number, metavar="KG_CM2",
                   help="allowed tensile stress of the cast iron, kg/cm² (default 5 v, Baumann's pairing)")
    add_format_option(p)


def _diagram_work(args) -> tuple[float, str]:
    from ...constructions import get
    from ...constructions.domain import LENGTH_M, PISTON_AREA
    from ...constructions.tangential import excess_area

    missing = [o for o, v in (("--piston-area", args.piston_area), ("--crank-radius", args.crank_radius)) if v is None]
    if missing:
        raise InvalidParameter(f"--diagram needs {' and '.join(missing)} to turn the excess area into work")
    if args.excess_work is not None or args.rim_weight is not None:
        raise InvalidParameter("give --diagram, --excess-work or --rim-weight, one of them")
    area = PISTON_AREA.check("piston area F (cm²)", args.piston_area)
    radius = LENGTH_M.check("crank radius (m)", args.crank_radius)
    givens = {}
    for item in args.given:
        name, sep, value = item.partition("=")
        if not sep or not name or not is_number(value) or not math.isfinite(number(value)):
            raise InvalidParameter(f"--given takes NAME=VALUE with a finite number, got {item!r}")
        givens[name] = number(value)
    c = get(args.diagram)
    givens.setdefault("force", "baumann")
    if givens["force"] != "baumann":
        raise InvalidParameter("the flywheel needs the pressure diagram (force=baumann), not the unit force")
    if "revolution" in givens:
        raise InvalidParameter("say --revolution, not --given revolution=...")
    if args.revolution:
        from ...constructions.revolution import excess_work

        fig = c.figure(revolution=True, **givens)
        excess = excess_work(fig)
        return excess * area * radius, (
            f"greatest swing of the excess areas {excess:.6g} at·rad over a revolution (the return stroke from "
            f"the same diagram mirrored) measured on the {args.diagram} construction × F = {area:g} cm² × "
            f"r = {radius:g} m")
    fig = c.figure(**givens)
    excess = excess_area(fig)
    return excess * area * radius, (f"excess area {excess:.6g} at·rad measured on the {args.diagram} construction "
                                    f"(the forward stroke; Baumann: the return stroke's equal) × F = {area:g} cm² "
                                    f"× r = {radius:g} m")


def _card_work(args) -> tuple[float, str]:
    """E from the user's cards: the tangential-pressure construction over a revolution, its greatest swing."""
    from ...constructions import get
    from ...constructions.domain import LENGTH_M, PISTON_AREA
    from ...constructions.revolution import excess_work

    missing = [o for o, v in (("--piston-area", args.piston_area), ("--crank-radius", args.crank_radius),
                              ("--rod-ratio", args.rod_ratio)) if v is None]
    if missing:
        raise InvalidParameter(f"--indicator needs {' and '.join(missing)} to turn the excess areas into work")
    if args.excess_work is not None or args.rim_weight is not None or args.diagram is not None:
        raise InvalidParameter("give --indicator, --diagram, --excess-work or --rim-weight, one of them")
    if args.given:
        raise InvalidParameter("--given belongs to --diagram; with --indicator the card gives the pressures")
    area = PISTON_AREA.check("piston area F (cm²)", args.piston_area)
    radius = LENGTH_M.check("crank radius (m)", args.crank_radius)
    fig = get("tangential-pressure").figure(
        rod_ratio=args.rod_ratio, revolution=True, machine=args.machine or "single", indicator=args.indicator,
        indicator_crank_side=args.indicator_crank_side or "", indicator_lp=args.indicator_lp or "",
        **({} if args.area_ratio is None else {"area_ratio": args.area_ratio}))
    swing = excess_work(fig)
    sides = "crank side from its own card" if args.indicator_crank_side else \
        "crank side: the cover side's card mirrored (Baumann's assumption)"
    if args.indicator_lp:
        sides += (f"; {fig.params['machine']} engine, the low-pressure cylinder from its own card, its pressures "
                  f"× F_lp/F_hp = {fig.replay.givens['area_ratio']:g}")
    return swing * area * radius, (f"greatest swing of the excess areas {swing:.6g} at·rad on the tangential-pressure "
                                   f"construction over a revolution from the card ({sides}) × F = {area:g} cm² × "
                                   f"r = {radius:g} m")


def run(args) -> int:
    source = None
    work = args.excess_work
    card_only = [o for o, v in (("--indicator-crank-side", args.indicator_crank_side), ("--rod-ratio", args.rod_ratio),
                                ("--machine", args.machine), ("--indicator-lp", args.indicator_lp),
                                ("--area-ratio", args.area_ratio)) if v is not None]
    if args.indicator is None and card_only:
        raise InvalidParameter(f"{', '.join(card_only)} belong(s) to --indicator FILE.csv")
    if args.area_ratio is not None and args.indicator_lp is None:
        raise InvalidParameter("--area-ratio goes with --indicator-lp (the low-pressure cylinder's own card)")
    if args.revolution and args.diagram is None:
        raise InvalidParameter("--revolution goes with --diagram (with --indicator the whole revolution is measured "
                               "anyway)")
    if args.indicator is not None:
        work, source = _card_work(args)
    elif args.diagram is not None:
        work, source = _diagram_work(args)
    elif args.given or args.piston_area is not None or args.crank_radius is not None:
        raise InvalidParameter("--given, --piston-area and --crank-radius belong to --diagram or --indicator")
    for opt in ("rpm", "diameter", "v", "kz", "excess_work", "rim_weight"):
        value = getattr(args, opt)
        if value is not None and not math.isfinite(value):
            raise InvalidParameter(f"--{opt.replace('_', '-')} must be finite, got {value!r}")
    d = design(rpm=args.rpm, diameter=args.diameter, v=args.v, kz=args.kz, excess_work=work,
               fluctuation=args.fluctuation, rim_weight=args.rim_weight)
    if args.format == "json":
        record = {k: d[k] for k in KEYS + _MORE}
        record["excess_source"] = source or ("given" if work is not None else None)
        print(json.dumps(record, ensure_ascii=False, indent=1))
        return 0
    lines = []
    if work is not None:
        lines.append(f"excess work E          {d['excess_work']:12.1f} kg·m" + (f"   ({source})" if source else ""))
        lines.append(f"irregularity δ         {d['fluctuation']:12.6g}       (1/{1 / d['fluctuation']:.4g})")
    lines += [
        f"rim speed v            {d['rim_speed']:12.2f} m/s   (D = {d['diameter']:.3f} m, n = {d['rpm']:g}/min)",
        f"kz                     {d['kz']:12.1f} kg/cm²  ({d['kz_rule']})",
        f"rim weight G_s         {d['rim_weight']:12.0f} kg" + ("     (E = (G_s/g) v² δ, g = 9.81)" if work else ""),
        f"total weight           {d['total_weight']:12.0f} kg     (G_s (1 + 0.06 v²/kz))",
        f"  rim of the wheel G1  {d['rim_of_wheel']:12.0f} kg     (G_total / (1 + 0.08075 v²/kz))",
        f"  arms and hub         {d['arms_hub_weight']:12.0f} kg     (G_total − G1)",
        f"moment G_s·D²          {d['moment']:12.0f} kg·m²",
    ]
    print("\n".join(lines))
    return 0
