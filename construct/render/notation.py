"""The books' notation for what a reader sees: figure captions, givens, sources.

A figure's caption names the figure, its title and its givens in the symbols
and units of the book it comes from -- the German line with the decimal comma
(``G = 830 kg, n = 50/min, R = 0,4 m, L = 2,0 m``), the English line with the
point -- and cites the book by author, title and figure, never by a file of
this repository.  Which text and which parameters exactly (the machine's
view) go into the SVG's ``<desc>`` and the protocol.

:data:`BOOKS` lists the four source texts as they introduce themselves: the
Baumann article names its author, title and volume; the three book excerpts
carry no title page, so they are cited by the section and figures they print.
:func:`givens` writes a construction's givens as its book does (Baumann's κ
for the tangential pressure, r/L where the book writes r/L, r/l in § 146).

>>> from construct.constructions import get
>>> de, en = givens(get("piston-force").figure(parts=9))
>>> de
'G = 830 kg, n = 50/min, R = 0,4 m, L = 2,0 m, F = 1529,1 cm², p₁ = 7 at, p₂ = 2 at, Füllung 30 %, schädlicher Raum 8 %, Kompression 15 %, Halbkreis in 9 Teilen (Dürers Dreiteilung)'
>>> en.split(", ")[:4]
['G = 830 kg', 'n = 50/min', 'R = 0.4 m', 'L = 2.0 m']
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Callable, Mapping

if TYPE_CHECKING:
    from ..constructions import Construction
    from ..figure import Figure

__all__ = ["Book", "BOOKS", "CITED", "book", "cited_as", "signed", "givens", "given_rows", "citation", "caption", "provenance", "with_provenance", "number"]


@dataclass(frozen=True)
class Book:
    """A source text as it names itself: author (when it says), title, where it was printed, what it teaches."""

    #: What a reader types and finds: ``construct errata --book baumann``, ``errata-baumann.html``.
    name: str
    author: str | None
    title_de: str
    title_en: str
    where: str = ""
    #: The title a caption cites (the full one is long for a line under a figure).
    short: str = ""
    #: When it was printed, as the text says, or what dates an excerpt that does not say.
    year: str = ""
    #: What a reader learns from it, in a sentence (the gallery's front page).
    teaches: str = ""
    #: The number of its text among the project's sources (``shared/seeds/NNN_*.txt``): the old
    #: ``--seed NNN`` still names it.  Never shown to a reader.
    number: str = ""


#: The four source texts, in the order of their files.  The Baumann article names its author, title and
#: volume; the three book excerpts carry no title page, so they are cited by the section and figures they
#: print (and dated by their spelling where they say nothing).
BOOKS: dict[str, Book] = {b.name: b for b in (
    Book("anhang-ii", None, "Anhang II, „Darstellung der Massendrücke“",
         "Anhang II, „Darstellung der Massendrücke“",
         year="undated; its spelling (Werthe, Curve, construiren) is that of before 1901",
         teaches="the curve of the inertia pressures of the reciprocating masses over the stroke: by calculation "
                 "(Tabellen 1 and 2), by construction (Fig. 77–79), its characteristic points and its tangents",
         number="000"),
    Book("handbook", None, "„Einfluß der Massenkräfte“, Maschine Tafel I",
         "„Einfluß der Massenkräfte“, engine of Tafel I",
         year="undated; it names Diesel engines and spells Zylinder: after 1900",
         teaches="the piston over-pressure line of a compound engine's high-pressure cylinder with the mass forces "
                 "(Abb. 1051–1055), and the pressures of four-stroke engines (Abb. 1056–1058)",
         number="001"),
    Book("mechanics", None, "§ 146–147, Zwei Kurbeln unter 90°", "§ 146–147, two cranks at 90°",
         year="undated; its spelling (Todtlage, Ueberschuß) is that of before 1901",
         teaches="two cranks at right angles on one shaft: the work the masses take up and give back, and the "
                 "shaft's speed fluctuation as a polar diagram (Fig. 566), for infinite and finite rods",
         number="002"),
    Book("baumann", "A. Baumann", "Ein neues Verfahren zur Bestimmung der Schwungradgewichte von Dampfmaschinen",
         "Ein neues Verfahren zur Bestimmung der Schwungradgewichte von Dampfmaschinen",
         "Dinglers Polytechnisches Journal, Bd. 317, S. 341", short="Schwungradgewichte (1902)", year="1902",
         teaches="a new method for flywheel weights: the steam diagram, the tangential-pressure diagram and its "
                 "excess area, rim, arms and hub, with his own error analysis and tables",
         number="004"),
)}

#: Per construction: the (book, figure) pairs it follows, the figure as the text numbers it.
CITED: dict[str, tuple[tuple[str, str], ...]] = {
    "crank": (("handbook", "Abb. 1051/1054"), ("anhang-ii", "Fig. 77")),
    "crank-angle": (("anhang-ii", "Fig. 77, Tabelle 2"),),
    "inertia-curve": (("anhang-ii", "Fig. 78/79, Tabelle 1"),),
    "inertia-stroke-fractions": (("anhang-ii", "Tabelle 2"),),
    "indicator-diagram": (("baumann", "Fig. 25"),),
    "piston-force": (("handbook", "Abb. 1054/1055"), ("baumann", "Fig. 25")),
    "tangential-pressure": (("baumann", "Fig. 26/27"),),
    "two-cranks": (("mechanics", "Fig. 566"),),
    "four-stroke": (("handbook", "Abb. 1056–1058"),),
    "flywheel-rim": (("baumann", "Fig. 28"),),
}


def book(name: str) -> Book:
    """The source text a reader names: by its name, or by the number of its text file (the old ``--seed``).

    >>> book("baumann").author, book("004").name
    ('A. Baumann', 'baumann')
    >>> book("003")
    Traceback (most recent call last):
    ...
    construct.kernel.errors.InvalidParameter: no book '003'; the books: anhang-ii, handbook, mechanics, baumann
    """
    from ..kernel.errors import InvalidParameter

    found = BOOKS.get(name) if isinstance(name, str) else None
    found = found or next((b for b in BOOKS.values() if isinstance(name, str) and name == b.number), None)
    if found is None:
        raise InvalidParameter(f"no book {name!r}; the books: {', '.join(BOOKS)}")
    return found


def cited_as(b: Book, lang: str = "en") -> str:
    """A book as a reader cites it: author, title (the short one where there is one), year.

    >>> cited_as(BOOKS["baumann"]), cited_as(BOOKS["mechanics"], "de")
    ('A. Baumann, Schwungradgewichte (1902)', '§ 146–147, Zwei Kurbeln unter 90°')
    """
    title = b.short or (b.title_de if lang == "de" else b.title_en)
    return ", ".join(x for x in (b.author, title) if x)


def number(v: float, lang: str, digits: int = 4) -> str:
    """*v* as the books print it: at most *digits* significant digits, the decimal comma in German.

    >>> number(0.4, "de"), number(0.4, "en"), number(1529.0720493, "de", 5), number(50.0, "de")
    ('0,4', '0.4', '1529,1', '50')
    """
    text = f"{float(v):.{digits}g}"
    if "e" in text:
        text = f"{float(v):.{digits}f}".rstrip("0").rstrip(".")
    return text.replace(".", ",") if lang == "de" else text


def signed(v: float, decimals: int = 2, *, minus: str = "-") -> str:
    """*v* with its sign to *decimals* places; a value that rounds to nothing has none (0.00, never -0.00).

    >>> signed(-0.67), signed(0.67), signed(0.004), signed(-0.004), signed(-2.5, 1, minus="−")
    ('-0.67', '+0.67', '0.00', '0.00', '−2.5')
    """
    text = f"{v:+.{decimals}f}"
    if float(text) == 0.0:
        return f"{0.0:.{decimals}f}"
    return text.replace("-", minus)


def _metres(v: float, lang: str) -> str:
    """A length in metres with one decimal at least, as Tafel I writes R = 0,4 m, L = 2,0 m."""
    text = f"{float(v):.1f}" if abs(v - round(v, 1)) < 1e-9 else number(v, "en")
    return text.replace(".", ",") if lang == "de" else text


def _percent(v: float, lang: str) -> str:
    return number(100.0 * v, lang, 3) + " %"


def _ratio(name: str, rod_ratio: float, lang: str) -> str:
    """The rod as the text writes it: r/L = 1/5 (Anhang II, Baumann), r/l = 1/5 (§ 146)."""
    return f"{name} = 1/{number(rod_ratio, lang)}"


_DIVISION = {
    "durer": ("Dürers Dreiteilung", "Dürer's trisection"),
    "exact": ("mit Zirkel und Lineal", "by compass and straightedge"),
    "neusis": ("Einschiebung", "neusis"),
    "dividers": ("mit dem Stechzirkel probiert", "with the dividers by trial"),
}


def _parts(fig: "Figure", lang: str) -> str:
    n = fig.params.get("parts")
    method = _DIVISION.get(str(fig.params.get("method")))
    de, en = f"Halbkreis in {n} Teilen", f"semicircle in {n} parts"
    if method and fig.params.get("method") != "exact":  # compass and straightedge go without saying
        de, en = f"{de} ({method[0]})", f"{en} ({method[1]})"
    return de if lang == "de" else en


def _scale(g: Mapping[str, float], lang: str, unit: str = "r") -> str:
    v = number(g["pressure_unit"], lang)
    return f"1 at als {v} {unit} gezeichnet" if lang == "de" else f"1 at drawn as {v} {unit}"


def _crank(fig: "Figure", lang: str) -> list[str]:
    return [_ratio("r/L", fig.replay.givens["rod_ratio"], lang), _parts(fig, lang)]


def _crank_angle(fig: "Figure", lang: str) -> list[str]:
    n = fig.params.get("divisions", 10)
    return [_ratio("r/L", fig.replay.givens["rod_ratio"], lang),
            f"Hub in {n} Teilen" if lang == "de" else f"stroke in {n} parts"]


def _inertia(fig: "Figure", lang: str) -> list[str]:
    g = fig.replay.givens
    out = [_ratio("r/L", g["rod_ratio"], lang), f"F/f = {number(g['pressure_ratio'], lang)} at", _scale(g, lang)]
    if "parts" in fig.params:
        out.append(_parts(fig, lang))
    else:
        n = fig.params.get("divisions", 10)
        out.append(f"Hub in {n} Teilen" if lang == "de" else f"stroke in {n} parts")
    return out


def _diagram(g: Mapping[str, float], lang: str) -> list[str]:
    """Baumann's givens of the steam diagram: P, P0, s1, s0, s3 (as fractions of the stroke s)."""
    de = lang == "de"
    return [f"P = {number(g['admission'], lang)} at", f"P₀ = {number(g['back_pressure'], lang)} at",
            f"s₁ = {_percent(g['filling'], lang)} s", f"s₀ = {_percent(g['clearance'], lang)} s",
            f"s₃ = {_percent(g['compression'], lang)} s" + (" (Kompression)" if de else " (compression)")]


def _indicator(fig: "Figure", lang: str) -> list[str]:
    g = fig.replay.givens
    if "admission" not in g:  # a digitised card, not Baumann's idealised diagram
        return _card(fig, lang) + [_scale(g, lang, "r")]
    return _diagram(g, lang) + [_scale(g, lang, "r")]


def _piston_force(fig: "Figure", lang: str) -> list[str]:
    g = fig.replay.givens
    de = lang == "de"
    out = [f"G = {number(g['weight'], lang)} kg", f"n = {number(g['rpm'], lang)}/min",
           f"R = {_metres(g['crank_radius'], lang)} m", f"L = {_metres(g['rod_length'], lang)} m",
           f"F = {number(g['piston_area'], lang, 5)} cm²"]
    if "admission" in g:  # Baumann's idealised diagram (a digitised card says itself, below)
        out += [f"p₁ = {number(g['admission'], lang)} at", f"p₂ = {number(g['back_pressure'], lang)} at",
                ("Füllung " if de else "cut-off ") + _percent(g["filling"], lang),
                ("schädlicher Raum " if de else "clearance ") + _percent(g["clearance"], lang),
                ("Kompression " if de else "compression ") + _percent(g["compression"], lang)]
    out.append(_parts(fig, lang))
    if fig.params.get("revolution"):  # both sides, each with its own area (Tafel I: F', F'')
        out[4] = (f"F′ = {number(g['piston_area_cover'], lang, 6)} cm² (Deckelseite), "
                  f"F″ = {number(g['piston_area_crank'], lang, 6)} cm² (Kurbelseite), Hin- und Rückgang" if de else
                  f"F′ = {number(g['piston_area_cover'], lang, 6)} cm² (cover side), "
                  f"F″ = {number(g['piston_area_crank'], lang, 6)} cm² (crank side), both strokes")
    return out + _card(fig, lang)


def _card(fig: "Figure", lang: str) -> list[str]:
    """A digitised indicator card among the givens (card.x0, card.p0, ...): how many points, which side mirrored."""
    g = fig.replay.givens
    de = lang == "de"
    out = []
    for side, name in (("card", ("Indikatordiagramm", "indicator card")), ("crank", ("Kurbelseite", "crank side"))):
        count = sum(1 for k in g if k.startswith(f"{side}.x"))
        if count:
            out.append(f"{name[0 if de else 1]} aus {count} Punkten" if de else f"{name[1]} of {count} points")
    if out and not any(k.startswith("crank.x") for k in g):
        out.append("Kurbelseite gespiegelt (Baumann)" if de else "crank side mirrored (Baumann)")
    return out


def _revolution(fig: "Figure", lang: str) -> list[str]:
    """A tangential diagram over the whole revolution: the machine and its cranks."""
    if not fig.params.get("revolution"):
        return []
    de = lang == "de"
    machine = str(fig.params.get("machine", "single"))
    names = {"single": ("Eincylindermaschine", "single-cylinder engine"),
             "tandem": ("Tandemmaschine", "tandem engine"), "compound": ("Verbundmaschine", "compound engine")}
    offsets = [float(v) for v in (fig.params.get("offsets") or (0.0,))]
    cranks = ", ".join(f"{number(v, lang)}°" for v in offsets)
    return [names.get(machine, (machine, machine))[0 if de else 1],
            (f"Kurbeln bei {cranks}" if de else f"cranks at {cranks}") if len(offsets) > 1 else "",
            "über eine Umdrehung" if de else "over a revolution"]


def _low_pressure(fig: "Figure", lang: str) -> list[str]:
    """A compound or tandem engine's low-pressure cylinder with a diagram of its own: its givens, its area ratio."""
    g = fig.replay.givens
    if "area_ratio" not in g:
        return []
    de = lang == "de"
    head = "Niederdruck: " if de else "low pressure: "
    if "lp.admission" in g:
        own = (f"P = {number(g['lp.admission'], lang)} at, P₀ = {number(g['lp.back_pressure'], lang)} at, "
               f"s₁ = {_percent(g['lp.filling'], lang)} s, s₃ = {_percent(g['lp.compression'], lang)} s")
    else:
        count = sum(1 for k in g if k.startswith("lp.card.x"))
        own = f"Indikatordiagramm aus {count} Punkten" if de else f"indicator card of {count} points"
    return [head + own, ("Kolbenfläche ND/HD = " if de else "piston area LP/HP = ") + number(g["area_ratio"], lang)]


def _tangential(fig: "Figure", lang: str) -> list[str]:
    g = fig.replay.givens
    if fig.params.get("force") == "unit":
        return [x for x in [_ratio("r/L", g["rod_ratio"], lang), "P′ = r", *_revolution(fig, lang), _parts(fig, lang),
                            *_card(fig, lang)] if x]
    # κ = P/B_max (Baumann): the construction keeps c v²/r = P/((1 + r/L) κ) as its given.
    if "admission" not in g:  # a digitised card's force
        return [x for x in [_ratio("r/L", g["rod_ratio"], lang), *_revolution(fig, lang), _parts(fig, lang),
                            *_card(fig, lang), *_low_pressure(fig, lang)] if x]
    kappa = g["admission"] / (g["pressure_ratio"] * (1.0 + 1.0 / g["rod_ratio"]))
    out = ([f"κ = P/Bmax = {number(round(kappa, 9), lang)}", _ratio("r/L", g["rod_ratio"], lang)]
           + _diagram(g, lang) + [_scale(g, lang), _parts(fig, lang)])
    if "lp.admission" in g:  # two cylinders, two diagrams: say whose the first givens are
        out[2] = ("Hochdruck: " if lang == "de" else "high pressure: ") + out[2]
    if fig.params.get("revolution"):  # the return stroke from the same diagram: Baumann's assumption, said
        out = [x for x in _revolution(fig, lang) if x] + out + [
            "Rückgang: dasselbe Diagramm gespiegelt (Baumanns Annahme)" if lang == "de"
            else "return stroke: the same diagram mirrored (Baumann's assumption)"]
        out += _low_pressure(fig, lang)
    return out


def _two_cranks(fig: "Figure", lang: str) -> list[str]:
    g = fig.replay.givens
    de = lang == "de"
    rod = (("unendlich lange Schubstangen" if de else "infinitely long rods") if fig.params.get("infinite_rod")
           else _ratio("r/l", g["rod_ratio"], lang))
    n = fig.params.get("parts")
    start = ((("ab der äußeren Totlage B₁ (§ 146)" if de else "from the crank-end dead centre B₁ (§ 146)")
              if fig.params.get("dead_centre", "head-end") == "crank-end"
              else ("ab der deckelseitigen Totlage" if de else "from the head-end dead centre")))
    return [rod, start, f"Qr/((m₁ + m₂)v₁²) = {number(g['fluctuation'], lang)}",
            (f"Schwankungen {number(g['magnify'], lang)}fach vergrößert" if de
             else f"speed deviations magnified {number(g['magnify'], lang)} times"),
            f"Kreis in {2 * int(n)} Teilen" if de else f"circle in {2 * int(n)} parts"]


def _four_stroke(fig: "Figure", lang: str) -> list[str]:
    g = fig.replay.givens
    de = lang == "de"
    diesel = fig.params.get("engine") == "diesel"
    out = [("Gleichdruckmaschine" if de else "compression-ignition engine") if diesel
           else ("Verpuffungsmaschine" if de else "explosion engine"),
           f"ε = {number(g['compression_ratio'], lang)}", f"n = {number(g['exponent'], lang)}"]
    out.append(f"ρ = {number(fig.params.get('cutoff', 2.0), lang)}" if diesel
               else ("Höchstdruck " if de else "peak pressure ") + f"{number(g['max_pressure'], lang)} at")
    out += [_ratio("r/L", g["rod_ratio"], lang), f"q = {number(g['pressure_ratio'], lang)} at"]
    return out


def _flywheel_rim(fig: "Figure", lang: str) -> list[str]:
    g = fig.replay.givens
    return [f"b₁ = {number(g['b1'], lang)} r₁", ("Kranz " if lang == "de" else "rim ") + f"{number(g['rim'], lang)} r₁"]


_GIVENS: dict[str, Callable[["Figure", str], list[str]]] = {
    "crank": _crank, "crank-angle": _crank_angle, "inertia-curve": _inertia, "inertia-stroke-fractions": _inertia,
    "indicator-diagram": _indicator, "piston-force": _piston_force, "tangential-pressure": _tangential,
    "two-cranks": _two_cranks, "four-stroke": _four_stroke, "flywheel-rim": _flywheel_rim,
}


def givens(fig: "Figure") -> tuple[str, str]:
    """The figure's givens in its book's symbols and units: (German, English); ("", "") for an unknown construction."""
    fn = _GIVENS.get(fig.protocol.construction)
    if fn is None:
        return "", ""
    return ", ".join(fn(fig, "de")), ", ".join(fn(fig, "en"))


def given_rows(fig: "Figure") -> dict[str, str]:
    """The givens as the player's table shows them: symbol -> value, German / English where they differ.

    >>> from construct.constructions import get
    >>> rows = given_rows(get("piston-force").figure(parts=9))
    >>> rows["R"], rows["Füllung 30 %"], list(rows)[:3]
    ('0,4 m / 0.4 m', 'cut-off 30 %', ['G', 'n', 'R'])
    """
    fn = _GIVENS.get(fig.protocol.construction)
    if fn is None:  # a protocol of the user's own: its givens by name
        return {k: number(v, "en", 6) if isinstance(v, float) else str(v) for k, v in sorted(fig.replay.givens.items())}
    rows: dict[str, str] = {}
    for de, en in zip(fn(fig, "de"), fn(fig, "en")):
        if " = " in de and " = " in en:
            k, v_de = de.split(" = ", 1)
            v_en = en.split(" = ", 1)[1]
            rows[k] = v_de if v_de == v_en else f"{v_de} / {v_en}"
        else:
            rows[de] = en if en != de else ""
    return rows


def citation(name: str, lang: str, *, after: bool = True) -> str:
    """The texts a construction follows, as a reader finds them: author, title, figure ("after" them, or not).

    >>> citation("tangential-pressure", "de")
    'nach A. Baumann, Schwungradgewichte (1902), Fig. 26/27'
    >>> citation("two-cranks", "en", after=False)
    '§ 146–147, two cranks at 90°, Fig. 566'
    """
    parts = "; ".join(f"{cited_as(BOOKS[key], lang)}, {fig}" for key, fig in CITED.get(name, ()))
    if not parts or not after:
        return parts
    return ("nach " if lang == "de" else "after ") + parts


def _special(fig: "Figure", lang: str) -> str:
    """What a figure must say beyond its givens (the 990-kg plate shows the high-pressure diagram)."""
    if fig.protocol.construction == "piston-force" and fig.replay.givens.get("weight") == 990.0:
        return ("Massen der Niederdruckseite (990 kg) über dem Dampfdiagramm der Hochdruckseite" if lang == "de" else
                "low-pressure side's masses (990 kg) over the high-pressure side's steam diagram")
    return ""


def caption(construction: "Construction | None", fig: "Figure", number_: int | str | None = None,
            *, plate: bool = True) -> tuple[str, str]:
    """A figure's caption lines: "Fig. 12. Title. Givens. — after the book, figure." in German and English."""
    head = f"Fig. {number_}. " if number_ is not None else ("Fig. " if plate else "")
    if construction is None:
        name = fig.protocol.construction
        return (f"{head}{name}.", f"{head}{name}.")
    de_g, en_g = givens(fig)
    out = []
    for lang, title, g in (("de", construction.title.de, de_g), ("en", construction.title.en, en_g)):
        special = _special(fig, lang)
        body = f"{head}{title.rstrip('.')}"
        body += f"; {special}" if special else ""
        if g[:2].isalpha():  # a word ("unendlich lange Schubstangen"), not a symbol (r/L, κ)
            g = g[:1].upper() + g[1:]
        body += f". {g}" if g else ""
        cite = citation(construction.name, lang)
        out.append(f"{body}. — {cite}." if cite else f"{body}.")
    return out[0], out[1]


def provenance(construction: "Construction | None", fig: "Figure") -> dict[str, Any]:
    """Which text and which parameters, for the machine: the SVG's ``<desc id="provenance">``."""
    params = {k: v for k, v in fig.params.items() if k not in ("group_titles", "plate", "captions", "givens")}
    out: dict[str, Any] = {"construction": fig.protocol.construction, "params": params,
                           "givens": dict(fig.replay.givens)}
    if construction is not None:
        # the texts as a reader cites them (a construction's own source string is the developers')
        out["source"] = citation(construction.name, "en", after=False) or construction.source
        out["texts"] = [{"book": key, "figure": figfig} for key, figfig in CITED.get(construction.name, ())]
    return out


#: The longest text the metadata keeps of any one value (a protocol of the user's own may name itself
#: with megabytes): the figure stays bounded, the protocol keeps the whole.
_META_TEXT = 200


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


def with_provenance(svg: str, construction: "Construction | None", fig: "Figure") -> str:
    """*svg* (a standalone file's text) with ``<desc id="provenance">`` holding the provenance as JSON, first in the root.

    The element is serialised by ElementTree (which escapes the text) and set in after the root's
    start tag, which follows the XML declaration.
    """
    import xml.etree.ElementTree as ET

    data = json.dumps(jsonable(provenance(construction, fig)), sort_keys=True, ensure_ascii=False)
    meta = ET.Element("desc", id="provenance")
    meta.text = data
    markup = ET.tostring(meta, encoding="unicode")
    decl = svg.find("?>")
    j = svg.find(">", decl + 2 if decl >= 0 else 0)
    if j < 0:
        return svg
    return svg[: j + 1] + "\n" + markup + svg[j + 1:]
