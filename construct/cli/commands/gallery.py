"""construct gallery: every construction at the books' parameters, in both styles, with an index."""

from __future__ import annotations

import sys
from pathlib import Path

from ...gallery import build_gallery

NAME = "gallery"
HELP = "build every construction at the books' parameters in the historical and teaching styles (default gallery/)"


def add_arguments(p) -> None:
    p.add_argument("--out", default="gallery", metavar="DIR", help="output folder (default: gallery)")


def run(args) -> int:
    entries = build_gallery(args.out, progress=True)
    figures = len({(e["construction"], tuple(sorted(e["params"].items()))) for e in entries})
    files = sum(1 for p in Path(args.out).rglob("*") if p.is_file())  # what is on disk, index and README too
    print(f"gallery: {figures} figures, {len(entries)} styled entries, {files} files written to {args.out}",
          file=sys.stderr)
    return 0
