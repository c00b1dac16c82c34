"""construct: the graphical methods of classic German steam-engine design books, replayed with compass and straightedge.

One import gives everything to build, replay, draw and check a construction:

- :class:`Builder` records a construction step by step with the instruments
  (straightedge, compass, dividers) and their composites; each step is data.
- :class:`Protocol` is the recorded construction; ``replay(givens)`` evaluates
  it again with other givens -- numpy arrays of givens make a *sweep*.
- :class:`Figure` is a protocol with the objects a replay made;
  ``figure.svg(style=...)`` draws it, ``figure.checks()`` checks a book
  construction against the analytic formulas.
- :func:`get` and :func:`names`: the book constructions (``crank``,
  ``crank-angle``, ``inertia-curve``, ...).
- Rules for which intersection a step takes: :func:`nearer`, :func:`farther`,
  :func:`left_of`, :func:`right_of`, :func:`toward`, :func:`only`.
- Errors: every error is a :class:`ConstructError`; a failing step raises a
  :class:`StepError` naming the step, its instrument and the values.  Every
  warning is a :class:`ConstructWarning` (:class:`HiddenLabelWarning`: a plate
  leaves out a point you lettered).

A complete construction -- the midpoint of a segment -- drawn to SVG:

>>> import construct
>>> b = construct.Builder("midpoint", givens={"s": 4.0})
>>> A = b.given_point("A", 0.0, 0.0)
>>> B = b.given_point("B", 1.0, 0.0, unit="s")
>>> M = b.midpoint("M", A, B)
>>> fig = b.figure()
>>> fig.replay["M"]
Point(2.0, 0.0)
>>> fig.protocol.replay({"s": 10.0})["M"]
Point(5.0, 0.0)
>>> fig.svg(style="plain").count("<circle") > 3      # the points and the compass circles
True
>>> construct.get("crank").figure(parts=6, rod_ratio=4.0).checks()[0].ok
True
"""

from __future__ import annotations

from typing import Any

from .constructions import Construction, find, get, names
from .kernel.errors import (ConstructError, ConstructWarning, DegenerateObject, DuplicateName, GeometryError,
                            HiddenLabelWarning, InvalidParameter, MissingGiven, NoIntersection, OutputError,
                            ProtocolFormatError, RuleError, StepError, UnknownConstruction, UnknownObject, WrongInput)

from .kernel import version as _installed_version
from .kernel.geometry import Circle, Length, Line, Point
from .figure import Builder, Figure
from .kernel.protocol import Protocol, Replay
from .kernel.rules import farther, left_of, nearer, only, right_of, toward


__version__ = _installed_version()

__all__ = [
    "__version__",
    # building, replaying, drawing
    "Builder",
    "Protocol",
    "Replay",
    "Figure",
    "Construction",
    "get",
    "names",
    "svg",
    "write_replay",
    # values
    "Point",
    "Line",
    "Circle",
    "Length",
    # rules
    "nearer",
    "farther",
    "left_of",
    "right_of",
    "toward",
    "only",
    # errors
    "ConstructError",
    "InvalidParameter",
    "UnknownConstruction",
    "ProtocolFormatError",
    "OutputError",
    "StepError",
    "GeometryError",
    "NoIntersection",
    "DegenerateObject",
    "RuleError",
    "UnknownObject",
    "WrongInput",
    "MissingGiven",
    "DuplicateName",
    # warnings
    "ConstructWarning",
    "HiddenLabelWarning",
]


def svg(figure: Figure, style: str = "plain", *, upto: int | None = None) -> str:
    """A figure (or its steps 1..upto) as SVG text in a named style: ``plain``, ``historical``, ``teaching``."""
    return _figure(figure, "svg").svg(style=style, upto=upto)


def write_replay(figure: Figure, out_dir, *, style: str = "plain", frames: str = "auto") -> dict:
    """Write a figure's outputs (final SVG, frames, protocol.json, animation, player) into *out_dir*.

    The folder is written whole or not at all.  Works for registered book
    constructions and for protocols of your own.
    """
    from .render.output import write_replay as _write

    if frames not in ("auto", "all", "groups", "none"):
        raise InvalidParameter(f"frames is one of auto, all, groups, none; got {frames!r}")
    fig = _figure(figure, "write_replay")
    book = find(fig.protocol.construction)
    # captioned as its book writes it when a book construction built or replayed it (it checks the figure)
    return _write(book if book is not None and fig.checker == book.check else None, fig, out_dir, style=style,
                  frames=frames)


def _figure(figure: Any, what: str) -> Figure:
    if not isinstance(figure, Figure):
        raise InvalidParameter(f"{what}() takes a Figure (from Builder.figure() or get(name).figure()), "
                               f"got {type(figure).__name__}")
    return figure
