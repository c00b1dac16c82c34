"""Checks that can fail: a tolerance comes from a bound stated before the measurement (the method's error
formula with a margin, or the float chain), never from the error it is there to judge.

Reference: the ratio of each check's tolerance to its error on every figure of the gallery and on the
methods' other divisions; a tolerance within 1 % of the error is the known error written back as its own
tolerance (the unrolled circle's 3.9865e-3 "of 3.9868e-3", Kochański's 5.93e-5 "of 5.94e-5").
"""

import math

import pytest

from construct.constructions import get
from construct.gallery import gallery_plan

OTHERS = [("crank", {"parts": n, "method": m}) for n in (9, 36) for m in ("durer", "dividers", "neusis")] + [
    ("tangential-pressure", {"parts": 36}), ("two-cranks", {"parts": 24}),
    ("four-stroke", {"parts": 6, "steps": 4, "over_pressure": True})]


@pytest.mark.parametrize("name, params", gallery_plan() + OTHERS, ids=lambda v: str(v))
def test_no_tolerance_is_its_own_error(name, params, gallery_figure):
    checks = gallery_figure(name, params)[1].checks()
    assert checks
    tight = [f"{c.name}: error {abs(c.error):.6g}, tolerance {c.tolerance:.6g}" for c in checks
             if c.error and c.tolerance <= 1.01 * abs(c.error)]
    assert not tight, tight


def test_kochanski_is_held_to_his_own_value_and_to_pi_by_a_margin():
    """His segment sqrt(40/3 − 2√3) r to the float chain; against π within 1.5 times his error."""
    checks = {c.name: c for c in get("two-cranks").figure().checks()}
    own = checks["Kochanski: BK / r (his construction)"]
    assert own.expected == pytest.approx(math.sqrt(40 / 3 - 2 * math.sqrt(3)), rel=1e-15) and own.tolerance <= 1e-12
    exact = checks["Kochanski: BK / r against pi"]
    assert exact.expected == math.pi and exact.tolerance >= 1.4 * abs(exact.error)


def test_the_unrolled_circle_is_held_to_the_chord_bound():
    """π − 2n sin(π/2n) <= π³/(24 n²); the tolerance is 1.5 times that bound."""
    c = next(c for c in get("tangential-pressure").figure().checks() if c.name == "unrolled length")
    assert c.tolerance >= 1.5 * math.pi ** 3 / (24 * 18 ** 2) and c.tolerance > 1.4 * abs(c.error)
