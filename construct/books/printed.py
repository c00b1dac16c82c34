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

from dataclasses import KW_ONLY, dataclass

__all__ = ["Printed", "PrintedFormula"]


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
