"""Import hygiene: ``ancf run`` loads no heavy library it does not use, and no module
imports one that imports it back (at module level or inside a function)."""
from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
HEAVY = ("sympy", "pandas", "dask", "matplotlib", "meshio")


@pytest.mark.parametrize("argv", [["run", "cantilever", "--json"],
                                  ["run", "pendulum", "--set", "t_end=0.05", "--json"]])
def test_run_imports_no_heavy_library(argv):
    code = ("import sys\nfrom ancf import cli\nrc = cli.main(%r)\n"
            "print(sorted(m for m in %r if m in sys.modules), file=sys.stderr)\n") % (argv, HEAVY)
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                       timeout=300)
    assert p.returncode == 0, p.stderr
    assert p.stderr.strip().splitlines()[-1] == "[]"


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _imports(path: Path, modules: set) -> set:
    """Project modules imported anywhere in a file (``from pkg import mod`` -> pkg.mod)."""
    out = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            out.update(f"{node.module}.{a.name}" if f"{node.module}.{a.name}" in modules
                       else node.module for a in node.names)
    return out & modules


def _graph() -> dict:
    files = [p for pkg in ("ancf", "analytic") for p in (ROOT / pkg).rglob("*.py")]
    modules = {_module_name(p) for p in files}
    return {_module_name(p): _imports(p, modules) - {_module_name(p)} for p in files}


def _cycle_through(graph, start):
    """A path start -> ... -> start, or None."""
    stack, seen = [(start, [start])], set()
    while stack:
        node, path = stack.pop()
        for nxt in graph.get(node, ()):
            if nxt == start:
                return path + [start]
            if nxt not in seen:
                seen.add(nxt)
                stack.append((nxt, path + [nxt]))
    return None


def test_no_import_cycles():
    graph = _graph()
    assert len(graph) > 30  # the walk found the project
    cycles = [c for m in sorted(graph) if (c := _cycle_through(graph, m))]
    assert not cycles, " | ".join(" -> ".join(c) for c in cycles[:5])


def test_numba_cache_follows_the_sources(tmp_path):
    """Any edit of a source starts a fresh numba cache (a cached caller would otherwise keep
    the old code of the kernels it compiles in); unchanged sources reuse theirs."""
    import ancf
    (tmp_path / "a.py").write_text("x = 1\n")
    first = ancf.numba_cache_dir(tmp_path)
    assert ancf.numba_cache_dir(tmp_path) == first and first.parent.name == "ancf-bench"
    (tmp_path / "a.py").write_text("x = 2\n")
    assert ancf.numba_cache_dir(tmp_path) != first
