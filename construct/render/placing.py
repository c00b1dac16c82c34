"""Where a drawing's letters and name tags stand: :func:`construct.render.lettering.place` run over a scene.

A :class:`Placing` places every letter of a scene on its canvas once (results
first, clear of the points and the result lines), again for each zoom level of
the player's camera (a letter that moves or gives way there gets a class and a
rule), and the name tags in the views that show them (:mod:`construct.render.tags`).  The drawing
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

from .camera import PLAYER_FIGURE_PX, THIN_FROM, ZOOM_LEVELS, View
from .gaps import Gap
from .lettering import HALO_PX, LEADER_FROM, LineIndex, label_box, near_rows, place, spots_extent, text_box
from .paths import bezier_arrays
from .plate import plain
from .scene import Mark, MarkKind, Scene, label_offset_direction
from .styles import Style
from .svgdoc import fmt
from .tags import TAG_FARTHER, place_tags
from .viewport import Viewport

__all__ = ["PlacedLabel", "Placing", "crowded", "furniture_text_box", "text_gap", "TAG_FARTHER"]



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
        self._row_ids: dict[int, list[str]] = {}
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
        #: the end state's letters (and the plate's lettering) set touching one another, by pairs of ids
        self.end_touching: set[frozenset[str]] = set()
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
            rows, ids = [], []
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
                ids.append(m.id)
            rows += self.words
            got = self._rows[lvl] = np.array(rows) if rows else np.zeros((0, 6))
            self._row_ids[lvl] = ids
        return got

    def letter_ids(self, lvl: int) -> list[str]:
        """The ids of the points whose letters are the first rows of :meth:`letters_at` (*lvl*); the rest of its
        rows are the rod's length written at a break (:attr:`words`)."""
        self.letters_at(lvl)
        return self._row_ids[lvl]

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
        spots = place(items, size, dots, self.lines_at(1.0, size), font=st.label_font, italic=st.label_italic,
                      halo=HALO_PX / 2 * k, reach=self.line_reach, soft=soft, taken=taken)
        thin = [it for it in items if spots.get(it[0], (0, 0, 0, False))[3]]
        if thin and st.camera:
            # a letter with no room beside its point stands farther off, tied by a leader, when there is room
            # there: the whole figure's view is the one the steps far apart are seen in, and their captions
            # name it (inertia curve: q6, q7 inside the crank circle's crowd)
            text = {it[0]: it[5] for it in items}
            held = [label_box(x, y, text[i], size, st.label_font, st.label_italic, HALO_PX / 2 * k)
                    for i, (x, y, _d, t) in spots.items() if not t]
            far = place(thin, size, dots, self.lines_at(1.0, size), font=st.label_font, italic=st.label_italic,
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
            got = place(its, size * f, _scaled(self.obstacle_arrays()[0], z), self.lines_at(z, size * f),
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
        items, got, _, _ = self._end_place(self.vp, letter, marks, taken, lettering, strokes, lettered=True)
        # the letters the placer set touching one another here (they may touch at another value too)
        size = self.style.label_size * letter
        boxes = [(mid, label_box(got[mid][0], got[mid][1], text, size, self.style.label_font, self.style.label_italic))
                 for mid, _r, _s, _p, _d, text in items if mid in got]
        self.end_touching = {frozenset((a, b)) for i, (a, p) in enumerate(boxes) for b, q in boxes[i + 1:]
                             if _meet(p, q)}
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

    def end_lettering_at(self, vp: Viewport, letter: float, marks: "Sequence[Mark] | Callable[[], Sequence[Mark]]",
                         taken: Sequence[tuple[float, float, float, float]],
                         lettering: Sequence[tuple[str, tuple[float, float], str]],
                         strokes: Sequence[tuple[float, float, float, float]] = (),
                         lettered: Sequence[Mark] | None = None) -> dict[str, tuple[float, float, float]]:
        """The plate's *lettering* placed as :meth:`place_end` places it, at another value of a live given: its end
        state's *marks*, *taken* boxes and *strokes* those of that value (drawn on *vp*), at the built end state's
        *letter* scale (the page's there; a fresh build's end state keeps it too); the marks' own letters
        stand where :attr:`end_spots` set them about their points (the live page moves them with their points, at
        *letter*) and are kept clear of.  {id: (dx, dy, distance)} as :attr:`end_spots` has them, for the letters
        that move: each stays where it stood at the built value unless it would lie there on another letter or on
        the plate's other writing (the values the plate writes crowd as the figure changes: Tafel 2's inertia
        pressures at L/r = 2 were written on one another where the built offsets were kept everywhere); those
        are placed anew among the rest.  *marks* may be given as a function that makes them, and *lettered* as
        those of them that are lettered (:meth:`end_lettered`, in their order): where nothing crowds, only their
        letters are read (a live sweep asks at every value, and the rest of the marks, a curve's hundreds of
        points, are made only where a letter is placed anew)."""
        st = self.style
        size = st.label_size * letter
        held = list(taken)
        if lettered is None:
            marks = lettered = marks() if callable(marks) else marks
        crowd, letters, at = self._end_crowd(vp, letter, lettered, taken, lettering, self.end_spots)
        if not crowd:
            return {}
        marks = marks() if callable(marks) else marks
        held += list(letters.values()) + [b for f, b in at.items() if f not in crowd]
        lettering = [it for it in lettering if it[0] in crowd or it[0] not in at]
        items, got, dots, lines = self._end_place(vp, letter, marks, held, lettering, strokes, lettered=False)
        # a letter the crowd sends off beyond a leader's reach where the built one stood near (or the other way
        # round) would change the plate's elements, which the page knows by their order: it stands as near as it
        # is free of the other letters and points, crossing the lines if it must (they are soft for it)
        lead = {fid for fid, _r, _s, _p, _d, _t in items if fid in got and fid in self.end_spots
                and (got[fid][2] >= LEADER_FROM) != (self.end_spots[fid][2] >= LEADER_FROM)}
        if lead:
            others = [label_box(got[f][0], got[f][1], t, size, st.label_font, st.label_italic)
                      for f, _r, _s, _p, _d, t in items if f in got and f not in lead]
            got.update(place([it for it in items if it[0] in lead], size, dots, LineIndex(size, []),
                             font=st.label_font, italic=st.label_italic, taken=held + others, keep=False,
                             halo=HALO_PX / 2 * letter, reach=self.line_reach, soft=LineIndex(size, lines)))
        return {fid: ((spot[0] - px) / letter, (spot[1] - py) / letter, spot[2])
                for fid, _r, _s, (px, py), _d, _t in items if (spot := got.get(fid)) is not None}

    @staticmethod
    def end_obstacle(m: Mark) -> bool:
        """Whether :meth:`end_lettering_at` reads the end state's mark *m* (a point, a lettered mark, a result
        line): the plate's lettering at another value is placed among those alone."""
        return m.kind is MarkKind.POINT or bool(m.label) or (m.role == "result" and m.kind.stroked)

    @staticmethod
    def end_lettered(m: Mark) -> bool:
        """Whether the end state's mark *m* is lettered: of the marks :meth:`end_lettering_at` reads
        (:meth:`end_obstacle`), those whose letters it asks whether the plate's lettering crowds
        (:meth:`end_crowd`)."""
        return bool(m.label)

    def end_crowd(self, vp: Viewport, letter: float, marks: Sequence[Mark],
                  taken: Sequence[tuple[float, float, float, float]],
                  lettering: Sequence[tuple[str, tuple[float, float], str]],
                  spots: dict[str, tuple[float, float, float]]) -> set[str]:
        """The plate's *lettering* that crowds where it stands at *spots* about its places ({id: (dx, dy,
        distance)}, as :meth:`end_lettering_at` gives them: a neighbouring value's), at another value of a live
        given (:meth:`end_lettering_at`'s arguments): each letter there on another one (but one it touched at the
        built value too), on a point's letter or on the plate's other writing (*taken*), by its id."""
        return self._end_crowd(vp, letter, marks, taken, lettering, spots)[0]

    def _end_crowd(self, vp: Viewport, letter: float, marks: Sequence[Mark],
                   taken: Sequence[tuple[float, float, float, float]],
                   lettering: Sequence[tuple[str, tuple[float, float], str]],
                   spots: dict[str, tuple[float, float, float]]) -> tuple[set[str], dict, dict]:
        """:meth:`end_crowd`, the marks' letters' boxes and the lettering's at *spots*."""
        st = self.style
        size = st.label_size * letter
        letters = {}
        for m in marks:
            rel = self.end_spots.get(m.id)
            if m.label and rel is not None:
                px, py = vp.px(*m.geom)
                letters[m.id] = label_box(px + letter * rel[0], py + letter * rel[1], m.label, size, st.label_font,
                                          st.label_italic)
        # the crowd: the letters whose spot here meets another letter (but one it touched at the built value too)
        # or the plate's other writing
        at = {fid: label_box(p[0] + letter * spots[fid][0], p[1] + letter * spots[fid][1], text, size,
                             st.label_font, st.label_italic) for fid, p, text in lettering if fid in spots}
        return crowded(at, letters, taken, self.end_touching), letters, at

    def _end_place(self, vp: Viewport, letter: float, marks: Sequence[Mark],
                   taken: Sequence[tuple[float, float, float, float]],
                   lettering: Sequence[tuple[str, tuple[float, float], str]],
                   strokes: Sequence[tuple[float, float, float, float]], *,
                   lettered: bool) -> tuple[list, dict, list, list]:
        """The end state's letters placed on *vp* (:meth:`place_end`; *lettered*: the marks' letters with the
        plate's lettering, else the lettering alone, each first where :attr:`end_spots` set it): the items placed,
        their spots, and the points and lines they keep clear of."""
        st = self.style
        size = st.label_size * letter
        span = self.scene.bbox[2] - self.scene.bbox[0]
        look = self.scene.end_look
        dots = [vp.px(*m.geom) for m in marks if m.kind is MarkKind.POINT and "hidden" not in look(m).split()]
        lines = _result_pieces(vp, [m for m in marks if m.role == "result" and m.kind.stroked
                                    and "hidden" not in look(m).split()], strokes)
        items, prefer = [], {}
        for fid, at, text in lettering:
            items.append((fid, "result", 0, at, (0.0, 1.0), text))
            # (first where the plate writes it; at another value, where it stood at the built one)
            rel = None if lettered else self.end_spots.get(fid)
            prefer[fid] = (0.0, 0.35 * size, 0.0) if rel is None else (rel[0] * letter, rel[1] * letter, rel[2])
        for m in marks if lettered else ():
            if not m.label:
                continue
            p = vp.px(*m.geom)
            items.append((m.id, m.role, m.step, p, label_offset_direction(m.geom, scale=span), m.label))
            spot = self.spots.get(m.id)
            if spot is not None:
                prefer[m.id] = ((spot[0] - p[0]) * letter, (spot[1] - p[1]) * letter, spot[2])
        # (the lines filed are those near a spot the letters may take: a live sweep places them at many values, and
        # the result lines are most of the end state's)
        halo = HALO_PX / 2 * letter
        near = spots_extent(items, size, font=st.label_font, italic=st.label_italic, halo=halo, prefer=prefer)
        index = LineIndex(size, lines if near is None else lines[near_rows(lines, near, self.line_reach + size)])
        got = place(items, size, dots, index, font=st.label_font, italic=st.label_italic,
                    taken=list(taken), keep=False, prefer=prefer, halo=halo, reach=self.line_reach)
        return items, got, dots, lines

    def place_tags(self, views: Sequence[View], full: View,
                   input_steps: Callable[[int], frozenset[int]]) -> None:
        """Where each shown name tag goes (:func:`construct.render.tags.place_tags`): :attr:`tag_spots`,
        :attr:`tag_hidden`, :attr:`tag_moves`."""
        self.tag_spots, self.tag_hidden, self.tag_moves = place_tags(self, views, full, input_steps)

    def obstacle_arrays(self) -> tuple[Any, Any]:
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
        dots, _ = self.obstacle_arrays()
        if ((dots[:, 0] >= box[0]) & (dots[:, 0] <= box[2]) & (dots[:, 1] >= box[1]) & (dots[:, 1] <= box[3])).any():
            return False
        reach = max(self.style.result_width, 2.2) / 2  # (2.2: the plates' heavy look)
        if self.lines_at(1.0, self.style.label_size).meets(box, reach):
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

    def lines_at(self, z: float, size: float) -> Any:
        """The result lines magnified *z* times, indexed for letters of *size*
        (:class:`construct.render.lettering.LineIndex`): made once for every placing at that zoom."""
        cache = self._line_index
        key = (z, size)
        if key not in cache:
            cache[key] = LineIndex(size, self.obstacle_arrays()[1] * z)
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


def _meet(a: tuple[float, float, float, float], b: tuple[float, float, float, float]) -> bool:
    """Whether two boxes (x0, y0, x1, y1) overlap."""
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def crowded(boxes: dict[str, tuple[float, float, float, float]], others: dict[str, tuple[float, float, float, float]],
            taken: Sequence[tuple[float, float, float, float]], touching: "set[frozenset[str]]") -> set[str]:
    """The ids of *boxes* ({id: (x0, y0, x1, y1)}, canvas px) whose box meets one of *taken*, another of *boxes* or
    one of *others* (a pair in *touching* aside: they touch where they were placed), in the order of *boxes*: each
    box against every other at once (a live sweep asks it of the plate's lettering at every value: Tafel 2's
    twenty-odd values and letters, 300 values).

    >>> sorted(crowded({"a": (0, 0, 2, 2), "b": (1, 1, 3, 3), "c": (10, 0, 12, 2)}, {"P": (11, 1, 13, 3)}, [], set()))
    ['a', 'b', 'c']
    >>> sorted(crowded({"a": (0, 0, 2, 2), "b": (1, 1, 3, 3)}, {}, [(20, 20, 21, 21)], {frozenset("ab")}))
    []
    """
    if not boxes:
        return set()
    ids = list(boxes)
    names = ids + list(others)
    a = np.array(list(boxes.values()), dtype=float).reshape(-1, 4)
    o = np.concatenate([a, np.array(list(others.values()), dtype=float).reshape(-1, 4)])
    t = np.array(taken, dtype=float).reshape(-1, 4)

    def meets(p: np.ndarray, q: np.ndarray) -> np.ndarray:  # (_meet of every row of p with every row of q)
        p0, p1, p2, p3 = (c[:, None] for c in p.T)
        return (p0 < q[:, 2]) & (q[:, 0] < p2) & (p1 < q[:, 3]) & (q[:, 1] < p3)

    hit = meets(a, o)
    row = {f: i for i, f in enumerate(ids)}
    for j, g in enumerate(names):  # (a box does not crowd itself, nor one of the same id)
        if g in row:
            hit[row[g], j] = False
    if touching:
        col: dict[str, list[int]] = {}
        for j, g in enumerate(names):
            col.setdefault(g, []).append(j)
        for pair in touching:
            if len(pair) == 2:
                f, g = pair
                for f, g in ((f, g), (g, f)):
                    if f in row and g in col:
                        hit[row[f], col[g]] = False
    crowd = hit.any(axis=1)
    if len(t):
        crowd |= meets(a, t).any(axis=1)
    return {f for f, c in zip(ids, crowd.tolist()) if c}


_QUARTERS = np.array([0.25, 0.5, 0.75, 1.0])[:, None]


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
        return [tuple(g[0]), *map(tuple, _curve_quarters(g).tolist())]
    return list(g)


def _curve_quarters(g: Any) -> np.ndarray:
    """The points after the first of a curve mark through the points *g*, as drawn (curve_path): its Catmull-Rom
    pieces, which leave the chords where the curve bends, each at a quarter, a half, three quarters and its end
    (every piece at once), as rows x, y."""
    p1, c1, c2, p2 = (a[:, None] for a in bezier_arrays(np.asarray(g, dtype=float)))
    t = _QUARTERS
    s = 1 - t
    return (s * s * s * p1 + 3 * s * s * t * c1 + 3 * s * t * t * c2 + t * t * t * p2).reshape(-1, 2)


#: A line of at least this many points is mapped on arrays (:func:`_pieces`), a shorter one point by point: numpy's
#: dozen calls cost more than a few points' sums.
_ARRAY_FROM = 24


def _result_pieces(vp: Any, marks: Sequence[Mark], strokes: Sequence[tuple[float, float, float, float]]) -> np.ndarray:
    """The straight pieces of the line *marks* (:func:`_polyline`) on the canvas of *vp*, after the *strokes* (canvas
    px), in order: rows x0, y0, x1, y1.  A long line's points are mapped at once (:func:`_pieces`: a live sweep places
    the plate's lettering at hundreds of values, among curves of hundreds of points), a short one's one by one (the
    same sums either way)."""
    blocks, run = [], list(strokes)
    for m in marks:
        curve = m.kind is MarkKind.CURVE and not m.straight and len(m.geom) > 2
        pts = _polyline_rows(m, vp.scale) if curve else _polyline(m, vp.scale)
        if len(pts) >= _ARRAY_FROM:
            if run:
                blocks.append(np.asarray(run, dtype=float).reshape(-1, 4))
                run = []
            blocks.append(_pieces(vp, pts))
        else:
            p = [vp.px(*q) for q in (pts.tolist() if curve else pts)]
            run.extend((a[0], a[1], b[0], b[1]) for a, b in zip(p, p[1:]))
    if run or not blocks:
        blocks.append(np.asarray(run, dtype=float).reshape(-1, 4))
    return blocks[0] if len(blocks) == 1 else np.concatenate(blocks)


def _polyline_rows(m: Mark, scale: float) -> np.ndarray:
    """:func:`_polyline` as rows x, y (a curve's points made on arrays stay arrays: not made into tuples and back).

    >>> m = Mark("c", 1, "c", MarkKind.CURVE, ((0.0, 0.0), (1.0, 1.0), (2.0, 0.0)), "result", "curve", "")
    >>> _polyline_rows(m, 10.0).tolist() == [list(p) for p in _polyline(m, 10.0)]
    True
    """
    g = m.geom
    if m.kind is MarkKind.CURVE and not m.straight and len(g) > 2:
        return np.concatenate([np.asarray(g[:1], dtype=float).reshape(1, 2), _curve_quarters(g)])
    return np.asarray(_polyline(m, scale), dtype=float).reshape(-1, 2)


def _pieces(vp: Any, pts: "Sequence[tuple[float, float]] | np.ndarray") -> np.ndarray:
    """The straight pieces between the points *pts* (drawing units) on the canvas of *vp*: rows x0, y0, x1, y1, the
    points mapped by ``vp.px`` of their coordinates as arrays (a viewport's map, and a sweep's value's: the same sums
    as point by point, :func:`_segments` of the points mapped one by one).

    >>> vp = Viewport(xmin=0.0, ymax=2.0, scale=10.0, margin=5.0, left=0.0, top=0.0, width=100.0, height=100.0)
    >>> pts = [(0.0, 0.0), (1.0, 2.0), (1.5, 0.5)]
    >>> list(map(tuple, _pieces(vp, pts).tolist())) == _segments([vp.px(*q) for q in pts])
    True
    """
    q = np.asarray(pts, dtype=float).reshape(-1, 2)
    x, y = vp.px(q[:, 0], q[:, 1])
    out = np.empty((max(len(q) - 1, 0), 4))
    out[:, 0], out[:, 1], out[:, 2], out[:, 3] = x[:-1], y[:-1], x[1:], y[1:]
    return out


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
