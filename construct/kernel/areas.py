"""Areas between drawn curves, measured as a draftsman measures them: with a planimeter.

The force diagrams of the books end in areas: the free forces between the
piston-force line and the mass-force curve, the excess area of the
tangential-pressure diagram above its mean line.  An :class:`Area` is the
region between two graphs over the drawing's x axis, split where they cross
into pieces with a sign (+1 where the upper curve lies above the lower one).
shapely measures and clips it; the renderer hatches it.

>>> from .curves import Polyline
>>> up = Polyline((Point(0, 1), Point(2, -1)))
>>> base = Line(Point(0, 0), Point(1, 0))
>>> a = area_between(up, base, 0.0, 2.0)
>>> [(s, round(p.area, 12)) for s, p in a.signed_pieces()]
[(1, 0.5), (-1, 0.5)]
>>> a.signed_area(), a.area
(0.0, 1.0)

In a sweep the region between two graphs is an :class:`Areas`: the planimeter's
reading of every set computed at once on arrays, each set's pieces made when
that set is looked at (``take(i)``, for a drawing of it).
"""

from __future__ import annotations

import math
from typing import Any, Iterable, Sequence

import numpy as np

from .errors import DegenerateObject, GeometryError
from .geometry import SCALAR, Length, Line, Point, points, sets_where, take

__all__ = ["Area", "Areas", "area_between", "graph_ordinate"]


class Area:
    """Polygon pieces with signs: the region between two graphs, or any polygons given directly.

    ``pieces`` is a tuple of (sign, ring), each ring a tuple of Points
    (not repeated at the end); ``hatch_deg`` the direction the drawing
    hatches it in (90: vertical, as the books hatch force areas; None: the
    style's default).
    """

    __slots__ = ("_pieces", "_coords", "hatch_deg", "_polygons")
    kind = "area"

    def __init__(self, pieces: Iterable[tuple[int, Sequence[Point]]], hatch_deg: float | None = None) -> None:
        out = []
        for sign, ring in pieces:
            ring = tuple(ring)
            if len(ring) < 3 or not all(type(p) is Point or isinstance(p, Point) for p in ring):
                raise DegenerateObject(f"an area piece needs at least three points, got {len(ring)}")
            if sign not in (1, -1):
                raise DegenerateObject(f"an area piece has sign +1 or -1, got {sign!r}")
            out.append((int(sign), ring))
        object.__setattr__(self, "_pieces", tuple(out))
        object.__setattr__(self, "_coords", None)
        object.__setattr__(self, "hatch_deg", None if hatch_deg is None else float(hatch_deg))
        object.__setattr__(self, "_polygons", None)  # the shapely pieces, made on first use (both are immutable)

    @classmethod
    def from_coordinates(cls, pieces: Iterable[tuple[int, Any, Any]], hatch_deg: float | None = None) -> "Area":
        """An area from (sign, xs, ys) per piece: coordinate arrays, checked at once; Points made when asked for.

        What :func:`area_between` makes (rings of a thousand vertices, a
        thousand areas in a sweep, most of them only measured).

        >>> a = Area.from_coordinates([(1, [0.0, 1.0, 0.0], [0.0, 0.0, 1.0])])
        >>> a.signed_area(), a.pieces[0][1][1]
        (0.5, Point(1.0, 0.0))
        >>> a == Area([(1, [Point(0, 0), Point(1, 0), Point(0, 1)])])
        True
        """
        out = []
        for sign, xs, ys in pieces:
            xs, ys = np.array(xs, dtype=float), np.array(ys, dtype=float)
            if xs.shape != ys.shape or xs.ndim != 1 or xs.size < 3:
                raise DegenerateObject(f"an area piece needs at least three points, got {xs.size}")
            if sign not in (1, -1):
                raise DegenerateObject(f"an area piece has sign +1 or -1, got {sign!r}")
            bad = ~(np.isfinite(xs) & np.isfinite(ys))
            if bad.any():
                i = int(np.flatnonzero(bad)[0])
                raise DegenerateObject(f"Point needs finite coordinates, got ({float(xs[i])!r}, {float(ys[i])!r})")
            xs.flags.writeable = ys.flags.writeable = False
            out.append((int(sign), xs, ys))
        self = object.__new__(cls)
        object.__setattr__(self, "_pieces", None)
        object.__setattr__(self, "_coords", tuple(out))
        object.__setattr__(self, "hatch_deg", None if hatch_deg is None else float(hatch_deg))
        object.__setattr__(self, "_polygons", None)
        return self

    @property
    def pieces(self) -> tuple[tuple[int, tuple[Point, ...]], ...]:
        """(sign, ring) per piece, each ring a tuple of Points."""
        if self._pieces is None:
            object.__setattr__(self, "_pieces", tuple((s, points(xs, ys)) for s, xs, ys in self._coords))
        return self._pieces

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("Area is immutable")

    def __reduce__(self):
        return (Area, (self.pieces, self.hatch_deg))

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Area):
            return NotImplemented
        return self.pieces == other.pieces and self.hatch_deg == other.hatch_deg

    def __hash__(self) -> int:
        return hash(("Area", self.pieces, self.hatch_deg))

    def __repr__(self) -> str:
        return f"Area({len(self.pieces)} pieces, {self.area:.6g} in all)"

    def signed_pieces(self):
        """(sign, shapely Polygon) for each piece."""
        if self._polygons is None:
            from shapely.geometry import Polygon

            if self._coords is not None:
                polys = tuple((s, Polygon(np.column_stack([xs, ys]))) for s, xs, ys in self._coords)
            else:
                polys = tuple((s, Polygon(np.array([(p.x, p.y) for p in ring]))) for s, ring in self._pieces)
            object.__setattr__(self, "_polygons", polys)
        return list(self._polygons)

    @property
    def area(self) -> float:
        """The unsigned area of all pieces together."""
        return sum(poly.area for _, poly in self.signed_pieces())

    def signed_area(self) -> float:
        """Positive pieces less negative ones (what a planimeter run round the whole boundary reads)."""
        return sum(s * poly.area for s, poly in self.signed_pieces())

    def rings(self) -> tuple[tuple[Point, ...], ...]:
        return tuple(ring for _, ring in self.pieces)

    def coordinate_pieces(self) -> tuple[tuple[int, tuple[tuple[float, float], ...]], ...]:
        """(sign, ring) per piece as :attr:`pieces` has them, each vertex an (x, y) pair of floats: what a drawing
        reads, without a Point made for each vertex of an area made from coordinates (a live player's piece of
        Tafel I draws rings of a thousand vertices).

        >>> a = Area.from_coordinates([(-1, [0.0, 1.0, 0.0], [0.0, 0.0, 1.0])])
        >>> a.coordinate_pieces()
        ((-1, ((0.0, 0.0), (1.0, 0.0), (0.0, 1.0))),)
        >>> a.coordinate_pieces() == tuple((s, tuple((p.x, p.y) for p in r)) for s, r in a.pieces)
        True
        """
        if self._coords is not None:
            return tuple((s, tuple(zip(xs.tolist(), ys.tolist()))) for s, xs, ys in self._coords)
        return tuple((s, tuple([(p.x, p.y) for p in ring])) for s, ring in self._pieces)

    def hatch(self, spacing: float, angle_deg: float = 90.0) -> tuple[tuple[float, float, float, float], ...]:
        """Hatch lines clipped to the pieces by shapely: (x1, y1, x2, y2) segments, *spacing* apart.

        90 degrees is vertical hatching, as the books hatch the free forces.
        """
        from shapely.geometry import LineString, MultiLineString

        if not spacing > 0.0:
            raise DegenerateObject(f"hatch spacing must be positive, got {spacing!r}")
        out = []
        a = math.radians(angle_deg)
        ux, uy = math.cos(a), math.sin(a)
        nx, ny = -uy, ux
        for _, poly in self.signed_pieces():
            xmin, ymin, xmax, ymax = poly.bounds
            reach = math.hypot(xmax - xmin, ymax - ymin)
            cx, cy = 0.5 * (xmin + xmax), 0.5 * (ymin + ymax)
            # Lines at fixed offsets k * spacing from the origin, so pieces hatch in register.
            c = cx * nx + cy * ny
            k0, k1 = math.floor((c - reach) / spacing), math.ceil((c + reach) / spacing)
            for k in range(k0, k1 + 1):
                off = k * spacing - c
                mx, my = cx + off * nx, cy + off * ny
                seg = LineString([(mx - reach * ux, my - reach * uy), (mx + reach * ux, my + reach * uy)])
                cut = poly.intersection(seg)
                parts = cut.geoms if isinstance(cut, MultiLineString) else [cut]
                for part in parts:
                    if part.is_empty or part.geom_type != "LineString" or part.length <= 0.0:
                        continue
                    if poly.boundary.distance(part.interpolate(0.5, normalized=True)) <= 1e-9 * reach:
                        continue  # a hatch line along an edge is the edge itself, already drawn
                    (x1, y1), (x2, y2) = part.coords[0], part.coords[-1]
                    out.append((x1, y1, x2, y2))
        return tuple(out)

    def as_json(self) -> dict[str, Any]:
        d: dict[str, Any] = {"type": "area", "pieces": [{"sign": s, "points": [[p[0], p[1]] for p in ring]}
                                                        for s, ring in self.pieces]}
        if self.hatch_deg is not None:
            d["hatch_deg"] = self.hatch_deg
        return d


def graph_ordinate(curve: Any, x: float) -> float:
    """The ordinate of a graph (a Line that is not vertical, or a drawn curve) at abscissa *x*."""
    if isinstance(curve, Line):
        (px, py), (qx, qy) = curve
        if abs(qx - px) <= 1e-15 * max(1.0, abs(px), abs(qx)):
            raise GeometryError("a vertical line is not a graph over the x axis")
        return py + (x - px) * (qy - py) / (qx - px)
    return curve.y_at(x)


def _graph(curve: Any):
    """A graph as drawn: None for a line (evaluated exactly), else its vertices (x ascending) as arrays."""
    if isinstance(curve, Line):
        graph_ordinate(curve, 0.0)  # refuses a vertical line
        return None
    if curve.kind == "bezier":
        xs, ys = curve.sample(64)
    else:
        pts = curve.curve_points()
        xs, ys = np.array([p.x for p in pts]), np.array([p.y for p in pts])
    order = np.argsort(xs, kind="stable")
    return xs[order], ys[order]


def _ordinates(curve: Any, graph, xs):
    if graph is None:
        (px, py), (qx, qy) = curve
        return py + (xs - px) * (qy - py) / (qx - px)
    gx, gy = graph
    if xs[0] < gx[0] - 1e-12 * max(1.0, abs(gx[0])) or xs[-1] > gx[-1] + 1e-12 * max(1.0, abs(gx[-1])):
        raise GeometryError(f"abscissae {xs[0]:.6g}..{xs[-1]:.6g} reach outside the drawn curve "
                            f"({gx[0]:.6g}..{gx[-1]:.6g})")
    return np.interp(xs, gx, gy)


def area_between(upper: Any, lower: Any, x_from: float, x_to: float, hatch_deg: float | None = None) -> Area:
    """The region between two graphs from x_from to x_to, split where they cross.

    Both graphs are taken as drawn: polylines and lines exactly, French-curve
    (Bézier) segments as 64-piece polylines (their drawing error, ~1e-5 of a
    segment's sag, is far below the planimeter's).  Pieces where *upper* lies
    above *lower* have sign +1.
    """
    lo, hi = min(x_from, x_to), max(x_from, x_to)
    if not hi > lo:
        raise DegenerateObject(f"an area between curves needs two different abscissae, got {x_from!r} twice")
    gu, gl = _graph(upper), _graph(lower)
    inner = [g[0][(g[0] > lo) & (g[0] < hi)] for g in (gu, gl) if g is not None]
    xs = np.unique(np.concatenate([[lo, hi], *inner]))
    us, ls = _ordinates(upper, gu, xs), _ordinates(lower, gl, xs)
    # Both graphs are straight between consecutive breakpoints: crossings are exact there.  Where the
    # difference changes sign strictly, the crossing is inserted (on it upper = lower, difference 0).
    d = us - ls
    d0, d1 = d[:-1], d[1:]
    cross = np.flatnonzero(((d0 < 0.0) & (0.0 < d1)) | ((d1 < 0.0) & (0.0 < d0)))
    t = d0[cross] / (d0[cross] - d1[cross])
    xc = xs[cross] + t * (xs[cross + 1] - xs[cross])
    yc = us[cross] + t * (us[cross + 1] - us[cross])
    fx, fu, fl = (np.insert(v, cross + 1, c) for v, c in ((xs, xc), (us, yc), (ls, yc)))
    sign = np.sign(fu - fl)
    # A piece runs from one zero of the difference (a crossing, a touching, or the first row) to the
    # next (or the last row); it has the sign of the rows inside it.
    ends = np.unique(np.concatenate([[0], np.flatnonzero(sign == 0.0), [fx.size - 1]]))
    out = []
    for a, b in zip(ends[:-1].tolist(), ends[1:].tolist()):
        inside = sign[a:b + 1]
        s = inside[inside != 0.0]
        if not s.size:
            continue
        rx = np.concatenate([fx[a:b + 1], fx[a:b + 1][::-1]])
        ry = np.concatenate([fu[a:b + 1], fl[a:b + 1][::-1]])
        # Drop the doubled points where a run starts or ends on a crossing.
        keep = (rx != np.roll(rx, 1)) | (ry != np.roll(ry, 1))
        if keep.sum() >= 3:
            out.append((int(s[0]), rx[keep], ry[keep]))
    if not out:
        raise GeometryError("the two curves enclose no area between the given abscissae")
    return Area.from_coordinates(out, hatch_deg)


class Areas:
    """The regions between two graphs over a sweep: one :class:`Area` per set of givens.

    What a later step reads -- the planimeter's signed area -- is computed for
    every set at once (:func:`areas_between`); set *i*'s pieces, which only a
    drawing of that set needs, are made by :func:`area_between` when it is
    taken (``take(i)``), from that set's graphs.
    """

    __slots__ = ("_graphs", "hatch_deg", "_signed")
    kind = "area"

    def __init__(self, upper: Any, lower: Any, x_from: Any, x_to: Any, hatch_deg: float | None, signed: Any) -> None:
        object.__setattr__(self, "_graphs", (upper, lower, x_from, x_to))
        object.__setattr__(self, "hatch_deg", hatch_deg)
        object.__setattr__(self, "_signed", signed)

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("Areas is immutable")

    def __reduce__(self):
        return (Areas, (*self._graphs, self.hatch_deg, self._signed))

    def __len__(self) -> int:
        return len(self._signed)

    def __repr__(self) -> str:
        return f"Areas({len(self._signed)} sets, signed {np.min(self._signed):.6g}..{np.max(self._signed):.6g})"

    def signed_area(self) -> Any:
        """Positive pieces less negative ones, for every set: an array."""
        return self._signed

    def take(self, i: int) -> Area:
        upper, lower, x_from, x_to = (take(v, i) for v in self._graphs)
        return area_between(upper, lower, x_from, x_to, self.hatch_deg)

    def extent(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The box (x0, x1, y0, y1) of every set's pieces, arrays, without making them (a drawing of the sweep
        asks where the areas reach): from lo to hi, as high and as low as either graph at its vertices between
        them and at lo and hi (a crossing lies between those).

        >>> from construct.kernel.geometry import Point
        >>> a = Areas(Line(Point(0.0, 1.0), Point(1.0, 1.0)), Line(Point(0.0, 0.0), Point(1.0, 2.0)),
        ...           np.array([0.0, 0.0]), np.array([1.0, 0.5]), None, np.zeros(2))
        >>> [v.tolist() for v in a.extent()]
        [[0.0, 0.0], [1.0, 0.5], [0.0, 0.0], [2.0, 1.0]]
        """
        upper, lower, x_from, x_to = self._graphs
        n = len(self._signed)
        lo, hi = np.minimum(x_from, x_to) * np.ones(n), np.maximum(x_from, x_to) * np.ones(n)
        ys = []
        for curve in (upper, lower):
            graph = _graph_rows(curve, n)
            if graph is None:  # a line: straight from lo to hi
                (px, py), (qx, qy) = curve
                ys += [py + (lo - px) * (qy - py) / (qx - px), py + (hi - px) * (qy - py) / (qx - px)]
                continue
            gx, gy = graph
            inside = (gx > lo) & (gx < hi)
            ys += [_ordinate_rows(graph, lo), _ordinate_rows(graph, hi),
                   np.where(inside, gy, np.inf).min(axis=0), np.where(inside, gy, -np.inf).max(axis=0)]
        Y = np.vstack([y * np.ones(n) for y in ys])
        return lo, hi, Y.min(axis=0), Y.max(axis=0)


def _graph_rows(curve: Any, n: int) -> tuple[np.ndarray, np.ndarray] | None:
    """:func:`_graph` for every set of a sweep: the vertices (x ascending in each set), arrays (vertices, n)."""
    if isinstance(curve, Line):
        (px, py), (qx, qy) = curve
        vertical = np.abs(qx - px) <= 1e-15 * np.maximum(1.0, np.maximum(np.abs(px), np.abs(qx)))
        if np.any(vertical):
            raise GeometryError("a vertical line is not a graph over the x axis"
                                + sets_where(np.broadcast_to(vertical, (n,))))
        return None
    if curve.kind == "bezier":
        segs = curve.segments()
        ctrl = np.empty((len(segs), 4, 2, n))
        for k, seg in enumerate(segs):
            for j, p in enumerate(seg):
                ctrl[k, j, 0], ctrl[k, j, 1] = p.x, p.y
        t = np.arange(65)[:, None] / 64  # sample(64), set by set
        s = 1.0 - t
        weights = np.hstack([s ** 3, 3.0 * s * s * t, 3.0 * s * t * t, t ** 3])
        pts = np.einsum("tj,kjdn->ktdn", weights, ctrl)
        pts[:, 0], pts[:, -1] = ctrl[:, 0], ctrl[:, 3]
        flat = np.concatenate([pts[:, :-1].reshape(-1, 2, n), ctrl[-1:, 3]])
        xs, ys = flat[:, 0], flat[:, 1]
    else:
        pts = curve.curve_points()
        xs, ys = np.empty((len(pts), n)), np.empty((len(pts), n))
        for k, p in enumerate(pts):
            xs[k], ys[k] = p.x, p.y
    if np.all(xs[1:] >= xs[:-1]):  # as a graph's vertices mostly are: sorting would change nothing
        return xs, ys
    order = np.argsort(xs, axis=0, kind="stable")
    return np.take_along_axis(xs, order, 0), np.take_along_axis(ys, order, 0)


def _ordinate_rows(graph, x: np.ndarray) -> np.ndarray:
    """The graph's ordinate at *x* (one abscissa per set), as np.interp gives it from the sorted vertices."""
    gx, gy = graph
    j = np.clip((gx <= x).sum(axis=0) - 1, 0, gx.shape[0] - 2)[None]
    x0, x1 = np.take_along_axis(gx, j, 0)[0], np.take_along_axis(gx, j + 1, 0)[0]
    y0, y1 = np.take_along_axis(gy, j, 0)[0], np.take_along_axis(gy, j + 1, 0)[0]
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(x == x0, y0, np.where(x == x1, y1, (y1 - y0) / (x1 - x0) * (x - x0) + y0))


def _integral_rows(curve: Any, graph, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """The integral of a graph from lo to hi in every set: the trapezoids of its vertices, cut at lo and hi."""
    if graph is None:  # a line: exact
        (px, py), (qx, qy) = curve
        at_lo, at_hi = py + (lo - px) * (qy - py) / (qx - px), py + (hi - px) * (qy - py) / (qx - px)
        return (hi - lo) * (at_lo + at_hi) * 0.5
    gx, gy = graph
    at_lo, at_hi = _ordinate_rows(graph, lo), _ordinate_rows(graph, hi)
    # a vertex before lo counts as the point of the graph at lo, one after hi as the point at hi
    x = np.concatenate([lo[None], np.clip(gx, lo, hi), hi[None]])
    y = np.concatenate([at_lo[None], np.where(gx < lo, at_lo, np.where(gx > hi, at_hi, gy)), at_hi[None]])
    return (0.5 * (x[1:] - x[:-1]) * (y[1:] + y[:-1])).sum(axis=0)


def areas_between(upper: Any, lower: Any, x_from: Any, x_to: Any, hatch_deg: float | None, n: int) -> Areas:
    """:func:`area_between` for every set of a sweep of *n* sets: the signed areas at once, on arrays.

    Both graphs are straight between their (sampled) vertices, so the signed
    area -- the pieces above less those below -- is the integral of the upper
    graph less that of the lower one, each the trapezoids' sum of its own
    vertices.  The same refusals as area_between, naming the sets; where a
    set's signed area is exactly 0 (the curves may coincide) that set's area
    is made as area_between makes it, which refuses an area of nothing.
    """
    lo = np.minimum(x_from, x_to) * np.ones(n)
    hi = np.maximum(x_from, x_to) * np.ones(n)
    same = ~(hi > lo)
    if same.any():
        raise DegenerateObject("an area between curves needs two different abscissae" + sets_where(same))
    gu, gl = _graph_rows(upper, n), _graph_rows(lower, n)
    for g in (gu, gl):
        if g is not None:
            first, last = g[0][0], g[0][-1]
            out = ((lo < first - 1e-12 * np.maximum(1.0, np.abs(first)))
                   | (hi > last + 1e-12 * np.maximum(1.0, np.abs(last))))
            if out.any():
                i = int(np.flatnonzero(out)[0])
                raise GeometryError(f"abscissae {lo[i]:.6g}..{hi[i]:.6g} reach outside the drawn curve "
                                    f"({first[i]:.6g}..{last[i]:.6g}){sets_where(out)}")
    signed = _integral_rows(upper, gu, lo, hi) - _integral_rows(lower, gl, lo, hi)
    for i in np.flatnonzero(signed == 0.0):
        area_between(take(upper, i), take(lower, i), take(x_from, i), take(x_to, i))  # raises for no area at all
    return Areas(upper, lower, x_from, x_to, None if hatch_deg is None else float(hatch_deg), signed)


# --------------------------------------------------------------------------
# The operations (entries of the op table, construct.kernel.ops).
# --------------------------------------------------------------------------


def area_between_op(args, params, givens, refs, xp):
    """The region between two graphs, from the abscissa of one point to that of another."""
    upper, lower, a, b = args
    if xp is not SCALAR:
        return (areas_between(upper, lower, a.x, b.x, params.get("hatch_deg"), xp.n),)
    return (area_between(upper, lower, a.x, b.x, params.get("hatch_deg")),)


def planimeter_op(args, params, givens, refs, xp):
    """A planimeter run round the area: its signed area (drawing units squared)."""
    (area,) = args
    return (area.signed_area(),)


def planimeter_height_op(args, params, givens, refs, xp):
    """The planimeter's reading divided by the base ab: the height of the rectangle of equal area."""
    area, a, b = args
    base = xp.hypot(b.x - a.x, b.y - a.y)
    reading = area.signed_area()
    height = reading / base
    if xp is SCALAR:
        if not height > 0.0:
            raise GeometryError(f"the area's net reading {reading:.6g} gives no positive mean height")
    elif not np.all(height > 0.0):
        bad = ~(height > 0.0)
        raise GeometryError(f"the area's net reading {reading[bad][0]:.6g} gives no positive mean height"
                            f"{sets_where(bad)}")
    return (Length(height),)
