"""The SVG writer: every SVG the project emits is built by svgwrite, here.

Elements come from svgwrite's element factory with validation off
(``debug=False``: checking every attribute of every mark costs more than the
drawing itself).  Each mark's element is turned into an ElementTree element
once (:meth:`Writer.frozen`) and shared by every document that shows it --
the layered figure, the frames, the animation, the player -- so a mark costs
one serialisation per document, never a rebuild.

Output is byte-stable: svgwrite writes attributes in sorted order, numbers
reach it already formatted (:func:`fmt`), ids are given
by the caller (step and object name) so svgwrite's own counter
(``svgwrite.utils.AutoID``) is never asked, and every element after the
root's opening tag starts a line of its own.

>>> w = Writer()
>>> dwg = w.drawing(size=("10", "5"), viewBox="0 0 10 5")
>>> _ = dwg.add(w.frozen(w.factory.circle(center=("1", "2"), r="0.5", id="s0001-O", class_="pt")))
>>> print(w.text(dwg), end="")
<?xml version="1.0" encoding="utf-8" ?>
<svg baseProfile="full" height="5" version="1.1" viewBox="0 0 10 5" width="10" xmlns="http://www.w3.org/2000/svg" xmlns:ev="http://www.w3.org/2001/xml-events" xmlns:xlink="http://www.w3.org/1999/xlink">
<defs />
<circle class="pt" cx="1" cy="2" id="s0001-O" r="0.5" />
</svg>
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from typing import Any

import svgwrite
from svgwrite.etree import CDATA_TAG

__all__ = ["Writer", "Frozen", "XML_DECLARATION", "MARKER", "fmt"]

#: What svgwrite's ``Drawing.write`` puts first.
XML_DECLARATION = '<?xml version="1.0" encoding="utf-8" ?>\n'
#: An attribute svgwrite's Drawing always writes and our own markup never did: tests look for it.
MARKER = 'xmlns:ev="http://www.w3.org/2001/xml-events"'

def fmt(v: float, decimals: int = 2) -> str:
    """Fixed-point with *decimals* decimals, trailing zeros trimmed; never '-0'.

    >>> fmt(1.005), fmt(-0.0001), fmt(12.5), fmt(3.14159, 3)
    ('1', '0', '12.5', '3.142')
    """
    text = f"{v:.{decimals}f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


# Elements whose content is text: no line breaks are put inside them.
_TEXTUAL = {"text", "tspan", "title", "desc", "style", "script", CDATA_TAG}


class Frozen:
    """An svgwrite element turned into its ElementTree element once, addable to any svgwrite container."""

    __slots__ = ("xml", "elementname")

    def __init__(self, xml: ET.Element):
        self.xml = xml
        self.elementname = xml.tag

    def get_xml(self) -> ET.Element:
        return self.xml


class Writer:
    """svgwrite's element factory (validation off) and the document serialiser."""

    def __init__(self) -> None:
        #: ``factory.circle(...)``, ``factory.g(...)``, ...: svgwrite elements sharing one parameter set.
        self.factory = svgwrite.Drawing(debug=False, profile="full")

    def frozen(self, elem: Any) -> Frozen:
        """*elem* serialised to an ElementTree element now, to be shared by several documents."""
        return elem if isinstance(elem, Frozen) else Frozen(elem.get_xml())

    def drawing(self, **attrs: Any) -> Any:
        """A new top-level ``<svg>`` (svgwrite's Drawing) with *attrs*."""
        return svgwrite.Drawing(debug=False, profile="full", **attrs)

    def svg_element(self, dwg: Any) -> ET.Element:
        """The ElementTree of *dwg* with line breaks between elements (the bytes are part of the goldens)."""
        root = dwg.get_xml()
        _lines(root)
        return root

    def markup(self, dwg: Any) -> str:
        """*dwg* as markup without the XML declaration (to inline into HTML)."""
        return ET.tostring(self.svg_element(dwg), encoding="unicode")

    def text(self, dwg: Any) -> str:
        """*dwg* as a standalone SVG file's text, as svgwrite's ``Drawing.write`` lays it out."""
        return XML_DECLARATION + self.markup(dwg) + "\n"


def _lines(elem: ET.Element) -> None:
    """Every child element on a line of its own (idempotent: shared elements are visited again)."""
    stack = [elem]
    while stack:
        e = stack.pop()
        if e.tag in _TEXTUAL or len(e) == 0:
            continue
        if not e.text:
            e.text = "\n"
        for child in e:
            if child.tag != CDATA_TAG:
                child.tail = "\n"
            stack.append(child)
