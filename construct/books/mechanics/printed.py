"""Seed 002 (a mechanics text, § 146–147, two cranks at 90°): every printed number, as printed.

The strings are the book's, with its decimal comma (``0,6211``) and angles
written ``19° 12'`` as in :mod:`construct.books.anhang_ii.printed`.  Nothing is
rounded or "fixed"; :mod:`construct.books.mechanics.errata` compares each with the
value it claims to be.

What the numbers claim (the seed's notation: crank angle α from the dead
centre of the first crank, the second 90° ahead, rods pushed by Q):

* ``sin_2alpha``  sin 2α = (4/π)² − 1 at the extremes of the speed (infinite rod);
* ``alpha1``, ``alpha2``  the two angles of the first quadrant that satisfy it
  (least and greatest speed);
* ``vmin_coefficient``  v_min = v1(1 − 0,0422·Qr/((m1 + m2)v1²)): the magnitude
  of 1 + sin α1 − cos α1 − (4/π)α1;
* ``equal_speed_spacing``  "überhaupt in Abständen von 45° dieselbe
  Geschwindigkeit v1": where the excess work is zero inside the first quadrant.

>>> [(p.quantity, p.text) for p in PRINTED][:2]
[('sin_2alpha', '0,6211'), ('alpha1', "19° 12'")]
"""

from __future__ import annotations

from ..printed import Printed

__all__ = ["SOURCE", "PRINTED", "FIGURE"]

#: The book's name (construct.constructions.phrases.BOOKS: author, title, year): ``construct errata --book mechanics``.
SOURCE = "mechanics"

#: The figure the seed refers to: the speeds as radii on the crank positions.
FIGURE = "Fig. 566"


PRINTED: tuple[Printed, ...] = (
    Printed("§ 146", "sin 2α = (4/π)² − 1", "value", "0,6211", "sin_2alpha"),
    Printed("§ 146", "α₁ (kleinste Geschwindigkeit)", "value", "19° 12'", "alpha1"),
    Printed("§ 146", "α₂ (größte Geschwindigkeit)", "value", "70° 48'", "alpha2"),
    Printed("§ 146", "v_min = v₁(1 − c·Qr/((m₁+m₂)v₁²))", "value", "0,0422", "vmin_coefficient"),
    Printed("§ 146", "v = v₁ in Abständen von", "value", "45°", "equal_speed_spacing"),
)
