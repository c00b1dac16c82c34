"""The piston-force plate (Abb. 1055): what it shows, its looks and lettering, and over a revolution its panels."""

from __future__ import annotations

import math
import re

from ...kernel.geometry import Point
from .. import Figure
from ..scales import scale_furniture

__all__ = ["PLATE", "piston_force_plate", "REVOLUTION_PLATE", "CARD_PLATE"]


#: What Abb. 1055 shows: the base line, the piston-force line, the mass-force curve, the free forces
#: hatched vertically, J; the ordinates' feet as the stroke's division.
PLATE = (r"fbase", r"F\d+", r"K\d+|Ks[12]", r"M\d+", r"ord\d+", r"force[abc]", r"mass", r"J", r"free\.[abc]")


def piston_force_plate(fig: Figure) -> dict:
    """Abb. 1055 as a plate: the piston-force line and the mass-force line heavy over a thin piston-path
    line, lettered as the book letters them -- J where the piston force changes sign, C the end of the
    force line and O the end of the piston-path line ("zwischen J und C negativ", "von J bis O") -- the
    lines named (P = F·p_ü, P_b the mass forces, eq. 297/298), and a force scale in kg beside the diagram.

    The two-sided plate (``--revolution``) is laid out in landscape, as a book sets a cover-side and a
    crank-side diagram side by side (:func:`_revolution_panels`): the forward stroke on the left (the cover
    side's indicator diagram over its force diagram), the return stroke on the right (the crank side's over
    its own), the two force diagrams on one level, so that one kg scale serves both.

    Every position is a constructed point; the scale's divisions are the given drawn length per kg.
    """
    R = fig.replay
    n = fig.params["parts"]
    F0, Fn, Kn = R["F0"], R[f"F{n}"], R[f"K{n}"]
    s = abs(Fn[0] - F0[0])
    unit = R.givens["force_unit"]
    two_sided = bool(fig.params.get("revolution"))
    panels = _revolution_panels(fig) if two_sided else []
    fdy = panels[1]["shift"][1] if panels else 0.0  # the forward force diagram's shift on the sheet
    y0 = F0[1] + fdy
    ks = [R[f"K{k}"][1] for k in range(n + 1)] + [R[f"M{k}"][1] for k in range(n + 1)]
    step = 2000.0
    lo = int(math.floor((min(ks) - F0[1]) / unit / step))
    hi = int(math.floor((max(ks) - F0[1]) / unit / step + 1e-9))
    # the scale stands clear of the piston-path line's end (which reaches a little past F0), so that no
    # line strikes its figures
    x = F0[0] - (0.25 if two_sided else 0.07) * s
    tick = 0.012 * s
    # "kg" over the scale, as Abb. 1055 has it
    kg_at = (x, y0 + (hi + 0.6) * step * unit)
    furniture: list[dict] = scale_furniture(x=x, zero=y0, unit=unit, values=[i * step for i in range(lo, hi + 1)],
                                            tick=tick, text="kg", size=1.0 if two_sided else 0.8,
                                            text_size=1.0 if two_sided else 0.85, gap=2.2, text_at=kg_at)
    d = 0.035 * s
    # the dead centres, where the stroke begins and ends: a heavy tick across the piston-path line
    ends = [(F0[0], y0), (Fn[0], y0)]
    if two_sided:
        (rx, ry) = panels[3]["shift"]
        ends += [(R["rF0"][0] + rx, R["rF0"][1] + ry), (R[f"rF{n}"][0] + rx, R[f"rF{n}"][1] + ry)]
    furniture += [{"kind": "stroke", "a": (ex, ey - 0.6 * d), "b": (ex, ey + 0.6 * d), "look": "heavy"}
                  for ex, ey in ends]
    if not two_sided:  # the book's O and C end its one diagram; the two-sided plate is not the book's
        furniture += [
            {"kind": "lettering", "at": (Fn[0] + 0.45 * d, Fn[1] + 0.5 * d), "text": "O"},
            {"kind": "lettering", "at": (Kn[0] + 0.5 * d, Kn[1] - 0.2 * d), "text": "C"},
        ]
    # the names of the lines, beside a quarter of the way along each
    kq, mq = R[f"K{max(1, (3 * n) // 8)}"], R[f"M{max(1, n // 6)}"]
    furniture += [
        {"kind": "lettering", "at": (kq[0] + 1.8 * d, kq[1] + fdy + 1.2 * d), "text": "P = F·p_ü", "anchor": "start"},
        {"kind": "lettering", "at": (mq[0] + 0.5 * d, mq[1] + fdy + 1.3 * d), "text": "P_b", "anchor": "start"},
    ]
    looks = {"forcea": "heavy", "forceb": "heavy", "forcec": "heavy", "mass": "heavy", "fbase": "thin"}
    if two_sided:
        # the return stroke runs from the crank end: its lines named a quarter of the way from there
        rk, rm = R[f"rK{n - max(1, (3 * n) // 8)}"], R[f"rM{n - max(1, n // 6)}"]
        furniture += [
            {"kind": "lettering", "at": (rk[0] + rx - 1.8 * d, rk[1] + ry + 1.2 * d), "text": "P = F·p_ü",
             "anchor": "end"},
            {"kind": "lettering", "at": (rm[0] + rx - 0.5 * d, rm[1] + ry + 1.3 * d), "text": "P_b", "anchor": "end"},
        ]
        # each side's steam diagram named over it; the crank side's is drawn downwards from its stroke line (as
        # Abb. 1054 draws it under the cover side's, the over-pressure between them)
        (cx, cy) = panels[2]["shift"]
        top = R["ind.A0"][1] if "ind.A0" in R else R["D0"][1] + 0.6 * s  # the admission line (a card has none)
        furniture += [
            {"kind": "lettering", "at": ((F0[0] + Fn[0]) / 2, top + 1.6 * d), "text": "Deckelseite"},
            {"kind": "lettering", "at": ((F0[0] + Fn[0]) / 2 + cx, R["D0"][1] + cy + 2.6 * d),
             "text": "Kurbelseite, nach unten aufgetragen"},
        ]
        # each column named under its force diagram
        bottom = min(y0 + (lo - 1.6) * step * unit, min(R[f"rK{k}"][1] + ry for k in range(n + 1)) - 3 * d)
        furniture += [
            {"kind": "lettering", "at": ((F0[0] + Fn[0]) / 2, bottom), "text": "Hingang (Deckelseite)"},
            {"kind": "lettering", "at": ((F0[0] + Fn[0]) / 2 + rx, bottom), "text": "Rückgang (Kurbelseite)"},
        ]
        looks.update({"rforcea": "heavy", "rforceb": "heavy", "rforcec": "heavy", "rmass": "heavy", "rbase": "thin"})
        # the clearance ends Z, Z' lettered over the stroke line, where nothing else stands: under it, the dead
        # centres' numbers would crowd them at the landscape sheet's scale
        letters = {n: t for st in fig.protocol.steps for n, t in st.labels}
        for name in ("ind.Z0", "ind.Z1"):
            if name in R and name in letters:
                Z = R[name]
                looks[name] = "unlettered"
                furniture.append({"kind": "lettering", "at": (Z[0], Z[1] + 2.2 * d), "text": letters[name]})
    # what the letters stand for, in the words of seed 001 ("Im Punkte J ... wird die Kolbenkraft Null und zwischen
    # J und C negativ", "von J bis O")
    legend = {"P = F·p_ü": ("Kolbenkraft, Gl. (297)", "piston force, eq. (297)"),
              "P_b": ("Massenkräfte, Gl. (298)", "mass forces, eq. (298)"),
              "J": ("Druckwechsel: die Kolbenkraft wird null", "reversal: the piston force is zero"),
              "C": ("Ende der Kolbenkraftlinie", "end of the piston-force line"),
              "O": ("Ende der Kolbenweglinie (Totpunkt)", "end of the piston-path line (dead centre)")}
    return {"looks": looks, "furniture": furniture, "panels": panels, "legend": legend}


#: The two-sided plate's panels: each side's indicator diagram over its stroke's force diagram.  The stroke
#: line, its dead centres and the ordinates stand in both columns.
_COVER = (r"axis", r"D[01]", r"ord\d+", r"ind\..*", r"card\..*")


_FORWARD = (r"ord\d+", r"fbase", r"F\d+", r"K\d+|Ks[12]", r"M\d+", r"force[abc]", r"mass", r"free\.[abc]", r"J")


_CRANK_SIDE = (r"axis", r"D[01]", r"ord\d+", r"crk\..*", r"crank\..*")


_RETURN = (r"ord\d+", r"rbase", r"rF\d+", r"rK\d+|rKs[12]", r"rM\d+", r"rforce[abc]", r"rmass", r"rfree\.[abc]")


def _revolution_panels(fig: Figure) -> list[dict]:
    """Where the two-sided plate puts its four diagrams (drawing units): the cover side's indicator diagram
    where it was constructed, its force diagram moved up under it, the crank side's diagram and the return
    stroke's force diagram a stroke and a half to the right, the two force diagrams' base lines on one level
    and the two indicator diagrams on one band.  Only whole diagrams move: every ordinate is read from its
    own base line, so no value on the plate changes."""
    R = fig.replay
    s = abs(R["D1"][0] - R["D0"][0])
    shown = [re.compile(p) for p in fig.params["plate"]]  # what the plate draws of each panel's objects

    def box(patterns: tuple[str, ...], skip: tuple[str, ...] = (r"ord\d+", r"axis")) -> tuple[float, ...]:
        pats = [re.compile(p) for p in patterns if p not in skip]
        pts = []
        for name, obj in R.items():
            if not (any(p.fullmatch(name) for p in pats) and any(p.fullmatch(name) for p in shown)):
                continue
            if hasattr(obj, "curve_points"):
                pts.extend(obj.curve_points())
            elif hasattr(obj, "rings"):
                pts.extend(q for ring in obj.rings() for q in ring)
            elif isinstance(obj, Point):
                pts.append(obj)
        return (min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts), max(p[1] for p in pts))

    cover, forward, crank = box(_COVER), box(_FORWARD), box(_CRANK_SIDE)
    gap = 0.35 * s  # under the stroke line: its letters (Z, 0, 18, Z')
    fdy = cover[1] - gap - forward[3]
    cdy = cover[1] - crank[1]  # the crank side's diagram on the cover side's band
    rdy = R["F0"][1] + fdy - R["rF0"][1]  # the base lines on one level
    dx = cover[2] - crank[0] + 0.5 * s
    return [{"names": _COVER, "shift": (0.0, 0.0)}, {"names": _FORWARD, "shift": (0.0, fdy)},
            {"names": _CRANK_SIDE, "shift": (dx, cdy)}, {"names": _RETURN, "shift": (dx, rdy)}]


#: What the two-sided plate adds: the crank side's diagram below the stroke line, the return stroke's base line,
#: piston forces, mass forces, lines and hatched free forces.
REVOLUTION_PLATE = (r"rbase", r"rF\d+", r"rK\d+|rKs[12]", r"rM\d+", r"rforce[abc]", r"rmass", r"rfree\.[abc]",
                    r"axis", r"D[01]", r"(ind|crk)\.(steam|backline)", r"(ind|crk)\.[ER]r?\d+", r"ind\.Z[01]")


#: What a figure drawn from cards adds: each card's points and its two strokes' straightedge lines.
CARD_PLATE = (r"(card|crank)\.C\d+", r"(card|crank)\.(fwd|back|loop)", r"axis", r"D[01]")
