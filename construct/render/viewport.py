"""Where the drawing goes on the sheet: the map from drawing units (y up) to SVG user units (y down).

A :class:`Viewport` fits a figure's extent into a style's page (:meth:`Viewport.fit`) or
into a pixel box (:meth:`Viewport.window`); :func:`camera_transform` is the SVG transform
that shows one camera view of the layered figure on the whole sheet.

>>> vp = Viewport(0.0, 1.0, 10.0, 20.0, 20.0, 0.0)
>>> vp.px(0.0, 0.0), vp.xy(0.5, 1.0), vp.length(0.25)
((0.0, 10.0), ('5', '0'), '2.5')
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

from .styles import Style
from .svgdoc import fmt

__all__ = ["Viewport", "camera_transform", "camera_zoom"]

@dataclass(frozen=True)
class Viewport:
    """The map from drawing coordinates (y up) to SVG user units (y down)."""

    xmin: float
    ymax: float
    scale: float
    width: float
    height: float
    margin: float
    left: float = 0.0
    top: float = 0.0

    @classmethod
    def fit(cls, bbox: tuple[float, float, float, float], style: Style, caption_lines: int) -> "Viewport":
        x0, y0, x1, y1 = bbox
        inner = style.width_px - 2 * style.margin_px
        scale = inner / max(x1 - x0, 1e-12)
        # Tall figures are limited to a page-like height.
        max_h = 1.4 * style.width_px
        if (y1 - y0) * scale > max_h:
            scale = max_h / (y1 - y0)
        # Narrow figures are centred (across and, with a minimum height, down).
        left = (inner - (x1 - x0) * scale) / 2.0
        drawing_h = max((y1 - y0) * scale, style.min_drawing_px)
        top = (drawing_h - (y1 - y0) * scale) / 2.0
        height = drawing_h + 2 * style.margin_px + caption_lines * 1.45 * style.caption_size
        return cls(x0, y1, scale, style.width_px, height, style.margin_px, left, top)

    @classmethod
    def window(cls, bbox: tuple[float, float, float, float], box: tuple[float, float, float, float]) -> "Viewport":
        """Map *bbox* (drawing units) into the pixel *box* (x0, y0, x1, y1), keeping the aspect ratio."""
        x0, y0, x1, y1 = bbox
        scale = min((box[2] - box[0]) / max(x1 - x0, 1e-12), (box[3] - box[1]) / max(y1 - y0, 1e-12))
        left = box[0] + ((box[2] - box[0]) - (x1 - x0) * scale) / 2.0
        top = box[1] + ((box[3] - box[1]) - (y1 - y0) * scale) / 2.0
        return cls(x0, y1, scale, box[2] - box[0], box[3] - box[1], 0.0, left, top)

    def px(self, x: float, y: float) -> tuple[float, float]:
        return (self.margin + self.left + (x - self.xmin) * self.scale,
                self.margin + self.top + (self.ymax - y) * self.scale)

    def xy(self, x: float, y: float) -> tuple[str, str]:
        a, b = self.px(x, y)
        return fmt(a), fmt(b)

    def length(self, d: float) -> str:
        return fmt(d * self.scale)
def camera_zoom(view: Sequence[float], full: Sequence[float]) -> float:
    """How many times :func:`camera_transform` magnifies *view* to show it whole on *full*.

    >>> camera_zoom((100, 50, 480, 334), (0, 0, 960, 668)), camera_zoom((0, 0, 960, 682), (0, 0, 960, 1390))
    (2.0, 1.0)
    """
    return min(full[2] / max(view[2], 1e-12), full[3] / max(view[3], 1e-12))


def camera_transform(view: Sequence[float], full: Sequence[float]) -> str:
    """The transform that shows *view* (x, y, w, h) on the whole of *full*: translate, then scale; a view of
    another shape than *full* (the player's window's) is shown whole about its centre, as the player does.

    >>> camera_transform((100, 50, 480, 334), (0, 0, 960, 668))
    'translate(-200 -100) scale(2)'
    >>> camera_transform((0, 100, 960, 500), (0, 0, 960, 1390))
    'translate(0 345) scale(1)'
    """
    z = camera_zoom(view, full)
    tx = full[0] + full[2] / 2 - (view[0] + view[2] / 2) * z
    ty = full[1] + full[3] / 2 - (view[1] + view[3] / 2) * z
    return f"translate({fmt(tx)} {fmt(ty)}) scale({fmt(z, 5)})"
