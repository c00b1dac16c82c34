"""The registry of constructions: each book method by name.

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

import numpy as np
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Callable, Mapping

from .checking import Check, run_checks
from ..kernel.errors import InvalidParameter, ProtocolFormatError, UnknownConstruction, did_you_mean
from ..kernel.numeric import shown
from ..figure import Figure
from ..kernel.protocol import Caption, Protocol

if TYPE_CHECKING:  # the module itself is imported where it is used: 'import construct' loads no construction
    from .domain import Domain

__all__ = ["Figure", "Construction", "register", "get", "find", "names", "positive", "bounded", "rod_ratio_param"]


@dataclass(frozen=True)
class Construction:
    """A book method: how to build it, how to check it, and its parameters."""

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
    extra: Mapping[str, Any] = field(default_factory=dict)
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

    def figure(self, **params: Any) -> Figure:
        unknown = sorted(set(params) - set(self.defaults))
        if unknown:
            raise InvalidParameter(f"{self.name} has no parameter {', '.join(unknown)}"
                                   f"{did_you_mean(unknown[0], self.defaults) if len(unknown) == 1 else ''}; "
                                   f"it takes {', '.join(sorted(self.defaults))}")
        merged = {**self.defaults, **{k: v for k, v in params.items() if v is not None}}
        built = self.build(**merged)
        return Figure(built.protocol, built.replay, self.check)

    def check(self, figure: Figure) -> list[Check]:
        """The checks of this construction on *figure* (what :meth:`Figure.checks` runs for the figures it makes).

        A figure replayed from a protocol by hand has not met the construction's own check of its givens (a rod
        no longer than the crank, say): the checks' formulas assume it, so it is made here first.
        """
        _validate_givens(self.name, figure.replay.givens)
        return run_checks(self, figure)

    def rod_ratio_sweep(self, givens: Mapping[str, float], ratios: Any) -> dict[str, Any] | None:
        """The givens that replay a figure of this construction at every rod ratio in *ratios* (None: no rod)."""
        if self.sweep is not None:
            return self.sweep(givens, np.asarray(ratios, dtype=float))
        if "rod_ratio" not in givens:
            return None
        return {**givens, "rod_ratio": np.asarray(ratios, dtype=float)}

    def sweep_checks(self, figure: Figure) -> list[list[Check]]:
        """The checks of every set of givens of a sweep (a figure replayed with arrays of givens), set by set.

        What the checks integrate from the givens (:attr:`sweep_model`) is
        computed once for the whole sweep, on arrays; what they measure is read
        off each set's objects, as :meth:`Figure.checks` reads them.
        """
        replay = figure.replay
        sets = [replay.take(i) for i in range(replay.size)] if replay.size else [replay]
        if self.validates_sweeps:  # every set is valid before the model is computed for all of them
            _validate_givens(self.name, replay.givens)
        else:
            for one in sets:
                _validate_givens(self.name, one.givens)
        model = None if self.sweep_model is None else self.sweep_model(replay.givens, figure.params)
        return [run_checks(self, Figure(figure.protocol, one), None if model is None else _take_model(model, i))
                for i, one in enumerate(sets)]

    def validate(self, givens: Mapping[str, Any]) -> None:
        """Raise InvalidParameter if a set of givens (a protocol's, by their own names) lies outside the domain."""
        _validate_givens(self.name, givens)

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
        _validate_givens(self.name, values)
        return Figure(protocol, protocol.replay(values), self.check)


def _take_model(model: Any, i: int) -> Any:
    """Element *i* of a sweep's model: arrays give their i-th value, mappings and sequences element by element."""
    if isinstance(model, Mapping):
        return {k: _take_model(v, i) for k, v in model.items()}
    if isinstance(model, (list, tuple)):
        return type(model)(_take_model(v, i) for v in model)
    if isinstance(model, np.ndarray) and model.ndim:
        return float(model[i])
    return model


_VALIDATORS: dict[str, Callable[[Mapping[str, float]], None]] = {}
_REGISTRY: dict[str, Construction] = {}
_MODULES = ("crank", "inertia", "indicator", "piston_force", "tangential", "two_cranks", "four_stroke", "flywheel_rim")


def register(c: Construction, validate: Callable[[Mapping[str, float]], None] | None = None) -> Construction:
    _REGISTRY[c.name] = c
    if validate is not None:
        _VALIDATORS[c.name] = validate
    return c


def _validate_givens(name: str, givens: Mapping[str, float]) -> None:
    if name in _VALIDATORS:
        try:
            _VALIDATORS[name](givens)
        except KeyError as exc:  # a protocol (truncated, edited) that no longer stores a given the construction has
            raise ProtocolFormatError(f"the protocol of {name!r} lacks the given {exc.args[0]!r} of the construction "
                                      f"(it has {', '.join(sorted(givens)) or 'none'})") from None


def _load() -> None:
    # Imported on first use, not at import time: the construction modules import this one.
    for mod in _MODULES:
        importlib.import_module(f"{__name__}.{mod}")


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
    from .domain import ROD_RATIO

    return bounded("rod ratio L/r", value, ROD_RATIO)
