"""Set-ups the test files share: built once per session, never changed by a test.

* ``rod_ratio_sweep(name, ratios)``: a registered construction, its default
  figure and the replay of that figure over *ratios* (a sweep), cached per
  construction and ratios -- the 1,000-ratio sweeps are the most expensive
  objects of the suite, and three tests read each.
* ``cli(*argv)``: ``construct``'s command line run in this process; the exit
  code and what it printed on stdout and stderr.
* ``cli_process(*argvs, env=..., cwd=...)``: several commands in one fresh
  process (an environment, an encoding or entry points the process starts with).
* ``gallery_figure(name, params)``: a construction and its figure, built once per
  session -- the gallery's 23 figures are read by five test modules.
* ``gallery_drawing(name, params)``: that figure's teaching drawing (its letters placed), made once per
  session -- the largest takes seconds, and three test modules read them.
* ``small_plan``: ``construct gallery`` builds one small figure without a live
  player's sweep, for the tests about the gallery's folder (tests/test_gallery.py
  has its own, with the sweep).

Two things hold for every test without being asked for:

* **It leaves no trace in the process** (``_leaves_the_process_as_it_found_it``):
  mpmath's precision, the signal handlers, the working folder, the environment,
  numpy's error handling, the locale, ``sys.path`` and the file-size limit are
  the same after each test as before the session -- so that the suite passes
  serially, in parallel and shuffled.  A test module whose mpmath references
  work at 30 digits says ``MPMATH_DPS = 30`` (each of its tests then runs under
  ``mpmath.workdps(30)``), never ``mpmath.mp.dps = 30``.
* **Hypothesis searches as far as the profile says.**  Locally (the README's
  test command) the ``dev`` profile; in CI (``CI`` set, as CI services set it)
  the ``ci`` profile, five times as many examples; ``HYPOTHESIS_PROFILE``
  chooses either.  A property test whose count is a matter of cost asks for a
  multiple of the profile's count (``settings.default.max_examples``), so that
  every property still runs here, with its pinned ``@example`` cases, and CI
  keeps the full search.
"""

from __future__ import annotations

import gc
import json
import locale
import os
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any, Callable, NamedTuple

import mpmath
import numpy as np
import pytest
from hypothesis import settings
from hypothesis.configuration import set_hypothesis_home_dir

# -- Hypothesis: how far the property tests search -----------------------------------------------------------

# No test writes into the checkout, Hypothesis neither: its home (by default .hypothesis in the working folder,
# where it caches the constants it reads from the sources) is a folder of the system's temporary files, and
# there is no example database (a failing example is printed with the failure, and pinned with @example when
# it is fixed).
set_hypothesis_home_dir(Path(tempfile.gettempdir()) / "construct-tests-hypothesis")
settings.register_profile("ci", max_examples=100, database=None)   # Hypothesis's own default count
settings.register_profile("dev", max_examples=20, database=None)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE") or ("ci" if os.environ.get("CI") else "dev"))

# The Python processes the tests start (the command line run as a user runs it, xdist's workers) cache the
# bytecode they compile in a folder of the system's temporary files, never beside the sources: without a cache
# (PYTHONDONTWRITEBYTECODE) each compiled the package again, about half of a small command's CPU (0.6 -> 0.3 s);
# beside the sources it would write into the checkout.  Processes started with -B read it and write nothing.
# Set before the state every test is held to is read, so that it is the state of the session.
if not os.environ.get("PYTHONPYCACHEPREFIX"):
    os.environ["PYTHONPYCACHEPREFIX"] = str(Path(tempfile.gettempdir()) / "construct-tests-pycache")
    os.environ.pop("PYTHONDONTWRITEBYTECODE", None)


# -- the collector: its young passes less often ---------------------------------------------------------------

# What the session's fixtures made (figures, drawings, sweeps, parsed modules) stays alive to the end, and every
# young pass of the collector (by default each 700 allocations) walks what survived the pass before: a seventh of
# the suite's CPU (measured: test_library, test_render_scene and test_constructions_crank serially, 11.0 -> 9.3 s).
# Set before the state every test is held to is read, so that it is the state of the session; below the 10,000 a
# command raises it to (io/collector.few_collections), so that tests/test_cli.py still sees a command raise it.
gc.set_threshold(7_000, 20, 20)


@pytest.hookimpl(tryfirst=True)
def pytest_unconfigure(config):
    """After the last test, before pytest's own end of session: what the process holds is frozen (kept out of the
    collector's passes).  pytest's unconfigure runs full passes (to report unraisable exceptions of objects freed
    late), which in a process that built the gallery's figures, drawings and sweeps walked and freed up to a
    gigabyte: 1.7-1.9 s per worker measured, and xdist's controller waits for the last worker to exit, so that the
    run ended that much later.  Every test has run; the process exits next and gives its memory back whole."""
    gc.freeze()


# -- the order: shuffled on request ---------------------------------------------------------------------------

def pytest_addoption(parser):
    parser.addoption("--shuffle", type=int, metavar="SEED", default=None,
                     help="run the tests in an order shuffled by SEED (the suite holds in any order; with -n the "
                          "workers need the one seed, so it is given, not drawn)")


def pytest_report_header(config):
    seed = config.getoption("--shuffle")
    return None if seed is None else f"tests shuffled: --shuffle {seed}"


#: The test modules whose tests take longest (a browser's drags, the 1,000-ratio sweeps, the live players' sweeps,
#: every output rendered), run first.  xdist's worksteal gives each worker a half of the list and a worker that runs
#: out takes the back half of what the other has left, so the run ends where the two meet: in collection order
#: that was among the 1,000-ratio sweeps (tests/test_sweep.py, up to 10 s a test), one worker alone for their
#: last 5 s.  With these first the workers meet among short tests.  (A simulation of worksteal with the measured
#: durations of a full run: the last worker's end over half the summed durations 5.0 -> 0.2 s; 2.7 -> 0.2 s mean
#: with every duration scaled by 0.6-1.4 at random.  More modules here are worse: the meeting falls among them.)
COSTLIEST_FIRST = ("test_render_live_browser.py", "test_sweep.py", "test_render_sweepdraw.py", "test_live.py",
                   "test_render_output.py")


def pytest_collection_modifyitems(config, items):
    """The costliest test modules first (:data:`COSTLIEST_FIRST`; a module's tests stay together and in their
    order, for its module-scoped fixtures).  ``--shuffle SEED``: instead, the collected tests in an order that only
    SEED decides (so that every xdist worker collects the same list), to show that no test needs another to run
    before it."""
    seed = config.getoption("--shuffle")
    if seed is not None:
        import random

        random.Random(seed).shuffle(items)
        return
    rank = {name: i for i, name in enumerate(COSTLIEST_FIRST)}
    items.sort(key=lambda item: rank.get(item.path.name, len(rank)))  # stable: the rest in collection order


# -- no test leaves a trace in the process ------------------------------------------------------------------

_SIGNALS = tuple(getattr(signal, n) for n in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, n))


def _process_state() -> dict[str, Any]:
    """What a test could change for every test after it (in the same worker process)."""
    return {
        "mpmath precision": mpmath.mp.prec,
        "signal handlers": [signal.getsignal(s) for s in _SIGNALS],
        "working folder": os.getcwd(),
        "environment": {k: v for k, v in os.environ.items() if k != "PYTEST_CURRENT_TEST"},  # pytest's own
        "numpy error handling": np.geterr(),
        "locale": locale.setlocale(locale.LC_ALL),
        "sys.path": list(sys.path),
        "file-size limit": resource.getrlimit(resource.RLIMIT_FSIZE),
        "garbage collector": (gc.isenabled(), gc.get_threshold(), gc.get_freeze_count()),
    }


_BEFORE_THE_SESSION = _process_state()


@pytest.fixture(autouse=True)
def _leaves_the_process_as_it_found_it():
    """Each test finds the process as it was before the session, and leaves it so (checked after its own
    fixtures, monkeypatch's included, have been torn down: this fixture is set up first)."""
    before = _process_state()
    changed = [k for k in before if before[k] != _BEFORE_THE_SESSION[k]]
    assert not changed, f"an earlier test or a test module's import changed {', '.join(changed)}"
    yield
    after = _process_state()
    changed = [k for k in after if after[k] != before[k]]
    assert not changed, f"the test changed {', '.join(changed)}: " + "; ".join(
        f"{k} {before[k]!r} -> {after[k]!r}" for k in changed)[:2000]


@pytest.fixture(autouse=True)
def _mpmath_digits(request):
    """A test module's ``MPMATH_DPS``: the digits its mpmath references work at, for each of its tests
    (``mpmath.workdps``: restored after the test, whatever it raised)."""
    dps = getattr(request.module, "MPMATH_DPS", None)
    if dps is None:
        yield
        return
    with mpmath.workdps(dps):
        yield


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


#: Runs the commands (a JSON list of argv lists) one after the other in this one process, as ``python -m
#: construct`` runs one; each command's stdout and stderr end with a NUL byte, the exit codes follow on stderr.
_COMMANDS = """
import json, sys
from construct.cli.main import main
codes = []
for argv in json.loads(sys.argv[1]):
    try:
        codes.append(main(argv))
    except SystemExit as exc:
        codes.append(exc.code)
    for stream in (sys.stdout, sys.stderr):
        stream.flush()
        stream.buffer.write(b"\\0")
        stream.buffer.flush()
sys.stderr.write(json.dumps(codes))
"""


def commands_in_a_process(*argvs: list[str], env: dict[str, str] | None = None, cwd: Path | None = None,
                          timeout: float = 120) -> list[Run]:
    """``construct ARGV`` for each of *argvs*, one after the other in one fresh Python process (what the process
    starts with -- its environment, the terminal's encoding, the installed entry points -- is the point; one
    interpreter start instead of one a command).  Each command restores what it changes in the process (the
    streams' error handling), so each finds the process as it started.  bytes out and err."""
    proc = subprocess.run([sys.executable, "-B", "-c", _COMMANDS, json.dumps([list(map(str, a)) for a in argvs])],
                          capture_output=True, timeout=timeout, cwd=cwd, env={**os.environ, **(env or {})})
    assert proc.returncode == 0 and b"Traceback" not in proc.stderr, proc.stderr[-2000:]
    outs, errs = proc.stdout.split(b"\0"), proc.stderr.split(b"\0")
    codes = json.loads(errs.pop())
    assert outs.pop() == b"" and len(outs) == len(errs) == len(codes) == len(argvs), proc
    return [Run(*run) for run in zip(codes, outs, errs)]


@pytest.fixture
def cli_process() -> Callable[..., list[Run]]:
    """:func:`commands_in_a_process`: several commands in one fresh process."""
    return commands_in_a_process


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


@pytest.fixture(scope="session")
def gallery_figure() -> Callable[..., tuple[Any, Any]]:
    """(construction, figure) for a name and parameters -- the gallery's figures above all, which five test
    modules read -- built once per session (per worker) when first asked for, never changed by a test."""
    from construct import get

    made: dict[tuple, tuple[Any, Any]] = {}

    def figure(name: str, params: Any = None) -> tuple[Any, Any]:
        params = dict(params or {})
        key = (name, tuple(sorted(params.items())))
        if key not in made:
            c = get(name)
            made[key] = (c, c.figure(**params))
        return made[key]

    return figure


@pytest.fixture(scope="session")
def gallery_drawing(gallery_figure, tmp_path_factory) -> Callable[..., Any]:
    """The teaching drawing (``Drawing`` of the figure's scene, style teaching) of :func:`gallery_figure`'s figure,
    made once per session when first asked for: placing the letters of the gallery's largest figures takes
    seconds (tangential-pressure's compound engine: 4,000 steps), and three test modules read them; no test
    changes one.  Under xdist the workers share it: the first to ask makes it and leaves a copy (pickled, in the
    run's temporary folder, under a lock) for the others, who read it in a tenth of the time (all the gallery's
    drawings: 18.9 s to make, 2.0 s to read); every figure's drawing was otherwise made on every worker."""
    made: dict[tuple, Any] = {}
    shared = tmp_path_factory.getbasetemp().parent / "gallery-drawings" if os.environ.get("PYTEST_XDIST_WORKER") \
        else None  # xdist gives each worker a folder in the run's own

    def drawing(name: str, params: Any = None) -> Any:
        params = dict(params or {})
        key = (name, tuple(sorted(params.items())))
        if key not in made:
            made[key] = _drawing(name, params) if shared is None else _shared_drawing(shared, name, params)
        return made[key]

    def _drawing(name: str, params: dict[str, Any]) -> Any:
        from construct.render.output import scene_for
        from construct.render.styles import STYLES
        from construct.render.svg import Drawing

        c, fig = gallery_figure(name, params)
        return Drawing(scene_for(c, fig), STYLES["teaching"])

    def _shared_drawing(folder: Path, name: str, params: dict[str, Any]) -> Any:
        import fcntl
        import hashlib
        import pickle

        folder.mkdir(exist_ok=True)
        path = folder / hashlib.sha256(repr((name, sorted(params.items()))).encode()).hexdigest()[:32]
        with open(path.with_suffix(".lock"), "w") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)  # released when closed: the one that makes it, the others wait
            if path.exists():
                return pickle.loads(path.read_bytes())
            made = _drawing(name, params)
            path.with_suffix(".part").write_bytes(pickle.dumps(made, protocol=pickle.HIGHEST_PROTOCOL))
            path.with_suffix(".part").replace(path)
            return made

    return drawing


@pytest.fixture(scope="session")
def crank6():
    """The crank construction and its figure at 6 parts, L/r = 5: small, with every kind of step (the renderers'
    tests share it)."""
    from construct import get

    c = get("crank")
    return c, c.figure(parts=6, rod_ratio=5.0)


# -- headless Chromium, for the player, the live player and the gallery site ---------------------------------

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync"]


def _browser_unavailable(reason: str):
    if os.environ.get("CI"):
        pytest.fail(f"browser test cannot run in CI: {reason}")
    pytest.skip(reason)


#: Playwright's window when a test names none (its own default)
_VIEWPORT = {"width": 1280, "height": 720}


class _Tab:
    """A page of :class:`_Browser`'s: Playwright's ``Page`` (every attribute is the page's), except that ``on``
    keeps what it registers and ``close`` hands the page back -- its handlers removed, its document left for an
    empty one -- instead of closing it."""

    def __init__(self, owner: "_Browser", page: Any):
        self._owner, self._page, self._handlers = owner, page, []

    def __getattr__(self, name: str) -> Any:
        return getattr(self._page, name)

    def on(self, event: str, handler: Callable) -> None:
        self._handlers.append((event, handler))
        self._page.on(event, handler)

    def close(self) -> None:
        for event, handler in self._handlers:
            self._page.remove_listener(event, handler)
        self._handlers.clear()
        self._page.goto("about:blank")  # (the document's frames and timers end here, not in the next test)
        self._owner._free.append(self._page)


class _Browser:
    """The session's browser, whose ``new_page`` hands out the pages closed before (:class:`_Tab`): a new page of
    a browser is a new context and a new renderer process, about 0.6 s of Chromium's CPU before its document is
    read (a reused page navigated to the next document: 0.25 s for a small player, measured), and the browser
    tests open some 60 pages.  A new document starts the page's scripts afresh (the player and the site keep
    nothing in the browser's storage); what a test opened and did not close (it failed) is not handed out again.
    ``new_context`` and the rest: the browser's own."""

    def __init__(self, browser: Any):
        self._browser, self._context, self._free = browser, None, []

    def __getattr__(self, name: str) -> Any:
        return getattr(self._browser, name)

    def new_page(self, viewport: dict[str, int] | None = None) -> _Tab:
        if not self._free:
            self._context = self._context or self._browser.new_context()
            self._free.append(self._context.new_page())
        page = self._free.pop()
        page.set_viewport_size(viewport or _VIEWPORT)
        page.bring_to_front()  # (a page behind another one gets an animation frame a second)
        return _Tab(self, page)


@pytest.fixture(scope="session")
def browser():
    """Debian's chromium driven by Playwright (.ci/install-browser.sh); skipped without them, except in CI.  Its
    pages are reused (:class:`_Browser`)."""
    try:
        from playwright.sync_api import sync_playwright
    except ImportError:
        _browser_unavailable("playwright is not installed (.ci/install-browser.sh)")
    if not Path(CHROMIUM).exists():
        _browser_unavailable("chromium is not installed (.ci/install-browser.sh)")
    with sync_playwright() as pw:
        b = pw.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        yield _Browser(b)
        b.close()
