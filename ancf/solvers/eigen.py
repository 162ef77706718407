"""The lowest eigenpairs of the generalised symmetric eigenproblem ``K phi = lambda M phi``
of a reduced system, both matrices in a pattern's storage
(:class:`~ancf.core.pattern.ReducedPattern`: band rows or CSR data).  With K a stiffness
(N/m) and M a mass (kg), lambda = omega^2 (rad^2/s^2).  M is symmetric positive definite,
K symmetric and possibly indefinite (a tangent beyond a limit point).

Both routes are shift-inverted: the shift sigma is put below the lowest eigenvalue by
inertia (Sylvester's law: the negative pivots of an LDL^T of ``K - s M`` count the
eigenvalues below s), and the largest mu = 1 / (lambda - sigma) of
``M phi = mu (K - sigma M) phi`` give the lowest lambda, negative ones included, to a
precision relative to lambda - sigma (the plain ``K phi = lambda M phi`` loses the lowest
bending modes of a slender beam to the round-off of its stiffest, axial and shear, ones:
1e-3 at L/h = 1000).  Chosen by size:

* ``dense``: LAPACK's ``eigh`` of the dense pair (M, K - sigma M), the ``count`` largest
  mu only, for at most :data:`DENSE_MAX` unknowns or when ``count`` is half of them or
  more (where a Lanczos basis would be as large as the matrix);
* shift-invert Lanczos: ARPACK (``scipy.sparse.linalg.eigsh``, mode 3) on
  ``(K - sigma M)^-1 M``, every application one solve with the factorisation the static
  solver uses (:func:`ancf.solvers.linear.factor`: the compiled band LU, or SuperLU for a
  CSR pattern).

Zero-energy modes (rigid motion, a mechanism) sit at round-off just above that shift:
their mu are up to 1e12 times the others', which the Lanczos basis then resolves only
to ~1e-3 (a free plate's first elastic frequency).  When the computed eigenvalues span more
than :data:`SPREAD_MAX` in distance from the shift, they are computed again with the shift
moved down by half the highest one's distance (every mu then within a few times the others).

One eigenpair more than asked for is computed, and an inertia count between the highest
reported and the next (just above the next where the two are one repeated eigenvalue)
confirms that none below was missed (the Sturm check).  :attr:`Eigenpairs.stiffness_rel`
measures each mode against K alone, phi^T K phi / (|K|_inf phi^T phi): a zero-energy
(rigid-body) mode has it at round-off, below
:data:`~ancf.solvers.linear.ZERO_EIGENVALUE_REL`, the static stability check's zero.

A failure (non-finite entries, no shift found, a singular factorisation, ARPACK not
converging) raises :class:`EigenFailure` with the reason.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ancf.solvers.linear import Singular, counter, factor

#: unknowns up to which the dense route is taken (LAPACK on 200 x 200: a few ms)
DENSE_MAX = 200
#: the first shift is this far below zero relative to :func:`scale` (the round-off of the
#: largest eigenvalue, where the zero-energy modes lie); then ten times further per
#: attempt, for at most SHIFT_ATTEMPTS attempts (down to -1e14 scale)
SHIFT_START = float(np.finfo(float).eps)
SHIFT_ATTEMPTS = 30
#: two eigenvalues closer than this fraction of their distance from the shift are one
#: repeated eigenvalue to the Sturm check (computed ones agree to about 1e-12 of it)
STURM_MARGIN = 1e-8
#: the largest ratio of (lambda - sigma) between the highest and the lowest computed
#: eigenpair before the shift is moved down (zero-energy modes at the shift)
SPREAD_MAX = 1e6


class EigenFailure(Exception):
    """The eigenpairs could not be computed; the message says why."""


@dataclass(kw_only=True)
class Eigenpairs:
    """``values`` lambda (count,) ascending, rad^2/s^2; ``vectors`` (n, count), M-normalised,
    in the pattern's numbering; ``stiffness_rel`` (count,) |phi^T K phi| / (|K|_inf phi^T phi);
    ``shift`` sigma; the work done (``factorizations``: inertia counts and the LU or
    Cholesky, ``solves``: Lanczos steps, 0 dense); ``sturm_count``, the number of
    eigenvalues below the Sturm check's point, and ``missed``, how many of them were not
    found (0; the inertia of zero-energy modes is round-off, so a count below the found
    ones is no miss)."""

    values: np.ndarray
    vectors: np.ndarray
    stiffness_rel: np.ndarray
    method: str
    shift: float
    factorizations: int
    solves: int
    sturm_count: int
    missed: int


def _diagonal(pattern, data) -> np.ndarray:
    return np.array(data[:, pattern.kl]) if pattern.band else pattern.as_csr(data).diagonal()


def scale(pattern, K, M) -> float:
    """The largest Rayleigh quotient K_ii / M_ii of a unit vector (0 if none is positive)."""
    dk, dm = _diagonal(pattern, K), _diagonal(pattern, M)
    ok = dm > 0
    return float(np.max(dk[ok] / dm[ok], initial=0.0))


def lowest(pattern, K, M, count: int) -> Eigenpairs:
    """The ``count`` lowest eigenpairs of (K, M), 1 <= count < n."""
    n = pattern.n
    if not 1 <= count < n:
        raise ValueError(f"count must be in [1, {n - 1}] (got {count})")
    if not (np.all(np.isfinite(K)) and np.all(np.isfinite(M))):
        raise EigenFailure("non-finite entries in the stiffness or mass matrix")
    top = scale(pattern, K, M)
    if not top > 0:
        raise EigenFailure("no positive diagonal entry in the stiffness matrix")
    sigma, facts = _shift(pattern, K, M, top)
    k = min(count + 1, n - 1)  # one more for the Sturm check
    dense = n <= DENSE_MAX or 2 * k >= n
    route = _dense if dense else _lanczos
    w, V, method, solves = route(pattern, K, M, k, sigma)
    if w.max() - sigma > SPREAD_MAX * (w.min() - sigma):
        sigma -= 0.5 * (w.max() - sigma)
        w, V, method, more = route(pattern, K, M, k, sigma)
        solves, facts = solves + more, facts + 1
    order = np.argsort(w)
    w, V = w[order], V[:, order]
    at = _sturm_point(w, count, sigma)
    sturm = _below(pattern, K, M, at)
    missed = max(sturm - int(np.sum(w < at)), 0)
    w, V = w[:count], V[:, :count]
    rel = np.abs(w) / (pattern.inf_norm(K) * np.einsum("ij,ij->j", V, V))
    return Eigenpairs(values=w, vectors=V, stiffness_rel=rel, method=method, shift=sigma,
                      factorizations=facts + 2, solves=solves, sturm_count=sturm, missed=missed)


def _sturm_point(w, count, sigma) -> float:
    """Between the count-th and the next computed eigenvalue, or above the next where they
    are one repeated eigenvalue (or none was computed beyond the count-th)."""
    if w.size > count and w[count] - w[count - 1] > STURM_MARGIN * (w[count] - sigma):
        return 0.5 * (w[count - 1] + w[count])
    return w[-1] + STURM_MARGIN * (w[-1] - sigma)


def _dense(pattern, K, M, count, sigma):
    """(lambda, M-normalised vectors, method, 0 solves) by LAPACK on (M, K - sigma M)."""
    import scipy.linalg as sla
    n = pattern.n
    A, B = pattern.as_csr(K - sigma * M).toarray(), pattern.as_csr(M).toarray()
    try:
        mu, V = sla.eigh(B, A, subset_by_index=[n - count, n - 1])
    except (np.linalg.LinAlgError, ValueError) as exc:
        raise EigenFailure(f"LAPACK eigh failed ({exc})") from None
    V = V / np.sqrt(np.einsum("ij,ij->j", V, B @ V))
    why = f"{n} unknowns <= {DENSE_MAX}" if n <= DENSE_MAX else "count >= n/2"
    return sigma + 1.0 / mu, V, f"dense: LAPACK eigh of (M, K - sigma M), shift-inverted ({why})", 0


def _below(pattern, K, M, s) -> int:
    """Eigenvalues of (K, M) below s (-1: K - s M has an exactly zero pivot)."""
    return int(counter(pattern, K - s * M)(0.0))


def _shift(pattern, K, M, top) -> tuple[float, int]:
    """(sigma below every eigenvalue, factorisations spent finding it)."""
    s = -SHIFT_START * top
    for attempt in range(1, SHIFT_ATTEMPTS + 1):
        if _below(pattern, K, M, s) == 0:
            return s, attempt
        s *= 10.0
    raise EigenFailure(f"no shift below the lowest eigenvalue down to {s / 10.0:.3g} rad^2/s^2")


def _lanczos(pattern, K, M, count, sigma):
    """(lambda, M-normalised vectors, method, solves) by ARPACK on (K - sigma M)^-1 M."""
    import scipy.sparse.linalg as spla
    try:
        lu = factor(pattern, K - sigma * M)
    except Singular as exc:
        raise EigenFailure(f"K - sigma M could not be factored ({exc})") from None
    n, solves = pattern.n, [0]

    def apply(x):
        solves[0] += 1
        return lu.solve(x)

    op = spla.LinearOperator((n, n), matvec=apply, dtype=float)
    v0 = 1.0 + 0.5 * np.sin(1.0 + 7.0 * np.arange(n))  # reproducible runs
    try:
        w, V = spla.eigsh(pattern.as_csr(K), k=count, M=pattern.as_csr(M), sigma=sigma,
                          which="LM", OPinv=op, v0=v0)
    except (spla.ArpackError, Singular) as exc:
        raise EigenFailure(f"ARPACK: {exc}") from None
    lu_kind = "band LU" if pattern.band else "SuperLU"
    method = f"shift-invert Lanczos: ARPACK eigsh on the {lu_kind} of K - sigma M ({n} unknowns)"
    return w, V, method, solves[0]
