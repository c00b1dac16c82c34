"""Captions broken into lines in time linear in their length: the lines :mod:`textwrap` gives.

:func:`textwrap.wrap` breaks a word longer than a line by slicing it off the
front and keeping the rest (``chunk[end:]``), a copy of the whole remainder
per line: a caption that is one word of n characters costs n²/width (a 3 MB
word took 12 s, 50 MB did not finish).  :func:`wrap` takes the same chunks
(textwrap's own word pattern) and the same decisions, but walks a long word
with an offset, so every character is looked at a bounded number of times.
The lines are exactly textwrap's -- the figures' bytes do not change -- which
the tests hold for every caption of the gallery and for random text.

>>> wrap("Kreis um 3 durch 12, der Schnitt mit der Hubachse", 20)
['Kreis um 3 durch 12,', 'der Schnitt mit der', 'Hubachse']
>>> wrap("x" * 45, 20)
['xxxxxxxxxxxxxxxxxxxx', 'xxxxxxxxxxxxxxxxxxxx', 'xxxxx']
>>> wrap("Kurbel-Schub-Getriebe", 10, break_on_hyphens=True)
['Kurbel-', 'Schub-', 'Getriebe']
>>> shorten("Schritte 1-9:   die Teilung  des Kurbelkreises", 30, placeholder=" …")
'Schritte 1-9: die Teilung …'
"""

from __future__ import annotations

import re
import textwrap

__all__ = ["wrap", "shorten"]

#: The whitespace textwrap turns into spaces and splits at (ASCII only, as textwrap does).
_WHITESPACE = "\t\n\x0b\x0c\r "
_TO_SPACE = {ord(c): " " for c in _WHITESPACE}
_SPACES = re.compile(f"([{re.escape(_WHITESPACE)}]+)")
#: textwrap's own word pattern (words, hyphenated parts, em-dashes): the same chunks, so the same lines.
_WORDS = textwrap.TextWrapper.wordsep_re


def _chunks(text: str, break_on_hyphens: bool) -> list[str]:
    text = text.expandtabs(8).translate(_TO_SPACE)
    return [c for c in (_WORDS if break_on_hyphens else _SPACES).split(text) if c]


def wrap(text: str, width: int, *, break_on_hyphens: bool = False, max_lines: int | None = None,
         placeholder: str = " [...]") -> list[str]:
    """``textwrap.wrap(text, width, break_long_words=True, ...)``, linear in ``len(text)``.

    The defaults of textwrap otherwise (tabs expanded to 8, whitespace made
    spaces, whitespace dropped at the ends of lines, no indents, no sentence
    endings fixed).
    """
    if width <= 0:
        raise ValueError(f"invalid width {width!r} (must be > 0)")
    if max_lines is not None and len(placeholder.lstrip()) > width:
        raise ValueError("placeholder too large for max width")
    chunks = _chunks(text, break_on_hyphens)
    n = len(chunks)
    i, off = 0, 0  # the next chunk is chunks[i][off:]: a long word is walked, never copied
    ends: dict[int, int] = {}  # where chunk i's text ends (len of its rstrip), looked up once per chunk

    def rest_blank(i: int, off: int) -> bool:
        # str.strip() == '' on the rest of a chunk: O(1) per line, not a copy of the rest each time
        end = ends.get(i)
        if end is None:
            end = ends[i] = len(chunks[i].rstrip())
        return end <= off

    lines: list[str] = []
    while i < n:
        cur: list[str] = []
        cur_len = 0
        if lines and rest_blank(i, off):
            i, off = i + 1, 0  # a line starts with whitespace: drop it (not at the very beginning)
        while i < n:
            size = len(chunks[i]) - off
            if cur_len + size > width:
                break
            cur.append(chunks[i][off:] if off else chunks[i])
            cur_len += size
            i, off = i + 1, 0
        if i < n and len(chunks[i]) - off > width:
            # the next chunk fits on no line: as much of it as fits here (after a hyphen if it may)
            space = width - cur_len
            end = off + space
            c = chunks[i]
            if break_on_hyphens:
                hyphen = c.rfind("-", off, end)
                if hyphen > off and c[off:hyphen].strip("-"):
                    end = hyphen + 1
            cur.append(c[off:end])
            off = end
            cur_len = sum(map(len, cur))
        if cur and not cur[-1].strip():
            cur_len -= len(cur[-1])
            del cur[-1]
        if not cur:
            continue
        if (max_lines is None or len(lines) + 1 < max_lines
                or (i >= n or (n - i == 1 and rest_blank(i, off))) and cur_len <= width):
            lines.append("".join(cur))
            continue
        # the last line allowed: end it with the placeholder where that fits
        while cur:
            if cur[-1].strip() and cur_len + len(placeholder) <= width:
                cur.append(placeholder)
                lines.append("".join(cur))
                break
            cur_len -= len(cur[-1])
            del cur[-1]
        else:
            if lines:
                prev = lines[-1].rstrip()
                if len(prev) + len(placeholder) <= width:
                    lines[-1] = prev + placeholder
                    break
            lines.append(placeholder.lstrip())
        break
    return lines


def shorten(text: str, width: int, *, placeholder: str = " [...]") -> str:
    """``textwrap.shorten(text, width, placeholder=...)``: whitespace collapsed, cut to one line of *width*."""
    lines = wrap(" ".join(text.strip().split()), width, break_on_hyphens=True, max_lines=1,
                 placeholder=placeholder)
    return "\n".join(lines)
