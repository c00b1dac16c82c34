"""Captions: the figure's own letters in words (the rules live in :mod:`construct.kernel.letters`) and the
caption lines of frames and figures, wrapped to the canvas.

The kernel writes every step's caption in the figure's letters when a
construction is built (:meth:`construct.kernel.instruments.Builder.protocol`),
so the protocol, the player, the animation and the storyboard read alike;
the renderers import the same names from here.  :class:`Captions` wraps a
scene's captions to a style's canvas once, for every output that shows them.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> sc = build_scene(get("crank").figure(parts=6))
>>> n = len(sc.steps)
>>> step_caption(sc, 0) == (f"Schritt 0 von {n}", f"Step 0 of {n}")
True
>>> caps = Captions(sc, width=912.0, size=13.0)
>>> [kind for kind, _ in caps.frame_lines(2)], caps.line_count() >= 2
(['de', 'en'], True)
"""

from __future__ import annotations

import re
from typing import Mapping, NamedTuple, Protocol, Sequence

from ..kernel.letters import (CAPTION_LIMIT, PLATE_CAPTION_LINES, TITLE_LIMIT, Reader, book_symbols, displayed,
                              equation, subscripts, tag, unbroken)
from .wrapping import wrap as wrap_chars

__all__ = ["Reader", "book_symbols", "equation", "subscripts", "tag", "displayed", "CAPTION_LIMIT", "TITLE_LIMIT",
           "wrap", "step_caption", "group_caption", "Captions", "Captioned", "PlateCaption"]


class Captioned(Protocol):
    """What the captions read of a scene (:class:`construct.render.scene.Scene`)."""

    @property
    def steps(self) -> Sequence: ...
    @property
    def title(self) -> tuple[str, str]: ...
    @property
    def group_captions(self) -> Mapping[tuple[str, ...], str]: ...
    def caption(self, k: int) -> tuple[str, str]: ...


#: The white space other than a space that the wrapper turns into spaces.
_WHITE = re.compile("[\t\n\r\x0b\x0c]")


def wrap(text: str, width_px: float, size: float) -> list[str]:
    """Lines of *text* that fit *width_px* at font size *size* (an average glyph is ~0.56 em).

    The lines ``textwrap.wrap`` gives (long words broken, not at hyphens), in time linear in
    the text (:func:`construct.render.wrapping.wrap`).

    >>> [len(line) for line in wrap("Schritt 3 von 40: " + "x" * 300, 912, 13)]
    [125, 125, 68]
    """
    chars = _chars(width_px, size)
    if _one_line(text, chars):
        return [text]  # one line as it stands: what the wrapper would return, without its cost
    return wrap_chars(text, chars) or [""]


def _chars(width_px: float, size: float) -> int:
    """How many characters :func:`wrap` puts on a line *width_px* wide at font size *size*."""
    return max(20, int(width_px / (0.56 * size)))


def _one_line(text: str, chars: int) -> bool:
    """Is *text* one line of at most *chars* as it stands (:func:`wrap` gives it back alone)?"""
    return len(text) <= chars and text == text.strip() and _WHITE.search(text) is None


class PlateCaption(NamedTuple):
    """A plate's caption as a book sets it under its figure: one language, the figure's number once, at most
    :data:`~construct.kernel.letters.PLATE_CAPTION_LINES` lines, never broken inside a number or a formula.

    *head* is "Fig. N. Title", *givens* the figure's givens in the book's symbols (the most telling first),
    *cite* "nach …".  :meth:`lines` gives as many givens as the lines hold, in order; the whole list stands in
    the figure's ``<desc>`` and on the site.

    >>> cap = PlateCaption("Fig. 3. Kurbelwinkel aus den Zehnteln des Hubes", ("r/L = 1/4", "Hub in 10 Teilen"),
    ...                    "nach Anhang II, „Darstellung der Massendrücke“, Fig. 77, Tabelle 2")
    >>> cap.lines(912.0, 12.0)
    ['Fig. 3. Kurbelwinkel aus den Zehnteln des Hubes. r/L = 1/4, Hub in 10 Teilen. — nach Anhang II, „Darstellung der Massendrücke“,', 'Fig. 77, Tabelle 2.']
    >>> cap.lines(912.0, 12.0, most=1)  # one line: the givens that fit, in order; the title and the source stay
    ['Fig. 3. Kurbelwinkel aus den Zehnteln des Hubes. r/L = 1/4. — nach Anhang II, „Darstellung der Massendrücke“, Fig. 77, Tabelle 2.']
    """

    head: str
    givens: tuple[str, ...] = ()
    cite: str = ""

    def text(self, k: int | None = None) -> str:
        """The caption with its first *k* givens (all when None), in one line."""
        shown = self.givens if k is None else self.givens[:k]
        body = self.head.rstrip(".") + (". " + ", ".join(shown) if shown else "")
        return f"{body}. — {self.cite}." if self.cite else f"{body}."

    def lines(self, width: float, size: float, most: int = PLATE_CAPTION_LINES) -> list[str]:
        """The caption wrapped to *width* pixels at font size *size* in at most *most* lines where it can be:
        every given that fits, in order; no number or formula split over two lines."""
        texts = [self.text(k) for k in range(len(self.givens), -1, -1)]
        texts.append(self.head.rstrip(".") + ".")  # not even the source fits: the title alone
        for text in texts:
            got = [line.replace("\u00a0", " ") for line in wrap(unbroken(text), width, size)]
            if len(got) <= most:
                return got
        return got


def step_caption(scene: Captioned, k: int) -> tuple[str, str]:
    """The German and English caption of frame k ("Schritt k von N: ...")."""
    n = len(scene.steps)
    if k <= 0:
        return (f"Schritt 0 von {n}", f"Step 0 of {n}")
    de, en = scene.caption(k)
    return (f"Schritt {k} von {n}: {de}", f"Step {k} of {n}: {en}")


def group_caption(scene: Captioned, k: int) -> str:
    """The group path of step k, German titles where the construction gave them."""
    if k <= 0:
        return ""
    return scene.group_captions[scene.steps[k - 1].group]


class Captions:
    """A scene's caption lines wrapped to *width* pixels at font size *size*: (kind, text) rows, kind ``de``,
    ``en`` or ``grp`` (the step's group, when *groups*).

    Each step's caption is wrapped once, however many outputs (frames, the animation, a zoomed
    region of the same figure) show it.
    """

    def __init__(self, scene: Captioned, *, width: float, size: float, groups: bool = False):
        self.scene = scene
        self.width = width
        self.size = size
        self.groups = groups
        self._wrapped: dict[int, tuple[list[str], list[str]]] = {}

    def wrapped(self, k: int) -> tuple[list[str], list[str]]:
        """Step k's caption lines (German, English) wrapped to the canvas: wrapped once per step."""
        got = self._wrapped.get(k)
        if got is None:
            de, en = step_caption(self.scene, k)
            got = self._wrapped[k] = (wrap(de, self.width, self.size), wrap(en, self.width, self.size))
        return got

    def line_count(self) -> int:
        """Caption lines for the frames: the most any step needs, so that all frames have one size."""
        most = 2
        chars = _chars(self.width, self.size)
        for k in range(1, len(self.scene.steps) + 1):
            if k not in self._wrapped:
                de, en = step_caption(self.scene, k)
                if _one_line(de, chars) and _one_line(en, chars):
                    continue  # two lines, not kept: a figure of 32,000 steps shows few of them in frames
            de, en = self.wrapped(k)
            most = max(most, len(de) + len(en))
        return most + (1 if self.groups else 0)

    def frame_lines(self, k: int) -> list[tuple[str, str]]:
        """Frame k's caption lines: its group (with *groups*), then German, then English."""
        de, en = self.wrapped(k)
        lines: list[tuple[str, str]] = []
        if self.groups:
            lines.append(("grp", group_caption(self.scene, k)))
        return lines + [("de", t) for t in de] + [("en", t) for t in en]

    def title_lines(self, caption: "Sequence[str] | PlateCaption | None" = None) -> list[tuple[str, str]]:
        """The figure's caption lines (German first, then English), wrapped to the canvas; a plate's
        (:class:`PlateCaption`) in its one language."""
        if isinstance(caption, PlateCaption):
            return [("de", line) for line in caption.lines(self.width, self.size)]
        lines = list(caption if caption is not None else self.scene.title)
        return [("de" if i == 0 else "en", t) for i, line in enumerate(lines)
                for t in wrap(displayed(line, TITLE_LIMIT), self.width, self.size)]
