"""Compiled step loop of the generalised-alpha scheme for the elimination form.

Applies to a :class:`~ancf.solvers.dynamics.ReducedModel` with one element group
and constant external forces (gravity), fixed, tied and prescribed (rheonomic)
coordinates: the pendulum and the spinning beam.  The whole march over the step
times runs in one numba call; the recurrence is that of
:mod:`ancf.solvers.generalized_alpha` (same unknowns, residual and convergence
test), with a modified Newton iteration:

* the iteration matrix ``S = M + beta' K`` and its band LU are kept across
  iterations and steps;
* they are refreshed (new tangent, new factorisation) when there is none yet, the
  step size changed, or an increment fails to contract (|d_k| > 0.5 |d_{k-1}|);
* a step that does not converge with a kept matrix is retried once with a fresh
  one; if that fails too the march returns, and the Python stepper takes that
  step with its step halving.

The coordinates are those of the pattern (``ReducedPattern.order``).  Prescribed
coordinates take their value at each step end from the tables ``gvals`` and
their accelerations enter as ``T^T M g''`` = ``Mp @ gdd``.
"""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.core.pattern import assemble_compiled
from ancf.solvers import banded

DONE, NEWTON_FAILED, NON_FINITE, BLOW_UP, BUDGET = 0, 1, 2, 3, 4
#: contraction ratio above which the kept iteration matrix is refreshed
REFRESH_RATIO = 0.5


@njit(cache=True)
def _step(h, t_index, st, fs, cf, mdl, sys, count, tol, max_iter, fresh):
    """One step of size h ending at step time t_index; True on convergence.
    st = (x, v, acc, a) updated in place; fs = (S, piv, h_factored)."""
    x, v, acc, a = st
    S, piv, hf = fs
    am, af, gamma, beta = cf
    Mb, kl, Qr, Mp, gdd, presc, gvals, g0 = sys
    n = x.size
    bp = h * h * beta * (1 - af) / (1 - am)
    gq = g0.copy()
    for j in range(presc.size):
        gq[presc[j]] = gvals[t_index, j]
    inertial = Mp @ gdd[t_index] if presc.size else np.zeros(n)
    acc1 = acc.copy()
    grad, K = np.zeros(n), np.zeros_like(Mb)
    refresh = fresh or hf[0] != h
    d_prev = np.inf
    for _ in range(max_iter):
        a1 = ((1 - af) * acc1 + af * acc - am * a) / (1 - am)
        x1 = x + h * v + h * h * ((0.5 - beta) * a + beta * a1)
        assemble_compiled(x1, gq, mdl, refresh, grad, K)
        count[0] += 1
        r = banded.matvec(Mb, kl, acc1) - Qr + grad + inertial
        if refresh:
            count[1] += 1
            S[:, :] = Mb + bp * K
            count[2] += 1
            if banded.lu(S, kl, piv, True) != 0:
                hf[0] = np.nan
                return False
            hf[0] = h
            refresh = False
        d = -r
        banded.solve(S, kl, piv, d)
        count[3] += 1
        acc1 += d
        dn = np.max(np.abs(d))
        if not np.isfinite(dn):
            return False
        if bp * dn <= tol * (1 + np.max(np.abs(x1))):
            a1 = ((1 - af) * acc1 + af * acc - am * a) / (1 - am)
            x[:] = x + h * v + h * h * ((0.5 - beta) * a + beta * a1)
            v[:] = v + h * ((1 - gamma) * a + gamma * a1)
            acc[:] = acc1
            a[:] = a1
            return True
        if dn > REFRESH_RATIO * d_prev:
            refresh = True
        d_prev = dn
    return False


@njit(cache=True)
def march(ts, k, st, fs, cf, mdl, sys, count, tol, max_iter, limit, max_steps, slot, out_x, out_v):
    """Steps ts[k] -> ts[-1]; returns (status, step index reached).  States after the
    steps with slot[i] >= 0 are stored in out_x/out_v[slot[i]]; at most max_steps
    steps are counted in count[4]."""
    x, v = st[0], st[1]
    backup = (x.copy(), v.copy(), st[2].copy(), st[3].copy())
    nsteps = ts.size - 1
    while k < nsteps:
        if count[4] >= max_steps:
            return BUDGET, k
        h = ts[k + 1] - ts[k]
        for i in range(4):
            backup[i][:] = st[i]
        ok = _step(h, k + 1, st, fs, cf, mdl, sys, count, tol, max_iter, False)
        if not ok:
            for i in range(4):
                st[i][:] = backup[i]
            ok = _step(h, k + 1, st, fs, cf, mdl, sys, count, tol, max_iter, True)
        if not ok:
            for i in range(4):
                st[i][:] = backup[i]
            fs[2][0] = np.nan
            return NEWTON_FAILED, k
        k += 1
        count[4] += 1
        if not np.all(np.isfinite(x)):
            return NON_FINITE, k
        if np.max(np.abs(x)) > limit:
            return BLOW_UP, k
        if slot[k] >= 0:
            out_x[slot[k]] = x
            out_v[slot[k]] = v
    return DONE, k


class CompiledAlpha:
    """The arrays of the compiled march for one model (in its pattern's numbering);
    :meth:`applies` says whether the model can use it."""

    def __init__(self, model, opt, ts):
        asm, rheo, p = model.assembly, model.rheo, model.pattern
        self.mdl = p.compiled(asm)
        presc = np.array(sorted({int(d) for dofs, _ in rheo.motions for d in dofs} | set(rheo.follow)),
                         dtype=np.int64)
        gvals = np.array([rheo.g(t)[presc] for t in ts]) if presc.size else np.zeros((ts.size, 0))
        gdd = np.array([rheo.g(t, 2)[presc] for t in ts]) if presc.size else np.zeros((ts.size, 0))
        Mcols = model.M_full[:, presc].toarray() if presc.size else np.zeros((asm.n_dofs, 0))
        Mp = np.zeros((p.n, presc.size))
        np.add.at(Mp, p.zsel, Mcols[p.qsel])
        Q = model.forces.value(rheo.g0, np.zeros(asm.n_dofs), 0.0)
        self.sys = (model.Mb, p.kl, p.reduce(Q), Mp, gdd, presc, gvals, np.array(rheo.g0, dtype=float))
        self.fs = (p.zeros_matrix(), np.zeros(p.n, dtype=np.int64), np.array([np.nan]))
        self.cf = np.array(opt.coefficients())
        self.count = np.zeros(5, dtype=np.int64)

    @staticmethod
    def applies(model) -> bool:
        from ancf.core.forces import Gravity
        p = getattr(model, "pattern", None)
        return (getattr(model, "form", "") == "elimination" and p is not None and p.band
                and p.compiled(model.assembly) is not None
                and all(isinstance(t, Gravity) for t in model.forces.terms))
