"""Hostile input at the command line: every case gives one line and exit 2, or the right answer.

Grouped by what is hostile: numbers too large for a float, files that
are not regular files, writes that fail, text a terminal cannot show, library
misuse, hangs (each bounded by the harness: a subprocess with ``timeout=``,
never a timed assertion), output that must be old or new at every point of
an interrupted swap, and folders that only look like ours.
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import construct
import construct.gallery as gallery
import construct.io.staging as staging
import construct.regress.verify as verify_module
from construct.cli.main import main
from construct.io.manifest import MANIFEST_NAME
from construct.io.staging import STAGING_PREFIX
from construct.kernel.errors import (ConstructError, InputFileError, InvalidParameter, OutputError,
                                     ProtocolFormatError, RuleError)

REPO = Path(__file__).resolve().parents[1]
BIG = int("9" * 400)  # no float holds it: float(BIG) raises OverflowError


def run(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def refused(code: int, err: str) -> bool:
    """Exit 2 with exactly one line on stderr and no traceback."""
    lines = err.strip().splitlines()
    return code == 2 and len(lines) == 1 and lines[0].startswith("construct: error:") and "Traceback" not in err


def cli(*argv: str, timeout: float = 120, env: dict | None = None, cwd: Path | None = None
        ) -> subprocess.CompletedProcess:
    """The CLI in a process of its own; *timeout* is the harness's bound on a hang."""
    full = {**os.environ, "PYTHONPATH": str(REPO), **(env or {})}
    return subprocess.run([sys.executable, "-m", "construct", *argv], capture_output=True, timeout=timeout,
                          env=full, cwd=cwd)


def tree(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def staging_left(folder: Path) -> list[str]:
    return sorted(n for n in os.listdir(folder) if n.startswith(STAGING_PREFIX))


@pytest.fixture(scope="module")
def crank_protocol() -> dict:
    fig = construct.get("crank").figure(parts=6)
    return json.loads(fig.protocol.to_json(fig.replay))


@pytest.fixture(scope="module")
def dividers_protocol() -> dict:
    fig = construct.get("crank").figure(parts=7, method="dividers")
    return json.loads(fig.protocol.to_json(fig.replay))


def _write(tmp_path: Path, doc: dict, name: str = "p.json") -> Path:
    path = tmp_path / name
    path.write_text(json.dumps(doc), encoding="utf-8")
    return path


def _first(doc: dict, op: str) -> dict:
    return next(s for s in doc["steps"] if s["op"] == op)


# --------------------------------------------------------------------------- 1. numbers beyond any float


def _given(doc):
    doc["params"]["givens"]["r"] = BIG


def _step_x(doc):
    _first(doc, "given_point")["params"]["x"] = BIG


def _provenance(doc):
    doc["steps"][0]["provenance"] = {"kind": "approximate", "error": BIG}


def _toward(doc):
    step = next(s for s in doc["steps"] if s.get("params", {}).get("rule", [None])[0] == "toward"
                and len(s["params"]["rule"]) == 5)
    step["params"]["rule"][3] = BIG


@pytest.mark.parametrize("mutate,field", [(_given, "'r'"), (_step_x, "'x'"), (_provenance, "provenance 'error'"),
                                          (_toward, "toward")])
def test_a_400_digit_integer_is_refused_naming_its_field(mutate, field, crank_protocol, tmp_path, capsys):
    doc = json.loads(json.dumps(crank_protocol))
    mutate(doc)
    path = _write(tmp_path, doc)
    for argv in (["check", "--protocol", str(path)], ["replay", "--protocol", str(path), "--out", str(tmp_path / "o")]):
        code, _, err = run(capsys, *argv)
        assert refused(code, err) and field in err and "400 digits" in err, err
    assert not (tmp_path / "o").exists()
    # diff compares it with the original: refused too, naming the path in the file
    clean = _write(tmp_path, crank_protocol, "clean.json")
    code, _, err = run(capsys, "diff", str(clean), str(path))
    assert refused(code, err) and "400 digits" in err, err
    with pytest.raises(ProtocolFormatError, match="400 digits"):
        construct.Protocol.from_json(json.dumps(doc))


def test_the_library_refuses_a_huge_integer_naming_the_argument():
    from construct.kernel.instruments import Builder

    with pytest.raises(InvalidParameter, match="the given 'r'.*401 digits"):
        Builder("demo", givens={"r": 10 ** 400})
    with pytest.raises(ConstructError, match="'x'.*401 digits"):
        Builder("demo", givens={}).given_point("A", 10 ** 400, 0.0)
    with pytest.raises(InvalidParameter, match="rod ratio"):
        construct.get("crank").figure(rod_ratio=10 ** 400)
    proto = construct.get("crank").figure(parts=3).protocol
    with pytest.raises(InvalidParameter, match="the given 'r'"):
        proto.replay({"r": 10 ** 400, "rod_ratio": 5.0})
    with pytest.raises(InvalidParameter, match="the swept given 'r'"):
        proto.replay({"r": [1.0, 10 ** 400], "rod_ratio": 5.0})


def test_a_value_one_float_step_outside_its_range_is_printed_apart_from_the_bound(capsys):
    import math

    above = math.nextafter(1000.0, math.inf)
    with pytest.raises(InvalidParameter) as info:
        construct.get("crank").figure(rod_ratio=above)
    assert f"= {above!r} is outside" in str(info.value)  # 1000.0000000000001, not "1000 is outside .. 1000"


# --------------------------------------------------------------------------- 2. files that are not files


def test_the_reading_helper_refuses_pipes_devices_and_links_to_them(tmp_path):
    from construct.io.reading import read_regular_file

    fifo = tmp_path / "pipe.svg"
    os.mkfifo(fifo)
    link = tmp_path / "zero.svg"
    link.symlink_to("/dev/zero")
    for path, kind in ((fifo, "a named pipe"), (link, "a device"), (tmp_path, "a folder")):
        with pytest.raises(InputFileError, match=kind):
            read_regular_file(path, limit=1 << 20, what="drawing")
    big = tmp_path / "big.svg"
    with open(big, "wb") as fh:
        fh.truncate(2 << 20)
    with pytest.raises(InputFileError, match="larger than 1 MiB"):
        read_regular_file(big, limit=1 << 20, what="drawing")
    with pytest.raises(ProtocolFormatError, match="named pipe"):  # the error class is the caller's
        read_regular_file(fifo, limit=10, what="protocol file", error=ProtocolFormatError)


def _tiny_gallery(out: Path) -> None:
    (out / "demo").mkdir(parents=True)
    (out / "demo" / "final.svg").write_text('<svg xmlns="http://www.w3.org/2000/svg"><circle r="1"/></svg>')
    (out / "README.md").write_text("# Gallery\n")


def test_verify_does_not_block_on_a_fifo_nor_read_dev_zero(tmp_path):
    """Run in a process of its own with a timeout: a hang fails the test instead of stopping the suite."""
    script = f"""
import os, sys
from pathlib import Path
sys.path.insert(0, {str(REPO)!r})
import tests.test_hostile as t
from construct.regress.verify import verify
g = Path({str(tmp_path / 'g')!r})
verify(g, builder=t._tiny_gallery, update=True)
os.unlink(g / "README.md"); os.mkfifo(g / "README.md")
os.unlink(g / "demo" / "final.svg"); os.symlink("/dev/zero", g / "demo" / "final.svg")
r = verify(g, builder=t._tiny_gallery)
print(r.report())
"""
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120,
                          env={**os.environ, "PYTHONPATH": str(REPO)})
    assert proc.returncode == 0, proc.stderr
    assert "named pipe" in proc.stdout and "a device" in proc.stdout and "2 changed" in proc.stdout


# --------------------------------------------------------------------------- 3. writes that fail

_FSIZE = """
import resource, runpy, sys
limit = int(sys.argv[1])
resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))  # Python ignores SIGXFSZ: a write past it fails with EFBIG
sys.argv = ["construct"] + sys.argv[2:]
runpy.run_module("construct", run_name="__main__")
"""


def _limited(limit: int, *argv: str, stdout=None) -> subprocess.CompletedProcess:
    # -B: under the limit Python would also cut the bytecode it caches in construct/**/__pycache__ (a write that
    # stops at the limit is renamed into place as it is), and every later run of the checkout would fail
    return subprocess.run([sys.executable, "-B", "-c", _FSIZE, str(limit), *argv], stdout=stdout or subprocess.PIPE,
                          stderr=subprocess.PIPE, text=True, timeout=120, env={**os.environ, "PYTHONPATH": str(REPO)})


def test_a_full_disk_during_a_replay_keeps_the_previous_replay(tmp_path, capsys):
    out = tmp_path / "o"
    assert run(capsys, "replay", "crank", "--parts", "3", "--out", str(out))[0] == 0
    before = tree(out)
    proc = _limited(20_000, "replay", "crank", "--parts", "6", "--out", str(out))
    assert proc.returncode == 2 and len(proc.stderr.splitlines()) == 1, proc.stderr
    assert "File too large" in proc.stderr and str(out) in proc.stderr and "Traceback" not in proc.stderr
    assert tree(out) == before and staging_left(tmp_path) == []


def test_a_full_disk_behind_stdout_is_one_line(tmp_path):
    with open(tmp_path / "errata.txt", "w") as fh:
        proc = _limited(2000, "errata", stdout=fh)
    assert proc.returncode == 2 and len(proc.stderr.splitlines()) == 1, proc.stderr
    assert "File too large" in proc.stderr and "Traceback" not in proc.stderr


def _failing_writes(monkeypatch, after: int):
    """write_text raises ENOSPC after *after* files (in this process and in forked gallery workers)."""
    import errno

    real = staging.write_text
    count = [0]

    def write(path, text):
        count[0] += 1
        if count[0] > after:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))
        real(path, text)

    for module in (staging, gallery, construct.render.output):
        monkeypatch.setattr(module, "write_text", write)


@pytest.mark.parametrize("command", ["gallery", "verify"])
def test_a_full_disk_during_gallery_or_verify_update_keeps_the_old_goldens(command, small_plan, tmp_path, capsys,
                                                                          monkeypatch):
    monkeypatch.setattr(verify_module, "default_builder", lambda out: gallery.build_gallery(out, workers=1))
    g = tmp_path / "g"
    assert run(capsys, "gallery", "--out", str(g))[0] == 0
    (g / "crank-parts-3-rod-ratio-4" / "checks.md").unlink()  # so that verify --update has something to rewrite
    before = tree(g)
    _failing_writes(monkeypatch, after=2)
    argv = ["gallery", "--out", str(g)] if command == "gallery" else ["verify", "--gallery", str(g), "--update"]
    code, _, err = run(capsys, *argv)
    assert refused(code, err) and "No space left on device" in err, err
    assert tree(g) == before and staging_left(tmp_path) == []


# --------------------------------------------------------------------------- 4, 5. text a terminal cannot show


@pytest.mark.parametrize("env", [{"PYTHONIOENCODING": "ascii"}, {"PYTHONIOENCODING": "latin-1"},
                                 {"LC_ALL": "C", "LANG": "C", "PYTHONUTF8": "0", "PYTHONCOERCECLOCALE": "0"}])
def test_a_terminal_that_is_not_utf8_gets_fallbacks_not_tracebacks(env, cli_process):
    # the terminal's encoding is the process's, set as it starts: the three commands share one process
    argvs = (["list"], ["errata", "--book", "anhang-ii"], ["check", "crank", "--json"])
    out = {}
    for argv, (code, stdout, stderr) in zip(argvs, cli_process(*argvs, env={"PYTHONPATH": str(REPO), **env})):
        assert code in (0, 1) and b"Traceback" not in stderr, (argv, stderr)
        out[argv[0]] = stdout
    errata = out["errata"]
    assert b"cos w" in errata or "cos ω".encode("latin-1", "ignore") in errata  # ω falls back to w
    data = json.loads(out["check"])  # JSON stays JSON, ASCII only
    assert data["construction"] == "crank"


def test_a_lone_surrogate_in_a_protocol_is_refused_naming_the_field(crank_protocol, tmp_path, capsys):
    doc = json.loads(json.dumps(crank_protocol))
    doc["steps"][2]["caption"]["en"] = "half a pair \ud800 here"
    path = _write(tmp_path, doc)
    for argv in (["check", "--protocol", str(path), "--json"], ["replay", "--protocol", str(path), "--out",
                                                                  str(tmp_path / "o")]):
        code, _, err = run(capsys, *argv)
        assert refused(code, err) and "steps[2].caption.en" in err and "lone surrogate" in err, err
    doc = json.loads(json.dumps(crank_protocol))
    doc["construction"] = "mine \udfff"
    code, _, err = run(capsys, "check", "--protocol", str(_write(tmp_path, doc)))
    assert refused(code, err) and "construction" in err


def test_a_surrogate_pair_is_text_and_is_kept(crank_protocol, tmp_path, capsys):
    doc = json.loads(json.dumps(crank_protocol))
    doc["construction"] = "mine \U0001F600"  # written by json.dumps as the escapes \\ud83d\\ude00: one character
    code, out, err = run(capsys, "check", "--protocol", str(_write(tmp_path, doc)), "--json")
    assert code == 0 and json.loads(out)["construction"] == "mine \U0001F600" and out.isascii()


def test_a_library_caption_with_a_lone_surrogate_is_refused_when_written(tmp_path):
    from construct.figure import Figure
    from construct.kernel.instruments import Builder
    from construct.render.output import write_replay

    b = Builder("demo\ud800", givens={})
    b.given_point("A", 0.0, 0.0)
    b.given_point("B", 1.0, 0.0)
    b.line("g", "A", "B")
    proto = b.protocol()
    with pytest.raises(OutputError, match="lone surrogate"):
        write_replay(None, Figure(proto, proto.replay()), tmp_path / "o")
    assert not (tmp_path / "o").exists() and staging_left(tmp_path) == []


def test_a_megabyte_name_prints_a_bounded_line(crank_protocol, tmp_path, capsys):
    doc = json.loads(json.dumps(crank_protocol))
    doc["construction"] = "mine " + "x" * 10 ** 6
    path = _write(tmp_path, doc)
    code, _, err = run(capsys, "replay", "--protocol", str(path), "--out", str(tmp_path / "o"))
    assert code == 0 and len(err) < 1000 and "written to" in err


# --------------------------------------------------------------------------- 6, 8. commands and library misuse


def test_bench_with_parts_of_its_own(capsys):
    code, out, err = run(capsys, "bench", "--parts", "6")
    assert code == 0 and "crank n=6" in out and "not measured" in out, err


@pytest.mark.parametrize("only", [[0], [9], [-1], ["a"], [1, 1], "1", 3])
def test_divide_segment_names_what_is_wrong_with_only(only):
    from construct.kernel.instruments import Builder

    b = Builder("demo", givens={})
    b.given_point("A", 0.0, 0.0)
    b.given_point("B", 4.0, 0.0)
    with pytest.raises(InvalidParameter, match=r"only=\.\.\.\) names division points 1\.\.3"):
        b.divide_segment("T", "A", "B", 4, only=only)


@pytest.mark.parametrize("call,message", [(lambda r: r.nearer(), "nearer() takes one point name, got nothing"),
                                          (lambda r: r.nearer("A", "B"), "nearer() takes one point name"),
                                          (lambda r: r.farther(), "farther()"),
                                          (lambda r: r.left_of("A"), "left_of() takes 2 point names, got 'A'"),
                                          (lambda r: r.right_of(), "right_of()")])
def test_a_rule_called_wrongly_names_the_rule(call, message):
    from construct.kernel import rules

    with pytest.raises(RuleError) as info:
        call(rules)
    assert message in str(info.value)


@pytest.mark.parametrize("option", ["--book", "--seed"])
def test_errata_with_an_empty_book_is_refused(capsys, option):
    code, _, err = run(capsys, "errata", option, "")
    assert refused(code, err) and "name a book" in err


def test_diff_of_a_protocol_with_a_nan_given_and_itself_is_equal(crank_protocol, tmp_path, capsys):
    text = json.dumps(crank_protocol).replace('"r": 1.0', '"r": NaN', 1)
    assert "NaN" in text
    path = tmp_path / "nan.json"
    path.write_text(text)
    code, out, _ = run(capsys, "diff", str(path), str(path))
    assert code == 0 and "equal" in out


def test_crank_angle_at_a_thousand_divisions_passes_its_checks():
    """Inside the stated domain (1..1000); the tolerance now carries the division points' own error
    (dividers stepped up to 1000 times: m^2 eps of the stroke, measured; crank.DIVISION_ERROR)."""
    from construct.constructions.crank import crank_angle_checks

    fig = construct.get("crank-angle").figure(divisions=1000)
    checks = crank_angle_checks(fig)
    assert len(checks) == 1001 and all(ch.ok for ch in checks), [ch for ch in checks if not ch.ok][:3]
    # and the allowance is what the division carries, not slack: along most of the stroke an angle off by
    # 2e-11 still fails (near the dead centres dw/dx grows without bound, and the allowance with it)
    middle = sorted(ch.tolerance for ch in checks[1:-1])[len(checks) // 2]
    assert middle < 2e-11


# --------------------------------------------------------------------------- hangs, bounded by the harness


def test_a_trial_chord_of_ten_million_parts_is_refused_at_load(dividers_protocol, tmp_path):
    doc = json.loads(json.dumps(dividers_protocol))
    _first(doc, "trial_chord")["params"]["parts"] = 10_000_000
    path = _write(tmp_path, doc)
    proc = cli("check", "--protocol", str(path), timeout=60)
    assert proc.returncode == 2 and b"parts 1..3600" in proc.stderr, proc.stderr


def test_frames_all_of_a_large_replay_is_refused_with_its_estimate(tmp_path):
    proc = cli("replay", "crank", "--parts", "360", "--frames", "all", "--out", str(tmp_path / "o"), timeout=120)
    err = proc.stderr.decode()
    assert proc.returncode == 2 and "GB in all" in err and "--force-frames" in err, err
    assert not (tmp_path / "o").exists()


def test_the_frames_estimate_is_near_what_is_written(tmp_path):
    from construct.render.output import frames_estimate, write_replay

    c = construct.get("crank")
    fig = c.figure(parts=18)
    frames, estimate = frames_estimate(fig, "all")
    write_replay(c, fig, tmp_path / "o", frames="all")
    written = sum(p.stat().st_size for p in (tmp_path / "o" / "steps").iterdir())
    assert frames == len(os.listdir(tmp_path / "o" / "steps")) and 0.5 < estimate / written < 2


# --------------------------------------------------------------------------- old or new, at every point


def _state(out: Path, old: dict, new: dict) -> str:
    now = {k: v for k, v in tree(out).items() if not k.startswith(MANIFEST_NAME)} if out.exists() else None
    if now == old:
        return "old"
    if now == new:
        return "new"
    return f"neither: {sorted(now) if now is not None else 'missing'}"


_FAULTS = [OSError(5, "Input/output error"), KeyboardInterrupt()]


def _replay_writer(tmp_path, monkeypatch):
    from construct.render.output import write_replay

    c = construct.get("crank")
    return lambda out, parts: write_replay(c, c.figure(parts=parts), out)


def _gallery_writer(tmp_path, monkeypatch):
    def write(out, parts):
        monkeypatch.setattr(gallery, "gallery_plan", lambda: [("crank", {"parts": parts, "rod_ratio": 4.0})])
        monkeypatch.setattr(gallery, "LIVE_PLAYERS", ())  # the folder is the point, not the live sweep
        gallery.build_gallery(out, workers=1)
    return write


@pytest.mark.parametrize("writer,exchange,fault", [
    (_replay_writer, True, _FAULTS[0]), (_replay_writer, True, _FAULTS[1]),
    (_replay_writer, False, _FAULTS[0]), (_replay_writer, False, _FAULTS[1]),
    (_gallery_writer, True, _FAULTS[0]), (_gallery_writer, False, _FAULTS[1]),
], ids=["replay-renameat2-OSError", "replay-renameat2-Ctrl-C", "replay-two-renames-OSError",
        "replay-two-renames-Ctrl-C", "gallery-renameat2-OSError", "gallery-two-renames-Ctrl-C"])
def test_output_is_old_or_new_whichever_rename_or_rmtree_fails(writer, exchange, fault, tmp_path, monkeypatch):
    """Make each os.rename / os.replace / shutil.rmtree / exchange of a replay or a gallery fail in turn
    (with an error, or Ctrl-C): the folder is always the whole old output or the whole new one, and what
    a failed run leaves in staging the next run removes."""
    write = writer(tmp_path, monkeypatch)
    out = tmp_path / "o"
    write(out, 3)
    old = {k: v for k, v in tree(out).items() if k != MANIFEST_NAME}
    fresh = tmp_path / "fresh"
    write(fresh, 4)
    new = {k: v for k, v in tree(fresh).items() if k != MANIFEST_NAME}
    shutil.rmtree(fresh)
    assert old != new
    if not exchange:
        monkeypatch.setattr(staging, "_exchange", lambda a, b: False)
    real = {"rename": os.rename, "replace": os.replace, "rmtree": shutil.rmtree, "exchange": staging._exchange}
    outcomes = []
    for n in range(1, 12):
        calls = [0]

        def faulty(name):
            def call(*args, **kwargs):
                calls[0] += 1
                if calls[0] == n:
                    raise fault
                return real[name](*args, **kwargs)
            return call

        monkeypatch.setattr(staging.os, "rename", faulty("rename"))
        monkeypatch.setattr(staging.os, "replace", faulty("replace"))
        monkeypatch.setattr(staging.shutil, "rmtree", faulty("rmtree"))
        monkeypatch.setattr(staging, "_exchange", faulty("exchange"))
        try:
            write(out, 4)
            result = "done"
        except (OutputError, KeyboardInterrupt) as exc:
            result = type(exc).__name__
        finally:
            for name in ("rename", "replace"):
                monkeypatch.setattr(staging.os, name, real[name])
            monkeypatch.setattr(staging.shutil, "rmtree", real["rmtree"])
            monkeypatch.setattr(staging, "_exchange", real["exchange"])
        state = _state(out, old, new)
        assert state in ("old", "new"), (n, result, state)
        staging.remove_stale_staging(tmp_path)  # the next run
        assert staging_left(tmp_path) == [] and _state(out, old, new) == state, (n, result, staging_left(tmp_path))
        outcomes.append((result, state))
        if state == "new":  # back to the old output for the next fault
            shutil.rmtree(out)
            write(out, 3)
        if calls[0] < n:  # every call has had its turn
            break
    assert ("done", "new") in outcomes and any(s == "old" for _, s in outcomes), outcomes


def test_a_swap_killed_between_its_renames_is_put_back_by_the_next_run(tmp_path):
    """What SIGKILL between the two renames leaves (no exchange here): the target gone, the previous folder
    in the staging folder of a dead process.  The next run puts it back before anything else."""
    target = tmp_path / "g"
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"], capture_output=True, text=True)
    stage = tmp_path / f"{STAGING_PREFIX}{int(dead.stdout)}-12345-abc"
    (stage / ".old").mkdir(parents=True)
    (stage / ".old" / "final.svg").write_text("the previous one")
    (stage / "g").mkdir()
    (stage / "g" / "final.svg").write_text("the new one, complete")
    (stage / ".target").write_text("g")
    assert staging.remove_stale_staging(tmp_path) == [stage.name]
    assert tree(target) == {"final.svg": b"the previous one"} and staging_left(tmp_path) == []


@pytest.mark.parametrize("handler", ["Ctrl-C", "ignored"])
def test_a_signal_during_the_swap_waits_until_it_is_done(handler, tmp_path, monkeypatch):
    """SIGINT raised from inside the swap (between its renames) arrives after, under the handler that was there
    before: Ctrl-C (KeyboardInterrupt) once the new folder is in place; a SIGINT the process ignores stays ignored.

    The test sets that handler itself.  A suite started as a background job of a shell without job control
    inherits SIGINT ignored (so do its xdist workers), and there no KeyboardInterrupt can come: that, not the
    order of the tests, is what made this test fail in some full runs ("DID NOT RAISE").
    """
    import signal

    out = tmp_path / "o"
    out.mkdir()
    (out / "a").write_text("old")
    monkeypatch.setattr(staging, "_exchange", lambda a, b: False)
    real = os.rename
    fired = []

    def rename(src, dst):
        real(src, dst)
        if not fired:
            fired.append(1)
            signal.raise_signal(signal.SIGINT)  # Ctrl-C right after the first rename

    monkeypatch.setattr(staging.os, "rename", rename)
    previous = signal.signal(signal.SIGINT, signal.default_int_handler if handler == "Ctrl-C" else signal.SIG_IGN)
    try:
        with pytest.raises(KeyboardInterrupt) if handler == "Ctrl-C" else contextlib.nullcontext():
            with staging.replaced_folder(out, recognise=lambda p: True, described="ours") as new:
                new.mkdir()
                (new / "a").write_text("new")
    finally:
        signal.signal(signal.SIGINT, previous)
    assert fired and tree(out) == {"a": b"new"} and staging_left(tmp_path) == []


# --------------------------------------------------------------------------- folders that only look like ours


def test_a_folder_that_looks_like_a_gallery_is_not_taken_for_one(small_plan, tmp_path, capsys):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "README.md").write_text(gallery.README_HEAD + "\n\nmy notes\n")
    (mine / "index.html").write_text("<p>my page</p>\n")
    for name in ("a.txt", "b.txt", "c.txt"):
        (mine / name).write_text(name)
    before = tree(mine)
    code, _, err = run(capsys, "gallery", "--out", str(mine))
    assert refused(code, err) and tree(mine) == before


def test_verify_update_refuses_a_folder_holding_every_name_of_a_gallery(small_plan, tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(verify_module, "default_builder", lambda out: gallery.build_gallery(out, workers=1))
    built = tmp_path / "built"
    gallery.build_gallery(built, workers=1)
    mine = tmp_path / "mine"
    mine.mkdir()
    for name in os.listdir(built):
        if name != MANIFEST_NAME:
            (mine / name).mkdir() if (built / name).is_dir() else (mine / name).write_text("mine")
    (mine / "thesis.tex").write_text("a year of work")
    before = tree(mine)
    code, _, err = run(capsys, "verify", "--gallery", str(mine), "--update")
    assert refused(code, err) and tree(mine) == before


def test_a_gallery_carries_a_manifest_and_verify_accepts_it(small_plan, tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(verify_module, "default_builder", lambda out: gallery.build_gallery(out, workers=1))
    g = tmp_path / "g"
    assert run(capsys, "gallery", "--out", str(g))[0] == 0
    manifest = json.loads((g / MANIFEST_NAME).read_text())
    assert set(manifest["files"]) == set(tree(g)) - {MANIFEST_NAME} and manifest["written_by"] == "construct gallery"
    code, out, _ = run(capsys, "verify", "--gallery", str(g))
    assert code == 0 and "all" in out and "files equal" in out
    assert run(capsys, "verify", "--gallery", str(g), "--update")[0] == 0 and gallery.is_gallery(g)
