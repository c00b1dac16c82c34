"""The SVG writer: every SVG the project emits is built by svgwrite, here.

Elements come from svgwrite's element factory with validation off
(``debug=False``: checking every attribute of every mark costs more than the
drawing itself); the plentiful plain ones (groups, points' circles, lines, paths, letters, ``<set>``)
are :class:`Element`, which gives svgwrite's element without its machinery.
Each mark's element is written once (:meth:`Writer.frozen`) and its markup
shared by every document that shows it -- the layered figure, the frames,
the animation, the player: a mark costs one serialisation in all, never a
rebuild.  Documents are written straight from their elements (:func:`_emit`),
not through ElementTree, byte for byte as ElementTree's ``tostring`` (with
svgwrite's CDATA patch) writes their trees (tests/test_render_svgdoc.py holds
the two equal).

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

import functools
import re
import xml.etree.ElementTree as ET
from typing import Any, Callable

import svgwrite
from svgwrite.etree import CDATA_TAG
from svgwrite.utils import iterflatlist, strlist

__all__ = ["Writer", "Element", "Frozen", "XML_DECLARATION", "MARKER", "fmt", "with_attribute"]

#: What svgwrite's ``Drawing.write`` puts first.
XML_DECLARATION = '<?xml version="1.0" encoding="utf-8" ?>\n'
#: An attribute svgwrite's Drawing always writes and our own markup never did: tests look for it.
MARKER = 'xmlns:ev="http://www.w3.org/2001/xml-events"'

def fmt(v: float, decimals: int = 2) -> str:
    """Fixed-point with *decimals* decimals, trailing zeros trimmed; never '-0'.

    >>> fmt(1.005), fmt(-0.0001), fmt(12.5), fmt(3.14159, 3)
    ('1', '0', '12.5', '3.142')
    """
    text = (f"{v:.2f}" if decimals == 2 else f"{v:.{decimals}f}").rstrip("0").rstrip(".")  # (a constant spec: faster)
    return "0" if text in ("-0", "") else text


# Elements whose content is text: no line breaks are put inside them.
_TEXTUAL = {"text", "tspan", "title", "desc", "style", "script", CDATA_TAG}


class Frozen:
    """An element written once, addable to any svgwrite container: its markup (:attr:`markup`, every
    child on a line of its own) is made when it is frozen and copied into every document that holds it;
    its ElementTree element only when asked (:meth:`get_xml`, for a tree a caller changes)."""

    __slots__ = ("source", "markup", "elementname", "_xml")

    def __init__(self, source: Any, markup: str):
        self.source = source
        self.markup = markup
        self.elementname = source.elementname
        self._xml: ET.Element | None = None

    def get_xml(self) -> ET.Element:
        if self._xml is None:
            self._xml = self.source.get_xml()
            _lines(self._xml)
        return self._xml


class Element:
    """An element as svgwrite's factory makes it with validation off, without its machinery: the same
    attributes (``class_`` -> ``class``, ``data_step`` -> ``data-step``), ``add``, ``elements``, ``attribs``
    and the same ElementTree element from :meth:`get_xml`.  The factory makes the plentiful plain ones so
    (:meth:`Writer.__init__`): a group per step and layer, made again for every frame and document, a
    point's circle, an animation's ``<set>`` -- through svgwrite's classes they cost a tenth of rendering.

    >>> Element("g", class_="step cur", data_step="3").get_xml().attrib
    {'class': 'step cur', 'data-step': '3'}
    """

    __slots__ = ("elementname", "attribs", "elements", "text")

    def __init__(self, elementname: str, **extra: Any):
        self.elementname = elementname
        names = _ATTRIBUTE_NAMES
        self.attribs = {names.get(k) or _attribute_name(k): v for k, v in extra.items()}
        self.elements: list[Any] = []
        #: the element's text (a ``<text>``'s), None for none
        self.text: Any = None

    def add(self, element: Any) -> Any:
        self.elements.append(element)
        return element

    def __getitem__(self, key: str) -> Any:
        return self.attribs[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self.attribs[key] = value

    def get_xml(self) -> ET.Element:
        attrib = {}
        for attribute, value in sorted(self.attribs.items()):
            if value is not None:
                value = str(value)
                if value:  # svgwrite leaves empty attributes out
                    attrib[attribute] = value
        xml = ET.Element(self.elementname, attrib)
        if self.text is not None:
            xml.text = str(self.text)
        if self.elements:
            xml.extend([element.get_xml() for element in self.elements])
        return xml


#: A keyword's attribute name (class_ -> class, data_step -> data-step), by keyword: a few recur thousands of times.
_ATTRIBUTE_NAMES: dict[str, str] = {}


def _attribute_name(keyword: str) -> str:
    name = _ATTRIBUTE_NAMES[keyword] = keyword.rstrip("_").replace("_", "-")
    return name


def _set(**extra: Any) -> Any:
    """svgwrite's ``factory.set``; one naming its target element (``href=``) is svgwrite's own."""
    if "href" in extra:
        return svgwrite.animate.Set(debug=False, profile="full", **extra)
    return Element("set", **extra)


def _circle(center: tuple[Any, Any] = (0, 0), r: Any = 1, **extra: Any) -> Element:
    """svgwrite's ``factory.circle``: *center* -> cx, cy."""
    e = Element("circle", **extra)
    e.attribs["cx"], e.attribs["cy"], e.attribs["r"] = center[0], center[1], r
    return e


def _line(start: tuple[Any, Any] = (0, 0), end: tuple[Any, Any] = (0, 0), **extra: Any) -> Element:
    """svgwrite's ``factory.line``: *start* -> x1, y1 and *end* -> x2, y2."""
    e = Element("line", **extra)
    e.attribs["x1"], e.attribs["y1"] = start
    e.attribs["x2"], e.attribs["y2"] = end
    return e


def _text(text: Any, insert: Any = None, x: Any = None, y: Any = None, **extra: Any) -> Any:
    """svgwrite's ``factory.text``; one set at *x*, *y* (every letter's) is an :class:`Element`, its positions
    written as svgwrite writes them."""
    if insert is not None or any(k in extra for k in ("dx", "dy", "rotate")):
        return svgwrite.text.Text(text, insert=insert, x=x, y=y, debug=False, profile="full", **extra)
    e = Element("text", **extra)
    e.text = text
    if x is not None:
        e.attribs["x"] = strlist(list(iterflatlist(x)), " ")
    if y is not None:
        e.attribs["y"] = strlist(list(iterflatlist(y)), " ")
    return e


def _path(d: Any = None, **extra: Any) -> Any:
    """svgwrite's ``factory.path``; a path given as one string (every mark's) is an :class:`Element`."""
    if isinstance(d, str):
        return Element("path", d=d, **extra)
    return svgwrite.path.Path(d=d, debug=False, profile="full", **extra)


class Writer:
    """svgwrite's element factory (validation off) and the document serialiser."""

    def __init__(self) -> None:
        #: ``factory.circle(...)``, ``factory.g(...)``, ...: svgwrite elements sharing one parameter set
        #: (``g``, ``set``, ``circle``, ``line`` and a ``path`` given as a string: an :class:`Element`).
        self.factory = svgwrite.Drawing(debug=False, profile="full")
        self.factory.g = functools.partial(Element, "g")
        self.factory.set = _set
        self.factory.circle = _circle
        self.factory.line = _line
        self.factory.path = _path
        self.factory.text = _text

    def frozen(self, elem: Any) -> Frozen:
        """*elem* written now, to be shared by several documents."""
        if isinstance(elem, Frozen):
            return elem
        out: list[str] = []
        _emit(elem, out, True)
        return Frozen(elem, "".join(out))

    def drawing(self, **attrs: Any) -> Any:
        """A new top-level ``<svg>`` (svgwrite's Drawing) with *attrs*."""
        return svgwrite.Drawing(debug=False, profile="full", **attrs)

    def svg_element(self, dwg: Any) -> ET.Element:
        """The ElementTree of *dwg* with line breaks between elements (the bytes are part of the goldens)."""
        root = dwg.get_xml()
        _lines(root)
        return root

    def markup(self, dwg: Any) -> str:
        """*dwg* as markup without the XML declaration (to inline into HTML): what :meth:`svg_element`'s
        tree serialises to, written straight from the elements (:func:`_emit`)."""
        out: list[str] = []
        _emit(dwg, out, True)
        return "".join(out)

    def text(self, dwg: Any) -> str:
        """*dwg* as a standalone SVG file's text, as svgwrite's ``Drawing.write`` lays it out."""
        return XML_DECLARATION + self.markup(dwg) + "\n"


def with_attribute(text: str, tag: str, cls: str, attr: str, value: Callable[[str], str]) -> str:
    """*text* (markup this writer wrote) with the attribute *attr* of every *tag* element of class *cls* set to
    *value* of what it was: one document's own change to elements it shares with others (each written once, its
    markup shared), made on its text rather than on a copy of its whole tree.  An attribute value holds no
    ``>`` or quote here (:func:`_escape_attribute`).

    >>> with_attribute('<g><circle class="pt a" r="2" /><circle class="b" r="2" /></g>', "circle", "pt", "r",
    ...                lambda r: fmt(float(r) * 1.5))
    '<g><circle class="pt a" r="3" /><circle class="b" r="2" /></g>'
    """
    opening = re.compile("<" + re.escape(tag) + r"(?![\w-])[^>]*>")
    own = re.compile(' ' + re.escape(attr) + '="([^"]*)"')

    def changed(m: re.Match) -> str:
        found = _CLASS.search(m.group(0))
        if found is None or cls not in found.group(1).split():
            return m.group(0)
        return own.sub(lambda a: f' {attr}="{value(a.group(1))}"', m.group(0), count=1)

    return opening.sub(changed, text)


_CLASS = re.compile(' class="([^"]*)"')


def _write(elem: ET.Element, out: list[str]) -> None:
    """*elem* and its tail as ``ET.tostring(elem, encoding="unicode")`` writes them (svgwrite's CDATA
    elements as CDATA sections, without a tail)."""
    if elem.tag == CDATA_TAG:
        out.append(CDATA_TAG % elem.text)
        return
    _open_close(elem, out)
    tail = elem.tail
    if tail:
        out.append(tail if tail == "\n" else _escape_text(tail))  # (the line break after nearly every element)


def _open_close(elem: ET.Element, out: list[str]) -> None:
    tag = elem.tag
    if not isinstance(tag, str) or "{" in tag:
        raise TypeError(f"the SVG writer writes plain tags only, got {tag!r}")  # ElementTree's namespaces
    out.append("<" + tag)
    attrib = elem.attrib
    if attrib:
        if _ATTRIBUTE_ESCAPED.search("".join(attrib.values())) is None:  # (nearly always: numbers, classes, ids)
            out.append("".join([f' {k}="{v}"' for k, v in attrib.items()]))
        else:
            for k, v in attrib.items():
                out.append(f' {k}="{_escape_attribute(v)}"')
    text = elem.text
    if text or len(elem):
        out.append(">")
        if text:
            out.append(_escape_text(text))
        for child in elem:
            _write(child, out)
        out.append("</" + tag + ">")
    else:
        out.append(" />")


def _escape_text(text: str) -> str:
    """Character data as ElementTree escapes it."""
    if "&" in text:
        text = text.replace("&", "&amp;")
    if "<" in text:
        text = text.replace("<", "&lt;")
    if ">" in text:
        text = text.replace(">", "&gt;")
    return text


#: What an attribute value escapes (:func:`_escape_attribute`).
_ATTRIBUTE_ESCAPED = re.compile('[&<>"\r\n\t]')
#: What an attribute value escapes but the quote (an opening tag's attributes are checked so, their quotes counted).
_TEXT_ESCAPED = re.compile('[&<>\r\n\t]')


def _escape_attribute(text: str) -> str:
    """An attribute value as ElementTree escapes it: as text, and quotes and line ends too."""
    text = _escape_text(text)
    if '"' in text:
        text = text.replace('"', "&quot;")
    if "\r" in text:
        text = text.replace("\r", "&#13;")
    if "\n" in text:
        text = text.replace("\n", "&#10;")
    if "\t" in text:
        text = text.replace("\t", "&#09;")
    return text


def _lines(elem: ET.Element) -> None:
    """Every child element on a line of its own (idempotent)."""
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


#: svgwrite's own ``get_xml`` (its attributes and children, nothing else): elements of a class that keeps it
#: are written straight (:func:`_emit`), as an :class:`Element` is.
_BASE_GET_XML = svgwrite.base.BaseElement.get_xml


def _emit(elem: Any, out: list[str], lines: bool) -> None:
    """*elem* (an :class:`Element`, a :class:`Frozen`, an svgwrite element) as markup, as its ElementTree
    element laid out by :func:`_lines` (when *lines*: not inside a textual element) serialises, without its
    tail -- written straight from its attributes and children rather than through ElementTree."""
    kind = type(elem)
    if kind is Frozen:
        out.append(elem.markup)
        return
    if kind is Element:
        text = elem.text
        if text is not None:
            text = str(text)
        values = []
        for k, v in sorted(elem.attribs.items()):
            if v is not None:
                if type(v) is not str:
                    v = str(v)
                if v:
                    values.append((k, v))
    elif kind.get_xml is _BASE_GET_XML or isinstance(elem, svgwrite.Drawing):
        if isinstance(elem, svgwrite.Drawing):
            attribs = elem.attribs  # (what Drawing.get_xml sets before svgwrite's own)
            attribs["xmlns"] = "http://www.w3.org/2000/svg"
            attribs["xmlns:xlink"] = "http://www.w3.org/1999/xlink"
            attribs["xmlns:ev"] = "http://www.w3.org/2001/xml-events"
            attribs["baseProfile"] = elem.profile
            attribs["version"] = elem.version
        text = None
        to_string = elem.value_to_string
        values = [(k, s) for k, v in sorted(elem.attribs.items()) if v is not None and (s := to_string(v))]
    else:  # svgwrite's own kinds (text with positions, a ``<set>`` naming its target, ...): through ElementTree
        xml = elem.get_xml()
        if lines:
            _lines(xml)
        _open_close(xml, out)
        return
    tag = elem.elementname
    children = elem.elements
    # (svgwrite leaves empty attributes out: *values* holds none)
    opening = "".join([f' {k}="{v}"' for k, v in values])
    if opening.count('"') != 2 * len(values) or _TEXT_ESCAPED.search(opening):  # (hardly ever: numbers, classes, ids)
        opening = "".join([f' {k}="{_escape_attribute(v)}"' for k, v in values])
    if not children and not text:  # (most elements: a mark)
        out.append(f"<{tag}{opening} />")
        return
    out.append("<" + tag + opening)
    if lines and children and tag not in _TEXTUAL:
        out.append(">" + _escape_text(text) if text else ">\n")
        for child in children:
            if type(child) is Frozen:  # (a step group's marks, a layer's step groups)
                out.append(child.markup)
                out.append("\n")
            else:
                _emit(child, out, True)
                if child.elementname != CDATA_TAG:
                    out.append("\n")
        out.append("</" + tag + ">")
    elif text or children:
        out.append(">")
        if text:
            out.append(_escape_text(text))
        for child in children:
            _emit(child, out, False)
        out.append("</" + tag + ">")
    else:
        out.append(" />")
