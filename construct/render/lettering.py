"""Where the letters go: one placement pass over all letters, results first, helpers give way.

A plate's letters are not all equal.  The piston positions 1′…17′, the
characteristic points q1…q7, the crank positions of a crank-angle plate are
what the figure is for; a helper's name is a convenience.  Letters are
placed in order of that rank (results, then givens, then the rest; within a
rank by step), each at the first free spot of a ring of candidates around
its point (twelve directions, five distances, nearest first, starting
radially outwards from the crank centre; from :data:`LEADER_FROM` letter
heights on the renderer ties the letter to its point by a leader line).  A
spot is free when its box meets no placed letter, no point marker and no
result line (a halo may cover thin helpers, never a result line or a point).
A letter that finds no free spot is not stacked on another: a result's or a
given's letter is kept for the magnified views (``thin``: the whole figure
leaves it out, so a dense family 1′…17′ shows every other letter), a
helper's is left out.  Boxes come from the font's real metrics
(:func:`text_box`: matplotlib's FreeType with the font the SVG names).
Collisions are looked up in a grid of cells one letter high, so the work
grows with the number of letters, not with its square.

>>> spots = place([("a", "result", 1, (100.0, 100.0), (1.0, 0.0), "q1"),
...                ("b", "construction", 2, (104.0, 100.0), (1.0, 0.0), "M1"),
...                ("c", "result", 3, (108.0, 100.0), (1.0, 0.0), "q2")], 12.0)
>>> "a" in spots and "c" in spots      # both results placed; the helper moved or gave way
True
>>> crowded = [(f"h{i}", "construction", i, (100.0, 100.0), (1.0, 0.0), "M1") for i in range(40)]
>>> len(place(crowded + [("q", "result", 99, (100.0, 100.0), (1.0, 0.0), "q7")], 12.0)) < 41  # helpers dropped
True
"""

from __future__ import annotations

import functools
import math
import os
from typing import Any, Iterable, Sequence

import numpy as np

__all__ = ["place", "spots_of", "spots_extent", "lines_near", "LineIndex", "label_box", "text_box", "text_width", "segment_meets_box", "clipped_segment", "RANK", "LEADER_FROM",
           "DEFAULT_FONT", "line_pieces", "line_pieces_one_by_one", "near_rows"]

#: Rank of a role: lower is placed first.
RANK = {"result": 0, "given": 1}

#: Directions tried, as turns from the preferred one (degrees), and distances in letter heights.
_TURNS = (0, 30, -30, 60, -60, 90, -90, 120, -120, 150, -150, 180)
#: On the farther rings (place's *distances*) the directions lie twice as close: a ring there is long.
_TURNS_FAR = (0,) + tuple(t for a in range(15, 180, 15) for t in (a, -a)) + (180,)
_DISTANCES = (0.9, 1.45, 2.1, 2.8, 3.6)
#: From this distance (letter heights) on, a letter is tied to its point by a leader line.
LEADER_FROM = 2.0
#: A cell of the collision grid holding more boxes than this is asked with numpy, all its boxes at once.
_CROWD = 128
#: Width of the paper-coloured halo drawn beneath every letter (styles.Style.css: stroke-width 3.5px).
HALO_PX = 3.5
#: The font a letter is measured in when none is named (the teaching style's).
DEFAULT_FONT = "'DejaVu Sans', Arial, sans-serif"

_SHIPPED = {("DejaVu Sans", False): "DejaVuSans.ttf", ("DejaVu Sans", True): "DejaVuSans-Oblique.ttf",
            ("DejaVu Serif", False): "DejaVuSerif.ttf", ("DejaVu Serif", True): "DejaVuSerif-Italic.ttf"}
_GENERIC = {"serif": "DejaVu Serif", "sans-serif": "DejaVu Sans", "monospace": "DejaVu Sans Mono"}


@functools.lru_cache(maxsize=16)
def _face(font: str, italic: bool) -> Any:
    """The FreeType face of the first family of the CSS *font* list matplotlib has (DejaVu at worst)."""
    from matplotlib import ft2font

    path = None
    for name in [n.strip().strip("'\"") for n in font.split(",")] + ["DejaVu Sans"]:
        name = _GENERIC.get(name, name)
        shipped = _SHIPPED.get((name, italic))
        if shipped:  # the DejaVu faces matplotlib ships: no font manager (its font list) needed
            import matplotlib

            path = os.path.join(matplotlib.get_data_path(), "fonts", "ttf", shipped)
            break
        from matplotlib import font_manager

        try:
            path = font_manager.findfont(font_manager.FontProperties(family=name, style="italic" if italic else "normal"),
                                         fallback_to_default=False)
            break
        except ValueError:
            continue
    face = ft2font.FT2Font(path)
    face.set_size(100.0, 72)  # 100 px to the em
    return face


@functools.lru_cache(maxsize=4096)
def _glyph(font: str, italic: bool, char: str) -> tuple[float, float, float, float, float]:
    """(advance, top, bottom, left, right) of one character in em, y up, left and right of its ink from
    the pen (cached: a figure has few distinct characters)."""
    from matplotlib import ft2font

    face = _face(font, italic)
    flags = getattr(getattr(ft2font, "LoadFlags", None), "NO_HINTING", None)
    if flags is None:
        flags = ft2font.LOAD_NO_HINTING
    g = face.load_char(ord(char), flags=flags)
    x0, y0, x1, y1 = g.bbox  # 26.6 fixed point at 100 px
    return g.linearHoriAdvance / 65536.0 / 100.0, y1 / 6400.0, y0 / 6400.0, x0 / 6400.0, x1 / 6400.0


@functools.lru_cache(maxsize=65536)
def _metrics(text: str, font: str, italic: bool) -> tuple[float, float, float, float, float]:
    """(advance, top, bottom, left, right) of *text* in em: left and right the reach of its ink or its
    advance, whichever is wider (an italic letter leans out of its advance); a figure's letters recur,
    each is measured once."""
    glyphs = [_glyph(font, italic, c) for c in text]
    adv = sum(g[0] for g in glyphs)
    left, right, pen = 0.0, adv, 0.0
    for g in glyphs:
        if g[4] > g[3]:  # a glyph with ink
            left, right = min(left, pen + g[3]), max(right, pen + g[4])
        pen += g[0]
    return (adv, max((g[1] for g in glyphs), default=0.7), min(min((g[2] for g in glyphs), default=0.0), 0.0),
            left, right)


def text_width(text: str, size: float, font: str = DEFAULT_FONT, italic: bool = False) -> float:
    """The advance width of *text* at *size* px in the font's real metrics.

    DejaVu Sans advances (its hmtx table, 2048 units to the em): K 1343, every digit 1303.

    >>> round(text_width("K17", 12.0), 3) == round(12.0 * (1343 + 2 * 1303) / 2048, 3)
    True
    """
    return size * _metrics(text, font, italic)[0]


def text_box(x: float, y: float, text: str, size: float, font: str = DEFAULT_FONT, italic: bool = False,
             anchor: str = "middle") -> tuple[float, float, float, float]:
    """The box (pixels, y down) the inked *text* covers when set at baseline (x, y) with *anchor*."""
    adv, top, bottom, left, right = _metrics(text, font, italic)
    w = size * adv
    x0 = x - w / 2 if anchor == "middle" else (x - w if anchor == "end" else x)
    return (x0 + left * size, y - top * size, x0 + right * size, y - bottom * size)


def label_box(x: float, y: float, text: str, size: float, font: str = DEFAULT_FONT,
              italic: bool = False, halo: float = HALO_PX / 2) -> tuple[float, float, float, float]:
    """The box a centred letter at baseline (x, y) covers (pixels, y down) with its halo (3.5 px wide:
    1.75 px round the ink), which may cover thin helpers but never a point or a result line.  *halo*:
    the halo's reach round the ink at this size (a letter drawn larger has its halo drawn larger too)."""
    b = text_box(x, y, text or " ", size, font, italic)
    m = halo
    return (b[0] - m, b[1] - m, b[2] + m, b[3] + m)


@functools.lru_cache(maxsize=4096)  # a name tag is placed once per level it is seen at: the same letters asked again
def _box_maker(text: str, size: float, font: str, italic: bool, halo: float):
    """``label_box(x, y, text, size, font, italic, halo)`` as a function of (x, y) alone: the letter's measures
    looked up once, the same sums in the same order (a placing tries sixty spots a letter)."""
    adv, top, bottom, left, right = _metrics(text or " ", font, italic)
    half, ls, ts, rs, bs, m = size * adv / 2, left * size, top * size, right * size, bottom * size, halo

    def box(x: float, y: float) -> tuple[float, float, float, float]:
        x0 = x - half
        return (x0 + ls - m, y - ts - m, x0 + rs + m, y - bs + m)

    return box


class _Grid:
    def __init__(self, cell: float):
        self.cell = cell
        self.cells: dict[tuple[int, int], list[tuple[float, float, float, float]]] = {}
        #: a crowded cell's boxes as one array (asked at once) and the box round them all, with how many boxes the
        #: cell held when made
        self.arrays: dict[tuple[int, int], tuple[Any, tuple[float, float, float, float]]] = {}
        #: the box that last answered "taken": the next spot tried is near, and it likely takes that too
        self.last: tuple[float, float, float, float] = (math.inf, math.inf, -math.inf, -math.inf)

    def free(self, b) -> bool:
        c, cells, floor = self.cell, self.cells, math.floor
        x0, y0, x1, y1 = b
        o = self.last
        if x0 < o[2] and o[0] < x1 and y0 < o[3] and o[1] < y1:
            return False
        # The cell of the box's centre first: the box covers most of it, so what is filed there most likely
        # meets it (a spot in a dense crowd of points is answered by the first boxes looked at, not after the
        # hundred filed in a corner cell it barely reaches).
        centre = (floor((x0 + x1) / 2 / c), floor((y0 + y1) / 2 / c))
        got = cells.get(centre)
        if got and self._taken(centre, got, x0, y0, x1, y1):
            return False
        js = range(floor(y0 / c), floor(y1 / c) + 1)
        for i in range(floor(x0 / c), floor(x1 / c) + 1):
            for j in js:
                got = cells.get((i, j))
                if got and (i, j) != centre and self._taken((i, j), got, x0, y0, x1, y1):
                    return False
        return True

    def _taken(self, key: tuple[int, int], got: list, x0: float, y0: float, x1: float, y1: float) -> bool:
        """Does a box filed in cell *key* (its boxes *got*) meet the box (x0, y0, x1, y1)?"""
        o = got[0]
        if x0 < o[2] and o[0] < x1 and y0 < o[3] and o[1] < y1:
            self.last = o
            return True
        if len(got) > _CROWD:
            # hundreds of points in one cell (3600 piston positions on a stroke): asked at once
            got_a = self.arrays.get(key)
            if got_a is None or len(got_a[0]) != len(got):
                a = np.array(got)
                got_a = self.arrays[key] = (a, (float(a[:, 0].min()), float(a[:, 1].min()), float(a[:, 2].max()),
                                                float(a[:, 3].max())))
            a, o = got_a
            # (a row of points along a stroke fills a strip of its cell: a box above or below it misses them all)
            return x0 < o[2] and o[0] < x1 and y0 < o[3] and o[1] < y1 and \
                bool(((x0 < a[:, 2]) & (a[:, 0] < x1) & (y0 < a[:, 3]) & (a[:, 1] < y1)).any())
        for k, o in enumerate(got):
            if x0 < o[2] and o[0] < x1 and y0 < o[3] and o[1] < y1:
                # to the front of its cell: the next spot tried is near, and it likely takes that too
                got[0], got[k] = o, got[0]
                self.last = o
                return True
        return False

    def add(self, b) -> None:
        c, cells = self.cell, self.cells
        js = range(math.floor(b[1] / c), math.floor(b[3] / c) + 1)
        for i in range(math.floor(b[0] / c), math.floor(b[2] / c) + 1):
            for j in js:
                got = cells.get((i, j))
                if got is None:
                    cells[(i, j)] = [b]
                else:
                    got.append(b)

    def add_many(self, boxes: np.ndarray) -> None:
        """:meth:`add` of each box (rows x0, y0, x1, y1), in order: the cells of all of them found at once (the
        points of a placing: thousands, most of them across a cell's border), each box filed in each of its cells
        in the order :meth:`add` files it (box by box, column by column)."""
        cells = self.cells
        i0, j0, i1, j1 = np.floor(boxes / self.cell).astype(np.int64).T
        nj = j1 - j0 + 1
        per = (i1 - i0 + 1) * nj
        if len(per) and (per.min() < 1 or per.max() > 64):
            for b in map(tuple, boxes.tolist()):  # (a box far larger than a point's: as add files it)
                self.add(b)
            return
        which = np.repeat(np.arange(len(per)), per)
        k = np.arange(len(which)) - np.repeat(np.cumsum(per) - per, per)  # the cell's number within its box's
        n = nj[which]
        filed = list(map(tuple, boxes.tolist()))
        for b, key in zip(which.tolist(), zip((i0[which] + k // n).tolist(), (j0[which] + k % n).tolist())):
            got = cells.get(key)
            if got is None:
                cells[key] = [filed[b]]
            else:
                got.append(filed[b])


class _Boxes:
    """The boxes a single letter must keep clear of, asked all at once (numpy): a letter placed alone tries a
    few spots among a few hundred boxes, where filing them in a :class:`_Grid` costs more than the asking."""

    def __init__(self, boxes: "list[tuple[float, float, float, float]] | np.ndarray"):
        a = np.asarray(boxes, dtype=float).reshape(-1, 4)
        self.x0, self.y0, self.x1, self.y1 = a[:, 0], a[:, 1], a[:, 2], a[:, 3]

    def free(self, b) -> bool:
        x0, y0, x1, y1 = b
        return not ((x0 < self.x1) & (self.x0 < x1) & (y0 < self.y1) & (self.y0 < y1)).any()

    def free_in(self, boxes: "Sequence[np.ndarray]", chunks: "Sequence[tuple[int, int]]") -> Iterable[int]:
        """The numbers of the free boxes of one letter's spots (four arrays x0, y0, x1, y1 of one row), in order,
        asked of the boxes *chunks* of spots at a time (first, end), each of those boxes alone that meet the box
        round the chunk's spots, and a chunk only once the spots before it are all used."""
        x0, y0, x1, y1 = (b[0] for b in boxes)
        for lo, hi in chunks:
            a0, b0, a1, b1 = x0[lo:hi], y0[lo:hi], x1[lo:hi], y1[lo:hi]
            near = np.flatnonzero((a0.min() < self.x1) & (self.x0 < a1.max()) & (b0.min() < self.y1)
                                  & (self.y0 < b1.max()))
            if not len(near):
                yield from range(lo, hi)
                continue
            c0, d0, c1, d1 = self.x0[near], self.y0[near], self.x1[near], self.y1[near]
            taken = ((a0[:, None] < c1) & (c0 < a1[:, None]) & (b0[:, None] < d1) & (d0 < b1[:, None])).any(axis=1)
            yield from (np.flatnonzero(~taken) + lo).tolist()

    def add(self, b) -> None:  # the letter is placed alone: nothing is asked after it
        pass


class _DotCounts:
    """How many points stand in each cell of a fine grid, summed from a corner (a summed-area table): asked for
    every spot of every letter at once whether some point's box surely meets the spot's, before the spots are
    tried one by one in the order of the letters.  A crowded figure's letters find most spots taken by points
    (3600 piston positions along a stroke), and a spot surely taken need not be asked in the grid.  Only cells
    wholly inside (by a margin far above rounding) the region where a point's box meets the spot's count, so
    "surely" is exact; a spot taken only near that region's edge is left to the grid."""

    #: At most this many cells: a figure spread out by a deep zoom gets coarser cells, not more memory and time.
    MAX_CELLS = 1 << 18

    def __init__(self, dots: "Sequence[tuple[float, float]]", r: float, size: float):
        a = np.array(dots, dtype=float).reshape(-1, 2)
        self.r = r
        lo, hi = a.min(axis=0), a.max(axis=0)
        g = 0.1 * size
        span = float((hi - lo).max())
        while ((hi - lo) / g + 2).prod() > self.MAX_CELLS:
            g *= 2.0
        self.g, self.lo, self.eps = g, lo, 1e-6 * g + 1e-9 * span
        n = ((hi - lo) / g).astype(int) + 1
        cell = np.minimum(((a - lo) / g).astype(int), n - 1)
        counts = np.bincount(cell[:, 0] * n[1] + cell[:, 1], minlength=int(n.prod())).reshape(n)
        self.sums = np.zeros((n[0] + 1, n[1] + 1), dtype=np.int64)
        self.sums[1:, 1:] = counts.cumsum(axis=0).cumsum(axis=1)
        self.n = n

    def surely_taken(self, x0: Any, y0: Any, x1: Any, y1: Any) -> Any:
        """For boxes given as four arrays: does a point's box (x - r, y - r, x + r, y + r) surely meet each?"""
        r, g, e, n = self.r, self.g, self.eps, self.n
        # a point meets the box when x0 - r < x < x1 + r (and so in y): the cells wholly inside that, less e
        i0 = np.clip(np.ceil((x0 - r + e - self.lo[0]) / g), 0, n[0]).astype(int)
        i1 = np.clip(np.floor((x1 + r - e - self.lo[0]) / g), 0, n[0]).astype(int)
        j0 = np.clip(np.ceil((y0 - r + e - self.lo[1]) / g), 0, n[1]).astype(int)
        j1 = np.clip(np.floor((y1 + r - e - self.lo[1]) / g), 0, n[1]).astype(int)
        i1, j1 = np.maximum(i1, i0), np.maximum(j1, j0)
        s = self.sums
        return (s[i1, j1] - s[i0, j1] - s[i1, j0] + s[i0, j0]) > 0


def clipped_segment(box, seg) -> tuple[float, float] | None:
    """The part (t0, t1) of the segment (x0, y0, x1, y1) inside the box (x0, y0, x1, y1), or None when it misses
    (Liang–Barsky clipping).

    >>> clipped_segment((0, 0, 2, 2), (-1, 1, 3, 1)), clipped_segment((0, 0, 2, 2), (3, 0, 3, 5))
    ((0.25, 0.75), None)
    """
    x0, y0, x1, y1 = seg
    dx, dy = x1 - x0, y1 - y0
    t0, t1 = 0.0, 1.0
    for p, q in ((-dx, x0 - box[0]), (dx, box[2] - x0), (-dy, y0 - box[1]), (dy, box[3] - y0)):
        if p == 0:
            if q < 0:
                return None
        else:
            t = q / p
            if p < 0:
                t0 = max(t0, t)
            else:
                t1 = min(t1, t)
            if t0 > t1:
                return None
    return (t0, t1)


def segment_meets_box(box, seg) -> bool:
    """Does the segment (x0, y0, x1, y1) cross the box (x0, y0, x1, y1)?  (:func:`clipped_segment`)

    >>> segment_meets_box((0, 0, 2, 2), (-1, 1, 3, 1)), segment_meets_box((0, 0, 2, 2), (3, 0, 3, 5))
    (True, False)
    """
    return clipped_segment(box, seg) is not None


def line_pieces(segments: Iterable[tuple[float, float, float, float]] | np.ndarray, cell: float
                ) -> tuple[list[tuple[int, int]], list[tuple[float, float, float, float]], list[int]]:
    """The pieces a :class:`LineIndex` files *segments* (x0, y0, x1, y1) under, in order: each cut into
    ``n = int(length / cell) + 1`` equal pieces (a segment of more than 4000 is far beyond the sheet and left
    out), each piece under the cell (of side *cell*) of its middle: (cells, pieces, the segments' numbers).

    The pieces of all segments are worked out at once (a figure's result lines are thousands, at every zoom
    level), with the numbers of one piece at a time (:func:`line_pieces_one_by_one`, the rule, held equal to
    this in the tests).

    >>> line_pieces([(0.0, 0.0, 4.0, 0.0), (0.0, 1.0, 0.0, 1.5)], 3.0)
    ([(0, 0), (1, 0), (0, 0)], [(0.0, 0.0, 2.0, 0.0), (2.0, 0.0, 4.0, 0.0), (0.0, 1.0, 0.0, 1.5)], [0, 0, 1])
    """
    seg = np.array(segments if isinstance(segments, np.ndarray) else list(segments), dtype=float).reshape(-1, 4)
    x0, y0 = seg[:, 0], seg[:, 1]
    dx, dy = seg[:, 2] - x0, seg[:, 3] - y0
    hypot = math.hypot  # (each length as the rule measures it: a piece count never differs by a last bit)
    n = np.array([max(1, int(hypot(a, b) / cell) + 1) for a, b in zip(dx.tolist(), dy.tolist())], dtype=np.int64)
    number = np.flatnonzero(n <= 4000)
    n = n[number]
    k = np.repeat(number, n)
    per = np.repeat(n, n)
    i = np.arange(len(k)) - np.repeat(np.cumsum(n) - n, n)
    a, b = i / per, (i + 1) / per
    x0, y0, dx, dy = x0[k], y0[k], dx[k], dy[k]
    pieces = np.column_stack((x0 + a * dx, y0 + a * dy, x0 + b * dx, y0 + b * dy))
    keys = np.floor(np.column_stack(((pieces[:, 0] + pieces[:, 2]) / 2 / cell,
                                     (pieces[:, 1] + pieces[:, 3]) / 2 / cell))).astype(np.int64)
    return list(map(tuple, keys.tolist())), list(map(tuple, pieces.tolist())), k.tolist()


def line_pieces_one_by_one(segments: Iterable[tuple[float, float, float, float]], cell: float
                           ) -> tuple[list[tuple[int, int]], list[tuple[float, float, float, float]], list[int]]:
    """:func:`line_pieces`, one segment and one piece at a time (the rule the array form follows)."""
    keys, pieces, numbers = [], [], []
    floor, hypot = math.floor, math.hypot
    for k, (x0, y0, x1, y1) in enumerate(segments):
        dx, dy = x1 - x0, y1 - y0
        n = max(1, int(hypot(dx, dy) / cell) + 1)
        if n > 4000:
            continue  # far beyond the sheet
        for i in range(n):
            a, b = i / n, (i + 1) / n
            piece = (x0 + a * dx, y0 + a * dy, x0 + b * dx, y0 + b * dy)
            keys.append((floor((piece[0] + piece[2]) / 2 / cell), floor((piece[1] + piece[3]) / 2 / cell)))
            pieces.append(piece)
            numbers.append(k)
    return keys, pieces, numbers


class LineIndex:
    """Result lines as short pieces in a grid, asked whether a box meets one.

    Made for a letter size (cells of 1.5 letter heights) and handed to every
    :func:`place` at that size, which may ask about a part of the lines only
    (*only*: their numbers): the pieces of a line are the same whichever
    lines are filed with it, so the answer is the one an index of that part
    alone would give.
    """

    def __init__(self, size: float, segments: Iterable[tuple[float, float, float, float]] | np.ndarray):
        cell = 1.5 * size
        self.size = size
        self.cell = cell
        self.cells: dict[tuple[int, int], list[tuple[tuple[float, float, float, float], int]]] = {}
        cells = self.cells
        for key, piece, k in zip(*line_pieces(segments, cell)):
            got = cells.get(key)
            if got is None:
                cells[key] = [(piece, k)]
            else:
                got.append((piece, k))

    def length_in(self, box) -> float:
        """How much of the lines lies inside *box*: what a plate would break them by for a letter there."""
        c, total = self.cell, 0.0
        seen: set[int] = set()
        for i in range(math.floor(box[0] / c) - 1, math.floor(box[2] / c) + 2):
            for j in range(math.floor(box[1] / c) - 1, math.floor(box[3] / c) + 2):
                for seg, _k in self.cells.get((i, j), ()):
                    if id(seg) in seen:
                        continue
                    seen.add(id(seg))
                    t = clipped_segment(box, seg)
                    if t is not None:
                        total += (t[1] - t[0]) * math.hypot(seg[2] - seg[0], seg[3] - seg[1])
        return total

    def meets(self, box, reach: float = 0.0, only: "Sequence[bool] | None" = None) -> bool:
        """Does a piece of a line (of those *only* marks true, by number) cross *box* grown by *reach*?"""
        c = self.cell
        if reach:
            box = (box[0] - reach, box[1] - reach, box[2] + reach, box[3] + reach)
        bx0, by0, bx1, by1 = box
        # a piece whose ends lie both beyond one side of the box (by more than rounding) misses it;
        # the others are clipped (the margin leaves every close call to the clipping)
        e = 1e-9 * c
        lx, ly, hx, hy = bx0 - e, by0 - e, bx1 + e, by1 + e
        cells = self.cells
        js = range(math.floor(by0 / c) - 1, math.floor(by1 / c) + 2)
        for i in range(math.floor(bx0 / c) - 1, math.floor(bx1 / c) + 2):
            for j in js:
                got = cells.get((i, j))
                if not got:
                    continue
                for seg, k in got:
                    sx0, sy0, sx1, sy1 = seg
                    if (sx0 < lx and sx1 < lx) or (sx0 > hx and sx1 > hx) or (sy0 < ly and sy1 < ly) \
                            or (sy0 > hy and sy1 > hy):
                        continue
                    if (only is None or only[k]) and segment_meets_box(box, seg):
                        return True
        return False


def _nearer_dot(box, own: tuple[float, float], dots) -> bool:
    """Is some point of *dots* nearer the letter's *box* than its own point *own*?"""
    def far(p):
        return math.hypot(max(box[0] - p[0], 0.0, p[0] - box[2]), max(box[1] - p[1], 0.0, p[1] - box[3]))

    mine = far(own)
    return any(far(p) < mine - 0.5 for p in dots if abs(p[0] - own[0]) > 1e-6 or abs(p[1] - own[1]) > 1e-6)


def _spots(ordered: "Sequence[tuple]", distances: tuple[float, ...], size: float, font: str,
           italic: bool, halo: float) -> tuple[Any, ...]:
    """Every spot of the plan (:func:`_plan` of the farther rings *distances*) for every letter of *ordered* (as
    :func:`place` takes them), at once: the letter's baseline x, y and its box x0, y0, x1, y1 (pixels, y down), each
    an array of a row per letter and a column per spot.  The letter's centre sits *dist* letter heights from its
    point (plus half its extra width sideways), its baseline a third of a letter lower; the box is
    :func:`label_box`'s, each number in the sums (and their order) of the spot asked alone, the cosines and sines
    :mod:`math`'s."""
    _plan_, _rings, radians, k, dists, _chunks = _plan(distances)
    cos, sin, px, py, extra, measures = [], [], [], [], [], []
    for _mid, _role, _step, (x, y), (dx, dy), text in ordered:
        base = math.atan2(-dy, dx)  # y down on the sheet
        angles = [base + a for a in radians]
        cos.append([math.cos(a) for a in angles])
        sin.append([math.sin(a) for a in angles])
        px.append(x)
        py.append(y)
        extra.append(max(0.0, text_width(text, size, font, italic) - 0.6 * size) / 2)
        adv, top, bottom, left, right = _metrics(text or " ", font, italic)
        measures.append((size * adv / 2, left * size, top * size, right * size, bottom * size))
    reach = dists * size
    cos_a, sin_a = np.array(cos).reshape(-1, len(radians))[:, k], np.array(sin).reshape(-1, len(radians))[:, k]
    half, ls, ts, rs, bs = (c[:, None] for c in np.array(measures).reshape(-1, 5).T)
    lxs = np.array(px)[:, None] + cos_a * (reach + np.array(extra)[:, None])
    lys = np.array(py)[:, None] + reach * sin_a + 0.35 * size
    x0, m = lxs - half, halo
    return lxs, lys, x0 + ls - m, lys - ts - m, x0 + rs + m, lys - bs + m


def spots_of(items: "Sequence[tuple]", size: float, *, font: str = DEFAULT_FONT, italic: bool = False,
             halo: float = HALO_PX / 2, distances: Sequence[float] = ()) -> tuple[Any, ...]:
    """The spots :func:`place` tries for each letter of *items* (as it takes them, in their order), in the order
    tried: arrays of a row per letter and a column per spot of its baseline x, y and its box x0, y0, x1, y1 (the
    numbers :func:`place` asks), and each spot's distance in letter heights.  The usual rings come first whatever
    the farther *distances*: without those, the spots where most letters find room.

    >>> lx, ly, x0, y0, x1, y1, dist = spots_of([("a", "result", 1, (0.0, 0.0), (1.0, 0.0), "q1")], 10.0)
    >>> lx.shape, float(dist[0]), bool(x0[0, 0] > 0)  # the first spot: 0.9 letter heights to the right
    ((1, 60), 0.9, True)
    """
    return _spots(items, tuple(distances), size, font, italic, halo) + (_plan(tuple(distances))[4],)


def spots_extent(items: "Sequence[tuple]", size: float, *, font: str = DEFAULT_FONT, italic: bool = False,
                 halo: float = HALO_PX / 2, prefer: "dict[str, tuple[float, float, float]] | None" = None,
                 distances: Sequence[float] = ()) -> tuple[float, float, float, float] | None:
    """The box (pixels) round every spot :func:`place` may ask of *items* (its arguments: the rings' spots and the
    preferred ones), or None without items: a line that keeps off it (by more than *place*'s reach) meets none.

    >>> box = spots_extent([("a", "result", 1, (0.0, 0.0), (1.0, 0.0), "q1")], 10.0)
    >>> box[0] < 0.0 < box[2] and box[1] < 0.0 < box[3]
    True
    """
    items = list(items)
    if not items:
        return None
    x0, y0, x1, y1 = _spots(items, tuple(distances), size, font, italic, halo)[2:]
    box = (float(x0.min()), float(y0.min()), float(x1.max()), float(y1.max()))
    for mid, _role, _step, (px, py), _d, text in items:
        if prefer and mid in prefer:
            b = _box_maker(text, size, font, italic, halo)(px + prefer[mid][0], py + prefer[mid][1])
            box = (min(box[0], b[0]), min(box[1], b[1]), max(box[2], b[2]), max(box[3], b[3]))
    return box


def lines_near(segments: Sequence[tuple[float, float, float, float]], box: tuple[float, float, float, float],
               margin: float) -> list[tuple[float, float, float, float]]:
    """The *segments* (x0, y0, x1, y1) whose own box comes within *margin* of *box*, in their order: a
    :class:`LineIndex` of them answers :meth:`LineIndex.meets` of a box inside *box* (grown by less than *margin*)
    as one of all *segments* does (a piece lies in its segment's box; the pieces of a segment are its own).

    >>> lines_near([(0.0, 0.0, 1.0, 1.0), (5.0, 5.0, 9.0, 5.0)], (2.0, 2.0, 3.0, 3.0), 1.5)
    [(0.0, 0.0, 1.0, 1.0)]
    """
    near = near_rows(np.array(segments, dtype=float).reshape(-1, 4), box, margin)
    return [s for s, k in zip(segments, near.tolist()) if k]


def near_rows(seg: np.ndarray, box: tuple[float, float, float, float], margin: float) -> np.ndarray:
    """:func:`lines_near` of segments as rows (x0, y0, x1, y1): which of them come within *margin* of *box* (a mask).

    >>> near_rows(np.array([(0.0, 0.0, 1.0, 1.0), (5.0, 5.0, 9.0, 5.0)]), (2.0, 2.0, 3.0, 3.0), 1.5).tolist()
    [True, False]
    """
    lo, hi = np.minimum(seg[:, :2], seg[:, 2:]), np.maximum(seg[:, :2], seg[:, 2:])
    return ((lo[:, 0] <= box[2] + margin) & (hi[:, 0] >= box[0] - margin) & (lo[:, 1] <= box[3] + margin)
            & (hi[:, 1] >= box[1] - margin))


@functools.lru_cache(maxsize=8)
def _plan(distances: tuple[float, ...]) -> tuple[list[tuple[int, float, int]], tuple[float, ...], list[float], Any,
                                                 Any, list[tuple[int, int]]]:
    """Every spot a letter may try, in the order tried: (ring, distance, turn); the rings' distances; the turns
    (radians, ascending by degrees), each spot's turn among them and its distance (arrays); the spots (first, end)
    a letter alone asks of its boxes at once (the two nearest rings, the other usual ones, the farther ones: most
    letters find a spot near) -- the same for every letter of a placing, made once (a name tag is placed alone,
    thousands of times a figure).  Not to be changed by the caller."""
    plan = [(j, dist, turn) for j, dist in enumerate(_DISTANCES + distances)
            for turn in (_TURNS if dist in _DISTANCES else _TURNS_FAR)]
    turns = sorted({t for _, _, t in plan})
    near, usual = 2 * len(_TURNS), len(_DISTANCES) * len(_TURNS)
    chunks = [(lo, hi) for lo, hi in ((0, near), (near, usual), (usual, len(plan))) if lo < hi]
    return (plan, _DISTANCES + distances, [math.radians(t) for t in turns],
            np.array([turns.index(t) for _, _, t in plan]), np.array([dist for _, dist, _ in plan]), chunks)


def place(items: Iterable[tuple[str, str, int, tuple[float, float], tuple[float, float], str]],
          size: float, dots: "Iterable[tuple[float, float]] | np.ndarray" = (),
          lines: "Sequence[tuple[float, float, float, float]] | LineIndex" = (), *, font: str = DEFAULT_FONT,
          italic: bool = False, taken: Iterable[tuple[float, float, float, float]] = (),
          keep: bool = True, prefer: "dict[str, tuple[float, float, float]] | None" = None,
          halo: float = HALO_PX / 2, reach: float = 0.0, only: "Sequence[bool] | None" = None,
          soft: "LineIndex | None" = None, distances: Sequence[float] = ()) -> dict[str, tuple]:
    """Baseline positions (pixels) for letters: {id: (x, y, distance in letter heights, thin)}.

    A letter set farther than :data:`LEADER_FROM` letter heights from its point gets a
    leader line from the renderer, so that it is never read as another point's; a
    *thin* one found no free spot and is shown only in magnified views.

    *items*: (id, role, step, point in pixels, preferred direction (dx, dy) in the
    drawing's y-up sense, text).  *dots*: points (pixels) a letter must not cover.
    *lines*: result lines as segments (pixels) a letter must not be struck by.
    *taken*: boxes already taken by letters placed before.  Without *keep*
    a letter that finds no free spot is left out, whatever its rank.  *prefer*:
    per letter an offset from its point (and its distance in letter heights)
    tried before the ring, so that a letter stays where it was when it can.  *halo*: how far
    the halo reaches round the ink at *size* (the player scales a letter with its halo).  *reach*:
    half the width of a result line (a halo reaching over the line's edge erases part of it).
    *lines* may be a :class:`LineIndex` made at *size* (placings at one size share it), and
    *only* the numbers of its lines that count (true), as if *lines* were those alone.  *soft*: the
    other lines (a plate's construction lines, ticks, axes), which a letter keeps clear of where a spot
    nearer than :data:`LEADER_FROM` allows it; where none does it takes the first free spot all the
    same, and the plate breaks those lines for it (:mod:`construct.render.gaps`).  *distances*: farther
    rings tried after the usual ones (letter heights; a name tag a caption names is set off with a leader
    rather than left out).
    """
    r = 0.3 * size
    items = list(items)
    taken = list(taken)
    if len(items) == 1:
        # (points given as an array of rows: their boxes made on the array)
        a = dots.reshape(-1, 2) if isinstance(dots, np.ndarray) else np.array(list(dots), dtype=float).reshape(-1, 2)
        grid: "_Grid | _Boxes" = _Boxes(np.concatenate([np.array(taken, dtype=float).reshape(-1, 4), np.column_stack(
            (a[:, 0] - r, a[:, 1] - r, a[:, 0] + r, a[:, 1] + r))]))
        dots = list(map(tuple, a.tolist())) if soft is not None else []  # (only a plate's letter asks them again)
    else:
        dots = list(map(tuple, dots.tolist())) if isinstance(dots, np.ndarray) else list(dots)
        grid = _Grid(1.0 * size)
        for b in taken:
            grid.add(b)
        if dots:
            a = np.array(dots, dtype=float).reshape(-1, 2)
            grid.add_many(np.column_stack((a[:, 0] - r, a[:, 1] - r, a[:, 0] + r, a[:, 1] + r)))
    if isinstance(lines, LineIndex):
        if lines.size != size:
            raise ValueError(f"place: the line index is made for letters of {lines.size}, not {size}")
        strokes = lines
    elif only is not None:
        raise ValueError("place: only= picks lines of a LineIndex")
    else:
        strokes = LineIndex(size, lines)
    out: dict[str, tuple] = {}
    ordered = sorted(items, key=lambda it: (RANK.get(it[1], 2), it[2], it[0]))
    # every spot a letter may try, in the order tried: (ring, distance, turn) -- the ring's number, not its distance,
    # ends a ring (a farther distance may repeat a usual one)
    plan, rings, _radians, _k, _dists, chunks = _plan(tuple(distances))
    # many letters: every spot of every letter made at once, and crossed off in bulk where a point surely takes it
    # (a crowd of points takes most spots of most letters) or a letter placed in this call meets it; the rest are
    # asked in the grid, in the order of the letters.  A few letters are asked spot by spot, each made as it is
    # tried (their first spots are most often free).  The boxes *taken* before are asked in the grid.
    bulk = len(ordered) >= _CROWD
    alone = isinstance(grid, _Boxes)
    if bulk:
        spots = _spots(ordered, tuple(distances), size, font, italic, halo)
        sx0, sy0, sx1, sy1 = spots[2:]
        alive = np.ones(sx0.shape, dtype=bool)
        if isinstance(grid, _Grid) and len(dots) >= _CROWD:
            alive = ~_DotCounts(dots, r, size).surely_taken(sx0, sy0, sx1, sy1)
        # the box round each letter's spots: a letter placed takes spots of those whose box it meets, of no other
        around = (sx0.min(axis=1), sy0.min(axis=1), sx1.max(axis=1), sy1.max(axis=1))

    def takes(b: tuple[float, float, float, float], after: int) -> None:
        """The box *b* is taken: no spot it meets of the letters after the first *after* is free."""
        x0, y0, x1, y1 = b
        rows = np.flatnonzero((around[0][after:] < x1) & (x0 < around[2][after:]) & (around[1][after:] < y1)
                              & (y0 < around[3][after:])) + after
        if len(rows):
            alive[rows] &= ~((sx0[rows] < x1) & (x0 < sx1[rows]) & (sy0[rows] < y1) & (y0 < sy1[rows]))

    for n, (mid, role, _step, (px, py), (dx, dy), text) in enumerate(ordered):
        first = None
        spot = None
        box_at = _box_maker(text, size, font, italic, halo)  # label_box(x, y, text, ...) for this letter
        if prefer and mid in prefer:
            ox, oy, od = prefer[mid]
            box = box_at(px + ox, py + oy)
            if grid.free(box) and not strokes.meets(box, reach, only):
                spot = (px + ox, py + oy, box, od)
        clear = None  # with soft lines: the first free spot near the point that no line crosses
        least = None  # else the near free spot the least of those lines would be broken for: (length, spot)
        if spot is None:
            if alone:
                # a letter alone (a name tag, thousands a figure): all its spots made at once and asked of the
                # boxes at once; the free ones are asked of the lines in the order tried
                spots = _spots(ordered, tuple(distances), size, font, italic, halo)
            if bulk or alone:
                first = (float(spots[0][n, 0]), float(spots[1][n, 0]), tuple(float(a[n, 0]) for a in spots[2:]),
                         plan[0][1])
                asked: Iterable[int] = grid.free_in(spots[2:], chunks) if alone else np.flatnonzero(alive[n]).tolist()
                row = None
            else:
                asked = range(len(plan))
                base = math.atan2(-dy, dx)  # y down on the sheet
                w = text_width(text, size, font, italic)
                ring_cs: dict[int, tuple[float, float]] = {}  # each direction's cosine and sine, for all distances

                def spot_at(k: int) -> tuple[float, float, tuple[float, float, float, float]]:
                    _j, dist, turn = plan[k]
                    cs = ring_cs.get(turn)
                    if cs is None:
                        a = base + math.radians(turn)
                        cs = ring_cs[turn] = (math.cos(a), math.sin(a))
                    # the letter's centre sits *dist* letter heights from the point (plus half its extra width
                    # sideways); its baseline a third of a letter lower
                    lx = px + cs[0] * (dist * size + max(0.0, w - 0.6 * size) / 2)
                    ly = py + dist * size * cs[1] + 0.35 * size
                    return lx, ly, box_at(lx, ly)
            ring = 0
            for i in asked:
                j, dist, turn = plan[i]
                if j != ring:
                    # the rings ended since the last spot asked (all their spots taken: nothing changed since)
                    if clear or (spot and (soft is None or max(rings[ring:j]) >= LEADER_FROM)):
                        break
                    ring = j
                if alone:  # (the few spots asked of a letter alone read one by one)
                    lx, ly, box = float(spots[0][0, i]), float(spots[1][0, i]), tuple(float(a[0, i]) for a in spots[2:])
                    free = True
                elif bulk:
                    if row is None:
                        row = [a[n].tolist() for a in spots]
                    lx, ly, box = row[0][i], row[1][i], (row[2][i], row[3][i], row[4][i], row[5][i])
                    free = None
                else:
                    lx, ly, box = spot_at(i)
                    free = None
                    if first is None:
                        first = (lx, ly, box, dist)
                if not (grid.free(box) if free is None else free) or strokes.meets(box, reach, only):
                    continue
                if soft is None:
                    spot = (lx, ly, box, dist)
                    break
                if spot is None:
                    spot = (lx, ly, box, dist)
                # beside the line, but on the side the letter belongs (outwards, not across its own figure)
                if dist < LEADER_FROM and abs(turn) <= 90:
                    broken = soft.length_in(box)
                    if broken == 0.0:
                        clear = (lx, ly, box, dist)
                        break
                    # (not along the line the point lies on: a letter on its own axis, turned a right angle)
                    if abs(turn) <= 60 and (least is None or broken < least[0] - 1e-9):
                        least = (broken, (lx, ly, box, dist))
        spot = clear or (least[1] if least is not None else spot)
        if spot is not None and soft is not None and spot[3] < LEADER_FROM and _nearer_dot(spot[2], (px, py), dots):
            # another point stands nearer the letter than its own (17′ beside B): tied to its own by a leader
            spot = (spot[0], spot[1], spot[2], LEADER_FROM)
        if spot is None:
            if keep and RANK.get(role, 2) <= 1 and first is not None:
                # no room in the whole figure: kept for the magnified views, never stacked here
                out[mid] = (first[0], first[1], first[3], True)
            continue
        grid.add(spot[2])
        if bulk:
            takes(spot[2], n + 1)
        out[mid] = (spot[0], spot[1], spot[3], False)
    return out
