"""The drawn elements of a sheet as straight lines: numbers, transforms, outlines flattened, pieces for the index.

Lint reads any SVG a user hands it (:mod:`.sheet`); what it needs of an element's geometry is its outline as
polylines in the element's own coordinates (:func:`polylines`: arcs and Bézier curves flattened within
:data:`FLATNESS`), carried into the drawing's user units by the current transform (:func:`compose`,
:func:`transform_point`) and cut into pieces at most :data:`PIECE` long (:func:`cut_pieces`) for the spatial
index of :mod:`.checks`.

>>> import xml.etree.ElementTree as ET
>>> polylines("line", ET.fromstring('<line x1="0" y1="0" x2="60" y2="0"/>'), "demo")
[[(0.0, 0.0), (60.0, 0.0)]]
>>> len(cut_pieces([[(0.0, 0.0), (60.0, 0.0)]])), transform_point(compose(IDENTITY, (2, 0, 0, 2, 5, 0)), 1.0, 1.0)
(3, (7.0, 2.0))
>>> number("12px"), number(None, 3.0), four_numbers("0 0 100 50"), four_numbers("0 0 -1 5")
(12.0, 3.0, (0.0, 0.0, 100.0, 50.0), None)
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import numpy as np

from ..svgdiff.geometry import arc_centre, parse_path
from ..svgdiff.values import NUMBER

__all__ = ["Box", "Matrix", "IDENTITY", "PIECE", "FLATNESS", "local_name", "compose", "transform_point",
           "transform_lines", "number", "four_numbers", "box_of", "arc_points", "polylines", "cut_pieces"]

#: A box (x0, y0, x1, y1), y down.
Box = tuple[float, float, float, float]
#: An SVG transform (a, b, c, d, e, f).
Matrix = tuple[float, float, float, float, float, float]
IDENTITY: Matrix = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)
#: The longest straight piece a result line is cut into for the spatial index (user units).
PIECE = 24.0
#: How far a flattened arc or curve may stray from the true one (user units).
FLATNESS = 0.2


def local_name(tag) -> str:
    """An element's tag without its namespace (a comment's or a processing instruction's: "")."""
    if not isinstance(tag, str):
        return ""
    return tag.rsplit("}", 1)[-1]


def compose(m: Matrix, n: Matrix) -> Matrix:
    """The transform *m* then *n* applied inside it (as nested groups)."""
    a, b, c, d, e, f = m
    A, B, C, D, E, F = n
    return (a * A + c * B, b * A + d * B, a * C + c * D, b * C + d * D, a * E + c * F + e, b * E + d * F + f)


def transform_point(m: Matrix, x: float, y: float) -> tuple[float, float]:
    """The point (x, y) carried by *m*."""
    return (m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5])


def transform_lines(m: Matrix, lines: list[list[tuple[float, float]]]) -> list[list[tuple[float, float]]]:
    """Every point of *lines* carried by *m* (:func:`transform_point`'s sums in its order; a long line on arrays).

    >>> transform_lines((2.0, 0.0, 0.0, 2.0, 5.0, 0.0), [[(1.0, 1.0), (0.0, -1.0)]])
    [[(7.0, 2.0), (5.0, -2.0)]]
    """
    out = []
    for pts in lines:
        if len(pts) < _ARRAY_FROM:
            out.append([(m[0] * x + m[2] * y + m[4], m[1] * x + m[3] * y + m[5]) for x, y in pts])
        else:
            xy = np.array(pts, dtype=float)
            x, y = xy[:, 0], xy[:, 1]
            out.append(list(zip((m[0] * x + m[2] * y + m[4]).tolist(), (m[1] * x + m[3] * y + m[5]).tolist())))
    return out


#: From how many points a line is carried and cut on arrays (below, numpy's calls cost more than the loop).
_ARRAY_FROM = 24


def number(raw: str | None, default: float = 0.0) -> float:
    """The (first) number of an attribute; *default* when there is none."""
    if raw is None:
        return default
    try:
        v = float(raw)  # what our renderer writes: a plain number
        return v if math.isfinite(v) else default
    except ValueError:
        pass
    first = re.split(r"[\s,]+", raw.strip())[0] if raw.strip() else ""
    m = re.match(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", first)
    return float(m.group()) if m else default


def box_of(points) -> Box:
    """The box (x0, y0, x1, y1) round *points*."""
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    return (min(xs), min(ys), max(xs), max(ys))


def arc_points(c, r, a0, sweep) -> list[tuple[float, float]]:
    """A circle's arc about *c* of radius *r* from angle *a0* through *sweep* as a polyline within :data:`FLATNESS`."""
    step = 2 * math.acos(max(-1.0, 1 - FLATNESS / r)) if r > FLATNESS else math.pi / 2
    n = max(2, min(720, math.ceil(abs(sweep) / max(step, 1e-6))))
    return [(c[0] + r * math.cos(a0 + sweep * i / n), c[1] + r * math.sin(a0 + sweep * i / n)) for i in range(n + 1)]


def polylines(tag: str, e: ET.Element, where: str) -> list[list[tuple[float, float]]]:
    """The element's outline as polylines in its own coordinates (arcs and curves flattened)."""
    if tag == "line":
        return [[(number(e.get("x1")), number(e.get("y1"))), (number(e.get("x2")), number(e.get("y2")))]]
    if tag in ("circle", "ellipse"):
        cx, cy = number(e.get("cx")), number(e.get("cy"))
        rx = number(e.get("r") if tag == "circle" else e.get("rx"))
        ry = rx if tag == "circle" else number(e.get("ry"), rx)
        if rx <= 0 or ry <= 0:
            return [[(cx, cy)]]
        pts = arc_points((0.0, 0.0), max(rx, ry), 0.0, 2 * math.pi)
        return [[(cx + x * rx / max(rx, ry), cy + y * ry / max(rx, ry)) for x, y in pts]]
    if tag == "rect":
        x, y, w, h = number(e.get("x")), number(e.get("y")), number(e.get("width")), number(e.get("height"))
        return [[(x, y), (x + w, y), (x + w, y + h), (x, y + h), (x, y)]]
    if tag in ("polyline", "polygon"):
        v = [float(t) for t in re.findall(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?", e.get("points", ""))]
        pts = [(v[i], v[i + 1]) for i in range(0, len(v) - 1, 2)]
        if tag == "polygon" and pts:
            pts.append(pts[0])
        return [pts] if pts else []
    # a path
    d = e.get("d", "")
    plain = _plain_path(d)
    if plain is not None:
        return plain
    out: list[list[tuple[float, float]]] = []
    cur: list[tuple[float, float]] = []
    for seg in parse_path(d, where):
        op = seg[0]
        if op == "M":
            if len(cur) > 1:
                out.append(cur)
            cur = [seg[1]]
        elif op in ("L", "Z"):
            cur = cur or [seg[1]]
            cur.append(seg[2])
        elif op == "C":
            (ax, ay), (bx, by), (cx, cy), (dx, dy) = seg[1:]
            cur = cur or [seg[1]]
            # the sums in the order sum() adds them (0 + w0 p0 + w1 p1 + ...): the same numbers, without its calls
            cur += [(0 + w0 * ax + w1 * bx + w2 * cx + w3 * dx, 0 + w0 * ay + w1 * by + w2 * cy + w3 * dy)
                    for w0, w1, w2, w3 in _CUBIC]
        elif op == "Q":
            (ax, ay), (bx, by), (cx, cy) = seg[1:]
            cur = cur or [seg[1]]
            cur.extend((0 + w0 * ax + w1 * bx + w2 * cx, 0 + w0 * ay + w1 * by + w2 * cy) for w0, w1, w2 in _QUADRATIC)
        else:  # an arc
            _, p0, p1, rx, ry, phi, large, sweep = seg
            cur = cur or [p0]
            (cx, cy), rx, ry = arc_centre(p0, p1, rx, ry, phi, large, sweep)
            if abs(rx - ry) > 1e-9 * max(rx, 1.0) or phi % 180:
                cur.append(p1)  # an ellipse turned: its chord (our drawings have none)
                continue
            a0 = math.atan2(p0[1] - cy, p0[0] - cx)
            a1 = math.atan2(p1[1] - cy, p1[0] - cx)
            d = a1 - a0
            if sweep:  # positive angles (clockwise on the y-down sheet)
                d = d % (2 * math.pi) or 2 * math.pi
            else:
                d = -((-d) % (2 * math.pi) or 2 * math.pi)
            cur.extend(arc_points((cx, cy), rx, a0, d)[1:])
    if len(cur) > 1 or (cur and not out):
        out.append(cur)
    return out


#: The weights a cubic and a quadratic Bézier piece is flattened with (12 points each, the end included).
_CUBIC = tuple(((1 - i / 12) * (1 - i / 12) * (1 - i / 12), 3 * (1 - i / 12) * (1 - i / 12) * (i / 12),
                3 * (1 - i / 12) * (i / 12) * (i / 12), (i / 12) * (i / 12) * (i / 12)) for i in range(1, 13))
_QUADRATIC = tuple(((1 - i / 12) * (1 - i / 12), 2 * (1 - i / 12) * (i / 12), (i / 12) * (i / 12)) for i in range(1, 13))


#: A path's commands and numbers as parse_path reads them one after another (anything else: the third group).
_PATH_TOKEN = re.compile(rf"[\s,]*(?:([MLCZ])|({NUMBER})|(.))", re.S)


def _plain_path(d: str) -> list[list[tuple[float, float]]] | None:
    """:func:`polylines` of a plain path -- absolute moves, lines, cubic curves and closes only, as the renderer
    writes them -- read in one pass, the same numbers as through
    :func:`construct.regress.svgdiff.geometry.parse_path`; None for any other path (read through it)."""
    out: list[list[tuple[float, float]]] = []
    cur: list[tuple[float, float]] = []
    at = start = (0.0, 0.0)
    cmd = ""
    v: list[float] = []
    for letter, num, other in _PATH_TOKEN.findall(d):
        if other:
            return None
        if letter:
            if v or (not cmd and letter != "M"):
                return None  # numbers left over, or no move first: parse_path says what is wrong
            cmd = letter
            if letter == "Z":
                cur.append(start)
                at = start
            continue
        if cmd in ("", "Z"):
            return None
        v.append(0.0 + float(num))  # as parse_path adds the origin of absolute coordinates (-0 is 0)
        if cmd == "C":
            if len(v) < 6:
                continue
            ax, ay = at
            bx, by, cx, cy, dx, dy = v
            cur += [(0 + w0 * ax + w1 * bx + w2 * cx + w3 * dx, 0 + w0 * ay + w1 * by + w2 * cy + w3 * dy)
                    for w0, w1, w2, w3 in _CUBIC]
            at = (dx, dy)
        elif len(v) < 2:
            continue
        elif cmd == "M":
            if len(cur) > 1:
                out.append(cur)
            at = start = (v[0], v[1])
            cur = [at]
            cmd = "L"  # further pairs are lines
        else:
            at = (v[0], v[1])
            cur.append(at)
        v = []
    if v:
        return None
    if len(cur) > 1 or (cur and not out):
        out.append(cur)
    return out


def cut_pieces(lines: list[list[tuple[float, float]]]) -> list[tuple[float, float, float, float]]:
    """Straight pieces at most :data:`PIECE` long (so that each sits in a few cells of the index)."""
    out = []
    for pts in lines:
        if len(pts) >= _ARRAY_FROM:
            out.extend(_cut_array(pts))
            continue
        for (ax, ay), (bx, by) in zip(pts, pts[1:]):
            n = max(1, math.ceil(math.hypot(bx - ax, by - ay) / PIECE))
            for i in range(n):
                out.append((ax + (bx - ax) * i / n, ay + (by - ay) * i / n,
                            ax + (bx - ax) * (i + 1) / n, ay + (by - ay) * (i + 1) / n))
    return out


def four_numbers(text: str) -> tuple[float, float, float, float] | None:
    """A box x y w h written as four numbers (a viewBox, a view), or None when it is not one with w, h > 0."""
    try:
        v = [float(t) for t in re.split(r"[\s,]+", text.strip()) if t]
    except ValueError:
        return None
    if len(v) != 4 or not all(math.isfinite(x) for x in v) or v[2] <= 0 or v[3] <= 0:
        return None
    return (v[0], v[1], v[2], v[3])


def _cut_array(pts: list[tuple[float, float]]) -> list[tuple[float, float, float, float]]:
    """:func:`cut_pieces` of one long line on arrays: the same sums in the same order."""
    xy = np.array(pts, dtype=float)
    a, b = xy[:-1], xy[1:]
    span = np.hypot(b[:, 0] - a[:, 0], b[:, 1] - a[:, 1]) / PIECE
    n = np.maximum(1, np.ceil(span)).astype(np.int64)
    # numpy's hypot may differ from math.hypot in the last place: where that could move a count, math's
    near = np.nonzero(np.abs(span - np.rint(span)) <= 1e-9 * np.maximum(1.0, span))[0]
    for k in near.tolist():
        n[k] = max(1, math.ceil(math.hypot(b[k, 0] - a[k, 0], b[k, 1] - a[k, 1]) / PIECE))
    seg = np.repeat(np.arange(len(a)), n)
    i = (np.arange(len(seg)) - np.repeat(np.cumsum(n) - n, n)).astype(float)
    m = n[seg].astype(float)
    ax, ay, d_x, d_y = a[seg, 0], a[seg, 1], (b[:, 0] - a[:, 0])[seg], (b[:, 1] - a[:, 1])[seg]
    return list(zip((ax + d_x * i / m).tolist(), (ay + d_y * i / m).tolist(),
                    (ax + d_x * (i + 1) / m).tolist(), (ay + d_y * (i + 1) / m).tolist()))
