"""The tangential-pressure plate (Fig. 26/27): what it shows, its looks and lettering."""

from __future__ import annotations

import math
import re

from .. import Figure
from ...kernel.identity import by_identity
from ..scales import scale_furniture

__all__ = ["PLATE", "tangential_plate"]


#: What the Fig. 26/27-like plate shows: the unrolled base, the ordinates and points of T, the curve,
#: the mean line, the crossings and the hatched excess area.
PLATE = (r"tbase", r"U\d+", r"u\d+", r"T\d+", r"tcurve", r"M0|Mn", r"mean", r"A1|A2", r"excess")
#: The points whose heights the scale spans: the ordinates' ends T, a revolution's sum S and its cylinders' c.
_HEIGHTS = re.compile(r"[TS]\d+|c\d+\.\d+")


def tangential_plate(fig: Figure) -> dict:
    """Baumann's Fig. 26 as a plate: the diagram ABCD heavy (A the start, B the top at the cut-off,
    D the end), the Ausgleichende MM lettered at both ends, and α₁, α₂ as he gives them -- abscissae,
    lettered at the foot of thin ordinates below the base line, so that no letter sits on the crossings
    or on the ends of the hatching.

    Every position is a constructed point.
    """
    R = fig.replay
    n = fig.params["parts"]
    if fig.params.get("revolution"):  # a revolution's diagrams are lettered by their own steps (each crank, the sum)
        # the work the flywheel takes up (over the mean line) hatched across the work it gives back (under it)
        return {"looks": {"excess": "signed"}, "furniture": _cylinder_letters(fig) + _scale(fig, 2 * n)}
    U0, Un, M0, Mn = R["U0"], R[f"U{n}"], R["M0"], R["Mn"]
    span = abs(Un[0] - U0[0])
    d = 0.018 * span
    top = max(range(1, n), key=lambda k: R[f"T{k}"][1])
    T = R[f"T{top}"]
    furniture: list[dict] = [
        {"kind": "lettering", "at": (U0[0] - 0.9 * d, U0[1] + 1.2 * d), "text": "A"},
        {"kind": "lettering", "at": (T[0], T[1] + 1.6 * d), "text": "B"},
        {"kind": "lettering", "at": (Un[0] + 0.9 * d, Un[1] + 1.4 * d), "text": "D"},
        {"kind": "lettering", "at": (M0[0] - 1.2 * d, M0[1] + 1.0 * d), "text": "M"},
        {"kind": "lettering", "at": (Mn[0] + 1.2 * d, Mn[1] + 1.0 * d), "text": "M"},
    ]
    for name, text in (("A1", "α₁"), ("A2", "α₂")):
        P = R[name]
        furniture.append({"kind": "stroke", "a": (P[0], P[1]), "b": (P[0], U0[1] - 1.0 * d), "look": "dashed thin"})
        furniture.append({"kind": "lettering", "at": (P[0], U0[1] - 2.2 * d), "text": text})
    looks = {"A1": "unlettered", "A2": "unlettered", "tcurve": "heavy", "mean": "medium", "tbase": "medium"}
    return {"looks": looks, "furniture": furniture + _scale(fig, n)}


def _scale(fig: Figure, m: int) -> list[dict]:
    """The tangential pressure's scale in at beside the diagram, from its base line (none for a unit force P′ = r,
    whose ordinates are lengths, not pressures)."""
    if fig.params.get("force") == "unit":
        return []
    R = fig.replay
    U0, Um = R["U0"], R[f"U{m}"]
    span = abs(Um[0] - U0[0])
    unit = R.givens["pressure_unit"]
    heights = [(R[k][1] - U0[1]) / unit for k in height_names(R)]
    step = 2.0 if max(heights) - min(heights) > 6 else 1.0
    lo, hi = math.floor(min(0.0, min(heights)) / step), math.floor(max(heights) / step + 1e-9)
    return scale_furniture(x=U0[0] - 0.06 * span, zero=U0[1], unit=unit, values=[i * step for i in range(lo, hi + 1)],
                           tick=0.008 * span, text="at")


#: The names whose heights the scale spans, by the protocol that makes them: {id: (protocol, names)} (at most
#: _NAMED protocols kept, each with its entry so that its id is not another's).
_named: dict[int, tuple[object, tuple[str, ...]]] = {}  # (kernel.identity.by_identity)
_NAMED = 16


def height_names(replay) -> list[str]:
    """The names of the points of *replay* whose heights the scale spans (:data:`_HEIGHTS`), in the protocol's order.

    A player asks at every value of a sweep, whose names are its protocol's: the protocol's thousands of names are
    scanned once, and a replay of part of the steps keeps those it has.
    """
    names = by_identity(_named, replay.protocol, lambda protocol: tuple(
        k for k in protocol.program.names if k[:1] in "TSc" and _HEIGHTS.fullmatch(k)), most=_NAMED)
    return [k for k in names if k in replay]


def _cylinder_letters(fig: Figure) -> list[dict]:
    """HD and ND at a compound's (or tandem's) two cylinder curves, each where it stands clearest of the others."""
    if not fig.params.get("low_pressure"):
        return []
    R = fig.replay
    n = fig.params["parts"]
    m = 2 * n
    d = 0.018 * abs(R[f"U{m}"][0] - R["U0"][0])
    out = []
    for i, text in ((0, "HD"), (1, "ND")):
        best, spot = -1.0, None
        for j in range(2, m - 1):
            if f"c{i}.{j}" not in R or f"S{j}" not in R:
                continue
            x, y = R[f"c{i}.{j}"]
            others = [R[f"S{j}"][1], R[f"U{j}"][1], R["M0"][1]] + [R[f"c{o}.{j}"][1] for o in (0, 1)
                                                                    if o != i and f"c{o}.{j}" in R]
            clear = min(abs(y - v) for v in others)
            if clear > best:
                best, spot = clear, (x, y)
        if spot is not None:
            # set off below the curve, half way to the next line, tied to it by a leader
            drop = min(2.6 * d, best / 2)
            out.append({"kind": "lettering", "at": (spot[0] + 1.2 * d, spot[1] - drop), "text": text, "to": spot})
    return out
