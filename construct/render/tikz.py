"""A plate as TikZ that a LaTeX book typesets: named points, the construction's lines, TeX's letters.

:func:`tikz_picture` writes the plate laid out on its sheet (:mod:`construct.render.page`) as one
``tikzpicture`` to ``\\input``; :func:`tikz_document` wraps it in a standalone document (a page of the
sheet's size, for pdflatex or lualatex).  The picture is written for a person to read and edit:

* every lettered point is a named coordinate, ``\\coordinate (X4) at (0.61803, 0);`` under its
  TeX-safe name (:func:`construct.render.page.tex_name`: primes, subscripts and Greek spelled out);
  with the sheet's ``tikz_style="tkz-euclide"`` defined by ``\\tkzDefPoint(0.61803,0){X4}`` instead
  (the steps stay TikZ paths: tkz-euclide cannot state the branch rules that chose the intersections);
* coordinates are in the construction's own units (the crank radius, mostly), one unit set once in
  the picture's options (``x=28.5714mm``), to the stated precision (0.001 mm on the page);
* lines, arcs, curves, hatching and the plate's furniture are drawn in the style's weights in
  points (``plate heavy``, ``plate thin``, ... styles defined in the picture's options);
* every letter is TeX text, a node anchored on the side that faces its point and set off from it
  in points, where the letter placer (:mod:`construct.render.lettering`) put it; the document's font
  sets it (``\\plateletters``, italic unless the document says otherwise before the ``\\input``), at the
  size it was placed for, and it stays at its point whatever the picture's scale;
* the same plate gives the same bytes: no dates, marks in the figure's order, fixed number formats.

>>> from construct.constructions import get
>>> from construct.render.output import print_plate
>>> tikz = tikz_picture(print_plate(get("crank").figure(parts=6), construction=get("crank")))
>>> "\\\\coordinate (X2) at (" in tikz and "\\\\node[plate letter" in tikz and tikz.endswith("\\\\end{tikzpicture}\\n")
True
"""

from __future__ import annotations

import math
from typing import Iterable

from .lettering import HALO_PX, LEADER_FROM, text_box
from .paths import bezier_controls, hatch_segments
from .plate import DASHES, PIECES, Piece, break_elements, crossing_lines, furniture_pieces, subscript_runs
from .rod_length import rod_pieces
from .scene import Mark, MarkKind
from .page import PrintPlate
from .styles import PRINT_STROKES, Style
from .svg import mark_layer, point_radius

__all__ = ["tikz_picture", "tikz_document", "tikz_example", "tex_text", "tex_lettering", "LETTER_MACRO"]

#: The command that sets the letters' face; the document may define it before the ``\input`` (e.g. upright:
#: ``\newcommand\plateletters{\upshape}``); the picture defines it only where the document has not.
LETTER_MACRO = "\\plateletters"
#: Decimals of a length in points (letter offsets, point radii): a hundredth of a point, 0.0035 mm.
PT_DECIMALS = 2
#: The largest error of a coordinate on the page, in millimetres (the decimals of a unit follow from it).
PRECISION_MM = 0.001
#: The tension of TikZ's smooth plot that puts a point's controls a sixth of the chord between its neighbours
#: away (pgf takes 0.2775 * tension of it: 1 / (6 * 0.2775)), as the SVG's curves (:func:`paths.bezier_controls`).
SMOOTH_TENSION = "0.6006"

#: The German opening quotes: the closing ones lowered to the baseline (kernel commands only: \quotedblbase
#: needs a T1 font, which a document in the default OT1 encoding does not have).
LOW_QUOTES = "\\raisebox{-1.05ex}{''}"
#: How the characters of the books' letters and captions are set in TeX (pdflatex and lualatex alike,
#: with no package beyond the kernel: every other character is written as itself only if it is ASCII).
_TEX = {"'": "$'$", "′": "$'$", "″": "$''$", "∞": "$\\infty$", "·": "$\\cdot$", "−": "$-$", "–": "--", "—": "---",
        "°": "\\textdegree{}", "²": "\\textsuperscript{2}", "§": "\\S{}", "ä": '\\"a', "ö": '\\"o', "ü": '\\"u',
        "Ä": '\\"A', "Ö": '\\"O', "Ü": '\\"U', "ß": "\\ss{}", "„": LOW_QUOTES, "“": "\\textquotedblleft{}",
        "”": "\\textquotedblright{}", "‘": "`", "’": "'", "…": "\\dots{}", "×": "$\\times$", "%": "\\%",
        "&": "\\&", "#": "\\#", "$": "\\$", "_": "\\_", "{": "\\{", "}": "\\}", "~": "\\textasciitilde{}",
        "^": "\\textasciicircum{}", "\\": "\\textbackslash{}", "<": "\\textless{}", ">": "\\textgreater{}",
        "|": "\\textbar{}", "\u00a0": "~", "\u202f": "\\,"}
_GREEK = dict(zip("αβγδεζηθικλμνξπρστυφχψω", ("alpha beta gamma delta varepsilon zeta eta vartheta iota kappa lambda mu "
                                               "nu xi pi rho sigma tau upsilon varphi chi psi omega").split()))


def tex_text(text: str) -> str:
    """*text* (a letter, a dimension, a caption) as TeX that pdflatex and lualatex set alike.

    >>> tex_text("4'"), tex_text("A₁"), tex_text("P = F·pü"), tex_text("ρ"), tex_text("100 %")
    ("4$'$", 'A\\\\textsubscript{1}', 'P = F$\\\\cdot$p\\\\"u', '$\\\\rho$', '100 \\\\%')
    """
    out = []
    for c in text:
        if c in _TEX:
            out.append(_TEX[c])
        elif "₀" <= c <= "₉":
            out.append(f"\\textsubscript{{{ord(c) - ord('₀')}}}")
        elif c in _GREEK:
            out.append(f"$\\{_GREEK[c]}$")
        elif c.isascii() and c.isprintable():
            out.append(c)
        else:
            out.append(f"[U+{ord(c):04X}]")  # a character the books have not used yet: seen, never a TeX error
    return "".join(out)


def tex_lettering(text: str) -> str:
    """A plate's lettering as TeX: its indices (``P_b``, ``p_{ü}``, :func:`~construct.render.plate.subscript_runs`)
    set below the line, as the SVG plate sets them, the rest as :func:`tex_text`.

    >>> tex_lettering("P_b"), tex_lettering("P = F·p_ü")
    ('P\\\\textsubscript{b}', 'P = F$\\\\cdot$p\\\\textsubscript{\\\\"u}')
    """
    return "".join(f"\\textsubscript{{{tex_text(run)}}}" if low else tex_text(run) for run, low in subscript_runs(text))


class _Writer:
    """The lines of one picture, with the plate's numbers formatted once."""

    def __init__(self, plate: PrintPlate):
        self.plate = plate
        self.vp = plate.drawing.vp
        self.st: Style = plate.style
        self.pt = plate.pt
        mm = plate.mm_per_unit
        self.decimals = max(2, math.ceil(math.log10(mm / PRECISION_MM))) if mm > PRECISION_MM else 2
        self.lines: list[str] = []

    # -- numbers -------------------------------------------------------------------------------------
    def num(self, v: float, decimals: int | None = None) -> str:
        text = f"{v:.{self.decimals if decimals is None else decimals}f}".rstrip("0").rstrip(".")
        return "0" if text in ("-0", "") else text

    def xy(self, x: float, y: float) -> str:
        """A point in drawing units."""
        return f"({self.num(x)},{self.num(y)})"

    def canvas(self, x: float, y: float) -> str:
        """A point of the canvas (pixels, y down) in drawing units."""
        vp = self.vp
        return self.xy(vp.xmin + (x - vp.margin - vp.left) / vp.scale, vp.ymax - (y - vp.margin - vp.top) / vp.scale)

    def pts(self, px: float) -> str:
        """A length on the canvas in points on the page."""
        return self.num(px * self.pt, PT_DECIMALS) + "pt"

    def add(self, line: str) -> None:
        self.lines.append(line)


def _weight(classes: Iterable[str]) -> str:
    """The print weight of a mark with these classes: the last rule of :data:`PRINT_STROKES` that names one."""
    have = set(classes)
    got = "construction"
    for selector, weight in PRINT_STROKES:
        if any(part.strip().lstrip(".") in have for part in selector.split(",") if " " not in part.strip()):
            got = weight
    return got


def _mark_classes(m: Mark) -> list[str]:
    return [m.role, m.tool, m.provenance, *m.look.split()]


def _colour(st: Style, m: Mark | str) -> str | None:
    """The colour of a mark's line as the style sheet gives it (or the colour *m*), None for black."""
    if isinstance(m, str):
        colour = m
    else:
        colour = st.ink if m.role == "result" else st.construction
        colour = st.tool_colours.get(m.tool, colour)
        colour = st.provenance_colours.get(m.provenance, colour)
    return None if colour.lower() in ("#000", "#000000") else colour


def _colour_name(colour: str) -> str:
    return "plate" + colour.lstrip("#").lower()


def _styles(w: _Writer) -> list[str]:
    """The picture's styles: the weights in points, the dash patterns, the points, the letters."""
    st, pt = w.st, w.pt
    weights = st.weights
    out = [f"plate {name}/.style={{line width={w.num(getattr(weights, name), 3)}pt}}"
           for name in ("heavy", "result", "medium", "thin", "construction", "fine")]
    for look, dash in DASHES.items():
        pattern = " ".join(f"{'on' if i % 2 == 0 else 'off'} {w.num(d * pt, PT_DECIMALS)}pt" for i, d in enumerate(dash))
        out.append(f"plate {look}/.style={{dash pattern={pattern}}}")
    ink = _colour_name(st.ink) if _colour(st, st.ink) else "black"
    ring = f"draw={ink}, line width={w.num(weights.thin, 3)}pt, fill=white" if st.point_ring else f"fill={ink}"
    out += [f"plate point/.style={{{ring}}}",
            f"plate result point/.style={{fill={ink}}}",
            f"plate letter/.style={{font={LETTER_MACRO}\\fontsize{{{w.num(st.label_size * pt, 2)}}}"
            f"{{{w.num(1.2 * st.label_size * pt, 2)}}}\\selectfont, inner sep={w.num(HALO_PX / 2 * pt, 2)}pt, "
            f"fill=white}}"]
    return out


def tikz_picture(plate: PrintPlate) -> str:
    """The plate as one ``tikzpicture`` (to ``\\input`` into a document that loads TikZ)."""
    w = _Writer(plate)
    st, sc = w.st, plate.scene
    title = " / ".join(t for t in plate.title if t)
    w.add(f"% {tex_comment(title)}")
    w.add(f"% construct: {plate.style.name} style, "
          f"{w.num(plate.sheet.width_mm, 3)} mm wide, letters {w.num(plate.sheet.letter_pt, 2)} pt.")
    w.add(f"% Coordinates in the construction's units (1 unit = {w.num(plate.mm_per_unit, 4)} mm on the page), "
          f"to {PRECISION_MM} mm; lengths of letters and points in pt.")
    w.add("% Every lettered point is a named coordinate; its letter a node anchored beside it.")
    face = "\\itshape" if st.label_italic else "\\upshape"
    w.add(f"\\providecommand{LETTER_MACRO}{{{face}}}%")  # no space in the paragraph that holds the picture
    unit = f"{w.num(plate.mm_per_unit, 5)}mm"
    options = [f"x={unit}", f"y={unit}", "line cap=round", "line join=round"] + _styles(w)
    w.add("\\begin{tikzpicture}[" + (",\n  ".join(options)) + "]")
    colours = sorted({c for m in [*sc.marks, st.ink] if (c := _colour(st, m)) is not None}
                     | {c for c in (*st.tool_colours.values(), *st.provenance_colours.values()) if _colour(st, c)})
    for c in colours:
        w.add(f"\\definecolor{{{_colour_name(c)}}}{{HTML}}{{{c.lstrip('#').upper()}}}")
    vp = w.vp
    # the page: the picture is the sheet's size, wherever its ink reaches
    w.add(f"\\path[use as bounding box] {w.canvas(0, vp.height)} rectangle {w.canvas(vp.width, 0)};")
    points = plate.points()
    named = {p.mark.id: p.name for p in points}
    if points and plate.sheet.tikz_style == "tkz-euclide":
        # tkz-euclide's own definitions; the steps stay TikZ paths: the construction found its intersections
        # by branch rules (nearer, left of, ...) that tkz-euclide's \tkzInter... macros cannot state
        w.add("% the lettered points, defined with tkz-euclide")
        for p in points:
            w.add(f"\\tkzDefPoint{w.xy(*p.mark.geom)}{{{p.name}}}")
    elif points:
        w.add("% the lettered points")
        for p in points:
            w.add(f"\\coordinate ({p.name}) at {w.xy(*p.mark.geom)};")
    for title_, layer in (("areas", "areas"), ("the construction", "construction"), ("the results", "results"),
                          ("the points", "points")):
        marks = [m for m in sc.marks if mark_layer(m) == layer and "hidden" not in m.look.split()]
        if marks:
            w.add(f"% {title_}")
        if layer == "points":
            _points(w, marks, named)
            continue
        for m in marks:
            _mark(w, m, named)
    _furniture(w)
    _letters(w, named)
    if plate.caption:
        _caption(w)
    w.add("\\end{tikzpicture}")
    return "\n".join(w.lines) + "\n"


def tex_comment(text: str) -> str:
    """*text* on one comment line (no line break ends the comment early)."""
    return " ".join(str(text).split())


def _draw_options(w: _Writer, m: Mark) -> str:
    looks = [look for look in m.look.split() if look in DASHES]
    colour = _colour(w.st, m)
    return ", ".join([f"plate {_weight(_mark_classes(m))}", *(f"plate {look}" for look in looks),
                      *([f"draw={_colour_name(colour)}"] if colour else [])])


def _mark(w: _Writer, m: Mark, named: dict[str, str]) -> None:
    g, kind = m.geom, m.kind
    st = w.st
    opts = _draw_options(w, m)
    if kind is MarkKind.SEGMENT:
        w.add(f"\\draw[{opts}] {w.xy(g[0], g[1])} -- {w.xy(g[2], g[3])};")
    elif kind is MarkKind.CIRCLE:
        w.add(f"\\draw[{opts}] {w.xy(g[0], g[1])} circle[radius={w.num(g[2])}];")
    elif kind is MarkKind.ARC:
        cx, cy, r, a0, sweep = g
        start = w.xy(cx + r * math.cos(a0), cy + r * math.sin(a0))
        w.add(f"\\draw[{opts}] {start} arc[start angle={w.num(math.degrees(a0), 4)}, "
              f"delta angle={w.num(math.degrees(sweep), 4)}, radius={w.num(r)}];")
    elif kind is MarkKind.CURVE:
        if len(g) < 2:
            return
        closed = m.straight and len(g) > 2 and tuple(g[0]) == tuple(g[-1])
        if m.straight:
            pieces = [w.xy(*p) for p in (g[:-1] if closed else g)]
            w.add(f"\\draw[{opts}] " + _wrapped(" -- ".join(pieces)) + (" -- cycle;" if closed else ";"))
        elif len(g) == 2:
            (_, c1, c2, p2), = bezier_controls(list(g))
            w.add(f"\\draw[{opts}] {w.xy(*g[0])} .. controls {w.xy(*c1)} and {w.xy(*c2)} .. {w.xy(*p2)};")
        else:
            # TikZ's smooth plot is the SVG's curve (Catmull-Rom: a point's controls a sixth of the chord
            # between its neighbours away, pgf's 0.2775 * tension) once the first and last points are written
            # twice: the plot's own ends would set their controls on the points themselves
            ends = [g[0], *g, g[-1]]
            coords = [w.xy(*q) for q in ends]
            rows = [" ".join(coords[i:i + 6]) for i in range(0, len(coords), 6)]
            w.add(f"\\draw[{opts}] plot[smooth, tension={SMOOTH_TENSION}] coordinates {{" + "\n    ".join(rows) + "};")
    else:  # an area: hatched as the style hatches, or filled
        if st.hatch:
            vp = w.vp
            segs = hatch_segments([vp.px(x, y) for x, y in g], st.hatch_spacing,
                                  *(() if m.hatch is None else (m.hatch,)),
                                  under=[[vp.px(x, y) for x, y in o] for o in w.plate.scene.areas_over(m)])
            if segs:
                w.add("\\draw[plate fine] " + "\n    ".join(f"{w.canvas(*a)} -- {w.canvas(*b)}" for a, b in segs) + ";")
        elif st.area_fill not in ("none", ""):
            w.add(f"\\fill[color={{rgb,255:red,{int(st.area_fill[1:3], 16)};green,{int(st.area_fill[3:5], 16)};"
                  f"blue,{int(st.area_fill[5:7], 16)}}}] " + " -- ".join(w.xy(*p) for p in g) + " -- cycle;")


def _points(w: _Writer, marks: list[Mark], named: dict[str, str]) -> None:
    """The points, those of one look and size in one list: ``\\foreach \\p in {(X4),(0.5,1),...}``."""
    st = w.st
    looks: dict[tuple[str, str], list[str]] = {}
    for m in marks:
        style = "plate point" + (", plate result point" if m.role == "result" else "")
        colour = st.tool_colours.get(m.tool) or st.provenance_colours.get(m.provenance)
        if colour:
            style += f", fill={_colour_name(colour)}"
        key = (style, w.pts(point_radius(m, st)))
        looks.setdefault(key, []).append(f"({named[m.id]})" if m.id in named else w.xy(*m.geom))
    for (style, r), at in looks.items():
        rows = [",".join(at[i:i + 8]) for i in range(0, len(at), 8)]
        w.add("\\foreach \\p in {" + ",\n    ".join(rows) + f"}}\n  \\path[{style}] \\p circle[radius={r}];")


def _wrapped(text: str, width: int = 100) -> str:
    """A long path broken at its joins (``--``), so that a line stays readable."""
    out, line = [], ""
    for part in text.split(" -- "):
        if line and len(line) + len(part) > width:
            out.append(line)
            line = part
        else:
            line = part if not line else f"{line} -- {part}"
    out.append(line)
    return " --\n    ".join(out)


#: The anchor of a letter on the side that faces its point, by the direction from the point to the letter
#: (sectors of 45 degrees counter-clockwise from the east, y up).
_ANCHORS = ("base west", "south west", "south", "south east", "base east", "north east", "north", "north west")


def _letters(w: _Writer, named: dict[str, str]) -> None:
    """Every shown letter: a node anchored on its side towards its point, set off from it by points."""
    st = w.st
    size = st.label_size
    labels = [lb for lb in w.plate.drawing.labels() if lb.shown]
    if labels:
        w.add("% the letters, set by TeX where the letter placer put them")
    h = HALO_PX / 2
    for lb in labels:
        px, py = lb.point
        x, y = px + lb.offset[0], py + lb.offset[1]
        x0, y0, x1, y1 = text_box(x, y, lb.text, size, st.label_font, st.label_italic)
        x0, y0, x1, y1 = x0 - h, y0 - h, x1 + h, y1 + h
        angle = math.degrees(math.atan2(-((y0 + y1) / 2 - py), (x0 + x1) / 2 - px))
        anchor = _ANCHORS[round(angle / 45.0) % 8]
        ax = x0 if "west" in anchor else x1 if "east" in anchor else (x0 + x1) / 2
        ay = y if anchor.startswith("base") else y1 if anchor.startswith("south") else y0
        at = f"({named[lb.id]})" if lb.id in named else w.canvas(px, py)
        if lb.distance >= LEADER_FROM:
            # a letter set off from a crowded point is tied to it, as in the SVG plate
            cx, cy = lb.offset[0], lb.offset[1] - 0.35 * size
            n = math.hypot(cx, cy) or 1.0
            a, b = 0.25 * size, n - 0.75 * size
            w.add(f"\\draw[plate fine] ([shift={{({w.pts(a * cx / n)},{w.pts(-a * cy / n)})}}]{at[1:-1]}) -- "
                  f"([shift={{({w.pts(b * cx / n)},{w.pts(-b * cy / n)})}}]{at[1:-1]});")
        w.add(f"\\node[plate letter, anchor={anchor}, xshift={w.pts(ax - px)}, yshift={w.pts(py - ay)}] "
              f"at {at} {{{tex_lettering(lb.text)}}};")


def _furniture(w: _Writer) -> None:
    """The plate's furniture (dimensions, angle arcs, scales, signs, lettering) and the broken axis's marks."""
    sc, vp, st = w.plate.scene, w.vp, w.st
    pieces = furniture_pieces(sc.furniture, vp.px, vp.scale, size=st.label_size)
    pieces += break_elements(sc.breaks, crossing_lines(sc.marks, sc.furniture), vp.px, PIECES, size=st.label_size)
    # a broken rod is drawn short: the figure says how long it is, where the SVG writes it (render/rod_length.py)
    pieces += rod_pieces(*w.plate.drawing.rod_at, st.label_size)
    if not pieces:
        return
    w.add("% the plate's furniture")
    for p in pieces:
        _piece(w, p)


def _piece(w: _Writer, p: Piece) -> None:
    st = w.st
    if p.kind == "text":
        size = st.label_size * p.size
        anchor = {"start": "west", "end": "east"}.get(p.anchor, "center")
        rotate = f", rotate={w.num(p.angle, 2)}" if p.angle else ""
        w.add(f"\\node[plate letter, font={LETTER_MACRO}\\fontsize{{{w.num(size * w.pt, 2)}}}"
              f"{{{w.num(1.2 * size * w.pt, 2)}}}\\selectfont, anchor={anchor}{rotate}] at {w.canvas(*p.points[0])} "
              f"{{{tex_lettering(p.text)}}};")
        return
    if p.kind == "dot":
        w.add(f"\\fill {w.canvas(*p.points[0])} circle[radius={w.pts(p.size)}];")
        return
    classes = p.cls.split()
    path = " -- ".join(w.canvas(*q) for q in p.points) + (" -- cycle" if p.closed else "")
    if "arrow" in classes:
        w.add(f"\\fill {path};")
    elif "brk" in classes:
        w.add(f"\\fill[white] {path};")
    else:
        looks = [c for c in classes if c in DASHES]
        opts = ", ".join([f"plate {_weight(classes)}", *(f"plate {look}" for look in looks)])
        w.add(f"\\draw[{opts}] {_wrapped(path)};")


def _caption(w: _Writer) -> None:
    plate, st, vp = w.plate, w.st, w.vp
    top = plate.drawing.drawing_height
    size = st.caption_size * w.pt
    italic = "\\itshape" if st.caption_italic else ""
    text = " ".join(tex_text(t) for t in plate.caption)
    w.add("% the caption")
    w.add(f"\\node[anchor=north, text width={w.num((vp.width - 2 * vp.margin) * w.pt, 2)}pt, align=center, "
          f"inner sep=0pt, font={italic}\\fontsize{{{w.num(size, 2)}}}{{{w.num(1.45 * size, 2)}}}\\selectfont] "
          f"at {w.canvas(vp.width / 2, top + 0.2 * st.caption_size)} {{{text}}};")


def tikz_document(plate: PrintPlate) -> str:
    """A standalone LaTeX document of the plate: a page the sheet's size holding the picture alone
    (pdflatex or lualatex; TikZ and geometry, both in every TeX distribution's basic set)."""
    # the page no smaller than the picture: a page rounded down by a thousandth of a millimetre sends the
    # picture to a second page and leaves the first blank
    w, h = (math.ceil(round(v / PRECISION_MM, 6)) * PRECISION_MM for v in (plate.width_mm, plate.height_mm))
    num = _Writer(plate).num
    return ("% The plate alone on a page of its size: pdflatex or lualatex this file.\n"
            "\\documentclass{article}\n"
            f"\\usepackage[paperwidth={num(w, 3)}mm, paperheight={num(h, 3)}mm, margin=0pt]{{geometry}}\n"
            + PREAMBLE + ("\\usepackage{tkz-euclide}\n" if plate.sheet.tikz_style == "tkz-euclide" else "") +
            "\\pagestyle{empty}\n"
            "\\begin{document}\n"
            "\\noindent%\n"
            + tikz_picture(plate) +
            "\\end{document}\n")


#: The preamble every document of plates needs: TikZ, and fonts at every size (Latin Modern; T1 under pdflatex,
#: lualatex sets Unicode fonts itself).
PREAMBLE = ("\\ifdefined\\directlua\\else\\usepackage[T1]{fontenc}\\fi\n"
            "\\usepackage{lmodern}\n"
            "\\usepackage{tikz}\n")


def tikz_example(plates: list[tuple[str, str]]) -> str:
    """A one-page LaTeX document that ``\\input``\\ s each plate's picture (*plates*: its ``.tikz`` file's
    name and its caption) as a figure of an A4 page with a type area 150 mm wide.

    >>> print(tikz_example([("crank.tikz", "Kolbenwege")]).splitlines()[-4])
      \\input{crank.tikz}
    """
    body = "".join("\\begin{figure}[!ht]\n  \\centering\n"
                   f"  \\input{{{name}}}\n  \\caption{{{tex_text(caption)}}}\n\\end{{figure}}\n"
                   for name, caption in plates)
    return ("% Plates drawn by construct (construct replay NAME --style historical --format tikz), set by LaTeX:\n"
            "% each picture is \\input where the figure goes; its letters are set in the document's font.\n"
            "% pdflatex or lualatex this file beside the .tikz files.\n"
            "\\documentclass[10pt]{article}\n"
            "\\usepackage[a4paper, textwidth=150mm, textheight=250mm]{geometry}\n"
            + PREAMBLE +
            "\\begin{document}\n"
            + body +
            "\\end{document}\n")
