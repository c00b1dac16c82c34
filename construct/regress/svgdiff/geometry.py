"""Transforms and path data: SVG's local coordinates turned into absolute drawing units.

Part of :mod:`construct.regress.svgdiff`.
"""

from __future__ import annotations

import math
import re

from .values import NUMBER_RE, SvgFormatError, parse_numbers

# --------------------------------------------------------------------------- transforms

Matrix = tuple[float, float, float, float, float, float]
"""SVG's ``matrix(a b c d e f)``: x' = a x + c y + e, y' = b x + d y + f."""
Point = tuple[float, float]
IDENTITY: Matrix = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)


def multiply(m: Matrix, n: Matrix) -> Matrix:
    """``m`` after ``n``."""
    a, b, c, d, e, f = m
    A, B, C, D, E, F = n
    return (a * A + c * B, b * A + d * B, a * C + c * D, b * C + d * D, a * E + c * F + e, b * E + d * F + f)


def apply_matrix(m: Matrix, p: Point) -> Point:
    """The point *p* transformed by the SVG matrix *m* ``(a, b, c, d, e, f)``."""
    return (m[0] * p[0] + m[2] * p[1] + m[4], m[1] * p[0] + m[3] * p[1] + m[5])


def determinant(m: Matrix) -> float:
    """The determinant of the linear part of *m*: negative where the transform mirrors."""
    return m[0] * m[3] - m[1] * m[2]


def scale_factor(m: Matrix) -> float:
    """The factor by which *m* scales lengths on average (sqrt of |det|)."""
    return math.sqrt(abs(determinant(m)))


_TRANSFORM_RE = re.compile(r"\s*,?\s*(matrix|translate|scale|rotate|skewX|skewY)\s*\(([^()]*)\)\s*")


def parse_transform(text: str, where: str = "transform") -> Matrix:
    """The matrix of an SVG ``transform`` list, composed left to right.

    >>> parse_transform("translate(10) scale(2)")
    (2.0, 0.0, 0.0, 2.0, 10.0, 0.0)
    >>> [round(v, 12) for v in parse_transform("rotate(90, 1, 1)")]
    [0.0, 1.0, -1.0, 0.0, 2.0, 0.0]
    """
    m = IDENTITY
    pos, text = 0, text.strip()
    while pos < len(text):
        found = _TRANSFORM_RE.match(text, pos)
        if not found:
            raise SvgFormatError(f"{where}: bad transform {text!r} at position {pos}")
        name, args = found.group(1), parse_numbers(found.group(2), where)
        m = multiply(m, _one_transform(name, args, where))
        pos = found.end()
    return m


def _one_transform(name: str, v: list[float], where: str) -> Matrix:
    counts = {"matrix": (6,), "translate": (1, 2), "scale": (1, 2), "rotate": (1, 3), "skewX": (1,), "skewY": (1,)}
    if len(v) not in counts[name]:
        raise SvgFormatError(f"{where}: {name}() takes {' or '.join(map(str, counts[name]))} numbers, got {len(v)}")
    if name == "matrix":
        return (v[0], v[1], v[2], v[3], v[4], v[5])
    if name == "translate":
        return (1.0, 0.0, 0.0, 1.0, v[0], v[1] if len(v) > 1 else 0.0)
    if name == "scale":
        return (v[0], 0.0, 0.0, v[1] if len(v) > 1 else v[0], 0.0, 0.0)
    if name == "rotate":
        t = math.radians(v[0])
        r = (math.cos(t), math.sin(t), -math.sin(t), math.cos(t), 0.0, 0.0)
        if len(v) == 3:
            return multiply(multiply((1.0, 0.0, 0.0, 1.0, v[1], v[2]), r), (1.0, 0.0, 0.0, 1.0, -v[1], -v[2]))
        return r
    if name == "skewX":
        return (1.0, 0.0, math.tan(math.radians(v[0])), 1.0, 0.0, 0.0)
    return (1.0, math.tan(math.radians(v[0])), 0.0, 1.0, 0.0, 0.0)


def ellipse_axes(m: Matrix, rx: float, ry: float, phi_deg: float) -> tuple[float, float, float]:
    """Radii and axis angle (degrees, in [0, 180)) of an ellipse after the linear part of *m*.

    >>> (ellipse_axes((2.0, 0.0, 0.0, -3.0, 5.0, 7.0), 1.5, 1.0, 0.0),
    ...  ellipse_axes((0.0, 1.0, -1.0, 0.0, 0, 0), 2.0, 1.0, 0.0))
    ((3.0, 3.0, 0.0), (2.0, 1.0, 90.0))
    """
    if m[1] == 0.0 and m[2] == 0.0 and phi_deg == 0.0:
        # No rotation or skew (most drawings): the axes are the scaled radii, as the SVD finds them
        # bit for bit; one numpy call per circle was most of the time a large drawing took to read.
        sx, sy = abs(m[0] * rx), abs(m[3] * ry)
        if math.isfinite(sx) and math.isfinite(sy):
            return (sx, sy, 0.0) if sx >= sy else (sy, sx, 90.0)
    import numpy as np

    t = math.radians(phi_deg)
    shape = np.array([[m[0], m[2]], [m[1], m[3]]]) @ np.array(
        [[math.cos(t), -math.sin(t)], [math.sin(t), math.cos(t)]]) @ np.diag([rx, ry])
    u, s, _ = np.linalg.svd(shape)
    angle = math.degrees(math.atan2(u[1, 0], u[0, 0])) % 180.0
    return float(s[0]), float(s[1]), angle



# --------------------------------------------------------------------------- paths

_COMMANDS = set("MmZzLlHhVvCcSsQqTtAa")
#: What may stand between a path's numbers (``\s`` is what ``str.isspace`` calls a space).
_SEPARATORS = re.compile(r"[\s,]*")
_ARGS = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "T": 2, "A": 7, "Z": 0}


def parse_path(d: str, where: str) -> list[tuple]:
    """Path data in absolute, normalised segments (local coordinates).

    H and V become L, S and T become C and Q with their reflected control
    points, a zero-radius arc becomes L; arcs stay arcs.

    >>> parse_path("m1 1h2v2z", "p")
    [('M', (1.0, 1.0)), ('L', (1.0, 1.0), (3.0, 1.0)), ('L', (3.0, 1.0), (3.0, 3.0)), ('Z', (3.0, 3.0), (1.0, 1.0))]
    >>> parse_path("M0 0a1 1 0 1110 0", "p")[1]
    ('A', (0.0, 0.0), (10.0, 0.0), 1.0, 1.0, 0.0, True, True)
    """
    pos, n = 0, len(d)
    out: list[tuple] = []
    cur: Point = (0.0, 0.0)
    start: Point = (0.0, 0.0)
    last_c: Point | None = None  # second control point of the previous C/S
    last_q: Point | None = None  # control point of the previous Q/T
    cmd: str | None = None

    def skip() -> None:
        nonlocal pos
        pos = _SEPARATORS.match(d, pos).end()  # spaces (as str.isspace) and commas

    def number() -> float:
        nonlocal pos
        skip()
        m = NUMBER_RE.match(d, pos)
        if not m:
            raise SvgFormatError(f"{where}: bad path data at position {pos}: {d[pos:pos + 20]!r}")
        pos = m.end()
        return float(m.group())

    def flag() -> bool:
        nonlocal pos
        skip()
        if pos < n and d[pos] in "01":
            pos += 1
            return d[pos - 1] == "1"
        raise SvgFormatError(f"{where}: bad arc flag at position {pos}: {d[pos:pos + 20]!r}")

    skip()
    while True:
        skip()
        if pos >= n:
            break
        ch = d[pos]
        if ch in _COMMANDS:
            cmd = ch
            pos += 1
        elif cmd is None or cmd in "Zz":
            raise SvgFormatError(f"{where}: path data must start with a command, at position {pos}: {d[pos:pos + 20]!r}")
        elif cmd in "Mm":
            cmd = "L" if cmd == "M" else "l"
        rel = cmd.islower()
        up = cmd.upper()
        ox, oy = cur if rel else (0.0, 0.0)
        prev_c, prev_q = last_c, last_q
        last_c = last_q = None
        if up == "Z":
            out.append(("Z", cur, start))
            cur = start
            continue
        if up == "M":
            cur = start = (ox + number(), oy + number())
            out.append(("M", cur))
        elif up == "L":
            p = (ox + number(), oy + number())
            out.append(("L", cur, p))
            cur = p
        elif up == "H":
            p = (ox + number(), cur[1])
            out.append(("L", cur, p))
            cur = p
        elif up == "V":
            p = (cur[0], oy + number())
            out.append(("L", cur, p))
            cur = p
        elif up in "CS":
            if up == "C":
                c1 = (ox + number(), oy + number())
            else:
                c1 = (2 * cur[0] - prev_c[0], 2 * cur[1] - prev_c[1]) if prev_c else cur
            c2 = (ox + number(), oy + number())
            p = (ox + number(), oy + number())
            out.append(("C", cur, c1, c2, p))
            cur, last_c = p, c2
        elif up in "QT":
            if up == "Q":
                c = (ox + number(), oy + number())
            else:
                c = (2 * cur[0] - prev_q[0], 2 * cur[1] - prev_q[1]) if prev_q else cur
            p = (ox + number(), oy + number())
            out.append(("Q", cur, c, p))
            cur, last_q = p, c
        else:  # A
            rx, ry, phi = abs(number()), abs(number()), number()
            large, sweep = flag(), flag()
            p = (ox + number(), oy + number())
            if p == cur:
                pass  # the spec omits an arc to its own start
            elif rx == 0 or ry == 0:
                out.append(("L", cur, p))
            else:
                out.append(("A", cur, p, rx, ry, phi, large, sweep))
            cur = p
    return out


def arc_centre(p0: Point, p1: Point, rx: float, ry: float, phi_deg: float, large: bool, sweep: bool
                ) -> tuple[Point, float, float]:
    """Centre and (possibly enlarged) radii of an endpoint-parametrised arc (SVG 1.1, F.6.5)."""
    t = math.radians(phi_deg)
    c, s = math.cos(t), math.sin(t)
    dx, dy = (p0[0] - p1[0]) / 2, (p0[1] - p1[1]) / 2
    x1, y1 = c * dx + s * dy, -s * dx + c * dy
    lam = (x1 / rx) ** 2 + (y1 / ry) ** 2
    if lam > 1:
        rx, ry = rx * math.sqrt(lam), ry * math.sqrt(lam)
    num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1
    den = rx * rx * y1 * y1 + ry * ry * x1 * x1
    k = math.sqrt(max(0.0, num / den)) if den else 0.0
    if large == sweep:
        k = -k
    cx1, cy1 = k * rx * y1 / ry, -k * ry * x1 / rx
    centre = (c * cx1 - s * cy1 + (p0[0] + p1[0]) / 2, s * cx1 + c * cy1 + (p0[1] + p1[1]) / 2)
    return centre, rx, ry
