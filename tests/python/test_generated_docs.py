"""Generated documents are never older than what they were generated from.

Each generated document records (bench/python/provenance.py) the command that made it, when, on what
machine, and a digest of the content of every input its generator declares (the generator itself and
the sources whose behaviour it measures). A document whose recorded digests differ from its inputs'
current content is stale: the test fails naming the changed inputs and the command that regenerates
it. Regenerating is a step a maintainer runs (a few minutes); it never needs a build inside the test.
"""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BENCH = ROOT / "bench" / "python"
sys.path.insert(0, str(BENCH))
import provenance  # noqa: E402


def _generator(name: str):
    spec = importlib.util.spec_from_file_location(f"_generator_{name}", BENCH / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


# document -> (generator script, how to read its stamp)
GENERATED = {
    "docs/extremes.md": ("bench_extremes", lambda p: provenance.read_markdown_stamp(p.read_text())),
    "docs/accuracy.md": ("accuracy_table", lambda p: provenance.read_markdown_stamp(p.read_text())),
    "docs/tradeoff_t_handle.png": ("plot_tradeoff_t_handle", provenance.read_png_stamp),
}


@pytest.mark.parametrize("document", sorted(GENERATED))
def test_generated_document_is_not_older_than_its_inputs(document):
    script, read = GENERATED[document]
    generator = _generator(script)
    made = read(ROOT / document)
    assert made is not None, (f"{document} does not say how it was made; regenerate it: {generator.REGENERATE}")
    changed = provenance.changed_inputs(made["inputs"], generator.INPUTS)
    assert not changed, (
        f"{document} is older than its inputs ({'; '.join(changed)}): it was made on {made['date']} with "
        f"`{made['command']}`. Regenerate it: {generator.REGENERATE}")


@pytest.mark.parametrize("document", sorted(GENERATED))
def test_generator_declares_itself_and_existing_sources_as_inputs(document):
    """An input pattern that matches nothing (a renamed source) would silently stop the check."""
    generator = _generator(GENERATED[document][0])
    assert f"bench/python/{GENERATED[document][0]}.py" in generator.INPUTS
    for pattern in generator.INPUTS:
        assert provenance.input_digests([pattern]), f"{GENERATED[document][0]}.INPUTS: {pattern!r} matches no file"


@pytest.mark.parametrize("document", ["docs/extremes.md", "docs/accuracy.md"])
def test_markdown_states_when_and_how_it_was_measured(document):
    text = (ROOT / document).read_text()
    made = provenance.read_markdown_stamp(text)
    assert made is not None and provenance.measured_sentence(made) in text


def test_staleness_is_detected(tmp_path):
    """The check itself: a changed, a new and a removed input are each reported; untouched ones are not."""
    for name in ("a.cpp", "b.cpp", "c.cpp"):
        (tmp_path / name).write_text(name)
    recorded = provenance.input_digests(["*.cpp"], tmp_path)
    assert provenance.changed_inputs(recorded, ["*.cpp"], tmp_path) == []
    (tmp_path / "a.cpp").write_text("a.cpp edited")
    (tmp_path / "c.cpp").unlink()
    (tmp_path / "d.cpp").write_text("d")
    assert provenance.changed_inputs(recorded, ["*.cpp"], tmp_path) == ["changed: a.cpp", "new: d.cpp", "removed: c.cpp"]
