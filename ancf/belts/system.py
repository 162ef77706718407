"""A belt drive as a system of the compiled generalised-alpha march
(:mod:`ancf.solvers.alpha_march`).

Unknowns: the belt coordinates z (band numbering of the drive's pattern) and the angles
theta_j of the k free pulleys (driven pulleys, idlers and tensioners; pulley p is free
pulley j = ``free[p]``) followed by the tensioners' arm angles (their rows and the corner
off its diagonal: :mod:`ancf.belts.forces`):

    M z'' + dU/dz - Q_c(z, z', omega(t), theta') - F_g = 0          (Eqs 2.27, 3.27)
    I_j theta_j'' - T_c,p(z, z', theta_j') + T_a,p(t) + c_j theta_j' = 0     (Eq. 3.26)

(T_a,p(t) signed; a ``resisting`` load |T_a,p(t)| tanh(theta_j' / omega_reg) instead,
:func:`load_terms`)

with the contact forces Q_c, the pulley moments T_c,p and the belt's weight F_g
(:mod:`ancf.belts.forces`); ``tabs`` (nlaws, nts) holds the pulley laws at every step
time (the drive's ``laws(ts)``).  The iteration matrix is bordered: a band block for
the belt,

    S_zz = M + beta' (K - dQ_c/dz) - gamma' dQ_c/dz'

(non-symmetric: friction), k columns ``C_j = -gamma' dQ_c/dtheta_j'``, k rows
``R_j = -beta' dT_c,p/dz - gamma' dT_c,p/dz'`` and the corner ``diag(I_j) + gamma'
diag(c_j - dT_c,p/dtheta_j')``.  It is solved by the band LU of S_zz and the k x k
Schur complement ``corner - R S_zz^-1 C`` (LU with partial pivoting; k extra band
solves per factorisation).  Kept factors are unpivoted: the LU then works on kl
instead of 2 kl columns per row, the mass matrix makes S_zz diagonally dominant
enough in practice, and fresh factors (the retry of a failed step) are pivoted.

Newton increments are damped by backtracking; converged when beta' |d_z|_inf <= tol
(1 + |z_n|_inf) and beta' |d_theta_j| <= tol (z_n: the step's start).  The blow-up
test looks at the belt coordinates only.  Counter ``count[5]``: element-pulley pairs
evaluated by the contact kernel (after its bounding test).

Window means: every converged step adds its end state's pulley speeds and the belt's
moments on the pulleys (the last residual's, at the accepted iterate) to ``sums``,
weighted by the part of the step after the window's start (``window``, :func:`window_weights`):
the means over every step of a steady window, whatever the output samples.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from ancf.belts import friction
from ancf.belts.forces import evaluate
from ancf.belts.pulleys import RESISTING, load_records
from ancf.common.dispatch import as_struct, implements
from ancf.solvers import banded
from ancf.solvers.alpha_march import (system_accept, system_factor, system_prepare,
                                      system_residual, system_solve, system_tests)

PAIRS = 5  # the counter of contact pairs


class BeltSystem(NamedTuple):
    """A drive's compiled data with the march's arrays (SI units) and work storage."""

    drive: tuple         # Drive2D or Drive3D (ancf.belts.forces)
    Mb: np.ndarray       # belt mass matrix, band storage, kg
    mass_rows: tuple     # its nonzeros by row (mass_rows): row pointers, columns, values
    kl: int              # half-bandwidth
    tabs: np.ndarray     # pulley laws at the step times (nlaws, nts)
    loads: np.ndarray    # (k,) how each free coordinate's load acts (pulleys.LOAD records)
    steps: np.ndarray    # (nts,) the step ending at each step time, s (0 at the first)
    zs: np.ndarray       # (nslots, ...) the friction state at the start of the step that
    #                      ended at each output slot (a law with a state; else (0, ...))
    hs: np.ndarray       # (nslots,) that step, s
    window: np.ndarray   # (nts,) each step's weight in the window means, s (window_weights)
    weight: np.ndarray   # (1,) the current step's, s
    sums: np.ndarray     # (3, np) over the converged steps: sum of the weights (s), of the
    #                      weights times the pulley speeds (rad) and times the moments (N m s)
    S: np.ndarray        # work: S_zz, then its band LU
    piv: np.ndarray      # work: its pivots
    U: np.ndarray        # work: (k, n) S_zz^-1 C_j
    row: np.ndarray      # work: (k, n) the border rows
    col: np.ndarray      # work: (k, n) the border columns
    corner: np.ndarray   # work: (k, k) the corner's force part
    schur: np.ndarray    # work: (k, k) the Schur complement, then its LU
    spiv: np.ndarray     # work: (k,) its pivots


def belt_system(drive, ts, nslots: int = 0, mean_from: float = np.inf) -> BeltSystem:
    """The system of a drive (:class:`~ancf.belts.drive2d.BeltDrive` or
    :class:`~ancf.belts.drive3d.Belt3DDrive`) over the step times ts (s), keeping the
    friction state (a law with a state) at ``nslots`` output slots and the window means
    from ``mean_from`` (s; inf: none)."""
    n, k = drive.n, drive.k
    kernel = drive.kernel()
    shape = (nslots if kernel.z.size else 0, *kernel.z.shape[1:])
    return BeltSystem(drive=kernel, Mb=drive.Mb, mass_rows=mass_rows(drive.Mb, drive.pattern.kl),
                      kl=drive.pattern.kl, tabs=drive.laws(ts), loads=loads_of(drive),
                      steps=steps(ts),
                      zs=np.zeros(shape), hs=np.zeros(shape[0]),
                      window=window_weights(ts, mean_from), weight=np.zeros(1),
                      sums=np.zeros((3, kernel.radii.size)), S=drive.pattern.zeros_matrix(),
                      piv=np.zeros(n, dtype=np.int64), U=np.zeros((k, n)), row=np.zeros((k, n)),
                      col=np.zeros((k, n)), corner=np.zeros((k, k)), schur=np.zeros((k, k)),
                      spiv=np.zeros(k, dtype=np.int64))


def loads_of(drive) -> np.ndarray:
    """The rig's :data:`ancf.belts.pulleys.LOAD` records (k,), every load signed where it
    has none (the thesis drives)."""
    loads = drive.rig.loads
    return load_records([(None, -1, {})] * drive.k) if loads is None else loads


@njit(cache=True)
def force_residual(system, x, v, k, want_J, f):
    """f = the residual forces at (x, v) and step time index k, the residual of the march
    (:func:`_residual`) without the inertia terms and without the iteration matrix (want_J:
    False, from Python: a runtime flag).  Called with the march's types, the drive as its
    struct and the laws as a column of ``tabs``, so it shares the march's compilation of
    :func:`ancf.belts.forces.evaluate` and :func:`load_terms`."""
    s = as_struct(system)
    nk = s.drive.inertia.size
    n = x.size - nk
    evaluate(x, v, s.tabs[:, k], s.drive, want_J, 0.0, 0.0, f, np.zeros((1, 1)),
             np.zeros((nk, n)), np.zeros((nk, n)), np.zeros((nk, nk)))
    load_terms(s.loads, s.tabs[:, k], v, 0.0, want_J, f, np.zeros((nk, nk)))


@njit(cache=True)
def load_terms(loads, laws, v, gp, want_J, r, corner):
    """Each free coordinate's load law (:data:`ancf.belts.pulleys.LOAD`, read by field):
    :func:`ancf.belts.forces.evaluate` puts the signed torque T_a = laws[row] (N m) into
    its residual r[n + j]; a ``resisting`` law's torque |T_a| tanh(omega / omega_reg)
    against the angular velocity omega = v[n + j] (rad/s) replaces it, with its
    derivative by omega, gp |T_a| (1 - tanh^2) / omega_reg, in the ``corner``."""
    n = v.size - loads.size
    for j in range(loads.size):
        rec = loads[j]
        if rec.law != RESISTING:
            continue
        Ta = laws[rec.row]
        s = np.tanh(v[n + j] / rec.omega_reg)
        r[n + j] += abs(Ta) * s - Ta
        if want_J:
            corner[j, j] += gp * abs(Ta) * (1.0 - s * s) / rec.omega_reg


def mass_rows(Mb, kl: int) -> tuple:
    """The nonzeros of a band matrix (storage of :mod:`ancf.solvers.banded`) by row, each
    row's by ascending column: (ptr (n + 1,), col, val), CSR.  The consistent mass of the
    belt elements couples the components of a vector only with themselves, so most of
    its band is zero (a plate's: 18 of 2 kl + 1 entries per row)."""
    n = Mb.shape[0]
    i, t = np.nonzero(Mb[:, : 2 * kl + 1])  # row-major: by row, then by column
    ptr = np.searchsorted(i, np.arange(n + 1))
    return ptr, (i + t - kl).astype(np.int64), Mb[i, t].copy()


@njit(cache=True)
def add_mass_times(rows, x, r):
    """r += M x, M by its nonzeros (:func:`mass_rows`): each row's product summed from
    zero by ascending column, as :func:`ancf.solvers.banded.matvec` sums the band (the
    exact zeros it adds change nothing but, at most, the sign of a zero sum)."""
    ptr, col, val = rows
    for i in range(ptr.size - 1):
        s = 0.0
        for k in range(ptr[i], ptr[i + 1]):
            s += val[k] * x[col[k]]
        r[i] += s


@njit(cache=True)
def add_mass(rows, kl, S):
    """S += M (band storage, half-bandwidth kl) by M's nonzeros (:func:`mass_rows`): the
    sum of adding the whole band, bit for bit (an exact zero added to an entry assembled
    from +0.0 leaves it as it is), on a fraction of its entries."""
    ptr, col, val = rows
    for i in range(ptr.size - 1):
        for k in range(ptr[i], ptr[i + 1]):
            S[i, col[k] - i + kl] += val[k]


@njit(cache=True)
def small_lu(A, piv) -> bool:
    """LU with partial pivoting of the small dense A in place; False if singular."""
    k = A.shape[0]
    for c in range(k):
        p = c + np.argmax(np.abs(A[c:, c]))
        piv[c] = p
        if A[p, c] == 0.0:
            return False
        if p != c:
            for j in range(k):
                A[c, j], A[p, j] = A[p, j], A[c, j]
        for i in range(c + 1, k):
            A[i, c] /= A[c, c]
            for j in range(c + 1, k):
                A[i, j] -= A[i, c] * A[c, j]
    return True


@njit(cache=True)
def small_solve(A, piv, b):
    """b = A^-1 b in place with the factors of :func:`small_lu`."""
    k = b.size
    for c in range(k):  # the row swaps first: the factors' L holds the rows swapped later
        p = piv[c]
        b[c], b[p] = b[p], b[c]
    for c in range(k):
        for i in range(c + 1, k):
            b[i] -= A[i, c] * b[c]
    for c in range(k - 1, -1, -1):
        for j in range(c + 1, k):
            b[c] -= A[c, j] * b[j]
        b[c] /= A[c, c]


@njit(cache=True)
def bordered_solve(S, kl, piv, U, row, schur, spiv, f):
    """Solve [[S, C], [R, corner]] d = f in place, with S factored, U = S^-1 C and
    schur = corner - R U factored."""
    k = U.shape[0]
    n = f.size - k
    y = f[:n].copy()
    banded.solve(S, kl, piv, y)
    th = np.empty(k)
    for j in range(k):
        th[j] = f[n + j] - np.dot(row[j], y)
    small_solve(schur, spiv, th)
    for j in range(k):
        y -= U[j] * th[j]
    f[:n] = y
    f[n:] = th


def steps(ts) -> np.ndarray:
    """The step ending at each step time ts[k] (s), 0 at the first."""
    return np.diff(ts, prepend=ts[:1])


def window_weights(ts, start: float) -> np.ndarray:
    """The part (s) of the step ending at each step time ts[k] that lies after ``start``
    (s), 0 at the first: the weights of a mean over (start, ts[-1]] by the steps' end
    states, which sum to ts[-1] - start on any grid of steps."""
    ts = np.asarray(ts, dtype=float)
    return np.maximum(ts - np.maximum(np.concatenate([ts[:1], ts[:-1]]), start), 0.0)


@implements(system_prepare, BeltSystem)
def _prepare(system, k):
    """The step (s) a friction law with a state steps its trial state over, and the
    step's weight in the window means."""
    system.drive.h[0] = system.steps[k]
    system.weight[0] = system.window[k]


@njit(cache=True)
def accept_state(prm, z, h, zs, hs, slot):
    """A friction law's state (a law with a state, prm; else z is empty): the trial z[1]
    becomes z[0]; the state the step started from and the step h[0] are kept in zs[slot],
    hs[slot] (slot >= 0: the step's friction forces are the law's on them at the slot's
    x, v).  Called, not inlined: writes to zs from inside an inlined implementation on the
    struct (:func:`ancf.common.dispatch.as_struct`) were lost (numba 0.68)."""
    if friction.has_state(prm):
        if slot >= 0:
            zs[slot] = z[0]
            hs[slot] = h[0]
        z[0] = z[1]


@njit(cache=True)
def accumulate(last, weight, sums):
    """The window means' sums (module docstring) of a converged step: ``last`` (2, np)
    the pulley speeds and moments of its last residual, ``weight`` (1,) its weight (s)."""
    w = weight[0]
    if w > 0.0:
        sums[0] += w
        sums[1] += w * last[0]
        sums[2] += w * last[1]


@implements(system_accept, BeltSystem)
def _accept(system, slot):
    """The friction state: the trial state of the step's last residual (the accepted
    iterate: the belt's Newton increments are damped, evaluated where they end) becomes
    the state; the step's start kept in output slot ``slot``.  The step's pulley speeds
    and moments (of that residual) go into the window means' sums."""
    accept_state(system.drive.prm, system.drive.z, system.drive.h, system.zs, system.hs, slot)
    accumulate(system.drive.last, system.weight, system.sums)


@implements(system_residual, BeltSystem)
def _residual(system, x1, v1, acc1, k, bp, gp, want_J, count, r):
    inertia = system.drive.inertia
    n = x1.size - inertia.size
    count[PAIRS] += evaluate(x1, v1, system.tabs[:, k], system.drive, want_J, bp, gp, r,
                             system.S, system.col, system.row, system.corner)
    load_terms(system.loads, system.tabs[:, k], v1, gp, want_J, r, system.corner)
    add_mass_times(system.mass_rows, acc1, r)
    for j in range(inertia.size):
        r[n + j] += inertia[j] * acc1[n + j]


@implements(system_factor, BeltSystem)
def _factor(system, bp, pivoting):
    S = system.S
    add_mass(system.mass_rows, system.kl, S)
    if banded.lu(S, system.kl, system.piv, pivoting) != 0:
        return False
    inertia, schur = system.drive.inertia, system.schur
    for j in range(inertia.size):
        system.U[j] = system.col[j]
        banded.solve(S, system.kl, system.piv, system.U[j])
    for i in range(inertia.size):
        for j in range(inertia.size):
            m = inertia[i] + system.corner[i, j] if i == j else system.corner[i, j]
            schur[i, j] = m - np.dot(system.row[i], system.U[j])
    return small_lu(schur, system.spiv)


@implements(system_solve, BeltSystem)
def _solve(system, d):
    bordered_solve(system.S, system.kl, system.piv, system.U, system.row, system.schur,
                   system.spiv, d)


@implements(system_tests, BeltSystem)
def _tests(system):
    """The belt coordinates, scaled at the step's start, damped Newton, velocities read."""
    return system.Mb.shape[0], True, True, True
