"""The speed guard CI runs after the tests: the benchmark's ratio targets, failing 2x past them.

``construct bench --guard`` measures, in one run on whatever machine CI has,
the ratios the benchmarks hold, in CPU time of this process (absolute times
depend on the machine and its neighbours; a ratio of two timings taken
together hardly does):

- a sweep of the 18-part crank over 10,000 rod ratios against one replay
  (target :data:`~construct.regress.replaybench.SWEEP_RATIO`), with every op on
  arrays (an op run element by element fails the guard whatever the ratio);
- replay and build time per step of the crank by the dividers at 18, 360 and
  3600 parts: the largest over the smallest (target
  :data:`~construct.regress.replaybench.FLAT`);
- rendering (every output of ``construct replay``) per step against replaying
  per step, at 360 and 1440 parts by the dividers (target
  :data:`RENDER_RATIO`), and rendering per step at 1440 parts over 360
  (target :data:`~construct.regress.replaybench.FLAT`: time proportional to
  the steps).

A ratio up to its target is met; past it and up to :data:`MARGIN` times the
target it is printed as MISSED and the guard still passes (a noisy neighbour
can do that much); beyond that it FAILS: a regression like a sweep falling
back to element-by-element (x264 against x30) or rendering turning quadratic
is caught on the day it lands.  The absolute times are printed beside.
"""

from __future__ import annotations

import functools
import tempfile
import time
from pathlib import Path
from typing import Any

from .replaybench import FLAT, SWEEP_RATIO, best_time, sweep_bench

__all__ = ["MARGIN", "RENDER_RATIO", "run_guard", "guard_lines"]

#: How far past its target a ratio may be before the guard fails.
MARGIN = 2.0

#: Rendering a step against replaying it: the targets of issue 28 on the machine they were set on, 0.1 ms a
#: step to render and 0.5 ms to replay the 18-part crank's 365 steps (1.37 us a step): 73x.
RENDER_RATIO = 0.1e-3 / (0.5e-3 / 365)


def _crank(parts: int) -> tuple[Any, Any, float]:
    """The crank by the dividers in *parts*: (construction, figure, build time)."""
    from ..constructions import get

    crank = get("crank")
    t = time.process_time()
    fig = crank.figure(parts=parts, rod_ratio=5.0, method="dividers")
    return crank, fig, time.process_time() - t


def _replay_per_step(fig: Any, repeat: int) -> float:
    proto = fig.protocol
    givens = {"r": 1.0, "rod_ratio": 5.5}
    proto.replay(givens)  # compiled once, as any replayer does
    return best_time(lambda: proto.replay(givens), repeat) / len(proto.steps)


@functools.cache
def _rendered_once() -> None:
    """A three-part crank rendered once in this process: what the first rendering does once (importing the
    output modules, reading the fonts' metrics; a tenth of a second, a quarter of the 360-part crank's
    rendering) is then charged to no measured figure's steps."""
    from ..constructions import get
    from ..render.output import write_replay

    crank = get("crank")
    with tempfile.TemporaryDirectory(prefix="construct-guard-") as tmp:
        write_replay(crank, crank.figure(parts=3), Path(tmp) / "out")


def render_per_step(construction: Any, figure: Any) -> float:
    """Every output ``construct replay`` writes (final figure, protocol, animation, player, storyboard) for
    *figure*, written to a temporary folder: seconds per step (what a process renders once at its first
    figure left out: :func:`_rendered_once`), with the garbage collector as the command runs it
    (:func:`~construct.io.collector.few_collections`; at Python's default thresholds its passes over the
    figure's objects were a fifth of the time, which no command spends)."""
    from ..io.collector import few_collections
    from ..render.output import write_replay

    _rendered_once()
    with tempfile.TemporaryDirectory(prefix="construct-guard-") as tmp, few_collections():
        t = time.process_time()
        write_replay(construction, figure, Path(tmp) / "out")
        return (time.process_time() - t) / len(figure.protocol.steps)


def run_guard() -> list[dict[str, Any]]:
    """Measure the ratios; one dict per ratio: what, value, target, and the timings it was made of."""
    out: list[dict[str, Any]] = []
    s = sweep_bench()
    out.append({"what": f"sweep of {s['size']} rod ratios / one replay (18-part crank)", "ratio": s["sweep_over_scalar"],
                "target": SWEEP_RATIO, "elementwise": s["elementwise"],
                "times": f"sweep {s['sweep_s'] * 1e3:.1f} ms, replay {s['scalar_replay_s'] * 1e3:.3f} ms"})
    replay, build, figures = {}, {}, {}
    for parts in (18, 360, 3600):
        crank, fig, built = _crank(parts)
        steps = len(fig.protocol.steps)
        replay[parts] = _replay_per_step(fig, 40 if parts <= 18 else 5 if parts <= 360 else 2)
        build[parts] = built / steps
        figures[parts] = (crank, fig)
    for what, per in (("replay", replay), ("build", build)):
        out.append({"what": f"{what} time per step, largest / smallest (dividers, 18 .. 3600 parts)",
                    "ratio": max(per.values()) / min(per.values()), "target": FLAT,
                    "times": ", ".join(f"n={n}: {v * 1e6:.2f} us" for n, v in per.items())})
    crank, small = figures[360]
    _, big, _ = _crank(1440)
    render = {360: render_per_step(crank, small), 1440: render_per_step(crank, big)}
    replay[1440] = _replay_per_step(big, 3)
    for parts in (360, 1440):
        out.append({"what": f"rendering / replay per step (dividers, {parts} parts)",
                    "ratio": render[parts] / replay[parts], "target": RENDER_RATIO,
                    "times": f"rendering {render[parts] * 1e3:.3f} ms, replay {replay[parts] * 1e6:.2f} us a step"})
    out.append({"what": "rendering per step, 1440 parts / 360 (time proportional to the steps)",
                "ratio": render[1440] / render[360], "target": FLAT,
                "times": f"{render[360] * 1e3:.3f} and {render[1440] * 1e3:.3f} ms a step"})
    return out


def verdict(r: dict[str, Any]) -> str:
    """met, MISSED (past the target, within the margin) or FAILED."""
    if r.get("elementwise"):
        return "FAILED"
    if r["ratio"] <= r["target"]:
        return "met"
    return "MISSED" if r["ratio"] <= MARGIN * r["target"] else "FAILED"


def guard_lines(results: list[dict[str, Any]]) -> list[str]:
    lines = []
    for r in results:
        slow = f"; element by element: {', '.join(r['elementwise'])}" if r.get("elementwise") else ""
        lines.append(f"guard {r['what']}: x{r['ratio']:.2f} (target x{r['target']:.3g}, fails past "
                     f"x{MARGIN * r['target']:.3g}; {r['times']}{slow}) -> {verdict(r)}")
    return lines
