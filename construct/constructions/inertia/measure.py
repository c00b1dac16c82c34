"""Reading the inertia figure: ordinates and abscissae in the frame of the stroke line, and the drawn curves' error."""

from __future__ import annotations


import numpy as np

from ...kernel.curve_ops import frame_of
from ...kernel.geometry import Point
from .. import Figure, analytic

__all__ = ["ordinate", "abscissa", "curve_deviation"]


def _axis_frame(fig: Figure) -> tuple[Point, float, float, float, float]:
    o = fig.replay["D0"]
    ux, uy, nx, ny = frame_of(fig.replay["axis"])
    return o, ux, uy, nx, ny


def ordinate(fig: Figure, name: str) -> float:
    """Signed distance of a point from the stroke line (up = positive), measured on the figure."""
    o, ux, uy, nx, ny = _axis_frame(fig)
    p = fig.replay[name]
    return (p[0] - o[0]) * nx + (p[1] - o[1]) * ny


def abscissa(fig: Figure, name: str) -> float:
    """Distance of a point's foot from the head-end dead centre along the stroke, as a fraction of the stroke."""
    o, ux, uy, nx, ny = _axis_frame(fig)
    p = fig.replay[name]
    return ((p[0] - o[0]) * ux + (p[1] - o[1]) * uy) / o.distance(fig.replay["D1"])


def slope(fig: Figure, line: str) -> float:
    """dy/dx of a drawn line in the frame of the stroke line."""
    _, ux, uy, nx, ny = _axis_frame(fig)
    (px, py), (qx, qy) = fig.replay[line]
    return ((qx - px) * nx + (qy - py) * ny) / ((qx - px) * ux + (qy - py) * uy)


def offset(fig: Figure, point: str, origin: str) -> float:
    """Signed offset of a point on a scale line from its origin, positive towards the head end (like r cos w)."""
    _, ux, uy, _, _ = _axis_frame(fig)
    p, o = fig.replay[point], fig.replay[origin]
    return -((p[0] - o[0]) * ux + (p[1] - o[1]) * uy)


def curve_deviation(fig: Figure, curve: str, per_segment: int = 64) -> float:
    """Largest vertical distance between a drawn curve and the analytic curve, in units of F/f.

    The drawn curve is sampled densely along its own parameter (*per_segment*
    points per Bézier segment, ends included); at each sample's abscissa the
    analytic curve has the ordinate of Gl. (4_1) at the crank angle of
    Gl. (h) for that piston path.  numpy does all samples at once.
    """
    g = fig.replay.givens
    r, L = g["r"], g["rod_ratio"] * g["r"]
    lam = r / L
    Ff = g["pressure_ratio"] * g["pressure_unit"]
    o, ux, uy, nx, ny = _axis_frame(fig)
    t = np.linspace(0.0, 1.0, per_segment + 1)[:, None]
    s = 1.0 - t
    weights = np.hstack([s ** 3, 3.0 * s * s * t, 3.0 * s * t * t, t ** 3])  # Bernstein basis
    segs = np.array([[(p.x, p.y) for p in seg] for seg in fig.replay[curve].segments()])  # (k, 4, 2)
    pts = np.einsum("tj,kjd->ktd", weights, segs).reshape(-1, 2)
    x = (pts[:, 0] - o.x) * ux + (pts[:, 1] - o.y) * uy
    y = (pts[:, 0] - o.x) * nx + (pts[:, 1] - o.y) * ny
    x = np.clip(x, 0.0, 2.0 * r)
    w = analytic.crank_angle_from_path(x, r, L)
    return float(np.max(np.abs(y - analytic.inertia_two_term(w, lam, Ff))) / Ff)
