"""The construction protocol: steps as data, replay as a fold.

A :class:`Protocol` is an ordered tuple of frozen :class:`Step` records.  Each
step names its instrument (``tool``), its operation (``op``), the objects it
reads (``inputs``) and makes (``outputs``), its parameters, a German and an
English caption and the provenance of what it makes.  Replaying folds the
steps over a table of named objects; replaying with other givens re-evaluates
the same steps, so every branch is chosen by the same stored *rule*.

>>> from construct.kernel.instruments import Builder
>>> b = Builder("demo", givens={"r": 2.0})
>>> O = b.given_point("O", 0.0, 0.0)
>>> r = b.given_length("r", product=("r",))
>>> k = b.circle_radius("k", O, r)
>>> axis = b.given_line("axis", O, angle_deg=0.0)
>>> A = b.intersect("A", axis, k, rule=("toward", "O", None, -1.0, 0.0))
>>> proto = b.protocol()
>>> proto.replay({"r": 2.0})["A"]
Point(-2.0, 0.0)
>>> Protocol.from_json(proto.to_json()).replay({"r": 5.0})["A"]
Point(-5.0, 0.0)
"""

from __future__ import annotations

import functools
import json
import math
import numbers
import operator
import os
from dataclasses import dataclass
from types import MappingProxyType
from collections.abc import Mapping, Sequence
from typing import Any, Callable, NamedTuple

import numpy as np

from .areas import Area
from .curves import BezierCurve, Polyline
from .errors import (ConstructError, InvalidParameter, MissingGiven, ProtocolFormatError, RuleError, StepError,
                     UnknownObject, WrongInput)
from .geometry import SCALAR, Circle, Length, Line, Point, Sweep, ArrayMath, take
from .ops import ACCEPTS, OPS, elementwise
from .protocol_file import (KNOWN_FORMATS, PROTOCOL_FILE_FORMAT, PROTOCOL_FORMAT, PROVENANCE_KINDS, ROLES, TOOLS,
                            check_format, frozen, parse_protocol_json, read_protocol_bytes, step_fields)
from .numeric import as_float, shown
from .rules import as_rule

__all__ = [
    "PROVENANCE_KINDS",
    "TOOLS",
    "ROLES",
    "KNOWN_FORMATS",
    "Caption",
    "Provenance",
    "Step",
    "Protocol",
    "Replay",
    "run_step",
    "compile_step",
    "CompiledStep",
    "Program",
    "object_json",
]

# PROVENANCE_KINDS, TOOLS, ROLES and the formats are defined with the file checks (protocol_file).


@dataclass(frozen=True, slots=True)
class Caption:
    """What a step does, in the books' German and in English."""

    de: str
    en: str

    @property
    def brief(self) -> str:
        """The English caption as an error message quotes it: on one line, at most 120 characters.

        >>> Caption("", "a\\nvery " + "long " * 40).brief[-12:]
        'ong long lo…'
        """
        text = " ".join(self.en.split())
        return text if len(text) <= 120 else text[:119] + "…"


@dataclass(frozen=True, slots=True)
class Provenance:
    """How trustworthy an object is.

    ``exact`` objects come from Euclidean steps only; ``approximate`` ones from
    a Euclidean construction of an approximate result (``method`` names it,
    ``error`` states its known error, in radians for angles); ``neusis`` from
    the marked ruler; ``trial`` from dividers set by trial to a tolerance.
    """

    kind: str
    method: str | None = None
    error: float | None = None

    def __post_init__(self) -> None:
        if self.kind not in PROVENANCE_KINDS:
            raise InvalidParameter(f"provenance kind must be one of {PROVENANCE_KINDS}, got {self.kind!r}")

    def combine(self, other: "Provenance") -> "Provenance":
        """The provenance of an object made from two others: the weaker one wins."""
        order = {"given": 0, "exact": 1, "approximate": 2, "neusis": 2, "trial": 3}
        if order[other.kind] > order[self.kind]:
            return other
        if order[other.kind] == order[self.kind] and self.kind == "approximate" and other.error is not None:
            err = max(abs(self.error or 0.0), abs(other.error))
            return Provenance(self.kind, self.method or other.method, err)
        return self


EXACT = Provenance("exact")
GIVEN = Provenance("given")


@dataclass(frozen=True, slots=True)
class Step:
    """One instrument use: data only, evaluated by the op table entry ``OPS[op]``."""

    index: int
    tool: str
    op: str
    inputs: tuple[str, ...]
    outputs: tuple[str, ...]
    params: Mapping[str, Any]
    caption: Caption
    provenance: Provenance = EXACT
    group: tuple[str, ...] = ()
    #: "result" objects are drawn heavy (crank circle, piston positions),
    #: "construction" ones thin, "auxiliary" ones may be hidden in a plate.
    role: str = "construction"
    #: Letters to print beside output objects in the figure: (name, label).
    labels: tuple[tuple[str, str], ...] = ()

    def as_dict(self) -> dict[str, Any]:
        d: dict[str, Any] = {
            "index": self.index,
            "tool": self.tool,
            "op": self.op,
            "inputs": list(self.inputs),
            "outputs": list(self.outputs),
            "params": jsonable(dict(self.params)),
            "caption": {"de": self.caption.de, "en": self.caption.en},
            "provenance": {
                "kind": self.provenance.kind,
                "method": self.provenance.method,
                "error": self.provenance.error,
            },
            "group": list(self.group),
            "role": self.role,
        }
        if self.labels:
            d["labels"] = {name: text for name, text in self.labels}
        return d

    def compact_dict(self, group_ids: Mapping[tuple[str, ...], int]) -> dict[str, Any]:
        """As :meth:`as_dict` for the protocol file: defaults left out, the group path as its number."""
        d = self.as_dict()
        if not d["params"]:
            del d["params"]
        if self.provenance == EXACT:
            del d["provenance"]
        else:
            d["provenance"] = {k: v for k, v in d["provenance"].items() if v is not None}
        if self.role == "construction":
            del d["role"]
        if self.group:
            d["group"] = group_ids[self.group]
        else:
            del d["group"]
        return d

    def __reduce__(self):
        return (Step.from_dict, (self.as_dict(),))

    @classmethod
    def from_dict(cls, d: Mapping[str, Any]) -> "Step":
        """A step from its dict form (:meth:`as_dict`), every field checked (ProtocolFormatError names it)."""
        return cls._from_fields(step_fields(d, None))

    @classmethod
    def _from_fields(cls, f: Mapping[str, Any]) -> "Step":
        kind, method, error = f["provenance"]
        return cls(index=f["index"], tool=f["tool"], op=f["op"], inputs=f["inputs"], outputs=f["outputs"],
                   params=f["params"], caption=Caption(*f["caption"]), provenance=Provenance(kind, method, error),
                   group=f["group"], role=f["role"], labels=f["labels"])


def jsonable(value: Any) -> Any:
    as_json = getattr(value, "as_json", None)
    if as_json is not None:  # a Rule
        return as_json()
    if isinstance(value, (tuple, list)):
        return [jsonable(v) for v in value]
    if isinstance(value, Mapping):
        return {str(k): jsonable(v) for k, v in value.items()}
    return value




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
    own form of each entry (:func:`_loop_entry`)."""

    entries: tuple[CompiledStep, ...]
    names: tuple[str, ...]
    loop: tuple[tuple, ...]


def _loop_entry(entry: CompiledStep) -> tuple:
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
_STEP_FAILURES = (ConstructError, KeyError, TypeError, AttributeError, ValueError, IndexError)


def run_step(entry: CompiledStep, env: Any, givens: Mapping[str, Any], xp: Any = SCALAR) -> tuple:
    """Evaluate one compiled step on the objects in *env*; store and return its outputs."""
    fn, ins, outs, params, refs, op, step = entry
    if xp is not SCALAR and not op.vector:
        fn = elementwise(fn)
    try:
        values = fn([env[k] for k in ins], params, givens, [env[k] for k in refs], xp)
    except _STEP_FAILURES as exc:
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


def _shown(value: Any) -> str:
    return shown(value)


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
        raise InvalidParameter(f"the swept given {shown(name)} must be numbers, got {_shown(value)}")
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
    checks took.
    """

    __slots__ = ("_source", "_i", "_taken")

    def __init__(self, source: Mapping[str, Any], i: int) -> None:
        self._source, self._i, self._taken = source, i, {}

    def __getitem__(self, name: str) -> Any:
        try:
            return self._taken[name]
        except KeyError:
            value = self._taken[name] = take(self._source[name], self._i)
            return value

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

    def __init__(self, protocol: "Protocol", objects: dict[str, Any], givens: Mapping[str, Any], size: int = 0,
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
            raise UnknownObject(f"the replay of {self.protocol.construction!r} has no object {_shown(name)}",
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
            raise InvalidParameter(f"a set of a sweep is taken by its number, got {_shown(i)}")
        if not self.size:
            return self
        if not -self.size <= i < self.size:
            raise InvalidParameter(f"sweep of {self.size} has no set {i}")
        i %= self.size
        objects = {n: take(v, i) for n, v in self._objects.items()} if whole else TakenSet(self._objects, i)
        return Replay(self.protocol, objects, {k: take(v, i) for k, v in self._givens.items()})

    def made_by(self) -> dict[str, Step]:
        """The step that made each object."""
        return {name: step for step in self.protocol.steps for name in step.outputs}

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


@dataclass(frozen=True)
class Protocol:
    """A construction as data: its name, its parameters and its steps."""

    construction: str
    params: Mapping[str, Any]
    steps: tuple[Step, ...]
    #: The givens a replay may change without changing the steps.
    givens: tuple[str, ...] = ()

    def __repr__(self) -> str:
        return f"<Protocol {self.construction!r}: {len(self.steps)} steps, givens {', '.join(self.givens) or '-'}>"

    def __reduce__(self):
        return (_unpickle, (self.as_dict(with_objects=False),))

    # -- replay -------------------------------------------------------------
    @functools.cached_property
    def program(self) -> Program:
        """The steps compiled for replay, once per protocol (the load-time check of ops, kinds and names)."""
        slot: dict[str, int] = {}
        kinds: dict[str, str] = {}
        entries = []
        for step in self.steps:
            for name in step.outputs:
                if name in slot:
                    raise ProtocolFormatError(f"step {step.index} makes {name!r} a second time")
            entry = compile_step(step, slot)
            check_kinds(step, entry.op, entry.params["rule"].refs if entry.op.rule else (), kinds)
            outs = []
            for name in step.outputs:
                slot[name] = len(slot)
                outs.append(slot[name])
            entries.append(entry._replace(outs=tuple(outs)))
        return Program(tuple(entries), tuple(slot), tuple(_loop_entry(e) for e in entries))

    def replay(self, givens: Mapping[str, Any] | None = None, *, upto: int | None = None) -> Replay:
        """Evaluate the steps (all, or 1..upto) with *givens*; return the objects by name.

        Givens that are arrays (or lists) make the replay a sweep: one value
        per set of givens in every coordinate.
        """
        if givens is not None and not isinstance(givens, Mapping):
            raise InvalidParameter(f"givens are a mapping of names to numbers, got {_shown(givens)}")
        if upto is not None and (isinstance(upto, bool) or not isinstance(upto, numbers.Integral)):
            raise InvalidParameter(f"upto is a step number, got {_shown(upto)}")
        givens, xp = sweep_givens(dict(self.params.get("givens", {}) if givens is None else givens))
        entries, names, loop = self.program
        env: list[Any] = [None] * len(names)
        stop = len(entries) if upto is None else max(0, min(upto, len(entries)))
        if xp is SCALAR:
            # run_step written out, on the loop's own form of the entries: the 18-part crank replays 365 steps in
            # half a millisecond, and a call per step would be a tenth of that.  The same op functions, the same
            # failure mapping.
            try:
                for fn, ins, first, end, params, refs in loop[:stop] if upto is not None else loop:
                    env[first:end] = fn(ins(env), params, givens, refs(env), SCALAR)
            except _STEP_FAILURES as exc:
                # the failing step is the first whose outputs are not made (every step makes at least one)
                failed = next(e for e in entries if env[e.outs[0]] is None)
                raise step_failure(failed.step, exc) from exc
            if upto is None or stop == len(entries):
                return Replay(self, dict(zip(names, env)), givens)
            return Replay(self, {names[k]: env[k] for k in range(len(names)) if env[k] is not None}, givens)
        for i in range(stop):
            run_step(entries[i], env, givens, xp)
        objects = {names[k]: env[k] for k in range(len(names)) if env[k] is not None}
        by_element = tuple(dict.fromkeys(e.step.op for e in entries[:stop] if not e.op.vector))
        return Replay(self, objects, givens, xp.n, by_element)

    # -- inspection ---------------------------------------------------------
    def instrument_counts(self) -> dict[str, int]:
        counts: dict[str, int] = {}
        for s in self.steps:
            counts[s.tool] = counts.get(s.tool, 0) + 1
        return dict(sorted(counts.items()))

    def groups(self) -> list[tuple[tuple[str, ...], int, int]]:
        """Each group path with the first and last step index (1-based) it spans."""
        spans: dict[tuple[str, ...], list[int]] = {}
        for s in self.steps:
            for depth in range(1, len(s.group) + 1):
                key = s.group[:depth]
                span = spans.setdefault(key, [s.index, s.index])
                span[1] = s.index
        return [(k, a, b) for k, (a, b) in spans.items()]

    # -- JSON ---------------------------------------------------------------
    def as_dict(self, replay: Replay | None = None, *, with_objects: bool = True) -> dict[str, Any]:
        params = dict(self.params)
        d: dict[str, Any] = {"format": PROTOCOL_FORMAT, "construction": self.construction}
        if with_objects:
            if replay is None:
                replay = self.replay()
            params["givens"] = dict(replay.givens)  # the givens this replay was made with
        d.update({
            "params": jsonable(params),
            "givens": list(self.givens),
            "instruments": self.instrument_counts(),
            "steps": [s.as_dict() for s in self.steps],
        })
        if with_objects:
            d["objects"] = replay.objects_json()
        return d

    def to_json(self, replay: Replay | None = None) -> str:
        """The protocol file: one line per step and per object, so that a diff names what changed, compactly.

        >>> from construct.kernel.instruments import Builder
        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("A", 0.0, 0.0)
        >>> with b.group("the point"):
        ...     _ = b.given_point("B", 1.0, 0.0)
        >>> print(b.protocol().to_json())  # doctest: +ELLIPSIS
        {"format": "construct-protocol/2", "construction": "demo", ...
         "groups": [
          ["the point"]
         ],
         "steps": [
          {"index": 1, "tool": "given", "op": "given_point", ...},
          {"index": 2, ..., "group": 0, ...}
         ],
         "objects": {
          "A": {"type": "point", "x": 0.0, "y": 0.0},
          "B": {"type": "point", "x": 1.0, "y": 0.0}
         }}
        <BLANKLINE>
        """
        d = self.as_dict(replay)
        objects = d.pop("objects")
        del d["steps"]
        group_ids: dict[tuple[str, ...], int] = {}
        for st in self.steps:
            if st.group and st.group not in group_ids:
                group_ids[st.group] = len(group_ids)
        d["format"] = PROTOCOL_FILE_FORMAT
        d["groups"] = [list(g) for g in group_ids]
        steps = [st.compact_dict(group_ids) for st in self.steps]

        def line(v: Any) -> str:
            return json.dumps(v, ensure_ascii=False, separators=(", ", ": "))

        groups = d.pop("groups")
        head = line(d)[:-1]
        head += ',\n "groups": [' + "".join(f"\n  {line(g)}," for g in groups).rstrip(",") + "\n ]"
        body = ",\n".join(f"  {line(s)}" for s in steps)
        objs = ",\n".join(f"  {line(k)}: {line(v)}" for k, v in objects.items())
        return f'{head},\n "steps": [\n{body}\n ],\n "objects": {{\n{objs}\n }}}}\n'

    @classmethod
    def from_dict(cls, d: Any) -> "Protocol":
        """A protocol from its dict form (:meth:`as_dict`, or a parsed file of format 1 or 2), checked whole.

        Everything a replay relies on is checked here, once: the format, every
        field of every step, each step against its operation's declared inputs,
        outputs and parameters (finite numbers, known kinds), that every object
        is made before it is used and every given a step reads is in
        ``params.givens``.  A malformed protocol raises ProtocolFormatError
        naming the step, the field, the value and what is allowed.
        """
        return cls._checked(d, empty_ok=False)

    @classmethod
    def _checked(cls, d: Any, *, empty_ok: bool) -> "Protocol":
        if not isinstance(d, Mapping):
            raise ProtocolFormatError(f"a protocol is a JSON object, got {type(d).__name__}")
        fmt = check_format(d)
        for key in ("construction", "params", "steps"):
            if key not in d:
                raise ProtocolFormatError(f"protocol has no {key!r}")
        name = d["construction"]
        if not isinstance(name, str) or not name:
            raise ProtocolFormatError(f"protocol 'construction' must be a name, got {_shown(name)}")
        if not isinstance(d["steps"], list):
            raise ProtocolFormatError(f"protocol 'steps' must be a list of objects, got {type(d['steps']).__name__}")
        if not d["steps"] and not empty_ok:
            raise ProtocolFormatError("protocol has no steps")
        if not isinstance(d["params"], Mapping):
            raise ProtocolFormatError(f"protocol 'params' must be an object, got {type(d['params']).__name__}")
        params = frozen(dict(d["params"]))
        stored = params.get("givens", MappingProxyType({}))
        if not isinstance(stored, Mapping):
            raise ProtocolFormatError(f"protocol 'params.givens' must map names to numbers, got {_shown(stored)}")
        for key, value in stored.items():
            as_float(value, f"protocol 'params.givens': the given {shown(key)}", ProtocolFormatError)
        titles = params.get("group_titles")  # read by every drawing of the protocol: checked here, once
        if titles is not None and not (isinstance(titles, Mapping) and all(
                isinstance(k, str) and isinstance(v, str) for k, v in titles.items())):
            raise ProtocolFormatError(f"protocol 'params.group_titles' must map each English group title to its "
                                      f"German one (text to text), got {_shown(titles)}")
        called = params.get("called")  # what lines are called in the captions: (German, English) by name
        if called is not None and not (isinstance(called, Mapping) and all(
                isinstance(k, str) and isinstance(v, Sequence) and not isinstance(v, str) and len(v) == 2
                and all(isinstance(t, str) for t in v) for k, v in called.items())):
            raise ProtocolFormatError(f"protocol 'params.called' must map object names to their German and English "
                                      f"names (two texts), got {_shown(called)}")
        givens = d.get("givens", [])
        if not isinstance(givens, list) or not all(isinstance(g, str) for g in givens):
            raise ProtocolFormatError(f"protocol 'givens' must be a list of names, got {_shown(givens)}")
        unstored = [g for g in givens if g not in stored]
        if unstored:
            raise ProtocolFormatError(f"protocol 'givens' names {unstored[0]!r}, which 'params.givens' lacks "
                                      f"(it has {', '.join(stored) or 'none'})")
        table = d.get("groups", []) if fmt == PROTOCOL_FILE_FORMAT else None
        if table is not None and not (isinstance(table, list) and all(
                isinstance(g, list) and all(isinstance(t, str) for t in g) for g in table)):
            raise ProtocolFormatError("protocol 'groups' must be a list of group paths (lists of titles)")
        steps = tuple(Step._from_fields(step_fields(s, k, table)) for k, s in enumerate(d["steps"], start=1))
        for st in steps:
            reads = _givens_read(st)
            missing = [g for g in reads if g not in stored]
            if missing:
                raise ProtocolFormatError(f"step {st.index} ({st.tool}: {st.caption.brief}) reads the given "
                                          f"{missing[0]!r}, which 'params.givens' lacks "
                                          f"(it has {', '.join(stored) or 'none'})")
        proto = cls(construction=name, params=params, steps=steps, givens=tuple(givens))
        try:
            proto.program  # unknown ops, wrong kinds and counts, dangling names, bad rules: now, not mid-replay
        except StepError as exc:
            raise ProtocolFormatError(str(exc)) from None
        return proto

    @classmethod
    def from_json(cls, text: str | bytes) -> "Protocol":
        """A protocol from the text of a protocol file (see :meth:`from_dict` for what is checked)."""
        return cls.from_dict(parse_protocol_json(text))

    @classmethod
    def load(cls, path: Any) -> "Protocol":
        """A protocol from a file: a regular file of at most MAX_PROTOCOL_BYTES (64 MiB), checked whole.

        >>> Protocol.load("/dev/zero")
        Traceback (most recent call last):
        ...
        construct.kernel.errors.ProtocolFormatError: cannot read protocol file '/dev/zero': it is not a regular file (a device); name a regular file
        """
        data = read_protocol_bytes(path)
        return cls.from_dict(parse_protocol_json(data, f"protocol file {os.fsdecode(os.fspath(path))!r}"))


def _unpickle(d: Mapping[str, Any]) -> Protocol:
    """A pickled protocol: checked as a file is, but a Builder's protocol may have no steps yet."""
    return Protocol._checked(d, empty_ok=True)


def _givens_read(step: Step) -> tuple[str, ...]:
    """The givens a step reads by name (a given point's unit, a given length's factors)."""
    if step.op == "given_point":
        unit = step.params.get("unit")
        return (unit,) if isinstance(unit, str) else ()
    if step.op == "given_length":
        product = step.params.get("product")
        return tuple(g for g in product if isinstance(g, str)) if isinstance(product, (list, tuple)) else ()
    return ()
