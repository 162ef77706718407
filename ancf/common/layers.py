"""The package's layers, bottom to top, and the rule between them.

A module imports only from its own layer and the layers below it, at module level
and inside functions (``tests/common/test_layers.py``).  Each layer is a folder whose
``__init__.py`` docstring says what it holds; the layout table of docs/architecture.md is generated
from this list and those docstrings: ``python -m ancf.common.layers`` rewrites it.
"""
from __future__ import annotations

import ast
import sys
from pathlib import Path

from ancf.common.paths import REPO

ROOT = REPO

#: bottom to top; each layer is one or more paths, a path a folder (its modules) or a file
LAYERS = (("ancf/common",), ("analytic",), ("ancf/core",), ("ancf/solvers",),
          ("ancf/elements",), ("ancf/models",), ("ancf/belts",), ("ancf/scenes",),
          ("ancf/study",), ("ancf/checks",), ("ancf/reports",), ("ancf/cli.py", "ancf/api.py", "ancf/result.py"))

#: files outside every layer: the package itself, whose ``__init__`` imports nothing of the
#: project at module level and only the top layer lazily, inside its module ``__getattr__``
#: (``ancf.run`` etc. load ``ancf.api`` on first use; see :func:`package_init_violations`)
PACKAGE_FILES = ("ancf/__init__.py",)

#: the page whose layout table is generated
PAGE = ROOT / "docs" / "architecture.md"
BEGIN, END = "<!-- layers: begin (python -m ancf.common.layers) -->", "<!-- layers: end -->"


def module_name(rel: str) -> str:
    """Dotted module name of a repository-relative .py path."""
    parts = rel[:-3].split("/")
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def layer_of(name: str) -> int | None:
    """Rank of a dotted module name (0 = bottom), None outside every layer."""
    if name == "ancf":
        return 0  # the package's __init__: importing anything imports it
    for rank, paths in enumerate(LAYERS):
        for path in paths:
            base = module_name(path if path.endswith(".py") else path + "/__init__.py")
            if name == base or name.startswith(base + "."):
                return rank
    return None


def project_files(root: Path = ROOT) -> list[str]:
    """Repository-relative paths of every module in ``ancf/`` and ``analytic/``."""
    return sorted(p.relative_to(root).as_posix() for top in ("ancf", "analytic")
                  for p in (root / top).rglob("*.py") if "__pycache__" not in p.parts)


def imports(source: str, name: str, is_package: bool) -> list[tuple[int, str]]:
    """(line, dotted target) of every project import in a module's source, at any depth
    (``from pkg import mod`` counts as ``pkg.mod``; relative imports resolved)."""
    pkg = name if is_package else name.rpartition(".")[0]
    out = []
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            out += [(node.lineno, a.name) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                up = pkg.split(".")[: len(pkg.split(".")) - node.level + 1]
                base = ".".join(up + ([base] if base else []))
            out += [(node.lineno, f"{base}.{a.name}") for a in node.names]
    return [(line, t) for line, t in out if t.split(".")[0] in ("ancf", "analytic")]


def _target_rank(target: str) -> int | None:
    """Rank of an imported name: the longest prefix that is a layer module."""
    parts = target.split(".")
    for k in range(len(parts), 0, -1):
        rank = layer_of(".".join(parts[:k]))
        if rank is not None and (k > 1 or parts[0] == "ancf"):
            return rank
    return None


def upward_imports(rel: str, source: str) -> list[str]:
    """One line per import in file ``rel`` of a layer above the file's own (the package
    ``__init__``: per :func:`package_init_violations`)."""
    if rel in PACKAGE_FILES:
        return package_init_violations(source)
    name = module_name(rel)
    own = layer_of(name)
    found = []
    for line, target in imports(source, name, rel.endswith("__init__.py")):
        rank = _target_rank(target)
        if rank is not None and own is not None and rank > own:
            found.append(f"{rel}:{line} (layer {own}) imports {target} (layer {rank})")
    return found


def package_init_violations(source: str) -> list[str]:
    """One line per project import of the package ``__init__`` that is not a lazy import of
    the top layer inside its module-level ``__getattr__`` (the cheap ``import ancf``)."""
    tree = ast.parse(source)
    lazy = set()
    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and node.name == "__getattr__":
            lazy |= {id(n) for n in ast.walk(node)}
    top = len(LAYERS) - 1
    found = []
    for node in ast.walk(tree):
        if not isinstance(node, (ast.Import, ast.ImportFrom)):
            continue
        for line, target in imports(ast.unparse(node), "ancf", True):
            rank = _target_rank(target)
            if id(node) not in lazy:
                found.append(f"ancf/__init__.py:{node.lineno} imports {target} outside "
                             "__getattr__ (import ancf must stay cheap)")
            elif rank != top:
                found.append(f"ancf/__init__.py:{node.lineno} imports {target} (layer {rank}); "
                             f"only the top layer ({', '.join(LAYERS[top])}) may be loaded lazily")
    return found


def _doc(path: str, root: Path) -> str:
    f = root / path if path.endswith(".py") else root / path / "__init__.py"
    doc = ast.get_docstring(ast.parse(f.read_text())) or ""
    return " ".join(doc.split("\n\n")[0].split()).replace("``", "`")


def _modules(path: str, root: Path) -> str:
    if path.endswith(".py"):
        return ""
    return ", ".join(f"`{p.name}`" for p in sorted((root / path).glob("*.py"))
                     if p.name != "__init__.py")


def layout_table(root: Path = ROOT) -> str:
    """The layout table of docs/architecture.md, top layer first."""
    rows = ["| layer | path | what it holds | modules |", "|---|---|---|---|"]
    for rank in reversed(range(len(LAYERS))):
        for path in LAYERS[rank]:
            shown = path if path.endswith(".py") else path + "/"
            rows.append(f"| {rank} | `{shown}` | {_doc(path, root)} | {_modules(path, root)} |")
    return "\n".join(rows)


def page_with_table(text: str, root: Path = ROOT) -> str:
    """The page's text with the generated table between the markers."""
    head, _, rest = text.partition(BEGIN)
    _, _, tail = rest.partition(END)
    return f"{head}{BEGIN}\n{layout_table(root)}\n{END}{tail}"


def main() -> int:
    page = PAGE
    text = page.read_text()
    if BEGIN not in text or END not in text:
        print(f"error: {PAGE.relative_to(ROOT)} has no {BEGIN} ... {END} block", file=sys.stderr)
        return 2
    page.write_text(page_with_table(text))
    return 0


if __name__ == "__main__":
    sys.exit(main())
