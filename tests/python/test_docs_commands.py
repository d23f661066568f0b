"""Every command line the README and the docs print runs as printed and exits 0.

The commands are found, not listed: each line of a code block (fenced or indented) and each inline code
span of README.md and docs/**/*.md that is a `python3 -m rigiddyn ...` or `rigiddyn ...` command (after
`&&`, without a trailing `# comment`). Each runs exactly as printed (none takes more than seconds), in a
fresh temporary folder, as a reader would run it from their own folder.
"""

import pathlib
import re
import shlex
import shutil
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
DOCS = [path for path in DOCS if "_build" not in path.parts]

COMMAND = re.compile(r"^(?:python3? -m )?rigiddyn [a-z-]")  # a subcommand or an option follows
# a placeholder of a command -> the names it stands for (the shipped scenes of the section that prints it)
PLACEHOLDERS = {"<name>": ("pendulum", "heavy_top", "foucault", "rocket")}
# a file a command names that the reader has written: a copy of the shipped file it was modelled on
READER_FILES = {"my_problem.toml": ROOT / "python/rigiddyn/problems/t_handle.toml"}


def _commands_in(text: str) -> list[str]:
    """The rigiddyn command lines of a markdown text: lines of fenced and indented code blocks, inline
    code spans."""
    found = []
    for block in re.findall(r"^```[^\n]*\n(.*?)^```", text, flags=re.DOTALL | re.MULTILINE):
        for line in block.splitlines():
            found += [part.strip() for part in line.split("&&")]
    text = re.sub(r"^```[^\n]*\n.*?^```", "", text, flags=re.DOTALL | re.MULTILINE)
    found += [line.strip() for line in re.findall(r"^(?: {4}|\t)(.+)$", text, flags=re.MULTILINE)]
    found += [" ".join(span.split()) for span in re.findall(r"`([^`]+)`", text)]  # a span may wrap a line
    commands = []
    for command in found:
        command = command.split(" #", 1)[0].strip()
        if COMMAND.match(command):
            commands.append(command)
    return commands


def doc_commands() -> list[tuple[str, str]]:
    """(file, command) of every command the docs print, each once, placeholders expanded."""
    out: dict[str, str] = {}
    for path in DOCS:
        for command in _commands_in(path.read_text(encoding="utf-8")):
            expanded = [command]
            for placeholder, names in PLACEHOLDERS.items():
                if placeholder in command:
                    expanded = [c.replace(placeholder, name) for c in expanded for name in names]
            for c in expanded:
                out.setdefault(c, str(path.relative_to(ROOT)))
    return [(where, command) for command, where in out.items()]


def test_the_docs_print_the_commands_this_file_knows():
    """The extraction finds the commands (a parser that found none would pass every test below)."""
    commands = {command for _, command in doc_commands()}
    assert "python3 -m rigiddyn simulate rocket" in commands
    assert "python3 -m rigiddyn tradeoff pendulum" in commands
    assert "python3 -m rigiddyn tradeoff --help" in commands  # the comment after it dropped
    assert "python3 -m rigiddyn tradeoff t_handle --out tradeoff-t_handle" in commands  # after "pip install ... &&"
    assert "python3 -m rigiddyn tradeoff heavy_top" in commands  # "<name>", wrapped over two lines
    unknown = [c for c in commands if any(p in c for p in PLACEHOLDERS) or re.search(r"<\w+>", c)]
    assert not unknown, unknown


@pytest.mark.parametrize("where,command", doc_commands(), ids=lambda x: x)
def test_the_command_runs_as_printed(tmp_path, where, command):
    argv = shlex.split(command)
    argv = argv[3:] if argv[0].startswith("python") else argv[1:]  # after "python3 -m rigiddyn" or "rigiddyn"
    for name, source in READER_FILES.items():
        if name in argv:
            shutil.copy(source, tmp_path / name)
    # a generous timeout: it only catches a hang (the longest command takes seconds)
    done = subprocess.run([sys.executable, "-m", "rigiddyn", *argv], cwd=tmp_path, capture_output=True, text=True,
                          timeout=900)
    assert done.returncode == 0, f"{where}: {command}\n{done.stderr[-2000:]}"
    if argv[0] == "simulate" and "--help" not in argv:  # the folder it says it wrote
        folder = re.search(r"^wrote .* to (.+)$", done.stdout, flags=re.MULTILINE).group(1)
        assert (tmp_path / folder / "trajectory.csv").is_file()
