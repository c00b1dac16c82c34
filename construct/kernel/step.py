"""A step of a construction protocol: what it does (its instrument, op, inputs, outputs, parameters), its caption
in the books' German and in English, and the provenance of what it makes.

Steps are data: frozen, compared and hashed by value, written to and read from protocol files
(:mod:`construct.kernel.protocol_file` checks the fields).  Part of :mod:`construct.kernel.protocol`, which
re-exports these names.

>>> Caption("Kreis um O mit r", "circle about O with r").en
'circle about O with r'
"""

from __future__ import annotations

from dataclasses import dataclass
from collections.abc import Mapping
from typing import Any

from .errors import InvalidParameter
from .protocol_file import PROVENANCE_KINDS, step_fields

__all__ = ["Caption", "Provenance", "Step", "EXACT", "GIVEN", "jsonable"]

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
        """As :meth:`as_dict` for the protocol file, to be written as JSON: defaults left out, the group path as its
        number (the same keys in the same order, made directly: a protocol of 3600 parts writes 32,000 steps)."""
        # (the names as tuples: JSON writes a tuple as the list it is read back as)
        d: dict[str, Any] = {"index": self.index, "tool": self.tool, "op": self.op, "inputs": self.inputs,
                             "outputs": self.outputs}
        if self.params:
            d["params"] = jsonable(self.params)
        d["caption"] = {"de": self.caption.de, "en": self.caption.en}
        p = self.provenance
        if p is not EXACT and p != EXACT:
            d["provenance"] = {k: v for k, v in (("kind", p.kind), ("method", p.method), ("error", p.error))
                               if v is not None}
        if self.group:
            d["group"] = group_ids[self.group]
        if self.role != "construction":
            d["role"] = self.role
        if self.labels:
            d["labels"] = {name: text for name, text in self.labels}
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


#: The types :func:`jsonable` hands back as they are, asked first: a step's parameters are mostly numbers and words
#: (a protocol of 3600 parts writes 32,000 steps; the attribute lookup that misses and the abstract ``Mapping``
#: check cost more than the rest of the step).
_PLAIN = frozenset({str, int, float, bool, type(None)})


def jsonable(value: Any) -> Any:
    if type(value) in _PLAIN:
        return value
    as_json = getattr(value, "as_json", None)
    if as_json is not None:  # a Rule
        return as_json()
    if isinstance(value, (tuple, list)):
        return [jsonable(v) for v in value]
    if isinstance(value, Mapping):
        return {str(k): jsonable(v) for k, v in value.items()}
    return value
