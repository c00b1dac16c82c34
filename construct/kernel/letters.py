"""Captions in the figure's own letters: what the reader sees, not what the code calls it.

(Kernel module: :meth:`Builder.protocol <construct.kernel.instruments.Builder.protocol>`
writes every step's caption and group title through :func:`letter_protocol`,
so the protocol file, the player, the animation, the storyboard and the
error messages name the same letters; :mod:`construct.render.captions`
re-exports these names for the renderers.)

A step's caption is written by the construction with object names
(``Kreis um P12 durch D1``, ``T7.G.M1 im Schnitt von T7.G.Mr1 und T7.G.Mk1``,
``Mittelsenkrechte von EinfFinf``).  The figure prints other letters: the
division point P12 is lettered 12, the dead centre D1 is B (or 18), a helper
point shows the last part of its name while it is in use, and a compass
circle has no letter at all.  :class:`Reader` rewrites a caption once, from
data only (the marks' labels, the step that made each curve), so a
construction added later gets readable captions without writing any:

* a lettered object is named by its letter (P12 -> 12, D0 -> A, K0 -> q1);
* a helper point by the last part of its dotted name (T7.G.M1 -> M1), which
  the teaching frames tag while the point is made or used;
* a circle by its centre ("Kreis um 3"), a line by two of its points, the
  stroke line and the crank circle by their names in the books; a curve's own
  name in the caption of the step that draws it is left out (the figure has
  no letter for it: "Mittelsenkrechte c6.N4.m von ..." -> "Mittelsenkrechte von ...");
* two names written together (the segment ``D0P6``) are split and joined by a dash;
* the English text gets the book's symbols: w -> ω, lam -> λ, sqrt -> √, ^2 -> ².

One pass over each caption with an identifier pattern and dictionary
look-ups: linear in the caption, independent of the number of steps; a name
is looked at, its neighbours read only as far as a slot word or a noun can
reach.  What a figure shows of a caption is bounded (:data:`CAPTION_LIMIT`,
:func:`displayed`); the protocol keeps the whole text.

>>> r = Reader({"P12": ("point", "12", None, ()), "D1": ("point", "B", None, ()),
...             "T4.k": ("circle", None, "circle_through", ("P12", "D1"))})
>>> r.text("Kreis um P12 durch D1", "de")
'Kreis um 12 durch B'
>>> r.text("D1 where T4.k meets axis", "en", outputs=("D1",))
'B where the circle about 12 meets axis'
>>> r.text("segment P12D1, angle w = 2w, sqrt(L^2 + 8 r^2), lam cos 2w", "en")
'segment 12–B, angle ω = 2ω, √(L² + 8 r²), λ cos 2ω'
"""

from __future__ import annotations

import functools
import re
from typing import Mapping, Sequence

from .typography import book_symbols, equation, formula_break, lowered, number, primed, subscripts, unbroken

__all__ = ["Reader", "book_symbols", "equation", "subscripts", "lowered", "formula_break", "unbroken", "primed",
           "PLATE_CAPTION_LINES", "tag", "displayed", "number", "CAPTION_LIMIT",
           "TITLE_LIMIT", "letter_steps", "object_kind", "FIGURE_LETTER"]

#: What a letter of a figure looks like: a letter, perhaps with a number of at most two digits, subscripts or
#: primes (M2, S1, q10, U24, 5′, a′); a number below 100 with a prime.  A helper's name that is no such
#: letter (c135, Nb17, cPq3) is read as one by :func:`tag`.
FIGURE_LETTER = re.compile(r"[A-Za-zΑ-Ωα-ω][0-9]{0,2}[′″'₀-₉]*|[0-9]{1,2}[′″']?")

#: The most characters of a step's caption (or a group's title) a figure shows; a longer one is
#: cut and ends in "…".  The books' step captions are at most 82 characters; 400 is about three
#: lines of the default 960 px canvas.  Every frame of a figure is as tall as its longest
#: caption, so one step's caption must not grow without bound.
CAPTION_LIMIT = 400
#: The same for a figure's title or plate caption, which lists every parameter: the gallery's
#: longest is 366 characters; 1000 is about eight lines.
TITLE_LIMIT = 1000
#: The most lines a plate's caption runs to, as a book's: the figure's number and title, what it shows, whose.
PLATE_CAPTION_LINES = 3
#: How much of a caption is rewritten at most: rewriting shortens names (a helper ``T7.G.M1`` is
#: shown as M1, a step's own curve not at all), so more than the limit is read -- but not all of a
#: caption of megabytes, whose end no one sees.
_READ_LIMIT = 16 * CAPTION_LIMIT

#: An identifier as the constructions write object names: letters, digits, dots inside, a prime (U', U'.k;
#: not the English genitive: crank's).
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*(?:'(?![A-Za-z]))?(?:\.[A-Za-z0-9_]+)*")
#: Words after which the instruments' captions put an object's name ("Kreis um X durch Y", "X where a meets b",
#: "perpendicular to X at Y").
_SLOTS = {"um", "durch", "von", "und", "mit", "zu", "zur", "in", "auf", "about", "through", "where", "meets", "and",
          "of", "from", "with", "for", "to", "at", "on", "onto"}

#: Nouns after which a lower-case name is a word of the sentence ("crank circle", "axis line").
_NOUNS = {"circle", "line", "centre", "center", "kreis", "linie", "gerade"}
#: The word after a name, read no further than the longest noun and one character beyond it
#: (lower-casing never shortens a word, so a longer word is no noun).
_NEXT_WORD = re.compile(r"\s*([^ ]{0,%d})" % (max(map(len, _NOUNS)) + 1))
_LONGEST_SLOT = max(map(len, _SLOTS))


def _compound(text: str, start: int, end: int) -> bool:
    """Is text[start:end] joined to a word by a hyphen ("mid" in "mid-plane", "plane" in "mid-plane")?

    >>> _compound("mid-plane of the wheel", 0, 3), _compound("line mid meets", 5, 8)
    (True, False)
    """
    after = text[end:end + 2]
    before = text[max(0, start - 2):start]
    return (len(after) == 2 and after[0] == "-" and after[1].isalpha()) or (
        len(before) == 2 and before[1] == "-" and before[0].isalpha())


#: How many words and plain captions a :class:`Reader` keeps (a figure's are a few hundred; the words of a
#: caption of megabytes are not all kept).
_WORDS_KEPT = 100_000
_SPACES = re.compile(r"  +")


def _finished(text: str, lang: str) -> str:
    """A rewritten caption's spacing, articles and symbols as the figure prints them.

    >>> _finished("Kreis  um 3 durch (  P0 ) von Kreis um 2", "de")
    'Kreis um 3 durch (P₀ ) vom Kreis um 2'
    """
    # the captions of a figure recur in every build of it (a live sweep's, a test's): short ones are kept
    return _finish(text, lang) if len(text) <= TITLE_LIMIT else _finish.__wrapped__(text, lang)


@functools.lru_cache(maxsize=1 << 14)
def _finish(text: str, lang: str) -> str:
    text = _SPACES.sub(" ", text).replace(" :", ":").replace("( ", "(").strip()
    # "im Schnitt von Kreis um 3" reads better with the article the English already has
    if lang == "de":
        text = text.replace("von Kreis um", "vom Kreis um").replace("und Kreis um", "und dem Kreis um")
    else:
        text = text.replace(" the the ", " the ")
    return subscripts(book_symbols(text))


#: How the books name the objects every crank figure has.
_COMMON = {
    "axis": ("Hubachse", "the stroke line"),
    "crank": ("Kurbelkreis", "the crank circle"),
    "vert": ("Senkrechte durch O", "the perpendicular through O"),
}


def displayed(text: str, limit: int = CAPTION_LIMIT) -> str:
    """*text* as a figure shows it: at most *limit* characters, a cut one ending in "…".

    >>> displayed("Kreis um 3 durch 12"), displayed("x" * 1000, 10)
    ('Kreis um 3 durch 12', 'xxxxxxxxx…')
    """
    return text if len(text) <= limit else text[: limit - 1] + "…"


def tag(name: str, letters: "frozenset[str] | set[str]" = frozenset()) -> str:
    """The short name of an unlettered point: the last part of its dotted name, read as a letter.

    A name that is no letter of a figure (:data:`FIGURE_LETTER`) is read as one: a capital with a family's
    small letters and a number keeps the capital and the number (``Ab1``, the A of crank point b1: A1;
    ``Ehs1``: E1), small letters before a capital name the family by its last letter (``cPq3``, Brauer's
    point on the ray q: Q3; ``iV0``: V0).  Where the letter is one the figure already uses (the helper
    ``ordD.A`` beside the dead centre A), a single capital is written small, a small letter takes a prime,
    and anything else keeps the part before it.  A name's ASCII prime is written as the figure's (U' : U′).

    >>> tag("T7.G.M1"), tag("ordD.A", {"A", "B"}), tag("D.2", {"2"}), tag("Dx"), tag("to42.a", {"a"})
    ('M1', 'a', 'D2', 'Dx', 'a′')
    >>> tag("Ab1"), tag("Zt10"), tag("Ehs1"), tag("cPq3"), tag("ePV10"), tag("iV0"), tag("U'")
    ('A1', 'Z10', 'E1', 'Q3', 'V10', 'V0', 'U′')
    """
    parts = name.split(".")
    last = _as_letter(parts[-1]).replace("'", "′")
    if last in letters:
        if len(last) == 1 and last.isupper():
            return last.lower()
        if len(last) == 1 and last.islower():
            return last + "′"
        if len(parts) > 1:
            return parts[-2].rsplit(".", 1)[-1] + last
    return last


_FAMILY = re.compile(r"([A-Z])[a-z]{1,3}([0-9]{1,2})")
_FAMILY_AFTER = re.compile(r"[a-z]{1,3}[A-Z]{0,2}([A-Za-z])([0-9]{1,2})")


def _as_letter(part: str) -> str:
    """A part of a name as a figure letters it (see :func:`tag`); as it stands when no rule reads it."""
    if FIGURE_LETTER.fullmatch(part):
        return part
    m = _FAMILY.fullmatch(part)
    if m:
        return m.group(1) + m.group(2)
    m = _FAMILY_AFTER.fullmatch(part)
    if m:
        return m.group(1).upper() + m.group(2)
    return part


class Reader:
    """Rewrites captions for one figure.

    *objects* maps each drawable object's name to (kind, label, maker op, maker inputs),
    kind one of point, line, circle, curve, area.
    """

    def __init__(self, objects: Mapping[str, tuple[str, str | None, str | None, tuple[str, ...]]],
                 called: "Mapping[str, Sequence[str]] | None" = None):
        self.objects = objects
        self.points = {n for n, v in objects.items() if v[0] == "point"}
        #: What the construction calls a line or circle (:meth:`Builder.call
        #: <construct.kernel.instruments.Builder.call>`): {name: (German, English)}.
        self.called = dict(called or {})
        self._calling: set[str] = set()
        #: Tokens that name nothing (no object, no pair of points): the words of the sentences, looked up once.
        self._words: set[str] = set()
        #: The captions that name nothing, read: the same at every step that writes them.
        self._plain_texts: dict[tuple[str, str, bool], str] = {}
        self._point_letters: dict[str, str] = {}

    # -- one name -------------------------------------------------------------------------
    def point(self, name: str) -> str:
        """The letter a point goes by in the figure (see :func:`tag`)."""
        got = self._point_letters.get(name)
        if got is None:  # (a point is named by every step that uses it)
            got = self._point_letters[name] = self._point(name)
        return got

    def _point(self, name: str) -> str:
        label = self.objects[name][1]
        if label:
            return label
        parts = name.rsplit(".", 1)
        # the helper of a lettered point, named for it (X.c45: the piston position of 45°): X(45°); a small
        # letter before it names a family of helpers (u.T1: the apex T1 of the division u), not the point
        head = parts[0].rsplit(".", 1)[-1] if len(parts) == 2 else ""
        other = self.objects.get(parts[-1]) if len(head) == 1 and head.isupper() else None
        if other is not None and other[1]:
            return f"{parts[0].rsplit('.', 1)[-1]}({other[1]})"  # X.c45, the piston position of 45°: X(45°)
        return tag(name, self.letters)

    @functools.cached_property
    def letters(self) -> frozenset[str]:
        return frozenset(v[1] for v in self.objects.values() if v[1])

    def curve_points(self, name: str) -> list[str]:
        """The points the description of a curve names (a circle's centre, two points of a line)."""
        kind, label, op, inputs = self.objects[name]
        if label or name in _COMMON:
            return []
        if name in self.called:  # called by what it is (the perpendicular at m4): the points named in that
            return [p for p in _NAME.findall(self.called[name][1]) if p in self.points]
        pts = [p for p in inputs if p in self.points]
        if kind == "line" and op == "line":
            return pts[:2]
        return pts[:1]

    def curve(self, name: str, lang: str) -> str:
        """A lettered or described line or circle."""
        kind, label, op, inputs = self.objects[name]
        if label:
            return label
        i = 0 if lang == "de" else 1
        if name in self.called and name not in self._calling:  # in the figure's letters (a call names others)
            self._calling.add(name)
            try:
                return self.text(self.called[name][i], lang, whole=True)
            finally:
                self._calling.discard(name)
        if name in _COMMON:
            return _COMMON[name][i]
        pts = [p for p in inputs if p in self.points]
        if kind == "circle" and pts:
            return ("Kreis um ", "the circle about ")[i] + self.point(pts[0])
        if kind == "line" and len(pts) >= 2 and op == "line":
            return ("Gerade ", "the line ")[i] + self._pair(self.point(pts[0]), self.point(pts[1]))
        if kind == "line" and pts:
            return ("Gerade durch ", "the line through ")[i] + self.point(pts[0])
        return ("Kreis", "the circle")[i] if kind == "circle" else ("Gerade", "the line")[i]

    @staticmethod
    def _pair(a: str, b: str) -> str:
        # Two single capitals read as a segment (AB); numbers and primes need a dash (3–6).
        return a + b if len(a) == 1 == len(b) and a.isalpha() and b.isalpha() else f"{a}–{b}"

    @functools.cached_property
    def _point_lengths(self) -> tuple[int, ...]:
        return tuple(sorted({len(p) for p in self.points}))

    def _split(self, token: str) -> tuple[str, str] | None:
        """``D0P6`` -> (D0, P6): two point names written together, if the token is exactly that."""
        if len(token) > 64:  # no point name is this long: not cached, a caption of megabytes stays out of memory
            return self._split_once(token)
        cache = self.__dict__.setdefault("_split_cache", {})
        got = cache.get(token, cache)
        if got is cache:  # the words of the captions recur on every step ("Kreis", "durch")
            got = cache[token] = self._split_once(token)
            if len(cache) > 100_000:
                cache.clear()
        return got

    def _split_once(self, token: str) -> tuple[str, str] | None:
        if token[1:].islower() and "." not in token and not any(c.isdigit() for c in token):
            return None  # a word ("Kreis", "durch"): not two names
        # Only cuts where both halves have the length of some point's name are tried, shortest
        # first: a token of megabytes is not sliced at every character.
        lengths = self._point_lengths
        n = len(token)
        for i in lengths:
            if i >= n:
                break
            if n - i in lengths and token[:i] in self.points and token[i:] in self.points:
                return token[:i], token[i:]
        return None

    # -- a caption ------------------------------------------------------------------------
    def mentioned(self, caption: str) -> set[str]:
        """The points *caption* names, directly, as a pair (D0P6) or as the centre of a circle it names."""
        out: set[str] = set()
        for m in _NAME.finditer(caption):
            token = m.group(0)
            obj = self.objects.get(token)
            if obj is None:
                out.update(self._split(token) or ())
            elif obj[0] == "point":
                out.add(token)
            elif obj[0] in ("circle", "line"):
                out.update(self.curve_points(token))
        return out

    def text(self, caption: str, lang: str, outputs: Sequence[str] = (), *, whole: bool = False) -> str:
        """*caption* (in *lang*, "de" or "en") in the figure's letters; *outputs* are the step's own objects.

        What a figure shows: at most :data:`CAPTION_LIMIT` characters (:func:`displayed`);
        *whole*: the whole text, as the protocol keeps it.
        """
        cut = len(caption) > _READ_LIMIT and not whole
        if cut:
            caption = caption[:_READ_LIMIT]
        # A caption that names nothing (no token is an object or a pair: "the ray meets the vertical through
        # the known point", written by the hundred in a figure) reads the same at every step: read once.
        key = (caption, lang, whole)
        known = self._plain_texts.get(key)
        if known is not None:
            return known
        objects = self.objects
        words = self._words
        out: list[str] = []
        pos = 0
        names = False  # has a token been an object's name (the text then depends on *outputs*)?
        for m in _NAME.finditer(caption):
            token = m.group()
            if token in words:  # a word of the sentences, no object's name nor two of them: most tokens
                continue
            obj = objects.get(token)
            if obj is None:
                pair = self._split(token)
                if pair is None:
                    if len(token) <= 64 and len(words) < _WORDS_KEPT:  # (no name is longer: see _split)
                        words.add(token)
                    continue
                start, end = m.span()
                if _compound(caption, start, end):
                    continue  # half of a hyphenated word ("mid-plane"): a word of the sentence, never a name
                rep = self._pair(self.point(pair[0]), self.point(pair[1]))
            else:
                names = True
                start, end = m.span()
                rep = self._named(token, obj, caption, start, end, outputs, lang)
                if rep is None:
                    continue
            out.append(caption[pos:start])
            out.append(rep)
            pos = end
        if out:
            out.append(caption[pos:])
            text = "".join(out)
        else:
            text = caption
        text = _finished(text, lang)
        if not whole:
            if cut and not text.endswith("…"):
                text = text[: CAPTION_LIMIT - 1] + "…"
            text = displayed(text)
        if not names and len(caption) <= TITLE_LIMIT and len(self._plain_texts) < _WORDS_KEPT:
            self._plain_texts[key] = text
        return text

    def _named(self, token: str, obj: tuple, caption: str, start: int, end: int, outputs: Sequence[str],
               lang: str) -> str | None:
        """What the object *token* at caption[start:end] is written as (None: left as it stands, a word)."""
        if _compound(caption, start, end):
            return None  # half of a hyphenated word ("mid-plane"): a word of the sentence, never a name
        kind, label = obj[0], obj[1]
        word = token.isalpha() and token.islower()
        if word and _NEXT_WORD.match(caption, end).group(1).lower() in _NOUNS:
            return None  # a word of the sentence that names a thing ("crank circle about O")
        if (kind in ("line", "circle") and not label and token in outputs
                and not (token.isalpha() and token.isupper())):
            return ""  # the step's own helper line or circle: the figure has no letter for it
        if word and (not self._names_slot(caption, start, end) or self._in_phrase(caption, end)):
            return None  # an ordinary word that is also a name ("crank centre", "the axis", "back pressure")
        if kind == "length":  # a length goes by its own letter (the rod length L is the rod's L)
            return label or token.rsplit(".", 1)[-1]
        if kind == "point":
            return self.point(token)
        if kind in ("line", "circle"):
            return self.curve(token, lang)
        return None

    def _in_phrase(self, text: str, end: int) -> bool:
        """Does a small word at text[..end] run on into a phrase ("admission and back pressure")?  The word
        after a name is a slot word, punctuation or the end; after a word of a phrase, another word."""
        m = _NEXT_WORD.match(text, end)
        nxt = m.group(1) if m else ""
        return bool(nxt) and nxt.isalpha() and nxt.islower() and nxt not in _SLOTS and nxt not in self.objects

    @staticmethod
    def _names_slot(text: str, start: int, end: int) -> bool:
        """Is the word at text[start:end] where a caption names an object ("Kreis um top", "where axis meets")?

        The word before it (``text[:start].rstrip().rsplit(" ", 1)[-1]``), read back no
        further than the longest slot word: a caption's length is not read per name.
        """
        if text[end:end + 1] == "-":
            return False
        j = start
        while j > 0 and text[j - 1].isspace():
            j -= 1
        lo = max(0, j - _LONGEST_SLOT - 1)
        space = text.rfind(" ", lo, j)
        if space < 0 and lo > 0:
            return False  # longer than any slot word
        return text[space + 1:j].lower() in _SLOTS


def object_kind(obj: object) -> str | None:
    """What a caption calls a constructed value: point, line, circle, curve, area, length (None: a number)."""
    from .geometry import Circle, Length, Line, Point

    if isinstance(obj, Point):
        return "point"
    if isinstance(obj, Line):
        return "line"
    if isinstance(obj, Circle):
        return "circle"
    if hasattr(obj, "rings"):
        return "area"
    if hasattr(obj, "curve_points"):
        return "curve"
    if isinstance(obj, Length):
        return "length"  # a compass opening laid off: named like a helper point (J.h1 -> h1)
    return None


def letter_steps(steps: Sequence, objects: Mapping[str, object],
                 called: "Mapping[str, Sequence[str]] | None" = None) -> list:
    """*steps* with every caption in the figure's letters.

    *objects*: the values the steps made (name -> Point, Line, ...); each step's
    ``labels`` letter its outputs; *called*: what the construction calls a line or circle (its names still
    in object names: ``{"lv4": ("Senkrechte in m4", "perpendicular at m4")}``).  A caption already in letters is left as it is
    (the protocol marks itself ``captions = letters``: a second reading could take a
    letter for another object's name).

    >>> from construct.kernel.instruments import Builder
    >>> b = Builder("demo", givens={})
    >>> _ = b.given_point("A", 0.0, 0.0); _ = b.given_point("B", 2.0, 0.0, label="E")
    >>> _ = b.circle_through("T7.k", "A", "B"); _ = b.circle_through("T7.m", "B", "A")
    >>> from construct.kernel.rules import toward
    >>> _ = b.intersect("T7.G.M1", "T7.k", "T7.m", rule=toward(dy=1.0))
    >>> [s.caption.en for s in b.protocol().steps][1:]
    ['point E given', 'circle about A through E', 'circle about E through A', 'M1 where the circle about A meets the circle about E']
    """
    from dataclasses import replace

    from .protocol import Caption

    makers = {n: s for s in steps for n in s.outputs}
    table: dict[str, tuple[str, str | None, str | None, tuple[str, ...]]] = {}
    for s in steps:
        labels = dict(s.labels)
        for name in s.outputs:
            kind = object_kind(objects.get(name))
            if kind is not None:
                table[name] = (kind, labels.get(name), makers[name].op, tuple(makers[name].inputs))
    reader = Reader(table, called)
    out = []
    for s in steps:
        de = reader.text(s.caption.de, "de", s.outputs, whole=True)
        en = reader.text(s.caption.en, "en", s.outputs, whole=True)
        out.append(s if (de, en) == (s.caption.de, s.caption.en) else replace(s, caption=Caption(de, en)))
    return out
