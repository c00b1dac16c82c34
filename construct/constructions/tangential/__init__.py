"""The tangential-pressure diagram ("Tangentialdruckdiagramm"), seed 004 (Baumann 1902, Fig. 26/27).

For each crank position P of the divided semicircle the rod line from the
crosshead C through P, extended, meets the perpendicular to the stroke
through O at K; by similar triangles the tangential pressure on the crank
pin is T = P'·OK/r (P' the free piston force: the piston force less the
acceleration force), and DESIGN §5 writes it T = P'·sin(ω + β)/cos β.  Steps:

* OK is swung onto the stroke line (a circle about O through K): the point H;
* P' stands as a compass opening on the vertical through the dead centre D1
  (at the distance r from O): the mark M, up = positive; the ray O–M meets the
  vertical through H at the height P'·OK/r (intercept theorem: the proportional
  angle at O, scale lines at r and at OK);
* that height is carried with the compass to the ordinate of the unrolled
  crank circle.

The unrolled circle is not a Euclidean step: the dividers step the chord of
one division n times along the base line, so the drawn length is
n·2r·sin(π/2n) instead of πr (the provenance of every abscissa says so and
states the shortfall).  Angles read off the unrolled scale are taken in
proportion to the drawn length, where the chord error cancels.

The free piston force P' comes, with ``force="baumann"``, from his model: the
over-pressure of the idealised indicator diagram (module
:mod:`construct.constructions.indicator`, hyperbolas by the ray construction)
less the acceleration force B = (c v²/r)(cos ω + (r/L) cos 2ω), constructed as
the inertia ordinates of seed 000 (:mod:`construct.constructions.inertia`),
with c v²/r = P/((1 + r/L) κ) for Baumann's κ = P/B_max.  With
``force="unit"`` P' is the crank radius r itself: the ordinates are OK.

Over a revolution (``revolution=True``, :mod:`construct.constructions.revolution`)
the return stroke's P' comes from the crank side's diagram: under Baumann's force
his diagram mirrored (drawn from the other dead centre, below the stroke line --
his assumption, and the caption says so) with the mass force of (298)'s minus
sign; with cards the crank side's card.  A compound or tandem engine's
low-pressure cylinder has its own diagram (``lp_*`` givens, or ``indicator_lp``)
drawn in the pressure scale times F_lp/F_hp (``area_ratio``), so that its
ordinates are forces in the high-pressure piston's unit and add with the dividers.

The curve is drawn through the points (French curve); the planimeter gives
the mean line ("Ausgleichende", height = area / drawn length, = 2 P_i/π for
the exact curve); where it crosses the curve are α1, α2; between them, above
the mean line, the excess area ("Überschussfläche", hatched), the work the
flywheel must take up.

>>> import math
>>> fig = TANGENTIAL.figure(force="unit", parts=6, rod_ratio=5.0)
>>> round(ok_over_r(fig, 3), 12)   # 90 degrees: sin(90° + β)/cos β = 1
1.0
>>> round(ok_over_r(fig, 2), 12) == round(math.sin(math.pi / 3 + math.asin(math.sin(math.pi / 3) / 5))
...                                         / math.cos(math.asin(math.sin(math.pi / 3) / 5)), 12)
True
"""

from __future__ import annotations

from ...kernel.division import NAMES as DIVISION_NAMES
from ...kernel.protocol import Caption
from .. import Construction, Figure, register
from ..indicator_parts import BAUMANN
from ..phrases import BAUMANN_1902, Cite, card, diagram, division, low_pressure, number, ratio, revolution, scale
from .analytic import baumann_force, low_force, model_summary, model_t
from .build import FORCES, KAPPA, LOW_PRESSURE, build_tangential, chord_shortfall, derived_givens, validate_tangential
from .checks import drawn_model, tangential_checks
from .measure import (crossing_angles, excess_area, free_force, mean_height, ok_over_r, return_free_force, t_over_unit,
                      unrolled_angle)
from .plate import tangential_plate

__all__ = ["TANGENTIAL", "build_tangential", "tangential_checks", "ok_over_r", "t_over_unit", "free_force",
           "model_t", "baumann_force", "return_free_force", "drawn_model", "unrolled_angle", "mean_height",
           "excess_area", "crossing_angles", "model_summary", "KAPPA", "FORCES",
           "LOW_PRESSURE", "low_force", "chord_shortfall"]


def tangential_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as Baumann writes them: κ = P/Bₘₐₓ, the rod, the diagram (or a digitised card), the scale and
    the division; over a revolution the machine, its cranks and the low-pressure cylinder."""
    g = fig.replay.givens
    if fig.params.get("force") == "unit":
        return [x for x in [ratio("r/L", g["rod_ratio"], lang), "P′ = r", *revolution(fig, lang), division(fig, lang),
                            *card(fig, lang)] if x]
    # κ = P/B_max (Baumann): the construction keeps c v²/r = P/((1 + r/L) κ) as its given.
    if "admission" not in g:  # a digitised card's force
        return [x for x in [ratio("r/L", g["rod_ratio"], lang), *revolution(fig, lang), division(fig, lang),
                            *card(fig, lang), *low_pressure(fig, lang)] if x]
    kappa = g["admission"] / (g["pressure_ratio"] * (1.0 + 1.0 / g["rod_ratio"]))
    out = ([f"κ = P/Bₘₐₓ = {number(round(kappa, 9), lang)}", ratio("r/L", g["rod_ratio"], lang)]
           + diagram(g, lang) + [scale(g, lang), division(fig, lang)])
    if "lp.admission" in g:  # two cylinders, two diagrams: say whose the first givens are
        out[2] = ("Hochdruck: " if lang == "de" else "high pressure: ") + out[2]
    if fig.params.get("revolution"):  # the return stroke from the same diagram: Baumann's assumption, said
        out = [x for x in revolution(fig, lang) if x] + out + [
            "Rückgang: dasselbe Diagramm gespiegelt (Baumanns Annahme)" if lang == "de"
            else "return stroke: the same diagram mirrored (Baumann's assumption)"]
        out += low_pressure(fig, lang)
    return out


TANGENTIAL = register(Construction(
    name="tangential-pressure",
    title=Caption("Tangentialdruckdiagramm mit Ausgleichender und Überschussfläche",
                  "Tangential-pressure diagram with mean line and excess area"),
    source="seed 004 (Baumann 1902), Fig. 26/27",
    build=build_tangential,
    checks=tangential_checks,
    sweep_model=lambda g, params: model_summary(g, params["force"]),
    defaults={"rod_ratio": 5.0, "parts": 18, "method": "auto", "r": 1.0, "force": "baumann", "kappa": KAPPA,
              **BAUMANN, "pressure_unit": 0.2, "revolution": False, "cranks": "", "machine": "single",
              "indicator": "", "indicator_crank_side": "", "indicator_lp": "", "indicator_lp_crank_side": "",
              **LOW_PRESSURE},
    book_params=({"rod_ratio": 5.0, "parts": 18, "kappa": 8.0}, {"rod_ratio": 5.0, "parts": 18, "kappa": 2.0},
                 # a compound engine, cranks at 90 degrees, each cylinder with its own diagram (Baumann's for the
                 # high-pressure one, the low-pressure one's own, its piston 2.5 times as large): the summed
                 # diagram over a revolution and its excess areas
                 {"rod_ratio": 5.0, "parts": 18, "revolution": True, "machine": "compound"}),
    structural=("parts", "method", "force", "filling", "compression", "revolution", "cranks", "machine", "indicator",
                "indicator_crank_side", "indicator_lp", "indicator_lp_crank_side", "lp_filling", "lp_compression"),
    steady=("kappa",),
    cites=(Cite(BAUMANN_1902, "Fig. 26/27"),),
    wording=tangential_wording,
    methods=DIVISION_NAMES,
    plate=tangential_plate,
    validator=validate_tangential,
    derived=lambda g, params: derived_givens(g),
    help={
        "cranks": "tangential-pressure --revolution: crank offsets in degrees ahead of the first, e.g. 0,90 "
                  "(multiples of 180/parts; default: the machine's)",
        "machine": "tangential-pressure --revolution: single (default; cranks as --cranks says), tandem (two "
                   "cylinders on one rod, forces added before the crank), compound (cranks at 0,90)",
        "indicator": "tangential-pressure: a digitised indicator diagram of the cover side, CSV x,p (the loop in "
                     "drawing order; x from the head-end dead centre in strokes, p absolute in at)",
        "indicator_crank_side": "tangential-pressure: the crank side's diagram (default: the cover side's mirrored, "
                                "Baumann's assumption)",
        "indicator_lp": "tangential-pressure --revolution --machine compound|tandem: the low-pressure cylinder's "
                        "own cover-side diagram, CSV x,p as --indicator (default: every cylinder has --indicator's)",
        "indicator_lp_crank_side": "tangential-pressure: the low-pressure crank side's diagram (default: the "
                                   "low-pressure cover side's mirrored)",
        "area_ratio": "tangential-pressure, compound/tandem with diagrams of their own: low-pressure piston area "
                      "over the high-pressure one's, 0.1 .. 20 (default 2.5)",
        "lp_filling": "tangential-pressure --force baumann, compound/tandem: the low-pressure cylinder's filling "
                      "s1/s, 0.001 .. 1 (default 0.35, illustrative: the books print no compound's diagrams)",
        "lp_admission": "the low-pressure cylinder's admission pressure in at over its back pressure, 0.001 .. 1000 "
                        "(default 1.6, illustrative)",
        "lp_back_pressure": "the low-pressure cylinder's back pressure in at absolute, 0.001 .. 1000 (default 0.15)",
        "lp_compression": "the low-pressure cylinder's compression s3/s, 0.001 .. 1 (default 0.30)",
        "lp_kappa": "the low-pressure cylinder's kappa = P/B_max, 0.1 .. 10000 (default 8)",
    },
))
