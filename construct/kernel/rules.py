"""Which of the points where two curves meet a construction wants: rules, never indices.

Two circles meet twice; a replay with other givens must pick the same branch,
so a step stores a *rule* that names objects of the construction:

- :func:`nearer` / :func:`farther`: the point nearer to / farther from a point;
- :func:`left_of` / :func:`right_of`: the point on that side of the directed line A→B;
- :func:`toward`: the point farthest along the direction A→B, or a fixed direction;
- :func:`only`: there must be one point (a line crossing, a tangency).

A rule is a small value; it serialises to the JSON list the protocol format
has always used (``["nearer", "A"]``, ``["toward", null, null, -1.0, 0.0]``).

>>> nearer("A")
nearer('A')
>>> left_of("A", "B").as_json()
['left', 'A', 'B']
>>> as_rule(["toward", "O", None, -1.0, 0.0])
toward(dx=-1.0, dy=0.0)
>>> as_rule("left")
Traceback (most recent call last):
...
construct.kernel.errors.RuleError: a rule is a value like left_of('A', 'B') or a list like ['left', 'A', 'B'], got 'left'
"""

from __future__ import annotations

import functools
from typing import Any, Sequence

from .errors import RuleError, did_you_mean
from .geometry import SCALAR, raw_point
from .numeric import is_finite, shown

__all__ = ["Rule", "nearer", "farther", "left_of", "right_of", "toward", "only", "as_rule", "RULE_ARITY", "choose",
           "choose_among", "choose_among_sets"]

#: How many object names each rule refers to.
RULE_ARITY = {"nearer": 1, "farther": 1, "left": 2, "right": 2, "toward": 2, "only": 0}


class Rule:
    """A branch rule: its name, the objects it refers to and, for ``toward``, a fixed direction."""

    __slots__ = ("name", "refs", "direction", "_json")

    def __init__(self, name: str, refs: Sequence[str] = (), direction: tuple[float, float] | None = None,
                 raw: Sequence[Any] | None = None) -> None:
        if name not in RULE_ARITY:
            raise RuleError(f"unknown intersection rule {name!r}{did_you_mean(name, RULE_ARITY)}; known: {', '.join(sorted(RULE_ARITY))}")
        refs = tuple(refs)
        if not all(isinstance(r, str) for r in refs):
            raise RuleError(f"rule {name!r} refers to objects by name, got {refs!r}")
        want = RULE_ARITY[name]
        if direction is None and len(refs) != want:
            raise RuleError(f"rule {name!r} names {want} object{'s' if want != 1 else ''}, got {len(refs)}: {refs!r}")
        if direction is not None:
            if name != "toward" or refs and len(refs) > 1:
                raise RuleError(f"only 'toward' takes a fixed direction, got {name!r} with {refs!r}")
            dx, dy = _direction(direction)
            if dx == 0.0 and dy == 0.0:
                raise RuleError("rule 'toward' needs a direction other than (0, 0)")
            direction = (dx, dy)
        s = object.__setattr__
        s(self, "name", name)
        s(self, "refs", refs if direction is None else ())
        s(self, "direction", direction)
        # The JSON form, kept exactly as a protocol file wrote it (a fixed direction may carry a point name).
        s(self, "_json", tuple(raw) if raw is not None else None)

    def __setattr__(self, key: str, value: Any) -> None:
        raise AttributeError("Rule is immutable")

    def as_json(self) -> list:
        if self._json is not None:
            return list(self._json)
        if self.direction is not None:
            return [self.name, None, None, self.direction[0], self.direction[1]]
        return [self.name, *self.refs]

    def as_tuple(self) -> tuple:
        return tuple(self.as_json())

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Rule):
            return NotImplemented
        return (self.name, self.refs, self.direction) == (other.name, other.refs, other.direction)

    def __hash__(self) -> int:
        return hash((self.name, self.refs, self.direction))

    def __reduce__(self):
        return (as_rule, (self.as_json(),))

    def __repr__(self) -> str:
        fn = {"left": "left_of", "right": "right_of"}.get(self.name, self.name)
        if self.direction is not None:
            return f"toward(dx={self.direction[0]!r}, dy={self.direction[1]!r})"
        return f"{fn}({', '.join(repr(r) for r in self.refs)})"


def _direction(direction: Any) -> tuple[float, float]:
    """(dx, dy) as two finite floats: a NaN direction would choose a branch by chance, steps later."""
    try:
        dx, dy = direction
    except (TypeError, ValueError):
        raise RuleError(f"rule 'toward' takes a direction (dx, dy), got {direction!r}") from None
    for v in (dx, dy):
        if not is_finite(v):
            raise RuleError(f"rule 'toward' needs a direction of two finite numbers, got ({shown(dx)}, {shown(dy)})")
    return float(dx), float(dy)


def _points(fn: str, points: tuple[Any, ...], want: int) -> tuple[str, ...]:
    """The point names a rule function was called with, else a RuleError naming the rule and what it takes.

    Called as ``nearer()`` or ``left_of("A")`` Python's own TypeError would not say which rule of which
    step; this one does.
    """
    if len(points) != want or not all(isinstance(p, str) and p for p in points):
        takes = "one point name" if want == 1 else f"{want} point names"
        got = ", ".join(shown(p) for p in points) or "nothing"
        raise RuleError(f"rule {fn}() takes {takes}, got {got}")
    return tuple(points)


def nearer(*point: str) -> Rule:
    """The intersection nearer to *point* (one name).

    >>> nearer()
    Traceback (most recent call last):
    ...
    construct.kernel.errors.RuleError: rule nearer() takes one point name, got nothing
    """
    return Rule("nearer", _points("nearer", point, 1))


def farther(*point: str) -> Rule:
    """The intersection farther from *point* (one name)."""
    return Rule("farther", _points("farther", point, 1))


def left_of(*ab: str) -> Rule:
    """The intersection to the left of the directed line a→b (two names).

    >>> left_of("A")
    Traceback (most recent call last):
    ...
    construct.kernel.errors.RuleError: rule left_of() takes 2 point names, got 'A'
    """
    return Rule("left", _points("left_of", ab, 2))


def right_of(*ab: str) -> Rule:
    """The intersection to the right of the directed line a→b (two names)."""
    return Rule("right", _points("right_of", ab, 2))


def toward(a: str | None = None, b: str | None = None, *, dx: float | None = None, dy: float | None = None) -> Rule:
    """The intersection farthest along a→b, or along the fixed direction (dx, dy).

    >>> toward("O", "P"), toward(dx=-1)
    (toward('O', 'P'), toward(dx=-1.0, dy=0.0))
    """
    if dx is not None or dy is not None:
        if a is not None or b is not None:
            raise RuleError("toward() takes two points or a direction (dx, dy), not both")
        return Rule("toward", (), (dx or 0.0, dy or 0.0))
    if a is None or b is None:
        raise RuleError("toward() needs two points a, b or a direction dx=..., dy=...")
    return Rule("toward", (a, b))


def only() -> Rule:
    """There must be exactly one point (two lines; a tangency)."""
    return Rule("only")


def as_rule(rule: Any) -> Rule:
    """A Rule from a Rule or from its JSON list / tuple form (the form protocols store)."""
    if isinstance(rule, Rule):
        return rule
    if type(rule) is tuple and all(type(part) is str for part in rule):
        # names only (a number of a fixed direction is kept as written: 1 and 1.0 are one key): made once, a
        # builder's every intersection asks twice (its step stores the form, the step's entry reads it)
        return _names_rule(rule)
    return _rule(rule)


@functools.lru_cache(maxsize=4096)
def _names_rule(rule: tuple[str, ...]) -> Rule:
    """:func:`as_rule` of a tuple of names (a Rule is immutable)."""
    return _rule(rule)


def _rule(rule: Any) -> Rule:
    if isinstance(rule, str) or not isinstance(rule, (list, tuple)) or not rule:
        raise RuleError(f"a rule is a value like left_of('A', 'B') or a list like ['left', 'A', 'B'], got {rule!r}")
    name = rule[0]
    if not isinstance(name, str):
        raise RuleError(f"a rule starts with its name ({', '.join(sorted(RULE_ARITY))}), got {list(rule)!r}")
    if name == "toward" and len(rule) == 5:
        if rule[1] is not None and not isinstance(rule[1], str):
            raise RuleError(f"rule {list(rule)!r}: the first point of a direction is a name or null")
        if rule[2] is not None:
            raise RuleError(f"rule {list(rule)!r}: a fixed direction leaves the second point empty")
        return Rule("toward", (), (rule[3], rule[4]), raw=rule)
    if name not in RULE_ARITY:
        raise RuleError(f"unknown intersection rule {name!r}{did_you_mean(name, RULE_ARITY)}; known: {', '.join(sorted(RULE_ARITY))}")
    return Rule(name, tuple(rule[1:]))


def rule_key(rule: Rule, refs: Sequence[Any], x: Any, y: Any) -> tuple[Any, bool]:
    """What *rule* ranks a point (x, y) by, and whether the smallest wins: the squared distance from the point it
    names (nearer: the smallest), the signed area to the left of its line (left: the largest), the distance along
    its direction (toward: the largest).  *x*, *y*: numbers or arrays.

    >>> from .geometry import Point
    >>> rule_key(nearer("Q"), (Point(0.0, 3.0),), 4.0, 0.0), rule_key(left_of("A", "B"), (Point(0, 0), Point(1, 0)), 2.0, -1.0)
    ((25.0, True), (-1.0, False))
    """
    name = rule.name
    if name in ("nearer", "farther"):
        (r,) = refs
        return (x - r.x) ** 2 + (y - r.y) ** 2, name == "nearer"
    if name in ("left", "right"):
        p, q = refs
        return (q.x - p.x) * (y - p.y) - (q.y - p.y) * (x - p.x), name == "right"
    if rule.direction is None:
        p, q = refs
        dx, dy = q.x - p.x, q.y - p.y
    else:
        dx, dy = rule.direction
    return x * dx + y * dy, False


def choose(points: Sequence[Any], rule: Rule, refs: Sequence[Any], xp: Any) -> tuple[Any, Any]:
    """Pick one of two points by *rule*; return (chosen, other).  Vectorised with ``xp.where``.

    *refs* are the objects the rule names, already looked up.  With one point
    (two lines), that point is the answer whatever the rule.

    >>> from .geometry import Point, SCALAR
    >>> pts = (Point(0.0, 1.0), Point(0.0, -1.0))
    >>> choose(pts, left_of("A", "B"), (Point(-1.0, 0.0), Point(1.0, 0.0)), SCALAR)[0]
    Point(0.0, 1.0)
    >>> choose(pts, nearer("Q"), (Point(0.0, -5.0),), SCALAR)[0]
    Point(0.0, -1.0)
    """
    if len(points) == 1:
        return points[0], None
    a, b = points
    if rule.name == "only":  # the caller has checked that the two points coincide
        return a, b
    ka, smallest = rule_key(rule, refs, a.x, a.y)
    kb, _ = rule_key(rule, refs, b.x, b.y)
    first = ka <= kb if smallest else ka >= kb
    if xp is SCALAR:
        return (a, b) if first else (b, a)
    # in a sweep the branch mostly stays the same for every set: then no selection is made at all
    if first.all():
        return a, b
    if not first.any():
        return b, a
    w = xp.where
    return raw_point(w(first, a.x, b.x), w(first, a.y, b.y)), raw_point(w(first, b.x, a.x), w(first, b.y, a.y))


def choose_among(points: Sequence[Any], rule: Rule, refs: Sequence[Any]) -> Any:
    """Pick one of any number of points (the crossings of a drawn curve) by *rule*; scalar values only."""
    if not points:
        raise ValueError("no points to choose from")
    if len(points) == 1 or rule.name == "only":
        return points[0]
    ranked = [rule_key(rule, refs, p.x, p.y) for p in points]
    key = [k for k, _ in ranked]
    best = min if ranked[0][1] else max
    target = best(key)
    return points[key.index(target)]


def choose_among_sets(xs: Any, ys: Any, found: Any, rule: Rule, refs: Sequence[Any]) -> Any:
    """:func:`choose_among` for every set of a sweep: the row chosen in each column.

    *xs*, *ys* are the candidates, one row per place a point can be, in the
    curve's order; *found* where each set has a point there.  The key is
    choose_among's, and of equal keys the first wins, as there.

    >>> import numpy as np
    >>> xs, ys = np.array([[0.0, 0.0], [2.0, 2.0]]), np.array([[1.0, 1.0], [1.0, 1.0]])
    >>> found = np.array([[True, False], [True, True]])
    >>> choose_among_sets(xs, ys, found, toward(dx=-1.0, dy=0.0), ()).tolist()
    [0, 1]
    """
    import numpy as np

    if rule.name == "only":
        return np.argmax(found, axis=0)  # the first point found
    key, smallest = rule_key(rule, refs, xs, ys)
    if smallest:
        return np.argmin(np.where(found, key, np.inf), axis=0)
    return np.argmax(np.where(found, key, -np.inf), axis=0)
