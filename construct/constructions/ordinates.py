"""Ordinates shared by the force constructions: the inertia ordinate of seed 000 and the mass force of seed 001.

The inertia curve (:mod:`construct.constructions.inertia`), the piston-force
line (:mod:`construct.constructions.piston_force`) and the tangential-pressure
diagram (:mod:`construct.constructions.tangential`) all construct the same
ordinate, (F/f)(cos w + (r/L) cos 2w) -- eq. (298) of seed 001 when F/f is
(G/g) w^2 R -- from a crank point: r cos w as the point's foot, r cos 2w from
the doubled-angle point, r/L and F/f by the proportional angle.  The steps live
here, once, with public names.

>>> point_kind(0, 18), point_kind(9, 18), point_kind(3, 12), point_kind(5, 18)
('start', 'quarter', 'octant', 'generic')
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping

from ..kernel.instruments import Builder
from ..kernel.proportional import ProportionalAngle, Scale, carry_across, scale_line, vertex_on

__all__ = ["OrdinateFrame", "inertia_setup", "project", "ordinate_line", "ordinate_value", "stroke_direction",
           "point_kind"]


@dataclass(frozen=True)
class OrdinateFrame:
    """Object names of the crank frame and the proportional angle an ordinate is constructed with."""

    O: str
    axis: str
    crank: str
    D0: str
    D1: str
    r: str
    L: str
    Ff: str
    vert: str
    top: str
    angle: ProportionalAngle
    gr: Scale
    gf: Scale


def inertia_setup(b: Builder, f: Mapping[str, str]) -> OrdinateFrame:
    """The givens in the pressure scale, and the proportional angle with its vertex below O."""
    Ff = b.given_length("Ff", product=("pressure_ratio", "pressure_unit"),
                        de="F/f im Höhenmaßstabe der Dampfdrücke", en="F/f in the pressure scale")
    with b.group("proportional angle for r/L and F/f", "Proportionswinkel für r/L und F/f"):
        vert = b.perpendicular_bisector("vert", f["D0"], f["D1"])
        top = b.intersect("top", vert, f["circle"], rule=("toward", f["O"], None, 0.0, 1.0),
                          de="Kurbelstellung ω = 90°", en="crank at 90 degrees", labels={"top": "90°"})
        angle = vertex_on(b, "S", origin=f["O"], leg=vert, length=f["L"], rule=("toward", f["O"], None, 0.0, -1.0),
                          de="Scheitel S des Proportionswinkels: SO = L",
                          en="vertex S of the proportional angle: SO = L")
        gr = scale_line(b, angle, "gr", length=f["r"], toward=("toward", "S", f["O"]),
                        de="Marke r von S aus: Maßlinie für r/L", en="mark r from S: scale line for r/L")
        gf = scale_line(b, angle, "gf", length=Ff, toward=("toward", "S", f["O"]),
                        de="Marke F/f von S aus: Maßlinie für F/f", en="mark F/f from S: scale line for F/f")
    return OrdinateFrame(f["O"], f["axis"], f["circle"], f["D0"], f["D1"], f["r"], f["L"], Ff, vert, top, angle, gr, gf)


def project(b: Builder, c: OrdinateFrame, name: str, Q: str, dc: str, what: str) -> str:
    """The foot of Q on the stroke line: the chord from Q to its mirror image (circle about a dead centre)."""
    k = b.circle_through(f"{name}.k", dc, Q, de=f"Kreis um den Totpunkt durch {what}",
                         en=f"circle about the dead centre through {what}")
    m = b.intersect(f"{name}.Q", k, c.crank, rule=("farther", Q), de=f"Spiegelpunkt von {what}",
                    en=f"mirror image of {what} in the stroke line")
    g = b.line(f"{name}.g", Q, m, de=f"Lot von {what} auf die Hubachse", en=f"perpendicular from {what} to the stroke line")
    return b.intersect(name, g, c.axis, rule=("only",), de=f"Fußpunkt {name}", en=f"foot {name}")


def ordinate_line(b: Builder, c: OrdinateFrame, name: str, X: str) -> str:
    """The perpendicular to the stroke line at X: a circle about X cuts it twice, their bisector."""
    with b.group(f"ordinate at {X}", f"Ordinate in {X}"):
        k = b.circle_radius(f"{name}.k", X, c.r, de=f"Kreis um {X} mit r", en=f"circle about {X} with radius r")
        a, a2 = b.intersect((f"{name}.A", f"{name}.B"), c.axis, k, rule=("toward", c.O, None, -1.0, 0.0))
        line = b.perpendicular_bisector(name, a, a2)
    b.call(line, f"Ordinate in {X}", f"the ordinate at {X}")
    return line


def ordinate_value(b: Builder, c: OrdinateFrame, tag: str, P: str, kind: str, dc_p: str, dc_2: str | None,
                   number: str | None = None) -> str:
    """Construct (F/f)(cos w + lam cos 2w) for the crank point P; return its point on the F/f scale line.

    *tag* names the helpers (Y7, G7), *number* is the crank point's number as the figure letters it (the
    title's: *tag* when None) -- the title names it, not P itself, which the steps' views need not show;
    a dead centre the title names by its letter.

    *kind* tells what the nominal angle makes exactly zero or a dead centre:
    "start" (P = D0), "end" (P = D1), "quarter" (90 degrees: no cos w term,
    the doubled point is D1), "octant" (45 or 135 degrees: no cos 2w term),
    "generic".
    """
    O, gr = c.O, c.gr
    Y = G = None
    # (a dead centre by its letter: A, not the crank point 0)
    number = P if kind in ("start", "end") else tag if number is None else number
    with b.group(f"ordinate value at crank point {number}", f"Ordinatenwert zum Kurbelpunkt {number}"):
        # r cos w: the foot of the crank point.
        if kind == "start":
            Y = c.D0
        elif kind == "end":
            Y = c.D1
        elif kind != "quarter":
            Y = project(b, c, f"Y{tag}", P, dc_p, tag)
            if b[Y] == b[O]:  # the foot falls on O as drawn (a crank point found at 90 degrees, Tafel 2's mark 6
                Y = None      # at L/r 2.6): r cos w is nothing to carry, and a compass cannot be set to it
        # r cos 2w: the doubled-angle point, then its foot.
        if kind in ("start", "end"):
            G = c.D0
        else:
            k = b.circle_segment(f"N{tag}.k", P, c.D0, P, de=f"Sehne {c.D0}–{P} von {P} aus nochmals abgetragen",
                                 en=f"chord {c.D0}–{P} stepped on once more from {P}")
            N = b.intersect(f"N{tag}", c.crank, k, rule=("farther", c.D0), de=f"Punkt N{tag} zum doppelten Winkel 2ω",
                            en=f"point N{tag} at the doubled angle 2w")
            if kind == "quarter":
                G = N  # 2w = 180 degrees: the doubled point is the dead centre itself
            elif kind != "octant":
                if dc_2 is None:  # angle not known in advance: the dead centre nearer to N as drawn now
                    dc_2 = c.D0 if b[N][0] * stroke_direction(b, c) < b[c.O][0] * stroke_direction(b, c) else c.D1
                G = project(b, c, f"G{tag}", N, dc_2, f"N{tag}")
        A = W = None
        if Y is not None:
            kA = b.circle_segment(f"A{tag}.k", gr.origin, O, Y, de=f"r·cos ω = O{Y} auf die Maßlinie r getragen",
                                  en=f"r cos w = O{Y} carried to the scale line r")
            A = b.intersect(f"A{tag}", gr.line, kA, rule=("toward", O, Y), de=f"A{tag}: r·cos ω", en=f"A{tag}: r cos w")
        if G is not None:
            W = carry_across(b, c.angle, f"W{tag}", G, gr, de=f"W{tag}: r/L · r·cos 2ω (Proportionswinkel)",
                             en=f"W{tag}: r/L times r cos 2w (proportional angle)")
        if A is not None and W is not None:
            kZ = b.circle_segment(f"Z{tag}.k", A, gr.origin, W, de="r/L·r·cos 2ω mit dem Zirkel angesetzt",
                                  en="r/L r cos 2w added with the compass")
            Z = b.intersect(f"Z{tag}", gr.line, kZ, rule=("toward", gr.origin, W),
                            de=f"Z{tag}: r (cos ω + r/L cos 2ω)", en=f"Z{tag}: r (cos w + r/L cos 2w)")
        else:
            Z = A if A is not None else W
        assert Z is not None
        return carry_across(b, c.angle, f"V{tag}", Z, c.gf, de=f"V{tag}: F/f-mal genommen (Proportionswinkel)",
                            en=f"V{tag}: multiplied by F/f (proportional angle)")


def stroke_direction(b: Builder, c: OrdinateFrame) -> float:
    """+1 if the stroke line runs from D0 towards increasing x (the layout of :func:`crank.build_frame`)."""
    return 1.0 if b[c.D1][0] > b[c.D0][0] else -1.0


def point_kind(k: int, n: int) -> str:
    if k == 0:
        return "start"
    if k == n:
        return "end"
    if 2 * k == n:
        return "quarter"
    if 4 * k == n or 4 * k == 3 * n:
        return "octant"
    return "generic"
