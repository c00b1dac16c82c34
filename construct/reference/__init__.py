"""The books' printed numbers, transcribed as data and never corrected.

Each seed text with printed tables gets one module (``seed000`` for Anhang II,
"Darstellung der Massendrücke").  The values are kept as the strings the book
prints; :mod:`construct.errata` compares them with the true values.

>>> from construct.reference import seed000
>>> seed000.table_1()[0].text
'1'
"""

from __future__ import annotations

__all__ = ["seed000", "seed001"]
