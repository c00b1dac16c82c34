"""construct bench: how fast the crank construction builds and replays."""

from __future__ import annotations

import json

from ..bench import CASES, run_bench, verdicts

NAME = "bench"
HELP = "benchmark building and replaying the crank construction (n = 18, 360, 3600)"


def add_arguments(p) -> None:
    p.add_argument("--json", action="store_true", help="print a JSON list of {case, steps, build_s, replay_s}")
    p.add_argument("--parts", type=int, action="append", help="cases to run instead of 18, 360, 3600")
    p.add_argument("--outputs", action="store_true",
                   help="time the outputs instead: replay at 360 and 1440 parts, gallery, verify (about a minute)")


def run(args) -> int:
    if args.outputs:
        from ..regress.outputbench import output_verdicts, run_output_bench

        found = run_output_bench()
        if args.json:
            print(json.dumps(found, indent=1))
            return 0
        for r in found:
            size = f"  {r['bytes'] / 1e6:8.2f} MB" if "bytes" in r else ""
            print(f"{r['command']:58s} {r['wall_s']:7.2f} s wall {r['cpu_s']:7.2f} s CPU{size}")
        for line in output_verdicts(found):
            print(line)
        return 0
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
