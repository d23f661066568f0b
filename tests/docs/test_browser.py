"""Every page of the built site opens in headless chromium (Debian's chromium + chromium-driver, driven
by selenium), and its images are loaded; the gallery's pages have figures."""

from __future__ import annotations

import shutil

import pytest
from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.support.ui import WebDriverWait

from site_pages import Site

# what a page shows: its title, the length of its text, the site's images (file:// URLs; lazy ones
# made eager) and those of them not loaded
INSPECT = """
const images = Array.from(document.images).filter(i => i.src.startsWith('file:'));
images.forEach(i => { i.loading = 'eager'; });
return {title: document.title, text: document.body.innerText.length, images: images.length,
        unloaded: images.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.getAttribute('src'))};
"""
IMAGES_SETTLED = "return Array.from(document.images).every(i => i.complete);"


@pytest.fixture(scope="module")
def browser():
    binary, driver_path = shutil.which("chromium"), shutil.which("chromedriver")
    if not (binary and driver_path):
        pytest.fail("chromium and chromedriver not found: apt-get install chromium chromium-driver "
                    "(tests/docs/run.sh does)")
    options = webdriver.ChromeOptions()
    options.binary_location = binary
    for argument in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage"):
        options.add_argument(argument)
    options.set_capability("goog:loggingPrefs", {"browser": "SEVERE"})
    driver = webdriver.Chrome(service=Service(executable_path=driver_path), options=options)
    driver.set_page_load_timeout(60)
    yield driver
    driver.quit()


def open_page(driver, page) -> dict:
    """Open `page`; return its title, text length, site images, unloaded images and console errors."""
    driver.get(page.as_uri())
    WebDriverWait(driver, 30).until(lambda d: d.execute_script("return document.readyState") == "complete")
    seen = driver.execute_script(INSPECT)
    if seen["unloaded"]:  # lazy images made eager just now: give them the time to load
        WebDriverWait(driver, 30).until(lambda d: d.execute_script(IMAGES_SETTLED))
        seen = driver.execute_script(INSPECT)
    # console errors about the site's own files (a missing script or stylesheet, a script that fails);
    # network resources (MathJax from its CDN) are not the site's, and the check runs offline
    seen["errors"] = [e["message"] for e in driver.get_log("browser") if "file://" in e["message"]]
    return seen


def gallery_pages(site: Site) -> list:
    return [site.root / "auto_examples" / "index.html"] + sorted((site.root / "auto_examples").glob("plot_*.html"))


def test_every_page_opens_with_its_images(site: Site, browser):
    failures = []
    pages = site.pages()
    for page in pages:
        seen = open_page(browser, page)
        name = page.relative_to(site.root)
        if not seen["title"] or not seen["text"]:
            failures.append(f"{name}: empty page (title {seen['title']!r}, {seen['text']} characters)")
        if seen["unloaded"]:
            failures.append(f"{name}: images not loaded: {seen['unloaded']}")
        if seen["errors"]:
            failures.append(f"{name}: console errors: {seen['errors']}")
    assert not failures, f"{len(failures)} problems in {len(pages)} pages:\n" + "\n".join(failures)


def test_gallery_pages_have_figures(site: Site, browser):
    pages = gallery_pages(site)
    assert len(pages) >= 2, "the gallery has no example pages"
    without = [str(p.relative_to(site.root)) for p in pages if open_page(browser, p)["images"] < 1]
    assert not without, f"gallery pages without an image: {without}"


# equations: Sphinx writes each as an element of class "math"; MathJax (shipped in the site's _static,
# docs/conf.py) replaces its TeX by an <mjx-container>, asynchronously, once its startup promise resolves
MATH_TYPESET = """
const done = arguments[arguments.length - 1];
const count = () => ({math: document.querySelectorAll('.math').length,
                      typeset: document.querySelectorAll('mjx-container').length});
if (!window.MathJax || !MathJax.startup || !MathJax.startup.promise) { done({...count(), loaded: false}); return; }
MathJax.startup.promise.then(() => done({...count(), loaded: true}), () => done({...count(), loaded: false}));
"""


def test_equations_are_typeset_offline(site: Site, browser):
    pages = [p for p in site.pages() if 'class="math' in p.read_text(encoding="utf-8")]
    assert pages, "no page has an equation: the check would test nothing"
    browser.set_script_timeout(60)
    failures = []
    for page in pages:
        browser.get(page.as_uri())
        seen = browser.execute_async_script(MATH_TYPESET)
        if not seen["loaded"] or seen["typeset"] < 1:
            failures.append(f"{page.relative_to(site.root)}: {seen['math']} equations, MathJax loaded "
                            f"{seen['loaded']}, {seen['typeset']} typeset")
    assert not failures, f"equations not typeset in {len(failures)} of {len(pages)} pages:\n" + "\n".join(failures)
