"""The operations that draw curves through constructed points: entries of the op table
(:mod:`construct.kernel.ops`), each taking (args, params, givens, refs, xp) and returning its outputs -- the
French curve along an axis (with its array form for a sweep), the parabola's envelope, the polyline, a
digitised diagram traced from its givens (trace) and a vertex of a drawn chain.

The curves themselves, and where a line crosses them, are :mod:`construct.kernel.curves`.

>>> axis = Line(Point(0.0, 0.0), Point(1.0, 0.0))
>>> frame_of(axis)  # along the axis, and its normal ("up")
(1.0, 0.0, -0.0, 1.0)
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .curves import BezierCurve, Polyline, coordinate_rows
from .errors import DegenerateObject, GeometryError
from .geometry import SCALAR, Line, Point, raw_point, sets_where

__all__ = ["frame_of", "french_curve_op", "parabola_envelope_op", "polyline_op", "trace_op", "vertex_op"]


def frame_of(axis: Line) -> tuple[float, float, float, float]:
    ux, uy = axis.direction()
    return ux, uy, -uy, ux  # along the axis, and its normal ("up")


def french_curve_op(args, params, givens, refs, xp):
    """A smooth curve through the points (sorted along the axis) that follows the given tangents.

    Piecewise cubic Hermite in the frame of the axis: the slope at a point is
    the given tangent's where there is one, else that of the parabola through
    the point and its two neighbours (Bessel), as a draftsman lays a French
    curve through three points at a time.  At a *corner* (``corners``: indices
    of points, optional) the curve is laid anew: the pieces on either side end
    there with their own one-sided slopes, as the draftsman stops the curve at a
    kink (a dead centre of a crank in a summed tangential diagram).
    """
    if xp is not SCALAR:
        return (_french_curve_sweep(args, params, xp.n),)
    axis = args[0]
    n = int(params["points"])
    pts = list(args[1:1 + n])
    tangents = dict(zip((int(i) for i in params["tangent_at"]), args[1 + n:]))
    corners = {int(i) for i in params.get("corners", ())}
    ux, uy, nx, ny = frame_of(axis)
    rows = sorted(((p.x * ux + p.y * uy, p.x * nx + p.y * ny, i, p) for i, p in enumerate(pts)),
                  key=lambda r: (r[0], r[2]))
    u = [r[0] for r in rows]
    v = [r[1] for r in rows]
    scale = max(abs(a) for a in u + v) or 1.0
    for a, c in zip(u, u[1:]):
        if c - a <= 1e-12 * scale:
            raise GeometryError("two points of the curve share an abscissa; a French curve cannot pass both")
    cuts = [0] + [j for j in range(1, len(rows) - 1) if rows[j][2] in corners] + [len(rows) - 1]

    def plane(a: float, b: float) -> Point:
        return Point(a * ux + b * nx, a * uy + b * ny)

    out = [rows[0][3]]
    for lo, hi in zip(cuts, cuts[1:]):
        pu, pv = u[lo:hi + 1], v[lo:hi + 1]
        slopes = _slopes(pu, pv, [r[2] for r in rows[lo:hi + 1]], tangents, ux, uy, nx, ny)
        for j in range(len(pu) - 1):
            third = (pu[j + 1] - pu[j]) / 3.0
            out += [plane(pu[j] + third, pv[j] + slopes[j] * third),
                    plane(pu[j + 1] - third, pv[j + 1] - slopes[j + 1] * third), rows[lo + j + 1][3]]
    return (BezierCurve(out),)


def _french_curve_sweep(args, params, sets: int) -> "BezierCurve":
    """french_curve_op for every set of a sweep at once: the same curve, set by set, on arrays.

    The points are sorted along the axis in each set on its own (their order may change with the givens);
    a corner lays the curve anew wherever its point comes in that set's order.
    """
    axis = args[0]
    m = int(params["points"])
    pts = list(args[1:1 + m])
    tangent_at = [int(i) for i in params["tangent_at"]]
    corners = {int(i) for i in params.get("corners", ())}
    ux, uy, nx, ny = frame_of(axis)
    px, py = coordinate_rows([p.x for p in pts], sets), coordinate_rows([p.y for p in pts], sets)
    order = np.argsort(px * ux + py * uy, axis=0, kind="stable")  # by abscissa, then by index: as sorted() does
    px, py = np.take_along_axis(px, order, 0), np.take_along_axis(py, order, 0)
    u, v = px * ux + py * uy, px * nx + py * ny
    scale = np.maximum(np.abs(u).max(axis=0), np.abs(v).max(axis=0))
    scale = np.where(scale == 0.0, 1.0, scale)
    h = u[1:] - u[:-1]
    close = (h <= 1e-12 * scale).any(axis=0)
    if close.any():
        raise GeometryError("two points of the curve share an abscissa; a French curve cannot pass both"
                            + sets_where(close))
    d = (v[1:] - v[:-1]) / h
    # each set's slope at each sorted position: the tangent's where its point has one, else Bessel's, one-sided
    # where a piece starts or ends (the first and last points, and the corners)
    given = np.full((m, sets), np.nan)
    for i, t in zip(tangent_at, args[1 + m:]):
        du = (t.q.x - t.p.x) * ux + (t.q.y - t.p.y) * uy
        dv = (t.q.x - t.p.x) * nx + (t.q.y - t.p.y) * ny
        steep = np.abs(du) <= 1e-12 * np.hypot(du, dv)
        if np.any(steep):
            raise GeometryError("a tangent of the curve is perpendicular to the axis" + sets_where(
                np.broadcast_to(steep, (sets,))))
        given[i] = dv / du
    given = np.take_along_axis(given, order, 0)
    cut = np.isin(order, list(corners)) if corners else np.zeros((m, sets), dtype=bool)
    cut[0] = cut[-1] = True  # where a piece starts or ends
    start = np.empty((m - 1, sets))  # the slope at the first point of each segment, within its piece
    end = np.empty((m - 1, sets))  # and at its last point
    alone = cut[:-1] & cut[1:]  # a piece of one segment
    with np.errstate(divide="ignore", invalid="ignore"):
        if m > 2:
            # segment j from position j to j + 1; a piece's last segment has no next one, its first no previous
            # one: there the one-sided slope is not needed (the piece is that segment alone: d)
            first = d[:-1] + (d[:-1] - d[1:]) * h[:-1] / (h[:-1] + h[1:])  # at a piece's start, j = 0 .. m-3
            last = d[1:] + (d[1:] - d[:-1]) * h[1:] / (h[1:] + h[:-1])  # at a piece's end, j = 1 .. m-2
            inner = (h[1:] * d[:-1] + h[:-1] * d[1:]) / (h[:-1] + h[1:])  # Bessel's, at positions 1 .. m-2
            start[:] = np.where(cut[:-1], np.vstack([first, d[-1:]]), np.vstack([d[:1], inner]))
            end[:] = np.where(cut[1:], np.vstack([d[:1], last]), np.vstack([inner, d[-1:]]))
        start = np.where(alone, d, start)
        end = np.where(alone, d, end)
    start = np.where(np.isnan(given[:-1]), start, given[:-1])
    end = np.where(np.isnan(given[1:]), end, given[1:])
    third = h / 3.0
    c1u, c1v = u[:-1] + third, v[:-1] + start * third
    c2u, c2v = u[1:] - third, v[1:] - end * third
    out = [raw_point(px[0], py[0])]
    for j in range(m - 1):
        out += [Point(c1u[j] * ux + c1v[j] * nx, c1u[j] * uy + c1v[j] * ny),
                Point(c2u[j] * ux + c2v[j] * nx, c2u[j] * uy + c2v[j] * ny), raw_point(px[j + 1], py[j + 1])]
    return BezierCurve(out)


def _slopes(u: list[float], v: list[float], index: list[int], tangents: dict, ux: float, uy: float, nx: float,
            ny: float) -> list[float]:
    """The slope at each point of one smooth piece: the given tangent's, else Bessel's (one-sided at the ends)."""
    h = [c - a for a, c in zip(u, u[1:])]
    d = [(v[i + 1] - v[i]) / h[i] for i in range(len(h))]
    slopes = []
    for j, i in enumerate(index):
        if i in tangents:
            t = tangents[i]
            du = (t.q.x - t.p.x) * ux + (t.q.y - t.p.y) * uy
            dv = (t.q.x - t.p.x) * nx + (t.q.y - t.p.y) * ny
            if abs(du) <= 1e-12 * math.hypot(du, dv):
                raise GeometryError("a tangent of the curve is perpendicular to the axis")
            slopes.append(dv / du)
        elif len(h) == 1:
            slopes.append(d[0])
        elif j == 0:
            slopes.append(d[0] + (d[0] - d[1]) * h[0] / (h[0] + h[1]))
        elif j == len(index) - 1:
            slopes.append(d[-1] + (d[-1] - d[-2]) * h[-1] / (h[-1] + h[-2]))
        else:
            slopes.append((h[j] * d[j - 1] + h[j - 1] * d[j]) / (h[j - 1] + h[j]))
    return slopes


def parabola_envelope_op(args, params, givens, refs, xp):
    """The parabola touching ED at E and DF at F (the envelope of the lines joining equal divisions of ED and DF)."""
    e, d, f = args
    c1 = Point(e.x + 2.0 / 3.0 * (d.x - e.x), e.y + 2.0 / 3.0 * (d.y - e.y))
    c2 = Point(f.x + 2.0 / 3.0 * (d.x - f.x), f.y + 2.0 / 3.0 * (d.y - f.y))
    return (BezierCurve((e, c1, c2, f)),)


def polyline_op(args, params, givens, refs, xp):
    """The constructed points joined in order by the straightedge."""
    return (Polyline(args, closed=bool(params.get("closed"))),)


def trace_op(args, params, givens, refs, xp):
    """A digitised diagram traced onto the drawing and its points joined by the straightedge.

    Inputs: the stroke's ends *head* and *crank*, and two points *up0*, *up1* whose left side the pressures
    stand on.  Each point i: x_i (the given ``xs[i]``) times the stroke length (the product of the givens
    ``stroke`` times ``stroke_factor``) from *head* towards *crank*, p_i (``ps[i]``) times the pressure scale
    (the product of ``pressure``) up the perpendicular.  ``extend`` continues the line level to both dead
    centres where it stops short of them (x = 0, 1); ``closed`` joins the last point to the first.  In a
    sweep the same, set by set, on arrays; the extension must then be the same in every set (the chain's
    points are the same in number).
    """
    head, crank, up0, up1 = args
    length = xp.hypot(crank.x - head.x, crank.y - head.y)
    ux, uy = (crank.x - head.x) / length, (crank.y - head.y) / length
    vx, vy = up1.x - up0.x, up1.y - up0.y
    norm = xp.hypot(vx, vy)
    nx, ny = -vy / norm, vx / norm   # the left normal of up0 -> up1
    stroke = float(params.get("stroke_factor", 1.0))
    for name in params["stroke"]:
        stroke = stroke * givens[name]
    scale = 1.0
    for name in params["pressure"]:
        scale = scale * givens[name]
    number = float if xp is SCALAR else (lambda v: np.asarray(v, dtype=float))
    xs = [number(givens[n]) for n in params["xs"]]
    ps = [number(givens[n]) for n in params["ps"]]
    if params.get("extend"):  # each end to the dead centre it is nearer: 0 (head) or 1 (crank)
        forward = _same_in_all(xs[0] <= xs[-1], "runs from the head end in some sets and not in others")
        first, last = (0.0, 1.0) if forward else (1.0, 0.0)
        if _same_in_all(xs[0] != first, "reaches its first dead centre in some sets and not in others"):
            xs, ps = [first] + xs, [ps[0]] + ps
        if _same_in_all(xs[-1] != last, "reaches its last dead centre in some sets and not in others"):
            xs, ps = xs + [last], ps + [ps[-1]]
    pts = [Point(head.x + ux * x * stroke + nx * p * scale, head.y + uy * x * stroke + ny * p * scale)
           for x, p in zip(xs, ps)]
    return (Polyline(pts, closed=bool(params.get("closed"))),)


def _same_in_all(cond: Any, what: str) -> bool:
    """A decision of the trace that fixes how many points it has: one value, or the same in every set of a sweep."""
    if isinstance(cond, np.ndarray):
        if cond.any() and not cond.all():
            raise GeometryError("the traced diagram " + what + sets_where(~cond if cond[0] else cond))
        return bool(cond.all())
    return bool(cond)


def vertex_op(args, params, givens, refs, xp):
    """A point of a drawn chain: its vertex ``index`` (the end of a chord the draftsman lays a straightedge on)."""
    (chain,) = args
    if not isinstance(chain, Polyline):
        raise GeometryError("a vertex is a point of a chain of chords; this graph is not one")
    i = int(params["index"])
    if not 0 <= i < len(chain.points):
        raise DegenerateObject(f"the chain has {len(chain.points)} points, no point {i}")
    return (chain.points[i],)
