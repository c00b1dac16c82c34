"""Legibility of drawn figures: what a reader cannot read, in every view, read from the files.

``construct lint PATH`` (and :func:`lint_path`) checks a ``final.svg``, a
replay folder or a gallery: every plate, and every step's view of a teaching
figure (through the camera's box when the output stores one), at a stated
screen size, for

* labels on each other (or on a caption line),
* labels on another object's point marker,
* labels struck by a result line (or erasing it with their halo),
* labels smaller than 9 px, and the current step's mark smaller than 12 px,
* labels outside the view,

naming the figure, the steps and the labels.  Text extents come from the
font the drawing names (:mod:`.fonts`), not from counting characters.  The
drawing is read as the renderer wrote it (:mod:`.sheet`), never rebuilt,
so a user's own output folder is checked the same way.

>>> svg = '''<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 300 200">
... <style>.lb{font-family:'DejaVu Sans';font-size:12px;text-anchor:middle}</style>
... <text class="lb" id="a-label" x="100" y="100">K6</text><text class="lb" id="b-label" x="104" y="102">K7</text>
... </svg>'''
>>> [f.kind for f in lint_svg(svg, "demo.svg")]
['overlap']
>>> print(lint_svg(svg, "demo.svg")[0].line())
demo.svg: figure: overlap: label 'K6' (a-label) and label 'K7' (b-label) cover each other

Modules: :mod:`.fonts` (text extents), :mod:`.cascade` (the style sheet
applied), :mod:`.sheet` (a drawing read: letters, points, result lines,
steps, the camera), :mod:`.checks` (the checks over the views).
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from pathlib import Path

from .checks import KINDS, MIN_LABEL_PX, MIN_MARK_PX, VIEW, Finding, check_sheet, view_count
from .sheet import LintInputError, player_data, read_sheet

__all__ = ["lint_svg", "lint_path", "lint_file", "report_of", "FileLint", "LintReport", "Finding", "KINDS", "VIEW", "MIN_LABEL_PX", "MIN_MARK_PX",
           "LintInputError", "figure_files"]


def lint_svg(source: str | bytes | Path, name: str = "<string>", *, view: tuple[float, float] = VIEW,
             data: dict | None = None) -> list[Finding]:
    """The findings of one SVG (text, bytes or a file); *data*: its player's data (inputs, camera), if any."""
    sheet = read_sheet(source if not isinstance(source, str) or source.lstrip().startswith("<") else Path(source),
                       name, data=data)
    return check_sheet(sheet, view)


@dataclass
class LintReport:
    """The findings of every figure under a path."""

    root: str
    view: tuple[float, float]
    figures: list[str] = field(default_factory=list)
    findings: list[Finding] = field(default_factory=list)
    #: Views checked, over all figures.
    views: int = 0

    @property
    def ok(self) -> bool:
        return not self.findings

    def counts(self) -> dict[str, dict[str, int]]:
        """{figure: {kind: findings}} for every figure checked (kinds without findings left out)."""
        out: dict[str, dict[str, int]] = {f: {} for f in self.figures}
        for f in self.findings:
            kinds = out.setdefault(f.figure, {})
            kinds[f.kind] = kinds.get(f.kind, 0) + 1
        return out

    def totals(self) -> dict[str, int]:
        """{kind: findings} over all figures, every kind listed."""
        out = {k: 0 for k in KINDS}
        for f in self.findings:
            out[f.kind] = out.get(f.kind, 0) + 1
        return out

    def summary(self) -> str:
        """A table: findings per figure and kind, and the totals."""
        w, h = self.view
        head = ["figure"] + list(KINDS)
        rows = [[fig] + [str(c.get(k, 0)) for k in KINDS] for fig, c in self.counts().items()]
        rows.append(["total"] + [str(v) for v in self.totals().values()])
        width = [max(len(r[i]) for r in rows + [head]) for i in range(len(head))]
        fmt = lambda r: "  ".join(c.ljust(width[0]) if i == 0 else c.rjust(width[i]) for i, c in enumerate(r))
        lines = [fmt(head)] + [fmt(r) for r in rows]
        verdict = ("no findings" if self.ok else f"{len(self.findings)} findings")
        return "\n".join(lines + [f"lint: {verdict} in {len(self.figures)} figures, {self.views} views "
                                  f"at {w:g}×{h:g} px"])

    def text(self, *, summary_only: bool = False) -> str:
        lines = [] if summary_only else [f.line() for f in self.findings]
        return "\n".join(lines + [self.summary()]) + "\n"

    def as_json(self) -> str:
        return json.dumps({"root": self.root, "view": list(self.view), "figures": self.figures, "views": self.views,
                           "ok": self.ok, "totals": self.totals(), "counts": self.counts(),
                           "findings": [f.as_dict() for f in self.findings]},
                          indent=1, ensure_ascii=False, sort_keys=True) + "\n"


def figure_files(path: str | Path) -> list[tuple[Path, str]]:
    """The drawings lint reads under *path*, with the names it reports them by.

    A file is itself.  A folder (a replay, a gallery) gives every ``final.svg``
    in it and below, and the frames ``steps/*.svg`` beside them (reported
    together as ``steps/*.svg``: a finding over the runs of frames showing it); the
    animation, the storyboard and the player carry the same elements again
    and are not read (the player's data is: the inputs of each step and the
    camera).  Raises :class:`LintInputError` when there is nothing to read.
    """
    p = Path(path)
    if p.is_file():
        return [(p, p.name)]
    if not p.is_dir():
        what = "not a regular file or folder" if p.exists() else "no such file or folder"
        raise LintInputError(f"{what}: {str(p)!r}")
    out: list[tuple[Path, str]] = []
    for folder, dirs, files in os.walk(p):
        dirs.sort()
        here = Path(folder)
        if "final.svg" in files:
            out.append((here / "final.svg", (here / "final.svg").relative_to(p).as_posix()))
            steps = here / "steps"
            if steps.is_dir():
                out += [(f, f.relative_to(p).as_posix()) for f in sorted(steps.glob("*.svg"))]
    if not out:
        raise LintInputError(f"{str(p)!r} holds no final.svg (give a final.svg, a replay folder or a gallery)")
    return out


@dataclass(frozen=True)
class FileLint:
    """What lint found in one drawing: its findings and how many views it checked (see :func:`lint_file`)."""

    name: str
    #: A frame ``steps/NNN.svg``: its findings are merged with its folder's other frames'.
    frame: bool
    findings: tuple[Finding, ...]
    views: int


def lint_file(file: Path, name: str, *, view: tuple[float, float] = VIEW) -> FileLint:
    """Lint one drawing of :func:`figure_files` (with its player's data beside it, if any).

    The drawings under a folder can be linted one by one, anywhere (a gallery's
    figures in the processes that built them), and put together by
    :func:`report_of` as :func:`lint_path` puts them together.
    """
    data = player_data(file.parent / "player.html") if file.name == "final.svg" else None
    is_frame = file.name != "final.svg" and file.parent.name == "steps"
    sheet = read_sheet(file, name, data=data)
    return FileLint(name, is_frame, tuple(check_sheet(sheet, view)), view_count(sheet, view))


def report_of(root: str | Path, linted, *, view: tuple[float, float] = VIEW) -> LintReport:
    """The report of the drawings *linted* (:class:`FileLint`, in the order of :func:`figure_files`)."""
    report = LintReport(str(root), (float(view[0]), float(view[1])))
    frames: dict[str, dict[tuple, list[Finding]]] = {}  # a replay's frames, reported together
    for done in linted:
        name, found = done.name, done.findings
        report.views += done.views
        if not done.frame:
            report.figures.append(name)
            report.findings += found
            continue
        # the same collision in frame after frame is one finding over the runs of frames that show it
        folder = name.rsplit("/", 1)[0] if "/" in name else "steps"
        if folder not in frames:
            frames[folder] = {}
            report.figures.append(f"{folder}/*.svg")
        for f in found:
            frames[folder].setdefault((f.kind, f.ids, f.labels, f.message), []).append(f)
    for folder, groups in frames.items():
        for same in groups.values():
            runs = sorted(r for f in same for r in f.steps)
            merged: list[tuple[int, int]] = []
            for a, b in runs:
                if merged and a <= merged[-1][1] + 1:
                    merged[-1] = (merged[-1][0], max(b, merged[-1][1]))
                else:
                    merged.append((a, b))
            f = same[0]
            report.findings.append(Finding(f.kind, f"{folder}/*.svg", tuple(merged), f.labels, f.ids, f.message,
                                           sum(x.views for x in same)))
    return report


def _view_size(view: tuple[float, float]) -> tuple[float, float]:
    w, h = view
    if not (w > 0 and h > 0 and w < 1e6 and h < 1e6):
        raise LintInputError(f"the view size must be positive, got {w:g}×{h:g}")
    return (float(w), float(h))


def lint_path(path: str | Path, *, view: tuple[float, float] = VIEW,
              linted: "dict[str, FileLint] | None" = None) -> LintReport:
    """Lint every figure under *path* (a final.svg, a replay folder or a gallery).

    *linted*: drawings already linted at this view size (by :func:`lint_file`, named as
    :func:`figure_files` names them under *path*), not read again.
    """
    view = _view_size(view)
    done = linted or {}
    return report_of(path, [done.get(name) or lint_file(file, name, view=view) for file, name in figure_files(path)],
                     view=view)
