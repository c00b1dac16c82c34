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


def sense_of(fig: Figure) -> float:
    """+1 when the figure's rods drive the shaft, −1 when its shaft drives pumps (the given ``sense``)."""
    return float(fig.replay.givens.get("sense", 1.0))


def speeds(fig: Figure, *, infinite: bool | None = None, crosshead_share: float = 0.0) -> list[dict[str, float]]:
    """v/v1 at each crank position from the constructed excess work, with the book's simplifications and without.

    With s = +1 when the rods drive the shaft and −1 when it drives pumps (the masses then take up −e):

    * ``v_book``  = 1 + s·k·e: § 146's "für große Massen" (linear in e);
    * ``v_exact`` = sqrt(1 + 2s·k·e): (m1 + m2)(v² − v1²)/2 = s·Q·r·e, the book's energy balance;
    * ``v_first`` keeps the crossheads' term the book derives and then drops (seed 002: "Bei der Kleinheit von
      m2 gegen m1 und von r gegen l kann man das letzte Glied ... vernachlässigen"), to the first order in r/l
      as the book writes it: L2 + L3 = m2(sin²α ∓ (r/l) sin α sin 2α + cos²α ± (r/l) cos α sin 2α)v²/2 − m2v1²/2,
      i.e. S1(α) = 1 + (r/l) sin 2θ (sin θ − cos θ) with θ the first crank's angle from the head-end dead
      centre, and v²(m1 + m2·S1(α)) = v1²(m1 + m2·S1(0)) + 2s·Q·r·e;
    * ``v_full``  the same with the exact piston law: S = (c1/v)² + (c2/v)².

    *crosshead_share* is m2/(m1 + m2); with 0, or for the infinite rod (S = 1), v_first = v_full = v_exact.
    k = Qr/((m1 + m2)v1²) is the figure's ``fluctuation``.
    """
    k = fig.replay.givens["fluctuation"]
    sense = sense_of(fig)
    mu = float(crosshead_share)
    if not 0.0 <= mu < 1.0:
        raise InvalidParameter(f"crosshead share m2/(m1 + m2) must be in [0, 1), got {crosshead_share!r}")
    n = fig.params["parts"]
    t = _prefix(fig, infinite)
    ratio = None if (t == "i" or fig.params["infinite_rod"]) else fig.replay.givens["rod_ratio"]

    def S(a: float) -> float:
        return piston_speed_factor(a, ratio) ** 2 + piston_speed_factor(a + 0.5 * math.pi, ratio) ** 2

    def S1(a: float) -> float:
        return 1.0 if ratio is None else 1.0 + math.sin(2.0 * a) * (math.sin(a) - math.cos(a)) / ratio

    def root(v: float) -> float:
        return math.sqrt(v) if v >= 0.0 else math.nan

    out = []
    a0 = start_angle(dead_centre_of(fig))
    for j in range(2 * n + 1):
        e = work_excess(fig, j, infinite=infinite)
        a = a0 + math.pi * j / n
        first = ((1.0 - mu) + mu * S1(a0) + 2.0 * sense * k * e) / ((1.0 - mu) + mu * S1(a))
        full = ((1.0 - mu) + mu * S(a0) + 2.0 * sense * k * e) / ((1.0 - mu) + mu * S(a))
        out.append({"index": j, "crank_angle_deg": 180.0 * j / n, "work_excess": e, "v_book": 1.0 + sense * k * e,
                    "v_exact": root(1.0 + 2.0 * sense * k * e), "v_first": root(first), "v_full": root(full)})
    return out


# -- checks ----------------------------------------------------------------------------
