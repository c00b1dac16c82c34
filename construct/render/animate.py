"""One self-contained animated SVG that plays the steps in order, without script.

The document is the layered figure (:meth:`construct.render.svg.Drawing.layered`)
with timing: every step group ``<g class="step" data-step="k">`` carries SMIL
``<set>`` elements that hide it until its time comes and mark it current, then
earlier; a clock animation restarts the whole play when it ends
(``begin="0s;clock.end"``).  Browsers play SMIL in a page and inside
``<img>``; renderers without animation (cairosvg, librsvg) show the final
figure with its title, since everything is visible by default.

A step stays :data:`STEP_SECONDS` on screen by default: long enough to read
its caption (the player lets the reader choose the pace).  A construction of
more than :data:`MAX_STAGES` steps is animated a group at a time (the 360-part
crank has 7292 steps: three hours at that pace).

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> svg = animated_svg(build_scene(get("crank").figure(parts=6)))
>>> svg.count('attributeName="visibility"') > 10 and "<script" not in svg
True
>>> step_seconds(6) >= 1.5 and step_seconds(7000) >= 1.5
True
"""

from __future__ import annotations

from typing import Any

from .svg import PLAIN, Drawing, Style, fmt, group_caption

__all__ = ["animated_svg", "step_seconds", "stages", "STEP_GROUP_CSS", "STEP_SECONDS", "MAX_STAGES"]

#: Seconds each step is shown in the animated SVG (a caption takes that long to read).
STEP_SECONDS = 1.5
#: Up to this many steps the animation shows each step; longer constructions a group at a time.
MAX_STAGES = 1000

#: Looks of the step groups, for players that switch classes on a whole step.
STEP_GROUP_CSS = """g.hid{display:none}
g.cur>*,g.stage.cur>g>*{stroke:%(hl)s;stroke-width:%(hw)s}
g.cur>.pt,g.cur>.lb,g.stage.cur>g>.pt,g.stage.cur>g>.lb{fill:%(hl)s;stroke:none}
g.old{opacity:%(op)s}"""


def step_seconds(n_steps: int, seconds: float = STEP_SECONDS) -> float:
    """Time per step of the animation: *seconds* whatever the length (the pace is the reader's, not the figure's)."""
    return max(float(seconds), 0.05)


def group_css(style: Style) -> str:
    return STEP_GROUP_CSS % {"hl": style.highlight or "inherit", "hw": fmt(style.highlight_width),
                             "op": fmt(style.earlier_opacity)}


def step_groups(drawing: Drawing, layer: str) -> list[tuple[int, list[Any]]]:
    """The layer's elements, gathered by step: [(k, [element, ...]), ...] in step order."""
    return drawing.groups[layer]


def stages(drawing: Drawing, most: int = MAX_STAGES) -> list[int]:
    """The last step of each stage the animation shows: every step, or for long constructions group ends.

    Up to *most* steps each step is a stage.  Beyond that a step-by-step
    animation would run for hours at a readable pace, so a stage is a group
    (the ends of the groups up to depth 2, thinned evenly to *most*).
    """
    from .output import frame_steps

    n = len(drawing.scene.steps)
    if n <= most:
        return list(range(1, n + 1))
    ends = frame_steps(drawing.scene, "groups")
    if len(ends) > most:
        ends = sorted({ends[round(i * (len(ends) - 1) / (most - 1))] for i in range(most)})
    return ends


def _stage_caption(drawing: Drawing, first: int, last: int) -> list[tuple[str, str]]:
    """The caption of a stage of several steps: its group and the span of steps."""
    if first == last:
        return [line for line in drawing.frame_caption_lines(last) if line[0] != "grp"]
    n = len(drawing.scene.steps)
    group = group_caption(drawing.scene, last)
    return [("de", f"Schritte {first}–{last} von {n}: {group}"), ("en", f"Steps {first}–{last} of {n}")]


def animated_svg(scene, style: Style = PLAIN, *, title: tuple[str, str] | None = None,
                 drawing: Drawing | None = None, seconds: float = STEP_SECONDS) -> str:
    """The animation of *scene* (or of the already laid-out *drawing*) as SVG text."""
    d = drawing or Drawing(scene, style)
    style = d.style
    f = d.doc.factory
    ends = stages(d)
    n = len(ends)
    dt = step_seconds(n, seconds)
    hold = 4.0
    total = n * dt + hold
    marks_steps = style.highlight is not None or style.earlier_opacity < 1.0
    dwg = d.document(extra_css=group_css(style) if marks_steps else "")
    clock = f.rect(insert=("0", "0"), size=("0", "0"), id="clock-face")
    clock.add(f.animate(id="clock", attributeName="x", from_="0", to="0", begin="0s;clock.end", dur=f"{fmt(total)}s"))
    dwg.add(clock)
    def timing(i: int, kind: str, fade: int | None = None) -> list[Any]:
        """The <set>s that show stage i's group (of class *kind*) at its time, then mark it current and earlier;
        after stage *fade* (its group finished) it fades to the end of the play, its results staying."""
        start = (i - 1) * dt
        sets = []
        if i > 1:
            sets.append(f.set(attributeName="visibility", to="hidden", begin="clock.begin", dur=f"{fmt(start)}s"))
        if marks_steps and style.highlight:
            sets.append(f.set(attributeName="class", to=f"{kind} cur", begin=f"clock.begin+{fmt(start)}s",
                              dur=f"{fmt(dt)}s"))
        until = n if fade is None else fade
        if marks_steps and style.earlier_opacity < 1.0 and i < n and until > i:
            sets.append(f.set(attributeName="class", to=f"{kind} old", begin=f"clock.begin+{fmt(i * dt)}s",
                              dur=f"{fmt((until - i) * dt)}s"))
        if fade is not None and fade >= i:
            sets.append(f.set(attributeName="class", to=f"{kind} done", begin=f"clock.begin+{fmt(fade * dt)}s",
                              dur=f"{fmt(total - fade * dt)}s"))
        return sets

    by_step = n == len(d.scene.steps)
    for layer in d.LAYERS:
        lg = f.g(id=layer)
        if by_step:
            for k, elems in d.groups[layer]:
                # no ids: a <set> animates its parent, the step group
                fade = d.scene.fade_end(k) if style.done_opacity < 1.0 else None
                lg.add(d.step_group(k, timing(k, "step", fade) + list(elems)))
        else:
            # a stage of several steps: one group with the timing around its (unmarked) step groups
            runs = d.groups[layer]
            groups = d.plain_groups(layer)
            j = 0
            for i, last in enumerate(ends, start=1):
                stage = f.g(class_="stage")
                while j < len(runs) and runs[j][0] <= last:
                    stage.add(groups[j])
                    j += 1
                if len(stage.elements):
                    for e in timing(i, "stage"):
                        stage.elements.insert(0, e)
                    lg.add(stage)
        dwg.add(lg)
    furniture = d.furniture()  # the broken axis's marks (and a plate's furniture)
    if furniture is not None:
        dwg.add(furniture)
    # Captions: each stage's while it is drawn, the figure's title otherwise (and in still renderers).
    title_lines = d.title_lines(title or d.scene.title)[: d.n_caption]
    tg = d.caption_group(title_lines, id="title")
    if tg is not None:
        tg.add(f.set(attributeName="visibility", to="hidden", begin="clock.begin", dur=f"{fmt(n * dt)}s"))
        dwg.add(tg)
    caps = f.g(id="step-captions")
    first = 1
    for i, last in enumerate(ends, start=1):
        # the caption in German and English (the group path is in the player and the frames)
        cap = d.caption_group(_stage_caption(d, first, last), id=f"caption-{last}", visibility="hidden")
        if cap is not None:
            cap.add(f.set(attributeName="visibility", to="visible", begin=f"clock.begin+{fmt((i - 1) * dt)}s",
                          dur=f"{fmt(dt)}s"))
            caps.add(cap)
        first = last + 1
    dwg.add(caps)
    return d.doc.text(dwg)
