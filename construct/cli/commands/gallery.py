"""construct gallery: every construction at the books' parameters, in both styles, with an index.

What it builds is linted (:mod:`construct.regress.lint`) before it replaces
the old gallery: the counts of findings by kind go to stderr.  With
``--legible`` a gallery with findings is not written (the previous one stays)
and the command exits 1.  Each figure is linted by the process that built it,
right after it (:func:`lint_figure`), so that the lint shares the cores with
the building; the report is the one ``construct lint`` gives for the folder.
"""

from __future__ import annotations

import sys
from pathlib import Path

from ...kernel.errors import ConstructError
from ...gallery import build_gallery

NAME = "gallery"
HELP = "build every construction at the books' parameters in the historical and teaching styles (default gallery/)"


class IllegibleGallery(ConstructError):
    """``construct gallery --legible`` found what a reader cannot read; the previous gallery was kept."""


def add_arguments(p) -> None:
    p.add_argument("--out", default="gallery", metavar="DIR", help="output folder (default: gallery)")
    from ...render.output import FORMATS

    p.add_argument("--format", default="svg", metavar="svg|pdf|tikz",
                   help=f"the plates also as {', '.join(FORMATS[1:])} at 120 mm (final.pdf; final.tikz and "
                        f"final.tex beside each historical final.svg), several joined by commas (default svg)")
    p.add_argument("--legible", action="store_true",
                   help="fail (exit 1, the previous gallery kept) when 'construct lint' finds anything in it")


def lint_figure(folder: Path) -> dict:
    """Lint one figure's drawings where it was built: {name under the gallery: its lint}."""
    from ...regress.lint import figure_files, lint_file

    return {f"{folder.name}/{name}": lint_file(file, f"{folder.name}/{name}") for file, name in figure_files(folder)}


def _lint(strict: bool):
    def check(root: Path, linted: list[dict] = ()) -> None:
        from ...regress.lint import lint_path

        # the figures linted by the processes that built them (lint_figure) are not read again; what
        # else the gallery holds is linted here, and the report is the one 'construct lint' gives
        report = lint_path(root, linted={name: done for found in linted for name, done in found.items()})
        if report.ok:
            print(f"lint: no findings in {len(report.figures)} drawings ({report.views} step views checked)",
                  file=sys.stderr)
            return
        kinds = ", ".join(f"{k} {n}" for k, n in report.totals().items() if n)
        print(f"lint: {len(report.findings)} findings in {len(report.figures)} drawings ({report.views} step views) "
              f"({kinds}); 'construct lint DIR' lists them", file=sys.stderr)
        if strict:
            raise IllegibleGallery(f"the gallery is not legible ({len(report.findings)} findings of "
                                   f"'construct lint'); the previous gallery is kept")

    return check


def _count(n: int, word: str) -> str:
    """*n* and the word, plural unless one.

    >>> _count(1, "plate"), _count(26, "figure")
    ('1 plate', '26 figures')
    """
    return f"{n} {word}{'' if n == 1 else 's'}"


def run(args) -> int:
    from ...regress.lint.fonts import load
    from ...render.output import check_formats

    check_formats([f.strip() for f in args.format.split(",")])  # refused before anything is built
    load()  # once here: the workers are forked with the fonts the lint measures with
    try:
        entries = build_gallery(args.out, progress=True, before_swap=_lint(args.legible), check=lint_figure,
                                formats=[f.strip() for f in args.format.split(",")])
    except IllegibleGallery as exc:
        print(f"construct: {exc}", file=sys.stderr)
        return 1
    figures = len({(e["construction"], tuple(sorted(e["params"].items()))) for e in entries})
    plates = sum(e.get("style") == "historical" for e in entries)
    players = len(entries) - plates
    files = sum(1 for p in Path(args.out).rglob("*") if p.is_file())  # what is on disk, index and README too
    print(f"gallery: {_count(figures, 'figure')} ({_count(plates, 'plate')}, {_count(players, 'step-by-step player')}) "
          f"in {files} files written to {args.out} -- open {Path(args.out) / 'index.html'}", file=sys.stderr)
    return 0
