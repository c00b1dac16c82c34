"""The analytic formulas the constructions are checked against, and the numerics they take.

Nothing in here is used to *make* a construction: these functions are the
independent side of every check.  Angles are in radians, lengths in the
units of the crank radius ``r`` unless a function says otherwise.

Notation (DESIGN.md section 1): crank radius ``r``, rod length ``L``,
``lam = r/L``, crank angle ``omega`` measured from the head-end dead centre.

One definition of each: the exact slider crank (the piston's path, its rate
and its acceleration, the tangential pressure's factor), the books'
approximations, and the two numerical methods the models need -- composite
Gauss-Legendre quadrature (:func:`gauss_legendre`) and bisection
(:func:`bisect`).  Every function takes numbers or numpy arrays (a sweep's
givens, a row of quadrature nodes) and gives a float for numbers.

>>> round(piston_path_exact(math.pi / 2, 1.0, 4.0), 12)
1.127016653793
>>> piston_path_book(math.pi / 2, 1.0, 4.0)
1.125
>>> round(math.degrees(crank_angle_from_path(1.0, 1.0, 4.0)), 6)
82.819244
>>> piston_fraction(np.array([0.0, math.pi]), 0.2).tolist()     # the dead centres, on an array
[0.0, 1.0]
"""

from __future__ import annotations

import math
from typing import Any, Callable, Sequence

import numpy as np

__all__ = [
    "piston_fraction",
    "piston_rate",
    "piston_path_exact",
    "piston_path_book",
    "crank_angle_from_path",
    "inertia_two_term",
    "inertia_exact",
    "inertia_slope",
    "inertia_two_term_bound",
    "piston_path_book_bound",
    "tangential_factor",
    "zero_crossing_cos",
    "plus_m_cos",
    "gauss_legendre",
    "bisect",
]


def _out(v: Any) -> Any:
    """A float for a number, the array for an array."""
    return float(v) if np.ndim(v) == 0 else v


def _arc(np_fn: Callable[[Any], Any], math_fn: Callable[[float], float]) -> Callable[[Any], Any]:
    """An inverse sine or cosine: numpy's on arrays, the math module's on a number (numpy's differs from it in
    the last bit for one argument in ten, and a book's number read against it would move with that bit)."""
    return lambda v: math_fn(float(v)) if np.ndim(v) == 0 else np_fn(v)


_arccos, _arcsin = _arc(np.arccos, math.acos), _arc(np.arcsin, math.asin)


# -- the exact slider crank --------------------------------------------------------------------


def piston_fraction(omega: Any, lam: Any) -> Any:
    """The piston's path from the head-end dead centre as a fraction of the stroke, exact:
    ((1 - cos w) + (1 - sqrt(1 - lam^2 sin^2 w)) / lam) / 2, the second term written as
    lam sin^2 w / (1 + sqrt(1 - lam^2 sin^2 w)), which does not cancel for long rods."""
    s = np.sin(omega)
    return _out(0.5 * (1.0 - np.cos(omega) + lam * s * s / (1.0 + np.sqrt(1.0 - (lam * s) ** 2))))


def piston_rate(omega: Any, lam: Any) -> Any:
    """d/dw of :func:`piston_fraction`: (sin w + lam sin w cos w / sqrt(1 - lam^2 sin^2 w)) / 2."""
    s = np.sin(omega)
    return _out((s + lam * s * np.cos(omega) / np.sqrt(1.0 - lam * lam * s * s)) / 2.0)


def piston_path_exact(omega: Any, r: Any, L: Any) -> Any:
    """Piston path from the head-end dead centre, exact: r(1 - cos w) + L - sqrt(L^2 - r^2 sin^2 w)."""
    return _out(2.0 * r * piston_fraction(omega, r / L))


def piston_path_book(omega: Any, r: Any, L: Any) -> Any:
    """The books' approximation, Gl. (1): r [1 - cos w + (r / 2L) sin^2 w]."""
    return _out(r * (1.0 - np.cos(omega) + 0.5 * (r / L) * np.sin(omega) ** 2))


def crank_angle_from_path(x: Any, r: Any, L: Any) -> Any:
    """Crank angle for a piston path x on the forward stroke, Gl. (h) of seed 000 (exact).

    cos w = (x / 2r) (2L - x) / (x - r - L) + 1
    """
    c = (x / (2.0 * r)) * (2.0 * L - x) / (x - r - L) + 1.0
    return _out(_arccos(np.clip(c, -1.0, 1.0)))


def inertia_two_term(omega: Any, lam: Any, pressure_ratio: Any = 1.0) -> Any:
    """Inertia pressure per unit area, Gl. (4_1): q = (F/f)(cos w + lam cos 2w); eq. (298) without its factor."""
    return _out(pressure_ratio * (np.cos(omega) + lam * np.cos(2.0 * omega)))


def inertia_exact(omega: Any, lam: Any, pressure_ratio: Any = 1.0) -> Any:
    """The exact piston acceleration in the same units as Gl. (4_1).

    cos w + lam (cos 2w + lam^2 sin^4 w) / (1 - lam^2 sin^2 w)^(3/2): the second
    derivative of the exact piston path; Gl. (4_1) is its first two terms.
    """
    s2 = np.sin(omega) ** 2
    return _out(pressure_ratio * (
        np.cos(omega) + lam * (np.cos(2.0 * omega) + lam * lam * s2 * s2) / (1.0 - lam * lam * s2) ** 1.5))


def inertia_two_term_bound(lam: Any) -> Any:
    """How far Gl. (4_1) may stray from the exact acceleration: |inertia_exact - inertia_two_term| <= 2.5 lam^3 /
    (1 - lam^2)^2.5 (the dropped lam^3 terms, in the units of Gl. (4_1)).

    >>> w = np.linspace(0.0, math.pi, 181)
    >>> bool(np.max(np.abs(inertia_exact(w, 0.25) - inertia_two_term(w, 0.25))) <= inertia_two_term_bound(0.25))
    True
    """
    return _out(2.5 * lam ** 3 / (1.0 - lam * lam) ** 2.5)


def piston_path_book_bound(omega: Any, lam: Any) -> Any:
    """How far the books' path Gl. (1) may stray from the exact one, in units of r: it truncates the series after
    lam sin^2 w / 2, the remainder is at most lam^3 sin^4 w / (8 (1 - lam^2)).

    >>> w = np.linspace(0.0, math.pi, 181)
    >>> bool(np.all(np.abs(piston_path_exact(w, 1.0, 4.0) - piston_path_book(w, 1.0, 4.0))
    ...             <= piston_path_book_bound(w, 0.25)))
    True
    """
    return _out(lam ** 3 * np.sin(omega) ** 4 / (8.0 * (1.0 - lam * lam)))


def inertia_slope(omega: Any, r: Any, lam: Any, pressure_ratio: Any = 1.0) -> Any:
    """Slope dq/dx of the curve q over the piston path of Gl. (1), Gl. (i) with its sign.

    dq/dx = -(F/f)/r * (1 + 4 lam cos w) / (1 + lam cos w)
    """
    c = np.cos(omega)
    return _out(-pressure_ratio / r * (1.0 + 4.0 * lam * c) / (1.0 + lam * c))


def tangential_factor(omega: Any, lam: Any) -> Any:
    """sin(w + beta)/cos beta, sin beta = lam sin w: the tangential pressure on the crank pin over the piston force."""
    beta = _arcsin(lam * np.sin(omega))
    return _out(np.sin(omega + beta) / np.cos(beta))


def zero_crossing_cos(lam: float) -> float:
    """cos w where q = 0 (point q6): (-1 + sqrt(1 + 8 lam^2)) / (4 lam)."""
    return (-1.0 + math.sqrt(1.0 + 8.0 * lam * lam)) / (4.0 * lam)


def plus_m_cos(lam: float) -> float:
    """cos w where q = +m = +lam F/f (point q7): (-1 + sqrt(1 + 16 lam^2)) / (4 lam).

    Seed 000 prints (-L + sqrt(L^2 - 16 r^2)) / 4r; the sign under the root is a
    misprint (its own numbers, .4140 for L/r = 4, follow from the plus sign).
    """
    return (-1.0 + math.sqrt(1.0 + 16.0 * lam * lam)) / (4.0 * lam)


# -- numerics ------------------------------------------------------------------------------------

#: Gauss-Legendre nodes and weights on [-1, 1], by order.
_LEGENDRE: dict[int, tuple[np.ndarray, np.ndarray]] = {}


def gauss_legendre(fn: Callable[[np.ndarray], Any], a: Any, b: Any, *, breaks: Sequence[Any] = (),
                   pieces: int = 16, order: int = 20) -> Any:
    """The integral of *fn* from *a* to *b*: Gauss-Legendre of *order* on *pieces* equal pieces of every smooth
    stretch between the *breaks* (where the integrand has a corner; those outside (a, b) make stretches of
    width 0).

    *a*, *b* and the breaks are numbers or arrays of n values (n integrals at once, a sweep's); *fn* takes
    the angles as an array of one row per integral and gives its values in the same shape.  Order 20 on 16
    pieces integrates the models (smooth between their corners) to rounding.

    >>> round(gauss_legendre(np.sin, 0.0, math.pi), 15), gauss_legendre(np.abs, -1.0, 1.0, breaks=[0.0])
    (2.0, 1.0)
    >>> gauss_legendre(lambda w: w * w, 0.0, np.array([1.0, 3.0])).round(15).tolist()
    [0.333333333333333, 9.0]
    """
    if order not in _LEGENDRE:
        _LEGENDRE[order] = np.polynomial.legendre.leggauss(order)
    xs, ws = _LEGENDRE[order]
    scalar = np.ndim(a) == 0 and np.ndim(b) == 0 and all(np.ndim(t) == 0 for t in breaks)
    a, b = np.atleast_1d(np.asarray(a, dtype=float)), np.atleast_1d(np.asarray(b, dtype=float))
    n = max(a.size, b.size)
    a, b = np.broadcast_to(a, (n,)), np.broadcast_to(b, (n,))
    inner = [np.clip(np.broadcast_to(np.asarray(t, dtype=float), (n,)), a, b) for t in breaks]
    edges = [a, *(np.sort(np.stack(inner), axis=0) if inner else ()), b]
    total = np.zeros(n)
    for lo, hi in zip(edges, edges[1:]):
        h = (hi - lo) / pieces
        nodes = (lo[:, None] + h[:, None] * np.arange(pieces))[:, :, None] + (xs + 1.0) * h[:, None, None] / 2.0
        values = np.asarray(fn(nodes.reshape(n, -1)), dtype=float).reshape(nodes.shape)
        total += (values * ws).sum(axis=(1, 2)) * h / 2.0
    return float(total[0]) if scalar else total


def bisect(fn: Callable[[Any], Any], a: Any, b: Any) -> Any:
    """Where *fn* changes sign between *a* and *b*, to the last bit: the interval is halved, keeping the half
    where the sign changes, until no float lies between its ends.  Numbers (*fn* is asked with numbers), or
    arrays (one root each; *fn* is asked with arrays).

    >>> abs(bisect(lambda x: x * x - 2.0, 0.0, 2.0) - math.sqrt(2.0)) <= math.ulp(math.sqrt(2.0))
    True
    >>> bisect(np.cos, np.array([0.0, 3.0]), np.array([3.0, 6.0])).tolist() == [math.pi / 2, 3 * math.pi / 2]
    True
    """
    scalar = np.ndim(a) == 0 and np.ndim(b) == 0
    a, b = (x.copy() for x in np.broadcast_arrays(np.atleast_1d(np.asarray(a, dtype=float)),
                                                  np.atleast_1d(np.asarray(b, dtype=float))))
    if scalar:  # a function of one number is asked with one
        fn = (lambda f: lambda v: np.array([f(float(v[0]))]))(fn)
    fa = np.asarray(fn(a), dtype=float)
    for _ in range(2100):  # each halving takes a bit off the interval: a float has fewer than 2100 to give
        m = 0.5 * (a + b)
        open_ = (a < m) & (m < b)
        if not open_.any():
            break
        fm = np.asarray(fn(m), dtype=float)
        same = open_ & ((fm > 0) == (fa > 0))
        a, fa, b = np.where(same, m, a), np.where(same, fm, fa), np.where(open_ & ~same, m, b)
    m = 0.5 * (a + b)
    return float(m[0]) if scalar else m
