"""Where the letters go (construct/render/lettering.py): font metrics, the placer, the line index.

Expectations come from the font file's metrics (DejaVu Sans' hmtx table), from shapely's geometry and
from boxes worked out here -- never from the placer's own answers.
"""

from __future__ import annotations

import itertools
import math
import random

import numpy as np
import pytest

from construct.render.lettering import (LEADER_FROM, LineIndex, label_box, line_pieces, line_pieces_one_by_one, place,
                                        spots_of, text_box, text_width)


def test_letters_are_measured_in_the_fonts_metrics():
    """DejaVu Sans (hmtx, 2048 units to the em): 'W' 2025, 'i' 569; a character count would make them equal."""
    w = text_box(0, 0, "W", 100.0)
    i = text_box(0, 0, "i", 100.0)
    assert w[2] - w[0] == pytest.approx(100 * 2025 / 2048, abs=0.01)
    assert i[2] - i[0] == pytest.approx(100 * 569 / 2048, abs=0.01)


def test_a_dense_family_is_never_stacked_and_keeps_clear_of_result_lines():
    """Forty result letters on points 3 px apart on a result line: placed ones never overlap, never touch
    the line or another point; what finds no room is thin (shown only magnified), never dropped."""
    size = 12.0
    pts = [(100.0 + 3.0 * i, 200.0) for i in range(40)]
    items = [(f"p{i}", "result", i, p, (0.0, -1.0), f"{i + 1}′") for i, p in enumerate(pts)]
    line = [(50.0, 200.0, 250.0, 200.0)]
    spots = place(items, size, pts, line)
    assert set(spots) == {f"p{i}" for i in range(40)}
    shown = [(i, label_box(x, y, items[int(i[1:])][5], size)) for i, (x, y, _d, thin) in spots.items() if not thin]
    assert 3 <= len(shown) < 40
    for (_a, b1), (_b, b2) in itertools.combinations(shown, 2):
        assert not (b1[0] < b2[2] and b2[0] < b1[2] and b1[1] < b2[3] and b2[1] < b1[3])
    for _i, b in shown:
        assert not (b[1] < 200.0 < b[3])  # the line y = 200 does not strike the letter
        assert not any(b[0] < x < b[2] and b[1] < y < b[3] for x, y in pts)




def test_the_line_index_answers_as_shapely_does():
    """Does a segment cross a box?  The index (pieces in a grid, clipped) against shapely's intersects."""
    from shapely.geometry import LineString, box

    rng = random.Random(7)
    segs = [(rng.uniform(0, 400), rng.uniform(0, 400), rng.uniform(0, 400), rng.uniform(0, 400)) for _ in range(60)]
    index = LineIndex(12.0, segs)
    for _ in range(400):
        x, y, w, h = rng.uniform(0, 400), rng.uniform(0, 400), rng.uniform(2, 40), rng.uniform(2, 20)
        b = (x, y, x + w, y + h)
        want = any(LineString([s[:2], s[2:]]).intersects(box(*b)) for s in segs)
        assert index.meets(b) == want, b


def test_the_line_index_cuts_its_lines_on_arrays_as_one_by_one_to_the_bit():
    """line_pieces (every segment's pieces at once) against the rule one piece at a time: the same cells, the
    same pieces to the last bit, in the same order -- on short, long, degenerate, negative and far segments, at
    the cell sizes letters are placed with (one rule in two forms: the faster copy must not drift)."""
    rng = np.random.default_rng(28)
    segs = rng.uniform(-300, 900, (400, 4))
    segs[::7, 2:] = segs[::7, :2] + rng.uniform(-3, 3, (len(segs[::7]), 2))  # short: one piece
    segs[::11, 2:] = segs[::11, :2]  # a point
    segs[5] = (0.0, 0.0, 1e6, 0.0)  # far beyond the sheet: left out, its number skipped
    segs[6] = (-0.0, -0.0, -0.0, 18.0)  # exactly on cell edges
    as_tuples = [tuple(s) for s in segs.tolist()]
    for cell in (12.0, 1.5 * 9.5, 1.5 * 12.0 * 2.7, 100.0):
        want = line_pieces_one_by_one(as_tuples, cell)
        got = line_pieces(segs, cell)
        assert got[0] == want[0] and got[2] == want[2]
        assert np.array_equal(np.array(got[1]).view(np.int64), np.array(want[1]).view(np.int64))
        assert 5 not in got[2] and len(got[1]) > len(segs)
    assert line_pieces([], 12.0) == ([], [], [])


def test_placed_letters_keep_clear_of_each_other_and_of_the_points():
    rng = random.Random(3)
    pts = [(rng.uniform(100, 300), rng.uniform(100, 300)) for _ in range(60)]
    items = [(f"p{i}", "given" if i % 3 else "result", i, p, (1.0, 0.0), f"P{i}") for i, p in enumerate(pts)]
    spots = place(items, 12.0, pts)
    shown = {i: label_box(x, y, f"P{i[1:]}", 12.0) for i, (x, y, _d, thin) in spots.items() if not thin}
    assert len(shown) > 20
    for a, b in itertools.combinations(shown.values(), 2):
        assert not (a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3])
    r = 0.3 * 12.0  # a point marker's reach
    for b in shown.values():
        assert not any(b[0] < x + r and x - r < b[2] and b[1] < y + r and y - r < b[3] for x, y in pts)
    # every letter stands off its point, and one farther than LEADER_FROM letter heights says how far
    assert all(0.0 < dist for _x, _y, dist, _t in spots.values())
    assert any(dist >= LEADER_FROM for _x, _y, dist, _t in spots.values())  # 60 points: some are crowded


def test_a_letter_is_set_on_its_baseline_and_centred():
    """text_box of a centred letter is symmetric about x; the baseline is y, the ink above it (y down)."""
    b = text_box(50.0, 80.0, "H", 20.0)
    assert (b[0] + b[2]) / 2 == pytest.approx(50.0, abs=0.01) and b[3] == pytest.approx(80.0, abs=1e-9) and b[1] < 80.0
    halo = label_box(50.0, 80.0, "H", 20.0, halo=2.0)
    assert halo == pytest.approx((b[0] - 2.0, b[1] - 2.0, b[2] + 2.0, b[3] + 2.0))


def test_the_collision_grid_files_boxes_in_bulk_as_one_by_one():
    """_Grid.add_many (every box's cells found at once) files each box in the cells, and in the order within each
    cell, that _Grid.add gives it box by box: points across cell borders, on them exactly, at negative
    coordinates, a box spanning many cells (one rule in two forms: the faster copy must not drift)."""
    from construct.render.lettering import _Grid

    rng = np.random.default_rng(28)
    xy = np.concatenate([rng.uniform(-60, 60, (2000, 2)), 7.5 * rng.integers(-8, 8, (200, 2))])
    r = rng.choice([0.9, 3.6, 7.5], len(xy))[:, None]
    boxes = np.concatenate([xy - r, xy + r], axis=1)
    grids = []
    for cell, rows in ((7.5, boxes), (3.0, boxes), (7.5, np.array([[-40.0, -40.0, 41.0, 12.0], [0.0, 0.0, 1.0, 1.0]]))):
        one, bulk = _Grid(cell), _Grid(cell)
        grids.append(one)
        for b in map(tuple, rows.tolist()):
            one.add(b)
        bulk.add_many(rows)
        assert bulk.cells == one.cells
        assert list(bulk.cells) == list(one.cells)
    # (crowded cells, and boxes in two or four cells: the cases filed in order)
    assert max(len(v) for v in grids[0].cells.values()) > 20 and sum(map(len, grids[0].cells.values())) > 2 * len(boxes)


class _Looked(tuple):
    """A filed box that counts how often the grid reads it."""

    reads = 0

    def __getitem__(self, k):
        _Looked.reads += 1
        return tuple.__getitem__(self, k)


def test_the_collision_grid_answers_as_a_search_of_every_box_and_looks_in_the_spots_own_cell_first():
    """The grid the placer asks whether a spot is free gives the answer a look at every filed box gives (boxes
    on cell borders, at negative coordinates, a dense ring of points); and a spot blocked by a box in the cell
    of its centre is answered there, not after a crowd filed in a corner cell it barely reaches (a circle
    divided in 3600 parts tried sixty spots for each of its 3600 numbers)."""
    import math

    from construct.render.lettering import _Grid

    rng = random.Random(11)
    boxes = []
    for k in range(900):  # a dense ring, 0.7 px apart, points 6 px across
        a = 2 * math.pi * k / 900
        x, y = 100 * math.cos(a), 100 * math.sin(a)
        boxes.append((x - 3, y - 3, x + 3, y + 3))
    boxes += [(float(i), float(j), float(i) + 10, float(j) + 10) for i in (-30, 0, 30) for j in (-20, 10)]
    grid = _Grid(10.0)
    for b in boxes:
        grid.add(b)
    spots = [(x, y, x + rng.choice((0.0, 6.0, 10.0)), y + rng.choice((0.0, 4.0, 10.0)))
             for x, y in ((rng.choice((rng.uniform(-120, 120), 10.0 * rng.randint(-12, 12))),
                           rng.choice((rng.uniform(-120, 120), 10.0 * rng.randint(-12, 12)))) for _ in range(3000))]
    expected = [not any(s[0] < b[2] and b[0] < s[2] and s[1] < b[3] and b[1] < s[3] for b in boxes) for s in spots]
    assert [grid.free(s) for s in spots] == expected
    assert 0 < sum(expected) < len(spots)
    # cells holding hundreds of boxes (asked with numpy, all at once: 3600 piston positions on a stroke line),
    # and boxes added between the questions
    from construct.render.lettering import _CROWD

    crowd = _Grid(10.0)
    filed = []
    for k in range(3000):
        x, y = rng.uniform(200, 260), rng.uniform(200, 230)
        filed.append((x, y, x + rng.uniform(0.0, 1.5), y + rng.uniform(0.0, 1.5)))
        crowd.add(filed[-1])
        if k % 500 == 499:
            tried = [(x, y, x + rng.uniform(0.1, 2.0), y + rng.uniform(0.1, 2.0))
                     for x, y in ((rng.uniform(190, 270), rng.uniform(190, 240)) for _ in range(400))]
            s, b = np.array(tried)[:, None, :], np.array(filed)[None, :, :]  # every spot against every box
            want = (~((s[..., 0] < b[..., 2]) & (b[..., 0] < s[..., 2]) & (s[..., 1] < b[..., 3])
                      & (b[..., 1] < s[..., 3])).any(axis=1)).tolist()
            assert [crowd.free(s) for s in tried] == want, k
            assert 0 < sum(want) < len(tried)
    assert max(len(got) for got in crowd.cells.values()) > _CROWD

    crowded = _Grid(10.0)
    for k in range(500):  # a crowd in the far corner of cell (0, 0)
        crowded.add(_Looked((0.1 + k * 1e-3, 0.1, 0.2 + k * 1e-3, 0.2)))
    crowded.add(_Looked((14.0, 14.0, 16.0, 16.0)))  # in cell (1, 1)
    _Looked.reads = 0
    assert not crowded.free((8.0, 8.0, 18.0, 18.0))  # centre (13, 13): cell (1, 1)
    assert _Looked.reads <= 4  # the one box beside the centre, not the five hundred in the corner


def test_a_crowd_of_letters_is_placed_as_each_letter_would_be_alone(monkeypatch):
    """Three hundred letters on a crowd of points (a piston's positions along its stroke, a ring of crank points,
    helpers among them): the bulk placing (every spot made at once, those a point surely takes or a placed letter
    meets crossed off before the grid is asked) places every letter where asking each spot in turn puts it, and
    no placed letter's box meets another's or a point's."""
    import construct.render.lettering as lettering

    rng = random.Random(7)
    size = 12.0
    stroke = [(100.0 + 0.7 * i, 300.0) for i in range(200)]
    ring = [(400.0 + 60.0 * math.cos(0.06 * i), 200.0 + 60.0 * math.sin(0.06 * i)) for i in range(100)]
    items = [(f"p{i}", "result" if i % 3 else "construction", i, p, (0.0, -1.0), f"{i}′")
             for i, p in enumerate(stroke)]
    items += [(f"c{i}", rng.choice(["given", "construction"]), 200 + i, p, (p[0] - 400.0, 200.0 - p[1]), f"C{i}")
              for i, p in enumerate(ring)]
    dots = stroke + ring + [(rng.uniform(80, 480), rng.uniform(120, 320)) for _ in range(200)]
    lines = [(100.0, 300.0, 240.0, 300.0)]
    bulk = place(items, size, dots, lines)
    monkeypatch.setattr(lettering, "_CROWD", 10 ** 9)  # every letter asked spot by spot, as a few letters are
    assert place(items, size, dots, lines) == bulk
    text = {it[0]: it[5] for it in items}
    boxes = [label_box(x, y, text[i], size) for i, (x, y, _d, thin) in bulk.items() if not thin]
    assert len(boxes) > 20 and any(t for *_, t in bulk.values())
    r = 0.3 * size
    for a, b in itertools.combinations(boxes, 2):
        assert not (a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3])
    for x, y in dots:
        assert not any(b[0] < x + r and x - r < b[2] and b[1] < y + r and y - r < b[3] for b in boxes)


def test_a_letter_alone_takes_the_first_spot_free_of_the_boxes_and_points_in_the_order_tried():
    """spots_of's spots are label_box's boxes at their baselines, the centre *dist* letter heights out (plus half
    the extra width) along the turn; a letter placed alone among boxes and points stands at the first of them
    that meets none (worked out here box by box), the farther rings included."""
    size, text, p = 12.0, "M12", (300.0, 300.0)
    item = ("a", "construction", 1, p, (1.0, 0.0), text)
    lx, ly, x0, y0, x1, y1, dist = spots_of([item], size, distances=(4.5, 8.0))
    extra = max(0.0, text_width(text, size) - 0.6 * size) / 2
    for i in range(lx.shape[1]):
        assert (x0[0, i], y0[0, i], x1[0, i], y1[0, i]) == label_box(lx[0, i], ly[0, i], text, size)
        along, across = lx[0, i] - p[0], ly[0, i] - 0.35 * size - p[1]  # the extra width lies along x only
        ratio = along / (dist[i] * size + extra)
        assert across ** 2 / (dist[i] * size) ** 2 + ratio ** 2 == pytest.approx(1.0, abs=1e-9)
    rng = random.Random(5)
    for _ in range(20):
        taken = [(p[0] + rng.uniform(-90, 90), p[1] + rng.uniform(-90, 90)) for _ in range(25)]
        taken = [(x, y, x + rng.uniform(5, 40), y + rng.uniform(5, 30)) for x, y in taken]
        dots = [(p[0] + rng.uniform(-60, 60), p[1] + rng.uniform(-60, 60)) for _ in range(15)]
        r = 0.3 * size
        walls = taken + [(x - r, y - r, x + r, y + r) for x, y in dots]
        want = next(((lx[0, i], ly[0, i]) for i in range(lx.shape[1])
                     if not any(x0[0, i] < w[2] and w[0] < x1[0, i] and y0[0, i] < w[3] and w[1] < y1[0, i]
                                for w in walls)), None)
        got = place([item], size, np.array(dots), taken=taken, keep=False, distances=(4.5, 8.0))
        assert (got["a"][:2] if "a" in got else None) == want
