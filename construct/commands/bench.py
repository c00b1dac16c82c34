"""construct bench: how fast the crank construction builds and replays."""

from __future__ import annotations

import json

from ..bench import CASES, run_bench, verdicts

NAME = "bench"
HELP = "benchmark building and replaying the crank construction (n = 18, 360, 3600)"


def add_arguments(p) -> None:
    p.add_argument("--json", action="store_true", help="print a JSON list of {case, steps, build_s, replay_s}")
    p.add_argument("--parts", type=int, action="append", help="cases to run instead of 18, 360, 3600")


def run(args) -> int:
    results = run_bench(tuple(args.parts) if args.parts else CASES)
    if args.json:
        print(json.dumps(results, indent=1))
        return 0
    for r in results:
        print(f"{r['case']:28s} {r['steps']:7d} steps  build {r['build_s'] * 1e3:9.2f} ms  "
              f"replay {r['replay_s'] * 1e3:9.3f} ms  ({r['replay_per_step_us']:.2f} us/step)")
    if not args.parts:
        for line in verdicts(results):
            print(line)
    return 0
