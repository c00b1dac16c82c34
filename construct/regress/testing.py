"""Two figures compared in geometry, for tests (``construct.testing``; shapely.testing is the model).

:func:`assert_figures_equal` passes when two figures -- or a figure and its golden ``protocol.json`` --
have the same steps (instrument, operation, inputs and outputs, parameters, captions, provenance) and
every constructed object within *tolerance* (drawing units), and fails with the protocol diff that
says which step and object differ (:func:`construct.regress.protocoldiff.diff_protocol`).  The pytest
plugin and ``construct verify`` compare protocols through the same :func:`figures_diff`.

>>> import construct
>>> a = construct.get("crank").figure(parts=6)
>>> assert_figures_equal(a, a.with_givens(r=1.0))
>>> assert_figures_equal(a, a.with_givens(rod_ratio=4.0))
Traceback (most recent call last):
...
AssertionError: figures differ: protocol diff crank -> crank (tolerance 1e-09): 36 changes
  param      givens.rod_ratio: 5 -> 4
  resized    L: length value 5 -> 4 (by 1)
...
"""

from __future__ import annotations

import json
from dataclasses import replace
from typing import Any, Mapping

from .change import Diff
from .protocoldiff import DEFAULT_TOLERANCE, diff_protocol

__all__ = ["assert_figures_equal", "figures_diff"]


def _protocol(x: Any) -> tuple[Any, str | None]:
    """What the protocol diff reads of *x* (a figure, a protocol, a protocol.json or its text), and a label."""
    if hasattr(x, "protocol") and hasattr(x, "replay") and not isinstance(x, Mapping):  # a figure
        return json.loads(x.protocol.to_json(x.replay)), x.protocol.construction
    if hasattr(x, "to_json") and hasattr(x, "steps"):  # a protocol: replayed with its own givens
        return json.loads(x.to_json()), x.construction
    return x, None


def figures_diff(a: Any, b: Any, *, tolerance: float = DEFAULT_TOLERANCE) -> Diff:
    """The protocol diff of *a* and *b*: figures, protocols, protocol.json files (paths) or their text."""
    (pa, la), (pb, lb) = _protocol(a), _protocol(b)
    d = diff_protocol(pa, pb, tolerance=tolerance)
    return replace(d, a=la or d.a, b=lb or d.b)


def assert_figures_equal(a: Any, b: Any, *, tolerance: float = DEFAULT_TOLERANCE, err_msg: str = "") -> None:
    """Raise AssertionError, with the steps and objects that differ, unless *a* and *b* agree within
    *tolerance* drawing units (figures, protocols, or protocol.json files and text, in any mix)."""
    __tracebackhide__ = True
    d = figures_diff(a, b, tolerance=tolerance)
    if not d.equal:
        raise AssertionError("figures differ: " + d.report() + (f"\n{err_msg}" if err_msg else ""))
