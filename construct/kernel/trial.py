"""Instruments that are not straightedge and compass: dividers set by trial, Archimedes' marked ruler.

Both are honest about what they are (provenance ``trial`` and ``neusis``):
the dividers are opened, stepped round and corrected until they close, as a
draftsman divides a circle into 7 or 9 parts; the marked ruler is slid until
its marks sit on a circle and a line.  Each is an entry of the op table
(:mod:`construct.kernel.ops`) taking ``(args, params, givens, refs, xp)``.
They iterate, so in a sweep they run once per set of givens.
"""

from __future__ import annotations

import math

from .errors import GeometryError
from .geometry import Circle, Length, Line, Point, intersect_line_circle

__all__ = ["trial_chord_op", "neusis_archimedes_op"]


def trial_chord_op(args, params, givens, refs, xp):
    """Set the dividers by trial so that *parts* steps from start round *circle* close on end."""
    circle, start, end = args
    n = int(params["parts"])
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
