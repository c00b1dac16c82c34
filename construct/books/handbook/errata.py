"""Errata of seed 001's worked example (Tafel I): each printed number beside its true value.

True values come from the formulas the text names, with its own data
(:mod:`construct.books.handbook.printed`): F = (pi/4)(D^2 - d^2), v = pi D n / 60
with D = 2R, eq. (298) at phi = 0, (G/g)(v^2/R)(1 + R/L) with g = 9.81; the
weights G as the sum of the printed part weights with half the connecting
rod (the lower end of the book's "1/2 bis 2/3"), read to the book's "rund"
(tens).  Classes as for seed 000 (:func:`construct.books.errata.classify`):
deviation printed - true in units of the last printed place.

>>> e = {x.row: x for x in entries()}
>>> e["v"].class_, round(e["v"].units, 2)
('slip', 0.6)
>>> e["P_b,max high-pressure side"].class_, round(e["P_b,max high-pressure side"].true, 2)
('slip', 1113.39)
"""

from __future__ import annotations

import math
from fractions import Fraction

from ..errata import Erratum, classify, read_printed
from ..printed import Printed
from . import printed as seed001

__all__ = ["entries", "true_values"]


def _weights() -> tuple[float, float, float, float]:
    w = seed001.PART_WEIGHTS
    common = w["piston_rod"] + w["pump_piston"] + w["crosshead"]
    hp = w["hp_piston"] + common
    lp = w["lp_piston"] + common
    return hp + w["connecting_rod"] / 2.0, lp + w["connecting_rod"] / 2.0, hp + w["connecting_rod"] * 2 / 3, \
        lp + w["connecting_rod"] * 2 / 3


def _mass_force_max(G: float, v: float) -> float:
    g = seed001.GIVEN
    R, L = g["crank_radius_m"], g["rod_length_m"]
    return G / g["g"] * v * v / R * (1.0 + R / L)


def true_values() -> dict[str, float]:
    """What each printed number claims to be, computed exactly from the seed's data."""
    g = seed001.GIVEN
    v = math.pi * 2.0 * g["crank_radius_m"] * g["rpm"] / 60.0
    hp, lp, _, _ = _weights()
    return {
        "area_cover": math.pi / 4.0 * (g["bore_cm"] ** 2 - g["tail_rod_cm"] ** 2),
        "area_crank": math.pi / 4.0 * (g["bore_cm"] ** 2 - g["piston_rod_cm"] ** 2),
        "weight_hp": hp, "weight_lp": lp, "speed": v,
        # the book feeds its rounded G (830, 990) into eq. (298): the claim is the force for those G
        "pbmax_hp": _mass_force_max(830.0, v), "pbmax_lp": _mass_force_max(990.0, v),
        "step_9": 180.0 / 9, "step_18": 180.0 / 18,
    }


def _note(p: Printed, true: float, units: float) -> str:
    hp, lp, hp23, lp23 = _weights()
    if p.quantity == "speed":
        return f"pi D n / 60 = {true:.5f}; with pi = 22/7 it is {22 / 7 * 0.8 * 50 / 60:.5f}, which gives the printed 2.095"
    if p.quantity in ("pbmax_hp", "pbmax_lp"):
        G = 830.0 if p.quantity == "pbmax_hp" else 990.0
        book = _mass_force_max(G, 2.095)
        note = f"with the book's own v = 2.095: {book:.1f}; slide-rule accuracy"
        if p.quantity == "pbmax_lp":
            note += "; read as rounded to tens (like the weights) it agrees"
        return note
    if p.quantity in ("weight_hp", "weight_lp"):
        half, two_thirds = (hp, hp23) if p.quantity == "weight_hp" else (lp, lp23)
        return (f"'rund': parts summed with 1/2 of the connecting rod = {half:.0f}, read to tens "
                f"(with 2/3 of it {two_thirds:.0f})")
    if p.quantity in ("area_cover", "area_crank"):
        return "pi/4 (45² - d²), correctly rounded"
    return "180° / parts"


def entries() -> list[Erratum]:
    """Every printed number of the worked example with its verdict, in text order."""
    true = true_values()
    out = []
    for p in seed001.worked_example():
        reading = read_printed(p.text)
        unit = Fraction(10) if p.quantity in ("weight_hp", "weight_lp") else reading.unit  # "rund": tens
        units = float((reading.value - Fraction(true[p.quantity])) / unit)
        out.append(Erratum(seed001.SOURCE, p.table, p.row, p.column, p.text, true[p.quantity], units,
                           classify(Fraction(units)), _note(p, true[p.quantity], units)))
    return out
