"""Lint's cascade (construct/regress/lint/cascade.py): the rules a chain matches are shared by the style sheets
with the same selectors (a gallery's drawings of one style differ only in their line widths); each sheet's looks
keep its own values."""

from __future__ import annotations

from pathlib import Path

import pytest

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


GALLERY = Path(__file__).resolve().parent.parent / "gallery"


@pytest.mark.parametrize("figure", ["tangential-pressure-kappa-8-parts-18-rod-ratio-5/teaching",
                                    "two-cranks-parts-12-rod-ratio-5/teaching", "piston-force/historical"])
def test_a_look_taken_from_a_level_where_it_looks_the_same_is_the_look_worked_out_there(figure):
    """Sheet.look at a zoom level takes the look of the first level where the element looks the same
    (Cascade.asking: only the rules naming a level's class tell levels apart); against every look worked out
    at its own level (Sheet._look), for every element of a gallery drawing, in every state, at every level
    (one rule in two forms: the shortcut must never change a look).  A stepped drawing has elements that look
    different at some level (letters moved, tags given way): those must keep their own."""
    from construct.regress.lint import player_data, read_sheet
    from construct.regress.lint.sheet import STATES

    folder = GALLERY / figure
    if not folder.is_dir():
        pytest.skip("no gallery")
    player = folder / "player.html"
    sheet = read_sheet(folder / "final.svg", figure, data=player_data(player) if player.exists() else None)
    chains = {c for c, _box in sheet.inked} | {t.chain for t in sheet.texts} | {ld.chain for ld in sheet.leaders}
    levels = range(len(sheet.levels) + 1)
    taken = differ = 0
    for chain in chains:
        for level in levels:
            for state in (None, "", *STATES):
                assert sheet.look(chain, state, level) == sheet._look(chain, state, level), (chain, state, level)
            taken += sheet.level_as(chain, level) != level
            differ += any(sheet._look(chain, s, level) != sheet._look(chain, s, 0) for s in (None, "cur"))
    assert taken >= len(chains)  # the shortcut is taken (most elements look alike at every level) ...
    if "teaching" in figure:
        assert differ > 0  # ... and some elements do look different at some level


def test_a_class_a_rule_names_is_asked_only_where_the_rule_could_match():
    c = Cascade(".zl1 .m1{display:none}.zl2 .m2{display:none}.cur .lb{opacity:0.5}.zl3>.cur .tag{opacity:0.5}"
                ".old{opacity:0.5}")
    names, states = frozenset({"zl0", "zl1", "zl2", "zl3"}), frozenset({"cur", "old"})
    root = node("svg", classes="zl0")
    step = node("g", classes="step old")

    def asked(*nodes):
        return sorted(c.asking((root, *nodes), names, states))

    assert asked(node("text", classes="lb")) == []
    assert asked(node("g", classes="m1"), node("text", classes="lb")) == ["zl1"]  # inherited from its group
    assert asked(node("g", classes="m1 m2")) == ["zl1", "zl2"]
    assert asked(step, node("text", classes="tag")) == ["zl3"]  # whichever state its step is in
    assert asked(node("text", classes="tag")) == []  # no group between it and the root


def _declared_by_every_rule(c: Cascade, chain) -> dict[str, str]:
    """What a chain's last node is declared, worked out as CSS says, without the sheet's shortcuts: its
    presentation attributes, then every rule of the sheet that matches it in the sheet's order (asked of all
    rules, not of those filed under its classes), then its style attribute."""
    from construct.regress.lint.cascade import PROPERTIES

    own = dict(chain[-1][3])
    got = {name: own["@" + name] for name in PROPERTIES if "@" + name in own}
    for rule in c.rules:
        if rule.matches(chain):
            got.update(rule.declarations)
    got.update({name: own[name] for name in PROPERTIES if name in own})
    return got


def test_chains_alike_in_their_rules_and_own_declarations_share_what_they_are_declared():
    """Cascade._declared is made once per (rules matched, node's own declarations) and shared by the chains
    alike in both; a node's own presentation attributes and style keep it apart from its look-alikes."""
    c = Cascade(".result{stroke:black;stroke-width:2}.cur>*{stroke:red}.old{opacity:0.5}")
    root, step = node("svg"), node("g", classes="step cur")
    plain = (root, step, node("line", classes="result"))
    other = (root, node("g", classes="step cur", ident="s2"), node("line", classes="result"))
    attr = (root, step, node("line", classes="result", declarations=(("@stroke-width", "5"),)))
    styled = (root, step, node("line", classes="result", declarations=(("@stroke-width", "5"), ("stroke", "green"))))
    got = {name: c._declared(chain) for name, chain in
           (("plain", plain), ("other", other), ("attr", attr), ("styled", styled))}
    assert got["plain"] == {"stroke": "red", "stroke-width": "2"}
    assert got["attr"] == {"stroke-width": "2", "stroke": "red"}  # the rule over the attribute
    assert got["styled"] == {"stroke-width": "2", "stroke": "green"}  # the style attribute over the rule
    assert got["plain"] is got["other"]  # alike: shared
    assert got["styled"] is not got["attr"]
    for chain in (plain, other, attr, styled):
        assert c._declared(chain) == _declared_by_every_rule(c, chain)


@pytest.mark.parametrize("figure", ["tangential-pressure-kappa-8-parts-18-rod-ratio-5/teaching",
                                    "piston-force/historical"])
def test_what_a_gallery_drawing_declares_is_what_every_rule_says(figure):
    """For every element of a gallery drawing (in every state a view puts its step in), the declarations
    shared among look-alike chains are those worked out from all the sheet's rules for that chain."""
    from construct.regress.lint import player_data, read_sheet
    from construct.regress.lint.sheet import STATES

    folder = GALLERY / figure
    if not folder.is_dir():
        pytest.skip("no gallery")
    player = folder / "player.html"
    sheet = read_sheet(folder / "final.svg", figure, data=player_data(player) if player.exists() else None)
    chains = {c for c, _box in sheet.inked} | {t.chain for t in sheet.texts} | {ld.chain for ld in sheet.leaders}
    for chain in chains:
        for state in (None, *STATES):
            sheet.look(chain, state)
    c = sheet.cascade
    asked = list(c._own)
    assert len(asked) > 50
    for chain in asked:
        assert c._declared(chain) == _declared_by_every_rule(c, chain), chain
    assert len({id(c._declared(chain)) for chain in asked}) < len(asked) / 4  # shared, not made per chain
