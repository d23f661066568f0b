"""The pages of a built Sphinx site and what they link to, read with the standard library's HTML parser."""

from __future__ import annotations

import functools
import posixpath
from dataclasses import dataclass, field
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

# directories of the output that hold no pages of the site (assets, copied sources, downloads)
NOT_PAGES = ("_static", "_sources", "_downloads", "_images", "_modules")

# attributes holding one URL, by tag; srcset holds several
URL_ATTRIBUTES = {"a": "href", "link": "href", "img": "src", "script": "src", "source": "src",
                  "iframe": "src", "video": "src", "audio": "src", "embed": "src", "object": "data"}


@dataclass
class Page:
    """One HTML page: the ids it defines (anchors) and the URLs it refers to, as (tag, url)."""

    ids: set[str] = field(default_factory=set)
    urls: list[tuple[str, str]] = field(default_factory=list)


class _Collector(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.page = Page()

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        values = {k: v for k, v in attrs if v is not None}
        if "id" in values:
            self.page.ids.add(values["id"])
        if tag == "a" and "name" in values:
            self.page.ids.add(values["name"])
        attribute = URL_ATTRIBUTES.get(tag)
        if attribute and attribute in values:
            self.page.urls.append((tag, values[attribute]))
        for candidate in values.get("srcset", "").split(","):
            if candidate.strip():
                self.page.urls.append((tag, candidate.split()[0]))


def is_internal(url: str) -> bool:
    """A URL relative to the page (no scheme, no host): what the site itself must provide."""
    parts = urlsplit(url)
    return not parts.scheme and not parts.netloc and not url.startswith("//")


class Site:
    """A built HTML site rooted at `root`."""

    def __init__(self, root: Path) -> None:
        self.root = root.resolve()

    def pages(self) -> list[Path]:
        """Every HTML page of the site (outside the asset directories), sorted."""
        return sorted(p for p in self.root.rglob("*.html")
                      if p.relative_to(self.root).parts[0] not in NOT_PAGES)

    @functools.lru_cache(maxsize=None)
    def read(self, path: Path) -> Page:
        collector = _Collector()
        collector.feed(path.read_text(encoding="utf-8"))
        return collector.page

    def broken_links(self, page: Path) -> list[str]:
        """The internal URLs of `page` whose file is missing, or whose #anchor the target lacks."""
        broken = []
        for tag, url in self.read(page).urls:
            if not is_internal(url):
                continue
            parts = urlsplit(url)
            if parts.path.startswith("/"):
                broken.append(f"<{tag}> {url}: absolute path (the site must work from any directory)")
                continue
            target = page if not parts.path else Path(posixpath.normpath(
                posixpath.join(page.parent.as_posix(), unquote(parts.path))))
            if target.is_dir():
                target = target / "index.html"
            if not target.is_relative_to(self.root):
                broken.append(f"<{tag}> {url}: outside the site")
            elif not target.is_file():
                broken.append(f"<{tag}> {url}: no file {target.relative_to(self.root)}")
            elif parts.fragment and target.suffix == ".html" and unquote(parts.fragment) not in self.read(target).ids:
                broken.append(f"<{tag}> {url}: no id {unquote(parts.fragment)!r} in {target.relative_to(self.root)}")
        return broken
