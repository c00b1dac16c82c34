"""The checks of legibility, over every view of a sheet.

A *view* is what one screen shows: a plate is one view; a layered teaching
figure is one view per step k (steps 1..k drawn, their groups in the states
the player gives them, through the camera's box for step k when the output
stores one), the last of them the finished figure as the file has it; a
frame (``steps/NNN.svg``) is the view of its step.  A view is fitted into
the stated screen size (default 1400×900 px, a typical window), which fixes how many pixels a
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
through, caption-lines, caption-break
               on a plate: a stroke through a letter's core, a caption too long or broken
               inside a number or a formula (:mod:`.plates`)
=============  =====================================================================
"""

from __future__ import annotations

import math
import re
from collections import defaultdict
from dataclasses import dataclass
from typing import Iterable, Iterator

from ...render.lettering import segment_meets_box
from . import plates
from .sheet import Box, Sheet
from .views import (MIN_OPACITY, Runs, Views, all_views, both_runs, boxes_meet, in_runs, merge_runs, runs_outside,
                    steps_of, view_total)

__all__ = ["Finding", "KINDS", "check_sheet", "view_count", "MIN_LABEL_PX", "MIN_MARK_PX", "MIN_OPACITY", "VIEW"]

KINDS = ("overlap", "on-point", "struck", "small-label", "small-mark", "outside", "leader", "caption-name",
         "fill") + plates.KINDS
#: Letters smaller than this on the screen cannot be read from a seat in the classroom (px).
MIN_LABEL_PX = 9.0
#: The current step's mark must be at least this large on the screen to be seen at once (px).
MIN_MARK_PX = 12.0
#: The screen a view is fitted into, px.
VIEW = (1400.0, 900.0)
#: Overlaps thinner than this (user units) are a touch, not a collision.
TOUCH = 0.25
#: A leader starts at its point and ends at its letter: each end within this many letter heights of them.
LEADER_REACH = 0.6
#: A figure whose drawing fills less than this fraction of its canvas, across or down, is mostly paper.
MIN_FILL = 0.6
#: A letter of the figure as a caption names it: one letter, a number below 20 or two digits with a prime,
#: subscripts, primes (:data:`construct.render.scene.FIGURE_LETTER`, written out here: lint reads files).
FIGURE_LETTER = re.compile(r"[A-Za-zΑ-Ωα-ω][0-9]{0,2}[′″'₀-₉]*|[0-9]{1,2}[′″']?")
#: A word of a caption that names something: a letter with digits, primes or subscripts, or a lone letter
#: (not a letter of a formula: F/f, r/L, r·cos, p(1 + tg β); not an angle's name, ∠AO5).
_NAMED = re.compile(r"(?<![\w′'″₀-₉./·∠])([A-Za-zΑ-Ωα-ω][A-Za-zΑ-Ωα-ω0-9₀-₉∞]*[′'″]*)(?![\w′'″₀-₉/·∞(])")
#: An internal name: letters and digits run together the way no figure letters them (c135, cPV10, to42a, t110).
_INTERNAL = re.compile(r"[A-Za-z]+[0-9]+[A-Za-z0-9]*|[a-z]+[A-Z][A-Za-z0-9]*")
#: Cell of the spatial index, user units (about two letters).
CELL = 32.0

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


# --------------------------------------------------------------------------- geometry

def _meet(a: Box, b: Box) -> Box | None:
    """The overlap of two boxes when it is more than a touch."""
    x0, y0, x1, y1 = max(a[0], b[0]), max(a[1], b[1]), min(a[2], b[2]), min(a[3], b[3])
    if x1 - x0 > TOUCH and y1 - y0 > TOUCH:
        return (x0, y0, x1, y1)
    return None


def _grow(b: Box, d: float) -> Box:
    return (b[0] - d, b[1] - d, b[2] + d, b[3] + d)


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


# --------------------------------------------------------------------------- the checks

def check_sheet(sheet: Sheet, screen: tuple[float, float] = VIEW) -> list[Finding]:
    """Every finding of every view of *sheet*, at the screen size *screen* (width, height px)."""
    views = Views(sheet, screen)
    seen = [(lay, views.letters(lay)) for lay in views.layouts]
    out: list[Finding] = []
    out += _overlaps(sheet, views, seen)
    out += _on_points(sheet, views, seen)
    out += _struck(sheet, views, seen)
    out += _small_labels(sheet, views, seen)
    out += _small_marks(sheet, views)
    out += _outside(sheet, views, seen)
    out += _leaders(sheet, views)
    out += _caption_names(sheet, views, seen)
    out += _fill(sheet, views)
    out += plates.check_plate(sheet, lambda kind, labels, ids, message: _finding(kind, sheet, views, views.all(),
                                                                                 labels, ids, message))
    return out


def view_count(sheet: Sheet, screen: tuple[float, float] = VIEW) -> int:
    """How many views :func:`check_sheet` checks in *sheet*."""
    return view_total(all_views(sheet))  # (which views, not how each is laid out at *screen*)


def _finding(kind: str, sheet: Sheet, views: Views, runs: Runs, labels, ids, message: str) -> Finding:
    steps = tuple(runs) if (views.stepped or sheet.frame is not None) else ()
    return Finding(kind, sheet.name, steps, tuple(labels), tuple(ids), message, view_total(runs))


def _point_names(sheet: Sheet) -> dict[str, str]:
    """A point's letter (or, for an unlettered one, its name tag) by the point's id."""
    names = {t.owner: t.text for t in sheet.texts if t.owner and t.kind == "tag"}
    names.update({t.owner: t.text for t in sheet.texts if t.owner and t.kind == "label"})
    return names


def _overlaps(sheet: Sheet, views: Views, seen) -> list[Finding]:
    found: dict[tuple[int, int], list] = {}
    for lay, letters in seen:
        grid = _Grid()
        for j, (t, b, runs) in enumerate(letters):
            for i in sorted(grid.near(b)):
                u, ub, uruns = letters[i]
                if u.kind == "caption" and t.kind == "caption":
                    continue
                region = _meet(b, ub)
                if region is None or not boxes_meet(region, lay.box):
                    continue
                both = both_runs(runs, uruns)
                if both:
                    found.setdefault((u.index, t.index), []).extend(both)
            grid.add(b, j)
    out = []
    for (ui, ti), runs in sorted(found.items()):
        u, t = sheet.texts[ui], sheet.texts[ti]
        what = "the caption line" if u.kind == "caption" else "label"
        out.append(_finding("overlap", sheet, views, merge_runs(runs), (u.text, t.text), (u.ident, t.ident),
                            f"{what} {u.name} and {'the caption line ' if t.kind == 'caption' else 'label '}"
                            f"{t.name} cover each other"))
    return out


def _on_points(sheet: Sheet, views: Views, seen) -> list[Finding]:
    grid = _Grid()
    for i, d in enumerate(sheet.dots):
        grid.add((d.x - d.r, d.y - d.r, d.x + d.r, d.y + d.r), i)
    names = _point_names(sheet)
    widest = max((d.r for d in sheet.dots), default=0.0)
    found: dict[tuple[int, int], list] = {}
    cells, dots, floor, hypot = grid.cells, sheet.dots, math.floor, math.hypot
    # a letter stands in the same box at the same scale in many views (those of a zoom level): the discs that
    # reach into it are found once per box and scale, and each view asks only whether it shows them
    reaching: dict[tuple, list[int]] = {}
    for lay, letters in seen:
        reach = widest * max(lay.letter - 1.0, 0.0)  # the grid holds the discs at their drawn size
        letter = lay.letter
        for t, b, runs in letters:
            hits = reaching.get((t.index, b, letter))
            if hits is None:
                hits = reaching[(t.index, b, letter)] = []
                g = _grow(b, reach) if reach else b
                near: set[int] = set()
                for ci in range(floor(g[0] / CELL), floor(g[2] / CELL) + 1):  # grid.near(g), written out
                    for cj in range(floor(g[1] / CELL), floor(g[3] / CELL) + 1):
                        got = cells.get((ci, cj))
                        if got:
                            near.update(got)
                owner = t.owner
                for i in sorted(near):
                    d = dots[i]
                    if d.ident is not None and d.ident == owner:
                        continue
                    r = d.r * letter
                    x, y = d.x, d.y
                    # does the disc reach into the box (from the box's nearest point to its centre)?
                    if hypot(x - min(max(x, b[0]), b[2]), y - min(max(y, b[1]), b[3])) < r - TOUCH:
                        hits.append(i)
            for i in hits:
                d = dots[i]
                r = d.r * letter
                if not boxes_meet((d.x - r, d.y - r, d.x + r, d.y + r), lay.box):
                    continue
                both = both_runs(runs, views.shown(d.chain, d.step, lay.level))
                if both:
                    found.setdefault((t.index, i), []).extend(both)
    out = []
    for (ti, i), runs in sorted(found.items()):
        t, d = sheet.texts[ti], sheet.dots[i]
        point = names.get(d.ident or "", "")
        shown = f"point {point} ({d.ident})" if point else f"the point {d.ident or 'without id'}"
        out.append(_finding("on-point", sheet, views, merge_runs(runs), (t.text,) + ((point,) if point else ()),
                            (t.ident, d.ident), f"{t.kind} {t.name} covers {shown}"))
    return out


def _piece_cells(boxes: list[Box]) -> dict[tuple[int, int], list[int]]:
    """The cells of :data:`CELL` (as :meth:`_Grid.keys` gives them) each box covers: {cell: box numbers}.

    Made with numpy for the boxes that cover at most two cells each way (every piece of a result line,
    at most :data:`sheet.PIECE` long), one by one for the others; a cell lists its boxes in order.
    """
    import numpy as np

    cells: dict[tuple[int, int], list[int]] = defaultdict(list)
    if not boxes:
        return cells
    b = np.array(boxes, dtype=float).reshape(-1, 4)
    i0, j0 = np.floor(b[:, 0] / CELL).astype(np.int64), np.floor(b[:, 1] / CELL).astype(np.int64)
    i1, j1 = np.floor(b[:, 2] / CELL).astype(np.int64), np.floor(b[:, 3] / CELL).astype(np.int64)
    small = (i1 - i0 <= 1) & (j1 - j0 <= 1)
    ks, ii, jj = [], [], []
    for di in (0, 1):
        for dj in (0, 1):
            m = small & (i0 + di <= i1) & (j0 + dj <= j1)
            ks.append(np.flatnonzero(m))
            ii.append(i0[m] + di)
            jj.append(j0[m] + dj)
    k, i, j = np.concatenate(ks), np.concatenate(ii), np.concatenate(jj)
    order = np.lexsort((k, j, i))
    k, i, j = k[order], i[order], j[order]
    if len(k):
        cut = (np.flatnonzero((np.diff(i) != 0) | (np.diff(j) != 0)) + 1).tolist()
        starts, ends = [0] + cut, cut + [len(k)]
        listed = k.tolist()
        for s0, s1, ci, cj in zip(starts, ends, i[starts].tolist(), j[starts].tolist()):
            cells[(ci, cj)] = listed[s0:s1]
    for n in np.flatnonzero(~small).tolist():  # a long box, cell by cell
        for key in _Grid.keys(boxes[n]):
            cells[key].append(n)
    return cells


#: Letter boxes times result-line pieces up to which :func:`_struck` asks each box of all pieces at once (numpy),
#: rather than filing the pieces in a grid.
_ALL_AT_ONCE = 1 << 22


def _struck(sheet: Sheet, views: Views, seen) -> list[Finding]:
    import numpy as np

    keys = list(dict.fromkeys((t.index, tb) for _, letters in seen for t, tb, _ in letters))
    if not keys or not sheet.strokes:
        return []
    halves = [s.half for s in sheet.strokes]
    flat = [p for s in sheet.strokes for p in s.pieces]
    a = np.array(flat, dtype=float).reshape(-1, 4)
    owner = np.repeat(np.arange(len(sheet.strokes)), [len(s.pieces) for s in sheet.strokes])
    lo, hi = np.minimum(a[:, 0:2], a[:, 2:4]), np.maximum(a[:, 0:2], a[:, 2:4])
    # A letter stands in the same box in many views (those of a zoom level): the pieces that strike it at the
    # widest stroke of any view are found once per box, and only they are tested in each view at its own stroke
    # (a piece that misses the box grown by the widest stroke misses it grown by less): {(text, box): [(line,
    # piece, its box), ...]}.
    most = max((lay.stroke for lay, _ in seen), default=1.0)
    reach = np.array(halves) * most - TOUCH
    candidates: dict[tuple, list] = {}

    def strike(key: tuple, near: Iterable[int], boxes: Iterable) -> None:
        tb = key[1]
        got = candidates[key] = []
        for i, pb in zip(near, boxes):
            si, p = owners[i], flat[i]
            d = halves[si] * most - TOUCH
            b = (tb[0] - d, tb[1] - d, tb[2] + d, tb[3] + d)
            if not (pb[2] < b[0] or pb[0] > b[2] or pb[3] < b[1] or pb[1] > b[3]) and segment_meets_box(b, p):
                got.append((si, p, pb))

    owners = owner.tolist()
    if len(keys) * len(flat) <= _ALL_AT_ONCE:
        # few letters (a plate's dozens over its tens of thousands of pieces): each box asks all pieces at once
        d = reach[owner]
        for key in keys:
            tb = key[1]
            near = np.flatnonzero(~((hi[:, 0] < tb[0] - d) | (lo[:, 0] > tb[2] + d) | (hi[:, 1] < tb[1] - d)
                                    | (lo[:, 1] > tb[3] + d)))
            strike(key, near.tolist(), np.concatenate((lo[near], hi[near]), axis=1).tolist())
    else:
        # many: the grid of :class:`_Grid` (its cells and keys), written out here
        boxes = np.concatenate((lo, hi), axis=1).tolist()
        cells = _piece_cells(boxes)
        r, floor = max(halves) * most, math.floor
        for key in keys:
            tb = key[1]
            got_near: set[int] = set()
            for i in range(floor((tb[0] - r) / CELL), floor((tb[2] + r) / CELL) + 1):
                for j in range(floor((tb[1] - r) / CELL), floor((tb[3] + r) / CELL) + 1):
                    cell = cells.get((i, j))
                    if cell:
                        got_near.update(cell)
            near = sorted(got_near)
            strike(key, near, [boxes[i] for i in near])
    found: dict[tuple[int, int], list] = {}
    for lay, letters in seen:
        stroke = lay.stroke
        for t, tb, runs in letters:
            near = candidates[(t.index, tb)]
            if not near:
                continue
            hit: set[int] = set()
            for si, p, pb in near:
                if si in hit:
                    continue
                d = halves[si] * stroke - TOUCH
                b = (tb[0] - d, tb[1] - d, tb[2] + d, tb[3] + d)
                if pb[2] < b[0] or pb[0] > b[2] or pb[3] < b[1] or pb[1] > b[3]:
                    continue  # the cheap test first: most pieces near a label pass beside it
                if segment_meets_box(b, p):
                    hit.add(si)
            for si in sorted(hit):
                s = sheet.strokes[si]
                both = both_runs(runs, views.shown(s.chain, s.step, lay.level))
                if both:
                    found.setdefault((t.index, si), []).extend(both)
    out = []
    for (ti, si), runs in sorted(found.items()):
        t, s = sheet.texts[ti], sheet.strokes[si]
        out.append(_finding("struck", sheet, views, merge_runs(runs), (t.text,), (t.ident, s.ident),
                            f"{t.kind} {t.name} is struck by the result line {s.ident or 'without id'}"))
    return out


def _small_labels(sheet: Sheet, views: Views, seen) -> list[Finding]:
    found: dict[float, tuple[list, set]] = {}
    for lay, letters in seen:
        for t, b, runs in letters:
            if t.kind == "caption":
                continue
            # a letter about its point is drawn at the player's letter scale; lettering set on the sheet is not
            px = t.size * (lay.letter if t.anchor is not None else 1.0) / lay.q
            if px < MIN_LABEL_PX:
                rs, texts = found.setdefault(round(px, 1), ([], set()))
                rs.extend(runs)
                texts.add(t.text)
    out = []
    for px, (runs, texts) in sorted(found.items()):
        names = sorted(texts)
        out.append(_finding("small-label", sheet, views, merge_runs(runs), names, (),
                            f"labels at {px:g} px (< {MIN_LABEL_PX:g} px at {views.screen[0]:g}×{views.screen[1]:g}), "
                            f"e.g. {_few(names)}"))
    return out


def _small_marks(sheet: Sheet, views: Views) -> list[Finding]:
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
        lay = views.layout(k)
        marks: list[tuple[Box, str | None]] = []
        for d in by_step.get(k, ()):
            look = sheet.look(d.chain, state, lay.level)
            if look.shown and look.opacity >= MIN_OPACITY:
                b = d.box
                point = "pt" in d.chain[-1][2]
                if lay.letter != 1.0 and point:  # the player draws points (and their strokes) at the letters' scale
                    cx, cy, r = (b[0] + b[2]) / 2, (b[1] + b[3]) / 2, (b[2] - b[0]) / 2 * lay.letter
                    b = (cx - r, cy - r, cx + r, cy + r)
                width = look.stroke_width * (lay.letter if point else lay.stroke)
                marks.append((_grow(b, width / 2 if look.stroked else 0.0), d.ident))
        if not marks:
            continue
        ring = sheet.rings.get(k) if views.player else None
        if ring is not None:  # the player's ring round the step's mark, at least 9 px in radius (its put)
            cx, cy, r = ring
            r = max(r, 9.0 * lay.q)
            marks.append(((cx - r, cy - r, cx + r, cy + r), "ring"))
        scale = 1.0 / lay.q
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


def _outside(sheet: Sheet, views: Views, seen) -> list[Finding]:
    found: dict[int, list] = defaultdict(list)
    for lay, letters in seen:
        for t, b, runs in letters:
            if t.kind != "caption" and not _inside(b, lay.box):
                found[t.index].extend(runs)
    if views.cameras:
        # the current step's own letters a view leaves out altogether
        own: dict[int, list] = defaultdict(list)
        for t in sheet.texts:
            if t.step is not None and t.kind != "caption":
                own[t.step].append(t)
        for k, ts in own.items():
            if k not in views._of_step:
                continue
            lay = views.layout(k)
            for t in ts:
                b = views.text_box(t, lay)
                if not boxes_meet(b, lay.box) and in_runs(views.shown(t.chain, t.step, lay.level), k):
                    found[t.index].append((k, k))
    out = []
    for i in sorted(found):
        t = sheet.texts[i]
        out.append(_finding("outside", sheet, views, merge_runs(found[i]), (t.text,), (t.ident,),
                            f"{t.kind} {t.name} reaches outside the view"))
    return out


def _few(texts: list[str], most: int = 8) -> str:
    shown = ", ".join(texts[:most])
    return shown + (f", … ({len(texts)} in all)" if len(texts) > most else "")


def _leaders(sheet: Sheet, views: Views) -> list[Finding]:
    """A leader must start at its point (drawn in that view) and end at its letter, in every view that shows it."""
    if not sheet.leaders:
        return []
    import numpy as np

    letters: dict[int, list] = defaultdict(list)
    for t in sheet.texts:
        if t.lbg is not None and t.kind != "caption":
            letters[t.lbg].append(t)
    dots: dict[tuple[float, float], list] = defaultdict(list)
    for d in sheet.dots:
        dots[(round(d.x), round(d.y))].append(d)
    found: dict[tuple[int, str], list] = defaultdict(list)
    anchors = np.array([ld.anchor for ld in sheet.leaders], dtype=float).reshape(-1, 2)
    marked: dict[tuple[int, int], Runs] = {}  # the views that draw a leader's point, by (leader, zoom level)
    for lay in views.layouts:
        x0, y0, x1, y1 = lay.box
        # the leaders whose point the layout's box holds and whose views reach into the layout's, in order
        shown, first, last = views.shown_all(sheet.leaders, lay.level)
        ax_, ay_ = anchors[:, 0], anchors[:, 1]
        for i in np.flatnonzero((x0 <= ax_) & (ax_ <= x1) & (y0 <= ay_) & (ay_ <= y1) & (first <= lay.runs[-1][1])
                                & (last >= lay.runs[0][0])).tolist():
            ld = sheet.leaders[i]
            ax, ay = ld.anchor
            runs = both_runs(shown[i], lay.runs)
            if not runs or not letters.get(ld.lbg):
                continue
            t = letters[ld.lbg][0]
            s, u = lay.letter, ld.unit
            dx, dy = (sheet.moves.get((lay.moves_key, ld.group), (0.0, 0.0))
                      if ld.group and (lay.moves_key, ld.group) in sheet.moved_leaders else (0.0, 0.0))
            a = (ax + s * u * (ld.line[0] + dx), ay + s * u * (ld.line[1] + dy))
            b = (ax + s * u * (ld.line[2] + dx), ay + s * u * (ld.line[3] + dy))
            reach = LEADER_REACH * t.size * s
            if math.hypot(a[0] - ax, a[1] - ay) > reach:
                found[(i, "point")].extend(runs)
            tb = views.text_box(t, lay)
            if math.hypot(b[0] - min(max(b[0], tb[0]), tb[2]), b[1] - min(max(b[1], tb[1]), tb[3])) > reach:
                found[(i, "letter")].extend(runs)
            # its point is drawn there: a marker at the anchor, seen in the same views (those of a zoom level alike)
            seen = marked.get((i, lay.level))
            if seen is None:
                seen = marked[(i, lay.level)] = merge_runs(
                    r for d in dots.get((round(ax), round(ay)), ())
                    if math.hypot(d.x - ax, d.y - ay) <= 1.0 for r in views.shown(d.chain, d.step, lay.level))
            hidden = runs_outside(runs, seen)
            if hidden:
                found[(i, "hidden")].extend(hidden)
    out = []
    what = {"point": "starts away from its point", "letter": "ends away from its letter",
            "hidden": "points at a point the view does not draw"}
    for (i, why), runs in sorted(found.items()):
        ld = sheet.leaders[i]
        t = letters[ld.lbg][0]
        out.append(_finding("leader", sheet, views, merge_runs(runs), (t.text,), (ld.ident or t.ident,),
                            f"the leader of {t.kind} {t.name} {what[why]}"))
    return out


def _caption_names(sheet: Sheet, views: Views, seen) -> list[Finding]:
    """A step's caption names only letters its view shows, and never an internal name (c135, cPV10).

    A name the figure letters somewhere (a letter or a name tag) must be seen in the step's view; a name no
    letter of the figure carries is a quantity of the caption (s1, P0) unless it is written the way no figure
    letters a point (letters and digits run together: an object's internal name); a point named before the
    step that makes it is what the group sets out to make.  The German caption and
    the title of the step's own group (the last of the group path) are read whole; in the English one a lone
    "a" is the article.
    """
    if not sheet.captions or not views.stepped:
        return []
    # the letters of points (a lettered line's letter, r or L, stands at a point of its own that is never
    # drawn: in a caption it is a length)
    drawn = {d.ident for d in sheet.dots if d.ident and sheet.look(d.chain).shown}
    lettered: dict[str, int] = {}  # a point's letter: from the step that makes the point on
    for t in sheet.texts:
        if t.kind == "tag" or (t.kind == "label" and t.owner in drawn):
            lettered[t.text] = min(lettered.get(t.text, sheet.n + 1), t.step or 0)
    shown: dict[int, set[str]] = defaultdict(set)
    for lay, letters in seen:
        for t, _b, runs in letters:
            if t.kind != "caption":
                for k in steps_of(runs):
                    shown[k].add(t.text)
    found: dict[tuple[str, str], list] = defaultdict(list)
    for k, texts in sheet.captions.items():
        for j, text in enumerate(texts):
            if j == 2:
                text = text.rsplit(" › ", 1)[-1]  # the step's own group; the path above it names its stage
            for name in dict.fromkeys(_NAMED.findall(text)):
                if j == 1 and name == "a":
                    continue
                if name in lettered:
                    # (a point named before it is made is the group's goal: "Hyperbelpunkt U5 durch …")
                    if lettered[name] <= k and name not in shown.get(k, ()):
                        found[(name, "unlettered")].append((k, k))
                elif _INTERNAL.fullmatch(name) and not FIGURE_LETTER.fullmatch(name):
                    found[(name, "internal")].append((k, k))
    out = []
    for (name, why), runs in sorted(found.items()):
        msg = (f"the caption names {name!r}, which the step's view does not letter" if why == "unlettered" else
               f"the caption names {name!r}, an internal name the figure does not letter")
        out.append(_finding("caption-name", sheet, views, merge_runs(runs), (name,), (), msg))
    return out


def _fill(sheet: Sheet, views: Views) -> list[Finding]:
    """A figure's drawing fills its canvas: at least :data:`MIN_FILL` of its width and of its height (the
    caption lines aside), as the file shows it."""
    if sheet.frame is not None or not sheet.inked:
        return []
    box = None
    for chain, b in sheet.inked:
        look = sheet.look(chain)
        if look.shown and look.opacity >= MIN_OPACITY:
            box = b if box is None else (min(box[0], b[0]), min(box[1], b[1]), max(box[2], b[2]), max(box[3], b[3]))
    for t in sheet.texts:
        if t.kind != "caption" and sheet.look(t.chain).shown:
            b = t.box
            box = b if box is None else (min(box[0], b[0]), min(box[1], b[1]), max(box[2], b[2]), max(box[3], b[3]))
    if box is None:
        return []
    x, y, w, h = sheet.viewbox
    caps = [t.box[1] for t in sheet.texts if t.kind == "caption" and t.box[1] > box[1]]
    bottom = min([y + h] + caps)
    # what lies on the canvas
    bx0, by0, bx1, by1 = max(box[0], x), max(box[1], y), min(box[2], x + w), min(box[3], bottom)
    across, down = max(bx1 - bx0, 0.0) / w, max(by1 - by0, 0.0) / max(bottom - y, 1e-9)
    if across >= MIN_FILL and down >= MIN_FILL:
        return []
    return [_finding("fill", sheet, views, [(sheet.n, sheet.n)] if views.stepped else [], (), (),
                     f"the drawing fills {across:.0%} of the canvas's width and {down:.0%} of its height "
                     f"(the caption aside; < {MIN_FILL:.0%}): crop the canvas to the drawing")]
