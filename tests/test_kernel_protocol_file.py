"""Hostile protocols and misuse of the library: a construct error naming the cause, never a traceback.

A protocol is checked whole when it is loaded -- its format, every field of
every step, each step against its operation's declared inputs, outputs and
parameters -- so that nothing malformed reaches a replay.  On the command
line every such protocol gives exit code 2 and exactly one line on stderr,
from ``replay --protocol`` and ``check --protocol`` alike.
"""

from __future__ import annotations

import copy
import json
import math
import os
import pickle
import re
import threading
from pathlib import Path

import numpy as np
import pytest

import construct
from construct import (Builder, ConstructError, InvalidParameter, Point, Protocol, ProtocolFormatError, RuleError,
                       StepError, UnknownConstruction, UnknownObject, WrongInput)
from construct.cli.main import main
from construct.kernel import protocol_file
from construct.kernel.ops import OPS, kind_of
from construct.kernel.protocol_file import MAX_PROTOCOL_BYTES
from construct.regress.protocoldiff import diff_protocol

GALLERY = Path(__file__).resolve().parent.parent / "gallery"


@pytest.fixture(scope="module")
def crank_file() -> dict:
    """The protocol file of the 6-part crank, as parsed JSON (format 2, as ``construct replay`` writes it)."""
    fig = construct.get("crank").figure(parts=6)
    return json.loads(fig.protocol.to_json(fig.replay))


def _step(d: dict, op: str) -> dict:
    return next(s for s in d["steps"] if s["op"] == op)


def _toward_step(d: dict) -> dict:
    return next(s for s in d["steps"] if (s.get("params") or {}).get("rule", [None])[0] == "toward"
                and len(s["params"]["rule"]) == 5)


def _cli(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def _assert_refused(capsys, path: Path, out_dir: Path) -> str:
    """replay --protocol and check --protocol both exit 2 with one line on stderr and write nothing."""
    lines = []
    for argv in (["replay", "--protocol", str(path), "--out", str(out_dir)], ["check", "--protocol", str(path)]):
        code, _, err = _cli(capsys, *argv)
        assert code == 2, (argv, err)
        assert len(err.splitlines()) == 1 and "Traceback" not in err, err
        lines.append(err)
    assert not out_dir.exists()
    return lines[0]


# -- 1, 2: malformed steps and files --------------------------------------------------------------------------


MALFORMED = {
    "a parameter of the wrong type": (lambda d: _step(d, "given_point")["params"].__setitem__("x", "abc"),
                                      r"step 1 \(given: .*given_point parameter 'x' must be a finite number, got 'abc'"),
    "params as a list": (lambda d: _step(d, "given_point").__setitem__("params", [1, 2]),
                         r"step 1: 'params' must be an object, got \[1, 2\]"),
    "no params.givens": (lambda d: d["params"].pop("givens"),
                         r"'givens' names 'r', which 'params.givens' lacks"),
    "no params.givens and no givens list": (lambda d: (d["params"].pop("givens"), d.pop("givens")),
                                            r"step 3 \(given: crank radius r\) reads the given 'r', which 'params.givens' lacks"),
    "an intersection with one input": (lambda d: _step(d, "intersect").__setitem__("inputs", ["axis"]),
                                       r"step 6 .*intersect takes 2 inputs \(curve, curve\), got 1"),
    "an intersection with extra outputs": (lambda d: _step(d, "intersect")["outputs"].extend(["Z1", "Z2"]),
                                           r"step 6 .*intersect makes 1 object \(point\), the step names 3"),
    "an intersection of a point": (lambda d: _step(d, "intersect").__setitem__("inputs", ["axis", "O"]),
                                   r"step 6 .*input 2 must be a curve, 'O' is a point"),
    "a rule naming a circle": (lambda d: _toward_step(d)["params"].__setitem__("rule", ["nearer", "crank"]),
                               r"step 6 .*rule names 'crank', a circle; a rule names points"),
    "NaN in a rule's direction": (lambda d: _toward_step(d)["params"]["rule"].__setitem__(3, math.nan),
                                  r"step 6 .*'toward' needs a direction of two finite numbers, got \(nan, 0.0\)"),
    "infinity as a coordinate": (lambda d: _step(d, "given_point")["params"].__setitem__("y", math.inf),
                                 r"step 1 .*parameter 'y' must be a finite number, got inf"),
    "a parameter the op does not take": (lambda d: _step(d, "line").__setitem__("params", {"width": 2}),
                                         r"line has no parameter 'width' \(it takes none\)"),
    "a missing parameter": (lambda d: _step(d, "given_line")["params"].pop("angle_deg"),
                            r"given_line needs the parameter 'angle_deg'"),
    "a given that is not a number": (lambda d: d["params"]["givens"].__setitem__("r", "1"),
                                     r"the given 'r' must be a finite number, got '1'"),
    "an unknown tool": (lambda d: d["steps"][3].__setitem__("tool", "hammer"),
                        r"step 4: 'tool' is 'hammer'; the instruments are given, straightedge, compass"),
    "an unknown role": (lambda d: d["steps"][3].__setitem__("role", "hero"),
                        r"step 4: 'role' is 'hero'; the roles are construction, result, auxiliary"),
    "an unknown provenance": (lambda d: d["steps"][3].__setitem__("provenance", {"kind": "guess"}),
                              r"step 4: provenance 'kind' is 'guess'"),
    "an unknown field": (lambda d: d["steps"][3].__setitem__("colour", "red"),
                         r"step 4: unknown field 'colour'"),
    "a wrong format version": (lambda d: d.__setitem__("format", "construct-protocol/9"),
                               r"protocol format 'construct-protocol/9' is not one this library reads "
                               r"\(construct-protocol/1, construct-protocol/2\)"),
    "a step index 4.7": (lambda d: d["steps"][3].__setitem__("index", 4.7),
                         r"step 4: 'index' must be the whole number 4 \(the step's place in the list\), got 4.7"),
    "a step index '4'": (lambda d: d["steps"][3].__setitem__("index", "4"), r"step 4: 'index' .*got '4'"),
    "a step index 4.0": (lambda d: d["steps"][3].__setitem__("index", 4.0), r"step 4: 'index' .*got 4.0"),
    "an empty step list": (lambda d: d.__setitem__("steps", []), r"protocol has no steps"),
    "a group number in format 1": (lambda d: d.__setitem__("format", "construct-protocol/1"),
                                   r"step 1 names its group by number \(0\), which only format construct-protocol/2"),
    "a group number beyond the table": (lambda d: d["steps"][0].__setitem__("group", 99),
                                        r"step 1 names group 99; the file's 'groups' table has"),
    "a caption without English": (lambda d: d["steps"][0]["caption"].pop("en"),
                                  r"step 1: 'caption' must be an object with 'de' and 'en'"),
    "a step that is not an object": (lambda d: d["steps"].__setitem__(2, [1]), r"step 3 must be an object"),
    "an object used before it is made": (lambda d: d["steps"][5].__setitem__("inputs", ["nowhere", "circle"]),
                                         r"step 6 .*uses 'nowhere' before any step made it"),
    "an object made twice": (lambda d: d["steps"][1].__setitem__("outputs", ["O"]), r"step 2 makes 'O' a second time"),
}


@pytest.mark.parametrize("case", list(MALFORMED))
def test_a_malformed_protocol_is_refused_at_load_naming_what_is_wrong(case, crank_file, tmp_path, capsys):
    mutate, message = MALFORMED[case]
    d = copy.deepcopy(crank_file)
    mutate(d)
    with pytest.raises(ProtocolFormatError, match=message):
        Protocol.from_dict(d)
    path = tmp_path / "protocol.json"
    path.write_text(json.dumps(d), encoding="utf-8")  # json writes NaN and Infinity as Python's json reads them
    with pytest.raises(ProtocolFormatError, match=message):
        Protocol.load(path)
    err = _assert_refused(capsys, path, tmp_path / "out")
    assert err.startswith("construct: error: ")


@pytest.mark.parametrize("text", ['{"a": ' * 100_000 + "1" + "}" * 100_000, "[" * 100_000 + "]" * 100_000,
                                  '{"construction": "x", "params": {}, "steps": [], "n": ' + "9" * 5000 + "}"])
def test_deep_nesting_and_huge_numbers_are_format_errors_not_recursion_errors(text, tmp_path, capsys):
    with pytest.raises(ProtocolFormatError, match="not a JSON protocol"):
        Protocol.from_json(text)
    path = tmp_path / "deep.json"
    path.write_text(text, encoding="utf-8")
    _assert_refused(capsys, path, tmp_path / "out")
    with pytest.raises(ProtocolFormatError):
        diff_protocol(str(path), str(path))


def test_params_nested_within_what_json_parses_but_deeper_than_any_protocol_are_refused():
    deep: object = 1.0
    for _ in range(900):
        deep = {"a": deep}
    d = {"construction": "x", "params": {"deep": deep}, "steps": [
        {"index": 1, "tool": "given", "op": "given_point", "inputs": [], "outputs": ["A"],
         "params": {"x": 0.0, "y": 0.0}, "caption": {"de": "A", "en": "A"}}]}
    with pytest.raises(ProtocolFormatError, match="nested more than 32 levels"):
        Protocol.from_json(json.dumps(d))
    with pytest.raises(ProtocolFormatError, match="nested more than 32 levels"):
        diff_protocol(d, d)


def test_a_protocol_without_a_format_key_reads_as_format_1(crank_file):
    """The in-memory form (as_dict) is format 1; without the key a dict is taken as that form, checked as strictly."""
    fig = construct.get("crank").figure(parts=6)
    d = fig.protocol.as_dict(fig.replay)
    assert d.pop("format") == "construct-protocol/1"
    again = Protocol.from_dict(d)
    assert again.replay()["P3"] == fig.replay["P3"]
    d["steps"][3]["tool"] = "hammer"
    with pytest.raises(ProtocolFormatError, match="'tool' is 'hammer'"):
        Protocol.from_dict(d)


def test_every_gallery_protocol_loads_and_replays():
    files = sorted(GALLERY.glob("*/protocol.json"))
    assert len(files) >= 10
    for f in files:
        proto = Protocol.load(f)
        objects = json.loads(f.read_text(encoding="utf-8"))["objects"]
        replay = proto.replay()
        assert set(replay) == set(objects), f


def test_the_op_table_declares_the_kinds_its_functions_make():
    """The static output kinds (what a file is checked against) agree with what each op really makes."""
    figs = [construct.get("crank").figure(parts=p, method=m) for p, m in ((6, "neusis"), (7, "dividers"))]
    figs += [construct.get(name).figure() for name in ("inertia-curve", "tangential-pressure", "two-cranks")]
    b = Builder("polyline", givens={})
    for name, x in (("A", 0.0), ("B", 1.0), ("C", 2.0)):
        b.given_point(name, x, x * x)
    b.polyline("p", ["A", "B", "C"])
    for name, x in (("D", 0.0), ("E", 1.0), ("F", 2.0)):
        b.given_point(name, x, 5.0)
    b.polyline("q", ["D", "E", "F"])
    b.area_between("between", "q", "p", "A", "C")
    b.planimeter("reading", "between")
    # a traced card and a point picked off it (the indicator card's trace, the piston force's J)
    b2 = Builder("traced", givens={"s": 1.0, "u": 1.0, "x0": 0.0, "p0": 2.0, "x1": 1.0, "p1": 1.0})
    b2.given_point("H", 0.0, 0.0)
    b2.given_point("K", 2.0, 0.0)
    b2.record("curve", "trace", ("H", "K", "H", "K"), ("t",), {"xs": ("x0", "x1"), "ps": ("p0", "p1"), "stroke": ("s",),
              "pressure": ("u",), "stroke_factor": 2.0}, "übertragen", "traced")
    b2.record("curve", "vertex", ("t",), ("v",), {"index": 1}, "Punkt", "point")
    assert b2["v"] == construct.Point(2.0, 1.0)
    figs += [b.figure(), b2.figure()]
    seen = set()
    for fig in figs:
        for step in fig.protocol.steps:
            made = OPS[step.op].output_kinds(step.params)
            assert tuple(kind_of(fig.replay[n]) for n in step.outputs) == made, step
            seen.add(step.op)
    assert seen == set(OPS)


def test_a_builder_protocol_with_no_steps_still_pickles():
    proto = Builder("empty", givens={}).protocol()
    assert pickle.loads(pickle.dumps(proto)).steps == ()
    with pytest.raises(ProtocolFormatError, match="no steps"):
        Protocol.from_dict(proto.as_dict(with_objects=False))


# -- 3: checks of a protocol that lacks what they read --------------------------------------------------------


def _truncated(d: dict) -> None:
    d["steps"] = d["steps"][:10]


def _renamed(d: dict) -> None:
    text = json.dumps(d).replace('"P3"', '"P3x"')
    d.clear()
    d.update(json.loads(text))


def _swapped(d: dict) -> None:  # a point's and a line's names exchanged: every step still fits its op
    text = json.dumps(d).replace('"P3"', '"@"').replace('"axis"', '"P3"').replace('"@"', '"axis"')
    d.clear()
    d.update(json.loads(text))


@pytest.mark.parametrize("edit,message", [
    (_truncated, r"the protocol of 'crank' lacks the object 'X0' its checks need \(truncated or renamed\?\)"),
    (_renamed, r"the protocol of 'crank' lacks the object 'P3' its checks need \(truncated or renamed\?\)"),
    (_swapped, r"the checks of 'crank' cannot read this protocol's figure .*was the protocol edited\?"),
    (lambda d: d["params"].__setitem__("parts", "6"), r"the checks of 'crank' cannot read"),
    (lambda d: d["params"].pop("parts"), r"the protocol of 'crank' lacks 'parts', which its checks need"),
])
def test_check_of_a_protocol_lacking_what_its_checks_need(edit, message, crank_file, tmp_path, capsys):
    d = copy.deepcopy(crank_file)
    edit(d)
    path = tmp_path / "protocol.json"
    path.write_text(json.dumps(d), encoding="utf-8")
    code, _, err = _cli(capsys, "check", "--protocol", str(path))
    assert code == 2 and len(err.splitlines()) == 1, err
    assert re.search(message, err), err
    proto = Protocol.load(path)  # it is a well-formed protocol: it loads and replays ...
    fig = construct.Figure(proto, proto.replay())
    with pytest.raises(ProtocolFormatError, match=message):  # ... but is not what the crank's checks read
        construct.get("crank").check(fig)
    with pytest.raises(ProtocolFormatError, match=message):  # the same through a figure that carries them
        construct.Figure(proto, proto.replay(), construct.get("crank").check).checks()


def test_a_whole_protocol_still_checks(crank_file, tmp_path, capsys):
    path = tmp_path / "protocol.json"
    path.write_text(json.dumps(crank_file), encoding="utf-8")
    code, out, err = _cli(capsys, "check", "--protocol", str(path))
    assert code == 0 and "checks pass" in out, err


# -- 4: a bounded read ----------------------------------------------------------------------------------------


def test_the_limit_leaves_room_above_the_largest_gallery_protocol():
    largest = max(f.stat().st_size for f in GALLERY.glob("*/protocol.json"))
    assert largest * 20 < MAX_PROTOCOL_BYTES == 64 * 2**20


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom"])
def test_a_device_is_refused_without_reading(device, tmp_path, capsys):
    if not os.path.exists(device):
        pytest.skip(f"no {device}")
    with pytest.raises(ProtocolFormatError, match="not a regular file"):
        Protocol.load(device)
    _assert_refused(capsys, Path(device), tmp_path / "out")
    with pytest.raises(ProtocolFormatError, match="not a regular file"):
        diff_protocol(device, device)


def test_a_fifo_without_a_writer_does_not_hang(tmp_path, capsys):
    fifo = tmp_path / "pipe.json"
    os.mkfifo(fifo)
    outcome = []
    reader = threading.Thread(target=lambda: outcome.append(main(["check", "--protocol", str(fifo)])), daemon=True)
    reader.start()
    reader.join(timeout=20)
    assert not reader.is_alive(), "reading a FIFO hung"
    assert outcome == [2]
    assert "not a regular file" in capsys.readouterr().err


def test_a_file_above_the_limit_is_refused_by_its_size(tmp_path, capsys):
    big = tmp_path / "big.json"
    with open(big, "wb") as fh:  # sparse: no disk space, no time
        fh.truncate(MAX_PROTOCOL_BYTES + 1)
    with pytest.raises(ProtocolFormatError, match="larger than 64 MiB"):
        Protocol.load(big)
    _assert_refused(capsys, big, tmp_path / "out")


def test_a_file_that_reports_no_size_is_still_read_only_to_the_limit(monkeypatch):
    status = Path("/proc/self/status")  # a regular file of size 0 with content, like a file that grows
    if not status.exists() or status.stat().st_size != 0:
        pytest.skip("no /proc")
    monkeypatch.setattr(protocol_file, "MAX_PROTOCOL_BYTES", 100)
    with pytest.raises(ProtocolFormatError, match="larger than"):
        protocol_file.read_protocol_bytes(status)


@pytest.mark.parametrize("name,message", [("", "empty"), ("nowhere.json", "does not exist"), (".", "is a folder")])
def test_unreadable_protocol_paths(name, message, tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    with pytest.raises(ProtocolFormatError, match=message):
        Protocol.load(name)
    code, _, err = _cli(capsys, "check", "--protocol", name)
    assert code == 2 and len(err.splitlines()) == 1


# -- 5: givens ------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("value", [math.nan, math.inf, -math.inf, "abc", None, True, [1.0, math.nan], ["a", "b"]])
def test_a_replay_refuses_a_given_that_is_not_a_finite_number_naming_it(value):
    proto = construct.get("crank").figure(parts=6).protocol
    with pytest.raises(InvalidParameter, match=r"the (swept )?given 'rod_ratio' must be"):
        proto.replay({"r": 1.0, "rod_ratio": value})


def test_a_sweep_of_finite_givens_still_replays():
    proto = construct.get("crank").figure(parts=6).protocol
    sweep = proto.replay({"r": 1.0, "rod_ratio": np.array([4.0, 5.0])})
    assert sweep.size == 2


@pytest.mark.parametrize("value", ["nan", "inf", "-inf", "abc", ""])
def test_the_given_option_refuses_what_is_not_a_finite_number(value, crank_file, tmp_path, capsys):
    path = tmp_path / "protocol.json"
    path.write_text(json.dumps({**crank_file, "construction": "my-crank"}), encoding="utf-8")
    code, _, err = _cli(capsys, "replay", "--protocol", str(path), "--given", f"rod_ratio={value}",
                        "--out", str(tmp_path / "out"))
    assert code == 2 and "rod_ratio" in err and len(err.splitlines()) == 1, err
    assert not (tmp_path / "out").exists()


# -- 6: the library's entry points ----------------------------------------------------------------------------


def _builder() -> Builder:
    b = Builder("demo", givens={"s": 1.0})
    b.given_point("A", 0.0, 0.0)
    b.given_point("B", 2.0, 0.0)
    b.circle_through("ka", "A", "B")
    b.circle_through("kb", "B", "A")
    return b


MISUSE = {
    "Builder givens None": (lambda: Builder("x", givens=None), InvalidParameter, "givens are a mapping"),
    "Builder givens a list": (lambda: Builder("x", givens=[("s", 1)]), InvalidParameter, "givens are a mapping"),
    "Builder a NaN given": (lambda: Builder("x", givens={"s": math.nan}), InvalidParameter, "the given 's'"),
    "Builder a name that is not a string": (lambda: Builder(5, givens={}), InvalidParameter, "non-empty string"),
    "a Point where a name is expected": (lambda: _builder().line("g", Point(0.0, 0.0), "B"), WrongInput,
                                         r"step 5 .*objects are passed by name"),
    "a list where a name is expected": (lambda: _builder().circle_through("k", ["A"], "B"), WrongInput,
                                        "objects are passed by name"),
    "a coordinate that is a string": (lambda: _builder().given_point("C", "abc", 0.0), WrongInput,
                                      r"step 5 .*parameter 'x' must be a finite number, got 'abc'"),
    "a NaN coordinate": (lambda: _builder().given_point("C", math.nan, 0.0), WrongInput, "parameter 'x'"),
    "a product that is a string": (lambda: _builder().given_length("L", product="s"), InvalidParameter,
                                   "product is a list of names"),
    "a rule naming an unknown object": (lambda: _builder().intersect("X", "ka", "kb", rule=construct.nearer("Q")),
                                        UnknownObject, "'Q'"),
    "a rule with a NaN direction": (lambda: construct.toward(dx=math.nan), RuleError, "finite"),
    "a rule whose name is a list": (lambda: _builder().intersect("X", "ka", "kb", rule=[["left"], "A", "B"]),
                                    RuleError, "starts with its name"),
    "an unknown instrument": (lambda: _builder().record("hammer", "line", ("A", "B"), ("g",), {}, "d", "e"),
                              StepError, "unknown instrument 'hammer'"),
    "an unknown role": (lambda: _builder().line("g", "A", "B", role="hero"), StepError, "unknown role 'hero'"),
    "outputs as one string": (lambda: _builder().record("straightedge", "line", ("A", "B"), "g", {}, "d", "e"),
                              StepError, "outputs are a list"),
    "a group title that is not text": (lambda: _builder().group(5).__enter__(), InvalidParameter, "titles are text"),
    "a label that is not text": (lambda: _builder().set_label("A", 5), InvalidParameter, "is text"),
    "a builder lookup by a list": (lambda: _builder()[["A"]], UnknownObject, "no object"),
    "a replay lookup of an unknown name": (lambda: _builder().protocol().replay()["Q"], UnknownObject,
                                           "has no object 'Q'"),
    "a replay lookup by a list": (lambda: _builder().protocol().replay()[["A"]], UnknownObject, "has no object"),
    "take by a string": (lambda: _builder().protocol().replay().take("a"), InvalidParameter, "by its number"),
    "take beyond a sweep": (lambda: _builder().protocol().replay({"s": [1.0, 2.0]}).take(5), InvalidParameter,
                            "no set 5"),
    "replay givens not a mapping": (lambda: _builder().protocol().replay([1.0]), InvalidParameter, "mapping"),
    "replay upto a string": (lambda: _builder().protocol().replay(upto="3"), InvalidParameter, "upto"),
    "from_json of None": (lambda: Protocol.from_json(None), ProtocolFormatError, "str or bytes"),
    "from_dict of a list": (lambda: Protocol.from_dict([]), ProtocolFormatError, "JSON object"),
    "from_dict with a number for a step": (lambda: Protocol.from_dict({"construction": "x", "params": {},
                                                                       "steps": [1]}),
                                           ProtocolFormatError, "step 1 must be an object"),
    "load of None": (lambda: Protocol.load(None), ProtocolFormatError, "named by a path"),
    "get of a list": (lambda: construct.get(["crank"]), UnknownConstruction, "unknown construction"),
    "svg in an unknown style": (lambda: _builder().figure().svg(style="nope"), InvalidParameter,
                                "unknown style 'nope'"),
    "svg upto a string": (lambda: _builder().figure().svg(upto="x"), InvalidParameter, "upto"),
    "write with unknown frames": (lambda: _builder().figure().write("unused", frames="x"),
                                  InvalidParameter, "unknown frames mode 'x'"),
    "with_givens of a string": (lambda: _builder().figure().with_givens(s="x"), InvalidParameter, "the given 's'"),
    "a Point of a string": (lambda: Point("a", 1.0), WrongInput, "are numbers, got 'a'"),
    "a Length of a string": (lambda: construct.Length("x"), WrongInput, "are numbers"),
}


@pytest.mark.parametrize("case", list(MISUSE))
def test_misuse_of_the_library_raises_a_construct_error_naming_it(case):
    call, cls, message = MISUSE[case]
    with pytest.raises(cls, match=message) as info:
        call()
    assert isinstance(info.value, ConstructError)


def test_a_protocol_without_a_given_its_construction_validates_is_refused(crank_file, tmp_path, capsys):
    d = copy.deepcopy(crank_file)
    d["steps"] = d["steps"][:3]  # no step reads the rod ratio any more ...
    del d["params"]["givens"]["rod_ratio"]  # ... so the file may drop it, but the crank's givens include it
    d["givens"].remove("rod_ratio")
    path = tmp_path / "protocol.json"
    path.write_text(json.dumps(d), encoding="utf-8")
    message = "the protocol of 'crank' lacks the given 'rod_ratio' of the construction (it has r)"
    assert message in _assert_refused(capsys, path, tmp_path / "out")


# -- fuzzing the protocol file: whatever is changed, a loaded protocol replays or fails with a construct error --

from hypothesis import HealthCheck, given, settings, strategies as st  # noqa: E402

_JSON = st.recursive(st.none() | st.booleans() | st.integers(-10, 10**6) | st.floats() | st.text(max_size=5),
                     lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=4), inner,
                                                                                  max_size=3), max_leaves=6)


def _paths(value, prefix=()):
    yield prefix
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _paths(v, prefix + (k,))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from _paths(v, prefix + (i,))


@pytest.fixture(scope="module")
def small_crank() -> dict:
    fig = construct.get("crank").figure(parts=2)
    d = json.loads(fig.protocol.to_json(fig.replay))
    del d["objects"]  # not read by the loader: mutations there would be wasted
    return d


@settings(max_examples=3 * settings.default.max_examples, deadline=None,  # 300 in CI (conftest.py)
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_fuzzed_protocols_load_and_replay_or_fail_with_a_construct_error(small_crank, data):
    d = copy.deepcopy(small_crank)
    paths = [p for p in _paths(d) if p]
    for _ in range(data.draw(st.integers(1, 3))):
        path = data.draw(st.sampled_from(paths))
        target = d
        try:
            for key in path[:-1]:
                target = target[key]
            action = data.draw(st.sampled_from(["set", "delete", "truncate"]))
            if action == "set":
                target[path[-1]] = data.draw(_JSON)
            elif action == "delete":
                del target[path[-1]]
            elif isinstance(target[path[-1]], list):
                del target[path[-1]][data.draw(st.integers(0, 5)):]
        except (KeyError, IndexError, TypeError):
            pass  # an earlier mutation removed or replaced this path
    text = json.dumps(d)  # NaN and Infinity included, as Python's json writes and reads them
    try:
        proto = Protocol.from_json(text)
    except ProtocolFormatError:
        return
    fig = None
    try:
        fig = construct.Figure(proto, proto.replay())
    except ConstructError:
        return
    try:
        construct.get(proto.construction).check(fig)
    except ConstructError:
        pass


def test_divide_segment_refuses_more_parts_than_it_can_draw():
    # divide_segment(..., 10**9) once ran until memory ran out: refused before the first part is drawn.
    from construct import Builder
    from construct.kernel.errors import InvalidParameter

    b = Builder("demo", givens={})
    b.given_point("A", 0.0, 0.0)
    b.given_point("B", 1.0, 0.0)
    for n in (10**9, 1, True, 2.5):
        with pytest.raises(InvalidParameter, match="parts"):
            b.divide_segment("T", "A", "B", n)
    assert len(b.divide_segment("T", "A", "B", 3)) == 2


def test_an_error_quotes_a_huge_multiline_caption_on_one_short_line(tmp_path, capsys):
    # A caption read from a file may hold line breaks and megabytes; the step's error quotes it, and the CLI
    # promises one line on stderr.
    import json as _json

    import construct
    from construct.cli.main import main

    fig = construct.get("crank").figure(parts=6)
    doc = _json.loads(fig.protocol.to_json(fig.replay))
    doc["steps"][5]["caption"]["en"] = "first line\nsecond line " + "x" * 1_000_000
    doc["steps"][5]["inputs"] = doc["steps"][5]["inputs"][:1]  # an intersect with one input: refused at load
    path = tmp_path / "p.json"
    path.write_text(_json.dumps(doc))
    assert main(["check", "--protocol", str(path)]) == 2
    err = capsys.readouterr().err
    assert len(err.splitlines()) == 1 and len(err) < 2100 and "first line second line" in err, err[:300]


def test_what_this_library_writes_it_reads_back(tmp_path, monkeypatch, cli):
    """A protocol larger than the reader's limit is refused when written, before the folder is touched: the same
    limit as construct check and replay --protocol read (a 280,000-step protocol of 71 MB was written, then
    refused by both)."""
    import construct.kernel.protocol as protocol_module
    from construct.constructions import get
    from construct.kernel.errors import OutputError

    text = get("crank").figure(parts=6).protocol.to_json()
    monkeypatch.setattr(protocol_module, "MAX_PROTOCOL_BYTES", len(text.encode()) - 1)
    with pytest.raises(OutputError, match="more than the 0 MiB a protocol file may have to be read back"):
        get("crank").figure(parts=6).protocol.to_json()
    code, _, err = cli("replay", "crank", "--parts", "6", "--out", tmp_path / "c")
    assert code == 2 and "read back" in err and not (tmp_path / "c").exists()
    monkeypatch.setattr(protocol_module, "MAX_PROTOCOL_BYTES", len(text.encode()))
    assert get("crank").figure(parts=6).protocol.to_json() == text
