"""The gallery's pages for people (construct.render.site): errata pages a historian reads, the front page, checks.

The expectations come from the errata themselves (construct.books.errata), from the legend the command line
prints (``construct errata --classes``), from the source texts (../shared/seeds) and from the issue that asked
for the pages -- not from the pages' own output.
"""

from __future__ import annotations

import functools
import re
from html.parser import HTMLParser

import pytest

from construct.books.errata import CLASS_MEANINGS, WRONG, all_errata
from construct.cli.main import main
from construct.constructions.phrases import BOOKS
from construct.kernel.protocol import Caption
from construct.render.site import checks_page, errata_page, errata_slug, index_page

BOOK_NAMES = ("anhang-ii", "handbook", "mechanics", "baumann")
#: Raw LaTeX a reader must not meet: a command, an index or a power written out, a brace group.
RAW_LATEX = re.compile(r"\\[A-Za-z]+|[_^]|\{|\}")
#: A negative zero, or a value that rounds to nothing shown with a sign (the issue counted "−0.00" 25 times).
SIGNED_ZERO = re.compile(r"(?<![\d.,])[-−+]0(?:[.,]0+)?(?![\d.,]*[1-9])(?![\d])")
SEED = re.compile(r"\bseeds?\b", re.I)


class _Page(HTMLParser):
    """A page as a reader meets it: its visible text (no script, no style) by section, its elements."""

    def __init__(self, text: str):
        super().__init__()
        self.skip = 0
        self.chunks: list[str] = []   # visible text, in order
        self.marks: list[tuple[str, int]] = []  # (h2 text, index into chunks where it starts)
        self.tags: list[tuple[str, dict]] = []
        self._h2: list[str] | None = None
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))
        if tag in ("script", "style"):
            self.skip += 1
        if tag == "h2":
            self._h2 = []

    def handle_endtag(self, tag):
        if tag in ("script", "style"):
            self.skip -= 1
        if tag == "h2" and self._h2 is not None:
            self.marks.append(("".join(self._h2), len(self.chunks)))
            self._h2 = None

    def handle_data(self, data):
        if not self.skip:
            self.chunks.append(data)
            if self._h2 is not None:
                self._h2.append(data)

    @property
    def text(self) -> str:
        return "".join(self.chunks)

    def section(self, heading: str) -> str:
        """The visible text from the h2 *heading* to the next h2."""
        starts = [i for h, i in self.marks] + [len(self.chunks)]
        k = next(j for j, (h, _) in enumerate(self.marks) if h.startswith(heading))
        return "".join(self.chunks[starts[k]:starts[k + 1]])


@functools.cache
def _errata() -> tuple:
    """Every erratum, computed once for the module (each holds the true values the books are checked against)."""
    return tuple(all_errata())


def _rows(book: str) -> list[dict]:
    return [e.as_dict() for e in _errata() if e.source == book]


@pytest.fixture(scope="module")
def pages() -> dict[str, tuple[str, _Page]]:
    out = {}
    for book in BOOK_NAMES:
        text = errata_page(BOOKS[book], _rows(book), back="index.html", meanings=CLASS_MEANINGS, wrong=WRONG,
                           books=list(BOOKS.values()))
        out[book] = (text, _Page(text))
    return out


def test_each_book_has_errata_and_its_page_is_named_after_it():
    assert {e.source for e in all_errata()} == set(BOOK_NAMES) == set(BOOKS)
    assert [errata_slug(b) for b in BOOK_NAMES] == [f"errata-{b}.html" for b in BOOK_NAMES]


def _ascii(text: str) -> str:
    """*text* with the books' typography written back in ASCII (primes, minus, subscript digits), to compare
    a note as the errata module words it with the page that sets it as the books print."""
    return text.translate(str.maketrans("′″−₀₁₂₃₄₅₆₇₈₉", "'\"-0123456789")).replace('"', "''")


@pytest.mark.parametrize("book", BOOK_NAMES)
def test_an_errata_page_leads_with_what_is_wrong(pages, book):
    text, page = pages[book]
    headings = [h for h, _ in page.marks]
    assert headings[0] == "What is wrong" and headings.index("What is wrong") < headings.index("Every printed number")
    summary = page.section("What is wrong")
    wrong = [e for e in _rows(book) if e["class"] in WRONG]
    # each real error with its cause (the note) and its true value, in the summary
    for e in wrong:
        assert _ascii(re.sub(r"_\{?|\}", "", e["note"]))[:40] in _ascii(summary.replace("\n", " ")), e
        if isinstance(e["true"], float) and "°" not in e["printed"]:
            digits = f"{abs(e['true']):.8g}"[:5].replace(".", "," if "," in e["printed"] else ".")
            assert digits in summary, (digits, e)
    if not wrong:
        assert "Nothing" in summary and "<table" not in text[text.index("What is wrong"):text.index("The classes")]
        return
    summary_rows = text[text.index("What is wrong"):text.index("The classes")].count("<tr>") - 1  # less the head
    groups = len({e["class"] for e in wrong})
    assert summary_rows == len(wrong) + groups  # each error once, under its class's heading


def test_the_summary_names_anhang_iis_typeset_digit_with_its_true_value(pages):
    # Tabelle 1, 110°, L/r = 6: printed -0.5385; cos 110° + cos 220°/6 = -0.342020 - 0.127674 = -0.533531
    summary = pages["anhang-ii"][1].section("What is wrong")
    row = next(line for line in summary.split("\n") if "-0.5385" in line)
    assert "0.53353" in row and "one digit wrong" in row


@pytest.mark.parametrize("book", BOOK_NAMES)
def test_an_errata_page_filters_by_table_and_class_and_shows_all_without_script(pages, book):
    text, page = pages[book]
    rows = _rows(book)
    forms = [a for t, a in page.tags if t == "form"]
    assert forms and "hidden" in forms[0]  # shown by the script that makes it work: none without it
    selects = re.findall(r'<select name="(\w+)">(.*?)</select>', text)
    assert [name for name, _ in selects] == ["table", "class"]
    tables = re.findall(r"<option(?: value=\"([^\"]*)\")?>([^<]*)</option>", selects[0][1])
    shown = [value or label for value, label in tables]
    assert shown[0] == "all" and len(shown) == 1 + len({e["table"] for e in rows})
    classes = [label for _, label in re.findall(r"<option(?: value=\"([^\"]*)\")?>([^<]*)</option>", selects[1][1])]
    assert {e["class"] for e in rows} <= set(classes)
    # the whole table is there, in the book's order
    body = text[text.index('id="all"'):]
    assert body.count('<tr data-i="') == len(rows)


@pytest.mark.parametrize("book", BOOK_NAMES)
def test_formulas_are_mathml_and_no_raw_latex_is_shown(pages, book):
    text, page = pages[book]
    formulas = [e for e in _rows(book) if e["table"] == "formula"]
    maths = text.count("<math>")
    # printed and true, in the summary and in the whole table
    assert maths >= 4 * len(formulas)
    assert not RAW_LATEX.search(page.text), RAW_LATEX.search(page.text)
    for e in formulas:
        assert e["printed"] not in text  # the source is not on the page, only its rendering


def test_baumanns_fraction_is_a_fraction():
    # errata-004 showed `\frac{s_1 - s_a}{s_a + s_1}` as source; its true form has s_a + s_0 below the line
    e = next(e for e in _rows("baumann") if e["row"] == "df_x")
    page = errata_page(BOOKS["baumann"], [e], back="index.html", meanings=CLASS_MEANINGS, wrong=WRONG)
    frac = re.findall(r"<mfrac>(.*?)</mfrac>", page)
    assert ("<msub><mi>s</mi><mi>a</mi></msub><mo>+</mo><msub><mi>s</mi><mn>0</mn></msub>" in frac[-1]
            and "<msub><mi>s</mi><mn>1</mn></msub><mo>−</mo><msub><mi>s</mi><mi>a</mi></msub>" in frac[-1])


@pytest.mark.parametrize("book", BOOK_NAMES)
def test_no_value_that_rounds_to_nothing_carries_a_sign(pages, book):
    page = pages[book][1]
    cells = [c.strip() for c in page.chunks]
    bad = [c for c in cells if SIGNED_ZERO.fullmatch(c)]
    assert not bad, bad[:5]
    assert "0.00" in cells  # the deviations that are zero are there, unsigned


def test_the_signed_zero_pattern_finds_what_the_issue_found():
    assert all(SIGNED_ZERO.fullmatch(t) for t in ("−0.00", "-0.00", "+0.00", "-0", "-0,0"))
    assert not any(SIGNED_ZERO.fullmatch(t) for t in ("0.00", "−0.01", "-0.5385", "+0.24", "-0,01776"))


def test_the_legend_is_the_one_the_command_line_prints(pages, capsys):
    assert main(["errata", "--classes"]) == 0
    cli = {}
    for line in capsys.readouterr().out.split("\n\n")[0].splitlines():  # the classes; the rules follow
        name, meaning = line.split(None, 1)
        cli[name] = meaning.strip()
    text, page = pages["anhang-ii"]
    legend = dict(re.findall(r"<dt>([^<]+)</dt><dd>([^<]+)</dd>", text))
    assert {k: v.replace("&#x27;", "'") for k, v in legend.items()} == cli
    # and the table's classes are the legend's (the issue found agrees/slip/misprint beside typesetting/...)
    used = set(re.findall(r"<td(?: class=\"[ws]\")?>(agrees|slip|typesetting|arithmetic|follows|drawing|"
                          r"unexplained|misprint)</td>", text))
    assert used and used <= set(cli)


@pytest.mark.parametrize("book", BOOK_NAMES)
def test_errata_pages_cite_books_by_author_and_title_never_seed(pages, book):
    text, page = pages[book]
    assert not SEED.search(page.text)
    h1 = re.search(r"<h1>(.*?)</h1>", text).group(1)
    # the titles as the texts give them (seeds/004: "Autor: A. Baumann", "Titel: Ein neues Verfahren zur Bestimmung
    # der Schwungradgewichte"; the excerpts: the section they print)
    expected = {"anhang-ii": "Darstellung der Massendrücke", "handbook": "Einfluß der Massenkräfte",
                "mechanics": "§ 146", "baumann": "A. Baumann, „Ein neues Verfahren zur Bestimmung der Schwungradgewichte"}
    assert expected[book] in h1 and ("1902" in h1) == (book == "baumann")


def _entry(number: int, player: bool) -> dict:
    return {"number": number, "slug": f"fig-{number}", "title": Caption("Kolbenwege", "Piston paths"),
            "params_text": "r/L = 1/5", "source": "after A. Baumann, Schwungradgewichte (1902), Fig. 28",
            "books": ["baumann"], "ok": True, "steps": 12, "player": player,
            "thumb": "#svgView(viewBox(1,2,3,4))" if player else "",
            "method": [("steps by provenance", "exact 12")], "checks": "12 of 12 checks pass; closest to its "
            "tolerance: x, error 5.1e-04 of 5.2e-04"}


def test_the_front_page_says_what_the_site_is_and_shows_the_plates():
    entries = [_entry(1, True), _entry(2, False)]
    rows = {b: _rows(b) for b in BOOK_NAMES}
    sources = [{"book": b, "count": len(rows[b]), "classes": {c: sum(e["class"] == c for e in rows[b])
                                                              for c in CLASS_MEANINGS}} for b in BOOK_NAMES]
    text = index_page(entries, sources, list(BOOKS.values()), wrong=WRONG)
    page = _Page(text)
    visible = page.text
    # what the books are: author, title, year (seeds/004: "Autor: A. Baumann", "Jahrgang 1902"), what they teach
    assert "A. Baumann" in visible and "Schwungradgewichte" in visible and "1902" in visible
    assert all(t in visible for t in ("Darstellung der Massendrücke", "Einfluß der Massenkräfte", "§ 146"))
    assert visible.count("Teaches ") == 4
    # whom it serves
    assert all(w in visible for w in ("historians", "Teachers", "Engineers"))
    # the plates as a grid: each opens its plate; the first also its player, its thumbnail a view of the figure
    imgs = [a for t, a in page.tags if t == "img"]
    assert [i["src"] for i in imgs] == ["fig-1/historical/final.svg", "fig-1/teaching/final.svg#svgView(viewBox(1,2,3,4))",
                                        "fig-2/historical/final.svg"]
    links = [a["href"] for t, a in page.tags if t == "a"]
    assert "fig-1/teaching/player.html" in links and "fig-2/teaching/player.html" not in links
    assert {errata_slug(b) for b in BOOK_NAMES} <= set(links)
    # no developer's figures on the cards: those are on each figure's checks page
    assert "provenance" not in visible and "5.1e-04" not in visible and not SEED.search(visible)
    # the plates are reached before the books' details: the grid's heading comes first after the lead
    assert visible.index("The plates") < visible.index("Figures here")


def test_a_checks_page_carries_the_method_and_the_closest_check():
    e = _entry(1, True)
    page = _Page(checks_page("Fig. 1. Kolbenwege: checks", [{"name": "x", "measured": -0.0, "expected": 0.0,
                                                             "error": -0.0, "tolerance": 1e-12, "ok": True,
                                                             "why": "float rounding"}],
                             back="../index.html", summary=e["checks"], method=e["method"]))
    assert "5.1e-04 of 5.2e-04" in page.text and "exact 12" in page.text
    assert not any(SIGNED_ZERO.fullmatch(c.strip()) or c.strip() == "-0.0e+00" for c in page.chunks)


@pytest.mark.parametrize("book", BOOK_NAMES)
def test_an_errata_page_prints_minutes_and_primes_as_the_books_do(pages, book):
    """The notes are worded in ASCII ("printed to 10'"); the page sets 10′ and t′ as the books print them,
    and a negative deviation with a minus sign, never an apostrophe or a hyphen."""
    text, _ = pages[book]
    body = re.sub(r"<(script|style)\b.*?</\1>", "", text, flags=re.S)
    assert not re.search(r"\d'(?!s\b)|(?<![A-Za-z])[A-Za-z]'(?![A-Za-z])|by -\d", body)  # κ = 8's stays
    if book == "anhang-ii":
        assert "printed to 10′; off by −0.7′" in body  # Tabelle 2, 77° 0.7′ (the book prints 77° 0′)
