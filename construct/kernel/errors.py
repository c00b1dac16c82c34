"""One exception tree for the whole library.

Every message names the step (when there is one), the instrument and the
offending values, so that a failure in a 400-step replay points at its cause.
Geometry raised inside a step is re-raised as the same class with the step's
index, instrument and operation attached (:meth:`StepError.at_step`), so a
build and a replay of the same protocol fail with the same error.

>>> e = NoIntersection("circle about (0, 0) with radius 1 and circle about (5, 0) with radius 1 do not meet")
>>> isinstance(e, StepError), isinstance(e, GeometryError)
(True, True)
>>> str(e.at_step(7, "compass", "intersect", "C7 where rod7 meets axis"))
'step 7 (compass: C7 where rod7 meets axis): circle about (0, 0) with radius 1 and circle about (5, 0) with radius 1 do not meet'
"""

from __future__ import annotations

import difflib
from typing import Iterable

__all__ = [
    "did_you_mean",
    "ConstructError",
    "InvalidParameter",
    "UnknownConstruction",
    "ProtocolFormatError",
    "InputFileError",
    "OutputError",
    "MissingDependency",
    "StepError",
    "GeometryError",
    "NoIntersection",
    "DegenerateObject",
    "RuleError",
    "UnknownObject",
    "WrongInput",
    "MissingGiven",
    "DuplicateName",
    "ConstructWarning",
    "HiddenLabelWarning",
]


class ConstructError(Exception):
    """Base class of every error this library raises on purpose."""


class InvalidParameter(ConstructError, ValueError):
    """A given (crank radius, rod ratio, number of parts, ...) is out of range."""


class UnknownConstruction(ConstructError, KeyError):
    """No construction is registered under that name."""

    def __str__(self) -> str:  # KeyError would quote the message
        return str(self.args[0]) if self.args else "unknown construction"


class ProtocolFormatError(ConstructError, ValueError):
    """A protocol file is malformed or refers to objects it never made."""


class InputFileError(ConstructError, ValueError):
    """A file to read is missing, not a regular file (a pipe, a device, a folder) or larger than its limit,
    or its contents are not what they must be (a digitised indicator diagram that cannot be read)."""


class OutputError(ConstructError, OSError):
    """An output folder cannot be created or written."""


class MissingDependency(ConstructError, ImportError):
    """An output needs an optional library that is not installed (cairosvg for PDF); names what to install."""


class StepError(ConstructError):
    """A step failed; names the step, its instrument and operation (when raised inside one)."""

    def __init__(self, message: str, *, step_index: int | None = None, tool: str | None = None,
                 op: str | None = None):
        super().__init__(message)
        self.step_index = step_index
        self.tool = tool
        self.op = op

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else type(self).__name__

    def __reduce__(self):
        return (_rebuild, (type(self), str(self), self.step_index, self.tool, self.op))

    def at_step(self, index: int, tool: str, op: str, caption: str) -> "StepError":
        """The same error, its message prefixed by the step that raised it."""
        if self.step_index is not None:
            return self
        return type(self)(f"step {index} ({tool}: {caption}): {self}", step_index=index, tool=tool, op=op)


def _rebuild(cls, message, step_index, tool, op):
    return cls(message, step_index=step_index, tool=tool, op=op)


class GeometryError(StepError):
    """A geometric operation has no result (parallel lines, circles that do not meet)."""


class NoIntersection(GeometryError):
    """Two curves that a step intersects do not meet."""


class DegenerateObject(GeometryError):
    """A line through two equal points, a circle of zero or non-finite radius."""


class RuleError(StepError, ValueError):
    """An intersection rule is unknown, names the wrong number of objects, or is not a rule at all."""


class UnknownObject(StepError, KeyError):
    """A step (or a lookup in a replay) names an object that no step made.

    A KeyError too, so that a :class:`~construct.kernel.protocol.Replay` stays a Mapping
    (``name in replay``, ``replay.get(name)``); ``name`` is the missing object's name.
    """

    def __init__(self, message: str, *, name: str | None = None, **where):
        super().__init__(message, **where)
        self.name = name


class WrongInput(StepError, TypeError):
    """A step was given an object of the wrong kind (a point where a curve is needed, ...)."""


class MissingGiven(StepError, InvalidParameter):
    """A replay lacks a given that a step needs."""


class DuplicateName(StepError, InvalidParameter):
    """A step would make an object under a name an earlier step already used."""


class ConstructWarning(UserWarning):
    """Base class of every warning this library issues: it did what was asked, but not all of it shows."""


class HiddenLabelWarning(ConstructWarning):
    """A style leaves out points a user lettered: a plate (the historical style) shows the results and what
    locates them, so a lettered construction point that locates no result is not drawn, nor is its letter."""


def did_you_mean(word: object, choices: Iterable[str]) -> str:
    """`` (did you mean 'x'?)`` for the choice nearest a misspelt *word*, to end a message with; nothing if none is near.

    >>> did_you_mean("crnk", ["crank", "crank-angle", "two-cranks"]), did_you_mean("zzz", ["crank"])
    (" (did you mean 'crank'?)", '')
    """
    near = difflib.get_close_matches(str(word), list(choices), n=1, cutoff=0.6)
    return f" (did you mean {near[0]!r}?)" if near else ""
