"""construct.live.wire: what travels to the live page (each column at the grid values it needs, stored once)."""

from __future__ import annotations

import numpy as np
import pytest

from construct.constructions.domain import ROD_RATIO
from construct.live import wire
from construct.live.sweep import LiveSweep
from construct.render.wire import decode


@pytest.fixture(scope="module")
def alike_columns() -> LiveSweep:
    """A sweep of 129 grid values whose columns come in sets alike to the bit (a point's coordinate in its circle,
    its lines, its arcs), with columns alike but in one bit, a sign of zero, their kind or their nearness."""
    rng = np.random.default_rng(7)
    u = np.linspace(0.0, 2.0, 129)
    smooth = [np.sin(a * u + b) * c + d for a, b, c, d in rng.uniform(0.5, 3.0, size=(12, 4))]
    kink = np.where(u < 0.77, 3.0 * u, 4.0 - 2.2 * u) * 40.0
    base = [*smooth, kink, np.zeros_like(u), np.full_like(u, 5.0)]
    cols, keys = [], []
    for i, c in enumerate(base * 3):  # every column three times, under keys of each kind
        for attr in ("cx", "cy", "r", "stroke-width"):
            cols.append(c * 60.0 + (200.0 if attr != "r" else 0.0) + (1.0 if attr == "r" else 0.0))
            keys.append((f"m{i}-{attr}", attr, "#"))
    one_bit = cols[0].copy()
    one_bit[64] = np.nextafter(one_bit[64], np.inf)
    minus = cols[-3].copy() * 0.0 - 0.0  # (-0.0: alike in value to the zeros, not in its bits)
    cols += [one_bit, minus, cols[4], cols[5]]
    keys += [("one-bit", "cx", "#"), ("minus", "cx", "#"), ("near", "cx", "#"), ("alike", "cx", "#")]
    fit = np.column_stack([40.0 + 3.0 * u, 600.0 - 5.0 * u, 2.0 + np.sqrt(u)])
    # a point that moves along a line in the construction's units, as drawn: stored by its x as a cx, its
    # numbers alike as a cy's (stored otherwise)
    drawn_x = fit[:, 0] + fit[:, 2] * (300.0 + 200.0 * u)  # (as drawn: 24 grid values, as x: 9)
    cols += [drawn_x, drawn_x]
    keys += [("along", "cx", "#"), ("along", "cy", "#")]
    return LiveSweep("rod_ratio", "L/r", ROD_RATIO, 5.0, 10.0 ** u, keys, np.column_stack(cols), 0.0,
                     snapped=[("near", "cx", "#")], u=u, start=9, fit=fit)


def _every_column_alone(monkeypatch) -> None:
    """Every column walks the tree alone: no set of columns alike shares a walk."""
    monkeypatch.setattr(wire, "same_walk", lambda drawn, kinds, nearest: np.arange(drawn.shape[1]))


def test_columns_alike_walk_once_and_need_what_each_needs_alone(alike_columns, monkeypatch):
    shared = wire.column_knots(alike_columns)
    shared_data = wire.encode(alike_columns)
    assert len(set(wire.same_walk(alike_columns.drawn, wire.column_kinds(alike_columns.keys),
                                  alike_columns.nearest_columns()).tolist())) < alike_columns.drawn.shape[1] / 2
    _every_column_alone(monkeypatch)
    alone = wire.column_knots(alike_columns)
    assert (shared[0] == alone[0]).all() and (shared[1] == alone[1]).all()
    assert 0 < shared[0].sum() < shared[0].size  # (some columns need fewer grid values than all, none none)
    assert shared[1][-2:].tolist() == [1, 0] and shared[0][:, -2].sum() < shared[0][:, -1].sum()
    assert shared_data == wire.encode(alike_columns)
    rows = decode(shared_data, alike_columns.u.tolist(), *alike_columns.drawn.shape)
    assert np.abs(rows - alike_columns.drawn).max() <= wire.ROW_PX


def test_columns_alike_are_alike_to_the_bit_in_kind_and_nearness(alike_columns):
    d = alike_columns.drawn
    kinds = wire.column_kinds(alike_columns.keys)
    like = wire.same_walk(d, kinds, alike_columns.nearest_columns())
    firsts = like == np.arange(d.shape[1])
    assert (like <= np.arange(d.shape[1])).all() and firsts[like].all()
    assert (d.view(np.int64) == d[:, like].view(np.int64)).all() and (kinds == kinds[like]).all()
    assert (alike_columns.nearest_columns() == alike_columns.nearest_columns()[like]).all()
    # one bit, a zero's sign, nearness, the kind (a cx and a cy of the same numbers): walked apart
    assert firsts[-6:-3].all() and firsts[-2:].all() and firsts[:2].all() and (d[:, 0] == d[:, 1]).all()
    assert like[-3] == 4 and like[60] == 0  # (the same numbers as a cx, the first column again: alike)


def test_the_columns_from_the_nearer_value_are_the_arcs_flags_and_the_snapped_marks():
    """LiveSweep.nearest_columns reads the keys' columns the refinement found (sweep._key_columns): the same as
    the keys read anew (arc_flags, and the snapped marks' columns), with the list of keys asked before or not."""
    from construct.live.sweep import _columns, _key_columns
    from construct.render.wire import arc_flags

    arc = "M# #A# # # # # # #"  # (9 numbers: M x y A rx ry rotation large-arc sweep x y: the flag is the sixth)
    keys = [("a", "cx", "#"), ("b", "d", arc), ("c", "d", arc), ("s", "cx", "#"), ("t", "r", "#")]
    live = LiveSweep("rod_ratio", "L/r", ROD_RATIO, 5.0, np.array([1.0, 10.0]), keys, np.zeros((2, 22)), 0.0,
                     snapped=[("s", "cx", "#")], u=np.array([0.0, 1.0]), start=2)
    assert live.nearest_columns().nonzero()[0].tolist() == [1 + 5, 1 + 9 + 5, 1 + 9 + 9]
    _key_columns(keys)  # (asked before, as the refinement asks)
    for snapped in ([("s", "cx", "#")], [], [("b", "d", arc), ("t", "r", "#")]):
        live.snapped = snapped
        old = arc_flags(keys) | _columns(keys, lambda k: k in set(snapped))
        assert (live.nearest_columns() == old).all()
