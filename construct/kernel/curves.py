"""Curves drawn through constructed points: the straight-edged polyline and the French curve.

A draftsman joins constructed points either with the straightedge, piece by
piece (:class:`Polyline`), or with a French curve ("Curvenlineal") that
follows the points and any tangents he has constructed (:class:`BezierCurve`,
a chain of cubic Bézier segments).  Neither constructs anything: the points
are constructed, the curve between them is drawn -- which is why every check
on a drawn curve states how far the drawing may stray.

Both are graphs or chains of points and share three questions a later step
asks of them: where does a line cross the curve (:func:`crossings`), what
ordinate does it have at an abscissa (``y_at``), and which polyline draws it
(``curve_points``).

In a sweep (a replay over arrays of givens) a chain's points hold one
coordinate per set of givens, as any point of a sweep does; ``take(i)`` is the
chain of set *i*.  The operations that draw and cross curves have array forms
beside their scalar ones (:func:`crossings_of_sweeps`, the French curve's
sweep in :mod:`construct.kernel.curve_ops`): the same steps on all sets at once, held equal to the
scalar ones set by set (tests/test_sweep.py).

>>> c = BezierCurve((Point(0, 0), Point(1, 1), Point(2, 1), Point(3, 0)))
>>> c.kind, len(c.segments()), c.curve_points(2)
('bezier', 1, (Point(0.0, 0.0), Point(1.5, 0.75), Point(3.0, 0.0)))
>>> c.y_at(1.5)
0.75
>>> [round(p.x, 12) for p in crossings(c, Line(Point(0, 0.5), Point(1, 0.5)))]
[0.633974596216, 2.366025403784]
>>> pl = Polyline((Point(0, 0), Point(2, 2), Point(4, 0)))
>>> pl.y_at(3.0), round(pl.length(), 12)
(1.0, 5.656854249492)
"""

from __future__ import annotations

import math
from typing import Any, Sequence

import numpy as np

from .errors import DegenerateObject, GeometryError
from .geometry import Line, Point, take

__all__ = ["Polyline", "BezierCurve", "crossings", "crossings_of_sweeps", "coordinate_rows", "CURVE_TYPES"]


class _Chain:
    """Shared behaviour of curves given by an ordered chain of points."""

    __slots__ = ("points",)
    kind = "chain"

    def __init__(self, points: Sequence[Point]) -> None:
        object.__setattr__(self, "points", tuple(points))

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError(f"{type(self).__name__} is immutable")

    def __reduce__(self):
        return (type(self), (self.points,))

    def __eq__(self, other: object) -> bool:
        if type(other) is not type(self):
            return NotImplemented
        return self.points == other.points  # type: ignore[attr-defined]

    def __hash__(self) -> int:
        return hash((type(self).__name__, self.points))

    def __len__(self) -> int:
        return len(self.points)

    def __iter__(self):
        return iter(self.points)

    def __getitem__(self, i):
        return self.points[i]

    def as_json(self) -> dict[str, Any]:
        return {"type": self.kind, "points": [[p[0], p[1]] for p in self.points]}

    def take(self, i: int) -> "_Chain":
        """Set *i* of a sweep's chain (a chain of one replay is the same for every set)."""
        return type(self)(tuple(take(p, i) for p in self.points))

    def sets(self) -> int:
        """How many sets of givens the chain holds a point for: 0 for a chain of one replay."""
        return next((c.size for p in self.points for c in (p.x, p.y) if isinstance(c, np.ndarray) and c.ndim), 0)

    def y_at(self, x: float) -> float:
        """The ordinate where the curve passes the abscissa *x* (drawing coordinates; a graph over x)."""
        pts = self.curve_points() if self.kind != "polyline" else self.points
        for a, b in zip(pts, pts[1:]):
            if min(a[0], b[0]) <= x <= max(a[0], b[0]) and a[0] != b[0]:
                t = (x - a[0]) / (b[0] - a[0])
                return a[1] + t * (b[1] - a[1])
        raise GeometryError(f"abscissa {x!r} is outside the drawn curve")


class Polyline(_Chain):
    """Points joined by the straightedge, in order; ``closed`` joins the last to the first.

    >>> Polyline((Point(0, 0),))
    Traceback (most recent call last):
    ...
    construct.kernel.errors.DegenerateObject: a polyline needs at least two points, got 1
    """

    __slots__ = ("closed",)
    kind = "polyline"

    def __init__(self, points: Sequence[Point], closed: bool = False) -> None:
        pts = tuple(points)
        if len(pts) < 2 or not all(isinstance(p, Point) for p in pts):
            raise DegenerateObject(f"a polyline needs at least two points, got {len(pts)}")
        super().__init__(pts)
        object.__setattr__(self, "closed", bool(closed))

    def __reduce__(self):
        return (Polyline, (self.points, self.closed))

    def take(self, i: int) -> "Polyline":
        return Polyline(tuple(take(p, i) for p in self.points), self.closed)

    def __eq__(self, other: object) -> bool:
        if type(other) is not Polyline:
            return NotImplemented
        return self.points == other.points and self.closed == other.closed  # type: ignore[attr-defined]

    __hash__ = _Chain.__hash__

    def curve_points(self, per_segment: int = 1) -> tuple[Point, ...]:
        """The vertices in drawing order (the first repeated at the end when closed)."""
        return self.points + (self.points[0],) if self.closed else self.points

    def length(self) -> float:
        pts = self.curve_points()
        return sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(pts, pts[1:]))

    def as_json(self) -> dict[str, Any]:
        d = super().as_json()
        if self.closed:
            d["closed"] = True
        return d

    def __repr__(self) -> str:
        sets = self.sets()
        if sets:
            return f"Polyline({len(self.points)} points, a sweep of {sets} sets)"
        x, y = self.points[0]
        return f"Polyline({len(self.points)} points from ({x:.6g}, {y:.6g}))"


class BezierCurve(_Chain):
    """A smooth curve drawn through points with a French curve: a chain of cubic Bézier segments.

    The points are p0, c1, c2, p1, c1, c2, p2, ... (3k + 1 of them): each
    segment runs from one point through two control points to the next.  An
    SVG renderer writes ``M p0 C c1 c2 p1 C ...``; :meth:`curve_points`
    gives a fixed polyline for renderers that only draw polylines.
    """

    __slots__ = ()
    kind = "bezier"

    def __init__(self, points: Sequence[Point]) -> None:
        pts = tuple(points)
        if len(pts) < 4 or len(pts) % 3 != 1 or not all(isinstance(p, Point) for p in pts):
            raise DegenerateObject(f"a Bézier chain needs 3k + 1 points (k >= 1), got {len(pts)}")
        super().__init__(pts)

    def segments(self) -> tuple[tuple[Point, Point, Point, Point], ...]:
        p = self.points
        return tuple((p[i], p[i + 1], p[i + 2], p[i + 3]) for i in range(0, len(p) - 1, 3))

    @staticmethod
    def _at(seg: Sequence[Point], t: float) -> tuple[float, float]:
        s = 1.0 - t
        w0, w1, w2, w3 = s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t
        a, b, c, d = seg
        # written out (the same sums, in the same order, as a generator would add them: called a million times
        # by y_at's bisection over a sweep)
        return (w0 * a[0] + w1 * b[0] + w2 * c[0] + w3 * d[0], w0 * a[1] + w1 * b[1] + w2 * c[1] + w3 * d[1])

    def sample(self, per_segment: int = 16):
        """The curve as a polyline, as two numpy arrays xs, ys: *per_segment* pieces per segment, ends exact."""
        t = np.arange(per_segment + 1)[:, None] / per_segment
        s = 1.0 - t
        weights = np.hstack([s ** 3, 3.0 * s * s * t, 3.0 * s * t * t, t ** 3])  # Bernstein basis
        ctrl = np.array([[(p.x, p.y) for p in seg] for seg in self.segments()])  # (k, 4, 2)
        pts = np.einsum("tj,kjd->ktd", weights, ctrl)
        pts[:, 0, :] = ctrl[:, 0, :]  # the points the curve passes through, exactly as constructed
        pts[:, -1, :] = ctrl[:, 3, :]
        flat = np.concatenate([pts[:, :-1, :].reshape(-1, 2), ctrl[-1:, 3, :]])
        return flat[:, 0], flat[:, 1]

    def curve_points(self, per_segment: int = 16) -> tuple[Point, ...]:
        """The curve as a polyline: *per_segment* pieces per Bézier segment, ends exact."""
        xs, ys = self.sample(per_segment)
        return tuple(Point(float(x), float(y)) for x, y in zip(xs, ys))

    def y_at(self, x: float) -> float:
        """The ordinate where the curve passes the abscissa *x* (the curve is a graph over x)."""
        for seg in self.segments():
            x0, x3 = seg[0][0], seg[3][0]
            if min(x0, x3) <= x <= max(x0, x3):
                lo, hi = 0.0, 1.0
                rising = x3 >= x0
                a, b, c, d = seg[0][0], seg[1][0], seg[2][0], seg[3][0]
                for _ in range(60):  # bisection to 1e-18 of the segment: x(t) is monotone on a graph's segment
                    mid = 0.5 * (lo + hi)
                    s = 1.0 - mid  # x(mid) as _at computes it
                    xm = s * s * s * a + 3.0 * s * s * mid * b + 3.0 * s * mid * mid * c + mid * mid * mid * d
                    if (xm < x) == rising:
                        lo = mid
                    else:
                        hi = mid
                return self._at(seg, 0.5 * (lo + hi))[1]
        raise GeometryError(f"abscissa {x!r} is outside the drawn curve")

    def __repr__(self) -> str:
        sets = self.sets()
        if sets:
            return f"BezierCurve({len(self.segments())} segments, a sweep of {sets} sets)"
        a, b = self.points[0], self.points[-1]
        return f"BezierCurve({len(self.segments())} segments, ({a[0]:.6g}, {a[1]:.6g})..({b[0]:.6g}, {b[1]:.6g}))"


CURVE_TYPES = (Polyline, BezierCurve)


def _cubic_roots01(c3: float, c2: float, c1: float, c0: float) -> list[float]:
    """Real roots in [0, 1] of c3 t^3 + c2 t^2 + c1 t + c0, polished by Newton's method."""
    coeffs = [c3, c2, c1, c0]
    while coeffs and abs(coeffs[0]) <= 1e-15 * max(1.0, *(abs(c) for c in coeffs)):
        coeffs.pop(0)
    if len(coeffs) < 2:
        return []
    return _polished01((c3, c2, c1, c0), np.roots(coeffs))


def _cubic_roots01_many(polys: list[tuple[float, float, float, float]]) -> list[list[float]]:
    """:func:`_cubic_roots01` of many cubics: the companion matrices of the true cubics in one eigvals call.

    np.roots computes the roots of a cubic with nonzero ends as the eigenvalues
    of its 3 x 3 companion matrix; here those matrices are stacked (LAPACK
    runs on each as it would alone), the rest go through _cubic_roots01.
    """
    out: list[list[float] | None] = [None] * len(polys)
    full = []
    for i, (c3, c2, c1, c0) in enumerate(polys):
        if abs(c3) > 1e-15 * max(1.0, abs(c3), abs(c2), abs(c1), abs(c0)) and c0 != 0.0:
            full.append(i)
        else:
            out[i] = _cubic_roots01(c3, c2, c1, c0)
    if full:
        p = np.array([polys[i] for i in full], dtype=float)
        comp = np.zeros((len(full), 3, 3))
        comp[:, 0, :] = -p[:, 1:] / p[:, :1]
        comp[:, 1, 0] = comp[:, 2, 1] = 1.0
        for i, roots in zip(full, np.linalg.eigvals(comp)):
            out[i] = _polished01(polys[i], roots)
    return out  # type: ignore[return-value]


def _polished01(poly: tuple[float, float, float, float], roots: Any) -> list[float]:
    c3, c2, c1, c0 = poly
    out = []
    for r in roots:
        if abs(r.imag) > 1e-7:
            continue
        t = float(r.real)
        for _ in range(3):  # polish: np.roots is a companion-matrix eigenvalue, ~1e-10 near double roots
            f = ((c3 * t + c2) * t + c1) * t + c0
            df = (3 * c3 * t + 2 * c2) * t + c1
            if df == 0.0:
                break
            t -= f / df
        if -1e-12 <= t <= 1.0 + 1e-12:
            out.append(min(1.0, max(0.0, t)))
    return sorted(out)


def crossings(curve: Any, line: Line) -> tuple[Point, ...]:
    """Every point where a drawn curve crosses a line, in the curve's order.

    Polyline segments are cut exactly; Bézier segments by the roots of their
    cubic in the line's normal coordinate.  A vertex shared by two segments is
    reported once.
    """
    (px, py), (qx, qy) = line
    dx, dy = qx - px, qy - py
    n = math.hypot(dx, dy)
    nx, ny = -dy / n, dx / n  # unit normal of the line

    def side(p: Point) -> float:
        return (p[0] - px) * nx + (p[1] - py) * ny

    found: list[Point] = []

    def add(x: float, y: float) -> None:
        if found and math.hypot(found[-1][0] - x, found[-1][1] - y) <= 1e-12 * max(1.0, abs(x), abs(y)):
            return
        found.append(Point(x, y))

    if isinstance(curve, BezierCurve):
        segs = []
        polys = []
        for seg in curve.segments():
            s0, s1, s2, s3 = (side(p) for p in seg)
            # A Bézier segment lies inside the hull of its control points: if they are all clearly on one side of
            # the line, the segment does not reach it and no cubic needs solving.  "Clearly": by more than the
            # root polishing's reach, so that a crossing at a shared vertex (s = ±1e-17 on both sides of it) is
            # still found as before.
            margin = 1e-9 * max(1.0, abs(s0), abs(s3))
            if min(s0, s1, s2, s3) > margin or max(s0, s1, s2, s3) < -margin:
                continue
            # Bernstein to power basis of the signed distance.
            c3 = -s0 + 3 * s1 - 3 * s2 + s3
            c2 = 3 * s0 - 6 * s1 + 3 * s2
            c1 = -3 * s0 + 3 * s1
            segs.append(seg)
            polys.append((c3, c2, c1, s0))
        for seg, roots in zip(segs, _cubic_roots01_many(polys)):
            for t in roots:
                add(*BezierCurve._at(seg, t))
    else:
        pts = curve.curve_points()
        # every vertex's side in one numpy pass (the same arithmetic as side(), element by element); only the
        # chords that touch or cross the line are cut -- a traced card has thousands of chords, two of them cross
        xy = np.asarray(pts, dtype=float)
        s = (xy[:, 0] - px) * nx + (xy[:, 1] - py) * ny
        sa, sb = s[:-1], s[1:]
        for k in np.flatnonzero((sa == 0.0) | ((sa < 0.0) & (sb > 0.0)) | ((sb < 0.0) & (sa > 0.0))):
            a, b = pts[k], pts[k + 1]
            ta, tb = float(sa[k]), float(sb[k])
            if ta == 0.0:
                add(a[0], a[1])
            if (ta < 0.0 < tb) or (tb < 0.0 < ta):
                t = ta / (ta - tb)
                add(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]))
        if float(s[-1]) == 0.0:
            add(pts[-1][0], pts[-1][1])
    return tuple(found)


def coordinate_rows(values: Sequence[Any], n: int) -> np.ndarray:
    """Coordinates (a float, or one per set of givens) as rows of an array of shape (len(values), n)."""
    out = np.empty((len(values), n))
    for k, v in enumerate(values):
        out[k] = v
    return out


def crossings_of_sweeps(curve: Any, line: Line, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`crossings` for every set of givens of a sweep of *n* sets at once.

    Every place a crossing can be (each vertex and each segment of a
    polyline, three roots of each Bézier segment) is a row, in the curve's
    order: the x and y arrays of shape (rows, n), and where each set has a
    crossing there (a shared vertex counted once, as :func:`crossings` does).
    The same arithmetic in the same order as the scalar function, on arrays.
    """
    (px, py), (qx, qy) = line
    dx, dy = qx - px, qy - py
    norm = np.hypot(dx, dy)
    nx, ny = -dy / norm, dx / norm
    if isinstance(curve, BezierCurve):
        xs, ys, found = _bezier_crossings(curve, px, py, nx, ny, n)
    else:
        pts = curve.curve_points()
        vx, vy = coordinate_rows([p[0] for p in pts], n), coordinate_rows([p[1] for p in pts], n)
        side = (vx - px) * nx + (vy - py) * ny
        sa, sb = side[:-1], side[1:]
        cut = ((sa < 0.0) & (0.0 < sb)) | ((sb < 0.0) & (0.0 < sa))
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.where(cut, sa / np.where(cut, sa - sb, 1.0), 0.0)
        cx, cy = vx[:-1] + t * (vx[1:] - vx[:-1]), vy[:-1] + t * (vy[1:] - vy[:-1])
        # per segment: its first vertex when on the line, then the cut inside it; the last vertex at the end
        rows = 2 * (len(pts) - 1) + 1
        xs, ys, found = np.empty((rows, n)), np.empty((rows, n)), np.empty((rows, n), dtype=bool)
        xs[0:-1:2], ys[0:-1:2], found[0:-1:2] = vx[:-1], vy[:-1], sa == 0.0
        xs[1::2], ys[1::2], found[1::2] = cx, cy, cut
        xs[-1], ys[-1], found[-1] = vx[-1], vy[-1], side[-1] == 0.0
    return xs, ys, _first_of_repeats(xs, ys, found)


def _first_of_repeats(xs: np.ndarray, ys: np.ndarray, found: np.ndarray) -> np.ndarray:
    """*found* without a crossing that repeats the one found before it (crossings' ``add``), set by set."""
    rows = np.arange(xs.shape[0])[:, None]
    while True:
        last = np.maximum.accumulate(np.where(found, rows, -1), axis=0)
        before = np.vstack([np.full((1, xs.shape[1]), -1), last[:-1]])
        at = np.maximum(before, 0)
        bx, by = np.take_along_axis(xs, at, 0), np.take_along_axis(ys, at, 0)
        with np.errstate(invalid="ignore"):
            near = np.hypot(bx - xs, by - ys) <= 1e-12 * np.maximum(1.0, np.maximum(np.abs(xs), np.abs(ys)))
        repeat = found & (before >= 0) & near
        if not repeat.any():
            return found
        found = found & ~repeat


def _bezier_crossings(curve: "BezierCurve", px, py, nx, ny, n: int):
    """The Bézier part of :func:`crossings_of_sweeps`: three root rows per segment."""
    segs = curve.segments()
    k = len(segs)
    cx = coordinate_rows([p[0] for seg in segs for p in seg], n).reshape(k, 4, n)
    cy = coordinate_rows([p[1] for seg in segs for p in seg], n).reshape(k, 4, n)
    side = (cx - px) * nx + (cy - py) * ny
    s0, s1, s2, s3 = side[:, 0], side[:, 1], side[:, 2], side[:, 3]
    margin = 1e-9 * np.maximum(1.0, np.maximum(np.abs(s0), np.abs(s3)))
    reach = ~((side.min(axis=1) > margin) | (side.max(axis=1) < -margin))  # the hull reaches the line
    c3 = -s0 + 3 * s1 - 3 * s2 + s3
    c2 = 3 * s0 - 6 * s1 + 3 * s2
    c1 = -3 * s0 + 3 * s1
    roots = np.full((k, 3, n), np.inf)
    seg_i, set_i = np.nonzero(reach)
    if seg_i.size:
        polys = np.stack([c3[seg_i, set_i], c2[seg_i, set_i], c1[seg_i, set_i], s0[seg_i, set_i]], axis=1)
        roots[seg_i, :, set_i] = _cubic_roots01_rows(polys)
    t = np.where(np.isfinite(roots), roots, 0.0)
    s = 1.0 - t
    w0, w1, w2, w3 = s * s * s, 3.0 * s * s * t, 3.0 * s * t * t, t * t * t
    xs = w0 * cx[:, None, 0] + w1 * cx[:, None, 1] + w2 * cx[:, None, 2] + w3 * cx[:, None, 3]
    ys = w0 * cy[:, None, 0] + w1 * cy[:, None, 1] + w2 * cy[:, None, 2] + w3 * cy[:, None, 3]
    return xs.reshape(3 * k, n), ys.reshape(3 * k, n), np.isfinite(roots).reshape(3 * k, n)


def _cubic_roots01_rows(polys: np.ndarray) -> np.ndarray:
    """:func:`_cubic_roots01` of each row (c3, c2, c1, c0): its roots in [0, 1], ascending, padded with inf.

    As the scalar function does it, row by row, but on arrays: the leading
    coefficients negligible beside the others are dropped, np.roots' companion
    matrices of what is left go through one eigvals call per degree (its
    trailing zero coefficients are roots at 0), and every root is polished by
    the same Newton steps on the whole cubic.
    """
    rows = polys.shape[0]
    size = np.abs(polys)
    lead = np.zeros(rows, dtype=int)  # the first coefficient kept
    for j in range(4):
        big = np.maximum(1.0, size[:, j:].max(axis=1))
        lead[(lead == j) & (size[:, j] <= 1e-15 * big)] = j + 1
    nonzero = polys != 0.0
    last = np.where(nonzero[:, ::-1].any(axis=1), 3 - np.argmax(nonzero[:, ::-1], axis=1), -1)  # last nonzero
    roots = np.full((rows, 3), np.nan, dtype=complex)
    for first in range(3):
        for end in range(first, 4):
            at = np.flatnonzero((lead == first) & (last == end))
            if not at.size:
                continue
            degree = end - first  # np.roots: the companion of the kept coefficients, and 3 - end roots at 0
            if degree:
                comp = np.zeros((at.size, degree, degree))
                comp[:, 0, :] = -polys[at, first + 1:end + 1] / polys[at, first:first + 1]
                for k in range(1, degree):
                    comp[:, k, k - 1] = 1.0
                roots[at, :degree] = np.linalg.eigvals(comp)
            roots[at, degree:degree + 3 - end] = 0.0
    real = np.abs(roots.imag) <= 1e-7  # NaN (no root there) is not
    t = np.where(real, roots.real, 0.0)
    a3, a2, a1, a0 = (polys[:, j:j + 1] for j in range(4))
    active = real.copy()
    for _ in range(3):  # _polished01's Newton steps, each root stopping where the derivative vanishes
        f = ((a3 * t + a2) * t + a1) * t + a0
        df = (3 * a3 * t + 2 * a2) * t + a1
        active &= df != 0.0
        t = np.where(active, t - f / np.where(df == 0.0, 1.0, df), t)
    keep = real & (t >= -1e-12) & (t <= 1.0 + 1e-12)
    return np.sort(np.where(keep, np.clip(t, 0.0, 1.0), np.inf), axis=1)
