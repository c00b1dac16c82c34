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

import gc
import json
import math
from dataclasses import dataclass, field
from types import MappingProxyType
from typing import Any, Callable, Mapping, Sequence

from .errors import ConstructError, GeometryError, InvalidParameter, ProtocolFormatError, StepError
from .geometry import Circle, Length, Line, Point, intersect

__all__ = [
    "PROVENANCE_KINDS",
    "TOOLS",
    "Caption",
    "Provenance",
    "Step",
    "Protocol",
    "Replay",
    "OPS",
    "choose",
]

PROVENANCE_KINDS = ("given", "exact", "approximate", "neusis", "trial")

#: The instruments.  "intersect" marks where two drawn curves cross: no new
#: instrument, but a step of its own because a choice is made there.  "curve"
#: is the draftsman's French curve (Curvenlineal): it draws a smooth line
#: through constructed points, it constructs nothing.
TOOLS = ("given", "straightedge", "compass", "dividers", "intersect", "neusis", "curve")

PROTOCOL_FORMAT = "construct-protocol/1"


@dataclass(frozen=True, slots=True)
class Caption:
    """What a step does, in the books' German and in English."""

    de: str
    en: str


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
    """One instrument use: data only, evaluated by :data:`OPS` [op]."""

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
            "params": _jsonable(dict(self.params)),
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

    @classmethod
    def from_dict(cls, d: Mapping[str, Any]) -> "Step":
        try:
            prov = d.get("provenance") or {"kind": "exact"}
            cap = d["caption"]
            return cls(
                index=int(d["index"]),
                tool=str(d["tool"]),
                op=str(d["op"]),
                inputs=tuple(str(s) for s in d["inputs"]),
                outputs=tuple(str(s) for s in d["outputs"]),
                params=MappingProxyType(_frozen(d.get("params") or {})),
                caption=Caption(str(cap["de"]), str(cap["en"])),
                provenance=Provenance(str(prov["kind"]), prov.get("method"), prov.get("error")),
                group=tuple(str(g) for g in d.get("group") or ()),
                role=str(d.get("role", "construction")),
                labels=tuple(sorted((str(k), str(v)) for k, v in (d.get("labels") or {}).items())),
            )
        except (KeyError, TypeError, ValueError, AttributeError) as exc:
            raise ProtocolFormatError(f"malformed step {d.get('index', '?') if isinstance(d, Mapping) else d!r}: {exc!r}") from None


def _frozen(value: Any) -> Any:
    """JSON lists become tuples so that params stay hashable and immutable."""
    if isinstance(value, list):
        return tuple(_frozen(v) for v in value)
    if isinstance(value, dict):
        return MappingProxyType({k: _frozen(v) for k, v in value.items()})
    return value


def _jsonable(value: Any) -> Any:
    if isinstance(value, (tuple, list)):
        return [_jsonable(v) for v in value]
    if isinstance(value, Mapping):
        return {str(k): _jsonable(v) for k, v in value.items()}
    return value


# --------------------------------------------------------------------------
# Branch rules.  A rule is a tuple whose first item names it; object names in
# it are resolved when the protocol is compiled.
#   ("nearer", A)            the point nearer to A
#   ("farther", A)           the point farther from A
#   ("left", A, B)           the point to the left of the directed line A->B
#   ("right", A, B)          ... to the right
#   ("toward", A, B)         the point farthest along the direction A->B;
#   ("toward", A, None, dx, dy)  ... along a fixed direction (dx, dy)
#   ("only",)                there must be exactly one point (lines, tangency)
# --------------------------------------------------------------------------

RULE_ARITY = {"nearer": 1, "farther": 1, "left": 2, "right": 2, "toward": 2, "only": 0}


def rule_refs(rule: Sequence[Any]) -> tuple[str, ...]:
    """The object names a rule refers to."""
    if not rule or rule[0] not in RULE_ARITY:
        raise ProtocolFormatError(f"unknown intersection rule {rule!r}; known: {sorted(RULE_ARITY)}")
    n = RULE_ARITY[rule[0]]
    return tuple(r for r in rule[1 : 1 + n] if r is not None)


def choose(points: tuple[Point, ...], rule: Sequence[Any], refs: Sequence[Any]) -> tuple[Point, Point | None]:
    """Pick one of the intersection points by *rule*; return (chosen, other).

    *refs* are the objects the rule names, already looked up.

    >>> pts = (Point(0.0, 1.0), Point(0.0, -1.0))
    >>> choose(pts, ("left", "A", "B"), (Point(-1.0, 0.0), Point(1.0, 0.0)))[0]
    Point(0.0, 1.0)
    >>> choose(pts, ("nearer", "Q"), (Point(0.0, -5.0),))[0]
    Point(0.0, -1.0)
    """
    name = rule[0]
    if len(points) == 1:  # a tangency or a line crossing: one point, whatever the rule
        return points[0], None
    if name == "only":
        raise GeometryError(f"expected exactly one intersection, found {len(points)}")
    a, b = points
    if name in ("nearer", "farther"):
        (rx, ry), = refs
        da = (a[0] - rx) ** 2 + (a[1] - ry) ** 2
        db = (b[0] - rx) ** 2 + (b[1] - ry) ** 2
        first = da <= db if name == "nearer" else da >= db
    elif name in ("left", "right"):
        (ax, ay), (bx, by) = refs
        sa = (bx - ax) * (a[1] - ay) - (by - ay) * (a[0] - ax)
        sb = (bx - ax) * (b[1] - ay) - (by - ay) * (b[0] - ax)
        first = sa >= sb if name == "left" else sa <= sb
    elif name == "toward":
        if len(refs) == 2:
            (ax, ay), (bx, by) = refs
            dx, dy = bx - ax, by - ay
        else:
            dx, dy = float(rule[3]), float(rule[4])
        first = a[0] * dx + a[1] * dy >= b[0] * dx + b[1] * dy
    else:  # pragma: no cover - rule_refs rejects unknown rules first
        raise ProtocolFormatError(f"unknown intersection rule {rule!r}")
    return (a, b) if first else (b, a)


# --------------------------------------------------------------------------
# Operations.  Each takes the input objects, the step's params and the givens
# and returns the tuple of output objects.  They are the only place where
# numbers are computed, and they compute only what the instrument does.
# --------------------------------------------------------------------------


def _given_point(args, params, givens):
    unit = givens[params["unit"]] if params.get("unit") else 1.0
    return (Point(params["x"] * unit, params["y"] * unit),)


def _given_length(args, params, givens):
    value = float(params.get("factor", 1.0))
    for name in params["product"]:
        value *= givens[name]
    return (Length(value),)


def _given_line(args, params, givens):
    (o,) = args
    a = math.radians(params["angle_deg"])
    # A second point one unit away fixes the direction; the drawing extent is
    # the renderer's business.
    return (Line(o, Point(o[0] + math.cos(a), o[1] + math.sin(a))),)


def _line(args, params, givens):
    return (Line(args[0], args[1]),)


def _circle_through(args, params, givens):
    c, p = args
    return (Circle(c, math.hypot(p[0] - c[0], p[1] - c[1])),)


def _circle_radius(args, params, givens):
    c, length = args
    return (Circle(c, float(length)),)


def _circle_segment(args, params, givens):
    c, a, b = args
    return (Circle(c, math.hypot(b[0] - a[0], b[1] - a[1])),)


def _length_of(args, params, givens):
    a, b = args
    return (Length(math.hypot(b[0] - a[0], b[1] - a[1])),)


def _intersect(args, params, givens, refs=()):
    c1, c2 = args
    pts = intersect(c1, c2)
    if not pts:
        raise GeometryError(f"{_describe(c1)} and {_describe(c2)} do not meet")
    chosen, other = choose(pts, params["rule"], refs)
    if params.get("both"):
        if other is None:
            raise GeometryError(f"{_describe(c1)} and {_describe(c2)} only touch; two points were expected")
        return (chosen, other)
    return (chosen,)


def _describe(obj: Any) -> str:
    if isinstance(obj, Circle):
        (x, y), r = obj
        return f"circle about ({x:.6g}, {y:.6g}) with radius {r:.6g}"
    if isinstance(obj, Line):
        (x1, y1), (x2, y2) = obj
        return f"line through ({x1:.6g}, {y1:.6g}) and ({x2:.6g}, {y2:.6g})"
    return repr(obj)


def _step_off(args, params, givens, refs=()):
    """Dividers: from a point, step a length off along a curve (no arc is drawn, a point is pricked)."""
    curve, start, length = args
    return _intersect((curve, Circle(start, float(length))), params, givens, refs)


OPS: dict[str, Callable[..., tuple[Any, ...]]] = {
    "given_point": _given_point,
    "given_length": _given_length,
    "given_line": _given_line,
    "line": _line,
    "circle_through": _circle_through,
    "circle_radius": _circle_radius,
    "circle_segment": _circle_segment,
    "length_of": _length_of,
    "intersect": _intersect,
    "step_off": _step_off,
}

#: Ops whose params carry a rule that names objects.
_RULE_OPS = {"intersect", "step_off"}


# -- compiled forms -----------------------------------------------------------
# Replaying is a fold over the steps; to make it cheap (the 18-part crank is
# ~360 steps and should replay in about a millisecond) each step is compiled
# once into a closure over integer slots.  The hot operations get hand-made
# closures; every other op runs through the generic wrapper.  Both compute
# exactly what OPS[op] computes.

_tuple_new = tuple.__new__


def _compile_generic(fn, ins, outs, params, refs):
    if refs:
        def run(env, givens):
            vals = fn([env[k] for k in ins], params, givens, [env[k] for k in refs])
            for k, v in zip(outs, vals):
                env[k] = v
    else:
        def run(env, givens):
            vals = fn([env[k] for k in ins], params, givens)
            for k, v in zip(outs, vals):
                env[k] = v
    return run


def _compile_intersect(fn, ins, outs, params, refs):
    """Intersections are most steps: the same _intersect, with its slots bound once."""
    a, b = ins
    frozen = {"rule": tuple(params["rule"]), "both": bool(params.get("both"))}
    if len(outs) == 2:
        o0, o1 = outs

        def run(env, givens):
            env[o0], env[o1] = _intersect((env[a], env[b]), frozen, givens, [env[k] for k in refs])
    else:
        (o0,) = outs

        def run(env, givens):
            (env[o0],) = _intersect((env[a], env[b]), frozen, givens, [env[k] for k in refs])
    return run


def _compile_step_off(fn, ins, outs, params, refs):
    curve, start, length = ins
    inner = _compile_intersect(fn, (curve, -1), outs, params, refs)

    def run(env, givens):
        # The dividers' reach is a circle about the start; it lives only in this step.
        env.append(_tuple_new(Circle, (env[start], float(env[length]))))
        try:
            inner(env, givens)
        finally:
            env.pop()
    return run


def _compile_circle_radius(fn, ins, outs, params, refs):
    c, length = ins
    (o,) = outs

    def run(env, givens):
        env[o] = _tuple_new(Circle, (env[c], float(env[length])))  # a Length is positive by construction
    return run


def _compile_circle_through(fn, ins, outs, params, refs):
    c, p = ins
    (o,) = outs

    def run(env, givens):
        cc, pp = env[c], env[p]
        r = math.hypot(pp[0] - cc[0], pp[1] - cc[1])
        if not r > 0.0:
            raise GeometryError(f"circle about {cc!r} through itself has no radius")
        env[o] = _tuple_new(Circle, (cc, r))
    return run


def _compile_line(fn, ins, outs, params, refs):
    a, b = ins
    (o,) = outs

    def run(env, givens):
        env[o] = Line(env[a], env[b])
    return run


_COMPILERS = {
    "intersect": _compile_intersect,
    "circle_radius": _compile_circle_radius,
    "circle_through": _compile_circle_through,
    "line": _compile_line,
    "step_off": _compile_step_off,
}


def register_op(name: str, fn: Callable[..., tuple[Any, ...]], *, rule: bool = False) -> None:
    """Add an operation (modules with special instruments call this on import)."""
    OPS[name] = fn
    _COMPILERS.pop(name, None)
    if rule:
        _RULE_OPS.add(name)


# --------------------------------------------------------------------------


class Replay(Mapping[str, Any]):
    """The objects a replay made, by name; ``upto(k)`` is what steps 1..k made."""

    __slots__ = ("protocol", "_objects", "givens")

    def __init__(self, protocol: "Protocol", objects: dict[str, Any], givens: Mapping[str, float]):
        self.protocol = protocol
        self._objects = objects
        self.givens = MappingProxyType(dict(givens))

    def __getitem__(self, name: str) -> Any:
        return self._objects[name]

    def __iter__(self):
        return iter(self._objects)

    def __len__(self) -> int:
        return len(self._objects)

    def made_by(self) -> dict[str, Step]:
        """The step that made each object."""
        return {name: step for step in self.protocol.steps for name in step.outputs}

    def objects_json(self) -> dict[str, Any]:
        return {name: object_json(obj) for name, obj in self._objects.items()}


def object_json(obj: Any) -> dict[str, Any]:
    """A drawn object as plain JSON data (the ``objects`` table of protocol.json)."""
    if isinstance(obj, Point):
        return {"type": "point", "x": obj[0], "y": obj[1]}
    if isinstance(obj, Line):
        (x1, y1), (x2, y2) = obj
        return {"type": "line", "x1": x1, "y1": y1, "x2": x2, "y2": y2}
    if isinstance(obj, Circle):
        (cx, cy), r = obj
        return {"type": "circle", "cx": cx, "cy": cy, "r": r}
    if isinstance(obj, Length):
        return {"type": "length", "value": float(obj)}
    if isinstance(obj, tuple) and getattr(obj, "kind", None) and all(isinstance(p, Point) for p in obj):
        # A curve made of points (a Bézier chain through constructed points): its points in order.
        return {"type": obj.kind, "points": [[p[0], p[1]] for p in obj]}
    if isinstance(obj, float):
        return {"type": "number", "value": float(obj)}
    raise TypeError(f"not a drawable object: {obj!r}")


@dataclass(frozen=True)
class Protocol:
    """A construction as data: its name, its parameters and its steps."""

    construction: str
    params: Mapping[str, Any]
    steps: tuple[Step, ...]
    #: The givens a replay may change without changing the steps.
    givens: tuple[str, ...] = ()
    _compiled: list = field(default_factory=list, repr=False, compare=False)

    # -- replay -------------------------------------------------------------
    def _compile(self) -> list:
        if self._compiled:
            return self._compiled
        slot: dict[str, int] = {}
        compiled = []
        for step in self.steps:
            fn = OPS.get(step.op)
            if fn is None:
                raise ProtocolFormatError(f"step {step.index}: unknown operation {step.op!r}")
            try:
                ins = tuple(slot[name] for name in step.inputs)
                refs: tuple[int, ...] = ()
                if step.op in _RULE_OPS:
                    refs = tuple(slot[name] for name in rule_refs(step.params["rule"]))
            except KeyError as exc:
                raise ProtocolFormatError(
                    f"step {step.index} ({step.op}) uses {exc.args[0]!r} before any step made it"
                ) from None
            outs = []
            for name in step.outputs:
                if name in slot:
                    raise ProtocolFormatError(f"step {step.index} makes {name!r} a second time")
                slot[name] = len(slot)
                outs.append(slot[name])
            params = dict(step.params)
            run = _COMPILERS.get(step.op, _compile_generic)(fn, ins, tuple(outs), params, refs)
            compiled.append((run, step))
        self._compiled.extend(compiled)
        self._compiled.append(tuple(slot))  # slot names in order, last item
        return self._compiled

    def replay(self, givens: Mapping[str, float] | None = None, *, upto: int | None = None) -> Replay:
        """Evaluate the steps (all, or 1..upto) with *givens*; return the objects by name."""
        givens = dict(self.params.get("givens", {}) if givens is None else givens)
        compiled = self._compile()
        names = compiled[-1]
        env: list[Any] = [None] * len(names)
        stop = len(compiled) - 1 if upto is None else min(upto, len(compiled) - 1)
        i = 0
        # Replay makes no reference cycles; the cyclic collector would only
        # rescan the growing table of objects (a 2x slowdown at 30000 steps).
        collecting = gc.isenabled()
        gc.disable()
        try:
            for i in range(stop):
                compiled[i][0](env, givens)
        except ConstructError as exc:
            step = compiled[i][-1]
            raise StepError(_step_message(step, exc), step_index=step.index, tool=step.tool) from exc
        except KeyError as exc:
            step = compiled[i][-1]
            raise InvalidParameter(f"step {step.index} ({step.op}) needs the given {exc.args[0]!r}") from None
        finally:
            if collecting:
                gc.enable()
        objects = {names[k]: env[k] for k in range(len(names)) if env[k] is not None}
        return Replay(self, objects, givens)

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
    def as_dict(self, replay: Replay | None = None) -> dict[str, Any]:
        if replay is None:
            replay = self.replay()
        params = dict(self.params)
        params["givens"] = dict(replay.givens)  # the givens this replay was made with
        return {
            "format": PROTOCOL_FORMAT,
            "construction": self.construction,
            "params": _jsonable(params),
            "givens": list(self.givens),
            "instruments": self.instrument_counts(),
            "steps": [s.as_dict() for s in self.steps],
            "objects": replay.objects_json(),
        }

    def to_json(self, replay: Replay | None = None) -> str:
        return json.dumps(self.as_dict(replay), indent=1, ensure_ascii=False, sort_keys=False) + "\n"

    @classmethod
    def from_dict(cls, d: Any) -> "Protocol":
        if not isinstance(d, Mapping):
            raise ProtocolFormatError("a protocol is a JSON object")
        for key in ("construction", "params", "steps"):
            if key not in d:
                raise ProtocolFormatError(f"protocol has no {key!r}")
        if not isinstance(d["steps"], list) or not all(isinstance(s, Mapping) for s in d["steps"]):
            raise ProtocolFormatError("protocol 'steps' must be a list of objects")
        steps = tuple(Step.from_dict(s) for s in d["steps"])
        for k, s in enumerate(steps, start=1):
            if s.index != k:
                raise ProtocolFormatError(f"step {k} carries index {s.index}")
        proto = cls(
            construction=str(d["construction"]),
            params=MappingProxyType(_frozen(dict(d["params"]))),
            steps=steps,
            givens=tuple(str(g) for g in d.get("givens", ())),
        )
        proto._compile()  # reject unknown ops and dangling names now, not mid-replay
        return proto

    @classmethod
    def from_json(cls, text: str) -> "Protocol":
        try:
            data = json.loads(text)
        except (json.JSONDecodeError, UnicodeDecodeError) as exc:
            raise ProtocolFormatError(f"not a JSON protocol: {exc}") from None
        return cls.from_dict(data)


def _step_message(step: Step, exc: Exception) -> str:
    return f"step {step.index} ({step.tool}: {step.caption.en}): {exc}"
