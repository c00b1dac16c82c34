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
import collections
import dataclasses
import functools
import math
import os
import re
import sys
import warnings
from dataclasses import dataclass
from enum import Enum
from typing import Any, Callable, Iterable, NamedTuple, Sequence

from ..kernel.errors import HiddenLabelWarning
from ..kernel.geometry import Circle, Length, Line, Point
from ..kernel.protocol import Protocol, Replay, Step
from .captions import TITLE_LIMIT, Reader, displayed

__all__ = ["Mark", "MarkKind", "Scene", "build_scene", "label_offset_direction", "on_curve_names", "extreme_points", "middle",
           "fanned_lines", "letter_point", "thin"]

TWO_PI = 2.0 * math.pi
#: What a letter of the figure looks like (:meth:`Scene.tag_shown`): a letter, a number below 20 or
#: two digits with a prime, subscripts, primes.
FIGURE_LETTER = re.compile(r"[A-Za-zΑ-Ωα-ω](?:[01]?[0-9])?[′″'₀-₉]*|[0-9]{1,2}[′″']?")


class MarkKind(str, Enum):
    """What a mark draws, which decides what its ``geom`` holds (:class:`Mark`).

    A ``str`` whose value is the word the drawings have always used (in CSS
    classes, JSON and captions), so that a kind compares, hashes, formats and
    serialises as that word: ``MarkKind.ARC == "arc"``, ``f"{kind}"`` is
    ``"arc"``, and a table keyed by kinds answers for the plain word too.

    >>> MarkKind("arc") is MarkKind.ARC, f"{MarkKind.ARC}", MarkKind.ARC == "arc"
    (True, 'arc', True)
    >>> [k.value for k in MarkKind if k.round], [k.value for k in MarkKind if k.stroked]
    (['circle', 'arc'], ['segment', 'circle', 'arc', 'curve'])
    """

    POINT = "point"
    SEGMENT = "segment"
    CIRCLE = "circle"
    ARC = "arc"
    CURVE = "curve"
    AREA = "area"

    # the word, not "MarkKind.ARC": on Python 3.11+ a str mix-in Enum would otherwise format by its name
    def __str__(self) -> str:
        return self.value

    def __format__(self, spec: str) -> str:
        return format(self.value, spec)

    @property
    def round(self) -> bool:
        """A circle or an arc of one: ``geom`` begins (cx, cy, r)."""
        return self is MarkKind.CIRCLE or self is MarkKind.ARC

    @property
    def stroked(self) -> bool:
        """Drawn as one line by the pen (segment, circle, arc, curve): not a dot, not a filled area."""
        return self is not MarkKind.POINT and self is not MarkKind.AREA


@dataclass(frozen=True, slots=True)
class Mark:
    """One drawable element of the figure.

    ``geom`` by kind: point (x, y); segment (x1, y1, x2, y2); circle (cx, cy, r);
    arc (cx, cy, r, start, sweep) with angles in radians, counter-clockwise in
    the y-up drawing plane; curve ((x, y), ...) drawn smooth through its points,
    or joined by straight segments when ``straight`` (a polyline: the straightedge);
    area ((x, y), ...) the ring of one hatched piece.  *kind* may be given as its
    word (``"circle"``); it is kept as a :class:`MarkKind`.
    """

    id: str
    step: int
    name: str
    kind: MarkKind
    geom: tuple
    role: str
    tool: str
    provenance: str
    label: str | None = None
    group: tuple[str, ...] = ()
    #: A line weight or pattern from the plate's description (heavy, thin, dashdot, dashed), "" = by role.
    look: str = ""
    #: Areas: the direction of their hatching in degrees (None: the style's).
    hatch: float | None = None
    #: Curves: the points are joined by straight segments (a polyline), not by a smooth curve.
    straight: bool = False

    def __post_init__(self) -> None:
        if type(self.kind) is not MarkKind:  # the word, as a caller may write it: kept as the kind
            object.__setattr__(self, "kind", MarkKind(self.kind))


@dataclass(frozen=True)
class Scene:
    """All marks of a figure in step order, with its bounding box (y up)."""

    marks: tuple[Mark, ...]
    bbox: tuple[float, float, float, float]  # xmin, ymin, xmax, ymax
    steps: tuple[Step, ...]
    title: tuple[str, str]
    params: dict
    #: Broken axes (:class:`Break`: where the break starts, its drawn width, the length it leaves out, which
    #: axis), drawing units.
    breaks: tuple[Break, ...] = ()
    #: Plate furniture (:mod:`construct.render.plate`): dimensions, angle arcs, scale bars, signs.
    furniture: tuple = ()
    #: What the book plate shows (:func:`plate_names`): what a finished group collapses to.
    essentials: frozenset = frozenset()

    def upto(self, k: int) -> list[Mark]:
        """The marks made by steps 1..k."""
        return [m for m in self.marks if m.step <= k]

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
            done = self._readable_cache[key] = self._reader.text(text, lang, outputs)
        return done

    @functools.cached_property
    def _readable_cache(self) -> dict[tuple, str]:
        return {}

    @functools.cached_property
    def _reader(self) -> Reader:
        # the reader names lines and circles (an arc is part of its circle)
        kinds = {MarkKind.SEGMENT: "line", MarkKind.ARC: "circle"}
        makers = {n: s for s in self.steps for n in s.outputs}
        objects = {}
        lettered_at = {}
        for m in self.marks:
            s = makers.get(m.name)
            if s is None:  # the point a straight line is lettered at (build_scene): the line goes by that letter
                lettered_at[m.name[:-len(".at")]] = m.label
                continue
            objects[m.name] = (kinds.get(m.kind, m.kind.value), m.label, s.op, tuple(s.inputs))
        for name, text in lettered_at.items():
            kind, _, op, inputs = objects[name]
            objects[name] = (kind, text, op, inputs)
        for name, s in makers.items():  # what is not drawn (a compass opening J.h1) goes by its short name
            objects.setdefault(name, ("length", None, s.op, tuple(s.inputs)))
        return Reader(objects)

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

    def step_of(self, name: str) -> int | None:
        m = self._drawn.get(name)
        return m.step if m is not None else None

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

    def inputs(self, k: int) -> frozenset[str]:
        """The objects step k's instrument is set on (centre, through point, the curves it cuts)."""
        if not 1 <= k <= len(self.steps):
            return frozenset()
        return frozenset(n for n in self.steps[k - 1].inputs if n in self._drawn)

    def struck_onto(self, k: int) -> frozenset[str]:
        """The lines and curves step k's arc is struck onto: those the step that next takes up what step k
        makes cuts it with (the scale line an arc is carried to is cut by the following step, which takes
        the crossing).  Without them the student would see an arc struck onto nothing.

        >>> from construct.constructions import get
        >>> sc = build_scene(get("tangential-pressure").figure())
        >>> sorted(sc.struck_onto(821))  # 'r cos ω = O–Yb7 carried to the scale line r'
        ['gr']
        """
        if not 1 <= k <= len(self.steps):
            return frozenset()
        made = {n for n in self.steps[k - 1].outputs
                if n in self._drawn and self._drawn[n].kind is not MarkKind.POINT}
        if not made:
            return frozenset()
        for s in self._takers.get(k, ()):
            step = self.steps[s - 1]
            if made & set(step.inputs) and all(n not in self._drawn or self._drawn[n].kind is MarkKind.POINT
                                               for n in step.outputs):
                return frozenset(n for n in step.inputs if n not in made and n in self._drawn
                                 and self._drawn[n].kind is not MarkKind.POINT and self._drawn[n].step < k)
            return frozenset()  # the next step that takes it up draws with it: what it is struck onto is its own
        return frozenset()

    @functools.cached_property
    def _takers(self) -> dict[int, list[int]]:
        """Per step, the later steps that take up what it makes (in step order)."""
        maker: dict[str, int] = {}
        for s in self.steps:
            for n in s.outputs:
                maker.setdefault(n, s.index)
        got: dict[int, list[int]] = {}
        for s in self.steps:
            for k in sorted({maker[n] for n in s.inputs if n in maker and maker[n] < s.index}):
                got.setdefault(k, []).append(s.index)
        return got

    def tagged(self, k: int) -> frozenset[str]:
        """The points a teaching frame tags at step k: what the step makes, what its instrument is set on
        (also the centre of a circle it cuts), and every point its caption names."""
        if not 1 <= k <= len(self.steps):
            return frozenset()
        s = self.steps[k - 1]
        names = set(s.outputs) | set(s.inputs) | self._reader.mentioned(s.caption.de) | self._reader.mentioned(s.caption.en)
        for n in s.inputs:
            if n in self._reader.objects and n not in self._reader.points:
                names.update(self._reader.curve_points(n))
        return frozenset(n for n in names if n in self._reader.points)

    @functools.cached_property
    def _drawn(self) -> dict[str, Mark]:
        return {m.name: m for m in self.marks}

    def display_name(self, name: str) -> str:
        """The letter or tag the reader sees for an object (the same one the captions use)."""
        return self._reader.point(name) if name in self._reader.points else name.rsplit(".", 1)[-1]

    def tag_shown(self, name: str) -> bool:
        """Whether an unlettered point's tag (:meth:`display_name`) reads as one of the figure's letters.

        A figure is lettered with one letter, perhaps with a number of at most two
        digits or a prime (M2, S1, q10, K17, 5′); the helpers' internal names
        (``c90``: the crank at 90°, ``Nb17``, ``iP6``) are not letters and are not
        shown, whatever the caption calls them.

        >>> from construct.constructions import get
        >>> sc = build_scene(get("crank").figure(parts=6))
        >>> [FIGURE_LETTER.fullmatch(t) is not None for t in ("M2", "q10", "5′", "c90", "Nb17", "iP6")]
        [True, True, True, False, False, False]
        """
        return FIGURE_LETTER.fullmatch(self.display_name(name)) is not None

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
        pts = [self._drawn[n].geom for n in self.inputs(k) if self._drawn[n].kind is MarkKind.POINT]
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
        pts = [p for m in self.marks[lo:hi] if m.kind is not MarkKind.SEGMENT for p in extreme_points(m)]
        if not pts:
            return self.bbox
        x0, x1 = min(p[0] for p in pts), max(p[0] for p in pts)
        y0, y1 = min(p[1] for p in pts), max(p[1] for p in pts)
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
        for s in self.steps:
            if s.group not in out:
                out[s.group] = displayed(" › ".join(self.readable(titles.get(g, g)) for g in s.group))
        return out


def thin(items: Sequence[int], most: int) -> list[int]:
    """*items* thinned evenly to at most *most* of them, the first and the last kept.

    >>> thin(list(range(1, 11)), 4), thin([3, 5], 4)
    ([1, 4, 7, 10], [3, 5])
    """
    if len(items) <= most:
        return list(items)
    return sorted({items[round(i * (len(items) - 1) / (most - 1))] for i in range(most)})


@functools.lru_cache(maxsize=65536)  # a live sweep names the same objects at hundreds of values
def _safe_id(text: str) -> str:
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


def build_scene(figure: Any, *, title: tuple[str, str] | None = None, plate: bool = False,
                break_axis: bool = True, furniture: tuple = (), looks: "dict[str, str] | None" = None,
                panels: tuple = ()) -> Scene:
    """The marks of a built or replayed figure (anything with ``.protocol`` and ``.replay``).

    With *plate* the scene is what a book plate shows (:func:`plate_names`):
    the results and the curves and points that locate them, each curve drawn
    only as far as the shown points on it, every construction step left out.
    A point lettered by the user that the plate leaves out is named in a
    :class:`~construct.kernel.errors.HiddenLabelWarning` (:func:`warn_hidden_labels`).
    *panels* (:class:`construct.render.plate.Panel`) lay a plate's sheet out (:func:`lay_out`);
    a sheet laid out so is not broken.
    """
    protocol: Protocol = figure.protocol
    objects: Replay = figure.replay
    shown = plate_names(protocol, objects) if plate else None
    if shown is not None:
        warn_hidden_labels(protocol, objects, shown)
    points = [o for n, o in objects.items() if isinstance(o, Point) and (shown is None or n in shown)]
    curves_pts = _curve_points(objects, shown)
    xs = [p[0] for p in points] + [p[0] for p in curves_pts]
    ys = [p[1] for p in points] + [p[1] for p in curves_pts]
    if not xs:
        xs, ys = [0.0, 1.0], [0.0, 1.0]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)
    margin = 0.035 * span
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
                have.extend(p for n, p in shown_pts if _on(obj, p, tol) and p not in have)
    in_fan = fanned_lines(protocol.steps)

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
                if "unlettered" in (looks or {}).get(name, "").split():
                    label = None  # the plate letters it otherwise (an abscissa, as the book does)
                common = dict(step=s.index, name=name, role=s.role, tool=s.tool, provenance=s.provenance.kind,
                              group=s.group, label=label, look=(looks or {}).get(name, ""))
                if isinstance(obj, Point):
                    marks.append(Mark(mid, kind=MarkKind.POINT, geom=(obj[0], obj[1]), **common))
                elif isinstance(obj, Line):
                    marks.append(Mark(mid, kind=MarkKind.SEGMENT, geom=_segment_extent(obj, on.get(name, []), margin), **common))
                elif isinstance(obj, Circle):
                    kind, geom = _circle_extent(obj, on.get(name, []), margin, s.role, plate=shown is not None)
                    marks.append(Mark(mid, kind=kind, geom=geom, **common))
                elif hasattr(obj, "rings"):  # an Area: one mark per piece, each hatched
                    for j, ring in enumerate(obj.rings()):
                        marks.append(Mark(mid if j == 0 else f"{mid}-{j}", kind=MarkKind.AREA,
                                          geom=tuple((p[0], p[1]) for p in ring), hatch=obj.hatch_deg, **common))
                elif hasattr(obj, "curve_points"):
                    # a polyline is drawn as it is measured (y_at, length): straight from point to point
                    straight = getattr(obj, "kind", "") == "polyline"
                    pts = tuple((p[0], p[1]) for p in obj.curve_points())
                    if straight and label:
                        # lettered at a point of its own on it, placed once the sheet is laid out (below)
                        marks.append(Mark(mid, kind=MarkKind.CURVE, geom=pts, straight=True, **{**common, "label": None}))
                        lettered[mid] = (label, in_fan[name])
                    else:
                        marks.append(Mark(mid, kind=MarkKind.CURVE, geom=pts, straight=straight, **common))
        return marks, lettered

    marks, lettered = draw(margin)
    breaks: tuple[Break, ...] = ()
    if panels:
        marks = lay_out(marks, panels, margin, 1e-9 * max(span, 1.0))
        xs = [m.geom[0] for m in marks if m.kind is MarkKind.POINT] or xs
        ys = [m.geom[1] for m in marks if m.kind is MarkKind.POINT] or ys
    elif break_axis and (shown is None or furniture):
        # a plate keeps more of the broken stretch: the rod drawn across it stays a shallow line
        broken = _broken(marks, tuple(furniture), shown is None)
        if shown is None and broken[2]:
            # a broken figure is drawn at the size it keeps: its lines reach past their points by a margin of
            # what is left of it (its points and curves, broken alone), not of the length broken out (at
            # L/r = 50 that would be 1.8 r)
            kept = 0.035 * _kept_span(marks)
            if kept < margin:
                again, letters = draw(kept)
                smaller = _broken(again, tuple(furniture), True)
                if smaller[2]:
                    margin, lettered, broken = kept, letters, smaller
        marks, furniture, breaks = broken
        if breaks:
            xs = [x for m in marks if m.kind is MarkKind.POINT for x in (m.geom[0],)] or xs
            ys = [y for m in marks if m.kind is MarkKind.POINT for y in (m.geom[1],)] or ys
    if lettered:
        marks = _letter_lines(marks, lettered, breaks)
    # Grow the box by what the curves reach (full circles, arcs, line ends), the plate's furniture and the margin.
    bx0, by0, bx1, by1 = min(xs), min(ys), max(xs), max(ys)
    if furniture:
        from .plate import extent

        fx = extent(furniture)
        if fx:
            bx0, by0, bx1, by1 = min(bx0, fx[0]), min(by0, fx[1]), max(bx1, fx[2]), max(by1, fx[3])
    for m in marks:
        for x, y in extreme_points(m):
            bx0, by0, bx1, by1 = min(bx0, x), min(by0, y), max(bx1, x), max(by1, y)
    pad = margin
    bbox = (bx0 - pad, by0 - pad, bx1 + pad, by1 + pad)
    if title is None:
        title = (protocol.construction, protocol.construction)
    # a figure shows a bounded title; the protocol keeps the name
    title = (displayed(title[0], TITLE_LIMIT), displayed(title[1], TITLE_LIMIT))
    essentials = frozenset(shown if shown is not None else plate_names(protocol, objects))
    return Scene(tuple(marks), bbox, protocol.steps, title, dict(protocol.params), breaks, tuple(furniture),
                 essentials)


#: A gap wider than this fraction of the figure, with nothing drawn in it, is broken out of the axis.
BREAK_FRACTION = 0.2
#: The same across the figure (a far point below it: the proportional angle's vertex S a rod's length under the
#: crank, Fig. 27): a tall figure is broken only where the gap is wider than this, so that the books' own
#: figures (at their rod ratios, S up to 6 r below) are drawn whole, as the books draw them.
BREAK_FRACTION_Y = 0.3
#: Width the broken-out stretch keeps, as a fraction of what remains of the figure.
BREAK_KEEP = 0.07
#: The same on a plate, where the rod is drawn across the break to its crosshead.
PLATE_BREAK_KEEP = 0.55


class Break(NamedTuple):
    """A stretch broken out of the figure: where the drawn break starts (x, or y for ``axis`` 1; drawing units),
    its drawn width, and the length it leaves out."""

    start: float
    width: float
    left_out: float
    axis: int = 0


def _broken(marks: list[Mark], furniture: tuple, whole: bool) -> tuple[list[Mark], tuple, tuple[Break, ...]]:
    """The figure broken along x (:func:`_break`) and, unless a plate (*whole* false: a plate keeps its sheet,
    the books draw S whole), across it."""
    marks, furniture, breaks = _break(marks, furniture, BREAK_KEEP if whole else PLATE_BREAK_KEEP)
    if whole and not furniture:
        marks, _, across = _break(marks, (), BREAK_KEEP, axis=1, fraction=BREAK_FRACTION_Y)
        breaks += across
    return marks, furniture, breaks


def _kept_span(marks: list[Mark]) -> float:
    """What the figure's points and curves span once broken alone (:func:`_broken`; as they are, unbroken)."""
    drawn = [m for m in marks if m.kind in (MarkKind.POINT, MarkKind.CURVE, MarkKind.AREA)]
    return _span(_broken(drawn, (), True)[0])


def _span(marks: list[Mark]) -> float:
    """The larger side of the box of the marks' points and curves (what the margin is a share of)."""
    pts = [m.geom for m in marks if m.kind is MarkKind.POINT]
    pts += [p for m in marks if m.kind in (MarkKind.CURVE, MarkKind.AREA) for p in m.geom]
    if not pts:
        return 1e-9
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)


def _break(marks: list[Mark], furniture: tuple = (), keep_fraction: float = 0.07, axis: int = 0,
           fraction: float = BREAK_FRACTION) -> tuple[list[Mark], tuple, tuple[Break, ...]]:
    """Break the widest empty stretch out of the figure, as a draftsman breaks a long axis.

    The crossheads lie a rod length (5 r) to the left of the crank circle;
    drawn to scale, the circle sits in a corner of an empty sheet.  Marks
    wholly left of the empty stretch move right by what it loses; lines
    that cross it (the stroke line) keep their right end and move their
    left one.  A plate's furniture (the rod drawn to its crosshead) is
    broken the same way.  *axis* 1 breaks across the figure instead: marks
    wholly below the stretch move up (a vertex a rod's length below the
    crank).  Returns the marks, the furniture and (:class:`Break`,) or ()
    when there is no gap wider than *fraction* of the figure.
    """
    from .plate import anchors, shifted
    ivals = []
    far: dict[int, float] = {}  # a circle's or arc's far end, by its place in *marks* (asked again below)
    for i, m in enumerate(marks):
        if m.kind is MarkKind.SEGMENT or (m.kind is MarkKind.CURVE and m.straight and len(m.geom) == 2):
            continue  # the stroke line spans everything; a rod drawn to its crosshead crosses the break
        cs = [p[axis] for p in extreme_points(m)]
        if cs:
            ivals.append((min(cs), max(cs)))
            if m.kind.round:
                far[i] = ivals[-1][1]
    ivals.extend((p[axis], p[axis]) for p in anchors(furniture))
    if len(ivals) < 2:
        return marks, furniture, ()
    ivals.sort()
    total = ivals[-1][1] - ivals[0][0]
    best, reach = None, ivals[0][1]
    for a, b in ivals[1:]:
        if a > reach and (best is None or a - reach > best[1] - best[0]):
            best = (reach, a)
        reach = max(reach, b)
    if best is None or best[1] - best[0] <= fraction * total:
        return marks, furniture, ()
    lo, hi = best
    keep = min(keep_fraction * (total - (hi - lo)), 0.8 * (hi - lo))
    shift = (hi - lo) - keep

    def sx(x: float) -> float:
        return x + shift if x <= lo else x

    def end(x: float) -> float:  # a line's end, drawn a margin past its last point: with the side it is nearer
        return x + shift if x <= (lo + hi) / 2 else x

    out = []
    for i, m in enumerate(marks):
        g = m.geom
        if m.kind is MarkKind.POINT:
            g = (sx(g[0]), g[1]) if axis == 0 else (g[0], sx(g[1]))
        elif m.kind is MarkKind.SEGMENT:
            g = (end(g[0]), g[1], end(g[2]), g[3]) if axis == 0 else (g[0], end(g[1]), g[2], end(g[3]))
        elif m.kind.round:  # moved whole, or not at all: a circle is not stretched
            if far[i] <= lo:
                g = (g[0] + shift,) + tuple(g[1:]) if axis == 0 else (g[0], g[1] + shift) + tuple(g[2:])
        else:  # a curve or an area: point by point
            g = tuple((sx(x), y) for x, y in g) if axis == 0 else tuple((x, sx(y)) for x, y in g)
        out.append(m if g is m.geom else _with_geom(m, g))
    # the near stretch now ends at hi - keep: the kept piece of the broken axis is [hi - keep, hi]
    moved = tuple(shifted(it, sx) for it in furniture) if axis == 0 else furniture
    return out, moved, (Break(hi - keep, keep, hi - lo, axis),)


def _with_geom(m: Mark, geom: tuple) -> Mark:
    """*m* with another geometry (dataclasses.replace asks every field by name: a live sweep moves a thousand
    marks at hundreds of rod ratios)."""
    return Mark(m.id, m.step, m.name, m.kind, geom, m.role, m.tool, m.provenance, m.label, m.group, m.look, m.hatch,
                m.straight)


# _with_geom names every field of a Mark: a field added without it would be lost on the broken axis
assert [f.name for f in dataclasses.fields(Mark)] == ["id", "step", "name", "kind", "geom", "role", "tool",
                                                      "provenance", "label", "group", "look", "hatch", "straight"]


def warn_hidden_labels(protocol: Protocol, objects: Replay, shown: set[str]) -> list[tuple[str, str]]:
    """Warn once for the figure (:class:`~construct.kernel.errors.HiddenLabelWarning`) when its plate leaves out
    lettered points; return them as (name, letter).

    Only a plate the library chooses is asked (:func:`plate_names` without the protocol's ``plate`` list):
    there a letter the user set on a point that locates no result would vanish without a word.  A
    construction that names its plate's objects (every book construction) leaves its other letters out on
    purpose, as its book does.

    >>> from construct import Builder
    >>> b = Builder("demo", givens={})
    >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 4.0, 0.0)
    >>> _ = b.midpoint("M", "A", "B"); b.set_label("M", "M"); _ = b.line("g", "A", "B", role="result")
    >>> fig = b.figure()
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     warn_hidden_labels(fig.protocol, fig.replay, plate_names(fig.protocol, fig.replay))
    [('M', 'M')]
    >>> print(caught[0].message)
    the plate (historical style) leaves out point M lettered 'M': it shows the results and what locates them; give M role="result", or name what the plate shows in params["plate"], to letter it there
    """
    if protocol.params.get("plate"):
        return []
    hidden = [(name, text) for s in protocol.steps for name, text in s.labels
              if name not in shown and isinstance(objects.get(name), Point)]
    if hidden:
        names = ", ".join(f"{n} lettered {t!r}" for n, t in hidden[:8]) + (", ..." if len(hidden) > 8 else "")
        which = "point" if len(hidden) == 1 else f"{len(hidden)} points:"
        them = hidden[0][0] if len(hidden) == 1 else "them"
        warnings.warn(HiddenLabelWarning(
            f"the plate (historical style) leaves out {which} {names}: it shows the results and what locates "
            f'them; give {them} role="result", or name what the plate shows in params["plate"], to letter '
            f"{'it' if len(hidden) == 1 else 'them'} there"), stacklevel=_caller_level())
    return hidden


#: This package's folder: a warning points at the first line outside it (the user's ``fig.svg(...)``).
_PACKAGE = os.path.dirname(os.path.dirname(os.path.abspath(__file__))) + os.sep


def _caller_level() -> int:
    """The ``stacklevel`` (for a warning raised by this function's caller) of the first frame outside the package.

    The drawing is reached by several paths (``Figure.svg``, ``construct.svg``, ``write_replay``), each
    a different depth below the user's line; the warning should name that line, not ours.
    """
    frame, level = sys._getframe(2), 2  # 1 is the function that warns
    while frame is not None and frame.f_code.co_filename.startswith(_PACKAGE):
        frame, level = frame.f_back, level + 1
    return level


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


def _letter_lines(marks: list[Mark], lettered: dict, breaks: tuple) -> list[Mark]:
    """Each lettered straight line followed by the point its letter stands at.

    A line (the crank r, the stroke s = 2r) is lettered at its middle -- a rod drawn across a broken axis
    at the middle of its part beside the crank -- on a point of its own that the drawing does not show
    (look ``hidden``; an auxiliary one).  A fan of lettered lines from one point (the cranks of Tabelle 2)
    is lettered at the lines' far ends, where they stand furthest apart, beside the points they were
    drawn to, with the lines' own role (their letters are placed with the results').
    """
    out: list[Mark] = []
    for m in marks:
        out.append(m)
        got = lettered.get(m.id)
        if got is None:
            continue
        label, fan = got
        at = letter_point(m.geom, fan, breaks)
        out.append(dataclasses.replace(m, id=f"{m.id}-at", kind=MarkKind.POINT, geom=(at[0], at[1]),
                                       name=f"{m.name}.at", role=m.role if fan else "auxiliary", label=label,
                                       look="hidden", straight=False))
    return out


def fanned_lines(steps: Iterable[Step]) -> dict[str, bool]:
    """Each lettered straight line (polyline) of *steps*: is it one of a fan of three or more drawn from one
    point (the cranks of Tabelle 2), lettered at its far end rather than its middle?

    >>> from construct.constructions import get
    >>> fanned_lines(get("crank-angle").figure().protocol.steps)["OW1"]  # the cranks AOW of Tabelle 2
    True
    >>> sorted(fanned_lines(get("crank").figure(parts=3).protocol.steps).items())  # r, L and s = 2r
    [('crankarm', False), ('rodline', False), ('stroke', False)]
    """
    fans: dict[str, list[str]] = collections.defaultdict(list)  # lettered straight lines by their first point
    for s in steps:
        if s.op == "polyline" and s.outputs[0] in dict(s.labels):
            fans[s.inputs[0]].append(s.outputs[0])
    return {name: len(lines) >= 3 for lines in fans.values() for name in lines}


def letter_point(pts: tuple, fan: bool, breaks: Iterable[tuple] = ()) -> tuple[float, float]:
    """Where a lettered straight line's letter stands: at its middle, or (one of a fan) at its far end; a
    line drawn across a broken axis (*breaks*: where the drawn break starts, its drawn width, and the axis if
    it is not x: :class:`Break`) at the middle of its part beyond the break (right of it, or above it).

    >>> letter_point(((0.0, 0.0), (4.0, 0.0)), False), letter_point(((0.0, 0.0), (4.0, 2.0)), True)
    ((2.0, 0.0), (4.0, 2.0))
    >>> letter_point(((0.0, 0.0), (4.0, 0.0)), False, [(1.0, 1.0)])
    (3.0, 0.0)
    >>> letter_point(((0.0, 0.0), (0.0, 4.0)), False, [Break(1.0, 1.0, 5.0, 1)])
    (0.0, 3.0)
    """
    at = pts[-1] if fan else middle(pts)
    for b in breaks:
        x0, w, axis = b[0], b[1], (b[3] if len(b) > 3 else 0)
        a, c = pts[0], pts[-1]
        if len(pts) == 2 and min(a[axis], c[axis]) < x0 + w and max(a[axis], c[axis]) > x0 + w and not fan:
            t = (x0 + w + max(a[axis], c[axis])) / 2.0  # the middle of the part beyond the break
            s = a[1 - axis] + (c[1 - axis] - a[1 - axis]) * (t - a[axis]) / (c[axis] - a[axis])
            at = (t, s) if axis == 0 else (s, t)
    return at


def middle(pts: tuple, at: float = 0.5) -> tuple[float, float]:
    """The point half way (or the fraction *at* of the way) along a polyline.

    >>> middle(((0.0, 0.0), (2.0, 0.0), (2.0, 2.0))), middle(((0.0, 0.0), (4.0, 0.0)), 0.75)
    ((2.0, 0.0), (3.0, 0.0))
    """
    lengths = [math.dist(p, q) for p, q in zip(pts, pts[1:])]
    half = sum(lengths) * at
    for (p, q), d in zip(zip(pts, pts[1:]), lengths):
        if half <= d and d > 0.0:
            t = half / d
            return (p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))
        half -= d
    return (pts[-1][0], pts[-1][1])


def lay_out(marks: list[Mark], panels: tuple, margin: float, tol: float) -> list[Mark]:
    """The marks laid out in a plate's panels: each mark drawn once in every panel whose patterns match its
    name, moved by that panel's shift; a mark no panel names stays.

    A line drawn in a panel reaches over that panel's points on it (plus *margin*, as every line does), so
    the stroke line under two diagrams is drawn under each; copies that fall on one line (an ordinate through
    two panels one above the other) are drawn as one line over all their points.  The first copy keeps the
    mark's id, the others add ``-panel<j>``.

    >>> from construct.render.plate import Panel
    >>> p = Mark("p", 1, "P", "point", (0.0, 0.0), "result", "", "")
    >>> q = Mark("q", 1, "Q", "point", (1.0, 0.0), "result", "", "")
    >>> ax = Mark("ax", 1, "axis", "segment", (-9.0, 0.0, 9.0, 0.0), "result", "", "")
    >>> out = lay_out([p, q, ax], (Panel(("P", "Q", "axis")), Panel(("Q", "axis"), (0.0, 3.0))), 0.5, 1e-9)
    >>> [(m.id, m.geom) for m in out]  # doctest: +NORMALIZE_WHITESPACE
    [('p', (0.0, 0.0)), ('q', (1.0, 0.0)), ('q-panel1', (1.0, 3.0)),
     ('ax', (-0.5, 0.0, 1.5, 0.0)), ('ax-panel1', (-1.5, 3.0, 3.5, 3.0))]
    """
    pats = [[re.compile(p) for p in panel.names] for panel in panels]
    homes = {m.id: [i for i, ps in enumerate(pats) if any(p.fullmatch(m.name) for p in ps)] for m in marks}
    points = [[m.geom for m in marks if m.kind is MarkKind.POINT and i in homes[m.id]] for i in range(len(panels))]
    out: list[Mark] = []
    for m in marks:
        ins = homes[m.id]
        if not ins:
            out.append(m)
            continue
        if m.kind is MarkKind.SEGMENT:
            geoms = _segment_copies(m.geom, [(tuple(panels[i].shift), points[i]) for i in ins], margin, tol)
        else:
            geoms = [_moved(m, tuple(panels[i].shift)) for i in ins]
        out.extend(dataclasses.replace(m, id=m.id if j == 0 else f"{m.id}-panel{j}", geom=g)
                   for j, g in enumerate(geoms))
    return out


def _moved(m: Mark, shift: tuple[float, float]) -> tuple:
    dx, dy = shift
    g = m.geom
    if m.kind is MarkKind.POINT:
        return (g[0] + dx, g[1] + dy)
    if m.kind is MarkKind.SEGMENT:
        return (g[0] + dx, g[1] + dy, g[2] + dx, g[3] + dy)
    if m.kind.round:
        return (g[0] + dx, g[1] + dy) + tuple(g[2:])
    return tuple((x + dx, y + dy) for x, y in g)  # curve, area


def _segment_copies(geom: tuple, homes: list, margin: float, tol: float) -> list[tuple]:
    """A segment's copies, one per (shift, that panel's points): each over the points on it, collinear ones merged."""
    x1, y1, x2, y2 = geom
    length = math.hypot(x2 - x1, y2 - y1) or 1.0
    ux, uy = (x2 - x1) / length, (y2 - y1) / length
    nx, ny = -uy, ux
    lines: list[list[float]] = []  # [offset across, t0, t1] in the frame of the unmoved line
    for (dx, dy), pts in homes:
        on = [(px - x1) * ux + (py - y1) * uy for px, py in pts
              if abs((px - x1) * nx + (py - y1) * ny) <= tol * max(1.0, length)]
        if on:
            pad = margin * (5.0 if max(on) - min(on) <= tol * max(1.0, length) else 1.0)
            t0, t1 = min(on) - pad, max(on) + pad
        else:
            t0, t1 = 0.0, length
        off, along = dx * nx + dy * ny, dx * ux + dy * uy
        for ln in lines:
            if abs(ln[0] - off) <= tol * max(1.0, length):
                ln[1], ln[2] = min(ln[1], t0 + along), max(ln[2], t1 + along)
                break
        else:
            lines.append([off, t0 + along, t1 + along])
    return [(x1 + off * nx + t0 * ux, y1 + off * ny + t0 * uy, x1 + off * nx + t1 * ux, y1 + off * ny + t1 * uy)
            for off, t0, t1 in lines]


def plate_names(protocol: Protocol, objects: Replay) -> set[str]:
    """What a book plate shows: results, the curves that locate them, the points those curves pass through.

    Given points stay (the crank centre); auxiliary objects and the points a
    curve is only centred on (the far crossheads of the rod arcs) do not.

    >>> from construct.constructions import get
    >>> fig = get("crank").figure(parts=6)
    >>> names = plate_names(fig.protocol, fig.replay)
    >>> {"crank", "X3", "back3", "P3", "ord2", "O"} <= names, "rod3" in names
    (True, False)
    """
    explicit = protocol.params.get("plate")
    if explicit:
        # The construction names what its book figure shows (regular expressions over object names).
        return set(_named(tuple(explicit), tuple(objects)))
    maker = {n: s for s in protocol.steps for n in s.outputs}
    shown: set[str] = set()
    curves: set[str] = set()
    for s in protocol.steps:
        if s.role == "result":
            shown.update(s.outputs)
            for name in s.inputs:
                if isinstance(objects.get(name), (Line, Circle)) or hasattr(objects.get(name), "curve_points"):
                    curves.add(name)
        elif s.op == "given_point":
            shown.update(s.outputs)
    shown |= curves
    for name in sorted(curves | {n for n in shown if isinstance(objects.get(n), (Line, Circle))}):
        s = maker[name]
        through = {"circle_through": s.inputs[1:], "line": s.inputs, "given_line": s.inputs}.get(s.op, ())
        for p in through:
            if isinstance(objects.get(p), Point) and maker[p].role != "auxiliary":
                shown.add(p)
    # Points that lie on a shown circle without the protocol saying so (the stroke
    # marks on the rod arcs of Fig. 77) belong to the plate too; helper points
    # (dotted names) and auxiliary ones do not.  Lines are not asked: every
    # crosshead lies on the stroke line, far from the plate.
    pts = [(n, o) for n, o in objects.items() if isinstance(o, Point) and n not in shown
           and "." not in n and maker[n].role != "auxiliary"]
    if pts:
        import numpy as np

        xs = [o[0] for _, o in objects.items() if isinstance(o, Point)]
        tol = 1e-9 * max(max(xs) - min(xs), 1.0)
        px, py = np.array([o[0] for _, o in pts], dtype=float), np.array([o[1] for _, o in pts], dtype=float)
        for name in sorted(curves):
            obj = objects[name]
            if not isinstance(obj, Circle):
                continue
            # every circle against every point at once (a 1440-part crank has thousands of each); numpy's
            # hypot may differ from math's in the last bit, so it only picks the candidates, _on decides
            (cx, cy), r = obj
            near = np.abs(np.hypot(px - cx, py - cy) - r) <= 2.0 * tol * max(1.0, r)
            for i in np.flatnonzero(near).tolist():
                n, o = pts[i]
                if n not in shown and _on(obj, o, tol):
                    shown.add(n)
    return shown


@functools.lru_cache(maxsize=8)
def _named(patterns: tuple[str, ...], names: tuple[str, ...]) -> frozenset[str]:
    """The *names* some pattern matches whole (a live sweep draws the same objects hundreds of times)."""
    compiled = [re.compile(p) for p in patterns]
    return frozenset(n for n in names if any(p.fullmatch(n) for p in compiled))


def _on(curve: Any, p: Point, tol: float) -> bool:
    if isinstance(curve, Circle):
        (cx, cy), r = curve
        return abs(math.hypot(p[0] - cx, p[1] - cy) - r) <= tol * max(1.0, r)
    if isinstance(curve, Line):
        (px, py), (qx, qy) = curve
        d = math.hypot(qx - px, qy - py)
        return abs((qx - px) * (p[1] - py) - (qy - py) * (p[0] - px)) / d <= tol
    return False


def _curve_points(objects: Replay, shown: set[str] | None = None) -> list[tuple[float, float]]:
    pts: list[tuple[float, float]] = []
    for n, o in objects.items():
        if shown is not None and n not in shown:
            continue
        if hasattr(o, "rings"):
            for ring in o.rings():
                pts.extend(ring)
        elif hasattr(o, "curve_points"):
            pts.extend(o.curve_points())
    return pts


#: Two gaps between the points marked on a circle are one gap's width apart by less than this (rad): a tie.
GAP_TIE = 1e-9


def widest_gap(angles: Sequence[float], gaps: Sequence[float]) -> int:
    """Which gap between the points marked on a circle (at *angles*, sorted) the drawn arc leaves out: the widest,
    and of two as wide (a circle cut by a line through its centre: a half circle either way) the one about the
    circle's rightmost point (angle 0; of two as near, the one about its top), never the other by a rounding --
    the arc stays on one side as a given moves.

    >>> widest_gap([math.pi / 2, 3 * math.pi / 2], [math.pi, math.pi]), widest_gap([0.0, 1.0], [1.0, TWO_PI - 1.0])
    (1, 1)
    """
    widest = max(gaps)
    tied = [j for j, g in enumerate(gaps) if g >= widest - GAP_TIE]
    if len(tied) == 1:
        return tied[0]
    mid = lambda j: angles[j] + gaps[j] / 2  # noqa: E731
    return max(tied, key=lambda j: (round(math.cos(mid(j)), 9), round(math.sin(mid(j)), 9), -j))


def _segment_extent(line: Line, pts: list[Point], margin: float) -> tuple[float, float, float, float]:
    (px, py), _ = line
    ux, uy = line.direction()
    ts = [(q[0] - px) * ux + (q[1] - py) * uy for q in pts] or [0.0, 1.0]
    if max(ts) - min(ts) <= 1e-9 * max(1.0, abs(ts[0])):
        # A line shown through one point only (a tangent at its point of contact)
        # is drawn long enough to be seen as a line.
        margin *= 5.0
    t0, t1 = min(ts) - margin, max(ts) + margin
    return (px + t0 * ux, py + t0 * uy, px + t1 * ux, py + t1 * uy)


def _circle_extent(circle: Circle, pts: list[Point], margin: float, role: str,
                   plate: bool = False) -> tuple[MarkKind, tuple]:
    """A full circle for results and unmarked circles, else the arc over the marked points.

    On a plate a result circle whose shown points cover at most a half turn
    (the crank circle of the forward stroke) is drawn as exactly that arc:
    the books' "über dem Kolbenhub geschlagene Halbkreis".
    """
    (cx, cy), r = circle
    if role == "result" and plate and len(pts) >= 3:
        kind, geom = _circle_extent(circle, pts, 0.0, "construction")
        if kind is MarkKind.ARC and geom[4] <= math.pi * (1.0 + 1e-9):
            return kind, geom
    if role == "result" or not pts:
        return MarkKind.CIRCLE, (cx, cy, r)
    angles: list[float] = []
    for a in sorted(math.atan2(p[1] - cy, p[0] - cx) % TWO_PI for p in pts):
        if not angles or a - angles[-1] > 1e-9:  # the same point marked twice counts once
            angles.append(a)
    if len(angles) > 1 and angles[0] + TWO_PI - angles[-1] <= 1e-9:
        angles.pop()
    # The drawn arc is the complement of the largest empty gap between marked points.
    gaps = [(angles[(i + 1) % len(angles)] - a) % TWO_PI or (TWO_PI if len(angles) == 1 else 0.0)
            for i, a in enumerate(angles)]
    i = widest_gap(angles, gaps)
    start = angles[(i + 1) % len(angles)]
    sweep = TWO_PI - gaps[i]
    pad = min(margin / r, 0.6)
    start, sweep = start - pad, sweep + 2.0 * pad
    if sweep >= 0.92 * TWO_PI:
        return MarkKind.CIRCLE, (cx, cy, r)
    return MarkKind.ARC, (cx, cy, r, start, sweep)


def _arc_extremes(g: tuple) -> list[tuple[float, float]]:
    """An arc's ends and the quarter points it passes: its exact box, in at most six points."""
    cx, cy, r, a0, sw = g
    quarter = math.pi / 2
    angles = [a0, a0 + sw] + [q * quarter for q in range(math.ceil(min(a0, a0 + sw) / quarter),
                                                          math.floor(max(a0, a0 + sw) / quarter) + 1)]
    return [(cx + r * math.cos(a), cy + r * math.sin(a)) for a in angles]


#: The points that bound a mark's ``geom``, by kind (:func:`extreme_points`).
_EXTREMES: dict[MarkKind, Callable[[tuple], list[tuple[float, float]]]] = {
    MarkKind.POINT: lambda g: [g],
    MarkKind.SEGMENT: lambda g: [(g[0], g[1]), (g[2], g[3])],
    MarkKind.CIRCLE: lambda g: [(g[0] - g[2], g[1] - g[2]), (g[0] + g[2], g[1] + g[2])],
    MarkKind.ARC: _arc_extremes,
    MarkKind.CURVE: list,
    MarkKind.AREA: list,
}


def extreme_points(m: Mark) -> list[tuple[float, float]]:
    """The points that bound a mark as drawn: a segment by its ends, a circle by its box's corners.

    >>> arc = Mark("m", 1, "k", MarkKind.ARC, (0.0, 0.0, 2.0, 0.0, math.pi / 2), "construction", "compass", "exact")
    >>> [(round(x, 12), round(y, 12)) for x, y in extreme_points(arc)]
    [(2.0, 0.0), (0.0, 2.0), (2.0, 0.0), (0.0, 2.0)]
    """
    return _EXTREMES[m.kind](m.geom)
