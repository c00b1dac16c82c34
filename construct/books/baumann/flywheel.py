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

**Where his method is not self-consistent** (:func:`design` gives both his figures and the exact ones):

* he uses 1 + 0.06 x where his own quotient is meant: at x = v/5 (his kz = 5 v) for v = 17 and 29.5 m/s
  it is 1.2036 and 1.3538 against the quotient's 1.1862 and 1.3080;
* his rim: the derivation gives G1 = G_s/(1 + 0.0218 x) (the wheel's moment equals the one required), his
  closing summary and his list of rims G_total/(1 + 0.08075 x) with the total from 1 + 0.06 x -- two
  different rims (the first is the consistent one);
* ρ = 7/12 r1 halves the disc's mass, but a mass "concentrated" there does not carry the disc's moment:
  the disc's mass is spread evenly over r1/6 … r1 (b·r is constant), so its radius of gyration is
  k² = (1 − 1/216)/3 · 6/5 r1² = 215/540 r1² = 0.398 r1², not 49/144 = 0.340; the hub's ring
  (r1/12 … r1/6) has k² = 2.5/144 r1², not 3/144.  From his assumptions, without his roundings, the
  moment coefficient is 0.0247, not 0.0218, and the arms and hub 0.0795, not 0.08075.

The rim's own moment (his last paragraph): G1·D1² with D1 = (Da + Di)/2 stands for G1·(Da² + Di²)/2 = G1(D1² +
h²) (a rim of radial height h); he says this too little makes up for the too much of the disc counted from
the rim's inner edge out to its mean circle.  :func:`rim_moment_correction` computes both.

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
           "ARMS_HUB_PRINTED_ASSUMPTIONS", "design", "parse_fraction", "KZ_PER_V", "DISC_GYRATION", "HUB_GYRATION",
           "exact_wheel", "rim_moment_correction"]

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

#: k²/r1² of the disc of equal stress (b·r constant: its mass evenly spread over r1/6 .. r1): 215/540, where his
#: ρ² = (7/12)² = 49/144 only halves the mass.
DISC_GYRATION = (1.0 - 1.0 / 216.0) / 3.0 * 6.0 / 5.0
#: k²/r1² of the hub, a ring of even thickness from r1/12 to r1/6: ((1/6)² + (1/12)²)/2 = 2.5/144 (he takes 3/144).
HUB_GYRATION = ((1.0 / 6.0) ** 2 + (1.0 / 12.0) ** 2) / 2.0


def derived(*, gamma: float = GAMMA, g: float = G) -> dict[str, float]:
    """The coefficients from Baumann's stated assumptions, without his roundings (kz in kg/cm²).

    Keys: ``section`` (F / b1 r1 = ln 6), ``centroid`` (r0/r1), ``disc`` (G2'/(π r1² b1 γ) = 5/3),
    ``hub`` (G2''/(π r1² b1 γ) = 1/2), ``arms_hub`` (G2/(G1 v²/kz)), ``disc_coeff``, ``hub_coeff``
    (G2'/(G1 v²/kz), G2''/(G1 v²/kz)), ``rho`` (ρ/r1 = 7/12), ``moment`` (the 1 + m x coefficient m with
    his ρ and his 3/144 for the hub), ``total`` (first order: arms_hub − moment), ``moment_gyration`` (m with
    the radii of gyration, :data:`DISC_GYRATION` and :data:`HUB_GYRATION`: the moment the wheel has).

    >>> d = derived()
    >>> round(DISC_GYRATION, 4), round(d["moment"], 4), round(d["moment_gyration"], 4)
    (0.3981, 0.0212, 0.0247)
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
            "total": disc_c + hub_c - moment,
            "moment_gyration": disc_c * DISC_GYRATION + hub_c * HUB_GYRATION}


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
    * ``kz_rule``: "given" or "kz = 5 v";

    and where his method contradicts itself, the other side: ``total_quotient`` G_s(1 + 0.08075 x)/(1 + 0.0218 x)
    (his derivation, of which 1 + 0.06 x is the expansion), ``rim_by_moment`` G_s/(1 + 0.0218 x) (his
    derivation's rim), and ``exact_rim``, ``exact_arms_hub``, ``exact_total`` (:func:`exact_wheel`: his
    assumptions without his roundings, the arms' radius of gyration).

    His first worked case (G_s = 2130 kg, D_s = 3.2 m, n = 120): total 2650 kg printed.

    >>> d = design(rim_weight=2130.0, diameter=3.2, rpm=120.0)
    >>> round(d["rim_speed"], 2), round(d["total_weight"]), round(d["rim_of_wheel"]), round(d["arms_hub_weight"])
    (20.11, 2644, 1996, 648)
    >>> d = design(excess_work=1000.0, fluctuation=1 / 50, diameter=3.0, rpm=120.0, kz=100.0)
    >>> round(d["rim_weight"], 1), round(d["moment"], 1)    # G_s = g E/(v² δ); G_s D² = 3600 g E/(π² n² δ)
    (1380.5, 12424.5)
    """
    n = _in("FLYWHEEL_RPM", "rpm", rpm)
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
        # the rim the work asks for stays in the range a given rim weight must keep
        _in("FLYWHEEL_WEIGHT", f"rim weight G_s = g E/(v² δ) (E = {work:g} kg·m, v = {speed:.4g} m/s, δ = {delta:g})",
            gs)
    else:
        if fluctuation is not None:
            raise InvalidParameter("--fluctuation belongs to the excess work; with --rim-weight G_s it is not used")
        work, delta = None, None
        gs = _in("FLYWHEEL_WEIGHT", "rim weight G_s", rim_weight)
    x = speed * speed / stress
    total = gs * (1.0 + TOTAL * x)
    g1 = total / (1.0 + ARMS_HUB * x)
    exact = exact_wheel(gs, speed, stress)
    return {"excess_work": work, "fluctuation": delta, "rpm": n, "diameter": d, "rim_speed": speed, "kz": stress,
            "kz_rule": rule, "rim_weight": gs, "total_weight": total, "rim_of_wheel": g1,
            "arms_hub_weight": total - g1, "moment": gs * d * d,
            "total_quotient": total_weight(gs, speed, stress, exact=True),
            "rim_by_moment": gs / (1.0 + MOMENT * x),
            "exact_rim": exact["rim"], "exact_arms_hub": exact["arms_hub"], "exact_total": exact["total"]}


def exact_wheel(gs: float, v: float, kz: float) -> dict[str, float]:
    """The wheel from G_s by his assumptions without his roundings, consistent in itself: arms and hub
    a·G1·x (a = 0.0795 from 13/6 π, not his 2.2 π), the moment G1·D1²(1 + m x) with the disc's and hub's radii of
    gyration (m = 0.0247, not 0.0218) equal to the required G_s·D1²: G1 = G_s/(1 + m x), total G1(1 + a x).

    >>> w = exact_wheel(2130.0, 20.1, 100.5)
    >>> round(w["rim"]), round(w["arms_hub"]), round(w["total"]), round(w["moment_coefficient"], 5)
    (1938, 619, 2557, 0.02467)
    """
    d = derived()
    x = v * v / kz
    a, m = d["arms_hub"], d["moment_gyration"]
    rim = gs / (1.0 + m * x)
    return {"rim": rim, "arms_hub": rim * a * x, "total": rim * (1.0 + a * x), "arms_hub_coefficient": a,
            "moment_coefficient": m}


def rim_moment_correction(rim: float, diameter: float, height: float, arms_hub: float) -> dict[str, float]:
    """His last paragraph, worked out: the rim's moment G1·D1² stands for G1·(Da² + Di²)/2 = G1·(D1² + h²) (a
    rectangular rim of radial height h: Da = D1 + h, Di = D1 − h), too little by G1·h²; the disc of the arms,
    counted out to the rim's mean radius, holds too much: its part from the rim's inner edge (r1 − h/2) out, of
    weight G2'·(h/2)/(5/6 r1) near D1, adds its G·D² = ∫ (2r)² dG (about 0.6·G2'·(h/r1)·D1²).  Whether "dieses zu wenig gleicht das
    vorher gekannte zu viel hinreichend aus" (his words) is ``too_little`` against ``too_much`` (kg·m²).

    *arms_hub* is G2 (arms and hub); the disc's share G2' is (5/3)/(13/6) of it by his assumptions.

    >>> c = rim_moment_correction(2000.0, 3.2, 0.16, 600.0)
    >>> round(c["too_little"]), round(c["too_much"]), round(c["ratio"], 2)
    (51, 270, 0.19)
    """
    for name, value in (("rim weight", rim), ("diameter", diameter), ("rim height", height), ("arms and hub", arms_hub)):
        _positive(name, [value])
    if height >= diameter:
        raise InvalidParameter(f"the rim's radial height h = {height:g} m must be less than its mean diameter "
                               f"D1 = {diameter:g} m")
    r1 = diameter / 2.0
    disc = arms_hub * (5.0 / 3.0) / (13.0 / 6.0)
    too_little = rim * height * height
    inner = r1 - height / 2.0   # the rim's inner edge: the disc's weight per unit radius is G2'/(5/6 r1)
    too_much = disc / (5.0 / 6.0 * r1) * 4.0 * (r1 ** 3 - inner ** 3) / 3.0
    return {"rim_moment_mean": rim * diameter * diameter, "rim_moment_true": rim * (diameter ** 2 + height ** 2),
            "too_little": too_little, "too_much": too_much, "ratio": too_little / too_much}


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
