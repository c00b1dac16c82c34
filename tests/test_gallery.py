"""The gallery: every registered construction at its book parameters, atomic and idempotent."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import construct.gallery as gallery
from construct.constructions import get, names
from construct.kernel.errors import InvalidParameter
from construct.kernel.geometry import Length

REPO = Path(__file__).resolve().parents[1]


@pytest.fixture
def small_plan(monkeypatch):
    """A gallery of one small figure, so that the tests stay quick."""
    monkeypatch.setattr(gallery, "gallery_plan", lambda: [("crank", {"parts": 3, "rod_ratio": 4.0})])


def _tree(root: Path) -> dict[str, bytes]:
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*")) if p.is_file()}


def test_plan_covers_every_registered_construction_and_book_parameter_set():
    plan = gallery.gallery_plan()
    for name in names():
        c = get(name)
        for params in c.book_params or ({},):
            assert (name, dict(params)) in plan


def test_gallery_entry_files_and_index(small_plan, tmp_path):
    out = tmp_path / "g"
    entries = gallery.build_gallery(out)
    assert [(e["construction"], e["style"]) for e in entries] == [("crank", "historical"), ("crank", "teaching")]
    fig = get("crank").figure(parts=3, rod_ratio=4.0)
    for e in entries:
        for f in e["files"]:
            assert (out / f).is_file(), f
        style_files = {Path(f).name for f in e["files"] if f"/{e['style']}/" in f}
        first = e["params"] == next(p for n, p in gallery.gallery_plan() if n == e["construction"])
        expected = {"historical": {"final.svg"},
                    "teaching": {"final.svg", "player.html"} if first else {"final.svg"}}[e["style"]]
        assert style_files == expected
    # no standalone frames: the teaching figure is layered, a group for every step that draws something
    assert not list(out.rglob("steps"))
    final = (out / "crank-parts-3-rod-ratio-4" / "teaching" / "final.svg").read_text(encoding="utf-8")
    drawn = {s.index for s in fig.protocol.steps
             if any(not isinstance(fig.replay.get(o), Length) for o in s.outputs if fig.replay.get(o) is not None)}
    assert {int(k) for k in re.findall(r'data-step="(\d+)"', final)} == drawn
    readme = (out / "README.md").read_text(encoding="utf-8")
    # every picture the index shows exists (the plate), with its caption and links to the player and the checks
    pics = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", readme)
    links = re.findall(r"\]\(([^)]+)\)", readme)
    assert pics == ["crank-parts-3-rod-ratio-4/historical/final.svg"] and all((out / p).is_file() for p in links)
    assert "Kolbenwege aus dem Kurbelkreis" in readme and "crank-parts-3-rod-ratio-4/teaching/player.html" in links
    # the method's figures are the checks page's, not the index's
    assert "steps by provenance" not in readme and "- steps by provenance: exact " in (
        out / "crank-parts-3-rod-ratio-4" / "checks.md").read_text(encoding="utf-8")
    html = (out / "index.html").read_text(encoding="utf-8")
    assert all(f'src="{p}"' in html for p in pics) and "steps by provenance" not in html
    assert "Fig. 1." in (out / "crank-parts-3-rod-ratio-4" / "historical" / "final.svg").read_text()


def test_gallery_is_idempotent(small_plan, tmp_path, monkeypatch):
    # the live player's data is held to the same bytes on its own (tests/test_live.py), at a
    # fraction of a gallery build's sweep
    monkeypatch.setattr(gallery, "LIVE_PLAYERS", ())
    out = tmp_path / "g"
    gallery.build_gallery(out)
    first = _tree(out)
    gallery.build_gallery(out)
    assert _tree(out) == first
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".construct-staging")]


def test_failed_build_leaves_the_previous_gallery(small_plan, tmp_path, monkeypatch):
    monkeypatch.setattr(gallery, "LIVE_PLAYERS", ())  # the folder is the point (idempotence covers the live player)
    out = tmp_path / "g"
    gallery.build_gallery(out)
    before = _tree(out)

    def broken(*args, **kwargs):
        raise RuntimeError("renderer broke half way")

    monkeypatch.setattr(gallery, "_index_html", broken)  # fails after every figure has been written
    with pytest.raises(RuntimeError):
        gallery.build_gallery(out)
    assert _tree(out) == before
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".construct-staging")]


def test_committed_gallery_has_every_construction():
    """The committed gallery/ is built by `construct gallery` from the current registry."""
    root = REPO / "gallery"
    if not root.is_dir():
        pytest.skip("no committed gallery in this checkout")
    readme = (root / "README.md").read_text(encoding="utf-8")
    seen = set()
    for name, params in gallery.gallery_plan():
        slug = gallery.entry_slug(name, params)
        assert (root / slug / "historical" / "final.svg").is_file(), slug
        assert f"({slug}/historical/final.svg)" in readme, slug
        # a construction's first figure is there whole (every step golden, its player, its protocol); its
        # further book figures as plates with their checks
        first = name not in seen
        seen.add(name)
        for whole in ("teaching/final.svg", "teaching/player.html", "protocol.json"):
            # (a construction whose given changes its steps has a player for each book figure: a switch)
            here = first or (name in gallery.SWITCHES and whole != "protocol.json")
            assert (root / slug / whole).is_file() == here, (slug, whole)
        assert (root / slug / "checks.json").is_file(), slug


def test_the_gallery_stays_small_enough_to_commit():
    """25 MB (10**6 bytes each), the budget `construct bench --outputs` also reports (15 MB before the live
    players: issue 27 grants them 10 more), each player at most 2 MB, and the LaTeX example's two TikZ plates
    (latex/, 71 kB: Abb. 1055's force curves are 2,000 points) beside it, at most 0.1 MB."""
    root = REPO / "gallery"
    if not root.is_dir():
        pytest.skip("no committed gallery in this checkout")
    latex = sum(p.stat().st_size for p in (root / "latex").rglob("*") if p.is_file())
    assert latex <= 0.1e6
    assert sum(p.stat().st_size for p in root.rglob("*") if p.is_file()) - latex <= 25e6
    players = {p.parent.parent.name: p.stat().st_size for p in root.glob("*/teaching/player.html")}
    assert players and max(players.values()) <= 2e6, players


def test_gallery_plates_also_for_print(small_plan, tmp_path):
    """``construct gallery --format pdf,tikz``: each plate also at its final size, beside its final.svg."""
    pytest.importorskip("pypdf")
    out = tmp_path / "g"
    entries = gallery.build_gallery(out, formats=("svg", "pdf", "tikz"))
    plate = out / "crank-parts-3-rod-ratio-4" / "historical"
    assert {p.name for p in plate.iterdir()} == {"final.svg", "final.pdf", "final.tikz", "final.tex"}
    assert {"final.pdf"} <= {Path(f).name for e in entries if e["style"] == "historical" for f in e["files"]}
    assert not list((out / "crank-parts-3-rod-ratio-4" / "teaching").glob("final.pdf"))
    with pytest.raises(InvalidParameter, match="unknown format"):
        gallery.build_gallery(tmp_path / "h", formats=("png",))


def test_the_committed_gallery_names_the_books_and_never_a_seed():
    """Pages, captions and metadata cite author and title; the errata pages are named after the books."""
    root = REPO / "gallery"
    if not root.is_dir():
        pytest.skip("no committed gallery in this checkout")
    assert sorted(p.name for p in root.glob("errata-*.html")) == [
        "errata-anhang-ii.html", "errata-baumann.html", "errata-handbook.html", "errata-mechanics.html"]
    seed = re.compile(r"\bseeds?\b", re.I)
    said = []
    for p in sorted(root.rglob("*")):
        if p.suffix not in (".html", ".md", ".svg", ".json"):
            continue
        text = p.read_text(encoding="utf-8")
        # what a reader (or a reader's tool) meets: everything but the scripts' code and encoded data
        text = re.sub(r"<script\b.*?</script>", "", text, flags=re.S)
        said += [f"{p.relative_to(root)}: {m.group(0)!r}" for m in seed.finditer(text)]
    assert not said, said[:10]
    index = (root / "index.html").read_text(encoding="utf-8")
    assert "A. Baumann" in index and "Schwungradgewichte" in index and "seed" not in index.lower()


_MALLINFO = '''
import ctypes, json, sys
import numpy as np

class Mallinfo2(ctypes.Structure):  # glibc's struct mallinfo2 (malloc.h)
    _fields_ = [(name, ctypes.c_size_t) for name in
                ("arena", "ordblks", "smblks", "hblks", "hblkhd", "usmblks", "fsmblks", "uordblks", "fordblks",
                 "keepcost")]

libc = ctypes.CDLL(None)
libc.mallinfo2.restype = Mallinfo2
kept = False
if sys.argv[1] == "kept":
    from construct.gallery import _keep_freed_memory
    kept = _keep_freed_memory()
before = libc.mallinfo2().hblks
blocks = [np.ones(2**20 // 8 * (k + 1)) for k in range(4)]  # 1 to 4 MiB each
mapped = libc.mallinfo2().hblks - before
top = libc.mallinfo2().arena
del blocks
print(json.dumps({"kept": kept, "mapped": mapped, "kept_after_free": libc.mallinfo2().arena >= top}))
'''


@pytest.mark.skipif(not gallery._glibc(), reason="the C allocator is glibc's only on glibc")
def test_a_worker_keeps_freed_memory_for_its_next_blocks():
    """A gallery worker (_worker_init) has glibc serve blocks of megabytes from its heap and keep what is freed
    (_keep_freed_memory), where by default each such block is mapped afresh and given back when freed; asked of
    the allocator itself (mallinfo2) in a process of its own, as a worker is."""
    import json
    import subprocess
    import sys

    def run(how: str) -> dict:
        done = subprocess.run([sys.executable, "-c", _MALLINFO, how], capture_output=True, text=True, check=True)
        return json.loads(done.stdout)

    default, kept = run("default"), run("kept")
    assert not default["kept"] and default["mapped"] >= 3  # each block its own mapping (128 KiB threshold)
    assert kept["kept"] and kept["mapped"] == 0  # from the heap ...
    assert kept["kept_after_free"]  # ... which keeps them when they are freed
    assert gallery._MALLOC_KEPT[0][1] <= 32 * 2**20  # glibc refuses a larger threshold (mallopt returns 0)
