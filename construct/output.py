"""Writing output folders so that a failure leaves nothing half-written.

Everything is first written into a hidden staging folder inside the target;
only when the whole job has succeeded are the finished entries moved into
place (each by an atomic ``os.replace``; a sub-folder is swapped as a whole).
On failure the staging folder is removed, and a target folder that did not
exist before is removed too.

>>> import tempfile, pathlib
>>> root = pathlib.Path(tempfile.mkdtemp())
>>> with staged_output(root / "out") as stage:
...     _ = (stage / "a.txt").write_text("hello")
>>> sorted(p.name for p in (root / "out").iterdir())
['a.txt']
"""

from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
from pathlib import Path
from typing import Iterator

from .errors import OutputError

STAGING_PREFIX = ".construct-staging-"


@contextlib.contextmanager
def staged_output(target: str | os.PathLike[str]) -> Iterator[Path]:
    """Yield a staging folder; on success move its entries into *target*."""
    target = Path(target)
    created = not target.exists()
    try:
        if target.exists() and not target.is_dir():
            raise OutputError(f"output folder {str(target)!r} exists and is not a folder")
        target.mkdir(parents=True, exist_ok=True)
        stage = Path(tempfile.mkdtemp(prefix=STAGING_PREFIX, dir=target))
    except OutputError:
        raise
    except OSError as exc:
        raise OutputError(f"cannot write to output folder {str(target)!r}: {exc.strerror or exc}") from None
    try:
        yield stage
        _commit(stage, target)
    except BaseException:
        shutil.rmtree(stage, ignore_errors=True)
        if created:
            shutil.rmtree(target, ignore_errors=True)
        raise
    shutil.rmtree(stage, ignore_errors=True)


def _commit(stage: Path, target: Path) -> None:
    try:
        for entry in sorted(stage.iterdir()):
            dest = target / entry.name
            if entry.is_dir() and dest.exists():
                # Swap whole folders: move the old one aside first, then drop it.
                old = Path(tempfile.mkdtemp(prefix=STAGING_PREFIX + "old-", dir=target))
                os.replace(dest, old / entry.name)
                os.replace(entry, dest)
                shutil.rmtree(old, ignore_errors=True)
            else:
                os.replace(entry, dest)
    except OSError as exc:
        raise OutputError(f"cannot write to output folder {str(target)!r}: {exc.strerror or exc}") from None


def write_text(path: Path, text: str) -> None:
    """Write *text* as UTF-8 with LF line ends, creating parent folders."""
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", encoding="utf-8", newline="\n") as fh:
        fh.write(text)
