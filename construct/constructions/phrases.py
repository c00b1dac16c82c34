"""How the books write a construction: the texts it follows, and its givens in their symbols and units.

Every construction carries its own notation (:class:`construct.constructions.Construction`:
``cites``, ``wording``, ``methods``, ``conventions``, ``note``); the renderer reads it there and keeps
no table of constructions.  This module holds what several constructions share: the four source
texts as they introduce themselves (the Baumann article names its author, title and volume; the three
book excerpts carry no title page, so they are cited by the section and figures they print), and the
phrases their givens are written in -- the rod as the text writes it (r/L = 1/5 in Anhang II and in
Baumann, r/l in § 146), the semicircle's division and its method, Baumann's diagram, a digitised
card, the cranks of a revolution -- the German with the decimal comma, the English with the point.

>>> ratio("r/L", 5.0, "de"), metres(0.4, "de"), percent(0.3, "en")
('r/L = 1/5', '0,4', '30 %')
>>> Cite(BAUMANN_1902, "Fig. 28").book.title("de")
'Schwungradgewichte (1902)'
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, Mapping

from ..kernel.division import NAMES as DIVISION_NAMES
from ..kernel.errors import InvalidParameter
from ..kernel.letters import number

__all__ = ["Book", "Cite", "ANHANG_II", "HANDBOOK", "COMBUSTION", "MECHANICS", "BAUMANN_1902", "BOOKS", "book", "number", "ratio",
           "metres", "percent", "division", "stroke_parts", "scale", "diagram", "card", "revolution", "low_pressure"]


@dataclass(frozen=True)
class Book:
    """A source text as it names itself: author (when it says), title, where and when it was printed, what it teaches.

    *key*: its name, what a reader types and finds (``construct errata --book baumann``,
    ``errata-baumann.html``); *number*: the number of its text among the project's sources, which the old
    ``--seed NNN`` still takes and no reader is shown.
    """

    key: str
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
    number: str = ""

    def title(self, lang: str) -> str:
        """The title a caption cites in *lang* ("de" or "en")."""
        return self.short or (self.title_de if lang == "de" else self.title_en)

    def cited(self, lang: str = "en") -> str:
        """The book as a line cites it: author and title.

        >>> BAUMANN_1902.cited(), MECHANICS.cited("de")
        ('A. Baumann, Schwungradgewichte (1902)', '§ 146–147, Zwei Kurbeln unter 90°')
        """
        return ", ".join(x for x in (self.author, self.title(lang)) if x)


@dataclass(frozen=True)
class Cite:
    """A text and the figure (or table) in it that a construction follows, as the text numbers it."""

    book: Book
    figure: str


# The Baumann article names its author, title and volume; the three book excerpts carry no title page, so they
# are cited by the section and figures they print, and dated by their spelling where they say nothing.
ANHANG_II = Book("anhang-ii", None, "Anhang II, „Darstellung der Massendrücke“",
                 "Anhang II, „Darstellung der Massendrücke“",
                 year="undated; its spelling (Werthe, Curve, construiren) is that of before 1901",
                 teaches="the curve of the inertia pressures of the reciprocating masses over the stroke: by "
                         "calculation (Tabellen 1 and 2), by construction (Fig. 77–79), its characteristic points "
                         "and its tangents", number="000")
HANDBOOK = Book("handbook", None, "„Einfluß der Massenkräfte“, Maschine Tafel I",
                "„Einfluß der Massenkräfte“, engine of Tafel I",
                year="undated; it names Diesel engines and spells Zylinder: after 1900",
                teaches="the piston over-pressure line of a compound engine's high-pressure cylinder with the mass "
                        "forces (Abb. 1051–1055), and the pressures of four-stroke engines (Abb. 1056–1058)",
                number="001")
MECHANICS = Book("mechanics", None, "§ 146–147, Zwei Kurbeln unter 90°", "§ 146–147, two cranks at 90°",
                 year="undated; its spelling (Todtlage, Ueberschuß) is that of before 1901",
                 teaches="two cranks at right angles on one shaft: the work the masses take up and give back, and "
                         "the shaft's speed fluctuation as a polar diagram (Fig. 566), for infinite and finite rods",
                 number="002")
BAUMANN_1902 = Book("baumann", "A. Baumann", "Ein neues Verfahren zur Bestimmung der Schwungradgewichte von Dampfmaschinen",
                    "Ein neues Verfahren zur Bestimmung der Schwungradgewichte von Dampfmaschinen",
                    "Dinglers Polytechnisches Journal, Bd. 317, S. 341", short="Schwungradgewichte (1902)",
                    year="1902", teaches="a new method for flywheel weights: the steam diagram, the "
                    "tangential-pressure diagram and its excess area, rim, arms and hub, with his own error "
                    "analysis and tables", number="004")
#: The handbook's section on combustion engines, "c) Die Kraftwirkungen in Verbrennungsmaschinen": the same
#: book as Tafel I's steam engine (its name, number, year), cited by the section's own title, since its figures
#: Abb. 1056-1058 are the engines', not Tafel I's.
COMBUSTION = replace(HANDBOOK, title_de="„Die Kraftwirkungen in Verbrennungsmaschinen“",
                     title_en="„Die Kraftwirkungen in Verbrennungsmaschinen“ (force effects in combustion engines)")
#: The four source texts by their names, in the order of their files (a section cited by its own title, as
#: COMBUSTION, is found by its book's name).
BOOKS: dict[str, Book] = {b.key: b for b in (ANHANG_II, HANDBOOK, MECHANICS, BAUMANN_1902)}


def book(name: str) -> Book:
    """The source text a reader names: by its name, or by the number of its text (the old ``--seed``).

    >>> book("baumann").author, book("004").key
    ('A. Baumann', 'baumann')
    >>> book("003")
    Traceback (most recent call last):
    ...
    construct.kernel.errors.InvalidParameter: no book '003'; the books: anhang-ii, handbook, mechanics, baumann
    """
    found = BOOKS.get(name) if isinstance(name, str) else None
    found = found or next((b for b in BOOKS.values() if isinstance(name, str) and name == b.number), None)
    if found is None:
        raise InvalidParameter(f"no book {name!r}; the books: {', '.join(BOOKS)}")
    return found


def metres(v: float, lang: str) -> str:
    """A length in metres with one decimal at least, as Tafel I writes R = 0,4 m, L = 2,0 m."""
    text = f"{float(v):.1f}" if abs(v - round(v, 1)) < 1e-9 else number(v, "en")
    return text.replace(".", ",") if lang == "de" else text


def percent(v: float, lang: str) -> str:
    return number(100.0 * v, lang, 3) + " %"


def ratio(name: str, rod_ratio: float, lang: str) -> str:
    """The rod as the text writes it: r/L = 1/5 (Anhang II, Baumann), r/l = 1/5 (§ 146)."""
    return f"{name} = 1/{number(rod_ratio, lang)}"


def division(fig: Any, lang: str) -> str:
    """The semicircle's division: its parts and, unless it is by compass and straightedge, its method."""
    n = fig.params.get("parts")
    method = DIVISION_NAMES.get(str(fig.params.get("method")))
    de, en = f"Halbkreis in {n} Teilen", f"semicircle in {n} parts"
    if method and fig.params.get("method") != "exact":  # compass and straightedge go without saying
        de, en = f"{de} ({method.de})", f"{en} ({method.en})"
    return de if lang == "de" else en


def stroke_parts(fig: Any, lang: str) -> str:
    """The stroke's division into equal parts (tenths, unless the figure says)."""
    n = fig.params.get("divisions", 10)
    return f"Hub in {n} Teilen" if lang == "de" else f"stroke in {n} parts"


def scale(g: Mapping[str, float], lang: str, unit: str = "r") -> str:
    """The pressure scale: 1 at drawn as so many crank radii."""
    v = number(g["pressure_unit"], lang)
    return f"1 at als {v} {unit} gezeichnet" if lang == "de" else f"1 at drawn as {v} {unit}"


def diagram(g: Mapping[str, float], lang: str) -> list[str]:
    """Baumann's givens of the steam diagram: P, P0, s1, s0, s3 (as fractions of the stroke s)."""
    de = lang == "de"
    return [f"P = {number(g['admission'], lang)} at", f"P₀ = {number(g['back_pressure'], lang)} at",
            f"s₁ = {percent(g['filling'], lang)} s", f"s₀ = {percent(g['clearance'], lang)} s",
            f"s₃ = {percent(g['compression'], lang)} s" + (" (Kompression)" if de else " (compression)")]


def card(fig: Any, lang: str) -> list[str]:
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


def revolution(fig: Any, lang: str) -> list[str]:
    """A diagram over the whole revolution: the machine and its cranks ([] for one stroke)."""
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


def low_pressure(fig: Any, lang: str) -> list[str]:
    """A compound or tandem engine's low-pressure cylinder with a diagram of its own: its givens, its area ratio."""
    g = fig.replay.givens
    if "area_ratio" not in g:
        return []
    de = lang == "de"
    head = "Niederdruck: " if de else "low pressure: "
    if "lp.admission" in g:
        own = (f"P = {number(g['lp.admission'], lang)} at, P₀ = {number(g['lp.back_pressure'], lang)} at, "
               f"s₁ = {percent(g['lp.filling'], lang)} s, s₃ = {percent(g['lp.compression'], lang)} s")
    else:
        count = sum(1 for k in g if k.startswith("lp.card.x"))
        own = f"Indikatordiagramm aus {count} Punkten" if de else f"indicator card of {count} points"
    return [head + own, ("Kolbenfläche ND/HD = " if de else "piston area LP/HP = ") + number(g["area_ratio"], lang)]
