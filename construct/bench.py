"""The speed benchmark: build and replay the crank construction at 18, 360 and 3600 parts.

Targets (issue "The construction kernel and the crank circle"): replaying the
18-part construction with new givens in at most 1 ms, and time per step flat
(within 2x) from 18 to 3600 parts.  Run it with ``construct bench``; it prints
what it measures, including when a target is missed.
"""

from __future__ import annotations

import time
from typing import Any

from .constructions import get

__all__ = ["run_bench", "CASES"]

CASES = (18, 360, 3600)


def _best(fn, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def run_bench(cases=CASES, rod_ratio: float = 5.0) -> list[dict[str, Any]]:
    crank = get("crank")
    results = []
    for n in cases:
        repeat = 60 if n <= 18 else 5 if n <= 360 else 2
        fig = crank.figure(parts=n, rod_ratio=rod_ratio)
        build = _best(lambda: crank.figure(parts=n, rod_ratio=rod_ratio), max(1, repeat // 4))
        proto = fig.protocol
        proto.replay(dict(fig.replay.givens))  # compile once, as any replayer would
        new = {"r": 1.0, "rod_ratio": rod_ratio + 0.5}
        replay = _best(lambda: proto.replay(new), repeat)
        results.append({
            "case": f"crank n={n} ({fig.params['method']})",
            "parts": n,
            "steps": len(proto.steps),
            "build_s": build,
            "replay_s": replay,
            "replay_per_step_us": replay / len(proto.steps) * 1e6,
        })
    return results


def verdicts(results: list[dict[str, Any]]) -> list[str]:
    out = []
    first = results[0]
    ok = first["replay_s"] <= 1e-3
    out.append(f"target replay n=18 <= 1 ms: {first['replay_s'] * 1e3:.3f} ms -> {'met' if ok else 'MISSED'}")
    per = [r["replay_per_step_us"] for r in results]
    spread = max(per) / min(per)
    out.append(f"target time per step flat within 2x: {min(per):.2f}..{max(per):.2f} us/step "
               f"(x{spread:.2f}) -> {'met' if spread <= 2 else 'MISSED'}")
    return out
