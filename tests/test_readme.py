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
