"""Tangential pressure over a revolution and several cranks (construct.constructions.revolution).

References, never this code's output: the tangential force of a unit piston force acting in the direction of
motion, |sin(ω + β)/cos β| with sin β = (r/L) sin ω (DESIGN §5), summed over the cranks and integrated with
mpmath; and seed 002 § 146's printed numbers for two cranks at 90° under a constant force Q: the extremes of
the work excess at α1 = 19°12′ and α2 = 70°48′, v_min = v1(1 − 0.0422 Qr/((m1 + m2) v1²)), so the excess
Qr(1 + sin α − cos α − 4α/π) is −0.0422 Qr at α1 and +0.0422 Qr at α2.
"""

import csv
import io
import math

import mpmath
import pytest

from construct.cli.main import main
from construct.constructions import get
from construct.constructions.revolution import (
    excess_lobes,
    excess_work,
    parse_cranks,
    revolution_mean,
    revolution_ordinate,
)
from construct.kernel.errors import InvalidParameter

MPMATH_DPS = 30  # the digits of the mpmath references: each test runs under mpmath.workdps (conftest.py)
TP = get("tangential-pressure")


def t_mp(w, K):
    """T for a unit force along the motion, either stroke (mpmath)."""
    w = mpmath.mpf(w)
    b = mpmath.asin(mpmath.sin(w) / K)
    return abs(mpmath.sin(w + b) / mpmath.cos(b))


def summed_mp(w, K, offsets, cylinders=1):
    return cylinders * sum(t_mp(mpmath.mpf(w) + mpmath.radians(t), K) for t in offsets)


def swing_mp(K, offsets, cylinders=1):
    """Greatest swing of ∫(T − T_m): the running integral at every crossing, by mpmath quadrature and root finding."""
    f = lambda w: summed_mp(w, K, offsets, cylinders)  # noqa: E731
    corners = sorted({(k * mpmath.pi - mpmath.radians(t)) % (2 * mpmath.pi) for t in offsets for k in range(2)}
                     | {mpmath.mpf(0), 2 * mpmath.pi})
    mean = mpmath.quad(f, corners) / (2 * mpmath.pi)
    grid = [2 * mpmath.pi * i / 720 for i in range(721)]
    pts = sorted(set(corners) | set(grid))
    roots = []
    for a, b in zip(pts, pts[1:]):
        if (f(a) - mean) * (f(b) - mean) < 0:
            roots.append(mpmath.findroot(lambda w: f(w) - mean, (a, b), solver="anderson"))
    marks = [mpmath.mpf(0)] + roots
    run = [mpmath.quad(lambda w: f(w) - mean, sorted({0, *[c for c in corners if c < m], m})) for m in marks]
    return float(max(run) - min(run)), float(mean)


@pytest.mark.parametrize("K, kw, offsets, cyl", [
    (5.0, {"machine": "compound"}, (0, 90), 1),
    (4.0, {}, (0,), 1),
    (6.0, {"machine": "tandem"}, (0,), 2),
    (5.0, {"cranks": "0,120,240", "parts": 6}, (0, 120, 240), 1),
])
def test_summed_ordinates_against_mpmath(K, kw, offsets, cyl):
    fig = TP.figure(force="unit", revolution=True, rod_ratio=K, **kw)
    n = fig.params["parts"]
    for j in range(2 * n + 1):
        expected = float(summed_mp(math.pi * j / n, K, offsets, cyl))
        # Dürer's trisection puts a division point within 4.4e-6 rad; |dT/dw| <= 1.3 per crank
        assert revolution_ordinate(fig, j) == pytest.approx(expected, abs=1e-5 * len(offsets) * cyl)
    assert revolution_mean(fig) == pytest.approx(2 / math.pi * len(offsets) * cyl, rel=2e-3)
    assert all(c.ok for c in fig.checks())


def test_return_stroke_is_not_the_forward_stroke_repeated():
    """At 60° and 240° (60° past the crank-end dead centre) the finite rod gives different tangential pressures."""
    fig = TP.figure(force="unit", revolution=True, rod_ratio=4.0, parts=6, method="exact")
    fwd, ret = revolution_ordinate(fig, 2), revolution_ordinate(fig, 8)
    assert fwd == pytest.approx(float(t_mp(math.pi / 3, 4)), abs=1e-12)
    assert ret == pytest.approx(float(t_mp(4 * math.pi / 3, 4)), abs=1e-12)
    assert fwd - ret == pytest.approx(float(t_mp(math.pi / 3, 4) - t_mp(4 * math.pi / 3, 4)), abs=1e-12)
    assert abs(fwd - ret) > 0.1


def test_two_cranks_at_90_reproduce_seed_002():
    """Constant Q, cranks at 90°: the first lobes are seed 002's ∓0.0422 Qr, the swing between them 0.0844 Qr.

    In the first quadrant the rod terms cancel (§ 147: "da die beiden Glieder r/2l sin²α sich fortheben"), so
    this holds for the finite rod too.  The drawn lobes carry the French curve's and the dividers' error: at
    36 parts the printed four digits come out.
    """
    fig = TP.figure(force="unit", revolution=True, machine="compound", rod_ratio=5.0, parts=36)
    lobes = excess_lobes(fig)
    assert lobes[0] == pytest.approx(-0.0422, abs=2e-4)
    assert lobes[1] == pytest.approx(2 * 0.0422, abs=3e-4)
    # the closed form 1 + sin a - cos a - 4a/pi at the printed angles
    a1, a2 = mpmath.radians(19 + 12 / mpmath.mpf(60)), mpmath.radians(70 + 48 / mpmath.mpf(60))
    e = lambda a: 1 + mpmath.sin(a) - mpmath.cos(a) - 4 * a / mpmath.pi  # noqa: E731
    assert lobes[1] == pytest.approx(float(e(a2) - e(a1)), abs=3e-4)


def test_infinite_rod_swing_is_seed_002s():
    """A very long rod: every quadrant repeats the first, the flywheel's swing is 2 x 0.0422 Qr.

    The rod's share of the work excess at the quadrant ends is r/L Qr (§ 147: e(180°) = ±0.20 Qr at L/r = 5),
    here 0.001 Qr; the drawing adds 3e-4.
    """
    fig = TP.figure(force="unit", revolution=True, machine="compound", rod_ratio=1000.0, parts=36)
    assert excess_work(fig) == pytest.approx(2 * 0.0422, abs=1e-3 + 3e-4)


@pytest.mark.parametrize("K, kw, offsets, cyl", [
    (5.0, {"machine": "compound"}, (0, 90), 1),
    (5.0, {}, (0,), 1),
])
def test_excess_work_against_mpmath(K, kw, offsets, cyl):
    fig = TP.figure(force="unit", revolution=True, rod_ratio=K, parts=36, **kw)
    swing, mean = swing_mp(K, offsets, cyl)
    assert mean == pytest.approx(2 / math.pi * len(offsets) * cyl, rel=1e-20)
    # chord unrolling at 36 parts shortens areas by 1 - 72 sin(pi/72)/pi = 3.2e-4; the French curve ~1e-3
    assert excess_work(fig) == pytest.approx(swing, rel=3e-3)


def test_table_cli(capsys):
    assert main(["table", "tangential-pressure", "--rod-ratio", "5", "--revolution", "--cranks", "0,90",
                 "--format", "csv"]) == 0
    rows = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert list(rows[0]) == ["crank_angle_deg", "T_over_P"]
    assert len(rows) == 37
    # keyed by the division's angle, measured where Dürer's trisection put the point: within his bound at 60
    # degrees times the summed line's steepest slope (two cranks, each below 1 + 1/5 per radian, 3 with margin)
    from construct.kernel.division import durer_error_bound

    assert [float(r["crank_angle_deg"]) for r in rows[:3]] == [0.0, 10.0, 20.0]
    for row in rows:
        w = math.radians(float(row["crank_angle_deg"]))
        assert float(row["T_over_P"]) == pytest.approx(float(summed_mp(w, 5, (0, 90))),
                                                       abs=3 * durer_error_bound(math.radians(60)))


@pytest.mark.parametrize("args, says", [
    (["--cranks", "0,90"], "add --revolution"),
    (["--revolution", "--cranks", "0,95"], "not a multiple of the division"),
    (["--revolution", "--cranks", "90"], "start with 0"),
    (["--revolution", "--cranks", "0,x"], "got 'x'"),
    (["--revolution", "--cranks", "0,400"], "outside 0 .. 360"),
    (["--revolution", "--machine", "triple"], "machine must be one of"),
])
def test_bad_engine_options(capsys, args, says):
    assert main(["table", "tangential-pressure", "--rod-ratio", "5", *args]) == 2
    err = capsys.readouterr().err
    assert says in err and len(err.strip().splitlines()) == 1


def test_parse_cranks_refuses_duplicates():
    with pytest.raises(InvalidParameter, match="given twice"):
        parse_cranks("0,90,90")
