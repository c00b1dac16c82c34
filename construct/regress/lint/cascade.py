"""A drawing's style sheet applied to its elements: the few properties legibility depends on.

Rules with type, class, id and universal selectors, compounds of them and the
descendant and child combinators (all our style sheets use: ``.lb``,
``.cur>.pt``, ``g.stage.cur>g>*``, ``#figure.zoomed .lb``) are applied in
the order of their specificity and position; presentation attributes come
before them and an element's ``style`` attribute after, as in a browser.
Rules with other selectors (pseudo-classes, attributes) are not applied: a
still view has no ``:hover``.

An element is given as its *chain*, the nodes from the root down to it; a
node is (tag, id, classes, own declarations).  Chains of elements that look
alike are alike, so each look is worked out once.

>>> c = Cascade(".lb{font-size:12px;font-family:'DejaVu Sans'}.tag{display:none;font-size:10px}"
...             ".cur>.tag{display:inline}.old{opacity:0.5}")
>>> root, step = node("svg"), node("g", classes="step cur")
>>> look = c.look((root, step, node("text", classes="lb tag")))
>>> look.shown, look.font_size, look.opacity
(True, 10.0, 1.0)
>>> c.look((root, node("g", classes="step old"), node("text", classes="lb tag"))).shown
False
>>> c.look((root, node("g", classes="step old"), node("text", classes="lb"))).opacity
0.5
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterable

__all__ = ["Cascade", "Look", "Node", "node", "PROPERTIES"]

Node = tuple[str, "str | None", frozenset, tuple]
"""(tag, id, classes, own declarations from presentation attributes and ``style``)."""

#: The properties read (and, but for display and opacity, inherited).
PROPERTIES = ("display", "visibility", "opacity", "font-size", "font-family", "font-style", "font-weight",
              "text-anchor", "stroke", "stroke-width", "fill")
_INHERITED = {"visibility", "font-size", "font-family", "font-style", "font-weight", "text-anchor", "stroke",
              "stroke-width", "fill"}
_INITIAL = {"visibility": "visible", "font-size": "16", "font-family": "serif", "font-style": "normal",
            "font-weight": "normal", "text-anchor": "start", "stroke": "none", "stroke-width": "1",
            "fill": "black"}


def node(tag: str, ident: str | None = None, classes: str | Iterable[str] = "",
         declarations: tuple[tuple[str, str], ...] = ()) -> Node:
    """A chain node: *classes* a space-separated string or any iterable of names."""
    names = classes.split() if isinstance(classes, str) else classes
    return (tag, ident, frozenset(names), declarations)


def declarations(text: str) -> dict[str, str]:
    """``"a: b; c: d"`` as a dict of the properties read here (later wins; ``!important`` dropped)."""
    out: dict[str, str] = {}
    for decl in re.sub(r"/\*.*?\*/", "", text, flags=re.S).split(";"):
        name, sep, value = decl.partition(":")
        name = name.strip().lower()
        value = re.sub(r"\s*!important\s*$", "", value.strip(), flags=re.I)
        if sep and name in PROPERTIES and value:
            out[name] = value
    return out


@dataclass(frozen=True, slots=True)
class Look:
    """What an element looks like, as far as legibility goes (lengths in user units)."""

    shown: bool
    opacity: float
    font_size: float
    font_family: str
    font_style: str
    font_weight: str
    text_anchor: str
    stroke: str
    stroke_width: float

    @property
    def stroked(self) -> bool:
        return self.stroke.strip().lower() not in ("none", "transparent") and self.stroke_width > 0


_COMPOUND = re.compile(r"(\*|[A-Za-z][\w-]*)?((?:[.#][\w-]+)*)")


@dataclass(frozen=True, slots=True)
class _Rule:
    #: (combinator before it, (tag, ids, classes)) from the leftmost compound to the subject.
    parts: tuple[tuple[str, tuple[str | None, tuple[str, ...], tuple[str, ...]]], ...]
    specificity: tuple[int, int, int, int]
    declarations: tuple[tuple[str, str], ...]

    def matches(self, chain: tuple[Node, ...]) -> bool:
        return _match(self.parts, chain, len(self.parts) - 1, len(chain) - 1)


def _fits(compound: tuple, nd: Node) -> bool:
    """Does the node *nd* fit the compound selector (tag, ids, classes)?"""
    tag, ids, classes = compound
    if tag is not None and tag != nd[0]:
        return False
    for i in ids:
        if i != nd[1]:
            return False
    for c in classes:
        if c not in nd[2]:
            return False
    return True


def _match(parts: tuple, chain: tuple[Node, ...], i: int, j: int) -> bool:
    """Do the selector's compounds up to *i* match the chain up to *j*, the *i*-th at node *j*?  (Module-level
    functions and loops, not closures and generators made at every call: the lint asks a sheet's rules of tens
    of thousands of chains.)"""
    if not _fits(parts[i][1], chain[j]):
        return False
    if i == 0:
        return True
    if parts[i][0] == ">":
        return j > 0 and _match(parts, chain, i - 1, j - 1)
    for jj in range(j - 1, -1, -1):
        if _match(parts, chain, i - 1, jj):
            return True
    return False


def _selector(text: str) -> tuple | None:
    """A selector's parts, or None when it uses what is not applied here."""
    parts = []
    combinator = " "
    for token in re.findall(r">|[^\s>]+", text):
        if token == ">":
            combinator = ">"
            continue
        m = _COMPOUND.fullmatch(token)
        if not m or not token:
            return None
        tag = None if m.group(1) in (None, "*") else m.group(1)
        parts.append((combinator, (tag, tuple(re.findall(r"#([\w-]+)", m.group(2))),
                                   tuple(re.findall(r"\.([\w-]+)", m.group(2))))))
        combinator = " "
    return tuple(parts) or None


class Cascade:
    """The rules of a style sheet, and the look of an element given as its chain."""

    def __init__(self, css: str = ""):
        text = re.sub(r"/\*.*?\*/", "", css, flags=re.S)
        text = re.sub(r"@[^{;]*(;|\{[^{}]*(\{[^{}]*\}[^{}]*)*\})", "", text)  # @media, @font-face, @import
        rules: list[_Rule] = []
        for n, block in enumerate(re.finditer(r"([^{}]+)\{([^{}]*)\}", text)):
            decls = tuple(declarations(block.group(2)).items())
            if not decls:
                continue
            for sel in block.group(1).split(","):
                parts = _selector(" ".join(sel.split()))
                if parts is None:
                    continue
                ids = sum(len(p[1][1]) for p in parts)
                classes = sum(len(p[1][2]) for p in parts)
                tags = sum(p[1][0] is not None for p in parts)
                rules.append(_Rule(parts, (ids, classes, tags, n), decls))
        rules.sort(key=lambda r: r.specificity)
        self.rules = rules
        #: Ids some rule names: only these need to stay in a chain (the others would spoil the sharing).
        self.ids = frozenset(i for r in rules for p in r.parts for i in p[1][1])
        #: Classes some rule names.
        self.classes = frozenset(c for r in rules for p in r.parts for c in p[1][2])
        # which rules match a chain depends on the selectors alone: drawings of one style whose rules differ only in
        # their values (each figure's line widths) share it (tens of drawings linted in one process)
        selectors = tuple(r.parts for r in rules)
        self._matches = _MATCHES.pop(selectors, None) or {}
        _MATCHES[selectors] = self._matches
        while len(_MATCHES) > _MATCHES_KEPT:
            del _MATCHES[next(iter(_MATCHES))]
        self._looks: dict[tuple[Node, ...], Look] = {}
        # (asking) per set of class names: the rules naming one of them, without them, and the chains asked
        self._relaxed: dict[tuple[frozenset[str], frozenset[str]], list[tuple]] = {}
        self._asking: dict[tuple[frozenset[str], frozenset[str]], dict[tuple[Node, ...], frozenset[str]]] = {}
        self._own: dict[tuple[Node, ...], dict[str, str]] = {}
        #: (:meth:`_declared`) by the rules matched and the node's own declarations
        self._alike: dict[tuple, dict[str, str]] = {}
        # the rules whose subject asks for classes, by the first of them (an element is asked only about the rules
        # filed under its own classes, and those that ask for none: a sheet of hundreds of rules, each asked of
        # every element, was a third of the lint)
        self._open = [i for i, r in enumerate(rules) if not r.parts[-1][1][2]]
        self._filed: dict[str, list[int]] = {}
        for i, r in enumerate(rules):
            if r.parts[-1][1][2]:
                self._filed.setdefault(r.parts[-1][1][2][0], []).append(i)

    def asking(self, chain: tuple[Node, ...], names: frozenset[str], others: frozenset[str] = frozenset()
               ) -> frozenset[str]:
        """Which of the classes *names* can change the look of *chain* -- with any of the classes *others* on its
        nodes (the same either way: what else the caller changes, a step's state)?  The look is the same
        whichever of the other classes of *names* its nodes carry.

        A class of *names* is asked when a rule naming it could match the chain or one of its ancestors (a look
        inherits its parent's), asked of the rules naming one of *names* with every class of *names* and
        *others* left out: such a rule matches wherever the whole rule would, with any of those classes (a
        selector only asks for classes, never for their absence), and the rules naming none of *names* match
        alike whichever of them a node carries.

        >>> c = Cascade(".zl1 .m1{display:none}.cur .lb{opacity:0.5}.zl2.cur .tag{opacity:0.5}")
        >>> root, names, states = node("svg", classes="zl0"), frozenset({"zl0", "zl1", "zl2"}), frozenset({"cur"})
        >>> [sorted(c.asking((root, node("text", classes=k)), names, states)) for k in ("lb", "m1", "tag m1")]
        [[], ['zl1'], ['zl1', 'zl2']]
        """
        key = (names, others)
        rules = self._relaxed.get(key)
        if rules is None:
            rules = self._relaxed[key] = [
                (tuple((comb, (tag, ids, tuple(c for c in classes if c not in names and c not in others)))
                       for comb, (tag, ids, classes) in r.parts),
                 frozenset(c for part in r.parts for c in part[1][2] if c in names))
                for r in self.rules if any(c in names for part in r.parts for c in part[1][2])]
            self._asking[key] = {}
        known = self._asking[key]
        got = known.get(chain)
        if got is None:
            last = len(chain) - 1
            got = self.asking(chain[:-1], names, others) if last else frozenset()
            for parts, named in rules:
                if not named <= got and _match(parts, chain, len(parts) - 1, last):
                    got = got | named
            known[chain] = got
        return got

    def _declared(self, chain: tuple[Node, ...]) -> dict[str, str]:
        """What the rules, the attributes and the style say about the last node of *chain*."""
        got = self._own.get(chain)
        if got is None:
            # what the last node says depends only on the rules matching it and its own declarations: chains
            # alike in both (most: a figure's thousands of elements carry a few dozen sets of classes) share it
            key = (self._matched(chain), chain[-1][3])
            got = self._alike.get(key)
            if got is None:
                got = self._alike[key] = self._declared_by(*key)
            self._own[chain] = got
        return got

    def _declared_by(self, matched: tuple[int, ...], own_pairs: tuple[tuple[str, str], ...]) -> dict[str, str]:
        """What the rules numbered *matched* and a node's own declarations *own_pairs* say (:meth:`_declared`)."""
        got: dict[str, str] = {}
        own = dict(own_pairs)
        for name in PROPERTIES:  # presentation attributes first, the style sheet over them
            if ("@" + name) in own:
                got[name] = own["@" + name]
        for i in matched:
            got.update(self.rules[i].declarations)
        for name in PROPERTIES:  # the style attribute last
            if name in own:
                got[name] = own[name]
        return got

    def _matched(self, chain: tuple[Node, ...]) -> tuple[int, ...]:
        """The numbers of the rules that match the last node of *chain*, in the sheet's order (asked by the nodes'
        tags, ids and classes alone: a chain's own declarations do not take part)."""
        key = tuple([nd[:3] for nd in chain])
        got = self._matches.get(key)
        if got is None:
            classes = chain[-1][2]
            asked = self._open + [i for c in classes for i in self._filed.get(c, ())]
            matched = []
            for i in sorted(asked) if len(asked) > len(self._open) else asked:  # (in the sheet's order)
                rule = self.rules[i]
                if rule.parts[-1][1][2] and not all(c in classes for c in rule.parts[-1][1][2]):
                    continue  # the subject's classes are the cheap test
                if rule.matches(chain):
                    matched.append(i)
            got = self._matches[key] = tuple(matched)
        return got

    def look(self, chain: tuple[Node, ...]) -> Look:
        """The look of the element whose chain (root first) is *chain*."""
        got = self._looks.get(chain)
        if got is not None:
            return got
        if len(chain) > 1:
            parent = self.look(chain[:-1])
            # a hidden parent hides its children (display), whatever they say (visibility: approximated alike)
            inherited = {"visibility": "visible", "font-size": str(parent.font_size),
                         "font-family": parent.font_family, "font-style": parent.font_style,
                         "font-weight": parent.font_weight, "text-anchor": parent.text_anchor,
                         "stroke": parent.stroke, "stroke-width": str(parent.stroke_width)}
            shown, opacity = parent.shown, parent.opacity
            parent_size = parent.font_size
        else:
            inherited = dict(_INITIAL)
            shown, opacity, parent_size = True, 1.0, 16.0
        values = dict(inherited)
        values.update(self._declared(chain))
        if values.get("display", "").strip().lower() == "none":
            shown = False
        if values.get("visibility", "").strip().lower() in ("hidden", "collapse"):
            shown = False
        opacity *= _number(values.get("opacity", "1"), 1.0, 1.0)
        size = _length(values["font-size"], parent_size)
        got = Look(shown=shown, opacity=max(0.0, min(1.0, opacity)), font_size=size,
                   font_family=values["font-family"].strip(), font_style=values["font-style"].strip().lower(),
                   font_weight=values["font-weight"].strip().lower(),
                   text_anchor=values["text-anchor"].strip().lower(), stroke=values["stroke"].strip(),
                   stroke_width=_length(values["stroke-width"], size))
        self._looks[chain] = got
        return got


#: The rules matched per chain, per style sheet's selectors (:meth:`Cascade._matched`): the last few kept.
_MATCHES: dict[tuple, dict[tuple, tuple[int, ...]]] = {}
_MATCHES_KEPT = 4


def _number(text: str, default: float, percent_of: float) -> float:
    s = text.strip().lower()
    try:
        return float(s[:-1]) / 100 * percent_of if s.endswith("%") else float(s)
    except ValueError:
        return default


_UNITS = {"": 1.0, "px": 1.0, "pt": 4 / 3, "pc": 16.0, "mm": 96 / 25.4, "cm": 96 / 2.54, "in": 96.0}


def _length(text: str, em: float) -> float:
    """A CSS length in user units (em and % of *em*); what cannot be read (``calc()``) is *em*."""
    m = re.fullmatch(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:e[-+]?\d+)?)\s*(px|pt|pc|mm|cm|in|em|%)?\s*", text, re.I)
    if not m:
        return em
    value, unit = float(m.group(1)), (m.group(2) or "").lower()
    if unit == "em":
        return value * em
    if unit == "%":
        return value / 100 * em
    return value * _UNITS[unit]
