"""The composite steps a draftsman builds from the instruments: midpoint, perpendiculars, parallels, division of
a segment by the intercept theorem, angle and arc bisection, copying an arc.

Each is made of the :class:`~construct.kernel.instruments.Builder`'s primitive steps only (straightedge,
compass, the point where two drawn curves cross) and recorded as a collapsible group, so a replay with other
givens repeats it step by step.  :class:`CompositeSteps` is the part of the Builder that holds them; it calls
the primitives on ``self`` and imports nothing of the Builder's module.

>>> from construct.kernel.instruments import Builder
>>> b = Builder("demo", givens={})
>>> _ = b.given_point("A", 0.0, 0.0), b.given_point("B", 4.0, 0.0)
>>> m = b[b.midpoint("M", "A", "B")]
>>> round(m.x, 12), round(m.y, 12)
(2.0, 0.0)
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from .errors import InvalidParameter
from .numeric import shown
from .ops import MAX_PARTS

__all__ = ["CompositeSteps", "MAX_SEGMENT_PARTS"]

#: The most parts divide_segment draws: as many as the finest semicircle division (3600); each part
#: costs a few steps, and 10**9 parts would fill the memory before the first one is drawn.  The same
#: bound as the dividers' trial_chord step (ops.MAX_PARTS).
MAX_SEGMENT_PARTS = MAX_PARTS


class CompositeSteps:
    """The composite steps of a :class:`~construct.kernel.instruments.Builder` (its base class)."""

    def bisect_angle(self, name: str, vertex: str, a: str, b: str) -> str:
        """The bisector of the angle a-vertex-b (less than two right angles).

        >>> from construct.kernel.instruments import Builder
        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("ABC", ((0, 0), (4, 0), (0, 3))):
        ...     _ = b.given_point(n, x, y)
        >>> w = b[b.bisect_angle("w", "A", "B", "C")]
        >>> round(w.direction()[0] - w.direction()[1], 12)   # 45 degrees
        0.0
        """
        with self.group(f"angle {a}{vertex}{b} bisected", f"Winkel {a}{vertex}{b} halbiert"):
            k = self.circle_through(self.fresh(f"{name}.k"), vertex, a)
            arm = self.line(self.fresh(f"{name}.g"), vertex, b)
            b2 = self.intersect(self.fresh(f"{name}.B"), arm, k, rule=("nearer", b))
            ka = self.circle_through(self.fresh(f"{name}.k"), a, b2)
            kb = self.circle_through(self.fresh(f"{name}.k"), b2, a)
            s = self.intersect(self.fresh(f"{name}.S"), ka, kb, rule=("farther", vertex))
            line = self.line(name, vertex, s, de=f"Winkelhalbierende {name}", en=f"angle bisector {name}")
        self.call(line, f"Winkelhalbierende von {a}{vertex}{b}", f"the bisector of the angle {a}{vertex}{b}")
        return line

    def perpendicular_bisector(self, name: str, a: str, b: str) -> str:
        """The perpendicular bisector of ab: two equal circles and the line through their crossings.

        >>> from construct.kernel.instruments import Builder
        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("ABC", ((0, 0), (4, 0), (0, 3))):
        ...     _ = b.given_point(n, x, y)
        >>> m = b[b.perpendicular_bisector("m", "A", "B")]
        >>> round(m.p.x, 12), round(m.q.x, 12)
        (2.0, 2.0)
        """
        with self.group(f"perpendicular bisector of {a}{b}", f"Mittelsenkrechte von {a}{b}"):
            ca = self.circle_through(self.fresh(f"{name}.k"), a, b)
            cb = self.circle_through(self.fresh(f"{name}.k"), b, a)
            u, v = self.intersect((self.fresh(f"{name}.S"), self.fresh(f"{name}.S")), ca, cb,
                                  rule=("left", a, b))
            line = self.line(name, u, v, de=f"Mittelsenkrechte {name} von {a}{b}",
                             en=f"perpendicular bisector {name} of {a}{b}")
        # named by what it is, not by the crossings S1, S2 (gone from the figure once its group is done)
        self.call(line, f"Mittelsenkrechte von {a}{b}", f"the perpendicular bisector of {a}{b}")
        return line

    def midpoint(self, name: str, a: str, b: str, *, through: str | None = None) -> str:
        """The midpoint of ab (``through``: an existing line ab, else one is drawn).

        >>> from construct.kernel.instruments import Builder
        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("ABC", ((0, 0), (4, 0), (0, 3))):
        ...     _ = b.given_point(n, x, y)
        >>> m = b[b.midpoint("M", "B", "C")]
        >>> round(m.x, 12), round(m.y, 12)
        (2.0, 1.5)
        """
        with self.group(f"midpoint of {a}{b}", f"Mitte von {a}{b}"):
            bis = self.perpendicular_bisector(f"{name}.m", a, b)
            ab = through or self.line(self.fresh(f"{name}.g"), a, b)
            return self.intersect(name, bis, ab, rule=("only",), de=f"Mitte {name} von {a}{b}",
                                  en=f"midpoint {name} of {a}{b}")

    def erect_perpendicular(self, name: str, p: str, line: str, on_line_point: str) -> str:
        """The perpendicular to *line* at its point *p*; *on_line_point* is another point of the line.

        A circle about p through the other point cuts the line again at its
        mirror image; the perpendicular bisector of those two is the perpendicular.

        >>> from construct.kernel.instruments import Builder
        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("ABC", ((0, 0), (4, 0), (0, 3))):
        ...     _ = b.given_point(n, x, y)
        >>> _ = b.line("AB", "A", "B")
        >>> pp = b[b.erect_perpendicular("p", "A", "AB", "B")]
        >>> round(pp.p.x, 12), round(pp.q.x, 12)
        (0.0, 0.0)
        """
        with self.group(f"perpendicular at {p}", f"Senkrechte in {p}"):
            k = self.circle_through(self.fresh(f"{name}.k"), p, on_line_point)
            mirror = self.intersect(self.fresh(f"{name}.Y"), line, k, rule=("farther", on_line_point))
            perp = self.perpendicular_bisector(name, on_line_point, mirror)
        self.call(perp, f"Senkrechte in {p}", f"the perpendicular at {p}")
        return perp

    def drop_perpendicular(self, name: str, p: str, line: str, a: str, b: str) -> tuple[str, str]:
        """The perpendicular from *p* to *line* (through its points a, b) and its foot.

        A circle about p through the farther of a, b cuts the line again at Y;
        circles about that point and about Y, both through p, meet again at the
        mirror image of p; p and its mirror image give the perpendicular.
        Returns (perpendicular, foot).  p must not lie on the line.

        >>> from construct.kernel.instruments import Builder
        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("ABC", ((0, 0), (4, 0), (0, 3))):
        ...     _ = b.given_point(n, x, y)
        >>> _ = b.line("AB", "A", "B")
        >>> perp, foot = b.drop_perpendicular("p", "C", "AB", "A", "B")
        >>> b[foot]
        Point(0.0, 0.0)
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
        self.call(perp, f"Lot von {p}", f"the perpendicular from {p}")
        return perp, foot

    def parallel_through(self, name: str, p: str, a: str, b: str, *, role: str = "construction",
                         along: tuple[str, str] | None = None) -> str:
        """The parallel to ab through p, by completing the parallelogram a b Q p.

        Q lies at distance |ab| from p and |ap| from b, on the other side of
        the diagonal pb than a; that side is read off the figure once, when
        the step is recorded, and stored as the step's rule.  *along*: what the
        direction ab is, where the figure says so (German, English: ``("zur
        45°-Linie", "to the 45 degree line")``): the steps' titles name that, not
        a point a far corner of the figure letters.

        >>> from construct.kernel.instruments import Builder
        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("ABC", ((0, 0), (4, 0), (0, 3))):
        ...     _ = b.given_point(n, x, y)
        >>> par = b[b.parallel_through("q", "C", "A", "B")]
        >>> round(par.q.y, 12)
        3.0
        """
        de, en = along or (f"zu {a}{b}", f"to {a}{b}")
        with self.group(f"parallel {en} through {p}", f"Parallele {de} durch {p}"):
            k1 = self.circle_segment(self.fresh(f"{name}.k"), p, a, b)
            k2 = self.circle_segment(self.fresh(f"{name}.k"), b, a, p)
            (px, py), (bx, by), (ax, ay) = self[p], self[b], self[a]
            a_left = (bx - px) * (ay - py) - (by - py) * (ax - px) > 0
            q = self.intersect(self.fresh(f"{name}.Q"), k1, k2, rule=("right" if a_left else "left", p, b))
            line = self.line(name, p, q, role=role)
        self.call(line, f"Parallele {de} durch {p}", f"the parallel {en} through {p}")
        return line

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

        >>> from construct.kernel.instruments import Builder
        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("ABC", ((0, 0), (4, 0), (0, 3))):
        ...     _ = b.given_point(n, x, y)
        >>> [round(b[p].x, 12) for p in b.divide_segment("T", "A", "B", 4)]
        [1.0, 2.0, 3.0]
        """
        if not isinstance(n, int) or isinstance(n, bool) or not 2 <= n <= MAX_SEGMENT_PARTS:
            raise InvalidParameter(f"divide_segment needs 2..{MAX_SEGMENT_PARTS} parts, got {n!r}")
        wanted = list(range(1, n)) if only is None else _division_points(only, n)
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
        """The midpoint of the arc ab (less than a semicircle) of *circle* about *center*.

        >>> from construct.kernel.instruments import Builder
        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("OAB", ((0, 0), (1, 0), (0, 1))):
        ...     _ = b.given_point(n, x, y)
        >>> _ = b.circle_through("k", "O", "A")
        >>> m = b[b.bisect_arc("M", "O", "A", "B", "k")]
        >>> round(m.x, 12) == round(m.y, 12) == round(0.5 ** 0.5, 12)
        True
        """
        with self.group(f"arc {a}{b} bisected", f"Bogen {a}{b} halbiert"):
            ka = self.circle_through(self.fresh(f"{name}.k"), a, b)
            kb = self.circle_through(self.fresh(f"{name}.k"), b, a)
            s = self.intersect(self.fresh(f"{name}.S"), ka, kb, rule=("farther", center))
            bis = self.line(self.fresh(f"{name}.w"), center, s)
            return self.intersect(name, bis, circle, rule=("nearer", s), de=f"Bogenmitte {name}",
                                  en=f"midpoint {name} of arc {a}{b}")

    def copy_arc(self, name: str, circle: str, start: str, a: str, b: str, *, away_from: str) -> str:
        """Step the chord ab off on *circle* from *start*, away from *away_from* (copying an arc).

        >>> from construct.kernel.instruments import Builder
        >>> b = Builder("demo", givens={})
        >>> for n, (x, y) in zip("OAB", ((0, 0), (1, 0), (0, 1))):
        ...     _ = b.given_point(n, x, y)
        >>> _ = b.circle_through("k", "O", "A")
        >>> c = b[b.copy_arc("C", "k", "B", "A", "B", away_from="A")]   # a quarter turn on from B
        >>> round(c.x, 12), round(abs(c.y), 12)
        (-1.0, 0.0)
        """
        k = self.circle_segment(self.fresh(f"{name}.k"), start, a, b)
        return self.intersect(name, circle, k, rule=("farther", away_from))


def _division_points(only: Any, n: int) -> list[int]:
    """The division points *only* names (1..n-1, each once), else an InvalidParameter naming the argument.

    >>> _division_points([0], 4)
    Traceback (most recent call last):
    ...
    construct.kernel.errors.InvalidParameter: divide_segment(..., only=...) names division points 1..3 of 4 parts, each once; got [0]
    """
    ok = (not isinstance(only, (str, bytes, Mapping)) and isinstance(only, (Sequence, set, frozenset, range))
          and all(isinstance(k, int) and not isinstance(k, bool) and 1 <= k < n for k in only)
          and len(set(only)) == len(only))
    if not ok:
        raise InvalidParameter(f"divide_segment(..., only=...) names division points 1..{n - 1} of {n} parts, "
                               f"each once; got {shown(only)}")
    return sorted(only) if isinstance(only, (set, frozenset)) else list(only)
