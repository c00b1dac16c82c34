"""Writing a replayed construction to a folder: frames, final figure, protocol.

``DIR/final.svg``, ``DIR/steps/NNN.svg`` (frame k shows steps 1..k) and
``DIR/protocol.json``; everything is staged and moved into place only when
all of it has been written (:func:`construct.output.staged_output`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

from ..constructions import Construction, Figure
from ..output import staged_output, write_text
from .scene import Scene, build_scene
from .svg import PLAIN, Style, render_svg

__all__ = ["FRAME_MODES", "frame_steps", "write_replay", "EXTRA_WRITERS", "scene_for"]

FRAME_MODES = ("auto", "all", "groups", "none")
#: Above this many steps "auto" writes a frame per group instead of per step:
#: frame k holds k marks, so all frames together grow with the square of the
#: step count (7000 steps would be gigabytes).
AUTO_ALL_LIMIT = 1500

#: Further outputs by other renderers: name -> fn(scene, figure, stage_dir, style_name).
EXTRA_WRITERS: dict[str, Callable[..., None]] = {}


def frame_steps(scene: Scene, mode: str) -> list[int]:
    """The step indices that get a frame."""
    n = len(scene.steps)
    if mode == "none":
        return []
    if mode == "all" or (mode == "auto" and n <= AUTO_ALL_LIMIT):
        return list(range(1, n + 1))
    ends = set()
    for i, s in enumerate(scene.steps):
        nxt = scene.steps[i + 1] if i + 1 < n else None
        if nxt is None or nxt.group[:2] != s.group[:2]:
            ends.add(s.index)
    return sorted(ends)


def scene_for(construction: Construction, figure: Figure) -> Scene:
    title = construction.title
    params = ", ".join(f"{k} = {v}" for k, v in sorted(figure.params.items()) if k not in ("givens", "group_titles"))
    givens = ", ".join(f"{k} = {v:g}" for k, v in sorted(figure.replay.givens.items()))
    return build_scene(figure, title=(f"{title.de} ({construction.source}); {givens}, {params}",
                                      f"{title.en}; {givens}, {params}"))


def write_replay(construction: Construction, figure: Figure, out_dir: str | Path, *, style: str = "plain",
                 frames: str = "auto", styles: dict[str, Style] | None = None) -> dict[str, Any]:
    """Write everything a replay produces; return a summary (counts, paths)."""
    from . import styles as style_module  # noqa: F401 - registers the styles it defines

    table = styles or style_module.STYLES
    if style not in table:
        from ..errors import InvalidParameter

        raise InvalidParameter(f"unknown style {style!r}; choose one of {', '.join(sorted(table))}")
    st = table[style]
    scene = scene_for(construction, figure)
    ks = frame_steps(scene, frames)
    width = max(3, len(str(len(scene.steps))))
    with staged_output(out_dir) as stage:
        write_text(stage / "final.svg", render_svg(scene, style=st))
        steps_dir = stage / "steps"
        steps_dir.mkdir()
        for k in ks:
            write_text(steps_dir / f"{k:0{width}d}.svg", render_svg(scene, upto=k, style=st))
        write_text(stage / "protocol.json", figure.protocol.to_json(figure.replay))
        for name, writer in sorted(EXTRA_WRITERS.items()):
            writer(scene, figure, stage, style)
    return {"steps": len(scene.steps), "frames": len(ks), "out": str(out_dir)}
