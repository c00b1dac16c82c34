"""A storyboard: a contact sheet of the construction's stages.

The tiles are the ends of the construction's groups (at most :data:`MAX_TILES`,
thinned evenly, the last step always included); each tile shows steps 1..k
of its stage's region, the steps since the previous tile in the style's
highlight colour, with the step numbers and the group's title beneath.

:func:`storyboard_svg` (what a replay and the gallery write) is made from the
layered figure's own elements: each step group is defined once, in the
delta of the tile that adds it, and tile i shows the deltas 1..i through
``<use>`` -- a handful of references per tile, no copy of the drawing and
no rasteriser.  (A figure on a matplotlib Axes is
:func:`construct.render.plotting.plot_figure`.)

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> sc = build_scene(get("crank").figure(parts=6))
>>> ks = storyboard_steps(sc)
>>> ks[-1] == len(sc.steps) and len(ks) <= MAX_TILES and ks == sorted(set(ks))
True
>>> sheet = storyboard_svg(Drawing(sc))
>>> sheet.count("<use ") > len(ks) and sheet.count('id="s0001-O"') == 1
True
"""

from __future__ import annotations

import math

from .camera import views_box
from .scene import Scene
from .svg import Drawing
from .svgdoc import fmt
from .wrapping import shorten, wrap

__all__ = ["storyboard_svg", "storyboard_steps", "MAX_TILES"]

MAX_TILES = 12
TILE_W = 3.2  # inches
CAPTION_H = 0.62  # inches below each tile's drawing


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


#: Tile width of the SVG sheet (px) and its caption's font size.
TILE_PX, TILE_FONT = 300.0, 10.0


def storyboard_svg(drawing: Drawing, *, columns: int = 4) -> str:
    """The contact sheet as SVG text, made of the *drawing*'s elements (each defined once)."""
    scene, style, doc = drawing.scene, drawing.style, drawing.doc
    f = doc.factory
    ks = storyboard_steps(scene)
    rows = math.ceil(len(ks) / columns)
    x0, y0, x1, y1 = scene.bbox
    aspect_t = min(max((y1 - y0) / max(x1 - x0, 1e-12), 0.25), 1.2)
    gap, head = 8.0, 30.0
    tw, th = TILE_PX, TILE_PX * aspect_t
    cell_h = th + 2.6 * TILE_FONT + gap
    width, height = columns * (tw + gap) + gap, head + rows * cell_h
    dwg = doc.drawing(size=(fmt(width), fmt(height)), viewBox=f"0 0 {fmt(width)} {fmt(height)}")
    css = (style.css() + (f"\n{drawing.extra_css}" if drawing.extra_css else "") + f"\n.sheet{{fill:{style.ink};font-family:'DejaVu Sans',Arial,sans-serif;"
           f"font-size:{fmt(TILE_FONT)}px;text-anchor:middle}}\n.sheet.title{{font-size:{fmt(1.3 * TILE_FONT)}px}}"
           f"\n.frame{{fill:{style.background};stroke:#bbbbbb;stroke-width:0.5}}")
    dwg.add(f.style("\n" + css + "\n"))
    dwg.add(f.rect(insert=("0", "0"), size=(fmt(width), fmt(height)), id="background", fill=style.background))
    dwg.add(f.text(scene.title[0], x=[fmt(width / 2)], y=[fmt(head * 0.6)], class_="sheet title"))
    # Each tile's new steps, per layer, defined once; later tiles refer to them.
    defs = dwg.defs  # svgwrite's own <defs> of the drawing
    bounds = [0] + ks
    present: set[tuple[int, str]] = set()
    for i in range(1, len(bounds)):
        for name in drawing.LAYERS:
            done = len(drawing.step_runs(name, bounds[i - 1]))
            upto = len(drawing.step_runs(name, bounds[i]))
            if upto > done:
                delta = f.g(id=f"tile{i}-{name}")
                present.add((i, name))
                plain = drawing.plain_groups(name)
                for j in range(done, upto):
                    k, elems = drawing.groups[name][j]
                    # the whole figure's group where it is the same (no class but "step"): written once for both
                    same = drawing.step_class(k, 0, mark_steps=False, layer=name) == ""
                    delta.add(plain[j] if same else drawing.step_group(k, elems))
                defs.add(delta)
    if style.highlight:
        tint = f.filter(id="now")
        tint.feFlood(flood_color=style.highlight, result="ink")
        tint.feComposite(in_="ink", in2="SourceAlpha", operator="in")
        defs.add(tint)

    vp = drawing.vp
    for i, k in enumerate(ks, start=1):
        col, row = (i - 1) % columns, (i - 1) // columns
        tx, ty = gap + col * (tw + gap), head + row * cell_h
        if style.camera:
            # the camera's views of the tile's steps, taken in together as the animation shows a stage (but for
            # the first step's: it shows the whole figure by convention, not for its work)
            v = views_box([drawing.camera_view(j) for j in range(max(bounds[i - 1] + 1, min(2, k)), k + 1)],
                          drawing.full_view)
            half = max(v[2] / 2, v[3] / 2 / aspect_t, 1e-12)
            px, py = v[0] + v[2] / 2, v[1] + v[3] / 2
        else:
            sx0, sy0, sx1, sy1 = scene.stage_box(k)
            cx, cy = (sx0 + sx1) / 2, (sy0 + sy1) / 2
            half = max((sx1 - sx0) / 2, (sy1 - sy0) / 2 / aspect_t, 1e-12) * vp.scale
            px, py = vp.px(cx, cy)
        box = f"{fmt(px - half)} {fmt(py - half * aspect_t)} {fmt(2 * half)} {fmt(2 * half * aspect_t)}"
        dwg.add(f.rect(insert=(fmt(tx), fmt(ty)), size=(fmt(tw), fmt(th)), class_="frame"))
        extra = {}
        if style.camera:
            from .camera import level

            # the level of the tile's own magnification (its box in the tile's shape)
            full = drawing.full_view
            extra["class_"] = f"zl{level(max(full[2], full[3] / aspect_t) / (2 * half))}"
        view = f.svg(insert=(fmt(tx), fmt(ty)), size=(fmt(tw), fmt(th)), viewBox=box, **extra)
        earlier = f.g(opacity=fmt(style.earlier_opacity)) if style.earlier_opacity < 1.0 else f.g()
        for name in drawing.LAYERS:
            for j in range(1, i):
                if (j, name) in present:
                    earlier.add(f.use(f"#tile{j}-{name}"))
        view.add(earlier)
        now = f.g(filter="url(#now)") if style.highlight else f.g()
        # the letters stay letters: the highlight's flood through their alpha would fill their halos too
        letters = f.g()
        for name in drawing.LAYERS:
            if (i, name) in present:
                (letters if name == "labels" else now).add(f.use(f"#tile{i}-{name}"))
        view.add(now)
        view.add(letters)
        dwg.add(view)
        text = shorten(_tile_text(scene, bounds[i - 1] + 1, k), 110, placeholder=" …")
        for n, line in enumerate(wrap(text, 54, break_on_hyphens=True)[:2]):
            dwg.add(f.text(line, x=[fmt(tx + tw / 2)], y=[fmt(ty + th + (n + 1.1) * 1.2 * TILE_FONT)],
                           class_="sheet"))
    return doc.text(dwg)
