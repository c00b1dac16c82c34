"""The four-stroke cycle's model: the pressures the constructed diagram is checked against (only the checks use it),
and the tangents of Brauer's rays the construction steps by."""

from __future__ import annotations

from typing import Mapping

__all__ = ["ENGINES", "COMPRESSION_RATIOS", "STROKES", "brauer_tangents", "model_pressure"]

ENGINES = ("explosion", "diesel")
#: Each engine's compression ratio when none is given (explosion engines 4..7, Diesel 12..16).
COMPRESSION_RATIOS = {"explosion": 5.0, "diesel": 14.0}
#: The four strokes in order, from the head-end dead centre (top dead centre) at 0°.
STROKES = ("suction", "compression", "expansion", "exhaust")


# --------------------------------------------------------------------------
# The model (for the checks only).
# --------------------------------------------------------------------------


def brauer_tangents(ratio: float, exponent: float, steps: int) -> tuple[float, float]:
    """tg α and tg β of Brauer's rays for *steps* steps across the volume ratio *ratio*.

    >>> ta, tb = brauer_tangents(5.0, 1.3, 8)
    >>> round((1 + ta) ** 8, 12), round((1 + tb) - (1 + ta) ** 1.3, 15)
    (5.0, 0.0)
    """
    return ratio ** (1.0 / steps) - 1.0, ratio ** (exponent / steps) - 1.0


def model_pressure(stroke: int, x: float, g: Mapping[str, float], engine: str) -> float:
    """Absolute pressure (at) of the idealised cycle on *stroke* (0..3) at piston path x (fraction of the stroke).

    On the expansion stroke beyond the release point x_e (``release``) the pressure falls on the straight
    line from e to the exhaust pressure at the dead centre.

    >>> g = {"suction": 0.9, "exhaust": 1.1, "compression_ratio": 5.0, "clearance": 0.25, "exponent": 1.3,
    ...      "max_pressure": 25.0, "cutoff": 2.0, "release": 1.0}
    >>> round(model_pressure(1, 0.0, g, "explosion"), 6), round(model_pressure(2, 1.0, g, "explosion"), 6)
    (7.292955, 3.085169)
    >>> g["release"] = 0.9
    >>> round(model_pressure(2, 0.9, g, "explosion"), 6), model_pressure(2, 1.0, g, "explosion")
    (3.438388, 1.1)
    """
    vc, n = g["clearance"], g["exponent"]
    if stroke == 0:
        return g["suction"]
    if stroke == 3:
        return g["exhaust"]
    if stroke == 1:
        return g["suction"] * ((1.0 + vc) / (vc + x)) ** n
    xe = g["release"]
    if x > xe:  # released: the straight line e-f
        pe = model_pressure(2, xe, g, engine)
        return pe + (g["exhaust"] - pe) * (x - xe) / (1.0 - xe)
    v = vc + x
    if engine == "explosion":
        return g["max_pressure"] * (vc / v) ** n
    pc = g["suction"] * g["compression_ratio"] ** n
    vd = g["cutoff"] * vc
    return pc if v <= vd else pc * (vd / v) ** n
