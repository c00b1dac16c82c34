"""The scene (construct/render/scene.py): marks from a replayed protocol, the plate, the groups' ends.

Expectations come from the protocol (roles, groups, which step made what), from the seeds' plates and
from geometry, never from the scene's own output.
"""

from __future__ import annotations

import math
import warnings
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from construct.constructions import get
from construct.render.output import scene_for
from construct.render.scene import MarkKind, build_scene, extreme_points, label_offset_direction, thin

SVG = "{http://www.w3.org/2000/svg}"


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
    assert not [m for m in sc.marks if m.kind == "circle"]
    crank = next(m for m in sc.marks if m.name == "crank")
    assert crank.kind == "arc" and crank.geom[4] == pytest.approx(math.pi, abs=1e-9)
    # the plate is no wider than the crank circle and a little margin (the crossheads are left out): all but
    # the rod of Fig. 1, drawn in one position to its crosshead
    r = fig.replay.givens["r"]
    xs = [p[0] for m in sc.marks if m.name not in ("rodline", "rodline.at") for p in extreme_points(m)]
    assert max(xs) - min(xs) < 2.6 * r


def test_rod_arc_on_the_plate_runs_from_the_point_to_the_stroke(crank6):
    """Seed 001: the arc with the rod length goes from the division point to the stroke line."""
    c, fig = crank6
    sc = build_scene(fig, plate=True)
    arc = next(m for m in sc.marks if m.name == "back2")
    cx, cy, rr, a0, sweep = arc.geom
    p, x = fig.replay["P2"], fig.replay["X2"]
    for q in (p, x):
        ang = (math.atan2(q[1] - cy, q[0] - cx) - a0) % (2 * math.pi)
        assert ang <= sweep  # both ends lie on the drawn part
    assert sweep < math.pi / 2  # and it is a short arc, not the circle


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


def test_no_gallery_plate_leaves_out_a_letter_silently(gallery_figure):
    """Every figure of the gallery, drawn as its plate: no HiddenLabelWarning (the constructions name
    their plates; the warning is for letters a user set)."""
    from construct.gallery import gallery_plan
    from construct.kernel.errors import HiddenLabelWarning

    with warnings.catch_warnings():
        warnings.simplefilter("error", HiddenLabelWarning)
        for name, params in gallery_plan():
            scene_for(*gallery_figure(name, params), plate=True)


def test_the_command_line_prints_the_warning_as_one_line(tmp_path, cli):
    """construct replay of a user's protocol in the historical style: written all the same (exit 0), the
    warning on stderr as one line, as the command line prints its errors."""
    path = tmp_path / "user.json"
    path.write_text(_lettered_helper_figure().protocol.to_json(), encoding="utf-8")
    run = cli("replay", "--protocol", path, "--style", "historical", "--out", tmp_path / "out")
    assert run.code == 0 and (tmp_path / "out" / "final.svg").is_file()
    lines = [line for line in run.err.splitlines() if "warning" in line]
    assert len(lines) == 1 and lines[0].startswith("construct: warning: the plate") and "M lettered 'M'" in lines[0]


def test_the_groups_end_where_the_protocol_leaves_a_group_at_depth_two(crank6):
    c, fig = crank6
    sc = build_scene(fig)
    paths = [s.group[:2] for s in fig.protocol.steps]
    by_hand = [k + 1 for k in range(len(paths)) if k + 1 == len(paths) or paths[k + 1] != paths[k]]
    assert sc.group_ends() == by_hand and by_hand[-1] == len(fig.protocol.steps) and len(by_hand) > 3


def test_thinning_keeps_the_ends_and_spreads_evenly():
    items = list(range(100, 1100, 10))  # 100 values
    got = thin(items, 7)
    assert len(got) == 7 and got[0] == items[0] and got[-1] == items[-1] and got == sorted(got)
    gaps = np.diff([items.index(v) for v in got])
    assert gaps.max() - gaps.min() <= 1  # evenly: 99 steps in 6 gaps of 16 or 17
    assert thin(items[:5], 7) == items[:5]


def test_a_letter_goes_radially_out_or_below_the_stroke_line():
    assert label_offset_direction((3.0, 4.0)) == pytest.approx((0.6, 0.8))
    assert label_offset_direction((2.0, 0.0)) == (0.0, -1.0)  # on the stroke line: below it
    assert label_offset_direction((5.0, 5.0), origin=(2.0, 1.0)) == pytest.approx((0.6, 0.8))


def test_an_arcs_extreme_points_bound_it():
    """Sampled densely, no point of the arc lies outside the box of its extreme points (and the box is tight)."""
    from construct.render.scene import Mark

    for a0, sweep in ((0.3, 2.5), (-1.0, 4.0), (2.0, 0.4), (5.5, 1.6)):
        m = Mark("a", 1, "k", MarkKind.ARC, (1.0, -2.0, 3.0, a0, sweep), "construction", "compass", "exact")
        pts = np.array(extreme_points(m))
        t = np.linspace(a0, a0 + sweep, 20001)
        xs, ys = 1.0 + 3.0 * np.cos(t), -2.0 + 3.0 * np.sin(t)
        assert xs.min() >= pts[:, 0].min() - 1e-12 and xs.max() <= pts[:, 0].max() + 1e-12
        assert ys.min() >= pts[:, 1].min() - 1e-12 and ys.max() <= pts[:, 1].max() + 1e-12
        assert xs.min() <= pts[:, 0].min() + 1e-6 and ys.max() >= pts[:, 1].max() - 1e-6


def test_a_section_drawn_over_an_area_keeps_its_hatching_out():
    """The flywheel's rim and hub are drawn over its disc: the disc's hatching (SVG and TikZ alike, through
    paths.hatch_segments) stops at them, as a draftsman hatches each section up to the next one's outline."""
    from shapely.geometry import LineString, Polygon

    from construct.render.paths import hatch_segments

    fig = get("flywheel-rim").figure()
    scene = scene_for(get("flywheel-rim"), fig, plate=True)
    areas = [m for m in scene.marks if m.kind is MarkKind.AREA]
    assert len(areas) >= 3  # disc, hub, rim
    disc = max(areas, key=lambda m: len(m.geom))  # the disc's outline follows its curve of equal strength
    over = scene.areas_over(disc)
    assert over and all(o is not disc.geom for o in over)
    ring = [(1000.0 * x, -1000.0 * y) for x, y in disc.geom]  # canvas units: the rim overlaps 70 x 20
    under = [[(1000.0 * x, -1000.0 * y) for x, y in o] for o in over]
    kept = Polygon(ring).buffer(0)
    for o in under:
        kept = kept.difference(Polygon(o).buffer(0))
    segs = hatch_segments(ring, 2.0, 45.0, under=under)
    assert segs and all(kept.buffer(1e-6).covers(LineString(s)) for s in segs)
    # without the sections the same hatching runs into them
    whole = hatch_segments(ring, 2.0, 45.0)
    assert any(Polygon(o).buffer(-1e-3).intersects(LineString(s)) for s in whole for o in under)


def test_whether_a_figure_breaks_is_what_breaking_it_gives(gallery_figure):
    """sheet.breaks_figure (asked before a long figure is broken, without moving a mark) says what sheet.broken's
    breaks say, for each construction's first gallery figure as a whole figure and as a plate, and for a vertex a
    long way below its figure: broken along x, across it, or not."""
    from construct.gallery import gallery_plan
    from construct.render.sheet import breaks_figure, broken

    from construct.render.marks import Mark

    # (no gallery figure breaks across)
    below = [Mark(f"p{i}", i, f"P{i}", MarkKind.POINT, xy, "construction", "compass", "exact")
             for i, xy in enumerate([(0.0, 0.0), (1.0, 0.5), (0.5, 1.0), (0.5, -20.0)])]
    first = dict(reversed(gallery_plan()))  # each construction once, at its first gallery parameters
    figures = [list(build_scene(gallery_figure(name, params)[1], break_axis=False).marks) for name, params in first.items()]
    seen = {True: 0, False: 0, "across": 0}
    for marks in figures + [below]:
        for whole in (True, False):
            cut = broken(marks, (), whole)[2]
            assert breaks_figure(marks, (), whole) == bool(cut), (marks[0].id, whole)
            seen[bool(cut)] += 1
            seen["across"] += any(b.axis == 1 for b in cut)
    assert seen[True] and seen[False] and seen["across"], seen  # every way a figure breaks, and does not, asked


@pytest.mark.parametrize("ratio", [5.0, 50.0])
def test_the_end_state_on_a_broken_sheet_draws_its_lines_to_the_figure_it_keeps(ratio):
    """The crank's end state on a sheet broken across its long rod: the plate's lines (the ordinates of the piston
    points, the axis) reach past the points marked on them by a share of what the sheet keeps -- not of the rod
    broken out, which at L/r = 50 drew every ordinate 1.8 r past the crank circle.  The crank circle (r = 1)
    spans [-1, 1] across the axis; a line drawn over it ends within 0.3 r of it, at every rod."""
    c = get("crank")
    scene = scene_for(c, c.figure(parts=18, rod_ratio=ratio), ending=True)
    assert scene.breaks
    lines = [m for m in scene.end_marks if m.kind is MarkKind.SEGMENT]
    assert lines
    for m in lines:
        x1, y1, x2, y2 = m.geom
        assert min(y1, y2) >= -1.3 and max(y1, y2) <= 1.3, (ratio, m.id, m.geom)
