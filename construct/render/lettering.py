"""Where the letters go: results first, helpers give way.

A plate's letters are not all equal.  The piston positions 1′…17′, the
characteristic points q1…q7, the crank positions of a crank-angle plate are
what the figure is for; a helper's name is a convenience.  Letters are
placed in order of that rank (results, then givens, then the rest; within a
rank by step), each at the first free spot of a ring of candidates around
its point, nearest first, starting radially outwards from the crank centre.
A result's letter is never left out: when every spot is taken it goes to its
preferred one all the same.  A helper's letter that finds no room is left
out.  Collisions are looked up in a grid of cells one letter high, so the
work grows with the number of letters, not with its square.

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

import math
from typing import Iterable

__all__ = ["place", "label_box", "RANK", "LEADER_FROM"]

#: Rank of a role: lower is placed first and is never dropped (0).
RANK = {"result": 0, "given": 1}

#: Directions tried, as turns from the preferred one (degrees), and distances in letter heights.
_TURNS = (0, 35, -35, 70, -70, 110, -110, 180, 145, -145)
_DISTANCES = (0.9, 1.45, 2.1, 2.8, 3.6)
#: From this distance (letter heights) on, a letter is tied to its point by a leader line.
LEADER_FROM = 2.0


def label_box(x: float, y: float, text: str, size: float) -> tuple[float, float, float, float]:
    """The box a centred letter at baseline (x, y) covers (pixels, y down)."""
    w = 0.62 * size * max(1, len(text))
    return (x - w / 2, y - 0.8 * size, x + w / 2, y + 0.2 * size)


class _Grid:
    def __init__(self, cell: float):
        self.cell = cell
        self.cells: dict[tuple[int, int], list[tuple[float, float, float, float]]] = {}

    def _keys(self, b) -> Iterable[tuple[int, int]]:
        c = self.cell
        for i in range(math.floor(b[0] / c), math.floor(b[2] / c) + 1):
            for j in range(math.floor(b[1] / c), math.floor(b[3] / c) + 1):
                yield i, j

    def free(self, b) -> bool:
        for key in self._keys(b):
            for o in self.cells.get(key, ()):
                if b[0] < o[2] and o[0] < b[2] and b[1] < o[3] and o[1] < b[3]:
                    return False
        return True

    def add(self, b) -> None:
        for key in self._keys(b):
            self.cells.setdefault(key, []).append(b)


def place(items: Iterable[tuple[str, str, int, tuple[float, float], tuple[float, float], str]],
          size: float, dots: Iterable[tuple[float, float]] = ()) -> dict[str, tuple[float, float, float]]:
    """Baseline positions (pixels) for letters: {id: (x, y, distance in letter heights)}.

    A letter set farther than :data:`LEADER_FROM` letter heights from its point gets a
    leader line from the renderer, so that it is never read as another point's.

    *items*: (id, role, step, point in pixels, preferred direction (dx, dy) in the
    drawing's y-up sense, text).  *dots*: other points (pixels) a letter should not cover.
    """
    grid = _Grid(2.0 * size)
    r = 0.35 * size
    for x, y in dots:
        grid.add((x - r, y - r, x + r, y + r))
    out: dict[str, tuple[float, float]] = {}
    ordered = sorted(items, key=lambda it: (RANK.get(it[1], 2), it[2], it[0]))
    for mid, role, _step, (px, py), (dx, dy), text in ordered:
        base = math.atan2(-dy, dx)  # y down on the sheet
        first = None
        spot = None
        for dist in _DISTANCES:
            for turn in _TURNS:
                a = base + math.radians(turn)
                # the letter's centre sits *dist* letter heights from the point; its baseline a third lower
                lx = px + dist * size * math.cos(a) * (1.0 + 0.25 * (len(text) - 1) * abs(math.cos(a)))
                ly = py + dist * size * math.sin(a) + 0.35 * size
                box = label_box(lx, ly, text, size)
                if first is None:
                    first = (lx, ly, box, dist)
                if grid.free(box):
                    spot = (lx, ly, box, dist)
                    break
            if spot:
                break
        if spot is None and RANK.get(role, 2) == 0 and first is not None:
            spot = first  # a result's letter is never dropped
        if spot is None:
            continue
        grid.add(spot[2])
        out[mid] = (spot[0], spot[1], spot[3])
    return out
