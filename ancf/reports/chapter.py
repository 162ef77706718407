"""The chapters of ``reports/``, registered by name: each chapter is one module of this
package that ends with its declaration ``CHAPTER = Chapter(...)`` (its page, its row of the
index, its generator, the modules computing its acceptance rows, its place in the report
and in the processes of a full generation, the chapters whose runs it reads).

:func:`chapters` reads the declarations from the modules' source without importing them,
so listing the chapters or writing one of them loads only what that chapter needs; a
chapter's generator is imported when it is called. Adding a chapter is adding its module.
"""
from __future__ import annotations

import ast
import importlib
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Callable

#: the processes of a full generation (``python -m ancf.reports --jobs 2``): the
#: speed-accuracy sweeps (two sweep workers of their own), every other chapter
PROCESSES = ("sweeps", "main")

_DECLARATION = "\nCHAPTER = Chapter("


@dataclass(frozen=True, kw_only=True)
class Chapter:
    """One page of ``reports/``.

    ``file``: the page (``NAME.md``, written by the module ``ancf.reports.NAME``);
    ``contents``: its cell in the index of ``reports/README.md``; ``generate``: ``() ->
    (markdown, {acceptance row: status})``; ``checks``: the modules computing its acceptance
    rows (``ancf.checks.*``, or the chapter's own module where it computes them itself);
    ``order``: its place in the index, the acceptance summary and a one-process generation
    (ascending); ``process``: one of :data:`PROCESSES`; ``reads``: the chapters whose runs
    it reads from the run store of the generation (``ancf.scenes.store``).
    """
    file: str
    contents: str
    generate: Callable[[], tuple[str, dict]]
    checks: tuple[str, ...]
    order: int
    process: str = "main"
    reads: tuple[str, ...] = ()

    def index_row(self) -> str:
        """The chapter's row of the index table of ``reports/README.md``."""
        return f"| [{self.file}]({self.file}) | {self.contents} |"


@dataclass(frozen=True)
class Generator:
    """A chapter's generator as its declaration names it: ``module.name``, imported when
    called."""
    module: str
    name: str

    def __call__(self) -> tuple[str, dict]:
        return getattr(importlib.import_module(self.module), self.name)()


def _field(module: str, node: ast.expr):
    """A keyword of a declaration: a function named by the module (the generator), or a
    literal."""
    if isinstance(node, ast.Name):
        return Generator(module, node.id)
    return ast.literal_eval(node)


def declared(path: Path) -> Chapter | None:
    """The chapter the module at ``path`` declares, read from its source (None: not a
    chapter)."""
    text = path.read_text()
    if _DECLARATION not in text:
        return None
    module = f"{__package__}.{path.stem}"
    for node in ast.parse(text).body:
        if (isinstance(node, ast.Assign) and len(node.targets) == 1
                and isinstance(node.targets[0], ast.Name) and node.targets[0].id == "CHAPTER"):
            return Chapter(**{k.arg: _field(module, k.value) for k in node.value.keywords})
    return None


@lru_cache(maxsize=1)
def chapters() -> dict[str, Chapter]:
    """Every chapter of this package, by file, in report order."""
    found = (declared(p) for p in Path(__file__).parent.glob("*.py"))
    return {c.file: c for c in sorted((c for c in found if c), key=lambda c: c.order)}


def groups() -> tuple[tuple[str, ...], ...]:
    """The chapter files each of the :data:`PROCESSES` writes, in report order, except that
    a chapter reading the runs of a chapter in another process comes after the rest of its
    own (by then the other process has made those runs; a run not found in the store is
    made where it is needed)."""
    every = chapters()
    out = []
    for process in PROCESSES:
        mine = [c for c in every.values() if c.process == process]
        late = {c.file for c in mine if any(every[r].process != process for r in c.reads)}
        out.append(tuple(c.file for c in mine if c.file not in late)
                   + tuple(c.file for c in mine if c.file in late))
    return tuple(out)
