"""Plate furniture: what a book plate carries besides the construction.

A plate in the books is more than its construction lines: the stroke is
dimensioned with arrowheads (s, r, L), the centre line is dash-dotted, the
result curve is drawn heavy and the helper lines thin, the angles of a crank
position carry their arcs and values, a diagram has its scale and the signs
of its zones.  A construction describes this as data, a :class:`Plate`: the
look of named objects and a tuple of furniture items in drawing
coordinates (y up, the figure's own units), so that any construction, the
force diagrams included, can letter its plate the same way.  Constructions do
not import the renderer: they describe their plate in plain data, a dict
that :meth:`Plate.from_data` reads::

    def my_plate(fig):
        return {"looks": {"axis": "centre", "curve": "heavy"},
                "furniture": [{"kind": "dimension", "a": (-1, 0), "b": (1, 0), "text": "s", "offset": -0.3}]}

    Construction(..., plate=my_plate)

Kinds: dimension (a, b, text, offset, text_at), angle (centre, start, end, radius,
text, text_at), stroke (a, b, look, broken), lettering (at, text, anchor,
angle, size, to), scale (origin, end, text), sign (at, text), dot (at).

A plate may also lay its sheet out in *panels*, as a book sets a cover-side
and a crank-side diagram side by side: ``{"panels": [{"names": [regex, ...],
"shift": (dx, dy)}, ...]}`` draws every object whose name matches a panel's
patterns moved by that panel's shift (drawing units).  An object named by
several panels is drawn in each (the stroke line under both diagrams); a line
drawn in a panel reaches over that panel's points on it only, and copies that
fall on one line (an ordinate through two panels one above the other) are one
line.  Objects no panel names stay where they are.  Furniture is given where it
stands on the sheet.  A shift moves a diagram, never changes a length in it:
every value read off a diagram is read from its own base line.

Every value written on a plate is read off the constructed figure (the
construction's own points), never from the formula the checks compare with.
:func:`furniture_elements` draws the items in a style, each lettering on a
paper-coloured halo of itself; a plate's drawing (:class:`construct.render.svg.Drawing`)
breaks every line for the lettering instead (:mod:`construct.render.gaps`) and leaves the halos out.

>>> d = Dimension((0.0, 0.0), (2.0, 0.0), "s", offset=-0.3)
>>> ext = extent((d,))
>>> ext[1] < -0.29 and ext[2] == 2.0
True
>>> dms(math.radians(61.3225))
'61°19′'
"""

from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass, field, fields, replace
from typing import Any, Callable, Mapping, NamedTuple, Sequence


__all__ = ["Plate", "Panel", "Dimension", "AngleArc", "Stroke", "Lettering", "ScaleBar", "Sign", "Dot", "dms", "extent",
           "anchors", "shifted",
           "furniture_elements", "break_elements", "LOOKS_CSS", "plate_of", "Piece", "PIECES", "furniture_pieces",
           "crossing_lines", "crossings", "DASHES", "subscript_runs", "plain"]

XY = tuple[float, float]

#: The dash patterns of the line looks (canvas units: dash, gap, dash, gap).
DASHES = {"dashdot": (14, 3, 2, 3), "centre": (18, 3, 2, 3), "dashed": (6, 4)}

#: Line looks a plate may give its objects (CSS classes on the marks).
LOOKS_CSS = (
    ".heavy{stroke-width:2.2px}",
    ".medium{stroke-width:1px}",
    ".thin{stroke-width:0.45px}",
    f".dashdot{{stroke-dasharray:{' '.join(map(str, DASHES['dashdot']))};stroke-width:0.7px}}",
    f".centre{{stroke-dasharray:{' '.join(map(str, DASHES['centre']))};stroke-width:0.5px}}",
    f".dashed{{stroke-dasharray:{' '.join(map(str, DASHES['dashed']))}}}",
    # a result the plate shows otherwise (the stroke s, dimensioned with arrowheads over the centre line)
    ".hidden{display:none}",
)


@dataclass(frozen=True)
class Dimension:
    """A dimension line from *a* to *b* with arrowheads, set off by *offset* (drawing units, + = left of a->b).

    The text stands on the line, which is broken for it; or, for a short dimension (a thickness), upright
    at *text_at* beside the whole line.  *room*: the characters the break in the line leaves room for (its
    text's, if 0): a text that changes with a given (the rod's length, L = 3,5 r) keeps one break as the given
    moves.
    """

    a: XY
    b: XY
    text: str
    offset: float = 0.0
    text_at: XY | None = None
    room: int = 0


@dataclass(frozen=True)
class AngleArc:
    """The arc of the angle at *centre* from the ray through *start* to the ray through *end*, radius *radius*.

    *text* is written at *text_at* (drawing units), or beside the arc's middle if None.
    """

    centre: XY
    start: XY
    end: XY
    radius: float
    text: str = ""
    text_at: XY | None = None


@dataclass(frozen=True)
class Stroke:
    """A line drawn for the plate only (the crank in one position, a radius): *look* as in :data:`LOOKS_CSS`.

    *broken*: the far end is drawn as a break (the part is longer than the sheet).
    """

    a: XY
    b: XY
    look: str = "thin"
    broken: bool = False


@dataclass(frozen=True)
class Lettering:
    """Text at *at*; *anchor* start, middle or end; *angle* in degrees (counter-clockwise), *size* relative;
    *to*: the point it names, tied to it by a leader (a letter set off from a crowded line)."""

    at: XY
    text: str
    anchor: str = "middle"
    angle: float = 0.0
    size: float = 1.0
    to: XY | None = None


@dataclass(frozen=True)
class ScaleBar:
    """A scale: the length from *origin* to *end* stands for *text* (e.g. 1 kg/cm²), with end ticks."""

    origin: XY
    end: XY
    text: str


@dataclass(frozen=True)
class Dot:
    """A point the plate marks (the crosshead of the rod drawn in one position)."""

    at: XY


@dataclass(frozen=True)
class Sign:
    """The sign of a zone of a diagram (+ or −), set large in it."""

    at: XY
    text: str


@dataclass(frozen=True)
class Panel:
    """A part of the sheet: the objects whose names match *names* (regular expressions), moved by *shift*."""

    names: tuple[str, ...]
    shift: XY = (0.0, 0.0)


@dataclass(frozen=True)
class Plate:
    """What a construction adds to its plate: looks of named objects, furniture, the sheet's panels, and the
    legend of its letters (letter -> (German, English): what J or P_b stands for, as the book's text says it;
    it goes with the plate's whole caption into its ``<desc>``, not onto the sheet)."""

    looks: Mapping[str, str] = field(default_factory=dict)
    furniture: tuple = ()
    panels: tuple[Panel, ...] = ()
    legend: Mapping[str, tuple[str, str]] = field(default_factory=dict)

    @classmethod
    def from_data(cls, data: Mapping[str, Any] | None) -> "Plate":
        """A plate from a construction's plain description (see the module docstring).

        >>> p = Plate.from_data({"looks": {"axis": "centre"}, "furniture": [{"kind": "sign", "at": (0, 1), "text": "+"}]})
        >>> p.looks["axis"], p.furniture
        ('centre', (Sign(at=(0, 1), text='+'),))
        """
        if not data:
            return cls()
        kinds = {"dimension": Dimension, "angle": AngleArc, "stroke": Stroke, "lettering": Lettering,
                 "scale": ScaleBar, "sign": Sign, "dot": Dot}
        items = []
        for d in data.get("furniture", ()):
            d = dict(d)
            kind = d.pop("kind")
            if kind not in kinds:
                from ..kernel.errors import InvalidParameter

                raise InvalidParameter(f"unknown plate furniture {kind!r}; choose one of {', '.join(sorted(kinds))}")
            items.append(kinds[kind](**d))
        panels = tuple(Panel(tuple(p["names"]), tuple(p.get("shift", (0.0, 0.0)))) for p in data.get("panels", ()))
        legend = {str(k): (str(v[0]), str(v[1])) for k, v in dict(data.get("legend", {})).items()}
        return cls(dict(data.get("looks", {})), tuple(items), panels, legend)


def plate_of(construction: Any, figure: Any) -> Plate:
    """The construction's plate (its ``plate(figure)``, plain data), or an empty one (no construction, or none)."""
    make: Callable[[Any], Any] | None = getattr(construction, "plate", None)
    return Plate.from_data(make(figure)) if make else Plate()


def dms(rad: float) -> str:
    """An angle in degrees and minutes, rounded to the minute, as the books print it (61°19′)."""
    minutes = round(math.degrees(rad) * 60.0)
    d, m = divmod(minutes, 60)
    return f"{d}°{m:02d}′"


def _points(item: Any) -> list[XY]:
    if isinstance(item, Dimension):
        (ax, ay), (bx, by) = item.a, item.b
        nx, ny = _normal(item.a, item.b)
        o = item.offset
        return [item.a, item.b, (ax + o * nx, ay + o * ny), (bx + o * nx, by + o * ny)] + (
            [item.text_at] if item.text_at else [])
    if isinstance(item, AngleArc):
        cx, cy = item.centre
        pts = [(cx + item.radius * math.cos(t), cy + item.radius * math.sin(t)) for t in _arc_angles(item, 9)]
        return pts + ([item.text_at] if item.text_at else [])
    if isinstance(item, (Stroke, ScaleBar)):
        return [item.origin, item.end] if isinstance(item, ScaleBar) else [item.a, item.b]
    if isinstance(item, Lettering):
        return [item.at] + ([item.to] if item.to else [])
    if isinstance(item, (Sign, Dot)):
        return [item.at]
    return []


def anchors(items: Sequence[Any]) -> list[XY]:
    """The points of the furniture that stand on their own (not the ends of a line or dimension):
    a broken axis keeps them clear of its gap."""
    return [p for it in items if not isinstance(it, (Stroke, Dimension)) for p in _points(it)]


def shifted(item: Any, sx: Callable[[float], float]) -> Any:
    """*item* with every point's x mapped by *sx* (a broken axis)."""
    changes = {}
    for name in _field_names(type(item)):
        v = getattr(item, name)
        if isinstance(v, tuple) and len(v) == 2 and all(isinstance(c, (int, float)) for c in v):
            changes[name] = (sx(v[0]), v[1])
    return replace(item, **changes) if changes else item


@functools.lru_cache(maxsize=64)
def _field_names(kind: type) -> tuple[str, ...]:
    """The names of the fields of the furniture item class *kind*, in their order (asked once a class: a live sweep
    shifts every item of the plate at every value)."""
    return tuple(f.name for f in fields(kind))


def extent(items: Sequence[Any]) -> tuple[float, float, float, float] | None:
    """The box (drawing units) the furniture's anchor points span, or None."""
    pts = [p for it in items for p in _points(it)]
    if not pts:
        return None
    return (min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts), max(p[1] for p in pts))


def _normal(a: XY, b: XY) -> XY:
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy) or 1.0
    return (-dy / n, dx / n)


def _arc_angles(item: AngleArc, n: int) -> list[float]:
    cx, cy = item.centre
    a0 = math.atan2(item.start[1] - cy, item.start[0] - cx)
    a1 = math.atan2(item.end[1] - cy, item.end[0] - cx)
    sweep = (a1 - a0) % (2 * math.pi)
    if sweep > math.pi:  # the angle of a crank position is at most 180°: go the short way round
        sweep -= 2 * math.pi
    return [a0 + sweep * i / (n - 1) for i in range(n)]


# -- drawing ---------------------------------------------------------------------------------


def _f(v: float) -> str:
    text = f"{v:.2f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def furniture_elements(items: Sequence[Any], px: Callable[[float, float], XY], scale: float, f: Any, *,
                       size: float = 12.0) -> list[Any]:
    """The furniture as svgwrite elements made by the factory *f* (pixels through *px*, *scale* px per unit).

    Classes: ``fur`` (lines, with a look: ``fur heavy``), ``arrow`` (filled heads), ``lb fur-text``
    (lettering), each letter on a ``lb halo`` copy of itself in paper colour.
    """
    out: list[Any] = []
    for it in items:
        out.extend(_item(it, px, scale, size, f))
    return out


class Piece(NamedTuple):
    """One piece of a plate's furniture on the canvas (pixels, y down), for a writer other than SVG (TikZ).

    *kind*: ``line`` (two points), ``poly`` (a polyline, *closed* or not), ``text`` (at its point: the middle
    of the text's height, *anchor* start/middle/end, *angle* in degrees counter-clockwise, *size* relative to
    the letters'), ``dot`` (a filled dot of radius *size* px).  *cls*: the SVG classes it would carry.
    """

    kind: str
    points: tuple[XY, ...]
    cls: str
    text: str = ""
    anchor: str = "middle"
    angle: float = 0.0
    size: float = 1.0
    closed: bool = False


class _Pieces:
    """Takes the place of svgwrite's factory where the furniture is wanted as :class:`Piece` values."""


#: Given as the factory to :func:`furniture_elements` or :func:`break_elements`, they return :class:`Piece` values.
PIECES = _Pieces()


def crossing_lines(marks: Sequence[Any], furniture: Sequence[Any]) -> list[tuple[float, float, float, float]]:
    """The straight lines a broken axis may cross (drawing units): the segments among *marks*, the straight lines
    drawn from point to point (a rod lettered L) and the plate's strokes (:func:`break_elements` breaks those
    that do)."""
    return ([m.geom for m in marks if m.kind == "segment"]
            + [(*m.geom[0], *m.geom[1]) for m in marks if m.kind == "curve" and m.straight and len(m.geom) == 2]
            + [(*it.a, *it.b) for it in furniture if isinstance(it, Stroke)])


def furniture_pieces(items: Sequence[Any], px: Callable[[float, float], XY], scale: float, *,
                     size: float = 12.0) -> list[Piece]:
    """The furniture as :class:`Piece` values: what :func:`furniture_elements` draws, as data.

    >>> [p.kind for p in furniture_pieces([Sign((0.0, 0.0), "+"), Dot((1.0, 0.0))], lambda x, y: (x, y), 1.0)]
    ['text', 'dot']
    """
    return furniture_elements(items, px, scale, PIECES, size=size)
def crossings(breaks: Sequence[tuple], lines: Sequence[tuple[float, float, float, float]]):
    """(axis, line, the break's middle on the line: x and y, drawing units) of every one of *lines* crossing a
    break of *breaks*, break by break."""
    for b in breaks:
        x0, w, axis = b[0], b[1], (b[3] if len(b) > 3 else 0)
        for line in lines:
            a0, a1, b0, b1 = (line[axis], line[1 - axis], line[2 + axis], line[3 - axis])
            if min(a0, b0) < x0 + 0.3 * w and max(a0, b0) > x0 + 0.7 * w and abs(b0 - a0) > 1e-12:
                t = x0 + w / 2
                s = a1 + (b1 - a1) * (t - a0) / (b0 - a0)
                yield axis, line, (t, s) if axis == 0 else (s, t)


def break_elements(breaks: Sequence[tuple], lines: Sequence[tuple[float, float, float, float]],
                   px: Callable[[float, float], XY], f: Any, *, size: float = 12.0) -> list[Any]:
    """The marks of a broken axis (:attr:`construct.render.scene.Scene.breaks`: where a break starts, its
    drawn width, drawing units, and its axis if not x) on every one of *lines* (segments, drawing units)
    crossing it: a gap in paper colour (class ``brk``) and two slanted strokes (``brkline``), sized by the
    letters' *size*.  The page of a live given draws the same marks as the given moves (its script's
    ``breakMarks``, held to these by tests/test_render_live_browser.py)."""
    out: list[Any] = []
    for _, line, at in crossings(breaks, lines):
        # the classic break: a short gap along the line, a slanted tick at each side
        cx, cy = px(*at)
        ax, ay, bx, by = line
        ex, ey = px(bx, by)
        sx, sy = px(ax, ay)
        n = math.hypot(ex - sx, ey - sy) or 1.0
        ux, uy = (ex - sx) / n, (ey - sy) / n
        nx, ny = -uy, ux
        h, gap = 0.6 * size, 0.45 * size
        corners = [(cx + su * gap * ux + sn * h * nx, cy + su * gap * uy + sn * h * ny)
                   for su, sn in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        out.append(_poly(f, corners, "brk", close=True))
        for su in (-1, 1):
            tx, ty = cx + su * gap * ux, cy + su * gap * uy
            out.append(_line(f, (tx - 0.35 * h * ux - h * nx, ty - 0.35 * h * uy - h * ny),
                             (tx + 0.35 * h * ux + h * nx, ty + 0.35 * h * uy + h * ny), "brkline"))
    return out


def _as_written(f: Any) -> Callable[[float], Any]:
    """How factory *f* takes a number: written (:func:`_f`), or as it is where the factory takes the numbers
    unwritten (``raw``: the live sweep's, :class:`construct.render.end_state.NumbersFactory`)."""
    return (lambda v: v) if getattr(f, "raw", False) else _f


def _line(f: Any, a: XY, b: XY, cls: str = "fur") -> Any:
    if isinstance(f, _Pieces):
        return Piece("line", (a, b), cls)
    w = _as_written(f)
    return f.line(start=(w(a[0]), w(a[1])), end=(w(b[0]), w(b[1])), class_=cls)


def _poly(f: Any, pts: Sequence[XY], cls: str, close: bool = False) -> Any:
    if isinstance(f, _Pieces):
        return Piece("poly", tuple(pts), cls, closed=close)
    if getattr(f, "raw", False):
        return f.path(d=("poly", tuple(pts), close), class_=cls)
    return f.path(d="M" + "L".join(f"{_f(x)} {_f(y)}" for x, y in pts) + ("Z" if close else ""), class_=cls)


def _arrow(f: Any, tip: XY, frm: XY, size: float) -> Any:
    """A filled arrowhead at *tip* pointing away from *frm* (pixels)."""
    dx, dy = tip[0] - frm[0], tip[1] - frm[1]
    n = math.hypot(dx, dy) or 1.0
    ux, uy = dx / n, dy / n
    L, W = 0.75 * size, 0.22 * size
    bx, by = tip[0] - L * ux, tip[1] - L * uy
    return _poly(f, [tip, (bx - W * uy, by + W * ux), (bx + W * uy, by - W * ux)], "arrow", close=True)


def _text(f: Any, at: XY, text: str, size: float, anchor: str = "middle", angle: float = 0.0,
          rel: float = 1.0) -> list[Any]:
    if isinstance(f, _Pieces):  # its halo is the writer's (a TikZ node's white ground)
        return [Piece("text", (at,), "lb fur-text", text, anchor, angle, rel)]
    raw, w = getattr(f, "raw", False), _as_written(f)
    attrs: dict[str, Any] = {"x": [w(at[0])], "y": [w(at[1] + 0.35 * size * rel)]}
    if angle:
        attrs["transform"] = ("rotate", -angle, at[0], at[1]) if raw else \
            f"rotate({_f(-angle)} {_f(at[0])} {_f(at[1])})"
    # in the style attribute: the style sheet's .lb{text-anchor:middle} overrides a presentation attribute
    # (a browser set the scale's numbers centred on their ticks; cairosvg did not)
    own = ([f"font-size:{_f(size * rel)}px"] if rel != 1.0 else []) + ([f"text-anchor:{anchor}"] if anchor != "middle" else [])
    if own:
        attrs["style"] = ";".join(own)
    runs = subscript_runs(text)
    if len(runs) == 1:
        return [f.text(text, class_="lb halo", **attrs), f.text(text, class_="lb fur-text", **attrs)]
    out = []
    for cls in ("lb halo", "lb fur-text"):
        # an index the font has no subscript glyph for (P_b, p_ü): a smaller run set below the line
        t = f.text("", class_=cls, **attrs)
        down = 0.0
        for part, low in runs:
            shift = 0.25 * size * rel if low else 0.0
            kw = {"dy": [_f(shift - down)]} if shift != down else {}
            if low:
                kw["style"] = f"font-size:{_f(0.7 * size * rel)}px"
            t.add(f.tspan(part, **kw))
            down = shift
        out.append(t)
    return out


def text_elements(f: Any, at: XY, text: str, size: float, *, rel: float = 1.0) -> list[Any]:
    """A piece of the plate's lettering as it draws it: halo and text centred on *at* (canvas px), an index
    (P_b, F·p_ü) set below the line as a smaller run; *rel*: its size relative to the letters' *size*."""
    return _text(f, at, text, size, rel=rel)


def subscript_runs(text: str) -> list[tuple[str, bool]]:
    """*text* as runs (text, set below the line?): an index is written ``_x`` or ``_{xyz}`` (P_b, F·p_ü).

    >>> subscript_runs("P = F·p_ü"), subscript_runs("B_{max} t"), subscript_runs("s₁")
    ([('P = F·p', False), ('ü', True)], [('B', False), ('max', True), (' t', False)], [('s₁', False)])
    """
    if "_" not in text:  # (no index: one run; most of a plate's texts, written at every value of a live sweep)
        return [(text, False)]
    out: list[tuple[str, bool]] = []
    pos = 0
    for m in re.finditer(r"_(\{[^}]*\}|[^\W_])", text):
        if m.start() > pos:
            out.append((text[pos:m.start()], False))
        out.append((m.group(1).strip("{}"), True))
        pos = m.end()
    if pos < len(text) or not out:
        out.append((text[pos:], False))
    return out


def plain(text: str) -> str:
    """*text* without its index marks, as a reader sees it (P_b -> Pb)."""
    return "".join(part for part, _ in subscript_runs(text))


def _item(it: Any, px: Callable[[float, float], XY], scale: float, size: float, f: Any) -> list[Any]:
    if isinstance(it, Dimension):
        nx, ny = _normal(it.a, it.b)
        o = it.offset
        a, b = px(*it.a), px(*it.b)
        a2 = px(it.a[0] + o * nx, it.a[1] + o * ny)
        b2 = px(it.b[0] + o * nx, it.b[1] + o * ny)
        out = []
        if abs(o) * scale > 2.0:
            # extension lines, from a little off the object to a little past the dimension line
            for p, q in ((a, a2), (b, b2)):
                dx, dy = q[0] - p[0], q[1] - p[1]
                n = math.hypot(dx, dy) or 1.0
                out.append(_line(f, (p[0] + 3 * dx / n, p[1] + 3 * dy / n), (q[0] + 4 * dx / n, q[1] + 4 * dy / n),
                                 "fur thin"))
        mid = ((a2[0] + b2[0]) / 2, (a2[1] + b2[1]) / 2)
        if it.text_at is not None:  # a short dimension: the whole line, the text upright beside it
            return out + [_line(f, a2, b2, "fur"), _arrow(f, a2, b2, size), _arrow(f, b2, a2, size)] + _text(
                f, px(*it.text_at), it.text, size)
        # the dimension line stops either side of its text, as a draftsman leaves room for the figure
        length = math.hypot(b2[0] - a2[0], b2[1] - a2[1]) or 1.0
        gap = min(0.5 * length - 1.0, 0.33 * size * (it.room or len(it.text)) + 0.4 * size)
        ux, uy = (b2[0] - a2[0]) / length, (b2[1] - a2[1]) / length
        out += [_line(f, a2, (mid[0] - gap * ux, mid[1] - gap * uy), "fur"),
                _line(f, (mid[0] + gap * ux, mid[1] + gap * uy), b2, "fur"),
                _arrow(f, a2, b2, size), _arrow(f, b2, a2, size)]
        ang = math.degrees(math.atan2(-(b2[1] - a2[1]), b2[0] - a2[0]))
        if ang > 90 or ang < -90:
            ang += 180
        if ang > 180:
            ang -= 360
        # the text sits on the dimension line; its halo opens the line for it
        return out + _text(f, mid, it.text, size, "middle", ang)
    if isinstance(it, AngleArc):
        angles = _arc_angles(it, 33)
        cx, cy = it.centre
        pts = [px(cx + it.radius * math.cos(t), cy + it.radius * math.sin(t)) for t in angles]
        out = [_poly(f, pts, "fur thin"), _arrow(f, pts[-1], pts[-3], 0.7 * size)]
        if it.text:
            if it.text_at:
                at = px(*it.text_at)
            else:
                t = angles[len(angles) // 2]
                rr = it.radius + 10.0 / scale
                at = px(cx + rr * math.cos(t), cy + rr * math.sin(t))
            out += _text(f, at, it.text, size, "middle", 0.0, 0.85)
        return out
    if isinstance(it, Stroke):
        a, b = px(*it.a), px(*it.b)
        out = [_line(f, a, b, f"fur {it.look}")]
        if it.broken:
            # the break: a short zig-zag across the end of a part longer than the sheet
            nx, ny = _normal(a, b)
            dx, dy = b[0] - a[0], b[1] - a[1]
            n = math.hypot(dx, dy) or 1.0
            ux, uy = dx / n, dy / n
            h = 0.5 * size
            zig = [(b[0] - h * nx, b[1] - h * ny),
                   (b[0] - 0.3 * h * ux - 0.2 * h * nx, b[1] - 0.3 * h * uy - 0.2 * h * ny),
                   (b[0] + 0.3 * h * ux + 0.2 * h * nx, b[1] + 0.3 * h * uy + 0.2 * h * ny),
                   (b[0] + h * nx, b[1] + h * ny)]
            out.append(_poly(f, zig, "fur"))
        return out
    if isinstance(it, ScaleBar):
        a, b = px(*it.origin), px(*it.end)
        nx, ny = _normal(a, b)
        t = 0.35 * size
        out = [_line(f, a, b, "fur medium"),
               _line(f, (a[0] - t * nx, a[1] - t * ny), (a[0] + t * nx, a[1] + t * ny), "fur medium"),
               _line(f, (b[0] - t * nx, b[1] - t * ny), (b[0] + t * nx, b[1] + t * ny), "fur medium")]
        mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        return out + _text(f, (mid[0] + 0.6 * size, mid[1]), it.text, size, "start", 0.0, 1.0)  # a scale is read: at the letters' size
    if isinstance(it, Lettering):
        out = []
        if it.to is not None:
            # the leader runs from beside the point to the letter's middle: the plate breaks it at the letter's
            # white (construct.render.gaps), so it ends there whatever the letter's width
            (ax, ay), (bx, by) = px(*it.to), px(*it.at)
            n = math.hypot(bx - ax, by - ay) or 1.0
            start = 0.3 * size
            out.append(_line(f, (ax + start * (bx - ax) / n, ay + start * (by - ay) / n), (bx, by), "fur leader"))
        return out + _text(f, px(*it.at), it.text, size, it.anchor, it.angle, it.size)
    if isinstance(it, Sign):
        return _text(f, px(*it.at), it.text, size, "middle", 0.0, 2.0)
    if isinstance(it, Dot):
        x, y = px(*it.at)
        if isinstance(f, _Pieces):
            return [Piece("dot", ((x, y),), "arrow", size=0.22 * size)]
        w = _as_written(f)
        return [f.circle(center=(w(x), w(y)), r=w(0.22 * size), class_="arrow")]
    return []
