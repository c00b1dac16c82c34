"""Semantic diff of two SVG drawings: what moved, resized, restyled, appeared or vanished.

Both drawings are parsed into geometry in absolute drawing units (every
``transform`` of the ancestors applied, ``<use>`` expanded, styles inherited
and normalised), then compared element by element.  Formatting is not
geometry: attribute order, whitespace, ``1.50`` against ``1.5``, ``#000``
against ``black`` and a ``style`` property against a presentation attribute
are all equal.

>>> a = '<svg xmlns="http://www.w3.org/2000/svg"><circle id="P" cx="1.50" cy="2" r="1" fill="#000"/></svg>'
>>> b = '<svg xmlns="http://www.w3.org/2000/svg"><circle r="1" style="fill: black" cy="2" cx="1.5" id="P"/></svg>'
>>> diff_svg(a, b).equal
True
>>> moved = b.replace('cx="1.5"', 'cx="1.51"')
>>> print(diff_svg(a, moved).report())
SVG diff <string> -> <string> (tolerance 1e-06): 1 change
  moved      P (circle, matched by id): by 0.01: centre (1.5, 2) -> (1.51, 2)

Each drawn element gets a stable key: its ``id``, else its tag and its
document-order index among the elements of that tag without an id
(``circle[0]``).  Elements are matched by id, then anonymous ones by an
order-preserving alignment of equal elements, then by key, and what is left
by kind and nearest geometry (a renamed element is "renamed", not
missing + extra).  Every change says how its element was matched.

Hostile drawings are bounded: the XML is read by :mod:`defusedxml` (no entity
declarations, no external references), the tree is walked on a stack of its
own (100,000 nested groups are no deeper for Python than one), and a drawing
that holds or expands to more than :data:`MAX_ELEMENTS` elements -- ``<use>``
references that double at every level -- is refused before it is worked out:

>>> bomb = ('<svg xmlns="http://www.w3.org/2000/svg"><defs><circle id="a0" r="1"/>'
...         + "".join(f'<g id="a{i}"><use href="#a{i - 1}"/><use href="#a{i - 1}"/></g>' for i in range(1, 25))
...         + '</defs><use href="#a24"/></svg>')
>>> parse_svg(bomb)
Traceback (most recent call last):
...
construct.regress.svgdiff.SvgTooLargeError: <string>: the drawing expands to more than 2,000,000 elements (its <use> references repeat what they reference; ...); refused

The package in four steps, each a module: :mod:`.parse` reads a document into
shapes (with :mod:`.geometry` for transforms and paths, :mod:`.css` for
colours and style sheets, :mod:`.values` for numbers), :mod:`.match` pairs the
shapes of A and B, :mod:`.report` compares each pair and says what changed
(a :class:`~construct.regress.change.Diff` of :class:`~construct.regress.change.Change` s, the types
the protocol diff and ``construct verify`` report in too).
"""

from __future__ import annotations

from .css import normalise_colour
from .geometry import parse_transform
from .match import MATCH_BUDGET
from .parse import SVG_NS, XLINK_NS, Drawing, Shape, parse_svg
from ..change import Change, Diff
from .report import CHANGE_KINDS, changes_by_step, diff_svg, iter_changes
from .values import DEFAULT_TOLERANCE, MAX_ELEMENTS, SvgFormatError, SvgTooLargeError

__all__ = ["DEFAULT_TOLERANCE", "MAX_ELEMENTS", "Change", "Diff", "SvgFormatError", "SvgTooLargeError",
           "diff_svg", "parse_svg",
           "changes_by_step", "iter_changes", "Drawing", "Shape", "normalise_colour", "parse_transform",
           "MATCH_BUDGET", "SVG_NS", "XLINK_NS", "CHANGE_KINDS"]

for _public in (Drawing, Shape, diff_svg, parse_svg, changes_by_step, iter_changes,
                normalise_colour, parse_transform):
    _public.__module__ = __name__  # documented, pickled and shown as construct.regress.svgdiff.<name>
del _public
