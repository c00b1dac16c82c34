"""The geometry kernel: immutable points, lines, circles and lengths, and where curves meet.

Every value is immutable, hashable (for plain numbers), picklable and
bounded in its repr.  A coordinate is a Python float -- or, in a *sweep*, a
numpy array holding one value per set of givens (``Protocol.replay`` with
array givens).  The same code serves both: each computation takes an array
namespace ``xp`` (:data:`SCALAR` for floats, :data:`ARRAY` for numpy) and is
written once for both.

An intersection of the public API returns a tuple of 0, 1 or 2 points
(never a different type); *which* of two points a construction wants is
decided by a named rule (:mod:`construct.kernel.rules`).  Tangency is decided
by one stated tolerance, :data:`TANGENCY_TOLERANCE`, relative to the size of
the figures involved: two curves whose gap (or overlap) is at most that
fraction of their size *touch* and meet in one point.  The values and where they meet are the two halves of
one doctested idea and stay one module (over 600 lines): split, each half would need the other's names back.

>>> c1 = Circle(Point(0.0, 0.0), 1.0)
>>> c2 = Circle(Point(1.0, 0.0), 1.0)
>>> [(round(p.x, 12), round(p.y, 12)) for p in intersect(c1, c2)]
[(0.5, -0.866025403784), (0.5, 0.866025403784)]
>>> intersect(c1, Circle(Point(2.0, 0.0), 1.0))
(Point(1.0, 0.0),)
>>> intersect(c1, Circle(Point(3.0, 0.0), 1.0))
()
>>> Point(1.0, 2.0) + Point(3.0, 4.0)
Traceback (most recent call last):
...
TypeError: unsupported operand type(s) for +: 'Point' and 'Point'
"""

from __future__ import annotations

import math
from typing import Any, Union

import numpy as np

from .errors import DegenerateObject, NoIntersection, WrongInput

__all__ = [
    "TANGENCY_TOLERANCE",
    "SCALAR",
    "ARRAY",
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
    "is_sweep",
    "sets_where",
    "take",
    "stack",
    "points",
]

#: Two curves whose gap or overlap is at most this fraction of their size
#: (the larger radius, or the distance of the centres) are taken to touch.
#: 1e-10 is far above the rounding of a few hundred chained float operations
#: (~1e-14) and far below anything a drawing can show (a 1 m crank: 0.1 nm).
TANGENCY_TOLERANCE = 1e-10


# --------------------------------------------------------------------------
# Array namespaces: the same formulas on floats (fast, math module) and on
# numpy arrays (a sweep over many givens at once).
# --------------------------------------------------------------------------


class _Scalar:
    """Python floats: the math module, and ``where`` as a conditional expression."""

    name = "scalar"
    sqrt = staticmethod(math.sqrt)
    hypot = staticmethod(math.hypot)
    cos = staticmethod(math.cos)
    sin = staticmethod(math.sin)
    abs = staticmethod(abs)
    maximum = staticmethod(max)
    radians = staticmethod(math.radians)

    @staticmethod
    def where(cond: Any, a: Any, b: Any) -> Any:
        return a if cond else b

    @staticmethod
    def any(cond: Any) -> bool:
        return bool(cond)

    @staticmethod
    def finite(v: Any) -> bool:
        return math.isfinite(v)


class ArrayMath:
    """numpy arrays: ufuncs, ``where`` element by element."""

    name = "array"

    def __init__(self, n: int = 0) -> None:
        self.n = n  # how many sets of givens the sweep holds

    sqrt = staticmethod(np.sqrt)
    hypot = staticmethod(np.hypot)
    cos = staticmethod(np.cos)
    sin = staticmethod(np.sin)
    abs = staticmethod(np.abs)
    maximum = staticmethod(np.maximum)
    radians = staticmethod(np.radians)
    where = staticmethod(np.where)

    @staticmethod
    def any(cond: Any) -> bool:
        return bool(np.any(cond))

    @staticmethod
    def finite(v: Any) -> bool:
        return bool(np.all(np.isfinite(v)))


SCALAR = _Scalar()
ARRAY = ArrayMath()


def is_sweep(v: Any) -> bool:
    """Is *v* (a number) one value per set of givens?"""
    return isinstance(v, np.ndarray)


def _num(v: Any) -> str:
    if isinstance(v, np.ndarray):
        return f"<{v.size} values {np.min(v):.6g}..{np.max(v):.6g}>" if v.size else "<no values>"
    return repr(float(v))


def _as_number(v: Any) -> Any:
    if isinstance(v, np.ndarray):
        return v
    try:
        return float(v)
    except (TypeError, ValueError):
        raise WrongInput(f"coordinates, radii and lengths are numbers, got {_bound(repr(v))}") from None


def _finite(v: Any) -> bool:
    if isinstance(v, np.ndarray):
        return bool(np.all(np.isfinite(v)))
    try:
        return math.isfinite(v)
    except TypeError:  # not a number at all: say so rather than let math's TypeError out
        raise WrongInput(f"coordinates, radii and lengths are numbers, got {_bound(repr(v))}") from None


def _bound(text: str, limit: int = 80) -> str:
    return text if len(text) <= limit else text[: limit - 4] + "...)"


class _Value:
    """Immutable value with slots: no attribute may be set after construction."""

    __slots__ = ()

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is immutable")

    def __delattr__(self, name: str) -> None:
        raise AttributeError(f"{type(self).__name__} is immutable")

    def _fields(self) -> tuple:
        return tuple(getattr(self, s) for s in self.__slots__)

    def __iter__(self):
        return iter(self._fields())

    def __getitem__(self, i: int) -> Any:
        return self._fields()[i]

    def __len__(self) -> int:
        return len(self.__slots__)

    def __reduce__(self):
        return (type(self), self._fields())

    def __copy__(self):
        return self

    def __deepcopy__(self, memo: dict) -> Any:
        return self

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        for a, b in zip(self._fields(), other._fields()):
            if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
                if not np.array_equal(a, b):
                    return False
            elif a != b:
                return False
        return True

    def __ne__(self, other: object) -> bool:
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    def __hash__(self) -> int:
        return hash((type(self).__name__, self._fields()))  # arrays are unhashable: a sweep value is too

    def __repr__(self) -> str:
        return _bound(f"{type(self).__name__}({', '.join(_show(v) for v in self._fields())})")


def _show(v: Any) -> str:
    return repr(v) if isinstance(v, _Value) else _num(v)


_new = object.__new__


class Point(_Value):
    """A point of the drawing plane.

    >>> Point(3.0, 4.0).distance(Point(0.0, 0.0))
    5.0
    >>> x, y = Point(1, 2); (x, y)
    (1.0, 2.0)
    >>> Point(1.0, float("nan"))
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: Point needs finite coordinates, got (1.0, nan)
    """

    __slots__ = ("x", "y")

    def __init__(self, x: float, y: float) -> None:
        if not (_finite(x) and _finite(y)):
            raise DegenerateObject(f"Point needs finite coordinates, got ({_num(x)}, {_num(y)})")
        _set_x(self, _as_number(x))
        _set_y(self, _as_number(y))

    def __iter__(self):
        return iter((self.x, self.y))

    def __eq__(self, other: object) -> bool:
        if type(other) is not Point:
            return NotImplemented
        if type(self.x) is float and type(self.y) is float and type(other.x) is float and type(other.y) is float:
            return self.x == other.x and self.y == other.y  # the common case, without building field tuples
        return _Value.__eq__(self, other)

    __hash__ = _Value.__hash__

    def __getitem__(self, i: int) -> Any:
        return (self.x, self.y)[i]

    def distance(self, other: "Point") -> Any:
        xp = ARRAY if is_sweep(self.x) or is_sweep(self.y) or is_sweep(other.x) or is_sweep(other.y) else SCALAR
        return xp.hypot(other.x - self.x, other.y - self.y)


_set_x = Point.x.__set__  # type: ignore[attr-defined]
_set_y = Point.y.__set__  # type: ignore[attr-defined]


def raw_point(x: Any, y: Any) -> Point:
    """A Point without the finiteness check: for results computed from finite values."""
    p = _new(Point)
    _set_x(p, x)
    _set_y(p, y)
    return p


def points(xs: Any, ys: Any) -> tuple[Point, ...]:
    """Points (xs[i], ys[i]) from two sequences of coordinates: one finiteness check for all of them.

    What a long ring of vertices (an area's, a curve's) is built from; as
    :class:`Point`, a non-finite coordinate is refused.

    >>> points([0.0, 1.0], [2.0, 3.0])
    (Point(0.0, 2.0), Point(1.0, 3.0))
    >>> points([0.0], [float("inf")])
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: Point needs finite coordinates, got (0.0, inf)
    """
    ax, ay = np.asarray(xs, dtype=float), np.asarray(ys, dtype=float)
    bad = ~(np.isfinite(ax) & np.isfinite(ay))
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise DegenerateObject(f"Point needs finite coordinates, got ({_num(ax[i])}, {_num(ay[i])})")
    return tuple(raw_point(x, y) for x, y in zip(ax.tolist(), ay.tolist()))


class Line(_Value):
    """The straight line through two distinct points (drawn as the segment between them).

    >>> Line(Point(0.0, 0.0), Point(0.0, 0.0))
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: Line needs two distinct points, got Point(0.0, 0.0) twice
    """

    __slots__ = ("p", "q")

    def __init__(self, p: Point, q: Point) -> None:
        if not (isinstance(p, Point) and isinstance(q, Point)):
            raise DegenerateObject(f"Line needs two points, got {p!r} and {q!r}")
        same = (p.x == q.x) & (p.y == q.y)
        if same if type(same) is bool else np.any(same):
            raise DegenerateObject(f"Line needs two distinct points, got {p!r} twice")
        _set_p(self, p)
        _set_q(self, q)

    def direction(self) -> tuple[Any, Any]:
        """Unit vector from p towards q."""
        dx, dy = self.q.x - self.p.x, self.q.y - self.p.y
        n = np.hypot(dx, dy) if is_sweep(dx) or is_sweep(dy) else math.hypot(dx, dy)
        return dx / n, dy / n


_set_p = Line.p.__set__  # type: ignore[attr-defined]
_set_q = Line.q.__set__  # type: ignore[attr-defined]


class Circle(_Value):
    """A circle about a centre with a positive, finite radius.

    >>> Circle(Point(0.0, 0.0), 0.0)
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: Circle needs a positive finite radius, got 0.0
    """

    __slots__ = ("center", "radius")

    def __init__(self, center: Point, radius: float) -> None:
        if not isinstance(center, Point):
            raise DegenerateObject(f"Circle needs a centre point, got {center!r}")
        if not (_finite(radius) and np.all(np.asarray(radius) > 0.0)):
            raise DegenerateObject(f"Circle needs a positive finite radius, got {_num(radius)}")
        _set_center(self, center)
        _set_radius(self, _as_number(radius))


_set_center = Circle.center.__set__  # type: ignore[attr-defined]
_set_radius = Circle.radius.__set__  # type: ignore[attr-defined]


def raw_circle(center: Point, radius: Any) -> Circle:
    c = _new(Circle)
    _set_center(c, center)
    _set_radius(c, radius)
    return c


class Length(_Value):
    """A compass opening: a positive finite length carried from one place to another.

    >>> float(Length(2.5))
    2.5
    >>> Length(-1.0)
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: Length must be positive and finite, got -1.0
    """

    __slots__ = ("value",)

    def __init__(self, value: float) -> None:
        if not (_finite(value) and np.all(np.asarray(value) > 0.0)):
            raise DegenerateObject(f"Length must be positive and finite, got {_num(value)}")
        _set_value(self, _as_number(value))

    def __float__(self) -> float:
        return float(self.value)


_set_value = Length.value.__set__  # type: ignore[attr-defined]


Curve = Union[Line, Circle]


# --------------------------------------------------------------------------
# Sweeps: element i of a value, and values stacked back into one.
# --------------------------------------------------------------------------


def take(v: Any, i: int) -> Any:
    """Element *i* of a sweep value (a value that is no sweep is the same for every i)."""
    if type(v) is Point:  # the commonest value of a sweep, taken without the dispatch below
        x, y = v.x, v.y
        return raw_point(x if type(x) is float else float(x[i]) if type(x) is np.ndarray and x.ndim else take(x, i),
                   y if type(y) is float else float(y[i]) if type(y) is np.ndarray and y.ndim else take(y, i))
    if isinstance(v, float):
        return v
    if isinstance(v, np.ndarray):
        return float(v[i]) if v.ndim else float(v)  # np.where of two floats is 0-dimensional
    if isinstance(v, np.generic):  # a numpy scalar: the same for every set of givens
        return float(v)
    if isinstance(v, Point):
        return raw_point(take(v.x, i), take(v.y, i))
    if isinstance(v, Line):
        return Line(take(v.p, i), take(v.q, i))
    if isinstance(v, Circle):
        return raw_circle(take(v.center, i), take(v.radius, i))
    if isinstance(v, Length):
        return Length(take(v.value, i))
    take_i = getattr(v, "take", None)
    return take_i(i) if take_i is not None else v


def take_all(v: Any, n: int) -> list:
    """``[take(v, i) for i in range(n)]``: every element of a sweep value of *n* sets, a point's, a line's or a
    circle's coordinates read as whole arrays (the checks of a sweep read the same objects of every set).

    >>> [(p.x, p.y) for p in take_all(Point(np.array([1.0, 2.0]), 3.0), 2)]
    [(1.0, 3.0), (2.0, 3.0)]
    """
    kind = type(v)
    if kind is Point:
        xs, ys = _floats(v.x, n), _floats(v.y, n)
        if xs is not None and ys is not None:
            return list(map(raw_point, xs, ys))
    elif kind is Line:
        return list(map(Line, take_all(v.p, n), take_all(v.q, n)))
    elif kind is Circle:
        radii = _floats(v.radius, n)
        if radii is not None:
            return list(map(raw_circle, take_all(v.center, n), radii))
    return [take(v, i) for i in range(n)]


def _floats(a: Any, n: int) -> list | None:
    """The *n* elements of a coordinate as :func:`take` gives them, read at once; None: take them one by one."""
    if type(a) is float:
        return [a] * n
    if type(a) is np.ndarray and a.ndim == 1 and a.size == n and a.dtype == np.float64:
        return a.tolist()
    return None


def stack(values: list) -> Any:
    """Values made one by one for each set of givens, as one sweep value."""
    first = values[0]
    if isinstance(first, float):
        return np.array(values, dtype=float)
    if isinstance(first, Point):
        return raw_point(np.array([p.x for p in values]), np.array([p.y for p in values]))
    if isinstance(first, Line):
        return Line(stack([l.p for l in values]), stack([l.q for l in values]))
    if isinstance(first, Circle):
        return raw_circle(stack([c.center for c in values]), np.array([c.radius for c in values]))
    if isinstance(first, Length):
        return Length(np.array([float(v) for v in values]))
    return Sweep(values)


class Sweep:
    """Values that do not stack into arrays (drawn curves, areas): one per set of givens."""

    __slots__ = ("values",)

    def __init__(self, values: Any) -> None:
        object.__setattr__(self, "values", tuple(values))

    def take(self, i: int) -> Any:
        return self.values[i]

    def __len__(self) -> int:
        return len(self.values)

    def __reduce__(self):
        return (Sweep, (self.values,))

    def __repr__(self) -> str:
        return f"Sweep({len(self.values)} × {type(self.values[0]).__name__})" if self.values else "Sweep()"


# --------------------------------------------------------------------------
# Intersections.  The cores take an array namespace and always return the
# same number of points (two for anything with a circle; a tangency gives the
# same point twice); they raise NoIntersection where the curves do not meet.
# --------------------------------------------------------------------------


def _describe(obj: Any) -> str:
    if isinstance(obj, Circle):
        return _bound(f"circle about ({_num(obj.center.x)}, {_num(obj.center.y)}) with radius {_num(obj.radius)}", 120)
    if isinstance(obj, Line):
        return _bound(f"line through ({_num(obj.p.x)}, {_num(obj.p.y)}) and ({_num(obj.q.x)}, {_num(obj.q.y)})", 120)
    return repr(obj)


def sets_where(bad: Any) -> str:
    """Which sets of givens of a sweep a failure happened for, as an error message adds it ("" for a replay).

    >>> sets_where(np.array([False, True, True]))
    ' (for 2 of 3 sets of givens, first at index 1)'
    """
    if isinstance(bad, np.ndarray):
        idx = np.flatnonzero(bad)
        return f" (for {idx.size} of {bad.size} sets of givens, first at index {idx[0]})"
    return ""


def line_line(l1: Line, l2: Line, xp: Any = SCALAR) -> Point:
    """The crossing of two lines; NoIntersection when they are parallel.

    Parallel means the sine of the angle between them is at most
    :data:`TANGENCY_TOLERANCE`.
    """
    p, q, u, v = l1.p, l1.q, l2.p, l2.q
    d1x, d1y = q.x - p.x, q.y - p.y
    d2x, d2y = v.x - u.x, v.y - u.y
    den = d1x * d2y - d1y * d2x
    bad = xp.abs(den) <= TANGENCY_TOLERANCE * xp.hypot(d1x, d1y) * xp.hypot(d2x, d2y)
    if xp.any(bad):
        raise NoIntersection(f"{_describe(l1)} and {_describe(l2)} are parallel{sets_where(bad)}")
    t = ((u.x - p.x) * d2y - (u.y - p.y) * d2x) / den
    return raw_point(p.x + t * d1x, p.y + t * d1y)


def line_circle(line: Line, circle: Circle, xp: Any = SCALAR) -> tuple[Point, Point]:
    """Where a line meets a circle, in the line's direction (a tangency: the foot twice)."""
    p, q = line.p, line.q
    c, r = circle.center, circle.radius
    if xp is SCALAR:
        return _line_circle_scalar(line, p.x, p.y, q.x, q.y, c.x, c.y, r, circle)
    dx, dy = q.x - p.x, q.y - p.y
    n = xp.hypot(dx, dy)
    ux, uy = dx / n, dy / n
    # Foot of the perpendicular from the centre, and the distance to it.
    t = (c.x - p.x) * ux + (c.y - p.y) * uy
    fx, fy = p.x + t * ux, p.y + t * uy
    delta = xp.abs((c.x - p.x) * uy - (c.y - p.y) * ux)
    gap = r - delta  # how deep the line cuts into the circle
    tol = TANGENCY_TOLERANCE * r
    bad = gap < -tol
    if xp.any(bad):
        raise NoIntersection(f"{_describe(line)} and {_describe(circle)} do not meet{sets_where(bad)}")
    # (r - d)(r + d) rather than r^2 - d^2: no cancellation when nearly tangent.
    touch = gap <= tol
    if xp.any(touch):
        h = xp.where(touch, 0.0, xp.sqrt(xp.maximum(gap, 0.0) * (r + delta)))
    else:  # no set touches (a sweep's usual case): the general formula alone
        h = xp.sqrt(gap * (r + delta))
    return raw_point(fx - h * ux, fy - h * uy), raw_point(fx + h * ux, fy + h * uy)


def _line_circle_scalar(line, px, py, qx, qy, cx, cy, r, circle):
    """line_circle on floats: the same operations in the same order, branches for where()."""
    dx, dy = qx - px, qy - py
    n = math.hypot(dx, dy)
    ux, uy = dx / n, dy / n
    t = (cx - px) * ux + (cy - py) * uy
    fx, fy = px + t * ux, py + t * uy
    delta = abs((cx - px) * uy - (cy - py) * ux)
    gap = r - delta
    tol = TANGENCY_TOLERANCE * r
    if gap < -tol:
        raise NoIntersection(f"{_describe(line)} and {_describe(circle)} do not meet")
    h = 0.0 if gap <= tol else math.sqrt(gap * (r + delta))
    return raw_point(fx - h * ux, fy - h * uy), raw_point(fx + h * ux, fy + h * uy)


def _circle_circle_scalar(c1, c2, x1, y1, r1, x2, y2, r2):
    """circle_circle on floats: the same operations in the same order, branches for where()."""
    dx, dy = x2 - x1, y2 - y1
    d = math.hypot(dx, dy)
    tol = TANGENCY_TOLERANCE * max(max(r1, r2), d)
    if d <= tol:
        if abs(r1 - r2) <= tol:
            raise DegenerateObject(f"coincident circles have no definite intersection: {_describe(c1)}")
        raise NoIntersection(f"{_describe(c1)} and {_describe(c2)} do not meet")
    outer = r1 + r2 - d
    inner = d - abs(r1 - r2)
    if outer < -tol or inner < -tol:
        raise NoIntersection(f"{_describe(c1)} and {_describe(c2)} do not meet")
    ux, uy = dx / d, dy / d
    if outer <= tol:
        a, h = r1, 0.0
    elif inner <= tol:
        a, h = (r1 if r1 >= r2 else -r1), 0.0
    else:
        a = 0.5 * (d + (r1 - r2) * (r1 + r2) / d)
        h = math.sqrt(outer * (r1 + r2 + d) * inner * (d + abs(r1 - r2))) / (2.0 * d)
    mx, my = x1 + a * ux, y1 + a * uy
    return raw_point(mx + h * uy, my - h * ux), raw_point(mx - h * uy, my + h * ux)


def circle_circle(c1: Circle, c2: Circle, xp: Any = SCALAR) -> tuple[Point, Point]:
    """Where two circles meet: right of the line of centres first, then left (a tangency: twice).

    The half chord is computed from the product of the four gaps (Heron's
    form), never as the difference of two nearly equal squares.
    """
    (x1, y1), r1 = (c1.center.x, c1.center.y), c1.radius
    (x2, y2), r2 = (c2.center.x, c2.center.y), c2.radius
    if xp is SCALAR:
        return _circle_circle_scalar(c1, c2, x1, y1, r1, x2, y2, r2)
    dx, dy = x2 - x1, y2 - y1
    d = xp.hypot(dx, dy)
    tol = TANGENCY_TOLERANCE * xp.maximum(xp.maximum(r1, r2), d)
    concentric = d <= tol
    if xp.any(concentric & (xp.abs(r1 - r2) <= tol)):
        raise DegenerateObject(f"coincident circles have no definite intersection: {_describe(c1)}")
    outer = r1 + r2 - d  # > 0 when the circles are not apart
    inner = d - xp.abs(r1 - r2)  # > 0 when neither lies inside the other
    bad = concentric | (outer < -tol) | (inner < -tol)
    if xp.any(bad):
        raise NoIntersection(f"{_describe(c1)} and {_describe(c2)} do not meet{sets_where(bad)}")
    ux, uy = dx / d, dy / d
    touch_out, touch_in = outer <= tol, inner <= tol
    if not xp.any(touch_out | touch_in):  # no set touches (a sweep's usual case): the general formulas alone
        a = 0.5 * (d + (r1 - r2) * (r1 + r2) / d)
        h = xp.sqrt(outer * (r1 + r2 + d) * inner * (d + xp.abs(r1 - r2))) / (2.0 * d)
    else:
        # Touching from outside: the point r1 along the centre line; from inside: r1 towards the smaller.
        a_touch_inner = xp.where(r1 >= r2, r1, -r1)
        a = xp.where(touch_out, r1, xp.where(touch_in, a_touch_inner, 0.5 * (d + (r1 - r2) * (r1 + r2) / d)))
        prod = xp.maximum(outer, 0.0) * (r1 + r2 + d) * xp.maximum(inner, 0.0) * (d + xp.abs(r1 - r2))
        h = xp.where(touch_out | touch_in, 0.0, xp.sqrt(prod) / (2.0 * d))
    mx, my = x1 + a * ux, y1 + a * uy
    return raw_point(mx + h * uy, my - h * ux), raw_point(mx - h * uy, my + h * ux)


def meet(a: Any, b: Any, xp: Any = SCALAR) -> tuple[Point, ...]:
    """The points where two curves (lines and circles) meet, as the cores give them."""
    if isinstance(a, Line):
        if isinstance(b, Line):
            return (line_line(a, b, xp),)
        return line_circle(a, b, xp)
    if isinstance(b, Line):
        return line_circle(b, a, xp)
    return circle_circle(a, b, xp)


def _distinct(points: tuple[Point, ...]) -> tuple[Point, ...]:
    if len(points) == 2 and points[0] == points[1]:
        return points[:1]
    return points


def distance(a: Point, b: Point) -> float:
    """Euclidean distance of two points."""
    return math.hypot(b.x - a.x, b.y - a.y)


def intersect_lines(l1: Line, l2: Line) -> tuple[Point, ...]:
    """The crossing of two lines: one point, or none when they are parallel.

    >>> intersect_lines(Line(Point(0, 0), Point(1, 1)), Line(Point(0, 1), Point(1, 0)))
    (Point(0.5, 0.5),)
    >>> intersect_lines(Line(Point(0, 0), Point(1, 0)), Line(Point(0, 1), Point(1, 1)))
    ()
    """
    try:
        return (line_line(l1, l2),)
    except NoIntersection:
        return ()


def intersect_line_circle(line: Line, circle: Circle) -> tuple[Point, ...]:
    """Where a line meets a circle: 0, 1 (touching) or 2 points, in the line's direction.

    >>> intersect_line_circle(Line(Point(-2, 0), Point(2, 0)), Circle(Point(0, 0), 1.0))
    (Point(-1.0, 0.0), Point(1.0, 0.0))
    >>> intersect_line_circle(Line(Point(-2, 1), Point(2, 1)), Circle(Point(0, 0), 1.0))
    (Point(0.0, 1.0),)
    """
    try:
        return _distinct(line_circle(line, circle))
    except NoIntersection:
        return ()


def intersect_circles(c1: Circle, c2: Circle) -> tuple[Point, ...]:
    """Where two circles meet: 0, 1 (touching) or 2 points (right of the centre line first).

    >>> intersect_circles(Circle(Point(0, 0), 1.0), Circle(Point(0, 0), 1.0))
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: coincident circles have no definite intersection: circle about (0.0, 0.0) with radius 1.0
    """
    try:
        return _distinct(circle_circle(c1, c2))
    except NoIntersection:
        return ()


def intersect(a: Curve, b: Curve) -> tuple[Point, ...]:
    """Intersection of any two curves (lines and circles), as a tuple of 0 to 2 points."""
    try:
        return _distinct(meet(a, b))
    except NoIntersection:
        return ()
