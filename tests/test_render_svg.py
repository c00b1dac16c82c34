"""The drawing (construct/render/svg.py): every mark's element, the layered figure and its frames.

Expectations come from the protocol (which step made which object), from the viewport's map worked out
by hand, and from geometry -- never from the renderer's own output.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import pytest

from construct.kernel.geometry import Circle, Line, Point
from construct.render.output import scene_for
from construct.render.scene import Mark, MarkKind, build_scene
from construct.render.styles import PLAIN, STYLES
from construct.render.svg import Drawing, mark_geometry, mark_layer, point_radius
from construct.render.viewport import Viewport

SVG = "{http://www.w3.org/2000/svg}"


def _ids(svg: str) -> set[str]:
    root = ET.fromstring(svg.encode("utf-8"))
    return {e.get("id") for e in root.iter() if re.fullmatch(r"s\d{4}-.+", e.get("id") or "")
            and not e.get("id").endswith(("-label", "-lb", "-hatch", "-tag", "-at"))}  # -at: where a line's letter stands


def _drawable_ids(fig, k: int) -> set[str]:
    out = set()
    for s in fig.protocol.steps[:k]:
        for name in s.outputs:
            obj = fig.replay.get(name)
            if isinstance(obj, (Point, Line, Circle)) or hasattr(obj, "curve_points"):  # a polyline: the crank
                out.add(f"s{s.index:04d}-{''.join(c if c.isalnum() or c in '-_' else '-' for c in name)}")
    return out


@pytest.mark.parametrize("style", sorted(STYLES))
def test_frame_k_shows_exactly_steps_1_to_k(crank6, style):
    c, fig = crank6
    d = Drawing(scene_for(c, fig), STYLES[style])
    for k in (0, 1, 7, 40, len(fig.protocol.steps)):
        svg = d.frame(k)
        # In a zoomed teaching frame the marks are all still there (clipped, not dropped).
        assert _ids(svg) == _drawable_ids(fig, k), k


def test_teaching_marks_current_and_earlier_steps(crank6):
    """A frame is a view of the layered figure: each element sits in its step's group, marked cur / old / done / inp."""
    c, fig = crank6
    svg = Drawing(scene_for(c, fig), STYLES["teaching"]).frame(12)
    root = ET.fromstring(svg.encode("utf-8"))
    seen = set()
    drawn = [g for layer in root.iter(f"{SVG}g") if layer.get("id") in Drawing.LAYERS for g in layer]
    for g in drawn:  # the camera's boxes (layer "views") are data, not marks of a step
        if g.get("data-step") is None:
            continue
        classes = g.get("class").split()
        step = int(g.get("data-step"))
        # an earlier step is old, or faded (its group is finished: "done"), or an input of step 12 ("inp")
        earlier = [c for c in ("old", "done", "inp") if c in classes]
        assert "step" in classes and ("cur" in classes) == (step == 12) and len(earlier) == (step < 12), step
        for e in g.iter():  # letters sit in a group about their point (-lb)
            m = re.fullmatch(r"s(\d{4})-.+", e.get("id") or "")
            if m:  # the id names the step whose group holds it
                assert int(m.group(1)) == step, e.get("id")
                seen.add(e.get("id").removesuffix("-label").removesuffix("-tag").removesuffix("-lb"))
    assert seen == _drawable_ids(fig, 12)


def test_a_polyline_is_drawn_with_straight_segments_through_its_corners():
    """A hexagon drawn by ``Builder.polyline`` is six straight sides, as it is measured (y_at, length),
    not a rounded blob: its path has only moves, lines and a close, and every side's midpoint
    (the mean of two corners, worked out here from the corners) lies on the drawn path."""
    from construct import Builder

    b = Builder("hexagon", givens={})
    corners = [(math.cos(k * math.pi / 3), math.sin(k * math.pi / 3)) for k in range(6)]
    names = [b.given_point(f"E{k}", x, y) for k, (x, y) in enumerate(corners)]
    b.polyline("hex", names, closed=True)
    fig = b.figure()
    scene = build_scene(fig)
    drawing = Drawing(scene)
    svg = drawing.layered()
    root = ET.fromstring(svg.encode("utf-8"))
    path = next(e for e in root.iter(f"{SVG}path") if (e.get("id") or "").endswith("-hex"))
    d = path.get("d")
    assert set(re.findall(r"[A-Za-z]", d)) <= {"M", "L", "Z"}, d
    # the drawn vertices, in pixels, and the pixel midpoints of the true sides
    drawn = [tuple(map(float, xy)) for xy in re.findall(r"(-?[\d.]+) (-?[\d.]+)", d)]
    assert len(drawn) == 6
    for k in range(6):
        (ax, ay), (bx, by) = corners[k], corners[(k + 1) % 6]
        mx, my = drawing.vp.px((ax + bx) / 2, (ay + by) / 2)
        # the midpoint lies on the segment between the two drawn corners (to the 0.01 px of the output)
        (px, py), (qx, qy) = drawn[k], drawn[(k + 1) % 6]
        cross = (qx - px) * (my - py) - (qy - py) * (mx - px)
        assert abs(cross) / math.hypot(qx - px, qy - py) < 0.02


def test_a_marks_geometry_is_its_drawing_coordinates_through_the_viewport():
    """x to the right from xmin, y down from ymax, both times the scale; numbers with at most two decimals."""
    vp = Viewport(-1.0, 2.0, 100.0, 400.0, 300.0, 0.0, 10.0, 20.0)  # xmin, ymax, scale, w, h, margin, left, top
    px = lambda x, y: (10.0 + (x + 1.0) * 100.0, 20.0 + (2.0 - y) * 100.0)  # noqa: E731  (by hand)
    seg = Mark("s", 1, "g", MarkKind.SEGMENT, (0.0, 0.0, 1.0, 1.0), "construction", "straightedge", "exact")
    (_, kind, a), = mark_geometry(seg, vp, PLAIN)
    assert kind == "line" and (float(a["x1"]), float(a["y1"]), float(a["x2"]), float(a["y2"])) == (*px(0, 0), *px(1, 1))
    circ = Mark("c", 2, "k", MarkKind.CIRCLE, (0.5, 0.25, 0.125), "construction", "compass", "exact")
    (_, kind, a), = mark_geometry(circ, vp, PLAIN)
    assert kind == "circle" and (float(a["cx"]), float(a["cy"]), float(a["r"])) == (*px(0.5, 0.25), 12.5)
    pt = Mark("p", 3, "P", MarkKind.POINT, (1.0 / 3.0, 0.0), "result", "compass", "exact", label="P")
    (_, kind, a), = mark_geometry(pt, vp, PLAIN)
    assert a["cx"] == "143.33" and float(a["r"]) == PLAIN.point_radius  # 10 + (4/3) 100, to the hundredth


def test_a_marks_layer_and_radius_follow_its_role():
    def mark(kind, role, name="P", label=None, geom=(0.0, 0.0)):
        return Mark("m", 1, name, kind, geom, role, "compass", "exact", label=label)

    assert mark_layer(mark(MarkKind.POINT, "result")) == "points"
    assert mark_layer(mark(MarkKind.SEGMENT, "result", geom=(0, 0, 1, 1))) == "results"
    assert mark_layer(mark(MarkKind.SEGMENT, "construction", geom=(0, 0, 1, 1))) == "construction"
    assert mark_layer(mark(MarkKind.AREA, "result", geom=((0, 0), (1, 0), (0, 1)))) == "areas"
    # an auxiliary point, or an unlettered helper with a dotted name, is drawn small
    assert point_radius(mark(MarkKind.POINT, "auxiliary"), PLAIN) == PLAIN.aux_point_radius
    assert point_radius(mark(MarkKind.POINT, "construction", name="T1.M"), PLAIN) == PLAIN.aux_point_radius
    assert point_radius(mark(MarkKind.POINT, "construction", name="T1.M", label="M"), PLAIN) == PLAIN.point_radius


def test_every_frame_has_the_canvas_of_the_whole_figure(crank6):
    """Frames are views of one layered figure: the same canvas, so that they line up in a player or a film."""
    c, fig = crank6
    d = Drawing(scene_for(c, fig), STYLES["plain"])
    sizes = {ET.fromstring(d.frame(k).encode()).get("viewBox") for k in (0, 1, 10, len(fig.protocol.steps))}
    assert sizes == {ET.fromstring(d.layered().encode()).get("viewBox")}


def test_primes_are_drawn_and_captioned_as_the_books_print_them(crank6):
    """The crank's piston positions are named 1', 2', ... by the construction (the protocol keeps that); the
    figure letters them 1′, 2′ (U+2032), and the player's captions and step list name them so."""
    from construct.render.player import player_html

    c, fig = crank6
    assert "1'" in dict(fig.protocol.steps[next(i for i, s in enumerate(fig.protocol.steps)
                                                  if "X1" in s.outputs)].labels).values()
    sc = scene_for(c, fig)
    d = Drawing(sc, STYLES["teaching"])
    root = ET.fromstring(d.layered().encode())
    texts = {"".join(t.itertext()) for t in root.iter("{http://www.w3.org/2000/svg}text")}
    assert {"1′", "5′"} <= texts
    assert not [t for t in texts if re.search(r"\w'", t)]
    page = player_html(sc, STYLES["teaching"], drawing=d)
    shown = re.sub(r"<script.*?</script>|<style.*?</style>", "", page, flags=re.S)
    data = re.search(r'id="data">(.*?)</script>', page, re.S).group(1)
    assert "1′" in data and not re.search(r"(?<![\w])\d+'", data + shown)


def test_a_figure_broken_across_its_rod_writes_the_rods_length_at_the_break():
    """A broken axis draws the long rod short: the figure says how long it is, beside the break on the first line
    crossing it (the axis), in the books' notation (L = 3,5 r, from the given, not from the drawing), once per
    break, clear of the result lines; a figure drawn whole (L/r = 3 at three parts) writes nothing, and the plate,
    which dimensions its rod itself (L = 3,5 r with the decimal comma), writes it no second time."""
    import re
    import xml.etree.ElementTree as ET

    from construct.constructions import get
    from construct.render.output import scene_for
    from construct.render.styles import STYLES
    from construct.render.svg import render_svg

    ns = "{http://www.w3.org/2000/svg}"
    c = get("crank")
    for v, written in ((3.5, "L = 3,5 r"), (50.0, "L = 50 r"), (3.0, None)):
        fig = c.figure(parts=3, rod_ratio=v)
        scene = scene_for(c, fig)
        assert bool(scene.breaks) == (written is not None), v
        root = ET.fromstring(render_svg(scene, style=STYLES["plain"]))
        groups = [g for g in root.iter(ns + "g") if "rodlen" in (g.get("class") or "").split()]
        if written is None:
            assert not groups
            continue
        assert len(groups) == 1, v
        texts = ["".join(t.itertext()) for t in groups[0].iter(ns + "text")]
        assert texts == [written, written]  # on its halo
        # at the break's middle on the axis (y = 0 of the figure: the axis is drawn at the crank centre's height)
        x, y = map(float, re.fullmatch(r"translate\(([-\d.]+) ([-\d.]+)\)", groups[0].get("transform")).groups())
        axis_y = float(root.find(f".//{ns}circle[@id='s0001-O']").get("cy"))
        assert y == pytest.approx(axis_y, abs=0.01)
        brk = next(p for p in root.iter(ns + "path") if p.get("class") == "brk")
        xs = [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?", brk.get("d"))][0::2]
        assert min(xs) < x < max(xs)
    plate = ET.fromstring(render_svg(scene_for(c, c.figure(parts=3, rod_ratio=3.5), plate=True),
                                     style=STYLES["historical"]))
    said = ["".join(t.itertext()) for t in plate.iter(ns + "text") if "halo" not in (t.get("class") or "")]
    assert said.count("L = 3,5 r") == 1
