"""Options shared by the subcommands that build a construction."""

from __future__ import annotations

import argparse
import math
from typing import Any

from ..constructions import Construction, Figure, find, get
from ..kernel.errors import InvalidParameter, did_you_mean
from ..kernel.protocol import Protocol


def brief(text: str, limit: int = 80) -> str:
    """A name read from a file (a protocol's construction, a path) as a report line quotes it: one line,
    at most *limit* characters -- a protocol may name its construction with a megabyte.

    >>> brief("crank"), len(brief("x" * 10**6)), brief("a\\nb")
    ('crank', 80, 'a b')
    """
    text = " ".join(str(text).split())
    return text if len(text) <= limit else text[:limit - 1] + "…"


def number(text: str) -> float:
    """An option's number, as argparse's ``type=``: a word that is no number is a usage error.

    >>> number("2.5"), number("1e3")
    (2.5, 1000.0)
    """
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    return v


def whole_number(text: str) -> int:
    """An option's whole number (a count of parts, divisions), as argparse's ``type=``.

    >>> whole_number("12")
    12
    """
    try:
        return int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None


def add_format_option(p: argparse.ArgumentParser, formats: tuple[str, ...] = ("text", "json")) -> None:
    """``--format FORMAT`` as every command that prints data takes it, with ``--json`` kept as its alias."""
    p.add_argument("--format", choices=formats, default=formats[0],
                   help=f"output format: {', '.join(formats)} (default: {formats[0]})")
    if "json" in formats:
        p.add_argument("--json", dest="format", action="store_const", const="json",
                       help="the same as --format json")


def add_print_options(p: argparse.ArgumentParser, *, formats: bool = True) -> None:
    """``--format`` and the options of a plate at its final size (:class:`construct.render.page.Sheet`)."""
    from ..render.output import FORMATS
    from ..render.page import CAPTIONS, TIKZ_STYLES, Sheet

    if formats:
        p.add_argument("--format", default="svg", metavar="svg|pdf|tikz",
                       help=f"what the plate is written as: {', '.join(FORMATS)}, or several joined by commas "
                            f"(default svg: the figure and its screen pages)")
    p.add_argument("--width-mm", type=number, default=Sheet.width_mm, metavar="MM",
                   help=f"(pdf, tikz) the plate's width on the page in millimetres (default {Sheet.width_mm:g})")
    p.add_argument("--letter-pt", type=number, default=Sheet.letter_pt, metavar="PT",
                   help=f"(pdf, tikz) the letters' size in points, which they are placed for (default {Sheet.letter_pt:g})")
    p.add_argument("--caption", default=Sheet.caption, metavar="|".join(CAPTIONS),
                   help="(pdf, tikz) the caption beneath the plate: none (the edition sets its own; default), de or en")
    p.add_argument("--outline", action="store_true",
                   help="(pdf) the letters as outlines: the file holds no font")
    p.add_argument("--tikz-style", default=Sheet.tikz_style, metavar="|".join(TIKZ_STYLES),
                   help="(tikz) TikZ's own paths (default), or tkz-euclide's macros for the points")
    p.add_argument("--paper", metavar="white|cream|#RRGGBB",
                   help="the paper's colour (default: the style's; the historical plate is white, its screen pages "
                        "cream)")


def print_request(args: argparse.Namespace) -> tuple[tuple[str, ...], Any]:
    """(formats, sheet) of the command line: each checked, a wrong one refused with its reason."""
    from ..render.output import check_formats
    from ..render.page import Sheet

    formats = check_formats([f.strip() for f in str(getattr(args, "format", "svg")).split(",")])
    sheet = Sheet(width_mm=args.width_mm, letter_pt=args.letter_pt, caption=args.caption, outline=args.outline,
                  tikz_style=args.tikz_style)
    if args.paper is not None:
        from ..render.styles import paper_colour

        paper_colour(args.paper)
    return formats, sheet


def add_construction_options(p: argparse.ArgumentParser, *, name_optional: bool = True) -> None:
    from ..constructions import names

    p.add_argument("name", nargs="?" if name_optional else None, metavar="CONSTRUCTION",
                   help=f"{', '.join(names())} (titles: 'construct list')")
    p.add_argument("--protocol", metavar="FILE", help="replay an exported protocol.json instead of building afresh")
    from ..constructions.domain import ROD_RATIO

    p.add_argument("--rod-ratio", type=number, metavar="L/r", help=f"connecting rod length over crank radius, "
                   f"{ROD_RATIO.low:g} <= L/r <= {ROD_RATIO.high:g}")
    p.add_argument("--parts", type=whole_number, metavar="N", help="parts of the semicircle (1..3600)")
    p.add_argument("--method", metavar="DIVISION", help="how the semicircle is divided: auto, exact, durer, neusis, dividers")
    p.add_argument("--divisions", type=whole_number, metavar="N", help="divisions of the stroke (crank-angle)")
    p.add_argument("--radius", type=number, metavar="r", help="crank radius r in drawing units")
    p.add_argument("--pressure-ratio", type=number, metavar="F/f", help="F/f of the inertia pressures")
    p.add_argument("--infinite-rod", action="store_true", default=None,
                   help="an infinitely long connecting rod (instead of --rod-ratio)")
    p.add_argument("--revolution", action="store_true", default=None,
                   help="tangential-pressure, piston-force: both strokes over the whole revolution")
    p.add_argument("--fluctuation", type=number, metavar="k", help="k = Qr/((m1+m2) v1²) of the two cranks")
    p.add_argument("--magnify", type=number, metavar="G", help="magnification of the speed deviations (two-cranks)")
    p.add_argument("--given", action="append", default=[], metavar="NAME=VALUE",
                   help="set a given of a --protocol by its own name (repeatable), e.g. --given s=10")
    _add_generic_options(p)


PARAM_OPTIONS = {"rod_ratio": "rod_ratio", "parts": "parts", "method": "method", "divisions": "divisions",
                 "radius": "r", "pressure_ratio": "pressure_ratio", "infinite_rod": "infinite_rod",
                 "fluctuation": "fluctuation", "magnify": "magnify", "revolution": "revolution"}


#: The placeholder of each construction parameter without an option of its own: the book's symbol or unit.
SYMBOLS = {"admission": "P", "back_pressure": "P0", "clearance": "s0/s", "compression": "s3/s",
           "crank_radius": "R", "filling": "s1/s", "force": "baumann|unit", "force_unit": "LENGTH/kg",
           "kappa": "kappa", "piston_area": "F", "pressure_unit": "LENGTH/at", "rod_length": "L", "rpm": "n",
           "scale": "LENGTH/m", "weight": "G", "b1": "b1/r1", "rim": "h/r1", "compression_ratio": "epsilon",
           "cutoff": "rho", "release": "x_e/s", "drive": "engine|pump", "efficiency": "eta", "dead_centre": "crank-end|head-end", "engine": "explosion|diesel", "exhaust": "p_g",
           "exponent": "n", "max_pressure": "p", "steps": "N", "suction": "p_a", "cranks": "DEG,DEG",
           "indicator": "FILE.csv", "indicator_crank_side": "FILE.csv", "machine": "single|tandem|compound",
           "piston_area_cover": "F'", "piston_area_crank": "F''", "indicator_lp": "FILE.csv",
           "indicator_lp_crank_side": "FILE.csv", "area_ratio": "F_lp/F_hp", "lp_filling": "s1/s",
           "lp_admission": "P", "lp_back_pressure": "P0", "lp_compression": "s3/s", "lp_kappa": "kappa"}

#: Help of parameters whose construction does not give one.
HELPS = {"kappa": "Baumann's kappa = P/B_max, the piston force over the largest acceleration force of the rod "
                  "drawn, B_max = c v²/r (1 + r/L) (his 1,2 for r/L = 1/5; tangential-pressure: 8 or 2)",
         "force": "the piston force: baumann (the indicator diagram less the acceleration force) or unit "
                  "(a unit force; tangential-pressure)"}


def _generic_params() -> dict[str, tuple[Any, str]]:
    """Every other construction parameter, as --its-name-with-dashes: (type of its default, help).

    A switch (a bool, or a construction's ``extra["switches"]`` whose default follows from other givens) is
    ``bool``: ``--name`` and ``--no-name``; a default of None is an optional number (its value follows from
    other givens, as the four-stroke's compression ratio from the engine).
    """
    from ..constructions import names

    covered = set(PARAM_OPTIONS.values())
    out: dict[str, tuple[Any, str]] = {}
    for name in names():
        c = get(name)
        helps = c.help
        for key, default in c.defaults.items():
            if key in covered or key in out:
                continue
            if isinstance(default, bool) or key in c.extra.get("switches", ()):
                kind: Any = bool
            elif isinstance(default, int):
                kind = whole_number
            else:
                kind = number if default is None or isinstance(default, float) else str
            out[key] = (kind, helps.get(key) or HELPS.get(key, f"{key.replace('_', ' ')} (default {default!r} in {name})"))
    return out


def _add_generic_options(p: argparse.ArgumentParser) -> None:
    for key, (kind, text) in sorted(_generic_params().items()):
        if kind is bool:
            p.add_argument(f"--{key.replace('_', '-')}", dest=key, action=argparse.BooleanOptionalAction,
                           default=None, help=text)
        else:
            p.add_argument(f"--{key.replace('_', '-')}", dest=key, type=kind, metavar=SYMBOLS.get(key, key.upper()),
                           help=text)


def given_options(args: argparse.Namespace) -> dict[str, Any]:
    if getattr(args, "infinite_rod", None) and getattr(args, "rod_ratio", None) is not None:
        raise InvalidParameter("give either --rod-ratio L/r or --infinite-rod, not both")
    out = {}
    options = {**PARAM_OPTIONS, **{key: key for key in _generic_params()}}
    for opt, param in options.items():
        v = getattr(args, opt, None)
        if v is not None:
            if isinstance(v, float) and not math.isfinite(v):
                raise InvalidParameter(f"--{opt.replace('_', '-')} must be finite, got {v!r}")
            out[param] = v
    return out


def load_protocol(path: str) -> Protocol:
    """A protocol file, read bounded and checked whole (:meth:`Protocol.load`)."""
    return Protocol.load(path)


def _named_givens(args: argparse.Namespace) -> dict[str, float]:
    out: dict[str, float] = {}
    for item in getattr(args, "given", None) or []:
        name, sep, value = item.partition("=")
        if not sep or not name:
            raise InvalidParameter(f"--given takes NAME=VALUE, got {item!r}")
        v = number(value) if is_number(value) else None
        if v is None or not math.isfinite(v):
            raise InvalidParameter(f"--given {name} must be a finite number, got {value!r}")
        out[name] = v
    return out


def construction_given(c: Construction, item: str, *, option: str = "--given") -> tuple[str, Any]:
    """``NAME=VALUE`` for a parameter of *c*, the value read as the parameter's own kind (its default's type).

    A count (``parts``) takes a whole number, a choice (``force``, ``method``) a word, a switch ``true`` or
    ``false``, everything else a finite number; a name the construction does not take is refused with the
    names it does take (and the nearest, when one is near).

    >>> from construct.constructions import get
    >>> c = get("tangential-pressure")
    >>> construction_given(c, "parts=18"), construction_given(c, "kappa=2"), construction_given(c, "force=unit")
    (('parts', 18), ('kappa', 2.0), ('force', 'unit'))
    >>> construction_given(c, "parts=18.5")
    Traceback (most recent call last):
    ...
    construct.kernel.errors.InvalidParameter: --given parts takes a whole number (a count), got '18.5'
    """
    name, sep, value = item.partition("=")
    name, value = name.strip(), value.strip()
    if not sep or not name:
        raise InvalidParameter(f"{option} takes NAME=VALUE, got {item!r}")
    if name not in c.defaults:
        raise InvalidParameter(f"{c.name} has no parameter {name!r}{did_you_mean(name, c.defaults)}; "
                               f"it takes {', '.join(sorted(c.defaults))}")
    default = c.defaults[name]
    if isinstance(default, bool):
        if value.lower() not in ("true", "false"):
            raise InvalidParameter(f"{option} {name} takes true or false, got {value!r}")
        return name, value.lower() == "true"
    if isinstance(default, int):
        try:
            return name, int(value)
        except ValueError:
            raise InvalidParameter(f"{option} {name} takes a whole number (a count), got {value!r}") from None
    if isinstance(default, str):
        return name, value
    v = number(value) if is_number(value) else None
    if v is None or not math.isfinite(v):
        raise InvalidParameter(f"{option} {name} takes a finite number, got {value!r}")
    return name, v


def is_number(text: str) -> bool:
    """Does *text* read as a number (``-3`` after an option is its value, not an option)?

    >>> is_number("-3"), is_number("-x")
    (True, False)
    """
    try:
        float(text)
    except ValueError:
        return False
    return True


def figure_from_args(args: argparse.Namespace) -> tuple[Construction | None, Figure]:
    """Build the named construction, or replay --protocol with the given givens.

    A protocol of a construction this library does not know replays all the
    same (it needs nothing but the op table); the construction is then None.
    """
    params = given_options(args)
    named = _named_givens(args)
    if args.protocol:
        proto = load_protocol(args.protocol)
        if args.name and args.name != proto.construction:
            raise InvalidParameter(f"the protocol is of {proto.construction!r}, not {args.name!r}")
        c = find(proto.construction)
        if c is not None and not named:
            return c, c.replay(proto, **params)
        givens = dict(proto.params.get("givens", {}))
        for key, value in {**params, **named}.items():
            if key not in givens:
                raise InvalidParameter(f"the protocol {proto.construction!r} has no given {key!r}; "
                                       f"it has {', '.join(sorted(givens)) or 'none'}")
            givens[key] = value
        if c is not None:  # a book construction's givens keep its stated domain, whatever they are called
            c.validate(givens)
        return c, Figure(proto, proto.replay(givens))
    if named:
        raise InvalidParameter("--given sets the givens of a --protocol; a named construction takes its own options")
    if not args.name:
        raise InvalidParameter("name a construction (see 'construct list') or give --protocol FILE")
    c = get(args.name)
    return c, c.figure(**params)
