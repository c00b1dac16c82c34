"""construct table: the books' tables regenerated from the constructions."""

from __future__ import annotations

import csv
import json
import io
import math
import sys

from ...kernel.errors import InvalidParameter, did_you_mean
from ...kernel.division import MAX_PARTS
from ...tables import TABLES, write_plot
from ..common import add_format_option, number, whole_number

NAME = "table"
HELP = ("print a table (piston-path, crank-angle, acceleration, characteristic-points, mass-forces, "
        "tangential-pressure, flywheel-coefficients, speed-fluctuation, speed-extremes)")


def add_arguments(p) -> None:
    p.add_argument("table", metavar="TABLE", help=", ".join(TABLES))
    p.add_argument("--rod-ratio", type=number, action="append", metavar="L/r",
                   help="rod length over crank radius (repeat for the acceleration table)")
    p.add_argument("--parts", type=whole_number, default=18, metavar="N",
                   help="parts of the semicircle the table is read off (default 18)")
    p.add_argument("--method", default="auto", metavar="DIVISION",
                   help="division of the semicircle: auto, exact, durer, neusis, dividers (default auto)")
    p.add_argument("--divisions", type=whole_number, default=10, metavar="N",
                   help="divisions of the stroke (crank-angle; default 10, the book's tenths)")
    p.add_argument("--step", type=number, default=10.0, metavar="DEG", help="angle step of the acceleration table")
    p.add_argument("--weight", type=number, metavar="G", help="mass-forces: weight of the reciprocating parts, kg")
    p.add_argument("--rpm", type=number, metavar="n", help="mass-forces: revolutions per minute")
    p.add_argument("--crank-radius", type=number, metavar="R", help="mass-forces: crank radius, m")
    p.add_argument("--rod-length", type=number, metavar="L", help="mass-forces: connecting-rod length, m")
    p.add_argument("--kz", type=number, action="append", metavar="kz", help="allowed stress kz in kg/cm² (flywheel; repeat)")
    p.add_argument("--v", type=number, action="append", metavar="v", help="rim speed v in m/s (flywheel; repeat)")
    p.add_argument("--infinite-rod", action="store_true",
                   help="an infinitely long rod (speed-fluctuation, speed-extremes)")
    p.add_argument("--dead-centre", choices=("crank-end", "head-end"), default="crank-end",
                   help="speed-fluctuation, speed-extremes: the first crank starts at § 146's B1, the crank-end dead "
                        "centre (default), or at the head-end one")
    p.add_argument("--drive", choices=("engine", "pump"), default="engine",
                   help="speed-fluctuation, speed-extremes: the rods drive the shaft (engine, default) or the shaft "
                        "drives pumps (§ 146: least and greatest speeds change places)")
    p.add_argument("--fluctuation", type=number, metavar="k",
                   help="speed-fluctuation, speed-extremes: k = Qr/((m1+m2) v1²): the speeds v/v1 beside e "
                        "(book's law, energy balance, with the crossheads' terms), the degree of irregularity")
    p.add_argument("--crosshead-share", type=number, metavar="m2/(m1+m2)",
                   help="speed-fluctuation with --fluctuation: the crossheads' share of the masses, 0 .. <1 "
                        "(default 0): v_first and v_full keep the crossheads' terms the book drops")
    add_format_option(p, ("text", "csv", "json"))
    p.add_argument("--plot", metavar="FILE",
                   help="also plot the table as the book draws it into FILE (.png, .pdf or .svg by its suffix)")
    p.add_argument("--revolution", action="store_true",
                   help="mass-forces, tangential-pressure: both strokes, 0..360 degrees")
    p.add_argument("--cranks", default="", metavar="DEG,DEG",
                   help="tangential-pressure --revolution: crank offsets ahead of the first, e.g. 0,90")
    p.add_argument("--machine", default="single", metavar="single|tandem|compound",
                   help="tangential-pressure --revolution: single (default), tandem, compound")
    p.add_argument("--indicator", metavar="FILE.csv",
                   help="tangential-pressure, mass-forces: a digitised indicator diagram of the cover side (x,p)")
    p.add_argument("--force", default="unit", choices=("unit", "baumann"), metavar="unit|baumann",
                   help="tangential-pressure: a unit piston force (default), or Baumann's idealised diagram less "
                        "the acceleration force (a column T in at; return stroke: the diagram mirrored)")
    p.add_argument("--kappa", type=number, metavar="kappa",
                   help="tangential-pressure --force baumann: kappa = P/B_max, 0.1 .. 10000 (default 8; Baumann's 8 and 2)")
    p.add_argument("--indicator-lp", metavar="FILE.csv",
                   help="tangential-pressure --revolution --machine compound|tandem: the low-pressure cylinder's own "
                        "cover-side diagram (x,p as --indicator; default: every cylinder has --indicator's)")
    p.add_argument("--indicator-lp-crank-side", metavar="FILE.csv",
                   help="the low-pressure crank side's diagram (default: the low-pressure cover side's mirrored)")
    p.add_argument("--area-ratio", type=number, metavar="F_lp/F_hp",
                   help="tangential-pressure, compound/tandem: low-pressure piston area over the high-pressure one's, "
                        "0.1 .. 20 (default 2.5)")
    p.add_argument("--piston-area", type=number, metavar="F",
                   help="tangential-pressure with --indicator or --force baumann: the (high-pressure) piston area in "
                        "cm², 0.01 .. 1e7: a column T_kg, the tangential force in kg")
    p.add_argument("--indicator-crank-side", metavar="FILE.csv",
                   help="the crank side's diagram (default: the cover side's mirrored, Baumann's assumption)")


def _one_ratio(args) -> float:
    if not args.rod_ratio:
        raise InvalidParameter(f"table {args.table} needs --rod-ratio L/r")
    if len(args.rod_ratio) > 1:
        raise InvalidParameter(f"table {args.table} takes one --rod-ratio (the acceleration table takes several)")
    return args.rod_ratio[0]


def _check_step(step: float, span: int) -> None:
    """--step must divide *span* degrees, and the semicircle's 180/step parts are at most MAX_PARTS.

    Said in terms of --step: the construction underneath speaks of "parts", which the user did not give.
    """
    if not (math.isfinite(step) and 0 < step <= span):
        raise InvalidParameter(f"--step must be between 0 and {span} degrees, got {step!r}")
    n = round(180.0 / step)
    if n > MAX_PARTS:
        raise InvalidParameter(f"--step must be at least {180 / MAX_PARTS:g} degrees (the table is read off a "
                               f"semicircle divided into 180/step parts, at most {MAX_PARTS}), got {step!r}")
    if abs(n * step - 180.0) > 1e-9 or (span == 90 and n % 2):
        raise InvalidParameter(f"--step must divide {span} degrees (e.g. {span / 9:g}, {span / 18:g}), got {step!r}")


def run(args) -> int:
    if args.table not in TABLES:
        raise InvalidParameter(f"unknown table {args.table!r}{did_you_mean(args.table, TABLES)}; choose one of {', '.join(TABLES)}")
    if (args.indicator or args.indicator_crank_side) and args.table not in ("tangential-pressure", "mass-forces"):
        raise InvalidParameter(f"--indicator goes with the tables tangential-pressure and mass-forces, not {args.table}")
    if args.table != "tangential-pressure" and (args.force != "unit" or args.kappa is not None or any(
            v is not None for v in (args.indicator_lp, args.indicator_lp_crank_side, args.area_ratio, args.piston_area))):
        raise InvalidParameter(f"--force, --kappa, --indicator-lp, --area-ratio and --piston-area go with the table "
                               f"tangential-pressure, not {args.table}")
    if args.table not in ("speed-fluctuation", "speed-extremes") and (
            args.fluctuation is not None or args.crosshead_share is not None or args.drive != "engine"):
        raise InvalidParameter(f"--fluctuation, --crosshead-share and --drive go with the tables speed-fluctuation "
                               f"and speed-extremes, not {args.table}")
    if args.revolution and args.table not in ("tangential-pressure", "mass-forces"):
        raise InvalidParameter(f"--revolution goes with the tables tangential-pressure and mass-forces, not {args.table}")
    if args.table == "piston-path":
        cols, rows = TABLES[args.table](rod_ratio=_one_ratio(args), parts=args.parts, method=args.method)
    elif args.table == "crank-angle":
        cols, rows = TABLES[args.table](rod_ratio=_one_ratio(args), divisions=args.divisions)
    elif args.table == "acceleration":
        if not args.rod_ratio:
            raise InvalidParameter("table acceleration needs at least one --rod-ratio L/r")
        _check_step(args.step, 180)
        cols, rows = TABLES[args.table](rod_ratios=args.rod_ratio, step=args.step)
    elif args.table == "mass-forces":
        missing = [f"--{k}" for k in ("weight", "rpm", "crank-radius", "rod-length")
                   if getattr(args, k.replace("-", "_")) is None]
        if missing:
            raise InvalidParameter(f"table mass-forces needs {' '.join(missing)}")
        if args.indicator or args.indicator_crank_side:
            raise InvalidParameter("table mass-forces takes no --indicator: the mass forces do not depend on the "
                                   "pressures (the piston-force construction takes the diagram)")
        cols, rows = TABLES[args.table](weight=args.weight, rpm=args.rpm, crank_radius=args.crank_radius,
                                        rod_length=args.rod_length, parts=args.parts, revolution=args.revolution)
    elif args.table == "tangential-pressure":
        cols, rows = TABLES[args.table](rod_ratio=_one_ratio(args), parts=args.parts, method=args.method,
                                        revolution=args.revolution, cranks=args.cranks, machine=args.machine,
                                        indicator=args.indicator, indicator_crank_side=args.indicator_crank_side,
                                        force=args.force, kappa=args.kappa, indicator_lp=args.indicator_lp,
                                        indicator_lp_crank_side=args.indicator_lp_crank_side,
                                        area_ratio=args.area_ratio, piston_area=args.piston_area)
    elif args.table == "flywheel-coefficients":
        cols, rows = TABLES[args.table](kz=args.kz, v=args.v)
    elif args.table in ("speed-fluctuation", "speed-extremes"):
        if args.infinite_rod and args.rod_ratio:
            raise InvalidParameter("give either --rod-ratio L/r or --infinite-rod, not both")
        rod = None if args.infinite_rod else _one_ratio(args)
        if args.table == "speed-fluctuation":
            _check_step(args.step, 90)
            cols, rows = TABLES[args.table](rod_ratio=rod, step=args.step, dead_centre=args.dead_centre,
                                            drive=args.drive, fluctuation=args.fluctuation,
                                            crosshead_share=args.crosshead_share)
        else:
            if args.crosshead_share is not None:
                raise InvalidParameter("--crosshead-share goes with the table speed-fluctuation")
            cols, rows = TABLES[args.table](rod_ratio=rod, parts=args.parts, dead_centre=args.dead_centre,
                                            drive=args.drive, fluctuation=args.fluctuation)
        if args.drive == "pump":
            print("construct: note: the shaft drives pumps (§ 146): the speeds fall where e rises -- the least "
                  "speed where e is greatest", file=sys.stderr)
    else:
        cols, rows = TABLES[args.table](rod_ratio=_one_ratio(args))
    text = format_table(cols, rows, args.format)
    if args.force == "baumann" and args.table == "tangential-pressure":
        print("construct: note: T from Baumann's idealised diagram"
              + ("; return stroke: the same diagram mirrored (his assumption: the diagrams of the forward and "
                 "return strokes are equal)" if args.revolution else "")
              + ("; the low-pressure cylinder: its own idealised diagram (illustrative defaults, see --help of "
                 "construct replay tangential-pressure: --lp-*)" if args.machine in ("compound", "tandem") else ""),
              file=sys.stderr)
    if args.indicator_lp is not None:
        print("construct: note: the low-pressure cylinder from its own indicator diagram, its pressures times "
              "--area-ratio in T", file=sys.stderr)
    if args.indicator is not None:
        from ...tables import indicator_note

        print(f"construct: note: {indicator_note(args.indicator_crank_side)}", file=sys.stderr)
    if args.plot is not None:
        write_plot(args.table, cols, rows, args.plot)
    sys.stdout.write(text)
    return 0


def _cell(v) -> str:
    if isinstance(v, float):
        return f"{v + 0.0:.15g}"  # + 0.0 turns a measured -0 into 0
    return str(v)


def format_table(cols, rows, fmt: str) -> str:
    if fmt == "json":  # the rows as objects, keys in the columns' order
        return json.dumps([{c: r[c] for c in cols} for r in rows], indent=1, ensure_ascii=False) + "\n"
    if fmt == "csv":
        buf = io.StringIO()
        w = csv.writer(buf, lineterminator="\n")
        w.writerow(cols)
        for r in rows:
            w.writerow([_cell(r[c]) for c in cols])
        return buf.getvalue()
    cells = [[c for c in cols]] + [[_cell(r[c]) for c in cols] for r in rows]
    widths = [max(len(row[i]) for row in cells) for i in range(len(cols))]
    return "".join("  ".join(v.rjust(w) for v, w in zip(row, widths)) + "\n" for row in cells)
