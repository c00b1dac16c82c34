"""The renderers not mirrored by a module of their own: hatching paths, matplotlib plotting, notebook display.

(Frames and layers: test_render_svg.py; the scene and its plate: test_render_scene.py; the animation:
test_render_animate.py; written folders: test_render_output.py.)  Expectations come from the protocol and
from geometry (shapely), never from the renderer's output.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import numpy as np

from construct.render.notebook import figure_repr_svg
from construct.render.paths import hatch_path
from construct.render.viewport import Viewport


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


def test_notebook_svg_is_embeddable(crank6):
    _, fig = crank6
    svg = figure_repr_svg(fig)
    assert svg.startswith("<svg") and "<?xml" not in svg
    ET.fromstring(svg.encode("utf-8"))


