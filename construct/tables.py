"""The books' tables, regenerated from constructions for any rod ratio.

Each table is a function returning ``(columns, rows)``; every number in it is
measured on a construction, with the analytic value beside it where the
table has a column for it.

>>> cols, rows = piston_path_table(rod_ratio=4.0, parts=2)
>>> cols
('index', 'crank_angle_deg', 'crank_angle_constructed_deg', 'x_constructed', 'x_exact', 'x_book')
>>> [round(r["x_constructed"], 9) for r in rows]
[0.0, 0.563508327, 1.0]
"""

from __future__ import annotations

import io
import math
from pathlib import Path
from typing import Any, Mapping, Sequence

from .constructions import analytic
from .constructions import get
from .constructions.crank import crank_angle, piston_fraction, point_name
from .constructions.inertia import acceleration_rows, characteristic_point_rows, q_at_crank_angle_rows
from .constructions.two_cranks import speed_extremes_rows, speed_fluctuation_rows
from .kernel.errors import InvalidParameter
from .render.plotting import TablePlot, plot_table

__all__ = ["TABLES", "PLOTS", "write_plot", "piston_path_table", "crank_angle_table", "acceleration_table",
           "characteristic_points_table", "indicator_note"]

Table = tuple[tuple[str, ...], list[dict[str, Any]]]


def nominal_angle(measured_deg: float, parts: int) -> float:
    """The division angle a row stands for: the constructed crank angle (Dürer's trisection or the dividers
    leave it 2e-6 degrees off) rounded to the nearest multiple of 180/parts, as the books key their tables.

    >>> nominal_angle(9.99999803554437, 18), nominal_angle(20.0000019644556, 18), nominal_angle(51.4285714, 7)
    (10.0, 20.0, 51.42857142857143)
    """
    return 180.0 * round(measured_deg * parts / 180.0) / parts


def piston_path_table(*, rod_ratio: float, parts: int = 18, method: str = "auto", r: float = 1.0) -> Table:
    """Piston path at each division point, constructed, exact and by the book's Gl. (1) (fraction of the stroke).

    ``crank_angle_deg`` is the division's angle 180°·k/parts, the key; ``crank_angle_constructed_deg`` the
    angle the division drew (Dürer's trisection or the dividers: a few millionths of a degree off), at which
    ``x_constructed`` is measured.
    """
    fig = get("crank").figure(rod_ratio=rod_ratio, parts=parts, method=method, r=r)
    g = fig.replay.givens
    L = g["rod_ratio"] * g["r"]
    rows = []
    for k in range(parts + 1):
        w = math.pi * k / parts
        rows.append({
            "index": k,
            "crank_angle_deg": 180.0 * k / parts,
            "crank_angle_constructed_deg": math.degrees(crank_angle(fig, point_name(fig, k))),
            "x_constructed": piston_fraction(fig, k),
            "x_exact": analytic.piston_path_exact(w, g["r"], L) / (2 * g["r"]),
            "x_book": analytic.piston_path_book(w, g["r"], L) / (2 * g["r"]),
        })
    return ("index", "crank_angle_deg", "crank_angle_constructed_deg", "x_constructed", "x_exact", "x_book"), rows


def crank_angle_table(*, rod_ratio: float, divisions: int = 10, r: float = 1.0) -> Table:
    """Tabelle 2's angle columns: the crank angle for each division of the stroke, constructed and by Gl. (h)."""
    fig = get("crank-angle").figure(rod_ratio=rod_ratio, divisions=divisions, r=r)
    g = fig.replay.givens
    L = g["rod_ratio"] * g["r"]
    rows = []
    for j in range(divisions + 1):
        x = j / divisions
        rows.append({
            "x": x,
            "omega_constructed_deg": math.degrees(crank_angle(fig, f"W{j}")),
            "omega_exact_deg": math.degrees(analytic.crank_angle_from_path(2 * g["r"] * x, g["r"], L)),
        })
    for row, extra in zip(rows, q_at_crank_angle_rows(rod_ratio=rod_ratio, divisions=divisions)):
        row["q"] = extra["q"]
    return ("x", "omega_constructed_deg", "omega_exact_deg", "q"), rows


def acceleration_table(*, rod_ratios: Sequence[float], step: float = 10.0) -> Table:
    """Tabelle 1 for any rod ratios, long format (q for F/f = 1)."""
    rows = []
    for k in rod_ratios:
        rows.extend(acceleration_rows(rod_ratio=k, step_deg=step))
    return ("rod_ratio", "omega_deg", "cos_omega", "cos_2omega", "lambda_cos_2omega", "q"), rows


def characteristic_points_table(*, rod_ratio: float) -> Table:
    """The seven characteristic points q1..q7 of the inertia curve, measured on the construction."""
    return ("point", "omega_deg", "x", "q"), characteristic_point_rows(rod_ratio=rod_ratio)


def mass_forces_table(*, weight: float, rpm: float, crank_radius: float, rod_length: float, parts: int = 18,
                      revolution: bool = False) -> Table:
    """Seed 001, eq. (298): P_b (kg, + where the masses are accelerated) at each crank position, measured.

    With *revolution*: both strokes over 0..360 degrees, a column ``stroke`` (forward, return); P_b positive
    where the masses take up force in the direction of the current stroke; the dead-centre rows once per stroke.
    """
    from .constructions.piston_force import mass_force_rows, revolution_mass_force_rows

    if revolution:
        return ("crank_angle_deg", "stroke", "x", "P_b"), _keyed(revolution_mass_force_rows(
            weight=weight, rpm=rpm, crank_radius=crank_radius, rod_length=rod_length, parts=parts), parts)
    return ("crank_angle_deg", "x", "P_b"), _keyed(mass_force_rows(
        weight=weight, rpm=rpm, crank_radius=crank_radius, rod_length=rod_length, parts=parts), parts)


def _keyed(rows: list[dict[str, Any]], parts: int) -> list[dict[str, Any]]:
    """The rows with ``crank_angle_deg`` the division angle they stand for (:func:`nominal_angle`)."""
    for row in rows:
        row["crank_angle_deg"] = nominal_angle(row["crank_angle_deg"], parts)
    return rows


def tangential_pressure_table(*, rod_ratio: float, parts: int = 18, method: str = "auto", revolution: bool = False,
                              cranks: str = "", machine: str = "single", indicator: Any = None,
                              indicator_crank_side: Any = None, force: str = "unit", kappa: Any = None,
                              indicator_lp: Any = None, indicator_lp_crank_side: Any = None, area_ratio: Any = None,
                              piston_area: Any = None) -> Table:
    """T/P' for a unit piston force at each crank position: OK/r measured on the construction (seed 004, Fig. 26).

    With *revolution*: over 0..360 degrees, a unit force in the direction of motion on each stroke, summed over
    the cranks set *cranks* degrees ahead of the first (and the cylinders of a tandem *machine*).

    With *indicator* (a digitised diagram of the cover side, :mod:`construct.constructions.indicator_card`; the
    crank side from *indicator_crank_side* or the same card mirrored): a column ``T`` in kg/cm² of piston area,
    measured on the construction drawn with the card (the over-pressure read on the card's straightedge lines
    at the constructed piston position, times OK/r) -- every cylinder of the engine with this diagram.

    With *force* ``"baumann"``: the column ``T`` (at) from Baumann's idealised diagram less the acceleration
    force (his κ = *kappa*, default 8), on the return stroke the same diagram mirrored (his assumption).

    A compound or tandem engine's low-pressure cylinder has its own diagram: *indicator_lp* (and
    *indicator_lp_crank_side*) with cards, its own idealised diagram under Baumann's force; its piston is
    *area_ratio* times the first's, so its pressures count that many times in ``T`` (at of the high-pressure
    piston's area).  With *piston_area* (the high-pressure piston's, cm²) a column ``T_kg``: the summed
    tangential force in kg, each cylinder's pressure times its own piston area.
    """
    from .constructions.tangential import ok_over_r, t_over_unit

    if indicator is None and indicator_crank_side is not None:
        raise InvalidParameter("--indicator-crank-side goes with --indicator (the cover side's diagram)")
    tp = get("tangential-pressure")
    engine = {"revolution": True, "cranks": cranks, "machine": machine} if revolution else \
        {"cranks": cranks, "machine": machine}
    card = None
    if force not in ("unit", "baumann"):
        raise InvalidParameter(f"--force must be unit or baumann, got {force!r}")
    if force == "unit" and kappa is not None:
        raise InvalidParameter("--kappa belongs to Baumann's force: add --force baumann")
    low = {} if area_ratio is None else {"area_ratio": area_ratio}
    if (area_ratio is not None or indicator_lp is not None) and not (revolution and machine in ("compound", "tandem")):
        raise InvalidParameter("--area-ratio and --indicator-lp belong to a compound or tandem engine's low-pressure "
                               "cylinder: add --revolution --machine compound (or tandem)")
    if area_ratio is not None and not (force == "baumann" or indicator_lp is not None):
        raise InvalidParameter("--area-ratio goes with the low-pressure cylinder's own diagram: --indicator-lp "
                               "FILE.csv, or --force baumann with --machine compound or tandem")
    if force == "baumann":
        if indicator is not None:
            raise InvalidParameter("--indicator gives the pressures itself: leave out --force baumann")
        card = tp.figure(rod_ratio=rod_ratio, parts=parts, method=method, force="baumann",
                         **({} if kappa is None else {"kappa": kappa}), **engine, **low)
    if indicator is not None:
        card = tp.figure(rod_ratio=rod_ratio, parts=parts, method=method, indicator=str(indicator),
                         indicator_crank_side=str(indicator_crank_side or ""),
                         indicator_lp=str(indicator_lp or ""), indicator_lp_crank_side=str(indicator_lp_crank_side or ""),
                         **engine, **low)
    elif indicator_lp is not None or indicator_lp_crank_side is not None:
        raise InvalidParameter("--indicator-lp goes with --indicator (the high-pressure cylinder's diagram)")
    if piston_area is not None:
        from .constructions.domain import PISTON_AREA

        piston_area = PISTON_AREA.check("--piston-area (the first cylinder's piston area, cm²)", piston_area)
        if card is None:
            raise InvalidParameter("--piston-area turns T (at) into kg: give the pressures (--indicator FILE.csv "
                                   "or --force baumann)")
    fig = tp.figure(rod_ratio=rod_ratio, parts=parts, method=method, force="unit", **engine)
    if revolution:
        from .constructions.revolution import revolution_ordinate, revolution_rows

        rows = _keyed(revolution_rows(fig), parts)
        if card is None:
            return ("crank_angle_deg", "T_over_P"), rows
        for j, row in enumerate(rows):
            row["T"] = revolution_ordinate(card, j)
            if piston_area is not None:
                row["T_kg"] = row["T"] * piston_area
        return ("crank_angle_deg", "T_over_P", "T") + (("T_kg",) if piston_area is not None else ()), rows
    rows = [{"crank_angle_deg": 180.0 * k / parts, "OK_over_r": ok_over_r(fig, k), "T_over_P": t_over_unit(fig, k)}
            for k in range(parts + 1)]
    if card is None:
        return ("crank_angle_deg", "OK_over_r", "T_over_P"), rows
    for k, row in enumerate(rows):
        row["T"] = t_over_unit(card, k)
        if piston_area is not None:
            row["T_kg"] = row["T"] * piston_area
    return ("crank_angle_deg", "OK_over_r", "T_over_P", "T") + (("T_kg",) if piston_area is not None else ()), rows


def indicator_note(crank_side: Any) -> str:
    """What a table computed from a card says about the crank side."""
    if crank_side is not None:
        return "crank side from its own indicator diagram"
    return ("crank side: the cover-side diagram mirrored (Baumann's assumption: the diagrams of both piston sides "
            "are equal)")


def flywheel_coefficients_table(*, kz: Sequence[float] | None = None, v: Sequence[float] | None = None) -> Table:
    """Baumann's two flywheel tables (seed 004) for his paired kz and v, or the ones given."""
    from .constructions import bounded
    from .constructions.domain import FLYWHEEL_KZ, RIM_SPEED
    from .books.baumann.flywheel import coefficient_rows

    for value in kz or ():
        bounded("kz", value, FLYWHEEL_KZ)
    for value in v or ():
        bounded("v", value, RIM_SPEED)
    return ("kz", "v", "arms_hub", "total_weight", "moment", "weight_for_moment"), coefficient_rows(kz, v)


def speed_fluctuation_table(*, rod_ratio: float | None, step: float = 10.0, dead_centre: str = "crank-end",
                            drive: str = "engine", fluctuation: float | None = None,
                            crosshead_share: float | None = None) -> Table:
    """Seed 002 § 146-147: the excess work of two cranks at 90 deg over a turn (units of Q r), from the construction.

    The angle counts from § 146's B1, the crank-end dead centre, unless *dead_centre* is "head-end".  With
    *fluctuation* k = Qr/((m1 + m2)v1²): the speeds v/v1 beside it -- ``v_book`` (1 + k e, § 146's law for
    great masses), ``v_exact`` (its energy balance), ``v_first`` (with the crossheads' term of first order in
    r/l the book derives and drops, their share m2/(m1 + m2) *crosshead_share*) and ``v_full`` (the exact
    piston speeds); *drive* "pump": the shaft drives the rods, e counts against the masses.
    """
    rows = speed_fluctuation_rows(rod_ratio=rod_ratio, step_deg=step, dead_centre=dead_centre, drive=drive,
                                  fluctuation=fluctuation, crosshead_share=crosshead_share)
    if fluctuation is None:
        return ("crank_angle_deg", "work_excess"), rows
    return ("crank_angle_deg", "work_excess", "v_book", "v_exact", "v_first", "v_full"), rows


def speed_extremes_table(*, rod_ratio: float | None, parts: int = 12, dead_centre: str = "crank-end",
                         drive: str = "engine", fluctuation: float | None = None) -> Table:
    """§ 147: the least and greatest e in each quadrant and over the turn, by the exact law and read off the
    construction's drawn wave; with *fluctuation* the degree of irregularity k·(e_max − e_min)."""
    cols = ("range", "alpha_min_deg", "e_min", "e_min_drawn", "alpha_max_deg", "e_max", "e_max_drawn", "swing")
    rows = speed_extremes_rows(rod_ratio=rod_ratio, parts=parts, dead_centre=dead_centre, drive=drive,
                               fluctuation=fluctuation)
    return cols + (("delta",) if fluctuation is not None else ()), rows


#: How the books draw each table (construct table NAME --plot FILE); axis texts German / English.
PLOTS = {
    "piston-path": TablePlot(
        "crank_angle_deg", (("x_constructed", "konstruiert / constructed"), ("x_exact", "x = r(1 − cos ω) + …"),
                            ("x_book", "Näherung / book's approximation")),
        "Kurbelwinkel ω / crank angle ω (°)", "Kolbenweg x / piston path x (r)", "Kolbenwege / piston paths"),
    "crank-angle": TablePlot(
        "x", (("omega_constructed_deg", "konstruiert / constructed"), ("omega_exact_deg", "Gl. (h)")),
        "Kolbenweg x / piston path x (Hub / stroke)", "Kurbelwinkel ω / crank angle ω (°)",
        "Kurbelwinkel aus den Zehnteln des Hubes / crank angles from tenths of the stroke"),
    "acceleration": TablePlot(
        "omega_deg", (("q", "q = cos ω + λ cos 2ω"),), "Kurbelwinkel ω / crank angle ω (°)",
        "Massendruck q / inertia pressure q (Pm)", "Beschleunigungsdrücke / acceleration pressures",
        label_by="rod_ratio", label_name="L/r"),
    "characteristic-points": TablePlot(
        "x", (("q", "q₁ … q₇"),), "Kolbenweg x / piston path x (Hub / stroke)",
        "Massendruck q / inertia pressure q (Pm)", "Kennzeichnende Punkte / characteristic points",
        points_only=True),
    "mass-forces": TablePlot(
        "x", (("P_b", "P_b, Gl. (298)"),), "Kolbenweg x / piston path x (Hub / stroke)",
        "Massenkraft P_b / mass force P_b (kg)", "Massenkräfte / mass forces"),
    "tangential-pressure": TablePlot(
        "crank_angle_deg", (("T_over_P", "T/P"),), "Kurbelwinkel ω / crank angle ω (°)",
        "Tangentialdruck T/P / tangential pressure T/P", "Tangentialdruckdiagramm / tangential-pressure diagram",
        mean_of="T_over_P"),
    "flywheel-coefficients": TablePlot(
        "v", (("total_weight", "Gesamtgewicht / total weight ÷ G_s"), ("moment", "Moment G·D² ÷ G_s·D_s²")),
        "Kranzgeschwindigkeit v / rim speed v (m/s)", "Beiwert / coefficient",
        "Schwungradbeiwerte (Baumann) / flywheel coefficients (Baumann)", points_only=True),
    "speed-fluctuation": TablePlot(
        "crank_angle_deg", (("work_excess", "e(α)"),), "Kurbelwinkel α / crank angle α (°)",
        "Überschußarbeit e / excess work e (Q·r)", "Zwei Kurbeln unter 90° / two cranks at 90°"),
    "speed-extremes": TablePlot(
        "alpha_min_deg", (("e_min", "e_min"), ("e_min_drawn", "e_min, Wellenlinie / wave")),
        "Kurbelwinkel α / crank angle α (°)", "Überschußarbeit e / excess work e (Q·r)",
        "Kleinste Werte von e / least e", points_only=True),
}

TABLES = {
    "piston-path": piston_path_table,
    "crank-angle": crank_angle_table,
    "acceleration": acceleration_table,
    "characteristic-points": characteristic_points_table,
    "mass-forces": mass_forces_table,
    "tangential-pressure": tangential_pressure_table,
    "flywheel-coefficients": flywheel_coefficients_table,
    "speed-fluctuation": speed_fluctuation_table,
    "speed-extremes": speed_extremes_table,
}


#: The files ``--plot`` writes, by suffix (matplotlib picks its writer by the suffix).
PLOT_SUFFIXES = (".png", ".pdf", ".svg")


def write_plot(name: str, columns: Sequence[str], rows: Sequence[Mapping[str, Any]], path: Any) -> Path:
    """Plot table *name* as the book draws it into *path* (png, pdf or svg by its suffix), written whole or not.

    >>> import tempfile, pathlib
    >>> cols, rows = speed_fluctuation_table(rod_ratio=None, step=15.0)
    >>> out = write_plot("speed-fluctuation", cols, rows, pathlib.Path(tempfile.mkdtemp()) / "e.svg")
    >>> out.read_text().startswith("<?xml")
    True
    """
    from matplotlib.figure import Figure

    from .io.staging import write_bytes

    target = Path(path)
    if target.suffix.lower() not in PLOT_SUFFIXES:
        raise InvalidParameter(f"--plot writes {', '.join(PLOT_SUFFIXES)} (by the file's suffix), got {str(path)!r}")
    fig = Figure(figsize=(7.5, 4.8))
    plot_table(PLOTS[name], columns, rows, fig.add_subplot())
    fig.tight_layout()
    buf = io.BytesIO()
    # no date or software version in the file: the same table gives the same bytes
    meta = {"svg": {"Date": None}, "pdf": {"CreationDate": None, "Producer": None},
            "png": {"Software": None}}[target.suffix.lower()[1:]]
    fig.savefig(buf, format=target.suffix.lower()[1:], metadata=meta)
    write_bytes(target, buf.getvalue())
    return target
