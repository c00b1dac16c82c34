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
    print(written(brief(name), info["steps"], info["frames"], brief(info["out"], 400), formats), file=sys.stderr)
    return 0


def written(name: str, steps: int, frames: int, out: str, formats: tuple[str, ...] = ("svg",)) -> str:
    """What a replay wrote and where to look, in one line.

    >>> written("crank", 365, 0, "out/crank")
    'crank: 365 steps written to out/crank: final.svg (every step a layer), protocol.json, animated.svg, player.html, storyboard.svg -- open out/crank/player.html to step through it'
    >>> written("crank", 365, 365, "out/crank").split(", storyboard.svg")[1]
    ' and 365 frames in steps/ -- open out/crank/player.html to step through it'
    >>> written("crank", 365, 0, "out/c", ("pdf", "tikz"))
    'crank: 365 steps, the plate written to out/c: final.pdf, final.tikz and final.tex'
    """
    plate = {"pdf": "final.pdf", "tikz": "final.tikz and final.tex"}
    printed = [plate[f] for f in formats if f in plate]
    if "svg" not in formats:
        return f"{name}: {steps} steps, the plate written to {out}: {', '.join(printed)}"
    files = ", ".join(["final.svg (every step a layer), protocol.json, animated.svg, player.html, storyboard.svg"]
                      + [f"{p} (the plate)" for p in printed])
    frames_text = f" and {frames} frame{'s' if frames != 1 else ''} in steps/" if frames else ""
    return f"{name}: {steps} steps written to {out}: {files}{frames_text} -- open {out}/player.html to step through it"
