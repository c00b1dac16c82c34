"""Lines broken for the letters they pass: the engraver's gap on a plate.

A book plate never runs a line through a letter: the letter stands beside
its line (the placer looks for such a spot first, :func:`construct.render.lettering.place`),
or, where there is none -- a numeral on its tick, a value written on its
ordinate, the sign of a hatched zone -- the line stops short of the letter
and goes on beyond it.  A :class:`Gap` is the white a letter keeps round its
ink (a box, turned with a turned letter); the functions here give the parts
of a segment, a polyline, an arc or a smooth curve that lie outside every
gap, as the ``d`` of one path (canvas pixels, y down).

>>> g = Gap.around((10.0, -5.0, 14.0, 5.0))
>>> segment_parts((0.0, 0.0), (30.0, 0.0), [g])
[(0.0, 0.3333333333333333), (0.4666666666666667, 1.0)]
>>> polyline_d([(0.0, 0.0), (30.0, 0.0)], [g])
'M0 0L10 0M14 0L30 0'
"""

from __future__ import annotations

import math
import re
from typing import NamedTuple, Sequence

from .paths import arc_path, bezier_controls
from .marks import Mark, MarkKind
from .svgdoc import fmt
from .viewport import Viewport

__all__ = ["Gap", "GapFactory", "segment_parts", "polyline_d", "arc_parts", "curve_d", "gapped_mark", "gapped_hatch",
           "CLEARANCE"]

XY = tuple[float, float]

#: The white a gap leaves round a letter's ink, in letter sizes (an em): about a letter stroke's width.
CLEARANCE = 0.15
#: Pieces shorter than this (pixels) left between two gaps are not drawn: a speck, not a line.
SPECK = 0.6
#: Curves are walked in steps of about this many pixels to find where they enter a gap (then bisected).
STEP = 0.5


class Gap(NamedTuple):
    """A box on the canvas a line may not cross: centre (cx, cy), unit axis (ux, uy) along its width, half
    width and half height."""

    cx: float
    cy: float
    ux: float
    uy: float
    hw: float
    hh: float

    @classmethod
    def around(cls, box: tuple[float, float, float, float], grow: float = 0.0, angle: float = 0.0,
               about: XY | None = None) -> "Gap":
        """The gap round *box* (x0, y0, x1, y1) grown by *grow*, turned *angle* degrees counter-clockwise
        (as the sheet shows it) about *about* (default its centre)."""
        x0, y0, x1, y1 = box
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        a = math.radians(-angle)  # y down: counter-clockwise on the sheet is a negative angle
        ux, uy = math.cos(a), math.sin(a)
        if about is not None and angle:
            ox, oy = about
            dx, dy = cx - ox, cy - oy
            cx, cy = ox + dx * ux - dy * uy, oy + dx * uy + dy * ux
        return cls(cx, cy, ux, uy, (x1 - x0) / 2 + grow, (y1 - y0) / 2 + grow)

    def local(self, x: float, y: float) -> XY:
        """(x, y) in the gap's own frame (along, across) from its centre."""
        dx, dy = x - self.cx, y - self.cy
        return (dx * self.ux + dy * self.uy, -dx * self.uy + dy * self.ux)

    def holds(self, x: float, y: float) -> bool:
        a, b = self.local(x, y)
        return abs(a) < self.hw and abs(b) < self.hh

    def reach(self) -> tuple[float, float, float, float]:
        """The upright box the gap covers."""
        rx = abs(self.ux) * self.hw + abs(self.uy) * self.hh
        ry = abs(self.uy) * self.hw + abs(self.ux) * self.hh
        return (self.cx - rx, self.cy - ry, self.cx + rx, self.cy + ry)


def _near(gaps: Sequence[Gap], box: tuple[float, float, float, float]) -> list[Gap]:
    out = []
    for g in gaps:
        r = g.reach()
        if r[0] <= box[2] and box[0] <= r[2] and r[1] <= box[3] and box[1] <= r[3]:
            out.append(g)
    return out


def _minus(parts: list[tuple[float, float]], cut: tuple[float, float]) -> list[tuple[float, float]]:
    a, b = cut
    out = []
    for s, e in parts:
        if b <= s or a >= e:
            out.append((s, e))
            continue
        if a > s:
            out.append((s, a))
        if b < e:
            out.append((b, e))
    return out


def segment_parts(a: XY, b: XY, gaps: Sequence[Gap]) -> list[tuple[float, float]]:
    """The parameter intervals (0..1 from *a* to *b*) of the segment outside every gap."""
    parts = [(0.0, 1.0)]
    box = (min(a[0], b[0]), min(a[1], b[1]), max(a[0], b[0]), max(a[1], b[1]))
    for g in _near(gaps, box):
        (ax, ay), (bx, by) = g.local(*a), g.local(*b)
        dx, dy = bx - ax, by - ay
        t0, t1 = 0.0, 1.0
        for p, q in ((-dx, ax + g.hw), (dx, g.hw - ax), (-dy, ay + g.hh), (dy, g.hh - ay)):
            if p == 0:
                if q < 0:
                    t0, t1 = 1.0, 0.0
                    break
            else:
                t = q / p
                if p < 0:
                    t0 = max(t0, t)
                else:
                    t1 = min(t1, t)
        if t0 < t1:
            parts = _minus(parts, (t0, t1))
    return parts


def polyline_d(pts: Sequence[XY], gaps: Sequence[Gap], closed: bool = False) -> str:
    """The path of a polyline (closed: back to its first point) with a gap wherever it crosses one."""
    pts = list(pts) + ([pts[0]] if closed and pts else [])
    runs: list[list[XY]] = []
    for a, b in zip(pts, pts[1:]):
        length = math.hypot(b[0] - a[0], b[1] - a[1])
        for t0, t1 in segment_parts(a, b, gaps):
            if (t1 - t0) * length < SPECK and not (t0 == 0.0 and t1 == 1.0):
                continue
            p = (a[0] + t0 * (b[0] - a[0]), a[1] + t0 * (b[1] - a[1]))
            q = (a[0] + t1 * (b[0] - a[0]), a[1] + t1 * (b[1] - a[1]))
            if runs and t0 == 0.0 and runs[-1][-1] == a:
                runs[-1].append(q)
            else:
                runs.append([p, q])
    return "".join("M" + "L".join(f"{fmt(x)} {fmt(y)}" for x, y in run) for run in runs)


def _runs_outside(at, n: int, gaps: Sequence[Gap]) -> list[tuple[float, float]]:
    """The intervals of 0..1 where the curve *at* (t -> (x, y)), walked in *n* steps, is outside every gap;
    each entry and exit bisected to a thousandth of a step."""
    def inside(t: float) -> bool:
        x, y = at(t)
        return any(g.holds(x, y) for g in gaps)

    def edge(lo: float, hi: float, lo_in: bool) -> float:
        for _ in range(12):
            mid = (lo + hi) / 2
            if inside(mid) == lo_in:
                lo = mid
            else:
                hi = mid
        return (lo + hi) / 2

    ts = [i / n for i in range(n + 1)]
    states = [inside(t) for t in ts]
    if not any(states):
        return [(0.0, 1.0)]
    out: list[tuple[float, float]] = []
    start = None if states[0] else 0.0
    for i in range(1, n + 1):
        if states[i] != states[i - 1]:
            t = edge(ts[i - 1], ts[i], states[i - 1])
            if states[i]:  # leaves the outside
                if start is not None:
                    out.append((start, t))
                start = None
            else:
                start = t
    if start is not None:
        out.append((start, 1.0))
    return out


def arc_parts(centre: XY, r: float, start: float, sweep: float, gaps: Sequence[Gap]) -> list[tuple[float, float]] | None:
    """The pieces (start, sweep) of the arc about *centre* (canvas pixels, angles as the caller measures them:
    the point at angle a is centre + r (cos a, sin a)) outside every gap; None when no gap meets it."""
    cx, cy = centre
    near = _near(gaps, (cx - r, cy - r, cx + r, cy + r))
    near = [g for g in near if _ring_meets(centre, r, g)]
    if not near:
        return None
    n = max(8, math.ceil(abs(sweep) * r / STEP))
    runs = _runs_outside(lambda t: (cx + r * math.cos(start + t * sweep), cy + r * math.sin(start + t * sweep)), n, near)
    if runs == [(0.0, 1.0)]:
        return None
    return [(start + t0 * sweep, (t1 - t0) * sweep) for t0, t1 in runs if abs(t1 - t0) * abs(sweep) * r >= SPECK]


def _ring_meets(c: XY, r: float, g: Gap) -> bool:
    """Could the circle about *c* of radius *r* pass through the gap (its reach)?"""
    x0, y0, x1, y1 = g.reach()
    near = math.hypot(max(x0 - c[0], 0.0, c[0] - x1), max(y0 - c[1], 0.0, c[1] - y1))
    far = max(math.hypot(x - c[0], y - c[1]) for x in (x0, x1) for y in (y0, y1))
    return near <= r <= far


def _cubic(q, t: float) -> XY:
    s = 1 - t
    return tuple(s * s * s * a + 3 * s * s * t * b + 3 * s * t * t * c + t * t * t * d for a, b, c, d in zip(*q))


def _split(q, t0: float, t1: float):
    """The part t0..t1 of the cubic *q* (de Casteljau twice)."""
    def left(q, t):
        (a, b, c, d) = q
        ab = _lerp(a, b, t); bc = _lerp(b, c, t); cd = _lerp(c, d, t)
        abc = _lerp(ab, bc, t); bcd = _lerp(bc, cd, t)
        return (a, ab, abc, _lerp(abc, bcd, t)), (_lerp(abc, bcd, t), bcd, cd, d)

    _, right = left(q, t0)
    if t1 >= 1.0:
        return right
    piece, _ = left(right, (t1 - t0) / (1 - t0) if t0 < 1 else 1.0)
    return piece


def _lerp(a: XY, b: XY, t: float) -> XY:
    return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t)


def curve_d(P: Sequence[XY], gaps: Sequence[Gap]) -> str | None:
    """The path of the smooth curve through *P* (pixels) broken at every gap it crosses; None when none does."""
    if len(P) < 2:
        return None
    xs, ys = [p[0] for p in P], [p[1] for p in P]
    near = _near(gaps, (min(xs) - 20, min(ys) - 20, max(xs) + 20, max(ys) + 20))
    if not near:
        return None
    pieces: list[tuple[XY, XY, XY, XY]] = []
    cut = False
    for q in bezier_controls(P):
        qx, qy = [p[0] for p in q], [p[1] for p in q]
        mine = _near(near, (min(qx), min(qy), max(qx), max(qy)))
        if not mine:
            pieces.append(q)
            continue
        length = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(q, q[1:]))
        runs = _runs_outside(lambda t: _cubic(q, t), max(4, math.ceil(length / STEP)), mine)
        if runs == [(0.0, 1.0)]:
            pieces.append(q)
            continue
        cut = True
        pieces.extend(_split(q, t0, t1) for t0, t1 in runs if (t1 - t0) * length >= SPECK)
    if not cut:
        return None
    d, last = [], None
    for a, b, c, e in pieces:
        if last is None or math.hypot(a[0] - last[0], a[1] - last[1]) > 1e-9:
            d.append(f"M{fmt(a[0])} {fmt(a[1])}")
        d.append(f"C{fmt(b[0])} {fmt(b[1])} {fmt(c[0])} {fmt(c[1])} {fmt(e[0])} {fmt(e[1])}")
        last = e
    return "".join(d)


class GapFactory:
    """An SVG element factory (svgwrite's) whose straight lines and open polylines of class ``fur`` (a plate's
    furniture: ticks, dimension and extension lines, angle arcs, scales) come out broken at *gaps*; the
    rest (arrowheads, dots, lettering) as the factory makes them."""

    def __init__(self, factory, gaps: Sequence[Gap]):
        self._f = factory
        self._gaps = list(gaps)

    def __getattr__(self, name: str):
        return getattr(self._f, name)

    def line(self, start, end, class_: str = "", **kw):
        if class_.split()[:1] == ["fur"]:
            ends = [(float(start[0]), float(start[1])), (float(end[0]), float(end[1]))]
            d = polyline_d(ends, self._gaps)
            if d != polyline_d(ends, ()):
                return self._f.path(d=d, class_=class_, **kw)
        return self._f.line(start=start, end=end, class_=class_, **kw)

    def path(self, d: str = "", class_: str = "", **kw):
        if class_.split()[:1] == ["fur"] and d.startswith("M") and set(d) <= set("MLZ0123456789.- "):
            closed = d.endswith("Z")
            pts = [tuple(float(v) for v in p.split()) for p in d.rstrip("Z")[1:].split("L")]
            got = polyline_d(pts, self._gaps, closed)
            if got != polyline_d(pts, (), closed):
                d = got
        return self._f.path(d=d, class_=class_, **kw)


def gapped_mark(m: Mark, vp: Viewport, gaps: Sequence[Gap]) -> str | None:
    """The path of the line *m* drawn through *vp*, broken where it crosses *gaps* (None: it crosses none, or it
    is not drawn at all)."""
    g = m.geom
    if m.look == "hidden":
        return None
    if m.kind is MarkKind.SEGMENT or m.straight:
        pts = [vp.px(g[0], g[1]), vp.px(g[2], g[3])] if m.kind is MarkKind.SEGMENT else [vp.px(*q) for q in g]
        d = polyline_d(pts, gaps)
        return d if d != polyline_d(pts, ()) else None
    if m.kind.round:
        start, sweep = (0.0, 2 * math.pi) if m.kind is MarkKind.CIRCLE else (g[3], g[4])
        # on the canvas (y down) the arc's angles turn the other way
        parts = arc_parts(vp.px(g[0], g[1]), g[2] * vp.scale, -start, -sweep, gaps)
        if parts is None:
            return None
        return "".join(arc_path(vp, g[0], g[1], g[2], -a, -s) for a, s in parts)
    return curve_d([vp.px(*q) for q in g], gaps)


def gapped_hatch(d: str, gaps: Sequence[Gap]) -> str:
    """Hatching (a path of straight pieces, ``M x y L x y ...``, as :func:`construct.render.paths.hatch_path`
    writes it) broken where it crosses *gaps*."""
    runs: list[list[XY]] = []
    for op, x, y in re.findall(r"([ML])\s*([-\d.e]+)[\s,]+([-\d.e]+)", d):
        if op == "M" or not runs:
            runs.append([])
        runs[-1].append((float(x), float(y)))
    return "".join(polyline_d(run, gaps) for run in runs)
