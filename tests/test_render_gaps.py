"""Lines broken for letters (the engraver's gap): the parts left keep to the line and stay out of the gap.

Each expectation is geometry worked out here: where a straight line leaves a box (by similar triangles),
which points of an arc or a cubic lie in a box (tested point by point on the original curve), never the
module's own numbers.
"""

from __future__ import annotations

import math
import re

import pytest

from construct.render.gaps import Gap, arc_parts, curve_d, polyline_d, segment_parts
from construct.render.paths import bezier_controls


def _cubic(q, t):
    s = 1 - t
    return tuple(s ** 3 * a + 3 * s * s * t * b + 3 * s * t * t * c + t ** 3 * d for a, b, c, d in zip(*q))


def test_a_segment_is_cut_where_it_enters_and_leaves_the_box():
    # y = x / 2 from (0, 0) to (40, 20) through the box 10..20 x 0..20: enters at x = 10, leaves at x = 20
    parts = segment_parts((0.0, 0.0), (40.0, 20.0), [Gap.around((10.0, 0.0, 20.0, 20.0))])
    assert parts == [(0.0, pytest.approx(0.25)), (pytest.approx(0.5), 1.0)]


def test_a_turned_gap_cuts_along_its_own_axes():
    # a square of side 2 turned 45° about the origin: the x axis crosses it from -√2 to +√2
    g = Gap.around((-1.0, -1.0, 1.0, 1.0), angle=45.0)
    (t0, t1), (t2, t3) = segment_parts((-10.0, 0.0), (10.0, 0.0), [g])
    assert (t1 * 20 - 10, t2 * 20 - 10) == (pytest.approx(-math.sqrt(2)), pytest.approx(math.sqrt(2)))
    # the same square upright would leave the line from -1 to 1
    assert segment_parts((-10.0, 0.0), (10.0, 0.0), [Gap.around((-1.0, -1.0, 1.0, 1.0))])[0][1] * 20 - 10 == pytest.approx(-1)


def test_a_polyline_keeps_its_corners_and_leaves_out_the_gap():
    d = polyline_d([(0.0, 0.0), (10.0, 0.0), (10.0, 30.0)], [Gap.around((5.0, 10.0, 15.0, 20.0))])
    assert d == "M0 0L10 0L10 10M10 20L10 30"
    assert polyline_d([(0.0, 0.0), (10.0, 0.0)], []) == "M0 0L10 0"


def test_an_arc_is_cut_at_the_box_and_its_parts_stay_on_the_circle():
    # a circle of radius 50 about (0, 0), the box 40..60 x -10..10 across it at angle 0
    box = (40.0, -10.0, 60.0, 10.0)
    parts = arc_parts((0.0, 0.0), 50.0, -1.0, 2.0, [Gap.around(box)])
    assert len(parts) == 2
    # the cut falls where the circle meets y = -10 and y = 10: asin(10/50) either side of 0
    cut = math.asin(10 / 50)
    assert parts[0][0] == pytest.approx(-1.0) and parts[0][0] + parts[0][1] == pytest.approx(-cut, abs=1e-5)
    assert parts[1][0] == pytest.approx(cut, abs=1e-5) and parts[1][0] + parts[1][1] == pytest.approx(1.0)
    assert arc_parts((0.0, 0.0), 50.0, 2.0, 1.0, [Gap.around(box)]) is None  # an arc the box does not meet


def test_a_smooth_curve_is_broken_on_itself_and_nowhere_in_the_gap():
    pts = [(0.0, 0.0), (30.0, 40.0), (60.0, 10.0), (90.0, 50.0)]
    gap = Gap.around((25.0, 20.0, 45.0, 45.0))
    d = curve_d(pts, [gap])
    assert d is not None and d.count("M") == 2
    whole = bezier_controls(pts)
    samples = [_cubic(q, i / 400) for q in whole for i in range(401)]
    for run in d.split("M")[1:]:  # each run: its start, then its cubic pieces
        nums = [float(v) for v in re.findall(r"-?[\d.]+", run)]
        at = (nums[0], nums[1])
        for j in range(2, len(nums), 6):
            q = (at, (nums[j], nums[j + 1]), (nums[j + 2], nums[j + 3]), (nums[j + 4], nums[j + 5]))
            for i in range(21):
                x, y = _cubic(q, i / 20)
                # on the original curve (to the 0.01 px the path is written with) and never inside the gap
                assert min(math.hypot(x - a, y - b) for a, b in samples) < 0.3
                a, b = gap.local(x, y)
                assert abs(a) >= gap.hw - 0.05 or abs(b) >= gap.hh - 0.05
            at = q[3]
    assert curve_d(pts, [Gap.around((200.0, 200.0, 210.0, 210.0))]) is None
