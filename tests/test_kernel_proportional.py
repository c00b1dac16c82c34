"""The proportional angle, fourth and mean proportionals: intercept theorem and Thales, step by step."""


import mpmath
import pytest
from hypothesis import given, settings, strategies as st

from construct.kernel.instruments import Builder
from construct.kernel.proportional import ProportionalAngle, carry_across, fourth_proportional, mean_proportional, scale_line

# A handful of Euclidean steps: float rounding only, relative to the lengths involved.
REL = 1e-12

lengths = st.floats(min_value=0.05, max_value=20.0, allow_nan=False)


def _builder(**givens):
    b = Builder("test", givens=givens)
    S = b.given_point("S", 0.3, -0.7)
    P = b.given_point("P", 1.3, 2.1)
    for name in givens:
        b.given_length(name, product=(name,))
    return b, S, P


@settings(max_examples=60, deadline=None)
@given(a=lengths, bb=lengths, c=lengths)
def test_fourth_proportional_is_b_c_over_a(a, bb, c):
    b, S, P = _builder(a=a, bb=bb, c=c)
    o, x = fourth_proportional(b, "x", vertex=S, leg_point=P, a="a", b_="bb", c="c")
    expected = float(mpmath.mpf(bb) * c / a)
    assert b[o].distance(b[x]) == pytest.approx(expected, rel=REL, abs=REL)


def test_fourth_proportional_ratio_one_does_not_degenerate():
    # a == b puts both scale lines on top of each other: the perpendiculars are still well defined.
    b, S, P = _builder(a=2.0, bb=2.0, c=0.7)
    o, x = fourth_proportional(b, "x", vertex=S, leg_point=P, a="a", b_="bb", c="c")
    assert b[o].distance(b[x]) == pytest.approx(0.7, rel=REL)


@settings(max_examples=60, deadline=None)
@given(a=lengths, c=lengths)
def test_mean_proportional_is_square_root(a, c):
    b, S, P = _builder(a=a, c=c)
    foot, top = mean_proportional(b, "g", start=S, direction_point=P, a="a", c="c")
    assert b[foot].distance(b[top]) == pytest.approx(float(mpmath.sqrt(mpmath.mpf(a) * c)), rel=REL)


def test_carry_across_keeps_the_side_of_the_leg():
    """Points left and right of the leg land left and right, scaled by d2/d1 (here 3/2)."""
    b = Builder("test", givens={"d1": 2.0, "d2": 3.0, "s": 0.4})
    S = b.given_point("S", 0.0, 0.0)
    leg = b.given_line("leg", S, angle_deg=90.0)
    b.given_length("d1", product=("d1",))
    b.given_length("d2", product=("d2",))
    b.given_length("s", product=("s",))
    ang = ProportionalAngle(S, leg)
    up = ("toward", S, None, 0.0, 1.0)
    one, two = scale_line(b, ang, "g1", length="d1", toward=up), scale_line(b, ang, "g2", length="d2", toward=up)
    k = b.circle_radius("k", one.origin, "s")
    left = b.intersect("L", one.line, k, rule=("toward", S, None, -1.0, 0.0))
    right = b.intersect("R", one.line, k, rule=("toward", S, None, 1.0, 0.0))
    assert b[carry_across(b, ang, "L2", left, two)] == pytest.approx((-0.6, 3.0), abs=1e-14)
    assert b[carry_across(b, ang, "R2", right, two)] == pytest.approx((0.6, 3.0), abs=1e-14)


def test_only_euclidean_instruments_and_replay_with_new_lengths():
    b, S, P = _builder(a=2.0, bb=3.0, c=5.0)
    o, x = fourth_proportional(b, "x", vertex=S, leg_point=P, a="a", b_="bb", c="c")
    proto = b.protocol()
    assert set(proto.instrument_counts()) <= {"given", "straightedge", "compass", "intersect"}
    again = proto.replay({"a": 4.0, "bb": 3.0, "c": 6.0})
    assert again[o].distance(again[x]) == pytest.approx(4.5, rel=REL)
