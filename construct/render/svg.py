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

import dataclasses
import heapq
import math
from typing import Any, Callable, Iterator, Sequence

from . import captions as _captions
from . import svgdoc
from .camera import level, step_views
from .edges import clear_edges, clear_tag_edges
from .captions import Captions, PlateCaption
from .end_state import END_MARGIN_PX, EndView, end_furniture, end_sheet, lay_out_end, own_strokes, wrapped
from .insets import ring_round, step_insets
from .magnifier import magnified_inset
from .gaps import CLEARANCE, Gap, GapFactory, gapped_hatch, gapped_mark
from .lettering import HALO_PX, LEADER_FROM, text_box, text_width
from .paths import hatch_path
from .placing import Placing, PlacedLabel, place_outwards, text_gap
from .plate import (Lettering, Stroke, break_elements, crossing_lines, furniture_elements, furniture_pieces, plain,
                    subscript_runs)
from .rod_length import clear_spots, rod_at, rod_box, rod_group, writes_rod
from .scene import Mark, MarkKind, Scene, extreme_points
from .shapes import mark_geometry, mark_layer, point_radius, stroke_element
from .step_groups import StepGroups
from .styles import PLAIN, Style
from .svgdoc import fmt
from .viewport import Viewport, camera_transform, camera_zoom

__all__ = ["render_svg", "Drawing", "EndView", "mark_geometry", "mark_layer", "point_radius", "END_MARGIN_PX",
           "own_strokes"]

#: Names that moved to :mod:`construct.render.captions`, still found here (with a DeprecationWarning).
_MOVED = {"wrap": "captions", "step_caption": "captions", "group_caption": "captions"}


class Drawing(StepGroups):
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
                 region: tuple[float, float, float, float] | None = None, canvas: "Viewport | None" = None,
                 plate: bool = False):
        self.scene = scene
        self.style = style
        #: a book plate: its letters stand beside the lines, or the lines are broken for them (:attr:`gaps`)
        self.plate = plate
        #: the caption lines, wrapped to the canvas
        self.captions = Captions(scene, width=style.width_px - 2 * style.margin_px, size=style.caption_size,
                                 groups=style.show_group)
        if caption_lines is None:
            caption_lines = self.captions.line_count() if style.show_caption else 0
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
        #: where the letters and the name tags stand (:class:`construct.render.placing.Placing`)
        #: the plate's furniture as drawn (an end-anchored lettering with an index set from its start)
        self.furniture_items = _start_anchored(scene.furniture, self.vp.scale, style)
        pieces = furniture_pieces(self.furniture_items, self.vp.px, self.vp.scale, size=style.label_size) if plate else []
        self.placing = pl = Placing(scene, style, self.vp, self.drawing_height, plate=plate, furniture=pieces)
        #: the rod's length written at the figure's breaks (None: no rod broken) and where (:func:`rod_spots`), by
        #: the line it is written over (None: between the points on either side); the camera keeps it whole
        self.rod_at = rod_at(scene, style, self.vp.px, plate=plate, layers=Drawing.LAYERS,
                             clear=pl.clear_of_results)
        pl.words = [(cx, cy, *(b[0] - cx, b[1] - cy, b[2] - cx, b[3] - cy))
                    for spots in self.rod_at[1].values() for _, cx, cy, dx, dy, anchor in spots
                    for b in [rod_box(self.rod_at[0], cx + dx, cy + dy, anchor, style)]]
        #: where the plate's lines are broken for its letters (:mod:`construct.render.gaps`): the ink of every
        #: letter shown and of the furniture's lettering, with a margin of white
        self.gaps: list[Gap] = self._gaps(pieces) if plate else []
        if style.name_tags:
            pl.place_tags(self.views if style.camera else (), self.full_view, self.input_steps)
            if style.camera and pl.tag_spots:
                self.__dict__["_views"] = clear_tag_edges(
                    self.views, self.full_view, lambda ks, lvl: pl.tags_at(ks, lvl, self.input_steps), pl.letters_at)
        #: the end state's view, letter scale and sheet (:class:`EndView`); None without one
        self.end = lay_out_end(scene, style, self.vp, pl, self.views, self.full_view, self.doc.factory) \
            if style.camera and scene.ending and scene.steps else None
        # layer -> [(step, [element, ...]), ...] in step order: each step's elements of that layer.
        self.groups: dict[str, list[tuple[int, list[Any]]]] = {name: [] for name in self.LAYERS}
        placed: list[tuple[float, float, float, float]] = []
        # the end state's own marks go with the step that made their object, shown in the end state only
        ends = sorted(scene.end_marks, key=lambda m: m.step) if self.end is not None else []
        for m in heapq.merge(scene.marks, ends, key=lambda m: m.step):
            end = m.id.endswith("-end") and m in ends
            for layer, elem in self.mark_elements(m, self.vp, placed, m.id, end=end):
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
        self.group_steps = {name: [k for k, _ in runs] for name, runs in self.groups.items()}

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
            if self.style.camera:
                got = step_views(self.scene, self.full_view, self.scene.bbox, self.vp.px, self.vp.scale,
                                 collapse=self.style.done_opacity <= 0.0)
                if self.placing.lettered:  # no letter is cut by the player's window
                    got = clear_edges(got, self.full_view, self.placing.letters_at)
            else:
                got = [self.full_view] * len(self.scene.steps)
            self.__dict__["_views"] = got
        return got

    @property
    def insets(self) -> list[tuple[float, float, float, float] | None]:
        """Per step, the region the player magnifies in an inset (:func:`construct.render.insets.step_insets`)."""
        got = self.__dict__.get("_insets")
        if got is None:
            got = self.__dict__["_insets"] = (step_insets(self.scene, self.views, self.full_view, self.vp.px) if self.style.camera
                                              else [None] * len(self.scene.steps))
        return got

    def labels(self) -> tuple[PlacedLabel, ...]:
        """Every letter of the whole figure where it stands (:meth:`construct.render.placing.Placing.labels`)."""
        return self.placing.labels()

    @property
    def extra_css(self) -> str:
        """The rules of this drawing alone (the letters moved per zoom level and in the end state)."""
        rules = self.placing.level_rules + self.placing.end_rules
        if self.end is not None and self.scene.end_furniture:
            e = self.end
            rules.append(f".end .lb{{font-size:{fmt(e.size)}px}}.end .lb.halo{{stroke-width:{fmt(HALO_PX * e.letter)}px}}")
        return "\n".join(rules)

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
        pts = [self.vp.px(*p) for m in self.scene.marks[slice(*spans[k])] for p in extreme_points(m)]
        return ring_round(pts, self.camera_view(k), self.full_view, self.style.ring_px)

    # -- layout ---------------------------------------------------------------------
    @property
    def drawing_height(self) -> float:
        """The canvas height without the caption lines (the player shows its captions in HTML)."""
        return self.vp.height - self.n_caption * 1.45 * self.style.caption_size

    def mark_elements(self, m: Mark, vp: Viewport, placed: list, mid: str | None, *,
                      end: bool = False) -> Iterator[tuple[str, Any]]:
        """(layer, svgwrite element) of mark *m* drawn on the canvas *vp*; its letter (if any) is a second one.

        On the drawing's own viewport (:attr:`vp`) the letters stand where :attr:`placing` put them; on another
        (the magnified inset, :mod:`construct.render.magnifier`) they go radially outwards, clear of the
        letter boxes in *placed* (which it extends).  *mid*: the element's id (None: none, a copy).

        An end state's own mark (*end*) is shown in the end state only (class ``fo``); a mark the end state
        leaves out, and its letter, are not shown there (``nf``)."""
        cls = f"{m.role} {m.tool} {m.provenance}" + (f" {m.look}" if m.look else "")
        sc = self.scene
        out = " fo" if end else (" nf" if sc.ending and not sc.in_end(m) else "")
        cls += out + "".join(f" fl-{w}" for w in sc.end_looks.get(m.id, "").split())
        ids = {"id": mid} if mid else {}
        st = self.style
        f = self.doc.factory
        shapes = mark_geometry(m, vp, st)
        if m.kind is MarkKind.POINT:
            a = shapes[0][2]
            yield "points", f.circle(center=(a["cx"], a["cy"]), r=a["r"], class_=f"pt {cls}", **ids)
            tag = self.placing.tag_spots.get(m.id) if vp is self.vp else None
            if tag is not None:
                # Shown only while its step is current or an input (CSS), placed clear of the letters.
                # no id of its own: it is its point's name, and a gallery carries thousands of them; at a zoom
                # level where its spot is taken it stands elsewhere, a copy of its own there (lvN, the other mN)
                name = self.scene.display_name(m.name)
                moves = self.placing.tag_moves.get(m.id, {})
                yield "labels", self._letter(vp, m, tag, name, "lb tag", {}, halo=False,
                                             extra=self.placing.tag_hidden.get(m.id, "") + out
                                             + "".join(f" m{lvl}" for lvl in sorted(moves)))
                for lvl, rel in sorted(moves.items()):
                    yield "labels", self._letter(vp, m, rel, name, "lb tag", {}, halo=False, extra=f" lv{lvl}{out}")
            if m.label and end:
                # an end state's own letter: it stands where the end state's placing set it, or nowhere
                rel = self.placing.end_spots.get(m.id)
                if rel is not None:
                    yield "labels", self._letter(vp, m, rel, m.label, "lb", {}, extra=" fo pf",
                                                 gid={"id": f"{m.id}-lb"})
            elif m.label:
                # in the drawing's own viewport the letters were placed by rank (results first); elsewhere
                # (the magnified inset) they go radially outwards, the other side, or are left out
                box = (self.placing.spots.get(m.id) if vp is self.vp
                       else place_outwards(m, vp, st, self.scene.bbox[2] - self.scene.bbox[0], placed))
                if box is not None:
                    lid = {"id": f"{mid}-label"} if mid else {}
                    px, py = vp.px(*m.geom)
                    rel = (box[0] - px, box[1] - py, box[2] if len(box) > 2 else 0.0)
                    # a letter with no room in the whole figure waits for the magnified views (lbx); without a
                    # camera there are none, and a result's letter is drawn all the same (never left out)
                    thin = len(box) > 3 and box[3] and (st.camera or m.role != "result")
                    extra = (" lbx" if thin else "") + self.placing.hidden_at.get(m.id, "") + out
                    if vp is self.vp and m.id in self.placing.end_spots:
                        extra += " pf lbm"  # it stands in the end state, where it may move
                    gid = {"id": f"{mid}-lb"} if mid and " lbm" in extra else {}
                    extra = extra.replace(" lbm", "")
                    # a plate breaks its lines for its letters: no paper-coloured halo beneath them
                    yield "labels", self._letter(vp, m, rel, m.label, "lb", lid, extra=extra, gid=gid,
                                                 halo=not (self.plate and vp is self.vp))
            return
        if m.kind.stroked:
            d = gapped_mark(m, self.vp, self.gaps) if self.gaps and vp is self.vp else None
            if d is not None:  # broken for the letters it passes
                yield mark_layer(m), f.path(d=d, class_=cls, **ids)
            else:
                yield mark_layer(m), stroke_element(f, m, shapes[0][2], class_=cls, **ids)
        else:  # an area, and its hatching if the style hatches and the lines meet it
            yield "areas", f.path(d=shapes[0][2]["d"], class_=f"area {cls}", **ids)
            for _, _, a in shapes[1:]:
                hid = {"id": f"{mid}-hatch"} if mid else {}
                yield "areas", f.path(d=self._plate_hatch(m, a["d"]) if self.plate and vp is self.vp else a["d"],
                                      class_="hatch", **hid)

    def _plate_hatch(self, m: Mark, d: str) -> str:
        """A plate's hatching of area *m* (*d* as the style hatches it): not run into a section drawn over it (the
        flywheel's disc into its rim), broken for the letters in it."""
        over = self.scene.areas_over(m)
        if over:
            d = hatch_path(self.vp, m.geom, self.style.hatch_spacing, *(() if m.hatch is None else (m.hatch,)),
                           under=tuple(over))
        return gapped_hatch(d, self.gaps) if self.gaps else d

    def _gaps(self, pieces: Sequence[Any]) -> list[Gap]:
        """The gaps a plate's lines leave for its letters: round the ink of every letter the plate shows and of
        the furniture's lettering (:data:`construct.render.gaps.CLEARANCE` of white)."""
        st = self.style
        grow = CLEARANCE * st.label_size
        out = []
        for p in self.labels():
            if p.shown:
                box = text_box(p.point[0] + p.offset[0], p.point[1] + p.offset[1], p.text, st.label_size,
                               st.label_font, st.label_italic)
                out.append(Gap.around(box, grow))
        out += [text_gap(p, st, CLEARANCE * st.label_size * p.size) for p in pieces if p.kind == "text"]
        return out

    def _letter(self, vp: Viewport, m: Mark, rel: tuple[float, float, float], text: str, cls: str,
                ids: dict, *, halo: bool = True, extra: str = "", gid: dict | None = None) -> Any:
        """A letter about its point: ``<g class="lbg" transform="translate(point)">`` holding (leader,) halo
        and letter at *rel* (offset in pixels, distance in letter heights), so that a zoomed view
        can keep letters at their screen size and distance from the point (its children scaled by CSS)."""
        f = self.doc.factory
        px, py = vp.px(*m.geom)
        outer = inner = f.g(class_="lbg" + extra, transform=f"translate({fmt(px)} {fmt(py)})", **(gid or {}))
        dx, dy, dist = rel
        xy = dict(x=[fmt(dx)], y=[fmt(dy)])
        pl = self.placing
        if "tag" in cls.split() or vp is not self.vp:
            # a name tag's leader is shown and hidden with its tag (the style shows tags at their step only)
            leaders = [(pl.leader_line(dx, dy, text), " tag" if "tag" in cls.split() else "")] if dist >= LEADER_FROM else []
        elif " fo" in extra:
            leaders = [(pl.leader_line(dx, dy, text), " lvf")] if dist >= LEADER_FROM else []
        else:
            # a letter set off from a crowded point is tied to it, wherever it stands (each zoom level, the end)
            leaders = pl.leaders(m.id, rel, text)
        for (x1, y1, x2, y2), more in leaders:
            inner.add(f.line(start=(fmt(x1), fmt(y1)), end=(fmt(x2), fmt(y2)), class_="leader" + more))
        if halo:
            inner.add(f.text(text, class_=f"{cls} halo", **xy))
        inner.add(f.text(text, class_=cls, **ids, **xy))
        return outer

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
            if self.group_steps[name] or name != "areas":
                layer = self.layer(name, k, mark_steps=mark_steps)
                if parent is not None:
                    parent.add(layer)
                else:
                    out.append(layer)
        furniture = self.furniture(k, mark_steps=mark_steps)
        if furniture is not None:
            (parent.add(furniture) if parent is not None else out.append(furniture))
        return out

    def furniture(self, k: int | None = None, *, mark_steps: bool = False,
                  timed: "Callable[[int], list[Any]] | None" = None) -> Any | None:
        """The broken axis's break marks and the plate's furniture (:mod:`construct.render.plate`); the break
        marks of a line go with its step (frame *k*: those of steps 1..k, in their states there; *timed*:
        the animation's timing of a step's group, put first in it)."""
        f = self.doc.factory
        sc = self.scene
        # the furniture first, the break marks over it (they open the rod and the axis for the gap)
        size = self.style.label_size
        elems = furniture_elements(self.furniture_items, self.vp.px, self.vp.scale,
                                   GapFactory(f, self.gaps) if self.gaps else f, size=size)
        rod, at = self.rod_at

        if self.plate:  # its lines are broken for its lettering: the lettering's halos go
            lines = crossing_lines(sc.marks, sc.furniture)
            elems += break_elements(sc.breaks, lines, self.vp.px, f, size=size)
            elems = [e for e in elems if e.attribs.get("class") != "lb halo"]
            elems += [rod_group(f, rod, p) for p in at.get(None, ())]
        else:
            # a line's break marks are shown when and where the line is: in a step group of the line's step
            # (the player gives it the line's state), not in the end state where that leaves the line out
            # (nf); those of the end state's own lines there only (fo)
            elems += break_elements(sc.breaks, crossing_lines((), sc.furniture), self.vp.px, f, size=size)
        if sc.breaks and not self.plate:
            n = len(sc.steps)
            inputs = self.input_steps(k) if mark_steps and k is not None else frozenset()
            elems += [rod_group(f, rod, p) for p in at.get(None, ())]  # (between points: no line crosses the break)
            for m in sc.marks:
                if m.kind is MarkKind.SEGMENT and (k is None or m.step <= k):
                    marks = break_elements(sc.breaks, [m.geom], self.vp.px, f, size=size)
                    # the rod's length over the line it is written over: with its step, as its break marks are
                    marks += [rod_group(f, rod, p) for p in at.get(m.id, ())]
                    if marks and self.end is not None and not sc.in_end(m):
                        marks = [wrapped(f.g(class_="nf"), marks)]
                    if marks:
                        state = self.step_class(m.step, n if k is None else k, mark_steps=mark_steps, inputs=inputs)
                        elems.append(self.step_group(m.step, (timed(m.step) if timed else []) + marks, state))
        if self.end is not None:
            ends = [m.geom for m in sc.end_marks if m.kind is MarkKind.SEGMENT]
            ends += [(*it.a, *it.b) for it in sc.end_furniture if isinstance(it, Stroke)]
            marks = break_elements(sc.breaks, ends, self.vp.px, f, size=size)
            if marks and rod and not writes_rod(sc.end_furniture):
                # (the end state's own: over its flattest line crossing the break, the axis before the rod)
                flat = sorted(ends, key=lambda e: abs(e[3] - e[1]) / (abs(e[2] - e[0]) or 1e-300))
                marks += [rod_group(f, rod, p) for p in clear_spots(sc.breaks, flat, rod, self.style, self.vp.px,
                                                                  self.placing.clear_of_results)]
            if marks:
                elems.append(wrapped(f.g(class_="fo"), marks))
        if self.end is not None and sc.end_furniture:
            elems.append(end_furniture(sc, self.style, self.vp, self.end, self.placing, f))
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
            region.captions = self.captions  # captions wrap alike
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
            inset = magnified_inset(self, k)
            if inset is not None:
                dwg.add(inset)
        if self.style.show_caption:
            cap = self.caption_group(self.captions.frame_lines(k))
            if cap is not None:
                dwg.add(cap)
        return self.doc.text(dwg)

    def camera_group(self, view: tuple[float, float, float, float], *, fin: bool = False,
                     **attrs: Any) -> tuple[Any, Any]:
        """(outer, inner): ``<g>`` clipped to the drawing area holding ``<g id="camera">`` whose
        transform shows *view* on the whole drawing area (a nested ``<svg>`` would be a time
        container of its own in browsers, out of step with the animation's clock); *fin*: the end state."""
        f = self.doc.factory
        full = self.full_view
        clip = f.clipPath(id="camera-clip")
        clip.add(f.rect(insert=("0", "0"), size=(fmt(full[2]), fmt(full[3]))))
        outer = f.g(clip_path="url(#camera-clip)")
        outer.add(clip)
        inner = f.g(id="camera", class_=f"zl{level(camera_zoom(view, full))}" + (" fin" if fin else ""),
                    transform=camera_transform(view, full), **attrs)
        outer.add(inner)
        return outer, inner

    def camera_box(self, k: int, elems: Sequence[Any]) -> Any:
        """The drawing shown through step k's view, with the ring round a small current mark (the last step:
        the end state, when the scene has one)."""
        outer, inner = self.camera_group(self.camera_view(k), fin=self.end is not None and k == len(self.scene.steps))
        ring = self.ring(k)
        for e in elems:
            if ring is not None and getattr(e, "attribs", {}).get("id") == "labels":
                # under the letters: a letter's halo opens the ring, never the ring a letter
                inner.add(self.doc.factory.circle(center=(fmt(ring[0]), fmt(ring[1])), r=fmt(ring[2]), class_="ring"))
                ring = None
            inner.add(e)
        if ring is not None:
            inner.add(self.doc.factory.circle(center=(fmt(ring[0]), fmt(ring[1])), r=fmt(ring[2]), class_="ring"))
        return outer

    def layered(self, caption: Sequence[str] | None = None, *, centred: bool = False) -> str:
        """The canonical figure: every step a ``data-step`` group, nothing highlighted, the figure's caption.

        Still renderers show the whole figure; frame k is the view of steps 1..k.  With an end state
        (:class:`EndView`) the file shows that: its sheet is the end state's drawing (the root's
        ``viewBox``, class ``fin`` and the end view's zoom level), every step's group still in it.  A plate
        says so on its root (``<svg class="plate">``): ``construct lint`` holds it to what a printed plate
        never shows.
        """
        if self.end is not None:
            css = self.style.css() + "".join("\n" + c for c in (self.extra_css,) if c)
            return end_sheet(self.doc, self.end, self.scene, self.style, css,
                             self.body(len(self.scene.steps), mark_steps=False), caption)
        dwg = self.document(**({"class_": "plate"} if self.plate else {}))
        for e in self.body(len(self.scene.steps), mark_steps=False):
            dwg.add(e)
        if self.style.show_caption:
            cap = self.caption_group(self.captions.title_lines(caption), centred=centred)
            if cap is not None:
                dwg.add(cap)
        return self.doc.text(dwg)

    def final(self, caption: Sequence[str] | None = None, *, centred: bool = False) -> str:
        """All steps, nothing highlighted, with the figure's caption lines (the layered figure)."""
        return self.layered(caption, centred=centred)


def _start_anchored(items: Sequence[Any], scale: float, style: Style) -> tuple:
    """*items* with every lettering that has an index (P = F·p_ü) and is set at its end moved to be set at its
    start: a renderer may lay out each run of an end-anchored text by itself (cairosvg sets the index apart)."""
    out = []
    for it in items:
        if isinstance(it, Lettering) and it.anchor == "end" and len(subscript_runs(it.text)) > 1:
            w = text_width(plain(it.text), style.label_size * it.size, style.label_font, style.label_italic) / scale
            a = math.radians(it.angle)
            it = dataclasses.replace(it, at=(it.at[0] - w * math.cos(a), it.at[1] - w * math.sin(a)), anchor="start")
        out.append(it)
    return tuple(out)


def render_svg(scene: Scene, *, upto: int | None = None, style: Style = PLAIN,
               caption: "tuple[str, str] | PlateCaption | None" = None) -> str:
    """The figure after steps 1..upto (all steps when None), as SVG text; *caption*: its caption lines, or a
    plate's (:class:`construct.render.captions.PlateCaption`, one language in at most three lines)."""
    if upto is None:
        if style.fig_caption:
            # a plate: its own size, the "Fig." caption centred beneath
            n = len(Captions(scene, width=style.width_px - 2 * style.margin_px, size=style.caption_size)
                    .title_lines(caption))
            return Drawing(scene, style, caption_lines=n, plate=style.plate).final(caption, centred=True)
        return Drawing(scene, style).final(caption)
    return Drawing(scene, style).frame(upto)


def __getattr__(name: str) -> Any:
    """A name that moved (:data:`_MOVED`), still found here with a DeprecationWarning."""
    if name in _MOVED:
        import warnings

        warnings.warn(f"construct.render.svg.{name} moved to construct.render.{_MOVED[name]}.{name}",
                      DeprecationWarning, stacklevel=2)
        return getattr(_captions, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
