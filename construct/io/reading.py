"""Reading files that may be anything: a regular file of bounded size, or one line saying why not.

The readers above the kernel -- SVG drawings (``construct diff``, the goldens
of ``construct verify``), README files of galleries, CSV diagrams -- read
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

from ..kernel.files import open_regular_file, read_regular_file

__all__ = ["open_regular_file", "read_regular_file"]
