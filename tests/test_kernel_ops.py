"""The op table (construct/kernel/ops.py): every operation a protocol names, its checks, scalar and array.

Expectations come from geometry worked out here (where two circles cross, by the radical line), from the
declared kinds of each op, and from the scalar op run set by set -- never from the op's own array answer.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from construct.kernel.geometry import SCALAR, ArrayMath, Circle, Line, Point
from construct.kernel.ops import OPS, PARAM_KINDS, elementwise, kind_of
from construct.kernel.rules import left_of, only


def test_every_op_declares_what_it_takes_and_makes():
    for name, op in OPS.items():
        assert op.name == name and callable(op.fn) and op.doc, name
        assert all(kind.rstrip("?") for kind in op.params) and all(k in PARAM_KINDS for k in op.params.values()), name
        required = [k for k in op.params if not k.endswith("?")]
        if required:  # a step that leaves out a required parameter is named in the error
            assert required[0] in op.check_params({}), name
        assert "has no parameter 'nonsense'" in (op.check_params({"nonsense": 1}) or ""), name


def test_two_circles_cross_where_the_radical_line_meets_them():
    """|P - A| = 5 and |P - B| = 3 with AB = 6: x = (25 - 9 + 36)/12 from A, y = ±sqrt(25 - x²)."""
    a, b = Circle(Point(0.0, 0.0), 5.0), Circle(Point(6.0, 0.0), 3.0)
    x = (25.0 - 9.0 + 36.0) / 12.0
    y = math.sqrt(25.0 - x * x)
    up, = OPS["intersect"].fn([a, b], {"rule": left_of("A", "B"), "both": False}, {},
                              [Point(0.0, 0.0), Point(6.0, 0.0)], SCALAR)
    assert (up.x, up.y) == pytest.approx((x, y), abs=1e-15)
    line = Line(Point(0.0, 1.0), Point(1.0, 1.0))
    cut, = OPS["intersect"].fn([line, Line(Point(2.0, 0.0), Point(2.0, 5.0))], {"rule": only()}, {}, [], SCALAR)
    assert (cut.x, cut.y) == (2.0, 1.0)


def test_the_array_form_is_the_scalar_op_set_by_set():
    """A sweep of radii: the intersect op on arrays gives, at each set, what it gives for that set alone (and
    what the op run set by set through elementwise gives)."""
    radii = np.array([3.0, 3.5, 4.0, 5.5])
    a = Circle(Point(np.zeros(4), np.zeros(4)), np.full(4, 5.0))
    b = Circle(Point(np.full(4, 6.0), np.zeros(4)), radii)
    refs = [Point(np.zeros(4), np.zeros(4)), Point(np.full(4, 6.0), np.zeros(4))]
    params = {"rule": left_of("A", "B"), "both": False}
    xp = ArrayMath(4)  # four sets of givens
    swept, = OPS["intersect"].fn([a, b], params, {}, refs, xp)
    by_set, = elementwise(OPS["intersect"].fn)([a, b], params, {}, refs, xp)
    for i, r in enumerate(radii):
        one, = OPS["intersect"].fn([Circle(Point(0.0, 0.0), 5.0), Circle(Point(6.0, 0.0), float(r))], params, {},
                                   [Point(0.0, 0.0), Point(6.0, 0.0)], SCALAR)
        assert float(swept.x[i]) == pytest.approx(one.x, abs=1e-14) and float(by_set.x[i]) == one.x
        assert float(swept.y[i]) == pytest.approx(one.y, abs=1e-14) and float(by_set.y[i]) == one.y


def test_objects_are_known_by_their_kind():
    assert kind_of(Point(0.0, 0.0)) == "point" and kind_of(Circle(Point(0.0, 0.0), 1.0)) == "circle"
    assert kind_of(Line(Point(0.0, 0.0), Point(1.0, 0.0))) == "line"
