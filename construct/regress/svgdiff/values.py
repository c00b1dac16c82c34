"""Numbers and values of an SVG as the diff reads them: parsed, compared within a tolerance, shown.

Part of :mod:`construct.regress.svgdiff`.
"""

from __future__ import annotations

import re
from typing import Any

from ...kernel.errors import ConstructError

DEFAULT_TOLERANCE = 1e-6
"""Drawing units; our goldens are written with far more digits than this."""


class SvgFormatError(ConstructError, ValueError):
    """An input is not a readable SVG drawing (not XML, no <svg> root, malformed geometry)."""


class SvgTooLargeError(SvgFormatError):
    """A drawing would be larger than the reader's stated limit (:data:`MAX_ELEMENTS` elements).

    Raised before the drawing is worked out, so that an SVG whose ``<use>``
    references double at every level (a few KB that expand to millions of
    elements) is refused in a moment instead of read until memory runs out.
    *source* names the file, *limit* the bound it would pass.
    """

    def __init__(self, message: str, *, source: str, limit: int):
        super().__init__(message)
        self.source = source
        self.limit = limit

    def __reduce__(self):
        return (_too_large, (str(self), self.source, self.limit))


def _too_large(message: str, source: str, limit: int) -> SvgTooLargeError:
    return SvgTooLargeError(message, source=source, limit=limit)


#: The most elements a drawing may hold, counted after every ``<use>`` is expanded (and, as
#: parsed, before): twice the largest drawing ``construct bench --diff-million`` reads.  A
#: million elements take about 1 GB to read; our figures hold a few thousand.
MAX_ELEMENTS = 2_000_000

#: The most characters the names (keys) of a drawing's elements may take together: an element
#: drawn through ``<use>`` is named by the ids along its references (``outer/inner/id``).
#: A million elements named as our renderer names them take about 10,000,000.
MAX_KEY_CHARS = 200_000_000

#: The most checks of a style rule against an element a drawing may take (a few seconds of work).
#: Rules are looked up by the id, class or tag they need and each look is worked out once, so our
#: drawings take a few hundred; only a sheet with a rule for every one of many different elements
#: comes near.
CSS_MATCH_BUDGET = 10_000_000

for _cls in (SvgFormatError, SvgTooLargeError):
    _cls.__module__ = "construct.regress.svgdiff"  # raised and documented as the package's own
del _cls


# --------------------------------------------------------------------------- numbers

NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
NUMBER_RE = re.compile(NUMBER)
# A number inside free text (animation values, CSS): not glued to a word or a '#'.
_FREE_NUMBER_RE = re.compile(r"(?<![\w#.])" + NUMBER)
UNITS = {"": 1.0, "px": 1.0, "mm": 96 / 25.4, "cm": 96 / 2.54, "in": 96.0, "pt": 96 / 72, "pc": 16.0,
         "em": 16.0, "ex": 8.0}  # em/ex: the initial font size, 16 px; good enough for a diff
LENGTH_RE = re.compile(r"\s*(" + NUMBER + r")\s*(px|mm|cm|in|pt|pc|em|ex|%)?\s*", re.I)


def format_number(x: float) -> str:
    """Fixed formatting for reports: up to 10 significant digits, no ``-0``.

    >>> format_number(0.010000000000000009), format_number(-0.0), format_number(123.0)
    ('0.01', '0', '123')
    """
    s = format(x, ".10g")
    return "0" if s in ("-0", "0") else s


def format_magnitude(x: float) -> str:
    """A size of a change as a report prints it: three significant digits.

    >>> format_magnitude(0.0099999), format_magnitude(1234.5)
    ('0.01', '1.23e+03')
    """
    return format(x, ".3g")


def parse_numbers(text: str, where: str) -> list[float]:
    """The numbers of a list like ``"1,2 3e1 -4"``; anything else is bad input."""
    if re.sub(r"[\s,]", "", NUMBER_RE.sub(" ", text)):
        raise SvgFormatError(f"{where}: not a list of numbers: {text!r}")
    return [float(t) for t in NUMBER_RE.findall(text)]


def tokenise(text: str) -> tuple[Any, ...]:
    """Free text as words and numbers, so ``1.50s`` equals ``1.5s`` and ``0;1`` equals ``0; 1``.

    Separators stay in the words (one space, none around punctuation), so
    ``"".join`` of the shown tokens reads like the source.

    >>> tokenise(" 0;  1.50 ; 2e1s ")
    (0.0, ';', 1.5, ';', 20.0, 's')
    >>> show_value(tokenise("translate(1.50, 2)  scale(2)"))
    'translate(1.5,2) scale(2)'
    """
    out: list[Any] = []
    pos = 0
    text = " ".join(text.split())

    def word(w: str) -> None:
        w = re.sub(r"\s*([;,:=])\s*", r"\1", w)
        w = re.sub(r"\(\s+", "(", re.sub(r"\s+\)", ")", w))
        if w:
            out.append(w)

    for m in _FREE_NUMBER_RE.finditer(text):
        word(text[pos:m.start()])
        out.append(float(m.group()))
        pos = m.end()
    word(text[pos:])
    if out and isinstance(out[0], str):
        out[0] = out[0].lstrip() or out[0]
    if out and isinstance(out[-1], str):
        out[-1] = out[-1].rstrip() or out[-1]
    return tuple(w for w in out if w != "")


def values_close(x: Any, y: Any, tol: float) -> bool:
    """Are two nested values equal, numbers within *tol*?"""
    if isinstance(x, float) and isinstance(y, float):
        return abs(x - y) <= tol or x == y
    if isinstance(x, tuple) and isinstance(y, tuple):
        return len(x) == len(y) and all(values_close(p, q, tol) for p, q in zip(x, y))
    return x == y


def show_value(value: Any) -> str:
    """A normalised value as text.

    >>> show_value((0.0, 0.0, 960.0, 813.91)), show_value(("xMidYMid", "meet")), show_value((1.5, "s"))
    ('0 0 960 813.91', 'xMidYMid meet', '1.5s')
    """
    if isinstance(value, float):
        return format_number(value)
    if isinstance(value, tuple):
        # Words from tokenise carry their own separators; two numbers or two
        # plain words in a row (a viewBox, a split list) need a space.
        out = ""
        for i, v in enumerate(value):
            if i and isinstance(v, str) == isinstance(value[i - 1], str):
                out += " "
            out += show_value(v)
        return out
    return str(value)


def numeric_difference(x: Any, y: Any) -> float | None:
    """Largest numeric difference between two values of the same shape, else None."""
    if isinstance(x, float) and isinstance(y, float):
        return abs(x - y)
    if isinstance(x, tuple) and isinstance(y, tuple) and len(x) == len(y):
        ds = [numeric_difference(p, q) for p, q in zip(x, y)]
        if all(d is not None for d in ds) and ds:
            return max(ds)  # type: ignore[type-var]
        if all(d is not None or p == q for d, p, q in zip(ds, x, y)):
            known = [d for d in ds if d is not None]
            return max(known) if known else None
    return None
