"""Reading a user's input file bounded: a regular file of at most a stated size, as UTF-8 text.

A path may name a FIFO with no writer (the read would wait for ever), a device
(``/dev/zero`` never ends) or a file far larger than any input the tool takes.
Only a regular file is read; its size is checked before and while reading, and
it is opened without blocking so that a path swapped for a FIFO cannot hang the
open.  Every refusal is an :class:`~construct.kernel.errors.InputFileError`
naming the file and what is wrong.

>>> import os, tempfile
>>> with tempfile.TemporaryDirectory() as d:
...     p = os.path.join(d, "a.csv")
...     _ = open(p, "w").write("x,p\\n0,1\\n")
...     read_bounded_text(p, 100)
'x,p\\n0,1\\n'
>>> read_bounded_text("/dev/null", 100, what="indicator diagram")
Traceback (most recent call last):
...
construct.kernel.errors.InputFileError: indicator diagram '/dev/null' is not a regular file (a pipe or a device); save it to a file and name that
"""

from __future__ import annotations

import os
import stat
from typing import Any

from ..kernel.errors import InputFileError

__all__ = ["read_bounded_text"]


def read_bounded_text(path: Any, limit: int, *, what: str = "input file") -> str:
    """The text of the regular file *path* (UTF-8), refused if it is larger than *limit* bytes."""
    try:
        name = os.fsdecode(os.fspath(path))
    except TypeError:
        raise InputFileError(f"a {what} is named by a path, got {type(path).__name__}") from None
    if not name:
        raise InputFileError(f"the {what} file name is empty")
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0)
    try:
        fd = os.open(name, flags)
    except FileNotFoundError:
        raise InputFileError(f"{what} {name!r} does not exist") from None
    except (OSError, ValueError) as exc:  # ValueError: a NUL byte in the name
        raise InputFileError(f"cannot read {what} {name!r}: {getattr(exc, 'strerror', None) or exc}") from None
    try:
        info = os.fstat(fd)
        if stat.S_ISDIR(info.st_mode):
            raise InputFileError(f"{what} {name!r} is a folder")
        if not stat.S_ISREG(info.st_mode):
            raise InputFileError(f"{what} {name!r} is not a regular file (a pipe or a device); save it to a file "
                                 f"and name that")
        too_big = f"{what} {name!r} is larger than {limit} bytes"
        if info.st_size > limit:
            raise InputFileError(too_big)
        chunks, total = [], 0
        while total <= limit:  # a file that grows while it is read is cut off at the limit too
            chunk = os.read(fd, min(1 << 20, limit + 1 - total))
            if not chunk:
                break
            chunks.append(chunk)
            total += len(chunk)
        if total > limit:
            raise InputFileError(too_big)
    except OSError as exc:
        raise InputFileError(f"cannot read {what} {name!r}: {exc.strerror or exc}") from None
    finally:
        os.close(fd)
    try:
        return b"".join(chunks).decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        raise InputFileError(f"{what} {name!r} is not UTF-8 text (byte {exc.start})") from None
