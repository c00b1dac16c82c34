"""The crank circle: semicircle over the stroke, its division and the connecting-rod arcs.

Seed 001 (Abb. 1051/1054): "Man teilt ... einen über dem Kolbenhub s
geschlagenen Halbkreis in eine Anzahl gleicher Teile, vorteilhafterweise in 9
oder 18 Teile ... ermittelt die Kolbenwege x zu den Teilpunkten ... durch
Kreisbögen mit der Schubstangenlänge als Halbmesser."  Seed 000, Fig. 77 and
Tabelle 2, goes the other way: tenths of the stroke swung back to the crank
circle with the rod length give the crank angles.

Layout (y up): crank centre O at the origin, stroke line horizontal, cylinder
to the left.  The head-end dead centre D0 = (-r, 0) is crank angle 0; the
forward stroke runs over the upper semicircle to D1 = (r, 0).  A crank point
P at angle w sits at (-r cos w, r sin w); its crosshead C lies on the stroke
line a rod length L to the left of P, and the piston position X is C moved
back by L onto the stroke D0..D1, so that D0X is the piston path.

>>> fig = CRANK.figure(parts=6, rod_ratio=4.0)
>>> round(piston_fraction(fig, 3), 12)   # 90 degrees: (1 + L/r - sqrt((L/r)^2 - 1)) / 2
0.563508326896
"""

from __future__ import annotations

import math
from typing import Any, Mapping

from . import analytic
from .checking import EUCLIDEAN_TOLERANCE, Check
from ..kernel.errors import InvalidParameter
from ..kernel.letters import number
from ..kernel.division import NAMES as DIVISION_NAMES
from ..kernel.division import TRIAL_TOLERANCE, check_parts, divide_semicircle
from ..kernel.instruments import Builder
from ..kernel.protocol import Caption
from . import Construction, Figure, bounded, register, rod_ratio_param
from .domain import DRAWN_LENGTH
from .phrases import ANHANG_II, HANDBOOK, Cite, division, ratio, stroke_parts

__all__ = ["CRANK", "CRANK_ANGLE", "piston_fraction", "crank_angle", "build_frame"]


def build_frame(b: Builder, *, result_circle: bool = True, radius: tuple[str, ...] = ("r",),
                rod: tuple[str, ...] = ("rod_ratio", "r")) -> dict[str, str]:
    """Crank centre, stroke line, crank circle and dead centres: the frame every figure starts from.

    *radius* and *rod* name the givens whose product is r and L (the books'
    examples give metres and a drawing scale, the plates a ratio L/r).
    """
    with b.group("crank circle and dead centres", "Kurbelkreis und Totpunkte"):
        O = b.given_point("O", 0.0, 0.0, de="Kurbelmittelpunkt O", en="crank centre O")
        axis = b.given_line("axis", O, angle_deg=0.0, de="Hubachse (Kolbenweglinie)", en="stroke line")
        r = b.given_length("r", product=radius, de="Kurbelhalbmesser r", en="crank radius r")
        L = b.given_length("L", product=rod, de="Schubstangenlänge L", en="connecting-rod length L")
        k = b.circle_radius("crank", O, r, de="Kurbelkreis um O mit r", en="crank circle about O with radius r",
                            role="result" if result_circle else "construction")
        D0 = b.intersect("D0", axis, k, rule=("toward", O, None, -1.0, 0.0), role="result",
                         de="Totpunkt auf der Deckelseite (Hubanfang)", en="head-end dead centre (start of stroke)",
                         labels={"D0": "A"})
        D1 = b.intersect("D1", axis, k, rule=("toward", O, None, 1.0, 0.0), role="result",
                         de="Totpunkt auf der Kurbelseite (Hubende)", en="crank-end dead centre (end of stroke)",
                         labels={"D1": "B"})
    return {"O": O, "axis": axis, "r": r, "L": L, "circle": k, "D0": D0, "D1": D1}


def _givens(r: Any, rod_ratio: Any) -> dict[str, float]:
    return {"r": bounded("crank radius r", r, DRAWN_LENGTH), "rod_ratio": rod_ratio_param(rod_ratio)}


def _validate(givens: Mapping[str, float]) -> None:
    _givens(givens["r"], givens["rod_ratio"])


# -- the crank construction -------------------------------------------------------


def build_crank(*, rod_ratio: float, parts: int, method: str, r: float) -> Figure:
    givens = _givens(r, rod_ratio)
    used = check_parts(parts, method)
    b = Builder("crank", givens, {"parts": parts, "method": used, "requested_method": method})
    f = build_frame(b)
    points = divide_semicircle(b, O=f["O"], D0=f["D0"], D1=f["D1"], circle=f["circle"], axis=f["axis"],
                               n=parts, method=used)
    for k, p in enumerate(points):
        b.set_label(p, str(k))  # the books number the division points 0, 1, ..., n
    rod_arcs(b, f, points)
    infinite_rod(b, f, points)
    crank_and_rod(b, f, points)
    proto = b.protocol()
    return Figure(proto, b.replay(proto, givens))


def crank_position(n: int) -> int:
    """The division point Fig. 1 draws the crank and the rod at: 40° (point 4 of 18)."""
    return min(n, max(1, round(2 * n / 9)))


def crank_and_rod(b: Builder, f: Mapping[str, str], points: list[str]) -> None:
    """What the figure is for, drawn as its result: the stroke s = 2r between the dead centres, and the crank
    and the connecting rod in one position (Fig. 1's 40°), each joined by the straightedge and lettered."""
    j = crank_position(len(points) - 1)
    with b.group("the stroke s = 2r; the crank and the rod in one position",
                 "Hub s = 2r; Kurbel und Schubstange in einer Stellung"):
        b.polyline("stroke", [f["D0"], f["D1"]], de="Hub s zwischen den Totpunkten", en="stroke s between the dead centres")
        b.set_label("stroke", "s = 2r")
        b.polyline("crankarm", [f["O"], points[j]], de=f"Kurbel O{j}", en=f"crank O{j}")
        b.set_label("crankarm", "r")
        b.polyline("rodline", [points[j], f"C{j}"], de=f"Schubstange {j}C{j}", en=f"connecting rod {j}C{j}")
        b.set_label("rodline", "L")


def rod_arcs(b: Builder, f: Mapping[str, str], points: list[str]) -> None:
    """For each division point: rod arc to the crosshead, and the rod swung back onto the stroke."""
    n = len(points) - 1
    with b.group(f"all {n + 1} connecting-rod arcs", f"alle {n + 1} Schubstangenbögen"):
        for k, p in enumerate(points):
            with b.group(f"rod arcs from point {k}", f"Schubstangenbögen von Punkt {k}"):
                # the rod length by its name: the caption writes the letter its figure gives it (L, or § 146's l)
                arc = b.circle_radius(f"rod{k}", p, f["L"], de=f"Bogen um {k} mit der Schubstangenlänge {f['L']}",
                                      en=f"arc about point {k} with the rod length {f['L']}")
                C = b.intersect(f"C{k}", arc, f["axis"], rule=("toward", f["O"], None, -1.0, 0.0),
                                de=f"Kreuzkopf C{k} auf der Hubachse", en=f"crosshead C{k} on the stroke line")
                back = b.circle_through(f"back{k}", C, p, de=f"Bogen um C{k} durch {k} zurück auf den Hub",
                                        en=f"arc about C{k} through point {k} back onto the stroke")
                # At the dead centres the piston position is the dead centre itself: no second letter.
                b.intersect(f"X{k}", back, f["axis"], rule=("toward", f["O"], None, 1.0, 0.0), role="result",
                            de=f"Kolbenstellung X{k}: Kolbenweg {f['D0']}–X{k}",
                            en=f"piston position X{k}: piston path {f['D0']}–X{k}",
                            labels={f"X{k}": f"{k}'"} if 0 < k < n else None)


def infinite_rod(b: Builder, f: Mapping[str, str], points: list[str]) -> None:
    """Infinite rod: the ordinate through each division point, found as the chord to its mirror image."""
    n = len(points) - 1
    with b.group("ordinates for the infinite rod", "Ordinaten für unendliche Stangenlänge"):
        for k, p in enumerate(points[1:-1], start=1):
            # The dead centre nearer to P gives the better-conditioned intersection.
            dc = f["D0"] if 2 * k <= n else f["D1"]
            with b.group(f"ordinate through point {k}", f"Ordinate durch Punkt {k}"):
                kc = b.circle_through(f"mir{k}.k", dc, p, de=f"Kreis um den Totpunkt durch {k}",
                                      en=f"circle about the dead centre through point {k}", role="auxiliary")
                q = b.intersect(f"Q{k}", kc, f["circle"], rule=("right", f["D0"], f["D1"]), role="auxiliary",
                                de=f"Spiegelpunkt von {k} unter der Hubachse", en=f"mirror image of point {k} below the stroke line")
                ordinate = b.line(f"ord{k}", p, q, de=f"Ordinate durch {k}", en=f"ordinate through point {k}")
                b.intersect(f"Y{k}", ordinate, f["axis"], rule=("only",), role="result",
                            de=f"Kolbenstellung Y{k} bei unendlicher Stange", en=f"piston position Y{k} for an infinite rod")


# -- measurements on the figure ------------------------------------------------------


def crank_angle(fig: Figure, point: str) -> float:
    """The angle D0-O-point, read off the figure (radians, 0..pi on the forward stroke)."""
    o, d0, p = fig.replay["O"], fig.replay["D0"], fig.replay[point]
    ux, uy = d0[0] - o[0], d0[1] - o[1]
    vx, vy = p[0] - o[0], p[1] - o[1]
    return math.atan2(abs(ux * vy - uy * vx), ux * vx + uy * vy)


def stroke_fraction(fig: Figure, point: str) -> float:
    """Distance D0-point as a fraction of the stroke D0-D1, measured on the figure."""
    d0, d1, x = fig.replay["D0"], fig.replay["D1"], fig.replay[point]
    return d0.distance(x) / d0.distance(d1)


def piston_fraction(fig: Figure, k: int) -> float:
    """Constructed piston path at division point k, as a fraction of the stroke."""
    return stroke_fraction(fig, f"X{k}")


def point_name(fig: Figure, k: int) -> str:
    n = fig.params["parts"]
    return "D0" if k == 0 else "D1" if k == n else f"P{k}"


def angle_tolerance(fig: Figure, name: str, made_by: dict | None = None) -> tuple[float, str]:
    """How far a division point may stray from its nominal angle, and why."""
    prov = (made_by or fig.replay.made_by())[name].provenance
    if prov.kind == "approximate":
        return prov.error + EUCLIDEAN_TOLERANCE, f"{prov.method}: a-priori error bound {prov.error:.2e} rad"
    if prov.kind == "trial":
        return 2.0 * TRIAL_TOLERANCE + 1e-11, "dividers by trial: closing tolerance 1e-11 r, spread over the steps"
    if prov.kind == "neusis":
        return 1e-11, "marked ruler slid to 1e-15 r: exact up to the float chain"
    return EUCLIDEAN_TOLERANCE, "Euclidean steps only: float rounding"


def crank_checks(fig: Figure) -> list[Check]:
    n = fig.params["parts"]
    g = fig.replay.givens
    r, L = g["r"], g["rod_ratio"] * g["r"]
    lam = r / L
    made_by = fig.replay.made_by()
    checks: list[Check] = []
    for k in range(n + 1):
        name = point_name(fig, k)
        nominal = math.pi * k / n
        w = crank_angle(fig, name)
        tol_w, why_w = angle_tolerance(fig, name, made_by)
        checks.append(Check(f"crank angle {k}", w, nominal, tol_w, why_w, "rad"))
        # The rod arcs are Euclidean: measured against the exact path at the angle the point really has ...
        x = piston_fraction(fig, k)
        checks.append(Check(f"piston path {k} (rod arcs)", x, analytic.piston_path_exact(w, r, L) / (2 * r),
                            EUCLIDEAN_TOLERANCE, "rod arcs are Euclidean: float rounding only", "stroke"))
        # ... and against the nominal angle, where the division's error comes in (|dx/dw| <= (1 + lam)/2 strokes).
        slope = 0.5 * (1.0 + lam)
        checks.append(Check(f"piston path {k} (exact formula)", x, analytic.piston_path_exact(nominal, r, L) / (2 * r),
                            EUCLIDEAN_TOLERANCE + slope * tol_w, f"division error {tol_w:.1e} rad times |dx/dw|",
                            "stroke"))
        # Gl. (1) drops the lam^3 sin^4 / 8 term and beyond: its error is at most that over (1 - lam^2).
        book_err = analytic.piston_path_book_bound(nominal, lam) / 2.0
        checks.append(Check(f"piston path {k} (book Gl. 1)", x, analytic.piston_path_book(nominal, r, L) / (2 * r),
                            book_err + EUCLIDEAN_TOLERANCE + slope * tol_w,
                            "Gl. (1) truncates the series after lam sin^2/2: remainder <= lam^3 sin^4 / (8 (1 - lam^2))",
                            "stroke"))
        if 0 < k < n:
            y = stroke_fraction(fig, f"Y{k}")
            checks.append(Check(f"infinite rod {k}", y, (1.0 - math.cos(nominal)) / 2.0,
                                EUCLIDEAN_TOLERANCE + 0.5 * tol_w, "Euclidean ordinate; division error times |dx/dw|",
                                "stroke"))
    return checks


# -- the plates' furniture (plain data; construct.render.plate draws it) -----------------------


def _unit(a, b) -> tuple[float, float]:
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(dx, dy)
    return dx / n, dy / n


def frame_furniture(fig: Figure, crank_point: str | None = None, crosshead: str | None = None) -> list[dict]:
    """Stroke s, crank radius r and rod length L as dimensions; the crank and the rod in one position.

    Every length is read off the figure: r = O-B, the rod from the crank point
    to its crosshead, L/r as the figure measures it.
    """
    R = fig.replay
    O, D0, D1 = R["O"], R["D0"], R["D1"]
    r = O.distance(D1)
    out: list[dict] = [{"kind": "dimension", "a": tuple(D0), "b": tuple(D1), "text": "s = 2r", "offset": -0.2 * r}]
    if crank_point is not None:
        P = R[crank_point]
        out += [{"kind": "stroke", "a": tuple(O), "b": tuple(P), "look": "heavy"},
                {"kind": "dimension", "a": tuple(O), "b": tuple(P), "text": "r", "offset": -0.08 * r}]
        if crosshead is not None:
            # the rod to its crosshead, a rod length away: the renderer breaks the long empty stretch out
            C = R[crosshead]
            ratio = P.distance(C) / r
            out += [{"kind": "stroke", "a": tuple(P), "b": tuple(C), "look": "heavy"},
                    {"kind": "dot", "at": tuple(C)},
                    {"kind": "lettering", "at": (C[0], C[1] - 0.12 * r), "text": "C"},
                    {"kind": "stroke", "a": (C[0] - 0.15 * r, C[1]), "b": tuple(D0), "look": "centre"},
                    # (room for the longest it writes, "L = 1,234 r": one break in the line whatever the rod)
                    {"kind": "dimension", "a": tuple(C), "b": tuple(P), "text": f"L = {number(ratio, 'de')} r",
                     "offset": 0.12 * r, "room": 11}]
    return out


def crank_plate(fig: Figure) -> dict:
    """Fig. 1: centre line dash-dotted, rod arcs and ordinates thin, s and r dimensioned, crank at 40°.

    The construction's own crank, rod and stroke are dimensioned here as the book does (arrowheads),
    not lettered; the stroke is not drawn over the centre line.
    """
    n = fig.params["parts"]
    j = crank_position(n)
    # one dot per point: the finite rod's piston positions 1′ ... are dotted; the infinite rod's (the feet of the
    # ordinates) are where those lines cross the centre line, undotted, so that no two dots stand for one division
    looks = {"axis": "centre", **{f"back{k}": "thin" for k in range(n + 1)},
             **{f"ord{k}": "thin" for k in range(1, n)}, **{f"Y{k}": "hidden" for k in range(1, n)},
             "stroke": "hidden unlettered", "crankarm": "heavy unlettered", "rodline": "heavy unlettered"}
    return {"looks": looks, "furniture": frame_furniture(fig, point_name(fig, j), f"C{j}")}


def crank_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as the books write them: the rod (r/L = 1/5) and the semicircle's division."""
    return [ratio("r/L", fig.replay.givens["rod_ratio"], lang), division(fig, lang)]


CRANK = register(Construction(
    name="crank",
    title=Caption("Kolbenwege aus dem Kurbelkreis", "Piston paths from the crank circle"),
    source="seed 001, Abb. 1051/1054; seed 000, Fig. 77",
    build=build_crank,
    checks=crank_checks,
    defaults={"rod_ratio": 5.0, "parts": 18, "method": "auto", "r": 1.0},
    book_params=({"rod_ratio": 5.0, "parts": 18}, {"rod_ratio": 5.0, "parts": 9}),
    structural=("parts", "method"),
    steady=("rod_ratio",),
    cites=(Cite(HANDBOOK, "Abb. 1051/1054"), Cite(ANHANG_II, "Fig. 77")),
    wording=crank_wording,
    methods=DIVISION_NAMES,
    plate=crank_plate,
    validator=_validate,
))


# -- the inverse: tenths of the stroke back to crank angles ----------------------------


def build_crank_angle(*, rod_ratio: float, divisions: int, r: float) -> Figure:
    givens = _givens(r, rod_ratio)
    if isinstance(divisions, bool) or not isinstance(divisions, int) or not 1 <= divisions <= 1000:
        raise InvalidParameter(f"number of stroke divisions must be a whole number from 1 to 1000, got {divisions!r}")
    b = Builder("crank-angle", givens, {"divisions": divisions})
    f = build_frame(b)
    m = divisions
    with b.group(f"stroke divided into {m} equal parts", f"Hub in {m} gleiche Teile geteilt"):
        marks = [f["D0"]] + (b.divide_segment("x", f["D0"], f["D1"], m, line=f["axis"]) if m > 1 else []) + [f["D1"]]
        for j in range(1, m):  # numbered as their crank points: the tenth j of the stroke gives the crank point j
            b.set_label(marks[j], str(j))
    with b.group("rod length swung back to the crank circle", "Schubstangenlänge auf den Kurbelkreis zurückgeschlagen"):
        for j, x in enumerate(marks):
            with b.group(f"crank angle for {j}/{m} of the stroke", f"Kurbelwinkel zu {j}/{m} Hub"):
                arc = b.circle_radius(f"cross{j}.k", x, f["L"], de=f"Bogen um {j}/{m} mit L",
                                      en=f"arc about mark {j}/{m} with L")
                C = b.intersect(f"C{j}", arc, f["axis"], rule=("toward", f["O"], None, -1.0, 0.0),
                                de=f"Kreuzkopf C{j}", en=f"crosshead C{j}")
                back = b.circle_radius(f"rod{j}", C, f["L"], de=f"Bogen um C{j} mit L auf den Kurbelkreis",
                                       en=f"arc about C{j} with L onto the crank circle")
                W = b.intersect(f"W{j}", back, f["circle"], rule=("left", f["D0"], f["D1"]), role="result",
                                de=f"Kurbelstellung {j}: Kurbelwinkel ω{j} = ∠A–O–{j}",
                                en=f"crank position {j}: crank angle ω{j} = ∠A–O–{j}",
                                labels={f"W{j}": f"{j}"})
                if 0 < j < m:  # the dead centres' cranks lie on the stroke line
                    # the crank drawn to its point and lettered with its angle AOW as the figure measures it
                    # (Tabelle 2's column): a reading of the constructed points, not the formula
                    b.polyline(f"OW{j}", [f["O"], W], role="result", de=f"Kurbel O{j}, Winkel ω{j} gemessen",
                               en=f"crank O{j}, its angle ω{j} measured")
                    b.set_label(f"OW{j}", f"{{∠{f['D0']} {f['O']} {W}}}")
    proto = b.protocol()
    return Figure(proto, b.replay(proto, givens))


def inverse_tolerance(x: float) -> float:
    """Near the dead centres the rod arc meets the crank circle almost tangentially.

    A gap error e in the circles moves the crossing by about sqrt(e) at the
    ends (tangency) and e / sin(w) elsewhere; with e ~ 1e-15 of the stroke this
    gives 1e-12 rad in the middle, up to ~1e-7 rad one step from the dead
    centre for very fine divisions.  Exactly at the dead centres the tangency
    tolerance makes the crossing the dead centre itself.
    """
    edge = min(x, 1.0 - x)
    if edge <= 0.0:
        return 1e-9
    return 1e-12 + 3e-16 / edge


#: The error of the stroke's division points, in units of eps x stroke x m^2 for m parts.  The points
#: come from divide_segment: dividers stepped m times along a ray (after log2(m) halvings), so a
#: point's error grows like m^2 eps.  Measured on the largest error of points 1..m-1 at L/r = 5:
#: 0.0050 (m = 100), 0.0051 (200), 0.0046 (500), 0.0044 (1000); the bound is four times that.
#: (At 1000 divisions 780 of 1001 checks failed by ~1.5e-12 -- the tolerance assumed points
#: exact to 1e-15 of the stroke; the measured angle error is the division points' error carried
#: through dw/dx, to within 1%.  The domain 1..1000 stands: the construction is honest there.)
DIVISION_ERROR = 0.02


def division_tolerance(m: int, x: float, r: float, L: float) -> float:
    """The angle error a division point of m parts carries at x of the stroke: its position error
    (DIVISION_ERROR m^2 eps of the stroke) times dw/dx, the sensitivity of the crank angle to the
    piston path (from the analytic law x(w), not from the figure)."""
    if m <= 1 or not 0.0 < x < 1.0:
        return 0.0  # the dead centres are given, not divided
    w = analytic.crank_angle_from_path(2 * r * x, r, L)
    dx_dw = 2.0 * r * analytic.piston_rate(w, r / L)
    return DIVISION_ERROR * m * m * 2.220446049250313e-16 * 2 * r / abs(dx_dw)


def crank_angle_checks(fig: Figure) -> list[Check]:
    m = fig.params["divisions"]
    g = fig.replay.givens
    r, L = g["r"], g["rod_ratio"] * g["r"]
    checks = []
    for j in range(m + 1):
        x = j / m
        w = crank_angle(fig, f"W{j}")
        checks.append(Check(f"crank angle at {j}/{m} stroke", w, analytic.crank_angle_from_path(2 * r * x, r, L),
                            inverse_tolerance(x) + division_tolerance(m, x, r, L),
                            "Euclidean; the rod arc meets the circle nearly tangentially at the ends; the stroke's "
                            "division points carry m^2 eps", "rad"))
    return checks


def crank_angle_plate(fig: Figure) -> dict:
    """Fig. 77 with what Tabelle 2 tabulates: the radius to each found crank position, its angle arc and value.

    The value is the angle AOW measured on the constructed figure, in degrees and minutes.
    """
    R = fig.replay
    m = fig.params["divisions"]
    O, D0 = R["O"], R["D0"]
    r = O.distance(R["D1"])
    out = frame_furniture(fig)
    for j in range(1, m):
        W = R[f"W{j}"]
        w = crank_angle(fig, f"W{j}")
        ux, uy = _unit(O, W)
        minutes = round(math.degrees(w) * 60.0)
        text = f"{minutes // 60}°{minutes % 60:02d}′"
        # the value along its radius, reading outwards on the right and inwards on the left
        along = math.degrees(math.atan2(uy, ux))
        along = along - 180.0 if along > 90.0 else along
        side = 0.035 * r
        out += [{"kind": "stroke", "a": tuple(O), "b": tuple(W), "look": "thin"},
                {"kind": "angle", "centre": tuple(O), "start": tuple(D0), "end": tuple(W),
                 "radius": (0.12 + 0.45 * j / m) * r},
                {"kind": "lettering", "at": (O[0] + 0.8 * r * ux - side * uy, O[1] + 0.8 * r * uy + side * ux),
                 "text": text, "angle": along, "size": 0.9}]
    # the construction's cranks are drawn here as the plate's thin radii with their angles along them
    looks = {"axis": "centre", **{f"rod{j}": "thin" for j in range(m + 1)},
             **{f"OW{j}": "hidden unlettered" for j in range(1, m)}}
    return {"looks": looks, "furniture": out}


def crank_angle_wording(fig: Figure, lang: str) -> list[str]:
    """The givens as seed 000 writes them: the rod (r/L = 1/5) and the stroke's tenths."""
    return [ratio("r/L", fig.replay.givens["rod_ratio"], lang), stroke_parts(fig, lang)]


CRANK_ANGLE = register(Construction(
    name="crank-angle",
    title=Caption("Kurbelwinkel aus den Zehnteln des Hubes", "Crank angles from tenths of the stroke"),
    source="seed 000, Fig. 77 and Tabelle 2, Gl. (h)",
    build=build_crank_angle,
    checks=crank_angle_checks,
    defaults={"rod_ratio": 5.0, "divisions": 10, "r": 1.0},
    book_params=({"rod_ratio": 4.0}, {"rod_ratio": 5.0}, {"rod_ratio": 6.0}),
    structural=("divisions",),
    steady=("rod_ratio",),
    cites=(Cite(ANHANG_II, "Fig. 77, Tabelle 2"),),
    wording=crank_angle_wording,
    plate=crank_angle_plate,
    validator=_validate,
))
