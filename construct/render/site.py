"""The gallery as a site a reader browses: an index of thumbnails, a checks page per figure, an errata page per text.

Everything is plain data in, one HTML page out; no page loads anything from
the network.  Thumbnails are the figures' own SVG files shown small by
``<img>`` (no copies: the gallery stays within its size).  The errata tables
sort by any column on a click on its heading (a few lines of script; without
script they stay in the book's order).

>>> page = errata_page("seed 000, Anhang II", [{"table": "T1", "row": "0°", "column": "cos ω", "printed": "1",
...                    "true": 1.0, "units": 0.0, "class": "agrees", "note": ""}], back="index.html")
>>> page.count("<tr") == 2 and 'href="index.html"' in page
True
"""

from __future__ import annotations

import html
import math
from typing import Any, Mapping, Sequence

__all__ = ["index_page", "checks_page", "errata_page", "errata_slug"]

_esc = html.escape

_STYLE = """body{font:14px/1.45 'DejaVu Sans',Arial,sans-serif;margin:0 auto;max-width:1400px;padding:12px 20px;
color:#222;background:#fafafa}
h1{font-size:22px}h2{font-size:17px;margin:4px 0 2px}h2 .en,.en{font-weight:normal;color:#666}
.meta{color:#666;margin:0}.ok{color:#1b7f3b}.fail,.bad,.misprint{color:#b00020;font-weight:bold}.slip{color:#a05a00}
.cards{display:grid;grid-template-columns:repeat(auto-fill,minmax(420px,1fr));gap:14px}
.card{background:#fff;border:1px solid #ddd;padding:8px 10px}
.thumbs{display:flex;gap:8px}.thumbs a{flex:1 1 0}
.thumbs img{width:100%;height:150px;object-fit:contain;border:1px solid #ccc;background:#fff}
.links a{margin-right:10px}
table{border-collapse:collapse;background:#fff}th,td{border:1px solid #ddd;padding:2px 8px;text-align:left;
vertical-align:top}th{background:#f0f0f0}th[data-col]{cursor:pointer}td.num{text-align:right;
font-variant-numeric:tabular-nums}"""

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


def _page(title: str, body: str, *, script: str = "") -> str:
    return (f'<!DOCTYPE html>\n<html lang="de"><head><meta charset="utf-8">'
            f'<meta name="viewport" content="width=device-width, initial-scale=1"><title>{_esc(title)}</title>'
            f"<style>{_STYLE}</style></head><body>\n{body}\n{script}</body></html>\n")


def errata_slug(source: str) -> str:
    """The file name of a source text's errata page: ``errata-000.html`` for "seed 000, ...".

    >>> errata_slug("seed 004, Baumann 1902 (Schwungradgewichte)")
    'errata-004.html'
    """
    seed = source.split(",")[0].split()[-1]
    return f"errata-{''.join(ch for ch in seed if ch.isalnum())}.html"


def index_page(entries: Sequence[Mapping[str, Any]], sources: Sequence[Mapping[str, Any]], intro: str) -> str:
    """The gallery's front page: a card per figure (thumbnails, title in the book's words, links), the errata."""
    cards = []
    for e in entries:
        t, s = e["title"], _esc(e["slug"])
        # a construction's first figure has its construction step by step and the player; the others are plates
        teaching = (f'<a href="{s}/teaching/player.html"><img src="{s}/teaching/final.svg" loading="lazy" '
                    f'alt="Fig. {e["number"]}, teaching, every step"></a>' if e["player"] else "")
        links = (f'<a href="{s}/teaching/player.html">player</a><a href="{s}/teaching/final.svg">construction</a>'
                 if e["player"] else "")
        cards.append(
            f'<section class="card" id="{s}">\n<h2>Fig. {e["number"]}. {_esc(t.de)}</h2>'
            f'<p class="en">{_esc(t.en)}</p>\n<p class="meta">{_esc(e["params_text"])} — {_esc(e["source"])}</p>\n'
            f'<div class="thumbs"><a href="{s}/historical/final.svg"><img src="{s}/historical/final.svg" '
            f'loading="lazy" alt="Fig. {e["number"]}, historical plate"></a>{teaching}</div>\n'
            f'<p class="links"><a href="{s}/historical/final.svg">plate</a>{links}'
            f'<a href="{s}/checks.html">checks</a> '
            f'<span class="{"ok" if e["ok"] else "fail"}">{_esc(e["checks"])}</span></p>\n'
            f'<p class="meta"><b>Method:</b> {_esc(e["method"])}</p></section>')
    errata = "".join(
        f'<li><a href="{_esc(errata_slug(src["source"]))}">{_esc(src["source"])}</a> — '
        f'{src["count"]} printed numbers: ' + ", ".join(f"{n} {_esc(c)}" for c, n in src["classes"].items()) + "</li>"
        for src in sources)
    body = (f"<h1>construct — gallery</h1>\n<p>{_esc(intro)}</p>\n"
            f'<h2>Errata of the source texts / Druckfehler der Quellen</h2>\n<ul>{errata}</ul>\n'
            f'<h2>Figures / Abbildungen</h2>\n<div class="cards">\n' + "\n".join(cards) + "\n</div>")
    return _page("construct gallery", body)


def _num(v: Any) -> tuple[str, str]:
    """(shown text, sort key) of a value."""
    if isinstance(v, float):
        if not math.isfinite(v):
            return str(v), ""
        return f"{v:.10g}", repr(v)
    if v is None:
        return "–", ""
    return str(v), ""


def checks_page(title: str, checks: Sequence[Mapping[str, Any]], *, back: str) -> str:
    """One figure's checks: constructed value, formula, error, tolerance, verdict (sortable)."""
    rows = []
    whys: dict[str, int] = {}  # each reason once, below the table: many checks share one
    for i, c in enumerate(checks):
        w = whys.setdefault(c.get("why", ""), len(whys) + 1)
        m, _ = _num(c["measured"])
        x, _ = _num(c["expected"])
        err = c["error"]
        # the shown numbers sort as numbers (no second copy: the gallery counts its bytes)
        rows.append(f'<tr data-i="{i}"><td>{_esc(c["name"])}<td class="num">{_esc(m)}<td class="num">{_esc(x)}'
                    f'<td class="num">{err:.1e}<td class="num">{c["tolerance"]:.0e}'
                    f'<td class="{"ok" if c["ok"] else "bad"}">{"✓" if c["ok"] else "✗"}<td class="num">{w}')
    body = (f'<p><a href="{_esc(back)}">← gallery</a></p><h1>{_esc(title)}</h1>\n'
            '<table class="sortable"><thead><tr><th data-col>check</th><th data-col>constructed</th>'
            '<th data-col>formula</th><th data-col>error</th><th>tolerance</th><th data-col>verdict</th>'
            '<th data-col>why this tolerance</th></tr></thead><tbody>\n' + "\n".join(rows) + "\n</tbody></table>\n"
            "<ol>" + "".join(f"<li>{_esc(w)}</li>" for w in whys) + "</ol>")
    return _page(title, body, script=_SORT)


def errata_page(source: str, errata: Sequence[Mapping[str, Any]], *, back: str) -> str:
    """A source text's errata: printed value, true value, deviation, class, note; sortable by any column."""
    rows = []
    for i, e in enumerate(errata):
        true, tk = _num(e["true"])
        units = e.get("units")
        u = "" if units is None else f"{units:.2f}"
        rows.append(f'<tr data-i="{i}"><td>{_esc(e["table"])}</td><td>{_esc(e["row"])}</td>'
                    f'<td>{_esc(e["column"])}</td><td class="num">{_esc(e["printed"])}</td>'
                    f'<td class="num" data-v="{tk}">{_esc(true)}</td><td class="num" data-v="{"" if units is None else repr(abs(units))}">{u}</td>'
                    f'<td class="{_esc(e["class"])}">{_esc(e["class"])}</td><td>{_esc(e["note"])}</td></tr>')
    body = (f'<p><a href="{_esc(back)}">← gallery</a></p><h1>Errata: {_esc(source)}</h1>\n'
            "<p>Every printed number beside its true value (from the formula the text names); the deviation in "
            "units of the last printed place; <i>agrees</i> within half a unit, <i>slip</i> up to 2, "
            "<i>misprint</i> beyond. Click a heading to sort.</p>\n"
            '<table class="sortable"><thead><tr><th data-col>table</th><th data-col>row</th><th data-col>column</th>'
            '<th data-col>printed</th><th data-col>true</th><th data-col>deviation (units)</th><th data-col>class</th>'
            '<th data-col>note</th></tr></thead><tbody>\n' + "\n".join(rows) + "\n</tbody></table>")
    return _page(f"Errata: {source}", body, script=_SORT)
