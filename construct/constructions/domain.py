"""Where the constructions keep their accuracy in float64: the stated domain of every given.

Every construction is replayed in float64 and checked against its analytic
formula to about 1e-12 of the stroke.  Outside the ranges below a float chain
loses the digits the checks ask for -- or overflows -- and a table would print
a wrong number with exit 0; so a given outside its range is refused, naming
the parameter, its value and the range.

**The rod ratio.**  The crosshead C lies a rod length L from the crank point, so
its coordinate carries a rounding error of a few eps·L = eps·(L/r)·r; the arc
back onto the stroke subtracts two lengths of size L to leave a piston path of
size r -- the absolute error stays eps·(L/r)·r while the quantity the rod arcs
are drawn for, the rod correction r²sin²w/(2L) = r/(2 L/r), shrinks: its
relative error grows like 2 eps (L/r)².  Measured (every check of a figure at
its defaults, bisected over L/r): the checks first fail at L/r = 4.1e3
(two-cranks, work excess), 6.5e3 (crank-angle), 1.6e4 (crank, piston-force),
1.9e4 (inertia-curve), 8.3e4 (inertia-stroke-fractions), 2.7e5
(tangential-pressure); the error of the piston path grows like 5e-17·(L/r) of
the stroke.  At L/r = 1e16 every piston position is the middle of the stroke.
Near L/r = 1 the rod arc meets the stroke line at a grazing angle and the inertia
curve's end tangent r tg beta = (F/f)(4λ - 1)/(1 - λ) grows like 1/(L/r - 1):
its check fails from L/r = 1.003 at the books' F/f and from 1.01 at F/f = 2 r,
with an error growing like 1/(L/r - 1)^2 (the piston-force area balance fails
from 1.0001).  The domain 1.05 <= L/r <= 1000 keeps every check within about a
quarter of its tolerance (books draw 4 to 6); a longer rod is as good as the infinite rod
(--infinite-rod, or the ordinates Y the crank figure draws beside the arcs).

>>> ROD_RATIO.check("rod ratio L/r", 5.0)
5.0
>>> ROD_RATIO.check("rod ratio L/r", 1e16)
Traceback (most recent call last):
...
construct.kernel.errors.InvalidParameter: rod ratio L/r = 1e+16 is outside 1.05 .. 1000, where the constructions keep their accuracy in float64 (the rod arc's cancellation loses digits as L/r grows; near 1 the arcs graze); for a longer rod take the infinite rod (--infinite-rod, or the crank figure's ordinates Y)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from ..kernel.errors import InvalidParameter
from ..kernel.numeric import shown

__all__ = ["AREA_RATIO", "Domain", "ROD_RATIO", "DRAWN_LENGTH", "PRESSURE", "PRESSURE_RATIO", "STROKE_FRACTION", "CLEARANCE",
           "DRAWN_PRESSURE_RATIO", "DRAWN_M", "DRAWN_MASS_FORCE", "KAPPA_RANGE", "FLUCTUATION", "SPEED_GAIN", "WEIGHT", "RPM", "LENGTH_M", "PISTON_AREA",
           "DRAWING_SCALE", "FORCE_UNIT", "FLYWHEEL_KZ", "RIM_SPEED",
           "FLYWHEEL_DIAMETER", "FLYWHEEL_RPM", "FLYWHEEL_WEIGHT", "EXCESS_WORK", "IRREGULARITY", "COMPRESSION_RATIO", "CUTOFF_RATIO",
           "ENGINE_PRESSURE", "EXHAUST_PRESSURE", "RELEASE", "MECHANICAL_EFFICIENCY", "POLYTROPE_EXPONENT", "SUCTION_PRESSURE", "DISC_THICKNESS",
           "RIM_SECTION", "CRANK_OFFSET", "CRANK_COUNT"]


@dataclass(frozen=True)
class Domain:
    """A closed range [low, high] of a given and why the constructions need it."""

    low: float
    high: float
    why: str
    advice: str = ""

    def check(self, name: str, value: Any) -> Any:
        """The value (or array of values, for a sweep) if it lies in the range, else InvalidParameter naming it."""
        try:
            arr = np.asarray(value, dtype=float)
        except OverflowError:  # an integer beyond any float
            raise InvalidParameter(f"{name} must be a finite number, got {shown(value)}") from None
        outside = ~((arr >= self.low) & (arr <= self.high))
        if outside.any():
            bad = float(arr[outside].flat[0])
            advice = f"; {self.advice}" if self.advice else ""
            where = f"outside {self.low:g} .. {self.high:g}" if math.isfinite(self.high) else f"below {self.low:g}"
            raise InvalidParameter(f"{name} = {_distinct(bad, self.low, self.high)} is {where}, {self.why}{advice}")
        return value


def _distinct(value: float, *bounds: float) -> str:
    """*value* to 6 digits, or to all its digits when 6 would print it as a bound it lies beyond.

    >>> _distinct(1000.0000000000001, 1.05, 1000.0), _distinct(1234.5678, 1.05, 1000.0)
    ('1000.0000000000001', '1234.57')
    """
    text = f"{value:.6g}"
    return repr(value) if any(float(text) == b or f"{b:g}" == text for b in bounds) else text


#: L/r: see the module's docstring for the measurement.
ROD_RATIO = Domain(1.05, 1000.0, "where the constructions keep their accuracy in float64 (the rod arc's "
                   "cancellation loses digits as L/r grows; near 1 the arcs graze)",
                   "for a longer rod take the infinite rod (--infinite-rod, or the crank figure's ordinates Y)")
#: Lengths in drawing units (crank radius r, the stroke half of a diagram, the drawn length of a pressure unit).
#: Several checks hold positions to an absolute 1e-12: measured, they pass from 1e-6 to 1e4 drawing units
#: (tangential-pressure and indicator-diagram fail at 1e6); a decade inside on either side.
DRAWN_LENGTH = Domain(1e-3, 1e3, "the drawing units in which the checks hold positions to 1e-12 "
                      "(measured: they pass from 1e-6 to 1e4)")
#: Pressures in at (admission P, back pressure P0).  Measured: the diagrams pass from 1e-6 to 1e6 times the
#: books' values; what a steam engine sees is 0.01 to 100 at.
PRESSURE = Domain(1e-3, 1e3, "pressures in at for which the diagram's float chain is measured (1e-6 to 1e6 "
                  "times the books' values pass)")
#: F/f of the inertia pressures and the drawn length of 1 kg/cm^2: bounded together by DRAWN_PRESSURE_RATIO.
PRESSURE_RATIO = Domain(1e-3, 1e3, "the range in which the inertia construction is measured")
#: The drawn F/f (pressure_ratio x pressure_unit) over the crank radius r: the proportional angle for F/f and the
#: curve's tangents lose the checks' digits outside 8e-4 .. 80 (measured; 8e-5 and 800 fail).
DRAWN_PRESSURE_RATIO = Domain(1e-2, 50.0, "the drawn F/f (pressure_ratio x pressure_unit) over the crank radius "
                              "r for which the inertia construction keeps its accuracy (measured: 8e-4 .. 80 pass)")
#: q5 (ordinate -m, m = (r/L) F/f) lies off the infinite-rod line Einf-Finf (slope F/f over r) by m r / sqrt(r^2 +
#: F/f^2), and the 90-degree tangent is the parallel through q5: when that offset is a tiny fraction of the line's
#: length 2 sqrt(r^2 + F/f^2) the parallel's circles meet at a grazing angle and the tangent misses by r/(2L).
#: Measured: the fraction m r / (2 (r^2 + F/f^2)) = 1.25e-5 fails by 6e5 tolerances, 1.43e-5 passes; ten times
#: that is the bound (at the books' F/f = 0.8 r it allows L/r up to 1600).
DRAWN_M = Domain(1.5e-4, math.inf, "the offset of q5 from the infinite-rod line over that line's length for which "
                 "the tangent at 90 degrees is drawn accurately (measured: it fails below 1.4e-5)",
                 "bring the drawn F/f (pressure ratio x pressure unit) nearer to r, or take a shorter rod")
#: Filling s1/s and compression s3/s, fractions of the stroke (below 1 is checked where they are read).
STROKE_FRACTION = Domain(1e-3, 1.0, "fractions of the stroke the diagram is measured for (below 1e-3 a "
                         "hyperbola's points crowd into the clearance corner)")
#: Clearance s0/s: the hyperbolas' asymptote; the checks fail at 1e-4, pass at 1e-3.
CLEARANCE = Domain(5e-3, 1.0, "the clearance s0/s for which the hyperbolas keep the checks' accuracy "
                   "(measured: 1e-4 fails, 1e-3 passes)")
#: Baumann's kappa = P/B_max (he draws 8 and 2): the checks pass from 0.008 to 8e6.
KAPPA_RANGE = Domain(0.1, 1e4, "the kappa = P/B_max for which the diagram is measured (0.008 .. 8e6 pass)")
#: Qr/((m1+m2) v1^2) of the two cranks (the book's example 0.25).  At the low end the largest magnification the
#: figure picks by itself (8) just reaches SPEED_GAIN's 0.1; the checks pass up to 2.5e5.
FLUCTUATION = Domain(0.0125, 1e3, "the fluctuation the two-cranks construction is measured for (the largest "
                     "automatic magnification, 8, brings 0.0125 to the drawn G k = 0.1)")
#: G k = magnify x fluctuation: the drawn wave's amplitude over the crank radius is G k e (|e| < 0.21); below
#: 0.02 the speed points crowd onto the circle and the wave's extremes fail their checks (measured: 0.0125 fails).
SPEED_GAIN = Domain(0.1, math.inf, "the magnified fluctuation G k for which the speed wave stands clear of the "
                    "crank circle (measured: below 0.02 its extremes fail their checks)",
                    "raise --magnify or --fluctuation")
#: The drawn mass force (G/g) omega^2 R x force_unit over the drawn crank radius R x scale (Tafel I: 0.11).
#: Measured: 4.5e-13 .. 4.5e8 pass, 4.5e-15 fails its area checks, 4.5e14 breaks the French curve.
DRAWN_MASS_FORCE = Domain(1e-9, 1e6, "the drawn mass force (G/g) omega^2 R x force_unit over the drawn crank "
                          "radius R x scale for which the piston-force figure is measured (4.5e-13 .. 4.5e8 pass)",
                          "choose --force-unit to suit --weight and --rpm")
#: Piston-force givens in the book's units; each range is 1e-3 .. 1e3 times inside what the checks pass.
WEIGHT = Domain(0.1, 1e6, "kg of reciprocating parts the mass forces are measured for (8e-4 .. 8e8 pass)")
RPM = Domain(0.1, 1e4, "revolutions per minute the mass forces are measured for (5e-5 .. 5e5 pass)")
LENGTH_M = Domain(1e-3, 1e3, "metres (crank radius, rod length) the piston-force figure is measured for")
PISTON_AREA = Domain(1e-2, 1e7, "cm^2 of piston area the forces are measured for (1.5e-3 .. 1.5e9 pass)")
DRAWING_SCALE = Domain(1e-3, 1e4, "drawn length per metre the figure is measured for (2.5e-6 .. 2.5e6 pass)")
FORCE_UNIT = Domain(1e-8, 10.0, "drawn length per kg the forces are measured for (1.2e-10 .. 120 pass)")
#: Baumann's flywheel coefficients 1 + c v^2/kz (closed formulas, not drawn): kz in kg/cm^2 and v in m/s only need
#: v^2/kz finite and normal; these ranges keep it within 1e-15 .. 1e14 (his tables: kz 40..200, v 10..40).
FLYWHEEL_KZ = Domain(1e-3, 1e6, "allowed stresses kz in kg/cm^2 for which v^2/kz stays a normal float")
RIM_SPEED = Domain(1e-3, 1e4, "rim speeds v in m/s for which v^2/kz stays a normal float")
#: The flywheel from the excess work (closed formulas): the rim's mean diameter in m, the excess work in kg m, and
#: the degree of irregularity delta = (v_max - v_min)/v_mean.  Wide bounds around practice (D 1 .. 10 m, E 10 .. 1e5
#: kg m, delta 1/300 .. 1/20): the formulas are plain products, the bounds only keep the float products normal and
#: delta a small fraction, as the relation E = (G/g) v^2 delta assumes (it neglects delta^2 against 1).
FLYWHEEL_DIAMETER = Domain(1e-3, 1e3, "rim diameters in m for which the flywheel products stay normal floats")
FLYWHEEL_RPM = Domain(0.1, 1e4, "revolutions per minute of a flywheel for which its products stay normal floats")
FLYWHEEL_WEIGHT = Domain(0.1, 1e9, "kg of flywheel rim for which its products stay normal floats")
EXCESS_WORK = Domain(1e-6, 1e12, "excess work in kg m for which the flywheel products stay normal floats")
IRREGULARITY = Domain(1e-6, 0.2, "degrees of irregularity for which E = (G/g) v^2 delta holds (it neglects "
                      "delta^2 against 1; practice: 1/300 .. 1/20)")
#: The four-stroke cycle (seed 001 c).  Compression ratio epsilon = (V_c + V_h)/V_c: gas engines 4..7, Diesel 12..16;
#: 1.5 .. 30 keeps the clearance V_c = s/(epsilon - 1) between s/29 and 2 s, drawable beside the stroke.
COMPRESSION_RATIO = Domain(1.5, 30.0, "compression ratios for which the clearance s/(epsilon - 1) is drawn beside "
                           "the stroke (gas engines 4..7, Diesel 12..16)")
#: Diesel cut-off ratio rho = V_d/V_c (combustion at constant pressure): above 1 (else no combustion line), below
#: epsilon/1.05 (checked where it is used).
CUTOFF_RATIO = Domain(1.01, 20.0, "cut-off ratios rho = V_d/V_c of the combustion at constant pressure")
#: Polytropic exponent: between the isotherm (1) and the adiabat of a monatomic gas (5/3); practice 1.25..1.4.
POLYTROPE_EXPONENT = Domain(1.0, 5.0 / 3.0, "polytropic exponents between the isotherm and the adiabat "
                            "(practice 1.25 .. 1.4)")
#: Suction (below the atmosphere) and exhaust (above it) pressures, absolute at.
SUCTION_PRESSURE = Domain(0.3, 1.0, "suction pressures in at absolute (a slight vacuum: practice 0.85 .. 0.95)")
EXHAUST_PRESSURE = Domain(1.0, 3.0, "exhaust pressures in at absolute (a slight over-pressure: practice 1.05 .. 1.2)")
#: Where a combustion engine's exhaust opens, the piston path x_e over the stroke (seed 001: "in e wurde die
#: Auslaßöffnung freigegeben", before the dead centre): from the middle of the stroke to the dead centre itself (1:
#: release at constant volume); practice 0.85 .. 0.95 (35 to 50 degrees before the dead centre).
RELEASE = Domain(0.5, 1.0, "piston paths x_e/s where the exhaust opens, between the middle of the stroke and the "
                 "crank-end dead centre (practice 0.85 .. 0.95)")
#: The mechanical efficiency of an engine, effective over indicated work (Baumann's Fig. 27): a steam engine's
#: 0.75 .. 0.92; below 0.3 the effective line falls far below the base, above 1 friction would give work.
MECHANICAL_EFFICIENCY = Domain(0.3, 1.0, "mechanical efficiencies, effective over indicated work (steam engines "
                               "0.75 .. 0.92)")
#: The highest pressure of the cycle, at: seed 001 names about 25 at for the explosion engine.
ENGINE_PRESSURE = Domain(2.0, 150.0, "highest cycle pressures in at (the handbook: about 25 at for the explosion engine)")
#: Baumann's Fig. 28 over the rim radius r1: the disc thickness b1 (a real wheel's is a few thousandths of r1; the
#: plate exaggerates) up to 1/30 r1, so that the hub (24 b1 long) stays within 0.8 r1; the rim's square side below
#: r1/2 so that the rim clears the hub radius.
DISC_THICKNESS = Domain(1e-3, 1.0 / 30.0, "disc thicknesses b1/r1 for which the hub (24 b1 long) stays within the "
                        "wheel's width (real wheels: a few thousandths)")
RIM_SECTION = Domain(1e-2, 0.5, "rim sections (side over r1) that clear the hub")
#: Crank offsets ahead of the first crank, in degrees (tangential pressure over a revolution): one turn; the offset
#: must moreover be a multiple of the division 180/parts (the ordinates are added where both cranks have one).
CRANK_OFFSET = Domain(0.0, 360.0, "degrees ahead of the first crank (one turn; 360 is the first crank again)")
#: Cranks on one shaft: the books draw one, two (seed 002, compound engines) or three; the summed ordinates'
#: error grows with their number (each addition is a compass transfer).
AREA_RATIO = Domain(0.1, 20.0, "the low-pressure piston's area over the high-pressure one's (compound engines "
                    "build 1.5 .. 4): the low-pressure diagram is drawn in that multiple of the pressure scale")
CRANK_COUNT = Domain(1.0, 8.0, "cranks on one shaft the summed diagram is measured for")
