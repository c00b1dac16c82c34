"""The named styles a replay can be drawn in: style sheets, never part of a construction.

* ``plain``       grey construction, black results, approximate objects in a warm tone.
* ``historical``  a plate of the books: black ink on paper, thin construction
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

>>> sorted(STYLES)
['historical', 'plain', 'teaching']
>>> STYLES["historical"].plate, STYLES["teaching"].highlight is not None
(True, True)
"""

from __future__ import annotations

from .svg import PLAIN, Style

__all__ = ["STYLES", "HISTORICAL", "TEACHING", "PLAIN"]

HISTORICAL = Style(
    name="historical",
    background="#f3ead6",          # paper tone
    ink="#1b1a17",                 # iron-gall black
    construction="#1b1a17",
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
    caption_italic=True,
    provenance_colours={},         # one ink; the protocol says what is approximate
    plate=True,
    fig_caption=True,
    hatch=True,
    hatch_spacing=4.0,
    area_fill="none",
)

TEACHING = Style(
    name="teaching",
    background="#ffffff",
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
    area_fill="#dbe7f3",
)

STYLES: dict[str, Style] = {"plain": PLAIN, "historical": HISTORICAL, "teaching": TEACHING}
