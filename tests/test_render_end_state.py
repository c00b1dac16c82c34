"""render/end_state.py: the plate's furniture in the end state, as the live sweep draws it value by value."""

from __future__ import annotations

import numpy as np
import pytest

from construct.constructions import get
from construct.render.end_state import (NumbersFactory, end_furniture, end_lettering, end_lettering_at,
                                        fixed_elements, furniture_numbers, lettering_box)
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
    """A value's fixed furniture and lettering made once (fixed_elements, end_lettering), placed among and then drawn,
    is what end_lettering_at and end_furniture make each on their own: the same keys, numbers and texts (fails when the shared elements are
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
    lettering = end_lettering(scene, d.vp, st, d.end.size)
    assert lettering
    spots = end_lettering_at(scene, marks, st, d.vp, d.end, d.placing, f, None, fixed, lettering)
    assert spots == end_lettering_at(scene, marks, st, d.vp, d.end, d.placing, f)
    shared = furniture_numbers(end_furniture(scene, st, d.vp, d.end, d.placing, f, {}, spots, fixed, lettering))
    alone = furniture_numbers(end_furniture(scene, st, d.vp, d.end, d.placing, f, {}, spots))
    assert shared == alone and len(shared[0]) > 10


def _numbers_attribute_by_attribute(group):
    """furniture_numbers as it read an element: each numbered attribute asked in turn, in the live data's order (the
    rule furniture_numbers' attributes found once per set of them replaced)."""
    import re

    from construct.render.end_state import _NUMBERED, _Text

    number = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
    keys, nums, texts = [], [], {}
    for e in group.elements:
        ident = e.attribs.get("id")
        if ident is None:
            continue
        for a in _NUMBERED:
            v = e.attribs.get(a)
            if v is None:
                continue
            if isinstance(v, list) and len(v) == 1:
                v = v[0]
            if isinstance(v, float):
                keys.append((ident, a, "#"))
                nums.append(round(v, 2) + 0.0)
            elif isinstance(v, tuple) and v and v[0] == "poly":
                keys.append((ident, a, "M" + "L".join(["# #"] * len(v[1])) + ("Z" if v[2] else "")))
                nums.extend(round(c, 2) + 0.0 for p in v[1] for c in p)
            elif isinstance(v, tuple) and v and v[0] == "rotate":
                keys.append((ident, a, "rotate(# # #)"))
                nums.extend(round(c, 2) + 0.0 for c in v[1:])
            else:
                v = " ".join(map(str, v)) if isinstance(v, (list, tuple)) else str(v)
                keys.append((ident, a, number.sub("#", v)))
                nums.extend(float(x) for x in number.findall(v))
        if isinstance(e, _Text):
            texts[ident] = e.text + "".join(getattr(t, "text", "") for t in e.elements)
    return keys, nums, texts


@pytest.mark.parametrize("name", ["inertia-stroke-fractions", "effective-work", "tangential-pressure", "piston-force",
                                  "crank-angle"])
def test_the_furniture_numbers_read_by_sets_of_attributes_are_those_read_attribute_by_attribute(name):
    """furniture_numbers (each element's numbered attributes found once per set of its attribute names) reads the
    end state's furniture as asking every numbered attribute of every element in turn did: the same keys, numbers
    and texts, for the plates of five constructions (lines, dots, arrows, arcs, turned texts, indices) and for
    their elements with their attributes in reverse order (fails when they are read in an element's own order)."""
    c = get(name)
    fig = c.figure()
    st = STYLES["teaching"]
    scene = scene_for(c, fig, ending=st.camera)
    d = Drawing(scene, st)
    g = end_furniture(scene, st, d.vp, d.end, d.placing, NumbersFactory())
    want = _numbers_attribute_by_attribute(g)
    assert furniture_numbers(g) == want and len(want[0]) > 8
    kinds = set()
    for e in g.elements:
        e.attribs = dict(reversed(list(e.attribs.items())))
        kinds.add(e.elementname)
    assert furniture_numbers(g) == want
    assert kinds >= {"line", "text"}


def test_the_lettering_placed_among_marks_made_only_where_it_crowds_is_the_lettering_placed_among_all():
    """end_lettering_at given the end state's lettered marks and a function that makes all its marks (made only where
    the plate's lettering crowds and is placed anew: a live sweep's values) places the lettering as given all the
    marks, at other values of the rod ratio, with and without a neighbouring value's spots kept; and asks for the
    marks only where something is placed anew (fails when the crowd is asked of other marks than all the lettered
    ones, or the marks are made everywhere)."""
    from construct.live.sweep import live_givens
    from construct.render.placing import Placing

    c = get("inertia-stroke-fractions")  # (Tafel 2: its values crowd at the built spots at most rod ratios)
    fig = c.figure()
    st = STYLES["teaching"]
    d = Drawing(scene_for(c, fig, ending=st.camera), st)
    f = NumbersFactory()
    given = live_givens(c, fig)[0].name
    base = float(fig.replay.givens[given])
    keep, made, anew = None, 0, 0
    for v in (0.5 * base, 0.8 * base, base, 1.3 * base, 2.0 * base):  # (at the book's value none crowds)
        scene = scene_for(c, c.figure(**{given: v}), ending=st.camera)
        vp = Drawing(scene, st).vp
        marks = [m for m in scene.end_drawn() if Placing.end_obstacle(m)]
        lettered = [m for m in marks if Placing.end_lettered(m)]
        # (the points' letters the crowd is asked among: the lettered marks' are all the marks' letters)
        texts = [b for els in fixed_elements(scene, vp, d.end, f) for e in els
                 if (b := lettering_box(e, d.end.size, st)) is not None]
        letters = d.placing._end_crowd(vp, d.end.letter, marks, texts, end_lettering(scene, vp, st, d.end.size),
                                       d.placing.end_spots)[1]
        assert letters and d.placing._end_crowd(vp, d.end.letter, lettered, texts, end_lettering(
            scene, vp, st, d.end.size), d.placing.end_spots)[1] == letters

        def making():
            nonlocal made
            made += 1
            return marks

        for kept in (None, keep):
            before = made
            want = end_lettering_at(scene, marks, st, vp, d.end, d.placing, f, kept)
            assert end_lettering_at(scene, making, st, vp, d.end, d.placing, f, kept, lettered=lettered) == want
            anew += made > before
            if v == base and kept is None:  # (the book's value: nothing crowds, none placed anew, no marks made)
                assert made == before and want is d.placing.end_spots
        keep = want
    assert 0 < made and anew == made < 10
