"""The live givens in the player page: a slider per continuous given, redrawing the figure from precomputed data.

:func:`with_live` adds to a player page (:func:`construct.render.player.player_html`)
an ``<input type="range" name="GIVEN">`` per given (log10 of the given over its stated
domain: the rod ratio runs from 1.05 to 1000, and a teacher lives between 3 and
8), the value in the book's notation, the construction's checks at the
nearest grid value they were computed at (the heading names it, and says so where the slider stands between
two), and a script that interpolates every drawn coordinate
between the grid values the data (:mod:`construct.live`) holds, in the wire format of
:mod:`construct.render.wire`.  Each given has its own sweep, taken with the
others at the book's values: one given moves at a time, and moving one sets
the others back to the book's values (the page says so).
The page stays one file: the coordinates travel deflated in base64 and are
inflated with the browser's own ``DecompressionStream``.  (This module is long -- over 600 lines -- because
most of it is the page's script in one string, one file for the browser; its Python is the wiring round it.)

**Every mark, every moment.**  Each ``input`` event of a slider redraws, in
the next animation frame, everything the page draws: every mark of every
step shown, in the window or not (those of steps not shown sit outside the
document, the player's ``lean``, and are brought to the shown value when
their step shows them again: the player's ``shown``; those the step's classes
hide -- display: none, another zoom level's letters -- wait
likewise until a step, zoom level or end state shows them: ``reveal``, and those the end state hides, most of its
letters and points, are out of the document there, the player's ``lean`` again;
``constructLive.flush()`` brings every mark at once, for a reader of their
numbers), the view box and each step's
view, the ring round the current mark, the letters and name tags with the
points they name (their placed offset kept; a tag names its point by
standing on it), the broken axes' marks on every line that crosses a break
(``breakMarks``, the script's twin of
:func:`construct.render.plate.break_elements`), with the rod's length written
at the break (L = 50 r: a broken rod is drawn short; where the drawing wrote it,
:func:`construct.render.rod_length.rod_spots`), and letters that come
to lie on one another: the later gives way (``declutter``) until there is
room again.  Nothing waits for the slider to be let go (``change``), which
only sets the letters' exact scale and glides the camera to the step's
view.  The end state (the last step drawn as the book's plate) follows too: its own
marks are swept as the rest (:meth:`construct.render.sweepdraw.SweepDrawing`), and the plate's furniture there
(its dimensions, lettering and added lines) item by item: an item the plate draws at every value of the domain
follows the given, one that comes and goes (a scale's ticks: :meth:`construct.live.Measure.furniture_kept`) is
shown where the nearer grid value's plate has it, and the page says which (a plate of panels is held whole).
Readings of the figure (an angle to the minute) are written as read at the nearer grid value; a decimal number
read off it (a value the plate writes) blended between the two grid values' and written with one digit fewer there.
An area's hatching is drawn anew with its outline, as the drawing hatches it (:func:`construct.render.paths.
hatch_segments`: the player's data says its spacing and each area's angle); a signed area's (its pieces' angle
turns with their sign) holds the built value's numbers and is shown at the book's values alone.  The inset (a
step's small work magnified beside the view) follows the given: a cluster's box is found anew by the player
about the step's finest detail (:func:`construct.render.insets.inset_detail`), a sliver's is swept, carried
with its points (:class:`construct.live.Measure`); its points are drawn where their circles stand; where the
box has grown until it magnifies no more than the view, it is not shown.

The script exposes ``window.constructLive``: ``set(value)`` moves the first
given (``set(value, true)``: as a drag draws it; ``set(value, dragging,
name)``: the given *name*), ``ready`` is a promise for the inflated data,
``lastMs`` the last redraw's time.

A drag is drawn inside one animation frame (``construct bench --live``):
numbers are set as SVG lengths, not parsed text, and written only when they
change (a path's from integers); the camera keeps its view while the step's view stays inside it, and
the letters their scale and zoom level (the player's ``holds`` and
``DRAG_LARGER``; exact, the camera gliding, on let-go), and a new view leads the motion (the player's
``ahead``); the groups the step
hides are out of the document (the player's ``lean``) and not written while
they are, nor are the marks their classes hide; the letters' boxes are kept in the figure's units, so a new view
or piece forces no layout; the curves an area is drawn from are read once a redraw; the
checks' cells change in place, the rows out of sight when they come into sight or on let-go.

>>> page = "<html><body><div id=stage></div>\\n<aside>\\n</aside>\\n</body></html>"
>>> out = with_live(page, {"given": "rod_ratio", "symbol": "L/r", "low": 1.05, "high": 1000.0,
...                        "initial": 5.0, "checks": []})
>>> 'name="rod_ratio"' in out and out.count("<script") == 2
True
"""

from __future__ import annotations

import html
import math
from typing import Any, Mapping, Sequence

from ..kernel.letters import number
from .player import json_for_script

__all__ = ["with_live", "with_switch", "LIVE_SCRIPT"]

_NOTE = "color:#777;font-size:12px"


def _slider(data: Mapping[str, Any], first: bool) -> str:
    """One given's slider, its value and its domain."""
    g = html.escape(str(data["given"]))
    sym = html.escape(str(data["symbol"]))
    lo, hi, v0 = math.log10(data["low"]), math.log10(data["high"]), math.log10(data["initial"])
    out_id = "live-value" if first else f"live-value-{g}"
    return (f'<label style="display:flex;gap:10px;align-items:center"><b class="sym">{sym}</b> '
            f'<input type="range" name="{g}" id="live-{g}" min="{lo:.12g}" max="{hi:.12g}" step="any" '
            f'value="{v0:.12g}" aria-label="{sym}" style="flex:1 1 auto">'
            f'<span>{sym} = <output id="{out_id}" class="live-value" data-given="{g}" '
            f'style="font-variant-numeric:tabular-nums">{html.escape(number(data["initial"], "de"))}</output>'
            f'{" " + html.escape(data["unit"]) if data.get("unit") else ""}</span></label>'
            f'<div class="live-range" style="{_NOTE}">{html.escape(number(data["low"], "de"))} … '
            f'{html.escape(number(data["high"], "de"))} (log. Skala / log scale; Buchwert / book: '
            f'{html.escape(number(data["initial"], "de"))})</div>')


def with_live(page: str, data: Mapping[str, Any] | Sequence[Mapping[str, Any]], *,
              steps_note: str | None = None) -> str:
    """*page* with a slider per given of *data* (one given's live data, or a list of them: :func:`construct.live.
    live_data`) and the checks under the figure, and the live script before </body>.

    *steps_note*: what the page says of a given the construction also takes but that changes its steps (the
    number of parts), instead of the default."""
    givens = [data] if isinstance(data, Mapping) else list(data)
    # a given whose domain is swept in pieces (the steps' form changes: live.sweep.pieces) has one slider
    sliders = list({d["given"]: d for d in reversed(givens)}.values())[::-1]
    syms = [html.escape(str(d["symbol"])) for d in sliders]
    held = (f'Nur {syms[0]} ist beweglich; die übrigen Gegebenen bleiben beim Buchwert. / Only {syms[0]} moves '
            f'here; the other givens stay at the book’s values' if len(sliders) == 1 else
            f'{" und ".join(syms)} bewegen sich einzeln: wer einen zieht, setzt die anderen auf den Buchwert '
            f'zurück. / {" and ".join(syms)} move one at a time: moving one sets the others back to the book’s '
            f'values')
    held += (steps_note if steps_note is not None else
             ': a sweep over two givens together would be needed, and the number of parts changes the steps '
             'themselves.')
    controls = ('<section id="live" style="background:#fff;border:1px solid #ddd;margin-top:8px;padding:6px 10px">'
                + "".join(_slider(d, i == 0) for i, d in enumerate(sliders))
                # why one given moves at a time (a teacher asks for the next given first)
                + f'<div class="live-held" style="{_NOTE}">{held}</div>'
                # a reading (an angle read off the figure, to the minute) blended between grid values would
                # print minutes the figure does not have
                + (f'<div class="live-readings" style="{_NOTE}">Abgelesene Winkel sind beim nächsten gespeicherten '
                   'Wert abgelesen; abgelesene Zahlen zwischen zwei gespeicherten Werten sind zwischen ihnen '
                   'gemittelt und mit einer Stelle weniger geschrieben. / Angles read off the figure are as read at '
                   'the nearest value the page holds; numbers read off it between two such values are blended '
                   'between them and written with one digit fewer.</div>'
                   if any(d.get("readings") for d in givens) else '')
                + '<details open><summary>Prüfungen / checks <span id="live-at"></span></summary>'
                '<div style="max-height:28vh;overflow:auto"><table id="live-checks" style="border-collapse:collapse;'
                'font-size:12px;font-variant-numeric:tabular-nums"><thead><tr><th>Größe / quantity</th>'
                '<th>konstruiert</th><th>Formel</th><th>Fehler</th><th></th></tr></thead><tbody></tbody></table>'
                '</div></details></section>\n')
    # under the figure's caption, in the stage (the side panel scrolls with the step list)
    aside = page.index("<aside>")
    at = page.rindex("</div>", 0, aside)
    page = page[:at] + controls + page[at:]
    payload = givens[0] if len(givens) == 1 else {"givens": givens}
    script = (f'<script type="application/json" id="live-data">{json_for_script(dict(payload))}</script>\n'
              f"<script>{LIVE_SCRIPT}</script>\n")
    end = page.rindex("</body>")
    return page[:end] + script + page[end:]


def with_switch(page: str, symbol: str, options: Sequence[tuple[str, str | None]], why: str) -> str:
    """*page* with a switch between precomputed figures of a given that changes the construction's steps (the
    indicator diagram's filling s₁: the cut-off's division points): *options* are (the value as the book
    writes it, the page of that figure, or None for this one), *why* says why it is a switch, not a slider.

    >>> out = with_switch("<div id=stage></div>\\n<aside>", "s₁/s", [("0,1", None), ("0,4", "../x/player.html")],
    ...                   "the filling changes the steps")
    >>> 'class="live-switch"' in out and 'href="../x/player.html"' in out and 'aria-current="page"' in out
    True
    """
    links = " ".join(f'<a href="{html.escape(href)}">{html.escape(value)}</a>' if href is not None else
                     f'<b aria-current="page">{html.escape(value)}</b>' for value, href in options)
    controls = (f'<section id="live" class="live-switch" style="background:#fff;border:1px solid #ddd;'
                f'margin-top:8px;padding:6px 10px"><div><b class="sym">{html.escape(symbol)}</b> = {links}</div>'
                f'<div class="live-held" style="{_NOTE}">{html.escape(why)}</div></section>\n')
    aside = page.index("<aside>")
    at = page.rindex("</div>", 0, aside)
    return page[:at] + controls + page[at:]


#: The page's script (no external resource; text reaches the page through textContent only).
LIVE_SCRIPT = r"""
(function(){
  "use strict";
  var raw = JSON.parse(document.getElementById("live-data").textContent);
  var LIST = raw.givens || [raw];
  var svg = document.getElementById("figure");
  var api = window.constructLive = {lastMs: 0, value: LIST[0].initial, given: LIST[0].given};
  var book = function(v){ return String(Number(v.toPrecision(4))).replace(".", ","); };
  var round2 = function(v){ return Math.round(v * 100) / 100; };
  // a number to two decimals as text, as String(round2(v)) writes it, from integers (a redraw writes thousands of
  // numbers into paths: a fraction's shortest digits cost three times an integer's)
  var HUNDREDTHS = [""];
  for (var c100 = 1; c100 < 100; c100++) HUNDREDTHS.push("." + (c100 < 10 ? "0" + c100 : String(c100 % 10 ? c100 : c100 / 10)));
  var text2 = function(v){
    var n = Math.round(v * 100), neg = n < 0, q;
    if (neg) n = -n;
    q = (n - n % 100) / 100;
    return (neg && n ? "-" : "") + q + HUNDREDTHS[n % 100];
  };
  function setText(e, text){  // an element's one text node changed in place (no node replaced), if it changed
    var t = e.firstChild;
    if (t && t.nodeType === 3 && !t.nextSibling) { if (t.nodeValue !== text) t.nodeValue = text; }
    else if (e.textContent !== text) e.textContent = text;
  }
  if (!LIST[0].data) { return; }
  function inflate(b64){
    var bin = atob(b64), bytes = new Uint8Array(bin.length);
    for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    var stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate"));
    return new Response(stream).arrayBuffer();
  }
  function json(b){ return JSON.parse(new TextDecoder().decode(b)); }
  var player = null, S = null, cur = null, sweeps = [], followers = [], readings = [], absent = [], lines = [];
  var VIEWS = "zooms", IDX = "z";
  // ---- one given's data: every drawn number at every grid value ---------------------------------------------
  function Sweep(L){
    this.L = L; this.value = L.initial; this.slots = []; this.byId = {}; this.zoomAt = []; this.ringAt = []; this.insetAt = [];
    this.loose = []; this.inGroup = new Map(); this.slotsOf = new Map();
    this.breakAt = null; this.full = null; this.pathSlot = new Map();
    this.input = document.querySelector('input[name="' + L.given + '"]');
    this.out = document.querySelector('output[data-given="' + L.given + '"]');
  }
  Sweep.prototype.expand = function(buf){
    // live/wire.py encode: the column map, each stored column's kind (drawn, or the construction's x, y,
    // length, or a radius's logarithm, through the grid value's fit to the view; 128 added where its deltas
    // are int32), its kept grid values (bits), the fits, the first values, then the deltas between kept
    // values (int16 columns in two byte planes, then int32 columns in four); between kept values a column is
    // a line in log10 of the given
    var L = this.L, rows = L.rows, cols = L.cols, U = L.ucols;
    var bytes = new Uint8Array(buf), dv = new DataView(buf), at = 0, c, r, b;
    var colmap = this.colmap = new Int32Array(cols);
    for (c = 0; c < cols; c++) colmap[c] = L.mapw === 2 ? dv.getUint16(at + 2 * c, true) : dv.getInt32(at + 4 * c, true);
    at += cols * L.mapw;
    var kinds = bytes.subarray(at, at + U);
    at += U;
    var keepAt = at, nbits = rows * U, counts = new Int32Array(U), n16 = 0, n32 = 0;
    at += (nbits + 7) >> 3;
    var bit = function(i){ return (bytes[keepAt + (i >> 3)] >> (7 - (i & 7))) & 1; };
    for (c = 0; c < U; c++) {
      for (r = 1; r < rows; r++) counts[c] += bit(c * rows + r);
      if (kinds[c] & 128) n32 += counts[c]; else n16 += counts[c];
    }
    var fit = new Float32Array(buf.slice(at, at + 12 * rows));
    at += 12 * rows;
    var firstAt = at, p16 = at + 4 * U, p32 = p16 + 2 * n16, pos16 = 0, pos32 = 0, g = L.grid;
    var X = new Float64Array(rows), D = this.D = new Float32Array(rows * U), moving = this.moving = new Uint8Array(U);
    for (c = 0; c < U; c++) {
      var wide = kinds[c] & 128, kind = kinds[c] & 127, q = kind === 4 ? L.ql : kind ? L.qx : L.q;
      var r0 = 0, v0 = dv.getInt32(firstAt + 4 * c, true);
      X[0] = v0 * q;
      for (r = 1; r < rows; r++) {
        if (!bit(c * rows + r)) continue;
        var d = 0;
        if (wide) { for (b = 3; b >= 0; b--) d = (d * 256) + bytes[p32 + b * n32 + pos32]; if (d >= 2147483648) d -= 4294967296; pos32++; }
        else { d = (bytes[p16 + n16 + pos16] << 8) | bytes[p16 + pos16]; if (d >= 32768) d -= 65536; pos16++; }
        var v1 = v0 + d;
        for (var m = r0 + 1; m <= r; m++) X[m] = (v0 + (v1 - v0) * (g[m] - g[r0]) / (g[r] - g[r0])) * q;
        r0 = r; v0 = v1;
      }
      for (r = 0; r < rows; r++) {
        var s = fit[3 * r + 2], x = X[r];
        var v = kind === 1 ? fit[3 * r] + s * x : kind === 2 ? fit[3 * r + 1] - s * x : kind === 3 ? s * x : kind === 4 ? s * Math.exp(x) : x;
        D[r * U + c] = v;
        if (r > 0 && Math.abs(v - D[c]) > 0.004) moving[c] = 1;
      }
    }
  };
  Sweep.prototype.prepare = function(buf){
    this.expand(buf);
    var L = this.L, self = this, at = 0, isFlag = this.isFlag = new Uint8Array(L.cols), isGeo = this.isGeo = new Uint8Array(L.cols);
    (L.flags || []).forEach(function(c){ isFlag[c] = 1; });
    L.keys.forEach(function(k){
      var parts = k[2].split("#"), nn = parts.length - 1, i;
      // a radius: blended geometrically (render/wire.py radii)
      if (k[1] === "d" && k[2] === "M# #A# # # # # # #") { isGeo[at + 2] = isGeo[at + 3] = 1; }
      else if (k[1] === "r" && nn === 1) isGeo[at] = 1;
      // a step's view, the ring round its mark, the broken axes: data for the shown step and the break marks
      if (k[0] === "#zoom") { self.zoomAt[+k[1]] = at; at += nn; return; }
      if (k[0] === "#ring") { self.ringAt[+k[1]] = at; at += nn; return; }
      if (k[0] === "#inset") { self.insetAt[+k[1]] = at; at += nn; return; }
      if (k[0] === "#break") { (self.breakAt = self.breakAt || [])[+k[1]] = at; at += nn; return; }
      var el = k[0] ? (player && player.find ? player.find(k[0]) : document.getElementById(k[0])) : svg;
      var cs = new Int32Array(nn), mv = false;
      for (i = 0; i < nn; i++) { cs[i] = at + i; if (self.moving[self.colmap[at + i]]) mv = true; }
      at += nn;
      // a mark whose numbers do not move over the domain keeps its attribute as built: never written (a given
      // swept in pieces writes them all: another piece may have written them)
      if (!el || (!mv && !L.piece && el !== svg)) return;
      var sl = {el: el, attr: k[1], parts: parts, cs: cs, v: new Float64Array(nn).fill(NaN), text: null,
                len: lengthOf(el, k[1], parts)};
      // the whole figure's box: written as data-full, and as the view by the player (or below without one)
      if (el === svg) { self.full = sl; sl.el = null; } else {
        self.slots.push(sl);
        // by the step group it is drawn in: a group out of the document (its step hides it) is brought up to
        // date when it is shown (shown), not every frame
        var grp = el.closest ? el.closest("g[data-step]") : null, bin = grp ? self.inGroup.get(grp) : self.loose;
        if (!bin) self.inGroup.set(grp, bin = []);
        bin.push(sl);
        (self.slotsOf.get(el) || self.slotsOf.set(el, []).get(el)).push(sl);
      }
      if (k[1] === "d") self.pathSlot.set(el, sl);
      if (k[1] === "cx" || k[1] === "cy") (self.byId[k[0]] = self.byId[k[0]] || {})[k[1]] = sl;
    });
  };
  Sweep.prototype.dirty = function(){  // everything written anew (another given was shown meanwhile)
    this.slots.forEach(function(sl){ sl.v.fill(NaN); sl.text = null; });
    if (this.full) { this.full.v.fill(NaN); this.full.text = null; }
  };
  function lengthOf(el, attr, parts){  // the SVG length an attribute of one bare number is (cx, cy, r, x1, …)
    var a = parts.length === 2 && !parts[0] && !parts[1] && el !== svg && el[attr];
    return a && a.baseVal && typeof a.baseVal.value === "number" && a.baseVal.unitType === 1 ? a.baseVal : null;
  }
  // ---- the shown value ----------------------------------------------------------------------------------------
  function cell(L, u){
    var g = L.grid, lo = 0, hi = g.length - 1;
    if (u <= g[0]) return [0, 0];
    if (u >= g[hi]) return [hi - 1, 1];
    while (hi - lo > 1) { var m = (lo + hi) >> 1; if (g[m] <= u) lo = m; else hi = m; }
    var t = (u - g[lo]) / (g[lo + 1] - g[lo]);
    // across a jump of the drawing (a broken axis appearing) the nearer side is drawn, not a blend
    if (L.jumps.indexOf(lo) >= 0) t = t < 0.5 ? 0 : 1;
    return [lo, t];
  }
  function num(c){  // key column c at the shown value: a flag from the nearer grid value, a radius geometrically
    var uc = S.colmap[c], a = S.D[cur.r0 + uc], b = S.D[cur.r1 + uc], t = cur.t;
    if (S.isFlag[c]) return t < 0.5 ? a : b;
    if (S.isGeo[c] && a > 0 && b > 0) return a * Math.pow(b / a, t);
    return a + (b - a) * t;
  }
  function write(sl){  // one mark's attribute at the shown value; written only when it changes
    var cs = sl.cs, v, i, changed = false;
    if (sl.len) {  // one length (a point's centre, a line's end): its number, set without text to parse
      v = round2(num(cs[0]));
      if (v !== sl.v[0]) { sl.v[0] = v; sl.len.value = v; }
      return;
    }
    for (i = 0; i < cs.length; i++) { v = round2(num(cs[i])); if (v !== sl.v[i]) { sl.v[i] = v; changed = true; } }
    if (!changed && sl.text !== null) return;
    var parts = sl.parts, txt = parts[0];
    for (i = 1; i < parts.length; i++) txt += text2(sl.v[i - 1]) + parts[i];
    if (txt !== sl.text) { sl.text = txt; if (sl.el) sl.el.setAttribute(sl.attr, txt); }
  }
  function pointNow(id){  // a moving point's centre at the shown value (null: it does not move)
    var p = S.byId[id];
    return p && (p.cx || p.cy) ? [p.cx ? round2(num(p.cx.cs[0])) : null, p.cy ? round2(num(p.cy.cs[0])) : null] : null;
  }
  // ---- letters and name tags: with the point they name --------------------------------------------------------
  var builtAt = {};  // each point's centre as built (before anything is written)
  svg.querySelectorAll("circle.pt[id]").forEach(function(c){ builtAt[c.id] = [+c.getAttribute("cx"), +c.getAttribute("cy")]; });
  function stepOf(e){ var g = e.closest ? e.closest("g[data-step]") : null; return g ? g.getAttribute("data-step") : null; }
  var atPoint = {};  // the points by where they stand as built, "x y" -> [id, step] (a tag stands on its point)
  svg.querySelectorAll("circle.pt[id]").forEach(function(c){
    var key = c.getAttribute("cx") + " " + c.getAttribute("cy");
    (atPoint[key] = atPoint[key] || []).push([c.id, stepOf(c)]);
  });
  function ownerOf(g, x, y){  // the point a label group names: its letter's id, or the point it stands on
    var t = g.querySelector('text[id$="-label"]'), own = t ? t.id.slice(0, -6) : null;
    if (own && builtAt[own]) return own;
    var here = atPoint[x + " " + y] || [], step = stepOf(g);
    for (var i = 0; i < here.length; i++) if (here[i][1] === step) return here[i][0];
    return here.length ? here[0][0] : null;
  }
  function nearest(x, y){  // (a letter of a plain figure, drawn where it stands: the nearest point)
    var best = null, bd = 60 * 60;
    for (var id in builtAt) { var p = builtAt[id], d = (p[0] - x) * (p[0] - x) + (p[1] - y) * (p[1] - y); if (d < bd) { bd = d; best = id; } }
    return best;
  }
  function gather(){
    api.unowned = 0;
    svg.querySelectorAll("g.lbg").forEach(function(g){
      if (g.closest("#caption") || g.closest("#furniture")) return;
      var m = /^translate\(([-0-9.e]+)[ ,]+([-0-9.e]+)\)$/.exec(g.getAttribute("transform") || "");
      if (!m) return;
      var own = ownerOf(g, m[1], m[2]);
      if (!own) { api.unowned++; return; }
      var list = g.transform && g.transform.baseVal, one = list && list.numberOfItems === 1 ? list.getItem(0) : null;
      followers.push({g: g, own: own, x: +m[1], y: +m[2], shift: one && one.type === 2 ? one : null, at: [NaN, NaN],
                      tag: !g.querySelector('text[id$="-label"]'), step: +(stepOf(g) || 0), grp: g.closest("g[data-step]") || svg});
    });
    // letters and leader lines drawn where they stand (a plain figure's): with the point they name, or the nearest
    svg.querySelectorAll("text, line:not([id])").forEach(function(t){
      if (t.closest("#caption") || t.closest("#furniture") || t.closest("g.lbg")) return;
      var x = +(t.getAttribute("x") || t.getAttribute("x1")), y = +(t.getAttribute("y") || t.getAttribute("y1"));
      var own = t.id && /-label$/.test(t.id) && builtAt[t.id.slice(0, -6)] ? t.id.slice(0, -6) : nearest(x, y);
      var built = {};
      ["x", "y", "x1", "y1", "x2", "y2"].forEach(function(a){ var v = t.getAttribute(a); if (v !== null && v !== "" && !isNaN(+v)) built[a] = +v; });
      if (own) followers.push({el: t, own: own, built: built, at: {}, grp: t.closest("g[data-step]") || svg});
    });
  }
  function follow(fo){  // a letter group (or a plain letter) with its point
    var p = pointNow(fo.own), b = builtAt[fo.own];
    var dx = p && p[0] !== null ? p[0] - b[0] : 0, dy = p && p[1] !== null ? p[1] - b[1] : 0;
    if (fo.g) {
      var gx = round2(fo.x + dx), gy = round2(fo.y + dy);
      if (gx === fo.at[0] && gy === fo.at[1]) return;
      fo.at[0] = gx; fo.at[1] = gy;
      // the group's one translate, set as numbers (a transform attribute's text would be parsed)
      if (fo.shift) fo.shift.setTranslate(gx, gy); else fo.g.setAttribute("transform", "translate(" + gx + " " + gy + ")");
      return;
    }
    for (var a in fo.built) {
      var v = round2(fo.built[a] + (a.charAt(0) === "x" ? dx : dy));
      if (v !== fo.at[a]) { fo.at[a] = v; fo.el.setAttribute(a, String(v)); }
    }
  }
  // ---- the broken axes: their marks on every line that crosses them (render/plate.py break_elements) ----------
  var SIZE = LIST[0].label_px || 12, NS = "http://www.w3.org/2000/svg", marksOf = new Map(), rodLabels = [], rodSpots = [], rodTexts = [];
  var TWO = /^M(-?[0-9.]+) (-?[0-9.]+)L(-?[0-9.]+) (-?[0-9.]+)$/;
  function mk(tag, cls, parent){ var e = document.createElementNS(NS, tag); e.setAttribute("class", cls); parent.appendChild(e); return e; }
  var ENDS = ["x1", "y1", "x2", "y2"];
  function ends(ln){  // a line's ends at the shown value: as written, or, a line the page hides (not written), the sweep's
    var out = ln.x1 ? [ln.x1.baseVal.value, ln.y1.baseVal.value, ln.x2.baseVal.value, ln.y2.baseVal.value] : drawnOf(ln).n.slice(0, 4);
    if (unseen.has(ln)) (S.slotsOf.get(ln) || []).forEach(function(sl){
      if (sl.len) out[ENDS.indexOf(sl.attr)] = round2(num(sl.cs[0]));
      else for (var i = 0; i < 4; i++) out[i] = round2(num(sl.cs[i]));
    });
    return out;
  }
  function breakMarks(every){  // (every: the lines of steps not shown too)
    var bands = [];
    for (var axis = 0; axis < 2; axis++) {
      var c = S.breakAt ? S.breakAt[axis] : undefined, w = c === undefined ? 0 : num(c + 1);
      bands.push(w > 0.5 ? [num(c), w] : null);
    }
    var first = [null, null], fin = svg.classList.contains("fin");
    for (var i = 0; i < lines.length; i++) {
      var ln = lines[i], x1, y1, x2, y2;
      if (!every && !ln.isConnected) continue;  // (a step not shown: its marks are set when it is shown)
      var q2 = ends(ln); x1 = q2[0]; y1 = q2[1]; x2 = q2[2]; y2 = q2[3];
      var got = marksOf.get(ln) || [null, null];
      for (axis = 0; axis < 2; axis++) {
        var band = bands[axis], a0 = axis ? y1 : x1, a1 = axis ? x1 : y1, b0 = axis ? y2 : x2, b1 = axis ? x2 : y2;
        var on = band && Math.min(a0, b0) < band[0] + 0.3 * band[1] && Math.max(a0, b0) > band[0] + 0.7 * band[1] && Math.abs(b0 - a0) > 1e-9;
        var set = got[axis];
        // (in its style too: the end state's rule that shows its own groups, .fin .fo, outranks the attribute)
        if (!on) { if (set) { set.g.setAttribute("display", "none"); set.g.style.display = "none"; } continue; }
        if (!set) {  // beside its line: shown and faded with the line's step
          var g = document.createElementNS(NS, "g");
          // (an end state's own line's marks in the end state alone, a line it leaves out's not there: fo, nf)
          // (and a straight line drawn point to point, the rod lettered L: the end state breaks the plate's own
          // rod over it, render/svg.py furniture_group)
          g.setAttribute("class", "brkg" + (ln.closest(".fo") ? " fo" : ln.classList.contains("nf") || (endAt && ln.tagName === "path") ? " nf" : ""));
          ln.parentNode.insertBefore(g, ln.nextSibling);
          set = got[axis] = {g: g, gap: mk("path", "brk", g), t: [mk("line", "brkline", g), mk("line", "brkline", g)], key: ""};
          marksOf.set(ln, got);
        }
        set.g.removeAttribute("display"); set.g.style.display = "";
        var t = band[0] + band[1] / 2, s = a1 + (b1 - a1) * (t - a0) / (b0 - a0), cx = axis ? s : t, cy = axis ? t : s;
        var n = Math.hypot(x2 - x1, y2 - y1) || 1, ux = (x2 - x1) / n, uy = (y2 - y1) / n, nx = -uy, ny = ux;
        var h = 0.6 * SIZE, gap = 0.45 * SIZE, key = cx + " " + cy + " " + ux + " " + uy;
        // (the rod's length on a break the step shows: in the end state not on a line it leaves out -- at L/r 50
        // the inertia curve's axis break, far out of the end state's view, wrote it at the window's edge)
        if (!first[axis] && ln.isConnected && !set.g.classList.contains(fin ? "nf" : "fo")) first[axis] = [cx, cy];
        if (key === set.key) continue;
        set.key = key;
        var corner = function(su, sn){ return round2(cx + su * gap * ux + sn * h * nx) + " " + round2(cy + su * gap * uy + sn * h * ny); };
        set.gap.setAttribute("d", "M" + corner(-1, -1) + "L" + corner(1, -1) + "L" + corner(1, 1) + "L" + corner(-1, 1) + "Z");
        for (var k = 0; k < 2; k++) {
          var su = k ? 1 : -1, tx = cx + su * gap * ux, ty = cy + su * gap * uy, e = set.t[k];
          e.setAttribute("x1", round2(tx - 0.35 * h * ux - h * nx)); e.setAttribute("y1", round2(ty - 0.35 * h * uy - h * ny));
          e.setAttribute("x2", round2(tx + 0.35 * h * ux + h * nx)); e.setAttribute("y2", round2(ty + 0.35 * h * uy + h * ny));
        }
      }
    }
    // the rod's length written at each break (a broken rod is drawn short: the figure says how long it is)
    var rod = sweeps.filter(function(w){ return w.L.rod; })[0];
    // (the value shown: of the piece of the domain that moves, not of the first piece's sweep, left where it was)
    var said = rod && rod.L.rod.replace("{v}", book(valueOf(rod.L.given)));
    for (axis = 0; axis < 2; axis++) {
      var lab = rodLabels[axis], at = first[axis];
      // (in the end state at the book's values the plate's own furniture writes it, a dimension L = 5 r)
      // (and at every value where that furniture follows the given)
      var inPlate = endWritesRod && fin && (!S.L.furniture_held || Math.abs(Math.log10(S.value / S.L.initial)) < 1e-9);
      // (its display in its style too: the end state's rule for its letters, .fin .lbg.pf, outranks the attribute;
      // hidden, it still says the slider's value: no stale length left in the document for a reader or a test)
      if (!rod || !at || inPlate) {
        if (lab) { lab.g.setAttribute("display", "none"); lab.g.style.display = "none"; if (said) { setText(lab.halo, said); setText(lab.text, said); } }
        continue;
      }
      if (!lab) {
        // (pf: shown in the end state too, where the plate's furniture that writes it is not: away from the book)
        var lg = mk("g", "lbg rodlen pf", svg.querySelector("#furniture") || svg);
        lab = rodLabels[axis] = {g: lg, halo: mk("text", "lb halo", lg), text: mk("text", "lb", lg)};
        // where the drawing wrote it at the book's value (render/rod_length.py rod_spots), or its first choice
        var spot = rodSpots[axis] || (axis ? [0.7 * SIZE, 0.35 * SIZE, "start"] : [0, -0.9 * SIZE, "middle"]);
        [lab.halo, lab.text].forEach(function(e){ e.setAttribute("x", spot[0]); e.setAttribute("y", spot[1]);
          if (spot[2] !== "middle") e.setAttribute("style", "text-anchor:" + spot[2]); });
      }
      lab.g.removeAttribute("display"); lab.g.style.display = "";
      lab.g.setAttribute("transform", "translate(" + round2(at[0]) + " " + round2(at[1]) + ")");
      setText(lab.halo, said); setText(lab.text, said);
    }
    if (rod) for (var ri = 0; ri < rodTexts.length; ri++) setText(rodTexts[ri], said);
  }
  // ---- areas between two graphs: drawn anew from the graphs that bound them (kernel/areas.py area_between) ----
  var areas = [];
  var NUMS = /-?[0-9]+(?:\.[0-9]+)?(?:e[-+]?[0-9]+)?/g;
  var still = new Map();
  function drawnOf(e){  // a path's numbers as drawn: its slot's, written this frame (no text parsed), or its d read
    // once (a graph that does not move has no slot); and whether it is a French curve
    var sl = S.pathSlot.get(e);
    if (sl) return sl.drawn || (sl.drawn = {n: sl.v, curve: sl.parts.join("").indexOf("C") >= 0});
    var got = still.get(e);
    if (!got) { var d = e.getAttribute("d"); still.set(e, got = {n: (d.match(NUMS) || []).map(Number), curve: d.indexOf("C") >= 0}); }
    return got;
  }
  var graphs = new Map();
  function graph(e){  // a graph as drawn: a line (null: evaluated exactly) or its vertices, x ascending
    if (e.tagName === "line") return {line: [e.x1.baseVal.value, e.y1.baseVal.value, e.x2.baseVal.value, e.y2.baseVal.value]};
    // (a curve bounds more than one area: read once a redraw, again when its numbers change)
    var sl = S.pathSlot.get(e), made = graphs.get(e);
    if (made && made.sl === sl && made.text === (sl ? sl.text : null)) return made.g;
    var got = vertices(e);
    graphs.set(e, {sl: sl, text: sl ? sl.text : null, g: got});
    return got;
  }
  function vertices(e){
    var g = drawnOf(e), n = g.n, xs = [], ys = [], i, k;
    if (!g.curve) { for (i = 0; i + 1 < n.length; i += 2) { xs.push(n[i]); ys.push(n[i + 1]); } }
    else {
      // a French curve: drawn through its points at sixteen to a Bézier segment (BezierCurve.curve_points), each
      // segment a cubic in its parameter, so that four of them give it whole: the area takes 64 to a segment
      // (kernel/areas.py _graph), read off that cubic (Lagrange, through the four nearest points of the segment)
      var P = [[n[0], n[1]]];
      for (i = 2; i + 5 < n.length; i += 6) P.push([n[i + 4], n[i + 5]]);
      for (var seg = 0; seg + 16 < P.length; seg += 16) {
        for (k = 0; k < 16; k++) {
          // four nodes j0 .. j0 + 3 about the piece, inside the segment (never past its end: no extrapolation)
          var j0 = seg + Math.min(Math.max(k - 1, 0), 13);
          xs.push(P[seg + k][0]); ys.push(P[seg + k][1]);
          for (var q = 1; q < 4; q++) {
            var t = seg + k + q / 4 - j0, lx = 0, ly = 0;
            for (var a = 0; a < 4; a++) {
              var w = 1;
              for (var b = 0; b < 4; b++) if (b !== a) w *= (t - b) / (a - b);
              lx += w * P[j0 + a][0]; ly += w * P[j0 + a][1];
            }
            xs.push(lx); ys.push(ly);
          }
        }
      }
      xs.push(P[P.length - 1][0]); ys.push(P[P.length - 1][1]);
    }
    // (drawn from left to right, or right to left, as a graph mostly is: no sort)
    var up = true, down = true;
    for (i = 1; i < xs.length && (up || down); i++) { if (xs[i] < xs[i - 1]) up = false; if (xs[i] >= xs[i - 1]) down = false; }
    if (up) return {xs: xs, ys: ys};
    if (down) return {xs: xs.reverse(), ys: ys.reverse()};
    var order = xs.map(function(_, j){ return j; }).sort(function(p, q){ return xs[p] - xs[q] || p - q; });
    return {xs: order.map(function(j){ return xs[j]; }), ys: order.map(function(j){ return ys[j]; })};
  }
  function ordinate(g, x){
    if (g.line) { var l = g.line; return l[1] + (x - l[0]) * (l[3] - l[1]) / (l[2] - l[0]); }
    var xs = g.xs, lo = 0, hi = xs.length - 1;
    if (x <= xs[0]) return g.ys[0];
    if (x >= xs[hi]) return g.ys[hi];
    while (hi - lo > 1) { var m = (lo + hi) >> 1; if (xs[m] <= x) lo = m; else hi = m; }
    return xs[hi] === xs[lo] ? g.ys[lo] : g.ys[lo] + (x - xs[lo]) * (g.ys[hi] - g.ys[lo]) / (xs[hi] - xs[lo]);
  }
  function areaPieces(up, low, xa, xb){  // the region between two graphs from xa to xb, split where they cross
    var lo = Math.min(xa, xb), hi = Math.max(xa, xb), xs = [lo], i;
    // the two graphs' vertices between the ends, in order, each x once (both graphs run x ascending: merged)
    var a = up.xs || [], b = low.xs || [], ia = 0, ib = 0;
    while (ia < a.length || ib < b.length) {
      var x = ib >= b.length || (ia < a.length && a[ia] <= b[ib]) ? a[ia++] : b[ib++];
      if (x > lo && x < hi && x !== xs[xs.length - 1]) xs.push(x);
    }
    if (hi !== lo) xs.push(hi);
    var fx = [], fu = [], fl = [];
    for (i = 0; i < xs.length; i++) {
      var u = ordinate(up, xs[i]), l = ordinate(low, xs[i]);
      if (i > 0) {  // a strict change of sign between breakpoints: the crossing (both straight there)
        var d0 = fu[fu.length - 1] - fl[fl.length - 1], d1 = u - l;
        if ((d0 < 0 && 0 < d1) || (d1 < 0 && 0 < d0)) {
          var t = d0 / (d0 - d1), xc = xs[i - 1] + t * (xs[i] - xs[i - 1]), yc = fu[fu.length - 1] + t * (u - fu[fu.length - 1]);
          fx.push(xc); fu.push(yc); fl.push(yc);
        }
      }
      fx.push(xs[i]); fu.push(u); fl.push(l);
    }
    var sign = fu.map(function(u, j){ return Math.sign(u - fl[j]); }), ends = [0], out = [], rings = [];
    sign.forEach(function(sg, j){ if (sg === 0 && j > 0 && j < sign.length - 1) ends.push(j); });
    ends.push(sign.length - 1);
    ends = ends.filter(function(e, j){ return j === 0 || e !== ends[j - 1]; });
    for (var p = 0; p + 1 < ends.length; p++) {
      var a = ends[p], b = ends[p + 1], any = false;
      for (i = a; i <= b; i++) if (sign[i] !== 0) any = true;
      if (!any) continue;
      var rx = [], ry = [];
      for (i = a; i <= b; i++) { rx.push(fx[i]); ry.push(fu[i]); }
      for (i = b; i >= a; i--) { rx.push(fx[i]); ry.push(fl[i]); }
      var ring = [], kx = [], ky = [];  // the doubled points where a run starts or ends on a crossing dropped
      for (i = 0; i < rx.length; i++) {
        var q = (i + rx.length - 1) % rx.length;
        if (rx[i] !== rx[q] || ry[i] !== ry[q]) { ring.push(text2(rx[i]) + " " + text2(ry[i])); kx.push(round2(rx[i])); ky.push(round2(ry[i])); }
      }
      if (ring.length >= 3) { out.push("M" + ring.join("L") + "Z"); rings.push([kx, ky]); }
    }
    out.rings = rings;
    return out;
  }
  // an area's hatching (render/paths.py hatch_segments, as the drawing hatches it): lines *px* apart at *deg*
  // through the figure's origin, each cut to the ring where it crosses the ring's edges (even-odd, along the
  // line), pieces under half a unit left out
  function hatchOf(ring, px, deg){
    var a = deg * Math.PI / 180, ux = Math.cos(a), uy = -Math.sin(a), nx = -uy, ny = ux;
    var xs = ring[0], ys = ring[1], n = xs.length, t = new Float64Array(n), lo = Infinity, hi = -Infinity, i, d = "";
    for (i = 0; i < n; i++) { t[i] = xs[i] * nx + ys[i] * ny; if (t[i] < lo) lo = t[i]; if (t[i] > hi) hi = t[i]; }
    for (var k = Math.floor(lo / px); k * px <= hi; k++) {
      var c = k * px, cut = [];
      for (i = 0; i < n; i++) {
        var j = (i + 1) % n, ti = t[i], tj = t[j];
        if ((ti <= c) === (tj <= c)) continue;  // (half-open: a vertex on the line is counted once)
        var f = (c - ti) / (tj - ti);
        cut.push((xs[i] + f * (xs[j] - xs[i])) * ux + (ys[i] + f * (ys[j] - ys[i])) * uy);
      }
      cut.sort(function(p, q){ return p - q; });
      for (i = 0; i + 1 < cut.length; i += 2) {
        if (cut[i + 1] - cut[i] < 0.5) continue;
        d += "M" + text2(c * nx + cut[i] * ux) + " " + text2(c * ny + cut[i] * uy)
          + "L" + text2(c * nx + cut[i + 1] * ux) + " " + text2(c * ny + cut[i + 1] * uy);
      }
    }
    return d;
  }
  function drawAreas(every){  // (every: the areas of steps not shown too)
    for (var i = 0; i < areas.length; i++) {
      var A = areas[i], e = A.els, pieces;
      if (!e.every(function(x){ return x; }) || !(every || A.pieces[0].isConnected && !unseen.has(A.pieces[0]))) continue;
      // the curves and points it is drawn from at the shown value, shown or not (a shown one is, this frame)
      for (var s = 0; s < e.length; s++) if (!e[s].isConnected || unseen.has(e[s])) (S.slotsOf.get(e[s]) || []).forEach(write);
      // (drawn anew when the shown value moves: its marks are the sweep's at that value, and their texts, many
      // thousand characters, are not read back to be compared)
      var key = sweeps.indexOf(S) + " " + S.value;
      if (key === A.key) continue;
      A.key = key;
      pieces = areaPieces(graph(e[0]), graph(e[1]), e[2].cx.baseVal.value, e[3].cx.baseVal.value);
      for (var j = 0; j < Math.max(pieces.length, A.pieces.length); j++) {
        var el = A.pieces[j];
        if (!el) {  // a piece more than the book's value has: the first one's like, beside the others
          el = A.pieces[0].cloneNode(false);
          el.setAttribute("id", A.id + "-" + j);
          A.pieces[j - 1].parentNode.insertBefore(el, A.pieces[j - 1].nextSibling);
          A.pieces.push(el);
        }
        var h = A.hatches ? A.hatches[j] : null;
        if (A.hatches && !h && j < pieces.length) {  // (a piece the drawing did not hatch at the book's value: after it)
          h = A.hatches[j] = mk("path", "hatch", el.parentNode);
          h.setAttribute("id", el.id + "-hatch");
          el.parentNode.insertBefore(h, el.nextSibling);
        }
        if (j < pieces.length) {
          if (A.drawn[j] !== pieces[j]) {
            A.drawn[j] = pieces[j]; el.setAttribute("d", pieces[j]);
            if (h) { var hd = hatchOf(pieces.rings[j], HATCH.px, A.deg); if (h.getAttribute("d") !== hd) h.setAttribute("d", hd); }
          }
          if (el.hasAttribute("display")) { el.removeAttribute("display"); el.style.display = ""; }
          if (h && h.style.display) h.style.display = "";
        }
        // (in its style too: an end state's own area, .fin .fo, is shown by a rule that outranks the attribute)
        else {
          if (el.getAttribute("display") !== "none") { el.setAttribute("display", "none"); el.style.display = "none"; }
          if (h && h.style.display !== "none") h.style.display = "none";
        }
      }
    }
  }
  var followersIn = new Map(), settling = false;  // (the letters by their step group, gathered at the start)
  function bring(g){  // step group g's marks and letters at the shown value (step groups do not nest)
    (S.inGroup.get(g) || []).forEach(write);
    (followersIn.get(g) || []).forEach(follow);
  }
  function shown(g){  // step group g is back in the document: what was not drawn while it was out, drawn now
    if (!S) return;
    bring(g);
    // the break marks and areas once the player has put back every group the step shows (before it is drawn)
    if (!settling) { settling = true; Promise.resolve().then(function(){ settling = false; breakMarks(); drawAreas(); }); }
  }
  // The page writes what it shows.  A mark or letter its classes hide (display: none: the end state's
  // letters, which the plate letters itself, points it leaves out, another zoom level's letters) is restyled by
  // every number written into it all the same -- at piston-force's end state three of four elements written
  // were hidden -- so it waits, as the groups of the steps not shown do, until a new step, zoom level or end
  // state shows it (reveal), and is drawn then, before the frame.  Which are hidden is asked again then.
  var unseen = new Set(), seenKey = null, marked = null;
  function seeing(){  // the marks and letters hidden now, asked again when what hides them may have changed
    var key = svg.getAttribute("class") + "|" + svg.getAttribute("data-step") + "|" + furnitureOn;
    if (key === seenKey) return false;
    seenKey = key;
    unseen = new Set();
    if (!marked) {  // every element a given's sweep writes, and the letters
      marked = new Set();
      sweeps.forEach(function(W){ W.slots.forEach(function(sl){ marked.add(sl.el); }); });
      followers.forEach(function(fo){ marked.add(fo.g || fo.el); });
      areas.forEach(function(A){ marked.add(A.pieces[0]); });
    }
    // (no box: not rendered; asked of the laid-out page, as the letters' boxes are. checkVisibility() says an SVG
    // element with display: none is visible)
    marked.forEach(function(e){ if (e.isConnected && !e.getClientRects().length) unseen.add(e); });
    return true;
  }
  function drawMarks(){  // the shown marks and letters at the shown value (the hidden wait: seeing)
    var i, j;
    for (i = 0; i < S.loose.length; i++) if (!unseen.has(S.loose[i].el)) write(S.loose[i]);
    S.inGroup.forEach(function(list, g){
      // (a point out of the document -- the end state's hidden ones: the player's lean -- waits until it is shown)
      if (g.isConnected) for (j = 0; j < list.length; j++) if (!unseen.has(list[j].el) && list[j].el.isConnected) write(list[j]); });
    for (i = 0; i < followers.length; i++) {
      var fo = followers[i];
      // (a letter group out of the document -- its step's, or the end state's hidden ones: the player's lean --
      // waits until it is shown)
      if ((fo.g || fo.el).isConnected && !unseen.has(fo.g || fo.el)) follow(fo);
    }
  }
  function reveal(){  // a new step, zoom level or end state: what it shows anew, at the shown value
    if (S && seeing()) { drawMarks(); drawAreas(); }
  }
  // every mark at the shown value at once, shown or not, in the document or not (for a reader of the figure's
  // numbers: the browser tests); what the page shows is untouched
  api.flush = function(){
    fillStale();
    if (!S) return;
    S.slots.forEach(write);
    if (player && player.pin) player.pin();
    followers.forEach(follow);
    breakMarks(true);
    drawAreas(true);
  };
  // ---- the camera: the shown step's view and ring at the shown value --------------------------------------------
  function view(atOnce, drag){  // what the player's show(k) does with the view, without touching the steps (cheap)
    var d = player.data, k = +(svg.getAttribute("data-step") || d.n), st = k > 0 ? d.steps[k - 1] : null;
    // (the end step at the book's values, where the plate's furniture held away from them is shown: the view the
    // camera made room in for it; elsewhere the sweep's, which frames the marks drawn there, live/measure.py)
    var builtView = k === d.n && S.L.furniture_held && furnitureOn ? endView : null;
    if (st && st[IDX] >= 0 && (builtView || S.zoomAt[k - 1] !== undefined)) {
      for (var i = 0; i < 4; i++) d[VIEWS][st[IDX]][i] = builtView ? builtView[i] : round2(num(S.zoomAt[k - 1] + i));
    }
    if (st && st.r && S.ringAt[k - 1] !== undefined) {  // the ring (the array the player rings with): round its mark
      st.r[0] = round2(num(S.ringAt[k - 1])); st.r[1] = round2(num(S.ringAt[k - 1] + 1));
    }
    // the inset (the step's small work magnified beside the view): a sliver's box carried with its points
    // (live/measure.py; a cluster's the player finds about its finest detail), drawn after the marks (its points
    // are read off their circles)
    insetDue = !!(st && (st.z || st.zd));
    if (insetDue && S.insetAt[k - 1] !== undefined) for (var zi = 0; zi < 4; zi++) st.z[zi] = round2(num(S.insetAt[k - 1] + zi));
    // the player moves its view there itself: at once while the given is dragged, smoothly to a new step
    if (player.jump && atOnce) { player.jump(!!drag); return; }
    if (player.move) { player.move(); return; }
  }
  // ---- letters that come to lie on one another: the later gives way -------------------------------------------
  var boxes = null, boxKey = null, pairs = null, lsRule = null;
  Array.prototype.forEach.call(document.styleSheets, function(sh){  // the letters' scale (the player's --ls)
    Array.prototype.forEach.call(sh.cssRules, function(r){
      if (!lsRule && r.style && r.style.getPropertyValue("--ls")) lsRule = r; });
  });
  var sized = null;  // the figure's box on the screen when the boxes were measured: [width, height]
  function measure(){  // each shown label group's box about its anchor, in the figure's units (asked again when
    // the zoom level, the letters' scale, the step or the window changes, not when only the view moves: a letter's
    // box in the figure's units is its --ls and zoom level's alone, so a new view, which a drag's camera takes
    // as the figure moves, asks no layout of the page)
    var key = svg.getAttribute("class") + "|" + (lsRule ? lsRule.style.getPropertyValue("--ls") : "")
      + "|" + svg.getAttribute("data-step") + "|" + window.innerWidth + "x" + window.innerHeight;
    if (key === boxKey && boxes) return true;
    // the figure's map to the screen (a layout of the page, forced after the frame's writes)
    var ctm = player && player.ctm ? player.ctm() : svg.getScreenCTM();  // (with the camera's transform in a drag)
    if (!ctm) return false;
    var s = Math.hypot(ctm.a, ctm.b);  // screen pixels per unit of the figure
    if (!s) return false;
    boxKey = key; boxes = new Map(); sized = [svg.clientWidth, svg.clientHeight];
    followers.forEach(function(fo){
      if (!fo.g || !fo.g.isConnected) return;
      var t = fo.g.querySelector("text:last-of-type"), r = t ? t.getBoundingClientRect() : null;
      if (!r) return;
      if (!r.width && !r.height) return;
      var px = ctm.a * fo.at[0] + ctm.c * fo.at[1] + ctm.e, py = ctm.b * fo.at[0] + ctm.d * fo.at[1] + ctm.f;
      boxes.set(fo, [(r.left - px) / s, (r.top - py) / s, (r.right - px) / s, (r.bottom - py) / s]);
    });
    return true;
  }
  function pixel(){  // one screen pixel in the figure's units, in the view shown (the viewBox fitted into the box)
    var v = player && player.view ? player.view() : (svg.getAttribute("viewBox") || "").split(/[ ,]+/).map(Number);
    var s = v.length === 4 && v[2] > 0 && v[3] > 0 ? Math.min(sized[0] / v[2], sized[1] / v[3]) : 0;
    return s > 0 ? 1 / s : 0;
  }
  function clash(p, q, px){  // two boxes overlapping by more than a screen pixel
    return p[0] < q[2] - px && p[2] > q[0] + px && p[1] < q[3] - px && p[3] > q[1] + px;
  }
  function declutter(){
    if (!measure()) return;
    var k = +(svg.getAttribute("data-step") || 0), placed = [], out = [], px = pixel();
    followers.forEach(function(fo){
      var rel = boxes.get(fo);
      if (!rel) { if (fo.hid) { fo.hid = false; fo.g.removeAttribute("visibility"); } return; }
      var x = fo.at[0], y = fo.at[1];
      // the current step's letters first, then letters before name tags, then by step (the figure's order)
      out.push({fo: fo, b: [x + rel[0], y + rel[1], x + rel[2], y + rel[3]], rank: (fo.step === k ? 0 : 2) + (fo.tag ? 1 : 0)});
    });
    out.sort(function(a, b){ return a.rank - b.rank || a.fo.step - b.fo.step; });
    out.forEach(function(o){
      var hit = false;
      for (var i = 0; i < placed.length && !hit; i++) {
        // (letters the placer set touching at the book's value stay as it set them)
        if (clash(o.b, placed[i].b, px) && !(pairs && pairs.has(o.fo) && pairs.get(o.fo).has(placed[i].fo))) hit = true;
      }
      if (!hit) placed.push(o);
      if (hit !== !!o.fo.hid) { o.fo.hid = hit; if (hit) o.fo.g.setAttribute("visibility", "hidden"); else o.fo.g.removeAttribute("visibility"); }
    });
    return out;
  }
  // ---- a redraw ---------------------------------------------------------------------------------------------
  function redraw(value, dragging, glide){  // glide: the camera to the step's view smoothly (let go)
    var t0 = performance.now(), u = Math.log10(value), ct = cell(S.L, u), U = S.L.ucols;
    cur = {r0: ct[0] * U, r1: Math.min(ct[0] + 1, S.L.rows - 1) * U, t: ct[1]};
    S.value = value;
    if (S.full) {  // the whole figure's box (the view when not magnified)
      var was = S.full.text;
      write(S.full);
      if (S.full.text !== was) {
        svg.setAttribute("data-full", S.full.text);
        if (player) for (var q = 0; q < 4; q++) player.full[q] = S.full.v[q];
        if (!player && !svg.classList.contains("zoomed")) svg.setAttribute("viewBox", S.full.text);
      }
    }
    // (the end state, the last step drawn as the book's plate, follows as the rest: its own marks and the plate's
    // furniture there are swept; what the furniture writes that is read off the figure is a reading, below)
    var atBook = Math.abs(Math.log10(value) - Math.log10(S.L.initial)) < 1e-9;  // (the other givens are there)
    // (the plate's furniture there follows the given item by item, unless it cannot be matched so over the domain,
    // a plate of panels: live/measure.py furniture_kept; then it is shown at the book's values alone, and the page
    // says so)
    var furnitureShown = furnitureOn = atBook || !S.L.furniture_held;
    for (var fi = 0; fi < endFurniture.length; fi++) {
      var fs = furnitureShown ? "" : "none"; if (endFurniture[fi].style.display !== fs) endFurniture[fi].style.display = fs;
    }
    var noted = atBook || !(S.L.furniture_held || S.L.furniture_note);
    if (endNote && endNote.hidden !== noted) endNote.hidden = noted;
    if (endNote && !noted) {  // (each given's own: what of the plate comes and goes with it)
      var said = S.L.furniture_note || endNote.getAttribute("data-held");
      if (endNote.textContent !== said) endNote.textContent = said;
    }
    for (var hi = 0; hi < hatches.length; hi++) {
      var hs = atBook ? "" : "none"; if (hatches[hi].style.display !== hs) hatches[hi].style.display = hs;
    }
    // the view first (the player reads the figure's size there: nothing written yet, no layout forced)
    if (player) view(!glide, dragging);
    seeing();  // (a new zoom level or end state: which marks are hidden)
    drawMarks();
    if (insetDue && player.inset) player.inset();
    if (player && player.pin) player.pin();  // (the end state's turned texts and arrowheads about their new anchors)
    drawAreas();
    breakMarks();
    // readings of the figure (an angle to the minute, a dimension's value): as read at the shown value (between)
    var near = ct[1] < 0.5 ? ct[0] : Math.min(ct[0] + 1, S.L.rows - 1);
    // (one of them blended a digit shorter: every number the figure writes a digit shorter there, so that a plate
    // writes its numbers with the same digits -- not +1,50 beside +0,093)
    var shorter = false;
    for (var j = 0; j < readings.length && !atBook && !shorter; j++) shorter = readings[j].L === S.L && blended(readings[j].texts, ct);
    for (var j = 0; j < readings.length; j++) {
      // (at the book's value, which the grid may miss by a hair, the built figure's own)
      var rd = readings[j], said = rd.L === S.L ? (atBook ? rd.built : between(rd.texts, ct, shorter)) : rd.L.given !== S.L.given ? rd.built : null;
      if (said) for (var rj = 0; rj < rd.els.length; rj++) setText(rd.els[rj], said);
    }
    // the plate's items that come and go with the given (a scale's ticks: live/measure.py Measure._furniture):
    // shown where the nearer grid value's plate has them
    for (var aj = 0; aj < absent.length; aj++) {
      var ab = S.L.absent[absent[aj].id], as = ab && ab[near] ? "none" : "";
      if (absent[aj].el.style.display !== as) absent[aj].el.style.display = as;
    }
    declutter();
    api.value = value; api.given = S.L.given;
    var said = book(value);
    if (S.out && S.out.textContent !== said) { setText(S.out, said); retitle(); }
    showChecks(S, u, dragging);
    api.lastMs = performance.now() - t0;
  }
  // A reading between two grid values: its decimal numbers (a value the plate writes, +0,748) blended between the
  // two values' readings and written with one digit fewer where they differ (the readings travel rounded to the
  // digits written: a blend of two rounded numbers is good to about a unit of their last digit, not to its half;
  // a fresh replay's +0,746 at L/r 2 is written +0,75, where the nearer grid value's +0,748 claimed a digit it has
  // not); at a grid value, and for an angle to the minute (a blend would print minutes the figure does not have),
  // the nearer grid value's reading.  *shorter*: another number of the figure is blended there -- this one is written
  // a digit shorter too, where it has two decimals or more (blended or not)
  var DECIMAL = /([+\u2212-]?)([0-9]+)([.,])([0-9]+)/g;
  function blended(texts, ct){  // whether a reading is blended between grid values at *ct* (between's own test)
    var t = ct[1], a = texts[ct[0]];
    return t >= 1e-9 && t <= 1 - 1e-9 && a !== texts[Math.min(ct[0] + 1, texts.length - 1)] && /[0-9][.,][0-9]{2}/.test(a);
  }
  function between(texts, ct, shorter){
    var a = texts[ct[0]], b = texts[Math.min(ct[0] + 1, texts.length - 1)], t = ct[1];
    if ((a === b && !shorter) || t < 1e-9 || t > 1 - 1e-9) return t < 0.5 ? a : b;  // (at a grid value: the slider's log10 to 1e-12)
    var na = [], nb = [];
    a.replace(DECIMAL, function(m){ na.push(m); return ""; });
    b.replace(DECIMAL, function(m){ nb.push(m); return ""; });
    var near = t < 0.5 ? a : b;
    if (!na.length || na.length !== nb.length || a.replace(DECIMAL, "#") !== b.replace(DECIMAL, "#")) return near;
    var k = 0, bad = false;
    var out = a.replace(DECIMAL, function(m, sign, whole, comma, frac){
      var q = nb[k++], mb = /([+\u2212-]?)([0-9]+)([.,])([0-9]+)/.exec(q);
      if (m === q && (!shorter || frac.length < 2)) return m;
      if (mb[4].length !== frac.length || frac.length < 2) { bad = true; return m; }
      var va = (sign === "+" || !sign ? 1 : -1) * Number(whole + "." + frac), vb = (mb[1] === "+" || !mb[1] ? 1 : -1) * Number(mb[2] + "." + mb[4]);
      var v = va + (vb - va) * t, d = frac.length - 1, r = Math.abs(v).toFixed(d);
      var s = Number(r) === 0 ? "" : v < 0 ? (sign === "-" || mb[1] === "-" ? "-" : "\u2212") : sign === "+" || mb[1] === "+" ? "+" : "";
      return s + r.replace(".", comma);
    });
    return bad ? near : out;
  }
  function pieceOf(given, value){  // the sweep of *given* whose piece of the domain holds *value* (or is nearest)
    var best = null, bd = Infinity;
    sweeps.forEach(function(w){
      if (w.L.given !== given) return;
      var p = w.L.piece || [w.L.low, w.L.high], d = value < p[0] ? p[0] / value : value > p[1] ? value / p[1] : 1;
      if (d < bd) { bd = d; best = w; }
    });
    return best;
  }
  function valueOf(given){  // the shown value of *given* (a given not moving is at the book's value)
    return S && S.L.given === given ? S.value : LIST.filter(function(L){ return L.given === given; })[0].initial;
  }
  function activate(W){  // another given moves: the one that moved goes back to its book value first
    if (W === S) return;
    if (S && S.L.given !== W.L.given) {
      var B = pieceOf(S.L.given, S.L.initial);  // (the piece of its domain the book's value lies in)
      var moved = B !== S || Math.abs(S.value - S.L.initial) > 1e-12 * S.L.initial;
      if (B !== S) { S = B; S.dirty(); }
      if (moved) redraw(S.L.initial, false, false);
      S.input.value = Math.log10(S.L.initial);
      setText(S.out, book(S.L.initial));
    }
    shownAt = -1;  // (another piece of the same given: its own checks)
    S = W;
    S.dirty();  // (the letters' boxes about their anchors are the same in every piece and given: kept)
  }
  // ---- the page's title, givens and checks name the shown values -------------------------------------------
  var titled = [], NUM = "[0-9]+(?:[.,][0-9]+)?", forms = {};
  LIST.forEach(function(L){
    // the given as the texts write it (live/sweep.py LiveGiven.written): L/r = 5, r/L = 1/5, κ = P/Bmax = 8
    forms[L.given] = (L.written && L.written.length ? L.written : [L.symbol + " = "])
      .map(function(f){ return [f, new RegExp(f.replace(/[.*+?^${}()|[\]\\/]/g, "\\$&") + NUM, "g")]; });
  });
  document.querySelectorAll("header h1, header h1 *, #givens th, #givens td").forEach(function(e){
    e.childNodes.forEach(function(t){
      if (t.nodeType === 3) titled.push({n: t, text: t.nodeValue, en: !!(t.parentNode.closest && t.parentNode.closest(".en")),
                                         head: !!(t.parentNode.closest && t.parentNode.closest("header"))});
    });
  });
  // givens that follow from the moving one and that the texts write (live/sweep.py DERIVED_WRITTEN): the two
  // cranks' magnification, chosen again at every rod
  var derived = [];
  LIST.forEach(function(L){
    Object.keys(L.derived || {}).forEach(function(k){
      derived.push({L: L, values: L.derived[k].values, forms: L.derived[k].written.map(function(f){
        return [f, new RegExp(f.replace(/[.*+?^${}()|[\]\\/]/g, "\\$&") + NUM, "g")]; })});
    });
  });
  var cells = [];  // the givens table's cells that name a given: [cell, given, inverse, as written]
  document.querySelectorAll("#givens th").forEach(function(th){
    var t = th.textContent.trim(), td = th.nextElementSibling;
    LIST.forEach(function(L){
      if (t === L.given || t === L.symbol) cells.push([td, L.given, false, td.textContent]);
      else if (L.given === "rod_ratio" && (t === "r/L" || t === "r/l")) cells.push([td, L.given, true, td.textContent]);
    });
  });
  function retitle(){
    var now = derived.map(function(d){  // its value at the nearer grid value of its given's shown value
      var v = valueOf(d.L.given), W = pieceOf(d.L.given, v);
      if (W.L !== d.L) return null;  // (another piece's)
      var ct = cell(d.L, Math.log10(v));
      return d.values[ct[1] < 0.5 ? ct[0] : Math.min(ct[0] + 1, d.values.length - 1)];
    });
    titled.forEach(function(t){
      var text = t.text;
      if (t.head) Object.keys(forms).forEach(function(given){
        var v = valueOf(given), shown = t.en ? String(Number(v.toPrecision(4))) : book(v);
        forms[given].forEach(function(f){ f[1].lastIndex = 0; text = text.replace(f[1], f[0] + shown); });
      });
      derived.forEach(function(d, j){
        if (now[j] === null) return;
        d.forms.forEach(function(f){ f[1].lastIndex = 0; text = text.replace(f[1], function(m){
          return f[0] + (m.indexOf(",") >= 0 || !t.en && m.indexOf(".") < 0 ? book(now[j]) : String(Number(now[j].toPrecision(4)))); }); });
      });
      if (t.n.nodeValue !== text) t.n.nodeValue = text;
    });
    cells.forEach(function(c){  // each number of the cell as written, in its own language (2,0 m / 2.0 m)
      var v = valueOf(c[1]);
      setText(c[0], c[2] ? "1/" + book(v) : c[3].replace(new RegExp(NUM, "g"), function(n){
        return n.indexOf(".") >= 0 ? String(Number(v.toPrecision(4))) : book(v); }));
    });
  }
  var body = document.querySelector("#live-checks tbody"), shownAt = -1, shownL = null, rowsOf = [], stale = 0;
  function put(td, text, cls){  // a cell's text (and class) written only when it changes: no row is rebuilt
    setText(td, text);
    if (cls !== undefined && td.className !== cls) td.className = cls;
  }
  // While a given is dragged, the rows out of sight (the table scrolls in its box, the box is often below the
  // window) wait: each changed cell lays the table out again, and the whole table's cells changing together
  // cost a drag's frame a third of its time (127 rows of piston-force's); a row coming into sight, letting go,
  // and constructLive.flush() bring them up to date
  var inSight = window.IntersectionObserver ? new IntersectionObserver(function(seen){
    seen.forEach(function(e){
      var i = e.target.sectionRowIndex, row = rowsOf[i];
      if (!row || row[0].parentNode !== e.target) return;
      row.seen = e.isIntersecting;
      if (row.seen && row.stale) fill(i);
    });
  }) : null;
  function fill(i){  // row i's cells at the shown nearest swept value
    var L = shownL, c = L.checks[shownAt][i], td = rowsOf[i], fmt = function(x){ return x === null ? "–" : x.toPrecision(8); };
    // [formula, error, ok, constructed value where formula + error does not give it] (live/wire.py _check_table)
    var made = c.length > 3 ? c[3] : (c[0] === null || c[1] === null ? null : c[0] + c[1]);
    put(td[0], L.check_names[i]); put(td[1], fmt(made)); put(td[2], fmt(c[0]));
    put(td[3], c[1] === null ? "–" : c[1].toExponential(1)); put(td[4], c[2] ? "✓" : "✗", c[2] ? "ok" : "bad");
    if (td.stale) { td.stale = false; stale--; }
  }
  function fillStale(){  // the rows left out of sight while dragging
    for (var i = 0; stale && i < rowsOf.length; i++) if (rowsOf[i].stale) fill(i);
  }
  function showChecks(W, u, dragging){
    var L = W.L;
    if (!L.checks || !L.checks.length) return;
    var k = 0, bd = Infinity;  // the nearest value the checks were swept at, in log10
    L.check_values.forEach(function(v, i){ var d = Math.abs(Math.log10(v) - u); if (d < bd) { bd = d; k = i; } });
    // the value the numbers belong to, and, where the slider stands elsewhere, that it is the nearest one computed
    // (a check's error is its point: a blend of two values' numbers would claim a check no one made)
    var at = L.check_values[k], own = book(at) === book(Math.pow(10, u));
    put(document.getElementById("live-at"), "(" + L.symbol + " = " + book(at) + (own ? ")" :
        ": nächster berechneter Wert zu " + book(Math.pow(10, u)) + " / the nearest computed value to " +
        String(Number(Math.pow(10, u).toPrecision(4))) + ")"));
    if (k === shownAt && L === shownL) { if (!dragging) fillStale(); return; }
    shownAt = k; shownL = L;
    var rows = L.checks[k];
    // the rows are made once (a rebuilt table is laid out anew, at the cost of a frame); their cells change
    while (rowsOf.length > rows.length) {
      var gone = rowsOf.pop();
      if (gone.stale) stale--;
      if (inSight) inSight.unobserve(gone[0].parentNode);
      body.removeChild(gone[0].parentNode);
    }
    while (rowsOf.length < rows.length) {
      var tr = document.createElement("tr"), row = [];
      for (var j = 0; j < 5; j++) row.push(tr.appendChild(document.createElement("td")));
      row.seen = true; row.stale = false;  // (in sight until the observer says otherwise)
      body.appendChild(tr);
      rowsOf.push(row);
      if (inSight) inSight.observe(tr);
    }
    for (var r = 0; r < rows.length; r++) {
      if (!dragging || rowsOf[r].seen) fill(r);
      else if (!rowsOf[r].stale) { rowsOf[r].stale = true; stale++; }
    }
  }
  // ---- start ------------------------------------------------------------------------------------------------
  function load(L){
    var W = new Sweep(L);
    return inflate(L.meta_z).then(function(b){
      var m = json(b);
      L.grid = m.grid; L.keys = m.keys; L.flags = m.flags; L.jumps = m.jumps; L.reading_texts = m.readings || {}; L.absent = m.absent || {};
      return L.checks_z ? inflate(L.checks_z) : null;
    }).then(function(b){
      if (b) { var c = json(b); L.check_names = c.check_names; L.check_values = c.check_values; L.checks = c.checks; }
      return inflate(L.data);
    }).then(function(buf){ W.buf = buf; return W; });
  }
  var endNote = null, insetDue = false, hatches = [], HATCH = null, endWritesRod = false, endAt = 0, endFurniture = [], furnitureOn = true, endView = null;
  api.ready = Promise.all(LIST.map(load)).then(function(ws){
    player = window.constructPlayer;
    endAt = player ? player.data.end : 0;
    HATCH = player ? player.data.hatch : null;
    endFurniture = Array.prototype.slice.call(svg.querySelectorAll("#furniture > g.fo"));
    svg.querySelectorAll("#furniture g.fo.end text").forEach(function(t){ if (/^L\s*=\s*[0-9]/.test(t.textContent)) endWritesRod = true; });
    var held = LIST.filter(function(L){ return L.furniture_held || L.furniture_note; });
    if (player && player.data.end && held.length) {
      endNote = document.createElement("div");
      endNote.className = "live-end"; endNote.hidden = true; endNote.setAttribute("style", "color:#777;font-size:12px");
      var wholly = LIST.filter(function(L){ return L.furniture_held; });
      endNote.textContent = !wholly.length ? held[0].furniture_note :
        "Der letzte Schritt zeigt Maße, Skala und Beschriftung der Tafel nur beim Buchwert von " + wholly[0].symbol +
        " (ihre Form ändert sich mit ihm). / The last step shows the plate’s dimensions, scale and lettering at the " +
        "book’s value of " + wholly[0].symbol + " only (their form changes with it).";
      endNote.setAttribute("data-held", endNote.textContent);
      var before = document.querySelector("#live .live-held");
      if (before) before.parentNode.insertBefore(endNote, before.nextSibling);
    }
    if (player) {  // each step's view (the camera's, or the magnified box) gets a box of its own, moved with the given
      VIEWS = player.data.views ? "views" : "zooms"; IDX = player.data.views ? "v" : "z";
      var own = [];
      player.data.steps.forEach(function(st, i){
        own[i] = st[IDX] >= 0 ? player.data[VIEWS][st[IDX]].slice() : null; if (st[IDX] >= 0) st[IDX] = i; });
      player.data[VIEWS] = own;
      endView = own[own.length - 1] && own[own.length - 1].slice();
    }
    sweeps = ws;
    ws.forEach(function(W){ W.prepare(W.buf); W.buf = null; });
    S = pieceOf(LIST[0].given, LIST[0].initial);
    gather();
    followers.forEach(function(fo){ (followersIn.get(fo.grp) || followersIn.set(fo.grp, []).get(fo.grp)).push(fo); });
    // the lines a break can cross (the marks', not the letters' leaders; a straight line from point to point,
    // the rod lettered L, too)
    // and the lines the plate adds in the end state, its strokes (render/end_state.py end_furniture: fin-s<k>)
    svg.querySelectorAll("line[id], path[id]").forEach(function(l){
      if (!l.closest("g.lbg") && (!l.closest("#furniture") || /^fin-s/.test(l.id)) && (l.tagName === "line" || TWO.test(l.getAttribute("d")))) lines.push(l); });
    // the areas: their pieces and the marks they are drawn from
    (LIST[0].areas || []).forEach(function(a){
      var find = function(id){ return player && player.find ? player.find(id) : document.getElementById(id); };
      var pieces = [], el;
      for (var j = 0; (el = find(j ? a[0] + "-" + j : a[0])); j++) pieces.push(el);
      // (an area's hatching: drawn anew with it where the page knows how the drawing hatches it (player.data.hatch),
      // else held at the book's value, shown there alone)
      var deg = HATCH ? HATCH.deg[a[0]] : undefined, hs = pieces.map(function(p){ return find(p.id + "-hatch"); });
      if (deg === undefined) hs.forEach(function(h){ if (h) hatches.push(h); });
      if (pieces.length) areas.push({id: a[0], pieces: pieces, els: a.slice(1).map(find), key: null, deg: deg,
                                     hatches: deg !== undefined ? hs : null,
                                     drawn: pieces.map(function(p){ return p.getAttribute("d"); })});
    });
    // the break marks as built give way to the page's own (drawn at every value, the built one too)
    // (the rod's length as built: the page writes its own where the drawing wrote it, "axis dx dy anchor")
    svg.querySelectorAll("#furniture .rodlen[data-rod]").forEach(function(g){
      var r = g.getAttribute("data-rod").split(" ");
      if (!rodSpots[+r[0]]) rodSpots[+r[0]] = [+r[1], +r[2], r[3]]; });
    svg.querySelectorAll("#furniture .brk, #furniture .brkline, #furniture .rodlen").forEach(function(e){ e.parentNode.removeChild(e); });
    // (each reading's texts: its letter's, and its halo's in its group; a text of runs, P_b, keeps its runs)
    LIST.forEach(function(L){ Object.keys(L.absent).forEach(function(id){
      var el = document.getElementById(id);
      if (el && !absent.some(function(a){ return a.id === id; })) absent.push({id: id, el: el}); }); });
    LIST.forEach(function(L){ (L.readings || []).forEach(function(id){
      var t = player && player.find ? player.find(id) : document.getElementById(id), g = t && t.closest("g.lbg");
      var els = (g ? Array.prototype.slice.call(g.querySelectorAll("text")) : t ? [t] : [])
        .filter(function(e){ return !e.firstElementChild; });
      if (els.length) readings.push({L: L, els: els, texts: L.reading_texts[id] || [], built: t.textContent});
    }); });
    // the rod's length the plate's furniture writes in the end state (a dimension "L = 5 r"): written anew
    var rodL = LIST.filter(function(L){ return L.rod; })[0];
    if (rodL) svg.querySelectorAll("#furniture text[id]").forEach(function(t){
      if (t.textContent === rodL.rod.replace("{v}", book(rodL.initial))) rodTexts.push(t); });
    // the groups the step hides leave the document (a new letter scale restyles them all the same)
    if (player && player.lean) player.lean();
    cur = {r0: 0, r1: 0, t: 0};
    redraw(S.L.initial, false, false);
    pairs = new Map();  // letters the placer set touching at the book's value (they stay so)
    var seen = declutter() || [];
    seen.forEach(function(a){ if (a.fo.hid) { a.fo.hid = false; a.fo.g.removeAttribute("visibility"); } });
    var px = sized ? pixel() : 0;
    for (var i = 0; i < seen.length; i++) for (var j = i + 1; j < seen.length; j++) {
      if (clash(seen[i].b, seen[j].b, px)) {
        (pairs.get(seen[i].fo) || pairs.set(seen[i].fo, new Set()).get(seen[i].fo)).add(seen[j].fo);
        (pairs.get(seen[j].fo) || pairs.set(seen[j].fo, new Set()).get(seen[j].fo)).add(seen[i].fo);
      }
    }
    ws.filter(function(W, i){ return ws.indexOf(pieceOf(W.L.given, W.L.initial)) === i; }).forEach(function(W){
      // one slider a given (its pieces share it): a drag sends more input events than frames, the last value of
      // each frame is drawn, once, just before it, by the piece of the domain it lies in
      var pending = false, input = W.input, given = W.L.given;
      var go = function(dragging, glide){ var v = Math.pow(10, +input.value); activate(pieceOf(given, v)); redraw(v, dragging, glide); };
      input.addEventListener("input", function(){
        if (pending) return;
        pending = true;
        requestAnimationFrame(function(){ pending = false; go(true); });
      });
      // let go (or a key's step): the letters at their exact scale, the camera gliding to the step's view
      input.addEventListener("change", function(){ requestAnimationFrame(function(){ go(false, true); }); });
    });
    // a group the step shows again: its marks, letters, break marks and areas at the shown value, before it is drawn
    if (player) player.shown = shown;
    // a new step: its view and ring at the shown value (the player has just set the built view); the letters
    // it shows make room for one another
    var seenStep = svg.getAttribute("data-step");
    if (player) new MutationObserver(function(){
      var now = svg.getAttribute("data-step");
      reveal();
      if (now !== seenStep) { seenStep = now; view(); breakMarks(); if (insetDue && player.inset) player.inset(); }  // (the rod's length: the plate's, or the page's)
      declutter();
    }).observe(svg, {attributes: true, attributeFilter: ["data-step", "viewBox", "class"]});
    showChecks(S, Math.log10(S.L.initial));
  });
  api.set = function(value, dragging, name){  // dragging: drawn as a drag draws it (the player's DRAG_LARGER)
    var L = name ? LIST.filter(function(l){ return l.given === name; })[0] : LIST[0];
    value = Math.min(L.high, Math.max(L.low, value));
    var W = pieceOf(L.given, value);
    activate(W);
    W.input.value = Math.log10(value);
    redraw(value, !!dragging);
    return api.lastMs;
  };
})();
"""
