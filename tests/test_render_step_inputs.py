"""What each step names and takes up (construct/render/step_inputs.py): the point a caption's letter means is found
in an index (``_LetterIndex``), and that agrees with the plain walk over every point of the letter made before."""

from __future__ import annotations

import numpy as np
import pytest

from construct.render.step_inputs import _LetterIndex


def _meant_plain(points, token, k, group):
    """The rule walked point by point (as the captions' reader once did): of the points made up to step *k* (in
    order, up to the first made after *k*), the latest of those sharing the most leading groups with *group*; one
    sharing none only if lettered or a numbered tag."""
    best = None
    for step, name, grp, lettered in points:
        if step > k:
            break
        shared = 0
        while shared < min(len(grp), len(group)) and grp[shared] == group[shared]:
            shared += 1
        if (lettered or shared or len(token) > 1) and (best is None or shared >= best[0]):
            best = (shared, name)
    return None if best is None else best[1]


@pytest.mark.parametrize("seed", range(6))
def test_the_letter_index_agrees_with_the_plain_walk(seed):
    rng = np.random.default_rng(seed)
    groups = [(), ("a",), ("a", "b"), ("a", "c"), ("a", "b", "d"), ("e",), ("e", "b")]
    by_letter = {}
    for token in ("F", "M2", "K", "S1"):
        n = int(rng.integers(0, 40))
        steps = np.sort(rng.integers(1, 60, n))
        if seed % 2:  # out of step order now and then: the walk stops at the first point made after k
            swap = rng.integers(0, max(n, 1), 3)
            steps[swap % max(n, 1)] = rng.integers(1, 60, 3)
        by_letter[token] = [(int(s), f"{token}.{i}", groups[rng.integers(len(groups))], bool(rng.random() < 0.2))
                            for i, s in enumerate(steps)]
    index = _LetterIndex(by_letter)
    asked = 0
    for token in ("F", "M2", "K", "S1", "Q"):
        for k in range(0, 62):
            for group in groups:
                want = _meant_plain(by_letter.get(token, ()), token, k, group)
                assert index.latest(token, k, group) == want, (token, k, group)
                asked += want is not None
    assert asked > 100  # the cases are not all empty


def test_a_figures_captions_name_the_points_the_plain_walk_finds():
    from construct import get
    from construct.render.scene import build_scene

    sc = build_scene(get("four-stroke").figure())
    assert sc.params.get("captions") == "letters"
    many = max(sc._by_letter.values(), key=len)
    assert len(many) > 50  # a letter standing for many helpers
    named = 0
    for s in sc.steps:
        for token, points in sc._by_letter.items():
            want = _meant_plain(points, token, s.index, s.group)
            assert sc._letter_index.latest(token, s.index, s.group) == want
        named += bool(sc._named_points(s.index))
    assert named > 100
