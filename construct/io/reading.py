"""Reading files that may be anything: a regular file of bounded size, or one line saying why not.

The readers above the kernel -- SVG drawings (``construct diff``, the goldens
of ``construct verify``), README files of galleries, indicator cards in CSV -- read
through :func:`read_regular_file` (whole) or :func:`open_regular_file` (only
a head), as the kernel reads protocol files: a named pipe, a device, a
socket, a folder, a link to one of them or a file over the limit is refused
at once with *error* (default :class:`~construct.kernel.errors.InputFileError`),
naming *what* and the path.  The one implementation is
:mod:`construct.kernel.files` (the kernel reads protocols, and sits below).

>>> import tempfile, os
>>> path = os.path.join(tempfile.mkdtemp(), "a.svg")
>>> with open(path, "w") as fh:
...     _ = fh.write("<svg/>")
>>> read_regular_file(path, limit=1024, what="drawing")
b'<svg/>'
>>> read_regular_file(path, limit=3, what="drawing")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
construct.kernel.errors.InputFileError: cannot read drawing '.../a.svg': it is larger than 3 bytes (6 bytes), the most a drawing is read
"""

from __future__ import annotations

import os
from typing import Any

from ..kernel.errors import InputFileError
from ..kernel.files import open_regular_file, read_regular_file

__all__ = ["open_regular_file", "read_regular_file", "read_bounded_text"]


def read_bounded_text(path: Any, limit: int, *, what: str = "input file") -> str:
    """The UTF-8 text (a byte-order mark allowed) of the regular file *path* of at most *limit* bytes.

    >>> import os, tempfile
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = os.path.join(d, "a.csv")
    ...     _ = open(p, "w").write("x,p\\n0,1\\n")
    ...     read_bounded_text(p, 100)
    'x,p\\n0,1\\n'
    """
    data = read_regular_file(path, limit=limit, what=what)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputFileError(f"{what} {os.fsdecode(os.fspath(path))!r} is not UTF-8 text (byte {exc.start})") from None
