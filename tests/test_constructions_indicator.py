"""Baumann's idealised indicator diagram: the ray-constructed hyperbolas against mpmath.

References: the model of seed 004 ("Bestimmung des Fehlers"), evaluated with mpmath --
(P + P0)(s1 + s0) = (Pa + P0)(sa + s0) on the expansion, P0 (s3 + s0) = p (s - sa + s0)
on the compression -- never this code's own output.
"""

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from construct.constructions.checking import all_ok
from construct.cli.main import main
from construct.constructions import get
from construct.constructions.crank import build_frame
from construct.constructions.indicator import (
    BAUMANN,
    abscissa,
    indicator_frame,
    indicator_givens,
    pressure,
    pressures_at,
)
from construct.kernel.errors import InvalidParameter
from construct.kernel.instruments import Builder

MPMATH_DPS = 30  # the digits of the mpmath references: each test runs under mpmath.workdps (conftest.py)
INDICATOR = get("indicator-diagram")


def steam_mp(x, g):
    x = mpmath.mpf(x)
    s1, s0, P, P0 = (mpmath.mpf(g[k]) for k in ("filling", "clearance", "admission", "back_pressure"))
    return P + P0 if x <= s1 else (P + P0) * (s1 + s0) / (x + s0)


def back_mp(x, g):
    x = mpmath.mpf(x)
    s3, s0, P0 = (mpmath.mpf(g[k]) for k in ("compression", "clearance", "back_pressure"))
    return P0 if x <= 1 - s3 else P0 * (s3 + s0) / (1 - x + s0)


CASES = [
    {},  # Baumann's case: P = 7.85 at, s1 = 10 %, s0 = 5 %, P0 = 0.15 at, compression 30 %
    {"filling": 0.4, "admission": 4.85},  # his second case (p = 4.85 at, s1 = 40 %)
    {"filling": 0.25, "clearance": 0.08, "admission": 7.0, "back_pressure": 2.0, "compression": 0.25},
]


@pytest.mark.parametrize("params", CASES)
def test_every_point_lies_on_its_hyperbola(params):
    fig = INDICATOR.figure(**params)
    g = fig.replay.givens
    n = fig.params["divisions"]
    on_expansion = on_compression = 0
    for k in range(n + 1):
        x_nominal = mpmath.mpf(k) / n
        assert abscissa(fig, f"E{k}") == pytest.approx(float(x_nominal), abs=1e-12)
        assert pressure(fig, f"E{k}") == pytest.approx(float(steam_mp(x_nominal, g)), abs=1e-11)
        assert pressure(fig, f"R{k}") == pytest.approx(float(back_mp(x_nominal, g)), abs=1e-11)
        if x_nominal > g["filling"] + 1e-9:
            on_expansion += 1
            x, p = abscissa(fig, f"E{k}"), pressure(fig, f"E{k}")
            const = (mpmath.mpf(g["admission"]) + g["back_pressure"]) * (mpmath.mpf(g["filling"]) + g["clearance"])
            assert p * (x + g["clearance"]) == pytest.approx(float(const), rel=1e-12)
        if x_nominal > 1 - g["compression"] + 1e-9:
            on_compression += 1
            x, p = abscissa(fig, f"R{k}"), pressure(fig, f"R{k}")
            const = mpmath.mpf(g["back_pressure"]) * (mpmath.mpf(g["compression"]) + g["clearance"])
            assert p * (1 - x + g["clearance"]) == pytest.approx(float(const), rel=1e-12)
    assert on_expansion >= 5 and on_compression >= 2
    assert all_ok(INDICATOR.checks(fig))


def test_end_pressures_of_baumanns_case():
    fig = INDICATOR.figure()
    # expansion end 8 * 0.15 / 1.05 (expansion ratio 7); compression end 0.15 * 0.35 / 0.05
    assert pressure(fig, "E10") == pytest.approx(8.0 / 7.0, abs=1e-12)
    assert pressure(fig, "R10") == pytest.approx(1.05, abs=1e-12)
    assert pressure(fig, "A1") == pytest.approx(8.0, abs=1e-12)
    assert abscissa(fig, "C2") == pytest.approx(0.7, abs=1e-12)


def test_tangents_meet_the_zero_line_at_twice_the_abscissa():
    fig = INDICATOR.figure()
    s0 = fig.replay.givens["clearance"]
    (px, py), (qx, qy) = fig.replay["tE5"]
    x, p = abscissa(fig, "E5"), pressure(fig, "E5")
    # slope of p = c/(x + s0) in drawing units: -p/(x + s0) times (pressure unit / stroke)
    slope = (qy - py) / (qx - px)
    u, s = fig.replay.givens["pressure_unit"], 2.0 * fig.replay.givens["r"]
    assert slope == pytest.approx(-p / (x + s0) * u / s, rel=1e-11)


def test_replay_with_new_pressures_keeps_the_steps():
    fig = INDICATOR.figure()
    again = INDICATOR.replay(fig.protocol, admission=9.85, back_pressure=0.2)
    g = again.replay.givens
    assert pressure(again, "E6") == pytest.approx(float(steam_mp(0.6, g)), abs=1e-11)
    assert pressure(again, "R9") == pytest.approx(float(back_mp(0.9, g)), abs=1e-11)


def test_replay_refuses_a_new_filling():
    fig = INDICATOR.figure()
    with pytest.raises(InvalidParameter, match="filling"):
        INDICATOR.replay(fig.protocol, filling=0.3)


@pytest.mark.parametrize("bad", [{"filling": 1.2}, {"compression": 1.0}, {"admission": -1.0}, {"clearance": 0.0}])
def test_bad_givens_raise(bad):
    with pytest.raises(InvalidParameter):
        INDICATOR.figure(**bad)


def test_cli_bad_filling_is_one_line(capsys):
    assert main(["check", "indicator-diagram", "--filling", "1.5"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "filling" in err


def test_cli_check_with_book_terms(capsys):
    assert main(["check", "indicator-diagram", "--filling", "0.2", "--clearance", "0.08", "--admission", "6",
                 "--back-pressure", "1", "--compression", "0.2"]) == 0


def test_builder_api_on_the_crank_frame():
    """The reusable part: a diagram on the crank's stroke line, pressures on any perpendicular."""
    givens = {"r": 1.0, "rod_ratio": 5.0, **indicator_givens(**BAUMANN, pressure_unit=0.1)}
    b = Builder("demo", givens)
    f = build_frame(b)
    d = indicator_frame(b, base=f["axis"], head=f["D0"], crank=f["D1"], prefix="i.")
    # a perpendicular at 3/4 of the stroke
    k = b.circle_radius("k", f["O"], f["r"])
    top = b.intersect("top", k, b.perpendicular_bisector("v", f["D0"], f["D1"]), rule=("toward", f["O"], None, 0, 1))
    mid = b.midpoint("M", f["O"], f["D1"], through=f["axis"])
    o = b.erect_perpendicular("o", mid, f["axis"], f["D1"])
    pts = pressures_at(b, d, o, "q")
    assert set(pts) == {"steam", "back"} and pts["steam"] == "i.Eq" and pts["back"] == "i.Rq"
    height = lambda name: b[name][1] / 0.1  # the stroke line is y = 0
    assert height(pts["steam"]) == pytest.approx(float(steam_mp(0.75, givens)), abs=1e-12)
    assert height(pts["back"]) == pytest.approx(float(back_mp(0.75, givens)), abs=1e-12)
    del top


@settings(max_examples=12, deadline=None)
@given(filling=st.floats(0.02, 0.9), clearance=st.floats(0.005, 0.3), admission=st.floats(0.5, 15.0),
       back_pressure=st.floats(0.05, 3.0), compression=st.floats(0.02, 0.9))
def test_hyperbola_invariant_for_any_diagram(filling, clearance, admission, back_pressure, compression):
    fig = INDICATOR.figure(filling=filling, clearance=clearance, admission=admission, back_pressure=back_pressure,
                           compression=compression, divisions=6)
    g = fig.replay.givens
    for k in range(7):
        x = abscissa(fig, f"E{k}")
        assert pressure(fig, f"E{k}") == pytest.approx(float(steam_mp(k / 6, g)), rel=1e-11, abs=1e-11)
        assert pressure(fig, f"R{k}") == pytest.approx(float(back_mp(k / 6, g)), rel=1e-11, abs=1e-11)
        assert x == pytest.approx(k / 6, abs=1e-12)
    assert all_ok(INDICATOR.checks(fig))
