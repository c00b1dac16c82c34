"""Four-stroke engines (seed 001 c, Abb. 1056–1058) against an independent computation with mpmath.

References: the idealised cycle written out here (suction and exhaust at constant pressure, polytropes
p V^n = const, ignition at constant volume or combustion at constant pressure), the exact piston law
x = (1 − cos θ + L/r − sqrt((L/r)² − sin² θ))/2 and the mass pressure q (cos θ + (r/L) cos 2θ); seed 001's
"about 25 at" for the explosion engine's highest pressure.
"""


import mpmath
import pytest

from construct.cli.main import main
from construct.constructions import get
from construct.constructions.four_stroke import pressure, volume
from construct.kernel.errors import InvalidParameter

MPMATH_DPS = 30  # the digits of the mpmath references: each test runs under mpmath.workdps (conftest.py)


def piston(theta, k):
    return (1 - mpmath.cos(theta) + k - mpmath.sqrt(k ** 2 - mpmath.sin(theta) ** 2)) / 2


def cycle(stroke, x, g, engine):
    """Absolute pressure (at) of the idealised cycle, 30 digits."""
    eps, n = mpmath.mpf(g["compression_ratio"]), mpmath.mpf(g["exponent"])
    vc = 1 / (eps - 1)
    v = vc + x
    pa = mpmath.mpf(g["suction"])
    if stroke == 0:
        return pa
    if stroke == 3:
        return mpmath.mpf(g["exhaust"])
    if stroke == 1:
        return pa * ((1 + vc) / v) ** n
    if engine == "explosion":
        return mpmath.mpf(g["max_pressure"]) * (vc / v) ** n
    pc, vd = pa * eps ** n, mpmath.mpf(g["cutoff"]) * vc
    return pc if v <= vd else pc * (vd / v) ** n


@pytest.fixture(scope="module", params=["explosion", "diesel"])
def case(request):
    kw = {"engine": request.param, "parts": 12}
    if request.param == "diesel":
        kw["compression_ratio"] = 14.0
    fig = get("four-stroke").figure(**kw)
    return request.param, fig


def _height(fig, name):
    rp = fig.replay
    return (rp[name][1] - rp["T0"][1]) / rp.givens["pressure_unit"]


def test_brauer_points_lie_on_the_polytropes(case):
    engine, fig = case
    g, m = fig.replay.givens, fig.params["steps"]
    eps, n = mpmath.mpf(g["compression_ratio"]), mpmath.mpf(g["exponent"])
    vc = 1 / (eps - 1)
    for j in range(m + 1):
        v = volume(fig, f"cP{j}")
        # the j-th point stands at V = (1 + V_c) ε^(−j/m), and on p V^n = p_a (1 + V_c)^n
        assert v == pytest.approx(float((1 + vc) * eps ** (-mpmath.mpf(j) / m)), rel=1e-12)
        assert pressure(fig, f"cP{j}") == pytest.approx(float(g["suction"] * ((1 + vc) / v) ** n), rel=1e-11)
    vd = vc if engine == "explosion" else g["cutoff"] * vc
    pd = g["max_pressure"] if engine == "explosion" else g["suction"] * eps ** n
    assert volume(fig, "eP0") == pytest.approx(float(vd), rel=1e-12)
    assert pressure(fig, "eP0") == pytest.approx(float(pd), rel=1e-12)
    for j in range(m + 1):
        v = volume(fig, f"eP{j}")
        assert pressure(fig, f"eP{j}") == pytest.approx(float(pd * (vd / v) ** n), rel=1e-11)
    assert volume(fig, f"eP{m}") == pytest.approx(float(1 + vc), rel=1e-12)   # lands on the crank-end dead centre


def test_explosion_peak_is_the_seeds_25_at():
    fig = get("four-stroke").figure(parts=4, steps=4)
    assert pressure(fig, "eP0") == pytest.approx(25.0, abs=1e-10)


def test_rays_satisfy_brauers_condition(case):
    _, fig = case
    g = fig.replay.givens
    n, m = mpmath.mpf(g["exponent"]), fig.params["steps"]
    ta, tb = mpmath.mpf(g["tan_alpha"]), mpmath.mpf(g["tan_beta"])
    assert float(1 + tb) == pytest.approx(float((1 + ta) ** n), rel=1e-14)
    assert float((1 + ta) ** m) == pytest.approx(g["compression_ratio"], rel=1e-13)


def test_pressure_over_720_degrees(case):
    engine, fig = case
    g, n = fig.replay.givens, fig.params["parts"]
    k = mpmath.mpf(g["rod_ratio"])
    for s in range(4):
        for i in range(n + 1):
            t = s * n + i
            theta = mpmath.pi * t / n
            x = piston(theta, k) if not (s == 1 and i == n) else mpmath.mpf(0)
            want = cycle(s, x, g, engine)
            got = _height(fig, f"A{s}.{i}")
            on_curve = (s == 1 and 0 < i < n) or (s == 2 and 0 < i < n)
            # constructed points and straight lines to float; readings on the French curve within 1 % or 0.2 % of
            # the diagram's height (near the crank end the Brauer points stand far apart: 1.39 in V for ε = 14)
            top = float(cycle(2, mpmath.mpf(0), g, engine))
            if on_curve:
                assert abs(got - float(want)) <= max(1e-2 * float(want), 2e-3 * top), (s, i)
            else:
                assert got == pytest.approx(float(want), rel=1e-9, abs=1e-9), (s, i)


def test_b_b_is_a_a_less_the_mass_pressure(case):
    _, fig = case
    g, n = fig.replay.givens, fig.params["parts"]
    q, lam = mpmath.mpf(g["pressure_ratio"]), 1 / mpmath.mpf(g["rod_ratio"])
    for s in range(4):
        for i in range(n + 1):
            theta = mpmath.pi * (s * n + i) / n
            mass = q * (mpmath.cos(theta) + lam * mpmath.cos(2 * theta))
            assert _height(fig, f"A{s}.{i}") - _height(fig, f"B{s}.{i}") == pytest.approx(float(mass), abs=1e-9)


def test_every_check_passes(case):
    _, fig = case
    checks = get("four-stroke").checks(fig)
    assert len(checks) > 100 and all(c.ok for c in checks)


def test_replay_with_other_givens_keeps_the_steps():
    from construct.kernel.protocol import Protocol

    fig = get("four-stroke").figure(parts=4, steps=4)
    again = get("four-stroke").replay(Protocol.from_json(fig.protocol.to_json()), max_pressure=30.0)
    assert pressure(again, "eP0") == pytest.approx(30.0, abs=1e-10)
    assert all(c.ok for c in get("four-stroke").checks(again))


@pytest.mark.parametrize("kw, words", [
    ({"engine": "steam"}, "engine must be one of"),
    ({"compression_ratio": 40.0}, "compression ratio ε = 40"),
    ({"max_pressure": 5.0}, "must exceed the compression end"),
    ({"engine": "diesel", "compression_ratio": 14.0, "cutoff": 14.0}, "cut-off ratio"),
    ({"exponent": 2.0}, "polytropic exponent n = 2"),
    ({"steps": 1}, "Brauer steps"),
])
def test_bad_givens_are_refused(kw, words):
    with pytest.raises(InvalidParameter, match=words):
        get("four-stroke").figure(parts=4, **kw)


def test_cli_bad_engine_one_line(capsys, tmp_path):
    out = tmp_path / "x"
    assert main(["replay", "four-stroke", "--engine", "steam", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "engine" in err and not out.exists()
