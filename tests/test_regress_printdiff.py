"""construct diff and verify for printed plates: two TikZ pictures or two PDFs, by named point."""

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from construct.constructions import get
from construct.regress.printdiff import PrintDiffError, diff_pdf, diff_tikz_text
from construct.regress.verify import compare_file
from construct.render.output import print_plate
from construct.render.tikz import tikz_picture

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def crank_tikz():
    c = get("crank")
    return tikz_picture(print_plate(c.figure(parts=9), construction=c))


def moved(text: str, name: str, dx: float) -> str:
    """*text* with the named point *name* moved by *dx* units."""
    def shift(m):
        return f"\\coordinate ({name}) at ({float(m[1]) + dx:.5f},"
    return re.sub(rf"\\coordinate \({name}\) at \(([-0-9.]+),", shift, text)


def test_a_moved_point_is_named_with_its_distance_on_the_page(crank_tikz):
    mm = float(re.search(r"x=([0-9.]+)mm", crank_tikz)[1])
    d = diff_tikz_text(crank_tikz, moved(crank_tikz, "X4", 0.001), "a", "b")
    assert [(c.kind, c.key) for c in d.changes] == [("moved", "X4")]
    assert d.changes[0].magnitude == pytest.approx(0.001 * mm, abs=1e-6)
    assert diff_tikz_text(crank_tikz, crank_tikz, "a", "b").equal


def test_points_added_and_removed_and_other_lines_changed(crank_tikz):
    b = crank_tikz.replace("\\coordinate (P3) at", "\\coordinate (P3x) at").replace("line width=0.8pt", "line width=0.7pt")
    kinds = {(c.kind, c.key) for c in diff_tikz_text(crank_tikz, b, "a", "b").changes}
    assert {("removed", "P3"), ("added", "P3x")} <= kinds
    assert any(k == "changed" and key.startswith("line ") for k, key in kinds)


def test_numbers_within_the_tolerance_are_equal(crank_tikz):
    """A number respelled or off by less than 0.001 mm on the page is no change (the picture's lines too)."""
    b = re.sub(r"delta angle=([-0-9.]+)", lambda m: f"delta angle={float(m[1]) + 1e-6:.7f}", crank_tikz)
    assert b != crank_tikz and diff_tikz_text(crank_tikz, b, "a", "b").equal


def test_something_that_names_no_point_cannot_be_compared_by_point():
    with pytest.raises(PrintDiffError, match="cannot be compared by named point"):
        diff_tikz_text("\\documentclass{article}", "\\documentclass{article}", "a", "b")


def test_pdfs_by_named_point(tmp_path):
    pytest.importorskip("pypdf")
    c = get("crank")
    a, b = tmp_path / "a.pdf", tmp_path / "b.pdf"
    c.figure(parts=6).pdf(a)
    c.figure(parts=6, rod_ratio=4.0).pdf(b)
    same = diff_pdf(a, a)
    assert same.equal and same.sizes[0] == 13  # O, the dead centres 0 and 6, crank positions 1-5, piston positions 1′-5′
    d = diff_pdf(a, b)
    assert {ch.key for ch in d.changes if ch.kind == "moved"} >= {"X1", "X2"}
    import cairosvg

    plain = tmp_path / "plain.pdf"
    cairosvg.svg2pdf(bytestring=c.figure(parts=3).svg().encode(), write_to=str(plain))
    with pytest.raises(PrintDiffError, match="names no point"):
        diff_pdf(a, plain)


def test_the_command_line_compares_tikz_files(tmp_path, crank_tikz):
    (tmp_path / "a.tikz").write_text(crank_tikz, encoding="utf-8")
    (tmp_path / "b.tikz").write_text(moved(crank_tikz, "P2", 0.01), encoding="utf-8")
    run = subprocess.run([sys.executable, "-m", "construct", "diff", str(tmp_path / "a.tikz"), str(tmp_path / "b.tikz")],
                         capture_output=True, text=True)
    assert run.returncode == 1 and "moved      P2 (point, matched by name)" in run.stdout
    run = subprocess.run([sys.executable, "-m", "construct", "diff", str(tmp_path / "a.tikz"), str(ROOT / "README.md")],
                         capture_output=True, text=True)
    assert run.returncode == 2 and run.stderr.count("\n") == 1


def test_verify_compares_a_golden_tikz_by_named_point(tmp_path, crank_tikz):
    golden, actual = tmp_path / "g.tikz", tmp_path / "a.tikz"
    golden.write_text(crank_tikz, encoding="utf-8")
    actual.write_text(moved(crank_tikz, "X2", 0.01), encoding="utf-8")
    found = compare_file("latex/crank.tikz", golden, actual)
    assert found is not None and found.kind == "tikz" and [c.key for c in found.changes] == ["X2"]
    shutil.copy(golden, actual)
    assert compare_file("latex/crank.tikz", golden, actual) is None
