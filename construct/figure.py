"""A figure: a construction's protocol, the objects a replay of it made, and how to check it.

It is what :meth:`Builder.figure` and every registered construction return.
It sits above the kernel and the drawing layer (:mod:`construct.render`, loaded
when a drawing is asked for, as shapely loads matplotlib only inside its
plotting functions) and below the book constructions: a construction hands
its figures the function that checks them, so nothing here looks the
constructions up.

:class:`Builder` is the kernel's :class:`~construct.kernel.instruments.Builder`
with the one method that needs this layer, :meth:`Builder.figure`.

>>> b = Builder("demo", givens={})
>>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 2.0, 0.0)
>>> _ = b.midpoint("M", "A", "B")
>>> fig = b.figure()
>>> fig.replay["M"], fig.svg().startswith("<?xml"), fig.checks()
(Point(1.0, 0.0), True, [])
"""

from __future__ import annotations

import numbers
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping, Sequence

from .kernel import instruments
from .kernel.geometry import Point
from .kernel.errors import InvalidParameter, did_you_mean
from .kernel.protocol import Protocol, Replay
from .render.notation import Described

__all__ = ["Figure", "Builder"]


@dataclass(frozen=True)
class Figure:
    """A construction built (or replayed): its protocol, the objects it made, and its checks (if a book's)."""

    protocol: Protocol
    replay: Replay
    #: Compares the figure's constructed quantities with the analytic formulas; set by the book construction
    #: that built or replayed the figure (:meth:`construct.constructions.Construction.check`), None otherwise.
    checker: Callable[["Figure"], list] | None = field(default=None, compare=False, repr=False)
    #: The book construction that built or replayed the figure (:class:`construct.constructions.Construction`):
    #: its citation and wording caption the figure, its domain bounds the givens.  None for a figure of your own.
    construction: Described | None = field(default=None, compare=False, repr=False)

    @property
    def params(self) -> Mapping[str, Any]:
        return self.protocol.params

    def __repr__(self) -> str:
        return f"<Figure {self.protocol.construction!r}: {len(self.protocol.steps)} steps>"

    def svg(self, style: str = "plain", *, upto: int | None = None) -> str:
        """The figure (all steps, or steps 1..upto) as SVG text in a named style (plain, historical, teaching)."""
        from .render.notebook import figure_svg  # the rendering layer, loaded when a drawing is asked for
        from .render.styles import STYLES

        if not isinstance(style, str) or style not in STYLES:
            raise InvalidParameter(f"unknown style {style!r}{did_you_mean(style, STYLES)}; choose one of {', '.join(sorted(STYLES))}")
        if upto is not None and (isinstance(upto, bool) or not isinstance(upto, numbers.Integral)):
            raise InvalidParameter(f"upto is a step number, got {upto!r}")
        return figure_svg(self, style=style, upto=upto)

    def pdf(self, path: Any = None, *, style: str = "historical", width_mm: float = 120.0, letter_pt: float = 7.0,
            caption: str = "none", outline: bool = False) -> bytes:
        """The figure's plate as a PDF at its final size; written to *path* (whole or not at all) when given.

        The page is *width_mm* wide, the letters *letter_pt* points high (placed for that size), every
        line in the style's weights in points, the fonts embedded (*outline*: drawn as outlines), the
        caption beneath it *none*, *de* or *en* (:mod:`construct.render.pdf`).  Needs cairosvg.

        >>> pdf = Builder("demo", givens={}).figure().pdf(width_mm=80)
        >>> pdf[:5]
        b'%PDF-'
        """
        from .render.pdf import pdf_bytes

        data = pdf_bytes(self._plate(style, width_mm, letter_pt, caption, outline=outline))
        if path is not None:
            from .io.staging import write_bytes

            write_bytes(path, data)
        return data

    def tikz(self, path: Any = None, *, style: str = "historical", width_mm: float = 120.0, letter_pt: float = 7.0,
             caption: str = "none", standalone: bool = False, tikz_style: str = "tikz") -> str:
        """The figure's plate as a TikZ picture to ``\\input`` (or, *standalone*, a whole LaTeX document);
        written to *path* when given (:mod:`construct.render.tikz`).

        Every lettered point is a named coordinate, every letter TeX text placed beside its point.

        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("A", 0.0, 0.0, label="A"); _ = b.given_point("B", 2.0, 0.0, label="B")
        >>> "\\\\coordinate (A) at (0,0);" in b.figure().tikz()
        True
        """
        from .render.tikz import tikz_document, tikz_picture

        if not isinstance(standalone, bool):
            raise InvalidParameter(f"standalone is True or False, got {standalone!r}")
        plate = self._plate(style, width_mm, letter_pt, caption, tikz_style=tikz_style)
        text = tikz_document(plate) if standalone else tikz_picture(plate)
        if path is not None:
            from .io.staging import write_bytes

            write_bytes(path, text.encode("utf-8"))
        return text

    def _plate(self, style: str, width_mm: float, letter_pt: float, caption: str, **how: Any) -> Any:
        """The figure laid out on a sheet (:func:`construct.render.output.print_plate`), with the plate of the book
        construction that built it (the owner of its checker), if one did."""
        from .render.output import print_plate
        from .render.page import Sheet

        sheet = Sheet(width_mm=width_mm, letter_pt=letter_pt, caption=caption, **how)
        return print_plate(self, construction=getattr(self.checker, "__self__", None), style=style, sheet=sheet)

    def checks(self) -> list:
        """The construction's checks, when a book construction built or replayed the figure; else none.

        Each check compares a quantity measured on the figure with its analytic value.
        """
        return [] if self.checker is None else self.checker(self)

    def plot(self, ax: Any = None, *, style: str = "plain", upto: int | None = None) -> Any:
        """Draw the figure (all steps, or steps 1..upto) on a matplotlib Axes (a new one when None); return it.

        matplotlib is imported only here, and no backend or global style is set (as ``shapely.plotting``).

        >>> ax = Builder("demo", givens={}).figure().plot()
        >>> ax.get_aspect()
        1.0
        """
        from .render.plotting import plot_figure

        if upto is not None and (isinstance(upto, bool) or not isinstance(upto, numbers.Integral)):
            raise InvalidParameter(f"upto is a step number, got {upto!r}")
        return plot_figure(self, ax, style=style, upto=upto)

    def with_givens(self, **givens: Any) -> "Figure":
        """The same steps replayed with other givens (arrays make a sweep); a book construction's figure keeps
        to the construction's domain.

        >>> import construct
        >>> fig = construct.get("crank").figure(parts=6)
        >>> again = fig.with_givens(rod_ratio=4.0)
        >>> again.replay.givens["rod_ratio"], again.protocol is fig.protocol
        (4.0, True)
        >>> fig.with_givens(rod_ratio=0.5)
        Traceback (most recent call last):
        ...
        construct.kernel.errors.InvalidParameter: rod ratio L/r must be greater than 1 (the rod must be longer than the crank), got 0.5
        """
        values = dict(self.replay.givens)
        values.update(givens)
        if self.construction is not None:
            self.construction.validate(values)
        return Figure(self.protocol, self.protocol.replay(values), self.checker, self.construction)

    def write(self, out_dir: Any, *, style: str = "plain", frames: str = "auto") -> dict:
        """Write the figure's outputs into *out_dir* (made or replaced whole, never half-written): the layered
        final.svg, protocol.json, the animation, the player, the storyboard and *frames* (auto, all, groups,
        none: standalone frames).  Returns what was written (counts, the folder)."""
        from .render.output import write_replay  # the rendering layer, loaded when a drawing is asked for

        return write_replay(self.construction, self, out_dir, style=style, frames=frames)

    def _repr_svg_(self) -> str:
        """Inline display in Jupyter: the final figure in the teaching style."""
        from .render.notebook import figure_repr_svg

        return figure_repr_svg(self)


class Builder(instruments.Builder):
    __doc__ = instruments.Builder.__doc__ + """
    This builder (``construct.Builder``) letters a result point by its own name unless told otherwise: a point
    made with ``role="result"`` and no letter in *labels* is lettered with its name (``labels={"B": ""}`` leaves
    it unlettered).
    """

    def record(self, tool: str, op: str, inputs: Sequence[str], outputs: Sequence[str],
               params: Mapping[str, Any], de: str, en: str, *, provenance: Any = None,
               role: str = "construction", labels: Mapping[str, str] | None = None) -> tuple[Any, ...]:
        """As :meth:`construct.kernel.instruments.Builder.record`; a result point without a letter gets its name.

        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("C", 2.0, 0.0)
        >>> _ = b.circle_through("ka", "A", "C"); _ = b.circle_through("kc", "C", "A")
        >>> _ = b.intersect("B", "ka", "kc", rule=("left", "A", "C"), role="result")
        >>> _ = b.intersect("D", "ka", "kc", rule=("right", "A", "C"), role="result", labels={"D": ""})
        >>> b.steps[-2].labels, b.steps[-1].labels
        ((('B', 'B'),), (('D', ''),))
        """
        given = dict(labels or {})
        if role == "result":
            named = [n for n in outputs if isinstance(n, str) and n not in given]
        else:
            named = []
        made = super().record(tool, op, inputs, outputs, params, de, en, provenance=provenance, role=role,
                              labels=given or None)
        for name in named:
            if isinstance(self.objects.get(name), Point):
                self.set_label(name, name)
        return made

    def figure(self, *, checks: Callable[[Figure], list] | None = None) -> Figure:
        """The construction as a :class:`Figure`: protocol and objects, ready to draw.

        *checks*, a function of the figure returning :class:`~construct.constructions.checking.Check` values,
        becomes the figure's :meth:`Figure.checks` (and follows it through :meth:`Figure.with_givens`).

        >>> b = Builder("demo", givens={})
        >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 2.0, 0.0)
        >>> _ = b.midpoint("M", "A", "B")
        >>> b.figure().replay["M"]
        Point(1.0, 0.0)
        """
        if checks is not None and not callable(checks):
            raise InvalidParameter(f"checks is a function of the figure returning its checks, got {checks!r}")
        proto = self.protocol()
        return Figure(proto, Replay(proto, dict(self.objects), self.givens), checks)
