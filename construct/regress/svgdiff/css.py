"""Colours, properties and style sheets: one spelling for every way SVG can say the same look.

Part of :mod:`construct.regress.svgdiff`.
"""

from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from typing import Any

import tinycss2.color4

from . import values
from .values import NUMBER, UNITS, SvgTooLargeError

# --------------------------------------------------------------------------- colours and styles

_COLOUR_PROPERTIES = {"fill", "stroke", "color", "stop-color", "flood-color", "lighting-color"}
_HEX_RE = re.compile(r"#(?:[0-9a-f]{3,4}|[0-9a-f]{6}|[0-9a-f]{8})")


def normalise_colour(raw: str, current: str = "#000000") -> str:
    """One spelling per colour: ``#rrggbb`` (``#rrggbbaa`` when not opaque), ``none`` or the text.

    Hex is read here (nearly every colour of our drawings); names and functions
    (``rgb()``, ``hsl()``, CSS Color 4's ``hwb()``, ``lab()``, ...) by tinycss2,
    once per spelling.

    >>> {normalise_colour(c) for c in ("#000", "#000000", "black", "rgb(0,0,0)", "rgb(0%, 0%, 0%)", "hsl(0, 0%, 0%)")}
    {'#000000'}
    >>> normalise_colour("rgba(255, 0, 0, 0.5)"), normalise_colour("URL(#Grad)"), normalise_colour("RebeccaPurple")
    ('#ff000080', 'url(#Grad)', '#663399')
    """
    s = raw.strip()
    low = s.lower()
    if low in ("none", "transparent"):
        return "none"
    if low == "currentcolor":
        return current
    if _HEX_RE.fullmatch(low):
        digits = low[1:] if len(low) > 5 else "".join(ch * 2 for ch in low[1:])
        return _rgba_hex(*(int(digits[i:i + 2], 16) for i in range(0, len(digits), 2)))
    if low.startswith("url"):
        return "url" + s[3:]  # references keep their case: ids are case-sensitive
    return _named_or_function(low)


@functools.lru_cache(maxsize=1024)
def _named_or_function(low: str) -> str:
    """A colour name or function in ``#rrggbb[aa]``; what is no colour stays as written (lower case)."""
    colour = tinycss2.color4.parse_color(low)
    if colour is None or isinstance(colour, str):
        return low
    try:
        channels = [min(255, max(0, round(255 * v))) for v in (*colour.to("srgb").coordinates, colour.alpha)]
    except (NotImplementedError, ValueError, ArithmeticError):  # lab() and kin, or a NaN: not converted
        return low
    return _rgba_hex(*channels)


def _rgba_hex(r: int, g: int, b: int, a: int = 255) -> str:
    return f"#{r:02x}{g:02x}{b:02x}" + ("" if a == 255 else f"{a:02x}")


# Presentation attributes that may stand on an element instead of in `style`.
PRESENTATION = {
    "alignment-baseline", "baseline-shift", "clip", "clip-path", "clip-rule", "color", "color-interpolation",
    "color-interpolation-filters", "color-rendering", "cursor", "direction", "display", "dominant-baseline",
    "fill", "fill-opacity", "fill-rule", "filter", "flood-color", "flood-opacity", "font", "font-family",
    "font-size", "font-size-adjust", "font-stretch", "font-style", "font-variant", "font-weight",
    "image-rendering", "letter-spacing", "lighting-color", "marker", "marker-end", "marker-mid", "marker-start",
    "mask", "opacity", "overflow", "paint-order", "pointer-events", "shape-rendering", "stop-color",
    "stop-opacity", "stroke", "stroke-dasharray", "stroke-dashoffset", "stroke-linecap", "stroke-linejoin",
    "stroke-miterlimit", "stroke-opacity", "stroke-width", "text-anchor", "text-decoration", "text-rendering",
    "unicode-bidi", "vector-effect", "visibility", "word-spacing", "writing-mode",
}
# Not inherited by the children of a group, but still acting on them: combined instead.
GROUP_EFFECTS = {"opacity", "display", "clip-path", "mask", "filter", "overflow", "clip"}
INITIAL = {
    "fill": "#000000", "fill-opacity": (1.0,), "fill-rule": ("nonzero",), "stroke": "none", "stroke-width": (1.0,),
    "stroke-opacity": (1.0,), "stroke-linecap": ("butt",), "stroke-linejoin": ("miter",),
    "stroke-miterlimit": (4.0,), "stroke-dasharray": ("none",), "stroke-dashoffset": (0.0,),
    "opacity": (1.0,), "display": ("inline",), "visibility": ("visible",), "font-style": ("normal",),
    "font-weight": (400.0,), "text-anchor": ("start",), "font-size": (16.0,), "color": "#000000",
    "clip-path": ("none",), "mask": ("none",), "filter": ("none",), "marker-start": ("none",),
    "marker-mid": ("none",), "marker-end": ("none",), "vector-effect": ("none",),
}
# Lengths in the element's user units: a scaled element draws them scaled.
SCALED = {"stroke-width", "stroke-dasharray", "stroke-dashoffset", "font-size", "letter-spacing", "word-spacing"}


def parse_declarations(text: str) -> dict[str, str]:
    """``"a: b; c: d"`` as a dict (later wins; ``!important`` dropped)."""
    out: dict[str, str] = {}
    for decl in re.sub(r"/\*.*?\*/", "", text, flags=re.S).split(";"):
        if ":" in decl:
            name, value = decl.split(":", 1)
            value = re.sub(r"\s*!important\s*$", "", value.strip(), flags=re.I)
            if name.strip() and value:
                out[name.strip().lower()] = value
    return out


def style_value(prop: str, raw: str, current: str) -> Any:
    """A property value in one spelling: a colour string or a tuple of words and numbers."""
    if prop in _COLOUR_PROPERTIES:
        return normalise_colour(raw, current)
    s = raw.strip()
    if prop == "font-family":
        return ", ".join(f.strip().strip("'\"").strip().lower() for f in s.split(","))
    if prop == "font-weight":
        s = {"normal": "400", "bold": "700"}.get(s.lower(), s)
    words: list[Any] = []
    for part in re.split(r"[\s,]+", s):
        if not part:
            continue
        if words:
            words.append(" ")
        m = re.fullmatch(r"(" + NUMBER + r")(px|mm|cm|in|pt|pc|em|ex|%)?", part, flags=re.I)
        if m:
            unit = (m.group(2) or "").lower()
            value = float(m.group(1))
            words.extend([value * UNITS[unit]] if unit != "%" else [value, "%"])
        else:
            words.append(part if part.lower().startswith("url(") else part.lower())
    return tuple(words)


@dataclass(frozen=True, slots=True)
class CssRule:
    """One selector of a style sheet with its declarations; *specificity* orders the rules as CSS does."""

    tag: str | None
    ids: tuple[str, ...]
    classes: tuple[str, ...]
    specificity: tuple[int, int, int, int]
    declarations: tuple[tuple[str, str], ...]

    def matches(self, tag: str, elem_id: str | None, classes: set[str]) -> bool:
        return ((self.tag is None or self.tag == tag) and all(i == elem_id for i in self.ids)
                and all(c in classes for c in self.classes))


def parse_css(text: str, order_start: int = 0) -> tuple[list[CssRule], list[tuple[str, tuple]]]:
    """Rules with simple selectors (``tag``, ``.class``, ``#id``, ``*`` and compounds) and a canonical form.

    Selectors with combinators or pseudo-classes are not applied, but they are
    part of the canonical form, so a change to them is still reported.
    """
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    text = re.sub(r"@[^{;]*(;|\{[^{}]*(\{[^{}]*\}[^{}]*)*\})", "", text)  # @import, @media, @font-face
    rules: list[CssRule] = []
    canon: list[tuple[str, tuple]] = []
    for n, block in enumerate(re.finditer(r"([^{}]+)\{([^{}]*)\}", text)):
        decls = parse_declarations(block.group(2))
        for sel in block.group(1).split(","):
            sel = " ".join(sel.split())
            canon.append((sel, tuple(sorted((k, style_value(k, v, "currentcolor")) for k, v in decls.items()))))
            m = re.fullmatch(r"(\*|[A-Za-z][\w-]*)?((?:[.#][\w-]+)*)", sel)
            if not m or not sel:
                continue
            ids = tuple(re.findall(r"#([\w-]+)", m.group(2)))
            classes = tuple(re.findall(r"\.([\w-]+)", m.group(2)))
            tag = None if m.group(1) in (None, "*") else m.group(1)
            spec = (len(ids), len(classes), 0 if tag is None else 1, order_start + n)
            rules.append(CssRule(tag, ids, classes, spec, tuple(decls.items())))
    rules.sort(key=lambda r: r.specificity)
    canon.sort()
    return rules, canon


class RuleIndex:
    """The rules of the style sheets by the id, class or tag they need, and what they give each look.

    An element meets only the rules that name its id, one of its classes or its
    tag (and the universal ones), and elements that look alike to the sheet
    (tag, classes, an id no rule names) share one answer: a drawing of a million
    elements and a few classes matches a few times.  The checks of rules
    against elements are counted; past :data:`CSS_MATCH_BUDGET` (a hostile
    sheet: a rule per element, every element different) the drawing is refused.
    """

    def __init__(self, rules: list[CssRule], name: str):
        self.name = name
        self.by_id: dict[str, list[CssRule]] = {}
        self.by_class: dict[str, list[CssRule]] = {}
        self.by_tag: dict[str, list[CssRule]] = {}
        self.anywhere: list[CssRule] = []
        for rule in rules:  # in specificity order; each rule filed under one thing it needs
            if rule.ids:
                self.by_id.setdefault(rule.ids[0], []).append(rule)
            elif rule.classes:
                self.by_class.setdefault(rule.classes[0], []).append(rule)
            elif rule.tag is not None:
                self.by_tag.setdefault(rule.tag, []).append(rule)
            else:
                self.anywhere.append(rule)
        self.looks: dict[tuple[str, str | None, str], dict[str, str]] = {}
        self.checks = 0

    def declarations(self, tag: str, elem_id: str | None, classes: str) -> dict[str, str]:
        look = (tag, elem_id if elem_id in self.by_id else None, classes)
        got = self.looks.get(look)
        if got is None:
            got = self.looks[look] = self._work_out(tag, look[1], set(classes.split()))
        return got

    def _work_out(self, tag: str, elem_id: str | None, classes: set[str]) -> dict[str, str]:
        candidates = list(self.anywhere)
        candidates += self.by_tag.get(tag, ())
        if elem_id is not None:
            candidates += self.by_id.get(elem_id, ())
        for c in classes:
            candidates += self.by_class.get(c, ())
        self.checks += len(candidates)
        if self.checks > values.CSS_MATCH_BUDGET:
            raise SvgTooLargeError(f"{self.name}: applying the style sheets takes more than "
                                   f"{values.CSS_MATCH_BUDGET:,} rule checks; refused",
                                   source=self.name, limit=values.CSS_MATCH_BUDGET)
        out: dict[str, str] = {}
        for rule in sorted(candidates, key=lambda r: r.specificity):
            if rule.matches(tag, elem_id, classes):
                out.update(rule.declarations)
        return out
