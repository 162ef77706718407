"""MkDocs hook (``hooks:`` in mkdocs.yml): the pages that are not written under docs/.

* the reference pages generated from the code (``gen_reference.PAGES``: the command line,
  the drive-file keys, the scenes), made at build time, never written to the repository;
* the report chapters as they are in ``reports/`` (Markdown, figures, animations, data), added to
  the site from their own folder under the same relative paths, so their relative links
  (``figures/x.png``, ``timing/x.md``, ``../x.md``) resolve unchanged; nothing is copied
  into docs/;
* their navigation: the chapters in the order of the table in ``reports/README.md``, then
  each chapter's timing page, then the benchmark pages.
"""
from __future__ import annotations

import re

from mkdocs.structure.files import File, Files

import gen_reference  # docs/hooks/, on the path while MkDocs loads this hook

REPO = gen_reference.REPO
REPORTS = REPO / "reports"


def report_files() -> list[str]:
    """Paths (relative to the repository, '/'-separated) of the report files in the site:
    every file of reports/ (pages, figures, animations, and the CSV and JSON files a page
    may link to) but the hidden ones (the cache)."""
    return sorted(p.relative_to(REPO).as_posix() for p in REPORTS.rglob("*")
                  if p.is_file()
                  and not any(part.startswith(".") for part in p.relative_to(REPORTS).parts))


def _chapters(top: list[str]) -> list[str]:
    """The chapters (``top``: the Markdown files directly in reports/) in the order
    reports/README.md's table lists them, then any it does not list yet."""
    text = (REPORTS / "README.md").read_text(encoding="utf-8")
    linked = [f"reports/{name}" for name in re.findall(r"\]\(([a-z0-9_]+\.md)\)", text)]
    return [f for f in dict.fromkeys(linked + sorted(top)) if f in top]


def reports_nav() -> list[dict]:
    """The "Reports" and "Benchmarks" sections of the navigation: every Markdown file of
    reports/ but the schemas (under Reference), so that none is left out of it."""
    pages = [f for f in report_files() if f.endswith(".md") and f != "reports/schemas.md"]
    folder = {f: f.removeprefix("reports/").rpartition("/")[0] for f in pages}
    top = [f for f in pages if not folder[f] and f != "reports/README.md"]
    timing = [f for f in pages if folder[f] == "timing"]
    bench = sorted((f for f in pages if folder[f] == "benchmarks"),
                   key=lambda f: (not f.endswith("README.md"), f))
    other = [f for f in pages if folder[f] not in ("", "timing", "benchmarks")]
    return [{"Reports": ["reports/README.md", *_chapters(top), *other, {"Timing": timing}]},
            {"Benchmarks": bench}]


def on_config(config, **kwargs):
    config["nav"] = list(config["nav"]) + reports_nav()
    return config


def on_files(files: Files, config, **kwargs) -> Files:
    for path in report_files():
        files.append(File(path, src_dir=str(REPO), dest_dir=config["site_dir"],
                          use_directory_urls=config["use_directory_urls"]))
    for path, make in gen_reference.PAGES.items():
        files.append(File.generated(config, path, content=make()))
    return files
