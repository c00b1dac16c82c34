"""Protocol diff: inserted steps, changed captions, moved objects and changes of method.

The fixture is a small crank construction written by hand: the crank circle
about M with radius r = 5, a straightedge line for the dead-centre axis, and
the dead centres as intersections.  Expected values come from that text.
"""

from __future__ import annotations

import copy
import json

import pytest

from construct.cli.main import main
from construct.kernel.errors import ConstructError, ProtocolFormatError
from construct.regress.change import Change
from construct.regress.protocoldiff import diff_protocol


def step(index, tool, op, inputs, outputs, de, en, params=None, kind="exact", group=()):
    return {"index": index, "tool": tool, "op": op, "inputs": list(inputs), "outputs": list(outputs),
            "params": params or {}, "caption": {"de": de, "en": en},
            "provenance": {"kind": kind, "method": None, "error": None}, "group": list(group)}


BASE = {
    "construction": "crank",
    "params": {"givens": {"r": 5.0, "L": 25.0}},
    "steps": [
        step(1, "given", "point", [], ["M"], "Kurbelmittelpunkt M", "crank centre M", {"x": 0, "y": 0}),
        step(2, "given", "point", [], ["X"], "Punkt X auf der Achse", "point X on the axis", {"x": 10, "y": 0}),
        step(3, "straightedge", "line", ["M", "X"], ["axis"], "Achse durch M", "axis through M"),
        step(4, "compass", "circle_radius", ["M"], ["crank"], "Kurbelkreis um M", "crank circle about M",
             {"radius": "r"}),
        step(5, "intersect", "intersect", ["axis", "crank"], ["T1", "T2"], "Totpunkte", "dead centres",
             {"rule": ["farther", "X"]}),
    ],
    "objects": {
        "M": {"type": "point", "x": 0.0, "y": 0.0},
        "X": {"type": "point", "x": 10.0, "y": 0.0},
        "axis": {"type": "line", "x1": 0.0, "y1": 0.0, "x2": 10.0, "y2": 0.0},
        "crank": {"type": "circle", "cx": 0.0, "cy": 0.0, "r": 5.0},
        "T1": {"type": "point", "x": 5.0, "y": 0.0},
        "T2": {"type": "point", "x": -5.0, "y": 0.0},
    },
}


def variant():
    return copy.deepcopy(BASE)


def kinds(diff):
    return [(c.kind, c.key) for c in diff.changes]


def test_equal_to_itself_and_to_a_reformatted_copy():
    again = json.loads(json.dumps(BASE))
    again["params"]["givens"] = {"L": 25, "r": 5}  # other key order, integers for floats
    again["steps"] = [dict(reversed(list(s.items()))) for s in again["steps"]]
    d = diff_protocol(BASE, json.dumps(again, indent=4))
    assert d.equal, d.report()
    assert "equal (5 steps; compass 1, straightedge 1, intersect 1, given 2)" in d.report()


def test_inserted_step_is_inserted_not_every_later_step_changed():
    b = variant()
    extra = step(4, "compass", "circle_radius", ["M"], ["rod"], "Stangenkreis", "rod circle", {"radius": "L"})
    b["steps"].insert(3, extra)
    for k, s in enumerate(b["steps"], 1):
        s["index"] = k
    d = diff_protocol(BASE, b)
    step_changes = [c for c in d.changes if c.kind != "method"]
    assert [(c.kind, c.key) for c in step_changes] == [("inserted", "step 4")]
    assert "compass circle_radius (M) -> rod" in step_changes[0].description
    # One step more, all of it compass: 5 -> 6 steps, compass 1 -> 2.
    assert d.changes[0].kind == "method"
    assert d.changes[0].description == "method changed: 5 -> 6 steps (compass 1 -> 2)"


def test_removed_step():
    b = variant()
    del b["steps"][1]  # point X no longer given
    d = diff_protocol(BASE, b)
    assert ("removed", "step 2") in kinds(d)
    assert not any(c.kind in ("tool", "op", "caption") for c in d.changes)


def test_changed_caption_names_step_and_language():
    b = variant()
    b["steps"][3]["caption"]["de"] = "Kurbelkreis um M mit r"
    d = diff_protocol(BASE, b)
    (change,) = d.changes
    assert change.kind == "caption" and change.key == "step 4"
    assert change.description == "caption.de 'Kurbelkreis um M' -> 'Kurbelkreis um M mit r'"


def test_changed_tool_and_provenance():
    b = variant()
    b["steps"][3]["tool"] = "dividers"
    b["steps"][4]["provenance"] = {"kind": "approximate", "method": "trial", "error": 0.002}
    d = diff_protocol(BASE, b)
    assert ("tool", "step 4") in kinds(d)
    prov = [c for c in d.changes if c.kind == "provenance"]
    assert [c.key for c in prov] == ["step 5", "step 5", "step 5"]
    assert any("provenance.kind 'exact' -> 'approximate'" in c.description for c in prov)
    # Same number of steps, one compass use became a dividers use.
    assert d.changes[0].description == "method changed: 5 -> 5 steps (compass 1 -> 0, dividers 0 -> 1)"


def test_moved_object_is_named_with_its_displacement():
    b = variant()
    b["objects"]["T1"]["x"] = 5.01
    d = diff_protocol(BASE, b)
    (change,) = d.changes
    assert change.kind == "moved" and change.key == "T1"
    # 5.01 - 5.0 = 0.01 up to one rounding of the subtraction.
    assert change.magnitude == pytest.approx(0.01, abs=1e-12)


def test_resized_circle_and_changed_param():
    b = variant()
    b["params"]["givens"]["r"] = 6.0
    b["objects"]["crank"]["r"] = 6.0
    d = diff_protocol(BASE, b)
    assert kinds(d) == [("param", "givens.r"), ("resized", "crank")]
    assert d.changes[1].magnitude == pytest.approx(1.0)


def test_tolerance_forgives_float_noise_only():
    b = variant()
    b["objects"]["T2"]["x"] = -5.0 + 1e-12  # replay noise of a few ulps
    assert diff_protocol(BASE, b).equal
    assert not diff_protocol(BASE, b, tolerance=1e-13).equal


def test_shorter_construction_is_a_change_of_method():
    # The same dead centres found with fewer instrument uses: no axis line, the
    # dead centres marked by compass directly on the circle.
    b = variant()
    b["steps"] = [b["steps"][0], b["steps"][3],
                  step(3, "compass", "circle_radius", ["M"], ["T1", "T2"], "Totpunkte", "dead centres")]
    b["steps"][1]["index"] = 2
    d = diff_protocol(BASE, b)
    assert not d.equal and d.method_changed
    method = [c for c in d.changes if c.kind == "method"]
    # 5 -> 3 steps; compass 1 -> 2, straightedge 1 -> 0, intersect 1 -> 0, given 2 -> 1.
    assert [c.description for c in method] == [
        "method changed: 5 -> 3 steps (compass 1 -> 2, straightedge 1 -> 0, intersect 1 -> 0, given 2 -> 1)"]
    assert "method changed: 5 -> 3 steps" in d.report()
    assert d.as_dict()["instruments"]["compass"] == {"a": 1, "b": 2}


def test_unknown_tools_are_counted_generically():
    b = variant()
    b["steps"][3]["tool"] = "ellipsograph"
    d = diff_protocol(BASE, b)
    assert "ellipsograph 0 -> 1" in d.changes[0].description


def test_report_and_dict_are_deterministic():
    b = variant()
    b["objects"]["T1"]["x"] = 5.5
    b["steps"][2]["caption"]["en"] = "the axis"
    d1, d2 = diff_protocol(BASE, b), diff_protocol(json.dumps(BASE), json.dumps(b).encode())
    assert d1.changes == d2.changes
    assert json.dumps(d1.as_dict()) == json.dumps(diff_protocol(BASE, b).as_dict())
    assert all(isinstance(c, Change) for c in d1.changes)


@pytest.mark.parametrize("bad", [
    "{not json", "[1, 2]", '{"steps": []}', '{"construction": "x", "steps": {}}',
    '{"construction": "x", "steps": [{"tool": "compass", "op": "circle", "inputs": "M"}]}',
    '{"construction": "x", "steps": [], "objects": {"M": [0, 0]}}',
])
def test_malformed_protocol_is_a_construct_error(bad):
    with pytest.raises(ProtocolFormatError):
        diff_protocol(bad, BASE)
    assert issubclass(ProtocolFormatError, ConstructError)


def test_cli_on_protocol_files(tmp_path, capsys):
    a, b, broken = tmp_path / "a.json", tmp_path / "b.json", tmp_path / "broken.json"
    a.write_text(json.dumps(BASE), encoding="utf-8")
    shorter = variant()
    del shorter["steps"][2]
    b.write_text(json.dumps(shorter, indent=1), encoding="utf-8")
    broken.write_text('{"construction": 1}', encoding="utf-8")
    assert main(["diff", str(a), str(a)]) == 0
    assert main(["diff", str(a), str(b)]) == 1
    assert "method changed: 5 -> 4 steps (straightedge 1 -> 0)" in capsys.readouterr().out
    assert main(["diff", str(a), str(b), "--json"]) == 1
    assert json.loads(capsys.readouterr().out)["method_changed"] is True
    assert main(["diff", str(a), str(broken)]) == 2


def test_changes_read_like_the_svg_diffs():
    """One Change type: a protocol's changes carry their step and serialise with the SVG diff's keys."""
    from construct.regress.svgdiff import diff_svg

    b = variant()
    b["steps"][2]["caption"]["en"] = "the axis"  # step 3 changed
    b["steps"].insert(1, step(2, "given", "point", [], ["Y"], "Punkt Y", "point Y", {"x": 0, "y": 3}))
    for k, s in enumerate(b["steps"], 1):
        s["index"] = k  # the old step 3 is now step 4
    b["objects"]["T1"]["x"] = 5.5  # an object: no step
    d = diff_protocol(BASE, b)
    assert {k: [c.kind for c in v] for k, v in d.by_step().items()} == {
        None: ["method", "moved"], 2: ["inserted"], 3: ["caption"]}
    assert [c.key for c in d.of_kind("caption")] == ["step 3->4"]
    svg = '<svg xmlns="http://www.w3.org/2000/svg"><circle id="P" r="1"/></svg>'
    moved = diff_svg(svg, svg.replace('r="1"', 'r="1" cx="2"'))
    assert list(d.as_dict()["changes"][0]) == list(moved.as_dict()["changes"][0])
    assert d.steps == (5, 6) and moved.elements == (1, 1)
