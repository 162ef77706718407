"""A belt drive as a system of the compiled generalised-alpha march
(:mod:`ancf.solvers.alpha_march`).

Unknowns: the belt coordinates z (band numbering of the drive's pattern) and the driven
pulley's angle theta:

    M z'' + dU/dz - Q_c(z, z', omega_1(t), theta') = 0         (Eqs 2.27, 3.27)
    I theta'' - T_c(z, z', theta') + T_a(t) = 0                 (Eq. 3.26)

with the contact forces Q_c and pulley moment T_c (:mod:`ancf.belts.forces`); ``tabs``
(nlaws, nts) holds the pulley laws at every step time (the drive's ``laws(ts)``).  The
iteration matrix is bordered: a band block for the belt,

    S_zz = M + beta' (K - dQ_c/dz) - gamma' dQ_c/dz'

(non-symmetric: friction), one column ``-gamma' dQ_c/dtheta'``, one row
``-beta' dT_c/dz - gamma' dT_c/dz'`` and the corner ``I - gamma' dT_c/dtheta'``.
It is solved by the band LU of S_zz and the Schur complement of the corner (one
extra band solve per factorisation).  Kept factors are unpivoted: the LU then works
on kl instead of 2 kl columns per row, the mass matrix makes S_zz diagonally dominant
enough in practice, and fresh factors (the retry of a failed step) are pivoted.

Newton increments are damped by backtracking; converged when beta' |d_z|_inf <= tol
(1 + |z_n|_inf) and beta' |d_theta| <= tol (z_n: the step's start).  The blow-up
test looks at the belt coordinates only.  Counter ``count[5]``: element-pulley pairs
evaluated by the contact kernel (after its bounding test).
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from ancf.belts.forces import evaluate
from ancf.common.dispatch import implements
from ancf.solvers import banded
from ancf.solvers.alpha_march import (system_factor, system_prepare, system_residual,
                                      system_solve, system_tests)

PAIRS = 5  # the counter of contact pairs


class BeltSystem(NamedTuple):
    """A drive's compiled data with the march's arrays (SI units) and work storage."""

    drive: tuple         # Drive2D or Drive3D (ancf.belts.forces)
    Mb: np.ndarray       # belt mass matrix, band storage, kg
    kl: int              # half-bandwidth
    tabs: np.ndarray     # pulley laws at the step times (nlaws, nts)
    S: np.ndarray        # work: S_zz, then its band LU
    piv: np.ndarray      # work: its pivots
    u: np.ndarray        # work: S_zz^-1 col
    row: np.ndarray      # work: the border row
    col: np.ndarray      # work: the border column
    corner: np.ndarray   # work: [force part of the corner, Schur complement]


def belt_system(drive, tabs) -> BeltSystem:
    """The system of a drive (:class:`~ancf.belts.drive2d.BeltDrive` or
    :class:`~ancf.belts.drive3d.Belt3DDrive`) over the step times of ``tabs``."""
    n = drive.n
    return BeltSystem(drive.kernel(), drive.Mb, drive.pattern.kl, tabs,
                      drive.pattern.zeros_matrix(), np.zeros(n, dtype=np.int64), np.zeros(n),
                      np.zeros(n), np.zeros(n), np.zeros(2))


@njit(cache=True)
def bordered_solve(S, kl, piv, u, row, schur, f):
    """Solve [[S, col], [row, corner]] d = f in place, with S factored, u = S^-1 col
    and schur = corner - row . u."""
    n = f.size - 1
    y = f[:n].copy()
    banded.solve(S, kl, piv, y)
    th = (f[n] - np.dot(row, y)) / schur
    f[:n] = y - u * th
    f[n] = th


@implements(system_prepare, BeltSystem)
def _prepare(system, k):
    pass


@implements(system_residual, BeltSystem)
def _residual(system, x1, v1, acc1, k, bp, gp, want_J, count, r):
    n = x1.size - 1
    corner, pairs = evaluate(x1, v1, system.tabs[:, k], system.drive, want_J, bp, gp, r,
                             system.S, system.col, system.row)
    count[PAIRS] += pairs
    r[:n] += banded.matvec(system.Mb, system.kl, acc1[:n])
    r[n] += system.drive.inertia * acc1[n]
    if want_J:
        system.corner[0] = corner


@implements(system_factor, BeltSystem)
def _factor(system, bp, pivoting):
    S = system.S
    S += system.Mb
    if banded.lu(S, system.kl, system.piv, pivoting) != 0:
        return False
    system.u[:] = system.col
    banded.solve(S, system.kl, system.piv, system.u)
    system.corner[1] = system.drive.inertia + system.corner[0] - np.dot(system.row, system.u)
    return True


@implements(system_solve, BeltSystem)
def _solve(system, d):
    bordered_solve(system.S, system.kl, system.piv, system.u, system.row, system.corner[1], d)


@implements(system_tests, BeltSystem)
def _tests(system):
    """The belt coordinates, scaled at the step's start, damped Newton, velocities read."""
    return system.Mb.shape[0], True, True, True
