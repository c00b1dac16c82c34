"""The camera of a teaching sequence: for every step the part of the figure a student should look at.

A group (a macro step: "trisect arc P3P6", "rod arc from 7") is the unit a
student learns.  Step k is shown through a *view*, a box of the drawing's
pixel canvas (x, y, w, h; y down) that frames the working region of the
innermost group around step k -- the box of that group's marks and of the
points its instruments are set on -- with room around it, so that the
student sees where the group sits.  The first and the last step, steps
outside every group, and groups that span most of the figure show the whole
figure.  Views change only from group to group, never inside one, so the
picture holds still while a group is drawn; the player and the animation
move between views smoothly.

Every view has the canvas's aspect ratio and magnifies at most
:data:`MAX_ZOOM` times.  The work is one pass over the marks and the steps
(boxes per group path, then one box per step), so it grows with the number
of steps, not with its square.  Numbers are rounded to hundredths of a pixel:
the same figure gives the same views on every machine.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> sc = build_scene(get("crank").figure(parts=6))
>>> vs = step_views(sc, (0.0, 0.0, 960.0, 700.0), sc.bbox, lambda x, y: (x, y), 1.0)
>>> len(vs) == len(sc.steps), vs[0] == vs[-1] == (0.0, 0.0, 960.0, 700.0)
(True, True)
"""

from __future__ import annotations

from typing import Callable, Sequence

from .scene import MarkKind, Scene, extreme_points
from .svgdoc import fmt

__all__ = ["step_views", "ZOOM_LEVELS", "level", "level_css", "MAX_ZOOM", "CONTEXT", "WHOLE_ABOVE", "view_text", "zoom_of"]

#: A view never magnifies the whole figure more than this many times (more would lose where it sits).
MAX_ZOOM = 4.0
#: Room around a group's working region, as a fraction of its size on every side.
CONTEXT = 0.6
#: Room round the clean figure of the last step (its letters stand outside its points).
FINAL_CONTEXT = 0.1
#: A group whose padded region covers more than this fraction of the figure (in width or height) shows the whole.
WHOLE_ABOVE = 0.6

#: Zoom levels at which letters, points and strokes are held at their screen size (CSS classes zl0, zl1, ...).
ZOOM_LEVELS = (1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0)
#: From this level on the letters a crowded whole figure leaves out (class ``lbx``) are shown.
THIN_FROM = 2


def level(zoom: float) -> int:
    """The zoom level (index into :data:`ZOOM_LEVELS`) a view of *zoom* is drawn at: the nearest below."""
    i = 0
    for j, z in enumerate(ZOOM_LEVELS):
        if zoom >= 0.999 * z:  # never below the level: its letters were placed for that zoom
            i = j
    return i


def level_css() -> str:
    """The rules that keep letters, points and leaders at their screen size at each zoom level."""
    rules = [".pt{transform-box:fill-box;transform-origin:center}",
             ".construction,.result,.auxiliary,.given,.hatch,.fur,.ring{vector-effect:non-scaling-stroke}",
             ".lbx{display:none}"]
    for i, z in enumerate(ZOOM_LEVELS[1:], start=1):
        rules.append(f".zl{i}{{--zs:{fmt(1 / z, 4)}}}.zl{i} .lbg>*,.zl{i} .pt{{transform:scale({fmt(1 / z, 4)})}}")
    rules.append(",".join(f".zl{i} .lbx" for i in range(THIN_FROM, len(ZOOM_LEVELS))) + "{display:inline}")
    # a letter with no room at a zoom level gives way there (svg.Drawing._zoom_placing)
    rules.append(",".join(f".zl{i} .h{i}" for i in range(1, len(ZOOM_LEVELS))) + "{display:none}")
    return "\n".join(rules)


Box = tuple[float, float, float, float]
View = tuple[float, float, float, float]


def view_text(v: View) -> str:
    """A view as an SVG viewBox / ``data-view`` value: "x y w h", two decimals."""
    return " ".join(fmt(c) for c in v)


def zoom_of(v: View, full: View) -> float:
    """How many times the view magnifies the whole canvas."""
    return full[2] / max(v[2], 1e-12)


def _grow(b: Box | None, x: float, y: float) -> Box:
    return (x, y, x, y) if b is None else (min(b[0], x), min(b[1], y), max(b[2], x), max(b[3], y))


def _group_boxes(scene: Scene) -> dict[tuple[str, ...], Box]:
    """Per group path (every prefix of every step's path): the box of its marks and of its steps' input points.

    Lines are left out of the marks: a line is drawn as far as all the points
    the whole construction ever marks on it (the stroke line reaches the far
    crossheads); its defining points are the step's inputs and count.
    """
    boxes: dict[tuple[str, ...], Box] = {}
    drawn = {m.name: m for m in scene.marks}
    for m in scene.marks:
        if m.kind is MarkKind.SEGMENT or not m.group:
            continue
        pts = extreme_points(m)
        for depth in range(1, len(m.group) + 1):
            key = m.group[:depth]
            b = boxes.get(key)
            for x, y in pts:
                b = _grow(b, x, y)
            boxes[key] = b  # type: ignore[assignment]
    for s in scene.steps:
        if not s.group:
            continue
        pts = [drawn[n].geom for n in s.inputs if n in drawn and drawn[n].kind is MarkKind.POINT]
        pts += [drawn[n].geom for n in s.outputs if n in drawn and drawn[n].kind is MarkKind.POINT]
        if not pts:
            continue
        for depth in range(1, len(s.group) + 1):
            key = s.group[:depth]
            b = boxes.get(key)
            for x, y in pts:
                b = _grow(b, x, y)
            boxes[key] = b  # type: ignore[assignment]
    return boxes


def final_box(scene: Scene) -> Box | None:
    """The box of what the last teaching frame shows: every mark but the finished groups' helpers."""
    n = len(scene.steps)
    b: Box | None = None
    for m in scene.marks:
        if m.kind is MarkKind.SEGMENT or scene.faded(m.step, n + 1):
            continue
        for x, y in extreme_points(m):
            b = _grow(b, x, y)
    return b


def step_views(scene: Scene, full: View, bbox: Box, px: Callable[[float, float], tuple[float, float]],
               scale: float, *, collapse: bool = False) -> list[View]:
    """The view of every step (pixel boxes x, y, w, h of the canvas *full*), in step order.

    *px* maps drawing coordinates to canvas pixels at *scale* pixels per drawing unit.
    With *collapse* (finished groups collapse to their results) the last step frames
    what remains, the clean figure, as large as the canvas allows.
    """
    n = len(scene.steps)
    if n == 0:
        return []
    boxes = _group_boxes(scene)
    fx, fy, fw, fh = full
    aspect = fh / max(fw, 1e-12)
    min_w = fw / MAX_ZOOM
    cache: dict[tuple[str, ...], View] = {}

    def view_of(path: tuple[str, ...], b: Box | None = None, context: float = CONTEXT) -> View:
        got = cache.get(path)
        if got is not None:
            return got
        b = boxes.get(path) if b is None else b
        if b is None:
            got = full
        else:
            (x0, y1), (x1, y0) = px(b[0], b[1]), px(b[2], b[3])  # y flips
            w, h = abs(x1 - x0), abs(y1 - y0)
            cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
            w, h = w * (1 + 2 * context), h * (1 + 2 * context)
            w = max(w, h / aspect, min_w)
            h = w * aspect
            if path and (w >= WHOLE_ABOVE * fw or h >= WHOLE_ABOVE * fh) or w >= fw or h >= fh:
                got = full
            else:
                # slide the view inside the canvas where it can (the figure's edge is not a reason to show paper)
                x = min(max(cx - w / 2, fx), fx + fw - w)
                y = min(max(cy - h / 2, fy), fy + fh - h)
                got = (round(x, 2), round(y, 2), round(w, 2), round(h, 2))
        cache[path] = got
        return got

    out: list[View] = []
    for i, s in enumerate(scene.steps):
        if i == n - 1 and collapse and n > 1:
            out.append(view_of((), final_box(scene), FINAL_CONTEXT))  # the clean figure of the results
            continue
        if i == 0 or i == n - 1 or not s.group:
            out.append(full)
            continue
        # the innermost group whose working region is a box (a group of lines only has none)
        path = s.group
        while path and path not in boxes:
            path = path[:-1]
        out.append(view_of(path) if path else full)
    return out


def same_view(a: Sequence[float], b: Sequence[float]) -> bool:
    return all(abs(p - q) < 0.005 for p, q in zip(a, b))
