"""What a scene is made of: marks (:class:`Mark`), how far a line or a circle is drawn to take in the points
marked on it, the points that bound a mark, and where a lettered line's letter stands.

>>> m = Mark("a", 1, "k", "arc", (0.0, 0.0, 1.0, 0.0, math.pi), "construction", "compass", "exact")
>>> pts = extreme_points(m)   # the ends and the quarter points it passes: the half circle's box
>>> m.kind is MarkKind.ARC, (min(p[0] for p in pts), max(p[0] for p in pts), round(max(p[1] for p in pts), 12))
(True, (-1.0, 1.0, 1.0))
"""

from __future__ import annotations

import collections
import dataclasses
import functools
import math
from dataclasses import dataclass
from enum import Enum
from typing import Any, Callable, Iterable, Sequence

from ..kernel.geometry import Circle, Line, Point
from ..kernel.protocol import Replay, Step

__all__ = ["could_show", "mark_box", "TWO_PI", "GAP_TIE", "widest_gap", "MarkKind", "Mark", "with_geom", "letter_lines", "fanned_lines", "letter_point", "middle",
           "lies_on", "curve_points", "segment_extent", "segment_span", "segment_at", "circle_extent", "marked_arc",
           "arc_at", "extreme_points"]


TWO_PI = 2.0 * math.pi


class MarkKind(str, Enum):
    """What a mark draws, which decides what its ``geom`` holds (:class:`Mark`).

    A ``str`` whose value is the word the drawings have always used (in CSS
    classes, JSON and captions), so that a kind compares, hashes, formats and
    serialises as that word: ``MarkKind.ARC == "arc"``, ``f"{kind}"`` is
    ``"arc"``, and a table keyed by kinds answers for the plain word too.

    >>> MarkKind("arc") is MarkKind.ARC, f"{MarkKind.ARC}", MarkKind.ARC == "arc"
    (True, 'arc', True)
    >>> [k.value for k in MarkKind if k.round], [k.value for k in MarkKind if k.stroked]
    (['circle', 'arc'], ['segment', 'circle', 'arc', 'curve'])
    """

    POINT = "point"
    SEGMENT = "segment"
    CIRCLE = "circle"
    ARC = "arc"
    CURVE = "curve"
    AREA = "area"

    # the word, not "MarkKind.ARC": on Python 3.11+ a str mix-in Enum would otherwise format by its name
    def __str__(self) -> str:
        return self.value

    def __format__(self, spec: str) -> str:
        return format(self.value, spec)

    @property
    def round(self) -> bool:
        """A circle or an arc of one: ``geom`` begins (cx, cy, r)."""
        return self is MarkKind.CIRCLE or self is MarkKind.ARC

    @property
    def stroked(self) -> bool:
        """Drawn as one line by the pen (segment, circle, arc, curve): not a dot, not a filled area."""
        return self is not MarkKind.POINT and self is not MarkKind.AREA


@dataclass(frozen=True, slots=True)
class Mark:
    """One drawable element of the figure.

    ``geom`` by kind: point (x, y); segment (x1, y1, x2, y2); circle (cx, cy, r);
    arc (cx, cy, r, start, sweep) with angles in radians, counter-clockwise in
    the y-up drawing plane; curve ((x, y), ...) drawn smooth through its points,
    or joined by straight segments when ``straight`` (a polyline: the straightedge);
    area ((x, y), ...) the ring of one hatched piece.  *kind* may be given as its
    word (``"circle"``); it is kept as a :class:`MarkKind`.
    """

    id: str
    step: int
    name: str
    kind: MarkKind
    geom: tuple
    role: str
    tool: str
    provenance: str
    label: str | None = None
    group: tuple[str, ...] = ()
    #: A line weight or pattern from the plate's description (heavy, thin, dashdot, dashed), "" = by role.
    look: str = ""
    #: Areas: the direction of their hatching in degrees (None: the style's).
    hatch: float | None = None
    #: Curves: the points are joined by straight segments (a polyline), not by a smooth curve.
    straight: bool = False

    def __post_init__(self) -> None:
        if type(self.kind) is not MarkKind:  # the word, as a caller may write it: kept as the kind
            object.__setattr__(self, "kind", MarkKind(self.kind))


def with_geom(m: Mark, geom: tuple) -> Mark:
    """*m* with another geometry (dataclasses.replace asks every field by name: a live sweep moves a thousand
    marks at hundreds of rod ratios)."""
    return Mark(m.id, m.step, m.name, m.kind, geom, m.role, m.tool, m.provenance, m.label, m.group, m.look, m.hatch,
                m.straight)


# with_geom names every field of a Mark: a field added without it would be lost on the broken axis
assert [f.name for f in dataclasses.fields(Mark)] == ["id", "step", "name", "kind", "geom", "role", "tool",
                                                      "provenance", "label", "group", "look", "hatch", "straight"]


def letter_lines(marks: list[Mark], lettered: dict, breaks: tuple) -> list[Mark]:
    """Each lettered straight line followed by the point its letter stands at.

    A line (the crank r, the stroke s = 2r) is lettered at its middle -- a rod drawn across a broken axis
    at the middle of its part beside the crank -- on a point of its own that the drawing does not show
    (look ``hidden``; an auxiliary one).  A fan of lettered lines from one point (the cranks of Tabelle 2)
    is lettered at the lines' far ends, where they stand furthest apart, beside the points they were
    drawn to, with the lines' own role (their letters are placed with the results').
    """
    out: list[Mark] = []
    for m in marks:
        out.append(m)
        got = lettered.get(m.id)
        if got is None:
            continue
        label, fan = got
        at = letter_point(m.geom, fan, breaks)
        out.append(dataclasses.replace(m, id=f"{m.id}-at", kind=MarkKind.POINT, geom=(at[0], at[1]),
                                       name=f"{m.name}.at", role=m.role if fan else "auxiliary", label=label,
                                       look="hidden", straight=False))
    return out


def fanned_lines(steps: Iterable[Step]) -> dict[str, bool]:
    """Each lettered straight line (polyline) of *steps*: is it one of a fan of three or more drawn from one
    point (the cranks of Tabelle 2), lettered at its far end rather than its middle?

    >>> from construct.constructions import get
    >>> fanned_lines(get("crank-angle").figure().protocol.steps)["OW1"]  # the cranks AOW of Tabelle 2
    True
    >>> sorted(fanned_lines(get("crank").figure(parts=3).protocol.steps).items())  # r, L and s = 2r
    [('crankarm', False), ('rodline', False), ('stroke', False)]
    """
    fans: dict[str, list[str]] = collections.defaultdict(list)  # lettered straight lines by their first point
    for s in steps:
        if s.op == "polyline" and s.outputs[0] in dict(s.labels):
            fans[s.inputs[0]].append(s.outputs[0])
    return {name: len(lines) >= 3 for lines in fans.values() for name in lines}


def letter_point(pts: tuple, fan: bool, breaks: Iterable[tuple] = ()) -> tuple[float, float]:
    """Where a lettered straight line's letter stands: at its middle, or (one of a fan) at its far end; a
    line drawn across a broken axis (*breaks*: where the drawn break starts, its drawn width, and the axis if
    it is not x: :class:`~construct.render.sheet.Break`) at the middle of its part beyond the break (right of
    it, or above it).

    >>> letter_point(((0.0, 0.0), (4.0, 0.0)), False), letter_point(((0.0, 0.0), (4.0, 2.0)), True)
    ((2.0, 0.0), (4.0, 2.0))
    >>> letter_point(((0.0, 0.0), (4.0, 0.0)), False, [(1.0, 1.0)])
    (3.0, 0.0)
    >>> letter_point(((0.0, 0.0), (0.0, 4.0)), False, [(1.0, 1.0, 5.0, 1)])
    (0.0, 3.0)
    """
    at = pts[-1] if fan else middle(pts)
    for b in breaks:
        x0, w, axis = b[0], b[1], (b[3] if len(b) > 3 else 0)
        a, c = pts[0], pts[-1]
        if len(pts) == 2 and min(a[axis], c[axis]) < x0 + w and max(a[axis], c[axis]) > x0 + w and not fan:
            t = (x0 + w + max(a[axis], c[axis])) / 2.0  # the middle of the part beyond the break
            s = a[1 - axis] + (c[1 - axis] - a[1 - axis]) * (t - a[axis]) / (c[axis] - a[axis])
            at = (t, s) if axis == 0 else (s, t)
    return at


def middle(pts: tuple, at: float = 0.5) -> tuple[float, float]:
    """The point half way (or the fraction *at* of the way) along a polyline.

    >>> middle(((0.0, 0.0), (2.0, 0.0), (2.0, 2.0))), middle(((0.0, 0.0), (4.0, 0.0)), 0.75)
    ((2.0, 0.0), (3.0, 0.0))
    """
    lengths = [math.dist(p, q) for p, q in zip(pts, pts[1:])]
    half = sum(lengths) * at
    for (p, q), d in zip(zip(pts, pts[1:]), lengths):
        if half <= d and d > 0.0:
            t = half / d
            return (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))
        half -= d
    return (pts[-1][0], pts[-1][1])


def lies_on(curve: Any, p: Point, tol: float) -> bool:
    if isinstance(curve, Circle):
        (cx, cy), r = curve
        return abs(math.hypot(p[0] - cx, p[1] - cy) - r) <= tol * max(1.0, r)
    if isinstance(curve, Line):
        (px, py), (qx, qy) = curve
        d = math.hypot(qx - px, qy - py)
        return abs((qx - px) * (p[1] - py) - (qy - py) * (p[0] - px)) / d <= tol
    return False


def curve_points(objects: Replay, shown: set[str] | None = None) -> list[tuple[float, float]]:
    pts: list[tuple[float, float]] = []
    for n, o in objects.items():
        if shown is not None and n not in shown:
            continue
        if hasattr(o, "rings"):
            for ring in o.rings():
                pts.extend(ring)
        elif hasattr(o, "curve_points"):
            pts.extend(o.curve_points())
    return pts


#: Two gaps between the points marked on a circle are one gap's width apart by less than this (rad): a tie.
GAP_TIE = 1e-9


def widest_gap(angles: Sequence[float], gaps: Sequence[float]) -> int:
    """Which gap between the points marked on a circle (at *angles*, sorted) the drawn arc leaves out: the widest,
    and of two as wide (a circle cut by a line through its centre: a half circle either way) the one about the
    circle's rightmost point (angle 0; of two as near, the one about its top), never the other by a rounding --
    the arc stays on one side as a given moves.

    >>> widest_gap([math.pi / 2, 3 * math.pi / 2], [math.pi, math.pi]), widest_gap([0.0, 1.0], [1.0, TWO_PI - 1.0])
    (1, 1)
    """
    widest = max(gaps)
    tied = [j for j, g in enumerate(gaps) if g >= widest - GAP_TIE]
    if len(tied) == 1:
        return tied[0]
    mid = lambda j: angles[j] + gaps[j] / 2  # noqa: E731
    return max(tied, key=lambda j: (round(math.cos(mid(j)), 9), round(math.sin(mid(j)), 9), -j))


def segment_extent(line: Line, pts: list[Point], margin: float) -> tuple[float, float, float, float]:
    """The segment of *line* over the points *pts* marked on it, reaching *margin* past them."""
    return segment_at(segment_span(line, pts), margin)


def segment_span(line: Line, pts: list[Point]) -> tuple:
    """What :func:`segment_extent` draws *line* over, before the margin (a scene drawn at two margins asks once)."""
    (px, py), _ = line
    ux, uy = line.direction()
    ts = [(q[0] - px) * ux + (q[1] - py) * uy for q in pts] or [0.0, 1.0]
    # a line shown through one point only (a tangent at its point of contact)
    lone = max(ts) - min(ts) <= 1e-9 * max(1.0, abs(ts[0]))
    return (px, py, ux, uy, min(ts), max(ts), lone)


def segment_at(span: tuple, margin: float) -> tuple[float, float, float, float]:
    """The segment over a :func:`segment_span`, reaching *margin* past its points."""
    px, py, ux, uy, lo, hi, lone = span
    if lone:
        # is drawn long enough to be seen as a line
        margin *= 5.0
    t0, t1 = lo - margin, hi + margin
    return (px + t0 * ux, py + t0 * uy, px + t1 * ux, py + t1 * uy)


def circle_extent(circle: Circle, pts: list[Point], margin: float, role: str,
                  plate: bool = False) -> tuple[MarkKind, tuple]:
    """A full circle for results and unmarked circles, else the arc over the marked points.

    On a plate a result circle whose shown points cover at most a half turn
    (the crank circle of the forward stroke) is drawn as exactly that arc:
    the books' "über dem Kolbenhub geschlagene Halbkreis".
    """
    return arc_at(marked_arc(circle, pts, role, plate), margin)


def marked_arc(circle: Circle, pts: list[Point], role: str, plate: bool = False) -> tuple[MarkKind | None, tuple]:
    """What :func:`circle_extent` draws before the margin (a scene drawn at two margins asks once): (kind, geom)
    as drawn whatever the margin, or (None, (cx, cy, r, start, sweep)) the arc over the marked points, which
    :func:`arc_at` pads."""
    (cx, cy), r = circle
    if role == "result" and plate and len(pts) >= 3:
        kind, geom = arc_at(marked_arc(circle, pts, "construction"), 0.0)
        if kind is MarkKind.ARC and geom[4] <= math.pi * (1.0 + 1e-9):
            return kind, geom
    if role == "result" or not pts:
        return MarkKind.CIRCLE, (cx, cy, r)
    angles: list[float] = []
    for a in sorted(math.atan2(p[1] - cy, p[0] - cx) % TWO_PI for p in pts):
        if not angles or a - angles[-1] > 1e-9:  # the same point marked twice counts once
            angles.append(a)
    if len(angles) > 1 and angles[0] + TWO_PI - angles[-1] <= 1e-9:
        angles.pop()
    # The drawn arc is the complement of the largest empty gap between marked points.
    gaps = [(angles[(i + 1) % len(angles)] - a) % TWO_PI or (TWO_PI if len(angles) == 1 else 0.0)
            for i, a in enumerate(angles)]
    i = widest_gap(angles, gaps)
    return None, (cx, cy, r, angles[(i + 1) % len(angles)], TWO_PI - gaps[i])


def arc_at(arc: tuple[MarkKind | None, tuple], margin: float) -> tuple[MarkKind, tuple]:
    """The circle or arc of a :func:`marked_arc`, an arc over marked points reaching *margin* past them (a
    circle when that is nearly all of it)."""
    kind, geom = arc
    if kind is not None:
        return kind, geom
    cx, cy, r, start, sweep = geom
    pad = min(margin / r, 0.6)
    start, sweep = start - pad, sweep + 2.0 * pad
    if sweep >= 0.92 * TWO_PI:
        return MarkKind.CIRCLE, (cx, cy, r)
    return MarkKind.ARC, (cx, cy, r, start, sweep)


@functools.lru_cache(maxsize=1 << 16)
def _arc_extremes(g: tuple) -> tuple[tuple[float, float], ...]:
    """An arc's ends and the quarter points it passes: its exact box, in at most six points (kept: breaking a
    figure's axis, its box and its groups' boxes ask every arc several times)."""
    cx, cy, r, a0, sw = g
    quarter = math.pi / 2
    angles = [a0, a0 + sw] + [q * quarter for q in range(math.ceil(min(a0, a0 + sw) / quarter),
                                                          math.floor(max(a0, a0 + sw) / quarter) + 1)]
    return tuple([(cx + r * math.cos(a), cy + r * math.sin(a)) for a in angles])


#: The points that bound a mark's ``geom``, by kind (:func:`extreme_points`).
_EXTREMES: dict[MarkKind, Callable[[tuple], Sequence[tuple[float, float]]]] = {
    MarkKind.POINT: lambda g: [g],
    MarkKind.SEGMENT: lambda g: [(g[0], g[1]), (g[2], g[3])],
    MarkKind.CIRCLE: lambda g: [(g[0] - g[2], g[1] - g[2]), (g[0] + g[2], g[1] + g[2])],
    MarkKind.ARC: _arc_extremes,
    MarkKind.CURVE: list,
    MarkKind.AREA: list,
}


def extreme_points(m: Mark) -> Sequence[tuple[float, float]]:
    """The points that bound a mark as drawn: a segment by its ends, a circle by its box's corners.

    >>> arc = Mark("m", 1, "k", MarkKind.ARC, (0.0, 0.0, 2.0, 0.0, math.pi / 2), "construction", "compass", "exact")
    >>> [(round(x, 12), round(y, 12)) for x, y in extreme_points(arc)]
    [(2.0, 0.0), (0.0, 2.0), (2.0, 0.0), (0.0, 2.0)]
    """
    return _EXTREMES[m.kind](m.geom)


def mark_box(m: Mark) -> tuple[float, float, float, float] | None:
    """The box (x0, y0, x1, y1) of a mark as drawn: of its :func:`extreme_points` (None for a curve of no points).

    >>> mark_box(Mark("m", 1, "k", MarkKind.CIRCLE, (1.0, 2.0, 0.5), "construction", "compass", "exact"))
    (0.5, 1.5, 1.5, 2.5)
    """
    if m.kind is MarkKind.ARC:
        return _arc_box(m.geom)
    return _box_of(extreme_points(m))


@functools.lru_cache(maxsize=1 << 16)
def _arc_box(g: tuple) -> tuple[float, float, float, float]:
    return _box_of(_arc_extremes(g))  # type: ignore[return-value]


def _box_of(pts: Sequence[tuple[float, float]]) -> tuple[float, float, float, float] | None:
    if not pts:
        return None
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return (min(xs), min(ys), max(xs), max(ys))


def could_show(m: Mark, region: tuple[float, float, float, float]) -> bool:
    """Could the mark show inside *region* (x0, y0, x1, y1, drawing units)?  Bounding boxes meet; a circle
    must not enclose it all."""
    x0, y0, x1, y1 = region
    g = m.geom
    if m.kind is MarkKind.POINT:
        return x0 <= g[0] <= x1 and y0 <= g[1] <= y1
    if m.kind.round:
        cx, cy, r = g[0], g[1], g[2]
        # distance from the centre to the nearest and farthest point of the region
        nx, ny = min(max(cx, x0), x1), min(max(cy, y0), y1)
        near = math.hypot(nx - cx, ny - cy)
        far = max(math.hypot(px - cx, py - cy) for px in (x0, x1) for py in (y0, y1))
        return near <= r <= far
    if m.kind is MarkKind.SEGMENT:
        bx0, bx1 = sorted((g[0], g[2]))
        by0, by1 = sorted((g[1], g[3]))
        return bx0 <= x1 and x0 <= bx1 and by0 <= y1 and y0 <= by1
    pts = g
    return any(x0 <= p[0] <= x1 and y0 <= p[1] <= y1 for p in pts)
