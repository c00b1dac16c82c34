"""What ``construct`` wrote into a folder: a manifest of its files and their hashes, the one mark of ours.

A folder that ``construct gallery`` or ``construct replay`` writes ends with
``.construct-manifest.json``: which command wrote it and every file it
wrote, by relative path, with its SHA-256.  A later run replaces the folder
only when everything in it is a file that list names: a file the user put
there, a link, a pipe or an empty folder that no listed file lies in is not
ours, and the run refuses and lists it.  A README that begins like ours, or
a folder that holds every name a gallery holds, is not enough any more:
those are what a user can make.  A listed file whose content has changed
(a golden that a merge or a hand rewrote, which is what ``verify --update``
is for) is still the file construct wrote there, and is replaced; the
hashes say which files changed (:func:`changed_files`).

A folder written before manifests existed has none and is not recognised;
remove it (or name a new folder) once.

>>> import tempfile
>>> root = Path(tempfile.mkdtemp())
>>> _ = (root / "final.svg").write_text("<svg/>")
>>> write_manifest(root, "replay")
>>> foreign_entries(root, "replay")
[]
>>> _ = (root / "notes.txt").write_text("mine")
>>> foreign_entries(root, "replay")
['notes.txt']
>>> foreign_entries(root, "gallery") is None  # a replay's folder is not a gallery
True
"""

from __future__ import annotations

import hashlib
import json
import os
import stat
from pathlib import Path
from typing import Callable, ContextManager

from ..kernel.errors import ConstructError, OutputError
from ..kernel.files import read_regular_file
from .staging import STAGING_PREFIX, replaced_folder

__all__ = ["MANIFEST_NAME", "MANIFEST_FORMAT", "write_manifest", "read_manifest", "foreign_entries", "changed_files",
           "recogniser", "replaced_with_manifest"]

MANIFEST_NAME = ".construct-manifest.json"
MANIFEST_FORMAT = "construct-manifest/1"
#: The largest manifest read: a line of about 100 bytes per file; a replay with a frame per step of
#: 62,000 steps lists 62,000 files (6 MB).
_MAX_MANIFEST_BYTES = 64 * 2**20
#: Foreign entries gathered before the search stops (a refusal lists a few and counts the rest).
_MAX_FOREIGN = 1000


def _hash(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as fh:
        for block in iter(lambda: fh.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def _walk(folder: Path) -> tuple[list[str], list[str]]:
    """(regular files, everything else) under *folder* by relative path, links not followed, the
    manifest and the top level's staging leftovers left out; a folder is listed only when empty."""
    files: list[str] = []
    other: list[str] = []
    stack = [(folder, "")]
    while stack:
        here, prefix = stack.pop()
        with os.scandir(here) as it:
            entries = sorted(it, key=lambda e: e.name)
        if prefix and not entries:
            other.append(prefix.rstrip("/") + "/")
        for e in entries:
            if not prefix and (e.name == MANIFEST_NAME or e.name.startswith(STAGING_PREFIX)):
                continue
            rel = prefix + e.name
            mode = e.stat(follow_symlinks=False).st_mode
            if stat.S_ISDIR(mode):
                stack.append((Path(e.path), rel + "/"))
            elif stat.S_ISREG(mode):
                files.append(rel)
            else:
                other.append(rel)
    return sorted(files), sorted(other)


def write_manifest(folder: Path, writer: str) -> None:
    """List every file under *folder* (which *writer*, e.g. "gallery", has just written) with its hash."""
    files, other = _walk(folder)
    if other:  # what construct writes are files and folders holding them, nothing else
        raise OutputError(f"cannot list the output in {str(folder)!r}: it holds {other[0]!r}, not a file")
    data = {"format": MANIFEST_FORMAT, "written_by": f"construct {writer}",
            "files": {rel: _hash(folder / rel) for rel in files}}
    text = json.dumps(data, indent=1, sort_keys=True, ensure_ascii=True) + "\n"
    with open(folder / MANIFEST_NAME, "w", encoding="ascii", newline="\n") as fh:
        fh.write(text)


def read_manifest(folder: Path, writer: str) -> dict[str, str] | None:
    """The files and hashes the manifest in *folder* lists, or None: no manifest, an unreadable or
    malformed one, or one another command wrote (a replay's folder is not a gallery)."""
    path = folder / MANIFEST_NAME
    if not os.path.lexists(path) or os.path.islink(path):
        return None
    try:
        data = json.loads(read_regular_file(path, limit=_MAX_MANIFEST_BYTES, what="manifest"))
    except (ConstructError, ValueError, RecursionError):
        return None
    if not (isinstance(data, dict) and data.get("format") == MANIFEST_FORMAT
            and data.get("written_by") == f"construct {writer}" and isinstance(data.get("files"), dict)):
        return None
    files = data["files"]
    if not all(isinstance(k, str) and isinstance(v, str) for k, v in files.items()):
        return None
    return files


def foreign_entries(folder: Path, writer: str) -> list[str] | None:
    """What in *folder* construct did not write, by relative path (``[]``: all of it is ours); None when
    the folder has no manifest of *writer*'s.  Listed files that are gone are no one's loss."""
    listed = read_manifest(folder, writer)
    if listed is None:
        return None
    files, other = _walk(folder)
    foreign = [f"{rel} (not a file)" if not rel.endswith("/") else f"{rel} (an empty folder)" for rel in other]
    foreign += [rel for rel in files if rel not in listed]
    return foreign[:_MAX_FOREIGN]


def changed_files(folder: Path, writer: str) -> list[str] | None:
    """The listed files of *folder* whose content is no longer what construct wrote (None: no manifest)."""
    listed = read_manifest(folder, writer)
    if listed is None:
        return None
    return [rel for rel, digest in sorted(listed.items())
            if os.path.isfile(folder / rel) and not os.path.islink(folder / rel) and _hash(folder / rel) != digest]


def recogniser(writer: str, shown: int = 3) -> Callable[[Path], bool]:
    """A *recognise* function for :mod:`construct.io.staging`: True when every entry of the folder is
    in its manifest; False when it has none; an OutputError listing the rest when something is not ours."""

    def recognise(folder: Path) -> bool:
        try:
            foreign = foreign_entries(folder, writer)
        except OSError as exc:
            raise OutputError(f"cannot read {str(folder)!r}: {exc.strerror or exc}") from None
        if foreign is None:
            return False
        if foreign:
            more = len(foreign) - shown
            listing = ", ".join(foreign[:shown]) + (f" and {more} more" if more > 0 else "")
            raise OutputError(f"refusing to replace {str(folder)!r}: it holds what construct did not write: "
                              f"{listing}; move that out of the folder, or name another folder")
        return True

    return recognise


def replaced_with_manifest(target: str | os.PathLike[str], writer: str, *, described: str,
                           what: str = "output folder") -> ContextManager[Path]:
    """:func:`construct.io.staging.replaced_folder` for a folder *writer* ("gallery", "replay") owns: the old
    folder is recognised by the manifest *writer* left in it, and the new one gets its own before it is
    swapped in.

    >>> import tempfile
    >>> out = Path(tempfile.mkdtemp()) / "replay"
    >>> with replaced_with_manifest(out, "replay", described="a demo") as new:
    ...     new.mkdir(); _ = (new / "final.svg").write_text("<svg/>")
    >>> sorted(p.name for p in out.iterdir()), foreign_entries(out, "replay")
    (['.construct-manifest.json', 'final.svg'], [])
    """
    return replaced_folder(target, recognise=recogniser(writer), described=described, what=what,
                           before_swap=lambda new: write_manifest(new, writer))
