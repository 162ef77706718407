"""Leaf functions (ancf.common.leaf): compiled without reference counting, they work on
the arrays they are given (views included), and numba refuses one that makes an array."""
import numpy as np
import pytest
from numba import njit
from numba.core.errors import NumbaError

from ancf.common.leaf import leaf


@leaf
def _axpy(a, x, y):
    for i in range(x.size):
        y[i] += a * x[i]


@leaf
def _makes_an_array(x, y):
    t = x * 2.0
    y[:] = t


@njit
def _caller(x, y):
    _axpy(2.0, x[1:], y[1:])  # views from a counted caller
    return y


def test_leaf_works_on_given_arrays_and_views():
    y = _caller(np.arange(4.0), np.ones(4))
    assert y.tolist() == [1.0, 3.0, 5.0, 7.0]


def test_a_leaf_that_makes_an_array_is_refused():
    with pytest.raises(NumbaError, match="NRT required"):
        _makes_an_array(np.ones(3), np.zeros(3))
