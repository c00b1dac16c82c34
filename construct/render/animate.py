"""One self-contained animated SVG that plays the steps in order, without script.

Each step's elements sit in one ``<g>`` per layer; SMIL ``<set>`` elements
hide a step until its time comes, and a clock animation restarts the whole
play when it ends (``begin="0s;clock.end"``).  Browsers play SMIL in a page
and inside ``<img>``; renderers without animation (cairosvg, librsvg) show
the final figure with its title, since everything is visible by default.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> svg = animated_svg(build_scene(get("crank").figure(parts=6)))
>>> svg.count('attributeName="visibility"') > 10 and "<script" not in svg
True
"""

from __future__ import annotations

from .svg import PLAIN, Drawing, Style, fmt, wrap

__all__ = ["animated_svg", "step_seconds", "STEP_GROUP_CSS"]

#: Looks of the step groups, for players that switch classes on a whole step.
STEP_GROUP_CSS = """g.hid{display:none}
g.cur>*{stroke:%(hl)s;stroke-width:%(hw)s}
g.cur>.pt,g.cur>.lb{fill:%(hl)s;stroke:none}
g.old{opacity:%(op)s}"""


def step_seconds(n_steps: int) -> float:
    """Time per step: a second for short constructions, a minute in all for long ones (at least 0.15 s)."""
    return max(0.15, min(1.0, 60.0 / max(n_steps, 1)))


def group_css(style: Style) -> str:
    return STEP_GROUP_CSS % {"hl": style.highlight or "inherit", "hw": fmt(style.highlight_width),
                             "op": fmt(style.earlier_opacity)}


def step_groups(drawing: Drawing, layer: str) -> list[tuple[int, list[str]]]:
    """The layer's elements, gathered by step: [(k, [element, ...]), ...] in step order."""
    out: list[tuple[int, list[str]]] = []
    for k, head, tail in drawing.layers[layer]:
        if not out or out[-1][0] != k:
            out.append((k, []))
        out[-1][1].append(head + tail)
    return out


def animated_svg(scene, style: Style = PLAIN, *, title: tuple[str, str] | None = None) -> str:
    d = Drawing(scene, style)
    n = len(scene.steps)
    dt = step_seconds(n)
    hold = 4.0
    total = n * dt + hold
    marks_steps = style.highlight is not None or style.earlier_opacity < 1.0
    parts = [d.header(extra_css=group_css(style) if marks_steps else "")]
    parts.append(f'<rect id="clock-face" x="0" y="0" width="0" height="0">'
                 f'<animate id="clock" attributeName="x" from="0" to="0" begin="0s;clock.end" dur="{fmt(total)}s"/>'
                 f"</rect>\n")
    for layer in d.LAYERS:
        parts.append(f'<g id="{layer}">\n')
        for k, elems in step_groups(d, layer):
            start = (k - 1) * dt
            parts.append(f'<g id="{layer}-{k}">')
            if k > 1:
                parts.append(f'<set attributeName="visibility" to="hidden" begin="clock.begin" dur="{fmt(start)}s"/>')
            if marks_steps and style.highlight:
                parts.append(f'<set attributeName="class" to="cur" begin="clock.begin+{fmt(start)}s" dur="{fmt(dt)}s"/>')
            if marks_steps and style.earlier_opacity < 1.0 and k < n:
                parts.append(f'<set attributeName="class" to="old" begin="clock.begin+{fmt(k * dt)}s" '
                             f'dur="{fmt((n - k) * dt)}s"/>')
            parts.append("\n" + "".join(e + "\n" for e in elems) + "</g>\n")
        parts.append("</g>\n")
    # Captions: each step's while it is drawn, the figure's title otherwise (and in still renderers).
    st = style
    width = st.width_px - 2 * st.margin_px
    lines = [(("de" if i == 0 else "en"), t) for i, line in enumerate(title or scene.title)
             for t in wrap(line, width, st.caption_size)][: d.n_caption]
    title_svg = d.caption_svg(lines).replace('<g id="caption">', '<g id="title">'
                                             f'<set attributeName="visibility" to="hidden" begin="clock.begin" '
                                             f'dur="{fmt(n * dt)}s"/>', 1)
    parts.append(title_svg)
    parts.append('<g id="step-captions">\n')
    for k in range(1, n + 1):
        cap = d.caption_svg(d.frame_caption_lines(k)).replace(
            '<g id="caption">', f'<g id="caption-{k}" visibility="hidden">'
            f'<set attributeName="visibility" to="visible" begin="clock.begin+{fmt((k - 1) * dt)}s" dur="{fmt(dt)}s"/>', 1)
        parts.append(cap)
    parts.append("</g>\n</svg>\n")
    return "".join(parts)
