"""The plate as TikZ (construct.render.tikz): named coordinates at the SVG plate's points after the scale,
letters as TeX text beside them, the same bytes every run; compiled with pdflatex and lualatex where TeX is
installed (under CI it must be: .ci/install-tex.sh), the LaTeX example of the README and the gallery with them."""

import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from construct.constructions import get
from construct.kernel.errors import InvalidParameter
from construct.render.output import plate_caption, scene_for
from construct.render.output import print_plate
from construct.render.page import Sheet, tex_name
from construct.render.styles import HISTORICAL
from construct.render.svg import Drawing, render_svg
from construct.render.tikz import tex_text, tikz_document, tikz_picture

ROOT = Path(__file__).resolve().parents[1]

COORDINATE = re.compile(r"\\coordinate \(([^)]+)\) at \(([-0-9.]+),([-0-9.]+)\);")
LETTER = re.compile(r"\\node\[plate letter, anchor=([a-z ]+), xshift=([-0-9.]+)pt, yshift=([-0-9.]+)pt\] "
                    r"at \(([^)]+)\) \{(.*)\};")


def unit_mm(tikz: str) -> float:
    return float(re.search(r"\\begin\{tikzpicture\}\[x=([0-9.]+)mm", tikz).group(1))


def svg_points(svg: str) -> dict[str, tuple[float, float]]:
    return {m[3]: (float(m[1]), float(m[2]))
            for m in re.finditer(r'<circle class="pt[^"]*" cx="([-0-9.]+)" cy="([-0-9.]+)" id="([^"]+)"', svg)}


@pytest.fixture(scope="module")
def piston_force(tmp_path_factory):
    """The issue's command: Abb. 1054's piston-force plate in the historical style, as TikZ."""
    out = tmp_path_factory.mktemp("pf") / "pf"
    run = subprocess.run([sys.executable, "-m", "construct", "replay", "piston-force", "--style", "historical",
                          "--format", "tikz", "--out", str(out)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    return out


def test_every_lettered_point_is_a_named_coordinate_at_the_svg_plates_point(piston_force):
    """Each lettered point of the SVG plate is a named coordinate of the picture, within 0.01 mm after the scale."""
    c = get("piston-force")
    fig = c.figure()
    scene = scene_for(c, fig, plate=True)
    svg = render_svg(scene, style=HISTORICAL, caption=plate_caption(c, fig))
    at_svg = svg_points(svg)
    tikz = (piston_force / "final.tikz").read_text(encoding="utf-8")
    coords = {name: (float(x), float(y)) for name, x, y in COORDINATE.findall(tikz)}
    lettered = [m for m in scene.marks if m.kind == "point" and m.label]
    assert lettered and len(coords) == len(lettered)
    mm = unit_mm(tikz)
    px_per_unit = Drawing(scene, HISTORICAL).vp.scale
    a = np.array([at_svg[m.id] for m in lettered]) / px_per_unit * mm   # the SVG's places, scaled to the page
    b = np.array([coords[tex_name(m.name)] for m in lettered]) * mm
    b[:, 1] *= -1  # the SVG's y runs down
    moved = b - a
    assert np.abs(moved - moved.mean(axis=0)).max() < 0.01


def test_the_standalone_document_holds_the_picture(piston_force):
    tex = (piston_force / "final.tex").read_text(encoding="utf-8")
    tikz = (piston_force / "final.tikz").read_text(encoding="utf-8")
    assert tex.startswith("% The plate alone") and tikz in tex and tex.rstrip().endswith("\\end{document}")
    assert "paperwidth=120mm" in tex


def test_the_letters_are_tex_text_anchored_beside_their_named_points():
    """Every shown letter is a node at its named point, set off in points (not in the picture's units, so that
    it stays at its point at any scale), with the letter as TeX text."""
    c = get("crank")
    plate = print_plate(c.figure(parts=18), construction=c)
    tikz = tikz_picture(plate)
    names = {p.mark.id: p.name for p in plate.points()}
    shown = [lb for lb in plate.drawing.labels() if lb.shown]
    nodes = LETTER.findall(tikz)
    assert len(nodes) == len(shown) > 30
    by_point = {at: (anchor, float(dx), float(dy), text) for anchor, dx, dy, at, text in nodes}
    for lb in shown:
        anchor, dx, dy, text = by_point[names[lb.id]]
        assert text == tex_text(lb.text)
        # the anchor faces the point: a letter to the right of its point is anchored at its west side
        ox, oy = lb.offset
        if abs(ox) > 2 * abs(oy) + 4:
            assert ("west" in anchor) == (ox > 0), (lb.text, anchor, lb.offset)
        assert abs(dx) < 30 and abs(dy) < 30  # points from the point: a few letter heights at most
    assert "\\node[plate letter, anchor=" in tikz and "$'$" in tikz  # 4' set with TeX's prime


def test_the_same_plate_gives_the_same_bytes():
    c = get("crank")
    first = tikz_picture(print_plate(c.figure(parts=9), construction=c))
    assert first == tikz_picture(print_plate(c.figure(parts=9), construction=c))


def test_numbers_are_to_the_stated_precision():
    """A coordinate's last decimal is under 0.001 mm on the page; lengths in points have two decimals."""
    c = get("crank")
    tikz = tikz_picture(print_plate(c.figure(parts=9), construction=c))
    mm = unit_mm(tikz)
    decimals = max(len(x.split(".")[1]) if "." in x else 0 for _, x, _ in COORDINATE.findall(tikz))
    assert 10 ** -decimals * mm <= 0.001 < 10 ** -(decimals - 1) * mm
    assert all(len(v.split(".")[1]) <= 2 for v in re.findall(r"(-?[0-9]+\.[0-9]+)pt", tikz))


@pytest.mark.parametrize("name, expected", [("X4", "X4"), ("O'", "Oprime"), ("F″", "Fdprime"), ("B₁", "B-1"),
                                            ("ρ", "rho"), ("Ω", "Omega"), ("sc.A", "sc-A"), ("A(1)", "A-u00281-u0029")])
def test_point_names_are_safe_for_tex(name, expected):
    assert tex_name(name) == expected
    assert re.fullmatch(r"[A-Za-z0-9-]+", tex_name(name))


@pytest.mark.parametrize("text, expected", [("4'", "4$'$"), ("B₂", "B\\textsubscript{2}"), ("E∞", "E$\\infty$"),
                                            ("61°19′", "61\\textdegree{}19$'$"), ("−4000", "$-$4000"),
                                            ("Rückgang", 'R\\"uckgang'), ("{x}_%", "\\{x\\}\\_\\%")])
def test_letters_are_set_in_tex(text, expected):
    assert tex_text(text) == expected


def test_a_plates_indices_are_set_below_the_line_as_in_the_svg(piston_force):
    """The piston force's P_b and P = F·p_ü: TeX subscripts, as the SVG plate lowers them, never a literal '_'."""
    tikz = (piston_force / "final.tikz").read_text(encoding="utf-8")
    assert "\\_" not in tikz
    assert "{P\\textsubscript{b}}" in tikz and "p\\textsubscript{\\\"u}}" in tikz


def test_a_tikz_of_a_figure_of_ones_own_and_bad_options(tmp_path):
    from construct import Builder

    b = Builder("demo", givens={})
    b.given_point("A", 0.0, 0.0, label="A′")
    b.given_point("B", 3.0, 1.0, label="B")
    text = b.figure().tikz(tmp_path / "demo.tex", standalone=True, width_mm=50)
    assert (tmp_path / "demo.tex").read_text(encoding="utf-8") == text
    assert "\\coordinate (A) at (0,0);" in text and "{A$'$}" in text
    for bad in ({"standalone": "yes"}, {"tikz_style": "pstricks"}, {"width_mm": -1.0}):
        with pytest.raises(InvalidParameter):
            b.figure().tikz(**bad)


# -- compiled ---------------------------------------------------------------------------------------------------


def tex_installed(*programs: str) -> bool:
    """Are the TeX programs there?  Under CI they must be (.ci/install-tex.sh installs them): a missing one fails."""
    missing = [p for p in programs if shutil.which(p) is None]
    if missing and os.environ.get("CI"):
        pytest.fail(f"{', '.join(missing)} missing under CI: .ci/install-tex.sh installs TeX Live and poppler")
    if missing:
        pytest.skip(f"{', '.join(missing)} not installed (.ci/install-tex.sh installs them)")
    return True


def compile_tex(folder: Path, name: str, engine: str) -> str:
    """Compile *name* in *folder* with *engine*; return its log (the run must succeed)."""
    run = subprocess.run([engine, "-interaction=nonstopmode", "-halt-on-error", name], cwd=folder,
                         capture_output=True, text=True, timeout=300)
    log = (folder / name).with_suffix(".log").read_text(encoding="utf-8", errors="replace")
    assert run.returncode == 0, log[-3000:]
    return log


@pytest.mark.parametrize("engine", ["pdflatex", "lualatex"])
def test_the_standalone_plate_compiles_without_missing_characters(piston_force, tmp_path, engine):
    tex_installed(engine)
    shutil.copy(piston_force / "final.tex", tmp_path / "final.tex")
    log = compile_tex(tmp_path, "final.tex", engine)
    assert "Missing character" not in log and "Font shape" not in log
    pypdf = pytest.importorskip("pypdf")
    pages = pypdf.PdfReader(tmp_path / "final.pdf").pages
    assert len(pages) == 1  # a page a hair smaller than the picture left a blank first page and the plate on a second
    assert float(pages[0].mediabox.width) * 25.4 / 72 == pytest.approx(120.0, abs=0.05)
    assert "Overfull" not in log  # nothing but the picture in its paragraph (a stray space made it 2.2 pt too wide)


def marks_document(example: str, folder: Path) -> str:
    """The example, each picture marking where TeX put its named points (pgf's \\pgfsys@markposition, written
    to the .aux as positions on the page): the PDF's own coordinates of C4, read without a PDF library."""
    out = example.replace("\\begin{document}", "\\makeatletter\n\\tikzset{every picture/.append style={execute at "
                          "end picture={\\foreach \\n in \\marknames {\\path (\\n) node[inner sep=0pt, outer sep=0pt] "
                          "{\\pgfsys@markposition{\\markplate-\\n}};}}}}\n\\makeatother\n\\begin{document}")
    for name in re.findall(r"\\input\{([^}]+)\}", example):
        names = ",".join(n for n, _, _ in COORDINATE.findall((folder / name).read_text(encoding="utf-8")))
        out = out.replace(f"\\input{{{name}}}", f"\\def\\marknames{{{names}}}\\def\\markplate{{{name}}}"
                                                f"\\input{{{name}}}")
    return out


@pytest.fixture(scope="module")
def example(tmp_path_factory):
    """The README's LaTeX example (gallery/latex/plates.tex, the same text) with its plates, in a folder of its own."""
    folder = tmp_path_factory.mktemp("latex")
    for f in (ROOT / "gallery" / "latex").iterdir():
        shutil.copy(f, folder / f.name)
    return folder


def test_the_readme_shows_the_gallerys_latex_example():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    block = re.search(r"```latex\n(.*?)```", readme, re.S).group(1)
    assert block == (ROOT / "gallery" / "latex" / "plates.tex").read_text(encoding="utf-8")


@pytest.mark.parametrize("engine", ["pdflatex", "lualatex"])
def test_the_latex_example_compiles_to_one_page(example, engine, tmp_path):
    tex_installed(engine)
    for f in example.iterdir():
        shutil.copy(f, tmp_path / f.name)
    log = compile_tex(tmp_path, "plates.tex", engine)
    assert "Missing character" not in log and "Output written on plates.pdf (1 page" in log


def test_the_compiled_page_has_the_svg_plates_points_within_a_tenth_of_a_millimetre(example, tmp_path):
    """The example compiled (pdflatex), its named points read where TeX put them on the page, and the page
    rasterised (pdftoppm): each named point is where the SVG plate has it, after the scale (within 0.1 mm),
    and the printed page shows a point there."""
    tex_installed("pdflatex", "pdftoppm")
    from construct.gallery import LATEX_PLATES, entry_slug

    text = (example / "plates.tex").read_text(encoding="utf-8")
    (tmp_path / "marks.tex").write_text(marks_document(text, example), encoding="utf-8")
    for f in example.glob("*.tikz"):
        shutil.copy(f, tmp_path / f.name)
    compile_tex(tmp_path, "marks.tex", "pdflatex")
    aux = (tmp_path / "marks.aux").read_text(encoding="utf-8")
    sp_per_mm = 65536 * 72.27 / 25.4
    marks = {m[1]: (int(m[2]) / sp_per_mm, int(m[3]) / sp_per_mm)
             for m in re.finditer(r"\\pgfsyspdfmark \{([^}]+)\}\{(-?\d+)\}\{(-?\d+)\}", aux)}
    subprocess.run(["pdftoppm", "-r", "600", "-gray", "marks.pdf", "page"], cwd=tmp_path, check=True)
    from PIL import Image

    page = np.asarray(Image.open(next(tmp_path.glob("page*.pgm"))))
    a4_height = 297.0
    for name, params in LATEX_PLATES:
        c = get(name)
        fig = c.figure(**params)
        scene = scene_for(c, fig, plate=True)
        at_svg = svg_points(render_svg(scene, style=HISTORICAL, caption=plate_caption(c, fig)))
        tikz = (example / f"{entry_slug(name, params)}.tikz").read_text(encoding="utf-8")
        plate = print_plate(fig, construction=c)
        points = plate.points()
        assert points
        a = np.array([at_svg[p.mark.id] for p in points]) / Drawing(scene, HISTORICAL).vp.scale * unit_mm(tikz)
        b = np.array([marks[f"{entry_slug(name, params)}.tikz-{p.name}"] for p in points])
        b[:, 1] = a4_height - b[:, 1]  # from the head of the page, as the SVG's y
        moved = b - a
        assert np.abs(moved - moved.mean(axis=0)).max() < 0.1, name
        # on the rasterised page (600 dpi), ink within 0.3 mm of each point: its ring or dot is printed there
        for x, y in b:
            i, j = round(y / 25.4 * 600), round(x / 25.4 * 600)
            r = round(0.3 / 25.4 * 600)
            assert page[i - r:i + r + 1, j - r:j + r + 1].min() < 128, (name, x, y)


def test_the_tkz_euclide_plate_defines_its_points_with_tkz_euclide_and_compiles(tmp_path):
    c = get("crank")
    plate = print_plate(c.figure(parts=6), construction=c, sheet=Sheet(tikz_style="tkz-euclide"))
    tex = tikz_document(plate)
    assert "\\usepackage{tkz-euclide}" in tex and "\\tkzDefPoint(0,0){O}" in tex and "\\coordinate" not in tex
    from construct.regress.printdiff import diff_tikz_text

    # the same points, by name and place, as the plain picture's coordinates
    d = diff_tikz_text(tikz_picture(print_plate(c.figure(parts=6), construction=c)), tikz_picture(plate), "a", "b")
    assert d.sizes == (13, 13) and not [ch for ch in d.changes if ch.kind in ("moved", "added", "removed")]
    tex_installed("pdflatex", "kpsewhich")
    if subprocess.run(["kpsewhich", "xpatch.sty"], capture_output=True).returncode != 0:
        if os.environ.get("CI"):
            pytest.fail("tkz-euclide's xpatch missing under CI: .ci/install-tex.sh installs texlive-latex-extra")
        pytest.skip("tkz-euclide needs xpatch (texlive-latex-extra)")
    (tmp_path / "p.tex").write_text(tex, encoding="utf-8")
    assert "Missing character" not in compile_tex(tmp_path, "p.tex", "pdflatex")


def pgf_smooth_pieces(points, tension):
    """The Bézier pieces pgf's smooth plot makes of *points* (pgflibraryplothandlers.code.tex, curveto handler:
    a point's supports 0.2775 * tension of the chord between its neighbours away; the plot's first piece starts
    with its first point as support, the last ends with its last), written out again here, independently."""
    k = 0.2775 * tension
    pieces, first, support, second = [], points[0], points[0], points[1]
    for current in points[2:]:
        d = (k * (current[0] - first[0]), k * (current[1] - first[1]))
        pieces.append((first, support, (second[0] - d[0], second[1] - d[1]), second))
        first, support, second = second, (second[0] + d[0], second[1] + d[1]), current
    pieces.append((first, support, second, second))
    return pieces


def test_a_smooth_curve_in_tikz_is_the_svgs_curve():
    """TikZ's smooth plot through the curve's points, its ends written twice, draws the SVG's Bézier pieces
    (within 1e-4 of a unit: pgf's tension is a decimal), and two pieces of no length at the ends, each turning
    back less than a thirteenth of its chord: under the line's round cap."""
    from construct.render.paths import bezier_controls
    from construct.render.tikz import SMOOTH_TENSION

    rng = np.random.default_rng(29)
    pts = [tuple(p) for p in np.cumsum(rng.uniform(0.2, 1.0, size=(9, 2)), axis=0)]
    got = pgf_smooth_pieces([pts[0], *pts, pts[-1]], float(SMOOTH_TENSION))
    ours = [piece[1:] for piece in bezier_controls(pts)]
    assert len(got) == len(ours) + 2
    for (p0, c1, c2, p1), (d1, d2, e1) in zip(got[1:-1], ours):
        assert np.allclose([c1, c2, p1], [d1, d2, e1], atol=1e-4)
    for p0, c1, c2, p1 in (got[0], got[-1]):
        assert p0 == p1 and math.dist(p0, c1) + math.dist(p0, c2) < math.dist(pts[0], pts[1]) / 5 + math.dist(pts[-1], pts[-2]) / 5


def test_a_broken_rod_has_its_length_written_where_the_svg_writes_it():
    """A figure that breaks its long rod out draws it short and says how long it is: the TikZ picture writes
    "L = 8 r" at the break as the SVG does (its baseline where the SVG's ``data-rod`` sets it, the node at the
    middle of the letters' height), not the short rod alone.  (A figure printed without its construction: a
    construction's plate writes the rod's length as its dimension.)"""
    c = get("crank")
    plate = print_plate(c.figure(parts=6, rod_ratio=8.0), style="teaching")
    svg, tikz = plate.svg(), tikz_picture(plate)
    spots = re.findall(r'<g class="lbg rodlen" data-rod="\d ([-0-9.]+) ([-0-9.]+) (\w+)" '
                       r'transform="translate\(([-0-9.]+) ([-0-9.]+)\)">', svg)
    nodes = re.findall(r"\\node\[plate letter, [^\]]*anchor=(\w+)\] at \(([-0-9.]+),([-0-9.]+)\) \{L = 8 r\};", tikz)
    assert spots and len(nodes) == len(spots)
    vp, size = plate.drawing.vp, plate.style.label_size
    for (dx, dy, anchor, cx, cy), (tex_anchor, x, y) in zip(spots, nodes):
        assert tex_anchor == {"start": "west", "end": "east"}.get(anchor, "center")
        # the node's point on the canvas (px, y down): the SVG's baseline less 0.35 letters
        px = vp.margin + vp.left + (float(x) - vp.xmin) * vp.scale
        py = vp.margin + vp.top + (vp.ymax - float(y)) * vp.scale
        assert abs(px - (float(cx) + float(dx))) < 0.01
        assert abs(py - (float(cy) + float(dy) - 0.35 * size)) < 0.01
