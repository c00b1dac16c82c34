"""The books' typography: numbers with the decimal comma, subscripts, primes, ω and √ for their ASCII stand-ins,
and where a formula may break across lines.

(Kernel module, used by :mod:`construct.kernel.letters` for captions and by the renderers for letters and
plates; :mod:`~construct.kernel.letters` re-exports every name.)

>>> number(0.4, "de"), lowered("q5"), book_symbols("r cos w + lam r cos 2w, Ordinate in 6'")
('0,4', 'q₅', 'r cos ω + λ r cos 2ω, Ordinate in 6′')
"""

from __future__ import annotations

import re

__all__ = ["number", "subscripts", "lowered", "formula_break", "unbroken", "equation", "primed", "book_symbols"]

#: Greek letters the constructions spell out in ASCII ("(4/pi) r alpha", "omega^2").
_GREEK = {"omega": "ω", "alpha": "α", "beta": "β", "kappa": "κ", "delta": "δ", "lambda": "λ", "pi": "π"}

_SUPER = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def number(v: float, lang: str, digits: int = 4) -> str:
    """*v* as the books print it: at most *digits* significant digits, the decimal comma in German.

    >>> number(0.4, "de"), number(0.4, "en"), number(1529.0720493, "de", 5), number(50.0, "de")
    ('0,4', '0.4', '1529,1', '50')
    """
    text = f"{float(v):.{digits}g}"
    if "e" in text:
        text = f"{float(v):.{digits}f}".rstrip("0").rstrip(".")
    return text.replace(".", ",") if lang == "de" else text


def subscripts(text: str) -> str:
    """Subscripts written with an underscore: digits as subscript digits, letters run on (p_ü -> pü).

    >>> subscripts("F·p_ü, x_1, q_max")
    'F·pü, x₁, qmax'
    """
    if "_" not in text:
        return text  # nothing to lower (most captions): no pattern run
    return re.sub(r"(?<=[^\W_])_([^\W_]+)", lambda m: m.group(1).translate(_SUB), text)


def lowered(letter: str) -> str:
    """A figure's letter with its number set as the books set it, below the line: q5 -> q₅, ω6 -> ω₆, K17 -> K₁₇.

    A name stays a name (the protocol's q5); this is its lettering.

    >>> lowered("q5"), lowered("ω6"), lowered("K17"), lowered("5′"), lowered("A")
    ('q₅', 'ω₆', 'K₁₇', '5′', 'A')
    """
    return re.sub(r"(?<=[^\W\d_])(\d+)$", lambda m: m.group(1).translate(_SUB), letter)


#: A line that ends with one of these (alone, or last in its word) leaves a formula open.
_OPEN_END = ("=", "+", "−", "-", "·", "×", "/", "≈", "(", "[", "{", ":")
#: A line that starts with one of these continues a formula of the line before.
_OPEN_START = ("=", "+", "−", "·", "×", "/", "≈", ")", "]", "}")
#: Words a number follows: "Fig. 77", "Abb. 1055", "Gl. (298)", "§ 146", "Tafel I".
_NUMBERED = frozenset({"fig.", "abb.", "gl.", "§", "§§", "tafel", "tabelle", "nr.", "no.", "bd.", "s.", "seite", "p.",
                       "formel", "table", "plate", "eq."})
_NUMBER = re.compile(r"[−+\-]?(?:\d+(?:[.,]\d+)*(?:/\d+)?%?|[IVX]+)[.,;]?$")
#: The units and unit-like letters a number is followed by in the books' givens (25 at, 0,8 r, 10 % s).
_UNITS = frozenset({"at", "atm", "kg", "t", "m", "cm", "mm", "cm²", "m²", "mm²", "m/s", "kg/cm²", "%", "°", "/min",
                    "ps", "r", "s", "r₁", "mal", "fach", "min", "sek", "sec"})


def _open_bracket(text: str) -> bool:
    """Does *text* leave a bracket open whose content so far is a formula (an operator or a digit in it)?"""
    depth, start = 0, None
    for j, c in enumerate(text):
        if c in "([":
            if depth == 0:
                start = j
            depth += 1
        elif c in ")]" and depth:
            depth -= 1
    if depth <= 0 or start is None:
        return False
    inside = text[start + 1:]
    return any(op in inside for op in ("=", "+", "−", "·", "×", "/")) or bool(re.search(r"\d", inside))


def formula_break(before: str, after: str) -> str | None:
    """What a line break between the text *before* and the text *after* it would split -- a formula, a number
    from its unit, a figure's number from its word -- as "'last / first'" with the kind, or None when it falls
    between two words of a sentence.

    >>> formula_break("Fig. 3. Kurbelwinkel, r/L =", "1/4, Hub in 10 Teilen"), formula_break("Höchstdruck 25", "at, r/L")
    ("the formula 'r/L = / 1/4,'", "'25 / at,'")
    >>> formula_break("nach Anhang II, Fig.", "77."), formula_break("Qr/((m₁ +", "m₂)v₁²) = 0,25")
    ("'Fig. / 77.'", "the formula 'Qr/((m₁ + / m₂)v₁²)'")
    >>> formula_break("Halbkreis in 18 Teilen (Dürers", "Dreiteilung)"), formula_break("Füllung 30 %,", "schädlicher Raum")
    (None, None)
    """
    words, nxt = before.split(), after.split()
    if not words or not nxt:
        return None
    last, first = words[-1], nxt[0]
    if last.endswith(_OPEN_END) or first.startswith(_OPEN_START) or _open_bracket(before):
        start = max(0, len(words) - 2) if last in _OPEN_END else len(words) - 1
        return f"the formula {' '.join(words[start:]) + ' / ' + first!r}"
    if last.lower().lstrip("([„") in _NUMBERED and re.match(r"\(?[\dIVX]", first):
        return f"{last + ' / ' + first!r}"
    if _NUMBER.match(last) and first.lower().rstrip(".,;)") in _UNITS:
        return f"{last + ' / ' + first!r}"
    if last in ("%", "°") and len(first.rstrip(".,;)").rstrip("₀₁₂₃₄₅₆₇₈₉′″")) == 1:  # "10 % s", "30 ° C"
        return f"{last + ' / ' + first!r}"
    return None


def unbroken(text: str) -> str:
    """*text* with a no-break space wherever a line break would split a number or a formula
    (:func:`formula_break`), and after an initial (A. Baumann): a caption wrapped at its spaces then breaks
    only between words.

    >>> unbroken("Fig. 7. Höchstdruck 25 at, r/L = 1/5, Qr/((m₁ + m₂)v₁²) = 0,25.").split(" ")
    ['Fig.\xa07.', 'Höchstdruck', '25\xa0at,', 'r/L\xa0=\xa01/5,', 'Qr/((m₁\xa0+\xa0m₂)v₁²)\xa0=\xa00,25.']
    """
    out = list(text)
    for i, c in enumerate(text):
        if c != " ":
            continue
        # a formula, or an initial from its name (A. Baumann): kept on one line
        if formula_break(text[:i], text[i + 1:]) is not None or re.search(r"(?:^|\s)[A-ZÄÖÜ]\.$", text[:i]) \
                and text[i + 1:i + 2].isupper():
            out[i] = "\u00a0"
    return "".join(out)


def equation(text: str) -> str:
    """Equation numbers as the book prints them: ``Gl. 4_1`` -> ``Gl. (4₁)``, ``Gl. (4_1)`` likewise; a
    parenthesis round the reference stays its own (``(Gl. 298)`` -> ``(Gl. (298))``).

    >>> equation("Gl. 4_1, Tabelle 1; Gl. (h); Gl. 1")
    'Gl. (4₁), Tabelle 1; Gl. (h); Gl. (1)'
    >>> equation("Massenkräfte (Gl. 298) an allen Kolbenstellungen")
    'Massenkräfte (Gl. (298)) an allen Kolbenstellungen'
    """
    if "Gl." not in text:
        return text

    def sub(m: "re.Match[str]") -> str:
        num, low = m.group(2), m.group(3)
        return f"Gl. ({num}{low.translate(_SUB) if low else ''})"
    # a closing parenthesis is the number's only where it opened one
    return re.sub(r"Gl\. (\()?(\d+)(?:_(\d+))?(?(1)\))", sub, text)


#: (what a text must hold for the pattern to match, pattern, replacement) in the order
#: :func:`book_symbols` applies them, compiled once; a text without the first is not searched
#: (the captions of a long figure are read by the ten thousand).
_SYMBOLS = tuple((need, re.compile(p), r) for need, p, r in (
    (("lam",), r"(?<![A-Za-z])lam(?![A-Za-z])", "λ"),
    (("omega", "alpha", "beta", "kappa", "delta", "lambda", "pi"),
     r"\b(omega|alpha|beta|kappa|delta|lambda|pi)\b", lambda m: _GREEK[m.group(1)]),
    (("w",), r"(?<![A-Za-z])w(?=\d|\b)", "ω"),
    (("sqrt",), r"(?<=[\w)]) sqrt\b\s*(?=[(\dA-Za-z])", "√"),   # r sqrt 2 -> r√2
    (("sqrt",), r"\bsqrt\b\s*(?=[(\dA-Za-z])", "√"),
    (("-",), r"(?<=[\s(=])-(?=[\w(])", "−"),   # a minus, not a hyphen
    (("^",), r"\^(\d+)", lambda m: m.group(1).translate(_SUPER)),
    ((" degrees",), r"(\d) degrees\b", r"\1°"),
    # the books' indexed symbols written flat in a caption (P0, s1, r1, b2, ω6): their index below the line
    (("P0", "p0", "s0", "s1", "s2", "s3", "r1", "b1", "b2", "p1", "p2", "v1", "ω"),
     r"(?<![\w.])(P0|p0|s[0-3]|r1|b[12]|p[12]|v1|ω\d{1,2})(?![\w′'])", lambda m: lowered(m.group(1))),
))


#: A figure's letter written with an ASCII prime (6', P', W0', s1''): a letter, perhaps with its number, or a
#: number, right after something that is not a letter, and not followed by one (Baumann's keeps its apostrophe).
_ASCII_PRIME = re.compile(r"(?<![^\W\d_])(?<![′'])((?:[^\W\d_]|[0-9₀-₉])[0-9₀-₉]{0,3})('{1,3})(?![^\W\d_])")


def primed(text: str) -> str:
    """A figure's letters with the prime the books print (′, ″) for the ASCII one a construction names them with.

    >>> primed("Ordinate in 6', P' = r, W0'' and W₀', the crank's angle, the pistons' areas")
    "Ordinate in 6′, P′ = r, W0″ and W₀′, the crank's angle, the pistons' areas"
    """
    if "'" not in text:
        return text
    return _ASCII_PRIME.sub(lambda m: m.group(1) + ("′", "″", "‴")[len(m.group(2)) - 1], text)


def book_symbols(text: str) -> str:
    """ASCII stand-ins for the book's symbols replaced: ω, λ, √, exponents, subscripts.

    >>> book_symbols("r cos w + lam r cos 2w (w = 0), r sqrt 2, L^2, w5 = AOW5, with w")
    'r cos ω + λ r cos 2ω (ω = 0), r√2, L², ω₅ = AOW5, with ω'
    >>> book_symbols("(4/pi) r alpha, omega^2 R, crank at 90 degrees")
    '(4/π) r α, ω² R, crank at 90°'
    >>> book_symbols("Gegendruck P0, Füllung s1, r1/12, b2/2 = 3 b1 (G2, K17 and M2 are tags)")
    'Gegendruck P₀, Füllung s₁, r₁/12, b₂/2 = 3 b₁ (G2, K17 and M2 are tags)'
    >>> book_symbols("Ordinate in 6', unit force P' = r")
    'Ordinate in 6′, unit force P′ = r'
    """
    for need, pattern, rep in _SYMBOLS:
        if any(map(text.__contains__, need)):  # (no generator: every caption of a long figure asks)
            text = pattern.sub(rep, text)
    return equation(primed(text))
