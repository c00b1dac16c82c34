"""The tangential-pressure diagram of seed 004 (Baumann 1902, Fig. 26/27) against independent mpmath values.

References: T/P' = sin(ω + β)/cos β with sin β = (r/L) sin ω (DESIGN §5), the exact piston
path, Baumann's steam-diagram model, all evaluated here with mpmath; never this code's output.
"""

import math

import mpmath
import pytest

from construct.constructions.checking import all_ok
from construct.cli.main import main
from construct.constructions import get
from construct.constructions.tangential import (
    chord_shortfall,
    crossing_angles,
    excess_area,
    free_force,
    mean_height,
    ok_over_r,
    t_over_unit,
)
from construct.kernel.errors import InvalidParameter
from construct.kernel.protocol import Protocol

MPMATH_DPS = 30  # the digits of the mpmath references: each test runs under mpmath.workdps (conftest.py)
TP = get("tangential-pressure")


def factor_mp(w, K):
    w = mpmath.mpf(w)
    b = mpmath.asin(mpmath.sin(w) / K)
    return mpmath.sin(w + b) / mpmath.cos(b)


def free_force_mp(w, K, kappa, P=7.85, P0=0.15, s1=0.10, s0=0.05, s3=0.30):
    """Baumann's P' at crank angle w: steam over back pressure, less B = P/(κ(1 + r/L))(cos w + r/L cos 2w)."""
    w, lam = mpmath.mpf(w), mpmath.mpf(1) / K
    x = (1 - mpmath.cos(w) + (1 - mpmath.sqrt(1 - (lam * mpmath.sin(w)) ** 2)) / lam) / 2
    steam = P + P0 if x <= s1 else (P + P0) * (s1 + s0) / (x + s0)
    back = P0 if x <= 1 - s3 else P0 * (s3 + s0) / (1 - x + s0)
    return steam - back - P / (kappa * (1 + lam)) * (mpmath.cos(w) + lam * mpmath.cos(2 * w))


@pytest.fixture(scope="module")
def unit12():
    return TP.figure(force="unit", parts=12, method="exact", rod_ratio=5.0)


@pytest.fixture(scope="module")
def book():
    return TP.figure()


def test_ok_over_r_is_the_tangential_factor(unit12):
    for k in range(13):
        w = mpmath.pi * k / 12
        expected = 0.0 if k in (0, 12) else float(factor_mp(w, 5))
        assert ok_over_r(unit12, k) == pytest.approx(expected, abs=1e-12)
        assert t_over_unit(unit12, k) == pytest.approx(expected, abs=1e-12)


def test_at_ninety_degrees_T_equals_P(unit12):
    # the rod line through the 90° point meets the vertical through O at the crank pin itself... only for
    # an infinite rod; for a finite rod sin(90° + β)/cos β = 1 all the same
    assert ok_over_r(unit12, 6) == pytest.approx(1.0, abs=1e-12)


def test_baumann_free_force_and_T_follow_the_model(book):
    n = book.params["parts"]
    for k in (1, 3, 4, 9, 13, 16, 17):
        P = book.replay[f"P{k}"] if f"P{k}" in book.replay else None
        w = math.atan2(P[1], -P[0])  # the angle the drawn point has (division by Dürer: approximate)
        assert free_force(book, k) == pytest.approx(float(free_force_mp(w, 5, 8.0)), abs=1e-10)
        expected_t = free_force_mp(w, 5, 8.0) * factor_mp(w, 5)
        assert t_over_unit(book, k) == pytest.approx(float(expected_t), abs=1e-10)
    assert n == 18


def _model_summary_mp(K, kappa):
    t = lambda w: free_force_mp(w, K, kappa) * factor_mp(w, K)  # noqa: E731
    lam = mpmath.mpf(1) / K
    path = lambda w: (1 - mpmath.cos(w) + (1 - mpmath.sqrt(1 - (lam * mpmath.sin(w)) ** 2)) / lam) / 2  # noqa: E731
    wf = mpmath.findroot(lambda w: path(w) - mpmath.mpf("0.10"), 0.6)
    wc = mpmath.findroot(lambda w: path(w) - mpmath.mpf("0.70"), 1.9)
    with mpmath.workdps(15):
        mean = mpmath.quad(t, [0, wf, wc, mpmath.pi]) / mpmath.pi
        a1 = mpmath.findroot(lambda w: t(w) - mean, (0.05, wf), solver="bisect")
        a2 = mpmath.findroot(lambda w: t(w) - mean, (wc - 0.2, mpmath.pi - 0.05), solver="bisect")
        excess = mpmath.quad(lambda w: t(w) - mean, [a1, wf, a2])
    return float(mean), float(a1), float(a2), float(excess)


@pytest.mark.parametrize("kappa", [8.0, 2.0])
def test_mean_line_crossings_and_excess_area(kappa):
    fig = TP.figure(kappa=kappa)
    mean, a1, a2, excess = _model_summary_mp(5, kappa)
    # the curve is drawn through 19 points: the drawing misses the corner at the cut-off (< 0.3 %)
    assert mean_height(fig) == pytest.approx(mean, rel=3e-3)
    m1, m2 = crossing_angles(fig)
    assert m1 == pytest.approx(a1, abs=3e-3)
    assert m2 == pytest.approx(a2, abs=5e-3)
    # the chord-stepped abscissae shorten every area by (1 - n chord/(pi r)) = 0.13 %, the drawing ~0.5 %
    assert excess_area(fig) == pytest.approx(excess, rel=1e-2)
    assert all_ok(TP.checks(fig))


def test_mean_height_is_two_P_i_over_pi_for_a_unit_force():
    fig = TP.figure(force="unit", parts=24, method="exact")
    assert mean_height(fig) == pytest.approx(2 / math.pi, abs=5e-5)


def test_unrolled_circle_is_approximate_and_says_by_how_much(book):
    n = 18
    made_by = book.replay.made_by()
    prov = made_by[f"U{n}"].provenance
    assert prov.kind in ("approximate", "trial") and "chord" in prov.method
    assert prov.error == pytest.approx(float(mpmath.pi - 2 * n * mpmath.sin(mpmath.pi / (2 * n))), rel=1e-9)
    length = book.replay["U0"].distance(book.replay[f"U{n}"])
    assert length == pytest.approx(math.pi - chord_shortfall(n), abs=1e-6)
    assert made_by["M0"].provenance.kind == "approximate" and "planimeter" in made_by["M0"].provenance.method
    assert made_by["excess"].provenance.kind == "approximate"


def test_checks_pass_for_other_rod_ratios_and_divisions():
    for kw in ({"rod_ratio": 4.0, "parts": 9}, {"rod_ratio": 6.0, "parts": 36, "kappa": 3.0},
               {"force": "unit", "parts": 6}, {"filling": 0.3, "parts": 12}):
        fig = TP.figure(**kw)
        failed = [c.name for c in TP.checks(fig) if not c.ok]
        assert not failed, (kw, failed)


def test_replay_with_a_new_rod_ratio_matches_a_fresh_build(book):
    # A replay keeps the givens it is not told to change, κ = P/B_max among them (Baumann's given, the
    # figure's caption): c v²/r = P/((1 + r/L) κ) follows the new rod, as a fresh build at that rod has it.
    replayed = TP.replay(Protocol.from_json(book.protocol.to_json()), rod_ratio=4.0)
    fresh = TP.figure(rod_ratio=4.0, kappa=8.0)
    assert replayed.replay.givens["pressure_ratio"] == pytest.approx(7.85 / (8.0 * 1.25), rel=1e-15)
    for k in (2, 7, 15):
        assert t_over_unit(replayed, k) == pytest.approx(t_over_unit(fresh, k), abs=1e-12)
    # and with a new κ (Baumann's second case, 2): four times the inertia
    again = TP.replay(Protocol.from_json(book.protocol.to_json()), kappa=2.0)
    assert again.replay.givens["pressure_ratio"] == pytest.approx(4 * 7.85 / (8.0 * 1.2), rel=1e-15)
    for k in (2, 7, 15):
        assert t_over_unit(again, k) == pytest.approx(t_over_unit(TP.figure(kappa=2.0), k), abs=1e-12)


def test_a_protocol_written_before_kappa_was_a_given_keeps_its_engine(book):
    """An older protocol has no κ: replayed with another rod it keeps its c v²/r (κ then follows the rod)."""
    import json

    data = json.loads(book.protocol.to_json())
    del data["params"]["givens"]["kappa"]
    data["givens"].remove("kappa")
    replayed = TP.replay(Protocol.from_json(json.dumps(data)), rod_ratio=4.0)
    assert replayed.replay.givens["pressure_ratio"] == pytest.approx(7.85 / (8.0 * 1.2), rel=1e-15)


@pytest.mark.parametrize("kw", [{"kappa": -1.0}, {"force": "nonsense"}, {"rod_ratio": 0.5}, {"filling": 1.5},
                                {"parts": 1}])
def test_bad_input_raises_typed_errors(kw):
    with pytest.raises(InvalidParameter):
        TP.figure(**kw)


def test_table_cli(capsys):
    assert main(["table", "tangential-pressure", "--rod-ratio", "5", "--parts", "6", "--format", "csv"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == "crank_angle_deg,OK_over_r,T_over_P"
    assert len(lines) == 8
    angle, ok, t = (float(v) for v in lines[2].split(","))
    assert angle == pytest.approx(30.0, abs=1e-9)
    assert ok == pytest.approx(float(factor_mp(mpmath.pi / 6, 5)), abs=1e-12)
    assert t == pytest.approx(ok, abs=1e-12)


def test_check_cli_and_bad_option(capsys):
    assert main(["check", "tangential-pressure", "--kappa", "2", "--parts", "9"]) == 0
    out = capsys.readouterr()
    assert "30 of 30 checks pass" in out.out + out.err
    assert main(["check", "tangential-pressure", "--kappa", "-2"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "kappa" in err[0]


@pytest.mark.parametrize("force", ["baumann", "unit"])
def test_the_sweeps_model_equals_the_model_of_each_set(force):
    """model_summary of a sweep's givens (one numpy pass over many rod ratios) gives, set by set, what it gives
    for one set."""
    import numpy as np

    from construct.constructions.tangential import model_summary

    ratios = np.array([1.05, 1.3, 2.0, 5.0, 12.0, 50.0])
    g = dict(TP.figure(force=force, parts=6).replay.givens)
    swept = model_summary({**g, "rod_ratio": ratios}, force)
    for i, ratio in enumerate(ratios):
        one = model_summary({**g, "rod_ratio": float(ratio)}, force)
        for key in ("mean", "alpha1", "alpha2", "excess"):
            assert abs(swept[key][i] - one[key]) <= 1e-13 * max(1.0, abs(one[key])), (force, ratio, key)
        assert len(swept["kinks"]) == len(one["kinks"])
        for a, b in zip(swept["kinks"], one["kinks"]):
            assert abs(a[i] - b) <= 1e-14, (force, ratio)


@pytest.mark.parametrize("kw", [{"parts": 9}, {"revolution": True, "machine": "compound", "parts": 6}])
def test_height_names_are_those_a_scan_of_the_replay_finds(kw):
    """The scale's names, found once per protocol, are those the pattern finds among every name of a replay (the
    book figure's, a sweep's values, a replay of part of the steps)."""
    from construct.constructions.tangential.plate import _HEIGHTS, height_names

    fig = TP.figure(**kw)
    proto = fig.protocol
    sweep = proto.replay({**fig.replay.givens, "kappa": [2.0, 8.0]})
    whole = [k for k in fig.replay if _HEIGHTS.fullmatch(k)]
    # (the ordinates' ends are among the last steps: a replay that stops a few short has some of them)
    part = next(R for R in map(lambda u: proto.replay(upto=u), range(len(proto.steps) - 1, 0, -1))
                if 0 < len([k for k in R if _HEIGHTS.fullmatch(k)]) < len(whole) - 1)
    for R in (fig.replay, sweep.take(0), sweep.take(1), part, fig.replay):
        assert height_names(R) == [k for k in R if _HEIGHTS.fullmatch(k)]
