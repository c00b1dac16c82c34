"""Writing output folders so that a failure leaves nothing half-written and nothing foreign is lost.

Everything is first written into a hidden staging folder; only when the
whole job has succeeded is it moved into place.  :func:`staged_output`
stages inside the target and moves the finished entries in (each by an
atomic ``os.replace``; a sub-folder is swapped as a whole);
:func:`replaced_folder` stages beside the target and swaps the whole folder.
On failure the staging folder is removed, and a target folder that did not
exist before is removed too.

A writer replaces only what it recognises as its own: a folder that is
missing, empty, or recognised by the writer's *recognise* function (a
gallery by its index, a replay by its files); anything else is refused with
an :class:`OutputError` and left untouched.  An empty path is never meant (an
unset variable) and is refused.

Staging folders are named ``.construct-staging-<pid>-<start>-...`` (the
process and its start time), so a later run can tell the leftovers of a run
that was killed (its process gone) from those of a run still going, and
removes the former.

>>> import tempfile, pathlib
>>> root = pathlib.Path(tempfile.mkdtemp())
>>> with staged_output(root / "out") as stage:
...     _ = (stage / "a.txt").write_text("hello")
>>> sorted(p.name for p in (root / "out").iterdir())
['a.txt']
>>> with replaced_folder(root / "out", recognise=lambda p: False, described="a demo") as new:
...     pass
Traceback (most recent call last):
construct.kernel.errors.OutputError: refusing to replace '...out': it is neither empty nor a demo (it holds a.txt); name a new or empty folder
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import stat
import tempfile
from pathlib import Path
from typing import Callable, Iterator

from ..kernel.errors import OutputError

__all__ = ["STAGING_PREFIX", "staged_output", "replaced_folder", "output_path", "remove_stale_staging",
           "write_text", "write_bytes"]

STAGING_PREFIX = ".construct-staging-"
_STAGING_NAME = re.compile(re.escape(STAGING_PREFIX) + r"(\d+)-(\d+)-")
_SHOWN = 3  # foreign entries named in a refusal


def output_path(target: str | os.PathLike[str], what: str = "output folder") -> Path:
    """*target* as a Path; an empty path (an unset variable, not the current folder) is refused.

    >>> output_path("")
    Traceback (most recent call last):
    construct.kernel.errors.OutputError: the output folder is an empty path; name a folder ('.' for the current one)
    """
    text = os.fspath(target)
    if text == "":
        raise OutputError(f"the {what} is an empty path; name a folder ('.' for the current one)")
    if "\0" in text:
        raise OutputError(f"the {what} {text!r} contains a NUL character")
    return Path(text)


def _reason(exc: OSError) -> str:
    return exc.strerror or str(exc)


def _stat(path: Path, what: str) -> os.stat_result | None:
    """The target's status, None when it does not exist; an unreachable path is an OutputError."""
    try:
        return path.stat()
    except FileNotFoundError:
        return None
    except NotADirectoryError:
        raise OutputError(f"cannot write {what} {str(path)!r}: a part of its path is a file, not a folder") from None
    except OSError as exc:  # a name too long, a parent folder that cannot be entered, a loop of links
        raise OutputError(f"cannot write {what} {str(path)!r}: {_reason(exc)}") from None


def _entries(folder: Path, what: str) -> list[str]:
    """The names in *folder*, without staging leftovers."""
    try:
        return sorted(n for n in os.listdir(folder) if not n.startswith(STAGING_PREFIX))
    except OSError as exc:
        raise OutputError(f"cannot read {what} {str(folder)!r}: {_reason(exc)}") from None


def _first_missing(path: Path) -> Path | None:
    """The outermost folder of *path* that does not exist yet (what a failed run must remove), or None."""
    missing = None
    for p in (path, *path.parents):
        if os.path.lexists(p):
            break
        missing = p
    return missing


def _check_replaceable(target: Path, recognise: Callable[[Path], bool], described: str, what: str) -> bool:
    """Whether *target* exists; raise OutputError unless it is missing, empty or recognised."""
    st = _stat(target, what)
    if st is None:
        return False
    if not stat.S_ISDIR(st.st_mode):
        raise OutputError(f"{what} {str(target)!r} exists and is not a folder; name a new or empty folder")
    names = _entries(target, what)
    if not names:
        return True
    try:
        ours = recognise(target)
    except OSError:
        ours = False
    if not ours:
        shown = ", ".join(names[:_SHOWN]) + (f" and {len(names) - _SHOWN} more" if len(names) > _SHOWN else "")
        raise OutputError(f"refusing to replace {str(target)!r}: it is neither empty nor {described} "
                          f"(it holds {shown}); name a new or empty folder")
    return True


# --------------------------------------------------------------------------- staging folders


def _start_token(pid: int) -> str | None:
    """The start time of process *pid* (clock ticks since boot) where /proc tells it; None otherwise."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as fh:
            fields = fh.read().rsplit(b")", 1)[1].split()
    except (OSError, IndexError):
        return None
    if fields[0] in (b"Z", b"X"):  # a zombie has finished: its staging folder is as dead as it is
        return "dead"
    return fields[19].decode("ascii", "replace") if len(fields) > 19 else None


def _staging_prefix(tag: str = "") -> str:
    pid = os.getpid()
    return f"{STAGING_PREFIX}{pid}-{_start_token(pid) or 0}-{tag}"


def _alive(pid: int, token: str) -> bool:
    try:
        os.kill(pid, 0)  # signal 0: only asks whether the process exists
    except ProcessLookupError:
        return False
    except OSError:
        return True  # it exists but belongs to someone else
    now = _start_token(pid)
    if now == "dead":
        return False
    # a different start time: the pid was reused by another process, the run is gone
    return now is None or token == "0" or now == token


def remove_stale_staging(folder: Path) -> list[str]:
    """Remove the staging folders in *folder* left by runs whose process is gone; return their names.

    Folders of runs still going are kept; so are names this version did not
    write (no pid in them): whose they are cannot be told.
    """
    removed = []
    try:
        names = [n for n in os.listdir(folder) if n.startswith(STAGING_PREFIX)]
    except OSError:
        return removed
    for name in names:
        m = _STAGING_NAME.match(name)
        if m and not _alive(int(m.group(1)), m.group(2)):
            shutil.rmtree(folder / name, ignore_errors=True)
            removed.append(name)
    return removed


def _make_stage(folder: Path, tag: str = "") -> Path:
    return Path(tempfile.mkdtemp(prefix=_staging_prefix(tag), dir=folder))


# --------------------------------------------------------------------------- staging inside the target


@contextlib.contextmanager
def staged_output(target: str | os.PathLike[str], *, recognise: Callable[[Path], bool] | None = None,
                  described: str = "", what: str = "output folder") -> Iterator[Path]:
    """Yield a staging folder inside *target*; on success move its entries into *target*.

    Without *recognise* the entries are added to what *target* holds (an entry
    of the same name is replaced).  With it, *target* must be missing, empty
    or recognised (else OutputError, *described* says what would have been
    recognised), and it ends up holding exactly the staged entries.
    """
    target = output_path(target, what)
    if recognise is not None:
        existed = _check_replaceable(target, recognise, described, what)
    else:
        st = _stat(target, what)
        existed = st is not None
        if existed and not stat.S_ISDIR(st.st_mode):  # type: ignore[union-attr]
            raise OutputError(f"{what} {str(target)!r} exists and is not a folder")
    created = _first_missing(target)  # the folders this run makes, removed again if it fails
    try:
        target.mkdir(parents=True, exist_ok=True)
        remove_stale_staging(target)
        stage = _make_stage(target)
    except OSError as exc:
        raise OutputError(f"cannot write to {what} {str(target)!r}: {_reason(exc)}") from None
    try:
        yield stage
        _commit(stage, target, exact=recognise is not None)
    except BaseException:
        shutil.rmtree(stage, ignore_errors=True)
        if created is not None:
            shutil.rmtree(created, ignore_errors=True)
        raise
    shutil.rmtree(stage, ignore_errors=True)


def _commit(stage: Path, target: Path, *, exact: bool = False) -> None:
    try:
        staged = sorted(stage.iterdir())
        for entry in staged:
            dest = target / entry.name
            if entry.is_dir() and dest.exists():
                # Swap whole folders: move the old one aside first, then drop it.
                old = _make_stage(target, "old-")
                os.replace(dest, old / entry.name)
                os.replace(entry, dest)
                shutil.rmtree(old, ignore_errors=True)
            else:
                os.replace(entry, dest)
        if exact:  # what the previous run wrote and this one did not (recognised as ours before)
            keep = {e.name for e in staged}
            for name in _entries(target, "output folder"):
                if name not in keep:
                    old = target / name
                    if old.is_dir() and not old.is_symlink():
                        shutil.rmtree(old)
                    else:
                        old.unlink()
    except OSError as exc:
        raise OutputError(f"cannot write to output folder {str(target)!r}: {_reason(exc)}") from None


# --------------------------------------------------------------------------- a folder swapped as a whole


@contextlib.contextmanager
def replaced_folder(target: str | os.PathLike[str], *, recognise: Callable[[Path], bool], described: str,
                    what: str = "output folder") -> Iterator[Path]:
    """Yield the path to build the new *target* at (beside it); on success swap it in whole.

    *target* must be missing, empty or recognised by *recognise* (else
    OutputError).  The new folder is built in a staging folder in *target*'s
    parent, so that folder must be writable; a failure leaves *target* as it
    was.
    """
    target = output_path(target, what)
    existed = _check_replaceable(target, recognise, described, what)
    try:
        target = target.resolve()
    except OSError as exc:
        raise OutputError(f"cannot write {what} {str(target)!r}: {_reason(exc)}") from None
    parent = target.parent
    if target == parent:
        raise OutputError(f"refusing to replace the root folder {str(target)!r}")
    try:
        here = Path.cwd().resolve()
    except OSError:  # the current folder was removed: it is not inside the target
        here = None
    if existed and here is not None and here.is_relative_to(target):
        raise OutputError(f"refusing to replace {str(target)!r}: it holds the current folder; "
                          f"run from outside it or name another folder")
    created = _first_missing(parent)  # folders made for the target, removed again if the run fails
    try:
        parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the folder {str(parent)!r} for {what} {str(target)!r}: "
                          f"{_reason(exc)}") from None
    remove_stale_staging(parent)
    try:
        stage = _make_stage(parent)
    except OSError as exc:
        if created is not None:
            shutil.rmtree(created, ignore_errors=True)
        # The target itself may well be writable: it is its parent that the whole-folder swap needs.
        raise OutputError(f"cannot replace {what} {str(target)!r}: it is built beside it and swapped in whole, "
                          f"and its parent folder {str(parent)!r} is not writable ({_reason(exc)})") from None
    new = stage / target.name
    try:
        yield new
        if not new.is_dir():
            raise OutputError(f"nothing was written for {what} {str(target)!r}")
        _swap(stage, new, target, existed)
    except BaseException:
        shutil.rmtree(stage, ignore_errors=True)
        if created is not None:
            shutil.rmtree(created, ignore_errors=True)
        raise
    shutil.rmtree(stage, ignore_errors=True)


def _swap(stage: Path, new: Path, target: Path, existed: bool) -> None:
    old = stage / ".old"
    try:
        if existed:
            os.replace(target, old)
        try:
            os.replace(new, target)
        except OSError:
            if existed:
                os.replace(old, target)  # put the previous folder back
            raise
    except OSError as exc:
        raise OutputError(f"cannot replace {str(target)!r}: {_reason(exc)}") from None


def write_text(path: Path, text: str) -> None:
    """Write *text* as UTF-8 with LF line ends, creating parent folders."""
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        fh.write(text)


def write_bytes(target: str | os.PathLike[str], data: bytes) -> Path:
    """Write one file whole or not at all: into a hidden file beside it, then one atomic rename.

    The parent folder must exist (a file the user names is not a place to create folders in); a folder or
    anything but a regular file at *target* is refused, and so is a failed write (disk full, permissions),
    with the previous file kept.

    >>> import tempfile
    >>> p = Path(tempfile.mkdtemp()) / "t.txt"
    >>> write_bytes(p, b"one").read_bytes(), sorted(x.name for x in p.parent.iterdir())
    (b'one', ['t.txt'])
    >>> write_bytes(p.parent, b"two")
    Traceback (most recent call last):
    ...
    construct.kernel.errors.OutputError: ... is a folder, not a file to write
    """
    path = output_path(target, "output file")
    st = _stat(path, "output file")
    if st is not None and stat.S_ISDIR(st.st_mode):
        raise OutputError(f"{str(path)!r} is a folder, not a file to write")
    if st is not None and not stat.S_ISREG(st.st_mode):
        raise OutputError(f"{str(path)!r} is not a regular file; refusing to replace it")
    if not path.parent.is_dir():
        raise OutputError(f"cannot write {str(path)!r}: its folder {str(path.parent)!r} does not exist")
    fd, tmp = tempfile.mkstemp(prefix=_staging_prefix("file-"), dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.replace(tmp, path)
    except BaseException as exc:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        if isinstance(exc, OSError):
            raise OutputError(f"cannot write {str(path)!r}: {_reason(exc)}") from None
        raise
    return path
