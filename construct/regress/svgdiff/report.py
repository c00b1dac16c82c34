"""The differences of two drawings: each matched pair compared, the unmatched ones named.

Part of :mod:`construct.regress.svgdiff`; the result is a :class:`~construct.regress.change.Diff`.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Iterator

from ...kernel.errors import InvalidParameter
from ..change import Change, Diff
from .values import DEFAULT_TOLERANCE, format_magnitude, format_number, numeric_difference, show_value, values_close
from .geometry import Point
from .css import INITIAL
from .parse import Drawing, Shape, parse_svg
from .source import source_label
from .match import bounding_box, drawing_extent, match_shapes

# --------------------------------------------------------------------------- the diff

CHANGE_KINDS = ("document", "definition", "missing", "extra", "renamed", "restepped", "reshaped", "moved",
                "resized", "rotated", "text", "restyled", "animated", "described")


def diff_svg(a: str | Path | bytes, b: str | Path | bytes, tolerance: float = DEFAULT_TOLERANCE) -> Diff:
    """Compare two SVG drawings; differences at or below *tolerance* (drawing units) are equal."""
    if not (isinstance(tolerance, (int, float)) and math.isfinite(tolerance) and tolerance >= 0):
        raise InvalidParameter(f"diff_svg: tolerance must be a finite number >= 0, got {tolerance!r}")
    tol = float(tolerance)
    da, db = parse_svg(a), parse_svg(b)
    return diff_drawings(da, db, tol, source_label(a), source_label(b))


def diff_drawings(da: Drawing, db: Drawing, tol: float, name_a: str, name_b: str) -> Diff:
    """The diff of two parsed drawings (what :func:`diff_svg` does after reading them)."""
    changes = _document_changes(da, db, tol) + _definition_changes(da, db, tol)
    pairs = match_shapes(da.shapes, db.shapes, tol, max(drawing_extent(da), drawing_extent(db)))
    by_a = {id(sa): (sb, how) for sa, sb, how in pairs}
    matched_b = {id(sb) for _, sb, _ in pairs}
    looks: dict[tuple[int, int], tuple[tuple[str, ...], tuple[float, ...]]] = {}
    for sa in da.shapes:
        if id(sa) in by_a:
            sb, how = by_a[id(sa)]
            changes += _compare(sa, sb, tol, how, looks)
        else:
            changes.append(Change("missing", sa.key, f"{sa.kind} only in A{_where(sa)}", None, sa.kind,
                                  step=sa.step))
    for sb in db.shapes:
        if id(sb) not in matched_b:
            changes.append(Change("extra", sb.key, f"{sb.kind} only in B{_where(sb)}", None, sb.kind,
                                  step=sb.step))
    return Diff("svg", name_a, name_b, tol, tuple(changes), "elements", (len(da.shapes), len(db.shapes)))


def _where(s: Shape) -> str:
    if s.points:
        return f" at {raw_point(s.points[0][1])}"
    return ""


def raw_point(p: Point) -> str:
    return f"({format_number(p[0])}, {format_number(p[1])})"


def _document_changes(da: Drawing, db: Drawing, tol: float) -> list[Change]:
    out = []
    a, b = dict(da.document), dict(db.document)
    for prop in sorted(set(a) | set(b)):
        va, vb = a.get(prop), b.get(prop)
        if prop == "stylesheet":
            if va != vb and not values_close(va, vb, tol):
                out.append(Change("document", prop, "style sheet rules changed"))
            continue
        if va is None or vb is None or not values_close(va, vb, tol):
            out.append(Change("document", prop, f"{show_value(va) if va is not None else '(none)'} -> "
                                                f"{show_value(vb) if vb is not None else '(none)'}",
                              numeric_difference(va, vb)))
    return out


def _definition_changes(da: Drawing, db: Drawing, tol: float) -> list[Change]:
    out = []
    a, b = dict(da.definitions), dict(db.definitions)
    for key in sorted(set(a) | set(b)):
        if key not in b:
            out.append(Change("definition", key, f"<{a[key][0]}> only in A"))
        elif key not in a:
            out.append(Change("definition", key, f"<{b[key][0]}> only in B"))
        elif not values_close(a[key], b[key], tol):
            out.append(Change("definition", key, f"<{a[key][0]}> changed"
                              + ("" if a[key][0] == b[key][0] else f" to <{b[key][0]}>"),
                              numeric_difference(a[key], b[key])))
    return out



# -- comparing one pair ----------------------------------------------------------------------------

def _compare(x: Shape, y: Shape, tol: float, how: str,
             looks: dict[tuple[int, int], tuple[tuple[str, ...], tuple[float, ...]]]) -> list[Change]:
    """The changes from *x* to *y*; *looks* remembers the style differences of each pair of looks.

    The parser shares one style tuple among the elements of one look, and both
    drawings keep theirs alive while they are compared: a pair of tuples' ids
    names the pair of looks, compared once however many elements have them.
    """
    out: list[Change] = []
    key_b = y.key if y.key != x.key else None

    def add(kind: str, description: str, magnitude: float | None = None) -> None:
        out.append(Change(kind, x.key, description, magnitude, x.kind, how, key_b,
                          x.step if x.step is not None else y.step))

    if key_b is not None and (x.has_id or y.has_id):
        add("renamed", f"id {x.key!r} -> {y.key!r}")
    if x.step != y.step:
        add("restepped", f"made by step {x.step} -> {y.step}")
    same_structure = (x.kind == y.kind and x.structure == y.structure
                      and [n for n, _ in x.points] == [n for n, _ in y.points]
                      and [n for n, _ in x.sizes] == [n for n, _ in y.sizes])
    if not same_structure:
        if x.kind != y.kind:
            what = f"{x.kind} -> {y.kind}"
        else:
            sa, sb = dict(x.structure), dict(y.structure)
            what = "; ".join(f"{k}: {show_value(sa.get(k, '-'))} -> {show_value(sb.get(k, '-'))}"
                             for k in sorted(set(sa) | set(sb)) if sa.get(k) != sb.get(k)) or "defining points differ"
        ba, bb = bounding_box(x), bounding_box(y)
        add("reshaped", f"{what}; bounding box {raw_point(ba[:2])}..{raw_point(ba[2:])} -> {raw_point(bb[:2])}..{raw_point(bb[2:])}",
            max(abs(u - v) for u, v in zip(ba, bb)) if x.points and y.points else None)
    elif x.points != y.points or x.sizes != y.sizes:  # equal values (or the same NaN) move nothing
        moved = [(math.dist(p, q), name, p, q) for (name, p), (_, q) in zip(x.points, y.points)]
        if any(m[0] > tol for m in moved):
            add("moved", _movement(moved, tol), max(m[0] for m in moved))
        resized = [(abs(u - v), name, u, v) for (name, u), (_, v) in zip(x.sizes, y.sizes) if abs(u - v) > tol]
        if resized:
            d, name, u, v = max(resized, key=lambda m: m[0])
            more = f" ({len(resized)} sizes changed)" if len(resized) > 1 else ""
            add("resized", f"{name} {format_number(u)} -> {format_number(v)} (by {format_magnitude(d)}){more}", d)
    ang_a, ang_b = dict(x.angles), dict(y.angles)
    for name in [] if x.angles == y.angles else [n for n, _ in x.angles if n in ang_b]:  # equal: none turned
        delta = (ang_b[name] - ang_a[name] + 180.0) % 360.0 - 180.0
        if abs(delta) > tol:
            add("rotated", f"{name} {format_number(ang_a[name])} -> {format_number(ang_b[name])} degrees "
                           f"(by {format_magnitude(abs(delta))})",
                abs(delta))
    if x.text != y.text:
        add("text", f"{x.text!r} -> {y.text!r}")
    pair = (id(x.style), id(y.style))
    if pair not in looks:
        looks[pair] = _style_differences(x.style, y.style, tol)
    diffs, mags = looks[pair]
    if diffs:
        add("restyled", "; ".join(diffs), max(mags) if mags else None)
    if not values_close(x.animations, y.animations, tol):
        gone = [a for a in x.animations if not any(values_close(a, b, tol) for b in y.animations)]
        new = [b for b in y.animations if not any(values_close(a, b, tol) for a in x.animations)]
        parts = [f"-<{a[0]} {_anim(a)}>" for a in gone] + [f"+<{b[0]} {_anim(b)}>" for b in new]
        add("animated", "; ".join(parts) or "animation order changed")
    if x.described != y.described:
        da, db = dict(x.described), dict(y.described)
        add("described", "; ".join(f"{k} {da.get(k)!r} -> {db.get(k)!r}" for k in ("title", "desc")
                                   if da.get(k) != db.get(k)))
    return out


def _style_differences(x: tuple[tuple[str, Any], ...], y: tuple[tuple[str, Any], ...], tol: float
                       ) -> tuple[tuple[str, ...], tuple[float, ...]]:
    """What differs between two looks: one line and (where numeric) one magnitude per property."""
    style_a, style_b = dict(x), dict(y)
    diffs, mags = [], []
    for prop in sorted(set(style_a) | set(style_b)):
        va, vb = style_a.get(prop, INITIAL.get(prop)), style_b.get(prop, INITIAL.get(prop))
        if va is None or vb is None or not values_close(va, vb, tol):
            diffs.append(f"{prop} {show_value(va) if va is not None else '(unset)'} -> "
                         f"{show_value(vb) if vb is not None else '(unset)'}")
            nd = numeric_difference(va, vb)
            if nd is not None:
                mags.append(nd)
    return tuple(diffs), tuple(mags)


def _movement(moved: list[tuple[float, str, Point, Point]], tol: float) -> str:
    """Say how far the defining points moved, naming the one that shows it best.

    A centre is named first when it moved as far as any point (a moved arc is
    a moved centre); a rigid translation is reported as such.
    """
    d = max(m[0] for m in moved)
    near_max = [m for m in moved if m[0] >= d - tol]
    _, name, p, q = next((m for m in near_max if m[1].endswith("centre")), near_max[0])
    text = f"by {format_magnitude(d)}: {name} {raw_point(p)} -> {raw_point(q)}"
    if len(moved) > 1:
        shifts = [(m[3][0] - m[2][0], m[3][1] - m[2][1]) for m in moved]
        if all(math.dist(s, shifts[0]) <= tol for s in shifts):
            text += f" (all {len(moved)} points translated by {raw_point(shifts[0])})"
        else:
            text += f" ({sum(m[0] > tol for m in moved)} of {len(moved)} points moved)"
    return text


def _anim(a: tuple) -> str:
    return " ".join(f'{k}="{show_value(v)}"' for k, v in a[1])


def changes_by_step(diff: Diff) -> dict[int | None, list[Change]]:
    """The changes of a layered figure gathered by the step that made each element (None: outside steps).

    The same as :meth:`Diff.by_step <construct.regress.change.Diff.by_step>`.

    >>> a = ('<svg xmlns="http://www.w3.org/2000/svg"><g class="step" data-step="3">'
    ...      '<circle id="s0003-P" cx="1" cy="2" r="1"/></g></svg>')
    >>> {k: [c.key for c in v] for k, v in changes_by_step(diff_svg(a, a.replace('cx="1"', 'cx="2"'))).items()}
    {3: ['s0003-P']}
    """
    return diff.by_step()


def iter_changes(diff: Diff, kind: str) -> Iterator[Change]:
    """The changes of one kind, in report order (:meth:`Diff.of_kind <construct.regress.change.Diff.of_kind>`).

    >>> d = diff_svg('<svg xmlns="http://www.w3.org/2000/svg"/>', '<svg xmlns="http://www.w3.org/2000/svg"><line x2="1"/></svg>')
    >>> [c.key for c in iter_changes(d, "extra")]
    ['line[0]']
    """
    return diff.of_kind(kind)
