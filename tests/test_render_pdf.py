"""The plate as PDF at its final size (construct.render.pdf), read back with a PDF library (pypdf):
the page's width, the fonts embedded, every line at 0.2 pt or more, only black on white, the named
points where the SVG plate has them."""

import math
import subprocess
import sys

import numpy as np
import pytest

pypdf = pytest.importorskip("pypdf")

from construct.constructions import get
from construct.kernel.errors import InvalidParameter, MissingDependency
from construct.render.output import plate_caption, scene_for
from construct.render.pdf import pdf_bytes
from construct.render.output import print_plate
from construct.render.page import PT_PER_MM, Sheet
from construct.render.styles import HISTORICAL
from construct.render.svg import render_svg


class Page:
    """What a PDF page draws, read from its content stream with the graphics state followed (q/Q/cm):
    every stroke with its width in points and its colour, every fill's colour, every closed path of curves
    alone (a circle) with its centre in points."""

    def __init__(self, reader, page):
        from pypdf.generic import ContentStream

        self.page = page
        self.strokes: list[tuple[float, tuple]] = []
        self.fills: list[tuple] = []
        self.circles: list[tuple[float, float]] = []
        ctm = np.eye(3)
        stack = []
        width, stroke, fill = 1.0, (0.0,), (0.0,)
        path: list[tuple[str, list]] = []
        for operands, op in ContentStream(page.get_contents(), reader).operations:
            op = op.decode()
            if op == "q":
                stack.append((ctm.copy(), width, stroke, fill))
            elif op == "Q":
                ctm, width, stroke, fill = stack.pop()
            elif op == "cm":
                a, b, c, d, e, f = map(float, operands)
                ctm = np.array([[a, b, 0], [c, d, 0], [e, f, 1]]) @ ctm
            elif op == "w":
                width = float(operands[0])
            elif op in ("RG", "G", "K"):
                stroke = tuple(float(v) for v in operands)
            elif op in ("rg", "g", "k"):
                fill = tuple(float(v) for v in operands)
            elif op in ("m", "l", "c", "re", "h"):
                path.append((op, [float(v) for v in operands]))
            elif op in ("S", "s", "f", "F", "f*", "B", "B*", "b", "b*", "n"):
                scale = math.sqrt(abs(np.linalg.det(ctm[:2, :2])))
                if op in ("S", "s", "B", "B*", "b", "b*"):
                    self.strokes.append((width * scale, stroke))
                if op not in ("S", "s", "n"):
                    self.fills.append(fill)
                curves = [args for kind, args in path if kind == "c"]
                # a circle: cairo closes two to four equal curves round its centre
                if len(curves) >= 2 and path[0][0] == "m" and {k for k, _ in path} <= {"m", "c", "h"}:
                    ends = np.array([[*args[4:6], 1.0] for args in curves]) @ ctm
                    self.circles.append(tuple(ends[:, :2].mean(axis=0)))
                path = []
            elif op in ("Tj", "TJ"):
                self.fills.append(fill)


def read(data: bytes):
    import io

    reader = pypdf.PdfReader(io.BytesIO(data))
    assert len(reader.pages) == 1
    return reader, reader.pages[0], Page(reader, reader.pages[0])


@pytest.fixture(scope="module")
def crank_pdf(tmp_path_factory):
    """The issue's command: the crank plate of 18 parts in the historical style, 120 mm wide, as PDF."""
    out = tmp_path_factory.mktemp("c") / "c"
    run = subprocess.run([sys.executable, "-m", "construct", "replay", "crank", "--parts", "18", "--style",
                          "historical", "--format", "pdf", "--width-mm", "120", "--out", str(out)],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert sorted(p.name for p in out.iterdir()) == [".construct-manifest.json", "final.pdf", "protocol.json"]
    return (out / "final.pdf").read_bytes()


def test_the_page_is_the_width_asked_for(crank_pdf):
    _, page, _ = read(crank_pdf)
    assert float(page.mediabox.width) / PT_PER_MM == pytest.approx(120.0, abs=0.01)
    assert float(page.mediabox.left) == 0.0 and float(page.mediabox.height) > 0


def test_its_fonts_are_embedded(crank_pdf):
    _, page, _ = read(crank_pdf)
    fonts = page["/Resources"]["/Font"]
    assert fonts, "the letters are set in a font"
    for name in fonts:
        font = fonts[name].get_object()
        if font["/Subtype"] == "/Type3":
            assert font["/CharProcs"]  # its glyphs are drawn in the file
            continue
        descriptor = (font["/DescendantFonts"][0].get_object() if font["/Subtype"] == "/Type0" else font)["/FontDescriptor"]
        assert any(k in descriptor for k in ("/FontFile", "/FontFile2", "/FontFile3")), font["/BaseFont"]


def test_every_line_is_at_least_a_fifth_of_a_point_and_black(crank_pdf):
    _, _, page = read(crank_pdf)
    inked = [(w, c) for w, c in page.strokes if c not in ((1.0,), (1.0, 1.0, 1.0))]  # white: the letters' halos
    assert len(inked) > 50
    assert min(w for w, _ in inked) >= 0.2 - 1e-6
    assert {c for _, c in inked} <= {(0.0,), (0.0, 0.0, 0.0)}
    assert set(page.fills) <= {(0.0,), (0.0, 0.0, 0.0), (1.0,), (1.0, 1.0, 1.0)}
    # the style's weights, in points, are what the page draws with
    widths = {round(w, 2) for w, _ in inked}
    assert {HISTORICAL.weights.heavy, HISTORICAL.weights.result, HISTORICAL.weights.thin} <= widths


def test_the_named_points_are_where_the_plate_draws_its_points(crank_pdf):
    """Each named destination stands at the centre of a point the page draws (within 0.01 mm)."""
    reader, page, drawn = read(crank_pdf)
    height = float(page.mediabox.height)
    dests = reader.named_destinations
    assert {"O", "D0", "X4", "P9"} <= set(dests)
    centres = np.array(drawn.circles)
    for name, d in dests.items():
        x, y = float(d["/Left"]), float(d["/Top"])
        nearest = np.hypot(centres[:, 0] - x, centres[:, 1] - y).min()
        assert nearest / PT_PER_MM < 0.01, (name, nearest)
    assert height > 0


def svg_points(svg: str) -> dict[str, tuple[float, float]]:
    """Every point marker of an SVG plate by its id: its centre (canvas units, y down)."""
    import re

    return {m[3]: (float(m[1]), float(m[2]))
            for m in re.finditer(r'<circle class="pt[^"]*" cx="([-0-9.]+)" cy="([-0-9.]+)" id="([^"]+)"', svg)}


def test_the_pdf_is_the_svg_plate_at_another_scale():
    """The named points of the PDF stand where the SVG plate (the gallery's, 960 units wide) has them,
    after the scale: one similarity maps all of them within 0.01 mm."""
    c = get("crank")
    fig = c.figure(parts=18)
    svg = render_svg(scene_for(c, fig, plate=True), style=HISTORICAL, caption=plate_caption(c, fig))
    at_svg = svg_points(svg)
    plate = print_plate(fig, construction=c)
    reader, page, _ = read(pdf_bytes(plate))
    dests = reader.named_destinations
    pairs = [(at_svg[p.mark.id], dests[p.name]) for p in plate.points()]
    assert len(pairs) == 37
    a = np.array([q for q, _ in pairs])
    # a destination's top is from the foot of the page: the SVG's y runs down from its head
    b = np.array([(float(d["/Left"]), float(page.mediabox.height) - float(d["/Top"])) for _, d in pairs]) / PT_PER_MM
    # the scale from the construction's units: the SVG's units per unit and the PDF's millimetres per unit
    from construct.render.svg import Drawing

    scale = plate.mm_per_unit / Drawing(scene_for(c, fig, plate=True), HISTORICAL).vp.scale
    moved = b - a * scale
    assert np.abs(moved - moved.mean(axis=0)).max() < 0.01


def test_outlined_letters_leave_no_font_in_the_file():
    c = get("crank")
    plate = print_plate(c.figure(parts=6), construction=c, sheet=Sheet(outline=True, caption="de"))
    _, page, drawn = read(pdf_bytes(plate))
    assert "/Font" not in page["/Resources"]
    embedded = print_plate(c.figure(parts=6), construction=c, sheet=Sheet(caption="de"))
    assert len(drawn.fills) > len(read(pdf_bytes(embedded))[2].fills) + 20  # every letter a filled outline


def test_a_caption_is_asked_for_by_language():
    c = get("crank")
    fig = c.figure(parts=6)
    de, en = (print_plate(fig, construction=c, sheet=Sheet(caption=lang)) for lang in ("de", "en"))
    assert "Kolbenwege" in de.svg() and "Kolbenwege" not in en.svg() and "Piston" in en.svg()
    assert "Kolbenwege" not in print_plate(fig, construction=c).svg()
    assert de.height_mm > print_plate(fig, construction=c).height_mm


def test_a_pdf_of_a_figure_of_ones_own(tmp_path):
    from construct import Builder

    b = Builder("demo", givens={})
    b.given_point("A", 0.0, 0.0, label="A")
    b.given_point("B", 3.0, 1.0, label="B")
    b.line("g", "A", "B")
    data = b.figure().pdf(tmp_path / "demo.pdf", width_mm=60, caption="en")
    assert (tmp_path / "demo.pdf").read_bytes() == data
    reader, page, _ = read(data)
    assert float(page.mediabox.width) / PT_PER_MM == pytest.approx(60.0, abs=0.01)
    assert set(reader.named_destinations) == {"A", "B"}


def test_the_same_date_gives_the_same_bytes(monkeypatch):
    monkeypatch.setenv("SOURCE_DATE_EPOCH", "1700000000")
    c = get("crank")
    plate = print_plate(c.figure(parts=6), construction=c)
    first = pdf_bytes(plate)
    assert first == pdf_bytes(print_plate(c.figure(parts=6), construction=c))
    assert b"20231114" in first


@pytest.mark.parametrize("kw, message", [({"width_mm": 0}, "width_mm"), ({"width_mm": -5.0}, "width_mm"),
                                         ({"width_mm": float("inf")}, "width_mm"), ({"letter_pt": float("nan")}, "letter_pt"),
                                         ({"caption": "fr"}, "caption"), ({"style": "sepia"}, "style")])
def test_bad_print_options_are_refused(tmp_path, kw, message):
    fig = get("crank").figure(parts=3)
    with pytest.raises(InvalidParameter, match=message):
        fig.pdf(tmp_path / "x.pdf", **kw)
    assert not (tmp_path / "x.pdf").exists()


def test_without_cairosvg_the_error_says_what_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "cairosvg", None)  # as if it were not installed
    with pytest.raises(MissingDependency, match="pip install"):
        get("crank").figure(parts=3).pdf()


@pytest.mark.parametrize("name", ["crank", "inertia-curve"])
def test_a_teaching_print_is_the_plate_in_the_teaching_look(name):
    """A teaching figure printed (``--style teaching --format pdf``) is what its player ends on: the book's
    plate, its points and its size, in the teaching colours -- not every helper of the construction on a
    canvas as tall as the player's stage (620 px of screen, empty paper on a page)."""
    c = get(name)
    fig = c.figure()
    teaching = print_plate(fig, construction=c, style="teaching")
    historical = print_plate(fig, construction=c, style=HISTORICAL)
    assert [p.name for p in teaching.points()] == [p.name for p in historical.points()]
    assert teaching.width_mm == pytest.approx(historical.width_mm)
    assert teaching.height_mm == pytest.approx(historical.height_mm, abs=0.5)
    assert pdf_bytes(teaching).startswith(b"%PDF")
