"""Reading the tangential-pressure figure: OK/r, T and P' at every crank position, the unrolled angles, the
mean height, the crossings α1, α2 and the excess area."""

from __future__ import annotations

import math

from .. import Figure

__all__ = ["ok_over_r", "t_over_unit", "free_force", "return_free_force", "unrolled_angle", "mean_height",
           "crossing_angles", "excess_area"]


def _up(fig: Figure, point: str, origin: str) -> float:
    """Signed height of *point* over *origin*, perpendicular to the stroke line (up positive)."""
    p, o = fig.replay[point], fig.replay[origin]
    return p[1] - o[1]


def ok_over_r(fig: Figure, k: int) -> float:
    """OK/r at crank position k, measured on the figure (0 at the dead centres)."""
    n = fig.params["parts"]
    if k in (0, n):
        return 0.0
    return _up(fig, f"K{k}", "O") / fig.replay.givens["r"]


def t_over_unit(fig: Figure, k: int) -> float:
    """The ordinate of T at k on the unrolled circle, over the force unit (r for a unit force, else 1 at)."""
    n = fig.params["parts"]
    g = fig.replay.givens
    unit = g["r"] if fig.params["force"] == "unit" else g["pressure_unit"]
    if k in (0, n):
        return 0.0
    return _up(fig, f"T{k}", f"U{k}") / unit


def free_force(fig: Figure, k: int, prefix: str = "") -> float:
    """P' at k in at (Baumann force), measured as the height of M_k over B (*prefix* ``lp.``: the low-pressure
    cylinder's, times F_lp/F_hp)."""
    return _up(fig, f"{prefix}M{k}", "D1") / fig.replay.givens["pressure_unit"]


def return_free_force(fig: Figure, k: int, prefix: str = "") -> float:
    """P' on the return stroke at the mirrored crank point of k, in at: the height of M′_k over B (*prefix*
    ``lp.``: the low-pressure cylinder's, times F_lp/F_hp)."""
    return _up(fig, f"{prefix}rM{k}", "D1") / fig.replay.givens["pressure_unit"]


def unrolled_angle(fig: Figure, point: str) -> float:
    """The crank angle of a point of the unrolled circle, read in proportion to the drawn length U0..Un."""
    n = fig.params["parts"]
    u0, un, p = fig.replay["U0"], fig.replay[f"U{n}"], fig.replay[point]
    return math.pi * (p[0] - u0[0]) / (un[0] - u0[0])


def mean_height(fig: Figure) -> float:
    """Height of the mean line over the base, in force units."""
    g = fig.replay.givens
    unit = g["r"] if fig.params["force"] == "unit" else g["pressure_unit"]
    return _up(fig, "M0", "U0") / unit


def crossing_angles(fig: Figure) -> tuple[float, float]:
    return unrolled_angle(fig, "A1"), unrolled_angle(fig, "A2")


def excess_area(fig: Figure) -> float:
    """The excess area as drawn, in force units times r (i.e. ∫(T − T_m) dα over (α1, α2) as drawn)."""
    g = fig.replay.givens
    unit = g["r"] if fig.params["force"] == "unit" else g["pressure_unit"]
    return fig.replay["excess"].signed_area() / (unit * g["r"])
