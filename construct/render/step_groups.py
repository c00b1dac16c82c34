"""The layered figure's step groups: every step's elements of a layer in ``<g class="step" data-step="k">``, and
the state each group has in frame k.

A frame is a view of the layered figure (:class:`construct.render.svg.Drawing`): the groups of steps 1..k,
the current one ``cur``, those that made what it is set on ``inp`` (in the input colour), a finished group's
helpers ``done`` (faint) and the rest ``old``; the whole figure (no step marked) shows only the finished
groups' helpers faint.  :class:`StepGroups` is the part of the Drawing that makes the groups and their states
(its base class, as :class:`~construct.kernel.composite.CompositeSteps` is the Builder's); it asks only for
the drawing's scene, style, SVG writer and the elements of each step by layer.

>>> from construct.constructions import get
>>> from construct.render.scene import build_scene
>>> from construct.render.styles import TEACHING
>>> from construct.render.svg import Drawing
>>> d = Drawing(build_scene(get("crank").figure(parts=6)), TEACHING)
>>> inputs = d.input_steps(8)  # step 8: a circle about the dead centre 0 (step 6) onto the crank circle (5) about O (1)
>>> [d.step_class(s, 8, mark_steps=True, inputs=inputs) for s in (8, 6, 4, 2)]
['cur', 'inp', 'done', 'old']
>>> d.layer("points", 2, mark_steps=True).attribs["id"], [s for s, _ in d.step_runs("points", 8)]
('points', [1, 6, 7])
"""

from __future__ import annotations

import bisect
from typing import Any, Sequence

from . import svgdoc
from .scene import Scene
from .styles import Style

__all__ = ["StepGroups", "is_view"]


class StepGroups:
    """The step groups of a :class:`~construct.render.svg.Drawing` and their states in a frame (its base class)."""

    scene: Scene
    style: Style
    doc: svgdoc.Writer
    #: layer -> [(step, [element, ...]), ...] in step order: each step's elements of that layer
    groups: dict[str, list[tuple[int, list[Any]]]]
    #: layer -> the steps of its groups, in order (for bisecting at a frame)
    group_steps: dict[str, list[int]]

    def step_group(self, k: int, elems: Sequence[Any], cls: str = "", **attrs: Any) -> Any:
        """Step k's elements of one layer: ``<g class="step ..." data-step="k">``.

        With fading (``Style.done_opacity``) a step whose helpers fade carries ``data-fade``:
        the last step of its group, after which the player and animation fade it too.
        """
        if self.style.done_opacity < 1.0 and not (elems and is_view(elems[0])):
            end = self.scene.fade_end(k)
            if end is not None:
                attrs = {**attrs, "data-fade": str(end)}
        g = self.doc.factory.g(class_=f"step {cls}".rstrip(), **{"data-step": str(k)}, **attrs)
        for e in elems:
            g.add(e)
        return g

    def step_runs(self, name: str, k: int) -> list[tuple[int, list[Any]]]:
        """Layer *name*'s (step, elements) for steps 1..k."""
        return self.groups[name][:bisect.bisect_right(self.group_steps[name], k)]

    def input_steps(self, k: int) -> frozenset[int]:
        """The steps that made what step k's instrument is set on, what its caption names, what its arc is
        struck onto and the rectangle its ray is the diagonal of (:class:`construct.render.step_inputs.StepInputs`)."""
        if not self.style.input_colour:
            return frozenset()
        done = self.__dict__.setdefault("_input_steps", {})  # asked by the tags' placing and by the player
        got = done.get(k)
        if got is None:
            sc = self.scene
            # and the lines its arc is struck onto (cut by the next step): drawn while it strikes it
            got = done[k] = frozenset(s for s in (sc.step_of(n) for n in sc.inputs(k) | sc.tagged(k)
                                                  | sc.struck_onto(k) | sc.aimed_at(k))
                                      if s is not None and s < k)
        return got

    def step_class(self, s: int, k: int, *, mark_steps: bool, inputs: frozenset[int] = frozenset(),
                   layer: str = "") -> str:
        """The class of step s's groups in frame k: cur, old (with inp), done (a finished group's helpers)."""
        if layer == "views":
            return ""  # the camera's boxes are data, never drawn
        fade = self.style.done_opacity < 1.0
        if not mark_steps:
            # the whole figure: every group finished, its helpers faint (teaching)
            return "done" if fade and self.scene.faded(s, len(self.scene.steps) + 1) else ""
        if s == k:
            return "cur"
        if s in inputs:
            return "inp"  # at full strength, in the input colour
        if fade and self.scene.faded(s, k):
            return "done"
        return "old" if self.style.earlier_opacity < 1.0 else ""

    def plain_groups(self, name: str) -> list[Any]:
        """Layer *name*'s step groups as the whole figure shows them (``class="step"``, ``"step done"``
        for a finished group's helpers), made once: the layered figure and the player carry the same ones."""
        cache = self.__dict__.setdefault("_plain_groups", {})
        if name not in cache:
            cache[name] = [self.doc.frozen(self.step_group(k, elems, self.step_class(k, 0, mark_steps=False, layer=name)))
                           for k, elems in self.groups[name]]
        return cache[name]

    def layer(self, name: str, k: int, *, mark_steps: bool) -> Any:
        """``<g id="name">`` with the step groups of steps 1..k; ``cur``/``old``/``done``/``inp`` when *mark_steps*."""
        inputs = self.input_steps(k) if mark_steps else frozenset()
        g = self.doc.factory.g(id=name)
        if not mark_steps:
            for group in self.plain_groups(name)[:bisect.bisect_right(self.group_steps[name], k)]:
                g.add(group)
            return g
        for s, elems in self.step_runs(name, k):
            g.add(self.step_group(s, elems, self.step_class(s, k, mark_steps=mark_steps, inputs=inputs, layer=name)))
        return g


def is_view(elem: Any) -> bool:
    """Is *elem* a camera box of the ``views`` layer (frozen or not)?"""
    return getattr(getattr(elem, "source", elem), "attribs", {}).get("class") == "view"
