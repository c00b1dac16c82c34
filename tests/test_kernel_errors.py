"""Misuse of the Builder and malformed protocols raise errors of the library's tree, naming the step."""

from __future__ import annotations

import json

import pytest

import construct
from construct import (Builder, DuplicateName, MissingGiven, NoIntersection, ProtocolFormatError, RuleError, StepError,
                       UnknownObject, WrongInput, left_of, toward)


def _two_points():
    b = Builder("demo", givens={"s": 1.0})
    b.given_point("A", 0.0, 0.0)
    b.given_point("B", 2.0, 0.0)
    return b


def test_unknown_name_names_the_step():
    b = _two_points()
    with pytest.raises(UnknownObject, match=r"step 3 \(compass: .*'k9'"):
        b.circle_through("k", "k9", "A")


def test_a_point_where_a_curve_is_needed():
    b = _two_points()
    with pytest.raises(WrongInput, match=r"step 3 .*input 1 must be a curve, got Point"):
        b.intersect("X", "A", "B", rule=left_of("A", "B"))


@pytest.mark.parametrize("rule", ["left", ("left", "A"), ("nearer",), ("sideways", "A"), 7])
def test_bad_rules_are_rule_errors(rule):
    b = _two_points()
    b.circle_through("ka", "A", "B")
    b.circle_through("kb", "B", "A")
    with pytest.raises(RuleError, match=r"^step 5 \(intersect"):
        b.intersect("X", "ka", "kb", rule=rule)


def test_rule_naming_an_unknown_point():
    b = _two_points()
    b.circle_through("ka", "A", "B")
    b.circle_through("kb", "B", "A")
    with pytest.raises(UnknownObject, match="'Q'"):
        b.intersect("X", "ka", "kb", rule=left_of("A", "Q"))


def test_circles_that_do_not_meet_raise_no_intersection_while_building_and_replaying_alike():
    b = Builder("demo", givens={"d": 1.0})
    b.given_point("A", 0.0, 0.0)
    b.given_point("B", 1.0, 0.0, unit="d")
    b.circle_through("ka", "A", "B")
    b.given_length("one", product=(), factor=0.6)
    b.circle_radius("kb", "B", "one")
    b.intersect("X", "ka", "kb", rule=toward(dx=1.0))
    with pytest.raises(NoIntersection) as built:
        b2 = Builder("demo", givens={"d": 0.2})
        b2.given_point("A", 0.0, 0.0)
        b2.given_point("B", 1.0, 0.0, unit="d")
        b2.circle_through("ka", "A", "B")
        b2.given_length("one", product=(), factor=0.6)
        b2.circle_radius("kb", "B", "one")
        b2.intersect("X", "ka", "kb", rule=toward(dx=1.0))
    with pytest.raises(NoIntersection) as replayed:
        b.protocol().replay({"d": 0.2})
    assert str(built.value) == str(replayed.value)
    assert replayed.value.step_index == 6 and replayed.value.tool == "intersect"


def test_degenerate_circle_is_the_same_error_in_build_and_replay():
    b = Builder("demo", givens={"d": 1.0})
    b.given_point("A", 0.0, 0.0)
    b.given_point("B", 1.0, 0.0, unit="d")
    b.circle_through("k", "A", "B")
    with pytest.raises(StepError) as replayed:
        b.protocol().replay({"d": 0.0})
    b2 = Builder("demo", givens={"d": 0.0})
    b2.given_point("A", 0.0, 0.0)
    b2.given_point("B", 1.0, 0.0, unit="d")
    with pytest.raises(StepError) as built:
        b2.circle_through("k", "A", "B")
    assert type(built.value) is type(replayed.value)
    assert str(built.value) == str(replayed.value)


def test_missing_given_names_step_and_given():
    b = Builder("demo", givens={"s": 2.0})
    b.given_length("s", product=("s",))
    with pytest.raises(MissingGiven, match=r"step 1 .*'s'"):
        b.protocol().replay({})


def test_name_used_twice():
    b = _two_points()
    with pytest.raises(DuplicateName, match="used twice"):
        b.given_point("A", 1.0, 1.0)


def test_protocol_file_errors_are_format_errors():
    b = _two_points()
    d = b.protocol().as_dict()
    d["steps"][1]["op"] = "teleport"
    with pytest.raises(ProtocolFormatError, match="unknown operation 'teleport'"):
        construct.Protocol.from_json(json.dumps(d))
    d = b.protocol().as_dict()
    d["steps"].append({**d["steps"][1], "index": 3, "op": "line", "tool": "straightedge", "inputs": ["A", "Z"],
                       "outputs": ["g"]})
    with pytest.raises(ProtocolFormatError, match="'Z' before any step made it"):
        construct.Protocol.from_dict(d)


def test_every_error_is_a_construct_error():
    for cls in (StepError, NoIntersection, RuleError, UnknownObject, WrongInput, MissingGiven, DuplicateName,
                ProtocolFormatError):
        assert issubclass(cls, construct.ConstructError)


@pytest.mark.parametrize("replayable, named", [(["rod_ratio"], "'rod_ratio'"), ("r", "'r'"), ([7], "7")])
def test_replayable_names_only_givens(replayable, named):
    """``replayable`` is a list of the builder's givens: a name that is no given (or a bare string, which would be
    read letter by letter) is refused when the builder is made, not found missing at some later replay."""
    with pytest.raises(construct.InvalidParameter) as info:
        Builder("crank", givens={"r": 0.4}, replayable=replayable)
    assert named in str(info.value)
    assert Builder("crank", givens={"r": 0.4, "n": 50.0}, replayable=("n",)).protocol().givens == ("n",)
