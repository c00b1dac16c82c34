"""The camera of a teaching sequence: for every step the part of the figure a student should look at.

A group (a macro step: "trisect arc P3P6", "rod arc from 7") is the unit a
student learns.  Step k is shown through a *view*, a box of the drawing's
pixel canvas (x, y, w, h; y down) round the place where the step works: its
own marks, the points its instrument is set on and the points its frame tags
(:func:`step_focus`), with room around it, so that the student sees where it
sits.  The camera holds still over a *shot*, a run of steps seen through the
view of all their working regions, and moves where the work moves
(:func:`shots`): a group that works in far-apart places (the crank circle,
then the proportional angle far below) is followed from place to place
rather than shot as the union of its extent, and a step that reaches far (a
rod arc struck from the crank circle onto the far crosshead) widens the view
of the steps about it rather than swinging the camera out and back.  Shots
end preferably where groups end.  The first step and steps outside every
group show the whole figure; the last step frames the clean figure of the
results (:func:`final_box`), not a lone far helper point.  The player and the
animation move between views smoothly.

Every view has the canvas's aspect ratio and magnifies at most
:data:`MAX_ZOOM` times.  The work is linear in the steps (one box per step,
a dynamic programme that looks back a bounded number of steps).  Numbers are
rounded to hundredths of a pixel: the same figure gives the same views on
every machine.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> sc = build_scene(get("crank").figure(parts=6))
>>> vs = step_views(sc, (0.0, 0.0, 960.0, 700.0), sc.bbox, lambda x, y: (x, y), 1.0)
>>> len(vs) == len(sc.steps), vs[0] == vs[-1] == (0.0, 0.0, 960.0, 700.0)
(True, True)
"""

from __future__ import annotations

import math
from typing import Any, Callable, Sequence

import numpy as np

from .scene import MarkKind, Scene, extreme_points
from .svgdoc import fmt

__all__ = ["step_views", "views_box", "shots", "step_focus", "step_focus_names", "step_shots", "framed_rows", "step_zooms", "step_details", "finest_detail", "DETAIL_TIE_PX", "compass_span", "read_tenth", "DETAIL_PX", "INSET_MAX", "final_box", "Framing", "ZOOM_LEVELS", "level", "level_css", "NON_SCALING", "MAX_ZOOM", "CONTEXT", "WHOLE_ABOVE", "view_text", "zoom_of", "clip_view", "PLAYER_FIGURE_PX",
           "player_letter_scale"]

#: The step player's figure box in a typical 1400 × 900 browser window (width, height in screen px, as its page
#: lays it out: what the side column leaves of the width, at most 70 % of the height): the window the views
#: are shaped for and their magnification is measured in (:func:`zoom_of`); the page keeps the box of this
#: shape (``aspect-ratio``), so that a view fills it at any window size.
PLAYER_FIGURE_PX = (998.0, 630.0)

#: A view never magnifies the whole figure more than this many times (more would lose where it sits).
MAX_ZOOM = 4.0
#: Room around a group's working region, as a fraction of its size on every side.
CONTEXT = 0.6
#: Room round the clean figure of the last step (its letters stand outside its points).
FINAL_CONTEXT = 0.1
#: The room round a region is at most this fraction of the canvas on each side.
ROOM = 0.08
#: A shot whose padded region covers more than this fraction of the figure (in width or height) shows the whole.
WHOLE_ABOVE = 0.6
#: What a move of the camera costs, in steps seen at half their own magnification (:func:`shots`).
MOVE = 4.0
#: A move inside a group (not where one group ends and another begins) costs this fraction of :data:`MOVE` more.
CUT_INTO = 0.5
#: The most steps a shot looks back over when the shots are chosen.
LONGEST = 400
#: The last frame frames the results; a remaining helper counts where it stands within this fraction of
#: the results' size from them (:func:`final_box`).
NEAR_RESULTS = 0.25

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


#: The lines the player holds at their screen width in every view (an end state's own file writes their
#: widths in its units instead: :func:`construct.render.svg.own_strokes`).
NON_SCALING = ".construction,.result,.auxiliary,.given,.hatch,.fur,.ring{vector-effect:non-scaling-stroke}"


def level_css() -> str:
    """The rules that keep letters, points and leaders at their screen size at each zoom level."""
    rules = [".pt{transform-box:fill-box;transform-origin:center}",
             NON_SCALING,
             ".lbx{display:none}"]
    # --zs (the level's letter scale) is declared on the letters, leaders and points themselves, and the
    # selectors end in their classes: a class of the figure's root that changes (the player's zoom level) then
    # restyles those, not every element of the figure (an inherited custom property, or a selector ending
    # in *, restyles the whole tree)
    for i, z in enumerate(ZOOM_LEVELS[1:], start=1):
        rules.append(f".zl{i} .lbg>.lb,.zl{i} .lbg>.leader,.zl{i} .pt"
                     f"{{--zs:{fmt(1 / z, 4)};transform:scale({fmt(1 / z, 4)})}}")
    rules.append(",".join(f".zl{i} .lbx" for i in range(THIN_FROM, len(ZOOM_LEVELS))) + "{display:inline}")
    # a letter that moves at a level has a leader of its own there (lvN), the whole figure's hidden (mN)
    levels = range(1, len(ZOOM_LEVELS))
    rules.append(",".join(f".lv{i}" for i in levels) + ",.lvf{display:none}")
    rules.append(",".join(f".zl{i} .lv{i}" for i in levels) + "{display:inline}")
    rules.append(",".join(f".zl{i} .m{i}" for i in levels) + "{display:none}")
    # a letter with no room at a zoom level gives way there (placing.Placing._zoom_placing)
    rules.append(",".join(f".zl{i} .h{i}" for i in range(len(ZOOM_LEVELS))) + "{display:none}")
    return "\n".join(rules)


Box = tuple[float, float, float, float]
View = tuple[float, float, float, float]


def view_text(v: View) -> str:
    """A view as an SVG viewBox / ``data-view`` value: "x y w h", two decimals."""
    return " ".join(fmt(c) for c in v)


def zoom_of(v: View, full: View, window: tuple[float, float] = PLAYER_FIGURE_PX) -> float:
    """How many times the player's *window* shows view *v* larger on the screen than the whole canvas *full*
    (each fitted into the window, keeping its aspect): the zoom the letters are held at their size for.

    A view of the canvas's shape magnifies as many times as it is narrower; a view of the
    window's shape in a tall canvas (960 × 1390, which the window shows at half its size)
    magnifies by its height:

    >>> zoom_of((0, 0, 480, 334), (0, 0, 960, 668)), round(zoom_of((0, 0, 960, 682.23), (0, 0, 960, 1390)), 3)
    (2.0, 2.037)
    """
    ww, wh = window
    whole = max(full[2] / ww, full[3] / wh)
    return whole / max(v[2] / ww, v[3] / wh, 1e-12)


def clip_view(cx: float, cy: float, w: float, h: float, full: View) -> View:
    """The view *w* × *h* about (cx, cy), cut to the canvas where it is wider or taller than *full* (the
    window shows as much: it fits the view's box, keeping its aspect) and moved onto the canvas where it
    would reach past an edge (a view grown about a point near the edge shows no paper beyond it).

    >>> clip_view(480, 300, 1200, 800, (0, 0, 960, 1390))
    (0.0, 0.0, 960.0, 800.0)
    >>> clip_view(900, 700, 200, 100, (0, 0, 960, 1390))
    (760.0, 650.0, 200.0, 100.0)
    """
    w, h = min(w, full[2]), min(h, full[3])
    x = min(max(cx - w / 2, full[0]), full[0] + full[2] - w)
    y = min(max(cy - h / 2, full[1]), full[1] + full[3] - h)
    return (round(float(x), 2), round(float(y), 2), round(float(w), 2), round(float(h), 2))


def _grow(b: Box | None, x: float, y: float) -> Box:
    return (x, y, x, y) if b is None else (min(b[0], x), min(b[1], y), max(b[2], x), max(b[3], y))


def step_focus(scene: Scene) -> list[Box | None]:
    """Per step, the box of where it works: its own marks, the points its instrument is set on and the points
    its caption names (:meth:`Scene.named`; the marks :func:`step_focus_names` names).

    Lines are left out of the marks: a line is drawn as far as all the points the
    whole construction ever marks on it (the stroke line reaches the far
    crossheads); its defining points are the step's inputs and count.  A curve the
    step cuts counts by the point the cut makes, not by its whole extent.
    """
    drawn = {m.name: m for m in scene.marks}
    out: list[Box | None] = []
    for names in step_focus_names(scene):
        b: Box | None = None
        for n in names:
            for x, y in extreme_points(drawn[n]):
                b = _grow(b, x, y)
        out.append(b)
    return out


def step_focus_names(scene: Scene) -> list[list[str]]:
    """Per step, the names of the marks whose extreme points set its working region (:func:`step_focus`): its
    own marks but lines, and the points it is set on or its caption names (a live page frames a step at another
    value of a given round these marks as drawn there)."""
    drawn = {m.name: m for m in scene.marks}
    out: list[list[str]] = []
    for s in scene.steps:
        names = [n for n in s.outputs if (m := drawn.get(n)) is not None and m.kind is not MarkKind.SEGMENT]
        # the points its instrument is set on, and those its caption names: the student looks for them too,
        # and a caption names only what the view shows
        names += [n for n in sorted(set(s.inputs) | scene.named(s.index))
                  if (m := drawn.get(n)) is not None and m.kind is MarkKind.POINT]
        out.append(names)
    return out


def _union(a: Box | None, b: Box | None) -> Box | None:
    if a is None or b is None:
        return a if b is None else b
    return (min(a[0], b[0]), min(a[1], b[1]), max(a[2], b[2]), max(a[3], b[3]))


class Framing:
    """How a region of the canvas is framed: the view round it, in the shape of the player's *window*.

    Room on every side in proportion to the region (*context* of its
    size), at most :data:`ROOM` of the canvas (a large region is its own context;
    padding it in proportion would push it to the whole figure); at most
    :data:`MAX_ZOOM` times magnified; the whole canvas where the view would
    magnify less than 1 / *whole_above* times.  Magnification is the window's
    (:func:`zoom_of`): a view of the window's shape fills it, so that a tall
    figure, which the window shows at half its size, is seen magnified in its
    views (a view of the canvas's shape would be letterboxed).  Widths are those
    of the window-shaped box (:attr:`span` for the whole); a view wider or taller
    than the canvas is cut to it (:func:`clip_view`).
    Regions are pixel boxes (x0, y0, x1, y1) of the canvas *full*.
    """

    def __init__(self, full: View, window: tuple[float, float] | None = PLAYER_FIGURE_PX, max_zoom: float = MAX_ZOOM):
        self.full = full
        ww, wh = window or (full[2], full[3])
        self.aspect = wh / max(ww, 1e-12)
        #: The width of the window-shaped box that shows the whole canvas.
        self.span = max(full[2], full[3] / self.aspect)
        self.min_w = self.span / max_zoom

    def width(self, w: float, h: float, context: float = CONTEXT, max_zoom: float | None = None) -> float:
        """The width of the view round a region *w* x *h* px (before the whole-figure rule); *max_zoom*: the
        most it magnifies (the framing's own by default)."""
        fw, fh = self.full[2], self.full[3]
        w, h = w + 2 * min(context * w, ROOM * fw), h + 2 * min(context * h, ROOM * fh)
        return max(w, h / self.aspect, self.min_w if max_zoom is None else self.span / max_zoom)

    def limit(self, whole_above: float = WHOLE_ABOVE) -> float:
        """From this view width on the whole canvas is shown."""
        return whole_above * self.span

    def zoom(self, b: Box | None) -> float:
        """How many times the view of region *b* magnifies the whole (1: the whole)."""
        if b is None:
            return 1.0
        w = self.width(b[2] - b[0], b[3] - b[1])
        return 1.0 if w >= self.limit() else self.span / w

    def view(self, b: Box | None, context: float = CONTEXT, whole_above: float = WHOLE_ABOVE,
             max_zoom: float | None = None) -> View:
        """The view round region *b*, slid inside the canvas where it can (the figure's edge is not a
        reason to show paper); numbers to hundredths of a pixel."""
        fx, fy, fw, fh = self.full
        if b is None:
            return self.full
        w = self.width(b[2] - b[0], b[3] - b[1], context, max_zoom)
        h = w * self.aspect
        if w >= self.limit(whole_above):
            return self.full
        w, h = min(w, fw), min(h, fh)  # the window shows as much of the canvas about the view's centre
        cx, cy = (b[0] + b[2]) / 2, (b[1] + b[3]) / 2
        x = min(max(cx - w / 2, fx), fx + fw - w)
        y = min(max(cy - h / 2, fy), fy + fh - h)
        return (round(x, 2), round(y, 2), round(w, 2), round(h, 2))


#: The smallest distance the student must tell apart on the screen (px), letters beside them: two points a step works with, the
#: radius of a circle it strikes.  Where the whole figure shows them closer, the step's view may magnify up
#: to the last zoom level (:func:`step_zooms`), past :data:`MAX_ZOOM`.
DETAIL_PX = 20.0
#: The most a step's finest detail is magnified (in an inset, past the last zoom level): Dürer's trisection
#: moves its thirds by a tenth of a canvas pixel (crank of 18 parts, step 54: 0.14 px), which the inset
#: shows 12 px apart; points equal but for rounding (0.1 px) never.
INSET_MAX = 128.0


#: What a step whose finest detail its shot shows smaller than :data:`DETAIL_PX` costs in :func:`shots`, per
#: halving of the magnification it lacks (two moves of the camera: a cluster of points is worth a shot).
UNSEEN = 2 * MOVE


def step_details(scene: Scene, framing: Framing,
                 px: Callable[[float, float], tuple[float, float]]) -> list[tuple[float, tuple[float, float] | None]]:
    """Per step, how much its view must magnify for its finest detail to be :data:`DETAIL_PX` on the screen
    (:func:`finest_detail` of the points it works with and the circles it strikes; 0: nothing finer than the
    whole figure shows), at most :data:`INSET_MAX`, and where that detail is (canvas px).  A cluster of points
    within a few pixels of each other (a trisection's thirds, a compass step of a few pixels) is seen
    magnified, not as one dot.
    """
    drawn = scene.marks_by_name
    whole = PLAYER_FIGURE_PX[0] / framing.span  # screen px per canvas px in the whole figure's view
    out: list[tuple[float, tuple[float, float] | None]] = []
    for s in scene.steps:
        pts: list[tuple[float, float]] = []
        rounds: list[tuple[float, tuple[float, float]]] = []
        for n in dict.fromkeys((*s.outputs, *s.inputs, *sorted(scene.named(s.index)))):
            m = drawn.get(n)
            if m is None:
                continue
            if m.kind is MarkKind.POINT:
                x, y = px(*m.geom)
                pts.append((read_tenth(x), read_tenth(y)))
            elif m.kind.round and n in s.outputs:
                c = px(*m.geom[:2])
                rounds.append((round(abs(px(m.geom[0] + m.geom[2], m.geom[1])[0] - c[0]), 2), c))  # (as written)
        span = _read_span(s, drawn, px) if rounds else None
        fine, at = finest_detail(rounds, list(dict.fromkeys(pts)), [span] if span else [])
        need = DETAIL_PX / (fine * whole) if 0.0 < fine < math.inf else 0.0
        out.append((min(INSET_MAX, need), at if need > 1.0 else None))
    return out


#: Two details of a step whose sizes differ by less than this (px, as read) are one size to the player: the step's
#: detail is magnified as the finer needs, about the first of them (:func:`finest_detail`).  A live page draws each point up to 0.2 px
#: off a fresh build's, so that a pair and its mirror image (Baumann's a and z, where a line meets a circle about C:
#: 6.6 px from C both) were told apart by that error, and the page magnified the other one.
DETAIL_TIE_PX = 0.5


def finest_detail(rounds: Sequence[tuple[float, tuple[float, float]]], points: Sequence[tuple[float, float]],
                  spans: Sequence[tuple[tuple[float, float], tuple[float, float]]] = ()
                  ) -> tuple[float, tuple[float, float] | None]:
    """A step's finest detail, as its size (px) and where it is: of the circles it strikes (*rounds*: radius and
    centre, the radius as written) and of every two of its *points* (read to 0.1 px: :func:`read_tenth`; apart,
    not the two of a compass's span in *spans*, :func:`compass_span`: their distance is the circle's radius), the
    size of the finest, the place of the first -- circles first, then pairs in the points' order -- within
    :data:`DETAIL_TIE_PX` of it.  The player's ``detail`` applies the same rule to the points as it draws them.
    (inf, None): none.

    >>> finest_detail([(4.33, (10.0, 10.0))], [(0.0, 0.0), (4.3, 0.0), (0.0, 9.0)], [((0.0, 0.0), (4.3, 0.0))])
    (4.33, (10.0, 10.0))
    >>> finest_detail([], [(0.0, 0.0), (6.7, 0.0), (0.0, 6.6)])  # (6.7 is within 0.5 px of 6.6: the first pair's place)
    (6.6, (3.35, 0.0))
    >>> finest_detail([], [(0.0, 0.0), (7.2, 0.0), (0.0, 6.6)])
    (6.6, (0.0, 3.3))
    """
    pairs = [(a, b) for i, a in enumerate(points) for b in points[i + 1:]
             if a != b and (not spans or (min(a, b), max(a, b)) not in spans)]
    sizes = [r for r, _ in rounds] + [math.hypot(a[0] - b[0], a[1] - b[1]) for a, b in pairs]
    if not sizes:
        return math.inf, None
    least = min(sizes)
    first = next(i for i, size in enumerate(sizes) if size < least + DETAIL_TIE_PX)
    if first < len(rounds):
        return least, rounds[first][1]
    a, b = pairs[first - len(rounds)]
    return least, ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)


def compass_span(step: Any) -> tuple[str, str] | None:
    """The two points *step*'s compass is set to, whose distance is the radius of the circle it strikes (about
    a point through a point: the centre and that point; a segment carried: its ends), or None.

    A step's finest detail (:func:`step_details`, :func:`~construct.render.insets.inset_detail`, the player's
    ``detail``) is the circle, never this pair beside it: the two are one size by construction, and only the
    reading (the points to 0.1 px, the radius to 0.01) told them apart -- which a live page, whose points stand
    0.2 px off, told otherwise, and magnified the pair 340 px from the arc a fresh build magnified (Baumann's
    effective work at κ = 8, step 426: U-V3 4.3 px apart, the arc about E3 4.33 px round).

    >>> from construct.constructions import get
    >>> from construct.render.scene import build_scene
    >>> sc = build_scene(get("inertia-stroke-fractions").figure())
    >>> [(s.index, s.op, compass_span(s)) for s in sc.steps if s.index in (56, 57, 211)]
    [(56, 'circle_through', ('x.M5', 'x.M4')), (57, 'intersect', None), (211, 'circle_segment', ('O', 'Yt5'))]
    """
    if step.op == "circle_through":
        return step.inputs[0], step.inputs[1]
    if step.op == "circle_segment":
        return step.inputs[1], step.inputs[2]
    return None


def _read_span(step: Any, drawn: Any, px: Callable[[float, float], tuple[float, float]]
               ) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """The two points of *step*'s :func:`compass_span` read to 0.1 px (:func:`read_tenth`), in order, as
    :func:`step_details` compares its points; None where it has none, or they are not both drawn points."""
    span = compass_span(step)
    if span is None:
        return None
    ms = [drawn.get(n) for n in span]
    if any(m is None or m.kind is not MarkKind.POINT for m in ms):
        return None
    (ax, ay), (bx, by) = (px(*m.geom) for m in ms)
    a, b = sorted(((read_tenth(ax), read_tenth(ay)), (read_tenth(bx), read_tenth(by))))
    return a, b


def read_tenth(v: float) -> float:
    """A canvas coordinate read to 0.1 px as the player reads it off its element: written to hundredths
    (:func:`~construct.render.svgdoc.fmt`), then to the nearest tenth, halves up (JavaScript's ``Math.round``).
    The finest detail of a step is found by this one reading here and in the page (insets.inset_detail and the
    player's ``detail``): read otherwise (Python's ``round`` takes halves to even), two points 3.25 px apart
    were 3.3 here and 3.2 there, and the page moved a cluster's inset off the points it letters.

    >>> read_tenth(268.25), round(268.25, 1), read_tenth(271.526)
    (268.3, 268.2, 271.5)
    """
    return math.floor(10.0 * round(v, 2) + 0.5) / 10.0


def step_zooms(scene: Scene, framing: Framing, px: Callable[[float, float], tuple[float, float]]) -> list[float]:
    """Per step, how much its view must magnify for its finest detail to be seen (:func:`step_details`); a view
    may magnify past :data:`MAX_ZOOM` as far as that, up to the last zoom level (beyond, an inset shows it)."""
    return [min(ZOOM_LEVELS[-1], need) for need, _ in step_details(scene, framing, px)]


def shots(scene: Scene, focus: Sequence[Box | None], framing: Framing,
          zooms: Sequence[float] | None = None) -> list[tuple[int, int]]:
    """The shots of the sequence: runs (first, last) of steps (1-based) seen through one view.

    A shot is seen through the view (*framing*) of all its steps' working regions
    (*focus*: :func:`step_focus` in canvas pixels).  The camera holds still while
    the work stays in one place and moves with it when a group works in
    far-apart places (the crank circle, then the proportional angle far below).
    The shots are the cheapest partition of each stage (a run of steps under one
    top-level group): every move costs :data:`MOVE`, more where it cuts into a
    group (a group is the unit a student learns) than where groups part; every
    step costs how many times (log 2) less its shot magnifies it than its own
    view would.  So a step that works far off (a rod arc struck from the crank
    circle onto the far crosshead) widens the view of the steps about it rather
    than the camera swinging out and back at every step.  Steps outside every
    group are shots of their own.

    Dynamic programming over the steps, each looking back over at most
    :data:`LONGEST` steps and no further than a shot can still pay: linear in
    the steps.  *zooms*: per step the most its view may magnify (:func:`step_zooms`; a shot magnifies as much
    as its finest step may).
    """
    steps = scene.steps
    n = len(steps)
    out: list[tuple[int, int]] = []
    i = 0
    while i < n:
        if not steps[i].group:
            out.append((i + 1, i + 1))
            i += 1
            continue
        j = i
        while j + 1 < n and steps[j + 1].group and steps[j + 1].group[:1] == steps[i].group[:1]:
            j += 1
        out.extend(_partition(steps, focus, framing, i, j, zooms))
        i = j + 1
    return out


def _partition(steps: Sequence, focus: Sequence[Box | None], framing: Framing, a: int, b: int,
               zooms: Sequence[float] | None = None) -> list[tuple[int, int]]:
    """The cheapest shots of steps a..b (0-based, inclusive) as in :func:`shots`, as 1-based runs."""
    m = b - a + 1
    fw = framing.span
    whole = framing.limit()
    width = framing.width
    need = [0.0] * m if zooms is None else list(zooms[a:b + 1])
    zs = [max(MAX_ZOOM, z) for z in need]

    def own_zoom(t: int) -> float:
        f = focus[a + t]
        w = width(f[2] - f[0], f[3] - f[1], max_zoom=zs[t])
        return 1.0 if w >= whole else fw / w

    # log 2 of each step's own magnification (0: a step without a working region frames nothing)
    own = [math.log2(own_zoom(t)) if focus[a + t] is not None else 0.0 for t in range(m)]
    framed = [focus[a + t] is not None for t in range(m)]
    logs, counts = [0.0], [0]
    for t in range(m):
        logs.append(logs[-1] + own[t])
        counts.append(counts[-1] + framed[t])
    moves = [0.0] + [MOVE * (1.0 if steps[a + t - 1].group != steps[a + t].group else 1.0 + CUT_INTO)
                     for t in range(1, m)]
    best = [0.0] + [math.inf] * m
    start = [0] * (m + 1)
    for t in range(m):
        x0 = y0 = math.inf
        x1 = y1 = -math.inf
        deepest = MAX_ZOOM
        finest = 0.0
        for s in range(t, max(-1, t - LONGEST), -1):
            f = focus[a + s]
            if f is not None:
                x0, y0, x1, y1 = min(x0, f[0]), min(y0, f[1]), max(x1, f[2]), max(y1, f[3])
            deepest = max(deepest, zs[s])
            finest = max(finest, need[s])
            if x0 <= x1:
                w = width(x1 - x0, y1 - y0, max_zoom=deepest)
                lz = 0.0 if w >= whole else math.log2(fw / w)
            else:
                lz = 0.0
            loss = (logs[t + 1] - logs[s]) - (counts[t + 1] - counts[s]) * lz
            if finest > 1.0:  # a step's finest detail, unseen in the shot: the shot pays for it
                loss += UNSEEN * max(0.0, math.log2(finest) - lz)
            cost = best[s] + moves[s] + loss
            if cost < best[t + 1]:
                best[t + 1], start[t + 1] = cost, s
            elif best[s] + loss >= best[t + 1]:
                break  # no earlier start can pay: it costs at least best[s] + loss (the loss only grows)
    runs = []
    t = m
    while t > 0:
        s = start[t]
        runs.append((a + s + 1, a + t))
        t = s
    return runs[::-1]


def final_box(scene: Scene, within: Box | None = None) -> Box | None:
    """The box (drawing units) of what the last teaching frame frames: the results, as a plate shows them.

    Every mark but the finished groups' helpers remains in the last frame;
    the results and givens set the box, and a remaining helper counts only
    where it stands near them (within :data:`NEAR_RESULTS` of their size): a lone
    point far off (the vertex S of a proportional angle below the figure) would
    shrink the results to a corner of an empty canvas.  Lines do not count
    (they reach as far as the construction's farthest points; the view cuts them).
    A helper inside *within* (the view the box gives) counts too: a point the
    view shows anyway is shown whole, not cut by its edge.
    """
    n = len(scene.steps)
    core: Box | None = None
    if scene.ending:
        # the end state: the figure as the book draws it, its furniture included, and nothing else
        from .plate import extent

        for m in scene.end_drawn():
            if scene.end_shows(m):
                for x, y in extreme_points(m):
                    core = _grow(core, x, y)
        fx = extent(scene.end_furniture)
        if fx is not None:
            core = _union(core, fx)
        return core
    rest: list[tuple[float, float]] = []
    for m in scene.marks:
        if m.kind is MarkKind.SEGMENT or scene.faded(m.step, n + 1):
            continue
        if m.role in ("result", "given"):
            for x, y in extreme_points(m):
                core = _grow(core, x, y)
        else:
            rest.extend(extreme_points(m))
    if core is None:
        for x, y in rest:
            core = _grow(core, x, y)
        return core
    pad = NEAR_RESULTS * max(core[2] - core[0], core[3] - core[1])
    near = (core[0] - pad, core[1] - pad, core[2] + pad, core[3] + pad)
    b = core
    for x, y in rest:
        if (near[0] <= x <= near[2] and near[1] <= y <= near[3]) or (
                within is not None and within[0] <= x <= within[2] and within[1] <= y <= within[3]):
            b = _grow(b, x, y)
    return b


def step_views(scene: Scene, full: View, bbox: Box, px: Callable[[float, float], tuple[float, float]],
               scale: float, *, collapse: bool = False) -> list[View]:
    """The view of every step (pixel boxes x, y, w, h of the canvas *full*), in step order.

    *px* maps drawing coordinates to canvas pixels at *scale* pixels per drawing unit.
    Each shot (:func:`shots`) is seen through the view of its steps' working regions;
    the first step and steps outside every group show the whole figure.  With *collapse*
    (finished groups collapse to their results) the last step frames what remains, the
    clean figure of the results (:func:`final_box`), as large as the canvas allows;
    without, it shows the whole.
    """
    n = len(scene.steps)
    if n == 0:
        return []
    framing = Framing(full)

    def to_px(b: Box | None) -> Box | None:
        if b is None:
            return None
        (x0, y1), (x1, y0) = px(b[0], b[1]), px(b[2], b[3])  # y flips
        return (min(x0, x1), min(y0, y1), max(x0, x1), max(y0, y1))

    def to_drawing(x: float, y: float) -> tuple[float, float]:
        ox, oy = px(0.0, 0.0)
        return ((x - ox) / scale, (oy - y) / scale)

    focus = [to_px(b) for b in step_focus(scene)]
    out: list[View] = []
    for first, last, most in step_shots(scene, framing, px, focus):
        u: Box | None = None
        for k in range(first, last + 1):
            u = _union(u, focus[k - 1])
        v = framing.view(u, max_zoom=most) if most else full
        out.extend([v] * (last - first + 1))
    out[0] = full
    if n > 1:
        # the clean figure of the results, and the last step's own work (its mark is the one the student
        # is looking for, even where the construction calls it a helper)
        out[-1] = full
        if collapse:
            b = final_box(scene)
            if scene.ending:  # the end state is framed as large as the window shows it (its letters held)
                framing = Framing(full, max_zoom=ZOOM_LEVELS[-1])
            for _ in range(3):
                # an end state is the lesson's summary: the last step's work is in it, or far from it (the
                # proportional angle below the figure) and its result is
                v = framing.view(to_px(b) if scene.ending else _union(to_px(b), focus[-1]), FINAL_CONTEXT, 1.0)
                if scene.ending:
                    break
                if b is None or v == full:
                    break
                # what the player's window shows of the view, in drawing units (y flips): the helpers
                # it shows anyway are framed whole
                ww, wh = PLAYER_FIGURE_PX
                sw, sh = max(v[2], v[3] * ww / wh), max(v[3], v[2] * wh / ww)
                cx, cy = v[0] + v[2] / 2, v[1] + v[3] / 2
                (x0, y1), (x1, y0) = to_drawing(cx - sw / 2, cy - sh / 2), to_drawing(cx + sw / 2, cy + sh / 2)
                grown = final_box(scene, (x0, y0, x1, y1))
                if grown == b:
                    break
                b = grown
            out[-1] = v
    return out


def step_shots(scene: Scene, framing: Framing, px: Callable[[float, float], tuple[float, float]],
               focus: Sequence[Box | None]) -> list[tuple[int, int, float]]:
    """The shots of :func:`step_views` (:func:`shots` of the steps' working regions *focus*, canvas px): runs
    (first, last) of steps, each with the most its view magnifies (:func:`step_zooms`; 0.0: a shot of steps
    outside every group, the whole figure)."""
    zooms = step_zooms(scene, framing, px)
    return [(first, last, max([MAX_ZOOM] + zooms[first - 1:last]) if scene.steps[first - 1].group else 0.0)
            for first, last in shots(scene, focus, framing, zooms)]


def framed_rows(box: Sequence, W: Any, H: Any, max_zoom: Any, context: float = CONTEXT,
                whole_above: float = WHOLE_ABOVE, window: tuple[float, float] = PLAYER_FIGURE_PX) -> Any:
    """:meth:`Framing.view` over arrays: the views (x, y, w, h: an array of 4 x the broadcast shape) round the
    regions *box* (x0, y0, x1, y1, each an array) of canvases *W* x *H* px, each magnifying at most *max_zoom*
    (a live page frames a step at every value of a sweep at once); the whole canvas where a region is NaN.

    >>> b, full = (100.0, 80.0, 180.0, 140.0), (0.0, 0.0, 960.0, 700.0)
    >>> framed_rows(np.asarray(b)[:, None], np.asarray([960.0]), np.asarray([700.0]), 4.0)[:, 0].tolist() == \\
    ...     list(Framing(full).view(b, max_zoom=4.0))
    True
    """
    x0, y0, x1, y1 = (np.asarray(c, dtype=float) for c in box)
    W, H, most = (np.asarray(c, dtype=float) for c in (W, H, max_zoom))
    aspect = window[1] / window[0]
    span = np.maximum(W, H / aspect)
    bw, bh = x1 - x0, y1 - y0
    with np.errstate(invalid="ignore"):
        w = np.maximum(np.maximum(bw + 2 * np.minimum(context * bw, ROOM * W), (bh + 2 * np.minimum(context * bh, ROOM * H))
                                  / aspect), span / most)
        h = w * aspect
        whole = ~(w < whole_above * span)  # (NaN: nothing framed, the whole)
        w, h = np.minimum(w, W), np.minimum(h, H)
        x = np.minimum(np.maximum((x0 + x1) / 2 - w / 2, 0.0), W - w)
        y = np.minimum(np.maximum((y0 + y1) / 2 - h / 2, 0.0), H - h)
    zero = np.zeros(np.broadcast(x, W).shape)
    return np.stack([np.where(whole, f, np.round(v, 2) + 0.0) for f, v in zip((zero, zero, W + zero, H + zero),
                                                                                (x, y, w, h))])


def views_box(views: Sequence[View], full: View) -> View:
    """The view that takes in *views* (the steps of a stage of the animation, of a storyboard tile): their
    one view, or the box round them in the canvas's aspect (the whole canvas where that reaches its edge).

    >>> views_box([(0.0, 0.0, 100.0, 50.0), (300.0, 100.0, 100.0, 50.0)], (0.0, 0.0, 800.0, 400.0))
    (0.0, 0.0, 400.0, 200.0)
    """
    if len(set(views)) == 1:
        return views[0]
    x0, y0 = min(v[0] for v in views), min(v[1] for v in views)
    x1, y1 = max(v[0] + v[2] for v in views), max(v[1] + v[3] for v in views)
    w = max(x1 - x0, (y1 - y0) * full[2] / full[3])
    h = w * full[3] / full[2]
    if w >= full[2] or h >= full[3]:
        return full
    x = min(max((x0 + x1) / 2 - w / 2, 0.0), full[2] - w)
    y = min(max((y0 + y1) / 2 - h / 2, 0.0), full[3] - h)
    return (round(x, 2), round(y, 2), round(w, 2), round(h, 2))


def player_letter_scale(q: float) -> float:
    """The player's letter scale (its ``--ls``) where a canvas pixel of the level's picture is *q* screen
    pixels: letters at 12 px on the screen, never below 9.5 px.

    >>> player_letter_scale(2.0), player_letter_scale(1.1), player_letter_scale(0.5)
    (1.5833333333333333, 1.0, 0.5)
    """
    return min(max(1.0, 9.5 * q / 12.0), q)
