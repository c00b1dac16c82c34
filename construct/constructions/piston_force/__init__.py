"""The piston-force line with the mass forces ("Einfluß der Massenkräfte"), seed 001, Abb. 1054/1055.

Seed 001 draws the over-pressure p_ü on the high-pressure piston over the
stroke (Abb. 1054: cover-side steam line less the crank-side back pressure at
the same piston position), carries it to the crank positions of a semicircle
over the stroke divided "vorteilhafterweise in 9 oder 18 Teile" through the
connecting-rod arcs, multiplies by the piston area, P = F p_ü (297), and
superposes the mass forces of eq. (298),

    P_b = (G/g)(v^2/R)(cos phi ± (R/L) cos 2 phi),

"welche während der Beschleunigungszeit von den Kolbenkräften aufgebracht
werden müssen, während der Verzögerungszeit aber wieder frei werden"; the
free forces are hatched vertically (Abb. 1055); J is the pressure change.

The construction, on one sheet:

* the crank circle over the stroke (drawing scale ``scale`` per metre), the
  semicircle divided into ``parts``, the rod arcs to the piston positions X_k;
* on the stroke line as absolute-zero line the idealised indicator diagram
  (module :mod:`construct.constructions.indicator`, Baumann's model) drawn
  in the force scale -- 1 at is drawn as F times ``force_unit`` (drawn length
  per kg), so every over-pressure reads directly as piston force;
* below, on a parallel base line (the "Kolbenweglinie" of Abb. 1055), at each
  X_k the piston force K_k (the segment back pressure -> steam line carried
  with the compass, sign kept) and the mass force M_k constructed as the
  inertia curve is (:mod:`construct.constructions.inertia`: r cos phi, the
  doubled angle, r/L by the proportional angle, then scaled to
  (G/g) omega^2 R in the force scale);
* the lines drawn through the points (the piston-force line in three pieces, its
  corners at the cut-off and the start of compression), the free forces between it
  and the mass-force line as hatched areas, the mass-force areas above and below the
  base read with the planimeter, and J, the zero of p_ü: the steam and compression hyperbolas cross where
  the distance between the clearance corners is divided in the ratio of the
  two rectangles (P + P0)(s1 + s0) : P0 (s3 + s0) -- a fourth proportional
  and the intercept theorem.

The mass forces and the area balance use the book's numbers (Tafel I: G = 830 kg
high-pressure side, n = 50/min, R = 0.4 m, L = 2.0 m; piston area the mean of
F' and F'' from the diameters 45 cm, 7.5 cm and 10 cm).  Tafel I's indicator
diagram is not in the seed: the over-pressure line is Baumann's idealised
diagram with an illustrative high-pressure setting (:data:`HP_DIAGRAM`).

>>> fig = PISTON_FORCE.figure(parts=6)
>>> round(mass_force(fig, 0), 3)        # P_b at phi = 0: (G/g) omega^2 R (1 + R/L); the book prints 1115
1113.391
"""

from __future__ import annotations

import math
from typing import Any

from ...kernel.division import NAMES as DIVISION_NAMES
from ...kernel.protocol import Caption
from .. import Construction, Figure, register
from ..crank import crank_angle, point_name
from ..phrases import BAUMANN_1902, Cite, HANDBOOK, card, division, metres, number, percent
from .analytic import card_force_zero, j_abscissa, model_areas
from .build import (GRAVITY, HP_DIAGRAM, PISTON_AREA_COVER, PISTON_AREA_CRANK, TAFEL_I, build_piston_force,
                    card_crossing_chords, force_line_form, mass_force_scale, piston_area_mean, piston_area_sides,
                    validate_piston_force)
from .checks import piston_force_checks
from .measure import abscissa, area_balance, mass_force, piston_force, return_mass_force, return_piston_force
from .plate import piston_force_plate

__all__ = ["PISTON_FORCE", "TAFEL_I", "HP_DIAGRAM", "GRAVITY", "piston_area_mean", "build_piston_force",
           "piston_force_checks", "mass_force", "piston_force", "abscissa", "mass_force_rows", "area_balance",
           "model_areas", "mass_force_scale", "j_abscissa", "card_force_zero", "card_crossing_chords",
           "piston_area_sides", "return_mass_force", "return_piston_force", "revolution_mass_force_rows",
           "PISTON_AREA_COVER", "PISTON_AREA_CRANK"]


def piston_force_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as Tafel I writes them (G, n, R, L, F; F′ and F″ over both strokes), Baumann's diagram or a
    digitised card's, and the semicircle's division."""
    g = fig.replay.givens
    de = lang == "de"
    out = [f"G = {number(g['weight'], lang)} kg", f"n = {number(g['rpm'], lang)}/min",
           f"R = {metres(g['crank_radius'], lang)} m", f"L = {metres(g['rod_length'], lang)} m",
           f"F = {number(g['piston_area'], lang, 5)} cm²"]
    if "admission" in g:  # Baumann's idealised diagram (a digitised card says itself, below)
        out += [f"p₁ = {number(g['admission'], lang)} at", f"p₂ = {number(g['back_pressure'], lang)} at",
                ("Füllung " if de else "cut-off ") + percent(g["filling"], lang),
                ("schädlicher Raum " if de else "clearance ") + percent(g["clearance"], lang),
                ("Kompression " if de else "compression ") + percent(g["compression"], lang)]
    out.append(division(fig, lang))
    if fig.params.get("revolution"):  # both sides, each with its own area (Tafel I: F', F'')
        out[4] = (f"F′ = {number(g['piston_area_cover'], lang, 6)} cm² (Deckelseite), "
                  f"F″ = {number(g['piston_area_crank'], lang, 6)} cm² (Kurbelseite), Hin- und Rückgang" if de else
                  f"F′ = {number(g['piston_area_cover'], lang, 6)} cm² (cover side), "
                  f"F″ = {number(g['piston_area_crank'], lang, 6)} cm² (crank side), both strokes")
    return out + card(fig, lang)


def piston_force_note(fig: Figure, lang: str) -> str:
    """What the 990-kg plate must say beyond its givens: it shows the high-pressure side's diagram."""
    if fig.replay.givens.get("weight") == 990.0:
        return ("Massen der Niederdruckseite (990 kg) über dem Dampfdiagramm der Hochdruckseite" if lang == "de" else
                "low-pressure side's masses (990 kg) over the high-pressure side's steam diagram")
    return ""


PISTON_FORCE = register(Construction(
    name="piston-force",
    title=Caption("Kolbenüberdrucklinie mit den Massenkräften", "Piston-force line with the mass forces"),
    source="seed 001, Abb. 1054/1055, Gl. (297)-(299), Tafel I; seed 004 (Baumann's idealised diagram)",
    build=lambda parts, method, **v: build_piston_force(parts=parts, method=method, **v),
    checks=piston_force_checks,
    sweep_model=lambda g, params: model_areas(g),
    defaults={"parts": 18, "method": "auto", **TAFEL_I, **HP_DIAGRAM, "scale": 2.5, "force_unit": 1.2e-4,
              "piston_area_cover": PISTON_AREA_COVER, "piston_area_crank": PISTON_AREA_CRANK, "revolution": False,
              "indicator": "", "indicator_crank_side": ""},
    # Tafel I: high-pressure and low-pressure side; and both strokes of the high-pressure side, F' and F''
    book_params=({}, {"weight": 990.0}, {"revolution": True}),
    structural=("parts", "method", "filling", "compression", "revolution", "indicator", "indicator_crank_side"),
    form=force_line_form,  # (the force line's pieces run through the points between its corners: L moves them)
    sweep=lambda g, ratios: {**g, "rod_length": ratios * g["crank_radius"]},  # L = (L/R) R
    cites=(Cite(HANDBOOK, "Abb. 1054/1055"), Cite(BAUMANN_1902, "Fig. 25")),
    wording=piston_force_wording,
    note=piston_force_note,
    methods=DIVISION_NAMES,
    plate=piston_force_plate,
    validator=validate_piston_force,
    help={
        "weight": "weight G of the reciprocating parts in kg (Tafel I: 830 high-pressure, 990 low-pressure side)",
        "rpm": "revolutions per minute n (Tafel I: 50)",
        "crank_radius": "crank radius R in m (Tafel I: 0.4)",
        "rod_length": "connecting-rod length L in m (Tafel I: 2.0)",
        "piston_area": "piston area F in cm^2 (Tafel I: (F' + F'')/2 = 1529.07)",
        "piston_area_cover": "piston-force --revolution: F' of the cover side in cm^2 (Tafel I: 1546.25)",
        "piston_area_crank": "piston-force --revolution: F'' of the crank side, less the rod, in cm^2 (Tafel I: 1511.89)",
        "scale": "drawn length per metre of stroke (piston-force; default 2.5)",
        "force_unit": "drawn length per kg of force (piston-force; default 1.2e-4)",
    },
))


def mass_force_rows(*, weight: float, rpm: float, crank_radius: float, rod_length: float,
                    parts: int = 18) -> list[dict[str, Any]]:
    """crank_angle_deg, x (fraction of the stroke) and P_b (kg, + = masses accelerated), read off the figure.

    >>> rows = mass_force_rows(weight=830, rpm=50, crank_radius=0.4, rod_length=2.0, parts=2)
    >>> [(round(r["crank_angle_deg"], 9), round(r["x"], 9), round(r["P_b"], 3)) for r in rows]
    [(0.0, 0.0, 1113.391), (90.0, 0.550510257, -185.565), (180.0, 1.0, -742.26)]
    """
    fig = PISTON_FORCE.figure(weight=weight, rpm=rpm, crank_radius=crank_radius, rod_length=rod_length, parts=parts)
    return [{"crank_angle_deg": math.degrees(crank_angle(fig, point_name(fig, k))), "x": abscissa(fig, f"M{k}"),
             "P_b": mass_force(fig, k)} for k in range(parts + 1)]


def revolution_mass_force_rows(*, weight: float, rpm: float, crank_radius: float, rod_length: float,
                               parts: int = 18) -> list[dict[str, Any]]:
    """Both strokes: crank_angle_deg 0..360, stroke, x (from the head-end dead centre) and P_b (kg), measured.

    P_b is positive where the masses take up force in the direction of the current stroke: eq. (298) forward,
    and on the return (298) with the angle from the crank-end dead centre and the minus sign.  The dead
    centres belong to both strokes: 180° closes the forward stroke (its row ``forward``) and opens the return
    (``return``); 0° opens the forward stroke, 360° closes the return.

    >>> rows = revolution_mass_force_rows(weight=830, rpm=50, crank_radius=0.4, rod_length=2.0, parts=2)
    >>> [(round(r["crank_angle_deg"], 9), r["stroke"], round(r["x"], 9), round(r["P_b"], 3)) for r in rows]
    ... # doctest: +NORMALIZE_WHITESPACE
    [(0.0, 'forward', 0.0, 1113.391), (90.0, 'forward', 0.550510257, -185.565), (180.0, 'forward', 1.0, -742.26),
     (180.0, 'return', 1.0, 742.26), (270.0, 'return', 0.550510257, 185.565), (360.0, 'return', 0.0, -1113.391)]
    """
    fig = PISTON_FORCE.figure(weight=weight, rpm=rpm, crank_radius=crank_radius, rod_length=rod_length, parts=parts,
                              revolution=True)
    rows = []
    for k in range(parts + 1):
        rows.append({"crank_angle_deg": math.degrees(crank_angle(fig, point_name(fig, k))), "stroke": "forward",
                     "x": abscissa(fig, f"M{k}"), "P_b": mass_force(fig, k)})
    for k in range(parts, -1, -1):
        rows.append({"crank_angle_deg": 360.0 - math.degrees(crank_angle(fig, point_name(fig, k))), "stroke": "return",
                     "x": abscissa(fig, f"rM{k}"), "P_b": return_mass_force(fig, k)})
    return rows
