"""SVG of a scene: the layered figure (every step a group), its frames, the final figure.

The style is a separate value (:class:`Style`): the construction never knows
how it is drawn.  Every look is in one ``<style>`` sheet at the top of the
file and the elements carry only classes (role, instrument, provenance); a
step's elements of one layer sit in ``<g class="step" data-step="k">``, and
a frame marks the current and earlier steps' groups ``cur``/``old``, which
keeps the files small and lets :mod:`construct.regress.svgdiff` compare
looks by class and changes by step.

Every element is made by svgwrite (:mod:`construct.render.svgdoc`).  Output
is deterministic: numbers with at most two decimals (a hundredth of a pixel
at 960 px), ids from step index and object name, attributes in svgwrite's
sorted order, no timestamps, marks in step order, so the same figure gives
the same bytes on every run and machine.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> sc = build_scene(get("crank").figure(parts=6))
>>> svg = render_svg(sc, upto=2)
>>> svg.startswith("<?xml") and 'data-step="3"' not in svg and "Schritt 2" in svg
True
>>> 'class="step cur" data-step="2"' in svg and svgdoc.MARKER in svg
True
"""

from __future__ import annotations

import bisect
import math
from typing import Any, Sequence

from . import svgdoc
from .captions import TITLE_LIMIT, displayed
from .camera import PLAYER_FIGURE_PX, THIN_FROM, ZOOM_LEVELS, clip_view, level, step_views, zoom_of
from .lettering import HALO_PX, LEADER_FROM
from .paths import arc_path, curve_path, hatch_path, polygon_path, polyline_path
from .scene import Mark, MarkKind, Scene, label_offset_direction
from .styles import PLAIN, Style
from .svgdoc import fmt
from .viewport import Viewport, camera_transform, camera_zoom
from .wrapping import wrap as wrap_chars

__all__ = ["render_svg", "Drawing", "step_caption", "group_caption", "wrap", "mark_geometry", "mark_layer",
           "point_radius"]


def wrap(text: str, width_px: float, size: float) -> list[str]:
    """Lines of *text* that fit *width_px* at font size *size* (an average glyph is ~0.56 em).

    The lines ``textwrap.wrap`` gives (long words broken, not at hyphens), in time linear in
    the text (:func:`construct.render.wrapping.wrap`).

    >>> [len(line) for line in wrap("Schritt 3 von 40: " + "x" * 300, 912, 13)]
    [125, 125, 68]
    """
    chars = max(20, int(width_px / (0.56 * size)))
    if len(text) <= chars and text == text.strip() and not any(c in text for c in "\t\n\r\x0b\x0c"):
        return [text]  # one line as it stands: what the wrapper would return, without its cost
    return wrap_chars(text, chars) or [""]


def step_caption(scene: Scene, k: int) -> tuple[str, str]:
    """The German and English caption of frame k ("Schritt k von N: ...")."""
    n = len(scene.steps)
    if k <= 0:
        return (f"Schritt 0 von {n}", f"Step 0 of {n}")
    de, en = scene.caption(k)
    return (f"Schritt {k} von {n}: {de}", f"Step {k} of {n}: {en}")


def group_caption(scene: Scene, k: int) -> str:
    """The group path of step k, German titles where the construction gave them."""
    if k <= 0:
        return ""
    return scene.group_captions[scene.steps[k - 1].group]


class Drawing:
    """A scene laid out in one style: every mark's SVG element, made once, reused by every output.

    The elements are made by svgwrite (:mod:`construct.render.svgdoc`), each
    turned into XML once however many documents carry it.  The canonical
    output, :meth:`layered`, holds every step as a group ``<g class="step"
    data-step="k">`` inside each layer; frame k (:meth:`frame`) is a view of
    it: the groups of steps 1..k, the current one ``cur`` and the earlier ones
    ``old``; the animation and the player switch the same groups.
    """

    LAYERS = ("areas", "construction", "results", "points", "labels")

    def __init__(self, scene: Scene, style: Style = PLAIN, *, caption_lines: int | None = None,
                 region: tuple[float, float, float, float] | None = None, canvas: "Viewport | None" = None):
        self.scene = scene
        self.style = style
        if caption_lines is None:
            caption_lines = self.caption_lines() if style.show_caption else 0
        self.n_caption = caption_lines
        self.vp = Viewport.fit(scene.bbox, style, caption_lines)
        self.region = region
        self._regions: dict[tuple, Drawing] = {}
        if region is not None and canvas is not None:
            # the same canvas as the whole figure, showing only *region*
            m = canvas.margin
            inner_h = canvas.height - 2 * m - caption_lines * 1.45 * style.caption_size
            win = Viewport.window(region, (m, m, canvas.width - m, m + inner_h))
            self.vp = Viewport(win.xmin, win.ymax, win.scale, canvas.width, canvas.height, 0.0, win.left, win.top)
        self.doc = svgdoc.Writer()
        self._spots = self._letter_spots(self.vp)
        #: per zoom level, every letter shown there: its offset from its point (canvas units, moves applied)
        self._level_rel: dict[int, dict[str, tuple[float, float]]] = {}
        self._hidden_at, self._level_rules = self._zoom_placing() if style.camera else ({}, [])
        self._tag_hidden: dict[str, str] = {}
        self._tag_spots = self._place_tags() if style.name_tags else {}
        if style.camera and self._tag_spots:
            self._clear_tag_edges()
        # layer -> [(step, [element, ...]), ...] in step order: each step's elements of that layer.
        self.groups: dict[str, list[tuple[int, list[Any]]]] = {name: [] for name in self.LAYERS}
        placed: list[tuple[float, float, float, float]] = []
        for m in scene.marks:
            for layer, elem in self._elements(m, self.vp, placed, m.id):
                runs = self.groups[layer]
                if not runs or runs[-1][0] != m.step:
                    runs.append((m.step, []))
                runs[-1][1].append(self.doc.frozen(elem))
        if style.camera:
            # the camera: a hidden box per view change, in a layer of its own, so that a moved
            # camera is a change of the step it moves at (construct verify, golden files)
            self.LAYERS = Drawing.LAYERS + ("views",)
            f = self.doc.factory
            runs = self.groups["views"] = []
            last = None
            for k, v in enumerate(self.views, start=1):
                if v != last:
                    runs.append((k, [self.doc.frozen(f.rect(insert=(fmt(v[0]), fmt(v[1])), size=(fmt(v[2]), fmt(v[3])),
                                                            class_="view"))]))
                    last = v
        self._steps = {name: [k for k, _ in runs] for name, runs in self.groups.items()}

    # -- camera -----------------------------------------------------------------------
    @property
    def full_view(self) -> tuple[float, float, float, float]:
        """The whole drawing (without the caption) as a view: x, y, w, h in canvas pixels."""
        return (0.0, 0.0, round(self.vp.width, 2), round(self.drawing_height, 2))

    @property
    def views(self) -> list[tuple[float, float, float, float]]:
        """The camera view of every step (:func:`construct.render.camera.step_views`), computed once."""
        got = self.__dict__.get("_views")
        if got is None:
            n = len(self.scene.steps)
            got = (self._clear_edges(step_views(self.scene, self.full_view, self.scene.bbox, self.vp.px,
                                                self.vp.scale, collapse=self.style.done_opacity <= 0.0))
                   if self.style.camera else [self.full_view] * n)
            self.__dict__["_views"] = got
        return got

    def _clear_edges(self, views: list) -> list:
        """The views widened so that no letter stands across the edge of the player's window.

        A magnified view cuts the figure, and a letter cut in half by the window's edge cannot be
        read.  The player shows a view in its window (:data:`PLAYER_FIGURE_PX`, the view's box
        widened to the window's shape) with letters at its letter scale about their points; a view
        whose window cuts a letter is widened about its centre until it takes the letter in
        (rounds until none is cut: the letters shrink as the view grows, and along a row of letters
        -- the piston positions 1′…11′ on the stroke line -- each round takes in one letter and may
        cut the next; every round grows the view by 2 % at least, so the rounds end), up to the
        whole figure.
        """
        import numpy as np

        from .lettering import label_box

        st = self.style
        marks = [m for m in self.scene.marks if m.kind is MarkKind.POINT and m.label and m.id in self._spots]
        if not marks:
            return views
        arrays: dict[int, Any] = {}

        def letters_at(lvl: int):
            """The letters level *lvl* shows, as (point, box about the point) rows, moves applied."""
            if lvl not in arrays:
                rel = self._level_rel.get(lvl)
                rows = []
                for m in marks:
                    px, py = self.vp.px(*m.geom)
                    spot = self._spots[m.id]
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
                arrays[lvl] = np.array(rows) if rows else np.zeros((0, 6))
            return arrays[lvl]
        self.__dict__["_letters_at"] = letters_at  # the tags' edges keep them in view (_clear_tag_edges)
        full = self.full_view
        W, H = PLAYER_FIGURE_PX
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
                    zl = ZOOM_LEVELS[level(z)]
                    a = letters_at(level(z))
                    q = max(w / W, h / H)
                    ql = q * z / zl
                    ls = min(max(1.0, 9.5 * ql / 12.0), ql)  # the player's --ls
                    hw, hh = W * q / 2, H * q / 2
                    x0, y0 = a[:, 0] + ls * a[:, 2] - cx, a[:, 1] + ls * a[:, 3] - cy
                    x1, y1 = a[:, 0] + ls * a[:, 4] - cx, a[:, 1] + ls * a[:, 5] - cy
                    meet = (x0 < hw) & (x1 > -hw) & (y0 < hh) & (y1 > -hh)
                    cut = meet & ((x0 < -hw) | (x1 > hw) | (y0 < -hh) | (y1 > hh))
                    if not cut.any():
                        break
                    g = max(float(np.maximum(-x0[cut], x1[cut]).max()) / hw,
                            float(np.maximum(-y0[cut], y1[cut]).max()) / hh) * 1.02
                    w, h = w * g, h * g
                if zoom_of((0.0, 0.0, w, h), full) <= 1.0:
                    done[v] = full
                else:
                    done[v] = v if (w, h) == (v[2], v[3]) else clip_view(cx, cy, w, h, full)
            out.append(done[v])
        return out

    def _clear_tag_edges(self) -> None:
        """Widen a view whose window cuts a name tag it shows (its step current or an input), as far as
        the view's zoom level allows (the tags were placed for that level)."""
        sc = self.scene
        full = self.full_view
        marks: dict[int, list] = {}  # a step may tag several points (the ends S1, S2 of a perpendicular)
        for m in sc.marks:
            if m.id in self._tag_spots:
                marks.setdefault(m.step, []).append(m)
        views = list(self.views)
        by_view: dict[tuple, list[int]] = {}
        for k, v in enumerate(views, start=1):
            if v != full:
                by_view.setdefault(v, []).append(k)
        for v0, ks in by_view.items():
            v = v0
            for _ in range(4):  # a view grown or shifted may take in part of another tag: again
                nv = self._tag_edge_view(v, ks, marks)
                if nv is None or nv == v:
                    break
                v = nv
            if v != v0:
                for k in ks:
                    views[k - 1] = v
        self.__dict__["_views"] = views

    def _tag_edge_view(self, v: tuple, ks: list[int], marks: dict) -> tuple | None:
        """View *v* (of steps *ks*) grown or shifted to take in the tags its window cuts (None: none cut)."""
        from .lettering import label_box

        st, sc = self.style, self.scene
        full = self.full_view
        W, H = PLAYER_FIGURE_PX
        x, y, w, h = v
        cx, cy = x + w / 2, y + h / 2
        lvl = level(zoom_of(v, full))
        zl = ZOOM_LEVELS[lvl]
        shown = [m for k in ks for s in {k} | set(self.input_steps(k)) for m in marks.get(s, ())
                 if f" h{lvl}" not in self._tag_hidden.get(m.id, "")]
        if not shown:
            return None
        q = max(w / W, h / H)
        ls = (lambda ql: min(max(1.0, 9.5 * ql / 12.0), ql))(q * zoom_of(v, full) / zl)
        grow = 1.0
        hw, hh = W * q / 2, H * q / 2
        own, inside, cut = [], [], []  # boxes about the view's centre: the views' own steps' tags first
        for m in shown:
            px, py = self.vp.px(*m.geom)
            dx, dy, _d = self._tag_spots[m.id]
            b = label_box(px + dx, py + dy, sc.display_name(m.name), st.label_size, st.label_font,
                          st.label_italic)
            b = (px + ls * (b[0] - px) - cx, py + ls * (b[1] - py) - cy, px + ls * (b[2] - px) - cx,
                 py + ls * (b[3] - py) - cy)
            # the views' own steps' tags are taken in wherever they stand, the inputs' where the window cuts them
            if m.step in ks or (b[0] < hw and b[2] > -hw and b[1] < hh and b[3] > -hh):
                (own if m.step in ks else inside if (-hw <= b[0] and b[2] <= hw and -hh <= b[1] and b[3] <= hh)
                 else cut).append(b)
                if b[0] < -hw or b[2] > hw or b[1] < -hh or b[3] > hh:
                    grow = max(grow, max(-b[0], b[2]) / hw * 1.02, max(-b[1], b[3]) / hh * 1.02)
        # the letters: none is cut by the view (_clear_edges), and none may be by the view grown or shifted
        letters = self.__dict__.get("_letters_at")
        boxes = [(r[0] + ls * r[2] - cx, r[1] + ls * r[3] - cy, r[0] + ls * r[4] - cx, r[1] + ls * r[5] - cy)
                 for r in (letters(lvl) if letters is not None else ())]
        for b in boxes:
            if (b[0] < hw and b[2] > -hw and b[1] < hh and b[3] > -hh) and (
                    b[0] < -hw or b[2] > hw or b[1] < -hh or b[3] > hh):
                grow = max(grow, max(-b[0], b[2]) / hw * 1.02, max(-b[1], b[3]) / hh * 1.02)
        if grow == 1.0:
            return None
        grown = (0.0, 0.0, w * grow, h * grow)
        if level(zoom_of(grown, full)) == lvl and zoom_of(grown, full) > 1.0:
            nv = clip_view(cx, cy, w * grow, h * grow, full)
        else:
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
            if pan == [0.0, 0.0]:
                return None
            nv = (round(x + pan[0], 2), round(y + pan[1], 2), w, h)
        return nv

    def camera_view(self, k: int) -> tuple[float, float, float, float]:
        """Step k's view (the whole figure for k = 0 and past the end)."""
        return self.views[k - 1] if 1 <= k <= len(self.views) else self.full_view

    def ring(self, k: int) -> tuple[float, float, float] | None:
        """(cx, cy, r) in canvas pixels of the ring round step k's mark when that mark is smaller on the
        screen than the ring (:attr:`Style.ring_px`) at step k's view; None when it is large enough."""
        if not self.style.ring_px or not 1 <= k <= len(self.scene.steps):
            return None
        done = self.__dict__.setdefault("_rings", {})
        if k not in done:  # the player and the animation ask for every step
            done[k] = self._ring(k)
        return done[k]

    def _ring(self, k: int) -> tuple[float, float, float] | None:
        spans = self.__dict__.get("_mark_spans")
        if spans is None:
            spans = self.__dict__["_mark_spans"] = {}
            for i, m in enumerate(self.scene.marks):
                lo, _ = spans.get(m.step, (i, i))
                spans[m.step] = (lo, i + 1)
        if k not in spans:
            return None
        pts = [self.vp.px(*p) for m in self.scene.marks[slice(*spans[k])] for p in _mark_points(m)]
        if not pts:
            return None
        x0, x1 = min(p[0] for p in pts), max(p[0] for p in pts)
        y0, y1 = min(p[1] for p in pts), max(p[1] for p in pts)
        z = zoom_of(self.camera_view(k), self.full_view)
        size = max(x1 - x0, y1 - y0) * z  # on the screen, at the view
        if size >= 3.2 * self.style.ring_px:  # also on a figure the player shows at 0.6 of its size
            return None
        r = max(self.style.ring_px, size / 2 + 4.0) / z
        return (round((x0 + x1) / 2, 2), round((y0 + y1) / 2, 2), round(r, 2))

    # -- layout ---------------------------------------------------------------------
    def caption_lines(self) -> int:
        """Caption lines for the frames: the most any step needs, so that all frames have one size."""
        st = self.style
        most = 2
        for k in range(1, len(self.scene.steps) + 1):
            de, en = self._wrapped_caption(k)
            most = max(most, len(de) + len(en))
        return most + (1 if st.show_group else 0)

    def _wrapped_caption(self, k: int) -> tuple[list[str], list[str]]:
        """Step k's caption lines (German, English) wrapped to the canvas: wrapped once per step."""
        cache = self.__dict__.setdefault("_wrap_cache", {})
        got = cache.get(k)
        if got is None:
            st = self.style
            width = st.width_px - 2 * st.margin_px
            de, en = step_caption(self.scene, k)
            got = cache[k] = (wrap(de, width, st.caption_size), wrap(en, width, st.caption_size))
        return got

    @property
    def drawing_height(self) -> float:
        """The canvas height without the caption lines (the player shows its captions in HTML)."""
        return self.vp.height - self.n_caption * 1.45 * self.style.caption_size

    def _letter_spots(self, vp: Viewport) -> dict[str, tuple]:
        """Where every letter goes in this viewport (:func:`construct.render.lettering.place`): results first,
        clear of the other letters, the points and the result lines."""
        from .lettering import place

        scale = self.scene.bbox[2] - self.scene.bbox[0]
        items, dots, lines = [], [], []
        for m in self.scene.marks:
            if m.kind is MarkKind.POINT:
                p = vp.px(*m.geom)
                dots.append(p)
                if m.label:
                    items.append((m.id, m.role, m.step, p, label_offset_direction(m.geom, scale=scale), m.label))
            elif m.role == "result" and m.kind.stroked:
                pts = [vp.px(*q) for q in _polyline(m, vp.scale)]
                lines.extend((a[0], a[1], b[0], b[1]) for a, b in zip(pts, pts[1:]))
        st = self.style
        self._obstacles = (dots, lines)
        self._letter_items = items
        k = self.letter_scale
        size = k * st.label_size
        spots = place(items, size, dots, self._lines_at(1.0, size), font=st.label_font, italic=st.label_italic,
                      halo=HALO_PX / 2 * k, reach=self.line_reach)
        thin = [it for it in items if spots.get(it[0], (0, 0, 0, False))[3]]
        if thin and st.camera:
            # the letters the whole figure has no room for, placed for the magnified views
            # (from zoom level THIN_FROM on): points twice as far apart, letters at their size
            from .lettering import label_box

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
        from .lettering import place

        st = self.style
        size = st.label_size
        items = self._letter_items
        classes: dict[str, str] = {}
        rules: list[str] = []
        moves: dict[tuple[str, str], list[int]] = {}
        for lvl, z in enumerate(ZOOM_LEVELS[1:], start=1):
            its = [(i, r, s_, (p[0] * z, p[1] * z), d, t) for i, r, s_, p, d, t in items
                   if i in self._spots and (lvl >= THIN_FROM or not self._spots[i][3])]
            # letters at the size the player shows them at this level (on the zoomed canvas)
            f = self.letter_scale_at(z) * z
            # each letter where it stands in the whole figure if there is room for it there
            prefer = {i: ((self._spots[i][0] - p[0] / z) * f, (self._spots[i][1] - p[1] / z) * f, self._spots[i][2])
                      for i, _r, _s, p, _d, _t in its}
            got = place(its, size * f, _scaled(self._obstacle_arrays()[0], z), self._lines_at(z, size * f),
                        font=st.label_font, italic=st.label_italic, keep=False, prefer=prefer, halo=HALO_PX / 2 * f, reach=self.line_reach)
            for i, _r, _s, (zx, zy), _d, _t in its:
                spot = got.get(i)
                if spot is None:
                    classes[i] = classes.get(i, "") + f" h{lvl}"
                    continue
                x, y = self._spots[i][0], self._spots[i][1]
                px, py = zx / z, zy / z
                ddx, ddy = (spot[0] - zx) / f - (x - px), (spot[1] - zy) / f - (y - py)
                if abs(ddx) <= 0.5 and abs(ddy) <= 0.5:
                    ddx = ddy = 0.0
                self._level_rel.setdefault(lvl, {})[i] = (x - px + ddx, y - py + ddy)
                if abs(ddx) > 0.5 or abs(ddy) > 0.5:
                    moves.setdefault((i, f"translate({fmt(ddx)}px,{fmt(ddy)}px)"), []).append(lvl)
                    classes[i] = classes.get(i, "") + " lbm"  # moved at some level: the group carries an id
        # one rule per letter and move, listing the levels it holds at (--zs: the level's letter scale)
        for (i, move), lvls in moves.items():
            rules.append(",".join(f".zl{lvl} #{i}-lb>.lb,.zl{lvl} #{i}-lb>.leader" for lvl in lvls)
                         + f"{{transform:scale(var(--ls,var(--zs))) {move}}}")
        return classes, rules

    def _place_tags(self) -> dict[str, tuple[float, float, float]]:
        """Where each shown name tag goes: {point id: (dx, dy, distance in letter heights)} about its point.

        A tag names an operand while its step is current or an input; it is placed like a letter
        (:func:`construct.render.lettering.place`), clear of the points, the result lines, the letters
        and the other tags, in the view of its own step (at that view's zoom level, where the points
        stand farther apart than in the whole figure).  A tag with no free spot there is left out,
        never stacked on another.
        """
        import numpy as np

        from .lettering import label_box, place

        sc, st = self.scene, self.style
        tags = [m for m in sc.marks if m.kind is MarkKind.POINT and not m.label and sc.tag_shown(m.name)]
        if not tags:
            return {}
        if st.camera:
            from .camera import THIN_FROM, ZOOM_LEVELS
        else:  # the one level of an unmagnified figure (local names: the function reads them either way)
            ZOOM_LEVELS, THIN_FROM = (1.0,), 0
        span = sc.bbox[2] - sc.bbox[0]
        # a tag is seen while its step is current and where its step is an input: it is placed at the
        # least magnified of those views (where the letters are largest beside the points)
        lowest: dict[int, int] = {}
        if st.camera:
            full = self.full_view
            step_levels = [level(zoom_of(v, full)) for v in self.views]

            def lvl_of(k: int) -> int:
                return step_levels[k - 1]

            steps = {m.step for m in tags}
            for m in tags:
                lowest[m.step] = lvl_of(m.step)
            for k in range(1, len(sc.steps) + 1):
                for s_ in self.input_steps(k):
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
                for s_ in self.input_steps(k):
                    if s_ in shown_at:
                        shown_at[s_].add(lvl_of(k))
        size = st.label_size
        pts = {m.id: self.vp.px(*m.geom) for m in sc.marks if m.kind is MarkKind.POINT}
        labels = [m for m in sc.marks if m.kind is MarkKind.POINT and m.label and m.id in self._spots]

        def frame(lvl: int):
            """(zoom, letter factor, boxes of the letters shown at level *lvl*) in that level's geometry."""
            z = ZOOM_LEVELS[lvl]
            f = self.letter_scale_at(z) * z if st.camera else 1.0
            rel = self._level_rel.get(lvl)
            boxes = []
            for m in labels:
                if rel is not None:
                    if m.id not in rel:
                        continue
                    dx, dy = rel[m.id]
                else:
                    spot = self._spots[m.id]
                    if spot[3] and lvl < THIN_FROM:
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

        def near(items, z: float, f: float):
            """The points and the numbers of the result lines (at zoom *z*) a tag of *items* could meet:
            within its reach (the lines as a mask over the level's :meth:`_lines_at`)."""
            xs = [it[3][0] for it in items]
            ys = [it[3][1] for it in items]
            r = 8.0 * size * f
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
                together = ({k} | self.input_steps(k)) & tag_steps
                mates = seen_with.setdefault(lvl_of(k), {})
                for s_ in together:
                    mates.setdefault(s_, set()).update(together)
        byid = {m.id: m for m in tags}
        out: dict[str, tuple[float, float, float]] = {}
        for lvl, ms in sorted(by_level.items()):
            z, f, taken = frame(lvl)
            # clear of the tags placed at a lower level that are seen with these at this one
            mates_here = set().union(*(seen_with.get(lvl, {}).get(m.step, set()) for m in ms))
            taken = taken + [label_box(pts[i][0] * z + out[i][0] * f, pts[i][1] * z + out[i][1] * f,
                                       sc.display_name(byid[i].name), size * f, st.label_font, st.label_italic,
                                       HALO_PX / 2 * f)
                             for i in out if byid[i].step in mates_here and lvl in shown_at[byid[i].step]]
            items = []
            for m in ms:
                px, py = pts[m.id]
                items.append((m.id, m.role, m.step, (px * z, py * z), label_offset_direction(m.geom, scale=span),
                              sc.display_name(m.name)))
            # the tags are checked against each other level by level below
            ds, only = near(items, z, f)
            got = place(items, size * f, ds, self._lines_at(z, size * f), only=only,
                        font=st.label_font, italic=st.label_italic, taken=taken, keep=False, halo=HALO_PX / 2 * f, reach=self.line_reach)
            for i, _r, _s, (zx, zy), _d, _t in items:
                if i in got:
                    x, y, dist, _thin = got[i]
                    out[i] = ((x - zx) / f, (y - zy) / f, dist)
        # every level a tag is seen at: it holds its spot there, or it gives way there (class hN),
        # never stacked on a letter, a point, a result line or a tag seen with it
        hidden: dict[str, str] = {}
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
                hidden[i] = hidden.get(i, "") + f" h{lvl}"
        self._tag_hidden = hidden
        return out

    def _obstacle_arrays(self) -> tuple[Any, Any]:
        """The points and the result lines' segments the letters keep clear of, as arrays (made once)."""
        got = self.__dict__.get("_obstacle_a")
        if got is None:
            import numpy as np

            dots, lines = self._obstacles
            got = self.__dict__["_obstacle_a"] = (np.array(dots, dtype=float).reshape(-1, 2),
                                                  np.array(lines, dtype=float).reshape(-1, 4))
        return got

    def _lines_at(self, z: float, size: float) -> Any:
        """The result lines magnified *z* times, indexed for letters of *size*
        (:class:`construct.render.lettering.LineIndex`): made once for every placing at that zoom."""
        from .lettering import LineIndex

        cache = self.__dict__.setdefault("_line_index", {})
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
    def extra_css(self) -> str:
        """The rules of this drawing alone (the letters moved per zoom level)."""
        return "\n".join(self._level_rules)

    @property
    def letter_scale(self) -> float:
        """How much larger than on the canvas the player draws letters in the whole-figure view.

        The player (1400 × 1000 window) shows the figure at most about
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

    def _elements(self, m: Mark, vp: Viewport, placed: list, mid: str | None):
        """(layer, svgwrite element) of a mark's elements; the label (if any) is a second one."""
        cls = f"{m.role} {m.tool} {m.provenance}" + (f" {m.look}" if m.look else "")
        ids = {"id": mid} if mid else {}
        st = self.style
        f = self.doc.factory
        shapes = mark_geometry(m, vp, st)
        if m.kind is MarkKind.POINT:
            a = shapes[0][2]
            yield "points", f.circle(center=(a["cx"], a["cy"]), r=a["r"], class_=f"pt {cls}", **ids)
            tag = self._tag_spots.get(m.id) if vp is self.vp else None
            if tag is not None:
                # Shown only while its step is current or an input (CSS), placed clear of the letters.
                # no id of its own: it is its point's name, and a gallery carries thousands of them
                yield "labels", self._letter(vp, m, tag, self.scene.display_name(m.name), "lb tag", {}, halo=False,
                                             extra=self._tag_hidden.get(m.id, ""))
            if m.label:
                box = self._place_label(m, vp, placed)
                if box is not None:
                    lid = {"id": f"{mid}-label"} if mid else {}
                    px, py = vp.px(*m.geom)
                    rel = (box[0] - px, box[1] - py, box[2] if len(box) > 2 else 0.0)
                    # a letter with no room in the whole figure waits for the magnified views (lbx); without a
                    # camera there are none, and a result's letter is drawn all the same (never left out)
                    thin = len(box) > 3 and box[3] and (st.camera or m.role != "result")
                    extra = (" lbx" if thin else "") + self._hidden_at.get(m.id, "")
                    gid = {"id": f"{mid}-lb"} if mid and " lbm" in extra else {}
                    extra = extra.replace(" lbm", "")
                    yield "labels", self._letter(vp, m, rel, m.label, "lb", lid, extra=extra, gid=gid)
            return
        if m.kind.stroked:
            yield mark_layer(m), _STROKES[m.kind](f, shapes[0][2], {"class_": cls, **ids})
        else:  # an area, and its hatching if the style hatches and the lines meet it
            yield "areas", f.path(d=shapes[0][2]["d"], class_=f"area {cls}", **ids)
            for _, _, a in shapes[1:]:
                hid = {"id": f"{mid}-hatch"} if mid else {}
                yield "areas", f.path(d=a["d"], class_="hatch", **hid)

    def _letter(self, vp: Viewport, m: Mark, rel: tuple[float, float, float], text: str, cls: str,
                ids: dict, *, halo: bool = True, extra: str = "", gid: dict | None = None) -> Any:
        """A letter about its point: ``<g class="lbg" transform="translate(point)">`` holding (leader,) halo
        and letter at *rel* (offset in pixels, distance in letter heights), so that a zoomed view
        can keep letters at their screen size and distance from the point (its children scaled by CSS)."""
        st = self.style
        f = self.doc.factory
        px, py = vp.px(*m.geom)
        outer = inner = f.g(class_="lbg" + extra, transform=f"translate({fmt(px)} {fmt(py)})", **(gid or {}))
        dx, dy, dist = rel
        xy = dict(x=[fmt(dx)], y=[fmt(dy)])
        if dist >= LEADER_FROM:
            # a letter set off from a crowded point is tied to it
            cx, cy = dx, dy - 0.35 * st.label_size
            n = math.hypot(cx, cy) or 1.0
            a, b = 0.25 * st.label_size, n - 0.75 * st.label_size
            # a name tag's leader is shown and hidden with its tag (the style shows tags at their step only)
            inner.add(f.line(start=(fmt(a * cx / n), fmt(a * cy / n)), end=(fmt(b * cx / n), fmt(b * cy / n)),
                             class_="leader tag" if "tag" in cls.split() else "leader"))
        if halo:
            inner.add(f.text(text, class_=f"{cls} halo", **xy))
        inner.add(f.text(text, class_=cls, **ids, **xy))
        return outer

    def _place_label(self, m: Mark, vp: Viewport, placed: list) -> tuple[float, float] | None:
        # In the drawing's own viewport the letters were placed by rank (results first);
        # elsewhere (the magnified inset) they go radially outwards, the other side, or are left out.
        if vp is self.vp:
            return self._spots.get(m.id)
        st = self.style
        dx, dy = label_offset_direction(m.geom, scale=self.scene.bbox[2] - self.scene.bbox[0])
        off = st.label_size * 0.9
        px, py = vp.px(*m.geom)
        for sign in (1.0, -1.0):
            lx, ly = px + sign * dx * off, py - sign * dy * off + st.label_size * 0.35
            box = _label_box(lx, ly, m.label or "", st.label_size)
            if not _overlaps(box, placed):
                placed.append(box)
                return lx, ly
        return None

    # -- documents --------------------------------------------------------------------
    def document(self, *, height: float | None = None, extra_css: str = "", **attrs: Any) -> Any:
        """An svgwrite Drawing of this canvas with the style sheet and the paper (the caller adds the rest)."""
        vp, st = self.vp, self.style
        h = fmt(vp.height if height is None else height)
        w = fmt(vp.width)
        css = st.css() + "".join("\n" + c for c in (self.extra_css, extra_css) if c)
        f = self.doc.factory
        dwg = self.doc.drawing(size=(w, h), viewBox=f"0 0 {w} {h}", **attrs)
        dwg.add(f.style("\n" + css + "\n"))
        dwg.add(f.rect(insert=("0", "0"), size=(w, h), id="background", fill=st.background))
        return dwg

    def step_group(self, k: int, elems: Sequence[Any], cls: str = "", **attrs: Any) -> Any:
        """Step k's elements of one layer: ``<g class="step ..." data-step="k">``.

        With fading (``Style.done_opacity``) a step whose helpers fade carries ``data-fade``:
        the last step of its group, after which the player and animation fade it too.
        """
        if self.style.done_opacity < 1.0 and not (elems and _is_view(elems[0])):
            end = self.scene.fade_end(k)
            if end is not None:
                attrs = {**attrs, "data-fade": str(end)}
        g = self.doc.factory.g(class_=f"step {cls}".rstrip(), **{"data-step": str(k)}, **attrs)
        for e in elems:
            g.add(e)
        return g

    def step_runs(self, name: str, k: int) -> list[tuple[int, list[Any]]]:
        """Layer *name*'s (step, elements) for steps 1..k."""
        return self.groups[name][:bisect.bisect_right(self._steps[name], k)]

    def input_steps(self, k: int) -> frozenset[int]:
        """The steps that made what step k's instrument is set on, what its caption names and what its arc is
        struck onto (:meth:`Scene.struck_onto`)."""
        if not self.style.input_colour:
            return frozenset()
        done = self.__dict__.setdefault("_input_steps", {})  # asked by the tags' placing and by the player
        got = done.get(k)
        if got is None:
            sc = self.scene
            # and the lines its arc is struck onto (cut by the next step): drawn while it strikes it
            got = done[k] = frozenset(s for s in (sc.step_of(n) for n in sc.inputs(k) | sc.tagged(k)
                                                  | sc.struck_onto(k))
                                      if s is not None and s < k)
        return got

    def step_class(self, s: int, k: int, *, mark_steps: bool, inputs: frozenset[int] = frozenset(),
                   layer: str = "") -> str:
        """The class of step s's groups in frame k: cur, old (with inp), done (a finished group's helpers)."""
        if layer == "views":
            return ""  # the camera's boxes are data, never drawn
        fade = self.style.done_opacity < 1.0
        if not mark_steps:
            # the whole figure: every group finished, its helpers faint (teaching)
            return "done" if fade and self.scene.faded(s, len(self.scene.steps) + 1) else ""
        if s == k:
            return "cur"
        if s in inputs:
            return "inp"  # at full strength, in the input colour
        if fade and self.scene.faded(s, k):
            return "done"
        return "old" if self.style.earlier_opacity < 1.0 else ""

    def plain_groups(self, name: str) -> list[Any]:
        """Layer *name*'s step groups as the whole figure shows them (``class="step"``, ``"step done"``
        for a finished group's helpers), made once: the layered figure and the player carry the same ones."""
        cache = self.__dict__.setdefault("_plain_groups", {})
        if name not in cache:
            cache[name] = [self.doc.frozen(self.step_group(k, elems, self.step_class(k, 0, mark_steps=False, layer=name)))
                           for k, elems in self.groups[name]]
        return cache[name]

    def layer(self, name: str, k: int, *, mark_steps: bool) -> Any:
        """``<g id="name">`` with the step groups of steps 1..k; ``cur``/``old``/``done``/``inp`` when *mark_steps*."""
        inputs = self.input_steps(k) if mark_steps else frozenset()
        g = self.doc.factory.g(id=name)
        if not mark_steps:
            for group in self.plain_groups(name)[:bisect.bisect_right(self._steps[name], k)]:
                g.add(group)
            return g
        for s, elems in self.step_runs(name, k):
            g.add(self.step_group(s, elems, self.step_class(s, k, mark_steps=mark_steps, inputs=inputs, layer=name)))
        return g

    def body(self, k: int, *, mark_steps: bool) -> list[Any]:
        """The layers of steps 1..k (clipped to the drawing when this is a region view)."""
        f = self.doc.factory
        out: list[Any] = []
        parent = None
        if self.region is not None:
            # a part of the figure: nothing may stray into the caption
            m = self.style.margin_px
            h = self.vp.height - 2 * m - self.n_caption * 1.45 * self.style.caption_size
            clip = f.clipPath(id="drawing-clip")
            clip.add(f.rect(insert=("0", "0"), size=(fmt(self.vp.width), fmt(h + 1.5 * m))))
            parent = f.g(clip_path="url(#drawing-clip)")
            out += [clip, parent]
        for name in self.LAYERS:
            if self._steps[name] or name != "areas":
                layer = self.layer(name, k, mark_steps=mark_steps)
                if parent is not None:
                    parent.add(layer)
                else:
                    out.append(layer)
        furniture = self.furniture()
        if furniture is not None:
            (parent.add(furniture) if parent is not None else out.append(furniture))
        return out

    def furniture(self) -> Any | None:
        """The broken axis's break marks and the plate's furniture (:mod:`construct.render.plate`)."""
        from .plate import Stroke, furniture_elements

        f = self.doc.factory
        # the furniture first, the break marks over it (they open the rod and the axis for the gap)
        elems = furniture_elements(self.scene.furniture, self.vp.px, self.vp.scale, f, size=self.style.label_size)
        lines = [m.geom for m in self.scene.marks if m.kind is MarkKind.SEGMENT]
        lines += [(*it.a, *it.b) for it in self.scene.furniture if isinstance(it, Stroke)]
        for x0, w, _left_out in self.scene.breaks:
            # on every line crossing the break: a gap in paper colour and two slanted strokes
            for ax, ay, bx, by in lines:
                if min(ax, bx) < x0 + 0.3 * w and max(ax, bx) > x0 + 0.7 * w and abs(bx - ax) > 1e-12:
                    # the classic break: a short gap along the line, a slanted tick at each side
                    xm = x0 + w / 2
                    ym = ay + (by - ay) * (xm - ax) / (bx - ax)
                    cx, cy = self.vp.px(xm, ym)
                    ex, ey = self.vp.px(bx, by)
                    sx, sy = self.vp.px(ax, ay)
                    n = math.hypot(ex - sx, ey - sy) or 1.0
                    ux, uy = (ex - sx) / n, (ey - sy) / n
                    nx, ny = -uy, ux
                    h, gap = 0.6 * self.style.label_size, 0.45 * self.style.label_size
                    corners = [(cx + su * gap * ux + sn * h * nx, cy + su * gap * uy + sn * h * ny)
                               for su, sn in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
                    elems.append(f.path(d="M" + "L".join(f"{fmt(x)} {fmt(y)}" for x, y in corners) + "Z",
                                        class_="brk"))
                    for su in (-1, 1):
                        tx, ty = cx + su * gap * ux, cy + su * gap * uy
                        elems.append(f.line(start=(fmt(tx - 0.35 * h * ux - h * nx), fmt(ty - 0.35 * h * uy - h * ny)),
                                            end=(fmt(tx + 0.35 * h * ux + h * nx), fmt(ty + 0.35 * h * uy + h * ny)),
                                            class_="brkline"))
        if not elems:
            return None
        g = f.g(id="furniture")
        for e in elems:
            g.add(e)
        return g

    def caption_group(self, lines: Sequence[tuple[str, str]], *, centred: bool = False, **attrs: Any) -> Any | None:
        """Caption lines (class suffix, text) at the foot of the figure: ``<g id="caption">``."""
        st, vp = self.style, self.vp
        if not lines:
            return None
        step = 1.45 * st.caption_size
        y = vp.height - st.margin_px * 0.6 - (len(lines) - 1) * step
        x = vp.width / 2 if centred else st.margin_px
        mid = " mid" if centred else ""
        f = self.doc.factory
        g = f.g(**{"id": "caption", **attrs})
        for i, (kind, text) in enumerate(lines):
            cls = f"cap{(' ' + kind) if kind else ''}{mid}"
            g.add(f.text(text, x=[fmt(x)], y=[fmt(y + i * step)], class_=cls))
        return g

    def frame_caption_lines(self, k: int) -> list[tuple[str, str]]:
        de, en = self._wrapped_caption(k)
        lines: list[tuple[str, str]] = []
        if self.style.show_group:
            lines.append(("grp", group_caption(self.scene, k)))
        return lines + [("de", t) for t in de] + [("en", t) for t in en]

    def title_lines(self, caption: Sequence[str] | None = None) -> list[tuple[str, str]]:
        """The figure's caption lines (German first, then English), wrapped to the canvas."""
        st = self.style
        width = st.width_px - 2 * st.margin_px
        lines = list(caption if caption is not None else self.scene.title)
        return [("de" if i == 0 else "en", t) for i, line in enumerate(lines)
                for t in wrap(displayed(line, TITLE_LIMIT), width, st.caption_size)]

    def view(self, k: int) -> "Drawing":
        """The drawing frame k is drawn with: this one, or (progressive zoom) one showing the stage so far."""
        if self.style.camera or not self.style.progressive_zoom or self.region is not None or k <= 0:
            return self
        box = self.scene.stage_box(k)
        if box == self.scene.bbox:
            return self
        key = tuple(round(v, 9) for v in box)
        if key not in self._regions:
            region = Drawing(self.scene, self.style, caption_lines=self.n_caption, region=box, canvas=self.vp)
            region.__dict__["_wrap_cache"] = self.__dict__.setdefault("_wrap_cache", {})  # captions wrap alike
            self._regions[key] = region
        return self._regions[key]

    def frame(self, k: int) -> str:
        """Frame k, a view of the layered figure: steps 1..k, the current one marked, with its caption."""
        k = max(0, min(k, len(self.scene.steps)))
        view = self.view(k)
        if view is not self:
            return view.frame(k)
        dwg = self.document()
        if self.style.camera:
            dwg.add(self.camera_box(k, self.body(k, mark_steps=True)))
        else:
            for e in self.body(k, mark_steps=True):
                dwg.add(e)
        if self.style.zoom_below > 0 and k > 0 and not self.style.camera:
            inset = self.inset(k)
            if inset is not None:
                dwg.add(inset)
        if self.style.show_caption:
            cap = self.caption_group(self.frame_caption_lines(k))
            if cap is not None:
                dwg.add(cap)
        return self.doc.text(dwg)

    def camera_group(self, view: tuple[float, float, float, float], **attrs: Any) -> tuple[Any, Any]:
        """(outer, inner): ``<g>`` clipped to the drawing area holding ``<g id="camera">`` whose
        transform shows *view* on the whole drawing area (a nested ``<svg>`` would be a time
        container of its own in browsers, out of step with the animation's clock)."""
        f = self.doc.factory
        full = self.full_view
        clip = f.clipPath(id="camera-clip")
        clip.add(f.rect(insert=("0", "0"), size=(fmt(full[2]), fmt(full[3]))))
        outer = f.g(clip_path="url(#camera-clip)")
        outer.add(clip)
        inner = f.g(id="camera", class_=f"zl{level(camera_zoom(view, full))}", transform=camera_transform(view, full),
                    **attrs)
        outer.add(inner)
        return outer, inner

    def camera_box(self, k: int, elems: Sequence[Any]) -> Any:
        """The drawing shown through step k's view, with the ring round a small current mark."""
        outer, inner = self.camera_group(self.camera_view(k))
        for e in elems:
            inner.add(e)
        ring = self.ring(k)
        if ring is not None:
            inner.add(self.doc.factory.circle(center=(fmt(ring[0]), fmt(ring[1])), r=fmt(ring[2]), class_="ring"))
        return outer

    def layered(self, caption: Sequence[str] | None = None, *, centred: bool = False) -> str:
        """The canonical figure: every step a ``data-step`` group, nothing highlighted, the figure's caption.

        Still renderers show the whole figure; frame k is the view of steps 1..k.
        """
        dwg = self.document()
        for e in self.body(len(self.scene.steps), mark_steps=False):
            dwg.add(e)
        if self.style.show_caption:
            cap = self.caption_group(self.title_lines(caption), centred=centred)
            if cap is not None:
                dwg.add(cap)
        return self.doc.text(dwg)

    def final(self, caption: Sequence[str] | None = None, *, centred: bool = False) -> str:
        """All steps, nothing highlighted, with the figure's caption lines (the layered figure)."""
        return self.layered(caption, centred=centred)

    # -- magnified inset -------------------------------------------------------------
    def inset(self, k: int) -> Any | None:
        """A magnified view of the current group when it is tiny in the whole figure (teaching)."""
        box = self.scene.group_box(k, self.style.zoom_below, self.region)
        if box is None:
            return None
        size = max(box[2] - box[0], box[3] - box[1])
        if size <= 0:
            return None
        pad = 0.25 * size
        cx, cy = (box[0] + box[2]) / 2, (box[1] + box[3]) / 2
        half = size / 2 + pad
        region = (cx - half, cy - half, cx + half, cy + half)
        vp = self.vp
        m = self.style.margin_px
        side = min(0.4 * vp.width, 0.8 * (vp.height - self.n_caption * 1.45 * self.style.caption_size - 2 * m))
        px0 = vp.width - m - side
        py0 = m
        win = Viewport.window(region, (px0, py0, px0 + side, py0 + side))
        f = self.doc.factory
        corner, square = (fmt(px0), fmt(py0)), (fmt(side), fmt(side))
        out = f.g(id="inset")
        clip = f.clipPath(id="inset-clip")
        clip.add(f.rect(insert=corner, size=square))
        out.add(clip)
        out.add(f.rect(insert=corner, size=square, class_="inset"))
        inner = f.g(clip_path="url(#inset-clip)")
        old = "old" if self.style.earlier_opacity < 1.0 else ""
        placed: list = []
        by_layer: dict[str, list[tuple[int, Any]]] = {name: [] for name in self.LAYERS}
        for mk in self.scene.marks:
            if mk.step > k:
                break
            if not _near(mk, region):
                continue
            for layer, elem in self._elements(mk, win, placed, None):
                by_layer[layer].append((mk.step, elem))
        for name in self.LAYERS:
            for s, elem in by_layer[name]:
                inner.add(self.step_group(s, [elem], "cur" if s == k else old))
        out.add(inner)
        zoom = win.scale / vp.scale
        out.add(f.text(f"× {zoom:.0f}", x=[fmt(px0 + 6)], y=[fmt(py0 + side - 6)], class_="cap grp"))
        return out


#: The SVG element of a mark the pen draws as one line, by kind: (factory, viewport, mark, attributes) -> element.
#: The svgwrite element of a stroked mark from its geometry's attributes (:func:`mark_geometry`).
_STROKES: dict[MarkKind, Any] = {
    MarkKind.SEGMENT: lambda f, a, kw: f.line(start=(a["x1"], a["y1"]), end=(a["x2"], a["y2"]), **kw),
    MarkKind.CIRCLE: lambda f, a, kw: f.circle(center=(a["cx"], a["cy"]), r=a["r"], **kw),
    MarkKind.ARC: lambda f, a, kw: f.path(d=a["d"], **kw),
    MarkKind.CURVE: lambda f, a, kw: f.path(d=a["d"], **kw),
}


def point_radius(m: Mark, style: Style) -> float:
    """The drawn radius of a point mark: small for an auxiliary one or an unlettered helper (a dotted name)."""
    aux = m.role == "auxiliary" or ("." in m.name and not m.label)
    return style.aux_point_radius if aux else style.point_radius


def mark_layer(m: Mark) -> str:
    """The layer of :attr:`Drawing.LAYERS` a mark's drawing (not its letter) goes into."""
    if m.kind is MarkKind.POINT:
        return "points"
    if not m.kind.stroked:
        return "areas"
    return "results" if m.role == "result" else "construction"


def mark_geometry(m: Mark, vp: Viewport, style: Style) -> list[tuple[str, str, dict[str, str]]]:
    """What a mark draws on the canvas *vp*, without its letter: (id suffix, element, {attribute: text}).

    The one place that turns a mark's geometry into SVG attributes: the :class:`Drawing` builds its
    elements from it, and the live player's sweep (:mod:`construct.constructions.live`) reads the same
    numbers at every grid value of a given without laying out a whole page.  An area is its outline and,
    when the style hatches it and the hatching meets it, a second element (suffix ``-hatch``).

    >>> vp = Viewport(0.0, 1.0, 10.0, 20.0, 20.0, 0.0)
    >>> seg = Mark("s", 1, "g", MarkKind.SEGMENT, (0.0, 0.0, 1.0, 1.0), "construction", "straightedge", "exact")
    >>> mark_geometry(seg, vp, PLAIN)
    [('', 'line', {'x1': '0', 'y1': '10', 'x2': '10', 'y2': '0'})]
    >>> pt = Mark("p", 1, "P", MarkKind.POINT, (0.5, 0.5), "result", "compass", "exact")
    >>> mark_geometry(pt, vp, PLAIN)
    [('', 'circle', {'cx': '5', 'cy': '5', 'r': '2'})]
    """
    g, kind = m.geom, m.kind
    if kind is MarkKind.POINT:
        x, y = vp.xy(*g)
        return [("", "circle", {"cx": x, "cy": y, "r": fmt(point_radius(m, style))})]
    if kind is MarkKind.SEGMENT:
        (x1, y1), (x2, y2) = vp.xy(*g[:2]), vp.xy(*g[2:4])
        return [("", "line", {"x1": x1, "y1": y1, "x2": x2, "y2": y2})]
    if kind is MarkKind.CIRCLE:
        x, y = vp.xy(*g[:2])
        return [("", "circle", {"cx": x, "cy": y, "r": vp.length(g[2])})]
    if kind is MarkKind.ARC:
        return [("", "path", {"d": arc_path(vp, *g)})]
    if kind is MarkKind.CURVE:
        return [("", "path", {"d": (polyline_path if m.straight else curve_path)(vp, g)})]
    out = [("", "path", {"d": polygon_path(vp, g)})]
    if style.hatch:
        d = hatch_path(vp, g, style.hatch_spacing, *(() if m.hatch is None else (m.hatch,)))
        if d:
            out.append(("-hatch", "path", {"d": d}))
    return out

#: Rounds of widening a view whose window cuts a letter (Drawing._clear_edges): each grows the view by 2 %
#: at least, so 80 rounds reach 4.9 times its width -- past the whole figure from any view (MAX_ZOOM = 4).
EDGE_ROUNDS = 80

def _is_view(elem: Any) -> bool:
    """Is *elem* a camera box of the ``views`` layer (frozen or not)?"""
    xml = getattr(elem, "xml", None)
    return (xml.get("class") if xml is not None else getattr(elem, "attribs", {}).get("class")) == "view"


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
        for i in range(len(g) - 1):
            p0, p1, p2 = g[i - 1] if i > 0 else g[i], g[i], g[i + 1]
            p3 = g[i + 2] if i + 2 < len(g) else g[i + 1]
            c1 = (p1[0] + (p2[0] - p0[0]) / 6.0, p1[1] + (p2[1] - p0[1]) / 6.0)
            c2 = (p2[0] - (p3[0] - p1[0]) / 6.0, p2[1] - (p3[1] - p1[1]) / 6.0)
            for t in (0.25, 0.5, 0.75, 1.0):
                s = 1 - t
                out.append(tuple(s * s * s * a + 3 * s * s * t * b + 3 * s * t * t * c + t * t * t * d
                                 for a, b, c, d in zip(p1, c1, c2, p2)))
        return out
    return list(g)


def _scaled(rows: Any, z: float) -> list[tuple[float, ...]]:
    """Every coordinate of *rows* (an array of points or segments) times *z*, as tuples
    (the same numbers as multiplying one by one, made at once: a figure has thousands)."""
    return list(map(tuple, (rows * z).tolist()))


def _mark_points(m: Mark) -> list[tuple[float, float]]:
    """The points that bound a mark as drawn (a segment by its ends)."""
    from .scene import extreme_points

    return extreme_points(m)


def _near(m: Mark, region: tuple[float, float, float, float]) -> bool:
    """Could the mark show inside *region*?  (Bounding boxes meet; a circle must not enclose it all.)"""
    x0, y0, x1, y1 = region
    g = m.geom
    if m.kind is MarkKind.POINT:
        return x0 <= g[0] <= x1 and y0 <= g[1] <= y1
    if m.kind.round:
        cx, cy, r = g[0], g[1], g[2]
        # distance from the centre to the nearest and farthest point of the region
        nx, ny = min(max(cx, x0), x1), min(max(cy, y0), y1)
        near = math.hypot(nx - cx, ny - cy)
        far = max(math.hypot(px - cx, py - cy) for px in (x0, x1) for py in (y0, y1))
        return near <= r <= far
    if m.kind is MarkKind.SEGMENT:
        bx0, bx1 = sorted((g[0], g[2]))
        by0, by1 = sorted((g[1], g[3]))
        return bx0 <= x1 and x0 <= bx1 and by0 <= y1 and y0 <= by1
    pts = g
    return any(x0 <= p[0] <= x1 and y0 <= p[1] <= y1 for p in pts)


def render_svg(scene: Scene, *, upto: int | None = None, style: Style = PLAIN,
               caption: tuple[str, str] | None = None) -> str:
    """The figure after steps 1..upto (all steps when None), as SVG text."""
    if upto is None:
        if style.fig_caption:
            # a plate: its own size, the "Fig." caption centred beneath
            lines = caption if caption is not None else scene.title
            width = style.width_px - 2 * style.margin_px
            n = sum(len(wrap(displayed(line, TITLE_LIMIT), width, style.caption_size)) for line in lines)
            return Drawing(scene, style, caption_lines=n).final(caption, centred=True)
        return Drawing(scene, style).final(caption)
    return Drawing(scene, style).frame(upto)


def _label_box(x: float, y: float, text: str, size: float) -> tuple[float, float, float, float]:
    w = 0.62 * size * len(text)
    return (x - w / 2, y - 0.8 * size, x + w / 2, y + 0.2 * size)


def _overlaps(box, placed) -> bool:
    x0, y0, x1, y1 = box
    return any(x0 < b[2] and b[0] < x1 and y0 < b[3] and b[1] < y1 for b in placed)
