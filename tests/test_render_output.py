"""Written folders (construct/render/output.py): the layered figure, frames, animation, player, protocol.

Expectations come from the protocol (its steps and groups) and from XML and raster readers (ElementTree,
cairosvg) -- never from the writer's own output; a second process's bytes are tests/test_determinism.py's.
"""

from __future__ import annotations

import warnings
import xml.etree.ElementTree as ET

import cairosvg

from construct.render import svgdoc
from construct.render.output import frame_steps, is_replay_folder, write_replay
from construct.render.scene import build_scene
from construct.render.styles import STYLES


def _render_clean(svg: str, width: int | None = None) -> bytes:
    """Rasterise with cairosvg (at *width* pixels, or the drawing's own size); any warning is an error."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return cairosvg.svg2png(bytestring=svg.encode("utf-8"), output_width=width)


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


def test_a_user_figure_without_parameters_is_captioned_by_its_name_alone():
    """No empty brackets ("demo ()") under a figure whose protocol carries no parameters."""
    from construct import Builder
    from construct.render.output import figure_title, plate_caption

    b = Builder("demo", givens={})
    b.given_point("A", 0.0, 0.0)
    fig = b.figure()
    assert plate_caption(None, fig, 3) == ("Fig. 3. demo.", "demo")
    assert figure_title(None, fig) == ("demo", "demo")


# (The replay's bytes in another process, under another hash seed: tests/test_determinism.py runs this replay --
# ``crank --parts 6 --style teaching --frames all`` -- in two fresh interpreters, with the historical style and the
# check report beside it, and compares every file.)


def test_frames_are_every_step_or_the_ends_of_the_groups(crank6):
    c, fig = crank6
    sc = build_scene(fig)
    steps = fig.protocol.steps
    ends = [k + 1 for k in range(len(steps)) if k + 1 == len(steps) or steps[k + 1].group[:2] != steps[k].group[:2]]
    assert frame_steps(sc, "none") == []
    assert frame_steps(sc, "all") == frame_steps(sc, "auto") == list(range(1, len(steps) + 1))  # a short one
    assert frame_steps(sc, "groups") == ends


def test_a_replay_folder_is_one_whose_every_file_is_in_its_manifest(crank6, tmp_path):
    c, fig = crank6
    out = tmp_path / "out"
    write_replay(c, fig, out, frames="none")
    assert is_replay_folder(out)
    (out / "notes.txt").write_text("mine")
    assert not is_replay_folder(out) and not is_replay_folder(tmp_path / "missing")
