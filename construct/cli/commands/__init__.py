"""Subcommands of the ``construct`` command line, one module each.

Add a module with ``NAME``, ``HELP``, ``add_arguments(parser)`` and
``run(args) -> int`` and list it in :data:`MODULES`.
"""

from __future__ import annotations

import importlib

_NAMES = [
    "list",
    "replay",
    "check",
    "table",
    "bench",
    # one line per subcommand module, in the order `construct --help` lists them
    "errata",
    "flywheel",
    "samples",
    "diff",
    "gallery",
    "verify",
    "lint",
]

MODULES = [importlib.import_module(f"{__name__}.{name}") for name in _NAMES]
