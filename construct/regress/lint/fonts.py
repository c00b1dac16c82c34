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

__all__ = ["text_extents", "font_file"]

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


@functools.lru_cache(maxsize=65536)
def text_extents(text: str, family: str, size: float, style: str = "normal", weight: str = "normal"
                 ) -> tuple[tuple[float, float, float, float], float]:
    """(ink box (x0, y0, x1, y1) relative to the start of the baseline, y down; advance width), in the units of *size*.

    An empty or blank text has an empty ink box at the origin.
    """
    from matplotlib import font_manager, ft2font
    kerning = getattr(getattr(ft2font, "Kerning", None), "DEFAULT", 0)  # an enum since matplotlib 3.10
    no_hinting = ft2font.LoadFlags.NO_HINTING if hasattr(ft2font, "LoadFlags") else ft2font.LOAD_NO_HINTING

    path = font_file(family, style, weight)
    if not text.strip():
        return (0.0, 0.0, 0.0, 0.0), 0.0
    font = font_manager.get_font(path)
    font.set_size(size, 72)  # 72 dpi: one point is one unit, as SVG's px
    advance = 0.0
    previous = None
    for ch in text:
        index = font.get_char_index(ord(ch))
        if previous is not None:
            advance += font.get_kerning(previous, index, kerning) / 64.0  # 26.6 fixed point
        advance += font.load_char(ord(ch), flags=no_hinting).linearHoriAdvance / 65536.0
        previous = index
    # the glyph outlines as TextPath lays them out; their points' extremes (control points of the
    # quadratic pieces bulge a hair beyond the outline: the box errs by far under a pixel, on the safe side)
    verts, codes = _TO_PATH().get_text_path(font_manager.FontProperties(fname=path), text)
    pts = [v for v, c in zip(verts, codes) if c not in (0, 79)]  # STOP, CLOSEPOLY carry no point
    if not pts:
        return (0.0, 0.0, 0.0, 0.0), advance
    k = size / _TO_PATH().FONT_SCALE
    xs, ys = [float(p[0]) * k for p in pts], [float(p[1]) * k for p in pts]
    return (min(xs), -max(ys), max(xs), -min(ys)), advance


@functools.lru_cache(maxsize=1)
def _TO_PATH():
    from matplotlib.textpath import TextToPath

    return TextToPath()
