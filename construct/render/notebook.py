"""Inline display in Jupyter: a figure's SVG for ``_repr_svg_``.

Hook it onto :class:`construct.constructions.Figure` with
``Figure._repr_svg_ = construct.render.notebook.figure_repr_svg`` (or a
method that returns ``figure_repr_svg(self)``); Jupyter then shows every
built figure as its final drawing in the teaching style.

>>> from construct.constructions import get
>>> svg = figure_repr_svg(get("crank").figure(parts=6))
>>> svg.startswith("<svg") and svg.rstrip().endswith("</svg>")
True
"""

from __future__ import annotations

from typing import Any

__all__ = ["figure_repr_svg", "figure_svg"]


def figure_svg(figure: Any, style: str = "teaching", upto: int | None = None) -> str:
    """The figure (all steps, or steps 1..upto) as SVG text in the named style."""
    from .scene import build_scene
    from .styles import STYLES
    from .svg import render_svg

    st = STYLES[style]
    scene = build_scene(figure, plate=st.plate and upto is None, ending=st.camera)
    return render_svg(scene, upto=upto, style=st)


def figure_repr_svg(figure: Any) -> str:
    """What Jupyter shows: the SVG without the XML declaration (it is embedded in the page)."""
    text = figure_svg(figure)
    return text.split("?>", 1)[1].lstrip() if text.startswith("<?xml") else text
