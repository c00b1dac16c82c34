"""q at tenths of the stroke (seed 000, Tabelle 2): the rod swung back to the crank circle, q constructed there.

Tabelle 2 of Anhang II gives the crank angle and the inertia pressure q at
each tenth of the stroke.  The construction divides the stroke by the
intercept theorem, swings the rod length back onto the crank circle from
each mark (as ``crank-angle`` does) and constructs q = (F/f)(cos ω + λ cos 2ω)
at the crank point found, with the same proportional angle as the inertia
curve.
"""

from __future__ import annotations

from typing import Any, Mapping

import numpy as np

from .. import analytic
from ..checking import Check
from ...kernel.errors import InvalidParameter
from ...kernel.instruments import Builder
from ...kernel.letters import lowered
from .. import Figure, form_rows
from ..crank import build_frame, inverse_tolerance
from ..ordinates import inertia_setup, ordinate_value, stroke_direction
from .build import inertia_givens
from .measure import offset

__all__ = ["build_q_at_stroke_fractions", "stroke_fraction_checks", "stroke_fractions_plate", "PLATE"]

#: What the plate shows of the construction: the stroke in tenths, the rod swung back to the crank
#: circle, the crank positions; the q found at each are drawn as ordinates over the stroke
#: (:func:`stroke_fractions_plate`) -- the proportional angle five crank radii below would leave the
#: sheet empty.
PLATE = (r"axis", r"crank", r"D[01]", r"O", r"x\d+", r"rod\d+", r"W\d+")


def stroke_fractions_plate(fig: Figure) -> dict:
    """Tabelle 2 as a plate: under the crank circle, on a base line of its own, each q as an ordinate at
    its tenth of the stroke (heavy), projected down from the mark (thin, dashed), with its value in at
    and its letter q₀ … q₁₀; a scale of 1 at beside it.

    The ordinates are the constructed ones: each is the distance of the point Vt carried to the F/f line
    from the line's start (gf.U), as the proportional angle gave it.
    """
    from .measure import offset

    R = fig.replay
    m = fig.params["divisions"]
    unit = R.givens["pressure_unit"]
    r = R["O"].distance(R["D1"])
    xs = [R["D0"][0]] + [R[f"x{j}"][0] for j in range(1, m)] + [R["D1"][0]]
    qs = [offset(fig, f"Vt{j}", "gf.U") for j in range(m + 1)]
    y0 = R["O"][1] - 0.45 * r - max(max(qs), 0.0)
    lo, hi = min(xs), max(xs)
    pitch = (hi - lo) / m
    small = pitch > 0.15 * r  # room for a value beside every ordinate
    furniture: list[dict] = [{"kind": "stroke", "a": (lo - 0.12 * r, y0), "b": (hi + 0.12 * r, y0), "look": "medium"}]
    for j, (x, q) in enumerate(zip(xs, qs)):
        furniture.append({"kind": "stroke", "a": (x, R["O"][1]), "b": (x, y0), "look": "dashed thin"})
        furniture.append({"kind": "stroke", "a": (x, y0), "b": (x, y0 + q), "look": "heavy"})
        furniture.append({"kind": "dot", "at": (x, y0 + q)})
        sign = 1.0 if q >= 0 else -1.0
        sub = str(j).translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))
        furniture.append({"kind": "lettering", "at": (x, y0 - sign * 0.09 * r), "text": f"q{sub}", "size": 1.0})
        if small or j % 2 == 0:
            value = f"{abs(q) / unit:.3f}".replace(".", ",")
            furniture.append({"kind": "lettering", "at": (x, y0 + q + sign * 0.08 * r),
                              "text": ("−" if q < 0 else "+") + value, "size": 1.0})
    sx = hi + 0.28 * r
    furniture.append({"kind": "scale", "origin": (sx, y0), "end": (sx, y0 + unit), "text": "1 at"})
    return {"looks": {"crank": "heavy", "axis": "centre"}, "furniture": furniture}


def build_q_at_stroke_fractions(*, rod_ratio: float, divisions: int, r: float = 1.0, pressure_ratio: float = 1.0,
                                pressure_unit: float = 1.0) -> Figure:
    """Tabelle 2: the stroke in equal parts, the rod swung back to the crank circle, q constructed there.

    >>> fig = build_q_at_stroke_fractions(rod_ratio=5.0, divisions=10)
    >>> round(offset(fig, "Vt0", "gf.U") / fig.replay.givens["pressure_unit"], 12)   # q1 = 1 + r/L
    1.2
    """
    givens = inertia_givens(r, rod_ratio, pressure_ratio, pressure_unit)
    if isinstance(divisions, bool) or not isinstance(divisions, int) or not 1 <= divisions <= 1000:
        raise InvalidParameter(f"number of stroke divisions must be a whole number from 1 to 1000, got {divisions!r}")
    b = Builder("inertia-stroke-fractions", givens, {"divisions": divisions, "plate": PLATE})
    f = build_frame(b)
    c = inertia_setup(b, f)
    m = divisions
    with b.group(f"stroke divided into {m} equal parts", f"Hub in {m} gleiche Teile geteilt"):
        marks = [c.D0] + (b.divide_segment("x", c.D0, c.D1, m, line=c.axis) if m > 1 else []) + [c.D1]
    for j, x in enumerate(marks):
        with b.group(f"q at {j}/{m} of the stroke", f"q zu {j}/{m} Hub"):
            if j in (0, m):
                P, kind = (c.D0, "start") if j == 0 else (c.D1, "end")
            else:
                arc = b.circle_radius(f"cross{j}.k", x, c.L, de=f"Bogen um {j}/{m} mit L", en=f"arc about mark {j}/{m} with L")
                C = b.intersect(f"C{j}", arc, c.axis, rule=("toward", c.O, None, -1.0, 0.0), de="Kreuzkopf", en="crosshead")
                back = b.circle_radius(f"rod{j}", C, c.L, de="mit L auf den Kurbelkreis", en="with L onto the crank circle")
                P = b.intersect(f"W{j}", back, c.crank, rule=("left", c.D0, c.D1), de=f"Kurbelstellung W{j}",
                                en=f"crank position W{j}", labels={f"W{j}": str(j)})
                kind = "generic"
            dc_p = c.D0 if b[P][0] * stroke_direction(b, c) < b[c.O][0] * stroke_direction(b, c) else c.D1
            ordinate_value(b, c, f"t{j}", P, kind, dc_p, None, number=str(j))
            b.set_label(f"Vt{j}", lowered(f"q{j}"))
    proto = b.protocol()
    return Figure(proto, b.replay(proto, givens))


def stroke_fractions_form(replay: Any, params: Mapping[str, Any]) -> np.ndarray:
    """The build's choices over a sweep (:attr:`~construct.constructions.Construction.form`): at each inner mark,
    the dead centre the crank point and its doubled-angle point are projected from (the nearer one, as drawn)."""
    d = np.where(replay["D1"][0] > replay["D0"][0], 1.0, -1.0)  # ordinates.stroke_direction
    o = replay["O"][0] * d
    return form_rows(*(replay[f"{p}{j}"][0] * d < o for j in range(1, params["divisions"]) for p in ("W", "Nt")))


def stroke_fraction_checks(fig: Figure) -> list[Check]:
    """q at each mark against Gl. (4₁) at the crank angle of Gl. (h) for that piston path."""
    g = fig.replay.givens
    m = fig.params["divisions"]
    r, L = g["r"], g["rod_ratio"] * g["r"]
    lam = r / L
    u, Ff = g["pressure_unit"], g["pressure_ratio"]
    checks = []
    for j in range(m + 1):
        x = j / m
        w = analytic.crank_angle_from_path(2.0 * r * x, r, L)
        q = offset(fig, f"Vt{j}", "gf.U") / u
        # the crank point is found where an arc meets the crank circle nearly tangentially near the dead centres:
        # its angle error (crank-angle's tolerance) times |dq/dw| <= F/f (1 + 2 lam), plus the float chain
        tol = 1e-11 * Ff + inverse_tolerance(x) * Ff * (1.0 + 2.0 * lam)
        checks.append(Check(f"q at {j}/{m} of the stroke", q, analytic.inertia_two_term(w, lam, Ff), tol,
                            "Euclidean; the rod arc meets the crank circle nearly tangentially at the dead centres",
                            "F/f"))
    return checks
