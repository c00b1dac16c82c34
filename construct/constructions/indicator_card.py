"""A digitised indicator diagram ("Indikatordiagramm"): the user's own card, read from a CSV file.

Seed 001 (Abb. 1054) takes the piston's over-pressure from the *measured*
diagrams of the cover side and the crank side.  A card is given as a CSV
file with the header ``x,p``: the closed loop of one cylinder side in drawing
order, ``x`` the piston position from the head-end dead centre as a fraction
of the stroke, ``p`` the absolute pressure in kg/cm² (at).  What a German
spreadsheet exports reads as well: the header ``x;p`` (or tab-separated) says
the fields are separated by semicolons (tabs), and then a decimal comma
(``0,5;4,85``) is a decimal point; a byte-order mark and Windows line ends
are allowed (:func:`csv_dialect` tells which a file is).

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
>>> parse_indicator_csv("\\ufeffx;p\\r\\n0;8\\r\\n0,3;8\\r\\n1;2,5\\r\\n1;1,1\\r\\n0,1;1,1\\r\\n0;2\\r\\n0;8\\r\\n",
...                     "demo").pressure(0.15, "forward")          # as a German spreadsheet writes it
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

__all__ = ["IndicatorCard", "parse_indicator_csv", "csv_dialect", "DIALECTS", "load_indicator", "card_givens", "card_from_givens", "draw_card",
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


#: The field separators a card may use, by what its header shows: the comma (decimal points), or -- as German
#: spreadsheets export -- the semicolon or the tab (decimal commas allowed).
DIALECTS = {",": "comma-separated, decimal points", ";": "semicolon-separated, decimal commas allowed",
            "\t": "tab-separated, decimal commas allowed"}


def csv_dialect(text: str) -> str:
    """The field separator of a card, read off its header line: ``;`` or a tab where the header has one, else ``,``.

    >>> csv_dialect("x,p\\n0,1\\n"), csv_dialect("\\ufeffx;p\\r\\n0,5;4,85\\r\\n"), csv_dialect("x\\tp\\n")
    (',', ';', '\\t')
    """
    header = text.lstrip("\ufeff").split("\n", 1)[0]
    return ";" if ";" in header else "\t" if "\t" in header else ","


def _number(cell: str, delimiter: str) -> float:
    """A cell as a number: with ``;`` or tab between the fields a decimal comma (4,85) is a decimal point."""
    cell = cell.strip()
    if delimiter != "," and "," in cell and "." not in cell:
        cell = cell.replace(",", ".", 1) if cell.count(",") == 1 else cell
    return float(cell)


def parse_indicator_csv(text: str, source: str) -> IndicatorCard:
    """The card in *text* (a CSV with header ``x,p``, or ``x;p`` with decimal commas), checked as described in the
    module; *source* names it."""
    text = text.lstrip("\ufeff")
    delimiter = csv_dialect(text)
    reader = csv.reader(io.StringIO(text), delimiter=delimiter)
    try:
        table = list(reader)
    except csv.Error as exc:
        raise _fail(source, reader.line_num, f"not a CSV file ({exc})") from None
    if not table or [c.strip().lower() for c in table[0]] != ["x", "p"]:
        got = delimiter.join(table[0])[:40] if table else "an empty file"
        raise _fail(source, 1, f"the header must be 'x,p' (or 'x;p' with decimal commas, as a German spreadsheet "
                               f"exports it), got {got!r}")
    pts: list[tuple[float, float]] = []
    rows: list[int] = []
    for i, cells in enumerate(table[1:], start=2):
        if not cells or all(not c.strip() for c in cells):
            continue  # a blank line
        if len(cells) != 2:
            hint = (" (decimal commas need ';' between the fields: a header 'x;p')"
                    if delimiter == "," and len(cells) in (3, 4) else "")
            raise _fail(source, i, f"a row holds two numbers x{delimiter}p; this one has {len(cells)} fields{hint}")
        vals = []
        for name, cell in zip("xp", cells):
            try:
                v = _number(cell, delimiter)
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
        if len(pts) > MAX_POINTS or (len(pts) == MAX_POINTS and (x, p) != pts[0]):  # the closing repeat is free
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
    """Refuse a loop whose chords cross (other than neighbours meeting at their common point).

    Only chords whose x-ranges overlap can cross: sorted by where they begin, each is tested against those
    beginning within its range -- a card of two strokes has a few such pairs per chord, so thousands of points
    cost milliseconds (numpy, in blocks of pairs), where testing every pair cost seconds.
    """
    a = np.array([(x, p / height) for x, p in pts])
    b = np.roll(a, -1, axis=0)
    n = len(a)
    lo, hi = np.minimum(a[:, 0], b[:, 0]), np.maximum(a[:, 0], b[:, 0])
    order = np.argsort(lo, kind="stable")
    starts = lo[order]
    # for the k-th chord in that order, the later ones that begin inside its x-range
    ends = np.searchsorted(starts, hi[order], side="right")
    counts = np.maximum(ends - np.arange(n) - 1, 0)
    first = np.repeat(order, counts)
    second = order[np.concatenate([np.arange(k + 1, e) for k, e in zip(range(n), ends) if e > k + 1] or
                                  [np.zeros(0, dtype=int)])]
    i, j = np.minimum(first, second), np.maximum(first, second)
    keep = (j - i > 1) & ~((i == 0) & (j == n - 1))   # neighbours share a point: that is no crossing
    i, j = i[keep], j[keep]
    d = b - a
    hits = []
    for s0 in range(0, i.size, 1_000_000):  # blocks bound the memory for a pathological card
        ii, jj = i[s0:s0 + 1_000_000], j[s0:s0 + 1_000_000]
        p, r, q, t_ = a[ii], d[ii], a[jj], d[jj]
        denom = r[:, 0] * t_[:, 1] - r[:, 1] * t_[:, 0]
        qp = q - p
        with np.errstate(divide="ignore", invalid="ignore"):
            t = (qp[:, 0] * t_[:, 1] - qp[:, 1] * t_[:, 0]) / denom
            u = (qp[:, 0] * r[:, 1] - qp[:, 1] * r[:, 0]) / denom
        eps = 1e-12
        hit = (np.abs(denom) > eps) & (t > eps) & (t < 1 - eps) & (u > eps) & (u < 1 - eps)
        hits += [(int(x), int(y)) for x, y in zip(ii[hit], jj[hit])]
    if hits:
        i0, k = min(hits)
        raise _fail(source, rows[(i0 + 1) % n], f"the loop crosses itself: the chord from row {rows[i0]} to row "
                    f"{rows[(i0 + 1) % n]} crosses the chord from row {rows[k]} to row {rows[(k + 1) % n]}")


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


def draw_card(b: Any, card: IndicatorCard, *, prefix: str, head: str, crank: str, axis: str,
              stroke: Sequence[str] = ("r",), stroke_factor: float = 2.0,
              pressure_scale: Sequence[str] = ("pressure_unit",), mirrored: bool = False,
              up: tuple[str, str] | None = None, given_prefix: str | None = None, de: str = "",
              en: str = "") -> DrawnCard:
    """Trace the card onto the drawing from its givens -- each point x along the stroke from *head*, p up the
    perpendicular, as the draftsman copies an indicator card with his scale -- and join each stroke's points with
    the straightedge: one step for the loop as digitised, one for each stroke's line.

    *mirrored*: the same givens (named by *given_prefix*) traced from the other dead centre (*head* is then the
    crank end): the crank side's card under Baumann's assumption; its forward stroke is the cover card's return
    branch.  *up* (two points of the stroke line) says which side the pressures stand on (left of up[0] -> up[1];
    default head -> crank).  The branches are continued level to the dead centres where the card stops short
    (within its stated tolerance) so every ordinate of the stroke meets them.  A card of thousands of points is
    three steps, not thousands: the readings are where the ordinates meet the traced lines.

    *axis* is the stroke line the card stands on (kept for the callers' symmetry: the trace needs its ends only).
    """
    up = up or (head, crank)
    gp = prefix if given_prefix is None else given_prefix  # the givens' names (a mirrored card reads another's)
    fwd_idx, back_idx = card.forward_index, card.back_index
    if mirrored:  # seen from the other dead centre the strokes change places
        fwd_idx, back_idx = tuple(reversed(card.back_index)), tuple(reversed(card.forward_index))
    params = {"stroke": tuple(stroke), "stroke_factor": stroke_factor, "pressure": tuple(pressure_scale)}

    def names(idx):
        return {"xs": tuple(f"{gp}x{i}" for i in idx), "ps": tuple(f"{gp}p{i}" for i in idx)}

    out = []
    with b.group(f"indicator card {en}: traced, each stroke's line with the straightedge",
                 f"Indikatordiagramm {de}: übertragen, die Linie jedes Hubes mit dem Lineal"):
        b.record("curve", "trace", (head, crank, *up), (f"{prefix}loop",),
                 {**names(range(len(card.points))), **params, "closed": True},
                 f"das Diagramm {de}, wie digitalisiert, mit dem Maßstab übertragen",
                 f"the card {en} as digitised, traced with the scale", role="result")
        for name, idx, what in (("fwd", fwd_idx, ("Hingang", "forward stroke")),
                                ("back", back_idx, ("Rückgang", "return stroke"))):
            # x runs from the head in the givens; traced from the crank end a mirrored card's x is 1 - x there,
            # which the trace does by starting at *head* (the crank end) -- the order of the points is the stroke's
            b.record("curve", "trace", (head, crank, *up), (f"{prefix}{name}",),
                     {**names(idx), **params, "extend": True},
                     f"{what[0]}: Punkte mit dem Lineal verbunden, waagerecht bis zu den Totpunkten",
                     f"{what[1]}: the points joined with the straightedge, level to the dead centres", role="result")
            out.append(f"{prefix}{name}")
    return DrawnCard(out[0], out[1])


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
