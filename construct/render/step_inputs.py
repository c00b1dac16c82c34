"""What a step takes up, as a teaching frame shows it: the objects its instrument is set on, the lines its arc
is struck onto, the rectangle its ray is the diagonal of, the points it tags and the points its caption names.

The player draws these at full strength in the input colour while the step is current (``inp``,
:meth:`construct.render.step_groups.StepGroups.input_steps`) and tags their points by the names the captions
use.  :class:`StepInputs` is the part of the :class:`~construct.render.scene.Scene` that answers these
questions (its base class, as :class:`~construct.kernel.composite.CompositeSteps` is the Builder's); it reads
only the scene's steps, marks, parameters and group titles.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> sc = build_scene(get("crank").figure(parts=6))
>>> sc.steps[8].caption.en  # step 9
'2 where the circle about 0 meets the crank circle'
>>> sorted(sc.inputs(9)), sorted(sc.tagged(9)), sc.step_of("crank")  # the curves it cuts, the points it tags
(['crank', 'hex.k1'], ['D0', 'P2'], 5)
>>> sorted(sc.struck_onto(8))  # step 8's circle about 0 is struck onto the crank circle, which step 9 cuts
['crank']
>>> sc.display_name("D0"), sc.display_name("P2")
('0', '2')
"""

from __future__ import annotations

import bisect
import functools
import math
import re

from ..kernel.letters import FIGURE_LETTER, primed
from ..kernel.protocol import Step
from .captions import Reader
from .marks import Mark, MarkKind

__all__ = ["StepInputs"]


#: A word of a caption written in the figure's letters that may name a point (a letter with what follows it).
#: (Not a letter of a formula: F/f, r/L, r·cos.)
_LETTERED = re.compile(r"(?<![\w′'″/·])[A-Za-zΑ-Ωα-ω][A-Za-z0-9Α-Ωα-ω′'″₀-₉∞]*(?![/·])")


class StepInputs:
    """What each step of a :class:`~construct.render.scene.Scene` takes up and names (its base class)."""

    marks: tuple[Mark, ...]
    steps: tuple[Step, ...]
    params: dict
    #: the group titles in the figure's letters, by group path (the scene's)
    group_captions: dict[tuple[str, ...], str]

    @functools.cached_property
    def reader(self) -> Reader:
        """Who reads the figure's captions and names its objects (:class:`construct.render.captions.Reader`)."""
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
        return Reader(objects, self.params.get("called"))

    @functools.cached_property
    def marks_by_name(self) -> dict[str, Mark]:
        """Every drawn object's mark by the object's name."""
        return {m.name: m for m in self.marks}

    def step_of(self, name: str) -> int | None:
        """The step that drew object *name* (None: it is not drawn)."""
        m = self.marks_by_name.get(name)
        return m.step if m is not None else None

    def inputs(self, k: int) -> frozenset[str]:
        """The objects step k's instrument is set on (centre, through point, the curves it cuts)."""
        if not 1 <= k <= len(self.steps):
            return frozenset()
        return frozenset(n for n in self.steps[k - 1].inputs if n in self.marks_by_name)

    def struck_onto(self, k: int) -> frozenset[str]:
        """The lines and curves step k's arc is struck onto: those the step that next takes up what step k
        makes cuts it with (the scale line an arc is carried to is cut by the following step, which takes
        the crossing).  Without them the student would see an arc struck onto nothing.

        >>> from construct.constructions import get
        >>> from construct.render.scene import build_scene
        >>> sc = build_scene(get("tangential-pressure").figure())
        >>> sorted(sc.struck_onto(821))  # 'r cos ω = O–Yb7 carried to the scale line r'
        ['gr']
        """
        if not 1 <= k <= len(self.steps):
            return frozenset()
        made = {n for n in self.steps[k - 1].outputs
                if n in self.marks_by_name and self.marks_by_name[n].kind is not MarkKind.POINT}
        if not made:
            return frozenset()
        for s in self._takers.get(k, ()):
            step = self.steps[s - 1]
            if made & set(step.inputs) and all(n not in self.marks_by_name or self.marks_by_name[n].kind is MarkKind.POINT
                                               for n in step.outputs):
                return frozenset(n for n in step.inputs if n not in made and n in self.marks_by_name
                                 and self.marks_by_name[n].kind is not MarkKind.POINT and self.marks_by_name[n].step < k)
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

    def aimed_at(self, k: int) -> frozenset[str]:
        """The sides of the rectangle step k's straightedge draws the diagonal of: a line laid from a point
        through a corner where two perpendicular straight lines cross (the hyperbola's ray from O through B,
        the ordinate meeting the horizontal through the known point) -- without them the student sees a ray
        aimed at a point on nothing.

        >>> from construct.constructions import get
        >>> from construct.render.scene import build_scene
        >>> sc = build_scene(get("flywheel-rim").figure())
        >>> k = next(s.index for s in sc.steps if s.outputs == ("U6.s",))
        >>> sorted(sc.aimed_at(k))  # the ordinate at 6/12 r1 and the horizontal through the rim's corner K
        ['khU', 'lv6']
        """
        if not 1 <= k <= len(self.steps):
            return frozenset()
        s = self.steps[k - 1]
        if s.op != "line" or len(s.inputs) != 2:
            return frozenset()
        maker = self.step_of(s.inputs[1])
        if maker is None or self.steps[maker - 1].op != "intersect":
            return frozenset()
        sides = [self.marks_by_name.get(n) for n in self.steps[maker - 1].inputs]
        if len(sides) != 2 or any(m is None or m.kind is not MarkKind.SEGMENT for m in sides):
            return frozenset()
        (ax0, ay0, ax1, ay1), (bx0, by0, bx1, by1) = (m.geom[:4] for m in sides)  # type: ignore[union-attr]
        ux, uy, vx, vy = ax1 - ax0, ay1 - ay0, bx1 - bx0, by1 - by0
        if abs(ux * vx + uy * vy) > 1e-6 * math.hypot(ux, uy) * math.hypot(vx, vy):
            return frozenset()  # not a rectangle's corner
        return frozenset(m.name for m in sides)  # type: ignore[union-attr]

    def tagged(self, k: int) -> frozenset[str]:
        """The points a teaching frame tags at step k: what the step makes, what its instrument is set on
        (also the centre of a circle it cuts), and every point its caption names."""
        if not 1 <= k <= len(self.steps):
            return frozenset()
        s = self.steps[k - 1]
        names = set(s.outputs) | set(s.inputs) | self.named(k)
        for n in s.inputs:
            if n in self.reader.objects and n not in self.reader.points:
                names.update(self.reader.curve_points(n))
        return frozenset(n for n in names if n in self.reader.points)

    def named(self, k: int) -> frozenset[str]:
        """The points step k's caption names (and its group's title, in a protocol written in letters)."""
        if not 1 <= k <= len(self.steps):
            return frozenset()
        got = self._named.get(k)
        if got is None:  # (the camera, the insets and the tags ask of every step)
            s = self.steps[k - 1]
            if self.params.get("captions") == "letters":  # the caption names points by their letters
                names = self._named_points(k)
            else:
                names = self.reader.mentioned(s.caption.de) | self.reader.mentioned(s.caption.en)
            got = self._named[k] = frozenset(n for n in names if n in self.reader.points)
        return got

    @functools.cached_property
    def _named(self) -> dict[int, frozenset[str]]:
        """:meth:`named` by step, as asked."""
        return {}

    def _named_points(self, k: int) -> set[str]:
        """The points step k's caption and its group's title (written in the figure's letters) name by a letter
        or a tag.

        A tag may stand for several helpers (the F of every trisection): the caption means the one of its
        own group, made by then (the latest of them); a lone letter of another top-level group is another F
        (a numbered tag, M2, is the latest made).  A lettered point is the figure's, whatever its group.
        """
        s = self.steps[k - 1]
        out: set[str] = set()
        # the step's caption and its group's title (the innermost, which the player shows with it)
        group = self.group_captions[s.group].rsplit(" › ", 1)[-1] if s.group else ""
        for token in set(_LETTERED.findall(s.caption.de)) | set(_LETTERED.findall(s.caption.en)) | set(
                _LETTERED.findall(group)):
            name = self._letter_index.latest(token, k, s.group)
            if name is not None:
                out.add(name)
        return out

    @functools.cached_property
    def _letter_index(self) -> "_LetterIndex":
        """:meth:`_by_letter` filed by group (:class:`_LetterIndex`)."""
        return _LetterIndex(self._by_letter)

    @functools.cached_property
    def _by_letter(self) -> dict[str, list[tuple[int, str, tuple[str, ...], bool]]]:
        """The points by the letter or tag a caption names them by: (step made, name, group, lettered?), in step
        order."""
        out: dict[str, list[tuple[int, str, tuple[str, ...], bool]]] = {}
        for m in self.marks:
            if m.kind is MarkKind.POINT and m.name in self.reader.points:
                out.setdefault(m.label or self.display_name(m.name), []).append((m.step, m.name, m.group, bool(m.label)))
        return out

    def display_name(self, name: str) -> str:
        """The letter or tag the reader sees for an object (the same one the captions use)."""
        return primed(self.reader.point(name) if name in self.reader.points else name.rsplit(".", 1)[-1])

    def tag_shown(self, name: str) -> bool:
        """Whether an unlettered point's tag (:meth:`display_name`) reads as one of the figure's letters.

        A figure is lettered with one letter, perhaps with a number of at most two
        digits or a prime (M2, S1, q10, K17, 5′); the helpers' internal names
        (``c135``: the crank at 135°, ``Nb17``, ``iP6``) are not letters and are not
        shown, whatever the caption calls them.

        >>> from construct.constructions import get
        >>> from construct.render.scene import build_scene
        >>> sc = build_scene(get("crank").figure(parts=6))
        >>> [FIGURE_LETTER.fullmatch(t) is not None for t in ("M2", "q10", "5′", "c135", "Nb17", "iP6")]
        [True, True, True, False, False, False]
        """
        return FIGURE_LETTER.fullmatch(self.display_name(name)) is not None


class _LetterIndex:
    """The points a letter or tag names, filed by each beginning of their group's path, so that the point a
    caption of step k means (:meth:`StepInputs._named_points`) is found by bisection, not by a walk over every
    point of that letter made before step k (a walk that grew with the square of the figure: 253 F's in the
    compound engine).

    The rule: of the points of the letter made up to step k (the points in step order, up to the first made
    after k), those sharing the most leading groups with step k's group, the latest of them; a point sharing
    none counts only if it is lettered or the letter is a numbered tag.
    """

    __slots__ = ("_steps", "_prefix", "_lettered", "_names")

    def __init__(self, by_letter: dict[str, list[tuple[int, str, tuple[str, ...], bool]]]) -> None:
        self._steps: dict[str, list[int]] = {}  # per letter, the highest step among its first points (for the cut)
        self._prefix: dict[tuple[str, tuple[str, ...]], list[int]] = {}  # (letter, leading groups): positions
        self._lettered: dict[str, list[int]] = {}  # per letter, the positions of the lettered points
        self._names: dict[str, list[str]] = {}
        for token, points in by_letter.items():
            top = -math.inf
            steps = self._steps[token] = []
            for i, (step, name, grp, lettered) in enumerate(points):
                top = max(top, step)
                steps.append(top)
                for d in range(1, len(grp) + 1):
                    self._prefix.setdefault((token, grp[:d]), []).append(i)
                if lettered:
                    self._lettered.setdefault(token, []).append(i)
            self._names[token] = [p[1] for p in points]

    def latest(self, token: str, k: int, group: tuple[str, ...]) -> str | None:
        """The point *token* means in a caption of step *k* in *group* (None: none made by then)."""
        steps = self._steps.get(token)
        if steps is None:
            return None
        cut = bisect.bisect_right(steps, k)  # the points made up to step k, before the first made after it
        for d in range(len(group), 0, -1):
            at = self._prefix.get((token, group[:d]))
            if at:
                i = bisect.bisect_left(at, cut) - 1
                if i >= 0:
                    return self._names[token][at[i]]
        if len(token) > 1:
            return self._names[token][cut - 1] if cut else None
        at = self._lettered.get(token, ())
        i = bisect.bisect_left(at, cut) - 1
        return self._names[token][at[i]] if i >= 0 else None
