"""The animation (construct/render/animate.py): one SVG that plays the steps without a script.

Expectations come from the protocol (its steps and groups) and the stated pace, never from the
animation's own output.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET


from construct.constructions import get
from construct.render.animate import MAX_STAGES, animated_svg, stages
from construct.render.output import scene_for
from construct.render.scene import build_scene
from construct.render.styles import STYLES
from construct.render.svg import Drawing

SVG = "{http://www.w3.org/2000/svg}"


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


def test_a_long_construction_is_animated_by_its_groups():
    """Past MAX_STAGES steps a stage is a group at depth two: the stages end where the protocol's groups end,
    at most MAX_STAGES of them, the last at the last step; below it every step is a stage."""
    fig = get("crank").figure(parts=360)  # 7,295 steps
    steps = fig.protocol.steps
    assert len(steps) > MAX_STAGES
    ends = set(k + 1 for k in range(len(steps)) if k + 1 == len(steps) or steps[k + 1].group[:2] != steps[k].group[:2])
    got = stages(Drawing(build_scene(fig), STYLES["plain"]))
    assert 10 < len(got) <= MAX_STAGES and set(got) <= ends and got[-1] == len(steps) and got == sorted(got)
    short = get("crank").figure(parts=6)
    assert stages(Drawing(build_scene(short), STYLES["plain"])) == list(range(1, len(short.protocol.steps) + 1))
