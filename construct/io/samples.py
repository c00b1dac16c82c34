"""The sample indicator cards the package ships (``construct/data/cards/``), written into a folder a user names.

The README's examples read them as ``examples/card.csv`` and so on; ``construct samples examples`` puts them
there.  Writing is all or nothing (:func:`~construct.io.staging.staged_output`), and a file of the same name
that differs from the sample -- a card of the user's -- is never overwritten: the whole run is refused first.

>>> import tempfile, pathlib
>>> folder = pathlib.Path(tempfile.mkdtemp()) / "examples"
>>> write_samples(folder)
['card.csv', 'crank.csv', 'hp.csv', 'lp.csv', 'karte.csv']
>>> write_samples(folder)          # already there, the same bytes: nothing to write
[]
>>> _ = (folder / "hp.csv").write_text("x,p\\n")
>>> write_samples(folder)
Traceback (most recent call last):
construct.kernel.errors.OutputError: refusing to overwrite hp.csv in '...examples': it differs from the sample card of that name; name another folder, or move it away
"""

from __future__ import annotations

import os
import stat
from importlib import resources

from ..kernel.errors import OutputError
from .staging import output_path, staged_output

__all__ = ["SAMPLES", "sample_cards", "write_samples"]

#: The sample cards, in the order the README introduces them, with what each is.
SAMPLES = {
    "card.csv": "a digitised card, x,p (one cylinder side, head end)",
    "crank.csv": "the same cylinder's crank side",
    "hp.csv": "a compound engine's high-pressure cylinder",
    "lp.csv": "its low-pressure cylinder",
    "karte.csv": "card.csv as a German spreadsheet writes it: x;p, decimal commas, a byte-order mark, CRLF",
}


def sample_cards() -> dict[str, bytes]:
    """The sample cards' bytes by file name, read from the installed package (a wheel holds them as package data).

    >>> sample_cards()["card.csv"].splitlines()[0]
    b'x,p'
    """
    folder = resources.files("construct").joinpath("data", "cards")
    return {name: folder.joinpath(name).read_bytes() for name in SAMPLES}


def write_samples(target: str | os.PathLike[str]) -> list[str]:
    """Write the sample cards into the folder *target* (made, with its parents, when missing); the names written.

    A card already there with the same bytes is left as it is; one that differs, or anything that is not a
    regular file under a sample's name, refuses the whole run before anything is written (OutputError naming
    them).  A folder that cannot be made or written is an OutputError too, and leaves nothing behind.
    """
    folder = output_path(target, "samples folder")
    cards = sample_cards()
    differing, missing = [], []
    for name, data in cards.items():
        path = folder / name
        try:
            st = path.lstat()
        except FileNotFoundError:
            missing.append(name)
            continue
        except NotADirectoryError:   # the folder itself is a file: staged_output says so
            missing.append(name)
            continue
        except OSError as exc:
            raise OutputError(f"cannot read {str(path)!r}: {exc.strerror or exc}") from None
        try:
            same = stat.S_ISREG(st.st_mode) and path.read_bytes() == data
        except OSError:
            same = False
        if not same:
            differing.append(name)
    if differing:
        many = len(differing) > 1
        raise OutputError(f"refusing to overwrite {', '.join(differing)} in {str(folder)!r}: "
                          f"{'they differ from the sample cards' if many else 'it differs from the sample card'} "
                          f"of {'those names' if many else 'that name'}; name another folder, or move "
                          f"{'them' if many else 'it'} away")
    if not missing:
        return []
    with staged_output(folder, what="samples folder") as stage:
        for name in missing:
            (stage / name).write_bytes(cards[name])
    return missing
