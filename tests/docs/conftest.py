"""Checks of the built documentation site (tests/docs/run.sh builds it first).

The site checked is docs/_build/html, or the directory in RIGIDDYN_DOCS_HTML. These tests are not part
of the default pytest run (pyproject.toml's testpaths is tests/python): run them with
``bash tests/docs/run.sh`` (build and check) or ``python3 -m pytest tests/docs`` on a built site.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from site_pages import Site

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def site() -> Site:
    html = Path(os.environ.get("RIGIDDYN_DOCS_HTML", ROOT / "docs" / "_build" / "html"))
    if not (html / "index.html").is_file():
        pytest.fail(f"no built site at {html} (index.html missing): run bash tests/docs/run.sh")
    return Site(html)
