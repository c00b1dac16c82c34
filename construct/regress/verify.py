"""Golden files: rebuild the gallery and compare every file with the committed one.

Every step is compared, not just the final figure, and in geometry, not in
bytes.  A figure is one layered SVG (``final.svg``: each step's elements in a
``<g data-step="k">`` group), so a change is reported per step from that one
file -- "crank-6/teaching step 5 (crank-6/teaching/final.svg)" -- the way a
standalone frame ``steps/005.svg`` (where one is written) is reported as step 5.
Files are compared by meaning: a ``.svg`` through
:func:`construct.regress.svgdiff.diff_svg`, a ``protocol.json`` through :func:`construct.regress.protocoldiff.diff_protocol`, so a
golden rewritten with reordered attributes or reformatted numbers is still
equal while a point moved by 0.01 drawing units is named; a ``.tikz`` plate
through :func:`construct.regress.printdiff.diff_tikz`, by named point and line by
line with its numbers within 0.001 mm on the page.  Other text files
(``.json``, ``.html``, ``.md``, ``.csv``, ...) are compared as text (line
ends normalised) with a unified-diff excerpt; ``.png`` storyboards only by
image size, because their pixels depend on the FreeType version that drew
the lettering, which is exactly the weakness of pixel goldens we avoid.

Byte-identical files are equal without being parsed, so a clean run costs
little more than reading both trees; only two files are held at a time.

>>> import tempfile, pathlib
>>> root = pathlib.Path(tempfile.mkdtemp())
>>> svg = ('<svg xmlns="http://www.w3.org/2000/svg"><g class="step" data-step="1"><circle id="s0001-O" r="1"/></g>'
...        '<g class="step" data-step="3"><circle id="s0003-P" cx="{}" cy="2" r="1"/></g></svg>')
>>> def build(out):
...     (out / "demo").mkdir(parents=True)
...     _ = (out / "demo" / "final.svg").write_text(svg.format("1.5"))
>>> build(root / "golden")
>>> verify(root / "golden", builder=build).equal
True
>>> _ = (root / "golden" / "demo" / "final.svg").write_text(svg.format("1.51"))
>>> print(verify(root / "golden", builder=build).report())
demo step 3 (demo/final.svg): 1 change
  moved      s0003-P (circle, matched by id): by 0.01: centre (1.51, 2) -> (1.5, 2)
construct verify: 1 of 1 files differ (1 changed, 0 missing, 0 extra) in 1 figure; ...
"""

from __future__ import annotations

import difflib
import filecmp
import os
import re
import shutil
import struct
import tempfile
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import Any, Callable

from ..kernel.errors import ConstructError, InvalidParameter
from .change import Change

__all__ = ["DEFAULT_TOLERANCE", "PROTOCOL_TOLERANCE", "FileDifference", "VerifyResult", "VerifyInputError",
           "compare_trees", "compare_file", "compare_file_by_step", "locate", "verify", "default_builder"]

DEFAULT_TOLERANCE = 0.004
"""Drawing units (SVG user units) for frames.

The renderer writes coordinates with a fixed number of decimals (two: a
quantum of 0.01).  The issue's smallest change to catch is one point moved
by 0.01, whose difference read back from text may be 0.00999...; so the
tolerance must stay well below that: 0.004 is under half of it.  It is far
above the float noise of reading respelled numbers and applying transforms
(~1e-12), so ``1.50`` against ``1.5e0`` is equal, and above a last-digit
rounding flip of a three-decimal writer (sqrt(2) * 0.001 for a point).  A
one-quantum flip of the two-decimal renderer between machines is *not*
forgiven: the renderer's determinism must prevent it (test_determinism.py).
"""

PROTOCOL_TOLERANCE = 1e-9
"""Construction units for ``protocol.json``: it stores full-precision floats of
a deterministic replay, so only float noise (~1e-15 relative) is forgiven."""

MAX_CHANGES = 20
"""Changes listed per file in a report; the rest are counted."""

KEPT_CHANGES = 200
"""Change lines kept per file (the count is always exact): a wholly different
gallery must not fill the memory with descriptions nobody reads."""

_STEP_FILE = re.compile(r"^(\d+)\.svg$")
_IGNORED_PREFIX = ".construct-"  # staging folders and failure pages: never goldens


class VerifyInputError(InvalidParameter):
    """The gallery folder is missing, not a folder, or the rebuild wrote nothing usable."""


@dataclass(frozen=True)
class FileDifference:
    """One file that differs: where it is, what kind of difference, its changes.

    The changes are those of the file's diff (:class:`~construct.regress.change.Change`, as
    ``construct diff`` reports them); a text file adds an *excerpt* of its unified diff.
    """

    path: str  # relative, with forward slashes
    status: str  # "changed", "missing" (only in the goldens) or "extra" (only in the rebuild)
    kind: str  # "svg", "protocol", "text", "png", "binary"
    changes: tuple[Change, ...] = ()  # each naming the element, object, step or lines it concerns
    total: int = 0  # number of changes (may exceed len(changes): at most KEPT_CHANGES are kept)
    at_step: int | None = None  # the step group of a layered figure the changes are in
    excerpt: tuple[str, ...] = ()  # a text file's unified-diff lines, printed after its changes

    @property
    def figure(self) -> str:
        return locate(self.path)[0]

    @property
    def step(self) -> int | None:
        return self.at_step if self.at_step is not None else locate(self.path)[1]

    def headline(self) -> str:
        figure, step = self.figure, self.step
        where = f"{figure} step {step}" if step is not None else f"{figure} {PurePosixPath(self.path).name}"
        if self.status == "missing":
            return f"{where} ({self.path}): missing: in the goldens, not written by the rebuild"
        if self.status == "extra":
            return f"{where} ({self.path}): extra: written by the rebuild, not in the goldens"
        n = self.total
        return f"{where} ({self.path}): {n} change{'s' if n != 1 else ''}"

    def lines(self) -> list[str]:
        """The report lines under the headline: one per change, then the excerpt."""
        return [c.line() for c in self.changes] + list(self.excerpt)

    def report(self, max_changes: int = MAX_CHANGES) -> str:
        shown = self.lines()
        lines = [self.headline()] + shown[:max_changes]
        hidden = self.total - min(len(shown), max_changes)
        if self.status == "changed" and hidden > 0:
            lines.append(f"  ... and {hidden} more")
        return "\n".join(lines)


@dataclass(frozen=True)
class VerifyResult:
    """What ``construct verify`` found (and, with ``update``, rewrote)."""

    gallery: str
    compared: int  # files present on both sides or on one
    differences: tuple[FileDifference, ...]
    tolerance: float
    png_by_size: int = 0
    updated: bool = False

    @property
    def equal(self) -> bool:
        return not self.differences

    def summary(self) -> str:
        d = self.differences
        # a layered figure gives one difference per step: files are counted once
        status = {f.path: f.status for f in d}
        counts = {s: sum(1 for v in status.values() if v == s) for s in ("changed", "missing", "extra")}
        figures = sorted({f.figure for f in d})
        head = "construct verify: "
        if not d:
            head += f"all {self.compared} files equal"
        else:
            head += (f"{len(status)} of {self.compared} files differ ({counts['changed']} changed, "
                     f"{counts['missing']} missing, {counts['extra']} extra) in {len(figures)} "
                     f"figure{'s' if len(figures) != 1 else ''}")
        head += (f"; tolerance {self.tolerance:g} drawing units for SVG, {PROTOCOL_TOLERANCE:g} for protocols")
        if self.png_by_size:
            head += f"; {self.png_by_size} PNG compared by image size only (pixels depend on FreeType)"
        if self.updated:
            head += f"; goldens in {self.gallery} rewritten" if d else f"; goldens in {self.gallery} already current"
        return head

    def report(self, max_changes: int = MAX_CHANGES) -> str:
        return "\n".join([f.report(max_changes) for f in self.differences] + [self.summary()])


# --------------------------------------------------------------------------- locating


def locate(path: str) -> tuple[str, int | None]:
    """The figure (its folder) and the step number of a gallery file.

    >>> locate("crank-k5/teaching/steps/012.svg")
    ('crank-k5/teaching', 12)
    >>> locate("crank-k5/final.svg"), locate("index.html")
    (('crank-k5', None), ('(gallery)', None))
    """
    p = PurePosixPath(path)
    parent = p.parent
    m = _STEP_FILE.match(p.name)
    if m and parent.name == "steps":
        folder = str(parent.parent)
        return (folder if folder != "." else "(gallery)"), int(m.group(1))
    return (str(parent) if str(parent) != "." else "(gallery)"), None


def _files(root: Path) -> list[str]:
    """Relative paths of the files under *root*, sorted, skipping our staging leftovers."""
    out: list[str] = []
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if not d.startswith(_IGNORED_PREFIX))
        rel = Path(dirpath).relative_to(root)
        out += [(rel / f).as_posix() for f in filenames if not f.startswith(_IGNORED_PREFIX)]
    return sorted(out)


# --------------------------------------------------------------------------- comparing


def _kind(path: str) -> str:
    name = PurePosixPath(path).name.lower()
    if name.endswith(".svg"):
        return "svg"
    if name == "protocol.json":
        return "protocol"
    if name.endswith(".png"):
        return "png"
    if name.endswith(".tikz"):
        return "tikz"
    return "text"


#: The largest golden read, by kind: a drawing (a 3600-part replay's final.svg is a few MB, a
#: million-element drawing about 80 MB) and any other file (the largest text golden is under 1 MB).
#: A golden that is a pipe, a device or a link to one is refused before it is opened.
MAX_GOLDEN_BYTES = {"svg": 320 * 2**20, "protocol": 64 * 2**20, "png": 64 * 2**20, "text": 64 * 2**20,
                    "tikz": 64 * 2**20}


def _check_readable(path: Path, kind: str) -> None:
    """*path* is a regular file within its kind's limit, else VerifyInputError naming it (nothing is read)."""
    from ..io.reading import open_regular_file

    with open_regular_file(path, limit=MAX_GOLDEN_BYTES[kind], what="golden" if kind != "svg" else "drawing",
                           error=VerifyInputError):
        pass


def png_size(path: Path) -> tuple[int, int] | None:
    """Width and height from a PNG header, or None when it is not a PNG."""
    from ..io.reading import open_regular_file

    with open_regular_file(path, limit=MAX_GOLDEN_BYTES["png"], what="image", error=VerifyInputError) as (fd, _):
        head = os.read(fd, 24)
    if len(head) < 24 or head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        return None
    w, h = struct.unpack(">II", head[16:24])
    return int(w), int(h)


def _read_text(path: Path) -> str | None:
    from ..io.reading import read_regular_file

    data = read_regular_file(path, limit=MAX_GOLDEN_BYTES["text"], what="golden", error=VerifyInputError)
    try:
        return data.decode("utf-8").replace("\r\n", "\n")
    except UnicodeDecodeError:
        return None


def _clip(line: str, width: int = 160) -> str:
    line = line.rstrip("\n")
    return line if len(line) <= width else line[:width] + f"... ({len(line)} chars)"


def _text_changes(rel: str, golden: Path, actual: Path) -> FileDifference | None:
    a, b = _read_text(golden), _read_text(actual)
    if a is None or b is None:
        size = f"{golden.stat().st_size} -> {actual.stat().st_size} bytes"
        return FileDifference(rel, "changed", "binary", (Change("bytes", "", f"content differs ({size})"),), 1)
    if a == b:
        return None  # only the line ends differed
    la, lb = a.splitlines(keepends=True), b.splitlines(keepends=True)
    matcher = difflib.SequenceMatcher(None, la, lb, autojunk=False)
    blocks = [op for op in matcher.get_opcodes() if op[0] != "equal"]
    excerpt = list(difflib.unified_diff(la, lb, "golden/" + rel, "rebuilt/" + rel, n=1))
    changes = tuple(Change("text", f"lines {i1 + 1}-{max(i1 + 1, i2)}", f"{op} ({i2 - i1} -> {j2 - j1} lines)")
                    for op, i1, i2, j1, j2 in blocks[:3])
    lines = ["    " + _clip(x) for x in excerpt[2:14]]
    if len(excerpt) > 14:
        lines.append(f"    ... ({len(excerpt) - 14} more diff lines)")
    return FileDifference(rel, "changed", "text", changes, len(blocks), excerpt=tuple(lines))


def compare_file(rel: str, golden: Path, actual: Path, *, tolerance: float = DEFAULT_TOLERANCE
                 ) -> FileDifference | None:
    """The difference between a golden file and its rebuilt twin, or None when equal (all steps in one)."""
    found = compare_file_by_step(rel, golden, actual, tolerance=tolerance)
    if not found:
        return None
    if len(found) == 1:
        return found[0]
    changes = tuple(c for d in found for c in d.changes)
    return FileDifference(rel, "changed", found[0].kind, changes[:KEPT_CHANGES], sum(d.total for d in found))


def compare_file_by_step(rel: str, golden: Path, actual: Path, *, tolerance: float = DEFAULT_TOLERANCE
                         ) -> list[FileDifference]:
    """The differences between a golden file and its rebuilt twin: for a layered figure one per step."""
    kind = _kind(rel)
    for path in (golden, actual):  # a pipe would block the comparison, /dev/zero would never end it
        _check_readable(path, kind)
    if filecmp.cmp(golden, actual, shallow=False):
        return []  # byte-identical: the common case, nothing to parse
    if kind == "svg":
        from .svgdiff import diff_svg

        d = diff_svg(golden, actual, tolerance=tolerance)
        if d.equal:
            return []
        if locate(rel)[1] is not None:
            # a standalone frame: every change is a change of that frame's step
            groups: dict[int | None, list] = {None: list(d.changes)}
        else:
            groups = d.by_step()
        return [FileDifference(rel, "changed", "svg", tuple(changes[:KEPT_CHANGES]), len(changes), at_step=step)
                for step, changes in groups.items()]
    if kind == "protocol":
        from .testing import figures_diff  # what construct.testing.assert_figures_equal compares

        p = figures_diff(golden, actual, tolerance=PROTOCOL_TOLERANCE)
        if p.equal:
            return []
        return [FileDifference(rel, "changed", "protocol", p.changes[:KEPT_CHANGES], len(p.changes))]
    if kind == "tikz":
        from .printdiff import diff_tikz

        t = diff_tikz(golden, actual)
        return [] if t.equal else [FileDifference(rel, "changed", "tikz", t.changes[:KEPT_CHANGES], len(t.changes))]
    if kind == "png":
        sa, sb = png_size(golden), png_size(actual)
        if sa == sb and sa is not None:
            return []  # pixels are not compared: see the module docstring
        show = lambda s: "not a PNG" if s is None else f"{s[0]}x{s[1]}"  # noqa: E731
        return [FileDifference(rel, "changed", "png", (Change("size", "", f"image {show(sa)} -> {show(sb)}"),), 1)]
    found = _text_changes(rel, golden, actual)
    return [found] if found is not None else []


def compare_trees(golden: Path, actual: Path, *, tolerance: float = DEFAULT_TOLERANCE,
                  progress: Callable[[int, int], None] | None = None
                  ) -> tuple[list[FileDifference], int, int]:
    """The differing files in path order, the number of files seen, and how many PNGs were compared."""
    a, b = _files(golden), _files(actual)
    in_a, in_b = set(a), set(b)
    names = sorted(in_a | in_b)
    del a, b
    diffs: list[FileDifference] = []
    pngs = 0
    for i, rel in enumerate(names):
        if progress:
            progress(i + 1, len(names))
        if rel not in in_b:
            diffs.append(FileDifference(rel, "missing", _kind(rel)))
        elif rel not in in_a:
            diffs.append(FileDifference(rel, "extra", _kind(rel)))
        else:
            pngs += _kind(rel) == "png"
            try:
                diffs += compare_file_by_step(rel, golden / rel, actual / rel, tolerance=tolerance)
            except ConstructError as exc:  # an unreadable golden is a difference, not a crash
                from .svgdiff import SvgTooLargeError

                if isinstance(exc, SvgTooLargeError):
                    raise  # but a drawing past the reader's bounds (an expansion bomb) refuses the run
                diffs.append(FileDifference(rel, "changed", _kind(rel), (Change("unreadable", "", str(exc)),), 1))
    return diffs, len(names), pngs


# --------------------------------------------------------------------------- the whole run


def default_builder(out: Path) -> Any:
    """Build the gallery the way ``construct gallery`` does (imported only when needed)."""
    try:
        from ..gallery import build_gallery
    except ModuleNotFoundError as exc:
        if exc.name != f"{__package__}.gallery":
            raise
        raise VerifyInputError("this version of construct has no gallery builder (construct.gallery)") from None
    return build_gallery(out, progress=False)


def _progress_printer(stream: Any) -> Callable[[int, int], None] | None:
    if not (hasattr(stream, "isatty") and stream.isatty()):
        return None

    def show(i: int, n: int) -> None:
        if i == n or i % 50 == 0:
            stream.write(f"\rconstruct verify: compared {i}/{n} files")
            if i == n:
                stream.write("\n")
            stream.flush()

    return show


def verify(gallery: str | os.PathLike[str], *, update: bool = False,
           builder: Callable[[Path], Any] | None = None, tolerance: float = DEFAULT_TOLERANCE,
           progress_stream: Any = None) -> VerifyResult:
    """Rebuild the gallery in a temporary folder and compare it with the goldens in *gallery*.

    *builder(out)* writes a whole gallery into the folder *out* (default: the
    real gallery).  With *update*, the goldens are replaced by the rebuilt
    tree as a whole folder (staged, then swapped), and the result says what
    changed.  A missing *gallery* is bad input unless *update* creates it.
    """
    if not (isinstance(tolerance, (int, float)) and tolerance >= 0 and tolerance != float("inf")):
        raise InvalidParameter(f"tolerance must be a finite number >= 0, got {tolerance!r}")
    if os.fspath(gallery) == "":
        raise VerifyInputError("the gallery folder is an empty path; name a folder ('.' for the current one)")
    gallery = Path(gallery)
    try:
        gallery.stat()
        exists = True
    except (FileNotFoundError, NotADirectoryError):
        exists = False
    except OSError as exc:  # a name too long, a folder that cannot be entered
        raise VerifyInputError(f"cannot read gallery folder {str(gallery)!r}: {exc.strerror or exc}") from None
    if exists and not gallery.is_dir():
        raise VerifyInputError(f"gallery {str(gallery)!r} is not a folder")
    if not exists and not update:
        raise VerifyInputError(f"gallery folder {str(gallery)!r} does not exist; "
                               f"create the goldens with 'construct verify --gallery {gallery} --update'")
    build = builder or default_builder
    show = _progress_printer(progress_stream)
    with tempfile.TemporaryDirectory(prefix="construct-verify-") as tmp:
        rebuilt = Path(tmp) / "gallery"
        if show:
            progress_stream.write("construct verify: rebuilding the gallery\n")
        build(rebuilt)
        if not rebuilt.is_dir():
            raise VerifyInputError("the gallery builder wrote no folder")
        golden_side = gallery if gallery.is_dir() else Path(tmp) / "empty"
        golden_side.mkdir(exist_ok=True)
        diffs, files, pngs = compare_trees(golden_side, rebuilt, tolerance=tolerance, progress=show)
        if update and (diffs or not gallery.exists()):
            _replace_tree(gallery, rebuilt)
    return VerifyResult(str(gallery), files, tuple(diffs), float(tolerance), pngs, update)


def _replace_tree(gallery: Path, rebuilt: Path) -> None:
    """Swap the rebuilt tree in for the goldens as one folder (nothing half-written).

    Only goldens are replaced: a folder whose every file is listed, unchanged,
    in the gallery manifest (:mod:`construct.io.manifest`) that ``construct
    gallery`` and this update write; anything else is refused and listed,
    its files are not ours.  The new goldens get their manifest.
    """
    from ..io.manifest import replaced_with_manifest

    with replaced_with_manifest(gallery, "gallery", what="gallery folder",
                         described="a gallery of goldens written by 'construct gallery' or 'construct verify "
                                   "--update' (recognised by its .construct-manifest.json)") as new:
        shutil.copytree(rebuilt, new, symlinks=True)
