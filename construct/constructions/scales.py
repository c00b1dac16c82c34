"""A diagram's scale as its plate draws it: a vertical line, a tick and a figure at every marked value, the unit
above (plain furniture data, :mod:`construct.render.plate`).

The indicator diagram (at), the piston force (kg), the four-stroke pressures (at) and the tangential
pressure (at) carry one beside their diagram, as the books' plates do.

>>> items = scale_furniture(x=-0.1, zero=0.0, unit=0.5, values=(0, 1, 2), tick=0.02, text="at")
>>> [it["kind"] for it in items].count("stroke"), [it["text"] for it in items if it["kind"] == "lettering"]
(4, ['0', '1', '2', 'at'])
"""

from __future__ import annotations

from typing import Sequence

__all__ = ["scale_furniture"]


def _figure(v: float) -> str:
    """A scale's figure as printed: a whole number without a point, the minus a minus sign."""
    text = f"{v:g}" if abs(v - round(v)) > 1e-9 else str(int(round(v)))
    return text.replace("-", "−").replace(".", ",")


def scale_furniture(*, x: float, zero: float, unit: float, values: Sequence[float], tick: float, text: str,
                    size: float = 0.8, text_size: float = 0.85, gap: float = 2.6,
                    text_at: tuple[float, float] | None = None) -> list[dict]:
    """The furniture of a vertical scale at abscissa *x*: value v stands at height ``zero + v·unit`` (drawing
    units), a tick of length *tick* to the left of the line and the figure *gap* ticks left of the line; the unit
    *text* above the top (or at *text_at*).  The figures are *size*, the unit *text_size* of the letters."""
    lo, hi = min(values), max(values)
    out: list[dict] = [{"kind": "stroke", "a": (x, zero + lo * unit), "b": (x, zero + hi * unit), "look": "medium"}]
    for v in values:
        y = zero + v * unit
        out.append({"kind": "stroke", "a": (x - tick, y), "b": (x, y), "look": "medium"})
        out.append({"kind": "lettering", "at": (x - gap * tick, y), "text": _figure(v), "anchor": "end", "size": size})
    step = (hi - lo) / max(len(values) - 1, 1)
    out.append({"kind": "lettering", "at": text_at or (x, zero + (hi + 0.7 * step) * unit), "text": text,
                "size": text_size})
    return out
