"""How much room a line of text takes: its extents from the font's own metrics.

A label's box is what its glyphs cover (their outlines, as matplotlib's
:class:`~matplotlib.textpath.TextToPath` lays them out) placed where SVG puts them: the
baseline at ``y``, shifted by ``text-anchor`` by the *advance* width (the
sum of the glyphs' advances with kerning, from :class:`~matplotlib.ft2font.FT2Font`).
The font is the first family the drawing names that matplotlib has; the
generic families are DejaVu (which ships with matplotlib): a browser with
Georgia installed draws the plain style a little narrower than measured.

matplotlib is imported here, when a text is first measured, and nothing
process-wide is changed (no backend, no rcParams).

>>> ink, advance = text_extents("K17", "'DejaVu Sans', Arial, sans-serif", 12.0)
>>> 22.0 < advance < 24.0 and ink[0] > 0 and ink[2] < advance and -9.0 < ink[1] < -8.0 and ink[3] == 0.0
True
>>> text_extents("K17", "Georgia, 'DejaVu Serif', serif", 12.0)[1] > advance   # serif is wider
True
"""

from __future__ import annotations

import functools

__all__ = ["text_extents", "font_file", "load"]

#: What the generic CSS families are measured with (the fonts matplotlib ships).
GENERIC = {"serif": "DejaVu Serif", "sans-serif": "DejaVu Sans", "monospace": "DejaVu Sans Mono",
           "cursive": "DejaVu Sans", "fantasy": "DejaVu Sans", "system-ui": "DejaVu Sans"}


@functools.lru_cache(maxsize=None)
def _families() -> frozenset[str]:
    from matplotlib import font_manager

    return frozenset(f.name.lower() for f in font_manager.fontManager.ttflist)


@functools.lru_cache(maxsize=256)
def font_file(family: str, style: str = "normal", weight: str = "normal") -> str:
    """The font file a CSS ``font-family`` list is measured with: its first family matplotlib has.

    >>> font_file("'No Such Font', serif").endswith(("DejaVuSerif.ttf",))
    True
    """
    from matplotlib import font_manager

    chosen = "DejaVu Sans"
    for name in (part.strip().strip("'\"").strip() for part in family.split(",")):
        if not name:
            continue
        if name.lower() in GENERIC:
            chosen = GENERIC[name.lower()]
            break
        if name.lower() in _families():
            chosen = name
            break
    prop = font_manager.FontProperties(family=chosen, style=style if style in ("italic", "oblique") else "normal",
                                       weight=weight)
    return font_manager.findfont(prop, fallback_to_default=True)


def load(families: "tuple[str, ...]" = ("serif", "sans-serif")) -> None:
    """Load what measuring text needs (matplotlib's font manager, its font list, the faces of
    *families*) now, in this process: processes forked after it (``construct gallery``'s workers,
    which lint what they build) share them instead of each loading them again.

    >>> load()
    """
    _families()
    for family in families:
        text_extents("A", family, 12.0)
        text_extents("A", family, 12.0, "italic")


#: The size glyphs are measured at (their metrics scale with the size: one measure serves every size).
_EM = 64.0


@functools.lru_cache(maxsize=65536)
def text_extents(text: str, family: str, size: float, style: str = "normal", weight: str = "normal"
                 ) -> tuple[tuple[float, float, float, float], float]:
    """(ink box (x0, y0, x1, y1) relative to the start of the baseline, y down; advance width), in the units of *size*.

    Each glyph's outline box is set at its pen position (the advances and kerning
    before it); an empty or blank text has an empty ink box at the origin.
    """
    path = font_file(family, style, weight)
    if not text.strip():
        return (0.0, 0.0, 0.0, 0.0), 0.0
    k = size / _EM
    pen = 0.0
    box = None
    previous = None
    for ch in text:
        advance, glyph, index = _glyph(path, ch)
        if previous is not None:
            pen += _kerning(path, previous, index)
        if glyph is not None:
            g = (pen + glyph[0], glyph[1], pen + glyph[2], glyph[3])
            box = g if box is None else (min(box[0], g[0]), min(box[1], g[1]), max(box[2], g[2]), max(box[3], g[3]))
        pen += advance
        previous = index
    if box is None:
        return (0.0, 0.0, 0.0, 0.0), pen * k
    return (box[0] * k, box[1] * k, box[2] * k, box[3] * k), pen * k


@functools.lru_cache(maxsize=4096)
def _glyph(path: str, ch: str) -> tuple[float, tuple[float, float, float, float] | None, int]:
    """A character at :data:`_EM`: its advance, its outline's box (y down; None when it draws nothing), glyph index.

    The box is the extremes of the outline's points as matplotlib's TextToPath
    lays them out (the control points of the quadratic pieces bulge a hair
    beyond the outline: the box errs by far under a pixel, on the safe side).
    """
    from matplotlib import font_manager, ft2font

    no_hinting = ft2font.LoadFlags.NO_HINTING if hasattr(ft2font, "LoadFlags") else ft2font.LOAD_NO_HINTING
    font = font_manager.get_font(path)
    font.set_size(_EM, 72)  # 72 dpi: one point is one unit, as SVG's px
    advance = font.load_char(ord(ch), flags=no_hinting).linearHoriAdvance / 65536.0
    index = font.get_char_index(ord(ch))
    verts, codes = _to_path().get_text_path(font_manager.FontProperties(fname=path, size=_EM), ch)
    pts = [v for v, c in zip(verts, codes) if c not in (0, 79)]  # STOP and CLOSEPOLY carry no point
    if not pts:
        return advance, None, index
    scale = _EM / _to_path().FONT_SCALE
    xs, ys = [float(p[0]) * scale for p in pts], [float(p[1]) * scale for p in pts]
    return advance, (min(xs), -max(ys), max(xs), -min(ys)), index


@functools.lru_cache(maxsize=65536)
def _kerning(path: str, left: int, right: int) -> float:
    from matplotlib import font_manager, ft2font

    mode = getattr(getattr(ft2font, "Kerning", None), "UNFITTED", 1)  # an enum since matplotlib 3.10
    font = font_manager.get_font(path)
    font.set_size(_EM, 72)
    return font.get_kerning(left, right, mode) / 64.0  # 26.6 fixed point


def _to_path():
    """matplotlib's TextToPath, one per import of matplotlib.textpath."""
    from matplotlib import textpath

    return _to_path_of(textpath)


@functools.lru_cache(maxsize=1)
def _to_path_of(textpath):
    # Made once per module object, not once per process: a host that drops the modules imported meanwhile and
    # imports matplotlib again (pytest's in-process runs restore sys.modules) would otherwise keep a TextToPath
    # of the old module, which refuses the new module's FontProperties (an order-dependent TypeError).
    return textpath.TextToPath()
