"""One exception tree for the whole library.

Every message names the step (when there is one), the instrument and the
offending values, so that a failure in a 400-step replay points at its cause.
"""

from __future__ import annotations

__all__ = [
    "ConstructError",
    "InvalidParameter",
    "UnknownConstruction",
    "GeometryError",
    "NoIntersection",
    "DegenerateObject",
    "StepError",
    "ProtocolFormatError",
    "OutputError",
]


class ConstructError(Exception):
    """Base class of every error this library raises on purpose."""


class InvalidParameter(ConstructError, ValueError):
    """A given (crank radius, rod ratio, number of parts, ...) is out of range."""


class UnknownConstruction(ConstructError, KeyError):
    """No construction is registered under that name."""

    def __str__(self) -> str:  # KeyError would quote the message
        return str(self.args[0]) if self.args else "unknown construction"


class GeometryError(ConstructError):
    """A geometric operation has no result (parallel lines, circles that do not meet)."""


class NoIntersection(GeometryError):
    """Two curves that a step intersects do not meet."""


class DegenerateObject(GeometryError):
    """A line through two equal points, a circle of zero or non-finite radius."""


class StepError(ConstructError):
    """A step of a protocol failed; wraps the geometric cause and names the step."""

    def __init__(self, message: str, *, step_index: int | None = None, tool: str | None = None):
        super().__init__(message)
        self.step_index = step_index
        self.tool = tool


class ProtocolFormatError(ConstructError, ValueError):
    """A protocol file is malformed or refers to objects it never made."""


class OutputError(ConstructError, OSError):
    """An output folder cannot be created or written."""
