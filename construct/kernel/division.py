"""Dividing the semicircle over the stroke into n equal parts.

Seed 001 divides the semicircle "vorteilhafterweise in 9 oder 18 Teile".
10 and 20 degree arcs have no compass-and-straightedge construction, so each
method says what it is:

* ``exact``     Euclidean steps only; here for n = 2^k * m with m in {1, 3, 5, 15}
                (hexagon, decagon by Ptolemy's golden section, their difference 12 deg).
* ``durer``     the exact frame for n/3 parts, each arc trisected by Dürer's
                approximate construction (1525): Euclidean steps, approximate result.
* ``neusis``    the same frame, each arc trisected by Archimedes' marked ruler:
                exact, but not a Euclidean instrument.
* ``dividers``  the dividers set by trial (the draftsman's way): step the opening
                round, correct it by 1/n of the closing error, repeat.
* ``auto``      exact where supported, else Dürer when n/3 is, else dividers.

>>> choose_method(18), choose_method(12), choose_method(7), choose_method(360), choose_method(3600)
('durer', 'exact', 'dividers', 'durer', 'dividers')
"""

from __future__ import annotations

import math
from typing import Any

from .errors import InvalidParameter, did_you_mean
from .instruments import Builder
from .protocol import Caption, Provenance

__all__ = ["METHODS", "NAMES", "MAX_PARTS", "choose_method", "exact_supported", "accepts", "methods_for", "divide_semicircle",
           "durer_error_bound"]

METHODS = ("auto", "exact", "durer", "neusis", "dividers")
#: What a caption calls each method (German, English).
NAMES = {
    "durer": Caption("Dürers Dreiteilung", "Dürer's trisection"),
    "exact": Caption("mit Zirkel und Lineal", "by compass and straightedge"),
    "neusis": Caption("Einschiebung", "neusis"),
    "dividers": Caption("mit dem Stechzirkel probiert", "with the dividers by trial"),
}
MAX_PARTS = 3600
FERMAT_PRIMES = (3, 5, 17, 257, 65537)
#: Odd parts of n for which this module has an exact construction.
EXACT_ODD_PARTS = (1, 3, 5, 15)
#: Closing tolerance of the dividers by trial, relative to the crank radius.
#: A draftsman stops at a fraction of a millimetre; we stop far below
#: anything drawable so that the reported error is the method's, not ours.
TRIAL_TOLERANCE = 1e-11


def _odd_part(n: int) -> int:
    while n % 2 == 0:
        n //= 2
    return n


def euclidean_constructible(n: int) -> bool:
    """Can an arc of 180/n degrees be constructed at all (Gauss-Wantzel)?"""
    odd = _odd_part(n)
    for p in FERMAT_PRIMES:
        if odd % p == 0:
            odd //= p
    return odd == 1


def exact_supported(n: int) -> bool:
    """Does this library construct the n-division exactly?"""
    return _odd_part(n) in EXACT_ODD_PARTS


def choose_method(n: int) -> str:
    """The method ``auto`` uses for n parts."""
    if exact_supported(n):
        return "exact"
    if n % 3 == 0 and exact_supported(n // 3):
        return "durer"
    return "dividers"


def accepts(method: str, n: int) -> bool:
    """Can *method* divide the semicircle into n parts?  The one predicate check_parts and its advice share.

    >>> [m for m in METHODS if accepts(m, 7)], [m for m in METHODS if accepts(m, 9)]
    (['auto', 'dividers'], ['auto', 'durer', 'neusis', 'dividers'])
    """
    if method == "exact":
        return exact_supported(n)
    if method in ("durer", "neusis"):  # Dürer and Archimedes trisect the arcs of an exact frame of n/3 parts
        return n % 3 == 0 and exact_supported(n // 3)
    return method in ("auto", "dividers")


def methods_for(n: int) -> list[str]:
    """The methods that accept n parts, besides auto (what an error message may recommend).

    >>> methods_for(7), methods_for(18), methods_for(17)
    (['dividers'], ['durer', 'neusis', 'dividers'], ['dividers'])
    """
    return [m for m in METHODS if m != "auto" and accepts(m, n)]


def _advice(n: int, rejected: str) -> str:
    others = [m for m in methods_for(n) if m != rejected]
    return "use --method " + (" or ".join([", ".join(others[:-1]), others[-1]]) if len(others) > 1 else others[0])


def check_parts(n: Any, method: str) -> str:
    """Validate n and the method; return the method actually used."""
    if isinstance(n, bool) or not isinstance(n, int):
        raise InvalidParameter(f"number of parts must be a whole number, got {n!r}")
    if not 1 <= n <= MAX_PARTS:
        raise InvalidParameter(f"number of parts must be between 1 and {MAX_PARTS}, got {n}")
    if method not in METHODS:
        raise InvalidParameter(f"unknown division method {method!r}{did_you_mean(method, METHODS)}; choose one of {', '.join(METHODS)}")
    if method == "auto":
        return choose_method(n)
    if accepts(method, n):
        return method
    if method == "exact":
        if euclidean_constructible(n):
            raise InvalidParameter(
                f"{n} parts are constructible (Gauss) but this library constructs exactly only "
                f"n = 2^k * (1, 3, 5 or 15); {_advice(n, method)}")
        raise InvalidParameter(f"{n} parts have no compass-and-straightedge construction "
                               f"(180/{n} degrees is not constructible); {_advice(n, method)}")
    raise InvalidParameter(f"--method {method} trisects an exact frame of n/3 arcs; {n} parts need n/3 "
                           f"= 2^k * (1, 3, 5 or 15); {_advice(n, method)}")


def durer_error_bound(arc: float) -> float:
    """A bound on the angle error (radians) of Dürer's trisection of an arc of *arc* radians.

    The error grows like arc^7 (numerically: 3.4e-8 rad at 30 deg, 4.4e-6 at
    60 deg); this bound is 1.5 times the leading term fitted at 60 deg, so it
    holds for all arcs up to 60 deg with a margin.
    """
    return 1.5 * 4.4e-6 * (arc / (math.pi / 3.0)) ** 7




# --------------------------------------------------------------------------


def divide_semicircle(b: Builder, *, O: str, D0: str, D1: str, circle: str, axis: str, n: int,
                      method: str) -> list[str]:
    """Add the division of the upper semicircle D0..D1 into n parts; return the points 0..n.

    The returned names run from D0 (0 degrees) to D1 (180 degrees).
    """
    method = check_parts(n, method)
    b.params["method"] = method
    de_m = {"exact": "genau", "durer": "Dürers Dreiteilung", "neusis": "Einschiebung", "dividers": "Stechzirkel"}
    with b.group(f"semicircle divided into {n} parts ({method})",
                 f"Halbkreis in {n} Teile geteilt ({de_m[method]})"):
        if method == "exact":
            points = _exact_division(b, O, D0, D1, circle, axis, n, n)
        elif method in ("durer", "neusis"):
            frame = _exact_division(b, O, D0, D1, circle, axis, n // 3, n)
            points = [frame[0]]
            trisect = _durer_trisect if method == "durer" else _neusis_trisect
            for i, (a, c) in enumerate(zip(frame, frame[1:])):
                h1, h2 = trisect(b, O, a, c, circle, 3 * i)
                points += [h1, h2, c]
        else:
            points = _dividers_division(b, D0, D1, circle, n)
    return points


def _exact_division(b: Builder, O: str, D0: str, D1: str, circle: str, axis: str, n: int,
                    total: int) -> list[str]:
    """Exact points at the multiples of 180/n degrees, named by their index among *total* parts."""
    odd = _odd_part(n)
    frame = _frame(b, O, D0, D1, circle, axis, odd, total)
    while len(frame) - 1 < n:
        finer = [frame[0]]
        step = total // (2 * (len(frame) - 1))  # index distance of the new midpoints
        for a, c in zip(frame, frame[1:]):
            name = f"P{len(finer) * step}"
            if len(frame) == 2:  # the semicircle itself: its midpoint is above O
                mid = _semicircle_top(b, O, D0, D1, circle, name)
            else:
                mid = b.bisect_arc(name, O, a, c, circle)
            finer += [mid, c]
        frame = finer
    return frame


def _semicircle_top(b: Builder, O: str, D0: str, D1: str, circle: str, name: str) -> str:
    with b.group("semicircle bisected", "Halbkreis halbiert"):
        ka = b.circle_through(b.fresh(f"{name}.k"), D0, D1)
        kb = b.circle_through(b.fresh(f"{name}.k"), D1, D0)
        s = b.intersect(b.fresh(f"{name}.S"), ka, kb, rule=("left", D0, D1))
        w = b.line(b.fresh(f"{name}.w"), O, s)
        return b.intersect(name, w, circle, rule=("nearer", s), de=f"Bogenmitte {name}",
                           en=f"midpoint {name} of the semicircle")


def _frame(b: Builder, O: str, D0: str, D1: str, circle: str, axis: str, odd: int, total: int) -> list[str]:
    """Points at the multiples of 180/odd degrees, odd in (1, 3, 5, 15), named by index among *total*."""

    def P(deg: int) -> str:
        return f"P{deg * total // 180}"

    if odd == 1:
        return [D0, D1]
    if odd == 3:
        with b.group("hexagon points 60 and 120 degrees", "Sechseckpunkte 60° und 120°"):
            k0 = b.circle_through(b.fresh("hex.k"), D0, O, de=f"Kreis um {D0} mit r", en=f"circle about {D0} with radius r")
            p60 = b.intersect(P(60), k0, circle, rule=("left", D0, D1))
            k1 = b.circle_through(b.fresh("hex.k"), D1, O, de=f"Kreis um {D1} mit r", en=f"circle about {D1} with radius r")
            p120 = b.intersect(P(120), k1, circle, rule=("left", D0, D1))
        return [D0, p60, p120, D1]
    s10 = _decagon_side(b, O, D0, D1, circle, axis)
    if odd == 5:
        with b.group("decagon side stepped off", "Zehneckseite abgetragen"):
            points = [D0]
            for k in range(1, 5):
                prev = points[-2] if len(points) > 1 else D1
                points.append(b.copy_arc(P(36 * k), circle, points[-1], O, s10,
                                         away_from=prev))
        return points + [D1]
    # odd == 15: 12 degrees = 72 - 60 (pentagon angle less hexagon angle)
    with b.group("12 degree chord: 72 - 60 degrees", "Sehne zu 12°: 72° − 60°"):
        k0 = b.circle_through(b.fresh("hex.k"), D0, O, de=f"Kreis um {D0} mit r", en=f"circle about {D0} with radius r")
        p60 = b.intersect(P(60), k0, circle, rule=("left", D0, D1))
        p36 = b.copy_arc(P(36), circle, D0, O, s10, away_from=D1)
        p72 = b.copy_arc(P(72), circle, p36, O, s10, away_from=D0)
    with b.group("12 degree chord stepped off", "Sehne zu 12° abgetragen"):
        points = [D0]
        made = {60: p60, 36: p36, 72: p72}
        for k in range(1, 15):
            deg = 12 * k
            if deg in made:
                points.append(made[deg])
                continue
            prev = points[-2] if len(points) > 1 else D1
            points.append(b.copy_arc(P(deg), circle, points[-1], p60, p72, away_from=prev))
    return points + [D1]


def _decagon_side(b: Builder, O: str, D0: str, D1: str, circle: str, axis: str) -> str:
    """Ptolemy: the circle about the midpoint M of O-D1 through the top E cuts the axis at K; OK is the decagon side."""
    with b.group("decagon side by the golden section (Ptolemy)", "Zehneckseite nach Ptolemäus (Goldener Schnitt)"):
        top = _semicircle_top(b, O, D0, D1, circle, "E")
        m = b.midpoint("M", O, D1, through=axis)
        k = b.circle_through(b.fresh("ptol.k"), m, top)
        return b.intersect("K", k, axis, rule=("nearer", O), de="K: OK ist die Zehneckseite",
                           en="K: OK is the side of the regular decagon")


def _durer_trisect(b: Builder, O: str, a: str, c: str, circle: str, base: int) -> tuple[str, str]:
    """Dürer's approximate trisection of the arc a..c; returns the two points (base+1, base+2)."""
    arc_deg = 3 * 180.0 / b.params["parts"]  # the nominal arc; the bound is the method's, a priori
    error = durer_error_bound(math.radians(arc_deg))
    tag = f"T{base + 1}"
    with b.group(f"Dürer's trisection of arc {a}{c} ({arc_deg:.4g} degrees)",
                 f"Dürers Dreiteilung des Bogens {a}{c}"):
        chord = b.line(b.fresh(f"{tag}.s"), a, c, de=f"Sehne {a}{c}", en=f"chord {a}{c}")
        (C,) = b.divide_segment(f"{tag}.C", a, c, 3, line=chord, only=[1])
        perp = b.erect_perpendicular(f"{tag}.p", C, chord, a)
        # Captions name the objects (the renderer writes them in the figure's letters: E, 0, 3 ...)
        E = b.intersect(f"{tag}.E", perp, circle, rule=("left", a, c),
                        de=f"{tag}.E: Senkrechte in {C} trifft den Bogen", en=f"{tag}.E: the perpendicular at {C} meets the arc")
        kE = b.circle_through(b.fresh(f"{tag}.k"), a, E, de=f"Kreis um {a} durch {E}", en=f"circle about {a} through {E}")
        F = b.intersect(f"{tag}.F", kE, chord, rule=("toward", a, c),
                        de=f"{tag}.F: Kreis um {a} mit {a}{E} trifft die Sehne",
                        en=f"{tag}.F: the circle about {a} with radius {a}{E} meets the chord")
        (G,) = b.divide_segment(f"{tag}.G", C, F, 3, line=chord, only=[2])
        kG = b.circle_through(b.fresh(f"{tag}.k"), a, G, de=f"Kreis um {a} durch {G}", en=f"circle about {a} through {G}")
        approx = Provenance("approximate", "Dürer's trisection (1525)", error)
        name1 = _point_name(b, base + 1)
        b.record("intersect", "intersect", (kG, circle), (name1,), {"rule": ("nearer", c), "both": False},
                 f"{name1}: Kreis um {a} mit {a}{G} trifft den Bogen (≈ 1/3)",
                 f"{name1}: the circle about {a} with radius {a}{G} meets the arc (≈ 1/3 of it)", provenance=approx)
        k2 = b.circle_segment(b.fresh(f"{tag}.k"), c, a, name1, de=f"Kreis um {c} mit {a}{name1}",
                              en=f"circle about {c} with radius {a}{name1}")
        name2 = _point_name(b, base + 2)
        b.record("intersect", "intersect", (k2, circle), (name2,), {"rule": ("nearer", a), "both": False},
                 f"{name2}: symmetrisch von {c} aus abgetragen", f"{name2}: the same chord stepped back from {c}",
                 provenance=approx)
    return name1, name2


def _neusis_trisect(b: Builder, O: str, a: str, c: str, circle: str, base: int) -> tuple[str, str]:
    tag = f"T{base + 1}"
    with b.group(f"Archimedes' neusis trisection of arc {a}{c}", f"Dreiteilung des Bogens {a}{c} durch Einschiebung"):
        neusis = Provenance("neusis", "Archimedes' marked ruler")
        D, C = f"{tag}.D", f"{tag}.C"
        b.record("neusis", "neusis_archimedes", (O, a, c, circle), (D, C), {},
                 f"Lineal mit Marken r durch {c} eingeschoben: CD = r",
                 f"marked ruler through {c} slid until CD = r", provenance=neusis)
        b.line(b.fresh(f"{tag}.g"), D, c, de=f"Lineal {D}{c}", en=f"the ruler's line {D}{c}")
        par = b.parallel_through(b.fresh(f"{tag}.q"), O, D, c)
        name1 = _point_name(b, base + 1)
        b.intersect(name1, par, circle, rule=("nearer", c), de=f"{name1}: Parallele durch O trifft den Bogen",
                    en=f"{name1}: the parallel through O meets the arc")
        k2 = b.circle_segment(b.fresh(f"{tag}.k"), c, a, name1)
        name2 = _point_name(b, base + 2)
        b.intersect(name2, k2, circle, rule=("nearer", a), de=f"{name2}: symmetrisch von {c} aus abgetragen",
                    en=f"{name2}: the same chord stepped back from {c}")
    return name1, name2


def _point_name(b: Builder, k: int) -> str:
    return f"P{k}"


def _dividers_division(b: Builder, D0: str, D1: str, circle: str, n: int) -> list[str]:
    if n == 1:
        return [D0, D1]
    with b.group("dividers set by trial and stepped round", "Stechzirkel durch Probieren eingestellt und abgetragen"):
        e = "e"
        b.record("dividers", "trial_chord", (circle, D0, D1), (e,), {"parts": n, "tolerance": TRIAL_TOLERANCE},
                 f"Stechzirkel durch Probieren auf 1/{n} des Halbkreises eingestellt",
                 f"dividers set by trial to 1/{n} of the semicircle",
                 provenance=Provenance("trial", "dividers by trial", TRIAL_TOLERANCE))
        points = [D0]
        for k in range(1, n):
            rule = ("left", D0, D1) if k == 1 else ("farther", points[-2])
            name = _point_name(b, k)
            points.append(b.step_off(name, circle, points[-1], e, rule=rule,
                                     de=f"Teilpunkt {k}: Stechzirkel von {k - 1} aus abgesetzt",
                                     en=f"division point {k}: dividers set down from point {k - 1}"))
    return points + [D1]
