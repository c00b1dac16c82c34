"""Semantic diff of two SVG drawings: what moved, resized, restyled, appeared or vanished.

Both drawings are parsed into geometry in absolute drawing units (every
``transform`` of the ancestors applied, ``<use>`` expanded, styles inherited
and normalised), then compared element by element.  Formatting is not
geometry: attribute order, whitespace, ``1.50`` against ``1.5``, ``#000``
against ``black`` and a ``style`` property against a presentation attribute
are all equal.

>>> a = '<svg xmlns="http://www.w3.org/2000/svg"><circle id="P" cx="1.50" cy="2" r="1" fill="#000"/></svg>'
>>> b = '<svg xmlns="http://www.w3.org/2000/svg"><circle r="1" style="fill: black" cy="2" cx="1.5" id="P"/></svg>'
>>> diff_svg(a, b).equal
True
>>> moved = b.replace('cx="1.5"', 'cx="1.51"')
>>> print(diff_svg(a, moved).report())
SVG diff <string> -> <string> (tolerance 1e-06): 1 change
  moved      P (circle, matched by id): by 0.01: centre (1.5, 2) -> (1.51, 2)

Each drawn element gets a stable key: its ``id``, else its tag and its
document-order index among the elements of that tag without an id
(``circle[0]``).  Elements are matched by id, then anonymous ones by an
order-preserving alignment of equal elements, then by key, and what is left
by kind and nearest geometry (a renamed element is "renamed", not
missing + extra).  Every change says how its element was matched.
"""

from __future__ import annotations

import difflib
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterator, Sequence

from ..kernel.errors import ConstructError, InvalidParameter

__all__ = ["DEFAULT_TOLERANCE", "SvgChange", "SvgDiff", "SvgFormatError", "diff_svg", "parse_svg",
           "changes_by_step"]

DEFAULT_TOLERANCE = 1e-6
"""Drawing units; our goldens are written with far more digits than this."""

SVG_NS = "http://www.w3.org/2000/svg"
XLINK_NS = "http://www.w3.org/1999/xlink"


class SvgFormatError(ConstructError, ValueError):
    """An input is not a readable SVG drawing (not XML, no <svg> root, malformed geometry)."""


# --------------------------------------------------------------------------- numbers

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_NUMBER_RE = re.compile(_NUMBER)
# A number inside free text (animation values, CSS): not glued to a word or a '#'.
_FREE_NUMBER_RE = re.compile(r"(?<![\w#.])" + _NUMBER)
_UNITS = {"": 1.0, "px": 1.0, "mm": 96 / 25.4, "cm": 96 / 2.54, "in": 96.0, "pt": 96 / 72, "pc": 16.0,
          "em": 16.0, "ex": 8.0}  # em/ex: the initial font size, 16 px; good enough for a diff
_LENGTH_RE = re.compile(r"\s*(" + _NUMBER + r")\s*(px|mm|cm|in|pt|pc|em|ex|%)?\s*", re.I)


def _fmt(x: float) -> str:
    """Fixed formatting for reports: up to 10 significant digits, no ``-0``.

    >>> _fmt(0.010000000000000009), _fmt(-0.0), _fmt(123.0)
    ('0.01', '0', '123')
    """
    s = format(x, ".10g")
    return "0" if s in ("-0", "0") else s


def _mag(x: float) -> str:
    return format(x, ".3g")


def _numbers(text: str, where: str) -> list[float]:
    """The numbers of a list like ``"1,2 3e1 -4"``; anything else is bad input."""
    if re.sub(r"[\s,]", "", _NUMBER_RE.sub(" ", text)):
        raise SvgFormatError(f"{where}: not a list of numbers: {text!r}")
    return [float(t) for t in _NUMBER_RE.findall(text)]


def _tokens(text: str) -> tuple[Any, ...]:
    """Free text as words and numbers, so ``1.50s`` equals ``1.5s`` and ``0;1`` equals ``0; 1``.

    Separators stay in the words (one space, none around punctuation), so
    ``"".join`` of the shown tokens reads like the source.

    >>> _tokens(" 0;  1.50 ; 2e1s ")
    (0.0, ';', 1.5, ';', 20.0, 's')
    >>> _show(_tokens("translate(1.50, 2)  scale(2)"))
    'translate(1.5,2) scale(2)'
    """
    out: list[Any] = []
    pos = 0
    text = " ".join(text.split())

    def word(w: str) -> None:
        w = re.sub(r"\s*([;,:=])\s*", r"\1", w)
        w = re.sub(r"\(\s+", "(", re.sub(r"\s+\)", ")", w))
        if w:
            out.append(w)

    for m in _FREE_NUMBER_RE.finditer(text):
        word(text[pos:m.start()])
        out.append(float(m.group()))
        pos = m.end()
    word(text[pos:])
    if out and isinstance(out[0], str):
        out[0] = out[0].lstrip() or out[0]
    if out and isinstance(out[-1], str):
        out[-1] = out[-1].rstrip() or out[-1]
    return tuple(w for w in out if w != "")


def _close(x: Any, y: Any, tol: float) -> bool:
    """Are two nested values equal, numbers within *tol*?"""
    if isinstance(x, float) and isinstance(y, float):
        return abs(x - y) <= tol or x == y
    if isinstance(x, tuple) and isinstance(y, tuple):
        return len(x) == len(y) and all(_close(p, q, tol) for p, q in zip(x, y))
    return x == y


def _show(value: Any) -> str:
    """A normalised value as text.

    >>> _show((0.0, 0.0, 960.0, 813.91)), _show(("xMidYMid", "meet")), _show((1.5, "s"))
    ('0 0 960 813.91', 'xMidYMid meet', '1.5s')
    """
    if isinstance(value, float):
        return _fmt(value)
    if isinstance(value, tuple):
        # Words from _tokens carry their own separators; two numbers or two
        # plain words in a row (a viewBox, a split list) need a space.
        out = ""
        for i, v in enumerate(value):
            if i and isinstance(v, str) == isinstance(value[i - 1], str):
                out += " "
            out += _show(v)
        return out
    return str(value)


def _num_diff(x: Any, y: Any) -> float | None:
    """Largest numeric difference between two values of the same shape, else None."""
    if isinstance(x, float) and isinstance(y, float):
        return abs(x - y)
    if isinstance(x, tuple) and isinstance(y, tuple) and len(x) == len(y):
        ds = [_num_diff(p, q) for p, q in zip(x, y)]
        if all(d is not None for d in ds) and ds:
            return max(ds)  # type: ignore[type-var]
        if all(d is not None or p == q for d, p, q in zip(ds, x, y)):
            known = [d for d in ds if d is not None]
            return max(known) if known else None
    return None


# --------------------------------------------------------------------------- transforms

Matrix = tuple[float, float, float, float, float, float]
"""SVG's ``matrix(a b c d e f)``: x' = a x + c y + e, y' = b x + d y + f."""
Point = tuple[float, float]
IDENTITY: Matrix = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)


def _mul(m: Matrix, n: Matrix) -> Matrix:
    """``m`` after ``n``."""
    a, b, c, d, e, f = m
    A, B, C, D, E, F = n
    return (a * A + c * B, b * A + d * B, a * C + c * D, b * C + d * D, a * E + c * F + e, b * E + d * F + f)


def _apply(m: Matrix, p: Point) -> Point:
    return (m[0] * p[0] + m[2] * p[1] + m[4], m[1] * p[0] + m[3] * p[1] + m[5])


def _det(m: Matrix) -> float:
    return m[0] * m[3] - m[1] * m[2]


def _scale(m: Matrix) -> float:
    """The factor by which *m* scales lengths on average (sqrt of |det|)."""
    return math.sqrt(abs(_det(m)))


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
        name, args = found.group(1), _numbers(found.group(2), where)
        m = _mul(m, _one_transform(name, args, where))
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
            return _mul(_mul((1.0, 0.0, 0.0, 1.0, v[1], v[2]), r), (1.0, 0.0, 0.0, 1.0, -v[1], -v[2]))
        return r
    if name == "skewX":
        return (1.0, 0.0, math.tan(math.radians(v[0])), 1.0, 0.0, 0.0)
    return (1.0, math.tan(math.radians(v[0])), 0.0, 1.0, 0.0, 0.0)


def _ellipse_axes(m: Matrix, rx: float, ry: float, phi_deg: float) -> tuple[float, float, float]:
    """Radii and axis angle (degrees, in [0, 180)) of an ellipse after the linear part of *m*."""
    import numpy as np

    t = math.radians(phi_deg)
    shape = np.array([[m[0], m[2]], [m[1], m[3]]]) @ np.array(
        [[math.cos(t), -math.sin(t)], [math.sin(t), math.cos(t)]]) @ np.diag([rx, ry])
    u, s, _ = np.linalg.svd(shape)
    angle = math.degrees(math.atan2(u[1, 0], u[0, 0])) % 180.0
    return float(s[0]), float(s[1]), angle


# --------------------------------------------------------------------------- colours and styles

_BASIC_COLOURS = {
    "black": "#000000", "silver": "#c0c0c0", "gray": "#808080", "grey": "#808080", "white": "#ffffff",
    "maroon": "#800000", "red": "#ff0000", "purple": "#800080", "fuchsia": "#ff00ff", "magenta": "#ff00ff",
    "green": "#008000", "lime": "#00ff00", "olive": "#808000", "yellow": "#ffff00", "navy": "#000080",
    "blue": "#0000ff", "teal": "#008080", "aqua": "#00ffff", "cyan": "#00ffff", "orange": "#ffa500",
}
_COLOUR_PROPERTIES = {"fill", "stroke", "color", "stop-color", "flood-color", "lighting-color"}


def normalise_colour(raw: str, current: str = "#000000") -> str:
    """One spelling per colour: ``#rrggbb`` (``#rrggbbaa`` when not opaque), ``none`` or the text.

    >>> {normalise_colour(c) for c in ("#000", "#000000", "black", "rgb(0,0,0)", "rgb(0%, 0%, 0%)", "hsl(0, 0%, 0%)")}
    {'#000000'}
    >>> normalise_colour("rgba(255, 0, 0, 0.5)"), normalise_colour("URL(#Grad)")
    ('#ff000080', 'url(#Grad)')
    """
    s = raw.strip()
    low = s.lower()
    if low in ("none", "transparent"):
        return "none"
    if low == "currentcolor":
        return current
    if re.fullmatch(r"#[0-9a-f]{3,4}", low):
        return _rgba_hex(*(int(ch * 2, 16) for ch in low[1:]))
    if re.fullmatch(r"#[0-9a-f]{6}([0-9a-f]{2})?", low):
        return _rgba_hex(*(int(low[i:i + 2], 16) for i in range(1, len(low), 2)))
    func = re.fullmatch(r"(rgba?|hsla?)\((.*)\)", low)
    if func:
        parts = [p for p in re.split(r"[\s,/]+", func.group(2).strip()) if p]
        try:
            return _functional_colour(func.group(1), parts)
        except (ValueError, IndexError):
            return low
    if low in _BASIC_COLOURS:
        return _BASIC_COLOURS[low]
    if re.fullmatch(r"[a-z]+", low):
        from matplotlib.colors import CSS4_COLORS  # the full CSS table, only when needed

        if low in CSS4_COLORS:
            return CSS4_COLORS[low].lower()
        return low
    # url(#id) references keep their case: ids are case-sensitive.
    return re.sub(r"^url", "url", s, flags=re.I)


def _rgba_hex(r: int, g: int, b: int, a: int = 255) -> str:
    return f"#{r:02x}{g:02x}{b:02x}" + ("" if a == 255 else f"{a:02x}")


def _functional_colour(name: str, parts: list[str]) -> str:
    def channel(p: str, full: float) -> float:
        return float(p[:-1]) / 100 * full if p.endswith("%") else float(p)

    alpha = channel(parts[3], 1.0) if len(parts) > 3 else 1.0
    if name.startswith("rgb"):
        rgb = [channel(p, 255.0) for p in parts[:3]]
    else:
        h = float(parts[0].removesuffix("deg")) / 360 % 1.0
        s, lum = channel(parts[1], 1.0), channel(parts[2], 1.0)
        import colorsys

        rgb = [255 * v for v in colorsys.hls_to_rgb(h, lum, s)]
    clamp = [min(255, max(0, round(v))) for v in rgb]
    return _rgba_hex(*clamp, min(255, max(0, round(alpha * 255))))


# Presentation attributes that may stand on an element instead of in `style`.
_PRESENTATION = {
    "alignment-baseline", "baseline-shift", "clip", "clip-path", "clip-rule", "color", "color-interpolation",
    "color-interpolation-filters", "color-rendering", "cursor", "direction", "display", "dominant-baseline",
    "fill", "fill-opacity", "fill-rule", "filter", "flood-color", "flood-opacity", "font", "font-family",
    "font-size", "font-size-adjust", "font-stretch", "font-style", "font-variant", "font-weight",
    "image-rendering", "letter-spacing", "lighting-color", "marker", "marker-end", "marker-mid", "marker-start",
    "mask", "opacity", "overflow", "paint-order", "pointer-events", "shape-rendering", "stop-color",
    "stop-opacity", "stroke", "stroke-dasharray", "stroke-dashoffset", "stroke-linecap", "stroke-linejoin",
    "stroke-miterlimit", "stroke-opacity", "stroke-width", "text-anchor", "text-decoration", "text-rendering",
    "unicode-bidi", "vector-effect", "visibility", "word-spacing", "writing-mode",
}
# Not inherited by the children of a group, but still acting on them: combined instead.
_GROUP_EFFECTS = {"opacity", "display", "clip-path", "mask", "filter", "overflow", "clip"}
_INITIAL = {
    "fill": "#000000", "fill-opacity": (1.0,), "fill-rule": ("nonzero",), "stroke": "none", "stroke-width": (1.0,),
    "stroke-opacity": (1.0,), "stroke-linecap": ("butt",), "stroke-linejoin": ("miter",),
    "stroke-miterlimit": (4.0,), "stroke-dasharray": ("none",), "stroke-dashoffset": (0.0,),
    "opacity": (1.0,), "display": ("inline",), "visibility": ("visible",), "font-style": ("normal",),
    "font-weight": (400.0,), "text-anchor": ("start",), "font-size": (16.0,), "color": "#000000",
    "clip-path": ("none",), "mask": ("none",), "filter": ("none",), "marker-start": ("none",),
    "marker-mid": ("none",), "marker-end": ("none",), "vector-effect": ("none",),
}
# Lengths in the element's user units: a scaled element draws them scaled.
_SCALED = {"stroke-width", "stroke-dasharray", "stroke-dashoffset", "font-size", "letter-spacing", "word-spacing"}


def _declarations(text: str) -> dict[str, str]:
    """``"a: b; c: d"`` as a dict (later wins; ``!important`` dropped)."""
    out: dict[str, str] = {}
    for decl in re.sub(r"/\*.*?\*/", "", text, flags=re.S).split(";"):
        if ":" in decl:
            name, value = decl.split(":", 1)
            value = re.sub(r"\s*!important\s*$", "", value.strip(), flags=re.I)
            if name.strip() and value:
                out[name.strip().lower()] = value
    return out


def _style_value(prop: str, raw: str, current: str) -> Any:
    """A property value in one spelling: a colour string or a tuple of words and numbers."""
    if prop in _COLOUR_PROPERTIES:
        return normalise_colour(raw, current)
    s = raw.strip()
    if prop == "font-family":
        return ", ".join(f.strip().strip("'\"").strip().lower() for f in s.split(","))
    if prop == "font-weight":
        s = {"normal": "400", "bold": "700"}.get(s.lower(), s)
    words: list[Any] = []
    for part in re.split(r"[\s,]+", s):
        if not part:
            continue
        if words:
            words.append(" ")
        m = re.fullmatch(r"(" + _NUMBER + r")(px|mm|cm|in|pt|pc|em|ex|%)?", part, flags=re.I)
        if m:
            unit = (m.group(2) or "").lower()
            value = float(m.group(1))
            words.extend([value * _UNITS[unit]] if unit != "%" else [value, "%"])
        else:
            words.append(part if part.lower().startswith("url(") else part.lower())
    return tuple(words)


@dataclass(frozen=True, slots=True)
class _CssRule:
    tag: str | None
    ids: tuple[str, ...]
    classes: tuple[str, ...]
    specificity: tuple[int, int, int, int]
    declarations: tuple[tuple[str, str], ...]

    def matches(self, tag: str, elem_id: str | None, classes: set[str]) -> bool:
        return ((self.tag is None or self.tag == tag) and all(i == elem_id for i in self.ids)
                and all(c in classes for c in self.classes))


def _parse_css(text: str, order_start: int = 0) -> tuple[list[_CssRule], list[tuple[str, tuple]]]:
    """Rules with simple selectors (``tag``, ``.class``, ``#id``, ``*`` and compounds) and a canonical form.

    Selectors with combinators or pseudo-classes are not applied, but they are
    part of the canonical form, so a change to them is still reported.
    """
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"@[^{;]*(;|\{[^{}]*(\{[^{}]*\}[^{}]*)*\})", "", text)  # @import, @media, @font-face
    rules: list[_CssRule] = []
    canon: list[tuple[str, tuple]] = []
    for n, block in enumerate(re.finditer(r"([^{}]+)\{([^{}]*)\}", text)):
        decls = _declarations(block.group(2))
        for sel in block.group(1).split(","):
            sel = " ".join(sel.split())
            canon.append((sel, tuple(sorted((k, _style_value(k, v, "currentcolor")) for k, v in decls.items()))))
            m = re.fullmatch(r"(\*|[A-Za-z][\w-]*)?((?:[.#][\w-]+)*)", sel)
            if not m or not sel:
                continue
            ids = tuple(re.findall(r"#([\w-]+)", m.group(2)))
            classes = tuple(re.findall(r"\.([\w-]+)", m.group(2)))
            tag = None if m.group(1) in (None, "*") else m.group(1)
            spec = (len(ids), len(classes), 0 if tag is None else 1, order_start + n)
            rules.append(_CssRule(tag, ids, classes, spec, tuple(decls.items())))
    rules.sort(key=lambda r: r.specificity)
    canon.sort()
    return rules, canon


# --------------------------------------------------------------------------- paths

_COMMANDS = set("MmZzLlHhVvCcSsQqTtAa")
_ARGS = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "T": 2, "A": 7, "Z": 0}


def _parse_path(d: str, where: str) -> list[tuple]:
    """Path data in absolute, normalised segments (local coordinates).

    H and V become L, S and T become C and Q with their reflected control
    points, a zero-radius arc becomes L; arcs stay arcs.

    >>> _parse_path("m1 1h2v2z", "p")
    [('M', (1.0, 1.0)), ('L', (1.0, 1.0), (3.0, 1.0)), ('L', (3.0, 1.0), (3.0, 3.0)), ('Z', (3.0, 3.0), (1.0, 1.0))]
    >>> _parse_path("M0 0a1 1 0 1110 0", "p")[1]
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
        while pos < n and (d[pos].isspace() or d[pos] == ","):
            pos += 1

    def number() -> float:
        nonlocal pos
        skip()
        m = _NUMBER_RE.match(d, pos)
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


def _arc_centre(p0: Point, p1: Point, rx: float, ry: float, phi_deg: float, large: bool, sweep: bool
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


# --------------------------------------------------------------------------- drawn elements

@dataclass(frozen=True, slots=True)
class Shape:
    """One drawn element as geometry in absolute drawing units, with its effective style."""

    key: str
    tag: str
    kind: str
    points: tuple[tuple[str, Point], ...] = ()
    sizes: tuple[tuple[str, float], ...] = ()
    angles: tuple[tuple[str, float], ...] = ()
    structure: tuple[tuple[str, Any], ...] = ()
    text: str | None = None
    style: tuple[tuple[str, Any], ...] = ()
    animations: tuple[Any, ...] = ()
    described: tuple[tuple[str, str], ...] = ()
    has_id: bool = False
    order: int = 0
    #: The step whose group (``<g data-step="k">``, a layered figure) holds the element, else None.
    step: int | None = None

    def fingerprint(self, tol: float) -> tuple:
        """Hashable, tolerance-rounded form used to align equal anonymous elements."""
        q = max(tol, 1e-12)

        def r(v: Any) -> Any:
            if isinstance(v, float):
                return round(v / q)
            if isinstance(v, tuple):
                return tuple(r(x) for x in v)
            return v

        return (self.tag, self.kind, r(self.points), r(self.sizes), r(self.angles), self.structure, self.text,
                r(self.style), r(self.animations), self.described)


@dataclass(frozen=True, slots=True)
class Drawing:
    """A parsed SVG: document-level properties, definitions and drawn shapes in document order."""

    document: tuple[tuple[str, Any], ...]
    definitions: tuple[tuple[str, Any], ...]
    shapes: tuple[Shape, ...]


_NOT_DRAWN = {"defs", "symbol", "marker", "clipPath", "mask", "pattern", "linearGradient", "radialGradient",
              "filter", "style", "script", "metadata", "title", "desc", "foreignObject", "font", "font-face",
              "cursor", "view"}
_ANIMATIONS = {"animate", "set", "animateTransform", "animateMotion", "animateColor", "discard"}
_CONTAINERS = {"g", "a", "switch", "svg"}


def _local(tag: Any) -> tuple[str | None, str]:
    if not isinstance(tag, str):
        return None, ""  # comments, processing instructions
    if tag.startswith("{"):
        ns, _, name = tag[1:].partition("}")
        return ns, name
    return None, tag


def _is_svg(elem: ET.Element) -> bool:
    ns, _ = _local(elem.tag)
    return ns in (None, SVG_NS)


def _attrs(elem: ET.Element) -> dict[str, str]:
    """Attributes by local name: SVG's own and ``xlink:href``; other namespaces (editors') dropped."""
    out: dict[str, str] = {}
    for name, value in elem.attrib.items():
        ns, local = _local(name)
        if ns is None or (ns == XLINK_NS and local == "href"):
            if (local == "href" and ns is None) or local not in out:  # plain href wins over xlink:href
                out[local] = value
    return out


def _canon(elem: ET.Element) -> tuple:
    """A definition (gradient, marker, symbol, ...) as nested tuples, numbers parsed."""
    attrs = tuple(sorted((k, _tokens(v)) for k, v in _attrs(elem).items()))
    children = tuple(_canon(c) for c in elem if _is_svg(c) and _local(c.tag)[1])
    text = " ".join((elem.text or "").split())
    return (_local(elem.tag)[1], attrs, _tokens(text) if text else (), children)


def _plain_text(elem: ET.Element) -> str:
    return " ".join("".join(elem.itertext()).split())


def _text_content(elem: ET.Element) -> str:
    """Character data of a text element and its tspans, whitespace as xml:space="default" renders it."""
    parts = [elem.text or ""]
    for child in elem:
        name = _local(child.tag)[1]
        if _is_svg(child) and name in ("tspan", "textPath", "a", "tref"):
            parts.append(_text_content(child))
        parts.append(child.tail or "")
    return "".join(parts)


@dataclass(slots=True)
class _State:
    ctm: Matrix
    style: dict[str, str]
    viewport: tuple[float, float]
    step: int | None = None  # from the nearest ancestor with data-step


class _Parser:
    """Walks one SVG tree and collects its shapes."""

    def __init__(self, root: ET.Element, name: str):
        self.root = root
        self.name = name
        self.ids: dict[str, ET.Element] = {}
        for e in root.iter():
            i = _attrs(e).get("id") if _is_svg(e) else None
            if i is not None and i not in self.ids:
                self.ids[i] = e
        self.rules: list[_CssRule] = []
        self.stylesheet: list[tuple[str, tuple]] = []
        for e in root.iter():
            if _is_svg(e) and _local(e.tag)[1] == "style":
                rules, canon = _parse_css("".join(e.itertext()), len(self.rules))
                self.rules.extend(rules)
                self.stylesheet.extend(canon)
        self.rules.sort(key=lambda r: r.specificity)
        self.shapes: list[Shape] = []
        self.used_keys: set[str] = set()

    # -- document ---------------------------------------------------------------------------

    def drawing(self) -> Drawing:
        attrs = _attrs(self.root)
        doc: list[tuple[str, Any]] = []
        vb = attrs.get("viewBox")
        viewbox = tuple(_numbers(vb, f"{self.name}: viewBox")) if vb else None
        if viewbox is not None and len(viewbox) != 4:
            raise SvgFormatError(f"{self.name}: viewBox needs 4 numbers, got {vb!r}")
        for prop in ("width", "height"):
            if prop in attrs:
                doc.append((prop, _style_value(prop, attrs[prop], "")))
        if viewbox is not None:
            doc.append(("viewBox", viewbox))
        if "preserveAspectRatio" in attrs:
            doc.append(("preserveAspectRatio", tuple(attrs["preserveAspectRatio"].split())))
        for child in self.root:
            if _is_svg(child) and _local(child.tag)[1] in ("title", "desc"):
                doc.append((_local(child.tag)[1], _plain_text(child)))
        if self.stylesheet:
            doc.append(("stylesheet", tuple(self.stylesheet)))
        vw = viewbox[2] if viewbox else self._length(attrs.get("width"), 100.0, "width")
        vh = viewbox[3] if viewbox else self._length(attrs.get("height"), 100.0, "height")
        state = _State(IDENTITY, {}, (vw, vh))
        self._walk_children(self.root, self._own_state(self.root, state, "svg"), "", {}, 0)
        return Drawing(tuple(doc), tuple(self._definitions()), tuple(self.shapes))

    def _definitions(self) -> list[tuple[str, Any]]:
        out: list[tuple[str, Any]] = []
        counters: dict[str, int] = {}

        def visit(elem: ET.Element, in_defs: bool) -> None:
            for child in elem:
                if not _is_svg(child):
                    continue
                name = _local(child.tag)[1]
                if name == "defs":
                    visit(child, True)
                elif in_defs or name in _NOT_DRAWN - {"title", "desc", "style", "metadata", "script"}:
                    i = _attrs(child).get("id")
                    if i is None:
                        i = f"{name}[{counters.get(name, 0)}]"
                        counters[name] = counters.get(name, 0) + 1
                    out.append((i, _canon(child)))
                elif name not in _NOT_DRAWN:
                    visit(child, False)

        visit(self.root, False)
        return sorted(out, key=lambda kv: kv[0])

    def _length(self, raw: str | None, ref: float, where: str) -> float:
        if raw is None:
            return ref
        m = _LENGTH_RE.fullmatch(raw)
        if not m:
            raise SvgFormatError(f"{self.name}: {where}: not a length: {raw!r}")
        value, unit = float(m.group(1)), (m.group(2) or "").lower()
        return value / 100 * ref if unit == "%" else value * _UNITS[unit]

    # -- styles -----------------------------------------------------------------------------

    def _own_style(self, elem: ET.Element, tag: str) -> dict[str, str]:
        attrs = _attrs(elem)
        own = {k: v for k, v in attrs.items() if k in _PRESENTATION}
        classes = set(attrs.get("class", "").split())
        for rule in self.rules:
            if rule.matches(tag, attrs.get("id"), classes):
                own.update(rule.declarations)
        own.update(_declarations(attrs.get("style", "")))
        return own

    def _own_state(self, elem: ET.Element, parent: _State, tag: str, extra: Matrix = IDENTITY) -> _State:
        attrs = _attrs(elem)
        ctm = parent.ctm
        if "transform" in attrs:
            ctm = _mul(ctm, parse_transform(attrs["transform"], f"{self.name}: <{tag}> transform"))
        ctm = _mul(ctm, extra)
        style = dict(parent.style)
        for prop, value in self._own_style(elem, tag).items():
            if value.strip().lower() == "inherit":
                continue
            if prop in _GROUP_EFFECTS and prop in style:
                style[prop] = self._combine(prop, style[prop], value)
            else:
                style[prop] = value
        step = parent.step
        if "data-step" in attrs:
            try:
                step = int(attrs["data-step"])
            except ValueError:
                raise SvgFormatError(f"{self.name}: <{tag}> data-step is not a step number: "
                                     f"{attrs['data-step']!r}") from None
        return _State(ctm, style, parent.viewport, step)

    @staticmethod
    def _combine(prop: str, outer: str, inner: str) -> str:
        if prop == "opacity":
            try:
                return _fmt(float(outer) * float(inner))
            except ValueError:
                return f"{outer} {inner}"
        if prop == "display":
            return "none" if "none" in (outer.strip(), inner.strip()) else inner
        if outer.strip().lower() == "none":
            return inner
        if inner.strip().lower() == "none":
            return outer
        return f"{outer} {inner}"

    def _effective_style(self, state: _State) -> tuple[tuple[str, Any], ...]:
        raw = state.style
        colour = normalise_colour(raw["color"]) if "color" in raw else "#000000"
        scale = _scale(state.ctm)
        non_scaling = raw.get("vector-effect", "").strip() == "non-scaling-stroke"
        out: list[tuple[str, Any]] = []
        for prop in sorted(raw):
            value = _style_value(prop, raw[prop], colour)
            if prop in _SCALED and scale != 1.0 and not (non_scaling and prop.startswith("stroke")):
                value = tuple(v * scale if isinstance(v, float) else v for v in value)
            if _INITIAL.get(prop) == value:
                continue
            out.append((prop, value))
        return tuple(out)

    # -- walking ----------------------------------------------------------------------------

    def _key(self, elem: ET.Element, tag: str, prefix: str, counters: dict[str, int]) -> tuple[str, bool]:
        i = _attrs(elem).get("id")
        if i is not None:
            key, has_id = prefix + i, True
        else:
            n = counters.get(tag, 0)
            counters[tag] = n + 1
            key, has_id = f"{prefix}{tag}[{n}]", False
        base, k = key, 2
        while key in self.used_keys:  # duplicate ids are invalid but exist
            key, k = f"{base}~{k}", k + 1
        self.used_keys.add(key)
        return key, has_id

    def _walk_children(self, elem: ET.Element, state: _State, prefix: str, counters: dict[str, int],
                       depth: int) -> None:
        for child in elem:
            if _is_svg(child):
                self._walk(child, state, prefix, counters, depth)

    def _walk(self, elem: ET.Element, parent: _State, prefix: str, counters: dict[str, int], depth: int) -> None:
        tag = _local(elem.tag)[1]
        if not tag or tag in _NOT_DRAWN or tag in _ANIMATIONS:
            return
        if depth > 64:
            raise SvgFormatError(f"{self.name}: <use> nesting deeper than 64 (a reference cycle?)")
        attrs = _attrs(elem)
        if tag == "svg":  # a nested viewport
            vp = self._nested_viewport(attrs, parent)
            state = self._own_state(elem, parent, tag, vp)
            key, has_id = self._key(elem, tag, prefix, counters)
            self._group_record(elem, key, has_id, tag, state)
            self._walk_children(elem, state, prefix, counters, depth)
            return
        state = self._own_state(elem, parent, tag)
        if tag in _CONTAINERS:
            key, has_id = self._key(elem, tag, prefix, counters)
            self._group_record(elem, key, has_id, tag, state)
            self._walk_children(elem, state, prefix, counters, depth)
            return
        if tag == "use":
            self._use(elem, attrs, state, prefix, counters, depth)
            return
        builder = getattr(self, f"_shape_{tag}", None)
        if builder is None:
            return  # an element that draws nothing we model (tspan outside text, unknown tags)
        key, has_id = self._key(elem, tag, prefix, counters)
        geometry = builder(elem, attrs, state, f"{self.name}: <{tag} {key}>")
        self._add(elem, key, has_id, tag, state, geometry)

    def _nested_viewport(self, attrs: dict[str, str], parent: _State) -> Matrix:
        x = self._length(attrs.get("x"), parent.viewport[0], "x") if "x" in attrs else 0.0
        y = self._length(attrs.get("y"), parent.viewport[1], "y") if "y" in attrs else 0.0
        m: Matrix = (1.0, 0.0, 0.0, 1.0, x, y)
        if "viewBox" in attrs:
            vb = _numbers(attrs["viewBox"], f"{self.name}: viewBox")
            if len(vb) == 4 and vb[2] > 0 and vb[3] > 0:
                w = self._length(attrs.get("width"), parent.viewport[0], "width") if "width" in attrs else parent.viewport[0]
                h = self._length(attrs.get("height"), parent.viewport[1], "height") if "height" in attrs else parent.viewport[1]
                sx, sy = w / vb[2], h / vb[3]
                par = attrs.get("preserveAspectRatio", "xMidYMid meet").split()
                if par and par[0] != "none":
                    s = max(sx, sy) if "slice" in par else min(sx, sy)
                    align = par[0]
                    tx = {"xMin": 0.0, "xMid": 0.5, "xMax": 1.0}.get(align[:4], 0.5) * (w - s * vb[2])
                    ty = {"YMin": 0.0, "YMid": 0.5, "YMax": 1.0}.get(align[4:], 0.5) * (h - s * vb[3])
                    sx = sy = s
                else:
                    tx = ty = 0.0
                m = _mul(m, (sx, 0.0, 0.0, sy, tx - sx * vb[0], ty - sy * vb[1]))
        return m

    def _use(self, elem: ET.Element, attrs: dict[str, str], state: _State, prefix: str,
             counters: dict[str, int], depth: int) -> None:
        key, has_id = self._key(elem, "use", prefix, counters)
        href = attrs.get("href", "")
        target = self.ids.get(href[1:]) if href.startswith("#") else None
        if target is None:
            # A dangling reference draws nothing; keep it visible to the diff.
            self._add(elem, key, has_id, "use", state, {"kind": "use", "structure": (("href", href),)})
            return
        x = self._length(attrs.get("x"), state.viewport[0], "x") if "x" in attrs else 0.0
        y = self._length(attrs.get("y"), state.viewport[1], "y") if "y" in attrs else 0.0
        inner = _State(_mul(state.ctm, (1.0, 0.0, 0.0, 1.0, x, y)), state.style, state.viewport, state.step)
        ttag = _local(target.tag)[1]
        if ttag in ("symbol", "svg"):
            sym_attrs = dict(_attrs(target))
            for k in ("width", "height"):
                if k in attrs:
                    sym_attrs[k] = attrs[k]
            sym_attrs.pop("x", None), sym_attrs.pop("y", None)
            sym = self._own_state(target, inner, ttag, self._nested_viewport(sym_attrs, inner))
            self._group_record(elem, key, has_id, "use", state)
            self._walk_children(target, sym, key + "/", {}, depth + 1)
        elif ttag in _CONTAINERS:
            self._group_record(elem, key, has_id, "use", state)
            self._walk(target, inner, key + "/", {}, depth + 1)
        else:
            builder = getattr(self, f"_shape_{ttag}", None)
            if builder is None:
                return
            tstate = self._own_state(target, inner, ttag)
            geometry = builder(target, _attrs(target), tstate, f"{self.name}: <use {key}> -> <{ttag}>")
            self._add(elem, key, has_id, f"use>{ttag}", tstate, geometry, extra_source=target)

    def _decorations(self, elem: ET.Element) -> tuple[tuple[Any, ...], tuple[tuple[str, str], ...]]:
        animations, described = [], []
        for child in elem:
            if not _is_svg(child):
                continue
            name = _local(child.tag)[1]
            if name in _ANIMATIONS:
                animations.append((name, tuple(sorted((k, _tokens(v)) for k, v in _attrs(child).items()))))
            elif name in ("title", "desc"):
                described.append((name, _plain_text(child)))
        return tuple(sorted(animations, key=_show)), tuple(described)

    def _group_record(self, elem: ET.Element, key: str, has_id: bool, tag: str, state: _State) -> None:
        """A group is recorded only for what it carries itself: animations, title, desc."""
        animations, described = self._decorations(elem)
        if animations or described:
            self.shapes.append(Shape(key=key, tag=tag, kind="group", animations=animations, described=described,
                                     has_id=has_id, order=len(self.shapes), step=state.step))

    def _add(self, elem: ET.Element, key: str, has_id: bool, tag: str, state: _State, geometry: dict[str, Any],
             extra_source: ET.Element | None = None) -> None:
        animations, described = self._decorations(elem)
        if extra_source is not None:
            more_a, more_d = self._decorations(extra_source)
            animations, described = tuple(sorted(animations + more_a, key=_show)), described + more_d
        style = self._effective_style(state)
        classes = " ".join(sorted(set(_attrs(elem).get("class", "").split())))
        if classes:  # our renderer writes the instrument and provenance as classes
            style = tuple(sorted(style + (("class", classes),)))
        self.shapes.append(Shape(key=key, tag=tag, style=style, animations=animations,
                                 described=described, has_id=has_id, order=len(self.shapes), step=state.step,
                                 **geometry))

    # -- geometry of each element kind ---------------------------------------------------------

    def _coord(self, attrs: dict[str, str], name: str, state: _State, where: str, axis: int = 0,
               default: float = 0.0) -> float:
        raw = attrs.get(name)
        if raw is None or not raw.strip() or raw.strip() == "auto":
            return default
        if axis == 2:
            ref = math.hypot(*state.viewport) / math.sqrt(2)
        else:
            ref = state.viewport[axis]
        return self._length(raw, ref, f"{where} {name}")

    def _shape_line(self, elem, attrs, state, where):
        p1 = (self._coord(attrs, "x1", state, where), self._coord(attrs, "y1", state, where, 1))
        p2 = (self._coord(attrs, "x2", state, where), self._coord(attrs, "y2", state, where, 1))
        a, b = _apply(state.ctm, p1), _apply(state.ctm, p2)
        return {"kind": "segment", "points": (("start", a), ("end", b)),
                "sizes": (("length", math.dist(a, b)),)}

    def _shape_circle(self, elem, attrs, state, where):
        c = (self._coord(attrs, "cx", state, where), self._coord(attrs, "cy", state, where, 1))
        r = self._coord(attrs, "r", state, where, 2)
        return self._ellipse(c, r, r, state, circle=True)

    def _shape_ellipse(self, elem, attrs, state, where):
        c = (self._coord(attrs, "cx", state, where), self._coord(attrs, "cy", state, where, 1))
        rx = self._coord(attrs, "rx", state, where, 0, default=math.nan)
        ry = self._coord(attrs, "ry", state, where, 1, default=math.nan)
        rx, ry = (ry if math.isnan(rx) else rx), (rx if math.isnan(ry) else ry)
        rx, ry = (0.0 if math.isnan(rx) else rx), (0.0 if math.isnan(ry) else ry)
        return self._ellipse(c, rx, ry, state, circle=False)

    def _ellipse(self, c: Point, rx: float, ry: float, state: _State, circle: bool) -> dict[str, Any]:
        centre = _apply(state.ctm, c)
        ax, ay, angle = _ellipse_axes(state.ctm, rx, ry, 0.0)
        if circle and abs(ax - ay) <= 1e-9 * max(ax, 1.0):
            return {"kind": "circle", "points": (("centre", centre),), "sizes": (("radius", (ax + ay) / 2),)}
        if abs(ax - ay) <= 1e-9 * max(ax, 1.0):
            angle = 0.0  # a circle has no axis direction
        return {"kind": "ellipse", "points": (("centre", centre),), "sizes": (("rx", ax), ("ry", ay)),
                "angles": (("axis", angle),)}

    def _shape_rect(self, elem, attrs, state, where):
        x, y = self._coord(attrs, "x", state, where), self._coord(attrs, "y", state, where, 1)
        w, h = self._coord(attrs, "width", state, where), self._coord(attrs, "height", state, where, 1)
        rx = self._coord(attrs, "rx", state, where, 0, default=math.nan)
        ry = self._coord(attrs, "ry", state, where, 1, default=math.nan)
        rx, ry = (ry if math.isnan(rx) else rx), (rx if math.isnan(ry) else ry)
        rx, ry = min(0.0 if math.isnan(rx) else rx, w / 2), min(0.0 if math.isnan(ry) else ry, h / 2)
        corners = [_apply(state.ctm, p) for p in ((x, y), (x + w, y), (x + w, y + h), (x, y + h))]
        s = _scale(state.ctm)
        return {"kind": "rect", "points": tuple((f"corner {i + 1}", p) for i, p in enumerate(corners)),
                "sizes": (("width", math.dist(corners[0], corners[1])), ("height", math.dist(corners[1], corners[2])),
                          ("corner rx", rx * s), ("corner ry", ry * s))}

    def _poly(self, attrs, state, where, kind):
        values = _numbers(attrs.get("points", ""), f"{where} points")
        if len(values) % 2:
            values = values[:-1]  # the spec draws up to the odd number
        pts = [_apply(state.ctm, (values[i], values[i + 1])) for i in range(0, len(values), 2)]
        return {"kind": kind, "points": tuple((f"point {i + 1}", p) for i, p in enumerate(pts)),
                "structure": (("points", len(pts)),)}

    def _shape_polyline(self, elem, attrs, state, where):
        return self._poly(attrs, state, where, "polyline")

    def _shape_polygon(self, elem, attrs, state, where):
        return self._poly(attrs, state, where, "polygon")

    def _shape_path(self, elem, attrs, state, where):
        segments = _parse_path(attrs.get("d", ""), where)
        m = state.ctm
        flip = _det(m) < 0
        points: list[tuple[str, Point]] = []
        sizes: list[tuple[str, float]] = []
        angles: list[tuple[str, float]] = []
        commands: list[str] = []
        for i, seg in enumerate(segments, 1):
            op = seg[0]
            label = f"segment {i} ({op})"
            if op == "M":
                points.append((f"{label} point", _apply(m, seg[1])))
                commands.append("M")
            elif op == "L":
                points.append((f"{label} end", _apply(m, seg[2])))
                commands.append("L")
            elif op == "C":
                points += [(f"{label} control 1", _apply(m, seg[2])), (f"{label} control 2", _apply(m, seg[3])),
                           (f"{label} end", _apply(m, seg[4]))]
                commands.append("C")
            elif op == "Q":
                points += [(f"{label} control", _apply(m, seg[2])), (f"{label} end", _apply(m, seg[3]))]
                commands.append("Q")
            elif op == "Z":
                commands.append("Z")
            else:
                _, p0, p1, rx, ry, phi, large, sweep = seg
                centre, rx, ry = _arc_centre(p0, p1, rx, ry, phi, large, sweep)
                ax, ay, angle = _ellipse_axes(m, rx, ry, phi)
                if abs(ax - ay) <= 1e-9 * max(ax, 1.0):
                    angle = 0.0
                points += [(f"{label} centre", _apply(m, centre)), (f"{label} end", _apply(m, p1))]
                sizes += [(f"{label} rx", ax), (f"{label} ry", ay)]
                angles.append((f"{label} axis", angle))
                commands.append(f"A{int(large)}{int(sweep != flip)}")
        return {"kind": "path", "points": tuple(points), "sizes": tuple(sizes), "angles": tuple(angles),
                "structure": (("commands", " ".join(commands)),)}

    def _shape_text(self, elem, attrs, state, where):
        def first(name: str, axis: int) -> float:
            raw = attrs.get(name, "").strip()
            if not raw:
                return 0.0
            return self._length(re.split(r"[\s,]+", raw)[0], state.viewport[axis], f"{where} {name}")

        anchor = (first("x", 0) + first("dx", 0), first("y", 1) + first("dy", 1))
        points = [("anchor", _apply(state.ctm, anchor))]
        n = 0
        for child in elem.iter():
            if child is not elem and _is_svg(child) and _local(child.tag)[1] == "tspan":
                n += 1
                ca = _attrs(child)
                if "x" in ca or "y" in ca:
                    cx = self._length(re.split(r"[\s,]+", ca["x"].strip())[0], state.viewport[0], where) if "x" in ca else anchor[0]
                    cy = self._length(re.split(r"[\s,]+", ca["y"].strip())[0], state.viewport[1], where) if "y" in ca else anchor[1]
                    points.append((f"tspan {n} anchor", _apply(state.ctm, (cx, cy))))
        angle = math.degrees(math.atan2(state.ctm[1], state.ctm[0]))
        text = " ".join(_text_content(elem).replace("\n", " ").replace("\t", " ").split())
        return {"kind": "text", "points": tuple(points), "angles": (("baseline", angle),), "text": text}

    def _shape_image(self, elem, attrs, state, where):
        geometry = self._shape_rect(elem, attrs, state, where)
        geometry["kind"] = "image"
        geometry["sizes"] = geometry["sizes"][:2]
        href = attrs.get("href", "")
        geometry["structure"] = (("href", href if len(href) <= 80 else f"{href[:60]}... ({len(href)} chars)"),)
        return geometry


# --------------------------------------------------------------------------- loading

def _load(source: str | Path | bytes, what: str) -> tuple[bytes | str, str]:
    if isinstance(source, bytes):
        return source, "<bytes>"
    if isinstance(source, str) and source.lstrip().startswith(("<", "\ufeff<")):
        return source, "<string>"
    path = Path(source)
    try:
        return path.read_bytes(), str(path)
    except OSError as exc:
        raise SvgFormatError(f"cannot read {what} {str(path)!r}: {exc.strerror or exc}") from None


def _label(source: str | Path | bytes) -> str:
    if isinstance(source, bytes):
        return "<bytes>"
    if isinstance(source, str) and source.lstrip().startswith(("<", "\ufeff<")):
        return "<string>"
    return str(source)


def parse_svg(source: str | Path | bytes, name: str | None = None) -> Drawing:
    """Parse an SVG (text, bytes or a file path) into a :class:`Drawing`.

    >>> d = parse_svg('<svg xmlns="http://www.w3.org/2000/svg"><g transform="translate(10,0)"><circle r="2"/></g></svg>')
    >>> d.shapes[0].key, d.shapes[0].kind, d.shapes[0].points
    ('circle[0]', 'circle', (('centre', (10.0, 0.0)),))
    >>> parse_svg("<html/>")
    Traceback (most recent call last):
    ...
    construct.regress.svgdiff.SvgFormatError: <string>: the root element is <html>, not <svg>
    """
    data, label = _load(source, "SVG file")
    label = name or label
    try:
        root = ET.fromstring(data)
    except ET.ParseError as exc:
        raise SvgFormatError(f"{label}: not well-formed XML: {exc}") from None
    except (ValueError, UnicodeError) as exc:
        raise SvgFormatError(f"{label}: cannot decode: {exc}") from None
    ns, tag = _local(root.tag)
    if tag != "svg" or ns not in (None, SVG_NS):
        raise SvgFormatError(f"{label}: the root element is <{tag}>, not <svg>")
    try:
        return _Parser(root, label).drawing()
    except (ValueError, ZeroDivisionError, OverflowError) as exc:
        if isinstance(exc, SvgFormatError):
            raise
        raise SvgFormatError(f"{label}: {exc}") from None


# --------------------------------------------------------------------------- the diff

CHANGE_KINDS = ("document", "definition", "missing", "extra", "renamed", "restepped", "reshaped", "moved",
                "resized", "rotated", "text", "restyled", "animated", "described")


@dataclass(frozen=True, slots=True)
class SvgChange:
    """One difference: its kind, the element key, a readable description and its size (drawing units)."""

    kind: str
    key: str
    description: str
    magnitude: float | None = None
    shape: str = ""
    matched_by: str = ""
    key_b: str | None = None
    #: The step of the element (its ``data-step`` group in a layered figure), None outside step groups.
    step: int | None = None

    def line(self) -> str:
        how = []
        if self.shape:
            how.append(self.shape)
        if self.matched_by:
            how.append(f"matched by {self.matched_by}")
        name = self.key if self.key_b in (None, self.key) else f"{self.key} -> {self.key_b}"
        where = f"{name} ({', '.join(how)})" if how else name
        return f"  {self.kind:<10} {where}: {self.description}"


@dataclass(frozen=True, slots=True)
class SvgDiff:
    """The differences between two drawings, in a fixed order (document first, then A's order)."""

    a: str
    b: str
    tolerance: float
    changes: tuple[SvgChange, ...]
    elements: tuple[int, int]

    @property
    def equal(self) -> bool:
        """Do the drawings agree within the tolerance?"""
        return not self.changes

    def report(self) -> str:
        """Readable text, one line per change."""
        head = f"SVG diff {self.a} -> {self.b} (tolerance {_mag(self.tolerance)}): "
        if self.equal:
            n = self.elements[0]
            return head + f"equal ({n} element{'s' if n != 1 else ''})"
        n = len(self.changes)
        return "\n".join([head + f"{n} change{'s' if n != 1 else ''}"] + [c.line() for c in self.changes])

    def as_dict(self) -> dict[str, Any]:
        """Plain data for JSON."""
        return {"kind": "svg", "a": self.a, "b": self.b, "tolerance": self.tolerance, "equal": self.equal,
                "elements": {"a": self.elements[0], "b": self.elements[1]},
                "changes": [{"kind": c.kind, "key": c.key, "key_b": c.key_b, "shape": c.shape,
                             "matched_by": c.matched_by, "description": c.description, "magnitude": c.magnitude}
                            for c in self.changes]}


def diff_svg(a: str | Path | bytes, b: str | Path | bytes, tolerance: float = DEFAULT_TOLERANCE) -> SvgDiff:
    """Compare two SVG drawings; differences at or below *tolerance* (drawing units) are equal."""
    if not (isinstance(tolerance, (int, float)) and math.isfinite(tolerance) and tolerance >= 0):
        raise InvalidParameter(f"diff_svg: tolerance must be a finite number >= 0, got {tolerance!r}")
    tol = float(tolerance)
    da, db = parse_svg(a), parse_svg(b)
    name_a, name_b = _label(a), _label(b)
    changes = _document_changes(da, db, tol) + _definition_changes(da, db, tol)
    pairs = _match(da.shapes, db.shapes, tol, max(_extent(da), _extent(db)))
    by_a = {id(sa): (sb, how) for sa, sb, how in pairs}
    matched_b = {id(sb) for _, sb, _ in pairs}
    for sa in da.shapes:
        if id(sa) in by_a:
            sb, how = by_a[id(sa)]
            changes += _compare(sa, sb, tol, how)
        else:
            changes.append(SvgChange("missing", sa.key, f"{sa.kind} only in A{_where(sa)}", None, sa.kind,
                                     step=sa.step))
    for sb in db.shapes:
        if id(sb) not in matched_b:
            changes.append(SvgChange("extra", sb.key, f"{sb.kind} only in B{_where(sb)}", None, sb.kind,
                                     step=sb.step))
    return SvgDiff(name_a, name_b, tol, tuple(changes), (len(da.shapes), len(db.shapes)))


def _where(s: Shape) -> str:
    if s.points:
        return f" at {_pt(s.points[0][1])}"
    return ""


def _pt(p: Point) -> str:
    return f"({_fmt(p[0])}, {_fmt(p[1])})"


def _document_changes(da: Drawing, db: Drawing, tol: float) -> list[SvgChange]:
    out = []
    a, b = dict(da.document), dict(db.document)
    for prop in sorted(set(a) | set(b)):
        va, vb = a.get(prop), b.get(prop)
        if prop == "stylesheet":
            if va != vb and not _close(va, vb, tol):
                out.append(SvgChange("document", prop, "style sheet rules changed"))
            continue
        if va is None or vb is None or not _close(va, vb, tol):
            out.append(SvgChange("document", prop, f"{_show(va) if va is not None else '(none)'} -> "
                                                   f"{_show(vb) if vb is not None else '(none)'}",
                                 _num_diff(va, vb)))
    return out


def _definition_changes(da: Drawing, db: Drawing, tol: float) -> list[SvgChange]:
    out = []
    a, b = dict(da.definitions), dict(db.definitions)
    for key in sorted(set(a) | set(b)):
        if key not in b:
            out.append(SvgChange("definition", key, f"<{a[key][0]}> only in A"))
        elif key not in a:
            out.append(SvgChange("definition", key, f"<{b[key][0]}> only in B"))
        elif not _close(a[key], b[key], tol):
            out.append(SvgChange("definition", key, f"<{a[key][0]}> changed"
                                 + ("" if a[key][0] == b[key][0] else f" to <{b[key][0]}>"), _num_diff(a[key], b[key])))
    return out


# -- matching ------------------------------------------------------------------------------------

def _match(sa: Sequence[Shape], sb: Sequence[Shape], tol: float, extent: float = 0.0
           ) -> list[tuple[Shape, Shape, str]]:
    """Pairs (a, b, how): by id, by aligned equal content, by key, by nearest geometry."""
    pairs: list[tuple[Shape, Shape, str]] = []
    free_a, free_b = list(sa), list(sb)

    def take(x: Shape, y: Shape, how: str) -> None:
        pairs.append((x, y, how))
        free_a.remove(x)
        free_b.remove(y)

    ids_b = {s.key: s for s in sb if s.has_id}
    for x in [s for s in sa if s.has_id]:
        if x.key in ids_b:
            take(x, ids_b[x.key], "id")
    # Anonymous elements: an inserted one must not shift every later key into a "change".
    anon_a = [s for s in free_a if not s.has_id]
    anon_b = [s for s in free_b if not s.has_id]
    fa = [s.fingerprint(tol) for s in anon_a]
    fb = [s.fingerprint(tol) for s in anon_b]
    matcher = difflib.SequenceMatcher(None, fa, fb, autojunk=False)
    for block in matcher.get_matching_blocks():
        for k in range(block.size):
            x, y = anon_a[block.a + k], anon_b[block.b + k]
            take(x, y, "key" if x.key == y.key else "order")
    keys_b = {s.key: s for s in free_b if not s.has_id}
    for x in [s for s in free_a if not s.has_id]:
        if x.key in keys_b and keys_b[x.key].kind == x.kind:
            take(x, keys_b.pop(x.key), "key")
    # What is left: same kind, nearest geometry, if clearly the same element.
    # "Clearly the same": within 2 % of the drawing's size (points, radii and viewBox).
    limit = max(tol, 0.02 * max(_diagonal(list(sa) + list(sb)), extent))
    candidates = []
    if len(free_a) * len(free_b) <= 4_000_000:
        for i, x in enumerate(free_a):
            for j, y in enumerate(free_b):
                d = _distance(x, y)
                if d <= limit:
                    candidates.append((d, i, j))
    candidates.sort()
    used_a: set[int] = set()
    used_b: set[int] = set()
    chosen = []
    for d, i, j in candidates:
        if i not in used_a and j not in used_b:
            used_a.add(i)
            used_b.add(j)
            chosen.append((free_a[i], free_b[j]))
    for x, y in chosen:
        take(x, y, "geometry")
    return pairs


def _extent(d: Drawing) -> float:
    """The size of a drawing: its viewBox diagonal, or the largest radius or length drawn."""
    doc = dict(d.document)
    vb = doc.get("viewBox")
    sizes = [abs(v) for s in d.shapes for _, v in s.sizes]
    return max([math.hypot(vb[2], vb[3]) if vb else 0.0] + sizes)


def _diagonal(shapes: list[Shape]) -> float:
    xs = [p[0] for s in shapes for _, p in s.points]
    ys = [p[1] for s in shapes for _, p in s.points]
    if not xs:
        return 0.0
    return math.hypot(max(xs) - min(xs), max(ys) - min(ys))


def _bbox(s: Shape) -> tuple[float, float, float, float]:
    xs = [p[0] for _, p in s.points] or [0.0]
    ys = [p[1] for _, p in s.points] or [0.0]
    return min(xs), min(ys), max(xs), max(ys)


def _distance(x: Shape, y: Shape) -> float:
    if x.kind != y.kind or x.tag != y.tag or (x.kind == "text" and x.text != y.text and x.points != y.points):
        return math.inf
    if x.kind == "group":
        return 0.0 if (x.animations, x.described) == (y.animations, y.described) else math.inf
    if [n for n, _ in x.points] == [n for n, _ in y.points] and [n for n, _ in x.sizes] == [n for n, _ in y.sizes]:
        d = max((math.dist(p, q) for (_, p), (_, q) in zip(x.points, y.points)), default=0.0)
        return max([d] + [abs(u - v) for (_, u), (_, v) in zip(x.sizes, y.sizes)])
    ba, bb = _bbox(x), _bbox(y)
    return max(abs(u - v) for u, v in zip(ba, bb))


# -- comparing one pair ----------------------------------------------------------------------------

def _compare(x: Shape, y: Shape, tol: float, how: str) -> list[SvgChange]:
    out: list[SvgChange] = []
    key_b = y.key if y.key != x.key else None

    def add(kind: str, description: str, magnitude: float | None = None) -> None:
        out.append(SvgChange(kind, x.key, description, magnitude, x.kind, how, key_b,
                             x.step if x.step is not None else y.step))

    if key_b is not None and (x.has_id or y.has_id):
        add("renamed", f"id {x.key!r} -> {y.key!r}")
    if x.step != y.step:
        add("restepped", f"made by step {x.step} -> {y.step}")
    same_structure = (x.kind == y.kind and x.structure == y.structure
                      and [n for n, _ in x.points] == [n for n, _ in y.points]
                      and [n for n, _ in x.sizes] == [n for n, _ in y.sizes])
    if not same_structure:
        if x.kind != y.kind:
            what = f"{x.kind} -> {y.kind}"
        else:
            sa, sb = dict(x.structure), dict(y.structure)
            what = "; ".join(f"{k}: {_show(sa.get(k, '-'))} -> {_show(sb.get(k, '-'))}"
                             for k in sorted(set(sa) | set(sb)) if sa.get(k) != sb.get(k)) or "defining points differ"
        ba, bb = _bbox(x), _bbox(y)
        add("reshaped", f"{what}; bounding box {_pt(ba[:2])}..{_pt(ba[2:])} -> {_pt(bb[:2])}..{_pt(bb[2:])}",
            max(abs(u - v) for u, v in zip(ba, bb)) if x.points and y.points else None)
    else:
        moved = [(math.dist(p, q), name, p, q) for (name, p), (_, q) in zip(x.points, y.points)]
        if any(m[0] > tol for m in moved):
            add("moved", _movement(moved, tol), max(m[0] for m in moved))
        resized = [(abs(u - v), name, u, v) for (name, u), (_, v) in zip(x.sizes, y.sizes) if abs(u - v) > tol]
        if resized:
            d, name, u, v = max(resized, key=lambda m: m[0])
            more = f" ({len(resized)} sizes changed)" if len(resized) > 1 else ""
            add("resized", f"{name} {_fmt(u)} -> {_fmt(v)} (by {_mag(d)}){more}", d)
    ang_a, ang_b = dict(x.angles), dict(y.angles)
    for name in [n for n, _ in x.angles if n in ang_b]:
        delta = (ang_b[name] - ang_a[name] + 180.0) % 360.0 - 180.0
        if abs(delta) > tol:
            add("rotated", f"{name} {_fmt(ang_a[name])} -> {_fmt(ang_b[name])} degrees (by {_mag(abs(delta))})",
                abs(delta))
    if x.text != y.text:
        add("text", f"{x.text!r} -> {y.text!r}")
    style_a, style_b = dict(x.style), dict(y.style)
    diffs, mags = [], []
    for prop in sorted(set(style_a) | set(style_b)):
        va, vb = style_a.get(prop, _INITIAL.get(prop)), style_b.get(prop, _INITIAL.get(prop))
        if va is None or vb is None or not _close(va, vb, tol):
            diffs.append(f"{prop} {_show(va) if va is not None else '(unset)'} -> "
                         f"{_show(vb) if vb is not None else '(unset)'}")
            nd = _num_diff(va, vb)
            if nd is not None:
                mags.append(nd)
    if diffs:
        add("restyled", "; ".join(diffs), max(mags) if mags else None)
    if not _close(x.animations, y.animations, tol):
        gone = [a for a in x.animations if not any(_close(a, b, tol) for b in y.animations)]
        new = [b for b in y.animations if not any(_close(a, b, tol) for a in x.animations)]
        parts = [f"-<{a[0]} {_anim(a)}>" for a in gone] + [f"+<{b[0]} {_anim(b)}>" for b in new]
        add("animated", "; ".join(parts) or "animation order changed")
    if x.described != y.described:
        da, db = dict(x.described), dict(y.described)
        add("described", "; ".join(f"{k} {da.get(k)!r} -> {db.get(k)!r}" for k in ("title", "desc")
                                   if da.get(k) != db.get(k)))
    return out


def _movement(moved: list[tuple[float, str, Point, Point]], tol: float) -> str:
    """Say how far the defining points moved, naming the one that shows it best.

    A centre is named first when it moved as far as any point (a moved arc is
    a moved centre); a rigid translation is reported as such.
    """
    d = max(m[0] for m in moved)
    near_max = [m for m in moved if m[0] >= d - tol]
    _, name, p, q = next((m for m in near_max if m[1].endswith("centre")), near_max[0])
    text = f"by {_mag(d)}: {name} {_pt(p)} -> {_pt(q)}"
    if len(moved) > 1:
        shifts = [(m[3][0] - m[2][0], m[3][1] - m[2][1]) for m in moved]
        if all(math.dist(s, shifts[0]) <= tol for s in shifts):
            text += f" (all {len(moved)} points translated by {_pt(shifts[0])})"
        else:
            text += f" ({sum(m[0] > tol for m in moved)} of {len(moved)} points moved)"
    return text


def _anim(a: tuple) -> str:
    return " ".join(f'{k}="{_show(v)}"' for k, v in a[1])


def changes_by_step(diff: SvgDiff) -> dict[int | None, list[SvgChange]]:
    """The changes of a layered figure gathered by the step that made each element (None: outside steps).

    >>> a = ('<svg xmlns="http://www.w3.org/2000/svg"><g class="step" data-step="3">'
    ...      '<circle id="s0003-P" cx="1" cy="2" r="1"/></g></svg>')
    >>> {k: [c.key for c in v] for k, v in changes_by_step(diff_svg(a, a.replace('cx="1"', 'cx="2"'))).items()}
    {3: ['s0003-P']}
    """
    out: dict[int | None, list[SvgChange]] = {}
    for c in diff.changes:
        out.setdefault(c.step, []).append(c)
    return dict(sorted(out.items(), key=lambda kv: (kv[0] is not None, kv[0] or 0)))


def iter_changes(diff: SvgDiff, kind: str) -> Iterator[SvgChange]:
    """The changes of one kind, in report order.

    >>> d = diff_svg('<svg xmlns="http://www.w3.org/2000/svg"/>', '<svg xmlns="http://www.w3.org/2000/svg"><line x2="1"/></svg>')
    >>> [c.key for c in iter_changes(d, "extra")]
    ['line[0]']
    """
    return (c for c in diff.changes if c.kind == kind)
