"""``construct samples FOLDER``: the sample indicator cards the README's examples read, written into FOLDER."""

from __future__ import annotations

from ...io.samples import SAMPLES, write_samples

NAME = "samples"
HELP = ("write the sample indicator cards (" + ", ".join(SAMPLES) + ") into a folder, as the README's examples "
        "read them: construct samples examples")


def add_arguments(p) -> None:
    p.add_argument("folder", metavar="FOLDER",
                   help="where to write them (made when missing); a file there of a sample's name that differs "
                        "from it is never overwritten: the command is refused and writes nothing")


def run(args) -> int:
    written = write_samples(args.folder)
    width = max(map(len, SAMPLES))
    if not written:
        print(f"{args.folder} already holds the sample cards, unchanged")
    else:
        print(f"wrote {len(written)} sample card{'s' if len(written) > 1 else ''} to {args.folder}:")
    for name, what in SAMPLES.items():
        print(f"  {name:<{width}}  {what}{'' if name in written else '  (already there)' if written else ''}")
    first = f"{args.folder.rstrip('/')}/card.csv"
    print(f"try: construct check indicator-diagram --indicator {first}")
    return 0
