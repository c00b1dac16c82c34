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
from typing import Any, Mapping, Sequence

import numpy as np

from ..io.reading import read_bounded_text
from . import analytic
from ..kernel.errors import InputFileError

__all__ = ["IndicatorCard", "parse_indicator_csv", "load_indicator", "card_givens", "card_from_givens", "draw_card",
           "DrawnCard", "card_pair", "card_force", "MAX_INDICATOR_BYTES", "MIN_POINTS",
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
    forward_index: tuple[int, ...] = ()   #: the points of the forward branch, x increasing (vertical runs thinned)
    back_index: tuple[int, ...] = ()      #: the points of the return branch, x increasing

    def pressure(self, x: float, stroke: str) -> float:
        """Absolute pressure at piston position x (fraction of the stroke) on the *stroke*'s branch, in at."""
        xs, ps = self.forward if stroke == "forward" else self.back
        return float(np.interp(min(max(x, 0.0), 1.0), xs, ps))

    def mirrored(self) -> IndicatorCard:
        """The same diagram for the other side of the piston: x -> 1 - x (Baumann's assumption)."""
        pts = tuple((1.0 - x, p) for x, p in self.points)
        card = _card(pts, self.rows, self.source)
        return IndicatorCard(card.source, card.points, card.rows, card.forward, card.back, True,
                             card.forward_index, card.back_index)

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
    f_xy, f_idx = _branch(pts, rows, fwd, +1, source)
    b_xy, b_idx = _branch(pts, rows, back, -1, source)
    return IndicatorCard(source, pts, rows, f_xy, b_xy, False, f_idx, b_idx)


def _walk(a: int, b: int, n: int) -> list[int]:
    out = [a]
    while out[-1] != b:
        out.append((out[-1] + 1) % n)
    return out


def _branch(pts, rows, idx: Sequence[int], sign: int, source: str):
    """(x increasing, p) along one branch and its point indices; x must not turn back; a vertical run keeps the
    pressure the piston meets."""
    xs, ps, kept = [], [], []
    for k, i in enumerate(idx):
        x, p = pts[i]
        if xs and (x - xs[-1]) * sign < 0.0:
            word = "forward (x increasing)" if sign > 0 else "return (x decreasing)"
            raise _fail(source, rows[i], f"x = {x:g} turns back on the {word} branch (after x = {xs[-1]:g}): "
                        f"each stroke's line must run one way")
        if xs and x == xs[-1]:
            if len(xs) == 1:  # the start of the branch: the piston leaves at the end of the run
                ps[-1] = p
                kept[-1] = i
            continue  # elsewhere: the pressure the piston met first
        xs.append(x)
        ps.append(p)
        kept.append(i)
    if sign < 0:
        xs.reverse()
        ps.reverse()
        kept.reverse()
    return (tuple(xs), tuple(ps)), tuple(kept)


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


# --------------------------------------------------------------------------
# A card as givens of a construction, and drawn with compass and straightedge.
# --------------------------------------------------------------------------


def card_givens(card: IndicatorCard, prefix: str) -> dict[str, float]:
    """The card's points as givens of a protocol: ``{prefix}x{i}``, ``{prefix}p{i}`` (a replay can change them)."""
    out: dict[str, float] = {}
    for i, (x, p) in enumerate(card.points):
        out[f"{prefix}x{i}"] = x
        out[f"{prefix}p{i}"] = p
    return out


def card_from_givens(givens: Any, prefix: str, source: str = "in the protocol") -> IndicatorCard | None:
    """The card a protocol's givens hold under *prefix* (None if none), checked as a file is (rows = points + 1)."""
    pts = []
    while f"{prefix}x{len(pts)}" in givens:
        i = len(pts)
        pts.append((givens[f"{prefix}x{i}"], givens[f"{prefix}p{i}"]))
    if not pts:
        return None
    pts.append(pts[0])  # the loop closed where it began (the card keeps its points without the repeat)
    text = "x,p\n" + "".join(f"{float(x)!r},{float(p)!r}\n" for x, p in pts)
    return parse_indicator_csv(text, source)


@dataclass(frozen=True)
class DrawnCard:
    """Object names of a card drawn into a figure: the straightedge lines of its two strokes."""

    forward: str   #: polyline of the forward stroke's branch (x increasing), continued level to both dead centres
    back: str      #: polyline of the return stroke's branch
    forward_points: tuple[str, ...] = ()  #: the forward polyline's points in order (its chords' ends)
    back_points: tuple[str, ...] = ()     #: the return polyline's points in order


def draw_card(b: Any, card: IndicatorCard, *, prefix: str, head: str, crank: str, axis: str,
              stroke: Sequence[str] = ("r",), stroke_factor: float = 2.0,
              pressure_scale: Sequence[str] = ("pressure_unit",), mirrored: bool = False,
              up: tuple[str, str] | None = None, given_prefix: str | None = None, de: str = "",
              en: str = "") -> DrawnCard:
    """Plot the card's points from their givens (x by the compass along the stroke from *head*, p up the
    perpendicular) and join each stroke's points with the straightedge.

    *mirrored*: the same givens (named by *given_prefix*) plotted from the other dead centre (*head* is then the
    crank end): the crank side's card under Baumann's assumption; its forward stroke is the cover card's return
    branch.  *up* (two
    points of the stroke line) says which side the pressures stand on (left of up[0] -> up[1]; default
    head -> crank).  The branches are continued level to the dead centres where the card stops short (within
    its stated tolerance) so every ordinate of the stroke meets them.
    """
    up = up or (head, crank)
    gp = prefix if given_prefix is None else given_prefix  # the givens' names (a mirrored card reads another's)
    pts: dict[int, str] = {}
    with b.group(f"indicator card {en}: its points plotted", f"Indikatordiagramm {de}: die Punkte aufgetragen"):
        v0 = b.erect_perpendicular(f"{prefix}v0", head, axis, crank)
        v1 = b.erect_perpendicular(f"{prefix}v1", crank, axis, head)
        for i, (x, p) in enumerate(card.points):
            if x == 0.0:  # on a dead centre: no opening to take (a compass opened to nothing draws nothing)
                foot, perp = head, v0
            elif x == 1.0:
                foot, perp = crank, v1
            else:
                lx = b.given_length(f"{prefix}lx{i}", product=(f"{gp}x{i}", *stroke), factor=stroke_factor,
                                    de=f"Kolbenweg x{i}", en=f"piston path x{i}")
                k = b.circle_radius(f"{prefix}F{i}.k", head, lx, de=f"x{i} vom Totpunkt aus", en=f"x{i} from the dead centre")
                foot = b.intersect(f"{prefix}F{i}", axis, k, rule=("toward", head, crank), de=f"Fußpunkt {i}",
                                   en=f"foot {i}")
                perp = b.erect_perpendicular(f"{prefix}o{i}", foot, axis, head)
            if p == 0.0:
                pts[i] = foot
                continue
            lp = b.given_length(f"{prefix}lp{i}", product=(f"{gp}p{i}", *pressure_scale),
                                de=f"Druck p{i}", en=f"pressure p{i}")
            k = b.circle_radius(f"{prefix}C{i}.k", foot, lp, de=f"p{i} im Druckmaßstab", en=f"p{i} in the pressure scale")
            pts[i] = b.intersect(f"{prefix}C{i}", perp, k, rule=("left", *up), role="result",
                                 de=f"Punkt {i} des Diagramms", en=f"point {i} of the diagram")
    fwd_idx, back_idx = (card.forward_index, card.back_index)
    xs_f, xs_b = card.forward[0], card.back[0]
    if mirrored:  # seen from the other dead centre the strokes change places
        fwd_idx, back_idx = tuple(reversed(card.back_index)), tuple(reversed(card.forward_index))
        xs_f, xs_b = tuple(1.0 - x for x in reversed(card.back[0])), tuple(1.0 - x for x in reversed(card.forward[0]))
    out = []
    vertices = []
    with b.group(f"indicator card {en}: each stroke's line with the straightedge",
                 f"Indikatordiagramm {de}: die Linie jedes Hubes mit dem Lineal"):
        b.polyline(f"{prefix}loop", [pts[i] for i in range(len(card.points))], closed=True,
                   de="das Diagramm, wie digitalisiert, geschlossen", en="the card as digitised, closed")
        for name, idx, xs, what in (("fwd", fwd_idx, xs_f, ("Hingang", "forward stroke")),
                                    ("back", back_idx, xs_b, ("Rückgang", "return stroke"))):
            names = [pts[i] for i in idx]
            ends = []
            for end, x_end, target, perp in (("s", xs[0], 0.0, v0), ("e", xs[-1], 1.0, v1)):
                if x_end == target:
                    ends.append(None)
                    continue
                point = names[0] if end == "s" else names[-1]
                level = b.parallel_through(f"{prefix}{name}.{end}.h", point, head, crank)
                ends.append(b.intersect(f"{prefix}{name}.{end}", level, perp, rule=("only",),
                                        de="Linie waagerecht bis zum Totpunkt fortgesetzt",
                                        en="line continued level to the dead centre"))
            line = ([ends[0]] if ends[0] else []) + names + ([ends[1]] if ends[1] else [])
            vertices.append(tuple(line))
            out.append(b.polyline(f"{prefix}{name}", line, de=f"{what[0]}: Punkte mit dem Lineal verbunden",
                                  en=f"{what[1]}: the points joined with the straightedge"))
    return DrawnCard(out[0], out[1], vertices[0], vertices[1])


def _card_key(givens: Mapping[str, float], prefix: str = "") -> tuple:
    return (prefix,) + tuple(sorted((k, float(v)) for k, v in givens.items()
                                    if k.startswith((f"{prefix}card.", f"{prefix}crank."))))


_CARDS: dict[tuple, tuple[IndicatorCard, IndicatorCard]] = {}


def card_pair(givens: Mapping[str, float], prefix: str = "") -> tuple[IndicatorCard, IndicatorCard]:
    """(cover side, crank side) from a figure's givens: the crank side's own card, or the cover side's mirrored.

    *prefix* names another cylinder's cards (``lp.``: a compound engine's low-pressure cylinder)."""
    key = _card_key(givens, prefix)
    if key not in _CARDS:
        if len(_CARDS) > 64:  # a small memo: the checks read the cards for every model value
            _CARDS.clear()
        cover = card_from_givens(givens, f"{prefix}card.", f"{prefix}(cover side) in the givens")
        crank = card_from_givens(givens, f"{prefix}crank.", f"{prefix}(crank side) in the givens") or cover.mirrored()
        _CARDS[key] = (cover, crank)
    return _CARDS[key]


def card_force(givens: Mapping[str, float], lam: float, prefix: str = "") -> Any:
    """The over-pressure (at) along the motion as a function of the crank angle over the whole turn (arrays)."""
    cover, crank = card_pair(givens, prefix)

    def force(w: Any) -> Any:
        w = np.asarray(w, dtype=float)
        x = analytic.piston_fraction(w, lam)
        fwd = np.interp(x, *cover.forward) - np.interp(x, *crank.forward)
        back = np.interp(x, *crank.back) - np.interp(x, *cover.back)
        return np.where(np.mod(w, 2.0 * math.pi) <= math.pi, fwd, back)

    return force
