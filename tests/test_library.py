"""The front door: one import builds, replays, draws and checks; protocols load with nothing else imported."""

from __future__ import annotations

import ast
import collections
import functools
import gc
import json
import subprocess
import sys
from pathlib import Path

import pytest

import construct

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "construct"


def test_public_names_exist_and_are_documented():
    assert construct.__doc__ and construct.__version__
    for name in construct.__all__:
        assert hasattr(construct, name), name
    for name in ("Builder", "Figure", "Protocol", "get", "nearer", "farther", "toward", "left_of", "StepError",
                 "NoIntersection", "Check", "Style"):
        assert name in construct.__all__


def test_every_error_and_warning_is_at_the_front_door():
    """What the library raises or warns, a user catches with one import (InputFileError was missing once)."""
    import inspect

    from construct.kernel import errors

    kinds = [c for _, c in inspect.getmembers(errors, inspect.isclass)
             if c.__module__ == errors.__name__ and issubclass(c, (errors.ConstructError, Warning))]
    assert len(kinds) >= 17
    assert [c.__name__ for c in kinds if getattr(construct, c.__name__, None) is not c
            or c.__name__ not in construct.__all__] == []


def test_what_a_figure_gives_and_takes_is_at_the_front_door():
    import construct.constructions.checking
    import construct.render.styles

    fig = construct.get("crank").figure(parts=6)
    assert type(fig.checks()[0]) is construct.Check is construct.constructions.checking.Check
    assert construct.Style is construct.render.styles.Style
    assert {"Check", "Style", "testing"} <= set(dir(construct))


def test_old_names_still_work_and_say_what_to_use():
    fig = construct.get("crank").figure(parts=6)
    with pytest.warns(DeprecationWarning, match="figure.svg"):
        svg = construct.svg(fig, style="plain")
    assert svg == fig.svg(style="plain")
    with pytest.warns(DeprecationWarning, match=r"figure.write\(out\)"), pytest.raises(construct.InvalidParameter):
        construct.write_replay(fig, "unused", frames="x")
    with pytest.raises(AttributeError):
        construct.no_such_name  # noqa: B018


def test_every_public_builder_method_has_a_runnable_example():
    missing = [name for name, fn in vars(construct.Builder).items()
               if callable(fn) and not name.startswith("_") and ">>>" not in (fn.__doc__ or "")]
    assert not missing, missing


FRESH = r"""
import glob, json, sys
import construct
from construct.kernel.protocol import object_json

def close(a, b):
    if isinstance(a, float):
        return abs(a - b) <= 1e-12 * max(1.0, abs(b))
    if isinstance(a, list):
        return len(a) == len(b) and all(close(x, y) for x, y in zip(a, b))
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(close(a[k], b[k]) for k in a)
    return a == b

count = 0
for path in sorted(glob.glob(sys.argv[1] + "/*/protocol.json")):
    text = open(path, encoding="utf-8").read()
    stored = json.loads(text)["objects"]
    replay = construct.Protocol.from_json(text).replay()
    for name, want in stored.items():
        got = object_json(replay[name])
        assert close(got, want), (path, name, got, want)
    assert set(replay) == set(stored), path
    count += 1
books = ("crank", "inertia", "indicator", "piston_force", "tangential", "two_cranks")
assert [m for m in sys.modules if m.startswith("construct.constructions.") and m.split(".")[2] in books] == [], \
    "constructions imported"
print(count)
"""


def test_a_fresh_process_loads_and_replays_every_gallery_protocol():
    out = subprocess.run([sys.executable, "-c", FRESH, str(ROOT / "gallery")], capture_output=True, text=True,
                         cwd=ROOT)
    assert out.returncode == 0, out.stderr[-2000:]
    assert int(out.stdout) >= 8


def test_a_custom_protocol_replays_and_checks_through_the_cli(tmp_path, cli):
    """In this process (``cli``): what a real process adds, the exit status and stderr without a traceback, is
    tests/test_hostile.py's and test_fuzz.py's."""
    b = construct.Builder("third of a segment", givens={"s": 3.0})
    b.given_point("A", 0.0, 0.0)
    b.given_point("B", 1.0, 0.0, unit="s")
    b.divide_segment("T", "A", "B", 3)
    fig = b.figure()
    path = tmp_path / "mine.json"
    path.write_text(fig.protocol.to_json(fig.replay), encoding="utf-8")
    code, _, err = cli("replay", "--protocol", path, "--given", "s=6", "--out", tmp_path / "o")
    assert code == 0, err
    written = json.loads((tmp_path / "o" / "protocol.json").read_text(encoding="utf-8"))
    assert abs(written["objects"]["T1"]["x"] - 2.0) <= 1e-12  # a third of 6, from the replayed steps
    assert (tmp_path / "o" / "final.svg").exists()
    code, out, _ = cli("check", "--protocol", path)
    assert code == 0 and "no checks" in out
    code, _, err = cli("replay", "--protocol", path, "--given", "q=1", "--out", tmp_path / "p")
    assert code == 2 and "no given 'q'" in err and "Traceback" not in err
    assert not (tmp_path / "p").exists()


def test_library_calls_leave_process_state_alone():
    import matplotlib

    backend = matplotlib.get_backend()
    enabled = gc.isenabled()
    fig = construct.get("crank").figure(parts=6)
    fig.protocol.replay({"r": 1.0, "rod_ratio": 4.0})
    fig.svg(style="teaching")
    assert gc.isenabled() == enabled and matplotlib.get_backend() == backend


# -- layers ------------------------------------------------------------------------------------------

#: The layers from the bottom up: a module may import from its own layer and those below it, never above --
#: at module level or inside a function.  Each layer is a list of module prefixes.
LAYERS = [
    ("kernel", ["construct.kernel"]),
    ("io", ["construct.io"]),
    ("render", ["construct.render"]),
    ("figure", ["construct.figure"]),
    ("constructions", ["construct.constructions"]),
    ("live", ["construct.live"]),
    ("books", ["construct.books"]),
    ("tables", ["construct.tables"]),
    ("gallery", ["construct.gallery"]),
    ("regress", ["construct.regress"]),
    ("cli", ["construct.cli", "construct.__main__"]),
    ("front door", ["construct", "construct.testing"]),
]


def _layer(module: str) -> int:
    best = max((len(prefix), i) for i, (_, prefixes) in enumerate(LAYERS) for prefix in prefixes
               if module == prefix or module.startswith(prefix + "."))
    return best[1]


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


@functools.lru_cache(maxsize=None)
def _parse(source: str) -> ast.Module:
    """A module's syntax tree, parsed once for the layer, circle and private-name tests (read, never changed)."""
    return ast.parse(source)


#: The fields of a node that hold statements (a function's, a class's, a branch's, a handler's, a case's body).
_BODIES = ("body", "orelse", "finalbody", "handlers", "cases")


def _statements(tree: ast.AST):
    """Every statement of *tree* at any depth, in the order ast.walk meets them: an import is a statement, so the
    expressions (most of a module's nodes) are not walked."""
    todo = collections.deque([tree])
    while todo:
        node = todo.popleft()
        yield node
        for field in _BODIES:
            todo.extend(getattr(node, field, ()))


def _imports(path: Path, text: str | None = None) -> list[tuple[str, int]]:
    """The construct-internal modules a file imports, anywhere in it: at module level, inside functions and
    under ``if TYPE_CHECKING:`` (read by type checkers only, but still an arrow a reader follows: the layers
    and the circles count them too).

    *text* is the file's source (read from *path* when None; *path* places it in the package).
    ``from package import name`` names the module package.name when there is one, else the package.
    """
    tree = _parse(path.read_text(encoding="utf-8") if text is None else text)
    pkg = path.relative_to(ROOT).with_suffix("").parts[:-1]
    out = []
    for node in _statements(tree):
        if isinstance(node, ast.ImportFrom) and (node.level or (node.module or "").startswith("construct")):
            if node.level:
                base = list(pkg[: len(pkg) - node.level + 1])
                target = ".".join(base + (node.module.split(".") if node.module else []))
            else:
                target = node.module
            out += [(f"{target}.{a.name}" if f"{target}.{a.name}" in _MODULES else target, node.lineno)
                    for a in node.names]
        elif isinstance(node, ast.Import):
            out += [(a.name, node.lineno) for a in node.names if a.name.startswith("construct")]
    return out


#: Every module of the package by its dotted name.
_MODULES = {".".join(p.relative_to(ROOT).with_suffix("").parts[:-1] if p.name == "__init__.py"
                     else p.relative_to(ROOT).with_suffix("").parts): p for p in PACKAGE.rglob("*.py")}


def _circles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The groups of modules that import one another round a circle (strongly connected, more than one)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    out = []
    for root in sorted(graph):  # Tarjan's algorithm, without recursion
        if root in index:
            continue
        work = [(root, iter(sorted(graph.get(root, ()))))]
        index[root] = low[root] = len(index)
        stack.append(root)
        while work:
            v, edges = work[-1]
            w = next(edges, None)
            if w is not None:
                if w not in index:
                    index[w] = low[w] = len(index)
                    stack.append(w)
                    work.append((w, iter(sorted(graph.get(w, ())))))
                elif w in stack:
                    low[v] = min(low[v], index[w])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                group = []
                while True:
                    w = stack.pop()
                    group.append(w)
                    if w == v:
                        break
                if len(group) > 1:
                    out.append(sorted(group))
    return out


def _import_graph() -> dict[str, set[str]]:
    return {name: {t for t, _ in _imports(path) if t in _MODULES and t != name} for name, path in _MODULES.items()}


def test_every_module_sits_in_a_layer():
    for path in sorted(PACKAGE.rglob("*.py")):
        _layer(_module_name(path))  # raises ValueError (max of nothing) for a module no layer names


def test_no_module_imports_a_layer_above_it():
    bad = []
    for path in sorted(PACKAGE.rglob("*.py")):
        here = _layer(_module_name(path))
        for target, line in _imports(path):
            if target.split(".")[0] == "construct" and _layer(target) > here:
                bad.append(f"{path.relative_to(ROOT)}:{line} imports {target} "
                           f"({LAYERS[here][0]} -> {LAYERS[_layer(target)][0]})")
    assert not bad, "\n".join(bad)


def test_the_layer_test_sees_imports_inside_functions():
    """A kernel function that loads the renderer is an arrow upward, and the test must see it."""
    probe = PACKAGE / "kernel" / "_probe_for_layer_test.py"  # read as if it were there; nothing is written
    text = "def f():\n    from ..render import svg\n    return svg\n"
    targets = [t for t, _ in _imports(probe, text)]
    assert targets == ["construct.render.svg"] and _layer(targets[0]) > _layer("construct.kernel.ops")


def test_the_layer_test_sees_typing_only_imports():
    """An import under TYPE_CHECKING is an arrow too: a renderer typed against a construction depends on it."""
    probe = PACKAGE / "render" / "_probe_for_layer_test.py"  # read as if it were there; nothing is written
    text = "from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from ..constructions import Construction\n"
    assert [t for t, _ in _imports(probe, text)] == ["construct.constructions"]


def test_no_modules_import_one_another_round_a_circle():
    """Inside a layer too: no module imports one that imports it back, directly or round a longer circle."""
    circles = _circles(_import_graph())
    assert not circles, "\n".join(" -> ".join(c) for c in circles)


def test_the_circle_test_sees_a_circle():
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a", "d"}, "d": set(), "e": {"e"}}
    assert _circles(graph) == [["a", "b", "c"]]


def test_the_top_of_the_package_holds_few_modules():
    """Everything but the front door (with its test helpers, construct.testing, as shapely.testing), the entry
    point and a few cross-layer modules lives in a package."""
    loose = sorted(p.name for p in PACKAGE.glob("*.py") if p.name not in ("__init__.py", "__main__.py", "testing.py"))
    assert len(loose) <= 3, loose


# -- private names ----------------------------------------------------------------------------------

#: Packages whose modules may still import ``_private`` names from one another: none.
PRIVATE_IMPORTS_ALLOWED_IN: tuple[str, ...] = ()


def _private_imports(source: str) -> list[tuple[int, str, str]]:
    """(line, module, name) of every ``from construct... import _name`` in *source*, inside functions too.

    A name with a leading underscore is its module's own business; what two modules share is public.
    Dunder names (``__version__``) are not private.
    """
    out = []
    for node in ast.walk(_parse(source)):
        if isinstance(node, ast.ImportFrom) and (node.level or (node.module or "").startswith("construct")):
            module = "." * node.level + (node.module or "")
            out += [(node.lineno, module, a.name) for a in node.names
                    if a.name.startswith("_") and not (a.name.startswith("__") and a.name.endswith("__"))]
    return out


def test_no_private_name_is_imported_from_another_module():
    bad = []
    for path in sorted(PACKAGE.rglob("*.py")):
        rel = path.relative_to(ROOT).as_posix()
        if rel.startswith(PRIVATE_IMPORTS_ALLOWED_IN):
            continue
        bad += [f"{rel}:{line} imports {name} from {module}"
                for line, module, name in _private_imports(path.read_text(encoding="utf-8"))]
    assert not bad, "\n".join(bad)


def test_the_private_import_test_sees_what_it_must():
    source = ("from .values import _fmt, show_value\n"
              "from construct.kernel import __version__\n"
              "import os.path\n"
              "from os import _exit\n"
              "def f():\n"
              "    from ..match import _bbox as box\n")
    assert _private_imports(source) == [(1, ".values", "_fmt"), (6, "..match", "_bbox")]


def test_no_unused_import_and_no_name_defined_twice():
    """pyflakes finds nothing in the package and the tests: no unused import (a layer crossed for nothing), no
    class or function defined twice (the second silently replaces the first).  pyflakes is a test dependency (the
    package's ``test`` extra); where it is missing the test is skipped."""
    api = pytest.importorskip("pyflakes.api")
    from pyflakes.reporter import Reporter
    import io

    out, err = io.StringIO(), io.StringIO()
    found = api.checkRecursive([str(PACKAGE), str(ROOT / "tests")], Reporter(out, err))
    assert found == 0 and not err.getvalue(), out.getvalue() + err.getvalue()
