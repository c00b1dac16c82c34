"""Which element of drawing A is which element of drawing B, in time near-linear in their number.

Four passes, each over what the earlier ones left: elements with the same
``id``; anonymous elements aligned by content (an inserted one must not shift
every later key into a change); anonymous elements with the same key; and
what is left by kind and nearest geometry (a renamed element is "renamed",
not missing + extra).

The costs are kept near-linear (two drawings of a million elements, one
moved, used to take minutes in ``list.remove`` and an all-pairs search):

* the content alignment interns each element's tolerance-rounded
  fingerprint as a small integer, keeps equal runs at both ends in place,
  anchors the middle on elements that occur once on each side (their
  longest order-preserving chain, as patience diff does) and runs difflib's
  alignment only on stretches of at most :data:`_DIFFLIB_AREA` pairs -- the
  whole sequences when they are that small, so small drawings align exactly
  as before;
* the geometry pass compares an element only with those of its tag and kind
  whose bounding-box corner lies in its own or a neighbouring cell of a grid
  as wide as the matching limit (a pair farther apart than the limit in x or
  y cannot be within it), and makes at most :data:`MATCH_BUDGET` comparisons.
"""

from __future__ import annotations

import bisect
import difflib
import math
from collections import Counter, defaultdict, deque
from typing import Any, Callable, Hashable, Sequence

from .parse import Drawing, Shape

__all__ = ["MATCH_BUDGET", "bounding_box", "drawing_extent", "match_shapes"]

#: Distance computations the geometry pass makes at most.  All pairs of 2000 x 2000 leftover
#: elements, as many as the all-pairs search allowed: within it the pass finds exactly what that
#: search found; beyond it (dense clusters of unmatched elements) the elements whose
#: neighbourhoods would exceed it stay unmatched, reported missing and extra, rather than hang.
MATCH_BUDGET = 4_000_000
#: Stretches of at most this many pairs (length A x length B) are aligned by difflib: its cost
#: grows with that product where elements repeat (many identical-looking circles).
_DIFFLIB_AREA = 1_000_000


def match_shapes(sa: Sequence[Shape], sb: Sequence[Shape], tol: float, extent: float = 0.0
           ) -> list[tuple[Shape, Shape, str]]:
    """Pairs (a, b, how): by id, by aligned equal content, by key, by nearest geometry."""
    pairs: list[tuple[Shape, Shape, str]] = []
    used_a, used_b = bytearray(len(sa)), bytearray(len(sb))

    def take(i: int, j: int, how: str) -> None:
        pairs.append((sa[i], sb[j], how))
        used_a[i] = used_b[j] = 1

    ids_b = {s.key: j for j, s in enumerate(sb) if s.has_id}
    for i, x in enumerate(sa):
        if x.has_id and x.key in ids_b:
            take(i, ids_b[x.key], "id")
    # Anonymous elements: an inserted one must not shift every later key into a "change".
    anon_a = [i for i, s in enumerate(sa) if not used_a[i] and not s.has_id]
    anon_b = [j for j, s in enumerate(sb) if not used_b[j] and not s.has_id]
    intern: dict[tuple, int] = {}
    fingerprint = _fingerprinter(tol)
    fa = [intern.setdefault(fingerprint(sa[i]), len(intern)) for i in anon_a]
    fb = [intern.setdefault(fingerprint(sb[j]), len(intern)) for j in anon_b]
    del intern
    for p, q in _align(fa, fb):
        i, j = anon_a[p], anon_b[q]
        take(i, j, "key" if sa[i].key == sb[j].key else "order")
    keys_b = {sb[j].key: j for j in anon_b if not used_b[j]}
    for i in anon_a:
        if not used_a[i]:
            j = keys_b.get(sa[i].key)
            if j is not None and sb[j].kind == sa[i].kind:
                del keys_b[sa[i].key]
                take(i, j, "key")
    # What is left: same kind, nearest geometry, if clearly the same element.
    # "Clearly the same": within 2 % of the drawing's size (points, radii and viewBox).
    limit = max(tol, 0.02 * max(_diagonal(sa, sb), extent))
    free_a = [i for i in range(len(sa)) if not used_a[i]]
    free_b = [j for j in range(len(sb)) if not used_b[j]]
    candidates = _near_pairs([sa[i] for i in free_a], [sb[j] for j in free_b], limit, MATCH_BUDGET)
    candidates.sort()
    chosen_a: set[int] = set()
    chosen_b: set[int] = set()
    for d, i, j in candidates:
        if i not in chosen_a and j not in chosen_b:
            chosen_a.add(i)
            chosen_b.add(j)
            take(free_a[i], free_b[j], "geometry")
    return pairs


# -- aligning equal content ---------------------------------------------------------------------

def _fingerprinter(tol: float) -> Callable[[Shape], tuple]:
    """:meth:`Shape.fingerprint` with the shared parts (styles) rounded once, not once per element."""
    q = max(tol, 1e-12)
    memo: dict[Any, Any] = {}

    def r(v: Any) -> Any:
        if isinstance(v, float):
            return round(v / q)
        if isinstance(v, tuple):
            return tuple(r(x) for x in v)
        return v

    def shared(v: Any) -> Any:
        if not v:
            return v
        got = memo.get(v)
        if got is None:
            got = memo[v] = r(v)
        return got

    def fingerprint(s: Shape) -> tuple:
        # points, sizes and angles are (name, point) and (name, number) of floats (the parser's
        # geometry): rounded directly, the same values r() gives, without its walk
        return (s.tag, s.kind, tuple((n, (round(p[0] / q), round(p[1] / q))) for n, p in s.points),
                tuple((n, round(v / q)) for n, v in s.sizes), tuple((n, round(v / q)) for n, v in s.angles),
                s.structure, s.text, shared(s.style), shared(s.animations), s.described)

    return fingerprint


def _align(fa: list[int], fb: list[int]) -> list[tuple[int, int]]:
    """Index pairs (p, q) with fa[p] == fb[q], increasing in both: an order-preserving alignment."""
    if len(fa) * len(fb) <= _DIFFLIB_AREA:
        return _difflib_pairs(fa, 0, len(fa), fb, 0, len(fb))
    out: list[tuple[int, int]] = []
    _align_stretch(fa, 0, len(fa), fb, 0, len(fb), out, anchor=True)
    return out


def _difflib_pairs(fa: list[int], a0: int, a1: int, fb: list[int], b0: int, b1: int) -> list[tuple[int, int]]:
    matcher = difflib.SequenceMatcher(None, fa[a0:a1], fb[b0:b1], autojunk=False)
    return [(a0 + block.a + k, b0 + block.b + k) for block in matcher.get_matching_blocks() for k in range(block.size)]


def _align_stretch(fa: list[int], a0: int, a1: int, fb: list[int], b0: int, b1: int,
                   out: list[tuple[int, int]], anchor: bool) -> None:
    # Equal runs at both ends stay where they are (what any alignment of the two keeps).
    while a0 < a1 and b0 < b1 and fa[a0] == fb[b0]:
        out.append((a0, b0))
        a0, b0 = a0 + 1, b0 + 1
    while a0 < a1 and b0 < b1 and fa[a1 - 1] == fb[b1 - 1]:
        a1, b1 = a1 - 1, b1 - 1
        out.append((a1, b1))
    if a0 == a1 or b0 == b1:
        return
    if (a1 - a0) * (b1 - b0) <= _DIFFLIB_AREA:
        out.extend(_difflib_pairs(fa, a0, a1, fb, b0, b1))
        return
    if anchor:
        # Elements that occur once on each side, in their longest order-preserving chain, cut the
        # stretch into smaller ones (patience diff); a stretch is cut once, so the cost stays n log n.
        count_a, count_b = Counter(fa[a0:a1]), Counter(fb[b0:b1])
        at_b = {fb[j]: j for j in range(b0, b1) if count_b[fb[j]] == 1 and count_a[fb[j]] == 1}
        chain = _longest_chain([(i, at_b[fa[i]]) for i in range(a0, a1) if fa[i] in at_b])
        if chain:
            pa, pb = a0, b0
            for i, j in chain:
                _align_stretch(fa, pa, i, fb, pb, j, out, anchor=False)
                out.append((i, j))
                pa, pb = i + 1, j + 1
            _align_stretch(fa, pa, a1, fb, pb, b1, out, anchor=False)
            return
    # A long stretch of repeated elements: each paired with the next equal one after the last pair.
    waiting: dict[int, deque[int]] = defaultdict(deque)
    for j in range(b0, b1):
        waiting[fb[j]].append(j)
    last = b0 - 1
    for i in range(a0, a1):
        queue = waiting.get(fa[i])
        while queue and queue[0] <= last:
            queue.popleft()
        if queue:
            last = queue.popleft()
            out.append((i, last))


def _longest_chain(pairs: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """The longest run of *pairs* (increasing in the first) that also increases in the second.

    >>> _longest_chain([(0, 3), (1, 0), (2, 1), (3, 4), (4, 2)])
    [(1, 0), (2, 1), (4, 2)]
    """
    tails: list[int] = []   # the smallest last second value of a chain of each length
    ends: list[int] = []    # which pair ends it
    before = [-1] * len(pairs)
    for k, (_, j) in enumerate(pairs):
        n = bisect.bisect_left(tails, j)
        if n == len(tails):
            tails.append(j)
            ends.append(k)
        else:
            tails[n], ends[n] = j, k
        before[k] = ends[n - 1] if n else -1
    chain = []
    k = ends[-1] if ends else -1
    while k >= 0:
        chain.append(pairs[k])
        k = before[k]
    return chain[::-1]


# -- nearest geometry -----------------------------------------------------------------------------

def _kind_key(s: Shape) -> Hashable:
    """Shapes of different keys are never near (:func:`_distance` is infinite between them)."""
    return (s.tag, s.kind, s.animations, s.described) if s.kind == "group" else (s.tag, s.kind)


def _near_pairs(xs: Sequence[Shape], ys: Sequence[Shape], limit: float, budget: int) -> list[tuple[float, int, int]]:
    """Every (distance, i, j) with ``_distance(xs[i], ys[j]) <= limit``, at most *budget* distances computed.

    Within the limit, two shapes' bounding-box corners (min x, min y) differ by at most the limit
    in each axis, so a grid of cells as wide as the limit holds them in the same or neighbouring
    cells.  A shape with a point that is not finite is compared with every shape of its kind.

    >>> from construct.regress.svgdiff import parse_svg
    >>> d = parse_svg('<svg xmlns="http://www.w3.org/2000/svg"><circle r="1"/><circle cx="50" r="1"/></svg>')
    >>> e = parse_svg('<svg xmlns="http://www.w3.org/2000/svg"><circle cx="50.5" r="1"/><circle cx="0.2" r="1"/></svg>')
    >>> sorted(_near_pairs(d.shapes, e.shapes, 1.0, 100))
    [(0.2, 0, 1), (0.5, 1, 0)]
    """
    # cells a little wider than the limit: two corners whose difference rounds to the limit may differ by a
    # hair more (1.0 and -7e-29 are 1.0 apart in floating point), and would land two cells apart
    size = limit * (1.0 + 1e-9)

    def cell(s: Shape) -> tuple | None:
        if not all(math.isfinite(v) for _, p in s.points for v in p):
            return None
        x0, y0, _, _ = bounding_box(s)
        if limit <= 0:
            return (x0, y0)
        gx, gy = x0 / size, y0 / size
        return (math.floor(gx), math.floor(gy)) if math.isfinite(gx) and math.isfinite(gy) else None

    grid: dict[Hashable, dict[tuple, list[int]]] = defaultdict(lambda: defaultdict(list))
    wild: dict[Hashable, list[int]] = defaultdict(list)
    every: dict[Hashable, list[int]] = defaultdict(list)
    for j, y in enumerate(ys):
        kind, c = _kind_key(y), cell(y)
        (wild[kind] if c is None else grid[kind][c]).append(j)
        every[kind].append(j)
    steps = ((-1, -1), (-1, 0), (-1, 1), (0, -1), (0, 0), (0, 1), (1, -1), (1, 0), (1, 1)) if limit > 0 else ((0, 0),)
    out: list[tuple[float, int, int]] = []
    spent = 0
    for i, x in enumerate(xs):
        kind = _kind_key(x)
        if kind not in every:
            continue
        c = cell(x)
        if c is None:
            near = every[kind]
        else:
            cells = grid[kind]
            near = [j for dx, dy in steps for j in cells.get((c[0] + dx, c[1] + dy), ())] + wild.get(kind, [])
        if spent + len(near) > budget:
            continue  # a dense cluster: left unmatched rather than searched pair by pair
        spent += len(near)
        for j in near:
            d = _distance(x, ys[j])
            if d <= limit:
                out.append((d, i, j))
    return out


def drawing_extent(d: Drawing) -> float:
    """The size of a drawing: its viewBox diagonal, or the largest radius or length drawn."""
    doc = dict(d.document)
    vb = doc.get("viewBox")
    sizes = [abs(v) for s in d.shapes for _, v in s.sizes]
    return max([math.hypot(vb[2], vb[3]) if vb else 0.0] + sizes)


def _diagonal(*drawings: Sequence[Shape]) -> float:
    """The diagonal of the box around every point of the shapes."""
    xs = [p[0] for shapes in drawings for s in shapes for _, p in s.points]
    if not xs:
        return 0.0
    x_span = max(xs) - min(xs)
    del xs
    ys = [p[1] for shapes in drawings for s in shapes for _, p in s.points]
    return math.hypot(x_span, max(ys) - min(ys))


def bounding_box(s: Shape) -> tuple[float, float, float, float]:
    """(min x, min y, max x, max y) of the defining points of *s*."""
    xs = [p[0] for _, p in s.points] or [0.0]
    ys = [p[1] for _, p in s.points] or [0.0]
    return min(xs), min(ys), max(xs), max(ys)


def _distance(x: Shape, y: Shape) -> float:
    if x.kind != y.kind or x.tag != y.tag or (x.kind == "text" and x.text != y.text and x.points != y.points):
        return math.inf
    if x.kind == "group":
        return 0.0 if (x.animations, x.described) == (y.animations, y.described) else math.inf
    if [n for n, _ in x.points] == [n for n, _ in y.points] and [n for n, _ in x.sizes] == [n for n, _ in y.sizes]:
        d = max((math.dist(p, q) for (_, p), (_, q) in zip(x.points, y.points)), default=0.0)
        return max([d] + [abs(u - v) for (_, u), (_, v) in zip(x.sizes, y.sizes)])
    ba, bb = bounding_box(x), bounding_box(y)
    return max(abs(u - v) for u, v in zip(ba, bb))
