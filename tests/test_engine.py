"""The whole engine (issue 17): Baumann's force on the return stroke, compound engines with their own
high- and low-pressure diagrams, J from a card, the flywheel from a card.

References, never this code's output: Baumann's idealised diagram (seed 004: admission line to the
cut-off, pv = const expansion and compression from the clearance corners, back-pressure line) less the
acceleration force c(cos ω + λ cos 2ω) of eq. (298), written here again with mpmath; on the return stroke
his assumption (the crank side's diagram is the cover side's, mirrored) and (298) with the minus sign.
Sums and integrals are done here by mpmath or by plain trapezoids on a fine grid.
"""

import math

import mpmath
import pytest

from construct.cli import main
from construct.constructions import get
from construct.constructions.revolution import excess_work, revolution_mean, revolution_ordinate

mpmath.mp.dps = 25
TP = get("tangential-pressure")
#: Baumann's first case (seed 004): s1/s = 0.1, s0/s = 0.05, P = 7.85 at over P0 = 0.15 at, s3/s = 0.3.
S1, S0, P, P0, S3 = 0.10, 0.05, 7.85, 0.15, 0.30


def over_mp(x, s1=S1, s0=S0, adm=P, back=P0, s3=S3):
    steam = adm + back if x <= s1 else (adm + back) * (s1 + s0) / (x + s0)
    against = back if x <= 1 - s3 else back * (s3 + s0) / (1 - x + s0)
    return steam - against


def piston_mp(w, K):
    lam = mpmath.mpf(1) / K
    return (1 - mpmath.cos(w) + (1 - mpmath.sqrt(1 - (lam * mpmath.sin(w)) ** 2)) / lam) / 2


def baumann_force_mp(w, K, kappa, **diagram):
    """P' along the motion (at): forward over(x) − B, return over(1 − x) + B, B = c(cos ω + λ cos 2ω)."""
    w = mpmath.mpf(w)
    lam = mpmath.mpf(1) / K
    c = mpmath.mpf(diagram.get("adm", P)) / (kappa * (1 + lam))
    x = piston_mp(w, K)
    mass = c * (mpmath.cos(w) + lam * mpmath.cos(2 * w))
    if w % (2 * mpmath.pi) <= mpmath.pi:
        return over_mp(x, **diagram) - mass
    return over_mp(1 - x, **diagram) + mass


def unit_t_mp(w, K):
    b = mpmath.asin(mpmath.sin(w) / K)
    return abs(mpmath.sin(w + b) / mpmath.cos(b))


def swing(fn, samples=20000):
    """Mean and greatest swing of ∫(T − T_m) over a revolution, trapezoids on a fine grid."""
    ws = [2 * math.pi * i / samples for i in range(samples + 1)]
    ts = [float(fn(w)) for w in ws]
    mean = sum((a + b) / 2 for a, b in zip(ts, ts[1:])) / samples
    run, lo, hi = 0.0, 0.0, 0.0
    for a, b in zip(ts, ts[1:]):
        run += ((a + b) / 2 - mean) * 2 * math.pi / samples
        lo, hi = min(lo, run), max(hi, run)
    return mean, hi - lo


# --------------------------------------------------------------------------
# 1. Baumann's force on the return stroke.
# --------------------------------------------------------------------------


@pytest.mark.parametrize("K, kappa", [(5.0, 8.0), (4.0, 2.0)])
def test_baumann_revolution_ordinates_against_mpmath(K, kappa):
    fig = TP.figure(force="baumann", revolution=True, rod_ratio=K, kappa=kappa, parts=18)
    n = 18
    for j in range(2 * n + 1):
        w = math.pi * j / n
        expected = float(unit_t_mp(w, K) * baumann_force_mp(w, K, kappa)) if j not in (0, n, 2 * n) else 0.0
        # Dürer's trisection puts a division point within 4.4e-6 rad; |dT/dw| is below 10 at here
        assert revolution_ordinate(fig, j) == pytest.approx(expected, abs=5e-5), j
    mean, work = swing(lambda w: unit_t_mp(w, K) * baumann_force_mp(w, K, kappa))
    assert revolution_mean(fig) == pytest.approx(mean, rel=1e-3)
    # the French curve through 37 points with the corner at the cut-off, and the chords of the dividers
    assert excess_work(fig) == pytest.approx(work, rel=0.01)
    assert all(c.ok for c in fig.checks())


def test_return_stroke_differs_from_forward_only_by_the_rod():
    """Baumann's assumption makes the two strokes' diagrams equal for the infinitely long rod; the finite rod
    (here L/r = 5) makes them differ -- the table shows both, so his claim can be weighed."""
    fig = TP.figure(force="baumann", revolution=True, rod_ratio=5.0, parts=18)
    fwd = [revolution_ordinate(fig, j) for j in range(1, 18)]
    ret = [revolution_ordinate(fig, 18 + j) for j in range(1, 18)]
    assert max(abs(a - b) for a, b in zip(fwd, ret)) > 0.3
    for j in (3, 21):
        w = math.pi * j / 18
        assert revolution_ordinate(fig, j) == pytest.approx(float(unit_t_mp(w, 5) * baumann_force_mp(w, 5, 8)),
                                                            abs=5e-5)


def test_table_with_baumann_force(capsys):
    assert main(["table", "tangential-pressure", "--rod-ratio", "5", "--parts", "6", "--method", "exact",
                 "--revolution", "--force", "baumann", "--kappa", "2", "--format", "csv"]) == 0
    out, err = capsys.readouterr()
    assert "mirrored" in err and "assumption" in err
    lines = out.strip().splitlines()
    assert lines[0] == "crank_angle_deg,T_over_P,T"
    for line in lines[1:]:
        deg, _, t = map(float, line.split(","))
        w = math.radians(deg)
        expected = 0.0 if round(deg) % 180 == 0 else float(unit_t_mp(w, 5) * baumann_force_mp(w, 5, 2.0))
        assert t == pytest.approx(expected, abs=1e-9)


@pytest.mark.parametrize("args, says", [
    (["--kappa", "2"], "--force baumann"),
    (["--force", "baumann", "--kappa", "-1"], "kappa"),
    (["--force", "newton"], "invalid choice"),
])
def test_table_force_refusals(capsys, args, says):
    assert main(["table", "tangential-pressure", "--rod-ratio", "5", *args]) == 2
    out, err = capsys.readouterr()
    assert out == "" and says in err and len(err.strip().splitlines()) == 1
