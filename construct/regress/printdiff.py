"""What changed between two printed plates, by named point: two TikZ pictures or two PDFs written by construct.

A TikZ plate names every lettered point (``\\coordinate (X4) at (0.61803,0);`` or tkz-euclide's
``\\tkzDefPoint(0.61803,0){X4}``, in units of
``x=27.77594mm``) and a PDF plate makes each a named destination at its place on the page
(:mod:`construct.render.pdf`): both are read as {name: (x, y) in millimetres on the page}, and
:func:`diff_points` reports each point moved, added or removed.  A TikZ picture's other lines
(its marks, letters and furniture) are compared too, number by number within the tolerance, and
a line that differs is named by its number; a PDF's pages are compared by their size.  A file
that names no point (a PDF from elsewhere) cannot be compared so, and :class:`PrintDiffError`
says it plainly.

>>> a = "\\\\begin{tikzpicture}[x=10mm,\\n\\\\coordinate (A) at (0,0);\\n\\\\coordinate (B) at (1,0);\\n"
>>> print(diff_tikz_text(a, a.replace("(1,0)", "(1.01,0)"), "a", "b").report())
TikZ diff a -> b (tolerance 0.001): 1 change
  moved      B (point, matched by name): by 0.1 mm: (10, 0) -> (10.1, 0) mm
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from ..kernel.errors import ConstructError, MissingDependency
from .change import Change, Diff

__all__ = ["diff_tikz", "diff_tikz_text", "diff_pdf", "diff_points", "tikz_points", "pdf_points", "PrintDiffError",
           "TOLERANCE_MM"]

#: Millimetres on the page: a TikZ plate writes its coordinates to 0.001 mm, a PDF its destinations to 0.001 pt.
TOLERANCE_MM = 0.001
#: The largest TikZ picture or PDF read (a 3600-part crank's picture is a few MB).
MAX_BYTES = 64 * 2**20

_UNIT = re.compile(r"\\begin\{tikzpicture\}\[x=([0-9.]+)mm")
_COORDINATE = re.compile(r"^(?:\\coordinate \(([^)]+)\) at \(([-0-9.]+),([-0-9.]+)\);"
                         r"|\\tkzDefPoint\(([-0-9.]+),([-0-9.]+)\)\{([^}]+)\})$", re.M)
_NUMBER = re.compile(r"-?[0-9]+(?:\.[0-9]+)?")
#: Lines of a TikZ picture compared at most (the rest are counted).
SHOWN_LINES = 20


class PrintDiffError(ConstructError, ValueError):
    """A TikZ picture or PDF cannot be compared by named point (it names none, or is not one construct wrote)."""


def tikz_points(text: str, where: str = "the picture") -> tuple[float, dict[str, tuple[float, float]]]:
    """(millimetres per unit, {name: (x, y) mm}) of a TikZ plate's named coordinates."""
    unit = _UNIT.search(text)
    if unit is None:
        raise PrintDiffError(f"{where} is no TikZ plate written by construct (no tikzpicture with x=...mm): "
                             f"it cannot be compared by named point")
    mm = float(unit.group(1))
    out = {}
    for m in _COORDINATE.finditer(text):  # \coordinate (NAME) at (x,y); or \tkzDefPoint(x,y){NAME}
        name, x, y = (m[1], m[2], m[3]) if m[1] else (m[6], m[4], m[5])
        out[name] = (float(x) * mm, float(y) * mm)
    return mm, out


def pdf_points(path: Path) -> tuple[tuple[float, float], dict[str, tuple[float, float]]]:
    """((width, height) of its page in mm, {name: (x, y) mm from the page's foot}) of a PDF's named destinations."""
    try:
        import pypdf
    except ImportError:
        raise MissingDependency("comparing PDFs needs pypdf; install it with pip install 'construct-steam[pdf]'") \
            from None
    try:
        reader = pypdf.PdfReader(str(path))
        box = reader.pages[0].mediabox
        dests = reader.named_destinations
    except Exception as exc:  # pypdf's errors for a file that is no PDF are many; each is this one complaint
        raise PrintDiffError(f"{str(path)!r} cannot be read as a PDF ({type(exc).__name__}: {exc})") from None
    mm = 25.4 / 72.0
    points = {}
    for name, d in dests.items():
        left, top = d.get("/Left"), d.get("/Top")
        if left is not None and top is not None:
            points[str(name)] = (float(left) * mm, float(top) * mm)
    return (float(box.width) * mm, float(box.height) * mm), points


def _mm(v: float) -> str:
    return f"{v:.3f}".rstrip("0").rstrip(".")


def diff_points(a: dict[str, tuple[float, float]], b: dict[str, tuple[float, float]],
                tolerance: float = TOLERANCE_MM) -> list[Change]:
    """Each named point moved by more than *tolerance* (mm), removed from A or added in B, in A's order."""
    out = []
    for name, (x, y) in a.items():
        if name not in b:
            out.append(Change("removed", name, f"at ({_mm(x)}, {_mm(y)}) mm", shape="point", matched_by="name"))
            continue
        u, v = b[name]
        d = math.hypot(u - x, v - y)
        if d > tolerance:
            out.append(Change("moved", name, f"by {_mm(d)} mm: ({_mm(x)}, {_mm(y)}) -> ({_mm(u)}, {_mm(v)}) mm", d,
                              shape="point", matched_by="name"))
    out += [Change("added", name, f"at ({_mm(u)}, {_mm(v)}) mm", shape="point", matched_by="name")
            for name, (u, v) in b.items() if name not in a]
    return out


def _read(path: Path, what: str) -> bytes:
    from ..io.reading import open_regular_file

    with open_regular_file(path, limit=MAX_BYTES, what=what, error=PrintDiffError):
        pass
    return Path(path).read_bytes()


def diff_tikz(a: Path, b: Path, *, tolerance: float = TOLERANCE_MM) -> Diff:
    """Two TikZ plates compared by named point, and line by line (numbers within *tolerance* mm)."""
    ta, tb = (_read(p, "TikZ picture").decode("utf-8", errors="replace") for p in (a, b))
    return diff_tikz_text(ta, tb, str(a), str(b), tolerance=tolerance)


def diff_tikz_text(ta: str, tb: str, a: str, b: str, *, tolerance: float = TOLERANCE_MM) -> Diff:
    """:func:`diff_tikz` of two pictures' text (*a*, *b* name them)."""
    mm_a, pa = tikz_points(ta, a)
    mm_b, pb = tikz_points(tb, b)
    if not pa and not pb:
        raise PrintDiffError(f"neither {a} nor {b} names a point: they cannot be compared by named point")
    changes = diff_points(pa, pb, tolerance)
    if not math.isclose(mm_a, mm_b, rel_tol=1e-9):
        changes.append(Change("scale", "", f"1 unit = {mm_a:g} mm -> {mm_b:g} mm"))
    # the other lines: the same words, and numbers within the tolerance (coordinates are in units: mm / unit)
    la = [line for line in ta.splitlines() if not _COORDINATE.match(line)]
    lb = [line for line in tb.splitlines() if not _COORDINATE.match(line)]
    differing = [i for i, (x, y) in enumerate(zip(la, lb), start=1) if not _same_line(x, y, tolerance / mm_a)]
    if len(la) != len(lb):
        changes.append(Change("lines", "", f"{len(la)} lines besides the named points -> {len(lb)}"))
    for i in differing[:SHOWN_LINES]:
        changes.append(Change("changed", f"line {i}", f"{_brief(la[i - 1])} -> {_brief(lb[i - 1])}"))
    if len(differing) > SHOWN_LINES:
        changes.append(Change("changed", "", f"{len(differing) - SHOWN_LINES} more lines"))
    return Diff("tikz", a, b, tolerance, tuple(changes), "points", (len(pa), len(pb)))


def _same_line(x: str, y: str, tolerance: float) -> bool:
    if x == y:
        return True
    if _NUMBER.sub("#", x) != _NUMBER.sub("#", y):
        return False
    return all(abs(float(p) - float(q)) <= tolerance for p, q in zip(_NUMBER.findall(x), _NUMBER.findall(y)))


def _brief(line: str, limit: int = 70) -> str:
    line = line.strip()
    return line if len(line) <= limit else line[:limit - 1] + "…"


def diff_pdf(a: Path, b: Path, *, tolerance: float = TOLERANCE_MM) -> Diff:
    """Two PDF plates compared by their named points (and their page's size)."""
    for p in (a, b):
        _read(p, "PDF")
    (size_a, pa), (size_b, pb) = pdf_points(a), pdf_points(b)
    if not pa or not pb:
        none = ", ".join(str(p) for p, pts in ((a, pa), (b, pb)) if not pts)
        raise PrintDiffError(f"{none} names no point (a PDF construct did not write, or one of an older version): "
                             f"the PDFs cannot be compared by named point; compare their SVG plates instead")
    changes = diff_points(pa, pb, tolerance)
    if any(abs(p - q) > tolerance for p, q in zip(size_a, size_b)):
        changes.insert(0, Change("page", "", f"{_mm(size_a[0])} x {_mm(size_a[1])} mm -> "
                                             f"{_mm(size_b[0])} x {_mm(size_b[1])} mm"))
    return Diff("pdf", str(a), str(b), tolerance, tuple(changes), "points", (len(pa), len(pb)))


def file_kind(head: bytes) -> str | None:
    """``"pdf"`` or ``"tikz"`` by a file's first bytes, else None."""
    if head.startswith(b"%PDF-"):
        return "pdf"
    if head.startswith((b"%", b"\\")):
        return "tikz"
    return None

