"""Time integration of the belt drives: set-up and bookkeeping around the compiled
generalised-alpha march (:mod:`ancf.solvers.alpha_march`) of a drive's system
(:mod:`ancf.belts.system`).

The steps are fixed (at most ``dt``, samples on steps, see
:func:`ancf.solvers.generalized_alpha.step_times`); a step whose Newton iteration
fails even with fresh factors is retried as two halves, down to
``dt / 2**max_halvings``; past that the run stops with ``converged=False`` and a
message, keeping the samples it reached.  The initial accelerations are
consistent (M a0 = -f(x0, v0)).  Given a window's start, the march also averages the
pulley speeds and the belt's moments on the pulleys over every step after it
(:mod:`ancf.belts.system`), halved steps included.
"""
from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

from ancf.belts.system import PAIRS, belt_system, force_residual, steps, window_weights
from ancf.solvers import banded
from ancf.solvers.alpha_march import (BLOW_UP, BUDGET, DONE, NEWTON_FAILED, NON_FINITE,
                                      REFRESH_RATIO, march, newton_settings)
from ancf.solvers.generalized_alpha import AlphaOptions, step_times
from ancf.solvers.result import DynamicResult

CHUNKS = 20  # progress reports per run, at least
CHUNK_S = 2.0  # with progress: wall seconds per chunk, about
MESSAGES = {DONE: "ok", BUDGET: "step budget exhausted (max_steps)",
            NON_FINITE: "non-finite coordinates", BLOW_UP: "coordinates blew up"}


@dataclass(frozen=True, kw_only=True)
class BeltOptions:
    dt: float = 2.5e-4
    rho_inf: float = 0.5
    newton_tol: float = 1e-7     # beta' |d acc|_inf <= tol (1 + |z|_inf)
    refresh_ratio: float = REFRESH_RATIO  # modified Newton: refactor when |d_k| > it |d_k-1|
    newton_accept: str = "applied"  # the converged state (ancf.solvers.alpha_march.ACCEPT)
    refresh: str = "contraction"  # when it refactors (ancf.solvers.alpha_march.REFRESH)
    give_up: int = 0             # damped increments before a cycling step gives up (0: never)
    max_iter: int = 12
    max_halvings: int = 4
    max_steps: int = 400_000
    q_limit: float = 1e3         # blow-up: |z|_inf above q_limit (1 + |z0|_inf)


class _March:
    """The arrays of one run of the compiled march."""

    def __init__(self, drive, opt: BeltOptions, ts, nslots: int, mean_from: float = np.inf):
        self.drive, self.opt, self.mean_from = drive, opt, mean_from
        self.system = belt_system(drive, ts, nslots, mean_from)
        self.system.drive.z[:] = 0.0  # a friction law's state (if any): the belt at rest
        self.system.drive.h[0] = 0.0
        self.ts = ts
        self.hf = np.array([np.nan])
        self.cf = np.array(AlphaOptions(rho_inf=opt.rho_inf).coefficients())
        self.count = np.zeros(PAIRS + 1, dtype=np.int64)

    def set_times(self, ts):
        self.ts = ts
        self.system = self.system._replace(tabs=self.drive.laws(ts), steps=steps(ts),
                                           window=window_weights(ts, self.mean_from))

    def initial_acceleration(self, x, v):
        s, n = self.system, self.drive.n
        f = np.zeros(n + self.drive.k)
        force_residual(s, x, v, 0, False, f)
        M = s.Mb.copy()
        piv = np.zeros(n, dtype=np.int64)
        banded.lu(M, s.kl, piv, True)
        a = -f
        banded.solve(M, s.kl, piv, a[:n])
        a[n:] /= s.drive.inertia
        return a

    def run(self, st, k, k_stop, slot, out_x, out_v, limit):
        o = self.opt
        newton = newton_settings(o.newton_tol, o.refresh_ratio, o.newton_accept, o.refresh,
                                 o.give_up)
        return march(self.ts, k, k_stop, st, self.system, self.hf, self.cf, self.count, newton,
                     o.max_iter, limit, o.max_steps, slot, out_x, out_v)


def _halved(m: _March, st, ta, tb, depth, limit, s=-1, out=None) -> bool:
    """Advance st from ta to tb in 2**depth equal steps (recursively on failure); the
    state at tb goes to output slot s of out = (X, V) (s = -1: none), as the march keeps
    it (and a friction law's state with it)."""
    ts_keep = m.ts
    sub = np.linspace(ta, tb, 3)
    m.set_times(sub)
    dummy = np.zeros((1, st[0].size))
    slot = np.array([-1, -1, s], dtype=np.int64)
    status, k = m.run(st, 0, 2, slot, *(out or (dummy, dummy)), limit)
    ok = status == DONE
    if not ok and status not in (NON_FINITE, BLOW_UP, BUDGET) and depth < m.opt.max_halvings:
        ok = all(_halved(m, st, a, b, depth + 1, limit, s if b == tb else -1, out)
                 for a, b in zip(sub[k:-1], sub[k + 1:]))
    m.set_times(ts_keep)
    return ok


def _chunks(n_steps: int, timed: bool):
    """Step indices at which the march returns to Python (a progress line may follow):
    :data:`CHUNKS` equal parts, and with ``timed`` parts of at most about
    :data:`CHUNK_S` s of wall time, sized from the pace of the steps so far.  The march
    carries its state across calls, so the split leaves the arithmetic unchanged."""
    size, k, t0 = max(n_steps // CHUNKS, 1), 0, time.monotonic()
    while k < n_steps:
        step = size
        if timed and k > 0:
            pace = (time.monotonic() - t0) / k  # s per step so far
            step = min(size, max(int(CHUNK_S / max(pace, 1e-9)), 1))
        k = min(k + step, n_steps)
        yield k


def simulate(drive, t_out, opt: BeltOptions, x0=None, v0=None, progress=None,
             mean_from: float = np.inf) -> DynamicResult:
    """Integrate the belt drive over the sample times t_out (s) from x0, v0 (system
    vectors; default: the laid belt at rest).  ``progress(t)`` is called per chunk.
    With ``mean_from`` (s) before the end, ``extra["step_means"]`` = (omega, T) (np,):
    the pulley speeds (rad/s) and the belt's moments on them (N m) averaged over every
    step after mean_from, each step's end state weighted by its part after mean_from."""
    t_out = np.asarray(t_out, dtype=float)
    ts = step_times(t_out, opt.dt)
    slot = np.full(ts.size, -1, dtype=np.int64)
    slot[np.searchsorted(ts, t_out[1:] - 1e-12)] = np.arange(1, t_out.size)
    n1 = drive.n + drive.k
    x = drive.state(drive.q0) if x0 is None else np.array(x0, dtype=float)
    v = np.zeros(n1) if v0 is None else np.array(v0, dtype=float)
    m = _March(drive, opt, ts, t_out.size, mean_from)
    a0 = m.initial_acceleration(x, v)
    st = (x, v, a0, a0.copy())
    X, V = np.zeros((t_out.size, n1)), np.zeros((t_out.size, n1))
    X[0], V[0] = x, v
    limit = opt.q_limit * (1 + np.max(np.abs(x[: drive.n])))
    t0, k, status, rejected = time.process_time(), 0, DONE, 0
    for k_stop in _chunks(ts.size - 1, progress is not None):
        while k < k_stop and status in (DONE, NEWTON_FAILED):
            status, k = m.run(st, k, k_stop, slot, X, V, limit)
            if status == NEWTON_FAILED:
                rejected += 1
                if not _halved(m, st, ts[k], ts[k + 1], 1, limit, slot[k + 1], (X, V)):
                    break
                status, k = DONE, k + 1
        if status != DONE:
            break
        if progress:
            progress(ts[k])
    reached = int(np.searchsorted(t_out, ts[k] + 1e-12))
    ok = status == DONE and k == ts.size - 1
    msg = "ok" if ok else (MESSAGES.get(status) or f"no convergence: Newton failed at t = {ts[k]:.6g} s "
                           f"even with steps of dt/2^{opt.max_halvings}")
    c = m.count
    res = DynamicResult(t=t_out[:reached], q=X[:reached], v=V[:reached], converged=ok,
                        message=msg, integrator="generalized-alpha", steps=int(c[4]), nfev=int(c[0]), njev=int(c[1]), nlu=int(c[2]),
                        newton_iterations=int(c[3]), rejected_steps=rejected,
                        cpu_time_s=time.process_time() - t0)
    res.extra["contact_pairs"] = int(c[PAIRS])
    total, omega, moment = m.system.sums
    if total[0] > 0:
        res.extra["step_means"] = (omega / total, moment / total)
    if m.system.zs.shape[0]:  # the friction state of the samples' steps (a law with a state)
        res.extra["friction_state"] = list(zip(m.system.zs[:reached], m.system.hs[:reached]))
    return res
