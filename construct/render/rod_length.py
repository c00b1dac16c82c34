"""The rod's length written where a figure breaks its rod: a broken rod is drawn short, and the figure says
how long it is ("L = 3,5 r" in the books' notation), beside the first line crossing the break.

Where the words go is chosen once here for the drawing (:class:`construct.render.svg.Drawing`) and read by
the live page (its ``data-rod``), which writes the length there as the given moves.

>>> rod_written({"rod_ratio": 3.5})
'L = 3,5 r'
>>> rod_spots([(1.0, 1.0, 5.0)], [(0.0, 0.0, 3.0, 0.0)], lambda x, y: (x, y), size=10.0)
[(0, 1.5, 0.0, 0.0, -9.0, 'middle')]
"""

from __future__ import annotations

import re
from typing import Any, Callable, Mapping, Sequence

from ..kernel.typography import number
from .lettering import label_box, text_width
from .marks import MarkKind
from .plate import XY, Dimension, Lettering, Piece, crossing_lines, crossings
from .shapes import mark_layer
from .svgdoc import fmt

__all__ = ["rod_written", "writes_rod", "ROD_SPOTS", "rod_spots", "beside_breaks", "rod_box", "clear_spots",
           "rod_at", "rod_group", "rod_pieces"]


def rod_written(givens: Mapping[str, Any]) -> str | None:
    """The rod's length as a figure broken across it writes it at the break, in the books' notation (the decimal
    comma): from the rod ratio (L = 3,5 r), from a rod length beside a crank radius (Tafel I: L = 2 m), or from
    givens L and r; None for a figure without a rod.

    >>> rod_written({"rod_ratio": 3.5}), rod_written({"rod_length": 2.0, "crank_radius": 0.4})
    ('L = 3,5 r', 'L = 2 m')
    >>> rod_written({"r": 1.0, "L": 4.0}), rod_written({"r": 1.0})
    ('L = 4 r', None)
    """
    def real(k: str) -> bool:
        return isinstance(givens.get(k), (int, float)) and not isinstance(givens.get(k), bool)

    if real("rod_ratio"):
        return f"L = {number(givens['rod_ratio'], 'de')} r"
    if real("rod_length") and real("crank_radius"):
        return f"L = {number(givens['rod_length'], 'de')} m"
    if real("L") and real("r") and givens["r"] > 0:
        return f"L = {number(givens['L'] / givens['r'], 'de')} r"
    return None


def writes_rod(items: Sequence[Any]) -> bool:
    """Does the furniture *items* write the rod's length itself (a dimension or a lettering "L = ...": the crank's
    plate dimensions its rod)?  Then a break across the rod needs no word of its own.

    >>> writes_rod([Dimension((0.0, 0.0), (1.0, 0.0), "L = 5 r")]), writes_rod([Lettering((0.0, 0.0), "L = ∞")])
    (True, False)
    """
    return any(isinstance(it, (Dimension, Lettering)) and re.match(r"L\s*=\s*\d", it.text) for it in items)


#: Where the rod's length is written about a break's middle on its line, in letter sizes, first choice first:
#: (x, the baseline's y, anchor), for a break across x (above the line, then below; centred, then ending or
#: starting beside the break) and across y (beside the line).
ROD_SPOTS = {0: ((0.0, -0.9, "middle"), (-0.6, -0.9, "end"), (0.6, -0.9, "start"),
                 (0.0, 1.6, "middle"), (-0.6, 1.6, "end"), (0.6, 1.6, "start")),
             1: ((0.7, 0.35, "start"), (-0.7, 0.35, "end"))}


def rod_spots(breaks: Sequence[tuple], lines: Sequence[tuple[float, float, float, float]],
              px: Callable[[float, float], XY], *, size: float = 12.0,
              clear: "Callable[[float, float, float, float, str], bool] | None" = None) -> list[tuple]:
    """Where the rod's length (:func:`rod_written`) is written at each break of *breaks*: beside the first of
    *lines* crossing it (a broken rod is drawn short, and the figure says how long it is), as (axis, the break's
    middle on that line: x, y, the text's baseline point about it: dx, dy, its anchor), canvas px.  Where no line
    crosses a break (a figure of points alone), *lines* may end with the line joining the points on either side
    of it.  The first of :data:`ROD_SPOTS` *clear* says is clear of the figure is taken (the first without it);
    the page of a live given writes the length there as the given moves (its script's ``breakMarks``).

    >>> rod_spots([(1.0, 1.0, 5.0)], [(0.0, 0.0, 3.0, 0.0)], lambda x, y: (x, y), size=10.0)
    [(0, 1.5, 0.0, 0.0, -9.0, 'middle')]
    """
    out: list[tuple] = []
    done: set[int] = set()
    for axis, _, at in crossings(breaks, lines):
        if axis in done:
            continue
        done.add(axis)
        cx, cy = px(*at)
        spots = [(dx * size, dy * size, anchor) for dx, dy, anchor in ROD_SPOTS[axis]]
        got = next((p for p in spots if clear is None or clear(cx, cy, *p)), spots[0])
        out.append((axis, cx, cy, *got))
    return out


def beside_breaks(breaks: Sequence[tuple], points: Sequence[XY]) -> list[tuple[float, float, float, float]]:
    """Per break of *breaks*, the line joining the nearest of *points* on either side of it (drawing units), where
    it has points on both sides.

    >>> beside_breaks([(1.0, 1.0, 5.0)], [(0.0, 0.0), (-1.0, 2.0), (2.5, 0.0)])
    [(0.0, 0.0, 2.5, 0.0)]
    """
    out = []
    for b in breaks:
        x0, w, axis = b[0], b[1], (b[3] if len(b) > 3 else 0)
        before = [p for p in points if p[axis] <= x0]
        after = [p for p in points if p[axis] >= x0 + w]
        if before and after:
            p, q = max(before, key=lambda p: p[axis]), min(after, key=lambda p: p[axis])
            out.append((*p, *q))
    return out


def rod_box(rod: str | None, x: float, y: float, anchor: str, style: Any) -> tuple[float, float, float, float]:
    """The box (canvas px) of the rod's length *rod* written at baseline point (x, y) with *anchor*."""
    w = text_width(rod or "", style.label_size, style.label_font, style.label_italic)
    return label_box(x + {"start": w / 2, "end": -w / 2}.get(anchor, 0.0), y, rod or "", style.label_size,
                     style.label_font, style.label_italic)


def clear_spots(breaks: Sequence[tuple], lines: Sequence[tuple[float, float, float, float]], rod: str, style: Any,
                px: Callable[[float, float], XY], clear: Callable[[tuple[float, float, float, float]], bool]) -> list:
    """:func:`rod_spots` of *rod* on *lines*, each spot's box (:func:`rod_box`) tried with *clear*."""
    return rod_spots(breaks, lines, px, size=style.label_size,
                     clear=lambda cx, cy, dx, dy, a: clear(rod_box(rod, cx + dx, cy + dy, a, style)))


def rod_at(scene: Any, style: Any, px: Callable[[float, float], XY], *, plate: bool, layers: Sequence[str],
           clear: Callable[[tuple[float, float, float, float]], bool]) -> tuple[str | None, dict[str | None, list]]:
    """The rod's length as *scene* writes it at its breaks (:func:`rod_written`) and where (:func:`rod_spots`):
    over the first line crossing a break in the page's order (by *layers*, then by step), or between the points
    on either side of it (key None); a plate whose furniture dimensions the rod writes nothing more.  *clear*
    says whether a box (canvas px) is clear of the figure's points and result lines."""
    rod = rod_written(scene.params.get("givens", {})) if scene.breaks else None
    if rod is None or (plate and writes_rod(scene.furniture)):
        return None, {}

    def spots(lines: Sequence[tuple[float, float, float, float]]) -> list[tuple]:
        return clear_spots(scene.breaks, lines, rod, style, px, clear)

    beside = beside_breaks(scene.breaks, [m.geom for m in scene.marks if m.kind is MarkKind.POINT])
    if plate:
        return rod, {None: spots(crossing_lines(scene.marks, scene.furniture) + beside)}
    layer = {name: i for i, name in enumerate(layers)}
    for m in sorted((m for m in scene.marks if m.kind is MarkKind.SEGMENT), key=lambda m: layer[mark_layer(m)]):
        got = spots([m.geom])
        if got:
            return rod, {m.id: got}
    return rod, {None: spots(beside)}


def rod_group(f: Any, rod: str, spot: tuple) -> Any:
    """The rod's length at a break as an SVG letter group of factory *f*, scaled as the letters are; *spot* one
    of :func:`rod_spots`."""
    axis, cx, cy, dx, dy, anchor = spot
    g = f.g(class_="lbg rodlen", transform=f"translate({fmt(cx)} {fmt(cy)})",
            **{"data-rod": f"{axis} {fmt(dx)} {fmt(dy)} {anchor}"})
    own = {} if anchor == "middle" else {"style": f"text-anchor:{anchor}"}
    for cls in ("lb halo", "lb"):
        g.add(f.text(rod, x=[fmt(dx)], y=[fmt(dy)], class_=cls, **own))
    return g


def rod_pieces(rod: str | None, at: Mapping[str | None, Sequence[tuple]], size: float) -> list[Piece]:
    """The rod's length at every spot of *at* (:func:`rod_at`) as plate pieces for a writer other than SVG (TikZ):
    the text :func:`rod_group` writes, at the middle of its height (its baseline less 0.35 letters of *size*).

    >>> rod_pieces("L = 8 r", {None: [(0, 10.0, 20.0, 0.0, -9.0, "middle")]}, 10.0)[0][:4]
    ('text', ((10.0, 7.5),), 'lb rodlen', 'L = 8 r')
    """
    if not rod:
        return []
    return [Piece("text", ((cx + dx, cy + dy - 0.35 * size),), "lb rodlen", rod, anchor)
            for spots in at.values() for _, cx, cy, dx, dy, anchor in spots]
