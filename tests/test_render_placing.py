"""Where a drawing's letters stand (construct/render/placing.py).

Expectations come from the font file's metrics (:func:`construct.render.lettering.label_box`),
from the viewport's map of the points and from the SVG the drawing writes -- never from the
placer's own numbers.
"""

from __future__ import annotations

import itertools
import re
import xml.etree.ElementTree as ET

import pytest

from construct.constructions import get
from construct.render.lettering import label_box
from construct.render.placing import PlacedLabel, place_outwards
from construct.render.scene import Mark, build_scene
from construct.render.styles import PLAIN
from construct.render.svg import Drawing
from construct.render.viewport import Viewport

SVG = "{http://www.w3.org/2000/svg}"


def _overlap(a, b) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


@pytest.fixture(scope="module")
def crank_drawing():
    return Drawing(build_scene(get("crank").figure()), PLAIN)  # 40 letters, 5 of them on leaders


def test_every_lettered_point_has_its_placed_label(crank_drawing):
    d = crank_drawing
    labels = d.labels()
    lettered = [m for m in d.scene.marks if m.kind == "point" and m.label]
    assert [p.name for p in labels] == [m.name for m in lettered][: len(labels)]
    assert {p.name for p in labels} == {m.name for m in lettered}  # the whole figure has room for every one here
    for p, m in zip(labels, lettered):
        assert isinstance(p, PlacedLabel) and p.text == m.label and p.anchor == "middle"
        assert p.point == d.vp.px(*m.geom) and p.at == tuple(m.geom)


def test_the_placed_labels_are_the_letters_the_svg_draws(crank_drawing):
    """The data and the drawing agree: each shown letter's <g transform="translate(point)"><text x y>, and its
    leader line where the data says it has one."""
    d = crank_drawing
    rows = []
    for g in ET.fromstring(d.final()).iter(f"{SVG}g"):
        cls = g.get("class", "").split()
        if "lbg" in cls and "lbx" not in cls:
            tx, ty = map(float, re.fullmatch(r"translate\(([-\d.]+) ([-\d.]+)\)", g.get("transform")).groups())
            text = next(t for t in g.iter(f"{SVG}text") if t.get("class") == "lb")
            leader = any(line.get("class") == "leader" for line in g.iter(f"{SVG}line"))
            rows.append((tx, ty, float(text.get("x")), float(text.get("y")), text.text, leader))
    shown = [p for p in d.labels() if p.shown]
    assert len(rows) == len(shown) > 10
    for (tx, ty, x, y, text, leader), p in zip(rows, shown):
        assert text == p.text and leader == p.leader
        assert (tx, ty) == pytest.approx(p.point, abs=0.006) and (x, y) == pytest.approx(p.offset, abs=0.006)


def test_shown_labels_never_overlap_in_the_fonts_metrics(crank_drawing):
    d, st = crank_drawing, crank_drawing.style
    boxes = [label_box(p.point[0] + p.offset[0], p.point[1] + p.offset[1], p.text, st.label_size, st.label_font,
                       st.label_italic) for p in d.labels() if p.shown]
    assert len(boxes) > 10
    assert not [(a, b) for a, b in itertools.combinations(boxes, 2) if _overlap(a, b)]


def test_the_inset_places_letters_by_the_fonts_metrics_too():
    """Two wide letters side by side: a box counting characters (0.62 em each) finds room for both below
    their points, where the font's W (0.99 em) makes them overlap; the one label box sends the second above."""
    size = PLAIN.label_size
    vp = Viewport(0.0, 10.0, 10.0, 400.0, 400.0, 0.0)
    gap = 1.5 * size / vp.scale  # drawing units between the points: 1.5 letter heights on the canvas
    marks = [Mark(f"p{i}", 1, f"P{i}", "point", (3.0 + i * gap, 0.0), "result", "compass", "exact", label="WW")
             for i in range(2)]
    placed: list = []
    spots = [place_outwards(m, vp, PLAIN, 10.0, placed) for m in marks]
    assert all(s is not None for s in spots)
    boxes = [label_box(x, y, "WW", size, PLAIN.label_font, PLAIN.label_italic) for x, y in spots]
    assert not _overlap(*boxes)
    below = [y > vp.px(*m.geom)[1] for (_, y), m in zip(spots, marks)]
    assert below == [True, False]
