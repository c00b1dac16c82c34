"""``construct lint PATH``: what a reader cannot read in a figure, in every view.

PATH is a ``final.svg``, a replay folder or a gallery.  Every plate and every
step's view (through the camera when the output stores one) is fitted into
the screen (``--view WxH``, default 1400x900) and checked for labels on each
other, labels on another object's point, labels struck by a result line,
labels under 9 px, a current step's mark under 12 px and labels outside the
view (:mod:`construct.regress.lint`).  Each finding names the figure, the
steps and the labels.  Exit 0 when there are none, 1 when there are, 2 on
bad input.
"""

from __future__ import annotations

import argparse
import re

from ...kernel.errors import InvalidParameter

NAME = "lint"
HELP = "check the legibility of figures: a final.svg, a replay folder or a gallery (exit 0 clean, 1 findings)"


def view_size(text: str) -> tuple[float, float]:
    """``"1400x1000"`` (or ``1400×1000``) as (width, height) in px."""
    m = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*[x×X]\s*(\d+(?:\.\d+)?)\s*", text)
    if not m or not (0 < float(m.group(1)) <= 100000 and 0 < float(m.group(2)) <= 100000):
        raise InvalidParameter(f"--view must be WIDTHxHEIGHT in px, e.g. 1400x1000, got {text!r}")
    return float(m.group(1)), float(m.group(2))


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("path", metavar="PATH", help="a final.svg, a replay folder or a gallery folder")
    parser.add_argument("--view", default="1400x900", metavar="WxH",
                        help="the screen a view is fitted into, px (default 1400x900)")
    parser.add_argument("--format", choices=("text", "json"), default="text",
                        help="text: one line per finding and a table per figure and kind; json: all of it as data")
    parser.add_argument("--summary", action="store_true", help="text: the table only, not every finding")


def run(args: argparse.Namespace) -> int:
    from ...regress.lint import lint_path

    report = lint_path(args.path, view=view_size(args.view))
    if args.format == "json":
        print(report.as_json(), end="")
    else:
        print(report.text(summary_only=args.summary), end="")
    return 0 if report.ok else 1
