"""Costs of a short ``ancf run`` process that are not its work: PyYAML and
importlib.metadata at numba's import, readying numba's compiler to load cached kernels,
and the interpreter's shutdown.

* ``numba.core.config`` imports PyYAML (10-15 ms CPU) only to read a ``.numba_config.yaml``
  in the working directory.  :func:`numba_without_yaml` lets numba be imported with
  ``yaml`` unimportable where no such file exists (numba then reads nothing either way);
  afterwards ``import yaml`` works as before.  With the file, nothing changes.
  :func:`metadata_on_first_use` defers importlib.metadata, which numba imports for its
  extension scan, to that scan (see below).
* The end of a process tears down every module numba and llvmlite loaded (about 25 ms
  CPU).  :func:`end_process` flushes the output and ends the process at once
  (``os._exit``): nothing in ``ancf run`` waits for the interpreter's exit handlers.  A
  numba chrome trace asked for (``NUMBA_CHROME_TRACE``) is written by one, so then the
  process ends the usual way.
* Numba readies its whole compiler before it looks in its on-disk cache (``refresh``: it
  imports every implementation module and fills its typing and lowering tables, about
  0.1 s CPU), though a cached kernel is machine code that needs only numba's runtime.
  :func:`lean_cache_loads` makes a cache load ready the runtime alone; a kernel not in the
  cache is compiled as before (numba's compiler refreshes the tables itself first).
  Two more costs of a cache load go with it: unpickling a kernel rebuilds the environment
  (module globals) of every numba implementation it inlined, importing that module
  (numba.np.arrayobj, arraymath, npyimpl, linalg: about 40 ms CPU), though only object-mode
  code ever reads those globals (``numba.core.pylowering``), and each first call scans every
  installed distribution for numba extensions (``entrypoints.init_all``, 10 ms), which only
  compiling needs (numba's compiler refresh runs that scan too).  The lean loads also keep
  numba's runtime library as machine code in the cache (:func:`_runtime_from_cache`), leave
  a library's bitcode unparsed until a compilation links it (:func:`_bitcode_when_linked`)
  and take llvmlite's lock without numba's events (:func:`_llvm_lock_unannounced`).
"""
from __future__ import annotations

import os
import pickle
import struct
import sys
from contextlib import contextmanager

NUMBA_CONFIG = ".numba_config.yaml"  # numba.core.config's file in the working directory


@contextmanager
def numba_without_yaml():
    """Within: ``import yaml`` fails (ImportError) unless yaml is loaded already or the
    working directory holds numba's config file."""
    block = "yaml" not in sys.modules and not os.path.isfile(NUMBA_CONFIG)
    if block:
        sys.modules["yaml"] = None
    try:
        yield
    finally:
        if block and sys.modules.get("yaml", 0) is None:
            del sys.modules["yaml"]


def metadata_on_first_use() -> None:
    """Import ``importlib.metadata`` lazily (:class:`importlib.util.LazyLoader`): numba's
    extension loader imports it with numba (8 ms CPU) but reads it only before compiling."""
    name = "importlib.metadata"
    if name in sys.modules:
        return
    import importlib
    import importlib.util
    spec = importlib.util.find_spec(name)
    spec.loader = importlib.util.LazyLoader(spec.loader)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    importlib.metadata = module


def end_process(code: int) -> None:
    """Flush stdout and stderr and end the process with ``code``, without the interpreter's
    shutdown (returns only where a chrome trace waits to be written at exit)."""
    if os.environ.get("NUMBA_CHROME_TRACE"):
        return
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(code)


def lean_cache_loads() -> None:
    """From now on numba loads a cached kernel after readying its runtime (NRT) only, not
    its compiler; a cache miss compiles as before (``CompilerBase`` refreshes first).  A
    numba whose cache lacks the loader this wraps keeps its own loads."""
    import numba.cpython.hashing  # noqa: F401  its import adds the hash-secret symbols
    from numba.core.caching import Cache
    from numba.core.runtime import rtsys
    if not hasattr(Cache, "_load_overload"):
        return

    def load_overload(self, sig, target_context):
        with _llvm_lock_unannounced():
            rtsys.initialize(target_context)
            with self._guard_against_spurious_io_errors():
                return self._load_overload(sig, target_context)
    Cache.load_overload = load_overload
    _environments_unimported()
    _extensions_at_compile()
    _runtime_from_cache()
    _bitcode_when_linked()


@contextmanager
def _llvm_lock_unannounced():
    """Within: llvmlite's calls take its lock without numba's ``numba:llvm_lock`` events.
    A cache load makes about 2300 such calls (reading the symbols of each kernel's
    module), each announced twice to numba's event system (3 us of 3.7 us a call, about
    9 ms CPU per run); the events feed only compile-time statistics and a chrome trace,
    which keeps them (``NUMBA_CHROME_TRACE``)."""
    from llvmlite.binding import ffi
    lock = getattr(ffi.lib, "_lock", None)
    callbacks = getattr(lock, "_cblist", None)
    if not isinstance(callbacks, list) or os.environ.get("NUMBA_CHROME_TRACE"):
        yield
        return
    saved = callbacks[:]
    callbacks.clear()
    try:
        yield
    finally:
        callbacks[:0] = saved


#: numba's own CPUCodeLibrary._unserialize (function) and _get_module_for_linking, kept
#: once :func:`_bitcode_when_linked` replaces them
_NUMBA_LIBRARY: list = []


def unserialize_library(cls, cg, state):
    """numba's ``CPUCodeLibrary._unserialize`` with the defined names read from the machine
    code and the bitcode kept unparsed (:func:`_bitcode_when_linked`).  At module level so
    that a library saved after :func:`lean_cache_loads` pickles it by reference."""
    name, kind, data = state
    names = _elf_defined(data[0]) if kind == "object" else None
    if names is None or not _NUMBA_LIBRARY:
        from numba.core import codegen
        original = _NUMBA_LIBRARY[0] if _NUMBA_LIBRARY else \
            codegen.CPUCodeLibrary._unserialize.__func__
        return original(cls, cg, state)
    self = cg.create_library(name)
    self.enable_object_caching()
    self._set_compiled_object(data[0])
    self._bitcode = data[1]
    self._finalize_final_module()
    cg._engine._defined_symbols |= names
    return self


def module_for_linking(self):
    """numba's ``_get_module_for_linking``, parsing a cached library's bitcode first."""
    import llvmlite.binding as ll
    bitcode = self.__dict__.pop("_bitcode", None)
    if bitcode is not None:
        self._shared_module = ll.parse_bitcode(bitcode)
    return _NUMBA_LIBRARY[1](self)


def _bitcode_when_linked() -> None:
    """A cached library holds its machine code and its LLVM bitcode, which numba parses at
    load (20-25 ms CPU a run) for two uses: the names it defines, and linking it into code
    compiled later.  The names are read from the machine code's ELF symbol table instead
    (the same set, checked on every cached library of the suite); the bitcode is parsed
    when a compilation first links the library (:func:`unserialize_library`,
    :func:`module_for_linking`).  Machine code that is not a 64-bit little-endian ELF
    object loads as numba does it."""
    from numba.core import codegen
    library = codegen.CPUCodeLibrary
    if _NUMBA_LIBRARY:
        return
    _NUMBA_LIBRARY[:] = [library._unserialize.__func__, library._get_module_for_linking]
    library._unserialize = classmethod(unserialize_library)
    library._get_module_for_linking = module_for_linking


def _elf_defined(obj: bytes):
    """Names of the functions and data an ELF64 little-endian object defines (its symbol
    table's named symbols of type NOTYPE, OBJECT or FUNC with a section), or None."""
    if obj[:6] != b"\x7fELF\x02\x01":
        return None
    shoff, = struct.unpack_from("<Q", obj, 0x28)
    size, count = struct.unpack_from("<HH", obj, 0x3A)
    sections = [struct.unpack_from("<IIQQQQIIQQ", obj, shoff + i * size) for i in range(count)]
    names = set()
    for _, kind, _, _, offset, length, link, _, _, entry in sections:
        if kind != 2:  # SHT_SYMTAB
            continue
        strings = sections[link][4]
        for k in range(offset, offset + length, entry):
            at, info, _, section = struct.unpack_from("<IBBH", obj, k)
            if at and section and info & 0xF <= 2:
                names.add(obj[strings + at:obj.index(b"\0", strings + at)].decode())
    return names


#: numba's own environment rebuild, kept once :func:`_environments_unimported` replaces it
_NUMBA_REBUILD: list = []


def rebuild_environment(modname, consts, env_name):
    """numba's ``environment._rebuild_env`` for a kernel's environment, without importing a
    module not imported yet (its globals ``{"__name__": modname}``).  At module level so
    that a kernel compiled after :func:`lean_cache_loads` pickles its environment by
    reference when numba saves it to the cache (a nested function pickled by value
    recursed without end, PicklingError)."""
    from numba.core import environment
    rebuild = _NUMBA_REBUILD[0] if _NUMBA_REBUILD else environment._rebuild_env
    if modname in sys.modules:
        return rebuild(modname, consts, env_name)
    env = environment.lookup_environment(env_name)
    if env is None:
        env = environment.Environment({"__name__": modname})
        env.consts[:] = consts
        env.env_name = env_name
        environment.Environment._memo[env_name] = env
    return env


def _environments_unimported() -> None:
    """An unpickled kernel's environment of a module not imported yet gets the globals
    ``{"__name__": module}`` instead of importing it (:func:`rebuild_environment`):
    nopython code never reads them, and pickling such an environment again gives the same
    state (module name, consts, name)."""
    from numba.core import environment
    if environment._rebuild_env is not rebuild_environment:
        _NUMBA_REBUILD[:] = [environment._rebuild_env]
        environment._rebuild_env = rebuild_environment


def _extensions_at_compile() -> None:
    """A dispatcher's first call no longer loads numba's extensions; the compiler's refresh
    before any compilation still does (``BaseContext.refresh``)."""
    from numba.core.dispatcher import _DispatcherBase
    _DispatcherBase._compilation_chain_init_hook = lambda self: None


def _runtime_from_cache() -> None:
    """Numba's runtime library (``nrtdynmod.compile_nrt_functions``: incref, decref and
    atomics, about 25 ms CPU to optimise and emit) is kept as machine code in numba's cache
    directory, named by a hash of its LLVM IR, the numba and llvmlite versions and the
    target machine; a later process loads it as it loads a cached kernel.  Without a cache
    directory, or with the file unreadable, it is compiled as before."""
    from numba.core import config
    from numba.core.runtime import nrtdynmod
    if not config.CACHE_DIR:
        return
    folder = os.path.join(config.CACHE_DIR, "ancf_nrt")

    def compile_nrt_functions(ctx):
        ir_mod, library = nrtdynmod.create_nrt_module(ctx)
        path = os.path.join(folder, _runtime_key(ctx, ir_mod) + ".nbo")
        try:
            with open(path, "rb") as f:
                return ctx.codegen().unserialize_library(pickle.load(f))
        except (OSError, EOFError, pickle.UnpicklingError, ValueError, TypeError):
            pass
        library.enable_object_caching()
        library.add_ir_module(ir_mod)
        library.finalize()
        _write_atomic(path, pickle.dumps(library.serialize_using_object_code()))
        return library
    nrtdynmod.compile_nrt_functions = compile_nrt_functions


def _runtime_key(ctx, ir_mod) -> str:
    """sha1 of the runtime's LLVM IR, numba's and llvmlite's versions and the target."""
    import hashlib

    import llvmlite
    import numba
    text = repr((numba.__version__, llvmlite.__version__, ctx.codegen().magic_tuple()))
    return hashlib.sha1((text + str(ir_mod)).encode()).hexdigest()


def _write_atomic(path: str, data: bytes) -> None:
    """Write ``data`` to ``path`` by a rename (readers see the whole file or none); a
    folder that cannot be written leaves the runtime uncached."""
    tmp = f"{path}.{os.getpid()}.tmp"
    try:
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(tmp, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except OSError:
        pass
