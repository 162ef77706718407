"""The belt drive with scipy's variable-step, variable-order BDF: an integrator with
error control, independent of the generalised-alpha march, for cross-checks and the
speed-accuracy study.

First-order form y = (x, v) of the equations of :mod:`ancf.belts.system`:

    x' = v,    v' = -Mt^-1 f(x, v, t),    Mt = diag(M, I_1, ..., I_k)

with the same compiled forces (:func:`ancf.belts.forces.evaluate`, called by
:func:`~ancf.belts.forces.evaluate_record`; the mass matrix is factored once).  The
Jacobian is exact and dense, ``[[0, I], [-Mt^-1 df/dx, -Mt^-1 df/dv]]``, its two blocks
from two evaluations of the iteration-matrix assembly (beta' = 1, gamma' = 0 and the reverse).
"""
from __future__ import annotations

import time

import numpy as np
from scipy.integrate import BDF

from ancf.solvers import banded
from ancf.belts import friction
from ancf.belts.forces import evaluate_record
from ancf.solvers.result import DynamicResult


class _FirstOrder:
    def __init__(self, drive):
        self.d, self.drive, self.n, self.k = drive, drive.kernel(), drive.n, drive.k
        if friction.has_state(self.drive.prm):
            raise ValueError("a friction law with a state per contact point steps with the "
                             "generalised-alpha march only; allowed with BDF: "
                             + ", ".join(friction.LAWS))
        self.kl = drive.pattern.kl
        self.M = drive.Mb.copy()
        self.piv = np.zeros(self.n, dtype=np.int64)
        banded.lu(self.M, self.kl, self.piv, False)
        self.nfev = self.njev = 0

    def _inv_mass(self, F):
        """Mt^-1 F for F (n + k,) or (n + k, m), in place."""
        cols = F if F.ndim == 2 else F[:, None]
        for j in range(cols.shape[1]):
            c = np.ascontiguousarray(cols[: self.n, j])
            banded.solve(self.M, self.kl, self.piv, c)
            cols[: self.n, j] = c
        cols[self.n:] /= self.drive.inertia[:, None]
        return F

    def _laws(self, t):
        return self.d.laws(np.array([t]))[:, 0].copy()

    def fun(self, t, y):
        n, k = self.n, self.k
        m = n + k
        f = np.zeros(m)
        evaluate_record(y[:m], y[m:], self._laws(t), self.drive, False, 0.0, 0.0, f,
                        np.zeros((1, 1)), np.zeros((k, n)), np.zeros((k, n)), np.zeros((k, k)))
        self.nfev += 1
        return np.concatenate([y[m:], -self._inv_mass(f)])

    def _block(self, t, y, bp, gp):
        """Dense d f / d(x or v) (bp, gp = 1, 0 or 0, 1)."""
        n, k = self.n, self.k
        m = n + k
        mat, col, row = self.d.pattern.zeros_matrix(), np.zeros((k, n)), np.zeros((k, n))
        corner = np.zeros((k, k))
        evaluate_record(y[:m], y[m:], self._laws(t), self.drive, True, bp, gp, np.zeros(m), mat,
                        col, row, corner)
        D = np.zeros((m, m))
        D[:n, :n] = self.d.pattern.as_csr(mat).toarray()
        D[:n, n:], D[n:, :n], D[n:, n:] = col.T, row, corner
        return D

    def jac(self, t, y):
        m = self.n + self.k
        self.njev += 1
        J = np.zeros((2 * m, 2 * m))
        J[:m, m:] = np.eye(m)
        J[m:, :m] = -self._inv_mass(self._block(t, y, 1.0, 0.0))
        J[m:, m:] = -self._inv_mass(self._block(t, y, 0.0, 1.0))
        return J


def simulate_bdf(drive, t_out, rtol: float, atol: float, x0, max_steps: int) -> DynamicResult:
    """Integrate with scipy's BDF from x0 at rest over the sample times t_out (s); at most
    max_steps steps."""
    sys_ = _FirstOrder(drive)
    m = drive.n + drive.k
    solver = BDF(sys_.fun, t_out[0], np.concatenate([x0, np.zeros_like(x0)]), t_out[-1],
                 rtol=rtol, atol=atol, jac=sys_.jac)
    Y, k, steps, msg = [solver.y.copy()], 1, 0, "ok"
    t0 = time.process_time()
    while k < t_out.size:
        if steps >= max_steps:
            msg = "step budget exhausted (max_steps)"
            break
        err = solver.step()
        steps += 1
        if err is not None or solver.status == "failed":
            msg = f"no convergence: {err or 'BDF failed'}"
            break
        hit = np.flatnonzero(t_out[k:] <= solver.t + 1e-12 * max(1.0, abs(solver.t)))
        if hit.size:
            dense = solver.dense_output()
            Y += [dense(t) for t in t_out[k: k + hit.size]]
            k += hit.size
    Y = np.array(Y)
    res = DynamicResult(t=t_out[:k], q=Y[:, :m], v=Y[:, m:], converged=msg == "ok",
                        message=msg, integrator="bdf", steps=steps,
                        nfev=sys_.nfev, njev=sys_.njev, nlu=int(solver.nlu),
                        newton_iterations=0, cpu_time_s=time.process_time() - t0)
    res.extra["contact_pairs"] = 0
    return res
