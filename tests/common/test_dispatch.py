"""Compile-time dispatch on records (ancf.common.dispatch): the implementation is
chosen by the record's class, the same for the NamedTuple and for its struct
reference (as_struct), nested records converted too, and the struct classes resolve
by name in a fresh process (cached code that names them loads)."""
import pickle
import subprocess
import sys
from typing import NamedTuple

import numpy as np
import pytest
from numba import njit, types

from ancf.common import dispatch
from ancf.common.dispatch import as_struct, implements


def weigh(record, x):
    """Stub: a number from the record and x."""
    raise NotImplementedError


class Inner(NamedTuple):
    w: np.ndarray


class Outer(NamedTuple):
    inner: tuple
    a: np.ndarray
    k: int


class Other(NamedTuple):
    a: np.ndarray


@implements(weigh, Inner)
def _weigh_inner(record, x):
    return np.dot(record.w, x)


@implements(weigh, Outer)
def _weigh_outer(record, x):
    return weigh(record.inner, x) + record.k * record.a.sum()


@implements(weigh, Other)
def _weigh_other(record, x):
    return -record.a.sum()


@njit
def _both(record, x):
    return weigh(record, x), weigh(as_struct(record), x)


@njit
def _fields(record):
    s = as_struct(record)
    return s.inner.w.sum(), s.a.size, s.k


def _outer():
    return Outer(Inner(np.array([1.0, 2.0])), np.array([0.5, 0.25]), 3)


@pytest.mark.slow
def test_tuple_and_struct_dispatch_alike():
    x = np.array([10.0, 100.0])
    assert _both(_outer(), x) == (212.25, 212.25)
    assert _both(Other(np.array([4.0])), x) == (-4.0, -4.0)


def test_nested_records_become_structs_with_their_fields():
    assert _fields(_outer()) == (3.0, 2, 3)
    (sig,) = _fields.signatures
    st = dispatch._struct_type(sig[0])
    assert isinstance(st, types.StructRef) and st.record_class is Outer
    assert isinstance(st.field_dict["inner"], types.StructRef)
    assert st.field_dict["k"] == types.int64


def test_struct_class_resolves_by_name_in_a_fresh_process():
    from ancf.solvers.alpha_compiled import ReducedSystem
    cls = dispatch._struct_class(ReducedSystem)
    assert getattr(dispatch, cls.__name__) is cls
    code = ("import pickle, sys; c = pickle.loads(sys.stdin.buffer.read()); "
            "print(c.record_class.__module__, c.record_class.__name__)")
    out = subprocess.run([sys.executable, "-c", code], input=pickle.dumps(cls),
                         capture_output=True, check=True)
    assert out.stdout.decode().split() == ["ancf.solvers.alpha_compiled", "ReducedSystem"]
