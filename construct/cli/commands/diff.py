"""``construct diff A B``: what changed between two drawings or two protocols, in geometry.

Two SVG files are compared with :func:`construct.regress.svgdiff.diff_svg`, two
``protocol.json`` files with :func:`construct.regress.protocoldiff.diff_protocol`,
two TikZ pictures or two PDFs of a plate by named point
(:mod:`construct.regress.printdiff`); which one is decided by the content (an
XML document, a JSON object, a PDF, TeX), and both files must be of the same kind.  Exit 0 when equal, 1 when different,
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
HELP = ("compare two SVG drawings, two protocol.json files, or two TikZ or PDF plates by named point, geometrically "
        "(exit 0 equal, 1 different)")


class DiffInputError(ConstructError, ValueError):
    """A file given to ``construct diff`` is missing, unreadable or neither SVG nor a JSON protocol."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("a", metavar="A", help="the reference: an .svg drawing, a protocol.json, a .tikz or a .pdf")
    parser.add_argument("b", metavar="B", help="the file compared with it (the same kind as A)")
    parser.add_argument("--tolerance", type=float, default=None, metavar="T",
                        help="differences at or below T are equal (default 1e-6 for SVG, 1e-9 for protocols, "
                             "0.001 mm for TikZ and PDF)")
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
    from ...regress import printdiff

    with open_regular_file(path, limit=max(MAX_DRAWING_BYTES, MAX_PROTOCOL_BYTES), what="file",
                           error=DiffInputError) as (fd, size):
        try:
            head = os.read(fd, 4096).lstrip(b"\xef\xbb\xbf \t\r\n")[:8]
        except OSError as exc:
            raise DiffInputError(f"cannot read {path!r}: {exc.strerror or exc}") from None
    kind = "svg" if head[:1] == b"<" else "protocol" if head[:1] == b"{" else printdiff.file_kind(head)
    if kind is None:
        raise DiffInputError(f"{path!r} is neither an SVG drawing, a JSON protocol, a TikZ picture nor a PDF")
    if kind in ("tikz", "pdf"):
        return kind
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
    from ...regress.printdiff import diff_pdf, diff_tikz

    differ = {"svg": diff_svg, "protocol": diff_protocol, "tikz": diff_tikz, "pdf": diff_pdf}[kind_a]
    result = differ(Path(args.a), Path(args.b), **tol)  # paths, so that errors name the file
    if args.format == "json":
        print(json.dumps(result.as_dict(), indent=2, ensure_ascii=True))
    else:
        print(result.report())
    return 0 if result.equal else 1
