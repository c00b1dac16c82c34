"""An SVG document read into drawn shapes: ancestors' transforms applied, ``<use>`` expanded, styles resolved.

Part of :mod:`construct.regress.svgdiff`.  The module is over 600 lines because it is one walk of the tree:
its methods share the walk's state (the expansion budget, the counters, the definitions), and reading the
source safely, CSS, transforms and paths already live in their own modules.
"""

from __future__ import annotations

import functools
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import defusedxml

from . import values
from .values import (LENGTH_RE, UNITS, SvgFormatError, SvgTooLargeError, format_number, parse_numbers, show_value,
                     tokenise)
from .geometry import (IDENTITY, Matrix, Point, apply_matrix, arc_centre, determinant, ellipse_axes, multiply,
                       parse_path, parse_transform, scale_factor)
from .source import load_source, read_tree
from .css import (GROUP_EFFECTS, INITIAL, PRESENTATION, SCALED, CssRule, RuleIndex, normalise_colour, parse_css,
                  parse_declarations, style_value)

SVG_NS = "http://www.w3.org/2000/svg"
XLINK_NS = "http://www.w3.org/1999/xlink"


# --------------------------------------------------------------------------- drawn elements

@dataclass(frozen=True, slots=True)
class Shape:
    """One drawn element as geometry in absolute drawing units, with its effective style."""

    key: str
    tag: str
    kind: str
    points: tuple[tuple[str, Point], ...] = ()
    sizes: tuple[tuple[str, float], ...] = ()
    angles: tuple[tuple[str, float], ...] = ()
    structure: tuple[tuple[str, Any], ...] = ()
    text: str | None = None
    style: tuple[tuple[str, Any], ...] = ()
    animations: tuple[Any, ...] = ()
    described: tuple[tuple[str, str], ...] = ()
    has_id: bool = False
    order: int = 0
    #: The step whose group (``<g data-step="k">``, a layered figure) holds the element, else None.
    step: int | None = None

    def fingerprint(self, tol: float) -> tuple:
        """Hashable, tolerance-rounded form used to align equal anonymous elements."""
        q = max(tol, 1e-12)

        def r(v: Any) -> Any:
            if isinstance(v, float):
                return round(v / q)
            if isinstance(v, tuple):
                return tuple(r(x) for x in v)
            return v

        return (self.tag, self.kind, r(self.points), r(self.sizes), r(self.angles), self.structure, self.text,
                r(self.style), r(self.animations), self.described)


@dataclass(frozen=True, slots=True)
class Drawing:
    """A parsed SVG: document-level properties, definitions and drawn shapes in document order."""

    document: tuple[tuple[str, Any], ...]
    definitions: tuple[tuple[str, Any], ...]
    shapes: tuple[Shape, ...]


_NOT_DRAWN = {"defs", "symbol", "marker", "clipPath", "mask", "pattern", "linearGradient", "radialGradient",
              "filter", "style", "script", "metadata", "title", "desc", "foreignObject", "font", "font-face",
              "cursor", "view"}
_ANIMATIONS = {"animate", "set", "animateTransform", "animateMotion", "animateColor", "discard"}
_CONTAINERS = {"g", "a", "switch", "svg"}


@functools.lru_cache(maxsize=512)
def _local(tag: Any) -> tuple[str | None, str]:
    """(namespace, local name) of a tag; cached: a drawing repeats a few tags, read many times each."""
    if not isinstance(tag, str):
        return None, ""  # comments, processing instructions
    if tag.startswith("{"):
        ns, _, name = tag[1:].partition("}")
        return ns, name
    return None, tag


def _is_svg(elem: ET.Element) -> bool:
    return _svg_tag(elem.tag)


@functools.lru_cache(maxsize=512)
def _svg_tag(tag: Any) -> bool:
    """Whether *tag* is SVG's (or has no namespace); cached like :func:`_local`: asked of every element."""
    return _local(tag)[0] in (None, SVG_NS)


def _attrs(elem: ET.Element) -> dict[str, str]:
    """Attributes by local name: SVG's own and ``xlink:href``; other namespaces (editors') dropped."""
    attrib = elem.attrib
    if not any(name[:1] == "{" for name in attrib):
        return dict(attrib)  # no namespaced names (nearly every element): all are SVG's own
    out: dict[str, str] = {}
    for name, value in attrib.items():
        ns, local = _local(name)
        if ns is None or (ns == XLINK_NS and local == "href"):
            if (local == "href" and ns is None) or local not in out:  # plain href wins over xlink:href
                out[local] = value
    return out


def _canon(elem: ET.Element) -> tuple:
    """A definition (gradient, marker, symbol, ...) as tuples, numbers parsed.

    ``(tag, attributes, text, descendants)``, the descendants one flat row each
    ``(depth, tag, attributes, text)`` in document order: as deep as the
    definition is, the value stays two tuples deep, so comparing and hashing it
    never recurses on the document's depth.

    >>> _canon(ET.fromstring('<marker id="m"><g><circle r="2.0"/></g></marker>'))
    ('marker', (('id', ('m',)),), (), ((1, 'g', (), ()), (2, 'circle', (('r', (2.0,)),), ())))
    """
    def row(e: ET.Element) -> tuple:
        attrs = tuple(sorted((k, tokenise(v)) for k, v in _attrs(e).items()))
        text = " ".join((e.text or "").split())
        return _local(e.tag)[1], attrs, tokenise(text) if text else ()

    rows: list[tuple] = []
    stack = [(iter(elem), 1)]
    while stack:
        children, depth = stack[-1]
        child = next(children, None)
        if child is None:
            stack.pop()
        elif _is_svg(child) and _local(child.tag)[1]:
            rows.append((depth, *row(child)))
            stack.append((iter(child), depth + 1))
    return (*row(elem), tuple(rows))


def _plain_text(elem: ET.Element) -> str:
    return " ".join("".join(elem.itertext()).split())


def _text_content(elem: ET.Element) -> str:
    """Character data of a text element and its tspans, whitespace as xml:space="default" renders it.

    >>> _text_content(ET.fromstring('<text>K<tspan>ur<desc>no</desc>b</tspan>el</text>'))
    'Kurbel'
    """
    parts = [elem.text or ""]
    stack: list[tuple[Any, str]] = [(iter(elem), "")]  # children still to read, the text after them
    while stack:
        children, tail = stack[-1]
        child = next(children, None)
        if child is None:
            stack.pop()
            parts.append(tail)
        elif _is_svg(child) and _local(child.tag)[1] in ("tspan", "textPath", "a", "tref"):
            parts.append(child.text or "")
            stack.append((iter(child), child.tail or ""))
        else:
            parts.append(child.tail or "")
    return "".join(parts)


@dataclass(slots=True)
class _State:
    ctm: Matrix
    style: dict[str, str]
    viewport: tuple[float, float]
    step: int | None = None  # from the nearest ancestor with data-step
    items: tuple[tuple[str, str], ...] = ()  # style's items sorted: the key of a look, made once a style


#: One level of the walk: the children still to visit, their inherited state, key prefix, key counters
#: and ``<use>`` depth.
_Frame = tuple[Any, _State, str, dict[str, int], int]


def _weight(elem: ET.Element) -> int:
    """What an element counts towards :data:`MAX_ELEMENTS` when references repeat it: one per 256 characters.

    A drawn element is shorter (one); a polyline of a million points repeated by
    ``<use>`` a thousand times is a billion points, not a thousand elements.
    """
    chars = len(elem.text or "") + sum(len(v) for v in elem.attrib.values())
    return 1 + chars // 256


class _Parser:
    """Walks one SVG tree and collects its shapes."""

    def __init__(self, root: ET.Element, name: str):
        self.root = root
        self.name = name
        self.ids: dict[str, ET.Element] = {}
        self.rules: list[CssRule] = []
        self.stylesheet: list[tuple[str, tuple]] = []
        for e in root.iter():  # once over the tree: every element's id, every style sheet
            if not _svg_tag(e.tag):
                continue
            i = e.get("id")  # what _attrs(e) names "id": only the attribute without a namespace
            if i is not None and i not in self.ids:
                self.ids[i] = e
            if _local(e.tag)[1] == "style":
                rules, canon = parse_css("".join(e.itertext()), len(self.rules))
                self.rules.extend(rules)
                self.stylesheet.extend(canon)
        self.rules.sort(key=lambda r: r.specificity)
        self.sheet = RuleIndex(self.rules, self.name)
        self.shapes: list[Shape] = []
        self.used_keys: set[str] = set()
        self.next_suffix: dict[str, int] = {}
        self.key_chars = 0
        self._last: tuple[ET.Element | None, dict[str, str]] = (None, {})
        self._styles: dict[tuple, tuple[tuple[str, Any], ...]] = {}
        self._classed: dict[tuple, tuple[tuple[str, Any], ...]] = {}

    def _attrs(self, elem: ET.Element) -> dict[str, str]:
        """:func:`_attrs` of *elem*, read once for the several looks the walk takes at one element."""
        last, attrs = self._last
        if last is not elem:
            attrs = _attrs(elem)
            self._last = (elem, attrs)
        return attrs

    # -- document ---------------------------------------------------------------------------

    def drawing(self) -> Drawing:
        attrs = _attrs(self.root)
        doc: list[tuple[str, Any]] = []
        vb = attrs.get("viewBox")
        viewbox = tuple(parse_numbers(vb, f"{self.name}: viewBox")) if vb else None
        if viewbox is not None and len(viewbox) != 4:
            raise SvgFormatError(f"{self.name}: viewBox needs 4 numbers, got {vb!r}")
        for prop in ("width", "height"):
            if prop in attrs:
                doc.append((prop, style_value(prop, attrs[prop], "")))
        if viewbox is not None:
            doc.append(("viewBox", viewbox))
        if "preserveAspectRatio" in attrs:
            doc.append(("preserveAspectRatio", tuple(attrs["preserveAspectRatio"].split())))
        for child in self.root:
            if _is_svg(child) and _local(child.tag)[1] in ("title", "desc"):
                doc.append((_local(child.tag)[1], _plain_text(child)))
        if self.stylesheet:
            doc.append(("stylesheet", tuple(self.stylesheet)))
        vw = viewbox[2] if viewbox else self._length(attrs.get("width"), 100.0, "width")
        vh = viewbox[3] if viewbox else self._length(attrs.get("height"), 100.0, "height")
        self._check_expansion()
        state = _State(IDENTITY, {}, (vw, vh))
        self._walk_tree(self.root, self._own_state(self.root, state, "svg"))
        return Drawing(tuple(doc), tuple(self._definitions()), tuple(self.shapes))

    def _check_expansion(self) -> None:
        """Refuse a drawing whose walk would visit more than :data:`MAX_ELEMENTS` elements.

        Counted before anything is worked out, each element once: what an element
        expands to is its weight (:func:`_weight`: one, more for a long one) plus
        what its children expand to, and a ``<use>`` expands to what it references
        (remembered, so a reference used a million times is counted once).  The
        count follows the walk: what the walk skips (``<defs>``, a dangling
        reference) counts its own weight only.  A reference cycle is refused here
        too.  Without any ``<use>`` there is nothing to count: the walk visits each
        element at most once, and :func:`_read_tree` bounded their number.
        """
        limit = values.MAX_ELEMENTS
        if next(self.root.iter(f"{{{SVG_NS}}}use"), None) is None and next(self.root.iter("use"), None) is None:
            return  # each element is visited once at most: the count as the file was read bounds the walk
        size: dict[int, int] = {}  # id(element) -> elements it expands to; ids stay valid, the tree is alive
        busy: set[int] = set()  # on the path being counted: met again, a cycle
        stack: list[tuple[ET.Element, list[ET.Element] | None]] = [(self.root, None)]
        while stack:
            elem, inner = stack.pop()
            if inner is None:  # first met: count what is below it, then come back to add it up
                if id(elem) in size:
                    continue
                inner = self._expands_to(elem)
                busy.add(id(elem))
                stack.append((elem, inner))
                for sub in inner:
                    if id(sub) in busy:
                        raise SvgFormatError(f"{self.name}: <use> references form a cycle "
                                             f"(through <{_local(sub.tag)[1]} id={_attrs(sub).get('id')!r}>)")
                    if id(sub) not in size:
                        stack.append((sub, None))
                continue
            busy.discard(id(elem))
            size[id(elem)] = min(limit + 1, _weight(elem) + sum(size[id(sub)] for sub in inner))
        total = size[id(self.root)]
        if total > limit:
            raise SvgTooLargeError(f"{self.name}: the drawing expands to more than {limit:,} elements "
                                   f"(its <use> references repeat what they reference; a long element "
                                   f"counts one per 256 characters); refused", source=self.name, limit=limit)

    def _expands_to(self, elem: ET.Element) -> list[ET.Element]:
        """The elements the walk visits right below *elem* (its children, or what a ``<use>`` draws)."""
        tag = _local(elem.tag)[1]
        if tag in _NOT_DRAWN or tag in _ANIMATIONS:
            return []
        if tag == "use":
            href = self._attrs(elem).get("href", "")
            target = self.ids.get(href[1:]) if href.startswith("#") else None
            if target is None:
                return []
            ttag = _local(target.tag)[1]
            if ttag in ("symbol", "svg"):
                return [c for c in target if _is_svg(c)]
            return [target]
        return [c for c in elem if _is_svg(c)]

    def _definitions(self) -> list[tuple[str, Any]]:
        out: list[tuple[str, Any]] = []
        counters: dict[str, int] = {}
        stack = [(iter(self.root), False)]  # children still to visit, inside <defs>?
        while stack:
            children, in_defs = stack[-1]
            child = next(children, None)
            if child is None:
                stack.pop()
                continue
            if not _is_svg(child):
                continue
            name = _local(child.tag)[1]
            if name == "defs":
                stack.append((iter(child), True))
            elif in_defs or name in _NOT_DRAWN - {"title", "desc", "style", "metadata", "script"}:
                i = _attrs(child).get("id")
                if i is None:
                    i = f"{name}[{counters.get(name, 0)}]"
                    counters[name] = counters.get(name, 0) + 1
                out.append((i, _canon(child)))
            elif name not in _NOT_DRAWN:
                stack.append((iter(child), False))
        return sorted(out, key=lambda kv: kv[0])

    def _length(self, raw: str | None, ref: float, where: str) -> float:
        if raw is None:
            return ref
        m = LENGTH_RE.fullmatch(raw)
        if not m:
            raise SvgFormatError(f"{self.name}: {where}: not a length: {raw!r}")
        value, unit = float(m.group(1)), (m.group(2) or "").lower()
        return value / 100 * ref if unit == "%" else value * UNITS[unit]

    # -- styles -----------------------------------------------------------------------------

    def _own_style(self, elem: ET.Element, tag: str) -> dict[str, str]:
        attrs = self._attrs(elem)
        own = {k: v for k, v in attrs.items() if k in PRESENTATION}
        if self.rules:
            own.update(self.sheet.declarations(tag, attrs.get("id"), attrs.get("class", "")))
        if "style" in attrs:
            own.update(parse_declarations(attrs["style"]))
        return own

    def _own_state(self, elem: ET.Element, parent: _State, tag: str, extra: Matrix = IDENTITY) -> _State:
        attrs = self._attrs(elem)
        ctm = parent.ctm
        if "transform" in attrs:
            ctm = multiply(ctm, parse_transform(attrs["transform"], f"{self.name}: <{tag}> transform"))
        ctm = multiply(ctm, extra)
        own = self._own_style(elem, tag)
        style, items = parent.style, parent.items
        if own:  # most elements style nothing themselves: they share their parent's dict, never changed after
            style = dict(style)
            for prop, value in own.items():
                if value.strip().lower() == "inherit":
                    continue
                if prop in GROUP_EFFECTS and prop in style:
                    style[prop] = self._combine(prop, style[prop], value)
                else:
                    style[prop] = value
            items = tuple(sorted(style.items()))
        step = parent.step
        if "data-step" in attrs:
            try:
                step = int(attrs["data-step"])
            except ValueError:
                raise SvgFormatError(f"{self.name}: <{tag}> data-step is not a step number: "
                                     f"{attrs['data-step']!r}") from None
        return _State(ctm, style, parent.viewport, step, items)

    @staticmethod
    def _combine(prop: str, outer: str, inner: str) -> str:
        if prop == "opacity":
            try:
                return format_number(float(outer) * float(inner))
            except ValueError:
                return f"{outer} {inner}"
        if prop == "display":
            return "none" if "none" in (outer.strip(), inner.strip()) else inner
        if outer.strip().lower() == "none":
            return inner
        if inner.strip().lower() == "none":
            return outer
        return f"{outer} {inner}"

    def _effective_style(self, state: _State) -> tuple[tuple[str, Any], ...]:
        # Most elements of a drawing look alike: each look is worked out once and shared by them
        # (the time and the memory of a drawing of a million elements).
        key = (state.items, scale_factor(state.ctm))
        got = self._styles.get(key)
        if got is None:
            got = self._styles[key] = self._work_out_style(state)
        return got

    def _work_out_style(self, state: _State) -> tuple[tuple[str, Any], ...]:
        raw = state.style
        colour = normalise_colour(raw["color"]) if "color" in raw else "#000000"
        scale = scale_factor(state.ctm)
        non_scaling = raw.get("vector-effect", "").strip() == "non-scaling-stroke"
        out: list[tuple[str, Any]] = []
        for prop in sorted(raw):
            value = style_value(prop, raw[prop], colour)
            if prop in SCALED and scale != 1.0 and not (non_scaling and prop.startswith("stroke")):
                value = tuple(v * scale if isinstance(v, float) else v for v in value)
            if INITIAL.get(prop) == value:
                continue
            out.append((prop, value))
        return tuple(out)

    # -- walking ----------------------------------------------------------------------------

    def _key(self, elem: ET.Element, tag: str, prefix: str, counters: dict[str, int]) -> tuple[str, bool]:
        i = self._attrs(elem).get("id")
        if i is not None:
            key, has_id = prefix + i, True
        else:
            n = counters.get(tag, 0)
            counters[tag] = n + 1
            key, has_id = f"{prefix}{tag}[{n}]", False
        if key in self.used_keys:  # duplicate ids are invalid but exist: id, id~2, id~3, ...
            base = key
            k = self.next_suffix.get(base, 2)  # remembered: a thousand equal ids are not a million tries
            while f"{base}~{k}" in self.used_keys:
                k += 1
            self.next_suffix[base] = k + 1
            key = f"{base}~{k}"
        self.used_keys.add(key)
        self.key_chars += len(key)
        if self.key_chars > values.MAX_KEY_CHARS:
            # Keys grow with <use> nesting (outer/inner/id): long ids repeated by references
            # could fill memory with names alone.
            raise SvgTooLargeError(f"{self.name}: the names of the drawing's elements (ids along their <use> "
                                   f"references) take more than {values.MAX_KEY_CHARS:,} characters; refused",
                                   source=self.name, limit=values.MAX_KEY_CHARS)
        return key, has_id

    def _walk_tree(self, root: ET.Element, state: _State) -> None:
        """Every element below *root* in document order, on a stack of its own, not Python's.

        A frame is what a recursive walk would hold: the children still to visit,
        the state they inherit, the key prefix and counters of their scope and the
        ``<use>`` depth.  100,000 nested groups are 100,000 frames in a list.
        """
        stack: list[_Frame] = [(iter(root), state, "", {}, 0)]
        while stack:
            children, parent, prefix, counters, depth = stack[-1]
            child = next(children, None)
            if child is None:
                stack.pop()
            elif _svg_tag(child.tag):
                inner = self._walk(child, parent, prefix, counters, depth)
                if inner is not None:
                    stack.append(inner)

    def _walk(self, elem: ET.Element, parent: _State, prefix: str, counters: dict[str, int], depth: int
              ) -> _Frame | None:
        """Record *elem*; the frame of what is to be walked below it, if anything."""
        tag = _local(elem.tag)[1]
        if not tag or tag in _NOT_DRAWN or tag in _ANIMATIONS:
            return None
        if depth > 64:
            raise SvgFormatError(f"{self.name}: <use> nesting deeper than 64 (a reference cycle?)")
        attrs = self._attrs(elem)
        if tag == "svg":  # a nested viewport
            vp = self._nested_viewport(attrs, parent)
            state = self._own_state(elem, parent, tag, vp)
            key, has_id = self._key(elem, tag, prefix, counters)
            self._group_record(elem, key, has_id, tag, state)
            return iter(elem), state, prefix, counters, depth
        state = self._own_state(elem, parent, tag)
        if tag in _CONTAINERS:
            key, has_id = self._key(elem, tag, prefix, counters)
            self._group_record(elem, key, has_id, tag, state)
            return iter(elem), state, prefix, counters, depth
        if tag == "use":
            return self._use(elem, attrs, state, prefix, counters, depth)
        builder = getattr(self, f"_shape_{tag}", None)
        if builder is None:
            return None  # an element that draws nothing we model (tspan outside text, unknown tags)
        key, has_id = self._key(elem, tag, prefix, counters)
        geometry = builder(elem, attrs, state, f"{self.name}: <{tag} {key}>")
        self._add(elem, key, has_id, tag, state, geometry)
        return None

    def _nested_viewport(self, attrs: dict[str, str], parent: _State) -> Matrix:
        x = self._length(attrs.get("x"), parent.viewport[0], "x") if "x" in attrs else 0.0
        y = self._length(attrs.get("y"), parent.viewport[1], "y") if "y" in attrs else 0.0
        m: Matrix = (1.0, 0.0, 0.0, 1.0, x, y)
        if "viewBox" in attrs:
            vb = parse_numbers(attrs["viewBox"], f"{self.name}: viewBox")
            if len(vb) == 4 and vb[2] > 0 and vb[3] > 0:
                w = self._length(attrs.get("width"), parent.viewport[0], "width") if "width" in attrs else parent.viewport[0]
                h = self._length(attrs.get("height"), parent.viewport[1], "height") if "height" in attrs else parent.viewport[1]
                sx, sy = w / vb[2], h / vb[3]
                par = attrs.get("preserveAspectRatio", "xMidYMid meet").split()
                if par and par[0] != "none":
                    s = max(sx, sy) if "slice" in par else min(sx, sy)
                    align = par[0]
                    tx = {"xMin": 0.0, "xMid": 0.5, "xMax": 1.0}.get(align[:4], 0.5) * (w - s * vb[2])
                    ty = {"YMin": 0.0, "YMid": 0.5, "YMax": 1.0}.get(align[4:], 0.5) * (h - s * vb[3])
                    sx = sy = s
                else:
                    tx = ty = 0.0
                m = multiply(m, (sx, 0.0, 0.0, sy, tx - sx * vb[0], ty - sy * vb[1]))
        return m

    def _use(self, elem: ET.Element, attrs: dict[str, str], state: _State, prefix: str,
             counters: dict[str, int], depth: int) -> _Frame | None:
        key, has_id = self._key(elem, "use", prefix, counters)
        href = attrs.get("href", "")
        target = self.ids.get(href[1:]) if href.startswith("#") else None
        if target is None:
            # A dangling reference draws nothing; keep it visible to the diff.
            self._add(elem, key, has_id, "use", state, {"kind": "use", "structure": (("href", href),)})
            return None
        x = self._length(attrs.get("x"), state.viewport[0], "x") if "x" in attrs else 0.0
        y = self._length(attrs.get("y"), state.viewport[1], "y") if "y" in attrs else 0.0
        inner = _State(multiply(state.ctm, (1.0, 0.0, 0.0, 1.0, x, y)), state.style, state.viewport, state.step,
                       state.items)
        ttag = _local(target.tag)[1]
        if ttag in ("symbol", "svg"):
            sym_attrs = dict(_attrs(target))
            for k in ("width", "height"):
                if k in attrs:
                    sym_attrs[k] = attrs[k]
            sym_attrs.pop("x", None), sym_attrs.pop("y", None)
            sym = self._own_state(target, inner, ttag, self._nested_viewport(sym_attrs, inner))
            self._group_record(elem, key, has_id, "use", state)
            return iter(target), sym, key + "/", {}, depth + 1
        if ttag in _CONTAINERS:
            self._group_record(elem, key, has_id, "use", state)
            return iter((target,)), inner, key + "/", {}, depth + 1
        builder = getattr(self, f"_shape_{ttag}", None)
        if builder is None:
            return None
        tstate = self._own_state(target, inner, ttag)
        geometry = builder(target, _attrs(target), tstate, f"{self.name}: <use {key}> -> <{ttag}>")
        self._add(elem, key, has_id, f"use>{ttag}", tstate, geometry, extra_source=target)
        return None

    def _decorations(self, elem: ET.Element) -> tuple[tuple[Any, ...], tuple[tuple[str, str], ...]]:
        if not len(elem):
            return (), ()  # nearly every drawn element has no children
        animations, described = [], []
        for child in elem:
            if not _is_svg(child):
                continue
            name = _local(child.tag)[1]
            if name in _ANIMATIONS:
                animations.append((name, tuple(sorted((k, tokenise(v)) for k, v in _attrs(child).items()))))
            elif name in ("title", "desc"):
                described.append((name, _plain_text(child)))
        return tuple(sorted(animations, key=show_value)), tuple(described)

    def _group_record(self, elem: ET.Element, key: str, has_id: bool, tag: str, state: _State) -> None:
        """A group is recorded only for what it carries itself: animations, title, desc."""
        animations, described = self._decorations(elem)
        if animations or described:
            self.shapes.append(Shape(key=key, tag=tag, kind="group", animations=animations, described=described,
                                     has_id=has_id, order=len(self.shapes), step=state.step))

    def _add(self, elem: ET.Element, key: str, has_id: bool, tag: str, state: _State, geometry: dict[str, Any],
             extra_source: ET.Element | None = None) -> None:
        animations, described = self._decorations(elem)
        if extra_source is not None:
            more_a, more_d = self._decorations(extra_source)
            animations, described = tuple(sorted(animations + more_a, key=show_value)), described + more_d
        style = self._effective_style(state)
        classes = self._attrs(elem).get("class", "")
        classes = " ".join(sorted(set(classes.split()))) if classes else ""
        if classes:  # our renderer writes the instrument and provenance as classes
            key_style = (style, classes)
            got = self._classed.get(key_style)
            if got is None:  # one tuple per look and classes, shared by the elements that have them
                got = self._classed[key_style] = tuple(sorted(style + (("class", classes),)))
            style = got
        self.shapes.append(Shape(key=key, tag=tag, style=style, animations=animations,
                                 described=described, has_id=has_id, order=len(self.shapes), step=state.step,
                                 **geometry))

    # -- geometry of each element kind ---------------------------------------------------------

    def _coord(self, attrs: dict[str, str], name: str, state: _State, where: str, axis: int = 0,
               default: float = 0.0) -> float:
        raw = attrs.get(name)
        if raw is None or not raw.strip() or raw.strip() == "auto":
            return default
        if axis == 2:
            ref = math.hypot(*state.viewport) / math.sqrt(2)
        else:
            ref = state.viewport[axis]
        return self._length(raw, ref, f"{where} {name}")

    def _shape_line(self, elem, attrs, state, where):
        p1 = (self._coord(attrs, "x1", state, where), self._coord(attrs, "y1", state, where, 1))
        p2 = (self._coord(attrs, "x2", state, where), self._coord(attrs, "y2", state, where, 1))
        a, b = apply_matrix(state.ctm, p1), apply_matrix(state.ctm, p2)
        return {"kind": "segment", "points": (("start", a), ("end", b)),
                "sizes": (("length", math.dist(a, b)),)}

    def _shape_circle(self, elem, attrs, state, where):
        c = (self._coord(attrs, "cx", state, where), self._coord(attrs, "cy", state, where, 1))
        r = self._coord(attrs, "r", state, where, 2)
        return self._ellipse(c, r, r, state, circle=True)

    def _shape_ellipse(self, elem, attrs, state, where):
        c = (self._coord(attrs, "cx", state, where), self._coord(attrs, "cy", state, where, 1))
        rx = self._coord(attrs, "rx", state, where, 0, default=math.nan)
        ry = self._coord(attrs, "ry", state, where, 1, default=math.nan)
        rx, ry = (ry if math.isnan(rx) else rx), (rx if math.isnan(ry) else ry)
        rx, ry = (0.0 if math.isnan(rx) else rx), (0.0 if math.isnan(ry) else ry)
        return self._ellipse(c, rx, ry, state, circle=False)

    def _ellipse(self, c: Point, rx: float, ry: float, state: _State, circle: bool) -> dict[str, Any]:
        centre = apply_matrix(state.ctm, c)
        ax, ay, angle = ellipse_axes(state.ctm, rx, ry, 0.0)
        if circle and abs(ax - ay) <= 1e-9 * max(ax, 1.0):
            return {"kind": "circle", "points": (("centre", centre),), "sizes": (("radius", (ax + ay) / 2),)}
        if abs(ax - ay) <= 1e-9 * max(ax, 1.0):
            angle = 0.0  # a circle has no axis direction
        return {"kind": "ellipse", "points": (("centre", centre),), "sizes": (("rx", ax), ("ry", ay)),
                "angles": (("axis", angle),)}

    def _shape_rect(self, elem, attrs, state, where):
        x, y = self._coord(attrs, "x", state, where), self._coord(attrs, "y", state, where, 1)
        w, h = self._coord(attrs, "width", state, where), self._coord(attrs, "height", state, where, 1)
        rx = self._coord(attrs, "rx", state, where, 0, default=math.nan)
        ry = self._coord(attrs, "ry", state, where, 1, default=math.nan)
        rx, ry = (ry if math.isnan(rx) else rx), (rx if math.isnan(ry) else ry)
        rx, ry = min(0.0 if math.isnan(rx) else rx, w / 2), min(0.0 if math.isnan(ry) else ry, h / 2)
        corners = [apply_matrix(state.ctm, p) for p in ((x, y), (x + w, y), (x + w, y + h), (x, y + h))]
        s = scale_factor(state.ctm)
        return {"kind": "rect", "points": tuple((f"corner {i + 1}", p) for i, p in enumerate(corners)),
                "sizes": (("width", math.dist(corners[0], corners[1])), ("height", math.dist(corners[1], corners[2])),
                          ("corner rx", rx * s), ("corner ry", ry * s))}

    def _poly(self, attrs, state, where, kind):
        values = parse_numbers(attrs.get("points", ""), f"{where} points")
        if len(values) % 2:
            values = values[:-1]  # the spec draws up to the odd number
        pts = [apply_matrix(state.ctm, (values[i], values[i + 1])) for i in range(0, len(values), 2)]
        return {"kind": kind, "points": tuple((f"point {i + 1}", p) for i, p in enumerate(pts)),
                "structure": (("points", len(pts)),)}

    def _shape_polyline(self, elem, attrs, state, where):
        return self._poly(attrs, state, where, "polyline")

    def _shape_polygon(self, elem, attrs, state, where):
        return self._poly(attrs, state, where, "polygon")

    def _shape_path(self, elem, attrs, state, where):
        segments = parse_path(attrs.get("d", ""), where)
        m = state.ctm
        flip = determinant(m) < 0
        points: list[tuple[str, Point]] = []
        sizes: list[tuple[str, float]] = []
        angles: list[tuple[str, float]] = []
        commands: list[str] = []
        for i, seg in enumerate(segments, 1):
            op = seg[0]
            label = f"segment {i} ({op})"
            if op == "M":
                points.append((f"{label} point", apply_matrix(m, seg[1])))
                commands.append("M")
            elif op == "L":
                points.append((f"{label} end", apply_matrix(m, seg[2])))
                commands.append("L")
            elif op == "C":
                points += [(f"{label} control 1", apply_matrix(m, seg[2])),
                           (f"{label} control 2", apply_matrix(m, seg[3])),
                           (f"{label} end", apply_matrix(m, seg[4]))]
                commands.append("C")
            elif op == "Q":
                points += [(f"{label} control", apply_matrix(m, seg[2])), (f"{label} end", apply_matrix(m, seg[3]))]
                commands.append("Q")
            elif op == "Z":
                commands.append("Z")
            else:
                _, p0, p1, rx, ry, phi, large, sweep = seg
                centre, rx, ry = arc_centre(p0, p1, rx, ry, phi, large, sweep)
                ax, ay, angle = ellipse_axes(m, rx, ry, phi)
                if abs(ax - ay) <= 1e-9 * max(ax, 1.0):
                    angle = 0.0
                points += [(f"{label} centre", apply_matrix(m, centre)), (f"{label} end", apply_matrix(m, p1))]
                sizes += [(f"{label} rx", ax), (f"{label} ry", ay)]
                angles.append((f"{label} axis", angle))
                commands.append(f"A{int(large)}{int(sweep != flip)}")
        return {"kind": "path", "points": tuple(points), "sizes": tuple(sizes), "angles": tuple(angles),
                "structure": (("commands", " ".join(commands)),)}

    def _shape_text(self, elem, attrs, state, where):
        def first(name: str, axis: int) -> float:
            raw = attrs.get(name, "").strip()
            if not raw:
                return 0.0
            return self._length(re.split(r"[\s,]+", raw)[0], state.viewport[axis], f"{where} {name}")

        anchor = (first("x", 0) + first("dx", 0), first("y", 1) + first("dy", 1))
        points = [("anchor", apply_matrix(state.ctm, anchor))]
        n = 0
        for child in elem.iter():
            if child is not elem and _is_svg(child) and _local(child.tag)[1] == "tspan":
                n += 1
                ca = _attrs(child)
                if "x" in ca or "y" in ca:
                    cx = self._length(re.split(r"[\s,]+", ca["x"].strip())[0], state.viewport[0], where) if "x" in ca else anchor[0]
                    cy = self._length(re.split(r"[\s,]+", ca["y"].strip())[0], state.viewport[1], where) if "y" in ca else anchor[1]
                    points.append((f"tspan {n} anchor", apply_matrix(state.ctm, (cx, cy))))
        angle = math.degrees(math.atan2(state.ctm[1], state.ctm[0]))
        text = " ".join(_text_content(elem).replace("\n", " ").replace("\t", " ").split())
        return {"kind": "text", "points": tuple(points), "angles": (("baseline", angle),), "text": text}

    def _shape_image(self, elem, attrs, state, where):
        geometry = self._shape_rect(elem, attrs, state, where)
        geometry["kind"] = "image"
        geometry["sizes"] = geometry["sizes"][:2]
        href = attrs.get("href", "")
        geometry["structure"] = (("href", href if len(href) <= 80 else f"{href[:60]}... ({len(href)} chars)"),)
        return geometry


def parse_svg(source: str | Path | bytes, name: str | None = None) -> Drawing:
    """Parse an SVG (text, bytes or a file path) into a :class:`Drawing`.

    >>> d = parse_svg('<svg xmlns="http://www.w3.org/2000/svg"><g transform="translate(10,0)"><circle r="2"/></g></svg>')
    >>> d.shapes[0].key, d.shapes[0].kind, d.shapes[0].points
    ('circle[0]', 'circle', (('centre', (10.0, 0.0)),))
    >>> parse_svg("<html/>")
    Traceback (most recent call last):
    ...
    construct.regress.svgdiff.SvgFormatError: <string>: the root element is <html>, not <svg>
    """
    data, label = load_source(source, "SVG file")
    label = name or label
    try:
        root = read_tree(data, label)
    except SvgFormatError:
        raise
    except ET.ParseError as exc:
        raise SvgFormatError(f"{label}: not well-formed XML: {exc}") from None
    except defusedxml.DefusedXmlException as exc:
        what = getattr(exc, "name", None) or getattr(exc, "sysid", None) or ""
        raise SvgFormatError(f"{label}: {type(exc).__name__} {what!r}: entity declarations, external references "
                             f"and DTDs that use them are not read (an XML bomb expands from them)") from None
    except (ValueError, UnicodeError) as exc:
        raise SvgFormatError(f"{label}: cannot decode: {exc}") from None
    ns, tag = _local(root.tag)
    if tag != "svg" or ns not in (None, SVG_NS):
        raise SvgFormatError(f"{label}: the root element is <{tag}>, not <svg>")
    try:
        return _Parser(root, label).drawing()
    except (ValueError, ZeroDivisionError, OverflowError) as exc:
        if isinstance(exc, SvgFormatError):
            raise
        raise SvgFormatError(f"{label}: {exc}") from None
