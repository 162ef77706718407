"""CPU time spent compiling numba kernels or loading them from numba's on-disk cache.

Numba compiles (or loads from its cache) a kernel on its first call with new argument
types, in the middle of whatever calls it: a run's first solve in a process pays seconds
of compilation with an empty cache and a tenth of a second of cache loading with a
warm one, against milliseconds for the solve itself.  :func:`compile_cpu` separates
the two.  It listens to numba's ``numba:compiler_lock`` event: every compilation and
every cache load of a dispatcher happens under numba's global compiler lock (a
``numba:compile`` event, by contrast, covers compilations only, not cache loads), and
nested acquisitions (a kernel compiling its callees) are counted once, as the outermost
span.  Seconds are process CPU seconds (:func:`time.process_time`), like the runs'
``cpu_time_s``.

Numba is listened to only when it is already imported: this module never imports it,
so a command that uses no kernel pays nothing (and reports 0).
"""
from __future__ import annotations

import contextlib
import sys
import time
from functools import lru_cache


class CompileTime:
    """CPU seconds spent under numba's compiler lock while the block ran."""

    def __init__(self):
        self.seconds = 0.0
        self.spans = 0  # outermost lock spans (dispatcher compilations or cache loads)
        self._depth = 0
        self._t0 = 0.0

    def on_start(self, event=None):
        if self._depth == 0:
            self._t0 = time.process_time()
        self._depth += 1

    def on_end(self, event=None):
        self._depth -= 1
        if self._depth == 0:
            self.seconds += time.process_time() - self._t0
            self.spans += 1


@contextlib.contextmanager
def compile_cpu():
    """Yield a :class:`CompileTime` that counts the compilations and cache loads of the block."""
    timer = CompileTime()
    event = sys.modules.get("numba.core.event")
    if event is None:
        yield timer
        return
    with event.install_listener("numba:compiler_lock", _forwarder(event.Listener)(timer)):
        yield timer


@lru_cache(maxsize=None)
def _forwarder(listener):
    """A subclass of numba's ``Listener`` passing its events to a :class:`CompileTime`,
    made once (a class statement costs 30 us, against a 1 ms run it would be timed in)."""
    class Forward(listener):
        def __init__(self, timer: CompileTime):
            self.timer = timer

        def on_start(self, ev):
            self.timer.on_start(ev)

        def on_end(self, ev):
            self.timer.on_end(ev)
    return Forward
