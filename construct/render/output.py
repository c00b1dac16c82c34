"""Writing a replayed construction to a folder: the layered figure, its views, the protocol.

``DIR/final.svg`` is the canonical output: every step is a group
``<g class="step" data-step="k">`` (in the historical style the figure is
the book plate, layered the same way), so frame k is a view of it, not a
copy.  ``DIR/protocol.json``, ``DIR/animated.svg`` (plays without script),
``DIR/player.html`` (the step player, one file) and ``DIR/storyboard.svg``
(contact sheet, made of the figure's own elements) come with it; standalone frames ``DIR/steps/NNN.svg`` (frame
k shows steps 1..k) only when asked (``--frames all`` or ``groups``): all
frames together grow with the square of the step count.  The print formats
(:data:`FORMATS`) write the plate at its final size instead or besides:
``DIR/final.pdf`` (:mod:`construct.render.pdf`), ``DIR/final.tikz`` and the
standalone ``DIR/final.tex`` (:mod:`construct.render.tikz`), laid out on a
:class:`~construct.render.page.Sheet`.  Everything is staged
in a folder beside the target and swapped in whole only when all of it has
been written (:func:`construct.io.staging.replaced_folder`): an interrupted
run leaves the previous replay or the new one, never a mix.  The folder
then holds exactly this run's files and their manifest
(``.construct-manifest.json``).  A folder is written only when it is new,
empty or a previous replay whose every file is in its manifest, unchanged
(:func:`is_replay_folder`): nothing else is ever replaced.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from ..io.manifest import foreign_entries, replaced_with_manifest
from ..io.staging import write_text
from .captions import PlateCaption
from .notation import Described, Drawn, caption, citation, given_rows, givens, phrases, with_provenance
from .plate import Plate, plate_of
from .scene import Scene, build_scene, thin
from .styles import Style
from .svg import Drawing, render_svg

__all__ = ["FRAME_MODES", "OUTPUTS", "FORMATS", "print_plate", "print_files", "check_formats", "MAX_FRAME_BYTES", "frames_estimate", "check_frames_size", "frame_steps",
           "write_replay", "write_outputs", "scene_for",
           "is_replay_folder", "figure_title", "plate_caption", "printed_caption", "params_text"]

FRAME_MODES = ("auto", "all", "groups", "none")
#: What a replay writes its plate as: the SVG figure and its screen pages, a PDF at its final size, TikZ.
FORMATS = ("svg", "pdf", "tikz")
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


def scene_for(construction: Described | None, figure: Drawn, *, plate: "bool | Plate" = False,
              ending: bool = False) -> Scene:
    """The figure's scene; a plate carries the construction's furniture and line looks (:mod:`.plate`; *plate*
    may be the construction's :class:`~construct.render.plate.Plate` already made).

    With *ending* (a teaching sequence) the scene carries its end state: the plate's objects, looks and
    furniture on the construction's sheet (:meth:`construct.render.scene.Scene.in_end`); a plate laid out in
    panels gives its looks only (its furniture stands where the panels move the diagrams).
    """
    if plate or ending:
        p = plate if isinstance(plate, Plate) else plate_of(construction, figure)
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


def printed_caption(construction: Described | None, figure: Drawn,
                    number: int | str | None = None) -> PlateCaption:
    """What a plate prints under its figure (:class:`construct.render.captions.PlateCaption`): in its book's
    language, "Fig. 12. Kolbenüberdrucklinie mit den Massenkräften. G = 830 kg, … — nach …", as many givens as
    three lines hold; the whole caption in both languages (:func:`plate_caption`) stands in its ``<desc>``.

    >>> from construct.constructions import get
    >>> c = get("crank-angle")
    >>> cap = printed_caption(c, c.figure(rod_ratio=4.0), 3)
    >>> cap.head, cap.givens, cap.cite
    ('Fig. 3. Kurbelwinkel aus den Zehnteln des Hubes', ('r/L = 1/4', 'Hub in 10 Teilen'), 'nach Anhang II, „Darstellung der Massendrücke“, Fig. 77, Tabelle 2')
    """
    head = f"Fig. {number}. " if number is not None else "Fig. "
    if construction is None:
        return PlateCaption(head + figure.protocol.construction, tuple(p for p in params_text(figure).split(", ") if p))
    note = construction.note(figure, "de") if construction.note is not None else ""
    cite = citation(construction, "de")
    # a title that names the book's figure ("… und Nabe (Fig. 28)") leaves it to the citation: one "Fig. 28"
    title = re.sub(r"\s*\((?:Fig|Abb)\.\s*([^)]*)\)$", lambda m: "" if m.group(1) in cite else m.group(0),
                   construction.title.de.rstrip("."))
    shown = phrases(figure, "de", construction)
    if shown and shown[0][:2].isalpha():  # a word ("unendlich lange Schubstangen") begins a sentence
        shown[0] = shown[0][:1].upper() + shown[0][1:]
    return PlateCaption(head + title + (f"; {note}" if note else ""), tuple(shown), cite)


#: What a replay writes besides final.svg, steps/ and protocol.json.
OUTPUTS = ("animated", "player", "storyboard")


def print_plate(figure: Drawn, *, construction: Described | None = None, style: str | Style = "historical",
                sheet: Any = None, fig_number: int | str | None = None) -> Any:
    """*figure* laid out on *sheet* (:class:`construct.render.page.Sheet`, default 120 mm) in *style*: the
    construction's plate, with its furniture and caption (:func:`construct.render.page.lay_out`).

    *construction*: the book construction that built the figure, if any.  A print in the teaching style is
    the plate too, in the teaching look: what its player ends on, not every helper of the construction.
    """
    from .page import Sheet, lay_out
    from .styles import STYLES

    if isinstance(style, str):
        if style not in STYLES:
            from ..kernel.errors import InvalidParameter

            raise InvalidParameter(f"unknown style {style!r}; choose one of {', '.join(sorted(STYLES))}")
        style = STYLES[style]
    title = plate_caption(construction, figure, fig_number) if style.plate else figure_title(construction, figure)
    return lay_out(scene_for(construction, figure, plate=construction is not None or style.plate), title, style=style,
                   sheet=Sheet() if sheet is None else sheet)


def print_files(construction: Described | None, figure: Drawn, st: Style, formats: tuple[str, ...],
                sheet: Any = None, fig_number: int | str | None = None) -> dict[str, bytes | str]:
    """The plate in the print formats of *formats* ("pdf", "tikz"), laid out once on *sheet*: {file name: content}.

    >>> from construct.constructions import get
    >>> from construct.render.styles import HISTORICAL
    >>> sorted(print_files(get("crank"), get("crank").figure(parts=3), HISTORICAL, ("pdf", "tikz")))
    ['final.pdf', 'final.tex', 'final.tikz']
    """
    wanted = [f for f in formats if f != "svg"]
    if not wanted:
        return {}
    plate = print_plate(figure, construction=construction, style=st, sheet=sheet, fig_number=fig_number)
    out: dict[str, bytes | str] = {}
    if "pdf" in wanted:
        from .pdf import pdf_bytes

        out["final.pdf"] = pdf_bytes(plate)
    if "tikz" in wanted:
        from .tikz import tikz_document, tikz_picture

        out["final.tikz"] = tikz_picture(plate)
        out["final.tex"] = tikz_document(plate)
    return out


def check_formats(formats: Any) -> tuple[str, ...]:
    """*formats* as a tuple of :data:`FORMATS` (a word, or several), or InvalidParameter naming the odd one."""
    from ..kernel.errors import InvalidParameter, did_you_mean

    got = (formats,) if isinstance(formats, str) else tuple(formats) if isinstance(formats, (tuple, list)) else None
    if not got or any(f not in FORMATS for f in got):
        odd = next((f for f in got or (formats,) if f not in FORMATS), formats)
        raise InvalidParameter(f"unknown format {odd!r}{did_you_mean(odd, FORMATS)}; choose one or more of "
                               f"{', '.join(FORMATS)}")
    return tuple(dict.fromkeys(got))


def write_outputs(stage: Path, construction: Described | None, figure: Drawn, st: Style, *, frames: str = "none",
                  fig_number: int | str | None = None, protocol: bool = True,
                  outputs: tuple[str, ...] = OUTPUTS, live: Any = None, drawing: Drawing | None = None,
                  formats: tuple[str, ...] = ("svg",), sheet: Any = None,
                  switch: tuple | None = None) -> dict[str, Any]:
    """Write final.svg, steps/ (when asked), protocol.json and *outputs*: animated.svg, player.html, storyboard.svg;
    and the plate in the print formats of *formats* (final.pdf; final.tikz and final.tex) laid out on *sheet*.
    Without "svg" in *formats* only the print files and protocol.json are written.

    *live*: the data of a live player (:func:`construct.live.wire.live_data`), whose slider the
    player then carries (:func:`construct.render.live.with_live`); *switch*: (symbol, options, why) of a given
    that changes the steps, offered as a switch between the player pages of the book's values
    (:func:`construct.render.live.with_switch`).  *drawing*: the figure's drawing in *st*,
    if the caller has laid it out already (a live player's sweep carries its camera views).

    One :class:`Drawing` lays the construction out once; the layered final
    figure, the frames, the animation and the player all carry its elements.
    In a plate style final.svg is the plate (its own, smaller scene), layered
    by step the same way.
    """
    from .animate import animated_svg
    from .player import player_html
    from .storyboard import storyboard_svg

    for name, data in print_files(construction, figure, st, formats, sheet, fig_number).items():
        (write_text(stage / name, data) if isinstance(data, str) else (stage / name).write_bytes(data))
    if "svg" not in formats:
        if protocol:
            write_text(stage / "protocol.json", figure.protocol.to_json(figure.replay))
        return {"steps": len(figure.protocol.steps), "frames": 0}
    # The plate style's final figure is the plate: the construction's drawing only serves frames and views
    # (a plate alone does not lay the construction out at all).
    if drawing is not None:
        scene = drawing.scene
    else:
        scene = scene_for(construction, figure, ending=st.camera) if (frames != "none" or outputs or not st.plate) \
            else None
    ks = frame_steps(scene, frames) if scene is not None else []
    # the frames, the animation, the player and the storyboard are for the screen: on its paper (the cream tint
    # of the historical style); final.svg is the figure as printed
    if drawing is None:
        drawing = Drawing(scene, st.for_screen()) if (ks or outputs or not st.plate) else None
    if st.plate:
        drawn = plate_of(construction, figure)
        final = render_svg(scene_for(construction, figure, plate=drawn), style=st,
                           caption=printed_caption(construction, figure, fig_number))
        # the plate prints one language and the givens that fit: both captions whole go with it, and its legend
        final = with_provenance(final, construction, figure, plate_caption(construction, figure, fig_number),
                                drawn.legend)
    else:
        final = with_provenance((drawing if drawing.style == st else Drawing(scene, st)).layered(),  # type: ignore[union-attr]
                                construction, figure)
    write_text(stage / "final.svg", final)
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
        if switch is not None:
            from .live import with_switch

            page = with_switch(page, *switch)
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
                 live: Any = None, formats: Any = ("svg",), sheet: Any = None,
                 paper: str | None = None) -> dict[str, Any]:
    """Write everything a replay produces; return a summary (counts, paths).

    Frames estimated above :data:`MAX_FRAME_BYTES` are refused before anything is drawn, unless *force*.
    *live*: the data of a live player (a slider for a given), as for :func:`write_outputs`.  *formats*: what
    the plate is written as (:data:`FORMATS`; the print formats laid out on *sheet*).  *paper*: the paper's
    colour by name or hex (:func:`construct.render.styles.paper_colour`), on the screen too.
    """
    formats = check_formats(formats)
    from . import styles as style_module

    table = styles or style_module.STYLES
    if style not in table:
        from ..kernel.errors import InvalidParameter

        raise InvalidParameter(f"unknown style {style!r}; choose one of {', '.join(sorted(table))}")
    st = table[style]
    if paper is not None:
        from dataclasses import replace

        from .styles import paper_colour

        colour = paper_colour(paper)
        st = replace(st, paper=colour, screen_paper=colour)
    if frames not in FRAME_MODES:
        from ..kernel.errors import InvalidParameter

        raise InvalidParameter(f"unknown frames mode {frames!r}; choose one of {', '.join(FRAME_MODES)}")
    if "svg" in formats:  # the frames are SVG
        check_frames_size(figure, frames, force)
    with replaced_with_manifest(out_dir, "replay", described=REPLAY_DESCRIBED, what="replay folder") as stage:
        stage.mkdir()
        info = write_outputs(stage, construction, figure, st, frames=frames, live=live, formats=formats, sheet=sheet,
                             outputs=OUTPUTS if "svg" in formats else ())
    return {**info, "out": str(out_dir), "formats": formats}
