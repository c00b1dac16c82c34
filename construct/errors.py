"""The library's exception tree (defined in :mod:`construct.kernel.errors`)."""

from .kernel.errors import *  # noqa: F401,F403
from .kernel.errors import __all__  # noqa: F401
