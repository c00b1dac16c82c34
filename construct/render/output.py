"""Writing a replayed construction to a folder: the layered figure, its views, the protocol.

``DIR/final.svg`` is the canonical output: every step is a group
``<g class="step" data-step="k">`` (in the historical style the figure is
the book plate, layered the same way), so frame k is a view of it, not a
copy.  ``DIR/protocol.json``, ``DIR/animated.svg`` (plays without script),
``DIR/player.html`` (the step player, one file) and ``DIR/storyboard.svg``
(contact sheet, made of the figure's own elements) come with it; standalone frames ``DIR/steps/NNN.svg`` (frame
k shows steps 1..k) only when asked (``--frames all`` or ``groups``): all
frames together grow with the square of the step count.  Everything is staged
in a folder beside the target and swapped in whole only when all of it has
been written (:func:`construct.io.staging.replaced_folder`): an interrupted
run leaves the previous replay or the new one, never a mix.  The folder
then holds exactly this run's files and their manifest
(``.construct-manifest.json``).  A folder is written only when it is new,
empty or a previous replay whose every file is in its manifest, unchanged
(:func:`is_replay_folder`): nothing else is ever replaced.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..io.manifest import foreign_entries, replaced_with_manifest
from ..io.staging import write_text
from .notation import Described, Drawn, caption, given_rows, givens, with_provenance
from .scene import Scene, build_scene, thin
from .styles import Style
from .svg import Drawing, render_svg

__all__ = ["FRAME_MODES", "OUTPUTS", "MAX_FRAME_BYTES", "frames_estimate", "check_frames_size", "frame_steps",
           "write_replay", "write_outputs", "scene_for",
           "is_replay_folder", "figure_title", "plate_caption", "params_text"]

FRAME_MODES = ("auto", "all", "groups", "none")
#: Up to this many steps "auto" writes a frame per step.  Frame k holds k
#: marks, so all frames together grow with the square of the step count.
AUTO_ALL_LIMIT = 1500
#: Above it, "auto" writes frames at group ends, thinned so that all frames
#: together stay near this many bytes (a mark is about this many bytes).
AUTO_BYTES, BYTES_PER_MARK = 100_000_000, 120

def frame_steps(scene: Scene, mode: str) -> list[int]:
    """The step indices that get a frame.

    >>> from construct.constructions import get
    >>> sc = build_scene(get("crank").figure(parts=360))
    >>> ks = frame_steps(sc, "auto")
    >>> len(sc.steps), len(ks) < 300, ks[-1] == len(sc.steps)
    (7295, True, True)
    """
    n = len(scene.steps)
    if mode == "none":
        return []
    if mode == "all" or (mode == "auto" and n <= AUTO_ALL_LIMIT):
        return list(range(1, n + 1))
    ends = scene.group_ends()
    if mode == "auto":
        return thin(ends, max(10, int(AUTO_BYTES / (BYTES_PER_MARK * len(scene.marks) / 2 + 1))))
    return ends


#: The most bytes of standalone frames a replay writes without --force (500 MB), and what a frame costs
#: per mark it shows: measured on the crank, 174 bytes a mark at 18 parts (11.9 MB for 362 frames),
#: 193 at 60 parts (54.5 MB for 752 frames); 200 rounds that up.
MAX_FRAME_BYTES, FRAME_BYTES_PER_MARK = 500_000_000, 200


def frames_estimate(figure: Drawn, mode: str) -> tuple[int, int]:
    """(frames, bytes) that *mode* would write for *figure*, from its protocol alone (no drawing is laid
    out: at 3600 parts that takes a minute, the estimate a moment).  Frame k shows the marks of steps
    1..k, about one per object made.

    >>> from construct.constructions import get
    >>> frames_estimate(get("crank").figure(parts=18), "all")
    (365, 14245800)
    """
    steps = figure.protocol.steps
    n = len(steps)
    if mode == "none":
        return 0, 0
    upto, total = [], 0
    for s in steps:
        total += max(1, len(s.outputs))
        upto.append(total)
    if mode == "all" or (mode == "auto" and n <= AUTO_ALL_LIMIT):
        ks = range(n)
    else:
        ks = [i for i in range(n) if i + 1 == n or steps[i + 1].group[:2] != steps[i].group[:2]]
        if mode == "auto":
            most = max(10, int(AUTO_BYTES / (BYTES_PER_MARK * total / 2 + 1)))
            if len(ks) > most:
                ks = sorted({ks[round(i * (len(ks) - 1) / (most - 1))] for i in range(most)})
    return len(ks), FRAME_BYTES_PER_MARK * sum(upto[i] for i in ks)


def check_frames_size(figure: Drawn, mode: str, force: bool = False) -> None:
    """Refuse (InvalidParameter) frames that would pass :data:`MAX_FRAME_BYTES`, with the estimate, unless *force*."""
    frames, size = frames_estimate(figure, mode)
    if size > MAX_FRAME_BYTES and not force:
        from ..kernel.errors import InvalidParameter

        raise InvalidParameter(f"--frames {mode} would write {frames} frames of about {_size(size)} in all "
                               f"(frame k shows steps 1..k), more than {_size(MAX_FRAME_BYTES)}; take --frames "
                               f"{'auto or ' if mode != 'auto' else ''}none (final.svg holds every step as a layer), "
                               f"or add --force-frames")


def _size(n: float) -> str:
    for unit in ("bytes", "kB", "MB", "GB", "TB"):
        if n < 1000 or unit == "TB":
            return f"{n:.0f} {unit}" if unit == "bytes" else f"{n:.3g} {unit}"
        n /= 1000
    return f"{n:.3g} TB"


def scene_for(construction: Described | None, figure: Drawn, *, plate: bool = False, ending: bool = False) -> Scene:
    """The figure's scene; a plate carries the construction's furniture and line looks (:mod:`.plate`).

    With *ending* (a teaching sequence) the scene carries its end state: the plate's objects, looks and
    furniture on the construction's sheet (:meth:`construct.render.scene.Scene.in_end`); a plate laid out in
    panels gives its looks only (its furniture stands where the panels move the diagrams).
    """
    if plate or ending:
        from .plate import plate_of

        p = plate_of(construction, figure)
        if ending:
            return build_scene(figure, title=figure_title(construction, figure), ending=True,
                               end_furniture=() if p.panels else p.furniture, end_looks=dict(p.looks))
        return build_scene(figure, title=figure_title(construction, figure), plate=True,
                           furniture=p.furniture, looks=dict(p.looks), panels=p.panels)
    return build_scene(figure, title=figure_title(construction, figure))


def params_text(figure: Drawn, lang: str = "en", construction: Described | None = None) -> str:
    """The figure's givens and parameters in *lang*: as its construction's book writes them
    (:func:`construct.render.notation.phrases`), else each by its name.

    >>> from construct.constructions import get
    >>> c = get("crank")
    >>> params_text(c.figure(parts=18), construction=c), params_text(c.figure(parts=18))
    ("r/L = 1/5, semicircle in 18 parts (Dürer's trisection)", 'r = 1, rod ratio = 5, parts = 18, method = durer, requested method = auto')
    """
    return givens(figure, construction)[0 if lang == "de" else 1]


def figure_title(construction: Described | None, figure: Drawn) -> tuple[str, str]:
    """The figure's title lines in its book's notation (:func:`construct.render.notation.caption`)."""
    if construction is None:  # a protocol of the user's own: its name is its title
        name, p = figure.protocol.construction, params_text(figure)
        return (f"{name}; {p}" if p else name, f"{name}; {p}" if p else name)
    return caption(construction, figure, plate=False)


def plate_caption(construction: Described | None, figure: Drawn,
                  number: int | str | None = None) -> tuple[str, str]:
    """A book plate's caption: "Fig. 12. Kolbenüberdrucklinie mit den Massenkräften. G = 830 kg, … — nach …" and the English."""
    if construction is None:
        fig = f"Fig. {number}." if number is not None else "Fig."
        name, p = figure.protocol.construction, params_text(figure)
        return (f"{fig} {name}.", f"{name} ({p})" if p else name)
    return caption(construction, figure, number)


#: What a replay writes besides final.svg, steps/ and protocol.json.
OUTPUTS = ("animated", "player", "storyboard")


def write_outputs(stage: Path, construction: Described | None, figure: Drawn, st: Style, *, frames: str = "none",
                  fig_number: int | str | None = None, protocol: bool = True,
                  outputs: tuple[str, ...] = OUTPUTS, live: Any = None, drawing: Drawing | None = None) -> dict[str, Any]:
    """Write final.svg, steps/ (when asked), protocol.json and *outputs*: animated.svg, player.html, storyboard.svg.

    *live*: the data of a live player (:func:`construct.live.wire.live_data`), whose slider the
    player then carries (:func:`construct.render.live.with_live`).  *drawing*: the figure's drawing in *st*,
    if the caller has laid it out already (a live player's sweep carries its camera views).

    One :class:`Drawing` lays the construction out once; the layered final
    figure, the frames, the animation and the player all carry its elements.
    In a plate style final.svg is the plate (its own, smaller scene), layered
    by step the same way.
    """
    from .animate import animated_svg
    from .player import player_html
    from .storyboard import storyboard_svg

    # The plate style's final figure is the plate: the construction's drawing only serves frames and views
    # (a plate alone does not lay the construction out at all).
    if drawing is not None:
        scene = drawing.scene
    else:
        scene = scene_for(construction, figure, ending=st.camera) if (frames != "none" or outputs or not st.plate) \
            else None
    ks = frame_steps(scene, frames) if scene is not None else []
    if drawing is None:
        drawing = Drawing(scene, st) if (ks or outputs or not st.plate) else None
    if st.plate:
        final = render_svg(scene_for(construction, figure, plate=True), style=st,
                           caption=plate_caption(construction, figure, fig_number))
    else:
        final = drawing.layered()  # type: ignore[union-attr]
    write_text(stage / "final.svg", with_provenance(final, construction, figure))
    n = len(figure.protocol.steps)  # the scene's steps
    width = max(3, len(str(n)))
    steps_dir = stage / "steps"
    if ks:
        steps_dir.mkdir()
    for k in ks:
        write_text(steps_dir / f"{k:0{width}d}.svg", drawing.frame(k))  # type: ignore[union-attr]
    if protocol:
        write_text(stage / "protocol.json", figure.protocol.to_json(figure.replay))
    if "animated" in outputs:
        write_text(stage / "animated.svg", animated_svg(scene, st, drawing=drawing))
    if "player" in outputs:
        page = player_html(scene, st, givens=given_rows(figure, construction), drawing=drawing)
        if live is not None:
            from .live import with_live

            page = with_live(page, live)
        write_text(stage / "player.html", page)
    if "storyboard" in outputs:
        write_text(stage / "storyboard.svg", storyboard_svg(drawing))  # type: ignore[arg-type]
    return {"steps": n, "frames": len(ks)}


#: What a refusal says a replay folder would have been.
REPLAY_DESCRIBED = ("a replay written by 'construct replay' (recognised by its .construct-manifest.json; "
                    "one written before manifests is not: remove it once)")


def is_replay_folder(folder: str | Path) -> bool:
    """Whether *folder* holds a replay and nothing else: every file in it is listed, unchanged, in the
    manifest ``construct replay`` wrote (what ``construct replay`` may replace).

    >>> is_replay_folder(Path(__file__).parent)
    False
    """
    try:
        return foreign_entries(Path(folder), "replay") == []
    except OSError:
        return False


def write_replay(construction: Described | None, figure: Drawn, out_dir: str | Path, *, style: str = "plain",
                 frames: str = "none", styles: dict[str, Style] | None = None, force: bool = False,
                 live: Any = None) -> dict[str, Any]:
    """Write everything a replay produces; return a summary (counts, paths).

    Frames estimated above :data:`MAX_FRAME_BYTES` are refused before anything is drawn, unless *force*.
    *live*: the data of a live player (a slider for a given), as for :func:`write_outputs`.
    """
    from . import styles as style_module

    table = styles or style_module.STYLES
    if style not in table:
        from ..kernel.errors import InvalidParameter

        raise InvalidParameter(f"unknown style {style!r}; choose one of {', '.join(sorted(table))}")
    st = table[style]
    if frames not in FRAME_MODES:
        from ..kernel.errors import InvalidParameter

        raise InvalidParameter(f"unknown frames mode {frames!r}; choose one of {', '.join(FRAME_MODES)}")
    check_frames_size(figure, frames, force)
    with replaced_with_manifest(out_dir, "replay", described=REPLAY_DESCRIBED, what="replay folder") as stage:
        stage.mkdir()
        info = write_outputs(stage, construction, figure, st, frames=frames, live=live)
    return {**info, "out": str(out_dir)}
