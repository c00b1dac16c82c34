"""How long the live player takes to redraw when the given slider moves: ``construct bench --live``.

A teacher drags the rod-ratio slider across the whole domain; every position
must be drawn inside one animation frame (16.7 ms at 60 Hz).  The page is opened
in headless Chromium (Debian's ``chromium`` driven by Playwright, as the
browser tests drive it), the construction shown at a few steps (the last step,
its middle step, its first quarter), and at each step the slider, taken to a
drag's low end first, is dragged through 120 values evenly spread in log10 up
to its high end (drawn as a drag draws them: ``constructLive.set(v, true)``):
across the whole domain, and between 3 and 8 (:data:`DRAGS`).  Each redraw is timed from inside
an animation-frame callback to a task queued behind the frame, so the time
counts the script *and* the style, layout, paint and commit work the frame
then does on the page's main thread (``script_ms`` is the script alone).

With ``breakdown`` the same drag is traced (Chromium's devtools timeline) and
the main thread's time per frame is split into script, style, layout,
pre-paint, paint and commit, with the elements restyled and the layout
objects laid out per frame; the raster work the frame then costs on Chromium's
worker threads (software raster: no GPU here) is given beside it, not counted
in the frame.  A timing depends on the machine and its load: it is a figure
reported here, never a test.
"""

from __future__ import annotations

import collections
import itertools
import json
import statistics
from pathlib import Path
from typing import Any

__all__ = ["FRAME_MS", "POSITIONS", "DRAGS", "PHASES", "run_live_bench", "live_verdicts", "trace_phases"]

#: One frame at 60 Hz.
FRAME_MS = 1000 / 60
#: Slider positions per step.
POSITIONS = 120
#: The drags timed at each step: across the whole domain (the most the letters and the camera change in a
#: frame: 6 % of L/r a frame), and a teacher's between 3 and 8 (both in 120 frames, two seconds).
DRAGS = {"domain": (None, None), "3 to 8": (3.0, 8.0)}
#: The main thread's phases of a frame: trace event names (self time) per phase.
PHASES = {
    "script": ("FunctionCall", "EvaluateScript", "v8.callFunction", "TimerFire", "FireAnimationFrame",
               "V8.GC_SCAVENGER", "MinorGC", "MajorGC"),
    "style": ("Document::recalcStyle", "UpdateLayoutTree", "Document::rebuildLayoutTree",
              "StyleEngine::scheduleInvalidationsForRuleSets", "ScheduleStyleRecalculation"),
    "layout": ("LocalFrameView::performLayout", "Layout", "InlineNode::ShapeTextIncludingFirstLine",
               "InlineNode::FindSvgTextChunks", "SvgTextLayoutAlgorithm::Layout", "InlineNode::SetTextWithOffset"),
    "prepaint": ("Blink.PrePaint.UpdateTime", "PrePaint", "Blink.CompositingInputs.UpdateTime"),
    "paint": ("Paint", "Blink.Paint.UpdateTime", "PaintArtifactCompositor::Update", "Layerize",
              "PaintController::commitNewDisplayItems"),
    "commit": ("ProxyMain::BeginMainFrame::commit", "Commit"),
}

_MEASURE = """async ([n, at, from, to]) => {
  const live = window.constructLive, p = window.constructPlayer;
  await live.ready;
  const input = document.querySelector('#live input[type="range"]');
  const clip = x => Math.min(+input.max, Math.max(+input.min, x));
  const lo = from === null ? +input.min : clip(Math.log10(from)), hi = to === null ? +input.max : clip(Math.log10(to));
  if (p && at !== null) { document.getElementById("slider").value = at; document.getElementById("slider").oninput(); }
  await new Promise(r => setTimeout(r, 500));  // the camera's glide to the step's view
  // the slider taken to the drag's low end and let go there (a drag starts where the slider is: the jump
  // from the built value, or from the last drag's end, is not a frame of the drag)
  live.set(Math.pow(10, lo));
  await new Promise(r => setTimeout(r, 500));
  await new Promise(r => requestAnimationFrame(() => setTimeout(r, 0)));
  performance.mark("live-drag-start");
  const out = [];
  for (let i = 1; i <= n; i++) {
    const v = Math.pow(10, lo + (hi - lo) * i / n);
    out.push(await new Promise(res => requestAnimationFrame(() => {
      const t0 = performance.now();
      live.set(v, true);
      const js = performance.now() - t0;
      setTimeout(() => res([performance.now() - t0, js]), 0);
    })));
  }
  performance.mark("live-drag-end");
  return {n: p ? p.data.n : 0, times: out};
}"""

_TRACE_CATEGORIES = ["devtools.timeline", "disabled-by-default-devtools.timeline", "blink.user_timing", "toplevel"]


def _percentile(s: list[float], p: float) -> float:
    return s[int(p * (len(s) - 1))]


def _figures(times: list[float]) -> dict[str, float]:
    s = sorted(times)
    return {"median_ms": statistics.median(s), "p90_ms": _percentile(s, 0.9), "p95_ms": _percentile(s, 0.95),
            "max_ms": s[-1], "within_frame": sum(t <= FRAME_MS for t in s), "count": len(s)}


def trace_phases(events: list[dict[str, Any]], frames: int) -> dict[str, float]:
    """Milliseconds per frame of each of :data:`PHASES` on the renderer's main thread between the drag's marks,
    the rest of its busy time as ``other``, the raster on the worker threads, and the work counts.

    Self times: an event's time less its children's (the trace nests them).

    >>> ev = [{"ph": "M", "name": "thread_name", "pid": 1, "tid": 2, "args": {"name": "CrRendererMain"}},
    ...       {"ph": "R", "name": "live-drag-start", "pid": 1, "tid": 2, "ts": 0},
    ...       {"ph": "X", "name": "RunTask", "pid": 1, "tid": 2, "ts": 10, "dur": 9000},
    ...       {"ph": "X", "name": "FunctionCall", "pid": 1, "tid": 2, "ts": 20, "dur": 3000},
    ...       {"ph": "X", "name": "UpdateLayoutTree", "pid": 1, "tid": 2, "ts": 4000, "dur": 4000,
    ...        "args": {"elementCount": 500}},
    ...       {"ph": "R", "name": "live-drag-end", "pid": 1, "tid": 2, "ts": 10000}]
    >>> t = trace_phases(ev, 1)
    >>> t["script_ms"], t["style_ms"], t["other_ms"], t["restyled"]
    (3.0, 4.0, 2.0, 500.0)
    """
    names = {(e["pid"], e["tid"]): e.get("args", {}).get("name") for e in events
             if e.get("ph") == "M" and e.get("name") == "thread_name"}
    main = {k for k, v in names.items() if v == "CrRendererMain"}
    marks = {e["name"]: e["ts"] for e in events if e.get("name") in ("live-drag-start", "live-drag-end")}
    t0, t1 = marks.get("live-drag-start", 0), marks.get("live-drag-end", float("inf"))
    inside = [e for e in events if e.get("ph") == "X" and "dur" in e and t0 <= e.get("ts", -1) <= t1]
    own: collections.Counter = collections.Counter()
    by_thread = collections.defaultdict(list)
    for e in inside:
        if (e["pid"], e["tid"]) in main:
            by_thread[(e["pid"], e["tid"])].append(e)
    busy = 0.0
    for evs in by_thread.values():
        evs.sort(key=lambda e: (e["ts"], -e["dur"]))
        stack: list[dict[str, Any]] = []
        for e in evs:
            while stack and stack[-1]["ts"] + stack[-1]["dur"] <= e["ts"]:
                stack.pop()
            if stack:
                own[stack[-1]["name"]] -= e["dur"]
            else:
                busy += e["dur"]
            own[e["name"]] += e["dur"]
            stack.append(e)
    out: dict[str, float] = {}
    for phase, evnames in PHASES.items():
        out[f"{phase}_ms"] = sum(own[n] for n in evnames) / 1000 / frames
    out["other_ms"] = busy / 1000 / frames - sum(out.values())
    out["raster_ms"] = sum(e["dur"] for e in inside if e["name"] == "RasterTask") / 1000 / frames
    out["restyled"] = sum((e.get("args") or {}).get("elementCount") or 0 for e in inside
                          if e["name"] == "UpdateLayoutTree") / frames
    out["laid_out"] = sum(((e.get("args") or {}).get("beginData") or {}).get("dirtyObjects") or 0 for e in inside
                          if e["name"] == "Layout") / frames
    return out


def run_live_bench(pages: list[Path], positions: int = POSITIONS, breakdown: bool = False) -> list[dict[str, Any]]:
    """Redraw times of each live player page in *pages*, at its last step, its middle and its first quarter.

    With *breakdown*, each drag is run once more under a trace (:func:`trace_phases`; the traced run is
    slower, and only its split is reported).
    """
    from playwright.sync_api import sync_playwright

    chromium = "/usr/bin/chromium"
    args = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking"]
    found = []
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=chromium, args=args)
        try:
            for path in pages:
                page = browser.new_page(viewport={"width": 1400, "height": 1000})
                page.goto(Path(path).resolve().as_uri())
                n = page.evaluate("window.constructPlayer ? window.constructPlayer.data.n : 0")
                for (label, at), (drag, (lo, hi)) in itertools.product(
                        (("last", None), ("middle", n // 2), ("quarter", n // 4)), DRAGS.items()):
                    got = page.evaluate(_MEASURE, [positions, at, lo, hi])
                    frame = [t[0] for t in got["times"]]
                    script = [t[1] for t in got["times"]]
                    row = {"page": str(path), "step": label if at is None else f"{label} ({at}/{n})", "drag": drag,
                           **_figures(frame), "script_median_ms": statistics.median(script),
                           "script_p95_ms": _percentile(sorted(script), 0.95), "script_max_ms": max(script),
                           "script_within_frame": sum(t <= FRAME_MS for t in script)}
                    if breakdown:
                        browser.start_tracing(page=page, categories=_TRACE_CATEGORIES)
                        page.evaluate(_MEASURE, [positions, at, lo, hi])
                        events = json.loads(browser.stop_tracing())["traceEvents"]
                        row["breakdown"] = trace_phases(events, positions)
                    found.append(row)
                page.close()
        finally:
            browser.close()
    return found


def page_name(page: str) -> str:
    """A player's name in the report: its figure's folder in a gallery (NAME/STYLE/player.html), else its path.

    >>> page_name("gallery/crank-parts-18-rod-ratio-5/teaching/player.html"), page_name("/tmp/crank/player.html")
    ('crank-parts-18-rod-ratio-5', '/tmp/crank/player.html')
    """
    from ..render.styles import STYLES

    p = Path(page)
    return p.parent.parent.name if p.name == "player.html" and p.parent.name in STYLES and p.parent.parent.name else str(p)


def live_verdicts(found: list[dict[str, Any]]) -> list[str]:
    """One line per page and step: inside a frame or not -- a teacher's drag is smooth when its median and its
    95th percentile frame fit in one frame (:data:`FRAME_MS`); how many frames did is printed beside.

    >>> live_verdicts([{"page": "p.html", "step": "last", "median_ms": 9.0, "p95_ms": 16.0, "max_ms": 21.0,
    ...                 "within_frame": 118, "count": 120, "script_within_frame": 120}])
    ['ok: p.html at last, drag domain: median 9.0 ms, p95 16.0 ms, max 21.0 ms; 118/120 frames within 16.7 ms (script alone: 120/120)']
    """
    out = []
    for r in found:
        ok = r["median_ms"] <= FRAME_MS and r["p95_ms"] <= FRAME_MS
        out.append(f"{'ok' if ok else 'SLOW'}: {page_name(r['page'])} at {r['step']}, drag {r.get('drag', 'domain')}: "
                   f"median {r['median_ms']:.1f} ms, p95 {r['p95_ms']:.1f} ms, max {r['max_ms']:.1f} ms; "
                   f"{r['within_frame']}/{r['count']} frames within {FRAME_MS:.1f} ms (script alone: "
                   f"{r['script_within_frame']}/{r['count']})")
    return out
