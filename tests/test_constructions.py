"""The registry (construct/constructions/__init__.py): a construction knows itself, and adding one is one module.

Expectations come from the source texts (which text and figure each construction follows, read from
../shared/seeds by the notation tests), from the README's own example run as a user runs it, and from
the render layer's source (which must name no construction).
"""

from __future__ import annotations

import ast
import re
import warnings
from pathlib import Path

import pytest

from construct.constructions import Construction, get, names, register
from construct.constructions.phrases import BOOKS
from construct.kernel.protocol import Caption

ROOT = Path(__file__).resolve().parents[1]


def _readme_module() -> str:
    """The first Python block after the ``<!-- plugin-construction -->`` marker of the README."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    after = text[text.index("<!-- plugin-construction -->"):]
    return re.search(r"```python\n(.*?)```", after, re.S).group(1)


def test_every_construction_cites_the_texts_it_follows():
    for name in names():
        c = get(name)
        # a book, or a section of one cited by its own title (four-stroke: the handbook's combustion engines)
        assert c.cites and all(cite.book.key in BOOKS and cite.figure for cite in c.cites), name
        assert all(cite.book.number == BOOKS[cite.book.key].number for cite in c.cites), name
        assert c.wording is not None, name  # its givens as its book writes them


def test_the_render_layer_names_no_construction():
    """No table keyed by a construction's name below the constructions: render reads what it needs off them."""
    known = set(names())
    found = []
    for path in sorted((ROOT / "construct" / "render").rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Constant) and isinstance(node.value, str) and node.value in known:
                found.append(f"{path.name}:{node.lineno} {node.value!r}")
    assert not found, found


def test_the_readmes_construction_is_one_module_found_by_its_entry_point(tmp_path, cli_process):
    """The README's module, installed with an entry point, is listed, checked and captioned by the command line."""
    (tmp_path / "crosshead.py").write_text(_readme_module(), encoding="utf-8")
    dist = tmp_path / "crosshead_plugin-0.1.dist-info"
    dist.mkdir()
    (dist / "METADATA").write_text("Metadata-Version: 2.1\nName: crosshead-plugin\nVersion: 0.1\n")
    (dist / "entry_points.txt").write_text("[construct.constructions]\ncrosshead = crosshead\n")
    out = tmp_path / "out"
    # a fresh process finds the entry point as it starts (the three commands share it)
    listed, checked, replayed = cli_process(
        ["list"], ["check", "crosshead-at-90", "--rod-ratio", "4"],
        ["replay", "crosshead-at-90", "--style", "historical", "--out", out],
        env={"PYTHONPATH": str(tmp_path), "PYTHONDONTWRITEBYTECODE": "1"}, cwd=tmp_path)
    assert re.search(r"^crosshead-at-90\s+The crosshead at 90° crank$", listed.out.decode(), re.M), listed.out
    assert checked.code == 0 and "1 of 1 checks pass" in checked.out.decode(), checked.out + checked.err
    assert replayed.code == 0, replayed.err
    svg = (out / "final.svg").read_text(encoding="utf-8")
    assert "The crosshead at 90° crank. r/L = 1/5. — after J. Doe, The slider crank, p. 3." in svg
    assert "Kreuzkopf bei 90° Kurbelstellung. r/L = 1/5. — nach J. Doe, Kurbeltrieb, p. 3." in svg


def test_the_old_places_of_plate_help_and_validator_still_work_and_warn():
    crank = get("crank")
    with pytest.warns(DeprecationWarning, match="plate="):
        c = Construction("old-style", Caption("a", "a"), "", crank.build, crank.checks, crank.defaults,
                         extra={"plate": crank.plate, "help": {"r": "the crank radius"}})
    assert c.plate is crank.plate and c.help == {"r": "the crank radius"}
    calls = []
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        mine = Construction("old-style", Caption("a", "a"), "", crank.build, crank.checks, crank.defaults)
    with pytest.warns(DeprecationWarning, match="validator="):
        registered = register(mine, validate=calls.append)
    try:
        registered.validate({"r": 1.0})
        assert calls == [{"r": 1.0}] and get("old-style") is registered
    finally:
        from construct import constructions

        del constructions._REGISTRY["old-style"]  # the registry is the process's: leave it as found
