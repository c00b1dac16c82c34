"""construct check: compare every constructed quantity with the analytic formulas."""

from __future__ import annotations

import json

from ...constructions.checking import run_checks, summary
from ...kernel.protocol import jsonable
from ..common import add_format_option, add_construction_options, brief, figure_from_args

NAME = "check"
HELP = "check a construction against the analytic formulas (exit 0 when all pass, 1 otherwise)"


def add_arguments(p) -> None:
    add_construction_options(p)
    add_format_option(p)
    p.add_argument("--all", action="store_true", help="list passing checks too")


def run(args) -> int:
    c, fig = figure_from_args(args)
    if c is None:  # a protocol of the user's own: it replayed, and there is nothing to check it against
        name = fig.protocol.construction
        if args.format == "json":
            print(json.dumps({"construction": name, "ok": True, "checks": [],
                              "note": "not a book construction: replayed, no checks"}, indent=1, ensure_ascii=True))
        else:
            print(f"{brief(name)}: replayed {len(fig.protocol.steps)} steps; not a book construction, no checks")
        return 0
    checks = run_checks(c, fig)
    ok = all(ch.ok for ch in checks)
    params = {k: v for k, v in jsonable(dict(fig.params)).items() if k not in ("group_titles", "plate", "called")}
    params["givens"] = dict(fig.replay.givens)
    if args.format == "json":
        print(json.dumps({"construction": c.name, "params": params, "ok": ok,
                          "checks": [ch.as_dict() for ch in checks]}, indent=1, ensure_ascii=True))
    else:
        for ch in checks:
            if args.all or not ch.ok:
                mark = "ok  " if ch.ok else "FAIL"
                print(f"{mark} {ch.name:40s} measured {ch.measured:.15g}  expected {ch.expected:.15g}  "
                      f"error {ch.error:+.2e}  tolerance {ch.tolerance:.1e}  ({ch.why})")
        print(f"{c.name}: {summary(checks)}")
    return 0 if ok else 1
