"""Import hygiene: ``ancf run`` loads no heavy library it does not use, and no module
imports one that imports it back (at module level or inside a function)."""
from __future__ import annotations

import ast
import os
import subprocess
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
HEAVY = ("sympy", "pandas", "dask", "matplotlib", "meshio")


@pytest.mark.slow
@pytest.mark.parametrize("argv", [["run", "cantilever", "--json"],
                                  ["run", "pendulum", "--set", "t_end=0.05", "--json"],
                                  ["modes", "plate-square", "--json"]])
def test_run_imports_no_heavy_library(argv):
    code = ("import sys\nfrom ancf import cli\nrc = cli.main(%r)\n"
            "print(sorted(m for m in %r if m in sys.modules), file=sys.stderr)\n") % (argv, HEAVY)
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                       timeout=300)
    assert p.returncode == 0, p.stderr
    assert p.stderr.strip().splitlines()[-1] == "[]"


def _loaded_after(argv, prefixes) -> list:
    """Modules starting with one of ``prefixes`` loaded by ``cli.main(argv)`` in a fresh process."""
    code = ("import sys\nfrom ancf import cli\ntry:\n    cli.main(%r)\nexcept SystemExit:\n    pass\n"
            "print(sorted(m for m in sys.modules if m.startswith(%r)), file=sys.stderr)\n"
            ) % (argv, tuple(prefixes))
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                       timeout=300)
    return eval(p.stderr.strip().splitlines()[-1])


@pytest.mark.parametrize("argv", [["--help"], ["run", "--help"], ["run"]])
def test_help_loads_no_numerics(argv):
    """``ancf --help`` (and argparse's errors) is argparse alone: no numba, numpy or scipy."""
    assert _loaded_after(argv, ("numba", "numpy", "scipy", "ancf.scenes")) == []


def test_static_run_loads_no_sparse_matrices():
    """``ancf run cantilever`` numbers its band system from the elimination's selection
    (:class:`ancf.core.constraints.Selection`): scipy.sparse is never loaded, nor threadpoolctl (the BLAS
    pool is pinned by the environment before numpy loads)."""
    loaded = _loaded_after(["run", "cantilever", "--json"], ("scipy.sparse", "pandas",
                                                             "matplotlib", "sympy", "dask",
                                                             "threadpoolctl"))
    assert loaded == []


def test_static_run_loads_blas_without_scipy_linalg():
    """Numba's BLAS check takes scipy's BLAS module alone (:mod:`ancf.common.blas`): not the
    scipy.linalg package, whose import also loads numpy.f2py and numpy.testing (0.09 s)."""
    loaded = _loaded_after(["run", "cantilever", "--json"],
                           ("scipy.linalg", "numpy.f2py", "numpy.testing"))
    assert loaded == ["scipy.linalg.cython_blas"]


@pytest.mark.slow
def test_the_preloaded_blas_serves_numba_and_scipy_linalg():
    """After the preload, a kernel's matrix product runs on it, and a later ``import
    scipy.linalg`` is the usual package, with the same BLAS module."""
    code = ("import sys, numpy as np\nfrom ancf.common.blas import preload_cython_blas\n"
            "assert preload_cython_blas()\nblas = sys.modules['scipy.linalg.cython_blas']\n"
            "import numba\nf = numba.njit(lambda a: a @ a)\n"
            "a = np.arange(9.0).reshape(3, 3)\nassert np.allclose(f(a), a @ a)\n"
            "import scipy.linalg\nfrom scipy.linalg import cython_blas\n"
            "assert cython_blas is blas and 'scipy.linalg' in sys.modules\n"
            "assert np.allclose(scipy.linalg.solve(a + np.eye(3) * 9, a[0]),\n"
            "                   np.linalg.solve(a + np.eye(3) * 9, a[0]))\n")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                       timeout=300)
    assert p.returncode == 0, p.stderr


def test_run_loads_its_scene_only():
    """``ancf run cantilever`` imports the cantilever's modules: no other scene, no belt
    element or model, no analytic reference, and none of scipy's modules that load
    scipy.linalg (csgraph, sparse.linalg) on a band pattern."""
    loaded = _loaded_after(["run", "cantilever", "--json"],
                           ("ancf.scenes.", "ancf.belts", "ancf.elements.belt3d",
                            "ancf.elements.dufva2d", "analytic", "scipy.sparse.csgraph",
                            "scipy.sparse.linalg"))
    assert "ancf.scenes.cantilever" in loaded  # the probe sees the scene it ran
    assert [m for m in loaded if not m.startswith("ancf.scenes.")] == []
    assert set(loaded) == {"ancf.scenes.cantilever", "ancf.scenes.base", "ancf.scenes.accuracy",
                           "ancf.scenes.beam_static"}


def test_modes_loads_its_scene_only():
    """``ancf modes cantilever`` imports the cantilever's modules, the mode shapes' sampler
    and the eigensolver: no other scene, no belt, no analytic reference."""
    loaded = _loaded_after(["modes", "cantilever", "--json"],
                           ("ancf.scenes.", "ancf.belts", "ancf.elements.belt3d",
                            "ancf.elements.dufva2d", "analytic", "ancf.solvers.eigen"))
    assert set(loaded) == {"ancf.scenes.cantilever", "ancf.scenes.base", "ancf.scenes.accuracy",
                           "ancf.scenes.beam_static", "ancf.scenes.frames", "ancf.scenes.modes",
                           "ancf.solvers.eigen"}


def test_the_scenes_with_modes_are_those_that_declare_them():
    """ancf.scenes.modes.MODAL (what ``ancf modes`` accepts by name) is every scene with a
    modal model, in the order of the scenes."""
    import ancf.scenes as scenes
    from ancf.scenes.modes import MODAL
    assert list(MODAL) == [n for n, sc in scenes.SCENES.items() if sc.modal is not None]


def test_scene_table_names_every_scene():
    """ancf.scenes.MODULES (what ``ancf run`` imports by name) matches the scenes' own names."""
    import ancf.scenes as scenes
    assert list(scenes.SCENES) == list(scenes.MODULES)
    assert all(scenes.scene(n).name == n for n in scenes.MODULES)
    mods = {p.stem for p in (ROOT / "ancf" / "scenes").glob("*.py")
            if re.search(r"^SCENE = \w*Scene\(", p.read_text(), flags=re.M)}
    assert mods == set(scenes.MODULES.values())


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
    """An edit of a kernel folder's source starts a fresh numba cache (a cached caller would
    otherwise keep the old code of the kernels it compiles in); unchanged sources, and
    edits above the kernel layers (a scene's), reuse theirs."""
    import ancf
    for folder in ("belts", "scenes"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "a.py").write_text("x = 1\n")
    first = ancf.numba_cache_dir(tmp_path)
    assert ancf.numba_cache_dir(tmp_path) == first and first.parent.name == "ancf-bench"
    (tmp_path / "scenes" / "a.py").write_text("x = 2\n")
    assert ancf.numba_cache_dir(tmp_path) == first
    (tmp_path / "belts" / "a.py").write_text("x = 2\n")
    assert ancf.numba_cache_dir(tmp_path) != first


def test_numba_cache_follows_the_optimisation_level(tmp_path, monkeypatch):
    """Numba's cache does not key by NUMBA_OPT: a level other than its default 3 (make test's
    1) compiles into a directory of its own, so test-compiled kernels never serve a report;
    3 spelled out is the default's directory."""
    import ancf
    (tmp_path / "belts").mkdir()
    (tmp_path / "belts" / "a.py").write_text("x = 1\n")
    monkeypatch.delenv("NUMBA_OPT", raising=False)
    default = ancf.numba_cache_dir(tmp_path)
    monkeypatch.setenv("NUMBA_OPT", "3")
    assert ancf.numba_cache_dir(tmp_path) == default
    monkeypatch.setenv("NUMBA_OPT", "1")
    assert ancf.numba_cache_dir(tmp_path) == default.with_name(default.name + "-opt1")


def test_a_numba_cache_dir_set_is_kept_without_hashing_the_sources(tmp_path):
    """``NUMBA_CACHE_DIR`` set by the user is kept, and ``import ancf`` then reads and hashes
    no source (no hashlib); unset, it is :func:`ancf.numba_cache_dir`, found by hashing."""
    import os

    import ancf
    code = "import os, sys, ancf\nprint(os.environ['NUMBA_CACHE_DIR'], 'hashlib' in sys.modules)"
    # NUMBA_OPT (make test sets 1) appends its suffix: the test above covers it
    base = {k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "NUMBA_OPT")}
    runs = {}
    for name, extra in (("set", {"NUMBA_CACHE_DIR": str(tmp_path / "mine")}), ("unset", {})):
        p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                           cwd=ROOT, env={**base, "XDG_CACHE_HOME": str(tmp_path), **extra},
                           timeout=60)
        assert p.returncode == 0, p.stderr
        runs[name] = p.stdout.split()
    assert runs["set"] == [str(tmp_path / "mine"), "False"]
    assert runs["unset"][0] == str(tmp_path / "ancf-bench" / ancf.source_hash(
        folders=ancf.KERNEL_FOLDERS)) and runs["unset"][1] == "True"


def test_compiled_code_lives_in_the_kernel_folders():
    """Every module that compiles (njit, jit, leaf, overload, vectorize: as a decorator or
    called) lies in ancf.KERNEL_FOLDERS, whose sources alone name the numba cache; a layer
    it imports is one of them too (the layers import downwards only).  Using numba's
    runtime (the CLI's compiler warm-up, the sweep pool's compile events) compiles
    nothing of ours."""
    import re

    import ancf
    from ancf.common.layers import LAYERS  # noqa: F401  (the layer table this relies on)
    root = Path(ancf.__file__).resolve().parent
    pattern = re.compile(r"(@|\b)(njit|jit|leaf|overload|vectorize|guvectorize)\b\s*[(\n]")
    outside = [p.relative_to(root).as_posix() for p in root.rglob("*.py")
               if pattern.search(p.read_text())
               and p.relative_to(root).parts[0] not in ancf.KERNEL_FOLDERS]
    assert outside == []
    assert pattern.search((root / "belts" / "contact2d.py").read_text())  # it sees kernels
    assert pattern.search("@njit(cache=True)\ndef f(x):\n") and not pattern.search("njit")


@pytest.mark.slow
def test_scenes_listing_is_kept_for_the_sources(tmp_path):
    """``ancf scenes`` lists from the scenes the first time in a source tree, and from the
    text kept beside numba's cache after that: the same text, no scene or numba loaded."""
    import os
    code = ("import sys\nfrom ancf import cli\ncli.main(['scenes'])\n"
            "print(sorted(m for m in sys.modules if m.startswith(('ancf.scenes', 'numba'))),"
            " file=sys.stderr)\n")
    env = {**os.environ, "XDG_CACHE_HOME": str(tmp_path)}
    runs = [subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                           cwd=ROOT, env=env, timeout=300) for _ in range(2)]
    assert all(p.returncode == 0 for p in runs), runs[0].stderr
    first, second = runs
    assert first.stdout == second.stdout and "Scenes (ancf run NAME):" in first.stdout
    assert "ancf.scenes.cantilever" in first.stderr.splitlines()[-1]
    assert second.stderr.strip().splitlines()[-1] == "[]"
    assert list(tmp_path.glob("ancf-bench/*/scenes-*.txt"))


@pytest.mark.slow
def test_run_loads_numba_without_yaml_unless_numba_has_a_config_file(tmp_path):
    """numba imports PyYAML (10-15 ms) only to read a .numba_config.yaml in the working
    directory: `ancf run` loads numba without it where there is none (after it, `import
    yaml` works), and with it where there is one."""
    code = ("import sys\nfrom ancf import cli\ncli.main(['run', 'cantilever', '--json'])\n"
            "print('yaml' in sys.modules, file=sys.stderr)\nimport yaml\n"
            "print(yaml.safe_load('a: 1'), file=sys.stderr)\n")
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    for cwd, loaded in ((ROOT, "False"), (tmp_path, "True")):
        if cwd == tmp_path:
            (tmp_path / ".numba_config.yaml").write_text("# read by numba\n")
        p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                           cwd=cwd, env=env, timeout=300)
        assert p.returncode == 0, p.stderr
        assert p.stderr.strip().splitlines()[-2:] == [loaded, "{'a': 1}"]


def test_a_run_process_ends_at_once_with_its_output_whole(monkeypatch):
    """`ancf run` ends with os._exit after flushing (no interpreter shutdown: 25 ms): the
    JSON on a pipe is whole and the exit code the run's (3: the solver failed)."""
    import json
    from ancf.common.process_start import end_process
    p = subprocess.run([sys.executable, "-m", "ancf.cli", "run", "cantilever", "--json", "--set",
                        "F=-5e6", "--set", "load_steps=1", "--set", "max_iterations=1"],
                       capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert p.returncode == 3 and json.loads(p.stdout)["converged"] is False
    monkeypatch.setenv("NUMBA_CHROME_TRACE", "trace.json")  # written at exit: the usual end
    assert end_process(0) is None
