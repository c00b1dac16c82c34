"""Semantic diff of two construction protocols (``protocol.json``), as a :class:`~construct.regress.change.Diff`.

What a reviewer of a changed construction wants to know: which steps were
inserted or removed, which changed (instrument, operation, inputs, outputs,
parameters, caption, provenance), which constructed objects moved, and
whether the *method* changed — a construction with fewer compass uses is a
different construction even if every point lands in the same place.

Steps are aligned by what they make (their output names), so one inserted
step is "inserted", not "every later step changed".

>>> a = {"construction": "demo", "params": {"r": 5}, "steps": [
...     {"index": 1, "tool": "given", "op": "point", "inputs": [], "outputs": ["M"]},
...     {"index": 2, "tool": "compass", "op": "circle", "inputs": ["M"], "outputs": ["k"]}],
...     "objects": {"M": {"type": "point", "x": 0, "y": 0}}}
>>> b = {**a, "steps": a["steps"][:1] + [
...     {"index": 2, "tool": "straightedge", "op": "line", "inputs": ["M"], "outputs": ["g"]}] + [
...     dict(a["steps"][1], index=3)]}
>>> print(diff_protocol(a, b).report())
protocol diff <data> -> <data> (tolerance 1e-09): 2 changes
  method     steps: method changed: 2 -> 3 steps (straightedge 0 -> 1)
  inserted   step 2: straightedge line (M) -> g
"""

from __future__ import annotations

import difflib
import json
import math
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping, Sequence

from ..kernel.errors import InvalidParameter, ProtocolFormatError
from ..kernel.numeric import json_number_problems, shown
from ..kernel.protocol_file import (MAX_PROTOCOL_BYTES, check_format, check_nesting, parse_protocol_json,
                                    read_protocol_bytes)
from .change import Change, Diff

__all__ = ["DEFAULT_TOLERANCE", "Change", "Diff", "diff_protocol", "load_protocol"]

DEFAULT_TOLERANCE = 1e-9
"""Drawing units; a replay is deterministic, so only float noise is forgiven."""

# Instruments in the order a report lists them; unknown tools follow alphabetically.
TOOL_ORDER = ("compass", "straightedge", "dividers", "neusis", "intersect", "given")
_STEP_FIELDS = ("tool", "op", "inputs", "outputs", "params", "caption", "provenance", "group")
_KNOWN_TOP = {"construction", "params", "steps", "objects", "instruments", "groups"}  # derived: recounted, resolved


def _fmt(x: float) -> str:
    s = format(x, ".10g")
    return "0" if s in ("-0", "0") else s


def _is_num(x: Any) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def _close(x: Any, y: Any, tol: float) -> bool:
    """Equal JSON values, numbers within *tol* (``5`` equals ``5.0``)."""
    if _is_num(x) and _is_num(y):
        # NaN against NaN: the same value read twice (a file compared with itself is equal)
        return x == y or abs(float(x) - float(y)) <= tol or (math.isnan(x) and math.isnan(y))
    if isinstance(x, list) and isinstance(y, list):
        return len(x) == len(y) and all(_close(p, q, tol) for p, q in zip(x, y))
    if isinstance(x, dict) and isinstance(y, dict):
        return x.keys() == y.keys() and all(_close(x[k], y[k], tol) for k in x)
    return type(x) is type(y) and x == y


def _show(x: Any) -> str:
    if _is_num(x):
        return _fmt(float(x))
    if x is None:
        return "null"
    if isinstance(x, str):
        return repr(x)
    if isinstance(x, list):
        return "[" + ", ".join(_show(v) for v in x) + "]"
    if isinstance(x, dict):
        return "{" + ", ".join(f"{k}: {_show(v)}" for k, v in x.items()) + "}"
    return json.dumps(x)


def _flat(x: Any, prefix: str = "") -> dict[str, Any]:
    """Nested dicts as dotted paths, so a report names ``givens.r`` rather than the whole dict."""
    if isinstance(x, dict) and x:
        out: dict[str, Any] = {}
        for k, v in x.items():
            out.update(_flat(v, f"{prefix}.{k}" if prefix else str(k)))
        return out
    return {prefix: x}


def _value_changes(a: Any, b: Any, tol: float) -> list[tuple[str, str, float | None]]:
    """(path, "old -> new", numeric difference) for every differing leaf of two JSON values."""
    fa, fb = _flat(a), _flat(b)
    out = []
    for path in list(fa) + [p for p in fb if p not in fa]:
        va, vb = fa.get(path, _MISSING), fb.get(path, _MISSING)
        if va is _MISSING or vb is _MISSING or not _close(va, vb, tol):
            mag = abs(float(va) - float(vb)) if _is_num(va) and _is_num(vb) else None
            out.append((path, f"{'(none)' if va is _MISSING else _show(va)} -> "
                              f"{'(none)' if vb is _MISSING else _show(vb)}", mag))
    return out


_MISSING = object()


# --------------------------------------------------------------------------- loading

@dataclass(frozen=True, slots=True)
class _Protocol:
    label: str
    data: dict[str, Any]
    steps: tuple[dict[str, Any], ...]
    objects: dict[str, dict[str, Any]]


def _read(source: str | Path | bytes | Mapping[str, Any]) -> tuple[Any, str]:
    if isinstance(source, Mapping):
        return dict(source), "<data>"
    if isinstance(source, (bytes, bytearray)):
        text, label = source, "<bytes>"
    elif isinstance(source, str) and source.lstrip().startswith(("{", "[", "\ufeff")):
        text, label = source, "<string>"
    else:  # a file: read as the loader reads it, regular files only and at most MAX_PROTOCOL_BYTES
        text, label = read_protocol_bytes(source), str(source)
    if len(text) > MAX_PROTOCOL_BYTES:
        raise ProtocolFormatError(f"{label}: larger than {MAX_PROTOCOL_BYTES // 2**20} MiB; no protocol this "
                                  f"library writes is")
    data = parse_protocol_json(text, label)
    for where, value in json_number_problems(data):  # JSON allows integers no float can hold
        raise ProtocolFormatError(f"{label}: {where} must be a finite number, got {shown(value)}")
    return data, label


def load_protocol(source: str | Path | bytes | Mapping[str, Any]) -> _Protocol:
    """Read and check the shape of a protocol (JSON text, bytes, a path or the parsed dict).

    >>> load_protocol('{"construction": "x", "steps": [{"tool": "compass"}]}')
    Traceback (most recent call last):
    ...
    construct.kernel.errors.ProtocolFormatError: <string>: step 1: 'op' must be a string, got None
    """
    data, label = _read(source)
    if not isinstance(data, dict):
        raise ProtocolFormatError(f"{label}: a protocol is a JSON object, got {type(data).__name__}")
    try:
        check_format(data)
        # the diff walks params, steps and objects recursively: deeper than this protocol files never go
        check_nesting(data, what=label)
    except ProtocolFormatError as exc:
        raise ProtocolFormatError(f"{label}: {exc}" if not str(exc).startswith(label) else str(exc)) from None
    if not isinstance(data.get("construction"), str):
        raise ProtocolFormatError(f"{label}: 'construction' must be a string, got {data.get('construction')!r}")
    if not isinstance(data.get("steps"), list):
        raise ProtocolFormatError(f"{label}: 'steps' must be a list")
    if not isinstance(data.get("params", {}), dict):
        raise ProtocolFormatError(f"{label}: 'params' must be an object")
    groups = data.get("groups", [])
    if not isinstance(groups, list) or not all(isinstance(g, list) for g in groups):
        raise ProtocolFormatError(f"{label}: 'groups' must be a list of group paths")
    steps = tuple(_check_step(s, k, label, groups) for k, s in enumerate(data["steps"], 1))
    objects = data.get("objects", {})
    if not isinstance(objects, dict) or not all(
            isinstance(o, dict) and isinstance(o.get("type"), str) for o in objects.values()):
        raise ProtocolFormatError(f"{label}: 'objects' must map names to objects with a 'type'")
    return _Protocol(label, data, steps, objects)


def _check_step(s: Any, k: int, label: str, groups: list | None = None) -> dict[str, Any]:
    if not isinstance(s, dict):
        raise ProtocolFormatError(f"{label}: step {k} is not an object")
    g = s.get("group")
    if isinstance(g, int) and not isinstance(g, bool):  # format 2: the group path by its number in the table
        if not 0 <= g < len(groups or []):
            raise ProtocolFormatError(f"{label}: step {k}: group {g} is not in the file's table")
        s = {**s, "group": groups[g]}
    for name in ("tool", "op"):
        if not isinstance(s.get(name), str):
            raise ProtocolFormatError(f"{label}: step {k}: {name!r} must be a string, got {s.get(name)!r}")
    for name in ("inputs", "outputs", "group"):
        v = s.get(name, [])
        if not isinstance(v, list) or not all(isinstance(x, str) for x in v):
            raise ProtocolFormatError(f"{label}: step {k}: {name!r} must be a list of names, got {v!r}")
    index = s.get("index", k)
    if not isinstance(index, int) or isinstance(index, bool):
        raise ProtocolFormatError(f"{label}: step {k}: 'index' must be an integer, got {index!r}")
    for name in ("params", "caption"):
        if not isinstance(s.get(name, {}), dict):
            raise ProtocolFormatError(f"{label}: step {k}: {name!r} must be an object")
    if not isinstance(s.get("provenance", {}), (dict, type(None))):
        raise ProtocolFormatError(f"{label}: step {k}: 'provenance' must be an object")
    # Format 2 leaves the defaults out: the same step reads the same in both formats.
    prov = s.get("provenance") or {"kind": "exact"}
    prov = {"kind": prov.get("kind"), "method": prov.get("method"), "error": prov.get("error")}
    return {"index": index, "inputs": [], "outputs": [], "params": {}, "caption": {}, "group": [],
            "role": "construction", **s, "provenance": prov}


# --------------------------------------------------------------------------- the diff

def diff_protocol(a: str | Path | bytes | Mapping[str, Any], b: str | Path | bytes | Mapping[str, Any],
                  tolerance: float = DEFAULT_TOLERANCE) -> Diff:
    """Compare two protocols; numbers differing by at most *tolerance* are equal."""
    if not (_is_num(tolerance) and math.isfinite(tolerance) and tolerance >= 0):
        raise InvalidParameter(f"diff_protocol: tolerance must be a finite number >= 0, got {tolerance!r}")
    tol = float(tolerance)
    pa, pb = load_protocol(a), load_protocol(b)
    changes: list[Change] = []
    if pa.data["construction"] != pb.data["construction"]:
        changes.append(Change("construction", "construction",
                              f"{pa.data['construction']!r} -> {pb.data['construction']!r}"))
    instruments = _instruments(pa.steps, pb.steps)
    method = _method_line(len(pa.steps), len(pb.steps), instruments)
    if method:
        changes.append(Change("method", "steps", method, float(abs(len(pb.steps) - len(pa.steps)))))
    for path, text, mag in _value_changes(pa.data.get("params", {}), pb.data.get("params", {}), tol):
        changes.append(Change("param", path, text, mag))
    other_a = {k: v for k, v in pa.data.items() if k not in _KNOWN_TOP}
    other_b = {k: v for k, v in pb.data.items() if k not in _KNOWN_TOP}
    for path, text, mag in _value_changes(other_a, other_b, tol):
        changes.append(Change("document", path, text, mag))
    changes += _step_changes(pa.steps, pb.steps, tol)
    changes += _object_changes(pa.objects, pb.objects, tol)
    return Diff("protocol", pa.label, pb.label, tol, tuple(changes), "steps", (len(pa.steps), len(pb.steps)),
                instruments)


def _tool_rank(tool: str) -> tuple[int, str]:
    return (TOOL_ORDER.index(tool) if tool in TOOL_ORDER else len(TOOL_ORDER), tool)


def _instruments(sa: Sequence[dict], sb: Sequence[dict]) -> tuple[tuple[str, int, int], ...]:
    ca, cb = Counter(s["tool"] for s in sa), Counter(s["tool"] for s in sb)
    return tuple((t, ca[t], cb[t]) for t in sorted(set(ca) | set(cb), key=_tool_rank))


def _method_line(na: int, nb: int, instruments: tuple[tuple[str, int, int], ...]) -> str | None:
    """``method changed: 412 -> 318 steps (compass 180 -> 130, straightedge 60 -> 44)``, or None."""
    changed = [f"{t} {x} -> {y}" for t, x, y in instruments if x != y]
    if na == nb and not changed:
        return None
    return f"method changed: {na} -> {nb} steps" + (f" ({', '.join(changed)})" if changed else "")


def _identity(step: dict) -> tuple:
    """What a step is, independent of its position: the names it makes (else its instrument and inputs)."""
    if step["outputs"]:
        return ("makes", tuple(step["outputs"]))
    return ("does", step["tool"], step["op"], tuple(step["inputs"]))


def _summary(step: dict) -> str:
    ins = ", ".join(step["inputs"])
    outs = ", ".join(step["outputs"]) or "-"
    return f"{step['tool']} {step['op']} ({ins}) -> {outs}"


def _align(sa: Sequence[dict], sb: Sequence[dict]) -> list[tuple[int | None, int | None]]:
    """Pairs of step positions (None where a step is only on one side), in protocol order."""
    out: list[tuple[int | None, int | None]] = []
    matcher = difflib.SequenceMatcher(None, [_identity(s) for s in sa], [_identity(s) for s in sb], autojunk=False)
    for op, i1, i2, j1, j2 in matcher.get_opcodes():
        if op == "equal" or (op == "replace" and i2 - i1 == j2 - j1):
            out += [(i1 + k, j1 + k) for k in range(i2 - i1)]  # same place: a changed step
        elif op == "replace":
            # Different lengths: pair what uses the same instrument and operation, in order.
            inner = difflib.SequenceMatcher(None, [(s["tool"], s["op"]) for s in sa[i1:i2]],
                                            [(s["tool"], s["op"]) for s in sb[j1:j2]], autojunk=False)
            for iop, a1, a2, b1, b2 in inner.get_opcodes():
                if iop == "equal":
                    out += [(i1 + a1 + k, j1 + b1 + k) for k in range(a2 - a1)]
                else:
                    out += [(i1 + k, None) for k in range(a1, a2)] + [(None, j1 + k) for k in range(b1, b2)]
        else:
            out += [(i1 + k, None) for k in range(i2 - i1)] + [(None, j1 + k) for k in range(j2 - j1)]
    return out


def _step_changes(sa: Sequence[dict], sb: Sequence[dict], tol: float) -> list[Change]:
    out: list[Change] = []
    for i, j in _align(sa, sb):
        if j is None:
            out.append(Change("removed", f"step {sa[i]['index']}", _summary(sa[i]), step=sa[i]["index"]))
            continue
        if i is None:
            out.append(Change("inserted", f"step {sb[j]['index']}", _summary(sb[j]), step=sb[j]["index"]))
            continue
        x, y = sa[i], sb[j]
        key = f"step {x['index']}" if x["index"] == y["index"] else f"step {x['index']}->{y['index']}"
        for field in _STEP_FIELDS:
            vx, vy = x.get(field), y.get(field)
            if _close(vx, vy, tol):
                continue
            kind = "step-params" if field == "params" else field
            if isinstance(vx, dict) or isinstance(vy, dict):
                for path, text, mag in _value_changes(vx or {}, vy or {}, tol):
                    out.append(Change(kind, key, f"{field}.{path} {text}", mag, step=x["index"]))
            else:
                out.append(Change(kind, key, f"{_show(vx)} -> {_show(vy)}", step=x["index"]))
        rest_x = {k: v for k, v in x.items() if k not in _STEP_FIELDS and k != "index"}
        rest_y = {k: v for k, v in y.items() if k not in _STEP_FIELDS and k != "index"}
        for path, text, mag in _value_changes(rest_x, rest_y, tol):
            out.append(Change("step", key, f"{path} {text}", mag, step=x["index"]))
    return out


# Coordinates that define each object type, and which of them are positions (pairs) or sizes.
_POSITIONS = {"point": [("x", "y", "")], "line": [("x1", "y1", " start"), ("x2", "y2", " end")],
              "circle": [("cx", "cy", " centre")]}
_SIZES = {"circle": ["r"], "length": ["value"]}


def _object_changes(oa: Mapping[str, dict], ob: Mapping[str, dict], tol: float) -> list[Change]:
    out: list[Change] = []
    for name in list(oa) + [n for n in ob if n not in oa]:
        if name not in ob:
            out.append(Change("missing", name, f"{oa[name]['type']} only in A"))
            continue
        if name not in oa:
            out.append(Change("extra", name, f"{ob[name]['type']} only in B"))
            continue
        x, y = oa[name], ob[name]
        if x["type"] != y["type"]:
            out.append(Change("object", name, f"type {x['type']} -> {y['type']}"))
            continue
        kind = x["type"]
        handled: set[str] = {"type"}
        try:
            moves = []
            for fx, fy, label in _POSITIONS.get(kind, []):
                handled |= {fx, fy}
                p, q = (float(x[fx]), float(x[fy])), (float(y[fx]), float(y[fy]))
                moves.append((math.dist(p, q), p, q, label))
            if moves and max(m[0] for m in moves) > tol:
                d, p, q, label = max(moves, key=lambda m: m[0])
                out.append(Change("moved", name, f"{kind}{label} moved by {format(d, '.3g')}: "
                                  f"({_fmt(p[0])}, {_fmt(p[1])}) -> ({_fmt(q[0])}, {_fmt(q[1])})", d))
            for f in _SIZES.get(kind, []):
                handled.add(f)
                u, v = float(x[f]), float(y[f])
                if abs(u - v) > tol:
                    out.append(Change("resized", name, f"{kind} {f} {_fmt(u)} -> {_fmt(v)} "
                                      f"(by {format(abs(u - v), '.3g')})", abs(u - v)))
        except (KeyError, TypeError, ValueError):
            handled = {"type"}  # not the documented shape: compare it field by field below
        rest_x = {k: v for k, v in x.items() if k not in handled}
        rest_y = {k: v for k, v in y.items() if k not in handled}
        for path, text, mag in _value_changes(rest_x, rest_y, tol):
            out.append(Change("object", name, f"{kind} {path} {text}", mag))
    return out
