"""Determinism: the same construction and givens give the same bytes in every process.

Two fresh interpreters with different ``PYTHONHASHSEED`` (so set and dict-of-str
iteration orders differ), different time zones (so a timestamp would show)
and different output folder names (so an embedded path would show) run the
same ``construct`` commands; every file they write and the JSON check report
must be byte-identical.  Whatever a replay writes is compared -- frames,
final figure, protocol, and the animation, player and storyboard when the
renderer writes them -- so a new output file is covered without editing
this test.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

# One interpreter per seed runs every command through the real CLI entry point;
# stdout of `construct check --json` is captured into a file next to the outputs.
_SCRIPT = r"""
import contextlib, io, sys
from pathlib import Path
from construct.cli.main import main
from construct.render import styles

out = Path(sys.argv[1])
runs = [("plain", ["replay", "crank", "--parts", "18", "--frames", "groups", "--out", str(out / "plain-18")])]
# The other styles at fewer parts, every frame: they exercise the same code per mark.
runs += [(s, ["replay", "crank", "--parts", "6", "--frames", "all", "--style", s, "--out", str(out / f"{s}-6")])
         for s in ("teaching", "historical") if s in styles.STYLES]
for style, argv in runs:
    code = main(argv)
    if code != 0:
        sys.exit(f"construct {' '.join(argv)} exited {code}")
buf = io.StringIO()
with contextlib.redirect_stdout(buf):
    code = main(["check", "crank", "--json"])
(out / "check-crank.json").write_text(buf.getvalue(), encoding="utf-8")
print(" ".join(style for style, _ in runs))
"""


def _run(out: Path, seed: str, tz: str) -> subprocess.Popen:
    env = dict(os.environ, PYTHONHASHSEED=seed, TZ=tz)
    return subprocess.Popen([sys.executable, "-c", _SCRIPT, str(out)], env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, cwd=out.parent)


def _tree(root: Path) -> dict[str, Path]:
    return {p.relative_to(root).as_posix(): p for p in sorted(root.rglob("*")) if p.is_file()}


def test_outputs_are_byte_identical_across_processes_and_hash_seeds(tmp_path: Path) -> None:
    a, b = tmp_path / "run-seed-0", tmp_path / "second-run-seed-12345"
    a.mkdir()
    b.mkdir()
    procs = [_run(a, "0", "UTC"), _run(b, "12345", "Asia/Kolkata")]  # both at once: half the wall time
    results = [p.communicate(timeout=600) for p in procs]
    for p, (out, err) in zip(procs, results):
        assert p.returncode == 0, err
    assert results[0][0] == results[1][0]  # the same styles ran in both
    styles = results[0][0].split()
    assert styles[0] == "plain"

    ta, tb = _tree(a), _tree(b)
    assert sorted(ta) == sorted(tb), "the two runs wrote different files"
    # The runs really wrote what they should: protocol, final figure and frames per style,
    # at least a handful of frames (18 parts by groups: dozens; 6 parts, every step: 74).
    for folder in ("plain-18",) + tuple(f"{s}-6" for s in styles[1:]):
        assert {f"{folder}/final.svg", f"{folder}/protocol.json"} <= set(ta)
        assert sum(1 for k in ta if k.startswith(f"{folder}/steps/")) >= 5
    assert "check-crank.json" in ta and '"checks"' in ta["check-crank.json"].read_text(encoding="utf-8")

    differing = [rel for rel in ta if ta[rel].read_bytes() != tb[rel].read_bytes()]
    assert not differing, f"{len(differing)} files differ between the runs, e.g. {differing[:5]}"
