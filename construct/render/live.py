"""The live given in the player page: a slider per continuous given, redrawing the figure from precomputed data.

:func:`with_live` adds to a player page (:func:`construct.render.player.player_html`)
an ``<input type="range" name="GIVEN">`` (log10 of the given over its stated
domain: the rod ratio runs from 1.05 to 1000, and a teacher lives between 3 and
8), the value in the book's notation, the construction's checks at the
nearest grid value, and a script that interpolates every drawn coordinate
between the grid values the data (:mod:`construct.live`) holds, in the wire format of
:mod:`construct.render.wire`.
The page stays one file: the coordinates travel deflated in base64 and are
inflated with the browser's own ``DecompressionStream``.

The script exposes ``window.constructLive``: ``set(value)`` moves the given
(``set(value, true)``: as a drag draws it), ``ready`` is a promise for the
inflated data, ``lastMs`` the last redraw's time.

A drag is drawn inside one animation frame (``construct bench --live``): each
frame draws only the marks and letters displayed in the window, the rest when
the slider is let go, a step is shown or the view changes; numbers are set as
SVG lengths, not parsed text; the camera keeps its view while the step's view
stays near it, and the letters their scale and zoom level (the player's
``holds`` and ``DRAG_LARGER``; exact, the camera gliding, on let-go); the
groups the step hides are out of the document (the player's ``lean``); the
checks' cells change in place.

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

from ..kernel.letters import number
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
                f'{html.escape(number(data["initial"], "de"))}</output></span></label>'
                f'<div class="live-range" style="color:#777;font-size:12px">{html.escape(number(data["low"], "de"))} … '
                f'{html.escape(number(data["high"], "de"))} (log. Skala / log scale; gebaut / built: '
                f'{html.escape(number(data["initial"], "de"))})</div>'
                # why there is one slider (a teacher asks for the next given first)
                f'<div class="live-held" style="color:#777;font-size:12px">Nur {sym} ist beweglich; die übrigen '
                f'Gegebenen bleiben beim Buchwert. / Only {sym} moves here; the other givens stay at the book’s '
                f'values: a second slider would need the sweep over both givens together, and the number of '
                f'parts changes the steps themselves.</div>'
                # a reading (an angle read off the figure, to the minute) blended between grid values would
                # print minutes the figure does not have
                + ('<div class="live-readings" style="color:#777;font-size:12px">Abgelesene Werte (Winkel) '
                   'stehen nur beim Buchwert. / Values read off the figure (angles) are shown at the book’s '
                   'value only.</div>' if data.get("readings") else '')
                + '<details open><summary>Prüfungen / checks <span id="live-at"></span></summary>'
                '<div style="max-height:28vh;overflow:auto"><table id="live-checks" style="border-collapse:collapse;'
                'font-size:12px;font-variant-numeric:tabular-nums"><thead><tr><th>Größe / quantity</th>'
                '<th>konstruiert</th><th>Formel</th><th>Fehler</th><th></th></tr></thead><tbody></tbody></table>'
                '</div></details></section>\n')
    # under the figure's caption, in the stage (the side panel scrolls with the step list)
    aside = page.index("<aside>")
    at = page.rindex("</div>", 0, aside)
    page = page[:at] + controls + page[at:]
    script = (f'<script type="application/json" id="live-data">{json_for_script(dict(data))}</script>\n'
              f"<script>{LIVE_SCRIPT}</script>\n")
    end = page.rindex("</body>")
    return page[:end] + script + page[end:]


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
  function setText(e, text){  // an element's one text node changed in place (no node replaced), if it changed
    var t = e.firstChild;
    if (t && t.nodeType === 3 && !t.nextSibling) { if (t.nodeValue !== text) t.nodeValue = text; }
    else if (e.textContent !== text) e.textContent = text;
  }
  if (!L.data) { return; }
  function inflate(b64){
    var bin = atob(b64), bytes = new Uint8Array(bin.length);
    for (var i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    var stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("deflate"));
    return new Response(stream).arrayBuffer();
  }
  var rows = L.rows, cols = L.cols, U = L.ucols, D = null, slots = [], followers = [], pts = [], LIST = "zooms", IDX = "z", player = null, zoomAt = [], ringAt = [], cur = null, zooms = null;
  var colmap = null, isFlag = null, moving = null, fullSlot = null, shownStep = Infinity, doneTo = -1, readings = [];
  function expand(buf){
    // live.py encode: the column map, each stored column's kind (drawn, or the construction's x, y, length
    // through the grid value's fit to the view), its kept grid values (bits), the fits, the first values,
    // then the deltas between kept values in byte planes; between kept values a column is a line in log10
    var bytes = new Uint8Array(buf), dv = new DataView(buf), at = 0, c, r, b;
    colmap = new Int32Array(cols);
    for (c = 0; c < cols; c++) colmap[c] = L.mapw === 2 ? dv.getUint16(at + 2 * c, true) : dv.getInt32(at + 4 * c, true);
    at += cols * L.mapw;
    var kinds = bytes.subarray(at, at + U);
    at += U;
    var keepAt = at, nbits = rows * U, kept = 0;
    at += (nbits + 7) >> 3;
    for (b = keepAt; b < at; b++) { var x = bytes[b]; while (x) { kept += x & 1; x >>= 1; } }
    var fit = new Float32Array(buf.slice(at, at + 12 * rows));
    at += 12 * rows;
    var firstAt = at, n = kept - U, w = L.width, planes = at + 4 * U, pos = 0, g = L.grid;
    var X = new Float64Array(rows);
    D = new Float32Array(rows * U);
    moving = new Uint8Array(U);
    for (c = 0; c < U; c++) {
      var r0 = 0, v0 = dv.getInt32(firstAt + 4 * c, true), kind = kinds[c], q = kind ? L.qx : L.q;
      X[0] = v0 * q;
      for (r = 1; r < rows; r++) {
        var bit = c * rows + r;
        if (!((bytes[keepAt + (bit >> 3)] >> (7 - (bit & 7))) & 1)) continue;
        var d = 0;
        for (b = w - 1; b >= 0; b--) d = (d << 8) | bytes[planes + b * n + pos];
        if (w === 2 && d >= 32768) d -= 65536;
        pos++;
        var v1 = v0 + d;
        for (var m = r0 + 1; m <= r; m++) X[m] = (v0 + (v1 - v0) * (g[m] - g[r0]) / (g[r] - g[r0])) * q;
        r0 = r; v0 = v1;
      }
      for (r = 0; r < rows; r++) {
        var s = fit[3 * r + 2], v = kind === 1 ? fit[3 * r] + s * X[r] : kind === 2 ? fit[3 * r + 1] - s * X[r] : kind === 3 ? s * X[r] : X[r];
        D[r * U + c] = v;
        if (r > 0 && Math.abs(v - D[c]) > 0.004) moving[c] = 1;
      }
    }
  }
  function prepare(buf){
    expand(buf);
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
    var byId = {};
    L.keys.forEach(function(k){
      var parts = k[2].split("#"), nn = parts.length - 1;
      // the view and the ring of a step: computed for the shown step only (view)
      if (k[0] === "#zoom") { zoomAt[+k[1]] = at; at += nn; return; }
      var el = k[0] ? document.getElementById(k[0]) : svg, cs = new Int32Array(nn), fl = new Uint8Array(nn), mv = false;
      for (var i = 0; i < nn; i++) { cs[i] = colmap[at + i]; fl[i] = isFlag[at + i]; if (moving[cs[i]]) mv = true; }
      at += nn;
      // a mark whose numbers do not move over the domain keeps its attribute as built: never written
      if (!el || (!mv && el !== svg)) return;
      var host = el.closest ? el.closest("g[data-step]") : null;
      var sl = {el: el, attr: k[1], parts: parts, cs: cs, fl: fl, v: new Float64Array(nn), text: el.getAttribute(k[1]),
                step: host ? +host.getAttribute("data-step") : 0, len: lengthOf(el, k[1], parts)};
      if (sl.len) sl.v[0] = sl.len.value;
      // the whole figure's box: written as data-full, and as the view by the player (or below without one)
      if (el === svg) { fullSlot = sl; sl.el = null; sl.text = svg.getAttribute("data-full") || sl.text; } else slots.push(sl);
      if (k[1] === "cx" || k[1] === "cy") (byId[k[0]] = byId[k[0]] || {})[k[1]] = sl;
    });
    // the marks of later steps are drawn when their step is shown (they are hidden until then)
    slots.sort(function(a, b){ return a.step - b.step; });
    // letters and leader lines follow the point they name: the nearest point of the built figure
    svg.querySelectorAll("circle.pt[id]").forEach(function(c){
      pts.push({el: c, x: +c.getAttribute("cx"), y: +c.getAttribute("cy"), s: byId[c.id]});
    });
    function nearest(x, y){
      var best = null, bd = 60 * 60;
      pts.forEach(function(q){ var d = (q.x - x) * (q.x - x) + (q.y - y) * (q.y - y); if (d < bd) { bd = d; best = q; } });
      return best;
    }
    function owned(t){  // the point a label names (its id "NAME-label"; a halo: the text after it)
      var named = t.id ? t : (t.nextElementSibling && t.nextElementSibling.tagName === "text" ? t.nextElementSibling : null);
      var owner = named && named.id && /-label$/.test(named.id) ? document.getElementById(named.id.slice(0, -6)) : null;
      return owner && owner.tagName === "circle" ? {el: owner, x: +owner.getAttribute("cx"), y: +owner.getAttribute("cy"), s: byId[owner.id]} : null;
    }
    function add(t, p){
      if (!p || !p.s) return;  // no point, or one that does not move
      var host = t.closest("g[data-step]");
      var at = coords(t), len = {};
      for (var a in at) if (a !== "g" && a !== "translate" && a !== "shift") len[a] = lengthOf(t, a, ["", ""]);
      followers.push({el: t, p: p, at: at, step: host ? +host.getAttribute("data-step") : 0, text: {}, len: len});
    }
    // a label group (the camera's: letters, halo and leader about an anchor) moves as one, with its point
    svg.querySelectorAll("g.lbg").forEach(function(g){
      if (g.closest("#caption") || g.closest("#furniture")) return;
      var m = /^translate\(([-0-9.e]+)[ ,]+([-0-9.e]+)\)$/.exec(g.getAttribute("transform") || "");
      var first = g.querySelector("text, line");
      if (!m || !first) return;
      var p = null;
      g.querySelectorAll("text").forEach(function(t){ p = p || owned(t); });
      add(first, p || nearest(+m[1], +m[2]));
    });
    // letters and leader lines drawn where they stand follow the point they name, or the nearest point
    svg.querySelectorAll("text, line:not([id])").forEach(function(t){
      if (t.closest("#caption") || t.closest("#furniture") || t.closest("g.lbg")) return;
      var x = +(t.getAttribute("x") || t.getAttribute("x1")), y = +(t.getAttribute("y") || t.getAttribute("y1"));
      add(t, owned(t) || nearest(x, y));
    });
    followers.sort(function(a, b){ return a.step - b.step; });
    group();
    // letters that are readings of the figure (an angle read off it): true at the built value only
    (L.readings || []).forEach(function(id){
      var t = document.getElementById(id);
      if (t) readings.push(t.closest("g.lbg") || t);
    });
    // the ring of a step (round its mark where that is small on the screen) follows the nearest point
    if (player) player.data.steps.forEach(function(st, i){
      var p = st.r ? nearest(st.r[0], st.r[1]) : null;
      if (p && p.s && p.s.cx && p.s.cy) ringAt[i] = {p: p, x: st.r[0], y: st.r[1]};
    });
  }
  // While the given is dragged only the marks in the window are drawn (at a magnified step much of the figure
  // lies outside it); each mark's box at the value is computed from its numbers, and a mark is drawn if that
  // box or the one it was last drawn at meets the window (widened by a margin).  The others are drawn when the
  // drag ends ('change'), the step or the view changes (the camera, the magnifier, the window's size): never
  // seen behind.
  var elems = [], MARGIN_PX = 40, LABEL_PX = 150, ownBox = null, stale = false, visKey = null, hid = new Map();
  // A mark in a group the step hides (display:none: later steps, finished groups, letters of another zoom
  // level) is not drawn either while dragging, yet a new attribute there costs the browser a restyle and a
  // layout all the same: at the inertia curve's last step 907 of its 1156 moving marks are hidden so.
  function hidden(node){  // the node or a group round it not displayed (known per step and zoom level)
    if (!node || node === svg || node.nodeType !== 1) return false;
    if (!node.isConnected) return true;  // in a group the player has taken out of the document (lean)
    var h = hid.get(node);
    if (h === undefined) { h = hidden(node.parentNode) || getComputedStyle(node).display === "none"; hid.set(node, h); }
    return h;
  }
  function shownNow(){  // what is displayed changes with the step and the zoom level's class only
    var key = svg.getAttribute("data-step") + "|" + svg.getAttribute("class");
    if (key !== visKey) { visKey = key; hid = new Map(); }
  }
  // what each number of a path's commands is: 1 an x, 2 a y, 3 a radius, 0 neither (arcs' angle and flags)
  var ROLES = {M: "12", L: "12", T: "12", H: "1", V: "2", C: "121212", S: "1212", Q: "1212", A: "3300012"};
  function rolesOf(attr, parts){  // null: numbers the box cannot be told from (the mark is always drawn)
    if (attr === "cx" || attr === "x1" || attr === "x2" || attr === "x") return parts.length === 2 ? [1] : null;
    if (attr === "cy" || attr === "y1" || attr === "y2" || attr === "y") return parts.length === 2 ? [2] : null;
    if (attr === "r") return parts.length === 2 ? [3] : null;
    if (attr !== "d") return null;
    var out = [], cmd = null, k = 0;
    for (var i = 0; i < parts.length - 1; i++) {
      var letters = parts[i].match(/[A-Za-z]/g);
      if (letters) { cmd = letters[letters.length - 1]; k = 0; }
      var pat = cmd && ROLES[cmd];
      if (!pat) return null;  // a relative command (lower case), or none: not told
      out.push(+pat.charAt(k % pat.length));
      k++;
    }
    return out;
  }
  var FIXED = {circle: ["cx", "cy", "r"], line: ["x1", "y1", "x2", "y2"], path: ["d"]};
  function group(){  // the slots of each mark together, with the numbers of its box that do not move
    var byEl = new Map();
    slots.forEach(function(sl){
      var e = byEl.get(sl.el);
      if (!e) { e = {el: sl.el, slots: [], step: sl.step, cull: true, fixed: [], box: null, stale: false}; byEl.set(sl.el, e); elems.push(e); }
      e.slots.push(sl);
      sl.roles = rolesOf(sl.attr, sl.parts);
      if (!sl.roles) e.cull = false;
    });
    byEl.forEach(function(e, el){
      var names = FIXED[el.tagName];
      // a mark under a transform of its own (other than its step's) is drawn in other coordinates: always drawn
      if (!names || el.hasAttribute("transform") || (el.parentNode && el.parentNode.closest && el.parentNode.closest("[transform]"))) { e.cull = false; return; }
      names.forEach(function(a){
        if (e.slots.some(function(sl){ return sl.attr === a; })) return;
        if (a === "d") { e.cull = false; return; }  // (a path's d is one slot or none)
        var v = +el.getAttribute(a);
        if (isNaN(v)) e.cull = false; else e.fixed.push(a === "r" ? 3 : a.charAt(0) === "x" || a === "cx" ? 1 : 2, v);
      });
    });
  }
  function numAt(sl, i){  // the i-th number of a slot at the shown value, as written (to the hundredth)
    var c = sl.cs[i], v = sl.fl[i] ? (cur.t < 0.5 ? D[cur.r0 + c] : D[cur.r1 + c]) : D[cur.r0 + c] + (D[cur.r1 + c] - D[cur.r0 + c]) * cur.t;
    return Math.round(v * 100) / 100;
  }
  function boxNow(e){  // the mark's box at the shown value (its arcs' and circles' radii round its points)
    var x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity, r = 0, j, v, role;
    function add(role, v){
      if (role === 1) { if (v < x0) x0 = v; if (v > x1) x1 = v; }
      else if (role === 2) { if (v < y0) y0 = v; if (v > y1) y1 = v; }
      else if (role === 3 && Math.abs(v) > r) r = Math.abs(v);
    }
    for (j = 0; j < e.fixed.length; j += 2) add(e.fixed[j], e.fixed[j + 1]);
    for (var s = 0; s < e.slots.length; s++) {
      var sl = e.slots[s];
      for (j = 0; j < sl.roles.length; j++) if ((role = sl.roles[j])) add(role, numAt(sl, j));
    }
    return [x0 - 2 * r, y0 - 2 * r, x1 + 2 * r, y1 + 2 * r];
  }
  function meets(b, w, m){ return !!b && b[0] <= w[2] + m && b[2] >= w[0] - m && b[1] <= w[3] + m && b[3] >= w[1] - m; }
  function visible(r){  // the figure's coordinates the window shows (the view fitted into it, centred) and px
    var vb = svg.viewBox && svg.viewBox.baseVal;
    if (!r || !r.width || !r.height || !vb || !vb.width || !vb.height) return null;
    var s = Math.min(r.width / vb.width, r.height / vb.height), hw = r.width / s / 2, hh = r.height / s / 2;
    var cx = vb.x + vb.width / 2, cy = vb.y + vb.height / 2;
    return [cx - hw, cy - hh, cx + hw, cy + hh, 1 / s];
  }
  function drawElem(e, w){  // a mark at the shown value: all of it, or (w: the window while dragging) if seen
    // (outside the window first: that is arithmetic, while whether it is displayed may ask the browser)
    var b = e.cull ? boxNow(e) : null;
    if (w && e.cull && !meets(b, w, MARGIN_PX * w[4]) && !meets(e.box, w, MARGIN_PX * w[4])) { e.stale = stale = true; return; }
    if (w && hidden(e.el)) { e.stale = stale = true; return; }
    if (e.cull) e.box = b;
    for (var s = 0; s < e.slots.length; s++) write(e.slots[s]);
    e.stale = false;
  }
  function lengthOf(el, attr, parts){  // the SVG length an attribute of one bare number is (cx, cy, r, x1, …)
    var a = parts.length === 2 && !parts[0] && !parts[1] && el !== svg && el[attr];
    return a && a.baseVal && typeof a.baseVal.value === "number" && a.baseVal.unitType === 1 ? a.baseVal : null;
  }
  function coords(e){  // a letter's x, y or a leader line's ends, as built; or its label group's translate
    var out = {}, g = e.parentNode, m = g && g.classList && g.classList.contains("lbg") &&
      /^translate\(([-0-9.e]+)[ ,]+([-0-9.e]+)\)$/.exec(g.getAttribute("transform") || "");
    if (m) {
      var list = g.transform && g.transform.baseVal, one = list && list.numberOfItems === 1 ? list.getItem(0) : null;
      return {translate: [+m[1], +m[2]], g: g, shift: one && one.type === 2 ? one : null};  // 2: SVG_TRANSFORM_TRANSLATE
    }
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
    if (L.jumps.indexOf(lo) >= 0) t = t < 0.5 ? 0 : 1;
    return [lo, t];
  }
  function view(atOnce, drag){  // what the player's show(k) does with the view, without touching the steps (cheap)
    var d = player.data, k = +(svg.getAttribute("data-step") || d.n), st = k > 0 ? d.steps[k - 1] : null;
    if (st && st[IDX] >= 0 && cur && zoomAt[k - 1] !== undefined) {
      for (var i = 0; i < 4; i++) d[LIST][st[IDX]][i] = Math.round(valueAt(zoomAt[k - 1] + i) * 100) / 100;
    }
    var rp = ringAt[k - 1];
    if (st && st.r && rp && rp.p.s) {  // the ring (the array the player rings with) stays on its point
      st.r[0] = Math.round((rp.x + now(rp.p.s.cx) - rp.p.x) * 100) / 100;
      st.r[1] = Math.round((rp.y + now(rp.p.s.cy) - rp.p.y) * 100) / 100;
    }
    // the player moves its view there itself: at once while the given is dragged, smoothly to a new step
    if (player.jump && atOnce) { player.jump(!!drag); return; }
    if (player.move) { player.move(); return; }
    var zoom = document.getElementById("zoom");
    var box = st && zoom && zoom.checked && k < d.n && st.z >= 0 ? d.zooms[st.z] : null;
    svg.setAttribute("viewBox", (box || player.full).join(" "));
    svg.style.setProperty("--z", box ? (player.full[2] / box[2]).toFixed(3) : "1");
  }
  function now(sl){  // a one-number mark's value at the shown value (written or not yet)
    var c = sl.cs[0];
    return D[cur.r0 + c] + (D[cur.r1 + c] - D[cur.r0 + c]) * cur.t;
  }
  function valueAt(c){  // column c (of the keys) at the shown value
    var uc = colmap[c];
    return isFlag[c] ? (cur.t < 0.5 ? D[cur.r0 + uc] : D[cur.r1 + uc]) : D[cur.r0 + uc] + (D[cur.r1 + uc] - D[cur.r0 + uc]) * cur.t;
  }
  function write(sl){  // one mark's attribute at the shown value; written only when it changes
    var parts = sl.parts, cs = sl.cs, r0 = cur.r0, r1 = cur.r1, t = cur.t, v;
    if (sl.len) {  // one length (a point's centre, a line's end): its number, set without text to parse
      var c0 = cs[0];
      v = sl.fl[0] ? (t < 0.5 ? D[r0 + c0] : D[r1 + c0]) : D[r0 + c0] + (D[r1 + c0] - D[r0 + c0]) * t;
      v = Math.round(v * 100) / 100;
      if (v !== sl.v[0]) { sl.v[0] = v; sl.len.value = v; }
      return;
    }
    var txt = parts[0];
    for (var i = 1; i < parts.length; i++) {
      var c = cs[i - 1];
      v = sl.fl[i - 1] ? (t < 0.5 ? D[r0 + c] : D[r1 + c]) : D[r0 + c] + (D[r1 + c] - D[r0 + c]) * t;
      v = Math.round(v * 100) / 100;
      sl.v[i - 1] = v;
      txt += v + parts[i];
    }
    if (txt !== sl.text) { sl.text = txt; if (sl.el) sl.el.setAttribute(sl.attr, txt); }
  }
  function follow(fo, w){  // a letter or leader line with its point (w: the window while dragging: if seen)
    var p = fo.p, dx = (p.s.cx ? numAt(p.s.cx, 0) : p.x) - p.x, dy = (p.s.cy ? numAt(p.s.cy, 0) : p.y) - p.y;
    var b = [p.x + dx, p.y + dy, p.x + dx, p.y + dy];  // its point moved by as much as the letter (LABEL_PX about it)
    if (w && !meets(b, w, LABEL_PX * w[4]) && !meets(fo.box, w, LABEL_PX * w[4])) { fo.stale = stale = true; return; }
    if (w && hidden(fo.at.g || fo.el)) { fo.stale = stale = true; return; }  // (a group: its own display)
    fo.box = b;
    fo.stale = false;
    // moved by their own coordinates (a transform attribute would lose to the camera's CSS scale)
    if (fo.at.g) {  // the camera's label group: its anchor moves (the letters scale about it)
      var gx = Math.round((fo.at.translate[0] + dx) * 100) / 100, gy = Math.round((fo.at.translate[1] + dy) * 100) / 100;
      if (gx !== fo.text.x || gy !== fo.text.y) {
        fo.text.x = gx; fo.text.y = gy;
        // the group's one translate, set as numbers (no transform text to parse)
        if (fo.at.shift) fo.at.shift.setTranslate(gx, gy); else fo.at.g.setAttribute("transform", "translate(" + gx + " " + gy + ")");
      }
      return;
    }
    for (var a in fo.at) {
      var v = Math.round((fo.at[a] + (a.charAt(0) === "x" ? dx : dy)) * 100) / 100;
      if (v !== fo.text[a]) { fo.text[a] = v; if (fo.len[a]) fo.len[a].value = v; else fo.el.setAttribute(a, String(v)); }
    }
  }
  function catchUp(k, w){  // the marks of the steps up to k at the shown value (later steps are hidden): those
    // not drawn yet, and those a drag left (w: the window while dragging, only the marks seen in it)
    if (!cur || (k <= doneTo && !stale && !w)) return;
    var was = stale;
    stale = false;
    for (var s = 0; s < elems.length; s++) {
      var e = elems[s];
      if (e.step <= k && (w || e.step > doneTo || (was && e.stale))) drawElem(e, w);
      else if (e.stale) stale = true;  // left by a drag in a step now hidden: drawn when it is shown
    }
    for (var f = 0; f < followers.length; f++) {
      var fo = followers[f];
      if (fo.step <= k && (w || fo.step > doneTo || (was && fo.stale))) follow(fo, w);
      else if (fo.stale) stale = true;
    }
    doneTo = Math.max(doneTo, k);
  }
  function redraw(value, dragging, glide){  // glide: the camera to the step's view smoothly (let go)
    var t0 = performance.now(), shape = dragging && player ? svg.getBoundingClientRect() : null;  // read before any write
    var u = Math.log10(value), ct = cell(u), t = ct[1];
    cur = {r0: ct[0] * U, r1: Math.min(ct[0] + 1, rows - 1) * U, t: t};
    if (fullSlot) {  // the whole figure's box (the view when not magnified)
      var was = fullSlot.text;
      write(fullSlot);
      if (fullSlot.text !== was) {
        svg.setAttribute("data-full", fullSlot.text);
        if (player) for (var q = 0; q < 4; q++) player.full[q] = fullSlot.v[q];
        if (!player && !svg.classList.contains("zoomed")) svg.setAttribute("viewBox", fullSlot.text);
      }
    }
    // the view first (the player reads the figure's size there: nothing written yet, no layout forced)
    if (player) view(!glide, dragging);
    var k = player ? +(svg.getAttribute("data-step") || player.data.n) : Infinity;
    doneTo = -1;
    // the broken axis's marks belong to the built value's break; elsewhere the break lies elsewhere or nowhere
    var furniture = document.getElementById("furniture"), shown = Math.abs(u - Math.log10(L.initial)) < 1e-9 ? "" : "none";
    if (furniture && furniture.style.display !== shown) furniture.style.display = shown;
    for (var j = 0; j < readings.length; j++) if (readings[j].style.display !== shown) { readings[j].style.display = shown; visKey = null; }
    if (shape) shownNow();
    catchUp(k, shape ? visible(shape) : null);
    ownBox = svg.getAttribute("viewBox");
    api.value = value;
    var said = book(value);
    if (out.textContent !== said) { setText(out, said); retitle(value); }
    showChecks(u);
    api.lastMs = performance.now() - t0;
  }
  // the page's title and givens name the built value: they name the shown one
  var titled = [], NUM = "[0-9]+(?:[.,][0-9]+)?";
  // the rod as the texts write it: L/r = 5, or r/L = 1/5 (Anhang II, Baumann), r/l = 1/5 (§ 146)
  var forms = L.given === "rod_ratio" ? [["L/r = ", ""], ["r/L = 1/", ""], ["r/l = 1/", ""]] : [[L.symbol + " = ", ""]];
  forms.forEach(function(f){ f[1] = new RegExp(f[0].replace(/[.*+?^${}()|[\]\\/]/g, "\\$&") + NUM, "g"); });
  document.querySelectorAll("header h1, header h1 *").forEach(function(e){
    e.childNodes.forEach(function(t){
      if (t.nodeType === 3 && forms.some(function(f){ f[1].lastIndex = 0; return f[1].test(t.nodeValue); }))
        titled.push({n: t, text: t.nodeValue, en: !!(t.parentNode.closest && t.parentNode.closest(".en"))});
    });
  });
  // the givens table names the rod as the book does: L/r = 5, or r/L = 1/5 (r/l in § 146)
  var givenCell = null, inverse = false;
  document.querySelectorAll("#givens th").forEach(function(th){
    var t = th.textContent.trim();
    if (t === L.given || t === L.symbol) givenCell = th.nextElementSibling;
    else if (L.given === "rod_ratio" && (t === "r/L" || t === "r/l")) { givenCell = th.nextElementSibling; inverse = true; }
  });
  function retitle(value){
    titled.forEach(function(t){
      var shown = t.en ? String(Number(value.toPrecision(4))) : book(value), text = t.text;
      forms.forEach(function(f){ text = text.replace(f[1], f[0] + shown); });
      t.n.nodeValue = text;
    });
    if (givenCell) setText(givenCell, (inverse ? "1/" : "") + book(value));
  }
  var body = document.querySelector("#live-checks tbody"), shownAt = -1, cells = [];
  L.checks = L.checks || [];
  function put(td, text, cls){  // a cell's text (and class) written only when it changes: no row is rebuilt
    setText(td, text);
    if (cls !== undefined && td.className !== cls) td.className = cls;
  }
  function showChecks(u){
    if (!L.checks || !L.checks.length) return;
    var k = 0, bd = Infinity;  // the nearest value the checks were swept at, in log10
    L.check_values.forEach(function(v, i){ var d = Math.abs(Math.log10(v) - u); if (d < bd) { bd = d; k = i; } });
    if (k === shownAt) return;
    shownAt = k;
    put(document.getElementById("live-at"), "(" + L.symbol + " = " + book(L.check_values[k]) + ")");
    var rows = L.checks[k];
    // the rows are made once (a rebuilt table is laid out anew, at the cost of a frame); their cells change
    while (cells.length > rows.length) body.removeChild(cells.pop()[0].parentNode);
    while (cells.length < rows.length) {
      var tr = document.createElement("tr"), row = [];
      for (var j = 0; j < 5; j++) row.push(tr.appendChild(document.createElement("td")));
      body.appendChild(tr);
      cells.push(row);
    }
    rows.forEach(function(c, i){
      // [formula, error, ok, constructed value where formula + error does not give it] (live.py _check_table)
      var td = cells[i], num = function(x){ return x === null ? "–" : x.toPrecision(8); };
      var made = c.length > 3 ? c[3] : (c[0] === null || c[1] === null ? null : c[0] + c[1]);
      put(td[0], L.check_names[i]); put(td[1], num(made)); put(td[2], num(c[0]));
      put(td[3], c[1] === null ? "–" : c[1].toExponential(1)); put(td[4], c[2] ? "✓" : "✗", c[2] ? "ok" : "bad");
    });
  }
  api.ready = inflate(L.meta_z).then(function(b){
    var m = JSON.parse(new TextDecoder().decode(b));
    L.grid = m.grid; L.keys = m.keys; L.flags = m.flags; L.jumps = m.jumps;
    return L.checks_z ? inflate(L.checks_z) : null;
  }).then(function(b){
    if (b) { var c = JSON.parse(new TextDecoder().decode(b)); L.check_names = c.check_names; L.check_values = c.check_values; L.checks = c.checks; }
    return inflate(L.data);
  }).then(function(buf){
    prepare(buf);
    // the groups the step hides leave the document (a new letter scale restyles them all the same)
    if (player && player.lean) player.lean();
    // a drag sends more input events than frames: the last value of each frame is drawn, once, just before it
    var pending = false;
    input.addEventListener("input", function(){
      if (pending) return;
      pending = true;
      requestAnimationFrame(function(){ pending = false; redraw(Math.pow(10, +input.value), true); });
    });
    // let go (or a key's step): the letters at their exact scale, the camera gliding to the step's view
    input.addEventListener("change", function(){
      requestAnimationFrame(function(){ redraw(Math.pow(10, +input.value), false, true); });
    });
    // a new step: its marks and its view at the shown value (the player has just set the built view)
    var seenStep = svg.getAttribute("data-step");
    if (player) new MutationObserver(function(){
      var now = svg.getAttribute("data-step");
      if (now !== seenStep) { seenStep = now; if (cur) { catchUp(+now); view(); } }
      // a view the drag did not draw (the camera gliding to a step, the magnifier): the marks the drag left
      else if (stale && svg.getAttribute("viewBox") !== ownBox) catchUp(+now);
    }).observe(svg, {attributes: true, attributeFilter: ["data-step", "viewBox"]});
    window.addEventListener("resize", function(){ if (stale) catchUp(+(svg.getAttribute("data-step") || Infinity)); });
    showChecks(Math.log10(L.initial));
  });
  api.set = function(value, dragging){  // dragging: drawn as a drag draws it (the player's DRAG_LARGER)
    value = Math.min(L.high, Math.max(L.low, value));
    input.value = Math.log10(value);
    redraw(value, !!dragging);
    return api.lastMs;
  };
})();
"""
