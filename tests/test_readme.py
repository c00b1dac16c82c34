"""The README's promises: its two commands, and its library example runs as written."""

import doctest
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def shell_blocks():
    return re.findall(r"```sh\n(.*?)```", (ROOT / "README.md").read_text(encoding="utf-8"), re.S)


def test_readme_starts_with_the_two_commands():
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    first_two = shell_blocks()[:2]
    assert "construct gallery" in first_two[0] and "pip install" in first_two[0]
    assert "pytest" in first_two[1] and "pip install" in first_two[1]
    assert text.index("```sh") < text.index("## ")  # before any section


def test_ci_runs_the_readmes_test_command_verbatim():
    command = shell_blocks()[1].strip()
    lines = [l for l in (ROOT / ".ci" / "run").read_text().splitlines() if l and not l.startswith("#")]
    assert command in lines


def test_readme_library_example():
    result = doctest.testfile(str(ROOT / "README.md"), module_relative=False,
                              optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.attempted >= 5 and result.failed == 0
