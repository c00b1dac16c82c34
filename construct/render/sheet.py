"""How a scene sits on its sheet: what a book plate shows (:func:`plate_names`), the panels it lays its
diagrams out in (:func:`lay_out`), the broken axis of a long stroke line (:func:`broken_axis`), and the
warning for a lettered point a plate leaves out (:func:`warn_hidden_labels`)."""

from __future__ import annotations

import dataclasses
import functools
import math
import os
import re
import sys
import warnings
from typing import TYPE_CHECKING, Callable, NamedTuple

from ..kernel.errors import HiddenLabelWarning
from ..kernel.geometry import Circle, Line, Point
from ..kernel.protocol import Protocol, Replay
from .marks import Mark, MarkKind, extreme_points, lies_on, mark_box, with_geom

if TYPE_CHECKING:  # (numpy is imported where it is used: the annotations name it)
    import numpy as np

__all__ = ["BREAK_FRACTION", "BREAK_FRACTION_Y", "BREAK_KEEP", "PLATE_BREAK_KEEP", "Break", "broken_axis", "broken",
           "breaks_figure", "kept_span", "span_of", "warn_hidden_labels", "lay_out", "plate_names", "moved_geom", "break_shift"]


#: A gap wider than this fraction of the figure, with nothing drawn in it, is broken out of the axis.
BREAK_FRACTION = 0.2


#: The same across the figure (a far point below it: the proportional angle's vertex S a rod's length under the
#: crank, Fig. 27): a tall figure is broken only where the gap is wider than this, so that the books' own
#: figures (at their rod ratios, S up to 6 r below) are drawn whole, as the books draw them.
BREAK_FRACTION_Y = 0.3


#: Width the broken-out stretch keeps, as a fraction of what remains of the figure.
BREAK_KEEP = 0.07


#: The same on a plate, where the rod is drawn across the break to its crosshead.
PLATE_BREAK_KEEP = 0.55


class Break(NamedTuple):
    """A stretch broken out of the figure: where the drawn break starts (x, or y for ``axis`` 1; drawing units),
    its drawn width, and the length it leaves out."""

    start: float
    width: float
    left_out: float
    axis: int = 0


def _extents(marks: list[Mark]) -> "np.ndarray":
    """The box (x0, y0, x1, y1) of each mark a broken axis keeps clear of its gap, one row each (:func:`_widest_gap`):
    every point, circle, arc, area and curve but the lines (the stroke line spans everything; a rod drawn to its
    crosshead -- a straight curve of two points -- crosses the break), in one pass.  The same numbers as
    :func:`extreme_points` gives (:func:`mark_box`): a break along x moves no y, so its rows' y serve the break
    across it too."""
    import numpy as np

    point, segment, curve = MarkKind.POINT, MarkKind.SEGMENT, MarkKind.CURVE
    flat: list[float] = []
    for m in marks:
        k = m.kind
        if k is point:  # (most marks: a long figure's points)
            x, y = m.geom
            flat += (x, y, x, y)
        elif k is segment or (k is curve and m.straight and len(m.geom) == 2):
            continue
        else:
            box = mark_box(m)
            if box is not None:
                flat += box
    return np.array(flat, dtype=float).reshape(-1, 4)


def _widest_gap(marks: list[Mark], furniture: tuple, axis: int, fraction: float,
                extents: "np.ndarray | None" = None) -> tuple[float, float, float] | None:
    """(start, end, total) of the widest empty stretch along *axis* that :func:`broken_axis` breaks out, or None
    when none is wider than *fraction* of the figure.  *extents*: the marks' :func:`_extents`, if made already.

    The walk of a draftsman's eye along the axis, on arrays: the marks' spans sorted by start (then end), the
    reach of those before each, the first widest stretch between a reach and the next start.
    """
    import numpy as np

    from .plate import anchors

    ext = _extents(marks) if extents is None else extents
    lo, hi = ext[:, axis], ext[:, axis + 2]
    own = [p[axis] for p in anchors(furniture)]
    if own:
        lo, hi = np.concatenate([lo, own]), np.concatenate([hi, own])
    if len(lo) < 2:
        return None
    order = np.lexsort((hi, lo))
    lo, hi = lo[order], hi[order]
    total = float(hi[-1] - lo[0])
    reach = np.maximum.accumulate(hi)[:-1]
    gaps = lo[1:] - reach
    i = int(np.argmax(gaps))  # the first of the widest
    if not gaps[i] > 0.0 or gaps[i] <= fraction * total:
        return None
    return float(reach[i]), float(lo[i + 1]), total


def broken_axis(marks: list[Mark], furniture: tuple = (), keep_fraction: float = 0.07, axis: int = 0,
                fraction: float = BREAK_FRACTION, *, extents: "np.ndarray | None" = None
                ) -> tuple[list[Mark], tuple, tuple[Break, ...]]:
    """Break the widest empty stretch out of the figure, as a draftsman breaks a long axis.

    The crossheads lie a rod length (5 r) to the left of the crank circle;
    drawn to scale, the circle sits in a corner of an empty sheet.  Marks
    wholly left of the empty stretch move right by what it loses; lines
    that cross it (the stroke line) keep their right end and move their
    left one (a line's end drawn a margin past its last point moves with the
    side it is nearer).  A plate's furniture (the rod drawn to its crosshead)
    is broken the same way.  *axis* 1 breaks across the figure instead: marks
    wholly below the stretch move up (a vertex a rod's length below the
    crank).  Returns the marks, the furniture and (:class:`Break`,) or ()
    when there is no gap wider than *fraction* of the figure.  *extents*: the marks' boxes
    (:func:`_extents`), if made already.
    """
    from .plate import shifted

    gap = _widest_gap(marks, furniture, axis, fraction, extents)
    if gap is None:
        return marks, furniture, ()
    lo, hi, total = gap
    keep, shift = _kept_of(gap, keep_fraction)

    def sx(x: float) -> float:
        return x + shift if x <= lo else x

    def end(x: float) -> float:  # a line's end, drawn a margin past its last point: with the side it is nearer
        return x + shift if x <= (lo + hi) / 2 else x

    def same(v: float) -> float:  # the other axis stays
        return v

    maps, ends = ((sx, same), (end, same)) if axis == 0 else ((same, sx), (same, end))
    out = []
    for m in marks:
        g = moved_geom(m, *maps, ends=ends)
        out.append(m if g == m.geom else with_geom(m, g))
    # the near stretch now ends at hi - keep: the kept piece of the broken axis is [hi - keep, hi]
    moved = tuple(shifted(it, sx) for it in furniture) if axis == 0 else furniture
    return out, moved, (Break(hi - keep, keep, hi - lo, axis),)


def _kept_of(gap: tuple[float, float, float], keep_fraction: float) -> tuple[float, float]:
    """How much of the gap (start, end, total) a broken axis keeps, and how far what lies before it moves."""
    lo, hi, total = gap
    keep = min(keep_fraction * (total - (hi - lo)), 0.8 * (hi - lo))
    return keep, (hi - lo) - keep


def moved_geom(m: Mark, x: Callable[[float], float], y: Callable[[float], float], *,
               ends: "tuple[Callable[[float], float], Callable[[float], float]] | None" = None) -> tuple:
    """A mark's geometry with x mapped by *x* and y by *y*, as a broken axis moves it: a point, and a curve's or
    an area's points, each; a segment's ends by the maps *ends* (*x*, *y* when None); a circle or an arc whole,
    by what its far point (rightmost, lowest) moves: a circle is not stretched.

    >>> def sx(v): return v + 5.0 if v <= 2.0 else v
    >>> def same(v): return v
    >>> circle = Mark("c", 1, "k", MarkKind.CIRCLE, (0.0, 0.0, 1.0), "construction", "compass", "exact")
    >>> moved_geom(circle, sx, same), moved_geom(with_geom(circle, (2.0, 0.0, 1.0)), sx, same)
    ((5.0, 0.0, 1.0), (2.0, 0.0, 1.0))
    """
    g = m.geom
    if m.kind is MarkKind.POINT:
        return (x(g[0]), y(g[1]))
    if m.kind is MarkKind.SEGMENT:
        ex, ey = ends or (x, y)
        return (ex(g[0]), ey(g[1]), ex(g[2]), ey(g[3]))
    if m.kind.round:
        far = extreme_points(m)
        right, low = max(p[0] for p in far), max(p[1] for p in far)
        return (g[0] + (x(right) - right), g[1] + (y(low) - low)) + tuple(g[2:])
    return tuple((x(px), y(py)) for px, py in g)


def break_shift(breaks: tuple, axis: int = 0) -> Callable[[float], float]:
    """The map of x (of y for *axis* 1) that a broken axis (:attr:`Scene.breaks`) applies to what lies before
    its gap.

    >>> sx = break_shift(((10.0, 1.0, 6.0),))  # drawn from 10 to 11, standing for 6: [5, 11] became [10, 11]
    >>> sx(2.0), sx(12.0)
    (7.0, 12.0)
    >>> break_shift(((10.0, 1.0, 6.0, 1),))(2.0)  # a break across the figure moves y, not x
    2.0
    """
    moves = [(b[0] + b[1] - b[2], b[2] - b[1]) for b in breaks if (b[3] if len(b) > 3 else 0) == axis]

    def shift(v: float) -> float:
        for lo, by in moves:
            if v <= lo:
                v += by
        return v

    return shift


def broken(marks: list[Mark], furniture: tuple, whole: bool) -> tuple[list[Mark], tuple, tuple[Break, ...]]:
    """The figure broken along x (:func:`broken_axis`) and, unless a plate (*whole* false: a plate keeps its
    sheet, the books draw S whole), across it."""
    extents = _extents(marks)  # (a break along x moves no y: the break across asks the same boxes)
    marks, furniture, breaks = broken_axis(marks, furniture, BREAK_KEEP if whole else PLATE_BREAK_KEEP,
                                           extents=extents)
    if whole and not furniture:
        marks, _, across = broken_axis(marks, (), BREAK_KEEP, axis=1, fraction=BREAK_FRACTION_Y, extents=extents)
        breaks += across
    return marks, furniture, breaks


def breaks_figure(marks: list[Mark], furniture: tuple, whole: bool) -> bool:
    """Would :func:`broken` break the figure (along x or, when *whole* and without furniture, across it)?  Asked
    without moving a mark: breaking along x moves no y."""
    extents = _extents(marks)
    if _widest_gap(marks, furniture, 0, BREAK_FRACTION, extents) is not None:
        return True
    return whole and not furniture and _widest_gap(marks, (), 1, BREAK_FRACTION_Y, extents) is not None


def kept_span(marks: list[Mark]) -> float:
    """What the figure's points and curves span once broken alone (:func:`broken`; as they are, unbroken): a
    broken figure's margin is a share of it."""
    import numpy as np

    drawn = [m for m in marks if m.kind in (MarkKind.POINT, MarkKind.CURVE, MarkKind.AREA)]
    if not drawn:
        return 1e-9
    # what broken(drawn, (), True) does to their coordinates, on arrays: a point before a gap moves by its shift
    ext = _extents(drawn)
    pts = [m.geom for m in drawn if m.kind is MarkKind.POINT] + [p for m in drawn if m.kind is not MarkKind.POINT
                                                                 for p in m.geom]
    if not pts:
        return 1e-9
    xy = np.array(pts, dtype=float).reshape(-1, 2)
    for axis, fraction in ((0, BREAK_FRACTION), (1, BREAK_FRACTION_Y)):  # (a break along x moves no y)
        gap = _widest_gap(drawn, (), axis, fraction, ext)
        if gap is not None:
            v = xy[:, axis]
            xy[:, axis] = np.where(v <= gap[0], v + _kept_of(gap, BREAK_KEEP)[1], v)
    x, y = xy[:, 0], xy[:, 1]
    return max(float(x.max() - x.min()), float(y.max() - y.min()), 1e-9)


def span_of(marks: list[Mark]) -> float:
    """The larger side of the box of the marks' points and curves (what the margin is a share of)."""
    pts = [m.geom for m in marks if m.kind is MarkKind.POINT]
    pts += [p for m in marks if m.kind in (MarkKind.CURVE, MarkKind.AREA) for p in m.geom]
    if not pts:
        return 1e-9
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)


def warn_hidden_labels(protocol: Protocol, objects: Replay, shown: set[str]) -> list[tuple[str, str]]:
    """Warn once for the figure (:class:`~construct.kernel.errors.HiddenLabelWarning`) when its plate leaves out
    lettered points; return them as (name, letter).

    Only a plate the library chooses is asked (:func:`plate_names` without the protocol's ``plate`` list):
    there a letter the user set on a point that locates no result would vanish without a word.  A
    construction that names its plate's objects (every book construction) leaves its other letters out on
    purpose, as its book does.

    >>> from construct import Builder
    >>> b = Builder("demo", givens={})
    >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 4.0, 0.0)
    >>> _ = b.midpoint("M", "A", "B"); b.set_label("M", "M"); _ = b.line("g", "A", "B", role="result")
    >>> fig = b.figure()
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     warn_hidden_labels(fig.protocol, fig.replay, plate_names(fig.protocol, fig.replay))
    [('M', 'M')]
    >>> print(caught[0].message)
    the plate (historical style) leaves out point M lettered 'M': it shows the results and what locates them; give M role="result", or name what the plate shows in params["plate"], to letter it there
    """
    if protocol.params.get("plate"):
        return []
    hidden = [(name, text) for s in protocol.steps for name, text in s.labels
              if name not in shown and isinstance(objects.get(name), Point)]
    if hidden:
        names = ", ".join(f"{n} lettered {t!r}" for n, t in hidden[:8]) + (", ..." if len(hidden) > 8 else "")
        which = "point" if len(hidden) == 1 else f"{len(hidden)} points:"
        them = hidden[0][0] if len(hidden) == 1 else "them"
        warnings.warn(HiddenLabelWarning(
            f"the plate (historical style) leaves out {which} {names}: it shows the results and what locates "
            f'them; give {them} role="result", or name what the plate shows in params["plate"], to letter '
            f"{'it' if len(hidden) == 1 else 'them'} there"), stacklevel=_caller_level())
    return hidden


#: This package's folder: a warning points at the first line outside it (the user's ``fig.svg(...)``).
_PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__))) + os.sep


def _caller_level() -> int:
    """The ``stacklevel`` (for a warning raised by this function's caller) of the first frame outside the package.

    The drawing is reached by several paths (``Figure.svg``, ``construct.svg``, ``write_replay``), each
    a different depth below the user's line; the warning should name that line, not ours.
    """
    frame, level = sys._getframe(2), 2  # 1 is the function that warns
    while frame is not None and frame.f_code.co_filename.startswith(_PACKAGE):
        frame, level = frame.f_back, level + 1
    return level


def lay_out(marks: list[Mark], panels: tuple, margin: float, tol: float) -> list[Mark]:
    """The marks laid out in a plate's panels: each mark drawn once in every panel whose patterns match its
    name, moved by that panel's shift; a mark no panel names stays.

    A line drawn in a panel reaches over that panel's points on it (plus *margin*, as every line does), so
    the stroke line under two diagrams is drawn under each; copies that fall on one line (an ordinate through
    two panels one above the other) are drawn as one line over all their points.  The first copy keeps the
    mark's id, the others add ``-panel<j>``.

    >>> from construct.render.plate import Panel
    >>> p = Mark("p", 1, "P", "point", (0.0, 0.0), "result", "", "")
    >>> q = Mark("q", 1, "Q", "point", (1.0, 0.0), "result", "", "")
    >>> ax = Mark("ax", 1, "axis", "segment", (-9.0, 0.0, 9.0, 0.0), "result", "", "")
    >>> out = lay_out([p, q, ax], (Panel(("P", "Q", "axis")), Panel(("Q", "axis"), (0.0, 3.0))), 0.5, 1e-9)
    >>> [(m.id, m.geom) for m in out]  # doctest: +NORMALIZE_WHITESPACE
    [('p', (0.0, 0.0)), ('q', (1.0, 0.0)), ('q-panel1', (1.0, 3.0)),
     ('ax', (-0.5, 0.0, 1.5, 0.0)), ('ax-panel1', (-1.5, 3.0, 3.5, 3.0))]
    """
    pats = [[re.compile(p) for p in panel.names] for panel in panels]
    homes = {m.id: [i for i, ps in enumerate(pats) if any(p.fullmatch(m.name) for p in ps)] for m in marks}
    points = [[m.geom for m in marks if m.kind is MarkKind.POINT and i in homes[m.id]] for i in range(len(panels))]
    out: list[Mark] = []
    for m in marks:
        ins = homes[m.id]
        if not ins:
            out.append(m)
            continue
        if m.kind is MarkKind.SEGMENT:
            geoms = _segment_copies(m.geom, [(tuple(panels[i].shift), points[i]) for i in ins], margin, tol)
        else:
            geoms = [_moved(m, tuple(panels[i].shift)) for i in ins]
        out.extend(dataclasses.replace(m, id=m.id if j == 0 else f"{m.id}-panel{j}", geom=g)
                   for j, g in enumerate(geoms))
    return out


def _moved(m: Mark, shift: tuple[float, float]) -> tuple:
    dx, dy = shift
    g = m.geom
    if m.kind is MarkKind.POINT:
        return (g[0] + dx, g[1] + dy)
    if m.kind is MarkKind.SEGMENT:
        return (g[0] + dx, g[1] + dy, g[2] + dx, g[3] + dy)
    if m.kind.round:
        return (g[0] + dx, g[1] + dy) + tuple(g[2:])
    return tuple((x + dx, y + dy) for x, y in g)  # curve, area


def _segment_copies(geom: tuple, homes: list, margin: float, tol: float) -> list[tuple]:
    """A segment's copies, one per (shift, that panel's points): each over the points on it, collinear ones merged."""
    x1, y1, x2, y2 = geom
    length = math.hypot(x2 - x1, y2 - y1) or 1.0
    ux, uy = (x2 - x1) / length, (y2 - y1) / length
    nx, ny = -uy, ux
    lines: list[list[float]] = []  # [offset across, t0, t1] in the frame of the unmoved line
    for (dx, dy), pts in homes:
        on = [(px - x1) * ux + (py - y1) * uy for px, py in pts
              if abs((px - x1) * nx + (py - y1) * ny) <= tol * max(1.0, length)]
        if on:
            pad = margin * (5.0 if max(on) - min(on) <= tol * max(1.0, length) else 1.0)
            t0, t1 = min(on) - pad, max(on) + pad
        else:
            t0, t1 = 0.0, length
        off, along = dx * nx + dy * ny, dx * ux + dy * uy
        for ln in lines:
            if abs(ln[0] - off) <= tol * max(1.0, length):
                ln[1], ln[2] = min(ln[1], t0 + along), max(ln[2], t1 + along)
                break
        else:
            lines.append([off, t0 + along, t1 + along])
    return [(x1 + off * nx + t0 * ux, y1 + off * ny + t0 * uy, x1 + off * nx + t1 * ux, y1 + off * ny + t1 * uy)
            for off, t0, t1 in lines]


def plate_names(protocol: Protocol, objects: Replay) -> set[str]:
    """What a book plate shows: results, the curves that locate them, the points those curves pass through.

    Given points stay (the crank centre); auxiliary objects and the points a
    curve is only centred on (the far crossheads of the rod arcs) do not.

    >>> from construct.constructions import get
    >>> fig = get("crank").figure(parts=6)
    >>> names = plate_names(fig.protocol, fig.replay)
    >>> {"crank", "X3", "back3", "P3", "ord2", "O"} <= names, "rod3" in names
    (True, False)
    """
    explicit = protocol.params.get("plate")
    if explicit:
        # The construction names what its book figure shows (regular expressions over object names).
        return set(_named(tuple(explicit), tuple(objects)))
    maker = {n: s for s in protocol.steps for n in s.outputs}
    shown: set[str] = set()
    curves: set[str] = set()
    for s in protocol.steps:
        if s.role == "result":
            shown.update(s.outputs)
            for name in s.inputs:
                if isinstance(objects.get(name), (Line, Circle)) or hasattr(objects.get(name), "curve_points"):
                    curves.add(name)
        elif s.op == "given_point":
            shown.update(s.outputs)
    shown |= curves
    for name in sorted(curves | {n for n in shown if isinstance(objects.get(n), (Line, Circle))}):
        s = maker[name]
        through = {"circle_through": s.inputs[1:], "line": s.inputs, "given_line": s.inputs}.get(s.op, ())
        for p in through:
            if isinstance(objects.get(p), Point) and maker[p].role != "auxiliary":
                shown.add(p)
    # Points that lie on a shown circle without the protocol saying so (the stroke
    # marks on the rod arcs of Fig. 77) belong to the plate too; helper points
    # (dotted names) and auxiliary ones do not.  Lines are not asked: every
    # crosshead lies on the stroke line, far from the plate.
    pts = [(n, o) for n, o in objects.items() if isinstance(o, Point) and n not in shown
           and "." not in n and maker[n].role != "auxiliary"]
    if pts:
        import numpy as np

        xs = [o[0] for _, o in objects.items() if isinstance(o, Point)]
        tol = 1e-9 * max(max(xs) - min(xs), 1.0)
        px, py = np.array([o[0] for _, o in pts], dtype=float), np.array([o[1] for _, o in pts], dtype=float)
        circles = [objects[name] for name in sorted(curves) if isinstance(objects[name], Circle)]
        if circles:
            # numpy's hypot may differ from math's in the last bit, so it only picks the candidates, lies_on decides
            c = np.array([(cx, cy, r) for (cx, cy), r in circles], dtype=float).reshape(-1, 3)
            for k, i in _near_circles(px, py, c, 2.0 * tol * np.maximum(1.0, c[:, 2])):
                n, o = pts[i]
                if n not in shown and lies_on(circles[k], o, tol):
                    shown.add(n)
    return shown


def _near_circles(px: "np.ndarray", py: "np.ndarray", c: "np.ndarray", e: "np.ndarray") -> list[tuple[int, int]]:
    """The pairs (circle k, point i) with the point within e[k] of the circle's line (``|hypot(p - centre) - r| <=
    e[k]``), circles c given as rows (cx, cy, r); without asking every pair (a 3600-part crank has 3600 rod arcs
    and 7200 points: 26 million distances).

    The points are filed in horizontal bands, sorted by x within each; within a band's y the ring about a circle
    lies over two stretches of x (its left and right arcs, from the band's nearest and farthest y), and only the
    points in those, widened by more than rounding, are asked.

    >>> import numpy as np
    >>> px, py = np.array([1.0, 0.0, 0.5, -1.0]), np.array([0.0, 1.0, 0.5, 0.0])
    >>> _near_circles(px, py, np.array([[0.0, 0.0, 1.0], [2.0, 0.0, 1.0]]), np.array([1e-9, 1e-9]))
    [(0, 0), (0, 1), (0, 3), (1, 0)]
    """
    import numpy as np

    m = len(px)
    if not m or not len(c):
        return []
    bands = int(min(32, max(1, math.isqrt(m))))
    y0 = float(py.min())
    h = (float(py.max()) - y0) / bands or 1.0
    band = np.minimum(((py - y0) / h).astype(np.int64), bands - 1)
    order = np.lexsort((px, band))
    band_s, x_s, y_s = band[order], px[order], py[order]
    starts = np.searchsorted(band_s, np.arange(bands + 1))
    ks = np.flatnonzero(starts[1:] > starts[:-1])  # the bands that hold points
    ylo, yhi = np.minimum.reduceat(y_s, starts[ks]), np.maximum.reduceat(y_s, starts[ks])
    # one key for (band, x): the bands apart by more than the points' x span
    xmin, xmax = float(x_s.min()), float(x_s.max())
    width = 2.0 * (xmax - xmin) + 1.0
    key = band_s * width + (x_s - xmin)
    cx, cy, r = c[:, 0:1], c[:, 1:2], c[:, 2:3]
    slack = 4.0 * e[:, None]
    dlo, dhi = ylo[None, :] - cy, yhi[None, :] - cy
    dmin = np.where(dlo > 0.0, dlo, np.where(dhi < 0.0, -dhi, 0.0))
    dmax = np.maximum(np.abs(dlo), np.abs(dhi))
    outer_r, inner_r = r + slack, np.maximum(r - slack, 0.0)
    meets = dmin <= outer_r
    outer = np.sqrt(np.maximum(outer_r * outer_r - dmin * dmin, 0.0)) + slack
    inner = np.sqrt(np.maximum(inner_r * inner_r - dmax * dmax, 0.0)) - slack
    inner = np.maximum(inner, 0.0)
    base = ks[None, :] * width
    pairs = []
    for lo, hi in ((cx - outer, cx - inner), (cx + inner, cx + outer)):  # the left arc, the right arc
        ok = meets & (hi >= xmin) & (lo <= xmax)
        a = np.searchsorted(key, (base + (np.clip(lo, xmin, xmax) - xmin))[ok], "left")
        b = np.searchsorted(key, (base + (np.clip(hi, xmin, xmax) - xmin))[ok], "right")
        n = np.maximum(b - a, 0)
        which = np.repeat(np.nonzero(ok)[0], n)
        at = np.repeat(a - np.concatenate([[0], np.cumsum(n)[:-1]]), n) + np.arange(int(n.sum()))
        pairs.append(which * m + order[at])
    both = np.unique(np.concatenate(pairs))
    k, i = both // m, both % m
    near = np.abs(np.hypot(px[i] - c[k, 0], py[i] - c[k, 1]) - c[k, 2]) <= e[k]
    return list(zip(k[near].tolist(), i[near].tolist()))


@functools.lru_cache(maxsize=8)
def _named(patterns: tuple[str, ...], names: tuple[str, ...]) -> frozenset[str]:
    """The *names* some pattern matches whole (a live sweep draws the same objects hundreds of times)."""
    compiled = [re.compile(p) for p in patterns]
    return frozenset(n for n in names if any(p.fullmatch(n) for p in compiled))
