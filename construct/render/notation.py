"""The books' notation for what a reader sees: figure captions, givens, sources.

A figure's caption names the figure, its title and its givens in the symbols
and units of the book it comes from -- the German line with the decimal comma
(``G = 830 kg, n = 50/min, R = 0,4 m, L = 2,0 m``), the English line with the
point -- and cites the book by author, title and figure, never by a file of
this repository.  Which text and which parameters exactly (the machine's
view) go into the SVG's ``<desc>`` and the protocol.

The construction knows all of that itself (:class:`Described`: its
citations, the wording of its givens, the names of its methods and
conventions); this module writes it out and keeps no table of constructions.
A figure without a construction (a protocol of the user's own) is captioned
by its name and its givens by their names.

>>> from construct.constructions import get
>>> c = get("piston-force")
>>> de, en = givens(c.figure(parts=9), c)
>>> de
'G = 830 kg, n = 50/min, R = 0,4 m, L = 2,0 m, F = 1529,1 cm², p₁ = 7 at, p₂ = 2 at, Füllung 30 %, schädlicher Raum 8 %, Kompression 15 %, Halbkreis in 9 Teilen (Dürers Dreiteilung)'
>>> en.split(", ")[:4]
['G = 830 kg', 'n = 50/min', 'R = 0.4 m', 'L = 2.0 m']
"""

from __future__ import annotations

import json
import math
from typing import Any, Callable, Mapping, Protocol, Sequence

from ..kernel.letters import TITLE_LIMIT, number
from ..kernel.protocol import Caption
from ..kernel.protocol import Protocol as StepProtocol
from ..kernel.protocol import Replay

__all__ = ["Described", "Drawn", "Cited", "givens", "phrases", "given_rows", "citation", "caption", "provenance",
           "with_provenance", "number", "signed"]


class Drawn(Protocol):
    """What the drawing reads of a figure (:class:`construct.figure.Figure` is one)."""

    @property
    def protocol(self) -> StepProtocol: ...
    @property
    def replay(self) -> Replay: ...
    @property
    def params(self) -> Mapping[str, Any]: ...


class Text(Protocol):
    """A source text as a caption cites it (:class:`construct.constructions.phrases.Book` is one)."""

    @property
    def key(self) -> str: ...
    @property
    def author(self) -> str | None: ...
    def title(self, lang: str) -> str: ...


class Cited(Protocol):
    """A text and the figure in it (:class:`construct.constructions.phrases.Cite` is one)."""

    @property
    def book(self) -> Text: ...
    @property
    def figure(self) -> str: ...


class Described(Protocol):
    """What the drawing reads of a construction (:class:`construct.constructions.Construction` is one)."""

    @property
    def name(self) -> str: ...
    @property
    def title(self) -> Caption: ...
    @property
    def source(self) -> str: ...
    @property
    def cites(self) -> Sequence[Cited]: ...
    @property
    def wording(self) -> Callable[[Any, str], Sequence[str]] | None: ...
    @property
    def symbols(self) -> Mapping[str, Caption]: ...
    @property
    def methods(self) -> Mapping[str, Caption]: ...
    @property
    def conventions(self) -> Mapping[str, Mapping[str, Caption]]: ...
    @property
    def note(self) -> Callable[[Any, str], str] | None: ...
    @property
    def plate(self) -> Callable[[Any], Mapping[str, Any]] | None: ...


#: What the kernel and the constructions keep in a protocol's parameters besides what they are built with.
_PROTOCOL_KEYS = ("givens", "group_titles", "captions", "plate", "called")


def _listed(fig: Drawn, lang: str, construction: Described | None) -> list[str]:
    """Each given and parameter in turn: as the construction's symbols, methods and conventions name it, else
    by its name (a given written ``card.x0`` is one of a digitised card's points, not named here)."""
    symbols = construction.symbols if construction is not None else {}
    methods = construction.methods if construction is not None else {}
    conventions = construction.conventions if construction is not None else {}
    values = {**{k: v for k, v in fig.replay.givens.items() if "." not in k},
              **{k: v for k, v in fig.params.items()
                 if k not in _PROTOCOL_KEYS and isinstance(v, (bool, int, float, str))}}
    out = []
    for key, v in values.items():
        text = number(v, lang, 6) if isinstance(v, float) else str(v)
        named = methods.get(text) if key == "method" else conventions.get(key, {}).get(text)
        if named is not None:
            out.append(named.de if lang == "de" else named.en)
        elif key in symbols:
            out.append((symbols[key].de if lang == "de" else symbols[key].en).format(v=text))
        else:
            out.append(f"{key.replace('_', ' ')} = {text}")
    return out


def phrases(fig: Drawn, lang: str, construction: Described | None = None) -> list[str]:
    """The figure's givens in *lang* as its book writes them (the construction's :attr:`wording`), or each
    in turn (:attr:`symbols`, or by name)."""
    if construction is not None and construction.wording is not None:
        return list(construction.wording(fig, lang))
    return _listed(fig, lang, construction)


def givens(fig: Drawn, construction: Described | None = None) -> tuple[str, str]:
    """The figure's givens in its book's symbols and units: (German, English) (:func:`phrases`)."""
    return ", ".join(phrases(fig, "de", construction)), ", ".join(phrases(fig, "en", construction))


def given_rows(fig: Drawn, construction: Described | None = None) -> dict[str, str]:
    """The givens as the player's table shows them: symbol -> value, German / English where they differ.

    >>> from construct.constructions import get
    >>> c = get("piston-force")
    >>> rows = given_rows(c.figure(parts=9), c)
    >>> rows["R"], rows["Füllung 30 %"], list(rows)[:3]
    ('0,4 m / 0.4 m', 'cut-off 30 %', ['G', 'n', 'R'])
    """
    if construction is None:  # a protocol of the user's own: its givens by name
        return {k: number(v, "en", 6) if isinstance(v, float) else str(v) for k, v in sorted(fig.replay.givens.items())}
    rows: dict[str, str] = {}
    for de, en in zip(phrases(fig, "de", construction), phrases(fig, "en", construction)):
        if " = " in de and " = " in en:
            k, v_de = de.split(" = ", 1)
            v_en = en.split(" = ", 1)[1]
            rows[k] = v_de if v_de == v_en else f"{v_de} / {v_en}"
        else:
            rows[de] = en if en != de else ""
    return rows


def citation(construction: Described | None, lang: str, *, after: bool = True) -> str:
    """The texts a construction follows, as a reader finds them: author, title, figure ("after" them, or not).

    >>> from construct.constructions import get
    >>> citation(get("tangential-pressure"), "de")
    'nach A. Baumann, Schwungradgewichte (1902), Fig. 26/27'
    >>> citation(get("two-cranks"), "en", after=False)
    '§ 146–147, two cranks at 90°, Fig. 566'
    """
    parts = "; ".join(", ".join(x for x in (c.book.author, c.book.title(lang), c.figure) if x)
                      for c in (construction.cites if construction is not None else ()))
    if not parts or not after:
        return parts
    return ("nach " if lang == "de" else "after ") + parts


def signed(v: float, decimals: int = 2, *, minus: str = "-") -> str:
    """*v* with its sign to *decimals* places; a value that rounds to nothing has none (0.00, never -0.00).

    >>> signed(-0.67), signed(0.67), signed(0.004), signed(-0.004), signed(-2.5, 1, minus="−")
    ('-0.67', '+0.67', '0.00', '0.00', '−2.5')
    """
    text = f"{v:+.{decimals}f}"
    if float(text) == 0.0:
        return f"{0.0:.{decimals}f}"
    return text.replace("-", minus)


def caption(construction: Described | None, fig: Drawn, number_: int | str | None = None,
            *, plate: bool = True) -> tuple[str, str]:
    """A figure's caption lines: "Fig. 12. Title. Givens. — after the book, figure." in German and English."""
    head = f"Fig. {number_}. " if number_ is not None else ("Fig. " if plate else "")
    if construction is None:
        name = fig.protocol.construction
        return (f"{head}{name}.", f"{head}{name}.")
    de_g, en_g = givens(fig, construction)
    out = []
    for lang, title, g in (("de", construction.title.de, de_g), ("en", construction.title.en, en_g)):
        # what a figure must say beyond its givens (the 990-kg plate shows the high-pressure diagram)
        special = construction.note(fig, lang) if construction.note is not None else ""
        body = f"{head}{title.rstrip('.')}"
        body += f"; {special}" if special else ""
        if g[:2].isalpha():  # a word ("unendlich lange Schubstangen"), not a symbol (r/L, κ)
            g = g[:1].upper() + g[1:]
        body += f". {g}" if g else ""
        cite = citation(construction, lang)
        out.append(f"{body}. — {cite}." if cite else f"{body}.")
    return out[0], out[1]


def provenance(construction: Described | None, fig: Drawn, full: tuple[str, str] | None = None,
               legend: Mapping[str, tuple[str, str]] | None = None) -> dict[str, Any]:
    """Which text and which parameters, for the machine: the SVG's ``<desc id="provenance">``; *full*: the
    figure's whole caption (German, English) where the figure prints less of it (a plate); *legend*: what its
    letters stand for (letter -> (German, English))."""
    params = {k: v for k, v in fig.params.items() if k not in _PROTOCOL_KEYS}
    out: dict[str, Any] = {"construction": fig.protocol.construction, "params": params,
                           "givens": dict(fig.replay.givens)}
    if construction is not None:
        # the texts as a reader cites them, and by the names ``construct errata --book`` takes (a construction's
        # own source string is the developers')
        out["source"] = citation(construction, "en", after=False) or construction.source
        out["texts"] = [{"book": c.book.key, "figure": c.figure} for c in construction.cites]
    if full is not None:
        out["caption"] = {"de": full[0], "en": full[1]}
    if legend:
        out["legend"] = {k: {"de": de, "en": en} for k, (de, en) in legend.items()}
    return out


#: The longest text the metadata keeps of any one value (a protocol of the user's own may name itself
#: with megabytes): the figure stays bounded, the protocol keeps the whole.  As long as a figure's title may
#: be: a plate's whole caption (a compound engine's runs to 600 characters) is kept whole.
_META_TEXT = TITLE_LIMIT


def jsonable(v: Any) -> Any:
    if isinstance(v, str):
        return v if len(v) <= _META_TEXT else v[: _META_TEXT - 1] + "…"
    if isinstance(v, float):
        return v if math.isfinite(v) else str(v)
    if isinstance(v, (list, tuple)):
        return [jsonable(x) for x in v]
    if isinstance(v, Mapping):
        return {jsonable(str(k)): jsonable(x) for k, x in v.items()}
    if isinstance(v, (int, bool)) or v is None:
        return v
    try:
        return jsonable(v.tolist())
    except AttributeError:
        return str(v)


def with_provenance(svg: str, construction: Described | None, fig: Drawn, full: tuple[str, str] | None = None,
                    legend: Mapping[str, tuple[str, str]] | None = None) -> str:
    """*svg* (a standalone file's text) with ``<desc id="provenance">`` holding the provenance as JSON, first in the root
    (*full*, *legend*: the whole caption of a plate and its letters' legend, :func:`provenance`).

    The element is serialised by ElementTree (which escapes the text) and set in after the root's
    start tag, which follows the XML declaration.
    """
    import xml.etree.ElementTree as ET

    data = json.dumps(jsonable(provenance(construction, fig, full, legend)), sort_keys=True, ensure_ascii=False)
    meta = ET.Element("desc", id="provenance")
    meta.text = data
    markup = ET.tostring(meta, encoding="unicode")
    decl = svg.find("?>")
    j = svg.find(">", decl + 2 if decl >= 0 else 0)
    if j < 0:
        return svg
    return svg[: j + 1] + "\n" + markup + svg[j + 1:]
