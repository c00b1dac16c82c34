"""construct list: the available constructions, as an aligned table of name and title (or JSON with the details)."""

from __future__ import annotations

import json

from ...constructions import get, names
from ...kernel.protocol import jsonable
from ...render.notation import citation
from ..common import add_format_option

NAME = "list"
HELP = "list the available constructions: name and title (--format json: source and parameters too)"


def add_arguments(p) -> None:
    add_format_option(p)


def run(args) -> int:
    found = [get(name) for name in names()]
    if args.format == "json":
        # the source as a reader cites it (author, title, figure) and the books by the names --book takes
        print(json.dumps([{"name": c.name, "title": {"en": c.title.en, "de": c.title.de},
                           "source": citation(c, "en", after=False) or c.source,
                           "books": [cite.book.key for cite in c.cites],
                           "parameters": jsonable(dict(c.defaults))} for c in found], indent=1, ensure_ascii=False))
        return 0
    width = max(len(c.name) for c in found)
    for c in found:
        print(f"{c.name:<{width}}  {c.title.en}")
    return 0
