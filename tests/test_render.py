"""The renderers: frames, plates, animation, storyboard, notebook display.

Expectations come from the protocol (which step made which object, which
role it has) and from geometry (shapely), never from the renderer's output.
"""

from __future__ import annotations

import math
import os
import re
import subprocess
import sys
import warnings
import xml.etree.ElementTree as ET

import cairosvg
import numpy as np
import pytest

from construct.constructions import get
from construct.kernel.geometry import Circle, Line, Point
from construct.render.animate import animated_svg
from construct.render.notebook import figure_repr_svg
from construct.render.output import scene_for, write_replay
from construct.render.scene import build_scene
from construct.render.styles import STYLES
from construct.render import svgdoc
from construct.render.paths import hatch_path
from construct.render.svg import Drawing
from construct.render.viewport import Viewport

SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def crank6():
    c = get("crank")
    return c, c.figure(parts=6, rod_ratio=5.0)


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


def _render_clean(svg: str, width: int | None = None) -> bytes:
    """Rasterise with cairosvg (at *width* pixels, or the drawing's own size); any warning is an error."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return cairosvg.svg2png(bytestring=svg.encode("utf-8"), output_width=width)


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


def test_every_svg_parses_strictly_and_renders(crank6, tmp_path):
    c, fig = crank6
    for style in sorted(STYLES):
        out = tmp_path / style
        write_replay(c, fig, out, style=style, frames="all")
        svgs = sorted(out.rglob("*.svg"))
        assert len(svgs) == len(fig.protocol.steps) + 3  # frames, final, animated, storyboard
        whole = [out / n for n in ("final.svg", "animated.svg", "storyboard.svg")]
        for i, p in enumerate(svgs):
            text = p.read_text(encoding="utf-8")
            ET.fromstring(text.encode("utf-8"))
            assert svgdoc.MARKER in text, p  # written by svgwrite's Drawing
            if p in whole or i % max(1, len(svgs) // 25) == 0:
                # every element of the frame is read and drawn whatever the size; a small raster spares the
                # PNG encoding of a large one (a third of the time) -- the three whole-figure files full size
                png = _render_clean(text, width=None if p in whole else 160)
                assert png.startswith(b"\x89PNG")


def test_historical_plate_shows_results_and_what_locates_them(crank6):
    c, fig = crank6
    sc = build_scene(fig, plate=True)
    names = {m.name for m in sc.marks if not m.id.endswith("-at")}  # -at: where a line's letter stands
    roles = {n: s.role for s in fig.protocol.steps for n in s.outputs}
    # every result the construction makes is on the plate
    assert {n for n, r in roles.items() if r == "result" and n in fig.replay} <= names
    # no auxiliary object, no crosshead far out on the stroke line, no helper of the division
    assert not any(roles[n] == "auxiliary" for n in names)
    assert not any(n.startswith("C") and n[1:].isdigit() for n in names)
    assert not any("." in n for n in names)
    # compass circles are short arcs; the crank circle is the semicircle over the stroke (seed 001: "Halbkreis")
    import math

    assert not [m for m in sc.marks if m.kind == "circle"]
    crank = next(m for m in sc.marks if m.name == "crank")
    assert crank.kind == "arc" and crank.geom[4] == pytest.approx(math.pi, abs=1e-9)
    # the plate is no wider than the crank circle and a little margin (the crossheads are left out): all but
    # the rod of Fig. 1, drawn in one position to its crosshead
    from construct.render.scene import extreme_points

    r = fig.replay.givens["r"]
    xs = [p[0] for m in sc.marks if m.name not in ("rodline", "rodline.at") for p in extreme_points(m)]
    assert max(xs) - min(xs) < 2.6 * r


def test_rod_arc_on_the_plate_runs_from_the_point_to_the_stroke(crank6):
    """Seed 001: the arc with the rod length goes from the division point to the stroke line."""
    import math

    c, fig = crank6
    sc = build_scene(fig, plate=True)
    arc = next(m for m in sc.marks if m.name == "back2")
    cx, cy, rr, a0, sweep = arc.geom
    p, x = fig.replay["P2"], fig.replay["X2"]
    for q in (p, x):
        ang = (math.atan2(q[1] - cy, q[0] - cx) - a0) % (2 * math.pi)
        assert ang <= sweep  # both ends lie on the drawn part
    assert sweep < math.pi / 2  # and it is a short arc, not the circle


def test_hatching_lies_inside_the_area():
    from shapely.geometry import Polygon

    vp = Viewport(0.0, 10.0, 10.0, 200.0, 200.0, 0.0)
    tri = ((1.0, 1.0), (9.0, 1.0), (5.0, 8.0))
    d = hatch_path(vp, tri, 4.0)
    segs = re.findall(r"M([\d.]+) ([\d.]+)L([\d.]+) ([\d.]+)", d)
    poly = Polygon([vp.px(x, y) for x, y in tri]).buffer(0.02)  # 0.02 px: two-decimal rounding
    assert len(segs) > 10
    for x1, y1, x2, y2 in segs:
        from shapely.geometry import LineString
        assert poly.contains(LineString([(float(x1), float(y1)), (float(x2), float(y2))]))


def test_animated_svg_hides_each_step_until_its_time(crank6):
    c, fig = crank6
    svg = animated_svg(scene_for(c, fig), STYLES["teaching"])
    root = ET.fromstring(svg.encode("utf-8"))
    times = {}
    for g in root.iter(f"{SVG}g"):
        if g.get("data-step"):
            sets = [s for s in g if s.tag == f"{SVG}set" and s.get("attributeName") == "visibility"]
            k = int(g.get("data-step"))
            dur = float(sets[0].get("dur").rstrip("s")) if sets else 0.0
            times.setdefault(k, set()).add(dur)
    ks = sorted(times)
    assert all(len(times[k]) == 1 for k in ks)  # every layer of a step appears at the same time
    durs = [times[k].pop() for k in ks]
    assert durs == sorted(durs) and durs[0] == 0.0 and len(set(durs)) == len(durs)
    # a step is shown at least 1.5 s (time to read its caption), the pace of the steps is even
    assert all(b - a >= 1.5 * (kb - ka) - 1e-9 for (ka, a), (kb, b) in zip(zip(ks, durs), zip(ks[1:], durs[1:])))
    assert "<script" not in svg


def test_plot_hands_matplotlib_the_figures_geometry(crank6):
    """As shapely's plot tests do: the data given to matplotlib, not pixels."""
    import matplotlib
    from matplotlib.collections import LineCollection

    _, fig = crank6
    backend = matplotlib.get_backend()
    ax = fig.plot()
    assert matplotlib.get_backend() == backend  # no backend chosen, no pyplot
    drawn = [seg for coll in ax.collections if isinstance(coll, LineCollection) for seg in coll.get_segments()]
    r = fig.replay.givens["r"]
    O = fig.replay["O"]
    # the crank circle is drawn: some polyline lies on the circle of radius r about O, to the chord's sagitta
    on_circle = [seg for seg in drawn
                 if len(seg) > 10 and np.allclose(np.hypot(seg[:, 0] - O.x, seg[:, 1] - O.y), r, atol=1e-9)]
    assert on_circle
    # every lettered point of the figure is plotted where the replay has it
    dots = np.vstack([c.get_offsets() for c in ax.collections if not isinstance(c, LineCollection)])
    for name in ("O", "D0", "D1"):
        p = fig.replay[name]
        assert np.min(np.hypot(dots[:, 0] - p.x, dots[:, 1] - p.y)) < 1e-12
    assert {t.get_text() for t in ax.texts} >= {"O"}
    # upto: the first steps only
    few = fig.plot(upto=3)
    assert sum(len(c.get_segments()) for c in few.collections if isinstance(c, LineCollection)) < len(drawn)


def test_plot_draws_a_polyline_segment_by_segment():
    from construct import Builder

    b = Builder("hexagon", givens={})
    pts = [b.given_point(f"P{i}", math.cos(i * math.pi / 3), math.sin(i * math.pi / 3)) for i in range(6)]
    b.polyline("hex", pts, closed=True)
    ax = b.figure().plot()
    segs = [s for c in ax.collections for s in getattr(c, "get_segments", lambda: [])()]
    hexagon = [s for s in segs if len(s) >= 6]
    # the corners themselves are vertices of what is drawn: P3 = (-1, 0) is not rounded off
    assert hexagon and np.min(np.hypot(hexagon[0][:, 0] + 1.0, hexagon[0][:, 1])) < 1e-12


def test_a_user_figure_without_parameters_is_captioned_by_its_name_alone():
    """No empty brackets ("demo ()") under a figure whose protocol carries no parameters."""
    from construct import Builder
    from construct.render.output import figure_title, plate_caption

    b = Builder("demo", givens={})
    b.given_point("A", 0.0, 0.0)
    fig = b.figure()
    assert plate_caption(None, fig, 3) == ("Fig. 3. demo.", "demo")
    assert figure_title(None, fig) == ("demo", "demo")


def test_notebook_svg_is_embeddable(crank6):
    _, fig = crank6
    svg = figure_repr_svg(fig)
    assert svg.startswith("<svg") and "<?xml" not in svg
    ET.fromstring(svg.encode("utf-8"))


def test_replay_output_is_the_same_in_another_process(tmp_path):
    """Byte-identical across processes and hash seeds (no timestamps, no set order)."""
    outs = []
    for seed in ("1", "2"):
        out = tmp_path / f"seed{seed}"
        env = {**os.environ, "PYTHONHASHSEED": seed}
        subprocess.run([sys.executable, "-m", "construct", "replay", "crank", "--parts", "6", "--style",
                        "teaching", "--frames", "all", "--out", str(out)], check=True, env=env, capture_output=True)
        outs.append(out)
    a = sorted(p.relative_to(outs[0]) for p in outs[0].rglob("*") if p.is_file())
    b = sorted(p.relative_to(outs[1]) for p in outs[1].rglob("*") if p.is_file())
    assert a == b and len(a) > 10
    for rel in a:
        assert (outs[0] / rel).read_bytes() == (outs[1] / rel).read_bytes(), rel


def test_a_polyline_is_drawn_with_straight_segments_through_its_corners():
    """A hexagon drawn by ``Builder.polyline`` is six straight sides, as it is measured (y_at, length),
    not a rounded blob: its path has only moves, lines and a close, and every side's midpoint
    (the mean of two corners, worked out here from the corners) lies on the drawn path."""
    import math

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


def _lettered_helper_figure(*, role: str = "construction"):
    """A user's figure: the segment AB as the result, its midpoint M lettered by the user (role *role*),
    and a second lettered point N on the perpendicular through M, neither of which locates the result."""
    from construct import Builder, left_of

    b = Builder("lettered helpers", givens={})
    b.given_point("A", 0.0, 0.0)
    b.given_point("B", 4.0, 0.0)
    b.midpoint("M", "A", "B")
    b.set_label("M", "M")
    b.circle_radius("k", "M", b.length_of("h", "A", "M"), role=role)
    b.intersect("N", "k", b.perpendicular_bisector("p", "A", "B"), rule=left_of("A", "B"), labels={"N": "N"},
                role=role)
    b.line("g", "A", "B", role="result")
    return b.figure()


def _letters(svg: str) -> set[str]:
    root = ET.fromstring(svg.encode("utf-8"))
    return {"".join(t.itertext()) for t in root.iter(f"{SVG}text") if "lb" in (t.get("class") or "").split()
            and "halo" not in (t.get("class") or "").split()}


def test_the_plate_warns_once_naming_every_lettered_point_it_leaves_out():
    """The historical plate shows the result AB and the given points; M and N (lettered by the user, default
    role) locate nothing of it.  One HiddenLabelWarning names both, with their letters; the plain and teaching
    styles, which draw every step, say nothing and letter both."""
    from construct.kernel.errors import ConstructWarning, HiddenLabelWarning

    fig = _lettered_helper_figure()
    with pytest.warns(HiddenLabelWarning) as caught:
        svg = fig.svg("historical")
    assert len(caught) == 1 and issubclass(caught[0].category, ConstructWarning)
    message = str(caught[0].message)
    assert "M lettered 'M'" in message and "N lettered 'N'" in message and "2 points" in message
    assert caught[0].filename == __file__  # it points at the line that asked for the drawing
    assert {"M", "N"}.isdisjoint(_letters(svg)) and {"A", "B"} <= _letters(svg)
    for style in ("plain", "teaching"):
        with warnings.catch_warnings():
            warnings.simplefilter("error", HiddenLabelWarning)
            assert {"M", "N", "A", "B"} <= _letters(fig.svg(style))
    # a frame of the historical style draws the steps, not the plate: nothing is left out
    with warnings.catch_warnings():
        warnings.simplefilter("error", HiddenLabelWarning)
        fig.svg("historical", upto=len(fig.protocol.steps))


def test_no_warning_when_the_plate_letters_the_point_or_the_protocol_names_its_plate():
    """A lettered point that is a result is on the plate (and lettered there); a protocol that lists what
    its plate shows (params["plate"], as every book construction does) leaves the rest out on purpose."""
    from construct import Builder
    from construct.kernel.errors import HiddenLabelWarning

    with warnings.catch_warnings():
        warnings.simplefilter("error", HiddenLabelWarning)
        b = Builder("lettered result", givens={})
        b.given_point("A", 0.0, 0.0)
        b.given_point("B", 4.0, 0.0)
        b.perpendicular_bisector("p", "A", "B")
        b.line("g", "A", "B", role="result")
        b.intersect("M", "p", "g", rule=("only",), labels={"M": "M"}, role="result")
        assert "M" in _letters(b.figure().svg("historical"))
        b = Builder("named plate", givens={}, params={"plate": ["A", "B", "g"]})
        b.given_point("A", 0.0, 0.0)
        b.given_point("B", 4.0, 0.0)
        b.midpoint("M", "A", "B")
        b.set_label("M", "M")
        b.line("g", "A", "B", role="result")
        assert "M" not in _letters(b.figure().svg("historical"))


def test_no_gallery_plate_leaves_out_a_letter_silently():
    """Every figure of the gallery, drawn as its plate: no HiddenLabelWarning (the constructions name
    their plates; the warning is for letters a user set)."""
    from construct.gallery import gallery_plan
    from construct.kernel.errors import HiddenLabelWarning

    with warnings.catch_warnings():
        warnings.simplefilter("error", HiddenLabelWarning)
        for name, params in gallery_plan():
            c = get(name)
            scene_for(c, c.figure(**params), plate=True)


def test_the_command_line_prints_the_warning_as_one_line(tmp_path, cli):
    """construct replay of a user's protocol in the historical style: written all the same (exit 0), the
    warning on stderr as one line, as the command line prints its errors."""
    path = tmp_path / "user.json"
    path.write_text(_lettered_helper_figure().protocol.to_json(), encoding="utf-8")
    run = cli("replay", "--protocol", path, "--style", "historical", "--out", tmp_path / "out")
    assert run.code == 0 and (tmp_path / "out" / "final.svg").is_file()
    lines = [line for line in run.err.splitlines() if "warning" in line]
    assert len(lines) == 1 and lines[0].startswith("construct: warning: the plate") and "M lettered 'M'" in lines[0]
