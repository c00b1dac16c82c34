"""Baumann's Fig. 27 (seed 004): indicated and effective work, friction as a constant tangential force.

References: Baumann's own statements -- "Diese Fläche [LHM] ist aber gleich der Fläche EBF, so lange man annimmt,
dass der der Reibungsarbeit entsprechende Tangentialdruck in jeder Kurbelstellung einen konstanten Wert hat";
N "senkrecht unter F und M"; "Fläche EBF und damit LHM = Fläche FCODP" -- and the efficiency's definition
(effective over indicated work: the effective mean line at η·T_m); his indicated diagram from mpmath quadrature
of his equations (the tangential-pressure tests' model, written out here again).
"""


import mpmath
import pytest

from construct.constructions import get
from construct.constructions.effective_work import flywheel_share, planimetered
from construct.kernel.errors import InvalidParameter

MPMATH_DPS = 30


@pytest.fixture(scope="module", params=[0.7, 0.92])
def fig(request):
    return get("effective-work").figure(parts=12, efficiency=request.param)


def _height(fig, name):
    R = fig.replay
    return (R[name][1] - R["U0"][1]) / R.givens["pressure_unit"]


def test_the_effective_excess_is_the_indicated_one(fig):
    """LHM = EBF: the effective line is the indicated one moved down by the friction R."""
    ebf = planimetered(fig, "excess")
    assert ebf > 0.5
    assert planimetered(fig, "effective") == pytest.approx(ebf, rel=1e-6)


def test_the_flywheel_gives_back_what_it_took(fig):
    """FCODP = EBF: below the mean line from F to the stroke's end and from the next stroke's start to E."""
    deficit = planimetered(fig, "deficit.end") + planimetered(fig, "deficit.start")
    assert deficit == pytest.approx(planimetered(fig, "excess"), rel=1e-5)


def test_the_effective_mean_line_and_the_friction(fig):
    eta = fig.replay.givens["efficiency"]
    tm = _height(fig, "M0")
    assert _height(fig, "EM0") == pytest.approx(eta * tm, rel=1e-12)
    assert float(fig.replay["R.eff"]) / fig.replay.givens["pressure_unit"] == pytest.approx((1 - eta) * tm, rel=1e-11)
    # every effective point is its indicated point less R (the compass along the ordinate)
    for k in range(1, 12):
        assert _height(fig, f"eff{k}") == pytest.approx(_height(fig, f"T{k}") - (1 - eta) * tm, abs=1e-11)


def test_l_m_n_stand_under_e_and_f(fig):
    R = fig.replay
    assert R["L.eff"][0] == pytest.approx(R["A1"][0], abs=1e-8)
    assert R["M.eff"][0] == pytest.approx(R["A2"][0], abs=1e-8)
    assert R["N.eff.F"][0] == pytest.approx(R["A2"][0], abs=1e-12) and R["N.eff.F"][1] == pytest.approx(R["U0"][1])
    assert all(c.ok for c in fig.checks())


def test_the_mean_height_is_baumanns_2_p_i_over_pi_by_quadrature():
    """T_m = (1/π)∫T dα of his diagram, the indicated mean line, against mpmath quadrature of T(α): his idealised
    diagram (P = 7,85 at over the back pressure, P0 = 0,15 at, s1 = 10 %, s0 = 5 %, compression from s − s3,
    s3 = 30 %, his equations 1)–3)) less the acceleration force with κ = 8 (B_max = P/κ, r/L = 1/5), times
    sin(α + β)/cos β, exact kinematics."""
    fig = get("effective-work").figure(parts=36)
    lam = 1 / mpmath.mpf(5)
    P, P0, s1, s0, s3 = (mpmath.mpf(x) for x in ("7.85", "0.15", "0.1", "0.05", "0.3"))

    def T(a):
        x = (1 - mpmath.cos(a) + (1 - mpmath.sqrt(1 - (lam * mpmath.sin(a)) ** 2)) / lam) / 2   # of the stroke
        back = P0 if x <= 1 - s3 else P0 * (s3 + s0) / (1 - x + s0)
        net = P if x <= s1 else (P + P0) * (s1 + s0) / (x + s0) - back
        accel = P / 8 * (mpmath.cos(a) + lam * mpmath.cos(2 * a)) / (1 + lam)
        sb = lam * mpmath.sin(a)
        return (net - accel) * mpmath.sin(a + mpmath.asin(sb)) / mpmath.sqrt(1 - sb ** 2)

    cut = mpmath.findroot(lambda a: (1 - mpmath.cos(a) + (1 - mpmath.sqrt(1 - (lam * mpmath.sin(a)) ** 2)) / lam) / 2
                          - s1, 0.6)
    comp = mpmath.findroot(lambda a: (1 - mpmath.cos(a) + (1 - mpmath.sqrt(1 - (lam * mpmath.sin(a)) ** 2)) / lam) / 2
                           - (1 - s3), 2.0)
    tm = mpmath.quad(T, [0, cut, comp, mpmath.pi]) / mpmath.pi
    # drawn: the French curve through 37 points, the dividers' unrolled base (n·chord against πr)
    assert _height(fig, "M0") == pytest.approx(float(tm), rel=3e-4)
    assert _height(fig, "EM0") == pytest.approx(float(fig.replay.givens["efficiency"] * tm), rel=3e-4)


def test_friction_proportional_to_the_piston_force_takes_up_less():
    """Baumann's other case: a share s of the friction constant, the rest proportional to the piston force --
    the effective line (1 − c)T − R0 with c = (1 − s)(1 − η) keeps (1 − c) of EBF."""
    assert flywheel_share(0.85, 1.0) == 1.0
    assert flywheel_share(0.85, 0.0) == pytest.approx(0.85, abs=1e-15)
    assert flywheel_share(0.8, 0.25) == pytest.approx(1 - 0.75 * 0.2, abs=1e-15)


def test_a_replay_with_another_efficiency_keeps_lhm_equal_to_ebf():
    c = get("effective-work")
    fig = c.figure(parts=12)
    again = c.replay(fig.protocol, efficiency=0.6)
    assert again.replay.givens["efficiency"] == 0.6
    assert planimetered(again, "effective") == pytest.approx(planimetered(again, "excess"), rel=1e-6)
    assert all(ch.ok for ch in again.checks())


@pytest.mark.parametrize("kw, words", [({"efficiency": 1.2}, "efficiency η = 1.2"), ({"efficiency": 0.1}, "0.3 .. 1"),
                                       ({"force": "unit"}, "effective-work has no parameter")])
def test_bad_givens_are_refused(kw, words):
    with pytest.raises(InvalidParameter, match=words):
        get("effective-work").figure(parts=6, **kw)
