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
- :class:`Check`: what ``figure.checks()`` gives, a measured quantity against
  its analytic value; :class:`Style`: how a figure is drawn.
- Errors: every error is a :class:`ConstructError`; a failing step raises a
  :class:`StepError` naming the step, its instrument and the values.  Every
  warning is a :class:`ConstructWarning` (:class:`HiddenLabelWarning`: a plate
  leaves out a point you lettered).  All of :mod:`construct.kernel.errors` is here.
- :mod:`construct.testing`: :func:`~construct.testing.assert_figures_equal` for
  your own tests.

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

import importlib
import warnings
from typing import Any

from .constructions import Construction, get, names
from .constructions.checking import Check
from .figure import Builder, Figure
from .kernel import errors as _errors
from .kernel import version as _installed_version
from .kernel.errors import InvalidParameter
from .kernel.geometry import Circle, Length, Line, Point
from .kernel.protocol import Protocol, Replay
from .kernel.rules import farther, left_of, nearer, only, right_of, toward

__version__ = _installed_version()

# every error and warning, as kernel/errors.py lists them (one list: a new error is at the front door at once)
globals().update((name, getattr(_errors, name)) for name in _errors.__all__)

__all__ = [
    "__version__",
    # building, replaying, drawing, checking
    "Builder", "Protocol", "Replay", "Figure", "Construction", "Check", "Style", "get", "names",
    # values
    "Point", "Line", "Circle", "Length",
    # rules
    "nearer", "farther", "left_of", "right_of", "toward", "only",
    # errors and warnings
    *_errors.__all__,
]

#: Names loaded when first asked for (``Style`` loads the drawing layer, which ``import construct`` does not).
_LAZY = {"Style": ("construct.render.styles", "Style")}
#: Old names that still work, with a DeprecationWarning, and what to use instead.
_DEPRECATED = {"svg": ("construct", "_svg", "construct.svg(figure) is deprecated; use figure.svg()"),
               "write_replay": ("construct", "_write_replay",
                                "construct.write_replay(figure, out) is deprecated; use figure.write(out)")}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        module, attr = _LAZY[name]
        value = getattr(importlib.import_module(module), attr)
        globals()[name] = value
        return value
    if name in _DEPRECATED:
        module, attr, message = _DEPRECATED[name]
        warnings.warn(message, DeprecationWarning, stacklevel=2)
        return getattr(importlib.import_module(module), attr)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_LAZY) | {"testing"})


def _svg(figure: Figure, style: str = "plain", *, upto: int | None = None) -> str:
    """What ``construct.svg(figure)`` did: ``figure.svg()``."""
    if not isinstance(figure, Figure):
        raise InvalidParameter(f"svg() takes a Figure (from Builder.figure() or get(name).figure()), "
                               f"got {type(figure).__name__}")
    return figure.svg(style=style, upto=upto)


def _write_replay(figure: Figure, out_dir, *, style: str = "plain", frames: str = "auto") -> dict:
    """What ``construct.write_replay(figure, out)`` did: ``figure.write(out)``."""
    if not isinstance(figure, Figure):
        raise InvalidParameter(f"write_replay() takes a Figure (from Builder.figure() or get(name).figure()), "
                               f"got {type(figure).__name__}")
    return figure.write(out_dir, style=style, frames=frames)
