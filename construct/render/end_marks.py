"""The end state's marks: the plate's figure on the teaching scene's sheet (:meth:`construct.render.scene.Scene.in_end`).

A teaching sequence ends with the figure as the book draws it.  The plate's scene is drawn on the teaching
scene's broken axis (:func:`construct.render.sheet.break_shift`); each of its marks that the teaching scene
draws otherwise (a line drawn as far as every point the construction marks on it, the crank circle whole, a
look the plate gives) becomes an end mark that replaces it in the end state (:func:`end_state`).  How the end
state is shown is :mod:`construct.render.end_state`.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> sc = build_scene(get("crank").figure(parts=6), ending=True)
>>> sc.ending and all(m.id.endswith("-end") for m in sc.end_marks)
True
>>> sc.end_replaced <= {m.id for m in sc.marks}
True
"""

from __future__ import annotations

import dataclasses
from typing import Any, Sequence

from .marks import Mark, with_geom
from .plate import shifted
from .sheet import break_shift, moved_geom

__all__ = ["end_state"]


def end_state(plate_marks: Sequence[Mark], plate_box: tuple[float, float, float, float], marks: Sequence[Mark],
              breaks: tuple, furniture: tuple) -> dict[str, Any]:
    """The end state's fields of a teaching scene (:class:`construct.render.scene.Scene`: ``ending``,
    ``end_marks``, ``end_replaced``, ``end_furniture``, ``end_looks``): the plate's marks *plate_marks* (in
    the box *plate_box*) and its furniture on the teaching scene's sheet (its *marks*, its *breaks*)."""
    sx, sy = break_shift(breaks), break_shift(breaks, axis=1)
    span = max(plate_box[2] - plate_box[0], plate_box[3] - plate_box[1], 1e-9)
    tol = 1e-9 * span
    teaching: dict[str, list[Mark]] = {}
    for m in marks:
        teaching.setdefault(m.name, []).append(m)
    seen: dict[str, int] = {}
    end_marks, replaced, looks_at = [], set(), {}
    for pm in plate_marks:
        pm = with_geom(pm, moved_geom(pm, sx, sy))
        i = seen.get(pm.name, 0)
        seen[pm.name] = i + 1
        same = teaching.get(pm.name, [])
        tm = same[i] if i < len(same) else None
        if tm is not None and tm.kind is pm.kind and tm.label == pm.label and _same_geom(tm.geom, pm.geom, tol):
            if tm.look != pm.look:  # drawn where it stands, in the plate's look (not drawn twice)
                looks_at[tm.id] = pm.look
            continue
        if tm is not None:
            replaced.add(tm.id)
        end_marks.append(dataclasses.replace(pm, id=f"{(tm or pm).id}-end"))
    return {"ending": True, "end_marks": tuple(end_marks), "end_replaced": frozenset(replaced),
            "end_furniture": tuple(shifted(it, sx) for it in furniture), "end_looks": looks_at}


def _same_geom(a: tuple, b: tuple, tol: float) -> bool:
    if len(a) != len(b):
        return False
    for u, v in zip(a, b):
        if isinstance(u, tuple):
            if not isinstance(v, tuple) or not _same_geom(u, v, tol):
                return False
        elif abs(u - v) > tol * max(1.0, abs(u)):
            return False
    return True
