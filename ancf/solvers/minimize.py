"""Static equilibrium of an unloaded, pre-stressed structure by energy minimisation.

For the free belt (thesis Fig. 3.5) there is no load to scale: the residual is the
internal force of the initial (wrapped) shape.  Newton's direction
``d = -K^-1 g`` on the reduced coordinates (band LU of the pattern) is used when it
descends; where the tangent is not positive definite (counted by the inertia of
its LDL^T, :func:`ancf.solvers.banded.count_below`) it is shifted,
``K + tau I`` with tau growing tenfold from 1e-6 of the largest diagonal entry,
until it is.  A backtracking line search halves the step until the energy
decreases (Armijo, 1e-4); the full step is also taken when it halves the residual,
since near the minimum the energy changes below its own round-off.  Converged when |g|_inf <= rtol |g_0|_inf and the last
increment |d|_inf <= xtol (1 + |z|_inf).  Every iterate is kept (Fig. 3.5).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ancf.solvers import banded

ARMIJO = 1e-4


@dataclass
class MinimizeResult:
    z: np.ndarray
    converged: bool
    message: str
    iterations: int
    iterates: list = field(default_factory=list)   # z after each iteration (iterate 0: start)
    residuals: list = field(default_factory=list)  # |g|_inf per iterate


def _direction(K, kl, g):
    """Newton direction with the smallest shift tau >= 0 that makes K + tau I positive definite."""
    n = g.size
    tau, top = 0.0, float(np.max(np.abs(K[:, kl])))
    for _ in range(40):
        A = K.copy()
        A[:, kl] += tau
        if banded.count_below(A, kl, 0.0) == 0:
            piv = np.zeros(n, dtype=np.int64)
            if banded.lu(A, kl, piv, True) == 0:
                d = -g.copy()
                banded.solve(A, kl, piv, d)
                return d
        tau = max(10 * tau, 1e-6 * top)
    return -g / top


def _line_search(energy, grad_tangent, z, U, g, d):
    """(z, U, g, K) after the step along d: the full step when it lowers the energy or
    halves |g|_inf (near the minimum the energy changes below its round-off), else
    Armijo backtracking on the energy."""
    slope, step = float(g @ d), 1.0
    g1, K1 = grad_tangent(z + d)
    U1 = energy(z + d)
    if U1 <= U + ARMIJO * slope or np.max(np.abs(g1)) <= 0.5 * np.max(np.abs(g)):
        return z + d, U1, g1, K1
    while step > 1e-12:
        step *= 0.5
        U1 = energy(z + step * d)
        if U1 <= U + ARMIJO * step * slope:
            break
    z = z + step * d
    g1, K1 = grad_tangent(z)
    return z, energy(z), g1, K1


def minimize(energy, grad_tangent, z0, kl, rtol=1e-10, xtol=1e-12, max_iter=200) -> MinimizeResult:
    """Minimise ``energy(z)`` from z0; ``grad_tangent(z)`` -> (g, K band of half-width kl)."""
    z = np.array(z0, dtype=float)
    g, K = grad_tangent(z)
    g0 = max(float(np.max(np.abs(g))), np.finfo(float).tiny)
    res = MinimizeResult(z, False, "", 0, [z.copy()], [float(np.max(np.abs(g)))])
    U = energy(z)
    for it in range(1, max_iter + 1):
        d = _direction(K, kl, g)
        z, U, g, K = _line_search(energy, grad_tangent, z, U, g, d)
        res.iterates.append(z.copy())
        res.residuals.append(float(np.max(np.abs(g))))
        res.iterations = it
        if res.residuals[-1] <= rtol * g0 and np.max(np.abs(res.iterates[-1] - res.iterates[-2])) <= \
                xtol * (1 + np.max(np.abs(z))):
            res.z, res.converged, res.message = z, True, "ok"
            return res
    res.z = z
    res.message = f"No convergence: |g| = {res.residuals[-1]:.3g} after {max_iter} iterations"
    return res
