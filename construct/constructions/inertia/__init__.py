"""The curve of the inertia pressures ("Darstellung der Massendrücke"), seed 000, Anhang II.

Over the stroke D0-D1 (abscissa: the piston path from the rod arcs, as in
Fig. 77) the ordinate at each crank position is the inertia pressure of
Gl. (4_1), q = (F/f)(cos w + lam cos 2w), drawn in the pressure scale (the
given length ``pressure_unit`` stands for 1 kg/cm^2), up = positive.  Every
ordinate is *constructed*:

* r cos w is the foot of the crank point on the stroke line (the chord to its
  mirror image, as for the infinite rod);
* r cos 2w is the foot of the doubled-angle point (the chord D0-P stepped on
  once more round the crank circle);
* lam r cos 2w comes out of the proportional angle (module
  :mod:`construct.kernel.proportional`): its vertex S lies on the perpendicular to
  the stroke through O with SO = L, and its scale line ``gr`` at the distance
  r from S: the ray from S through a point of the stroke line meets ``gr``
  at lam times its offset;
* the two are added on ``gr`` by carrying lengths with the compass, and the
  same proportional angle carries the sum onto the scale line ``gf`` at the
  distance F/f (in the pressure scale) from S: the ordinate, taken with the
  compass to the perpendicular at the piston position.

Then the book's quick method (Anhang II c, d): the seven characteristic
points q1..q7 (the square roots in the positions of q6 and q7 by
Pythagoras), the infinite-rod line, the point D on both end tangents, the
tangents at 0, 90 and 180 degrees, and the curve a draftsman draws through
points and tangents (and the parabola enveloped by E-D-F), checked against
the analytic curve.

>>> fig = INERTIA.figure(rod_ratio=4.0, parts=6)
>>> round(ordinate(fig, "K0") / fig.replay.givens["pressure_unit"], 12)   # q1 = (F/f)(1 + r/L)
1.25
>>> round(ordinate(fig, "q5") / fig.replay.givens["pressure_unit"], 12)   # q5 = -m
-0.25
"""

from __future__ import annotations


from ...kernel.division import NAMES as DIVISION_NAMES
from ...kernel.protocol import Caption
from .. import Construction, Figure, register
from ..phrases import ANHANG_II, Cite, division, number, ratio, scale, stroke_parts
from .build import validate_inertia, build_inertia
from .checks import inertia_checks
from .measure import abscissa, curve_deviation, ordinate
from .stroke_fractions import (build_q_at_stroke_fractions, stroke_fraction_checks, stroke_fractions_form,
                               stroke_fractions_plate)
from .rows import acceleration_rows, characteristic_point_rows, q_at_crank_angle_rows

__all__ = [
    "INERTIA",
    "INERTIA_STROKE",
    "build_inertia",
    "inertia_checks",
    "ordinate",
    "abscissa",
    "curve_deviation",
    "acceleration_rows",
    "characteristic_point_rows",
    "q_at_crank_angle_rows",
]

def inertia_plate(fig) -> dict:
    """Fig. 78/79: the curve heavy, tangents thin, the infinite-rod line dash-dotted and lettered,
    F/f and m dimensioned, the pressure scale beside the diagram, the signs of the zones.

    Positions are the constructed points; the scale bar is the given drawn length of 1 at (1 kg/cm²).
    """
    R = fig.replay
    n = fig.params["parts"]
    D0, D1, O = R["D0"], R["D1"], R["O"]
    r = O.distance(D1)
    E, F = R["Einf"], R["Finf"]
    unit = fig.replay.givens["pressure_unit"]
    foot5, q5 = R["X.top"], R["q5"]
    t = 0.42
    on_inf = (E[0] + t * (F[0] - E[0]), E[1] + t * (F[1] - E[1]))
    up, down = R[f"K{max(1, n // 6)}"], R[f"K{n - max(1, n // 6)}"]
    furniture = [
        {"kind": "dimension", "a": tuple(D0), "b": tuple(E), "text": "F/f", "offset": 0.12 * r},
        {"kind": "dimension", "a": tuple(foot5), "b": tuple(q5), "text": "m", "offset": 0.1 * r},  # clear of the curve
        # upright: turned along the line the ∞ read as an 8
        {"kind": "lettering", "at": (on_inf[0] + 0.03 * r, on_inf[1] + 0.05 * r), "text": "L = ∞", "anchor": "start"},
        # the pressure scale close beside the diagram, in the unit the caption names (F/f = 1 at)
        {"kind": "scale", "origin": (D1[0] + 0.09 * r, 0.0), "end": (D1[0] + 0.09 * r, unit), "text": "1 at"},
        {"kind": "sign", "at": (up[0], 0.4 * up[1]), "text": "+"},
        {"kind": "sign", "at": (down[0], 0.4 * down[1]), "text": "−"},
    ]
    looks = {"curve": "heavy", "tan0": "thin", "tan90": "thin", "tan180": "thin", "inf": "dashdot"}
    return {"looks": looks, "furniture": furniture}


def inertia_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as seed 000 writes them: the rod, F/f, the pressure scale, and the division (of the
    semicircle, or of the stroke into tenths)."""
    g = fig.replay.givens
    return [ratio("r/L", g["rod_ratio"], lang), f"F/f = {number(g['pressure_ratio'], lang)} at", scale(g, lang),
            division(fig, lang) if "parts" in fig.params else stroke_parts(fig, lang)]


INERTIA = register(Construction(
    name="inertia-curve",
    title=Caption("Curve der Massendrücke", "Curve of the inertia pressures"),
    source="seed 000, Anhang II a, c, d (Gl. 4_1, Tabelle 1, Fig. 78/79)",
    build=lambda rod_ratio, parts, method, r, pressure_ratio, pressure_unit: build_inertia(
        rod_ratio=rod_ratio, parts=parts, method=method, r=r, pressure_ratio=pressure_ratio,
        pressure_unit=pressure_unit),
    checks=inertia_checks,
    defaults={"rod_ratio": 5.0, "parts": 18, "method": "auto", "r": 1.0, "pressure_ratio": 1.0, "pressure_unit": 0.8},
    book_params=({"rod_ratio": 4.0}, {"rod_ratio": 5.0}, {"rod_ratio": 6.0}),
    structural=("parts", "method"),
    steady=("rod_ratio",),
    cites=(Cite(ANHANG_II, "Fig. 78/79, Tabelle 1"),),
    wording=inertia_wording,
    methods=DIVISION_NAMES,
    plate=inertia_plate,
    validator=validate_inertia,
))

INERTIA_STROKE = register(Construction(
    name="inertia-stroke-fractions",
    title=Caption("Massendrücke in den Zehnteln des Hubes", "Inertia pressures at tenths of the stroke"),
    source="seed 000, Anhang II, Tabelle 2, Gl. (h) and (4₁)",
    build=build_q_at_stroke_fractions,
    checks=stroke_fraction_checks,
    defaults={"rod_ratio": 5.0, "divisions": 10, "r": 1.0, "pressure_ratio": 1.0, "pressure_unit": 0.8},
    book_params=({"rod_ratio": 5.0},),
    structural=("divisions",),
    form=stroke_fractions_form,  # (the dead centre each point is projected from: the nearer one, as drawn)
    cites=(Cite(ANHANG_II, "Tabelle 2"),),
    wording=inertia_wording,
    plate=stroke_fractions_plate,
    validator=validate_inertia,
))
