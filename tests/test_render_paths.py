"""The SVG paths of the drawing's marks: the one smooth-curve rule in its two forms.

Expectations come from the rule's scalar form, which draws, places and breaks every curve; its array form
(a sweep's curves at every value, a letter's polyline) must give the same numbers to the bit.
"""

from __future__ import annotations

import numpy as np

from construct.render.paths import bezier_arrays, bezier_controls


def test_the_smooth_curves_array_form_gives_the_scalar_forms_numbers_to_the_bit():
    """bezier_arrays (a sweep's curve at every value at once, placing's polyline) is bezier_controls, the rule
    curve_path draws by, to the last bit: the same operations in the same order, for curves of 2 to 40 points,
    and for one coordinate of a curve at many values (the points' rows x values)."""
    rng = np.random.default_rng(28)
    for n in (2, 3, 4, 7, 40):
        for _ in range(20):
            P = rng.normal(0.0, 100.0, (n, 2)) * rng.uniform(1e-3, 1e3)
            want = bezier_controls([tuple(p) for p in P.tolist()])
            got = bezier_arrays(P)
            assert [tuple(map(tuple, piece)) for piece in zip(*(a.tolist() for a in got))] == want
            # one coordinate over a sweep of 5 values: each value's column is its own curve's
            xs = rng.normal(0.0, 50.0, (n, 5))
            cols = bezier_arrays(xs)
            for v in range(5):
                one = bezier_controls([(float(x), 0.0) for x in xs[:, v]])
                assert [tuple(a[:, v].tolist()) for a in cols] == [tuple(p[0] for p in piece) for piece in
                                                                   zip(*one)]
