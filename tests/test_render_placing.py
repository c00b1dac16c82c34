"""Where a drawing's letters stand (construct/render/placing.py).

Expectations come from the font file's metrics (:func:`construct.render.lettering.label_box`),
from the viewport's map of the points and from the SVG the drawing writes -- never from the
placer's own numbers.
"""

from __future__ import annotations

import itertools
import math
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
        if "lbg" in cls and "lbx" not in cls and "rodlen" not in cls:  # (the rod's length at a break: no point's)
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


def test_the_ring_round_the_current_point_never_covers_its_tag():
    """While a step is current the player rings its point (Style.ring_px across on the screen); the point's name
    tag stands beside the ring at that step's zoom level, not under it (crank step 328: the ring sat on Q9)."""
    from construct.render.camera import level, zoom_of
    from construct.render.output import scene_for
    from construct.render.scene import MarkKind
    from construct.render.styles import STYLES

    c = get("crank")
    st = STYLES["teaching"]
    d = Drawing(scene_for(c, c.figure(parts=18, rod_ratio=5.0), ending=True), st)
    sc, pl = d.scene, d.placing
    points = {m.name: m for m in sc.marks if m.kind is MarkKind.POINT}
    checked = 0
    for s in sc.steps[:-1]:
        if d.ring(s.index) is None:
            continue
        lvl = level(zoom_of(d.camera_view(s.index), d.full_view))
        for name in s.outputs:
            m = points.get(name)
            if m is None or m.id not in pl.tag_spots or f" h{lvl}" in pl.tag_hidden.get(m.id, ""):
                continue
            dx, dy, _dist = pl.tag_moves.get(m.id, {}).get(lvl, pl.tag_spots[m.id])
            # the tag's box about its point in letter units (the player's screen px), the ring's radius in screen px
            x0, y0, x1, y1 = label_box(dx, dy, sc.display_name(m.name), st.label_size, st.label_font, st.label_italic, 0.0)
            near = (max(x0, min(0.0, x1)), max(y0, min(0.0, y1)))
            assert (near[0] ** 2 + near[1] ** 2) ** 0.5 >= 0.95 * st.ring_px, (s.index, m.name, (dx, dy))
            checked += 1
    assert checked > 50


def test_a_curve_is_kept_clear_of_along_its_catmull_rom_pieces():
    """The smooth curve the letters keep off (placing._polyline) runs through its points and, between two of
    them, along the cubic piece the SVG draws: at a quarter, a half and three quarters of each piece the
    Bernstein form of its control points (Catmull-Rom: c1 = p1 + (p2 - p0)/6, c2 = p2 - (p3 - p1)/6, the ends'
    neighbours themselves), computed here in exact fractions."""
    from fractions import Fraction
    from types import SimpleNamespace

    from construct.render.placing import _polyline
    from construct.render.scene import MarkKind

    pts = [(0.0, 0.0), (1.0, 2.0), (3.0, 2.5), (4.0, -1.0), (6.5, 0.25)]
    got = _polyline(SimpleNamespace(geom=tuple(pts), kind=MarkKind.CURVE, straight=False), 1.0)
    assert len(got) == 1 + 4 * (len(pts) - 1)
    F = [tuple(map(Fraction, p)) for p in pts]
    for i in range(len(pts) - 1):
        p0, p1, p2, p3 = F[max(i - 1, 0)], F[i], F[i + 1], F[min(i + 2, len(F) - 1)]
        c1 = tuple(a + (b - c) / 6 for a, b, c in zip(p1, p2, p0))
        c2 = tuple(a - (b - c) / 6 for a, b, c in zip(p2, p3, p1))
        for j, t in enumerate((Fraction(1, 4), Fraction(1, 2), Fraction(3, 4), Fraction(1))):
            s = 1 - t
            want = [s ** 3 * a + 3 * s * s * t * b + 3 * s * t * t * c + t ** 3 * d
                    for a, b, c, d in zip(p1, c1, c2, p2)]
            assert got[1 + 4 * i + j] == pytest.approx([float(w) for w in want], abs=1e-12), (i, t)
    assert got[0] == pts[0] and got[4::4] == pts[1:]


def _crowded_one_by_one(boxes, others, taken, touching):
    """The plate lettering's crowd as it was asked box by box: a box meets one of *taken*, or another box of *boxes* or
    *others* (another id, not a pair in *touching*)."""
    def meet(a, b):
        return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]

    return {f for f, b in boxes.items() if any(meet(b, o) for o in taken) or any(
        g != f and frozenset((f, g)) not in touching and meet(b, o) for g, o in [*boxes.items(), *others.items()])}


def test_the_crowd_asked_at_once_is_the_crowd_asked_box_by_box():
    """placing.crowded (every box against every other at once, numpy) is the test box by box it replaces, over random
    boxes with pairs that touched where they were placed, an id among both kinds, boxes not drawn (NaN) and none
    taken: fails when a pair that touched, the taken boxes, the box itself or another kind is read otherwise."""
    import random

    from construct.render.placing import crowded

    rng = random.Random(28)
    ways = {"taken": 0, "letters": 0, "touching": 0, "free": 0}
    for _ in range(600):
        def box():
            if rng.random() < 0.05:
                return (math.nan,) * 4
            x, y = rng.uniform(0, 60), rng.uniform(0, 60)
            return (x, y, x + rng.uniform(0.5, 12), y + rng.uniform(0.5, 8))

        boxes = {f"fur{i}": box() for i in range(rng.randint(0, 9))}
        others = {f"s{i}": box() for i in range(rng.randint(0, 6))}
        if boxes and others and rng.random() < 0.2:  # (an id of both kinds)
            others[next(iter(boxes))] = box()
        taken = [box() for _ in range(rng.randint(0, 5))]
        ids = list(boxes) + list(others)
        touching = {frozenset(rng.sample(ids, 2)) for _ in range(rng.randint(0, 12))} if len(ids) > 1 else set()
        want = _crowded_one_by_one(boxes, others, taken, touching)
        assert crowded(boxes, others, taken, touching) == want
        ways["taken"] += bool(want - _crowded_one_by_one(boxes, others, [], touching))
        ways["letters"] += bool(want - _crowded_one_by_one(boxes, {}, taken, touching))
        ways["touching"] += bool(_crowded_one_by_one(boxes, others, taken, set()) - want)
        ways["free"] += bool(set(boxes) - want)
    assert min(ways.values()) > 20, ways


@pytest.mark.parametrize("name", ["tangential-pressure", "effective-work"])
def test_the_end_states_result_lines_mapped_at_once_are_those_mapped_point_by_point(name):
    """Placing._end_place's result lines (each line's points mapped by vp.px on arrays) are the pieces between its
    points mapped one by one, in order, the plate's strokes first: on the built figure's viewport and on a live
    sweep's value's map (SweepDrawing.px_of), at values across the rod ratio's domain, curves, circles and segments
    among them, long lines (mapped on arrays) and short ones (fails when a line's points are mapped otherwise or its
    pieces come in another order)."""
    from types import SimpleNamespace

    from construct.render.output import scene_for
    from construct.render.placing import _ARRAY_FROM, Placing, _polyline
    from construct.render.styles import STYLES
    from construct.render.sweepdraw import SweepDrawing

    c = get(name)
    fig = c.figure()
    st = STYLES["teaching"]
    scene = scene_for(c, fig, ending=st.camera)
    d = Drawing(scene, st)
    strokes = [(10.0, 20.0, 30.0, 40.0), (1.0, 2.0, 3.0, 4.5)]

    def one_by_one(vp, marks):
        lines = list(strokes)
        for m in marks:
            if m.role == "result" and m.kind.stroked and "hidden" not in scene.end_look(m).split():
                pts = [vp.px(*q) for q in _polyline(m, vp.scale)]
                lines.extend((a[0], a[1], b[0], b[1]) for a, b in zip(pts, pts[1:]))
        return lines

    def at_once(vp, marks):
        return list(map(tuple, d.placing._end_place(vp, d.end.letter, marks, [], [], strokes, lettered=False)[3]
                        .tolist()))

    marks = [m for m in scene.end_drawn() if Placing.end_obstacle(m)]
    want = one_by_one(d.vp, marks)
    assert at_once(d.vp, marks) == want and len(want) > 50
    ratios = [3.0, 4.0, 5.5, 8.0]
    sweep = fig.protocol.replay(c.given_sweep(dict(fig.replay.givens), "rod_ratio", ratios, fig.protocol.params))
    drawn = SweepDrawing(scene, fig.protocol, sweep, len(ratios), st)
    kinds, long = set(), set()
    for i in range(len(ratios)):
        vp = SimpleNamespace(px=drawn.px_of(i), scale=float(drawn.fit[i][2]))
        marks = drawn.end_marks_at(i, Placing.end_obstacle)
        kinds |= {m.kind for m in marks if m.role == "result"}
        long |= {len(_polyline(m, vp.scale)) >= _ARRAY_FROM for m in marks if m.role == "result" and m.kind.stroked}
        assert at_once(vp, marks) == one_by_one(vp, marks)
    assert len(kinds) > 1 and long == {True, False}  # (lines mapped on arrays and point by point)
