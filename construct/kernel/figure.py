"""A figure: a construction's protocol and the objects a replay of it made.

It is what :meth:`Builder.figure <construct.kernel.instruments.Builder.figure>`
and every registered construction return.  Drawing and checking belong to
the layers above the kernel (:mod:`construct.render`,
:mod:`construct.constructions`); the methods here load them when asked, as
shapely loads matplotlib only inside its plotting functions, so the kernel
itself imports nothing outside itself.
"""

from __future__ import annotations

import numbers
from dataclasses import dataclass
from typing import Any, Mapping

from .errors import InvalidParameter

from .protocol import Protocol, Replay

__all__ = ["Figure"]


@dataclass(frozen=True)
class Figure:
    """A construction built (or replayed): its protocol and the objects it made."""

    protocol: Protocol
    replay: Replay

    @property
    def params(self) -> Mapping[str, Any]:
        return self.protocol.params

    def __repr__(self) -> str:
        return f"<Figure {self.protocol.construction!r}: {len(self.protocol.steps)} steps>"

    def svg(self, style: str = "plain", *, upto: int | None = None) -> str:
        """The figure (all steps, or steps 1..upto) as SVG text in a named style (plain, historical, teaching)."""
        from ..render.notebook import figure_svg  # the rendering layer, loaded when a drawing is asked for
        from ..render.styles import STYLES

        if not isinstance(style, str) or style not in STYLES:
            raise InvalidParameter(f"unknown style {style!r}; choose one of {', '.join(sorted(STYLES))}")
        if upto is not None and (isinstance(upto, bool) or not isinstance(upto, numbers.Integral)):
            raise InvalidParameter(f"upto is a step number, got {upto!r}")
        return figure_svg(self, style=style, upto=upto)

    def checks(self) -> list:
        """The construction's checks, when it is a registered book construction; else none.

        Each check compares a quantity measured on the figure with its analytic value.
        """
        from ..checks import run_checks
        from ..constructions import _validate_givens, find  # the book constructions sit above the kernel

        c = find(self.protocol.construction)
        if c is None:
            return []
        # A figure replayed from a protocol by hand has not met the construction's own check of its givens
        # (a rod no longer than the crank, say): the checks' formulas assume it.
        _validate_givens(c.name, self.replay.givens)
        return run_checks(c, self)

    def with_givens(self, **givens: Any) -> "Figure":
        """The same steps replayed with other givens (arrays make a sweep)."""
        values = dict(self.replay.givens)
        values.update(givens)
        return Figure(self.protocol, self.protocol.replay(values))

    def _repr_svg_(self) -> str:
        """Inline display in Jupyter: the final figure in the teaching style."""
        from ..render.notebook import figure_repr_svg

        return figure_repr_svg(self)
