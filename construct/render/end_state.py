"""The end state of a teaching sequence on its own sheet: its view, its letters' size, its furniture, its file.

A teaching scene with an end state (:meth:`construct.render.scene.Scene.in_end`) ends with the figure as the
book draws it.  Here is how that last step is laid out (:func:`lay_out_end`: the last step's view grown to take
the end state's letters and the plate's furniture, :class:`EndView`), the plate's furniture drawn in it
(:func:`end_furniture`), and the layered figure written on the end state's sheet (:func:`end_sheet`) -- with
the player's letter scale and the lines' widths written out as numbers (:func:`own_strokes`), for renderers
without CSS variables or ``vector-effect``.  :class:`construct.render.svg.Drawing` calls these; marks become
SVG elements there.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> from construct.render.styles import TEACHING
>>> from construct.render.svg import Drawing
>>> d = Drawing(build_scene(get("crank").figure(parts=6), ending=True), TEACHING)
>>> isinstance(d.end, EndView) and d.end.view == d.views[-1]
True
>>> x0, y0, x1, y1 = d.end.crop
>>> d.layered().count('class="fin zl') == 1 and x1 > x0 and y1 > y0
True
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from typing import Any, Callable, Sequence

from .camera import FINAL_CONTEXT, NON_SCALING, PLAYER_FIGURE_PX, ZOOM_LEVELS, Framing, level, player_letter_scale, zoom_of
from .captions import Captions
from .lettering import LEADER_FROM, label_box, text_width
from .placing import Placing
from .plate import Dot, Lettering, ScaleBar, Stroke, extent, furniture_elements, plain, text_elements
from .scene import Scene, extreme_points
from .styles import Style
from .svgdoc import Element, Writer, fmt, with_attribute
from .viewport import Viewport

__all__ = ["EndView", "END_MARGIN_PX", "lay_out_end", "end_fixed", "end_lettering", "end_lettering_at",
           "end_furniture", "fixed_elements", "end_sheet", "own_strokes", "wrapped", "NumbersFactory",
           "furniture_numbers", "lettering_box", "end_letter_boxes"]

#: The margin round the end state's drawing on its sheet (screen px at the end view).
END_MARGIN_PX = 14.0

#: The player's letter scale in a style rule (``var(--ls)``, ``var(--ls,var(--zs,1))``), which the end state's own
#: file writes out as its number.
_LETTER_SCALE = re.compile(r"var\(--ls(?:,var\(--zs(?:,1)?\))?\)")

#: The end state's points scaled by the letter scale (:data:`construct.render.styles.END_CSS`); its own file draws
#: them at that scale in their radius instead.
_END_POINTS = ".fin .lbg>.lb,.fin .lbg>.leader,.fin .pt{"
_END_POINTS_OWN = ".fin .pt{transform:none}\n.fin .lbg>.lb,.fin .lbg>.leader{"

#: A style rule and the lengths of a line's stroke in it (its width, its dashes).
_RULE = re.compile(r"([^{}]+)\{([^{}]*)\}")
_STROKE_LENGTHS = re.compile(r"(stroke-width|stroke-dasharray):([^;}]*)")
#: What draws its own strokes at the figure's scale in the player too (no ``vector-effect`` on them, see
#: :func:`construct.render.camera.level_css`): letters, their halos and leaders, points, insets, break lines.
_SCALED_STROKES = frozenset({"lb", "halo", "leader", "pt", "inset", "brkline"})


def own_strokes(css: str, q: float) -> str:
    """*css* with the lines' stroke widths and dashes written in the file's own units for its one view of *q*
    units per screen px, instead of held at their screen size by ``vector-effect: non-scaling-stroke``
    (which cairosvg, Inkscape's import and print workflows ignore, drawing every line 1/q times too heavy).

    >>> own_strokes(".result{stroke-width:2}\\n.dashdot{stroke-dasharray:14 3;stroke-width:0.7px}\\n"
    ...             ".leader{stroke-width:0.4px}\\n" + NON_SCALING, 0.5)
    '.result{stroke-width:1}\\n.dashdot{stroke-dasharray:7 1.5;stroke-width:0.35}\\n.leader{stroke-width:0.4px}\\n'
    """
    def lengths(m: re.Match) -> str:
        return m.group(1) + ":" + " ".join(fmt(float(v.removesuffix("px")) * q, 4)
                                           for v in m.group(2).replace(",", " ").split())

    def rule(m: re.Match) -> str:
        classes = set(re.findall(r"\.([\w-]+)", m.group(1)))
        if classes & _SCALED_STROKES:
            return m.group(0)
        return m.group(1) + "{" + _STROKE_LENGTHS.sub(lengths, m.group(2)) + "}"

    return _RULE.sub(rule, css.replace(NON_SCALING, ""))


@dataclass(frozen=True)
class EndView:
    """How the end state of a teaching sequence is shown (:meth:`construct.render.svg.Drawing.layered`, the
    player's last step).

    *view*: the last step's camera view (canvas px, x y w h); *level*: its zoom level; *letter*: the
    player's letter scale there (canvas units a letter unit); *scale*: screen px per canvas px there;
    *crop*: the end state's drawing with its letters, furniture and a margin (canvas px, x0 y0 x1 y1), the
    sheet of ``final.svg``; *size*: the furniture's letter size (canvas px).
    """

    view: tuple[float, float, float, float]
    level: int
    letter: float
    scale: float
    crop: tuple[float, float, float, float]
    size: float


def wrapped(g: Any, elems: Sequence[Any]) -> Any:
    """The group *g* holding *elems*."""
    for e in elems:
        g.add(e)
    return g


def _grown(box: tuple[float, float, float, float] | None,
           pts: Sequence[tuple[float, float]]) -> tuple[float, float, float, float] | None:
    for x, y in pts:
        box = (x, y, x, y) if box is None else (min(box[0], x), min(box[1], y), max(box[2], x), max(box[3], y))
    return box


def end_fixed(scene: Scene) -> tuple:
    """The end state's furniture that stands where the plate sets it (all but its lettering)."""
    return tuple(it for it in scene.end_furniture if not isinstance(it, Lettering))


def end_lettering(scene: Scene, vp: Viewport, style: Style,
                  size: float) -> list[tuple[str, tuple[float, float], str]]:
    """The plate's lettering in the end state, placed as letters are (:meth:`Placing.place_end`): (id, the
    middle of where the plate writes it, canvas px, its text)."""
    out = []
    for i, it in enumerate(scene.end_furniture):
        if isinstance(it, Lettering):
            x, y = vp.px(*it.at)
            text = plain(it.text)  # as a reader sees it (P_b: Pb, its b a smaller run)
            w = text_width(text, size * it.size, style.label_font, style.label_italic)
            x += {"start": w / 2, "end": -w / 2}.get(it.anchor, 0.0)
            out.append((f"fur{i}", (x, y), text))
    return out


def lettering_box(elem: Any, size: float, style: Style) -> tuple[float, float, float, float] | None:
    """The box (canvas px) of a furniture lettering element made at *size* (not turned; its halo, a copy
    beneath it, and any other element: None)."""
    tag, get, text = _written(elem)
    if tag != "text" or "halo" in get("class", "").split():
        return None
    got = re.search(r"font-size:\s*([\d.]+)px", get("style", ""))
    size = float(got.group(1)) if got else size
    text = text or ""
    # (a live sweep's raw numbers, NumbersFactory's, may be written as one-element arrays: "[796.56]")
    x, y = (float(_NUMBER.search(get(a)).group()) for a in ("x", "y"))
    w = text_width(text, size, style.label_font, style.label_italic)
    x += {"start": w / 2, "end": -w / 2}.get(get("text-anchor", "middle"), 0.0)
    return label_box(x, y, text, size, style.label_font, style.label_italic)


def _written(elem: Any) -> tuple[str, Any, str | None]:
    """The tag, a reader of the attributes (``get(name, default=None)``) and the text of *elem* as its ElementTree
    element (``get_xml()``) has them: a plain :class:`~construct.render.svgdoc.Element` read as that would write
    it (each attribute ``str()``-ed, the empty and None ones left out) without making it -- the live sweep boxes
    the plate's lettering at every value of a given (Tafel 2: 14,000 elements)."""
    if isinstance(elem, Element) and type(elem).get_xml is Element.get_xml:
        attribs = elem.attribs

        def get(name: str, default: Any = None) -> Any:
            v = attribs.get(name)
            return (str(v) or default) if v is not None else default

        return elem.elementname, get, None if elem.text is None else str(elem.text)
    xml = elem.get_xml()
    return xml.tag.rsplit("}", 1)[-1], xml.get, xml.text


def end_letter_boxes(scene: Scene, style: Style, vp: Viewport, placing: Placing, end: EndView,
                     factory: Any) -> list[tuple[str, str, tuple[float, float], tuple[float, float, float, float]]]:
    """The letters the end state writes, as :func:`lay_out_end` boxed them in its view: (the id of the element
    the page draws it with or beside -- its point's, or its own text's --, that element's attribute of x (``cx``,
    ``x``), the element's (x, y) there, the letter's box: canvas px).  The points' letters where the placing set
    them; the plate's lettering where it set it (its first element: :func:`end_furniture`); the texts of the rest
    of the furniture (a scale's, a dimension's) where the plate sets them."""
    st, ls, size = style, end.letter, end.size
    out = []
    for m in scene.end_drawn():
        rel = placing.end_spots.get(m.id)
        if rel is not None and m.label:
            px, py = vp.px(*m.geom)
            out.append((m.id, "cx", (px, py), label_box(px + ls * rel[0], py + ls * rel[1], m.label, size,
                                                        st.label_font, st.label_italic)))
    k, items = 0, scene.end_furniture
    for it in items:  # (the ids as end_furniture gives them: the fixed furniture first, item by item)
        if isinstance(it, Lettering):
            continue
        for j, e in enumerate(furniture_elements([it], vp.px, vp.scale, factory, size=size)):
            b = lettering_box(e, size, st)
            if b is not None:
                xml = e.get_xml()
                out.append((f"fin-{'s' if j == 0 and isinstance(it, Stroke) else 'f'}{k}", "x",
                            (float(xml.get("x")), float(xml.get("y"))), b))
            k += 1
    for (fid, (px, py), text), i in zip(end_lettering(scene, vp, st, size),
                                       [i for i, it in enumerate(items) if isinstance(it, Lettering)]):
        rel = placing.end_spots.get(fid)
        if rel is None:
            continue
        k += rel[2] >= LEADER_FROM  # (its leader)
        x, y = px + ls * rel[0], py + ls * rel[1]
        els = text_elements(factory, (x, y - 0.35 * size * items[i].size), items[i].text, size, rel=items[i].size)
        xml = els[0].get_xml()
        out.append((f"fin-f{k}", "x", (float(xml.get("x")), float(xml.get("y"))),
                    label_box(x, y, text, size, st.label_font, st.label_italic)))
        k += len(els)
    return out


def lay_out_end(scene: Scene, style: Style, vp: Viewport, placing: Placing, views: list, full: tuple,
                factory: Any) -> EndView:
    """The end state's letters, view and sheet (:class:`EndView`): its letters placed (by *placing*) at the
    player's letter scale in the last step's view, the view grown to take them and the furniture in (the last
    of *views* replaced by it), the sheet the end state's drawing with a margin of :data:`END_MARGIN_PX`.
    *full*: the whole drawing as a view; *factory*: the svgwrite element factory."""
    sc, st, pl = scene, style, placing
    marks = sc.end_drawn()
    v = views[-1]
    framing = Framing(full, max_zoom=ZOOM_LEVELS[-1])
    for _ in range(4):  # the letters and the furniture widen the view, which sets their size
        z = zoom_of(v, full)
        lvl = level(z)
        q = max(v[2] / PLAYER_FIGURE_PX[0], v[3] / PLAYER_FIGURE_PX[1])  # canvas px per screen px
        ls = player_letter_scale(q * z / ZOOM_LEVELS[lvl])
        size = st.label_size * ls
        texts = [b for e in furniture_elements(end_fixed(sc), vp.px, vp.scale, factory, size=size)
                 if (b := lettering_box(e, size, st)) is not None]
        lettering = end_lettering(sc, vp, st, size)
        pl.place_end(ls, marks, texts, lettering, _result_strokes(sc, vp))
        box = None
        for m in marks:
            if sc.end_shows(m):
                box = _grown(box, [vp.px(*p) for p in extreme_points(m)])
        fx = extent(sc.end_furniture)
        if fx is not None:
            box = _grown(box, [vp.px(fx[0], fx[1]), vp.px(fx[2], fx[3])])
        for b in texts:
            box = _grown(box, [b[:2], b[2:]])
        for fid, (px, py), text in lettering:
            rel = pl.end_spots.get(fid)
            if rel is not None:
                b = label_box(px + ls * rel[0], py + ls * rel[1], text, size, st.label_font, st.label_italic)
                box = _grown(box, [b[:2], b[2:]])
        for m in marks:
            rel = pl.end_spots.get(m.id)
            if rel is not None:
                px, py = vp.px(*m.geom)
                b = label_box(px + ls * rel[0], py + ls * rel[1], m.label or "", size, st.label_font,
                              st.label_italic)
                box = _grown(box, [b[:2], b[2:]])
        if box is None:
            break
        new = framing.view(box, FINAL_CONTEXT, 1.0)
        if new == v:
            break
        v = new
    views[-1] = v
    pad = END_MARGIN_PX * q
    crop = (box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad) if box is not None else \
        (full[0], full[1], full[0] + full[2], full[1] + full[3])
    return EndView(v, lvl, round(ls, 4), round(1.0 / q, 6), tuple(round(c, 2) for c in crop), size)


def _result_strokes(scene: Any, vp: Any) -> list[tuple[float, float, float, float]]:
    """The plate's own lines that are results (its ordinates), not its thin and dashed helpers (canvas px)."""
    return [(*vp.px(*it.a), *vp.px(*it.b)) for it in scene.end_furniture
            if isinstance(it, Stroke) and not {"thin", "dashed", "hidden"} & set(it.look.split())]


def end_lettering_at(sheet: Any, marks: "Sequence[Any] | Callable[[], Sequence[Any]]", style: Style, vp: Any,
                     end: EndView, placing: Placing, factory: Any,
                     keep: dict[str, tuple[float, float, float]] | None = None,
                     fixed: list[list[Any]] | None = None,
                     lettering: list[tuple[str, tuple[float, float], str]] | None = None,
                     lettered: Sequence[Any] | None = None) -> dict[str, tuple[float, float, float]]:
    """Where the plate's lettering of *sheet* (anything with ``end_furniture``: the plate at another value of a live
    given, in the built plate's form) stands about its places at that value, as :func:`lay_out_end` places it
    (:meth:`~construct.render.placing.Placing.end_lettering_at`: among that value's end-state *marks* on *vp*):
    {id: (dx, dy, distance)}, as ``placing.end_spots``.  A letter with no room there, or one that would take a
    leader where the built one has none (or lose its leader), keeps its built spot: the furniture keeps its form
    over the sweep (its elements, by which the page knows them).  *keep*: spots of this form (a neighbouring
    value's), kept as they are where they crowd there no more than those placed anew
    (:meth:`~construct.render.placing.Placing.end_crowd`: a letter that has no room there crowds either way).
    *fixed*: the elements of the rest of the furniture (:func:`fixed_elements`), *lettering*: :func:`end_lettering`
    at the end state's size, if the caller made them.  *marks* may be a function that makes them and *lettered*
    those of them that are lettered, in their order (:meth:`~construct.render.placing.Placing.end_lettering_at`:
    the rest are made only where a letter is placed anew).
    """
    fixed = fixed_elements(sheet, vp, end, factory) if fixed is None else fixed
    texts = [b for els in fixed for e in els if (b := lettering_box(e, end.size, style)) is not None]
    lettering = end_lettering(sheet, vp, style, end.size) if lettering is None else lettering
    if lettered is None:
        marks = lettered = marks() if callable(marks) else marks
    crowd = placing.end_crowd(vp, end.letter, lettered, texts, lettering, keep) if keep is not None else set()
    if keep is not None and not crowd:
        return keep
    got = placing.end_lettering_at(vp, end.letter, marks, texts, lettering, _result_strokes(sheet, vp), lettered)
    built = placing.end_spots
    got = {**built, **{f: rel for f, rel in got.items()
                       if f in built and (rel[2] >= LEADER_FROM) == (built[f][2] >= LEADER_FROM)}} if got else built
    if keep is not None and len(placing.end_crowd(vp, end.letter, lettered, texts, lettering, got)) >= len(crowd):
        return keep
    return got


def fixed_elements(sheet: Any, vp: Any, end: EndView, factory: Any) -> list[list[Any]]:
    """The elements of the end state's furniture of *sheet* that stands where the plate sets it (:func:`end_fixed`:
    all but its lettering), item by item, made by *factory* on *vp* at the end state's letter size: what
    :func:`end_lettering_at` boxes the lettering among and :func:`end_furniture` draws (a live sweep makes them
    once a value for both)."""
    return [furniture_elements([it], vp.px, vp.scale, factory, size=end.size) for it in end_fixed(sheet)]


def end_furniture(scene: Scene, style: Style, vp: Viewport, end: EndView, placing: Placing, factory: Any,
                  owners: dict[str, int] | None = None,
                  spots: dict[str, tuple[float, float, float]] | None = None,
                  fixed: list[list[Any]] | None = None,
                  lettering: list[tuple[str, tuple[float, float], str]] | None = None) -> Any:
    """The plate's furniture in the end state (``<g class="fo end">``), its letters at the size of the end
    state's, its lettering where the end state's placing set it (upright; tied to its place by a leader when
    set off).  Each of its elements has an id in the order drawn (``fin-s<k>``: the line of a stroke the plate
    adds, which a broken axis breaks; ``fin-f<k>`` the rest): the live page moves them with the given
    (:func:`furniture_numbers`).  *owners*, if given, gets each element's item: {its id: the item's index in
    ``scene.end_furniture``}.  *spots*: where the lettering stands about its places (``placing.end_spots`` without;
    another value of a live given's: :func:`end_lettering_at`).  *fixed*: the elements of the furniture but its
    lettering (:func:`fixed_elements`, made by *factory* on *vp*), if the caller made them (they are given ids);
    *lettering*: :func:`end_lettering` at the end state's size, if the caller made it."""
    f = factory
    spots = placing.end_spots if spots is None else spots
    g = f.g(class_="fo end")
    owners = {} if owners is None else owners
    k = 0
    made = iter(fixed) if fixed is not None else None
    for i, it in enumerate(scene.end_furniture):
        if isinstance(it, Lettering):  # (below: where the placing set it)
            continue
        for j, e in enumerate(next(made) if made is not None else furniture_elements([it], vp.px, vp.scale, f,
                                                                                      size=end.size)):
            e["id"] = f"fin-{'s' if j == 0 and isinstance(it, Stroke) else 'f'}{k}"
            owners[e["id"]] = i
            if _at_letter_size(it, j):
                e["class"] = e["class"] + " sc"
            k += 1
            g.add(e)
    ls = end.letter
    lettering = end_lettering(scene, vp, style, end.size) if lettering is None else lettering
    for (fid, (px, py), text), i in zip(lettering,
                                       [i for i, it in enumerate(scene.end_furniture) if isinstance(it, Lettering)]):
        rel = spots.get(fid)
        if rel is None:
            continue
        it = scene.end_furniture[i]
        x, y = px + ls * rel[0], py + ls * rel[1]
        if rel[2] >= LEADER_FROM:
            x1, y1, x2, y2 = placing.leader_line(rel[0], rel[1], text)
            g.add(f.line(start=(fmt(px + ls * x1), fmt(py + ls * y1)), end=(fmt(px + ls * x2), fmt(py + ls * y2)),
                         class_="fur thin", id=f"fin-f{k}"))
            owners[f"fin-f{k}"] = i
            k += 1
        # (its index set below the line as the plate sets it: P_b, F·p_ü)
        for el in text_elements(f, (x, y - 0.35 * end.size * it.size), it.text, end.size, rel=it.size):
            el["id"] = f"fin-f{k}"
            owners[el["id"]] = i
            k += 1
            g.add(el)
    return g


def _at_letter_size(item: Any, j: int) -> bool:
    """Whether element *j* of the furniture *item* is drawn at the letters' size about its own middle (a scale's
    end ticks, a broken stroke's zig-zag, a dot): class ``sc``, which the player scales about its middle by its
    letter scale over the end state's (:mod:`construct.render.player`), as it scales the plate's upright lettering.
    (An arrowhead, drawn about its tip, and a turned text, about its turn, the player finds by their form.)

    >>> _at_letter_size(ScaleBar((0, 0), (1, 0), "1 at"), 1), _at_letter_size(ScaleBar((0, 0), (1, 0), "1 at"), 0)
    (True, False)
    """
    return (isinstance(item, ScaleBar) and j in (1, 2)) or (isinstance(item, Stroke) and j == 1) or isinstance(item, Dot)


class _Text(Element):
    """A text element as :class:`NumbersFactory` records it: its attributes and its text."""

    __slots__ = ("text",)


class NumbersFactory:
    """Takes the place of the SVG writer's element factory where only the elements' numbers and texts are wanted
    (:func:`furniture_numbers`: the live sweep's end state, value by value): each element a plain
    :class:`~construct.render.svgdoc.Element` with the attributes the writer writes, its numbers as they are
    (``raw``: :mod:`construct.render.plate` hands them over unwritten; :func:`furniture_numbers` rounds them as
    the writer writes them, two decimals)."""

    raw = True

    def g(self, **kw: Any) -> Element:
        return Element("g", **kw)

    def line(self, start: tuple, end: tuple, **kw: Any) -> Element:
        return Element("line", x1=start[0], y1=start[1], x2=end[0], y2=end[1], **kw)

    def circle(self, center: tuple, r: Any, **kw: Any) -> Element:
        return Element("circle", cx=center[0], cy=center[1], r=r, **kw)

    def path(self, **kw: Any) -> Element:
        return Element("path", **kw)

    def text(self, text: str, **kw: Any) -> _Text:
        e = _Text("text", **kw)
        e.text = text
        return e

    tspan = text


#: The attributes of the end state's furniture that carry its numbers, in the order the live data keys them.
_NUMBERED = ("x1", "y1", "x2", "y2", "cx", "cy", "r", "x", "y", "d", "transform")


@functools.lru_cache(maxsize=256)
def _numbered(names: tuple[str, ...]) -> tuple[str, ...]:
    """Those of the attributes *names* (an element's) that carry numbers (:data:`_NUMBERED`), in its order: an element's
    attributes are asked once for each set of them (the plate's elements come in a handful: a line, a text, ...).

    >>> _numbered(("class", "y", "x", "id"))
    ('x', 'y')
    """
    return tuple(a for a in _NUMBERED if a in names)
_NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def furniture_numbers(group: Element, *, exact: bool = True) -> tuple[list[tuple[str, str, str]], list[float],
                                                                      dict[str, str]]:
    """The numbers of the end state's furniture as :func:`end_furniture` drew it with a :class:`NumbersFactory`:
    (keys (id, attribute, its text with each number a ``#``), the numbers, {id: text} of its letterings), in the
    live data's form (:mod:`construct.live.measure`).  *exact* False: the numbers handed over as they are left
    unrounded (a sweep rounds all its values' at once).

    >>> f = NumbersFactory()
    >>> g = f.g(); e = g.add(f.line(start=("1", "2"), end=("3", "4.5"), id="fin-s0"))
    >>> t = g.add(f.text("L = 5 r", x=["7"], y=["8"], transform="rotate(-20 7 8)", id="fin-f1"))
    >>> furniture_numbers(g)
    ([('fin-s0', 'x1', '#'), ('fin-s0', 'y1', '#'), ('fin-s0', 'x2', '#'), ('fin-s0', 'y2', '#'), ('fin-f1', 'x', '#'), ('fin-f1', 'y', '#'), ('fin-f1', 'transform', 'rotate(# # #)')], [1.0, 2.0, 3.0, 4.5, 7.0, 8.0, -20.0, 7.0, 8.0], {'fin-f1': 'L = 5 r'})
    """
    keys, nums, texts = [], [], {}
    r2 = (lambda v: round(v, 2) + 0.0) if exact else (lambda v: v)  # noqa: E731
    for e in group.elements:
        attribs = e.attribs
        ident = attribs.get("id")
        if ident is None:
            continue
        for a in _numbered(tuple(attribs)):
            v = attribs[a]
            if v is None:
                continue
            if isinstance(v, list) and len(v) == 1:  # (x=[...], as the writer takes it)
                v = v[0]
            if isinstance(v, float):  # a number as it is: written with two decimals
                keys.append((ident, a, "#"))
                nums.append(r2(v))
                continue
            if isinstance(v, tuple) and v and v[0] == "poly":  # a path's points (plate._poly)
                keys.append((ident, a, "M" + "L".join(["# #"] * len(v[1])) + ("Z" if v[2] else "")))
                nums.extend(r2(c) for p in v[1] for c in p)
                continue
            if isinstance(v, tuple) and v and v[0] == "rotate":  # a turned text (plate._text)
                keys.append((ident, a, "rotate(# # #)"))
                nums.extend(r2(c) for c in v[1:])
                continue
            v = " ".join(map(str, v)) if isinstance(v, (list, tuple)) else str(v)
            ns = _NUMBER.findall(v)
            keys.append((ident, a, _NUMBER.sub("#", v)))
            nums.extend(float(x) for x in ns)
        if isinstance(e, _Text):
            texts[ident] = e.text + "".join(getattr(t, "text", "") for t in e.elements)
    return keys, nums, texts


def end_sheet(doc: Writer, end: EndView, scene: Scene, style: Style, css: str, body: Sequence[Any],
              caption: Sequence[str] | None) -> str:
    """The layered figure (*body*, its layers; *css*: the style sheet) on the end state's sheet: the end
    state's drawing shown at the player's screen scale of its view (letters at their size), the caption set
    beneath it at the screen's size."""
    e, st = end, style
    x0, y0, x1, y1 = e.crop
    s = e.scale
    w = (x1 - x0) * s
    m = st.margin_px
    lines = Captions(scene, width=max(w - 2 * m, 240.0), size=st.caption_size).title_lines(caption) \
        if st.show_caption else []
    step = 1.45 * st.caption_size
    foot = (len(lines) * step + 0.6 * m) if lines else 0.0
    h = (y1 - y0) * s + foot
    f = doc.factory
    # the letter scale written out: every letter inherits the root's --ls here, and a renderer without CSS
    # variables (cairosvg, Inkscape's import) would drop each element scaled by var() -- letters and points
    css = _LETTER_SCALE.sub(fmt(e.letter, 4), css).replace(_END_POINTS, _END_POINTS_OWN)
    # and its lines as wide as the player draws them on this view, in the sheet's own units (see own_strokes)
    css = own_strokes(css, 1 / s)
    dwg = doc.drawing(size=(fmt(w), fmt(h)), viewBox=f"{fmt(x0)} {fmt(y0)} {fmt(x1 - x0)} {fmt(h / s)}",
                      class_=f"fin zl{e.level}", style=f"--ls:{fmt(e.letter, 4)}")
    dwg.add(f.style("\n" + css + "\n"))
    dwg.add(f.rect(insert=("-10000", "-10000"), size=("20000", "20000"), id="background", fill=st.background))
    for el in body:
        dwg.add(el)
    if lines:
        g = f.g(id="caption", transform=f"translate({fmt(x0)} {fmt(y1)}) scale({fmt(1 / s, 6)})")
        for i, (kind, text) in enumerate(lines):
            g.add(f.text(text, x=[fmt(m)], y=[fmt(st.caption_size + i * step)],
                         class_=f"cap{(' ' + kind) if kind else ''}"))
        dwg.add(g)
    # (and a point's marker at that scale in its radius: such a renderer scales about the origin, not the
    # marker's centre) -- in the text written (the marks' elements are shared with the figure's other documents)
    return with_attribute(doc.text(dwg), "circle", "pt", "r", lambda r: fmt(float(r) * e.letter, 3))
