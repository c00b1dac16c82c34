"""svgwrite writes every SVG the project emits.

Checks that can fail: no module but the writer builds SVG markup from
strings (a string constant in the code that opens an SVG element is a
hand-made element), every SVG a replay writes carries the attributes
svgwrite's ``Drawing`` always writes and our old string templates never did,
the writer's serialiser writes what ElementTree's ``tostring`` writes, and the
elements the writer makes itself are the ones svgwrite makes.
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

from construct.constructions import get
from construct.render import svgdoc
from construct.render.output import write_replay

PACKAGE = Path(svgdoc.__file__).resolve().parents[1]
ELEMENT = re.compile(r"<(svg|g|circle|line|path|text|tspan|rect|set|animate\w*|clipPath|use|defs|polyline|polygon|"
                     r"ellipse|filter|fe\w+|style)(?![\w-])")
# Modules that read SVG (the semantic diff) or show it read from files (the golden failure page):
# their strings are patterns and messages, never output.
READERS = {"regress/svgdiff.py", "regress/svgdiff/parse.py", "regress/svgdiff/source.py", "regress/pytest_plugin.py", "regress/lint/sheet.py",
           "render/wire.py"}  # wire.py reads the drawn numbers back out of the SVG the player page drew
# HTML pages carry their own <style> sheets: that is HTML, not SVG.
HTML_STYLE = {"render/player.py", "gallery.py", "render/site.py"}


def _strings(tree: ast.AST) -> list[tuple[int, str]]:
    docstrings = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            body = getattr(node, "body", [])
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                docstrings.add(id(body[0].value))
    return [(n.lineno, n.value) for n in ast.walk(tree)
            if isinstance(n, ast.Constant) and isinstance(n.value, str) and id(n) not in docstrings]


def test_no_module_writes_svg_markup_by_hand():
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(PACKAGE).as_posix()
        if rel in READERS:
            continue
        for line, text in _strings(ast.parse(path.read_text(encoding="utf-8"))):
            for m in ELEMENT.finditer(text):
                if m.group(1) == "style" and rel in HTML_STYLE:
                    continue
                found.append(f"{rel}:{line}: {text[max(0, m.start() - 10):m.end() + 20]!r}")
    assert not found, "SVG markup outside svgwrite:\n" + "\n".join(found)


def test_every_svg_of_a_replay_is_written_by_svgwrite(tmp_path):
    c = get("crank")
    write_replay(c, c.figure(parts=3), tmp_path, style="teaching", frames="all")
    svgs = sorted(tmp_path.rglob("*.svg"))
    assert {"final.svg", "animated.svg", "storyboard.svg"} <= {p.name for p in svgs} and len(svgs) > 10
    for p in svgs:
        text = p.read_text(encoding="utf-8")
        assert text.startswith(svgdoc.XML_DECLARATION), p
        assert svgdoc.MARKER in text and 'baseProfile="full"' in text, p
    page = (tmp_path / "player.html").read_text(encoding="utf-8")
    assert page.count(svgdoc.MARKER) == 1  # the player's one inline SVG


def test_the_writer_writes_what_elementtree_writes(tmp_path, monkeypatch):
    """The serialiser (shared elements written once) gives ElementTree's tostring byte for byte: for every
    document of a replay in each style, and for text and attributes that need escaping, CDATA, and an
    element shared by two documents."""
    import xml.etree.ElementTree as ET

    from construct.render.styles import STYLES

    def elementtree(w, dwg):
        return ET.tostring(w.svg_element(dwg), encoding="unicode")

    w = svgdoc.Writer()
    f = w.factory
    shared = w.frozen(f.text('a < b & "c"\n\td', x=["1"], y=["2"], id="s0001-t", class_="lb"))
    docs = []
    for k in range(2):
        dwg = w.drawing(size=("10", "5"))
        g = f.g(id=f"g{k}", class_='x "quoted" & <odd>\r')
        g.add(shared)
        dwg.add(g)
        dwg.add(f.style("circle > .a { fill: red } & more"))
        words = f.text("P", x=["1"], y=["2"])  # a textual element's children: no line breaks inside
        words.add(f.tspan("b", dy=["1"]))
        inside = words.add(f.g(id="inside"))
        inside.add(f.tspan("c"))
        inner = f.g(id=f"o{k}")  # a frozen group holding a frozen element
        inner.add(shared)
        inner.add(words)
        dwg.add(w.frozen(inner))
        docs.append(dwg)
    for dwg in docs:
        assert w.markup(dwg) == elementtree(w, dwg)
    assert "<![CDATA[" in w.markup(docs[0]) and "&amp;" in w.markup(docs[1]) and "&#13;" in w.markup(docs[1])

    checked = []
    real = svgdoc.Writer.markup

    def both(self, dwg):
        mine = real(self, dwg)
        assert mine == elementtree(self, dwg)
        checked.append(len(mine))
        return mine

    monkeypatch.setattr(svgdoc.Writer, "markup", both)
    c = get("crank")
    fig = c.figure(parts=6)
    for style in sorted(STYLES):
        write_replay(c, fig, tmp_path / style, style=style, frames="all")
    assert len(checked) > 3 * 10


def test_the_factorys_plain_elements_are_svgwrites():
    """The writer makes groups, points' circles, lines, paths given as a string, letters set at x, y and animations'
    <set> itself (svgdoc.Element): each gives the ElementTree element svgwrite's own class gives for the same
    arguments, children and empty or None attributes included; a <set> naming its target, a path given as a list
    of commands and a text placed by insert or moved by dx, dy are svgwrite's."""
    import xml.etree.ElementTree as ET

    import svgwrite

    ref = svgwrite.Drawing(debug=False, profile="full")  # svgwrite's factory, untouched
    f = svgdoc.Writer().factory
    cases = [("g", dict(class_="step cur", id="g1", data_fade="7", **{"data-step": "3"}, fill=None, stroke="")),
             ("g", {}),
             ("circle", dict(center=("1.5", "-2"), r="0.25", class_="pt result", id="s0001-O")),
             ("circle", dict(center=(3, 4.5), r=2)),
             ("set", dict(attributeName="class", to="step old", begin="clock.begin+1.5s", fill="freeze")),
             ("set", dict(href="#s0002", attributeName="visibility", to="hidden")),
             ("line", dict(start=("0", "1.5"), end=("-2", "3"), class_="construction straightedge exact", id="s0003-g")),
             ("line", dict(start=(1, 2.5), end=(3, 4))),
             ("path", dict(d="M 1 2 A 3 3 0 0 1 4 5", class_="result compass exact", id="s0004-k", stroke=None)),
             ("path", dict(d="")),
             ("path", dict(d=["M", 1, 2, "L", (3, 4)])),  # commands, not a string: svgwrite's Path itself
             ("text", dict(text="12′", x=["1.5"], y=["-2"], class_="lb halo", id="s0005-P12-label")),
             ("text", dict(text="", x=[1, [2.5, None]], y=(3,), class_="lb", style="font-size:7px")),
             ("text", dict(text=7, class_=None)),
             ("text", dict(text="K", insert=("1", "2"))),  # placed by insert, moved by dx: svgwrite's Text itself
             ("text", dict(text="b", x=["1"], y=["2"], dy=["3"]))]
    for name, kw in cases:
        mine, theirs = getattr(f, name)(**kw), getattr(ref, name)(**kw)
        for parent in (mine, theirs):
            parent.add(ref.circle(center=("0", "0"), r="1"))
        assert ET.tostring(mine.get_xml()) == ET.tostring(theirs.get_xml()), (name, kw)
    assert all(type(e) is svgdoc.Element for e in (f.g(), f.circle(), f.line(), f.path(d="M 0 0"), f.text("a", x=["0"])))
