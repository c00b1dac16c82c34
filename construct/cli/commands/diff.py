"""``construct diff A B``: what changed between two drawings or two protocols, in geometry.

Two SVG files are compared with :func:`construct.regress.svgdiff.diff_svg`, two
``protocol.json`` files with :func:`construct.regress.protocoldiff.diff_protocol`;
which one is decided by the content (an XML document or a JSON object), and
both files must be of the same kind.  Exit 0 when equal, 1 when different,
2 on bad input.
"""

from __future__ import annotations

import argparse
import json
import os
from pathlib import Path

from ...kernel.errors import ConstructError, InvalidParameter
from ..common import add_format_option

NAME = "diff"
HELP = "compare two SVG drawings or two protocol.json files geometrically (exit 0 equal, 1 different)"


class DiffInputError(ConstructError, ValueError):
    """A file given to ``construct diff`` is missing, unreadable or neither SVG nor a JSON protocol."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("a", metavar="A", help="the reference: an .svg drawing or a protocol.json")
    parser.add_argument("b", metavar="B", help="the file compared with it (the same kind as A)")
    parser.add_argument("--tolerance", type=float, default=None, metavar="T",
                        help="differences at or below T are equal (default 1e-6 for SVG, 1e-9 for protocols)")
    add_format_option(parser)


#: The largest drawing ``diff`` reads.  A 3600-part replay's final.svg is a few MB and a million-element
#: drawing about 80 MB; four times that still fits the memory of a small machine.
MAX_DRAWING_BYTES = 320 * 2**20


def file_kind(path: str) -> str:
    """``"svg"`` or ``"protocol"``, by the first character of the content.

    Only a regular file of a bounded size is accepted, and only its first
    bytes are read here: ``/dev/zero`` or a named pipe must not be read until
    memory runs out, nor make the command wait.
    """
    from ...io.reading import open_regular_file
    from ...kernel.protocol_file import MAX_PROTOCOL_BYTES

    with open_regular_file(path, limit=max(MAX_DRAWING_BYTES, MAX_PROTOCOL_BYTES), what="file",
                           error=DiffInputError) as (fd, size):
        try:
            head = os.read(fd, 4096).lstrip(b"\xef\xbb\xbf \t\r\n")[:1]
        except OSError as exc:
            raise DiffInputError(f"cannot read {path!r}: {exc.strerror or exc}") from None
    kind = "svg" if head == b"<" else "protocol" if head == b"{" else None
    if kind is None:
        raise DiffInputError(f"{path!r} is neither an SVG drawing nor a JSON protocol")
    limit = MAX_DRAWING_BYTES if kind == "svg" else MAX_PROTOCOL_BYTES
    if size > limit:
        raise DiffInputError(f"{path!r} is larger than {limit // 2**20} MiB ({size} bytes); "
                             f"no {'drawing' if kind == 'svg' else 'protocol'} this library writes is")
    return kind


def run(args: argparse.Namespace) -> int:
    from ...regress.protocoldiff import diff_protocol
    from ...regress.svgdiff import diff_svg

    kind_a, kind_b = file_kind(args.a), file_kind(args.b)
    if kind_a != kind_b:
        raise DiffInputError(f"cannot compare {args.a!r} ({kind_a}) with {args.b!r} ({kind_b})")
    if args.tolerance is not None and not (args.tolerance >= 0 and args.tolerance != float("inf")):
        raise InvalidParameter(f"--tolerance must be a finite number >= 0, got {args.tolerance!r}")
    tol = {} if args.tolerance is None else {"tolerance": args.tolerance}
    differ = diff_svg if kind_a == "svg" else diff_protocol
    result = differ(Path(args.a), Path(args.b), **tol)  # paths, so that errors name the file
    if args.format == "json":
        print(json.dumps(result.as_dict(), indent=2, ensure_ascii=True))
    else:
        print(result.report())
    return 0 if result.equal else 1
