"""What the player page draws at a value of a given, without laying the page out (:class:`Measure`).

**Cost.**  A grid value is not a page (0.25 s for the 18-part crank, 0.5 s for
the inertia curve: the letters' placing and the camera): the marks' numbers of
all the values a round of the refinement asks for are drawn at once
(:class:`~construct.render.sweepdraw.SweepDrawing`, each kind of mark one
array over the values), and only a value where a mark changes its form, or a
figure the sweep does not draw (plate furniture), is drawn value by value (a
scene and the marks' numbers: 15 to 30 ms; an area is drawn by the page from
the curves that bound it, so a style's hatching does not count: a teaching
style that hatches took the three figures with areas value by value, 1,700
scenes, two thirds of the gallery's time).  The whole sweep of the 18-part
crank takes about 1 s, of the inertia curve about 4 s.  A mark that jumps (an
arc that flips to its other side) is recognised when halving its cell twice
does not shrink its miss, instead of being refined down to :data:`MIN_CELL`.
"""

from __future__ import annotations

import difflib
import heapq
import math
from collections.abc import Callable, Sequence
from types import SimpleNamespace
from typing import Any

import numpy as np

from ..constructions import Construction
from ..figure import Figure
from ..kernel.identity import by_identity
from ..render.camera import (FINAL_CONTEXT, MAX_ZOOM, PLAYER_FIGURE_PX, ZOOM_LEVELS, Framing, clip_view, framed_rows,
                             level, player_letter_scale, step_focus_names, step_shots, zoom_of)
from ..render.edges import clear_edges_rows
from ..render.end_state import (NumbersFactory, end_furniture, end_letter_boxes, end_lettering, end_lettering_at,
                                fixed_elements, furniture_numbers)
from ..render.output import scene_for
from ..render.insets import inset_details
from ..render.placing import Placing
from ..render.plate import Lettering, extent, plain, plate_of, shifted, subscript_runs
from ..render.player import inset_marks, player_html
from ..render.scene import MarkKind, extreme_points, reading
from ..render.sheet import break_shift
from ..render.styles import STYLES
from ..render.svg import Drawing, mark_geometry, mark_layer
from ..render.svgdoc import fmt
from ..render.sweepdraw import SweepDrawing, SweepForm, sweep_drawable
from ..render.viewport import Viewport
from ..render.wire import ARC, NUMBER, canonical_arc

#: How many forms of another value's furniture a Measure keeps matched to the built one's (:meth:`Measure._aligned`).
MATCHES = 64
#: The end state's furniture drawn as numbers (:func:`~construct.render.end_state.furniture_numbers`).
NUMBERS = NumbersFactory()

__all__ = ["Measure", "Frames", "player_page", "player_page_and_fit", "fit_of", "areas_of", "breaks_px"]


def number_places(keys: list) -> dict[tuple[str, str], int]:
    """Where each element's attribute (its id and attribute: a key's first two) starts among a page's numbers,
    which the keys *keys* (id, attribute, template with a ``#`` per number) give in order.

    >>> number_places([("a", "cx", "#"), ("a", "cy", "#"), ("p", "d", "M#,# L#,#")])
    {('a', 'cx'): 0, ('a', 'cy'): 1, ('p', 'd'): 2}
    """
    at, n = {}, 0
    for k in keys:
        at.setdefault((k[0], k[1]), n)
        n += k[2].count("#")
    return at


def _inside(scene: Any, vp: Viewport, view: tuple) -> list[str]:
    """The ids of the marks of *scene* that lie whole inside *view* (canvas px: x, y, w, h) on viewport *vp*."""
    x, y, w, h = view
    out = []
    for m in scene.marks:
        pts = [vp.px(*p) for p in extreme_points(m)]
        if pts and all(x <= px <= x + w and y <= py <= y + h for px, py in pts):
            out.append(m.id)
    return out


class Frames(Sequence):
    """The frames of a sweep's values (:meth:`Measure.frames`), each drawn when it is first read: what is drawn
    for all values at once is drawn, what is drawn value by value waits for a reader."""

    def __init__(self, size: int, frame: Callable[[int], tuple]):
        self._size, self._frame, self._got = size, frame, {}

    def __len__(self) -> int:
        return self._size

    def __getitem__(self, i):
        if isinstance(i, slice):
            return [self[j] for j in range(*i.indices(self._size))]
        if not -self._size <= i < self._size:
            raise IndexError(f"a sweep of {self._size} values has no value {i}")
        i %= self._size
        if i not in self._got:
            self._got[i] = self._frame(i)
        return self._got[i]


class Measure:
    """What the player page draws at a value of the given, without laying the page out: the same numbers as
    :func:`~construct.render.wire.drawn_numbers` of :func:`player_page` (tests/test_live.py holds them equal).

    The marks are drawn by the drawing's own code (:func:`~construct.render.svg.mark_geometry`) on the
    drawing's own fit to the view.  Letters are not placed: the page moves them with their points.  Each
    step's camera view is framed at every value as the camera frames its shot there (:meth:`_framing`: round
    the working regions of the shot's steps as drawn there, widened for the letters its window would cut where
    the page writes them); the shots themselves and how far each may magnify are the built value's (the
    camera's choice of shots costs 40 ms a value, and a teacher who moves the rod ratio keeps the shots of the
    book's figure).  A view no mark of its steps sets is carried along with the marks it shows (:meth:`_carried`:
    it moves and grows or shrinks with their box, cut to the canvas as the camera cuts it).  The end step's
    view, the finished figure, is framed at every value as the camera frames the end state there (its marks,
    the plate's furniture and the letters the page writes beside them: :meth:`_end_view`), as a fresh build
    frames it where its letters stand where the book's value's stand.  A sweep's values are measured together
    by :meth:`frames`.

    >>> from construct.constructions import get
    >>> c = get("crank"); fig = c.figure(parts=3)
    >>> keys, nums, fit, texts = Measure(c, fig)(fig)
    >>> keys[0], texts["s0001-O-label"]
    (('figure', 'viewBox', '# # # #'), 'O')
    """

    def __init__(self, construction: Construction, built: Figure, style: Any = None, *, drawing: Any = None):
        self.construction = construction
        self.style = style or STYLES["teaching"]
        # per list of keys (by its identity, the list kept): the columns of the edge letters' points (_letter_points)
        self._letter_columns: dict[int, tuple[list, dict[int, tuple[np.ndarray, np.ndarray]]]] = {}
        # *drawing*: the built figure's drawing in this style, if the caller has it (the player's own)
        if drawing is None:
            drawing = Drawing(scene_for(construction, built, ending=self.style.camera), self.style)
        scene = drawing.scene
        full = drawing.full_view
        self.steps = [s.index for s in scene.steps]
        views = [drawing.camera_view(k) for k in self.steps]
        #: per step, which of the distinct views it shows (-1: the whole figure)
        distinct: dict[tuple, int] = {}
        self.view_of = [-1 if v == full else distinct.setdefault(v, len(distinct)) for v in views]
        shows: list[set[int]] = [set() for _ in distinct]
        for k, j in zip(self.steps, self.view_of):
            if j >= 0:
                shows[j].add(k)
        self.framed = [[m.id for m in scene.marks if m.step in ks] for ks in shows]
        #: the end step's view, framed at every value as the camera frames the end state (:meth:`_end_view`): its
        #: index among the views, the box of what it draws, the page there and its letters (:meth:`_end_of`);
        #: None without an end state (or with its view shared by another step)
        self._end = self._end_of(scene, drawing)
        self.views = list(distinct)
        for j, ids in enumerate(self.framed):
            if not ids:  # another step that draws nothing of its own: carried with the marks inside its view
                self.framed[j] = _inside(scene, drawing.vp, self.views[j])
        #: the views framed anew at every value as the camera frames their shots (:meth:`_framing`): by the view's
        #: index, the most it magnifies and how the built view stands to the camera's framing of its marks
        self.framing = self._framing(scene, drawing)
        #: the areas between curves: drawn by the page from the curves that bound them (:func:`areas_of`)
        self.areas = areas_of(built.protocol, scene)
        #: the steps whose current mark is ringed (small on the screen at the built value), by their index, and
        #: the marks the ring goes round: the ring's centre is carried (the centre of their box)
        self.rings = [(i, [m.id for m in scene.marks if m.step == k]) for i, k in enumerate(self.steps)
                      if drawing.ring(k) is not None]
        self.boxes = self._boxes(scene, drawing.vp)
        #: the steps shown with an inset (:func:`~construct.render.insets.step_insets`, chosen at the built value) that
        #: the page does not find anew (a cluster's, :func:`~construct.render.insets.inset_detail`), by their index:
        #: its box (x, y, w, h) and the marks it is carried with (the points it letters, else the step's own
        #: marks), and their box at the built value (:meth:`_carried_insets`)
        boxed = [(i, k, z) for i, k in enumerate(self.steps) if (z := drawing.insets[k - 1]) is not None]
        details = inset_details(scene, drawing.vp.px, drawing.vp.scale, [(k, z) for _, k, z in boxed])
        self.insets = [(i, tuple(z), [m.id for m, _ in inset_marks(drawing, k, z)]
                        or [m.id for m in scene.marks if m.step == k]) for (i, k, z), d in zip(boxed, details)
                       if d is None]
        self._inset_b0 = self._inset_boxes(scene, drawing.vp)
        self.least = 1.0 / MAX_ZOOM
        self.template = scene
        #: the end state's view and letters' places: its furniture (the plate's) is drawn at every value as the
        #: drawing draws it (:func:`~construct.render.end_state.end_furniture`), the letters' offsets the built ones
        self.end, self.placing = drawing.end, drawing.placing
        #: the end state's furniture as built (keys, numbers, texts); drawn at every value while
        #: :attr:`furniture_live` (the sweep of a given over which it can be matched item by item:
        #: :meth:`furniture_kept`), held at these numbers else (the page shows it at the book's values alone)
        self._built = built
        self._checks: list[list[Any]] | None = None  # (built_checks)
        self._items = scene.end_furniture
        #: another value's furniture matched to the built one's, by its items' forms and texts (:meth:`_aligned`),
        #: and where each of the built items' forms and texts first stands (:func:`_pattern`)
        self._matches: dict[tuple, dict[int, int]] = {}
        self._first: dict[tuple, int] = {}
        for i, sign in enumerate(_signs(scene.end_furniture)[1]):
            self._first.setdefault(sign, i)
        #: each built furniture element's item: {its id: the item's index in the built furniture}
        self.owners: dict[str, int] = {}
        self.held = self._furniture(scene.end_furniture, drawing.vp, owners=self.owners)
        #: the ids of the elements of the plate's lettering (its texts and their leaders): where a value writes it
        #: at other spots about its places than its neighbour (:meth:`spots_key`), the sweep does not blend them
        #: there but switches at a grid value (live.sweep)
        self.lettering_ids = frozenset(i for i, k in self.owners.items() if isinstance(self._items[k], Lettering))
        #: the spots of the plate's lettering a value of a sweep wrote it at, by their key (:meth:`spots_key`)
        self._spots: dict[str, dict[str, tuple[float, float, float]]] = {}
        #: the built furniture's items that come and go over the sweep (a scale's ticks), by their index
        #: (:meth:`furniture_kept`): shown where the nearer grid value's plate has them; the rest follows the given
        self.hidden_items: frozenset[int] = frozenset()
        #: the texts of the items some value of the sweep draws that the built furniture has not (a scale's tick
        #: more): the page has no element for them (:meth:`furniture_kept`; said in :meth:`hidden_note`)
        self.added: list[str] = []
        #: whether the end state's furniture is drawn at every value of the sweep (None: not asked -- a value
        #: measured alone draws its own furniture, a sweep asks over its values); held (False), the page shows it
        #: at the book's values alone, and the end step's view frames the end state without it
        self.furniture_live: bool | None = None
        # the marks' keys as this value's page has them: each mark's numbers are a run of them, the runs in the
        # page's order (a sweep draws each mark's numbers for every value at once, :meth:`frames`)
        self.keys, _, _, texts = self._measured(scene)  # (the drawing's scene is what __call__ would make)
        self.runs = self._runs(self.keys)
        #: the end state's letters as the page moves them (:meth:`_letters`; None: none, or no end view)
        self._lettered = self._letters(self._end[3], drawing.end.letter) if self._end is not None else None
        # a protocol of another piece of the domain (live.sweep.pieces): its scene, runs and keys, made once (the
        # protocol kept with them: its id stays its own)
        self._forms = {id(built.protocol): (built.protocol, scene, self.runs, self.keys)}
        #: per protocol (by its id, kept alive in _forms): the marks a sweep's drawing boxes, and the rows of each
        #: view's and ring's marks among them (:meth:`frames`)
        self._rows: dict[int, tuple[tuple[str, ...], dict[tuple[str, ...], np.ndarray]]] = {}
        #: per protocol (by its id, kept alive in _forms): what a sweep's drawing draws whatever the values
        #: (:class:`~construct.render.sweepdraw.SweepForm`), made by the first round of its refinement for the rest
        self._sweep_forms: dict[int, SweepForm] = {}
        # the letters whose text is read off the figure (an angle), by the id of their letter (a lettered line's
        # letter stands at a point of its own, "NAME.at")
        readings = {name: label for st in built.protocol.steps for name, label in st.labels if "{∠" in label}
        of = lambda m: m.name[:-3] if m.id.endswith("-at") and m.name.endswith(".at") else m.name  # noqa: E731
        self.readings = {f"{m.id}-label": readings[of(m)] for m in scene.marks if of(m) in readings and m.label}
        # the same at every value (but the spots the built value writes its plate lettering at: each value its own)
        self.texts = {k: v for k, v in texts.items() if k not in self.readings and k != "#spots"}

    def _framing(self, scene: Any, drawing: Any) -> dict[int, tuple[float, float, float, float]]:
        """The views framed at every value as the camera frames a shot there (:func:`~construct.render.camera.
        step_views`: round the working regions of its steps, :func:`~construct.render.camera.step_focus_names`,
        widened where its window would cut a letter, :func:`~construct.render.edges.clear_edges`), the shots and
        their magnification the built value's: {view j: (the most it magnifies, s, ox, oy)}, the marks that set
        it in :attr:`framed` (their box is the shot's region), the letters it clears in :attr:`edge_letters`.
        Where the built view is that framing grown s times about its centre moved (ox, oy) times its width (the
        name tags of its steps, :func:`~construct.render.edges.clear_tag_edges`), so is every value's.  (The
        camera's own choice of shots at another value is not made: 40 ms a value.)  The end view is framed by
        :meth:`_end_view`; a view whose steps are shown whole or that no mark of theirs sets is carried
        (:meth:`_carried`)."""
        by_name = {m.name: m.id for m in scene.marks}
        ids = [[by_name[n] for n in ns] for ns in step_focus_names(scene)]
        full = drawing.full_view
        most: dict[int, float] = {}
        for first, last, z in step_shots(scene, Framing(full), drawing.vp.px, self._boxes(scene, drawing.vp, ids)):
            for k in range(first, last + 1):
                j = self.view_of[k - 1]
                if j >= 0:
                    most[j] = max(most.get(j, 0.0), z)  # (0.0: shown whole)
        #: the letters a framed view's window is widened for (:meth:`_framed_views`): per zoom level, the ids of
        #: their points and their boxes about them (x0, y0, x1, y1 less x, y at the letter scale 1), as the
        #: page moves them with their points (the rod's length at a break left out: it moves with the break)
        pl = drawing.placing
        self.edge_letters = {lvl: (pl.letter_ids(lvl), pl.letters_at(lvl)[:len(pl.letter_ids(lvl)), 2:])
                             for lvl in range(len(ZOOM_LEVELS))} if pl.lettered else {}
        end = self._end[0] if self._end is not None else None
        js, zs, focus = [], [], []
        for j, z in most.items():
            marks = list(dict.fromkeys(i for k, w in zip(self.steps, self.view_of) if w == j for i in ids[k - 1]))
            if j != end and z and marks:
                js.append(j)
                zs.append(z)
                focus.append(marks)
        if not js:
            return {}
        b = np.asarray(self._boxes(scene, drawing.vp, focus), dtype=float).T[:, :, None]
        at = {lvl: (pl.letters_at(lvl)[:len(i), :1], pl.letters_at(lvl)[:len(i), 1:2]) for lvl, (i, _) in
              self.edge_letters.items()}
        f = self._framed(b, np.asarray([full[2]]), np.asarray([full[3]]), np.asarray(zs)[:, None], at)[:, :, 0]
        out = {}
        for j, z, marks, (x, y, w, h) in zip(js, zs, focus, f.T.tolist()):
            if w < full[2] or h < full[3]:  # (else the camera frames the whole figure: no shot of its own)
                v = self.views[j]
                out[j] = (z, v[2] / w, (v[0] + v[2] / 2 - x - w / 2) / w, (v[1] + v[3] / 2 - y - h / 2) / w)
                self.framed[j] = marks
        return out

    def _framed(self, box: np.ndarray, W: np.ndarray, H: np.ndarray, z: np.ndarray, at: dict) -> np.ndarray:
        """The camera's views round the regions *box* (x0, y0, x1, y1 x views x values) on pages W x H, each view
        magnifying at most *z* (views x 1), widened for the letters its window cuts (*at*: per zoom level, the
        letters' points: x, y, each letters x values; their boxes :attr:`edge_letters`): 4 x views x values."""
        f = framed_rows(box, W, H, z)
        if not self.edge_letters:
            return f
        n, size = f.shape[1:]

        def letters_at(lvl: int, i: np.ndarray) -> tuple:  # (the views' columns i: view after view, of the values)
            x, y = at[lvl]
            return x[:, i % size], y[:, i % size], self.edge_letters[lvl][1]

        return clear_edges_rows(f.reshape(4, -1), np.tile(W, n), np.tile(H, n), letters_at).reshape(4, n, size)

    def _letter_points(self, keys: list, nums: np.ndarray) -> dict:
        """Per zoom level, the points of :attr:`edge_letters` on the pages whose numbers are *nums* (values x
        numbers, in the order of *keys*): x, y, each letters x values (NaN: not drawn)."""
        def columns(keys: list) -> dict:
            at = number_places(keys)
            return {lvl: tuple(np.asarray([at.get((i, a), -1) for i in ids], dtype=int) for a in ("cx", "cy"))
                    for lvl, (ids, _) in self.edge_letters.items()}

        # (every round of a piece asks with its one list of keys: found once)
        return {lvl: tuple(np.where((c >= 0)[:, None], nums[:, c].T, np.nan) for c in cols)
                for lvl, cols in by_identity(self._letter_columns, keys, columns).items()}

    def _framed_views(self, box: np.ndarray, W: np.ndarray, H: np.ndarray, out: np.ndarray, keys: list,
                      nums: np.ndarray) -> np.ndarray:
        """*out* (the views x (x, y, w, h) x values of :meth:`_carried_rows`) with the views of :attr:`framing`
        framed round their marks' boxes *box* (x0, y0, x1, y1 x views x values) on pages W x H whose numbers are
        *nums* (values x numbers, in the order of *keys*: the letters' points): the camera's framing of each
        value, grown and moved as the built view is grown and moved from the built one's."""
        if not self.framing:
            return out
        js = list(self.framing)
        z, s, ox, oy = (np.asarray(c, dtype=float)[:, None] for c in zip(*self.framing.values()))
        f = self._framed(box[:, js], W, H, z, self._letter_points(keys, nums) if self.edge_letters else {})
        w, h = f[2] * s, f[3] * s
        vw, vh = np.minimum(w, W), np.minimum(h, H)
        x = np.clip(f[0] + f[2] / 2 + ox * f[2] - vw / 2, 0.0, W - vw)
        y = np.clip(f[1] + f[3] / 2 + oy * f[2] - vh / 2, 0.0, H - vh)
        whole = (f[2] >= W) & (f[3] >= H) | np.isnan(box[0, js])
        moved = np.stack([np.round(c, 2) + 0.0 for c in (x, y, vw, vh)], axis=1)
        kept = (s == 1.0) & (ox == 0.0) & (oy == 0.0)
        out[js] = np.where(whole[:, None], out[-1][None], np.where(kept[:, None], f.transpose(1, 0, 2), moved))
        # (the built value: the camera's own view, to the hundredth -- a sweep's box and a scene's differ in the last
        # bits, a view's rounding with them)
        b0 = np.asarray([self.boxes[j] for j in js], dtype=float).T[:, :, None]
        with np.errstate(invalid="ignore"):
            built = (np.abs(box[:, js] - b0) < 1e-6).all(axis=0)
        out[js] = np.where(built[:, None], np.asarray([self.views[j] for j in js], dtype=float)[:, :, None], out[js])
        return out

    def _end_of(self, scene: Any, drawing: Any) -> tuple[int, tuple, tuple, list] | None:
        """:attr:`_end` of the built figure: the end view's index j, the box of what the end state draws
        (:func:`end_box`: its marks and the plate's furniture), the built page, and the letters it writes
        (:func:`~construct.render.end_state.end_letter_boxes`), which :meth:`_letters` finds on the page's
        numbers."""
        j = self.view_of[-1] if len(self.view_of) > 1 else -1
        if not scene.ending or drawing.end is None or j < 0 or self.view_of.count(j) > 1:
            return None
        drawn = end_box(scene, drawing.vp.px)
        if drawn is None:
            return None
        # (its marks: the end state's of the figure, which a sweep boxes; the end state's own from their numbers)
        self.framed[j] = [m.id for m in scene.marks if scene.in_end(m) and scene.end_shows(m)]
        return j, drawn, drawing.full_view, end_letter_boxes(scene, self.style, drawing.vp, drawing.placing,
                                                              drawing.end, drawing.doc.factory)

    def _letters(self, letters: list, ls0: float) -> tuple[np.ndarray, ...] | None:
        """The end state's *letters* (written at the letter scale *ls0*) as the page moves them: each with the
        place of its element's x and y among the page's numbers, and its box there as x, y + c + ls s (canvas
        px; ls the letter scale): a point's letter at its offset from the point, which the letter scale scales;
        the plate's lettering scaled about its own middle (the player's ``scale`` of it); and whether it is
        the plate's (the furniture's, which a held furniture does not show away from the book's value); and the
        ids of their elements."""
        at = number_places(self.keys)
        rows, ids = [], []
        for ident, attr, (x, y), b in letters:
            if (ident, attr) not in at or (ident, "cy" if attr == "cx" else "y") not in at:
                continue
            box = np.asarray(b) - (x, y, x, y)
            mid = (box[:2] + box[2:]) / 2 if attr == "x" else np.zeros(2)
            rows.append((at[(ident, attr)], at[(ident, "cy" if attr == "cx" else "y")], *mid, *mid,
                         *(box - np.tile(mid, 2)) / ls0, attr == "x"))
            ids.append(ident)
        if not rows:
            return None
        t = np.asarray(rows, dtype=float)
        return t[:, 0].astype(int), t[:, 1].astype(int), t[:, 2:6], t[:, 6:10], t[:, 10] > 0, ids

    def _end_view(self, box: tuple | None, full: tuple, nums: np.ndarray, absent: str = "") -> list[float]:
        """The end step's view of a value where the end state draws within *box* (canvas px: x0, y0, x1, y1) on
        the page *full*, its numbers *nums* (the page's, in its order; *absent*: the ids of the plate's elements it
        hides there, a scale's ticks that come and go, space-separated): as the camera frames it
        (end_state.lay_out_end: :data:`FINAL_CONTEXT` round it and the letters it writes, at the letter scale of
        the view, magnified at most the last zoom level), the letters where the page writes them (beside their
        points as placed at the book's value)."""
        if box is None:
            return list(full)
        j, built, page, _ = self._end
        box = tuple(round(c, 6) for c in box)  # (a sweep's box and a scene's differ in the last bits)
        if tuple(full) == page and max(abs(a - b) for a, b in zip(box, built)) < 1e-6:
            return list(self.views[j])  # (the built value: the camera's own view, to the hundredth)
        framing = Framing(full, max_zoom=ZOOM_LEVELS[-1])
        view = framing.view(box, FINAL_CONTEXT, 1.0)
        if self._lettered is None:
            return list(view)
        cx, cy, c, s, fur, ids = self._lettered
        shown = ~fur if self.furniture_live is False else np.ones(len(fur), dtype=bool)
        if absent:
            gone = set(absent.split())
            shown &= np.fromiter((i not in gone for i in ids), dtype=bool, count=len(ids))
        at = np.column_stack([nums[cx], nums[cy], nums[cx], nums[cy]])[shown] + c[shown]
        W, H = PLAYER_FIGURE_PX
        for _ in range(4):  # the letters widen the view, which sets their size (lay_out_end)
            z = zoom_of(view, full)
            ls = player_letter_scale(max(view[2] / W, view[3] / H) * z / ZOOM_LEVELS[level(z)])
            b = at + ls * s[shown]
            with np.errstate(invalid="ignore"):
                grown = (min(box[0], np.nanmin(b[:, 0], initial=box[0])), min(box[1], np.nanmin(b[:, 1], initial=box[1])),
                         max(box[2], np.nanmax(b[:, 2], initial=box[2])), max(box[3], np.nanmax(b[:, 3], initial=box[3])))
            new = framing.view(grown, FINAL_CONTEXT, 1.0)
            if new == view:
                break
            view = new
        return [float(c) for c in view]

    def _furniture(self, items: tuple, vp: Any, exact: bool = True, owners: dict[str, int] | None = None,
                   marks: "Callable[[], Any] | None" = None, keep: str | None = None,
                   lettered: "Callable[[], Any] | None" = None) -> tuple[list, list[float], dict[str, str]]:
        """The end state's furniture *items* (the plate's, on the sheet's broken axis) drawn on *vp* (anything with
        ``px`` and ``scale``): its keys, numbers and texts (:func:`~construct.render.end_state.furniture_numbers`).
        Another value's furniture is drawn in the built one's form (:meth:`_aligned`): a built item it lacks (a
        scale's tick) drawn where the built figure has it, on this value's axes, and named among the texts as
        ``"#absent"`` (its elements' ids: the page hides them there); its lettering placed among that value's
        end-state marks (*marks*: gives them; :func:`~construct.render.end_state.end_lettering_at`: where it stood
        at the built value where there is room, at the built end state's letter scale, which a fresh build there
        keeps too; *lettered*: gives the lettered ones among them, which alone are read where the lettering
        stands where it stood), or where the built value's placing set it about its places without *marks*; the
        spots it is written at are named among the texts as ``"#spots"`` (:meth:`spots_key`).  *keep*: the key of
        spots (a neighbouring value's) it is written at where they do not crowd there."""
        if self.end is None or not items:
            return [], [], {}
        absent: frozenset[int] = frozenset()
        if owners is None:  # (another value's)
            items, absent = self._aligned(items)
        own: dict[str, int] = {} if owners is None else owners
        sheet = SimpleNamespace(end_furniture=items)
        spots = fixed = lettering = None
        if marks is not None and any(isinstance(it, Lettering) for it in items):
            # (made once: placed among, then drawn)
            fixed = fixed_elements(sheet, vp, self.end, NUMBERS)
            lettering = end_lettering(sheet, vp, self.style, self.end.size)
            spots = end_lettering_at(sheet, marks, self.style, vp, self.end, self.placing, NUMBERS,
                                     None if keep is None else self._spots[keep], fixed, lettering,
                                     None if lettered is None else lettered())
        keys, nums, texts = furniture_numbers(end_furniture(sheet, self.style, vp, self.end, self.placing, NUMBERS,
                                                            own, spots, fixed, lettering), exact=exact)
        if spots is not None:
            texts["#spots"] = self.spots_key(spots)
        if absent:
            texts["#absent"] = " ".join(i for i, k in own.items() if k in absent)
        return keys, nums, texts

    def built_checks(self, figure: Figure) -> list[list[Any]]:
        """The construction's checks of *figure* (the built value's), as the live data carries them: [[name,
        measured, expected, error, tolerance, ok], ...].  Made once for the figure the Measure was built from:
        every piece of a given's domain and every given of the figure carry the same (Tafel I: eight pieces)."""
        if figure is not self._built or self._checks is None:
            rows = [[c.name, c.measured, c.expected, c.error, c.tolerance, bool(c.ok)]
                    for c in self.construction.checks(figure)]
            if figure is not self._built:
                return rows
            self._checks = rows
        return [list(r) for r in self._checks]

    def spots_key(self, spots: dict[str, tuple[float, float, float]]) -> str:
        """A name of the spots the plate's lettering stands at about its places (:func:`~construct.render.end_state.
        end_lettering_at`): its letters that stand elsewhere than at the built value, and where ("" where none
        does); two values write it alike where their keys are equal.  The spots are kept by it (*keep* of
        :meth:`frames`)."""
        # (to a millionth of a letter: a spot found anew where the built one stands differs in its last bits; a
        # built spot kept is the built one itself)
        at = lambda r: tuple(round(float(c), 6) for c in r)  # noqa: E731
        built = self.placing.end_spots
        key = " ".join(f"{f}:{','.join(map(repr, at(r)))}" for f, r in sorted(spots.items())
                       if built.get(f) is not r and (f not in built or at(built[f]) != at(r)))
        self._spots.setdefault(key, spots)
        return key

    def hidden_note(self, symbol: str) -> str:
        """The page's note on the items that come and go (:attr:`hidden_items`) with *symbol*, German / English, or
        "" without any: what of the plate the last step shows only where the plate has it.

        (A scale's ticks and numbers: "„3“, „4“ und 2 Striche" / "“3”, “4” and 2 strokes".)"""
        items = [self._items[i] for i in sorted(self.hidden_items)]
        many = len(self.added) > 1
        more = (" „" + "“, „".join(self.added) + f"“ (wo die Tafel {'sie' if many else 'es'} dazunähme) "
                + ("fehlen" if many else "fehlt"), " “" + "”, “".join(self.added)
                + f"” (where the plate would add {'them' if many else 'it'}) {'are' if many else 'is'} left out") \
            if self.added else ("", "")
        if not items:
            return (f"Im letzten Schritt{more[0]}. / In the last step{more[1]}.") if self.added else ""
        texts = [plain(it.text) for it in items if isinstance(it, Lettering)]
        lines = len(items) - len(texts)
        de = ", ".join(f"„{t}“" for t in texts) + (f" und {lines} Striche" if lines > 1 else " und einen Strich"
                                                   if lines else "")
        en = ", ".join(f"“{t}”" for t in texts) + (f" and {lines} strokes" if lines > 1 else " and a stroke"
                                                   if lines else "")
        return (f"Im letzten Schritt stehen {de.removeprefix(' und ')} der Tafel nur, wo die Tafel sie beim nächsten "
                f"berechneten Wert von {symbol} hat (sie kommen und gehen mit {symbol}); alles andere folgt {symbol}"
                f"{';' + more[0] if more[0] else ''}. / In the last step the plate’s {en.removeprefix(' and ')} "
                f"stand only where the plate has them at the nearest computed value of {symbol} (they come and go "
                f"with {symbol}); everything else follows {symbol}{';' + more[1] if more[1] else ''}.")

    def _aligned(self, items: tuple) -> tuple[tuple, frozenset[int]]:
        """Another value's furniture *items* in the built one's form: each built item where that value has it
        (:func:`_matched`), the built item where it has not; and the built items it has not, by their index."""
        # (matched once for each pattern of the items (_pattern): the values of a sweep write other numbers on
        # the plate, in a few patterns -- Tafel 2's 333 values in 17; at most MATCHES of them kept)
        key = _pattern(self._first, items)
        at = self._matches.get(key)
        if at is None:
            if len(self._matches) >= MATCHES:
                self._matches.clear()
            at = self._matches[key] = _matched(self._items, items)
        return (tuple(items[at[i]] if i in at else it for i, it in enumerate(self._items)),
                frozenset(range(len(self._items))) - set(at))

    def furniture_kept(self, protocol: Any, replay: Any, size: int, at: int = 0) -> frozenset[int] | None:
        """The built furniture's items that some value of the sweep *replay* of *protocol* lacks (a scale's
        ticks come and go with the diagram's height): drawn at every value where the built plate has them and
        shown where the nearer grid value's plate has them (an element that comes and goes would make the
        refinement split every cell about it); the rest of the furniture swept.  None where the furniture cannot
        be matched item by item (a plate of panels): held whole.  The texts of items some value adds that the
        built plate lacks go to :attr:`added`.  *at*: where the *size* values asked begin among the sweep's."""
        if not self.held[0]:
            return frozenset()
        # (its items' kinds and what of them is drawn, matched item by item: a value where an item draws other
        # elements all the same, a dimension turned level, is drawn value by value: frames)
        built = plate_of(self.construction, self._built).furniture
        if len(built) != len(self._items):
            return None
        kept = set(range(len(built)))
        self.added = []
        for i in range(at, at + size):
            p = plate_of(self.construction, Figure(protocol, replay.take(i), self.construction.check,
                                                   self.construction))
            if p.panels:
                return None
            at = _matched(built, p.furniture)
            kept &= set(at)
            new = set(range(len(p.furniture))) - set(at.values())
            self.added += [t for j in sorted(new) if isinstance(p.furniture[j], Lettering)
                           and (t := plain(p.furniture[j].text)) not in self.added]
        return frozenset(range(len(built))) - kept

    def furniture_keeps_form(self, protocol: Any, replay: Any, size: int) -> bool:
        """Whether the end state's furniture has the built figure's items at every value of the sweep *replay* of
        *protocol* (:meth:`furniture_kept` holds none)."""
        return self.furniture_kept(protocol, replay, size) == frozenset()

    def _furniture_at(self, figure: Figure, at_once: Any, i: int,
                      keep: str | None = None) -> tuple[list, list[float], dict[str, str], tuple]:
        """:meth:`_furniture` at value *i* of a sweep drawn at once: the plate's furniture of *figure* (that value
        of the sweep) on that value's broken axis and fit; and the box of the points it is set at (canvas px: x0,
        y0, x1, y1; NaN without any)."""
        p = plate_of(self.construction, figure)
        if p.panels or not p.furniture:
            return [], [], {}, (math.nan,) * 4
        breaks = at_once.breaks_at(i)
        items = tuple(shifted(it, break_shift(breaks)) for it in p.furniture) if breaks else tuple(p.furniture)
        px, fx = at_once.px_of(i), extent(items)
        # (the end state's marks there, which its lettering is placed among: read off the sweep's arrays, when
        # _furniture asks; the lettered ones alone where its lettering does not crowd)
        def marks() -> Any:
            return at_once.end_marks_at(i, Placing.end_obstacle)

        def lettered() -> Any:
            return at_once.end_marks_at(i, Placing.end_lettered)

        # (its numbers unrounded: frames rounds every value's at once)
        return (*self._furniture(items, SimpleNamespace(px=px, scale=float(at_once.fit[i][2])), exact=False,
                                 marks=marks, keep=keep, lettered=lettered),
                (*px(fx[0], fx[3]), *px(fx[2], fx[1])) if fx is not None else (math.nan,) * 4)

    def _runs(self, keys: list[tuple[str, str, str]]) -> list[tuple[str, int]]:
        """Each mark's run of numbers among *keys*: (its id, how many)."""
        runs: list[tuple[str, int]] = []
        for k in keys[1:len(keys) - len(self.view_of) - len(self.rings) - len(self.insets) - 2]:
            if runs and runs[-1][0] == k[0]:
                runs[-1] = (k[0], runs[-1][1] + k[2].count("#"))
            else:
                runs.append((k[0], k[2].count("#")))
        return runs

    def _form(self, protocol: Any, replay: Any) -> tuple[Any, list[tuple[str, int]], list[tuple[str, str, str]]]:
        """The scene, the marks' runs and the keys of *protocol* (drawn at the first value of *replay*)."""
        if id(protocol) not in self._forms:
            first = Figure(protocol, replay.take(0, whole=True), self.construction.check, self.construction)
            # (with its end state where the player shows one: __call__'s scene)
            scene = scene_for(self.construction, first, ending=self.style.camera)
            keys = self._measured(scene, keys_only=True)[0]
            self._forms[id(protocol)] = (protocol, scene, self._runs(keys), keys)
        return self._forms[id(protocol)][1:]

    def _boxes(self, scene, vp, framed=None) -> list[tuple[float, float, float, float] | None]:
        """Per distinct view, the box (canvas px: x0, y0, x1, y1) of the marks it frames (or of each list of
        *framed*)."""
        by_id = {m.id: m for m in scene.marks}
        out = []
        for ids in self.framed if framed is None else framed:
            pts = [p for i in ids if i in by_id for p in extreme_points(by_id[i])]
            if not pts:
                out.append(None)
                continue
            xs, ys = [p[0] for p in pts], [p[1] for p in pts]
            (x0, y0), (x1, y1) = vp.px(min(xs), max(ys)), vp.px(max(xs), min(ys))  # y runs down the canvas
            out.append((x0, y0, x1, y1))
        return out

    def _carried(self, j: int, box, full: tuple) -> list[float]:
        """View j of the built value carried along with its marks, now in *box*.

        The view moves with the marks' box and grows or shrinks with it, by the larger of the two sides'
        ratios (a side shorter than a quarter of the view counts as that quarter, so that a box of one point
        is not a division by nothing): a view that held its marks holds them still.  It shrinks no further
        than the camera's greatest magnification."""
        x, y, w, h = self.views[j]
        b0 = self.boxes[j]
        if b0 is None or box is None:
            return list(full)
        fw, fh = 0.25 * w, 0.25 * h
        s = max(max(box[2] - box[0], fw) / max(b0[2] - b0[0], fw), max(box[3] - box[1], fh) / max(b0[3] - b0[1], fh))
        if s < 1.0:
            s = max(s, min(1.0, self.least * max(full[2] / w, full[3] / h)))
        if w * s >= full[2] and h * s >= full[3]:
            return list(full)
        cx = (box[0] + box[2]) / 2 + (x + w / 2 - (b0[0] + b0[2]) / 2) * s
        cy = (box[1] + box[3]) / 2 + (y + h / 2 - (b0[1] + b0[3]) / 2) * s
        return list(clip_view(cx, cy, w * s, h * s, full))

    def frames(self, protocol: Any, replay: Any, size: int, keep: dict[int, str] | None = None) -> Frames:
        """:meth:`__call__` at every value of the sweep *replay* (of *size* values): the marks' numbers drawn for
        all values at once (:class:`~construct.render.sweepdraw.SweepDrawing`) where that draws what the drawing
        draws, value by value elsewhere (a value where a mark changes its form, a figure the sweep does not
        draw).  What is drawn value by value (the plate's furniture, a value's scene) is drawn when the value is
        read (:class:`Frames`): the refinement draws midpoints ahead and reads about half of them.  *keep*: the
        spots of the plate's lettering (their key, :meth:`spots_key`) some values write it at where they do not
        crowd there, by the values' index."""
        keep = keep or {}
        at_once = None
        template, runs, keys = self._form(protocol, replay)
        if sweep_drawable(template, self.style, hatching=False):  # (the page draws areas from their curves)
            try:
                at_once = SweepDrawing(template, protocol, replay, size, self.style,
                                       form=self._sweep_forms.get(id(protocol)))
                self._sweep_forms[id(protocol)] = at_once.form
            except ValueError:  # a mark of another kind than the built figure's: value by value
                at_once = None
        if at_once is not None and any(at_once.numbers.get(i, np.zeros((0, 0))).shape[1:] != (n,) for i, n in runs
                                       if not i.startswith("fin-")):  # (the end state's furniture: below)
            at_once = None
        whole = lambda i: self(Figure(protocol, replay.take(i, whole=True), self.construction.check,  # noqa: E731
                                      self.construction), keep=keep.get(i))
        if at_once is None or not at_once.ok.any():
            return Frames(size, whole)
        # the end state's furniture: the plate's, value by value (a plate's furniture is a few dozen lines and
        # letters read off a handful of points: 0.02 to 1.5 ms a value), when the value is read (below)
        furniture = {i: 0 for i, _ in runs if i.startswith("fin-")}
        live = self.furniture_live
        if furniture and live is None:  # (not asked: matched item by item over these values)
            kept = self.furniture_kept(protocol, replay, size)
            live = kept is not None
            self.hidden_items = kept or frozenset()
        want = [k for k in keys if k[0] in furniture] if furniture and live else []
        if furniture:  # held at the built value's numbers; drawn at every value: filled in as each is read
            table = np.tile(np.asarray(self.held[1], dtype=float), (size, 1)) if not want else \
                np.zeros((size, sum(k[2].count("#") for k in want)))
            at = 0
            for ident, count in runs:
                if ident in furniture:
                    at_once.numbers[ident] = table[:, at:at + count]
                    at += count
        rows = np.concatenate([at_once.numbers[i] for i, _ in runs], axis=1)  # (each a values x numbers block)
        # (the furniture's columns among them)
        stops = np.cumsum([n for _, n in runs])
        at_furniture = np.concatenate([np.arange(e - n, e) for (i, n), e in zip(runs, stops) if i in furniture]
                                      or [np.zeros(0, dtype=int)])
        width, height = (np.round(v, 2) for v in at_once.size)
        px = at_once.page_px

        # every mark's box (x0, x1, y0, y1: rows of marks x values), each view's and ring's marks as rows of them
        # (found once for a protocol's marks: every round asks for the same boxes of the same marks), all the
        # views' and rings' boxes at once: their marks' rows one after the other, each group reduced
        marked = tuple(at_once.extremes)
        found = self._rows.get(id(protocol))
        if found is None or found[0] != marked:
            at = {i: r for r, i in enumerate(marked)}
            groups = [[at[i] for i in ids if i in at] for ids in
                      self.framed + [ids for _, ids in self.rings] + [ids for _, _, ids in self.insets]]
            sizes = np.asarray([len(g) for g in groups], dtype=int)
            found = self._rows[id(protocol)] = (marked, np.asarray([r for g in groups for r in g], dtype=int),
                                                (np.cumsum(sizes) - sizes)[sizes > 0], sizes > 0)
        _, rows_of, starts, boxed = found
        box = np.full((4, len(boxed), size), np.nan)  # per group: x0, y0, x1, y1 on the page of every value
        if rows_of.size:
            ends = [at_once.extreme_rows[k][rows_of] for k in range(4)]
            least, most = np.minimum.reduceat, np.maximum.reduceat
            box[:, boxed] = (*px(least(ends[0], starts, axis=0), most(ends[3], starts, axis=0)),
                             *px(most(ends[1], starts, axis=0), least(ends[2], starts, axis=0)))
        views = len(self.framed)
        carried = self._framed_views(box[:, :views], width, height,  # (views + 1) x 4 x values
                                     self._carried_rows(box[:, :views], boxed[:views], width, height), keys,
                                     np.concatenate([np.zeros((size, 2)), width[:, None], height[:, None], rows], axis=1))
        if self._end is not None:  # the end view: framed at every value (the end state's own marks boxed too; the
            # furniture's box and the letters it writes where each value is read, below)
            j_end = self._end[0]
            ends = [at_once.end_boxes[m.id] for m in template.end_marks
                    if template.end_shows(m) and m.id in at_once.end_boxes]
            with np.errstate(invalid="ignore"):  # (NaN: nothing there)
                end_marks = np.stack([np.nanmin(np.stack([box[0, j_end], *(e[0] for e in ends)]), 0),
                                      np.nanmin(np.stack([box[1, j_end], *(e[1] for e in ends)]), 0),
                                      np.nanmax(np.stack([box[2, j_end], *(e[2] for e in ends)]), 0),
                                      np.nanmax(np.stack([box[3, j_end], *(e[3] for e in ends)]), 0)])
            # (where each step showing it keeps its view among the rest of a value's numbers)
            end_at = [4 * s + c for s, j in enumerate(self.view_of) if j == j_end for c in range(4)]
        # each value's row: these blocks, the marks' rows between the first three and the rest
        blocks = [np.zeros((size, 2)), width[:, None], height[:, None],
                  carried[self.view_of].transpose(2, 0, 1).reshape(size, -1)]
        rings = views + len(self.rings)
        if self.rings:  # the ring's centre: of the box of the step's marks
            ring = box[:, views:rings]
            centre = np.stack([np.round((ring[0] + ring[2]) / 2, 2), np.round((ring[1] + ring[3]) / 2, 2)])
            blocks.append(np.where(boxed[views:rings, None], centre, 0.0).transpose(2, 1, 0).reshape(size, -1))
        if self.insets:  # each inset's box: carried with its points
            blocks.append(self._carried_insets(box[:, rings:]).transpose(2, 0, 1).reshape(size, -1))
        blocks.append(at_once.breaks_page())
        head, rest = np.hstack(blocks[:3]), np.hstack(blocks[3:])
        fits = [tuple(row) for row in at_once.fit.tolist()]

        def frame(i: int) -> tuple:
            if not at_once.ok[i]:
                return whole(i)
            texts, fur_box = self.texts, (math.nan,) * 4
            if want:
                fk, fn, ft, fur_box = self._furniture_at(Figure(protocol, replay.take(i), self.construction.check,
                                                                self.construction), at_once, i, keep.get(i))
                if fk != want:  # (another form of the furniture there: value by value)
                    at_once.ok[i] = False
                    return whole(i)
                # (rounded as the writer writes them: within 0.01)
                rows[i, at_furniture] = np.round(np.asarray(fn, dtype=float), 2) + 0.0
                texts = {**texts, **ft} if ft else texts
            if self._end is not None:  # the end view: of its marks, the furniture and the letters written there
                with np.errstate(invalid="ignore"):
                    b = np.concatenate([np.fmin(end_marks[:2, i], fur_box[:2]), np.fmax(end_marks[2:, i], fur_box[2:])])
                rest[i, end_at] = np.tile(self._end_view(
                    None if np.isnan(b[0]) else tuple(b.tolist()), (0.0, 0.0, float(width[i]), float(height[i])),
                    np.concatenate([head[i], rows[i]]), texts.get("#absent", "")), len(end_at) // 4)
            if self.readings:
                taken = replay.take(i)
                texts = {**texts, **{k: reading(label, taken) for k, label in self.readings.items()}}
            # (the row as an array: the sweep reads every value's numbers as one; a list of floats would be
            # made and read back per value)
            return keys, np.concatenate([head[i], rows[i], rest[i]]), fits[i], texts

        return Frames(size, frame)

    def _carried_rows(self, box: np.ndarray, boxed: np.ndarray, W: np.ndarray, H: np.ndarray) -> np.ndarray:
        """:meth:`_carried` over a sweep, every view at once: the views carried along with their marks' boxes *box*
        (x0, y0, x1, y1 x views x values; *boxed*: the views whose marks the sweep draws), on pages W x H, and
        the whole page last: (views + 1) x (x, y, w, h) x values."""
        x, y, w, h = np.asarray(self.views, dtype=float).reshape(-1, 4).T[:, :, None]
        b0 = np.asarray([b if b is not None else (np.nan,) * 4 for b in self.boxes], dtype=float).reshape(-1, 4)
        b0 = b0.T[:, :, None]
        full = [np.zeros(W.shape), np.zeros(W.shape), W, H]
        fw, fh = 0.25 * w, 0.25 * h
        with np.errstate(invalid="ignore"):  # (the views without a box are the whole page)
            s = np.maximum(np.maximum(box[2] - box[0], fw) / np.maximum(b0[2] - b0[0], fw),
                           np.maximum(box[3] - box[1], fh) / np.maximum(b0[3] - b0[1], fh))
            s = np.where(s < 1.0, np.maximum(s, np.minimum(1.0, self.least * np.maximum(W / w, H / h))), s)
            whole = (w * s >= W) & (h * s >= H) | ~(boxed & ~np.isnan(b0[0]).ravel())[:, None]
            cx = (box[0] + box[2]) / 2 + (x + w / 2 - (b0[0] + b0[2]) / 2) * s
            cy = (box[1] + box[3]) / 2 + (y + h / 2 - (b0[1] + b0[3]) / 2) * s
            vw, vh = np.minimum(w * s, W), np.minimum(h * s, H)  # camera.clip_view over the sweep: on the canvas
            view = [np.clip(cx - vw / 2, 0.0, W - vw), np.clip(cy - vh / 2, 0.0, H - vh), vw, vh]
            out = np.stack([np.where(whole, f, np.round(v, 2) + 0.0) for f, v in zip(full, view)], axis=1)
        return np.concatenate([out, np.stack(full)[None]])

    def _inset_boxes(self, scene: Any, vp: Viewport) -> np.ndarray:
        """The boxes that carry the insets (:meth:`_carried_insets`) in *scene* drawn on *vp*: x0, y0, x1, y1 x
        insets x 1 (NaN where its marks are not drawn)."""
        boxes = self._boxes(scene, vp, [ids for _, _, ids in self.insets])
        return np.asarray([b if b is not None else (np.nan,) * 4 for b in boxes], dtype=float).reshape(-1, 4).T[:, :, None]

    def _carried_insets(self, box: np.ndarray) -> np.ndarray:
        """Each inset's box carried along with its marks, now in *box* (x0, y0, x1, y1 x insets x values; NaN where
        they are not drawn: the built box held), as :meth:`_carried` carries a view, not cut to the canvas (the
        inset may magnify a place at its edge): insets x (x, y, w, h) x values."""
        x, y, w, h = np.asarray([z for _, z, _ in self.insets], dtype=float).reshape(-1, 4).T[:, :, None]
        b0 = self._inset_b0
        fw, fh = 0.25 * w, 0.25 * h
        with np.errstate(invalid="ignore"):
            s = np.maximum(np.maximum(box[2] - box[0], fw) / np.maximum(b0[2] - b0[0], fw),
                           np.maximum(box[3] - box[1], fh) / np.maximum(b0[3] - b0[1], fh))
            cx = (box[0] + box[2]) / 2 + (x + w / 2 - (b0[0] + b0[2]) / 2) * s
            cy = (box[1] + box[3]) / 2 + (y + h / 2 - (b0[1] + b0[3]) / 2) * s
            carried = [cx - w * s / 2, cy - h * s / 2, w * s, h * s]
            held = np.isnan(s)
            out = [np.where(held, np.broadcast_to(z, s.shape), np.round(c, 2) + 0.0) for z, c in zip((x, y, w, h), carried)]
        return np.stack(out, axis=1)

    def __call__(self, figure: Figure, keep: str | None = None) -> tuple[list[tuple[str, str, str]], list[float],
                                                                         tuple, dict[str, str]]:
        # (with its end state where the player shows one: its own marks, the plate's, are drawn as the rest)
        return self._measured(scene_for(self.construction, figure, ending=self.style.camera), keep)

    def _view_keys(self) -> list[tuple[str, str, str]]:
        """The keys :meth:`__call__` ends with, whatever the figure: each step's view, ring, inset and the breaks."""
        return ([("#zoom", str(i), "# # # #") for i in range(len(self.view_of))]
                + [("#ring", str(i), "# #") for i, _ in self.rings]
                + [("#inset", str(i), "# # # #") for i, _, _ in self.insets]
                + [("#break", str(axis), "# #") for axis in (0, 1)])

    def _measured(self, scene: Any, keep: str | None = None, keys_only: bool = False
                  ) -> tuple[list[tuple[str, str, str]], list[float], tuple, dict[str, str]]:
        """:meth:`__call__` of the figure whose scene is *scene* (*keep*: as :meth:`frames` has it).  *keys_only*:
        its keys as :meth:`__call__` has them, its numbers only as far as the marks' and the furniture's (the views,
        rings, insets and breaks add keys of their own, whatever their numbers: :meth:`_form` reads the keys of a
        piece's protocol, and the views' numbers were a third of that)."""
        st = self.style
        vp = Viewport.fit(scene.bbox, st, 0)
        full = (0.0, 0.0, round(vp.width, 2), round(vp.height, 2))
        # each layer's elements in the order of the marks, the layers in the page's order
        layers: dict[str, tuple[list, list]] = {name: ([], []) for name in Drawing.LAYERS}
        texts: dict[str, str] = {}
        # (the end state's own marks among the rest by the step that made their object, as the drawing has them)
        for m in heapq.merge(scene.marks, sorted(scene.end_marks, key=lambda m: m.step), key=lambda m: m.step):
            if m.label and not m.id.endswith("-end"):  # (an end state's letter has no id: it follows its point)
                texts[f"{m.id}-label"] = m.label
            if m.kind is MarkKind.AREA:  # drawn by the page from the curves that bound it (areas_of)
                continue
            lk, ln = layers[mark_layer(m)]
            for suffix, _, attrs in mark_geometry(m, vp, st):
                ident = m.id + suffix
                for a, v in attrs.items():
                    if a != "d":  # one number (cx, r, x1, ...)
                        lk.append((ident, a, "#"))
                        ln.append(float(v))
                        continue
                    ns = [float(x) for x in NUMBER.findall(v)]
                    if ns:
                        t = NUMBER.sub("#", v)
                        lk.append((ident, a, t))
                        ln.extend(canonical_arc(ns) if t == ARC else ns)
        keys = [("figure", "viewBox", "# # # #")]
        nums = [0.0, 0.0, float(fmt(vp.width)), float(fmt(vp.height))]
        for lk, ln in layers.values():
            keys += lk
            nums += ln
        fk, fn, ft = self._furniture(scene.end_furniture, vp, marks=scene.end_drawn, keep=keep) \
            if self.furniture_live is not False else self.held
        keys += fk
        nums += fn
        texts.update(ft)
        if keys_only:
            return keys + self._view_keys(), nums, fit_of(vp), texts
        boxes = self._boxes(scene, vp)
        carried = [self._carried(j, box, full) for j, box in enumerate(boxes)] + [list(full)]  # [-1]: the whole
        if self.framing:
            b = np.asarray([bx if bx is not None else (np.nan,) * 4 for bx in boxes], dtype=float).reshape(-1, 4).T
            rows = np.asarray(carried, dtype=float)[:, :, None]
            W, H = np.asarray([full[2]]), np.asarray([full[3]])
            carried = self._framed_views(b[:, :, None], W, H, rows, keys, np.asarray([nums], dtype=float))[:, :, 0].tolist()
        if self._end is not None:
            carried[self._end[0]] = self._end_view(end_box(scene, vp.px, self.furniture_live is not False), full,
                                                   np.asarray(nums, dtype=float), texts.get("#absent", ""))
        for j in self.view_of:
            nums += carried[j]
        by_id = {m.id: m for m in scene.marks}
        for _, ids in self.rings:
            pts = [vp.px(*p) for m in ids if m in by_id for p in extreme_points(by_id[m])]
            nums += _ring_centre(min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts),
                                 max(p[1] for p in pts)) if pts else [0.0, 0.0]
        if self.insets:
            for z in self._carried_insets(self._inset_boxes(scene, vp))[:, :, 0].tolist():
                nums += z
        for axis in (0, 1):
            nums += breaks_px(scene.breaks, axis, fit_of(vp))
        return keys + self._view_keys(), nums, fit_of(vp), texts


def end_box(scene: Any, px: Any, furniture: bool = True) -> tuple[float, float, float, float] | None:
    """The box (canvas px: x0, y0, x1, y1; *px* maps a point of the figure there) of what the end state of
    *scene* draws: its marks shown and, with *furniture*, the plate's furniture (the points it is set at), as the
    camera frames it (:func:`~construct.render.camera.final_box`); None where it draws nothing."""
    pts = [px(*p) for m in scene.end_drawn() if scene.end_shows(m) for p in extreme_points(m)]
    fx = extent(scene.end_furniture) if furniture else None
    if fx is not None:
        pts += [px(fx[0], fx[1]), px(fx[2], fx[3])]
    if not pts:
        return None
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return (min(xs), min(ys), max(xs), max(ys))


def _form(items: Any) -> tuple:
    """The form of a plate's furniture: each item's kind and what of it is drawn (its text's runs, an upright
    text beside a dimension, a break, a turned text, a leader)."""
    return tuple((type(it).__name__, len(subscript_runs(t)) if (t := getattr(it, "text", "")) else 0,
                  getattr(it, "text_at", None) is None, getattr(it, "broken", False), bool(getattr(it, "angle", 0)),
                  getattr(it, "to", None) is None) for it in items)


def _matched(built: Any, items: Any) -> dict[int, int]:
    """Which of the furniture *items* (another value's) is each of the furniture *built*'s: {built index: index
    in items}, for the items of the same form and text in the longest common runs (difflib): a scale that lost
    its top ticks keeps its others and its unit; between those runs, a run of items of the same forms as many
    as the built one's (a text that changes with the given: a length, an angle).

    >>> from construct.render.plate import Lettering, Stroke
    >>> tick = lambda y: Stroke((0, y), (0.1, y))
    >>> five = (Lettering((0, 0), "B"), tick(0), Lettering((0, 0), "0"), tick(1), Lettering((0, 1), "1"),
    ...         Lettering((0, 2), "at"))
    >>> _matched(five, (Lettering((1, 1), "B"), tick(0), Lettering((0, 0), "0"), Lettering((0, 1), "at")))
    {0: 0, 1: 1, 2: 2, 5: 3}
    """
    (fb, sb), (fi, si) = _signs(built), _signs(items)
    out = {}
    for op, i0, i1, j0, j1 in difflib.SequenceMatcher(None, sb, si, autojunk=False).get_opcodes():
        if op == "equal" or (op == "replace" and fb[i0:i1] == fi[j0:j1]):
            out.update(zip(range(i0, i1), range(j0, j1)))
    return out


def _signs(items: Any) -> tuple[tuple, list[tuple]]:
    """The forms of a plate's furniture *items* (:func:`_form`), and each item's form with its text: what
    :func:`_matched` matches."""
    forms = _form(items)
    return forms, [(f, getattr(it, "text", "")) for f, it in zip(forms, items)]


def _pattern(first: dict[tuple, int], items: Any) -> tuple:
    """What :func:`_matched` of the built furniture and *items* depends on, as a key: the items' forms, and which
    built item each equals in form and text (*first*: each of the built items' forms and texts -> where it first
    stands among them; -1: none).  The matcher (difflib) pairs equal items only, so two values whose keys are
    equal are matched alike: a scale's numbers written anew at each value ("0,53" where the built plate has
    "0,52") are one key, not one a value.

    >>> from construct.render.plate import Lettering
    >>> first = {s: i for i, s in enumerate(_signs((Lettering((0, 0), "B"), Lettering((0, 1), "0,5")))[1])}
    >>> _pattern(first, (Lettering((1, 1), "B"), Lettering((0, 1), "0,6")))[1]
    (0, -1)
    >>> _pattern(first, (Lettering((1, 1), "B"), Lettering((0, 1), "0,7")))[1]
    (0, -1)
    """
    forms, signs = _signs(items)
    return forms, tuple(first.get(s, -1) for s in signs)


def areas_of(protocol: Any, scene: Any) -> list[list[str]]:
    """Each area between two graphs the figure draws (``area_between``) as the page draws it from the marks that
    bound it: [its first piece's id, the upper graph's, the lower graph's, the points whose abscissae end it].
    Its pieces come and go and hold as many points as the graphs have breakpoints between those abscissae, so
    no sweep can blend them; they are drawn anew from the graphs at every value (the script's ``areaPieces``,
    the twin of :func:`construct.kernel.areas.area_between`).

    >>> from construct.constructions import get
    >>> from construct.render.output import scene_for
    >>> c = get("tangential-pressure"); fig = c.figure(parts=6)
    >>> areas_of(fig.protocol, scene_for(c, fig))[1]
    ['s0526-excess', 's0516-tcurve', 's0523-mean', 's0524-A1', 's0525-A2']
    """
    first: dict[str, str] = {}
    for m in scene.marks:
        first.setdefault(m.name, m.id)
    out = []
    for st in protocol.steps:
        if st.op == "area_between" and st.outputs[0] in first and all(n in first for n in st.inputs):
            out.append([first[st.outputs[0]], *(first[n] for n in st.inputs)])
    return out


def _ring_centre(x0: float, y0: float, x1: float, y1: float) -> list[float]:
    """The centre of a ring round a box (canvas px, as the player's data writes it: insets.ring_round)."""
    return [round((x0 + x1) / 2, 2), round((y0 + y1) / 2, 2)]


def breaks_px(breaks: Any, axis: int, fit: tuple[float, float, float]) -> list[float]:
    """Where the figure's break across *axis* stands on the page: [the start of its band, its width] (canvas px:
    x and width, or top and height), or [0, 0] where the figure is not broken so."""
    ox, oy, s = fit
    for b in breaks:
        if (b[3] if len(b) > 3 else 0) == axis:
            start = ox + s * b[0] if axis == 0 else oy - s * (b[0] + b[1])
            return [round(start, 2), round(s * b[1], 2)]
    return [0.0, 0.0]


def player_page(construction: Construction, figure: Figure, style: Any) -> str:
    """The player page of *figure* (the same scene, drawing and fit as ``construct replay`` writes)."""
    scene = scene_for(construction, figure, ending=style.camera)
    return player_html(scene, style, drawing=Drawing(scene, style))


def player_page_and_fit(construction: Construction, figure: Figure, style: Any) -> tuple[str, tuple[float, float, float]]:
    """:func:`player_page` and the fit of its drawing to the view: (ox, oy, s), a point (x, y) of the
    construction is drawn at (ox + s x, oy - s y) px."""
    scene = scene_for(construction, figure, ending=style.camera)
    drawing = Drawing(scene, style)
    return player_html(scene, style, drawing=drawing), fit_of(drawing.vp)


def fit_of(vp: Viewport) -> tuple[float, float, float]:
    """A drawing's fit to the view, (ox, oy, s): a point (x, y) of the construction is drawn at (ox + s x, oy - s y)."""
    return (vp.margin + vp.left - vp.xmin * vp.scale, vp.margin + vp.top + vp.ymax * vp.scale, vp.scale)
