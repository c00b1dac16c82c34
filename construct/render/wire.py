"""The live player's wire format, as the page's script reads it (:data:`construct.render.live.LIVE_SCRIPT`).

A live player's data (:func:`construct.live.wire.live_data`) names every number of the drawn figure by a key
``(element id, attribute, template)``: the attribute's text with each number written ``#``, so that the page
writes the numbers of a grid value back into the template.  :func:`drawn_numbers` reads those keys and numbers
out of a player page's SVG (an arc's numbers as drawn counter-clockwise, :func:`canonical_arc`, so that they vary
continuously with the given).  The coordinates travel deflated: each stored column in its own units (drawn, or
the construction's x, y or length through the grid value's fit to the view, :func:`as_drawn`), between its kept
grid values a line in log10 of the given.  :func:`decode` is what the script's ``expand`` does, in numpy: the
tests hold the two to the same numbers.

>>> keys, nums, _ = drawn_numbers('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 5">'
...                               '<path id="a" d="M1 0A1 1 0 0 0 0 1"/></svg>')
>>> keys[1], nums[4:]      # drawn clockwise: read as the same arc counter-clockwise
(('a', 'd', 'M# #A# # # # # # #'), [0.0, 1.0, 1.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0])
>>> inflated(deflated({"a": [1, 2]}))
{'a': [1, 2]}
"""

from __future__ import annotations

import base64
import json
import re
import xml.etree.ElementTree as ET
import zlib
from typing import Any, Mapping

import numpy as np

__all__ = ["drawn_numbers", "arc_flags", "radii", "blend", "canonical_arc", "decode", "as_drawn", "as_stored", "deflated",
           "inflated", "DEFLATE_LEVEL", "ARC", "NUMBER", "PX", "X", "Y", "LENGTH", "LOG"]

#: A number as the drawing writes it.
NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
#: The attributes that carry geometry.
_GEOMETRY = ("cx", "cy", "r", "x1", "y1", "x2", "y2", "d", "points", "x", "y", "transform", "viewBox")
#: The attributes of a text's place (the end state's furniture: its dimensions' and scales' lettering).
_PLACE = ("x", "y", "transform")
#: The template of an arc's path: its start, radii, rotation, large-arc and sweep flags, end.
ARC = "M# #A# # # # # # #"
#: How a column is stored: as drawn (px), or in the construction's own units through the row's fit to the
#: view (ox, oy, s): an x (ox + s x), a y (oy - s y), a length (s l), a radius by its logarithm (s e^l: a rod's
#: arc about a crank point grows as L/r, which the slider moves in log10, so its logarithm is a line).
PX, X, Y, LENGTH, LOG = 0, 1, 2, 3, 4


def drawn_numbers(page: str) -> tuple[list[tuple[str, str, str]], list[float], dict[str, Any]]:
    """The geometry of a player page's figure: ((element id, attribute, template), ...) and the numbers in order.

    Every element with an id, the figure's view box and, when the page has the player's data, each step's
    magnified view (key ``("#zoom", k, ...)``) and the centre of the ring round a step's small mark (``"#ring"``), the box its inset magnifies (``"#inset"``).  The third value holds the text of every lettered element by
    id (``texts``): a letter that is a measured value (an angle read off the figure) changes with the given.

    >>> keys, nums, _ = drawn_numbers('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 5">'
    ...                               '<circle id="p" cx="1.5" cy="2" r="3"/></svg>')
    >>> keys, nums
    ([('', 'viewBox', '# # # #'), ('p', 'cx', '#'), ('p', 'cy', '#'), ('p', 'r', '#')], [0.0, 0.0, 10.0, 5.0, 1.5, 2.0, 3.0])
    """
    svg = page[page.index("<svg"):page.index("</svg>") + len("</svg>")]
    root = ET.fromstring(svg)
    keys: list[tuple[str, str, str]] = []
    nums: list[float] = []
    texts: dict[str, str] = {}
    for e in root.iter():
        ident = e.get("id") or ""
        if ident and e.tag.rsplit("}", 1)[-1] == "text":
            texts[ident] = "".join(e.itertext())
        if e is not root and (not ident or ident == "ring"):  # the ring is the player's (the page moves it)
            continue
        for a in _GEOMETRY:
            v = e.get(a)
            # (a letter's place and its group's: the page moves them with their point; the end state's furniture,
            # fin-..., is swept: render/end_state.py end_furniture)
            if v is None or (e is root) != (a == "viewBox") or (a in _PLACE and not ident.startswith("fin-")):
                continue
            ns = NUMBER.findall(v)
            if ns:
                keys.append((ident, a, NUMBER.sub("#", v)))
                fs = [float(x) for x in ns]
                nums.extend(canonical_arc(fs) if a == "d" and keys[-1][2] == ARC else fs)
    marker = '<script type="application/json" id="data">'
    if marker in page:
        at = page.index(marker) + len(marker)
        data = json.loads(page[at:page.index("</script>", at)])
        full = [float(x) for x in root.get("data-full", root.get("viewBox", "")).split()]
        # each step's view: the camera's (``views``, ``v``) or the magnified box (``zooms``, ``z``; -1: the whole)
        boxes, index = ("views", "v") if "views" in data else ("zooms", "z")
        for i, st in enumerate(data["steps"]):
            keys.append(("#zoom", str(i), "# # # #"))
            j = st.get(index, -1)
            nums.extend(float(x) for x in data[boxes][j]) if j >= 0 else nums.extend(full)
        for i, st in enumerate(data["steps"]):  # the ring round a step's small mark: its centre
            if "r" in st:
                keys.append(("#ring", str(i), "# #"))
                nums.extend(float(x) for x in st["r"][:2])
        for i, st in enumerate(data["steps"]):  # the box a step's inset magnifies
            if "z" in st and "zd" not in st and "views" in data:  # (a cluster's: the page finds it anew)
                keys.append(("#inset", str(i), "# # # #"))
                nums.extend(float(x) for x in st["z"])

    return keys, nums, {"texts": texts}


def arc_flags(keys: list[tuple[str, str, str]]) -> np.ndarray:
    """Which of the numbers of *keys* are an arc's large-arc flag (taken from the nearer grid value, not blended).

    >>> arc_flags([("a", "cx", "#"), ("b", "d", "M# #A# # # # # # #")]).nonzero()[0].tolist()
    [6]
    """
    starts, arcs = _arc_keys(keys)
    out = np.zeros(starts[-1], dtype=bool)
    out[starts[:-1][arcs] + 5] = True
    return out


def radii(keys: list[tuple[str, str, str]]) -> np.ndarray:
    """Which of the numbers of *keys* are radii (a circle's r, an arc's two radii): blended between grid values
    geometrically, not linearly (a rod's arc of radius L grows as L/r: its radius at the geometric mean of two
    grid values is the geometric mean of theirs; a linear blend misses a 30,000 px radius by a pixel).

    >>> radii([("a", "r", "#"), ("b", "d", "M# #A# # # # # # #"), ("c", "cx", "#")]).nonzero()[0].tolist()
    [0, 3, 4]
    """
    starts, arcs = _arc_keys(keys)
    out = np.zeros(starts[-1], dtype=bool)
    out[starts[:-1][np.fromiter((k[1] == "r" and k[2] == "#" for k in keys), dtype=bool, count=len(keys))]] = True
    for i in (2, 3):
        out[starts[:-1][arcs] + i] = True
    return out


def _arc_keys(keys: list[tuple[str, str, str]]) -> tuple[np.ndarray, np.ndarray]:
    """Where each key's numbers begin (and, last, how many there are in all), and which keys are arcs' paths (a
    sweep's keys are thousands, asked for at every sweep: one pass over them, the rest on arrays)."""
    counts = np.fromiter((k[2].count("#") for k in keys), dtype=np.int64, count=len(keys))
    arcs = np.fromiter((k[1] == "d" and k[2] == ARC for k in keys), dtype=bool, count=len(keys))
    return np.concatenate([[0], np.cumsum(counts)]), arcs


def blend(a: np.ndarray, b: np.ndarray, t: Any, geometric: np.ndarray) -> np.ndarray:
    """The page's drawing between two grid values' numbers *a* and *b*, the fraction *t* of the way in log10 of
    the given: linear, and geometric for the radii (*geometric*, :func:`radii`)."""
    out = np.array(a + (b - a) * t, dtype=float)
    # (the power only where it is taken: the radii are a few of a sweep's thousands of numbers)
    g = np.broadcast_to(geometric & (a > 0) & (b > 0), out.shape)
    if g.any():
        A, B = np.broadcast_to(a, out.shape)[g], np.broadcast_to(b, out.shape)[g]
        out[g] = A * np.power(B / A, t if np.ndim(t) == 0 else np.broadcast_to(t, out.shape)[g])
    return out


def canonical_arc(ns: list[float]) -> list[float]:
    """An arc path's numbers drawn counter-clockwise on the page (sweep flag 1): the same arc, its ends swapped
    where it was drawn the other way, so that its numbers vary continuously with the given."""
    if ns[6] == 0.0:
        return [ns[7], ns[8], ns[2], ns[3], ns[4], ns[5], 1.0, ns[0], ns[1]]
    return ns


def as_stored(drawn: np.ndarray, fit: np.ndarray | None, kinds: np.ndarray) -> np.ndarray:
    """The drawn numbers in each column's stored units (the inverse of :func:`as_drawn`)."""
    if fit is None or not kinds.any():
        return drawn
    ox, oy, sc = (fit[:, i:i + 1] for i in range(3))
    return _by_kind(drawn, kinds, {X: lambda d: (d - ox) / sc, Y: lambda d: (oy - d) / sc, LENGTH: lambda d: d / sc,
                                   LOG: lambda d: np.log(d / sc)})


def as_drawn(stored: np.ndarray, fit: np.ndarray | None, kinds: np.ndarray) -> np.ndarray:
    """Stored numbers (rows of the grid x columns) as drawn, px: the script's ``expand`` after its lines."""
    if fit is None or not kinds.any():
        return stored
    ox, oy, sc = (fit[:, i:i + 1] for i in range(3))
    return _by_kind(stored, kinds, {X: lambda s: ox + sc * s, Y: lambda s: oy - sc * s, LENGTH: lambda s: sc * s,
                                    LOG: lambda s: sc * np.exp(s)})


def _by_kind(numbers: np.ndarray, kinds: np.ndarray, how: Mapping[int, Any]) -> np.ndarray:
    """*numbers* (rows x columns) with each kind's columns turned by its function in *how*, the others as they are:
    each function sees only its own columns (a sweep's grid is thousands of columns; every kind's formula over
    all of them, then a choice, would be four times the work)."""
    out = np.array(numbers, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        for kind, turn in how.items():
            cols = np.flatnonzero(kinds == kind)
            if cols.size:
                out[:, cols] = turn(out[:, cols])
    return out


def decode(data: Mapping[str, Any], grid: Any, rows: int, cols: int) -> np.ndarray:
    """The inverse of :func:`construct.live.wire.encode`, on the whole grid (*grid*: log10 of the grid values),
    as the page does it with DecompressionStream: each stored column between its kept values is the line
    between them in log10 of the given, drawn through the grid value's fit."""
    raw = zlib.decompress(base64.b64decode(data["data"]))
    ucols, mapw = data["ucols"], data["mapw"]
    at = cols * mapw
    colmap = np.frombuffer(raw[:at], dtype=f"<u{mapw}").astype(np.int64)
    byte = np.frombuffer(raw[at:at + ucols], dtype=np.uint8)
    kinds, wide = (byte & 127).astype(np.int8), byte >= 128
    at += ucols
    nbits = rows * ucols
    keep = np.unpackbits(np.frombuffer(raw[at:at + (nbits + 7) // 8], dtype=np.uint8))[:nbits]
    keep = keep.reshape(ucols, rows).astype(bool)
    at += (nbits + 7) // 8
    fit = np.frombuffer(raw[at:at + 12 * rows], dtype="<f4").reshape(rows, 3).astype(float)
    at += 12 * rows
    first = np.frombuffer(raw[at:at + 4 * ucols], dtype="<i4").astype(np.int64)
    at += 4 * ucols
    counts = keep.sum(axis=1) - 1  # each stored column's deltas
    deltas: dict[bool, np.ndarray] = {}
    for w, which in ((2, False), (4, True)):
        n = int(counts[wide == which].sum())
        planes = np.frombuffer(raw[at:at + w * n], dtype=np.uint8).reshape(w, n)
        deltas[which] = np.ascontiguousarray(planes.T).view(f"<i{w}").reshape(-1).astype(np.int64)
        at += w * n
    g = np.asarray(grid, dtype=float)
    quanta = np.where(kinds == LOG, data.get("ql", data["qx"]), np.where(kinds > 0, data["qx"], data["q"]))
    out = np.empty((rows, ucols))
    pos = {False: 0, True: 0}
    for c in range(ucols):
        idx = np.nonzero(keep[c])[0]
        w = bool(wide[c])
        vals = first[c] + np.concatenate([[0], np.cumsum(deltas[w][pos[w]:pos[w] + idx.size - 1])])
        pos[w] += idx.size - 1
        out[:, c] = np.interp(g, g[idx], vals * quanta[c])
    return as_drawn(out, fit, kinds)[:, colmap]


#: How hard the live data is deflated: zlib's default.  Its best (9) made the gallery's live data 1.4 % smaller
#: (2.04 MB of base64 instead of 2.07) in six times the time (a second of the gallery's CPU: the byte planes of
#: the coordinates are long runs that its longer search keeps trying).
DEFLATE_LEVEL = 6


def deflated(value: Any) -> str:
    """*value* as JSON, deflated and in base64 (a field of the live data)."""
    return base64.b64encode(zlib.compress(json.dumps(value, separators=(",", ":")).encode("utf-8"),
                                          DEFLATE_LEVEL)).decode("ascii")


def inflated(text: str) -> Any:
    """A deflated JSON field of the live data read back (:func:`deflated`)."""
    return json.loads(zlib.decompress(base64.b64decode(text)))
