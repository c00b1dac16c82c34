"""A self-contained HTML step player: one file, no network, no external script.

The page holds one SVG of the whole construction whose elements are grouped
by step (one ``<g class="step" data-step>`` per step and layer, the layered figure's own
groups); a small script shows steps
1..k by switching classes.  Controls: previous / next / play-pause buttons, a
slider, the arrow keys (Home/End, space to play), a tempo control (seconds per
step, keys + and -), a step list grouped by the
construction's groups in collapsible ``<details>``, the givens, and each
step's caption in German and English.  Every step is shown through its
camera view (:mod:`construct.render.camera`, the same views the layered
figure stores): the viewBox moves there smoothly, letters and points keep
their screen size and stay on their points, a ring marks a small current
mark; the "magnify" switch shows the whole figure instead.

All text from the protocol reaches the page escaped: in the markup through
:func:`html.escape`, in the embedded JSON with ``<``, ``>`` and ``&`` written
as ``\\u003c`` etc., and the script only ever assigns ``textContent``.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> fig = get("crank").figure(parts=6)
>>> page = player_html(build_scene(fig), givens={"r": 1.0})
>>> page.count("<script") == 2 and "http" not in page.replace("http://www.w3.org", "")
True
"""

from __future__ import annotations

import html
import json
import re
from typing import Any, Mapping, Sequence

from .animate import STEP_SECONDS, group_css
from .camera import DETAIL_PX, DETAIL_TIE_PX, INSET_MAX, PLAYER_FIGURE_PX, Framing, step_details, zoom_of
from .captions import group_caption
from .insets import CLUSTER_ABOVE, INSET_PX, inset_detail, points_at
from .marks import MarkKind
from .styles import PLAIN, Style
from .svg import Drawing
from .svgdoc import fmt

__all__ = ["player_html", "json_for_script", "inset_marks"]


def json_for_script(data: Any) -> str:
    """JSON safe inside a ``<script>`` element (no ``</script>``, no ``<!--``).

    >>> json_for_script({"c": "</script><b>&"})
    '{"c": "\\\\u003c/script\\\\u003e\\\\u003cb\\\\u003e\\\\u0026"}'
    """
    text = json.dumps(data, ensure_ascii=False, sort_keys=True)
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026") \
        .replace("\u2028", "\\u2028").replace("\u2029", "\\u2029")


def _step_tree(scene) -> tuple[list[str], list[list[int]], list[int]]:
    """The step list's groups as data, for the page's script to build the list from: (the groups' titles, each
    in English / German; the group paths, each a list of title numbers; per step the number of its path).

    The list is the players' largest part written out (a fourth of a long figure's page): built from these and
    each step's English caption (already in the data), it costs a few numbers a step.
    """
    titles = scene.params.get("group_titles") or {}
    labels: dict[str, int] = {}
    paths: dict[tuple[str, ...], int] = {}
    per_step = []
    for s in scene.steps:
        if s.group not in paths:
            for g in s.group:
                if g not in labels:
                    labels[g] = len(labels)
            paths[s.group] = len(paths)
        per_step.append(paths[s.group])
    order = sorted(labels, key=labels.__getitem__)
    # each language read in its own words (the lines a construction calls by name, its own way)
    text = [scene.readable(g, "en") if titles.get(g, g) == g
            else f"{scene.readable(g, 'en')} / {scene.readable(titles[g])}" for g in order]
    return text, [[labels[g] for g in path] for path in sorted(paths, key=paths.__getitem__)], per_step


def player_html(scene, style: Style = PLAIN, *, givens: Mapping[str, Any] | None = None,
                title: tuple[str, str] | None = None, drawing: Drawing | None = None) -> str:
    """The player page of *scene* (or of the already laid-out *drawing*: the same elements as the figure)."""
    d = drawing or Drawing(scene, style, caption_lines=0)
    scene, style = d.scene, d.style
    f = d.doc.factory
    n = len(scene.steps)
    w, h = fmt(d.vp.width), fmt(d.drawing_height)
    dwg = d.doc.drawing(size=(None, None), viewBox=f"0 0 {w} {h}", id="figure", role="img",
                        **{"data-full": f"0 0 {w} {h}"})
    dwg.add(f.style("\n" + style.css() + "\n" + group_css(style) + "\n" + (d.extra_css + "\n" if d.extra_css else "")))
    dwg.add(f.rect(insert=("-10000", "-10000"), size=("20000", "20000"), fill=style.background))
    for layer in d.LAYERS:
        if layer == "labels" and style.ring_px:
            # the ring round a small current mark, under the letters: a letter's halo opens it, never the
            # ring a letter
            dwg.add(f.circle(center=("0", "0"), r="0", class_="ring", id="ring", visibility="hidden"))
        lg = f.g(id=layer)
        for group in d.plain_groups(layer):
            lg.add(group)
        dwg.add(lg)
    furniture = d.furniture()  # the broken axis's marks (and a plate's furniture)
    if furniture is not None:
        dwg.add(furniture)
    # the steps whose finest detail a page that moves the points (a live given) judges anew, as a fresh build would
    # (:func:`_clustering`), an inset shown or not
    clustering = _clustering(d)
    insets = any(z is not None for z in d.insets) or any(clustering)
    if insets:  # where the inset magnifies (the player moves it)
        dwg.add(f.rect(insert=("0", "0"), size=("0", "0"), class_="insetbox", id="insetbox", visibility="hidden"))
    svg = d.doc.markup(dwg)
    # Group captions and camera views are shared by runs of steps: each is stored once, steps point to it.
    groups: dict[str, int] = {}
    views: dict[tuple, int] = {}
    steps = []
    points = {m.name: m for m in scene.marks if m.kind is MarkKind.POINT}
    at_point = None  # the points' ids by where they stand, for the insets' details (made at the first)
    for s in scene.steps:
        de, en = scene.caption(s.index)
        st = {"de": de, "en": en, "g": groups.setdefault(group_caption(scene, s.index), len(groups)),
              "v": views.setdefault(tuple(d.camera_view(s.index)), len(views))}
        ring = d.ring(s.index)
        if ring is not None:  # a ring round the current mark where it is small on the screen
            st["r"] = list(ring)
        inputs = sorted(d.input_steps(s.index))
        if inputs:  # the steps that made what this step's instrument is set on
            st["i"] = inputs
        inset = d.insets[s.index - 1]
        if inset is not None:  # a sliver or a cluster: its place magnified beside the view, its points lettered
            st["z"] = list(inset)
            if at_point is None:
                at_point = points_at(scene, d.vp.px)
            detail = inset_detail(scene, d.vp.px, d.vp.scale, s.index, inset, at_point=at_point)
            # (a cluster's: every point of the step, since the page finds its finest detail anew where the points
            # move -- among other points, at another value -- and draws those the box takes in)
            st["zp"] = _inset_points(d, s.index, None if detail is not None else inset, points)
            if detail is not None:  # a cluster's: the page finds its finest detail anew where the points move
                st["zd"] = detail
        elif clustering[s.index - 1]:  # none here: the page asks anew where the points move
            if at_point is None:
                at_point = points_at(scene, d.vp.px)
            detail = inset_detail(scene, d.vp.px, d.vp.scale, s.index, None, at_point=at_point)
            if detail is not None:
                st["zd"] = detail
                st["zp"] = _inset_points(d, s.index, None, points)
        steps.append(st)
    from .camera import ZOOM_LEVELS

    titles, paths, per_step = _step_tree(scene)
    for st, p in zip(steps, per_step):
        st["p"] = p  # its group path in the step list (the script builds the list)
    data = {"n": n, "steps": steps, "groups": list(groups), "views": [list(v) for v in views],
            "levels": list(ZOOM_LEVELS), "dt": round(1000 * STEP_SECONDS), "titles": titles, "paths": paths}
    if style.hatch:
        # an area's hatching as the style draws it (render/paths.py hatch_segments), which a live given draws anew:
        # its lines' spacing (canvas px) and each area's angle (a signed area's pieces turn with their sign: held)
        deg = {m.id: 45.0 if m.hatch is None else m.hatch for m in scene.marks
               if m.kind is MarkKind.AREA and "signed" not in m.look.split()}
        if deg:
            data["hatch"] = {"px": style.hatch_spacing, "deg": deg}
    if d.end is not None:
        data["end"] = 1  # the last step shows the end state (the figure's class fin)
        # its letter scale as laid out: the plate's lettering in it (the furniture's texts, set at that scale's size
        # in the figure's units) is scaled by the shown letter scale over it, as the end state's letters are
        data["els"] = d.end.letter
    title = title or scene.title
    giv = givens or {}
    givens_rows = "".join(f"<tr><th>{html.escape(str(k))}</th><td>{html.escape(_show(v))}</td></tr>"
                          for k, v in giv.items())  # in the caller's order (the book's, from notation.given_rows)
    values = dict((
        ("{{TITLE_DE}}", html.escape(title[0])),
        ("{{TITLE_EN}}", html.escape(title[1])),
        ("{{N}}", str(n)),
        ("{{STYLE}}", html.escape(style.name)),
        ("{{GIVENS}}", givens_rows),
        ("{{SVG}}", svg + ("\n" + _inset(d) if insets else "")),
        ("{{DATA}}", json_for_script(data)),
        ("{{PAGE_BG}}", "#f7f3ea" if style.name == "historical" else "#f4f5f7"),
        ("{{SPEEDS}}", _speed_options(data["dt"] / 1000)),
        ("{{ASPECT}}", "/".join(fmt(x) for x in PLAYER_FIGURE_PX)),
        ("{{DETAIL}}", " ".join(fmt(x) for x in (DETAIL_PX, INSET_MAX, *INSET_PX, CLUSTER_ABOVE, DETAIL_TIE_PX))),
    ))
    # One pass, so that text from the protocol is never read as a placeholder.
    return re.sub(r"\{\{[A-Z_]+\}\}", lambda m: values[m.group(0)], _TEMPLATE)


#: Seconds per step the player offers, slowest first (the keys + and - step through them).
SPEEDS = (4.0, 3.0, 2.0, 1.5, 1.0, 0.5, 0.25, 0.1)


#: A step shown without an inset whose finest detail needs this much of the magnification that makes it a cluster
#: (:func:`~construct.render.insets.step_insets`: :data:`~construct.render.insets.CLUSTER_ABOVE`) is judged anew
#: by the page as its points move (:func:`_clustering`): a live given that draws two points nearer (Baumann's T2 at
#: κ = 2, 4.4 times magnified, not 1.26 as at κ = 8) gives it an inset where a fresh build gives one.
CLUSTER_NEAR = 0.25


def _clustering(d: Drawing) -> list[bool]:
    """Per step of *d*, whether the page judges its finest detail anew (:data:`CLUSTER_NEAR`): a step of a group,
    shown without an inset, whose detail needs more than that share of the magnification that makes it a cluster."""
    if not d.style.camera:
        return [False] * len(d.scene.steps)
    details = step_details(d.scene, Framing(d.full_view), d.vp.px)
    return [z is None and bool(s.group) and need > CLUSTER_NEAR * CLUSTER_ABOVE * zoom_of(v, d.full_view)
            for s, z, v, (need, _) in zip(d.scene.steps, d.insets, d.views, details)]


def _speed_options(default: float) -> str:
    """The <option>s of the tempo control, *default* selected."""
    return "".join(f'<option value="{v:g}"{" selected" if v == default else ""}>{v:g} s</option>' for v in SPEEDS)


def inset_marks(d: Drawing, k: int, box: Sequence[float] | None,
                points: dict[str, Any] | None = None) -> list[tuple[Any, bool]]:
    """The point marks of step *k* and of what it works on (its inputs, the points its caption names) inside the
    inset *box* (canvas px: x y w h; None: wherever they stand) at the drawing's value, each with whether it is
    the step's own (*points*: the scene's point marks by name, if the caller has them)."""
    s = d.scene.steps[k - 1]
    if points is None:
        points = {m.name: m for m in d.scene.marks if m.kind is MarkKind.POINT}
    out = []
    for name in dict.fromkeys((*s.outputs, *s.inputs, *sorted(d.scene.named(k)))):
        m = points.get(name)
        if m is None or m.step > k:
            continue
        x, y = d.vp.px(*m.geom)
        if box is None or box[0] <= x <= box[0] + box[2] and box[1] <= y <= box[1] + box[3]:
            out.append((m, name in s.outputs))
    return out


def _inset_points(d: Drawing, k: int, box: Sequence[float] | None, points: dict[str, Any]) -> list[list]:
    """The points the inset *box* of step *k* draws and letters (:func:`inset_marks`): [the id of the point's
    circle, its letter(, 1 for the step's own)] (letter '' for a point the figure does not letter).  The page
    draws each where its circle stands -- at a live given's value, too.  The view beside it shows them a pixel
    or two apart; the inset, apart."""
    return [[m.id, m.label or (d.scene.display_name(m.name) if d.scene.tag_shown(m.name) else "")]
            + ([1] if own else []) for m, own in inset_marks(d, k, box, points)]


def _inset(d: Drawing) -> str:
    """The inset of a sliver or a cluster (:func:`construct.render.insets.step_insets`): the figure's lines and
    areas again, magnified (a ``<use>`` of each of the figure's layers, which show each step as the figure
    does), a dot where the step works, and the step's points with their letters (:func:`_inset_points`)."""
    f = d.doc.factory
    ins = d.doc.drawing(size=(None, None), viewBox="0 0 1 1", id="inset", role="img", **{"aria-label": "magnified"})
    for layer in ("areas", "construction", "results"):
        ins.add(f.use(href=f"#{layer}"))
    ins.add(f.circle(center=("0", "0"), r="0", id="inset-pt"))
    ins.add(f.g(id="inset-pts"))  # the step's points and their letters (the script draws them)
    return d.doc.markup(ins)


def _show(v: Any) -> str:
    if isinstance(v, float):
        return f"{v:g}"
    return str(v)


_TEMPLATE = """<!DOCTYPE html>
<html lang="de">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{{TITLE_EN}}</title>
<style>
body{margin:0;font:14px/1.4 'DejaVu Sans',Arial,sans-serif;background:{{PAGE_BG}};color:#222}
header{padding:10px 16px 4px}
h1{font-size:18px;margin:0}
h1 .en{display:block;font-size:14px;font-weight:normal;color:#555}
main{display:flex;gap:12px;padding:8px 16px;align-items:flex-start}
#stage{flex:1 1 auto;min-width:0;position:relative}
#inset{position:absolute;top:8px;right:8px;width:300px;height:210px;background:#fff;border:1px solid #888;display:none}
.insetbox{fill:none;stroke:#888;stroke-width:1px;stroke-dasharray:4 3;vector-effect:non-scaling-stroke}
#inset-pt{fill:#e8590c}
#inset .ipt{fill:#c2255c}
#inset .icur{fill:#e8590c}
#inset .ilb{fill:#c2255c;font-family:'DejaVu Sans',sans-serif;paint-order:stroke;stroke:#fff;stroke-width:.25em}
#figure{width:100%;height:auto;aspect-ratio:{{ASPECT}};max-height:70vh;border:1px solid #ccc;background:#fff;display:block}
#figure:where(:not(.fin)) .lbg>*,#figure .lbg:where(.pf)>*,#figure:where(:not(.fin)) .pt,#figure .pt:where(:not(.nf)){--ls:1;transform:scale(var(--ls))}
#figure .fo.end text:not([transform]),#figure .fo.end .sc{transform-box:fill-box;transform-origin:center}
#figure .fo.end text:not([transform])[style*="text-anchor:start"]{transform-origin:left center}
#figure .fo.end text:not([transform])[style*="text-anchor:end"]{transform-origin:right center}
#figure .fo.end text[transform],#figure .fo.end path.arrow{transform-box:view-box;transform-origin:0 0}
#controls{display:flex;gap:6px;align-items:center;margin:8px 0;flex-wrap:wrap}
#controls button{font:inherit;padding:3px 10px;min-width:2.4em}
#slider{flex:1 1 200px}
#counter{font-variant-numeric:tabular-nums;min-width:7em;text-align:right}
#caption{background:#fff;border:1px solid #ddd;padding:6px 10px;min-height:4.2em}
#cap-group{color:#777;font-size:12px}
#cap-de{font-weight:bold}
#cap-en{color:#444}
aside{flex:0 0 340px;max-height:88vh;overflow:auto;background:#fff;border:1px solid #ddd;padding:6px 8px}
aside h2{font-size:14px;margin:6px 0}
aside table{border-collapse:collapse;margin-bottom:8px}
aside th,aside td{text-align:left;padding:1px 8px 1px 0;font-weight:normal}
aside th{color:#666}
details{margin-left:6px}
summary{cursor:pointer;color:#333}
ul{margin:0;padding-left:14px;list-style:none}
li a{color:#333;text-decoration:none;display:block;font-size:12px}
li a .n{color:#999;font-variant-numeric:tabular-nums}
li a.done{color:#777}
li a.current{background:#ffe8d6;color:#000;font-weight:bold}
li a.later{color:#bbb}
</style>
</head>
<body>
<header>
<h1>{{TITLE_DE}}<span class="en">{{TITLE_EN}}</span></h1>
</header>
<main>
<div id="stage">
{{SVG}}
<div id="controls">
<button id="first" title="first step (Home)" aria-label="first">|◀</button>
<button id="prev" title="previous step (←)" aria-label="previous">◁</button>
<button id="play" title="play / pause (space)" aria-label="play">▶</button>
<button id="next" title="next step (→)" aria-label="next">▷</button>
<button id="last" title="last step (End)" aria-label="last">▶|</button>
<input id="slider" type="range" min="0" max="{{N}}" value="{{N}}" aria-label="step">
<span id="counter"></span>
<label title="seconds per step while playing (+ / - keys)">Tempo <select id="speed" aria-label="seconds per step">{{SPEEDS}}</select></label>
<label title="magnify tiny groups"><input id="zoom" type="checkbox" checked> Lupe / magnify</label>
</div>
<div id="caption"><div id="cap-group"></div><div id="cap-de"></div><div id="cap-en"></div></div>
</div>
<aside>
<h2>Gegeben / givens</h2>
<table id="givens">{{GIVENS}}</table>
<h2>Schritte / steps ({{N}})</h2>
<div id="steps"></div>
</aside>
</main>
<script type="application/json" id="data">{{DATA}}</script>
<script>
(function () {
  "use strict";
  var data = JSON.parse(document.getElementById("data").textContent);
  (function () {  // the step list: <details> by group path, each step a link with its number and English caption
    var root = document.getElementById("steps"), open = [], into = [root.appendChild(document.createElement("ul"))];
    data.steps.forEach(function (st, i) {
      var path = data.paths[st.p] || [], common = 0;
      while (common < Math.min(open.length, path.length) && open[common] === path[common]) { common++; }
      open.length = common; into.length = common + 1;
      for (var d = common; d < path.length; d++) {
        var det = document.createElement("details"), sum = document.createElement("summary"), ul = document.createElement("ul");
        sum.textContent = data.titles[path[d]];
        det.appendChild(sum); det.appendChild(ul); into[into.length - 1].appendChild(det);
        into.push(ul); open.push(path[d]);
      }
      var li = document.createElement("li"), a = document.createElement("a"), num = document.createElement("span");
      a.href = "#" + (i + 1); a.setAttribute("data-k", String(i + 1));
      num.className = "n"; num.textContent = String(i + 1);
      a.appendChild(num); a.appendChild(document.createTextNode(" " + st.en));
      li.appendChild(a); into[into.length - 1].appendChild(li);
    });
  })();
  var n = data.n, k = n, timer = null;
  var svg = document.getElementById("figure");
  var groups = Array.prototype.slice.call(svg.querySelectorAll("g[data-step]"));
  var links = Array.prototype.slice.call(document.querySelectorAll("#steps a[data-k]"));
  var slider = document.getElementById("slider");
  var zoom = document.getElementById("zoom");
  var full = svg.getAttribute("data-full").split(" ").map(Number);
  var now = svg.getAttribute("viewBox").split(" ").map(Number), anim = null, ringAt = null, level = 0;
  // the box the view is fitted into: the figure's content box (its border aside: with it, a view of the window's
  // shape would be fitted by the other side, and a view of exactly a zoom level's magnification fall below it)
  // (kept, not read from the element each time: a read in a drag's frame, after the given's slider moved, laid the
  // page out before anything was written, a layout of its own each frame; a ResizeObserver, called after the
  // frame's layout, keeps it, and a resize of the window reads it anew)
  var boxNow = null;
  function boxOf() { return boxNow || (boxNow = {width: svg.clientWidth, height: svg.clientHeight}); }
  if (window.ResizeObserver) { new ResizeObserver(function () { boxNow = null; boxOf(); }).observe(svg); }
  function ratio(v, r) {  // canvas pixels per screen pixel in view *v* (the view is fitted into the element)
    r = r || boxOf();
    if (!r.width || !r.height) { return 1; }
    return Math.max(v[2] / r.width, v[3] / r.height);
  }
  // the letter scale --ls is declared on the letters and points themselves (this rule), not inherited
  // from the figure: a new value then restyles those, not every element of the figure (a third of them)
  // (and of a live player, only those of the steps shown: see lean); and in the end state (.fin) only the letters
  // and points it shows -- the plate's own letters (.pf) and the points not left out (.nf) --: a changed rule
  // restyles every element its selector matches, hidden or not (at piston-force's end state 512, of which 64 are
  // shown: 4.5 ms of a drag's frame).  (:where keeps the selector's weight as it was: the rules that move a
  // letter, placing.py's, still outrank it)
  // (and the end state's plate lettering's rule, which a new letter scale scales too: data.els, see put)
  var lsRule = null, furRule = null;
  Array.prototype.forEach.call(document.styleSheets, function (sh) {
    Array.prototype.forEach.call(sh.cssRules, function (r) {
      if (!lsRule && r.style && r.style.getPropertyValue("--ls")) { lsRule = r; }
      if (!furRule && data.els && r.selectorText && r.selectorText.indexOf("#figure .fo.end text:not([transform])") === 0) { furRule = r; }
    });
  });
  // While a given is dragged (jump(true)), a new letter scale or zoom level is a frame of its own: it restyles
  // and lays out every letter and point shown.  So a drag keeps the shown scale while the letters stay between
  // 4 % smaller (a 9.5 px letter above 9 px) and 20 % larger than exact, and when it must change sets it near
  // the far side of that band from where the drag is heading (18 % larger, 3 % smaller), which lasts a change
  // of a quarter in the figure's size, not of 4 %; it keeps the shown zoom level while the magnification is
  // within a fifth of that level's range.  Letting go of the slider sets both exactly.
  var DRAG_SMALLER = 0.04, DRAG_LARGER = 0.2, DRAG_SET_SMALLER = 0.03, DRAG_SET_LARGER = 0.18, DRAG_LEVEL = 1.2;
  var dragFrom = null;  // the whole figure's canvas pixels per screen pixel at the last view shown
  // While a given is dragged a new view moves the figure by the transform of one group round it (the camera's),
  // the viewBox kept as the drag found it: a new viewBox lays the whole figure out anew (at piston-force's last
  // step the camera's move and the layout it forces took 1.6 ms, by a transform 0.4 ms).  Letting go (put without
  // *drag*) sets the viewBox and drops the transform.  view() is the view shown, ctm() the figure's map to the
  // screen (the camera group's, transform and all).
  var cam = null, camAt = null, camSet = "";
  function aim(box, r) {  // show the view *box* (its text) by the camera's transform in the viewBox camAt
    if (!cam) {  // (made at the first drag: every element of the figure but its style sheet, in their order)
      cam = document.createElementNS(svg.namespaceURI, "g");
      cam.setAttribute("id", "camera");
      Array.prototype.slice.call(svg.childNodes).forEach(function (c) { if (c.nodeName !== "style") { cam.appendChild(c); } });
      svg.appendChild(cam);
    }
    if (!camAt) { camAt = svg.getAttribute("viewBox").split(" ").map(Number); }
    // each view fitted into the box (centred, its scale the smaller of the two): a point x of view v is where the
    // viewBox camAt shows k x + t
    var v = box.split(" ").map(Number), b = camAt, s = 1 / ratio(v, r), sb = 1 / ratio(b, r), k = s / sb;
    var tx = b[0] + (sb * b[2] - s * v[2]) / 2 / sb - k * v[0], ty = b[1] + (sb * b[3] - s * v[3]) / 2 / sb - k * v[1];
    var m = "matrix(" + k.toFixed(6) + " 0 0 " + k.toFixed(6) + " " + tx.toFixed(3) + " " + ty.toFixed(3) + ")";
    if (m !== camSet) { camSet = m; cam.setAttribute("transform", m); }
  }
  function put(v, r, drag) {  // show view *v*: letters and points at their screen size (12 px, never below 9.5 px)
    // the letter scale of the view's zoom level (the letters were placed for it): the level's picture
    // magnified as a whole, letters never smaller on the screen than at the level's own zoom
    // (q times the view's magnification is the whole figure's canvas pixels per screen pixel)
    // (*r*: the figure's box on the screen, if read before anything was written: no layout forced here;
    // *drag*: a given is being dragged, see DRAG_LARGER)
    r = r || boxOf();
    var q = ratio(v, r), zl = data.levels[level] || 1, qf = ratio(full, r), ql = qf / zl;
    // written only when changed: a new --ls restyles every letter, a new viewBox repaints the figure
    var box = v.map(function (x) { return x.toFixed(2); }).join(" ");
    var exact = Math.min(Math.max(1, 9.5 * ql / 12), ql), ls = exact.toFixed(4), lsAt = lsRule ? lsRule.style : svg.style;
    if (drag && r.width && r.height) { aim(box, r); }
    else {
      if (camAt) { camAt = null; camSet = ""; cam.removeAttribute("transform"); }
      if (box !== svg.getAttribute("viewBox")) { svg.setAttribute("viewBox", box); }
    }
    var was = lsAt.getPropertyValue("--ls").trim();
    if (drag && was) {
      if (was >= exact * (1 - DRAG_SMALLER) && was <= exact * (1 + DRAG_LARGER)) { ls = was; }
      else {  // the scale grows with the whole figure's canvas pixels per screen pixel (a new level aside)
        var up = qf !== dragFrom ? qf > dragFrom : was < exact;
        ls = (exact * (up ? 1 + DRAG_SET_LARGER : 1 - DRAG_SET_SMALLER)).toFixed(4);
      }
    }
    dragFrom = qf;
    if (ls !== was) {
      lsAt.setProperty("--ls", ls);
      // the end state's plate lettering (and a scale's ticks, a dot: .sc) about its own middle, at the letters'
      // size; 1 where the end state was laid out.  Its turned texts and arrowheads about their anchors: pin
      if (furRule) { furScale = (ls / data.els).toFixed(4); furRule.style.setProperty("scale", furScale); pin(); }
    }
    var ring = document.getElementById("ring");
    if (ring) {  // (its attributes written only when they change: each write restyles and repaints it)
      attr(ring, "visibility", ringAt ? "visible" : "hidden");
      if (ringAt) { attr(ring, "cx", String(ringAt[0])); attr(ring, "cy", String(ringAt[1])); attr(ring, "r", Math.max(ringAt[2], 9 * q).toFixed(2)); }
    }
  }
  // The end state's turned texts (F/f along its dimension) and arrowheads are scaled with its upright lettering, but
  // about their anchor -- the turn's centre, the arrow's tip -- which the given moves: a transform origin there
  // would move the turn too (the attribute turns about its own centre, and an origin shifts the whole transform),
  // so each is scaled about the figure's origin and moved back by (1 - s) times its anchor (translate and scale
  // come before the attribute's turn).  Asked again when the live given writes them (constructLive: pin).
  var pinned = null, furScale = "1", TURN = /rotate[(] *[-0-9.e]+[ ,]+([-0-9.e]+)[ ,]+([-0-9.e]+)/, TIP = /^M *([-0-9.e]+)[ ,]+([-0-9.e]+)/;
  function pin() {
    if (!data.els) { return; }
    if (!pinned) { pinned = Array.prototype.slice.call(svg.querySelectorAll("#furniture .fo.end text[transform], #furniture .fo.end path.arrow")); }
    for (var i = 0; i < pinned.length; i++) {
      var e = pinned[i], m = e.tagName === "text" ? TURN.exec(e.getAttribute("transform")) : TIP.exec(e.getAttribute("d"));
      var key = m ? furScale + " " + m[1] + " " + m[2] : "";
      if (!m || e.pinned === key) { continue; }
      e.pinned = key;
      var s = +furScale;
      e.style.translate = ((1 - s) * m[1]).toFixed(3) + "px " + ((1 - s) * m[2]).toFixed(3) + "px";
      e.style.scale = furScale;
    }
  }
  function move(to) {  // the viewBox from where it is to *to* in a third of a second
    var from = now.slice(), t0 = null;
    if (anim) { cancelAnimationFrame(anim); anim = null; }
    if (!window.requestAnimationFrame || from.join(" ") === to.join(" ")) { now = to.slice(); put(now); return; }
    function frame(t) {
      if (t0 === null) { t0 = t; }
      var u = Math.min(1, (t - t0) / 350), e = u * u * (3 - 2 * u);
      now = from.map(function (a, i) { return a + (to[i] - a) * e; });
      put(now);
      anim = u < 1 ? requestAnimationFrame(frame) : null;
    }
    anim = requestAnimationFrame(frame);
  }
  window.addEventListener("resize", function () { boxNow = null; put(now); });
  function text(id, s) { document.getElementById(id).textContent = s; }
  function attr(e, name, v) { if (e.getAttribute(name) !== v) { e.setAttribute(name, v); } }
  function zoomLevel(view, r, drag) {  // the zoom level of *view*: its letters (placed for it) and their scale
    // how many times the window shows it larger than the whole figure (a view of the window's shape in a
    // tall figure is magnified more than its width says)
    r = r || boxOf();
    var z = ratio(full, r) / ratio(view, r), lvl = 0, L = data.levels;
    L.forEach(function (l, i) { if (z >= 0.999 * l) { lvl = i; } });
    // a drag keeps the shown level while near its range (see DRAG_LEVEL)
    if (drag && lvl !== level && level < L.length && z >= L[level] / DRAG_LEVEL
        && (level + 1 >= L.length || z < L[level + 1] * DRAG_LEVEL)) { lvl = level; }
    var cls = "zl" + lvl + (data.end && k === n ? " fin" : "");  // the last step: the end state
    // (the end state's hidden letters and points out of the document before the class changes: see ends)
    if (lean) { placeEnds(data.end && k === n); }
    if (svg.getAttribute("class") !== cls) { svg.setAttribute("class", cls); }
    level = lvl;
  }
  // Once a live given asks (lean()), the groups the step hides leave the document, a comment keeping each
  // one's place: Chromium restyles the matches of a changed rule or class inside display:none SVG groups too,
  // so a new letter scale or zoom level at the inertia curve's last step restyled 1,060 letters and points of
  // which 219 are shown (10 ms, not 4; a drag's frame has 16).  Which classes hide a group the stylesheet says
  // (asked of a probe group once).  find(id) finds an element of the figure, in the document or out of it.
  var lean = false, places = [], hides = {};
  function hiding(cls) {
    if (!(cls in hides)) {
      var probe = document.createElementNS("http://www.w3.org/2000/svg", "g");
      probe.setAttribute("class", cls);
      svg.appendChild(probe);
      hides[cls] = getComputedStyle(probe).display === "none";
      svg.removeChild(probe);
    }
    return hides[cls];
  }
  function place(i) {  // group i in the document if it is shown, out of it (its place kept) if not
    var g = groups[i], shown = !hiding(g.getAttribute("class") || "");
    if (shown && !g.isConnected) {
      places[i].replaceWith(g);
      // (a live given brings its marks to the shown value: it did not draw them while they were out)
      if (api && api.shown) { api.shown(g); }
    }
    else if (!shown && g.isConnected) { g.replaceWith(places[i]); }
  }
  // The end state (.fin) shows the plate's own letters (.pf) and the points it keeps and hides the steps' other
  // label groups (.fin .lbg) and points (.nf), but a new zoom level's class restyled each of their letters, leaders
  // and points all the same (at piston-force's end state a change restyled 627-661 elements, 63 of them shown: a
  // drag's worst frames; 163 with them out).  So, lean, the label groups and points the end state hides at every
  // zoom level leave the document in it too, a comment keeping each one's place, and come back when a step before
  // it is shown (the live given brings them to the shown value then: its reveal, as for the marks a class hides).
  // Which they are the stylesheet says (asked of probes once, at the first end state, at each zoom level, the
  // figure's own class set aside: a probe under it would take its level's rules too).
  var ends = null, endsOut = false;  // [label group or point, its place] each; whether they are out
  function endHidden() {
    if (ends) { return ends; }
    ends = [];
    if (!data.end) { return ends; }
    var all = [], kinds = {}, probes = [], NS = svg.namespaceURI, was = svg.getAttribute("class");
    groups.forEach(function (g) {
      Array.prototype.forEach.call(g.querySelectorAll("g.lbg, circle.pt"), function (e) {
        var key = e.tagName + " " + e.getAttribute("class");
        all.push([e, key]); kinds[key] = [e.tagName, e.getAttribute("class")];
      });
    });
    svg.removeAttribute("class");
    Object.keys(kinds).forEach(function (key) {
      data.levels.forEach(function (_, x) {
        var w = document.createElementNS(NS, "g"), s = document.createElementNS(NS, "g"), p = document.createElementNS(NS, kinds[key][0]);
        w.setAttribute("class", "zl" + x + " fin"); s.setAttribute("class", "step"); p.setAttribute("class", kinds[key][1]);
        s.appendChild(p); w.appendChild(s); svg.appendChild(w); probes.push([key, p, w]);
      });
    });
    var shown = {};  // (all read, then all removed: one restyle)
    probes.forEach(function (q) { if (getComputedStyle(q[1]).display !== "none") { shown[q[0]] = true; } });
    probes.forEach(function (q) { svg.removeChild(q[2]); });
    if (was !== null) { svg.setAttribute("class", was); }
    all.forEach(function (e) {
      if (!shown[e[1]]) { var at = document.createComment("end state: hidden"); at.held = e[0]; ends.push([e[0], at]); }
    });
    return ends;
  }
  function placeEnds(out) {  // the end state's hidden letters and points out of the document (*out*) or back in place
    out = !!out;
    if (out === endsOut) { return; }
    endsOut = out;
    endHidden().forEach(function (e) { if (out) { e[0].replaceWith(e[1]); } else { e[1].replaceWith(e[0]); } });
  }
  function find(id) {
    var e = document.getElementById(id), i;
    for (i = 0; !e && i < groups.length; i++) {
      if (!groups[i].isConnected) { e = groups[i].id === id ? groups[i] : groups[i].querySelector("#" + CSS.escape(id)); }
    }
    for (i = 0; !e && endsOut && i < ends.length; i++) { e = ends[i][0].id === id ? ends[i][0] : ends[i][0].querySelector("#" + CSS.escape(id)); }
    return e;
  }
  // every element of step group *g* in the figure's order, the letters and points out of the document in their places
  // (for a reader of the whole figure: the browser tests)
  function parts(g) {
    var out = [], w = document.createTreeWalker(g, NodeFilter.SHOW_ELEMENT | NodeFilter.SHOW_COMMENT), e;
    while ((e = w.nextNode())) {
      if (e.nodeType === 1) { out.push(e); }
      else if (e.held) { out.push(e.held); out.push.apply(out, e.held.querySelectorAll("*")); }
    }
    return out;
  }
  // the inset: a step's small work magnified beside the view (its box st.z, canvas px; a cluster's found about its
  // finest detail: detail), its points where their circles stand (a live given moves them, and a sliver's box:
  // render/live.py), lettered.  Not shown where it would magnify no more than the view *view* shows anyway (a
  // live given can grow a sliver's box so).
  var FIG = "{{ASPECT}}".split("/").map(Number), DETAIL = "{{DETAIL}}".split(" ").map(Number);
  // a cluster's box about its finest detail where the points stand now, in step view *v* of the whole *full*, or
  // null where a fresh build shows none (insets.step_insets and inset_detail: its detail, read as written to 0.1 px,
  // shown DETAIL[0] px large, more than DETAIL[4] times as magnified as the view magnifies the whole)
  function detail(st, v) {
    var zd = st.zd, cands = [], pts = [], span = [], i, j, fine = Infinity, at = null;
    function read(e) { return [Math.round(10 * e.getAttribute("cx")) / 10, Math.round(10 * e.getAttribute("cy")) / 10]; }
    zd[1].forEach(function (cr) {  // a circle or arc the step strikes: its radius
      var c = find(cr[0]), m = find(cr[1]), a = cr[2] && find(cr[2]), b = cr[3] && find(cr[3]);
      if (!c || !m) { return; }
      var r = m.tagName === "circle" ? +m.getAttribute("r") : +(m.getAttribute("d").match(/-?[0-9.]+(?:e[-+]?[0-9]+)?/g) || [])[2];
      cands.push([r, [+c.getAttribute("cx"), +c.getAttribute("cy")]]);
      if (a && b) { span.push(read(a).concat(read(b))); }  // (the compass's span: the radius, not a detail of its own)
    });
    zd[0].forEach(function (id) {  // the points, read to 0.1 px
      var e = find(id);
      if (e) { pts.push(read(e)); }
    });
    function spans(p, q) {
      return span.some(function (s) { return s[0] === p[0] && s[1] === p[1] && s[2] === q[0] && s[3] === q[1]
        || s[0] === q[0] && s[1] === q[1] && s[2] === p[0] && s[3] === p[1]; });
    }
    for (i = 0; i < pts.length; i++) {
      for (j = i + 1; j < pts.length; j++) {
        var d = Math.hypot(pts[i][0] - pts[j][0], pts[i][1] - pts[j][1]);
        if (d > 0 && !spans(pts[i], pts[j])) { cands.push([d, [(pts[i][0] + pts[j][0]) / 2, (pts[i][1] + pts[j][1]) / 2]]); }
      }
    }
    // (camera.finest_detail: the finest's size, the place of the first within DETAIL[5] px of it -- circles first,
    // then pairs in order)
    for (i = 0; i < cands.length; i++) { fine = Math.min(fine, cands[i][0]); }
    for (i = 0; i < cands.length && !at; i++) { if (cands[i][0] < fine + DETAIL[5]) { at = cands[i][1]; } }
    if (!at) { return null; }
    // (camera.step_details: the magnification its detail needs; camera.zoom_of: the view's)
    var need = Math.min(DETAIL[1], DETAIL[0] * Math.max(full[2], full[3] * FIG[0] / FIG[1]) / (fine * FIG[0]));
    var zv = Math.max(full[2] / FIG[0], full[3] / FIG[1]) / Math.max(v[2] / FIG[0], v[3] / FIG[1], 1e-12);
    if (!(need > 1 && need > DETAIL[4] * zv)) { return null; }
    // (the box as a fresh build sizes it in this view: in proportion to the detail where the inset magnifies it
    // past twice the view, whatever the view; twice the view where the detail needs less -- the built box in
    // proportion to the detail was 50-72 px off a fresh build's there, Tafel 2's step 105 at L/r = 4.37 and 5.55)
    var q = Math.min(FIG[0] / v[2], FIG[1] / v[3]) * Math.max(2, need / zv), r2 = function (x) { return Math.round(100 * x) / 100; };
    var w = DETAIL[2] / q, h = DETAIL[3] / q;
    return [r2(at[0] - w / 2), r2(at[1] - h / 2), r2(w), r2(h)];
  }
  function drawInset(view) {
    var inset = document.getElementById("inset"), ibox = document.getElementById("insetbox");
    if (!inset) { return; }
    var st = k > 0 ? data.steps[k - 1] : null, z = st && zoom.checked && k < n ? st.z : null;
    if (st && st.zd && zoom.checked && k < n) { z = detail(st, view); }
    if (z && Math.min(300 / z[2], 210 / z[3]) <= Math.min(FIG[0] / view[2], FIG[1] / view[3])) { z = null; }
    inset.style.display = z ? "block" : "none";
    ibox.setAttribute("visibility", z ? "visible" : "hidden");
    if (!z) { return; }
    inset.setAttribute("viewBox", z.join(" "));
    var dot = document.getElementById("inset-pt");  // the place the step works at, in the middle
    dot.setAttribute("cx", z[0] + z[2] / 2); dot.setAttribute("cy", z[1] + z[3] / 2);
    dot.setAttribute("r", st.zp && st.zp.length ? 0 : z[2] / 70);  // where no point of the step is drawn
    var pts = document.getElementById("inset-pts"), u = z[2] / 300;  // canvas px per inset px
    while (pts.firstChild) { pts.removeChild(pts.firstChild); }
    (st.zp || []).forEach(function (p, i) {
      var e = find(p[0]);
      if (!e) { return; }
      var x = +e.getAttribute("cx"), y = +e.getAttribute("cy");
      var c = document.createElementNS("http://www.w3.org/2000/svg", "circle");
      c.setAttribute("cx", x); c.setAttribute("cy", y); c.setAttribute("r", (p[2] ? 3.5 : 2.5) * u);
      c.setAttribute("class", p[2] ? "ipt icur" : "ipt");
      pts.appendChild(c);
      if (p[1]) {  // its letter beside it, above and below in turn where points crowd
        var t = document.createElementNS("http://www.w3.org/2000/svg", "text");
        t.setAttribute("x", x + 4 * u); t.setAttribute("y", y + (i % 2 ? 14 : -5) * u);
        t.setAttribute("font-size", 12 * u); t.setAttribute("class", "ilb");
        t.textContent = p[1];
        pts.appendChild(t);
      }
    });
    ibox.setAttribute("x", z[0]); ibox.setAttribute("y", z[1]);
    ibox.setAttribute("width", z[2]); ibox.setAttribute("height", z[3]);
  }
  function show(j) {
    var box = boxOf();  // read before the classes change (a read after them forces a restyle)
    dragWas = null; easing = true;  // (a new step's view is no motion of the given)
    k = Math.max(0, Math.min(n, j));
    groups.forEach(function (g, i) {
      var s = +g.getAttribute("data-step");
      // earlier steps: an input of step k, faded once their group is finished (data-fade), or old
      var fade = +(g.getAttribute("data-fade") || 0), inp = k > 0 && k < n ? (data.steps[k - 1].i || []) : [];
      g.setAttribute("class", "step" + (s > k ? " hid" : (s === k && k < n ? " cur" :
        (s < k && inp.indexOf(s) >= 0 ? " inp" : (fade && fade < k + (k === n ? 1 : 0) && s < k + (k === n ? 1 : 0) ? " done" :
        (k < n ? " old" : ""))))));
      if (lean) { place(i); }
    });
    links.forEach(function (a) {
      var s = +a.getAttribute("data-k");
      a.className = s < k ? "done" : (s === k ? "current" : "later");
    });
    slider.value = k;
    text("counter", "Schritt " + k + " / " + n);
    var st = k > 0 ? data.steps[k - 1] : null;
    text("cap-group", st ? data.groups[st.g] : "");
    text("cap-de", st ? "Schritt " + k + ": " + st.de : document.title);
    text("cap-en", st ? "Step " + k + ": " + st.en : "");
    // the camera: the step's view (the whole figure at the ends or without the magnifier), reached smoothly
    var view = target();
    zoomLevel(view, box);
    drawInset(view);
    ringAt = st && k < n ? (st.r || null) : null;
    move(view);
    var cur = links[k - 1];
    if (cur) {
      for (var p = cur.parentNode; p && p.id !== "steps"; p = p.parentNode) {
        if (p.tagName === "DETAILS") { p.open = true; }
      }
      // the list scrolls to the step, the page does not: scrollIntoView would move the window too, and the
      // figure with its title would jump under a teacher's pointer at every step
      var box = cur.closest ? cur.closest("aside") : null;
      if (box) {
        var r = cur.getBoundingClientRect(), b = box.getBoundingClientRect();
        if (r.top < b.top) { box.scrollTop += r.top - b.top; }
        else if (r.bottom > b.bottom) { box.scrollTop += r.bottom - b.bottom; }
      }
    }
    svg.setAttribute("data-step", String(k));
  }
  var speed = document.getElementById("speed");
  function seconds() { return +speed.value; }
  function tick() { if (k >= n) { pause(); } else { show(k + 1); timer = setTimeout(tick, seconds() * 1000); } }
  function pause() { if (timer) { clearTimeout(timer); timer = null; } text("play", "▶"); }
  function play() {
    if (timer) { pause(); return; }
    if (k >= n) { show(0); }
    text("play", "||");
    timer = setTimeout(tick, seconds() * 1000);
  }
  function repace() {  // a new pace takes effect at once
    if (timer) { clearTimeout(timer); timer = setTimeout(tick, seconds() * 1000); }
  }
  function faster(by) {
    speed.selectedIndex = Math.max(0, Math.min(speed.options.length - 1, speed.selectedIndex + by));
    repace();
  }
  speed.onchange = repace;
  document.getElementById("first").onclick = function () { pause(); show(0); };
  document.getElementById("prev").onclick = function () { pause(); show(k - 1); };
  document.getElementById("next").onclick = function () { pause(); show(k + 1); };
  document.getElementById("last").onclick = function () { pause(); show(n); };
  document.getElementById("play").onclick = play;
  slider.oninput = function () { pause(); show(+slider.value); };
  zoom.onchange = function () { show(k); };
  links.forEach(function (a) {
    a.onclick = function (e) { e.preventDefault(); pause(); show(+a.getAttribute("data-k")); };
  });
  document.addEventListener("keydown", function (e) {
    // a given's slider (the live player's) moves its given with the keys, natively: they do not step too
    if (e.target && e.target.tagName === "INPUT" && e.target.type === "range" && e.target !== slider) { return; }
    // the keys the player takes are its own: Home and End would also scroll the page to its top and bottom
    if (["ArrowLeft", "ArrowRight", "Home", "End"].indexOf(e.key) >= 0) { e.preventDefault(); }
    if (e.key === "ArrowRight") { pause(); show(k + 1); }
    else if (e.key === "ArrowLeft") { pause(); show(k - 1); }
    else if (e.key === "Home") { pause(); show(0); }
    else if (e.key === "End") { pause(); show(n); }
    else if (e.key === " ") { e.preventDefault(); play(); }
    else if (e.key === "+") { faster(1); }
    else if (e.key === "-") { faster(-1); }
  });
  var start = parseInt((location.hash || "").slice(1), 10);
  show(isNaN(start) ? n : start);
  // live givens (construct/render/live.py) redraw the figure and its views in place, then show step k again
  // the live player's hook (construct.render.live): redraw the step, move the camera to the step's view
  // (move: to the step's view, smoothly; jump: there at once, as a given's slider is dragged)
  // the step's view (the whole figure at the ends and without the magnifier)
  function target() { var st = k > 0 ? data.steps[k - 1] : null; return st && zoom.checked ? data.views[st.v] : full; }
  // A drag keeps the shown view while the step's view lies inside it and fills more than two thirds of it; when
  // the step's view leaves it (or shrinks away in it) the camera takes the step's view with a tenth of its size
  // of room in each direction, once, and holds that: the room on the side the step's view moves to (its edges'
  // motion since the last frame), half of it on each side when it keeps still or shrinks.  So what the step
  // frames never leaves the window, and a camera that stays put shows the construction move, as a teacher
  // dragging a given expects; and a new view is dear: it moves every mark on the screen, to be laid out and
  // painted anew (a third of a drag's frame), and a view that leads the motion is taken half as often as one
  // centred on it.  Letting go glides to the step's exact view.
  // From the step's exact view (let go, a new step) a drag's camera eases out just enough to hold the step's view
  // (the box round both), as long as that is within the room a new view would take, rather than stepping out by
  // that room at the drag's first frame: a value that barely moves barely moves the camera (it stepped out by a
  // tenth of the view and glided back on the next let-go).
  var DRAG_ROOM = 0.05, dragWas = null, easing = true;  // (the step's view at the drag's last frame)
  function ahead(to, was) {  // the view a drag takes: *to* with room, on the side it moves to from *was*
    var v = [0, 0, to[2] * (1 + 2 * DRAG_ROOM), to[3] * (1 + 2 * DRAG_ROOM)];
    for (var a = 0; a < 2; a++) {
      // (each edge's motion outwards; a ten-thousandth of the size is none)
      var still = 1e-4 * to[a + 2], room = 2 * DRAG_ROOM * to[a + 2];
      var out0 = was && was[a] - to[a] > still ? was[a] - to[a] : 0;
      var out1 = was && to[a] + to[a + 2] - was[a] - was[a + 2] > still ? to[a] + to[a + 2] - was[a] - was[a + 2] : 0;
      var low = out0 + out1 > 0 ? room * out0 / (out0 + out1) : room / 2;
      v[a] = to[a] - low;
    }
    return v;
  }
  function holds(v, t) {  // does view *v* hold view *t* while a given is dragged?
    return t[0] >= v[0] && t[1] >= v[1] && t[0] + t[2] <= v[0] + v[2] && t[1] + t[3] <= v[1] + v[3]
      && Math.max(t[2] / v[2], t[3] / v[3]) >= 2 / 3;
  }
  var api = window.constructPlayer = {data: data, full: full, redraw: function () { show(k); }, shown: null,
    groups: function () { return groups.slice(); },  // the step groups, in the document or out of it (lean)
    parts: parts,  // a step group's elements, in the document or out of it (the end state's hidden ones: lean)
    move: function () { dragWas = null; easing = true; zoomLevel(target()); move(target()); },  // (the level a drag kept, made exact)
    find: find, lean: function () {
      if (lean) { return; }
      lean = true;
      groups.forEach(function (g, i) { places[i] = document.createComment("step " + g.getAttribute("data-step")); place(i); });
      placeEnds(data.end && k === n);
    },
    target: target, pin: pin,
    inset: function () { drawInset(target()); },  // (a live given moved the step's inset box: st.z)
    view: function () { return now.slice(); },
    ctm: function () { return (cam || svg).getScreenCTM(); },
    jump: function (drag) {  // *drag*: as a given's drag draws it (the view, the letters' scale and level kept near)
      if (anim) { cancelAnimationFrame(anim); anim = null; }
      // the figure's box read once, before the level's class is set (a read after it would restyle the figure twice)
      var r = boxOf(), to = target();
      if (!drag) { now = to.slice(); }
      // a new view while dragging: the step's view with a little room (it can move or grow by a tenth before the
      // next), not the step's view exactly (which it would leave at once)
      else if (!holds(now, to)) {
        var u = [Math.min(now[0], to[0]), Math.min(now[1], to[1])];
        u.push(Math.max(now[0] + now[2], to[0] + to[2]) - u[0], Math.max(now[1] + now[3], to[1] + to[3]) - u[1]);
        if (easing && u[2] <= to[2] * (1 + 2 * DRAG_ROOM) && u[3] <= to[3] * (1 + 2 * DRAG_ROOM)) { now = u; }
        else { now = ahead(to, dragWas); easing = false; }
      }
      dragWas = drag ? to.slice() : null;
      if (!drag) { easing = true; }
      zoomLevel(now, r, !!drag); put(now, r, !!drag); }};
})();
</script>
</body>
</html>
"""
