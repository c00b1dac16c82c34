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
crank has 7295 steps: three hours at that pace).

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> svg = animated_svg(build_scene(get("crank").figure(parts=6)))
>>> svg.count('attributeName="visibility"') > 10 and "<script" not in svg
True
>>> step_seconds() >= 1.5
True
"""

from __future__ import annotations

from typing import Any

from .captions import group_caption
from .scene import thin
from .styles import PLAIN, Style
from .svg import Drawing
from .svgdoc import fmt
from .viewport import camera_transform, camera_zoom

__all__ = ["animated_svg", "step_seconds", "stages", "STEP_GROUP_CSS", "STEP_SECONDS", "MAX_STAGES"]

#: Seconds each step is shown in the animated SVG (a caption takes that long to read).
STEP_SECONDS = 1.5
#: Up to this many steps the animation shows each step; longer constructions a group at a time.
MAX_STAGES = 1000

#: Looks of the step groups, for players that switch classes on a whole step.
STEP_GROUP_CSS = """g.hid{display:none}
g.cur>*,g.stage.cur>g>*{stroke:%(hl)s;stroke-width:%(hw)s}
g.cur .lb,g.stage.cur>g .lb{fill:%(hl)s;stroke:none}
g.cur>.pt,g.stage.cur>g>.pt{fill:%(hl)s}
g.old{opacity:%(op)s}"""


def step_seconds(seconds: float = STEP_SECONDS) -> float:
    """Time per step of the animation: *seconds* whatever the length (the pace is the reader's, not the figure's)."""
    return max(float(seconds), 0.05)


def group_css(style: Style) -> str:
    return STEP_GROUP_CSS % {"hl": style.highlight or "inherit", "hw": fmt(style.highlight_width),
                             "op": fmt(style.earlier_opacity)}


def stages(drawing: Drawing, most: int = MAX_STAGES) -> list[int]:
    """The last step of each stage the animation shows: every step, or for long constructions group ends.

    Up to *most* steps each step is a stage.  Beyond that a step-by-step
    animation would run for hours at a readable pace, so a stage is a group
    (the ends of the groups up to depth 2, thinned evenly to *most*).
    """
    n = len(drawing.scene.steps)
    if n <= most:
        return list(range(1, n + 1))
    return thin(drawing.scene.group_ends(), most)


def _stage_caption(drawing: Drawing, first: int, last: int) -> list[tuple[str, str]]:
    """The caption of a stage of several steps: its group and the span of steps."""
    if first == last:
        return [line for line in drawing.captions.frame_lines(last) if line[0] != "grp"]
    n = len(drawing.scene.steps)
    group = group_caption(drawing.scene, last)
    return [("de", f"Schritte {first}–{last} von {n}: {group}"), ("en", f"Steps {first}–{last} of {n}")]


def _keyed(f, attribute: str, values: list[str], times: list[float], total: float, *, discrete: bool) -> Any:
    """One ``<animate>`` of *attribute* through *values* at *times* (seconds) over the clock's period."""
    keys = ";".join(fmt(min(max(t / total, 0.0), 1.0), 5) for t in times)
    extra = {"calcMode": "discrete"} if discrete else {}
    return f.animate(attributeName=attribute, values=";".join(values), keyTimes=keys, begin="clock.begin",
                     dur=f"{fmt(total)}s", fill="freeze", **extra)


def _stage_view(d: Drawing, first: int, last: int) -> tuple[float, float, float, float]:
    """The view of a stage: its one step's view, or the box round the views of its steps (:func:`views_box`)."""
    from .camera import views_box

    if first >= last:
        return d.camera_view(last)
    return views_box([d.camera_view(k) for k in range(first, last + 1)], d.full_view)


def _camera(d: Drawing, ends: list[int], dt: float, total: float) -> tuple[Any, Any, Any]:
    """(outer, camera, ring): the camera group (:meth:`Drawing.camera_group`) whose transform moves from
    view to view in the last moments before a stage whose view differs, its zoom level class and the
    ring round a small current mark switching with the stages."""
    from .camera import level

    f = d.doc.factory
    full = d.full_view
    views = [_stage_view(d, (ends[i - 1] if i else 0) + 1, k) for i, k in enumerate(ends)]
    move = min(0.45, 0.3 * dt)
    times, keys = [0.0], [views[0]]
    lt, lv = [0.0], [f"zl{level(camera_zoom(views[0], full))}"]
    for i in range(1, len(ends)):
        if views[i] != views[i - 1]:
            start = i * dt
            times += [start - move, start]
            keys += [views[i - 1], views[i]]
            lv_i = f"zl{level(camera_zoom(views[i], full))}"
            if lv_i != lv[-1]:
                lt.append(start - move)
                lv.append(lv_i)
    if d.end is not None and ends[-1] == len(d.scene.steps):
        # the last stage shows the end state (class fin)
        lt.append((len(ends) - 1) * dt)
        lv.append(f"zl{level(camera_zoom(views[-1], full))} fin")
    times.append(total)
    keys.append(keys[-1])
    outer, box = d.camera_group(views[0])
    if len(keys) > 2:
        # translate and scale, each interpolated: the view glides from one group to the next
        parts = [camera_transform(v, full) for v in keys]
        tr = [p[p.index("(") + 1:p.index(")")] for p in parts]
        sc = [p[p.rindex("(") + 1:-1] for p in parts]
        keyt = ";".join(fmt(min(max(t / total, 0.0), 1.0), 5) for t in times)
        for kind, values, extra in (("translate", tr, {}), ("scale", sc, {"additive": "sum"})):
            anim = f.animateTransform(kind, values=";".join(values), keyTimes=keyt, begin="clock.begin",
                                      dur=f"{fmt(total)}s", fill="freeze", **extra)
            anim["attributeName"] = "transform"  # svgwrite leaves it out
            box.add(anim)
    if len(lv) > 1:
        box.add(_keyed(f, "class", lv, lt, total, discrete=True))
    ring = None
    if d.style.ring_px:
        rings = [d.ring(k) if k < len(d.scene.steps) and k == (ends[i - 1] if i else 0) + 1 else None
                 for i, k in enumerate(ends)]  # a ring marks a single step, not a stage of several
        if any(rings):
            times = [i * dt for i in range(len(ends))]
            ring = f.circle(center=("0", "0"), r="0", class_="ring", visibility="hidden")
            ring.add(_keyed(f, "visibility", ["visible" if r else "hidden" for r in rings], times, total, discrete=True))
            for j, attr in enumerate(("cx", "cy", "r")):
                ring.add(_keyed(f, attr, [fmt(r[j]) if r else "0" for r in rings], times, total, discrete=True))
    return outer, box, ring


def animated_svg(scene, style: Style = PLAIN, *, title: tuple[str, str] | None = None,
                 drawing: Drawing | None = None, seconds: float = STEP_SECONDS) -> str:
    """The animation of *scene* (or of the already laid-out *drawing*) as SVG text."""
    d = drawing or Drawing(scene, style)
    style = d.style
    f = d.doc.factory
    ends = stages(d)
    n = len(ends)
    dt = step_seconds(seconds)
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
    outer, camera, ring = _camera(d, ends, dt, total) if style.camera else (None, None, None)
    for layer in d.LAYERS:
        if layer == "labels" and camera is not None and ring is not None:
            camera.add(ring)  # over the drawing, under the letters (a letter's halo opens it)
            ring = None
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
        (camera if camera is not None else dwg).add(lg)
    # the broken axis's marks (and a plate's furniture), each line's with its step
    furniture = d.furniture(timed=(lambda k: timing(k, "step", d.scene.fade_end(k) if style.done_opacity < 1.0
                                                    else None)) if by_step else None)
    if furniture is not None:
        (camera if camera is not None else dwg).add(furniture)
    if camera is not None:
        if ring is not None:
            camera.add(ring)
        dwg.add(outer)
    # Captions: each stage's while it is drawn, the figure's title otherwise (and in still renderers).
    title_lines = d.captions.title_lines(title or d.scene.title)[: d.n_caption]
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
