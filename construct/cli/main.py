"""The ``construct`` command line.

Each subcommand lives in its own module under :mod:`construct.cli.commands`
(``NAME``, ``HELP``, ``add_arguments(parser)``, ``run(args) -> int``), so the
parser here stays a thin dispatcher.  Every failure the library raises on
purpose becomes one line on stderr and exit code 2; nothing is half-written
because writers go through :mod:`construct.io.staging`.
"""

from __future__ import annotations

import argparse
import codecs
import contextlib
import os
import signal
import sys
import threading
import warnings
from typing import Sequence

from ..io.collector import few_collections
from ..kernel.errors import ConstructError, ConstructWarning, did_you_mean

EXIT_OK, EXIT_BAD_INPUT = 0, 2  # a failed check exits 1: the commands that check return it


class UsageError(ConstructError):
    """The command line itself is wrong (unknown option, missing value)."""


class _Parser(argparse.ArgumentParser):
    """argparse that raises instead of printing usage and exiting."""

    def error(self, message: str) -> None:  # type: ignore[override]
        # "construct check: ..." would read "construct: error: construct check: ..." once printed
        where = self.prog.removeprefix("construct").strip()
        raise UsageError(f"{where}: {message}" if where else message)

    def _check_value(self, action: argparse.Action, value: object) -> None:
        # a misspelt command or choice names the nearest one ('chek' -> 'check')
        if action.choices is not None and value not in action.choices:
            choices = ", ".join(map(repr, action.choices))
            raise argparse.ArgumentError(action, f"invalid choice: {value!r}{did_you_mean(value, action.choices)} "
                                                 f"(choose from {choices})")
        super()._check_value(action, value)


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


def _nearest_option(parser: argparse.ArgumentParser, argv: Sequence[str], message: str) -> str:
    """For "unrecognized arguments: --rod-ration", the subcommand's option nearest the first one
    (" (did you mean '--rod-ratio'?)"); nothing for other errors.

    >>> _nearest_option(build_parser(), ["check", "crank", "--rod-ration", "5"], "unrecognized arguments: --rod-ration 5")
    " (did you mean '--rod-ratio'?)"
    """
    head = "unrecognized arguments: "
    if head not in message:
        return ""
    subparsers = next((a for a in parser._actions if isinstance(a, argparse._SubParsersAction)), None)
    sub = subparsers.choices.get(argv[0]) if subparsers is not None and argv else None
    unknown = message.split(head, 1)[1].split()
    word = next((w.split("=")[0] for w in unknown if w.startswith("--")), None)
    if sub is None or word is None:
        return ""
    return did_you_mean(word, [o for a in sub._actions for o in a.option_strings if o.startswith("--")])


def _one_line(message: str, limit: int = 2000) -> str:
    """The error as the one line the CLI promises: a name or caption read from a file may hold line breaks,
    and a value quoted from it may be megabytes long.

    >>> _one_line("a\\nb  c")
    'a b c'
    """
    text = " ".join(message.split())
    return text if len(text) <= limit else text[:limit - 1] + "…"


#: Plain-text stand-ins for the symbols the tool prints, on a stream that cannot encode them.
_FALLBACK = {
    "ω": "w", "φ": "phi", "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "eps", "κ": "kappa",
    "λ": "lambda", "μ": "mu", "π": "pi", "ρ": "rho", "σ": "sigma", "τ": "tau", "θ": "theta", "Δ": "Delta",
    "′": "'", "″": '"', "‘": "'", "’": "'", "‚": ",", "“": '"', "”": '"', "„": '"', "²": "^2", "³": "^3",
    "°": " deg", "—": "--", "–": "-", "−": "-", "…": "...", "·": "*", "×": "x", "≈": "~", "≤": "<=", "≥": ">=",
    "→": "->", "←": "<-", "√": "sqrt", "∞": "inf", "ä": "ae", "ö": "oe", "ü": "ue", "Ä": "Ae", "Ö": "Oe",
    "Ü": "Ue", "ß": "ss", "✅": "[ok]", "❌": "[FAIL]", "\u00a0": " ",
}
_ERRORS = "construct-terminal"


def _terminal_fallback(exc: UnicodeError) -> tuple[str, int]:
    """What a stream prints for a character its encoding lacks: a plain stand-in (ω -> w, ′ -> '), the letter
    without its accent, or a backslash escape (a lone surrogate, a symbol without a stand-in).

    >>> "ω = 2π, ′ é \\ud800 ✓".encode("ascii", _ERRORS)
    b"w = 2pi, ' e \\\\ud800 \\\\u2713"
    """
    import unicodedata

    if not isinstance(exc, UnicodeEncodeError):
        raise exc
    out = []
    for ch in exc.object[exc.start:exc.end]:
        if ch in _FALLBACK:
            out.append(_FALLBACK[ch])
            continue
        plain = "".join(c for c in unicodedata.normalize("NFKD", ch) if not unicodedata.combining(c))
        if plain and plain.isascii() and plain != ch:
            out.append(plain)
        else:
            out.append(ch.encode("ascii", "backslashreplace").decode("ascii")
                       if not 0xD800 <= ord(ch) <= 0xDFFF else f"\\u{ord(ch):04x}")
    return "".join(out), exc.end


codecs.register_error(_ERRORS, _terminal_fallback)


@contextlib.contextmanager
def _streams_for_the_terminal():
    """stdout and stderr print what they cannot encode as :func:`_terminal_fallback` says, for the command's
    duration (an ASCII or Latin-1 terminal, a lone surrogate in a caption read from a file)."""
    changed = []
    for stream in (sys.stdout, sys.stderr):
        reconfigure = getattr(stream, "reconfigure", None)
        if reconfigure is None or getattr(stream, "errors", None) == _ERRORS:
            continue
        try:
            previous = stream.errors
            reconfigure(errors=_ERRORS)
        except (ValueError, OSError, AttributeError, TypeError):
            continue
        changed.append((stream, previous))
    try:
        yield
    finally:
        for stream, previous in changed:
            try:
                stream.reconfigure(errors=previous)
            except (ValueError, OSError):
                pass


def _write_failed(exc: OSError) -> str:
    """A write to stdout (redirected to a full disk, a file over the size limit) as the CLI's one line; what
    is still buffered goes nowhere, so that the exit does not fail on it a second time."""
    try:
        sys.stdout.flush()
    except (OSError, ValueError):
        try:
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, sys.stdout.fileno())
            os.close(devnull)
        except (OSError, ValueError, AttributeError):
            pass
    where = f" {exc.filename!r}" if getattr(exc, "filename", None) else " the output"
    return f"cannot write{where}: {exc.strerror or exc}"


@contextlib.contextmanager
def _warnings_as_lines():
    """For the command's duration, the library's own warnings (:class:`ConstructWarning`) print as one line
    ``construct: warning: ...``, as its errors do, not as a source line of the library; others as Python prints."""
    previous = warnings.showwarning

    def show(message, category, filename, lineno, file=None, line=None):
        if issubclass(category, ConstructWarning):
            print(f"construct: warning: {_one_line(str(message))}", file=sys.stderr if file is None else file)
        else:
            previous(message, category, filename, lineno, file, line)

    warnings.showwarning = show
    try:
        yield
    finally:
        warnings.showwarning = previous


def main(argv: Sequence[str] | None = None) -> int:
    with _streams_for_the_terminal(), _warnings_as_lines():
        return _main(argv)


def _main(argv: Sequence[str] | None) -> int:
    try:
        parser = build_parser()
        argv = sys.argv[1:] if argv is None else list(argv)
        try:
            args = parser.parse_args(_negative_values_attached(parser, argv))
        except SystemExit as exc:  # --help and --version print and exit 0: a return code, as for every command
            return int(exc.code or 0)
        except UsageError as exc:
            raise UsageError(f"{exc}{_nearest_option(parser, argv, str(exc))}") from None
        with _terminate_cleanly(), few_collections():
            code = int(args._run(args))
            sys.stdout.flush()  # a full disk behind a redirected stdout shows here, not at exit
            return code
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
    except OSError as exc:  # a write the staging helper does not see: stdout, redirected to a file
        print(f"construct: error: {_one_line(_write_failed(exc))}", file=sys.stderr)
        return EXIT_BAD_INPUT


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
