"""Semantic SVG diff: geometry changes are caught and named, formatting changes are not.

Every expected value below is worked out by hand from the fixture text (a
centre shifted by 0.01, a circle inside translate(10, 0) at cx + 10, ...),
never copied from the diff's own output.
"""

from __future__ import annotations

import json
import math
import random

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from construct.cli.main import main
from construct.kernel.errors import ConstructError
from construct.regress.change import Change
from construct.regress.svgdiff import SvgFormatError, diff_svg, parse_svg

HEAD = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 200 100">'


def svg(body: str, head: str = HEAD) -> str:
    return f"{head}{body}</svg>"


def kinds(diff) -> list[tuple[str, str]]:
    return [(c.kind, c.key) for c in diff.changes]


# A frame as our renderer writes it: ids from step and object names, a group per step.
GOLDEN = svg("""
<g id="s001" stroke="#000000" stroke-width="0.35" fill="none">
  <line id="s001-axis" x1="10.000" y1="50.000" x2="190.000" y2="50.000"/>
  <circle id="s001-crank-circle" cx="60.000" cy="50.000" r="20.000"/>
</g>
<g id="s012" stroke="#000000" stroke-width="0.25" fill="none">
  <path id="s012-rod-arc-P3" d="M 140.000 50.000 A 60.000 60.000 0 0 1 129.000 79.000"/>
  <circle id="s012-P3" cx="80.000" cy="50.000" r="0.800" fill="#000000"/>
  <text id="s012-label-P3" x="82.000" y="47.000" font-size="4" fill="#000000" stroke="none">P3</text>
</g>
""")


def test_golden_equals_itself():
    d = diff_svg(GOLDEN, GOLDEN)
    assert d.equal and d.changes == ()
    assert "equal" in d.report()


def test_moving_one_point_by_a_hundredth_is_caught_and_named():
    moved = GOLDEN.replace('cx="80.000" cy="50.000" r="0.800"', 'cx="80.010" cy="50.000" r="0.800"')
    d = diff_svg(GOLDEN, moved)
    assert not d.equal
    assert kinds(d) == [("moved", "s012-P3")]
    (change,) = d.changes
    # 80.010 - 80.000 = 0.01; the tolerance covers only float noise of one subtraction.
    assert change.magnitude == pytest.approx(0.01, abs=1e-12)
    assert change.shape == "circle" and change.matched_by == "id"
    assert "s012-P3" in d.report() and "0.01" in d.report()


def test_moving_one_end_of_a_segment_by_a_hundredth():
    moved = GOLDEN.replace('y2="50.000"/>', 'y2="50.010"/>')
    d = diff_svg(GOLDEN, moved)
    change = next(c for c in d.changes if c.kind == "moved")
    assert change.key == "s001-axis"
    assert change.magnitude == pytest.approx(0.01, abs=1e-12)
    assert "end" in change.description
    # Length grows from 180 to hypot(180, 0.01) = 180.00000028; below the 1e-6 tolerance.
    assert [c.kind for c in d.changes] == ["moved"]


def test_reformatted_golden_is_equal():
    """Reordered attributes, whitespace, 1.50 vs 1.5, colour spellings, style vs attributes."""
    rewritten = svg("""<g  stroke-width = '.35'   fill='none' style="stroke: black" id='s001'>
        <line y2="50" x2="190" y1="5e1" x1="10" id="s001-axis"/><circle r="20.0" cy="50.0" cx="60" id="s001-crank-circle"/>
      </g>
      <g style="fill:none;stroke:rgb(0, 0, 0);stroke-width:0.250" id="s012">
        <path d="m140,50a60,60,0,0,1-11,29" id="s012-rod-arc-P3"/>
        <circle style="fill:#000" r=".8" cy="50" cx="80.0" id="s012-P3"/>
        <text font-size="4.0" y="47" x="82" id="s012-label-P3" style="fill: BLACK; stroke: none">
            P3
        </text>
      </g>""", head='<svg viewBox="0,0,200,100" xmlns:xlink="http://www.w3.org/1999/xlink" xmlns="http://www.w3.org/2000/svg">')
    d = diff_svg(GOLDEN, rewritten)
    assert d.equal, d.report()


@pytest.mark.parametrize("a, b", [
    ('<circle cx="1.50" cy="2" r="1"/>', '<circle r="1" cy="2" cx="1.5"/>'),
    ('<circle r="1" fill="#000"/>', '<circle r="1" fill="black"/>'),
    ('<circle r="1" fill="#000000"/>', '<circle r="1" fill="rgb(0,0,0)"/>'),
    ('<circle r="1" fill="#f00"/>', '<circle r="1" fill="red"/>'),
    ('<circle r="1" stroke="blue" stroke-width="2"/>', '<circle r="1" style="stroke:#0000ff;stroke-width:2.0"/>'),
    ('<circle r="1" fill="black"/>', '<circle r="1"/>'),  # black is the initial fill
    ('<circle r="1" stroke="currentColor" color="red"/>', '<circle r="1" stroke="red" color="red"/>'),
    ('<path d="M 0 0 H 10 V 5 L 0 5 Z"/>', '<path d="M0,0 L10,0 L10,5 L0,5 z"/>'),
    ('<path d="M 0 0 l 10 0 l 0 5"/>', '<path d="M0 0 10 0 10 5"/>'),  # implicit lineto after moveto
    # S reflects the previous second control point (2,4) about the current point (3,0): (4,-4).
    ('<path d="M0 0 C 1 2 2 4 3 0 S 5 1 6 0"/>', '<path d="M0 0 C1 2 2 4 3 0 C 4 -4 5 1 6 0"/>'),
    ('<rect x="1" y="1" width="2" height="2"/>', '<rect height="2" width="2" y="1" x="1" rx="0"/>'),
    ('<text x="1" y="2">Kurbel\n   K</text>', '<text y="2" x="1"> Kurbel K </text>'),
])
def test_formatting_only_differences_are_equal(a, b):
    assert diff_svg(svg(a), svg(b)).equal, diff_svg(svg(a), svg(b)).report()


@pytest.mark.parametrize("group, shape", [
    ('<g transform="translate(10,0)"><circle cx="1" cy="2" r="3"/></g>', '<circle cx="11" cy="2" r="3"/>'),
    # scale(2) doubles coordinates, the radius and the stroke width.
    ('<g transform="scale(2)" stroke-width="1"><circle cx="1" cy="2" r="3"/></g>',
     '<circle cx="2" cy="4" r="6" stroke-width="2"/>'),
    # rotate(90) maps (x, y) to (-y, x): (1,0)-(3,0) becomes (0,1)-(0,3).
    ('<g transform="rotate(90)"><line x1="1" y1="0" x2="3" y2="0"/></g>', '<line x1="0" y1="1" x2="0" y2="3"/>'),
    # Nested groups compose: translate(5,5) after rotate(180) maps (1,2) to (4,3).
    ('<g transform="translate(5,5)"><g transform="rotate(180)"><circle cx="1" cy="2" r="1"/></g></g>',
     '<circle cx="4" cy="3" r="1"/>'),
    # matrix(1 0 0 1 7 8) is a translation by (7, 8).
    ('<g transform="matrix(1 0 0 1 7 8)"><line x1="0" y1="0" x2="1" y2="1"/></g>', '<line x1="7" y1="8" x2="8" y2="9"/>'),
    # skewX(45) maps (x, y) to (x + y, y).
    ('<g transform="skewX(45)"><line x1="0" y1="2" x2="1" y2="3"/></g>', '<line x1="2" y1="2" x2="4" y2="3"/>'),
    # An arc of radius 10 about the origin, translated by (10, 0): centre (10, 0).
    ('<path transform="translate(10 0)" d="M 10 0 A 10 10 0 0 1 0 10"/>', '<path d="M 20 0 A 10 10 0 0 1 10 10"/>'),
    # <use> of a definition at x=5: the definition itself is not drawn.
    ('<defs><circle id="dot" r="1"/></defs><use xlink:href="#dot" x="5" y="6"/>',
     '<defs><circle id="dot" r="1"/></defs><use href="#dot" transform="translate(5 6)"/>'),
])
def test_transforms_are_composed_to_absolute_coordinates(group, shape):
    d = diff_svg(svg(group), svg(shape))
    # Float noise of cos/sin(90 deg) is ~1e-16 per unit; far below the default 1e-6.
    assert d.equal, d.report()


def test_defs_are_not_drawn_and_use_is_expanded():
    drawing = parse_svg(svg('<defs><circle id="dot" r="1"/></defs><use xlink:href="#dot" x="5" y="6"/>'))
    assert [(s.key, s.kind) for s in drawing.shapes] == [("use[0]", "circle")]
    assert drawing.shapes[0].points == (("centre", (5.0, 6.0)),)


def test_moved_arc_reports_a_moved_centre():
    a = svg('<path id="s012-rod-arc-P3" d="M 10 0 A 10 10 0 0 1 0 10"/>')
    # Both end points shift by 0.01 in x, so the centre of the radius-10 arc moves from (0,0) to (0.01,0).
    b = svg('<path id="s012-rod-arc-P3" d="M 10.01 0 A 10 10 0 0 1 0.01 10"/>')
    (change,) = diff_svg(a, b).changes
    assert change.kind == "moved" and change.key == "s012-rod-arc-P3"
    assert change.magnitude == pytest.approx(0.01, abs=1e-9)
    assert "centre (0, 0) -> (0.01, 0)" in change.description


def test_arc_radius_change_is_resized():
    a = svg('<path id="arc" d="M 10 0 A 10 10 0 0 1 -10 0"/>')
    # Same end points, radius 10 -> 12: a different arc through them.
    b = svg('<path id="arc" d="M 10 0 A 12 12 0 0 1 -10 0"/>')
    d = diff_svg(a, b)
    resized = [c for c in d.changes if c.kind == "resized"]
    assert resized and resized[0].magnitude == pytest.approx(2.0, abs=1e-9)


def test_path_with_other_commands_is_reshaped():
    d = diff_svg(svg('<path id="p" d="M0 0 L 10 0"/>'), svg('<path id="p" d="M0 0 Q 5 5 10 0"/>'))
    assert [c.kind for c in d.changes] == ["reshaped"]
    assert "M L -> M Q" in d.changes[0].description


def test_circle_radius_change_is_resized_not_moved():
    d = diff_svg(svg('<circle id="k" cx="5" cy="5" r="2"/>'), svg('<circle id="k" cx="5" cy="5" r="2.5"/>'))
    assert kinds(d) == [("resized", "k")]
    assert d.changes[0].magnitude == pytest.approx(0.5)


def test_restyled_stroke_width_names_old_and_new():
    d = diff_svg(svg('<line id="g" x2="1" stroke-width="0.35"/>'), svg('<line id="g" x2="1" style="stroke-width:0.5"/>'))
    (change,) = d.changes
    assert change.kind == "restyled" and change.key == "g"
    assert "stroke-width 0.35 -> 0.5" in change.description
    assert change.magnitude == pytest.approx(0.15)


def test_restyle_inherited_from_a_group_reaches_its_elements():
    a = svg('<g stroke="black"><line id="g" x2="1"/></g>')
    b = svg('<g stroke="red"><line id="g" x2="1"/></g>')
    (change,) = diff_svg(a, b).changes
    assert change.kind == "restyled" and "stroke #000000 -> #ff0000" in change.description


def test_missing_and_extra():
    a = svg('<circle id="A" r="1"/><circle id="B" cx="50" r="1"/>')
    b = svg('<circle id="A" r="1"/><line id="C" x1="100" x2="150"/>')
    d = diff_svg(a, b)
    assert kinds(d) == [("missing", "B"), ("extra", "C")]


def test_renamed_element_is_matched_by_geometry():
    d = diff_svg(svg('<circle id="s003-M" cx="5" cy="5" r="1"/>'), svg('<circle id="s004-M" cx="5" cy="5" r="1"/>'))
    (change,) = d.changes
    assert change.kind == "renamed" and change.matched_by == "geometry"
    assert change.key == "s003-M" and change.key_b == "s004-M"


def test_inserted_anonymous_element_shifts_no_keys_into_changes():
    a = svg('<circle r="1"/><circle r="2"/><circle r="3"/>')
    b = svg('<circle cx="100" r="9"/><circle r="1"/><circle r="2"/><circle r="3"/>')
    d = diff_svg(a, b)
    assert kinds(d) == [("extra", "circle[0]")]


def test_text_changed():
    d = diff_svg(svg('<text id="t" x="1" y="2">P3</text>'), svg('<text id="t" x="1" y="2">P4</text>'))
    (change,) = d.changes
    assert change.kind == "text" and "'P3' -> 'P4'" in change.description


def test_document_size_change():
    a = svg("<circle r='1'/>")
    b = svg("<circle r='1'/>", head=HEAD.replace("0 0 200 100", "0 0 200 120"))
    (change,) = diff_svg(a, b).changes
    assert change.kind == "document" and change.key == "viewBox"
    assert change.magnitude == pytest.approx(20)


def test_animation_is_an_attribute_of_its_parent():
    a = svg('<circle id="P" r="1"><set attributeName="visibility" to="visible" begin="1.50s"/></circle>')
    same = svg('<circle id="P" r="1"><set begin="1.5s" attributeName="visibility" to="visible"/></circle>')
    later = svg('<circle id="P" r="1"><set attributeName="visibility" to="visible" begin="2s"/></circle>')
    assert diff_svg(a, same).equal
    (change,) = diff_svg(a, later).changes
    assert change.kind == "animated" and change.key == "P"
    assert "1.5s" in change.description and "2s" in change.description


def test_title_change_is_described():
    a = svg('<g id="s1"><title>Schritt 1</title><circle id="k" r="1"/></g>')
    b = svg('<g id="s1"><title>Schritt 2</title><circle id="k" r="1"/></g>')
    assert kinds(diff_svg(a, b)) == [("described", "s1")]


def test_tolerance_is_inclusive():
    a, b = svg('<circle id="k" cx="1" r="1"/>'), svg('<circle id="k" cx="1.5" r="1"/>')
    # 1.5 - 1 = 0.5 exactly in binary floating point.
    assert diff_svg(a, b, tolerance=0.5).equal
    assert not diff_svg(a, b, tolerance=0.25).equal


def test_report_and_dict_are_deterministic():
    moved = GOLDEN.replace('r="20.000"', 'r="21"').replace(">P3<", ">P4<")
    d1, d2 = diff_svg(GOLDEN, moved), diff_svg(GOLDEN, moved)
    assert d1.report() == d2.report()
    assert json.dumps(d1.as_dict()) == json.dumps(d2.as_dict())
    assert [c["key"] for c in d1.as_dict()["changes"]] == ["s001-crank-circle", "s012-label-P3"]
    assert all(isinstance(c, Change) for c in d1.changes)


@pytest.mark.parametrize("bad", ["not xml at all", "<html><body/></html>", "<svg xmlns='x'><g></svg>", b"\xff\xfe<"])
def test_bad_input_raises_a_construct_error(bad):
    with pytest.raises(SvgFormatError):
        diff_svg(bad if not isinstance(bad, str) or bad.startswith("<") else bad.encode(), svg(""))
    assert issubclass(SvgFormatError, ConstructError)


def test_malformed_path_data_is_bad_input():
    with pytest.raises(SvgFormatError, match="path"):
        parse_svg(svg('<path d="M 0 0 L x"/>'))


# --------------------------------------------------------------------------- command line

@pytest.fixture
def files(tmp_path):
    def write(name: str, text: str):
        p = tmp_path / name
        p.write_text(text, encoding="utf-8")
        return str(p)
    return write


def test_cli_exit_codes(files, capsys):
    a = files("a.svg", GOLDEN)
    b = files("b.svg", GOLDEN.replace('cx="80.000"', 'cx="80.010"'))
    assert main(["diff", a, a]) == 0
    assert main(["diff", a, b]) == 1
    out = capsys.readouterr().out
    assert "s012-P3" in out and "moved" in out
    assert main(["diff", a, b, "--tolerance", "0.02"]) == 0
    assert "equal" in capsys.readouterr().out
    assert main(["diff", a, b, "--json"]) == 1
    data = json.loads(capsys.readouterr().out)
    assert data["equal"] is False and data["changes"][0]["key"] == "s012-P3"


def test_cli_bad_input_exits_2(files, capsys):
    a = files("a.svg", GOLDEN)
    text = files("notes.txt", "Kurbelkreis, Schubstange\n")
    html = files("page.html", "<html><body/></html>")
    proto = files("protocol.json", '{"construction": "x", "params": {}, "steps": []}')
    assert main(["diff", a, text]) == 2
    assert main(["diff", a, html]) == 2
    assert main(["diff", a, a + ".missing"]) == 2
    assert main(["diff", a, proto]) == 2  # mixed kinds
    assert main(["diff", a, a, "--tolerance", "-1"]) == 2
    err = capsys.readouterr().err
    assert err.count("construct: error:") == 5


# --------------------------------------------------------------------------- invariants

# Coordinates on a 1/8 grid: every spelling below ("1.5", "1.500000", "+1.5", "15e-1")
# parses to the very same float, so equality must be exact.
coord = st.integers(-800, 800).map(lambda k: k / 8)
radius = st.integers(1, 400).map(lambda k: k / 8)
COLOURS = [("#000", "black", "rgb(0,0,0)", "#000000"), ("#f00", "red", "#FF0000", "rgb(100%,0%,0%)"),
           ("none", "none", "None", "transparent")]


@st.composite
def drawings(draw):
    """A random drawing as a list of (tag, attributes, text) with abstract values."""
    elements = []
    for n in range(draw(st.integers(1, 8))):
        tag = draw(st.sampled_from(["circle", "line", "rect", "path", "text"]))
        if tag == "circle":
            attrs = {"cx": draw(coord), "cy": draw(coord), "r": draw(radius)}
        elif tag == "line":
            attrs = {"x1": draw(coord), "y1": draw(coord), "x2": draw(coord), "y2": draw(coord)}
        elif tag == "rect":
            attrs = {"x": draw(coord), "y": draw(coord), "width": draw(radius), "height": draw(radius)}
        elif tag == "path":
            x, y, r = draw(coord), draw(coord), draw(radius)
            attrs = {"d": ("arc", x, y, r)}
        else:
            attrs = {"x": draw(coord), "y": draw(coord)}
        attrs["stroke"] = ("colour", draw(st.integers(0, 2)))
        attrs["stroke-width"] = (n + 1) / 8  # distinct, so no two elements are identical
        if draw(st.booleans()):
            attrs["id"] = f"s{n:03d}-{tag}"
        elements.append((tag, attrs, f"P{n}" if tag == "text" else None))
    return elements


def render(elements, rnd: random.Random, shift: tuple[int, float, float] | None = None) -> str:
    """Write a drawing with random attribute order, number spellings and colour spellings."""

    def num(v: float) -> str:
        return rnd.choice([repr(v), f"{v:.6f}", f"+{v}" if v >= 0 else repr(v), f"{v * 10:g}e-1"])

    parts = []
    for i, (tag, attrs, text) in enumerate(elements):
        items = []
        for name, value in attrs.items():
            if isinstance(value, tuple) and value[0] == "colour":
                items.append((name, rnd.choice(COLOURS[value[1]])))
            elif isinstance(value, tuple) and value[0] == "arc":
                # A quarter circle of radius r about (x, y), from (x+r, y) to (x, y+r).
                _, x, y, r = value
                items.append((name, f"M {num(x + r)} {num(y)} A {num(r)} {num(r)} 0 0 1 {num(x)} {num(y + r)}"))
            elif isinstance(value, float):
                items.append((name, num(value)))
            else:
                items.append((name, value))
        rnd.shuffle(items)
        style = [kv for kv in items if kv[0] in ("stroke", "stroke-width") and rnd.random() < 0.5]
        plain = [kv for kv in items if kv not in style]
        attr_text = " ".join(f'{k}="{v}"' for k, v in plain)
        if style:
            attr_text += ' style="' + "; ".join(f"{k}: {v}" for k, v in style) + '"'
        element = f"<{tag} {attr_text}>{text}</{tag}>" if text else f"<{tag} {attr_text}/>"
        if shift is not None and shift[0] == i:
            element = f'<g transform="translate({shift[1]!r}, {shift[2]!r})">{element}</g>'
        parts.append(" " * rnd.randint(0, 3) + element + "\n" * rnd.randint(0, 2))
    return svg("".join(parts))


@settings(max_examples=60, deadline=None)
@given(drawings(), st.integers(0, 2**32 - 1), st.integers(0, 2**32 - 1))
def test_rewritten_drawing_is_equal(elements, seed_a, seed_b):
    assert diff_svg(render(elements, random.Random(seed_a)), render(elements, random.Random(seed_b))).equal


@settings(max_examples=60, deadline=None)
@given(drawings(), st.data())
def test_translated_element_is_caught_and_named(elements, data):
    i = data.draw(st.integers(0, len(elements) - 1))
    dx = data.draw(st.floats(-5, 5, allow_nan=False))
    dy = data.draw(st.floats(-5, 5, allow_nan=False))
    distance = math.hypot(dx, dy)
    # Well above the 1e-6 default tolerance plus the float noise of adding the shift (~1e-13).
    if distance < 1e-5:
        dx, distance = dx + 1e-3, math.hypot(dx + 1e-3, dy)
    rnd = random.Random(i)
    d = diff_svg(render(elements, rnd), render(elements, random.Random(7), shift=(i, dx, dy)))
    tag, attrs = elements[i][0], elements[i][1]
    key = attrs.get("id") or f"{tag}[{sum(1 for t, a, _ in elements[:i] if t == tag and 'id' not in a)}]"
    moved = [c for c in d.changes if c.kind == "moved"]
    assert [c.key for c in moved] == [key], d.report()
    assert [c.kind for c in d.changes] == ["moved"], d.report()
    assert moved[0].magnitude == pytest.approx(distance, rel=1e-9, abs=1e-9)


def test_class_change_is_restyled():
    # Our renderer writes instrument and provenance as classes: exact -> approximate is a change.
    a = svg('<path id="k1" class="construction compass exact" d="M0 0 L1 1"/>')
    b = svg('<path id="k1" class="compass construction approximate" d="M0 0 L1 1"/>')
    (change,) = diff_svg(a, b).changes
    assert change.kind == "restyled" and "exact" in change.description and "approximate" in change.description


def test_stylesheet_rules_apply_and_reformatting_them_is_equal():
    a = svg('<style>.k{stroke:#000;stroke-width:0.50}</style><line id="g" class="k" x2="1"/>')
    b = svg('<style>\n  .k { stroke: black; stroke-width: .5 }\n</style><line x2="1" class="k" id="g"/>')
    assert diff_svg(a, b).equal
    # The rule reaches the element: same as writing the presentation attributes directly.
    c = svg('<style>.k{stroke:#000;stroke-width:0.50}</style><line id="g" class="k" x2="1" stroke-width="2"/>')
    assert parse_svg(a).shapes[0].style == parse_svg(c).shapes[0].style


# --------------------------------------------------------------------------- hostile drawings
# Each case runs the command line in a fresh interpreter under a time bound the harness enforces
# (subprocess timeout): a hang fails the test instead of stalling the suite.  The bound is generous
# (the cases take a second or a few here); what it catches is a read that goes on for minutes.

import os  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
from pathlib import Path  # noqa: E402

import construct  # noqa: E402
from construct.regress.svgdiff import MAX_ELEMENTS, SvgTooLargeError  # noqa: E402
from construct.regress.svgdiff import values as svgvalues  # noqa: E402

HARNESS_BOUND_S = 120
ROOT = Path(construct.__file__).resolve().parent.parent


def run_construct(*args: str, code: str | None = None) -> subprocess.CompletedProcess:
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    argv = [sys.executable, "-c", code, *args] if code else [sys.executable, "-m", "construct", *args]
    return subprocess.run(argv, capture_output=True, text=True, timeout=HARNESS_BOUND_S, env=env, cwd=ROOT)


def doubling_bomb(levels: int = 24) -> str:
    """Level k holds two <use> of level k - 1: the last level draws 2**levels circles from a 1.8 KB file."""
    chain = "".join(f'<g id="a{k}"><use xlink:href="#a{k - 1}"/><use xlink:href="#a{k - 1}" x="1"/></g>'
                    for k in range(1, levels + 1))
    return svg(f'<defs><circle id="a0" r="1"/>{chain}</defs><use xlink:href="#a{levels}"/>')


def nested_groups(depth: int, r: float = 1) -> str:
    return svg("<g>" * depth + f'<circle id="deepest" r="{r}"/>' + "</g>" * depth)


def test_the_doubling_bomb_is_small_and_expands_past_the_limit():
    text = doubling_bomb()
    assert len(text) < 2000 and 2 ** 24 > MAX_ELEMENTS  # the premise: a small file, more than the bound
    with pytest.raises(SvgTooLargeError) as caught:
        parse_svg(text, name="bomb.svg")
    e = caught.value
    assert isinstance(e, ConstructError) and e.source == "bomb.svg" and e.limit == MAX_ELEMENTS
    assert "bomb.svg" in str(e) and f"{MAX_ELEMENTS:,}" in str(e)
    # Below the bound the same structure is drawn in full: 2**10 circles.
    assert len(parse_svg(doubling_bomb(10)).shapes) == 2 ** 10


def test_the_doubling_bomb_is_refused_by_diff_with_one_line_and_exit_2(tmp_path):
    bomb, plain = tmp_path / "bomb.svg", tmp_path / "plain.svg"
    bomb.write_text(doubling_bomb(), encoding="utf-8")
    plain.write_text(GOLDEN, encoding="utf-8")
    for a, b in ((bomb, plain), (plain, bomb)):
        done = run_construct("diff", str(a), str(b))
        assert done.returncode == 2, done.stderr
        assert done.stdout == "" and len(done.stderr.splitlines()) == 1, done.stderr
        assert "expands to more than" in done.stderr and str(bomb) in done.stderr


VERIFY_WITH_A_COPIED_REBUILD = """
import shutil, sys
import construct.regress.verify as verify
from construct.cli.main import main
golden, rebuilt = sys.argv[1], sys.argv[2]
verify.default_builder = lambda out: shutil.copytree(rebuilt, out)
sys.exit(main(["verify", "--gallery", golden]))
"""


def test_a_bomb_among_the_goldens_is_refused_by_verify_with_one_line_and_exit_2(tmp_path):
    golden, rebuilt = tmp_path / "gallery", tmp_path / "rebuilt"
    for tree, text in ((golden, doubling_bomb()), (rebuilt, GOLDEN)):
        (tree / "crank-6").mkdir(parents=True)
        (tree / "crank-6" / "final.svg").write_text(text, encoding="utf-8")
    done = run_construct(str(golden), str(rebuilt), code=VERIFY_WITH_A_COPIED_REBUILD)
    assert done.returncode == 2, done.stderr
    assert len(done.stderr.splitlines()) == 1 and "expands to more than" in done.stderr, done.stderr
    assert (golden / "crank-6" / "final.svg").read_text(encoding="utf-8") == doubling_bomb()  # left alone


@pytest.mark.parametrize("depth", [500, 100_000])
def test_deeply_nested_groups_are_read_without_recursion(tmp_path, depth):
    # Python's recursion limit is 1,000: a recursive walk fails at the first case already.
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    a.write_text(nested_groups(depth), encoding="utf-8")
    b.write_text(nested_groups(depth, r=2), encoding="utf-8")
    same = run_construct("diff", str(a), str(a))
    assert (same.returncode, same.stderr) == (0, ""), same.stderr
    assert "equal (1 element)" in same.stdout
    changed = run_construct("diff", str(a), str(b), "--json")
    assert changed.returncode == 1, changed.stderr
    (change,) = json.loads(changed.stdout)["changes"]
    assert (change["kind"], change["key"], change["magnitude"]) == ("resized", "deepest", 1.0)


def test_deep_definitions_and_text_are_read_without_recursion(tmp_path):
    depth = 100_000
    deep_defs = svg('<defs><marker id="m">' + "<g>" * depth + "</g>" * depth + "</marker></defs>")
    deep_text = svg('<text x="1">' + "<tspan>K" * depth + "</tspan>" * depth + "</text>")
    for name, text in (("defs.svg", deep_defs), ("text.svg", deep_text)):
        path = tmp_path / name
        path.write_text(text, encoding="utf-8")
        done = run_construct("diff", str(path), str(path))
        assert (done.returncode, done.stderr) == (0, ""), done.stderr


def test_the_element_count_is_bounded_as_the_file_is_read(monkeypatch):
    monkeypatch.setattr(svgvalues, "MAX_ELEMENTS", 100)
    circles = '<circle r="1"/>' * 100  # with the root, 101 elements
    with pytest.raises(SvgTooLargeError, match="holds more than 100 elements") as caught:
        parse_svg(svg(circles), name="many.svg")
    assert (caught.value.source, caught.value.limit) == ("many.svg", 100)
    # '<' in comments pass the quick bound of the bytes; the elements are then counted as read: 100 fit.
    fits = svg("<!--" + "<" * 500 + "-->" + '<circle r="1"/>' * 99)
    assert len(parse_svg(fits).shapes) == 99


def test_reference_cycles_and_entity_declarations_are_bad_input():
    with pytest.raises(SvgFormatError, match="cycle"):
        parse_svg(svg('<g id="loop"><circle r="1"/><use href="#loop"/></g>'))
    laughs = ('<?xml version="1.0"?><!DOCTYPE svg [<!ENTITY lol "lol"><!ENTITY lol2 "&lol;&lol;&lol;">]>'
              + svg("<text>&lol2;</text>"))
    for spelled in (laughs, laughs.encode("utf-8"), laughs.encode("utf-16")):  # UTF-16 hides b"<!DOCTYPE"
        with pytest.raises(SvgFormatError, match="entity"):
            parse_svg(spelled)
    # A document type without entities (as editors write it) is read.
    doctype = '<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" "http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd">'
    assert len(parse_svg(doctype + svg('<circle r="1"/>')).shapes) == 1


@pytest.mark.parametrize("a, b", [
    ('<circle r="1" fill="darkslategray"/>', '<circle r="1" fill="#2f4f4f"/>'),  # CSS named colour
    ('<circle r="1" fill="rebeccapurple"/>', '<circle r="1" fill="rgb(102 51 153)"/>'),  # CSS Color 4 syntax
    ('<circle r="1" fill="hsl(120deg 100% 25%)"/>', '<circle r="1" fill="#008000"/>'),
    ('<circle r="1" fill="hwb(0 0% 0%)"/>', '<circle r="1" fill="red"/>'),
])
def test_colours_in_every_css_spelling_are_equal(a, b):
    assert diff_svg(svg(a), svg(b)).equal, diff_svg(svg(a), svg(b)).report()


def test_the_diff_does_not_import_matplotlib(tmp_path):
    path = tmp_path / "a.svg"
    path.write_text(svg('<circle r="1" fill="darkslategray" stroke="papayawhip"/>'), encoding="utf-8")
    code = ("import sys; from construct.cli import main; code = main(['diff', sys.argv[1], sys.argv[1]]); "
            "print('matplotlib' in sys.modules); sys.exit(code)")
    done = run_construct(str(path), code=code)
    assert done.returncode == 0 and done.stdout.splitlines()[-1] == "False", done.stdout + done.stderr


def test_a_style_sheet_with_a_rule_for_every_element_is_refused_past_the_budget(monkeypatch):
    # Every rule needs class "a" and one more; every element has "a" and its own: rules x elements checks.
    n = 300
    sheet = "".join(f".a.b{k}{{stroke-width:{k + 2}}}" for k in range(n))
    lines = "".join(f'<line class="a b{k}" x2="{k}"/>' for k in range(n))
    drawing = svg(f"<style>{sheet}</style>{lines}")
    shapes = parse_svg(drawing).shapes  # within the default budget: each line gets its own rule
    assert [dict(s.style)["stroke-width"] for s in shapes[:3]] == [(2.0,), (3.0,), (4.0,)]
    monkeypatch.setattr(svgvalues, "CSS_MATCH_BUDGET", n * n // 2)
    with pytest.raises(SvgTooLargeError, match="rule checks"):
        parse_svg(drawing, name="sheet.svg")


def test_a_long_element_repeated_by_references_counts_by_its_length(monkeypatch):
    # 2,000 points (about 16 KB) drawn 8 times through doubling <use>: 8 polylines, 128,000 characters.
    points = " ".join(f"{k},{k % 7}" for k in range(2000))
    chain = "".join(f'<g id="p{k}"><use href="#p{k - 1}"/><use href="#p{k - 1}"/></g>' for k in range(1, 4))
    drawing = svg(f'<defs><polyline id="p0" points="{points}"/>{chain}</defs><use href="#p3"/>')
    assert len(parse_svg(drawing).shapes) == 8
    monkeypatch.setattr(svgvalues, "MAX_ELEMENTS", 200)  # 8 polylines, but 8 x 16 KB / 256 = 500 units
    with pytest.raises(SvgTooLargeError, match="expands to more than 200 elements"):
        parse_svg(drawing)


def test_names_along_references_are_bounded(monkeypatch):
    # Each level's key is the path of ids to it: 10 levels of 1,000-character ids, 1,024 circles.
    long = "x" * 1000
    chain = "".join(f'<g id="{long}{k}"><use href="#{long}{k - 1}"/><use href="#{long}{k - 1}"/></g>'
                    for k in range(1, 11))
    drawing = svg(f'<defs><circle id="{long}0" r="1"/>{chain}</defs><use href="#{long}10"/>')
    assert len(parse_svg(drawing).shapes) == 1024
    monkeypatch.setattr(svgvalues, "MAX_KEY_CHARS", 1_000_000)  # the circles' names alone: 1024 x 10,000
    with pytest.raises(SvgTooLargeError, match="names"):
        parse_svg(drawing)


def test_a_hundred_thousand_equal_ids_are_named_in_linear_time(tmp_path):
    # The duplicates are named id, id~2, id~3, ...; trying every suffix from 2 each time was quadratic.
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    a.write_text(svg('<circle id="P" r="1"/>' * 100_000), encoding="utf-8")
    b.write_text(svg('<circle id="P" r="1"/>' * 99_999 + '<circle id="P" r="2"/>'), encoding="utf-8")
    done = run_construct("diff", str(a), str(b), "--json")
    assert done.returncode == 1, done.stderr
    (change,) = json.loads(done.stdout)["changes"]
    assert (change["kind"], change["key"]) == ("resized", "P~100000")
