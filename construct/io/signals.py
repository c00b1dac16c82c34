"""Signals held back: Ctrl-C, SIGTERM and SIGHUP wait while a block runs that must not be cut in two.

The atomic swap of an output folder and the removal of its staging (:mod:`construct.io.staging`) run under
:func:`signals_deferred`: a signal there would leave the target missing or a staging folder behind.  The
handlers in place before are restored afterwards, and a signal that came meanwhile arrives then, under them.

>>> import signal
>>> before = signal.getsignal(signal.SIGINT)
>>> with signals_deferred():  # a Ctrl-C here would arrive after the block
...     pass
>>> signal.getsignal(signal.SIGINT) is before
True
"""

from __future__ import annotations

import contextlib
import signal
import threading
from typing import Iterator

__all__ = ["signals_deferred"]

#: The signals held back (those a platform lacks are skipped).
_DEFERRED = ("SIGINT", "SIGTERM", "SIGHUP")


@contextlib.contextmanager
def signals_deferred() -> Iterator[None]:
    """Ctrl-C, SIGTERM and SIGHUP wait until the block is done, then arrive as they would have.

    For the moments a folder is swapped and its staging removed: a signal
    there would leave the target missing or a staging folder behind.  Only
    the main thread receives signals in Python; elsewhere nothing changes.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    caught: list[int] = []
    previous = {}
    for name in _DEFERRED:
        sig = getattr(signal, name, None)
        if sig is None or signal.getsignal(sig) is None:  # None: a handler set outside Python, not restorable
            continue
        try:
            previous[sig] = signal.signal(sig, lambda signum, frame: caught.append(signum))
        except (ValueError, OSError):
            pass
    try:
        yield
    finally:
        for sig, handler in previous.items():
            signal.signal(sig, handler)
        for sig in dict.fromkeys(caught):
            signal.raise_signal(sig)  # now, under the handler that was there before
