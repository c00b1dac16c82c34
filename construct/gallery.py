"""The gallery: every registered construction at the books' parameters, in every gallery style.

``build_gallery(out)`` writes, for each construction in
:func:`construct.constructions.names` and each of its ``book_params``::

    OUT/<entry>/protocol.json            the protocol (same for both styles; the first entry of a construction)
    OUT/<entry>/checks.md, checks.json    the check report against the analytic formulas
    OUT/<entry>/<style>/final.svg         historical: the book plate; teaching (the first entry of a construction):
                                          the whole construction,
                                          every step a <g data-step="k"> group (the golden of every step)
    OUT/<entry>/teaching/player.html      the step player, one file (it plays the steps too)

(``construct replay`` also writes animated.svg and storyboard.svg; the
gallery leaves them out, they carry the same elements again and the
committed gallery stays small.)
    OUT/README.md, OUT/index.html         the front page: the books, the plates (and players), the errata
    OUT/<entry>/checks.html               the checks and the construction's method, steps and instruments
    OUT/errata-<book>.html                a book's errata: what is wrong first, then every printed number
    OUT/latex/plates.tex, OUT/latex/*.tikz  two plates as TikZ, set on one LaTeX page (:data:`LATEX_PLATES`)

    OUT/.construct-manifest.json        every file above with its SHA-256: the mark of a gallery

The whole folder is built in a staging folder next to *out* and swapped in
as one piece (:func:`construct.io.staging.replaced_folder`), so a failure leaves
the previous gallery as it was.  Only an empty folder or a gallery whose every
file is in its manifest, unchanged (:func:`is_gallery`), is replaced; any other
folder or file at *out* is refused and left as it is, and a refusal lists what
in it construct did not write.  (A gallery written before manifests has none:
it is refused once; remove it and build again.)  Output is deterministic:
no dates, entries in registry order, fixed number formats.

>>> entry_slug("crank", {"rod_ratio": 5.0, "parts": 18})
'crank-parts-18-rod-ratio-5'
>>> entry_slug("piston-force", {"revolution": True})
'piston-force-revolution'
"""

from __future__ import annotations

import contextlib
import html
import json
import os
import signal
import sys
from pathlib import Path
from typing import Any, Callable, Iterator, Mapping

from .constructions.checking import summary
from .constructions import get, names
from .io.manifest import foreign_entries, replaced_with_manifest
from .io.staging import write_text
from .render.output import write_outputs
from .render.notation import citation
from .render.notation import givens as book_givens
from .render.styles import STYLES

__all__ = ["build_gallery", "gallery_plan", "entry_slug", "is_gallery", "GALLERY_STYLES", "GALLERY_OUTPUTS",
           "FRAME_MODE", "LIVE_PLAYERS", "LATEX_PLATES"]

GALLERY_STYLES = ("historical", "teaching")
#: No standalone frames: frame k holds the marks of k steps, so all frames
#: together grow with the square of the step count (65 MB for eight figures).
#: The teaching final.svg holds every step as a group, and `construct verify`
#: compares it step by step, so every step stays golden in one file.
FRAME_MODE = "none"
#: What each style adds to its final.svg: the teaching style's step player (it also plays the steps;
#: the animation and storyboard of `construct replay` carry the same elements again); the historical
#: style is the plate (the construction's views in the plate's ink would double the gallery).
GALLERY_OUTPUTS = {"historical": (), "teaching": ("player",)}
#: The constructions whose gallery player has a slider for each continuous given (construct.live): the rod
#: wherever the construction takes it (L/r; piston-force's L in metres beside R) and Baumann's kappa
#: (tangential-pressure, effective-work).  The live data adds 0.02-0.8 MB a player (its grid bounded by the
#: refinement's 0.4 px and 800 values, each coordinate at the grid values it needs, one sweep for each piece
#: of the domain where the steps' form changes; live.sweep and live.wire), and a sweep of 0.2-8.5 s of CPU to
#: the build.  `construct replay NAME --live` gives any construction with such a given its sliders.
LIVE_PLAYERS = ("crank", "crank-angle", "effective-work", "four-stroke", "inertia-curve", "inertia-stroke-fractions",
                "piston-force", "tangential-pressure", "two-cranks")
#: The live players whose data costs most, the costliest first (``construct bench --outputs`` measures each: 1.5 to
#: 5 s of CPU here, the others under 1 s): the workers take them first, so that the two cores end together
#: rather than one of them starting the longest figure when the other has nothing left to do.
LONGEST_FIRST = ("piston-force", "tangential-pressure", "effective-work", "two-cranks", "inertia-curve",
                 "inertia-stroke-fractions")
#: Givens a book varies that change the construction's steps (the indicator diagram's filling s1: the division
#: up to the cut-off): every book figure of the construction gets its player, and each player a switch
#: between them (render.live.with_switch) instead of a slider -- construction -> (param, symbol, how a value is
#: written).
SWITCHES: dict[str, tuple[str, str, Callable[[float], str]]] = {
    "indicator-diagram": ("filling", "s₁/s", lambda v: f"{round(100 * v):d} %")}
#: Why such a given is a switch, as the page says it.
SWITCH_WHY = ("Die Füllung s₁ ändert die Schritte der Konstruktion (die Teilung bis zum Abschluss): die Figuren "
              "des Buches, umschaltbar, kein Schieber. / The filling s₁ changes the construction's steps (the "
              "division up to the cut-off): the book's figures to switch between, not a slider.")
#: The plates the gallery's LaTeX example sets on one page (``latex/plates.tex``, beside their ``.tikz``
#: files): the crank and Abb. 1055, the piston-force line over the whole revolution.
LATEX_PLATES = (("crank", {"rod_ratio": 5.0, "parts": 18}), ("piston-force", {"revolution": True}))
#: The width (CSS px) at which the gallery page shows a figure: its own width, one figure per row,
#: so that letters of 12 px and captions of 13-14 px are shown at that size (never under 9 px).
DISPLAY_PX = 960


#: The first lines of the README.md the gallery writes (a heading for people; the gallery is recognised
#: by its manifest, not by this).
README_HEAD = "# Gallery\n\nBuilt by `construct gallery`; do not edit by hand."
#: What a refusal says a gallery folder would have been.
GALLERY_DESCRIBED = ("a gallery written by 'construct gallery' (recognised by its .construct-manifest.json; "
                     "one written before manifests is not: remove it once)")


def is_gallery(folder: str | Path) -> bool:
    """Whether *folder* is a gallery written by ``construct gallery`` and nothing else: every file in it
    is listed, unchanged, in its manifest (what ``construct gallery`` and ``verify --update`` may replace).

    >>> is_gallery(Path(__file__).parent), is_gallery("/nonexistent")
    (False, False)
    """
    try:
        return foreign_entries(Path(folder), "gallery") == []
    except OSError:
        return False


def _value(v: Any) -> str:
    return f"{v:g}" if isinstance(v, float) else str(v)


def entry_slug(name: str, params: Mapping[str, Any]) -> str:
    """A folder name for a construction at *params*: stable, readable, no odd characters.

    A switch is named when it is on and left out when off (no Python ``True``/``False`` in a name).

    >>> entry_slug("two-cranks", {"infinite_rod": True, "parts": 12}), entry_slug("crank", {"rod_ratio": 4.5})
    ('two-cranks-infinite-rod-parts-12', 'crank-rod-ratio-4_5')
    """
    parts = [name] + [k if v is True else f"{k}-{_value(v)}" for k, v in sorted(params.items()) if v is not False]
    text = "-".join(parts).replace("_", "-").replace(".", "_")
    return "".join(c if c.isalnum() or c in "-_" else "-" for c in text)


def gallery_plan() -> list[tuple[str, dict[str, Any]]]:
    """(construction, book params) in order: registry names sorted, each one's book_params as listed."""
    plan = []
    for name in names():
        c = get(name)
        for params in c.book_params or ({},):
            plan.append((name, dict(params)))
    return plan


class _Progress:
    """A progress bar on a terminal; nothing when not asked or not a terminal."""

    def __init__(self, total: int, enabled: bool):
        self.total = total
        self.enabled = enabled and sys.stderr.isatty()
        self.done = 0

    def step(self, text: str) -> None:
        if not self.enabled:
            return
        width = 30
        filled = int(width * self.done / max(self.total, 1))
        sys.stderr.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.total} {text[:40]:40s}")
        sys.stderr.flush()
        self.done += 1

    def close(self) -> None:
        if self.enabled:
            sys.stderr.write(f"\r[{'#' * 30}] {self.total}/{self.total} {'done':40s}\n")


def _checks_md(title: str, checks: list, method: list[tuple[str, str]]) -> str:
    lines = [f"# Checks: {title}", "", f"**{summary(checks)}**", "",
             *[f"- {what}: {_md(how)}" for what, how in method], "",
             "| | quantity | measured | expected | error | tolerance | why |",
             "|---|---|---:|---:|---:|---:|---|"]
    for ch in checks:
        mark = "ok" if ch.ok else "**FAIL**"
        lines.append(f"| {mark} | {_md(ch.name)} | {ch.measured:.12g} | {ch.expected:.12g} | {ch.error:+.2e} "
                     f"| {ch.tolerance:.1e} | {_md(ch.why)} |")
    return "\n".join(lines) + "\n"


def _md(text: str) -> str:
    """Text for a Markdown table cell: no pipes, no HTML."""
    # Only what Markdown would read as HTML is escaped; an apostrophe stays one.
    return html.escape(text, quote=False).replace("|", "\\|").replace("\n", " ")


def _method(fig) -> list[tuple[str, str]]:
    """What method the figure uses: the division method (if any), its steps by provenance, its instruments."""
    kinds: dict[str, int] = {}
    for s in fig.protocol.steps:
        kinds[s.provenance.kind] = kinds.get(s.provenance.kind, 0) + 1
    methods = sorted({s.provenance.method for s in fig.protocol.steps if s.provenance.method})
    # the division's method by its name (Dürer's trisection (1525)), else the params' word for it
    return [("method", "; ".join(methods) or str(fig.params.get("method", "Euclidean construction"))),
            ("steps by provenance", ", ".join(f"{k} {v}" for k, v in sorted(kinds.items()))),
            ("instruments", ", ".join(f"{k} {v}" for k, v in fig.protocol.instrument_counts().items()))]


def _build_entry(root: Path, number: int, name: str, params: dict[str, Any],
                 formats: tuple[str, ...] = ("svg",)) -> tuple[list[dict], dict]:
    """Build one figure's folder (protocol, checks, both styles) under *root*; return its entries and index row."""
    c = get(name)
    fig = c.figure(**params)
    slug = entry_slug(name, params)
    edir = root / slug
    edir.mkdir()
    # The first of a construction's book parameters is built whole: its protocol, the teaching style (every step
    # golden) and the player.  The others are the book's further figures of the same method: their plate and their
    # checks (a replay writes the rest: `construct replay NAME --PARAM VALUE`).  The gallery stays small enough to
    # commit (25 MB, each player at most 2 MB), and a teacher changes a given in the player rather than opening
    # another copy.
    first = _first_of_its_construction(name, params)
    if first:
        write_text(edir / "protocol.json", fig.protocol.to_json(fig.replay))
    checks = c.checks(fig)
    method = _method(fig)
    write_text(edir / "checks.md", _checks_md(f"{c.title.en} ({book_givens(fig, c)[1]})", checks, method))
    write_text(edir / "checks.json", json.dumps(
        {"construction": name, "params": params, "summary": summary(checks),
         "ok": all(ch.ok for ch in checks), "checks": [ch.as_dict() for ch in checks]},
        indent=1, ensure_ascii=False, sort_keys=True) + "\n")
    entries = []
    thumb = ""
    switch = _switch(name, params)
    for style in GALLERY_STYLES if first or switch else GALLERY_STYLES[:1]:
        sdir = edir / style
        sdir.mkdir()
        live, drawing = (_live(c, fig, style) if first and GALLERY_OUTPUTS[style] and name in LIVE_PLAYERS
                         else (None, None))
        if style == "teaching":
            # laid out here (once: the outputs carry it) for the front page's thumbnail of what it keeps
            from .render.output import scene_for
            from .render.site import thumbnail_view
            from .render.svg import Drawing

            drawing = drawing or Drawing(scene_for(c, fig, ending=STYLES[style].camera), STYLES[style])
            thumb = thumbnail_view(drawing)
        # the plates also as PDF or TikZ when asked (construct gallery --format): the historical style's
        info = write_outputs(sdir, c, fig, STYLES[style], frames=FRAME_MODE, fig_number=number, protocol=False,
                             outputs=GALLERY_OUTPUTS[style], live=live, drawing=drawing,
                             formats=("svg", *formats) if style == "historical" else ("svg",),
                             switch=switch if GALLERY_OUTPUTS[style] else None)
        files = sorted(str(p.relative_to(root)) for p in sdir.rglob("*") if p.is_file())
        files += [f"{slug}/protocol.json"] * first + [f"{slug}/checks.md", f"{slug}/checks.json"]
        entries.append({"construction": name, "params": dict(params), "style": style,
                        "files": sorted(files), "steps": info["steps"], "frames": info["frames"],
                        "frame_mode": FRAME_MODE})
    row = {"number": number, "name": name, "slug": slug, "params": params, "title": c.title,
           "source": citation(c, "en") or c.source, "books": [cite.book.key for cite in c.cites],
           "method": method, "checks": summary(checks), "ok": all(ch.ok for ch in checks),
           "steps": len(fig.protocol.steps), "params_text": book_givens(fig, c)[1], "player": first or bool(switch),
           "thumb": thumb}
    if (name, params) in LATEX_PLATES:
        # the LaTeX example's plate made here, from the figure just built (the index writes it: _latex_example)
        from .render.output import figure_title, print_plate
        from .render.tikz import tikz_picture

        row["latex"] = (tikz_picture(print_plate(fig, construction=c)), figure_title(c, fig)[0])
    return entries, row


def _live(c, fig, style: str) -> tuple[list[dict[str, Any]] | None, Any]:
    """The live data of a gallery player (a slider for each continuous given the construction can sweep) and
    the figure's drawing, laid out once for the sweeps' camera views and the player."""
    from .live import live_givens, live_pages
    from .render.output import scene_for
    from .render.svg import Drawing

    if not live_givens(c, fig):
        return None, None
    drawing = Drawing(scene_for(c, fig, ending=STYLES[style].camera), STYLES[style])
    return live_pages(c, fig, STYLES[style], drawing=drawing), drawing


def _switch(name: str, params: Mapping[str, Any]) -> tuple | None:
    """The switch between the book figures of a construction whose varied given changes its steps (SWITCHES):
    (symbol, [(value as written, the sibling player's page or None for this one)], why); None elsewhere."""
    if name not in SWITCHES:
        return None
    key, symbol, written = SWITCHES[name]
    c = get(name)
    here = entry_slug(name, params)
    options = []
    for p in [dict(q) for n, q in gallery_plan() if n == name]:
        slug = entry_slug(name, p)
        options.append((written(float(p.get(key, c.defaults[key]))),
                        None if slug == here else f"../../{slug}/teaching/player.html"))
    return symbol, options, SWITCH_WHY


def _expected_cost(name: str, params: Mapping[str, Any]) -> tuple[int, int]:
    """Where a figure comes in the workers' order (least first): the first figure of a construction with a live
    player, the costliest of those first (LONGEST_FIRST); then the other first figures (their teaching figure
    and player); then the rest (a plate and its checks)."""
    if not _first_of_its_construction(name, params):
        return (2, 0)
    if name not in LIVE_PLAYERS:
        return (1, 0)
    return (0, LONGEST_FIRST.index(name) if name in LONGEST_FIRST else len(LONGEST_FIRST))


def _first_of_its_construction(name: str, params: Mapping[str, Any]) -> bool:
    return next(p for n, p in gallery_plan() if n == name) == dict(params)


def build_gallery(out: str | Path, *, progress: bool = False, workers: int | None = None,
                  before_swap: Callable[..., None] | None = None,
                  check: Callable[[Path], Any] | None = None, formats: Any = ("svg",)) -> list[dict]:
    """Build the whole gallery into *out* (swapped in whole); return one dict per (entry, style).

    *formats*: besides the SVG figures, each plate (the historical style) also as ``final.pdf`` or
    ``final.tikz`` and ``final.tex`` at its final size (:data:`construct.render.output.FORMATS`).

    *before_swap* is called with the finished staging folder just before it
    replaces *out* (``construct gallery`` lints it there); what it raises
    leaves the previous gallery as it was.  *check*, a function of a figure's
    folder (a module's own function: the workers are handed it), is called
    in the process that built the figure, right after it (``construct
    gallery`` lints each figure there, so that the checking shares the cores
    with the building); then *before_swap* is called with the staging folder
    and the list of what *check* returned, in plan order.

    The figures are built by up to *workers* processes (default: one per CPU,
    at most 4); each writes its own folder, and the index is written from the
    results in plan order, so the bytes do not depend on which process
    finished first.  The first figure of each construction (the whole
    teaching figure and its player, the longest to build) is handed out
    first, the live players (their sweeps) before the others and the
    costliest of those first (:data:`LONGEST_FIRST`), so that no process is
    left with a long one at the end.
    """
    from .render.output import check_formats

    extra = tuple(f for f in check_formats(formats) if f != "svg")
    plan = gallery_plan()
    bar = _Progress(len(plan), progress)
    entries: list[dict] = []
    index: list[dict] = []
    checked: list[Any] = []
    jobs = [(number, name, dict(params), check, extra) for number, (name, params) in enumerate(plan, start=1)]
    if workers is None:
        workers = min(4, os.cpu_count() or 1)
    with replaced_with_manifest(out, "gallery", described=GALLERY_DESCRIBED, what="gallery folder") as root:
        root.mkdir()
        if workers > 1 and len(jobs) > 1:
            import concurrent.futures
            import multiprocessing

            # fork where there is one: the workers start with construct already imported
            methods = multiprocessing.get_all_start_methods()
            context = multiprocessing.get_context("fork" if "fork" in methods else None)
            with concurrent.futures.ProcessPoolExecutor(min(workers, len(jobs)), mp_context=context,
                                                        initializer=_worker_init, initargs=(os.getpid(),)) as pool:
                ours: list[Any] = []  # the pool's worker processes, once forked
                try:
                    # the long ones first: the live players' sweeps before them all, the costliest first (each
                    # result goes to its own place in plan order)
                    order = sorted(range(len(jobs)), key=lambda i: _expected_cost(*jobs[i][1:3]))
                    before = set(multiprocessing.active_children())
                    with _signals_held():  # the workers are forked here
                        futures = {pool.submit(_build_and_check, root, *jobs[i]): i for i in order}
                        # known before a held signal comes in (at the end of this block), so that it stops them
                        ours = [p for p in multiprocessing.active_children() if p not in before]
                    sources = _errata_sources()  # read while the workers build (the index shows them)
                    for fut in concurrent.futures.as_completed(futures):
                        bar.step(jobs[futures[fut]][1])
                    by_job = {i: fut.result() for fut, i in futures.items()}
                    results = [by_job[i] for i in range(len(jobs))]
                except BaseException:
                    # interrupted or failed: the figures not yet begun are not built for nothing, and the
                    # ones being built are stopped -- a live player's sweep takes seconds, and Ctrl-C or
                    # SIGTERM must not wait for it (SIGTERM ends a worker: _worker_init)
                    for worker in ours:
                        if worker.is_alive():
                            worker.terminate()
                    pool.shutdown(wait=True, cancel_futures=True)
                    raise
        else:
            sources = _errata_sources()
            results = []
            for job in jobs:
                bar.step(job[1])
                results.append(_build_and_check(root, *job))
        for figure_entries, row, found in results:
            entries += figure_entries
            index.append(row)
            checked.append(found)
        _latex_example(root, index)
        write_text(root / "README.md", _readme(index, sources))
        write_text(root / "index.html", _index_html(index, sources))
        _site_pages(root, index, sources)
        bar.close()
        if before_swap is not None:
            before_swap(*((root, checked) if check is not None else (root,)))
    return entries


def _latex_example(root: Path, index: list[dict]) -> None:
    """``latex/plates.tex``: the plates of :data:`LATEX_PLATES` the plan builds, as TikZ, on one LaTeX page
    (each TikZ picture made where its figure was built: the index row's ``latex``)."""
    from .render.tikz import tikz_example

    plates = []
    for row in sorted((row for row in index if "latex" in row),
                      key=lambda row: LATEX_PLATES.index((row["name"], row["params"]))):
        picture, title = row["latex"]
        file = f"{row['slug']}.tikz"
        write_text(root / "latex" / file, picture)
        plates.append((file, title))
    if plates:
        write_text(root / "latex" / "plates.tex", tikz_example(plates))


def _build_and_check(root: Path, number: int, name: str, params: dict[str, Any],
                     check: Callable[[Path], Any] | None,
                     formats: tuple[str, ...] = ()) -> tuple[list[dict], dict, Any]:
    """:func:`_build_entry`, then *check* on the figure's folder (None without one)."""
    figure_entries, row = _build_entry(root, number, name, params, formats)
    return figure_entries, row, (check(root / row["slug"]) if check is not None else None)


_HELD = ("SIGINT", "SIGTERM")


@contextlib.contextmanager
def _signals_held() -> Iterator[None]:
    """Hold Ctrl-C and SIGTERM in this thread while worker processes are forked, then let them in.

    A handler that raises during a fork raises inside an at-fork hook, where
    Python ignores the exception (the interrupt is lost and the build goes on)
    or leaves the pool half set up; held, the signal arrives just after, where
    it unwinds the build like anywhere else.  Only this thread's signal mask
    changes, and only for the moment of the forks.
    """
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, [getattr(signal, s) for s in _HELD])
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


def _worker_init(parent: int) -> None:
    """In a worker process: SIGTERM ends it (a forked worker would inherit the CLI's handler, which
    unwinds the command in the main process; the main process cleans up after its workers), the
    signals held while it was forked are let in again, it ends when its parent has gone, its
    garbage collector runs less often and its C allocator keeps what is freed (:func:`_keep_freed_memory`)."""
    import gc
    import threading

    # A worker builds figures of tens of thousands of objects that live until the figure is written: the
    # collector's young passes would walk them again and again (a tenth of the build), and what the worker
    # was forked with (construct, imported) is never garbage.  This process is the gallery's own.
    gc.freeze()
    gc.set_threshold(50_000, 20, 20)
    _keep_freed_memory()
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    if hasattr(signal, "pthread_sigmask"):
        signal.pthread_sigmask(signal.SIG_UNBLOCK, [getattr(signal, s) for s in _HELD])
    threading.Thread(target=_exit_with_parent, args=(parent,), daemon=True).start()


#: glibc's mallopt parameters (malloc.h) and what a worker sets them to: blocks of up to 32 MiB (glibc's largest
#: threshold) from the heap rather than each mapped afresh, and freed memory kept for the next figure rather than
#: handed back to the system after every free.
_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3
_MALLOC_KEPT = ((_M_MMAP_THRESHOLD, 32 * 2**20), (_M_TRIM_THRESHOLD, 1 << 30))


def _keep_freed_memory() -> bool:
    """In a gallery worker (a process of its own, ended with the gallery): let the C allocator keep what is freed.

    A figure's sweeps and drawings allocate and free arrays and lists of megabytes again and again; by default
    glibc maps each block above 128 KiB afresh and unmaps it when freed, and gives the heap's top back, so every
    new block is faulted in page by page again: measured on two live players' figures, 96,000 page faults and 0.5-0.7 s
    of system time in 8.3 s of CPU, with it 62,000 and 0.35-0.45 s.  Nothing that is computed changes, only where
    memory comes from.  Returns whether it was set (glibc only; elsewhere nothing).
    """
    if "CS_GNU_LIBC_VERSION" not in getattr(os, "confstr_names", {}) or not _glibc():
        return False
    import ctypes

    mallopt = getattr(ctypes.CDLL(None), "mallopt", None)
    if mallopt is None:
        return False
    return all([mallopt(ctypes.c_int(param), ctypes.c_int(value)) == 1 for param, value in _MALLOC_KEPT])


def _glibc() -> bool:
    try:
        return os.confstr("CS_GNU_LIBC_VERSION").startswith("glibc")
    except (ValueError, OSError):
        return False


def _exit_with_parent(parent: int) -> None:
    """A worker whose parent was killed, or unwound while it was being forked (then the pool
    never knew it), would wait for work forever, holding the parent's pipes open."""
    import time

    while os.getppid() == parent:
        time.sleep(0.5)
    os._exit(1)


def _readme(index: list[dict], sources: list[dict]) -> str:
    """The gallery's README (what a repository browser shows): the books, then the plates with their links."""
    from .constructions.phrases import BOOKS
    from .render.site import book_title, book_where, errata_slug

    lines = [README_HEAD + "  The graphical methods of four German texts on steam-engine design from around "
             "1900, redrawn as the books draw them and checked against their formulas: every figure as a plate "
             "(the historical style) and, for the first figure of each method, step by step in the step player "
             "(`*/teaching/player.html`). `index.html` is the same for a browser.", "", "## The books", ""]
    errata = {src["book"] for src in sources}
    for name, b in BOOKS.items():
        lines.append(f"- **{_md(book_title(b))}** — {_md(book_where(b))}. Teaches {_md(b.teaches)}."
                     + (f" [Errata]({errata_slug(name)})." if name in errata else ""))
    lines += ["", "## The plates", ""]
    for e in index:
        t = e["title"]
        s = e["slug"]
        lines += [f"### Fig. {e['number']}. {_md(t.de)} / {_md(t.en)}", "",
                  f"*{_md(e['params_text'])}* — {_md(e['source'])}", "",
                  # one picture per row: at the page's width the letters stay at least 9 px (DISPLAY_PX)
                  f"![Fig. {e['number']}, historical plate]({s}/historical/final.svg)", "",
                  " · ".join([f"[plate]({s}/historical/final.svg)"]
                             + ([f"[step player]({s}/teaching/player.html) ({e['steps']} steps)",
                                 f"[construction]({s}/teaching/final.svg)"] if e["player"] else [])
                             + [f"[checks]({s}/checks.md){'' if e['ok'] else ' (a check fails)'}"]), ""]
    return "\n".join(lines)


def _index_html(index: list[dict], sources: list[dict] | None = None) -> str:
    """The front page (:func:`construct.render.site.index_page`): the books, the plates, the errata."""
    from .books.errata import WRONG
    from .constructions.phrases import BOOKS
    from .render.site import index_page

    return index_page(index, _errata_sources() if sources is None else sources, list(BOOKS.values()), wrong=WRONG)


def _errata_sources() -> list[dict]:
    """Each book with errata, in the books' order: its name, how many printed numbers, of each class, the rows."""
    from .books.errata import CLASSES, all_errata

    by_book: dict[str, list] = {}
    for e in all_errata():
        by_book.setdefault(e.source, []).append(e.as_dict())
    return [{"book": name, "count": len(rows), "rows": rows,
             "classes": {c: sum(r["class"] == c for r in rows) for c in CLASSES}}
            for name, rows in by_book.items()]


def _site_pages(root: Path, index: list[dict], sources: list[dict] | None = None) -> None:
    """The gallery's other pages: each figure's checks (from its checks.json), each book's errata."""
    from .books.errata import CLASS_MEANINGS, WRONG
    from .constructions.phrases import BOOKS
    from .render.site import checks_page, errata_page, errata_slug

    for e in index:
        report = json.loads((root / e["slug"] / "checks.json").read_text(encoding="utf-8"))
        write_text(root / e["slug"] / "checks.html", checks_page(
            f"Fig. {e['number']}. {e['title'].de} ({e['params_text']}): checks", report["checks"],
            back=f"../index.html#{e['slug']}", summary=report["summary"], method=e["method"]))
    for src in _errata_sources() if sources is None else sources:
        write_text(root / errata_slug(src["book"]), errata_page(
            BOOKS[src["book"]], src["rows"], back="index.html", meanings=CLASS_MEANINGS, wrong=WRONG,
            books=list(BOOKS.values())))
