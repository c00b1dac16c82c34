"""The ``construct`` command line.

Each subcommand lives in its own module under :mod:`construct.cli.commands`
(``NAME``, ``HELP``, ``add_arguments(parser)``, ``run(args) -> int``), so the
parser here stays a thin dispatcher.  Every failure the library raises on
purpose becomes one line on stderr and exit code 2; nothing is half-written
because writers go through :mod:`construct.io.staging`.
"""

from __future__ import annotations

import argparse
import contextlib
import signal
import sys
import threading
from typing import Sequence

from ..kernel.errors import ConstructError

EXIT_OK, EXIT_BAD_INPUT = 0, 2  # a failed check exits 1: the commands that check return it


class UsageError(ConstructError):
    """The command line itself is wrong (unknown option, missing value)."""


class _Parser(argparse.ArgumentParser):
    """argparse that raises instead of printing usage and exiting."""

    def error(self, message: str) -> None:  # type: ignore[override]
        # "construct check: ..." would read "construct: error: construct check: ..." once printed
        where = self.prog.removeprefix("construct").strip()
        raise UsageError(f"{where}: {message}" if where else message)


def build_parser() -> argparse.ArgumentParser:
    from . import commands

    from ..kernel import version

    parser = _Parser(prog="construct", description=__doc__.splitlines()[0])
    parser.add_argument("--version", action="version", version=f"construct {version()}",
                        help="print the version and exit")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for module in commands.MODULES:
        p = sub.add_parser(module.NAME, help=module.HELP, description=module.HELP)
        module.add_arguments(p)
        p.set_defaults(_run=module.run)
    return parser


class Terminated(BaseException):
    """SIGTERM arrived: unwinds like Ctrl-C, so that staging folders are removed on the way out."""


def _terminate(signum: int, frame: object) -> None:
    raise Terminated(signum)


@contextlib.contextmanager
def _terminate_cleanly():
    """For the command's duration only, SIGTERM raises Terminated (by default it would kill the process
    with its staging folders still there); the previous handler is restored after."""
    if threading.current_thread() is not threading.main_thread():
        yield  # handlers can only be set from the main thread; there the default stays
        return
    previous = signal.signal(signal.SIGTERM, _terminate)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


def _negative_values_attached(parser: argparse.ArgumentParser, argv: Sequence[str]) -> list[str]:
    """'--rod-ratio -inf' as '--rod-ratio=-inf': argparse takes a token like -inf or -1e-3 for an option.

    Its own test for negative numbers knows only -5 and -.5, so '--radius -1e-3' would report "expected one
    argument" instead of the real complaint (the radius must be positive).  Only options that take a value
    are joined to a following token that reads as a float (float() reads -inf, nan and 1e-3).

    >>> _negative_values_attached(build_parser(), ["check", "crank", "--rod-ratio", "-inf", "--infinite-rod"])
    ['check', 'crank', '--rod-ratio=-inf', '--infinite-rod']
    """
    from .common import is_number

    subparsers = next((a for a in parser._actions if isinstance(a, argparse._SubParsersAction)), None)
    sub = subparsers.choices.get(argv[0]) if subparsers is not None and argv else None
    if sub is None:
        return list(argv)
    takes_value = {opt for action in sub._actions if action.option_strings and action.nargs != 0
                   for opt in action.option_strings}
    out: list[str] = []
    i = 0
    while i < len(argv):
        token = argv[i]
        if (token in takes_value and i + 1 < len(argv) and argv[i + 1].startswith("-")
                and is_number(argv[i + 1])):
            out.append(f"{token}={argv[i + 1]}")
            i += 2
            continue
        if token == "--":  # everything after it is positional already
            out.extend(argv[i:])
            break
        out.append(token)
        i += 1
    return out


def _one_line(message: str, limit: int = 2000) -> str:
    """The error as the one line the CLI promises: a name or caption read from a file may hold line breaks,
    and a value quoted from it may be megabytes long.

    >>> _one_line("a\\nb  c")
    'a b c'
    """
    text = " ".join(message.split())
    return text if len(text) <= limit else text[:limit - 1] + "…"


def main(argv: Sequence[str] | None = None) -> int:
    try:
        parser = build_parser()
        try:
            args = parser.parse_args(_negative_values_attached(parser, sys.argv[1:] if argv is None else list(argv)))
        except SystemExit as exc:  # --help and --version print and exit 0: a return code, as for every command
            return int(exc.code or 0)
        with _terminate_cleanly():
            return int(args._run(args))
    except ConstructError as exc:
        print(f"construct: error: {_one_line(str(exc))}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except KeyboardInterrupt:
        print("construct: interrupted", file=sys.stderr)
        return 130
    except Terminated:
        print("construct: terminated", file=sys.stderr)
        return 128 + signal.SIGTERM
    except BrokenPipeError:
        return EXIT_OK


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
