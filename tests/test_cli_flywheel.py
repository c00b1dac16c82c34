"""``construct flywheel``: Baumann's procedure from the excess work to the weights (seed 004).

References: E = (G_s/g)·v²·δ solved with mpmath, v = π D n/60; his six worked totals printed in the
seed ("Richtige Werte", to 50 kg; his 116800 read as 16800, a typesetting error his own rim 12000 +
arms 4800 confirms); his arms-and-hub coefficients as printed (0.06, 0.08075).
"""

import json

import mpmath
import pytest

from construct.books.baumann import flywheel as fw
from construct.books.baumann import printed as seed004
from construct.cli.main import main

MPMATH_DPS = 30  # the digits of the mpmath references: each test runs under mpmath.workdps (conftest.py)


def _json(capsys, argv):
    assert main(argv + ["--format", "json"]) == 0
    return json.loads(capsys.readouterr().out)


def test_rim_weight_from_excess_work_by_mpmath(capsys):
    E, delta, D, n, kz = 1234.5, mpmath.mpf(1) / 80, mpmath.mpf("3.6"), 95, 110
    rec = _json(capsys, ["flywheel", "--excess-work", "1234.5", "--fluctuation", "1/80", "--diameter", "3.6",
                         "--rpm", "95", "--kz", "110"])
    v = mpmath.pi * D * n / 60
    gs = mpmath.mpf("9.81") * E / (v ** 2 * delta)
    x = v ** 2 / kz
    total = gs * (1 + mpmath.mpf("0.06") * x)
    assert set(("excess_work", "rim_weight", "arms_hub_weight", "total_weight", "moment")) <= set(rec)
    assert rec["excess_work"] == pytest.approx(1234.5, rel=1e-15)
    assert rec["rim_weight"] == pytest.approx(float(gs), rel=1e-12)
    assert rec["total_weight"] == pytest.approx(float(total), rel=1e-12)
    assert rec["arms_hub_weight"] == pytest.approx(float(total - total / (1 + mpmath.mpf("0.08075") * x)), rel=1e-12)
    assert rec["rim_of_wheel"] + rec["arms_hub_weight"] == pytest.approx(rec["total_weight"], rel=1e-14)
    # the moment G_s D² is 3600 g E / (π² n² δ), whatever D
    assert rec["moment"] == pytest.approx(float(3600 * mpmath.mpf("9.81") * E / (mpmath.pi ** 2 * n ** 2 * delta)),
                                          rel=1e-12)


def test_speed_instead_of_diameter(capsys):
    a = _json(capsys, ["flywheel", "--excess-work", "800", "--fluctuation", "0.02", "--diameter", "4", "--rpm", "90"])
    b = _json(capsys, ["flywheel", "--excess-work", "800", "--fluctuation", "0.02", "--v", str(a["rim_speed"]),
                       "--rpm", "90"])
    assert b["diameter"] == pytest.approx(4.0, rel=1e-14)
    assert b["rim_weight"] == pytest.approx(a["rim_weight"], rel=1e-14)
    assert a["kz"] == pytest.approx(5 * a["rim_speed"], rel=1e-15) and "5 v" in a["kz_rule"]


@pytest.mark.parametrize("i", range(6))
def test_baumanns_six_worked_totals_from_his_own_gs(capsys, i):
    gs, d, n = fw.WORKED[i]
    v = seed004.WORKED_V[i].replace(",", ".")      # his printed (rounded) rim speed, as he computes with it
    rec = _json(capsys, ["flywheel", "--rim-weight", str(gs), "--v", v, "--rpm", str(n)])
    printed = float(seed004.WORKED_TOTALS[i])
    if printed == 116800:      # typesetting: his rim 12000 and arms 4800 add to 16800
        printed = 16800.0
        assert sum(float(t) for t in seed004.WORKED_RIMS[i]) == printed
    # he prints to 50 kg; three of the six lie 1 to 1.4 units of that place off (14057 printed 14000,
    # 16731 printed 16800, 13719 printed 13750): within 2 units, the "slip" of the errata, and within
    # the 0.5 % of a slide rule
    assert abs(rec["total_weight"] - printed) <= 100.0
    assert abs(rec["total_weight"] - printed) <= 0.005 * printed
    assert abs(rec["diameter"] - d) < 0.01   # and his v is π D n/60 to his rounding (17,65 for 17,67)


def test_from_the_tangential_diagram(capsys):
    from construct.constructions import get
    from construct.constructions.tangential import model_summary

    rec = _json(capsys, ["flywheel", "--diagram", "tangential-pressure", "--given", "kappa=2", "--piston-area", "1000",
                         "--crank-radius", "0.5", "--rpm", "100", "--fluctuation", "1/60", "--diameter", "4"])
    fig = get("tangential-pressure").figure(kappa=2.0)
    exact = model_summary(fig.replay.givens, "baumann")["excess"]
    # the drawn excess area (18 ordinates, French curve) within 1 % of the exact integral
    assert rec["excess_work"] == pytest.approx(exact * 1000 * 0.5, rel=1e-2)
    assert rec["excess_source"].startswith("excess area")


@pytest.mark.parametrize("argv, words", [
    (["--excess-work", "100", "--diameter", "3", "--rpm", "100"], "--fluctuation"),
    (["--excess-work", "100", "--fluctuation", "1/50", "--rpm", "100"], "diameter"),
    (["--excess-work", "100", "--rim-weight", "5", "--diameter", "3", "--rpm", "100"], "one of them"),
    (["--excess-work", "-1", "--fluctuation", "1/50", "--diameter", "3", "--rpm", "100"], "excess work E = -1"),
    (["--excess-work", "1", "--fluctuation", "1/2", "--diameter", "3", "--rpm", "100"], "irregularity"),
    (["--excess-work", "1", "--fluctuation", "1/x", "--diameter", "3", "--rpm", "100"], "1/x"),
    (["--diagram", "tangential-pressure", "--rpm", "100", "--diameter", "3", "--fluctuation", "0.02"], "--piston-area"),
    (["--excess-work", "nan", "--fluctuation", "0.02", "--diameter", "3", "--rpm", "100"], "finite"),
])
def test_bad_input_one_line_exit_2(capsys, argv, words):
    assert main(["flywheel"] + argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and words in err and err.count("\n") == 1
