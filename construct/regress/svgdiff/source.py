"""Reading an SVG document safely: a file's bytes, a bound on its elements before its tree is built, and the
XML parser that cannot be exploded by entities.

Part of :mod:`construct.regress.svgdiff`; :func:`~construct.regress.svgdiff.parse.parse_svg` reads its tree here
and turns it into shapes.

>>> read_tree(b'<svg><g/></svg>', "<bytes>").tag
'svg'
"""

from __future__ import annotations

import io
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import defusedxml.ElementTree as SafeET

from . import values
from .values import SvgFormatError, SvgTooLargeError

__all__ = ["read_drawing_file", "load_source", "most_elements", "cannot_declare_entities", "read_tree",
           "source_label"]


def read_drawing_file(path: Path) -> bytes:
    """The bytes of the SVG file at *path*: the one place the reader opens a file.

    Today a plain read, as before (``construct diff`` checks its files first:
    a regular file of bounded size).  The seam for the shared bounded reader of
    :mod:`construct.io` (a regular file of bounded size, FIFOs and devices
    refused at once) when it exists: one call to switch.
    """
    return path.read_bytes()


def load_source(source: str | Path | bytes, what: str) -> tuple[bytes | str, str]:
    """The document *source* names (text, bytes, or a path read) and how a report names it."""
    if isinstance(source, bytes):
        return source, "<bytes>"
    if isinstance(source, str) and source.lstrip().startswith(("<", "\ufeff<")):
        return source, "<string>"
    path = Path(source)
    try:
        return read_drawing_file(path), str(path)
    except OSError as exc:
        raise SvgFormatError(f"cannot read {what} {str(path)!r}: {exc.strerror or exc}") from None


def most_elements(data: bytes | str) -> int:
    """An upper bound of the elements *data* holds, in two scans of its bytes.

    Every element has a start tag: a ``<`` not followed by ``/`` (comments,
    CDATA and processing instructions only add to the bound).  Sound because
    entity declarations are refused (:func:`read_tree`): an entity's text
    could hold elements this count does not see.

    >>> most_elements(b'<svg><!-- < --><g><circle/></g></svg>')  # 3 elements; the comment counts 2
    5
    """
    if isinstance(data, str):
        return data.count("<") - data.count("</")
    return data.count(b"<") - data.count(b"</")


DECLARED_ENCODING = re.compile(rb"(?:\xef\xbb\xbf)?<\?xml[^>]*?encoding\s*=\s*[\"']([^\"']*)")


def cannot_declare_entities(data: bytes | str) -> bool:
    """Is *data* a document without a document type, in an encoding where its markup is ASCII bytes?

    Entities are declared only inside ``<!DOCTYPE ... [...]>``: without one, the
    standard library's parser reads no more than defusedxml's would.

    >>> cannot_declare_entities(b'<?xml version="1.0" encoding="utf-8"?><svg/>')
    True
    >>> cannot_declare_entities(b'<!DOCTYPE svg [<!ENTITY a "b">]><svg/>'), cannot_declare_entities("<svg/>".encode("utf-16"))
    (False, False)
    """
    if isinstance(data, str):
        return "<!DOCTYPE" not in data
    if data[:2] in (b"\xfe\xff", b"\xff\xfe") or b"\x00" in data[:4]:
        return False  # UTF-16 or UTF-32: the markup is not these bytes
    declared = DECLARED_ENCODING.match(data, 0, 512)
    if declared and declared.group(1).lower() not in (b"utf-8", b"utf8", b"us-ascii", b"ascii"):
        return False
    return b"<!DOCTYPE" not in data


def read_tree(data: bytes | str, label: str) -> ET.Element:
    """The XML tree of *data*, safe against XML bombs and refused beyond :data:`MAX_ELEMENTS` elements.

    A document that can declare entities (one with a document type, or in an
    encoding whose markup is not ASCII bytes) is read by :mod:`defusedxml`,
    which refuses entity declarations and external references outright,
    whatever the expat version.  Every other document -- every drawing this
    library writes -- by the standard library's C parser, which is as safe
    for it and 1.7 times as fast.  When the quick bound of the element count
    passes the limit, the elements are counted as they are read instead, and
    reading stops at the limit: the tree of a hostile file is never built
    beyond it.
    """
    limit = values.MAX_ELEMENTS
    xml = ET if cannot_declare_entities(data) else SafeET
    if most_elements(data) <= limit:
        return xml.fromstring(data)
    stream = io.StringIO(data) if isinstance(data, str) else io.BytesIO(data)
    events = xml.iterparse(stream, events=("start",))
    for n, _ in enumerate(events, 1):
        if n > limit:
            raise SvgTooLargeError(f"{label}: the drawing holds more than {limit:,} elements; refused",
                                   source=label, limit=limit)
    return events.root


def source_label(source: str | Path | bytes) -> str:
    """How a report names a source: its path, else ``<string>`` or ``<bytes>``."""
    if isinstance(source, bytes):
        return "<bytes>"
    if isinstance(source, str) and source.lstrip().startswith(("<", "\ufeff<")):
        return "<string>"
    return str(source)
