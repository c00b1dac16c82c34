"""The named styles a replay can be drawn in: style sheets, never part of a construction.

* ``plain``       grey construction, black results, approximate objects in a warm tone.
* ``historical``  a plate of the books: pure black ink on white paper (the
                  paper's cream tint only on the screen), thin construction
                  lines, heavy result lines, compass arcs only around the
                  crossings they make, small pricked points, italic serif
                  letters, hatched areas, a "Fig." caption; the final figure
                  shows the plate (results and what locates them).
* ``teaching``    colour by instrument, the current step highlighted with its
                  caption and group, earlier steps quieter, later ones absent;
                  each step is shown through a camera view of its group's
                  working region (:mod:`construct.render.camera`), a ring
                  round the current mark when it is small; a finished group
                  collapses to its results, and the current step's
                  instrument inputs (centre, through point, curves cut) are
                  marked and named.

Every style also states its line weights in points (:class:`LineWeights`,
DESIGN §8): a plate laid out for print (:meth:`Style.for_print`) draws its
lines with them, whatever its size on the page.

>>> sorted(STYLES)
['historical', 'plain', 'teaching']
>>> STYLES["historical"].plate, STYLES["teaching"].highlight is not None
(True, True)
>>> HISTORICAL.paper, HISTORICAL.ink, HISTORICAL.for_screen().paper
('#ffffff', '#000000', '#f3ead6')
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, fields, replace
from typing import Mapping

from .camera import level_css
from .lettering import HALO_PX
from .plate import LOOKS_CSS
from .svgdoc import fmt
from ..kernel.errors import InvalidParameter

__all__ = ["Style", "STYLES", "HISTORICAL", "TEACHING", "PLAIN", "LineWeights", "PAPERS", "MIN_LINE_PT", "paper_colour", "END_CSS"]

#: The finest line a printed plate may carry, in points: finer lines break up in print (publishers ask for 0.2 pt
#: or more; DESIGN §8).
MIN_LINE_PT = 0.2

#: The paper colours a style may be given by name (any CSS hex colour is taken too).
PAPERS = {"white": "#ffffff", "cream": "#f3ead6"}

_HEX = re.compile(r"#(?:[0-9a-fA-F]{3}|[0-9a-fA-F]{6})")


def paper_colour(value: str) -> str:
    """A paper colour by its name in :data:`PAPERS` or as a CSS hex colour; anything else is refused.

    >>> paper_colour("cream"), paper_colour("#FFF")
    ('#f3ead6', '#fff')
    >>> paper_colour("url(x)")
    Traceback (most recent call last):
    ...
    construct.kernel.errors.InvalidParameter: unknown paper colour 'url(x)'; choose cream, white or a hex colour such as #ffffff
    """
    if isinstance(value, str) and value in PAPERS:
        return PAPERS[value]
    if isinstance(value, str) and _HEX.fullmatch(value):
        return value.lower()
    raise InvalidParameter(f"unknown paper colour {value!r}; choose {', '.join(sorted(PAPERS))} or a hex colour "
                           f"such as #ffffff")


@dataclass(frozen=True)
class LineWeights:
    """The line weights of a printed plate, in points (DESIGN §8): every line a plate draws has one of them.

    >>> LineWeights().heavy, LineWeights().construction
    (0.8, 0.25)
    >>> LineWeights(thin=0.1)
    Traceback (most recent call last):
    ...
    construct.kernel.errors.InvalidParameter: line weight thin = 0.1 pt is under 0.2 pt, the finest line print holds
    """

    #: the plate's main curves and parts (the rod and crank drawn in one position, the result curve)
    heavy: float = 0.8
    #: the results of the construction (what its steps find)
    result: float = 0.6
    #: base lines and scales
    medium: float = 0.5
    #: helper lines the plate shows thin, centre lines, dimension lines, point rims
    thin: float = 0.3
    #: the construction's lines and arcs
    construction: float = 0.25
    #: hatching and the leaders that tie a letter to its point
    fine: float = 0.2

    def __post_init__(self) -> None:
        for f in fields(self):
            v = getattr(self, f.name)
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                raise InvalidParameter(f"line weight {f.name} must be a number of points, got {v!r}")
            if v < MIN_LINE_PT:
                raise InvalidParameter(f"line weight {f.name} = {v} pt is under {MIN_LINE_PT} pt, the finest line "
                                       f"print holds")


#: Which weight each stroked class of the style sheet is drawn with in print, in the sheet's order (a later
#: rule wins over an earlier one of the same weight: ``construction thin`` is thin).
PRINT_STROKES = (
    (".construction,.auxiliary", "construction"),
    (".result", "result"),
    (".hatch", "fine"),
    (".pt", "thin"),
    (".fur", "thin"),
    (".heavy", "heavy"),
    (".medium", "medium"),
    (".thin", "thin"),
    (".dashdot", "thin"),
    (".centre", "thin"),
    (".brkline", "thin"),
    (".leader,.cur .leader,.inp .leader", "fine"),
)


@dataclass(frozen=True)
class Style:
    """How marks look.  Colours are CSS colours, widths in px at the drawing scale (in print: :attr:`weights`)."""

    name: str = "plain"
    #: The colour of the paper: the sheet, the inside of an open point, the halo that opens lines for a letter.
    paper: str = "#ffffff"
    #: The paper's colour on the screen (player, animation, storyboard, frames), None: :attr:`paper`.
    screen_paper: str | None = None
    ink: str = "#000000"
    construction: str = "#8a8a8a"
    construction_width: float = 0.7
    result_width: float = 1.8
    auxiliary_dash: str | None = None
    point_radius: float = 2.0
    aux_point_radius: float = 1.1
    #: Points are drawn as a ring of this stroke width (0: a filled dot).
    point_ring: float = 0.0
    label_font: str = "Georgia, 'DejaVu Serif', serif"
    label_size: float = 13.0
    label_italic: bool = False
    caption_font: str = "'DejaVu Sans', Arial, sans-serif"
    caption_size: float = 13.0
    caption_italic: bool = False
    #: Colour of marks by the provenance of what they show (approximate in a warm tone).
    provenance_colours: Mapping[str, str] = field(default_factory=lambda: {"approximate": "#b35900", "trial": "#7a3fb0",
                                                                            "neusis": "#00708a"})
    #: Colour of marks by instrument (teaching style); empty: one construction colour.
    tool_colours: Mapping[str, str] = field(default_factory=dict)
    show_caption: bool = True
    #: Colour of the current step's marks in frames (None: no highlight).
    highlight: str | None = None
    highlight_width: float = 2.4
    #: Opacity of the steps before the current one in frames (1: no change).
    earlier_opacity: float = 1.0
    #: Opacity of the helpers of a finished group (:meth:`Scene.fade_end`; 1: they never fade).
    done_opacity: float = 1.0
    #: Colour of what the current step's instrument is set on (centre, through point, curves cut).
    input_colour: str | None = None
    #: The final figure shows a book plate (results and what locates them), not every step.
    plate: bool = False
    #: Caption of the final figure: "Fig." plate caption or the plain title lines.
    fig_caption: bool = False
    #: Hatch areas with fine lines (else a light fill).
    hatch: bool = False
    hatch_spacing: float = 5.0
    area_fill: str = "#d9d9d9"
    #: Frames whose current group is smaller than this fraction of the figure get a magnified inset.
    zoom_below: float = 0.0
    #: Frames show only the region drawn by the end of the current top-level group (same canvas size).
    progressive_zoom: bool = False
    #: The caption shows the group path of the current step above it.
    show_group: bool = False
    #: Tag the current step's unlettered points with their names, so that the
    #: caption's "M2 where k1 meets k2" can be found in the figure.
    name_tags: bool = False
    #: Every step is shown through a camera view (:mod:`construct.render.camera`): player, animation, frames.
    camera: bool = False
    #: Radius (screen px) of the ring round the current step's mark when that mark is small (0: none).
    ring_px: float = 0.0
    width_px: float = 960.0
    #: Line weights on the printed page, in points (:meth:`for_print` draws with them).
    weights: LineWeights = field(default_factory=LineWeights)
    #: Points per canvas unit when the style is laid out for print (:meth:`for_print`); None on the screen.
    print_pt: float | None = None
    #: Smallest height of the drawing area (wide figures get room for the stages of a progressive zoom).
    min_drawing_px: float = 0.0
    margin_px: float = 24.0

    @property
    def background(self) -> str:
        """The paper colour (:attr:`paper`), by its older name."""
        return self.paper

    def for_screen(self) -> "Style":
        """This style as the screen shows it: on :attr:`screen_paper` where it has one."""
        return replace(self, paper=self.screen_paper) if self.screen_paper else self

    def for_print(self, width_pt: float, letter_pt: float) -> "Style":
        """This style laid out for a page *width_pt* points wide with letters of *letter_pt* points.

        The canvas is as many units wide as the letters' size asks (a letter is :attr:`label_size` units
        high), so the letters are placed for the size they are printed at, and every line is drawn with
        its weight in points (:attr:`weights`).

        >>> st = HISTORICAL.for_print(120 / 25.4 * 72, 8.0)
        >>> round(st.width_px, 1), st.print_pt, ".heavy{stroke-width:1.2}" in st.css()
        (510.2, 0.6666666666666666, True)
        """
        for name, v in (("page width", width_pt), ("letter size", letter_pt)):
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) or v <= 0:
                raise InvalidParameter(f"the {name} must be a positive number of points, got {v!r}")
        pt = letter_pt / self.label_size
        # a page is as tall as its figure: the screen's least height (a player's stage) would print empty paper
        return replace(self, width_px=width_pt / pt, print_pt=pt, min_drawing_px=0.0)

    def css(self) -> str:
        """The style sheet every SVG in this style carries."""
        rules = [
            ".construction,.auxiliary,.result,.given{fill:none;stroke-linecap:round}",
            f".construction,.auxiliary{{stroke:{self.construction};stroke-width:{fmt(self.construction_width)}}}",
            f".result{{stroke:{self.ink};stroke-width:{fmt(self.result_width)}}}",
        ]
        if self.auxiliary_dash:
            rules.append(f".auxiliary{{stroke-dasharray:{self.auxiliary_dash}}}")
        for tool, colour in sorted(self.tool_colours.items()):
            rules.append(f".{tool}{{stroke:{colour}}}")
            rules.append(f".pt.{tool}{{fill:{colour}}}")
        for prov, colour in sorted(self.provenance_colours.items()):
            rules.append(f".{prov}{{stroke:{colour}}}")
            rules.append(f".pt.{prov}{{fill:{colour}}}")
        if self.point_ring:
            rules.append(f".pt{{fill:{self.paper};stroke:{self.ink};stroke-width:{fmt(self.point_ring)}}}")
        else:
            rules.append(f".pt{{fill:{self.ink};stroke:none}}")
        rules.append(".result.pt{stroke:none}" if not self.point_ring else f".result.pt{{fill:{self.ink}}}")
        rules.append(f".area{{fill:{self.area_fill};stroke:none}}")
        rules.append(f".hatch{{fill:none;stroke:{self.ink};stroke-width:0.4}}")
        italic = "font-style:italic;" if self.label_italic else ""
        rules.append(f".lb{{fill:{self.ink};stroke:none;font-family:{self.label_font};"
                     f"font-size:{fmt(self.label_size)}px;{italic}text-anchor:middle}}")
        cap_italic = "font-style:italic;" if self.caption_italic else ""
        rules.append(f".cap{{fill:{self.ink};stroke:none;font-family:{self.caption_font};"
                     f"font-size:{fmt(self.caption_size)}px;{cap_italic}}}")
        rules.append(f".cap.en{{fill:{self.construction}}}")
        rules.append(f".cap.grp{{font-size:{fmt(0.85 * self.caption_size)}px;fill:{self.construction}}}")
        rules.append(".cap.mid{text-anchor:middle}")
        if self.earlier_opacity < 1.0:
            rules.append(f".old{{opacity:{fmt(self.earlier_opacity)}}}")
        if self.highlight:
            # ``cur`` and ``old`` sit on a step's group (frames are views of the layered figure)
            rules.append(f".cur>*{{stroke:{self.highlight};stroke-width:{fmt(self.highlight_width)}}}")
            # a point is small: the current one gets a halo in the highlight colour, 18 units across or more with
            # its dot (14 px on the screen at the player's smallest letter scale), stronger than any line the
            # step is set on: the current mark is the loudest thing in view
            rules.append(f".cur>.pt{{fill:{self.highlight};stroke:{self.highlight};stroke-width:16;"
                         f"stroke-opacity:0.55}}")
            rules.append(f".cur .lb{{fill:{self.highlight};stroke:none}}")
        rules.append(f".inset{{fill:{self.paper};stroke:{self.construction};stroke-width:0.8}}")
        if self.done_opacity <= 0.0:
            rules.append(".done{display:none}")  # a finished group collapses to its results
        elif self.done_opacity < 1.0:
            rules.append(f".done{{opacity:{fmt(self.done_opacity)}}}")
        if self.input_colour:
            ic = self.input_colour
            # what the instrument is set on, marked, but thinner than the current step's own line
            rules.append(f".inp>*{{stroke:{ic};stroke-width:{fmt(0.5 * self.highlight_width)}}}")
            rules.append(f".inp>.pt{{fill:{ic};stroke:{ic};stroke-width:2}}")
            rules.append(f".inp .lb{{fill:{ic};stroke:none}}")
        if self.name_tags:
            # a tag at the letters' size: the player holds letters at 9.5 px at least, a smaller tag would fall below 9
            rules.append(".tag{display:none}")
            rules.append(".cur .tag,.inp .tag{display:inline}")
        # Plate looks and furniture (construct.render.plate), and the paper-coloured halo
        # behind every letter, drawn as a copy beneath it (cairosvg has no paint-order).
        rules.append(f".fur{{fill:none;stroke:{self.ink};stroke-width:0.6px}}.arrow{{fill:{self.ink};stroke:none}}")
        rules.extend(LOOKS_CSS)
        rules.append(f".brk{{fill:{self.paper};stroke:none}}.brkline{{fill:none;stroke:{self.ink};stroke-width:0.8px}}")
        rules.append(".view{display:none}")
        if self.ring_px and self.highlight:
            rules.append(f".ring{{fill:none;stroke:{self.highlight};stroke-width:2.5px;opacity:0.85}}")
        # letters drawn about their point (class lbg): set off by a screen distance at every zoom
        if self.camera:
            rules.append(level_css())
            rules.append(END_CSS)
        else:
            rules.append(".lbx{display:none}")

        halo = f"fill:{self.paper};stroke:{self.paper};stroke-width:{fmt(HALO_PX)}px;stroke-linejoin:round"
        rules.append(f".lb.halo,.cur .lb.halo,.inp .lb.halo{{{halo}}}")
        rules.append(f".leader,.cur .leader,.inp .leader{{fill:none;stroke:{self.ink};stroke-width:0.4px}}")
        if self.print_pt:
            # in print every line has its weight in points, whatever the canvas unit is on the page
            rules.extend(f"{sel}{{stroke-width:{fmt(getattr(self.weights, w) / self.print_pt, 3)}}}"
                         for sel, w in PRINT_STROKES)
        return "\n".join(rules)


#: The end state of a teaching sequence (class ``fin`` on the figure, :meth:`construct.render.scene.Scene.in_end`):
#: what it leaves out (``nf``) hidden, what it alone draws (``fo``) shown, only its letters (``pf``) at their
#: places there with their own leaders (``lvf``), scaled by the player's letter scale (``--ls``).
END_CSS = "\n".join((
    ".fo{display:none}", ".fin .fo{display:inline}", ".fin .nf,.fin .fo.hidden{display:none}",
    ".fin .lbg{display:none}", ".fin .lbg.pf{display:inline}",
    ".fin .leader{display:none}", ".fin .leader.lvf{display:inline}",
    ".fin .lbg>.lb,.fin .lbg>.leader,.fin .pt{transform:scale(var(--ls,var(--zs,1)))}",
    # the plate's looks (construct.render.plate.LOOKS_CSS) on what the end state draws where it stands
    *(".fin .fl-" + rule[1:] for rule in LOOKS_CSS),
))

PLAIN = Style()

HISTORICAL = Style(
    name="historical",
    paper=PAPERS["white"],         # print-safe: pure black on white
    screen_paper=PAPERS["cream"],  # the paper's tone, on the screen only
    ink="#000000",
    construction="#000000",
    construction_width=0.45,
    result_width=1.5,
    point_radius=1.7,
    aux_point_radius=1.1,
    point_ring=0.6,                # a pricked point: a small hole with its rim
    label_font="'DejaVu Serif', Georgia, 'Times New Roman', serif",
    label_size=12.0,
    label_italic=True,
    caption_font="'DejaVu Serif', Georgia, 'Times New Roman', serif",
    caption_size=12.0,
    caption_italic=False,          # a book sets its figure captions upright; the letters in the figure italic
    provenance_colours={},         # one ink; the protocol says what is approximate
    plate=True,
    fig_caption=True,
    hatch=True,
    hatch_spacing=4.0,
    area_fill="none",
)

TEACHING = Style(
    name="teaching",
    ink="#222222",
    construction="#7f7f7f",
    construction_width=0.9,
    result_width=2.0,
    point_radius=2.4,
    aux_point_radius=1.6,
    label_font="'DejaVu Sans', Arial, sans-serif",
    label_size=12.0,
    caption_size=14.0,
    provenance_colours={},
    tool_colours={"given": "#222222", "straightedge": "#2b8a3e", "compass": "#1c6bb0",
                  "intersect": "#222222", "dividers": "#8e44ad", "neusis": "#00838f"},
    highlight="#e8590c",
    highlight_width=2.6,
    earlier_opacity=0.45,
    done_opacity=0.0,              # a finished group collapses to its results: its helpers are not drawn
    input_colour="#c2255c",        # what the instrument is set on (centre, through point, curves cut)
    show_group=True,
    name_tags=True,
    camera=True,                   # every step through its group's view (construct.render.camera)
    ring_px=9.0,                   # a ring round a small current mark: 18 px across on the screen
    min_drawing_px=620.0,
    hatch=True,                    # hatched, as the books hatch (free forces, the excess area), over a tint
    hatch_spacing=5.0,
    area_fill="#eef3f9",
)

STYLES: dict[str, Style] = {"plain": PLAIN, "historical": HISTORICAL, "teaching": TEACHING}
