"""The geometry kernel: immutable points, lines and circles and their intersections.

Everything here is a pure value type.  An intersection always returns a tuple
of 0, 1 or 2 points (never a different type); *which* of two points a
construction wants is not decided here but by a named rule in
:mod:`construct.kernel.protocol`.

Tangency is decided by one stated tolerance, :data:`TANGENCY_TOLERANCE`,
relative to the size of the figures involved: two curves whose gap (or
overlap) is at most that fraction of their size *touch* and meet in one point.

>>> c1 = Circle(Point(0.0, 0.0), 1.0)
>>> c2 = Circle(Point(1.0, 0.0), 1.0)
>>> [tuple(round(v, 12) for v in p) for p in intersect(c1, c2)]
[(0.5, -0.866025403784), (0.5, 0.866025403784)]
>>> intersect(c1, Circle(Point(2.0, 0.0), 1.0))
(Point(1.0, 0.0),)
>>> intersect(c1, Circle(Point(3.0, 0.0), 1.0))
()
"""

from __future__ import annotations

import math
from typing import Union

from .errors import DegenerateObject

__all__ = [
    "TANGENCY_TOLERANCE",
    "Point",
    "Line",
    "Circle",
    "Length",
    "Curve",
    "intersect",
    "intersect_lines",
    "intersect_line_circle",
    "intersect_circles",
    "distance",
]

#: Two curves whose gap or overlap is at most this fraction of their size
#: (the larger radius, or the distance of the centres) are taken to touch.
#: 1e-10 is far above the rounding of a few hundred chained float operations
#: (~1e-14) and far below anything a drawing can show (a 1 m crank: 0.1 nm).
TANGENCY_TOLERANCE = 1e-10


def _point(x: float, y: float) -> "Point":
    """A Point without the finiteness check: for results computed from finite points."""
    return _tuple_new(Point, (x, y))


_tuple_new = tuple.__new__


class _Value(tuple):
    """Immutable geometric value stored as a tuple; equal only to a value of its own kind."""

    __slots__ = ()

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, type(self)):
            # A plain tuple with the same numbers is not a Point (nor a Line a Circle).
            return False if isinstance(other, tuple) else NotImplemented
        return tuple.__eq__(self, other)

    def __ne__(self, other: object) -> bool:
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    __hash__ = tuple.__hash__


class Point(_Value):
    """A point of the drawing plane; immutable and hashable.

    >>> Point(3.0, 4.0).distance(Point(0.0, 0.0))
    5.0
    >>> Point(1.0, float("nan"))
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: Point needs finite coordinates, got (1.0, nan)
    """

    __slots__ = ()

    def __new__(cls, x: float, y: float) -> "Point":
        if not (math.isfinite(x) and math.isfinite(y)):
            raise DegenerateObject(f"Point needs finite coordinates, got ({x!r}, {y!r})")
        return tuple.__new__(cls, (float(x), float(y)))

    @property
    def x(self) -> float:
        return self[0]

    @property
    def y(self) -> float:
        return self[1]

    def distance(self, other: "Point") -> float:
        return math.hypot(other[0] - self[0], other[1] - self[1])

    def __repr__(self) -> str:
        return f"Point({self[0]!r}, {self[1]!r})"


class Line(_Value):
    """The straight line through two distinct points (drawn as the segment between them).

    >>> Line(Point(0.0, 0.0), Point(0.0, 0.0))
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: Line needs two distinct points, got Point(0.0, 0.0) twice
    """

    __slots__ = ()

    def __new__(cls, p: Point, q: Point) -> "Line":
        if p[0] == q[0] and p[1] == q[1]:
            raise DegenerateObject(f"Line needs two distinct points, got {p!r} twice")
        return tuple.__new__(cls, (p, q))

    @property
    def p(self) -> Point:
        return self[0]

    @property
    def q(self) -> Point:
        return self[1]

    def direction(self) -> tuple[float, float]:
        """Unit vector from p towards q."""
        dx, dy = self[1][0] - self[0][0], self[1][1] - self[0][1]
        n = math.hypot(dx, dy)
        return dx / n, dy / n

    def __repr__(self) -> str:
        return f"Line({self[0]!r}, {self[1]!r})"


class Circle(_Value):
    """A circle about a centre with a positive, finite radius.

    >>> Circle(Point(0.0, 0.0), 0.0)
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: Circle needs a positive finite radius, got 0.0
    """

    __slots__ = ()

    def __new__(cls, center: Point, radius: float) -> "Circle":
        if not (radius > 0.0 and math.isfinite(radius)):
            raise DegenerateObject(f"Circle needs a positive finite radius, got {radius!r}")
        return tuple.__new__(cls, (center, float(radius)))

    @property
    def center(self) -> Point:
        return self[0]

    @property
    def radius(self) -> float:
        return self[1]

    def __repr__(self) -> str:
        return f"Circle({self[0]!r}, {self[1]!r})"


class Length(float):
    """A compass opening: a positive finite length carried from one place to another.

    >>> Length(2.5) * 2
    5.0
    >>> Length(-1.0)
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: Length must be positive and finite, got -1.0
    """

    __slots__ = ()

    def __new__(cls, value: float) -> "Length":
        if not (value > 0.0 and math.isfinite(value)):
            raise DegenerateObject(f"Length must be positive and finite, got {value!r}")
        return float.__new__(cls, value)

    def __repr__(self) -> str:
        return f"Length({float(self)!r})"


Curve = Union[Line, Circle]


def distance(a: Point, b: Point) -> float:
    """Euclidean distance of two points."""
    return math.hypot(b[0] - a[0], b[1] - a[1])


def intersect_lines(l1: Line, l2: Line) -> tuple[Point, ...]:
    """The crossing of two lines: one point, or none when they are parallel.

    Parallel means the sine of the angle between them is at most
    :data:`TANGENCY_TOLERANCE`.

    >>> intersect_lines(Line(Point(0, 0), Point(1, 1)), Line(Point(0, 1), Point(1, 0)))
    (Point(0.5, 0.5),)
    >>> intersect_lines(Line(Point(0, 0), Point(1, 0)), Line(Point(0, 1), Point(1, 1)))
    ()
    """
    (px, py), (qx, qy) = l1
    (ux, uy), (vx, vy) = l2
    d1x, d1y = qx - px, qy - py
    d2x, d2y = vx - ux, vy - uy
    den = d1x * d2y - d1y * d2x
    if abs(den) <= TANGENCY_TOLERANCE * math.hypot(d1x, d1y) * math.hypot(d2x, d2y):
        return ()
    t = ((ux - px) * d2y - (uy - py) * d2x) / den
    return (_point(px + t * d1x, py + t * d1y),)


def intersect_line_circle(line: Line, circle: Circle) -> tuple[Point, ...]:
    """Where a line meets a circle: 0, 1 (touching) or 2 points, in the line's direction.

    >>> intersect_line_circle(Line(Point(-2, 0), Point(2, 0)), Circle(Point(0, 0), 1.0))
    (Point(-1.0, 0.0), Point(1.0, 0.0))
    >>> intersect_line_circle(Line(Point(-2, 1), Point(2, 1)), Circle(Point(0, 0), 1.0))
    (Point(0.0, 1.0),)
    """
    (px, py), (qx, qy) = line
    (cx, cy), r = circle
    dx, dy = qx - px, qy - py
    n = math.hypot(dx, dy)
    ux, uy = dx / n, dy / n
    # Foot of the perpendicular from the centre, and the signed distance to it.
    t = (cx - px) * ux + (cy - py) * uy
    fx, fy = px + t * ux, py + t * uy
    delta = abs((cx - px) * uy - (cy - py) * ux)
    gap = r - delta  # how deep the line cuts into the circle
    tol = TANGENCY_TOLERANCE * r
    if gap < -tol:
        return ()
    if gap <= tol:
        return (_point(fx, fy),)
    # (r - d)(r + d) rather than r^2 - d^2: no cancellation when nearly tangent.
    h = math.sqrt(gap * (r + delta))
    return (_point(fx - h * ux, fy - h * uy), _point(fx + h * ux, fy + h * uy))


def intersect_circles(c1: Circle, c2: Circle) -> tuple[Point, ...]:
    """Where two circles meet: 0, 1 (touching) or 2 points.

    With two points, the first lies to the right of the directed line from
    the first centre to the second, the second to its left.  The half chord
    is computed from the product of the four gaps (Heron's form), never as
    the difference of two nearly equal squares.

    >>> intersect_circles(Circle(Point(0, 0), 1.0), Circle(Point(0, 0), 1.0))
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: coincident circles have no definite intersection: Circle(Point(0.0, 0.0), 1.0)
    """
    (x1, y1), r1 = c1
    (x2, y2), r2 = c2
    dx, dy = x2 - x1, y2 - y1
    d = math.hypot(dx, dy)
    scale = max(r1, r2, d)
    tol = TANGENCY_TOLERANCE * scale
    if d <= tol:
        if abs(r1 - r2) <= tol:
            raise DegenerateObject(f"coincident circles have no definite intersection: {c1!r}")
        return ()
    ux, uy = dx / d, dy / d
    outer = r1 + r2 - d  # > 0 when the circles are not apart
    inner = d - abs(r1 - r2)  # > 0 when neither lies inside the other
    if outer < -tol or inner < -tol:
        return ()
    if outer <= tol:
        return (_point(x1 + r1 * ux, y1 + r1 * uy),)
    if inner <= tol:
        sign = 1.0 if r1 >= r2 else -1.0
        return (_point(x1 + sign * r1 * ux, y1 + sign * r1 * uy),)
    a = 0.5 * (d + (r1 - r2) * (r1 + r2) / d)
    h = math.sqrt(outer * (r1 + r2 + d) * inner * (d + abs(r1 - r2))) / (2.0 * d)
    mx, my = x1 + a * ux, y1 + a * uy
    return (_point(mx + h * uy, my - h * ux), _point(mx - h * uy, my + h * ux))


def intersect(a: Curve, b: Curve) -> tuple[Point, ...]:
    """Intersection of any two curves (lines and circles), as a tuple of 0 to 2 points."""
    if isinstance(a, Line):
        if isinstance(b, Line):
            return intersect_lines(a, b)
        return intersect_line_circle(a, b)
    if isinstance(b, Line):
        return intersect_line_circle(b, a)
    return intersect_circles(a, b)
