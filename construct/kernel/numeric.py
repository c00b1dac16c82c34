"""Numbers from outside -- a JSON file, a caller -- turned into floats, their magnitude checked first.

JSON has no limit on an integer's size, and Python reads ``1`` followed by
400 zeros as an exact ``int``; ``float()`` of it (and ``math.isfinite`` of
it) raise ``OverflowError``.  Every reader of a number a file or a caller can
give goes through :func:`as_float` (or asks :func:`is_finite`, which never
raises), so that such a number is refused where it is read, naming the field.

>>> as_float(2, "the given 'r'")
2.0
>>> as_float(10 ** 400, "the given 'r'")
Traceback (most recent call last):
...
construct.kernel.errors.InvalidParameter: the given 'r' must be a finite number, got 1000000000...0000000000 (an integer of 401 digits, beyond any float)
>>> is_finite(10 ** 400), is_finite(float("nan")), is_finite(True), is_finite(3)
(False, False, False, True)
"""

from __future__ import annotations

import math
import numbers
import sys
from typing import Any, Iterator

from .errors import ConstructError, InvalidParameter

__all__ = ["FLOAT_MAX", "is_finite", "as_float", "shown", "json_number_problems"]

#: The largest finite float; an integer beyond it has no float.
FLOAT_MAX = sys.float_info.max


def is_finite(value: Any) -> bool:
    """Whether *value* is a real number (not a bool) with a finite float; never raises.

    An int is compared with the largest float exactly (Python compares an int
    and a float without converting either), so a 400-digit integer is simply
    not finite here.
    """
    if isinstance(value, bool):
        return False
    if isinstance(value, float):
        return math.isfinite(value)
    if isinstance(value, int):
        return -FLOAT_MAX <= value <= FLOAT_MAX
    if isinstance(value, numbers.Real):
        try:
            return math.isfinite(float(value))
        except (OverflowError, ValueError, TypeError):
            return False
    return False


def shown(value: Any, limit: int = 60) -> str:
    """*value* as an error message quotes it: a huge integer by its first and last digits and its length
    (its repr would be as long as the number, and Python refuses the repr of one over 4300 digits)."""
    if isinstance(value, int) and not isinstance(value, bool) and not -FLOAT_MAX <= value <= FLOAT_MAX:
        digits = _digits(value)
        sign = "-" if value < 0 else ""
        return f"{sign}{digits[:10]}...{digits[-10:]} (an integer of {len(digits)} digits, beyond any float)"
    try:
        text = repr(value)
    except ValueError:  # an int too long for its repr
        return f"<{type(value).__name__}>"
    return text if len(text) <= limit else text[:limit - 3] + "..."


def _digits(value: int) -> str:
    try:
        return str(abs(value))
    except ValueError:  # more digits than Python turns into text
        return "9" * 20 + "0" * 4300  # only the count and the ends are shown; the count is then a bound


def as_float(value: Any, what: str, error: type[ConstructError] = InvalidParameter) -> float:
    """*value* as a float when it is a finite real number, else *error* naming *what*."""
    if type(value) is float and math.isfinite(value):
        return value
    if is_finite(value):
        return float(value)
    raise error(f"{what} must be a finite number, got {shown(value)}")


def json_number_problems(data: Any, path: str = "") -> Iterator[tuple[str, Any]]:
    """(path, value) of every number in parsed JSON *data* that has no float (iteratively, in order)."""
    stack: list[tuple[str, Any]] = [(path, data)]
    while stack:
        where, v = stack.pop()
        if isinstance(v, dict):
            stack.extend((f"{where}.{k}" if where else str(k), x) for k, x in reversed(list(v.items())))
        elif isinstance(v, (list, tuple)):
            stack.extend((f"{where}[{i}]", x) for i, x in reversed(list(enumerate(v))))
        elif isinstance(v, int) and not isinstance(v, bool) and not -FLOAT_MAX <= v <= FLOAT_MAX:
            yield where, v
