"""The four source texts: what each prints (as printed), its errata, and the formulas that are its own.

One package per text, named after the book rather than the seed file:

- :mod:`.anhang_ii` -- seed 000, Anhang II of a steam-engine design book, "Darstellung der Massendrücke"
  (Tabellen 1 and 2, the characteristic points of the inertia curve);
- :mod:`.handbook` -- seed 001, a machine-elements handbook: the piston over-pressure line of Tafel I;
- :mod:`.mechanics` -- seed 002, a mechanics text, § 146–147: two cranks at 90°;
- :mod:`.baumann` -- seed 004, Baumann (1902) on flywheel weights, with his coefficients
  (:mod:`.baumann.flywheel`) and his error analysis (:mod:`.baumann.excess_error`).

:mod:`.printed` holds the one type every text lists its printed numbers as (:class:`.printed.Printed`, and
:class:`.printed.PrintedFormula` for a formula); :mod:`.errata` what they share besides: reading a printed
number, judging it against the true value, and collecting every text's errata.

>>> from construct.books.errata import errata_of
>>> sorted({e.class_ for e in errata_of("000")})
['agrees', 'arithmetic', 'follows', 'slip', 'typesetting']
"""
