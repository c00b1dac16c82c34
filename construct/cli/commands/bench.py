"""construct bench: how fast the kernel builds, replays and sweeps the crank construction."""

from __future__ import annotations

import json

from ...regress.replaybench import CASES, run_bench, sweep_bench, verdicts
from ..common import add_format_option

NAME = "bench"
HELP = ("benchmark building, replaying and sweeping the crank construction "
        "(Dürer n = 18, 360; dividers n = 18, 360, 3600; a sweep over 10,000 rod ratios); exit 0 when every "
        "target is met, 1 when one is MISSED")


def add_arguments(p) -> None:
    add_format_option(p)
    p.add_argument("--parts", type=int, action="append", metavar="N",
                   help="cases to run (dividers, N parts; repeat) instead of the standard set")
    p.add_argument("--outputs", action="store_true",
                   help="time the outputs instead: replay at 360 and 1440 parts, gallery, verify (about a minute)")
    p.add_argument("--diff", action="store_true",
                   help="time 'construct diff' instead: two drawings of 10,000 and 100,000 elements, one moved "
                        "(time, peak memory, time per element; about a minute)")
    p.add_argument("--live", nargs="*", metavar="PLAYER",
                   help="time the live player's redraw in headless Chromium instead (median, p90, max ms per slider "
                        "move, and how many inside one 16.7 ms frame) for the PLAYER pages given, by default the "
                        "gallery's live players (gallery/*/teaching/player.html with a slider)")
    p.add_argument("--breakdown", action="store_true",
                   help="with --live: also trace each drag in Chromium and split the frame's main-thread time into "
                        "script, style, layout, pre-paint, paint and commit (with the elements restyled and the "
                        "objects laid out per frame, and the raster time on the worker threads beside it)")
    p.add_argument("--diff-million", action="store_true",
                   help="with --diff: also 1,000,000 elements (about 80 MB per drawing; minutes)")
    p.add_argument("--guard", action="store_true",
                   help="CI's speed guard instead: the ratio targets (sweep / replay, time per step flat from 18 to "
                        "3600 parts, rendering / replay per step and its growth), exit 1 when one is more than 2x past "
                        "its target (about 20 s)")


def run(args) -> int:
    if args.guard:
        from ...regress.guard import guard_lines, run_guard, verdict

        found = run_guard()
        if args.format == "json":
            print(json.dumps([{**r, "verdict": verdict(r)} for r in found], indent=1))
        else:
            for line in guard_lines(found):
                print(line)
        return 1 if any(verdict(r) == "FAILED" for r in found) else 0
    if args.live is not None:
        return _live(args)
    if args.diff or args.diff_million:
        from ...regress.diffbench import SIZES, diff_verdicts, run_diff_bench

        found = run_diff_bench(SIZES + ((1_000_000,) if args.diff_million else ()))
        if args.format == "json":
            print(json.dumps(found, indent=1))
            return met(diff_verdicts(found))
        return met(diff_verdicts(found), show=True)
    if args.outputs:
        from ...regress.outputbench import output_verdicts, run_output_bench

        found = run_output_bench()
        if args.format == "json":
            print(json.dumps(found, indent=1))
            return met(output_verdicts(found))
        for r in found:
            if r["case"] == "live":
                continue  # (its own line below: each player's cost)
            size = f"  {r['bytes'] / 1e6:8.2f} MB" if "bytes" in r else ""
            print(f"{r['command']:58s} {r['wall_s']:7.2f} s wall {r['cpu_s']:7.2f} s CPU{size}")
        return met(output_verdicts(found), show=True)
    cases = tuple((n, "dividers") for n in args.parts) if args.parts else CASES
    results = run_bench(cases)
    sweep = None if args.parts else sweep_bench()
    if args.format == "json":
        print(json.dumps({"cases": results, "sweep": sweep}, indent=1))
        return met(verdicts(results, sweep))
    for r in results:
        print(f"{r['case']:28s} {r['steps']:7d} steps  build {r['build_s'] * 1e3:9.2f} ms "
              f"({r['build_per_step_us']:6.2f} us/step)  replay {r['replay_s'] * 1e3:9.3f} ms "
              f"({r['replay_per_step_us']:.2f} us/step)")
    if sweep is not None:
        print(f"{sweep['case']}: {sweep['sweep_s'] * 1e3:.1f} ms (one replay {sweep['scalar_replay_s'] * 1e3:.3f} ms)")
    return met(verdicts(results, sweep), show=True)


def met(lines, *, show: bool = False) -> int:
    """Exit 0 when every target is met, 1 when a verdict line says MISSED or a live drag's line SLOW (as a failed
    check exits 1); with *show* the lines are printed.

    >>> met(["target a -> met", "target b -> MISSED"]), met(["target a -> met"])
    (1, 0)
    >>> met(["ok: p.html at last, drag domain: median 9.0 ms", "SLOW: q.html at last, drag domain: median 18.0 ms"])
    1
    """
    lines = list(lines)
    if show:
        for line in lines:
            print(line)
    return 1 if any(line.rstrip().endswith("MISSED") or line.startswith("SLOW:") for line in lines) else 0


def _live(args) -> int:
    from pathlib import Path

    from ...kernel.errors import InvalidParameter
    from ...regress.livebench import live_verdicts, page_name, run_live_bench

    pages = [Path(p) for p in args.live] or sorted(
        p for p in Path("gallery").glob("*/teaching/player.html") if 'id="live-data"' in p.read_text(encoding="utf-8"))
    missing = [str(p) for p in pages if not p.is_file()]
    if not pages or missing:
        raise InvalidParameter(f"--live: no live player {'at ' + ', '.join(missing) if missing else 'in gallery/'} "
                               "(write one with: construct replay crank --live --style teaching --out DIR)")
    found = run_live_bench(pages, breakdown=args.breakdown)
    if args.format == "json":
        print(json.dumps(found, indent=1))
        return met(live_verdicts(found))
    for r in found:
        print(f"{page_name(r['page'])}  {r['step']:18s} {r['drag']:7s} frame: median {r['median_ms']:6.1f} ms  "
              f"p95 {r['p95_ms']:6.1f}  max {r['max_ms']:6.1f}  script: median {r['script_median_ms']:5.1f}  "
              f"p95 {r['script_p95_ms']:5.1f}")
        if "breakdown" in r:
            b = r["breakdown"]
            print("    traced, ms a frame: " + "  ".join(f"{k[:-3]} {b[k]:.1f}" for k in b if k.endswith("_ms"))
                  + f"  (raster on the workers, beside the frame); restyled {b['restyled']:.0f} elements, "
                  f"laid out {b['laid_out']:.0f} objects a frame")
    return met(live_verdicts(found), show=True)
