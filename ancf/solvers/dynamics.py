"""Equations of motion M e'' = Q_e + Q_k (thesis Eqs 2.27-2.32) and their integration.

Two forms of the same constrained system, interchangeable in every integrator:

* :class:`ReducedModel` (elimination): q = T z + g(t), so
  ``M_r z'' = T^T (Q(q, q', t) - M g''(t))`` with ``M_r = T^T M T`` factored once.
* :class:`MultiplierModel` (Lagrange multipliers, Eq. 2.32): all coordinates,
  ``M q'' + C_e^T lam = Q`` and the constraints; M factored once, the multipliers
  from the Schur complement ``C_e M^-1 C_e^T`` (constant for linear constraints).

A model exposes ``n``, ``M`` and the tangents (dense numpy up to
``DENSE_MAX`` global coordinates, where sparse bookkeeping would cost more than
the arithmetic; sparse CSR above), ``force`` / ``tangent`` (for the
generalised-alpha scheme, ``ancf.solvers.generalized_alpha``), ``acc`` /
``acc_jacobian`` (the first-order ODE for scipy's integrators; that Jacobian
is always dense, since M^-1 of the consistent mass is full) and ``full``
(global q, q').  :func:`integrate` runs either integrator family and returns a
:class:`DynamicResult`; non-convergence (failed step, step collapse, NaN or
blow-up, step budget) is ``converged=False`` plus a ``message``, never an
exception and never a silent NaN.
"""
from __future__ import annotations

import time
import warnings

import numpy as np
import scipy.integrate as si
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from numba import njit

from ancf.core.pattern import ReducedPattern, assemble_group
from ancf.solvers.banded import solve as banded_solve
from ancf.solvers.linear import Singular, factor
from ancf.solvers.result import DynamicResult, finish, global_samples, stacked

IVP_METHODS = {"rk45": si.RK45, "dop853": si.DOP853, "radau": si.Radau, "bdf": si.BDF}
IMPLICIT = ("radau", "bdf")
INTEGRATORS = tuple(IVP_METHODS) + ("generalized-alpha",)


class _Dense:
    """Dense inverse of a constant SPD matrix, computed once, for Jacobians."""

    def __init__(self, lu, n):
        self._lu, self._n, self._inv = lu, n, None

    @property
    def inv(self) -> np.ndarray:
        if self._inv is None:
            self._inv = self._lu.solve(np.eye(self._n))
        return self._inv


#: systems up to this many global coordinates use dense tangents and LU (the sparse
#: bookkeeping costs more than the arithmetic for the small beams of the papers).
#: Measured crossover (generalised-alpha pendulum, process time, OPENBLAS 1 thread):
#: linear 132 DOFs dense 0.096 s / sparse 0.091 s, 260 DOFs 0.58 / 0.22 s;
#: Omar-Shabana 102 DOFs 0.111 / 0.120 s, 198 DOFs 0.34 / 0.24 s.
DENSE_MAX = 128


def _factor(M):
    return spla.splu(sp.csc_matrix(M))


def _dense(A):
    return A.toarray() if sp.issparse(A) else np.asarray(A)


def assembled_tangent(assembly, q, dense: bool):
    """dU/dq and d2U/dq2, dense (np.add.at on the element blocks) or sparse CSR."""
    if not dense:
        return assembly.gradient_tangent(q)
    n = assembly.n_dofs
    g, K = np.zeros(n), np.zeros((n, n))
    for grp in assembly.groups:
        ge, Ke = grp.element.gradient(q[grp.dofmap], tangent=True)
        np.add.at(g, grp.dofmap, ge)
        np.add.at(K, (grp.rows, grp.cols), Ke.ravel())
    return g, K


def _mul(A, B):
    """Dense A @ B for B dense or sparse."""
    return (B.T @ A.T).T if sp.issparse(B) else A @ B


@njit(cache=True)
def _elastic_gradient(group, z, g, grad):
    """grad = T^T dU/dq at q = T z + g (N): :func:`~ancf.core.pattern.assemble_group`
    without the tangent, one call from Python."""
    assemble_group(group, z, g, False, grad, np.zeros((1, 1)))


@njit(cache=True)
def _rate(group, y, g, load, AB, kl, piv):
    """([z', z''], finite) at y = [z, z'] with z'' = M_r^-1 (T^T Q - T^T dU/dq) (band
    factors AB, piv of :func:`ancf.solvers.banded.lu`): ReducedModel.acc's arithmetic."""
    n = load.size
    grad = np.empty(n)
    _elastic_gradient(group, y[:n], g, grad)
    a = np.empty(n)
    for i in range(n):
        a[i] = load[i] - grad[i]
    banded_solve(AB, kl, piv, a)
    out = np.empty(2 * n)
    out[:n] = y[n:]
    out[n:] = a
    return out, np.isfinite(a).all()


class ReducedModel:
    """Elimination form q = T z + g(t) (``rheo`` from ``Elimination.rheonomic()``), in
    the numbering of its :class:`~ancf.core.pattern.ReducedPattern`: forces and tangents
    are scattered straight into the reduced system, M_r is factored once (band LU)."""

    form = "elimination"
    constraints = None

    def __init__(self, assembly, forces, rheo, dense: bool | None = None):
        self.assembly, self.forces, self.rheo = assembly, forces, rheo
        self.dense = assembly.n_dofs <= DENSE_MAX if dense is None else dense
        self.pattern = p = ReducedPattern(assembly.n_dofs, [g.dofmap for g in assembly.groups], rheo.T)
        self.n = p.n
        self.T = rheo.T.tocsr()[:, np.argsort(p.order)].tocsr()  # columns in the pattern's order
        self.TT = self.T.T.tocsr()
        self.M_full = assembly.mass()
        self.Mb = p.mass(assembly)
        self.lu = factor(p, self.Mb)
        self.minv = _Dense(self.lu, self.n)
        M = p.as_csr(self.Mb)
        self.M = M.toarray() if self.dense else M
        self._zero = np.zeros(assembly.n_dofs)
        self._fast = self._constant_load()

    def _constant_load(self):
        """(compiled group, T^T Q) where :meth:`force` needs one compiled call: a single
        element group on band storage (:meth:`ReducedPattern.compiled`), g not depending
        on time and every force term constant (gravity); else None.  The same arithmetic
        as the general path (q = g + T z, the element kernel, the scatter, T^T Q once)."""
        if self.rheo.time_dependent or not getattr(self.forces, "constant", False):
            return None
        group = self.pattern.compiled(self.assembly)
        if group is None:
            return None
        q = self.rheo.g0
        return group, self.pattern.reduce(self.forces.value(q, self._zero, 0.0))

    def _g(self, t, order=0):
        if self.rheo.time_dependent:
            return self.rheo.g(t, order)
        return self.rheo.g0 if order == 0 else self._zero

    def full(self, z, zd, t):
        return self.pattern.expand(z, self._g(t)), self.pattern.expand(zd, self._g(t, 1))

    def samples(self, Z, Zd, ts):
        """Global (q, q') at the times ts from the states Z, Zd (one row per time): the
        rows of :meth:`full`, in one scatter where g does not depend on time."""
        if self.rheo.time_dependent or not len(ts):
            return stacked([self.full(z, zd, t) for z, zd, t in zip(Z, Zd, ts)])
        p, shape = self.pattern, (len(ts), self.assembly.n_dofs)
        Q = np.broadcast_to(np.asarray(self.rheo.g0, dtype=float), shape).copy()
        V = np.zeros(shape)
        Q[:, p.qsel] += np.asarray(Z)[:, p.zsel]
        V[:, p.qsel] += np.asarray(Zd)[:, p.zsel]
        return Q, V

    def initial(self, q0, v0):
        return self.pattern.restrict(q0), self.pattern.restrict(v0)

    def _inertial(self, t):
        if not self.rheo.time_dependent:
            return 0.0
        return self.pattern.reduce(self.M_full @ self.rheo.g(t, 2))

    def force(self, z, zd, t):
        if self._fast is not None:  # one compiled call (:meth:`_constant_load`)
            group, load = self._fast
            grad = np.empty(self.n)
            _elastic_gradient(group, z, self.rheo.g0, grad)
            return load - grad
        q, v = self.full(z, zd, t)
        grad, _ = self.pattern.assemble(self.assembly, q, want_K=False)
        return self.pattern.reduce(self.forces.value(q, v, t)) - grad - self._inertial(t)

    def tangent(self, z, zd, t):
        """(F_r, K_r = -dF_r/dz, D_r = -dF_r/dz' or None), dense or sparse."""
        q, v = self.full(z, zd, t)
        grad, Kb = self.pattern.assemble(self.assembly, q)
        F = self.pattern.reduce(self.forces.value(q, v, t)) - grad - self._inertial(t)
        K = self.pattern.as_csr(Kb)
        Kq, Kv = self.forces.jacobians(q, v, t)
        if Kq is not None:
            K = K - self.TT @ Kq @ self.T
        D = None if Kv is None else -(self.TT @ Kv @ self.T).tocsr()
        if self.dense:
            return F, _dense(K), None if D is None else _dense(D)
        return F, K.tocsr(), D

    def acc(self, z, zd, t):
        return self.lu.solve(self.force(z, zd, t))

    def rate_function(self):
        """y = [z, z'] -> [z', z''] in one compiled call (Singular where not finite), as
        [z', :meth:`acc`], where :meth:`force` is one call and M_r is band-factored; else
        None."""
        if self._fast is None or getattr(self.lu, "AB", None) is None:
            return None
        (group, load), g, lu = self._fast, self.rheo.g0, self.lu

        def rate(y):
            out, finite = _rate(group, y, g, load, lu.AB, lu.kl, lu.piv)
            if not finite:
                raise Singular("non-finite solution")
            return out
        return rate

    def acc_jacobian(self, z, zd, t):
        """Dense d(acc)/dz = -M_r^-1 K_r and d(acc)/dz' = -M_r^-1 D_r."""
        _, K, D = self.tangent(z, zd, t)
        Jv = np.zeros((self.n, self.n)) if D is None else -_mul(self.minv.inv, D)
        return -_mul(self.minv.inv, K), Jv

    def violation(self, z, t) -> float:
        return 0.0


class MultiplierModel:
    """Lagrange-multiplier form (Eq. 2.32) with Baumgarte drift control for the
    index-1 (acceleration) form; ``constraints`` from ``ancf.core.multipliers``."""

    form = "lagrange"

    def __init__(self, assembly, forces, constraints, baumgarte, dense: bool | None = None):
        self.assembly, self.forces = assembly, forces
        self.constraints, self.baumgarte = constraints, baumgarte
        self.dense = assembly.n_dofs <= DENSE_MAX if dense is None else dense
        M = assembly.mass().tocsr()
        self.n = M.shape[0]
        self.lu = _factor(M)
        self.M = M.toarray() if self.dense else M
        self.minv = _Dense(self.lu, self.n)
        self._schur = None
        if constraints.constant_jacobian:
            self._schur = self._schur_of(constraints.jacobian(None, 0.0))

    def _schur_of(self, B):
        Y = self.lu.solve(np.asarray(B.T.todense()))  # M^-1 C_e^T, (n, m)
        return B, Y, sla.cho_factor(B @ Y)

    def full(self, q, v, t):
        return q, v

    def initial(self, q0, v0):
        return np.asarray(q0, dtype=float).copy(), np.asarray(v0, dtype=float).copy()

    def force(self, q, v, t):
        return self.forces.value(q, v, t) - self.assembly.gradient(q)

    def tangent(self, q, v, t):
        grad, K = assembled_tangent(self.assembly, q, self.dense)
        Kq, Kv = self.forces.jacobians(q, v, t)
        conv = _dense if self.dense else (lambda A: sp.csr_matrix(A))
        if Kq is not None:
            K = K - conv(Kq)
        return self.forces.value(q, v, t) - grad, K, None if Kv is None else -conv(Kv)

    def _schur_at(self, q, t):
        return self._schur or self._schur_of(self.constraints.jacobian(q, t))

    def multipliers(self, q, v, t):
        """(acceleration, lambda) of the stabilised Eq. 2.32."""
        B, Y, S = self._schur_at(q, t)
        a0 = self.lu.solve(self.force(q, v, t))
        lam = sla.cho_solve(S, B @ a0 - self.baumgarte.qd(self.constraints, q, v, t))
        return a0 - Y @ lam, lam

    def acc(self, q, v, t):
        return self.multipliers(q, v, t)[0]

    def acc_jacobian(self, q, v, t):
        """Dense d(acc)/dq and d(acc)/dq' of the stabilised index-1 form (exact for
        linear constraints; for nonlinear ones the derivative of C_e is left out)."""
        B, Y, S = self._schur_at(q, t)
        _, K, D = self.tangent(q, v, t)
        MK = _mul(self.minv.inv, K)  # M^-1 K
        P = lambda A: A - Y @ sla.cho_solve(S, B @ A)  # noqa: E731  (I - Y S^-1 B) A
        dq, dv = self.baumgarte.qd_jacobians(self.constraints, q, t)
        Jq = -P(MK) + Y @ sla.cho_solve(S, np.asarray(dq.todense()))
        Jv = Y @ sla.cho_solve(S, np.asarray(dv.todense()))
        if D is not None:
            Jv = Jv - P(_mul(self.minv.inv, D))
        return Jq, Jv

    def violation(self, q, t) -> float:
        c = self.constraints.value(q, t)
        return float(np.max(np.abs(c))) if c.size else 0.0


class _Abort(Exception):
    pass


def _ivp_fun(model, n, budget):
    """y' = [x', acc]; trial stages may be wild (the step is then rejected), so only
    the accepted states are checked for blow-up, in :func:`integrate_ivp`."""
    calls = [0]
    rate = getattr(model, "rate_function", lambda: None)()  # one compiled call, or None

    def fun(t, y):
        calls[0] += 1
        if calls[0] > budget:
            raise _Abort(f"function-evaluation budget of {budget} exhausted at t = {t:.6g} s")
        if rate is not None:
            return rate(y)
        with np.errstate(all="ignore"):
            return np.concatenate([y[n:], model.acc(y[:n], y[n:], t)])
    return fun


def _ivp_jac(model, n):
    def jac(t, y):
        Jq, Jv = model.acc_jacobian(y[:n], y[n:], t)
        return np.block([[np.zeros((n, n)), np.eye(n)], [Jq, Jv]])
    return jac


def _samples(model, t_out, X):
    """Global q, q' at the samples from the integrated states X (k, 2n)."""
    n = model.n
    X = np.asarray(X)
    return global_samples(model, X[:, :n], X[:, n:], t_out)


def _step_loop(solver, t_out, max_steps, limit, X, count):
    """Advance ``solver`` to t_out[-1], appending its dense output at t_out to X and
    counting accepted steps in count[0].  Returns (ok, message)."""
    k = 1
    while solver.status == "running":
        if count[0] >= max_steps:
            return False, f"step budget of {max_steps} exhausted at t = {solver.t:.6g} s"
        m = solver.step()
        count[0] += 1
        if solver.status == "failed":
            return False, f"step size collapse at t = {solver.t:.6g} s ({m})"
        if not np.all(np.isfinite(solver.y)):
            return False, f"non-finite state at t = {solver.t:.6g} s"
        if np.max(np.abs(solver.y)) > limit:
            return False, (f"blow-up: |y| exceeded {limit:.3g} at t = {solver.t:.6g} s "
                           "(energy growing without bound)")
        j = int(np.searchsorted(t_out, solver.t, side="right"))
        if j > k:
            X.extend(np.atleast_2d(solver.dense_output()(t_out[k:j]).T))
            k = j
    return True, "reached t_end"


def integrate_ivp(model, x0, v0, t_out, method="dop853", rtol=1e-8, atol=1e-10,
                  max_steps=200_000, y_limit=1e6) -> DynamicResult:
    """scipy integrator (``rk45``, ``dop853``, ``radau``, ``bdf``) on y = [x, x'], stepped
    by hand so that steps can be counted and failures reported.  Implicit methods get
    the analytic Jacobian (dense: M^-1 is full for the consistent mass)."""
    n, t_out = model.n, np.asarray(t_out, dtype=float)
    y0 = np.concatenate([x0, v0])
    kw = {"jac": _ivp_jac(model, n)} if method in IMPLICIT else {}
    t0 = time.process_time()
    X, count, solver = [y0], [0], None
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            solver = IVP_METHODS[method](_ivp_fun(model, n, 20 * max_steps), t_out[0], y0,
                                         t_out[-1], rtol=rtol, atol=atol, **kw)
            ok, msg = _step_loop(solver, t_out, max_steps, y_limit * (1.0 + np.max(np.abs(y0))),
                                 X, count)
        except _Abort as exc:
            ok, msg = False, str(exc)
        except (np.linalg.LinAlgError, ValueError, RuntimeError, Singular) as exc:
            ok, msg = False, f"stopped: {exc} (a singular or ill-conditioned solve)"
    cpu = time.process_time() - t0
    X = np.array(X)
    finite = np.all(np.isfinite(X), axis=1)
    if not finite.all():
        ok, msg, X = False, "non-finite state in the output", X[: int(np.argmin(finite))]
    elif ok and len(X) < t_out.size:
        ok, msg = False, "stopped before t_end"
    q, v = _samples(model, t_out[:len(X)], X)
    res = DynamicResult(t=t_out[:len(X)], q=q, v=v, converged=ok,
                        message=msg if ok else f"{method}: {msg}", integrator=method,
                        steps=count[0], nfev=getattr(solver, "nfev", 0),
                        njev=getattr(solver, "njev", 0), nlu=getattr(solver, "nlu", 0),
                        cpu_time_s=cpu)
    return finish(model, res, X[:, :n])


def integrate(model, q0, v0, t_out, integrator: str, *, rtol=1e-8, atol=1e-10, dt=1e-3,
              rho_inf=0.9, max_steps=200_000) -> DynamicResult:
    """Integrate from global q0, q0' over the sample times ``t_out`` (first = start)."""
    x0, xd0 = model.initial(q0, v0)
    if integrator == "generalized-alpha":
        from ancf.solvers.generalized_alpha import AlphaOptions, integrate_generalized_alpha
        return integrate_generalized_alpha(model, x0, xd0, t_out,
                                           AlphaOptions(dt=dt, rho_inf=rho_inf, max_steps=max_steps))
    if integrator not in IVP_METHODS:
        raise ValueError(f"integrator must be one of {', '.join(INTEGRATORS)} (got {integrator!r})")
    return integrate_ivp(model, x0, xd0, t_out, integrator, rtol, atol, max_steps)
