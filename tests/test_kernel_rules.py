"""Which crossing a step takes (construct/kernel/rules.py): rules, their JSON form, their choice on arrays.

Expectations come from geometry worked out here (which of two points is nearer, left of a line, farther
along a direction), never from the rules' own answers.
"""

from __future__ import annotations

import json
import pickle

import numpy as np
import pytest

from construct.kernel.errors import RuleError
from construct.kernel.geometry import ARRAY, SCALAR, Point
from construct.kernel.rules import as_rule, choose, farther, left_of, nearer, only, right_of, toward

UP, DOWN = Point(0.0, 1.0), Point(0.0, -1.0)


@pytest.mark.parametrize("rule, refs, want", [
    (nearer("Q"), (Point(0.3, 4.0),), UP),               # |UP - Q|^2 = 9.09 < |DOWN - Q|^2 = 25.09
    (farther("Q"), (Point(0.3, 4.0),), DOWN),
    (left_of("A", "B"), (Point(-1.0, 0.0), Point(1.0, 0.0)), UP),   # going A -> B (east), up is on the left
    (right_of("A", "B"), (Point(-1.0, 0.0), Point(1.0, 0.0)), DOWN),
    (left_of("A", "B"), (Point(1.0, 0.0), Point(-1.0, 0.0)), DOWN),  # the other way round, the other side
    (toward(dx=0.2, dy=-1.0), (), DOWN),
    (toward("A", "B"), (Point(5.0, 5.0), Point(5.0, 7.0)), UP),
])
def test_a_rule_takes_the_point_the_geometry_says(rule, refs, want):
    chosen, other = choose((UP, DOWN), rule, refs, SCALAR)
    assert chosen == want and other == (DOWN if want == UP else UP)
    chosen, _ = choose((DOWN, UP), rule, refs, SCALAR)  # whichever comes first
    assert chosen == want


def test_on_arrays_each_set_takes_its_own_point():
    """A sweep: the reference moves across the x axis; each set picks the crossing on its side."""
    qy = np.array([3.0, -3.0, 0.5, -0.5])
    a, b = Point(np.zeros(4), np.ones(4)), Point(np.zeros(4), -np.ones(4))
    chosen, _ = choose((a, b), nearer("Q"), (Point(np.zeros(4), qy),), ARRAY)
    assert np.asarray(chosen.y).tolist() == [1.0, -1.0, 1.0, -1.0]


def test_a_rule_is_a_value_that_travels():
    for rule in (nearer("A"), farther("A"), left_of("A", "B"), right_of("A", "B"), toward("A", "B"),
                 toward(dx=-1.0, dy=0.0), only()):
        assert as_rule(json.loads(json.dumps(rule.as_json()))) == rule
        assert pickle.loads(pickle.dumps(rule)) == rule and hash(rule) == hash(as_rule(rule.as_json()))
        assert len(repr(rule)) < 80


@pytest.mark.parametrize("bad", ["left", ["left", "A"], ["sideways", "A"], ["toward", None, None, "x", 0.0], 5])
def test_a_rule_that_is_not_one_says_so(bad):
    with pytest.raises(RuleError):
        as_rule(bad)
