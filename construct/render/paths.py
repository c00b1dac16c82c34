"""SVG path data for what the instruments draw: arcs, curves, straight pieces, polygons, hatching.

Every function maps drawing units through a :class:`~construct.render.viewport.Viewport`
and returns the ``d`` attribute of one ``<path>``, numbers formatted by
:func:`~construct.render.svgdoc.fmt` (byte-stable).

>>> from construct.render.viewport import Viewport
>>> vp = Viewport(0.0, 1.0, 10.0, 20.0, 20.0, 0.0)
>>> polygon_path(vp, ((0, 0), (1, 1), (1, 0)))
'M0 10L10 0L10 10Z'
"""

from __future__ import annotations

import math
from typing import Sequence

import numpy as np

from .svgdoc import fmt
from .viewport import Viewport

__all__ = ["arc_path", "bezier_arrays", "bezier_controls", "curve_path", "polyline_path", "polygon_path", "hatch_path",
           "hatch_segments"]


def arc_path(vp: Viewport, cx: float, cy: float, r: float, start: float, sweep: float) -> str:
    """An SVG arc path; y is flipped, so counter-clockwise in the plane is sweep-flag 0."""
    x0, y0 = vp.xy(cx + r * math.cos(start), cy + r * math.sin(start))
    x1, y1 = vp.xy(cx + r * math.cos(start + sweep), cy + r * math.sin(start + sweep))
    large = 1 if sweep > math.pi else 0
    rr = vp.length(r)
    return f"M{x0} {y0}A{rr} {rr} 0 {large} 0 {x1} {y1}"


def bezier_controls(P) -> list[tuple[tuple[float, float], ...]]:
    """The cubic pieces (p1, c1, c2, p2) of the smooth curve through the points *P* (Catmull-Rom): the one
    rule a curve is drawn by (:func:`curve_path`), placed round (the letters keep off it) and broken by (a
    plate's gap for a letter).

    >>> bezier_controls([(0.0, 0.0), (6.0, 0.0)])
    [((0.0, 0.0), (1.0, 0.0), (5.0, 0.0), (6.0, 0.0))]
    """
    out = []
    for i in range(len(P) - 1):
        p0 = P[i - 1] if i > 0 else P[i]
        p1, p2 = P[i], P[i + 1]
        p3 = P[i + 2] if i + 2 < len(P) else P[i + 1]
        c1 = (p1[0] + (p2[0] - p0[0]) / 6.0, p1[1] + (p2[1] - p0[1]) / 6.0)
        c2 = (p2[0] - (p3[0] - p1[0]) / 6.0, p2[1] - (p3[1] - p1[1]) / 6.0)
        out.append((p1, c1, c2, p2))
    return out


def bezier_arrays(P: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """:func:`bezier_controls` on arrays: the points *P* (a row each: n x 2, or one coordinate of the points at
    every value of a sweep, n x values) -> p1, c1, c2, p2 (each n - 1 rows), the same numbers (the same operations
    in the same order).

    >>> [a.tolist() for a in bezier_arrays(np.array([(0.0, 0.0), (6.0, 0.0)]))]
    [[[0.0, 0.0]], [[1.0, 0.0]], [[5.0, 0.0]], [[6.0, 0.0]]]
    """
    i = np.arange(len(P) - 1)
    p1, p2 = P[i], P[i + 1]
    return p1, p1 + (p2 - P[np.maximum(i - 1, 0)]) / 6.0, p2 - (P[np.minimum(i + 2, len(P) - 1)] - p1) / 6.0, p2


def curve_path(vp: Viewport, pts: tuple) -> str:
    """A smooth curve through the points (Catmull-Rom as cubic Béziers, :func:`bezier_controls`)."""
    P = [vp.px(x, y) for x, y in pts]
    if len(P) < 2:
        return ""
    d = [f"M{fmt(P[0][0])} {fmt(P[0][1])}"]
    for _, c1, c2, p2 in bezier_controls(P):
        d.append(f"C{fmt(c1[0])} {fmt(c1[1])} {fmt(c2[0])} {fmt(c2[1])} {fmt(p2[0])} {fmt(p2[1])}")
    return "".join(d)


def polyline_path(vp: Viewport, pts: tuple) -> str:
    """Straight segments from point to point, as the straightedge joins them (closed: back to the first by Z).

    >>> vp = Viewport(0.0, 1.0, 10.0, 20.0, 20.0, 0.0)
    >>> polyline_path(vp, ((0, 0), (1, 1), (1, 0))), polyline_path(vp, ((0, 0), (1, 1), (1, 0), (0, 0)))
    ('M0 10L10 0L10 10', 'M0 10L10 0L10 10Z')
    """
    P = [vp.xy(x, y) for x, y in pts]
    if len(P) < 2:
        return ""
    closed = len(pts) > 2 and tuple(pts[0]) == tuple(pts[-1])
    if closed:
        P = P[:-1]
    return "M" + "L".join(f"{a} {b}" for a, b in P) + ("Z" if closed else "")


def polygon_path(vp: Viewport, pts: tuple) -> str:
    """A closed polygon through the points."""
    return "M" + "L".join(f"{a} {b}" for a, b in (vp.xy(x, y) for x, y in pts)) + "Z"


def hatch_path(vp: Viewport, pts: tuple, spacing_px: float, angle_deg: float = 45.0, under: tuple = ()) -> str:
    """Fine parallel lines at *angle_deg*, clipped to the polygon by shapely (the draftsman's hatching); *under*:
    the polygons (drawing units) of sections drawn over this one, which its hatching does not run into."""
    return "".join(f"M{fmt(ax)} {fmt(ay)}L{fmt(bx)} {fmt(by)}"
                   for (ax, ay), (bx, by) in hatch_segments([vp.px(x, y) for x, y in pts], spacing_px, angle_deg,
                                                            under=[[vp.px(x, y) for x, y in o] for o in under]))


def hatch_segments(ring: list[tuple[float, float]], spacing: float, angle_deg: float = 45.0,
                   under: Sequence[Sequence[tuple[float, float]]] = (),
                   ) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The hatching of the polygon *ring* (canvas units, y down): lines *spacing* apart at *angle_deg*, each
    clipped to the polygon less the polygons *under* (sections drawn over it), as (start, end) pairs; pieces
    shorter than half a unit are left out.

    >>> hatch_segments([(1, 1), (9, 1), (9, 9), (1, 9)], 5.0, 0.0)
    [((1.0, 5.0), (9.0, 5.0))]
    """
    from shapely.geometry import LineString, MultiLineString, Polygon

    poly = Polygon(ring).buffer(0)
    for other in under:
        poly = poly.difference(Polygon(other).buffer(0))
    if poly.is_empty:
        return []
    x0, y0, x1, y1 = poly.bounds
    a = math.radians(angle_deg)
    ux, uy = math.cos(a), -math.sin(a)  # along the hatch (y down)
    nx, ny = -uy, ux                      # across it
    corners = [(x0, y0), (x1, y0), (x0, y1), (x1, y1)]
    ts = [cx * nx + cy * ny for cx, cy in corners]
    reach = math.hypot(x1 - x0, y1 - y0)
    lines = []
    t = math.floor(min(ts) / spacing) * spacing
    while t <= max(ts):
        mx, my = t * nx, t * ny
        # a point on the hatch line near the box centre, then a long segment both ways
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        s = (cx - mx) * ux + (cy - my) * uy
        px, py = mx + s * ux, my + s * uy
        lines.append(LineString([(px - reach * ux, py - reach * uy), (px + reach * ux, py + reach * uy)]))
        t += spacing
    clipped = MultiLineString(lines).intersection(poly)
    out = []
    for g in getattr(clipped, "geoms", [clipped]):
        if g.geom_type != "LineString" or g.length < 0.5:
            continue
        out.append((tuple(g.coords[0]), tuple(g.coords[-1])))
    return out
