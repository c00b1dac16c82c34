"""The named styles a replay can be drawn in."""

from __future__ import annotations

from .svg import PLAIN, Style

__all__ = ["STYLES"]

STYLES: dict[str, Style] = {"plain": PLAIN}
