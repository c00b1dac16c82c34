"""What is worked out once for one object, known by its identity: a list of thousands of keys, a protocol.

Hashing such an object at every ask costs more than the ask (a live sweep asks at every cell and every value), and
its value may be unhashable; its identity is free.  An id is another object's once the first is gone, so each
entry keeps its object: while the entry stands, the id is that object's.

>>> made = {}
>>> keys = ["a", "b"]
>>> by_identity(made, keys, len), by_identity(made, keys, lambda k: 0)
(2, 2)
"""

from __future__ import annotations

from typing import Any, Callable, TypeVar

__all__ = ["by_identity"]

T = TypeVar("T")


def by_identity(made: dict[int, tuple[Any, Any]], obj: Any, make: Callable[[Any], T], most: int = 8) -> T:
    """``make(obj)``, made once for *obj* while it is kept in *made* ({id: (object, value)}; at most *most*
    objects kept: a full *made* is emptied before a new one goes in)."""
    got = made.get(id(obj))
    if got is not None and got[0] is obj:
        return got[1]
    value = make(obj)
    if len(made) >= most:
        made.clear()
    made[id(obj)] = (obj, value)
    return value
