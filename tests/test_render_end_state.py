"""render/end_state.py: the plate's furniture in the end state, as the live sweep draws it value by value."""

from __future__ import annotations

import numpy as np
import pytest

from construct.constructions import get
from construct.render.end_state import (NumbersFactory, end_furniture, end_lettering_at, fixed_elements,
                                        furniture_numbers, lettering_box)
from construct.render.output import scene_for
from construct.render.styles import STYLES
from construct.render.svg import Drawing


class _OnlyXml:
    """An element read only through its ElementTree element (as lettering_box reads svgwrite's)."""

    def __init__(self, elem):
        self._elem = elem

    def get_xml(self):
        return self._elem.get_xml()


def test_lettering_box_reads_a_plain_element_as_its_xml_reads():
    """lettering_box reads a plain Element's attributes as get_xml() would write them (each str()-ed, the empty and
    None ones left out) without making that element: the same box as through the element, for texts with numbers
    as floats and one-element lists, every anchor, sizes in the style and not, halos and other elements (fails
    when the plain reading drops an attribute: the anchor, the style)."""
    f, st = NumbersFactory(), STYLES["teaching"]
    rng = np.random.default_rng(27)
    seen = 0
    for _ in range(200):
        x, y = float(rng.uniform(-50, 900)), float(rng.uniform(-50, 700))
        kw = {"x": [x] if rng.random() < 0.5 else x, "y": [y] if rng.random() < 0.5 else y,
              "class_": str(rng.choice(["lb fur-text", "lb halo", "", "fur"])),
              "text_anchor": rng.choice(["start", "middle", "end", "", None]),
              "style": rng.choice([None, "", f"font-size:{rng.uniform(6, 20):.2f}px"])}
        elem = f.text(str(rng.choice(["0,53", "P_b", "1 at", "L = 5 r", ""])), **kw) if rng.random() < 0.9 else \
            f.line(start=(x, y), end=(x + 1, y), class_="fur")
        got, want = lettering_box(elem, 12.0, st), lettering_box(_OnlyXml(elem), 12.0, st)
        assert got == want
        seen += got is not None
    assert seen > 50


@pytest.mark.parametrize("name", ["inertia-stroke-fractions", "effective-work"])
def test_the_furniture_drawn_from_elements_made_once_is_the_furniture_made_twice(name):
    """A value's fixed furniture made once (fixed_elements), placed among and then drawn, is what end_lettering_at
    and end_furniture make each on their own: the same keys, numbers and texts (fails when the shared elements are
    drawn in another order or given ids before they are placed among)."""
    c = get(name)
    fig = c.figure()
    st = STYLES["teaching"]
    scene = scene_for(c, fig, ending=st.camera)
    d = Drawing(scene, st)
    f = NumbersFactory()
    marks = scene.end_drawn()
    fixed = fixed_elements(scene, d.vp, d.end, f)
    assert sum(map(len, fixed)) > 0
    spots = end_lettering_at(scene, marks, st, d.vp, d.end, d.placing, f, None, fixed)
    assert spots == end_lettering_at(scene, marks, st, d.vp, d.end, d.placing, f)
    shared = furniture_numbers(end_furniture(scene, st, d.vp, d.end, d.placing, f, {}, spots, fixed))
    alone = furniture_numbers(end_furniture(scene, st, d.vp, d.end, d.placing, f, {}, spots))
    assert shared == alone and len(shared[0]) > 10
