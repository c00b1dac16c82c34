"""Two cranks at 90° (seed 002, § 146–147) against an independent high-precision computation.

The references are computed here with mpmath from the piston's geometry
(x = r(1 − cos w) + L − sqrt(L² − r² sin² w), or r(1 − cos w) for the
infinite rod), never from construct's own formulas.
"""

import json
import math

import mpmath
import numpy as np
import pytest

from construct.cli.main import main
from construct.constructions import get
from construct.constructions.two_cranks import crank_angle, speed_radius, speeds, work_excess
from construct.kernel.errors import InvalidParameter
from construct.kernel.protocol import Protocol


def position_mp(w, ratio):
    """Piston position from the head-end dead centre, units of r (None: infinite rod)."""
    if ratio is None:
        return 1 - mpmath.cos(w)
    L = mpmath.mpf(ratio)
    return 1 - mpmath.cos(w) + L - mpmath.sqrt(L ** 2 - mpmath.sin(w) ** 2)


def travel_mp(theta0, theta1, ratio):
    """Distance travelled while the crank turns theta0..theta1: sum of |dx| over the monotone half turns
    (the piston turns back at every multiple of pi)."""
    total = mpmath.mpf(0)
    a = mpmath.mpf(theta0)
    while a < theta1:
        b = min((mpmath.floor(a / mpmath.pi + mpmath.mpf("1e-30")) + 1) * mpmath.pi, theta1)
        total += abs(position_mp(b, ratio) - position_mp(a, ratio))
        a = b
    return total


def excess_mp(j, n, ratio, dead_centre="crank-end"):
    """e(alpha_j)/(Q r), alpha_j = j pi / n from the first crank's dead centre (§ 146's B1: the crank end), 40 digits.

    The first crank turns from a0 to a0 + alpha, the second (90 degrees ahead) from a0 + 90 to a0 + 90 + alpha.
    """
    with mpmath.workdps(40):
        a0 = mpmath.pi if dead_centre == "crank-end" else mpmath.mpf(0)
        a = mpmath.pi * j / n
        h = mpmath.pi / 2
        return float(travel_mp(a0, a0 + a, ratio) + travel_mp(a0 + h, a0 + h + a, ratio) - 4 * a / mpmath.pi)


@pytest.fixture(scope="module")
def finite():
    return get("two-cranks").figure(rod_ratio=5.0, parts=12)


@pytest.fixture(scope="module")
def infinite():
    return get("two-cranks").figure(infinite_rod=True, parts=12)


@pytest.mark.parametrize("ratio", [4.0, 5.0, 2.5])
def test_excess_work_matches_exact_piston_law(ratio):
    fig = get("two-cranks").figure(rod_ratio=ratio, parts=12)
    for j in range(25):
        assert work_excess(fig, j) == pytest.approx(excess_mp(j, 12, ratio), abs=1e-12), j
        assert work_excess(fig, j, infinite=True) == pytest.approx(excess_mp(j, 12, None), abs=1e-12), j


def test_infinite_rod_first_quadrant_is_the_books_formula(infinite):
    for j in range(7):
        a = math.pi * j / 12
        book = 1 + math.sin(a) - math.cos(a) - 4 * a / math.pi  # § 146, infinite rod
        assert work_excess(infinite, j) == pytest.approx(book, abs=1e-12)


def test_equal_speed_every_45_degrees_for_the_infinite_rod_only(infinite, finite):
    assert all(abs(work_excess(infinite, j)) < 1e-12 for j in range(0, 25, 3))
    # § 147: with a finite rod the half turn no longer closes: from B1 (§ 146's rule) 180 degrees is above v1
    lam = mpmath.mpf(1) / 5
    e180 = float(2 * (1 / lam - mpmath.sqrt(1 / lam ** 2 - 1)))  # both pistons gain 2(L - sqrt(L^2 - r^2))
    assert work_excess(finite, 12) == pytest.approx(e180, abs=1e-12)
    assert e180 == pytest.approx(0.2020, abs=1e-4)  # the issue's +0.20 Q r at L/r = 5
    assert work_excess(finite, 24) == pytest.approx(0.0, abs=1e-12)  # a whole turn: 8 r of work either way


def test_quadrants_differ_for_a_finite_rod(finite):
    rises = []
    for q in range(4):
        es = [work_excess(finite, j) for j in range(6 * q, 6 * q + 7)]
        rises.append(max(es) - es[0])
    assert max(rises) - min(rises) > 0.03  # quadrant 1 rises ~0.04 Q r above its start, quadrant 2 not at all


def test_constructed_extremes_carry_kochanskis_error_exactly():
    fig = get("two-cranks").figure(infinite_rod=True, parts=4)
    with mpmath.workdps(40):
        rho = mpmath.sqrt(4 + (3 - mpmath.tan(mpmath.pi / 6)) ** 2)  # Kochanski's segment, r = 1
        a1_k = mpmath.asin(16 / rho ** 2 - 1) / 2
        a1 = mpmath.asin((4 / mpmath.pi) ** 2 - 1) / 2
    m1, m2 = crank_angle(fig, "K.M1"), crank_angle(fig, "K.M2")
    # the construction is Euclidean from Kochanski's segment on: float agreement with his value ...
    assert m1 == pytest.approx(float(a1_k), abs=1e-12)
    assert m2 == pytest.approx(float(mpmath.pi / 2 - a1_k), abs=1e-12)
    # ... and off the exact angle by the rectification's error, as the provenance states
    err = float(abs(a1_k - a1))
    assert 3.5e-5 < err < 4.5e-5
    assert abs(m1 - float(a1)) == pytest.approx(err, rel=1e-6)
    prov = fig.replay.made_by()["K.M1"].provenance
    assert prov.kind == "approximate" and "Kocha" in prov.method
    assert prov.error == pytest.approx(err, rel=1e-9)
    assert math.degrees(m1) == pytest.approx(19.19968, abs=0.003)  # 19°12' in the book
    assert round(math.degrees(m2) * 60) == 70 * 60 + 48


def test_speed_radii_are_the_books_law_magnified(finite):
    g = finite.replay.givens
    gain = g["fluctuation"] * g["magnify"]
    for j in range(24):
        assert speed_radius(finite, j) == pytest.approx(1 + gain * excess_mp(j, 12, 5.0), abs=1e-11)


def test_speeds_with_and_without_the_books_simplification(infinite):
    k = infinite.replay.givens["fluctuation"]
    rows = speeds(infinite)
    for row in rows:
        e = excess_mp(row["index"], 12, None)
        assert row["v_book"] == pytest.approx(1 + k * e, abs=1e-12)
        assert row["v_exact"] == pytest.approx(math.sqrt(1 + 2 * k * e), abs=1e-12)
    # the linear law is symmetric about v1, the exact one falls further than it rises
    lo, hi = min(rows, key=lambda r: r["v_exact"]), max(rows, key=lambda r: r["v_exact"])
    assert (1 - lo["v_exact"]) > (hi["v_exact"] - 1)


def test_replay_with_another_rod_ratio_keeps_the_steps(finite):
    again = get("two-cranks").replay(Protocol.from_json(finite.protocol.to_json()), rod_ratio=4.0)
    for j in (3, 9, 17):
        assert work_excess(again, j) == pytest.approx(excess_mp(j, 12, 4.0), abs=1e-12)


def test_all_checks_pass_and_durer_division_is_reported():
    c = get("two-cranks")
    fig = c.figure(rod_ratio=5.0, parts=18)  # 10 degree steps: Dürer's trisection
    checks = c.checks(fig)
    assert all(ch.ok for ch in checks)
    assert any("durer" in ch.why for ch in checks)


def test_magnification_that_would_invert_a_radius_is_refused():
    with pytest.raises(InvalidParameter, match="speed radius"):
        get("two-cranks").figure(rod_ratio=2.0, magnify=20.0)
    with pytest.raises(InvalidParameter, match="even number"):
        get("two-cranks").figure(parts=9)


# -- the command line ------------------------------------------------------------------


def test_check_json_names_the_extreme_angles(capsys):
    assert main(["check", "two-cranks", "--infinite-rod", "--parts", "8", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    names = {c["name"]: c for c in data["checks"]}
    a1 = names["extreme angle alpha1 (constructed, deg)"]
    a2 = names["extreme angle alpha2 (constructed, deg)"]
    assert a1["expected"] == pytest.approx(19.19968, abs=1e-5) and a2["expected"] == pytest.approx(70.80032, abs=1e-5)
    assert a1["ok"] and a2["ok"] and abs(a1["error"]) > 1e-3  # Kochański's 8 seconds of arc are visible


def test_table_speed_fluctuation_csv(capsys):
    assert main(["table", "speed-fluctuation", "--rod-ratio", "4", "--step", "15", "--format", "csv"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == "crank_angle_deg,work_excess"
    rows = [tuple(map(float, line.split(","))) for line in lines[1:]]
    assert [r[0] for r in rows] == [15.0 * j for j in range(25)]
    for j, (_, e) in enumerate(rows):
        assert e == pytest.approx(excess_mp(j, 12, 4.0), abs=1e-12)


def test_table_infinite_rod(capsys):
    assert main(["table", "speed-fluctuation", "--infinite-rod", "--step", "10", "--format", "csv"]) == 0
    rows = [tuple(map(float, line.split(","))) for line in capsys.readouterr().out.splitlines()[1:]]
    assert len(rows) == 37
    # 10 degree steps come from Dürer's trisection: its error (< 1e-7 rad) times |de/dalpha| <= 2 + 4/pi
    for j, (_, e) in enumerate(rows):
        assert e == pytest.approx(excess_mp(j, 18, None), abs=5e-7)


@pytest.mark.parametrize("argv", [
    ["check", "two-cranks", "--rod-ratio", "4", "--infinite-rod"],
    ["check", "two-cranks", "--parts", "7"],
    ["check", "two-cranks", "--magnify", "nan"],
    ["table", "speed-fluctuation", "--step", "7", "--infinite-rod"],
    ["table", "speed-fluctuation", "--rod-ratio", "4", "--infinite-rod"],
])
def test_bad_input_is_one_line_and_exit_2(argv, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err


def test_historical_plate_reads_like_fig_566():
    fig = get("two-cranks").figure(rod_ratio=5.0, parts=8)
    svg = fig.svg("historical")
    assert svg == get("two-cranks").figure(rod_ratio=5.0, parts=8).svg("historical")  # byte-stable
    for text in ("M₁ 19°12′", "M₂ 70°48′", "B₁", "B₂", "B₃", "B₄", "v₁", "O′ (l = ∞)"):
        assert text in svg, text
    assert "-wave" in svg and "-iwave" in svg        # both wave curves, side by side
    assert "-K-t4" not in svg and "-V3" not in svg   # the plate leaves the construction out
    assert "-K-W1" in svg and "-K-W2" in svg         # the extremes on the wave


def test_speed_without_either_simplification(finite):
    """v_full against the kinetic energy of shaft and both crossheads, piston speeds by mpmath.diff."""
    k, mu = finite.replay.givens["fluctuation"], 0.2
    rows = speeds(finite, crosshead_share=mu)
    with mpmath.workdps(30):
        def share(a):  # (c1/v)^2 + (c2/v)^2 with c = dx/dalpha (r = 1, v = r omega)
            d1 = mpmath.diff(lambda w: position_mp(w, 5.0), a)
            d2 = mpmath.diff(lambda w: position_mp(w, 5.0), a + mpmath.pi / 2)
            return d1 ** 2 + d2 ** 2
        for row in rows[::3]:
            a = mpmath.pi + mpmath.pi * row["index"] / 12     # from B1, the crank-end dead centre
            e = excess_mp(row["index"], 12, 5.0)
            want = mpmath.sqrt(((1 - mu) + mu * share(mpmath.pi) + 2 * k * e) / ((1 - mu) + mu * share(a)))
            assert row["v_full"] == pytest.approx(float(want), abs=1e-11), row["index"]
    plain = speeds(finite)
    assert all(r["v_full"] == pytest.approx(r["v_exact"], abs=1e-15) for r in plain)


def test_the_array_law_equals_the_scalar_law():
    """excess_exact_array (grids, sweeps) is excess_exact with numpy: on both rods, all four quadrants and beyond."""
    from construct.constructions.two_cranks import excess_exact, excess_exact_array

    angles = np.linspace(0.0, 2.5 * math.pi, 301)
    for ratio in (None, 1.05, 2.0, 5.0, 50.0):
        swept = excess_exact_array(angles, ratio)
        assert np.allclose(swept, [excess_exact(a, ratio) for a in angles], rtol=0.0, atol=1e-13), ratio
    ratios = np.array([1.05, 3.0, 40.0])
    grid = excess_exact_array(angles[None, :], ratios[:, None])
    assert np.allclose(grid, [[excess_exact(a, k) for a in angles] for k in ratios], rtol=0.0, atol=1e-13)


@pytest.mark.parametrize("dead_centre", ["crank-end", "head-end"])
def test_excess_from_on_an_array_is_the_scalar_law_to_the_bit(dead_centre):
    """A figure's checks read e at every point of the division in one numpy pass: the same numbers, bit for bit,
    as one scalar call a point (so a check's expected value does not move with the pass)."""
    from construct.constructions.two_cranks import excess_from

    for parts in (2, 12, 60):
        angles = math.pi * np.arange(2 * parts + 1) / parts
        for ratio in (None, 1.05, 4.5, 50.0):
            assert excess_from(angles, ratio, dead_centre).tolist() == \
                [excess_from(math.pi * j / parts, ratio, dead_centre) for j in range(2 * parts + 1)], (parts, ratio)


def test_quadrant_extremes_over_a_sweep_equal_a_dense_scalar_sampling():
    """One numpy pass over many rod ratios gives, ratio by ratio, the scalar answer, and the extremes of the
    law sampled point by point (4,000 points a quadrant) to within the sampling's error."""
    from construct.constructions.two_cranks import excess_exact, quadrant_extremes

    ratios = np.array([1.05, 2.0, 5.0, 50.0])
    swept = quadrant_extremes(ratios)
    for i, ratio in enumerate(ratios):
        single = quadrant_extremes(float(ratio))
        for q_sweep, q in zip(swept, single):
            for key in ("start", "alpha_min", "e_min", "alpha_max", "e_max", "rise", "fall"):
                assert abs(q_sweep[key][i] - q[key]) <= 1e-12, (ratio, q["quadrant"], key)
            a0 = (q["quadrant"] - 1) * 0.5 * math.pi
            vals = [excess_exact(a0 + 0.5 * math.pi * j / 4000, float(ratio)) for j in range(4001)]
            # the refined extremes lie beyond the samples' by at most the sampling error (step^2 |e''| / 8)
            assert -1e-6 <= min(vals) - q["e_min"] <= 1e-6 and -1e-6 <= q["e_max"] - max(vals) <= 1e-6
            assert q["e_min"] <= min(vals) + 1e-12 and q["e_max"] >= max(vals) - 1e-12  # at an end: the end
            assert q["start"] == vals[0] or abs(q["start"] - vals[0]) <= 1e-15


def test_a_sweep_picks_each_ratios_magnification_as_a_single_figure_does():
    """The sweep's magnifications (one numpy pass) are those auto_magnification picks ratio by ratio, the
    fallback below the smallest nice value included."""
    from construct.constructions.two_cranks import auto_magnification

    ratios = np.concatenate([np.geomspace(1.001, 50.0, 40), [1.05, 1.1, 2.0, 5.0]])
    for fluctuation in (0.05, 0.25, 1.0, 5.0):
        swept = auto_magnification(ratios, fluctuation)
        assert swept.tolist() == [auto_magnification(float(k), fluctuation) for k in ratios], fluctuation
    g = dict(get("two-cranks").figure().replay.givens)
    assert get("two-cranks").rod_ratio_sweep(g, ratios)["magnify"].tolist() == \
        [auto_magnification(float(k), g["fluctuation"]) for k in ratios]


def test_the_domain_check_of_a_sweep_names_the_first_set_a_single_check_refuses():
    """_validate on a sweep's givens (one pass) refuses exactly when a set does, with that set's message."""
    from construct.constructions import two_cranks as tc

    g = dict(get("two-cranks").figure().replay.givens)
    ratios = np.geomspace(1.05, 50.0, 40)
    for fluctuation, magnify in ((0.25, None), (1.0, 8.0), (0.5, 3.0), (0.1, 8.0)):
        mags = tc.auto_magnification(ratios, fluctuation) if magnify is None else np.full(ratios.size, magnify)
        swept = {**g, "rod_ratio": ratios, "fluctuation": fluctuation, "magnify": mags}
        first = None
        for i in range(ratios.size):
            try:
                tc.validate_two_cranks({**g, "rod_ratio": float(ratios[i]), "fluctuation": fluctuation, "magnify": float(mags[i])})
            except InvalidParameter as exc:
                first = str(exc)
                break
        if first is None:
            tc.validate_two_cranks(swept)
        else:
            with pytest.raises(InvalidParameter) as info:
                tc.validate_two_cranks(swept)
            assert str(info.value) == first


# -- § 146's sign rule and the other dead centre --------------------------------------------


def test_section_146_sign_rule_first_order():
    """§ 146 to first order in r/l, upper sign in the Hingang: from B1 the first piston has gone
    r(1 − cos α) − r² sin² α/2l; at 180 degrees the second crank (from 90 to 270) has gone
    r(1 + r/2l) + r(1 + r/2l) = 2r + r²/l, the first 2r: e = (4r + r²/l)/r − 4 = r/l = 0.2 at L/r = 5,
    the exact law a little more (0.2020)."""
    fig = get("two-cranks").figure(rod_ratio=5.0, parts=12)
    assert work_excess(fig, 12) == pytest.approx(0.2, abs=0.003)
    assert fig.params["dead_centre"] == "crank-end"


@pytest.mark.parametrize("ratio", [5.0, 2.5])
def test_head_end_option_is_the_other_diagram(ratio):
    fig = get("two-cranks").figure(rod_ratio=ratio, parts=12, dead_centre="head-end")
    for j in range(25):
        assert work_excess(fig, j) == pytest.approx(excess_mp(j, 12, ratio, "head-end"), abs=1e-12), j
    assert work_excess(fig, 12) < -0.1
    assert all(ch.ok for ch in get("two-cranks").checks(fig))


def test_first_quadrant_agrees_in_both_conventions():
    a = get("two-cranks").figure(rod_ratio=5.0, parts=12)
    b = get("two-cranks").figure(rod_ratio=5.0, parts=12, dead_centre="head-end")
    # the rod terms of the two cranks cancel to first order: the difference is third order in r/l
    assert all(abs(work_excess(a, j) - work_excess(b, j)) < 2e-3 for j in range(7))
    assert abs(work_excess(a, 12) - work_excess(b, 12)) > 0.4


def test_caption_names_the_dead_centre():
    from construct.render.notation import givens

    c = get("two-cranks")
    a = c.figure(rod_ratio=5.0, parts=8)
    b = c.figure(rod_ratio=5.0, parts=8, dead_centre="head-end")
    assert "crank-end dead centre B₁ (§ 146" in givens(a, c)[1] and "äußeren Totlage B₁" in givens(a, c)[0]
    assert "head-end dead centre" in givens(b, c)[1]


def test_table_dead_centre_option(capsys):
    assert main(["table", "speed-fluctuation", "--rod-ratio", "5", "--step", "45", "--format", "csv",
                 "--dead-centre", "head-end"]) == 0
    rows = [tuple(map(float, line.split(","))) for line in capsys.readouterr().out.splitlines()[1:]]
    assert rows[4][0] == 180.0 and rows[4][1] == pytest.approx(excess_mp(4, 4, 5.0, "head-end"), abs=1e-12)
    assert main(["table", "speed-fluctuation", "--rod-ratio", "5", "--step", "45", "--dead-centre", "middle"]) == 2


def test_no_view_cuts_a_letter_of_the_stroke_line(tmp_path):
    """At steps 620-624 (crank position 20 of the infinite rod, § 146's start at B1) the player's
    window cut the letter 4′ in half: widening the view took in one piston position's letter per round and
    cut the next along the row 3′…11′, and the widening stopped after six rounds."""
    from construct.regress.lint import lint_path

    out = tmp_path / "r"
    assert main(["replay", "two-cranks", "--parts", "12", "--style", "teaching", "--frames", "none",
                 "--out", str(out)]) == 0
    report = lint_path(out)
    assert [f.line() for f in report.findings if f.kind == "outside"] == []


def test_work_line_steps_are_captioned_in_the_figures_letters():
    """'iU19 im Schnitt von Gerade durch W₀ und dem Kreis um iE18' -- the steps that find U on the
    work line and V on the speed scale named the internal objects; they say U19, V0 as the text does."""
    import re

    fig = get("two-cranks").figure(parts=12)
    for s in fig.protocol.steps:
        if any(re.fullmatch(r"i?[UV]\d+", o) for o in s.outputs):
            for text in (s.caption.de, s.caption.en):
                assert not re.search(r"\bi[A-Z]\w*", text), text


def test_the_work_line_keeps_its_marks_while_the_work_is_stepped_on():
    """At step 620 (crank position 20 of the infinite rod) the work line and the works E1...E19
    stepped on before had faded with their finished groups: the student saw one arc and one point in empty
    paper.  The work line is one stage: it keeps its marks until every crank position is stepped on."""
    from construct.render.output import scene_for

    c = get("two-cranks")
    fig = c.figure(parts=12)
    scene = scene_for(c, fig)
    step = {n: s.index for s in fig.protocol.steps for n in s.outputs}
    k = step["iU20"]
    for name in ["iwork"] + [f"iE{j}" for j in range(1, 20)] + [f"iM{j}" for j in range(1, 20)]:
        assert not scene.faded(step[name], k), name
    # once the stage is done its helpers collapse (the speeds are taken from M and E as inputs)
    assert scene.faded(step["iE19"], len(fig.protocol.steps) + 1)


def e_mp(alpha, ratio, dead_centre="crank-end"):
    """e(α)/(Q r) for a real angle α (mpmath), from the first crank's dead centre: both pistons' travel less 4α/π."""
    a0 = mpmath.pi if dead_centre == "crank-end" else mpmath.mpf(0)
    h = mpmath.pi / 2
    return travel_mp(a0, a0 + alpha, ratio) + travel_mp(a0 + h, a0 + h + alpha, ratio) - 4 * alpha / mpmath.pi


def extremum_mp(guess_deg, ratio):
    """Where e'(α) = 0 near *guess_deg* (degrees), and e there: mpmath's root finder on the derivative."""
    with mpmath.workdps(30):
        a = mpmath.findroot(lambda t: mpmath.diff(lambda u: e_mp(u, ratio), t), mpmath.radians(guess_deg))
        return float(mpmath.degrees(a)), float(e_mp(a, ratio))


def test_the_finite_rods_extremes_over_the_turn_on_the_command_line(capsys):
    """§ 147 at L/r 4.5, from B1: the least e -0.04190 at 19.07°, the greatest +0.26694 at 250.93°."""
    a_min, e_min = extremum_mp(19.0, 4.5)
    a_max, e_max = extremum_mp(251.0, 4.5)
    assert (round(a_min, 2), round(e_min, 5), round(a_max, 2), round(e_max, 5)) == (19.07, -0.0419, 250.93, 0.26694)
    assert main(["table", "speed-extremes", "--rod-ratio", "4.5", "--fluctuation", "0.1", "--format", "json"]) == 0
    turn = json.loads(capsys.readouterr().out)[-1]
    assert turn["range"] == "turn"
    # at a flat extreme a float search finds the angle to about sqrt(eps) rad (1e-6 deg); the value to eps
    assert turn["alpha_min_deg"] == pytest.approx(a_min, abs=1e-4) and turn["e_min"] == pytest.approx(e_min, abs=1e-12)
    assert turn["alpha_max_deg"] == pytest.approx(a_max, abs=1e-4) and turn["e_max"] == pytest.approx(e_max, abs=1e-12)
    assert turn["swing"] == pytest.approx(e_max - e_min, abs=1e-10)          # 0.30884 Q r
    assert turn["delta"] == pytest.approx(0.1 * (e_max - e_min), abs=1e-11)  # k times the swing
    # read off the drawn wave: a French curve through points 10 degrees apart
    assert turn["e_min_drawn"] == pytest.approx(e_min, abs=2e-4) and turn["e_max_drawn"] == pytest.approx(e_max, abs=5e-4)


def test_check_reads_the_finite_rods_extremes_off_the_wave(capsys):
    assert main(["check", "two-cranks", "--rod-ratio", "4.5", "--json"]) == 0
    checks = {c["name"]: c for c in json.loads(capsys.readouterr().out)["checks"]}
    a_min, e_min = extremum_mp(19.0, 4.5)
    low = checks["e_min over the turn, read off the wave (L/r = 4.5, the least speed)"]
    assert low["expected"] == pytest.approx(e_min, abs=1e-10) and low["ok"]
    angle = checks["angle of e_min from the crank-end dead centre (L/r = 4.5, read off the wave, deg)"]
    assert angle["expected"] == pytest.approx(a_min, abs=1e-4) and abs(angle["error"]) < 1.0
    assert checks["swing e_max - e_min over the turn (L/r = 4.5, read off the wave)"]["ok"]


@pytest.mark.parametrize("ratio", [None, 4.5])
def test_the_pump_drive_turns_the_speeds_round(ratio):
    """§ 146: "Bei der Bewegung von Pumpen durch die Kurbelwelle würde das Gegentheil stattfinden": r − g e."""
    rod = {"infinite_rod": True} if ratio is None else {"rod_ratio": ratio}
    pump = get("two-cranks").figure(parts=12, drive="pump", **rod)
    g = pump.replay.givens
    gain = g["magnify"] * g["fluctuation"]
    for j in range(24):
        assert speed_radius(pump, j) == pytest.approx(1 - gain * excess_mp(j, 12, ratio), abs=1e-11), j
    assert all(c.ok for c in pump.checks())
    if ratio is None:   # the greatest speed at alpha1 = 19° 12', the least at alpha2 = 70° 48'
        rp = pump.replay
        w1, w2 = rp["O"].distance(rp["K.W1"]), rp["O"].distance(rp["K.W2"])
        assert w1 > 1.0 > w2
        assert "größte" in next(s.caption.de for s in pump.protocol.steps if "K.M1" in s.outputs)


def test_the_crossheads_first_order_term_as_the_book_writes_it():
    """Seed 002: L1 + L2 + L3 = (m1 + m2)(v² − v1²)/2 + m2 (r/l)(∓ sin α ± cos α) sin 2α v²/2 (first quadrant from
    B1: the upper signs) = Q r e; v_full with the crossheads' exact speeds, from the piston law's derivative."""
    fig = get("two-cranks").figure(rod_ratio=5.0, parts=12, fluctuation=0.1)
    mu, k, lam = 0.2, 0.1, 0.2
    rows = speeds(fig, crosshead_share=mu)
    with mpmath.workdps(30):
        for row in rows[1:6]:   # the first quadrant
            a = mpmath.radians(row["crank_angle_deg"])
            e = e_mp(a, 5.0)
            book = (1 + 2 * k * e) / (1 + mu * lam * (-mpmath.sin(a) + mpmath.cos(a)) * mpmath.sin(2 * a))
            assert row["v_first"] == pytest.approx(float(mpmath.sqrt(book)), abs=1e-10)
            c1 = mpmath.diff(lambda t: position_mp(t, 5.0), mpmath.pi + a)        # crosshead speeds over v
            c2 = mpmath.diff(lambda t: position_mp(t, 5.0), 3 * mpmath.pi / 2 + a)
            full = (1 - mu + mu * 1 + 2 * k * e) / (1 - mu + mu * (c1 ** 2 + c2 ** 2))
            assert row["v_full"] == pytest.approx(float(mpmath.sqrt(full)), abs=1e-10)


def test_table_speed_fluctuation_with_the_speeds(capsys):
    assert main(["table", "speed-fluctuation", "--rod-ratio", "5", "--step", "45", "--fluctuation", "0.1",
                 "--crosshead-share", "0.2", "--drive", "pump", "--format", "csv"]) == 0
    out, err = capsys.readouterr()
    lines = out.splitlines()
    assert lines[0] == "crank_angle_deg,work_excess,v_book,v_exact,v_first,v_full" and "pumps" in err
    angle, e, book = (float(v) for v in lines[3].split(",")[:3])     # 90 degrees... the row at 90
    assert angle == 90.0 and book == pytest.approx(1 - 0.1 * e, abs=1e-12)
