"""Set-ups the test files share: built once per session, never changed by a test.

* ``rod_ratio_sweep(name, ratios)``: a registered construction, its default
  figure and the replay of that figure over *ratios* (a sweep), cached per
  construction and ratios -- the 1,000-ratio sweeps are the most expensive
  objects of the suite, and three tests read each.
* ``cli(*argv)``: ``construct``'s command line run in this process; the exit
  code and what it printed on stdout and stderr.
* ``small_plan``: ``construct gallery`` builds one small figure without a live
  player's sweep, for the tests about the gallery's folder (tests/test_gallery.py
  has its own, with the sweep).
"""

from __future__ import annotations

import os
import shutil
from pathlib import Path
from typing import Any, Callable, NamedTuple

import numpy as np
import pytest


class Run(NamedTuple):
    """One run of the command line: exit code, stdout, stderr."""

    code: int
    out: str
    err: str


@pytest.fixture
def small_plan(monkeypatch):
    """A gallery of one small figure without a live player's sweep: a build takes a moment."""
    import construct.gallery as gallery

    monkeypatch.setattr(gallery, "gallery_plan", lambda: [("crank", {"parts": 3, "rod_ratio": 4.0})])
    monkeypatch.setattr(gallery, "LIVE_PLAYERS", ())


@pytest.fixture
def cli(capsys) -> Callable[..., Run]:
    """Run ``construct ARGV...`` in-process (``construct.cli.main``) and return (code, out, err)."""
    # from the module, not the package: collecting construct/cli/main.py's doctests re-imports the module
    # and rebinds the package attribute ``construct.cli.main`` to it, so ``from construct.cli import main``
    # may then give the module instead of the function
    from construct.cli.main import main

    def run(*argv: Any) -> Run:
        capsys.readouterr()  # what the test printed before is not the command's
        try:
            code = main([str(a) for a in argv])
        except SystemExit as exc:  # --help and argparse's own errors exit, as they do in a process
            code = exc.code
        out, err = capsys.readouterr()
        return Run(code, out, err)

    return run


@pytest.fixture(scope="session")
def rod_ratio_sweep() -> Callable[[str, Any], tuple[Any, Any, Any]]:
    """(construction, default figure, sweep replay over the ratios), made once per session for each pair."""
    from construct import get

    made: dict[tuple[str, bytes], tuple[Any, Any, Any]] = {}

    def sweep(name: str, ratios: Any) -> tuple[Any, Any, Any]:
        ratios = np.asarray(ratios, dtype=float)
        key = (name, ratios.tobytes())
        if key not in made:
            c = get(name)
            fig = c.figure()
            made[key] = (c, fig, fig.protocol.replay(c.rod_ratio_sweep(dict(fig.replay.givens), ratios)))
        return made[key]

    return sweep


# -- headless Chromium, for the player, the live player and the gallery site ---------------------------------

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync"]


def _browser_unavailable(reason: str):
    if os.environ.get("CI"):
        pytest.fail(f"browser test cannot run in CI: {reason}")
    pytest.skip(reason)


@pytest.fixture(scope="session")
def browser():
    """Debian's chromium driven by Playwright (.ci/install-browser.sh); skipped without them, except in CI."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        _browser_unavailable("playwright is not installed (.ci/install-browser.sh)")
    if not Path(CHROMIUM).exists():
        _browser_unavailable("chromium is not installed (.ci/install-browser.sh)")
    with sync_playwright() as pw:
        b = pw.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield b
        b.close()
