"""The one evaluation path of a protocol: each step compiled once into an entry, entries run by
:func:`run_step` while building and by the replay loop while replaying, and the :class:`Replay` that a replay
returns -- the objects by name, for one set of givens or for a sweep of many.

Part of :mod:`construct.kernel.protocol`, which re-exports these names; :class:`~construct.kernel.protocol.Protocol`
compiles itself through :func:`compile_step` and folds its steps with :func:`run_step`.

>>> object_json(Point(1.0, 2.0))
{'type': 'point', 'x': 1.0, 'y': 2.0}
"""

from __future__ import annotations

import math
import numbers
import operator
from types import MappingProxyType
from collections.abc import Mapping
from typing import Any, Callable, NamedTuple

import numpy as np

from .areas import Area
from .curves import BezierCurve, Polyline
from .errors import (ConstructError, InvalidParameter, MissingGiven, ProtocolFormatError, RuleError, StepError,
                     UnknownObject, WrongInput)
from .geometry import SCALAR, Circle, Length, Line, Point, Sweep, ArrayMath, take, take_all
from .ops import ACCEPTS, OPS, elementwise
from .numeric import as_float, shown
from .rules import as_rule
from .step import Step

__all__ = ["CompiledStep", "Program", "loop_entry", "compile_step", "check_kinds", "step_failure", "run_step", "sweep_givens",
           "TakenSet", "Replay", "object_json", "STEP_FAILURES"]

# --------------------------------------------------------------------------
# The one evaluation path.  A step is compiled once into an entry
# (function, input slots, output slots, params, rule slots, step); building
# and replaying both run entries through run_step / the replay loop below,
# which differ only in where they keep the objects (a dict by name while
# building, a list by slot while replaying).
# --------------------------------------------------------------------------


class CompiledStep(NamedTuple):
    """A step ready to run: its op's function, where its inputs and outputs are kept, its parsed parameters.

    *ins*, *outs* and *refs* (the points a rule names) are object names while building and list slots while
    replaying.  A tuple underneath, so that the replay loop unpacks it at tuple speed.
    """

    fn: Callable[..., tuple]
    ins: tuple
    outs: tuple
    params: dict[str, Any]
    refs: tuple
    op: Any  # the op table's entry (construct.kernel.ops.Op)
    step: Step


class Program(NamedTuple):
    """A protocol compiled for replay: one entry per step, the object name of every list slot, and the loop's
    own form of each entry (:func:`loop_entry`)."""

    entries: tuple[CompiledStep, ...]
    names: tuple[str, ...]
    loop: tuple[tuple, ...]


def loop_entry(entry: CompiledStep) -> tuple:
    """What the scalar replay loop needs of an entry, each part ready to run in C: (function, inputs of the
    environment, first and end slot of the outputs, parameters, points of the rule).

    Inputs and rule points are gathered by ``operator.itemgetter`` -- a tuple of several slots, a slice for one
    or none (a list) -- instead of a comprehension per step (a call of its own in this Python); the outputs are
    consecutive slots (made so by Protocol.program), set by one slice assignment.
    """
    def getter(slots: tuple) -> Callable[[list], Any]:
        if len(slots) > 1:
            return operator.itemgetter(*slots)
        first = slots[0] if slots else 0
        return operator.itemgetter(slice(first, first + len(slots)))

    first, end = (entry.outs[0], entry.outs[-1] + 1) if entry.outs else (0, 0)
    return (entry.fn, getter(entry.ins), first, end, entry.params, getter(entry.refs))


def compile_step(step: Step, slot: Mapping[str, Any] | None = None) -> CompiledStep:
    """The entry for *step*; *slot* maps names to list slots (None: objects are kept by name).

    Raises ProtocolFormatError for an unknown operation, WrongInput for
    parameters the op does not take (or of the wrong kind), UnknownObject for a
    name no earlier step made and RuleError for a malformed rule.
    """
    op = OPS.get(step.op)
    if op is None:
        raise ProtocolFormatError(f"step {step.index}: unknown operation {step.op!r}; known: {', '.join(sorted(OPS))}")

    def unknown(name: str) -> UnknownObject:
        return UnknownObject(f"step {step.index} ({step.tool}: {step.caption.brief}) uses {name!r} before any step made it",
                             name=name, step_index=step.index, tool=step.tool, op=step.op)

    if slot is not None:
        missing = [n for n in step.inputs if n not in slot]
        if missing:
            raise unknown(missing[0])
    problem = op.check_params(step.params)
    if problem:
        raise WrongInput(f"step {step.index} ({step.tool}: {step.caption.brief}): {step.op} {problem}",
                         step_index=step.index, tool=step.tool, op=step.op)
    params = dict(step.params)
    refs: tuple[str, ...] = ()
    if op.rule:
        try:
            rule = as_rule(params.get("rule"))
        except RuleError as exc:
            raise exc.at_step(step.index, step.tool, step.op, step.caption.brief) from None
        params["rule"] = rule
        refs = rule.refs
    if slot is None:  # objects are kept by name
        ins, ref_slots = tuple(step.inputs), refs
    else:
        missing = [n for n in refs if n not in slot]
        if missing:
            raise unknown(missing[0])
        ins, ref_slots = tuple(slot[n] for n in step.inputs), tuple(slot[n] for n in refs)
    return CompiledStep(op.fn, ins, step.outputs, params, ref_slots, op, step)


def check_kinds(step: Step, op: Any, refs: tuple[str, ...], kinds: dict[str, str]) -> None:
    """Does *step* fit its op's declared inputs and outputs, given the kinds of the objects made before it?

    Records the kinds of its outputs in *kinds*.  This is the load-time check of a
    protocol (a Builder checks the evaluated objects themselves as it goes).
    """
    def wrong(problem: str) -> WrongInput:
        return WrongInput(f"step {step.index} ({step.tool}: {step.caption.brief}): {step.op} {problem}",
                          step_index=step.index, tool=step.tool, op=step.op)

    want = op.input_kinds(step.params, len(step.inputs))
    if isinstance(want, str):
        raise wrong(want)
    for i, (name, kind) in enumerate(zip(step.inputs, want), start=1):
        if kinds[name] not in ACCEPTS[kind]:
            raise wrong(f"input {i} must be a {kind}, {name!r} is a {kinds[name]}")
    for name in refs:
        if kinds[name] != "point":
            raise wrong(f"rule names {name!r}, a {kinds[name]}; a rule names points")
    made = op.output_kinds(step.params)
    if len(made) != len(step.outputs):
        raise wrong(f"makes {len(made)} object{'s' if len(made) != 1 else ''} ({', '.join(made)}), "
                    f"the step names {len(step.outputs)}: {', '.join(step.outputs) or 'none'}")
    for name, kind in zip(step.outputs, made):
        kinds[name] = kind


def step_failure(step: Step, exc: BaseException) -> ConstructError:
    """The error a failing step raises, the same while building and while replaying."""
    where = (step.index, step.tool, step.op, step.caption.brief)
    if isinstance(exc, StepError):
        return exc.at_step(*where)
    if isinstance(exc, KeyError):
        return MissingGiven(f"step {step.index} ({step.tool}: {step.caption.brief}) needs the given {exc.args[0]!r}",
                            step_index=step.index, tool=step.tool, op=step.op)
    if isinstance(exc, (TypeError, AttributeError, ValueError, IndexError)):
        return WrongInput(f"step {step.index} ({step.tool}: {step.caption.brief}): operation {step.op!r} "
                          f"cannot use its inputs {', '.join(step.inputs)}: {exc}",
                          step_index=step.index, tool=step.tool, op=step.op)
    if isinstance(exc, ConstructError):
        return StepError(f"step {step.index} ({step.tool}: {step.caption.brief}): {exc}",
                         step_index=step.index, tool=step.tool, op=step.op)
    raise exc


#: What an op raises when its step cannot be carried out: turned into the step's error by step_failure.
STEP_FAILURES = (ConstructError, KeyError, TypeError, AttributeError, ValueError, IndexError)


def run_step(entry: CompiledStep, env: Any, givens: Mapping[str, Any], xp: Any = SCALAR) -> tuple:
    """Evaluate one compiled step on the objects in *env*; store and return its outputs."""
    fn, ins, outs, params, refs, op, step = entry
    if xp is not SCALAR and not op.vector:
        fn = elementwise(fn)
    try:
        values = fn([env[k] for k in ins], params, givens, [env[k] for k in refs], xp)
    except STEP_FAILURES as exc:
        raise step_failure(step, exc) from exc
    for k, v in zip(outs, values):
        env[k] = v
    return values


def sweep_givens(givens: Mapping[str, Any]) -> tuple[dict[str, Any], Any]:
    """Givens as floats, or as equally long 1-d arrays when any is an array; and the namespace to use.

    >>> g, xp = sweep_givens({"r": 1, "rod_ratio": [4.0, 5.0]})
    >>> g["r"], g["rod_ratio"], xp.n
    (1.0, array([4., 5.]), 2)
    """
    arrays = {k: _given_array(k, v) for k, v in givens.items() if isinstance(v, (np.ndarray, list, tuple))}
    if not arrays:
        return {k: _given_number(k, v) for k, v in givens.items()}, SCALAR
    try:
        shaped = np.broadcast_arrays(*arrays.values())
    except ValueError as exc:
        raise InvalidParameter(f"swept givens {', '.join(arrays)} do not broadcast together: {exc}") from None
    out: dict[str, Any] = {k: _given_number(k, v) for k, v in givens.items() if k not in arrays}
    for k, a in zip(arrays, shaped):
        out[k] = np.ascontiguousarray(a, dtype=float).reshape(-1)
    n = next(iter(out[k] for k in arrays)).size
    if n == 0:
        raise InvalidParameter("a sweep needs at least one set of givens")
    return out, ArrayMath(n)


def _given_number(name: Any, value: Any) -> float:
    """A given as a float: a finite real number, else an InvalidParameter naming it."""
    if type(value) is float and math.isfinite(value):
        return value
    return as_float(value, f"the given {shown(name)}")


def _given_array(name: Any, value: Any) -> Any:
    """A swept given as a 1-d array of finite floats, else an InvalidParameter naming it."""
    numeric = (value.dtype.kind in "fiu" if isinstance(value, np.ndarray)
               else all(isinstance(v, numbers.Real) and not isinstance(v, bool) for v in value))
    if not numeric:
        raise InvalidParameter(f"the swept given {shown(name)} must be numbers, got {shown(value)}")
    if not isinstance(value, np.ndarray) or value.dtype.kind == "O":
        for v in value:  # a huge int has no float: refused here, not by an OverflowError in numpy
            as_float(v, f"the swept given {shown(name)}")
    a = np.asarray(value, dtype=float)
    if not np.isfinite(a).all():
        raise InvalidParameter(f"the swept given {name!r} must be finite numbers, got {a[~np.isfinite(a)][:3].tolist()}")
    return a


class TakenSet(Mapping[str, Any]):
    """The objects of set *i* of a sweep, each taken from the sweep's arrays when first looked up.

    A check reads a few dozen of a figure's thousand objects: taking them all
    for every set of a 1,000-set sweep was most of the time the sweep's
    checks took.  The sets of :meth:`Replay.sets` share *columns*: an object
    looked up in one set is taken for all *n* of them at once.
    """

    __slots__ = ("_source", "_i", "_at", "_n", "_columns")

    def __init__(self, source: Mapping[str, Any], i: int, columns: dict[str, list] | None = None, n: int = 0) -> None:
        self._source, self._i = source, i
        self._columns: dict[str, list] = {} if columns is None else columns
        self._n, self._at = (n, i) if columns is not None else (0, 0)

    def __getitem__(self, name: str) -> Any:
        try:
            return self._columns[name][self._at]
        except KeyError:
            v = self._source[name]
            column = self._columns[name] = take_all(v, self._n) if self._n else [take(v, self._i)]
            return column[self._at]

    def __contains__(self, name: object) -> bool:
        return name in self._source

    def __iter__(self):
        return iter(self._source)

    def __len__(self) -> int:
        return len(self._source)

    def __reduce__(self):
        return (dict, (list(self.items()),))


class Replay(Mapping[str, Any]):
    """The objects a replay made, by name (arrays of coordinates in a sweep)."""

    __slots__ = ("protocol", "_objects", "_givens", "size", "elementwise")

    def __init__(self, protocol: Any, objects: dict[str, Any], givens: Mapping[str, Any], size: int = 0,
                 elementwise: tuple[str, ...] = ()):
        self.protocol = protocol
        self._objects = objects
        self._givens = dict(givens)
        #: 0 for a plain replay, else the number of sets of givens swept.
        self.size = size
        #: The ops a sweep ran once per set of givens, having no array form (none of the op table's).
        self.elementwise = elementwise

    @property
    def givens(self) -> Mapping[str, Any]:
        return MappingProxyType(self._givens)

    def __getitem__(self, name: str) -> Any:
        try:
            return self._objects[name]
        except (KeyError, TypeError):  # TypeError: an unhashable "name"
            raise UnknownObject(f"the replay of {self.protocol.construction!r} has no object {shown(name)}",
                                name=name) from None

    def __contains__(self, name: object) -> bool:  # without building the error a miss in __getitem__ makes
        try:
            return name in self._objects
        except TypeError:
            return False

    def get(self, name: object, default: Any = None) -> Any:
        try:
            return self._objects.get(name, default)
        except TypeError:
            return default

    def __iter__(self):
        return iter(self._objects)

    def items(self):  # the objects' own view: a drawing walks tens of thousands (Mapping's asks each by name)
        return self._objects.items()

    def values(self):
        return self._objects.values()

    def __len__(self) -> int:
        return len(self._objects)

    def __reduce__(self):
        return (Replay, (self.protocol, self._objects, self._givens, self.size, self.elementwise))

    def __repr__(self) -> str:
        kind = f"sweep of {self.size}" if self.size else "replay"
        return f"<Replay ({kind}) of {self.protocol.construction!r}: {len(self._objects)} objects>"

    def take(self, i: int, *, whole: bool = False) -> "Replay":
        """Set *i* of a sweep as a plain replay (a plain replay is its own only set).

        Its objects are taken from the sweep's arrays as they are looked up (a check reads a few of them);
        *whole* takes them all at once, for a reader of every object (a drawing reads each several times).
        """
        if isinstance(i, bool) or not isinstance(i, numbers.Integral):
            raise InvalidParameter(f"a set of a sweep is taken by its number, got {shown(i)}")
        if not self.size:
            return self
        if not -self.size <= i < self.size:
            raise InvalidParameter(f"sweep of {self.size} has no set {i}")
        i %= self.size
        objects = {n: take(v, i) for n, v in self._objects.items()} if whole else TakenSet(self._objects, i)
        return Replay(self.protocol, objects, {k: take(v, i) for k, v in self._givens.items()})

    def sets(self) -> list["Replay"]:
        """Every set of a sweep as :meth:`take` gives it (a plain replay is its own only set), their objects taken
        as they are looked up, each for all the sets at once (the checks of a sweep read the same objects of
        every set).

        >>> from construct.kernel.instruments import Builder
        >>> b = Builder("demo", givens={"r": 1.0})
        >>> _ = b.given_point("A", 1.0, 0.0, unit="r")
        >>> [one["A"].x for one in b.protocol().replay({"r": np.array([2.0, 3.0])}).sets()]
        [2.0, 3.0]
        """
        if not self.size:
            return [self]
        columns: dict[str, list] = {}
        givens = {k: take_all(v, self.size) for k, v in self._givens.items()}
        return [Replay(self.protocol, TakenSet(self._objects, i, columns, self.size),
                       {k: v[i] for k, v in givens.items()}) for i in range(self.size)]

    def made_by(self) -> dict[str, Step]:
        """The step that made each object (:attr:`Protocol.makers <construct.kernel.protocol.Protocol.makers>`,
        a copy of it)."""
        return dict(self.protocol.makers)

    def objects_json(self) -> dict[str, Any]:
        return {name: object_json(obj) for name, obj in self._objects.items()}


def object_json(obj: Any) -> dict[str, Any]:
    """A drawn object as plain JSON data (the ``objects`` table of protocol.json).

    >>> object_json(Point(1.0, 2.0))
    {'type': 'point', 'x': 1.0, 'y': 2.0}
    """
    if isinstance(obj, Point):
        return {"type": "point", "x": obj.x, "y": obj.y}
    if isinstance(obj, Line):
        return {"type": "line", "x1": obj.p.x, "y1": obj.p.y, "x2": obj.q.x, "y2": obj.q.y}
    if isinstance(obj, Circle):
        return {"type": "circle", "cx": obj.center.x, "cy": obj.center.y, "r": obj.radius}
    if isinstance(obj, Length):
        return {"type": "length", "value": obj.value}
    if isinstance(obj, (BezierCurve, Polyline, Area)):
        return obj.as_json()
    if isinstance(obj, float):
        return {"type": "number", "value": obj}
    raise ProtocolFormatError(f"not a drawable object: {obj!r}" if not isinstance(obj, Sweep)
                              else "a sweep's objects have no JSON form; write a single replay")
