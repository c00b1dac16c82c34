r"""Formulas and symbols as a reader sees them: the books' formulas as MathML, subscripts as subscripts.

The errata quote the books' formulas as printed: Baumann's in the LaTeX the
OCR gave (``\frac{s_1 - s_a}{s_a + s_1}``, ``cos α`` without a backslash,
decimal commas), Anhang II's in Unicode (``√(L² - 16r²)``, ``tg β``).
:func:`to_mathml` reads both as LaTeX -- after :func:`as_latex` has written
the Unicode forms and the bare function names the way LaTeX spells them --
and converts with latex2mathml, offline; a page shows the result with any
browser's MathML.  :func:`with_subscripts` sets the subscripts of names in
running text (``f_x``, ``P_b,max``) as HTML.

>>> to_mathml(r"\sqrt{9 - 5 \frac{s_0}{s}}")
'<math><mrow><msqrt><mrow><mn>9</mn><mo>−</mo><mn>5</mn><mfrac><mrow><msub><mi>s</mi><mn>0</mn></msub></mrow><mrow><mi>s</mi></mrow></mfrac></mrow></msqrt></mrow></math>'
>>> with_subscripts("f_x in mm², P_b,max & more")
'f<sub>x</sub> in mm², P<sub>b,max</sub> &amp; more'
"""

from __future__ import annotations

import html
import re

__all__ = ["as_latex", "to_mathml", "formula_html", "with_subscripts"]

#: The functions the books write upright (LaTeX has no \\tg: it becomes an operator name).
_FUNCTIONS = re.compile(r"(?<![\\A-Za-z])(sin|cos|tan|ln|log|tg)(?![A-Za-z])")
#: ... with its power, if any (sin^2 α): the thin space goes after the power.
_FUNCTION_POWER = re.compile(_FUNCTIONS.pattern[:-len("(?![A-Za-z])")] + r"(\^\{?\d+\}?)?(?![A-Za-z])")
#: A word of two or more letters that is no command: text inside the formula ("Kranzgewicht", "or").
_WORD = re.compile(r"(?<![\\A-Za-zÄÖÜäöüß])([A-Za-zÄÖÜäöüß]{2,})(?![A-Za-zÄÖÜäöüß])")
_SUPERSCRIPTS = str.maketrans({"²": "^{2}", "³": "^{3}"})
_SUBSCRIPTS = {chr(0x2080 + d): str(d) for d in range(10)}
_SYMBOLS = {"−": "-", "±": r"\pm ", "·": r"\cdot ", "…": r"\ldots ", "∂": r"\partial "}


def as_latex(text: str) -> str:
    r"""A book's formula as LaTeX: Unicode roots, powers, indices and signs, function names, words.

    cos, sin, tg become operator names with their thin space (``\cos\,``), a word of the text
    (``Kranzgewicht``, ``or``) text with the space it had, and a wide gap (two spaces) a quad.

    >>> print(as_latex("cos ω = (-L + √(L² + 16r²)) / 4r"))
    \cos\, ω = (-L + \sqrt{L^{2} + 16r^{2}}) / 4r
    >>> print(as_latex(r"Kranzgewicht = G_{total} / (1 + 0,08075 v^2/k_z)  (or sin^2 α)"))
    \text{Kranzgewicht}\; = G_{\text{total}} / (1 + 0,08075 v^2/k_z)\quad (\text{or}\; \sin^2\, α)
    """
    out = _roots(text.translate(_SUPERSCRIPTS))
    out = re.sub("[₀-₉]+", lambda m: "_{" + "".join(_SUBSCRIPTS[c] for c in m.group(0)) + "}", out)
    for sign, tex in _SYMBOLS.items():
        out = out.replace(sign, tex)
    out = re.sub(r"\s{2,}", r"\\quad ", out)

    def word(m: re.Match) -> str:
        before = m.start() > 0 and m.string[m.start() - 1] == " "
        after = m.end() < len(m.string) and m.string[m.end()] == " "
        return ("\\;" if before and m.start() > 1 else "") + rf"\text{{{m.group(1)}}}" + ("\\;" if after else "")

    out = _WORD.sub(lambda m: m.group(0) if _FUNCTIONS.fullmatch(m.group(0)) else word(m), out)
    # an operator name: upright, a thin space before its argument (after its power, if it has one) and after
    # a factor it follows (r/L cos 2ω)
    def function(m: re.Match) -> str:
        before = m.string[:m.start()].rstrip()[-1:]
        return ((r"\," if before.isalnum() or before == ")" else "")
                + (r"\operatorname{tg}" if m.group(1) == "tg" else "\\" + m.group(1)) + (m.group(2) or "") + r"\,")

    return _FUNCTION_POWER.sub(function, out)


def _roots(text: str) -> str:
    r"""``√(…)`` with its parenthesis matched, as ``\sqrt{…}`` (the parentheses are the root's bar)."""
    while (i := text.find("√(")) >= 0:
        depth, j = 0, i + 1
        for j in range(i + 1, len(text)):
            depth += {"(": 1, ")": -1}.get(text[j], 0)
            if depth == 0:
                break
        text = text[:i] + r"\sqrt{" + text[i + 2:j] + "}" + text[j + 1:]
    return text.replace("√", r"\sqrt ")


def to_mathml(text: str) -> str:
    """A book's formula (LaTeX, or the Unicode a book excerpt prints) as inline MathML.

    Decimal commas stay one number (``<mn>0,2</mn>``); cos, sin, tg upright with their spacing.
    """
    from latex2mathml.converter import convert

    got = convert(as_latex(text))
    # The page is HTML: <math> is MathML there without its namespace, and inline is the default.
    got = got.replace(' xmlns="http://www.w3.org/1998/Math/MathML"', "").replace(' display="inline"', "")
    # Characters rather than references (except the three markup needs): the page stays readable.
    got = re.sub(r"&#x([0-9A-Fa-f]+);", lambda m: html.escape(chr(int(m.group(1), 16)), quote=False), got)
    # A decimal comma is part of its number, not a separator with space after it.
    got = re.sub(r"<mn>(\d+)</mn>(?:<mrow>)?<mo>,</mo>(?:</mrow>)?<mn>(\d+)</mn>", r"<mn>\1,\2</mn>", got)
    # latex2mathml sets \pm as an identifier; it is an operator (with an operator's spacing).  A slash is
    # set tight, as the books print r/L and F/f.
    return got.replace("<mi>±</mi>", "<mo>±</mo>").replace("<mo>/</mo>", '<mo lspace="0" rspace="0">/</mo>')


def formula_html(text: str) -> str:
    """A book's formula as MathML that a narrow column can wrap: one ``<math>`` per side of each ``=`` and
    per part set apart by a wide gap, so that a line breaks there (MathML itself never breaks a line).

    >>> formula_html("y = F/f (1 - r/L)").count("<math>")
    2
    """
    return " ".join(to_mathml(piece) for piece in _pieces(text))


def _pieces(text: str) -> list[str]:
    """*text* cut after each "=" and before each wide gap that stand outside brackets: ``a =``, ``b``."""
    pieces, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        depth += (ch in "([{") - (ch in ")]}")
        if depth == 0 and (ch == "=" or text.startswith("  ", i)) and text[start:i + 1].strip(" ="):
            pieces.append(text[start:i + 1].strip())
            start = i + 1
    return pieces + ([text[start:].strip()] if text[start:].strip() else [])


#: A name (Greek too, primes allowed) and its subscript: f_x, df_x, α_f, t'_a, P_b,max, G_{total}.
_SUBSCRIPTED = re.compile(r"([A-Za-zα-ωΑ-Ω]+'*)_(\{[^}]*\}|[A-Za-z0-9]+(?:,[A-Za-z]+)?)")


def with_subscripts(text: str) -> str:
    """*text* as HTML, each name's subscript set as one (``f_x`` → f<sub>x</sub>)."""
    return _SUBSCRIPTED.sub(lambda m: f"{m.group(1)}<sub>{m.group(2).strip('{}')}</sub>",
                            html.escape(text, quote=False))
