"""matplotlib for what it is good at: a figure on an Axes, and a table plotted the way the book draws it.

As in ``shapely.plotting``, matplotlib is imported inside the functions that
need it, the Axes is the caller's (``ax=None`` makes a new figure without
pyplot), and nothing process-wide is touched: no backend is chosen, no
global style set.

>>> from construct import get
>>> ax = plot_figure(get("crank").figure(parts=6, rod_ratio=4.0), upto=20)
>>> len(ax.collections) > 0, ax.get_aspect()
(True, 1.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping, Sequence

from .scene import Mark, MarkKind, Scene, build_scene

__all__ = ["plot_figure", "TablePlot", "plot_table", "mark_points"]


def _arc_points(cx: float, cy: float, r: float, start: float, sweep: float, fine: float) -> list[tuple[float, float]]:
    """An arc as a polyline whose chords stay within *fine* (drawing units) of the arc, 3 to 360 chords."""
    step = 2.0 * math.sqrt(max(2.0 * fine / max(r, 1e-12), 1e-12))  # chord angle for a sagitta of *fine*
    n = min(360, max(3, int(abs(sweep) / min(step, math.radians(6.0))) + 1))
    return [(cx + r * math.cos(start + sweep * i / n), cy + r * math.sin(start + sweep * i / n)) for i in range(n + 1)]


def mark_points(mark: Mark, fine: float) -> tuple[str, list[tuple[float, float]]]:
    """A mark as ``("point" | "line" | "area", points)``: what a plotting library draws it with.

    Circles and arcs become polylines within *fine* of the curve; curves are their points in order.

    >>> kind, pts = mark_points(Mark("m", 1, "k", MarkKind.CIRCLE, (0.0, 0.0, 1.0), "construction", "compass", "exact"), 1e-3)
    >>> kind, math.dist(pts[0], pts[-1]) < 1e-12, max(abs(math.hypot(x, y) - 1.0) for x, y in pts) < 1e-12
    ('line', True, True)
    """
    return _PLOTTED[mark.kind](mark.geom, fine)


#: What a plotting library draws a mark with, by kind (:func:`mark_points`); a curve is its points, joined in order.
_PLOTTED: dict[MarkKind, Any] = {
    MarkKind.POINT: lambda g, fine: ("point", [g]),
    MarkKind.SEGMENT: lambda g, fine: ("line", [(g[0], g[1]), (g[2], g[3])]),
    MarkKind.CIRCLE: lambda g, fine: ("line", _arc_points(g[0], g[1], g[2], 0.0, 2 * math.pi, fine)),
    MarkKind.ARC: lambda g, fine: ("line", _arc_points(*g, fine)),
    MarkKind.CURVE: lambda g, fine: ("line", list(g)),
    MarkKind.AREA: lambda g, fine: ("area", list(g)),
}


def plot_figure(figure: Any, ax: Any = None, *, style: str = "plain", upto: int | None = None,
                labels: bool = True) -> Any:
    """Draw a figure (all steps, or steps 1..upto) on a matplotlib Axes and return the Axes.

    Lines by role as the SVG styles draw them (results heavy, construction thin), areas filled lightly,
    points as dots with their letters.  The Axes keeps the drawing's proportions (aspect 1) and has no
    frame or ticks, as a plate has none.
    """
    from matplotlib.collections import LineCollection, PolyCollection

    from .styles import STYLES

    if style not in STYLES:
        from ..kernel.errors import InvalidParameter

        raise InvalidParameter(f"unknown style {style!r}; choose one of {', '.join(sorted(STYLES))}")
    st = STYLES[style]
    scene: Scene = build_scene(figure)
    if ax is None:
        from matplotlib.figure import Figure

        ax = Figure(figsize=(8, 6)).add_subplot()
    x0, y0, x1, y1 = scene.bbox
    fine = max(x1 - x0, y1 - y0, 1e-12) / 2000.0
    marks = scene.marks if upto is None else [m for m in scene.marks if m.step <= upto]
    lines: dict[tuple[str, float], list] = {}
    areas: list = []
    points: list = []
    for m in marks:
        kind, pts = mark_points(m, fine)
        if kind == "point":
            points.append((m, pts[0]))
        elif kind == "area":
            areas.append(pts)
        else:
            result = m.role == "result"
            key = (st.ink if result else st.construction, st.result_width if result else st.construction_width)
            lines.setdefault(key, []).append(pts)
    if areas:
        ax.add_collection(PolyCollection(areas, facecolors=st.construction, alpha=0.25, edgecolors="none"))
    for (colour, width), segs in lines.items():
        ax.add_collection(LineCollection(segs, colors=colour, linewidths=width))
    if points:
        ax.scatter([p[0] for _, p in points], [p[1] for _, p in points], s=6, color=st.ink, zorder=3)
        if labels:
            for m, (x, y) in points:
                if m.label:
                    ax.annotate(m.label, (x, y), xytext=(3, 3), textcoords="offset points", fontsize=7,
                                color=st.ink)
    pad = 0.03 * max(x1 - x0, y1 - y0, 1e-12)
    ax.set_xlim(x0 - pad, x1 + pad)
    ax.set_ylim(y0 - pad, y1 + pad)
    ax.set_aspect(1.0)
    ax.set_axis_off()
    return ax


@dataclass(frozen=True)
class TablePlot:
    """How the book draws a table: which column runs along the abscissa, which curves stand over it.

    *curves* pairs a column with its legend text; *label_by* splits the rows into one curve per value of that
    column (the acceleration table's rod ratios); *mean_of* draws the mean of that column as a dashed line
    (the tangential-pressure diagram's mean line).  Axis texts are in the book's symbols, German / English.
    """

    x: str
    curves: tuple[tuple[str, str], ...]
    xlabel: str
    ylabel: str
    title: str
    label_by: str | None = None
    #: How the legend names *label_by*'s values (the book's symbol), e.g. "L/r".
    label_name: str = ""
    mean_of: str | None = None
    points_only: bool = False


def plot_table(plot: TablePlot, columns: Sequence[str], rows: Sequence[Mapping[str, Any]], ax: Any = None) -> Any:
    """Plot a table's rows as *plot* says on a matplotlib Axes (a new one when *ax* is None); return the Axes.

    >>> rows = [{"w": w, "x": 1 - math.cos(math.radians(w))} for w in range(0, 181, 10)]
    >>> ax = plot_table(TablePlot("w", (("x", "x/r"),), "ω", "x/r", "Kolbenweg"), ("w", "x"), rows)
    >>> [round(float(v), 6) for v in ax.lines[0].get_ydata()[[0, -1]]]
    [0.0, 2.0]
    """
    if ax is None:
        from matplotlib.figure import Figure

        ax = Figure(figsize=(7, 4.5)).add_subplot()
    groups: dict[Any, list] = {}
    for r in rows:
        groups.setdefault(r[plot.label_by] if plot.label_by else None, []).append(r)
    for key, group in groups.items():
        xs = [float(r[plot.x]) for r in group]
        for column, text in plot.curves:
            if column not in columns:
                continue
            label = text if key is None else f"{text}, {plot.label_name or plot.label_by} = {key:g}"
            ys = [float(r[column]) for r in group]
            if plot.points_only:
                ax.plot(xs, ys, "o", label=label)
            else:
                ax.plot(xs, ys, label=label)
    if plot.mean_of and len(rows) > 1:
        # the planimeter's mean height: the area under the curve (trapezoids) over its base
        xs = [float(r[plot.x]) for r in rows]
        ys = [float(r[plot.mean_of]) for r in rows]
        area = sum((xs[i + 1] - xs[i]) * (ys[i] + ys[i + 1]) / 2 for i in range(len(xs) - 1))
        mean = area / (xs[-1] - xs[0])
        ax.axhline(mean, linestyle="--", linewidth=0.8, color="0.3", label=f"Mittellinie / mean = {mean:.4g}")
    ax.axhline(0.0, linewidth=0.5, color="0.6")
    ax.set_xlabel(plot.xlabel)
    ax.set_ylabel(plot.ylabel)
    ax.set_title(plot.title)
    ax.legend(fontsize=8)
    ax.grid(True, linewidth=0.3)
    return ax
