"""construct list: the available constructions."""

from __future__ import annotations

from ...constructions import get, names

NAME = "list"
HELP = "list the available constructions"


def add_arguments(p) -> None:
    pass


def run(args) -> int:
    for name in names():
        c = get(name)
        defaults = ", ".join(f"{k}={v}" for k, v in c.defaults.items())
        print(f"{name:16s} {c.title.en} — {c.title.de} [{c.source}] ({defaults})")
    return 0
