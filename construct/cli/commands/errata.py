"""``construct errata``: every printed number of the books' tables and worked examples beside its true value.

Text output is an aligned table, one line per printed number or formula, and
a summary of the counts per class (``agrees``, ``slip``, ``follows``, and for what is
wrong the cause: ``typesetting``, ``arithmetic``, ``drawing``, ``ambiguous``,
``unexplained``; ``--classes`` prints what each means and the rules they follow); ``--format json`` prints the list of
records (``true`` to 8 significant digits, ``units`` to 2 decimals);
``--class`` keeps one class only, ``--book NAME`` one book (anhang-ii, handbook, mechanics,
baumann; ``--seed NNN``, the number of its text, is the old name of the option).  Each book's rows
come under its citation (author, title, year).

>>> from construct.cli import main
>>> main(["errata", "--class", "slip", "--book", "anhang-ii"])  # doctest: +ELLIPSIS
Anhang II, „Darstellung der Massendrücke“
<BLANKLINE>
table ...
Tabelle 1 ... 0.1666 ... slip ... truncated instead of rounded
...
10 printed numbers: 0 agrees, 10 slip, 0 follows, 0 typesetting, 0 arithmetic, 0 drawing, 0 ambiguous, 0 unexplained; 0 wrong formulas
0
"""

from __future__ import annotations

import argparse
import json
from collections import Counter

from ...books.errata import CLASS_MEANINGS, CLASSES, RULES, Erratum, errata_of
from ...constructions.phrases import BOOKS
from ...render.notation import signed
from ..common import add_format_option

NAME = "errata"
HELP = ("List every printed number of the books' tables and worked examples with its true value and a verdict "
        "(agrees, slip, follows, or the cause: typesetting, arithmetic, drawing, ambiguous, unexplained).")

_HEADINGS = ("table", "row", "column", "printed", "true", "units", "class", "note")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_format_option(parser)
    parser.add_argument(
        "--class", dest="class_", choices=CLASSES, default=None, help="show only the entries of this class"
    )
    parser.add_argument("--book", default=None, metavar="NAME",
                        help=f"show only one book's entries ({', '.join(BOOKS)}; default: all)")
    # the old name: the number of the book's text file (000 ... 004), kept for scripts that use it
    parser.add_argument("--seed", dest="book", metavar="NNN", help=argparse.SUPPRESS)
    parser.add_argument("--classes", action="store_true",
                        help="print what each class means and the rules of the verdicts, and stop")


def run(args: argparse.Namespace) -> int:
    if args.classes:
        width = max(map(len, CLASS_MEANINGS))
        print("\n".join(f"{name.ljust(width)}  {text}" for name, text in CLASS_MEANINGS.items()))
        print("\nRules:")
        print("\n".join(f"- {rule}" for rule in RULES))
        return 0
    entries = [e for e in errata_of("all" if args.book is None else args.book) if args.class_ is None or e.class_ == args.class_]
    if args.format == "json":
        print(json.dumps([_json_record(e) for e in entries], ensure_ascii=True, indent=1))
    else:
        print(_text_table(entries))
    return 0


def _json_record(e: Erratum) -> dict[str, object]:
    record = e.as_dict()
    if isinstance(e.true, float):
        record["true"] = float(f"{e.true:.8g}") + 0.0  # + 0.0 turns -0.0 into 0.0
    if e.units is not None:
        record["units"] = round(e.units, 2) + 0.0
    return record


def _format_true(e: Erratum) -> str:
    # cos 90° computes to 6e-17: a value below the last place of any printed number is 0
    return e.true if isinstance(e.true, str) else f"{e.true:.8g}" if abs(e.true) >= 1e-12 else "0"


def _text_table(entries: list[Erratum]) -> str:
    """Each book's rows under its citation (the books' own order), then the counts of them all."""
    lines: list[str] = []
    for name in dict.fromkeys(e.source for e in entries):
        if lines:
            lines.append("")
        lines += [BOOKS[name].cited() if name in BOOKS else name, ""]
        lines += _book_table([e for e in entries if e.source == name])
    lines.append(_summary(entries))
    return "\n".join(lines)


def _book_table(entries: list[Erratum]) -> list[str]:
    numbers = [e for e in entries if e.table != "formula"]
    formulas = [e for e in entries if e.table == "formula"]
    lines = []
    if numbers:
        rows = [
            (e.table, e.row, e.column, e.printed, _format_true(e), signed(e.units or 0.0), e.class_, e.note)
            for e in numbers
        ]
        widths = [max([len(h)] + [len(r[i]) for r in rows]) for i, h in enumerate(_HEADINGS[:-1])]
        lines.append(_line(_HEADINGS, widths))
        lines += [_line(r, widths) for r in rows]
    if formulas:
        # Whole formulas would stretch every column of the table: one block each instead.
        if lines:
            lines.append("")
        lines.append("wrong formulas")
        for e in formulas:
            lines += [f"  {e.row} ({e.column}): {e.class_}", f"    printed: {e.printed}", f"    true:    {e.true}", f"    note:    {e.note}"]
    return lines


def _line(cells: tuple[str, ...], widths: list[int]) -> str:
    padded = [cell.ljust(w) if i != 5 else cell.rjust(w) for i, (cell, w) in enumerate(zip(cells, widths))]
    return "  ".join(padded + [cells[-1]]).rstrip()


def _summary(entries: list[Erratum]) -> str:
    numbers = Counter(e.class_ for e in entries if e.table != "formula")
    formulas = sum(1 for e in entries if e.table == "formula")
    counts = ", ".join(f"{numbers[c]} {c}" for c in CLASSES)
    return f"{sum(numbers.values())} printed numbers: {counts}; {formulas} wrong formulas"
