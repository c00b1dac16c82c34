"""A plate as PDF at its final size: the print layout (:mod:`construct.render.page`) converted by cairosvg.

The page is the sheet's width (120 mm by default) and as high as the plate;
every line has its weight in points (:class:`construct.render.styles.LineWeights`,
none under 0.2 pt); the historical plate is pure black on white.  The letters'
font is embedded as a subset (cairo writes TrueType), or, with *outline*, every
glyph is drawn as its outline and the file holds no font at all (what a
publisher asks who will not take fonts).  Every lettered point is a PDF named
destination at its place on the page, under its TeX-safe name
(:func:`construct.render.page.tex_name`): the PDF's own record of where C4
is, which :mod:`construct.regress.printdiff` reads to compare two PDFs point by point.

Why cairosvg and not matplotlib's PDF backend (measured on the crank plate,
18 parts, and Abb. 1055 at 120 mm): cairosvg converts the SVG plate itself,
so the PDF is the same figure -- the letters where the placer put them, the
plate's furniture, the hatching, the break marks -- with every point where
the SVG has it (to the SVG's 0.01 units); matplotlib would draw the scene
again (:func:`construct.render.plotting.plot_figure` has no furniture and
no letter placement of its own), a second renderer to keep equal to the
first.  cairosvg's files are smaller (28 kB against 41 kB, 81 kB against
231 kB), embed TrueType subsets where matplotlib writes Type 3 fonts unless
told otherwise, and take a third of the time.  cairosvg is already what
the tests rasterise with; it needs the cairo library, so it is imported
only when a PDF is asked for (:class:`~construct.kernel.errors.MissingDependency`
names what to install when it is absent).

The bytes are the same on every run when ``SOURCE_DATE_EPOCH`` is set (the
PDF's creation date is taken from it, as reproducible builds do); otherwise
cairo dates the file.

>>> from construct.constructions import get
>>> from construct.render.output import print_plate
>>> pdf = pdf_bytes(print_plate(get("crank").figure(parts=6), construction=get("crank")))
>>> pdf[:5], b"/FontFile2" in pdf, b"/Dests" in pdf
(b'%PDF-', True, True)
"""

from __future__ import annotations

import datetime
import io
import os
from typing import Any

from ..kernel.errors import MissingDependency
from .page import PrintPlate

__all__ = ["pdf_bytes", "cairosvg_modules"]


def cairosvg_modules() -> tuple[Any, Any, Any]:
    """(cairocffi, cairosvg.parser, cairosvg.surface), or MissingDependency naming what to install."""
    try:
        import cairocffi
        from cairosvg import parser, surface
    except (ImportError, OSError) as exc:  # OSError: cairosvg is there, the cairo library is not
        raise MissingDependency(f"a PDF needs cairosvg and the cairo library ({exc}); install them with "
                                f"pip install 'construct-steam[pdf]' and your system's cairo package") from None
    return cairocffi, parser, surface


class _Outlining:
    """A cairo context whose ``show_text`` fills the glyphs' outlines instead of setting them in a font
    (so the PDF holds no font); the path being built around it (the letter's halo) is kept."""

    def __init__(self, context: Any):
        self._context = context

    def __getattr__(self, name: str) -> Any:
        return getattr(self._context, name)

    def show_text(self, text: str) -> None:
        c = self._context
        kept = c.copy_path()
        x, y = c.get_current_point()
        c.new_path()
        c.move_to(x, y)
        c.text_path(text)
        c.fill()
        c.append_path(kept)


def _creation_date() -> str | None:
    """The PDF's creation date from ``SOURCE_DATE_EPOCH`` (ISO 8601, UTC), or None (cairo's clock)."""
    epoch = os.environ.get("SOURCE_DATE_EPOCH", "")
    if not epoch.isdigit():
        return None
    return datetime.datetime.fromtimestamp(int(epoch), datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%S")


def pdf_bytes(plate: PrintPlate) -> bytes:
    """The laid-out *plate* as a one-page PDF: its page the sheet's width, fonts embedded (or outlined, as
    its sheet says), every lettered point a named destination."""
    outline = plate.sheet.outline
    cairo, parser, surface = cairosvg_modules()
    svg = plate.svg()

    class PlateSurface(surface.PDFSurface):
        def draw(self, node: Any) -> None:
            if outline and not isinstance(self.context, _Outlining):
                self.context = _Outlining(self.context)
            super().draw(node)

    out = io.BytesIO()
    # at 72 dots to the inch a canvas unit is a point: the page is output_width points wide
    pdf = PlateSurface(parser.Tree(bytestring=svg.encode("utf-8")), out, 72, output_width=plate.sheet.width_pt)
    context = pdf.context._context if outline else pdf.context
    for p in plate.points():
        # a destination's x and y are the page's points from its top left corner
        context.tag_begin(cairo.TAG_DEST, f"name='{p.name}' x={p.x * plate.pt:.3f} y={p.y * plate.pt:.3f}")
        context.tag_end(cairo.TAG_DEST)
    from ..kernel import version

    meta = {cairo.PDF_METADATA_TITLE: plate.title[0], cairo.PDF_METADATA_CREATOR: f"construct {version()}"}
    date = _creation_date()
    if date:
        meta[cairo.PDF_METADATA_CREATE_DATE] = date
    for key, value in meta.items():
        pdf.cairo.set_metadata(key, value)
    pdf.finish()
    return out.getvalue()
