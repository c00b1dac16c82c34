"""Where a drawing's letters and name tags stand: :func:`construct.render.lettering.place` run over a scene.

A :class:`Placing` places every letter of a scene on its canvas once (results
first, clear of the points and the result lines), again for each zoom level of
the player's camera (a letter that moves or gives way there gets a class and a
rule), and the name tags in the views that show them.  The drawing
(:class:`construct.render.svg.Drawing`) writes the letters where this says;
:meth:`Placing.labels` hands the same answer to any other writer (a TikZ
picture, a test) as data: each letter's point, text, anchor and offset.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> from construct.render.viewport import Viewport
>>> from construct.render.styles import PLAIN
>>> sc = build_scene(get("crank").figure(parts=6))
>>> vp = Viewport.fit(sc.bbox, PLAIN, 0)
>>> labels = Placing(sc, PLAIN, vp, vp.height).labels()
>>> o = next(p for p in labels if p.name == "O")
>>> o.text, o.anchor, o.shown, o.leader
('O', 'middle', True, False)
>>> abs(o.offset[0]) < 3 * PLAIN.label_size and abs(o.offset[1]) < 3 * PLAIN.label_size
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Sequence

import numpy as np

from .camera import PLAYER_FIGURE_PX, THIN_FROM, ZOOM_LEVELS, View, level, zoom_of
from .gaps import Gap
from .lettering import HALO_PX, LEADER_FROM, RANK, LineIndex, label_box, place, text_box
from .paths import bezier_controls
from .plate import plain
from .scene import Mark, MarkKind, Scene, label_offset_direction
from .styles import Style
from .svgdoc import fmt
from .viewport import Viewport

__all__ = ["PlacedLabel", "Placing", "furniture_text_box", "text_gap", "TAG_FARTHER"]

#: The farther rings (letter heights) a name tag tries, tied by a leader, before it gives way: a tag the
#: step's caption names is worth a longer leader.
TAG_FARTHER = (4.5, 5.5, 6.5, 8.0, 10.0, 12.0, 14.0)


@dataclass(frozen=True, slots=True)
class PlacedLabel:
    """Where one point's letter stands on the canvas (pixels, y down), and the point in the figure's units (*at*).

    The text is set with *anchor* at ``point + offset`` (its baseline); *distance* is how far that
    is from the point in letter heights, and a letter from :data:`~construct.render.lettering.LEADER_FROM`
    on is tied to its point by a leader.  *shown*: the whole figure shows it (a letter the whole
    figure has no room for waits for a magnified view).
    """

    id: str
    name: str
    text: str
    role: str
    point: tuple[float, float]
    offset: tuple[float, float]
    distance: float
    shown: bool
    anchor: str = "middle"
    #: The point in the figure's own units (y up), for a writer that maps the figure itself (TikZ).
    at: tuple[float, float] = (0.0, 0.0)

    @property
    def leader(self) -> bool:
        """Is the letter tied to its point by a leader line?"""
        return self.distance >= LEADER_FROM


class Placing:
    """Where the letters and the name tags of *scene* stand on the canvas *vp* in *style*.

    *drawing_height*: the canvas without its caption lines (the part the player's window shows).
    On making: :attr:`spots` (every letter's baseline on the canvas, its distance in letter heights and
    whether the whole figure has no room for it), and with a camera :attr:`level_rel`, :attr:`hidden_at`
    and :attr:`level_rules` (the letters placed again at every zoom level).  :meth:`place_tags` places
    the name tags once the camera's views are known.
    """

    def __init__(self, scene: Scene, style: Style, vp: Viewport, drawing_height: float, *,
                 plate: bool = False, furniture: "Sequence[Any]" = ()):
        self.scene = scene
        self.style = style
        self.vp = vp
        self.drawing_height = drawing_height
        #: a plate: the letters stand clear of every line where they can, never on the furniture's lettering
        #: (*furniture*: the plate's furniture as data, :class:`construct.render.plate.Piece`)
        self.plate = plate
        self.furniture = tuple(furniture)
        self._line_index: dict[tuple[float, float], LineIndex] = {}
        self._rows: dict[int, Any] = {}
        self._obstacle_a: tuple[Any, Any] | None = None
        #: words the drawing writes beside the figure at every zoom level, as the rows of :meth:`letters_at` (the
        #: rod's length at a break): the camera keeps them whole in its views as it keeps the letters
        self.words: list[tuple[float, ...]] = []
        self._tags_by_step: dict[int, list[Mark]] | None = None
        self.spots = self._letter_spots()
        #: the lettered points that have a spot (in mark order)
        self.lettered = [m for m in scene.marks if m.kind is MarkKind.POINT and m.label and m.id in self.spots]
        #: per zoom level, every letter shown there: its offset from its point (canvas units, moves applied)
        self.level_rel: dict[int, dict[str, tuple[float, float]]] = {}
        #: per letter, the zoom levels it moves at: {level: its offset there and its distance in letter heights}
        self.level_moves: dict[str, dict[int, tuple[float, float, float]]] = {}
        self.hidden_at, self.level_rules = self._zoom_placing() if style.camera else ({}, [])
        #: the end state's letters (:meth:`place_end`): {id: (dx, dy, distance)} about their points, in the
        #: letters' own units, and the rules that set them there
        self.end_spots: dict[str, tuple[float, float, float]] = {}
        self.end_rules: list[str] = []
        #: name tags: {point id: (dx, dy, distance in letter heights)}, and the levels each gives way at
        self.tag_spots: dict[str, tuple[float, float, float]] = {}
        self.tag_hidden: dict[str, str] = {}
        #: the levels a name tag stands elsewhere at: {point id: {level: (dx, dy, distance)}}
        self.tag_moves: dict[str, dict[int, tuple[float, float, float]]] = {}

    def labels(self) -> tuple[PlacedLabel, ...]:
        """Every placed letter of the whole figure, in mark order, as data (:class:`PlacedLabel`)."""
        camera = self.style.camera
        out = []
        for m in self.lettered:
            x, y, dist, thin = self.spots[m.id]
            px, py = self.vp.px(*m.geom)
            out.append(PlacedLabel(m.id, m.name, m.label or "", m.role, (px, py), (x - px, y - py), dist,
                                   not (thin and (camera or m.role != "result")), at=tuple(m.geom)))
        return tuple(out)

    def letters_at(self, lvl: int) -> Any:
        """The letters zoom level *lvl* shows, moves applied: an array of rows (point x, y, then the box of the
        letter about the point: x0, y0, x1, y1 less the point's x, y), canvas pixels (made once a level)."""
        got = self._rows.get(lvl)
        if got is None:
            st = self.style
            rel = self.level_rel.get(lvl)
            rows = []
            for m in self.lettered:
                px, py = self.vp.px(*m.geom)
                spot = self.spots[m.id]
                if rel is not None:
                    if m.id not in rel:
                        continue
                    dx, dy = rel[m.id]
                elif spot[3] and lvl < THIN_FROM:
                    continue
                else:
                    dx, dy = spot[0] - px, spot[1] - py
                b = label_box(px + dx, py + dy, m.label, st.label_size, st.label_font, st.label_italic)
                rows.append((px, py, b[0] - px, b[1] - py, b[2] - px, b[3] - py))
            rows += self.words
            got = self._rows[lvl] = np.array(rows) if rows else np.zeros((0, 6))
        return got

    def tags_at(self, ks: Sequence[int], lvl: int,
                input_steps: Callable[[int], frozenset[int]]) -> list[tuple[tuple[float, ...], bool]]:
        """The name tags a view of steps *ks* at zoom level *lvl* shows (of its steps and of their inputs):
        (row as in :meth:`letters_at`, is it a tag of the view's own steps?)."""
        by_step = self._tags_by_step
        if by_step is None:
            by_step = self._tags_by_step = {}  # a step may tag several points (the ends S1, S2 of a perpendicular)
            for m in self.scene.marks:
                if m.id in self.tag_spots:
                    by_step.setdefault(m.step, []).append(m)
        st, sc = self.style, self.scene
        out = []
        for m in [m for k in ks for s in {k} | set(input_steps(k)) for m in by_step.get(s, ())
                  if f" h{lvl}" not in self.tag_hidden.get(m.id, "")]:
            px, py = self.vp.px(*m.geom)
            dx, dy, _d = self.tag_moves.get(m.id, {}).get(lvl) or self.tag_spots[m.id]
            b = label_box(px + dx, py + dy, sc.display_name(m.name), st.label_size, st.label_font,
                          st.label_italic)
            out.append(((px, py, b[0] - px, b[1] - py, b[2] - px, b[3] - py), m.step in ks))
        return out

    def _letter_spots(self) -> dict[str, tuple]:
        """Where every letter goes on the canvas (:func:`construct.render.lettering.place`): results first,
        clear of the other letters, the points and the result lines."""
        vp = self.vp
        scale = self.scene.bbox[2] - self.scene.bbox[0]
        items, dots, lines = [], [], []
        for m in self.scene.marks:
            if m.kind is MarkKind.POINT:
                p = vp.px(*m.geom)
                dots.append(p)
                if m.label:
                    items.append((m.id, m.role, m.step, p, label_offset_direction(m.geom, scale=scale), m.label))
            elif m.role == "result" and m.kind.stroked:
                # pieces as close to the line at the deepest zoom level as at the whole figure: the levels'
                # placings magnify them (a crank circle's chords 30 px off it at 8x left room for a letter on it)
                pts = [vp.px(*q) for q in _polyline(m, vp.scale * (ZOOM_LEVELS[-1] if self.style.camera else 1.0))]
                lines.extend((a[0], a[1], b[0], b[1]) for a, b in zip(pts, pts[1:]))
        st = self.style
        self._obstacles = (dots, lines)
        self._letter_items = items
        k = self.letter_scale
        size = k * st.label_size
        soft, taken = None, []
        if self.plate:
            # a plate's letters stand beside every line where they can (a construction line, a tick, an axis
            # as much as a result), and off the furniture's lettering
            thin = [seg for m in self.scene.marks if m.kind.stroked and m.role != "result" and m.look != "hidden"
                    for seg in _segments([vp.px(*q) for q in _polyline(m, vp.scale)])]
            for p in self.furniture:
                if p.kind == "line" or (p.kind == "poly" and "arrow" not in p.cls):
                    thin += _segments(list(p.points) + ([p.points[0]] if p.closed else []))
                elif p.kind == "text":
                    taken.append(furniture_text_box(p, st))
            soft = LineIndex(size, thin)
        spots = place(items, size, dots, self._lines_at(1.0, size), font=st.label_font, italic=st.label_italic,
                      halo=HALO_PX / 2 * k, reach=self.line_reach, soft=soft, taken=taken)
        thin = [it for it in items if spots.get(it[0], (0, 0, 0, False))[3]]
        if thin and st.camera:
            # a letter with no room beside its point stands farther off, tied by a leader, when there is room
            # there: the whole figure's view is the one the steps far apart are seen in, and their captions
            # name it (inertia curve: q6, q7 inside the crank circle's crowd)
            text = {it[0]: it[5] for it in items}
            held = [label_box(x, y, text[i], size, st.label_font, st.label_italic, HALO_PX / 2 * k)
                    for i, (x, y, _d, t) in spots.items() if not t]
            far = place(thin, size, dots, self._lines_at(1.0, size), font=st.label_font, italic=st.label_italic,
                        taken=held, keep=False, halo=HALO_PX / 2 * k, reach=self.line_reach, distances=TAG_FARTHER)
            spots.update(far)
            thin = [it for it in thin if it[0] not in far]
        if thin and st.camera:
            # the letters the whole figure has no room for, placed for the magnified views
            # (from zoom level THIN_FROM on): points twice as far apart, letters at their size
            z = ZOOM_LEVELS[THIN_FROM]
            byid = {it[0]: it for it in items}
            taken = [label_box(byid[i][3][0] * z + (x - byid[i][3][0]), byid[i][3][1] * z + (y - byid[i][3][1]),
                               byid[i][5], size, st.label_font, st.label_italic, HALO_PX / 2 * k)
                     for i, (x, y, _d, t) in spots.items() if not t]
            again = place([(i, r, s_, (p[0] * z, p[1] * z), d, t) for i, r, s_, p, d, t in thin], size,
                          [(x * z, y * z) for x, y in dots], [tuple(c * z for c in seg) for seg in lines],
                          font=st.label_font, italic=st.label_italic, taken=taken, keep=False, halo=HALO_PX / 2 * k, reach=self.line_reach)
            for i, r, s_, p, d, t in thin:
                got = again.get(i)
                if got is None and r != "result":
                    del spots[i]  # no room even magnified: left out, never stacked
                elif got is None:
                    pass  # a result's letter is never left out: the magnified views show it where it was
                else:
                    spots[i] = (p[0] + got[0] - p[0] * z, p[1] + got[1] - p[1] * z, got[2], True)
        if k != 1.0:
            # placed at the size the player shows the whole figure at; written for the canvas (offsets / k)
            pts = {m.id: vp.px(*m.geom) for m in self.scene.marks if m.id in spots}
            spots = {i: (pts[i][0] + (x - pts[i][0]) / k, pts[i][1] + (y - pts[i][1]) / k, d, thin)
                     for i, (x, y, d, thin) in spots.items()}
        return spots

    def _zoom_placing(self) -> tuple[dict[str, str], list[str]]:
        """Letters placed again for every zoom level: (classes per letter, CSS rules).

        A magnified view keeps letters at their screen size while the points move
        apart, so the whole figure's spots may collide there.  For every zoom level
        (:data:`construct.render.camera.ZOOM_LEVELS`) the placer runs again over all
        letters with points and result lines spread by the level's zoom; a letter
        whose spot differs gets a rule that moves it at that level (``.zlN
        #id>*{transform:scale(..) translate(..)}``), one with no room hides there
        (class ``hN``): a magnified view never stacks letters either.
        """
        st = self.style
        size = st.label_size
        items = self._letter_items
        classes: dict[str, str] = {}
        rules: list[str] = []
        moves: dict[tuple[str, str], list[int]] = {}
        for lvl, z in enumerate(ZOOM_LEVELS[1:], start=1):
            its = [(i, r, s_, (p[0] * z, p[1] * z), d, t) for i, r, s_, p, d, t in items
                   if i in self.spots and (lvl >= THIN_FROM or not self.spots[i][3])]
            # letters at the size the player shows them at this level (on the zoomed canvas)
            f = self.letter_scale_at(z) * z
            # each letter where it stands in the whole figure if there is room for it there
            prefer = {i: ((self.spots[i][0] - p[0] / z) * f, (self.spots[i][1] - p[1] / z) * f, self.spots[i][2])
                      for i, _r, _s, p, _d, _t in its}
            got = place(its, size * f, _scaled(self._obstacle_arrays()[0], z), self._lines_at(z, size * f),
                        font=st.label_font, italic=st.label_italic, keep=False, prefer=prefer, halo=HALO_PX / 2 * f, reach=self.line_reach)
            for i, _r, _s, (zx, zy), _d, _t in its:
                spot = got.get(i)
                if spot is None:
                    classes[i] = classes.get(i, "") + f" h{lvl}"
                    continue
                x, y = self.spots[i][0], self.spots[i][1]
                px, py = zx / z, zy / z
                ddx, ddy = (spot[0] - zx) / f - (x - px), (spot[1] - zy) / f - (y - py)
                if abs(ddx) <= 0.5 and abs(ddy) <= 0.5:
                    ddx = ddy = 0.0
                self.level_rel.setdefault(lvl, {})[i] = (x - px + ddx, y - py + ddy)
                if abs(ddx) > 0.5 or abs(ddy) > 0.5:
                    moves.setdefault((i, f"translate({fmt(ddx)}px,{fmt(ddy)}px)"), []).append(lvl)
                    classes[i] = classes.get(i, "") + " lbm"  # moved at some level: the group carries an id
                    # the letter's leader is drawn anew there, from the point to where the letter stands
                    self.level_moves.setdefault(i, {})[lvl] = (x - px + ddx, y - py + ddy, spot[2])
        # one rule per letter and move, listing the levels it holds at (--zs: the level's letter scale); the
        # letter moves, its leader does not (the level has a leader of its own, :meth:`leaders`)
        for (i, move), lvls in moves.items():
            rules.append(",".join(f".zl{lvl} #{i}-lb>.lb" for lvl in lvls)
                         + f"{{transform:scale(var(--ls,var(--zs))) {move}}}")
        return classes, rules

    def leaders(self, mid: str, rel: tuple[float, float, float],
                text: str = "") -> list[tuple[tuple[float, float, float, float], str]]:
        """The leaders of letter *mid* standing at *rel* (offset, distance in letter heights) in the whole
        figure: ((x1, y1, x2, y2) about its point in the letter's units, classes), one for every place it
        stands at -- the whole figure's (hidden at the levels it moves at: ``mN``), each zoom level it
        moves at (``lvN``, shown at that level only) and the end state's (``lvf``) -- each from its point to
        the letter *text* there, and none where the letter stands close enough to be read as its point's.
        """
        out = []
        moved = self.level_moves.get(mid, {})
        if rel[2] >= LEADER_FROM:
            out.append((self.leader_line(rel[0], rel[1], text), "".join(f" m{lvl}" for lvl in sorted(moved))))
        for lvl, (dx, dy, dist) in sorted(moved.items()):
            if dist >= LEADER_FROM:
                out.append((self.leader_line(dx, dy, text), f" lv{lvl}"))
        end = self.end_spots.get(mid)
        if end is not None and end[2] >= LEADER_FROM:
            out.append((self.leader_line(end[0], end[1], text), " lvf"))
        return out

    def leader_line(self, dx: float, dy: float, text: str = "") -> tuple[float, float, float, float]:
        """A leader from a point to its letter *text* set at (dx, dy) from it (the baseline's middle, letter
        units): from a quarter letter off the point to where it meets the letter's white -- a wide letter
        (M₁ 19°12′) is not run into, a narrow one (I) not left short of -- or, without *text*, to three quarters
        short of the letter's middle."""
        st = self.style
        size = st.label_size
        cx, cy = dx, dy - 0.35 * size
        n = math.hypot(cx, cy) or 1.0
        a, b = 0.25 * size, n - 0.75 * size
        if text:
            entry = _entry(label_box(dx, dy, text, size, st.label_font, st.label_italic), cx / n, cy / n)
            if math.isfinite(entry):
                b = max(a, entry)
        return (a * cx / n, a * cy / n, b * cx / n, b * cy / n)

    def place_end(self, letter: float, marks: Sequence[Mark], taken: Sequence[tuple[float, float, float, float]],
                  lettering: Sequence[tuple[str, tuple[float, float], str]] = (),
                  strokes: Sequence[tuple[float, float, float, float]] = ()) -> None:
        """Place the end state's letters (:meth:`construct.render.scene.Scene.in_end`): the lettered points of
        its *marks*, among its points and result lines and clear of the boxes *taken* (canvas px: its
        furniture's scales and dimensions), at *letter* canvas units a letter unit (the player's letter scale
        at the end view).  Each stays where the whole figure set it when there is room; one with none is left
        out of the end state (class ``pf`` marks the placed).  The plate's *lettering* (id, the point it is
        written at, canvas px, text: the values of its ordinates) is placed with them, first where the plate
        writes it, else beside it; the plate's *strokes* (canvas px: its ordinates) are kept clear of as its
        result lines are.  Sets :attr:`end_spots` and :attr:`end_rules`.
        """
        st = self.style
        size = st.label_size * letter
        span = self.scene.bbox[2] - self.scene.bbox[0]
        look = self.scene.end_look
        dots = [self.vp.px(*m.geom) for m in marks if m.kind is MarkKind.POINT and "hidden" not in look(m).split()]
        lines = list(strokes)
        for m in marks:
            if m.role == "result" and m.kind.stroked and "hidden" not in look(m).split():
                pts = [self.vp.px(*q) for q in _polyline(m, self.vp.scale)]
                lines.extend((a[0], a[1], b[0], b[1]) for a, b in zip(pts, pts[1:]))
        items, prefer = [], {}
        for fid, at, text in lettering:
            items.append((fid, "result", 0, at, (0.0, 1.0), text))
            prefer[fid] = (0.0, 0.35 * size, 0.0)
        for m in marks:
            if not m.label:
                continue
            p = self.vp.px(*m.geom)
            items.append((m.id, m.role, m.step, p, label_offset_direction(m.geom, scale=span), m.label))
            spot = self.spots.get(m.id)
            if spot is not None:
                prefer[m.id] = ((spot[0] - p[0]) * letter, (spot[1] - p[1]) * letter, spot[2])
        got = place(items, size, dots, LineIndex(size, lines), font=st.label_font, italic=st.label_italic,
                    taken=list(taken), keep=False, prefer=prefer, halo=HALO_PX / 2 * letter, reach=self.line_reach)
        spots, rules = {}, []
        for mid, _r, _s, (px, py), _d, _t in items:
            spot = got.get(mid)
            if spot is None:
                continue
            rel = ((spot[0] - px) / letter, (spot[1] - py) / letter, spot[2])
            spots[mid] = rel
            base = self.spots.get(mid)
            if base is None:
                continue  # an end mark's letter: drawn where it stands here (it stands nowhere else)
            dx, dy = rel[0] - (base[0] - px), rel[1] - (base[1] - py)
            rules.append(f".fin #{mid}-lb>.lb{{transform:scale(var(--ls,var(--zs,1))) "
                         f"translate({fmt(dx)}px,{fmt(dy)}px)}}")
        self.end_spots, self.end_rules = spots, rules

    def place_tags(self, views: Sequence[View], full: View,
                   input_steps: Callable[[int], frozenset[int]]) -> None:
        """Where each shown name tag goes: {point id: (dx, dy, distance in letter heights)} about its point.

        A tag names an operand while its step is current or an input; it is placed like a letter
        (:func:`construct.render.lettering.place`), clear of the points, the result lines, the letters
        and the other tags, in the view of its own step (at that view's zoom level, where the points
        stand farther apart than in the whole figure).  A tag with no free spot there is left out,
        never stacked on another.
        """
        sc, st = self.scene, self.style
        tags = [m for m in sc.marks if m.kind is MarkKind.POINT and not m.label and sc.tag_shown(m.name)]
        if not tags:
            return
        # the levels of the player's views; the one level of an unmagnified figure
        levels, thin_from = (ZOOM_LEVELS, THIN_FROM) if st.camera else ((1.0,), 0)
        span = sc.bbox[2] - sc.bbox[0]
        # a tag is seen while its step is current and where its step is an input: it is placed at the
        # least magnified of those views (where the letters are largest beside the points)
        lowest: dict[int, int] = {}
        if st.camera:
            step_levels = [level(zoom_of(v, full)) for v in views]

            def lvl_of(k: int) -> int:
                return step_levels[k - 1]

            steps = {m.step for m in tags}
            for m in tags:
                lowest[m.step] = lvl_of(m.step)
            for k in range(1, len(sc.steps) + 1):
                for s_ in input_steps(k):
                    if s_ in steps:
                        lowest[s_] = min(lowest[s_], lvl_of(k))
        by_level: dict[int, list[Mark]] = {}
        for m in tags:
            by_level.setdefault(lowest.get(m.step, 0), []).append(m)
        shown_at: dict[int, set[int]] = {m.step: {lowest.get(m.step, 0)} for m in tags}
        if st.camera:
            for m in tags:
                shown_at[m.step].add(lvl_of(m.step))
            for k in range(1, len(sc.steps) + 1):
                for s_ in input_steps(k):
                    if s_ in shown_at:
                        shown_at[s_].add(lvl_of(k))
        size = st.label_size
        pts = {m.id: self.vp.px(*m.geom) for m in sc.marks if m.kind is MarkKind.POINT}
        labels = [m for m in sc.marks if m.kind is MarkKind.POINT and m.label and m.id in self.spots]

        def frame(lvl: int):
            """(zoom, letter factor, boxes of the letters shown at level *lvl*) in that level's geometry."""
            z = levels[lvl]
            f = self.letter_scale_at(z) * z if st.camera else 1.0
            rel = self.level_rel.get(lvl)
            boxes = []
            for m in labels:
                if rel is not None:
                    if m.id not in rel:
                        continue
                    dx, dy = rel[m.id]
                else:
                    spot = self.spots[m.id]
                    if spot[3] and lvl < thin_from:
                        continue
                    dx, dy = spot[0] - pts[m.id][0], spot[1] - pts[m.id][1]
                px, py = pts[m.id]
                boxes.append(label_box(px * z + dx * f, py * z + dy * f, m.label, st.label_size * f, st.label_font,
                                       st.label_italic, HALO_PX / 2 * f))
            return z, f, boxes

        # the points and result lines as arrays, asked once per level and group of tags below
        dot_a, line_a = self._obstacle_arrays()
        line_lo = np.minimum(line_a[:, 0:2], line_a[:, 2:4])
        line_hi = np.maximum(line_a[:, 0:2], line_a[:, 2:4])

        reach = (max(TAG_FARTHER) + 3.0) * size  # how far from its point a tag's box may reach (letter units)

        def near(items, z: float, f: float):
            """The points and the numbers of the result lines (at zoom *z*) a tag of *items* could meet:
            within its reach (the lines as a mask over the level's :meth:`_lines_at`): as far as a tag's box
            reaches from its point (a tag 14 letter heights off reached beyond a window of 8, and the crank
            circle's pieces crossing it there went unseen)."""
            xs = [it[3][0] for it in items]
            ys = [it[3][1] for it in items]
            r = reach * f
            x0, y0, x1, y1 = min(xs) - r, min(ys) - r, max(xs) + r, max(ys) + r
            dz = dot_a * z
            ds = dz[(x0 <= dz[:, 0]) & (dz[:, 0] <= x1) & (y0 <= dz[:, 1]) & (dz[:, 1] <= y1)]
            lo, hi = line_lo * z, line_hi * z
            mask = (lo[:, 0] <= x1) & (hi[:, 0] >= x0) & (lo[:, 1] <= y1) & (hi[:, 1] >= y0)
            return list(map(tuple, ds.tolist())), mask.tolist()

        # per level, the tags' steps seen together in some view of that level (a step and its inputs)
        seen_with: dict[int, dict[int, set[int]]] = {}
        if st.camera:
            tag_steps = {m.step for m in tags}
            for k in range(1, len(sc.steps) + 1):
                together = ({k} | input_steps(k)) & tag_steps
                mates = seen_with.setdefault(lvl_of(k), {})
                for s_ in together:
                    mates.setdefault(s_, set()).update(together)
        byid = {m.id: m for m in tags}
        out: dict[str, tuple[float, float, float]] = {}
        frames: dict[int, tuple] = {}
        tags_of: dict[int, list[Mark]] = {}
        for m in tags:
            tags_of.setdefault(m.step, []).append(m)

        def place_at(m: Mark, lvl: int) -> bool:
            """Place tag *m* at level *lvl*, clear of the letters there and of the tags placed so far that are
            seen with it at that level (tags never seen together may share a spot)."""
            if lvl not in frames:
                z, f, boxes = frame(lvl)
                frames[lvl] = (z, f, np.array(boxes, dtype=float).reshape(-1, 4))
            z, f, boxes = frames[lvl]
            x, y = pts[m.id][0] * z, pts[m.id][1] * z
            r = reach * f
            near_ = boxes[(boxes[:, 2] >= x - r) & (boxes[:, 0] <= x + r) & (boxes[:, 3] >= y - r) & (boxes[:, 1] <= y + r)]
            taken = list(map(tuple, near_.tolist())) + [
                label_box(pts[o.id][0] * z + out[o.id][0] * f, pts[o.id][1] * z + out[o.id][1] * f,
                          sc.display_name(o.name), size * f, st.label_font, st.label_italic, HALO_PX / 2 * f)
                for k in seen_with.get(lvl, {}).get(m.step, ()) if lvl in shown_at[k]
                for o in tags_of.get(k, ()) if o.id in out]
            if st.ring_px and lvl == lowest.get(m.step, 0):
                # the ring the player draws round the point while its step is current: the tag beside it, not under
                rr = st.ring_px * f
                taken.append((x - rr, y - rr, x + rr, y + rr))
            item = (m.id, m.role, m.step, (x, y), label_offset_direction(m.geom, scale=span), sc.display_name(m.name))
            ds, only = near([item], z, f)
            got = place([item], size * f, ds, self._lines_at(z, size * f), only=only, font=st.label_font,
                        italic=st.label_italic, taken=taken, keep=False, halo=HALO_PX / 2 * f,
                        reach=self.line_reach, distances=TAG_FARTHER)
            if m.id not in got:
                return False
            gx, gy, dist, _thin = got[m.id]
            out[m.id] = ((gx - x) / f, (gy - y) / f, dist)
            return True

        # each tag at the least magnified level it is seen at, in the placer's order (results first)
        hidden: dict[str, str] = {}
        for lvl, ms in sorted(by_level.items()):
            for m in sorted(ms, key=lambda m: (RANK.get(m.role, 2), m.step, m.id)):
                place_at(m, lvl)
        # a tag with no room there takes its spot at the next level that has room (a step's caption names it),
        # given way at the levels below
        for m in tags:
            if m.id not in out:
                for lvl in sorted(shown_at[m.step] - {lowest.get(m.step, 0)}):
                    if place_at(m, lvl):
                        hidden[m.id] = "".join(f" h{lo}" for lo in sorted(shown_at[m.step]) if lo < lvl)
                        break
        # every level a tag is seen at: it holds its spot there, or it gives way there (class hN),
        # never stacked on a letter, a point, a result line or a tag seen with it
        moves: dict[str, dict[int, tuple[float, float, float]]] = {}
        for lvl in sorted({v for vs in shown_at.values() for v in vs}):
            z, f, taken = frame(lvl)
            here = [byid[i] for i in out if lvl in shown_at[byid[i].step]]
            if all(lowest.get(m.step, 0) == lvl for m in here):
                continue  # placed together at this level, against the same letters: nothing to check
            items = [(m.id, m.role, m.step, (pts[m.id][0] * z, pts[m.id][1] * z), (1.0, 0.0), sc.display_name(m.name))
                     for m in here]
            prefer = {m.id: (out[m.id][0] * f, out[m.id][1] * f, out[m.id][2]) for m in here}
            ds, only = near(items, z, f)
            got = place(items, size * f, ds, self._lines_at(z, size * f), only=only,
                        font=st.label_font, italic=st.label_italic, taken=taken, keep=False, prefer=prefer,
                        halo=HALO_PX / 2 * f, reach=self.line_reach)
            def kept(got, items) -> set[str]:
                return {i for i, _r, _s, (zx, zy), _d, _t in items if (spot := got.get(i)) is not None
                        and abs(spot[0] - zx - prefer[i][0]) <= 1e-6 and abs(spot[1] - zy - prefer[i][1]) <= 1e-6}

            holds = kept(got, items)
            arrays = None
            losers = []
            for it in items:
                i = it[0]
                if i in holds:
                    continue
                # it lost its spot to all the tags of the level together; it holds it where it is seen only
                # with the tags seen together with it (crank step 181: M1 gave way to tags never shown with it)
                mates = seen_with.get(lvl, {}).get(byid[i].step, set())
                local = [o for o in items if byid[o[0]].step in mates and (o[0] in holds or o[0] == i)]
                if len(local) < len(items):
                    # it holds its spot where the spot is free of the level's letters, points and result
                    # lines (as the placer asks) and of the tags seen with it (arrays made once per level)
                    if arrays is None:
                        arrays = (np.array(ds, dtype=float).reshape(-1, 2),
                                  (line_a[np.array(only, dtype=bool)] * z).reshape(-1, 4),
                                  np.array(taken, dtype=float).reshape(-1, 4))
                    ds, ls_, tk = arrays

                    def spot_box(o):
                        return label_box(o[3][0] + prefer[o[0]][0], o[3][1] + prefer[o[0]][1], o[5], size * f,
                                         st.label_font, st.label_italic, HALO_PX / 2 * f)

                    b = spot_box(it)
                    rr = 0.3 * size * f
                    e = self.line_reach
                    free = not any(b[0] < c[2] and c[0] < b[2] and b[1] < c[3] and c[1] < b[3]
                                   for c in (spot_box(o) for o in local if o[0] != i))
                    free = free and not ((tk[:, 0] < b[2]) & (b[0] < tk[:, 2]) & (tk[:, 1] < b[3])
                                         & (b[1] < tk[:, 3])).any()
                    free = free and not ((ds[:, 0] - rr < b[2]) & (b[0] < ds[:, 0] + rr) & (ds[:, 1] - rr < b[3])
                                         & (b[1] < ds[:, 1] + rr)).any()
                    if free and len(ls_):
                        # a result line crossing the box widened by the line's half width (clipped to it)
                        p0, dv = ls_[:, :2], ls_[:, 2:] - ls_[:, :2]
                        with np.errstate(divide="ignore", invalid="ignore"):
                            ta = (np.array([b[0] - e, b[1] - e]) - p0) / dv
                            tb = (np.array([b[2] + e, b[3] + e]) - p0) / dv
                            t_in = np.nan_to_num(np.minimum(ta, tb), nan=-np.inf)
                            t_out = np.nan_to_num(np.maximum(ta, tb), nan=np.inf)
                        inside = (dv != 0) | ((p0 >= np.array([b[0] - e, b[1] - e])) & (p0 <= np.array([b[2] + e, b[3] + e])))
                        t0 = np.maximum(0.0, np.where(dv != 0, t_in, -np.inf).max(axis=1))
                        t1 = np.minimum(1.0, np.where(dv != 0, t_out, np.inf).min(axis=1))
                        free = not ((t0 <= t1) & inside.all(axis=1)).any()
                    if free:
                        holds.add(i)  # the tags it is seen with after it are placed with it
                        continue
                losers.append(it)
            if losers:
                # a tag with no room at its spot stands elsewhere at this level, clear of the letters and of the
                # tags that hold theirs (a step's caption names it: it is never left out while there is room)
                held = [label_box(o[3][0] + prefer[o[0]][0], o[3][1] + prefer[o[0]][1], o[5], size * f, st.label_font,
                                  st.label_italic, HALO_PX / 2 * f) for o in items if o[0] in holds]
                again = place(losers, size * f, ds, self._lines_at(z, size * f), only=only, font=st.label_font,
                              italic=st.label_italic, taken=taken + held, keep=False, halo=HALO_PX / 2 * f,
                              reach=self.line_reach, distances=TAG_FARTHER)
                for it in losers:
                    i, (zx, zy) = it[0], it[3]
                    spot = again.get(i)
                    if spot is None:
                        hidden[i] = hidden.get(i, "") + f" h{lvl}"
                    else:
                        moves.setdefault(i, {})[lvl] = ((spot[0] - zx) / f, (spot[1] - zy) / f, spot[2])
        self.tag_hidden = hidden
        self.tag_moves = moves
        self.tag_spots = out

    def _obstacle_arrays(self) -> tuple[Any, Any]:
        """The points and the result lines' segments the letters keep clear of, as arrays (made once)."""
        got = self._obstacle_a
        if got is None:
            dots, lines = self._obstacles
            got = self._obstacle_a = (np.array(dots, dtype=float).reshape(-1, 2),
                                                  np.array(lines, dtype=float).reshape(-1, 4))
        return got

    def clear_of_results(self, box: tuple[float, float, float, float]) -> bool:
        """Is *box* (canvas px) clear of the points and the result lines the letters keep clear of (a word the
        drawing writes beside them: the rod's length at a break)?"""
        dots, _ = self._obstacle_arrays()
        if ((dots[:, 0] >= box[0]) & (dots[:, 0] <= box[2]) & (dots[:, 1] >= box[1]) & (dots[:, 1] <= box[3])).any():
            return False
        reach = max(self.style.result_width, 2.2) / 2  # (2.2: the plates' heavy look)
        if self._lines_at(1.0, self.style.label_size).meets(box, reach):
            return False
        return not _overlaps(box, self.letter_boxes())

    def letter_boxes(self) -> list[tuple[float, float, float, float]]:
        """The box (canvas px) of every letter placed in the whole figure (made once)."""
        got = self.__dict__.get("_letter_boxes")
        if got is None:
            st = self.style
            got = self.__dict__["_letter_boxes"] = [
                label_box(p.point[0] + p.offset[0], p.point[1] + p.offset[1], p.text, st.label_size, st.label_font,
                          st.label_italic) for p in self.labels() if p.shown]
        return got

    def _lines_at(self, z: float, size: float) -> Any:
        """The result lines magnified *z* times, indexed for letters of *size*
        (:class:`construct.render.lettering.LineIndex`): made once for every placing at that zoom."""
        cache = self._line_index
        key = (z, size)
        if key not in cache:
            cache[key] = LineIndex(size, _scaled(self._obstacle_arrays()[1], z))
        return cache[key]

    @property
    def line_reach(self) -> float:
        """Half the width of the widest result line, in the units letters are placed in: canvas pixels,
        or with a camera the player's screen pixel at the whole figure (its strokes do not scale, and
        the placing works in each zoom level's magnified canvas, where that pixel is the same)."""
        half = max(self.style.result_width, 2.2) / 2  # 2.2: the plates' heavy look
        if not self.style.camera:
            return half
        return half * max(self.vp.width / PLAYER_FIGURE_PX[0], self.drawing_height / PLAYER_FIGURE_PX[1])

    @property
    def letter_scale(self) -> float:
        """How much larger than on the canvas the player draws letters in the whole-figure view.

        The player (a 1400 × 900 window) shows the figure at most about
        :data:`PLAYER_FIGURE_PX` wide and tall and holds letters at 12 px, never below 9.5 px
        on the screen (its ``--ls``); a tall figure shown at half its size gets letters 1.6
        times their canvas size, and they are placed at that size.  1 without a camera.
        """
        return self.letter_scale_at(1.0) if self.style.camera else 1.0

    def letter_scale_at(self, zoom: float) -> float:
        """The player's letter scale (its ``--ls``: canvas units per letter unit) in a view magnifying *zoom*
        times: letters at 12 px on the screen, never below 9.5 px (:attr:`letter_scale` for the whole)."""
        q = max(self.vp.width / PLAYER_FIGURE_PX[0], self.drawing_height / PLAYER_FIGURE_PX[1]) / zoom
        if zoom == 1.0 and q <= 1.0:
            return 1.0  # the whole figure as drawn on the canvas
        return min(max(1.0, 9.5 * q / self.style.label_size), q)


def _polyline(m: Mark, scale: float) -> list[tuple[float, float]]:
    """A line mark as points (drawing units) joined by straight pieces no more than ~4 px off it."""
    g = m.geom
    if m.kind is MarkKind.SEGMENT:
        return [(g[0], g[1]), (g[2], g[3])]
    if m.kind.round:
        cx, cy, r = g[0], g[1], g[2]
        a0, sw = (0.0, 2 * math.pi) if m.kind is MarkKind.CIRCLE else (g[3], g[4])
        n = min(720, max(8, int(abs(sw) * math.sqrt(max(r * scale, 1.0) / 8.0)) + 1))
        return [(cx + r * math.cos(a0 + sw * i / n), cy + r * math.sin(a0 + sw * i / n)) for i in range(n + 1)]
    if m.kind is MarkKind.CURVE and not m.straight and len(g) > 2:
        # as drawn (curve_path): the Catmull-Rom pieces, which leave the chords where the curve bends
        out = [tuple(g[0])]
        for p1, c1, c2, p2 in bezier_controls(g):
            for t in (0.25, 0.5, 0.75, 1.0):
                s = 1 - t
                out.append(tuple(s * s * s * a + 3 * s * s * t * b + 3 * s * t * t * c + t * t * t * d
                                 for a, b, c, d in zip(p1, c1, c2, p2)))
        return out
    return list(g)


def _segments(pts: Sequence[tuple[float, float]]) -> list[tuple[float, float, float, float]]:
    return [(a[0], a[1], b[0], b[1]) for a, b in zip(pts, pts[1:])]


def furniture_text_box(p: Any, style: Style, grow: float = HALO_PX / 2) -> tuple[float, float, float, float]:
    """The upright box (pixels) a plate's lettering (a ``text`` :class:`construct.render.plate.Piece`) covers
    with its halo, turned or not."""
    return text_gap(p, style, grow).reach()


def text_gap(p: Any, style: Style, grow: float) -> Gap:
    """The box a plate's lettering (a ``text`` :class:`construct.render.plate.Piece`: set about its point, the
    middle of its height) covers, grown by *grow* pixels round its ink, turned with it: a :class:`Gap`."""
    size = style.label_size * p.size
    (x, y), = p.points
    box = text_box(x, y + 0.35 * size, plain(p.text), size, style.label_font, style.label_italic, p.anchor)
    return Gap.around(box, grow, p.angle, about=(x, y))


def _scaled(rows: Any, z: float) -> list[tuple[float, ...]]:
    """Every coordinate of *rows* (an array of points or segments) times *z*, as tuples
    (the same numbers as multiplying one by one, made at once: a figure has thousands)."""
    return list(map(tuple, (rows * z).tolist()))



def place_outwards(m: Mark, vp: Viewport, style: Style, span: float,
                   placed: list[tuple[float, float, float, float]]) -> tuple[float, float] | None:
    """Where *m*'s letter goes in a viewport of its own (the magnified inset), where the letters are not
    placed by rank: radially outwards from its point, else the other side, else left out (None).  *span*:
    the width of the figure (drawing units); *placed*: the boxes taken so far, to which the letter's is added."""
    dx, dy = label_offset_direction(m.geom, scale=span)
    off = style.label_size * 0.9
    px, py = vp.px(*m.geom)
    for sign in (1.0, -1.0):
        lx, ly = px + sign * dx * off, py - sign * dy * off + style.label_size * 0.35
        box = label_box(lx, ly, m.label or "", style.label_size, style.label_font, style.label_italic)
        if not _overlaps(box, placed):
            placed.append(box)
            return lx, ly
    return None


def _overlaps(box, placed) -> bool:
    x0, y0, x1, y1 = box
    return any(x0 < b[2] and b[0] < x1 and y0 < b[3] and b[1] < y1 for b in placed)


def _entry(box: tuple[float, float, float, float], ux: float, uy: float) -> float:
    """How far along the unit direction (ux, uy) from the origin a ray enters *box* (infinity: it misses)."""
    t_in, t_out = 0.0, math.inf
    for u, lo, hi in ((ux, box[0], box[2]), (uy, box[1], box[3])):
        if abs(u) < 1e-12:
            if not lo <= 0.0 <= hi:
                return math.inf
            continue
        t0, t1 = sorted((lo / u, hi / u))
        t_in, t_out = max(t_in, t0), min(t_out, t1)
    return t_in if t_in <= t_out else math.inf
