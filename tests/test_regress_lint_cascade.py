"""Lint's cascade (construct/regress/lint/cascade.py): the rules a chain matches are shared by the style sheets
with the same selectors (a gallery's drawings of one style differ only in their line widths); each sheet's looks
keep its own values."""

from __future__ import annotations

from construct.regress.lint.cascade import Cascade, node


def test_sheets_with_the_same_selectors_keep_their_own_values():
    a = Cascade(".result{stroke:black;stroke-width:2}.cur>*{stroke:red}.old{opacity:0.5}")
    b = Cascade(".result{stroke:black;stroke-width:3px}.cur>*{stroke:blue}.old{opacity:0.25}")
    root = node("svg")
    line = node("line", classes="result")
    own = node("line", classes="result", declarations=(("@stroke-width", "5"), ("stroke", "green")))
    for c, colour, width, opacity in ((a, "red", 2.0, 0.5), (b, "blue", 3.0, 0.25), (a, "red", 2.0, 0.5)):
        cur = c.look((root, node("g", classes="step cur"), line))
        assert (cur.stroke, cur.stroke_width, cur.opacity) == (colour, width, 1.0)
        old = c.look((root, node("g", classes="step old"), line))
        assert (old.stroke, old.stroke_width, old.opacity) == ("black", width, opacity)
        # presentation attributes under the rules, the style attribute over them
        styled = c.look((root, node("g", classes="step cur"), own))
        assert (styled.stroke, styled.stroke_width) == ("green", width)
