"""The garbage collector while a command runs: its young passes seldom, then as it was.

A figure and its drawing are tens of thousands of objects that live until the command ends; at Python's
default thresholds every 700 new objects start a pass that walks the young ones again, a fifth of
rendering a long figure.  :func:`few_collections` is what ``construct`` (the CLI) runs every command
under, and what the benchmark times the rendering under (:mod:`construct.regress.guard`), so that it
measures what the command costs.

>>> import gc
>>> before = gc.get_threshold()
>>> with few_collections():
...     gc.get_threshold()[0] >= 10_000
True
>>> gc.get_threshold() == before
True
"""

from __future__ import annotations

import contextlib
import gc
from typing import Iterator

__all__ = ["few_collections"]


@contextlib.contextmanager
def few_collections() -> Iterator[None]:
    """The collector's young passes seldom while the block runs (as in the gallery's workers), then as before.

    What the process holds when the block starts (construct, imported) is set aside for the block
    (``gc.freeze``).  A command owns its process; run in-process (the tests call the CLI's ``main``) it
    leaves the collector as it found it.
    """
    before, mine = gc.get_threshold(), gc.get_freeze_count() == 0  # (objects frozen by another: theirs to unfreeze)
    if mine:
        gc.freeze()
    gc.set_threshold(50_000, 20, 20)
    try:
        yield
    finally:
        gc.set_threshold(*before)
        if mine:
            gc.unfreeze()
