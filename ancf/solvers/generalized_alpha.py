"""Generalised-alpha scheme (Chung & Hulbert 1993) in the form of Arnold & Brüls
(2007): all equations at t_{n+1}, so constraints are enforced at the position
level (index 3) and it stays second-order accurate.

    q_{n+1} = q_n + h q'_n + h^2 (1/2 - beta) a_n + h^2 beta a_{n+1}
    q'_{n+1} = q'_n + h (1 - gamma) a_n + h gamma a_{n+1}
    (1 - alpha_m) a_{n+1} + alpha_m a_n = (1 - alpha_f) q''_{n+1} + alpha_f q''_n
    M q''_{n+1} + C_e^T lam = Q(q_{n+1}, q'_{n+1}, t_{n+1}),   C(q_{n+1}, t_{n+1}) = 0

Unknowns q''_{n+1} (and lam); Newton with the exact tangent
``S = M + beta' K + gamma' D`` (beta' = h^2 beta (1-alpha_f)/(1-alpha_m),
gamma' = h gamma (1-alpha_f)/(1-alpha_m)); the constraint rows are scaled by
1/beta' (Bottasso et al.) so the iteration matrix stays well conditioned.  M is
constant, S is refactored (sparse LU) each iteration.  ``rho_inf`` in [0, 1] is
the spectral radius at infinite frequency (1: no numerical dissipation).

The step is fixed (at most ``dt``; see :func:`step_times` for how it meets the
sample times); a step whose Newton iteration fails is retried as two halves,
down to ``dt / 2**max_halvings``; past that the run stops with
``converged=False`` and a message.
"""
from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from ancf.solvers.alpha_compiled import CompiledAlpha
from ancf.solvers.alpha_march import (BLOW_UP, BUDGET, DONE, NON_FINITE, kinematics, march,
                                      newton_settings)
from ancf.solvers.result import DynamicResult, finish, global_samples


@dataclass(frozen=True)
class AlphaOptions:
    dt: float = 1e-3
    rho_inf: float = 0.9
    newton_tol: float = 1e-10     # |dq| <= newton_tol (1 + |q|_inf) (position increment)
    max_iter: int = 15
    max_halvings: int = 6
    max_steps: int = 200_000
    q_limit: float = 1e6          # blow-up: |q|_inf above q_limit (1 + |q0|_inf)
    compiled: bool = True         # use the compiled loop where the model allows
    refresh_ratio: float = 0.02   # contraction above which its iteration matrix is refreshed:
                                  # a factorisation costs a few residuals (alpha_march)

    def coefficients(self):
        r = self.rho_inf
        am, af = (2 * r - 1) / (r + 1), r / (r + 1)
        gamma = 0.5 + af - am
        return am, af, gamma, 0.25 * (gamma + 0.5) ** 2


@dataclass
class _State:
    x: np.ndarray
    v: np.ndarray
    acc: np.ndarray   # true acceleration q''
    a: np.ndarray     # pseudo-acceleration of the recurrence
    lam: np.ndarray


class _Failed(Exception):
    pass


class _Budget(_Failed):
    """Out of steps: not retried with smaller steps."""


class _Stepper:
    def __init__(self, model, opt: AlphaOptions):
        self.model, self.opt = model, opt
        self.am, self.af, self.gamma, self.beta = opt.coefficients()
        self.cf = np.array(opt.coefficients())
        con = model.constraints
        self.m = 0 if con is None else con.m
        self.nfev = self.nlu = self.iters = self.steps = self.rejected = 0

    def initial(self, x0, v0, t0) -> _State:
        if self.m:
            acc, lam = self.model.multipliers(x0, v0, t0)
        else:
            acc, lam = self.model.acc(x0, v0, t0), np.zeros(0)
        return _State(x0, v0, acc, acc.copy(), lam)

    def _kinematics(self, s: _State, acc, h):
        """(q, q', a) at the step's end for the acceleration acc: the compiled march's
        recurrence (:func:`ancf.solvers.alpha_march.kinematics`)."""
        return kinematics(acc, (s.x, s.v, s.acc, s.a), h, self.cf)

    def step(self, s: _State, t1, h) -> _State:
        """One step of size h ending at t1; raises _Failed."""
        ratio = (1 - self.af) / (1 - self.am)
        bp, gp = h * h * self.beta * ratio, h * self.gamma * ratio
        acc, lam = s.acc.copy(), s.lam.copy()
        con, M = self.model.constraints, self.model.M
        for _ in range(self.opt.max_iter):
            x, v, a = self._kinematics(s, acc, h)
            F, K, D = self.model.tangent(x, v, t1)
            self.nfev += 1
            r = M @ acc - F
            S = M + bp * K if D is None else M + bp * K + gp * D
            if self.m:
                Ce = con.jacobian(x, t1)
                r = np.concatenate([r + Ce.T @ lam, con.value(x, t1) / bp])
                S = self._augment(S, Ce)
            d = self._solve(S, -r)
            self.iters += 1
            acc = acc + d[: acc.size]
            lam = lam + d[acc.size:]
            if bp * np.max(np.abs(d[: acc.size])) <= self.opt.newton_tol * (1 + np.max(np.abs(x))):
                x, v, a = self._kinematics(s, acc, h)
                return _State(x, v, acc, a, lam)
        raise _Failed(f"Newton: no convergence in {self.opt.max_iter} iterations")

    def _augment(self, S, Ce):
        if sp.issparse(S):
            return sp.bmat([[S, Ce.T], [Ce, None]])
        Ce = Ce.toarray() if sp.issparse(Ce) else Ce
        return np.block([[S, Ce.T], [Ce, np.zeros((self.m, self.m))]])

    def _solve(self, S, rhs):
        self.nlu += 1
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            try:
                if sp.issparse(S):
                    d = spla.splu(sp.csc_matrix(S)).solve(rhs)
                else:
                    d = sla.lu_solve(sla.lu_factor(S, check_finite=False), rhs, check_finite=False)
            except (RuntimeError, Warning, ValueError, np.linalg.LinAlgError) as exc:
                raise _Failed(f"singular iteration matrix ({exc})") from None
        if not np.all(np.isfinite(d)):
            raise _Failed("non-finite Newton increment")
        return d

    def advance(self, s: _State, t0, h, depth=0) -> _State:
        """Step t0 -> t0 + h, halving on failure."""
        if self.steps >= self.opt.max_steps:
            raise _Budget(f"step budget of {self.opt.max_steps} exhausted at t = {t0:.6g} s")
        try:
            new = self.step(s, t0 + h, h)
            self.steps += 1
            return new
        except _Budget:
            raise
        except _Failed as exc:
            self.rejected += 1
            if depth >= self.opt.max_halvings:
                raise _Failed(f"step size collapse at t = {t0:.6g} s (h = {h:.3g} s, "
                              f"{self.opt.max_halvings} halvings): {exc}") from None
            mid = self.advance(s, t0, h / 2, depth + 1)
            return self.advance(mid, t0 + h / 2, h / 2, depth + 1)


def step_times(t_out, dt: float) -> np.ndarray:
    """Step end times.  dt no longer than the sample spacing: every sample interval is
    split into equal steps <= dt (samples fall on steps).  Otherwise equal steps
    <= dt over the whole span, and the samples are interpolated."""
    t_out = np.asarray(t_out, dtype=float)
    gaps = np.diff(t_out)
    if dt <= gaps.min() * (1 + 1e-9):
        return np.concatenate([t_out[:1], _split(t_out, np.maximum(
            1, np.ceil(gaps / dt - 1e-9)).astype(np.int64))])
    n = max(1, math.ceil((t_out[-1] - t_out[0]) / dt - 1e-9))
    return np.linspace(t_out[0], t_out[-1], n + 1)


def _split(t_out, m):
    """The ends of m[i] equal parts of each interval [t_out[i], t_out[i + 1]], the
    values of ``np.linspace(t_out[i], t_out[i + 1], m[i] + 1)[1:]``, in one array."""
    a, b = t_out[:-1], t_out[1:]
    which = np.repeat(np.arange(m.size), m)
    ends = np.cumsum(m)
    k = np.arange(1, ends[-1] + 1) - np.repeat(ends - m, m)
    t = k * ((b - a) / m)[which] + a[which]
    t[ends - 1] = b
    return t


def _hermite(s0: _State, s1: _State, ta, tb, t):
    """Cubic Hermite (x, v, lam) at t in [ta, tb] from the step's end states."""
    h = tb - ta
    u = (t - ta) / h
    h00, h10, h01, h11 = 2 * u**3 - 3 * u**2 + 1, u**3 - 2 * u**2 + u, -2 * u**3 + 3 * u**2, u**3 - u**2
    d00, d10, d01, d11 = 6 * u**2 - 6 * u, 3 * u**2 - 4 * u + 1, -6 * u**2 + 6 * u, 3 * u**2 - 2 * u
    x = h00 * s0.x + h10 * h * s0.v + h01 * s1.x + h11 * h * s1.v
    v = (d00 * s0.x + d01 * s1.x) / h + d10 * s0.v + d11 * s1.v
    return x, v, (1 - u) * s0.lam + u * s1.lam


def _run_steps(st: _Stepper, s: _State, t_out, ts, limit):
    """March over the step times ts, collecting the samples at t_out; returns
    (X, V, Lam, ok, message)."""
    X, V, L = [s.x], [s.v], [s.lam]
    k = 1
    try:
        for ta, tb in zip(ts[:-1], ts[1:]):
            new = st.advance(s, ta, tb - ta)
            if not np.all(np.isfinite(new.x)):
                raise _Failed(f"non-finite coordinates at t = {tb:.6g} s")
            if np.max(np.abs(new.x)) > limit:
                raise _Failed(f"blow-up: |q| exceeded {limit:.3g} at t = {tb:.6g} s "
                              "(energy growing without bound)")
            while k < len(t_out) and t_out[k] <= tb + 1e-12 * max(1.0, abs(tb)):
                x, v, lam = (new.x, new.v, new.lam) if abs(t_out[k] - tb) <= 1e-12 * max(1.0, abs(tb)) \
                    else _hermite(s, new, ta, tb, t_out[k])
                X.append(x), V.append(v), L.append(lam)
                k += 1
            s = new
    except _Failed as exc:
        return X, V, L, False, str(exc)
    return X, V, L, True, "reached t_end"


def _located(t_out, ts):
    """(i, near): per sample time, the first step end ts[i] at or after it (within
    1e-12 s, relative above 1 s) and whether the sample falls on it."""
    t_out = np.asarray(t_out, dtype=float)
    i = np.minimum(np.searchsorted(ts, t_out - 1e-12 * np.maximum(1.0, np.abs(t_out))),
                   ts.size - 1)
    return i, np.abs(t_out - ts[i]) <= 1e-12 * np.maximum(1.0, np.abs(ts[i]))


def _keep_slots(t_out, ts):
    """slot[i] >= 0 for the step ends whose states the samples need (the step a
    sample falls on, or both ends of the step it is interpolated in)."""
    slot = np.full(ts.size, -1, dtype=np.int64)
    i, near = _located(t_out[1:], ts)
    need = np.unique(np.concatenate([[0], i, i[~near] - 1]))
    slot[need] = np.arange(need.size)
    return slot, need.size


def _compiled_samples(t_out, ts, slot, out_x, out_v, reached):
    """Samples (X, V) up to the step index reached, from the kept step-end states."""
    X, V = [], []
    for t, i, near in zip(t_out, *_located(t_out, ts)):
        if i > reached:
            break
        if near:
            X.append(out_x[slot[i]]), V.append(out_v[slot[i]])
            continue
        s0, s1 = (_State(out_x[slot[j]], out_v[slot[j]], None, None, np.zeros(0)) for j in (i - 1, i))
        x, v, _ = _hermite(s0, s1, ts[i - 1], ts[i], t)
        X.append(x), V.append(v)
    return X, V


def _python_fallback(st, state, ts, k, slot, out_x, out_v):
    """Take step k with the Python stepper (step halving), updating state in place;
    returns (ok, message, step reached, next step)."""
    cur = _State(*(a.copy() for a in state), np.zeros(0))
    try:
        new = st.advance(cur, ts[k], ts[k + 1] - ts[k])
    except _Failed as exc:
        return False, str(exc), k, k
    for arr, val in zip(state, (new.x, new.v, new.acc, new.a)):
        arr[:] = val
    if slot[k + 1] >= 0:
        out_x[slot[k + 1]], out_v[slot[k + 1]] = state[0], state[1]
    return True, "reached t_end", ts.size - 1, k + 1


def _run_compiled(model, st, s, t_out, ts, limit, opt):
    """March with the compiled loop, handing failed steps to the Python stepper."""
    ca = CompiledAlpha(model, opt, ts)
    slot, kept = _keep_slots(t_out, ts)
    state = tuple(np.array(a, dtype=float) for a in (s.x, s.v, s.acc, s.a))
    out_x, out_v = np.zeros((kept, s.x.size)), np.zeros((kept, s.x.size))
    out_x[slot[0]], out_v[slot[0]] = state[0], state[1]
    k, ok, msg, reached = 0, True, "reached t_end", ts.size - 1
    while ok:
        status, k = march(ts, k, ts.size - 1, state, ca.system, ca.hf, ca.cf, ca.count,
                          newton_settings(opt.newton_tol, opt.refresh_ratio),
                          opt.max_iter, limit,
                          opt.max_steps - st.steps, slot,
                          out_x, out_v)
        if status == DONE:
            break
        ok, reached = False, k - 1
        if status == BUDGET:
            msg, reached = f"step budget of {opt.max_steps} exhausted at t = {ts[k]:.6g} s", k
        elif status == NON_FINITE:
            msg = f"non-finite coordinates at t = {ts[k]:.6g} s"
        elif status == BLOW_UP:
            msg = (f"blow-up: |q| exceeded {limit:.3g} at t = {ts[k]:.6g} s "
                   "(energy growing without bound)")
        else:
            ok, msg, reached, k = _python_fallback(st, state, ts, k, slot, out_x, out_v)
    X, V = _compiled_samples(t_out, ts, slot, out_x, out_v, reached)
    return X, V, [np.zeros(0)] * len(X), ok, msg, ca.count


def integrate_generalized_alpha(model, x0, v0, t_out, opt: AlphaOptions) -> DynamicResult:
    """Fixed-step generalised-alpha over the samples ``t_out`` (see :func:`step_times`);
    compiled (:mod:`ancf.solvers.alpha_march`) where the model allows."""
    st, t_out = _Stepper(model, opt), np.asarray(t_out, dtype=float)
    limit = opt.q_limit * (1.0 + np.max(np.abs(x0)))
    count = np.zeros(5, dtype=np.int64)  # residuals, tangents, factorisations, iterations, steps
    t0 = time.process_time()
    with np.errstate(all="ignore"):
        s = st.initial(np.asarray(x0, float), np.asarray(v0, float), t_out[0])
        ts = step_times(t_out, opt.dt)
        if opt.compiled and CompiledAlpha.applies(model):
            X, V, L, ok, msg, count = _run_compiled(model, st, s, t_out, ts, limit, opt)
        else:
            X, V, L, ok, msg = _run_steps(st, s, t_out, ts, limit)
    cpu = time.process_time() - t0
    tt = t_out[: len(X)]
    q, v = global_samples(model, np.array(X), np.array(V), tt)
    res = DynamicResult(t=tt, q=q, v=v, converged=ok, message=msg,
                        integrator="generalized-alpha", steps=st.steps + int(count[4]),
                        nfev=st.nfev + int(count[0]), njev=st.nfev + int(count[1]),
                        nlu=st.nlu + int(count[2]), newton_iterations=st.iters + int(count[3]),
                        rejected_steps=st.rejected, cpu_time_s=cpu,
                        multipliers=np.array(L) if st.m else None)
    return finish(model, res, np.array(X))
