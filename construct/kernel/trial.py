"""Instruments that are not straightedge and compass: dividers set by trial, Archimedes' marked ruler.

Both are honest about what they are (provenance ``trial`` and ``neusis``):
the dividers are opened, stepped round and corrected until they close, as a
draftsman divides a circle into 7 or 9 parts; the marked ruler is slid until
its marks sit on a circle and a line.  Each is an entry of the op table
(:mod:`construct.kernel.ops`) taking ``(args, params, givens, refs, xp)``.
They iterate; in a sweep every set of givens iterates at once on arrays, each
set stopping where its own trial closes (the same rounds, steps and tests as
the scalar loop, held equal to it set by set in tests/test_sweep.py).
"""

from __future__ import annotations

import math

import numpy as np

from .errors import GeometryError
from .geometry import (ARRAY, SCALAR, Circle, Length, Line, Point, intersect_line_circle, line_circle, raw_point,
                       sets_where)

__all__ = ["trial_chord_op", "neusis_archimedes_op"]


def trial_chord_op(args, params, givens, refs, xp):
    """Set the dividers by trial so that *parts* steps from start round *circle* close on end."""
    circle, start, end = args
    n = int(params["parts"])
    if xp is not SCALAR:
        return (Length(_trial_chord_sweep(circle, start, end, n, float(params["tolerance"]), xp.n)),)
    r = circle.radius
    tol = float(params["tolerance"]) * r
    # First guess, the draftsman's rule of thumb: half as much again as the
    # straight distance shared out (the half circle is pi/2 = 1.57 diameters).
    opening = 1.5 * start.distance(end) / n
    for _ in range(200):
        landing = _step_round(circle, start, end, opening, n)
        gap = landing.distance(end)
        # Short of the end while still on the near side of the stroke, else beyond it.
        short = _side(start, end, landing) > 0 or gap <= tol
        if gap <= tol:
            return (Length(opening),)
        opening += gap / n if short else -gap / n
        if not 0.0 < opening < 2.0 * r:
            raise GeometryError(f"dividers by trial diverged (opening {opening:.6g} for radius {r:.6g})")
    raise GeometryError(f"dividers by trial did not close to {tol:.3g} in 200 rounds")


def _side(a: Point, b: Point, p: Point) -> float:
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x)


def _step_round(circle: Circle, start: Point, end: Point, opening: float, n: int) -> Point:
    """Step the dividers n times round *circle* from *start*; return where they land.

    Each step is the compass step of the protocol (a circle of radius
    *opening* about the last point, cut with the crank circle, going on
    away from the point before), written out inline because the trial
    repeats it n times per round.
    """
    ox, oy, r = circle.center.x, circle.center.y, circle.radius
    # Which way is "on": the first step goes to the left of start->end (above the stroke).
    ex, ey = end.x - start.x, end.y - start.y
    px, py = start.x, start.y  # previous point
    hx, hy = start.x, start.y  # current point
    for i in range(n):
        dx, dy = hx - ox, hy - oy
        d = math.hypot(dx, dy)
        outer = r + opening - d
        inner = d - abs(r - opening)
        if outer < 0.0 or inner < 0.0:
            raise GeometryError(f"dividers opening {opening:.6g} does not reach round the circle")
        ux, uy = dx / d, dy / d
        a = 0.5 * (d + (r - opening) * (r + opening) / d)
        h = math.sqrt(outer * (r + opening + d) * inner * (d + abs(r - opening))) / (2.0 * d)
        mx, my = ox + a * ux, oy + a * uy
        ax, ay = mx + h * uy, my - h * ux
        bx, by = mx - h * uy, my + h * ux
        if i == 0:
            first = ex * (ay - start.y) - ey * (ax - start.x) >= ex * (by - start.y) - ey * (bx - start.x)
        else:
            first = (ax - px) ** 2 + (ay - py) ** 2 >= (bx - px) ** 2 + (by - py) ** 2
        px, py = hx, hy
        hx, hy = (ax, ay) if first else (bx, by)
    return Point(hx, hy)


def neusis_archimedes_op(args, params, givens, refs, xp):
    """Archimedes' marked ruler: through b, a line meeting the circle at C and line aO beyond O at D with CD = r."""
    o, a, b, circle = args
    if xp is not SCALAR:
        return _neusis_sweep(o, a, b, circle, xp.n)
    r = circle.radius
    ux, uy = (o.x - a.x) / r, (o.y - a.y) / r  # direction from a through O, beyond O

    def excess(t: float) -> tuple[float, Point, Point]:
        d = Point(o.x + t * ux, o.y + t * uy)
        pts = intersect_line_circle(Line(d, b), circle)
        c = min(pts, key=d.distance)
        return d.distance(c) - r, d, c

    lo, hi = r * (1.0 + 1e-12), 2.0 * r * (1.0 - 1e-12)
    f_lo, f_hi = excess(lo)[0], excess(hi)[0]
    if f_lo * f_hi > 0:
        raise GeometryError("the marked ruler finds no position (arc larger than a semicircle?)")
    for _ in range(200):  # slide the ruler until the marks sit on circle and line
        mid = 0.5 * (lo + hi)
        f_mid = excess(mid)[0]
        if (f_mid > 0) == (f_lo > 0):
            lo, f_lo = mid, f_mid
        else:
            hi = mid
        if hi - lo <= 1e-15 * r:
            break
    _, d, c = excess(0.5 * (lo + hi))
    return (d, c)


# --------------------------------------------------------------------------
# The same instruments for every set of a sweep at once.
# --------------------------------------------------------------------------


def _sets(v, n: int) -> np.ndarray:
    return np.broadcast_to(np.asarray(v, dtype=float), (n,))


def _trial_chord_sweep(circle: Circle, start: Point, end: Point, n: int, tolerance: float, sets: int) -> np.ndarray:
    """trial_chord_op's opening for every set: each set's trial runs its own rounds, all sets at once."""
    ox, oy, r = (_sets(v, sets) for v in (circle.center.x, circle.center.y, circle.radius))
    sx, sy, ex, ey = (_sets(v, sets) for v in (start.x, start.y, end.x, end.y))
    tol = tolerance * r
    opening = 1.5 * np.hypot(ex - sx, ey - sy) / n
    todo = np.arange(sets)  # the sets whose dividers do not close yet
    for _ in range(200):
        at = (ox[todo], oy[todo], r[todo], sx[todo], sy[todo], ex[todo], ey[todo])
        lx, ly = _step_round_sets(*at, opening[todo], n, todo, sets)
        gap = np.hypot(ex[todo] - lx, ey[todo] - ly)
        closed = gap <= tol[todo]
        short = ((ex[todo] - sx[todo]) * (ly - sy[todo]) - (ey[todo] - sy[todo]) * (lx - sx[todo]) > 0) | closed
        todo, gap, short = todo[~closed], gap[~closed], short[~closed]
        if not todo.size:
            return opening
        opening[todo] += np.where(short, gap / n, -gap / n)
        off = ~((0.0 < opening[todo]) & (opening[todo] < 2.0 * r[todo]))
        if off.any():
            i = todo[off][0]
            raise GeometryError(f"dividers by trial diverged (opening {opening[i]:.6g} for radius {r[i]:.6g})"
                                + _at_sets(todo[off], sets))
    raise GeometryError(f"dividers by trial did not close to {tol[todo[0]]:.3g} in 200 rounds" + _at_sets(todo, sets))


def _at_sets(which: np.ndarray, sets: int) -> str:
    bad = np.zeros(sets, dtype=bool)
    bad[which] = True
    return sets_where(bad)


def _step_round_sets(ox, oy, r, sx, sy, ex, ey, opening, n: int, which: np.ndarray, sets: int):
    """_step_round for the sets *which* at once: where n steps of the dividers land, as arrays."""
    ex, ey = ex - sx, ey - sy
    px, py = sx, sy
    hx, hy = sx, sy
    for i in range(n):
        dx, dy = hx - ox, hy - oy
        d = np.hypot(dx, dy)
        outer = r + opening - d
        inner = d - np.abs(r - opening)
        short = (outer < 0.0) | (inner < 0.0)
        if short.any():
            raise GeometryError(f"dividers opening {opening[short][0]:.6g} does not reach round the circle"
                                + _at_sets(which[short], sets))
        ux, uy = dx / d, dy / d
        a = 0.5 * (d + (r - opening) * (r + opening) / d)
        h = np.sqrt(outer * (r + opening + d) * inner * (d + np.abs(r - opening))) / (2.0 * d)
        mx, my = ox + a * ux, oy + a * uy
        ax, ay = mx + h * uy, my - h * ux
        bx, by = mx - h * uy, my + h * ux
        if i == 0:
            first = ex * (ay - sy) - ey * (ax - sx) >= ex * (by - sy) - ey * (bx - sx)
        else:
            first = (ax - px) ** 2 + (ay - py) ** 2 >= (bx - px) ** 2 + (by - py) ** 2
        px, py = hx, hy
        hx, hy = np.where(first, ax, bx), np.where(first, ay, by)
    return hx, hy


def _neusis_sweep(o: Point, a: Point, b: Point, circle: Circle, sets: int) -> tuple[Point, Point]:
    """neusis_archimedes_op for every set: the marked ruler slid by bisection in all sets at once."""
    r = _sets(circle.radius, sets)
    ux, uy = (o.x - a.x) / r, (o.y - a.y) / r

    def excess(t):
        d = raw_point(o.x + t * ux, o.y + t * uy)
        p, q = line_circle(Line(d, b), circle, ARRAY)
        near = np.hypot(p.x - d.x, p.y - d.y) <= np.hypot(q.x - d.x, q.y - d.y)
        c = raw_point(np.where(near, p.x, q.x), np.where(near, p.y, q.y))
        return np.hypot(c.x - d.x, c.y - d.y) - r, d, c

    lo, hi = r * (1.0 + 1e-12), 2.0 * r * (1.0 - 1e-12)
    f_lo, f_hi = excess(lo)[0], excess(hi)[0]
    none = f_lo * f_hi > 0
    if none.any():
        raise GeometryError("the marked ruler finds no position (arc larger than a semicircle?)" + sets_where(none))
    sliding = np.ones(sets, dtype=bool)
    for _ in range(200):  # slide the ruler until the marks sit on circle and line
        mid = 0.5 * (lo + hi)
        f_mid = excess(mid)[0]
        up = sliding & ((f_mid > 0) == (f_lo > 0))
        lo, f_lo = np.where(up, mid, lo), np.where(up, f_mid, f_lo)
        hi = np.where(sliding & ~up, mid, hi)
        sliding &= ~(hi - lo <= 1e-15 * r)
        if not sliding.any():
            break
    _, d, c = excess(0.5 * (lo + hi))
    return d, c
