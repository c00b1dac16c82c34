"""The magnifying glass of a teaching frame without a camera: the current group, when it is tiny in the whole
figure, drawn again enlarged in a square at the drawing's top right corner.

A style with ``zoom_below`` (a fraction of the figure) and no camera gets it in every frame whose current
group (:meth:`construct.render.scene.Scene.group_box`) is smaller than that; the camera's players show a
step's small work in their own inset instead (:mod:`construct.render.insets`).  The marks are drawn by the
drawing's own :meth:`~construct.render.svg.Drawing.mark_elements` on the square's viewport, their letters
placed radially outwards (there is no room for the whole figure's placing), the current step's groups
``cur`` and the earlier ones ``old``; the square says how much it magnifies (``× 12``).

>>> import dataclasses
>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> from construct.render.styles import PLAIN
>>> from construct.render.svg import Drawing
>>> d = Drawing(build_scene(get("crank").figure(parts=6)), dataclasses.replace(PLAIN, zoom_below=0.5))
>>> glass = magnified_inset(d, 8)  # the circle that starts the crank circle's division
>>> glass.attribs["id"], glass.elements[-1].text.startswith("×")
('inset', True)
>>> magnified_inset(d, 1) is None  # the givens: no group
True
"""

from __future__ import annotations

from typing import Any, Iterator, Protocol

from . import svgdoc
from .marks import could_show
from .scene import Mark, Scene
from .styles import Style
from .svgdoc import fmt
from .viewport import Viewport

__all__ = ["magnified_inset", "Magnified"]


class Magnified(Protocol):
    """What :func:`magnified_inset` asks of the drawing it magnifies (a :class:`~construct.render.svg.Drawing`)."""

    scene: Scene
    style: Style
    vp: Viewport
    doc: svgdoc.Writer
    region: tuple[float, float, float, float] | None
    LAYERS: tuple[str, ...]

    @property
    def drawing_height(self) -> float: ...

    def mark_elements(self, m: Mark, vp: Viewport, placed: list, mid: str | None, *,
                      end: bool = False) -> Iterator[tuple[str, Any]]: ...

    def step_group(self, k: int, elems: Any, cls: str = "", **attrs: Any) -> Any: ...


def magnified_inset(drawing: Magnified, k: int) -> Any | None:
    """``<g id="inset">``: frame k's current group magnified in a square at the top right, or None when the
    group is not smaller than the style's ``zoom_below`` of the figure (or has no extent)."""
    st = drawing.style
    box = drawing.scene.group_box(k, st.zoom_below, drawing.region)
    if box is None:
        return None
    size = max(box[2] - box[0], box[3] - box[1])
    if size <= 0:
        return None
    pad = 0.25 * size
    cx, cy = (box[0] + box[2]) / 2, (box[1] + box[3]) / 2
    half = size / 2 + pad
    region = (cx - half, cy - half, cx + half, cy + half)
    vp = drawing.vp
    m = st.margin_px
    side = min(0.4 * vp.width, 0.8 * (drawing.drawing_height - 2 * m))
    px0 = vp.width - m - side
    py0 = m
    win = Viewport.window(region, (px0, py0, px0 + side, py0 + side))
    f = drawing.doc.factory
    corner, square = (fmt(px0), fmt(py0)), (fmt(side), fmt(side))
    out = f.g(id="inset")
    clip = f.clipPath(id="inset-clip")
    clip.add(f.rect(insert=corner, size=square))
    out.add(clip)
    out.add(f.rect(insert=corner, size=square, class_="inset"))
    inner = f.g(clip_path="url(#inset-clip)")
    old = "old" if st.earlier_opacity < 1.0 else ""
    placed: list = []
    by_layer: dict[str, list[tuple[int, Any]]] = {name: [] for name in drawing.LAYERS}
    for mk in drawing.scene.marks:
        if mk.step > k:
            break
        if not could_show(mk, region):
            continue
        for layer, elem in drawing.mark_elements(mk, win, placed, None):
            by_layer[layer].append((mk.step, elem))
    for name in drawing.LAYERS:
        for s, elem in by_layer[name]:
            inner.add(drawing.step_group(s, [elem], "cur" if s == k else old))
    out.add(inner)
    zoom = win.scale / vp.scale
    out.add(f.text(f"× {zoom:.0f}", x=[fmt(px0 + 6)], y=[fmt(py0 + side - 6)], class_="cap grp"))
    return out
