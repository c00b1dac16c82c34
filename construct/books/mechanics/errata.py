"""Errata of seed 002's printed numbers (§ 146–147, two cranks at 90°).

Each number of :mod:`construct.books.mechanics.printed` beside the value it claims
to be, judged as :mod:`construct.books.errata` judges seed 000 (distance in units of
the last printed place: agrees within half a unit, slip up to 2, else the
cause, "unexplained" until one is named).  The true values come from the book's formulas solved exactly
(:func:`construct.constructions.two_cranks.excess_exact` is the exact
piston law); the note adds what the construction gives (the extreme angles
through Kochański's π) so the reader sees both errors side by side.

A remark the numbers cannot carry: the seed writes the piston path as
r(1 − cos α) ∓ r² sin² α/2l, upper sign on the forward stroke, i.e. measured
from the crank-end dead centre B1; the two-cranks construction starts there
by default (``dead_centre="crank-end"``), while the other books and the
option ``dead_centre="head-end"`` count from the head-end dead centre (piston
path r(1 − cos α) + …).  The excess work from one is the other shifted by
half a turn; the first-quadrant cancellation of the r/2l terms holds in both
(exactly to first order; the exact law leaves −(r/l)³ sin² 2α/16).

>>> rows = {e.row: e for e in entries()}
>>> e = rows["α₁ (kleinste Geschwindigkeit)"]
>>> e.printed, round(e.true, 5), round(e.units, 2), e.class_
("19° 12'", 19.19968, 0.02, 'agrees')
"""

from __future__ import annotations

import math
from fractions import Fraction

from ...constructions.analytic import bisect
from ..errata import Erratum, classify, read_printed
from . import printed as seed002

__all__ = ["entries", "true_value"]


def true_value(quantity: str) -> float:
    """What a printed number of seed 002 claims to be (degrees for angles)."""
    from ...constructions.two_cranks import excess_exact

    s = (4.0 / math.pi) ** 2 - 1.0
    a1 = 0.5 * math.asin(s)
    if quantity == "sin_2alpha":
        return s
    if quantity == "alpha1":
        return math.degrees(a1)
    if quantity == "alpha2":
        return 90.0 - math.degrees(a1)
    if quantity == "vmin_coefficient":
        return -excess_exact(a1, None)
    if quantity == "equal_speed_spacing":
        # the zero of the excess work between the two extremes (infinite rod)
        # (bisection to the float's last bits; a billionth of a degree is far below the printed minute)
        return round(math.degrees(bisect(lambda a: excess_exact(a, None), a1, 0.5 * math.pi - a1)), 9)
    raise KeyError(quantity)


def _constructed() -> dict[str, float]:
    """The extreme angles as the construction gives them (π by Kochański), in degrees."""
    from ...constructions.two_cranks import TWO_CRANKS, crank_angle

    fig = TWO_CRANKS.figure(parts=4, infinite_rod=True)
    return {"alpha1": math.degrees(crank_angle(fig, "K.M1")), "alpha2": math.degrees(crank_angle(fig, "K.M2"))}


def _minutes(deg: float) -> str:
    m = deg * 60.0
    return f"{int(m // 60)}°{m % 60:.2f}′"


def entries() -> list[Erratum]:
    """Every printed number of seed 002 with its verdict, in text order."""
    built = _constructed()
    out = []
    for p in seed002.PRINTED:
        reading = read_printed(p.text.replace(",", ".").replace("° ", "°"))
        true = true_value(p.quantity)
        true_print = Fraction(true * 60) if reading.is_angle else Fraction(true)
        units = (reading.value - true_print) / reading.unit
        note = ""
        if p.quantity in built:
            note = (f"exact {_minutes(true)}; constructed with Kochański's π {_minutes(built[p.quantity])} "
                    f"(error {(built[p.quantity] - true) * 3600:+.1f}\")")
        elif p.quantity == "vmin_coefficient":
            note = ("book's linear law; v_max exceeds v1 by the same amount (e(90° − α) = −e(α)); "
                    "with v = v1·sqrt(1 + 2e·Qr/((m1+m2)v1²)) the fall is the larger")
        elif p.quantity == "equal_speed_spacing":
            note = "infinite rod only; a finite rod shifts the zeros (§ 147)"
        elif p.quantity == "sin_2alpha":
            note = "(4/π)² − 1"
        out.append(Erratum(seed002.SOURCE, p.table, p.row, p.column, p.text, true, float(units) + 0.0,
                           classify(units), note))
    return out
