"""Helpers for tests of your own constructions (as ``shapely.testing``).

>>> from construct import Builder
>>> from construct.testing import assert_figures_equal
>>> def midpoint(s):
...     b = Builder("midpoint", givens={"s": s})
...     _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 1.0, 0.0, unit="s"); _ = b.midpoint("M", "A", "B")
...     return b.figure()
>>> assert_figures_equal(midpoint(2.0), midpoint(2.0 + 1e-12))
>>> assert_figures_equal(midpoint(2.0), midpoint(2.2), tolerance=0.01)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
AssertionError: figures differ: protocol diff midpoint -> midpoint (tolerance 0.01): ...
"""

from .regress.testing import assert_figures_equal, figures_diff

__all__ = ["assert_figures_equal", "figures_diff"]
