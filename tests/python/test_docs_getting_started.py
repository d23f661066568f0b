"""The prose pages of the documentation site (docs/getting_started.md, docs/guide/*.md, docs/cpp.md)
say what the code does:

- every command block marked `% same as README.md` (a MyST comment line right above the fence) is
  the README's, literally (whitespace aside), and the README's two set-up commands are on the
  getting-started page;
- every ```python block (and matplotlib's `.. plot::` directive in an ```{eval-rst} block: the code
  shown with its figure, made by the build) of docs/index.md,
  docs/getting_started.md, docs/conventions.md and docs/guide/*.md runs as written: the blocks of a page
  in order, in one namespace (as a reader runs them in one session), in a scratch folder, each with the
  asserts of what the text claims (their bounds are argued next to them on the page); a ```text block
  right below a `% printed by the block above` line is what the block above it prints, literally;
- the methods table of docs/guide/models_integrators.md is rigiddyn.methods();
- docs/cpp.md describes every layer folder of cpp/include/rigiddyn/ and includes files that exist.
"""

from __future__ import annotations

import contextlib
import io
import math
import pathlib
import re
import sys
import textwrap

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
README = (ROOT / "README.md").read_text()
GUIDE_PAGES = sorted((DOCS / "guide").glob("*.md"))
PROSE_PAGES = [DOCS / "getting_started.md", *GUIDE_PAGES]
RUN_PAGES = [DOCS / "index.md", DOCS / "getting_started.md", DOCS / "conventions.md",
             *[p for p in GUIDE_PAGES if p.name != "index.md"]]
README_MARK = "% same as README.md"
PRINTED_MARK = "% printed by the block above"


def fenced_blocks(text: str, language: str) -> list[str]:
    """The bodies of the ```<language> blocks of a Markdown text, in order."""
    return re.findall(rf"^```{language}\n(.*?)^```", text, flags=re.DOTALL | re.MULTILINE)


def runnable_blocks(text: str) -> list[tuple[str, str | None]]:
    """The ```python blocks and the code of the `.. plot::` directives in ```{eval-rst} blocks of a Markdown
    text, in order, each with what it prints: the body of the ```text block right below a PRINTED_MARK
    line that follows it, or None where no such block does."""
    blocks: list[tuple[str, str | None]] = []
    end = 0
    for fence in re.finditer(r"^```([^\n]*)\n(.*?)^```", text, flags=re.DOTALL | re.MULTILINE):
        info, body = fence.group(1).strip(), fence.group(2)
        line_above = text[end:fence.start()].rstrip("\n").rsplit("\n", 1)[-1]
        end = fence.end()
        plot = re.fullmatch(r"\.\. plot::\n(?:   :[\w-]+:[^\n]*\n)*\n?(.*)", body, flags=re.DOTALL)
        if info == "python" or (info == "{eval-rst}" and plot):
            blocks.append((body if info == "python" else textwrap.dedent(plot.group(1)), None))
        elif line_above == PRINTED_MARK:
            assert info == "text" and blocks and blocks[-1][1] is None, \
                f"{PRINTED_MARK!r} above a ```{info} block that follows no runnable block, or a second one"
            blocks[-1] = (blocks[-1][0], body)
    return blocks


def marked_blocks(text: str) -> list[str]:
    """The bodies of the fenced blocks right below a `% same as README.md` line."""
    return re.findall(rf"^{re.escape(README_MARK)}\n```\w*\n(.*?)^```", text, flags=re.DOTALL | re.MULTILINE)


def words(text: str) -> str:
    return " ".join(text.split())


@pytest.mark.parametrize("page", [DOCS / "getting_started.md", DOCS / "cpp.md"], ids=lambda p: p.name)
def test_blocks_claimed_from_the_readme_are_in_it(page: pathlib.Path) -> None:
    blocks = marked_blocks(page.read_text())
    assert blocks, f"{page.name}: no block marked {README_MARK!r}"
    for block in blocks:
        # whitespace aside: the README wraps the install command of the C++ section over two lines
        assert words(block) in words(README), f"{page.name}: not in README.md:\n{block}"


def test_the_readme_set_up_commands_are_on_the_getting_started_page() -> None:
    set_up = README.split("## Set-up: two commands", 1)[1].split("\n## ", 1)[0]
    commands = fenced_blocks(set_up, "bash")[:2]  # the two commands; the section then shows `simulate`
    assert any("pip install" in c for c in commands) and any("run_all.sh" in c for c in commands), commands
    on_page = marked_blocks((DOCS / "getting_started.md").read_text())
    for command in commands:
        assert command in on_page, f"getting_started.md lacks the README's set-up command:\n{command}"


def test_every_topic_page_has_python_blocks() -> None:
    assert [p.name for p in PROSE_PAGES if not fenced_blocks(p.read_text(), "python")] == ["index.md"]


@pytest.mark.parametrize("page", RUN_PAGES, ids=lambda p: str(p.relative_to(DOCS)))
def test_python_blocks_run_as_written(page: pathlib.Path, tmp_path: pathlib.Path,
                                      monkeypatch: pytest.MonkeyPatch) -> None:
    blocks = runnable_blocks(page.read_text())
    assert blocks, f"{page.name}: no ```python block or plot directive"
    monkeypatch.chdir(tmp_path)  # files the blocks write (plots) go to a scratch folder
    monkeypatch.setenv("MPLBACKEND", "Agg")
    namespace: dict[str, object] = {"__name__": "__docs__"}
    for i, (block, printed) in enumerate(blocks):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(compile(block, f"{page.relative_to(DOCS)}, python block {i + 1}", "exec"), namespace)
        if printed is not None:
            assert out.getvalue() == printed, f"{page.name}, block {i + 1} printed:\n{out.getvalue()}"
    plt = sys.modules.get("matplotlib.pyplot")
    if plt is not None:
        plt.close("all")


def test_printed_output_is_marked_below_a_runnable_block() -> None:
    text = ("```python\nprint(1)\n```\n\n" + PRINTED_MARK + "\n```text\n1\n```\n\n"
            "```{eval-rst}\n.. plot::\n   :context:\n\n   x = 2\n   if x:\n       y = 3\n```\n"
            "```{eval-rst}\n.. note:: not code\n```\n")
    assert runnable_blocks(text) == [("print(1)\n", "1\n"), ("x = 2\nif x:\n    y = 3\n", None)]
    with pytest.raises(AssertionError, match="follows no runnable block"):
        runnable_blocks(PRINTED_MARK + "\n```text\n1\n```\n")


def _limit_text(limit: float) -> str:
    """The page's spelling of a stability limit (dt |w| [rad])."""
    if math.isinf(limit):
        return "∞"
    return "0 (never)" if limit == 0 else f"{limit:.3g}"


def test_methods_table_is_methods() -> None:
    import rigiddyn as rd

    text = (DOCS / "guide" / "models_integrators.md").read_text()
    header = "| method | order | evaluations per step | conserves | stability limit (dt·\\|ω\\|) |"
    assert header in text
    table = text.split(header, 1)[1].split("\n\n", 1)[0].strip().splitlines()[1:]  # after the |---| line

    def row(m: dict) -> str:
        conserves = m["conserves"].replace("|", "\\|")  # a Markdown table cell escapes "|"
        limit = _limit_text(m["stability_limit"])
        return f"| `{m['name']}` | {m['order']} | {m['evaluations']} | {conserves} | {limit} |"

    expected = [row(m) for m in rd.methods()]
    assert table == expected


def test_cpp_page_covers_every_layer_and_includes_existing_files() -> None:
    text = (DOCS / "cpp.md").read_text()
    layers = {p.name for p in (ROOT / "cpp/include/rigiddyn").iterdir() if p.is_dir()}
    described = set(re.findall(r"^\| `(\w+)/` \|", text, flags=re.MULTILINE))
    assert described == layers
    for top in (ROOT / "cpp/include/rigiddyn").glob("*.hpp"):
        assert f"`{top.name}`" in text, top.name
    included = re.findall(r"^```\{literalinclude\} (\S+)", text, flags=re.MULTILINE)
    assert "../tests/packaging/downstream/main.cpp" in included
    for path in included:
        assert (DOCS / path).is_file(), path
