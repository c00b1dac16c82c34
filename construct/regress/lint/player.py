"""What a drawing tells the player beside its marks: the camera's view of each step, the letters each zoom level
(or the end state) moves, the player page's own data.

Lint reads these to show each view as the player shows it (:mod:`.views`); :func:`read_views` is the one place
that knows where the camera is stored.

>>> read_moves(".fin #a-lb>.lb{transform:scale(var(--ls)) translate(3px,-1px)}")
{(-1, 'a-lb'): (3.0, -1.0)}
"""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
from pathlib import Path

from .outlines import four_numbers, local_name

__all__ = ["read_views", "read_moves", "player_data", "END", "END_LEVEL"]

#: The class of a figure's root (or camera group) that shows its end state: the player's last step.
END = "fin"
#: The key of the end state's letter moves in :attr:`construct.regress.lint.sheet.Sheet.moves` (in place of a
#: zoom level).
END_LEVEL = -1


def read_views(root: ET.Element, data: dict | None) -> dict[int, tuple[float, float, float, float]]:
    """The camera's view of every step that has one: {step: (x, y, w, h)} in the drawing's user units.

    Read from the output, in this order: the ``views`` layer (``<g id="views">`` holding
    ``<g class="step" data-step="k"><rect class="view" x y width height/></g>`` at each step
    where the view changes; it holds until the next change), a ``data-view="x y w h"`` on an
    element of step k, then the player's data (``views``: a list of boxes, each step's ``v``
    an index into it, or ``v`` the box itself).  A step without a view is shown whole (the
    drawing's viewBox).  This is the one place that knows where the camera is stored.

    >>> svg = '<svg xmlns="http://www.w3.org/2000/svg"><g id="views"><g class="step" data-step="1">' \\
    ...       '<rect class="view" x="0" y="0" width="100" height="50"/></g><g class="step" data-step="3">' \\
    ...       '<rect class="view" x="10" y="5" width="20" height="10"/></g></g>' \\
    ...       '<g class="step" data-step="4"/></svg>'
    >>> read_views(ET.fromstring(svg), None)
    {1: (0.0, 0.0, 100.0, 50.0), 2: (0.0, 0.0, 100.0, 50.0), 3: (10.0, 5.0, 20.0, 10.0), 4: (10.0, 5.0, 20.0, 10.0)}
    """
    views: dict[int, tuple[float, float, float, float]] = {}
    changes: dict[int, tuple[float, float, float, float]] = {}
    last = 0
    for e in root.iter():
        step = e.get("data-step")
        if step is not None and step.strip().isdigit():
            last = max(last, int(step))
        if local_name(e.tag) == "g" and e.get("id") == "views":
            for g in e:
                k = g.get("data-step")
                if k is None or not k.strip().isdigit():
                    continue
                for r in g:
                    if local_name(r.tag) == "rect" and "view" in r.get("class", "").split():
                        box = four_numbers(" ".join(r.get(a, "") for a in ("x", "y", "width", "height")))
                        if box is not None:
                            changes[int(k)] = box
    if changes:
        keys = sorted(changes)
        for i, k in enumerate(keys):
            for j in range(k, (keys[i + 1] if i + 1 < len(keys) else last + 1)):
                views[j] = changes[k]
    for e in root.iter():
        raw, step = e.get("data-view"), e.get("data-step")
        if raw is None or step is None:
            continue
        box = four_numbers(raw)
        if box is not None and step.strip().isdigit():
            views.setdefault(int(step), box)
    if data:
        table = data.get("views") if isinstance(data.get("views"), list) else None
        for k, st in enumerate(data.get("steps") or (), start=1):
            v = st.get("v") if isinstance(st, dict) else None
            if isinstance(v, int) and table is not None and 0 <= v < len(table):
                v = table[v]
            box = four_numbers(" ".join(map(str, v))) if isinstance(v, (list, tuple)) else None
            if box is not None:
                views.setdefault(k, box)
    return views


_MOVE = re.compile(r"translate\(\s*([-+\d.eE]+)(?:px)?\s*[, ]\s*([-+\d.eE]+)(?:px)?\s*\)")


def read_moves(css: str, leaders: set | None = None) -> dict[tuple[int, str], tuple[float, float]]:
    """The letters a zoom level (or the end state, ``.fin``: key :data:`END_LEVEL`) moves:
    ``.zlN #id>.lb{transform:scale(..) translate(dx, dy)}`` rules (earlier drawings wrote ``#id>*`` or moved
    the leader too, ``#id>.leader``: those (level, id) are added to *leaders*).

    >>> read_moves(".zl1 #a-lb>.lb,.zl1 #a-lb>.leader,.zl3 #a-lb>.lb{transform:scale(var(--ls,var(--zs))) "
    ...            "translate(-9.4px,2px)}")
    {(1, 'a-lb'): (-9.4, 2.0), (3, 'a-lb'): (-9.4, 2.0)}
    >>> read_moves(".zl2 #b-lb>*{transform:scale(var(--ls,var(--zs))) translate(1px,0px)}")
    {(2, 'b-lb'): (1.0, 0.0)}
    """
    out: dict[tuple[int, str], tuple[float, float]] = {}
    for block in re.finditer(r"([^{}]+)\{([^{}]*)\}", re.sub(r"/\*.*?\*/", "", css, flags=re.S)):
        m = _MOVE.search(block.group(2))
        if not m or "transform" not in block.group(2):
            continue
        for sel in block.group(1).split(","):
            t = re.fullmatch(r"\s*\.(zl\d+|fin)\s+#([\w-]+)\s*>\s*(\*|\.lb|\.leader)\s*", sel)
            if t:
                lvl = END_LEVEL if t.group(1) == END else int(t.group(1)[2:])
                out[(lvl, t.group(2))] = (float(m.group(1)), float(m.group(2)))
                if leaders is not None and t.group(3) != ".lb":
                    leaders.add((lvl, t.group(2)))
    return out


def player_data(path: Path) -> dict | None:
    """The JSON data of a ``player.html`` (steps, their inputs and views), or None when there is none."""
    try:
        if not path.is_file():
            return None
        page = path.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return None
    m = re.search(r'<script type="application/json" id="data">(.*?)</script>', page, re.S)
    if not m:
        return None
    try:
        data = json.loads(m.group(1))
    except ValueError:
        return None
    return data if isinstance(data, dict) else None
