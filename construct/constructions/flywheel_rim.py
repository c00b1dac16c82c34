"""Baumann's flywheel: rim, arms smeared into a disc of equal stress, and hub (seed 004, Fig. 28).

Baumann turns the arms into a disc of the same tensile stress kz in every
concentric ring: its thickness grows inward as b = b1·r1/r from b1 at the
rim's mean radius r1 to b2 = 6 b1 at the hub radius r1/6 ("Begrenzungen durch
Hyperbeln"); the hub runs from the shaft radius r1/12 to r1/6 with the length
4 b2 = 24 b1.  The plate is the wheel's half section:

* the radius r1 (along the mid-plane, the shaft axis vertical through O) divided into 12 parts (the straightedge's equal division):
  r1/12 the shaft, r1/6 the hub;
* each side of the disc is the hyperbola x·r = b1 r1/2 through the point
  (±b1/2, r1), drawn point by point with the rectangle's diagonal from the
  centre O (as the indicator diagram's hyperbolas): at r1/6 it gives
  b2/2 = 3 b1 by itself;
* the hub's half-length 2 b2 = four times that half-thickness, stepped off;
* the circle that halves the disc's mass, ρ = (r1/6 + r1)/2 = 7/12 r1: b·r is
  constant, so every radius interval carries the same mass -- the midpoint,
  where Baumann concentrates the disc for its moment (his ρ = 7/12 r1);
* the rim, a square section of side ``rim`` about the radius r1.

The planimeter gives the disc's section, which Baumann integrates to
b1 r1 ln 6 = 1.79 b1 r1.

>>> fig = FLYWHEEL_RIM.figure()
>>> round(disc_half_width(fig, "U2") / fig.replay.givens["b1"], 12)   # at r1/6: 3 b1 = b2/2
3.0
"""

from __future__ import annotations

import math
from typing import Any, Mapping

from .checking import EUCLIDEAN_TOLERANCE, Check
from ..kernel.instruments import Builder
from ..kernel.protocol import Caption
from . import Construction, Figure, bounded, register
from .domain import DISC_THICKNESS, DRAWN_LENGTH, RIM_SECTION
from .indicator_parts import hyperbola_point, square
from .phrases import BAUMANN_1902, Cite, number

__all__ = ["FLYWHEEL_RIM", "build_flywheel_rim", "flywheel_rim_checks", "disc_half_width"]

PLATE = (r"axis|mid", r"O", r"R1", r"rim\d", r"disc[UD]", r"hub\d", r"shaft", r"rho[UD]?", r"[UD]\d+", r"K[UD]",
         r"section", r"(hub|rim)section")


def _givens(r: Any, b1: Any, rim: Any) -> dict[str, float]:
    g = {"r": bounded("rim radius r1 (drawing units)", r, DRAWN_LENGTH),
         "b1": bounded("disc thickness b1 at the rim over r1", b1, DISC_THICKNESS),
         "rim": bounded("rim section side over r1", rim, RIM_SECTION)}
    return g


def _validate(givens: Mapping[str, float]) -> None:
    _givens(givens["r"], givens["b1"], givens["rim"])


def build_flywheel_rim(*, r: float, b1: float, rim: float) -> Figure:
    givens = _givens(r, b1, rim)
    b = Builder("flywheel-rim", givens, {"plate": PLATE})
    with b.group("mid-plane, shaft axis and the radius r1", "Mittelebene, Wellenachse und Halbmesser r1"):
        O = b.given_point("O", 0.0, 0.0, de="Wellenmitte O in der Mittelebene", en="shaft centre O in the mid-plane")
        mid = b.given_line("mid", O, angle_deg=0.0, de="Mittelebene des Rades (Halbmesser)",
                           en="mid-plane of the wheel (radius)", role="result")
        b.call(mid, "Mittelebene", "the mid-plane")
        b.given_length("r1", product=("r",), de="Schwerkreishalbmesser r1", en="mean radius r1 of the rim")
        k = b.circle_radius("R1.k", O, "r1", de="r1 auf der Mittelebene", en="r1 on the mid-plane")
        R1 = b.intersect("R1", mid, k, rule=("toward", O, None, 1.0, 0.0), role="result", labels={"R1": "r₁"},
                         de="Schwerkreis des Kranzes", en="the rim's mean circle")
        b.erect_perpendicular("axis", O, mid, R1)
    with b.group("r1 in 12 parts: shaft r1/12, hub r1/6", "r1 in 12 Teile: Welle r1/12, Nabe r1/6"):
        marks = [O] + b.divide_segment("m", O, R1, 12, line=mid) + [R1]
        b.given_length("open", product=("r",), factor=0.05, de="Zirkelöffnung (r1/20)", en="compass opening (r1/20)")
        levels = {j: square(b, f"lv{j}", marks[j], mid, "open") for j in range(1, 13)}
    with b.group("the disc at the rim: b1", "Scheibe am Kranz: b1"):
        b.given_length("b1/2", product=("b1", "r"), factor=0.5, de="b1/2", en="b1/2")
        sides = {}
        for side, rule in (("U", ("toward", R1, None, 0.0, 1.0)), ("D", ("toward", R1, None, 0.0, -1.0))):
            kk = b.circle_radius(f"K{side}.k", R1, "b1/2", de="b1/2 von der Mittelebene", en="b1/2 from the mid-plane")
            K = b.intersect(f"K{side}", levels[12], kk, rule=rule, de="Scheibenrand am Schwerkreis",
                            en="face of the disc at the mean circle")
            sides[side] = (K, square(b, f"kh{side}", K, levels[12], "open"))
    pts: dict[str, list[str]] = {"U": [], "D": []}
    with b.group("both faces of the disc: hyperbolas x r = b1 r1/2 by the rectangle's diagonal",
                 "beide Seiten der Scheibe: Hyperbeln x r = b1 r1/2 durch die Rechteckdiagonale"):
        for side in ("U", "D"):
            K, hor = sides[side]
            for j in range(2, 12):
                pts[side].append(hyperbola_point(b, f"{side}{j}", corner=O, known=K, known_horizontal=hor,
                                                 known_vertical=levels[12], ordinate=levels[j], opening="open",
                                                 what=(f"Scheibenseite bei {j}/12 r1", f"face of the disc at {j}/12 r1")))
            pts[side].append(K)
            b.french_curve(f"disc{side}", mid, pts[side], de="Scheibenseite (Hyperbel)", en="face of the disc (hyperbola)")
    with b.group("the hub: length 4 b2 = 24 b1, from the shaft r1/12 to r1/6",
                 "die Nabe: Länge 4 b2 = 24 b1, von der Welle r1/12 bis r1/6"):
        b.length_of("b2/2", marks[2], "U2", de="b2/2 = 3 b1 (aus der Hyperbel)", en="b2/2 = 3 b1 (from the hyperbola)")
        corners = {}
        for side in ("U", "D"):
            p = start = f"{side}2"
            for i in range(3):  # the hub's corner on this side: H1, H2, H3 (a tag each, one side's at a time)
                p = b.step_off(f"{side}.H{i + 1}", levels[2], p, "b2/2", rule=("toward", marks[2], start),
                               de="b2/2 abgetragen", en="b2/2 stepped off")
            h = square(b, f"hh{side}", p, levels[2], "open")
            corners[side] = (p, b.intersect(f"HS{side}", h, levels[1], rule=("only",), de="Nabenecke an der Welle",
                                            en="corner of the hub at the shaft"))
        # each side with the straightedge on its own (a drawn line through several points would round the corners)
        hub = [corners["U"][1], corners["U"][0], corners["D"][0], corners["D"][1]]
        for i, (p0, p1) in enumerate(zip(hub, hub[1:])):
            b.polyline(f"hub{i}", [p0, p1], role="result", de="Nabe (Halbschnitt)", en="hub (half section)")
        b.polyline("shaft", [corners["U"][1], corners["D"][1]], role="result", de="Bohrung r1/12", en="bore r1/12")
    with b.group("the circle that halves the disc: rho = 7/12 r1", "der Kreis, der die Scheibe halbiert: ρ = 7/12 r1"):
        rho = b.midpoint("rho", marks[2], R1, through=mid)
        b.set_label(rho, "ρ")
        rl = square(b, "rhol", rho, mid, "open")
        b.intersect("rhoU", rl, "discU", rule=("only",), role="result", de="ρ auf der oberen Scheibenseite",
                    en="rho on the upper face of the disc")
        b.intersect("rhoD", rl, "discD", rule=("only",), role="result", de="ρ auf der unteren Scheibenseite",
                    en="rho on the lower face of the disc")
    with b.group("the rim: a square section about r1", "der Kranz: quadratischer Querschnitt um r1"):
        b.given_length("a/2", product=("rim", "r"), factor=0.5, de="halbe Kranzbreite", en="half the rim's width")
        ku = b.circle_radius("rimM.k", R1, "a/2", de="a/2 beiderseits r1", en="a/2 either side of r1")
        # the rim's inner and outer face on the mid-plane (J, K), its corners J1, J2 and K1, K2
        inner = b.intersect("rim.J", mid, ku, rule=("toward", R1, O), de="innere Kranzseite J",
                            en="inner face J of the rim")
        outer = b.intersect("rim.K", mid, ku, rule=("farther", O), de="äußere Kranzseite K",
                            en="outer face K of the rim")
        cs = {}
        for tag, foot in (("J", inner), ("K", outer)):
            v = square(b, f"rimv{tag}", foot, mid, "open")
            kk = b.circle_radius(f"rim.{tag}.c", foot, "a/2", de="a/2 nach beiden Seiten", en="a/2 to either side")
            cs[tag] = b.intersect((f"rim.{tag}1", f"rim.{tag}2"), v, kk, rule=("toward", None, None, 0.0, 1.0),
                                  de=f"Kranzecken {tag}1 und {tag}2", en=f"corners {tag}1 and {tag}2 of the rim")
        ring = [cs["J"][0], cs["K"][0], cs["K"][1], cs["J"][1], cs["J"][0]]
        for i, (p0, p1) in enumerate(zip(ring, ring[1:])):
            b.polyline(f"rim{i}", [p0, p1], role="result", de="Kranzquerschnitt", en="section of the rim")
    with b.group("the planimeter: the disc's section", "Planimeter: Querschnitt der Scheibe"):
        b.area_between("section", "discU", "discD", "U2", "KU", hatch_deg=45.0, role="result",
                       de="Scheibenquerschnitt zwischen r1/6 und r1", en="section of the disc between r1/6 and r1")
    with b.group("hub and rim in section", "Nabe und Kranz im Schnitt"):
        # hatched across the disc; the disc, counted up to r1 (Baumann: "bewusstermassen ... zu viel gerechnet"),
        # is hatched on the plate up to the rim, whose section lies over it
        b.area_between("hubsection", "hub0", "hub2", "HSU", "U.H3", hatch_deg=135.0, role="result",
                       de="Nabe im Schnitt", en="the hub in section")
        b.area_between("rimsection", "rim0", "rim2", "rim.J1", "rim.K1", hatch_deg=135.0, role="result",
                       de="Kranz im Schnitt", en="the rim in section")
    proto = b.protocol()
    return Figure(proto, b.replay(proto, givens))


def disc_half_width(fig: Figure, point: str) -> float:
    """Distance of a point from the mid-plane, in units of r1."""
    rp = fig.replay
    return abs(rp[point][1] - rp["O"][1]) / rp.givens["r"]


def _radius(fig: Figure, point: str) -> float:
    rp = fig.replay
    return (rp[point][0] - rp["O"][0]) / rp.givens["r"]


def flywheel_rim_checks(fig: Figure) -> list[Check]:
    g = fig.replay.givens
    b1 = g["b1"]
    tol = 10 * EUCLIDEAN_TOLERANCE
    checks = []
    for side in ("U", "D"):
        for j in range(2, 12):
            p = f"{side}{j}"
            checks.append(Check(f"disc face {side} at {j}/12 r1: x r = b1 r1/2", disc_half_width(fig, p) * _radius(fig, p),
                                b1 / 2, tol, "the rectangle's diagonal: Euclidean", "r1²"))
    checks.append(Check("b2 = 6 b1 at the hub radius r1/6", 2 * disc_half_width(fig, "U2"), 6 * b1, tol,
                        "the hyperbola itself at r1/6", "r1"))
    checks.append(Check("hub length 4 b2 = 24 b1", disc_half_width(fig, "U.H3") + disc_half_width(fig, "D.H3"), 24 * b1,
                        tol * 4, "b2/2 stepped off four times on each side", "r1"))
    checks.append(Check("rho = 7/12 r1 (halves the disc's mass)", _radius(fig, "rho"), 7 / 12, tol,
                        "midpoint of r1/6 and r1: b r is constant", "r1"))
    area = fig.replay["section"].signed_area() / g["r"] ** 2
    exact = b1 * math.log(6.0)
    # the same French curve through exact points strays from the hyperbola; its area error is the tolerance
    checks.append(Check("disc section b1 r1 ln 6 (planimeter)", abs(area), exact, 2e-2 * exact,
                        "French curve through 11 points of the hyperbola: within 2 % (Baumann rounds ln 6 to 1.79)",
                        "r1²"))
    return checks


def flywheel_rim_plate(fig: Figure) -> dict:
    """Fig. 28 as a half section: the centre lines dash-dotted, hub, disc and rim hatched and named, the disc's
    thickness dimensioned where Baumann names it -- b₂ = 6 b₁ at the hub, b at a radius between, b₁ at r₁
    (outside the rim, which covers it) -- every length read off the constructed points."""
    R = fig.replay
    r1 = R["R1"][0] - R["O"][0]
    a = R["rim.K1"][1] - R["R1"][1]  # half the rim's side
    hub_top = R["HSU"][1]
    gap = 0.025 * r1

    def thickness(top: str, bottom: str, text: str, offset: float, side: float, up: float = 0.0) -> dict:
        # a vertical dimension between the two faces, its letter upright beside it (*up*: raised off the centre
        # line, which would run through it)
        (x, y0), (_, y1) = R[top], R[bottom]
        return {"kind": "dimension", "a": (x, y0), "b": (x, y1), "text": text, "offset": offset,
                "text_at": (x + offset + side, (y0 + y1) / 2 + up)}

    x_hub = R["U.H3"][0]
    furniture = [
        thickness("U2", "D2", "b₂", gap, 0.03 * r1, 0.022 * r1),
        # (the disc is thinner there than the letter is high: b stands above its face)
        thickness("U5", "D5", "b", 0.0, 0.022 * r1, (R["U5"][1] - R["D5"][1]) / 2 + 0.016 * r1),
        thickness("KU", "KD", "b₁", (R["rim.K1"][0] - R["R1"][0]) + gap, 0.025 * r1),
        {"kind": "lettering", "at": ((R["HSU"][0] + x_hub) / 2, hub_top + 0.025 * r1), "text": "Nabe"},
        {"kind": "lettering", "at": (R["R1"][0], R["R1"][1] + a + 0.025 * r1), "text": "Kranz"},
        {"kind": "lettering", "at": (R["rho"][0], R["rhoU"][1] + 0.03 * r1), "text": "Armscheibe"},
    ]
    return {"looks": {"axis": "centre", "mid": "centre"}, "furniture": furniture}


def flywheel_rim_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as Baumann writes them: b₁ and the rim's side, in r₁."""
    g = fig.replay.givens
    return [f"b₁ = {number(g['b1'], lang)} r₁", ("Kranz " if lang == "de" else "rim ") + f"{number(g['rim'], lang)} r₁"]


FLYWHEEL_RIM = register(Construction(
    name="flywheel-rim",
    title=Caption("Schwungrad: Kranz, Armscheibe gleicher Festigkeit und Nabe (Fig. 28)",
                  "Flywheel: rim, arm disc of equal stress and hub (Fig. 28)"),
    source="seed 004 (Baumann 1902), Fig. 28",
    build=lambda r, b1, rim: build_flywheel_rim(r=r, b1=b1, rim=rim),
    checks=flywheel_rim_checks,
    defaults={"r": 1.0, "b1": 0.02, "rim": 0.14},
    book_params=({},),
    cites=(Cite(BAUMANN_1902, "Fig. 28"),),
    wording=flywheel_rim_wording,
    plate=flywheel_rim_plate,
    validator=_validate,
    help={"b1": "flywheel-rim: disc thickness b1 at the rim, over r1 (drawn exaggerated: 0.02)",
          "rim": "flywheel-rim: side of the rim's square section, over r1 (0.14)"},
))
