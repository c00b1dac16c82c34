"""The README's promises: its two commands, and its library example runs as written."""

import doctest
import os
import re
from pathlib import Path

import pytest

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
    """.ci/run runs the README's test command as written and nothing the README does not name: after it, the
    speed guard, which the README names beside the command."""
    command = shell_blocks()[1].strip()
    lines = [l for l in (ROOT / ".ci" / "run").read_text().splitlines() if l and not l.startswith("#")]
    assert command in lines
    after = lines[lines.index(command) + 1:]
    assert after == ["construct bench --guard"], after
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    assert all(f"`{line}`" in text[:text.index("## ")] for line in after)  # named where the command is


def test_readme_library_example():
    result = doctest.testfile(str(ROOT / "README.md"), module_relative=False,
                              optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.attempted >= 5 and result.failed == 0


def test_readme_renders_as_written():
    """Every heading of the source renders as a heading, and no prose is swallowed by an open code fence.

    A fence left open turns the rest of the file inside out: headings become code and code becomes prose.
    CommonMark (markdown-it-py) is what GitHub and most renderers implement.
    """
    from markdown_it import MarkdownIt

    text = (ROOT / "README.md").read_text(encoding="utf-8")
    tokens = MarkdownIt("commonmark").parse(text)
    rendered = [tokens[i + 1].content for i, t in enumerate(tokens) if t.type == "heading_open"]
    written = [m.group(1) for m in re.finditer(r"^#{1,6} (.+)$", text, re.M)
               if not _inside_fence(text, m.start())]
    assert rendered == written
    assert rendered and all(f"# {h}" in text for h in rendered)
    code = [t for t in tokens if t.type in ("fence", "code_block")]
    assert not [t.content for t in code if re.search(r"^#{2,6} [A-Z]", t.content, re.M)], "a heading rendered as code"
    assert text.count("```") % 2 == 0


def _inside_fence(text: str, offset: int) -> bool:
    """Whether *offset* lies between an opening and a closing ``` line (counted as a reader counts them)."""
    return len(re.findall(r"^```", text[:offset], re.M)) % 2 == 1


# --------------------------------------------------------------------------
# Every shell line of the README, run as written.

import shlex

#: The two install blocks: CI runs the second verbatim (test above); they install, which a test cannot.
INSTALL_BLOCKS = 2
#: Commands whose exit 1 reports a finding, not a broken example (lint findings, drawings that differ, a missed
#: speed target).
FINDINGS = ("lint", "diff", "bench")
#: The benchmarks time themselves for minutes: their lines are parsed here and run when CONSTRUCT_README_BENCH=1.
SLOW = ("bench",)


def commands(block: str) -> list[str]:
    """The commands of one ```sh block: continuation lines joined, comments and comment-only lines dropped."""
    joined = block.replace("\\\n", " ")
    out = []
    for line in joined.splitlines():
        words = shlex.split(line, comments=True)
        if words:
            out.append(shlex.join(words))
    return out


def construct_blocks() -> list[list[str]]:
    return [commands(b) for b in shell_blocks()[INSTALL_BLOCKS:] if commands(b)]


#: The README's line that writes the sample cards into ./examples, as a reader runs it before the examples.
SAMPLES = "construct samples examples"


def reads_samples(block: list[str]) -> bool:
    return any(word.startswith("examples/") for c in block for word in shlex.split(c))


def test_every_shell_line_is_a_command_this_file_runs():
    """No placeholder (E, F, D), no optional part in brackets ([--json]), no file the package does not ship: a card
    a line reads is one `construct samples` writes into examples/, and the README says so before any line reads it."""
    from construct.io.samples import SAMPLES as CARDS

    lines = [c for block in construct_blocks() for c in block]
    assert lines and all(c.split()[0] in ("construct", "pytest") for c in lines), lines
    assert not [c for c in lines if "[" in c or " E " in c or c.endswith((" D", " N", " F", " R"))]
    for c in lines:
        for word in shlex.split(c):
            if word.endswith(".csv"):
                assert word.startswith("examples/") and word.removeprefix("examples/") in CARDS, word
    first = next(i for i, c in enumerate(lines) if reads_samples([c]))
    assert SAMPLES in lines[:first], "the first example that reads a sample card comes before the line writing them"
    assert not (ROOT / "examples").exists()   # the top level is the user's: the cards are package data


@pytest.mark.parametrize("block", range(len(construct_blocks())))
def test_readme_commands_run_as_written(block, tmp_path, monkeypatch, capsys):
    """Each block's commands in order, in a fresh folder: exit 0 (1 only for a finding of lint or bench), and what
    they write stays in that folder.  A block that reads the sample cards and does not write them itself runs the
    README's `construct samples examples` first, as a reader who followed the README from the top has."""
    from construct.cli.main import build_parser, main

    monkeypatch.chdir(tmp_path)
    lines = construct_blocks()[block]
    if reads_samples(lines) and SAMPLES not in lines:
        lines = [SAMPLES, *lines]
    for command in lines:
        argv = shlex.split(command)
        if argv[0] == "pytest":
            continue   # the golden walkthrough: tests/test_regress_pytest_plugin.py runs it as the README says
        if argv[1] in SLOW and not os.environ.get("CONSTRUCT_README_BENCH"):
            build_parser().parse_args(argv[1:])   # the line parses; timing it is bench's own business
            continue
        code = main(argv[1:])
        out, err = capsys.readouterr()
        allowed = (0, 1) if argv[1] in FINDINGS else (0,)
        assert code in allowed, f"{command}: exit {code}\n{err[-2000:]}"
