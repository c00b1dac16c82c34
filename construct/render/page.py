"""A plate at its final size (DESIGN §8): the page's width in millimetres, the letters' size in points.

A plate for an edition is set at 100 %: a book's type area is about 110-130 mm
wide, its figures' letters about 7-9 pt, its lines stated in points.  Scaling
the screen's 960-unit plate down to 120 mm would set 12-unit letters at 4.2 pt
and a 0.45-unit construction line at 0.16 pt, so a print plate is laid out
again for its page (:meth:`Style.for_print`): the canvas is as many units wide
as letters of :attr:`Sheet.letter_pt` ask, the letter placer (:mod:`.lettering`)
places them for that density, and every line gets its weight in points.  The
geometry is the SVG plate's: every named point stands where it stands there,
up to the scale.

:func:`lay_out` gives the laid-out :class:`PrintPlate` (of a figure:
:func:`construct.render.output.print_plate`), from which the PDF
(:mod:`construct.render.pdf`) and the TikZ picture (:mod:`construct.render.tikz`)
are written.

>>> from construct.constructions import get
>>> from construct.render.output import print_plate
>>> plate = print_plate(get("crank").figure(parts=6), construction=get("crank"))
>>> round(plate.width_mm, 6), plate.sheet.caption, plate.svg().count('class="cap')
(120.0, 'none', 0)
>>> [p.name for p in plate.points()][:3]
['O', 'D0', 'D1']
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from typing import Any, NamedTuple

from ..kernel.errors import InvalidParameter
from .captions import Captions
from .scene import MarkKind, Scene
from .styles import Style
from .svg import Drawing

__all__ = ["Sheet", "PrintPlate", "PlatePoint", "lay_out", "CAPTIONS", "TIKZ_STYLES", "PT_PER_MM", "tex_name"]

#: Points in a millimetre.
PT_PER_MM = 72.0 / 25.4
#: What a printed plate carries beneath it: nothing (the edition sets its own caption), or the German or
#: the English caption.
CAPTIONS = ("none", "de", "en")
#: How a TikZ plate is written: TikZ's own paths, or tkz-euclide's macros where they express a point.
TIKZ_STYLES = ("tikz", "tkz-euclide")
#: The widest page a plate is laid out for (a broadsheet; cairo's PDF pages end at 5 m).
MAX_WIDTH_MM = 2000.0


def _positive(name: str, value: Any, most: float) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
            or not 0 < value <= most:
        raise InvalidParameter(f"{name} must be a number above 0 and at most {most:g}, got {value!r}")
    return float(value)


@dataclass(frozen=True)
class Sheet:
    """The page a plate is printed on and how it is set: its width, its letters' size, its caption (none, de,
    en); in a PDF its letters as outlines instead of an embedded font (*outline*), in TikZ with tkz-euclide's
    macros where they express a point (*tikz_style* ``tkz-euclide``) or TikZ's own (``tikz``).

    >>> Sheet().width_mm, Sheet().letter_pt
    (120.0, 7.0)
    >>> Sheet(width_mm=float("nan"))
    Traceback (most recent call last):
    ...
    construct.kernel.errors.InvalidParameter: width_mm must be a number above 0 and at most 2000, got nan
    """

    width_mm: float = 120.0
    #: 7 pt, as figures are lettered: at 8 pt the crank's 37 letters crowd a plate 120 mm wide
    letter_pt: float = 7.0
    caption: str = "none"
    outline: bool = False
    tikz_style: str = "tikz"

    def __post_init__(self) -> None:
        object.__setattr__(self, "width_mm", _positive("width_mm", self.width_mm, MAX_WIDTH_MM))
        object.__setattr__(self, "letter_pt", _positive("letter_pt", self.letter_pt, 72.0))
        if self.caption not in CAPTIONS:
            raise InvalidParameter(f"unknown caption {self.caption!r}; choose one of {', '.join(CAPTIONS)}")
        if not isinstance(self.outline, bool):
            raise InvalidParameter(f"outline is True or False, got {self.outline!r}")
        if self.tikz_style not in TIKZ_STYLES:
            raise InvalidParameter(f"unknown TikZ style {self.tikz_style!r}; choose one of {', '.join(TIKZ_STYLES)}")

    @property
    def width_pt(self) -> float:
        return self.width_mm * PT_PER_MM


class PlatePoint(NamedTuple):
    """A lettered point of a printed plate: its TeX-safe name, the mark, its place on the canvas (units, y down)."""

    name: str
    mark: Any
    x: float
    y: float


@dataclass(frozen=True)
class PrintPlate:
    """A figure laid out on its :class:`Sheet`: the drawing on the print canvas and its caption lines."""

    drawing: Drawing
    sheet: Sheet
    #: the caption lines beneath the figure (none: the edition sets its own)
    caption: tuple[str, ...]
    #: the German and English title (the PDF's title, the TikZ file's head)
    title: tuple[str, str]

    @property
    def scene(self) -> Scene:
        return self.drawing.scene

    @property
    def style(self) -> Style:
        return self.drawing.style

    @property
    def pt(self) -> float:
        """Points per canvas unit on the page."""
        return self.style.print_pt  # type: ignore[return-value]

    @property
    def width_mm(self) -> float:
        return self.drawing.vp.width * self.pt / PT_PER_MM

    @property
    def height_mm(self) -> float:
        return self.drawing.vp.height * self.pt / PT_PER_MM

    @property
    def mm_per_unit(self) -> float:
        """Millimetres on the page per drawing unit (the crank radius, for most constructions)."""
        return self.drawing.vp.scale * self.pt / PT_PER_MM

    def svg(self) -> str:
        """The plate as SVG on the print canvas (the PDF's source)."""
        return self.drawing.final(self.caption or None, centred=self.style.plate)

    def points(self) -> list[PlatePoint]:
        """Every lettered point, in the figure's order, named for TeX (:func:`tex_name`; a copy in a further
        panel of the sheet by its panel, ``D0-panel1``), with its place on the canvas."""
        out, taken = [], set()
        for m in self.scene.marks:
            if m.kind is MarkKind.POINT and m.label:
                panel = _PANEL.search(m.id)
                name = tex_name(m.name) + (panel.group(0) if panel else "")
                base, k = name, 2
                while name in taken:  # two points whose names read alike in TeX
                    name, k = f"{base}-{k}", k + 1
                taken.add(name)
                x, y = self.drawing.vp.px(*m.geom)
                out.append(PlatePoint(name, m, x, y))
        return out


#: The end of the id of a point's copy in a further panel of the sheet (:func:`construct.render.scene.lay_out`).
_PANEL = re.compile(r"-panel[0-9]+$")
#: How the characters of the books' names are spelled in a TeX-safe name.
_SPELLED = {"'": "prime", "′": "prime", "″": "dprime", "∞": "inf", ".": "-", "-": "-", "_": "-"}
_GREEK = dict(zip("αβγδεζηθικλμνξοπρστυφχψω", ("alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu "
                                                   "nu xi omicron pi rho sigma tau upsilon phi chi psi omega").split()))


def tex_name(name: str) -> str:
    """A point's name as TeX and TikZ take it in ``\\coordinate (NAME)``: letters and digits as they are,
    primes spelled out, subscript digits as digits after a hyphen, Greek letters by their names, a dot as
    a hyphen (TikZ reads a dot as an anchor); anything else by its code.

    >>> tex_name("X4"), tex_name("O'"), tex_name("A₁"), tex_name("ρ"), tex_name("K.W1"), tex_name("F∞")
    ('X4', 'Oprime', 'A-1', 'rho', 'K-W1', 'Finf')
    """
    out = []
    for c in name:
        if c.isascii() and c.isalnum():
            out.append(c)
        elif c in _SPELLED:
            out.append(_SPELLED[c])
        elif "₀" <= c <= "₉":
            out.append("-" + str(ord(c) - ord("₀")))
        elif c.lower() in _GREEK:
            out.append(_GREEK[c.lower()].capitalize() if c.isupper() else _GREEK[c])
        else:
            out.append(f"-u{ord(c):04x}")
    return "".join(out) or "point"


def lay_out(scene: Scene, title: tuple[str, str], *, style: Style, sheet: Sheet = Sheet()) -> PrintPlate:
    """*scene* (titled *title*: German, English) laid out on *sheet* in *style*: the caption the sheet asks for
    beneath it.  :func:`construct.render.output.print_plate` lays a figure out so, as a book plate."""
    if not isinstance(sheet, Sheet):
        raise InvalidParameter(f"sheet must be a Sheet, got {type(sheet).__name__}")
    st = style.for_print(sheet.width_pt, sheet.letter_pt)
    caption = () if sheet.caption == "none" else (title[CAPTIONS.index(sheet.caption) - 1],)
    if not caption:
        st = replace(st, show_caption=False)
    n = len(Captions(scene, width=st.width_px - 2 * st.margin_px, size=st.caption_size).title_lines(caption)) \
        if caption else 0
    return PrintPlate(Drawing(scene, st, caption_lines=n), sheet, caption, title)
