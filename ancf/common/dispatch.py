"""Compile-time dispatch on the type of a record: a lower layer declares a stub and
calls it from compiled code; each higher layer implements the stub for its own
``NamedTuple`` class, and numba picks the implementation from the argument's type.

    def system_solve(system, d): ...            # stub, in the layer that calls it

    @implements(system_solve, BeltSystem)       # in the layer that owns BeltSystem
    def _solve(system, d): ...

The first argument of a stub is the record; an implementation takes the stub's
arguments under the stub's names.  The record's class and its implementations belong
in one module, so any record that reaches compiled code has its implementations
registered.  Implementations are inlined into their callers, and compiled callers
keep ``cache=True``.

A record with many arrays is costly to hand on inside a compiled loop: every pass
(a call, an inlined implementation's argument) counts a reference of each array.
:func:`as_struct` turns it, once, into a struct reference of the same fields and
names (one count per pass); the implementations of the record's class serve both.
"""
from __future__ import annotations

import importlib
import inspect

from numba import njit, types
from numba.experimental import structref
from numba.extending import overload

_STRUCTS: dict = {}
_IMPLEMENTED: set = set()  # record classes with implementations


def _struct_class(cls):
    """The StructRef class of the record class ``cls``, registered once under a name
    this module resolves again (:func:`__getattr__`), so that cached code that names
    it loads in a fresh process."""
    if cls not in _STRUCTS:
        name = "S__" + "__".join(cls.__module__.split(".") + [cls.__qualname__])
        struct = type(name, (types.StructRef,), {"record_class": cls, "__module__": __name__})
        _STRUCTS[cls] = structref.register(struct)
    return _STRUCTS[cls]


def __getattr__(name):
    """The StructRef class named by :func:`_struct_class` (importing its record's module)."""
    if not name.startswith("S__"):
        raise AttributeError(name)
    *module, qualname = name[3:].split("__")
    return _struct_class(getattr(importlib.import_module(".".join(module)), qualname))


def _struct_type(record):
    """The struct-reference type with the fields of the numba NamedTuple type ``record``."""
    fields = [(f, _field_type(t)) for f, t in zip(record.fields, record.types)]
    return _struct_class(record.instance_class)(fields)


def _is(record, cls) -> bool:
    """Whether the numba type ``record`` is a record of ``cls`` (tuple or struct)."""
    if isinstance(record, types.BaseNamedTuple):
        return record.instance_class is cls
    return isinstance(record, types.StructRef) and getattr(record, "record_class", None) is cls


def implements(stub, cls):
    """Decorator: the function is ``stub`` for records of the NamedTuple class ``cls``
    (as the tuple or as its :func:`as_struct`); returns it compiled (callable from
    Python too)."""
    _IMPLEMENTED.add(cls)

    def register(fn):
        def typer(record, *args):
            return fn if _is(record, cls) else None

        typer.__signature__ = inspect.signature(stub)
        overload(stub, inline="always")(typer)
        return njit(cache=True)(fn)

    return register


def as_struct(record):
    """The NamedTuple ``record`` as a struct reference with the same field names, its
    fields that are records of classes with implementations converted too (from
    compiled code)."""
    raise NotImplementedError("compiled code only")


def _has_implementations(t) -> bool:
    return isinstance(t, types.BaseNamedTuple) and t.instance_class in _IMPLEMENTED


def _field_type(t):
    return _struct_type(t) if _has_implementations(t) else t


@overload(as_struct)
def _as_struct(record):
    if not isinstance(record, types.BaseNamedTuple):
        return None
    struct_type = _struct_type(record)
    lines = [f"    s.{f} = as_struct(record.{f})" if _has_implementations(t) else
             f"    s.{f} = record.{f}" for f, t in zip(record.fields, record.types)]
    src = "def impl(record):\n    s = new(struct_type)\n" + "\n".join(lines) + "\n    return s\n"
    scope = {"new": structref.new, "struct_type": struct_type, "as_struct": as_struct}
    exec(src, scope)  # the field names are known only here, at compile time
    return scope["impl"]
