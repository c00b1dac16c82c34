"""What the player shows when a step's work is too small in its view: an inset that magnifies it, a ring round it.

The camera (:mod:`construct.render.camera`) shows each step through a view that keeps its surroundings in
sight.  A step whose finest detail that view shows too small, or which works on a sliver (a rectangle a few
pixels thick across the whole figure), gets a magnified inset beside the view (:func:`step_insets`); a
current mark smaller on the screen than a ring gets a ring round it (:func:`ring_round`).

>>> from construct.constructions import get
>>> from construct.render.camera import step_views
>>> from construct.render.scene import build_scene
>>> sc = build_scene(get("crank").figure(parts=6))
>>> full = (0.0, 0.0, 960.0, 700.0)
>>> insets = step_insets(sc, step_views(sc, full, sc.bbox, lambda x, y: (x, y), 1.0), full, lambda x, y: (x, y))
>>> len(insets) == len(sc.steps) and all(b is None or len(b) == 4 for b in insets)
True
"""

from __future__ import annotations

from typing import Callable, Sequence

from .camera import PLAYER_FIGURE_PX, Framing, View, compass_span, finest_detail, read_tenth, step_details, step_focus, zoom_of
from .scene import MarkKind, Scene

__all__ = ["step_insets", "inset_detail", "inset_details", "points_at", "ring_round", "SLIVER_PX", "SLIVER_RATIO", "INSET_PX", "CLUSTER_ABOVE",
           "INSET_DETAIL_PX"]


#: A step's work is a sliver where its region is thinner on the screen than this (px) and at least
#: :data:`SLIVER_RATIO` times as long: no view of the window's shape shows both its length and its
#: thickness, so the player shows the thickness in an inset (:func:`step_insets`).
SLIVER_PX = 10.0
SLIVER_RATIO = 5.0
#: The inset's window on the screen (px) and how thick the sliver is made there at least.
INSET_PX = (300.0, 210.0)
INSET_DETAIL_PX = 28.0
#: A step's finest detail is a cluster magnified in an inset where it must be seen more than this many times as
#: magnified as its view magnifies the whole (:func:`step_insets`; the player judges it so too, as a live given moves
#: the points).
CLUSTER_ABOVE = 1.25


def step_insets(scene: Scene, views: Sequence[View], full: View,
                px: Callable[[float, float], tuple[float, float]]) -> list[View | None]:
    """Per step, the region (canvas px, x y w h) the player shows magnified in an inset, or None.

    A step whose finest detail its view shows smaller than it must be seen (:func:`step_details`: its view
    widened to take in its letters, or shared with its shot) gets it magnified beside the view.  A step
    working on a sliver -- the thin rectangle O r₁ of a disc 0,02 r₁ thick, a pressure of 0,15 at
    laid off over a stroke of 24 cm -- is seen whole in its view only a few pixels thick.  The inset
    shows the place where the step makes its point (or the point its line is aimed at) magnified until
    the sliver is :data:`INSET_DETAIL_PX` thick, while the view keeps its whole length in sight.
    """
    drawn = {m.name: m for m in scene.marks}
    focus = step_focus(scene)
    details = step_details(scene, Framing(full), px)
    out: list[View | None] = []
    for s, f, v, (need, at) in zip(scene.steps, focus, views, details):
        box = None
        z = zoom_of(v, full)
        if at is not None and s.group and need > CLUSTER_ABOVE * z:
            # a cluster the view (widened for its letters, or its shot's) shows smaller than it must be seen
            q = min(PLAYER_FIGURE_PX[0] / v[2], PLAYER_FIGURE_PX[1] / v[3])
            m = max(2.0, need / z)
            w, h = INSET_PX[0] / (q * m), INSET_PX[1] / (q * m)
            box = (round(at[0] - w / 2, 2), round(at[1] - h / 2, 2), round(w, 2), round(h, 2))
        elif f is not None and s.group:
            (x0, y1), (x1, y0) = px(f[0], f[1]), px(f[2], f[3])
            q = min(PLAYER_FIGURE_PX[0] / v[2], PLAYER_FIGURE_PX[1] / v[3])  # screen px per canvas px
            thin, long = min(x1 - x0, y1 - y0) * q, max(x1 - x0, y1 - y0) * q
            if 0.75 < thin < SLIVER_PX and long >= SLIVER_RATIO * thin:  # (points on one line are no sliver)
                own = [drawn[n].geom for n in s.outputs if n in drawn and drawn[n].kind is MarkKind.POINT]
                if not own:
                    own = [drawn[n].geom for n in s.inputs if n in drawn and drawn[n].kind is MarkKind.POINT][-1:]
                if own:
                    cx = sum(px(*p)[0] for p in own) / len(own)
                    cy = sum(px(*p)[1] for p in own) / len(own)
                    m = min(max(INSET_DETAIL_PX / max(thin, 0.5), 2.0), 16.0)  # the inset's magnification
                    w, h = INSET_PX[0] / (q * m), INSET_PX[1] / (q * m)
                    box = (round(cx - w / 2, 2), round(cy - h / 2, 2), round(w, 2), round(h, 2))
        out.append(box)
    return out


def inset_detail(scene: Scene, px: Callable[[float, float], tuple[float, float]], scale: float, k: int,
                 box: Sequence[float] | None, *, at_point: "dict[tuple[float, ...], str] | None" = None
                 ) -> tuple[list[str], list[list[str]], float] | None:
    """Where step *k*'s inset *box* (canvas px: x y w h) magnifies a cluster: the finest detail of the step
    (:func:`~construct.render.camera.step_details`: the two closest of its points, read to 0.1 px, or the smallest
    circle or arc it strikes where that is finer) in the middle of the box, the box as large as the detail in
    proportion.  Then the ids of the points it compares, of each circle's centre point and circle and of the two
    points its compass is set to where they are drawn (:func:`~construct.render.camera.compass_span`: [centre,
    circle(, a, b)], a pair that is the circle's radius, not compared) and the detail's size (canvas px): a page that moves the points (a live given) finds the detail
    among them anew and carries the box with it (the player's ``detail``).  None for any other inset (a sliver's,
    centred on the step's own points), or where no point stands at a circle's centre.  *box* None: a step shown
    without an inset here, whose detail a page whose points move (a live given) judges anew (its size is then
    the detail's size, as it is found here).

    *px*: the drawing's map to canvas pixels; *scale*: its canvas pixels per unit; *at_point*: the scene's points'
    ids by where they stand (:func:`points_at`), if the caller asks of many steps.
    """
    s = scene.steps[k - 1]
    drawn = scene.marks_by_name
    near = [drawn[n] for n in dict.fromkeys((*s.outputs, *s.inputs, *sorted(scene.named(k))))
            if n in drawn and drawn[n].kind is MarkKind.POINT]
    rounds, circles = [], []
    span = compass_span(s)  # (the pair the compass is set to: its circle's radius, no detail of its own)
    span_ids = [drawn[n].id for n in span if n in drawn and drawn[n].kind is MarkKind.POINT] if span else []
    for n in s.outputs:
        m = drawn.get(n)
        if m is None or not m.kind.round:
            continue
        if at_point is None:  # (made only for a step that strikes a circle)
            at_point = points_at(scene, px)
        c = px(*m.geom[:2])
        spot = tuple(round(x, 2) for x in c)
        # (the point the step sets its compass on where it stands there: another point on that spot at this value,
        # apart at another, would carry the live page's box away -- effective work's step 838, the arc about U8,
        # found about Y1 of u7, 50 px off at κ = 3)
        centre = next((drawn[n].id for n in s.inputs if n in drawn and drawn[n].kind is MarkKind.POINT
                       and tuple(round(x, 2) for x in px(*drawn[n].geom)) == spot), None) or at_point.get(spot)
        if centre is None:
            return None  # (the page could not find it anew)
        rounds.append([centre, m.id] + (span_ids if len(span_ids) == 2 else []))
        circles.append((round(m.geom[2] * scale, 2), c))  # (its radius as written: the page reads it)
    read = {m.id: (read_tenth(px(*m.geom)[0]), read_tenth(px(*m.geom)[1])) for m in near}
    spans = [(min(a, b), max(a, b)) for r in rounds if len(r) == 4 for a, b in [(read[r[2]], read[r[3]])]]
    fine, at = finest_detail(circles, [read[m.id] for m in near], spans)
    # (the box rounded to 0.01 px)
    if at is None or box is not None and (abs(at[0] - box[0] - box[2] / 2) > 0.02
                                          or abs(at[1] - box[1] - box[3] / 2) > 0.02):
        return None
    return [m.id for m in near], rounds, round(fine, 4)


def inset_details(scene: Scene, px: Callable[[float, float], tuple[float, float]], scale: float,
                  asked: Sequence[tuple[int, Sequence[float]]]) -> list[tuple | None]:
    """:func:`inset_detail` of each (step, box) *asked*, the scene's points by where they are drawn read once for
    all of them (a figure's hundreds of insets each read its thousands of marks).

    >>> from construct.constructions import get
    >>> from construct.render.output import scene_for
    >>> from construct.render.styles import STYLES
    >>> from construct.render.svg import Drawing
    >>> c = get("tangential-pressure")
    >>> d = Drawing(scene_for(c, c.figure(parts=6), ending=True), STYLES["teaching"])
    >>> asked = [(k, z) for k, z in enumerate(d.insets, start=1) if z is not None]
    >>> found = inset_details(d.scene, d.vp.px, d.vp.scale, asked)
    >>> len(asked), sum(f is not None for f in found)  # (the others: a sliver's, centred on the step's points)
    (30, 19)
    """
    at_point = points_at(scene, px) if asked else None
    return [inset_detail(scene, px, scale, k, box, at_point=at_point) for k, box in asked]


def points_at(scene: Scene, px: Callable[[float, float], tuple[float, float]]) -> dict[tuple[float, ...], str]:
    """The ids of the scene's points by where they stand (canvas px, to hundredths), as :func:`inset_detail`
    finds a circle's centre."""
    return {tuple(round(c, 2) for c in px(*m.geom)): m.id for m in scene.marks if m.kind is MarkKind.POINT}


def ring_round(points: Sequence[tuple[float, float]], view: View, full: View,
               ring_px: float) -> tuple[float, float, float] | None:
    """(cx, cy, r), canvas pixels, of the ring round a mark through *points* (canvas pixels) when the mark is
    smaller on the screen than the ring (*ring_px* across) at *view*; None when it is large enough (or has no
    points).

    >>> ring_round([(100.0, 100.0), (102.0, 101.0)], (0, 0, 480, 334), (0, 0, 960, 668), 18.0)
    (101.0, 100.5, 9.0)
    """
    if not points:
        return None
    x0, x1 = min(p[0] for p in points), max(p[0] for p in points)
    y0, y1 = min(p[1] for p in points), max(p[1] for p in points)
    z = zoom_of(view, full)
    size = max(x1 - x0, y1 - y0) * z  # on the screen, at the view
    if size >= 3.2 * ring_px:  # also on a figure the player shows at 0.6 of its size
        return None
    r = max(ring_px, size / 2 + 4.0) / z
    return (round((x0 + x1) / 2, 2), round((y0 + y1) / 2, 2), round(r, 2))
