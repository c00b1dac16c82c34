"""Lint's outlines (construct/regress/lint/outlines.py): a plain path read in one pass, long lines carried and cut on
arrays -- each the same numbers as the general reader and the plain loops they stand in for."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from construct.regress.lint import outlines
from construct.regress.lint.outlines import PIECE, cut_pieces, polylines, transform_lines, transform_point
from construct.regress.svgdiff.geometry import parse_path


def _through_parse_path(d: str) -> list[list[tuple[float, float]]]:
    """The path's polylines read through the general reader alone (the one-pass reading switched off)."""
    mp = pytest.MonkeyPatch()
    try:
        mp.setattr(outlines, "_plain_path", lambda d: None)
        return polylines("path", ET.fromstring(f'<path d="{d}"/>'), "test")
    finally:
        mp.undo()


def _random_path(rng) -> str:
    """A plain path as the renderer writes it (moves, lines, cubic curves, closes; numbers with signs, no
    separator before a sign, exponents, -0), sometimes with implicit repeats."""
    def num() -> str:
        v = float([rng.uniform(-500, 500), 0.0, -0.0, rng.uniform(-1, 1) * 1e-3][rng.integers(4)])
        return [f"{v:.2f}", f"{v:g}", f"{v:.3e}", repr(v)][rng.integers(4)]

    parts = []
    for _ in range(rng.integers(1, 4)):
        parts.append(f"M{num()} {num()}")
        for _ in range(rng.integers(1, 12)):
            kind = ["L", "C", "Z", "LL", "CC"][rng.integers(5)]
            if kind == "L":
                parts.append(f"L{num()},{num()}")
            elif kind == "LL":
                parts.append(f"L {num()} {num()} {num()} {num()}")
            elif kind == "C":
                parts.append("C" + " ".join(num() for _ in range(6)))
            elif kind == "CC":
                parts.append("C" + " ".join(num() for _ in range(12)))
            else:
                parts.append("Z")
    return " ".join(parts) if rng.random() < 0.5 else "".join(parts)


@pytest.mark.parametrize("seed", range(3))
def test_a_plain_path_read_in_one_pass_is_what_parse_path_gives(seed):
    rng = np.random.default_rng(seed)
    for _ in range(150):
        d = _random_path(rng)
        assert outlines._plain_path(d) is not None, d
        got = polylines("path", ET.fromstring(f'<path d="{d}"/>'), "test")
        want = _through_parse_path(d)
        assert repr(got) == repr(want), d  # repr: -0.0 and 0.0 told apart


@pytest.mark.parametrize("d", ["m1 1l2 2", "M0 0H5V5", "M0 0A1 1 0 0 1 2 0", "M0 0L1", "M0 0Z3 4", "L1 1", "M0 0Q1 1 2 0",
                               "M1 2e", "M0 0C1 1 2 2"])
def test_other_paths_are_left_to_parse_path(d):
    assert outlines._plain_path(d) is None


def test_a_path_parse_path_refuses_is_refused_alike():
    for d in ("M0 0L1", "M0 0Z3 4", "M1 2e"):
        with pytest.raises(Exception) as plain:
            parse_path(d, "test")
        with pytest.raises(type(plain.value)):
            polylines("path", ET.fromstring(f'<path d="{d}"/>'), "test")


def _cut_plain(lines):
    """The pieces cut one segment after another in plain Python (the loop the arrays stand in for)."""
    out = []
    for pts in lines:
        for (ax, ay), (bx, by) in zip(pts, pts[1:]):
            n = max(1, math.ceil(math.hypot(bx - ax, by - ay) / PIECE))
            for i in range(n):
                out.append((ax + (bx - ax) * i / n, ay + (by - ay) * i / n,
                            ax + (bx - ax) * (i + 1) / n, ay + (by - ay) * (i + 1) / n))
    return out


def test_long_lines_carried_and_cut_on_arrays_are_the_plain_loops_numbers():
    rng = np.random.default_rng(7)
    lines = [[tuple(p) for p in rng.uniform(-300, 300, (k, 2)).tolist()] for k in (2, 5, 23, 24, 25, 200)]
    # segments exactly 1, 2 and 3 pieces long (where a count could tip over), and one of length 0
    lines.append([(0.0, 0.0), (PIECE, 0.0), (PIECE, 2 * PIECE), (PIECE + 3 * PIECE * 0.6, 3 * PIECE * 0.8),
                  (PIECE + 3 * PIECE * 0.6, 3 * PIECE * 0.8)] + [(float(i), -0.0) for i in range(30)])
    m = (0.8660254037844387, 0.5, -0.5, 0.8660254037844387, 12.5, -3.25)
    carried = transform_lines(m, lines)
    assert repr(carried) == repr([[transform_point(m, x, y) for x, y in pts] for pts in lines])
    assert repr(cut_pieces(carried)) == repr(_cut_plain(carried))
    assert repr(cut_pieces(lines)) == repr(_cut_plain(lines))
