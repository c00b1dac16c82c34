"""Numeric checks: a quantity measured on the construction against the analytic value.

Every check states its tolerance and why that tolerance is right (the float
chain of a Euclidean construction, or the known error of an approximate one).

>>> c = Check("demo", measured=0.50000000000001, expected=0.5, tolerance=1e-12, why="float chain")
>>> c.ok, f"{c.error:.1e}"
(True, '1.0e-14')
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Iterable

__all__ = ["Check", "all_ok", "summary"]

#: Euclidean chains of a few hundred steps agree with the formulas to this
#: fraction of the stroke (or radians): each step rounds at ~1e-16, and the
#: worst-conditioned intersections here amplify that by at most ~1e3.
EUCLIDEAN_TOLERANCE = 1e-12


@dataclass(frozen=True, slots=True)
class Check:
    """One constructed quantity compared with its analytic value."""

    name: str
    measured: float
    expected: float
    tolerance: float
    why: str = ""
    unit: str = ""

    @property
    def error(self) -> float:
        return self.measured - self.expected

    @property
    def ok(self) -> bool:
        return math.isfinite(self.measured) and abs(self.error) <= self.tolerance

    def as_dict(self) -> dict[str, Any]:
        return {
            "name": self.name,
            "measured": self.measured,
            "expected": self.expected,
            "error": self.error,
            "tolerance": self.tolerance,
            "ok": self.ok,
            "unit": self.unit,
            "why": self.why,
        }


def all_ok(checks: Iterable[Check]) -> bool:
    return all(c.ok for c in checks)


def summary(checks: list[Check]) -> str:
    """One line: how many passed, and the largest error relative to its tolerance."""
    failed = [c for c in checks if not c.ok]
    worst = max(checks, key=lambda c: abs(c.error) / c.tolerance if c.tolerance else math.inf, default=None)
    text = f"{len(checks) - len(failed)} of {len(checks)} checks pass"
    if worst is not None:
        text += f"; closest to its tolerance: {worst.name}, error {abs(worst.error):.2e} of {worst.tolerance:.1e}"
    return text
