"""Goldens: ``construct verify`` on a small gallery-like tree written by the real renderer.

The goldens are written by :func:`write_replay` (every step frame, the final
figure, the protocol) plus an HTML page and a PNG, then edited by hand the
way a regression or a harmless reformatting would edit them.  The expected
findings come from the edit itself (which element, which step, by how much),
never from a previous run of the code.
"""

from __future__ import annotations

import json
import re
import shutil
import struct
import xml.etree.ElementTree as ET
import zlib
from pathlib import Path

import pytest

import construct.regress.verify as verify_module
from construct.cli.main import main
from construct.constructions import get
from construct.render.output import write_replay
from construct.regress.verify import DEFAULT_TOLERANCE, locate, verify

FIGURE = "crank-6"
FRAME = f"{FIGURE}/steps/005.svg"  # step 5 of the crank: the crank circle about O is drawn
POINT = "s0001-O"  # the given point O, drawn as a circle in every frame


def _png(width: int, height: int, shade: int) -> bytes:
    """A grey PNG, written by hand (so that the test does not depend on a renderer)."""
    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    raw = b"".join(b"\x00" + bytes([shade]) * width for _ in range(height))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 0, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def build_small_gallery(out: Path) -> None:
    """A gallery-like tree: one construction with all its frames, an index page, a storyboard."""
    c = get("crank")
    write_replay(c, c.figure(parts=6), out / FIGURE, frames="all")
    (out / "index.html").write_text("<!doctype html>\n<title>gallery</title>\n<p>crank, 6 parts</p>\n",
                                    encoding="utf-8")
    (out / FIGURE / "storyboard.png").write_bytes(_png(8, 4, 200))


@pytest.fixture(scope="module")
def pristine(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The goldens as ``verify --update`` writes them: the builder's tree and its manifest."""
    g = tmp_path_factory.mktemp("pristine") / "gallery"
    verify(g, builder=build_small_gallery, update=True)
    return g


def _files(root: Path) -> list[Path]:
    """The goldens, without the manifests (.construct-manifest.json: what wrote them, not what is compared)."""
    return [p for p in root.rglob("*") if p.is_file() and not p.name.startswith(".construct-")]


@pytest.fixture()
def goldens(tmp_path: Path, pristine: Path) -> Path:
    """A fresh copy of the goldens for each test to edit."""
    g = tmp_path / "gallery"
    shutil.copytree(pristine, g)
    return g


@pytest.fixture()
def rebuild(pristine: Path):
    """The builder handed to verify: the same tree as a real rebuild (checked in the first test),
    copied instead of re-rendered so that each test takes a moment, not seconds."""
    return lambda out: shutil.copytree(pristine, out)


def _move_circle(svg: str, elem_id: str, dx: float) -> tuple[str, float]:
    """Move the circle with *elem_id* by *dx* in x; return the new text and the old cx."""
    m = re.search(r'<circle\b[^>]*\bid="' + re.escape(elem_id) + r'"[^>]*/>', svg)
    assert m, f"{elem_id} not in the frame"
    cx_m = re.search(r'cx="([^"]+)"', m.group())
    old = float(cx_m.group(1))
    elem = m.group().replace(cx_m.group(), f'cx="{old + dx:.3f}"')
    return svg[:m.start()] + elem + svg[m.end():], old


def test_clean_gallery_is_equal(goldens: Path) -> None:
    result = verify(goldens, builder=build_small_gallery)
    assert result.equal, result.report()
    # Every file was looked at: 77 frames, final, protocol, storyboard, index, and
    # whatever else the renderer writes (animation, player), counted independently.
    files = _files(goldens)
    assert len([p for p in files if p.parent.name == "steps"]) == 77
    assert result.compared == len(files)
    assert result.png_by_size == 1
    assert f"all {len(files)} files equal" in result.summary()


def test_point_moved_by_a_hundredth_is_caught_and_named(goldens: Path, rebuild) -> None:
    path = goldens / FRAME
    text, old = _move_circle(path.read_text(encoding="utf-8"), POINT, 0.01)
    path.write_text(text, encoding="utf-8")
    result = verify(goldens, builder=rebuild)
    assert not result.equal
    assert [d.path for d in result.differences] == [FRAME]  # only that frame, not the other 76
    d = result.differences[0]
    assert (d.figure, d.step, d.status, d.kind) == (FIGURE, 5, "changed", "svg")
    report = result.report()
    assert f"{FIGURE} step 5 ({FRAME}): 1 change" in report
    line = next(x for x in report.splitlines() if POINT in x)
    assert "moved" in line and "by 0.01" in line
    assert "files differ (1 changed, 0 missing, 0 extra) in 1 figure" in report
    assert re.search(r"construct verify: 1 of \d+ files differ", report)


def test_rounding_noise_is_forgiven_but_not_at_tolerance_zero(goldens: Path, rebuild) -> None:
    # 0.001 is a last-digit flip of a three-decimal writer: below the default
    # tolerance, which must also stay under half of the 0.01 the issue demands
    # to catch (read back from text, 0.01 may be 0.00999...).
    assert 0.001 * 2 ** 0.5 < DEFAULT_TOLERANCE < 0.005
    path = goldens / FRAME
    path.write_text(_move_circle(path.read_text(encoding="utf-8"), POINT, 0.001)[0], encoding="utf-8")
    assert verify(goldens, builder=rebuild).equal
    strict = verify(goldens, builder=rebuild, tolerance=0.0)
    assert [(d.step, d.kind) for d in strict.differences] == [(5, "svg")]


def _reformat(svg_text: str) -> str:
    """The same drawing written differently: attributes reversed, numbers in another spelling."""
    ET.register_namespace("", "http://www.w3.org/2000/svg")
    ET.register_namespace("xlink", "http://www.w3.org/1999/xlink")
    ET.register_namespace("ev", "http://www.w3.org/2001/xml-events")
    root = ET.fromstring(svg_text)

    def respell(value: str) -> str:
        # 722.875 -> 7.228750e+02 and 2 -> 2.000000e+00: the same numbers, no digit kept in place
        return re.sub(r"(?<![\w#.])-?\d+(?:\.\d+)?(?![\w.])", lambda m: format(float(m.group()), ".6e"), value)

    def respell_path(d: str) -> str:
        # Arc flags must stay 0/1, so a path only gets trailing zeros and commas.
        return re.sub(r"(\d+\.\d+) (?=-?\d)", r"\g<1>000,", d)

    for elem in root.iter():
        items = list(elem.attrib.items())
        elem.attrib.clear()
        for k, v in reversed(items):
            if k == "d":
                v = respell_path(v)
            elif k in ("x", "y", "cx", "cy", "r", "x1", "y1", "x2", "y2", "width", "height", "viewBox",
                       "stroke-width"):
                v = respell(v)
            elem.set(k, v)
    return ET.tostring(root, encoding="unicode")


def test_reformatted_golden_is_equal(goldens: Path, rebuild) -> None:
    for rel in (FRAME, f"{FIGURE}/final.svg"):
        path = goldens / rel
        before = path.read_text(encoding="utf-8")
        after = _reformat(before)
        assert after != before and "e+02" in after  # the edit really rewrote the text
        path.write_text(after, encoding="utf-8")
    assert "000," in after  # the final figure's arcs were respelled too
    proto = goldens / FIGURE / "protocol.json"
    data = json.loads(proto.read_text(encoding="utf-8"))
    proto.write_text(json.dumps(data, indent=4, sort_keys=True), encoding="utf-8")
    result = verify(goldens, builder=rebuild)
    assert result.equal, result.report()


def test_reformatted_and_moved_golden_names_only_the_move(goldens: Path, rebuild) -> None:
    path = goldens / FRAME
    moved, _ = _move_circle(path.read_text(encoding="utf-8"), POINT, -0.01)
    path.write_text(_reformat(moved), encoding="utf-8")
    d, = verify(goldens, builder=rebuild).differences
    (change,) = d.changes
    assert d.total == 1 and change.key == POINT and change.kind == "moved" and "by 0.01" in change.line()


def test_protocol_point_moved_is_named(goldens: Path, rebuild) -> None:
    proto = goldens / FIGURE / "protocol.json"
    data = json.loads(proto.read_text(encoding="utf-8"))
    data["objects"]["O"]["x"] += 0.01
    proto.write_text(json.dumps(data, indent=1), encoding="utf-8")
    d, = verify(goldens, builder=rebuild).differences
    assert (d.path, d.kind, d.step) == (f"{FIGURE}/protocol.json", "protocol", None)
    assert any(c.key == "O" and " O:" in c.line() and "moved by 0.01" in c.line() for c in d.changes), d.lines()


def test_missing_extra_text_and_png(goldens: Path, rebuild) -> None:
    (goldens / FIGURE / "steps" / "077.svg").unlink()  # the rebuild writes it: extra
    (goldens / FIGURE / "steps" / "078.svg").write_text("<svg xmlns='http://www.w3.org/2000/svg'/>")  # missing
    index = goldens / "index.html"
    index.write_text(index.read_text(encoding="utf-8").replace("6 parts", "8 parts"), encoding="utf-8")
    (goldens / FIGURE / "storyboard.png").write_bytes(_png(8, 5, 200))  # another size
    result = verify(goldens, builder=rebuild)
    found = {d.path: d for d in result.differences}
    assert sorted(found) == ["crank-6/steps/077.svg", "crank-6/steps/078.svg", "crank-6/storyboard.png",
                             "index.html"]
    assert found["crank-6/steps/077.svg"].status == "extra"
    assert found["crank-6/steps/078.svg"].status == "missing"
    assert "image 8x5 -> 8x4" in found["crank-6/storyboard.png"].changes[0].line()
    text = "\n".join(found["index.html"].lines())
    assert "-<p>crank, 8 parts</p>" in text and "+<p>crank, 6 parts</p>" in text
    report = result.report()
    assert "crank-6 step 77 (crank-6/steps/077.svg): extra" in report
    assert "crank-6 step 78 (crank-6/steps/078.svg): missing" in report
    assert "(gallery) index.html (index.html): 1 change" in report


def test_png_pixels_are_not_compared(goldens: Path, rebuild) -> None:
    (goldens / FIGURE / "storyboard.png").write_bytes(_png(8, 4, 10))  # same size, other pixels
    result = verify(goldens, builder=rebuild)
    assert result.equal and "PNG compared by image size only" in result.summary()


def test_update_rewrites_the_goldens_as_a_whole(goldens: Path, rebuild) -> None:
    path = goldens / FRAME
    path.write_text(_move_circle(path.read_text(encoding="utf-8"), POINT, 0.5)[0], encoding="utf-8")
    (goldens / FIGURE / "steps" / "077.svg").unlink()  # a golden the rebuild writes again
    result = verify(goldens, builder=rebuild, update=True)
    assert {d.path for d in result.differences} == {FRAME, f"{FIGURE}/steps/077.svg"} and result.updated
    assert "rewritten" in result.summary()
    assert not [p for p in goldens.parent.iterdir() if p.name.startswith(".construct-")]  # no leftovers
    assert verify(goldens, builder=rebuild).equal


def test_update_refuses_goldens_beside_a_file_it_did_not_write(goldens: Path, rebuild) -> None:
    """A file put among the goldens is not ours; --update lists it and changes nothing."""
    from construct.kernel.errors import OutputError

    (goldens / "stale.md").write_text("not written by the builder\n")
    path = goldens / FRAME
    path.write_text(_move_circle(path.read_text(encoding="utf-8"), POINT, 0.5)[0], encoding="utf-8")
    before = {p: p.read_bytes() for p in _files(goldens)}
    with pytest.raises(OutputError, match="stale.md"):
        verify(goldens, builder=rebuild, update=True)
    assert {p: p.read_bytes() for p in _files(goldens)} == before


def test_update_creates_missing_goldens(tmp_path: Path, rebuild) -> None:
    target = tmp_path / "new" / "gallery"
    result = verify(target, builder=rebuild, update=True)
    files = _files(target)
    assert len(result.differences) == len(files) >= 78 and all(d.status == "extra" for d in result.differences)
    assert verify(target, builder=rebuild).equal


def test_locate() -> None:
    assert locate("crank-k5/historical/steps/0007.svg") == ("crank-k5/historical", 7)
    assert locate("crank-k5/steps/notes.txt") == ("crank-k5/steps", None)


def test_cli_exit_codes(goldens: Path, rebuild, monkeypatch: pytest.MonkeyPatch,
                        capsys: pytest.CaptureFixture) -> None:
    monkeypatch.setattr(verify_module, "default_builder", rebuild)
    assert main(["verify", "--gallery", str(goldens)]) == 0
    assert re.search(r"all \d+ files equal", capsys.readouterr().out)
    path = goldens / FRAME
    path.write_text(_move_circle(path.read_text(encoding="utf-8"), POINT, 0.01)[0], encoding="utf-8")
    assert main(["verify", "--gallery", str(goldens)]) == 1
    out = capsys.readouterr().out
    assert f"{FIGURE} step 5" in out and POINT in out
    assert main(["verify", "--gallery", str(goldens), "--update"]) == 0
    assert main(["verify", "--gallery", str(goldens)]) == 0
    capsys.readouterr()
    assert main(["verify", "--gallery", str(goldens / "nothing")]) == 2
    assert "does not exist" in capsys.readouterr().err
    assert main(["verify", "--gallery", str(goldens / "index.html")]) == 2
    assert main(["verify", "--gallery", str(goldens), "--tolerance", "-1"]) == 2
