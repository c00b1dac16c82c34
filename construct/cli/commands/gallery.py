"""construct gallery: every construction at the books' parameters, in both styles, with an index."""

from __future__ import annotations

import sys

from ...gallery import build_gallery

NAME = "gallery"
HELP = "build every construction at the books' parameters in the historical and teaching styles (default gallery/)"


def add_arguments(p) -> None:
    p.add_argument("--out", default="gallery", metavar="DIR", help="output folder (default: gallery)")


def run(args) -> int:
    entries = build_gallery(args.out, progress=True)
    figures = len({(e["construction"], tuple(sorted(e["params"].items()))) for e in entries})
    files = sum(len(e["files"]) for e in entries)
    print(f"gallery: {figures} figures, {len(entries)} styled entries, {files} files written to {args.out}",
          file=sys.stderr)
    return 0
