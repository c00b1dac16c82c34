"""Baumann's flywheel (seed 004, Fig. 28 and his two tables): his coefficients derived afresh with mpmath.

References: his stated assumptions (disc thickness b1·r1/r from r1/6 to r1, hub r1/12..r1/6 of length 24 b1,
γ = 7200, g = 9.81), integrated here with mpmath; his printed tables and worked numbers from the seed.
"""

import mpmath
import pytest

from construct.books.baumann import flywheel as fw
from construct.cli.main import main
from construct.kernel.errors import InvalidParameter
from construct.books.baumann import printed as seed004

MPMATH_DPS = 30  # the digits of the mpmath references: each test runs under mpmath.workdps (conftest.py)


@pytest.fixture(scope="module")
def assumptions():
    """Disc and hub per unit π r1² b1 γ (r1 = b1 = 1), integrated numerically."""
    b = lambda r: 1 / r  # noqa: E731  b = b1 r1/r
    section = mpmath.quad(b, [mpmath.mpf(1) / 6, 1])
    first_moment = mpmath.quad(lambda r: b(r) * r, [mpmath.mpf(1) / 6, 1])
    centroid = first_moment / section
    disc = 2 * mpmath.pi * centroid * section / mpmath.pi           # Pappus: 2π r0 F
    hub = ((mpmath.mpf(1) / 6) ** 2 - (mpmath.mpf(1) / 12) ** 2) * 24
    rho = mpmath.findroot(lambda p: mpmath.quad(lambda r: b(r) * r, [p, 1])
                          - mpmath.quad(lambda r: b(r) * r, [mpmath.mpf(1) / 6, p]), 0.5)
    k = mpmath.mpf(7200) / (mpmath.mpf("9.81") * 10 ** 4)  # γ/(g kz), kz in kg/cm²
    return {"section": section, "centroid": centroid, "disc": disc, "hub": hub, "rho": rho, "k": k}


def test_derived_coefficients_follow_from_his_assumptions(assumptions):
    d = fw.derived()
    a = assumptions
    assert d["section"] == pytest.approx(float(a["section"]), abs=1e-12)
    assert d["centroid"] == pytest.approx(float(a["centroid"]), abs=1e-12)
    assert d["disc"] == pytest.approx(float(a["disc"]), abs=1e-12)           # 5/3, printed ∼1.7
    assert d["hub"] == pytest.approx(float(a["hub"]), abs=1e-15)             # 1/2, printed ∼0.5
    assert d["rho"] == pytest.approx(float(a["rho"]), abs=1e-12)             # 7/12 as printed
    # b1 = G1 v²/(2π r1² g kz): G2 = (disc + hub)/2 · γ/(g kz) · G1 v²
    assert d["arms_hub"] == pytest.approx(float((a["disc"] + a["hub"]) / 2 * a["k"]), abs=1e-15)


def test_printed_coefficients_reproduce_only_with_his_roundings(assumptions):
    k = float(assumptions["k"])
    # 0.08075 is 1.1 γ/(g·10⁴) = 0.080734 (his 2.2π for 13/6 π): a slip of 1.6 in the last place ...
    assert 1.1 * k == pytest.approx(fw.ARMS_HUB, abs=2e-5)
    # ... while his exact assumptions give 1.5 % less
    assert fw.derived()["arms_hub"] / fw.ARMS_HUB == pytest.approx(0.9846, abs=1e-3)
    # 0.0218 from his printed 0.0625 and 0.01825; the exact chain gives 0.0212 (2.8 % less)
    assert 0.0625 * 49 / 144 + 0.01825 * 3 / 144 == pytest.approx(fw.MOMENT, abs=2e-4)
    assert fw.derived()["moment"] == pytest.approx(0.021194, abs=1e-6)
    # 0.06 is the first-order expansion of (1 + 0.08075x)/(1 + 0.0218x): 0.05895
    assert fw.ARMS_HUB - fw.MOMENT == pytest.approx(0.059, abs=1e-4)


def test_tables_regenerated_match_his_rows():
    rows = fw.coefficient_rows()
    assert [r["kz"] for r in rows] == [float(k) for k in seed004.TABLE_KZ]
    for r, g2, total, moment, weight in zip(rows, seed004.TABLE_1_G2, seed004.TABLE_1_TOTAL,
                                           seed004.TABLE_2_MOMENT, seed004.TABLE_2_WEIGHT):
        x = r["v"] ** 2 / r["kz"]
        assert r["arms_hub"] == pytest.approx(0.08075 * x, abs=1e-15)
        # his rows agree with the formulas to his slide rule (within 0.0015)
        assert abs(float(g2.replace(",", ".")) - r["arms_hub"]) < 1.5e-3
        assert abs(float(total.replace(",", ".")) - r["total_weight"]) < 1.5e-3
        assert abs(float(moment.replace(",", ".")) - r["moment"]) < 1.5e-3
        assert abs(float(weight.replace(",", ".")) - r["weight_for_moment"]) < 1.5e-3


def test_tables_for_given_kz_and_v():
    rows = fw.coefficient_rows([100.0], [20.0, 30.0])
    assert [(r["kz"], r["v"]) for r in rows] == [(100.0, 20.0), (100.0, 30.0)]
    assert rows[1]["weight_for_moment"] == pytest.approx(1 + 0.06 * 9.0, abs=1e-15)
    with pytest.raises(InvalidParameter):
        fw.coefficient_rows([100.0, 120.0], [20.0, 25.0, 30.0])
    with pytest.raises(InvalidParameter):
        fw.coefficient_rows([-5.0], None)


def test_worked_totals():
    rows = fw.worked_totals()
    first = rows[0]
    assert first["v"] == pytest.approx(float(mpmath.pi * 3.2 * 120 / 60), abs=1e-12)   # printed 20,1
    assert round(first["total"] / 50) * 50 == 2650                                       # printed 2650
    assert round(first["rim"] / 50) * 50 == 2000 and round(first["arms_hub"] / 50) * 50 == 650
    # "116800" in the seed: 12900 (1 + 0.06 v²/kz) is 16730
    assert rows[4]["total"] == pytest.approx(16730, abs=1)


def test_required_moment_against_the_energy_of_the_rim():
    A, n, delta = 1234.0, 90.0, 1 / 60
    gd2 = fw.required_moment(A, n, delta)
    # a rim of weight G on the diameter D: (G/g) v² δ with v = π D n/60 must give back A
    D = 3.0
    G = gd2 / D ** 2
    v = mpmath.pi * D * n / 60
    assert float(G / mpmath.mpf("9.81") * v ** 2 * delta) == pytest.approx(A, rel=1e-12)
    with pytest.raises(InvalidParameter):
        fw.required_moment(A, n, 0.0)


def test_table_cli(capsys):
    assert main(["table", "flywheel-coefficients", "--format", "csv"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == "kz,v,arms_hub,total_weight,moment,weight_for_moment"
    assert len(lines) == 15
    assert lines[1].split(",")[:2] == ["75", "15"]
    assert float(lines[1].split(",")[5]) == pytest.approx(1.18, abs=1e-12)
    assert main(["table", "flywheel-coefficients", "--kz", "120", "--v", "24", "--format", "csv"]) == 0
    row = capsys.readouterr().out.splitlines()[1].split(",")
    assert float(row[2]) == pytest.approx(0.08075 * 576 / 120, abs=1e-14)
    assert main(["table", "flywheel-coefficients", "--v", "-3"]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1


def test_moment_from_the_excess_area_of_the_diagram():
    from construct.constructions import get
    from construct.constructions.tangential import excess_area

    fig = get("tangential-pressure").figure()
    ex = excess_area(fig)  # at × r
    F, r, n, delta = 1590.0, 0.4, 120.0, 1 / 80   # a cylinder of 45 cm, stroke 0.8 m
    expected = 3600 * mpmath.mpf("9.81") * ex * F * r / (mpmath.pi ** 2 * n ** 2 * delta)
    assert fw.moment_from_excess(ex, piston_area=F, crank_radius=r, rpm=n, irregularity=delta) == pytest.approx(
        float(expected), rel=1e-12)
