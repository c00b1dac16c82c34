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
import numbers
import os
from types import MappingProxyType
from dataclasses import dataclass
from collections.abc import Mapping, Sequence
from typing import Any

from .errors import InvalidParameter, OutputError, ProtocolFormatError, StepError
from .geometry import SCALAR
# A step (step.py) and the evaluation path (replay.py) live in modules of their own; their names stay importable
# from here, where every caller has found them.
from .step import EXACT, GIVEN, Caption, Provenance, Step, jsonable
from .replay import (STEP_FAILURES, CompiledStep, Program, Replay, check_kinds, compile_step, loop_entry,
                     object_json, run_step, step_failure, sweep_givens)
from .protocol_file import (KNOWN_FORMATS, MAX_PROTOCOL_BYTES, PROTOCOL_FILE_FORMAT, PROTOCOL_FORMAT,
                            PROVENANCE_KINDS, ROLES, TOOLS, check_format, frozen, parse_protocol_json,
                            read_protocol_bytes, step_fields)
from .numeric import as_float, shown

__all__ = [
    "PROVENANCE_KINDS",
    "TOOLS",
    "ROLES",
    "KNOWN_FORMATS",
    "Caption",
    "Provenance",
    "Step",
    "EXACT",
    "GIVEN",
    "Protocol",
    "Replay",
    "run_step",
    "compile_step",
    "CompiledStep",
    "Program",
    "object_json",
]

# PROVENANCE_KINDS, TOOLS, ROLES and the formats are defined with the file checks (protocol_file).


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

    @functools.cached_property
    def makers(self) -> Mapping[str, Step]:
        """The step that made each object, by the object's name (read-only, made once: the checks of each set
        of a 1,000-set sweep ask for it)."""
        return MappingProxyType({name: step for step in self.steps for name in step.outputs})

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
        return Program(tuple(entries), tuple(slot), tuple(loop_entry(e) for e in entries))

    def replay(self, givens: Mapping[str, Any] | None = None, *, upto: int | None = None) -> Replay:
        """Evaluate the steps (all, or 1..upto) with *givens*; return the objects by name.

        Givens that are arrays (or lists) make the replay a sweep: one value
        per set of givens in every coordinate.
        """
        if givens is not None and not isinstance(givens, Mapping):
            raise InvalidParameter(f"givens are a mapping of names to numbers, got {shown(givens)}")
        if upto is not None and (isinstance(upto, bool) or not isinstance(upto, numbers.Integral)):
            raise InvalidParameter(f"upto is a step number, got {shown(upto)}")
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
            except STEP_FAILURES as exc:
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
    def as_dict(self, replay: Replay | None = None, *, with_objects: bool = True,
                with_steps: bool = True) -> dict[str, Any]:
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
        })
        if with_steps:
            d["steps"] = [s.as_dict() for s in self.steps]
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
        d = self.as_dict(replay, with_steps=False)  # the steps are written compactly below
        objects = d.pop("objects")
        group_ids: dict[tuple[str, ...], int] = {}
        for st in self.steps:
            if st.group and st.group not in group_ids:
                group_ids[st.group] = len(group_ids)
        d["format"] = PROTOCOL_FILE_FORMAT
        d["groups"] = [list(g) for g in group_ids]
        steps = [st.compact_dict(group_ids) for st in self.steps]

        line = _line_encoder()
        groups = d.pop("groups")
        head = line(d)[:-1]
        head += ',\n "groups": [' + "".join(f"\n  {line(g)}," for g in groups).rstrip(",") + "\n ]"
        body = ",\n".join(f"  {line(s)}" for s in steps)
        key = json.encoder.encode_basestring  # (a name as the line encoder writes it, without a call of it per name)
        objs = ",\n".join(f"  {key(k) if type(k) is str else line(k)}: {line(v)}" for k, v in objects.items())
        text = f'{head},\n "steps": [\n{body}\n ],\n "objects": {{\n{objs}\n }}}}\n'
        size = len(text.encode("utf-8"))
        if size > MAX_PROTOCOL_BYTES:  # what this library writes, it reads back: the reader's limit, here
            raise OutputError(f"the protocol of {self.construction!r} ({len(self.steps)} steps) would be "
                              f"{size / 2**20:.1f} MiB, more than the {MAX_PROTOCOL_BYTES // 2**20} MiB a protocol "
                              f"file may have to be read back (construct check, replay --protocol); fewer steps "
                              f"(parts, divisions) make it smaller")
        return text

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
            raise ProtocolFormatError(f"protocol 'construction' must be a name, got {shown(name)}")
        if not isinstance(d["steps"], list):
            raise ProtocolFormatError(f"protocol 'steps' must be a list of objects, got {type(d['steps']).__name__}")
        if not d["steps"] and not empty_ok:
            raise ProtocolFormatError("protocol has no steps")
        if not isinstance(d["params"], Mapping):
            raise ProtocolFormatError(f"protocol 'params' must be an object, got {type(d['params']).__name__}")
        params = frozen(dict(d["params"]))
        stored = params.get("givens", MappingProxyType({}))
        if not isinstance(stored, Mapping):
            raise ProtocolFormatError(f"protocol 'params.givens' must map names to numbers, got {shown(stored)}")
        for key, value in stored.items():
            as_float(value, f"protocol 'params.givens': the given {shown(key)}", ProtocolFormatError)
        titles = params.get("group_titles")  # read by every drawing of the protocol: checked here, once
        if titles is not None and not (isinstance(titles, Mapping) and all(
                isinstance(k, str) and isinstance(v, str) for k, v in titles.items())):
            raise ProtocolFormatError(f"protocol 'params.group_titles' must map each English group title to its "
                                      f"German one (text to text), got {shown(titles)}")
        called = params.get("called")  # what lines are called in the captions: (German, English) by name
        if called is not None and not (isinstance(called, Mapping) and all(
                isinstance(k, str) and isinstance(v, Sequence) and not isinstance(v, str) and len(v) == 2
                and all(isinstance(t, str) for t in v) for k, v in called.items())):
            raise ProtocolFormatError(f"protocol 'params.called' must map object names to their German and English "
                                      f"names (two texts), got {shown(called)}")
        givens = d.get("givens", [])
        if not isinstance(givens, list) or not all(isinstance(g, str) for g in givens):
            raise ProtocolFormatError(f"protocol 'givens' must be a list of names, got {shown(givens)}")
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


#: One line of a protocol file: json.dumps(v, ensure_ascii=False, separators=(", ", ": ")), with one encoder for
#: every line (json.dumps makes an encoder per call for any options but the defaults).
_LINE = json.JSONEncoder(ensure_ascii=False, separators=(", ", ": "))


def _line_encoder() -> Any:
    """``_LINE.encode`` for the lines of a protocol file, as one C encoder made once (``JSONEncoder.encode`` makes
    one per call: for 70,000 lines that was most of the encoding); ``_LINE.encode`` where the C encoder is missing.
    (No check for circular containers: a protocol's data is a tree.)"""
    make = getattr(json.encoder, "c_make_encoder", None)
    if make is None:
        return _LINE.encode
    enc = make(None, _LINE.default, json.encoder.encode_basestring, None, _LINE.key_separator,
               _LINE.item_separator, False, False, True)

    def line(value: Any) -> str:
        return "".join(enc(value, 0))

    return line


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
