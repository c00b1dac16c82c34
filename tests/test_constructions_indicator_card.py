"""Digitised indicator diagrams (construct.constructions.indicator_card, construct.io.reading) and --indicator.

References: a card whose lines are straight, so the pressures are known in closed form, with the piston path and
the tangential factor evaluated with mpmath; every broken file refused with one line on stderr and exit 2.
"""

import csv
import io
import math
import os

import mpmath
import numpy as np
import pytest

from construct.cli.main import main
from construct.constructions.indicator_card import CLOSE_TOLERANCE, load_indicator, parse_indicator_csv
from construct.io.reading import read_bounded_text
from construct.kernel.errors import InputFileError

MPMATH_DPS = 30  # the digits of the mpmath references: each test runs under mpmath.workdps (conftest.py)

#: Cover side: steam line straight from 8 at at x = 0 to 2 at at x = 1; exhaust at 1 at, straight back.
STRAIGHT = "x,p\n0,8\n0.5,5\n1,2\n1,1\n0.5,1\n0,1\n0,8\n"


def x_mp(w, K):
    w, lam = mpmath.mpf(w), 1 / mpmath.mpf(K)
    return (1 - mpmath.cos(w) + (1 - mpmath.sqrt(1 - (lam * mpmath.sin(w)) ** 2)) / lam) / 2


def t_mp(w, K):
    w = mpmath.mpf(w)
    b = mpmath.asin(mpmath.sin(w) / K)
    return abs(mpmath.sin(w + b) / mpmath.cos(b))


def over_pressure_mp(w, K):
    """Cover 8 - 6x forward, 1 back; crank side mirrored: forward it exhausts at 1, on the return 8 - 6(1 - x)."""
    x = x_mp(w, K)
    if mpmath.sin(w) >= 0:
        return 8 - 6 * x - 1
    return (8 - 6 * (1 - x)) - 1


def write(tmp_path, text, name="card.csv"):
    p = tmp_path / name
    p.write_text(text)
    return str(p)


def table(args, capsys):
    code = main(["table", "tangential-pressure", "--rod-ratio", "5", "--format", "csv", *args])
    out = capsys.readouterr()
    return code, out


def test_forward_stroke_t_against_closed_form(tmp_path, capsys):
    code, out = table(["--parts", "6", "--method", "exact", "--indicator", write(tmp_path, STRAIGHT)], capsys)
    assert code == 0
    assert "mirrored" in out.err and "Baumann" in out.err
    rows = list(csv.DictReader(io.StringIO(out.out)))
    assert list(rows[0]) == ["crank_angle_deg", "OK_over_r", "T_over_P", "T"]
    for row in rows:
        w = math.radians(float(row["crank_angle_deg"]))
        assert float(row["T"]) == pytest.approx(float(over_pressure_mp(w, 5) * t_mp(w, 5)), abs=1e-10)


@pytest.mark.parametrize("data", [
    "\ufeffx;p\r\n0;8\r\n0,5;5\r\n1;2\r\n1;1\r\n0,5;1\r\n0;1\r\n0;8\r\n".encode("utf-8"),  # Excel, German
    "x;p\n0;8,0\n0,5;5,0\n1;2\n1;1\n0,5;1\n0;1\n0;8\n".encode("utf-8"),
    "x\tp\n0\t8\n0,5\t5\n1\t2\n1\t1\n0,5\t1\n0\t1\n0\t8\n".encode("utf-8"),            # tab-separated
], ids=["bom-crlf-semicolon", "semicolon", "tab"])
def test_a_german_spreadsheets_card_reads_as_the_same_card(tmp_path, capsys, data):
    """'x;p' with decimal commas, a byte-order mark, CRLF: the same card as STRAIGHT, the same table."""
    path = tmp_path / "karte.csv"
    path.write_bytes(data)
    german = table(["--parts", "6", "--method", "exact", "--indicator", str(path)], capsys)
    plain = table(["--parts", "6", "--method", "exact", "--indicator", write(tmp_path, STRAIGHT)], capsys)
    assert german[0] == plain[0] == 0 and german[1].out == plain[1].out
    assert load_indicator(str(path)).points == load_indicator(write(tmp_path, STRAIGHT)).points


def test_decimal_commas_without_semicolons_are_explained(tmp_path, capsys):
    code, out = table(["--indicator", write(tmp_path, "x,p\n0,8\n0,5,5\n1,2\n")], capsys)
    assert code == 2 and "decimal commas need ';'" in out.err and out.err.count("\n") == 1
    code, out = table(["--indicator", write(tmp_path, "x p\n0 8\n")], capsys)
    assert code == 2 and "'x;p' with decimal commas" in out.err


def test_revolution_with_cranks_against_closed_form(tmp_path, capsys):
    code, out = table(["--revolution", "--machine", "compound", "--indicator", write(tmp_path, STRAIGHT)], capsys)
    assert code == 0
    rows = list(csv.DictReader(io.StringIO(out.out)))
    assert list(rows[0]) == ["crank_angle_deg", "T_over_P", "T"]
    assert len(rows) == 37
    for row in rows:
        w = mpmath.radians(mpmath.mpf(row["crank_angle_deg"]))
        expected = sum(over_pressure_mp(w + mpmath.radians(t), 5) * t_mp(w + mpmath.radians(t), 5) for t in (0, 90))
        # Dürer's trisection: angles within 4.4e-6 rad; dT/dw <= ~10 at here
        assert float(row["T"]) == pytest.approx(float(expected), abs=1e-4)


def test_crank_side_file(tmp_path, capsys):
    """A crank-side card of its own: 1.5 at throughout its exhaust (forward), the mirrored steam line back."""
    crank = "x,p\n1,8\n0.5,5\n0,2\n0,1.5\n0.5,1.5\n1,1.5\n1,8\n"
    code, out = table(["--parts", "2", "--method", "exact", "--indicator", write(tmp_path, STRAIGHT),
                       "--indicator-crank-side", write(tmp_path, crank, "crank.csv")], capsys)
    assert code == 0 and "own indicator diagram" in out.err
    row = list(csv.DictReader(io.StringIO(out.out)))[1]   # 90 degrees
    x = x_mp(mpmath.pi / 2, 5)
    assert float(row["T"]) == pytest.approx(float(8 - 6 * x - 1.5), abs=1e-12)


BROKEN = [
    ("y,p\n0,1\n", "row 1: the header must be 'x,p'"),
    ("x,p\n0,8\n0.5,five\n1,2\n0,1\n0,8\n", "row 3: p = 'five' is not a number"),
    ("x,p\n0,8\n0.5,5,1\n1,2\n0,1\n0,8\n", "row 3: a row holds two numbers"),
    ("x,p\n0,8\n1.5,5\n1,2\n0,1\n0,8\n", "row 3: x = 1.5 is outside 0 .. 1"),
    ("x,p\n0,8\n0.5,nan\n1,2\n0,1\n0,8\n", "row 3: p = 'nan' is not a finite number"),
    ("x,p\n0,8\n0.5,-1\n1,2\n0,1\n0,8\n", "row 3: p = -1 at is outside"),
    ("x,p\n0,8\n1,2\n0,1\n", "needs at least 4 points, the file has 3"),
    ("x,p\n0,8\n0.5,5\n1,2\n1,1\n0.5,1\n0,1\n", "row 7: the loop is not closed"),
    ("x,p\n0,8\n1,2\n1,1\n0.5,9\n0,1\n0,8\n", "crosses itself"),
    ("x,p\n0,8\n0.5,5\n0.3,4\n1,2\n1,1\n0,1\n0,8\n", "row 4: x = 0.3 turns back on the forward"),
    ("x,p\n0.2,8\n0.5,5\n1,2\n1,1\n0.2,1\n0.2,8\n", "must reach both dead centres"),
    ("x,p\n0,3\n0.5,3\n1,3\n0.2,3\n0,3\n", "encloses nothing"),
    ("", "the header must be 'x,p' (or 'x;p' with decimal commas, as a German spreadsheet exports it), got 'an empty file'"),
]


@pytest.mark.parametrize("text, says", BROKEN)
def test_broken_card_refused_one_line_exit_2(tmp_path, capsys, text, says):
    code, out = table(["--indicator", write(tmp_path, text)], capsys)
    assert code == 2
    assert out.out == ""                       # nothing written
    assert says in out.err
    assert len(out.err.strip().splitlines()) == 1 and "Traceback" not in out.err


def test_broken_card_on_the_revolution_and_the_crank_side(tmp_path, capsys):
    good = write(tmp_path, STRAIGHT)
    bad = write(tmp_path, "x,p\n0,8\n0.5,x\n1,2\n0,1\n0,8\n", "bad.csv")
    for args in (["--revolution", "--indicator", bad], ["--indicator", good, "--indicator-crank-side", bad]):
        code, out = table(args, capsys)
        assert code == 2 and out.out == "" and "bad.csv" in out.err and "row 3" in out.err


def test_closing_tolerance_is_as_stated():
    near = f"x,p\n0,8\n0.5,5\n1,2\n1,1\n0.5,1\n0,1\n0,{8 - 0.9 * CLOSE_TOLERANCE * 7}\n"
    parse_indicator_csv(near, "near")
    far = f"x,p\n0,8\n0.5,5\n1,2\n1,1\n0.5,1\n0,1\n0,{8 - 1.1 * CLOSE_TOLERANCE * 7}\n"
    with pytest.raises(InputFileError, match="not closed"):
        parse_indicator_csv(far, "far")


def test_files_that_are_not_regular_are_refused(tmp_path, capsys):
    fifo = tmp_path / "pipe.csv"
    os.mkfifo(fifo)
    for path, says in ((str(fifo), "not a regular file"), (str(tmp_path), "is a folder"),
                       (str(tmp_path / "none.csv"), "does not exist"), ("/dev/zero", "not a regular file")):
        code, out = table(["--indicator", path], capsys)
        assert code == 2 and out.out == "" and says in out.err


def test_size_bound(tmp_path):
    p = write(tmp_path, "x,p\n" + "0,1\n" * 100)
    with pytest.raises(InputFileError, match="larger than 50 bytes"):
        read_bounded_text(p, 50)
    big = tmp_path / "big.csv"
    big.write_bytes(b"x,p\n" + b"0" * 1_000_001)
    with pytest.raises(InputFileError, match="larger than") as err:
        load_indicator(str(big))
    assert "the most an indicator diagram is read" in str(err.value)   # it said "a indicator diagram"


def test_indicator_only_where_it_applies(tmp_path, capsys):
    assert main(["table", "piston-path", "--rod-ratio", "5", "--indicator", write(tmp_path, STRAIGHT)]) == 2
    assert "--indicator goes with" in capsys.readouterr().err


def test_pressure_on_the_chords():
    """Between digitised points the straightedge: a linear interpolation, checked at a third of a chord."""
    card = parse_indicator_csv("x,p\n0,9\n0.3,6\n1,3\n1,1\n0,1\n0,9\n", "c")
    assert card.pressure(0.1, "forward") == pytest.approx(9 - 3 * (0.1 / 0.3), abs=1e-15)
    assert card.pressure(0.65, "forward") == pytest.approx(6 - 3 * 0.5, abs=1e-15)
    assert card.pressure(0.4, "return") == 1.0


def test_construction_with_a_card_via_check_and_replay(tmp_path, capsys):
    card = write(tmp_path, STRAIGHT)
    assert main(["check", "tangential-pressure", "--indicator", card, "--parts", "6"]) == 0
    assert main(["check", "tangential-pressure", "--indicator", card, "--revolution", "--machine", "compound"]) == 0
    out = tmp_path / "tp"
    assert main(["replay", "tangential-pressure", "--indicator", card, "--revolution", "--frames", "none",
                 "--out", str(out)]) == 0
    capsys.readouterr()
    # the protocol holds the card: it replays and checks without the file
    os.remove(card)
    assert main(["check", "--protocol", str(out / "protocol.json")]) == 0
    # ... and a card edited in the protocol's givens is checked as a file is: x outside 0..1 is named
    assert main(["check", "--protocol", str(out / "protocol.json"), "--given", "card.x1=1.5"]) == 2
    err = capsys.readouterr().err
    assert "x = 1.5 is outside 0 .. 1" in err and len(err.strip().splitlines()) == 1


def test_construction_refuses_a_broken_card_and_writes_nothing(tmp_path, capsys):
    bad = write(tmp_path, "x,p\n0,8\n1,2\n1,1\n0.5,9\n0,1\n0,8\n")
    out = tmp_path / "never"
    assert main(["replay", "tangential-pressure", "--indicator", bad, "--frames", "none", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert "crosses itself" in err and len(err.strip().splitlines()) == 1
    assert not out.exists()


def test_construction_card_ordinates_against_closed_form(tmp_path):
    """The drawn card: P' at each crank position is the straight-line over-pressure at the constructed piston path."""
    from construct.constructions import get
    from construct.constructions.tangential import free_force

    fig = get("tangential-pressure").figure(indicator=write(tmp_path, STRAIGHT), parts=6, method="exact")
    for k in range(1, 6):
        w = mpmath.pi * k / 6
        assert free_force(fig, k) == pytest.approx(float(over_pressure_mp(w, 5)), abs=1e-10)


def test_indicator_diagram_construction_draws_the_card(tmp_path, capsys):
    """Each plotted point at its (x, p); the readings on the ordinates are the chords' (closed form here)."""
    from construct.constructions import get
    from construct.constructions.indicator import abscissa, pressure

    c = get("indicator-diagram")
    fig = c.figure(indicator=write(tmp_path, STRAIGHT), divisions=4)
    assert all(ch.ok for ch in c.checks(fig))
    for k in range(1, 4):
        x = abscissa(fig, f"fE{k}")
        assert x == pytest.approx(k / 4, abs=1e-12)
        assert pressure(fig, f"fE{k}") == pytest.approx(8 - 6 * x, abs=1e-12)      # cover side, forward
        assert pressure(fig, f"rW{k}") == pytest.approx(1.0, abs=1e-12)            # cover side, return
        assert pressure(fig, f"fW{k}") == pytest.approx(1.0, abs=1e-12)            # crank side (mirrored), forward
        assert pressure(fig, f"rE{k}") == pytest.approx(8 - 6 * (1 - x), abs=1e-12)  # crank side, return
    assert main(["replay", "indicator-diagram", "--indicator", write(tmp_path, STRAIGHT), "--frames", "none",
                 "--out", str(tmp_path / "ic")]) == 0
    bad = write(tmp_path, "x,p\n0,8\n0.5,5\n1,2\n1,1\n0.5,1\n0,1\n", "open.csv")
    assert main(["check", "indicator-diagram", "--indicator", bad]) == 2
    assert "not closed" in capsys.readouterr().err


def _dense_card(n: int) -> str:
    """STRAIGHT's loop with n points on each stroke (the same lines, more digitised points)."""
    fwd = [(i / (n - 1), 8 - 6 * i / (n - 1)) for i in range(n)]
    back = [(1 - i / (n - 1), 1.0) for i in range(n)]
    return "x,p\n" + "".join(f"{x!r},{p!r}\n" for x, p in fwd + back + [fwd[0]])


def test_a_card_of_thousands_of_points_costs_no_more_steps(tmp_path):
    """The card is traced in one step per line: 2,500 points a stroke make the figure no longer than 20 (a 5,000-point
    card took 11 s and 290 MB, 11 steps a point); the readings are the same lines' (the straight card's)."""
    from construct.constructions import get

    small, large = (get("indicator-diagram").figure(indicator=write(tmp_path, _dense_card(n), f"c{n}.csv"))
                    for n in (20, 2500))
    assert len(large.protocol.steps) == len(small.protocol.steps)
    assert all(c.ok for c in large.checks())
    code = main(["table", "tangential-pressure", "--rod-ratio", "5", "--parts", "6", "--method", "exact",
                 "--indicator", write(tmp_path, _dense_card(2500), "big.csv"), "--format", "csv"])
    assert code == 0


def test_a_traced_card_replays_in_a_sweep_as_set_by_set(tmp_path):
    """The trace runs on arrays like every op of the table: a tangential-pressure figure from a card, replayed over
    three rod ratios at once, reads in each set what the figure made at that ratio alone reads."""
    from construct.constructions import get

    c = get("tangential-pressure")
    card = write(tmp_path, STRAIGHT)
    fig = c.figure(indicator=card, parts=6, method="exact")
    ratios = [4.0, 5.0, 6.0]
    sweep = fig.protocol.replay({**fig.replay.givens, "rod_ratio": np.asarray(ratios)})
    assert not sweep.elementwise  # no op ran once per set
    for i, ratio in enumerate(ratios):
        alone = c.figure(indicator=card, parts=6, method="exact", rod_ratio=ratio)
        ours, theirs = sweep.take(i), alone.replay
        traced = [name for step in alone.protocol.steps if step.op in ("trace", "vertex") for name in step.outputs]
        assert len(traced) >= 2
        for name in traced:
            a, b = ours[name], theirs[name]
            pa, pb = (getattr(a, "points", [a]), getattr(b, "points", [b]))
            assert len(pa) == len(pb) > 0
            assert all(math.isclose(float(u.x), v.x, abs_tol=1e-12) and math.isclose(float(u.y), v.y, abs_tol=1e-12)
                       for u, v in zip(pa, pb)), name
        assert [ch.measured for ch in c.checks(type(alone)(alone.protocol, ours))] == pytest.approx(
            [ch.measured for ch in alone.checks()], rel=1e-9, abs=1e-12)


def test_a_trace_that_would_differ_in_length_between_sets_is_refused():
    """A card whose first point reaches the dead centre in one set of a sweep and not in another would be a chain of
    another length per set: the trace names the sets instead of drawing one wrong."""
    from construct.kernel.curve_ops import trace_op
    from construct.kernel.errors import GeometryError
    from construct.kernel.geometry import ArrayMath, Point

    head, crank = Point(np.zeros(2), np.zeros(2)), Point(np.ones(2), np.zeros(2))
    givens = {"x0": np.array([0.0, 0.1]), "x1": 1.0, "p0": 2.0, "p1": 1.0, "s": 1.0, "u": 1.0}
    params = {"xs": ["x0", "x1"], "ps": ["p0", "p1"], "stroke": ["s"], "pressure": ["u"], "extend": True}
    with pytest.raises(GeometryError, match="1 of 2 sets"):
        trace_op((head, crank, head, crank), params, givens, {}, ArrayMath(2))
    givens["x0"] = np.array([0.1, 0.2])  # short of the head end in both: extended in both, values set by set
    (chain,) = trace_op((head, crank, head, crank), params, givens, {}, ArrayMath(2))
    assert len(chain.points) == 3 and np.allclose(chain.points[1].x, [0.1, 0.2])
