"""The grid of a live given: chosen so that the page's linear interpolation draws within 0.5 px.

**The bound.**  The grid is chosen, not guessed: starting from a coarse grid in
log10 of the given, every cell's midpoint is replayed and drawn, the linear
interpolation of the cell's ends is compared there with the exact drawing,
coordinate by coordinate (pixels of the player's 1400-wide view), and a cell
whose error exceeds :data:`REFINE_PX` is split, until none does.  Stored
coordinates are quantised to :data:`QUANTUM_PX`, which adds at most half a
quantum; so every drawn coordinate the page shows at a midpoint is within
``REFINE_PX + QUANTUM_PX / 2`` = 0.425 px < 0.5 px of the exact drawing
(:attr:`LiveSweep.bound` is the measured maximum).  The drawing depends
smoothly on the given between grid values -- no intersection of the
constructions switches branch between neighbouring rod ratios
(tests/test_sweep.py, ``test_no_intersection_switches_branch_between_neighbouring_ratios``,
2000 ratios from 1.02 to 50; above 50 the refinement below would see a jump) --
so the midpoint error bounds the cell's error up to the curvature's variation
across the cell, which the refinement keeps small.  One thing in the drawing
is not continuous: the broken axis (a gap wider than a fifth of the figure is
broken out) appears at one rod ratio.  A cell across it never converges; it
is split down to :data:`MIN_CELL` and recorded in :attr:`LiveSweep.jumps`,
and the page snaps to the nearer side there.  An arc's large-arc flag is never
blended: it comes from the nearer grid value, and a cell where it flips is
refined while the other arc its ends allow lies more than 0.4 px away.  A mark
that alone jumps inside the domain (the inertia curve's arc about D flips to
its other side at several rod ratios) is drawn from the nearer grid value
everywhere (:attr:`LiveSweep.snapped`) instead of forcing the grid down at every
flip.  The grid stops growing at *max_values* values; a cell still too coarse
then is recorded as a jump (measured: none for the crank and the inertia curve).
"""

from __future__ import annotations

import collections
import functools
import math
import re
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..constructions import Construction
from ..constructions.domain import KAPPA_RANGE, ROD_RATIO, Domain
from ..figure import Figure
from ..kernel.errors import ConstructError, InvalidParameter
from ..kernel.identity import by_identity
from ..kernel.instruments import unlettered
from ..render.styles import STYLES
from ..render.wire import arc_flags, blend, radii
from .measure import Measure

__all__ = ["LiveGiven", "LiveSweep", "Piece", "live_givens", "live_sweep", "pieces", "scan_pieces", "form_pieces",
           "reach", "check_picks", "REFINE_PX", "QUANTUM_PX", "MIN_CELL", "SWITCH_CELL", "CHECK_VALUES"]


@dataclass(frozen=True)
class LiveGiven:
    """A continuous given a player moves: its name in the protocol (the slider's name), the book's symbol, its
    stated domain, the unit it is written in, and how the page's texts write it (the title's and the givens'
    "L/r = 5", "r/L = 1/5": the value follows each prefix)."""

    name: str
    symbol: str
    domain: Domain
    unit: str = ""
    written: tuple[str, ...] = ()
    #: How the rod's length is written at a broken axis, "{v}" the value ("L = {v} r"); "": not a rod.
    rod: str = ""


#: Givens that follow from the moving one (Construction.derived) and that the page's texts write: their name
#: -> what precedes the number in the title and the givens (two-cranks: "Schwankungen 8fach vergrößert").
DERIVED_WRITTEN: dict[str, tuple[str, ...]] = {"magnify": ("Schwankungen ", "magnified ")}
#: The rod ratio, as the books write it: L/r = 5, r/L = 1/5 (Anhang II, Baumann), r/l = 1/5 (§ 146).
ROD = LiveGiven("rod_ratio", "L/r", ROD_RATIO, "", ("L/r = ", "r/L = 1/", "r/l = 1/"), "L = {v} r")
#: Baumann's κ = P/B_max (Fig. 26/27: 8 and 2): the slider spans two decades about them, from an engine whose
#: masses press at the dead centre as hard as its steam (κ = 1) to one where they hardly count (100); the
#: construction holds from 0.1 to 10,000 (KAPPA_RANGE), a replay takes any of those.
KAPPA = LiveGiven("kappa", "κ", Domain(1.0, 100.0, KAPPA_RANGE.why, KAPPA_RANGE.advice), "",
                  ("κ = P/Bₘₐₓ = ", "κ = P/Bmax = ", "κ = "))
#: A cell is split while linear interpolation misses the exact drawing by more than this (px).
REFINE_PX = 0.4
#: The refinement blends coordinates rounded to multiples of this (px).
QUANTUM_PX = 0.05
#: A jump caused by at most this many marks is theirs (they are drawn from the nearer grid value), not the figure's.
SNAP_AT_MOST = 3
#: A round of the refinement draws the midpoints of a cell's halves (and of theirs, ...) at least this many levels
#: ahead, and deeper while the round draws at most AHEAD_VALUES values: a round costs about as much as thirty to
#: fifty values (its marks' Python and the replay's steps, whatever the number of values), so the last rounds, which
#: split a few cells down towards a jump, look further ahead (what no cell needs is dropped; the grid is the same).
#: A round of many cells looks none ahead: about half its halves hold, and a value drawn for nothing costs its
#: share of the drawing (tangential-pressure's rod drew 929 values for a grid of 603 one level ahead; the live data
#: of it, effective-work and piston-force 10 to 15 % less CPU at none, the same bytes).
AHEAD = 0
AHEAD_VALUES = 64
#: ... and never more levels ahead than this.
AHEAD_MOST = 6
#: A mark whose miss at a cell's midpoint stays above this share of its miss in the cell split into it, twice
#: running, jumps there (a smooth mark's miss falls to a quarter at each halving, a kink's to a half).
JUMPING = 0.85
#: ... and misses by more than this (px): a smaller step is refined like the rest.
JUMP_PX = 2.0
#: A cell narrower than this (in log10 of the given) is not split further: it straddles a jump of the drawing.
MIN_CELL = 1e-4


def live_givens(construction: Construction, figure: Figure) -> list[LiveGiven]:
    """The continuous givens of *figure* a player offers a slider for: the rod (as a ratio L/r, or a length in
    metres beside the crank radius R: Tafel I's L = 2 m), and Baumann's κ.

    >>> from construct.constructions import get
    >>> [g.name for g in live_givens(get("tangential-pressure"), get("tangential-pressure").figure())]
    ['rod_ratio', 'kappa']
    >>> live_givens(get("piston-force"), get("piston-force").figure())[0].domain.high  # L/R up to 1000, R = 0.4 m
    400.0
    >>> live_givens(get("indicator-diagram"), get("indicator-diagram").figure())  # its filling: a switch
    []
    """
    g = figure.replay.givens
    out = []
    if "rod_ratio" in g:
        out.append(ROD)
    elif "rod_length" in g and "crank_radius" in g:
        R = float(g["crank_radius"])
        out.append(LiveGiven("rod_length", "L", Domain(ROD_RATIO.low * R, ROD_RATIO.high * R, ROD_RATIO.why,
                                                       ROD_RATIO.advice), "m", ("L = ",), "L = {v} m"))
    if "kappa" in g:
        out.append(KAPPA)
    return out


def reach(construction: Construction, figure: Figure, given: str, domain: Domain, initial: float) -> Domain:
    """The part of *domain* about *initial* where the construction holds with the figure's other givens (the two
    cranks' speed radius magnified 8 times vanishes below L/r = 2.3 at the book's fluctuation): its validator asked,
    each end found by bisection in log10 to three significant digits (rounded inwards).

    >>> from construct.constructions import get
    >>> c = get("two-cranks"); fig = c.figure(parts=12, magnify=8.0)  # (magnified as chosen: at every rod)
    >>> reach(c, fig, "rod_ratio", ROD_RATIO, 5.0).low, reach(c, c.figure(parts=12), "rod_ratio", ROD_RATIO, 5.0).low
    (2.29, 1.05)
    """
    holds = functools.partial(_holds, construction, dict(figure.replay.givens), figure.protocol.params, given)

    def edge(inside: float, outside: float, up: bool) -> float:
        a, b = math.log10(inside), math.log10(outside)
        for _ in range(24):  # to 1e-7 of a decade: below the three digits kept
            m = (a + b) / 2
            a, b = (m, b) if holds(10 ** m) else (a, m)
        digits = 2 - math.floor(b)  # three significant digits, rounded towards the inside
        v = (math.ceil if not up else math.floor)(10 ** a * 10 ** digits) / 10 ** digits
        return v if holds(v) else 10 ** a

    low = domain.low if holds(domain.low) else edge(initial, domain.low, False)
    high = domain.high if holds(domain.high) else edge(initial, domain.high, True)
    return domain if (low, high) == (domain.low, domain.high) else Domain(low, high, domain.why, domain.advice)


def _holds(construction: Construction, givens: dict[str, Any], params: Any, given: str, v: float) -> bool:
    """Whether the construction holds with *given* at *v*, the figure's other givens kept (its validator asked)."""
    try:
        construction.validate({k: (float(x[0]) if isinstance(x, np.ndarray) else x)
                               for k, x in construction.given_sweep(givens, given, [v], params).items()})
    except InvalidParameter:
        return False
    return True


#: How many values of a given's domain (evenly in log10) a fresh build is asked at for the steps' form, and to what
#: part of a decade a change of form is then found by bisection.
FORM_SCAN = 24
FORM_TOL = 1e-4


@dataclass(frozen=True)
class Piece:
    """A part [low, high] of a given's domain over which a fresh build makes the same steps from the same
    objects (:func:`pieces`): replaying *protocol* there is what a fresh build draws."""

    low: float
    high: float
    protocol: Any


def _form(protocol: Any) -> tuple:
    """The steps' form: each step's operation, its inputs and outputs (their values aside)."""
    return tuple((s.op, tuple(s.inputs), tuple(s.outputs)) for s in protocol.steps)


def pieces(construction: Construction, figure: Figure, given: str, domain: Domain,
           scan: int = FORM_SCAN) -> list[Piece]:
    """*domain* in the parts where a fresh build of *figure* at another value of *given* takes the same steps from
    the same objects: one piece where the form never changes (a replay of the built protocol is then the fresh
    build everywhere); several where it does (Tafel I's piston-force pieces run through the points between their
    corners: which points those are depends on the rod).  Each piece's protocol is built inside it (the built
    figure's own in its piece; the others unlettered, :func:`~construct.kernel.instruments.unlettered`: their
    steps are a lettered build's, their captions are left as written, and what a player is sent of a piece
    reads none of them); the changes are found at *scan* values evenly in log10, then by bisection in log10
    to FORM_TOL.  Where the construction reads its choices off a sweep
    (:attr:`~construct.constructions.Construction.form`), the steps' form at all the values of a round is one
    replay of the built protocol over them (:func:`form_pieces`); elsewhere a fresh build at each value tells it
    (:func:`scan_pieces`).  A given the construction names in :attr:`~construct.constructions.Construction.steady`
    is one piece without either (tests/test_live.py holds both to the fresh builds).

    >>> from construct.constructions import get
    >>> c = get("crank"); fig = c.figure(parts=3)
    >>> [(p.low, p.high, p.protocol is fig.protocol) for p in pieces(c, fig, "rod_ratio", ROD_RATIO)]
    [(1.05, 1000.0, True)]

    (tests/test_render_live_browser.py drags Tafel I's eight pieces.)
    """
    if given in construction.steady:
        return [Piece(domain.low, domain.high, figure.protocol)]
    if construction.form is not None:
        found = form_pieces(construction, figure, given, domain, scan)
        if found is not None:
            return found
    return scan_pieces(construction, figure, given, domain, scan)


def _keywords(construction: Construction, figure: Figure) -> dict[str, Any]:
    """What a fresh build of *figure* is given: its givens and parameters, the construction's defaults else."""
    givens, params = figure.replay.givens, figure.protocol.params
    return {k: givens[k] if k in givens else params[k] if isinstance(params.get(k), (int, float, str, bool))
            else construction.defaults[k] for k in construction.defaults}


def _value_at(domain: Domain):
    """A value of the given from its log10 *u*, inside *domain* (how a scan and the pieces' ends read it)."""
    return lambda u: float(min(max(10 ** u, domain.low), domain.high))


def _changes(forms, us: list[float], tol: float, ahead: bool = False) -> tuple[list[tuple[float, float]],
                                                                              dict[float, Any]]:
    """Every change of form between neighbours of *us* (log10 of the given), each found by bisection down to a
    cell of *tol*: the cells (a, b) across which it changes, in order, and the form found at every value asked.
    *forms* tells the forms at a list of values at once (each round of the bisection asks its midpoints together)."""
    known = dict(zip(us, forms(us)))
    cuts: list[tuple[float, float]] = []
    todo = [(a, b) for a, b in zip(us[:-1], us[1:]) if known[a] != known[b]]
    while todo:
        mids = [(a + b) / 2 for a, b in todo if b - a > tol and (a + b) / 2 not in known]
        if mids and ahead:
            # and the midpoints the bisection will ask for below them, as live_sweep looks ahead (*ahead*: a round
            # of *forms* is one replay, whatever the number of values); where the construction fails at one of
            # those, only what this round needs
            below = [q for a, b in todo if b - a > tol for q in _ahead(a, b, _depth(len(todo)))]
            more = [q for q in dict.fromkeys(mids + below) if q not in known]
            try:
                known.update(zip(more, forms(more)))
            except ConstructError:
                known.update(zip(mids, forms(mids)))
        else:
            known.update(zip(mids, forms(mids)))
        nxt = []
        for a, b in todo:
            if b - a <= tol:
                cuts.append((a, b))
                continue
            m = (a + b) / 2
            if known[m] != known[a]:
                nxt.append((a, m))
            if known[m] != known[b]:
                nxt.append((m, b))
        todo = nxt
    return sorted(cuts), known


def _pieces_from(construction: Construction, figure: Figure, given: str, domain: Domain, scan: int, forms,
                 built: Any, holds, ahead: bool = False) -> list[Piece]:
    """The pieces of *domain* from the steps' forms (*forms*: at a list of log10 values at once; *built*: the
    built figure's), each other piece's protocol from one unlettered build inside it; the whole domain as one
    piece where no change is found or a piece would begin where the construction does not hold.  *ahead*: *forms* costs
    a round, not a value (one replay): the bisection asks for the values below its midpoints in the same round."""
    value = _value_at(domain)
    lo, hi = math.log10(domain.low), math.log10(domain.high)
    initial = math.log10(float(figure.replay.givens[given]))
    us = sorted(set(np.linspace(lo, hi, scan).tolist()) | {initial})
    cuts, form = _changes(forms, us, FORM_TOL, ahead)
    if not cuts:
        return [Piece(domain.low, domain.high, figure.protocol)]
    ends = [lo] + [x for a, b in cuts for x in (a, b)] + [hi]
    if not all(holds(a) for a in ends[0::2]):  # a build that fails inside the domain (reach found it holds)
        return [Piece(domain.low, domain.high, figure.protocol)]
    kw = _keywords(construction, figure)
    with unlettered():  # (the captions' letters are a third of a build's time; the live data reads no caption)
        return [Piece(domain.low if a == lo else 10 ** a, domain.high if b == hi else 10 ** b,
                      figure.protocol if form[a] == built else construction.build(**{**kw, given: value(a)}).protocol)
                for a, b in zip(ends[0::2], ends[1::2])]


def scan_pieces(construction: Construction, figure: Figure, given: str, domain: Domain,
                scan: int = FORM_SCAN) -> list[Piece]:
    """:func:`pieces` found by fresh builds at *scan* values, whatever the construction says of *given*."""
    kw = _keywords(construction, figure)
    value = _value_at(domain)
    made: dict[float, tuple | None] = {}  # log10 of a value -> the steps' form a fresh build takes there (None: none)

    def form(u: float) -> tuple | None:
        if u not in made:
            try:
                with unlettered():
                    made[u] = _form(construction.build(**{**kw, given: value(u)}).protocol)
            except InvalidParameter:
                made[u] = None
        return made[u]

    built = _form(figure.protocol)
    if form(math.log10(float(figure.replay.givens[given]))) != built:
        # the figure is not what its givens build (a protocol replayed by hand): as it is
        return [Piece(domain.low, domain.high, figure.protocol)]
    return _pieces_from(construction, figure, given, domain, scan, lambda us: [form(u) for u in us], built,
                        lambda u: form(u) is not None)


def form_pieces(construction: Construction, figure: Figure, given: str, domain: Domain,
                scan: int = FORM_SCAN) -> list[Piece] | None:
    """:func:`pieces` found on arrays: the steps' form at every value of a round of the bisection is read off one
    replay of the built protocol over them (:attr:`~construct.constructions.Construction.form`: the build's
    choices, made on arrays), not from a fresh build at each.  None where the construction cannot tell."""
    protocol, givens = figure.protocol, dict(figure.replay.givens)
    value = _value_at(domain)

    def forms(us: list[float]) -> list[bytes]:
        if not us:
            return []
        swept = construction.given_sweep(givens, given, np.asarray([value(u) for u in us]), protocol.params)
        rows = np.asarray(read(protocol.replay(swept), protocol.params), dtype=np.int64)
        return [row.tobytes() for row in np.ascontiguousarray(np.broadcast_to(rows, (len(us), rows.shape[-1])))]

    read = construction.form
    if read is None or read(figure.replay, protocol.params) is None:  # (its choices depend on its params only)
        return None
    initial = math.log10(float(givens[given]))
    at = forms([initial])
    with unlettered():  # the figure is what its givens build (not a protocol replayed by hand), as the scan asks
        try:
            fresh = construction.build(**{**_keywords(construction, figure), given: value(initial)}).protocol
        except InvalidParameter:
            fresh = None
    if fresh is None or _form(fresh) != _form(protocol):
        return [Piece(domain.low, domain.high, protocol)]
    return _pieces_from(construction, figure, given, domain, scan, forms, at[0],
                        lambda u: _holds(construction, givens, protocol.params, given, value(u)), ahead=True)


#: A change of the spots the plate's lettering stands at is put this close (in log10 of the given) below or above
#: a grid value: the page writes either side's spots up to it and switches there (a jump of the drawing).
SWITCH_CELL = MIN_CELL / 4


def _switch_spots(data: dict[float, tuple], spots, jumps: list[tuple[float, float]], values, frames) -> None:
    """Put each change of the spots the plate's lettering stands at (:meth:`Measure.spots_key`, *spots* of a grid
    value) at a grid value: across a cell (a, b) of the refined grid *data* (log10 of the given -> its frame)
    whose ends write it at other spots, a's spots are written up to a value :data:`SWITCH_CELL` below b where they
    do not crowd there, else b's from a value as far above a where those do not; else the cell is split at its
    midpoint (a value drawn anew) and each half asked so, down to MIN_CELL.  The cell of the switch is a jump of
    the drawing (*jumps*, as the values *values* gives: the page draws the nearer side there), a few values
    where the refinement chased each change down to MIN_CELL (Tafel 2's last piece: about 130 values, not 410).
    *frames*: the frames at a list of log10 values, with the spots some of them keep (by their index)."""
    jumped = {float(a) for a, _ in jumps}
    us = sorted(data)
    todo = [(a, b) for a, b in zip(us[:-1], us[1:]) if spots(a) != spots(b) and float(values(a)) not in jumped
            and data[a][0] == data[b][0]]
    as_array = lambda f: (f[0], np.asarray(f[1], dtype=float), *f[2:])  # noqa: E731
    while todo:
        n = len(todo)
        asked = [b - SWITCH_CELL for _, b in todo] + [a + SWITCH_CELL for a, _ in todo]
        drawn = frames(asked, {**{i: spots(a) for i, (a, _) in enumerate(todo)},
                               **{n + i: spots(b) for i, (_, b) in enumerate(todo)}})
        split = []
        for i, (a, b) in enumerate(todo):
            for at, (u, was) in enumerate(((asked[i], a), (asked[n + i], b))):
                f = drawn[i + at * n]
                if f[0] == data[was][0] and f[3].get("#spots", "") == spots(was):
                    data[u] = as_array(f)
                    jumps.append((float(values(u)), float(values(b))) if at == 0 else
                                 (float(values(a)), float(values(u))))
                    break
            else:
                if b - a >= MIN_CELL:
                    split.append((a, b))
                else:
                    jumps.append((float(values(a)), float(values(b))))
        if not split:
            return
        mids = [(a + b) / 2 for a, b in split]
        drawn = frames(mids, {})
        todo = []
        for (a, b), m, i in zip(split, mids, range(len(mids))):
            data[m] = as_array(drawn[i])
            todo += [(x, y) for x, y in ((a, m), (m, b)) if spots(x) != spots(y) and data[x][0] == data[y][0]]


#: A step's view whose edge is this much further (px) from where the blend of its cell's ends puts it, at the
#: cell's midpoint, jumps inside the cell (:func:`_switch_views`) ...
VIEW_JUMP_PX = 30.0
#: ... where the cell lies this near the book's value (in log10 of the given: a factor 1.12 either side), where a
#: teacher drags most: at most VIEW_CELLS such cells, the largest jumps (in px times the cell's width) first ...
VIEW_NEAR = 0.05
VIEW_CELLS = 4
#: ... looked into this many levels of halving a round (a round costs as much as thirty to fifty values: its marks'
#: set-up and the replay's steps), in at most VIEW_ROUNDS rounds (four rounds of two levels narrow a cell of the
#: crank's grid near the book's value, about 0.02 to 0.05 wide, to about 0.0002, where its marks move by
#: REFINE_PX or less).
VIEW_LEVELS = 2
VIEW_ROUNDS = 4


def _switch_views(data: dict[float, tuple], jumps: list[tuple[float, float]], values, frames, near: float,
                  cells: int = VIEW_CELLS) -> None:
    """Put each jump of a step's view near the book's value *near* (log10) inside a cell of the refined grid *data*
    (log10 of the given -> its frame) where it happens.  A view is not refined for (it frames the figure: blended
    between grid values), but where the camera's rule switches -- a shot that magnifies too little shown whole, a
    letter its window would cut widening it -- the view jumps, and a blend across the cell showed a frame neither
    side has (the crank's 60 % step at the book's value itself: 131 px off its own view).

    A jump of J px anywhere in a cell puts the view at the cell's midpoint J / 2 from the blend of its ends.  The
    cells within :data:`VIEW_NEAR` of the book's value whose ends' views differ by more than :data:`VIEW_JUMP_PX`
    (the *cells* largest: VIEW_CELLS, a piece of the domain its share) have :data:`VIEW_LEVELS` levels of their
    halvings drawn (one sweep for all of them a round); where the view misses at a cell's midpoint by more than
    half that, the midpoint becomes a grid value and each half whose ends differ so is looked into (*cells* of
    them a round), down to a cell across which every other number of the drawing moves by at most REFINE_PX:
    drawn from either side, its marks are within half that of the line between its ends (and that line within
    REFINE_PX of the drawing, as the refinement held the larger cell's), and the cell is a jump of the drawing (*jumps*, as the values *values* gives: the page draws the nearer
    side).  A view that moves smoothly, or by less, is blended as before; a cell not down to that after
    :data:`VIEW_ROUNDS` rounds stays blended, narrower.  *frames*: the frames at a list of log10 values."""
    jumped = {float(a) for a, _ in jumps}

    def alike(fa: tuple, fb: tuple) -> bool:
        return fa[0] is fb[0] or fa[0] == fb[0]

    def apart(fa: tuple, fb: tuple) -> tuple[float, float]:  # how far two frames' views and other numbers are apart
        if not alike(fa, fb):
            return 0.0, math.inf
        cols = _view_columns(fa[0])
        d = np.abs(fa[1] - fb[1])
        return float(d[cols].max(initial=0.0)), float(d[~cols].max(initial=0.0))

    us = sorted(data)
    todo = [(a, b) for a, b in zip(us[:-1], us[1:]) if float(values(a)) not in jumped and b >= near - VIEW_NEAR
            and a <= near + VIEW_NEAR and apart(data[a], data[b])[0] > VIEW_JUMP_PX]
    todo = sorted(sorted(todo, key=lambda c: -apart(data[c[0]], data[c[1]])[0] * (c[1] - c[0]))[:cells])
    as_array = lambda f: (f[0], np.asarray(f[1], dtype=float), *f[2:])  # noqa: E731
    for _ in range(VIEW_ROUNDS if todo else 0):
        inside = [_ahead(a, b, VIEW_LEVELS - 1) + [(a + b) / 2] for a, b in todo]
        asked = [u for us in inside for u in us]
        drawn = frames(asked, {})
        got = {u: as_array(drawn[i]) for i, u in enumerate(asked)}
        nxt = []

        def walk(a: float, b: float, depth: int) -> None:
            if apart(data[a], data[b])[1] <= REFINE_PX:
                jumps.append((float(values(a)), float(values(b))))
                return
            m = (a + b) / 2
            if depth == VIEW_LEVELS or b - a < MIN_CELL:
                nxt.append((a, b))
                return
            fa, fb, fm = data[a], data[b], got[m]
            if not (alike(fa, fm) and alike(fb, fm)):
                return  # (another form there: not a view's jump)
            cols = _view_columns(fa[0])
            if np.abs((fa[1][cols] + fb[1][cols]) / 2 - fm[1][cols]).max(initial=0.0) <= VIEW_JUMP_PX / 2:
                return
            data[m] = fm
            for x, y in ((a, m), (m, b)):
                if apart(data[x], data[y])[0] > VIEW_JUMP_PX:
                    walk(x, y, depth + 1)

        for a, b in todo:
            walk(a, b, 0)
        todo = [(a, b) for a, b in nxt if b - a >= MIN_CELL][:cells]
        if not todo:
            return


def _view_columns(keys: list[tuple[str, str, str]]) -> np.ndarray:
    """Which numbers of *keys* are the steps' views (not the insets': carried with their points), found once per list
    of keys (known by its identity, as :func:`_key_columns`)."""
    return by_identity(_VIEW_COLUMNS, keys, lambda keys: _columns(keys, lambda k: k[0] == "#zoom"), most=4)


_VIEW_COLUMNS: dict[int, tuple] = {}


_KEY_COLUMNS: dict[int, tuple] = {}


def _key_columns(keys: list[tuple[str, str, str]]) -> tuple[np.ndarray, ...]:
    """Which key each number of *keys* belongs to, which numbers are views, which are large-arc flags, which are
    radii: asked at every cell of the refinement, for the same list of keys (known by its identity: hashing
    thousands of keys at every cell cost more than the cell)."""
    return by_identity(_KEY_COLUMNS, keys, lambda keys: (
        np.asarray([i for i, k in enumerate(keys) for _ in range(k[2].count("#"))], dtype=int),
        _columns(keys, lambda k: k[0] in ("#zoom", "#inset")), arc_flags(keys), radii(keys)), most=4)


def _midpoint_error(keys, na: np.ndarray, nb: np.ndarray, exact: np.ndarray, snap: set[int],
                    unlike: np.ndarray | None = None) -> tuple[float, dict[int, float]]:
    """The largest distance (px) between the page's drawing at a cell's midpoint and the exact one, and the
    keys that exceed REFINE_PX with the distance of their coordinates (without large-arc flags).

    Coordinates are blended from the quantised ends (radii geometrically, as the page blends them);
    large-arc flags and snapped keys come from either end
    (the worse counts); a wrong flag moves the arc by the distance between the two centres its ends and
    radius allow, 2 sqrt(r^2 - (c/2)^2).  The numbers *unlike* marks (the plate's lettering where the cell's
    values write it at other spots) are not asked."""
    owner, views, flags, geometric = _key_columns(keys)
    if owner.size == 0:
        return 0.0, {}
    q = lambda n: np.round(n / QUANTUM_PX) * QUANTUM_PX  # noqa: E731
    blended = blend(q(na), q(nb), 0.5, geometric)
    col_err = np.abs(blended - exact)
    nearest = np.isin(owner, list(snap)) if snap else np.zeros(owner.size, dtype=bool)
    col_err[nearest] = np.maximum(np.abs(na - exact), np.abs(nb - exact))[nearest]
    col_err[views] = 0.0  # views frame the figure: blended, not refined for
    if unlike is not None:
        col_err[unlike] = 0.0
    c = np.flatnonzero(flags & ~nearest)  # the flags: each arc's numbers are c-5 .. c+3
    flipped = (na[c] != exact[c]) | (nb[c] != exact[c])
    half = np.hypot(exact[c + 2] - exact[c - 5], exact[c + 3] - exact[c - 4]) / 2
    r = exact[c - 3]
    col_err[c] = np.where(flipped, 2 * np.sqrt(np.maximum(r * r - half * half, 0.0)), 0.0)
    worst = float(col_err.max())
    if not worst > REFINE_PX:  # (the commonest: a cell that holds; no key to name)
        return worst, {}
    bad = np.unique(owner[col_err > REFINE_PX])  # the keys with a number that misses
    # what a culprit misses by in its coordinates (a large-arc flag that flips is not a jump of the arc: the
    # two arcs its ends allow meet as it flips, and refining converges there)
    at = np.flatnonzero(np.isin(owner, bad))
    coord_err = np.full(len(keys), -np.inf)
    np.maximum.at(coord_err, owner[at], np.where(flags & ~nearest, 0.0, col_err)[at])
    return worst, {k: float(coord_err[k]) for k in bad.tolist()}


def _ahead(a: float, b: float, depth: int) -> list[float]:
    """The midpoints of the halves of the cell (a, b), and of theirs, *depth* levels down: as the refinement
    will split them (to the last bit: (a + m) / 2 with m = (a + b) / 2)."""
    if depth <= 0:
        return []
    m = (a + b) / 2
    return [(a + m) / 2, (m + b) / 2] + _ahead(a, m, depth - 1) + _ahead(m, b, depth - 1)


def _asked(first: list[float], todo: list[tuple[float, float]]) -> list[float]:
    """The values a round of the refinement draws (log10 of the given): *first* (the starting values, drawn in the
    first round), the midpoints of the cells *todo*, and the midpoints of their halves, drawn ahead: a cell that
    must be split has its halves tested in the same round (a round draws every mark of the figure once, over all
    its values: its cost is the marks', not the values'); what no cell needed is dropped."""
    return (first + [(a + b) / 2 for a, b in todo]
            + [q for a, b in todo for q in _ahead(a, b, _depth(len(todo)))])


def _depth(cells: int) -> int:
    """How many levels ahead a round of *cells* cells draws (AHEAD, AHEAD_VALUES, AHEAD_MOST).

    >>> _depth(100), _depth(21), _depth(2), _depth(1)
    (0, 1, 4, 5)
    """
    depth = AHEAD
    while depth < AHEAD_MOST and cells * (2 ** (depth + 2) - 1) <= AHEAD_VALUES:
        depth += 1
    return depth


def _columns(keys: list[tuple[str, str, str]], pick) -> np.ndarray:
    """Which numbers of *keys* belong to keys *pick* selects."""
    counts = np.fromiter((k[2].count("#") for k in keys), dtype=np.int64, count=len(keys))
    return np.repeat(np.fromiter(map(pick, keys), dtype=bool, count=len(keys)), counts)


@dataclass
class LiveSweep:
    """A given's grid and what the player draws at every grid value."""

    given: str
    symbol: str
    domain: Domain
    initial: float
    grid: np.ndarray
    keys: list[tuple[str, str, str]]
    #: grid x numbers, pixels of the player's view.
    drawn: np.ndarray
    #: The measured maximum of |interpolated - exact| over every midpoint tested (px, after quantisation).
    bound: float
    #: Cells (low, high) across which the drawing jumps (the broken axis appearing).
    jumps: list[tuple[float, float]] = field(default_factory=list)
    #: At the grid values the page shows checks for (:func:`check_picks`), by their index in the grid:
    #: [[name, measured, expected, error, tolerance, ok], ...].
    checks: dict[int, list[list[Any]]] = field(default_factory=dict)
    #: Elements whose geometry is not interpolated (their form changes across the domain): shown at the built value.
    fixed: list[str] = field(default_factory=list)
    #: Letters whose text changes with the given (readings of the figure, e.g. the angle AOW, a dimension's
    #: value): written as at the nearer grid value (:attr:`reading_texts`; a blend of two would print minutes
    #: the figure does not have).
    readings: list[str] = field(default_factory=list)
    #: Marks drawn from the nearer grid value (they jump inside the domain: an arc drawn the other way round).
    snapped: list[tuple[str, str, str]] = field(default_factory=list)
    #: The grid in log10 of the given, exactly as refined (a cell (a, b) was split at (a + b) / 2), and how
    #: many values the refinement started from: the cells of the refinement (:func:`column_knots`).
    u: np.ndarray | None = None
    start: int = 0
    #: Per grid value, the drawing's fit to the view (ox, oy, s): (x, y) is drawn at (ox + s x, oy - s y) px.
    fit: np.ndarray | None = None
    #: The checks at the built value, as :attr:`checks`.
    built_checks: list[list[Any]] = field(default_factory=list)
    #: The style's letter size (px): the page sizes the marks of a break by it, as the drawing does.
    label_px: float = 12.0
    #: The given as its book writes it (unit, the texts' forms, the rod at a break): :class:`LiveGiven`.
    live: LiveGiven | None = None
    #: The slider's whole domain where this sweep is one piece of it (:func:`pieces`); None: the sweep's own.
    whole: Domain | None = None
    #: The areas the page draws from the graphs that bound them (:func:`construct.live.measure.areas_of`).
    areas: list[list[str]] = field(default_factory=list)
    #: The end state's furniture (the plate's dimensions, scales, lettering and added lines) is held at the book's
    #: value over this sweep (it cannot be matched item by item across the domain, a plate of panels:
    #: :meth:`construct.live.Measure.furniture_kept`); it follows the given else.
    furniture_held: bool = False
    #: The end state's furniture elements of the items that come and go over the domain (a scale's ticks:
    #: :attr:`construct.live.Measure.hidden_items`), by id: at each grid value 1 where its plate lacks them (the
    #: page hides them where the nearer grid value's plate does); and the page's note that says which
    #: (:meth:`construct.live.Measure.hidden_note`).
    furniture_absent: dict[str, list[int]] = field(default_factory=dict)
    furniture_note: str = ""
    #: The texts of :attr:`readings` at every grid value (the page writes the nearer grid value's).
    reading_texts: dict[str, list[str]] = field(default_factory=dict)
    #: Givens that follow from this one and that the texts write (DERIVED_WRITTEN): name -> value at each grid
    #: value (a step function, the two cranks' magnification: the page writes the nearer grid value's).
    derived: dict[str, list[float]] = field(default_factory=dict)

    def nearest_columns(self) -> np.ndarray:
        """The columns taken from the nearer grid value: large-arc flags and the snapped marks (the keys' columns
        as the refinement found them for the same list: :func:`_key_columns`; the page's data asks twice)."""
        owner, _, flags, _ = _key_columns(self.keys)
        snapped = set(self.snapped)
        marked = np.fromiter((k in snapped for k in self.keys), dtype=bool, count=len(self.keys)) if snapped else \
            np.zeros(len(self.keys), dtype=bool)
        return flags | marked[owner]


def _frames(construction: Construction, figure: Figure, given: str, values: np.ndarray, measure,
            protocol: Any, keep: dict[int, str] | None = None) -> list[tuple]:
    """(keys, numbers, fit, texts) of the player's figure at every value, from one sweep of *protocol* (the
    figure's, or its piece's: :func:`pieces`); *keep*: :meth:`Measure.frames`'s."""
    replay = protocol.replay(construction.given_sweep(dict(figure.replay.givens), given, values, protocol.params))
    return measure.frames(protocol, replay, len(values), keep), replay


def live_sweep(construction: Construction, figure: Figure, given: str, *, initial: float | None = None,
               style: Any = None, start: int = 9, max_values: int = 800, drawing: Any = None,
               measure: Measure | None = None, piece: Piece | None = None) -> LiveSweep:
    """The grid of *given* over its domain on which linear interpolation draws within 0.5 px (see the module).

    *drawing*: the figure's :class:`~construct.render.svg.Drawing` in *style*, if the caller lays it out anyway
    (the player's): its camera views are the ones carried along.  *measure*: the figure's :class:`Measure`, if
    another given's sweep made it (it depends on the figure, not on the given).  *piece*: the part of the domain
    swept (:func:`pieces`: where the steps' form changes, each part is swept apart, replaying its own protocol)."""
    style = style or STYLES["teaching"]
    live = next((g for g in live_givens(construction, figure) if g.name == given), None)
    if live is None:
        raise InvalidParameter(f"{construction.name} has no given {given!r} a player can move; it moves "
                               f"{', '.join(g.name for g in live_givens(construction, figure)) or 'none'}")
    symbol = live.symbol
    initial = float(figure.replay.givens[given] if initial is None else initial)
    domain = whole = reach(construction, figure, given, live.domain, initial)
    protocol = figure.protocol
    if piece is not None:
        domain = Domain(max(piece.low, whole.low), min(piece.high, whole.high), whole.why, whole.advice)
        protocol = piece.protocol
    measure = measure or Measure(construction, figure, style, drawing=drawing)
    lo, hi = math.log10(domain.low), math.log10(domain.high)
    # the end state's furniture follows the given where it keeps its form over the domain (asked at FORM_SCAN
    # values, as the steps' form is: :func:`pieces`), item by item (a plate of panels is held whole at the book's
    # value), so that an end state drawn mostly by the plate -- Tafel 2's ordinates, dots and values -- is the
    # finished figure at every value (a piece of the domain its share of them)
    share = (hi - lo) / math.log10(whole.high / whole.low)
    scan = np.unique(np.clip(10.0 ** np.append(np.linspace(lo, hi, max(3, round(FORM_SCAN * share))),
                                               math.log10(initial)), domain.low, domain.high))
    us = list(np.linspace(lo, hi, start))
    values = lambda u: np.clip(10.0 ** np.asarray(u), domain.low, domain.high)  # noqa: E731
    # -- item by item: the items that come and go over them (a scale's ticks) shown where the nearer grid value's
    # plate has them, the rest swept; those values are replayed with the first round's (one replay of the protocol,
    # not two: Tafel I's eight pieces replay 1,467 steps each), after its values, which alone are drawn
    todo = list(zip(us[:-1], us[1:]))
    both = None
    if measure.held[0]:
        asked = _asked(us, todo)
        both = protocol.replay(construction.given_sweep(dict(figure.replay.givens), given,
                                                        np.concatenate([values(asked), scan]), protocol.params))
        kept = measure.furniture_kept(protocol, both, len(scan), at=len(asked))
    else:
        kept = frozenset()
    measure.furniture_live = kept is not None
    measure.hidden_items = kept or frozenset()
    # each value's numbers as one array, made once (every cell it bounds reads them)
    as_array = lambda f: (f[0], np.asarray(f[1], dtype=float), *f[2:])  # noqa: E731
    data: dict[float, tuple] = {}
    first = us  # the starting values are drawn in the first round, with its midpoints (one sweep, not two)
    jumps: list[tuple[float, float]] = []
    snap: set[int] = set()  # keys drawn from the nearer grid value
    bound = 0.0
    # per cell, its culprits' errors in the cell it was split from and in that one's parent: a mark that
    # jumps misses by the same at every depth, a smooth one by a quarter at each halving
    before: dict[tuple[float, float], tuple[dict[int, float], dict[int, float]]] = {}
    # the spots the plate's lettering stands at about its places (Measure.spots_key) are a choice, not a coordinate:
    # a cell across which they change is refined for the rest of the drawing only, and the change put at a grid
    # value after (_switch_spots), not chased down to MIN_CELL
    spots = lambda u: data[u][3].get("#spots", "")  # noqa: E731
    lettering: dict[int, tuple[list, np.ndarray]] = {}  # per list of keys (by its identity): the lettering's numbers

    def letters_of(keys: list) -> np.ndarray:
        got = lettering.get(id(keys))
        if got is None or got[0] is not keys:
            got = lettering[id(keys)] = (keys, _columns(keys, lambda k: k[0] in measure.lettering_ids))
        return got[1]

    while todo or first:
        asked = _asked(first, todo)
        if both is not None:  # (the first round, replayed with the furniture's values: drawn after its own, unread)
            drawn, both = measure.frames(protocol, both, both.size), None
        else:
            drawn, _ = _frames(construction, figure, given, values(asked), measure, protocol)
        # (each value's frame read as a cell needs it: what is drawn value by value is drawn then, not for the
        # midpoints ahead that no cell needs)
        at = dict(zip(asked, range(len(asked))))
        take = lambda u: as_array(drawn[at.pop(u)])  # noqa: E731
        data.update((u, take(u)) for u in first)
        first = []
        nxt = []
        queue = collections.deque(todo)
        while queue:
            a, b = queue.popleft()
            m = (a + b) / 2
            if m not in at:  # a half of a half: next round
                nxt.append((a, b))
                continue
            fm = data[m] = take(m)
            ka, na = data[a][:2]
            kb, nb = data[b][:2]
            parent, grand = before.pop((a, b), ({}, {}))
            if not ka == kb == fm[0]:
                err, culprits = math.inf, {-1: math.inf}
            else:
                err, culprits = _midpoint_error(ka, na, nb, fm[1], snap, None if spots(a) == spots(b) == spots(m)
                                                else letters_of(ka))
            if err <= REFINE_PX:
                bound = max(bound, err)
                continue
            if 0 < len(culprits) <= SNAP_AT_MOST and -1 not in culprits and all(ka[c][0] != "figure" and
                    c in parent and c in grand and e > JUMPING * parent[c] and parent[c] > JUMPING * grand[c]
                    and e > JUMP_PX for c, e in culprits.items()):
                # one or two marks jump here (an arc drawn the other way round): halving the cell twice did not
                # shrink what they miss by, so they are drawn from the nearer grid value everywhere (the rest
                # stays blended) rather than refined down to the floor
                snap.update(culprits)
                continue
            if b - a >= MIN_CELL and len(data) <= max_values:
                queue += [(a, m), (m, b)]
                before[(a, m)] = before[(m, b)] = (culprits, parent)
                continue
            if 0 < len(culprits) <= SNAP_AT_MOST and -1 not in culprits:
                snap.update(culprits)
                continue
            jumps.append((float(values(a)), float(values(b))))
        todo = nxt
    _switch_views(data, jumps, values, lambda us, keep: _frames(construction, figure, given, values(us), measure,
                                                               protocol, keep)[0], math.log10(initial),
                  max(1, round(VIEW_CELLS * share)))
    _switch_spots(data, spots, jumps, values, lambda us, keep: _frames(construction, figure, given, values(us),
                                                                     measure, protocol, keep)[0])
    us = sorted(data)
    # The keys every grid value shares; a few elements change form (e.g. a curve's number of points):
    # they stay at the built value.  (Most values share one list of keys, the same object: each list is read once.)
    forms = list({id(data[u][0]): data[u][0] for u in us}.values())
    shared = set(forms[0]).intersection(*forms[1:]) if len(forms) > 1 else set()
    keys = forms[0] if len(forms) == 1 else [k for k in data[us[0]][0] if k in shared]
    rows = []
    for u in us:
        kk, nn = data[u][:2]
        if kk is keys or kk == keys:  # (the commonest: every mark at every value) the numbers as they are
            rows.append(nn)
            continue
        pos, at = {}, 0
        for k in kk:
            n = k[2].count("#")
            pos[k] = nn[at:at + n]
            at += n
        rows.append([x for k in keys for x in pos[k]])
    fixed = sorted({k[0] for kk in forms[1:] + forms[:1] for k in kk if k not in shared}) if len(forms) > 1 else []
    # letters whose text is not the same at every grid value: values read off the figure (an angle in degrees
    # and minutes); a blend of two grid values' readings would print minutes the figure does not have
    # (a letter left out at some values -- no room there -- is not one of them)
    # (the rod's length the plate's furniture writes, a dimension "L = 5 r", is no reading: the page writes it)
    rod = re.compile(re.escape(live.rod).replace(re.escape("{v}"), r"[0-9.,]+") + "$") if live.rod else None
    said: dict[str, set[str]] = {}
    for texts in {id(data[u][3]): data[u][3] for u in us}.values():  # (most values share one dict of texts)
        for i, t in texts.items():
            said.setdefault(i, set()).add(t)
    # (the furniture's items a value's plate lacks: "#absent", their elements' ids)
    gone = [set(data[u][3].get("#absent", "").split()) for u in us]
    absent = {i: [int(i in g) for g in gone] for i in sorted(set().union(*gone), key=lambda i: (len(i), i))}
    said.pop("#absent", None)
    said.pop("#spots", None)
    varying = sorted(i for i, ts in said.items() if len(ts) > 1 and not (rod and all(rod.match(t) for t in ts)))
    first = data[us[0]][0]
    snapped = [first[i] for i in sorted(snap) if i < len(first) and (len(forms) == 1 or first[i] in shared)]
    grid = values(us)
    live = LiveSweep(given, symbol, domain, initial, grid, keys, np.asarray(rows, dtype=float), bound, jumps,
                     fixed=fixed, snapped=snapped, u=np.asarray(us, dtype=float), start=start, readings=varying,
                     # the fit travels as float32: the columns are checked against the drawing through it
                     fit=np.asarray([data[u][2] for u in us], dtype=np.float32).astype(float),
                     label_px=float(style.label_size), live=live, areas=measure.areas,
                     furniture_held=not measure.furniture_live and bool(measure.held[0]),
                     furniture_absent=absent,
                     furniture_note=measure.hidden_note(symbol) if measure.furniture_live else "",
                     reading_texts={i: [data[u][3].get(i, "") for u in us] for i in varying},
                     whole=whole if piece is not None else None)
    swept = construction.given_sweep(dict(figure.replay.givens), given, grid, protocol.params)
    live.derived = {k: np.broadcast_to(swept[k], grid.shape).astype(float).tolist() for k in DERIVED_WRITTEN
                    if k in swept and k != given and np.ptp(np.broadcast_to(swept[k], grid.shape)) > 0}
    # a piece of the domain: its share of the slider's checks (at least its ends)
    share = 1.0 if piece is None else math.log10(domain.high / domain.low) / math.log10(whole.high / whole.low)
    picks = check_picks(grid, max(2, round(CHECK_VALUES * share)))
    live.checks = dict(zip(picks, _checks(construction, figure, given, grid[picks], protocol)))
    # and at the built value (the book's): a teacher who returns there sees its own checks
    live.built_checks = measure.built_checks(figure)
    return live


def _checks(construction: Construction, figure: Figure, given: str, grid: np.ndarray,
            protocol: Any) -> list[list[list[Any]]]:
    """The construction's checks at every value of *grid*, from one sweep of *protocol*
    (:meth:`Construction.sweep_checks`)."""
    swept = construction.given_sweep(dict(figure.replay.givens), given, grid, protocol.params)
    sweep = Figure(protocol, protocol.replay(swept), construction.check, construction)
    return [[[c.name, c.measured, c.expected, c.error, c.tolerance, bool(c.ok)] for c in row]
            for row in construction.sweep_checks(sweep)]


#: The checks travel at this many grid values at most, and at the built value (the page shows the nearest: it
#: says which).
CHECK_VALUES = 48


def check_picks(grid: np.ndarray, at_most: int = CHECK_VALUES) -> list[int]:
    """The grid values (indices) the page shows checks at: up to *at_most*, evenly in log10 of the given
    (the grid is dense where the drawing bends, the slider is not), the first and the last among them.

    >>> check_picks(np.array([1.0, 1.1, 1.2, 10.0, 100.0]))  # 1.1 and 1.2 are one place on the slider
    [0, 2, 3, 4]
    >>> len(check_picks(10 ** np.linspace(0, 3, 500))), check_picks(10 ** np.linspace(0, 3, 500))[-1]
    (48, 499)
    """
    u = np.log10(grid)
    return sorted({int(np.argmin(np.abs(u - t))) for t in np.linspace(u[0], u[-1], min(len(u), at_most))})
