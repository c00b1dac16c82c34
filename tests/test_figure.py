"""The public Builder and Figure (construct/figure.py): letters of results, checks of one's own figure."""

import pytest

from construct import Builder
from construct.constructions.checking import Check
from construct.kernel.errors import InvalidParameter


def _triangle() -> Builder:
    b = Builder("letters", givens={"c": 2.0})
    b.given_point("A", 0.0, 0.0)
    b.given_point("C", 1.0, 0.0, unit="c")
    b.circle_through("ka", "A", "C")
    b.circle_through("kc", "C", "A")
    return b


def test_a_result_point_is_lettered_by_its_name():
    """The Builder's word: results are "always on the plate and lettered" -- B was left bare."""
    b = _triangle()
    b.intersect("B", "ka", "kc", rule=("left", "A", "C"), role="result")
    b.intersect("D", "ka", "kc", rule=("right", "A", "C"), role="result", labels={"D": ""})
    b.intersect("E", "ka", "kc", rule=("left", "A", "C"))   # a construction point stays bare
    labels = {name: letter for step in b.figure().protocol.steps for name, letter in step.labels}
    assert labels["B"] == "B" and labels["D"] == "" and "E" not in labels
    plate = b.figure().svg(style="historical")
    assert ">B<" in plate and ">D<" not in plate


def test_a_figure_of_ones_own_carries_its_checks_through_a_replay():
    b = _triangle()
    b.intersect("B", "ka", "kc", rule=("left", "A", "C"), role="result")

    def side(fig):   # an equilateral triangle: AB = AC = c
        return [Check("AB = c", fig.replay["A"].distance(fig.replay["B"]), fig.replay.givens["c"], 1e-12, "float")]

    fig = b.figure(checks=side)
    assert [c.ok for c in fig.checks()] == [True] and [c.ok for c in fig.with_givens(c=5.0).checks()] == [True]
    assert fig.with_givens(c=5.0).checks()[0].expected == 5.0
    with pytest.raises(InvalidParameter, match="checks is a function"):
        b.figure(checks=[1])
