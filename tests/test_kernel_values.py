"""Geometry values behave: they travel (pickle, copy), refuse tuple arithmetic, and print in a line."""

from __future__ import annotations

import copy
import pickle

import numpy as np
import pytest

import construct
from construct import Circle, Length, Line, Point, get
from construct.kernel.areas import Area
from construct.kernel.curves import BezierCurve, Polyline

VALUES = [
    Point(1.0, 2.0),
    Line(Point(0.0, 0.0), Point(1.0, 1.0)),
    Circle(Point(1.0, 0.0), 2.5),
    Length(3.0),
    Polyline((Point(0, 0), Point(1, 2), Point(2, 0))),
    BezierCurve((Point(0, 0), Point(1, 1), Point(2, 1), Point(3, 0))),
    Area([(1, (Point(0, 0), Point(1, 0), Point(1, 1)))]),
    construct.nearer("A"),
    construct.toward(dx=-1.0),
]


@pytest.mark.parametrize("value", VALUES, ids=lambda v: type(v).__name__)
def test_values_round_trip_through_pickle_and_copy(value):
    for other in (pickle.loads(pickle.dumps(value)), copy.copy(value), copy.deepcopy(value)):
        assert other == value and type(other) is type(value)


@pytest.mark.parametrize("value", VALUES, ids=lambda v: type(v).__name__)
def test_values_are_immutable(value):
    with pytest.raises(AttributeError):
        value.x = 5.0


def test_point_arithmetic_is_refused_not_concatenation():
    p, q = Point(1.0, 2.0), Point(3.0, 4.0)
    for op in (lambda: p + q, lambda: p * 2, lambda: 2 * p, lambda: (1.0, 2.0) + p):
        with pytest.raises(TypeError):
            op()
    assert p != (1.0, 2.0) and (p == (1.0, 2.0)) is False


def test_figures_protocols_and_replays_travel_to_other_processes():
    fig = get("crank").figure(parts=6, rod_ratio=4.0)
    for obj in (fig, fig.protocol, fig.replay):
        back = pickle.loads(pickle.dumps(obj))
        assert copy.deepcopy(obj) is not None
    back = pickle.loads(pickle.dumps(fig))
    assert back.protocol.steps == fig.protocol.steps
    assert dict(back.replay) == dict(fig.replay)
    assert back.protocol.replay({"r": 1.0, "rod_ratio": 6.0})["X3"] == fig.protocol.replay({"r": 1.0, "rod_ratio": 6.0})["X3"]


def test_reprs_stay_short():
    fig = get("crank").figure(parts=360)
    sweep = fig.protocol.replay({"r": 1.0, "rod_ratio": np.linspace(2, 9, 5000)})
    for obj in (fig, fig.protocol, fig.replay, sweep, sweep["X9"], sweep["crank"], *VALUES):
        assert len(repr(obj)) <= 120, repr(obj)[:200]


def test_sweep_values_compare_by_array():
    a = Point(np.array([1.0, 2.0]), np.array([0.0, 0.0]))
    assert a == Point(np.array([1.0, 2.0]), np.array([0.0, 0.0]))
    assert a != Point(np.array([1.0, 2.5]), np.array([0.0, 0.0]))
    with pytest.raises(TypeError):
        hash(a)
