"""The geometry kernel: intersections lie on both curves, tangency and precision."""

import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from construct.kernel.errors import DegenerateObject
from construct.kernel.geometry import (
    TANGENCY_TOLERANCE,
    Circle,
    Length,
    Line,
    Point,
    intersect,
    intersect_circles,
    intersect_line_circle,
    intersect_lines,
)

coord = st.floats(-100, 100, allow_nan=False)
radius = st.floats(0.01, 100)


def on_circle(p, c, tol):
    return abs(math.hypot(p.x - c.center.x, p.y - c.center.y) - c.radius) <= tol


def on_line(p, l, tol):
    (px, py), (qx, qy) = l
    d = math.hypot(qx - px, qy - py)
    return abs((qx - px) * (p.y - py) - (qy - py) * (p.x - px)) / d <= tol


@settings(max_examples=300, deadline=None)
@given(coord, coord, radius, coord, coord, radius)
def test_circle_circle_points_lie_on_both_circles(x1, y1, r1, x2, y2, r2):
    c1, c2 = Circle(Point(x1, y1), r1), Circle(Point(x2, y2), r2)
    if math.hypot(x2 - x1, y2 - y1) < 1e-6:
        return
    pts = intersect_circles(c1, c2)
    scale = max(r1, r2, math.hypot(x2 - x1, y2 - y1))
    # A touching point may sit up to sqrt(2 * tol * scale) * scale off: tangency is decided by the gap.
    tol = 1e-9 * scale if len(pts) == 2 else math.sqrt(2 * TANGENCY_TOLERANCE) * scale + 1e-9 * scale
    for p in pts:
        assert on_circle(p, c1, tol) and on_circle(p, c2, tol)
    d = math.hypot(x2 - x1, y2 - y1)
    if d < r1 + r2 - 1e-6 * scale and d > abs(r1 - r2) + 1e-6 * scale:
        assert len(pts) == 2
    if d > r1 + r2 + 1e-6 * scale or d < abs(r1 - r2) - 1e-6 * scale:
        assert pts == ()


@settings(max_examples=300, deadline=None)
@given(coord, coord, coord, coord, coord, coord, radius)
def test_line_circle_points_lie_on_both(px, py, qx, qy, cx, cy, r):
    if math.hypot(qx - px, qy - py) < 1e-3:
        return
    line, c = Line(Point(px, py), Point(qx, qy)), Circle(Point(cx, cy), r)
    scale = max(r, abs(px), abs(py), abs(qx), abs(qy), abs(cx), abs(cy), 1.0)
    for p in intersect_line_circle(line, c):
        assert on_line(p, line, 1e-9 * scale)
        assert on_circle(p, c, math.sqrt(2 * TANGENCY_TOLERANCE) * r + 1e-9 * scale)


def test_lines_cross_once_or_not_at_all():
    assert intersect_lines(Line(Point(0, 0), Point(2, 2)), Line(Point(0, 2), Point(2, 0))) == (Point(1.0, 1.0),)
    assert intersect_lines(Line(Point(0, 0), Point(1, 0)), Line(Point(5, 1), Point(6, 1))) == ()


def test_tangent_circles_meet_once_outside_and_inside():
    assert intersect(Circle(Point(0, 0), 1.0), Circle(Point(3, 0), 2.0)) == (Point(1.0, 0.0),)
    assert intersect(Circle(Point(0, 0), 3.0), Circle(Point(1, 0), 2.0)) == (Point(3.0, 0.0),)
    assert intersect(Circle(Point(1, 0), 2.0), Circle(Point(0, 0), 3.0)) == (Point(3.0, 0.0),)


def test_nearly_tangent_circles_keep_their_precision():
    """Unit circles 2 - 1e-8 apart: the half chord is 1e-4; r^2 - a^2 would lose 8 digits, Heron's form none."""
    d = 2.0 - 1e-8
    a, b = intersect_circles(Circle(Point(0.0, 0.0), 1.0), Circle(Point(d, 0.0), 1.0))
    with mpmath.workdps(50):
        h_ref = mpmath.sqrt(1 - (mpmath.mpf(d) / 2) ** 2)  # the circles sit exactly at the float d
    assert abs(abs(a.y) - float(h_ref)) <= 1e-15 * float(h_ref)
    assert a.y == -b.y


def test_long_rod_crosshead_is_accurate():
    """Rod arc of length L = 1000 r about a crank point: crosshead exact to float precision of L."""
    L, s = 1000.0, 0.7
    pts = intersect_line_circle(Line(Point(-1.0, 0.0), Point(1.0, 0.0)), Circle(Point(0.0, s), L))
    with mpmath.workdps(40):
        ref = mpmath.sqrt(mpmath.mpf(L) ** 2 - mpmath.mpf(s) ** 2)
    assert abs(pts[1].x - float(ref)) <= 2e-16 * L


def test_degenerate_values_raise():
    with pytest.raises(DegenerateObject):
        Point(float("inf"), 0.0)
    with pytest.raises(DegenerateObject):
        Line(Point(1, 1), Point(1, 1))
    with pytest.raises(DegenerateObject):
        Circle(Point(0, 0), -1.0)
    with pytest.raises(DegenerateObject):
        Length(float("nan"))
    with pytest.raises(DegenerateObject):
        intersect_circles(Circle(Point(0, 0), 1.0), Circle(Point(0, 0), 1.0))


def test_values_are_immutable_and_typed():
    p = Point(1.0, 2.0)
    with pytest.raises((AttributeError, TypeError)):
        p.x = 3.0  # type: ignore[misc]
    assert Point(1.0, 2.0) == Point(1.0, 2.0) and hash(Point(1.0, 2.0)) == hash(Point(1.0, 2.0))
    assert (Point(1.0, 2.0) == (1.0, 2.0)) is False
    assert repr(Circle(Point(0.0, 0.0), 2.0)) == "Circle(Point(0.0, 0.0), 2.0)"
