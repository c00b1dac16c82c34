"""The instruments and the composite steps a draftsman builds from them.

A :class:`Builder` records a protocol while it evaluates it, so an
impossible step (circles that do not meet) fails at once and names itself.
Its primitive methods are the instruments -- straightedge, compass (about a
point through a point, or with an opening carried over from a segment or a
given length), dividers -- and the point where two drawn curves cross.  The
composite methods (midpoint, perpendiculars, parallels, division of a segment
by the intercept theorem, angle bisection, copying an arc) are made of those
primitives only, each as a collapsible group; they are inherited from
:class:`~construct.kernel.composite.CompositeSteps`.  What is left here (over 600 lines) is one idea: the
Builder's recording and one method per instrument.

>>> b = Builder("demo", givens={"s": 3.0})
>>> A = b.given_point("A", 0.0, 0.0)
>>> B = b.given_point("B", 3.0, 0.0)
>>> parts = b.divide_segment("T", A, B, 3)
>>> [round(b[p].x, 12) for p in parts]
[1.0, 2.0]
>>> b.protocol().instrument_counts()
{'compass': 4, 'given': 2, 'intersect': 5, 'straightedge': 5}
"""

from __future__ import annotations

import contextlib
import contextvars
from dataclasses import replace
from types import MappingProxyType
from collections.abc import Mapping, Sequence
from typing import Any, Iterator

import numpy as np

from .errors import DuplicateName, InvalidParameter, RuleError, StepError, UnknownObject, WrongInput
from .protocol import (EXACT, GIVEN, ROLES, TOOLS, Caption, Protocol, Provenance, Replay, Step, compile_step,
                       run_step)
from .numeric import as_float, shown
from .geometry import SCALAR
from .replay import sweep_givens
from .rules import Rule, as_rule
from .composite import CompositeSteps



__all__ = ["Builder", "unlettered"]

#: Set while builds need only their steps' form (:func:`unlettered`).
_UNLETTERED: contextvars.ContextVar[bool] = contextvars.ContextVar("unlettered", default=False)


@contextlib.contextmanager
def unlettered() -> Iterator[None]:
    """Builds inside leave their captions as written, not read into the figure's letters, and their protocol's
    replay is what the build made as it went (the same ops on the same values), not a second evaluation: a third
    of a build's time, for a caller that asks only which steps a build takes (a live player's pieces:
    :func:`construct.live.sweep.pieces`).  The protocol says so (``captions`` is not ``"letters"``).

    >>> with unlettered():
    ...     b = Builder("demo", givens={}); _ = b.given_point("A", 0.0, 0.0)
    ...     b.protocol().params.get("captions")
    >>> b.protocol().params["captions"]
    'letters'
    """
    token = _UNLETTERED.set(True)
    try:
        yield
    finally:
        _UNLETTERED.reset(token)


def _same_givens(givens: Mapping[str, Any], own: Mapping[str, Any]) -> bool:
    """Are *givens* a build's own (*own*), not a sweep over them (arrays of givens are never its own)?"""
    asked, xp = sweep_givens(dict(givens))
    return xp is SCALAR and asked == dict(own)


class _Sketch(Protocol):
    """An unlettered build's protocol (:func:`unlettered`): its replay at the build's own givens is what the
    build made."""

    def __init__(self, construction: str, params: Any, steps: tuple, replayable: tuple, made: dict[str, Any]):
        super().__init__(construction, params, steps, replayable)
        object.__setattr__(self, "_made", made)

    def replay(self, givens: Mapping[str, Any] | None = None, *, upto: int | None = None) -> Replay:
        if upto is None and (givens is None or _same_givens(givens, self.params["givens"])):
            return Replay(self, dict(self._made), self.params["givens"])
        return super().replay(givens, upto=upto)


class Builder(CompositeSteps):
    """Records and evaluates a construction step by step.

    Each method draws with one instrument (or a few, for the composites) and
    returns the name of what it made; ``b[name]`` is the object itself.

    Arguments every drawing method shares:

    - *de*, *en*: the step's caption in German and English, as the player and
      the animation show it ("Kreis um 7 durch A" / "circle about 7 through
      A").  Left out, the method writes one from the names of its inputs.
    - *role*: what the object is in the figure, which decides how a style
      draws it: ``"construction"`` (the default: a thin line, drawn in every
      step; a plate -- the historical style's final figure -- keeps it only
      where it locates a result), ``"result"`` (what the construction is for:
      heavy, always on the plate and lettered) or ``"auxiliary"`` (a helper a
      plate leaves out).  A letter on a point the plate leaves out is not
      lost in silence: drawing the plate warns
      (:class:`~construct.kernel.errors.HiddenLabelWarning`).
    - *label* (:meth:`given_point`), *labels* (``{name: letter}``, for the
      methods that make several points: :meth:`intersect`, :meth:`pick`) and
      :meth:`set_label` (any object, afterwards): the letter printed beside
      a point; points without one are drawn unlettered (the teaching style
      tags them with their name while they are in use).

    What a builder holds, read but not to be changed by hand: ``construction``
    (its name), ``givens`` and ``params`` (see :meth:`__init__`),
    ``replayable``, ``steps`` (the recorded steps, each a :class:`~construct.kernel.protocol.Step`),
    ``objects`` (name -> the object a step made; ``b[name]`` reads one) and
    ``provenance`` (name -> how exact it is).  :meth:`record` is the one door
    every method goes through; call it for an op that has no method of its own.

    Objects are passed to methods by name (the strings they return), so that a
    step is data -- tool, op, inputs, outputs, parameters, caption -- which
    :meth:`protocol` collects and :meth:`Protocol.replay
    <construct.kernel.protocol.Protocol.replay>` evaluates again with other
    givens.  ``construct.Builder`` adds :meth:`figure`, the protocol with its
    objects ready to draw and check.

    >>> b = Builder("two points", givens={})
    >>> b.given_point("A", 0.0, 0.0), b.given_point("B", 4.0, 3.0)
    ('A', 'B')
    >>> b["B"]
    Point(4.0, 3.0)
    >>> b["C"]
    Traceback (most recent call last):
    ...
    construct.kernel.errors.UnknownObject: no object 'C' in 'two points' (it has A, B)
    """

    def __init__(self, construction: str, givens: Mapping[str, float], params: Mapping[str, Any] | None = None,
                 replayable: Sequence[str] | None = None):
        """Start an empty construction named *construction*.

        *givens* are the numbers a replay may change (``{"r": 1.0, "rod_ratio": 5.0}``), each a finite
        number: steps refer to them by name (``given_point(..., unit="r")``, ``given_length(...,
        product=("r",))``), so that :meth:`Protocol.replay <construct.kernel.protocol.Protocol.replay>`
        with other values redraws the same steps.  *params* are stored with the protocol but fixed for its
        steps (the number of parts, the division method; ``"plate"``, a list of regular expressions over
        object names, says what the historical plate shows).  The protocol adds ``"givens"``,
        ``"captions"`` and ``"group_titles"`` itself.  *replayable* names the givens a replay is meant to
        change, a subset of *givens* (default: all of them); the protocol lists them as
        :attr:`Protocol.givens <construct.kernel.protocol.Protocol.givens>`.

        >>> b = Builder("crank", givens={"r": 0.4}, params={"parts": 12})
        >>> _ = b.given_point("O", 0.0, 0.0); _ = b.given_point("A", 1.0, 0.0, unit="r")
        >>> p = b.protocol()
        >>> p.givens, p.params["parts"], b["A"], p.replay({"r": 2.0})["A"]
        (('r',), 12, Point(0.4, 0.0), Point(2.0, 0.0))
        >>> Builder("crank", givens={"r": 0.4}, replayable=["rod_ratio"])
        Traceback (most recent call last):
        ...
        construct.kernel.errors.InvalidParameter: replayable names givens of 'crank'; 'rod_ratio' is none (it has r)
        """
        if not isinstance(construction, str) or not construction:
            raise InvalidParameter(f"a construction is named by a non-empty string, got {construction!r}")
        if not isinstance(givens, Mapping):
            raise InvalidParameter(f"givens are a mapping of names to numbers, got {shown(givens)}")
        for key, value in givens.items():
            _check_given(key, value)
        if params is not None and not isinstance(params, Mapping):
            raise InvalidParameter(f"params are a mapping of names to values, got {shown(params)}")
        if replayable is not None:
            # a bare string would be read letter by letter
            if isinstance(replayable, str) or not isinstance(replayable, Sequence):
                raise InvalidParameter(f"replayable is a list of names of givens, got {shown(replayable)}")
            for name in replayable:
                if not isinstance(name, str) or name not in givens:
                    raise InvalidParameter(f"replayable names givens of {construction!r}; {shown(name)} is none "
                                           f"(it has {', '.join(givens) or 'no givens'})")
        self.construction = construction
        self.givens = dict(givens)
        self.params = dict(params or {})
        self.replayable = tuple(replayable if replayable is not None else self.givens)
        self.steps: list[Step] = []
        self.objects: dict[str, Any] = {}
        self.provenance: dict[str, Provenance] = {}
        self._maker: dict[str, int] = {}  # object name -> index into steps (labels are set in O(1))
        self._group: list[str] = []
        self._group_titles: dict[str, str] = {}
        self._counter: dict[str, int] = {}
        self._called: dict[str, tuple[str, str]] = {}
        self._taken_over = 0  # the first steps, taken over from a protocol, whose captions are lettered already

    @classmethod
    def continuing(cls, protocol: Protocol, objects: Mapping[str, Any], construction: str,
                   givens: Mapping[str, float] | None = None, params: Mapping[str, Any] | None = None) -> "Builder":
        """A builder for a construction that goes on from another's figure: its first steps are *protocol*'s
        (with the objects its replay made), its givens and params those of *protocol* and *givens*, *params*.

        The steps taken over keep their captions, groups and letters; the new ones are lettered as usual.

        >>> b = Builder("segment", givens={"s": 2.0})
        >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 1.0, 0.0, unit="s")
        >>> first = b.protocol()
        >>> c = Builder.continuing(first, first.replay(), "midpoint", params={"note": "on"})
        >>> _ = c.midpoint("M", "A", "B")
        >>> p = c.protocol()
        >>> p.construction, p.steps[:2] == first.steps, p.replay({"s": 6.0})["M"]
        ('midpoint', True, Point(3.0, 0.0))
        """
        inherited = dict(protocol.params)
        old_givens = dict(inherited.pop("givens", {}))
        titles = dict(inherited.pop("group_titles", {}))
        inherited.pop("captions", None)
        b = cls(construction, {**old_givens, **(givens or {})}, {**inherited, **(params or {})})
        for step in protocol.steps:
            b.steps.append(step)
            for name in step.outputs:
                b.objects[name] = objects[name]
                b.provenance[name] = step.provenance
                b._maker[name] = step.index - 1
        b._group_titles.update(titles)
        # what the first steps call their lines, for the new steps' captions too
        b._called.update({k: (v[0], v[1]) for k, v in inherited.get("called", {}).items()})
        b._taken_over = len(b.steps)
        return b

    # -- bookkeeping ----------------------------------------------------------
    def __getitem__(self, name: str) -> Any:
        """The object made under *name* (a Point, Line, Circle, Length, curve or area); UnknownObject if none."""
        try:
            return self.objects[name]
        except (KeyError, TypeError):  # TypeError: an unhashable "name"
            have = ", ".join(list(self.objects)[:8]) + (", ..." if len(self.objects) > 8 else "")
            raise UnknownObject(f"no object {name!r} in {self.construction!r} (it has {have or 'nothing yet'})") from None

    def fresh(self, prefix: str) -> str:
        """A new object name starting with *prefix* (for auxiliary objects).

        >>> b = Builder("demo", givens={})
        >>> b.fresh("k"), b.fresh("k"), b.fresh("g")
        ('k1', 'k2', 'g1')
        """
        k = self._counter.get(prefix, 0) + 1
        self._counter[prefix] = k
        name = f"{prefix}{k}"
        while name in self.objects:
            k += 1
            self._counter[prefix] = k
            name = f"{prefix}{k}"
        return name

    @contextlib.contextmanager
    def group(self, en: str, de: str | None = None) -> Iterator[None]:
        """Steps recorded inside belong to a group (shown collapsed or expanded).

        >>> b = Builder("demo", givens={})
        >>> with b.group("the ends", "die Enden"):
        ...     _ = b.given_point("A", 0.0, 0.0)
        >>> b.steps[0].group
        ('the ends',)
        """
        if not isinstance(en, str) or not (de is None or isinstance(de, str)):
            raise InvalidParameter(f"a group's titles are text, got {en!r} and {de!r}")
        self._group.append(en)
        if de:
            self._group_titles[en] = de
        try:
            yield
        finally:
            self._group.pop()

    def record(self, tool: str, op: str, inputs: Sequence[str], outputs: Sequence[str],
               params: Mapping[str, Any], de: str, en: str, *, provenance: Provenance | None = None,
               role: str = "construction", labels: Mapping[str, str] | None = None) -> tuple[Any, ...]:
        """Evaluate one step with the op table's function and append it to the protocol.

        The drawing methods all end here; call it directly for an op of the
        kernel's op table (:mod:`construct.kernel.ops`) that has no method of
        its own.  *tool* is the instrument (``"compass"``, ``"straightedge"``,
        ``"dividers"``, ...), *op* the op table's name, *inputs* and *outputs*
        object names, *params* the op's parameters (a ``rule`` choosing an
        intersection is stored as data), *de*/*en* the caption, *provenance*
        how exact the result is (Euclidean unless said), *role* and *labels*
        as for the drawing methods.  Returns the objects made.

        This is the one place a step is evaluated while building; replay runs
        the same compiled entry (:func:`~construct.kernel.protocol.run_step`).


        >>> b = Builder("demo", givens={})
        >>> b.record("given", "given_point", (), ("A",), {"x": 1.0, "y": 2.0, "unit": None},
        ...          "Punkt A", "point A")
        (Point(1.0, 2.0),)
        """
        index = len(self.steps) + 1
        where = dict(step_index=index, tool=tool, op=op)
        problem = _record_problem(tool, inputs, outputs, de, en, role, labels, provenance)
        if problem:
            raise StepError(f"step {index} ({tool}: {en}): {problem}", **where)
        for name in inputs:
            if not isinstance(name, str):
                raise WrongInput(f"step {index} ({tool}: {en}): objects are passed by name (the string a Builder "
                                 f"method returns), got {shown(name)}", **where)
        for name in outputs:
            if not isinstance(name, str) or not name:
                raise StepError(f"step {index} ({tool}: {en}): object names are non-empty strings, got {name!r}", **where)
            if name in self.objects:
                raise DuplicateName(f"step {index} ({tool}: {en}): object name {name!r} is used twice in "
                                f"{self.construction!r}", **where)
        params = dict(params)
        if "rule" in params:
            try:
                params["rule"] = as_rule(params["rule"]).as_tuple()  # stored as its JSON form
            except RuleError as exc:
                raise exc.at_step(index, tool, op, en) from None
        if provenance is None and all(name in self.provenance for name in inputs):
            provenance = self._inherited(tool, inputs)  # (an input no step made is refused below)
        step = Step(index, tool, op, tuple(inputs), tuple(outputs), MappingProxyType(params), Caption(de, en),
                    provenance or EXACT, tuple(self._group), role, tuple(sorted((labels or {}).items())))
        entry = compile_step(step)  # objects kept by name: the builder's dict is the environment
        spec = entry.op
        missing = [n for n in (*step.inputs, *entry.refs) if n not in self.objects]
        if missing:
            raise UnknownObject(f"step {index} ({tool}: {en}) uses {missing[0]!r}, which no earlier step made", **where)
        problem = spec.check_inputs([self.objects[n] for n in step.inputs])
        if problem:
            raise WrongInput(f"step {index} ({tool}: {en}): {op} {problem}", **where)
        try:
            values = run_step(entry, self.objects, self.givens)
        except StepError as exc:  # quote the caption as the protocol will write it: in the figure's letters
            raise self._lettered(exc, step) from None
        if len(values) != len(outputs):
            raise StepError(f"step {index} ({tool}: {en}): {op} makes {len(values)} objects, "
                            f"{len(outputs)} names were given", **where)
        self.steps.append(step)
        for name in outputs:
            self.provenance[name] = step.provenance
            self._maker[name] = index - 1
        return values

    def _lettered(self, exc: StepError, step: Step) -> StepError:
        """*exc* quoting *step*'s caption in the figure's letters, as a replay of the protocol quotes it."""
        import copy

        from .letters import letter_steps

        lettered = letter_steps([*self.steps, step], self.objects, self._called)[-1].caption.brief
        raw = f"({step.tool}: {step.caption.brief})"
        if lettered == step.caption.brief or not exc.args or raw not in str(exc.args[0]):
            return exc
        out = copy.copy(exc)
        out.args = (str(exc.args[0]).replace(raw, f"({step.tool}: {lettered})", 1), *exc.args[1:])
        return out

    def call(self, name: str, de: str, en: str) -> None:
        """Say what a line or circle made already is, for the captions that name it (German, English, in the
        objects' names): a perpendicular built from the helper points S1, S2 of its bisector is read as
        "Senkrechte in m4", not as the line S1–S2 (whose points are long gone from the figure).

        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 2.0, 0.0); _ = b.line("g", "A", "B")
        >>> b.call("g", "Grundlinie durch A", "the base line through A")
        >>> _ = b.circle_through("k", "B", "A"); _ = b.intersect("C", "g", "k", rule=("farther", "A"))
        >>> b.protocol().steps[-1].caption.de
        'C im Schnitt von Grundlinie durch A und dem Kreis um B'
        """
        for text in (de, en):
            if not isinstance(text, str) or not text:
                raise InvalidParameter(f"what {name!r} is called is text, got {shown(text)}")
        if not isinstance(name, str) or name not in self._maker:
            raise UnknownObject(f"no object {name!r} to call in {self.construction!r}")
        self._called[name] = (de, en)

    def set_label(self, name: str, text: str) -> None:
        """Letter an object already made (the figure prints *text* beside it).

        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("P12", 1.0, 0.0)
        >>> b.set_label("P12", "12"); b.steps[0].labels
        (('P12', '12'),)
        """
        if not isinstance(text, str):
            raise InvalidParameter(f"the label of {name!r} is text, got {shown(text)}")
        i = self._maker.get(name) if isinstance(name, str) else None
        if i is None:
            raise UnknownObject(f"no object {name!r} to label in {self.construction!r}")
        step = self.steps[i]
        labels = dict(step.labels)
        labels[name] = text
        self.steps[i] = replace(step, labels=tuple(sorted(labels.items())))

    def _inherited(self, tool: str, inputs: Sequence[str]) -> Provenance:
        """An object is as trustworthy as the weakest object it was made from."""
        if tool == "given":
            return GIVEN
        result = EXACT
        for name in inputs:
            source = self.provenance[name]
            if source.kind != "given":
                result = result.combine(source)
        return result

    def protocol(self) -> Protocol:
        """The recorded steps as a replayable :class:`~construct.kernel.protocol.Protocol`.

        >>> b = Builder("demo", givens={"s": 2.0})
        >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_length("s", product=("s",))
        >>> _ = b.circle_radius("k", "A", "s")
        >>> b.protocol().replay({"s": 3.0})["k"].radius
        3.0
        """
        from .letters import letter_steps

        params = dict(self.params)
        params["givens"] = dict(self.givens)
        if self._group_titles:
            params["group_titles"] = dict(sorted(self._group_titles.items()))
        if self._called:  # what lines and circles are called, read again for the group titles
            params["called"] = {n: list(t) for n, t in sorted(self._called.items())}
        if _UNLETTERED.get():
            return _Sketch(self.construction, MappingProxyType(params), tuple(self.steps), self.replayable,
                           dict(self.objects))
        # The captions name what the figure letters (12, B, M1), not the objects' internal names; steps taken
        # over from another protocol (continuing) are lettered already.
        lettered = letter_steps(self.steps, self.objects, self._called)
        steps = tuple(self.steps[:self._taken_over]) + tuple(lettered[self._taken_over:])
        params["captions"] = "letters"  # read once: a second reading would take a letter (S1) for a name
        return Protocol(self.construction, MappingProxyType(params), steps, self.replayable)

    def replay(self, protocol: Protocol, givens: Mapping[str, Any] | None = None) -> Replay:
        """*protocol* (this builder's, from :meth:`protocol`) replayed at *givens* (default: the build's own).

        At the build's own givens the replay is what the build made: each step was evaluated as it was recorded,
        by the op function a replay runs (:meth:`record`), so the objects are the replay's to the bit and the
        steps are not compiled and run a second time (half the piston-force line's build).  At other givens, or
        of another protocol, it is :meth:`Protocol.replay`.

        >>> b = Builder("demo", givens={"s": 2.0})
        >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_length("s", product=("s",))
        >>> _ = b.circle_radius("k", "A", "s")
        >>> p = b.protocol()
        >>> dict(b.replay(p)) == dict(p.replay()), b.replay(p, {"s": 3.0})["k"].radius
        (True, 3.0)
        """
        own, _ = sweep_givens(self.givens)
        if givens is not None:
            asked, xp = sweep_givens(dict(givens))
            if xp is not SCALAR or asked != own:
                return protocol.replay(givens)
        if (protocol.construction != self.construction or len(protocol.steps) != len(self.steps)
                or dict(protocol.params.get("givens", {})) != dict(self.givens)
                or len(self.objects) != sum(len(s.outputs) for s in self.steps)):
            return protocol.replay(givens)
        return Replay(protocol, dict(self.objects), own)

    # -- givens ----------------------------------------------------------------
    def given_point(self, name: str, x: float, y: float, *, unit: str | None = None,
                    de: str | None = None, en: str | None = None, label: str | None = None) -> str:
        """A point given by its coordinates (multiplied by the given named *unit*, if any); lettered *label*.

        >>> b = Builder("demo", givens={"r": 2.0})
        >>> b["P"] if b.given_point("P", 1.0, 0.5, unit="r") else None
        Point(2.0, 1.0)
        """
        self.record("given", "given_point", (), (name,), {"x": x, "y": y, "unit": unit},
                    de or f"Punkt {name} gegeben", en or f"point {name} given", labels={name: label or name})
        return name

    def given_length(self, name: str, *, product: Sequence[str], factor: float = 1.0,
                     de: str | None = None, en: str | None = None) -> str:
        """A compass opening given as *factor* times the product of the named givens.

        >>> b = Builder("demo", givens={"r": 2.0, "rod_ratio": 5.0})
        >>> float(b[b.given_length("L", product=("rod_ratio", "r"))])
        10.0
        """
        if isinstance(product, str) or not isinstance(product, Sequence):
            raise InvalidParameter(f"given_length {name!r}: product is a list of names of givens, got {shown(product)}")
        self.record("given", "given_length", (), (name,), {"product": tuple(product), "factor": factor},
                    de or f"Länge {name} gegeben", en or f"length {name} given")
        return name

    def given_line(self, name: str, through: str, *, angle_deg: float, de: str | None = None,
                   en: str | None = None, role: str = "construction") -> str:
        """A line through a point at a given angle to the x axis (degrees, counter-clockwise).

        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("O", 0.0, 0.0)
        >>> b[b.given_line("axis", "O", angle_deg=0.0)].q
        Point(1.0, 0.0)
        """
        self.record("given", "given_line", (through,), (name,), {"angle_deg": angle_deg},
                    de or f"Gerade {name} durch {through} gegeben", en or f"line {name} through {through} given",
                    role=role)
        return name

    # -- straightedge and compass ----------------------------------------------
    def line(self, name: str, a: str, b: str, *, de: str | None = None, en: str | None = None,
             role: str = "construction") -> str:
        """The straightedge laid through two points.

        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 1.0, 1.0)
        >>> b[b.line("g", "A", "B")].direction()
        (0.7071067811865475, 0.7071067811865475)
        """
        self.record("straightedge", "line", (a, b), (name,), {},
                    de or f"Gerade durch {a} und {b}", en or f"line through {a} and {b}", role=role)
        return name

    def circle_through(self, name: str, center: str, through: str, *, de: str | None = None,
                       en: str | None = None, role: str = "construction") -> str:
        """The compass set in *center* and opened to *through*.

        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 3.0, 4.0)
        >>> b[b.circle_through("k", "A", "B")].radius
        5.0
        """
        self.record("compass", "circle_through", (center, through), (name,), {},
                    de or f"Kreis um {center} durch {through}", en or f"circle about {center} through {through}",
                    role=role)
        return name

    def circle_radius(self, name: str, center: str, length: str, *, de: str | None = None,
                      en: str | None = None, role: str = "construction") -> str:
        """The compass set in *center* with an opening carried over (a given or measured length).

        >>> b = Builder("demo", givens={"r": 1.5})
        >>> _ = b.given_point("O", 0.0, 0.0); _ = b.given_length("r", product=("r",))
        >>> b[b.circle_radius("k", "O", "r")].radius
        1.5
        """
        self.record("compass", "circle_radius", (center, length), (name,), {},
                    de or f"Kreis um {center} mit Halbmesser {length}",
                    en or f"circle about {center} with radius {length}", role=role)
        return name

    def circle_segment(self, name: str, center: str, a: str, b: str, *, de: str | None = None,
                       en: str | None = None, role: str = "construction") -> str:
        """The compass opened to the segment ab and set in *center*.

        >>> b = Builder("demo", givens={})
        >>> for n, x in (("A", 0.0), ("B", 2.0), ("C", 5.0)):
        ...     _ = b.given_point(n, x, 0.0)
        >>> b[b.circle_segment("k", "C", "A", "B")].radius
        2.0
        """
        self.record("compass", "circle_segment", (center, a, b), (name,), {},
                    de or f"Kreis um {center} mit Halbmesser {a}{b}",
                    en or f"circle about {center} with radius {a}{b}", role=role)
        return name

    def length_of(self, name: str, a: str, b: str, *, de: str | None = None, en: str | None = None) -> str:
        """The compass set to the segment ab, kept as an opening to carry elsewhere.

        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 0.0, 2.0)
        >>> float(b[b.length_of("ab", "A", "B")])
        2.0
        """
        self.record("compass", "length_of", (a, b), (name,), {},
                    de or f"Zirkel auf {a}{b} eingestellt", en or f"compass set to {a}{b}")
        return name

    def intersect(self, name: str | Sequence[str], c1: str, c2: str, *, rule: Rule | Sequence[Any],
                  de: str | None = None, en: str | None = None, role: str = "construction",
                  labels: Mapping[str, str] | None = None, provenance: Provenance | None = None) -> Any:
        """Mark where two curves cross; *rule* says which point (:mod:`construct.kernel.rules`).

        With two names, both points are kept: the first is the one the rule
        picks.  A drawn curve (polyline, French curve) may be crossed by a line.
        *provenance* overrides the one inherited from the inputs (a point read
        off a drawing by eye says so).

        >>> from construct.kernel.rules import left_of
        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 2.0, 0.0)
        >>> _ = b.circle_through("ka", "A", "B"); _ = b.circle_through("kb", "B", "A")
        >>> b[b.intersect("T", "ka", "kb", rule=left_of("A", "B"))]
        Point(1.0, 1.7320508075688772)
        >>> b.intersect("U", "ka", "kb", rule="left")
        Traceback (most recent call last):
        ...
        construct.kernel.errors.RuleError: step 6 (intersect: U where ka meets kb): a rule is a value like left_of('A', 'B') or a list like ['left', 'A', 'B'], got 'left'
        """
        names = (name,) if isinstance(name, str) else tuple(name)
        params = {"rule": rule, "both": len(names) == 2}
        self.record("intersect", "intersect", (c1, c2), names, params,
                    de or f"{' und '.join(names)} im Schnitt von {c1} und {c2}",
                    en or f"{' and '.join(names)} where {c1} meets {c2}", role=role, labels=labels,
                    provenance=provenance)
        return names[0] if len(names) == 1 else names

    def step_off(self, name: str, curve: str, start: str, length: str, *, rule: Rule | Sequence[Any],
                 de: str | None = None, en: str | None = None, role: str = "construction") -> str:
        """Dividers: step the opening *length* off along *curve* from *start*; prick the point.

        >>> from construct.kernel.rules import toward
        >>> b = Builder("demo", givens={"e": 0.5})
        >>> _ = b.given_point("O", 0.0, 0.0); _ = b.given_line("g", "O", angle_deg=0.0)
        >>> _ = b.given_length("e", product=("e",))
        >>> b[b.step_off("X", "g", "O", "e", rule=toward(dx=1.0))]
        Point(0.5, 0.0)
        """
        self.record("dividers", "step_off", (curve, start, length), (name,), {"rule": rule, "both": False},
                    de or f"{name}: Stechzirkel {length} von {start} auf {curve} abgetragen",
                    en or f"{name}: dividers {length} stepped off from {start} along {curve}", role=role)
        return name

    def pick(self, name: str, a: str, b: str, *, rule: Rule | Sequence[Any], de: str | None = None,
             en: str | None = None, role: str = "construction", labels: Mapping[str, str] | None = None) -> str:
        """Of two constructed points, the one *rule* names: a curve that is the envelope of two, point by point.

        The steam line of an indicator diagram is the lower of the admission
        line and the expansion hyperbola: both are constructed on an ordinate,
        the lower one is taken -- by a stored rule, so that a replay with other
        givens takes the right one wherever the cut-off falls.

        >>> from construct.kernel.rules import toward
        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("A", 1.0, 3.0); _ = b.given_point("B", 1.0, 2.0)
        >>> b[b.pick("low", "A", "B", rule=toward(dy=-1.0))]
        Point(1.0, 2.0)
        """
        self.record("intersect", "pick", (a, b), (name,), {"rule": rule},
                    de or f"{name}: von {a} und {b} der nach der Regel", en or f"{name}: of {a} and {b} the one the rule names",
                    role=role, labels=labels)
        return name

    # -- drawn curves and areas ----------------------------------------------------
    def polyline(self, name: str, points: Sequence[str], *, closed: bool = False, de: str | None = None,
                 en: str | None = None, role: str = "result") -> str:
        """The constructed points joined in order by the straightedge.

        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("ABC", ((0, 0), (1, 2), (2, 0))):
        ...     _ = b.given_point(n, x, y)
        >>> b[b.polyline("pl", "ABC")].y_at(0.5)
        1.0
        """
        pts = tuple(points)
        self.record("straightedge", "polyline", pts, (name,), {"closed": bool(closed)},
                    de or f"Linienzug durch {', '.join(pts)}", en or f"polyline through {', '.join(pts)}", role=role)
        return name

    def french_curve(self, name: str, axis: str, points: Sequence[str], tangents: Mapping[int, str] | None = None,
                     *, de: str | None = None, en: str | None = None, role: str = "result",
                     corners: Sequence[int] = ()) -> str:
        """A smooth curve drawn through *points* with a French curve, along *tangents* (point index -> line).

        It constructs nothing: checks on it state how far a drawn curve may stray.

        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("O", 0.0, 0.0); _ = b.given_line("x", "O", angle_deg=0.0)
        >>> for n, (x, y) in zip("ABC", ((0, 0), (1, 1), (2, 0))):
        ...     _ = b.given_point(n, x, y)
        >>> round(b[b.french_curve("c", "x", "ABC")].y_at(1.0), 12)
        1.0
        >>> b[b.french_curve("v", "x", "ABC", corners=(1,))].y_at(0.5)   # laid anew at the corner B
        0.5
        """
        tangents = dict(tangents or {})
        at = sorted(tangents)
        params: dict[str, Any] = {"points": len(points), "tangent_at": tuple(at)}
        if corners:  # only when asked: the protocols of smooth curves stay as they were
            params["corners"] = tuple(sorted(int(i) for i in corners))
        self.record("curve", "french_curve", (axis, *points, *(tangents[i] for i in at)), (name,), params,
                    de or "Kurve mit dem Kurvenlineal gezogen", en or "curve drawn with a French curve", role=role)
        return name

    def parabola_envelope(self, name: str, e: str, d: str, f: str, *, de: str | None = None,
                          en: str | None = None, role: str = "result") -> str:
        """The parabola touching DE at E and DF at F (the envelope of the joins of equal divisions).

        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("EDF", ((0, 1), (1, -1), (2, 1))):
        ...     _ = b.given_point(n, x, y)
        >>> round(b[b.parabola_envelope("p", "E", "D", "F")].y_at(1.0), 12)   # half-way to D
        0.0
        """
        self.record("curve", "parabola_envelope", (e, d, f), (name,), {},
                    de or f"Parabel an {e}{d} und {d}{f}", en or f"parabola touching {e}{d} and {d}{f}", role=role)
        return name

    def area_between(self, name: str, upper: str, lower: str, start: str, end: str, *, hatch_deg: float | None = None,
                     de: str | None = None, en: str | None = None, role: str = "result") -> str:
        """The region between two graphs over the x axis, from the abscissa of *start* to that of *end*.

        Split where the graphs cross; pieces where *upper* is above carry the sign +1.
        *hatch_deg* is the direction of its hatching (90: vertical, as the books hatch force areas).

        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("ABCD", ((0, 1), (2, 1), (0, 0), (2, 0))):
        ...     _ = b.given_point(n, x, y)
        >>> _ = b.line("top", "A", "B"); _ = b.line("bottom", "C", "D")
        >>> b[b.area_between("F", "top", "bottom", "A", "B")].area
        2.0
        """
        self.record("intersect", "area_between", (upper, lower, start, end), (name,),
                    {} if hatch_deg is None else {"hatch_deg": float(hatch_deg)},
                    de or f"Fläche zwischen {upper} und {lower}", en or f"area between {upper} and {lower}", role=role)
        return name

    def planimeter(self, name: str, area: str, *, base: tuple[str, str] | None = None, de: str | None = None,
                   en: str | None = None) -> str:
        """A planimeter run round *area*: its signed area, or with *base* = (a, b) the mean height over ab.

        The planimeter measures; its provenance says so (``approximate``, the
        instrument's reading).  The mean height is a compass opening (a Length).

        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("ABCD", ((0, 1), (2, 1), (0, 0), (2, 0))):
        ...     _ = b.given_point(n, x, y)
        >>> _ = b.line("top", "A", "B"); _ = b.line("bottom", "C", "D")
        >>> _ = b.area_between("F", "top", "bottom", "A", "B")
        >>> b[b.planimeter("f", "F")], float(b[b.planimeter("h", "F", base=("C", "D"))])
        (2.0, 1.0)
        """
        prov = Provenance("approximate", "planimeter")
        if base is None:
            self.record("planimeter", "planimeter", (area,), (name,), {},
                        de or f"Fläche {area} planimetriert", en or f"area {area} measured with a planimeter",
                        provenance=prov)
        else:
            a, b = base
            self.record("planimeter", "planimeter_height", (area, a, b), (name,), {},
                        de or f"mittlere Höhe von {area} über {a}{b} (Planimeter)",
                        en or f"mean height of {area} over {a}{b} (planimeter)", provenance=prov)
        return name


def _check_given(name: Any, value: Any) -> None:
    """A given is a finite number (or, for a sweep, finite numbers), named by a string."""
    if not isinstance(name, str) or not name:
        raise InvalidParameter(f"givens are named by non-empty strings, got {shown(name)}")
    values = value if isinstance(value, (list, tuple, np.ndarray)) else (value,)
    for v in np.ravel(np.asarray(values, dtype=object)):
        as_float(v, f"the given {shown(name)}")


def _record_problem(tool: Any, inputs: Any, outputs: Any, de: Any, en: Any, role: Any, labels: Any,
                    provenance: Any) -> str | None:
    """What is wrong with the fields of a step to record (None: nothing); the same rules a protocol file obeys.

    Every step of every build passes here: the usual types are let through first, without the ABC checks.
    """
    if tool not in TOOLS:
        return f"unknown instrument {shown(tool)}; the instruments are {', '.join(TOOLS)}"
    if role not in ROLES:
        return f"unknown role {shown(role)}; the roles are {', '.join(ROLES)}"
    for what, names in (("inputs", inputs), ("outputs", outputs)):
        if type(names) is not tuple and type(names) is not list and (
                isinstance(names, str) or not isinstance(names, Sequence)):
            return f"{what} are a list of object names, got {shown(names)}"
    if not isinstance(de, str) or not isinstance(en, str):
        return f"captions are text, got {shown(de)} and {shown(en)}"
    if labels is not None and (not isinstance(labels, Mapping) or
                               not all(isinstance(k, str) and isinstance(v, str) for k, v in labels.items())):
        return f"labels map object names to text, got {shown(labels)}"
    if provenance is not None and not isinstance(provenance, Provenance):
        return f"a provenance is a Provenance, got {shown(provenance)}"
    return None
