"""What travels to the live page: the sweep's coordinates, each at the grid values it needs, and the checks.

**What travels.**  The grid is shared, but most coordinates need few of its
values: each coordinate keeps only the grid values where the line between
its neighbours would miss the exact drawing by more than :data:`ROW_PX` at
some grid value between (:func:`column_knots`), stored either as drawn or,
through each grid value's fit to the view, in the construction's own units
(the figure is rescaled to the view's width as L/r changes, so every drawn
coordinate moves, though the crank circle and all on it do not move in the
construction); identical coordinates travel once (:func:`encode`).  The page
rebuilds every grid value from that, then blends as above.

The format is the page's (:mod:`construct.render.wire` reads it back as the page's script does).
"""

from __future__ import annotations

import base64
import math
import re
import zlib
from collections.abc import Sequence
from typing import Any

import numpy as np

from ..render.wire import ARC, DEFLATE_LEVEL, LENGTH, LOG, PX, X, Y, as_stored, deflated, radii
from .measure import Measure
from .sweep import DERIVED_WRITTEN, QUANTUM_PX, LiveSweep, live_givens, live_sweep, pieces, reach

__all__ = ["ROW_PX", "STORED_PX", "column_kinds", "column_knots", "encode", "live_data", "live_pages", "same_walk"]

#: The page's coordinates travel as multiples of this (px, or its share of the largest scale in the
#: construction's units): the rounding is inside ROW_PX, which the columns are checked against.
STORED_PX = 0.1
#: At every grid value, a coordinate the page computes from its column's kept values is within this of the
#: exact drawing (px, quantisation included); between grid values the page blends two grid values, whose
#: own blending error the refinement held under REFINE_PX at the parent cell's midpoint (about a quarter of
#: that at a cell's own), so a drawn coordinate stays under 0.5 px (measured at fresh values by the tests).
ROW_PX = 0.35
#: A cell's open columns of one kind are read as one run of columns (a view, the others among them dropped after)
#: while the run is at most this many times as many columns.
NEARLY_A_RUN = 1.5
_PATH = re.compile(r"^[MLCZ# ,]*$")


def column_kinds(keys: list[tuple[str, str, str]]) -> np.ndarray:
    """What each number of *keys* is in the construction: x, y, a length (a radius: by its logarithm), or a
    number of the drawing only.

    >>> column_kinds([("a", "cx", "#"), ("a", "r", "#"), ("b", "d", "M# #A# # # # # # #"), ("#zoom", "0", "# # # #")]).tolist()
    [1, 4, 1, 2, 4, 4, 0, 0, 0, 1, 2, 1, 2, 3, 3]
    """
    out: list[int] = []
    for ident, attr, template in keys:
        n = template.count("#")
        if attr in ("cx", "x1", "x2", "x"):
            out.append(X)
        elif attr in ("cy", "y1", "y2", "y"):
            out.append(Y)
        elif attr == "r" and n == 1:
            out.append(LOG)
        elif ident in ("#zoom", "#inset") or attr == "viewBox":
            out += [X, Y, LENGTH, LENGTH]
        elif attr == "d" and template == ARC:
            out += [X, Y, LOG, LOG, PX, PX, PX, X, Y]
        elif attr in ("d", "points") and _PATH.match(template):
            out += [X if i % 2 == 0 else Y for i in range(n)]
        else:
            out += [PX] * n
    return np.asarray(out, dtype=np.int8)


def _quanta(live: LiveSweep, kinds: np.ndarray) -> np.ndarray:
    """The quantum of each column in its stored units: STORED_PX drawn, at most that at the largest scale (a
    logarithm's: STORED_PX at the largest radius drawn)."""
    smax = float(np.max(live.fit[:, 2])) if live.fit is not None and kinds.any() else 1.0
    logs = kinds == LOG  # (the largest radius looked for only where a column is stored by its logarithm)
    return np.where(logs, STORED_PX / _largest_radius(live) if logs.any() else 1.0,
                    np.where(kinds > 0, STORED_PX / smax, STORED_PX))


def _largest_radius(live: LiveSweep) -> float:
    """The largest radius the sweep draws (px): a logarithm's quantum keeps it within STORED_PX."""
    r = radii(live.keys)
    return float(max(np.max(live.drawn[:, r]), 1.0)) if r.any() else 1.0


def _knots(live: LiveSweep, kinds: np.ndarray, columns: np.ndarray | None = None,
           across: np.ndarray | None = None, nearest: np.ndarray | None = None) -> np.ndarray:
    """The grid values each of the *columns* (all, if not given) needs when stored as *kinds* says (see
    :func:`column_knots`): grid values x those columns (each column walks the tree alone).  *across*: those
    columns' drawn numbers turned on their side (columns x grid values), and *nearest*,
    :meth:`LiveSweep.nearest_columns`, if the caller has them (both walks of :func:`column_knots` read them)."""
    columns = np.arange(live.drawn.shape[1]) if columns is None else columns
    across = np.ascontiguousarray(live.drawn[:, columns].T) if across is None else across
    rows, cols = live.drawn.shape[0], columns.size
    u = np.asarray(live.u if live.u is not None else np.log10(live.grid), dtype=float)
    keep = np.zeros((rows, cols), dtype=bool)
    keep[:, (live.nearest_columns() if nearest is None else nearest)[columns]] = True
    kinds = kinds[columns]
    start = live.start or rows
    # the starting values of the refinement: evenly spaced in log10 (live_sweep's np.linspace)
    firsts = sorted({int(np.argmin(np.abs(u - x))) for x in np.linspace(u[0], u[-1], start)})
    # The columns walk the tree in the order of their kinds, each column's values in a row of its own: a cell's
    # open columns of one kind are drawn from the grid values inside it by one formula over a block (as_drawn's,
    # with the rows' fit broadcast), the values gathered in runs; which columns are still open is asked of all.
    # Each kind's block is stored and quantised as encode stores it (as_stored, the kind's quantum), the rows'
    # fit broadcast along the block (the same arithmetic, number by number, as on the grid's side).
    kinds = kinds if live.fit is not None else np.zeros(cols, dtype=np.int8)
    order = np.argsort(kinds, kind="stable")
    every = (order == np.arange(cols)).all()  # (every column in order)
    dt = across if every else across[order]
    bounds = np.searchsorted(kinds[order], np.arange(LOG + 2))
    qt = np.empty(dt.shape)
    for kind in range(LOG + 1):
        b0, b1 = bounds[kind], bounds[kind + 1]
        if b1 > b0:
            quantum = _quanta(live, np.full(1, kind, dtype=np.int8))[0]
            block = as_stored(dt[b0:b1].T, live.fit, np.full(b1 - b0, kind, dtype=np.int8)).T
            np.round(block / quantum, out=qt[b0:b1])
            qt[b0:b1] *= quantum
    fit = live.fit if live.fit is not None else np.zeros((rows, 3))
    ox, oy, sc = fit[:, 0], fit[:, 1], fit[:, 2]

    def drawn_as(kind: int, s: np.ndarray, r: slice) -> np.ndarray:
        """as_drawn of stored numbers *s* (columns of one *kind* x grid values *r*), in place (the same roundings)."""
        if kind == LOG:
            np.exp(s, out=s)
        if kind != PX:
            s *= sc[r]
        if kind == X:
            s += ox[r]
        elif kind == Y:
            np.subtract(oy[r], s, out=s)
        return s

    def mid_of(i: int, j: int) -> int | None:
        m = (u[i] + u[j]) / 2
        at = int(np.searchsorted(u, m))
        for k in (at - 1, at, at + 1):
            if i < k < j and abs(u[k] - m) <= 1e-12 * max(1.0, abs(m)):
                return k
        return None

    def misses(at: np.ndarray, i: int, j: int, t: np.ndarray, r: slice) -> np.ndarray:
        """How far the line between grid values i and j misses the drawing at grid values *r* (*t* of the way),
        at most, in each column of *at*."""
        err = np.empty(at.size)
        edges = np.searchsorted(at, bounds)
        for kind in range(LOG + 1):
            a0, a1 = edges[kind], edges[kind + 1]
            if a1 > a0:
                # a run of columns, or nearly one (most of a cell's columns hold at its midpoint and are then
                # asked at every grid value inside it), is read as a view, the few columns between dropped after:
                # a gathered copy of the block costs more than the numbers of the columns read for nothing
                span = at[a1 - 1] + 1 - at[a0]
                g = slice(at[a0], at[a1 - 1] + 1) if span <= NEARLY_A_RUN * (a1 - a0) else at[a0:a1]
                a = qt[g, i][:, None]
                line = (qt[g, j][:, None] - a) * t
                line += a
                miss = drawn_as(kind, line, r)
                miss -= dt[g, r]
                worst = np.abs(miss, out=miss).max(axis=1)
                err[a0:a1] = worst if type(g) is not slice or span == a1 - a0 else worst[at[a0:a1] - at[a0]]
        return err

    shut = np.zeros((rows, cols), dtype=bool)  # (in the columns' walking order)
    todo = [(i, j, np.arange(cols)) for i, j in zip(firsts[:-1], firsts[1:])]
    while todo:
        i, j, at = todo.pop()  # the columns still open here (deep in the tree, a few of thousands)
        m = mid_of(i, j)
        if m is None:  # a cell the refinement did not split: every column's own
            shut[[i, j], at[:, None]] = True
            if j - i > 1:  # (but for a value inside that is not its midpoint: where the plate's lettering switches
                # its spots, live.sweep._switch_spots) -- kept by the columns the line between the ends misses there
                err = misses(at, i, j, (u[i + 1:j] - u[i]) / (u[j] - u[i]), slice(i + 1, j))
                shut[np.arange(i + 1, j)[None, :], at[err > ROW_PX][:, None]] = True
            continue
        # the line between the cell's quantised ends, at every grid value inside the cell, as drawn: first at
        # the midpoint alone (most columns still open miss there), then at the others for the columns that do not
        t = (u[i + 1:j] - u[i]) / (u[j] - u[i])
        err = misses(at, i, j, t[m - i - 1:m - i], slice(m, m + 1))
        near = np.flatnonzero(err <= ROW_PX)
        if near.size and j - i > 2:
            err[near] = misses(at[near], i, j, t, slice(i + 1, j))
        done = err <= ROW_PX
        shut[[i, j], at[done][:, None]] = True
        rest = at[~done]
        if rest.size:
            todo += [(i, m, rest), (m, j, rest)]
    if every:
        keep |= shut
    else:
        keep[:, order] |= shut
    return keep


def column_knots(live: LiveSweep) -> tuple[np.ndarray, np.ndarray]:
    """Which grid values each column of *live* needs (grid x columns, bool), and how it is stored.

    The refinement splits a cell while any coordinate misses at the midpoint; most coordinates would not have
    needed it.  Each column is walked down the same tree of cells, and a cell is that column's own (its ends
    kept, the grid values inside it dropped) as soon as the line between the cell's quantised ends is within
    :data:`ROW_PX` of the exact drawing at *every* grid value inside the cell (the midpoint, and every
    midpoint the refinement drew below it).  Between its kept values a column is that line (the page
    interpolates in log10 of the given).  Large-arc flags and snapped marks (drawn from the nearer grid
    value) keep every grid value.

    The fit to the view changes with the given (the figure is scaled to the view's width), so every drawn
    coordinate moves, and kinks where another point becomes the one that bounds the figure; in the
    construction's own units most coordinates do not move at all (the crank circle and everything on it) or
    move smoothly.  So each column is stored either as drawn or, through the row's fit, as the construction's
    x, y or length (:func:`column_kinds`), whichever needs fewer grid values.

    >>> from construct.constructions.domain import ROD_RATIO
    >>> live = LiveSweep("rod_ratio", "L/r", ROD_RATIO, 5.0, np.array([1.0, 10 ** 0.5, 10.0]), [("p", "cx", "#"),
    ...     ("q", "cx", "#")], np.array([[0.0, 0.0], [5.0, 7.0], [10.0, 10.0]]), 0.0, u=np.array([0.0, 0.5, 1.0]),
    ...     start=2)
    >>> column_knots(live)[0].T.astype(int).tolist()  # p is a line: its middle value is not needed; q is not
    [[1, 0, 1], [1, 1, 1]]
    """
    keep, kinds, _, of = _walked_knots(live)
    return keep[:, of], kinds[of]


def _walked_knots(live: LiveSweep) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """:func:`column_knots` of the columns that walk the tree (:func:`same_walk`: one of each set of columns alike
    in their numbers, kind and nearness): grid values x walks, their kinds, the walks (their columns, in order),
    and each column's walk among them (its index)."""
    cols = live.drawn.shape[1]
    natural = column_kinds(live.keys) if live.fit is not None else np.zeros(cols, dtype=np.int8)
    # a radius that rounds to nothing somewhere (an arc about a point it is struck from, at L/r = 600) has no
    # logarithm there: a length
    natural = np.where((natural == LOG) & (live.drawn.min(axis=0) <= 0.0), LENGTH, natural).astype(np.int8)
    nearest = live.nearest_columns()
    # a column walks the tree alone, by its own numbers, kind and nearness: of the columns alike in those (a
    # point's coordinate in its circle, its lines and arcs: two thirds of tangential-pressure's), the first walks for all
    like = same_walk(live.drawn, natural, nearest)
    walks = np.flatnonzero(like == np.arange(cols))
    of = np.searchsorted(walks, like)  # (each column's walk among them)
    across = np.ascontiguousarray(live.drawn[:, walks].T)  # (each walk's values in a row: both walks read them so)
    as_drawn = _knots(live, np.zeros(cols, dtype=np.int8), walks, across, nearest)
    natural = natural[walks]
    if not natural.any():
        return as_drawn, natural, walks, of
    # (a number of the drawing only is stored as drawn either way: walked once)
    built = natural != 0
    as_built = as_drawn.copy()
    as_built[:, built] = _knots(live, natural, np.flatnonzero(built), across[built], nearest[walks])
    built = as_built.sum(axis=0) < as_drawn.sum(axis=0)
    return np.where(built, as_built, as_drawn), np.where(built, natural, 0).astype(np.int8), walks, of


def same_walk(drawn: np.ndarray, kinds: np.ndarray, nearest: np.ndarray) -> np.ndarray:
    """For each column of the drawn numbers *drawn* (grid values x columns), stored as *kinds*, taken from the
    nearer grid value where *nearest*: the first column with the same numbers (to the bit), kind and nearness
    (:func:`column_knots` walks that one alone for all of them).

    >>> same_walk(np.array([[0.0, 0.0, 0.0, -0.0], [2.0, 2.0, 2.0, 2.0]]), np.array([1, 1, 2, 1]),
    ...           np.zeros(4, dtype=bool)).tolist()
    [0, 0, 2, 3]
    """
    return _first_alike((*np.ascontiguousarray(drawn).view(np.int64), kinds.astype(np.int64) * 2 + nearest))


def _first_alike(rows: Sequence[np.ndarray]) -> np.ndarray:
    """For each column of the integer *rows* (each a row of as many numbers), the first column equal to it in
    every row.

    A column is known by two weighted sums of its numbers (integer arithmetic, wrapping, row by row: no copy of
    the rows turned on their side, no sort of the columns), and every column is then compared whole with the
    first one of its sums: two different columns with the same sums are told apart by their bytes.

    >>> _first_alike([np.array([1, 2, 1, 1]), np.array([3, 4, 3, 5])]).tolist()
    [0, 1, 0, 3]
    """
    cols = len(rows[0])
    weights = np.random.default_rng(28).integers(1, 2 ** 62, size=(len(rows), 2), dtype=np.int64)
    sums = np.zeros((2, cols), dtype=np.int64)
    with np.errstate(over="ignore"):
        for row, w in zip(rows, weights):
            sums[0] += row * w[0]
            sums[1] += row * w[1]
    seen: dict[tuple[int, int], int] = {}
    like = np.fromiter((seen.setdefault(s, c) for c, s in enumerate(zip(*sums.tolist()))), dtype=np.int64,
                       count=cols)
    dup = np.flatnonzero(like != np.arange(cols))  # (a column is itself: only those like an earlier one)
    of = like[dup]
    if not all((row[dup] == row[of]).all() for row in rows):  # two columns with the same sums: by their bytes
        whole = np.ascontiguousarray(np.vstack(rows).T)
        by_bytes: dict[bytes, int] = {}
        like = np.fromiter((by_bytes.setdefault(whole[c].tobytes(), c) for c in range(cols)), dtype=np.int64,
                           count=cols)
    return like


def encode(live: LiveSweep) -> dict[str, Any]:
    """The coordinates of *live* for the page: identical columns once, each column at its own grid values and
    in its own units (:func:`column_knots`), quantised, delta-coded, deflated, base64.

    One deflated buffer: the column map (which stored column each coordinate is; uint16 or int32), each stored
    column's kind (uint8; 128 added where its deltas are int32), its kept grid values as bits, the fit of every
    grid value (3 float32), each stored column's first value (int32), then the deltas between its kept values,
    all columns one after the other, as int16 in byte planes (all low bytes, then all high bytes: the high bytes
    of small deltas are runs of 0 and 255 that deflate squeezes away), then those of the int32 columns in four
    planes.  :func:`construct.render.wire.decode` is what the page does.

    >>> from construct.constructions.domain import ROD_RATIO
    >>> from construct.render.wire import decode
    >>> live = LiveSweep("rod_ratio", "L/r", ROD_RATIO, 5.0, np.array([1.0, 10 ** 0.5, 10.0]), [("p", "cx", "#"),
    ...     ("q", "cx", "#"), ("r", "cx", "#")], np.array([[0.0, 0.0, 0], [5.0, 7.0, 5], [10.0, 10.0, 10]]), 0.0,
    ...     u=np.array([0.0, 0.5, 1.0]), start=2)
    >>> e = encode(live); e["ucols"], decode(e, [0.0, 0.5, 1.0], 3, 3).tolist()
    (2, [[0.0, 0.0, 0.0], [5.0, 7.0, 5.0], [10.0, 10.0, 10.0]])
    """
    rows = live.drawn.shape[0]
    # (the columns alike in their numbers, kind and nearness are stored alike: each set's first stands for them)
    keep, kinds, walks, of = _walked_knots(live)
    quanta = _quanta(live, kinds)
    q = np.round(as_stored(live.drawn[:, walks], live.fit, kinds) / quanta).astype(np.int64)
    fit = live.fit if live.fit is not None else np.zeros((rows, 3))
    # identical columns (a point's coordinate in its circle, its lines, its arcs) travel once, with the union
    # of their kept values; stored in the order the columns first appear (neighbours stay neighbours)
    colmap, firsts = _same_columns(q, keep, kinds)
    colmap = colmap[of]
    pick = np.asarray(firsts, dtype=np.int64)
    uq, ukeep, ukinds = q[:, pick], keep[:, pick], kinds[pick]
    ukeep[[0, -1]] = True
    # every column's kept values one column after the other, and the steps between them (a column's first
    # value is not a step)
    values = uq.T[ukeep.T]
    counts = ukeep.sum(axis=0)
    first = np.zeros(values.size, dtype=bool)
    first[(np.cumsum(counts) - counts)[counts > 0]] = True
    column = np.repeat(np.arange(uq.shape[1]), counts)[~first]
    steps = np.diff(values, prepend=0)[~first]
    # a column whose steps do not fit int16 (a rod's arc of radius 1000 r by its logarithm, to a tenth of a
    # pixel) has its steps in int32, apart: the kind's high bit says which
    wide = np.zeros(uq.shape[1], dtype=bool)
    wide[column[np.abs(steps) >= 2 ** 15]] = True
    planes = b""
    for w, which in ((2, ~wide), (4, wide)):
        d = steps[which[column]]
        planes += np.ascontiguousarray(d.astype(f"<i{w}").view(np.uint8).reshape(-1, w).T).tobytes()
    mapw = 2 if uq.shape[1] < 2 ** 16 else 4
    payload = (colmap.astype(f"<u{mapw}").tobytes() + (ukinds.astype(np.uint8) | (wide * 128).astype(np.uint8)).tobytes()
               + np.packbits(ukeep.T.reshape(-1)).tobytes() + fit.astype("<f4").tobytes()
               + uq[0].astype("<i4").tobytes() + planes)
    return {"data": base64.b64encode(zlib.compress(payload, DEFLATE_LEVEL)).decode("ascii"), "mapw": mapw,
            "ucols": int(uq.shape[1]), "q": STORED_PX, "qx": float(_quanta(live, np.ones(1, dtype=np.int8))[0]),
            "ql": float(_quanta(live, np.full(1, LOG, dtype=np.int8))[0])}


def _same_columns(q: np.ndarray, keep: np.ndarray, kinds: np.ndarray) -> tuple[np.ndarray, list[int]]:
    """Which columns of (q, keep, kinds) are the same (grid x columns, each column's values, kept grid values
    and kind): for each column the number of the first one like it, counting those in order, and those firsts
    (:func:`_first_alike`; the kept values eight to a byte).

    >>> m, f = _same_columns(np.array([[1, 2, 1], [3, 4, 3]]), np.ones((2, 3), dtype=bool), np.zeros(3, dtype=np.int8))
    >>> m.tolist(), f
    ([0, 1, 0], [0, 1])
    """
    cols = q.shape[1]
    colmap = _first_alike((*q, *np.packbits(keep, axis=0).astype(np.int64), kinds.astype(np.int64)))
    firsts = np.flatnonzero(colmap == np.arange(cols))
    return np.searchsorted(firsts, colmap), firsts.tolist()


def live_data(live: LiveSweep) -> dict[str, Any]:
    """What the page needs: the given and its domain in the open; deflated: the grid (log10), the keys, which
    columns are drawn from the nearer grid value, the jumps (``meta_z``), the coordinates (``data``,
    :func:`encode`) and the checks (``checks_z``)."""
    # a jump: the index of its cell's lower grid value (the keys as they are: JSON writes a tuple as a list)
    where = {float(v): i for i, v in enumerate(live.grid)}
    meta = {"grid": [round(math.log10(v), 12) for v in live.grid],
            "keys": live.keys, "flags": live.nearest_columns().nonzero()[0].tolist(),
            "jumps": sorted(where[float(a)] for a, _ in live.jumps),
            **({"readings": live.reading_texts} if live.reading_texts else {}),
            **({"absent": live.furniture_absent} if live.furniture_absent else {})}
    given = live.live
    whole = live.whole or live.domain
    return {"given": live.given, "symbol": live.symbol, "low": whole.low, "high": whole.high,
            **({"piece": [live.domain.low, live.domain.high]} if live.whole is not None else {}),
            **({"unit": given.unit, "written": list(given.written), "rod": given.rod} if given is not None else {}),
            "initial": live.initial, "rows": int(live.drawn.shape[0]), "cols": int(live.drawn.shape[1]),
            "label_px": live.label_px, **({"areas": live.areas} if live.areas else {}),
            **({"derived": {k: {"values": v, "written": list(DERIVED_WRITTEN[k])} for k, v in live.derived.items()}}
               if live.derived else {}),
            **({"readings": live.readings} if live.readings else {}),
            **({"furniture_held": True} if live.furniture_held else {}),
            **({"furniture_note": live.furniture_note} if live.furniture_note else {}),
            **encode(live), "bound": round(live.bound + QUANTUM_PX / 2, 3),
            "meta_z": deflated(meta), "checks_z": deflated(_check_table(live))}


def _check_table(live: LiveSweep) -> dict[str, Any]:
    """The checks at up to CHECK_VALUES grid values, evenly in log10: names once, numbers to 9 digits."""
    if not live.checks:
        return {"checks": [], "check_values": [], "check_names": []}
    g = lambda x: float(f"{x:.9g}") if math.isfinite(x) else None  # noqa: E731
    at = [(float(live.grid[i]), live.checks[i]) for i in sorted(live.checks)]
    if live.built_checks and all(v != live.initial for v, _ in at):  # the book's value among them
        at = sorted(at + [(float(live.initial), live.built_checks)], key=lambda x: x[0])

    def row(c: list[Any]) -> list[Any]:
        # [formula, error, ok] and the constructed value where formula + error does not give its 9 digits
        # (a Euclidean chain's error is 1e-16: the constructed value is the formula's, to every digit shown)
        expected, error = g(c[2]), float(f"{c[3]:.2g}") if math.isfinite(c[3]) else None
        out = [expected, error, c[5]]
        if expected is None or error is None or g(expected + error) != g(c[1]):
            out.append(g(c[1]))
        return out

    return {"check_names": [c[0] for c in at[0][1]], "check_values": [v for v, _ in at],
            "checks": [[row(c) for c in cs] for _, cs in at]}


def live_pages(construction: Any, figure: Any, style: Any, *, drawing: Any = None) -> list[dict[str, Any]]:
    """The live data of every continuous given of *figure* (:func:`~construct.live.sweep.live_givens`), one sweep
    for each piece of its domain (:func:`~construct.live.sweep.pieces`): what the gallery's players and
    ``construct replay --live`` carry.  *drawing*: the figure's drawing in *style*, if the caller has it."""
    measure = Measure(construction, figure, style, drawing=drawing)  # (the givens' sweeps share it)
    out = []
    for g in live_givens(construction, figure):
        parts = pieces(construction, figure, g.name, reach(construction, figure, g.name, g.domain,
                                                          float(figure.replay.givens[g.name])))
        out += [live_data(live_sweep(construction, figure, g.name, style=style, drawing=drawing, measure=measure,
                                     piece=p if len(parts) > 1 else None)) for p in parts]
    return out
