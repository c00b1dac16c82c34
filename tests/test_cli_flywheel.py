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


def test_a_count_given_to_the_diagram_is_a_whole_number(capsys):
    """``--given parts=N`` reaches the construction as the count it is (it was stored as 18.0 and refused)."""
    from construct.constructions import get
    from construct.constructions.tangential import model_summary

    base = ["flywheel", "--diagram", "tangential-pressure", "--piston-area", "1000", "--crank-radius", "0.5",
            "--rpm", "100", "--fluctuation", "1/60", "--diameter", "4"]
    default = _json(capsys, base)
    eighteen = _json(capsys, base + ["--given", "parts=18"])
    assert eighteen["excess_work"] == default["excess_work"]        # 18 parts is the default
    finer = _json(capsys, base + ["--given", "parts=36"])
    exact = model_summary(get("tangential-pressure").figure().replay.givens, "baumann")["excess"] * 1000 * 0.5
    assert finer["excess_work"] == pytest.approx(exact, rel=1e-2)   # the drawn area, 36 ordinates


@pytest.mark.parametrize("given, words", [
    ("parts=18.5", "whole number"), ("kapa=3", "did you mean 'kappa'"), ("kappa=x", "finite number"),
    ("force=unit", "force=baumann"), ("parts", "NAME=VALUE"),
])
def test_a_bad_given_to_the_diagram_is_named(capsys, given, words):
    assert main(["flywheel", "--diagram", "tangential-pressure", "--given", given, "--piston-area", "1000",
                 "--crank-radius", "0.5", "--rpm", "100", "--fluctuation", "1/60", "--diameter", "4"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and words in err and err.count("\n") == 1


def _wheel_mp(gs, v, kz_cm2, r1=mpmath.mpf("1.6")):
    """The wheel by Baumann's assumptions, from first principles with mpmath: arms smeared into a disc of equal
    stress, thickness b1 r1/r from r1/6 to r1, hub 24 b1 long from r1/12 to r1/6, γ = 7200, g = 9.81; the rim G1
    such that the whole wheel's G·D² (each part's ∫(2r)² dG) is G_s·D1²."""
    g, gamma, kz = mpmath.mpf("9.81"), mpmath.mpf(7200), mpmath.mpf(kz_cm2) * 10 ** 4
    v = mpmath.mpf(v)

    def parts(g1):
        b1 = g1 * v ** 2 / (2 * mpmath.pi * r1 ** 2 * g * kz)
        disc_w = gamma * 2 * mpmath.pi * mpmath.quad(lambda r: b1 * r1 / r * r, [r1 / 6, r1])
        disc_m = gamma * 2 * mpmath.pi * mpmath.quad(lambda r: b1 * r1 / r * r * (2 * r) ** 2, [r1 / 6, r1])
        hub_w = gamma * 2 * mpmath.pi * mpmath.quad(lambda r: 24 * b1 * r, [r1 / 12, r1 / 6])
        hub_m = gamma * 2 * mpmath.pi * mpmath.quad(lambda r: 24 * b1 * r * (2 * r) ** 2, [r1 / 12, r1 / 6])
        return disc_w + hub_w, g1 * (2 * r1) ** 2 + disc_m + hub_m

    g1 = mpmath.findroot(lambda g1: parts(g1)[1] - mpmath.mpf(gs) * (2 * r1) ** 2, mpmath.mpf(gs))
    arms = parts(g1)[0]
    return g1, arms, g1 + arms


def test_the_exact_wheel_beside_baumanns(capsys):
    """His method is not consistent in itself; the exact column is: its wheel has the moment G_s·D² it is sized for
    (the arms' radius of gyration, not ρ = 7/12 r1), arms and hub from 13/6 π, not his 2.2 π."""
    g1, arms, total = _wheel_mp(2130, "20.1", "100.5")
    rec = _json(capsys, ["flywheel", "--rim-weight", "2130", "--v", "20.1", "--rpm", "120"])
    assert rec["exact_rim"] == pytest.approx(float(g1), rel=1e-12)
    assert rec["exact_arms_hub"] == pytest.approx(float(arms), rel=1e-12)
    assert rec["exact_total"] == pytest.approx(float(total), rel=1e-12)
    x = mpmath.mpf("20.1") ** 2 / mpmath.mpf("100.5")
    # his own figures: the total from 1 + 0.06 x, his quotient, his derivation's rim, his summary's rim
    assert rec["total_weight"] == pytest.approx(float(2130 * (1 + mpmath.mpf("0.06") * x)), rel=1e-14)
    quotient = (1 + mpmath.mpf("0.08075") * x) / (1 + mpmath.mpf("0.0218") * x)
    assert rec["total_quotient"] == pytest.approx(float(2130 * quotient), rel=1e-14)
    assert rec["rim_by_moment"] == pytest.approx(float(2130 / (1 + mpmath.mpf("0.0218") * x)), rel=1e-14)
    assert rec["rim_of_wheel"] == pytest.approx(rec["total_weight"] / float(1 + mpmath.mpf("0.08075") * x),
                                                rel=1e-14)
    assert main(["flywheel", "--rim-weight", "2130", "--v", "20.1", "--rpm", "120"]) == 0
    out = capsys.readouterr().out
    assert "Baumann, as printed" in out and "exact, from his assumptions" in out and "not consistent" in out
    assert "radius of gyration" in out and f"{rec['exact_total']:.5g}" in out


def test_his_factor_against_his_quotient():
    """At v = 17 m/s, kz = 85 (his tables' column): 1 + 0.06 x = 1.204 against his own quotient 1.1866."""
    from construct.books.baumann.flywheel import design

    x = mpmath.mpf(17) ** 2 / 85
    d = design(rim_weight=1000.0, v=17.0, rpm=100.0, kz=85.0)
    assert d["total_weight"] / 1000 == pytest.approx(1.204, abs=1e-12)
    assert d["total_quotient"] / 1000 == pytest.approx(
        float((1 + mpmath.mpf("0.08075") * x) / (1 + mpmath.mpf("0.0218") * x)), rel=1e-14)
    assert round(d["total_quotient"] / 1000, 4) == 1.1866
    # and his two rims: his derivation's G_s/(1 + 0.0218 x), his summary's total/(1 + 0.08075 x)
    assert d["rim_by_moment"] == pytest.approx(float(1000 / (1 + mpmath.mpf("0.0218") * x)), rel=1e-14)
    assert d["rim_of_wheel"] == pytest.approx(float(1204 / (1 + mpmath.mpf("0.08075") * x)), rel=1e-14)


def test_the_rim_moment_of_his_last_paragraph(capsys):
    """G1(Da² + Di²)/2 against his G1 D1², and the disc counted inside the rim, by quadrature."""
    rec = _json(capsys, ["flywheel", "--rim-weight", "2130", "--v", "20.1", "--rpm", "120", "--rim-height", "0.16"])
    c = rec["rim_moment"]
    d1, h, g1 = mpmath.mpf(rec["diameter"]), mpmath.mpf("0.16"), mpmath.mpf(rec["rim_of_wheel"])
    da, di = d1 + h, d1 - h
    assert c["rim_moment_true"] == pytest.approx(float(g1 * (da ** 2 + di ** 2) / 2), rel=1e-13)
    assert c["too_little"] == pytest.approx(float(g1 * (da ** 2 + di ** 2) / 2 - g1 * d1 ** 2), rel=1e-12)
    r1 = d1 / 2
    disc = mpmath.mpf(rec["arms_hub_weight"]) * (mpmath.mpf(5) / 3) / (mpmath.mpf(13) / 6)
    inside = mpmath.quad(lambda r: disc / (5 * r1 / 6) * (2 * r) ** 2, [r1 - h / 2, r1])
    assert c["too_much"] == pytest.approx(float(inside), rel=1e-12)
    assert main(["flywheel", "--rim-weight", "2130", "--v", "20.1", "--rpm", "120", "--rim-height", "0.16"]) == 0
    assert "too little" in capsys.readouterr().out


@pytest.mark.parametrize("argv, words, not_words", [
    (["--rim-weight", "0.01", "--v", "20", "--rpm", "120"], "kg of flywheel rim", "reciprocating"),
    (["--rim-weight", "100", "--v", "20", "--rpm", "1e6"], "of a flywheel", "mass forces"),
    (["--excess-work", "1e-6", "--fluctuation", "1/50", "--diameter", "3", "--rpm", "120"], "G_s = g E/(v² δ)",
     "reciprocating"),
])
def test_flywheel_errors_speak_of_the_flywheel(capsys, argv, words, not_words):
    assert main(["flywheel"] + argv) == 2
    err = capsys.readouterr().err
    assert words in err and not_words not in err and err.count("\n") == 1


def test_text_output_keeps_significant_digits(capsys):
    """A small wheel is printed to five figures, not rounded to 0 (the JSON has the same numbers)."""
    argv = ["flywheel", "--excess-work", "0.0005", "--fluctuation", "1/50", "--diameter", "0.5", "--rpm", "30"]
    rec = _json(capsys, argv)
    assert main(argv) == 0
    out = capsys.readouterr().out
    assert 0.1 < rec["rim_weight"] < 10
    assert f"{rec['rim_weight']:.5g}" in out and f"{rec['excess_work']:.5g}" in out and f"{rec['rim_speed']:.5g}" in out
