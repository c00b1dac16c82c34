"""q at tenths of the stroke (seed 000, Tabelle 2): the rod swung back to the crank circle, q constructed there.

Tabelle 2 of Anhang II gives the crank angle and the inertia pressure q at
each tenth of the stroke.  The construction divides the stroke by the
intercept theorem, swings the rod length back onto the crank circle from
each mark (as ``crank-angle`` does) and constructs q = (F/f)(cos ω + λ cos 2ω)
at the crank point found, with the same proportional angle as the inertia
curve.
"""

from __future__ import annotations


from .. import analytic
from ..checking import Check
from ...kernel.errors import InvalidParameter
from ...kernel.instruments import Builder
from .. import Figure
from ..crank import build_frame, inverse_tolerance
from .build import _dir, _givens, _setup, _value
from .measure import _offset

__all__ = ["build_q_at_stroke_fractions", "stroke_fraction_checks", "PLATE"]

#: What the plate shows: the stroke in tenths, the rod swung back to the crank circle, the crank
#: positions, and the proportional angle's rays carrying each q to the F/f line.
PLATE = (r"axis", r"crank", r"D[01]", r"O", r"vert", r"x\d+", r"rod\d+", r"W\d+", r"S", r"gf", r"gf\.U", r"Vt\d+",
         r"Vt\d+\.s")


def build_q_at_stroke_fractions(*, rod_ratio: float, divisions: int, r: float = 1.0, pressure_ratio: float = 1.0,
                                pressure_unit: float = 1.0) -> Figure:
    """Tabelle 2: the stroke in equal parts, the rod swung back to the crank circle, q constructed there.

    >>> fig = build_q_at_stroke_fractions(rod_ratio=5.0, divisions=10)
    >>> round(_offset(fig, "Vt0", "gf.U") / fig.replay.givens["pressure_unit"], 12)   # q1 = 1 + r/L
    1.2
    """
    givens = _givens(r, rod_ratio, pressure_ratio, pressure_unit)
    if isinstance(divisions, bool) or not isinstance(divisions, int) or not 1 <= divisions <= 1000:
        raise InvalidParameter(f"number of stroke divisions must be a whole number from 1 to 1000, got {divisions!r}")
    b = Builder("inertia-stroke-fractions", givens, {"divisions": divisions, "plate": PLATE})
    f = build_frame(b)
    c = _setup(b, f)
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
            dc_p = c.D0 if b[P][0] * _dir(b, c) < b[c.O][0] * _dir(b, c) else c.D1
            _value(b, c, f"t{j}", P, kind, dc_p, None)
            b.set_label(f"Vt{j}", f"q{j}")
    proto = b.protocol()
    return Figure(proto, proto.replay(givens))


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
        q = _offset(fig, f"Vt{j}", "gf.U") / u
        # the crank point is found where an arc meets the crank circle nearly tangentially near the dead centres:
        # its angle error (crank-angle's tolerance) times |dq/dw| <= F/f (1 + 2 lam), plus the float chain
        tol = 1e-11 * Ff + inverse_tolerance(x) * Ff * (1.0 + 2.0 * lam)
        checks.append(Check(f"q at {j}/{m} of the stroke", q, analytic.inertia_two_term(w, lam, Ff), tol,
                            "Euclidean; the rod arc meets the crank circle nearly tangentially at the dead centres",
                            "F/f"))
    return checks
