"""The instruments and the composite steps a draftsman builds from them.

A :class:`Builder` records a protocol while it evaluates it, so an
impossible step (circles that do not meet) fails at once and names itself.
Its primitive methods are the instruments -- straightedge, compass (about a
point through a point, or with an opening carried over from a segment or a
given length), dividers -- and the point where two drawn curves cross.  The
composite methods (midpoint, perpendiculars, parallels, division of a segment
by the intercept theorem, angle bisection, copying an arc) are made of those
primitives only, each as a collapsible group.

>>> b = Builder("demo", givens={"s": 3.0})
>>> A = b.given_point("A", 0.0, 0.0)
>>> B = b.given_point("B", 3.0, 0.0)
>>> parts = b.divide_segment("T", A, B, 3)
>>> [round(b[p].x, 12) for p in parts]
[1.0, 2.0]
>>> b.protocol().instrument_counts()
{'compass': 4, 'given': 2, 'intersect': 5, 'straightedge': 5}
"""

from __future__ import annotations

import contextlib
import math
from dataclasses import replace
from types import MappingProxyType
from typing import Any, Iterator, Mapping, Sequence

from .errors import ConstructError, InvalidParameter, StepError
from .protocol import EXACT, GIVEN, OPS, Caption, Protocol, Provenance, Step, rule_refs

__all__ = ["Builder"]


class Builder:
    """Records and evaluates a construction step by step."""

    def __init__(self, construction: str, givens: Mapping[str, float], params: Mapping[str, Any] | None = None,
                 replayable: Sequence[str] | None = None):
        self.construction = construction
        self.givens = dict(givens)
        self.params = dict(params or {})
        self.replayable = tuple(replayable if replayable is not None else self.givens)
        self.steps: list[Step] = []
        self.objects: dict[str, Any] = {}
        self.provenance: dict[str, Provenance] = {}
        self._group: list[str] = []
        self._group_titles: dict[str, str] = {}
        self._counter: dict[str, int] = {}

    # -- bookkeeping ----------------------------------------------------------
    def __getitem__(self, name: str) -> Any:
        return self.objects[name]

    def fresh(self, prefix: str) -> str:
        """A new object name starting with *prefix* (for auxiliary objects)."""
        k = self._counter.get(prefix, 0) + 1
        self._counter[prefix] = k
        name = f"{prefix}{k}"
        while name in self.objects:
            k += 1
            self._counter[prefix] = k
            name = f"{prefix}{k}"
        return name

    @contextlib.contextmanager
    def group(self, en: str, de: str | None = None) -> Iterator[None]:
        """Steps recorded inside belong to a group (shown collapsed or expanded)."""
        self._group.append(en)
        if de:
            self._group_titles[en] = de
        try:
            yield
        finally:
            self._group.pop()

    def record(self, tool: str, op: str, inputs: Sequence[str], outputs: Sequence[str],
               params: Mapping[str, Any], de: str, en: str, *, provenance: Provenance | None = None,
               role: str = "construction", labels: Mapping[str, str] | None = None) -> tuple[Any, ...]:
        """Evaluate one step and append it to the protocol."""
        for name in outputs:
            if name in self.objects:
                raise InvalidParameter(f"object name {name!r} is used twice in {self.construction!r}")
        frozen = MappingProxyType(dict(params))
        index = len(self.steps) + 1
        args = [self.objects[n] for n in inputs]
        try:
            if "rule" in params:
                refs = [self.objects[n] for n in rule_refs(params["rule"])]
                values = OPS[op](args, frozen, self.givens, refs)
            else:
                values = OPS[op](args, frozen, self.givens)
        except ConstructError as exc:
            raise StepError(f"step {index} ({tool}: {en}): {exc}", step_index=index, tool=tool) from exc
        if provenance is None:
            provenance = self._inherited(tool, inputs)
        step = Step(index, tool, op, tuple(inputs), tuple(outputs), frozen, Caption(de, en), provenance,
                    tuple(self._group), role, tuple(sorted((labels or {}).items())))
        self.steps.append(step)
        for name, value in zip(outputs, values):
            self.objects[name] = value
            self.provenance[name] = provenance
        return values

    def set_label(self, name: str, text: str) -> None:
        """Letter an object already made (the figure prints *text* beside it)."""
        for i, step in enumerate(self.steps):
            if name in step.outputs:
                labels = dict(step.labels)
                labels[name] = text
                self.steps[i] = replace(step, labels=tuple(sorted(labels.items())))
                return
        raise InvalidParameter(f"no object {name!r} to label")

    def _inherited(self, tool: str, inputs: Sequence[str]) -> Provenance:
        """An object is as trustworthy as the weakest object it was made from."""
        if tool == "given":
            return GIVEN
        result = EXACT
        for name in inputs:
            source = self.provenance[name]
            if source.kind != "given":
                result = result.combine(source)
        return result

    def protocol(self) -> Protocol:
        params = dict(self.params)
        params["givens"] = dict(self.givens)
        if self._group_titles:
            params["group_titles"] = dict(sorted(self._group_titles.items()))
        return Protocol(self.construction, MappingProxyType(params), tuple(self.steps), self.replayable)

    # -- givens ----------------------------------------------------------------
    def given_point(self, name: str, x: float, y: float, *, unit: str | None = None,
                    de: str | None = None, en: str | None = None, label: str | None = None) -> str:
        self.record("given", "given_point", (), (name,), {"x": x, "y": y, "unit": unit},
                    de or f"Punkt {name} gegeben", en or f"point {name} given", labels={name: label or name})
        return name

    def given_length(self, name: str, *, product: Sequence[str], factor: float = 1.0,
                     de: str | None = None, en: str | None = None) -> str:
        self.record("given", "given_length", (), (name,), {"product": tuple(product), "factor": factor},
                    de or f"Länge {name} gegeben", en or f"length {name} given")
        return name

    def given_line(self, name: str, through: str, *, angle_deg: float, de: str | None = None,
                   en: str | None = None, role: str = "construction") -> str:
        self.record("given", "given_line", (through,), (name,), {"angle_deg": angle_deg},
                    de or f"Gerade {name} durch {through} gegeben", en or f"line {name} through {through} given",
                    role=role)
        return name

    # -- straightedge and compass ----------------------------------------------
    def line(self, name: str, a: str, b: str, *, de: str | None = None, en: str | None = None,
             role: str = "construction") -> str:
        self.record("straightedge", "line", (a, b), (name,), {},
                    de or f"Gerade durch {a} und {b}", en or f"line through {a} and {b}", role=role)
        return name

    def circle_through(self, name: str, center: str, through: str, *, de: str | None = None,
                       en: str | None = None, role: str = "construction") -> str:
        self.record("compass", "circle_through", (center, through), (name,), {},
                    de or f"Kreis um {center} durch {through}", en or f"circle about {center} through {through}",
                    role=role)
        return name

    def circle_radius(self, name: str, center: str, length: str, *, de: str | None = None,
                      en: str | None = None, role: str = "construction") -> str:
        self.record("compass", "circle_radius", (center, length), (name,), {},
                    de or f"Kreis um {center} mit Halbmesser {length}",
                    en or f"circle about {center} with radius {length}", role=role)
        return name

    def circle_segment(self, name: str, center: str, a: str, b: str, *, de: str | None = None,
                       en: str | None = None, role: str = "construction") -> str:
        """Compass opening carried over from the segment ab."""
        self.record("compass", "circle_segment", (center, a, b), (name,), {},
                    de or f"Kreis um {center} mit Halbmesser {a}{b}",
                    en or f"circle about {center} with radius {a}{b}", role=role)
        return name

    def length_of(self, name: str, a: str, b: str, *, de: str | None = None, en: str | None = None) -> str:
        self.record("compass", "length_of", (a, b), (name,), {},
                    de or f"Zirkel auf {a}{b} eingestellt", en or f"compass set to {a}{b}")
        return name

    def intersect(self, name: str | Sequence[str], c1: str, c2: str, *, rule: Sequence[Any],
                  de: str | None = None, en: str | None = None, role: str = "construction",
                  labels: Mapping[str, str] | None = None) -> Any:
        """Mark where two curves cross; *rule* says which point (see :func:`protocol.choose`).

        With two names, both points are kept: the first is the one the rule picks.
        """
        names = (name,) if isinstance(name, str) else tuple(name)
        params = {"rule": tuple(rule), "both": len(names) == 2}
        self.record("intersect", "intersect", (c1, c2), names, params,
                    de or f"{' und '.join(names)} im Schnitt von {c1} und {c2}",
                    en or f"{' and '.join(names)} where {c1} meets {c2}", role=role, labels=labels)
        return names[0] if len(names) == 1 else names

    def step_off(self, name: str, curve: str, start: str, length: str, *, rule: Sequence[Any],
                 de: str | None = None, en: str | None = None, role: str = "construction") -> str:
        """Dividers: step the opening *length* off along *curve* from *start*; prick the point."""
        self.record("dividers", "step_off", (curve, start, length), (name,), {"rule": tuple(rule), "both": False},
                    de or f"{name}: Stechzirkel {length} von {start} auf {curve} abgetragen",
                    en or f"{name}: dividers {length} stepped off from {start} along {curve}", role=role)
        return name

    # -- composite steps -------------------------------------------------------
    def bisect_angle(self, name: str, vertex: str, a: str, b: str) -> str:
        """The bisector of the angle a-vertex-b (less than two right angles)."""
        with self.group(f"angle {a}{vertex}{b} bisected", f"Winkel {a}{vertex}{b} halbiert"):
            k = self.circle_through(self.fresh(f"{name}.k"), vertex, a)
            arm = self.line(self.fresh(f"{name}.g"), vertex, b)
            b2 = self.intersect(self.fresh(f"{name}.B"), arm, k, rule=("nearer", b))
            ka = self.circle_through(self.fresh(f"{name}.k"), a, b2)
            kb = self.circle_through(self.fresh(f"{name}.k"), b2, a)
            s = self.intersect(self.fresh(f"{name}.S"), ka, kb, rule=("farther", vertex))
            return self.line(name, vertex, s, de=f"Winkelhalbierende {name}", en=f"angle bisector {name}")

    def perpendicular_bisector(self, name: str, a: str, b: str) -> str:
        """The perpendicular bisector of ab: two equal circles and the line through their crossings."""
        with self.group(f"perpendicular bisector of {a}{b}", f"Mittelsenkrechte von {a}{b}"):
            ca = self.circle_through(self.fresh(f"{name}.k"), a, b)
            cb = self.circle_through(self.fresh(f"{name}.k"), b, a)
            u, v = self.intersect((self.fresh(f"{name}.S"), self.fresh(f"{name}.S")), ca, cb,
                                  rule=("left", a, b))
            return self.line(name, u, v, de=f"Mittelsenkrechte {name} von {a}{b}",
                             en=f"perpendicular bisector {name} of {a}{b}")

    def midpoint(self, name: str, a: str, b: str, *, through: str | None = None) -> str:
        """The midpoint of ab (``through``: an existing line ab, else one is drawn)."""
        with self.group(f"midpoint of {a}{b}", f"Mitte von {a}{b}"):
            bis = self.perpendicular_bisector(f"{name}.m", a, b)
            ab = through or self.line(self.fresh(f"{name}.g"), a, b)
            return self.intersect(name, bis, ab, rule=("only",), de=f"Mitte {name} von {a}{b}",
                                  en=f"midpoint {name} of {a}{b}")

    def erect_perpendicular(self, name: str, p: str, line: str, on_line_point: str) -> str:
        """The perpendicular to *line* at its point *p*; *on_line_point* is another point of the line.

        A circle about p through the other point cuts the line again at its
        mirror image; the perpendicular bisector of those two is the perpendicular.
        """
        with self.group(f"perpendicular at {p}", f"Senkrechte in {p}"):
            k = self.circle_through(self.fresh(f"{name}.k"), p, on_line_point)
            mirror = self.intersect(self.fresh(f"{name}.Y"), line, k, rule=("farther", on_line_point))
            return self.perpendicular_bisector(name, on_line_point, mirror)

    def drop_perpendicular(self, name: str, p: str, line: str, a: str, b: str) -> tuple[str, str]:
        """The perpendicular from *p* to *line* (through its points a, b) and its foot.

        A circle about p through the farther of a, b cuts the line again at Y;
        circles about that point and about Y, both through p, meet again at the
        mirror image of p; p and its mirror image give the perpendicular.
        Returns (perpendicular, foot).  p must not lie on the line.
        """
        pa, pb = self[p].distance(self[a]), self[p].distance(self[b])
        far = a if pa >= pb else b  # read off the figure once; stored in the steps
        with self.group(f"perpendicular from {p}", f"Lot von {p}"):
            k = self.circle_through(self.fresh(f"{name}.k"), p, far)
            y = self.intersect(self.fresh(f"{name}.Y"), line, k, rule=("farther", far))
            k1 = self.circle_through(self.fresh(f"{name}.k"), far, p)
            k2 = self.circle_through(self.fresh(f"{name}.k"), y, p)
            mirror = self.intersect(self.fresh(f"{name}.Q"), k1, k2, rule=("farther", p))
            perp = self.line(name, p, mirror, de=f"Lot {name} von {p}", en=f"perpendicular {name} from {p}")
            foot = self.intersect(f"{name}.F", perp, line, rule=("only",), de=f"Fußpunkt des Lotes von {p}",
                                  en=f"foot of the perpendicular from {p}")
        return perp, foot

    def parallel_through(self, name: str, p: str, a: str, b: str, *, role: str = "construction") -> str:
        """The parallel to ab through p, by completing the parallelogram a b Q p.

        Q lies at distance |ab| from p and |ap| from b, on the other side of
        the diagonal pb than a; that side is read off the figure once, when
        the step is recorded, and stored as the step's rule.
        """
        with self.group(f"parallel to {a}{b} through {p}", f"Parallele zu {a}{b} durch {p}"):
            k1 = self.circle_segment(self.fresh(f"{name}.k"), p, a, b)
            k2 = self.circle_segment(self.fresh(f"{name}.k"), b, a, p)
            (px, py), (bx, by), (ax, ay) = self[p], self[b], self[a]
            a_left = (bx - px) * (ay - py) - (by - py) * (ax - px) > 0
            q = self.intersect(self.fresh(f"{name}.Q"), k1, k2, rule=("right" if a_left else "left", p, b))
            return self.line(name, p, q, role=role)

    def divide_segment(self, name: str, a: str, b: str, n: int, *, line: str | None = None,
                       only: Sequence[int] | None = None) -> list[str]:
        """Points dividing ab into n equal parts, by the intercept theorem.

        Two parallel rays leave a and b on opposite sides (towards the apexes
        of the equilateral triangles on ab); equal steps are marked on both,
        and the line joining the k-th mark from a to the (n-k)-th mark from b
        crosses ab at the k-th division point.  Returns the names of points
        1..n-1 (or of those listed in *only*).

        The step is ab itself for up to 4 parts; for more, ab halved often
        enough that the n marks reach about as far as ab again -- a draftsman
        picks a short opening, else ten parts would need a ray nine times ab.
        """
        if not isinstance(n, int) or n < 2:
            raise InvalidParameter(f"divide_segment needs n >= 2 parts, got {n!r}")
        wanted = list(range(1, n)) if only is None else list(only)
        halvings = max(0, math.ceil(math.log2(n)) - 2)
        with self.group(f"{a}{b} divided into {n} equal parts", f"{a}{b} in {n} gleiche Teile geteilt"):
            ab = line or self.line(self.fresh(f"{name}.g"), a, b)
            ka = self.circle_through(self.fresh(f"{name}.k"), a, b)
            kb = self.circle_through(self.fresh(f"{name}.k"), b, a)
            t, t2 = self.intersect((self.fresh(f"{name}.T"), self.fresh(f"{name}.T")), ka, kb, rule=("left", a, b))
            need_a = max((k for k in wanted), default=0)
            need_b = max((n - k for k in wanted), default=0)
            if halvings == 0:
                marks_a = self._marks(name + ".M", a, t, need_a)
                marks_b = self._marks(name + ".N", b, t2, need_b)
            else:
                end = b
                for _ in range(halvings):
                    end = self.midpoint(self.fresh(f"{name}.h"), a, end, through=ab)
                marks_a = self._marks(name + ".M", a, t, need_a, opening=(a, end))
                marks_b = self._marks(name + ".N", b, t2, need_b, opening=(a, end))
            out = []
            for k in wanted:
                j = self.line(self.fresh(f"{name}.j"), marks_a[k - 1], marks_b[n - k - 1])
                out.append(self.intersect(f"{name}{k}", j, ab, rule=("only",),
                                          de=f"Teilpunkt {name}{k}", en=f"division point {name}{k}"))
            return out

    def _marks(self, prefix: str, origin: str, towards: str, count: int,
               opening: tuple[str, str] | None = None) -> list[str]:
        """*count* equal steps from *origin* along the ray towards *towards*, with the dividers.

        The step is origin-towards itself, or the segment *opening* set off first.
        """
        if count == 0:
            return []
        ray = self.line(self.fresh(prefix + "r"), origin, towards)
        if opening is None:
            first = towards
        else:
            k = self.circle_segment(self.fresh(prefix + "k"), origin, *opening)
            first = self.intersect(self.fresh(prefix), ray, k, rule=("nearer", towards))
        marks = [first]
        for _ in range(count - 1):
            k = self.circle_through(self.fresh(prefix + "k"), marks[-1], marks[-2] if len(marks) > 1 else origin)
            marks.append(self.intersect(self.fresh(prefix), ray, k, rule=("farther", origin)))
        return marks

    def bisect_arc(self, name: str, center: str, a: str, b: str, circle: str) -> str:
        """The midpoint of the arc ab (less than a semicircle) of *circle* about *center*."""
        with self.group(f"arc {a}{b} bisected", f"Bogen {a}{b} halbiert"):
            ka = self.circle_through(self.fresh(f"{name}.k"), a, b)
            kb = self.circle_through(self.fresh(f"{name}.k"), b, a)
            s = self.intersect(self.fresh(f"{name}.S"), ka, kb, rule=("farther", center))
            bis = self.line(self.fresh(f"{name}.w"), center, s)
            return self.intersect(name, bis, circle, rule=("nearer", s), de=f"Bogenmitte {name}",
                                  en=f"midpoint {name} of arc {a}{b}")

    def copy_arc(self, name: str, circle: str, start: str, a: str, b: str, *, away_from: str) -> str:
        """Step the chord ab off on *circle* from *start*, away from *away_from* (copying an arc)."""
        k = self.circle_segment(self.fresh(f"{name}.k"), start, a, b)
        return self.intersect(name, circle, k, rule=("farther", away_from))
