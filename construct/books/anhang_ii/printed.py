"""Seed 000, Anhang II "Darstellung der Massendrücke": every printed number as printed.

The strings are the book's, character for character as the seed text gives
them, with two notational conventions: the raised decimal point the seed
writes as LaTeX ``\\cdot 563`` is kept as ``·563``, and angles are written
``79° 20'``.  Nothing is rounded, padded or "fixed" here; a wrong value stays
wrong (the errata in :mod:`construct.books.errata` say which).

What each number claims to be is stored beside it (:class:`~construct.books.printed.Printed`):
the quantity, the rod ratio ``L/r`` and the crank angle or piston path of its
row.  Units: crank angles in degrees, piston paths as fractions of the stroke
``2r`` ("des Hubes"), pressures for ``F/f = 1``, ``r·tg β`` in units of ``F/f``.

>>> v = table_1()[4]
>>> v.row, v.column, v.text, v.rod_ratio
('0°', 'r/L·cos 2ω (L/r=6)', '0.1666', 6)
>>> len(table_1()), len(table_2()), len(characteristic_points()), len(tangent_values())
(152, 66, 21, 12)
>>> [f.row for f in printed_formulas()][:2]
['b) Tabelle 2 header', 'c) q7']
"""

from __future__ import annotations

from ..printed import Printed, PrintedFormula

__all__ = [
    "SOURCE",
    "ROD_RATIOS",
    "TABLE_1",
    "TABLE_2",
    "table_1",
    "table_2",
    "characteristic_points",
    "tangent_values",
    "all_printed",
    "printed_formulas",
    "TABLE_ORDER",
]

#: The book's name (construct.constructions.phrases.BOOKS: author, title, year): ``construct errata --book anhang-ii``.
SOURCE = "anhang-ii"

#: The three rod ratios L/r every table of the appendix is computed for.
ROD_RATIOS = (4, 5, 6)

#: Table names in the order the appendix prints them (also the errata order).
TABLE_ORDER = ("Tabelle 1", "Tabelle 2", "characteristic points", "tangents", "formula")


# --------------------------------------------------------------------------
# Tabelle 1: "Werthe der Beschleunigungsdrücke bei den einzelnen Lagen der Kurbel"
# columns: cos ω, cos 2ω, (r/L)·cos 2ω for r/L = 1/4, 1/5, 1/6,
#          cos ω + (r/L) cos 2ω for r/L = 1/4, 1/5, 1/6.

TABLE_1_COLUMNS = (
    ("cos ω", "cos_omega", None),
    ("cos 2ω", "cos_2omega", None),
    ("r/L·cos 2ω (L/r=4)", "lam_cos_2omega", 4),
    ("r/L·cos 2ω (L/r=5)", "lam_cos_2omega", 5),
    ("r/L·cos 2ω (L/r=6)", "lam_cos_2omega", 6),
    ("cos ω + r/L·cos 2ω (L/r=4)", "q", 4),
    ("cos ω + r/L·cos 2ω (L/r=5)", "q", 5),
    ("cos ω + r/L·cos 2ω (L/r=6)", "q", 6),
)

TABLE_1: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("0°", ("1", "1", "0.2500", "0.2000", "0.1666", "1.2500", "1.2000", "1.1666")),
    ("10°", ("0.9848", "0.9397", "0.2349", "0.1879", "0.1566", "1.2197", "1.1727", "1.1414")),
    ("20°", ("0.9397", "0.7660", "0.1915", "0.1532", "0.1277", "1.1312", "1.0929", "1.0674")),
    ("30°", ("0.8660", "0.5000", "0.1250", "0.1000", "0.0833", "0.9910", "0.9660", "0.9493")),
    ("40°", ("0.7660", "0.1736", "0.0434", "0.0347", "0.0289", "0.8094", "0.8007", "0.7949")),
    ("50°", ("0.6428", "-0.1736", "-0.0434", "-0.0347", "-0.0289", "0.5994", "0.6081", "0.6139")),
    ("60°", ("0.5000", "-0.5000", "-0.1250", "-0.1000", "-0.0833", "0.3750", "0.4000", "0.4167")),
    ("70°", ("0.3420", "-0.7660", "-0.1915", "-0.1532", "-0.1277", "0.1505", "0.1888", "0.2143")),
    ("80°", ("0.1736", "-0.9397", "-0.2349", "-0.1879", "-0.1566", "-0.0613", "-0.0143", "0.0170")),
    ("90°", ("0", "-1", "-0.2500", "-0.2000", "-0.1666", "-0.2500", "-0.2000", "-0.1666")),
    ("100°", ("-0.1736", "-0.9397", "-0.2349", "-0.1879", "-0.1566", "-0.4085", "-0.3615", "-0.3302")),
    ("110°", ("-0.3420", "-0.7660", "-0.1915", "-0.1532", "-0.1277", "-0.5385", "-0.4952", "-0.4697")),
    ("120°", ("-0.5000", "-0.5000", "-0.1250", "-0.1000", "-0.0833", "-0.6250", "-0.6000", "-0.5833")),
    ("130°", ("-0.6428", "-0.1736", "-0.0434", "-0.0347", "-0.0289", "-0.6862", "-0.6775", "-0.6717")),
    ("140°", ("-0.7660", "0.1736", "0.0434", "0.0347", "0.0289", "-0.7226", "-0.7313", "-0.7371")),
    ("150°", ("-0.8660", "0.5000", "0.1250", "0.1000", "0.0833", "-0.7410", "-0.7660", "-0.7827")),
    ("160°", ("-0.9397", "0.7660", "0.1915", "0.1532", "0.1277", "-0.7482", "-0.7865", "-0.8120")),
    ("170°", ("-0.9848", "0.9397", "0.2349", "0.1879", "0.1566", "-0.7499", "-0.7969", "-0.8282")),
    ("180°", ("-1", "1", "0.2500", "0.2000", "0.1666", "-0.7500", "-0.8000", "-0.8334")),
)

# --------------------------------------------------------------------------
# Tabelle 2: "Werthe der Beschleunigungsdrücke bei den einzelnen Lagen des Kolbens"
# rows: piston path in tenths of the stroke, forward ("Hingang") and, in the
# last column, the same row counted on the return ("Rückgang"); columns: crank
# angle ω and q for r/L = 1/4, 1/5, 1/6.

TABLE_2_COLUMNS = (
    ("ω (L/r=4)", "omega", 4),
    ("ω (L/r=5)", "omega", 5),
    ("ω (L/r=6)", "omega", 6),
    ("q (L/r=4)", "q", 4),
    ("q (L/r=5)", "q", 5),
    ("q (L/r=6)", "q", 6),
)

#: (forward path, six values, return path) per row, as printed.
TABLE_2: tuple[tuple[str, tuple[str, ...], str], ...] = (
    ("0", ("0° 0'", "0° 0'", "0° 0'", "1.2500", "1.2000", "1.1667"), "1.0"),
    ("0.1", ("33° 7'", "33° 48'", "34° 16'", "0.9382", "0.9073", "0.8875"), ".9"),
    ("0.2", ("47° 58'", "48° 55'", "49° 34'", "0.6437", "0.6299", "0.6220"), ".8"),
    ("0.3", ("60° 18'", "61° 28'", "62° 15'", "0.3682", "0.3691", "0.3712"), ".7"),
    ("0.4", ("71° 41'", "73° 0'", "73° 54'", "0.1137", "0.1265", "0.1364"), ".6"),
    ("0.5", ("82° 49'", "84° 15'", "85° 13'", "-0.1172", "-0.0960", "-0.0810"), ".5"),
    ("0.6", ("94° 14'", "95° 45'", "96° 44'", "-0.3210", "-0.2960", "-0.2793"), ".4"),
    ("0.7", ("106° 28'", "107° 59'", "108° 58'", "-0.4932", "-0.4706", "-0.4566"), ".3"),
    ("0.8", ("120° 23'", "121° 49'", "122° 44'", "-0.6279", "-0.6161", "-0.6099"), ".2"),
    ("0.9", ("138° 3'", "139° 13'", "139° 56'", "-0.7172", "-0.7278", "-0.7368"), ".1"),
    ("1.0", ("180° 0'", "180° 0'", "180° 0'", "-0.7500", "-0.8000", "-0.8333"), ".0"),
)

# --------------------------------------------------------------------------
# c) Charakteristische Punkte: per point, per L/r = 4, 5, 6.

#: The crank angles of q6 and q7 are printed to the nearest ten minutes
#: (77°, 79° 20', 80° 50', 65° 30', 69° 30', 72° 20': every minute value a
#: multiple of ten, 77° standing for 77° 0'), so their last printed place is
#: taken as 10' rather than 1'.  Judged per minute they would all look like
#: slips or misprints, which misreads how the book states them.
CHARACTERISTIC_ANGLE_RESOLUTION = "10'"

CHARACTERISTIC_POINTS: tuple[tuple[str, str, str, tuple[str, str, str]], ...] = (
    # (row, column, quantity, printed for L/r = 4, 5, 6)
    ("s5", "s/2r", "s5", ("·563", "·550", "·542")),
    ("q6", "cos ω", "q6_cos", ("·2247", "·18615", "·1583")),
    ("q6", "ω", "q6_omega", ("77°", "79° 20'", "80° 50'")),
    ("q6", "x/2r", "q6_x", ("·4482", "·4558", "·4659")),
    ("q7", "cos ω", "q7_cos", ("·4140", "·3508", "·3028")),
    ("q7", "ω", "q7_omega", ("65° 30'", "69° 30'", "72° 20'")),
    ("q7", "x/2r", "q7_x", ("·3469", "·3689", "·3868")),
)

# --------------------------------------------------------------------------
# d) Tangenten: r·tg β at the dead centres and at ω = 90°, in units of F/f.
# The seed's OCR scrambled this little table: "= 0 mal F/f" (L/r = 4 at 180°)
# sits on the "Es wird für:" line and 1/4 = .25 (L/r = 5) on the L/r = 4 line.
# The assignment below follows the printed formulas (1 ± 4 r/L)/(1 ± r/L):
# at 0° 8/5, 9/6, 10/7; at 180° 0, 1/4, 2/5 for L/r = 4, 5, 6.

TANGENT_VALUES: tuple[tuple[str, int | None, tuple[str, ...]], ...] = (
    # (row ω, L/r or None for "every L/r", printed strings: fraction then decimal)
    ("0°", 4, ("8/5", "1.6")),
    ("0°", 5, ("9/6", "1.5")),
    ("0°", 6, ("10/7", "1.4")),
    ("90°", None, ("F/f",)),
    ("180°", 4, ("0",)),
    ("180°", 5, ("1/4", ".25")),
    ("180°", 6, ("2/5", ".4")),
)

# --------------------------------------------------------------------------
# Printed formulas the errata find fault with, quoted as printed.

PRINTED_FORMULAS = (
    PrintedFormula("formula", "b) Tabelle 2 header", "q", "q/f = cos ω + r/L cos 2ω"),
    PrintedFormula("formula", "c) q7", "cos ω", "cos ω = (-L + √(L² - 16r²)) / 4r"),
    PrintedFormula("formula", "d) ∂y/∂ω", "∂y/∂ω", "∂y/∂ω = F/f [sin ω + 4 r/L sin ω cos ω]"),
    PrintedFormula("formula", "d) Gl. (i)", "tg β", "tg β = ∂y/∂x = F/f (1 + 4 r/L cos ω) / (r (1 + r/L cos ω))"),
    PrintedFormula("formula", "d) Gl. (i₁) 90°", "y", "y = F/f · r/L"),
    PrintedFormula("formula", "d) Gl. (i₁) 180°", "y", "y = F/f (1 - r/L)"),
)


def _degrees(label: str) -> float:
    return float(label.rstrip("°"))


def table_1() -> tuple[Printed, ...]:
    """Tabelle 1 as 19 rows × 8 printed numbers, row by row."""
    out = []
    for row, texts in TABLE_1:
        for (column, quantity, ratio), text in zip(TABLE_1_COLUMNS, texts, strict=True):
            out.append(Printed("Tabelle 1", row, column, text, quantity, rod_ratio=ratio, omega_deg=_degrees(row)))
    return tuple(out)


def table_2() -> tuple[Printed, ...]:
    """Tabelle 2 as 11 rows × 6 printed numbers (the path columns are row labels)."""
    out = []
    for row, texts, _return in TABLE_2:
        for (column, quantity, ratio), text in zip(TABLE_2_COLUMNS, texts, strict=True):
            out.append(Printed("Tabelle 2", row, column, text, quantity, rod_ratio=ratio, stroke_fraction=float(row)))
    return tuple(out)


def characteristic_points() -> tuple[Printed, ...]:
    """The values of section c): s5, and cos ω, ω and x/2r for q6 and q7."""
    out = []
    for row, column, quantity, texts in CHARACTERISTIC_POINTS:
        resolution = CHARACTERISTIC_ANGLE_RESOLUTION if quantity.endswith("_omega") else None
        for ratio, text in zip(ROD_RATIOS, texts, strict=True):
            out.append(
                Printed(
                    "characteristic points",
                    row,
                    f"{column} (L/r={ratio})",
                    text,
                    quantity,
                    rod_ratio=ratio,
                    omega_deg=90.0 if row == "s5" else None,
                    resolution=resolution,
                )
            )
    return tuple(out)


def tangent_values() -> tuple[Printed, ...]:
    """The numbers r·tg β of section d), fractions and decimals, in units of F/f."""
    out = []
    for row, ratio, texts in TANGENT_VALUES:
        suffix = "all L/r" if ratio is None else f"L/r={ratio}"
        for text in texts:
            kind = "r·tg β fraction" if "/" in text and text != "F/f" else "r·tg β"
            out.append(
                Printed("tangents", row, f"{kind} ({suffix})", text, "r_tg_beta", rod_ratio=ratio, omega_deg=_degrees(row))
            )
    return tuple(out)


#: The appendix's printed tables (every number of it stands in one): a trailing 5 one place beyond its column is
#: the author's half (:func:`construct.books.printed.in_halves`).
TABLES = ("Tabelle 1", "Tabelle 2", "characteristic points", "tangents")


def all_printed() -> tuple[Printed, ...]:
    """Every printed number of the appendix, in table, row and column order."""
    return table_1() + table_2() + characteristic_points() + tangent_values()


def printed_formulas() -> tuple[PrintedFormula, ...]:
    """The printed formulas quoted by the errata, in the order of the text."""
    return PRINTED_FORMULAS
