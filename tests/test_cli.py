"""The command line contract: outputs, exit codes, and one clear line for bad input."""

import csv
import io
import json
import os
import subprocess
import sys

import pytest

from construct.kernel.errors import OutputError


def test_list_names_the_constructions(cli):
    code, out, _ = cli("list")
    assert code == 0 and "crank " in out and "crank-angle" in out


def test_replay_writes_frames_final_and_protocol(tmp_path, cli):
    # by default the layered final figure and no standalone frames
    plain = tmp_path / "plain"
    code, _, err = cli("replay", "crank", "--parts", "6", "--rod-ratio", "4", "--out", str(plain))
    assert code == 0, err
    assert not (plain / "steps").exists() and 'data-step="1"' in (plain / "final.svg").read_text()
    out = tmp_path / "o"
    code, _, err = cli("replay", "crank", "--parts", "6", "--rod-ratio", "4", "--frames", "all",
                       "--out", str(out))
    assert code == 0, err
    proto = json.loads((out / "protocol.json").read_text())
    n = len(proto["steps"])
    frames = sorted((out / "steps").iterdir())
    assert [f.name for f in frames] == [f"{k:03d}.svg" for k in range(1, n + 1)]
    assert (out / "final.svg").read_text().startswith("<?xml")
    assert not [p for p in out.iterdir() if p.name.startswith(".construct-staging")]
    # Frame k holds exactly the marks of steps 1..k: the ids carry the step index.
    import re

    ids = lambda p: {int(m) for m in re.findall(r'id="s(\d{4})-', p.read_text())}
    assert max(ids(frames[9])) == 10 or max(ids(frames[9])) < 10  # step 10 may make a length (not drawn)
    assert ids(frames[9]) <= set(range(1, 11)) and ids(frames[-1]) == ids(out / "final.svg")


def test_replay_of_an_exported_protocol_with_new_givens_equals_a_fresh_build(tmp_path, cli):
    a, b, c = tmp_path / "a", tmp_path / "b", tmp_path / "c"
    assert cli("replay", "crank", "--parts", "9", "--rod-ratio", "4", "--frames", "none", "--out", str(a))[0] == 0
    assert cli("replay", "--protocol", str(a / "protocol.json"), "--rod-ratio", "6", "--frames", "none",
               "--out", str(b))[0] == 0
    assert cli("replay", "crank", "--parts", "9", "--rod-ratio", "6", "--frames", "none", "--out", str(c))[0] == 0
    assert json.loads((b / "protocol.json").read_text()) == json.loads((c / "protocol.json").read_text())


def test_check_exit_codes_and_json(cli, tmp_path):
    code, out, _ = cli("check", "crank", "--json")
    data = json.loads(out)
    assert code == 0 and data["construction"] == "crank" and data["params"]["parts"] == 18
    assert {"name", "measured", "expected", "error", "tolerance", "ok"} <= set(data["checks"][0])
    assert all(c["ok"] for c in data["checks"])
    # A protocol whose crosshead takes the wrong branch fails its checks: exit 1.
    cli("replay", "crank", "--parts", "6", "--frames", "none", "--out", str(tmp_path / "p"))
    proto = json.loads((tmp_path / "p" / "protocol.json").read_text())
    step = next(s for s in proto["steps"] if s["outputs"] == ["C2"])
    step["params"]["rule"] = ["toward", "O", None, 1.0, 0.0]
    (tmp_path / "bad.json").write_text(json.dumps(proto))
    code, out, _ = cli("check", "--protocol", str(tmp_path / "bad.json"))
    assert code == 1 and "FAIL" in out


def test_piston_path_table_csv(cli):
    code, out, _ = cli("table", "piston-path", "--rod-ratio", "4", "--parts", "18", "--format", "csv")
    rows = list(csv.DictReader(io.StringIO(out)))
    assert code == 0 and list(rows[0]) == ["index", "crank_angle_deg", "crank_angle_constructed_deg", "x_constructed",
                                           "x_exact", "x_book"]
    assert len(rows) == 19 and float(rows[-1]["x_constructed"]) == pytest.approx(1.0, abs=1e-12)
    assert float(rows[9]["crank_angle_deg"]) == pytest.approx(90.0, abs=1e-9)


@pytest.mark.parametrize("argv", [
    ("piston-path", "--rod-ratio", "5"), ("tangential-pressure", "--rod-ratio", "5"),
    ("tangential-pressure", "--rod-ratio", "5", "--revolution"),
    ("mass-forces", "--weight", "830", "--rpm", "50", "--crank-radius", "0.4", "--rod-length", "2.0"),
    ("mass-forces", "--weight", "830", "--rpm", "50", "--crank-radius", "0.4", "--rod-length", "2.0", "--revolution"),
])
def test_tables_are_keyed_by_the_division_angle(cli, argv):
    """Dürer's trisection draws 10° as 9.99999803554437°: the key is the 10° the row stands for."""
    code, out, _ = cli("table", *argv, "--format", "csv")
    keys = [row["crank_angle_deg"] for row in csv.DictReader(io.StringIO(out))]
    assert code == 0 and keys[:4] == ["0", "10", "20", "30"]
    assert all(float(k) == 10 * round(float(k) / 10) for k in keys)


def test_crank_angle_table_csv(cli):
    code, out, _ = cli("table", "crank-angle", "--rod-ratio", "5", "--format", "csv")
    rows = list(csv.DictReader(io.StringIO(out)))
    assert code == 0 and list(rows[0])[:3] == ["x", "omega_constructed_deg", "omega_exact_deg"]
    assert len(rows) == 11 and float(rows[5]["omega_constructed_deg"]) == pytest.approx(84 + 15.65 / 60, abs=0.01 / 60)


def test_bench_json_shape(cli):
    code, out, _ = cli("bench", "--json", "--parts", "6")
    data = json.loads(out)
    case = data["cases"][0]
    assert code in (0, 1) and {"case", "steps", "build_s", "replay_s", "trial_step_s"} <= set(case) and case["steps"] > 0
    assert case["method"] == "dividers" and case["trial_step_s"] >= 0.0


@pytest.mark.parametrize("lines, code", [(["target a -> met"], 0), (["target a -> met", "target b -> MISSED"], 1)])
def test_bench_exits_1_when_a_target_is_missed(cli, monkeypatch, lines, code):
    """A missed target is a finding, as a failed check is: exit 1 (it printed MISSED and exited 0)."""
    from construct.cli import commands

    # the module the parser runs (collecting the package's doctests may import a second copy of it)
    bench = next(m for m in commands.MODULES if m.NAME == "bench")
    monkeypatch.setattr(bench, "verdicts", lambda results, sweep: lines)
    got, out, _ = cli("bench", "--parts", "6")
    assert got == code and lines[-1] in out

def test_bench_sweep_is_measured_against_a_loop():
    from construct.regress.replaybench import sweep_bench

    s = sweep_bench(size=200)
    assert s["size"] == 200 and s["sweep_s"] > 0 and s["speedup_over_loop"] == pytest.approx(
        s["scalar_replay_s"] * 200 / s["sweep_s"])
    assert s["elementwise"] == []  # every op of the crank on arrays


BAD = [
    ["replay", "crank", "--rod-ratio", "1", "--out", "{out}"],
    ["replay", "crank", "--rod-ratio", "0.5", "--out", "{out}"],
    ["replay", "crank", "--rod-ratio", "nan", "--out", "{out}"],
    ["replay", "crank", "--rod-ratio", "inf", "--out", "{out}"],
    ["replay", "crank", "--parts", "0", "--out", "{out}"],
    ["replay", "crank", "--parts", "1000000", "--out", "{out}"],
    ["replay", "crank", "--parts", "-3", "--out", "{out}"],
    ["replay", "crank", "--radius", "-1", "--out", "{out}"],
    ["replay", "crank", "--method", "magic", "--out", "{out}"],
    ["replay", "crank", "--parts", "18", "--method", "exact", "--out", "{out}"],
    ["replay", "nosuch", "--out", "{out}"],
    ["replay", "crank", "--divisions", "3", "--out", "{out}"],
    ["replay", "--protocol", "{bad}", "--out", "{out}"],
    ["replay", "--protocol", "{missing}", "--out", "{out}"],
    ["replay", "crank", "--parts", "x", "--out", "{out}"],
    ["check", "crank", "--rod-ratio", "-2"],
    ["table", "piston-path", "--rod-ratio", "0.9"],
    ["table", "nosuch", "--rod-ratio", "4"],
    ["frobnicate"],
]


def _bad_args(argv, tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"construction": "crank", "steps": 3}')
    return [a.format(out=tmp_path / "out", bad=bad, missing=tmp_path / "missing.json") for a in argv]


@pytest.mark.parametrize("argv", BAD, ids=[" ".join(a[:4]) for a in BAD])
def test_bad_input_gives_one_line_exit_2_and_writes_nothing(argv, tmp_path, cli):
    """In-process (an exception escaping main fails the test); the entry point itself is run below."""
    code, out, err = cli(*_bad_args(argv, tmp_path))
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("construct"), err
    assert "Traceback" not in err and out == ""
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("argv", [BAD[0], BAD[-1]], ids=["library error", "argparse error"])
def test_python_m_construct_keeps_the_contract_in_its_own_process(argv, tmp_path):
    """The same contract through the interpreter: exit status 2, one line, no traceback from Python."""
    proc = subprocess.run([sys.executable, "-m", "construct", *_bad_args(argv, tmp_path)], capture_output=True,
                          text=True)
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("construct"), proc.stderr
    assert "Traceback" not in proc.stderr and proc.stdout == ""
    assert not (tmp_path / "out").exists()


def test_unwritable_output_folder(tmp_path, cli):
    blocker = tmp_path / "file"
    blocker.write_text("not a folder")
    for target in (blocker, blocker / "sub"):
        code, _, err = cli("replay", "crank", "--parts", "2", "--out", str(target))
        assert code == 2 and len(err.strip().splitlines()) == 1, err
    assert blocker.read_text() == "not a folder"


@pytest.mark.skipif(os.geteuid() == 0, reason="root can write into read-only folders")
def test_read_only_output_folder(tmp_path, cli):
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    code, _, err = cli("replay", "crank", "--parts", "2", "--out", str(ro / "x"))
    assert code == 2 and len(err.strip().splitlines()) == 1, err


def test_a_failure_midway_leaves_the_previous_output_intact(tmp_path, cli, monkeypatch):
    out = tmp_path / "o"
    assert cli("replay", "crank", "--parts", "3", "--frames", "none", "--out", str(out))[0] == 0
    before = {p.name: p.read_bytes() for p in out.iterdir() if p.is_file()}
    import construct.render.output as ro

    real_write = ro.write_text
    calls = []

    def write_then_fail(path, text):  # the first file goes through, the second hits a full disk
        calls.append(path)
        if len(calls) > 1:
            raise OutputError("disk full (simulated)")
        real_write(path, text)

    monkeypatch.setattr(ro, "write_text", write_then_fail)
    code, _, err = cli("replay", "crank", "--parts", "6", "--out", str(out))
    assert code == 2 and "disk full" in err and len(calls) == 2
    assert {p.name: p.read_bytes() for p in out.iterdir() if p.is_file()} == before
    assert not [p for p in out.iterdir() if p.name.startswith(".construct-staging")]


@pytest.mark.parametrize("other", ["/dev/zero", "fifo", "folder", "huge.svg"])
def test_diff_reads_only_bounded_regular_files(tmp_path, cli, other):
    # 'construct diff a.json /dev/zero' once read until memory ran out.  A device, a named pipe
    # (which would make the read wait for a writer), a folder and a file above the size limit are refused
    # before anything is read.
    from construct.cli.commands.diff import MAX_DRAWING_BYTES

    a = tmp_path / "a.svg"
    a.write_text('<svg xmlns="http://www.w3.org/2000/svg"/>')
    if other == "fifo":
        other = tmp_path / "pipe"
        os.mkfifo(other)
    elif other == "folder":
        other = tmp_path
    elif other == "huge.svg":
        other = tmp_path / "huge.svg"
        with open(other, "wb") as fh:  # sparse: no disk space used
            fh.write(b"<")
            fh.truncate(MAX_DRAWING_BYTES + 1)
    code, _, err = cli("diff", str(a), str(other))
    assert code == 2 and len(err.splitlines()) == 1 and str(other) in err, err


def test_version_comes_from_the_installed_distribution(cli):
    from importlib.metadata import version

    code, out, _ = cli("--version")
    assert code == 0 and out.strip() == f"construct {version('construct-steam')}"
    assert construct_version() == version("construct-steam")


def construct_version() -> str:
    import construct

    return construct.__version__


@pytest.mark.parametrize("argv", [("check", "crank", "--rod-ratio"), ("frob",), ("table",), ("check", "--bogus")])
def test_usage_errors_name_the_program_once(cli, argv):
    code, _, err = cli(*argv)
    assert code == 2 and err.count("construct") == 1 and err.startswith("construct: error: "), err


@pytest.mark.parametrize("argv, nearest", [
    (("chek", "crank"), "'check'"), (("check", "crnk"), "'crank'"), (("table", "piston-pth"), "'piston-path'"),
    (("check", "crank", "--rod-ration", "5"), "'--rod-ratio'"), (("check", "crank", "--method", "durr"), "'durer'"),
    (("check", "four-stroke", "--engine", "disel"), "'diesel'"),
    (("check", "two-cranks", "--dead-centre", "head-nd"), "'head-end'"),
    (("replay", "crank", "--format", "tkz", "--out", "never-written"), "'tikz'"),
])
def test_a_misspelt_name_gets_the_nearest_one(cli, argv, nearest):
    code, out, err = cli(*argv)
    assert code == 2 and out == "" and f"(did you mean {nearest}?)" in err and err.count("\n") == 1, err


def test_a_name_near_nothing_gets_no_guess(cli):
    code, _, err = cli("check", "zzzzzz")
    assert code == 2 and "did you mean" not in err and "available: crank" in err


def test_every_table_has_a_plot_of_its_own_columns():
    from construct.tables import PLOTS, TABLES

    assert set(PLOTS) == set(TABLES)


@pytest.mark.parametrize("suffix", [".png", ".svg", ".pdf"])
def test_table_plot_draws_the_rows_it_prints(tmp_path, cli, suffix):
    """The curve handed to matplotlib is the table's column; the file is written whole, by its suffix."""
    from construct.tables import PLOTS, speed_fluctuation_table
    from construct.render.plotting import plot_table

    cols, rows = speed_fluctuation_table(rod_ratio=None, step=15.0)
    ax = plot_table(PLOTS["speed-fluctuation"], cols, rows)
    x, y = ax.lines[0].get_xdata(), ax.lines[0].get_ydata()
    # seed 002, infinite rod, 0 <= a <= 90 deg: e(a) = Q r (1 - cos a + sin a) - (4/pi) Q r a, which vanishes at
    # the dead centre and at 45 deg (both terms are Q r there)
    assert list(x) == [r["crank_angle_deg"] for r in rows] and abs(y[0]) < 1e-12
    assert abs(y[list(x).index(45.0)]) < 1e-9
    out = tmp_path / f"e{suffix}"
    code, text, err = cli("table", "speed-fluctuation", "--infinite-rod", "--step", "15", "--plot", str(out))
    assert code == 0 and err == "" and text.startswith("crank_angle_deg")
    head = out.read_bytes()[:8]
    assert head.startswith({".png": b"\x89PNG", ".svg": b"<?xml", ".pdf": b"%PDF"}[suffix])
    assert sorted(p.name for p in tmp_path.iterdir()) == [out.name]  # no staging file left beside it


@pytest.mark.parametrize("target", ["x.gif", "no-such-folder/x.png", "."])
def test_table_plot_refuses_a_file_it_cannot_write(tmp_path, cli, monkeypatch, target):
    monkeypatch.chdir(tmp_path)
    code, _, err = cli("table", "piston-path", "--rod-ratio", "5", "--plot", target)
    assert code == 2 and len(err.splitlines()) == 1 and "Traceback" not in err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("argv", [
    ("list",),
    ("check", "crank", "--parts", "6"),
    ("table", "crank-angle", "--rod-ratio", "5"),
    ("errata", "--book", "mechanics"),
    ("bench", "--parts", "6"),
])
def test_every_command_that_prints_data_prints_json(cli, argv):
    code, out, err = cli(*argv, "--format", "json")
    assert code in ((0, 1) if argv[0] == "bench" else (0,)) and err == "", err   # bench: 1 for a missed target
    data = json.loads(out)
    assert data  # a list or an object with content
    code, alias, _ = cli(*argv, "--json")  # the older spelling stays an alias
    assert code == 0 and json.loads(alias).__class__ is data.__class__


def test_diff_prints_json(tmp_path, cli):
    a = tmp_path / "a.svg"
    a.write_text('<svg xmlns="http://www.w3.org/2000/svg"><circle id="p" cx="1" cy="1" r="1"/></svg>')
    code, out, _ = cli("diff", str(a), str(a), "--format", "json")
    assert code == 0 and isinstance(json.loads(out), (dict, list))


def test_table_json_holds_the_csv_rows(cli):
    _, text, _ = cli("table", "crank-angle", "--rod-ratio", "5", "--format", "csv")
    _, data, _ = cli("table", "crank-angle", "--rod-ratio", "5", "--format", "json")
    rows = list(csv.DictReader(io.StringIO(text)))
    assert [list(r) for r in json.loads(data)] == [list(r) for r in rows]
    assert all(abs(float(r["omega_exact_deg"]) - d["omega_exact_deg"]) < 1e-12 for r, d in zip(rows, json.loads(data)))


def test_list_is_an_aligned_table_of_names_and_titles(cli):
    from construct import get, names

    _, out, _ = cli("list")
    lines = out.splitlines()
    assert [l.split()[0] for l in lines] == names()
    column = {len(l) - len(l[len(l.split()[0]):].lstrip()) for l in lines}
    assert len(column) == 1  # the titles start in one column
    assert all(get(l.split()[0]).title.en in l and len(l) < 100 for l in lines)


def test_every_option_has_a_help_line_and_a_placeholder_that_names_its_quantity():
    import argparse

    from construct.cli.main import build_parser

    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    bare = []
    for command, p in sub.choices.items():
        for action in p._actions:
            if not action.option_strings or isinstance(action, argparse._HelpAction):
                continue
            if not action.help:
                bare.append(f"{command} {action.option_strings[0]}: no help")
            if action.nargs != 0 and action.choices is None and action.metavar in (None, action.dest.upper()):
                bare.append(f"{command} {action.option_strings[0]}: placeholder {action.metavar or action.dest.upper()}")
    assert not bare, bare


def test_replay_says_what_it_wrote_and_where_to_look(tmp_path, cli):
    """Not '0 frames written' after five files: the files, by name, and the page to open."""
    out = tmp_path / "c"
    code, _, err = cli("replay", "crank", "--parts", "3", "--out", out)
    assert code == 0 and "0 frames" not in err and f"open {out}/player.html" in err
    for name in ("final.svg", "protocol.json", "animated.svg", "player.html", "storyboard.svg"):
        assert name in err and (out / name).is_file()
    code, _, err = cli("replay", "crank", "--parts", "3", "--frames", "all", "--out", out)
    frames = len(list((out / "steps").glob("*.svg")))
    assert code == 0 and frames and f"{frames} frames in steps/" in err


def test_gallery_says_where_to_look(tmp_path, cli, small_plan):
    code, _, err = cli("gallery", "--out", tmp_path / "g")
    assert code == 0 and f"open {tmp_path / 'g' / 'index.html'}" in err and (tmp_path / "g" / "index.html").is_file()
    assert "styled entries" not in err and "gallery: 1 figure (1 plate, 1 step-by-step player)" in err
