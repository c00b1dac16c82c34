"""A live given: what the player draws at every value of a continuous given, precomputed by one sweep.

A teacher moves the rod ratio in the player and the whole construction follows.
The page does not construct anything: the protocol is replayed here over a grid
of the given in one numpy pass (``Protocol.replay`` with an array, the same
kernel as ``construct replay``), every grid value is measured as the player
draws it (:class:`Measure`: the scene and the drawing's own mark geometry on
the same fit to the view, without laying out a page -- a test holds the
numbers equal to the page's), and the page interpolates linearly between grid
values.

What is interpolated: every element of the figure that carries an id (the
marks: points, lines, circles, arcs, curves, areas and their hatching), the
figure's view box, and each step's camera view.  The bound holds for the
marks and the view box; the views are the built value's, carried along with
the marks they frame (:class:`Measure`), and blended (they frame, they are
not drawn).  Letters and leader lines belong to the label placer, which
may choose another spot from one value to the next; they move with the point
they name (the offset of the built value kept).

The layer sits above the constructions and the drawing: :mod:`.sweep` chooses the grid (the bound below
0.5 px), :mod:`.measure` reads what the page draws at a value without laying the page out, :mod:`.wire`
writes what travels to the page; the page's script and the wire format it reads are in
:mod:`construct.render.live` and :mod:`construct.render.wire`.

>>> from construct.constructions import get
>>> live = live_sweep(get("crank"), get("crank").figure(parts=3), "rod_ratio", initial=5)
>>> bool(live.bound < 0.5 and live.grid[0] == 1.05 and live.grid[-1] == 1000.0)
True
"""

from __future__ import annotations

from .measure import Measure, player_page, player_page_and_fit
from .sweep import LiveGiven, LiveSweep, live_givens, live_sweep
from .wire import live_data, live_pages

__all__ = ["LiveGiven", "LiveSweep", "Measure", "live_givens", "live_sweep", "live_data", "live_pages", "player_page",
           "player_page_and_fit"]
