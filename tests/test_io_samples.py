"""``construct samples FOLDER``: the shipped sample cards written into a folder, never over a user's file."""

from __future__ import annotations

import csv
import fnmatch
import io
import os
import tomllib
from pathlib import Path

import pytest

import construct.io.staging as staging
from construct.io.samples import SAMPLES, write_samples
from construct.io.staging import STAGING_PREFIX

REPO = Path(__file__).resolve().parents[1]
CARDS = REPO / "construct" / "data" / "cards"
NAMES = ["card.csv", "crank.csv", "hp.csv", "lp.csv", "karte.csv"]   # what the README's examples read


def refused(run) -> bool:
    """Exit 2, one line on stderr, no traceback."""
    lines = run.err.strip().splitlines()
    return run.code == 2 and len(lines) == 1 and lines[0].startswith("construct: error:")


def tree(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def test_the_samples_are_written_as_shipped(tmp_path, cli):
    run = cli("samples", tmp_path / "examples")
    assert run.code == 0, run.err
    assert tree(tmp_path) == {f"examples/{name}": (CARDS / name).read_bytes() for name in NAMES}
    assert all(name in run.out for name in NAMES) and "construct check indicator-diagram --indicator" in run.out


def test_the_samples_are_what_the_readme_says():
    """The README's five cards, and karte.csv is card.csv as a German spreadsheet writes it (read here by hand)."""
    assert list(SAMPLES) == NAMES and sorted(p.name for p in CARDS.iterdir()) == sorted(NAMES)
    karte = (CARDS / "karte.csv").read_bytes()
    assert karte.startswith(b"\xef\xbb\xbf") and b"\r\n" in karte
    german = list(csv.reader(io.StringIO(karte.decode("utf-8-sig"), newline=""), delimiter=";"))
    plain = list(csv.reader(io.StringIO((CARDS / "card.csv").read_text(encoding="utf-8"))))
    assert german[0] == ["x", "p"] and plain[0] == ["x", "p"]
    assert [[float(v.replace(",", ".")) for v in row] for row in german[1:]] == \
           [[float(v) for v in row] for row in plain[1:]]


def test_a_pip_installed_user_has_them_too():
    """Every file under construct/data is package data (pyproject.toml), so a wheel ships it."""
    globs = tomllib.loads((REPO / "pyproject.toml").read_text())["tool"]["setuptools"]["package-data"]["construct"]
    shipped = [p.relative_to(REPO / "construct").as_posix() for p in (REPO / "construct" / "data").rglob("*")
               if p.is_file()]
    assert shipped and all(any(fnmatch.fnmatch(f, g) for g in globs) for f in shipped), (shipped, globs)


def test_a_second_run_changes_nothing(tmp_path, cli):
    assert cli("samples", tmp_path).code == 0
    before = {p.name: p.stat().st_mtime_ns for p in tmp_path.iterdir()}
    run = cli("samples", tmp_path)
    assert run.code == 0 and "already holds" in run.out
    assert {p.name: p.stat().st_mtime_ns for p in tmp_path.iterdir()} == before


def test_missing_cards_are_added_beside_the_users_files(tmp_path, cli):
    (tmp_path / "mine.csv").write_text("x,p\n")
    (tmp_path / "hp.csv").write_bytes((CARDS / "hp.csv").read_bytes())
    run = cli("samples", tmp_path)
    assert run.code == 0, run.err
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(NAMES + ["mine.csv"])
    assert (tmp_path / "mine.csv").read_text() == "x,p\n"


@pytest.mark.parametrize("kind", ["differs", "folder", "link"])
def test_a_users_file_of_a_samples_name_is_never_overwritten(kind, tmp_path, cli):
    """A card.csv of the user's (or a folder or a link under that name): refused, and nothing else written
    either (no other sample, no staging)."""
    if kind == "differs":
        (tmp_path / "card.csv").write_text("x,p\n0,1\n")
    elif kind == "folder":
        (tmp_path / "card.csv").mkdir()
    else:
        (tmp_path / "card.csv").symlink_to(CARDS / "card.csv")   # the same bytes, but a link is not a copy
    before = tree(tmp_path), sorted(os.listdir(tmp_path))
    run = cli("samples", tmp_path)
    assert refused(run) and "card.csv" in run.err and "refusing to overwrite" in run.err, run.err
    assert (tree(tmp_path), sorted(os.listdir(tmp_path))) == before


def test_two_differing_files_are_named_together(tmp_path, cli):
    for name in ("hp.csv", "lp.csv"):
        (tmp_path / name).write_text("x,p\n")
    run = cli("samples", tmp_path)
    assert refused(run) and "hp.csv, lp.csv" in run.err and "they differ" in run.err


@pytest.mark.parametrize("where", ["a file", "under a file", "empty"])
def test_a_bad_folder_is_one_line(where, tmp_path, cli):
    (tmp_path / "f").write_text("mine")
    target = {"a file": tmp_path / "f", "under a file": tmp_path / "f" / "examples", "empty": ""}[where]
    run = cli("samples", target)
    assert refused(run), run.err
    assert sorted(os.listdir(tmp_path)) == ["f"] and (tmp_path / "f").read_text() == "mine"


def test_a_write_that_fails_halfway_leaves_nothing(tmp_path, cli, monkeypatch):
    """The disk fills at the third card: no card written, the folder this run made removed again."""
    real, moved = os.replace, []

    def failing(src, dst):
        if STAGING_PREFIX in str(src):
            moved.append(dst)
            if len(moved) == 3:
                raise OSError(28, "No space left on device", str(dst))
        return real(src, dst)

    monkeypatch.setattr(staging.os, "replace", failing)
    run = cli("samples", tmp_path / "new" / "examples")
    assert refused(run) and "No space left on device" in run.err and "nothing was written" in run.err, run.err
    assert len(moved) == 3 and os.listdir(tmp_path) == []


def test_the_library_call_names_what_it_wrote(tmp_path):
    (tmp_path / "lp.csv").write_bytes((CARDS / "lp.csv").read_bytes())
    assert write_samples(tmp_path) == ["card.csv", "crank.csv", "hp.csv", "karte.csv"]
    assert write_samples(tmp_path) == []
