"""The live given in the player page: a slider per continuous given, redrawing the figure from precomputed data.

:func:`with_live` adds to a player page (:func:`construct.render.player.player_html`)
an ``<input type="range" name="GIVEN">`` (log10 of the given over its stated
domain: the rod ratio runs from 1.05 to 1000, and a teacher lives between 3 and
8), the value in the book's notation, the construction's checks at the
nearest grid value, and a script that interpolates every drawn coordinate
between the grid values the data (:mod:`construct.constructions.live`) holds.
The page stays one file: the coordinates travel deflated in base64 and are
inflated with the browser's own ``DecompressionStream``.

The script exposes ``window.constructLive``: ``set(value)`` moves the given,
``ready`` is a promise for the inflated data, ``lastMs`` the last redraw's time.

>>> page = "<html><body><div id=stage></div>\\n<aside>\\n</aside>\\n</body></html>"
>>> out = with_live(page, {"given": "rod_ratio", "symbol": "L/r", "low": 1.05, "high": 1000.0,
...                        "initial": 5.0, "checks": []})
>>> 'name="rod_ratio"' in out and out.count("<script") == 2
True
"""

from __future__ import annotations

import html
import math
from typing import Any, Mapping

from .player import json_for_script

__all__ = ["with_live", "LIVE_SCRIPT"]


def with_live(page: str, data: Mapping[str, Any]) -> str:
    """*page* with the given's slider and checks at the top of its side panel and the live script before </body>."""
    g = html.escape(str(data["given"]))
    sym = html.escape(str(data["symbol"]))
    lo, hi, v0 = math.log10(data["low"]), math.log10(data["high"]), math.log10(data["initial"])
    controls = (f'<section id="live" style="background:#fff;border:1px solid #ddd;margin-top:8px;padding:6px 10px">'
                f'<label style="display:flex;gap:10px;align-items:center"><b class="sym">{sym}</b> '
                f'<input type="range" name="{g}" id="live-{g}" min="{lo:.12g}" max="{hi:.12g}" step="any" '
                f'value="{v0:.12g}" aria-label="{sym}" style="flex:1 1 auto">'
                f'<span>{sym} = <output id="live-value" style="font-variant-numeric:tabular-nums">'
                f'{html.escape(_book(data["initial"]))}</output></span></label>'
                f'<div class="live-range" style="color:#777;font-size:12px">{html.escape(_book(data["low"]))} … '
                f'{html.escape(_book(data["high"]))} (log. Skala / log scale; gebaut / built: '
                f'{html.escape(_book(data["initial"]))})</div>'
                f'<details open><summary>Prüfungen / checks <span id="live-at"></span></summary>'
                f'<div style="max-height:28vh;overflow:auto"><table id="live-checks" style="border-collapse:collapse;'
                f'font-size:12px;font-variant-numeric:tabular-nums"><thead><tr><th>Größe / quantity</th>'
                f'<th>konstruiert</th><th>Formel</th><th>Fehler</th><th></th></tr></thead><tbody></tbody></table>'
                f'</div></details></section>\n')
    # under the figure's caption, in the stage (the side panel scrolls with the step list)
    aside = page.index("<aside>")
    at = page.rindex("</div>", 0, aside)
    page = page[:at] + controls + page[at:]
    script = (f'<script type="application/json" id="live-data">{json_for_script(dict(data))}</script>\n'
              f"<script>{LIVE_SCRIPT}</script>\n")
    end = page.rindex("</body>")
    return page[:end] + script + page[end:]


def _book(v: float) -> str:
    return f"{v:.4g}".replace(".", ",")


#: The page's script (no external resource; text reaches the page through textContent only).
LIVE_SCRIPT = r"""
(function(){
  "use strict";
  var L = JSON.parse(document.getElementById("live-data").textContent);
  var svg = document.getElementById("figure");
  var input = document.querySelector('input[name="' + L.given + '"]');
  var out = document.getElementById("live-value");
  var api = window.constructLive = {lastMs: 0, value: L.initial};
  var book = function(v){ return String(Number(v.toPrecision(4))).replace(".", ","); };
  if (!L.data) { return; }
  function inflate(b64){
    var bin = atob(b64), bytes = new Uint8Array(bin.length);
    for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    var stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate"));
    return new Response(stream).arrayBuffer();
  }
  var rows = L.rows, cols = L.cols, D = null, slots = [], followers = [], pts = [], isFlag = null, LIST = "zooms", IDX = "z", player = null, zoomAt = [], cur = null, zooms = null;
  function prepare(buf){
    // the first row as int32, then the deltas along the grid column by column in byte planes (live.py: encode)
    var first = new Int32Array(buf.slice(0, 4 * cols)), bytes = new Uint8Array(buf, 4 * cols);
    var w = L.width, n = cols * (rows - 1);
    D = new Float64Array(rows * cols);
    for (var c = 0; c < cols; c++) {
      var acc = first[c];
      D[c] = acc * L.q;
      for (var r = 1; r < rows; r++) {
        var i = c * (rows - 1) + r - 1, v = 0;
        for (var b = w - 1; b >= 0; b--) v = (v << 8) | bytes[b * n + i];
        if (w === 2 && v >= 32768) v -= 65536;
        acc += v;
        D[r * cols + c] = acc * L.q;
      }
    }
    isFlag = new Uint8Array(cols);
    (L.flags || []).forEach(function(c){ isFlag[c] = 1; });
    var at = 0;
    player = window.constructPlayer;
    if (player) {  // each step's view (the camera's, or the magnified box) gets a box of its own, moved with the given
      LIST = player.data.views ? "views" : "zooms"; IDX = player.data.views ? "v" : "z";
      zooms = [];
      player.data.steps.forEach(function(st, i){
        zooms[i] = st[IDX] >= 0 ? player.data[LIST][st[IDX]].slice() : null; if (st[IDX] >= 0) st[IDX] = i; });
      player.data[LIST] = zooms;
    }
    L.keys.forEach(function(k){
      if (k[0] === "#zoom") {
        var parts = k[2].split("#");
        zoomAt[+k[1]] = at; at += parts.length - 1; return;  // computed for the shown step only (view)
      }
      var el = k[0] ? document.getElementById(k[0]) : svg;
      var parts = k[2].split("#");
      slots.push({el: el, attr: k[1], parts: parts, at: at});
      at += parts.length - 1;
    });
    // letters and leader lines follow the point they name: the nearest point of the built figure
    svg.querySelectorAll("circle.pt[id]").forEach(function(c){
      pts.push({el: c, x: +c.getAttribute("cx"), y: +c.getAttribute("cy")});
    });
    svg.querySelectorAll("text, line:not([id])").forEach(function(t){
      if (t.closest("#caption") || t.closest("#furniture")) return;
      // a label follows its mark (id "NAME-label"), its halo (the text before it) the same mark
      var named = t.id ? t : (t.nextElementSibling && t.nextElementSibling.tagName === "text" ? t.nextElementSibling : null);
      var owner = named && named.id && /-label$/.test(named.id) ? document.getElementById(named.id.slice(0, -6)) : null;
      if (owner && owner.tagName === "circle") {
        followers.push({el: t, p: {el: owner, x: +owner.getAttribute("cx"), y: +owner.getAttribute("cy")}, at: coords(t)});
        return;
      }
      var x = +(t.getAttribute("x") || t.getAttribute("x1")), y = +(t.getAttribute("y") || t.getAttribute("y1"));
      var best = null, bd = Infinity;
      pts.forEach(function(p){ var d = (p.x - x) * (p.x - x) + (p.y - y) * (p.y - y); if (d < bd) { bd = d; best = p; } });
      if (best && bd < 60 * 60) followers.push({el: t, p: best, at: coords(t)});
    });
  }
  function coords(e){  // a letter's x, y or a leader line's ends, as built; or its label group's translate
    var out = {}, g = e.parentNode, m = g && g.classList && g.classList.contains("lbg") &&
      /^translate\(([-0-9.e]+)[ ,]+([-0-9.e]+)\)$/.exec(g.getAttribute("transform") || "");
    if (m) return {translate: [+m[1], +m[2]], g: g};
    ["x", "y", "x1", "y1", "x2", "y2"].forEach(function(a){ var v = e.getAttribute(a); if (v !== null && v !== "" && !isNaN(+v)) out[a] = +v; });
    return out;
  }
  function cell(u){
    var g = L.grid, lo = 0, hi = g.length - 1;
    if (u <= g[0]) return [0, 0];
    if (u >= g[hi]) return [hi - 1, 1];
    while (hi - lo > 1) { var m = (lo + hi) >> 1; if (g[m] <= u) lo = m; else hi = m; }
    var t = (u - g[lo]) / (g[lo + 1] - g[lo]);
    // across a jump of the drawing (the broken axis appearing) the nearer side is drawn, not a blend
    var a = L.values[lo], b = L.values[lo + 1];
    for (var j = 0; j < L.jumps.length; j++) if (L.jumps[j][0] === a && L.jumps[j][1] === b) t = t < 0.5 ? 0 : 1;
    return [lo, t];
  }
  function view(){  // what the player's show(k) does with the view, without touching the steps (cheap)
    var d = player.data, k = +(svg.getAttribute("data-step") || d.n), st = k > 0 ? d.steps[k - 1] : null;
    if (st && st[IDX] >= 0 && cur && zoomAt[k - 1] !== undefined) {
      for (var i = 0; i < 4; i++) d[LIST][st[IDX]][i] = Math.round(valueAt(zoomAt[k - 1] + i) * 100) / 100;
    }
    if (player.move) { player.move(); return; }  // the camera's player moves its view there itself
    var zoom = document.getElementById("zoom");
    var box = st && zoom && zoom.checked && k < d.n && st.z >= 0 ? d.zooms[st.z] : null;
    svg.setAttribute("viewBox", (box || player.full).join(" "));
    svg.style.setProperty("--z", box ? (player.full[2] / box[2]).toFixed(3) : "1");
  }
  function valueAt(c){  // column c at the shown value
    return isFlag[c] ? (cur.t < 0.5 ? D[cur.r0 + c] : D[cur.r1 + c]) : D[cur.r0 + c] + (D[cur.r1 + c] - D[cur.r0 + c]) * cur.t;
  }
  function redraw(value){
    var t0 = performance.now();
    var u = Math.log10(value), ct = cell(u), r0 = ct[0] * cols, r1 = Math.min(ct[0] + 1, rows - 1) * cols, t = ct[1];
    cur = {r0: r0, r1: r1, t: t};
    var zoomed = svg.classList.contains("zoomed");
    for (var s = 0; s < slots.length; s++) {
      var sl = slots[s], parts = sl.parts, txt = parts[0];
      for (var i = 1; i < parts.length; i++) {
        var c = sl.at + i - 1, v = isFlag[c] ? (t < 0.5 ? D[r0 + c] : D[r1 + c]) : D[r0 + c] + (D[r1 + c] - D[r0 + c]) * t;
        txt += (Math.round(v * 100) / 100) + parts[i];
      }
      if (sl.el === svg) {
        svg.setAttribute("data-full", txt);
        if (player) { var nf = txt.split(" ").map(Number); for (var q = 0; q < 4; q++) player.full[q] = nf[q]; }
        if (zoomed) continue;
      }
      if (sl.el) sl.el.setAttribute(sl.attr, txt);
    }
    for (var f = 0; f < followers.length; f++) {
      var fo = followers[f], p = fo.p;
      var dx = +p.el.getAttribute("cx") - p.x, dy = +p.el.getAttribute("cy") - p.y;
      // moved by their own coordinates (a transform attribute would lose to the camera's CSS scale)
      if (fo.at.g) {  // the camera's label group: its anchor moves (the letters scale about it)
        fo.at.g.setAttribute("transform", "translate(" + (fo.at.translate[0] + dx).toFixed(2) + " " + (fo.at.translate[1] + dy).toFixed(2) + ")");
        continue;
      }
      for (var a in fo.at) fo.el.setAttribute(a, (fo.at[a] + (a.charAt(0) === "x" ? dx : dy)).toFixed(2));
    }
    // the broken axis's marks belong to the built value's break; elsewhere the break lies elsewhere or nowhere
    var furniture = document.getElementById("furniture");
    if (furniture) furniture.style.display = Math.abs(u - Math.log10(L.initial)) < 1e-9 ? "" : "none";
    if (player) view();  // the step's view (magnified or whole) at the new value
    api.value = value;
    out.textContent = book(value);
    retitle(value);
    showChecks(u);
    api.lastMs = performance.now() - t0;
  }
  // the page's title and givens name the built value: they name the shown one
  var titled = [], NUM = "[0-9]+(?:[.,][0-9]+)?";
  // the rod as the texts write it: L/r = 5, or r/L = 1/5 (seed 000, Baumann), r/l = 1/5 (§ 146)
  var forms = L.given === "rod_ratio" ? [["L/r = ", ""], ["r/L = 1/", ""], ["r/l = 1/", ""]] : [[L.symbol + " = ", ""]];
  forms.forEach(function(f){ f[1] = new RegExp(f[0].replace(/[.*+?^${}()|[\]\\/]/g, "\\$&") + NUM, "g"); });
  document.querySelectorAll("header h1, header h1 *").forEach(function(e){
    e.childNodes.forEach(function(t){
      if (t.nodeType === 3 && forms.some(function(f){ f[1].lastIndex = 0; return f[1].test(t.nodeValue); }))
        titled.push({n: t, text: t.nodeValue, en: !!(t.parentNode.closest && t.parentNode.closest(".en"))});
    });
  });
  var givenCell = null;
  document.querySelectorAll("#givens th").forEach(function(th){ if (th.textContent === L.given) givenCell = th.nextElementSibling; });
  function retitle(value){
    titled.forEach(function(t){
      var shown = t.en ? String(Number(value.toPrecision(4))) : book(value), text = t.text;
      forms.forEach(function(f){ text = text.replace(f[1], f[0] + shown); });
      t.n.nodeValue = text;
    });
    if (givenCell) givenCell.textContent = book(value);
  }
  var body = document.querySelector("#live-checks tbody"), shownAt = -1;
  L.checks = L.checks || [];
  function cellText(tr, text, cls){ var td = document.createElement("td"); td.textContent = text; if (cls) td.className = cls; tr.appendChild(td); }
  function showChecks(u){
    if (!L.checks || !L.checks.length) return;
    var k = 0, bd = Infinity;  // the nearest value the checks were swept at, in log10
    L.check_values.forEach(function(v, i){ var d = Math.abs(Math.log10(v) - u); if (d < bd) { bd = d; k = i; } });
    if (k === shownAt) return;
    shownAt = k;
    document.getElementById("live-at").textContent = "(" + L.symbol + " = " + book(L.check_values[k]) + ")";
    while (body.firstChild) body.removeChild(body.firstChild);
    L.checks[k].forEach(function(c, i){
      var tr = document.createElement("tr"), num = function(x){ return x === null ? "–" : x.toPrecision(8); };
      cellText(tr, L.check_names[i]); cellText(tr, num(c[0])); cellText(tr, num(c[1]));
      cellText(tr, c[2].toExponential(1)); cellText(tr, c[3] ? "✓" : "✗", c[3] ? "ok" : "bad");
      body.appendChild(tr);
    });
  }
  api.ready = (L.checks_z ? inflate(L.checks_z).then(function(b){
    var c = JSON.parse(new TextDecoder().decode(b)); L.check_names = c.check_names; L.check_values = c.check_values; L.checks = c.checks;
  }) : Promise.resolve()).then(function(){ return inflate(L.data); }).then(function(buf){
    prepare(buf);
    input.addEventListener("input", function(){ redraw(Math.pow(10, +input.value)); });
    // a new step: its magnified view at the shown value (the player has just set the built one)
    var seenStep = svg.getAttribute("data-step");
    if (player) new MutationObserver(function(){
      var now = svg.getAttribute("data-step");
      if (now !== seenStep) { seenStep = now; if (cur) view(); }
    }).observe(svg, {attributes: true, attributeFilter: ["data-step"]});
    showChecks(Math.log10(L.initial));
  });
  api.set = function(value){
    value = Math.min(L.high, Math.max(L.low, value));
    input.value = Math.log10(value);
    redraw(value);
    return api.lastMs;
  };
})();
"""
