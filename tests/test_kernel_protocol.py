"""Steps as data: JSON round trip, replay with new givens, branch rules, errors naming the step."""

import json
import math

import pytest

from construct.constructions import get
from construct.kernel.errors import InvalidParameter, ProtocolFormatError, StepError
from construct.kernel.instruments import Builder
from construct.kernel.protocol import Protocol


def crank(**kw):
    return get("crank").figure(**kw)


def test_json_round_trip_keeps_every_step():
    fig = crank(parts=6, rod_ratio=4.0)
    text = fig.protocol.to_json(fig.replay)
    again = Protocol.from_json(text)
    assert [s.as_dict() for s in again.steps] == [s.as_dict() for s in fig.protocol.steps]
    data = json.loads(text)
    assert {"construction", "params", "steps", "objects"} <= set(data)
    assert {"index", "tool", "inputs", "outputs", "caption", "provenance"} <= set(data["steps"][0])


@pytest.mark.parametrize("method", ["exact", "durer", "neusis", "dividers"])
def test_imported_protocol_replayed_with_new_givens_equals_a_fresh_build(method):
    parts = 12 if method == "exact" else 9
    fig = crank(parts=parts, rod_ratio=4.0, method=method)
    imported = Protocol.from_json(fig.protocol.to_json(fig.replay))
    replayed = get("crank").replay(imported, rod_ratio=6.5, r=2.0)
    fresh = crank(parts=parts, rod_ratio=6.5, method=method, r=2.0)
    assert set(replayed.replay) == set(fresh.replay)
    for name, obj in fresh.replay.items():
        assert replayed.replay[name] == obj, name  # same steps, same rules: bit-identical


def test_branch_rules_keep_their_choice_under_new_givens():
    """The crosshead stays on the cylinder side and the piston on the stroke for any rod ratio."""
    fig = crank(parts=6, rod_ratio=4.0)
    for ratio in (1.05, 2.0, 50.0):
        rep = fig.protocol.replay({"r": 1.0, "rod_ratio": ratio})
        for k in range(7):
            p = rep["D0" if k == 0 else "D1" if k == 6 else f"P{k}"]
            assert rep[f"C{k}"].x < p.x  # the crosshead is on the cylinder side of its crank pin
            assert math.hypot(rep[f"C{k}"].x - p.x, p.y) == pytest.approx(ratio, rel=1e-12)
            assert rep["D0"].x - 1e-12 <= rep[f"X{k}"].x <= rep["D1"].x + 1e-12


def test_rod_shorter_than_the_crank_is_refused_by_name():
    fig = crank(parts=6, rod_ratio=4.0)
    with pytest.raises(InvalidParameter, match="rod ratio"):
        get("crank").replay(fig.protocol, rod_ratio=0.8)
    # Below the registry's validation, the replay itself names the step whose circles miss.
    with pytest.raises(StepError) as info:
        fig.protocol.replay({"r": 1.0, "rod_ratio": 0.5})
    assert "step" in str(info.value) and "do not meet" in str(info.value)
    assert info.value.step_index is not None


def test_structural_parameters_cannot_be_replayed():
    fig = crank(parts=6)
    with pytest.raises(InvalidParameter, match="changes the steps"):
        get("crank").replay(fig.protocol, parts=18)


@pytest.mark.parametrize("text,match", [
    ("{", "not a JSON protocol"),
    ("[]", "JSON object"),
    ('{"construction": "crank", "params": {}}', "no 'steps'"),
    ('{"construction": "crank", "params": {}, "steps": [{"index": 1}]}', "malformed step"),
])
def test_malformed_protocols_are_refused(text, match):
    with pytest.raises(ProtocolFormatError, match=match):
        Protocol.from_json(text)


def test_a_step_using_an_object_nobody_made_is_refused():
    fig = crank(parts=2)
    data = json.loads(fig.protocol.to_json(fig.replay))
    data["steps"][5]["inputs"] = ["nowhere", "crank"]
    with pytest.raises(ProtocolFormatError, match="nowhere"):
        Protocol.from_dict(data)


def test_groups_span_their_steps():
    fig = crank(parts=6)
    spans = {g: (a, b) for g, a, b in fig.protocol.groups()}
    top = [g for g in spans if len(g) == 1]
    assert ("crank circle and dead centres",) in top
    a, b = spans[("all 7 connecting-rod arcs",)]
    assert b - a + 1 == 7 * 4  # each rod: arc, crosshead, arc back, piston position


def test_every_step_has_captions_in_both_languages_and_a_provenance():
    fig = crank(parts=18)
    for s in fig.protocol.steps:
        assert s.caption.de and s.caption.en
        assert s.provenance.kind in ("given", "exact", "approximate", "neusis", "trial")
    approx = [s for s in fig.protocol.steps if s.provenance.kind == "approximate"]
    assert approx and all(s.provenance.error and s.provenance.error > 0 for s in approx)


def test_builder_refuses_a_name_used_twice():
    b = Builder("demo", givens={})
    b.given_point("A", 0.0, 0.0)
    with pytest.raises(InvalidParameter, match="used twice"):
        b.given_point("A", 1.0, 0.0)


def test_a_whole_take_is_the_lazy_take():
    """take(i, whole=True) takes every object at once (a drawing reads them all): the same objects as
    looking each up in the lazy take, and as the figure built at that value."""
    from construct.kernel.protocol import object_json

    c = get("crank")
    fig = c.figure(parts=6)
    sweep = fig.protocol.replay(c.rod_ratio_sweep(dict(fig.replay.givens), [2.0, 4.0]))
    whole, lazy = sweep.take(1, whole=True), sweep.take(1)
    fresh = c.figure(parts=6, rod_ratio=4.0).replay
    assert list(whole) == list(lazy) == list(fresh)
    for name in whole:
        assert object_json(whole[name]) == object_json(lazy[name])
        got, want = object_json(whole[name]), object_json(fresh[name])
        assert got.keys() == want.keys()
        for k in got:
            assert got[k] == (pytest.approx(want[k], abs=1e-12) if isinstance(want[k], float) else want[k]), name
