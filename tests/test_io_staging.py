"""Output folders: a writer replaces only what it wrote, says why it cannot write, and leaves no staging behind.

No data lost: no traceback for an output folder, no staging folder left after
a kill, a message naming the unwritable parent.  The CLI runs in-process
(``construct.cli.main``) with a one-figure gallery, except where a signal
must reach a real process.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import construct.gallery as gallery
import construct.regress.verify as verify_module
from construct.constructions import get
from construct.kernel.errors import OutputError
import construct.io.staging as output
from construct.io.staging import STAGING_PREFIX
from construct.regress.pytest_plugin import GoldenChecker

REPO = Path(__file__).resolve().parents[1]
ROOT = os.geteuid() == 0 if hasattr(os, "geteuid") else False


def refused(code: int, err: str) -> bool:
    """Exit 2 with exactly one line on stderr and no traceback."""
    lines = err.strip().splitlines()
    return code == 2 and len(lines) == 1 and lines[0].startswith("construct: error:") and "Traceback" not in err


def tree(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def staging(folder: Path) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name.startswith(STAGING_PREFIX))


# --------------------------------------------------------------------------- gallery --out


def test_gallery_refuses_a_folder_of_other_files(small_plan, tmp_path, cli):
    p = tmp_path / "p"
    p.mkdir()
    (p / "notes.txt").write_text("x\n")
    code, _, err = cli("gallery", "--out", str(p))
    assert refused(code, err) and "notes.txt" in err and "gallery" in err
    assert tree(p) == {"notes.txt": b"x\n"} and not staging(tmp_path)


def test_gallery_refuses_the_current_folder_and_an_empty_path(small_plan, tmp_path, cli, monkeypatch):
    p = tmp_path / "p"
    p.mkdir()
    (p / "notes.txt").write_text("x\n")
    monkeypatch.chdir(p)
    for out in (".", ""):
        code, _, err = cli("gallery", "--out", out)
        assert refused(code, err), (out, err)
        assert tree(p) == {"notes.txt": b"x\n"}
    assert "empty path" in err
    # an empty path is never meant, not even in an empty folder
    (p / "notes.txt").unlink()
    code, _, err = cli("gallery", "--out", "")
    assert refused(code, err) and os.listdir(p) == [] and not staging(tmp_path)


def test_gallery_refuses_a_file(small_plan, tmp_path, cli):
    f = tmp_path / "f.txt"
    f.write_text("hi\n")
    code, _, err = cli("gallery", "--out", str(f))
    assert refused(code, err) and "not a folder" in err
    assert f.read_text() == "hi\n" and not staging(tmp_path)


def test_gallery_replaces_a_gallery_or_an_empty_folder(small_plan, tmp_path, cli):
    out = tmp_path / "g"
    out.mkdir()
    assert cli("gallery", "--out", str(out))[0] == 0
    first = tree(out)
    assert gallery.is_gallery(out)  # recognised by its manifest
    assert cli("gallery", "--out", str(out))[0] == 0
    assert tree(out) == first and not staging(tmp_path)
    # a file put into a gallery by hand is not ours: refused and named, nothing removed
    (out / "crank-parts-3-rod-ratio-4" / "stale.svg").write_text("put here by hand")
    assert not gallery.is_gallery(out)
    code, _, err = cli("gallery", "--out", str(out))
    assert refused(code, err) and "crank-parts-3-rod-ratio-4/stale.svg" in err
    assert tree(out) == {**first, "crank-parts-3-rod-ratio-4/stale.svg": b"put here by hand"}


def test_a_readme_that_is_a_pipe_is_not_read(small_plan, tmp_path, cli):
    if not hasattr(os, "mkfifo"):
        pytest.skip("no named pipes here")
    out = tmp_path / "g"
    out.mkdir()
    os.mkfifo(out / "README.md")  # reading it would wait for a writer forever
    (out / "index.html").write_text("x")
    code, _, err = cli("gallery", "--out", str(out))
    assert refused(code, err) and sorted(os.listdir(out)) == ["README.md", "index.html"]


def test_the_committed_gallery_is_recognised():
    if not (REPO / "gallery").is_dir():
        pytest.skip("no committed gallery in this checkout")
    if not (REPO / "gallery" / ".construct-manifest.json").exists():
        pytest.skip("the committed gallery predates manifests (rebuilt with `construct gallery` when merged)")
    assert gallery.is_gallery(REPO / "gallery")
    assert not gallery.is_gallery(REPO) and not gallery.is_gallery(REPO / "README.md")


# --------------------------------------------------------------------------- verify --update, --construct-update


def _small_gallery(out: Path) -> None:
    c = get("crank")
    from construct.render.output import write_replay

    write_replay(c, c.figure(parts=3), out / "crank-3")
    (out / "index.html").write_text("<title>gallery</title>\n")


def test_verify_update_refuses_a_folder_it_did_not_write(tmp_path, cli, monkeypatch):
    monkeypatch.setattr(verify_module, "default_builder", _small_gallery)
    p = tmp_path / "project"
    p.mkdir()
    (p / "notes.txt").write_text("x\n")
    (p / "index.html").write_text("my own page\n")
    code, _, err = cli("verify", "--gallery", str(p), "--update")
    assert refused(code, err) and "notes.txt" in err
    assert tree(p) == {"notes.txt": b"x\n", "index.html": b"my own page\n"} and not staging(tmp_path)
    monkeypatch.chdir(p)
    code, _, err = cli("verify", "--gallery", "", "--update")
    assert refused(code, err) and "empty path" in err
    assert tree(p) == {"notes.txt": b"x\n", "index.html": b"my own page\n"}
    # goldens it wrote are rewritten; a file put among them by hand is refused and named
    g = tmp_path / "g"
    assert cli("verify", "--gallery", str(g), "--update")[0] == 0
    (g / "crank-3" / "final.svg").write_text("<svg/>")  # a golden that changed is still ours: rewritten
    assert cli("verify", "--gallery", str(g), "--update")[0] == 0
    assert (g / "crank-3" / "final.svg").read_text() != "<svg/>"
    (g / "crank-3" / "steps").mkdir()
    (g / "crank-3" / "steps" / "007.svg").write_text("<svg/>")
    code, _, err = cli("verify", "--gallery", str(g), "--update")
    assert refused(code, err) and "crank-3/steps/007.svg" in err
    assert (g / "crank-3" / "steps" / "007.svg").read_text() == "<svg/>"


def test_construct_update_refuses_a_folder_it_did_not_write(tmp_path):
    fig = get("crank").figure(parts=3)
    goldens = tmp_path / "goldens"
    mine = goldens / "fig"
    mine.mkdir(parents=True)
    (mine / "notes.txt").write_text("x\n")
    checker = GoldenChecker(goldens=goldens, default_name="fig", update=True)
    with pytest.raises(OutputError, match="notes.txt"):
        checker.check(fig, name="fig")
    assert tree(mine) == {"notes.txt": b"x\n"} and not staging(goldens)
    # its own goldens it rewrites, stale frames included
    (mine / "notes.txt").unlink()
    GoldenChecker(goldens=goldens, default_name="fig", update=True).check(fig, name="fig", legible=False)
    (mine / "steps").mkdir()
    (mine / "steps" / "999.svg").write_text("<svg/>")
    GoldenChecker(goldens=goldens, default_name="fig", update=True).check(fig, name="fig", legible=False)
    assert sorted(os.listdir(mine)) == ["final.svg", "protocol.json"]


# --------------------------------------------------------------------------- replay --out


def test_replay_refuses_an_empty_path_and_a_folder_of_other_files(tmp_path, cli, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, _, err = cli("replay", "crank", "--parts", "3", "--out", "")
    assert refused(code, err) and "empty path" in err and os.listdir(tmp_path) == []
    (tmp_path / "notes.txt").write_text("x\n")
    code, _, err = cli("replay", "crank", "--parts", "3", "--out", ".")
    assert refused(code, err) and "notes.txt" in err
    assert os.listdir(tmp_path) == ["notes.txt"]


def test_a_second_replay_leaves_exactly_its_own_files(tmp_path, cli):
    out = tmp_path / "o"
    assert cli("replay", "crank", "--parts", "6", "--frames", "all", "--out", str(out))[0] == 0
    assert len(os.listdir(out / "steps")) > 50
    assert cli("replay", "crank", "--parts", "3", "--frames", "none", "--out", str(out))[0] == 0
    fresh = tmp_path / "fresh"
    assert cli("replay", "crank", "--parts", "3", "--frames", "none", "--out", str(fresh))[0] == 0
    assert tree(out) == tree(fresh)
    # a replay folder with something foreign in it is not ours any more
    (out / "notes.txt").write_text("x\n")
    code, _, err = cli("replay", "crank", "--parts", "3", "--out", str(out))
    assert refused(code, err) and (out / "notes.txt").exists()


# --------------------------------------------------------------------------- unreachable targets


@pytest.mark.parametrize("command", [["replay", "crank", "--parts", "3"], ["gallery"], ["verify", "--update"]])
def test_unreachable_targets_give_one_line(command, small_plan, tmp_path, cli, monkeypatch):
    monkeypatch.setattr(verify_module, "default_builder", _small_gallery)
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")
    option = "--gallery" if command[0] == "verify" else "--out"
    for target in (tmp_path / ("x" * 300), tmp_path / ("x" * 300) / "sub", blocker / "sub", blocker / "a" / "b"):
        code, _, err = cli(*command, option, str(target))
        assert refused(code, err), (target, err)
    assert sorted(os.listdir(tmp_path)) == ["file"] and blocker.read_text() == "not a folder"


@pytest.mark.skipif(ROOT, reason="root enters folders whatever their mode")
@pytest.mark.parametrize("command", [["replay", "crank", "--parts", "3"], ["gallery"]])
def test_a_folder_that_cannot_be_entered(command, small_plan, tmp_path, cli):
    closed = tmp_path / "closed"
    closed.mkdir()
    closed.chmod(0)
    try:
        code, _, err = cli(*command, "--out", str(closed / "x"))
    finally:
        closed.chmod(0o700)
    assert refused(code, err) and "Permission denied" in err


@pytest.mark.skipif(ROOT, reason="root writes into read-only folders")
def test_a_gallery_whose_parent_is_read_only_names_what_cannot_be_written(small_plan, tmp_path, cli):
    parent = tmp_path / "ro"
    out = parent / "g"
    out.mkdir(parents=True)  # the target itself is writable
    parent.chmod(0o500)
    try:
        code, _, err = cli("gallery", "--out", str(out))
    finally:
        parent.chmod(0o700)
    assert refused(code, err)
    assert f"cannot replace gallery folder {str(out)!r}" in err
    assert f"parent folder {str(parent)!r} is not writable" in err
    assert os.listdir(out) == []


def test_the_unwritable_parent_message_also_as_root(small_plan, tmp_path, cli, monkeypatch):
    """The same case where root cannot be denied: the staging folder cannot be made in the parent."""
    parent, out = tmp_path / "ro", tmp_path / "ro" / "g"
    out.mkdir(parents=True)
    real = output._make_stage

    def denied(folder, tag=""):
        if Path(folder) == parent.resolve():
            raise PermissionError(13, "Permission denied")
        return real(folder, tag)

    monkeypatch.setattr(output, "_make_stage", denied)
    code, _, err = cli("gallery", "--out", str(out))
    assert refused(code, err)
    assert f"parent folder {str(parent.resolve())!r} is not writable (Permission denied)" in err
    assert os.listdir(out) == []


def test_a_swap_leaves_the_previous_folder_when_the_build_fails(tmp_path):
    out = tmp_path / "g"
    out.mkdir()
    (out / "a").write_text("old")
    with pytest.raises(RuntimeError):
        with output.replaced_folder(out, recognise=lambda p: True, described="ours") as new:
            new.mkdir()
            (new / "a").write_text("new")
            raise RuntimeError("broke")
    assert tree(out) == {"a": b"old"} and not staging(tmp_path)


# --------------------------------------------------------------------------- staging after a kill


def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_stale_staging_of_a_dead_run_is_removed_and_a_live_one_kept(small_plan, tmp_path, cli):
    dead = tmp_path / f"{STAGING_PREFIX}{_dead_pid()}-12345-abc"
    (dead / "g").mkdir(parents=True)
    (dead / "g" / "big.svg").write_text("x" * 1000)
    # a run still going: the process that started pytest (this process's own folders are known by name)
    parent = os.getppid()
    live = tmp_path / f"{STAGING_PREFIX}{parent}-{output._start_token(parent) or 0}-theirs"
    live.mkdir()
    foreign = tmp_path / f"{STAGING_PREFIX}abcdef"  # no pid in its name: whose it is cannot be told
    foreign.mkdir()
    assert cli("gallery", "--out", str(tmp_path / "g"))[0] == 0
    assert not dead.exists() and live.is_dir() and foreign.is_dir()
    assert output.remove_stale_staging(tmp_path) == []


def _start_gallery(out: Path) -> subprocess.Popen:
    env = {**os.environ, "PYTHONPATH": str(REPO) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    return subprocess.Popen([sys.executable, "-m", "construct", "gallery", "--out", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
                            start_new_session=True)


def _wait_for_staging(folder: Path, proc: subprocess.Popen, besides: tuple[str, ...] = ()) -> str:
    """Poll (not a timing assertion: a slow machine only waits longer) until the run's staging folder is there."""
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        new = [n for n in staging(folder) if n not in besides]
        if new:
            return new[0]
        if proc.poll() is not None:
            pytest.fail(f"the gallery run ended before staging: {proc.returncode} {proc.stderr.read()}")
        time.sleep(0.02)
    proc.kill()
    pytest.fail("no staging folder appeared")


def test_sigterm_during_gallery_removes_its_staging(tmp_path):
    out = tmp_path / "g"
    proc = _start_gallery(out)
    _wait_for_staging(tmp_path, proc)
    proc.send_signal(signal.SIGTERM)  # to the main process only, as `kill PID` does
    # the figures being built are stopped, not waited for: the live players' sweeps take many seconds of CPU
    # (a bound far above the tenth of a second it takes, far below the sweeps it once waited for)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode != 0 and "Traceback" not in err, err
    assert os.listdir(tmp_path) == [], os.listdir(tmp_path)


def test_the_next_run_removes_the_staging_of_a_killed_one(tmp_path):
    out = tmp_path / "g"
    proc = _start_gallery(out)
    stale = _wait_for_staging(tmp_path, proc)
    os.killpg(proc.pid, signal.SIGKILL)  # the run and its workers: no chance to clean up
    proc.communicate()
    assert staging(tmp_path) == [stale]
    nxt = _start_gallery(out)
    _wait_for_staging(tmp_path, nxt, besides=(stale,))
    assert stale not in staging(tmp_path)  # removed before the next run staged its own
    nxt.send_signal(signal.SIGTERM)
    _, err = nxt.communicate(timeout=300)
    assert nxt.returncode != 0 and os.listdir(tmp_path) == [], (nxt.returncode, err, os.listdir(tmp_path))
    shutil.rmtree(out, ignore_errors=True)


def test_a_failed_replay_removes_the_folders_it_made_for_its_target(tmp_path):
    # --out a/b/c: a run that failed while writing made a/ and a/b/ for its target and left them behind.
    from construct.io.staging import staged_output

    with pytest.raises(RuntimeError):
        with staged_output(tmp_path / "a" / "b" / "c") as stage:
            (stage / "final.svg").write_text("<svg/>")
            raise RuntimeError("a step failed")
    assert list(tmp_path.iterdir()) == []


def test_a_failed_gallery_removes_the_folders_it_made_for_its_target(tmp_path, monkeypatch):
    from construct.io.staging import replaced_folder

    with pytest.raises(RuntimeError):
        with replaced_folder(tmp_path / "a" / "b" / "g", recognise=lambda p: False, described="a gallery") as new:
            new.mkdir()
            raise RuntimeError("a figure failed")
    assert list(tmp_path.iterdir()) == []


# -- all or nothing: staged_output's commit, its messages, a folder that cannot be moved --------------------------


def _old_output(root: Path) -> Path:
    target = root / "out"
    with output.staged_output(target, recognise=lambda p: True, described="ours") as stage:
        for name in ("animated.svg", "final.svg", "player.html"):
            (stage / name).write_text("old " + name)
    return target


def test_a_commit_that_fails_halfway_puts_the_previous_files_back(tmp_path, monkeypatch):
    """An I/O error at the second move: the folder holds the previous files, all of them, and no new one (it held
    a new animated.svg beside an old final.svg)."""
    target = _old_output(tmp_path)
    real, calls = os.replace, []

    def failing(src, dst):
        if str(src).startswith(str(target / STAGING_PREFIX)) and Path(dst).parent == target:
            calls.append(dst)
            if len(calls) == 2:
                raise OSError(28, "No space left on device", str(dst))
        return real(src, dst)

    monkeypatch.setattr(output.os, "replace", failing)
    with pytest.raises(OutputError, match="No space left on device; the previous files are kept"):
        with output.staged_output(target, recognise=lambda p: True, described="ours") as stage:
            for name in ("animated.svg", "final.svg", "player.html"):
                (stage / name).write_text("new " + name)
    monkeypatch.setattr(output.os, "replace", real)
    assert sorted(p.name for p in target.iterdir()) == ["animated.svg", "final.svg", "player.html"]
    assert {p.read_text() for p in target.iterdir()} == {"old animated.svg", "old final.svg", "old player.html"}


def test_ctrl_c_during_a_commit_waits_until_the_new_files_are_all_in(tmp_path, monkeypatch):
    """Ctrl-C between two moves arrives after the last one: the new output whole, then the interruption."""
    target = _old_output(tmp_path)
    real, sent = os.replace, []

    def interrupted(src, dst):
        if Path(dst).parent == target and not sent:
            sent.append(True)
            signal.raise_signal(signal.SIGINT)
        return real(src, dst)

    monkeypatch.setattr(output.os, "replace", interrupted)
    # Ctrl-C as a terminal delivers it, whatever this process inherited (a test worker may ignore SIGINT)
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        with pytest.raises(KeyboardInterrupt):
            with output.staged_output(target, recognise=lambda p: True, described="ours") as stage:
                for name in ("animated.svg", "final.svg", "player.html"):
                    (stage / name).write_text("new " + name)
    finally:
        signal.signal(signal.SIGINT, previous)
    assert sent and {p.read_text() for p in target.iterdir()} == {"new animated.svg", "new final.svg",
                                                                  "new player.html"}


def test_a_failure_where_there_was_no_previous_folder_says_nothing_was_written(tmp_path):
    with pytest.raises(OutputError) as err:
        with output.replaced_folder(tmp_path / "new", recognise=lambda p: True, described="a demo") as new:
            new.mkdir()
            raise OSError(28, "No space left on device", str(new / "a.svg"))
    assert "nothing was written" in str(err.value) and "previous" not in str(err.value)


def test_an_unmovable_gallery_is_refused_before_anything_is_built(small_plan, tmp_path, cli, monkeypatch):
    """A folder the swap cannot move (not writable: its ".." must change) is said at once, not after the build."""
    target = tmp_path / "g"
    assert cli("gallery", "--out", target).code == 0
    built = []
    monkeypatch.setattr(gallery, "_build_and_check", lambda *a, **k: built.append(a))
    real = os.access
    monkeypatch.setattr(output.os, "access", lambda p, mode: False if Path(p) == target.resolve() else real(p, mode))
    code, _, err = cli("gallery", "--out", target)
    assert code == 2 and "not writable" in err and "nothing was built" in err and not built
    assert (target / "index.html").is_file()
