"""``construct verify``: rebuild the gallery and compare every file with the committed goldens.

Every step (each figure's layered final.svg, step group by step group), the
plates, the protocols and the reports are compared through the semantic diff
(see :mod:`construct.regress.verify`); the report names the figure, the step
and the element of each change.  Exit 0 when
everything is equal, 1 when something differs, 2 on bad input.  With
``--update`` the goldens are replaced by the rebuilt tree and the report
says what changed (exit 0).
"""

from __future__ import annotations

import argparse
import math
import sys

from ...kernel.errors import InvalidParameter

NAME = "verify"
HELP = "rebuild the gallery and compare every file with the goldens (exit 0 equal, 1 different)"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from ...regress.verify import DEFAULT_TOLERANCE, MAX_CHANGES

    parser.add_argument("--out", "--gallery", dest="gallery", default="gallery", metavar="DIR",
                        help="the committed gallery whose files are the goldens, as 'construct gallery --out' "
                             "wrote it (default: gallery; --gallery is the older name)")
    parser.add_argument("--update", action="store_true",
                        help="replace the goldens by the rebuilt gallery and report what changed")
    parser.add_argument("--tolerance", type=float, default=DEFAULT_TOLERANCE, metavar="UNITS",
                        help=f"SVG differences at or below UNITS drawing units are equal (default {DEFAULT_TOLERANCE:g}: "
                             "under half of the renderer's 0.01 quantum, far above float noise)")
    parser.add_argument("--max-changes", type=int, default=MAX_CHANGES, metavar="N",
                        help=f"changes listed per file (default {MAX_CHANGES})")


def run(args: argparse.Namespace) -> int:
    from ...regress.verify import verify

    if not (math.isfinite(args.tolerance) and args.tolerance >= 0):
        raise InvalidParameter(f"--tolerance must be a finite number >= 0, got {args.tolerance!r}")
    if args.max_changes < 0:
        raise InvalidParameter(f"--max-changes must be >= 0, got {args.max_changes}")
    result = verify(args.gallery, update=args.update, tolerance=args.tolerance, progress_stream=sys.stderr)
    print(result.report(args.max_changes))
    return 0 if result.equal or args.update else 1
