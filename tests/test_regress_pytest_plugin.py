"""The pytest plugin, used the way the README tells a user to use it, in a fresh project.

The test file of the fresh project *is* the README's example (read from
README.md, so the documentation cannot drift from what works).  Its first run
is a separate pytest process that finds the plugin through its ``pytest11``
entry point, as a user's would; the runs after it are pytest sessions of
their own in this process (``runpytest_inprocess``: the same entry point and
plugin code, without starting Python, pytest and its plugins five more times).
"""

from __future__ import annotations

import re
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

pytest_plugins = ["pytester"]

README = Path(__file__).resolve().parents[1] / "README.md"
NAME = "middle-of-stroke"  # the name the README example gives its figure


def readme_example() -> str:
    """The first Python block after the ``<!-- pytest-plugin -->`` marker of the README."""
    text = README.read_text(encoding="utf-8")
    tail = text[text.index("<!-- pytest-plugin -->"):]
    return re.search(r"```python\n(.*?)```", tail, re.S).group(1)


def _move_point(svg: str, elem_id: str, dy: float) -> str:
    m = re.search(r'<circle\b[^>]*\bid="' + re.escape(elem_id) + r'"[^>]*/>', svg)
    assert m, f"{elem_id} is not drawn in this frame"
    cy = re.search(r'cy="([^"]+)"', m.group())
    moved = m.group().replace(cy.group(), f'cy="{float(cy.group(1)) + dy:.3f}"')
    return svg[:m.start()] + moved + svg[m.end():]


def _respell(svg: str) -> str:
    """The same drawing, attributes in reverse order, numbers like 86.99 as 8.699000e+01."""
    for prefix, uri in (("", "http://www.w3.org/2000/svg"), ("xlink", "http://www.w3.org/1999/xlink"),
                        ("ev", "http://www.w3.org/2001/xml-events")):
        ET.register_namespace(prefix, uri)
    root = ET.fromstring(svg)
    for elem in root.iter():
        items = list(elem.attrib.items())
        elem.attrib.clear()
        for k, v in reversed(items):
            if k in ("cx", "cy", "x1", "y1", "x2", "y2", "x", "y", "r", "width", "height"):
                v = format(float(v), ".6e")
            elem.set(k, v)
    return ET.tostring(root, encoding="unicode")


@pytest.fixture()
def project(pytester: pytest.Pytester) -> pytest.Pytester:
    pytester.makepyfile(test_stroke=readme_example())
    return pytester


def test_readme_example_in_a_fresh_project(project: pytest.Pytester) -> None:
    # 1. No goldens yet: the test fails and says how to make them.
    first = project.runpytest_subprocess()  # the entry point, as a user's pytest finds it
    first.assert_outcomes(failed=1)
    first.stdout.fnmatch_lines([f"*no goldens for '{NAME}'*--construct-update*"])

    # 2. --construct-update writes the layered figure (every step a group) and the protocol, and says so.
    update = project.runpytest_inprocess("--construct-update")
    update.assert_outcomes(passed=1)
    goldens = project.path / "goldens" / NAME
    update.stdout.fnmatch_lines(["*construct goldens written*", f"{goldens}: final.svg, protocol.json"])
    assert sorted(p.name for p in goldens.iterdir()) == ["final.svg", "protocol.json"]
    layered = ET.fromstring((goldens / "final.svg").read_text(encoding="utf-8"))
    steps = {int(g.get("data-step")) for g in layered.iter("{http://www.w3.org/2000/svg}g") if g.get("data-step")}
    # O, D0, D1 given + midpoint of D0D1 (2 circles + their crossing + line + line D0D1 + M) = 9 steps
    assert steps == set(range(1, 10))
    project.runpytest_inprocess().assert_outcomes(passed=1)

    # 3. One point of the layered golden moved by 0.01: caught, with its step and element named.
    frame = goldens / "final.svg"
    original = frame.read_text(encoding="utf-8")
    frame.write_text(_move_point(original, "s0003-D1", 0.01), encoding="utf-8")
    failed = project.runpytest_inprocess()
    failed.assert_outcomes(failed=1)
    out = failed.stdout.str()
    assert f"construct golden '{NAME}': 1 of 2 files differ" in out
    line = next(x for x in out.splitlines() if "s0003-D1" in x)
    assert "moved" in line and "by 0.01" in line
    assert f"{NAME} step 3 ({NAME}/final.svg): 1 change" in out
    page = project.path / ".construct-failures" / f"{NAME}.html"
    assert f"side by side: {page}" in out
    html = page.read_text(encoding="utf-8")
    # expected | actual: each drawing inline, in its own sandboxed frame (srcdoc, escaped)
    assert html.count("srcdoc=") == 2 and html.count("&lt;svg") == 2 and "<svg" not in html
    assert "expected: " in html and "actual" in html
    assert "[id=&quot;s0003-D1&quot;]" in html  # the moved element is highlighted
    assert "<pre>" in html and "s0003-D1 (circle, matched by id)" in html  # the report, escaped text
    assert f"<title>construct golden {NAME}: 1 file differs</title>" in html  # as many as the message counts

    # 4. The same golden respelled (attributes reordered, numbers reformatted): equal again,
    #    and the failure page is cleaned up.
    respelled = _respell(original)
    assert respelled != original and "e+0" in respelled
    frame.write_text(respelled, encoding="utf-8")
    project.runpytest_inprocess().assert_outcomes(passed=1)
    assert not page.exists() and not page.parent.exists()  # no empty failures folder left behind

    # 5. The README's change: a shorter rod slides the stroke towards the shaft -- a geometric change, not a
    #    uniform scale (which fitting the drawing to its view would hide): named step by step, and in the
    #    protocol by the figure's own units.
    # As the README says it: "Change ROD to 3.5" -- one edit, and the test's own assertion follows it (a rod
    # written twice left the walkthrough stopping at 'assert 3.5 == 4.0' before the step diff it promises).
    source = project.path / "test_stroke.py"
    text = source.read_text(encoding="utf-8")
    assert text.count("ROD = 4.0") == 1 and "4.0" not in text.replace("ROD = 4.0", "")
    source.write_text(text.replace("ROD = 4.0", "ROD = 3.5"), encoding="utf-8")
    # the edit keeps the file's size, and the runs before may have cached its bytecode within the same second:
    # a cache that looks current would run the old test
    shutil.rmtree(project.path / "__pycache__", ignore_errors=True)
    moved = project.runpytest_inprocess()
    moved.assert_outcomes(failed=1)
    out = moved.stdout.str()
    # the drawing breaks the empty stretch between the shaft and the stroke out, as the books break a long rod:
    # drawn alike at both rods but for the rod's length written at the break, the protocol says what moved
    assert f"construct golden '{NAME}': 2 of 2 files differ" in out, out
    assert "final.svg): 2 changes" in out and "'L = 4 r' -> 'L = 3,5 r'" in out, out
    assert "moved      D0: point moved by 0.5: (3, 0) -> (2.5, 0)" in out
    assert "moved      M: point moved by 0.5: (4, 0) -> (3.5, 0)" in out
    assert not re.search(r"moved +O:", out)  # the shaft itself stays where it was
    assert "3.5 == 4.0" not in out


def test_update_drops_stale_frames_and_name_collisions(pytester: pytest.Pytester) -> None:
    pytester.makepyfile(test_two=readme_example().replace(
        'construct_golden.check(figure, name="middle-of-stroke")',
        'construct_golden.check(figure)\n    construct_golden.check(figure)'))
    result = pytester.runpytest_inprocess("--construct-update")  # the entry point: the test above
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*checked twice in this test*"])
    goldens = pytester.path / "goldens" / "test_two.test_middle_of_stroke"  # default: module and test
    assert (goldens / "final.svg").is_file()
    stale = goldens / "steps" / "999.svg"
    stale.parent.mkdir()
    stale.write_text((goldens / "final.svg").read_text(encoding="utf-8"))
    pytester.runpytest_inprocess("--construct-update")
    assert not stale.exists()
