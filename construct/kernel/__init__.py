"""The construction kernel: geometry values, drawn curves and areas, the op table, protocols, instruments.

Layers, each importing only those before it:
``errors`` ← ``geometry`` ← ``curves``, ``areas``, ``rules``, ``trial`` ← ``ops`` ←
``protocol`` ← ``instruments`` (the Builder) ← ``division``, ``proportional``.
Nothing in the kernel imports anything outside it, at module level or inside a function.
"""

from __future__ import annotations


def version() -> str:
    """The installed distribution's version (pyproject.toml is the one place it is written).

    >>> version() == __import__("importlib.metadata").metadata.version("construct-steam")
    True
    """
    from importlib.metadata import PackageNotFoundError, version as installed

    try:
        return installed("construct-steam")
    except PackageNotFoundError:  # run from a source tree that was never installed
        return "0+unknown"
