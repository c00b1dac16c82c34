"""A live given: what the player draws at every value of a continuous given, precomputed by one sweep.

A teacher moves the rod ratio in the player and the whole construction follows.
The page does not construct anything: the protocol is replayed here over a grid
of the given in one numpy pass (``Protocol.replay`` with an array, the same
kernel as ``construct replay``), every grid value is laid out as the player
lays it out (the same :class:`~construct.render.svg.Drawing`, fitted to the
same view), and the page interpolates linearly between grid values.

**The bound.**  The grid is chosen, not guessed: starting from a coarse grid in
log10 of the given, every cell's midpoint is replayed and drawn, the linear
interpolation of the cell's ends is compared there with the exact drawing,
coordinate by coordinate (pixels of the player's 1400-wide view), and a cell
whose error exceeds :data:`REFINE_PX` is split, until none does.  Stored
coordinates are quantised to :data:`QUANTUM_PX`, which adds at most half a
quantum; so every drawn coordinate the page shows at a midpoint is within
``REFINE_PX + QUANTUM_PX / 2`` = 0.425 px < 0.5 px of the exact drawing
(:attr:`LiveSweep.bound` is the measured maximum).  The drawing depends
smoothly on the given between grid values -- no intersection of the
constructions switches branch between neighbouring rod ratios
(tests/test_sweep.py, ``test_no_intersection_switches_branch_between_neighbouring_ratios``,
2000 ratios from 1.02 to 50; above 50 the refinement below would see a jump) --
so the midpoint error bounds the cell's error up to the curvature's variation
across the cell, which the refinement keeps small.  One thing in the drawing
is not continuous: the broken axis (a gap wider than a fifth of the figure is
broken out) appears at one rod ratio.  A cell across it never converges; it
is split down to :data:`MIN_CELL` and recorded in :attr:`LiveSweep.jumps`,
and the page snaps to the nearer side there.  An arc's large-arc flag is never
blended: it comes from the nearer grid value, and a cell where it flips is
refined while the other arc its ends allow lies more than 0.4 px away.  A mark
that alone jumps inside the domain (the inertia curve's arc about D flips to
its other side at several rod ratios) is drawn from the nearer grid value
everywhere (:attr:`LiveSweep.snapped`) instead of forcing the grid down at every
flip.  The grid stops growing at *max_values* values; a cell still too coarse
then is recorded as a jump (measured: none for the crank and the inertia curve).

What is interpolated: every element of the figure that carries an id (the
marks: points, lines, circles, arcs, curves, areas and their hatching), the
figure's view box, and each step's magnified view.  The bound holds for the
marks and the view box; the magnified views jump where another group becomes
the one too small to see, and are blended there (they frame, they are not drawn).  Letters and leader lines belong to the label placer, which
may choose another spot from one value to the next; they move with the point
they name (the offset of the built value kept).

>>> from construct.constructions import get
>>> live = live_sweep(get("crank"), get("crank").figure(parts=3), "rod_ratio", initial=5)
>>> bool(live.bound < 0.5 and live.grid[0] == 1.05 and live.grid[-1] == 1000.0)
True
"""

from __future__ import annotations

import base64
import json
import math
import re
import xml.etree.ElementTree as ET
import zlib
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import Construction
from ..figure import Figure
from ..kernel.errors import InvalidParameter
from .domain import Domain, ROD_RATIO

__all__ = ["LIVE_GIVENS", "LiveSweep", "live_sweep", "drawn_numbers", "REFINE_PX", "QUANTUM_PX", "MIN_CELL",
           "live_data", "live_givens", "player_page"]

#: The continuous givens a player can move: protocol name -> (stated domain, the book's symbol).
LIVE_GIVENS: dict[str, tuple[Domain, str]] = {"rod_ratio": (ROD_RATIO, "L/r")}
#: A cell is split while linear interpolation misses the exact drawing by more than this (px).
REFINE_PX = 0.4
#: Stored coordinates are multiples of this (px).
QUANTUM_PX = 0.05
#: A jump caused by at most this many marks is theirs (they are drawn from the nearer grid value), not the figure's.
SNAP_AT_MOST = 3
#: A cell narrower than this (in log10 of the given) is not split further: it straddles a jump of the drawing.
MIN_CELL = 1e-4

_NUM = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
#: The attributes that carry geometry.
_GEOMETRY = ("cx", "cy", "r", "x1", "y1", "x2", "y2", "d", "points", "viewBox")
_SVG = "{http://www.w3.org/2000/svg}"


def live_givens(construction: Construction, figure: Figure) -> list[str]:
    """The continuous givens of *figure* a player offers a slider for (those a sweep can replay).

    >>> from construct.constructions import get
    >>> live_givens(get("crank"), get("crank").figure()), live_givens(get("indicator-diagram"), get("indicator-diagram").figure())
    (['rod_ratio'], [])
    """
    givens = dict(figure.replay.givens)
    out = []
    for name in LIVE_GIVENS:
        if name == "rod_ratio" and construction.rod_ratio_sweep(givens, [1.0]) is not None:
            out.append(name)
    return out


def drawn_numbers(page: str) -> tuple[list[tuple[str, str, str]], list[float], dict[str, Any]]:
    """The geometry of a player page's figure: ((element id, attribute, template), ...) and the numbers in order.

    Every element with an id, the figure's view box and, when the page has the player's data, each step's
    magnified view (key ``("#zoom", k, ...)``).

    >>> keys, nums, _ = drawn_numbers('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 5">'
    ...                               '<circle id="p" cx="1.5" cy="2" r="3"/></svg>')
    >>> keys, nums
    ([('', 'viewBox', '# # # #'), ('p', 'cx', '#'), ('p', 'cy', '#'), ('p', 'r', '#')], [0.0, 0.0, 10.0, 5.0, 1.5, 2.0, 3.0])
    """
    svg = page[page.index("<svg"):page.index("</svg>") + len("</svg>")]
    root = ET.fromstring(svg)
    keys: list[tuple[str, str, str]] = []
    nums: list[float] = []
    for e in root.iter():
        ident = e.get("id") or ""
        if e is not root and not ident:
            continue
        for a in _GEOMETRY:
            v = e.get(a)
            if v is None or (e is root) != (a == "viewBox"):
                continue
            ns = _NUM.findall(v)
            if ns:
                keys.append((ident, a, _NUM.sub("#", v)))
                fs = [float(x) for x in ns]
                nums.extend(_canonical_arc(fs) if a == "d" and keys[-1][2] == _ARC else fs)
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
    return keys, nums, {}


_ARC = "M# #A# # # # # # #"


def arc_flags(keys: list[tuple[str, str, str]]) -> np.ndarray:
    """Which of the numbers of *keys* are an arc's large-arc flag (taken from the nearer grid value, not blended).

    >>> arc_flags([("a", "cx", "#"), ("b", "d", "M# #A# # # # # # #")]).nonzero()[0].tolist()
    [6]
    """
    out: list[bool] = []
    for k in keys:
        n = k[2].count("#")
        out += [k[1] == "d" and k[2] == _ARC and i == 5 for i in range(n)]
    return np.asarray(out, dtype=bool)


def _midpoint_error(keys, na: np.ndarray, nb: np.ndarray, exact: np.ndarray, snap: set[int]) -> tuple[float, list[int]]:
    """The largest distance (px) between the page's drawing at a cell's midpoint and the exact one, and the
    keys that exceed REFINE_PX.  Coordinates are blended from the quantised ends; large-arc flags and snapped
    keys come from either end (the worse counts); a wrong flag moves the arc by the distance between the two
    centres its ends and radius allow, 2 sqrt(r^2 - (c/2)^2)."""
    owner = np.asarray([i for i, k in enumerate(keys) for _ in range(k[2].count("#"))], dtype=int)
    if owner.size == 0:
        return 0.0, []
    q = lambda n: np.round(n / QUANTUM_PX) * QUANTUM_PX  # noqa: E731
    blended = (q(na) + q(nb)) / 2
    col_err = np.abs(blended - exact)
    nearest = np.isin(owner, list(snap)) if snap else np.zeros(owner.size, dtype=bool)
    col_err[nearest] = np.maximum(np.abs(na - exact), np.abs(nb - exact))[nearest]
    col_err[_columns(keys, lambda k: k[0] == "#zoom")] = 0.0  # views frame the figure: blended, not refined for
    flags = arc_flags(keys)
    for c in np.nonzero(flags & ~nearest)[0]:
        col_err[c] = 0.0
        if na[c] != exact[c] or nb[c] != exact[c]:  # c is the flag: the arc's numbers are c-5 .. c+3
            x0, y0, r, x1, y1 = exact[c - 5], exact[c - 4], exact[c - 3], exact[c + 2], exact[c + 3]
            half = math.hypot(x1 - x0, y1 - y0) / 2
            col_err[c] = 2 * math.sqrt(max(r * r - half * half, 0.0))
    key_err = np.zeros(len(keys))
    np.maximum.at(key_err, owner, col_err)
    bad = np.nonzero(key_err > REFINE_PX)[0].tolist()
    return float(col_err.max()), bad


def _columns(keys: list[tuple[str, str, str]], pick) -> np.ndarray:
    """Which numbers of *keys* belong to keys *pick* selects."""
    return np.asarray([pick(k) for k in keys for _ in range(k[2].count("#"))], dtype=bool)


def _canonical_arc(ns: list[float]) -> list[float]:
    """An arc path's numbers drawn counter-clockwise on the page (sweep flag 1): the same arc, its ends swapped
    where it was drawn the other way, so that its numbers vary continuously with the given."""
    if ns[6] == 0.0:
        return [ns[7], ns[8], ns[2], ns[3], ns[4], ns[5], 1.0, ns[0], ns[1]]
    return ns


@dataclass
class LiveSweep:
    """A given's grid and what the player draws at every grid value."""

    given: str
    symbol: str
    domain: Domain
    initial: float
    grid: np.ndarray
    keys: list[tuple[str, str, str]]
    #: grid x numbers, pixels of the player's view.
    drawn: np.ndarray
    #: The measured maximum of |interpolated - exact| over every midpoint tested (px, after quantisation).
    bound: float
    #: Cells (low, high) across which the drawing jumps (the broken axis appearing).
    jumps: list[tuple[float, float]] = field(default_factory=list)
    #: Per grid value: [[name, measured, expected, error, tolerance, ok], ...].
    checks: list[list[list[Any]]] = field(default_factory=list)
    #: Elements whose geometry is not interpolated (their form changes across the domain): shown at the built value.
    fixed: list[str] = field(default_factory=list)
    #: Marks drawn from the nearer grid value (they jump inside the domain: an arc drawn the other way round).
    snapped: list[tuple[str, str, str]] = field(default_factory=list)

    def nearest_columns(self) -> np.ndarray:
        """The columns taken from the nearer grid value: large-arc flags and the snapped marks."""
        snapped = set(self.snapped)
        return arc_flags(self.keys) | _columns(self.keys, lambda k: k in snapped)


def _frames(construction: Construction, figure: Figure, given: str, values: np.ndarray, draw) -> list[tuple]:
    """(keys, numbers) of the player's figure at every value, from one sweep of the protocol."""
    givens = dict(figure.replay.givens)
    if given == "rod_ratio":
        swept = construction.rod_ratio_sweep(givens, values)
    else:
        swept = {**givens, given: np.asarray(values, dtype=float)}
    if swept is None:
        raise InvalidParameter(f"{construction.name} has no given {given} to sweep")
    replay = figure.protocol.replay(swept)
    out = []
    for i in range(len(values)):
        keys, nums, _ = drawn_numbers(draw(Figure(figure.protocol, replay.take(i), construction.check)))
        out.append((keys, nums))
    return out, replay


def player_page(construction: Construction, figure: Figure, style: Any) -> str:
    """The player page of *figure* (the same scene, drawing and fit as ``construct replay`` writes)."""
    from ..render.output import scene_for
    from ..render.player import player_html
    from ..render.svg import Drawing

    scene = scene_for(construction, figure)
    return player_html(scene, style, drawing=Drawing(scene, style))


def live_sweep(construction: Construction, figure: Figure, given: str, *, initial: float | None = None,
               style: Any = None, start: int = 9, max_values: int = 400) -> LiveSweep:
    """The grid of *given* over its domain on which linear interpolation draws within 0.5 px (see the module)."""
    from ..render.styles import STYLES

    style = style or STYLES["teaching"]
    domain, symbol = LIVE_GIVENS[given]
    initial = float(figure.replay.givens[given] if initial is None else initial)
    draw = lambda f: player_page(construction, f, style)  # noqa: E731
    lo, hi = math.log10(domain.low), math.log10(domain.high)
    us = list(np.linspace(lo, hi, start))
    values = lambda u: np.clip(10.0 ** np.asarray(u), domain.low, domain.high)  # noqa: E731
    frames, _ = _frames(construction, figure, given, values(us), draw)
    data = dict(zip(us, frames))
    todo = list(zip(us[:-1], us[1:]))
    jumps: list[tuple[float, float]] = []
    snap: set[int] = set()  # keys drawn from the nearer grid value
    bound = 0.0
    while todo:
        mids = [(a + b) / 2 for a, b in todo]
        mframes, _ = _frames(construction, figure, given, values(mids), draw)
        nxt = []
        for (a, b), m, fm in zip(todo, mids, mframes):
            data[m] = fm
            ka, na = data[a]
            kb, nb = data[b]
            if not ka == kb == fm[0]:
                err, culprits = math.inf, [-1]
            else:
                err, culprits = _midpoint_error(ka, np.asarray(na), np.asarray(nb), np.asarray(fm[1]), snap)
            if err <= REFINE_PX:
                bound = max(bound, err)
                continue
            if b - a >= MIN_CELL and len(data) <= max_values:
                nxt += [(a, m), (m, b)]
                continue
            if 0 < len(culprits) <= SNAP_AT_MOST and culprits[0] >= 0:
                # one or two marks jump here (an arc drawn the other way round): they are drawn from the nearer
                # grid value everywhere, the rest stays blended
                snap.update(culprits)
                continue
            jumps.append((float(values(a)), float(values(b))))
        todo = nxt
    us = sorted(data)
    # The keys every grid value shares; a few elements change form (e.g. a curve's number of points):
    # they stay at the built value.
    shared = set(data[us[0]][0])
    for u in us:
        shared &= set(data[u][0])
    keys = [k for k in data[us[0]][0] if k in shared]
    rows = []
    for u in us:
        kk, nn = data[u]
        pos, at = {}, 0
        for k in kk:
            n = k[2].count("#")
            pos[k] = nn[at:at + n]
            at += n
        rows.append([x for k in keys for x in pos[k]])
    fixed = sorted({k[0] for u in us for k in data[u][0] if k not in shared})
    first = data[us[0]][0]
    snapped = [k for i, k in enumerate(first) if i in snap and k in shared]
    grid = values(us)
    live = LiveSweep(given, symbol, domain, initial, grid, keys, np.asarray(rows, dtype=float), bound, jumps,
                     fixed=fixed, snapped=snapped)
    live.checks = _checks(construction, figure, given, grid)
    return live


def _checks(construction: Construction, figure: Figure, given: str, grid: np.ndarray) -> list[list[list[Any]]]:
    """The construction's checks at every grid value, from one sweep (:meth:`Construction.sweep_checks`)."""
    givens = dict(figure.replay.givens)
    swept = construction.rod_ratio_sweep(givens, grid) if given == "rod_ratio" else {**givens, given: grid}
    sweep = Figure(figure.protocol, figure.protocol.replay(swept), construction.check)
    return [[[c.name, c.measured, c.expected, c.error, c.tolerance, bool(c.ok)] for c in row]
            for row in construction.sweep_checks(sweep)]


def encode(drawn: np.ndarray) -> tuple[str, int]:
    """Coordinates quantised to QUANTUM_PX, delta-coded along the grid column by column, deflated, base64;
    and the width in bytes of a delta.

    The first row travels as int32; the deltas as int16 where they fit (else int32), split into byte planes
    (all low bytes, then all high bytes: the high bytes of small deltas are runs of 0 and 255 that deflate
    squeezes away).

    >>> a = np.array([[0.0, 10.0], [0.05, 10.0], [0.1, 12.5], [-3000.0, 12.5]])
    >>> np.array_equal(decode(*encode(a), *a.shape), np.round(a / QUANTUM_PX) * QUANTUM_PX)
    True
    >>> encode(a[:3])[1], encode(a)[1]
    (2, 4)
    """
    q = np.round(drawn / QUANTUM_PX).astype(np.int64)
    first, rest = q[0], np.diff(q, axis=0)
    width = 2 if rest.size == 0 or np.abs(rest).max() < 2 ** 15 else 4
    cols = np.ascontiguousarray(rest.T).astype(f"<i{width}").view(np.uint8).reshape(-1, width)
    payload = first.astype("<i4").tobytes() + np.ascontiguousarray(cols.T).tobytes()
    return base64.b64encode(zlib.compress(payload, 9)).decode("ascii"), width


def decode(text: str, width: int, rows: int, cols: int) -> np.ndarray:
    """The inverse of :func:`encode` (what the page does with DecompressionStream)."""
    raw = zlib.decompress(base64.b64decode(text))
    first = np.frombuffer(raw[:4 * cols], dtype="<i4").astype(np.int64)
    planes = np.frombuffer(raw[4 * cols:], dtype=np.uint8).reshape(width, -1)
    rest = np.ascontiguousarray(planes.T).view(f"<i{width}").reshape(cols, rows - 1).T.astype(np.int64)
    return np.cumsum(np.vstack([first, rest]), axis=0) * QUANTUM_PX


def book_number(value: float) -> str:
    """A given as the book prints it: decimal comma, no trailing zeros.

    >>> book_number(4.5), book_number(5.0), book_number(1.05)
    ('4,5', '5', '1,05')
    """
    return f"{value:.4g}".replace(".", ",")


def live_data(live: LiveSweep) -> dict[str, Any]:
    """What the page needs: the grid (log10), the keys, the encoded coordinates, the checks."""
    return {"given": live.given, "symbol": live.symbol, "low": live.domain.low, "high": live.domain.high,
            "initial": live.initial, "grid": [round(math.log10(v), 12) for v in live.grid],
            "values": [float(v) for v in live.grid],
            "keys": [list(k) for k in live.keys], "rows": int(live.drawn.shape[0]),
            "cols": int(live.drawn.shape[1]), "q": QUANTUM_PX,
            "flags": live.nearest_columns().nonzero()[0].tolist(), **dict(zip(("data", "width"), encode(live.drawn))),
            "bound": round(live.bound + QUANTUM_PX / 2, 3), "jumps": live.jumps,
            "checks_z": base64.b64encode(zlib.compress(json.dumps(_check_table(live)).encode("utf-8"), 9)).decode("ascii")}


#: The checks travel at this many grid values at most (the page shows the nearest: it says which).
CHECK_VALUES = 48


def _check_table(live: LiveSweep) -> dict[str, Any]:
    """The checks at up to CHECK_VALUES grid values, evenly in log10: names once, numbers to 9 digits."""
    if not live.checks:
        return {"checks": [], "check_values": [], "check_names": []}
    n = len(live.grid)
    picks = sorted({int(round(i)) for i in np.linspace(0, n - 1, min(n, CHECK_VALUES))})
    g = lambda x: float(f"{x:.9g}") if math.isfinite(x) else None  # noqa: E731
    return {"check_names": [c[0] for c in live.checks[0]],
            "check_values": [float(live.grid[i]) for i in picks],
            "checks": [[[g(c[1]), g(c[2]), float(f"{c[3]:.2g}"), c[5]] for c in live.checks[i]] for i in picks]}
