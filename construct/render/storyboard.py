"""A storyboard: a contact sheet of the construction's stages as one PNG, drawn by matplotlib.

The tiles are the ends of the construction's groups (at most :data:`MAX_TILES`,
thinned evenly, the last step always included); each tile shows steps 1..k,
the steps since the previous tile in the style's highlight colour, with the
step number and caption beneath.  The PNG carries no software/date metadata,
so the bytes depend only on the figure and the matplotlib version.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> sc = build_scene(get("crank").figure(parts=6))
>>> ks = storyboard_steps(sc)
>>> ks[-1] == len(sc.steps) and len(ks) <= MAX_TILES and ks == sorted(set(ks))
True
"""

from __future__ import annotations

import io
import math
import textwrap

from .scene import Scene
from .svg import PLAIN, Style

__all__ = ["storyboard_png", "storyboard_steps", "MAX_TILES"]

MAX_TILES = 20


def storyboard_steps(scene: Scene, max_tiles: int = MAX_TILES) -> list[int]:
    """The steps whose frames make the tiles: where groups (up to depth 2) end."""
    n = len(scene.steps)
    ends = set()
    for i, s in enumerate(scene.steps):
        nxt = scene.steps[i + 1] if i + 1 < n else None
        if nxt is None or nxt.group[:2] != s.group[:2]:
            ends.add(s.index)
    ks = sorted(ends)
    if len(ks) < min(8, n):  # few groups: spread single steps evenly instead
        ks = sorted({round(1 + (n - 1) * i / (min(8, n) - 1)) for i in range(min(8, n))} | set(ks))
    if len(ks) > max_tiles:
        picks = {ks[round(i * (len(ks) - 1) / (max_tiles - 1))] for i in range(max_tiles)}
        ks = sorted(picks)
    return ks


def _colour(style: Style, m, current: bool) -> str:
    if current and style.highlight:
        return style.highlight
    if m.tool in style.tool_colours:
        return style.tool_colours[m.tool]
    if m.provenance in style.provenance_colours:
        return style.provenance_colours[m.provenance]
    return style.ink if (m.role == "result" or m.kind == "point") else style.construction


def _arc_points(cx: float, cy: float, r: float, start: float, sweep: float) -> list[tuple[float, float]]:
    """An arc as a polyline (3 degrees a segment).

    Agg draws matplotlib's Arc and Circle patches of a large radius seen
    through a small tile very slowly (minutes for the inertia curve's rod
    arcs); a polyline of this fineness is indistinguishable at tile size.
    """
    n = max(4, int(abs(sweep) / math.radians(3.0)) + 1)
    return [(cx + r * math.cos(start + sweep * i / n), cy + r * math.sin(start + sweep * i / n)) for i in range(n + 1)]


def _draw(ax, scene: Scene, k: int, since: int, style: Style) -> None:
    """Steps 1..k on *ax*; marks gathered into one collection per look (fast, and few artists)."""
    from matplotlib.collections import LineCollection
    from matplotlib.patches import Polygon

    lines: dict[tuple, list] = {}
    points: dict[tuple, list] = {}
    areas = []
    for m in scene.marks:
        if m.step > k:
            break
        current = m.step > since
        c = _colour(style, m, current)
        alpha = 1.0 if current or style.earlier_opacity >= 1.0 else max(style.earlier_opacity, 0.3)
        lw = 0.35 * (style.result_width if m.role == "result" else style.construction_width)
        if current and style.highlight:
            lw = max(lw, 0.8)
        g = m.geom
        look = (c, round(lw, 3), alpha)
        if m.kind == "point":
            points.setdefault((c, alpha, 1.6 if m.role == "result" else 1.0), []).append(g)
        elif m.kind == "segment":
            lines.setdefault(look, []).append([(g[0], g[1]), (g[2], g[3])])
        elif m.kind == "curve":
            lines.setdefault(look, []).append(list(g))
        elif m.kind == "circle":
            lines.setdefault(look, []).append(_arc_points(g[0], g[1], g[2], 0.0, 2 * math.pi))
        elif m.kind == "arc":
            lines.setdefault(look, []).append(_arc_points(*g))
        elif m.kind == "area":
            areas.append((Polygon(g, closed=True), c, alpha))
    for poly, c, alpha in areas:
        poly.set(fc=style.area_fill if style.area_fill != "none" else "none", ec=c, lw=0.3,
                 hatch="////" if style.hatch else None, alpha=alpha)
        ax.add_patch(poly)
    for (c, lw, alpha), segs in sorted(lines.items(), key=lambda kv: kv[0][2]):
        ax.add_collection(LineCollection(segs, colors=c, linewidths=lw, alpha=alpha, capstyle="round"),
                          autolim=False)
    for (c, alpha, ms), pts in sorted(points.items()):
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", ms=ms, color=c, alpha=alpha, mec="none", ls="none")


def _tile_text(scene: Scene, first: int, k: int) -> str:
    """"Schritte 8–16: <group, German> / <group>" for the group the tile ends; a single step's caption else."""
    step = scene.steps[k - 1]
    span = f"{first}–{k}" if first < k else f"{k}"
    if step.group:
        g = step.group[min(1, len(step.group) - 1)]
        de = (scene.params.get("group_titles") or {}).get(g, g)
        return scene.readable(f"{span}: {de} / {g}" if de != g else f"{span}: {g}")
    de, en = scene.caption(k)
    return f"{span}: {de} / {en}"


def storyboard_png(scene: Scene, style: Style = PLAIN, *, columns: int = 4, dpi: int = 90) -> bytes:
    """The contact sheet as PNG bytes."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    ks = storyboard_steps(scene)
    rows = math.ceil(len(ks) / columns)
    x0, y0, x1, y1 = scene.bbox
    aspect = (y1 - y0) / max(x1 - x0, 1e-12)
    tile_w = 3.2
    aspect_t = min(max(aspect, 0.25), 1.2)  # height / width of a tile's drawing
    tile_h = tile_w * aspect_t + 0.62
    fig = Figure(figsize=(tile_w * columns, tile_h * rows + 0.5), dpi=dpi, facecolor=style.background)
    fig.suptitle(f"{scene.title[0]}", fontsize=9, color=style.ink, family="DejaVu Sans", y=1 - 0.12 / (tile_h * rows + 0.5))
    prev = 0
    for i, k in enumerate(ks):
        ax = fig.add_subplot(rows, columns, i + 1)
        ax.set_facecolor(style.background)
        # each tile shows the region of its top-level group (the far division ray
        # of the stroke would otherwise shrink the crank circle to a dot)
        sx0, sy0, sx1, sy1 = scene.stage_box(k)
        cx, cy = (sx0 + sx1) / 2, (sy0 + sy1) / 2
        half = max((sx1 - sx0) / 2, (sy1 - sy0) / 2 / aspect_t)
        ax.set_xlim(cx - half, cx + half)
        ax.set_ylim(cy - half * aspect_t, cy + half * aspect_t)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xticks([])
        ax.set_yticks([])
        for sp in ax.spines.values():
            sp.set_color("#bbbbbb")
            sp.set_linewidth(0.5)
        _draw(ax, scene, k, prev, style)
        text = textwrap.shorten(_tile_text(scene, prev + 1, k), 110, placeholder=" …")
        ax.set_xlabel("\n".join(textwrap.wrap(text, 52)[:2]), fontsize=6.2, color=style.ink, family="DejaVu Sans",
                      labelpad=2)
        prev = k
    fig.subplots_adjust(left=0.01, right=0.99, bottom=0.04, top=1 - 0.45 / (tile_h * rows + 0.5),
                        wspace=0.04, hspace=0.32)
    buf = io.BytesIO()
    # No "Software" (version) or date chunks: the same figure gives the same bytes.
    fig.savefig(buf, format="png", dpi=dpi, facecolor=style.background, metadata={"Software": None})
    return buf.getvalue()
