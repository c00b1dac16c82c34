"""Seed 000, Anhang II "Darstellung der Massendrücke": its printed numbers (:mod:`.printed`).

Its errata are judged in :mod:`construct.books.errata`, against the formulas of :mod:`construct.constructions.analytic`.
"""
