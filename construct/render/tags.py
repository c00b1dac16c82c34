"""Where the name tags stand: a point's name shown beside it while its step is current or an input.

A teaching figure names the unlettered points a step works with (its operands) by small tags.  A tag is
placed like a letter (:func:`construct.render.lettering.place`) clear of the points, the result lines, the
letters and the other tags seen with it, at the zoom level of the view that first shows it, and held,
moved (class ``lvN``) or given way (``hN``) at every other level it is seen at (:func:`place_tags`).  It asks
a :class:`construct.render.placing.Placing` (a :class:`Ground`) where the letters already stand.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> from construct.render.styles import TEACHING
>>> from construct.render.svg import Drawing
>>> pl = Drawing(build_scene(get("crank").figure(parts=6)), TEACHING).placing
>>> len(pl.tag_spots) > 0 and all(dist >= 0 for _dx, _dy, dist in pl.tag_spots.values())
True
"""

from __future__ import annotations

from typing import Any, Callable, Protocol, Sequence

import numpy as np

from .camera import THIN_FROM, ZOOM_LEVELS, View, level, zoom_of
from .lettering import HALO_PX, RANK, label_box, place, spots_of
from .scene import Mark, MarkKind, Scene, label_offset_direction
from .styles import Style
from .viewport import Viewport

__all__ = ["place_tags", "spots_clear", "Ground", "Tags", "TAG_FARTHER"]

#: The farther rings (letter heights) a name tag tries, tied by a leader, before it gives way: a tag the
#: step's caption names is worth a longer leader.
TAG_FARTHER = (4.5, 5.5, 6.5, 8.0, 10.0, 12.0, 14.0)

#: Where the tags stand: {point id: (dx, dy, distance in letter heights)} about their points, {point id: the
#: classes ``hN`` of the levels it gives way at}, {point id: {level: (dx, dy, distance)} where it stands elsewhere}.
Tags = tuple[dict[str, tuple[float, float, float]], dict[str, str], dict[str, dict[int, tuple[float, float, float]]]]


class Ground(Protocol):
    """What the tags are placed against: the letters placed already (:class:`construct.render.placing.Placing`)."""

    scene: Scene
    style: Style
    vp: Viewport
    #: every letter's baseline on the canvas, its distance in letter heights, whether it has no room
    spots: dict[str, tuple]
    #: per zoom level, every letter shown there: its offset from its point
    level_rel: dict[int, dict[str, tuple[float, float]]]

    @property
    def line_reach(self) -> float: ...

    def letter_scale_at(self, zoom: float) -> float: ...

    def obstacle_arrays(self) -> tuple[Any, Any]: ...

    def lines_at(self, z: float, size: float) -> Any: ...


#: How many (tag, obstacle) pairs :func:`place_tags` asks of all their spots at once (a tag's pairs are never
#: split): arrays of some 120,000 spot tests (60 spots a tag), which stay in the processor's cache (the compound
#: engine's tags, 240,000 pairs at one level: 14 million at once took a quarter longer).
_PAIRS_AT_ONCE = 2048


def place_tags(placing: Ground, views: Sequence[View], full: View, input_steps: Callable[[int], frozenset[int]]) -> Tags:
    """Where each shown name tag goes: {point id: (dx, dy, distance in letter heights)} about its point.

    A tag names an operand while its step is current or an input; it is placed like a letter
    (:func:`construct.render.lettering.place`), clear of the points, the result lines, the letters
    and the other tags, in the view of its own step (at that view's zoom level, where the points
    stand farther apart than in the whole figure).  A tag with no free spot there is left out,
    never stacked on another.
    """
    sc, st = placing.scene, placing.style
    tags = [m for m in sc.marks if m.kind is MarkKind.POINT and not m.label and sc.tag_shown(m.name)]
    if not tags:
        return {}, {}, {}
    # the levels of the player's views; the one level of an unmagnified figure
    levels, thin_from = (ZOOM_LEVELS, THIN_FROM) if st.camera else ((1.0,), 0)
    span = sc.bbox[2] - sc.bbox[0]
    # a tag is seen while its step is current and where its step is an input: it is placed at the
    # least magnified of those views (where the letters are largest beside the points)
    lowest: dict[int, int] = {}
    # each step's inputs, asked once (three walks over the steps below)
    inputs = [input_steps(k) for k in range(1, len(sc.steps) + 1)] if st.camera else []
    if st.camera:
        step_levels = [level(zoom_of(v, full)) for v in views]

        def lvl_of(k: int) -> int:
            return step_levels[k - 1]

        steps = {m.step for m in tags}
        for m in tags:
            lowest[m.step] = lvl_of(m.step)
        for k, ins in enumerate(inputs, 1):
            for s_ in ins:
                if s_ in steps:
                    lowest[s_] = min(lowest[s_], lvl_of(k))
    by_level: dict[int, list[Mark]] = {}
    for m in tags:
        by_level.setdefault(lowest.get(m.step, 0), []).append(m)
    shown_at: dict[int, set[int]] = {m.step: {lowest.get(m.step, 0)} for m in tags}
    if st.camera:
        for m in tags:
            shown_at[m.step].add(lvl_of(m.step))
        for k, ins in enumerate(inputs, 1):
            for s_ in ins:
                if s_ in shown_at:
                    shown_at[s_].add(lvl_of(k))
    size = st.label_size
    pts = {m.id: placing.vp.px(*m.geom) for m in sc.marks if m.kind is MarkKind.POINT}
    labels = [m for m in sc.marks if m.kind is MarkKind.POINT and m.label and m.id in placing.spots]

    def frame(lvl: int):
        """(zoom, letter factor, boxes of the letters shown at level *lvl*) in that level's geometry."""
        z = levels[lvl]
        f = placing.letter_scale_at(z) * z if st.camera else 1.0
        rel = placing.level_rel.get(lvl)
        boxes = []
        for m in labels:
            if rel is not None:
                if m.id not in rel:
                    continue
                dx, dy = rel[m.id]
            else:
                spot = placing.spots[m.id]
                if spot[3] and lvl < thin_from:
                    continue
                dx, dy = spot[0] - pts[m.id][0], spot[1] - pts[m.id][1]
            px, py = pts[m.id]
            boxes.append(label_box(px * z + dx * f, py * z + dy * f, m.label, st.label_size * f, st.label_font,
                                   st.label_italic, HALO_PX / 2 * f))
        return z, f, boxes

    # the points and result lines as arrays, asked once per level and group of tags below
    dot_a, line_a = placing.obstacle_arrays()
    line_lo = np.minimum(line_a[:, 0:2], line_a[:, 2:4])
    line_hi = np.maximum(line_a[:, 0:2], line_a[:, 2:4])

    scaled: dict[float, tuple] = {}
    reach = (max(TAG_FARTHER) + 3.0) * size  # how far from its point a tag's box may reach (letter units)

    def at_zoom(z: float):
        """The points and the result lines' lower and upper corners at zoom *z*: made once, asked by each tag there."""
        if z not in scaled:
            scaled[z] = dot_a * z, line_lo * z, line_hi * z
        return scaled[z]

    def near(items, z: float, f: float):
        """The points and the numbers of the result lines (at zoom *z*) a tag of *items* could meet:
        within its reach (the lines as a mask over the level's :meth:`_lines_at`): as far as a tag's box
        reaches from its point (a tag 14 letter heights off reached beyond a window of 8, and the crank
        circle's pieces crossing it there went unseen)."""
        xs = [it[3][0] for it in items]
        ys = [it[3][1] for it in items]
        r = reach * f
        x0, y0, x1, y1 = min(xs) - r, min(ys) - r, max(xs) + r, max(ys) + r
        dz, lo, hi = at_zoom(z)
        ds = dz[(x0 <= dz[:, 0]) & (dz[:, 0] <= x1) & (y0 <= dz[:, 1]) & (dz[:, 1] <= y1)]
        mask = (lo[:, 0] <= x1) & (hi[:, 0] >= x0) & (lo[:, 1] <= y1) & (hi[:, 1] >= y0)
        return ds, mask.tolist()

    # per level, the tags' steps seen together in some view of that level (a step and its inputs)
    seen_with: dict[int, dict[int, set[int]]] = {}
    if st.camera:
        tag_steps = {m.step for m in tags}
        for k, ins in enumerate(inputs, 1):
            together = ({k} | ins) & tag_steps
            mates = seen_with.setdefault(lvl_of(k), {})
            for s_ in together:
                mates.setdefault(s_, set()).update(together)
    byid = {m.id: m for m in tags}
    out: dict[str, tuple[float, float, float]] = {}
    frames: dict[int, tuple] = {}
    tags_of: dict[int, list[Mark]] = {}
    for m in tags:
        tags_of.setdefault(m.step, []).append(m)

    def frame_at(lvl: int):
        """:func:`frame` of level *lvl*, made once: (zoom, letter factor, the boxes as a list and as an array)."""
        if lvl not in frames:
            z, f, boxes = frame(lvl)
            frames[lvl] = (z, f, boxes, np.array(boxes, dtype=float).reshape(-1, 4))
        return frames[lvl]

    def place_at(m: Mark, lvl: int) -> bool:
        """Place tag *m* at level *lvl*, clear of the letters there and of the tags placed so far that are
        seen with it at that level (tags never seen together may share a spot)."""
        z, f, _taken, boxes = frame_at(lvl)
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
        got = place([item], size * f, ds, placing.lines_at(z, size * f), only=only, font=st.label_font,
                    italic=st.label_italic, taken=taken, keep=False, halo=HALO_PX / 2 * f,
                    reach=placing.line_reach, distances=TAG_FARTHER)
        if m.id not in got:
            return False
        gx, gy, dist, _thin = got[m.id]
        out[m.id] = ((gx - x) / f, (gy - y) / f, dist)
        return True

    def place_level(ms: list[Mark], lvl: int) -> None:
        """:func:`place_at` each tag of *ms* in turn at level *lvl*: the spots of the usual rings of all of them
        made and asked of the letters, points and rings near each at once; a tag with none of those free of the
        tags placed before it and of the result lines is placed by :func:`place_at`."""
        z, f, _taken, boxes = frame_at(lvl)
        r, sz, halo = reach * f, size * f, HALO_PX / 2 * f
        xy = [(pts[m.id][0] * z, pts[m.id][1] * z) for m in ms]
        items = [(m.id, m.role, m.step, p, label_offset_direction(m.geom, scale=span), sc.display_name(m.name))
                 for m, p in zip(ms, xy)]
        # (the usual rings: the farther ones are tried by place_at)
        lx, ly, sx0, sy0, sx1, sy1, dist = spots_of(items, sz, font=st.label_font, italic=st.label_italic, halo=halo)
        x, y = (np.array(xy, dtype=float).reshape(-1, 2)[:, k:k + 1] for k in (0, 1))
        dz, lo, hi = at_zoom(z)
        d = 0.3 * sz
        # what each tag's place_at asks: the level's letters within its reach, the points within it (as boxes)
        obst = np.concatenate([boxes, np.column_stack((dz[:, 0] - d, dz[:, 1] - d, dz[:, 0] + d, dz[:, 1] + d))])
        # (the box round each tag's spots: only the letters and points meeting it are asked spot by spot)
        a0, b0, a1, b1 = sx0.min(axis=1)[:, None], sy0.min(axis=1)[:, None], sx1.max(axis=1)[:, None], \
            sy1.max(axis=1)[:, None]
        meet = (obst[:, 0] < a1) & (a0 < obst[:, 2]) & (obst[:, 1] < b1) & (b0 < obst[:, 3])
        if not ((a0 - d >= x - r) & (a1 + d <= x + r) & (b0 - d >= y - r) & (b1 + d <= y + r)).all():
            # a spot beyond a tag's reach: what meets it there is asked only within the reach, as place_at asks
            meet &= np.concatenate([
                (boxes[:, 2] >= x - r) & (boxes[:, 0] <= x + r) & (boxes[:, 3] >= y - r) & (boxes[:, 1] <= y + r),
                (x - r <= dz[:, 0]) & (dz[:, 0] <= x + r) & (y - r <= dz[:, 1]) & (dz[:, 1] <= y + r)], axis=1)
        ti, bi = np.nonzero(meet)
        taken = np.zeros(sx0.shape, dtype=bool)
        if len(ti):
            # (tag, obstacle) pairs by tag (np.nonzero gives them in order), a few tags' pairs at a time: the
            # spots of the compound engine's 1463 tags met 240,000 pairs, 14 million spot-pair tests at once
            rows, starts = np.unique(ti, return_index=True)
            ends = np.append(starts[1:], len(ti))
            cut = [0, *np.flatnonzero(np.diff(starts // _PAIRS_AT_ONCE)) + 1, len(rows)]
            for c0, c1 in zip(cut, cut[1:]):
                p0, p1 = starts[c0], ends[c1 - 1]
                t_, o = ti[p0:p1], obst[bi[p0:p1]]
                hit = ((sx0[t_] < o[:, 2:3]) & (o[:, 0:1] < sx1[t_]) & (sy0[t_] < o[:, 3:4]) & (o[:, 1:2] < sy1[t_]))
                taken[rows[c0:c1]] = np.logical_or.reduceat(hit, starts[c0:c1] - p0, axis=0)
        if st.ring_px:
            # the ring the player draws round the point while its step is current
            rr = st.ring_px * f
            taken |= (sx0 < x + rr) & (x - rr < sx1) & (sy0 < y + rr) & (y - rr < sy1)
        lines = placing.lines_at(z, sz)
        only = (lo[:, 0] <= x + r) & (hi[:, 0] >= x - r) & (lo[:, 1] <= y + r) & (hi[:, 1] >= y - r)
        free = [np.flatnonzero(~t).tolist() for t in taken]
        for t, m in enumerate(ms):
            mates = [label_box(pts[o.id][0] * z + out[o.id][0] * f, pts[o.id][1] * z + out[o.id][1] * f,
                               sc.display_name(o.name), sz, st.label_font, st.label_italic, halo)
                     for k in seen_with.get(lvl, {}).get(m.step, ()) if lvl in shown_at[k]
                     for o in tags_of.get(k, ()) if o.id in out] if free[t] else ()
            for i in free[t]:
                b = (float(sx0[t, i]), float(sy0[t, i]), float(sx1[t, i]), float(sy1[t, i]))
                if any(b[0] < c[2] and c[0] < b[2] and b[1] < c[3] and c[1] < b[3] for c in mates) or \
                        lines.meets(b, placing.line_reach, only[t]):
                    continue
                out[m.id] = ((float(lx[t, i]) - xy[t][0]) / f, (float(ly[t, i]) - xy[t][1]) / f, float(dist[i]))
                break
            else:
                place_at(m, lvl)

    # each tag at the least magnified level it is seen at, in the placer's order (results first)
    hidden: dict[str, str] = {}
    for lvl, ms in sorted(by_level.items()):
        place_level(sorted(ms, key=lambda m: (RANK.get(m.role, 2), m.step, m.id)), lvl)
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
        z, f, taken, _boxes = frame_at(lvl)
        here = [byid[i] for i in out if lvl in shown_at[byid[i].step]]
        if all(lowest.get(m.step, 0) == lvl for m in here):
            continue  # placed together at this level, against the same letters: nothing to check
        items = [(m.id, m.role, m.step, (pts[m.id][0] * z, pts[m.id][1] * z), (1.0, 0.0), sc.display_name(m.name))
                 for m in here]
        prefer = {m.id: (out[m.id][0] * f, out[m.id][1] * f, out[m.id][2]) for m in here}
        ds, only = near(items, z, f)
        got = place(items, size * f, ds, placing.lines_at(z, size * f), only=only,
                    font=st.label_font, italic=st.label_italic, taken=taken, keep=False, prefer=prefer,
                    halo=HALO_PX / 2 * f, reach=placing.line_reach)
        def kept(got, items) -> set[str]:
            return {i for i, _r, _s, (zx, zy), _d, _t in items if (spot := got.get(i)) is not None
                    and abs(spot[0] - zx - prefer[i][0]) <= 1e-6 and abs(spot[1] - zy - prefer[i][1]) <= 1e-6}

        holds = kept(got, items)
        # whether each tag that lost its spot has it free of the level's letters, points and result lines (as
        # the placer asks), all such tags at once; asked below only of a tag seen with fewer than all
        spots = [it for it in items if it[0] not in holds]
        boxes = [label_box(o[3][0] + prefer[o[0]][0], o[3][1] + prefer[o[0]][1], o[5], size * f, st.label_font,
                           st.label_italic, HALO_PX / 2 * f) for o in items]
        box_of = {o[0]: b for o, b in zip(items, boxes)}
        ds = np.array(ds, dtype=float).reshape(-1, 2)
        clear = dict(zip((it[0] for it in spots), spots_clear(
            np.array([box_of[it[0]] for it in spots], dtype=float).reshape(-1, 4), ds,
            (line_a[np.array(only, dtype=bool)] * z).reshape(-1, 4), np.array(taken, dtype=float).reshape(-1, 4),
            0.3 * size * f, placing.line_reach).tolist()))
        losers = []
        # the level's tags by their step: those seen with a tag are gathered from its mates' steps, not picked
        # out of all the level's tags for each tag that lost its spot (which grew with the square of the tags)
        here_of: dict[int, list[str]] = {}
        for o in items:
            here_of.setdefault(byid[o[0]].step, []).append(o[0])
        for it in spots:
            i = it[0]
            # it lost its spot to all the tags of the level together; it holds it where it is seen only
            # with the tags seen together with it (crank step 181: M1 gave way to tags never shown with it)
            mates = seen_with.get(lvl, {}).get(byid[i].step, set())
            if clear[i]:  # (asked first: the tags seen with it are gathered only for a spot free of the rest)
                local = [o for k in mates for o in here_of.get(k, ()) if o in holds or o == i]
                # it holds its spot where the spot is also free of the tags seen with it
                b = box_of[i]
                if len(local) < len(items) and not any(b[0] < c[2] and c[0] < b[2] and b[1] < c[3] and c[1] < b[3]
                                                       for c in (box_of[o] for o in local if o != i)):
                    holds.add(i)  # the tags it is seen with after it are placed with it
                    continue
            losers.append(it)
        if losers:
            # a tag with no room at its spot stands elsewhere at this level, clear of the letters and of the
            # tags that hold theirs (a step's caption names it: it is never left out while there is room)
            held = [box_of[o[0]] for o in items if o[0] in holds]
            again = place(losers, size * f, ds, placing.lines_at(z, size * f), only=only, font=st.label_font,
                          italic=st.label_italic, taken=taken + held, keep=False, halo=HALO_PX / 2 * f,
                          reach=placing.line_reach, distances=TAG_FARTHER)
            for it in losers:
                i, (zx, zy) = it[0], it[3]
                spot = again.get(i)
                if spot is None:
                    hidden[i] = hidden.get(i, "") + f" h{lvl}"
                else:
                    moves.setdefault(i, {})[lvl] = ((spot[0] - zx) / f, (spot[1] - zy) / f, spot[2])
    return out, hidden, moves


def spots_clear(boxes: np.ndarray, dots: np.ndarray, lines: np.ndarray, taken: np.ndarray, r: float,
                e: float) -> np.ndarray:
    """For each box (n, 4): is it free of the boxes *taken* (k, 4), of the points *dots* (m, 2) widened by *r*
    and of the result *lines* (p, 4: x0, y0, x1, y1) widened by *e* (a line crossing the box grown by *e*,
    clipped to it: the slab test), all boxes at once.

    >>> b = np.array([[0.0, 0.0, 10.0, 10.0], [20.0, 0.0, 30.0, 10.0]])
    >>> spots_clear(b, np.zeros((0, 2)), np.array([[-5.0, 5.0, 15.0, 5.0]]), np.zeros((0, 4)), 1.0, 0.5).tolist()
    [False, True]
    """
    x0, y0, x1, y1 = (boxes[:, k:k + 1] for k in range(4))
    free = ~((taken[:, 0] < x1) & (x0 < taken[:, 2]) & (taken[:, 1] < y1) & (y0 < taken[:, 3])).any(axis=1)
    free &= ~((dots[:, 0] - r < x1) & (x0 < dots[:, 0] + r) & (dots[:, 1] - r < y1) & (y0 < dots[:, 1] + r)).any(axis=1)
    if not len(lines) or not len(boxes):
        return free
    # the slab test only for the pairs whose boxes meet (grown by a hair: a pair left out could not cross)
    lo, hi = np.concatenate([x0 - e, y0 - e], axis=1), np.concatenate([x1 + e, y1 + e], axis=1)  # (n, 2)
    l_lo, l_hi = np.minimum(lines[:, :2], lines[:, 2:]), np.maximum(lines[:, :2], lines[:, 2:])
    hair = 1e-6 * (1.0 + np.abs(lines).max())
    bi, li = np.nonzero((l_lo[:, 0] <= hi[:, 0:1] + hair) & (l_hi[:, 0] >= lo[:, 0:1] - hair)
                        & (l_lo[:, 1] <= hi[:, 1:2] + hair) & (l_hi[:, 1] >= lo[:, 1:2] - hair))
    if not len(bi):
        return free
    lo, hi, p0 = lo[bi], hi[bi], lines[li, :2]
    dv = lines[li, 2:] - p0
    moving = dv != 0
    with np.errstate(divide="ignore", invalid="ignore"):
        ta = (lo - p0) / dv
        tb = (hi - p0) / dv
        t_in = np.nan_to_num(np.minimum(ta, tb), nan=-np.inf)
        t_out = np.nan_to_num(np.maximum(ta, tb), nan=np.inf)
    inside = moving | ((p0 >= lo) & (p0 <= hi))
    t0 = np.maximum(0.0, np.where(moving, t_in, -np.inf).max(axis=1))
    t1 = np.minimum(1.0, np.where(moving, t_out, np.inf).min(axis=1))
    crossed = np.zeros(len(boxes), dtype=bool)
    crossed[bi[(t0 <= t1) & inside.all(axis=1)]] = True
    return free & ~crossed
