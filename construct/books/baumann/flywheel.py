"""The flywheel from the excess area: rim, arms and hub (seed 004, Baumann 1902, Fig. 28 and his two tables).

The excess area of the tangential-pressure diagram is the work A the
flywheel takes up while the crank runs ahead; with the degree of
irregularity δ = (v_max − v_min)/v_mean the rim (weight G_s, mean diameter
D_s, rim speed v = π D_s n/60) must satisfy A = (G_s/g)·v²·δ, i.e.

    G_s·D_s² = 3600 g A / (π² n² δ)     (kg, m; n in 1/min)

Baumann then adds arms and hub.  His assumptions (seed text): the arms
smeared into a disc of equal stress kz whose thickness grows as r1/r
inward from the rim's mean radius r1 to a hub radius r1/6; shaft radius
r1/12, hub length 4·b2 = 24·b1; cast iron γ = 7200 kg/m³, g = 9.81 m/s².
From them, exactly:

* disc section b1·r1·ln 6, centroid (5/6)r1/ln 6, weight G2' = (5/3)π r1² b1 γ
  (he writes 2·0.4655·1.79 ≈ 1.7);
* hub G2'' = π((r1/6)² − (r1/12)²)·24 b1 γ = 0.5 π r1² b1 γ (exact);
* b1 = G1 v²/(2π r1² g kz), so G2 = (G2' + G2'')... = c_arms·G1 v²/kz with
  c_arms = (5/3 + 1/2)/2 · γ/(g·10⁴) = 0.0795 (kz in kg/cm²); with his 2.2 π
  it is 1.1 γ/(g 10⁴) = 0.08073, printed 0.08075;
* moment: the disc's mass "concentrated" on the circle that halves its mass
  (ρ = 7/12 r1, so D'² = 49/144 D1²), the hub at D''² = 3/144 D1² (not
  derivable from the stated assumptions: the hub's bore and outside give
  2.5/144 by the same halving rule, 4/144 at its outside);
* total G_s(1 + 0.08075 x)/(1 + 0.0218 x) ≈ G_s(1 + 0.059 x) ≈ G_s(1 + 0.06 x),
  x = v²/kz: the first-order expansion.

>>> round(ARMS_HUB_PRINTED_ASSUMPTIONS, 6), round(derived()["arms_hub"], 5)
(0.080734, 0.07951)
>>> row = coefficient_rows([75.0], [15.0])[0]
>>> round(row["arms_hub"], 5), round(row["weight_for_moment"], 4)
(0.24225, 1.18)
"""

from __future__ import annotations

import math
from typing import Iterable, Sequence

from ...kernel.errors import InvalidParameter

__all__ = ["GAMMA", "G", "book_chain", "ARMS_HUB", "MOMENT", "TOTAL", "derived", "coefficient_rows", "BOOK_KZ", "BOOK_V",
           "required_moment", "moment_from_excess", "rim_speed", "total_weight", "WORKED", "worked_totals",
           "ARMS_HUB_PRINTED_ASSUMPTIONS", "design", "parse_fraction", "KZ_PER_V"]

GAMMA = 7200.0  #: kg/m³, cast iron (seed 004)
G = 9.81        #: m/s² (seed 004)

#: Baumann's printed coefficients (kz in kg/cm²).
ARMS_HUB = 0.08075
MOMENT = 0.0218
TOTAL = 0.06

#: The kz and v of his two tables (kz in kg/cm², v in m/s): he pairs them, kz = 5 v.
BOOK_KZ = (75.0, 85.0, 95.0, 100.0, 105.0, 110.0, 115.0, 120.0, 125.0, 130.0, 135.0, 140.0, 145.0, 150.0)
BOOK_V = (15.0, 17.0, 19.0, 20.0, 21.0, 22.0, 23.0, 24.0, 25.0, 26.0, 27.0, 28.0, 29.0, 30.0)

#: 1.1 γ/(g·10⁴): his 2.2π for arms and hub, the rest exact.
ARMS_HUB_PRINTED_ASSUMPTIONS = 1.1 * GAMMA / (G * 1e4)


def derived(*, gamma: float = GAMMA, g: float = G) -> dict[str, float]:
    """The coefficients from Baumann's stated assumptions, without his roundings (kz in kg/cm²).

    Keys: ``section`` (F / b1 r1 = ln 6), ``centroid`` (r0/r1), ``disc`` (G2'/(π r1² b1 γ) = 5/3),
    ``hub`` (G2''/(π r1² b1 γ) = 1/2), ``arms_hub`` (G2/(G1 v²/kz)), ``disc_coeff``, ``hub_coeff``
    (G2'/(G1 v²/kz), G2''/(G1 v²/kz)), ``rho`` (ρ/r1 = 7/12), ``moment`` (the 1 + m x coefficient m with
    his 3/144 for the hub), ``total`` (first order: arms_hub − moment), ``total_exact_at`` not given here.
    """
    k = gamma / (g * 1e4)   # γ/(g kz) with kz in kg/cm² -> per kg/m²
    section = math.log(6.0)
    centroid = (5.0 / 6.0) / section
    disc = 2.0 * centroid * section          # 2 π r0 F γ / (π r1² b1 γ)
    hub = ((1.0 / 6.0) ** 2 - (1.0 / 12.0) ** 2) * 24.0
    # b1 = G1 v² / (2 π r1² g kz): a weight c·π r1² b1 γ is (c/2)·G1 v² γ/(g kz)
    disc_c, hub_c = disc / 2.0 * k, hub / 2.0 * k
    rho = 7.0 / 12.0
    moment = disc_c * rho ** 2 + hub_c * 3.0 / 144.0
    return {"section": section, "centroid": centroid, "disc": disc, "hub": hub, "arms_hub": disc_c + hub_c,
            "disc_coeff": disc_c, "hub_coeff": hub_c, "rho": rho, "moment": moment,
            "total": disc_c + hub_c - moment}


def book_chain() -> dict[str, float]:
    """His chain with his own roundings: 1.79, 0.4655, 1.7, 0.5, 2.2; G2' and G2'' coefficients as he forms them."""
    k = GAMMA / (G * 1e4)
    return {"centroid": (5.0 / 6.0) / 1.79, "disc": 2.0 * 0.4655 * 1.79, "arms_hub": 1.1 * k,
            "disc_coeff": 1.7 / 2.0 * k, "hub_coeff": 0.5 / 2.0 * k,
            "moment": 0.0625 * 49.0 / 144.0 + 0.01825 * 3.0 / 144.0,
            "total": ARMS_HUB - MOMENT}


def _positive(name: str, values: Iterable[float]) -> list[float]:
    out = []
    for v in values:
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise InvalidParameter(f"{name} must be finite and positive, got {v!r}")
        out.append(float(v))
    return out


def coefficient_rows(kz: Sequence[float] | None = None, v: Sequence[float] | None = None) -> list[dict[str, float]]:
    """Baumann's two tables for paired kz and v (his by default; one of a pair may be a single value).

    Columns: kz, v, arms_hub = 0.08075 v²/kz, total_weight = 1 + 0.08075 v²/kz,
    moment = 1 + 0.0218 v²/kz, weight_for_moment = 1 + 0.06 v²/kz.
    """
    kzs = _positive("kz", BOOK_KZ if kz is None else kz)
    vs = _positive("v", BOOK_V if v is None else v)
    if len(kzs) == 1 and len(vs) > 1:
        kzs = kzs * len(vs)
    if len(vs) == 1 and len(kzs) > 1:
        vs = vs * len(kzs)
    if len(kzs) != len(vs):
        raise InvalidParameter(f"give as many kz as v (or one of either): {len(kzs)} kz, {len(vs)} v")
    rows = []
    for a, b in zip(kzs, vs):
        x = b * b / a
        rows.append({"kz": a, "v": b, "arms_hub": ARMS_HUB * x, "total_weight": 1.0 + ARMS_HUB * x,
                     "moment": 1.0 + MOMENT * x, "weight_for_moment": 1.0 + TOTAL * x})
    return rows


def rim_speed(diameter: float, rpm: float) -> float:
    """v = π D n / 60 (m/s)."""
    return math.pi * diameter * rpm / 60.0


def required_moment(excess_work: float, rpm: float, irregularity: float, *, g: float = G) -> float:
    """G_s·D_s² (kg m²) that takes up the excess work (kg m) with the degree of irregularity δ.

    A = (G/g) v² δ with v = π D n/60  =>  G D² = 3600 g A / (π² n² δ).

    >>> round(required_moment(1000.0, 120.0, 1 / 50), 1)
    12424.5
    """
    for name, val in (("excess work", excess_work), ("rpm", rpm), ("irregularity", irregularity)):
        _positive(name, [val])
    return 3600.0 * g * excess_work / (math.pi ** 2 * rpm ** 2 * irregularity)


def moment_from_excess(excess: float, *, piston_area: float, crank_radius: float, rpm: float,
                       irregularity: float) -> float:
    """G_s·D_s² from an excess area measured in at × r (the tangential diagram's units, r the crank radius).

    The work is excess · F · r with F the piston area in cm² (1 at = 1 kg/cm²) and r in m.

    >>> round(moment_from_excess(1.0, piston_area=1000.0, crank_radius=0.4, rpm=120.0, irregularity=1 / 50), 1)
    4969.8
    """
    return required_moment(excess * piston_area * crank_radius, rpm, irregularity)


def total_weight(gs: float, v: float, kz: float, *, exact: bool = False) -> float:
    """G_total from the rim weight G_s: ≈ G_s(1 + 0.06 v²/kz), or his unexpanded quotient."""
    x = v * v / kz
    return gs * ((1.0 + ARMS_HUB * x) / (1.0 + MOMENT * x) if exact else 1.0 + TOTAL * x)


#: His worked cases (Gs kg, Ds m, n 1/min, v printed m/s, "Richtige Werte" printed total kg).
WORKED = (
    (2130.0, 3.2, 120.0), (11400.0, 5.4, 60.0), (17500.0, 4.5, 105.0),
    (19100.0, 4.5, 75.0), (12900.0, 4.5, 105.0), (11600.0, 4.5, 75.0),
)


def worked_totals(kz_per_v: float = 5.0) -> list[dict[str, float]]:
    """His worked totals recomputed: v = π D n/60 and G_total = G_s(1 + 0.06 v²/kz) with his pairing kz = 5 v.

    Also the rim weight as his closing summary says to find it, G1 = G_total/(1 + 0.08075 v²/kz) (his
    "Kranzgewichte" list follows this, not G_s/(1 + 0.0218 v²/kz) of the moment derivation, which is
    ``rim_by_moment``), and arms and hub G_total − G1.
    """
    rows = []
    for gs, d, n in WORKED:
        v = rim_speed(d, n)
        kz = kz_per_v * v
        total = total_weight(gs, v, kz)
        g1 = total / (1.0 + ARMS_HUB * v * v / kz)
        rows.append({"Gs": gs, "Ds": d, "n": n, "v": v, "kz": kz, "total": total,
                     "total_quotient": total_weight(gs, v, kz, exact=True), "rim": g1, "arms_hub": total - g1,
                     "rim_by_moment": gs / (1.0 + MOMENT * v * v / kz)})
    return rows


#: kz = 5 v (kz in kg/cm², v in m/s): the pairing of both his tables and of his worked totals.
KZ_PER_V = 5.0


def _in(domain_name: str, name: str, value: float) -> float:
    from ...constructions import domain

    return float(getattr(domain, domain_name).check(name, value))


def design(*, rpm: float, diameter: float | None = None, v: float | None = None, kz: float | None = None,
           excess_work: float | None = None, fluctuation: float | None = None,
           rim_weight: float | None = None) -> dict[str, float | str]:
    """The flywheel by Baumann's procedure, from the excess work (or from his G_s) to the total weight.

    Give the excess work E (kg·m) with the degree of irregularity δ, or the rim weight G_s itself;
    the rim's mean diameter D_s (m) or its speed v (m/s); the revolutions n (1/min); the allowed
    stress kz (kg/cm², default his pairing kz = 5 v).  Returns (kg, m):

    * ``excess_work`` E (None when G_s was given), ``rim_speed`` v = π D n/60, ``diameter`` D = 60 v/(π n), ``kz``;
    * ``rim_weight`` G_s = g E/(v² δ), from E = (G_s/g)·v²·δ with g = 9.81: the rim that alone
      would take up E;
    * ``total_weight`` G_s(1 + 0.06 v²/kz) (his table 2, the first-order form of his quotient);
    * ``rim_of_wheel`` G1 = G_total/(1 + 0.08075 v²/kz) and ``arms_hub_weight`` G_total − G1: the split
      his list "Kranzgewichte (Arm- und Nabengewichte)" prints (the arms and hub carry part of the moment,
      so the wheel's own rim is lighter than G_s);
    * ``moment`` G_s·D² (kg m²), the Schwungmoment the diagram requires;
    * ``kz_rule``: "given" or "kz = 5 v".

    His first worked case (G_s = 2130 kg, D_s = 3.2 m, n = 120): total 2650 kg printed.

    >>> d = design(rim_weight=2130.0, diameter=3.2, rpm=120.0)
    >>> round(d["rim_speed"], 2), round(d["total_weight"]), round(d["rim_of_wheel"]), round(d["arms_hub_weight"])
    (20.11, 2644, 1996, 648)
    >>> d = design(excess_work=1000.0, fluctuation=1 / 50, diameter=3.0, rpm=120.0, kz=100.0)
    >>> round(d["rim_weight"], 1), round(d["moment"], 1)    # G_s = g E/(v² δ); G_s D² = 3600 g E/(π² n² δ)
    (1380.5, 12424.5)
    """
    n = _in("RPM", "rpm", rpm)
    if (diameter is None) == (v is None):
        raise InvalidParameter("give the rim's mean diameter D (--diameter) or its speed v (--v), one of them")
    if diameter is not None:
        d = _in("FLYWHEEL_DIAMETER", "diameter D", diameter)
        speed = rim_speed(d, n)
    else:
        speed = _in("RIM_SPEED", "rim speed v", v)
        d = 60.0 * speed / (math.pi * n)
    _in("RIM_SPEED", "rim speed v", speed)
    if kz is None:
        stress, rule = KZ_PER_V * speed, "5 v, Baumann's pairing"
    else:
        stress, rule = _in("FLYWHEEL_KZ", "kz", kz), "given"
    if (excess_work is None) == (rim_weight is None):
        raise InvalidParameter("give the excess work E (--excess-work, with --fluctuation) or the rim weight G_s "
                               "(--rim-weight), one of them")
    if excess_work is not None:
        if fluctuation is None:
            raise InvalidParameter("the excess work needs the degree of irregularity δ (--fluctuation, e.g. 1/80)")
        work = _in("EXCESS_WORK", "excess work E", excess_work)
        delta = _in("IRREGULARITY", "degree of irregularity δ", fluctuation)
        gs = G * work / (speed * speed * delta)
    else:
        if fluctuation is not None:
            raise InvalidParameter("--fluctuation belongs to the excess work; with --rim-weight G_s it is not used")
        work, delta = None, None
        gs = _in("WEIGHT", "rim weight G_s", rim_weight)
    x = speed * speed / stress
    total = gs * (1.0 + TOTAL * x)
    g1 = total / (1.0 + ARMS_HUB * x)
    return {"excess_work": work, "fluctuation": delta, "rpm": n, "diameter": d, "rim_speed": speed, "kz": stress,
            "kz_rule": rule, "rim_weight": gs, "total_weight": total, "rim_of_wheel": g1,
            "arms_hub_weight": total - g1, "moment": gs * d * d, "total_quotient": total_weight(gs, speed, stress,
                                                                                                exact=True)}


def parse_fraction(text: str) -> float:
    """A number or a fraction such as the books write δ: ``1/80`` or ``0.0125``.

    >>> parse_fraction("1/80"), parse_fraction("0.02")
    (0.0125, 0.02)
    """
    num, sep, den = text.partition("/")
    try:
        value = float(num) / float(den) if sep else float(text)
    except (ValueError, ZeroDivisionError):
        raise InvalidParameter(f"not a number or fraction: {text!r}") from None
    if not math.isfinite(value):
        raise InvalidParameter(f"not a finite number: {text!r}")
    return value
