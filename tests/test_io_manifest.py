"""What construct wrote into a folder (construct/io/manifest.py): its files and their hashes.

Expectations come from hashlib and the file system, worked out here, never from the manifest's own reading.
"""

from __future__ import annotations

import hashlib
import json

import pytest

from construct.io.manifest import (MANIFEST_NAME, changed_files, foreign_entries, read_manifest, recogniser,
                                   replaced_with_manifest, write_manifest)
from construct.kernel.errors import OutputError


def _folder(tmp_path):
    root = tmp_path / "out"
    (root / "steps").mkdir(parents=True)
    (root / "final.svg").write_text("<svg/>")
    (root / "steps" / "001.svg").write_text("<svg id='1'/>")
    return root


def test_the_manifest_lists_every_file_with_its_sha256(tmp_path):
    root = _folder(tmp_path)
    write_manifest(root, "replay")
    raw = json.loads((root / MANIFEST_NAME).read_text())
    listed = read_manifest(root, "replay")
    assert listed == {rel: hashlib.sha256((root / rel).read_bytes()).hexdigest()
                      for rel in ("final.svg", "steps/001.svg")}
    assert raw and read_manifest(root, "gallery") is None  # another writer's folder is not ours


def test_what_is_not_listed_is_foreign_and_what_changed_is_named(tmp_path):
    root = _folder(tmp_path)
    write_manifest(root, "replay")
    assert foreign_entries(root, "replay") == [] and changed_files(root, "replay") == []
    (root / "final.svg").write_text("<svg>edited</svg>")
    (root / "notes.txt").write_text("mine")
    (root / "empty").mkdir()
    assert changed_files(root, "replay") == ["final.svg"]
    assert sorted(foreign_entries(root, "replay")) == ["empty/ (an empty folder)", "notes.txt"]
    with pytest.raises(OutputError, match="notes.txt"):
        recogniser("replay")(root)


def test_a_folder_without_a_manifest_is_not_recognised(tmp_path):
    root = _folder(tmp_path)
    assert foreign_entries(root, "replay") is None and recogniser("replay")(root) is False


def test_a_replaced_folder_gets_its_writers_manifest_and_replaces_only_its_own(tmp_path):
    out = tmp_path / "replay"
    for text in ("one", "two"):
        with replaced_with_manifest(out, "replay", described="a test folder") as new:
            new.mkdir()
            (new / "final.svg").write_text(text)
        assert (out / "final.svg").read_text() == text and foreign_entries(out, "replay") == []
    (out / "notes.txt").write_text("mine")
    with pytest.raises(OutputError, match="notes.txt"):
        with replaced_with_manifest(out, "replay", described="a test folder") as new:
            new.mkdir()
    assert (out / "notes.txt").read_text() == "mine"  # nothing of the user's is lost
