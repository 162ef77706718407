"""MkDocs hook (``hooks:`` in mkdocs.yml): the pages that are not written under docs/.

* the reference pages generated from the code (``gen_reference.PAGES``: the command line,
  the drive-file keys, the scenes), made at build time, never written to the repository;
* the report chapters as they are in ``reports/`` (Markdown, figures, animations), added to
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
#: what of reports/ becomes part of the site (data/ and the caches stay out: no page
#: links them)
SUFFIXES = (".md", ".png", ".gif", ".svg", ".jpg")
SKIP = ("data", ".cache")


def report_files() -> list[str]:
    """Paths (relative to the repository, '/'-separated) of the report files in the site."""
    return sorted(p.relative_to(REPO).as_posix() for p in REPORTS.rglob("*")
                  if p.is_file() and p.suffix in SUFFIXES
                  and p.relative_to(REPORTS).parts[0] not in SKIP)


def _chapters() -> list[str]:
    """The chapters in the order reports/README.md's table lists them."""
    text = (REPORTS / "README.md").read_text(encoding="utf-8")
    linked = re.findall(r"\]\(([a-z0-9_]+\.md)\)", text)
    return [f"reports/{name}" for name in dict.fromkeys(linked) if name != "schemas.md"]


def reports_nav() -> list[dict]:
    """The "Reports" and "Benchmarks" sections of the navigation."""
    files = report_files()
    timing = [f for f in files if f.startswith("reports/timing/") and f.endswith(".md")]
    bench = [f for f in files if f.startswith("reports/benchmarks/") and f.endswith(".md")]
    bench.sort(key=lambda f: (not f.endswith("README.md"), f))
    return [{"Reports": ["reports/README.md", *_chapters(), {"Timing": timing}]},
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
