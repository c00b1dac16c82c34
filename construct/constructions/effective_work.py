"""Indicated and effective work: Baumann's Fig. 27 (seed 004), friction as a constant tangential force.

"Das Tangentialdruckdiagramm wird ganz allgemein für die indizierte Leistung
verzeichnet.  Die Ueberschussfläche EBF (Fig. 27) stellt den Ueberschuss an
indizierter Leistung dar, den das Schwungrad aufzunehmen hat.  In der That
nimmt das Schwungrad jedoch nur effektive Arbeit in sich auf, d.h. einen Betrag
dargestellt durch die Fläche LHM.  Diese Fläche ist aber gleich der Fläche EBF,
so lange man annimmt, dass der der Reibungsarbeit entsprechende Tangentialdruck
in jeder Kurbelstellung einen konstanten Wert hat" -- and the flywheel gives out
"die Arbeit der Fläche FCODP zur Ueberwindung der Reibungsarbeit und Nutzlast",
equal to EBF.

What is constructed, going on from the tangential-pressure construction (its
diagram ABCD of the indicated force over the unrolled crank circle, the mean
line MM at the height T_m = 2P_i/π, the excess area EBF between α₁ and α₂):

* the efficiency η (the mechanical efficiency: effective over indicated work)
  carries the mean height to the effective mean line at η·T_m by the
  proportional angle (a fourth proportional to r, η·r and T_m), and the
  compass takes the friction R = T_m − η·T_m between the two lines: the
  friction as a constant tangential force;
* every point of the indicated curve stepped down by R along its ordinate with
  the compass: the effective curve (the French curve through them), which meets
  the effective mean line in L and M and has its top in H, vertically under
  E, F and B; the area LHM hatched and planimetered;
* N, the foot of the perpendicular from F (and M) to the base: from there on the
  flywheel gives out work;
* the deficit FCODP -- the regions between the mean line and the curve from F
  to the end of the stroke and, the strokes being equal ("der Einfachheit
  halber angenommen, dass die Tangentialdruckdiagramme für Hin- und Rückgang
  gleich seien"), from the start of the next one to its E -- planimetered.

The checks: LHM = EBF (a translation: the planimeter's own error), L, H, M under
E, B, F, FCODP = EBF (the mean line's balance), the effective mean line at η·T_m,
besides the tangential-pressure construction's own; a replay with another η keeps
LHM = EBF (what friction as a constant tangential force means).

**The influence of the efficiency.**  With friction a constant tangential force
the flywheel takes up EBF whatever η: the effective curve is the indicated one
moved down.  Baumann names the other case ("zusätzliche Reibungsarbeit,
proportional in jeder Kurbelstellung dem jeweiligen Kolbendruck"): with a share
*s* of the friction constant and the rest proportional to the piston force, the
effective curve is (1 − c)·T − R₀ with c = (1 − s)(1 − η), R₀ = s(1 − η)T_m, and
the flywheel takes up (1 − c)·EBF.  :func:`flywheel_share` gives that factor
(Baumann's s = 1 gives 1); the figure draws his case.

>>> fig = EFFECTIVE_WORK.figure(parts=6)
>>> round(planimetered(fig, "effective") / planimetered(fig, "excess"), 9)
1.0
>>> round(flywheel_share(0.85, 0.0), 4), flywheel_share(0.85, 1.0)
(0.85, 1.0)
"""

from __future__ import annotations

import math
from typing import Any, Mapping

import numpy as np

from .checking import EUCLIDEAN_TOLERANCE, Check
from ..kernel.errors import InvalidParameter
from ..kernel.instruments import Builder
from ..kernel.proportional import fourth_proportional
from ..kernel.protocol import Caption
from . import Construction, Figure, bounded, form_rows, register
from .domain import MECHANICAL_EFFICIENCY
from .phrases import BAUMANN_1902, Cite, number
from .tangential import TANGENTIAL, model_summary, tangential_checks

__all__ = ["EFFECTIVE_WORK", "build_effective_work", "effective_work_checks", "planimetered", "flywheel_share",
           "EFFICIENCY"]

#: The mechanical efficiency drawn by default: a steam engine's 0.85 (Baumann names none).
EFFICIENCY = 0.85


def flywheel_share(efficiency: float, constant_share: float = 1.0) -> float:
    """What the flywheel takes up of the indicated excess EBF when a share *constant_share* of the friction is a
    constant tangential force and the rest proportional to the piston force: 1 − (1 − s)(1 − η).

    >>> flywheel_share(0.8, 0.5)
    0.9
    """
    return 1.0 - (1.0 - constant_share) * (1.0 - efficiency)


def build_effective_work(*, efficiency: float, **tangential: Any) -> Figure:
    """The tangential-pressure figure (Baumann's diagram, one stroke) and, going on from it, Fig. 27."""
    eta = float(bounded("mechanical efficiency η", efficiency, MECHANICAL_EFFICIENCY))
    if tangential.get("force", "baumann") != "baumann":
        raise InvalidParameter("effective-work draws Baumann's indicated diagram (force baumann)")
    base = TANGENTIAL.figure(**{**tangential, "force": "baumann"})
    n = base.params["parts"]
    b = Builder.continuing(base.protocol, base.replay, "effective-work", givens={"efficiency": eta},
                           params={"plate": PLATE})
    # Fig. 27 letters Fig. 26's crossings α₁, α₂ E and F
    b.set_label("A1", "E")
    b.set_label("A2", "F")
    with b.group("the effective mean line: η times the mean height (proportional angle)",
                 "Die effektive Ausgleichende: η mal die mittlere Höhe (Proportionswinkel)"):
        S = b.given_point("S.eff", -1.4, -2.2, unit="r", de="Scheitel S des Proportionswinkels",
                          en="vertex S of the proportional angle", label="S")
        b.given_length("one.eff", product=("r",), de="Einheit r", en="unit r")
        b.given_length("eta.eff", product=("efficiency", "r"), de="η·r", en="eta r")
        origin, end = fourth_proportional(b, "ehm", vertex=S, leg_point="U0", a="one.eff", b_="eta.eff", c="hm")
        b.length_of("ehm.l", origin, end, de="Zirkel auf η·T_m", en="compass set to eta T_m")
        up = ("toward", None, None, 0.0, 1.0)
        for end_name, mark, ordinate in (("EM0", "U0", "u0"), ("EMn", f"U{n}", f"u{n}")):
            k = b.circle_radius(f"{end_name}.k", mark, "ehm.l", de="η·T_m über der Grundlinie",
                                en="eta T_m above the base")
            b.intersect(end_name, ordinate, k, rule=up, de="effektive mittlere Höhe", en="effective mean height")
        b.line("emean", "EM0", "EMn", role="result", de="effektive Ausgleichende (Höhe η·T_m): äusserer Widerstand",
               en="effective mean line (height eta T_m): the outer resistance")
        b.length_of("R.eff", "EM0", "M0", de="Reibung R = T_m − η·T_m als konstanter Tangentialdruck",
                    en="friction R = T_m - eta T_m as a constant tangential force")
    down = ("toward", None, None, 0.0, -1.0)
    points = ["U0"] + [f"T{k}" for k in range(1, n)] + [f"U{n}"]
    effective = []
    with b.group("the effective curve: every ordinate less the friction R",
                 "Die effektive Tangentialdrucklinie: jede Ordinate weniger der Reibung R"):
        for k, p in enumerate(points):
            kc = b.circle_radius(f"eff{k}.k", p, "R.eff", de=f"R von Punkt {k} abwärts", en=f"R down from point {k}")
            effective.append(b.intersect(f"eff{k}", f"u{k}", kc, rule=down, role="result",
                                         de=f"effektiver Tangentialdruck bei {k}", en=f"effective tangential force at {k}"))
        b.french_curve("ecurve", "tbase", effective, {}, de="effektive Tangentialdrucklinie (Curvenlineal)",
                       en="effective tangential-pressure line (French curve)")
    with b.group("L, H, M and the effective excess area LHM", "L, H, M und die effektive Überschussfläche LHM"):
        for name, rule, word in (("L.eff", ("toward", None, None, -1.0, 0.0), ("erster", "first")),
                                 ("M.eff", ("toward", None, None, 1.0, 0.0), ("letzter", "last"))):
            b.record("intersect", "intersect", ("ecurve", "emean"), (name,), {"rule": rule, "both": False},
                     f"{name[0]}: effektive Ausgleichende schneidet die effektive Linie ({word[0]} Schnitt)",
                     f"{name[0]}: the effective mean line crosses the effective line ({word[1]} crossing)",
                     role="result", labels={name: name[0]})
        b.area_between("effective", "ecurve", "emean", "L.eff", "M.eff", hatch_deg=90.0, role="result",
                       de="effektive Überschussfläche LHM (schraffiert)", en="effective excess area LHM (hatched)")
        b.planimeter("P.effective", "effective", de="Planimeter: Fläche LHM", en="planimeter: area LHM")
        b.planimeter("P.excess", "excess", de="Planimeter: Fläche EBF", en="planimeter: area EBF")
    with b.group("N under F and M; the work the flywheel gives out, FCODP",
                 "N unter F und M; die vom Schwungrad abgegebene Arbeit FCODP"):
        _, foot = b.drop_perpendicular("N.eff", "A2", "tbase", "U0", f"U{n}")
        b.set_label(foot, "N")
        b.area_between("deficit.end", "mean", "tcurve", "A2", f"U{n}", hatch_deg=45.0, role="result",
                       de="FC: Fehlbetrag bis zum Hubende", en="FC: deficit to the end of the stroke")
        b.area_between("deficit.start", "mean", "tcurve", "U0", "A1", hatch_deg=45.0, role="result",
                       de="OD…P: Fehlbetrag des nächsten Hubes bis E (Hin- und Rückgang gleich)",
                       en="OD...P: the next stroke's deficit up to E (both strokes equal)")
        b.planimeter("P.deficit.end", "deficit.end", de="Planimeter: FC", en="planimeter: FC")
        b.planimeter("P.deficit.start", "deficit.start", de="Planimeter: ODP", en="planimeter: ODP")
    proto = b.protocol()
    return Figure(proto, b.replay(proto))


def planimetered(fig: Figure, area: str) -> float:
    """A planimetered area of the figure in force units times r (as the tangential diagram measures its excess)."""
    g = fig.replay.givens
    return float(fig.replay[f"P.{area}"]) / (g["pressure_unit"] * g["r"])


def effective_work_checks(fig: Figure, model: Mapping[str, Any] | None = None) -> list[Check]:
    """The tangential-pressure figure's own checks, then Fig. 27's."""
    checks = tangential_checks(fig, model)
    R = fig.replay
    g = R.givens
    n = fig.params["parts"]
    unit = g["pressure_unit"]
    eta = g["efficiency"]
    ebf = planimetered(fig, "excess")
    # the planimeter reads an area to 1e-6 of it (its stated error); the two areas it compares
    plan = 2e-6 * abs(ebf) + 1e-12
    why_plan = "the planimeter's stated error (1e-6 of each area read)"
    scale = max(abs(R["M0"][1] - R["U0"][1]), g["r"])
    checks += [
        Check("LHM = EBF (friction a constant tangential force)", planimetered(fig, "effective"), ebf, plan,
              "the effective curve is the indicated one moved down by R: " + why_plan, "at·r"),
        Check("FCODP = EBF (the mean line's balance over a stroke)",
              planimetered(fig, "deficit.end") + planimetered(fig, "deficit.start"), ebf, 3.0 * plan + 1e-9,
              "areas above and below the mean line are equal: " + why_plan, "at·r"),
        Check("effective mean line at η·T_m", (R["EM0"][1] - R["U0"][1]) / unit,
              eta * (R["M0"][1] - R["U0"][1]) / unit, 50 * EUCLIDEAN_TOLERANCE * scale / unit,
              "fourth proportional to r, η·r and T_m: Euclidean", "at"),
        Check("friction R = (1 − η)·T_m", float(R["R.eff"]) / unit, (1.0 - eta) * (R["M0"][1] - R["U0"][1]) / unit,
              50 * EUCLIDEAN_TOLERANCE * scale / unit, "the compass between the two mean lines: Euclidean", "at"),
    ]
    for a, e, what in (("L.eff", "A1", "L under E"), ("M.eff", "A2", "M under F"), ("N", "A2", "N under F")):
        name = a if a != "N" else next(o for o, letter in _letters(fig).items() if letter == "N")
        checks.append(Check(f"{what} (abscissa)", R[name][0] - R[e][0], 0.0, 1e-7 * g["r"] * math.pi,
                            "the crossings of a curve and a line moved down together: the crossing solver's "
                            "1e-9 of the base" if a != "N" else "the perpendicular from F: Euclidean", "r"))
    top = max(range(1, n), key=lambda k: R[f"T{k}"][1])
    checks.append(Check("H under B (the tops)", R[f"eff{top}"][0] - R[f"T{top}"][0], 0.0, 50 * EUCLIDEAN_TOLERANCE * scale,
                        "the compass along the ordinate: Euclidean", "r"))
    return checks


def _letters(fig: Figure) -> dict[str, str]:
    return {name: letter for step in fig.protocol.steps for name, letter in step.labels}


def effective_work_wording(fig: Figure, lang: str) -> list[str]:
    """The tangential diagram's givens as Baumann writes them, and the efficiency."""
    eta = fig.replay.givens["efficiency"]
    return list(TANGENTIAL.wording(fig, lang)) + [
        (f"Wirkungsgrad η = {number(eta, lang)}" if lang == "de" else f"efficiency η = {number(eta, lang)}")]


def effective_work_plate(fig: Figure) -> dict:
    """Fig. 27 as a plate: Fig. 26's diagram with E, B, F for α₁, the top and α₂, the effective line below it with
    L, H, M, and N on the base."""
    plate = TANGENTIAL.plate(fig)
    R = fig.replay
    n = fig.params["parts"]
    span = abs(R[f"U{n}"][0] - R["U0"][0])
    d = 0.018 * span
    top = max(range(1, n), key=lambda k: R[f"T{k}"][1])
    letters = [(R[f"eff{top}"], "H", (0.0, -2.2))]
    # Fig. 26's α₁, α₂ (and their dashed ordinates) are Fig. 27's E and F, lettered at their points; its A, D and
    # the mean line's M, M give way to Fig. 27's letters (its M is the effective crossing)
    furniture = [f for f in plate["furniture"] if f.get("text") not in ("α₁", "α₂", "A", "D", "M")
                 and not (f.get("kind") == "stroke" and f.get("look") == "dashed thin")]
    furniture += [{"kind": "lettering", "at": (p[0] + dx * d, p[1] + dy * d), "text": t} for p, t, (dx, dy) in letters]
    looks = {**{k: v for k, v in plate["looks"].items() if k not in ("A1", "A2")}, "ecurve": "heavy",
             "emean": "medium", "N.eff": "dashed thin"}
    return {"looks": looks, "furniture": furniture}


def effective_work_form(replay: Any, params: Mapping[str, Any]) -> np.ndarray:
    """The build's choice over a sweep (:attr:`~construct.constructions.Construction.form`): the perpendicular from
    F to the base is struck through the farther of its ends
    (:meth:`~construct.kernel.composite.CompositeSteps.drop_perpendicular`), and which that is moves with the rod."""
    F, n = replay["A2"], params["parts"]
    return form_rows(F.distance(replay["U0"]) >= F.distance(replay[f"U{n}"]))


#: The plate: Fig. 26's diagram, the effective line and mean line, the areas EBF, LHM, FCODP, N.
PLATE = (r"tbase", r"tcurve", r"mean", r"excess", r"A[12]", r"U\d+", r"ecurve", r"emean", r"effective", r"[LM]\.eff",
         r"deficit\.\w+", r"eff\d+", r"N\.eff", r"N\.eff\.F")


def _validate(givens: Mapping[str, float]) -> None:
    TANGENTIAL.validator(givens)
    bounded("mechanical efficiency η", givens["efficiency"], MECHANICAL_EFFICIENCY)


EFFECTIVE_WORK = register(Construction(
    name="effective-work",
    title=Caption("Indizierte und effektive Arbeit: Reibung als konstanter Tangentialdruck",
                  "Indicated and effective work: friction as a constant tangential force"),
    source="seed 004 (Baumann 1902), Fig. 27",
    build=build_effective_work,
    checks=effective_work_checks,
    sweep_model=lambda g, params: model_summary(g, "baumann"),
    defaults={**{k: v for k, v in TANGENTIAL.defaults.items()
                 if k in ("rod_ratio", "parts", "method", "r", "kappa", "filling", "clearance", "admission",
                          "back_pressure", "compression", "pressure_unit")},
              "efficiency": EFFICIENCY},
    # Fig. 27 is a sketch over Fig. 26's diagram: nine parts (20°, seed 001's "9 oder 18 Teile") draw it, and
    # keep its player small
    book_params=({"rod_ratio": 5.0, "parts": 9, "kappa": 8.0},),
    structural=("parts", "method", "filling", "compression"),
    steady=("kappa",),
    form=effective_work_form,  # (the perpendicular from F through the farther end of the base: the rod moves them)
    cites=(Cite(BAUMANN_1902, "Fig. 27"),),
    wording=effective_work_wording,
    methods=TANGENTIAL.methods,
    plate=effective_work_plate,
    validator=_validate,
    derived=TANGENTIAL.derived,  # Fig. 26's c v^2/r follows κ and the rod, on replay and in a sweep (the live page)
    help={"efficiency": "effective-work: the mechanical efficiency η, effective over indicated work, 0.3 .. 1 "
                        "(default 0.85): the friction (1 - η) T_m as a constant tangential force (Fig. 27)"},
))
