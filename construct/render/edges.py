"""Letters at the edge of the player's window: views widened (or shifted) so that no letter is cut.

A magnified view (:mod:`construct.render.camera`) cuts the figure, and a letter or a name tag cut in half by
the window's edge cannot be read.  :func:`clear_edges` widens each view until its window cuts no letter;
:func:`clear_tag_edges` widens or shifts it to take in the name tags of its steps, within its zoom level.
Both ask what each zoom level shows (:meth:`construct.render.placing.Placing.letters_at`, ``tags_at``): rows
(x, y, then the letter's box x0, y0, x1, y1 less x, y) in canvas pixels.

>>> import numpy as np
>>> full = (0.0, 0.0, 998.0, 630.0)
>>> def letters_at(level):  # one letter at (500, 150), its box 20 × 12 px about it at the letter scale 1
...     return np.array([[500.0, 150.0, -10.0, -6.0, 10.0, 6.0]])
>>> half = (0.0, 0.0, 499.0, 315.0)  # a view magnifying 2 times, whose window's edge at x = 499 cuts the letter
>>> v = clear_edges([full, half], full, letters_at)
>>> v[0] == full and v[1][0] == 0.0 and v[1][2] > 499.0  # widened to take it in
True
"""

from __future__ import annotations

import math
from typing import Any, Callable, Sequence

import numpy as np

from .camera import PLAYER_FIGURE_PX, ZOOM_LEVELS, View, clip_view, level, player_letter_scale, zoom_of

__all__ = ["clear_edges", "clear_edges_rows", "clear_tag_edges", "EDGE_ROUNDS", "Letters", "Tags"]

#: Rounds of widening a view whose window cuts a letter (:func:`clear_edges`): each grows the view by 2 %
#: at least, so 80 rounds reach 4.9 times its width -- past the whole figure from any view (MAX_ZOOM = 4).
EDGE_ROUNDS = 80

#: What a level shows as letters about their points: rows (x, y, then the letter's box x0, y0, x1, y1
#: less x, y), canvas pixels (:meth:`construct.render.placing.Placing.letters_at`).
Letters = Callable[[int], Any]


def clear_edges(views: list[View], full: View, letters_at: Letters) -> list[View]:
    """The *views* widened so that no letter stands across the edge of the player's window.

    A magnified view cuts the figure, and a letter cut in half by the window's edge cannot be
    read.  The player shows a view in its window (:data:`PLAYER_FIGURE_PX`, the view's box
    widened to the window's shape) with letters at its letter scale about their points; a view
    whose window cuts a letter is widened about its centre until it takes the letter in
    (rounds until none is cut: the letters shrink as the view grows, and along a row of letters
    -- the piston positions 1′…11′ on the stroke line -- each round takes in one letter and may
    cut the next; every round grows the view by 2 % at least, so the rounds end), up to the
    whole figure.  *letters_at*: the letters each zoom level shows.
    """
    done: dict = {}
    out = []
    for v in views:
        if v == full:
            out.append(v)
            continue
        if v not in done:
            x, y, w, h = v
            cx, cy = x + w / 2, y + h / 2
            for _ in range(EDGE_ROUNDS):  # the level can change as the view grows, moving other letters
                z = zoom_of((0.0, 0.0, w, h), full)  # the window's magnification
                if z <= 1.0:
                    break
                # the letters the view cuts where it will stand: moved onto the canvas (clip_view), a view grown
                # about a point near an edge has its far side further out than its centre says
                g = _letter_cut(clip_view(cx, cy, w, h, full), full, level(z), letters_at(level(z)))
                if g == 1.0:
                    break
                w, h = w * g, h * g
            if zoom_of((0.0, 0.0, w, h), full) <= 1.0:
                done[v] = full
            else:
                done[v] = v if (w, h) == (v[2], v[3]) else clip_view(cx, cy, w, h, full)
        out.append(done[v])
    return out


def clear_edges_rows(view: Any, W: Any, H: Any, letters_at: Callable[[int, Any], tuple[Any, Any, Any]]) -> Any:
    """:func:`clear_edges` over arrays: the views *view* (x, y, w, h: 4 x n) of canvases *W* x *H* (n each: a
    live page's step at every value of a sweep), each widened until its window cuts no letter.  *letters_at*: the
    letters a zoom level shows with the views of the given indices, (x, y: letters x indices, their boxes less x,
    y: letters x 4); a letter at NaN is not there.

    >>> full = (0.0, 0.0, 998.0, 630.0)
    >>> row = np.array([[500.0, 150.0, -10.0, -6.0, 10.0, 6.0]])
    >>> at = lambda lvl, i: (row[:, :1], row[:, 1:2], row[:, 2:])
    >>> v = (0.0, 0.0, 499.0, 315.0)
    >>> tuple(clear_edges_rows(np.array(v)[:, None], np.array([998.0]), np.array([630.0]), at)[:, 0]) == \\
    ...     clear_edges([v], full, lambda lvl: row)[0]
    True
    """
    x, y, w, h = (np.array(c, dtype=float) for c in view)
    W, H = np.asarray(W, dtype=float), np.asarray(H, dtype=float)
    ww, wh = PLAYER_FIGURE_PX
    whole = np.maximum(W / ww, H / wh)
    cx, cy = x + w / 2, y + h / 2
    w0, h0 = w.copy(), h.copy()
    going = ~((x == 0.0) & (y == 0.0) & (w == W) & (h == H))
    levels = np.asarray(ZOOM_LEVELS)
    for _ in range(EDGE_ROUNDS):  # (the rounds of clear_edges, every view at once until none is cut)
        z = whole / np.maximum(np.maximum(w / ww, h / wh), 1e-12)
        going &= z > 1.0
        if not going.any():
            break
        lvl = np.maximum((z[:, None] >= 0.999 * levels).sum(axis=1) - 1, 0)  # (camera.level)
        g = np.ones(len(z))
        for at in np.unique(lvl[going]):
            i = np.flatnonzero(going & (lvl == at))
            px, py, box = letters_at(int(at), i)
            vw, vh = np.minimum(w[i], W[i]), np.minimum(h[i], H[i])  # (clip_view: where the view will stand)
            vx = np.minimum(np.maximum(cx[i] - vw / 2, 0.0), W[i] - vw)
            vy = np.minimum(np.maximum(cy[i] - vh / 2, 0.0), H[i] - vh)
            q = np.maximum(vw / ww, vh / wh)
            t = whole[i] / ZOOM_LEVELS[at]  # (q times the view's zoom: player_letter_scale(t) over arrays)
            ls = np.minimum(np.maximum(1.0, 9.5 * t / 12.0), t)
            hw, hh = ww * q / 2, wh * q / 2
            mx, my = vx + vw / 2, vy + vh / 2
            with np.errstate(invalid="ignore"):
                x0, y0 = px + ls * box[:, :1] - mx, py + ls * box[:, 1:2] - my
                x1, y1 = px + ls * box[:, 2:3] - mx, py + ls * box[:, 3:4] - my
                meet = (x0 < hw) & (x1 > -hw) & (y0 < hh) & (y1 > -hh)
                cut = meet & ((x0 < -hw) | (x1 > hw) | (y0 < -hh) | (y1 > hh))
                need = np.maximum(np.where(cut, np.maximum(-x0, x1), -np.inf).max(axis=0, initial=-np.inf) / hw,
                                  np.where(cut, np.maximum(-y0, y1), -np.inf).max(axis=0, initial=-np.inf) / hh)
            g[i] = np.where(cut.any(axis=0), need * 1.02, 1.0)
        going &= g != 1.0
        w, h = w * g, h * g
    z = whole / np.maximum(np.maximum(w / ww, h / wh), 1e-12)
    vw, vh = np.minimum(w, W), np.minimum(h, H)
    grown = [np.round(np.minimum(np.maximum(cx - vw / 2, 0.0), W - vw), 2), np.round(np.minimum(np.maximum(
        cy - vh / 2, 0.0), H - vh), 2), np.round(vw, 2), np.round(vh, 2)]
    same = (w == w0) & (h == h0)
    out = [np.where(same, v, np.where(z <= 1.0, f, g_ + 0.0))
           for v, f, g_ in zip((x, y, w0, h0), (np.zeros_like(W), np.zeros_like(W), W, H), grown)]
    return np.stack(out)


#: The name tags a view of some steps at a zoom level shows: (row as in :data:`Letters`, is it a tag of
#: the view's own steps?) (:meth:`construct.render.placing.Placing.tags_at`).
Tags = Callable[[Sequence[int], int], list[tuple[tuple[float, ...], bool]]]


def clear_tag_edges(views: list[View], full: View, tags_at: Tags, letters_at: Letters) -> list[View]:
    """The *views* widened or shifted to take in the name tags their windows cut (of their steps or inputs),
    as far as each view's zoom level allows (the tags were placed for that level)."""
    views = list(views)
    by_view: dict[tuple, list[int]] = {}
    for k, v in enumerate(views, start=1):
        if v != full:
            by_view.setdefault(v, []).append(k)
    for v0, ks in by_view.items():
        v = v0
        for _ in range(4):  # a view grown or shifted may take in part of another tag: again
            nv = _tag_edge_view(v, ks, full, tags_at, letters_at)
            if nv is None or nv == v:
                break
            v = nv
        if v != v0:
            for k in ks:
                views[k - 1] = v
    return views


def _letter_cut(v: View, full: View, lvl: int, a: Any) -> float:
    """How much view *v* must grow about its centre to take in the letters *a* (rows as in :data:`Letters`) of
    level *lvl* its window cuts (1.0: it cuts none; as :func:`clear_edges` grows a view, 2 % more)."""
    W, H = PLAYER_FIGURE_PX
    x, y, w, h = v
    q = max(w / W, h / H)
    ls = player_letter_scale(q * zoom_of(v, full) / ZOOM_LEVELS[lvl])
    hw, hh = W * q / 2, H * q / 2
    cx, cy = x + w / 2, y + h / 2
    x0, y0 = a[:, 0] + ls * a[:, 2] - cx, a[:, 1] + ls * a[:, 3] - cy
    x1, y1 = a[:, 0] + ls * a[:, 4] - cx, a[:, 1] + ls * a[:, 5] - cy
    meet = (x0 < hw) & (x1 > -hw) & (y0 < hh) & (y1 > -hh)
    cut = meet & ((x0 < -hw) | (x1 > hw) | (y0 < -hh) | (y1 > hh))
    if not cut.any():
        return 1.0
    return max(float(np.maximum(-x0[cut], x1[cut]).max()) / hw, float(np.maximum(-y0[cut], y1[cut]).max()) / hh) * 1.02


def _tag_edge_view(v: View, ks: list[int], full: View, tags_at: Tags, letters_at: Letters) -> View | None:
    """View *v* (of steps *ks*) grown or shifted to take in the tags its window cuts (None: none cut)."""
    W, H = PLAYER_FIGURE_PX
    x, y, w, h = v
    cx, cy = x + w / 2, y + h / 2
    lvl = level(zoom_of(v, full))
    zl = ZOOM_LEVELS[lvl]
    shown = tags_at(ks, lvl)
    if not shown:
        return None
    q = max(w / W, h / H)
    ls = player_letter_scale(q * zoom_of(v, full) / zl)
    grow = 1.0
    hw, hh = W * q / 2, H * q / 2
    own, inside, cut = [], [], []  # boxes about the view's centre: the views' own steps' tags first
    for r, is_own in shown:
        b = (r[0] + ls * r[2] - cx, r[1] + ls * r[3] - cy, r[0] + ls * r[4] - cx, r[1] + ls * r[5] - cy)
        # the views' own steps' tags are taken in wherever they stand, the inputs' where the window cuts them
        if is_own or (b[0] < hw and b[2] > -hw and b[1] < hh and b[3] > -hh):
            (own if is_own else inside if (-hw <= b[0] and b[2] <= hw and -hh <= b[1] and b[3] <= hh)
             else cut).append(b)
            if b[0] < -hw or b[2] > hw or b[1] < -hh or b[3] > hh:
                grow = max(grow, max(-b[0], b[2]) / hw * 1.02, max(-b[1], b[3]) / hh * 1.02)
    # the letters: none is cut by the view (clear_edges), and none may be by the view grown or shifted
    boxes = [(r[0] + ls * r[2] - cx, r[1] + ls * r[3] - cy, r[0] + ls * r[4] - cx, r[1] + ls * r[5] - cy)
             for r in letters_at(lvl)]
    for b in boxes:
        if (b[0] < hw and b[2] > -hw and b[1] < hh and b[3] > -hh) and (
                b[0] < -hw or b[2] > hw or b[1] < -hh or b[3] > hh):
            grow = max(grow, max(-b[0], b[2]) / hw * 1.02, max(-b[1], b[3]) / hh * 1.02)
    if grow == 1.0:
        return None
    # grown about its centre, and on while it cuts a letter (a row of letters at its edge), within its level
    for _ in range(EDGE_ROUNDS):
        grown = (0.0, 0.0, w * grow, h * grow)
        if level(zoom_of(grown, full)) != lvl or zoom_of(grown, full) <= 1.0:
            break
        nv = clip_view(cx, cy, w * grow, h * grow, full)
        more = _letter_cut(nv, full, lvl, letters_at(lvl))
        if more == 1.0:
            return nv
        grow *= more
    # where growing would leave the level, the shift that takes the tags in: the views' own steps'
    # tags first, then it keeps in what it shows whole (the letters too), then the inputs' tags
    inside += [b for b in boxes if -hw <= b[0] and b[2] <= hw and -hh <= b[1] and b[3] <= hh]
    pan = [0.0, 0.0]
    for i, half in ((0, hw), (1, hh)):
        lo, hi = -math.inf, math.inf  # the shifts that keep in what is taken so far
        for b in own + inside + cut:
            nlo, nhi = max(lo, b[i + 2] - half + 1.0), min(hi, b[i] + half - 1.0)
            if nlo <= nhi:
                lo, hi = nlo, nhi
        pan[i] = min(max(0.0, lo), hi)
    # a shift that brings a letter outside the window part way in cuts it: the shift is shortened until none
    # is cut (piston force steps 1216-1222: the row of piston positions at the window's top)
    arr = np.array(boxes, dtype=float).reshape(-1, 4)
    for _ in range(6):
        if pan == [0.0, 0.0]:
            return None
        a = arr - np.array(pan * 2)
        meet = (a[:, 0] < hw) & (a[:, 2] > -hw) & (a[:, 1] < hh) & (a[:, 3] > -hh)
        if not (meet & ((a[:, 0] < -hw) | (a[:, 2] > hw) | (a[:, 1] < -hh) | (a[:, 3] > hh))).any():
            return (round(x + pan[0], 2), round(y + pan[1], 2), w, h)
        pan = [pan[0] / 2, pan[1] / 2]
    return None
