"""A digitised indicator diagram ("Indikatordiagramm"): the user's own card, read from a CSV file.

Seed 001 (Abb. 1054) takes the piston's over-pressure from the *measured*
diagrams of the cover side and the crank side.  A card is given as a CSV
file with the header ``x,p``: the closed loop of one cylinder side in drawing
order, ``x`` the piston position from the head-end dead centre as a fraction
of the stroke, ``p`` the absolute pressure in kg/cm² (at).

How it is read:

* **the two strokes.**  In drawing order the indicator's pencil runs with the
  piston: the part of the loop traversed with x increasing (from its leftmost
  to its rightmost point) belongs to the forward stroke, the rest to the return
  stroke.  On the cover side that is the steam line forward and the exhaust
  and compression line back; on the crank side the other way round.
* **between the points, straight lines** (the straightedge): the pressure at a
  piston position is read on the chord between the two digitised points on
  either side.  Where a branch runs vertically (a valve opening at a dead
  centre) the pressure the piston *meets* is taken: the last point of the run
  where the branch starts, the first elsewhere.
* **the crank side** is a second card, or -- Baumann's assumption ("die
  Diagramme der beiden Kolbenseiten gleich") -- the same card mirrored,
  x -> 1 - x; :meth:`IndicatorCard.mirrored` does it, and whatever prints a
  result says so.

A file that is not such a loop is refused, naming the row (the header is row
1) and what is wrong: not numeric, x outside 0..1, p outside 0..1000 at, fewer
than :data:`MIN_POINTS` points, more than :data:`MAX_POINTS`, not closed (the
last point farther than :data:`CLOSE_TOLERANCE` from the first, x in strokes
and p in heights of the loop), self-crossing, a branch that turns back, or a
loop that does not reach both dead centres (x = 0 and 1 within
:data:`CLOSE_TOLERANCE`).

>>> card = parse_indicator_csv("x,p\\n0,8\\n0.3,8\\n1,2.5\\n1,1.1\\n0.1,1.1\\n0,2\\n0,8\\n", "demo")
>>> card.pressure(0.15, "forward"), card.pressure(0.5, "return")
(8.0, 1.1)
>>> card.mirrored().pressure(0.85, "return")     # the crank side's steam line, mirrored
8.0
>>> parse_indicator_csv("x,p\\n0,8\\n0.3,eight\\n1,2\\n0,1\\n0,8\\n", "demo")
Traceback (most recent call last):
...
construct.kernel.errors.InputFileError: indicator diagram demo, row 3: p = 'eight' is not a number
"""

from __future__ import annotations

import csv
import io
import math
from dataclasses import dataclass
from typing import Any, Sequence

import numpy as np

from ..io.reading import read_bounded_text
from ..kernel.errors import InputFileError

__all__ = ["IndicatorCard", "parse_indicator_csv", "load_indicator", "MAX_INDICATOR_BYTES", "MIN_POINTS",
           "MAX_POINTS", "CLOSE_TOLERANCE", "MAX_CARD_PRESSURE", "STROKES"]

#: The largest indicator file read (bytes): 5000 rows of two numbers need about 100 kB.
MAX_INDICATOR_BYTES = 1_000_000
#: A loop needs at least four points (a cylinder side's diagram has four events at least).
MIN_POINTS = 4
#: The most points a card may have: the self-crossing test compares every pair of chords.
MAX_POINTS = 5000
#: The last point may lie this far from the first (x in strokes, p in heights of the loop): a digitised loop
#: rarely ends exactly where it began; the closing chord is drawn with the straightedge.  The same tolerance
#: says how near to the dead centres the loop must reach.
CLOSE_TOLERANCE = 0.01
#: Absolute pressures read (at): the domain of the diagrams' pressures (construct.constructions.domain.PRESSURE).
MAX_CARD_PRESSURE = 1000.0
STROKES = ("forward", "return")


@dataclass(frozen=True)
class IndicatorCard:
    """A closed loop of (x, p) in drawing order, split into its forward and return branches."""

    source: str
    points: tuple[tuple[float, float], ...]
    rows: tuple[int, ...]
    forward: tuple[tuple[float, ...], tuple[float, ...]]   #: (x increasing, p) of the forward branch
    back: tuple[tuple[float, ...], tuple[float, ...]]      #: (x increasing, p) of the return branch
    mirror: bool = False

    def pressure(self, x: float, stroke: str) -> float:
        """Absolute pressure at piston position x (fraction of the stroke) on the *stroke*'s branch, in at."""
        xs, ps = self.forward if stroke == "forward" else self.back
        return float(np.interp(min(max(x, 0.0), 1.0), xs, ps))

    def mirrored(self) -> IndicatorCard:
        """The same diagram for the other side of the piston: x -> 1 - x (Baumann's assumption)."""
        pts = tuple((1.0 - x, p) for x, p in self.points)
        card = _card(pts, self.rows, self.source)
        return IndicatorCard(card.source, card.points, card.rows, card.forward, card.back, mirror=True)

    def work(self) -> float:
        """The loop's area (at x stroke), positive when the forward branch lies above the return branch."""
        xs = np.linspace(0.0, 1.0, 4001)
        f = np.array([self.pressure(x, "forward") for x in xs]) - np.array([self.pressure(x, "return") for x in xs])
        return float(np.trapezoid(f, xs)) if hasattr(np, "trapezoid") else float(np.trapz(f, xs))


def _fail(source: str, row: int | None, what: str) -> InputFileError:
    where = f", row {row}" if row is not None else ""
    return InputFileError(f"indicator diagram {source}{where}: {what}")


def parse_indicator_csv(text: str, source: str) -> IndicatorCard:
    """The card in *text* (a CSV with header ``x,p``), checked as described in the module; *source* names it."""
    reader = csv.reader(io.StringIO(text))
    try:
        table = list(reader)
    except csv.Error as exc:
        raise _fail(source, reader.line_num, f"not a CSV file ({exc})") from None
    if not table or [c.strip().lower() for c in table[0]] != ["x", "p"]:
        got = ",".join(table[0])[:40] if table else "an empty file"
        raise _fail(source, 1, f"the header must be 'x,p', got {got!r}")
    pts: list[tuple[float, float]] = []
    rows: list[int] = []
    for i, cells in enumerate(table[1:], start=2):
        if not cells or all(not c.strip() for c in cells):
            continue  # a blank line
        if len(cells) != 2:
            raise _fail(source, i, f"a row holds two numbers x,p; this one has {len(cells)} fields")
        vals = []
        for name, cell in zip("xp", cells):
            try:
                v = float(cell)
            except ValueError:
                raise _fail(source, i, f"{name} = {cell.strip()[:20]!r} is not a number") from None
            if not math.isfinite(v):
                raise _fail(source, i, f"{name} = {cell.strip()!r} is not a finite number")
            vals.append(v)
        x, p = vals
        if not 0.0 <= x <= 1.0:
            raise _fail(source, i, f"x = {x:g} is outside 0 .. 1 (the piston position as a fraction of the stroke)")
        if not 0.0 <= p <= MAX_CARD_PRESSURE:
            raise _fail(source, i, f"p = {p:g} at is outside 0 .. {MAX_CARD_PRESSURE:g} (absolute pressure in at)")
        if len(pts) >= MAX_POINTS:
            raise _fail(source, i, f"more than {MAX_POINTS} points")
        pts.append((x, p))
        rows.append(i)
    distinct = len(pts) - (len(pts) >= 2 and pts[-1] == pts[0])
    if distinct < MIN_POINTS:
        raise _fail(source, None, f"a closed loop needs at least {MIN_POINTS} points, the file has {distinct}")
    height = _height(pts, source)
    gap = math.hypot(pts[-1][0] - pts[0][0], (pts[-1][1] - pts[0][1]) / height)
    if gap > CLOSE_TOLERANCE:
        raise _fail(source, rows[-1], f"the loop is not closed: its last point ({pts[-1][0]:g}, {pts[-1][1]:g}) lies "
                    f"{gap:.3g} from the first (row {rows[0]}); at most {CLOSE_TOLERANCE:g} (x in strokes, p in "
                    f"heights of the loop): end the file where the loop began")
    if pts[-1] == pts[0]:
        pts.pop()  # the closing point repeated
        rows.pop()
    return _card(tuple(pts), tuple(rows), source)


def _height(pts: Sequence[tuple[float, float]], source: str) -> float:
    ps = [p for _, p in pts]
    height = max(ps) - min(ps)
    if height <= 0.0:
        raise _fail(source, None, "every point has the same pressure: the loop encloses nothing")
    return height


def _card(pts: tuple[tuple[float, float], ...], rows: tuple[int, ...], source: str) -> IndicatorCard:
    height = _height(pts, source)
    _no_crossing(pts, rows, height, source)
    xs = [x for x, _ in pts]
    if min(xs) > CLOSE_TOLERANCE or max(xs) < 1.0 - CLOSE_TOLERANCE:
        raise _fail(source, None, f"the loop must reach both dead centres (x from 0 to 1 within {CLOSE_TOLERANCE:g}); "
                    f"it runs from {min(xs):g} to {max(xs):g}")
    n = len(pts)
    lo = min(range(n), key=lambda i: (xs[i], i))
    hi = max(range(n), key=lambda i: (xs[i], -i))
    # Where the leftmost (rightmost) x is a vertical run, the forward branch starts at its last point in drawing
    # order and ends at its first: walk the run.
    while xs[(lo + 1) % n] == xs[lo] and (lo + 1) % n != hi:
        lo = (lo + 1) % n
    fwd = _walk(lo, hi, n)
    back = _walk(hi, lo, n)
    return IndicatorCard(source, pts, rows, _branch(pts, rows, fwd, +1, source), _branch(pts, rows, back, -1, source))


def _walk(a: int, b: int, n: int) -> list[int]:
    out = [a]
    while out[-1] != b:
        out.append((out[-1] + 1) % n)
    return out


def _branch(pts, rows, idx: Sequence[int], sign: int, source: str) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """(x increasing, p) along one branch; x must not turn back; a vertical run keeps the pressure the piston meets."""
    xs, ps = [], []
    for k, i in enumerate(idx):
        x, p = pts[i]
        if xs and (x - xs[-1]) * sign < 0.0:
            word = "forward (x increasing)" if sign > 0 else "return (x decreasing)"
            raise _fail(source, rows[i], f"x = {x:g} turns back on the {word} branch (after x = {xs[-1]:g}): "
                        f"each stroke's line must run one way")
        if xs and x == xs[-1]:
            if len(xs) == 1:  # the start of the branch: the piston leaves at the end of the run
                ps[-1] = p
            continue  # elsewhere: the pressure the piston met first
        xs.append(x)
        ps.append(p)
    if sign < 0:
        xs.reverse()
        ps.reverse()
    return tuple(xs), tuple(ps)


def _no_crossing(pts, rows, height: float, source: str) -> None:
    """Refuse a loop whose chords cross (other than neighbours meeting at their common point)."""
    a = np.array([(x, p / height) for x, p in pts])
    b = np.roll(a, -1, axis=0)
    n = len(a)
    d = b - a
    for i in range(n - 2):
        j = np.arange(i + 2, n if i > 0 else n - 1)
        if j.size == 0:
            continue
        p, r = a[i], d[i]
        q, s = a[j], d[j]
        denom = r[0] * s[:, 1] - r[1] * s[:, 0]
        qp = q - p
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (qp[:, 0] * s[:, 1] - qp[:, 1] * s[:, 0]) / denom
            u = (qp[:, 0] * r[1] - qp[:, 1] * r[0]) / denom
        eps = 1e-12
        hit = (np.abs(denom) > eps) & (t > eps) & (t < 1 - eps) & (u > eps) & (u < 1 - eps)
        if hit.any():
            k = int(j[np.argmax(hit)])
            raise _fail(source, rows[(i + 1) % n], f"the loop crosses itself: the chord from row {rows[i]} to row "
                        f"{rows[(i + 1) % n]} crosses the chord from row {rows[k]} to row {rows[(k + 1) % n]}")


def load_indicator(path: Any) -> IndicatorCard:
    """Read and check the card in the file *path* (bounded: a regular file of at most MAX_INDICATOR_BYTES)."""
    text = read_bounded_text(path, MAX_INDICATOR_BYTES, what="indicator diagram")
    import os

    return parse_indicator_csv(text, repr(os.fsdecode(os.fspath(path))))
