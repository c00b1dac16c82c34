"""Reading a protocol file: a bounded read, a JSON parse that cannot blow the stack, and the record checks.

Everything here runs once, when a file is loaded, never in the replay loop.
Each error names the file's field, the step, the value and what is allowed.

>>> check_format({"format": "construct-protocol/7"})
Traceback (most recent call last):
...
construct.kernel.errors.ProtocolFormatError: protocol format 'construct-protocol/7' is not one this library reads (construct-protocol/1, construct-protocol/2)
>>> step_fields({"index": 4.7, "tool": "compass", "op": "line", "inputs": [], "outputs": ["g"],
...              "caption": {"de": "", "en": ""}}, 4)
Traceback (most recent call last):
...
construct.kernel.errors.ProtocolFormatError: step 4: 'index' must be the whole number 4 (the step's place in the list), got 4.7
"""

from __future__ import annotations

import json
import re
from types import MappingProxyType
from collections.abc import Mapping
from typing import Any

from .errors import ProtocolFormatError
from .files import read_regular_file
from .numeric import as_float, shown

__all__ = ["PROTOCOL_FORMAT", "PROTOCOL_FILE_FORMAT", "KNOWN_FORMATS", "TOOLS", "ROLES", "PROVENANCE_KINDS",
           "MAX_PROTOCOL_BYTES", "MAX_NESTING", "read_protocol_bytes", "parse_protocol_json", "check_format",
           "check_nesting", "step_fields", "frozen"]

PROTOCOL_FORMAT = "construct-protocol/1"
#: The protocol file: format 1 less the defaults of each step, the group paths in a table ("groups")
#: that each step names by number.  Both load.
PROTOCOL_FILE_FORMAT = "construct-protocol/2"
KNOWN_FORMATS = (PROTOCOL_FORMAT, PROTOCOL_FILE_FORMAT)

#: The instruments.  "intersect" marks where two drawn curves cross: no new
#: instrument, but a step of its own because a choice is made there.  "curve"
#: is the draftsman's French curve (Curvenlineal): it draws a smooth line
#: through constructed points, it constructs nothing.
TOOLS = ("given", "straightedge", "compass", "dividers", "intersect", "neusis", "curve", "planimeter")

#: How a step's objects are drawn: "result" heavy, "construction" thin, "auxiliary" may be hidden.
ROLES = ("construction", "result", "auxiliary")

PROVENANCE_KINDS = ("given", "exact", "approximate", "neusis", "trial")

#: The largest protocol file read, in bytes (64 MiB).  The largest protocol this library writes is
#: about 27 MiB (the crank at 3072 parts by Dürer's division, 62,000 steps; 3600 parts by the
#: dividers are 15 MiB), the largest in the gallery 0.9 MB: the limit leaves room for twice the
#: largest and stops ``--protocol /dev/zero`` or a runaway file at a bounded cost in memory.
MAX_PROTOCOL_BYTES = 64 * 2**20

#: How deeply a protocol's free-form data (its params) may nest.  What this library writes nests 2
#: deep there (7 in the whole file); Python's own recursion limit is about 1000, and a file nested
#: 100,000 deep must be an error, not a RecursionError.
MAX_NESTING = 32

_STEP_KEYS = ("index", "tool", "op", "inputs", "outputs", "params", "caption", "provenance", "group", "role",
              "labels")


def _short(value: Any, limit: int = 60) -> str:
    return shown(value, limit)


def read_protocol_bytes(path: Any) -> bytes:
    """The bytes of a protocol file, at most :data:`MAX_PROTOCOL_BYTES` of them.

    Only a regular file is read (:func:`construct.kernel.files.read_regular_file`):
    its size is known before reading, and nothing can make the read wait (a
    FIFO with no writer) or run on forever (``/dev/zero``).
    """
    return read_regular_file(path, limit=MAX_PROTOCOL_BYTES, what="protocol file", error=ProtocolFormatError)


def parse_protocol_json(text: str | bytes, label: str = "protocol") -> Any:
    """The parsed JSON of a protocol, or a ProtocolFormatError (never a RecursionError).

    >>> parse_protocol_json("[" * 100_000)
    Traceback (most recent call last):
    ...
    construct.kernel.errors.ProtocolFormatError: protocol: not a JSON protocol: nested too deeply
    """
    if not isinstance(text, (str, bytes, bytearray)):
        raise ProtocolFormatError(f"{label}: the text of a protocol is a str or bytes, got {type(text).__name__}")
    try:
        data = json.loads(text)
    except RecursionError:
        raise ProtocolFormatError(f"{label}: not a JSON protocol: nested too deeply") from None
    except ValueError as exc:  # JSONDecodeError, UnicodeDecodeError, an integer of more than 4300 digits
        raise ProtocolFormatError(f"{label}: not a JSON protocol: {exc}") from None
    if _may_hold_surrogate(text):
        where = _lone_surrogate(data)
        if where is not None:
            raise ProtocolFormatError(f"{label}: {where} holds a lone surrogate (a half of a UTF-16 pair, "
                                      f"\\ud800-\\udfff), which is not text; no name or caption can hold one")
    return data


def _may_hold_surrogate(text: str | bytes) -> bool:
    """Whether the text of a file may hold a lone surrogate: a JSON escape (``\\u``), a surrogate itself
    (text given as str) or its UTF-8-like bytes (lead byte 0xED; json reads those from bytes too).  Only
    then are the parsed strings searched, one by one; the usual protocol is passed over in a scan."""
    if isinstance(text, str):
        if "\\u" in text:
            return True
        try:
            text.encode("utf-8")
        except UnicodeEncodeError:
            return True
        return False
    return b"\\u" in text or b"\xed" in text


def _lone_surrogate(data: Any) -> str | None:
    """Where in parsed JSON a string (or a key) holds a lone surrogate, as a path; None when none does.

    A surrogate pair written as two escapes is one character once parsed; what is left is a lone half,
    which no UTF-8 file, terminal or SVG can hold.
    """
    stack: list[tuple[str, Any]] = [("the protocol", data)]
    while stack:
        where, v = stack.pop()
        if isinstance(v, str):
            if _SURROGATE.search(v):
                return where
        elif isinstance(v, dict):
            for k, x in v.items():
                if _SURROGATE.search(k):
                    return f"a key of {where}"
                stack.append((f"{where}.{k}" if where != "the protocol" else str(k), x))
        elif isinstance(v, list):
            stack.extend((f"{where}[{i}]", x) for i, x in enumerate(v))
    return None


_SURROGATE = re.compile("[\ud800-\udfff]")


def check_format(d: Mapping[str, Any]) -> str:
    """The format a protocol declares; a file without the key reads as format 1.

    Every file this library has written carries the key; a dict without it is
    the in-memory form :meth:`Protocol.as_dict` also produces and a user may
    assemble by hand, which is format 1.  Everything else in it is checked as
    strictly either way, so taking it costs no safety.  An unknown value is
    refused: it was written by another program, or a later version.
    """
    fmt = d.get("format", PROTOCOL_FORMAT)
    if not isinstance(fmt, str) or fmt not in KNOWN_FORMATS:
        raise ProtocolFormatError(f"protocol format {_short(fmt)} is not one this library reads "
                                  f"({', '.join(KNOWN_FORMATS)})")
    return fmt


def check_nesting(value: Any, limit: int = MAX_NESTING, what: str = "protocol") -> None:
    """Refuse data nested deeper than *limit* (iteratively: deep data cannot blow the stack here)."""
    stack = [(value, 0)]
    while stack:
        v, depth = stack.pop()
        if isinstance(v, Mapping):
            children = v.values()
        elif isinstance(v, (list, tuple)):
            children = v
        else:
            continue
        if depth >= limit:
            raise ProtocolFormatError(f"{what} is nested more than {limit} levels deep")
        stack.extend((c, depth + 1) for c in children)


def frozen(value: Any, depth: int = 0) -> Any:
    """JSON lists become tuples and objects read-only mappings, so that params stay hashable and immutable."""
    if depth > MAX_NESTING:
        raise ProtocolFormatError(f"protocol data is nested more than {MAX_NESTING} levels deep")
    if isinstance(value, list):
        return tuple(frozen(v, depth + 1) for v in value)
    if isinstance(value, dict):
        return MappingProxyType({k: frozen(v, depth + 1) for k, v in value.items()})
    return value


def _names(value: Any, where: str, field: str) -> tuple[str, ...]:
    if not isinstance(value, (list, tuple)) or not all(isinstance(n, str) and n for n in value):
        raise ProtocolFormatError(f"{where}: {field!r} must be a list of object names, got {_short(value)}")
    return tuple(value)


def _text(value: Any, where: str, field: str) -> str:
    if not isinstance(value, str):
        raise ProtocolFormatError(f"{where}: {field} must be text, got {_short(value)}")
    return value


def step_fields(d: Any, position: Any, table: Any = None) -> dict[str, Any]:
    """The fields of a :class:`~construct.kernel.protocol.Step` from a step of a protocol file, each checked.

    *position* is the step's place in the list (1-based; None: take the index as
    given), *table* the file's group paths (format 2 names a step's group by
    its number there; None: format 1, which names no group by number).  The op and its parameters are checked against the op
    table when the protocol is compiled.
    """
    where = f"step {position}" if position is not None else "step"
    if not isinstance(d, Mapping):
        raise ProtocolFormatError(f"{where} must be an object, got {_short(d)}")
    unknown = [k for k in d if k not in _STEP_KEYS]
    if unknown:
        raise ProtocolFormatError(f"{where}: unknown field {_short(unknown[0])}; a step has {', '.join(_STEP_KEYS)}")
    for key in ("index", "tool", "op", "inputs", "outputs", "caption"):
        if key not in d:
            raise ProtocolFormatError(f"malformed {where}: no {key!r} (a step needs index, tool, op, inputs, "
                                      f"outputs and caption)")
    index = d["index"]
    if position is None:
        if not isinstance(index, int) or isinstance(index, bool) or index < 1:
            raise ProtocolFormatError(f"step: 'index' must be a whole number >= 1, got {_short(index)}")
        where = f"step {index}"
    elif type(index) is not int or index != position:
        raise ProtocolFormatError(f"{where}: 'index' must be the whole number {position} (the step's place in the "
                                  f"list), got {_short(index)}")
    tool = d["tool"]
    if not isinstance(tool, str) or tool not in TOOLS:
        raise ProtocolFormatError(f"{where}: 'tool' is {_short(tool)}; the instruments are {', '.join(TOOLS)}")
    op = d["op"]
    if not isinstance(op, str) or not op:
        raise ProtocolFormatError(f"{where}: 'op' must be the name of an operation, got {_short(op)}")
    inputs = _names(d["inputs"], where, "inputs")
    outputs = _names(d["outputs"], where, "outputs")
    if len(set(outputs)) != len(outputs):
        raise ProtocolFormatError(f"{where}: 'outputs' names an object twice: {list(outputs)!r}")
    params = d.get("params")
    if params is None:
        params = {}
    if not isinstance(params, Mapping) or not all(isinstance(k, str) for k in params):
        raise ProtocolFormatError(f"{where}: 'params' must be an object, got {_short(params)}")
    cap = d["caption"]
    if not isinstance(cap, Mapping) or set(cap) != {"de", "en"}:
        raise ProtocolFormatError(f"{where}: 'caption' must be an object with 'de' and 'en', got {_short(cap)}")
    caption = (_text(cap["de"], where, "caption 'de'"), _text(cap["en"], where, "caption 'en'"))
    return {
        "index": index,
        "tool": tool,
        "op": op,
        "inputs": inputs,
        "outputs": outputs,
        "params": MappingProxyType(frozen(dict(params), 1)),
        "caption": caption,
        "provenance": _provenance(d.get("provenance"), where),
        "group": _group(d.get("group"), where, table),
        "role": _role(d.get("role", "construction"), where),
        "labels": _labels(d.get("labels"), where, outputs),
    }


def _provenance(prov: Any, where: str) -> tuple[str, str | None, float | None]:
    if prov is None:
        return ("exact", None, None)
    if not isinstance(prov, Mapping) or not set(prov) <= {"kind", "method", "error"}:
        raise ProtocolFormatError(f"{where}: 'provenance' must be an object with 'kind' and optionally 'method' "
                                  f"and 'error', got {_short(prov)}")
    kind = prov.get("kind")
    if not isinstance(kind, str) or kind not in PROVENANCE_KINDS:
        raise ProtocolFormatError(f"{where}: provenance 'kind' is {_short(kind)}; "
                                  f"the kinds are {', '.join(PROVENANCE_KINDS)}")
    method, error = prov.get("method"), prov.get("error")
    if method is not None and not isinstance(method, str):
        raise ProtocolFormatError(f"{where}: provenance 'method' must be text or null, got {_short(method)}")
    if error is not None:
        error = as_float(error, f"{where}: provenance 'error'", ProtocolFormatError)
    return (kind, method, error)


def _group(g: Any, where: str, table: Any) -> tuple[str, ...]:
    if g is None:
        return ()
    if isinstance(g, int) and not isinstance(g, bool):  # format 2: the group path by its number in the table
        if table is None:
            raise ProtocolFormatError(f"{where} names its group by number ({g}), which only format "
                                      f"{PROTOCOL_FILE_FORMAT} does; this protocol is of format {PROTOCOL_FORMAT} "
                                      f"(or has no 'format')")
        if not 0 <= g < len(table):
            raise ProtocolFormatError(f"{where} names group {g}; the file's 'groups' table has {len(table)}")
        g = table[g]
    if not isinstance(g, (list, tuple)) or not all(isinstance(t, str) for t in g):
        raise ProtocolFormatError(f"{where}: 'group' must be a list of group titles (or, in format 2, a number "
                                  f"in the 'groups' table), got {_short(g)}")
    return tuple(g)


def _role(role: Any, where: str) -> str:
    if not isinstance(role, str) or role not in ROLES:
        raise ProtocolFormatError(f"{where}: 'role' is {_short(role)}; the roles are {', '.join(ROLES)}")
    return role


def _labels(labels: Any, where: str, outputs: tuple[str, ...]) -> tuple[tuple[str, str], ...]:
    if labels is None:
        return ()
    if not isinstance(labels, Mapping) or not all(isinstance(v, str) for v in labels.values()):
        raise ProtocolFormatError(f"{where}: 'labels' must map object names to text, got {_short(labels)}")
    # a letter for an object the step does not make is never drawn: harmless, and left as it is
    return tuple(sorted(labels.items()))
