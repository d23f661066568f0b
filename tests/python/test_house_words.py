"""The repository speaks to its users and maintainers only: no tracked file (code, docs, tests, benchmarks,
their names) mentions an issue number, a scratch build folder, a person by role letter, or notes and designs
that are not in the repository. Theory is cited by author and title (docs/references.md).

Reads `git ls-files` of the checkout holding this file, or of the tree named by the environment variable
RIGIDDYN_HOUSE_WORDS_ROOT; needs no build (it never imports rigiddyn). Skipped outside a git checkout."""

import os
import re
import subprocess
from pathlib import Path

import pytest

# (what it is, the pattern): each a mention that means something only to whoever wrote it
FORBIDDEN = [
    ("an issue number", re.compile(r"issues?[ _#-]{0,2}[0-9]+|\(issues?\b", re.IGNORECASE)),
    ("a scratch build folder", re.compile(r"\bbuild/(lead|[A-Z])(?![\w.<-])")),
    ("a person by role letter", re.compile(r"\b[Ee]ngineer [A-Z]\b")),
    ("notes outside the repository", re.compile(r"shared/(design|notes|seeds)\b|\.\./shared\b")),
]

THIS_FILE = Path(__file__).resolve()


def checkout_root() -> Path:
    """The tree to read: RIGIDDYN_HOUSE_WORDS_ROOT if set, else the checkout holding this file."""
    return Path(os.environ.get("RIGIDDYN_HOUSE_WORDS_ROOT", THIS_FILE.parents[2])).resolve()


def tracked_files(root: Path) -> list[str]:
    """The paths `git ls-files` lists under root (relative to it); skips the test outside a git checkout."""
    try:
        listed = subprocess.run(["git", "-C", str(root), "ls-files", "-z"], capture_output=True, timeout=60,
                                check=False)
    except (OSError, subprocess.TimeoutExpired) as error:  # no git on this machine
        pytest.skip(f"git ls-files could not run: {error}")
    if listed.returncode != 0:
        pytest.skip(f"{root} is not a git checkout")
    return [name for name in listed.stdout.decode("utf-8", "surrogateescape").split("\0") if name]


def hits_in(root: Path, name: str) -> list[str]:
    """Each forbidden mention in the file's path or text, as "path:line: what: the line"."""
    found = [f"{name}:0: {what} in the file name" for what, pattern in FORBIDDEN if pattern.search(name)]
    path = root / name
    if not path.is_file() or path.resolve() == THIS_FILE:
        return found
    data = path.read_bytes()
    if b"\0" in data:  # a binary file
        return found
    for number, line in enumerate(data.decode("utf-8", "replace").splitlines(), start=1):
        found += [f"{name}:{number}: {what}: {line.strip()[:160]}" for what, pattern in FORBIDDEN
                  if pattern.search(line)]
    return found


def test_no_tracked_file_mentions_issues_scratch_folders_or_outside_notes():
    root = checkout_root()
    hits = [hit for name in tracked_files(root) for hit in hits_in(root, name)]
    assert not hits, f"{len(hits)} mention(s) meant for the authors only:\n" + "\n".join(hits)


# The words themselves are filled in when the test runs, so that this file does not carry them either.
WORDS = {"issue": "issue", "engineer": "engineer", "scratch": "lead", "letter": "F", "outside": "../shared"}


@pytest.mark.parametrize("template, what", [
    ("// golden states ({issue} 11, item 0): the refactoring", "an issue number"),
    ("tests/python/test_{issue}12_api.py", "an issue number"),
    ("the scene pipeline's {issue}-12 parts", "an issue number"),
    ("see {issue} #7", "an issue number"),
    ("the SIMD path ({engineer} B's file)", "a person by role letter"),
    ("valgrind build/{scratch}/bench/bench_simd", "a scratch build folder"),
    ("PYTHONPATH=build/{letter}/python python3 bench/python/bench_scene.py", "a scratch build folder"),
    ("cmake --build build/{letter} --target bench_scene", "a scratch build folder"),
    ("(Landau & Lifshitz §37; {outside}/notes/free-rigid-body.md)", "notes outside the repository"),
])
def test_each_pattern_finds_what_it_names(template, what):
    line = template.format(**WORDS)
    assert [name for name, pattern in FORBIDDEN if pattern.search(line)] == [what]


@pytest.mark.parametrize("line", [
    "rng = np.random.default_rng(seed)",
    "a known issue of the compiler: see https://github.com/org/repo/issues/123",
    "an engineer can read it",
    "build/py/python and build/<dir>/bench/bench_scene",
])
def test_ordinary_words_pass(line):
    assert not [name for name, pattern in FORBIDDEN if pattern.search(line)]
