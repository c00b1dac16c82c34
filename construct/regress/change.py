"""What changed between two drawings, protocols or gallery files: a :class:`Diff` of :class:`Change` s.

The SVG diff (:func:`construct.regress.svgdiff.diff_svg`), the protocol diff
(:func:`construct.regress.protocoldiff.diff_protocol`) and ``construct
verify`` all say what they found in these two types, so a change reads, prints
and serialises the same way whichever comparison found it.

>>> moved = Change("moved", "P", "by 0.01: centre (1.5, 2) -> (1.51, 2)", 0.01, shape="circle", matched_by="id",
...                step=3)
>>> print(moved.line())
  moved      P (circle, matched by id): by 0.01: centre (1.5, 2) -> (1.51, 2)
>>> d = Diff("svg", "a.svg", "b.svg", 1e-6, (moved,), "elements", (2, 2))
>>> print(d.report())
SVG diff a.svg -> b.svg (tolerance 1e-06): 1 change
  moved      P (circle, matched by id): by 0.01: centre (1.5, 2) -> (1.51, 2)
>>> d.equal, d.elements, list(d.by_step())
(False, (2, 2), [3])
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Iterator

__all__ = ["Change", "Diff"]

#: How a report heads a diff of each subject.
TITLES = {"svg": "SVG", "protocol": "protocol", "tikz": "TikZ", "pdf": "PDF"}


@dataclass(frozen=True, slots=True)
class Change:
    """One difference: what happened (*kind*), to what (*key*), and before -> after in words (*description*).

    *magnitude* is its size where it has one (a distance in drawing or construction
    units, a count of steps).  An SVG change also names the element's *shape*, how
    the two sides were paired (*matched_by*: id, key, order or geometry) and the
    element's key in B when it differs (*key_b*).  *step* is the construction step
    the change belongs to (the step group of a layered figure, the step of a
    protocol), None where there is none.
    """

    kind: str
    key: str
    description: str
    magnitude: float | None = None
    shape: str = ""
    matched_by: str = ""
    key_b: str | None = None
    step: int | None = None

    def line(self) -> str:
        """The change as one report line: kind, what it concerns, description.

        >>> print(Change("size", "", "image 8x5 -> 8x4").line())
          size       image 8x5 -> 8x4
        """
        if not self.key:
            return f"  {self.kind:<10} {self.description}"
        how = []
        if self.shape:
            how.append(self.shape)
        if self.matched_by:
            how.append(f"matched by {self.matched_by}")
        name = self.key if self.key_b in (None, self.key) else f"{self.key} -> {self.key_b}"
        where = f"{name} ({', '.join(how)})" if how else name
        return f"  {self.kind:<10} {where}: {self.description}"

    def as_dict(self) -> dict[str, Any]:
        """Plain data for JSON (every field, whichever diff made the change)."""
        return {"kind": self.kind, "key": self.key, "key_b": self.key_b, "shape": self.shape,
                "matched_by": self.matched_by, "step": self.step, "description": self.description,
                "magnitude": self.magnitude}


@dataclass(frozen=True, slots=True)
class Diff:
    """The differences between A and B, in a fixed order, with what each side holds.

    *subject* says what was compared (``"svg"``, ``"protocol"``); *counted* what
    *sizes* counts on each side (``"elements"``, ``"steps"``); *instruments*, for
    protocols, the uses of each instrument on each side as ``(tool, in A, in B)``.
    """

    subject: str
    a: str
    b: str
    tolerance: float
    changes: tuple[Change, ...]
    counted: str
    sizes: tuple[int, int]
    instruments: tuple[tuple[str, int, int], ...] = ()

    @property
    def equal(self) -> bool:
        """Do A and B agree within the tolerance?"""
        return not self.changes

    @property
    def elements(self) -> tuple[int, int]:
        """The drawn elements of A and B (an SVG diff)."""
        return self._count("elements")

    @property
    def steps(self) -> tuple[int, int]:
        """The steps of A and B (a protocol diff)."""
        return self._count("steps")

    def _count(self, what: str) -> tuple[int, int]:
        if self.counted != what:
            raise AttributeError(f"a diff of {self.subject} counts {self.counted}, not {what}")
        return self.sizes

    @property
    def method_changed(self) -> bool:
        """Did the number of steps or of uses of some instrument change (a protocol diff)?"""
        return self.sizes[0] != self.sizes[1] or any(x != y for _, x, y in self.instruments)

    def by_step(self) -> dict[int | None, list[Change]]:
        """The changes gathered by their step, those outside any step (None) first, then by step number."""
        out: dict[int | None, list[Change]] = {}
        for c in self.changes:
            out.setdefault(c.step, []).append(c)
        return dict(sorted(out.items(), key=lambda kv: (kv[0] is not None, kv[0] or 0)))

    def of_kind(self, kind: str) -> Iterator[Change]:
        """The changes of one kind, in report order."""
        return (c for c in self.changes if c.kind == kind)

    def report(self) -> str:
        """Readable text: a head line, then one line per change."""
        head = (f"{TITLES.get(self.subject, self.subject)} diff {self.a} -> {self.b} "
                f"(tolerance {format(self.tolerance, '.3g')}): ")
        if self.equal:
            n = self.sizes[0]
            tools = f"; {', '.join(f'{t} {x}' for t, x, _ in self.instruments)}" if self.instruments else ""
            return head + f"equal ({n} {self.counted if n != 1 else self.counted[:-1]}{tools})"
        n = len(self.changes)
        return "\n".join([head + f"{n} change{'s' if n != 1 else ''}"] + [c.line() for c in self.changes])

    def as_dict(self) -> dict[str, Any]:
        """Plain data for JSON: ``kind`` (the subject), the sides, the counts, the changes."""
        out: dict[str, Any] = {"kind": self.subject, "a": self.a, "b": self.b, "tolerance": self.tolerance,
                               "equal": self.equal, self.counted: {"a": self.sizes[0], "b": self.sizes[1]}}
        if self.subject == "protocol":
            out["instruments"] = {t: {"a": x, "b": y} for t, x, y in self.instruments}
            out["method_changed"] = self.method_changed
        out["changes"] = [c.as_dict() for c in self.changes]
        return out
