"""Lean cache loads (:func:`ancf.common.process_start.lean_cache_loads`): a cached kernel is
loaded without readying numba's compiler, importing the numba modules whose code it inlined
or scanning for numba extensions, and gives the answer it gave when compiled; a signature
not in the cache is compiled as before.  Numba's import with importlib.metadata deferred
(:func:`ancf.common.process_start.metadata_on_first_use`)."""
from __future__ import annotations

import json
import os
import pickle
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

#: a cached kernel using an NRT array, a reduction (numba.np) and a string hash, and an
#: uncached function calling it (compiling it links the kernel's library)
KERNEL = '''
import numpy as np
from numba import njit


@njit(cache=True)
def kernel(a):
    b = np.empty_like(a)
    for i in range(a.size):
        b[i] = a[i] * a[i]
    return float(b.sum()) + (hash("ancf") != 0)


@njit
def twice(a):
    return 2.0 * kernel(a)
'''

#: a module only numba's compiler refresh imports (none of the loaded code needs it)
COMPILER_ONLY = "numba.np.random.generator_core"
#: the module of np.empty_like's implementation, inlined into the kernel (its environment)
INLINED = "numba.np.arrayobj"


def _call(folder: Path, lean: bool, dtypes=("float64",), linked: bool = False) -> dict:
    """In a fresh process, call the kernel on input of each of ``dtypes`` in turn: for each,
    its value, cache hits and misses so far, and whether numba's compiler tables are loaded,
    the inlined module :data:`INLINED` is imported, numba's extensions were scanned,
    numba's runtime library was loaded as machine code (not compiled in the process),
    numba announced LLVM lock events so far and the bitcode of the kernel's first library
    is still unparsed; with ``linked``, ``twice``'s value on the first input type (it
    links that library) and whether that bitcode is then still unparsed."""
    code = textwrap.dedent(f"""
        import json, sys
        import numpy as np
        sys.path.insert(0, {str(folder)!r})
        from ancf.common.process_start import lean_cache_loads
        if {lean}:
            lean_cache_loads()
        from kmod import kernel, twice
        from numba.core import entrypoints, event
        from numba.core.runtime import rtsys
        llvm = event.RecordingListener()
        event.register("numba:llvm_lock", llvm)
        out = {{}}
        for dtype in {dtypes!r}:
            value = kernel(np.array([5.0, -2.0, 7.0, 4.0, 1.0], dtype=dtype))
            first = next(iter(kernel.overloads.values())).library
            out[dtype] = [value, sum(kernel.stats.cache_hits.values()),
                          sum(kernel.stats.cache_misses.values()),
                          {COMPILER_ONLY!r} in sys.modules, {INLINED!r} in sys.modules,
                          entrypoints._already_initialized,
                          getattr(rtsys.library, "_compiled_object", 0) is None,
                          len(llvm.buffer) > 0, "_bitcode" in vars(first)]
        if {linked}:
            out["twice"] = [twice(np.array([5.0, -2.0, 7.0, 4.0, 1.0], dtype={dtypes[0]!r})),
                            "_bitcode" in vars(first)]
        print(json.dumps(out))
    """)
    env = dict(os.environ, NUMBA_CACHE_DIR=str(folder / "cache"))
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                       env=env, timeout=120)
    assert p.returncode == 0, p.stderr
    return json.loads(p.stdout.strip().splitlines()[-1])


def _expected(values) -> float:
    """The kernel's value by plain Python: the sum of squares, plus 1 (a nonzero hash)."""
    return sum(x * x for x in values) + 1.0


@pytest.mark.slow
def test_lean_load_reuses_the_cache_and_a_miss_compiles(tmp_path):
    """Rows (value, cache hits so far, misses so far, compiler tables loaded, inlined
    module imported, extensions scanned, runtime loaded from the cache, LLVM lock events
    announced, kernel bitcode unparsed)."""
    (tmp_path / "kmod.py").write_text(KERNEL)
    want = _expected([5.0, -2.0, 7.0, 4.0, 1.0])
    first = _call(tmp_path, lean=False)  # compiles and fills the cache
    assert first == {"float64": [want, 0, 1, True, True, True, False, True, False]}
    usual = _call(tmp_path, lean=False)  # the control: numba's own load readies its compiler
    assert usual == {"float64": [want, 1, 0, True, True, True, False, True, False]}
    lean = _call(tmp_path, lean=True, dtypes=("float64", "int64"))
    assert lean["float64"] == [want, 1, 0, False, False, False, False, False, True]
    assert lean["int64"] == [want, 1, 1, True, True, True, False, True, True]  # a miss
    # the runtime's machine code from the last process; a miss and a caller compiled after
    again = _call(tmp_path, lean=True, dtypes=("float64", "int32"), linked=True)
    assert again == {"float64": [want, 1, 0, False, False, False, True, False, True],
                     "int32": [want, 1, 1, True, True, True, True, True, True],
                     "twice": [2.0 * want, False]}  # linking parsed the kernel's bitcode
    assert _expected([5.0, -2.0, 7.0, 4.0, 2.0]) != want  # the check sees a changed input


def test_numba_imports_with_metadata_deferred_until_used():
    """importlib.metadata stays an unloaded lazy module through numba's import; its first use
    loads it and answers as pip's record does (numpy's version, read by numpy itself)."""
    code = textwrap.dedent("""
        import sys
        from ancf.common.process_start import metadata_on_first_use
        metadata_on_first_use()
        import numba, numpy
        lazy = type(sys.modules["importlib.metadata"]).__name__
        from importlib import metadata
        print(lazy, metadata.version("numpy") == numpy.__version__,
              type(sys.modules["importlib.metadata"]).__name__)
    """)
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                       timeout=120)
    assert p.returncode == 0, p.stderr
    assert p.stdout.split() == ["_LazyModule", "True", "module"]


def test_elf_symbols_are_the_bitcode_definitions(tmp_path):
    """The names numba reads from a library's bitcode (defined functions and globals) are
    those of its machine code's ELF symbol table (numba's runtime library as a lean
    process keeps it, compiled in a fresh process: in this one it would define the
    runtime's symbols twice); anything but an ELF64 little-endian object gives None."""
    import llvmlite.binding as ll

    from ancf.common.process_start import _elf_defined
    code = ("from ancf.common.process_start import lean_cache_loads\n"
            "lean_cache_loads()\n"
            "from numba.core.registry import cpu_target\n"
            "from numba.core.runtime import rtsys\n"
            "rtsys.initialize(cpu_target.target_context)\n")
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path))
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                       env=env, timeout=120)
    assert p.returncode == 0, p.stderr
    (path,) = (tmp_path / "ancf_nrt").glob("*.nbo")
    obj, bitcode = pickle.loads(path.read_bytes())[2]
    mod = ll.parse_bitcode(bitcode)
    defined = {v.name for vs in (mod.functions, mod.global_variables) for v in vs
               if not v.is_declaration}
    assert "NRT_incref" in defined and _elf_defined(obj) == defined
    assert _elf_defined(obj[:4] + b"\x01" + obj[5:]) is None  # a 32-bit ELF header


def test_compile_after_lean_loads_saves_to_the_cache(tmp_path):
    """Lean loads turned on 300 times (as the fuzz tests' ``ancf.cli.main`` calls in one
    pytest worker do),
    then a cache miss: the kernel compiles and numba saves it (its environment pickles by
    reference: a nested rebuild function once recursed without end, PicklingError), and a
    fresh process loads it from the cache."""
    (tmp_path / "kmod.py").write_text(KERNEL)
    code = textwrap.dedent(f"""
        import sys
        import numpy as np
        sys.path.insert(0, {str(tmp_path)!r})
        from ancf.common.process_start import lean_cache_loads
        for _ in range(300):
            lean_cache_loads()
        from kmod import kernel
        print(kernel(np.array([5.0, -2.0, 7.0, 4.0, 1.0])),
              sum(kernel.stats.cache_misses.values()))
    """)
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"))
    runs = [subprocess.run([sys.executable, "-W", "error::numba.NumbaWarning", "-c", code],
                           capture_output=True, text=True, cwd=ROOT, env=env, timeout=120)
            for _ in range(2)]
    assert all(p.returncode == 0 for p in runs), runs[0].stderr[-2000:]
    want = _expected([5.0, -2.0, 7.0, 4.0, 1.0])
    assert [p.stdout.split() for p in runs] == [[str(want), "1"], [str(want), "0"]]
