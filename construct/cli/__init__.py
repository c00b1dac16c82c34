"""The ``construct`` command line: ``main`` (in :mod:`.main`) and one module per subcommand in :mod:`.commands`."""

from .main import main

__all__ = ["main"]
