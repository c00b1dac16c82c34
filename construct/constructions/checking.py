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

from ..kernel.errors import ConstructError, ProtocolFormatError, UnknownObject

__all__ = ["Check", "all_ok", "summary", "run_checks"]

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
        error, tolerance = decisive_digits(abs(worst.error), worst.tolerance)
        text += f"; closest to its tolerance: {worst.name}, error {error} of {tolerance}"
    return text


def decisive_digits(a: float, b: float) -> tuple[str, str]:
    """*a* and *b* in exponent notation with as many digits as it takes to see which is larger (at least 2).

    "error 6.12e-05 of 6.1e-05" reads as a failure; the tolerance was 6.128e-05.

    >>> decisive_digits(6.1234e-05, 6.128e-05)
    ('6.12e-05', '6.13e-05')
    >>> decisive_digits(3.2e-13, 1e-12)
    ('3.2e-13', '1.0e-12')
    """
    for digits in range(2, 18):
        fa, fb = f"{a:.{digits - 1}e}", f"{b:.{digits - 1}e}"
        if (float(fa) < float(fb)) == (a < b) and (float(fa) == float(fb)) == (a == b):
            return fa, fb
    return repr(a), repr(b)


def run_checks(construction: Any, figure: Any, model: Any = None) -> list[Check]:
    """The checks of a book construction on *figure*: where every caller runs them.

    The check functions read objects, givens and parameters by the names the
    construction's own build gives them.  A protocol that was truncated or
    edited may lack them or hold something else under a name; that is the
    protocol's fault, reported as a ProtocolFormatError naming what is missing,
    not a KeyError from inside a check.  *model*: what the checks would
    otherwise compute from the givens (a sweep's, taken at this set; see
    ``Construction.sweep_model``).

    >>> from construct import get
    >>> crank = get("crank")
    >>> fig = crank.figure(parts=6)
    >>> short = type(fig.protocol)(fig.protocol.construction, fig.protocol.params, fig.protocol.steps[:10])
    >>> run_checks(crank, type(fig)(short, short.replay()))
    Traceback (most recent call last):
    ...
    construct.kernel.errors.ProtocolFormatError: the protocol of 'crank' lacks the object 'X0' its checks need (truncated or renamed?)
    """
    name = construction.name
    try:
        return construction.checks(figure) if model is None else construction.checks(figure, model=model)
    except UnknownObject as exc:  # a lookup in the replay: Replay[name]
        missing = exc.name if exc.name is not None else str(exc)
        raise ProtocolFormatError(f"the protocol of {name!r} lacks the object {missing!r} its checks need "
                                  f"(truncated or renamed?)") from None
    except ConstructError:  # raised on purpose, already naming its cause
        raise
    except KeyError as exc:  # a given, a parameter or an object's step, looked up by name
        raise ProtocolFormatError(f"the protocol of {name!r} lacks {exc.args[0] if exc.args else exc!r}, which its "
                                  f"checks need (truncated or edited?)") from None
    except (AttributeError, TypeError, ValueError, IndexError, ArithmeticError) as exc:
        # An object of another kind under a checked name, a parameter of another type or value (parts 0): an
        # edited protocol.
        raise ProtocolFormatError(f"the checks of {name!r} cannot read this protocol's figure ({exc}); "
                                  f"was the protocol edited?") from None
