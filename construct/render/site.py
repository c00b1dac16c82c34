"""The gallery as a site for people: a front page, a checks page per figure, an errata page per book.

Everything is plain data in, one HTML page out; no page loads anything from
the network.  Thumbnails are the figures' own SVG files shown small by
``<img>`` (no copies: the gallery stays within its size); a teaching
figure's thumbnail shows the part of its canvas that holds the drawing
(:func:`thumbnail_view`).  The errata pages lead with what is wrong, then
the whole table, which filters by table and class and sorts by any column
on a click on its heading (a few lines of script; without script it is
shown whole, in the book's order).  The books' formulas are MathML
(:mod:`construct.render.mathml`).

>>> from construct.constructions.phrases import ANHANG_II
>>> page = errata_page(ANHANG_II, [{"table": "T1", "row": "0°", "column": "cos ω", "printed": "1",
...                    "true": 1.0, "units": 0.0, "class": "agrees", "note": ""}], back="index.html",
...                    meanings={"agrees": "correctly rounded"}, wrong=())
>>> page.count("<tr") == 2 and 'href="index.html"' in page and "Darstellung der Massendrücke" in page
True
"""

from __future__ import annotations

import html
import math
import re
from typing import Any, Mapping, Protocol, Sequence

from ..kernel.letters import book_symbols
from .mathml import formula_html, with_subscripts
from .notation import signed

__all__ = ["Source", "index_page", "checks_page", "errata_page", "errata_slug", "thumbnail_view", "book_title",
           "book_where"]


class Source(Protocol):
    """A book as the site shows it (:class:`construct.constructions.phrases.Book` is one)."""

    @property
    def key(self) -> str: ...
    @property
    def author(self) -> str | None: ...
    @property
    def title_de(self) -> str: ...
    @property
    def where(self) -> str: ...
    @property
    def year(self) -> str: ...
    @property
    def teaches(self) -> str: ...
    def cited(self, lang: str = "en") -> str: ...

_esc = html.escape

#: The pages' style: what every page has (a checks page needs no more), then the front page's and the errata's.
_STYLE = """body{font:15px/1.45 'DejaVu Sans',Arial,sans-serif;margin:0 auto;max-width:1400px;padding:10px 24px 30px;
color:#222;background:#fafafa}a{color:#1c5fa8}h1{font-size:26px;margin:10px 0 4px}h2{font-size:19px;margin:20px 0 8px}
.lead{font-size:16px;margin:4px 0 10px;max-width:68em}.en,.meta{color:#666}.meta{margin:2px 0;font-size:13.5px}
.ok{color:#1b7f3b}.bad,.w{color:#b00020;font-weight:bold}.s{color:#a05a00}
table{border-collapse:collapse;background:#fff;margin:6px 0}th,td{border:1px solid #ddd;padding:2px 8px;
text-align:left;vertical-align:top}th{background:#f0f0f0}th[data-col]{cursor:pointer}
td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}dl{margin:4px 0}
dt{font-weight:bold;float:left;clear:left;width:11em}dd{margin:0 0 3px 11.5em}"""
_FRONT = """h3{font-size:15px;margin:0 0 4px}.who,.books{display:grid;gap:12px}
.who{grid-template-columns:repeat(3,1fr);margin:0 0 4px}
.books{grid-template-columns:repeat(4,1fr)}.books>div,.card{background:#fff;border:1px solid #ddd;
padding:8px 12px}.who p{margin:0;font-size:14px}.books p{margin:2px 0;font-size:13.5px}
.cards{display:grid;grid-template-columns:repeat(auto-fill,minmax(410px,1fr));gap:16px}
.card h3{margin-top:6px}.card .en{margin:0}.plate img{display:block;width:100%;height:300px;object-fit:contain}
.under{display:flex;gap:12px;align-items:flex-start}.under>div{flex:1;min-width:0}
.under h3{hyphens:auto;overflow-wrap:break-word}
.teach{flex:0 0 176px;font-size:12.5px;text-align:center;text-decoration:none}
.teach img{display:block;width:174px;height:130px;border:1px solid #ccc;background:#fff}.links a{margin-right:12px}"""
_ERRATA = """tbody th{background:#f7f0f0;font-weight:normal}.filters{margin:8px 0}.filters label{margin-right:16px}
math{font-size:1.15em;math-style:normal}"""

_SORT = """<script>
(function(){
  document.querySelectorAll("table.sortable").forEach(function(t){
    var heads = t.querySelectorAll("th[data-col]"), body = t.tBodies[0];
    heads.forEach(function(th){
      var col = th.cellIndex;
      th.addEventListener("click", function(){
        var dir = th.getAttribute("aria-sort") === "ascending" ? -1 : 1;
        heads.forEach(function(h){ h.removeAttribute("aria-sort"); });
        th.setAttribute("aria-sort", dir > 0 ? "ascending" : "descending");
        var rows = Array.prototype.slice.call(body.rows);
        rows.sort(function(a, b){
          var x = a.cells[col].getAttribute("data-v") || a.cells[col].textContent;
          var y = b.cells[col].getAttribute("data-v") || b.cells[col].textContent;
          if ((x.trim() === "") !== (y.trim() === "")) return x.trim() === "" ? 1 : -1;  // blanks last
          var nx = x.trim() === "" ? NaN : Number(x), ny = y.trim() === "" ? NaN : Number(y);
          var c = (!isNaN(nx) && !isNaN(ny)) ? nx - ny : x.localeCompare(y, "de");
          return dir * (c || (+a.getAttribute("data-i") - +b.getAttribute("data-i")));
        });
        rows.forEach(function(r){ body.appendChild(r); });
      });
    });
  });
})();
</script>"""

#: The errata table's filters: by table and by class (the controls are hidden until the script runs, so
#: that a reader without script has the whole table and no controls that do nothing).
_FILTER = """<script>
(function(){
  var f = document.getElementById("filters"), t = document.getElementById("all"), n = document.getElementById("shown");
  var table = f.querySelector("[name=table]"), cls = f.querySelector("[name=class]");
  function apply(){
    var shown = 0;
    Array.prototype.forEach.call(t.tBodies[0].rows, function(r){
      var keep = (!table.value || r.cells[0].textContent === table.value) &&
                 (!cls.value || r.cells[6].textContent === cls.value || (cls.value === "*" && r.cells[6].className === "w"));
      r.hidden = !keep; shown += keep;
    });
    n.textContent = shown;
  }
  table.addEventListener("change", apply); cls.addEventListener("change", apply);
  f.hidden = false; apply();
})();
</script>"""


def _page(title: str, body: str, *, script: str = "", style: str = "") -> str:
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
            f'<meta name="viewport" content="width=device-width, initial-scale=1"><title>{_esc(title)}</title>'
            f"<style>{_STYLE}{style}</style></head><body>\n{body}\n{script}</body></html>\n")


def errata_slug(book: str) -> str:
    """The file name of a book's errata page, by the book's name (``construct errata --book NAME``).

    >>> errata_slug("baumann")
    'errata-baumann.html'
    """
    return f"errata-{''.join(ch for ch in book if ch.isalnum() or ch == '-')}.html"


def book_title(b: Source) -> str:
    """A book by its author and its title in the book's words (a section's title is quoted in it already).

    >>> from construct.constructions.phrases import BOOKS
    >>> book_title(BOOKS["baumann"])[:44], book_title(BOOKS["mechanics"])
    ('A. Baumann, „Ein neues Verfahren zur Bestimm', '§ 146–147, Zwei Kurbeln unter 90°')
    """
    return ", ".join(x for x in (b.author, f"„{b.title_de}“" if b.author else b.title_de) if x)


def book_where(b: Source) -> str:
    """Where and when a book was printed, or what dates an excerpt that does not say.

    >>> from construct.constructions.phrases import BOOKS
    >>> book_where(BOOKS["baumann"])
    'Dinglers Polytechnisches Journal, Bd. 317, S. 341, 1902'
    """
    return ", ".join(x for x in (b.where, b.year) if x)


def _book_heading(b: Source) -> str:
    """A book as a page's heading cites it: author, title, where and when it was printed."""
    return book_title(b) + (f" ({book_where(b)})" if b.year[:1].isdigit() else "")


# -- the front page ---------------------------------------------------------------------------------------

_WHO = (
    ("Authors and historians", "the plates, as the books draw them, in SVG for print; each book's errata: what it "
     "prints wrong, with the true value and the likely cause."),
    ("Teachers", "the step players: each construction step by step in the book's words, German and English; "
     "the crank and the inertia curve with a live slider for the rod ratio."),
    ("Engineers", "each figure's checks against the analytic formulas, the protocol of every step, byte-stable "
     "SVG; the construct command line and Python library (its README)."),
)


def index_page(entries: Sequence[Mapping[str, Any]], sources: Sequence[Mapping[str, Any]], books: Sequence[Source],
               *, wrong: Sequence[str] = ()) -> str:
    """The gallery's front page: what the books are, whom the site serves, the plates as a grid, the errata.

    *entries*: one per figure (number, slug, title, params_text, source, books, ok, steps, player, thumb);
    *sources*: one per book with errata (book, count, classes); *books*: the source texts in order;
    *wrong*: the classes of a wrong number.
    """
    figures: dict[str, list[Mapping[str, Any]]] = {}
    for e in entries:
        for name in e.get("books", ()):
            figures.setdefault(name, []).append(e)
    errata = {src["book"]: src for src in sources}
    cards = []
    for b in books:
        name = b.key
        figs = ", ".join(f'<a href="#{_esc(e["slug"])}">{e["number"]}</a>' for e in figures.get(name, ()))
        src = errata.get(name)
        bad = sum(n for c, n in src["classes"].items() if c in wrong) if src else 0
        cards.append(
            f'<div><h3>{_esc(book_title(b))}</h3><p class="meta">{_esc(book_where(b))}</p>'
            f"<p>Teaches {_esc(b.teaches)}.</p>"
            + (f"<p>Figures here: {figs}</p>" if figs else "")
            + (f'<p><a href="{errata_slug(name)}">Errata</a>: {src["count"]} printed numbers and formulas checked, '
               f'{bad} wrong</p>' if src else "") + "</div>")
    who = "".join(f"<p><b>{_esc(h)}</b>: {_esc(t)}</p>" for h, t in _WHO)
    body = (
        "<header><h1>Steam-engine figures by compass and straightedge</h1>\n"
        '<p class="lead">The graphical methods of four German texts on steam-engine design from around 1900, '
        "redrawn as the books draw them: every line a step of compass, straightedge or dividers, every constructed "
        'value checked against the books\' formulas. <a href="#plates">The plates</a> are below: click one to open '
        "it; a step player shows how it is constructed.</p></header>\n"
        f'<section class="who">{who}</section>\n'
        f'<h2 id="books">The books</h2>\n<section class="books">{"".join(cards)}</section>\n'
        f'<h2 id="plates">The plates ({len(entries)} figures)</h2>\n<div class="cards">\n'
        + "\n".join(map(_card, entries))
        + "\n</div>\n"
        '<p class="meta">Built by <code>construct gallery</code>; every page works offline.</p>')
    return _page("Steam-engine figures by compass and straightedge", body, style=_FRONT)


def _card(e: Mapping[str, Any]) -> str:
    """One figure: its plate (opens the plate), title, givens and source, the step player's thumbnail."""
    t, s, n = e["title"], _esc(e["slug"]), e["number"]
    plate = f"{s}/historical/final.svg"
    links = [f'<a href="{plate}">plate</a>']
    teach = ""
    if e["player"]:
        links.append(f'<a href="{s}/teaching/player.html">step player</a>')
        teach = (f'<a class="teach" href="{s}/teaching/player.html"><img src="{s}/teaching/final.svg'
                 f'{_esc(e.get("thumb", ""))}" loading="lazy" alt="Fig. {n} step by step">'
                 f'step by step, {e["steps"]} steps</a>')
    links.append(f'<a href="{s}/checks.html">checks</a>'
                 + ("" if e["ok"] else ' <span class="bad">a check fails</span>'))
    return (f'<section class="card" id="{s}"><a class="plate" href="{plate}"><img src="{plate}" loading="lazy" '
            f'alt="Fig. {n}, {_esc(t.en)}, plate"></a>\n'
            f'<div class="under"><div><h3 lang="de">Fig. {n}. {_esc(t.de)}</h3>'
            f'<p class="en">{_esc(t.en)}</p><p class="meta">{_esc(e["params_text"])} — {_esc(e["source"])}</p>'
            f'<p class="links">{"".join(links)}</p></div>{teach}</div></section>')


def thumbnail_view(drawing: Any, aspect: float = 174 / 130, margin: float = 24.0) -> str:
    """The SVG view (``#svgView(viewBox(...))``) that shows a layered figure's results as large as a thumbnail can.

    The teaching figure's canvas is laid out for every step; at its end the finished groups' helpers
    are hidden, and the results can fill a small part of it beside long axes and far helpers.  A figure
    with an end state (:class:`construct.render.svg.EndView`) shows its end state's sheet.  The box
    of the results that stay (of everything that stays, if none is a result), with *margin* canvas
    pixels for their letters, widened to the thumbnail's *aspect*, is what the thumbnail shows: the
    figure's own file, nothing copied.
    """
    from .scene import extreme_points

    end = getattr(drawing, "end", None)
    if end is not None:  # the end state: its own sheet is the figure as the book draws it
        x0, y0, x1, y1 = end.crop
        w, h = x1 - x0, y1 - y0
        if w / max(h, 1e-9) < aspect:
            x0, w = x0 - (h * aspect - w) / 2, h * aspect
        else:
            y0, h = y0 - (w / aspect - h) / 2, w / aspect
        return f"#svgView(viewBox({x0:.0f},{y0:.0f},{w:.0f},{h:.0f}))"
    sc, vp = drawing.scene, drawing.vp
    end = len(sc.steps) + 1
    fade = drawing.style.done_opacity < 1.0
    shown = [m for m in sc.marks if not (fade and sc.faded(m.step, end))]
    pts = [vp.px(*p) for m in ([m for m in shown if m.role == "result"] or shown) for p in extreme_points(m)]
    full_w, full_h = drawing.full_view[2], drawing.full_view[3]
    st = drawing.style
    if st.show_caption:  # the figure's caption (as Drawing.caption_group sets it) is no part of the drawing
        lines = len(drawing.captions.title_lines())
        full_h = min(full_h, drawing.vp.height - st.margin_px * 0.6 - (lines - 1) * 1.45 * st.caption_size
                     - 1.2 * st.caption_size)
    if not pts:
        return ""
    x0 = max(0.0, min(x for x, _ in pts) - margin)
    x1 = min(full_w, max(x for x, _ in pts) + margin)
    y0 = max(0.0, min(y for _, y in pts) - margin)
    y1 = min(full_h, max(y for _, y in pts) + margin)
    w, h = x1 - x0, y1 - y0
    # the thumbnail's shape, centred on the results, kept on the drawing (not its caption) where it fits
    if w / max(h, 1e-9) < aspect:
        x0, w = _slide(x0 - (h * aspect - w) / 2, h * aspect, full_w), h * aspect
    else:
        y0, h = _slide(y0 - (w / aspect - h) / 2, w / aspect, full_h), w / aspect
    return f"#svgView(viewBox({x0:.0f},{y0:.0f},{w:.0f},{h:.0f}))"


def _slide(start: float, size: float, room: float) -> float:
    """Where a span of *size* starting near *start* begins so that it stays within 0..*room* (if it fits):
    a thumbnail widened to its shape shows more of the drawing, not the caption below it."""
    return start if size >= room else min(max(start, 0.0), room - size)


# -- checks -----------------------------------------------------------------------------------------------


def _num(v: Any) -> tuple[str, str]:
    """(shown text, sort key) of a value; a negative zero, or a tiny value shown as zero, is 0."""
    if isinstance(v, float):
        if not math.isfinite(v):
            return str(v), ""
        return f"{v + 0.0:.10g}", repr(v)
    if v is None:
        return "–", ""
    return str(v), ""


def checks_page(title: str, checks: Sequence[Mapping[str, Any]], *, back: str, summary: str = "",
                method: Sequence[tuple[str, str]] = ()) -> str:
    """One figure's checks: constructed value, formula, error, tolerance, verdict (sortable), the method's figures.

    *summary* says how many pass and which is closest to its tolerance; *method* holds (what, how many)
    of the construction: its division method, its steps by provenance, its instruments.
    """
    rows = []
    whys: dict[str, int] = {}  # each reason once, below the table: many checks share one
    for i, c in enumerate(checks):
        w = whys.setdefault(c.get("why", ""), len(whys) + 1)
        m, _ = _num(c["measured"])
        x, _ = _num(c["expected"])
        err = c["error"] + 0.0
        # the shown numbers sort as numbers (no second copy: the gallery counts its bytes)
        rows.append(f'<tr data-i="{i}"><td>{_esc(c["name"])}<td class="num">{_esc(m)}<td class="num">{_esc(x)}'
                    f'<td class="num">{err:.1e}<td class="num">{c["tolerance"]:.0e}'
                    f'<td class="{"ok" if c["ok"] else "bad"}">{"✓" if c["ok"] else "✗"}<td class="num">{w}')
    head = f'<p class="lead">{_esc(summary)}</p>\n' if summary else ""
    if method:
        head += "<h2>The construction</h2><dl>" + "".join(f"<dt>{_esc(k)}</dt><dd>{_esc(v)}</dd>"
                                                          for k, v in method) + "</dl>\n<h2>Every check</h2>\n"
    body = (f'<p><a href="{_esc(back)}">← gallery</a></p><h1>{_esc(title)}</h1>\n{head}'
            '<table class="sortable"><thead><tr><th data-col>check</th><th data-col>constructed</th>'
            '<th data-col>formula</th><th data-col>error</th><th>tolerance</th><th data-col>verdict</th>'
            '<th data-col>why this tolerance</th></tr></thead><tbody>\n' + "\n".join(rows) + "\n</tbody></table>\n"
            "<ol>" + "".join(f"<li>{_esc(w)}</li>" for w in whys) + "</ol>")
    return _page(title, body, script=_SORT)


# -- errata -----------------------------------------------------------------------------------------------

#: How the summary names each class of what is wrong (the legend gives each class's meaning).
_WRONG_HEADINGS = {"typesetting": "Typesetting errors", "arithmetic": "The author's arithmetic",
                   "follows": "Following from another printed value", "drawing": "Read off a drawing",
                   "unexplained": "Unexplained"}


def _units(units: float | None) -> str:
    """The deviation in units of the last printed place, signed (none when it rounds to nothing).

    >>> _units(-0.004), _units(-0.67), _units(None)
    ('0.00', '−0.67', '')
    """
    return "" if units is None else signed(units, minus="−")


def _true(e: Mapping[str, Any]) -> tuple[str, str]:
    """(HTML, sort key) of the true value: a formula as MathML, an angle in degrees and minutes as the
    book prints it, a number to 8 digits (a value that rounds to nothing is 0)."""
    v = e["true"]
    if isinstance(v, str):
        return formula_html(v), ""
    if not math.isfinite(v):
        return _esc(str(v)), ""
    if "°" in str(e["printed"]):
        minutes = round(abs(v) * 60.0, 1)
        sign = "−" if v < 0 and minutes else ""
        text = f"{sign}{int(minutes // 60)}° {minutes % 60:.1f}′"
        return (text.replace(".", ",") if "," in str(e["printed"]) else text), repr(v)
    text = f"{v:.8g}" if abs(v) >= 1e-12 else "0"
    if "," in str(e["printed"]):  # the book's decimal comma
        text = text.replace(".", ",")
    return text.replace("-", "−"), repr(v)


def _printed(e: Mapping[str, Any]) -> str:
    return formula_html(e["printed"]) if e["table"] == "formula" else _esc(e["printed"])


def _cell(e: Mapping[str, Any]) -> str:
    """The class of a value's cell: a number's right-aligned, a formula's as it reads."""
    return "f" if e["table"] == "formula" else "num"


def _option(text: str) -> str:
    """A filter's choice of *text*: its value the cell's textContent (what the filter compares), shown with
    its subscripts in Unicode where Unicode has them (an option holds no markup)."""
    cell = _book_html(text)
    value = html.unescape(re.sub(r"</?sub>", "", cell))
    label = html.unescape(re.sub(r"<sub>(.*?)</sub>", lambda m: m.group(1).translate(_SUB), cell))
    return f"<option>{_esc(value)}</option>" if label == value else \
        f'<option value="{_esc(value, quote=True)}">{_esc(label)}</option>'


#: The letters and digits Unicode has subscripts for (a name whose subscript it lacks reads "fy" in a list).
_SUB = str.maketrans("0123456789aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ")


def _book_html(text: str) -> str:
    """A note or a table's name as HTML in the books' typography: primes (10′, t′), minus signs, ω, subscripts.

    >>> _book_html("printed to 10'; off by -0.7' in t'_a")
    'printed to 10′; off by −0.7′ in t′<sub>a</sub>'
    """
    return book_symbols(with_subscripts(text))  # after the markup: "t'_a" is t with subscript a, primed


def _where(e: Mapping[str, Any]) -> str:
    return " · ".join(_book_html(str(e[k])) for k in ("table", "row", "column") if e[k] and e[k] != "value")


def errata_page(book: Source, errata: Sequence[Mapping[str, Any]], *, back: str, meanings: Mapping[str, str],
                wrong: Sequence[str], books: Sequence[Source] = ()) -> str:
    """A book's errata for a historian: what is wrong first (each with its true value and likely cause),
    the classes, then every printed number beside its true value, filtered by table and class, sortable.

    *meanings* is what each class means (the legend ``construct errata --classes`` prints), *wrong* the
    classes of what is wrong, *books* all the books (the page links to the others' errata).
    """
    heading = _book_heading(book)
    numbers = [e for e in errata if e["table"] != "formula"]
    count = {c: sum(e["class"] == c for e in numbers) for c in meanings}
    bad = [e for e in errata if e["class"] in wrong]
    formulas = len(errata) - len(numbers)
    # the summary: how many agree, slip, are wrong; then what is wrong, class by class, in the book's order
    said = [f"{count.get('agrees', 0)} agree with the true value to the last printed place",
            f"{count.get('slip', 0)} are slips (within 2 units of the last place)",
            f"{sum(count.get(c, 0) for c in wrong)} are wrong"]
    lead = (f"Of the {len(numbers)} numbers this text prints, " + ", ".join(said[:-1]) + f" and {said[-1]}"
            + (f"; {formulas} printed formulas are wrong" if formulas else "") + ".")
    groups = []
    for c in wrong:
        mine = [e for e in bad if e["class"] == c]
        if not mine:
            continue
        groups.append(f'<tbody><tr><th colspan="5">{_esc(_WRONG_HEADINGS.get(c, c))} ({len(mine)}): '
                      f"{_esc(meanings.get(c, ''))}</th></tr>\n" + "\n".join(
                          f'<tr><td>{_where(e)}</td><td class="{_cell(e)}">{_printed(e)}</td>'
                          f'<td class="{_cell(e)}">{_true(e)[0]}</td><td class="num">{_units(e["units"])}</td>'
                          f'<td>{_book_html(e["note"])}</td></tr>' for e in mine) + "</tbody>")
    summary = ("<h2>What is wrong</h2>\n" + (
        '<table class="wrong"><thead><tr><th>where</th><th>printed</th><th>true</th><th>off by (units)</th>'
        "<th>likely cause</th></tr></thead>\n" + "\n".join(groups) + "</table>" if groups
        else "<p>Nothing: every number agrees with its true value or is a slip in the last place.</p>"))
    legend = ("<h2>The classes</h2>\n<p>The deviation is counted in units of the last printed place.</p><dl>"
              + "".join(f"<dt>{_esc(c)}</dt><dd>{_esc(m)}</dd>" for c, m in meanings.items()) + "</dl>")
    rows = []
    for i, e in enumerate(errata):
        true, key = _true(e)
        units = e.get("units")
        cls = ' class="w"' if e["class"] in wrong else ' class="s"' if e["class"] == "slip" else ""
        rows.append(f'<tr data-i="{i}"><td>{_book_html(e["table"])}</td><td>{_book_html(e["row"])}</td>'
                    f'<td>{_book_html(e["column"])}</td><td class="{_cell(e)}">{_printed(e)}</td>'
                    f'<td class="{_cell(e)}" data-v="{key}">{true}</td>'
                    f'<td class="num" data-v="{"" if units is None else repr(abs(units))}">{_units(units)}</td>'
                    f"<td{cls}>{_esc(e['class'])}</td><td>{_book_html(e['note'])}</td></tr>")
    tables = list(dict.fromkeys(e["table"] for e in errata))
    present = [c for c in meanings if any(e["class"] == c for e in errata)]
    filters = ('<form class="filters" id="filters" hidden><label>table <select name="table"><option value="">all'
               "</option>" + "".join(map(_option, tables))
               + '</select></label><label>class <select name="class"><option value="">all</option>'
               + ('<option value="*">wrong (any cause)</option>' if bad else "")
               + "".join(f"<option>{_esc(c)}</option>" for c in present)
               + f'</select></label> <span id="shown">{len(errata)}</span> of {len(errata)} shown</form>')
    others = " · ".join(f'<a href="{errata_slug(o.key)}">{_esc(o.cited())}</a>' if o.key != book.key
                        else f"<b>{_esc(o.cited())}</b>" for o in books or (book,))
    body = (f'<p><a href="{_esc(back)}">← gallery</a> · errata of the books: {others}</p>\n'
            f"<h1>Errata: {_esc(heading)}</h1>\n<p class=\"lead\">{_esc(lead)}</p>\n{summary}\n{legend}\n"
            "<h2>Every printed number</h2>\n<p>Each beside its true value (from the formula the text names); "
            "click a heading to sort.</p>\n" + filters + "\n"
            '<table class="sortable" id="all"><thead><tr><th data-col>table</th><th data-col>row</th>'
            '<th data-col>column</th><th data-col>printed</th><th data-col>true</th><th data-col>off by (units)</th>'
            '<th data-col>class</th><th data-col>note</th></tr></thead><tbody>\n' + "\n".join(rows)
            + "\n</tbody></table>")
    return _page(f"Errata: {heading}", body, script=_SORT + _FILTER, style=_ERRATA)
