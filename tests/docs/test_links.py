"""No broken internal link in the built site: every relative href/src (and srcset) of every page
resolves to a file of the site, and every #anchor exists in the page it points to."""

from __future__ import annotations

from pathlib import Path

from site_pages import Site

# pages the site must have: the landing page, the API reference, the gallery, the search page
REQUIRED = ("index.html", "api/index.html", "auto_examples/index.html", "genindex.html", "search.html")


def test_site_has_its_main_pages(site: Site):
    missing = [p for p in REQUIRED if not (site.root / p).is_file()]
    assert not missing, f"pages missing from {site.root}: {missing}"


def test_no_broken_internal_link(site: Site):
    pages = site.pages()
    broken = {str(p.relative_to(site.root)): b for p in pages if (b := site.broken_links(p))}
    report = "\n".join(f"{page}: {link}" for page, links in broken.items() for link in links)
    assert not broken, f"broken internal links in {len(broken)} of {len(pages)} pages:\n{report}"


def test_the_crawler_sees_the_links(site: Site):
    """The check above cannot pass by seeing nothing: every page links within the site, and anchors
    are read (each page's own title has an id that the table of contents points to)."""
    pages = site.pages()
    assert len(pages) >= 10
    internal = [p for p in pages if any(u.startswith(("#", ".")) or u.endswith(".html") for _, u in site.read(p).urls)]
    assert internal == pages
    assert all(site.read(p).ids for p in pages)


def test_a_broken_link_is_caught(tmp_path: Path):
    """The crawler flags a missing file, a missing anchor and an absolute path, and passes good links."""
    (tmp_path / "a.html").write_text('<h1 id="top">A</h1><a href="b.html#here">b</a><a href="#top">t</a>'
                                     '<img src="img/x.png"><a href="c.html">c</a><a href="b.html#gone">g</a>'
                                     '<a href="/abs.html">abs</a><a href="https://example.org/x">ext</a>')
    (tmp_path / "b.html").write_text('<p id="here">B</p>')
    (tmp_path / "img").mkdir()
    (tmp_path / "img" / "x.png").write_bytes(b"")
    broken = Site(tmp_path).broken_links(tmp_path / "a.html")
    assert [b.split(":")[0] for b in broken] == ["<a> c.html", "<a> b.html#gone", "<a> /abs.html"]
