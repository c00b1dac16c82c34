"""Building two cranks at 90°: the crank circle over a whole turn, the pistons, the work line, the speed radii and the French curve; the plate."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping, Sequence

import numpy as np

from ...kernel.errors import InvalidParameter
from ...kernel.division import check_parts, divide_semicircle
from ...kernel.geometry import Point
from ...kernel.instruments import Builder
from ...kernel.proportional import ProportionalAngle, carry_across, fourth_proportional, scale_line
from ...kernel.protocol import Provenance
from .. import Figure, bounded, positive, rod_ratio_param
from ..domain import DRAWN_LENGTH, FLUCTUATION, SPEED_GAIN
from ..crank import build_frame, rod_arcs
from .analytic import (KOCHANSKI_ERROR, drive_sign, kochanski_angle_error, max_magnification, quadrant_extremes,
                       start_angle)

# --------------------------------------------------------------------------
# The closed French curve through the speed points (op ``smooth_loop``, kernel/closed_curves.py).
# --------------------------------------------------------------------------


def closed_curve(b: Builder, name: str, points: Sequence[str], *, de: str, en: str, role: str = "result") -> str:
    """Record the drawing of a closed smooth curve through *points* (in order round the figure)."""
    b.record("curve", "smooth_loop", tuple(points), (name,), {"points": len(points)}, de, en, role=role)
    return name


# --------------------------------------------------------------------------
# The construction.
# --------------------------------------------------------------------------

_FWD = (1.0, 0.0)
_SUB = "₀₁₂₃₄₅₆₇₈₉"


@dataclass(frozen=True)
class _Part:
    """The object names of one crank circle with its diagram."""

    tag: str            # "" for the circle about O, "i" for the infinite rod beside it
    infinite: bool
    C: str
    D0: str
    D1: str
    circle: str
    crank_points: tuple[str, ...]    # index 0..2N-1 round the whole circle
    pistons: tuple[str, ...]         # piston position for index 0..2N-1
    W0: str = ""
    ends: tuple[str, ...] = ()       # E_j: end of the work stepped on, j = 0..2N
    means: tuple[str, ...] = ()      # M_j: mean-work marks (r/g behind; for pumps r/g ahead), j = 0..2N
    radii: tuple[str, ...] = ()      # Z_j: speed points, j = 0..2N-1


def _givens(r: Any, rod_ratio: Any, fluctuation: Any, magnify: Any, sense: Any = 1.0) -> dict[str, float]:
    if np.ndim(sense) or sense not in (1.0, -1.0):
        raise InvalidParameter(f"sense must be 1 (the rods drive the shaft) or -1 (the shaft drives pumps), "
                               f"got {sense!r}")
    g = {"r": bounded("crank radius r", r, DRAWN_LENGTH), "rod_ratio": rod_ratio_param(rod_ratio),
         "fluctuation": bounded("fluctuation Qr/((m1+m2) v1^2)", fluctuation, FLUCTUATION),
         "magnify": positive("magnification of the speed deviations", magnify), "sense": float(sense)}
    SPEED_GAIN.check("magnify x fluctuation", g["magnify"] * g["fluctuation"])
    return g


def validate_two_cranks(givens: Mapping[str, Any]) -> None:
    """The givens' domain; a sweep's (arrays) in one pass, the message naming its first set outside.

    The given ``sense`` is +1 when the rods drive the shaft, −1 when the shaft drives pumps (a protocol from
    before the pump drive has none: its rods drive the shaft).
    """
    g = _givens(givens["r"], givens["rod_ratio"], givens["fluctuation"], givens["magnify"], givens.get("sense", 1.0))
    limit = max_magnification(g["rod_ratio"])
    gain = g["fluctuation"] * g["magnify"]
    outside = np.flatnonzero(np.atleast_1d(gain >= limit))
    if outside.size:
        i = int(outside[0])
        at = lambda v: float(np.asarray(v).flat[i]) if np.ndim(v) else v  # noqa: E731  (set i of a sweep)
        gain_i, ratio_i, limit_i = at(gain), at(g["rod_ratio"]), at(limit)
        raise InvalidParameter(
            f"fluctuation x magnify = {gain_i:.6g} makes a speed radius r ± g*e vanish "
            f"for L/r = {ratio_i:.6g} (e falls to {-1.0 / limit_i:.4g} Q r); keep --magnify times --fluctuation "
            f"below {limit_i:.4g}")


#: Magnifications a draftsman would pick for the speed deviations (largest first).
NICE_MAGNIFICATIONS = (8.0, 5.0, 4.0, 2.0, 1.0, 0.5, 0.25, 0.1)


def derived_givens(g: Mapping[str, Any], params: Mapping[str, Any]) -> dict[str, Any]:
    """The givens that follow from the others: a magnification the figure chose itself (params "magnify" is
    "auto") is chosen again for the rod (:func:`auto_magnification`: 8 at L/r = 5, 5 at 3, 4 at 2), as a fresh
    build at that rod chooses it; one the user gave stays.  Arrays (a sweep's) give arrays.

    >>> derived_givens({"rod_ratio": 3.0, "fluctuation": 0.25, "magnify": 8.0}, {"magnify": "auto"})["magnify"]
    5.0
    >>> derived_givens({"rod_ratio": 3.0, "fluctuation": 0.25, "magnify": 2.0}, {})["magnify"]
    2.0
    """
    out = dict(g)
    if params.get("magnify") == "auto" and "rod_ratio" in out:
        out["magnify"] = auto_magnification(out["rod_ratio"], out["fluctuation"])
    return out


def auto_magnification(rod_ratio: Any, fluctuation: float) -> Any:
    """The largest of :data:`NICE_MAGNIFICATIONS` that keeps every speed radius above 0.4 r.

    For an array of rod ratios (a sweep), an array of magnifications, in one pass.

    >>> auto_magnification(5.0, 0.25), auto_magnification(2.0, 0.25), auto_magnification(1.1, 0.25)
    (8.0, 4.0, 1.0)
    >>> auto_magnification(np.array([5.0, 2.0, 1.1]), 0.25).tolist()
    [8.0, 4.0, 1.0]
    """
    if rod_ratio is None or np.ndim(rod_ratio) == 0:
        e_min = min(q["e_min"] for q in quadrant_extremes(rod_ratio, samples=400))
        for m in NICE_MAGNIFICATIONS:
            if fluctuation * m * max(-e_min, 0.0) <= 0.6:
                return m
        return NICE_MAGNIFICATIONS[-1] * 0.6 / (fluctuation * -e_min) / 1.01
    e_min = np.min([q["e_min"] for q in quadrant_extremes(rod_ratio, samples=400)], axis=0)
    out = NICE_MAGNIFICATIONS[-1] * 0.6 / (fluctuation * -e_min) / 1.01
    for m in NICE_MAGNIFICATIONS[::-1]:  # the largest that fits is written last
        out = np.where(fluctuation * m * np.maximum(-e_min, 0.0) <= 0.6, m, out)
    return out


def _check_parts(parts: Any, method: str) -> str:
    used = check_parts(parts, method)
    if parts % 2:
        raise InvalidParameter(f"two cranks at 90 degrees need an even number of parts of the semicircle "
                               f"(90 degrees must be a division point), got {parts}")
    return used


def _mirror_points(b: Builder, tag: str, C: str, D0: str, D1: str, circle: str, upper: Sequence[str]) -> list[str]:
    """The lower half: each point's mirror image, found with a circle about the nearer dead centre."""
    n = len(upper) - 1
    lower = []
    with b.group("lower half: mirror images of the division points",
                 "untere Hälfte: Spiegelbilder der Teilpunkte"):
        for k in range(1, n):
            dc = D0 if 2 * k <= n else D1
            kc = b.circle_through(f"{tag}mir{k}.k", dc, upper[k], de=f"Kreis um den Totpunkt durch {k}",
                                  en=f"circle about the dead centre through point {k}")
            lower.append(b.intersect(f"{tag}Q{k}", kc, circle, rule=("right", D0, D1),
                                     de=f"Spiegelpunkt von {k}: Kurbelstellung {2 * n - k}",
                                     en=f"mirror image of point {k}: crank position {2 * n - k}"))
    return lower


def _copied_points(b: Builder, tag: str, C: str, D0: str, D1: str, circle: str,
                   source: Sequence[str], src_D0: str, src_D1: str) -> tuple[list[str], list[str]]:
    """The division carried to a second circle of the same radius: each chord from the nearer dead centre.

    The circle about the dead centre with the chord cuts the second circle in
    the point and its mirror image at once.
    """
    n = len(source) - 1
    upper, lower = [D0], []
    with b.group("division carried over with the compass", "Teilung mit dem Zirkel übertragen"):
        for k in range(1, n):
            near, src = (D0, src_D0) if 2 * k <= n else (D1, src_D1)
            kc = b.circle_segment(f"{tag}cp{k}.k", near, src, source[k], de=f"Sehne zu Punkt {k} übertragen",
                                  en=f"chord to point {k} carried over")
            p, q = b.intersect((f"{tag}P{k}", f"{tag}Q{k}"), kc, circle, rule=("left", D0, D1),
                               de=f"Kurbelstellungen {k} und {2 * n - k}", en=f"crank positions {k} and {2 * n - k}")
            upper.append(p)
            lower.append(q)
    return upper + [D1], lower


def _ordinates(b: Builder, tag: str, axis: str, upper: Sequence[str], lower: Sequence[str]) -> list[str]:
    """Infinite rod: the chord from a point to its mirror image cuts the stroke line at the piston."""
    n = len(upper) - 1
    feet = [upper[0]]
    with b.group("piston positions for the infinite rod (ordinates)",
                 "Kolbenstellungen bei unendlicher Stange (Ordinaten)"):
        for k in range(1, n):
            o = b.line(f"{tag}ord{k}", upper[k], lower[k - 1], de=f"Ordinate durch {k}", en=f"ordinate through {k}")
            feet.append(b.intersect(f"{tag}Y{k}", o, axis, rule=("only",), role="result",
                                    de=f"Kolbenstellung Y{k}", en=f"piston position Y{k}"))
    return feet + [upper[n]]


def _whole_circle(upper: Sequence[str], lower: Sequence[str], pistons_upper: Sequence[str]):
    """Crank points and piston positions for indices 0..2N-1 (lower index 2N-k mirrors k)."""
    n = len(upper) - 1
    points = list(upper) + [lower[k - 1] for k in range(n - 1, 0, -1)]
    pistons = list(pistons_upper) + [pistons_upper[k] for k in range(n - 1, 0, -1)]
    return tuple(points), tuple(pistons)


@dataclass(frozen=True)
class _Speed:
    angle: ProportionalAngle
    one: Any      # Scale at distance r
    gain: Any     # Scale at distance g r
    lead: str     # Length r/g


def _speed_angle(b: Builder, S_at: tuple[float, float]) -> _Speed:
    """The proportional angle with scale lines at r and g·r, and r/g read off it.

    Two given points set the side of W0 the mean-work marks start on: behind it when the rods drive the
    shaft (M_j E_j = r/g + e), ahead of it when the shaft drives pumps (E_j M_j = r/g − e); the given
    ``sense`` (+1, −1) places the second point.
    """
    with b.group("which side of W0 the mean work starts", "auf welcher Seite von W0 die mittlere Arbeit beginnt"):
        b.given_point("lead.o", 0.0, 0.0, de="Bezugspunkt der Richtung", en="reference point of the direction",
                      label="")
        b.given_point("lead.d", -1.0, 0.0, unit="sense", de="Richtung: rückwärts beim Antrieb durch die Stangen, "
                      "vorwärts beim Pumpenantrieb", en="direction: backwards when the rods drive, forwards when "
                      "the shaft drives pumps", label="")
    with b.group("proportional angle for the speed scale", "Proportionswinkel für den Geschwindigkeitsmaßstab"):
        S = b.given_point("S", S_at[0], S_at[1], unit="r", de="Scheitel S des Proportionswinkels",
                          en="vertex S of the proportional angle", label="S")
        leg = b.given_line("leg", S, angle_deg=0.0, de="Schenkel des Proportionswinkels",
                           en="leg of the proportional angle")
        b.given_length("gr", product=("magnify", "fluctuation", "r"),
                       de="g·r = G·k·r (Vergrößerung G mal Qr/((m1+m2)v1²))",
                       en="g r = G k r (magnification G times Qr/((m1+m2)v1^2))")
        ang = ProportionalAngle(S, leg)
        side = ("toward", S, None, 1.0, 0.0)
        one = scale_line(b, ang, "sr", length="r", toward=side)
        gain = scale_line(b, ang, "sg", length="gr", toward=side)
        k = b.circle_radius("sg.kR", gain.origin, "r", de="r auf der Maßlinie g·r", en="r on the scale line g r")
        R = b.intersect("sg.R", gain.line, k, rule=("toward", S, None, 0.0, -1.0))
        Rr = carry_across(b, ang, "sr.R", R, one, de="r/g auf der Maßlinie r", en="r/g on the scale line r")
        lead = b.length_of("lead", one.origin, Rr, de="Zirkel auf r/g", en="compass set to r/g")
    return _Speed(ang, one, gain, lead)


def _work(b: Builder, part: _Part, speed: _Speed, W_at: tuple[float, float], n: int, mstep: str,
          start: int = 0) -> _Part:
    """Both pistons' paths stepped on along the work line; the mean-work marks beside them."""
    tag = part.tag
    m = 2 * n
    half = n // 2
    with b.group(f"work of the rods and mean work{' (infinite rod)' if part.infinite else ''}",
                 f"Arbeit der Stangen und mittlere Arbeit{' (unendliche Stange)' if part.infinite else ''}"):
        # one stage the student watches grow: the work line keeps its marks until every crank position is
        # stepped on (a finished group collapses, and each position alone would take the line's marks with it)
        with b.group("the work line: both pistons' paths and the mean work stepped on",
                     "Arbeitslinie: Wege beider Kolben und mittlere Arbeit abgetragen"):
            # the second diagram's work line (the infinite rod beside the finite one) starts at W0′: two
            # points lettered alike would send the student to the wrong line
            W0 = b.given_point(f"{tag}W0", W_at[0], W_at[1], unit="r", de="Anfang W0 der Arbeitslinie",
                               en="start W0 of the work line", label="W₀′" if tag else "W₀")
            wl = b.given_line(f"{tag}work", W0, angle_deg=0.0, de="Arbeitslinie", en="work line")
            back = b.circle_radius(f"{tag}M0.k", W0, speed.lead, de="r/g von W0", en="r/g from W0")
            means = [b.intersect(f"{tag}M0", wl, back, rule=("toward", "lead.o", "lead.d"),
                                 de="Anfang der mittleren Arbeit, r/g vor W0 (beim Pumpenantrieb hinter W0)",
                                 en="start of the mean work, r/g before W0 (after it when the shaft drives pumps)")]
            ends = [W0]
            for j in range(1, m + 1):
                with b.group(f"crank position {j}: work stepped on", f"Kurbelstellung {j}: Arbeit abgetragen"):
                    # *start* is the first crank's starting index (N: § 146's B1, the crank-end dead centre)
                    a1, c1 = part.pistons[(start + j - 1) % m], part.pistons[(start + j) % m]
                    a2, c2 = part.pistons[(start + j - 1 + half) % m], part.pistons[(start + j + half) % m]
                    k1 = b.circle_segment(f"{tag}U{j}.k", ends[-1], a1, c1, de=f"Weg des ersten Kolbens, Schritt {j}",
                                          en=f"path of the first piston, step {j}")
                    # captions in the figure's letters: U, E, M as the text names them, whichever diagram
                    U = b.intersect(f"{tag}U{j}", wl, k1, rule=("toward", W0, None) + _FWD,
                                    de=f"U{j}: Weg des ersten Kolbens auf der Arbeitslinie",
                                    en=f"U{j}: the first piston's path along the work line")
                    k2 = b.circle_segment(f"{tag}E{j}.k", U, a2, c2, de=f"Weg des zweiten Kolbens, Schritt {j}",
                                          en=f"path of the second piston, step {j}")
                    ends.append(b.intersect(f"{tag}E{j}", wl, k2, rule=("toward", W0, None) + _FWD,
                                            de=f"E{j}: Arbeit beider Stangen bis Stellung {j}",
                                            en=f"E{j}: work of both rods up to position {j}"))
                    means.append(b.step_off(f"{tag}M{j}", wl, means[-1], mstep, rule=("toward", W0, None) + _FWD,
                                            de=f"M{j}: mittlere Arbeit (4/π)·r·α, um 4r/N weiter",
                                            en=f"M{j}: mean work (4/pi) r alpha, 4r/N further"))
    return _Part(**{**part.__dict__, "W0": W0, "ends": tuple(ends), "means": tuple(means)})


def _radii(b: Builder, part: _Part, speed: _Speed, n: int, start: int = 0) -> _Part:
    """For each crank position: M_j E_j = r/g ± e carried to g·(r/g ± e) = r ± g e, laid on the crank position
    (+ when the rods drive the shaft, − when it drives pumps)."""
    tag = part.tag
    m = 2 * n
    radii = []
    pm = "+" if b.givens["sense"] > 0 else "−"
    with b.group(f"speeds as radii on the crank positions{' (infinite rod)' if part.infinite else ''}",
                 f"Geschwindigkeiten als Halbmesser auf den Kurbelstellungen{' (unendliche Stange)' if part.infinite else ''}"):
        for j in range(m):
            with b.group(f"speed at crank position {j}", f"Geschwindigkeit in Kurbelstellung {j}"):
                k = b.circle_segment(f"{tag}V{j}.k", speed.one.origin, part.means[j], part.ends[j],
                                     de=f"M{j}–E{j} auf die Maßlinie r", en=f"M{j}–E{j} onto the scale line r")
                V = b.intersect(f"{tag}V{j}", speed.one.line, k, rule=("toward", speed.angle.vertex, None, 0.0, -1.0),
                                de=f"V{j}: M{j}–E{j} auf der Maßlinie r", en=f"V{j}: M{j}–E{j} on the scale line r")
                Vg = carry_across(b, speed.angle, f"{tag}Vg{j}", V, speed.gain,
                                  de=f"auf die Maßlinie g·r: r {pm} g·e{j}", en=f"onto the scale line g r: r {pm} g e{j}")
                point = part.crank_points[(start + j) % m]
                ray = b.line(f"{tag}ray{j}", part.C, point, de=f"Kurbelstellung {j}", en=f"crank position {j}")
                kz = b.circle_segment(f"{tag}Z{j}.k", part.C, speed.gain.origin, Vg,
                                      de=f"Halbmesser r {pm} g·e{j} um den Wellenmittelpunkt",
                                      en=f"radius r {pm} g e{j} about the shaft centre")
                label = None
                if j % (n // 2) == 0:
                    label = "B" + _SUB[j // (n // 2) + 1]
                radii.append(b.intersect(f"{tag}Z{j}", ray, kz, rule=("toward", part.C, point),
                                         role="result", de=f"Geschwindigkeitspunkt {j}", en=f"speed point {j}",
                                         labels={f"{tag}Z{j}": label} if label else None))
        closed_curve(b, f"{tag}wave", radii, de="Wellenlinie der Geschwindigkeiten (Kurvenlineal)",
                     en="wave curve of the speeds (French curve)")
    return _Part(**{**part.__dict__, "radii": tuple(radii)})


def _kochanski(b: Builder, part: _Part, n: int) -> None:
    """π by Kochański's rectification; sin 2α = (4/π)² − 1 and the two extreme angles (§ 146)."""
    C, D0, D1, circle = part.C, part.D0, part.D1, part.circle
    top, bottom = part.crank_points[n // 2], part.crank_points[3 * n // 2]
    koch = Provenance("approximate", "Kochański's rectification (1685)", KOCHANSKI_ERROR)
    with b.group("half circle rectified (Kochański 1685)", "Halbkreis rektifiziert (Kochański 1685)"):
        d = b.line("K.d", bottom, top, de="senkrechter Durchmesser", en="vertical diameter")
        t = b.erect_perpendicular("K.t", top, d, bottom)
        k60 = b.circle_radius("K.k60", D0, "r", de="Kreis um den Totpunkt mit r", en="circle about the dead centre with r")
        E = b.intersect("K.E", k60, circle, rule=("left", D0, D1), de="Punkt bei 60°", en="the 60 degree point")
        g30 = b.line("K.g30", C, E, de="Strahl unter 30° zum Durchmesser", en="ray at 30 degrees to the diameter")
        start = b.intersect("K.C", g30, t, rule=("only",), de="auf der Tangente: r·tg 30°",
                            en="on the tangent: r tan 30 degrees")
        marks = [start]
        for i in (1, 2, 3):
            marks.append(b.step_off(f"K.{i}" if i < 3 else "K.D", t, marks[-1], "r", rule=("toward", C, None) + _FWD,
                                    de=f"r zum {i}. Mal abgetragen", en=f"r stepped off, {i} of 3"))
        b.set_label("K.D", "K")
        b.line("K.BD", bottom, "K.D", de="BK ≈ π·r (Kochański)", en="BK approximately pi r (Kochanski)", role="result")
        b.record("compass", "length_of", (bottom, "K.D"), ("BK",), {}, "Zirkel auf BK ≈ π·r",
                 "compass set to BK, approximately pi r", provenance=koch)
        b.length_of("2r", D0, D1, de="Zirkel auf den Hub 2r", en="compass set to the stroke 2r")
    with b.group("4/π and (4/π)² by fourth proportionals", "4/π und (4/π)² als vierte Proportionale"):
        o1, p1 = fourth_proportional(b, "K.t4", vertex=bottom, leg_point="K.D", a="BK", b_="2r", c="2r")
        b.length_of("4r/π", o1, p1, de="(4/π)·r = 2r·2r/(π r)", en="(4/pi) r = 2r 2r / (pi r)")
        o2, p2 = fourth_proportional(b, "K.u4", vertex=bottom, leg_point="K.D", a="r", b_="4r/π", c="4r/π")
        b.length_of("16r/π²", o2, p2, de="(4/π)²·r", en="(4/pi)^2 r")
    with b.group("sin 2α = (4/π)² − 1 and the extreme angles", "sin 2α = (4/π)² − 1 und die ausgezeichneten Winkel"):
        kh = b.circle_radius("K.kH", bottom, "16r/π²", de="(4/π)²·r vom tiefsten Punkt", en="(4/pi)^2 r from the lowest point")
        H = b.intersect("K.H", d, kh, rule=("toward", bottom, top), de="Höhe r·sin 2α über der Hubachse",
                        en="height r sin 2 alpha above the stroke line")
        hline = b.erect_perpendicular("K.h", H, d, bottom)
        b.intersect(("K.G1", "K.G2"), hline, circle, rule=("toward", C, D0), de="Punkte bei 2α₁ und 2α₂ = 180° − 2α₁",
                    en="points at 2α₁ and 2α₂ = 180° − 2α₁")
        err = kochanski_angle_error()
        angle_prov = Provenance("approximate", "Kochański's rectification (1685)", err)  # its error in the angle
        least_first = b.givens["sense"] > 0   # § 146: "Bei der Bewegung von Pumpen ... das Gegentheil"
        for i, (G, word) in enumerate((("K.G1", "kleinste" if least_first else "größte"),
                                       ("K.G2", "größte" if least_first else "kleinste")), start=1):
            name = f"K.M{i}"
            with b.group(f"arc {D0}{G} bisected: α{'₁₂'[i - 1]}", f"Bogen {D0}{G} halbiert: α{'₁₂'[i - 1]}"):
                ka = b.circle_through(b.fresh(f"{name}.k"), D0, G)
                kb = b.circle_through(b.fresh(f"{name}.k"), G, D0)
                s = b.intersect(b.fresh(f"{name}.S"), ka, kb, rule=("farther", C))
                w = b.line(b.fresh(f"{name}.w"), C, s)
                sub = "₁₂"[i - 1]
                b.record("intersect", "intersect", (w, circle), (name,), {"rule": ("nearer", s), "both": False},
                         f"M{i}: α{sub}, {word} Geschwindigkeit",
                         f"M{i}: α{sub}, the {'least' if word == 'kleinste' else 'greatest'} speed",
                         provenance=angle_prov, role="result")
    return None


def _label_extremes(b: Builder, part: _Part) -> None:
    """Rays to the extremes, lettered with the angles the construction gives (to the minute)."""
    least = 1 if b.givens["sense"] > 0 else 2   # pumps: the greatest speed at alpha1
    with b.group("extremes marked", "ausgezeichnete Stellungen bezeichnet"):
        for i in (1, 2):
            name = f"K.M{i}"
            a = angle_at(b[part.C], b[part.D0], b[name])
            minutes = round(math.degrees(a) * 60.0)
            ray = b.line(f"K.ray{i}", part.C, name, de=f"Strahl nach M{i}", en=f"ray to M{i}", role="result")
            b.intersect(f"K.W{i}", f"{part.tag}wave", ray, rule=("nearer", name), role="result",
                        de=f"M{i} auf der Wellenlinie: {'kleinste' if i == least else 'größte'} Geschwindigkeit",
                        en=f"M{i} on the wave curve: the {'least' if i == least else 'greatest'} speed",
                        labels={f"K.W{i}": f"M{_SUB[i]} {minutes // 60}°{minutes % 60}′"})


def angle_at(o: Point, d0: Point, p: Point) -> float:
    """The angle from O-D0 to O-P, counter-clockwise as the crank turns over the top (0..2pi)."""
    ux, uy = d0[0] - o[0], d0[1] - o[1]
    vx, vy = p[0] - o[0], p[1] - o[1]
    # The crank turns clockwise in the y-up plane (from the left dead centre over the top).
    a = math.atan2(-(ux * vy - uy * vx), ux * vx + uy * vy)
    return a % (2.0 * math.pi)


def _scale_bar(b: Builder, at: tuple[float, float]) -> None:
    with b.group("speed scale", "Geschwindigkeitsmaßstab"):
        A = b.given_point("sc.A", at[0], at[1], unit="r", de="Maßstab", en="scale", label="0")
        line = b.given_line("sc.g", A, angle_deg=0.0, role="result", de="Maßstablinie", en="scale line")
        B = b.step_off("sc.B", line, A, "r", rule=("toward", A, None) + _FWD, de="r ≙ v₁", en="r stands for v1")
        b.set_label(B, "v₁")
        b.given_length("tenth", product=("magnify", "r"), factor=0.1, de="G·r/10 ≙ 0,1·v₁", en="G r / 10 stands for 0.1 v1")
        C = b.step_off("sc.C", line, B, "tenth", rule=("toward", A, None) + _FWD, de="0,1·v₁ vergrößert",
                       en="0.1 v1, magnified")
        b.set_label(C, "1,1 v₁")


def build_two_cranks(*, rod_ratio: float, infinite_rod: bool, parts: int, method: str, r: float,
                     fluctuation: float, magnify: float, dead_centre: str = "crank-end",
                     drive: str = "engine") -> Figure:
    infinite_rod = bool(infinite_rod)
    start_angle(dead_centre)
    chosen = magnify is None  # the figure chooses it: again at every rod (derived_givens)
    sign = drive_sign(drive)
    if chosen:
        magnify = auto_magnification(rod_ratio_param(rod_ratio),
                                     bounded("fluctuation Qr/((m1+m2) v1^2)", fluctuation, FLUCTUATION))
    givens = _givens(r, rod_ratio, fluctuation, magnify, sign)
    validate_two_cranks(givens)
    used = _check_parts(parts, method)
    n = parts
    b = Builder("two-cranks", givens, {"parts": n, "method": used, "requested_method": method,
                                       "infinite_rod": infinite_rod, "dead_centre": dead_centre, "drive": drive,
                                       **({"magnify": "auto"} if chosen else {})})
    start = n if dead_centre == "crank-end" else 0
    f = build_frame(b)
    b.set_label(f["L"], "l")  # § 146 writes the rod length l (the title's r/l): its captions too
    upper = divide_semicircle(b, O=f["O"], D0=f["D0"], D1=f["D1"], circle=f["circle"], axis=f["axis"], n=n,
                              method=used)
    lower = _mirror_points(b, "", f["O"], f["D0"], f["D1"], f["circle"], upper)
    if infinite_rod:
        feet = _ordinates(b, "", f["axis"], upper, lower)
        pts, pistons = _whole_circle(upper, lower, feet)
        parts_ = [_Part("", True, f["O"], f["D0"], f["D1"], f["circle"], pts, pistons)]
        inf = parts_[0]
        b.set_label(f["O"], "O (l = ∞)")
    else:
        rod_arcs(b, f, upper)
        pts, pistons = _whole_circle(upper, lower, [f["D0"]] + [f"X{k}" for k in range(1, n)] + [f["D1"]])
        fin = _Part("", False, f["O"], f["D0"], f["D1"], f["circle"], pts, pistons)
        with b.group("second crank circle for the infinite rod", "zweiter Kurbelkreis für unendliche Stange"):
            O2 = b.given_point("O'", 3.2, 0.0, unit="r", de="Wellenmittelpunkt O' (unendliche Stange)",
                               en="shaft centre O' (infinite rod)", label="O′ (l = ∞)")
            k2 = b.circle_radius("crank'", O2, f["r"], de="Kurbelkreis um O'", en="crank circle about O'", role="result")
            A2 = b.intersect("iD0", f["axis"], k2, rule=("toward", O2, None, -1.0, 0.0), labels={"iD0": "A′"})
            B2 = b.intersect("iD1", f["axis"], k2, rule=("toward", O2, None, 1.0, 0.0))
        up2, low2 = _copied_points(b, "i", O2, A2, B2, k2, upper, f["D0"], f["D1"])
        feet = _ordinates(b, "i", f["axis"], up2, low2)
        pts2, pistons2 = _whole_circle(up2, low2, feet)
        inf = _Part("i", True, O2, A2, B2, k2, pts2, pistons2)
        parts_ = [fin, inf]
    speed = _speed_angle(b, (-3.0, -3.3))
    with b.group("mean work per step: the stroke in N/2 parts", "mittlere Arbeit je Schritt: Hub in N/2 Teile"):
        if n // 2 >= 2:
            t1 = b.divide_segment("T", f["D0"], f["D1"], n // 2, line=f["axis"], only=[1])[0]
        else:
            t1 = f["D1"]
        b.length_of("mstep", f["D0"], t1, de="Zirkel auf 4r/N", en="compass set to 4r/N")
    built = []
    for i, part in enumerate(parts_):
        part = _work(b, part, speed, (-1.6, -1.6 - 0.5 * i), n, "mstep", start)
        built.append(_radii(b, part, speed, n, start))
    _kochanski(b, inf, n)
    _label_extremes(b, inf)
    _scale_bar(b, (-1.2 if infinite_rod else 2.0, -1.55 if infinite_rod else 1.55))
    for part in built:
        for j in range(2 * n + 1):
            if sign * _ahead(b, part.means[j], part.ends[j]) <= 0.0:
                raise InvalidParameter(f"speed radius at crank position {j} would not be positive; "
                                       f"lower --magnify or the fluctuation")
    b.params["plate"] = _plate_patterns(infinite_rod, n)
    proto = b.protocol()
    return Figure(proto, b.replay(proto, givens))


def _ahead(b: Builder, a: str, c: str) -> float:
    """How far c lies ahead of a along the work line (drawn from left to right), read off the figure."""
    return b[c][0] - b[a][0]


def _plate_patterns(infinite_rod: bool, n: int = 0) -> list[str]:
    """Fig. 566: the crank circles, the crank positions, the speed points and the wave, the extremes.

    The rays along the stroke line (0 and n) are left to the plate's centre lines, one per diagram
    (:func:`two_cranks_plate`): drawn as rays they would run on across the gap between the diagrams.
    (The same patterns serve both layouts: names of the second circle simply do not occur without it.)
    """
    pats = [r"O", r"O'", r"crank", r"crank'", r"D0", r"D1", r"iD0", r"iD1", r"i?wave", r"i?Z\d+",
            rf"i?ray(?!(?:0|{n})$)\d+",
            r"K\.W[12]", r"K\.ray[12]", r"P\d+", r"iP\d+", r"i?Q\d+", r"sc\.[ABCg]"]
    return pats


def two_cranks_plate(fig: Figure) -> dict:
    """Fig. 566 as a plate: the speed curve heavy over a lighter crank circle (the reference of the
    mean speed), the stroke line and the vertical through each shaft centre dash-dotted as centre lines,
    each ending at its own diagram -- none runs across the gap between the two.

    Every position is a constructed point.
    """
    R = fig.replay
    n = fig.params["parts"]
    r = R["O"].distance(R["D1"])
    furniture = []
    looks = {"crank": "medium", "crank'": "medium", "wave": "heavy", "iwave": "heavy"}
    for centre, pre in (("O", ""), ("O'", "i")):
        if centre not in R:
            continue
        C = R[centre]
        furniture.append({"kind": "stroke", "a": (C[0] - 1.22 * r, C[1]), "b": (C[0] + 1.22 * r, C[1]),
                          "look": "centre"})
        for j in (n // 2, 3 * n // 2):
            looks[f"{pre}ray{j}"] = "centre"
    return {"looks": looks, "furniture": furniture}


# -- measurements on the figure ------------------------------------------------------
