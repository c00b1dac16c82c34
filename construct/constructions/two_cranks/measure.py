"""Reading a built two-cranks figure: crank angles, the excess work and the speed radius at each position, the speeds."""

from __future__ import annotations

import math

from ...kernel.errors import InvalidParameter
from .. import Figure
from .analytic import piston_speed_factor, start_angle
from .build import angle_at

def crank_angle(fig: Figure, point: str, centre: str | None = None, d0: str | None = None) -> float:
    """The angle of a crank point from its circle's head-end dead centre, 0..2pi in the sense of rotation."""
    if centre is None:
        centre, d0 = ("O'", "iD0") if point.startswith("i") or (point.startswith("K.") and "O'" in fig.replay) \
            else ("O", "D0")
    return angle_at(fig.replay[centre], fig.replay[d0], fig.replay[point])


def _prefix(fig: Figure, infinite: bool | None) -> str:
    """Object prefix of a diagram: None is the one about O (the figure's own rod), True the infinite rod."""
    if infinite is None:
        return ""
    if infinite and not fig.params["infinite_rod"]:
        return "i"
    if not infinite and fig.params["infinite_rod"]:
        raise InvalidParameter("this figure has the infinite rod only")
    return ""


def work_excess(fig: Figure, j: int, *, infinite: bool | None = None) -> float:
    """e at crank position j in units of Q·r, read off the work line: (M_j E_j − M_0 W_0) / r."""
    t = _prefix(fig, infinite)
    rp = fig.replay
    m0, w0, mj, ej = rp[f"{t}M0"], rp[f"{t}W0"], rp[f"{t}M{j}"], rp[f"{t}E{j}"] if j else rp[f"{t}W0"]
    return ((ej[0] - mj[0]) - (w0[0] - m0[0])) / fig.replay.givens["r"]


def speed_radius(fig: Figure, j: int, *, infinite: bool | None = None) -> float:
    """The drawn radius of speed point j over the crank radius: v/v1 by the book's law, deviation magnified G times."""
    t = _prefix(fig, infinite)
    centre = "O'" if t == "i" else "O"
    return fig.replay[centre].distance(fig.replay[f"{t}Z{j % (2 * fig.params['parts'])}"]) / fig.replay.givens["r"]


def dead_centre_of(fig: Figure) -> str:
    """The dead centre the figure's first crank starts from (a protocol from before the option: the head end)."""
    return str(fig.params.get("dead_centre", "head-end"))


def speeds(fig: Figure, *, infinite: bool | None = None, crosshead_share: float = 0.0) -> list[dict[str, float]]:
    """v/v1 at each crank position from the constructed excess work, with the book's simplifications and without.

    * ``v_book``  = 1 + k·e: § 146's "für große Massen" (linear in e);
    * ``v_exact`` = sqrt(1 + 2k·e): (m1 + m2)(v² − v1²)/2 = Q·r·e, the book's energy balance;
    * ``v_full``  drops the book's other simplification too (§ 146: "Bei der Kleinheit von m2 gegen m1
      und von r gegen l ..."): each crosshead (mass m2) moves at c = v·c/v(α), so
      v²(m1 + m2·S(α)) = v1²(m1 + m2·S(0)) + 2Q·r·e with S = (c1/v)² + (c2/v)², exact piston law.
      *crosshead_share* is m2/(m1 + m2); with 0, or for the infinite rod (S = 1), v_full = v_exact.

    k = Qr/((m1 + m2)v1²) is the figure's ``fluctuation``.
    """
    k = fig.replay.givens["fluctuation"]
    mu = float(crosshead_share)
    if not 0.0 <= mu < 1.0:
        raise InvalidParameter(f"crosshead share m2/(m1 + m2) must be in [0, 1), got {crosshead_share!r}")
    n = fig.params["parts"]
    t = _prefix(fig, infinite)
    ratio = None if (t == "i" or fig.params["infinite_rod"]) else fig.replay.givens["rod_ratio"]

    def S(a: float) -> float:
        return piston_speed_factor(a, ratio) ** 2 + piston_speed_factor(a + 0.5 * math.pi, ratio) ** 2

    out = []
    a0 = start_angle(dead_centre_of(fig))
    for j in range(2 * n + 1):
        e = work_excess(fig, j, infinite=infinite)
        a = a0 + math.pi * j / n
        full = ((1.0 - mu) + mu * S(a0) + 2.0 * k * e) / ((1.0 - mu) + mu * S(a))
        out.append({"index": j, "crank_angle_deg": 180.0 * j / n, "work_excess": e, "v_book": 1.0 + k * e,
                    "v_exact": math.sqrt(1.0 + 2.0 * k * e) if 1.0 + 2.0 * k * e >= 0.0 else math.nan,
                    "v_full": math.sqrt(full) if full >= 0.0 else math.nan})
    return out


# -- checks ----------------------------------------------------------------------------
