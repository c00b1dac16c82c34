"""The registry of constructions: each book method by name.

A construction knows itself: how it is built and checked, its parameters and
their domain, the texts it follows, how its books write its givens, methods
and conventions, and its plate (:class:`Construction`).  The drawing layer
reads all of that off the construction and keeps no table of constructions,
so adding one is adding one module: a module of this package that calls
:func:`register` is found by :func:`names` and :func:`get`, and so is one of
another package that names itself under the entry point group
``construct.constructions``.

>>> sorted(names())[:2]
['crank', 'crank-angle']
>>> get("nonsense")
Traceback (most recent call last):
...
construct.kernel.errors.UnknownConstruction: unknown construction 'nonsense'; available: crank, crank-angle...
"""

from __future__ import annotations

import importlib
import math
import pkgutil
import warnings

import numpy as np
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Mapping, Sequence

from .checking import Check, run_checks
from .domain import ROD_RATIO, Domain
from .phrases import Cite
from ..kernel.errors import InvalidParameter, ProtocolFormatError, UnknownConstruction, did_you_mean
from ..kernel.numeric import shown
from ..figure import Figure
from ..kernel.protocol import Caption, Protocol

__all__ = ["Figure", "Construction", "Cite", "register", "get", "find", "names", "positive", "bounded",
           "rod_ratio_param", "form_rows", "ENTRY_POINTS"]

#: The entry point group under which another package names the modules that register its constructions.
ENTRY_POINTS = "construct.constructions"


@dataclass(frozen=True)
class Construction:
    """A book method: how to build it, how to check it, its parameters, and how its books write it."""

    name: str
    title: Caption
    source: str
    build: Callable[..., Figure]
    checks: Callable[[Figure], list[Check]]
    defaults: Mapping[str, Any]
    #: Parameter sets the books print figures or tables for (the gallery builds these).
    book_params: tuple[Mapping[str, Any], ...] = ()
    #: Structural params: changing them changes the steps, not just their values.
    structural: tuple[str, ...] = ()
    #: Continuous givens whose value never changes which steps it takes, only their values (the rod in the
    #: crank's figure): a live player replays the built protocol over their whole domain without looking for
    #: pieces (:func:`construct.live.sweep.pieces`; tests/test_live.py scans every one).
    steady: tuple[str, ...] = ()
    #: For the other continuous givens: the build's choices that shape its steps (which points a line runs
    #: through, which dead centre a circle is struck about), read off a replay of the built protocol over a
    #: sweep's values -- (replay, the protocol's params) -> an integer array, one row per value, rows equal where
    #: fresh builds take the same steps from the same objects; or None where it cannot tell (those params).  A
    #: live player finds the pieces of the domain from it on arrays (:func:`construct.live.sweep.pieces`;
    #: tests/test_live.py holds it to fresh builds).  None: fresh builds tell.
    form: Callable[[Any, Mapping[str, Any]], Any] | None = None
    #: Anything else a caller keeps with it (read by no one here).
    extra: Mapping[str, Any] = field(default_factory=dict)
    #: The texts and the figures in them it follows, as a caption cites them.
    cites: tuple[Cite, ...] = ()
    #: Its givens as its book writes them, in the book's symbols and units: (figure, "de" or "en") -> phrases
    #: ("r/L = 1/5", "Halbkreis in 18 Teilen").  None: each given and parameter in turn, by :attr:`symbols`.
    wording: Callable[[Figure, str], Sequence[str]] | None = None
    #: How its book writes a given or parameter, "{v}" the value ("rod_ratio": Caption("L/r = {v}", ...)),
    #: where it has no :attr:`wording`.
    symbols: Mapping[str, Caption] = field(default_factory=dict)
    #: The names of its methods, the values of its parameter "method".
    methods: Mapping[str, Caption] = field(default_factory=dict)
    #: The names of its conventions: parameter -> value -> name (where two cranks start: "dead_centre").
    conventions: Mapping[str, Mapping[str, Caption]] = field(default_factory=dict)
    #: What a figure must say beyond its givens, (figure, lang) -> text ("" for nothing).
    note: Callable[[Figure, str], str] | None = None
    #: Its plate's looks and furniture as plain data (:meth:`construct.render.plate.Plate.from_data`).
    plate: Callable[[Figure], Mapping[str, Any]] | None = None
    #: Raises InvalidParameter when a set of givens (a protocol's, by their own names) is outside its domain.
    validator: Callable[[Mapping[str, Any]], None] | None = None
    #: A line of help per parameter, for the command line.
    help: Mapping[str, str] = field(default_factory=dict)
    #: The givens of a sweep over rod ratios L/r, from a figure's givens: for constructions that name the rod
    #: otherwise (a rod length in metres) or whose other givens follow the rod ratio.  None: set "rod_ratio".
    sweep: Callable[[Mapping[str, float], Any], dict[str, Any]] | None = None
    #: What the checks compute numerically from the givens alone (the exact model's integrals, extremes),
    #: for a sweep's givens in one numpy pass: (givens, params) -> names to arrays, element i for set i.
    #: The checks take it as ``checks(figure, model=...)``.  None: the checks integrate nothing.
    sweep_model: Callable[[Mapping[str, Any], Mapping[str, Any]], Mapping[str, Any]] | None = None
    #: Whether its validator takes a sweep's givens (arrays) at once, naming the first set outside the domain;
    #: else :meth:`sweep_checks` validates set by set.
    validates_sweeps: bool = False
    #: The givens it computes from others by its book's own formula, whatever set those (tangential-pressure:
    #: c v²/r = P/((1 + r/L) κ) from κ and L/r; two-cranks: the magnification it chose itself, from L/r): applied
    #: to the givens of a protocol replayed with new givens and of a sweep (arrays): (givens, the protocol's
    #: params) -> givens.  None: no given follows from another.
    derived: Callable[[Mapping[str, Any], Mapping[str, Any]], dict[str, Any]] | None = None

    def __post_init__(self) -> None:
        # where a construction kept its plate and its parameters' help before they were fields of their own
        moved = [key for key in ("plate", "help") if key in self.extra and not getattr(self, key)]
        if moved:
            warnings.warn(f"Construction(extra={{{', '.join(map(repr, moved))}: ...}}) is deprecated; pass "
                          f"{'= and '.join(moved)}= itself", DeprecationWarning, stacklevel=3)
        for key in moved:
            object.__setattr__(self, key, self.extra[key])

    def figure(self, **params: Any) -> Figure:
        unknown = sorted(set(params) - set(self.defaults))
        if unknown:
            raise InvalidParameter(f"{self.name} has no parameter {', '.join(unknown)}"
                                   f"{did_you_mean(unknown[0], self.defaults) if len(unknown) == 1 else ''}; "
                                   f"it takes {', '.join(sorted(self.defaults))}")
        merged = {**self.defaults, **{k: v for k, v in params.items() if v is not None}}
        built = self.build(**merged)
        return Figure(built.protocol, built.replay, self.check, self)

    def check(self, figure: Figure) -> list[Check]:
        """The checks of this construction on *figure* (what :meth:`Figure.checks` runs for the figures it makes).

        A figure replayed from a protocol by hand has not met the construction's own check of its givens (a rod
        no longer than the crank, say): the checks' formulas assume it, so it is made here first.
        """
        self.validate(figure.replay.givens)
        return run_checks(self, figure)

    def rod_ratio_sweep(self, givens: Mapping[str, float], ratios: Any) -> dict[str, Any] | None:
        """The givens that replay a figure of this construction at every rod ratio in *ratios* (None: no rod)."""
        if self.sweep is not None:
            return self.sweep(givens, np.asarray(ratios, dtype=float))
        if "rod_ratio" not in givens:
            return None
        return self.given_sweep(givens, "rod_ratio", ratios)

    def given_sweep(self, givens: Mapping[str, Any], name: str, values: Any,
                    params: Mapping[str, Any] | None = None) -> dict[str, Any]:
        """The givens that replay a figure of this construction at every value of its given *name* in *values*
        (the others as in *givens*, those that follow from them by :attr:`derived`; *params*: the protocol's).

        >>> from construct.constructions import get
        >>> g = get("tangential-pressure").figure().replay.givens
        >>> swept = get("tangential-pressure").given_sweep(g, "kappa", [8.0, 2.0])
        >>> [round(float(x), 6) for x in swept["pressure_ratio"]]  # c v^2/r = P/((1 + r/L) kappa): 4 times as much
        [0.817708, 3.270833]
        """
        if name not in givens:
            raise InvalidParameter(f"{self.name} has no given {name!r} to sweep; it has {', '.join(sorted(givens))}")
        out = {**givens, name: np.asarray(values, dtype=float)}
        return self.derived(out, params or {}) if self.derived is not None else out

    def sweep_checks(self, figure: Figure) -> list[list[Check]]:
        """The checks of every set of givens of a sweep (a figure replayed with arrays of givens), set by set.

        What the checks integrate from the givens (:attr:`sweep_model`) is
        computed once for the whole sweep, on arrays; what they measure is read
        off each set's objects, as :meth:`Figure.checks` reads them.
        """
        replay = figure.replay
        sets = replay.sets()
        if self.validates_sweeps:  # every set is valid before the model is computed for all of them
            self.validate(replay.givens)
        else:
            for one in sets:
                self.validate(one.givens)
        model = None if self.sweep_model is None else self.sweep_model(replay.givens, figure.params)
        return [run_checks(self, Figure(figure.protocol, one), None if model is None else _take_model(model, i))
                for i, one in enumerate(sets)]

    def validate(self, givens: Mapping[str, Any]) -> None:
        """Raise InvalidParameter if a set of givens (a protocol's, by their own names) lies outside the domain."""
        if self.validator is None:
            return
        try:
            self.validator(givens)
        except KeyError as exc:  # a protocol (truncated, edited) that no longer stores a given the construction has
            raise ProtocolFormatError(f"the protocol of {self.name!r} lacks the given {exc.args[0]!r} of the "
                                      f"construction (it has {', '.join(sorted(givens)) or 'none'})") from None

    def replay(self, protocol: Protocol, **givens: Any) -> Figure:
        """Replay an existing protocol with new givens (only those that keep the steps)."""
        values = dict(protocol.params.get("givens", {}))
        for key, value in givens.items():
            if value is None:
                continue
            if key in self.structural and protocol.params.get(key) != value:
                raise InvalidParameter(
                    f"{key} = {value!r} changes the steps of the protocol ({key} = {protocol.params.get(key)!r}); "
                    f"build it afresh with 'construct replay {self.name} --{key.replace('_', '-')}"
                    f"{'' if value is True else ' ' + str(value)}'")
            if key in values:
                values[key] = positive(key, value)
        if self.derived is not None:  # what follows from the new givens by the book's formula
            values = self.derived(values, protocol.params)
        self.validate(values)
        return Figure(protocol, protocol.replay(values), self.check, self)


def _take_model(model: Any, i: int) -> Any:
    """Element *i* of a sweep's model: arrays give their i-th value, mappings and sequences element by element."""
    if isinstance(model, Mapping):
        return {k: _take_model(v, i) for k, v in model.items()}
    if isinstance(model, (list, tuple)):
        return type(model)(_take_model(v, i) for v in model)
    if isinstance(model, np.ndarray) and model.ndim:
        return float(model[i])
    return model


_REGISTRY: dict[str, Construction] = {}
_loaded = False


def register(c: Construction, validate: Callable[[Mapping[str, Any]], None] | None = None) -> Construction:
    """Register *c* under its name (a later one of the same name replaces it) and return it.

    *validate*: the old place of :attr:`Construction.validator` (deprecated).
    """
    if validate is not None:
        warnings.warn("register(c, validate=f) is deprecated; give the construction validator=f",
                      DeprecationWarning, stacklevel=2)
        c = replace(c, validator=validate)
    _REGISTRY[c.name] = c
    return c


def _load() -> None:
    """Import every module of this package and every module named under :data:`ENTRY_POINTS`: each registers
    the constructions it defines.  On first use, not at import time: the construction modules import this one."""
    global _loaded
    if _loaded:
        return
    for info in pkgutil.iter_modules(__path__):
        importlib.import_module(f"{__name__}.{info.name}")
    from importlib.metadata import entry_points

    for ep in entry_points(group=ENTRY_POINTS):
        ep.load()
    _loaded = True


def names() -> list[str]:
    _load()
    return sorted(_REGISTRY)


def get(name: str) -> Construction:
    _load()
    try:
        return _REGISTRY[name]
    except (KeyError, TypeError):  # TypeError: an unhashable name
        raise UnknownConstruction(f"unknown construction {name!r}{did_you_mean(name, _REGISTRY)}; "
                                  f"available: {', '.join(sorted(_REGISTRY))}") from None


def find(name: str) -> Construction | None:
    """The registered construction of that name, or None (a protocol of the user's own)."""
    _load()
    return _REGISTRY.get(name) if isinstance(name, str) else None


def form_rows(*choices: Any) -> np.ndarray:
    """A build's choices over a sweep as :attr:`Construction.form` gives them: one row per value, one integer
    column per choice (arrays over the values, or numbers the same at every value; booleans are 0 and 1).

    >>> form_rows(np.array([1.0, 2.0]) < 1.5, 3).tolist()
    [[1, 3], [0, 3]]
    """
    return np.stack(np.broadcast_arrays(*(np.atleast_1d(np.asarray(c)) for c in choices)), axis=-1).astype(np.int64)


def positive(name: str, value: Any) -> Any:
    """A finite, positive number (or array of them, for a sweep), or a clear error naming the parameter."""
    if isinstance(value, (np.ndarray, list, tuple)):
        try:
            arr = np.asarray(value, dtype=float)
        except (TypeError, ValueError, OverflowError):  # OverflowError: an integer beyond any float
            raise InvalidParameter(f"{name} must be finite numbers, got {shown(value)}") from None
        bad = ~np.isfinite(arr) | ~(arr > 0.0)
        if arr.size == 0 or bad.any():
            raise InvalidParameter(f"{name} must be finite and positive, got {arr[bad][:3].tolist() or 'no values'}")
        return arr
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InvalidParameter(f"{name} must be a number, got {shown(value)}") from None
    except OverflowError:  # an integer beyond any float
        raise InvalidParameter(f"{name} must be finite and positive, got {shown(value)}") from None
    if not math.isfinite(v) or v <= 0.0:
        raise InvalidParameter(f"{name} must be finite and positive, got {shown(value)}")
    return v


def bounded(name: str, value: Any, domain: Domain) -> Any:
    """A finite, positive number (or array) inside *domain* (construct.constructions.domain), or an error naming it."""
    return domain.check(name, positive(name, value))


def rod_ratio_param(value: Any) -> Any:
    """L/r: the connecting rod must be longer than the crank (every value of a sweep), L/r in the stated domain."""
    try:
        v = np.asarray(value, dtype=float)
    except (TypeError, ValueError, OverflowError):  # OverflowError: an integer beyond any float
        raise InvalidParameter(f"rod ratio L/r must be a finite number, got {shown(value)}") from None
    if v.size and np.all(np.isfinite(v)) and np.any(v <= 1.0):
        raise InvalidParameter(f"rod ratio L/r must be greater than 1 (the rod must be longer than the crank), "
                               f"got {value!r}")
    return bounded("rod ratio L/r", value, ROD_RATIO)
