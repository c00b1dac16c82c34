"""How long the live player takes to redraw when the given slider moves: ``construct bench --live``.

A teacher drags the rod-ratio slider across the whole domain; every position
must be drawn inside one animation frame (16 ms at 60 Hz).  The page is opened
in headless Chromium (Debian's ``chromium`` driven by Playwright, as the
browser tests drive it), the construction shown at a few steps (the whole
figure, its middle step, its first quarter), and at each step the slider is
set to 120 values evenly spread in log10 over the domain.  Each redraw is
timed from inside an animation-frame callback to a task queued behind the
frame, so the time counts the script *and* the style, layout and paint work
the frame then does on the page's main thread (``script_ms`` is the script
alone).  A timing depends on the machine: it is a figure reported here, never
a test.
"""

from __future__ import annotations

import statistics
from pathlib import Path
from typing import Any

__all__ = ["FRAME_MS", "POSITIONS", "run_live_bench", "live_verdicts"]

#: One frame at 60 Hz.
FRAME_MS = 1000 / 60
#: Slider positions per step.
POSITIONS = 120

_MEASURE = """async ([n, at]) => {
  const live = window.constructLive, p = window.constructPlayer;
  await live.ready;
  const input = document.querySelector('#live input[type="range"]');
  const lo = +input.min, hi = +input.max;
  if (p && at !== null) { document.getElementById("slider").value = at; document.getElementById("slider").oninput(); }
  await new Promise(r => requestAnimationFrame(() => setTimeout(r, 0)));
  const out = [];
  for (let i = 0; i < n; i++) {
    const v = Math.pow(10, lo + (hi - lo) * i / (n - 1));
    out.push(await new Promise(res => requestAnimationFrame(() => {
      const t0 = performance.now();
      live.set(v);
      const js = performance.now() - t0;
      setTimeout(() => res([performance.now() - t0, js]), 0);
    })));
  }
  return {n: p ? p.data.n : 0, times: out};
}"""


def _figures(times: list[float]) -> dict[str, float]:
    s = sorted(times)
    return {"median_ms": statistics.median(s), "p90_ms": s[int(0.9 * (len(s) - 1))], "max_ms": s[-1],
            "within_frame": sum(t <= FRAME_MS for t in s), "count": len(s)}


def run_live_bench(pages: list[Path], positions: int = POSITIONS) -> list[dict[str, Any]]:
    """Redraw times of each live player page in *pages*, at the whole figure, its middle and its first quarter."""
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
                for label, at in (("whole", None), ("middle", n // 2), ("quarter", n // 4)):
                    got = page.evaluate(_MEASURE, [positions, at])
                    frame = [t[0] for t in got["times"]]
                    script = [t[1] for t in got["times"]]
                    found.append({"page": str(path), "step": label if at is None else f"{label} ({at}/{n})",
                                  **_figures(frame), "script_median_ms": statistics.median(script),
                                  "script_max_ms": max(script),
                                  "script_within_frame": sum(t <= FRAME_MS for t in script)})
                page.close()
        finally:
            browser.close()
    return found


def live_verdicts(found: list[dict[str, Any]]) -> list[str]:
    """One line per page and step: inside a frame or not."""
    out = []
    for r in found:
        ok = r["within_frame"] == r["count"]
        out.append(f"{'ok' if ok else 'SLOW'}: {Path(r['page']).parent.parent.name or r['page']} at {r['step']}: "
                   f"{r['within_frame']}/{r['count']} frames within {FRAME_MS:.1f} ms (script alone: "
                   f"{r['script_within_frame']}/{r['count']})")
    return out
