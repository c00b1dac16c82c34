"""The checks of a plate: what a book plate of 1900 never shows.

A plate (the root ``<svg class="plate">``: one still view, printed) is read
for every stroked line, whatever it is -- a construction line, a result, a
tick, an axis, a dimension line, hatching, another letter's leader -- and
for its caption.

=============  =====================================================================
kind           finding
=============  =====================================================================
through        a stroke passes through a letter's core: a book sets the letter beside
               its line or breaks the line for it
caption-lines  the caption runs over :data:`CAPTION_LINES` lines
caption-break  a caption line ends inside a number or a formula ("Fig. / 77",
               "r/L = / 1/5", "25 / at", "G / = 990 kg", "(m₁ + / m₂)v₁²")
=============  =====================================================================

A letter's *core* is the box its glyphs' ink covers, shrunk on every side by
:data:`CORE_MARGIN` of its size (never by more than a quarter of the box): a
line that only grazes the edge of the ink (the tail of a 7 beside a tick)
is not through it, a line that crosses its middle is, however thin.  A line
is taken at its stroke width, in the letter's own frame (a turned letter's
core is a turned box), and as drawn: a line broken for the letter (a gap
in the path under it) does not pass through it, a paper-coloured halo
round the glyphs does not hide it (the line still runs through the
letter's counters and between its glyphs).  A letter's own leader counts
too: it should end where the letter's white begins.

>>> svg = '''<svg xmlns="http://www.w3.org/2000/svg" class="plate" viewBox="90 15 60 70">
... <style>.lb{font-family:'DejaVu Serif';font-size:12px;text-anchor:middle}.thin{stroke:black;stroke-width:0.5}</style>
... <line class="thin" x1="100" y1="20" x2="100" y2="80"/><text class="lb" x="100" y="54">1</text>
... <text class="lb" x="140" y="54">2</text></svg>'''
>>> from . import lint_svg
>>> [(f.kind, f.labels) for f in lint_svg(svg, "tick.svg")]
[('through', ('1',))]
>>> caption_breaks(["Fig. 77. Kurbelwinkel, r/L =", "1/4. — nach Anhang II, Fig.", "77."])
[(0, "ends inside the formula 'r/L = / 1/4.'"), (1, "ends inside 'Fig. / 77.'")]
"""

from __future__ import annotations

import math

from ...kernel.letters import PLATE_CAPTION_LINES, formula_break
from ...render.lettering import segment_meets_box
from .sheet import Sheet, Text

__all__ = ["KINDS", "CORE_MARGIN", "CAPTION_LINES", "check_plate", "core_of", "through", "caption_breaks"]

KINDS = ("through", "caption-lines", "caption-break")
#: How far a letter's core lies inside its ink box, in letter sizes (an em): a line nearer the edge grazes it.
CORE_MARGIN = 0.12
#: The most lines a plate's caption runs to (a book's: the figure number, its title, what it shows).
CAPTION_LINES = PLATE_CAPTION_LINES

def core_of(t: Text) -> tuple[float, float, float, float]:
    """The core of letter *t* in its own coordinates: its ink box less :data:`CORE_MARGIN` of its size."""
    x0, y0, x1, y1 = t.ink
    size = t.size / max(_scale(t.ctm), 1e-12)  # the font size in the text's own units
    mx = min(CORE_MARGIN * size, (x1 - x0) / 4)
    my = min(CORE_MARGIN * size, (y1 - y0) / 4)
    return (x0 + mx, y0 + my, x1 - mx, y1 - my)


def _scale(m) -> float:
    return math.sqrt(abs(m[0] * m[3] - m[1] * m[2]))


def _inverse(m):
    a, b, c, d, e, f = m
    det = a * d - b * c
    if abs(det) < 1e-300:
        return None
    ia, ib, ic, id_ = d / det, -b / det, -c / det, a / det
    return (ia, ib, ic, id_, -(ia * e + ic * f), -(ib * e + id_ * f))


def _dist_point_box(x: float, y: float, b) -> float:
    dx = max(b[0] - x, 0.0, x - b[2])
    dy = max(b[1] - y, 0.0, y - b[3])
    return math.hypot(dx, dy)


def _dist_point_segment(px: float, py: float, ax: float, ay: float, bx: float, by: float) -> float:
    dx, dy = bx - ax, by - ay
    n = dx * dx + dy * dy
    t = 0.0 if n == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / n))
    return math.hypot(ax + t * dx - px, ay + t * dy - py)


def through(seg, half: float, core) -> bool:
    """Does a stroke along *seg* of half width *half* cover any of the box *core* (the same coordinates)?

    >>> through((0.0, -5.0, 0.0, 5.0), 0.25, (-1.0, -1.0, 1.0, 1.0)), through((3.0, -5.0, 3.0, 5.0), 0.5, (-1.0, -1.0, 1.0, 1.0))
    (True, False)
    """
    if core[2] <= core[0] or core[3] <= core[1]:
        return False
    if segment_meets_box(core, seg):
        return True
    x0, y0, x1, y1 = seg
    d = min(_dist_point_box(x0, y0, core), _dist_point_box(x1, y1, core),
            *(_dist_point_segment(cx, cy, x0, y0, x1, y1) for cx in (core[0], core[2]) for cy in (core[1], core[3])))
    return d < half


def _struck_letters(sheet: Sheet) -> list[tuple[Text, list[str | None]]]:
    """Each letter of the plate with the ids of the lines through its core."""
    import numpy as np

    pieces, owners = [], []
    for i, ln in enumerate(sheet.lines):
        for p in ln.pieces:
            pieces.append(p)
            owners.append(i)
    if not pieces:
        return []
    arr = np.array(pieces, dtype=float)
    lo = np.minimum(arr[:, 0:2], arr[:, 2:4])
    hi = np.maximum(arr[:, 0:2], arr[:, 2:4])
    halves = np.array([sheet.lines[i].half for i in owners])
    out = []
    for t in sheet.texts:
        if t.kind == "caption":
            continue
        core = core_of(t)
        inv = _inverse(t.ctm)
        if inv is None or core[2] <= core[0] or core[3] <= core[1]:
            continue
        corners = [(t.ctm[0] * x + t.ctm[2] * y + t.ctm[4], t.ctm[1] * x + t.ctm[3] * y + t.ctm[5])
                   for x in (core[0], core[2]) for y in (core[1], core[3])]
        bx0, by0 = min(c[0] for c in corners), min(c[1] for c in corners)
        bx1, by1 = max(c[0] for c in corners), max(c[1] for c in corners)
        near = np.flatnonzero((lo[:, 0] <= bx1 + halves) & (hi[:, 0] >= bx0 - halves)
                              & (lo[:, 1] <= by1 + halves) & (hi[:, 1] >= by0 - halves))
        k = _scale(inv)
        hit: list[int] = []
        for j in near.tolist():
            li = owners[j]
            ln = sheet.lines[li]
            if li in hit:
                continue
            x0, y0, x1, y1 = pieces[j]
            local = (inv[0] * x0 + inv[2] * y0 + inv[4], inv[1] * x0 + inv[3] * y0 + inv[5],
                     inv[0] * x1 + inv[2] * y1 + inv[4], inv[1] * x1 + inv[3] * y1 + inv[5])
            if through(local, ln.half * k, core):
                hit.append(li)
        if hit:
            out.append((t, [sheet.lines[i].ident for i in hit]))
    return out


def caption_breaks(lines: list[str]) -> list[tuple[int, str]]:
    """The lines (by number) that end inside a number or a formula, each with what it breaks
    (:func:`construct.kernel.letters.formula_break`, the rule the plates' captions are wrapped by).

    >>> caption_breaks(["G", "= 990 kg", "Füllung 25", "at, (m₁ +", "m₂)v₁²", "(Dürers", "Dreiteilung)"])
    [(0, "ends inside the formula 'G / ='"), (2, "ends inside '25 / at,'"), (3, "ends inside the formula '(m₁ + / m₂)v₁²'")]
    """
    out = []
    for i in range(len(lines) - 1):
        why = formula_break(lines[i], lines[i + 1])
        if why is not None:
            out.append((i, f"ends inside {why}"))
    return out


def check_plate(sheet: Sheet, finding) -> list:
    """The findings of a plate (*finding*: kind, labels, ids, message -> a finding of this sheet)."""
    if not sheet.plate:
        return []
    out = []
    for t, ids in _struck_letters(sheet):
        what = ", ".join(i or "a line without id" for i in ids[:4]) + (f" and {len(ids) - 4} more" if len(ids) > 4 else "")
        out.append(finding("through", (t.text,), (t.ident, *ids),
                           f"letter {t.name} has {'a stroke' if len(ids) == 1 else f'{len(ids)} strokes'} "
                           f"through its core ({what})"))
    caps = sorted((t for t in sheet.texts if t.kind == "caption"), key=lambda t: (t.box[1], t.box[0]))
    if len(caps) > CAPTION_LINES:
        out.append(finding("caption-lines", tuple(t.text for t in caps[:1]), tuple(t.ident for t in caps[:1]),
                           f"the caption runs to {len(caps)} lines (a plate's is at most {CAPTION_LINES})"))
    for i, why in caption_breaks([t.text for t in caps]):
        out.append(finding("caption-break", (caps[i].text, caps[i + 1].text), (caps[i].ident, caps[i + 1].ident),
                           f"caption line {i + 1} {why}"))
    return out
