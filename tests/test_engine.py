"""The whole engine: Baumann's force on the return stroke, compound engines with their own
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

from construct.cli.main import main
from construct.constructions import get
from construct.constructions.revolution import excess_work, revolution_mean, revolution_ordinate

MPMATH_DPS = 25  # the digits of the mpmath references: each test runs under mpmath.workdps (conftest.py)
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


def swing(fn, samples=2000):
    """Mean and greatest swing of ∫(T − T_m) over a revolution, trapezoids on a fine grid.

    The diagrams are continuous with a few kinks (cut-off, compression), so the trapezoids' error falls as
    1/samples²: 2,000 of them are within 1e-5 (relative) of 20,000 for every diagram here, a hundredth of the
    tightest tolerance these references are held to (1e-3).
    """
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


# --------------------------------------------------------------------------
# 2. Compound and tandem engines, each cylinder with its own diagram.
# --------------------------------------------------------------------------

#: High pressure: steam line straight from 8 at to 2 at, exhaust at 1 at.  Low pressure: 3 at to 1.5 at,
#: exhaust at 0.2 at.  Both crank sides the cover side's mirrored.
HP_CARD = "x,p\n0,8\n0.5,5\n1,2\n1,1\n0.5,1\n0,1\n0,8\n"
LP_CARD = "x,p\n0,3\n0.5,2.25\n1,1.5\n1,0.2\n0.5,0.2\n0,0.2\n0,3\n"


def straight_over_mp(w, K, top, slope, exhaust):
    x = piston_mp(mpmath.mpf(w), K)
    if mpmath.sin(w) >= 0:
        return top - slope * x - exhaust
    return top - slope * (1 - x) - exhaust


def compound_t_mp(w, K, ratio, lp_offset=90):
    """Σ T: the high-pressure crank at w, the low-pressure crank lp_offset degrees ahead, its force × ratio."""
    w = mpmath.mpf(w)
    wl = w + mpmath.radians(lp_offset)
    hp = unit_t_mp(w, K) * straight_over_mp(w, K, 8, 6, 1)
    lp = unit_t_mp(wl, K) * straight_over_mp(wl, K, 3, 1.5, 0.2)
    return hp + ratio * lp


def test_compound_with_two_cards_table_in_kg(tmp_path, capsys):
    hp, lp = tmp_path / "hp.csv", tmp_path / "lp.csv"
    hp.write_text(HP_CARD)
    lp.write_text(LP_CARD)
    assert main(["table", "tangential-pressure", "--rod-ratio", "5", "--parts", "6", "--method", "exact",
                 "--revolution", "--machine", "compound", "--indicator", str(hp), "--indicator-lp", str(lp),
                 "--area-ratio", "2.5", "--piston-area", "1546.25", "--format", "csv"]) == 0
    out, err = capsys.readouterr()
    assert "low-pressure cylinder from its own" in err
    lines = out.strip().splitlines()
    assert lines[0] == "crank_angle_deg,T_over_P,T,T_kg"
    for line in lines[1:]:
        deg, _, t, kg = map(float, line.split(","))
        expected = float(compound_t_mp(math.radians(deg), 5, 2.5))
        if round(deg) % 180 == 0:  # the high-pressure crank at a dead centre: only the low-pressure one pushes
            expected = float(2.5 * unit_t_mp(math.radians(deg + 90), 5)
                             * straight_over_mp(math.radians(deg + 90), 5, 3, 1.5, 0.2))
        assert t == pytest.approx(expected, abs=1e-9)
        assert kg == pytest.approx(expected * 1546.25, abs=1e-6)


def test_compound_cards_figure_against_an_independent_summation(tmp_path):
    hp, lp = tmp_path / "hp.csv", tmp_path / "lp.csv"
    hp.write_text(HP_CARD)
    lp.write_text(LP_CARD)
    fig = TP.figure(revolution=True, machine="compound", parts=18, rod_ratio=5.0, indicator=str(hp),
                    indicator_lp=str(lp), area_ratio=2.5)
    assert all(c.ok for c in fig.checks())
    mean, work = swing(lambda w: compound_t_mp(w, 5, 2.5))
    assert revolution_mean(fig) == pytest.approx(mean, rel=1e-3)
    assert excess_work(fig) == pytest.approx(work, rel=0.02)
    # the low-pressure diagram matters: with the high-pressure card in both cylinders the sum differs
    same = TP.figure(revolution=True, machine="compound", parts=18, rod_ratio=5.0, indicator=str(hp))
    assert abs(revolution_mean(same) - revolution_mean(fig)) > 0.5


@pytest.mark.parametrize("machine, lp_offset", [("compound", 90), ("tandem", 0)])
def test_baumann_low_pressure_cylinder_of_its_own(machine, lp_offset):
    """Each cylinder its own idealised diagram: the high-pressure one Baumann's, the low-pressure one with its own
    filling, pressures, κ, and piston 2.5 times as large; the sum against mpmath at every ordinate."""
    K, ratio = 5.0, 2.5
    lp = dict(s1=0.35, s0=S0, adm=1.6, back=0.15, s3=0.30)
    fig = TP.figure(force="baumann", revolution=True, machine=machine, parts=18, rod_ratio=K)
    n = 18

    def total(w):
        wl = mpmath.mpf(w) + mpmath.radians(lp_offset)
        return (unit_t_mp(w, K) * baumann_force_mp(w, K, 8.0)
                + ratio * unit_t_mp(wl, K) * baumann_force_mp(wl, K, 8.0, **lp))

    for j in range(2 * n + 1):
        w = math.pi * j / n
        hp_dead = j in (0, n, 2 * n)
        lp_dead = (j + lp_offset // 10) % n == 0
        expected = 0.0 if hp_dead else float(unit_t_mp(w, K) * baumann_force_mp(w, K, 8.0))
        if not lp_dead:
            wl = w + math.radians(lp_offset)
            expected += float(ratio * unit_t_mp(wl, K) * baumann_force_mp(wl, K, 8.0, **lp))
        assert revolution_ordinate(fig, j) == pytest.approx(expected, abs=1e-4), j
    mean, work = swing(total)
    assert revolution_mean(fig) == pytest.approx(mean, rel=1e-3)
    assert excess_work(fig) == pytest.approx(work, rel=0.02)
    assert all(c.ok for c in fig.checks())


@pytest.mark.parametrize("args, says", [
    (["--indicator-lp", "LP"], "--indicator"),
    (["--indicator", "HP", "--indicator-lp", "LP"], "compound or tandem"),
    (["--indicator", "HP", "--indicator-lp", "LP", "--revolution", "--machine", "compound", "--area-ratio", "50"],
     "area ratio"),
    (["--indicator", "HP", "--indicator-lp", "BROKEN", "--revolution", "--machine", "compound"], "row"),
    (["--piston-area", "100"], "--piston-area"),
    (["--force", "baumann", "--piston-area", "-3"], "piston area"),
])
def test_compound_refusals(tmp_path, capsys, args, says):
    files = {"HP": HP_CARD, "LP": LP_CARD, "BROKEN": "x,p\n0,1\n0.5,zwei\n1,1\n0,1\n"}
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    args = [str(tmp_path / a) if a in files else a for a in args]
    assert main(["table", "tangential-pressure", "--rod-ratio", "5", "--parts", "6", *args]) == 2
    out, err = capsys.readouterr()
    assert out == "" and says in err and len(err.strip().splitlines()) == 1


# --------------------------------------------------------------------------
# 3. J from a card.
# --------------------------------------------------------------------------

#: Cover side: admission to 0.2, expansion to 1.6 at; exhaust at 1.1 at, compression from 0.4 back to 6 at.
#: The crank side (mirrored) compresses to 6 at near the crank end: the forward force changes sign there.
COMPRESSING = "x,p\n0,8\n0.2,8\n0.6,3\n1,1.6\n1,1.1\n0.4,1.1\n0.1,3\n0,6\n0,8\n"


def test_j_from_a_card_against_a_root_of_its_straight_lines(tmp_path):
    from construct.constructions.piston_force import abscissa
    import numpy as np

    card = tmp_path / "card.csv"
    card.write_text(COMPRESSING)
    fig = get("piston-force").figure(indicator=str(card))
    # independent: the cover side's forward line and the mirrored return line, straight between the points
    cover = lambda x: np.interp(x, [0, 0.2, 0.6, 1], [8, 8, 3, 1.6])  # noqa: E731
    crank = lambda x: np.interp(1 - x, [0, 0.1, 0.4, 1], [6, 3, 1.1, 1.1])  # noqa: E731
    root = mpmath.findroot(lambda x: float(cover(float(x)) - crank(float(x))), (0.6, 0.9), solver="bisect")
    assert abscissa(fig, "J") == pytest.approx(float(root), abs=1e-10)
    assert abscissa(fig, "J") == pytest.approx(0.6 + 1.9 / (3.5 + 1.9 / 0.3), abs=1e-12)  # the two chords by hand
    assert all(c.ok for c in fig.checks())
    assert any(c.name == "pressure change J (abscissa)" for c in fig.checks())


def test_no_j_where_the_card_force_keeps_its_sign(tmp_path):
    card = tmp_path / "card.csv"
    card.write_text(HP_CARD)
    fig = get("piston-force").figure(indicator=str(card))
    assert "J" not in fig.replay
    assert all(c.ok for c in fig.checks())


# --------------------------------------------------------------------------
# 4. The flywheel from indicator cards.
# --------------------------------------------------------------------------


def card_t_numpy(w, K, cover_fwd, crank_fwd, cover_back, crank_back):
    """T per unit piston area (at) over a revolution from straight-line cards: numpy, written here afresh."""
    import numpy as np

    lam = 1.0 / K
    x = 0.5 * (1 - np.cos(w) + (1 - np.sqrt(1 - (lam * np.sin(w)) ** 2)) / lam)
    fwd = np.interp(x, *cover_fwd) - np.interp(x, *crank_fwd)
    back = np.interp(x, *crank_back) - np.interp(x, *cover_back)
    over = np.where(np.sin(w) >= 0, fwd, back)
    beta = np.arcsin(lam * np.sin(w))
    return over * np.abs(np.sin(w + beta) / np.cos(beta))


def numpy_swing(t, w):
    import numpy as np

    mean = np.trapezoid(t, w) / (2 * math.pi) if hasattr(np, "trapezoid") else np.trapz(t, w) / (2 * math.pi)
    run = np.concatenate(([0.0], np.cumsum((t[1:] + t[:-1] - 2 * mean) * 0.5 * np.diff(w))))
    return run.max() - run.min()


def test_flywheel_from_a_card_against_numpy_integration(tmp_path, capsys):
    import json

    import numpy as np

    card = tmp_path / "card.csv"
    card.write_text(COMPRESSING)
    assert main(["flywheel", "--indicator", str(card), "--rod-ratio", "5", "--piston-area", "1546.25",
                 "--crank-radius", "0.4", "--rpm", "50", "--fluctuation", "1/80", "--diameter", "5",
                 "--format", "json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    # the cover side's lines; the crank side's are them mirrored (x -> 1 - x, the strokes exchanged)
    cover_fwd = ([0, 0.2, 0.6, 1], [8, 8, 3, 1.6])
    cover_back = ([0, 0.1, 0.4, 1], [6, 3, 1.1, 1.1])
    crank_fwd = ([0, 0.6, 0.9, 1], [1.1, 1.1, 3, 6])
    crank_back = ([0, 0.4, 0.8, 1], [1.6, 3, 8, 8])
    w = np.linspace(0, 2 * math.pi, 400001)
    swing = numpy_swing(card_t_numpy(w, 5.0, cover_fwd, crank_fwd, cover_back, crank_back), w)
    E = swing * 1546.25 * 0.4
    # drawn: 37 ordinates over the revolution, the French curve with corners at the dead centres
    assert rec["excess_work"] == pytest.approx(E, rel=0.02)
    v = math.pi * 5 * 50 / 60
    assert rec["rim_weight"] == pytest.approx(9.81 * rec["excess_work"] / (v * v / 80), rel=1e-12)
    assert "mirrored" in rec["excess_source"]


def test_flywheel_of_a_compound_from_two_cards(tmp_path, capsys):
    import json

    import numpy as np

    hp, lp = tmp_path / "hp.csv", tmp_path / "lp.csv"
    hp.write_text(HP_CARD)
    lp.write_text(LP_CARD)
    assert main(["flywheel", "--indicator", str(hp), "--indicator-lp", str(lp), "--machine", "compound",
                 "--area-ratio", "2.5", "--rod-ratio", "5", "--piston-area", "1000", "--crank-radius", "0.5",
                 "--rpm", "80", "--fluctuation", "1/100", "--diameter", "4", "--format", "json"]) == 0
    rec = json.loads(capsys.readouterr().out)
    w = np.linspace(0, 2 * math.pi, 400001)
    wl = w + math.pi / 2
    hp_t = card_t_numpy(w, 5.0, ([0, 1], [8, 2]), ([0, 1], [1, 1]), ([0, 1], [1, 1]), ([0, 1], [2, 8]))
    lp_t = card_t_numpy(wl, 5.0, ([0, 1], [3, 1.5]), ([0, 1], [0.2, 0.2]), ([0, 1], [0.2, 0.2]), ([0, 1], [1.5, 3]))
    E = numpy_swing(hp_t + 2.5 * lp_t, w) * 1000 * 0.5
    assert rec["excess_work"] == pytest.approx(E, rel=0.03)
    assert "low-pressure cylinder from its own card" in rec["excess_source"]


@pytest.mark.parametrize("argv, says", [
    (["--indicator", "CARD", "--piston-area", "100", "--crank-radius", "0.4"], "--rod-ratio"),
    (["--indicator", "CARD", "--rod-ratio", "5", "--crank-radius", "0.4"], "--piston-area"),
    (["--indicator", "CARD", "--rod-ratio", "5", "--piston-area", "100", "--crank-radius", "0.4",
      "--excess-work", "10"], "one of them"),
    (["--indicator", "CARD", "--rod-ratio", "0.5", "--piston-area", "100", "--crank-radius", "0.4"], "L/r"),
    (["--indicator", "BROKEN", "--rod-ratio", "5", "--piston-area", "100", "--crank-radius", "0.4"], "row"),
    (["--rod-ratio", "5", "--excess-work", "10"], "--indicator"),
    (["--indicator", "CARD", "--area-ratio", "2", "--rod-ratio", "5", "--piston-area", "100",
      "--crank-radius", "0.4"], "--indicator-lp"),
    (["--indicator", "CARD", "--rod-ratio", "5", "--piston-area", "0", "--crank-radius", "0.4"], "piston area"),
])
def test_flywheel_card_refusals(tmp_path, capsys, argv, says):
    (tmp_path / "CARD").write_text(COMPRESSING)
    (tmp_path / "BROKEN").write_text("x,p\n0,1\n2,1\n1,0\n0,1\n")
    argv = [str(tmp_path / a) if a in ("CARD", "BROKEN") else a for a in argv]
    assert main(["flywheel", *argv, "--rpm", "50", "--fluctuation", "1/80", "--diameter", "5"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and says in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("args, says", [
    (["--lp-admission", "2"], "--lp-admission belongs to a compound"),
    (["--area-ratio", "3", "--revolution", "--machine", "compound", "--force", "unit"], "--area-ratio belongs"),
    (["--lp-admission", "-1", "--revolution", "--machine", "compound"], "low-pressure cylinder"),
    (["--area-ratio", "50", "--revolution", "--machine", "tandem"], "area ratio F_lp/F_hp = 50"),
])
def test_low_pressure_givens_refused_where_they_do_not_apply(capsys, args, says):
    assert main(["check", "tangential-pressure", *args]) == 2
    out, err = capsys.readouterr()
    assert out == "" and says in err and len(err.strip().splitlines()) == 1


def test_table_forward_stroke_with_baumann_force(capsys):
    assert main(["table", "tangential-pressure", "--rod-ratio", "4", "--parts", "6", "--method", "exact",
                 "--force", "baumann", "--format", "csv"]) == 0
    out, err = capsys.readouterr()
    assert "mirrored" not in err   # one stroke: nothing assumed about the other
    lines = out.strip().splitlines()
    assert lines[0] == "crank_angle_deg,OK_over_r,T_over_P,T"
    for line in lines[2:-1]:
        deg, _, _, t = map(float, line.split(","))
        w = math.radians(deg)
        assert t == pytest.approx(float(unit_t_mp(w, 4) * baumann_force_mp(w, 4, 8.0)), abs=1e-9)


def test_baumanns_claim_that_unequal_strokes_do_not_change_the_result(capsys):
    """His assumption (both strokes' tangential diagrams equal) against the return stroke drawn from his own
    diagram mirrored: with L/r = 5 the flywheel's work is the revolution's greatest swing, about 5 % above the
    forward stroke's excess area; with a very long rod the two agree.  Independent: mpmath's model, trapezoids."""
    import json

    def flywheel(*extra):
        assert main(["flywheel", "--diagram", "tangential-pressure", *extra, "--piston-area", "1000",
                     "--crank-radius", "0.5", "--rpm", "100", "--fluctuation", "1/80", "--diameter", "4",
                     "--format", "json"]) == 0
        return json.loads(capsys.readouterr().out)["excess_work"]

    forward_only = lambda w: unit_t_mp(w % math.pi, 5) * baumann_force_mp(w % math.pi, 5, 8.0)  # noqa: E731
    both = lambda w: unit_t_mp(w, 5) * baumann_force_mp(w, 5, 8.0)  # noqa: E731
    ratio = swing(both)[1] / swing(forward_only)[1]
    assert 1.04 < ratio < 1.07
    assert flywheel("--revolution") / flywheel() == pytest.approx(ratio, rel=0.01)
    long_rod = lambda w: unit_t_mp(w, 1000) * baumann_force_mp(w, 1000, 8.0)  # noqa: E731
    long_fwd = lambda w: unit_t_mp(w % math.pi, 1000) * baumann_force_mp(w % math.pi, 1000, 8.0)  # noqa: E731
    assert swing(long_rod)[1] == pytest.approx(swing(long_fwd)[1], rel=2e-3)


def test_low_pressure_crank_side_card(tmp_path, capsys):
    """The low-pressure cylinder's crank side from a card of its own (not the cover side's mirrored)."""
    import numpy as np

    files = {"hp.csv": HP_CARD, "lp.csv": LP_CARD,
             # crank side in head-end coordinates: exhaust 0.2 at forward, steam 3 -> 2 -> 1 at on the return
             "lpk.csv": "x,p\n0,0.2\n1,0.2\n1,3\n0.5,2\n0,1\n0,0.2\n"}
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    assert main(["table", "tangential-pressure", "--rod-ratio", "5", "--parts", "6", "--method", "exact",
                 "--revolution", "--machine", "tandem", "--indicator", str(tmp_path / "hp.csv"),
                 "--indicator-lp", str(tmp_path / "lp.csv"), "--indicator-lp-crank-side", str(tmp_path / "lpk.csv"),
                 "--area-ratio", "3", "--format", "csv"]) == 0
    out = capsys.readouterr().out.strip().splitlines()
    for line in out[1:]:
        deg, _, t = map(float, line.split(","))
        w = math.radians(deg)
        if round(deg) % 180 == 0:
            assert t == pytest.approx(0.0, abs=1e-9)
            continue
        x = float(piston_mp(w, 5))
        lp = (3 - 1.5 * x) - 0.2 if deg < 180 else float(np.interp(x, [0, 0.5, 1], [1, 2, 3])) - 0.2
        expected = float(unit_t_mp(w, 5)) * (float(straight_over_mp(w, 5, 8, 6, 1)) + 3 * lp)
        assert t == pytest.approx(expected, abs=1e-9)
