"""A drawing read from its file for legibility: its letters, point markers, result lines and steps.

What is read is what the renderer writes (:mod:`construct.render.svg`) and
DESIGN §7 names as stable: ``text.lb`` a label (``text.lb.halo`` the paper
coloured halo beneath it, ``text.lb.tag`` the name tag of a current step's
point), ``text.cap`` a caption line, ``circle.pt`` a point marker (a label
``X-label`` or ``X-tag`` names the point ``X``), elements of class
``result`` the result lines, ``g[data-step=k]`` the groups of step k
(``data-fade``: the last step of its group, after which its helpers fade).
Nothing is rebuilt from a construction: any user's output folder can be read.

How each element looks is worked out from the drawing's own style sheet
(:mod:`.cascade`) for every state a step's group takes in the player
(current ``cur``, earlier ``old``, faded ``done``, an input ``inp``), so that
what a view shows is what a browser shows.  Text extents come from the font
the style sheet names (:mod:`.fonts`).  Lengths are user units of the
drawing, boxes (x0, y0, x1, y1) with y down.  The elements' outlines are :mod:`.outlines`; what the drawing
tells the player (the camera's views, the letters' moves) is :mod:`.player`.

>>> svg = '''<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 100">
... <style>.lb{font-family:'DejaVu Sans';font-size:12px;text-anchor:middle}.pt{fill:black}
... .result{stroke:black;stroke-width:2;fill:none}</style>
... <g class="step" data-step="1"><circle class="pt" id="s0001-A" cx="50" cy="50" r="2"/>
... <text class="lb" id="s0001-A-label" x="60" y="45">A</text></g>
... <g class="step" data-step="2"><line class="result" x1="0" y1="90" x2="200" y2="90"/></g></svg>'''
>>> sh = read_sheet(svg, "demo")
>>> [t.text for t in sh.texts], sh.texts[0].owner, sh.n, len(sh.dots), len(sh.strokes)
(['A'], 's0001-A', 2, 1, 1)
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field, replace
from pathlib import Path

from ...kernel.errors import ConstructError
from ..svgdiff.geometry import parse_transform
from .cascade import PROPERTIES, Cascade, Look, Node, declarations
from .fonts import text_extents
from .outlines import (IDENTITY, Box, Matrix, box_of, compose, cut_pieces, four_numbers, local_name, number, polylines,
                       transform_lines, transform_point)
from .player import END, END_LEVEL, player_data, read_moves, read_views

__all__ = ["Sheet", "Text", "Dot", "Stroke", "Line", "Leader", "read_sheet", "read_views", "player_data",
           "LintInputError", "STATES", "Box", "read_moves", "END", "END_LEVEL"]


#: The classes the player gives a step's groups (besides ``step``); "" is the whole figure as the file has it.
STATES = ("cur", "old", "done", "inp", "hid")

#: A label's box reaches this far beyond its glyphs when it has no halo (user units): labels closer
#: than twice this read as one word ("ω7ω6").
MIN_MARGIN = 0.5

_NOT_DRAWN = {"defs", "clipPath", "mask", "marker", "pattern", "symbol", "style", "script", "metadata", "title",
              "desc", "linearGradient", "radialGradient", "filter", "foreignObject", "animate", "set",
              "animateTransform", "animateMotion"}
_DRAWN = {"line", "path", "circle", "ellipse", "polyline", "polygon", "rect"}
#: The largest drawing read (a 3600-part replay's final.svg is a few MB; as ``construct diff``).
MAX_BYTES = 320 * 2**20
#: Subtrees not read: the magnified inset of a frame is a second picture at another scale over the first.
_SKIPPED_IDS = {"inset"}


_PROPERTY_SET = frozenset(PROPERTIES)
#: A zoom level's class (``zl3``).
_ZOOM_CLASS = re.compile(r"zl\d+")
#: Marks a step's group in a chain (its state classes are what a view changes).
_STEP_GROUP = ("#step-group", "")
_STATE_CLASSES = frozenset(STATES)
#: The classes a view changes besides the zoom level (:meth:`Sheet._look`): a step's state, the end state.
_VIEW_STATES = _STATE_CLASSES | {END}


class LintInputError(ConstructError, ValueError):
    """What lint was given is not a drawing it can read (not XML, no <svg>, no such file or folder)."""


@dataclass(frozen=True, slots=True)
class Text:
    """A label, a point's name tag or a caption line, with the box its glyphs and halo cover."""

    index: int
    text: str
    kind: str  # "label", "tag" or "caption"
    ident: str | None
    owner: str | None  # the id of the point it names
    step: int | None
    chain: tuple[Node, ...]
    box: Box
    size: float  # font size, user units
    #: A letter drawn about its point (``<g class="lbg" transform="translate(point)">``): the point, where
    #: the player's letter scale and a zoom level's move are applied about; None for a text set on the sheet.
    anchor: tuple[float, float] | None = None
    #: The id of its letter group (a zoom level's rule moves it by that id), and the group's own scale.
    group: str | None = None
    unit: float = 1.0
    #: Its letter group, numbered in the order the groups stand in the file (None: set on the sheet).
    lbg: int | None = None
    #: The box its glyphs' ink covers in its own coordinates (before its transforms), and those transforms:
    #: a turned letter's ink is a turned box on the sheet (a plate's core test, :mod:`.plates`).
    ink: Box = (0.0, 0.0, 0.0, 0.0)
    ctm: Matrix = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)

    @property
    def name(self) -> str:
        return f"{self.text!r} ({self.ident})" if self.ident else repr(self.text)


@dataclass(frozen=True, slots=True)
class Dot:
    """A point marker: a disc of radius ``r`` (its stroke included)."""

    ident: str | None
    step: int | None
    chain: tuple[Node, ...]
    x: float
    y: float
    r: float


@dataclass(frozen=True, slots=True)
class Stroke:
    """A drawn line of the result role: straight pieces and half its stroke width."""

    ident: str | None
    step: int | None
    chain: tuple[Node, ...]
    pieces: tuple[tuple[float, float, float, float], ...]
    half: float


@dataclass(frozen=True, slots=True)
class Leader:
    """A leader line of a letter group: from near its point towards its letter, about the point (its anchor).

    ``line`` is (x1, y1, x2, y2) in the group's own units, from the point's end; a view draws it scaled by the
    player's letter scale about the anchor (and, in drawings made before leaders were drawn per zoom level,
    moved with the letter).
    """

    ident: str | None
    step: int | None
    chain: tuple[Node, ...]
    anchor: tuple[float, float]
    line: tuple[float, float, float, float]
    group: str | None
    unit: float
    lbg: int


@dataclass(frozen=True, slots=True)
class Line:
    """Any stroked line of a plate (construction, result, furniture, hatching, a leader): its straight
    pieces and half its stroke width."""

    ident: str | None
    chain: tuple[Node, ...]
    pieces: tuple[tuple[float, float, float, float], ...]
    half: float


@dataclass(frozen=True, slots=True)
class Drawn:
    """Any drawn element of a step (for the size of the current step's mark): its box without stroke."""

    step: int
    ident: str | None
    chain: tuple[Node, ...]
    box: Box


@dataclass
class Sheet:
    """A drawing as lint reads it."""

    name: str
    viewbox: tuple[float, float, float, float]  # x, y, w, h
    cascade: Cascade
    texts: list[Text] = field(default_factory=list)
    dots: list[Dot] = field(default_factory=list)
    strokes: list[Stroke] = field(default_factory=list)
    drawn: list[Drawn] = field(default_factory=list)
    leaders: list[Leader] = field(default_factory=list)
    #: Every drawn element but the paper (any step, the furniture too): its chain and box with its stroke.
    inked: list[tuple[tuple[Node, ...], Box]] = field(default_factory=list)
    #: The (zoom level, letter group id) whose rule moves the leader with the letter (``#id>.leader``, ``#id>*``).
    moved_leaders: set[tuple[int, str]] = field(default_factory=set)
    #: The steps that have groups, and the last of them (0: none).
    steps: list[int] = field(default_factory=list)
    n: int = 0
    #: data-fade of a step's groups: the last step of its group (its helpers fade after it).
    fades: dict[int, int] = field(default_factory=dict)
    #: The state a step's groups have in the file ("" when none): the figure as it stands.
    file_states: dict[int, str] = field(default_factory=dict)
    #: A frame (one step's view, its groups marked in the file): that step; None for a layered figure.
    frame: int | None = None
    #: Whether the style sheet marks a current step: then every step's view is checked.
    marks_steps: bool = False
    #: Per step, the steps whose objects it is set on (from the player's data; empty when not known).
    inputs: dict[int, tuple[int, ...]] = field(default_factory=dict)
    #: The camera: per step its view box (x, y, w, h) when the output stores one.
    views: dict[int, tuple[float, float, float, float]] = field(default_factory=dict)
    #: Shown by the player (its data read): letters and points held at their screen size, views through its window.
    player: bool = False
    #: Its steps are seen only in its player: a layered figure with a camera but no player's data beside it is
    #: seen as the file stands, through its last view (the player's look of its last step).
    unplayed: bool = False
    #: The zoom levels of the style sheet's ``.zlN`` classes (from the player's data; (1,) when none).
    levels: tuple[float, ...] = (1.0,)
    #: Per (zoom level, letter group id): the move (dx, dy) a ``.zlN #id>.lb`` rule gives the letter there.
    moves: dict[tuple[int, str], tuple[float, float]] = field(default_factory=dict)
    #: Per step, the ring the player draws round a small current mark: (cx, cy, r) as its data gives it.
    rings: dict[int, tuple[float, float, float]] = field(default_factory=dict)
    #: The file shows an end state (class ``fin`` on its root): the last step's view; the steps before show
    #: the figure without it (the player sets the class at the last step only).
    end: bool = False
    #: Per step, what the player writes beside the figure: its caption (German, English) and its group's.
    captions: dict[int, tuple[str, ...]] = field(default_factory=dict)
    #: A plate (the root ``<svg class="plate">``): one still view, read for every stroked line (:attr:`lines`).
    plate: bool = False
    #: A plate's stroked lines of every kind (read for plates only: a stepped figure has thousands).
    lines: list[Line] = field(default_factory=list)
    #: The width the file asks to be shown at (its root's ``width``, px), if it says.
    width: float | None = None
    #: The looks asked for, by (chain, state, level): every view asks again for the same few.
    _looks: dict[tuple, Look] = field(default_factory=dict, repr=False, compare=False)

    def look(self, chain: tuple[Node, ...], state: str | None = None, level: int = 0) -> Look:
        """The look of an element (its chain) with its step's groups in *state* (None: as in the file), the
        drawing shown at zoom level *level* (the player's class ``zlN`` on the root)."""
        key = (chain, state, level)
        got = self._looks.get(key)
        if got is None:
            seen_as = self.level_as(chain, level)
            got = self._looks[key] = (self.look(chain, state, seen_as) if seen_as != level
                                      else self._look(chain, state, level))
        return got

    def level_as(self, chain: tuple[Node, ...], level: int) -> int:
        """The first zoom level at which *chain* looks as it does at *level*, in every state (:meth:`look`).
        Most elements look the same at every level: only the rules naming a level's class (``.zl2 .lv2``) tell
        the levels apart, and they are asked once per chain (:meth:`Cascade.asking`) rather than every look
        worked out at every level."""
        if not level:
            return 0
        names = self.__dict__.get("_zoom_classes")
        if names is None:
            names = self.__dict__["_zoom_classes"] = frozenset(
                c for r in self.cascade.rules for part in r.parts for c in part[1][2] if _ZOOM_CLASS.fullmatch(c))
        # (a step's state and the end state are changed alongside: _look)
        asked = self.cascade.asking(chain, names, _VIEW_STATES)
        if f"zl{level}" in asked:
            return level
        return next(k for k in range(level + 1) if f"zl{k}" not in asked)

    def _look(self, chain: tuple[Node, ...], state: str | None, level: int) -> Look:
        root = chain[0]
        classes = root[2]
        if state is not None:
            classes = classes - {END}  # a step's view before the last: the player shows no end state
        if level or any(c.startswith("zl") for c in classes):  # the view's zoom level, in place of the file's
            classes = frozenset(c for c in classes if not _ZOOM_CLASS.fullmatch(c)) | {f"zl{level}"}
        if classes is not root[2]:
            chain = ((root[0], root[1], classes, root[3]),) + chain[1:]
        if state is None:
            return self.cascade.look(chain)
        for i in range(len(chain) - 1, -1, -1):
            nd = chain[i]
            if _STEP_GROUP in nd[3]:
                classes = nd[2] - _STATE_CLASSES
                if state:
                    classes = classes | {state}
                changed = chain[:i] + ((nd[0], nd[1], classes, nd[3]),) + chain[i + 1:]
                return self.cascade.look(changed)
        return self.cascade.look(chain)


# --------------------------------------------------------------------------- reading

def read_sheet(source: str | bytes | Path, name: str, *, data: dict | None = None) -> Sheet:
    """Read a drawing (SVG text, bytes or a file) into a :class:`Sheet`; *data*: the player's, if any."""
    if isinstance(source, Path):
        try:
            size = source.stat().st_size
            if size > MAX_BYTES:
                raise LintInputError(f"{name}: larger than {MAX_BYTES // 2**20} MiB ({size} bytes); "
                                     f"no drawing this library writes is")
            source = source.read_bytes()
        except OSError as exc:
            raise LintInputError(f"{name}: cannot read: {exc.strerror or exc}") from None
    try:
        root = ET.fromstring(source)
    except ET.ParseError as exc:
        raise LintInputError(f"{name}: not well-formed XML: {exc}") from None
    except (ValueError, UnicodeError) as exc:
        raise LintInputError(f"{name}: cannot decode: {exc}") from None
    if local_name(root.tag) != "svg":
        raise LintInputError(f"{name}: the root element is <{local_name(root.tag)}>, not <svg>")
    css = "\n".join("".join(e.itertext()) for e in root.iter() if local_name(e.tag) == "style")
    cascade = Cascade(css)
    vb = four_numbers(root.get("viewBox", "")) or (0.0, 0.0, number(root.get("width"), 0.0), number(root.get("height"), 0.0))
    if vb[2] <= 0 or vb[3] <= 0:
        raise LintInputError(f"{name}: the drawing has no size (no viewBox, width or height)")
    sheet = Sheet(name=name, viewbox=vb, cascade=cascade)
    sheet.marks_steps = _marks_steps(cascade)
    sheet.plate = "plate" in root.get("class", "").split()
    sheet.width = number(root.get("width"), 0.0) or None
    _Reader(sheet).read(root)
    sheet.steps = sorted(set(sheet.steps))
    sheet.n = sheet.steps[-1] if sheet.steps else 0
    current = [k for k, s in sheet.file_states.items() if s == "cur"]
    sheet.frame = current[0] if len(current) == 1 else None
    sheet.views = read_views(root, data)
    sheet.moves = read_moves(css, sheet.moved_leaders)
    camera_layer = any(local_name(e.tag) == "g" and e.get("id") == "views" for e in root)
    sheet.player = bool(sheet.views) and (bool(data) or camera_layer)
    sheet.unplayed = camera_layer and not data
    sheet.end = END in root.get("class", "").split()
    if data:
        if isinstance(data.get("steps"), list):
            sheet.n = max(sheet.n, len(data["steps"]))  # a last step that draws nothing is still a view
        levels = data.get("levels")
        if isinstance(levels, list) and levels and all(isinstance(z, (int, float)) and z > 0 for z in levels):
            sheet.levels = tuple(float(z) for z in levels)
        groups = data.get("groups") if isinstance(data.get("groups"), list) else []
        for k, st in enumerate(data.get("steps") or (), start=1):
            if isinstance(st, dict) and isinstance(st.get("i"), list):
                sheet.inputs[k] = tuple(int(i) for i in st["i"] if isinstance(i, int))
            if isinstance(st, dict):
                g = st.get("g")
                group = groups[g] if isinstance(g, int) and 0 <= g < len(groups) else ""
                sheet.captions[k] = tuple(str(t) for t in (st.get("de", ""), st.get("en", ""), group))
            r = st.get("r") if isinstance(st, dict) else None
            if isinstance(r, list) and len(r) == 3 and all(isinstance(v, (int, float)) for v in r):
                sheet.rings[k] = (float(r[0]), float(r[1]), float(r[2]))
    _own_points(sheet)
    return sheet


def _own_points(sheet: Sheet) -> None:
    """A letter group without a named owner (a name tag) names the point it is drawn about."""
    at: dict[tuple[float, float], str] = {}
    for d in sheet.dots:
        if d.ident:
            at.setdefault((round(d.x, 1), round(d.y, 1)), d.ident)
    for i, t in enumerate(sheet.texts):
        if t.owner is None and t.anchor is not None:
            owner = at.get((round(t.anchor[0], 1), round(t.anchor[1], 1)))
            if owner:
                sheet.texts[i] = replace(t, owner=owner)


def _marks_steps(cascade: Cascade) -> bool:
    """Does the style sheet mark the current step's marks (a rule for ``.cur>*``, ``.cur>.pt``, a ring)?

    Rules for the current step's letters alone (every style keeps their halo) do not count:
    a plate, which is never stepped through, has them too.
    """
    text_only = {"lb", "halo", "leader", "tag"}
    return any(any("cur" in part[1][2] for part in rule.parts) and not set(rule.parts[-1][1][2]) & text_only
               for rule in cascade.rules)


class _Reader:
    def __init__(self, sheet: Sheet):
        self.sheet = sheet
        self.halos: dict[tuple, float] = {}
        self.pending: list[tuple] = []
        self.groups = 0  # letter groups met so far

    def read(self, root: ET.Element) -> None:
        self._walk(root, (), IDENTITY, None)
        # the labels last: their halos (drawn before them) are known by then
        for args in self.pending:
            self._text(*args)

    def _node(self, e: ET.Element, tag: str, step: int | None) -> Node:
        c = self.sheet.cascade
        own: list[tuple[str, str]] = []
        attrib = e.attrib
        if not _PROPERTY_SET.isdisjoint(attrib):  # most elements carry none: their classes say it
            for name in PROPERTIES:
                if attrib.get(name) is not None:
                    own.append(("@" + name, attrib[name]))
        style = attrib.get("style")
        if style:
            own.extend(declarations(style).items())
        if step is not None and e.get("data-step") is not None:
            own.append(_STEP_GROUP)  # the same for every step: elements that look alike share their chains
        ident = e.get("id")
        classes = frozenset(e.get("class", "").split())
        return (tag, ident if ident in c.ids else None, classes, tuple(own))

    def _walk(self, e: ET.Element, chain: tuple[Node, ...], ctm: Matrix, step: int | None,
              group: tuple | None = None) -> None:
        tag = local_name(e.tag)
        if not tag or tag in _NOT_DRAWN or e.get("id") in _SKIPPED_IDS or e.get("id") == "views":
            return
        sheet = self.sheet
        raw_step = e.get("data-step")
        if raw_step is not None and raw_step.strip().isdigit() and tag == "g":
            step = int(raw_step)
            sheet.steps.append(step)
            classes = set(e.get("class", "").split())
            states = classes & set(STATES)
            sheet.file_states.setdefault(step, next(iter(sorted(states)), ""))
            fade = e.get("data-fade")
            if fade is not None and fade.strip().isdigit():
                sheet.fades[step] = int(fade)
        if e.get("transform"):
            try:
                ctm = compose(ctm, parse_transform(e.get("transform")))
            except ConstructError:
                pass  # a transform lint cannot read: the element is taken where it stands
        chain = chain + (self._node(e, tag, step),)
        if tag in ("svg", "g", "a", "switch"):
            if tag == "g" and "lbg" in chain[-1][2]:
                # a letter about its point: the player scales (and a zoom level moves) its children about it
                group = (transform_point(ctm, 0.0, 0.0), e.get("id"), math.sqrt(abs(ctm[0] * ctm[3] - ctm[1] * ctm[2])),
                         self.groups)
                self.groups += 1
            for child in e:
                self._walk(child, chain, ctm, step, group)
            return
        classes = chain[-1][2]
        if tag == "text":
            if "halo" in classes:
                look = sheet.look(chain)
                self.halos[(_text_of(e), e.get("x"), e.get("y"), e.get("transform"))] = look.stroke_width / 2
            else:
                self.pending.append((e, chain, ctm, step, group))
            return
        if tag not in _DRAWN:
            return
        if tag == "line" and "leader" in classes and group is not None:
            anchor, gid, unit, serial = group
            line = tuple(number(e.get(a)) for a in ("x1", "y1", "x2", "y2"))
            sheet.leaders.append(Leader(e.get("id"), step, chain, anchor, line, gid, unit, serial))  # type: ignore[arg-type]
        if tag == "circle" and ("pt" in classes or ("result" not in classes and not sheet.plate)):
            # a point marker or a thin circle: its centre and radius are all that is read (its box is exact)
            lines = pts = []
        else:
            where = f"{sheet.name}: <{tag} {e.get('id') or ''}>"
            try:
                lines = polylines(tag, e, where)
            except ConstructError as exc:
                raise LintInputError(str(exc)) from None
            lines = transform_lines(ctm, lines)
            pts = [p for line in lines for p in line]
            if not pts:
                return
        scale = math.sqrt(abs(ctm[0] * ctm[3] - ctm[1] * ctm[2]))
        if not (tag == "rect" and (e.get("id") == "background" or "view" in classes)):
            if tag == "circle":
                cx, cy = transform_point(ctm, number(e.get("cx")), number(e.get("cy")))
                r = number(e.get("r")) * scale
                ink = (cx - r, cy - r, cx + r, cy + r)
            else:
                ink = box_of(pts)
            sheet.inked.append((chain, ink))
        if tag == "circle" and "pt" in classes:
            look = sheet.look(chain)
            cx, cy = transform_point(ctm, number(e.get("cx")), number(e.get("cy")))
            r = number(e.get("r")) * scale + (look.stroke_width * scale / 2 if look.stroked else 0.0)
            sheet.dots.append(Dot(e.get("id"), step, chain, cx, cy, r))
        elif "result" in classes:
            look = sheet.look(chain)
            if look.stroked:
                sheet.strokes.append(Stroke(e.get("id"), step, chain, tuple(cut_pieces(lines)),
                                            look.stroke_width * scale / 2))
        if sheet.plate and not (tag == "circle" and "pt" in classes) and not classes & {"halo", "brk"}:
            look = sheet.look(chain)
            if look.stroked and look.shown and look.opacity > 0:
                sheet.lines.append(Line(e.get("id"), chain, tuple(cut_pieces(lines)), look.stroke_width * scale / 2))
        if step is not None and not classes & {"leader", "halo", "brk", "brkline"}:
            if tag == "circle":  # exact: the flattened outline's corners fall inside the circle
                cx, cy = transform_point(ctm, number(e.get("cx")), number(e.get("cy")))
                r = number(e.get("r")) * scale
                box = (cx - r, cy - r, cx + r, cy + r)
            else:
                box = box_of(pts)
            sheet.drawn.append(Drawn(step, e.get("id"), chain, box))

    def _text(self, e: ET.Element, chain: tuple[Node, ...], ctm: Matrix, step: int | None,
              group: tuple | None = None) -> None:
        sheet = self.sheet
        text = _text_of(e)
        if not text.strip():
            return
        classes = chain[-1][2]
        kind = "caption" if "cap" in classes else ("tag" if "tag" in classes else "label")
        look = sheet.look(chain)
        (ix0, iy0, ix1, iy1), advance = text_extents(text, look.font_family, round(look.font_size, 3),
                                                      look.font_style, look.font_weight)
        x, y = number(e.get("x")) + number(e.get("dx")), number(e.get("y")) + number(e.get("dy"))
        shift = {"middle": -advance / 2, "end": -advance}.get(look.text_anchor, 0.0)
        margin = self.halos.get((text, e.get("x"), e.get("y"), e.get("transform")), MIN_MARGIN)
        margin = max(margin, MIN_MARGIN)
        corners = [transform_point(ctm, x + shift + a, y + b) for a in (ix0 - margin, ix1 + margin)
                   for b in (iy0 - margin, iy1 + margin)]
        ink = (x + shift + ix0, y + iy0, x + shift + ix1, y + iy1)
        ident = e.get("id")
        owner = None
        if ident:
            for suffix in ("-label", "-tag"):
                if ident.endswith(suffix):
                    owner = ident[: -len(suffix)]
        scale = math.sqrt(abs(ctm[0] * ctm[3] - ctm[1] * ctm[2]))
        anchor, gid, unit, serial = group if group is not None else (None, None, 1.0, None)
        sheet.texts.append(Text(len(sheet.texts), text, kind, ident, owner, step, chain, box_of(corners),
                                look.font_size * scale, anchor, gid, unit, serial, ink, ctm))


def _text_of(e: ET.Element) -> str:
    return " ".join("".join(e.itertext()).split())
