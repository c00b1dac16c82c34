"""render/sheet.py: the broken axis's widest gap and the plate's points on its circles, against plain walks."""

import math

import numpy as np
import pytest

from construct.render.marks import Mark, MarkKind
from construct.render.sheet import _extents, _near_circles, _widest_gap


def _walk(spans, fraction):
    """The widest empty stretch, walked as a draftsman's eye walks the axis: spans by start (then end)."""
    spans = sorted(spans)
    total = spans[-1][1] - spans[0][0]
    best, reach = None, spans[0][1]
    for a, b in spans[1:]:
        if a > reach and (best is None or a - reach > best[1] - best[0]):
            best = (reach, a)
        reach = max(reach, b)
    if best is None or best[1] - best[0] <= fraction * total:
        return None
    return best[0], best[1], total


def _mark(i, kind, geom, straight=False):
    return Mark(f"m{i}", i, f"m{i}", kind, geom, "construction", "compass", "exact", straight=straight)


@pytest.mark.parametrize("seed", range(6))
def test_the_widest_gap_is_the_walks(seed):
    rng = np.random.default_rng(seed)
    marks, spans = [], {0: [], 1: []}
    for i in range(300):
        kind = rng.integers(5)
        if kind == 0:
            x, y = (float(v) for v in rng.choice([-3.0, 1.0, 5.0]) + rng.normal(0, 0.4, 2).round(1))
            marks.append(_mark(i, MarkKind.POINT, (x, y)))
            box = (x, y, x, y)
        elif kind == 1:
            cx, cy, r = (float(v) for v in rng.uniform(-2, 2, 3))
            r = abs(r)
            marks.append(_mark(i, MarkKind.CIRCLE, (cx, cy, r)))
            box = (cx - r, cy - r, cx + r, cy + r)
        elif kind == 2:
            a0, sw = (float(v) for v in rng.uniform(-4, 4, 2))
            marks.append(_mark(i, MarkKind.ARC, (0.0, 0.0, 1.5, a0, sw)))
            angles = [a0, a0 + sw] + [q * math.pi / 2 for q in range(math.ceil(min(a0, a0 + sw) / (math.pi / 2)),
                                                                    math.floor(max(a0, a0 + sw) / (math.pi / 2)) + 1)]
            xs, ys = [1.5 * math.cos(a) for a in angles], [1.5 * math.sin(a) for a in angles]
            box = (min(xs), min(ys), max(xs), max(ys))
        elif kind == 3:  # a line, and a rod to its crosshead: left out of the gap
            marks.append(_mark(i, MarkKind.SEGMENT, (-9.0, 0.0, 9.0, 0.0)))
            marks.append(_mark(1000 + i, MarkKind.CURVE, ((-9.0, 0.0), (1.0, 1.0)), straight=True))
            continue
        else:
            pts = tuple((float(x), float(y)) for x, y in rng.uniform(3, 6, (4, 2)))
            marks.append(_mark(i, MarkKind.CURVE, pts))
            box = (min(p[0] for p in pts), min(p[1] for p in pts), max(p[0] for p in pts), max(p[1] for p in pts))
        spans[0].append((box[0], box[2]))
        spans[1].append((box[1], box[3]))
    ext = _extents(marks)
    for axis in (0, 1):
        for fraction in (0.0, 0.05, 0.2):
            assert _widest_gap(marks, (), axis, fraction) == _walk(spans[axis], fraction)
            assert _widest_gap(marks, (), axis, fraction, ext) == _walk(spans[axis], fraction)


def test_a_gap_wide_enough_is_found_and_a_narrow_one_is_not():
    marks = [_mark(1, MarkKind.POINT, (0.0, 0.0)), _mark(2, MarkKind.POINT, (1.0, 0.0)),
             _mark(3, MarkKind.POINT, (10.0, 0.0))]
    assert _widest_gap(marks, (), 0, 0.2) == (1.0, 10.0, 10.0)
    assert _widest_gap(marks, (), 0, 0.95) is None
    assert _widest_gap(marks[:1], (), 0, 0.2) is None


@pytest.mark.parametrize("seed", range(4))
def test_the_points_near_the_circles_are_every_pairs(seed):
    """Every pair asked (the plain way) finds the same pairs as the bands: points on circles, just off them by the
    tolerance each way, at tangents and far away."""
    rng = np.random.default_rng(seed)
    c = np.column_stack([rng.uniform(-3, 3, 40), rng.uniform(-3, 3, 40), rng.uniform(0.1, 4, 40)])
    c[:5, 2] = 5.0
    e = 1e-9 * np.maximum(1.0, c[:, 2])
    pts = [rng.uniform(-4, 4, (300, 2))]
    for k in range(0, 40, 3):  # on the circle, and just inside and outside the tolerance
        a = rng.uniform(0, 2 * math.pi, 6)
        for dr in (0.0, 0.9, -0.9, 1.1, -1.1):
            r = c[k, 2] + dr * e[k]
            pts.append(np.column_stack([c[k, 0] + r * np.cos(a), c[k, 1] + r * np.sin(a)]))
        # the top and the bottom of the circle (a band's nearest y at the tangent)
        pts.append(np.array([[c[k, 0], c[k, 1] + c[k, 2]], [c[k, 0], c[k, 1] - c[k, 2]]]))
    p = np.vstack(pts)
    px, py = p[:, 0], p[:, 1]
    every = np.abs(np.hypot(px[None, :] - c[:, 0:1], py[None, :] - c[:, 1:2]) - c[:, 2:3]) <= e[:, None]
    want = sorted(zip(*(v.tolist() for v in np.nonzero(every))))
    assert len(want) > 100
    assert sorted(_near_circles(px, py, c, e)) == want


@pytest.mark.parametrize("name, params", [("crank", {"parts": 36, "rod_ratio": 5.0}),
                                          ("crank", {"parts": 12, "rod_ratio": 50.0}), ("crank-angle", {}),
                                          ("two-cranks", {}), ("piston-force", {})])
def test_the_kept_span_is_the_span_of_the_figure_broken(name, params):
    """kept_span on arrays is what breaking the points and curves (sheet.broken) and measuring them gives."""
    from construct.constructions import get
    from construct.render.scene import build_scene
    from construct.render.sheet import broken, kept_span, span_of

    marks = build_scene(get(name).figure(**params), break_axis=False).marks
    drawn = [m for m in marks if m.kind in (MarkKind.POINT, MarkKind.CURVE, MarkKind.AREA)]
    assert kept_span(marks) == span_of(broken(drawn, (), True)[0])
