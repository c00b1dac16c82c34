"""Seed 004, Baumann (1902), "Ein neues Verfahren zur Bestimmung der Schwungradgewichte": printed numbers as printed.

The strings are the book's, with its decimal comma, character for character
as the seed text gives them (angles written ``33° 15'``); a sign the book
leaves out stays left out.  Nothing is corrected here; the errata
(:mod:`construct.books.baumann.errata`) say which are wrong.

Each :class:`~construct.books.printed.Printed` names where it stands (``table``: the section or
table, ``row``, ``column``) and ``quantity``, what it claims to be (the
errata compute that quantity).  ``resolution`` overrides the last printed
place where the book rounds to a coarser step (totals "to 50 kg").

>>> len(all_printed()) > 100, all_printed()[0].text
(True, '0,805')
>>> [f.row for f in printed_formulas()][:1]
['df_x']
"""

from __future__ import annotations

from ..printed import Printed, PrintedFormula, in_halves

__all__ = ["SOURCE", "all_printed", "printed_formulas", "TABLE_KZ", "TABLE_V",
           "TABLE_1_G2", "TABLE_1_TOTAL", "TABLE_2_MOMENT", "TABLE_2_WEIGHT", "WORKED_V", "WORKED_TOTALS",
           "WORKED_RIMS", "FORMULA_ROWS", "FORMULA_TOTALS", "FORMULA_RIMS", "MACHINE_COLUMNS"]

#: The book's name (construct.constructions.phrases.BOOKS: author, title, year): ``construct errata --book baumann``.
SOURCE = "baumann"


# -- "Bestimmung des Fehlers": the error area f_x --------------------------------------

_ERROR = (
    ("case p = 9,85", "k = 7,85/9,85", "0,805", "k1"),
    ("case p = 9,85", "f_x", "-0,01776", "fx1"),
    ("case p = 9,85", "f_x in mm²", "17,76", "fx1_mm2"),
    ("case p = 9,85", "2685/0,805", "3360", "area1_assumed"),
    ("case p = 9,85", "actual area", "3342,24", "area1_actual"),
    ("case p = 4,85", "k = 7,85/4,85", "1,515", "k2"),
    ("case p = 4,85", "ε", "2,33", "eps2"),
    ("case p = 4,85", "f_x", "0,0167", "fx2"),
    ("case p = 4,85", "f_x in mm²", "16,7", "fx2_mm2"),
    ("case p = 4,85", "actual area", "3891,7", "area2_actual"),
)

# -- the tangential-diagram error: integral coefficients, angles, corrected areas ---------

_TANGENTIAL = (
    ("integral (s1 = 10 %, s0 = 5 %)", "A", "-0,0875", "coef_A"),
    ("integral (s1 = 10 %, s0 = 5 %)", "root", "11,08", "root_minus"),
    ("integral (s1 = 10 %, s0 = 5 %)", "B", "0,2995", "coef_B"),
    ("integral (s1 = 10 %, s0 = 5 %)", "root", "1,08", "root_plus"),
    ("integral (s1 = 10 %, s0 = 5 %)", "C", "4,89", "coef_C"),
    ("integral (s1 = 10 %, s0 = 5 %)", "D", "0,2445", "coef_D"),
    ("integral (s1 = 10 %, s0 = 5 %)", "α_f (10 % filling)", "33° 15'", "alpha_f"),
    ("integral (s1 = 10 %, s0 = 5 %)", "f from α_f to π (mm·at)", "-1,778", "f_full"),
    ("integral (s1 = 10 %, s0 = 5 %)", "f from α_f to π (mm²)", "-17,78", "f_full_mm2"),
    ("angles", "α_c (30 % compression)", "107° 50'", "alpha_c"),
    ("angles κ = 8", "α1", "10° 20'", "alpha1_k8"),
    ("angles κ = 8", "cos α1", "0,98", "cos_alpha1_k8"),
    ("angles κ = 8", "α2", "99° 10'", "alpha2_k8"),
    ("angles κ = 8", "cos α2", "0,159", "cos_alpha2_k8"),
    ("angles κ = 2", "α1", "20° 30'", "alpha1_k2"),
    ("angles κ = 2", "cos α1", "0,94", "cos_alpha1_k2"),
    ("angles κ = 2", "α2", "149°", "alpha2_k2"),
    ("angles κ = 2", "cos α2", "0,86", "cos_alpha2_k2"),
    ("correction κ = 8", "C in the bracket", "4,98", "coef_C"),
    ("correction κ = 8", "r∫f1 from α_f to α2", "8,06", "f_k8"),
    ("correction κ = 8", "α2 (rad)", "1,73", "alpha2_k8_rad"),
    ("correction κ = 8", "α1 (rad)", "0,175", "alpha1_k8_rad"),
    ("correction κ = 8", "(α2 − α1) f_x/π", "-8,79", "shift_k8"),
    ("correction κ = 8", "f_x'", "0,73", "fxc_k8"),
    ("correction κ = 2", "C in the bracket", "4,98", "coef_C"),
    ("correction κ = 2", "r∫f1 from α_f to α2", "-17,40", "f_k2"),
    ("correction κ = 2", "α2 (rad)", "2,6005", "alpha2_k2_rad"),
    ("correction κ = 2", "(α2 − α1) f_x/π", "13,7", "shift_k2"),
    ("correction κ = 2", "f_x'", "3,7", "fxc_k2"),
    ("correction κ = 2", "F_u corrected (F_u = 659)", "662,7", "fu_k2"),
)

# -- the flywheel: disc, hub, coefficients --------------------------------------------

_FLYWHEEL = (
    ("arms and hub", "ln 6", "1,79", "ln6"),
    ("arms and hub", "r0/r1", "0,4655", "centroid"),
    ("arms and hub", "G2'/(π r1² b1 γ)", "1,7", "disc"),
    ("arms and hub", "G2''/(π r1² b1 γ)", "0,5", "hub"),
    ("arms and hub", "G2/(π r1² b1 γ)", "2,2", "arms_factor"),
    ("arms and hub", "G2 (kz in kg/m²)", "807,5", "arms_m2"),
    ("arms and hub", "G2 (kz in kg/cm²)", "0,08075", "arms_cm2"),
    ("moment", "G2' coefficient", "0,0625", "disc_coeff"),
    ("moment", "G2'' coefficient", "0,01825", "hub_coeff"),
    ("moment", "1 + m v²/kz", "0,0218", "moment"),
    ("moment", "total, first order", "0,059", "total_first_order"),
)

#: His two tables: kz and v as printed (the column heads), then the rows.
TABLE_KZ = ("75", "85", "95", "100", "105", "110", "115", "120", "125", "130", "135", "140", "145", "150")
TABLE_V = ("15", "17", "19", "20", "21", "22", "23", "24", "25", "26", "27", "28", "29", "30")
TABLE_V2 = ("225", "289", "361", "400", "441", "484", "529", "576", "625", "676", "729", "784", "841", "900")
TABLE_1_G2 = ("0,2425", "0,274", "0,307", "0,323", "0,339", "0,356", "0,371", "0,388", "0,405", "0,420", "0,435",
              "0,4525", "0,468", "0,485")
TABLE_1_TOTAL = ("1,2425", "1,274", "1,307", "1,323", "1,339", "1,356", "1,371", "1,388", "1,405", "1,420", "1,435",
                 "1,4525", "1,468", "1,485")
TABLE_2_MOMENT = ("1,0655", "1,074", "1,083", "1,087", "1,0915", "1,096", "1,1", "1,105", "1,109", "1,113", "1,118",
                  "1,122", "1,126", "1,131")
TABLE_2_WEIGHT = ("1,18", "1,204", "1,228", "1,24", "1,252", "1,264", "1,276", "1,288", "1,30", "1,312", "1,324",
                  "1,336", "1,348", "1,36")

#: The worked cases: (G_s, D_s, n) as given, v as printed; "Richtige Werte" totals, rims (arms and hub).
WORKED_V = ("20,1", "16,95", "24,75", "17,65", "24,75", "17,65")
WORKED_TOTALS = ("2650", "13750", "22700", "23100", "116800", "14000")
WORKED_RIMS = (("2000", "650"), ("10750", "3000"), ("16200", "6500"), ("17800", "5300"), ("12000", "4800"),
               ("10800", "3200"))
WORKED_CASES = ("Gs 2130, Ds 3,2, n 120", "Gs 11400, Ds 5,4, n 60", "Gs 17500, Ds 4,50, n 105",
                "Gs 19100, Ds 4,50, n 75", "Gs 12900, Ds 4,50, n 105", "Gs 11600, Ds 4,5, n 75")


#: His comparison of the other formulas (seed text after the worked cases): the machine type of each of the six
#: cases -- two single-cylinder, two tandem, two compound engines.
MACHINE_COLUMNS = ("Eincylinder I", "Eincylinder II", "Tandem I", "Tandem II", "Verbund I", "Verbund II")
FORMULA_ROWS = ("Formel A", "Formel B", "Formel C", "Formel D", "Nach Kás", "Formel E")
#: Totals ("Gesamtgewichte") by each formula; None where he prints nothing.  The seed text loses the empty cells:
#: D's two numbers stand under the compound engines and Kás's under the single-cylinder ones (their sizes match
#: those columns of the other formulas: D 12000 beside C's 11000, Kás 36000 beside A's 41000).
FORMULA_TOTALS = {
    "Formel A": ("5750", "41000", "28000", "28000", "18000", "18000"),
    "Formel B": ("5000", "30600", "20000", "22000", "15500", "15500"),
    "Formel C": ("3250", "20500", "18500", "18000", "11000", "11000"),
    "Formel D": (None, None, None, None, "12000", "12000"),
    "Nach Kás": ("8750", "36000", None, None, None, None),
    "Formel E": ("5100", "33500", "22500", "22500", "13500", "13500"),
}
#: "Kranzgewichte, wobei die Arm- und Nabengewichte in Klammern angegeben sind": (rim, arms and hub).
FORMULA_RIMS = {
    "Formel A": (("4250", "1500"), ("30300", "10700"), ("20800", "7200"), ("20600", "7400"), ("13500", "4500"),
                 ("13500", "4500")),
    "Formel B": (("3700", "1300"), ("23000", "7600"), ("21600", "7400"), ("16400", "5600"), ("11400", "4100"),
                 ("11500", "4000")),
    "Formel C": (("2320", "930"), ("15150", "5350"), ("13600", "4900"), ("13400", "4600"), ("8100", "2900"),
                 ("8100", "2900")),
    "Formel D": (None, None, None, None, ("9000", "3000"), ("8850", "3150")),
    "Nach Kás": (("6500", "2250"), ("27000", "9000"), None, None, None, None),
    "Formel E": (("3800", "1300"), ("24950", "8550"), ("16700", "5800"), ("16000", "5900"), ("9950", "3550"),
                 ("9850", "3650")),
}


#: His two printed tables: a number in them with a trailing 5 one place beyond its column is his half (in_halves).
TABLES = ("Tabelle G2", "Tabelle Schwungmoment")


def all_printed() -> list[Printed]:
    """Every printed number, in the order of the text."""
    out = [Printed("Fehler f_x", row, col, text, key) for row, col, text, key in _ERROR]
    out += [Printed("Tangentialdruck-Fehler", row, col, text, key) for row, col, text, key in _TANGENTIAL]
    out += [Printed("Arm- und Nabengewicht", row, col, text, key) for row, col, text, key in _FLYWHEEL]
    for i, (kz, v) in enumerate(zip(TABLE_KZ, TABLE_V)):
        row = f"kz = {kz}, v = {v}"
        out.append(Printed("Tabelle G2", row, "v²", TABLE_V2[i], f"v2:{i}"))
        out.append(Printed("Tabelle G2", row, "G2 = G1 mal", TABLE_1_G2[i], f"t1_g2:{i}"))
        out.append(Printed("Tabelle G2", row, "Gtotal = G1 mal", TABLE_1_TOTAL[i], f"t1_total:{i}"))
    for i, (kz, v) in enumerate(zip(TABLE_KZ, TABLE_V)):
        row = f"kz = {kz}, v = {v}"
        out.append(Printed("Tabelle Schwungmoment", row, "1 + 0,0218 v²/kz", TABLE_2_MOMENT[i], f"t2_moment:{i}"))
        out.append(Printed("Tabelle Schwungmoment", row, "1 + 0,06 v²/kz", TABLE_2_WEIGHT[i], f"t2_weight:{i}"))
    for i, case in enumerate(WORKED_CASES):
        out.append(Printed("Beispiele", case, "v", WORKED_V[i], f"worked_v:{i}"))
        out.append(Printed("Beispiele", case, "Gtotal (Richtige Werte)", WORKED_TOTALS[i], f"worked_total:{i}", resolution="50"))
        out.append(Printed("Beispiele", case, "Kranz (Richtige Werte)", WORKED_RIMS[i][0], f"worked_rim:{i}", resolution="50"))
        out.append(Printed("Beispiele", case, "Arme und Nabe (Richtige Werte)", WORKED_RIMS[i][1], f"worked_arms:{i}",
                           resolution="50"))
    for name in FORMULA_ROWS:
        for i, column in enumerate(MACHINE_COLUMNS):
            if FORMULA_TOTALS[name][i] is None:
                continue
            rim, arms = FORMULA_RIMS[name][i]
            row = f"{name}, {column}"
            out.append(Printed("Formeln", row, "Gesamtgewicht", FORMULA_TOTALS[name][i], f"formula_total:{name}:{i}",
                               resolution="50"))
            out.append(Printed("Formeln", row, "Kranzgewicht", rim, f"formula_rim:{name}:{i}", resolution="10"))
            out.append(Printed("Formeln", row, "Arme und Nabe", arms, f"formula_arms:{name}:{i}", resolution="10"))
    return list(in_halves(out, TABLES))


def printed_formulas() -> list[PrintedFormula]:
    """The printed formulas the errata list as wrong, as printed (seed text, LaTeX as OCR gave it)."""
    t = "Fehler f_x"
    u = "Tangentialdruck-Fehler"
    return [
        PrintedFormula(t, "df_x", "Flächenelement", r"d f_x = \frac{s_1 - s_a}{s_a + s_1} (P_0 - k p_0) d s_a"),
        PrintedFormula(t, "f_x integral", "Integrand", r"f_x = (P_0 - k p_0) \int \frac{s_1 - s_0}{s_a + s_0} d s_a"),
        PrintedFormula(u, "Gl. 1 (first line)", "Beschleunigungsdruck", r"P (1 - \frac{1}{2,2 x} (cos α + 0,2 cos 2α))"),
        PrintedFormula(u, "sin(α + β)/cos β", "Gl. 1, 2, 3 and t'_a",
                       r"sin α + \frac{cos 2α}{10 - 0,2 sin^2 α}"),
        PrintedFormula(u, "t'_a (first form)", "Ordinate der Fehlerfläche",
                       r"t'_a = x (sin α + \frac{cos α}{10 - 0,2 sin^2 α})"),
        PrintedFormula(u, "x in the tangential diagram", "Ordinate des Fehlers",
                       r"x = \frac{s_1 - s_a}{s_a + s_0} (P - k p_0)"),
        PrintedFormula(u, "A, B", "Nenner", r"\sqrt{9 - 5 \frac{s_0}{s}}"),
        PrintedFormula(u, "α_c", "Beginn der Kompression", r"cos α = -5 ± \sqrt{36 - 20 \frac{s_3}{s}}"),
        PrintedFormula("Arm- und Nabengewicht", "Rechnungsgang", "Kranzgewicht",
                       r"Kranzgewicht = G_s / (1 + 0,08075 v^2/k_z)"),
    ]
