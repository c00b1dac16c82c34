"""Errata of seed 004 (Baumann 1902): every printed number of his worked examples and tables beside its true value.

The true value is what the number claims to be, computed from his own
equations (the error area f_x, his closed-form tangential integral, his
series model of the crank for the angles, his flywheel assumptions and
tables) by :mod:`construct.books.baumann.excess_error` and :mod:`construct.books.baumann.flywheel`;
judged as for seed 000 (:func:`construct.books.errata.classify`: within half a unit
of the last printed place ``agrees``, within 2 ``slip``, else the cause: ``typesetting``,
``arithmetic``, ``follows``, ``drawing`` or ``unexplained``, each entry's cause named in
``_CAUSES`` and argued in its note).  Where the true value needs an assumption
(kz = 5 v for his worked cases, which he does not state) the note says so.

His comparison of the other formulas (Formeln A–E, Kás: totals, rim weights
and arms and hub in brackets) is checked against itself
(:func:`formula_table_check`): total = rim + arms and hub, and the factor
total/rim against his "1,33 ÷ 1,35".  Two columns do not add up; the
correction that restores the sum with the factor in his band and the fewest
wrong digits is the likely slip.
Where he carries a wrong number on, the later numbers are judged against the
value his own (wrong) inputs give, so each error is counted where it is made;
the note gives the value from the right inputs too.

>>> rows = {(e.table, e.row, e.column): e for e in entries()}
>>> e = rows["Fehler f_x", "case p = 9,85", "k = 7,85/9,85"]
>>> e.printed, round(e.true, 5), e.class_
('0,805', 0.79695, 'arithmetic')
>>> rows["Tabelle Schwungmoment", "kz = 75, v = 15", "1 + 0,06 v²/kz"].class_
'agrees'
"""

from __future__ import annotations

import math
from fractions import Fraction

from . import excess_error as ee
from . import flywheel as fw
from ..errata import Erratum, classify, read_printed
from ..printed import Printed
from . import printed as seed004

__all__ = ["entries", "true_values", "formula_table_check", "factor_within", "FACTOR_BAND"]

_P, _P0, _S0 = 7.85, 0.15, 0.05
_MODEL = {"admission": _P, "back_pressure": _P0, "filling": 0.10, "clearance": _S0, "compression": 0.30}
_R_MM, _MM_PER_AT, _MM2_PER_AT_STROKE = 50.0, 10.0, 1000.0  # r = 50 mm, 1 at = 10 mm, s = 100 mm


def _deg(text: str) -> float:
    r = read_printed(text)
    return float(r.value) / 60.0


def true_values() -> dict[str, tuple[float, str]]:
    """Key -> (true value, note on what it is and where a printed number goes wrong)."""
    out: dict[str, tuple[float, str]] = {}
    k1, k2 = 0.805, 1.515  # as printed and carried on
    fx1 = ee.error_area(k1, _P0, _P0, 0.10, _S0)
    fx1_true_k = ee.error_area(_P / 9.85, _P0, _P0, 0.10, _S0)
    out["k1"] = (_P / 9.85, "7,85/9,75 = 0,805: a wrong divisor; the case carries 0,805 on")
    note = (f"with k = 0,805 as printed (true k gives {fx1_true_k:.5f}); −0,01776 follows with ln 7 read as 1,952 "
            "— he later quotes −17,76 himself against −17,78 from the integral")
    out["fx1"] = (fx1, note)
    out["fx1_mm2"] = (0.01776 * _MM2_PER_AT_STROKE, f"his −0,01776 in mm² (from his k: {abs(fx1) * 1000:.2f})")
    a1 = 2685.0 / k1
    out["area1_assumed"] = (a1, f"2685/0,805 = {a1:.1f} (2705/0,805 = 3360); true k: {2685 * 9.85 / _P:.1f}")
    out["area1_actual"] = (3360.0 - 17.76, f"his 3360 − 17,76 (the wrong 3360 carried on; from 2685/0,805 and his "
                           f"k: {a1 + fx1 * _MM2_PER_AT_STROKE:.2f})")
    out["k2"] = (_P / 4.85, "7,35/4,85 = 1,515: a misread 7,85; the case carries 1,515 on")
    out["eps2"] = (ee.epsilon(0.40, _S0), "ε = 1,05/0,45")
    fx2 = ee.error_area(k2, _P0, _P0, 0.40, _S0)
    note2 = (f"with k = 1,515 as printed (true k gives {ee.error_area(_P / 4.85, _P0, _P0, 0.40, _S0):.5f}); "
             "ε rounded to 2,33 gives 0,016854")
    out["fx2"] = (fx2, note2)
    out["fx2_mm2"] = (0.0167 * _MM2_PER_AT_STROKE, f"his 0,0167 in mm² (recomputed: {fx2 * 1000:.2f})")
    out["area2_actual"] = (3875.0 + 16.7, f"his 3875 + 16,7 (recomputed: {3875.0 + fx2 * 1000:.2f})")
    coef = ee.integral_coefficients(0.10, _S0)
    why = "partial fractions of his integrand (with sin 2α, as his integration requires)"
    for key in "ABCD":
        out[f"coef_{key}"] = (coef[key], why)
    out["root_minus"] = (-coef["c2"], "5 + √37")
    out["root_plus"] = (coef["c1"], "√37 − 5")
    af = ee.cutoff_angle(0.10)
    out["alpha_f"] = (math.degrees(af), f"cos α_f = −5 + √34 = {math.cos(af):.4f}; his 11,92 = 11,08 + 0,84 shows he "
                      "took cos α_f = 0,836 (√34 as 5,836); exact kinematics 33° 47,7'")
    # He integrates from his α_f = 33° 15'.
    af_book = math.radians(_deg("33° 15'"))
    kw = {"r": _R_MM, "k": k1, "p0": _P0, "P0": _P0, "s1": 0.10, "s0": _S0}
    f_full = ee.tangential_error(af_book, math.pi, **kw)
    out["f_full"] = (f_full, "r(P0 − k p0)[H(−1) − H(cos α_f)] with his α_f = 33° 15'")
    out["f_full_mm2"] = (-1.778 * _MM_PER_AT, "his −1,778 mm·at, 1 at = 10 mm")
    out["alpha_c"] = (math.degrees(ee.compression_angle(0.30)),
                      "sa = s − s3 in his series: cos α = −5 + √(16 + 20 s3/s) (the printed √(36 − 20 s3/s) gives "
                      "61° 30'); exact kinematics 107° 58,8'")
    why_a = ("his equations 1)–3) (κ = P/B_max, B = P/(1,2 κ)(cos α + 0,2 cos 2α), 30 % compression) with the mean "
             "line (1/π)∫T dα; exact kinematics, no compression or B = P/κ(…) do not reproduce it either: probably "
             "read off his drawn diagrams")
    for kappa, tag in ((8.0, "k8"), (2.0, "k2")):
        c = ee.crossings(kappa, _MODEL)
        out[f"alpha1_{tag}"] = (math.degrees(c["alpha1"]), why_a)
        out[f"alpha2_{tag}"] = (math.degrees(c["alpha2"]), why_a)
    printed_angles = {"alpha1_k8": "10° 20'", "alpha2_k8": "99° 10'", "alpha1_k2": "20° 30'", "alpha2_k2": "149°"}
    for key, text in printed_angles.items():
        out[f"cos_{key}"] = (math.cos(math.radians(_deg(text))), f"cosine of his printed {text}")
    rad = {key: math.radians(_deg(text)) for key, text in printed_angles.items()}
    out["alpha2_k8_rad"] = (rad["alpha2_k8"], "99° 10' in radians")
    out["alpha1_k8_rad"] = (rad["alpha1_k8"], "10° 20' in radians (0,175 is 10° 2')")
    fx_mm2 = f_full * _MM_PER_AT
    for tag in ("k8", "k2"):
        f = ee.tangential_error(af_book, rad[f"alpha2_{tag}"], **kw) * _MM_PER_AT
        shift = (rad[f"alpha2_{tag}"] - rad[f"alpha1_{tag}"]) * fx_mm2 / math.pi
        out[f"f_{tag}"] = (f, "r(P0 − k p0)[H(cos α2) − H(cos α_f)] with his printed angles")
        out[f"shift_{tag}"] = (shift, "(α2 − α1)·f_x/π with his printed angles and f_x = −17,78")
        out[f"fxc_{tag}"] = (f - shift, "r∫f1 − (α2 − α1) f_x/π")
        out[f"alpha2_{tag}_rad"] = (rad[f"alpha2_{tag}"], "α2 in radians")
    out["f_k8"] = (out["f_k8"][0], out["f_k8"][1] + "; his own bracket terms sum to −0,6088, i.e. −8,90 mm²")
    out["shift_k2"] = (out["shift_k2"][0], out["shift_k2"][1] + "; he takes α1 = 0,175 (κ = 8's) for 20° 30' = 0,358: "
                       "−13,73")
    out["fxc_k8"] = (out["fxc_k8"][0], out["fxc_k8"][1] + "; 8,06 − 8,79 = −0,73 printed without its sign; "
                     "recomputed the correction vanishes, as he concludes")
    out["fxc_k2"] = (out["fxc_k2"][0], out["fxc_k2"][1] + "; his −17,40 less his 13,7 taken as −13,7: −17,40 + 13,7 "
                     "= −3,7, printed without its sign")
    out["fu_k2"] = (659.0 + 3.7, f"his 659 + 3,7 (with the recomputed f_x' = {out['fxc_k2'][0]:.2f}: "
                    f"{659.0 + out['fxc_k2'][0]:.1f}, the error 0,55 % the other way)")
    # -- flywheel
    d, bc = fw.derived(), fw.book_chain()
    out["ln6"] = (math.log(6.0), "ln 6")
    out["centroid"] = (d["centroid"], f"(5/6)/ln 6; from the printed 1,79: {bc['centroid']:.5f}")
    out["disc"] = (d["disc"], "2·(5/6)/ln 6·ln 6 = 5/3 exactly (he rounds 2·0,4655·1,79 = 1,6665 up)")
    out["hub"] = (d["hub"], "((1/6)² − (1/12)²)·24 = 1/2")
    out["arms_factor"] = (d["disc"] + d["hub"], "5/3 + 1/2 = 13/6")
    note_arms = (f"from his rounded 2,2 π: 1,1 γ/g; from the exact 13/6 π of his assumptions "
                 f"{d['arms_hub'] * 1e4:.1f} (kg/m²) = {d['arms_hub']:.5f} (kg/cm²), 1,5 % less")
    out["arms_m2"] = (fw.ARMS_HUB_PRINTED_ASSUMPTIONS * 1e4, note_arms)
    out["arms_cm2"] = (fw.ARMS_HUB_PRINTED_ASSUMPTIONS, note_arms)
    out["disc_coeff"] = (bc["disc_coeff"], f"1,7/2·γ/(g·10⁴); exact 5/6·γ/(g·10⁴) = {d['disc_coeff']:.5f}")
    with_true = 0.0625 * 49.0 / 144.0 + bc["hub_coeff"] * 3.0 / 144.0
    out["hub_coeff"] = (bc["hub_coeff"], f"0,5/2·γ/(g·10⁴) = 0,01835: one digit wrong, two readings: a misprint of "
                        f"0,01835, or his own slip in working it out; his later use cannot tell them apart "
                        f"(0,0625·49/144 + 0,01825·3/144 = {bc['moment']:.6f}, with 0,01835 {with_true:.6f}: both "
                        f"0,0216 beside his 0,0218)")
    out["moment"] = (bc["moment"], f"0,0625·49/144 + 0,01825·3/144 from his printed coefficients; from his exact "
                     f"assumptions {d['moment']:.5f} (the hub's 3/144 itself is not derivable from them).  Not "
                     f"the wheel's moment: ρ = 7/12 r1 halves the disc's mass, its radius of gyration is "
                     f"k² = 215/540 r1² = {fw.DISC_GYRATION:.4f} r1² (not 49/144 = 0,3403), the hub's 2,5/144: "
                     f"the moment coefficient is {d['moment_gyration']:.4f} (construct flywheel: the exact column)")
    out["total_first_order"] = (fw.ARMS_HUB - fw.MOMENT, "(1 + a x)/(1 + m x) ≈ 1 + (a − m) x; he computes with "
                                "1 + 0,06 x, not the quotient (construct flywheel prints both)")
    for i, (kz, v) in enumerate(zip(seed004.TABLE_KZ, seed004.TABLE_V)):
        x = float(v) ** 2 / float(kz)
        out[f"v2:{i}"] = (float(v) ** 2, "v²")
        out[f"t1_g2:{i}"] = (fw.ARMS_HUB * x, "0,08075 v²/kz")
        out[f"t1_total:{i}"] = (1.0 + fw.ARMS_HUB * x, "1 + 0,08075 v²/kz")
        out[f"t2_moment:{i}"] = (1.0 + fw.MOMENT * x, "1 + 0,0218 v²/kz")
        quotient = (1.0 + fw.ARMS_HUB * x) / (1.0 + fw.MOMENT * x)
        out[f"t2_weight:{i}"] = (1.0 + fw.TOTAL * x, f"1 + 0,06 v²/kz as his formula; his own quotient "
                                 f"(1 + 0,08075 x)/(1 + 0,0218 x) of which it is the expansion is {quotient:.4f}")
    # His worked cases, judged along his own chain: the total from G_s and his printed (rounded) v, the rim from
    # his printed total, arms and hub as printed total − printed rim.  kz = 5 v is an assumption (his tables pair
    # kz and v so; he does not say which kz he takes here).
    totals = [16800.0 if t == "116800" else float(t) for t in seed004.WORKED_TOTALS]
    for i, row in enumerate(fw.worked_totals()):
        v = float(seed004.WORKED_V[i].replace(",", "."))
        out[f"worked_v:{i}"] = (row["v"], "π D n/60" + ("; 17,65 for 17,67: π taken as 3,14 gives 17,66, a slide "
                                                       "rule's reading" if seed004.WORKED_V[i] == "17,65" else ""))
        pair = "assuming kz = 5 v as his tables pair them"
        gs = row["Gs"]
        total = gs * (1.0 + fw.TOTAL * v / fw.KZ_PER_V)
        out[f"worked_total:{i}"] = (total, f"G_s(1 + 0,06 v²/kz) with his printed v = {seed004.WORKED_V[i]}, {pair}; "
                                    f"to 50 kg (with v = π D n/60: {row['total']:.0f})")
        rim = totals[i] / (1.0 + fw.ARMS_HUB * v / fw.KZ_PER_V)
        rim85 = totals[i] / (1.0 + fw.ARMS_HUB * v * v / 85.0)
        alt = (f"; with kz = 85, his tables' column for v = 17, {rim85:.0f}: the printed value follows from that "
               f"rounded kz" if round(rim85 / 50.0) * 50.0 == float(seed004.WORKED_RIMS[i][0]) and
               abs(rim - float(seed004.WORKED_RIMS[i][0])) > 25.0 else "")
        out[f"worked_rim:{i}"] = (rim, f"his printed total {totals[i]:.0f} / (1 + 0,08075 v²/kz), {pair}; to 50 kg"
                                  f"{alt} (G_s/(1 + 0,0218 v²/kz) of his derivation gives {row['rim_by_moment']:.0f})")
        arms = totals[i] - float(seed004.WORKED_RIMS[i][0])
        out[f"worked_arms:{i}"] = (arms, f"follows exactly from his printed total − printed rim ({totals[i]:.0f} − "
                                   f"{seed004.WORKED_RIMS[i][0]}); by the method, {pair}: {row['arms_hub']:.0f}")
    out.update(_formula_table_values())
    return out


#: His factor for arms and hub, "die errechneten Kranzgewichte, wie sonst allgemein üblich, mit 1,33 ÷ 1,35
#: multipliziert": a factor that rounds to two decimals within it is within.
FACTOR_BAND = (1.33, 1.35)


def _digits_apart(a: str, b: str) -> int:
    """How many digits a typesetter would have to get wrong: 1 for one wrong digit or two adjacent swapped."""
    if len(a) != len(b):
        return 99
    diff = [i for i in range(len(a)) if a[i] != b[i]]
    if len(diff) == 2 and diff[1] == diff[0] + 1 and a[diff[0]] == b[diff[1]] and a[diff[1]] == b[diff[0]]:
        return 1
    return len(diff)


def _rounding_step(total: int) -> int:
    """The step a printed total is rounded to, read off its trailing digits (he rounds to 500, 250, 50 kg)."""
    return next(step for step in (500, 250, 50, 10, 1) if total % step == 0)


def _factor_note(total: int, rim: int) -> tuple[float, str]:
    f = total / rim
    h = _rounding_step(total) / 2
    low, high = (total - h) / rim, (total + h) / rim
    inside = low <= FACTOR_BAND[1] and high >= FACTOR_BAND[0]
    where = (f"within his 1,33–1,35 (the total rounded to {2 * h:.0f} kg: {low:.3f}–{high:.3f})" if inside else
             f"outside his 1,33–1,35 even with the total's rounding to {2 * h:.0f} kg ({low:.3f}–{high:.3f}): this "
             "formula's own allowance for arms and hub (he takes, for the formula that gives the total, the arms "
             "and hub as its calculation gives)")
    return f, f"factor total/rim {f:.3f}, {where}"


def factor_within(total: int, rim: int) -> bool:
    """Does the factor total/rim lie within his 1,33–1,35, allowing for the total's rounding?

    >>> factor_within(28000, 20600), factor_within(20000, 12600)
    (True, False)
    """
    return "within" in _factor_note(total, rim)[1]


def formula_table_check(total: str, rim: str, arms: str) -> dict[str, object]:
    """One column of his comparison checked against itself: total = rim + arms and hub, and his factor 1,33–1,35.

    Returns ``true`` (the consistent triple: the printed one, or with the likely slip corrected), ``wrong``
    (which of "total", "rim", "arms" is corrected, or None), ``cause`` and ``note``.  When the sum fails,
    each single correction that restores it is weighed: the one that puts the factor within (or nearest) his
    band and needs the fewest wrong digits is the likely slip -- a typesetting error when one digit (or two
    adjacent swapped) is wrong, else the author's arithmetic.

    >>> c = formula_table_check("20000", "21600", "7400")       # Formel B, third column
    >>> c["wrong"], c["true"]["total"], c["cause"]
    ('total', 29000, 'typesetting')
    >>> c = formula_table_check("22500", "16000", "5900")       # Formel E, fourth column
    >>> c["wrong"], c["true"]["rim"], c["cause"]
    ('rim', 16600, 'typesetting')
    """
    t, r, a = int(total), int(rim), int(arms)
    printed = {"total": t, "rim": r, "arms": a}
    if t == r + a:
        f, note = _factor_note(t, r)
        return {"true": printed, "wrong": None, "cause": None, "note": note, "factor": f}
    options = []
    for which, value in (("total", r + a), ("rim", t - a), ("arms", t - r)):
        triple = {**printed, which: value}
        if min(triple.values()) <= 0:
            continue
        f = triple["total"] / triple["rim"]
        off = 0.0 if factor_within(triple["total"], triple["rim"]) else min(abs(f - b) for b in FACTOR_BAND)
        digits = _digits_apart(str(printed[which]), str(value))
        options.append((off > 0.03, digits, off, which, triple, f))
    options.sort(key=lambda o: o[:3])
    far, digits, off, which, triple, f = options[0]
    cause = "typesetting" if digits <= 1 else "arithmetic"
    others = ", ".join(f"{w} {o[4][w]} (factor {o[5]:.3f})" for o in options[1:] for w in [o[3]])
    note = (f"{r} + {a} = {r + a}, not {t}: the {which} {printed[which]} read as {triple[which]} restores the sum "
            f"with factor {f:.3f} and {digits} wrong digit{'s' if digits != 1 else ''}"
            + (f"; the other readings: {others}" if others else ""))
    return {"true": triple, "wrong": which, "cause": cause, "note": note, "factor": f}


def _against_formula_a(name: str, i: int, c: dict[str, object]) -> dict[str, object]:
    """A corrected total weighed against the rest of his comparison: each formula's totals stand in a steady
    ratio to Formel A's (B: 0,75–0,87), and A, C and E give the two tandem engines nearly equal totals.  Where
    the correction takes the formula's ratio to A far out of the range of its other columns and the printed total
    stays near it, the other reading -- the total right, the rim and arms both wrong -- fits as well: the verdict
    is ``ambiguous`` and the note gives both."""
    if c["wrong"] != "total" or name == "Formel A":
        return c
    totals = seed004.FORMULA_TOTALS
    ratios = [int(totals[name][j]) / int(totals["Formel A"][j]) for j in range(len(seed004.MACHINE_COLUMNS))
              if j != i and totals[name][j] is not None and totals["Formel A"][j] is not None]
    if len(ratios) < 2:
        return c
    lo, hi = min(ratios), max(ratios)
    a = int(totals["Formel A"][i])
    printed, corrected = int(totals[name][i]), int(c["true"]["total"])  # type: ignore[index]

    def off(x: float) -> float:
        return max(lo - x, x - hi, 0.0)

    if off(corrected / a) <= 2.0 * off(printed / a) + 0.05:
        return c
    rim = round(printed / 1.34 / 100.0) * 100
    note = (f"two readings: (1) {c['note']}; then {name}/Formel A = {corrected / a:.2f} against "
            f"{lo:.2f}–{hi:.2f} in the other columns; (2) the total {printed} right ({name}/Formel A = "
            f"{printed / a:.2f}) and the rim and arms both wrong (with his factor 1,34 about {rim} and "
            f"{printed - rim}) -- the printed rim and arms add to the other reading's total, the ratios to Formel A "
            f"speak for this one")
    return {**c, "cause": "ambiguous", "note": note}


def _formula_table_values() -> dict[str, tuple[float, str]]:
    out: dict[str, tuple[float, str]] = {}
    for name in seed004.FORMULA_ROWS:
        for i in range(len(seed004.MACHINE_COLUMNS)):
            if seed004.FORMULA_TOTALS[name][i] is None:
                continue
            rim, arms = seed004.FORMULA_RIMS[name][i]
            c = _against_formula_a(name, i, formula_table_check(seed004.FORMULA_TOTALS[name][i], rim, arms))
            true = c["true"]
            sums = {"total": f"rim + arms and hub = {true['rim']} + {true['arms']}",
                    "rim": f"total − arms and hub = {true['total']} − {true['arms']}",
                    "arms": f"total − rim = {true['total']} − {true['rim']}"}
            for part in ("total", "rim", "arms"):
                note = c["note"] if c["wrong"] == part else (
                    f"{sums[part]}" + (f"; {c['note']}" if c["wrong"] is None else
                                       f"; agrees with the {c['wrong']} corrected ({c['wrong']} {true[c['wrong']]}, factor "
                                       f"total/rim {c['factor']:.3f})"))
                if c["cause"] == "ambiguous" and c["wrong"] != part:
                    note += f"; under the other reading (the {c['wrong']} as printed) it is wrong: see the {c['wrong']}'s note"
                out[f"formula_{part}:{name}:{i}"] = (float(true[part]), note)
                if c["wrong"] == part or c["cause"] == "ambiguous":   # an ambiguous column is so in all its numbers
                    _CAUSES[f"formula_{part}:{name}:{i}"] = str(c["cause"])
    return out


#: Why the printed numbers more than 2 units off are wrong (keys as in :func:`true_values`); the notes say more.
_CAUSES: dict[str, str] = {
    "k1": "arithmetic", "fx1": "arithmetic", "area1_assumed": "arithmetic", "k2": "arithmetic",
    "coef_A": "arithmetic", "coef_B": "arithmetic", "coef_D": "arithmetic", "alpha_f": "arithmetic",
    "alpha_c": "arithmetic",
    "alpha1_k8": "drawing", "alpha2_k8": "drawing", "alpha1_k2": "drawing", "alpha2_k2": "drawing",
    "cos_alpha2_k8": "typesetting", "cos_alpha2_k2": "typesetting",
    "coef_C": "typesetting",          # 4,98 in the brackets for the 4,89 he prints two lines before
    "f_k8": "arithmetic", "alpha1_k8_rad": "arithmetic", "fxc_k8": "follows", "f_k2": "arithmetic",
    "shift_k2": "arithmetic", "fxc_k2": "follows", "centroid": "follows", "hub_coeff": "ambiguous",
    "worked_v:3": "arithmetic", "worked_v:5": "arithmetic", "worked_total:4": "typesetting",
    "worked_rim:3": "follows", "worked_rim:5": "follows",
}


def _units(reading_value: Fraction, unit: Fraction, true: float) -> Fraction:
    return (reading_value - Fraction(true)) / unit


def _entry(p: Printed, true: float, note: str) -> Erratum:
    reading = read_printed(p.text.replace(",", "."))
    unit = Fraction(p.resolution) if p.resolution else reading.unit
    value = reading.value
    t = true * 60.0 if reading.is_angle else true
    units = _units(value, unit, t)
    cause = _CAUSES.get(p.quantity, "unexplained")
    # two readings: the class says so whatever the distance under the first
    verdict = "ambiguous" if cause == "ambiguous" else classify(units, cause)
    notes = [note]
    if verdict != "agrees" and classify(_units(-value, unit, t)) in ("agrees", "slip"):
        notes.append("sign dropped: the magnitude is right")
    if verdict == "slip" and p.table.startswith("Tabelle") and abs(float(value) - t) <= 0.0025 * abs(t):
        notes.append("within a slide rule's three figures")
    if verdict not in ("agrees", "slip") and not reading.is_angle and p.text.lstrip("-").startswith("1") and len(p.text) > 3:
        shorter = Fraction(p.text.replace(",", ".").lstrip("-")[1:] or "0")
        if classify(_units(shorter, unit, abs(t))) in ("agrees", "slip"):
            notes.append("a stray leading 1: the rest agrees")
    return Erratum(seed004.SOURCE, p.table, p.row, p.column, p.text, true, float(units) + 0.0, verdict, "; ".join(notes))


_FORMULAS = {
    "df_x": (r"d f_x = \frac{s_1 - s_a}{s_a + s_0} (P_0 - k p_0) d s_a",
             "denominator s_a + s_0 (from x two lines above); the integral is evaluated with it"),
    "f_x integral": (r"f_x = (P_0 - k p_0) \int_{s_1}^{s} \frac{s_1 - s_a}{s_a + s_0} d s_a",
                     "numerator s_1 - s_a; the next line splits exactly this integrand"),
    "Gl. 1 (first line)": (r"P (1 - \frac{1}{1,2 κ} (cos α + 0,2 cos 2α))",
                           "B_a = P/(1,2 κ)(…); the next line's 1/(2,4 κ) follows from 1,2, not 2,2"),
    "sin(α + β)/cos β": (r"sin α + \frac{sin 2α}{10 - 0,2 sin^2 α}",
                         "cos α tan β = (λ/2) sin 2α/√(1 − λ² sin²α) ≈ sin 2α/(10 − 0,2 sin²α) for λ = 0,2; "
                         "his closed-form integral (A, B, C, D reproduce) needs sin 2α"),
    "t'_a (first form)": (r"t'_a = x (sin α + \frac{sin 2α}{10 - 0,2 sin^2 α})", "as above (sin 2α)"),
    "x in the tangential diagram": (r"x = \frac{s_1 - s_a}{s_a + s_0} (P_0 - k p_0)",
                                    "P_0 - k p_0, as derived for the steam diagram and used in the next line"),
    "A, B": (r"\sqrt{9 + 5 \frac{s_0}{s}}", "c1 − c2 = 2√(36 + 20 s0/s) = 4√(9 + 5 s0/s); the roots ±√37 need +"),
    "α_c": (r"cos α = -5 + \sqrt{16 + 20 \frac{s_3}{s}}  (or \sqrt{36 - 20 \frac{s_2}{s}})",
            "s_a = s − s_3 in his series; with s_3 as printed the formula gives 61° 30', his 107° 50' needs s_2 = 0,7 s"),
    "Rechnungsgang": (r"Kranzgewicht = G_{total} / (1 + 0,08075 v^2/k_z)",
                      "G_total = G_1(1 + 0,08075 v²/kz); his own list of rim weights divides the total (2650/1,325 "
                      "= 2000), dividing G_s would give 1610"),
}


#: Every wrong formula of his is the typesetter's: the next lines, his integrals and his numbers follow from the
#: right form (the notes say which).
_FORMULA_CLASS = {row: "typesetting" for row in _FORMULAS}


def entries() -> list[Erratum]:
    """Every printed number of seed 004 with its verdict, in the order of the text, then the wrong formulas."""
    truth = true_values()
    out = [_entry(p, *truth[p.quantity]) for p in seed004.all_printed()]
    for f in seed004.printed_formulas():
        true, note = _FORMULAS[f.row]
        out.append(Erratum(seed004.SOURCE, "formula", f.row, f.column, f.text, true, None, _FORMULA_CLASS[f.row], note))
    return out
