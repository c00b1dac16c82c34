"""construct replay: build (or replay) a construction and write its frames."""

from __future__ import annotations

import sys

from ...render.output import FRAME_MODES, write_replay
from ..common import add_construction_options, brief, figure_from_args

NAME = "replay"
HELP = ("build a construction and write DIR/final.svg (every step a layer), DIR/protocol.json, "
        "DIR/animated.svg, DIR/player.html, DIR/storyboard.svg and, when asked, DIR/steps/NNN.svg")


def add_arguments(p) -> None:
    add_construction_options(p)
    p.add_argument("--out", required=True, metavar="DIR", help="output folder")
    p.add_argument("--style", default="plain", metavar="plain|historical|teaching", help="drawing style (default plain)")
    p.add_argument("--frames", default="none", choices=FRAME_MODES,
                   help="standalone frames besides the layered final.svg: none (default), a frame per step (all), "
                        "per group (groups); auto: all up to 1500 steps")
    p.add_argument("--force-frames", action="store_true",
                   help="(--frames) write frames even when they are estimated above 500 MB (refused with the estimate otherwise)")


def run(args) -> int:
    c, fig = figure_from_args(args)
    info = write_replay(c, fig, args.out, style=args.style, frames=args.frames, force=args.force_frames)
    name = c.name if c is not None else fig.protocol.construction
    print(f"{brief(name)}: {info['steps']} steps, {info['frames']} frames written to {brief(info['out'], 400)}",
          file=sys.stderr)
    return 0
