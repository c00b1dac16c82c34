"""The proportional angle ("Proportionswinkel") and the fourth and mean proportionals.

Seed 000 multiplies the table values by F/f "mit dem Zirkel oder einem
Proportionswinkel".  All three instruments here are the intercept theorem (or
Thales' circle) made of compass-and-straightedge steps, recorded on a
:class:`~construct.kernel.instruments.Builder` like any other composite step.

The proportional angle is laid out with a right angle, so that every line
it needs is an erected perpendicular and no step degenerates for any ratio
(a ratio of 1 included): a vertex S on a *leg*; each *scale line* crosses
the leg at right angles at a known distance from S.  The ray from S through
a point of one scale line meets another scale line at the point whose
offset from the leg is multiplied by the ratio of the two distances::

    S ----- d1 ----- U1 (scale line 1) ---- d2 ---- U2 (scale line 2)
    offset on line 2 = offset on line 1 * d2 / d1      (signs kept: same side of the leg)

>>> from construct.kernel.instruments import Builder
>>> b = Builder("demo", givens={"a": 2.0, "b": 3.0, "c": 5.0})
>>> S = b.given_point("S", 0.0, 0.0)
>>> leg = b.given_line("leg", S, angle_deg=90.0)
>>> for g in "abc":
...     _ = b.given_length(g, product=(g,))
>>> ang = ProportionalAngle(S, leg)
>>> one = scale_line(b, ang, "s1", length="a", toward=("toward", S, None, 0.0, 1.0))
>>> two = scale_line(b, ang, "s2", length="b", toward=("toward", S, None, 0.0, 1.0))
>>> P = b.intersect("P", one.line, b.circle_radius("kP", one.origin, "c"), rule=("toward", S, None, -1.0, 0.0))
>>> Q = carry_across(b, ang, "Q", P, two)
>>> round(b[two.origin].distance(b[Q]), 12)   # 5 * 3 / 2
7.5
>>> O2, X = fourth_proportional(b, "x", vertex=S, leg_point=P, a="a", b_="b", c="c")
>>> round(b[O2].distance(b[X]), 12)
7.5
>>> foot, top = mean_proportional(b, "g", start=S, direction_point=P, a="a", c="c")
>>> round(b[foot].distance(b[top]) ** 2, 12)  # sqrt(2 * 5) squared
10.0
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Sequence

from .instruments import Builder

__all__ = ["ProportionalAngle", "Scale", "scale_line", "carry_across", "fourth_proportional", "mean_proportional"]


@dataclass(frozen=True, slots=True)
class ProportionalAngle:
    """The vertex S of a proportional angle and the leg through it (object names)."""

    vertex: str
    leg: str


@dataclass(frozen=True, slots=True)
class Scale:
    """A scale line of a proportional angle: it crosses the leg at right angles in ``origin``."""

    origin: str
    line: str


def vertex_on(b: Builder, name: str, *, origin: str, leg: str, length: str, rule: Sequence[Any],
              de: str | None = None, en: str | None = None) -> ProportionalAngle:
    """Put the vertex on *leg* at the distance *length* from *origin* (a point of the leg)."""
    k = b.circle_radius(b.fresh(f"{name}.k"), origin, length,
                        de=f"Kreis um {origin} mit {length}", en=f"circle about {origin} with radius {length}")
    b.intersect(name, leg, k, rule=rule, de=de or f"Scheitel {name} des Proportionswinkels",
                en=en or f"vertex {name} of the proportional angle", labels={name: name})
    return ProportionalAngle(name, leg)


def scale_line(b: Builder, angle: ProportionalAngle, name: str, *, length: str, toward: Sequence[Any],
               de: str | None = None, en: str | None = None) -> Scale:
    """Mark *length* from the vertex along the leg and erect the scale line there.

    *toward* is the rule picking the side of the vertex (the same side for
    every scale line that is to keep signs).
    """
    S = angle.vertex
    # (the title names the line by where it stands: its name would read as the perpendicular at a point not made yet)
    with b.group(f"scale line at distance {length} from {S}", f"Maßlinie im Abstand {length} von {S}"):
        k = b.circle_radius(b.fresh(f"{name}.k"), S, length, de=f"{length} von {S} aus auf dem Schenkel abgetragen",
                            en=f"{length} laid off from {S} along the leg")
        origin = b.intersect(f"{name}.U", angle.leg, k, rule=toward, de=de or f"Marke {length} auf dem Schenkel",
                             en=en or f"mark {length} on the leg")
        line = b.erect_perpendicular(name, origin, angle.leg, S)
    return Scale(origin, line)


def carry_across(b: Builder, angle: ProportionalAngle, name: str, point: str, to: Scale, *,
                 de: str | None = None, en: str | None = None, role: str = "construction") -> str:
    """The ray from the vertex through *point* (on one scale line) meets the scale line *to*."""
    ray = b.line(f"{name}.s", angle.vertex, point, de=f"Strahl von {angle.vertex} durch {point}",
                 en=f"ray from {angle.vertex} through {point}")
    return b.intersect(name, ray, to.line, rule=("only",), role=role,
                       de=de or f"{name}: Strahl trifft die Maßlinie (Strahlensatz)",
                       en=en or f"{name}: the ray meets the scale line (intercept theorem)")


def fourth_proportional(b: Builder, name: str, *, vertex: str, leg_point: str, a: str, b_: str, c: str) -> tuple[str, str]:
    """x = b * c / a for three compass openings; returns two points whose distance is x.

    A proportional angle with its vertex at *vertex* and its leg towards
    *leg_point*: scale lines at the distances a and b, c laid off on the first.
    """
    with b.group(f"fourth proportional {name} = {b_}·{c}/{a}", f"vierte Proportionale {name} = {b_}·{c}/{a}"):
        leg = b.line(f"{name}.leg", vertex, leg_point, de="Schenkel des Proportionswinkels",
                     en="leg of the proportional angle")
        angle = ProportionalAngle(vertex, leg)
        side = ("toward", vertex, leg_point)
        first = scale_line(b, angle, f"{name}.a", length=a, toward=side)
        second = scale_line(b, angle, f"{name}.b", length=b_, toward=side)
        k = b.circle_radius(b.fresh(f"{name}.k"), first.origin, c, de=f"{c} auf der ersten Maßlinie abgetragen",
                            en=f"{c} laid off on the first scale line")
        mark = b.intersect(f"{name}.C", first.line, k, rule=("left", vertex, first.origin))
        return second.origin, carry_across(b, angle, name, mark, second)


def mean_proportional(b: Builder, name: str, *, start: str, direction_point: str, a: str, c: str) -> tuple[str, str]:
    """sqrt(a * c) by Thales' circle: returns two points whose distance is the mean proportional.

    a and c are laid end to end on the line from *start* towards
    *direction_point*; the perpendicular at the joint meets the semicircle over
    the whole at the height sqrt(a * c) (Euclid VI.13).
    """
    with b.group(f"mean proportional {name} of {a} and {c}", f"mittlere Proportionale {name} von {a} und {c}"):
        g = b.line(f"{name}.g", start, direction_point)
        ka = b.circle_radius(b.fresh(f"{name}.k"), start, a)
        joint = b.intersect(f"{name}.B", g, ka, rule=("toward", start, direction_point))
        kc = b.circle_radius(b.fresh(f"{name}.k"), joint, c)
        end = b.intersect(f"{name}.C", g, kc, rule=("farther", start))
        mid = b.midpoint(f"{name}.M", start, end, through=g)
        thales = b.circle_through(f"{name}.t", mid, start, de="Thaleskreis über dem Ganzen",
                                  en="Thales' circle over the whole")
        perp = b.erect_perpendicular(f"{name}.p", joint, g, start)
        top = b.intersect(name, perp, thales, rule=("left", start, end),
                          de=f"{name}: Höhe = mittlere Proportionale", en=f"{name}: the height is the mean proportional")
    return joint, top
