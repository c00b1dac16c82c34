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

from ...books.baumann.flywheel import DISC_GYRATION, derived, design, parse_fraction, rim_moment_correction
from ...kernel.errors import InvalidParameter
from ..common import add_format_option, construction_given, number

NAME = "flywheel"
HELP = ("size a flywheel by Baumann (1902): excess work (given, or measured on a diagram or your indicator cards) -> rim weight G_s (E = G_s v² δ/g), arms and hub, "
        "total weight and moment G·D²")

KEYS = ("excess_work", "rim_weight", "arms_hub_weight", "total_weight", "moment")
_MORE = ("rim_of_wheel", "rim_speed", "diameter", "rpm", "kz", "kz_rule", "fluctuation", "total_quotient",
         "rim_by_moment", "exact_rim", "exact_arms_hub", "exact_total")
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
    p.add_argument("--rim-height", type=number, metavar="H",
                   help="the rim's radial height h in m: his last paragraph worked out -- the rim's moment "
                        "G1(Da² + Di²)/2 against his G1·D1², and the disc's part inside the rim")
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
    c = get(args.diagram)
    givens = dict(construction_given(c, item) for item in args.given)
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
    if args.rim_height is not None and not math.isfinite(args.rim_height):
        raise InvalidParameter(f"--rim-height must be finite, got {args.rim_height!r}")
    correction = None if args.rim_height is None else rim_moment_correction(
        d["rim_of_wheel"], d["diameter"], _in_m("--rim-height", args.rim_height), d["arms_hub_weight"])
    if args.format == "json":
        record = {k: d[k] for k in KEYS + _MORE}
        record["excess_source"] = source or ("given" if work is not None else None)
        if correction is not None:
            record["rim_moment"] = correction
        print(json.dumps(record, ensure_ascii=False, indent=1))
        return 0
    print("\n".join(_text(d, work, source, correction)))
    return 0


def _in_m(option: str, value: float) -> float:
    from ...constructions.domain import LENGTH_M

    return float(LENGTH_M.check(f"{option} (m)", value))


def _sig(value: float) -> str:
    """A quantity to five significant figures, whatever its size: 1376.2, 20.944, 5.2e-05 (never 0 for 5.2e-05).

    >>> _sig(1376.23), _sig(20.9439), _sig(5.2e-05), _sig(17597.3)
    ('1376.2', '20.944', '5.2e-05', '17597')
    """
    return f"{value:.5g}"


def _text(d: dict, work: float | None, source: str | None, correction: dict | None) -> list[str]:
    """The text report: his figures beside the exact ones, and what each is."""
    v = d["rim_speed"]
    x = v * v / d["kz"]
    exact = derived()
    a, m = f"{exact['arms_hub']:.4f}", f"{exact['moment_gyration']:.4f}"   # 0.0795, 0.0247
    lines = []
    if work is not None:
        lines.append(f"excess work E          {_sig(d['excess_work']):>12} kg·m" + (f"   ({source})" if source else ""))
        lines.append(f"irregularity δ         {_sig(d['fluctuation']):>12}       (1/{1 / d['fluctuation']:.4g})")
    lines += [
        f"rim speed v            {_sig(v):>12} m/s   (D = {_sig(d['diameter'])} m, n = {d['rpm']:g}/min)",
        f"kz                     {_sig(d['kz']):>12} kg/cm²  ({d['kz_rule']}; x = v²/kz = {_sig(x)})",
        f"rim weight G_s         {_sig(d['rim_weight']):>12} kg" + ("     (E = (G_s/g) v² δ, g = 9.81)" if work else ""),
        f"moment G_s·D²          {_sig(d['moment']):>12} kg·m²",
    ]
    rows = [("", "Baumann, as printed", "", "exact, from his assumptions", ""),
            ("total weight", _sig(d["total_weight"]), "G_s(1 + 0.06 x)", _sig(d["exact_total"]), f"G1(1 + {a} x)"),
            ("  rim of the wheel G1", _sig(d["rim_of_wheel"]), "G_total/(1 + 0.08075 x)", _sig(d["exact_rim"]),
             f"G_s/(1 + {m} x)"),
            ("  arms and hub", _sig(d["arms_hub_weight"]), "G_total − G1", _sig(d["exact_arms_hub"]), f"G1·{a} x")]
    w = [max(len(r[i]) for r in rows[1:]) for i in range(5)]
    lines.append("")
    lines.append(f"{'':{w[0]}}  {rows[0][1]:<{w[1] + w[2] + 5}}  {rows[0][3]}")
    for label, his, his_f, exact, exact_f in rows[1:]:
        lines.append(f"{label:{w[0]}}  {his:>{w[1]}} kg  {his_f:<{w[2]}}  {exact:>{w[3]}} kg  {exact_f}")
    lines += [
        "",
        "Baumann's method is not consistent in itself (the exact column is: its wheel has the moment G_s·D² it "
        "was sized for):",
        f"  his 1 + 0.06 x = {1 + 0.06 * x:.4f} expands his own quotient (1 + 0.08075 x)/(1 + 0.0218 x) = "
        f"{d['total_quotient'] / d['rim_weight']:.4f} (total {_sig(d['total_quotient'])} kg);",
        f"  his derivation's rim G_s/(1 + 0.0218 x) = {_sig(d['rim_by_moment'])} kg, his summary's "
        f"G_total/(1 + 0.08075 x) = {_sig(d['rim_of_wheel'])} kg;",
        f"  ρ = 7/12 r1 halves the arms' mass but is not their radius of gyration (k² = {DISC_GYRATION:.3f} r1², "
        f"not 0.340): the moment coefficient is {m}, not 0.0218; the arms and hub from 13/6 π, not his 2.2 π: "
        f"{a}, not 0.08075.",
    ]
    if correction is not None:
        lines += [
            "",
            f"rim moment (his last paragraph): G1·D1² = {_sig(correction['rim_moment_mean'])} kg·m² stands for "
            f"G1(Da² + Di²)/2 = {_sig(correction['rim_moment_true'])} kg·m²: too little by "
            f"{_sig(correction['too_little'])};",
            f"  the disc counted inside the rim (from Di/2 to D1/2) adds {_sig(correction['too_much'])} kg·m² too "
            f"much: the too little makes up {correction['ratio']:.0%} of it (his 'hinreichend' holds for "
            f"{'this rim' if correction['ratio'] >= 0.9 else 'a far taller rim only'})",
        ]
    return lines
