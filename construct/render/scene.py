"""From a replayed protocol to a list of drawable marks, independent of any style.

A draftsman does not draw whole circles and endless lines: he draws a short
arc around each crossing he wants and a line a little past its last point.
The scene does the same, from the protocol alone: every point a step marks on
a curve (an intersection, a "through" point) extends that curve's drawn part.
Extents are taken from the *whole* construction, so that frame k is exactly
the first k steps of the final figure and frames line up.

>>> from construct.constructions import get
>>> fig = get("crank").figure(parts=6, rod_ratio=4.0)
>>> sc = build_scene(fig)
>>> sc.marks[0].kind, sc.marks[0].name
(<MarkKind.POINT: 'point'>, 'O')
>>> len(sc.upto(5)) < len(sc.marks)
True
"""

from __future__ import annotations

import bisect
import dataclasses
import functools
import math
import re
from dataclasses import dataclass
from typing import Any, Iterable, Sequence

from ..kernel.geometry import Circle, Length, Line, Point
from ..kernel.protocol import Protocol, Replay, Step
from ..kernel.letters import FIGURE_LETTER, primed
from .captions import TITLE_LIMIT, displayed
from .marks import (TWO_PI, Mark, MarkKind, arc_at, curve_points, extreme_points, fanned_lines, letter_lines,
                    lies_on, mark_box, marked_arc, segment_at, segment_span)
from .end_marks import end_state
from .sheet import Break, break_shift, breaks_figure, broken, kept_span, lay_out, plate_names, warn_hidden_labels
from .step_inputs import StepInputs

__all__ = ["Mark", "MarkKind", "Scene", "build_scene", "label_offset_direction", "on_curve_names", "extreme_points",
           "thin", "reading", "plate_names", "break_shift", "FIGURE_LETTER"]


@dataclass(frozen=True)
class Scene(StepInputs):
    """All marks of a figure in step order, with its bounding box (y up).

    What each step takes up and names (its inputs, what its arc is struck onto, the points it tags) it answers
    as a :class:`~construct.render.step_inputs.StepInputs`, its base class.
    """

    marks: tuple[Mark, ...]
    bbox: tuple[float, float, float, float]  # xmin, ymin, xmax, ymax
    steps: tuple[Step, ...]
    title: tuple[str, str]
    params: dict
    #: Broken axis: (x where the break starts, its drawn width, the length it leaves out), drawing units.
    breaks: tuple[Break, ...] = ()
    #: Plate furniture (:mod:`construct.render.plate`): dimensions, angle arcs, scale bars, signs.
    furniture: tuple = ()
    #: What the book plate shows (:func:`plate_names`): what a finished group collapses to.
    essentials: frozenset = frozenset()
    #: The end state (:meth:`in_end`): the last teaching frame shows the figure as the book draws it.
    ending: bool = False
    #: Marks only the end state draws: the plate's look of a result whose teaching mark is drawn otherwise
    #: (a line as far as the points the book shows on it, the crank circle as the book's half circle).
    end_marks: tuple[Mark, ...] = ()
    #: The ids of the marks the end state draws otherwise (by a mark of :attr:`end_marks`).
    end_replaced: frozenset = frozenset()
    #: The plate's furniture the end state adds (ordinates with their values, scales, signs).
    end_furniture: tuple = ()
    #: The looks the end state gives marks it draws where they stand ({mark id: look}: the curve heavy).
    end_looks: "dict[str, str]" = dataclasses.field(default_factory=dict)

    def upto(self, k: int) -> list[Mark]:
        """The marks made by steps 1..k."""
        return [m for m in self.marks if m.step <= k]

    def in_end(self, m: Mark) -> bool:
        """Does the end state (the last teaching frame, :attr:`ending`) draw mark *m* as it stands?

        The end state is the figure as the book's plate shows it (:attr:`essentials`): the results and
        what locates them, the helpers gone, a result the plate draws otherwise replaced by its
        :attr:`end_marks`.  Without an end state every mark stays.
        """
        return not self.ending or (m.name in self.essentials and m.id not in self.end_replaced)

    def end_look(self, m: Mark) -> str:
        """The look mark *m* has in the end state (the plate's, where it gives one)."""
        return self.end_looks.get(m.id, m.look)

    def end_drawn(self) -> list[Mark]:
        """The marks the end state draws: those of the figure it keeps (:meth:`in_end`), then its own
        (:attr:`end_marks`)."""
        return [m for m in self.marks if self.in_end(m)] + list(self.end_marks)

    def end_shows(self, m: Mark) -> bool:
        """Is mark *m*, one the end state draws (:meth:`end_drawn`), seen there (its end look not hidden)?"""
        return "hidden" not in self.end_look(m).split()

    def readable(self, text: str, lang: str = "de", outputs: tuple[str, ...] = ()) -> str:
        """*text* in the figure's letters (:class:`construct.render.captions.Reader`).

        Composite steps name their helpers by path (``T4.G.M2``: mark M2 of
        the division G of trisection T4); in a caption beside the figure the
        last part is what the eye finds (the teaching style tags the current
        step's points with it), the path is in the group title above.  A
        lettered object goes by its letter (P12 -> 12); names that run together
        (a group "T7.C1T7.F") are split and joined by a dash.  One identifier
        pattern and dictionary look-ups: the cost grows with the text only.

        >>> from construct.constructions import get
        >>> sc = build_scene(get("crank").figure(parts=9))
        >>> sc.readable("Kreis um P3 durch T1.C1"), sc.readable("T1.C1T1.F geteilt")
        ('Kreis um 3 durch C1', 'C1–F geteilt')
        """
        key = (text, lang, tuple(outputs))
        done = self._readable_cache.get(key)
        if done is None:  # group titles recur on every step of their group: rewritten once
            done = self._readable_cache[key] = self.reader.text(text, lang, outputs)
        return done

    @functools.cached_property
    def _readable_cache(self) -> dict[tuple, str]:
        return {}

    @functools.cached_property
    def _captions(self) -> list[tuple[str, str] | None]:
        return [None] * len(self.steps)

    def caption(self, k: int) -> tuple[str, str]:
        """Step k's caption (German, English) in the figure's letters, rewritten once per step."""
        cached = self._captions[k - 1]
        if cached is None:
            s = self.steps[k - 1]
            if self.params.get("captions") == "letters":  # written in the figure's letters when built
                cached = self._captions[k - 1] = (displayed(s.caption.de), displayed(s.caption.en))
            else:  # a protocol from an older file: read here
                cached = self._captions[k - 1] = (self.readable(s.caption.de, "de", s.outputs),
                                                  self.readable(s.caption.en, "en", s.outputs))
        return cached

    # -- what a teaching frame shows at strength ----------------------------------------
    def fade_end(self, step: int) -> int | None:
        """The last step of the group whose end fades *step*'s marks, or None if they stay at strength.

        A group the student has finished collapses to its result: once the
        group at depth two around a step is complete (one trisection, the rod
        arcs of one point), its helpers fade; the results, and the curves that
        locate them (the rod arc back onto the stroke), stay.
        """
        if self._keeps[step - 1]:
            return None
        end = self._ends[step - 1]
        return end if end <= len(self.steps) else None

    def faded(self, step: int, k: int) -> bool:
        """Is *step* faded in frame *k* (k = len(steps) + 1: the final figure, every group finished)?"""
        end = self.fade_end(step)
        return end is not None and step < k and end < k

    def areas_over(self, m: Mark) -> list[tuple]:
        """The areas drawn after area *m* whose boxes meet its box: sections over it (a flywheel's rim over its
        disc), which its hatching does not run into (the SVG plate and the TikZ picture alike)."""
        a = _box(m.geom)
        return [o.geom for o in self.marks if o.kind is MarkKind.AREA and o.step > m.step and _meets(a, _box(o.geom))]

    def group_ends(self) -> list[int]:
        """The last step of every run of steps in one group at depth two (a run of ungrouped steps is one
        too): where a stage of the animation, or a frame of a long construction, ends."""
        steps = self.steps
        return [s.index for i, s in enumerate(steps) if i + 1 == len(steps) or steps[i + 1].group[:2] != s.group[:2]]

    @functools.cached_property
    def _ends(self) -> list[int]:
        """For each step, the last step of its group at depth two (or its top-level group)."""
        ends = [0] * len(self.steps)
        i, n = 0, len(self.steps)
        while i < n:
            key = self.steps[i].group[:2]
            j = i
            while j + 1 < n and self.steps[j + 1].group[:2] == key:
                j += 1
            for t in range(i, j + 1):
                # ungrouped steps (the givens) never fade
                ends[t] = j + 1 if key else n + 1
            i = j + 1
        return ends

    @functools.cached_property
    def _locating(self) -> frozenset[str]:
        """What a finished group collapses to: lettered points and what the book plate shows
        (:func:`plate_names`: results, the curves that locate them, their points); without
        the plate, results, the curves a result step cuts (the rod arc back onto the stroke)
        and the points those curves are drawn from (the crosshead the arc is struck about)."""
        out = {m.name for m in self.marks if m.label} | set(self.essentials)
        if self.essentials:
            return frozenset(out)
        makers = {n: s for s in self.steps for n in s.outputs}
        for s in self.steps:
            if s.role == "result":
                out.update(s.outputs)
                for n in s.inputs:
                    out.add(n)
                    if n in makers and makers[n].op.startswith("circle"):
                        out.update(makers[n].inputs[:1])
        return frozenset(out)

    @functools.cached_property
    def _keeps(self) -> list[bool]:
        loc = self._locating
        return [s.role in ("result", "given") or not s.group or any(o in loc for o in s.outputs) for s in self.steps]

    def stage_box(self, k: int) -> tuple[float, float, float, float]:
        """The region of step k's top-level group (all its steps), with a margin.

        A teaching frame shows this region: the division of the crank circle is
        seen large, the far-reaching rod arcs in the whole figure.
        """
        if not 1 <= k <= len(self.steps):
            return self.bbox
        span = self._stage_spans[k - 1]
        box = self._stage_cache.get(span)
        if box is None:
            box = self._stage_cache[span] = self._box_of_steps(*span)
        # the instrument's inputs are in view even when they lie outside the stage (a far centre)
        pts = [self.marks_by_name[n].geom for n in self.inputs(k) if self.marks_by_name[n].kind is MarkKind.POINT]
        if pts and not all(box[0] <= x <= box[2] and box[1] <= y <= box[3] for x, y in pts):
            x0 = min([box[0]] + [p[0] for p in pts])
            y0 = min([box[1]] + [p[1] for p in pts])
            x1 = max([box[2]] + [p[0] for p in pts])
            y1 = max([box[3]] + [p[1] for p in pts])
            pad = 0.04 * max(x1 - x0, y1 - y0)
            b = self.bbox
            box = (max(b[0], x0 - pad), max(b[1], y0 - pad), min(b[2], x1 + pad), min(b[3], y1 + pad))
        return box

    @functools.cached_property
    def _stage_spans(self) -> list[tuple[int, int]]:
        """For each step, the first and last step of its top-level group's run."""
        spans: list[tuple[int, int]] = []
        i, n = 0, len(self.steps)
        while i < n:
            j, top = i, self.steps[i].group[:1]
            while j + 1 < n and self.steps[j + 1].group[:1] == top:
                j += 1
            spans.extend([(i + 1, j + 1)] * (j - i + 1))
            i = j + 1
        return spans

    @functools.cached_property
    def _stage_cache(self) -> dict[tuple[int, int], tuple[float, float, float, float]]:
        return {}

    @functools.cached_property
    def _mark_steps(self) -> list[int]:
        return [m.step for m in self.marks]  # marks are in step order

    def _box_of_steps(self, start: int, end: int) -> tuple[float, float, float, float]:
        # Lines are left out: they are drawn as far as points of the whole construction
        # (the stroke line reaches the far crossheads) but say nothing about the stage.
        lo = bisect.bisect_left(self._mark_steps, start)
        hi = bisect.bisect_right(self._mark_steps, end)
        point, segment = MarkKind.POINT, MarkKind.SEGMENT
        boxes = [m.geom * 2 if m.kind is point else mark_box(m) for m in self.marks[lo:hi] if m.kind is not segment]
        boxes = [b for b in boxes if b is not None]
        if not boxes:
            return self.bbox
        x0s, y0s, x1s, y1s = zip(*boxes)
        x0, x1, y0, y1 = min(x0s), max(x1s), min(y0s), max(y1s)
        pad = 0.06 * max(x1 - x0, y1 - y0, 1e-9)
        b = self.bbox
        return (max(b[0], x0 - pad), max(b[1], y0 - pad), min(b[2], x1 + pad), min(b[3], y1 + pad))

    def group_box(self, k: int, below: float = 1.0,
                  within: tuple[float, float, float, float] | None = None) -> tuple[float, float, float, float] | None:
        """The box of the widest group around step k smaller than *below* times the figure (None: none is).

        The whole group counts, later steps too, so that a magnified view stays put
        while the group is drawn.  *within* measures against another region than the whole figure.
        """
        if not 1 <= k <= len(self.steps):
            return None
        x0, y0, x1, y1 = within or self.bbox
        limit = below * max(x1 - x0, y1 - y0)
        path = self.steps[k - 1].group
        for depth in range(1, len(path) + 1):
            box = self.group_boxes.get(path[:depth])
            if box is not None and max(box[2] - box[0], box[3] - box[1]) < limit:
                return box
        return None

    @functools.cached_property
    def group_boxes(self) -> dict[tuple[str, ...], tuple[float, float, float, float]]:
        """The extent (x0, y0, x1, y1) of every group and its enclosing groups, by group path."""
        boxes: dict[tuple[str, ...], tuple[float, float, float, float]] = {}
        for m in self.marks:
            pts = extreme_points(m)
            for depth in range(1, len(m.group) + 1):
                key = m.group[:depth]
                for x, y in pts:
                    b = boxes.get(key)
                    boxes[key] = (x, y, x, y) if b is None else (min(b[0], x), min(b[1], y),
                                                                 max(b[2], x), max(b[3], y))
        return boxes

    @functools.cached_property
    def group_captions(self) -> dict[tuple[str, ...], str]:
        """The caption of every step's group path ("Kurbelkreis › Teilung"), German titles where given.

        Runs of steps share a group, so each path is written once.
        """
        titles = self.params.get("group_titles") or {}
        out: dict[tuple[str, ...], str] = {}
        read: dict[str, str] = {}  # a title heads thousands of paths (all 3601 rod arcs ›): read once
        for s in self.steps:
            if s.group not in out:
                parts = []
                for g in s.group:
                    got = read.get(g)
                    if got is None:
                        got = read[g] = self.readable(titles.get(g, g))
                    parts.append(got)
                out[s.group] = displayed(" › ".join(parts))
        return out


def thin(items: Sequence[int], most: int) -> list[int]:
    """*items* thinned evenly to at most *most* of them, the first and the last kept.

    >>> thin(list(range(1, 11)), 4), thin([3, 5], 4)
    ([1, 4, 7, 10], [3, 5])
    """
    if len(items) <= most:
        return list(items)
    return sorted({items[round(i * (len(items) - 1) / (most - 1))] for i in range(most)})


#: A name that is an id as it stands: letters and digits (``str.isalnum``'s, which are ``\w``'s less "_"), "-", "_".
_ID = re.compile(r"[\w-]*")


@functools.lru_cache(maxsize=65536)  # a live sweep names the same objects at hundreds of values
def _safe_id(text: str) -> str:
    if _ID.fullmatch(text):  # (most names: a figure of 3600 parts names 32,000 objects)
        return text
    return "".join(c if c.isalnum() or c in "-_" else "-" for c in text)


def label_offset_direction(p: tuple[float, float], origin: tuple[float, float] = (0.0, 0.0),
                           scale: float = 1.0) -> tuple[float, float]:
    """Where to put a point's letter: radially out from the crank centre, or below the stroke line."""
    dx, dy = p[0] - origin[0], p[1] - origin[1]
    if abs(dy) <= 1e-9 * scale:
        return (0.0, -1.0)
    n = math.hypot(dx, dy)
    return (dx / n, dy / n)


def _on_curve_points(steps: Iterable[Step], objects: Replay,
                     shown: set[str] | None = None) -> dict[str, list[Point]]:
    """For every line and circle, the points the construction marks on it (only *shown* ones, if given)."""
    points = {n for n, o in objects.items() if isinstance(o, Point)}
    return {c: [objects[p] for p in ps] for c, ps in on_curve_names(steps, points, shown).items()}


def on_curve_names(steps: Iterable[Step], points: set[str], shown: set[str] | None = None) -> dict[str, list[str]]:
    """For every line and circle, the names of the points (of *points*) the construction marks on it, in the
    order it marks them (only *shown* ones, if given).

    >>> from construct.constructions import get
    >>> fig = get("crank").figure(parts=6)
    >>> on_curve_names(fig.protocol.steps, {n for n in fig.replay if n in ("O", "D0", "D1")})["crank"]
    ['D0', 'D1']
    """
    on: dict[str, list[str]] = {}

    def add(curve: str, point: str) -> None:
        if shown is not None and point not in shown:
            return
        if point in points:
            on.setdefault(curve, []).append(point)

    for s in steps:
        if s.op == "line":
            for p in s.inputs:
                add(s.outputs[0], p)
        elif s.op == "given_line":
            add(s.outputs[0], s.inputs[0])
        elif s.op == "circle_through":
            add(s.outputs[0], s.inputs[1])
        elif s.op in ("intersect",):
            for c in s.inputs:
                for p in s.outputs:
                    add(c, p)
        # neusis_archimedes marks no point on a curve it extends: the marked ruler's points are its own
    return on


#: How far a line or arc reaches past the points it is drawn over, and the paper about the figure: this part of
#: the figure's span (of what a broken figure keeps, where it is broken).  render/sweepdraw.py draws by it too.
MARGIN = 0.035


def build_scene(figure: Any, *, title: tuple[str, str] | None = None, plate: bool = False,
                break_axis: bool = True, furniture: tuple = (), looks: "dict[str, str] | None" = None,
                panels: tuple = (), ending: bool = False, end_furniture: tuple = (),
                end_looks: "dict[str, str] | None" = None, _warn: bool = True, _margin: float | None = None) -> Scene:
    """The marks of a built or replayed figure (anything with ``.protocol`` and ``.replay``).

    With *plate* the scene is what a book plate shows (:func:`plate_names`):
    the results and the curves and points that locate them, each curve drawn
    only as far as the shown points on it, every construction step left out.
    A point lettered by the user that the plate leaves out is named in a
    :class:`~construct.kernel.errors.HiddenLabelWarning` (:func:`warn_hidden_labels`).
    *panels* (:class:`construct.render.plate.Panel`) lay a plate's sheet out (:func:`lay_out`);
    a sheet laid out so is not broken.

    With *ending* the scene carries its end state (:meth:`Scene.in_end`): what the plate shows, drawn as
    the plate draws it (*end_looks*: the plate's looks), with the plate's furniture *end_furniture*, on the
    scene's own sheet (its broken axis).  *_margin*: the most its lines reach past their points (the end state's
    plate on a broken sheet: a share of what the sheet keeps of it).
    """
    protocol: Protocol = figure.protocol
    objects: Replay = figure.replay
    shown = plate_names(protocol, objects) if plate else None
    if shown is not None and _warn:
        warn_hidden_labels(protocol, objects, shown)
    points = [o for n, o in objects.items() if isinstance(o, Point) and (shown is None or n in shown)]
    curves_pts = curve_points(objects, shown)
    xs = [p[0] for p in points] + [p[0] for p in curves_pts]
    ys = [p[1] for p in points] + [p[1] for p in curves_pts]
    if not xs:
        xs, ys = [0.0, 1.0], [0.0, 1.0]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)
    margin = MARGIN * span if _margin is None else min(MARGIN * span, _margin)
    on = _on_curve_points(protocol.steps, objects, shown)
    if shown is not None:
        # a plate draws each arc between all the shown points on it, found or not by the protocol
        tol = 1e-9 * max(span, 1.0)
        shown_pts = [(n, objects[n]) for n in sorted(shown) if isinstance(objects.get(n), Point)]
        for name in sorted(shown):
            obj = objects.get(name)
            # Lines only where the construction names its plate: otherwise every
            # crosshead far out on the stroke line would stretch it.
            if isinstance(obj, Circle) or (isinstance(obj, Line) and protocol.params.get("plate")):
                have = on.setdefault(name, [])
                have.extend(p for n, p in shown_pts if lies_on(obj, p, tol) and p not in have)
    in_fan = fanned_lines(protocol.steps)
    spans: dict[str, tuple] = {}  # a line's or circle's reach before the margin, by mark: redraw draws it again

    def draw(margin: float) -> tuple[list[Mark], dict[str, tuple[str, bool]]]:
        """The marks, each line and arc reaching *margin* past the points marked on it."""
        marks: list[Mark] = []
        lettered: dict[str, tuple[str, bool]] = {}  # lettered straight lines: their letter, whether in a fan
        for s in protocol.steps:
            labels = dict(s.labels)
            for name in s.outputs:
                obj = objects.get(name)
                if obj is None or isinstance(obj, Length) or (shown is not None and name not in shown):
                    continue
                mid = f"s{s.index:04d}-{_safe_id(name)}"
                label = labels.get(name)
                if label and "{∠" in label:
                    label = reading(label, objects)
                if label:
                    label = primed(label)  # drawn as the books print it (6′); the protocol keeps its 6'
                if "unlettered" in (looks or {}).get(name, "").split():
                    label = None  # the plate letters it otherwise (an abscissa, as the book does)
                look = (looks or {}).get(name, "")
                if isinstance(obj, Point):  # (the marks made by position: a long figure makes tens of thousands)
                    marks.append(Mark(mid, s.index, name, MarkKind.POINT, (obj[0], obj[1]), s.role, s.tool,
                                      s.provenance.kind, label, s.group, look))
                    continue
                if isinstance(obj, Line):
                    span = spans.get(mid)
                    if span is None:
                        span = spans[mid] = segment_span(obj, on.get(name, []))
                    marks.append(Mark(mid, s.index, name, MarkKind.SEGMENT, segment_at(span, margin), s.role, s.tool,
                                      s.provenance.kind, label, s.group, look))
                    continue
                if isinstance(obj, Circle):
                    span = spans.get(mid)
                    if span is None:
                        span = spans[mid] = marked_arc(obj, on.get(name, []), s.role, plate=shown is not None)
                    kind, geom = arc_at(span, margin)
                    marks.append(Mark(mid, s.index, name, kind, geom, s.role, s.tool, s.provenance.kind, label,
                                      s.group, look))
                    continue
                common = dict(step=s.index, name=name, role=s.role, tool=s.tool, provenance=s.provenance.kind,
                              group=s.group, label=label, look=look)
                if hasattr(obj, "rings"):  # an Area: one mark per piece, each hatched
                    # a look "signed": the pieces under the lower line hatched across those over it (+ and −)
                    signed = "signed" in common["look"].split()
                    # (its vertices as pairs of floats: an area of coordinates makes no Point for each)
                    rings = obj.coordinate_pieces() if hasattr(obj, "coordinate_pieces") else \
                        tuple((sign, tuple([(p[0], p[1]) for p in ring])) for sign, ring in obj.pieces)
                    for j, (sign, ring) in enumerate(rings):
                        hatch = obj.hatch_deg
                        if signed and sign < 0:
                            hatch = (90.0 if hatch is None else hatch) - 45.0
                        marks.append(Mark(mid if j == 0 else f"{mid}-{j}", kind=MarkKind.AREA,
                                          geom=ring, hatch=hatch, **common))
                elif hasattr(obj, "curve_points"):
                    # a polyline is drawn as it is measured (y_at, length): straight from point to point
                    straight = getattr(obj, "kind", "") == "polyline"
                    pts = tuple([(p.x, p.y) for p in obj.curve_points()])  # (Points: read as fields)
                    if straight and label:
                        # lettered at a point of its own on it, placed once the sheet is laid out (below)
                        marks.append(Mark(mid, kind=MarkKind.CURVE, geom=pts, straight=True, **{**common, "label": None}))
                        lettered[mid] = (label, in_fan[name])
                    else:
                        marks.append(Mark(mid, kind=MarkKind.CURVE, geom=pts, straight=straight, **common))
        return marks, lettered

    def redraw(marks: list[Mark], margin: float) -> list[Mark]:
        """*marks* (drawn by :func:`draw`) drawn at another *margin*: what ``draw(margin)`` gives (its letters are
        the same), the lines and arcs over their marked points reaching *margin* past them, the rest as they are."""
        out = []
        for m in marks:
            span = spans.get(m.id)
            if span is None:
                out.append(m)
                continue
            kind, geom = (MarkKind.SEGMENT, segment_at(span, margin)) if m.kind is MarkKind.SEGMENT \
                else arc_at(span, margin)
            out.append(Mark(m.id, m.step, m.name, kind, geom, m.role, m.tool, m.provenance, m.label, m.group, m.look,
                            m.hatch, m.straight))
        return out

    marks, lettered = draw(margin)
    breaks: tuple[Break, ...] = ()
    if panels:
        marks = lay_out(marks, panels, margin, 1e-9 * max(span, 1.0))
        xs = [m.geom[0] for m in marks if m.kind is MarkKind.POINT] or xs
        ys = [m.geom[1] for m in marks if m.kind is MarkKind.POINT] or ys
    elif break_axis and (shown is None or furniture):
        # a plate keeps more of the broken stretch: the rod drawn across it stays a shallow line
        cut = None
        if shown is None and breaks_figure(marks, tuple(furniture), True):
            # a broken figure is drawn at the size it keeps: its lines reach past their points by a margin of
            # what is left of it (its points and curves, broken alone), not of the length broken out (at
            # L/r = 50 that would be 1.8 r)
            kept = MARGIN * kept_span(marks)
            if kept < margin:
                again = redraw(marks, kept)
                smaller = broken(again, tuple(furniture), True)
                if smaller[2]:
                    margin, cut = kept, smaller
        if cut is None:  # (broken at the first margin only when it is kept: a long figure's every mark moved)
            cut = broken(marks, tuple(furniture), shown is None)
        marks, furniture, breaks = cut
        if breaks:
            xs = [x for m in marks if m.kind is MarkKind.POINT for x in (m.geom[0],)] or xs
            ys = [y for m in marks if m.kind is MarkKind.POINT for y in (m.geom[1],)] or ys
    if lettered:
        marks = letter_lines(marks, lettered, breaks)
    # Grow the box by what the curves reach (full circles, arcs, line ends), the plate's furniture and the margin.
    bx0, by0, bx1, by1 = min(xs), min(ys), max(xs), max(ys)
    if furniture:
        from .plate import extent

        fx = extent(furniture)
        if fx:
            bx0, by0, bx1, by1 = min(bx0, fx[0]), min(by0, fx[1]), max(bx1, fx[2]), max(by1, fx[3])
    boxes = [m.geom * 2 if m.kind is MarkKind.POINT else mark_box(m) for m in marks]  # (a point's box: (x, y, x, y))
    boxes = [b for b in boxes if b is not None]
    if boxes:
        x0s, y0s, x1s, y1s = zip(*boxes)
        bx0, by0, bx1, by1 = min(bx0, min(x0s)), min(by0, min(y0s)), max(bx1, max(x1s)), max(by1, max(y1s))
    pad = margin
    bbox = (bx0 - pad, by0 - pad, bx1 + pad, by1 + pad)
    if title is None:
        title = (protocol.construction, protocol.construction)
    # a figure shows a bounded title; the protocol keeps the name
    title = (displayed(title[0], TITLE_LIMIT), displayed(title[1], TITLE_LIMIT))
    essentials = frozenset(shown if shown is not None else plate_names(protocol, objects))
    end: dict[str, Any] = {}
    if ending and shown is None:
        plate_scene = build_scene(figure, plate=True, break_axis=False, looks=end_looks, _warn=False)
        if breaks:
            # on a broken sheet the plate's lines reach past their points by a share of what the plate spans
            # there (its points and curves moved as the sheet moves them; a lettered line's letter point is
            # placed on the sheet), not of the length broken out (at L/r = 50 the crank's ordinates reached 1.8 r
            # past the circle)
            sx, sy = break_shift(breaks), break_shift(breaks, axis=1)
            kept = [(sx(p[0]), sy(p[1])) for m in plate_scene.marks
                    for p in ((m.geom,) if m.kind is MarkKind.POINT and not m.id.endswith("-at") else
                              m.geom if m.kind in (MarkKind.CURVE, MarkKind.AREA) else ())]
            if kept:
                plate_scene = build_scene(figure, plate=True, break_axis=False, looks=end_looks, _warn=False,
                                          _margin=MARGIN * max(max(p[0] for p in kept) - min(p[0] for p in kept),
                                                               max(p[1] for p in kept) - min(p[1] for p in kept), 1e-9))
        end = end_state(plate_scene.marks, plate_scene.bbox, marks, breaks, end_furniture)
    return Scene(tuple(marks), bbox, protocol.steps, title, dict(protocol.params), breaks, tuple(furniture),
                 essentials, **end)


#: A label that is a reading of the figure: ``{∠A O B}`` is written as the angle AOB measured on the replayed
#: figure, in degrees and minutes as the books print it (61°19′), so that a replay with other givens letters
#: its own angles.
READING = re.compile(r"\{∠(\S+) (\S+) (\S+)\}")


def reading(label: str, objects: Any) -> str:
    """*label* with every reading ``{∠A O B}`` replaced by the angle AOB measured on *objects*.

    >>> from construct.kernel.geometry import Point
    >>> reading("ω = {∠A O B}", {"A": Point(1.0, 0.0), "O": Point(0.0, 0.0), "B": Point(0.5, 3 ** 0.5 / 2)})
    'ω = 60°00′'
    >>> reading("{∠A O X}", {"A": Point(1.0, 0.0), "O": Point(0.0, 0.0)})
    Traceback (most recent call last):
    construct.kernel.errors.InvalidParameter: the label '{∠A O X}' reads an angle at the points A, O, X; 'X' is no point of the figure
    """
    from ..kernel.errors import InvalidParameter
    from .plate import dms

    def angle(m: re.Match) -> str:
        missing = [n for n in m.groups() if not isinstance(objects.get(n), Point)]
        if missing:
            raise InvalidParameter(f"the label {label!r} reads an angle at the points {', '.join(m.groups())}; "
                                   f"{missing[0]!r} is no point of the figure")
        a, o, b = (objects[n] for n in m.groups())
        ua = math.atan2(a[1] - o[1], a[0] - o[0])
        ub = math.atan2(b[1] - o[1], b[0] - o[0])
        w = abs((ub - ua + math.pi) % TWO_PI - math.pi)
        return dms(w)

    return READING.sub(angle, label)


def _box(pts: Sequence[tuple[float, float]]) -> tuple[float, float, float, float]:
    return (min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts), max(p[1] for p in pts))


def _meets(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]
