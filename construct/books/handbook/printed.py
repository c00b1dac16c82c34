"""Seed 001 (Kolbenüberdrucklinie, "Einfluß der Massenkräfte", Tafel I): every printed number as printed.

The worked example of the high-pressure cylinder of the engine of Tafel I:
piston areas, the weights of the reciprocating parts, the crank-pin speed and
the largest mass forces; and the division of the semicircle.  The strings are
the seed's with the decimal comma written as a point; nothing is rounded or
"fixed" here (the errata in :mod:`construct.books.handbook.errata` say which agree).

>>> [v.text for v in worked_example()][:3]
['1546.3', '1511.9', '830']
>>> GIVEN["bore_cm"], GIVEN["rpm"]
(45.0, 50.0)
"""

from __future__ import annotations

from ..printed import Printed

__all__ = ["SOURCE", "GIVEN", "PART_WEIGHTS", "worked_example"]

#: The book's name (construct.constructions.phrases.BOOKS: author, title, year): ``construct errata --book handbook``.
SOURCE = "handbook"

#: The data the example starts from, as printed (not results: nothing to check).
GIVEN = {"bore_cm": 45.0, "tail_rod_cm": 7.5, "piston_rod_cm": 10.0, "rpm": 50.0, "crank_radius_m": 0.4,
         "rod_length_m": 2.0, "g": 9.81}

#: "Einzelgewichte" in kg, as printed: high-pressure piston, low-pressure piston, piston rod, pump piston
#: with rod and coupling, crosshead, connecting rod; G takes "1/2 bis 2/3" of the connecting rod.
PART_WEIGHTS = {"hp_piston": 122.0, "lp_piston": 282.0, "piston_rod": 122.0, "pump_piston": 282.0,
                "crosshead": 190.0, "connecting_rod": 220.0}


def worked_example() -> list[Printed]:
    """The printed results of the example, in text order."""
    t = "Tafel I"
    return [
        Printed(t, "F'", "cm²", "1546.3", "area_cover"),
        Printed(t, "F''", "cm²", "1511.9", "area_crank"),
        Printed(t, "G high-pressure side", "kg", "830", "weight_hp"),
        Printed(t, "G low-pressure side", "kg", "990", "weight_lp"),
        Printed(t, "v", "m/s", "2.095", "speed"),
        Printed(t, "P_b,max high-pressure side", "kg", "1115", "pbmax_hp"),
        Printed(t, "P_b,max low-pressure side", "kg", "1330", "pbmax_lp"),
        Printed("semicircle", "9 parts", "degrees", "20", "step_9"),
        Printed("semicircle", "18 parts", "degrees", "10", "step_18"),
    ]
