"""Sphinx configuration of rigiddyn's documentation site (furo, MyST Markdown, autodoc + autosummary,
sphinx-gallery).

Build (README, "Documentation"), warnings as errors:

    python3 -m pip install ".[docs]" && python3 -m sphinx -W -b html docs docs/_build/html

and check the built site (headless chromium, internal links): ``bash tests/docs/run.sh``.

Iterating on prose without running the gallery (every docs/examples/plot_*.py runs at each full build):

    RIGIDDYN_DOCS_GALLERY=0 python3 -m sphinx -W -b html docs /tmp/html      # gallery pages, no run, no figures
    RIGIDDYN_DOCS_EXAMPLES=plot_kepler python3 -m sphinx -W -b html docs /tmp/html   # run only the
                                                 # examples whose path matches this regular expression

(the first is sphinx-gallery's ``plot_gallery`` option, also ``-D plot_gallery=0``; the second its
``filename_pattern``). A build of the published site sets neither.
"""

from __future__ import annotations

import os
import re
import sys
from pathlib import Path

import rigiddyn

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE / "_ext"))  # rigiddyn_docstrings (the docstring hook), gallery_order

from rigiddyn_docstrings import is_numpydoc, render_docstring, render_numpydoc  # noqa: E402
from sphinx.util.docstrings import prepare_docstring  # noqa: E402

project = "rigiddyn"
author = "the rigiddyn developers"
copyright = "the rigiddyn developers, BSD-3-Clause"
version = release = rigiddyn.__version__

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    # the docstrings' numpydoc sections (Parameters, Returns, Raises, See Also, Examples) rendered as fields
    "sphinx.ext.napoleon",
    # MathJax 3 shipped inside the built site (docs/_build/html/_static/mathjax) instead of loaded from
    # its CDN: the pages render their equations offline, and the browser check sees them typeset
    "sphinx-mathjax-offline",
    "sphinx_gallery.gen_gallery",
    # `.. plot::` (getting_started.md, in an ```{eval-rst} block: MyST cannot run it directly): the code
    # shown runs at every build, its figure below it
    "matplotlib.sphinxext.plot_directive",
]

source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
root_doc = "index"
templates_path = ["_templates"]
# examples/: the gallery's sources (sphinx-gallery turns them into auto_examples/); _build: the output
exclude_patterns = ["_build", "examples", "Thumbs.db", ".DS_Store"]

# MyST: ::: fences for directives, $...$ and $$...$$ math, definition lists; anchors for headings
# down to ### so that [text](page.md#a-heading) links resolve (and are checked)
myst_enable_extensions = ["colon_fence", "dollarmath", "deflist"]
myst_heading_anchors = 3

# no intersphinx: the build needs no network

# ---- API reference (docs/api/): autosummary writes one page per name into docs/api/generated/
autosummary_generate = True
# classes: every member, documented or not (docs/_templates/autosummary/class.rst); modules: their docstring
# and the names listed on the page
autoclass_content = "class"          # the class docstring; pybind11's __init__ docstrings are signatures only
autodoc_class_signature = "mixed"
autodoc_member_order = "bysource"
autodoc_typehints = "signature"
napoleon_google_docstring = False
napoleon_numpy_docstring = True
napoleon_use_ivar = True  # a class's Attributes as fields (its member pages describe each attribute once)
autodoc_inherit_docstrings = False   # a pybind11 class inherits object's generic docstrings otherwise


def _render(app, what, name, obj, options, lines):  # noqa: ARG001  (Sphinx's event signature)
    """rigiddyn's docstrings in numpydoc form (napoleon has made their sections fields) stay reST, the markup
    characters of their equations escaped (rigiddyn_docstrings.render_numpydoc); any other is free-form text,
    whose line layout carries meaning, rendered faithfully (rigiddyn_docstrings.render_docstring)."""
    if not (name == "rigiddyn" or name.startswith("rigiddyn.")):
        return
    if what in ("data", "attribute") and lines == prepare_docstring(type(obj).__doc__ or ""):
        lines[:] = []  # a constant's type's docstring (tuple's, float's, an enum's): not the constant's
    elif is_numpydoc(lines):
        lines[:] = render_numpydoc(lines)
    else:
        lines[:] = render_docstring(lines)


# pybind11's placeholder type of a parameter the binding converts itself (the Parameters section states its type)
_UNTYPED = re.compile(r": object(?=[,)\s])")


def _signature(app, what, name, obj, options, signature, return_annotation):  # noqa: ARG001  (Sphinx's event)
    """A compiled function's signature without pybind11's ": object" on the parameters it converts itself, and the
    core's classes named as the package exports them (rigiddyn.SceneResult, not rigiddyn._core.SceneResult)."""
    if not (name == "rigiddyn" or name.startswith("rigiddyn.")):
        return None
    if signature is not None:
        signature = _UNTYPED.sub("", signature).replace("rigiddyn._core.", "rigiddyn.")
    if return_annotation is not None:
        return_annotation = return_annotation.replace("rigiddyn._core.", "rigiddyn.")
    return signature, return_annotation


def setup(app):
    app.connect("autodoc-process-docstring", _render, priority=400)  # before napoleon's (500) reads the sections
    app.connect("autodoc-process-signature", _signature)


# ---- gallery: every docs/examples/plot_*.py runs at build time; a failing example fails the build
_examples = os.environ.get("RIGIDDYN_DOCS_EXAMPLES")
sphinx_gallery_conf = {
    "examples_dirs": ["examples"],
    "gallery_dirs": ["auto_examples"],
    "filename_pattern": _examples if _examples else re.escape(os.sep) + "plot_",
    "ignore_pattern": r"__init__\.py",
    "within_subsection_order": "gallery_order.TextbookOrder",   # docs/_ext/gallery_order.py
    "plot_gallery": os.environ.get("RIGIDDYN_DOCS_GALLERY", "1") != "0",
    "abort_on_example_error": True,
    "only_warn_on_example_error": False,
    "image_scrapers": ("matplotlib",),
    "download_all_examples": False,
    "remove_config_comments": True,
    "show_memory": False,
    # no sg_execution_times pages: their table needs jQuery and DataTables from a CDN (a console error
    # offline, and in the browser check)
    "write_computation_times": False,
}

# ---- `.. plot::` directives: the source shown, then its figure as one PNG; no links to download the source or
# other formats
plot_include_source = True
plot_html_show_source_link = False
plot_html_show_formats = False
plot_formats = [("png", 120)]

# ---- HTML
html_theme = "furo"
html_title = f"rigiddyn {release}"
html_static_path = ["_static"]
html_css_files = ["rigiddyn.css"]
