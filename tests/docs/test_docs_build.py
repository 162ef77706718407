"""The documentation site builds with ``mkdocs build --strict`` (every MkDocs warning an
error: a broken link, a missing page or anchor, a docstring mkdocstrings cannot render)
and every internal link of the built site resolves: each ``href`` or ``src`` that points
inside the site names a file there, and each ``#anchor`` an ``id`` on its page.

Needs the ``docs`` packages (the ``test`` extra has them); skipped without them.
One build takes about 13 CPU seconds (hence slow: ``make test`` runs it, ``make test-fast``
does not).
"""
import importlib.util
import os
import posixpath
import subprocess
import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

import pytest

from ancf.common.paths import REPO

pytestmark = pytest.mark.slow

MISSING = [m for m in ("mkdocs", "material", "mkdocstrings", "mkdocstrings_handlers")
           if importlib.util.find_spec(m) is None]
if MISSING:
    pytest.skip(f"the docs packages are not installed ({', '.join(MISSING)}); "
                "`pip install -e '.[docs]'` or `make docs` installs them",
                allow_module_level=True)


def _hook(name: str):
    """The module docs/hooks/NAME.py (its folder on the path only while it loads, as
    MkDocs loads it)."""
    folder = str(REPO / "docs" / "hooks")
    spec = importlib.util.spec_from_file_location(f"docs_hooks_{name}", f"{folder}/{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.path.insert(0, folder)
    try:
        spec.loader.exec_module(module)
    finally:
        sys.path.remove(folder)
    return module


gen_reference, pages = _hook("gen_reference"), _hook("pages")


class _Links(HTMLParser):
    """The ids of a page and the URLs its elements point to (href, src)."""

    def __init__(self):
        super().__init__()
        self.ids, self.urls = set(), []

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("id", "name") and value:
                self.ids.add(value)
            elif name in ("href", "src") and value:
                self.urls.append(value)


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    """The site built with --strict into a temporary folder, and what the build printed."""
    out = tmp_path_factory.mktemp("site")
    env = {**os.environ, "NO_MKDOCS_2_WARNING": "1"}
    p = subprocess.run([sys.executable, "-m", "mkdocs", "build", "--strict", "--config-file",
                        str(REPO / "mkdocs.yml"), "--site-dir", str(out)],
                       cwd=REPO, env=env, capture_output=True, text=True)
    assert p.returncode == 0, f"mkdocs build --strict failed:\n{p.stdout}\n{p.stderr}"
    return out, p.stdout + p.stderr


def _pages(root: Path) -> dict:
    """Every HTML page of the site by its path relative to the root: its _Links."""
    out = {}
    for path in root.rglob("*.html"):
        links = _Links()
        links.feed(path.read_text(encoding="utf-8"))
        out[path.relative_to(root).as_posix()] = links
    return out


def _target(page: str, url: str, root: Path) -> tuple[str, str] | None:
    """The site file (relative path) and anchor an internal ``url`` on ``page`` points to;
    None for an external URL."""
    parts = urlsplit(url)
    if parts.scheme or parts.netloc or url.startswith(("mailto:", "javascript:")):
        return None
    path = unquote(parts.path)
    if not path:
        return page, parts.fragment
    base = "" if path.startswith("/") else posixpath.dirname(page)  # 404.html: from the root
    joined = posixpath.normpath(posixpath.join(base, path.lstrip("/")))
    if (root / joined).is_dir():
        joined = posixpath.normpath(posixpath.join(joined, "index.html"))
    return joined, parts.fragment


def test_build_has_no_warning(site):
    _, log = site
    assert "WARNING" not in log, log


def test_every_internal_link_resolves(site):
    root, _ = site
    pages_ = _pages(root)
    broken, checked = [], 0
    for page, links in pages_.items():
        for url in links.urls:
            target = _target(page, url, root)
            if target is None:
                continue
            checked += 1
            path, anchor = target
            if path.startswith("..") or not (root / path).is_file():
                broken.append(f"{page}: {url} (no file {path})")
            elif anchor and path.endswith(".html") and anchor not in pages_[path].ids:
                broken.append(f"{page}: {url} (no id {anchor!r} on {path})")
    assert checked > len(pages_), "too few links found: the parser missed them"
    assert not broken, "\n".join(broken)


def test_every_report_and_reference_page_is_built(site):
    root, _ = site
    expected = [f for f in pages.report_files() if f.endswith(".md")]
    expected += list(gen_reference.PAGES) + ["reference/api.md", "getting-started.md"]
    missing = []
    for md in expected:
        stem = md.removesuffix(".md").removesuffix("README").removesuffix("index").rstrip("/")
        html = f"{stem}/index.html" if stem else "index.html"
        if not (root / html).is_file():
            missing.append(f"{md} -> {html}")
    assert not missing, missing


def test_cli_page_lists_every_command_and_option():
    page = gen_reference.cli_page()
    parser = gen_reference.cli_parser()
    sub = next(a for a in parser._actions if a.dest == "cmd")
    for name, p in sub.choices.items():
        assert f"{{#ancf-{name}}}" in page, name
        for action in p._actions:
            for flag in action.option_strings:
                if flag not in ("-h", "--help"):
                    assert f"`{flag}" in page, (name, flag)


def test_scenes_page_lists_every_scene_and_parameter():
    import ancf
    page = gen_reference.scenes_page()
    for s in ancf.scenes():
        assert f"### `{s['name']}` {{#{s['name']}}}" in page, s["name"]
        for name, info in s["params"].items():
            assert f"| `{name}` |" in page and gen_reference._cell(info["doc"]) in page, name


def test_drive_file_page_lists_every_declared_key():
    from ancf.belts import drive_data as dd
    page = gen_reference.drive_file_page()
    tables = [dd.TOP, dd.BELT, dd.PLATE_BELT, dd.PULLEY, dd.TIME_KEYS, dd.MOTION,
              dd.ALIGNMENT, dd.FLANGES, dd.RUN, *dd.CONTACT_KEYS.values(),
              *dd.FRICTION_KEYS.values()]
    keys = [k for t in tables for k in t.values()]
    keys += [k for role in dd.ROLES.values() for k in role.keys]
    for k in keys:
        assert f"| `{k.name}` | {gen_reference._unit(k)} | {gen_reference._default(k)} " \
               f"| {gen_reference._cell(k.allowed())} |" in page, k.name
