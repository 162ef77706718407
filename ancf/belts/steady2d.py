"""The steady running state of a 2D belt drive by Newton's method in the axially moving
description (:mod:`ancf.belts.ale2d`): one nonlinear solve instead of a march.

Unknowns: the belt's coordinates (the system numbering of the drive's pattern) but one,
the transport speed vb (m/s), and per free coordinate of the rig (:class:`ancf.belts.
drive2d.Rig`) a free pulley's angular velocity omega_j (rad/s) or a tensioner arm's angle
psi (rad).  Equations: the belt's (elastic and strain-rate damping forces, the steady
flow's Eq. (2) of :mod:`ancf.belts.ale2d`, contact and friction at the material
velocities, weight), each free pulley's moment balance -T_c,p + T_a + c_j omega_j = 0
(the load law of :mod:`ancf.belts.pulleys`) and each arm's -A - preload + k psi - c_j
omega_p = 0 (:mod:`ancf.belts.forces`' rows with every rate zero but the pulleys' spin).
The mesh may slide along the belt's own shape (a steady state shifted along x is one
too, up to the discretisation), so the coordinate of node 0 along the path's tangent
stays at its settled value (the gauge) and vb takes its column: the loop's tangential
balance (the friction forces summed round the belt vanish) fixes vb.

Continuation: the pulley laws' final values (prescribed speeds, load torques) are scaled
by a factor lam from 0 (the belt settled on its pulleys at rest) to 1, in steps halved
where Newton fails and widened where it converges quickly.  Past 1, :func:`max_load`
raises the driven pulleys' loads alone until no steady state is found (gross slip).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from ancf.belts.ale2d import ale_terms, spin_matrix, transport_map
from ancf.belts.arm2d import COORD, PRELOAD, PULLEY, STIFFNESS
from ancf.belts.pulleys import RESISTING

#: Newton's tolerance on the residual, relative to the force scale (pre-tension + loads)
RTOL = 1e-9
MAX_ITER = 30
#: a stalled Newton's |R| accepted, relative to the force scale (Newton's docstring)
STALL = 1e-3
#: smallest continuation step before the solve is declared without a steady state
MIN_STEP = 1.0 / 256


@dataclass(kw_only=True)
class Steady:
    """A steady state: ``x`` the system vector (belt, then the free coordinates: a free
    pulley's entry unused, an arm's its angle psi), ``w`` the free pulleys' angular
    velocities at their places (rad/s), ``vb`` the transport speed (m/s), ``lam`` the
    load factor reached, ``converged``, ``message``, Newton ``iterations`` and
    continuation ``steps``, the ``residual`` reached and the force ``scale`` (N)."""

    x: np.ndarray
    w: np.ndarray
    vb: float
    lam: float
    converged: bool
    message: str
    iterations: int
    steps: int
    residual: float = 0.0   # |R| inf-norm of the state returned, N
    scale: float = 1.0      # the force scale of the tolerances, N


class SteadyProblem:
    """The steady equations of a 2D :class:`ancf.belts.drive2d.BeltDrive` at its pulley
    laws' values at ``t_end`` (s; :meth:`~ancf.belts.drive2d.PulleyDrive.laws`, a centre
    motion's rate taken 0)."""

    def __init__(self, drive, t_end: float):
        self.drive, self.kern, self.t_end = drive, drive.kernel(), float(t_end)
        self.speed = 1.0
        laws = drive.laws(np.array([self.t_end]))[:, 0]
        if self.kern.z.size:
            raise ValueError("a friction law with a state has no steady form here")
        npul = drive.radii.size
        self.laws = np.array(laws, dtype=float)
        self.laws[npul + 1::2] = 0.0
        self.P = transport_map(drive.mesh.lengths)
        self.Mx = spin_matrix(drive.element.mass(), self.P)
        self.n, self.k = drive.n, drive.k
        gauge = np.zeros(drive.n_dofs)
        gauge[drive.fixed_dofs()[0]] = 1.0
        self.gauge = int(np.argmax(np.abs(drive.pattern.restrict(gauge))))
        self.keep = np.delete(np.arange(self.n + 1 + self.k), self.gauge)
        self.arm_of = {int(a[COORD]): i for i, a in enumerate(drive.rig.arms)}
        self.pulley_of = {int(j): p for p, j in enumerate(drive.rig.free) if j >= 0}

    def scaled(self, lam: float) -> np.ndarray:
        """The laws with the free pulleys' load torques times lam, the prescribed speeds
        times :attr:`speed` (1 but in :func:`solve`'s speed continuation), the centre
        motions whole."""
        out = self.laws.copy()
        free = self.kern.free >= 0
        out[: free.size][free] *= lam
        out[: free.size][~free] *= self.speed
        return out

    def rolling(self, x) -> tuple:
        """(w, vb): every pulley rolling on the belt of state x without slip, the transport
        speed from the first prescribed pulley's rim speed: vb (r_x . t) = omega R over its
        wrap (t its counter-clockwise tangent), each free pulley's omega_p = vb (r_x . t_p)
        / R_p over its own (means weighted by the contact force)."""
        from ancf.belts.contact2d import contact_state_moving
        drive, kern = self.drive, self.kern
        E, V = ale_terms(kern, x, np.zeros_like(x), 1.0, self.P, self.laws, False)[:2]
        o, _ = drive.moved(x, np.zeros_like(x), self.t_end)
        _, _, Fn, _, vt = contact_state_moving(E, V, drive.S0, o, np.zeros_like(o),
                                               drive.radii, np.zeros(drive.radii.size),
                                               kern.prm)
        slide = np.array([np.sum(Fn[..., p] * vt[..., p]) / max(np.sum(Fn[..., p]), 1e-300)
                          for p in range(drive.radii.size)])  # mean r_x . t_p
        d = int(np.flatnonzero(kern.free < 0)[0])
        vb = self.laws[d] * drive.radii[d] / slide[d] if slide[d] != 0 else 0.0
        w = np.zeros(self.n + self.k)
        for j, p in self.pulley_of.items():
            w[self.n + j] = vb * slide[p] / drive.radii[p]
        return w, float(vb)

    def split(self, x, w, vb) -> np.ndarray:
        """The unknown vector of a state."""
        u = np.concatenate([x[: self.n], [vb], np.zeros(self.k)])
        for j in range(self.k):
            u[self.n + 1 + j] = x[self.n + j] if j in self.arm_of else w[self.n + j]
        return u[self.keep]

    def join(self, u, x_ref) -> tuple:
        """(x, w, vb) of an unknown vector (the gauge coordinate from x_ref)."""
        full = np.empty(self.n + 1 + self.k)
        full[self.keep] = u
        full[self.gauge] = x_ref[self.gauge]
        x, w = np.zeros(self.n + self.k), np.zeros(self.n + self.k)
        x[: self.n] = full[: self.n]
        for j in range(self.k):
            (x if j in self.arm_of else w)[self.n + j] = full[self.n + 1 + j]
        return x, w, float(full[self.n])

    def residual(self, x, w, vb, lam, want_J=True):
        """(R (n + k,), J sparse (n + k, n + 1 + k) or None): module docstring."""
        kern, n, k = self.kern, self.n, self.k
        laws = self.scaled(lam)
        E, V, g, K, c, arm = ale_terms(kern, x, w, vb, self.P, laws, want_J)
        Q, Kq, Cv, Qw, T, dTq, dTv, dTw = c
        A, dAq, dAv, dAw, dAp, Qp, Tp = arm
        Ef = E.reshape(E.shape[0], -1)
        PE = np.einsum("eab,eb->ea", self.P, Ef)
        MxE = np.einsum("eab,eb->ea", self.Mx, Ef)
        vidx = kern.vidx
        R = np.zeros(n + k)
        np.add.at(R, vidx, g - Q - vb**2 * MxE)
        R[:n] -= kern.weight
        omegas = np.where(kern.free < 0, laws[: kern.free.size], 0.0)
        for j, p in self.pulley_of.items():
            omegas[p] = w[n + j]
        rows, cols, vals = [], [], []

        def put(r, c_, v):
            r, c_, v = np.broadcast_arrays(r, c_, v)
            rows.append(r.ravel()), cols.append(c_.ravel()), vals.append(v.ravel())

        for j, p in self.pulley_of.items():
            rec = self.drive.rig.loads[j] if self.drive.rig.loads is not None else None
            Ta, dTa = laws[p], 0.0
            if rec is not None and rec.law == RESISTING:
                s = np.tanh(omegas[p] / rec.omega_reg)
                Ta, dTa = abs(laws[p]) * s, abs(laws[p]) * (1 - s * s) / rec.omega_reg
            R[n + j] = -T[p] + Ta + kern.damping[j] * omegas[p]
            if want_J:
                put(n + j, vidx, -(dTq[p] + vb * np.einsum("eb,eba->ea", dTv[p], self.P)))
                put(n + j, n, -np.sum(dTv[p] * PE))
                put(n + j, n + 1 + j, -dTw[p] + kern.damping[j] + dTa)
                put(vidx, n + 1 + j, -Qw[:, p, :])
        for ja, a in self.arm_of.items():
            row = kern.arms[a]
            j, p = int(kern.free[int(row[PULLEY])]), int(row[PULLEY])
            cj = kern.damping[j]
            R[n + ja] = -A[a] - row[PRELOAD] + row[STIFFNESS] * x[n + ja] - cj * omegas[p]
            if want_J:
                put(n + ja, vidx, -(dAq[a] + vb * np.einsum("eb,eba->ea", dAv[a], self.P)))
                put(n + ja, n, -np.sum(dAv[a] * PE))
                put(n + ja, n + 1 + j, -dAw[a] - cj)
                put(n + ja, n + 1 + ja, row[STIFFNESS] - dAp[a, 0])
                put(vidx, n + 1 + ja, -Qp[a, 0])
                put(n + j, n + 1 + ja, -Tp[a, 0])
        if not want_J:
            return R, None
        Kt = K - Kq - vb * np.einsum("eab,ebc->eac", Cv, self.P) - vb**2 * self.Mx
        put(vidx[:, :, None], vidx[:, None, :], Kt)
        put(vidx, n, -np.einsum("eab,eb->ea", Cv, PE) - 2 * vb * MxE)
        J = sp.coo_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                          shape=(n + k, n + 1 + k)).tocsc()
        return R, J[:, self.keep]

    def newton(self, x, w, vb, lam, scale: float) -> tuple:
        """Newton from (x, w, vb) at load factor lam with a backtracking line search on
        |R|; ``scale`` (N) the force scale of the tolerance.  Where the line search finds
        no descent (the penalty's damping jumps where a point first touches its pulley
        with a normal velocity, as at a wrap's entry, so the residual is discontinuous),
        the best iterate stands if its |R| is within STALL of the scale.  Returns (x, w,
        vb, converged, iterations, |R| inf-norm reached, N)."""
        u, x_ref = self.split(x, w, vb), x
        R, J = self.residual(x, w, vb, lam)
        norm = np.linalg.norm(R, np.inf)
        for it in range(1, MAX_ITER + 1):
            if norm <= RTOL * scale:
                return x, w, vb, True, it - 1, norm
            du = _solve(J, R)
            if du is None or not np.isfinite(norm):
                break
            step = 1.0
            for _ in range(8):
                x1, w1, vb1 = self.join(u + step * du, x_ref)
                R1, J1 = self.residual(x1, w1, vb1, lam)
                n1 = np.linalg.norm(R1, np.inf)
                if n1 < (1 - 1e-4 * step) * norm:
                    break
                step *= 0.5
            else:
                break
            u, R, J, norm = u + step * du, R1, J1, n1
            x, w, vb = x1, w1, vb1
        ok = bool(np.isfinite(norm) and norm <= STALL * scale)
        return x, w, vb, ok, it, norm


def _solve(J, R):
    """-J^-1 R, None where J is singular."""
    try:
        return splu(J).solve(-R)
    except RuntimeError:
        return None


def force_scale(drive, laws) -> float:
    """The tolerance's force scale, N: the belt's largest nodal force at the start plus the
    loads' torques over the smallest radius."""
    npul = drive.radii.size
    return float(1.0 + np.abs(laws[:npul]).max() / drive.radii.min()
                 + np.abs(drive.rig.arms[:, PRELOAD]).sum() / drive.radii.min())


def solve(problem: SteadyProblem, x0, progress=None) -> Steady:
    """The steady state at load factor 1 by continuation from the settled belt x0 (the
    module docstring): the pulleys rolling at full speed without load first, or, where
    Newton fails there, the prescribed speeds raised from 0 (:attr:`SteadyProblem.speed`);
    then the loads.  ``progress(label, value)`` after every converged step."""
    scale = force_scale(problem.drive, problem.laws) + _belt_scale(problem, x0)
    x = np.array(x0, dtype=float)
    w, vb = problem.rolling(x)
    x1, w1, vb1, ok, iters, res = problem.newton(x, w, vb, 0.0, scale)
    steps = 0
    if not ok:  # the prescribed speeds from rest
        problem.speed = 0.0
        start = problem.newton(x, 0 * w, 0.0, 0.0, scale)
        iters += start[4]

        def at_speed(state, t):
            problem.speed = t
            return problem.newton(*state, 0.0, scale)
        (x1, w1, vb1), reached, it, steps, res = _continue(
            at_speed, start[:3], scale, progress, "speed factor", problem,
            first=lambda t: (x, w * t, vb * t))  # rolling, at the first step's speed
        iters += it
        problem.speed = 1.0
        if reached < 1.0 or not start[3]:
            return Steady(x=x1, w=w1, vb=vb1, lam=0.0, converged=False,
                          message=f"no steady state above {reached:.4g} of the prescribed "
                          "speeds", iterations=iters, steps=steps, residual=res, scale=scale)
    (x, w, vb), lam, it, n, res = _continue(
        lambda state, t: problem.newton(*state, t, scale), (x1, w1, vb1), scale, progress,
        "load factor", problem)
    iters, steps = iters + it, steps + n
    if lam < 1.0:
        return Steady(x=x, w=w, vb=vb, lam=lam, converged=False,
                      message=f"no steady state beyond load factor {lam:.4g}",
                      iterations=iters, steps=steps, residual=res, scale=scale)
    return Steady(x=x, w=w, vb=vb, lam=1.0, converged=True, message="steady state",
                  iterations=iters, steps=steps, residual=res, scale=scale)


def _continue(newton, state, scale, progress, label, problem, first=None) -> tuple:
    """Follow ``newton(state, t)`` (:meth:`SteadyProblem.newton`'s outcome) from a
    converged ``state`` (x, w, vb) at t = 0 to t = 1: steps widened after quick
    convergence, halved after a failure down to MIN_STEP, a secant predictor in the
    unknowns (``first(t)``: the first step's guess, else the start).  Returns (state, t
    reached, iterations, steps, |R| at the last step)."""
    t, dt, iters, steps, res = 0.0, 0.125, 0, 0, 0.0
    last = None
    while t < 1.0:
        target = min(1.0, t + dt)
        guess = state if first is None or last is not None else first(target)
        if last is not None:
            u, u0 = problem.split(*state), problem.split(*last[1])
            guess = problem.join(u + (u - u0) * (target - t) / (t - last[0]), state[0])
        x, w, vb, ok, it, r = newton(guess, target)
        iters += it
        if ok:
            last, state, t, steps, res = (t, state), (x, w, vb), target, steps + 1, r
            dt = min(0.5, dt * (2.0 if it < 6 else 1.0))
            if progress is not None:
                progress(label, t)
            continue
        dt *= 0.5
        if dt < MIN_STEP:
            break
    return state, t, iters, steps, res


def _belt_scale(problem: SteadyProblem, x0) -> float:
    """The largest elastic generalised force of an element of the settled belt, N."""
    g = ale_terms(problem.kern, x0, np.zeros_like(x0), 0.0, problem.P, problem.laws, False)[2]
    return float(np.abs(g).max())
