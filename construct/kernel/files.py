"""Reading a file that may be anything: only a regular file, of bounded size, is read.

Every reader of a file named by a user or found in a folder -- a protocol, an
SVG drawing, a golden, a README, a CSV diagram -- goes through
:func:`read_regular_file` (or :func:`open_regular_file` to read only its
head), so that a named pipe cannot make the command wait for a writer,
``/dev/zero`` or ``/dev/urandom`` cannot be read until memory runs out, and a
symbolic link to either is refused the same way, at once.

The path is looked at (``stat``) before it is opened, so that a device is
never opened at all; it is then opened without blocking and looked at again
(``fstat``), so that a path swapped for a pipe in between cannot hang the
open either; and the read stops at the limit even if the file grows.

(The kernel reads protocol files itself, so the helper sits here;
:mod:`construct.io.reading` is where the layers above find it.)

>>> read_regular_file("/dev/zero", limit=1024, what="golden")
Traceback (most recent call last):
...
construct.kernel.errors.InputFileError: cannot read golden '/dev/zero': it is not a regular file (a device); name a regular file
"""

from __future__ import annotations

import contextlib
import os
import stat
from typing import Any, Iterator

from .errors import ConstructError, InputFileError

__all__ = ["open_regular_file", "read_regular_file"]


def _a(what: str) -> str:
    """*what* with its indefinite article.

    >>> _a("indicator diagram"), _a("protocol")
    ('an indicator diagram', 'a protocol')
    """
    return f"{'an' if what[:1].lower() in 'aeiou' else 'a'} {what}"


def _name(path: Any, what: str, error: type[ConstructError]) -> str:
    try:
        name = os.fsdecode(os.fspath(path))
    except TypeError:
        raise error(f"{_a(what)} is named by a path, got {type(path).__name__}") from None
    if not name:
        raise error(f"the {what} name is empty")
    if "\0" in name:
        raise error(f"the {what} name {name[:60]!r} contains a NUL character")
    return name


def _kind(mode: int) -> str | None:
    """What a file that is not a regular one is, for the message; None for a regular file."""
    if stat.S_ISREG(mode):
        return None
    if stat.S_ISDIR(mode):
        return "a folder"
    if stat.S_ISFIFO(mode):
        return "a named pipe"
    if stat.S_ISSOCK(mode):
        return "a socket"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    return "not a regular file"


def _refuse(name: str, what: str, kind: str, error: type[ConstructError]) -> ConstructError:
    if kind == "a folder":
        return error(f"cannot read {what} {name!r}: it is a folder")
    return error(f"cannot read {what} {name!r}: it is not a regular file ({kind}); name a regular file")


def _too_big(name: str, what: str, size: int | None, limit: int, error: type[ConstructError]) -> ConstructError:
    shown = f"{limit // 2**20} MiB" if limit >= 2**20 else f"{limit} bytes"
    size_text = f" ({size} bytes)" if size is not None else ""
    return error(f"cannot read {what} {name!r}: it is larger than {shown}{size_text}, the most {_a(what)} is read")


@contextlib.contextmanager
def open_regular_file(path: Any, *, limit: int, what: str = "file",
                      error: type[ConstructError] = InputFileError) -> Iterator[tuple[int, int]]:
    """Open *path* for reading if it is a regular file of at most *limit* bytes; yield (fd, size).

    Raises *error* (a ConstructError class; its message names *what* and the
    path) for a missing file, a folder, a pipe, a device, a socket, a link to
    any of them, a file over the limit, or a file that cannot be read.  The
    descriptor is non-blocking and closed on leaving.
    """
    name = _name(path, what, error)
    try:
        info = os.stat(name)
    except FileNotFoundError:
        raise error(f"cannot read {what} {name!r}: it does not exist") from None
    except (OSError, ValueError) as exc:
        raise error(f"cannot read {what} {name!r}: {getattr(exc, 'strerror', None) or exc}") from None
    kind = _kind(info.st_mode)
    if kind is not None:  # refused before it is opened: opening a device may have effects of its own
        raise _refuse(name, what, kind, error)
    if info.st_size > limit:
        raise _too_big(name, what, info.st_size, limit, error)
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_CLOEXEC", 0) | getattr(os, "O_NOCTTY", 0)
    try:
        fd = os.open(name, flags)
    except FileNotFoundError:
        raise error(f"cannot read {what} {name!r}: it does not exist") from None
    except OSError as exc:
        raise error(f"cannot read {what} {name!r}: {exc.strerror or exc}") from None
    try:
        info = os.fstat(fd)  # again: the path may have been swapped since it was looked at
        kind = _kind(info.st_mode)
        if kind is not None:
            raise _refuse(name, what, kind, error)
        if info.st_size > limit:
            raise _too_big(name, what, info.st_size, limit, error)
        yield fd, info.st_size
    finally:
        os.close(fd)


def read_regular_file(path: Any, *, limit: int, what: str = "file",
                      error: type[ConstructError] = InputFileError) -> bytes:
    """The bytes of *path*, a regular file of at most *limit* bytes (see :func:`open_regular_file`).

    A file that grows while it is read is cut off at the limit and refused too.
    """
    name = _name(path, what, error)
    with open_regular_file(name, limit=limit, what=what, error=error) as (fd, _):
        chunks, total = [], 0
        try:
            while total <= limit:
                chunk = os.read(fd, min(1 << 20, limit + 1 - total))
                if not chunk:
                    break
                chunks.append(chunk)
                total += len(chunk)
        except OSError as exc:
            raise error(f"cannot read {what} {name!r}: {exc.strerror or exc}") from None
        if total > limit:
            raise _too_big(name, what, None, limit, error)
        return b"".join(chunks)
