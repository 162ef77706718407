"""Compiled leaf functions: the small functions a compiled loop calls per point or per
element that make no arrays (they read and write the arrays they are given).

Compiled code counts references on each array argument of a call (an atomic increment
and decrement per array); for a function that does a few dozen flops per point over a
handful of arrays that costs as much as the work.  :func:`leaf` compiles without the
runtime's reference counting (numba's ``_nrt=False``): the function may then not make
arrays, slices and views are fine, and numba refuses at compile time what would need
it ("NRT required but not enabled").  One place for that flag.
"""
from __future__ import annotations

from numba import njit


def leaf(fn):
    """``fn`` compiled as a leaf (cached, no reference counting)."""
    return njit(cache=True, _nrt=False)(fn)
