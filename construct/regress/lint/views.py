"""The views of a sheet lint checks: which steps show an element, and what each view's screen shows.

A layered teaching figure is one view per step; which of its elements a view shows depends only on the
states the player gives their step groups, so an element's visible views are a few *runs* of steps
(first, last), and :mod:`.checks` works on runs, never step by step.  :class:`Views` holds a sheet's views
(:class:`Layout`: the views that show the same box at the same scale) as the player lays them out on a
screen (:func:`player_window`, :func:`player_letter_scale`, :func:`zoom_level`).

>>> merge_runs([(5, 6), (1, 2), (3, 3)]), both_runs([(1, 4), (8, 9)], [(3, 8)]), runs_without([(1, 4)], 2)
([(1, 3), (5, 6)], [(3, 4), (8, 8)], [(1, 1), (3, 4)])
>>> runs_outside([(1, 9), (12, 14)], [(0, 1), (4, 5), (7, 12)])
[(2, 3), (6, 6), (13, 14)]
>>> in_runs([(1, 2), (5, 7)], 6), list(steps_of([(1, 2), (5, 5)])), view_total([(1, 2), (5, 7)])
(True, [1, 2, 5], 5)
"""

from __future__ import annotations

import bisect
import math
from collections import defaultdict
from dataclasses import dataclass
from typing import TYPE_CHECKING, Iterable, Iterator

from ...render.camera import PLAYER_FIGURE_PX
from .player import END_LEVEL
from .sheet import Box, Sheet

if TYPE_CHECKING:  # (numpy is imported where it is used: the annotations name it)
    import numpy as np

__all__ = ["Runs", "merge_runs", "both_runs", "runs_without", "runs_outside", "in_runs", "runs_of", "steps_of",
           "view_total", "boxes_meet", "Layout", "Views", "player_window", "player_letter_scale", "zoom_level", "MIN_OPACITY",
           "PLAYER_SIDE_PX", "PLAYER_HEIGHT", "PLAYER_ASPECT", "all_views", "stepped"]

#: Marks fainter than this (a finished group's faded helpers) are background: they do not collide.
MIN_OPACITY = 0.25

#: Runs of steps, (first, last) each, in order and apart.
Runs = list[tuple[int, int]]


# --------------------------------------------------------------------------- runs of steps

def merge_runs(runs: Iterable[tuple[int, int]]) -> Runs:
    out: Runs = []
    for a, b in sorted(runs):
        if a > b:
            continue  # (an empty run)
        if out and a <= out[-1][1] + 1:
            if b > out[-1][1]:
                out[-1] = (out[-1][0], b)
        else:
            out.append((a, b))
    return out


def both_runs(x: Runs, y: Runs) -> Runs:
    if len(x) == 1 and len(y) == 1:  # (most often: an element seen from its step on, in one view's steps)
        a, b = max(x[0][0], y[0][0]), min(x[0][1], y[0][1])
        return [(a, b)] if a <= b else []
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


def runs_without(x: Runs, k: int) -> Runs:
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


def runs_outside(x: Runs, y: Runs) -> Runs:
    """The steps of *x* that are in no run of *y* (both in order and apart), as runs."""
    out: Runs = []
    j = 0
    for a, b in x:
        while j < len(y) and y[j][1] < a:
            j += 1
        i = j
        while a <= b:
            if i >= len(y) or y[i][0] > b:
                out.append((a, b))
                break
            if y[i][0] > a:
                out.append((a, y[i][0] - 1))
            a = max(a, y[i][1] + 1)
            i += 1
    return out


def in_runs(x: Runs, k: int) -> bool:
    i = bisect.bisect_right(x, (k, math.inf)) - 1
    return i >= 0 and x[i][0] <= k <= x[i][1]


def runs_of(ks: Iterable[int]) -> Runs:
    return merge_runs((k, k) for k in ks)


def steps_of(runs: Runs) -> Iterator[int]:
    for a, b in runs:
        yield from range(a, b + 1)


def view_total(runs: Runs) -> int:
    return sum(b - a + 1 for a, b in runs)


# --------------------------------------------------------------------------- views

#: The player's page (construct.render.player's stylesheet) at the stated screen size: the page's padding
#: (2 × 16 px), the gap (12 px) and the side column (340 px, its padding 2 × 8 and border 2 × 1) take this many px
#: of the width; the figure is as wide as what is left, of the camera's window's shape (``aspect-ratio``) but at
#: most this fraction of the screen's height (``max-height:70vh``).  Measured in Chromium: 998 × 630 px at
#: 1400 × 900, 998 × 630 at 1400 × 1000, 878 × 554 at 1280 × 800.
PLAYER_SIDE_PX = 402.0
PLAYER_HEIGHT = 0.7
PLAYER_ASPECT = PLAYER_FIGURE_PX[1] / PLAYER_FIGURE_PX[0]


def player_window(screen: tuple[float, float]) -> tuple[float, float]:
    """The player's figure box (px) on a screen of *screen* px, as its page lays it out.

    >>> player_window((1400, 900)), [round(x, 1) for x in player_window((1280, 800))]
    ((998.0, 630.0), [878.0, 554.2])
    """
    w = max(screen[0] - PLAYER_SIDE_PX, 1.0)
    return (w, min(w * PLAYER_ASPECT, screen[1] * PLAYER_HEIGHT))


def player_letter_scale(q: float, zoom: float = 1.0, level_zoom: float = 1.0) -> float:
    """The player's ``--ls`` in a view of *q* user units per screen pixel magnifying *zoom* times, drawn at a
    zoom level of *level_zoom* (its script's ``put``): letters and points are drawn this many times their
    size about their points, 12 px on the screen at the level's own zoom, never below 9.5 there, and the
    same in every view of the level (the level's picture, for which the letters were placed, magnified).

    >>> player_letter_scale(2.0), player_letter_scale(1.1), player_letter_scale(0.5)
    (1.5833333333333333, 1.0, 0.5)
    >>> round(player_letter_scale(1.0, 1.4, 1.0), 4)  # the whole figure's look magnified 1.4 times
    1.1083
    """
    ql = q * zoom / level_zoom
    return min(max(1.0, 9.5 * ql / 12.0), ql)


def zoom_level(zoom: float, levels: tuple[float, ...]) -> int:
    """The player's class ``zlN`` for a view magnifying *zoom* times: the nearest level below (as its script)."""
    i = 0
    for j, z in enumerate(levels):
        if zoom >= 0.999 * z:
            i = j
    return i


@dataclass(frozen=True, slots=True)
class Layout:
    """How a run of views shows the sheet: they show the same box at the same scale."""

    runs: Runs
    #: What the screen shows (user units): the view's box, widened to the window's shape by the player.
    box: Box
    #: User units per screen pixel.
    q: float
    #: The zoom level (the player's ``zlN``), the letters' and points' scale about their points, and the
    #: factor on a line's stroke width (a non-scaling stroke in the player is as wide on every view's screen).
    level: int = 0
    letter: float = 1.0
    stroke: float = 1.0
    #: The end state's view (the last step of a figure that has one): its letters stand where it sets them.
    fin: bool = False

    @property
    def moves_key(self) -> int:
        """The key of the letter moves this layout applies (:attr:`Sheet.moves`): its level's, or the end's."""
        return END_LEVEL if self.fin else self.level


def stepped(sheet: Sheet) -> bool:
    """Whether *sheet* shows its steps one by one (a player's or a replay's final drawing), each step a view."""
    return bool(sheet.marks_steps and sheet.frame is None and sheet.n > 1 and not sheet.unplayed)


def all_views(sheet: Sheet) -> Runs:
    """The steps whose views *sheet* has (:meth:`Views.all`), known without laying the views out."""
    if stepped(sheet):
        return [(1, sheet.n)]
    single = sheet.frame if sheet.frame is not None else sheet.n
    return [(single, single)]


class Views:
    """Which views a sheet has, which of them show an element, and each view's box and scale."""

    def __init__(self, sheet: Sheet, screen: tuple[float, float]):
        self.sheet = sheet
        self.screen = screen
        n = sheet.n
        self.stepped = stepped(sheet)
        self.single = sheet.frame if sheet.frame is not None else n
        x, y, w, h = sheet.viewbox
        self.whole = (x, y, x + w, y + h)
        self.cameras = {k: (v[0], v[1], v[0] + v[2], v[1] + v[3]) for k, v in sheet.views.items()}
        #: Shown in the player: every view through its window, letters and points at the player's scale.
        self.player = sheet.player and sheet.frame is None
        # the steps whose objects step k is set on, turned round: in which views step s is an input
        self.input_in: dict[int, list[int]] = defaultdict(list)
        for k, ss in sheet.inputs.items():
            for s in ss:
                if s < k < n:
                    self.input_in[s].append(k)
        self._cache: dict[tuple, Runs] = {}
        self._states: dict[tuple, tuple[bool, ...]] = {}
        self.layouts = self._layouts()
        self._of_step: dict[int, Layout] = {}
        for lay in self.layouts:
            for k in steps_of(lay.runs):
                self._of_step[k] = lay

    def all(self) -> Runs:
        return all_views(self.sheet)

    def box(self, k: int) -> Box:
        return self.cameras.get(k, self.whole)

    def scale(self, k: int) -> float:
        """Screen pixels per user unit in view k: the view fitted into the screen (the player's window)."""
        b = self.box(k)
        if not self.player and self.sheet.width:
            # a still figure (a plate) opened in the browser is shown at its own width (a tall one scrolls),
            # narrowed to the screen
            return min(self.sheet.width, self.screen[0]) / max(self.sheet.viewbox[2], 1e-12)
        w, h = player_window(self.screen) if self.player else self.screen
        return min(w / max(b[2] - b[0], 1e-12), h / max(b[3] - b[1], 1e-12))

    def layout(self, k: int) -> Layout:
        return self._of_step[k]

    def _layouts(self) -> list[Layout]:
        everything = self.all()
        if not self.cameras or (not self.stepped and self.single not in self.cameras):
            return [Layout(everything, self.whole, 1.0 / self.scale(everything[0][0]))]
        by_box: dict[tuple, list[int]] = defaultdict(list)
        end = self.sheet.end and self.stepped
        for k in steps_of(everything):
            by_box[(self.box(k), end and k == self.sheet.n)].append(k)
        out = []
        # the whole figure the camera moves over (its widest and tallest view: the first step's is the whole
        # drawing, without the caption), and its user units per screen pixel in the window
        ww, wh = player_window(self.screen)
        cams = list(self.cameras.values())
        fw, fh = max(c[2] - c[0] for c in cams), max(c[3] - c[1] for c in cams)
        q_whole = max(fw / ww, fh / wh)
        for (b, fin), ks in by_box.items():
            q = 1.0 / self.scale(ks[0])
            if not self.player:
                out.append(Layout(runs_of(ks), b, q, fin=fin))
                continue
            # the player fits the view into its window (preserveAspectRatio meet): what shows is wider or taller
            w, h = player_window(self.screen)
            cx, cy = (b[0] + b[2]) / 2, (b[1] + b[3]) / 2
            seen = (cx - w * q / 2, cy - h * q / 2, cx + w * q / 2, cy + h * q / 2)
            zoom = q_whole / q  # how many times the window shows the view larger than the whole figure
            level = zoom_level(zoom, self.sheet.levels)
            out.append(Layout(runs_of(ks), seen, q, level, player_letter_scale(q, zoom, self.sheet.levels[level]), q,
                               fin))
        return out

    def text_box(self, t, lay: Layout) -> Box:
        """Where a letter stands in a layout: scaled (and moved at its zoom level) about its point."""
        move = self.sheet.moves.get((lay.moves_key, t.group)) if lay.moves_key and t.group else None
        if t.anchor is None or (lay.letter == 1.0 and move is None):
            return t.box
        ax, ay = t.anchor
        s = lay.letter
        dx, dy = (move[0] * t.unit, move[1] * t.unit) if move else (0.0, 0.0)
        b = t.box
        return (ax + s * (b[0] - ax + dx), ay + s * (b[1] - ay + dy), ax + s * (b[2] - ax + dx),
                ay + s * (b[3] - ay + dy))

    def _seen(self, chain, state: str | None, level: int = 0) -> bool:
        look = self.sheet.look(chain, state, level)
        return look.shown and look.opacity >= MIN_OPACITY

    def _seen_as(self, chain, level: int) -> tuple[bool, ...]:
        """Whether the element is seen with its step's groups current, old, done, as in the file and as an
        input (:meth:`_seen` in each state), worked out once per chain and level: elements that look alike
        share their chains, in every step."""
        key = (chain, level)
        got = self._states.get(key)
        if got is None:
            got = self._states[key] = tuple(self._seen(chain, state, level)
                                            for state in ("cur", "old", "done", None, "inp"))
        return got

    def shown(self, chain, step: int | None, level: int = 0) -> Runs:
        """The views (runs of steps) in which the element is seen (the drawing at zoom level *level*)."""
        level = self.sheet.level_as(chain, level)  # (the views of a level where it looks the same)
        key = (chain, step, level)
        got = self._cache.get(key)
        if got is not None:
            return got
        sheet, n = self.sheet, self.sheet.n
        if not self.stepped:
            got = [(self.single, self.single)] if self._seen(chain, None, level) else []
        elif step is None:  # outside the steps: the end state's own furniture is seen at the last step only
            got = merge_runs(([(1, n - 1)] if self._seen(chain, "", level) else [])
                         + ([(n, n)] if self._seen(chain, None, level) else []))
        else:
            s = step
            cur, old, done, filed, as_input = self._seen_as(chain, level)
            runs: Runs = []
            if s < n and cur:
                runs.append((s, s))
            fade = sheet.fades.get(s)
            last_old = n - 1 if fade is None else min(fade, n - 1)
            if old:
                runs.append((s + 1, last_old))
            if fade is not None and done:
                runs.append((max(fade + 1, s + 1), n - 1))
            if filed:
                runs.append((n, n))
            inputs = self.input_in.get(s, ())
            if as_input:  # seen in the views where its step is an input, too
                runs = merge_runs(runs + [(k, k) for k in inputs])
            else:
                runs = merge_runs(runs)
                for k in inputs:
                    runs = runs_without(runs, k)
            got = runs
        self._cache[key] = got
        return got

    def _text_arrays(self) -> tuple:
        """The texts' boxes, points and letter units as arrays (made once)."""
        got = self.__dict__.get("_arrays")
        if got is None:
            import numpy as np

            texts = self.sheet.texts
            boxes = np.array([t.box for t in texts], dtype=float).reshape(-1, 4)
            anchored = np.array([t.anchor is not None for t in texts], dtype=bool)
            points = np.array([t.anchor or (0.0, 0.0) for t in texts], dtype=float).reshape(-1, 2)
            units = np.array([t.unit for t in texts], dtype=float)
            got = self.__dict__["_arrays"] = (boxes, anchored, points, units)
        return got

    def _texts_in(self, lay: Layout, among: "np.ndarray") -> tuple[list[int], list[list[float]]]:
        """The texts of *among* (a mask) whose box in *lay* meets the layout's box (:func:`boxes_meet`), in
        order, and those boxes (:meth:`text_box`, for all texts at once: the same sums in the same order)."""
        import numpy as np

        boxes, anchored, points, units = self._text_arrays()
        texts = self.sheet.texts
        level_moves = self.__dict__.setdefault("_level_moves", {})
        key = lay.moves_key
        if key not in level_moves:  # the texts a zoom level (or the end state) moves, and by how much
            moves = self.sheet.moves
            moved = np.zeros(len(texts), dtype=bool)
            d = np.zeros((len(texts), 2))
            if key and moves:
                for i, t in enumerate(texts):
                    m = moves.get((key, t.group)) if t.group else None
                    if m is not None:
                        moved[i] = True
                        d[i] = (m[0] * t.unit, m[1] * t.unit)
            level_moves[key] = (moved, d)
        moved, d = level_moves[key]
        if lay.letter == 1.0 and not moved.any():
            b = boxes
        else:
            s = lay.letter
            at = anchored & (moved | (s != 1.0))
            scaled = np.concatenate((points + s * (boxes[:, 0:2] - points + d), points + s * (boxes[:, 2:4] - points + d)),
                                    axis=1)
            b = np.where(at[:, None], scaled, boxes)
        x0, y0, x1, y1 = lay.box
        i = np.flatnonzero(among & (b[:, 0] < x1) & (x0 < b[:, 2]) & (b[:, 1] < y1) & (y0 < b[:, 3]))
        return i.tolist(), b[i].tolist()

    def shown_all(self, items, level: int) -> tuple[list[Runs], "np.ndarray", "np.ndarray"]:
        """For each of *items* (a sheet's texts, leaders, ...: anything with a ``chain`` and a ``step``), the
        views that show it at zoom level *level* (:meth:`shown`), and the first and the last of them as two
        arrays (an item never seen: +inf, -inf), made once per level: a layout asks only the items whose
        views reach into its own."""
        import numpy as np

        store = self.__dict__.setdefault("_shown_all", {})
        key = (id(items), level)
        got = store.get(key)
        if got is None or got[0] is not items:
            runs = [self.shown(it.chain, it.step, level) for it in items]
            first = np.array([r[0][0] if r else math.inf for r in runs], dtype=float)
            last = np.array([r[-1][1] if r else -math.inf for r in runs], dtype=float)
            got = store[key] = (items, runs, first, last)
        return got[1], got[2], got[3]

    def letters(self, lay: Layout, *, captions: bool = True) -> list[tuple]:
        """The texts a layout shows: (text, its box there, the layout's steps that show it)."""
        out = []
        texts = self.sheet.texts
        shown, first, last = self.shown_all(texts, lay.level)
        skip = self.player or not captions  # the player shows no caption lines on its figure
        views = lay.runs
        for i, b in zip(*self._texts_in(lay, (first <= views[-1][1]) & (last >= views[0][0]))):
            t = texts[i]
            if skip and t.kind == "caption":
                continue
            runs = both_runs(shown[i], views)
            if runs:
                out.append((t, tuple(b), runs))
        return out


def boxes_meet(a: Box, b: Box) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]
