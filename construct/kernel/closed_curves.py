"""Closed smooth curves through constructed points: the French curve laid round a whole figure.

The polar speed diagram of seed 002 (Fig. 566) is a wave *round* the crank
centre, not a graph over an axis, so :func:`~construct.kernel.curves.french_curve_op`
(which sorts its points along an axis) cannot draw it.  A draftsman lays the
French curve through three points at a time all the way round; here that is a
periodic cubic Hermite chain with Bessel tangents (the tangent at a point is
that of the parabola through it and its two neighbours, parametrised by chord
length), closed on its first point.

>>> from construct.kernel.geometry import SCALAR, Point
>>> sq = [Point(1.0, 0.0), Point(0.0, 1.0), Point(-1.0, 0.0), Point(0.0, -1.0)]
>>> (c,) = closed_french_curve_op(sq, {"points": 4}, {}, (), SCALAR)
>>> c.kind, len(c.segments()), c.points[0] == c.points[-1]
('bezier', 4, True)
"""

from __future__ import annotations

import math

import numpy as np

from .curves import BezierCurve
from .errors import GeometryError
from .geometry import SCALAR, Point, sets_where

__all__ = ["closed_french_curve_op"]


def closed_french_curve_op(args, params, givens, refs, xp):
    """A closed smooth curve through the points in their order (periodic Hermite, Bessel tangents)."""
    pts = list(args)
    n = len(pts)
    if n < 3:
        raise GeometryError(f"a closed curve needs at least 3 points, got {n}")
    if xp is not SCALAR:
        return (_closed_curve_sweep(pts, xp.n),)
    h = [math.hypot(pts[(i + 1) % n].x - pts[i].x, pts[(i + 1) % n].y - pts[i].y) for i in range(n)]
    if min(h) <= 1e-12 * max(h):
        raise GeometryError("two consecutive points of the closed curve coincide")
    d = [((pts[(i + 1) % n].x - pts[i].x) / h[i], (pts[(i + 1) % n].y - pts[i].y) / h[i]) for i in range(n)]
    tangents = []
    for i in range(n):
        hp, hn = h[i - 1], h[i]
        dp, dn = d[i - 1], d[i]
        tangents.append(((hn * dp[0] + hp * dn[0]) / (hp + hn), (hn * dp[1] + hp * dn[1]) / (hp + hn)))
    out = [pts[0]]
    for i in range(n):
        j = (i + 1) % n
        third = h[i] / 3.0
        out += [Point(pts[i].x + tangents[i][0] * third, pts[i].y + tangents[i][1] * third),
                Point(pts[j].x - tangents[j][0] * third, pts[j].y - tangents[j][1] * third), pts[j]]
    return (BezierCurve(out),)


def _closed_curve_sweep(pts: list, sets: int) -> BezierCurve:
    """closed_french_curve_op for every set of a sweep at once: the same arithmetic on arrays."""
    n = len(pts)
    x, y = np.empty((n, sets)), np.empty((n, sets))
    for k, p in enumerate(pts):
        x[k], y[k] = p.x, p.y
    ex, ey = np.roll(x, -1, axis=0) - x, np.roll(y, -1, axis=0) - y  # from each point to the next
    h = np.hypot(ex, ey)
    close = h.min(axis=0) <= 1e-12 * h.max(axis=0)
    if close.any():
        raise GeometryError("two consecutive points of the closed curve coincide" + sets_where(close))
    dx, dy = ex / h, ey / h
    hp, dpx, dpy = np.roll(h, 1, axis=0), np.roll(dx, 1, axis=0), np.roll(dy, 1, axis=0)  # the segment before
    tx, ty = (h * dpx + hp * dx) / (hp + h), (h * dpy + hp * dy) / (hp + h)
    third = h / 3.0
    out = [pts[0]]
    for i in range(n):
        j = (i + 1) % n
        out += [Point(x[i] + tx[i] * third[i], y[i] + ty[i] * third[i]),
                Point(x[j] - tx[j] * third[i], y[j] - ty[j] * third[i]), pts[j]]
    return BezierCurve(out)
