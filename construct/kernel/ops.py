"""The op table: every operation a protocol step can name, defined once, here.

A protocol file names each step's operation (``"op": "intersect"``); loading
it needs nothing but this table, whatever construction wrote it.  Building
(:class:`~construct.kernel.instruments.Builder`) and replaying
(:meth:`~construct.kernel.protocol.Protocol.replay`) call the very same
functions, so they cannot disagree.

An operation is a function ``fn(args, params, givens, refs, xp)``: the input
objects, the step's parameters, the givens, the objects its branch rule
names (``()`` without a rule) and the array namespace -- :data:`SCALAR`
for plain floats, :data:`ARRAY` for a sweep over many givens at once.  It
returns the tuple of its outputs and computes only what its instrument does.
Every operation of the table runs on arrays in a sweep -- those that iterate
(dividers by trial, the marked ruler), draw curves through points, cross them
or measure areas by array forms of their own beside the scalar ones.  An op
marked ``vector=False`` (none of the table's: one a caller adds) runs once per
set of givens instead (:func:`elementwise`), and the sweep's replay names it
(``Replay.elementwise``), so that a slow sweep says why.

>>> sorted(OPS)[:6]
['area_between', 'circle_radius', 'circle_segment', 'circle_through', 'french_curve', 'given_length']
>>> OPS["intersect"].inputs, OPS["intersect"].rule
(('curve', 'curve'), True)

Each entry also declares, as data, what a protocol file is checked against
when it is loaded (once, never in the replay loop): the kinds of object the
op makes (``outputs``) and the parameters it reads with their kinds
(``params``; a name ending in ``?`` may be left out).

>>> OPS["given_point"].check_params({"x": "abc", "y": 0.0})
"parameter 'x' must be a finite number, got 'abc'"
>>> OPS["intersect"].output_kinds({"rule": ["only"], "both": True})
('point', 'point')
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping

import numpy as np

from .areas import Area, area_between_op, planimeter_height_op, planimeter_op
from .closed_curves import closed_french_curve_op
from .curves import BezierCurve, Polyline, crossings, crossings_of_sweeps
from .curve_ops import french_curve_op, parabola_envelope_op, polyline_op, trace_op, vertex_op
from .errors import DegenerateObject, GeometryError, NoIntersection
from .geometry import (SCALAR, Circle, Length, Line, Point, Sweep, raw_circle, raw_point, circle_circle, line_circle,
                       line_line, sets_where, stack, take)
from .numeric import is_finite, shown
from .rules import choose, choose_among, choose_among_sets
from .trial import neusis_archimedes_op, trial_chord_op

__all__ = ["MAX_PARTS", "Op", "OPS", "KINDS", "OBJECT_KINDS", "ACCEPTS", "PARAM_KINDS", "kind_of", "elementwise"]

#: Input kinds an op declares, and the values that fill them.
KINDS: dict[str, tuple[type, ...]] = {
    "point": (Point,),
    "line": (Line,),
    "circle": (Circle,),
    "length": (Length,),
    "curve": (Line, Circle, Polyline, BezierCurve),
    "graph": (Line, Polyline, BezierCurve),
    "area": (Area,),
}

#: The kind of each object an op can make, by its type ("number": a planimeter's reading).
OBJECT_KINDS: dict[type, str] = {Point: "point", Line: "line", Circle: "circle", Length: "length",
                                 BezierCurve: "bezier", Polyline: "polyline", Area: "area", float: "number"}

#: Which object kinds fill each input kind (the same sets as KINDS, named by kind, for checking a file
#: before anything is evaluated).
ACCEPTS: dict[str, frozenset[str]] = {
    **{kind: frozenset(OBJECT_KINDS[t] for t in types) for kind, types in KINDS.items()},
    "any": frozenset(OBJECT_KINDS.values()),
}


def kind_of(obj: Any) -> str:
    """The kind of a made object: 'point', 'circle', ...

    >>> kind_of(Point(0.0, 1.0))
    'point'
    """
    return OBJECT_KINDS.get(type(obj), type(obj).__name__)


def _real(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _finite(v: Any) -> bool:
    return is_finite(v)  # a 400-digit integer from a file is not finite: it has no float


def _name(v: Any) -> bool:
    return isinstance(v, str) and v != ""


def _whole(v: Any) -> bool:
    return isinstance(v, int) and not isinstance(v, bool)


#: The most parts an instrument step divides into (dividers set by trial to 1/n of an arc; a segment
#: divided by the intercept theorem): as many as the finest semicircle division.  The dividers step
#: round n times per trial, so 10**7 parts in a file would run for minutes before failing.
MAX_PARTS = 3600

#: The kinds of step parameters: a test and what it asks for (for the error message).
PARAM_KINDS: dict[str, tuple[Callable[[Any], bool], str]] = {
    "number": (_finite, "a finite number"),
    "number|null": (lambda v: v is None or _finite(v), "a finite number or null"),
    "positive": (lambda v: _finite(v) and v > 0, "a finite number > 0"),
    "count": (lambda v: _whole(v) and v >= 1, "a whole number >= 1"),
    "count|zero": (lambda v: _whole(v) and v >= 0, "a whole number >= 0"),
    "parts": (lambda v: _whole(v) and 1 <= v <= MAX_PARTS, f"a whole number of parts 1..{MAX_PARTS}"),
    "flag": (lambda v: isinstance(v, bool), "true or false"),
    "given|null": (lambda v: v is None or _name(v), "the name of a given, or null"),
    "givens": (lambda v: isinstance(v, (list, tuple)) and all(_name(g) for g in v), "a list of names of givens"),
    "indices": (lambda v: isinstance(v, (list, tuple)) and all(_whole(i) and i >= 0 for i in v),
                "a list of whole numbers >= 0"),
    # the rule itself is read by construct.kernel.rules.as_rule, which says what is wrong with it
    "rule": (lambda v: True, "a rule"),
}


@dataclass(frozen=True)
class Op:
    """An operation: its function, the kinds of its inputs (a trailing ``*`` repeats the last), its rule."""

    name: str
    fn: Callable[..., tuple]
    inputs: tuple[str, ...]
    rule: bool = False
    vector: bool = True
    doc: str = ""
    #: The kinds of the objects it makes (a true ``both`` parameter makes two of each: both crossings).
    outputs: tuple[str, ...] = ("point",)
    #: The parameters it reads: name -> kind (PARAM_KINDS); a trailing "?" on the name: may be left out.
    params: Mapping[str, str] = field(default_factory=dict, hash=False)

    @functools.cached_property
    def _kinds(self) -> tuple[bool, tuple[str, ...]]:
        """Whether the last input kind repeats, and the kinds without the ``*`` (asked at every step of a build)."""
        kinds = self.inputs
        return bool(kinds) and kinds[-1].endswith("*"), tuple(k.rstrip("*") for k in kinds)

    def check_inputs(self, args: list) -> str | None:
        """None when *args* fit the declared kinds, else what is wrong (for the step's error)."""
        variadic, fixed = self._kinds
        if variadic:
            if len(args) < len(fixed) - 1:
                return f"takes at least {len(fixed) - 1} inputs, got {len(args)}"
        elif len(args) != len(fixed):
            return f"takes {len(fixed)} inputs ({', '.join(fixed)}), got {len(args)}"
        for i, a in enumerate(args):
            kind = fixed[min(i, len(fixed) - 1)]
            if kind == "any" or isinstance(a, Sweep):
                continue
            if not isinstance(a, KINDS[kind]):
                return f"input {i + 1} must be a {kind}, got {type(a).__name__}"
        return None

    # -- what a protocol file is checked against, before anything is evaluated --------------------
    def check_params(self, params: Mapping[str, Any]) -> str | None:
        """None when *params* are the ones this op reads, of the declared kinds; else what is wrong."""
        spec = self.params
        for key, value in params.items():
            kind = spec.get(key) or spec.get(f"{key}?")
            if kind is None:
                allowed = ", ".join(k.rstrip("?") for k in spec) or "none"
                return f"has no parameter {key!r} (it takes {allowed})"
            test, wanted = PARAM_KINDS[kind]
            if not test(value):
                return f"parameter {key!r} must be {wanted}, got {_short(value)}"
        for key in spec:
            if not key.endswith("?") and key not in params:
                return f"needs the parameter {key!r} ({PARAM_KINDS[spec[key]][1]})"
        return None

    def input_kinds(self, params: Mapping[str, Any], count: int) -> tuple[str, ...] | str:
        """The kind each of *count* inputs must have (params already checked), or what is wrong with the count."""
        if self.name == "french_curve":  # the axis, the points, then one tangent line per index in tangent_at
            n, at = params["points"], params["tangent_at"]
            if len(set(at)) != len(at) or any(i >= n for i in at):
                return f"'tangent_at' must name distinct points 0..{n - 1}, got {list(at)!r}"
            if n < 2:
                return f"draws a curve through at least 2 points, 'points' is {n}"
            want = 1 + n + len(at)
            if count != want:
                return f"takes {want} inputs (the axis, {n} points, {len(at)} tangents), got {count}"
            return ("line",) + ("point",) * n + ("line",) * len(at)
        if self.name == "smooth_loop" and params.get("points", count) != count:
            return f"'points' is {params['points']} but the step names {count} points"
        kinds = self.inputs
        fixed = [k.rstrip("*") for k in kinds]
        if kinds and kinds[-1].endswith("*"):
            if count < len(fixed) - 1:
                return f"takes at least {len(fixed) - 1} inputs ({', '.join(fixed[:-1])}, ...), got {count}"
            return tuple(fixed[:-1]) + (fixed[-1],) * (count - len(fixed) + 1)
        if count != len(fixed):
            return f"takes {len(fixed)} input{'s' if len(fixed) != 1 else ''} ({', '.join(fixed) or 'none'}), got {count}"
        return tuple(fixed)

    def output_kinds(self, params: Mapping[str, Any]) -> tuple[str, ...]:
        """The kinds of the objects a step of this op makes."""
        return self.outputs * 2 if params.get("both") else self.outputs


def _short(value: Any) -> str:
    return shown(value)


# --------------------------------------------------------------------------
# Givens.
# --------------------------------------------------------------------------


def _given_point(args, params, givens, refs, xp):
    unit = givens[params["unit"]] if params.get("unit") else 1.0
    return (Point(params["x"] * unit, params["y"] * unit),)


def _given_length(args, params, givens, refs, xp):
    value = float(params.get("factor", 1.0))
    for name in params["product"]:
        value = value * givens[name]
    return (Length(value),)


def _given_line(args, params, givens, refs, xp):
    (o,) = args
    a = xp.radians(params["angle_deg"])
    # A second point one unit away fixes the direction; the drawing extent is the renderer's business.
    return (Line(o, raw_point(o.x + xp.cos(a), o.y + xp.sin(a))),)


# --------------------------------------------------------------------------
# Straightedge, compass, dividers.
# --------------------------------------------------------------------------


def _line(args, params, givens, refs, xp):
    return (Line(args[0], args[1]),)


def _no_radius(what: str) -> DegenerateObject:
    return DegenerateObject(f"{what} has no radius (its two points coincide)")


def _circle_through(args, params, givens, refs, xp):
    c, p = args
    r = xp.hypot(p.x - c.x, p.y - c.y)
    if not (r > 0.0 if xp is SCALAR else np.all(r > 0.0)):  # written out: a call per circle is a tenth of it
        raise _no_radius(f"circle about {c!r} through {p!r}")
    return (raw_circle(c, r),)


def _circle_radius(args, params, givens, refs, xp):
    c, length = args
    return (raw_circle(c, length.value),)  # a Length is positive by construction


def _circle_segment(args, params, givens, refs, xp):
    c, a, b = args
    r = xp.hypot(b.x - a.x, b.y - a.y)
    if not (r > 0.0 if xp is SCALAR else np.all(r > 0.0)):
        raise _no_radius(f"compass set to {a!r}{b!r}")
    return (raw_circle(c, r),)


def _length_of(args, params, givens, refs, xp):
    a, b = args
    return (Length(xp.hypot(b.x - a.x, b.y - a.y)),)


def _circle_line(circle, line, xp):
    return line_circle(line, circle, xp)


def _line_line(a, b, xp):
    return (line_line(a, b, xp),)


#: Which core meets two curves of these kinds (the order of the points follows the first-named curve).
_MEET = {(Circle, Circle): circle_circle, (Line, Circle): line_circle, (Circle, Line): _circle_line,
         (Line, Line): _line_line}


def _intersect(args, params, givens, refs, xp):
    c1, c2 = args
    rule = params["rule"]
    core = _MEET.get((type(c1), type(c2)))
    if core is None:  # a drawn curve: any number of crossings
        if xp is not SCALAR:
            return _cross_curve_sweep(c1, c2, rule, refs, bool(params.get("both")), xp.n)
        return _cross_curve(c1, c2, rule, refs, bool(params.get("both")))
    pts = core(c1, c2, xp)
    if len(pts) == 1:
        chosen, other = pts[0], None
    else:
        if rule.name == "only":
            a, b = pts
            scale = c1.radius if type(c1) is Circle else c2.radius
            if xp.any(xp.hypot(a.x - b.x, a.y - b.y) > 1e-9 * scale):
                raise GeometryError("expected exactly one intersection, found 2")
        chosen, other = choose(pts, rule, refs, xp)
    if params.get("both"):
        return (chosen, other if other is not None else chosen)
    return (chosen,)


def _cross_curve(c1, c2, rule, refs, both):
    """A drawn curve crossed by a line: any number of crossings, one chosen by the rule."""
    curve, line = (c1, c2) if isinstance(c2, Line) else (c2, c1)
    if not isinstance(line, Line):
        raise GeometryError("a drawn curve can only be crossed with a straight line")
    pts = crossings(curve, line)
    if not pts:
        raise NoIntersection(f"{curve!r} and the line do not meet")
    chosen = choose_among(pts, rule, refs)
    if both:
        rest = [p for p in pts if p is not chosen]
        return (chosen, choose_among(rest, rule, refs) if rest else chosen)
    return (chosen,)


def _cross_curve_sweep(c1, c2, rule, refs, both, n):
    """_cross_curve for every set of a sweep at once (crossings_of_sweeps, choose_among_sets)."""
    curve, line = (c1, c2) if isinstance(c2, Line) else (c2, c1)
    if not isinstance(line, Line):
        raise GeometryError("a drawn curve can only be crossed with a straight line")
    xs, ys, found = crossings_of_sweeps(curve, line, n)
    none = ~found.any(axis=0)
    if none.any():
        raise NoIntersection(f"{curve!r} and the line do not meet{sets_where(none)}")
    sets = np.arange(n)
    row = choose_among_sets(xs, ys, found, rule, refs)
    chosen = raw_point(xs[row, sets], ys[row, sets])
    if not both:
        return (chosen,)
    rest = found.copy()
    rest[row, sets] = False
    other = np.where(rest.any(axis=0), choose_among_sets(xs, ys, rest, rule, refs), row)
    return (chosen, raw_point(xs[other, sets], ys[other, sets]))


def _pick(args, params, givens, refs, xp):
    """Of two constructed points, the one the rule names (the lower of two curves' points, say)."""
    chosen, _ = choose(tuple(args), params["rule"], refs, xp)
    return (chosen,)


def _step_off(args, params, givens, refs, xp):
    """Dividers: from a point, step a length off along a curve (no arc is drawn, a point is pricked)."""
    curve, start, length = args
    return _intersect((curve, raw_circle(start, length.value)), params, givens, refs, xp)


# --------------------------------------------------------------------------
# Sweeps of operations that only work on single values.
# --------------------------------------------------------------------------


def elementwise(fn: Callable[..., tuple]) -> Callable[..., tuple]:
    """Run *fn* once per set of givens of a sweep (``xp.n`` of them) and stack the results: how a sweep runs
    an op without an array form (``vector=False``; every op of the table has one)."""

    def run(args, params, givens, refs, xp):
        n = xp.n
        outs = []
        for i in range(n):
            outs.append(fn([take(a, i) for a in args], params, {k: take(v, i) for k, v in givens.items()},
                           [take(r, i) for r in refs], SCALAR))
        return tuple(stack([o[j] for o in outs]) for j in range(len(outs[0])))

    return run


# --------------------------------------------------------------------------
# The table.
# --------------------------------------------------------------------------

OPS: dict[str, Op] = {op.name: op for op in (
    Op("given_point", _given_point, (), params={"x": "number", "y": "number", "unit?": "given|null"},
       doc="a point given by its coordinates (times a given unit)"),
    Op("given_length", _given_length, (), outputs=("length",),
       params={"product": "givens", "factor?": "number"}, doc="a length given as a product of givens"),
    Op("given_line", _given_line, ("point",), outputs=("line",), params={"angle_deg": "number"},
       doc="a line through a point at a given angle"),
    Op("line", _line, ("point", "point"), outputs=("line",), doc="straightedge through two points"),
    Op("circle_through", _circle_through, ("point", "point"), outputs=("circle",), doc="compass about a point through a point"),
    Op("circle_radius", _circle_radius, ("point", "length"), outputs=("circle",),
       doc="compass about a point with a carried opening"),
    Op("circle_segment", _circle_segment, ("point", "point", "point"), outputs=("circle",),
       doc="compass opening taken from a segment"),
    Op("length_of", _length_of, ("point", "point"), outputs=("length",), doc="compass set to a segment"),
    Op("intersect", _intersect, ("curve", "curve"), rule=True, params={"rule": "rule", "both?": "flag"},
       doc="where two drawn curves cross"),
    Op("step_off", _step_off, ("curve", "point", "length"), rule=True,
       params={"rule": "rule", "both?": "flag"}, doc="dividers stepped along a curve"),
    Op("pick", _pick, ("point", "point"), rule=True, params={"rule": "rule"},
       doc="of two constructed points, the one a rule names (an envelope of two curves, point by point)"),
    Op("trial_chord", trial_chord_op, ("circle", "point", "point"), outputs=("length",),
       params={"parts": "parts", "tolerance": "positive"},
       doc="dividers set by trial to 1/n of an arc"),
    Op("neusis_archimedes", neusis_archimedes_op, ("point", "point", "point", "circle"), outputs=("point", "point"),
       doc="Archimedes' marked ruler slid into place"),
    Op("french_curve", french_curve_op, ("line", "point", "any*"), outputs=("bezier",),
       params={"points": "count", "tangent_at": "indices", "corners?": "indices"},
       doc="a smooth curve through points along tangents (the tangent lines follow the points), laid anew at corners"),
    Op("parabola_envelope", parabola_envelope_op, ("point", "point", "point"), outputs=("bezier",),
       doc="the parabola enveloped by the joins of equal divisions of ED and DF"),
    Op("polyline", polyline_op, ("point", "point", "point*"), outputs=("polyline",),
       params={"closed?": "flag"}, doc="points joined by the straightedge"),
    Op("trace", trace_op, ("point", "point", "point", "point"), outputs=("polyline",),
       params={"xs": "givens", "ps": "givens", "stroke": "givens", "stroke_factor?": "number", "pressure": "givens",
               "extend?": "flag", "closed?": "flag"},
       doc="a digitised diagram traced onto the drawing from its givens, its points joined by the straightedge"),
    Op("vertex", vertex_op, ("graph",), params={"index": "count|zero"},
       doc="a vertex of a drawn chain: the end of one of its chords"),
    Op("smooth_loop", closed_french_curve_op, ("point", "point", "point*"), outputs=("bezier",),
       params={"points?": "count"}, doc="a closed French curve through points in order"),
    Op("area_between", area_between_op, ("graph", "graph", "point", "point"), outputs=("area",),
       params={"hatch_deg?": "number|null"},
       doc="the region between two graphs between two abscissae"),
    Op("planimeter", planimeter_op, ("area",), outputs=("number",), doc="a planimeter's reading of an area"),
    Op("planimeter_height", planimeter_height_op, ("area", "point", "point"), outputs=("length",),
       doc="the mean height of an area over a base"),
)}
