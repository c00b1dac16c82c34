"""pytest plugin: golden files for your own constructions, compared in geometry.

Registered through the ``pytest11`` entry point, so installing ``construct``
is enough.  The fixture :func:`construct_golden` renders a figure -- the
layered drawing ``final.svg`` (every step a ``<g data-step="k">`` group, so
*every* step is golden in one file) and the protocol, plus standalone step
frames when asked -- and compares them with the goldens in ``goldens/<name>/``
next to the test file, through the semantic diff
(:mod:`construct.regress.verify`): reordered attributes or respelled numbers
are equal, a point moved by 0.01 drawing units is named with its step and
element.  ``pytest --construct-update`` writes or rewrites them.

On a difference the test fails with the report (figure, step, element,
what changed) and a side-by-side page of expected and actual for every
failing frame, written to ``.construct-failures/<name>.html`` beside the
``goldens`` folder; the message gives its path.

The protocol is compared as :func:`construct.testing.assert_figures_equal` compares two figures (through
:func:`construct.regress.testing.figures_diff`); use that function in a test to compare figures directly.

The rendered figure must also be legible (:mod:`construct.regress.lint`:
no labels on each other, on another point or struck by a result line, none
too small or outside the view); ``check(..., legible=False)`` skips that.

>>> safe_name("test_stroke[2.0-exact]")
'test_stroke-2.0-exact'
"""

from __future__ import annotations

import html
import os
import re
import shutil
import tempfile
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Callable

import pytest

from ..kernel.errors import InvalidParameter

__all__ = ["GoldenChecker", "construct_golden", "safe_name", "render_goldens", "side_by_side_html"]

MAX_REPORTED = 20  # change lines per file in the failure message
MAX_PAGES = 12  # failing frames drawn side by side in the HTML page (the rest are only listed)
FAILURES = ".construct-failures"
_NAME_RE = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9._-]*$")


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("construct", "golden files of constructions (construct_golden fixture)")
    group.addoption("--construct-update", action="store_true", default=False,
                    help="write or rewrite the goldens of construct_golden.check() instead of comparing")
    parser.addini("construct_goldens", default="goldens",
                  help="folder of construct goldens, relative to each test file (default: goldens)")


def safe_name(text: str) -> str:
    """A folder name from a test name: ``[``, ``]``, spaces and the like become ``-``."""
    name = re.sub(r"[^A-Za-z0-9._-]+", "-", text).strip("-.")
    return name or "figure"


# --------------------------------------------------------------------------- rendering


def _style(style: Any) -> Any:
    from ..render.styles import STYLES
    from ..render.styles import Style

    if isinstance(style, Style):
        return style
    if style not in STYLES:
        raise InvalidParameter(f"unknown style {style!r}; choose one of {', '.join(sorted(STYLES))}")
    return STYLES[style]


def render_goldens(figure: Any, out: Path, *, style: Any = "plain", frames: str = "none",
                   title: tuple[str, str] | None = None) -> int:
    """Write the layered ``final.svg``, ``protocol.json`` and (*frames*) ``steps/NNN.svg`` into *out*.

    Returns the number of standalone frames written.
    """
    from ..io.staging import write_text
    from ..render.output import FRAME_MODES, frame_steps
    from ..render.scene import build_scene

    if frames not in FRAME_MODES:
        raise InvalidParameter(f"frames must be one of {', '.join(FRAME_MODES)}, got {frames!r}")
    st = _style(style)
    scene = build_scene(figure, title=title, ending=st.camera)
    from ..render.svg import Drawing

    drawing = Drawing(scene, st)
    frame: Callable[[int], str] = drawing.frame
    write_text(out / "final.svg", drawing.layered())
    ks = frame_steps(scene, frames)
    width = max(3, len(str(len(scene.steps))))  # the same names as `construct replay` writes
    for k in ks:
        write_text(out / "steps" / f"{k:0{width}d}.svg", frame(k))
    write_text(out / "protocol.json", figure.protocol.to_json(figure.replay))
    return len(ks)


# --------------------------------------------------------------------------- the failure page


def _inline_svg(path: Path) -> str:
    """An SVG file as markup to inline into HTML (XML declaration and doctype dropped)."""
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        return f"<p class='none'>cannot read {html.escape(str(path))}: {html.escape(str(exc))}</p>"
    text = re.sub(r"^\s*<\?xml[^>]*\?>", "", text)
    return re.sub(r"^\s*<!DOCTYPE[^>[]*(\[[^]]*\])?\s*>", "", text, flags=re.I).strip()


def _changed_keys(golden: Path, actual: Path, tolerance: float) -> list[str]:
    """The element ids the semantic diff names for one failing frame."""
    from .svgdiff import diff_svg

    try:
        changes = diff_svg(golden, actual, tolerance=tolerance).changes
    except Exception:  # noqa: BLE001 - an unreadable side just gets no highlight
        return []
    return sorted({k for c in changes for k in (c.key, c.key_b) if k and re.fullmatch(r"[\w.:-]+", k)})


def _svg_size(markup: str) -> tuple[float, float]:
    """Width and height of an SVG (viewBox first), for the frame's aspect ratio; 4:3 when unknown."""
    head = markup[:2000]
    box = re.search(r'viewBox="\s*[-\d.e+]+[\s,]+[-\d.e+]+[\s,]+([\d.e+]+)[\s,]+([\d.e+]+)', head)
    try:
        w, h = (float(box.group(1)), float(box.group(2))) if box else (4.0, 3.0)
    except ValueError:
        w, h = 4.0, 3.0
    return (w, h) if w > 0 and h > 0 else (4.0, 3.0)


def _framed(markup: str, keys: list[str], label: str) -> str:
    """One drawing in a sandboxed iframe: its own document, so the two sides' stylesheets
    cannot restyle each other; the changed elements are drawn in red."""
    red = ", ".join(f'[id="{k}"]' for k in keys)
    rule = f"{red} {{ stroke: #e00000 !important; stroke-width: 3px !important; }}" if keys else ""
    doc = ("<!DOCTYPE html><html><head><meta charset='utf-8'><style>html, body { margin: 0; } "
           f"svg {{ display: block; width: 100%; height: auto; }} {rule}</style></head><body>{markup}</body></html>")
    w, h = _svg_size(markup)
    return (f"<iframe sandbox title='{html.escape(label, quote=True)}' srcdoc=\"{html.escape(doc, quote=True)}\" "
            f"style='width: 100%; aspect-ratio: {w:g} / {h:g}; border: 1px solid #ccc;'></iframe>")


def side_by_side_html(name: str, golden_root: Path, actual_root: Path, differences: list, tolerance: float) -> str:
    """A self-contained page: for each failing file its changes, then expected | actual."""
    esc = html.escape
    sections: list[str] = []
    drawn = 0
    pictured: set[str] = set()  # a layered file differing in several steps is drawn once
    for d in differences:
        g, a = golden_root / d.path, actual_root / d.path
        head = f"<h2>{esc(d.headline())}</h2>"
        listed = "\n".join(d.lines()[:MAX_REPORTED])
        body = f"<pre>{esc(listed)}</pre>" if listed else ""
        if d.kind == "svg" and d.path in pictured:
            body += "<p class='none'>(drawn above)</p>"
        elif d.kind == "svg" and drawn < MAX_PAGES:
            drawn += 1
            pictured.add(d.path)
            keys = _changed_keys(g, a, tolerance) if d.status == "changed" else []
            left = _framed(_inline_svg(g), keys, "expected") if g.exists() else "<p class='none'>(no golden)</p>"
            right = _framed(_inline_svg(a), keys, "actual") if a.exists() else "<p class='none'>(not rendered)</p>"
            body += (f"<div class='pair'><figure><figcaption>expected: {esc(str(g))}</figcaption>{left}</figure>"
                     f"<figure><figcaption>actual (rendered now)</figcaption>{right}</figure></div>")
        elif d.kind == "svg":
            body += "<p class='none'>(not drawn: the first frames are)</p>"
        sections.append(f"<section>{head}{body}</section>")
    n = len({d.path for d in differences})  # a layered file differing in several steps is one file, as in the message
    title = f"construct golden {name}: {n} file{' differs' if n == 1 else 's differ'}"
    style = ("body { font-family: 'DejaVu Sans', Arial, sans-serif; margin: 1.5em; }\n"
             "pre { background: #f6f6f6; padding: .5em; white-space: pre-wrap; }\n"
             ".pair { display: grid; grid-template-columns: 1fr 1fr; gap: 1em; }\n"
             ".pair figure { margin: 0; }\n"
             "figcaption { font-size: 90%; color: #555; overflow-wrap: anywhere; } .none { color: #999; }\n")
    return ("<!DOCTYPE html>\n<html lang='en'>\n<head>\n<meta charset='utf-8'>\n"
            f"<title>{esc(title)}</title>\n<style>\n{style}</style>\n</head>\n<body>\n"
            f"<h1>{esc(title)}</h1>\n<p>Changed elements are drawn in red on both sides. "
            f"Tolerance {tolerance:g} drawing units.</p>\n" + "\n".join(sections) + "\n</body>\n</html>\n")


# --------------------------------------------------------------------------- the fixture


@dataclass
class GoldenChecker:
    """What the ``construct_golden`` fixture gives a test: :meth:`check` a figure against its goldens."""

    goldens: Path  # the folder holding one sub-folder per checked figure
    default_name: str
    update: bool = False
    checked: list[str] = field(default_factory=list)
    #: The golden folders --construct-update wrote (listed at the end of the run).
    written: list[Path] = field(default_factory=list)

    def check(self, figure: Any, name: str | None = None, *, style: Any = "plain", frames: str = "none",
              title: tuple[str, str] | None = None, tolerance: float | None = None,
              legible: bool = True) -> Path:
        """Render *figure* (the layered final.svg, the protocol) and compare it with ``goldens/<name>/``.

        *figure* is anything with ``.protocol`` and ``.replay`` (a
        :class:`construct.constructions.Figure`).  *name* defaults to
        ``<test module>.<test name>``; *style* is a style name (``plain``, ``teaching``, ``historical``)
        or a :class:`construct.Style`; *frames* as for ``construct
        replay`` (standalone frames besides the layered figure; "none" by default: every step
        is compared from ``final.svg`` already).  With *legible* (the default) the rendered
        figure must also pass ``construct lint`` (:func:`construct.regress.lint.lint_path`): the
        test fails naming the steps and labels a reader cannot read.  Returns the goldens folder.
        """
        __tracebackhide__ = True
        from .verify import DEFAULT_TOLERANCE, compare_trees

        name = self.default_name if name is None else name
        if not isinstance(name, str) or not _NAME_RE.match(name):
            raise InvalidParameter(f"golden name must be a plain folder name (letters, digits, ._-), got {name!r}")
        if name in self.checked:
            raise InvalidParameter(f"golden {name!r} is checked twice in this test; give each figure its own name")
        self.checked.append(name)
        tol = DEFAULT_TOLERANCE if tolerance is None else tolerance
        golden_dir = self.goldens / name
        page = self.goldens.parent / FAILURES / f"{name}.html"
        with tempfile.TemporaryDirectory(prefix="construct-golden-") as tmp:
            actual = Path(tmp) / name
            render_goldens(figure, actual, style=style, frames=frames, title=title)
            illegible = _illegible(name, actual) if legible else None
            if self.update:
                _replace(golden_dir, actual)
                _remove(page)
                self.written.append(golden_dir)
                if illegible:
                    raise AssertionError(illegible)
                return golden_dir
            if not golden_dir.is_dir():
                pytest.fail(f"no goldens for {name!r} in {golden_dir}; create them with "
                            f"'pytest --construct-update' (then review and commit them)", pytrace=False)
            found, files, _ = compare_trees(golden_dir, actual, tolerance=tol)
            if not found:
                _remove(page)
                if illegible:
                    raise AssertionError(illegible)
                return golden_dir
            # Paths from the goldens folder, so that reports read "<name> step 5 (<name>/steps/005.svg)".
            diffs = [replace(d, path=f"{name}/{d.path}") for d in found]
            page.parent.mkdir(parents=True, exist_ok=True)
            page.write_text(side_by_side_html(name, self.goldens, Path(tmp), diffs, tol), encoding="utf-8")
        lines = [f"construct golden {name!r}: {len({d.path for d in diffs})} of {files} files differ from {golden_dir} "
                 f"(tolerance {tol:g} drawing units)"]
        for d in diffs[:MAX_REPORTED]:
            lines.append(d.report(MAX_REPORTED))
        if len(diffs) > MAX_REPORTED:
            lines.append(f"... and {len(diffs) - MAX_REPORTED} more files")
        lines.append(f"side by side: {page}")
        lines.append("if the change is intended, rewrite the goldens: pytest --construct-update")
        raise AssertionError("\n".join(lines))


def _illegible(name: str, rendered: Path) -> str | None:
    """The lint report of a rendered figure when it has findings (the message a test fails with), else None."""
    from .lint import lint_path

    report = lint_path(rendered)
    if report.ok:
        return None
    lines = [f"construct golden {name!r}: the figure is not legible ({len(report.findings)} findings of "
             f"'construct lint'; check(..., legible=False) skips this)"]
    lines += [f.line() for f in report.findings[:MAX_REPORTED]]
    if len(report.findings) > MAX_REPORTED:
        lines.append(f"... and {len(report.findings) - MAX_REPORTED} more")
    return "\n".join(lines)


#: What :func:`render_goldens` writes into a figure's folder.
GOLDEN_NAMES = frozenset({"final.svg", "protocol.json", "steps"})


def is_golden_folder(folder: Path) -> bool:
    """Whether *folder* holds goldens of ``construct_golden`` and nothing else (final.svg, protocol.json,
    steps/): what ``--construct-update`` may replace."""
    names = set(os.listdir(folder))
    return "final.svg" in names and names <= GOLDEN_NAMES


def _replace(golden_dir: Path, rendered: Path) -> None:
    """Put the rendered folder in place of the goldens as a whole (no stale frames survive);
    a folder that holds anything else is refused and left as it is."""
    from ..io.staging import replaced_folder

    with replaced_folder(golden_dir, recognise=is_golden_folder, what="goldens folder",
                         described="a goldens folder of construct_golden (final.svg, protocol.json, steps/)") as new:
        shutil.copytree(rendered, new)


def _remove(page: Path) -> None:
    """Remove a failure page, and its folder when that is left empty (nothing to review, nothing to ignore)."""
    try:
        os.remove(page)
    except FileNotFoundError:
        pass
    try:
        page.parent.rmdir()
    except OSError:  # not empty (another figure's page), or not there
        pass


#: Where the goldens the session wrote are collected for the summary.
_WRITTEN = pytest.StashKey[list]()


def pytest_configure(config: pytest.Config) -> None:
    config.stash[_WRITTEN] = []


def pytest_terminal_summary(terminalreporter: Any, exitstatus: int, config: pytest.Config) -> None:
    """With --construct-update: which golden folders were written, and what each holds."""
    written = config.stash.get(_WRITTEN, [])
    if not written:
        return
    terminalreporter.section("construct goldens written")
    for folder in written:
        files = sorted(str(p.relative_to(folder)) for p in folder.rglob("*") if p.is_file())
        terminalreporter.write_line(f"{folder}: {', '.join(files)}")
    terminalreporter.write_line("review them (git diff) and commit them with the change")


@pytest.fixture
def construct_golden(request: pytest.FixtureRequest) -> GoldenChecker:
    """Compare figures with golden SVG frames: ``construct_golden.check(figure, name="...")``."""
    folder = request.config.getini("construct_goldens") or "goldens"
    return GoldenChecker(goldens=Path(request.node.path).parent / folder,
                         # module and test: two test files of one folder may hold tests of one name
                         default_name=f"{safe_name(Path(request.node.path).stem)}.{safe_name(request.node.name)}",
                         update=bool(request.config.getoption("construct_update")),
                         written=request.config.stash.get(_WRITTEN, []))
