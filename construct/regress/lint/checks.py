"""The checks of legibility, over every view of a sheet.

A *view* is what one screen shows: a plate is one view; a layered teaching
figure is one view per step k (steps 1..k drawn, their groups in the states
the player gives them, through the camera's box for step k when the output
stores one), the last of them the finished figure as the file has it; a
frame (``steps/NNN.svg``) is the view of its step.  A view is fitted into
the stated screen size (default 1400×1000 px), which fixes how many pixels a
user unit is.

Which elements a view shows depends only on the states of their step groups,
and each element's visible views are a few runs of steps.  So every pair of
things that could collide is found once for the whole sheet (a spatial grid,
no test of all pairs) and reported with the runs of steps in which both
are seen: the work per step does not grow with the number of steps.

=============  =====================================================================
kind           finding
=============  =====================================================================
overlap        two labels (or a label and a caption line) cover each other
on-point       a label covers the marker of a point that is not its own
struck         a result line passes through a label (or its halo erases the line)
small-label    labels smaller than 9 px on the screen
small-mark     a mark of the current step smaller than 12 px on the screen (unless a ring of
               the step around it is larger)
outside        a label (partly) outside the view
=============  =====================================================================
"""

from __future__ import annotations

import bisect
import math
from collections import defaultdict
from dataclasses import dataclass
from typing import Iterable, Iterator

from .sheet import Box, Sheet

__all__ = ["Finding", "KINDS", "check_sheet", "view_count", "MIN_LABEL_PX", "MIN_MARK_PX", "MIN_OPACITY", "VIEW"]

KINDS = ("overlap", "on-point", "struck", "small-label", "small-mark", "outside")
#: Letters smaller than this on the screen cannot be read from a seat in the classroom (px).
MIN_LABEL_PX = 9.0
#: The current step's mark must be at least this large on the screen to be seen at once (px).
MIN_MARK_PX = 12.0
#: Marks fainter than this (a finished group's faded helpers) are background: they do not collide.
MIN_OPACITY = 0.25
#: The screen a view is fitted into, px.
VIEW = (1400.0, 1000.0)
#: Overlaps thinner than this (user units) are a touch, not a collision.
TOUCH = 0.25
#: Cell of the spatial index, user units (about two letters).
CELL = 32.0

Runs = list[tuple[int, int]]


@dataclass(frozen=True, slots=True)
class Finding:
    """One thing a reader cannot read, in the views (steps) where it holds."""

    kind: str
    figure: str
    #: Runs of steps (first, last) whose views show it; () for a figure with one view (a plate).
    steps: tuple[tuple[int, int], ...]
    #: The texts concerned (labels first, then what they collide with, when that has a text).
    labels: tuple[str, ...]
    #: The ids of the elements concerned (None for an element without one).
    ids: tuple[str | None, ...]
    message: str
    #: How many views show it.
    views: int = 1

    def where(self) -> str:
        """"steps 3–9, 12" or "figure"."""
        if not self.steps:
            return "figure"
        parts = [f"{a}" if a == b else f"{a}–{b}" for a, b in self.steps]
        shown = ", ".join(parts[:6]) + (f", … ({len(parts)} runs)" if len(parts) > 6 else "")
        return ("step " if self.views == 1 else "steps ") + shown

    def line(self) -> str:
        return f"{self.figure}: {self.where()}: {self.kind}: {self.message}"

    def as_dict(self) -> dict:
        return {"kind": self.kind, "figure": self.figure, "steps": [list(r) for r in self.steps],
                "views": self.views, "labels": list(self.labels), "ids": list(self.ids), "message": self.message}


# --------------------------------------------------------------------------- runs of steps

def _merge(runs: Iterable[tuple[int, int]]) -> Runs:
    out: Runs = []
    for a, b in sorted(r for r in runs if r[0] <= r[1]):
        if out and a <= out[-1][1] + 1:
            if b > out[-1][1]:
                out[-1] = (out[-1][0], b)
        else:
            out.append((a, b))
    return out


def _both(x: Runs, y: Runs) -> Runs:
    out: Runs = []
    i = j = 0
    while i < len(x) and j < len(y):
        a, b = max(x[i][0], y[j][0]), min(x[i][1], y[j][1])
        if a <= b:
            out.append((a, b))
        if x[i][1] < y[j][1]:
            i += 1
        else:
            j += 1
    return out


def _without(x: Runs, k: int) -> Runs:
    out: Runs = []
    for a, b in x:
        if a <= k <= b:
            if a < k:
                out.append((a, k - 1))
            if k < b:
                out.append((k + 1, b))
        else:
            out.append((a, b))
    return out


def _contains(x: Runs, k: int) -> bool:
    i = bisect.bisect_right(x, (k, math.inf)) - 1
    return i >= 0 and x[i][0] <= k <= x[i][1]


def _runs(ks: Iterable[int]) -> Runs:
    return _merge((k, k) for k in ks)


def _steps_of(runs: Runs) -> Iterator[int]:
    for a, b in runs:
        yield from range(a, b + 1)


def _count(runs: Runs) -> int:
    return sum(b - a + 1 for a, b in runs)


# --------------------------------------------------------------------------- geometry

def _meet(a: Box, b: Box) -> Box | None:
    """The overlap of two boxes when it is more than a touch."""
    x0, y0, x1, y1 = max(a[0], b[0]), max(a[1], b[1]), min(a[2], b[2]), min(a[3], b[3])
    if x1 - x0 > TOUCH and y1 - y0 > TOUCH:
        return (x0, y0, x1, y1)
    return None


def _grow(b: Box, d: float) -> Box:
    return (b[0] - d, b[1] - d, b[2] + d, b[3] + d)


def _disc_in_box(x: float, y: float, r: float, b: Box) -> bool:
    nx, ny = min(max(x, b[0]), b[2]), min(max(y, b[1]), b[3])
    return math.hypot(x - nx, y - ny) < r - TOUCH


def _segment_in_box(p: tuple[float, float, float, float], b: Box) -> bool:
    """Does the segment cross the box's inside (Liang–Barsky)?"""
    x0, y0, x1, y1 = p
    dx, dy = x1 - x0, y1 - y0
    t0, t1 = 0.0, 1.0
    for q, d in ((x0 - b[0], -dx), (b[2] - x0, dx), (y0 - b[1], -dy), (b[3] - y0, dy)):
        if d == 0:
            if q < 0:
                return False
            continue
        t = q / d
        if d < 0:
            t0 = max(t0, t)
        else:
            t1 = min(t1, t)
        if t0 > t1:
            return False
    return True


class _Grid:
    """Items by the cells of :data:`CELL` their boxes cover."""

    def __init__(self) -> None:
        self.cells: dict[tuple[int, int], list[int]] = defaultdict(list)

    @staticmethod
    def keys(b: Box) -> Iterator[tuple[int, int]]:
        for i in range(math.floor(b[0] / CELL), math.floor(b[2] / CELL) + 1):
            for j in range(math.floor(b[1] / CELL), math.floor(b[3] / CELL) + 1):
                yield i, j

    def add(self, b: Box, item: int) -> None:
        for key in self.keys(b):
            self.cells[key].append(item)

    def near(self, b: Box) -> set[int]:
        out: set[int] = set()
        for key in self.keys(b):
            got = self.cells.get(key)
            if got:
                out.update(got)
        return out


# --------------------------------------------------------------------------- views

class _Views:
    """Which views a sheet has, which of them show an element, and each view's box and scale."""

    def __init__(self, sheet: Sheet, screen: tuple[float, float]):
        self.sheet = sheet
        self.screen = screen
        n = sheet.n
        self.stepped = sheet.marks_steps and sheet.frame is None and n > 1
        self.single = sheet.frame if sheet.frame is not None else n
        x, y, w, h = sheet.viewbox
        self.whole = (x, y, x + w, y + h)
        self.cameras = {k: (v[0], v[1], v[0] + v[2], v[1] + v[3]) for k, v in sheet.views.items()}
        # the steps whose objects step k is set on, turned round: in which views step s is an input
        self.input_in: dict[int, list[int]] = defaultdict(list)
        for k, ss in sheet.inputs.items():
            for s in ss:
                if s < k < n:
                    self.input_in[s].append(k)
        self._cache: dict[tuple, Runs] = {}

    def all(self) -> Runs:
        return [(1, self.sheet.n)] if self.stepped else [(self.single, self.single)]

    def box(self, k: int) -> Box:
        return self.cameras.get(k, self.whole)

    def scale(self, k: int) -> float:
        """Screen pixels per user unit in view k: the view fitted into the screen."""
        b = self.box(k)
        return min(self.screen[0] / max(b[2] - b[0], 1e-12), self.screen[1] / max(b[3] - b[1], 1e-12))

    def _seen(self, chain, state: str | None) -> bool:
        look = self.sheet.look(chain, state)
        return look.shown and look.opacity >= MIN_OPACITY

    def shown(self, chain, step: int | None) -> Runs:
        """The views (runs of steps) in which the element is seen."""
        key = (chain, step)
        got = self._cache.get(key)
        if got is not None:
            return got
        sheet, n = self.sheet, self.sheet.n
        if not self.stepped:
            got = [(self.single, self.single)] if self._seen(chain, None) else []
        elif step is None:
            got = [(1, n)] if self._seen(chain, None) else []
        else:
            s = step
            runs: Runs = []
            if s < n and self._seen(chain, "cur"):
                runs.append((s, s))
            fade = sheet.fades.get(s)
            last_old = n - 1 if fade is None else min(fade, n - 1)
            if self._seen(chain, "old"):
                runs.append((s + 1, last_old))
            if fade is not None and self._seen(chain, "done"):
                runs.append((max(fade + 1, s + 1), n - 1))
            if self._seen(chain, None):
                runs.append((n, n))
            runs = _merge(runs)
            as_input = self._seen(chain, "inp")
            for k in self.input_in.get(s, ()):
                runs = _merge(runs + [(k, k)]) if as_input else _without(runs, k)
            got = runs
        self._cache[key] = got
        return got

    def where_seen(self, runs: Runs, region: Box) -> Runs:
        """The views of *runs* whose box shows (part of) *region*."""
        if not runs:
            return []
        if not self.cameras:
            return runs if _meet_any(self.whole, region) else []
        return _runs(k for k in _steps_of(runs) if _meet_any(self.box(k), region))


def _meet_any(a: Box, b: Box) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


# --------------------------------------------------------------------------- the checks

def check_sheet(sheet: Sheet, screen: tuple[float, float] = VIEW) -> list[Finding]:
    """Every finding of every view of *sheet*, at the screen size *screen* (width, height px)."""
    views = _Views(sheet, screen)
    out: list[Finding] = []
    out += _overlaps(sheet, views)
    out += _on_points(sheet, views)
    out += _struck(sheet, views)
    out += _small_labels(sheet, views)
    out += _small_marks(sheet, views)
    out += _outside(sheet, views)
    return out


def view_count(sheet: Sheet, screen: tuple[float, float] = VIEW) -> int:
    """How many views :func:`check_sheet` checks in *sheet*."""
    return _count(_Views(sheet, screen).all())


def _finding(kind: str, sheet: Sheet, views: _Views, runs: Runs, labels, ids, message: str) -> Finding:
    steps = tuple(runs) if (views.stepped or sheet.frame is not None) else ()
    return Finding(kind, sheet.name, steps, tuple(labels), tuple(ids), message, _count(runs))


def _point_names(sheet: Sheet) -> dict[str, str]:
    """A point's letter (or, for an unlettered one, its name tag) by the point's id."""
    names = {t.owner: t.text for t in sheet.texts if t.owner and t.kind == "tag"}
    names.update({t.owner: t.text for t in sheet.texts if t.owner and t.kind == "label"})
    return names


def _overlaps(sheet: Sheet, views: _Views) -> list[Finding]:
    grid = _Grid()
    out = []
    for t in sheet.texts:
        for j in sorted(grid.near(t.box)):
            u = sheet.texts[j]
            if u.kind == "caption" and t.kind == "caption":
                continue
            region = _meet(t.box, u.box)
            if region is None:
                continue
            runs = views.where_seen(_both(views.shown(t.chain, t.step), views.shown(u.chain, u.step)), region)
            if runs:
                what = "the caption line" if u.kind == "caption" else "label"
                out.append(_finding("overlap", sheet, views, runs, (u.text, t.text), (u.ident, t.ident),
                                    f"{what} {u.name} and {'the caption line ' if t.kind == 'caption' else 'label '}"
                                    f"{t.name} cover each other"))
        grid.add(t.box, t.index)
    return out


def _on_points(sheet: Sheet, views: _Views) -> list[Finding]:
    grid = _Grid()
    for i, d in enumerate(sheet.dots):
        grid.add((d.x - d.r, d.y - d.r, d.x + d.r, d.y + d.r), i)
    names = _point_names(sheet)
    out = []
    for t in sheet.texts:
        for i in sorted(grid.near(t.box)):
            d = sheet.dots[i]
            if d.ident is not None and d.ident == t.owner:
                continue
            if not _disc_in_box(d.x, d.y, d.r, t.box):
                continue
            region = (d.x - d.r, d.y - d.r, d.x + d.r, d.y + d.r)
            runs = views.where_seen(_both(views.shown(t.chain, t.step), views.shown(d.chain, d.step)), region)
            if runs:
                point = names.get(d.ident or "", "")
                shown = f"point {point} ({d.ident})" if point else f"the point {d.ident or 'without id'}"
                out.append(_finding("on-point", sheet, views, runs, (t.text,) + ((point,) if point else ()),
                                    (t.ident, d.ident), f"{t.kind} {t.name} covers {shown}"))
    return out


def _struck(sheet: Sheet, views: _Views) -> list[Finding]:
    grid = _Grid()
    pieces: list[tuple[int, tuple[float, float, float, float]]] = []
    for si, s in enumerate(sheet.strokes):
        for p in s.pieces:
            grid.add(_grow((min(p[0], p[2]), min(p[1], p[3]), max(p[0], p[2]), max(p[1], p[3])), s.half),
                     len(pieces))
            pieces.append((si, p))
    out = []
    for t in sheet.texts:
        hit: dict[int, Box] = {}
        for i in sorted(grid.near(t.box)):
            si, p = pieces[i]
            if si in hit:
                continue
            b = _grow(t.box, sheet.strokes[si].half - TOUCH)
            if max(p[0], p[2]) < b[0] or min(p[0], p[2]) > b[2] or max(p[1], p[3]) < b[1] or min(p[1], p[3]) > b[3]:
                continue  # the cheap test first: most pieces near a label pass beside it
            if _segment_in_box(p, b):
                hit[si] = t.box
        for si in sorted(hit):
            s = sheet.strokes[si]
            runs = views.where_seen(_both(views.shown(t.chain, t.step), views.shown(s.chain, s.step)), t.box)
            if runs:
                out.append(_finding("struck", sheet, views, runs, (t.text,), (t.ident, s.ident),
                                    f"{t.kind} {t.name} is struck by the result line {s.ident or 'without id'}"))
    return out


def _small_labels(sheet: Sheet, views: _Views) -> list[Finding]:
    letters = [t for t in sheet.texts if t.kind != "caption"]
    out = []
    if not views.cameras:
        scale = views.scale(views.all()[0][0])
        by_size: dict[float, list] = defaultdict(list)
        for t in letters:
            px = t.size * scale
            if px < MIN_LABEL_PX:
                runs = views.shown(t.chain, t.step)
                if runs:
                    by_size[round(px, 1)].append((t, runs))
        for px, items in sorted(by_size.items()):
            runs = _merge(r for _, rs in items for r in rs)
            texts = sorted({t.text for t, _ in items})
            out.append(_finding("small-label", sheet, views, runs, texts, (),
                                f"{len(items)} labels at {px:g} px (< {MIN_LABEL_PX:g} px at "
                                f"{views.screen[0]:g}×{views.screen[1]:g}): {_few(texts)}"))
        return out
    # a camera: each view its own scale; the labels it shows are looked up in the grid of its box
    grid = _Grid()
    for i, t in enumerate(letters):
        grid.add(t.box, i)
    sizes = sorted({t.size for t in letters})
    found: dict[float, dict[int, list]] = defaultdict(dict)  # px -> {step: examples}
    for k in _steps_of(views.all()):
        scale = views.scale(k)
        small = {f for f in sizes if f * scale < MIN_LABEL_PX}
        if not small:
            continue
        box = views.box(k)
        seen: list = []
        for i in grid.near(box):
            t = letters[i]
            if t.size in small and _meet_any(t.box, box) and _contains(views.shown(t.chain, t.step), k):
                seen.append(t)
                if len(seen) >= 8:
                    break
        for t in seen:
            found[round(t.size * scale, 1)].setdefault(k, []).append(t.text)
    for px, per_step in sorted(found.items()):
        runs = _runs(per_step)
        texts = sorted({x for xs in per_step.values() for x in xs})
        out.append(_finding("small-label", sheet, views, runs, texts, (),
                            f"labels at {px:g} px (< {MIN_LABEL_PX:g} px at {views.screen[0]:g}×{views.screen[1]:g}), "
                            f"e.g. {_few(texts)}"))
    return out


def _small_marks(sheet: Sheet, views: _Views) -> list[Finding]:
    if not (views.stepped or (sheet.frame is not None and sheet.marks_steps)):
        return []
    by_step: dict[int, list] = defaultdict(list)
    for d in sheet.drawn:
        by_step[d.step].append(d)
    letters: dict[int, list[str]] = defaultdict(list)
    for t in sheet.texts:
        if t.step is not None and t.kind != "caption":
            letters[t.step].append(t.text)
    steps = [sheet.frame] if sheet.frame is not None else [k for k in sorted(by_step) if k < sheet.n]
    state = None if sheet.frame is not None else "cur"
    out = []
    for k in steps:
        marks: list[tuple[Box, str | None]] = []
        for d in by_step.get(k, ()):
            look = sheet.look(d.chain, state)
            if look.shown and look.opacity >= MIN_OPACITY:
                marks.append((_grow(d.box, look.stroke_width / 2 if look.stroked else 0.0), d.ident))
        if not marks:
            continue
        scale = views.scale(k)
        # each mark is seen as large as the largest of the step's marks around it (a ring round a dot)
        small = []
        for b, ident in marks:
            seen = max(max(o[2] - o[0], o[3] - o[1]) for o, _ in marks if _holds(o, b)) * scale
            if seen < MIN_MARK_PX:
                small.append((seen, ident))
        if small:
            px = min(p for p, _ in small)
            ids = tuple(i for _, i in small)
            out.append(_finding("small-mark", sheet, views, [(k, k)], tuple(letters.get(k, ())), ids,
                                f"the current step's mark{'s' if len(ids) > 1 else ''} "
                                f"({', '.join(i or '?' for i in ids)}) {'span' if len(ids) > 1 else 'spans'} "
                                f"{px:.1f} px (< {MIN_MARK_PX:g} px at {views.screen[0]:g}×{views.screen[1]:g})"))
    return out


def _holds(outer: Box, inner: Box) -> bool:
    return outer[0] <= inner[0] and outer[1] <= inner[1] and outer[2] >= inner[2] and outer[3] >= inner[3]


def _inside(b: Box, view: Box) -> bool:
    return b[0] >= view[0] and b[1] >= view[1] and b[2] <= view[2] and b[3] <= view[3]


def _outside(sheet: Sheet, views: _Views) -> list[Finding]:
    letters = [t for t in sheet.texts if t.kind != "caption"]
    out = []
    if not views.cameras:
        for t in letters:
            if _inside(t.box, views.whole):
                continue
            runs = views.shown(t.chain, t.step)
            if runs:
                out.append(_finding("outside", sheet, views, runs, (t.text,), (t.ident,),
                                    f"{t.kind} {t.name} reaches outside the view"))
        return out
    # a camera: the letters cut by the edge of each step's view, and the current step's letters it leaves out
    grid = _Grid()
    for i, t in enumerate(letters):
        grid.add(t.box, i)
    own: dict[int, list[int]] = defaultdict(list)
    for i, t in enumerate(letters):
        if t.step is not None:
            own[t.step].append(i)
    cut: dict[int, list[int]] = defaultdict(list)
    for k in _steps_of(views.all()):
        box = views.box(k)
        edges = ((box[0], box[1], box[0], box[3]), (box[2], box[1], box[2], box[3]),
                 (box[0], box[1], box[2], box[1]), (box[0], box[3], box[2], box[3]))
        near: set[int] = set(own.get(k, ()))
        for e in edges:
            near |= grid.near(e)
        for i in near:
            t = letters[i]
            if not _inside(t.box, box) and (_meet_any(t.box, box) or t.step == k) \
                    and _contains(views.shown(t.chain, t.step), k):
                cut[i].append(k)
    for i in sorted(cut):
        t = letters[i]
        out.append(_finding("outside", sheet, views, _runs(cut[i]), (t.text,), (t.ident,),
                            f"{t.kind} {t.name} reaches outside the view"))
    return out


def _few(texts: list[str], most: int = 8) -> str:
    shown = ", ".join(texts[:most])
    return shown + (f", … ({len(texts)} in all)" if len(texts) > most else "")
