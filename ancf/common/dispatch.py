"""Compile-time dispatch on the type of a record: a lower layer declares a stub and
calls it from compiled code; each higher layer implements the stub for its own
``NamedTuple`` class, and numba picks the implementation from the argument's type.

    def system_solve(system, d): ...            # stub, in the layer that calls it

    @implements(system_solve, BeltSystem)       # in the layer that owns BeltSystem
    def _solve(system, d): ...

The first argument of a stub is the record; an implementation takes the stub's
arguments under the stub's names.  The record's class and its implementations belong
in one module, so any record that reaches compiled code has its implementations
registered.  Implementations are inlined into their callers (no call, no reference
counting of the record's arrays per call), and compiled callers keep ``cache=True``.
"""
from __future__ import annotations

import inspect

from numba import njit, types
from numba.extending import overload


def implements(stub, cls):
    """Decorator: the function is ``stub`` for records of the NamedTuple class ``cls``;
    returns it compiled (callable from Python too)."""
    def register(fn):
        def typer(record, *args):
            if isinstance(record, types.BaseNamedTuple) and record.instance_class is cls:
                return fn
            return None

        typer.__signature__ = inspect.signature(stub)
        overload(stub, inline="always")(typer)
        return njit(cache=True)(fn)

    return register
