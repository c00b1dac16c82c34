"""construct replay: build (or replay) a construction and write its frames."""

from __future__ import annotations

import sys

from ...render.output import FRAME_MODES, write_replay
from ..common import add_construction_options, add_print_options, brief, figure_from_args, print_request

NAME = "replay"
HELP = ("build a construction and write DIR/final.svg (every step a layer), DIR/protocol.json, "
        "DIR/animated.svg, DIR/player.html, DIR/storyboard.svg and, when asked, DIR/steps/NNN.svg; "
        "--format pdf or tikz: the plate at its final size as DIR/final.pdf or DIR/final.tikz and DIR/final.tex")


def add_arguments(p) -> None:
    add_construction_options(p)
    p.add_argument("--out", required=True, metavar="DIR", help="output folder")
    p.add_argument("--style", default="plain", metavar="plain|historical|teaching", help="drawing style (default plain)")
    p.add_argument("--frames", default="none", choices=FRAME_MODES,
                   help="standalone frames besides the layered final.svg: none (default), a frame per step (all), "
                        "per group (groups); auto: all up to 1500 steps")
    p.add_argument("--force-frames", action="store_true",
                   help="(--frames) write frames even when they are estimated above 500 MB (refused with the estimate otherwise)")
    add_print_options(p)
    p.add_argument("--live", action="store_true",
                   help="the player gets a slider for each continuous given over its domain (the rod ratio L/r, "
                        "1.05 .. 1000; the rod in metres; Baumann's kappa): the protocol swept over a grid fine enough "
                        "that the page draws within 0.5 px (takes seconds)")


def _live_page(c, fig, style: str):
    """The live data of the player (construct.live), computed before anything is written."""
    from ...live import live_givens, live_pages
    from ...kernel.errors import InvalidParameter
    from ...render.styles import STYLES

    givens = live_givens(c, fig) if c is not None else []
    if not givens or style not in STYLES:
        raise InvalidParameter(f"--live: {fig.protocol.construction} has no continuous given to move (the rod, κ)"
                               if not givens else f"unknown style {style!r}")
    return live_pages(c, fig, STYLES[style])


def run(args) -> int:
    formats, sheet = print_request(args)  # a wrong format or size is refused before anything is built
    c, fig = figure_from_args(args)
    live = _live_page(c, fig, args.style) if args.live and "svg" in formats else None
    # the live player is written with the rest of the replay, in its staging folder (and its manifest)
    info = write_replay(c, fig, args.out, style=args.style, frames=args.frames, force=args.force_frames, live=live,
                        formats=formats, sheet=sheet, paper=args.paper)
    name = c.name if c is not None else fig.protocol.construction
    made = f"{info['frames']} frames" if "svg" in formats else "the plate"
    print(f"{brief(name)}: {info['steps']} steps, {made} ({', '.join(formats)}) written to {brief(info['out'], 400)}",
          file=sys.stderr)
    return 0
