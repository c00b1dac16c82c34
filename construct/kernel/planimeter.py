"""Reading a drawn curve with the planimeter, and the areas a mean line cuts off it.

These are not compass-and-straightedge steps: a planimeter traces the drawn
curve and reads its area (the indicator planimeter reads the mean ordinate
directly); where the mean line crosses a curve drawn with the French curve is
found by eye.  Steps made with them must say so in their provenance
(``approximate``, with the method named).

All three work on any curve value with ``curve_points()`` (a polyline of the
drawn curve, e.g. the French curve's Bézier chain) over a base line; they are
exact for that polyline.

>>> from construct.kernel.geometry import Line, Point
>>> class Roof(tuple):
...     def curve_points(self, per_segment=16):
...         return (Point(0, 0), Point(1, 2), Point(2, 0))
>>> roof, a, b = Roof(), Point(0.0, 0.0), Point(2.0, 0.0)
>>> m0, m1 = PLANIMETER_OPS["planimeter_mean"]((roof, a, b), {}, {})
>>> m0, m1                       # area 2 over the base 2: mean height 1
(Point(0.0, 1.0), Point(2.0, 1.0))
>>> mean = Line(m0, m1)
>>> p1, p2 = PLANIMETER_OPS["curve_crossings"]((roof, mean), {}, {})
>>> p1, p2
(Point(0.5, 1.0), Point(1.5, 1.0))
>>> PLANIMETER_OPS["excess_area"]((roof, mean, p1, p2), {}, {})[0].area   # the triangle above the mean line
0.5
"""

from __future__ import annotations

import math
from typing import Any, Sequence

from .errors import GeometryError
from .geometry import Line, Point
from .protocol import register_op

__all__ = ["ExcessArea", "PLANIMETER_OPS", "TRACE_CHORDS", "polyline_area"]

#: Chords per Bézier segment the planimeter follows: the drawn curve to ~1e-7 of its height.
TRACE_CHORDS = 64


def _trace(curve: Any) -> tuple[Point, ...]:
    pts = tuple(curve.curve_points(TRACE_CHORDS))
    if len(pts) < 2:
        raise GeometryError("a planimeter needs a drawn curve of at least two points")
    return pts


def _frame(a: Point, b: Point) -> tuple[float, float, float, float, float]:
    dx, dy = b[0] - a[0], b[1] - a[1]
    length = math.hypot(dx, dy)
    if length == 0.0:
        raise GeometryError("the base of the planimeter reading has no length")
    return dx / length, dy / length, -dy / length, dx / length, length


def polyline_area(points: Sequence[Point], a: Point, b: Point) -> float:
    """Signed area between the polyline and the base a-b (left of a->b positive), by the trapezoids."""
    ux, uy, nx, ny, _ = _frame(a, b)
    total = 0.0
    prev = None
    for p in points:
        u = (p[0] - a[0]) * ux + (p[1] - a[1]) * uy
        v = (p[0] - a[0]) * nx + (p[1] - a[1]) * ny
        if prev is not None:
            total += (u - prev[0]) * (v + prev[1]) / 2.0
        prev = (u, v)
    return total


def _planimeter_mean(args, params, givens):
    """Area under the curve over the base a-b, divided by its length: the mean line's two ends."""
    curve, a, b = args
    ux, uy, nx, ny, length = _frame(a, b)
    h = polyline_area(_trace(curve), a, b) / length
    return (Point(a[0] + h * nx, a[1] + h * ny), Point(b[0] + h * nx, b[1] + h * ny))


def _crossings(pts: Sequence[Point], line: Line) -> list[Point]:
    (px, py), (dx, dy) = line.p, line.direction()
    side = [(q[0] - px) * dy - (q[1] - py) * dx for q in pts]
    out = []
    for i in range(len(pts) - 1):
        s0, s1 = side[i], side[i + 1]
        if s0 == 0.0:
            out.append(pts[i])
        elif s0 * s1 < 0.0:
            t = s0 / (s0 - s1)
            out.append(Point(pts[i][0] + t * (pts[i + 1][0] - pts[i][0]), pts[i][1] + t * (pts[i + 1][1] - pts[i][1])))
    return out


def _curve_crossings(args, params, givens):
    """The first and the last point where the line crosses the drawn curve (in the curve's order)."""
    curve, line = args
    found = _crossings(_trace(curve), line)
    if len(found) < 2:
        raise GeometryError(f"the line crosses the drawn curve {len(found)} time(s); two crossings are needed")
    return (found[0], found[-1])


class ExcessArea(tuple):
    """The region between a drawn curve and a line, from one crossing to the other (hatched when drawn).

    A tuple of its outline points: the first crossing, the curve's points, the
    second crossing (the chord back along the line closes it).  ``area`` is
    signed: positive where the curve lies on the left of first -> last.
    """

    __slots__ = ()
    kind = "area"

    def __new__(cls, outline: Sequence[Point]) -> "ExcessArea":
        pts = tuple(outline)
        if len(pts) < 2 or not all(isinstance(p, Point) for p in pts):
            raise GeometryError("an area needs an outline of at least two points")
        return tuple.__new__(cls, pts)

    @property
    def area(self) -> float:
        return polyline_area(self, self[0], self[-1])

    def area_points(self) -> tuple[Point, ...]:
        return tuple(self)

    def __repr__(self) -> str:
        return f"ExcessArea(area={self.area!r}, {len(self)} outline points)"


def _excess_area(args, params, givens):
    """Between the curve and the line from crossing p1 to crossing p2: the outline and its area."""
    curve, line, p1, p2 = args
    pts = _trace(curve)
    ux, uy, nx, ny, _ = _frame(p1, p2)

    def u(p: Point) -> float:
        return (p[0] - p1[0]) * ux + (p[1] - p1[1]) * uy

    inner = [p for p in pts if 0.0 < u(p) < u(p2)]
    outline = [p1, *inner, p2]
    return (ExcessArea(outline),)


PLANIMETER_OPS = {
    "planimeter_mean": _planimeter_mean,
    "curve_crossings": _curve_crossings,
    "excess_area": _excess_area,
}

for _name, _fn in PLANIMETER_OPS.items():
    register_op(_name, _fn)
