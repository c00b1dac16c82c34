"""SVG frames of a scene: one per step and the final figure.

The style is a separate value (:class:`Style`): the construction never knows
how it is drawn.  Output is deterministic: numbers with a fixed number of
decimals, ids from step index and object name, no timestamps, marks in step
order, so the same figure gives the same bytes on every run and machine.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> sc = build_scene(get("crank").figure(parts=6))
>>> svg = render_svg(sc, upto=3)
>>> svg.startswith("<?xml") and 'id="s0003-r"' not in svg and "Schritt 3" in svg
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Iterable, Mapping

import svgwrite

from .scene import Mark, Scene, label_offset_direction

__all__ = ["Style", "PLAIN", "render_svg", "fmt", "Viewport"]


def fmt(v: float) -> str:
    """Fixed-point with three decimals, trailing zeros trimmed; never '-0'."""
    text = f"{v:.3f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


@dataclass(frozen=True)
class Style:
    """How marks look.  Colours are CSS colours, widths in px at the drawing scale."""

    name: str = "plain"
    background: str = "#ffffff"
    ink: str = "#000000"
    construction: str = "#8a8a8a"
    construction_width: float = 0.7
    result_width: float = 1.8
    given_width: float = 1.0
    point_radius: float = 2.0
    aux_point_radius: float = 1.1
    label_font: str = "Georgia, 'DejaVu Serif', serif"
    label_size: float = 13.0
    label_italic: bool = False
    caption_font: str = "'DejaVu Sans', Arial, sans-serif"
    caption_size: float = 13.0
    #: Colour of marks by provenance of what they show (approximate in a warm tone).
    provenance_colours: Mapping[str, str] = field(default_factory=lambda: {"approximate": "#b35900", "trial": "#7a3fb0",
                                                                            "neusis": "#00708a"})
    show_caption: bool = True
    highlight: str | None = None  # colour of the current step's marks in frames (None: no highlight)
    width_px: float = 960.0
    margin_px: float = 24.0


PLAIN = Style()


@dataclass(frozen=True)
class Viewport:
    """The map from drawing coordinates (y up) to SVG user units (y down)."""

    xmin: float
    ymax: float
    scale: float
    width: float
    height: float
    margin: float

    @classmethod
    def fit(cls, bbox: tuple[float, float, float, float], style: Style, caption_lines: int) -> "Viewport":
        x0, y0, x1, y1 = bbox
        inner = style.width_px - 2 * style.margin_px
        scale = inner / max(x1 - x0, 1e-12)
        # Tall figures are limited to a page-like height.
        max_h = 1.4 * style.width_px
        if (y1 - y0) * scale > max_h:
            scale = max_h / (y1 - y0)
        height = (y1 - y0) * scale + 2 * style.margin_px + caption_lines * 1.6 * style.caption_size
        return cls(x0, y1, scale, style.width_px, height, style.margin_px)

    def xy(self, x: float, y: float) -> tuple[str, str]:
        return fmt(self.margin + (x - self.xmin) * self.scale), fmt(self.margin + (self.ymax - y) * self.scale)

    def length(self, d: float) -> str:
        return fmt(d * self.scale)


def render_svg(scene: Scene, *, upto: int | None = None, style: Style = PLAIN,
               caption: tuple[str, str] | None = None) -> str:
    """The figure after steps 1..upto (all steps when None), as SVG text."""
    n_steps = len(scene.steps)
    k = n_steps if upto is None else max(0, min(upto, n_steps))
    if caption is None:
        if upto is None:
            caption = scene.title
        else:
            step = scene.steps[k - 1] if k else None
            caption = (f"Schritt {k} von {n_steps}: {step.caption.de}" if step else f"Schritt 0 von {n_steps}",
                       f"Step {k} of {n_steps}: {step.caption.en}" if step else f"Step 0 of {n_steps}")
    lines = 2 if style.show_caption else 0
    vp = Viewport.fit(scene.bbox, style, lines)
    dwg = svgwrite.Drawing(size=(fmt(vp.width), fmt(vp.height)), viewBox=f"0 0 {fmt(vp.width)} {fmt(vp.height)}",
                           debug=False, profile="full")
    dwg.add(dwg.rect(insert=(0, 0), size=(fmt(vp.width), fmt(vp.height)), fill=style.background, id="background"))
    marks = scene.upto(k)
    layers = {
        "construction": dwg.g(id="construction", fill="none", stroke=style.construction,
                              stroke_width=fmt(style.construction_width), stroke_linecap="round"),
        "result": dwg.g(id="results", fill="none", stroke=style.ink, stroke_width=fmt(style.result_width),
                        stroke_linecap="round"),
        "points": dwg.g(id="points", fill=style.ink, stroke="none"),
        "labels": dwg.g(id="labels", fill=style.ink, font_family=style.label_font,
                        font_size=fmt(style.label_size)),
    }
    placed: list[tuple[float, float, float, float]] = []
    for m in marks:
        current = upto is not None and m.step == k
        _draw_mark(dwg, layers, vp, m, style, current, placed)
    for g in layers.values():
        dwg.add(g)
    if style.show_caption and caption:
        cap = dwg.g(id="caption", fill=style.ink, font_family=style.caption_font, font_size=fmt(style.caption_size))
        y0 = vp.height - style.margin_px * 0.5 - 1.6 * style.caption_size
        for i, text in enumerate(caption):
            cap.add(dwg.text(text, insert=(fmt(style.margin_px), fmt(y0 + i * 1.4 * style.caption_size))))
        dwg.add(cap)
    return dwg.tostring().replace("><", ">\n<") + "\n"


def _stroke_for(m: Mark, style: Style, current: bool) -> dict:
    attrs: dict = {}
    if current and style.highlight:
        attrs["stroke"] = style.highlight
    return attrs


def _label_box(x: float, y: float, text: str, size: float) -> tuple[float, float, float, float]:
    w = 0.62 * size * len(text)
    return (x - w / 2, y - 0.8 * size, x + w / 2, y + 0.2 * size)


def _overlaps(box, placed) -> bool:
    x0, y0, x1, y1 = box
    return any(x0 < b[2] and b[0] < x1 and y0 < b[3] and b[1] < y1 for b in placed)


def _draw_mark(dwg, layers, vp: Viewport, m: Mark, style: Style, current: bool, placed: list) -> None:
    cls = f"{m.role} {m.tool} {m.provenance}" + (" current" if current else "")
    if m.kind == "point":
        aux = "." in m.name and not m.label
        r = style.aux_point_radius if aux else style.point_radius
        fill = style.highlight if current and style.highlight else style.provenance_colours.get(m.provenance, style.ink)
        cx, cy = vp.xy(*m.geom)
        layers["points"].add(dwg.circle(center=(cx, cy), r=fmt(r), id=m.id, class_=cls, fill=fill))
        if m.label:
            # Letters go radially outwards (below the stroke line for points on it);
            # a letter that would overprint an earlier one tries the other side, then is left out.
            dx, dy = label_offset_direction(m.geom)
            off = style.label_size * 0.9
            px = vp.margin + (m.geom[0] - vp.xmin) * vp.scale
            py = vp.margin + (vp.ymax - m.geom[1]) * vp.scale
            for sign in (1.0, -1.0):
                lx, ly = px + sign * dx * off, py - sign * dy * off + style.label_size * 0.35
                box = _label_box(lx, ly, m.label, style.label_size)
                if not _overlaps(box, placed):
                    break
            else:
                return
            placed.append(box)
            t = dwg.text(m.label, insert=(fmt(lx), fmt(ly)), id=f"{m.id}-label", text_anchor="middle")
            if style.label_italic:
                t["font-style"] = "italic"
            layers["labels"].add(t)
        return
    layer = layers["result"] if m.role == "result" else layers["construction"]
    attrs = _stroke_for(m, style, current)
    if m.kind == "segment":
        x1, y1 = vp.xy(m.geom[0], m.geom[1])
        x2, y2 = vp.xy(m.geom[2], m.geom[3])
        layer.add(dwg.line(start=(x1, y1), end=(x2, y2), id=m.id, class_=cls, **attrs))
    elif m.kind == "circle":
        cx, cy = vp.xy(m.geom[0], m.geom[1])
        layer.add(dwg.circle(center=(cx, cy), r=vp.length(m.geom[2]), id=m.id, class_=cls, **attrs))
    elif m.kind == "arc":
        layer.add(dwg.path(d=arc_path(vp, *m.geom), id=m.id, class_=cls, **attrs))
    elif m.kind == "curve":
        layer.add(dwg.path(d=curve_path(vp, m.geom), id=m.id, class_=cls, **attrs))


def arc_path(vp: Viewport, cx: float, cy: float, r: float, start: float, sweep: float) -> str:
    """An SVG arc path; y is flipped, so counter-clockwise in the plane is sweep-flag 0."""
    x0, y0 = vp.xy(cx + r * math.cos(start), cy + r * math.sin(start))
    x1, y1 = vp.xy(cx + r * math.cos(start + sweep), cy + r * math.sin(start + sweep))
    large = 1 if sweep > math.pi else 0
    rr = vp.length(r)
    return f"M {x0} {y0} A {rr} {rr} 0 {large} 0 {x1} {y1}"


def curve_path(vp: Viewport, pts: tuple) -> str:
    """A smooth curve through the points (Catmull-Rom as cubic Béziers)."""
    P = [(vp.margin + (x - vp.xmin) * vp.scale, vp.margin + (vp.ymax - y) * vp.scale) for x, y in pts]
    if len(P) < 2:
        return ""
    d = [f"M {fmt(P[0][0])} {fmt(P[0][1])}"]
    for i in range(len(P) - 1):
        p0 = P[i - 1] if i > 0 else P[i]
        p1, p2 = P[i], P[i + 1]
        p3 = P[i + 2] if i + 2 < len(P) else P[i + 1]
        c1 = (p1[0] + (p2[0] - p0[0]) / 6.0, p1[1] + (p2[1] - p0[1]) / 6.0)
        c2 = (p2[0] - (p3[0] - p1[0]) / 6.0, p2[1] - (p3[1] - p1[1]) / 6.0)
        d.append(f"C {fmt(c1[0])} {fmt(c1[1])} {fmt(c2[0])} {fmt(c2[1])} {fmt(p2[0])} {fmt(p2[1])}")
    return " ".join(d)
