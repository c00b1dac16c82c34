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
gallery or a replay by the manifest it wrote, :mod:`construct.io.manifest`);
anything else is refused with an :class:`OutputError` and left untouched.
An empty path is never meant (an unset variable) and is refused.

The swap of a whole folder is one atomic exchange where the system has one
(Linux ``renameat2``), else two renames undone on failure; Ctrl-C, SIGTERM
and SIGHUP are held back while it and the clean-up run
(:func:`signals_deferred`), so an interrupted run leaves the old folder or
the new one, never neither or a mix.  A write that fails (a full disk, a
quota, a permission) is one OutputError naming the target and the cause.

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
import errno
import os
import re
import secrets
import shutil
import stat
import tempfile
from pathlib import Path
from typing import Any, Callable, Iterator

from ..kernel.errors import OutputError
from .signals import signals_deferred

__all__ = ["STAGING_PREFIX", "staged_output", "replaced_folder", "output_path", "remove_stale_staging",
           "write_text", "write_bytes", "write_failure", "signals_deferred"]

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
    except OutputError:  # the recogniser's own refusal, listing what is not ours
        raise
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


#: The staging folders this process is using now; one of its own that is not here was left by an
#: earlier run in this process that could not remove it (a failed clean-up), and is stale.
_ACTIVE: set[str] = set()
#: In a staging folder of a whole-folder swap: the target's name, written before the swap begins,
#: and where the previous folder waits while the two renames of a swap without an atomic exchange
#: are under way.
_TARGET_NOTE, _OLD = ".target", ".old"


def remove_stale_staging(folder: Path) -> list[str]:
    """Remove the staging folders in *folder* left by runs whose process is gone; return their names.

    Folders of runs still going are kept; so are names this version did not
    write (no pid in them): whose they are cannot be told.  A run killed
    between the two renames of a swap left its target missing and the
    previous folder in its staging folder: that folder is put back first.
    """
    removed = []
    try:
        names = [n for n in os.listdir(folder) if n.startswith(STAGING_PREFIX)]
    except OSError:
        return removed
    for name in names:
        m = _STAGING_NAME.match(name)
        if not m:
            continue
        pid, token = int(m.group(1)), m.group(2)
        if pid == os.getpid() and token == (_start_token(pid) or "0"):
            stale = _key(folder / name) not in _ACTIVE
        else:
            stale = not _alive(pid, token)
        if stale and _restore_interrupted_swap(folder, folder / name):
            _remove_tree(folder / name)
            removed.append(name)
    return removed


def _restore_interrupted_swap(parent: Path, stage: Path) -> bool:
    """Put back the previous folder a killed swap left in *stage*; False when it cannot (keep the stage)."""
    old = stage / _OLD
    if not os.path.isdir(old):
        return True
    try:
        with open(stage / _TARGET_NOTE, encoding="utf-8") as fh:
            name = fh.read()
    except OSError:
        return False  # which folder it was cannot be told: keep it rather than lose it
    if "/" in name or name in ("", ".", ".."):
        return False
    target = parent / name
    if os.path.lexists(target):
        return True  # the new folder went in before the run was killed: the old one is what is left over
    try:
        os.rename(old, target)
    except OSError:
        return False
    return True


def _key(stage: Path) -> str:
    """A staging folder as _ACTIVE knows it: one spelling, whatever path led to its folder."""
    return os.path.join(os.path.realpath(os.path.dirname(stage)), os.path.basename(stage))


def _remove_tree(path: Path) -> None:
    """Remove a staging folder; what cannot be removed stays for the next run (its process is gone then)."""
    try:
        shutil.rmtree(path, ignore_errors=True)
    except OSError:
        pass


def _make_stage(folder: Path, tag: str = "") -> Path:
    """A new staging folder in *folder*, known as this process's own before it exists (another thread's
    clean-up must never take it for a leftover)."""
    for _ in range(100):
        stage = Path(folder) / (_staging_prefix(tag) + secrets.token_hex(4))
        _ACTIVE.add(_key(stage))
        made = False
        try:
            os.mkdir(stage, 0o700)
            made = True
            return stage
        except FileExistsError:
            continue
        finally:
            if not made:
                _ACTIVE.discard(_key(stage))
    raise FileExistsError(errno.EEXIST, "no free name for a staging folder", str(folder))


def _release(stage: Path) -> None:
    """Remove a staging folder this process made (what cannot be removed, the next run removes)."""
    try:
        _remove_tree(stage)
    finally:
        _ACTIVE.discard(_key(stage))


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
        try:
            yield stage
        except OSError as exc:
            if isinstance(exc, OutputError):
                raise
            raise write_failure(exc, target, stage, what, existed) from None
        _commit(stage, target, exact=recognise is not None, existed=existed)
    except BaseException:
        _release(stage)
        if created is not None:
            shutil.rmtree(created, ignore_errors=True)
        raise
    _release(stage)


def _commit(stage: Path, target: Path, *, exact: bool = False, existed: bool = True) -> None:
    """Move the staged entries into *target*, all of them or none: what they replace (and, *exact*, what the
    previous run wrote and this one did not) goes aside into a staging folder first; if a move fails, the
    entries already moved go back into the stage and the old ones back into place.  Ctrl-C, SIGTERM and
    SIGHUP wait until it is done either way (:func:`signals_deferred`)."""
    with signals_deferred():
        aside: Path | None = None
        moved_aside: list[str] = []
        placed: list[str] = []
        try:
            staged = sorted(stage.iterdir())
            names = {e.name for e in staged}
            aside = _make_stage(target, "old-")
            for name in _entries(target, "output folder"):
                if name in names or exact:
                    os.replace(target / name, aside / name)
                    moved_aside.append(name)
            for entry in staged:
                os.replace(entry, target / entry.name)
                placed.append(entry.name)
        except BaseException as exc:
            restored = _roll_back(stage, target, aside, placed, moved_aside)
            if aside is not None and restored:
                _release(aside)
            elif aside is not None:   # something could not be put back: it stays where the message says
                _ACTIVE.discard(_key(aside))
            if not isinstance(exc, OSError) or isinstance(exc, OutputError):
                raise
            kept = ((f"the previous {'files are' if moved_aside else 'output is'} kept" if existed else
                     "nothing was written") if restored else
                    f"the previous files could not all be put back: they are in {str(aside)!r}")
            raise OutputError(f"cannot write to output folder {str(target)!r}: {_reason(exc)}; {kept}") from None
        _release(aside)


def _roll_back(stage: Path, target: Path, aside: Path | None, placed: list[str], moved_aside: list[str]) -> bool:
    """Undo a commit that failed halfway: the new entries back into the stage, the old ones back into place.
    True when everything is back."""
    ok = True
    for name in reversed(placed):
        try:
            os.replace(target / name, stage / name)
        except OSError:
            ok = False
    for name in reversed(moved_aside):
        try:
            os.replace(aside / name, target / name)  # type: ignore[operator]
        except OSError:
            ok = False
    return ok


# --------------------------------------------------------------------------- a folder swapped as a whole


@contextlib.contextmanager
def replaced_folder(target: str | os.PathLike[str], *, recognise: Callable[[Path], bool], described: str,
                    what: str = "output folder", before_swap: Callable[[Path], None] | None = None) -> Iterator[Path]:
    """Yield the path to build the new *target* at (beside it); on success swap it in whole.

    *target* must be missing, empty or recognised by *recognise* (else
    OutputError).  *before_swap* is called with the new folder once it is
    written, before it is swapped in (a writer's manifest goes in there:
    :func:`construct.io.manifest.replaced_with_manifest`).  The new folder is
    built in a staging folder in *target*'s parent, so that folder must be
    writable; a failure leaves *target* as it was, and a write that fails (a
    full disk, a quota, a permission) is one OutputError naming the path and
    the cause.
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
    if existed and not os.access(target, os.W_OK | os.X_OK):
        # a folder moved whole to its new place needs writing into itself (its ".."): say so before building
        raise OutputError(f"cannot replace {what} {str(target)!r}: it is not writable, and it is replaced by "
                          f"moving it whole; nothing was built, the previous {what} is kept")
    created = _first_missing(parent)  # folders made for the target, removed again if the run fails
    try:
        parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the folder {str(parent)!r} for {what} {str(target)!r}: "
                          f"{_reason(exc)}") from None
    remove_stale_staging(parent)
    stage: Path | None = None
    swapped = False
    try:
        try:
            with signals_deferred():  # made and noted as one: a signal in between would leave it unnoted
                stage = _make_stage(parent)
                with open(stage / _TARGET_NOTE, "w", encoding="utf-8") as fh:  # for the next run, if this is killed
                    fh.write(target.name)
        except OSError as exc:
            # The target itself may well be writable: it is its parent that the whole-folder swap needs.
            raise OutputError(f"cannot replace {what} {str(target)!r}: it is built beside it and swapped in "
                              f"whole, and its parent folder {str(parent)!r} is not writable ({_reason(exc)})"
                              ) from None
        new = stage / target.name
        try:
            yield new
            if not new.is_dir():
                raise OutputError(f"nothing was written for {what} {str(target)!r}")
            if before_swap is not None:
                before_swap(new)
        except OSError as exc:
            if isinstance(exc, OutputError):
                raise
            raise write_failure(exc, target, new, what, existed) from None
        with signals_deferred():  # Ctrl-C or SIGTERM from here on waits until the old or the new is in place
            swapped = _swap(stage, new, target, existed, what)
            _release(stage)
    except BaseException:
        if not swapped:
            if stage is not None and os.path.isdir(stage / _OLD) and not os.path.lexists(target):
                _ACTIVE.discard(_key(stage))  # the previous folder could not be put back: the next run restores it
            elif stage is not None:
                _release(stage)
            if created is not None and not os.path.lexists(target):
                shutil.rmtree(created, ignore_errors=True)
        raise


def write_failure(exc: OSError, target: Path, stage: Path, what: str, existed: bool = True) -> OutputError:
    """A write that failed while a folder was staged, as one line naming the target, the file and the cause, and
    what is left: the previous folder where there was one, nothing where there was none."""
    name = getattr(exc, "filename", None)
    where = ""
    if name:
        try:
            where = f" (writing {Path(os.fsdecode(name)).relative_to(stage).as_posix()})"
        except ValueError:
            where = f" (writing {os.fsdecode(name)})"
    left = f"nothing was changed, the previous {what} is kept" if existed else "nothing was written"
    return OutputError(f"cannot write {what} {str(target)!r}: {_reason(exc)}{where}; {left}")


#: renameat2's flag for an atomic exchange of two paths (Linux 3.15, glibc 2.28), and the "current folder" fd.
_RENAME_EXCHANGE, _AT_FDCWD = 2, -100
_renameat2: Any = None


def _exchange(a: Path, b: Path) -> bool:
    """Swap *a* and *b* in one atomic step where the system can (Linux); False where it cannot."""
    global _renameat2
    if _renameat2 is None:
        try:
            import ctypes

            libc = ctypes.CDLL(None, use_errno=True)
            fn = libc.renameat2
            fn.argtypes = [ctypes.c_int, ctypes.c_char_p, ctypes.c_int, ctypes.c_char_p, ctypes.c_uint]
            _renameat2 = (fn, ctypes)
        except (OSError, AttributeError, ImportError):
            _renameat2 = False
    if not _renameat2:
        return False
    fn, ctypes = _renameat2
    if fn(_AT_FDCWD, os.fsencode(a), _AT_FDCWD, os.fsencode(b), _RENAME_EXCHANGE) == 0:
        return True
    err = ctypes.get_errno()
    if err in (errno.ENOSYS, errno.EINVAL, errno.ENOTSUP, errno.EOPNOTSUPP, errno.EPERM):
        return False  # no exchange here (old kernel, a file system without it): two renames instead
    raise OSError(err, os.strerror(err), os.fsdecode(b))


def _swap(stage: Path, new: Path, target: Path, existed: bool, what: str) -> bool:
    """Put *new* in place of *target*; True when done.  At every moment *target* is the old folder or
    the new one: by one atomic exchange where the system has it; else by two renames, and if the
    second fails the first is undone (should even that fail, the old folder stays in *stage* for the
    next run to put back, and the message says where it is)."""
    try:
        if not existed or not os.path.lexists(target):
            os.rename(new, target)
            return True
        if _exchange(new, target):
            return True
        old = stage / _OLD
        os.rename(target, old)
        try:
            os.rename(new, target)
        except BaseException:
            try:
                os.rename(old, target)  # put the previous folder back
            except OSError as exc:
                raise OutputError(f"cannot replace {str(target)!r}: {_reason(exc)}; the previous {what} is "
                                  f"kept in {str(old)!r} and the next run puts it back") from None
            raise
        return True
    except OutputError:
        raise
    except OSError as exc:
        left = f"the previous {what} is kept" if existed else "nothing was written"
        raise OutputError(f"cannot write {what} {str(target)!r}: {_reason(exc)}; {left}") from None


def write_text(path: Path, text: str) -> None:
    """Write *text* as UTF-8 with LF line ends, creating parent folders.

    Text that is not Unicode (a lone surrogate, from a caption or a name of a caller's) has no UTF-8:
    an OutputError names the file and where in the text it is, nothing is written.
    """
    try:
        data = text.encode("utf-8")
    except UnicodeEncodeError as exc:
        raise OutputError(f"cannot write {path.name}: its text holds {text[exc.start]!r} at character {exc.start}, "
                          f"which is not Unicode text (a lone surrogate); correct the name or caption") from None
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        with open(path, "wb") as fh:
            fh.write(data)
    except OSError as exc:  # a write error carries no file name: the message names the file
        if exc.filename is None and exc.errno is not None:
            raise OSError(exc.errno, exc.strerror, str(path)) from None
        raise


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
