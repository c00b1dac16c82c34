"""Four-stroke engines: pressure over two revolutions and the piston over-pressure (seed 001 c, Abb. 1056–1058).

Seed 001 describes the explosion engine ("Viertakt-Verpuffungsmaschine",
Abb. 1056): suction c–b under a slight vacuum, compression b–c, ignition in c
"unter rascher Steigerung des Druckes" -- idealised at constant volume --,
expansion c–d–e, release in e, exhaust f–g; "der höchste Druck ... pflegt bei
25 at zu liegen".  The compression-ignition engine (Diesel, Abb. 1057) burns at
constant pressure instead.  Abb. 1058 shows the piston over-pressure a–a
without and b–b with the mass forces.

The idealised cycle (absolute pressures in at, volumes in strokes):

* suction at ``suction`` p_a, exhaust at ``exhaust`` p_g (horizontal lines);
* compression p V^n = p_a (1 + V_c)^n from the crank-end dead centre to the
  clearance V_c = 1/(ε − 1) (ε the ``compression_ratio``);
* explosion: ignition at constant volume to ``max_pressure``, expansion
  p V^n = const; Diesel: combustion at constant pressure (the compression-end
  pressure p_a ε^n) to the ``cutoff`` volume ρ·V_c, then expansion;
* release early, as the handbook has it: "In *e* wurde die Auslaßöffnung
  freigegeben, durch welche die verbrannten Gase während des vierten, des
  Auspuffhubes, von *f* bis *g* vom Kolben hinausgeschoben werden" -- the
  expansion ends at e, the piston path ``release`` (x_e/s, default 0.9, about
  37° before the crank-end dead centre at L/r = 5), and the pressure falls
  along the straight line e–f to the exhaust line at the dead centre f
  (``release`` 1 releases at the dead centre, at constant volume).

The compression ratio is the engine's own unless given: ε = 5 for the explosion
engine, 14 for the Diesel (gas engines 4 to 7, Diesel 12 to 16).

**The polytropes by Brauer's construction** (E. Brauer, 1885; the period
graphical method for p V^n = const): two rays from the origin O of the
p–V diagram, OM below the volume axis at α and ON to the left of the pressure
axis at β, with 1 + tg β = (1 + tg α)^n.  From a point (V, p) of the curve
the next is (V(1 + tg α), p/(1 + tg β)): the vertical through V meets OM, the
45° line from there meets the volume axis at V(1 + tg α); the 45° line from
p on the pressure axis meets ON at the height p/(1 + tg β).  Inward (the
compression) the steps run backwards.  Every point so found lies on
p V^n = const exactly -- the rays are the method's givens: tg α = R^(1/m) − 1
(m steps across the volume ratio R, so that the last point lands on the
dead-centre ordinate) and tg β = R^(n/m) − 1, numbers a draftsman took from
a table of powers or the slide rule; they are laid off as lengths (tg α·r
under r), and every step after them is straightedge, compass and a 45° line
drawn as a parallel.  The curve is drawn through the points with the French
curve (its straying from the polytrope is checked against the same curve
through the exact points).

**Over 720°** (Abb. 1058, which the handbook draws for the engine with
self-ignition: ``over_pressure`` defaults to the Diesel's, and the explosion
engine's plate is Abb. 1056's diagram alone unless asked): the crank circle is divided, the piston positions come from
the rod arcs; each position's ordinate in the p–V diagram meets the branch of
its stroke (suction, compression, expansion, exhaust), and the compass
carries the height to the ordinate of that crank angle in the 720° diagram
(abscissae: a length 8r divided into 4N equal parts).  Measured from its
atmospheric line (1 at) the curve is the piston over-pressure a–a of a
single-acting engine (open crank side).  b–b takes off the mass force per unit
of piston area, q (cos θ + (r/L) cos 2θ), q = m ω² r/F in at (``pressure_ratio``),
constructed as the inertia ordinates of seed 000 (the proportional angle for
r/L and q).

>>> fig = FOUR_STROKE.figure(parts=4, steps=4, over_pressure=True)
>>> g = fig.replay.givens
>>> round(pressure(fig, "cP4"), 10) == round(g["suction"] * g["compression_ratio"] ** g["exponent"], 10)
True
>>> round(volume(fig, "cP4"), 12) == round(g["clearance"], 12)     # the last Brauer point lands on V_c
True
"""

from __future__ import annotations

from ...kernel.division import NAMES as DIVISION_NAMES
from ...kernel.protocol import Caption
from .. import Construction, Figure, register
from ..phrases import COMBUSTION, Cite, number, ratio
from .build import build_four_stroke, four_stroke_plate, validate_four_stroke
from .checks import four_stroke_checks, pressure, volume
from .model import COMPRESSION_RATIOS, ENGINES, STROKES, brauer_tangents, model_pressure

__all__ = ["FOUR_STROKE", "ENGINES", "COMPRESSION_RATIOS", "build_four_stroke", "four_stroke_checks",
           "model_pressure", "pressure", "volume", "brauer_tangents", "STROKES"]


OPTION_HELP = {
    "engine": "four-stroke: explosion (Abb. 1056, ignition at constant volume) or diesel (Abb. 1057, constant pressure)",
    "compression_ratio": "four-stroke: compression ratio epsilon = (V_c + V_h)/V_c (default: explosion 5, Diesel 14)",
    "release": "four-stroke: piston path x_e/s where the exhaust opens (the handbook: early, at e; default 0.9; 1 "
               "releases at the dead centre)",
    "over_pressure": "four-stroke: draw the over-pressure a-a, b-b over 720 degrees (Abb. 1058; default: the "
                     "Diesel's, as the handbook)",
    "suction": "four-stroke: suction pressure p_a, at absolute (0.9)",
    "exhaust": "four-stroke: exhaust pressure p_g, at absolute (1.1)",
    "max_pressure": "four-stroke, explosion: maximum pressure after ignition, at (the handbook: about 25)",
    "cutoff": "four-stroke, diesel: cut-off ratio rho = V_d/V_c of the combustion at constant pressure (2)",
    "exponent": "four-stroke: polytropic exponent n of compression and expansion (1.3)",
    "steps": "four-stroke: Brauer steps per polytrope (12: the French curve then strays by a thousandth of the diagram)",
}


def four_stroke_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as the handbook writes them: the engine, ε and n, its peak pressure or ρ, the release, the rod,
    and -- where the figure draws Abb. 1058's over-pressure -- a–a, b–b and q."""
    g = fig.replay.givens
    de = lang == "de"
    diesel = fig.params.get("engine") == "diesel"
    out = [("Gleichdruckmaschine" if de else "compression-ignition engine") if diesel
           else ("Verpuffungsmaschine" if de else "explosion engine"),
           f"ε = {number(g['compression_ratio'], lang)}", f"n = {number(g['exponent'], lang)}"]
    out.append(f"ρ = {number(fig.params.get('cutoff', 2.0), lang)}" if diesel
               else ("Höchstdruck " if de else "peak pressure ") + f"{number(g['max_pressure'], lang)} at")
    release = g.get("release", 1.0)
    out.append(("Auslass bei " if de else "release at ") + f"{number(release, lang)} s" if release < 1.0 else
               ("Auslass im Totpunkt" if de else "release at the dead centre"))
    out.append(ratio("r/L", g["rod_ratio"], lang))
    if fig.params.get("over_pressure", True):   # a protocol from before the option drew a-a and b-b
        out += [("Kolbenüberdruck a–a, b–b über zwei Umdrehungen" if de else
                 "piston over-pressure a–a, b–b over two turns"), f"q = {number(g['pressure_ratio'], lang)} at"]
    return out


FOUR_STROKE = register(Construction(
    name="four-stroke",
    title=Caption("Druckverlauf im Viertakt", "Four-stroke pressures"),
    source="seed 001 c, Abb. 1056-1058",
    build=build_four_stroke,
    checks=four_stroke_checks,
    defaults={"engine": "explosion", "rod_ratio": 5.0, "parts": 12, "method": "auto", "r": 1.0,
              "compression_ratio": None, "suction": 0.9, "exhaust": 1.1, "max_pressure": 25.0, "cutoff": 2.0,
              "exponent": 1.3, "pressure_unit": 0.1, "pressure_ratio": 6.0, "release": 0.9, "over_pressure": None,
              "steps": 12},
    book_params=({}, {"engine": "diesel"}),
    structural=("engine", "parts", "method", "steps", "cutoff", "release", "over_pressure"),
    cites=(Cite(COMBUSTION, "Abb. 1056–1058"),),
    wording=four_stroke_wording,
    plate=four_stroke_plate,
    methods=DIVISION_NAMES,
    validator=validate_four_stroke,
    help=OPTION_HELP,
    extra={"switches": ("over_pressure",)},
))
