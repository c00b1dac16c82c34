"""Captions in the figure's own letters (the rules live in :mod:`construct.kernel.letters`).

The kernel writes every step's caption in the figure's letters when a
construction is built (:meth:`construct.kernel.instruments.Builder.protocol`),
so the protocol, the player, the animation and the storyboard read alike;
the renderers import the same names from here.
"""

from __future__ import annotations

from ..kernel.letters import (CAPTION_LIMIT, TITLE_LIMIT, Reader, book_symbols, displayed, equation, subscripts,
                              tag)

__all__ = ["Reader", "book_symbols", "equation", "subscripts", "tag", "displayed", "CAPTION_LIMIT", "TITLE_LIMIT"]
