"""The diff benchmark: what ``construct diff`` costs on two large drawings with one element moved.

Run with ``construct bench --diff`` (10,000 and 100,000 elements; ``--diff-million``
adds 1,000,000, about 80 MB per file and some minutes).  Each case runs in a
fresh interpreter, so that its peak memory (``ru_maxrss``) is its own; it
reads the two files and reports the wall and CPU time of reading both
drawings and of diffing them (matching and comparing, the matching alone
beside it), the peak memory above what the interpreter held before, and the
time per element.  Two kinds of drawing: every element with an ``id`` (as the figures
are written), and anonymous elements of a few repeated looks (matched by
content, then key, then geometry).

Target: the time per element flat -- within 2x from n to 10 n;
the matching used to be quadratic (435 s and 2.5 GB at a million elements,
17 s at 100,000).  Nothing here is a test: the numbers depend on the machine.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

__all__ = ["synthetic_svg", "measure_case", "run_diff_bench", "diff_verdicts", "SIZES", "FLAT_RATIO"]

#: Elements per drawing; ``--diff-million`` adds 1,000,000.
SIZES = (10_000, 100_000)
#: The time per element at 10 n within this factor of that at n: near-linear.
FLAT_RATIO = 2.0


def synthetic_svg(n: int, *, moved: int | None = None, ids: bool = False) -> str:
    """A drawing of *n* elements (circles and lines, ~60-80 bytes each), element *moved* shifted by 3 px.

    Anonymous elements repeat a few looks (two classes, one radius), as points and
    helper lines of a figure do; their positions walk the canvas in a fixed pattern.
    Written by svgwrite, as every SVG of the project is (:mod:`construct.render.svgdoc`).

    >>> svg = synthetic_svg(4, moved=1, ids=True)
    >>> svg.count("<circle"), svg.count("<line"), 'cx="922.25" cy="44.5" id="e1"' in svg
    (2, 2, True)
    """
    from ..render.svgdoc import Writer

    w = Writer()
    f = w.factory
    dwg = w.drawing(size=("1000", "1000"), viewBox="0 0 1000 1000")
    dwg.add(f.style(".pt{fill:#000}.ln{stroke:#888;stroke-width:0.5}"))
    for i in range(n):
        x, y = (i * 7919) % 1000, (i * 104729) % 997
        if i == moved:
            x += 3
        ident = {"id": f"e{i}"} if ids else {}
        if i % 2:
            dwg.add(f.circle(center=(f"{x}.25", f"{y}.5"), r="1.5", class_="pt", **ident))
        else:
            dwg.add(f.line(start=(str(x), str(y)), end=(str(x + 10), str(y + 5)), class_="ln", **ident))
    return w.text(dwg)


def measure_case(a: str, b: str, n: int, ids: bool) -> dict[str, Any]:
    """One case, in this process: read both files, diff them, and the matching alone."""
    import resource
    import time
    from pathlib import Path

    from .svgdiff import DEFAULT_TOLERANCE, parse_svg
    from .svgdiff.match import drawing_extent, match_shapes
    from .svgdiff.report import diff_drawings

    def rss_mb() -> float:
        return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # kB on Linux

    base = rss_mb()
    clock = time.perf_counter
    t, c = clock(), time.process_time()
    da, db = parse_svg(Path(a)), parse_svg(Path(b))
    parse_wall, parse_cpu = clock() - t, time.process_time() - c
    t, c = clock(), time.process_time()
    diff = diff_drawings(da, db, DEFAULT_TOLERANCE, a, b)
    diff_wall, diff_cpu = clock() - t, time.process_time() - c
    t = time.process_time()
    match_shapes(da.shapes, db.shapes, DEFAULT_TOLERANCE, max(drawing_extent(da), drawing_extent(db)))
    match_cpu = time.process_time() - t
    kinds = sorted({ch.kind for ch in diff.changes})
    return {"case": f"{n} {'ids' if ids else 'anonymous'}", "elements": n, "ids": ids,
            "bytes": Path(a).stat().st_size,
            "parse_s": parse_wall, "parse_cpu_s": parse_cpu, "diff_s": diff_wall, "diff_cpu_s": diff_cpu,
            "match_cpu_s": match_cpu, "wall_s": parse_wall + diff_wall, "cpu_s": parse_cpu + diff_cpu,
            "cpu_per_element_us": (parse_cpu + diff_cpu) / n * 1e6,
            "peak_mb": rss_mb() - base, "changes": len(diff.changes), "kinds": kinds}


def run_diff_bench(sizes: tuple[int, ...] = SIZES) -> list[dict[str, Any]]:
    """Run each size, with ids and anonymous, each in a fresh interpreter on files; one dict per case."""
    out = []
    with tempfile.TemporaryDirectory(prefix="construct-diffbench-") as tmp:
        for n in sizes:
            for ids in (True, False):
                a, b = Path(tmp, "a.svg"), Path(tmp, "b.svg")
                a.write_text(synthetic_svg(n, ids=ids), encoding="utf-8")
                b.write_text(synthetic_svg(n, moved=n // 2 + 1, ids=ids), encoding="utf-8")
                code = ("import json; from construct.regress.diffbench import measure_case; "
                        f"print(json.dumps(measure_case({str(a)!r}, {str(b)!r}, {n}, {ids})))")
                done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
                if done.returncode != 0:
                    raise RuntimeError(f"diff bench case {n} failed: {done.stderr.strip().splitlines()[-1:]}")
                out.append(json.loads(done.stdout.strip().splitlines()[-1]))
    return out


def diff_verdicts(results: list[dict[str, Any]]) -> list[str]:
    """One line per case, then the target: CPU time per element flat from n to 10 n (within 2x)."""
    lines = []
    for r in results:
        lines.append(f"diff {r['case']:>18s} elements, one moved ({r['bytes'] / 1e6:5.1f} MB each): "
                     f"{r['wall_s']:7.2f} s wall, {r['cpu_s']:7.2f} s CPU (reading {r['parse_cpu_s']:.2f}, "
                     f"diff {r['diff_cpu_s']:.2f}, of it matching {r['match_cpu_s']:.2f}), "
                     f"peak +{r['peak_mb']:.0f} MB, {r['cpu_per_element_us']:.0f} us/element; "
                     f"{r['changes']} change ({', '.join(r['kinds'])})")
    for ids in (True, False):
        same = sorted((r for r in results if r["ids"] == ids), key=lambda r: r["elements"])
        for small, big in zip(same, same[1:]):
            ratio = big["cpu_per_element_us"] / small["cpu_per_element_us"]
            match = (big["match_cpu_s"] / big["elements"]) / max(small["match_cpu_s"] / small["elements"], 1e-12)
            lines.append(f"target diff time per element flat within {FLAT_RATIO:g}x "
                         f"({'ids' if ids else 'anonymous'}, n = {small['elements']} -> {big['elements']}): "
                         f"x{ratio:.2f} (matching alone x{match:.2f}) -> "
                         f"{'met' if ratio <= FLAT_RATIO else 'MISSED'}")
    lines.append(f"(machine: {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f})")
    return lines
