"""Linear solvers behind one interface, chosen by the pattern (:class:`ReducedPattern`).

* band storage (open chains, and closed loops after reverse Cuthill-McKee): the
  compiled band LU of :mod:`ancf.solvers.banded`, O(n kl^2);
* CSR (patterns whose band would be mostly zeros, e.g. a coordinate coupled to
  every node): SuperLU.

:func:`factor` returns an object with ``solve(rhs)``; a singular or non-finite
matrix raises :class:`Singular`.  :func:`stability` counts the negative and zero
eigenvalues of a symmetric tangent by inertia (Sylvester's law: negative pivots of
an LDL^T of ``K - s I``), at any size, and finds the lowest eigenvalue by
bisection on those counts.

scipy's sparse solvers (and the scipy.linalg they import) load on the first CSR
pattern only: band patterns, the common case, do not need them.
"""
from __future__ import annotations

import warnings

import numpy as np
from numba import njit

from ancf.solvers import banded

#: |lambda| / max|lambda| below this is a zero-energy mode (the softest legitimate
#: mode in the suite, a 64-element cantilever at L/h = 1e4, is 2.8e-13)
ZERO_EIGENVALUE_REL = 1e-14
NEGATIVE_EIGENVALUE_REL = 1e-9
#: relative precision of the lowest eigenvalue found by bisection on inertia counts
LOWEST_RTOL = 1e-3
#: inverse iterations allowed for the lowest eigenvalue of a positive definite matrix
INVERSE_ITERATIONS = 60


class Singular(Exception):
    """The matrix could not be factored (zero pivot, non-finite entries)."""


class _BandLU:
    def __init__(self, data, kl, overwrite=False):
        self.AB, self.kl = (data if overwrite else np.array(data)), kl
        self.piv = np.empty(data.shape[0], dtype=np.int64)
        k = banded.lu(self.AB, kl, self.piv, True)
        if k:
            raise Singular(f"zero pivot in column {k - 1}")

    def solve(self, rhs):
        """Solve for a vector, or for each column of a matrix."""
        x = np.array(rhs, dtype=float)
        if x.ndim == 2:
            return np.stack([self.solve(c) for c in x.T], axis=1)
        banded.solve(self.AB, self.kl, self.piv, x)
        if not np.isfinite(x).all():  # the method: no Python wrapper per call
            raise Singular("non-finite solution")
        return x


class _SparseLU:
    def __init__(self, A):
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            try:
                import scipy.sparse.linalg as spla
                self.lu = spla.splu(A.tocsc())
            except (RuntimeError, Warning) as exc:
                raise Singular(str(exc)) from None

    def solve(self, rhs):
        x = self.lu.solve(np.asarray(rhs, dtype=float))
        if not np.all(np.isfinite(x)):
            raise Singular("non-finite solution")
        return x


def factor(pattern, data, overwrite=False):
    """LU of the matrix stored as ``data`` in ``pattern``'s storage (band storage is
    factored in place with ``overwrite``).  Non-finite entries show as a non-finite
    solution."""
    if pattern.band:
        return _BandLU(data, pattern.kl, overwrite)
    return _SparseLU(pattern.as_csr(data))


def _sparse_count_below(A, shift) -> int:
    import scipy.sparse as sp
    import scipy.sparse.linalg as spla
    S = (A - shift * sp.identity(A.shape[0], format="csr")).tocsc()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            lu = spla.splu(S, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                           options={"SymmetricMode": True})
        except (RuntimeError, Warning):
            return -1
    return int(np.sum(lu.U.diagonal() < 0))


def counter(pattern, data):
    """The function ``s -> number of eigenvalues of the stored symmetric matrix below s``
    (-1 where a pivot of the LDL^T of ``data - s I`` is exactly zero)."""
    if pattern.band:
        return lambda s: banded.count_below(data, pattern.kl, s)
    A = pattern.as_csr(data)
    return lambda s: _sparse_count_below(A, s)


def _top(pattern, data) -> float:
    """Largest eigenvalue magnitude of a CSR-stored symmetric matrix (ARPACK)."""
    import scipy.sparse.linalg as spla
    v0 = 1.0 + 0.5 * np.sin(1.0 + 7.0 * np.arange(pattern.n))  # reproducible runs
    return float(abs(spla.eigsh(pattern.as_csr(data), k=1, which="LM", v0=v0,
                                return_eigenvectors=False)[0]))


def _lowest_by_bisection(count, top) -> float:
    """Lowest eigenvalue / top of an indefinite matrix: bisection on the magnitude of
    the most negative eigenvalue (log scale), to LOWEST_RTOL."""
    lo, hi = np.log(1e-300), np.log(2.0)
    while hi - lo > LOWEST_RTOL:
        mid = 0.5 * (lo + hi)
        if count(-np.exp(mid) * top) >= 1:
            lo = mid
        else:
            hi = mid
    return float(-np.exp(0.5 * (lo + hi)))


@njit(cache=True)
def _band_stability(data, kl, x, iterations, rtol):
    """:func:`stability` of a band-stored matrix in one compiled call, the same steps:
    (top = largest |eigenvalue| by power iteration, negative count, zero count, count
    below the zero band, column + 1 of a zero pivot of the LU (0: none), mu, finite);
    mu the lowest eigenvalue by inverse iteration from ``x`` when the count below the
    zero band is 0 and the LU succeeded, else 0."""
    n = data.shape[0]
    top = banded.largest_magnitude(data, kl, 40)
    if top == 0.0:
        return top, 0, n, 0, 0, 0.0, True
    neg = banded.count_below(data, kl, -NEGATIVE_EIGENVALUE_REL * top)
    below = banded.count_below(data, kl, ZERO_EIGENVALUE_REL * top)
    zero = 0 if below == neg else below - banded.count_below(data, kl, -ZERO_EIGENVALUE_REL * top)
    if below != 0:
        return top, neg, zero, below, 0, 0.0, True
    AB, piv = data.copy(), np.empty(n, dtype=np.int64)
    k = banded.lu(AB, kl, piv, bool(True))  # not a literal: one compilation of lu
    if k != 0:
        return top, neg, zero, below, k, 0.0, True
    mu, finite = _band_inverse_iteration(AB, kl, piv, x, iterations, rtol)
    return top, neg, zero, below, 0, mu, finite


@njit(cache=True)
def _band_inverse_iteration(AB, kl, piv, x, iterations, rtol):
    """(mu, finite): the Rayleigh quotient of inverse iteration (x <- K^-1 x) on the band
    LU (AB, piv), stopped when it settles to ``rtol``; finite False on a non-finite
    iterate."""
    mu = np.inf
    for _ in range(iterations):
        x = x / np.sqrt(np.dot(x, x))
        y = x.copy()
        banded.solve(AB, kl, piv, y)
        if not np.all(np.isfinite(y)):
            return mu, False
        new = 1.0 / np.dot(x, y)
        if abs(new - mu) <= rtol * abs(new):
            return new, True
        mu, x = new, y
    return mu, True


def _start(n: int) -> np.ndarray:
    """The start vector of inverse iteration (n,)."""
    return 1.0 + 0.5 * np.sin(1.0 + 7.0 * np.arange(n))


def _lowest_by_inverse_iteration(lu, n, top, iterations=INVERSE_ITERATIONS) -> float:
    """Lowest eigenvalue / top of a positive definite matrix: inverse iteration
    (x <- K^-1 x) with the factorisation at hand (SuperLU), stopped when the Rayleigh
    quotient settles to LOWEST_RTOL."""
    x = _start(n)
    mu = np.inf
    for _ in range(iterations):
        x /= np.linalg.norm(x)
        y = lu.solve(x)
        new = 1.0 / float(x @ y)
        if abs(new - mu) <= LOWEST_RTOL * abs(new):
            return new / top
        mu, x = new, y
    return mu / top


def stability(pattern, data):
    """(negative eigenvalues, zero eigenvalues, lowest eigenvalue / largest magnitude)
    of the symmetric matrix in ``data``: negative below -1e-9 of the largest magnitude,
    zero within +-1e-14 of it (the thresholds of the former dense check).  Costs two
    factorisations plus a few solves when the matrix is positive definite."""
    if pattern.n == 0:
        return 0, 0, None
    if pattern.band:
        return _stability_band(pattern, data)
    top = _top(pattern, data)
    if top == 0.0:
        return 0, pattern.n, 0.0
    count = counter(pattern, data)
    neg = count(-NEGATIVE_EIGENVALUE_REL * top)
    below_zero_band = count(ZERO_EIGENVALUE_REL * top)
    zero = 0 if below_zero_band == neg else below_zero_band - count(-ZERO_EIGENVALUE_REL * top)
    if below_zero_band == 0:
        return int(neg), int(zero), _lowest_by_inverse_iteration(factor(pattern, data), pattern.n, top)
    return int(neg), int(zero), _lowest_by_bisection(count, top)


def _stability_band(pattern, data):
    """:func:`stability` on band storage (:func:`_band_stability`; bisection in Python)."""
    top, neg, zero, below, k, mu, finite = _band_stability(
        data, pattern.kl, _start(pattern.n), INVERSE_ITERATIONS, LOWEST_RTOL)
    if top == 0.0:
        return 0, pattern.n, 0.0
    if below != 0:
        return int(neg), int(zero), _lowest_by_bisection(counter(pattern, data), top)
    if k:
        raise Singular(f"zero pivot in column {k - 1}")
    if not finite:
        raise Singular("non-finite solution")
    return int(neg), int(zero), mu / top
