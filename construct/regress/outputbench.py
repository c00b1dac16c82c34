"""The output benchmark: what `construct replay`, `construct gallery` and `construct verify` cost.

Run with ``construct bench --outputs``.  Each case runs the real command in a
fresh interpreter (so start-up and imports count, as they do for a user) in a
temporary folder, and reports the wall time, the CPU time of the process
and its children (on a busy machine the wall time says more about the
neighbours than about us) and the bytes written.  Targets:

* ``replay crank --parts 1440 --frames none`` within 5x the time of ``--parts 360``
  (the output is linear in the steps; 1440 parts are 4x the steps);
* ``replay crank --parts 360`` with the default outputs within 3 s and 30 MB;
* rendering every output of ``replay crank --parts 3600 --method dividers``
  (timed in this process, the figure built beforehand) within 0.1 ms a step;
* ``construct gallery`` within 5 s, ``construct verify`` within 5 s (two cores).

Beside them, what the gallery's live players' data costs (:func:`live_costs`: the CPU time of
:func:`construct.live.live_pages` for each, in this process).

Nothing here is a test: the numbers depend on the machine.
"""

from __future__ import annotations

import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from ..constructions import get

__all__ = ["run_output_bench", "output_verdicts", "live_costs", "TARGETS"]

TARGETS = {"replay_360_s": 3.0, "replay_360_mb": 30.0, "linear_ratio": 5.0, "gallery_s": 5.0, "verify_s": 5.0,
           "gallery_mb": 25.0, "render_step_s": 0.1e-3}


def _size(path: Path) -> int:
    return sum(p.stat().st_size for p in path.rglob("*") if p.is_file())


def _run(args: list[str], cwd: Path) -> dict[str, Any]:
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "construct", *args], cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode not in (0, 1):
        raise RuntimeError(f"construct {' '.join(args)} exited {done.returncode}: {done.stderr.strip()}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"command": "construct " + " ".join(args), "wall_s": wall, "cpu_s": cpu, "exit": done.returncode}


def run_output_bench() -> list[dict[str, Any]]:
    """Run the cases; return one dict per command (wall_s, cpu_s, and bytes where it writes)."""
    out: list[dict[str, Any]] = []
    with tempfile.TemporaryDirectory(prefix="construct-bench-") as tmp:
        root = Path(tmp)
        for name, args in (("replay_360", ["replay", "crank", "--parts", "360", "--out", "r360"]),
                           ("replay_360_none", ["replay", "crank", "--parts", "360", "--frames", "none",
                                                "--out", "n360"]),
                           ("replay_1440_none", ["replay", "crank", "--parts", "1440", "--frames", "none",
                                                 "--out", "n1440"]),
                           ("gallery", ["gallery", "--out", "gallery"]),
                           ("verify", ["verify", "--gallery", "gallery"])):
            r = _run(args, root)
            r["case"] = name
            folder = {"replay_360": "r360", "replay_360_none": "n360", "replay_1440_none": "n1440",
                      "gallery": "gallery"}.get(name)
            if folder:
                r["bytes"] = _size(root / folder)
            out.append(r)
    out.append({"case": "live", "command": "the live players' data (live_pages, every gallery player)",
                "players": (costs := live_costs()), "wall_s": float("nan"), "cpu_s": sum(costs.values())})
    from .guard import render_per_step

    crank = get("crank")
    fig = crank.figure(parts=3600, method="dividers")
    t = time.process_time()
    per = render_per_step(crank, fig)
    out.append({"case": "render_3600", "command": "rendering of replay crank --parts 3600 --method dividers",
                "wall_s": per * len(fig.protocol.steps), "cpu_s": time.process_time() - t,
                "steps": len(fig.protocol.steps), "per_step_s": per})
    return out


def live_costs() -> dict[str, float]:
    """The CPU time (s) of each gallery live player's data (:func:`construct.live.live_pages`, the figure and
    its drawing made beforehand), by construction."""
    from ..gallery import LIVE_PLAYERS, gallery_plan
    from ..live import live_pages
    from ..render.output import scene_for
    from ..render.styles import STYLES
    from ..render.svg import Drawing

    style, out = STYLES["teaching"], {}
    for name, params in gallery_plan():
        if name in LIVE_PLAYERS and name not in out:
            c = get(name)
            fig = c.figure(**params)
            drawing = Drawing(scene_for(c, fig, ending=style.camera), style)
            t = time.process_time()
            live_pages(c, fig, style, drawing=drawing)
            out[name] = time.process_time() - t
    return out


def output_verdicts(results: list[dict[str, Any]]) -> list[str]:
    """One line per target: measured, target, met or MISSED."""
    by = {r["case"]: r for r in results}
    lines = []

    def verdict(ok: bool) -> str:
        return "met" if ok else "MISSED"

    r = by["replay_360"]
    mb = r["bytes"] / 1e6
    lines.append(f"target replay --parts 360 <= {TARGETS['replay_360_s']:g} s and <= {TARGETS['replay_360_mb']:g} MB: "
                 f"{r['wall_s']:.2f} s wall ({r['cpu_s']:.2f} s CPU), {mb:.1f} MB -> "
                 f"{verdict(r['wall_s'] <= TARGETS['replay_360_s'] and mb <= TARGETS['replay_360_mb'])}")
    a, b = by["replay_360_none"], by["replay_1440_none"]
    ratio, cpu_ratio = b["wall_s"] / a["wall_s"], b["cpu_s"] / max(a["cpu_s"], 1e-9)
    lines.append(f"target replay --parts 1440 --frames none within {TARGETS['linear_ratio']:g}x of --parts 360: "
                 f"{b['wall_s']:.2f} s / {a['wall_s']:.2f} s = x{ratio:.2f} wall (x{cpu_ratio:.2f} CPU) -> "
                 f"{verdict(ratio <= TARGETS['linear_ratio'])}")
    r = by["render_3600"]
    lines.append(f"target rendering <= {TARGETS['render_step_s'] * 1e3:g} ms a step (crank, 3600 parts by the dividers, "
                 f"every output, {r['steps']} steps): {r['per_step_s'] * 1e3:.3f} ms a step -> "
                 f"{verdict(r['per_step_s'] <= TARGETS['render_step_s'])}")
    g = by["gallery"]
    lines.append(f"target construct gallery <= {TARGETS['gallery_s']:g} s: {g['wall_s']:.2f} s wall "
                 f"({g['cpu_s']:.2f} s CPU in all processes) -> {verdict(g['wall_s'] <= TARGETS['gallery_s'])}")
    lines.append(f"target gallery <= {TARGETS['gallery_mb']:g} MB: {g['bytes'] / 1e6:.2f} MB -> "
                 f"{verdict(g['bytes'] / 1e6 <= TARGETS['gallery_mb'])}")
    v = by["verify"]
    lines.append(f"target construct verify <= {TARGETS['verify_s']:g} s: {v['wall_s']:.2f} s wall "
                 f"({v['cpu_s']:.2f} s CPU; exit {v['exit']}) -> {verdict(v['wall_s'] <= TARGETS['verify_s'])}")
    if "live" in by:
        costs = by["live"]["players"]
        lines.append(f"(the live players' data: {sum(costs.values()):.1f} s CPU: "
                     + ", ".join(f"{k} {v:.1f}" for k, v in sorted(costs.items(), key=lambda kv: -kv[1])) + ")")
    lines.append(f"(machine: {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f})")
    return lines
