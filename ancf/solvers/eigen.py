"""The lowest eigenpairs of the generalised symmetric eigenproblem ``K phi = lambda M phi``
of a reduced system, both matrices in a pattern's storage
(:class:`~ancf.core.pattern.ReducedPattern`: band rows or CSR data).  With K a stiffness
(N/m) and M a mass (kg), lambda = omega^2 (rad^2/s^2).  M is symmetric positive definite,
K symmetric and possibly indefinite (a tangent beyond a limit point).

Two routes, chosen by size:

* ``dense``: LAPACK's ``eigh`` of the dense pair, the lowest ``count`` only, for at most
  :data:`DENSE_MAX` unknowns or when ``count`` is half of them or more (where a Lanczos
  basis would be as large as the matrix);
* shift-invert Lanczos: ARPACK (``scipy.sparse.linalg.eigsh``, mode 3) on
  ``(K - sigma M)^-1 M``, every application one solve with the factorisation the static
  solver uses (:func:`ancf.solvers.linear.factor`: the compiled band LU, or SuperLU for a
  CSR pattern).  The shift is put below the lowest eigenvalue by inertia (Sylvester's
  law: the negative pivots of an LDL^T of ``K - s M`` count the eigenvalues below s), so
  the ``count`` eigenvalues nearest to it are the lowest ones, negative ones included; an
  inertia count just above the highest eigenvalue found (the Sturm check) confirms that
  none below it was missed.

A failure (non-finite entries, no shift found, a singular factorisation, ARPACK not
converging) raises :class:`EigenFailure` with the reason.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ancf.solvers.linear import ZERO_EIGENVALUE_REL, Singular, counter, factor

#: unknowns up to which the dense route is taken (LAPACK on 200 x 200: a few ms)
DENSE_MAX = 200
#: the first shift is this far below zero, relative to :func:`scale`; then ten times
#: further per attempt, for at most SHIFT_ATTEMPTS attempts (down to -1e15 scale)
SHIFT_START = ZERO_EIGENVALUE_REL
SHIFT_ATTEMPTS = 30
#: the Sturm check counts the eigenvalues below the highest found plus this fraction of
#: its distance from the shift (ARPACK's eigenvalues are exact to about 1e-12 of it)
STURM_MARGIN = 1e-8


class EigenFailure(Exception):
    """The eigenpairs could not be computed; the message says why."""


@dataclass
class Eigenpairs:
    """``values`` lambda (count,) ascending, rad^2/s^2; ``vectors`` (n, count), M-normalised,
    in the pattern's numbering; ``scale`` the largest K_ii / M_ii (a lower bound of the
    largest eigenvalue); ``shift`` sigma of the Lanczos route (None: dense); the work done
    (``factorizations``, ``solves``) and ``sturm_count``, the number of eigenvalues below
    the highest found (None: dense, where LAPACK returns the lowest by construction)."""

    values: np.ndarray
    vectors: np.ndarray
    method: str
    scale: float
    shift: float | None
    factorizations: int
    solves: int
    sturm_count: int | None


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
    if n <= DENSE_MAX or 2 * count >= n:
        return _dense(pattern, K, M, count, top)
    return _lanczos(pattern, K, M, count, top)


def _dense(pattern, K, M, count, top) -> Eigenpairs:
    import scipy.linalg as sla
    A, B = pattern.as_csr(K).toarray(), pattern.as_csr(M).toarray()
    try:
        w, V = sla.eigh(A, B, subset_by_index=[0, count - 1])
    except (np.linalg.LinAlgError, ValueError) as exc:
        raise EigenFailure(f"LAPACK eigh failed ({exc})") from None
    why = f"{pattern.n} unknowns <= {DENSE_MAX}" if pattern.n <= DENSE_MAX else "count >= n/2"
    return Eigenpairs(w, V, f"dense: LAPACK eigh of the reduced K and M ({why})", top, None,
                      1, 0, None)


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


def _lanczos(pattern, K, M, count, top) -> Eigenpairs:
    import scipy.sparse.linalg as spla
    sigma, facts = _shift(pattern, K, M, top)
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
    order = np.argsort(w)
    w, V = w[order], V[:, order]
    sturm = _below(pattern, K, M, w[-1] + STURM_MARGIN * (w[-1] - sigma))
    kind = "band LU" if pattern.band else "SuperLU"
    return Eigenpairs(w, V, f"shift-invert Lanczos: ARPACK eigsh on the {kind} of K - sigma M "
                            f"({n} unknowns)", top, sigma, facts + 2, solves[0], sturm)
