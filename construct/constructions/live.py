"""A live given: what the player draws at every value of a continuous given, precomputed by one sweep.

A teacher moves the rod ratio in the player and the whole construction follows.
The page does not construct anything: the protocol is replayed here over a grid
of the given in one numpy pass (``Protocol.replay`` with an array, the same
kernel as ``construct replay``), every grid value is measured as the player
draws it (:class:`Measure`: the scene and the drawing's own mark geometry on
the same fit to the view, without laying out a page -- a test holds the
numbers equal to the page's), and the page interpolates linearly between grid
values.

**The bound.**  The grid is chosen, not guessed: starting from a coarse grid in
log10 of the given, every cell's midpoint is replayed and drawn, the linear
interpolation of the cell's ends is compared there with the exact drawing,
coordinate by coordinate (pixels of the player's 1400-wide view), and a cell
whose error exceeds :data:`REFINE_PX` is split, until none does.  Stored
coordinates are quantised to :data:`QUANTUM_PX`, which adds at most half a
quantum; so every drawn coordinate the page shows at a midpoint is within
``REFINE_PX + QUANTUM_PX / 2`` = 0.425 px < 0.5 px of the exact drawing
(:attr:`LiveSweep.bound` is the measured maximum).  The drawing depends
smoothly on the given between grid values -- no intersection of the
constructions switches branch between neighbouring rod ratios
(tests/test_sweep.py, ``test_no_intersection_switches_branch_between_neighbouring_ratios``,
2000 ratios from 1.02 to 50; above 50 the refinement below would see a jump) --
so the midpoint error bounds the cell's error up to the curvature's variation
across the cell, which the refinement keeps small.  One thing in the drawing
is not continuous: the broken axis (a gap wider than a fifth of the figure is
broken out) appears at one rod ratio.  A cell across it never converges; it
is split down to :data:`MIN_CELL` and recorded in :attr:`LiveSweep.jumps`,
and the page snaps to the nearer side there.  An arc's large-arc flag is never
blended: it comes from the nearer grid value, and a cell where it flips is
refined while the other arc its ends allow lies more than 0.4 px away.  A mark
that alone jumps inside the domain (the inertia curve's arc about D flips to
its other side at several rod ratios) is drawn from the nearer grid value
everywhere (:attr:`LiveSweep.snapped`) instead of forcing the grid down at every
flip.  The grid stops growing at *max_values* values; a cell still too coarse
then is recorded as a jump (measured: none for the crank and the inertia curve).

**What travels.**  The grid is shared, but most coordinates need few of its
values: each coordinate keeps only the grid values where the line between
its neighbours would miss the exact drawing by more than :data:`ROW_PX` at
some grid value between (:func:`column_knots`), stored either as drawn or,
through each grid value's fit to the view, in the construction's own units
(the figure is rescaled to the view's width as L/r changes, so every drawn
coordinate moves, though the crank circle and all on it do not move in the
construction); identical coordinates travel once (:func:`encode`).  The page
rebuilds every grid value from that, then blends as above.

What is interpolated: every element of the figure that carries an id (the
marks: points, lines, circles, arcs, curves, areas and their hatching), the
figure's view box, and each step's camera view.  The bound holds for the
marks and the view box; the views are the built value's, carried along with
the marks they frame (:class:`Measure`), and blended (they frame, they are
not drawn).  Letters and leader lines belong to the label placer, which
may choose another spot from one value to the next; they move with the point
they name (the offset of the built value kept).

**Cost.**  A grid value is not a page (0.25 s for the 18-part crank, 0.5 s for
the inertia curve: the letters' placing and the camera): the marks' numbers of
all the values a round of the refinement asks for are drawn at once
(:class:`~construct.render.sweepdraw.SweepDrawing`, each kind of mark one
array over the values), and only a value where a mark changes its form, or a
figure the sweep does not draw (hatched areas), is drawn value by value (a
scene and the marks' numbers: 15 to 30 ms).  The whole sweep of the 18-part
crank takes about 1 s, of the inertia curve about 4 s.  A mark that jumps (an
arc that flips to its other side) is recognised when halving its cell twice
does not shrink its miss, instead of being refined down to :data:`MIN_CELL`.

>>> from construct.constructions import get
>>> live = live_sweep(get("crank"), get("crank").figure(parts=3), "rod_ratio", initial=5)
>>> bool(live.bound < 0.5 and live.grid[0] == 1.05 and live.grid[-1] == 1000.0)
True
"""

from __future__ import annotations

import base64
import functools
import json
import math
import re
import xml.etree.ElementTree as ET
import zlib
from dataclasses import dataclass, field
from typing import Any, Mapping

import numpy as np

from . import Construction
from ..figure import Figure
from ..kernel.errors import InvalidParameter
from .domain import Domain, ROD_RATIO

__all__ = ["LIVE_GIVENS", "LiveSweep", "Measure", "live_sweep", "drawn_numbers", "column_knots", "column_kinds", "encode", "decode", "inflated", "ROW_PX", "REFINE_PX", "QUANTUM_PX", "STORED_PX", "MIN_CELL",
           "live_data", "live_givens", "player_page", "check_picks"]

#: The continuous givens a player can move: protocol name -> (stated domain, the book's symbol).
LIVE_GIVENS: dict[str, tuple[Domain, str]] = {"rod_ratio": (ROD_RATIO, "L/r")}
#: A cell is split while linear interpolation misses the exact drawing by more than this (px).
REFINE_PX = 0.4
#: The refinement blends coordinates rounded to multiples of this (px).
QUANTUM_PX = 0.05
#: The page's coordinates travel as multiples of this (px, or its share of the largest scale in the
#: construction's units): the rounding is inside ROW_PX, which the columns are checked against.
STORED_PX = 0.1
#: A jump caused by at most this many marks is theirs (they are drawn from the nearer grid value), not the figure's.
SNAP_AT_MOST = 3
#: A mark whose miss at a cell's midpoint stays above this share of its miss in the cell split into it, twice
#: running, jumps there (a smooth mark's miss falls to a quarter at each halving, a kink's to a half).
JUMPING = 0.85
#: ... and misses by more than this (px): a smaller step is refined like the rest.
JUMP_PX = 2.0
#: A cell narrower than this (in log10 of the given) is not split further: it straddles a jump of the drawing.
MIN_CELL = 1e-4

_NUM = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
#: The attributes that carry geometry.
_GEOMETRY = ("cx", "cy", "r", "x1", "y1", "x2", "y2", "d", "points", "viewBox")
_SVG = "{http://www.w3.org/2000/svg}"


def live_givens(construction: Construction, figure: Figure) -> list[str]:
    """The continuous givens of *figure* a player offers a slider for (those a sweep can replay).

    >>> from construct.constructions import get
    >>> live_givens(get("crank"), get("crank").figure()), live_givens(get("indicator-diagram"), get("indicator-diagram").figure())
    (['rod_ratio'], [])
    """
    givens = dict(figure.replay.givens)
    out = []
    for name in LIVE_GIVENS:
        if name == "rod_ratio" and construction.rod_ratio_sweep(givens, [1.0]) is not None:
            out.append(name)
    return out


def drawn_numbers(page: str) -> tuple[list[tuple[str, str, str]], list[float], dict[str, Any]]:
    """The geometry of a player page's figure: ((element id, attribute, template), ...) and the numbers in order.

    Every element with an id, the figure's view box and, when the page has the player's data, each step's
    magnified view (key ``("#zoom", k, ...)``).  The third value holds the text of every lettered element by
    id (``texts``): a letter that is a measured value (an angle read off the figure) changes with the given.

    >>> keys, nums, _ = drawn_numbers('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 5">'
    ...                               '<circle id="p" cx="1.5" cy="2" r="3"/></svg>')
    >>> keys, nums
    ([('', 'viewBox', '# # # #'), ('p', 'cx', '#'), ('p', 'cy', '#'), ('p', 'r', '#')], [0.0, 0.0, 10.0, 5.0, 1.5, 2.0, 3.0])
    """
    svg = page[page.index("<svg"):page.index("</svg>") + len("</svg>")]
    root = ET.fromstring(svg)
    keys: list[tuple[str, str, str]] = []
    nums: list[float] = []
    texts: dict[str, str] = {}
    for e in root.iter():
        ident = e.get("id") or ""
        if ident and e.tag.rsplit("}", 1)[-1] == "text":
            texts[ident] = "".join(e.itertext())
        if e is not root and (not ident or ident == "ring"):  # the ring is the player's (the page moves it)
            continue
        for a in _GEOMETRY:
            v = e.get(a)
            if v is None or (e is root) != (a == "viewBox"):
                continue
            ns = _NUM.findall(v)
            if ns:
                keys.append((ident, a, _NUM.sub("#", v)))
                fs = [float(x) for x in ns]
                nums.extend(_canonical_arc(fs) if a == "d" and keys[-1][2] == _ARC else fs)
    marker = '<script type="application/json" id="data">'
    if marker in page:
        at = page.index(marker) + len(marker)
        data = json.loads(page[at:page.index("</script>", at)])
        full = [float(x) for x in root.get("data-full", root.get("viewBox", "")).split()]
        # each step's view: the camera's (``views``, ``v``) or the magnified box (``zooms``, ``z``; -1: the whole)
        boxes, index = ("views", "v") if "views" in data else ("zooms", "z")
        for i, st in enumerate(data["steps"]):
            keys.append(("#zoom", str(i), "# # # #"))
            j = st.get(index, -1)
            nums.extend(float(x) for x in data[boxes][j]) if j >= 0 else nums.extend(full)

    return keys, nums, {"texts": texts}


_ARC = "M# #A# # # # # # #"


def arc_flags(keys: list[tuple[str, str, str]]) -> np.ndarray:
    """Which of the numbers of *keys* are an arc's large-arc flag (taken from the nearer grid value, not blended).

    >>> arc_flags([("a", "cx", "#"), ("b", "d", "M# #A# # # # # # #")]).nonzero()[0].tolist()
    [6]
    """
    out: list[bool] = []
    for k in keys:
        n = k[2].count("#")
        out += [k[1] == "d" and k[2] == _ARC and i == 5 for i in range(n)]
    return np.asarray(out, dtype=bool)


@functools.lru_cache(maxsize=4)
def _key_columns(keys: tuple[tuple[str, str, str], ...]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Which key each number of *keys* belongs to, which numbers are views, which are large-arc flags
    (asked at every cell of the refinement, for the same keys)."""
    owner = np.asarray([i for i, k in enumerate(keys) for _ in range(k[2].count("#"))], dtype=int)
    return owner, _columns(keys, lambda k: k[0] == "#zoom"), arc_flags(keys)


def _midpoint_error(keys, na: np.ndarray, nb: np.ndarray, exact: np.ndarray,
                    snap: set[int]) -> tuple[float, dict[int, float]]:
    """The largest distance (px) between the page's drawing at a cell's midpoint and the exact one, and the
    keys that exceed REFINE_PX with the distance of their coordinates (without large-arc flags).

    Coordinates are blended from the quantised ends; large-arc flags and snapped keys come from either end
    (the worse counts); a wrong flag moves the arc by the distance between the two centres its ends and
    radius allow, 2 sqrt(r^2 - (c/2)^2)."""
    owner, views, flags = _key_columns(tuple(keys))
    if owner.size == 0:
        return 0.0, {}
    q = lambda n: np.round(n / QUANTUM_PX) * QUANTUM_PX  # noqa: E731
    blended = (q(na) + q(nb)) / 2
    col_err = np.abs(blended - exact)
    nearest = np.isin(owner, list(snap)) if snap else np.zeros(owner.size, dtype=bool)
    col_err[nearest] = np.maximum(np.abs(na - exact), np.abs(nb - exact))[nearest]
    col_err[views] = 0.0  # views frame the figure: blended, not refined for
    for c in np.nonzero(flags & ~nearest)[0]:
        col_err[c] = 0.0
        if na[c] != exact[c] or nb[c] != exact[c]:  # c is the flag: the arc's numbers are c-5 .. c+3
            x0, y0, r, x1, y1 = exact[c - 5], exact[c - 4], exact[c - 3], exact[c + 2], exact[c + 3]
            half = math.hypot(x1 - x0, y1 - y0) / 2
            col_err[c] = 2 * math.sqrt(max(r * r - half * half, 0.0))
    key_err = np.zeros(len(keys))
    np.maximum.at(key_err, owner, col_err)
    # what a culprit misses by in its coordinates (a large-arc flag that flips is not a jump of the arc: the
    # two arcs its ends allow meet as it flips, and refining converges there)
    coord_err = np.zeros(len(keys))
    np.maximum.at(coord_err, owner, np.where(flags & ~nearest, 0.0, col_err))
    bad = np.nonzero(key_err > REFINE_PX)[0].tolist()
    return float(col_err.max()), {k: float(coord_err[k]) for k in bad}


def _columns(keys: list[tuple[str, str, str]], pick) -> np.ndarray:
    """Which numbers of *keys* belong to keys *pick* selects."""
    return np.asarray([pick(k) for k in keys for _ in range(k[2].count("#"))], dtype=bool)


def _canonical_arc(ns: list[float]) -> list[float]:
    """An arc path's numbers drawn counter-clockwise on the page (sweep flag 1): the same arc, its ends swapped
    where it was drawn the other way, so that its numbers vary continuously with the given."""
    if ns[6] == 0.0:
        return [ns[7], ns[8], ns[2], ns[3], ns[4], ns[5], 1.0, ns[0], ns[1]]
    return ns


@dataclass
class LiveSweep:
    """A given's grid and what the player draws at every grid value."""

    given: str
    symbol: str
    domain: Domain
    initial: float
    grid: np.ndarray
    keys: list[tuple[str, str, str]]
    #: grid x numbers, pixels of the player's view.
    drawn: np.ndarray
    #: The measured maximum of |interpolated - exact| over every midpoint tested (px, after quantisation).
    bound: float
    #: Cells (low, high) across which the drawing jumps (the broken axis appearing).
    jumps: list[tuple[float, float]] = field(default_factory=list)
    #: At the grid values the page shows checks for (:func:`check_picks`), by their index in the grid:
    #: [[name, measured, expected, error, tolerance, ok], ...].
    checks: dict[int, list[list[Any]]] = field(default_factory=dict)
    #: Elements whose geometry is not interpolated (their form changes across the domain): shown at the built value.
    fixed: list[str] = field(default_factory=list)
    #: Letters whose text changes with the given (readings of the figure, e.g. the angle AOW): shown at the
    #: built value only.
    readings: list[str] = field(default_factory=list)
    #: Marks drawn from the nearer grid value (they jump inside the domain: an arc drawn the other way round).
    snapped: list[tuple[str, str, str]] = field(default_factory=list)
    #: The grid in log10 of the given, exactly as refined (a cell (a, b) was split at (a + b) / 2), and how
    #: many values the refinement started from: the cells of the refinement (:func:`column_knots`).
    u: np.ndarray | None = None
    start: int = 0
    #: Per grid value, the drawing's fit to the view (ox, oy, s): (x, y) is drawn at (ox + s x, oy - s y) px.
    fit: np.ndarray | None = None
    #: The checks at the built value, as :attr:`checks`.
    built_checks: list[list[Any]] = field(default_factory=list)

    def nearest_columns(self) -> np.ndarray:
        """The columns taken from the nearer grid value: large-arc flags and the snapped marks."""
        snapped = set(self.snapped)
        return arc_flags(self.keys) | _columns(self.keys, lambda k: k in snapped)


def _frames(construction: Construction, figure: Figure, given: str, values: np.ndarray, measure) -> list[tuple]:
    """(keys, numbers, fit, texts) of the player's figure at every value, from one sweep of the protocol."""
    givens = dict(figure.replay.givens)
    if given == "rod_ratio":
        swept = construction.rod_ratio_sweep(givens, values)
    else:
        swept = {**givens, given: np.asarray(values, dtype=float)}
    if swept is None:
        raise InvalidParameter(f"{construction.name} has no given {given} to sweep")
    replay = figure.protocol.replay(swept)
    return measure.frames(figure.protocol, replay, len(values)), replay


class Measure:
    """What the player page draws at a value of the given, without laying the page out: the same numbers as
    :func:`drawn_numbers` of :func:`player_page` (tests/test_constructions_live.py holds them equal).

    The marks are drawn by the drawing's own code (:func:`~construct.render.svg.mark_geometry`) on the
    drawing's own fit to the view.  Letters are not placed: the page moves them with their points.  Each
    step's camera view is the built value's view carried along with the marks it frames: the box of the
    marks of the steps it shows moves and grows or shrinks, and the view with it (its room round them kept
    in proportion, cut to the canvas as the camera cuts it, never past the camera's greatest magnification).
    The camera's own choice at another value is not computed (it places every letter of the figure, 0.2 to
    0.5 s a value); a teacher who moves the rod ratio keeps the shots of the book's figure.  A sweep's values
    are measured together by :meth:`frames`.

    >>> from construct.constructions import get
    >>> c = get("crank"); fig = c.figure(parts=3)
    >>> keys, nums, fit, texts = Measure(c, fig)(fig)
    >>> keys[0], texts["s0001-O-label"]
    (('figure', 'viewBox', '# # # #'), 'O')
    """

    def __init__(self, construction: Construction, built: Figure, style: Any = None, *, drawing: Any = None):
        from ..render.camera import MAX_ZOOM
        from ..render.output import scene_for
        from ..render.styles import STYLES
        from ..render.svg import Drawing

        self.construction = construction
        self.style = style or STYLES["teaching"]
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
        self.views = list(distinct)
        self.boxes = self._boxes(scene, drawing.vp)
        self.least = 1.0 / MAX_ZOOM
        self.template = scene
        # the marks' keys as this value's page has them: each mark's numbers are a run of them, the runs in the
        # page's order (a sweep draws each mark's numbers for every value at once, :meth:`frames`)
        self.keys, _, _, texts = self(built)
        self.runs: list[tuple[str, int]] = []
        for k in self.keys[1:len(self.keys) - len(self.view_of)]:
            if self.runs and self.runs[-1][0] == k[0]:
                self.runs[-1] = (k[0], self.runs[-1][1] + k[2].count("#"))
            else:
                self.runs.append((k[0], k[2].count("#")))
        # the letters whose text is read off the figure (an angle), by the id of their letter (a lettered line's
        # letter stands at a point of its own, "NAME.at")
        readings = {name: label for st in built.protocol.steps for name, label in st.labels if "{∠" in label}
        of = lambda m: m.name[:-3] if m.id.endswith("-at") and m.name.endswith(".at") else m.name  # noqa: E731
        self.readings = {f"{m.id}-label": readings[of(m)] for m in scene.marks if of(m) in readings and m.label}
        self.texts = {k: v for k, v in texts.items() if k not in self.readings}  # the same at every value

    def _boxes(self, scene, vp) -> list[tuple[float, float, float, float] | None]:
        """Per distinct view, the box (canvas px: x0, y0, x1, y1) of the marks it frames."""
        from ..render.scene import extreme_points

        by_id = {m.id: m for m in scene.marks}
        out = []
        for ids in self.framed:
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
        from ..render.camera import clip_view

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

    def frames(self, protocol: Any, replay: Any, size: int) -> list[tuple]:
        """:meth:`__call__` at every value of the sweep *replay* (of *size* values): the marks' numbers drawn for
        all values at once (:class:`~construct.render.sweepdraw.SweepDrawing`) where that draws what the drawing
        draws, value by value elsewhere (a value where a mark changes its form, a figure the sweep does not
        draw)."""
        from ..render.scene import reading
        from ..render.sweepdraw import SweepDrawing, sweep_drawable

        at_once = None
        if sweep_drawable(self.template):
            try:
                at_once = SweepDrawing(self.template, protocol, replay, size, self.style)
            except ValueError:  # a mark of another kind than the built figure's: value by value
                at_once = None
        if at_once is not None and any(at_once.numbers.get(i, np.zeros((0, 0))).shape[1:] != (n,)
                                       for i, n in self.runs):
            at_once = None
        if at_once is None or not at_once.ok.any():
            return [self(Figure(protocol, replay.take(i, whole=True), self.construction.check)) for i in range(size)]
        rows = np.hstack([at_once.numbers[i] for i, _ in self.runs])
        width, height = (np.round(v, 2) for v in at_once.size)
        px = at_once.page_px
        boxes = []
        for ids in self.framed:  # each view's marks' box, on the page of every value
            e = [at_once.extremes[i] for i in ids if i in at_once.extremes]
            if not e:
                boxes.append(None)
                continue
            (x0, y0), (x1, y1) = (px(np.min([b[0] for b in e], 0), np.max([b[3] for b in e], 0)),
                                  px(np.max([b[1] for b in e], 0), np.min([b[2] for b in e], 0)))
            boxes.append((x0, y0, x1, y1))
        out = []
        for i in range(size):
            if not at_once.ok[i]:
                out.append(self(Figure(protocol, replay.take(i, whole=True), self.construction.check)))
                continue
            full = (0.0, 0.0, float(width[i]), float(height[i]))
            nums = [0.0, 0.0, float(width[i]), float(height[i])] + rows[i].tolist()
            carried = [self._carried(j, None if b is None else tuple(float(c[i]) for c in b), full)
                       for j, b in enumerate(boxes)] + [list(full)]
            for j in self.view_of:
                nums += carried[j]
            taken = replay.take(i)
            texts = {**self.texts, **{k: reading(label, taken) for k, label in self.readings.items()}}
            out.append((self.keys, nums, tuple(float(v) for v in at_once.fit[i]), texts))
        return out

    def __call__(self, figure: Figure) -> tuple[list[tuple[str, str, str]], list[float], tuple, dict[str, str]]:
        from ..render.output import scene_for
        from ..render.svg import Drawing, mark_geometry, mark_layer
        from ..render.svgdoc import fmt
        from ..render.viewport import Viewport

        st = self.style
        scene = scene_for(self.construction, figure)
        vp = Viewport.fit(scene.bbox, st, 0)
        full = (0.0, 0.0, round(vp.width, 2), round(vp.height, 2))
        # each layer's elements in the order of the marks, the layers in the page's order
        layers: dict[str, tuple[list, list]] = {name: ([], []) for name in Drawing.LAYERS}
        texts: dict[str, str] = {}
        for m in scene.marks:
            if m.label:
                texts[f"{m.id}-label"] = m.label
            lk, ln = layers[mark_layer(m)]
            for suffix, _, attrs in mark_geometry(m, vp, st):
                ident = m.id + suffix
                for a, v in attrs.items():
                    if a != "d":  # one number (cx, r, x1, ...)
                        lk.append((ident, a, "#"))
                        ln.append(float(v))
                        continue
                    ns = [float(x) for x in _NUM.findall(v)]
                    if ns:
                        t = _NUM.sub("#", v)
                        lk.append((ident, a, t))
                        ln.extend(_canonical_arc(ns) if t == _ARC else ns)
        keys = [("figure", "viewBox", "# # # #")]
        nums = [0.0, 0.0, float(fmt(vp.width)), float(fmt(vp.height))]
        for lk, ln in layers.values():
            keys += lk
            nums += ln
        boxes = self._boxes(scene, vp)
        carried = [self._carried(j, box, full) for j, box in enumerate(boxes)] + [list(full)]  # [-1]: the whole
        for i, j in enumerate(self.view_of):
            keys.append(("#zoom", str(i), "# # # #"))
            nums += carried[j]
        fit = (vp.margin + vp.left - vp.xmin * vp.scale, vp.margin + vp.top + vp.ymax * vp.scale, vp.scale)
        return keys, nums, fit, texts


def player_page(construction: Construction, figure: Figure, style: Any) -> str:
    """The player page of *figure* (the same scene, drawing and fit as ``construct replay`` writes)."""
    from ..render.output import scene_for
    from ..render.player import player_html
    from ..render.svg import Drawing

    scene = scene_for(construction, figure, ending=style.camera)
    return player_html(scene, style, drawing=Drawing(scene, style))


def player_page_and_fit(construction: Construction, figure: Figure, style: Any) -> tuple[str, tuple[float, float, float]]:
    """:func:`player_page` and the fit of its drawing to the view: (ox, oy, s), a point (x, y) of the
    construction is drawn at (ox + s x, oy - s y) px."""
    from ..render.output import scene_for
    from ..render.player import player_html
    from ..render.svg import Drawing

    scene = scene_for(construction, figure, ending=style.camera)
    drawing = Drawing(scene, style)
    vp = drawing.vp
    fit = (vp.margin + vp.left - vp.xmin * vp.scale, vp.margin + vp.top + vp.ymax * vp.scale, vp.scale)
    return player_html(scene, style, drawing=drawing), fit


def live_sweep(construction: Construction, figure: Figure, given: str, *, initial: float | None = None,
               style: Any = None, start: int = 9, max_values: int = 400, drawing: Any = None) -> LiveSweep:
    """The grid of *given* over its domain on which linear interpolation draws within 0.5 px (see the module).

    *drawing*: the figure's :class:`~construct.render.svg.Drawing` in *style*, if the caller lays it out anyway
    (the player's): its camera views are the ones carried along."""
    from ..render.styles import STYLES

    style = style or STYLES["teaching"]
    domain, symbol = LIVE_GIVENS[given]
    initial = float(figure.replay.givens[given] if initial is None else initial)
    measure = Measure(construction, figure, style, drawing=drawing)
    lo, hi = math.log10(domain.low), math.log10(domain.high)
    us = list(np.linspace(lo, hi, start))
    values = lambda u: np.clip(10.0 ** np.asarray(u), domain.low, domain.high)  # noqa: E731
    frames, _ = _frames(construction, figure, given, values(us), measure)
    # each value's numbers as one array, made once (every cell it bounds reads them)
    as_arrays = lambda fs: [(f[0], np.asarray(f[1], dtype=float), *f[2:]) for f in fs]  # noqa: E731
    data = dict(zip(us, as_arrays(frames)))
    todo = list(zip(us[:-1], us[1:]))
    jumps: list[tuple[float, float]] = []
    snap: set[int] = set()  # keys drawn from the nearer grid value
    bound = 0.0
    # per cell, its culprits' errors in the cell it was split from and in that one's parent: a mark that
    # jumps misses by the same at every depth, a smooth one by a quarter at each halving
    before: dict[tuple[float, float], tuple[dict[int, float], dict[int, float]]] = {}
    while todo:
        mids = [(a + b) / 2 for a, b in todo]
        mframes, _ = _frames(construction, figure, given, values(mids), measure)
        mframes = as_arrays(mframes)
        nxt = []
        for (a, b), m, fm in zip(todo, mids, mframes):
            data[m] = fm
            ka, na = data[a][:2]
            kb, nb = data[b][:2]
            parent, grand = before.pop((a, b), ({}, {}))
            if not ka == kb == fm[0]:
                err, culprits = math.inf, {-1: math.inf}
            else:
                err, culprits = _midpoint_error(ka, na, nb, fm[1], snap)
            if err <= REFINE_PX:
                bound = max(bound, err)
                continue
            if 0 < len(culprits) <= SNAP_AT_MOST and -1 not in culprits and all(ka[c][0] != "figure" and
                    c in parent and c in grand and e > JUMPING * parent[c] and parent[c] > JUMPING * grand[c]
                    and e > JUMP_PX for c, e in culprits.items()):
                # one or two marks jump here (an arc drawn the other way round): halving the cell twice did not
                # shrink what they miss by, so they are drawn from the nearer grid value everywhere (the rest
                # stays blended) rather than refined down to the floor
                snap.update(culprits)
                continue
            if b - a >= MIN_CELL and len(data) <= max_values:
                nxt += [(a, m), (m, b)]
                before[(a, m)] = before[(m, b)] = (culprits, parent)
                continue
            if 0 < len(culprits) <= SNAP_AT_MOST and -1 not in culprits:
                snap.update(culprits)
                continue
            jumps.append((float(values(a)), float(values(b))))
        todo = nxt
    us = sorted(data)
    # The keys every grid value shares; a few elements change form (e.g. a curve's number of points):
    # they stay at the built value.
    shared = set(data[us[0]][0])
    for u in us:
        shared &= set(data[u][0])
    keys = [k for k in data[us[0]][0] if k in shared]
    rows = []
    for u in us:
        kk, nn = data[u][:2]
        if kk == keys:  # (the commonest: every mark at every value) the numbers as they are
            rows.append(nn)
            continue
        pos, at = {}, 0
        for k in kk:
            n = k[2].count("#")
            pos[k] = nn[at:at + n]
            at += n
        rows.append([x for k in keys for x in pos[k]])
    fixed = sorted({k[0] for u in us for k in data[u][0] if k not in shared})
    # letters whose text is not the same at every grid value: values read off the figure (an angle in degrees
    # and minutes); a blend of two grid values' readings would print minutes the figure does not have
    idents = set().union(*(data[u][3] for u in us))
    # (a letter left out at some values -- no room there -- is not one of them)
    varying = sorted(i for i in idents if len({data[u][3][i] for u in us if i in data[u][3]}) > 1)
    first = data[us[0]][0]
    snapped = [k for i, k in enumerate(first) if i in snap and k in shared]
    grid = values(us)
    live = LiveSweep(given, symbol, domain, initial, grid, keys, np.asarray(rows, dtype=float), bound, jumps,
                     fixed=fixed, snapped=snapped, u=np.asarray(us, dtype=float), start=start, readings=varying,
                     # the fit travels as float32: the columns are checked against the drawing through it
                     fit=np.asarray([data[u][2] for u in us], dtype=np.float32).astype(float))
    picks = check_picks(grid)
    live.checks = dict(zip(picks, _checks(construction, figure, given, grid[picks])))
    # and at the built value (the book's): a teacher who returns there sees its own checks
    live.built_checks = [[c.name, c.measured, c.expected, c.error, c.tolerance, bool(c.ok)]
                         for c in construction.checks(figure)]
    return live


def _checks(construction: Construction, figure: Figure, given: str, grid: np.ndarray) -> list[list[list[Any]]]:
    """The construction's checks at every value of *grid*, from one sweep (:meth:`Construction.sweep_checks`)."""
    givens = dict(figure.replay.givens)
    swept = construction.rod_ratio_sweep(givens, grid) if given == "rod_ratio" else {**givens, given: grid}
    sweep = Figure(figure.protocol, figure.protocol.replay(swept), construction.check)
    return [[[c.name, c.measured, c.expected, c.error, c.tolerance, bool(c.ok)] for c in row]
            for row in construction.sweep_checks(sweep)]


#: At every grid value, a coordinate the page computes from its column's kept values is within this of the
#: exact drawing (px, quantisation included); between grid values the page blends two grid values, whose
#: own blending error the refinement held under REFINE_PX at the parent cell's midpoint (about a quarter of
#: that at a cell's own), so a drawn coordinate stays under 0.5 px (measured at fresh values by the tests).
ROW_PX = 0.35
#: How a column is stored: as drawn (px), or in the construction's own units through the row's fit to the
#: view (:attr:`LiveSweep.fit`): an x (ox + s x), a y (oy - s y), a length (s l).
PX, X, Y, LENGTH = 0, 1, 2, 3
_PATH = re.compile(r"^[MLCZ# ,]*$")


def column_kinds(keys: list[tuple[str, str, str]]) -> np.ndarray:
    """What each number of *keys* is in the construction: x, y, a length, or a number of the drawing only.

    >>> column_kinds([("a", "cx", "#"), ("a", "r", "#"), ("b", "d", "M# #A# # # # # # #"), ("#zoom", "0", "# # # #")]).tolist()
    [1, 3, 1, 2, 3, 3, 0, 0, 0, 1, 2, 1, 2, 3, 3]
    """
    out: list[int] = []
    for ident, attr, template in keys:
        n = template.count("#")
        if attr in ("cx", "x1", "x2", "x"):
            out.append(X)
        elif attr in ("cy", "y1", "y2", "y"):
            out.append(Y)
        elif attr == "r":
            out.append(LENGTH)
        elif ident == "#zoom" or attr == "viewBox":
            out += [X, Y, LENGTH, LENGTH]
        elif attr == "d" and template == _ARC:
            out += [X, Y, LENGTH, LENGTH, PX, PX, PX, X, Y]
        elif attr in ("d", "points") and _PATH.match(template):
            out += [X if i % 2 == 0 else Y for i in range(n)]
        else:
            out += [PX] * n
    return np.asarray(out, dtype=np.int8)


def _quanta(live: LiveSweep, kinds: np.ndarray) -> np.ndarray:
    """The quantum of each column in its stored units: STORED_PX drawn, at most that at the largest scale."""
    smax = float(np.max(live.fit[:, 2])) if live.fit is not None and kinds.any() else 1.0
    return np.where(kinds > 0, STORED_PX / smax, STORED_PX)


def _stored(drawn: np.ndarray, fit: np.ndarray | None, kinds: np.ndarray) -> np.ndarray:
    """The drawn numbers in each column's stored units (the inverse of :func:`_drawn`)."""
    if fit is None or not kinds.any():
        return drawn
    ox, oy, sc = (fit[:, i:i + 1] for i in range(3))
    return np.select([kinds == X, kinds == Y, kinds == LENGTH], [(drawn - ox) / sc, (oy - drawn) / sc, drawn / sc],
                     drawn)


def _drawn(stored: np.ndarray, fit: np.ndarray | None, kinds: np.ndarray) -> np.ndarray:
    """Stored numbers (rows of the grid x columns) as drawn, px."""
    if fit is None or not kinds.any():
        return stored
    ox, oy, sc = (fit[:, i:i + 1] for i in range(3))
    return np.select([kinds == X, kinds == Y, kinds == LENGTH], [ox + sc * stored, oy - sc * stored, sc * stored],
                     stored)


def _knots(live: LiveSweep, kinds: np.ndarray) -> np.ndarray:
    """The grid values each column needs when stored as *kinds* says (see :func:`column_knots`)."""
    drawn = live.drawn
    rows, cols = drawn.shape
    u = np.asarray(live.u if live.u is not None else np.log10(live.grid), dtype=float)
    keep = np.zeros((rows, cols), dtype=bool)
    keep[:, live.nearest_columns()] = True
    quanta = _quanta(live, kinds)
    q = np.round(_stored(drawn, live.fit, kinds) / quanta) * quanta
    start = live.start or rows
    # the starting values of the refinement: evenly spaced in log10 (live_sweep's np.linspace)
    firsts = sorted({int(np.argmin(np.abs(u - x))) for x in np.linspace(u[0], u[-1], start)})

    def mid_of(i: int, j: int) -> int | None:
        m = (u[i] + u[j]) / 2
        at = int(np.searchsorted(u, m))
        for k in (at - 1, at, at + 1):
            if i < k < j and abs(u[k] - m) <= 1e-12 * max(1.0, abs(m)):
                return k
        return None

    todo = [(i, j, np.ones(cols, dtype=bool)) for i, j in zip(firsts[:-1], firsts[1:])]
    while todo:
        i, j, cs = todo.pop()
        m = mid_of(i, j)
        if m is None:  # a cell the refinement did not split: every column's own
            keep[[i, j]] |= cs
            continue
        # the line between the cell's quantised ends, at every grid value inside the cell, as drawn
        t = ((u[i + 1:j] - u[i]) / (u[j] - u[i]))[:, None]
        fit = live.fit[i + 1:j] if live.fit is not None else None
        at = np.flatnonzero(cs)  # only the columns still open here (deep in the tree, a few of thousands)
        err = np.abs(_drawn(q[i, at] + (q[j, at] - q[i, at]) * t, fit, kinds[at]) - drawn[i + 1:j, at]).max(axis=0)
        done = np.zeros(cols, dtype=bool)
        done[at[err <= ROW_PX]] = True
        keep[[i, j]] |= done
        rest = cs & ~done
        if rest.any():
            todo += [(i, m, rest), (m, j, rest)]
    return keep


def column_knots(live: LiveSweep) -> tuple[np.ndarray, np.ndarray]:
    """Which grid values each column of *live* needs (grid x columns, bool), and how it is stored.

    The refinement splits a cell while any coordinate misses at the midpoint; most coordinates would not have
    needed it.  Each column is walked down the same tree of cells, and a cell is that column's own (its ends
    kept, the grid values inside it dropped) as soon as the line between the cell's quantised ends is within
    :data:`ROW_PX` of the exact drawing at *every* grid value inside the cell (the midpoint, and every
    midpoint the refinement drew below it).  Between its kept values a column is that line (the page
    interpolates in log10 of the given).  Large-arc flags and snapped marks (drawn from the nearer grid
    value) keep every grid value.

    The fit to the view changes with the given (the figure is scaled to the view's width), so every drawn
    coordinate moves, and kinks where another point becomes the one that bounds the figure; in the
    construction's own units most coordinates do not move at all (the crank circle and everything on it) or
    move smoothly.  So each column is stored either as drawn or, through the row's fit, as the construction's
    x, y or length (:func:`column_kinds`), whichever needs fewer grid values.

    >>> live = LiveSweep("rod_ratio", "L/r", ROD_RATIO, 5.0, np.array([1.0, 10 ** 0.5, 10.0]), [("p", "cx", "#"),
    ...     ("q", "cx", "#")], np.array([[0.0, 0.0], [5.0, 7.0], [10.0, 10.0]]), 0.0, u=np.array([0.0, 0.5, 1.0]),
    ...     start=2)
    >>> column_knots(live)[0].T.astype(int).tolist()  # p is a line: its middle value is not needed; q is not
    [[1, 0, 1], [1, 1, 1]]
    """
    cols = live.drawn.shape[1]
    natural = column_kinds(live.keys) if live.fit is not None else np.zeros(cols, dtype=np.int8)
    as_drawn = _knots(live, np.zeros(cols, dtype=np.int8))
    if not natural.any():
        return as_drawn, natural
    as_built = _knots(live, natural)
    built = as_built.sum(axis=0) < as_drawn.sum(axis=0)
    return np.where(built, as_built, as_drawn), np.where(built, natural, 0).astype(np.int8)


def encode(live: LiveSweep) -> dict[str, Any]:
    """The coordinates of *live* for the page: identical columns once, each column at its own grid values and
    in its own units (:func:`column_knots`), quantised, delta-coded, deflated, base64.

    One deflated buffer: the column map (which stored column each coordinate is; uint16 or int32), each stored
    column's kind (uint8), its kept grid values as bits, the fit of every grid value (3 float32), each stored
    column's first value (int32), then the deltas between its kept values, all columns one after the other, as
    int16 where they fit (else int32) in byte planes (all low bytes, then all high bytes: the high bytes of
    small deltas are runs of 0 and 255 that deflate squeezes away).  :func:`decode` is what the page does.

    >>> live = LiveSweep("rod_ratio", "L/r", ROD_RATIO, 5.0, np.array([1.0, 10 ** 0.5, 10.0]), [("p", "cx", "#"),
    ...     ("q", "cx", "#"), ("r", "cx", "#")], np.array([[0.0, 0.0, 0], [5.0, 7.0, 5], [10.0, 10.0, 10]]), 0.0,
    ...     u=np.array([0.0, 0.5, 1.0]), start=2)
    >>> e = encode(live); (e["ucols"], e["width"]), decode(e, [0.0, 0.5, 1.0], 3, 3).tolist()
    ((2, 2), [[0.0, 0.0, 0.0], [5.0, 7.0, 5.0], [10.0, 10.0, 10.0]])
    """
    rows, cols = live.drawn.shape
    keep, kinds = column_knots(live)
    quanta = _quanta(live, kinds)
    q = np.round(_stored(live.drawn, live.fit, kinds) / quanta).astype(np.int64)
    fit = live.fit if live.fit is not None else np.zeros((rows, 3))
    # identical columns (a point's coordinate in its circle, its lines, its arcs) travel once, with the union
    # of their kept values; stored in the order the columns first appear (neighbours stay neighbours).  A
    # column is known by its bytes (np.unique over columns sorts them all: half the encoding's time)
    whole = np.ascontiguousarray(np.vstack([q, keep, kinds[None, :]]).T)
    seen: dict[bytes, int] = {}
    colmap = np.empty(cols, dtype=np.int64)
    firsts: list[int] = []
    for c in range(cols):
        colmap[c] = seen.setdefault(whole[c].tobytes(), len(firsts))
        if colmap[c] == len(firsts):
            firsts.append(c)
    pick = np.asarray(firsts, dtype=np.int64)
    uq, ukeep, ukinds = q[:, pick], keep[:, pick], kinds[pick]
    ukeep[[0, -1]] = True
    values = [uq[ukeep[:, c], c] for c in range(uq.shape[1])]
    deltas = np.concatenate([np.diff(v) for v in values]) if values else np.zeros(0, dtype=np.int64)
    width = 2 if deltas.size == 0 or np.abs(deltas).max() < 2 ** 15 else 4
    mapw = 2 if uq.shape[1] < 2 ** 16 else 4
    planes = np.ascontiguousarray(deltas.astype(f"<i{width}").view(np.uint8).reshape(-1, width).T)
    payload = (colmap.astype(f"<u{mapw}").tobytes() + ukinds.astype(np.uint8).tobytes()
               + np.packbits(ukeep.T.reshape(-1)).tobytes() + fit.astype("<f4").tobytes()
               + uq[0].astype("<i4").tobytes() + planes.tobytes())
    return {"data": base64.b64encode(zlib.compress(payload, 9)).decode("ascii"), "width": width, "mapw": mapw,
            "ucols": int(uq.shape[1]), "q": STORED_PX, "qx": float(_quanta(live, np.ones(1, dtype=np.int8))[0])}


def decode(data: Mapping[str, Any], grid: Any, rows: int, cols: int) -> np.ndarray:
    """The inverse of :func:`encode`, on the whole grid (*grid*: log10 of the grid values), as the page does it
    with DecompressionStream: each stored column between its kept values is the line between them in log10
    of the given, drawn through the grid value's fit."""
    raw = zlib.decompress(base64.b64decode(data["data"]))
    ucols, width, mapw = data["ucols"], data["width"], data["mapw"]
    at = cols * mapw
    colmap = np.frombuffer(raw[:at], dtype=f"<u{mapw}").astype(np.int64)
    kinds = np.frombuffer(raw[at:at + ucols], dtype=np.uint8).astype(np.int8)
    at += ucols
    nbits = rows * ucols
    keep = np.unpackbits(np.frombuffer(raw[at:at + (nbits + 7) // 8], dtype=np.uint8))[:nbits]
    keep = keep.reshape(ucols, rows).astype(bool)
    at += (nbits + 7) // 8
    fit = np.frombuffer(raw[at:at + 12 * rows], dtype="<f4").reshape(rows, 3).astype(float)
    at += 12 * rows
    first = np.frombuffer(raw[at:at + 4 * ucols], dtype="<i4").astype(np.int64)
    at += 4 * ucols
    n = int(keep.sum()) - ucols
    deltas = np.ascontiguousarray(np.frombuffer(raw[at:], dtype=np.uint8).reshape(width, n).T).view(f"<i{width}")
    deltas = deltas.reshape(-1).astype(np.int64)
    g = np.asarray(grid, dtype=float)
    quanta = np.where(kinds > 0, data["qx"], data["q"])
    out = np.empty((rows, ucols))
    pos = 0
    for c in range(ucols):
        idx = np.nonzero(keep[c])[0]
        vals = first[c] + np.concatenate([[0], np.cumsum(deltas[pos:pos + idx.size - 1])])
        pos += idx.size - 1
        out[:, c] = np.interp(g, g[idx], vals * quanta[c])
    return _drawn(out, fit, kinds)[:, colmap]


def book_number(value: float) -> str:
    """A given as the book prints it: decimal comma, no trailing zeros.

    >>> book_number(4.5), book_number(5.0), book_number(1.05)
    ('4,5', '5', '1,05')
    """
    return f"{value:.4g}".replace(".", ",")


def live_data(live: LiveSweep) -> dict[str, Any]:
    """What the page needs: the given and its domain in the open; deflated: the grid (log10), the keys, which
    columns are drawn from the nearer grid value, the jumps (``meta_z``), the coordinates (``data``,
    :func:`encode`) and the checks (``checks_z``)."""
    # a jump: the index of its cell's lower grid value
    where = {float(v): i for i, v in enumerate(live.grid)}
    meta = {"grid": [round(math.log10(v), 12) for v in live.grid],
            "keys": [list(k) for k in live.keys], "flags": live.nearest_columns().nonzero()[0].tolist(),
            "jumps": sorted(where[float(a)] for a, _ in live.jumps)}
    return {"given": live.given, "symbol": live.symbol, "low": live.domain.low, "high": live.domain.high,
            "initial": live.initial, "rows": int(live.drawn.shape[0]), "cols": int(live.drawn.shape[1]),
            **({"readings": live.readings} if live.readings else {}),
            **encode(live), "bound": round(live.bound + QUANTUM_PX / 2, 3),
            "meta_z": _deflated(meta), "checks_z": _deflated(_check_table(live))}


def _deflated(value: Any) -> str:
    return base64.b64encode(zlib.compress(json.dumps(value, separators=(",", ":")).encode("utf-8"), 9)).decode("ascii")


def inflated(text: str) -> Any:
    """A deflated JSON field of :func:`live_data` read back.

    >>> inflated(_deflated({"a": [1, 2]}))
    {'a': [1, 2]}
    """
    return json.loads(zlib.decompress(base64.b64decode(text)))


#: The checks travel at this many grid values at most, and at the built value (the page shows the nearest: it
#: says which).
CHECK_VALUES = 48


def check_picks(grid: np.ndarray) -> list[int]:
    """The grid values (indices) the page shows checks at: up to CHECK_VALUES, evenly in log10 of the given
    (the grid is dense where the drawing bends, the slider is not), the first and the last among them.

    >>> check_picks(np.array([1.0, 1.1, 1.2, 10.0, 100.0]))  # 1.1 and 1.2 are one place on the slider
    [0, 2, 3, 4]
    >>> len(check_picks(10 ** np.linspace(0, 3, 500))), check_picks(10 ** np.linspace(0, 3, 500))[-1]
    (48, 499)
    """
    u = np.log10(grid)
    return sorted({int(np.argmin(np.abs(u - t))) for t in np.linspace(u[0], u[-1], min(len(u), CHECK_VALUES))})


def _check_table(live: LiveSweep) -> dict[str, Any]:
    """The checks at up to CHECK_VALUES grid values, evenly in log10: names once, numbers to 9 digits."""
    if not live.checks:
        return {"checks": [], "check_values": [], "check_names": []}
    g = lambda x: float(f"{x:.9g}") if math.isfinite(x) else None  # noqa: E731
    at = [(float(live.grid[i]), live.checks[i]) for i in sorted(live.checks)]
    if live.built_checks and all(v != live.initial for v, _ in at):  # the book's value among them
        at = sorted(at + [(float(live.initial), live.built_checks)], key=lambda x: x[0])

    def row(c: list[Any]) -> list[Any]:
        # [formula, error, ok] and the constructed value where formula + error does not give its 9 digits
        # (a Euclidean chain's error is 1e-16: the constructed value is the formula's, to every digit shown)
        expected, error = g(c[2]), float(f"{c[3]:.2g}") if math.isfinite(c[3]) else None
        out = [expected, error, c[5]]
        if expected is None or error is None or g(expected + error) != g(c[1]):
            out.append(g(c[1]))
        return out

    return {"check_names": [c[0] for c in at[0][1]], "check_values": [v for v, _ in at],
            "checks": [[row(c) for c in cs] for _, cs in at]}
