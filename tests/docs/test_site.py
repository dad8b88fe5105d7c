"""The built documentation site, opened in a real headless browser (``nox -s docs``).

The site is served over HTTP on the loopback address, as a reader's browser would load it
(the search fetches pages, which a ``file://`` page may not). Chromium loads each page, runs
its scripts and prints the resulting document; every console message is collected, and a
page passes only with none. The home page's screenshot is kept beside the site as the build's
artefact (``screenshot.png``).
"""

from __future__ import annotations

import functools
import http.server
import os
import re
import shutil
import subprocess
import threading
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest

SITE = Path(os.environ.get("TYPED_MJCF_DOCS_SITE", "docs/_build/html")).resolve()
BROWSERS = ("chromium", "chromium-browser", "google-chrome")
# Chromium's log line for a page's console message: INFO:CONSOLE(line)] "text", source: url
CONSOLE = re.compile(r':CONSOLE(?:\(\d+\)|:\d+)\] "(.*)", source: (\S*)')


@dataclass(frozen=True)
class Page:
    dom: str  # the document after its scripts ran
    console: list[str]  # every console message, with its source


def browser() -> str:
    found = next((shutil.which(name) for name in BROWSERS if shutil.which(name)), None)
    assert found is not None, ("no Chromium: `apt-get install chromium` (.ci/run installs it "
                               "for nox -s docs)")
    return found


class _Quiet(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: object) -> None:
        pass


@pytest.fixture(scope="module")
def server() -> Iterator[str]:
    assert (SITE / "index.html").is_file(), f"no site in {SITE}: run nox -s docs"
    handler = functools.partial(_Quiet, directory=str(SITE))
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}"
    httpd.shutdown()
    httpd.server_close()


def run_browser(*arguments: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [browser(), "--headless", "--no-sandbox", "--disable-gpu", "--enable-logging=stderr",
         "--v=0", "--virtual-time-budget=8000", *arguments],
        capture_output=True, text=True, timeout=120, check=False)


def open_page(url: str) -> Page:
    done = run_browser("--dump-dom", url)
    assert done.returncode == 0, done.stderr[-2000:]
    console = [f"{m[1]} ({m[2]})" for m in CONSOLE.finditer(done.stderr)]
    return Page(done.stdout, console)


def test_the_home_page(server: str) -> None:
    page = open_page(f"{server}/index.html")
    assert page.console == []
    assert "<title>typed-mjcf" in page.dom
    assert "from_mjcf_model" in page.dom  # the example (highlighted: one span per name)
    assert 'href="guide/index.html"' in page.dom and 'href="reference/index.html"' in page.dom


def test_a_guide_page(server: str) -> None:
    page = open_page(f"{server}/guide/defaults.html")
    assert page.console == []
    assert "Default classes" in page.dom and "commit_defaults" in page.dom


def test_an_element_page(server: str) -> None:
    page = open_page(f"{server}/reference/joint.html")
    assert page.console == []
    assert "springyield" in page.dom and "JointType" in page.dom
    assert 'href="body.html"' in page.dom  # a parent's page


def test_the_api_page_links_the_reference(server: str) -> None:
    page = open_page(f"{server}/api.html")
    assert page.console == []
    assert 'id="typed_mjcf.RootElement"' in page.dom


def test_the_search_finds_an_attribute(server: str) -> None:
    page = open_page(f"{server}/search.html?q=springyield")
    assert page.console == []
    results = re.search(r'<ul[^>]*class="search"[^>]*>(.*?)</ul>', page.dom, re.DOTALL)
    assert results is not None, "the search printed no results"
    assert 'href="reference/joint.html' in results.group(1)


def test_a_screenshot_of_the_home_page(server: str) -> None:
    shot = SITE.parent / "screenshot.png"
    shot.unlink(missing_ok=True)
    done = run_browser("--window-size=1280,900", f"--screenshot={shot}",
                       f"{server}/index.html")
    assert done.returncode == 0, done.stderr[-2000:]
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert shot.stat().st_size > 20_000  # a page with text and a picture, not a blank one
