"""Drawn curves and areas: crossings, areas and hatching against independent computations."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from construct import Builder, Circle, Line, Point, nearer
from construct.kernel.areas import Area, area_between
from construct.kernel.curves import BezierCurve, Polyline, crossings
from construct.kernel.geometry import intersect


def test_area_between_a_sine_and_its_axis_is_two_each_side():
    xs = np.linspace(0.0, 2.0 * math.pi, 2001)
    wave = Polyline([Point(x, math.sin(x)) for x in xs])
    axis = Line(Point(0.0, 0.0), Point(1.0, 0.0))
    a = area_between(wave, axis, 0.0, 2.0 * math.pi)
    signed = sorted((s, poly.area) for s, poly in a.signed_pieces())
    # Polyline through 2001 points: its area falls short of the integral by ~h^2/12 of it.
    assert [s for s, _ in signed] == [-1, 1]
    for _, area in signed:
        assert area == pytest.approx(2.0, abs=1e-5)
    assert a.signed_area() == pytest.approx(0.0, abs=1e-12)


def test_area_between_two_crossing_lines_is_two_triangles():
    up = Line(Point(0.0, 1.0), Point(2.0, -1.0))
    down = Line(Point(0.0, -1.0), Point(2.0, 1.0))
    a = area_between(up, down, 0.0, 2.0)
    assert sorted(round(p.area, 12) for _, p in a.signed_pieces()) == [1.0, 1.0]
    assert [s for s, _ in a.pieces] == [1, -1]


def test_bezier_crossings_against_mpmath():
    c = BezierCurve((Point(0, 0), Point(1, 3), Point(2, -2), Point(3, 1)))
    line = Line(Point(0.0, 0.4), Point(3.0, 0.1))
    got = crossings(c, line)

    def gap(t):
        s = 1 - t
        x = s**3 * 0 + 3 * s * s * t * 1 + 3 * s * t * t * 2 + t**3 * 3
        y = s**3 * 0 + 3 * s * s * t * 3 + 3 * s * t * t * (-2) + t**3 * 1
        return y - (0.4 - 0.1 * x)

    roots = []
    for t0 in np.linspace(0.01, 0.99, 60):
        try:
            r = mpmath.findroot(gap, t0)
        except (ZeroDivisionError, ValueError):
            continue
        if 0 <= r <= 1 and all(abs(r - q) > 1e-9 for q in roots):
            roots.append(r)
    assert len(got) == len(roots) == 3
    for p, t in zip(got, sorted(roots)):
        s = 1 - t
        x = 3 * s * s * t + 6 * s * t * t + 3 * t**3
        assert abs(p.x - float(x)) < 1e-10


def test_a_builder_crosses_a_drawn_curve_with_a_line_and_measures_an_area():
    b = Builder("demo", givens={})
    pts = []
    for i, x in enumerate(np.linspace(0.0, 2.0, 5)):
        pts.append(b.given_point(f"P{i}", float(x), float(1.0 - (x - 1.0) ** 2)))
    b.given_point("A", 0.0, 0.5)
    b.given_point("B", 2.0, 0.5)
    b.line("mean", "A", "B")
    b.polyline("curve", pts)
    b.intersect("X", "curve", "mean", rule=nearer("A"))
    b.area_between("F", "curve", "mean", "A", "B", hatch_deg=90)
    b.planimeter("f", "F")
    # polyline through (0,0), (.5,.75), (1,1), (1.5,.75), (2,0): crosses y = .5 at x = 1/3 and 5/3
    assert b["X"].x == pytest.approx(1.0 / 3.0, abs=1e-15)
    # net area: polyline area 1.25 minus the rectangle under the mean line, 1.0
    assert b["f"] == pytest.approx(0.25, abs=1e-15)
    assert b["F"].hatch_deg == 90.0


def test_hatch_lines_lie_inside_and_are_evenly_spaced():
    square = Area([(1, (Point(0, 0), Point(4, 0), Point(4, 2), Point(0, 2)))])
    lines = square.hatch(0.5, angle_deg=90.0)
    xs = sorted(round(x1, 12) for x1, _, x2, _ in lines)
    assert xs == [0.5 * k for k in range(1, 8)]  # none along the edges x = 0 and x = 4
    for x1, y1, x2, y2 in lines:
        assert x1 == pytest.approx(x2) and {round(y1, 12), round(y2, 12)} == {0.0, 2.0}


coord = st.floats(-5.0, 5.0, allow_nan=False)
radius = st.floats(0.1, 5.0, allow_nan=False)


@settings(max_examples=300, deadline=None)
@given(coord, coord, radius, coord, coord, radius)
def test_circle_intersections_lie_on_both_circles(x1, y1, r1, x2, y2, r2):
    c1, c2 = Circle(Point(x1, y1), r1), Circle(Point(x2, y2), r2)
    if math.hypot(x2 - x1, y2 - y1) < 1e-6:
        return
    for p in intersect(c1, c2):
        assert abs(p.distance(c1.center) - r1) <= 1e-9 * max(r1, r2, 1.0)
        assert abs(p.distance(c2.center) - r2) <= 1e-9 * max(r1, r2, 1.0)
