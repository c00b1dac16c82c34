"""What a book prints, as printed: one number (:class:`Printed`) or one formula (:class:`PrintedFormula`).

Every source text lists its printed numbers as :class:`Printed` (its ``printed``
module: :mod:`.anhang_ii.printed`, :mod:`.handbook.printed`,
:mod:`.mechanics.printed`, :mod:`.baumann.printed`), and its errata judge each
against the quantity it claims to be.  Where a number stands is what an
erratum quotes (table, row, column); ``text`` is the book's string, never
rounded or corrected.

>>> p = Printed("Tabelle 1", "60°", "cos ω", "0.5000", "cos_omega", omega_deg=60.0)
>>> p.text, p.quantity, p.resolution, p.rod_ratio
('0.5000', 'cos_omega', None, None)
>>> Printed("§ 146", "α₁", "value", "19° 12'", "alpha1", "1'")
Traceback (most recent call last):
...
TypeError: ...__init__() takes 6 positional arguments but 7 were given
"""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import KW_ONLY, dataclass, replace
from typing import Iterable

__all__ = ["Printed", "PrintedFormula", "in_halves", "decimals_of"]


@dataclass(frozen=True, slots=True)
class Printed:
    """One number as a book prints it: where it stands, what it claims to be, and the string.

    ``table`` is the table or section it stands in, ``row`` and ``column``
    its place there (a number printed in running text has the column
    ``"value"``), ``text`` the string as printed (its decimal comma, a raised
    point ``·563``, angles ``79° 20'``), ``quantity`` the name of what it
    claims to be (the text's errata compute it).  Keyword-only:
    ``resolution`` overrides the last printed place where the book rounds to a
    coarser step than it prints (totals "to 50 kg": ``"50"``; angles to
    ``"10'"``); ``rod_ratio`` L/r, ``omega_deg`` (the crank angle) and
    ``stroke_fraction`` (the piston path x/2r) are set where the claim depends
    on the row it stands in (the tables of seed 000).
    """

    table: str
    row: str
    column: str
    text: str
    quantity: str
    _: KW_ONLY
    resolution: str | None = None
    rod_ratio: int | None = None
    omega_deg: float | None = None
    stroke_fraction: float | None = None


@dataclass(frozen=True, slots=True)
class PrintedFormula:
    """A printed formula (or table header), quoted as printed where the errata find fault with it."""

    table: str
    row: str
    column: str
    text: str


def decimals_of(text: str) -> int | None:
    """How many decimals a printed number shows (its comma, point or raised point); None for angles, fractions.

    >>> decimals_of("0,4525"), decimals_of("·18615"), decimals_of("1115"), decimals_of("79° 20'")
    (4, 5, 0, None)
    """
    m = re.fullmatch(r"(\d*)(?:[,.·](\d+))?", text.strip().lstrip("-"))
    if m is None or not (m.group(1) or m.group(2)):
        return None
    return len(m.group(2) or "")


def in_halves(printed: Iterable[Printed], tables: Iterable[str]) -> tuple[Printed, ...]:
    """One rule for a trailing 5: in a printed table, a number one decimal place beyond the rest of its column that
    ends in 5 is the author's half (0,4525 among 0,274 … is 0,452½; ·18615 among ·2247, ·1583 is ·1861½): it is
    read to half a unit of the place before it.  A number of the running text has no column to show a coarser
    precision, so its last printed place is its unit (0,01825, 0,4655, 24,75).

    A column is the numbers of one table that claim the same kind of quantity (the quantity's name before any
    ``:``).  Returns the numbers, those halves with their ``resolution`` set; the others unchanged.

    >>> col = [Printed("Tabelle G2", f"r{i}", "G2", t, f"t1_g2:{i}") for i, t in enumerate(("0,274", "0,4525", "0,307"))]
    >>> [p.resolution for p in in_halves(col, ("Tabelle G2",))]
    [None, '0.0005', None]
    >>> in_halves(col, ())[1].resolution is None     # not a table: read by its last place
    True
    """
    printed = tuple(printed)
    tables = set(tables)
    columns: dict[tuple[str, str], Counter] = {}
    for p in printed:
        d = decimals_of(p.text)
        if p.table in tables and d is not None:
            columns.setdefault((p.table, p.quantity.split(":")[0]), Counter())[d] += 1
    out = []
    for p in printed:
        d = decimals_of(p.text)
        counts = columns.get((p.table, p.quantity.split(":")[0]))
        if counts and d is not None and p.resolution is None and p.text.endswith("5") and d >= 1:
            usual = counts.most_common(1)[0][0]
            if d == usual + 1:
                p = replace(p, resolution=f"{5 * 10.0 ** -d:.{d}f}")
        out.append(p)
    return tuple(out)
