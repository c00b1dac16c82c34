"""The marks' numbers over a whole sweep of the givens at once: what the drawing draws, value by value, in numpy.

A live player's sweep (:mod:`construct.live`) asks what the player draws at
hundreds of rod ratios.  :func:`~construct.render.scene.build_scene` and
:func:`~construct.render.svg.mark_geometry` answer for one value at a time (a scene of a thousand
marks: 15 to 30 ms); this module answers for every value of a sweep in one pass over the marks,
each mark's numbers a numpy column over the values.  It follows the drawing step by step -- the
figure's margin, each line drawn as far as the points marked on it, each circle as the arc over its
marked points (or whole), the broken axis, the letters' points on lettered lines, the bounding box,
the fit to the page, the numbers as the SVG writes them (two decimals) -- for the figures a live
player moves: points, lines, circles, arcs and curves, no hatched areas, no plate.

It answers only where it is sure to draw what the drawing draws: a value at which a mark changes its
form (an arc that closes into a whole circle, a curve of another number of points, two marked points
that coincide on a circle) is left out (:attr:`SweepDrawing.ok` false there), and the caller draws it
value by value.  The numbers may differ from the drawing's in the last written digit (numpy rounds
x * 100, the writer the exact decimal; hypot and atan2 may differ in the last bit): at most 0.01 px
(tests/test_render_sweepdraw.py holds them to that at 40 rod ratios across the domain; they agree there to
the last digit).
"""

from __future__ import annotations

import math
from itertools import compress
from typing import Any, Callable

import numpy as np

from ..kernel.curves import BezierCurve, Polyline
from ..kernel.geometry import Circle, Line, Point, Sweep, take
from .marks import GAP_TIE, TWO_PI, Mark, MarkKind, fanned_lines, letter_point, with_geom
from .paths import bezier_arrays
from .scene import MARGIN, Scene, on_curve_names
from .sheet import BREAK_FRACTION, BREAK_FRACTION_Y, BREAK_KEEP
from .svg import point_radius
from .styles import Style

__all__ = ["SweepDrawing", "sweep_drawable"]


def sweep_drawable(scene: Scene, style: Style | None = None, *, hatching: bool = True) -> bool:
    """Can :class:`SweepDrawing` draw *scene*'s figure over a sweep (points, lines, circles, arcs, curves and
    areas on axes that may be broken; no plate furniture, no hatching: a style that hatches draws its hatching
    value by value, as many lines as each area's size holds)?  *hatching* False: the caller draws no hatching
    (a live page draws its areas, hatching and all, from the curves that bound them), an area is its extent."""
    hatched = hatching and (style is None or style.hatch)
    return not scene.furniture and not (hatched and any(m.kind is MarkKind.AREA for m in scene.marks))


def _curve_rows(o: Any, n: int, vec: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A curve's drawn points (its ``curve_points``) at every value of a sweep: x and y (points x values), and
    how many points each value has (the rows past that are nan).  A French curve or a polyline whose points
    are the sweep's arrays is sampled for all values at once (BezierCurve.sample, Polyline.curve_points);
    another curve value by value."""
    if isinstance(o, BezierCurve):
        ctrl = np.stack([np.stack([np.stack([vec(p.x), vec(p.y)]) for p in seg]) for seg in o.segments()])
        t = np.arange(17)[:, None] / 16
        u = 1.0 - t
        weights = np.hstack([u ** 3, 3.0 * u * u * t, 3.0 * u * t * t, t ** 3])
        pts = np.einsum("tj,kjdn->ktdn", weights, ctrl)  # (segments, 17, 2, values)
        pts[:, 0], pts[:, -1] = ctrl[:, 0], ctrl[:, 3]
        flat = np.concatenate([pts[:, :-1].reshape(-1, 2, n), ctrl[-1:, 3]])
        return flat[:, 0], flat[:, 1], np.full(n, flat.shape[0])
    if isinstance(o, Polyline):
        pts = o.points + ((o.points[0],) if o.closed else ())
        X, Y = _stack([vec(p.x) for p in pts]), _stack([vec(p.y) for p in pts])
        return X, Y, np.full(n, len(pts))
    rows = [take(o, i).curve_points() for i in range(n)]
    counts = np.array([len(r) for r in rows])
    X, Y = np.full((counts.max(), n), np.nan), np.full((counts.max(), n), np.nan)
    for i, r in enumerate(rows):
        X[:len(r), i] = [p[0] for p in r]
        Y[:len(r), i] = [p[1] for p in r]
    return X, Y, counts


def _stack(rows: Any) -> np.ndarray:
    """Rows over the values (1-D arrays, each as long) as one array (rows x values): np.vstack's, without its
    Python for each row (a round stacks the rows of thousands of points and curve points)."""
    return np.array(rows, dtype=float)


def _rows(values: list, n: int) -> np.ndarray | None:
    """``np.array([vec(v) for v in values])``, vec a coordinate over the *n* values of a sweep (the sweep's own array,
    or one number for all), each number written into its row rather than made a row first (a round's points, lines
    and circles have thousands of coordinates the given does not move: a row apiece was a fifth of a round); None
    where an array is not of floats (the caller makes the rows one by one, as vec keeps it).

    >>> _rows([1.0, np.array([2.0, 3.0]), np.float64(4.0)], 2).tolist()
    [[1.0, 1.0], [2.0, 3.0], [4.0, 4.0]]
    """
    out = np.empty((len(values), n))
    swept = [type(v) is np.ndarray and v.shape == (n,) for v in values]
    arrays = list(compress(values, swept))
    if any(a.dtype != np.float64 for a in arrays):
        return None
    at = np.fromiter(swept, dtype=bool, count=len(values))
    if arrays:
        out[at] = arrays
    if len(arrays) < len(values):
        out[~at] = np.array([float(v) for v, a in zip(values, swept) if not a])[:, None]
    return out


def _r2(v: np.ndarray) -> np.ndarray:
    """Numbers as the SVG writer writes them (svgdoc.fmt: two decimals)."""
    return np.round(v, 2) + 0.0  # + 0.0: no -0


#: What an object is to a sweep's drawing, by its kind (:class:`SweepForm`): drawn as a curve, an area's extent (a
#: sweep's areas: their boxes without their pieces), an area's pieces (value by value), or nothing of its own.
CURVE, EXTENT, PIECES = "curve", "extent", "pieces"


def _role(o: Any) -> str | None:
    """What the object *o* of a sweep is to its drawing (CURVE, EXTENT, PIECES; None: a point, line or circle, or
    nothing drawn), from its first value."""
    if isinstance(o, (Point, Line, Circle)):
        return None
    first = take(o, 0)
    if hasattr(first, "rings"):  # an area's pieces count for the extent (marks.curve_points)
        return EXTENT if hasattr(o, "extent") else PIECES
    return CURVE if hasattr(first, "curve_points") else None


class SweepForm:
    """What a :class:`SweepDrawing` of the scene *template* over sweeps of *protocol* draws whatever the values:
    which mark is drawn from which object, over which of the points marked on it, in which block of rows, with
    which radius; the steps' marked points (:func:`~construct.render.scene.on_curve_names`) and fans of lettered
    lines.  Made from one sweep's *objects* (their names and kinds: every sweep of a protocol has the same), once
    for all the sweeps of a form (a live player's refinement draws a dozen rounds of one protocol:
    live.measure keeps the form with its scene), and asked of each sweep whether it fits (:meth:`fits`): the
    drawing's set-up was about half of a round's drawing, the values' arrays the rest.

    A mark the sweep does not draw: ValueError, as :class:`SweepDrawing` raises it.

    >>> from construct.constructions import get
    >>> from construct.render.output import scene_for
    >>> from construct.render.styles import STYLES
    >>> c = get("crank"); fig = c.figure(parts=3)
    >>> sweep = lambda v: fig.protocol.replay(c.rod_ratio_sweep(dict(fig.replay.givens), v))
    >>> scene = scene_for(c, fig)
    >>> form = SweepForm(scene, fig.protocol, sweep([3.0]), STYLES["teaching"])
    >>> d = SweepDrawing(scene, fig.protocol, sweep([3.0, 5.0]), 2, STYLES["teaching"], form=form)
    >>> d.form is form, d.numbers["s0001-O"].shape  # (another scene of the figure: a form of its own)
    (True, (2, 3))
    >>> SweepDrawing(scene_for(c, fig), fig.protocol, sweep([3.0, 5.0]), 2, STYLES["teaching"], form=form).form is form
    False
    """

    def __init__(self, template: Scene, protocol: Any, objects: Any, style: Style):
        self.template, self.protocol, self.style = template, protocol, style
        #: the objects' names and kinds, as every sweep this form draws has them (:meth:`fits`)
        self.names, self.kinds = tuple(objects), tuple(map(type, objects.values()))
        kind_of = dict(zip(self.names, self.kinds))
        #: which of the objects are points (itertools.compress of the objects' values), and their names
        self.is_point = tuple(issubclass(t, Point) for t in self.kinds)
        self.point_names = [k for k, p in zip(self.names, self.is_point) if p]
        self.point_rows = {k: i for i, k in enumerate(self.point_names)}
        roles = {k: r for (k, o), t in zip(objects.items(), self.kinds)
                 if not issubclass(t, (Point, Line, Circle)) and (r := _role(o)) is not None}
        #: the objects drawn as curves and areas, and what each is (:func:`_role`), in the objects' order
        self.roles = list(roles.items())
        # (a sweep of values of any kind, geometry.Sweep, is what its first value is: asked of every sweep, :meth:`fits`)
        self._swept = [(k, roles.get(k)) for k, t in kind_of.items() if issubclass(t, Sweep)]
        points = set(self.point_names)
        self.on = on_curve_names(protocol.steps, points)
        ids = {m.id for m in template.marks}
        #: a lettered straight line's letter point (marks.letter_lines): placed once the axis is broken
        self.at = {m.id + "-at" for m in template.marks if m.kind is MarkKind.CURVE and m.straight} & ids
        self.marks = [m for m in template.marks if m.id not in self.at]
        self.at_marks = [m for m in template.marks if m.id in self.at]
        self.in_fan = fanned_lines(protocol.steps)
        # _lay_out: each mark's block
        by: dict[MarkKind, list] = {k: [] for k in (MarkKind.POINT, MarkKind.SEGMENT, MarkKind.CIRCLE, MarkKind.ARC)}
        self.curved, pieces = [], set()
        for m in self.marks:
            t = kind_of.get(m.name)
            if m.kind is MarkKind.POINT and m.name in points:
                by[m.kind].append(self.point_rows[m.name])
            elif m.kind is MarkKind.SEGMENT and t is not None and issubclass(t, Line):
                by[m.kind].append((m.name, list(dict.fromkeys(self.on.get(m.name, [])))))
            elif m.kind.round and t is not None and issubclass(t, Circle):
                by[m.kind].append((m, m.name, list(dict.fromkeys(self.on.get(m.name, [])))))
            elif m.kind is MarkKind.AREA and roles.get(m.name) in (EXTENT, PIECES):
                if m.name not in pieces:
                    pieces.add(m.name)
                    self.curved.append(m)
            elif m.kind is MarkKind.CURVE and roles.get(m.name) == CURVE:
                self.curved.append(m)
            else:
                raise ValueError(f"{m.id}: a {m.kind.value} the sweep does not draw")
        #: the points' rows among the objects' points; the lines' names and, by how many points are marked on
        #: them, their rows and those points' rows; the circles' and arcs' so, and which are drawn whole
        self.point_marks = np.asarray(by[MarkKind.POINT], dtype=np.intp)
        self.lines = [name for name, _ in by[MarkKind.SEGMENT]]
        self.line_groups = [(idx, self._marked_rows(names)) for idx, names in _by_count(by[MarkKind.SEGMENT])]
        self.rounds: dict[MarkKind, tuple] = {}
        for kind in (MarkKind.CIRCLE, MarkKind.ARC):
            rounds = by[kind]
            whole = np.array([m.role == "result" or not names for m, _, names in rounds], dtype=bool)
            groups = []
            for idx, names in _by_count([r[1:] for r in rounds]):
                drawn = np.flatnonzero(~whole[idx])
                if drawn.size:
                    groups.append((idx[drawn], self._marked_rows([names[i] for i in drawn])))
            self.rounds[kind] = ([name for _, name, _ in rounds], whole, groups)
        curved = {m.id for m in self.curved}
        #: each kind's marks in its block (curves and areas aside), and their points' radii
        self.rows = {k: [m for m in self.marks if m.kind is k and m.id not in curved] for k in MarkKind}
        self.point_radii = np.array([[point_radius(m, style)] for m in self.rows[MarkKind.POINT]]).reshape(-1, 1)
        self.at_radii = np.array([[point_radius(m, style)] for m in self.at_marks]).reshape(-1, 1)
        self.curve_marks = [m for m in self.marks if m.id in curved]
        self.curve_mark = {m.id: m for m in self.curve_marks}
        #: the end state's (:meth:`SweepDrawing._end_numbers`): the points marked on its lines and circles, of the
        #: points it shows, and those points (by name)
        self.end_on: dict[str, list[str]] = {}
        self.shown_points: list[str] = []
        self.shown_rows = np.zeros(0, dtype=np.intp)
        if getattr(template, "end_marks", ()):
            shown = template.essentials
            self.end_on = on_curve_names(protocol.steps, points, set(shown))
            self.shown_points = [k for k in sorted(shown) if k in points]
            self.shown_rows = np.asarray([i for i, k in enumerate(self.point_names) if k in shown], dtype=np.intp)

    def _marked_rows(self, names: list[list[str]]) -> tuple[np.ndarray, tuple[int, int]]:
        """The rows among the points of the points *names* (as many for each row), and their shape (rows, points)."""
        shape = (len(names), len(names[0]) if names else 0)
        at = self.point_rows
        return np.fromiter((at[p] for row in names for p in row), dtype=np.intp, count=shape[0] * shape[1]), shape

    def fits(self, template: Scene, protocol: Any, objects: Any, style: Style) -> bool:
        """Whether this form draws the sweep *objects* of *protocol* as *template* in *style*: the same scene,
        protocol and style, and objects of the same names and kinds."""
        return (template is self.template and protocol is self.protocol and style is self.style
                and tuple(objects) == self.names and tuple(map(type, objects.values())) == self.kinds
                and all(_role(objects[k]) == r for k, r in self._swept))


class SweepDrawing:
    """The drawing's numbers at every value of a sweep: ``numbers[mark id]`` is a (values × numbers) array in
    the order :func:`~construct.render.svg.mark_geometry` writes them (an arc's as the live data reads it:
    drawn counter-clockwise on the page), ``extremes[mark id]`` its box (x0, x1, y0, y1 in drawing units),
    ``fit`` the page's (ox, oy, scale), ``size`` its (width, height), ``ok`` where all of it holds.

    *template* is the scene of one value (its marks, their order, kinds and ids); *objects* the sweep's replay.
    The marks of one kind are drawn together, as rows of one array (marks x values).

    >>> from construct.constructions import get
    >>> from construct.render.output import scene_for
    >>> from construct.render.styles import STYLES
    >>> c = get("crank"); fig = c.figure(parts=3)
    >>> sweep = fig.protocol.replay(c.rod_ratio_sweep(dict(fig.replay.givens), [3.0, 5.0]))
    >>> d = SweepDrawing(scene_for(c, fig), fig.protocol, sweep, 2, STYLES["teaching"])
    >>> d.ok.tolist(), d.numbers["s0001-O"].shape  # the crank centre O: cx, cy, r at both values
    ([True, True], (2, 3))
    """

    def __init__(self, template: Scene, protocol: Any, objects: Any, size: int, style: Style,
                 form: SweepForm | None = None):
        self.n = n = size
        self.style = style
        def vec(v: Any) -> np.ndarray:  # a coordinate over the values (a sweep's array, or one number for all)
            return v if type(v) is np.ndarray and v.shape == (n,) else np.full(n, float(v))

        self._vec = vec
        # what depends on the template and the protocol alone: the caller's *form* where it fits (made once for
        # all the sweeps of a protocol), made here else
        if form is None or not form.fits(template, protocol, objects, style):
            form = SweepForm(template, protocol, objects, style)
        #: what this drawing draws whatever the values (:class:`SweepForm`)
        self.form = form
        # a lettered straight line's letter point (marks.letter_lines): placed below, once the axis is broken
        self._at = form.at
        pts = list(compress(objects.values(), form.is_point))
        PX, PY = _rows([o.x for o in pts], n), _rows([o.y for o in pts], n)
        if PX is None or PY is None:  # (a coordinate not of floats: each point's own, as vec keeps it)
            points = dict(zip(form.point_names, ((vec(o.x), vec(o.y)) for o in pts)))
            PX, PY = _stack([p[0] for p in points.values()]), _stack([p[1] for p in points.values()])
        else:  # (each point's coordinates: its rows)
            points = dict(zip(form.point_names, zip(PX, PY)))
        on = form.on
        # the figure's extent before the marks are drawn: every point, every curve's points
        xs, ys = [PX], [PY]
        # every point's row in those (the points marked on lines and circles are gathered from them: _marked)
        self._point_rows = form.point_rows
        self._point_xy = (xs[0], ys[0])
        curves: dict[str, list[tuple]] = {}
        areas: dict[str, list[tuple]] = {}  # an area's pieces at each value, each a ring of points
        for name, role in form.roles:
            o = objects[name]
            if role == EXTENT:  # a sweep's areas: their boxes without their pieces
                areas[name] = x0, x1, y0, y1 = o.extent()
                xs += [np.vstack([x0, x1])]
                ys += [np.vstack([y0, y1])]
                continue
            if role == PIECES:
                rings = [[p for ring in take(o, i).rings() for p in ring] for i in range(n)]
                areas[name] = tuple(np.array([f(p[c] for p in r) for r in rings]) for c, f in
                                    ((0, min), (0, max), (1, min), (1, max)))
                rows = [tuple(r) for r in rings]
            else:
                curves[name] = _curve_rows(o, n, vec)
                CX, CY, counts = curves[name]
                if (counts > 0).all():
                    with np.errstate(invalid="ignore"):
                        xs += [np.vstack([np.nanmin(CX, 0), np.nanmax(CX, 0)])]
                        ys += [np.vstack([np.nanmin(CY, 0), np.nanmax(CY, 0)])]
                continue
            if rows and all(rows):
                xs += [np.array([[min(p[0] for p in r) for r in rows], [max(p[0] for p in r) for r in rows]])]
                ys += [np.array([[min(p[1] for p in r) for r in rows], [max(p[1] for p in r) for r in rows]])]
        X, Y = np.vstack(xs), np.vstack(ys)
        span = np.maximum(np.maximum(X.max(0) - X.min(0), Y.max(0) - Y.min(0)), 1e-9)
        margin = MARGIN * span
        # each mark's geometry, its kind's rows
        self.marks = form.marks
        self._sources = (objects, points, on, curves, areas)
        self._spans: dict[Any, tuple] = {}  # each end state line's marked span (the passes share them)
        self._kinds: dict[MarkKind, tuple] | None = None  # the marks' rows as far as the margin (:meth:`_lay_out`)
        self._arcs_reach: tuple | None = None  # the arcs' start angles and their reach (_ArcReach), made once for them
        self._draw(margin)
        if self._broken is not None:
            # scene.build_scene: a broken figure is drawn again with the margin of what is left of it (its
            # points and curves, broken alone), where it is broken so too
            kept = MARGIN * self._kept_span()
            smaller = self._broken & (kept < margin)
            if smaller.any():
                first = (self.geoms, self.curves, self._broken, self._breaks, self.ok)
                self._draw(np.where(smaller, kept, margin))
                # where the figure drawn so is not broken, it is drawn as before
                keep = smaller & self._broken
                margin = np.where(keep, kept, margin)
                if not keep[smaller].all():
                    self._choose(keep, first)
        self._letter_lines(template, protocol)
        ext = self._extremes()
        if self._broken is not None:  # the box of a broken figure: its points, where they now stand
            PX, PY = self.geoms[MarkKind.POINT]
            brk = self._broken
            bx0, bx1 = np.where(brk, PX.min(0), X.min(0)), np.where(brk, PX.max(0), X.max(0))
            by0, by1 = np.where(brk, PY.min(0), Y.min(0)), np.where(brk, PY.max(0), Y.max(0))
        else:
            bx0, bx1, by0, by1 = X.min(0), X.max(0), Y.min(0), Y.max(0)
        for e in ext.values():
            bx0, bx1 = np.minimum(bx0, e[0].min(0)), np.maximum(bx1, e[1].max(0))
            by0, by1 = np.minimum(by0, e[2].min(0)), np.maximum(by1, e[3].max(0))
        self._fit(bx0 - margin, by0 - margin, bx1 + margin, by1 + margin)
        self.extremes = {}
        self.numbers = {}
        for key, e in ext.items():
            for i, m in enumerate(self._members(key)):
                self.extremes[m.id] = (e[0][i], e[1][i], e[2][i], e[3][i])
        #: the boxes of :attr:`extremes` as four arrays (marks in its order x values: x0, x1, y0, y1), stacked from
        #: the kinds' blocks (a reader of every box takes them so, not mark by mark)
        blocks = list(ext.values()) if sum(len(e[0]) for e in ext.values()) == len(self.extremes) else \
            list(self.extremes.values())  # (a mark drawn twice: its last box, mark by mark)
        self.extreme_rows = tuple(np.concatenate([e[k] for e in blocks] or [np.zeros((0, n))]) for k in range(4))
        for key, nums in self._numbers().items():
            for i, m in enumerate(self._members(key)):
                self.numbers[m.id] = nums[i]
        #: the end state's own marks' boxes on the page of every value: {mark id: (x0, y0, x1, y1), each over the
        #: values} (canvas px: the end step's view frames them, live.measure)
        self.end_boxes: dict[str, tuple[np.ndarray, ...]] = {}
        #: the end state's own marks' geometry over the values, as their marks have it (drawing units, on the
        #: broken sheet): {mark id: (coordinate arrays)} (:meth:`end_marks_at`)
        self._end_geoms: dict[str, tuple[np.ndarray, ...]] = {}
        self.numbers.update(self._end_numbers(template, protocol))
        self._template = template
        self._end_rows: dict[Any, list[tuple[Mark, Any]]] = {}

    def end_marks_at(self, i: int, among: "Callable[[Mark], bool] | None" = None) -> list[Mark]:
        """The marks the end state draws at value *i* (the template's :meth:`~construct.render.scene.Scene.end_drawn`,
        each with its geometry at that value, drawing units on that value's broken sheet), as a scene built there
        has them (to the last bits of its arithmetic): what the end state's lettering is placed among, without a
        scene (80 ms) for every value.  (Its areas aside: the page draws them from the curves that bound them.)
        *among*: only the marks it holds for (the few a reader asks of, at every value of a sweep).

        >>> from construct.constructions import get
        >>> from construct.render.output import scene_for
        >>> from construct.render.styles import STYLES
        >>> c = get("crank"); fig = c.figure(parts=3)
        >>> sweep = fig.protocol.replay(c.rod_ratio_sweep(dict(fig.replay.givens), [3.0, 5.0]))
        >>> d = SweepDrawing(scene_for(c, fig, ending=True), fig.protocol, sweep, 2, STYLES["teaching"])
        >>> [m.geom for m in d.end_marks_at(1) if m.id == "s0001-O"] == [m.geom for m in scene_for(c, fig,
        ...     ending=True).end_drawn() if m.id == "s0001-O"]
        True
        """
        rows = self._end_rows.get(among)
        if rows is None:  # (a curve's points as one array, values first: each value's points are read at once)
            rows = self._end_rows[among] = [
                (m, np.stack([src[0].T, src[1].T], axis=-1) if type(src) is tuple else src)
                for m, src in self._end_sources() if among is None or among(m)]
        out = []
        for m, src in rows:
            if src.ndim == 3:  # a curve: its points (x, y) at each value
                out.append(with_geom(m, tuple(map(tuple, src[i].tolist()))))
            else:
                out.append(with_geom(m, tuple(src[:, i].tolist())))
        return out

    def _end_sources(self) -> list[tuple[Mark, Any]]:
        """Each mark of the end state but its areas with where its geometry stands over the values: an array
        (coordinates x values) or a curve's points (a tuple of x, y arrays)."""
        rows: dict[str, Any] = {}
        for kind, marks in self.rows.items():
            g = self.geoms[kind]
            if not g or not marks:
                continue
            cols = np.stack([np.broadcast_to(c, (len(marks), self.n)) for c in g], axis=1)
            rows.update((m.id, cols[r]) for r, m in enumerate(marks))
        for mid, pts in self.curves.items():
            rows[mid] = pts
        if getattr(self, "at_marks", None):
            x, y = self.at_geom
            rows.update((m.id, np.stack([x[r], y[r]])) for r, m in enumerate(self.at_marks))
        rows.update((mid, np.stack(g)) for mid, g in self._end_geoms.items())
        return [(m, rows[m.id]) for m in self._template.end_drawn() if m.kind is not MarkKind.AREA]

    def _end_numbers(self, template: Scene, protocol: Any) -> dict[str, np.ndarray]:
        """The end state's own marks (:mod:`construct.render.end_marks`: the plate's marks of the same objects, on
        this sheet's broken axes) over the sweep, as mark_geometry writes them: {mark id: (values x numbers)}.

        The plate draws each line and arc over the points it shows on it (those the construction marks there and
        every shown point lying on it), with the margin of what it shows (scene.build_scene, plate); a result
        circle whose shown points cover at most a half turn is that half circle (marks.circle_extent).  Which
        points lie on a curve is asked at every value: where it is not the built figure's choice, or a mark
        changes its kind, the value is not drawn here (:attr:`ok`)."""
        ends = getattr(template, "end_marks", ())
        if not ends:
            return {}
        objects, points, _, curves, areas = self._sources
        shown = template.essentials
        n, vec = self.n, self._vec
        # the plate's margin: of the points and curves it shows, unbroken
        rows = self.form.shown_rows  # (the shown points' rows among the points)
        xs = [self._point_xy[0][rows] if rows.size else np.zeros((1, n))]
        ys = [self._point_xy[1][rows] if rows.size else np.zeros((1, n))]
        with np.errstate(invalid="ignore"):
            for k, (CX, CY, _) in curves.items():
                if k in shown:
                    xs += [np.vstack([np.nanmin(CX, 0), np.nanmax(CX, 0)])]
                    ys += [np.vstack([np.nanmin(CY, 0), np.nanmax(CY, 0)])]
        for k, (x0, x1, y0, y1) in areas.items():
            if k in shown:
                xs += [np.vstack([vec(x0), vec(x1)])]
                ys += [np.vstack([vec(y0), vec(y1)])]
        X, Y = np.vstack(xs), np.vstack(ys)
        span = np.maximum(np.maximum(X.max(0) - X.min(0), Y.max(0) - Y.min(0)), 1e-9)
        margin = MARGIN * span
        if self._broken is not None:  # scene.build_scene: on a broken sheet, of what it spans there
            KX, KY = self._shifted(X, Y)
            kept = np.maximum(np.maximum(KX.max(0) - KX.min(0), KY.max(0) - KY.min(0)), 1e-9)
            margin = np.where(self._broken, np.minimum(margin, MARGIN * kept), margin)
        tol = 1e-9 * np.maximum(span, 1.0)
        on, shown_pts = self.form.end_on, self.form.shown_points
        # the shown points as rows (points x values): which of them lie on a mark is asked of all at once
        shown_xy = tuple(_stack([points[k][c] for k in shown_pts]) for c in (0, 1)) if shown_pts else None
        lines_too = bool(protocol.params.get("plate"))
        out: dict[str, np.ndarray] = {}
        st, scale = self.style, self._page[2]
        for m in ends:
            obj = objects.get(m.name)
            marked = [points[p] for p in dict.fromkeys(on.get(m.name, []))]
            if shown_xy is not None and (isinstance(obj, Circle) or (isinstance(obj, Line) and lines_too)):
                # every shown point lying on it, as the built figure found them (elsewhere: value by value)
                lying = self._lies_on(obj, shown_xy, tol)
                every = lying.all(axis=1)
                for at in np.flatnonzero(lying.any(axis=1)).tolist():  # (a point on it nowhere does nothing)
                    k = shown_pts[at]
                    if k in on.get(m.name, []):
                        continue
                    near = lying[at]
                    if every[at] or marked:
                        # (where it does not lie on it: a point marked there already, twice, which draws the same)
                        marked.append(points[k] if every[at] else
                                      tuple(np.where(near, points[k][c], marked[0][c]) for c in (0, 1)))
                    else:
                        self.ok &= ~near
            if m.kind is MarkKind.POINT and m.name in points:
                x, y = self._shifted(*points[m.name])
                self._end_geoms[m.id] = (x, y)
                px, py = self._px(x, y)
                out[m.id] = np.stack([_r2(c) for c in (px, py, np.full(n, point_radius(m, st)))], -1)
                self.end_boxes[m.id] = (px, py, px, py)
            elif m.kind is MarkKind.SEGMENT and isinstance(obj, Line):
                x1, y1, x2, y2 = self._segment(obj, marked, margin, key=m.id)
                (x1, y1), (x2, y2) = self._shifted(x1, y1), self._shifted(x2, y2)
                self._end_geoms[m.id] = (x1, y1, x2, y2)
                (x1, y1), (x2, y2) = self._px(x1, y1), self._px(x2, y2)
                out[m.id] = np.stack([_r2(c) for c in (x1, y1, x2, y2)], -1)
                self.end_boxes[m.id] = (np.minimum(x1, x2), np.minimum(y1, y2), np.maximum(x1, x2), np.maximum(y1, y2))
            elif m.kind.round and isinstance(obj, Circle):
                cx, cy, r = vec(obj.center.x), vec(obj.center.y), vec(obj.radius)
                if m.role == "result" or not marked:
                    geom, kind = (cx, cy, r, np.zeros(n), np.full(n, TWO_PI)), np.full(n, m.kind is MarkKind.CIRCLE)
                    if m.role == "result" and len(marked) >= 3:  # the book's half circle over the stroke
                        a0, sw, ok = self._arc_over(cx, cy, marked)
                        half = ok & (sw <= math.pi * (1.0 + 1e-9))
                        geom = (cx, cy, r, np.where(half, a0, 0.0), np.where(half, sw, TWO_PI))
                        kind = np.where(half, m.kind is MarkKind.ARC, kind)
                else:
                    a0, sw, ok = self._arc_over(cx, cy, marked)
                    pad = np.minimum(margin / r, 0.6)
                    a0, sw = a0 - pad, sw + 2.0 * pad
                    self.ok &= ok
                    kind = (sw >= 0.92 * TWO_PI) == (m.kind is MarkKind.CIRCLE)
                    geom = (cx, cy, r, a0, sw)
                self.ok &= kind
                cx, cy, r, a0, sw = geom
                if m.kind is MarkKind.CIRCLE:
                    x, y = self._shifted(cx + r, cy + r, centre=(cx, cy))
                    self._end_geoms[m.id] = (x, y, r)
                    px, py = self._px(x, y)
                    out[m.id] = np.stack([_r2(c) for c in (px, py, r * scale)], -1)
                    self.end_boxes[m.id] = (px - r * scale, py - r * scale, px + r * scale, py + r * scale)
                    continue
                bx0, bx1, by0, by1 = _arc_box(cx, cy, r, a0, sw)
                sx, sy = self._shifted(bx1, by1, centre=(cx, cy))  # (where the break moves its centre)
                (ax0, ay0), (ax1, ay1) = self._px(bx0 + sx - cx, by1 + sy - cy), self._px(bx1 + sx - cx, by0 + sy - cy)
                self.end_boxes[m.id] = (ax0, ay0, ax1, ay1)
                cx, cy = sx, sy
                self._end_geoms[m.id] = (cx, cy, r, a0, sw)
                x0, y0 = self._px(cx + r * np.cos(a0), cy + r * np.sin(a0))
                x1, y1 = self._px(cx + r * np.cos(a0 + sw), cy + r * np.sin(a0 + sw))
                rr = r * scale
                out[m.id] = np.stack([_r2(c) for c in (x1, y1, rr, rr, 0.0 * rr, (sw > math.pi) * 1.0, 0.0 * rr + 1.0,
                                                       x0, y0)], -1)
            else:
                raise ValueError(f"{m.id}: an end state's {m.kind.value} the sweep does not draw")
        return out

    def _lies_on(self, curve: Any, p: tuple, tol: np.ndarray) -> np.ndarray:
        """marks.lies_on over the sweep: where point *p* (x, y arrays: values, or points x values) lies on *curve*."""
        vec = self._vec
        if isinstance(curve, Circle):
            cx, cy, r = vec(curve.center.x), vec(curve.center.y), vec(curve.radius)
            return np.abs(np.hypot(p[0] - cx, p[1] - cy) - r) <= tol * np.maximum(1.0, r)
        px, py, qx, qy = vec(curve.p.x), vec(curve.p.y), vec(curve.q.x), vec(curve.q.y)
        d = np.hypot(qx - px, qy - py)
        return np.abs((qx - px) * (p[1] - py) - (qy - py) * (p[0] - px)) / d <= tol

    def _shifted(self, x: np.ndarray, y: np.ndarray, centre: tuple | None = None) -> tuple[np.ndarray, np.ndarray]:
        """sheet.break_shift over the sweep: (x, y) moved as the broken axes move what lies before their gaps;
        with *centre*, (x, y) is a round mark's far point (rightmost, lowest: sheet.moved_geom) and the centre is
        moved by what it moves."""
        out = [x, y]
        for axis, (brk, start, keep, width) in self._breaks.items():
            v = out[axis]
            out[axis] = np.where(brk & (v <= start + keep - width), v + (width - keep), v)
        if centre is None:
            return out[0], out[1]
        return centre[0] + (out[0] - x), centre[1] + (out[1] - y)

    def _kept_span(self) -> np.ndarray:
        """sheet.kept_span over the sweep: what the points and curves span once broken alone."""
        objects, points, on, curves, areas = self._sources
        P = tuple(_stack(c) for c in zip(*[points[m.name] for m in self.marks
                                               if m.kind is MarkKind.POINT and m.name in points]))
        saved = (self.geoms, self.curves, self._broken, self._breaks)
        self.geoms = {k: (P if k is MarkKind.POINT else ()) for k in MarkKind}
        self.curves = dict(self._unbroken_curves)
        self._broken, self._breaks = None, {}
        self._break(axis=1, ext=self._break())
        cx = [self.geoms[MarkKind.POINT][0]] + [X for X, _ in self.curves.values()]
        cy = [self.geoms[MarkKind.POINT][1]] + [Y for _, Y in self.curves.values()]
        self.geoms, self.curves, self._broken, self._breaks = saved
        KX, KY = np.vstack(cx), np.vstack(cy)
        with np.errstate(invalid="ignore"):  # (a curve of another number of points: not ok there)
            return np.maximum(np.maximum(np.nanmax(KX, 0) - np.nanmin(KX, 0), np.nanmax(KY, 0) - np.nanmin(KY, 0)),
                              1e-9)

    def _choose(self, which: np.ndarray, other: tuple) -> None:
        """This drawing at the values *which* says, *other* (geoms, curves, broken, breaks, ok) elsewhere."""
        geoms, curves, broken, breaks, ok = other
        pick = lambda a, b: np.where(which, a, b)  # noqa: E731
        self.geoms = {k: tuple(pick(a, b) for a, b in zip(self.geoms[k], geoms[k])) for k in MarkKind}
        self.curves = {mid: (pick(X, curves[mid][0]), pick(Y, curves[mid][1])) for mid, (X, Y) in self.curves.items()}
        self._broken = pick(self._broken, broken if broken is not None else False)
        for axis in set(self._breaks) | set(breaks):
            a = self._breaks.get(axis, (np.zeros(self.n, dtype=bool),) + (np.zeros(self.n),) * 3)
            b = breaks.get(axis, (np.zeros(self.n, dtype=bool),) + (np.zeros(self.n),) * 3)
            self._breaks[axis] = tuple(pick(x, y) for x, y in zip(a, b))
        self.ok = pick(self.ok, ok)

    def _draw(self, margin: np.ndarray) -> None:
        """The marks' geometry with lines and arcs reaching *margin* past their marked points, broken."""
        objects, points, on, curves, areas = self._sources
        n, vec = self.n, self._vec
        self.ok = np.ones(n, dtype=bool)
        if self._kinds is None:  # (what does not depend on the margin: made once, for both passes)
            self._kinds = self._lay_out()
        curve_geoms: dict[str, tuple] = {}
        for m in self.form.curved:
            if m.kind is MarkKind.AREA:
                # an area's pieces come and go and hold as many points as their curves' breakpoints: the page
                # draws them from those curves (live.py areaPieces); here they count for the figure's extent, as
                # the box of all its pieces (two corners, broken point by point as the pieces are), on its first
                x0, x1, y0, y1 = areas[m.name]
                curve_geoms[m.id] = (_stack([vec(x0), vec(x1)]), _stack([vec(y0), vec(y1)]))
                continue
            CX, CY, counts = curves[m.name]
            count = len(m.geom)
            self.ok &= counts == count
            if CX.shape[0] < count:  # (nowhere as many points as the built figure's: not drawn here)
                CX = np.vstack([CX, np.full((count - CX.shape[0], n), np.nan)])
                CY = np.vstack([CY, np.full((count - CY.shape[0], n), np.nan)])
            ok = counts == count
            # (its points as rows: x and y, points x values)
            curve_geoms[m.id] = (np.where(ok, CX[:count], np.nan), np.where(ok, CY[:count], np.nan))
        self.geoms = {k: () for k in MarkKind}
        for kind, got in self._kinds.items():
            if kind is MarkKind.POINT:
                self.geoms[kind] = got
            elif kind is MarkKind.SEGMENT:
                self.geoms[kind] = _lines_reaching(got, margin)
            else:
                self.geoms[kind] = self._round(kind, got, margin)
        self.rows = self.form.rows
        self.curves = curve_geoms
        self._unbroken_curves = dict(curve_geoms)
        self.curve_marks = self.form.curve_marks
        self._curve_mark = self.form.curve_mark
        self._broken = None
        #: per axis: (broken at which values, where the drawn break starts, its drawn width, what it leaves out)
        self._breaks: dict[int, tuple] = {}
        self._break(axis=1, ext=self._break())

    def _lay_out(self) -> dict[MarkKind, tuple]:
        """Each kind's marks as rows of arrays (marks x values), as far as the margin leaves them: the points'
        (x, y); the lines' spans over their marked points (:func:`_line_spans`); the circles' and arcs' centres and
        radii, and the arcs over their marked points (:func:`_arcs_over`).  The curves and areas are left to
        :meth:`_draw` (the form's ``curved``, the first piece of each area).  (Which mark is in which block, over
        which points: :class:`SweepForm`.)"""
        objects = self._sources[0]
        form, vec = self.form, self._vec
        X, Y = self._point_xy
        out: dict[MarkKind, tuple] = {}
        if form.point_marks.size:
            out[MarkKind.POINT] = (X[form.point_marks], Y[form.point_marks])
        if form.lines:
            lines = list(map(objects.__getitem__, form.lines))
            P = _rows([c for o in lines for c in (o.p.x, o.p.y, o.q.x, o.q.y)], self.n)
            P = np.array([[vec(o.p.x), vec(o.p.y), vec(o.q.x), vec(o.q.y)] for o in lines]) if P is None else \
                P.reshape(len(lines), 4, self.n)
            spans = np.empty((7,) + P[:, 0].shape)
            for idx, marked in form.line_groups:
                spans[:, idx] = _line_spans(P[idx], *self._marked(marked))
            out[MarkKind.SEGMENT] = (*spans[:6], spans[6].astype(bool))
        for kind in (MarkKind.CIRCLE, MarkKind.ARC):
            names, whole, groups = form.rounds[kind]
            if not names:
                continue
            rounds = list(map(objects.__getitem__, names))
            C = _rows([c for o in rounds for c in (o.center.x, o.center.y, o.radius)], self.n)
            C = np.array([[vec(o.center.x), vec(o.center.y), vec(o.radius)] for o in rounds]) if C is None else \
                C.reshape(len(rounds), 3, self.n)
            # whole: a result, or a circle with no point marked on it
            arcs = np.zeros((3,) + C[:, 0].shape)
            arcs[2] = 1.0
            for idx, marked in groups:
                arcs[:, idx] = _arcs_over(C[idx, 0], C[idx, 1], *self._marked(marked))
            out[kind] = (C[:, 0], C[:, 1], C[:, 2], whole, arcs[0], arcs[1], arcs[2].astype(bool))
        return out

    def _marked(self, marked: tuple[np.ndarray, tuple[int, int]]) -> tuple[np.ndarray, np.ndarray]:
        """The points marked on lines or circles, as many on each (their rows among the points and the shape,
        :meth:`SweepForm._marked_rows`), as arrays (rows x points x values): x and y."""
        rows, shape = marked
        X, Y = self._point_xy
        return X[rows].reshape(shape + (self.n,)), Y[rows].reshape(shape + (self.n,))

    def _round(self, kind: MarkKind, got: tuple, margin: np.ndarray) -> tuple:
        """marks.circle_extent over the sweep for all the circles (or all the arcs) at once: whole, or the arc over
        its marked points and the margin; a value where the arc would be whole (or a whole one an arc) is not drawn
        here."""
        cx, cy, r, whole, start, sweep, sure = got
        if whole.any() and kind is not MarkKind.CIRCLE:  # an arc drawn whole: not by the sweep
            self.ok[:] = False
        over = ~whole
        if over.any():
            self.ok &= sure[over].all(axis=0)
            pad = np.minimum(margin / r[over], 0.6)
            start, sweep = start.copy(), sweep.copy()
            start[over], sweep[over] = start[over] - pad, sweep[over] + 2.0 * pad
            full = sweep[over] >= 0.92 * TWO_PI
            self.ok &= full.all(axis=0) if kind is MarkKind.CIRCLE else ~full.any(axis=0)
        return (cx, cy, r) if kind is MarkKind.CIRCLE else (cx, cy, r, start, sweep)

    def _members(self, key) -> list:
        """The marks of one row block: a kind's marks, or one curve (its id), or the lettered lines' points."""
        if isinstance(key, MarkKind):
            return self.rows[key]
        return [self._curve_mark[key]] if key != "-at" else self.at_marks

    # -- the marks ---------------------------------------------------------------------------------------
    def _segment(self, line: Line, marked: list, margin: np.ndarray, key: Any) -> tuple:
        """marks.segment_extent over the sweep: the line as far as its marked points (x, y arrays), and a margin
        (*key*: its marked span's, made once)."""
        got = self._spans.get(key)
        if got is None:  # (its marked points' span does not depend on the margin: made once, for both passes)
            vec = self._vec
            P = np.array([[vec(line.p.x), vec(line.p.y), vec(line.q.x), vec(line.q.y)]])
            X, Y = (np.array([[p[c] for p in marked]]).reshape(1, len(marked), self.n) for c in (0, 1))
            got = self._spans[key] = tuple(a[0] for a in _line_spans(P, X, Y))
        return _lines_reaching(got, margin)

    def _arc_over(self, cx: np.ndarray, cy: np.ndarray, marked: list) -> tuple:
        """The arc over a circle's marked points (x, y arrays), before its margin: (start, sweep, where it is sure)."""
        X, Y = (np.array([[p[c] for p in marked]]).reshape(1, len(marked), self.n) for c in (0, 1))
        return tuple(a[0] for a in _arcs_over(cx[None], cy[None], X, Y))

    def _extremes(self) -> dict:
        """scene.extreme_points over the sweep, as boxes: {block: (x0, x1, y0, y1)}, each (marks x values)."""
        out: dict[Any, tuple] = {}
        g = self.geoms
        if g[MarkKind.POINT]:
            x, y = g[MarkKind.POINT]
            out[MarkKind.POINT] = (x, x, y, y)
        if g[MarkKind.SEGMENT]:
            x1, y1, x2, y2 = g[MarkKind.SEGMENT]
            out[MarkKind.SEGMENT] = (np.minimum(x1, x2), np.maximum(x1, x2), np.minimum(y1, y2), np.maximum(y1, y2))
        if g[MarkKind.CIRCLE]:
            cx, cy, r = g[MarkKind.CIRCLE]
            out[MarkKind.CIRCLE] = (cx - r, cx + r, cy - r, cy + r)
        if g[MarkKind.ARC]:
            cx, cy, r, a0, sw = g[MarkKind.ARC]
            if self._arcs_reach is None or self._arcs_reach[0] is not a0:  # (a broken axis moves only the centres)
                self._arcs_reach = (a0, _ArcReach(r, a0, sw))
            out[MarkKind.ARC] = self._arcs_reach[1].box(cx, cy)
        for m in self.curve_marks:
            X, Y = self.curves[m.id]
            out[m.id] = (X.min(0)[None], X.max(0)[None], Y.min(0)[None], Y.max(0)[None])
        if getattr(self, "at_marks", None):
            x, y = self.at_geom
            out["-at"] = (x, x, y, y)
        return out

    # -- the broken axis, the lettered lines ---------------------------------------------------------------
    def _break(self, axis: int = 0, ext: dict | None = None) -> dict | None:
        """sheet.broken_axis over the sweep: the widest empty stretch broken out where it is wider than a fifth
        (*axis* 1: across the figure, where wider than BREAK_FRACTION_Y).  *ext*: the marks' extremes, if the
        caller has them as they are now; returned where nothing was broken (the next axis reads them so)."""
        ext = self._extremes() if ext is None else ext
        lo_at, hi_at = (0, 1) if axis == 0 else (2, 3)
        spans = [(e[lo_at], e[hi_at]) for key, e in ext.items() if key is not MarkKind.SEGMENT
                 and not (key in self.curves and self._members(key)[0].straight and len(self.curves[key][0]) == 2)]
        if sum(s.shape[0] for s, _ in spans) < 2:
            return ext
        S, E = np.concatenate([s for s, _ in spans]), np.concatenate([e for _, e in spans])  # (blocks of rows)
        lo, hi, width, total = _widest_gaps(S, E)
        brk = (width > 0) & (width > (BREAK_FRACTION if axis == 0 else BREAK_FRACTION_Y) * total)
        if not brk.any():
            return ext
        keep = np.minimum(BREAK_KEEP * (total - width), 0.8 * width)
        shift = np.where(brk, width - keep, 0.0)
        sx = lambda x: np.where(brk & (x <= lo), x + shift, x)  # noqa: E731
        end = lambda x: np.where(brk & (x <= (lo + hi) / 2), x + shift, x)  # noqa: E731  (a line's end)
        g = self.geoms
        if g[MarkKind.POINT]:
            p = g[MarkKind.POINT]
            g[MarkKind.POINT] = (sx(p[0]), p[1]) if axis == 0 else (p[0], sx(p[1]))
        if g[MarkKind.SEGMENT]:
            x1, y1, x2, y2 = g[MarkKind.SEGMENT]
            g[MarkKind.SEGMENT] = (end(x1), y1, end(x2), y2) if axis == 0 else (x1, end(y1), x2, end(y2))
        for kind in (MarkKind.CIRCLE, MarkKind.ARC):  # moved whole, or not at all
            if g[kind]:
                moved = brk & (ext[kind][hi_at] <= lo)
                c = list(g[kind])
                c[axis] = np.where(moved, c[axis] + shift, c[axis])
                g[kind] = tuple(c)
        for mid, (X, Y) in self.curves.items():  # (every point of a curve at once: rows of points)
            self.curves[mid] = (sx(X), Y) if axis == 0 else (X, sx(Y))
        self._broken = brk if self._broken is None else (self._broken | brk)
        self._breaks[axis] = (brk, hi - keep, keep, width)
        return None

    def _letter_lines(self, template: Scene, protocol: Any) -> None:
        """marks.letter_lines over the sweep: each lettered straight line's letter point (value by value: a
        handful of lines)."""
        in_fan = self.form.in_fan
        self.at_marks = self.form.at_marks
        xs, ys = [], []
        for m in self.at_marks:
            LX, LY = (c.T.tolist() for c in self.curves[m.id[:-3]])  # (each value's points: a row)
            fan = in_fan.get(m.name[:-3], False)
            ats = []
            for i in range(self.n):
                pts = tuple(zip(LX[i], LY[i]))
                breaks = [(float(b[1][i]), float(b[2][i]), float(b[3][i]), axis)
                          for axis, b in sorted(self._breaks.items()) if b[0][i]]
                ats.append(letter_point(pts, fan, breaks))
            xs.append([a[0] for a in ats])
            ys.append([a[1] for a in ats])
        if self.at_marks:
            self.at_geom = (np.array(xs, dtype=float), np.array(ys, dtype=float))

    # -- the page ----------------------------------------------------------------------------------------
    def _fit(self, x0, y0, x1, y1) -> None:
        """Viewport.fit over the sweep (no caption lines: the player writes its captions in HTML)."""
        st = self.style
        inner = st.width_px - 2 * st.margin_px
        scale = inner / np.maximum(x1 - x0, 1e-12)
        max_h = 1.4 * st.width_px
        scale = np.where((y1 - y0) * scale > max_h, max_h / (y1 - y0), scale)
        left = (inner - (x1 - x0) * scale) / 2.0
        drawing_h = np.maximum((y1 - y0) * scale, st.min_drawing_px)
        top = (drawing_h - (y1 - y0) * scale) / 2.0
        self._page = (x0, y1, scale, left, top)
        m = st.margin_px
        self.fit = np.column_stack([m + left - x0 * scale, m + top + y1 * scale, scale])
        self.size = (np.full(self.n, float(st.width_px)), drawing_h + 2 * m)

    def page_px(self, x, y) -> tuple[np.ndarray, np.ndarray]:
        """Points (drawing units) on the page of every value (Viewport.px over the sweep)."""
        return self._px(x, y)

    def px_at(self, i: int, x: float, y: float) -> tuple[float, float]:
        """A point (drawing units) on the page of value *i*."""
        xmin, ymax, scale, left, top = (float(v[i]) for v in self._page)
        m = self.style.margin_px
        return m + left + (x - xmin) * scale, m + top + (ymax - y) * scale

    def px_of(self, i: int):
        """:meth:`px_at` of value *i* as a function of a point (its page's numbers read once)."""
        xmin, ymax, scale, left, top = (float(v[i]) for v in self._page)
        x0, y0 = self.style.margin_px + left, self.style.margin_px + top
        return lambda x, y: (x0 + (x - xmin) * scale, y0 + (ymax - y) * scale)

    def breaks_at(self, i: int) -> tuple[tuple[float, float, float, int], ...]:
        """Value *i*'s breaks as a scene has them (:attr:`construct.render.scene.Scene.breaks`: where the drawn
        break starts, its drawn width, the length it leaves out, its axis)."""
        return tuple((float(b[1][i]), float(b[2][i]), float(b[3][i]), axis)
                     for axis, b in sorted(self._breaks.items()) if b[0][i])

    def breaks_page(self) -> np.ndarray:
        """:meth:`breaks_px` of every value: (values x 4)."""
        out = []
        for axis in (0, 1):
            b = self._breaks.get(axis)
            if b is None:
                out += [np.zeros(self.n), np.zeros(self.n)]
                continue
            brk, start, keep = b[0], b[1], b[2]
            at = self._px(start, 0.0)[0] if axis == 0 else self._px(0.0, start + keep)[1]
            out += [np.where(brk, np.round(at, 2), 0.0), np.where(brk, np.round(self._page[2] * keep, 2), 0.0)]
        return np.column_stack(out) + 0.0

    def breaks_px(self, i: int) -> list[float]:
        """Where value *i*'s breaks stand on its page: [x, width, top, height] of their bands (canvas px, two
        decimals), 0 0 for an axis not broken there (live.measure.breaks_px)."""
        out: list[float] = []
        scale = float(self._page[2][i])
        for axis in (0, 1):
            b = self._breaks.get(axis)
            if b is None or not b[0][i]:
                out += [0.0, 0.0]
                continue
            start, keep = float(b[1][i]), float(b[2][i])
            at = self.px_at(i, start, 0.0)[0] if axis == 0 else self.px_at(i, 0.0, start + keep)[1]
            out += [round(at, 2), round(scale * keep, 2)]
        return out

    def _px(self, x, y) -> tuple[np.ndarray, np.ndarray]:
        xmin, ymax, scale, left, top = self._page
        m = self.style.margin_px
        return m + left + (x - xmin) * scale, m + top + (ymax - y) * scale

    def _numbers(self) -> dict:
        """Every mark's numbers as mark_geometry writes them (an arc's drawn counter-clockwise on the page):
        {block: (marks x values x numbers)}."""
        g, out = self.geoms, {}
        scale = self._page[2]
        stack = lambda *cols: np.stack([_r2(c) for c in cols], axis=-1)  # noqa: E731
        if g[MarkKind.POINT]:
            x, y = self._px(*g[MarkKind.POINT])
            r = self.form.point_radii + np.zeros(x.shape)
            out[MarkKind.POINT] = stack(x, y, r)
        if g[MarkKind.SEGMENT]:
            x1, y1, x2, y2 = g[MarkKind.SEGMENT]
            out[MarkKind.SEGMENT] = stack(*self._px(x1, y1), *self._px(x2, y2))
        if g[MarkKind.CIRCLE]:
            cx, cy, r = g[MarkKind.CIRCLE]
            out[MarkKind.CIRCLE] = stack(*self._px(cx, cy), r * scale)
        if g[MarkKind.ARC]:
            cx, cy, r, a0, sw = g[MarkKind.ARC]
            x0, y0 = self._px(cx + r * np.cos(a0), cy + r * np.sin(a0))
            x1, y1 = self._px(cx + r * np.cos(a0 + sw), cy + r * np.sin(a0 + sw))
            rr = r * scale
            out[MarkKind.ARC] = stack(x1, y1, rr, rr, 0.0 * rr, (sw > math.pi) * 1.0, 0.0 * rr + 1.0, x0, y0)
        for m in self.curve_marks:
            if m.kind is MarkKind.AREA:  # (the page draws areas from their curves)
                continue
            X, Y = self._px(*self.curves[m.id])  # points x values
            k = X.shape[0]
            if m.straight:
                closed = k > 2 and tuple(m.geom[0]) == tuple(m.geom[-1])
                cols = np.stack([X, Y], axis=1)[:k - 1 if closed else k].reshape(-1, self.n)
            else:
                # the smooth curve's control points (paths.bezier_arrays), every segment at once
                _, c1x, c2x, p2x = bezier_arrays(X)
                _, c1y, c2y, p2y = bezier_arrays(Y)
                segs = np.stack([c1x, c1y, c2x, c2y, p2x, p2y], axis=1)
                cols = np.concatenate([X[:1], Y[:1], segs.reshape(-1, self.n)])
            out[m.id] = _r2(cols.T)[None]
        if getattr(self, "at_marks", None):
            x, y = self._px(*self.at_geom)
            r = self.form.at_radii + np.zeros(x.shape)
            out["-at"] = stack(x, y, r)
        return out


def _by_count(rows: list[tuple]) -> list[tuple[np.ndarray, list[list[str]]]]:
    """The rows (each an object and the names of the points marked on it) grouped by how many points: (their
    indices, their names), each group a block of arrays of one shape."""
    groups: dict[int, list[int]] = {}
    for i, (_, names) in enumerate(rows):
        groups.setdefault(len(names), []).append(i)
    return [(np.asarray(idx), [rows[i][1] for i in idx]) for idx in groups.values()]


def _line_spans(P: np.ndarray, X: np.ndarray, Y: np.ndarray) -> tuple:
    """marks.segment_extent over a sweep, before its margin, for lines with as many marked points each: *P* the
    lines' own two points (lines x 4 x values: px, py, qx, qy), *X*, *Y* their marked points (lines x points x
    values; none: the line's own two) -> (px, py, ux, uy, lo, hi, tangent), each lines x values: the line from
    (px, py) along (ux, uy), marked from lo to hi, tangent where through one point only."""
    px, py, qx, qy = P[:, 0], P[:, 1], P[:, 2], P[:, 3]
    dx, dy = qx - px, qy - py
    h = np.hypot(dx, dy)
    ux, uy = dx / h, dy / h
    if X.shape[1]:
        ts = (X - px[:, None]) * ux[:, None] + (Y - py[:, None]) * uy[:, None]
    else:
        ts = np.stack([np.zeros(px.shape), np.ones(px.shape)], axis=1)
    lo, hi = ts.min(1), ts.max(1)
    # a line through one point only (a tangent at its point of contact) is drawn long enough to be seen
    tangent = hi - lo <= 1e-9 * np.maximum(1.0, np.abs(ts[:, 0]))
    return px, py, ux, uy, lo, hi, tangent


def _lines_reaching(spans: tuple, margin: np.ndarray) -> tuple:
    """Lines' spans (:func:`_line_spans`) drawn *margin* past their marked points (five margins at a tangent):
    (x1, y1, x2, y2)."""
    px, py, ux, uy, lo, hi, tangent = spans
    m = np.where(tangent, 5.0 * margin, margin)
    t0, t1 = lo - m, hi + m
    return (px + t0 * ux, py + t0 * uy, px + t1 * ux, py + t1 * uy)


def _arcs_over(cx: np.ndarray, cy: np.ndarray, X: np.ndarray, Y: np.ndarray) -> tuple:
    """The arcs over circles' marked points, before their margins, for circles with as many marked points each
    (*cx*, *cy*: circles x values; *X*, *Y*: circles x points x values): (start, sweep, where it is sure), each
    circles x values."""
    # (two points marked half a turn apart, a diameter, leave two equal gaps: marks.widest_gap takes one by
    # a rule, not by the last bit of an arctangent)
    a = _sorted_across(np.mod(np.arctan2(Y - cy[:, None], X - cx[:, None]), TWO_PI))
    k = a.shape[1]
    ok = np.ones(cx.shape, dtype=bool)
    if k == 1:
        return a[:, 0], np.zeros(cx.shape), ok
    # points marked at one place (a dead centre found twice) count once: a run of equal angles adds
    # gaps of nothing, and the gap after it is the gap after the one it stands for; angles a hair apart
    # (not one place, not two) are left to the drawing
    step = np.diff(a, axis=1)
    ok &= ~((step > 0) & (step <= 1e-9)).any(1)
    # a point marked a hair below a full turn is the point at angle 0 (marks.circle_extent drops it): its
    # angle a full turn past the first's, a gap of nothing after it
    a[:, -1] = np.where(a[:, 0] + TWO_PI - a[:, -1] <= 1e-9, a[:, 0] + TWO_PI, a[:, -1])
    gaps = np.mod(np.concatenate([a[:, 1:], a[:, :1]], axis=1) - a, TWO_PI)
    # marks.widest_gap: the widest, and of two as wide the one about angle 0
    tied = gaps >= gaps.max(axis=1, keepdims=True) - GAP_TIE
    mid = a + gaps / 2
    score = np.round(np.cos(mid), 9) + 1e-10 * np.round(np.sin(mid), 9) - 1e-12 * np.arange(k)[:, None]
    i = np.argmax(np.where(tied, score, -np.inf), axis=1)[:, None]
    one = a[:, -1] == a[:, 0]  # every marked point at one place: the arc is that place (and its margin)
    start = np.where(one, a[:, 0], np.take_along_axis(a, (i + 1) % k, axis=1)[:, 0])
    sweep = np.where(one, 0.0, TWO_PI - np.take_along_axis(gaps, i, axis=1)[:, 0])
    return start, sweep, ok


#: A circle with at most this many points marked on it has their angles sorted by compare-exchange (_sorted_across).
FEW_MARKED = 6


def _sorted_across(a: np.ndarray) -> np.ndarray:
    """``np.sort(a, axis=1)`` for a few columns (rows x columns x values): by odd-even transposition, each
    compare-exchange a minimum and a maximum of whole arrays (numpy sorts the few numbers of each row and value
    apart: 50,000 sorts of two or three angles a round, 5 ms).  The same numbers in the same places: a minimum and a
    maximum are the two numbers, equal ones are equal to the bit (no -0.0 among angles mod 2 pi); a NaN, which
    np.sort puts last, is left to np.sort.

    >>> _sorted_across(np.array([[[3.0], [1.0], [2.0]]]))[0, :, 0].tolist()
    [1.0, 2.0, 3.0]
    """
    k = a.shape[1]
    if k < 2 or k > FEW_MARKED or np.isnan(a).any():
        return np.sort(a, axis=1)
    cols = [a[:, i] for i in range(k)]
    for rnd in range(k):  # (k rounds of odd-even transposition sort k numbers)
        for i in range(rnd % 2, k - 1, 2):
            cols[i], cols[i + 1] = np.minimum(cols[i], cols[i + 1]), np.maximum(cols[i], cols[i + 1])
    return np.stack(cols, axis=1)


def _widest_gaps(S: np.ndarray, E: np.ndarray) -> tuple[np.ndarray, ...]:
    """sheet._widest_gap over a sweep: the widest stretch no span [S, E] covers (spans x values), at every value:
    (where it starts, where it ends, how wide, the figure's extent as the scalar walk reads it: from the first
    start to the end of the span that starts last).  Where no stretch is uncovered the width is not positive.

    The starts and the ends are sorted apart (numpy's sort of numbers, not an argsort of the pairs): after the
    k-th end, the k+1-th start opens a stretch no span covers exactly when it lies past it, and then the k spans
    that start first are the k that end first, so the stretch is the scalar walk's, to the bit.  A value with a
    span of no extent (nan: a curve of another number of points) is walked as the scalar walk does, sorted by
    start then end.

    >>> [float(v[0]) for v in _widest_gaps(np.array([[0.0], [5.0], [1.0]]), np.array([[2.0], [6.0], [1.5]]))]
    [2.0, 5.0, 3.0, 6.0]
    """
    s, e = np.sort(S, axis=0), np.sort(E, axis=0)
    gaps = s[1:] - e[:-1]
    j = np.argmax(gaps, axis=0)
    cols = np.arange(S.shape[1])
    # the end of the span that starts last (of those, the one that ends last)
    last = np.where(S == s[-1], E, -np.inf).max(axis=0)
    lo, hi, width, total = e[j, cols], s[j + 1, cols], gaps[j, cols], last - s[0]
    odd = np.isnan(S).any(axis=0) | np.isnan(E).any(axis=0)
    if odd.any():
        So, Eo = S[:, odd], E[:, odd]
        order = np.lexsort((Eo, So), axis=0)
        So, Eo = np.take_along_axis(So, order, 0), np.take_along_axis(Eo, order, 0)
        reach = np.maximum.accumulate(Eo, axis=0)
        g = So[1:] - reach[:-1]
        k = np.argmax(g, axis=0)
        at = np.arange(So.shape[1])
        lo[odd], hi[odd], width[odd], total[odd] = reach[k, at], So[k + 1, at], g[k, at], Eo[-1] - So[0]
    return lo, hi, width, total


def _arc_box(cx, cy, r, a0, sw) -> tuple:
    """marks._arc_extremes over arrays: an arc's ends and the quarter points it passes, as a box."""
    return _ArcReach(r, a0, sw).box(cx, cy)


class _ArcReach:
    """How far an arc reaches from its centre along x and along y, each way (:func:`_arc_box` without its centre):
    a broken axis moves an arc's centre, not its radius or its angles, so the box of an arc that moved is its
    centre and the same reach.  The box is the scalar's to the bit: its x are ``cx + r cos(a)`` at the ends and at
    the quarter points passed (one rounding of a product, one of a sum), and a sum rounds monotonically, so the
    least of the sums is the centre plus the least of the products."""

    def __init__(self, r, a0, sw) -> None:
        lo, hi = np.minimum(a0, a0 + sw), np.maximum(a0, a0 + sw)
        xs, ys = [r * np.cos(a0), r * np.cos(a0 + sw)], [r * np.sin(a0), r * np.sin(a0 + sw)]
        quarter = math.pi / 2
        first, last = np.ceil(lo / quarter), np.floor(hi / quarter)
        for q in range(int(np.nanmin(first)), int(np.nanmax(last)) + 1):
            inside = (q >= first) & (q <= last)
            xs.append(np.where(inside, r * math.cos(q * quarter), xs[0]))
            ys.append(np.where(inside, r * math.sin(q * quarter), ys[0]))
        X, Y = np.stack(xs), np.stack(ys)
        self.reach = (X.min(0), X.max(0), Y.min(0), Y.max(0))

    def box(self, cx, cy) -> tuple:
        x0, x1, y0, y1 = self.reach
        return (cx + x0, cx + x1, cy + y0, cy + y1)
