"""The name tags' placing (construct/render/tags.py): the moves pass asks of all tags at once whether each one's
spot is free of the level's letters, points and result lines; that agrees with a plain walk, box by box and line by
line."""

from __future__ import annotations

import numpy as np
import pytest

from construct.render.tags import spots_clear


def _clear_plain(box, dots, lines, taken, r, e) -> bool:
    """One box, in plain Python: no taken box overlaps it, no point's square of half side *r* meets it, and no line
    segment has a point inside the box grown by *e* (the segment clipped to the box's slabs, per axis)."""
    x0, y0, x1, y1 = box
    if any(c[0] < x1 and x0 < c[2] and c[1] < y1 and y0 < c[3] for c in taken):
        return False
    if any(px - r < x1 and x0 < px + r and py - r < y1 and y0 < py + r for px, py in dots):
        return False
    lo, hi = (x0 - e, y0 - e), (x1 + e, y1 + e)
    for ax, ay, bx, by in lines:
        t0, t1 = 0.0, 1.0
        for p, d, a, b in ((ax, bx - ax, lo[0], hi[0]), (ay, by - ay, lo[1], hi[1])):
            if d == 0:
                if not a <= p <= b:
                    t0, t1 = 1.0, 0.0
            else:
                ta, tb = (a - p) / d, (b - p) / d
                t0, t1 = max(t0, min(ta, tb)), min(t1, max(ta, tb))
        if t0 <= t1:
            return False
    return True


@pytest.mark.parametrize("seed", range(4))
def test_spots_clear_agrees_with_a_plain_walk(seed):
    rng = np.random.default_rng(seed)
    n, m, p, k = 60, 40, 300, 25
    xy = rng.uniform(0, 200, (n, 2))
    boxes = np.concatenate([xy, xy + rng.uniform(2, 20, (n, 2))], axis=1)
    dots = rng.uniform(0, 200, (m, 2))
    a = rng.uniform(0, 200, (p, 2))
    b = a + rng.uniform(-40, 40, (p, 2))
    b[: p // 6, 0] = a[: p // 6, 0]  # upright lines
    b[p // 6: p // 3, 1] = a[p // 6: p // 3, 1]  # level lines
    b[-3:] = a[-3:]  # single points
    lines = np.concatenate([a, b], axis=1)
    txy = rng.uniform(0, 200, (k, 2))
    taken = np.concatenate([txy, txy + 8.0], axis=1)
    got = spots_clear(boxes, dots, lines, taken, 1.5, 0.75).tolist()
    want = [_clear_plain(bx, dots.tolist(), lines.tolist(), taken.tolist(), 1.5, 0.75) for bx in boxes.tolist()]
    assert got == want
    assert 0 < sum(want) < n  # both answers met


def test_a_line_touching_the_grown_box_crosses_it():
    box = np.array([[10.0, 10.0, 20.0, 20.0]])
    touching = np.array([[0.0, 9.5, 30.0, 9.5]])  # along the box's edge grown by 0.5
    assert spots_clear(box, np.zeros((0, 2)), touching, np.zeros((0, 4)), 1.0, 0.5).tolist() == [False]
    assert spots_clear(box, np.zeros((0, 2)), touching + [0, -0.01, 0, -0.01], np.zeros((0, 4)), 1.0, 0.5).tolist() == [True]


def test_the_tags_spots_are_the_same_asked_a_few_pairs_or_all_at_once(crank6, monkeypatch):
    """place_tags asks the (tag, obstacle) pairs of a level a few tags at a time (_PAIRS_AT_ONCE); a tag per chunk
    and all tags in one give the same spots."""
    import construct.render.tags as tags
    from construct.render.output import scene_for
    from construct.render.styles import STYLES
    from construct.render.svg import Drawing

    c, fig = crank6
    st = STYLES["teaching"]
    got = []
    for n in (1, 10**9):
        monkeypatch.setattr(tags, "_PAIRS_AT_ONCE", n)
        got.append(Drawing(scene_for(c, fig, ending=st.camera), st).placing.tag_spots)
    assert got[0]  # tags were placed
    assert got[0] == got[1]
