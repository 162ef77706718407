"""Compiled generalised-alpha march of the belt drives (:mod:`ancf.belts.drive2d` in 2D,
:mod:`ancf.belts.drive3d` in 3D; their forces: :mod:`ancf.belts.forces`).

The recurrence is that of :mod:`ancf.solvers.generalized_alpha` (Arnold & Brüls:
unknown the acceleration at t_{n+1}).  Unknowns: the belt coordinates z (band
numbering of the model's pattern) and the driven pulley's angle theta:

    M z'' + dU/dz - Q_c(z, z', omega_1(t), theta') = 0         (Eqs 2.27, 3.27)
    I theta'' - T_c(z, z', theta') + T_a(t) = 0                 (Eq. 3.26)

with the contact forces Q_c and pulley moment T_c (:mod:`ancf.belts.contact2d`,
:mod:`ancf.belts.contact3d`); ``tabs`` (nlaws, nsteps) holds the pulley laws at every
step time (the model's ``laws(ts)``).  The
iteration matrix is bordered: a band block for the belt,

    S_zz = M + beta' (K - dQ_c/dz) - gamma' dQ_c/dz'

(non-symmetric: friction), one column ``-gamma' dQ_c/dtheta'``, one row
``-beta' dT_c/dz - gamma' dT_c/dz'`` and the corner ``I - gamma' dT_c/dtheta'``.
It is solved by the band LU of S_zz and the Schur complement of the corner (one
extra band solve per factorisation).  Modified Newton as in
:mod:`ancf.solvers.alpha_compiled`: the factors are kept across iterations and
steps and refreshed when there are none, the step size changed or an increment
fails to contract; a step that fails with kept factors is retried with fresh ones,
one that fails with fresh factors ends the march (status NEWTON_FAILED).

Counters ``count``: 0 force evaluations, 1 tangents, 2 factorisations, 3 solves,
4 steps, 5 Newton iterations, 6 element-pulley pairs evaluated by the contact
kernel (after its bounding test).
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.solvers import banded
from ancf.belts.forces import evaluate

DONE, NEWTON_FAILED, NON_FINITE, BLOW_UP, BUDGET = 0, 1, 2, 3, 4
REFRESH_RATIO = 0.5
MAX_BACKTRACKS = 8  # trial lengths 1, 1/2, ... 1/128 of a Newton increment


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


@njit(cache=True)
def _residual(acc1, st, h, k, cf, mdl, Mb, kl, tabs, want_J, fs, count, r):
    """r = residual at the step-end acceleration acc1 (and, if want_J, the force part of
    the iteration matrix into fs); returns the corner's force part."""
    x, v, acc, a = st
    am, af, gamma, beta = cf
    n = x.size - 1
    a1 = ((1 - af) * acc1 + af * acc - am * a) / (1 - am)
    x1 = x + h * v + h * h * ((0.5 - beta) * a + beta * a1)
    v1 = v + h * ((1 - gamma) * a + gamma * a1)
    bp = h * h * beta * (1 - af) / (1 - am)
    gp = h * gamma * (1 - af) / (1 - am)
    corner, pairs = evaluate(x1, v1, tabs[:, k], mdl, want_J, bp, gp, r, fs[0],
                             fs[4], fs[3])
    count[0] += 1
    count[6] += pairs
    r[:n] += banded.matvec(Mb, kl, acc1[:n])
    r[n] += mdl[8] * acc1[n]
    return corner


@njit(cache=True)
def _factor(fs, Mb, kl, corner, inertia, h, pivoting, count) -> bool:
    """Factor the bordered iteration matrix assembled in fs (band LU + Schur complement).
    Without pivoting the LU works on kl instead of 2 kl columns per row; the mass
    matrix makes S_zz diagonally dominant enough in practice, and a step that fails
    is retried with fresh, pivoted factors."""
    S, piv, u, row, col, sc = fs
    count[1] += 1
    count[2] += 1
    S += Mb
    if banded.lu(S, kl, piv, pivoting) != 0:
        sc[1] = np.nan
        return False
    u[:] = col
    banded.solve(S, kl, piv, u)
    sc[0] = inertia + corner - np.dot(row, u)
    sc[1] = h
    return True


@njit(cache=True)
def _step(h, k, st, fs, cf, mdl, Mb, kl, tabs, count, tol, max_iter, fresh):
    """One step of size h ending at step index k; True on convergence.  Damped Newton:
    the increment is halved (at most MAX_BACKTRACKS times) until the residual norm
    decreases (Armijo 1e-4), which breaks the 2-cycles of points switching between
    sticking, sliding and no contact."""
    x, v, acc, a = st
    am, af, gamma, beta = cf
    n = x.size - 1
    bp = h * h * beta * (1 - af) / (1 - am)
    acc1 = acc.copy()
    r, rt = np.zeros(n + 1), np.zeros(n + 1)
    refresh = fresh or fs[5][1] != h
    corner = _residual(acc1, st, h, k, cf, mdl, Mb, kl, tabs, refresh, fs, count, r)
    d_prev = np.inf
    for _ in range(max_iter):
        if refresh:
            if not _factor(fs, Mb, kl, corner, mdl[8], h, fresh, count):
                return False
            refresh = False
        d = -r
        bordered_solve(fs[0], kl, fs[1], fs[2], fs[3], fs[5][0], d)
        count[3] += 1
        count[5] += 1
        rn, lam = np.sqrt(np.dot(r, r)), 1.0
        for _ in range(MAX_BACKTRACKS):
            _residual(acc1 + lam * d, st, h, k, cf, mdl, Mb, kl, tabs, False, fs, count, rt)
            if np.sqrt(np.dot(rt, rt)) <= (1 - 1e-4 * lam) * rn:
                break
            lam *= 0.5
        acc1 += lam * d
        r[:] = rt
        dn = lam * np.max(np.abs(d[:n]))
        if not np.isfinite(dn):
            return False
        if bp * dn <= tol * (1 + np.max(np.abs(x[:n]))) and bp * lam * abs(d[n]) <= tol:
            a1 = ((1 - af) * acc1 + af * acc - am * a) / (1 - am)
            x[:] = x + h * v + h * h * ((0.5 - beta) * a + beta * a1)
            v[:] = v + h * ((1 - gamma) * a + gamma * a1)
            acc[:] = acc1
            a[:] = a1
            return True
        if dn > REFRESH_RATIO * d_prev or lam < 1.0:
            refresh = True
            corner = _residual(acc1, st, h, k, cf, mdl, Mb, kl, tabs, True, fs, count, r)
        d_prev = dn
    return False


@njit(cache=True)
def march(ts, k, k_stop, st, fs, cf, mdl, Mb, kl, tabs, count, tol, max_iter, limit, max_steps,
          slot, out_x, out_v):
    """Steps ts[k] -> ts[k_stop]; returns (status, step index reached).  States after
    steps with slot[i] >= 0 go to out_x/out_v[slot[i]]."""
    x, v = st[0], st[1]
    backup = (x.copy(), v.copy(), st[2].copy(), st[3].copy())
    while k < k_stop:
        if count[4] >= max_steps:
            return BUDGET, k
        h = ts[k + 1] - ts[k]
        for i in range(4):
            backup[i][:] = st[i]
        ok = _step(h, k + 1, st, fs, cf, mdl, Mb, kl, tabs, count, tol, max_iter, False)
        if not ok:
            for i in range(4):
                st[i][:] = backup[i]
            ok = _step(h, k + 1, st, fs, cf, mdl, Mb, kl, tabs, count, tol, max_iter, True)
        if not ok:
            for i in range(4):
                st[i][:] = backup[i]
            fs[5][1] = np.nan
            return NEWTON_FAILED, k
        k += 1
        count[4] += 1
        n = x.size - 1
        if not np.all(np.isfinite(x)):
            return NON_FINITE, k
        if np.max(np.abs(x[:n])) > limit:
            return BLOW_UP, k
        if slot[k] >= 0:
            out_x[slot[k]] = x
            out_v[slot[k]] = v
    return DONE, k
