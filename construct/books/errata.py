"""Errata of seed 000's printed numbers: each one beside its true value.

For every number of :mod:`construct.books.anhang_ii.printed` the true value is
computed from the formula the book names for it (Gl. (1), (h), (h₁), (4₁), (i)
and the roots of section c), via :mod:`construct.constructions.analytic`), and the printed
value is judged by its distance in units of its last printed place:

- ``agrees``: within half a unit (what correct rounding gives);
- ``follows``: the printed value comes out exactly (to its last place) of another
  printed value the note names -- a rounded intermediate, a wrong input carried
  on -- however near or far it lies;
- ``slip``: up to 2 units (truncation, rounding, slide rule) with no printed value
  that gives it exactly; or a value correct to one place fewer, padded with a 0;
- more than 2 units: one of the classes a historian can cite (:data:`CLASS_MEANINGS`) --
  ``typesetting`` (a digit, a sign, a stray figure: the author's own later use or
  sums show the right value), ``arithmetic`` (the author's own computation from
  his own inputs goes wrong), ``drawing`` (probably read off a drawing: no
  computation from the stated equations gives it), ``ambiguous`` (two readings
  fit the evidence: the note gives both), ``unexplained`` (none of these found).

The rules (:data:`RULES`, ``construct errata --classes``) are the same for every
text: a trailing 5 one place beyond its table column is the author's half
(:func:`construct.books.printed.in_halves`); one cause, one class.

Where a deviation's cause can be seen, the note names it: computed from the
book's own printed (rounded) intermediates, truncated instead of rounded,
sign dropped, adjacent digits swapped, a single wrong digit.  The printed
formulas that are wrong come last, with table ``"formula"``, classed
``typesetting`` (the text goes on with the right form) or ``arithmetic`` (the
author carries the wrong form on).

>>> rows = {(e.table, e.row, e.column): e for e in errata()}
>>> e = rows["Tabelle 1", "180°", "cos ω + r/L·cos 2ω (L/r=6)"]
>>> e.printed, round(e.true, 6), round(e.units, 2), e.class_
('-0.8334', -0.833333, -0.67, 'follows')
>>> e.note
'computed from printed intermediates: -1 + 0.1666 = -0.8334'
>>> classify(0.5), classify(-1.7), classify(2.01)
('agrees', 'slip', 'unexplained')
>>> classify(2.01, "typesetting"), classify(1.0, "typesetting"), classify(1.0, "follows")
('typesetting', 'slip', 'follows')
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction
from typing import Callable

from ..constructions import analytic
from ..kernel.errors import InvalidParameter
from .anhang_ii import printed as seed000
from .printed import Printed, in_halves

__all__ = ["CLASS_MEANINGS", "WRONG", "Erratum", "Reading", "errata", "all_errata", "classify", "read_printed",
           "true_value", "CLASSES", "SOURCES", "errata_of", "RULES"]

#: The other books' errata modules (each has ``entries()``), listed after Anhang II's by :func:`all_errata`.
SOURCES = ("construct.books.handbook.errata", "construct.books.mechanics.errata", "construct.books.baumann.errata")

#: What each class says about a printed number (or formula).
CLASS_MEANINGS = {
    "agrees": "within half a unit of the last printed place: correctly rounded",
    "slip": "within 2 units (truncation, rounding, slide rule) and no printed value gives it exactly; or correct to "
            "one place fewer and padded with a 0",
    "follows": "comes out exactly of another printed value (rounded, or itself wrong) that the note names, at any "
               "distance",
    "typesetting": "a typesetting (or OCR) error: a digit, a sign, a stray figure; the author's own later use, "
                   "sums or neighbours show the right value",
    "arithmetic": "an arithmetic error of the author: his own computation from his own inputs goes wrong "
                  "(and he carries it on)",
    "drawing": "probably read off a drawing: no computation from the stated equations gives it",
    "ambiguous": "two readings fit the evidence (a misprint or a miscalculation; one number wrong or another): "
                 "the note gives both and does not choose",
    "unexplained": "more than 2 units off and none of the causes above found",
}
CLASSES = tuple(CLASS_MEANINGS)
#: The classes a cause can give (a printed number judged beyond agreement, or a wrong formula).
WRONG = ("follows", "typesetting", "arithmetic", "drawing", "ambiguous", "unexplained")

#: The rules every text's errata follow, as ``construct errata --classes`` prints them.
RULES = (
    "The unit is the last printed place, or the step the book rounds to (totals to 50 kg, angles to 10').",
    "A trailing 5 one place beyond the rest of its table column is the author's half (0,4525 among 0,274 ... is "
    "0,452 1/2; ·18615 among ·2247, ·1583 is ·1861 1/2): judged to half a unit of the place before it.  In running "
    "text a number's last printed place is its unit (0,01825, 0,4655).",
    "A value correct to one place fewer and padded with a 0 (·4140 for ·4142) is a slip, not a wrong figure.",
    "'follows' names the printed value it comes out of, exactly; without one it is not 'follows'.",
    "One cause, one class: two numbers with the same explanation have the same class, however far each lies.",
    "Where two readings fit the evidence, the entry is 'ambiguous' and its note gives both.",
    "Printed numbers carried on are judged against what the author's own (wrong) inputs give; the note gives the "
    "value from the right inputs too.",
)

# Boundaries in units of the last printed place.  They are compared exactly
# (units are Fractions of the printed value minus the float true value), so a
# value exactly half-way, like 0.5625 printed as ·563, is judged by its exact
# distance of 0.5 units.
AGREES_WITHIN = Fraction(1, 2)
SLIP_WITHIN = Fraction(2)

_ANGLE_QUANTITIES = frozenset({"omega", "q6_omega", "q7_omega"})


@dataclass(frozen=True, slots=True)
class Erratum:
    """One printed number (or formula) beside its true value and a verdict.

    ``true`` is a float (degrees for angles) or, for a formula, the corrected
    formula as text; ``units`` is the deviation printed − true in units of the
    last printed place (None for formulas); ``class_`` is one of :data:`CLASSES`.
    """

    source: str
    table: str
    row: str
    column: str
    printed: str
    true: float | str
    units: float | None
    class_: str
    note: str

    def as_dict(self) -> dict[str, object]:
        """The fields as a plain dict, ``class_`` spelt ``class``."""
        return {
            "source": self.source,
            "table": self.table,
            "row": self.row,
            "column": self.column,
            "printed": self.printed,
            "true": self.true,
            "units": self.units,
            "class": self.class_,
            "note": self.note,
        }


@dataclass(frozen=True, slots=True)
class Reading:
    """A printed string read as a number: value and one unit of its last place.

    Angles are read in minutes of arc, everything else as plain numbers;
    ``decimals`` is the number of printed decimals (None for angles and fractions).

    >>> read_printed("·563")
    Reading(value=Fraction(563, 1000), unit=Fraction(1, 1000), is_angle=False, decimals=3)
    >>> r = read_printed("33° 7'"); (r.value, r.unit)
    (Fraction(1987, 1), Fraction(1, 1))
    >>> read_printed("10/7").unit
    Fraction(1, 7)
    """

    value: Fraction
    unit: Fraction
    is_angle: bool
    decimals: int | None


_ANGLE = re.compile(r"^(-?\d+)°(?:\s*(\d+)')?$")
_FRACTION = re.compile(r"^(\d+)/(\d+)$")
_DECIMAL = re.compile(r"^-?\d*\.?\d+$")


def read_printed(text: str, resolution: str | None = None) -> Reading:
    """Read a printed string; *resolution* (like ``"10'"``) overrides the last place."""
    if m := _ANGLE.match(text):
        degrees, minutes = int(m.group(1)), m.group(2)
        value = Fraction(degrees * 60 + (int(minutes) if minutes else 0))
        unit = Fraction(1) if minutes is not None else Fraction(60)
        if resolution is not None:
            if not resolution.endswith("'"):
                raise InvalidParameter(f"angle resolution {resolution!r} must be in minutes, like \"10'\"")
            unit = Fraction(int(resolution[:-1]))
        return Reading(value, unit, True, None)
    if text == "F/f":
        # The tangent values are in units of F/f; "F/f" alone is 1 times F/f.
        return Reading(Fraction(1), Fraction(1), False, None)
    if m := _FRACTION.match(text):
        return Reading(Fraction(int(m.group(1)), int(m.group(2))), Fraction(1, int(m.group(2))), False, None)
    plain = text.replace("·", ".")
    if _DECIMAL.match(plain):
        d = Decimal(plain)
        exponent = d.as_tuple().exponent
        assert isinstance(exponent, int)
        unit = Fraction(10) ** exponent if resolution is None else Fraction(resolution)
        return Reading(Fraction(d), unit, False, -exponent)
    raise InvalidParameter(f"cannot read the printed value {text!r} as a number")


def classify(units: float | Fraction, cause: str | None = None) -> str:
    """Class of a deviation in units of the last printed place; beyond a slip, *cause* (one of :data:`WRONG`).

    ``follows`` holds at any distance beyond agreement (the value comes out exactly of a named printed one); the
    other causes only beyond 2 units, within which a deviation is a slip.
    """
    size = abs(Fraction(units))
    if cause is not None and cause not in WRONG:
        raise InvalidParameter(f"cause {cause!r} is not one of {', '.join(WRONG)}")
    if size <= AGREES_WITHIN:
        return "agrees"
    if cause == "follows":
        return "follows"
    if size <= SLIP_WITHIN:
        return "slip"
    return "unexplained" if cause is None else cause


def cause_of(note: str) -> str | None:
    """The class a cause in a note names: the typesetter's, the author's arithmetic, or a printed input.

    >>> cause_of("one digit wrong (8 printed for 3; -0.5335): a type (or OCR) error")
    'typesetting'
    >>> cause_of("computed from printed intermediates: -1 + 0.1666 = -0.8334"), cause_of("rounded to 3 places and padded with 0")
    ('follows', None)
    """
    if any(k in note for k in ("one digit wrong", "adjacent digits swapped", "sign dropped", "stray leading")):
        return "typesetting"
    if "computed from printed intermediates" in note:
        return "follows"
    if "truncated instead of rounded" in note:
        return "arithmetic"
    if "the printed intermediates give" in note:
        return "arithmetic"
    return None


# --------------------------------------------------------------------------
# True values: the quantity each printed number claims to be.


def _lam(v: Printed) -> float:
    assert v.rod_ratio is not None
    return 1.0 / v.rod_ratio


def true_value(v: Printed) -> float:
    """The exact value of what *v* claims to be (degrees for angles).

    >>> from construct.books.anhang_ii.printed import characteristic_points
    >>> true_value(characteristic_points()[0])      # s5 for L/r = 4, Gl. (1): (1 + 1/8) / 2
    0.5625
    """
    q = v.quantity
    if q in ("cos_omega", "cos_2omega", "lam_cos_2omega") or (q == "q" and v.table == "Tabelle 1"):
        w = math.radians(v.omega_deg)  # type: ignore[arg-type]
        if q == "cos_omega":
            return math.cos(w)
        if q == "cos_2omega":
            return math.cos(2.0 * w)
        if q == "lam_cos_2omega":
            return _lam(v) * math.cos(2.0 * w)
        return analytic.inertia_two_term(w, _lam(v))
    if q in ("omega", "q"):  # Tabelle 2: rows are tenths of the stroke, ω from Gl. (h) (exact)
        w = _table_2_angle(v)
        return math.degrees(w) if q == "omega" else analytic.inertia_two_term(w, _lam(v))
    if q == "s5":
        # Gl. (1) at ω = 90°, s = r(1 + r/2L), as a fraction of the stroke 2r = 1.
        return analytic.piston_path_book(math.pi / 2, 0.5, 0.5 * v.rod_ratio)  # type: ignore[operator]
    if q.startswith(("q6_", "q7_")):
        c = _point_cos(q[:2], _lam(v))
        if q.endswith("_cos"):
            return c
        if q.endswith("_omega"):
            return math.degrees(math.acos(c))
        # Gl. (h1) solved for x with 2r = 1: the exact piston path at that crank angle.
        return analytic.piston_path_exact(math.acos(c), 0.5, 0.5 * v.rod_ratio)  # type: ignore[operator]
    if q == "r_tg_beta":
        # Gl. (i) as printed, i.e. the magnitude (1 + 4λ cos ω)/(1 + λ cos ω) times F/f;
        # at 90° that is 1 for every L/r.
        lam = 0.0 if v.rod_ratio is None else _lam(v)
        return -analytic.inertia_slope(math.radians(v.omega_deg), 1.0, lam)  # type: ignore[arg-type]
    raise InvalidParameter(f"no true value known for quantity {q!r} ({v.table}, {v.row}, {v.column})")


def _table_2_angle(v: Printed) -> float:
    # Tabelle 2 uses 2r = 10 and x = tenths of the stroke; in units of r the path is 2·fraction.
    return analytic.crank_angle_from_path(2.0 * v.stroke_fraction, 1.0, float(v.rod_ratio))  # type: ignore[operator]


def _point_cos(point: str, lam: float) -> float:
    return analytic.zero_crossing_cos(lam) if point == "q6" else analytic.plus_m_cos(lam)


# --------------------------------------------------------------------------
# The book's own chain: what each value gives when computed from the printed,
# already rounded, numbers it was derived from.


def _printed_intermediate(
    v: Printed, lookup: Callable[[str, str, str], Printed]
) -> tuple[float, str] | None:
    """(value, description) of *v* recomputed from printed intermediates, if it has any."""
    q, table = v.quantity, v.table
    if table == "Tabelle 1" and q == "lam_cos_2omega":
        c2 = lookup(table, v.row, "cos 2ω").text
        value = float(read_printed(c2).value) / v.rod_ratio  # type: ignore[operator]
        return value, f"{c2} / {v.rod_ratio} = {value:.5f}"
    if table == "Tabelle 1" and q == "q":
        c = lookup(table, v.row, "cos ω").text
        part = lookup(table, v.row, f"r/L·cos 2ω (L/r={v.rod_ratio})").text
        value = float(read_printed(c).value + read_printed(part).value)
        sign = "-" if part.startswith("-") else "+"
        return value, f"{c} {sign} {part.lstrip('-')} = {_format_decimal(Fraction(value), 4)}"
    if table == "Tabelle 2" and q == "q":
        angle = lookup(table, v.row, f"ω (L/r={v.rod_ratio})").text
        w = math.radians(float(read_printed(angle).value) / 60.0)
        value = analytic.inertia_two_term(w, _lam(v))
        return value, f"Gl. (4₁) at the printed ω = {angle}: {value:.5f}"
    if q in ("q6_omega", "q7_omega", "q6_x", "q7_x"):
        c = lookup(table, v.row, f"cos ω (L/r={v.rod_ratio})").text
        w = math.acos(float(read_printed(c).value))
        if q.endswith("_omega"):
            value = math.degrees(w)
            return value, f"arccos {c} = {_format_angle(Fraction(value * 60), 10)}"
        value = analytic.piston_path_exact(w, 0.5, 0.5 * v.rod_ratio)  # type: ignore[operator]
        approx = analytic.piston_path_book(w, 0.5, 0.5 * v.rod_ratio)  # type: ignore[operator]
        return value, f"Gl. (h₁) at the printed cos ω = {c}: {value:.5f} (Gl. (1) would give {approx:.5f})"
    if q == "r_tg_beta" and v.column.startswith("r·tg β (") and v.rod_ratio is not None:
        try:
            fraction = lookup(table, v.row, f"r·tg β fraction (L/r={v.rod_ratio})").text
        except KeyError:  # "0" at 180° for L/r = 4 is printed without a fraction
            return None
        value = float(read_printed(fraction).value)
        return value, f"{fraction} = {value:.5f}"
    return None


# --------------------------------------------------------------------------
# Seeing the cause of a deviation.


def _round_half_away(x: Fraction, unit: Fraction) -> Fraction:
    n = x / unit
    k = math.floor(abs(n) + Fraction(1, 2))
    return unit * (k if n >= 0 else -k)


def _truncate(x: Fraction, unit: Fraction) -> Fraction:
    n = x / unit
    k = math.floor(abs(n))
    return unit * (k if n >= 0 else -k)


def _format_decimal(x: Fraction, decimals: int) -> str:
    return f"{float(x):.{decimals}f}"


def _format_angle(minutes: Fraction, step: int = 1) -> str:
    total = int(_round_half_away(minutes, Fraction(step)))
    return f"{total // 60}° {total % 60}'"


def _digits(text: str) -> str:
    return "".join(ch for ch in text if ch.isdigit())


def _digit_causes(printed: str, candidates: list[str]) -> str | None:
    """Adjacent digits swapped or one digit wrong, against correctly formatted candidates."""
    p = _digits(printed)
    for candidate in candidates:
        c = _digits(candidate)
        if len(c) != len(p) or c == p:
            continue
        diff = [i for i in range(len(p)) if p[i] != c[i]]
        if len(diff) == 2 and diff[1] == diff[0] + 1 and p[diff[0]] == c[diff[1]] and p[diff[1]] == c[diff[0]]:
            return f"adjacent digits swapped ({p[diff[0]]}{p[diff[1]]} printed for {c[diff[0]]}{c[diff[1]]}; {candidate})"
        if len(diff) == 1:
            i = diff[0]
            return f"one digit wrong ({p[i]} printed for {c[i]}; {candidate}): a type (or OCR) error"
    return None


def _chain_explains(reading: Reading, intermediate: tuple[float, str] | None) -> bool:
    """Does rounding the value recomputed from printed intermediates give the printed value?"""
    if intermediate is None:
        return False
    recomputed = Fraction(intermediate[0] * 60) if reading.is_angle else Fraction(intermediate[0])
    return _round_half_away(recomputed, reading.unit) == reading.value


def _causes(
    v: Printed, reading: Reading, true_print: Fraction, intermediate: tuple[float, str] | None, verdict: str
) -> list[str]:
    """Causes that explain why *v* is not the correctly rounded true value."""
    unit = reading.unit
    if _chain_explains(reading, intermediate):
        # The book's own chain explains it; a truncation look-alike would be coincidence.
        return [f"computed from printed intermediates: {intermediate[1]}"]  # type: ignore[index]
    causes = []
    if _truncate(true_print, unit) == reading.value:
        causes.append("truncated instead of rounded")
    if reading.value != 0 and _round_half_away(-true_print, unit) == reading.value:
        causes.append("sign dropped")
    if reading.decimals and v.text.endswith("0"):
        # Stated to one place fewer and padded with a zero (·414 written ·4140).
        coarse = unit * 10
        for how, approx in (("rounded", _round_half_away), ("truncated", _truncate)):
            if approx(true_print, coarse) == reading.value:
                causes.append(f"{how} to {reading.decimals - 1} places and padded with 0")
                break
    if not causes and verdict not in ("agrees", "slip"):
        # Only an error beyond a slip is worth a digit-level story: a slip of one unit always differs in one digit.
        candidates = [_round_half_away(true_print, unit), _truncate(true_print, unit)]
        if reading.is_angle:
            texts = [_format_angle(c, int(unit)) for c in candidates]
        elif reading.decimals is not None:
            texts = [_format_decimal(c, reading.decimals) for c in candidates]
        else:
            texts = []
        digit = _digit_causes(v.text, texts)
        if digit:
            causes.append(digit)
    return causes


def _quantity_note(v: Printed, true: float, reading: Reading) -> str:
    """What the reader needs to know about the true value itself, whatever the verdict."""
    q = v.quantity
    if q == "s5":
        exact = analytic.piston_path_exact(math.pi / 2, 0.5, 0.5 * v.rod_ratio)  # type: ignore[operator]
        units = float((reading.value - Fraction(exact)) / reading.unit)
        return f"Gl. (1); the exact piston path is {exact:.5f}, the printed is {units:+.2f} units from it"
    if q == "q7_cos" and v.rod_ratio == seed000.ROD_RATIOS[0]:
        return "from (-L + √(L² + 16r²)) / 4r; the printed -16r² cannot give it (see formula)"
    if q in ("q6_omega", "q7_omega"):
        return f"printed to 10'; off by {float(reading.value) - true * 60:+.1f}'"
    if q == "r_tg_beta":
        if true == 0.0:
            return "Gl. (i); the tangent is horizontal here"
        return f"magnitude per Gl. (i); the slope dq/dx is {-true:.5g}·F/f / r (sign dropped, see formula)"
    return ""


def _entry(v: Printed, lookup: Callable[[str, str, str], Printed]) -> Erratum:
    reading = read_printed(v.text, v.resolution)
    true = true_value(v)
    true_print = Fraction(true * 60) if reading.is_angle else Fraction(true)
    units = (reading.value - true_print) / reading.unit
    verdict = classify(units)
    notes = []
    correctly_rounded = _round_half_away(true_print, reading.unit) == reading.value
    intermediate = _printed_intermediate(v, lookup)
    if not correctly_rounded:
        causes = _causes(v, reading, true_print, intermediate, verdict)
        if causes:
            notes.extend(causes)
        elif verdict == "slip":
            notes.append("rounding slip in the last place")
        elif verdict == "unexplained" and intermediate is not None and not _chain_explains(reading, intermediate):
            notes.append("no typesetting pattern; the author's arithmetic from his own inputs")
        else:
            notes.append("no cause found")
        if verdict not in ("agrees", "slip") and intermediate is not None and not _chain_explains(reading, intermediate):
            # Show the book's own chain even when it does not explain the error: then the author's arithmetic
            # from his own printed inputs went wrong.
            notes.append(f"the printed intermediates give {intermediate[1]}")
        verdict = classify(units, cause_of("; ".join(notes)))
        if verdict not in ("agrees", "slip") and any("padded with 0" in n for n in notes):
            verdict = "slip"   # right to the places it was computed to; the 0 only fills the column
    elif abs(units) == AGREES_WITHIN:
        notes.append("exactly half-way, rounded up" if units > 0 else "exactly half-way, rounded down")
    extra = _quantity_note(v, true, reading)
    if extra:
        notes.append(extra)
    return Erratum(
        seed000.SOURCE, v.table, v.row, v.column, v.text, true, float(units) + 0.0, verdict, "; ".join(notes)
    )


# --------------------------------------------------------------------------
# Printed formulas: corrected form and why.

_FORMULA_CORRECTIONS: dict[str, tuple[str, str]] = {
    "b) Tabelle 2 header": (
        "q = cos ω + r/L cos 2ω  (F/f = 1)",
        "probably: Gl. (4₁) defines q itself per unit of piston area, so q/f has the wrong "
        "dimension; Tabelle 1 heads the same values cos ω + r/L cos 2ω",
    ),
    "c) q7": (
        "cos ω = (-L + √(L² + 16r²)) / 4r",
        "sign under the root: q = m gives 2(r/L)cos²ω + cos ω - 2 r/L = 0, whose root has +16r²; "
        "with -16r² it gives cos ω = -1, -0.5, -0.382 for L/r = 4, 5, 6, while the printed "
        "·4140 ·3508 ·3028 follow from +",
    ),
    "d) ∂y/∂ω": (
        "∂y/∂ω = -F/f [sin ω + 4 r/L sin ω cos ω]",
        "sign dropped: d(cos ω)/dω = -sin ω; carried into Gl. (i)",
    ),
    "d) Gl. (i)": (
        "tg β = ∂y/∂x = -F/f (1 + 4 r/L cos ω) / (r (1 + r/L cos ω))",
        "sign dropped (from ∂y/∂ω); the book itself writes tg β = -(1/r)·F/f for the infinite rod "
        "and calls it the same slope as Gl. (i) at 90°; the r·tg β values are magnitudes",
    ),
    "d) Gl. (i₁) 90°": (
        "y = -F/f · r/L",
        "sign dropped: cos 90° + r/L cos 180° = -r/L; section c) itself gives q5 = -m",
    ),
    "d) Gl. (i₁) 180°": (
        "y = -F/f (1 - r/L)",
        "sign dropped: cos 180° + r/L cos 360° = -1 + r/L (Tabelle 1: -0.7500 for L/r = 4)",
    ),
}


#: Whose error each printed formula is: the typesetter's where the book goes on with the right form (its numbers
#: follow from it), the author's where he carries the wrong form on.
_FORMULA_CLASS = {
    "b) Tabelle 2 header": "typesetting",      # Tabelle 1 heads the same values rightly
    "c) q7": "typesetting",                    # his ·4140 ·3508 ·3028 follow from the right sign
    "d) ∂y/∂ω": "arithmetic",                  # carried into Gl. (i) and (i₁)
    "d) Gl. (i)": "arithmetic",
    "d) Gl. (i₁) 90°": "arithmetic",
    "d) Gl. (i₁) 180°": "arithmetic",
}


def _formula_entries() -> list[Erratum]:
    out = []
    for f in seed000.printed_formulas():
        true, note = _FORMULA_CORRECTIONS[f.row]
        out.append(Erratum(seed000.SOURCE, f.table, f.row, f.column, f.text, true, None, _FORMULA_CLASS[f.row], note))
    return out


def errata() -> list[Erratum]:
    """Every printed number of seed 000's appendix with its verdict, then the wrong formulas.

    Ordered as the book prints them: Tabelle 1, Tabelle 2, characteristic points,
    tangents (each row by row, column by column), then the formulas in text order.
    """
    printed = in_halves(seed000.all_printed(), seed000.TABLES)
    index = {(p.table, p.row, p.column): p for p in printed}

    def lookup(table: str, row: str, column: str) -> Printed:
        return index[table, row, column]

    return [_entry(v, lookup) for v in printed] + _formula_entries()


def errata_of(book: str = "all") -> list[Erratum]:
    """The errata of one book, by its name ("anhang-ii", "handbook", "mechanics", "baumann"; the number of its
    text, "000" ... "004", is the old name), or of all of them, Anhang II first.

    >>> {e.source for e in errata_of("baumann")} == {e.source for e in errata_of("004")} == {"baumann"}
    True
    """
    from ..constructions.phrases import book as named

    if not isinstance(book, str) or not book.strip():  # an empty --book '' is an unset variable, not "all"
        raise InvalidParameter(f"name a book (anhang-ii, handbook, mechanics, baumann) or 'all', got {book!r}")
    out = all_errata()
    if book == "all":
        return out
    name = named(book).key
    return [e for e in out if e.source == name]


def all_errata() -> list[Erratum]:
    """Anhang II's errata, then those of every module in :data:`SOURCES` (``source`` is the book's name)."""
    import importlib

    out = errata()
    for module in SOURCES:
        out += importlib.import_module(module).entries()
    return out
