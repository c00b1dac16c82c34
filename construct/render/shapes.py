"""What a mark draws on the canvas, without its letter: the SVG attributes of its geometry, the layer it goes
into, the radius of a point.

The one place that turns a mark (:class:`construct.render.marks.Mark`) into SVG numbers: the drawing
(:class:`construct.render.svg.Drawing`) makes its elements from them, the live sweep
(:mod:`construct.live.measure`) reads the same numbers at every value of a given, and the TikZ picture
(:mod:`construct.render.tikz`) sorts its marks into the same layers.

>>> from construct.render.styles import PLAIN
>>> vp = Viewport(0.0, 1.0, 10.0, 20.0, 20.0, 0.0)
>>> arc = Mark("a", 2, "k", MarkKind.ARC, (0.5, 0.5, 0.5, 0.0, 3.14159), "construction", "compass", "exact")
>>> mark_layer(arc), mark_geometry(arc, vp, PLAIN)[0][:2]
('construction', ('', 'path'))
"""

from __future__ import annotations

from typing import Any, Callable

from .marks import Mark, MarkKind
from .paths import arc_path, curve_path, hatch_path, polygon_path, polyline_path
from .styles import Style
from .svgdoc import fmt
from .viewport import Viewport

__all__ = ["mark_geometry", "mark_layer", "point_radius", "stroke_element"]


#: The svgwrite element of a stroked mark, by kind, from its geometry's attributes (:func:`mark_geometry`).
_STROKES: dict[MarkKind, Callable[[Any, dict[str, str], dict[str, Any]], Any]] = {
    MarkKind.SEGMENT: lambda f, a, kw: f.line(start=(a["x1"], a["y1"]), end=(a["x2"], a["y2"]), **kw),
    MarkKind.CIRCLE: lambda f, a, kw: f.circle(center=(a["cx"], a["cy"]), r=a["r"], **kw),
    MarkKind.ARC: lambda f, a, kw: f.path(d=a["d"], **kw),
    MarkKind.CURVE: lambda f, a, kw: f.path(d=a["d"], **kw),
}


def point_radius(m: Mark, style: Style) -> float:
    """The drawn radius of a point mark: small for an auxiliary one or an unlettered helper (a dotted name)."""
    aux = m.role == "auxiliary" or ("." in m.name and not m.label)
    return style.aux_point_radius if aux else style.point_radius


def mark_layer(m: Mark) -> str:
    """The layer of :attr:`construct.render.svg.Drawing.LAYERS` a mark's drawing (not its letter) goes into."""
    if m.kind is MarkKind.POINT:
        return "points"
    if not m.kind.stroked:
        return "areas"
    return "results" if m.role == "result" else "construction"


def mark_geometry(m: Mark, vp: Viewport, style: Style) -> list[tuple[str, str, dict[str, str]]]:
    """What a mark draws on the canvas *vp*, without its letter: (id suffix, element, {attribute: text}).

    The one place that turns a mark's geometry into SVG attributes: the
    :class:`~construct.render.svg.Drawing` builds its
    elements from it, and the live player's sweep (:mod:`construct.live`) reads the same
    numbers at every grid value of a given without laying out a whole page.  An area is its outline and,
    when the style hatches it and the hatching meets it, a second element (suffix ``-hatch``).

    >>> from construct.render.styles import PLAIN
    >>> vp = Viewport(0.0, 1.0, 10.0, 20.0, 20.0, 0.0)
    >>> seg = Mark("s", 1, "g", MarkKind.SEGMENT, (0.0, 0.0, 1.0, 1.0), "construction", "straightedge", "exact")
    >>> mark_geometry(seg, vp, PLAIN)
    [('', 'line', {'x1': '0', 'y1': '10', 'x2': '10', 'y2': '0'})]
    >>> pt = Mark("p", 1, "P", MarkKind.POINT, (0.5, 0.5), "result", "compass", "exact")
    >>> mark_geometry(pt, vp, PLAIN)
    [('', 'circle', {'cx': '5', 'cy': '5', 'r': '2'})]
    """
    g, kind = m.geom, m.kind
    if kind is MarkKind.POINT:
        x, y = vp.xy(*g)
        return [("", "circle", {"cx": x, "cy": y, "r": fmt(point_radius(m, style))})]
    if kind is MarkKind.SEGMENT:
        (x1, y1), (x2, y2) = vp.xy(*g[:2]), vp.xy(*g[2:4])
        return [("", "line", {"x1": x1, "y1": y1, "x2": x2, "y2": y2})]
    if kind is MarkKind.CIRCLE:
        x, y = vp.xy(*g[:2])
        return [("", "circle", {"cx": x, "cy": y, "r": vp.length(g[2])})]
    if kind is MarkKind.ARC:
        return [("", "path", {"d": arc_path(vp, *g)})]
    if kind is MarkKind.CURVE:
        return [("", "path", {"d": (polyline_path if m.straight else curve_path)(vp, g)})]
    out = [("", "path", {"d": polygon_path(vp, g)})]
    if style.hatch:
        d = hatch_path(vp, g, style.hatch_spacing, *(() if m.hatch is None else (m.hatch,)))
        if d:
            out.append(("-hatch", "path", {"d": d}))
    return out


def stroke_element(factory: Any, m: Mark, attrs: dict[str, str], **kw: Any) -> Any:
    """The svgwrite element (made by *factory*) of the line, circle, arc or curve *m*, from its attributes as
    :func:`mark_geometry` gives them; *kw*: its class and id.

    >>> from construct.render import svgdoc
    >>> from construct.render.styles import PLAIN
    >>> vp = Viewport(0.0, 1.0, 10.0, 20.0, 20.0, 0.0)
    >>> seg = Mark("s", 1, "g", MarkKind.SEGMENT, (0.0, 0.0, 1.0, 1.0), "construction", "straightedge", "exact")
    >>> el = stroke_element(svgdoc.Writer().factory, seg, mark_geometry(seg, vp, PLAIN)[0][2], class_="g")
    >>> el.elementname, el.attribs["x2"]
    ('line', '10')
    """
    return _STROKES[m.kind](factory, attrs, kw)
