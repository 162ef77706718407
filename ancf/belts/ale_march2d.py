"""The transient march of a 2D belt drive in the axially moving (ALE) description
(Pechstein & Gerstmayr, Multibody Syst Dyn 30 (2013) 343-358): the mesh stays on the
path, the material flows through it at the transport speed vb (m/s).

Unknowns: the steady problem's (:class:`ancf.belts.steady2d.SteadyProblem`): the belt's
coordinates q less the gauge (node 0's tangential coordinate, held at its settled
value), vb, the free pulleys' angular velocities omega_j (rad/s) and the tensioner arms'
angles psi (rad).  Every one is a position or the rate of one, so the march is the
generalised-alpha scheme of second-order systems (:func:`ancf.solvers.alpha_march.
kinematics`) in y = (q, s, theta): s the material's shift (m; vb = s'), theta the free
coordinates (a pulley's angle, cyclic, or an arm's psi).  With the
element kinetic energy T = 1/2 q'^T M q' + vb q'^T M P q + 1/2 vb^2 q^T M_x q
(:mod:`ancf.belts.modes2d`; M_x = P^T M P, :mod:`ancf.belts.ale2d`) the rows are

    M q'' + vb' M P q + vb (M P - P^T M) q' - vb^2 M_x q + dU/dq + Q_d - Q_c - F_g = 0  (1)
    I_j omega_j' - T_c,p + T_a,p(t) + c_j (omega_j - psi') = 0                         (3)
    I_a psi'' - A - preload + k psi + c_a psi' - c_j (omega_j - psi') = 0               (4)

(1) the belt's, every row of it (element sums; Q_c the contact and friction forces, Q_d
the strain-rate damping, both at the material velocities V = q' + vb P q): the gauge
coordinate's own row takes vb' (its column M P q), as the steady solve keeps every belt
row and gives vb the gauge's column, so the march's steady state is the steady solve's.
(The axial momentum's d/dt (q'^T M P q + vb q^T M_x q) = Q_s (2) in the gauge's row
instead, as :mod:`ancf.belts.modes2d` has it, leaves the held gauge a tangential reaction
at the steady state: 0.9 N at 60 elements on the serpentine, its crank torque 0.9 % off
the steady solve's.)  (3) the free pulleys' and (4) the arms' (the Lagrangian march's,
a ``resisting`` load by its tanh law, A the belt's moment about the pivot; psi' the rate
of the arm the pulley rides on, else 0: :mod:`ancf.belts.ale_rows2d`).  The pulley laws
are the drive's at each step's end (ramps and load steps as in :func:`ancf.belts.dynamics.
simulate`); the start is the settled belt at rest (vb = 0).

Newton per step on the iteration matrix S = M* + gamma' C + beta' K (M* the mass of (1)-(4)
by (q'', vb', omega', psi''), C and K their derivatives by the rates and positions) in sparse
form, factored with diagonal pivots (the mass makes S diagonally dominant, as the
Lagrangian march's kept factors); modified: the factor is kept over iterations and steps
and refreshed where an increment shrinks by less than ``refresh_ratio`` (at that iterate)
or a step fails (at its start); a step that fails on a fresh factor is halved, down to
dt / 2**max_halvings.  Converged when beta' |d acc|_inf <= newton_tol (1 + |y_n|_inf),
the march's test.
"""
from __future__ import annotations

import time

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from ancf.belts.ale2d import ale_terms
from ancf.belts.ale_rows2d import free_entries, free_rows
from ancf.belts.steady2d import SteadyProblem
from ancf.belts.system import loads_of, window_weights
from ancf.solvers.alpha_march import MAX_BACKTRACKS, kinematics
from ancf.solvers.generalized_alpha import AlphaOptions, step_times
from ancf.solvers.result import DynamicResult


class _Failed(Exception):
    """A step without convergence."""


class AleSystem:
    """Rows (1)-(4) and their iteration matrix for a 2D drive (module docstring), in the
    full layout (q (n), s, theta (k)); :attr:`keep` the unknowns (the gauge left out)."""

    def __init__(self, drive, x0):
        pb = SteadyProblem(drive, 0.0)
        self.drive, self.kern, self.pb = drive, pb.kern, pb
        self.n, self.k, self.keep, self.gauge = pb.n, pb.k, pb.keep, pb.gauge
        self.eq = self.keep.copy()
        self.eq[self.n - 1] = self.gauge
        self.P, self.Mx = pb.P, pb.Mx
        self.M = drive.element.mass()
        self.MP = np.einsum("eab,ebc->eac", self.M, self.P)
        self.G0 = self.MP - np.transpose(self.MP, (0, 2, 1))
        self.loads = loads_of(drive)
        self.x0 = np.array(x0, dtype=float)
        v = self.kern.vidx
        self.rows = np.broadcast_to(v[:, :, None], self.M.shape).ravel()
        self.cols = np.broadcast_to(v[:, None, :], self.M.shape).ravel()
        self.count = np.zeros(self.n + 1 + self.k)
        np.add.at(self.count, v, 1.0)

    def full(self, u, gauge_value) -> np.ndarray:
        """A full-layout vector of the unknowns u, the gauge entry ``gauge_value``."""
        out = np.empty(self.n + 1 + self.k)
        out[self.keep] = u
        out[self.gauge] = gauge_value
        return out

    def system(self, y) -> np.ndarray:
        """The drive's system vector (belt, free angles) of a full-layout vector."""
        return np.concatenate([y[: self.n], y[self.n + 1:]])

    def _scatter(self, e) -> np.ndarray:
        return np.bincount(self.kern.vidx.ravel(), e.ravel(), self.n + 1 + self.k)

    def evaluate(self, y, yd, ydd, laws, coef=None):
        """(R full, the belt's moments T_c (np,) N m, the pulley speeds (np,) rad/s, the
        element material velocities V (nel, 6, 2) m/s, S) at positions y, rates yd and
        accelerations ydd; S (sparse, keep x keep) for coef = (beta', gamma'), else None."""
        kern, n, P = self.kern, self.n, self.P
        vb, vbd = yd[n], ydd[n]
        want = coef is not None
        E, V, g, K, c, arm = ale_terms(kern, self.system(y), self.system(yd), vb, P, laws,
                                       want)
        Q, T = c[0], c[4]
        vidx, Ef = kern.vidx, E.reshape(E.shape[0], -1)
        Ed, Edd = yd[vidx], ydd[vidx]
        PE = np.einsum("eab,eb->ea", P, Ef)
        MPE = np.einsum("eab,eb->ea", self.MP, Ef)
        MxE = np.einsum("eab,eb->ea", self.Mx, Ef)
        belt = (np.einsum("eab,eb->ea", self.M, Edd) + vbd * MPE
                + vb * np.einsum("eab,eb->ea", self.G0, Ed) - vb * vb * MxE + g - Q)
        R = self._scatter(belt)
        R[:n] -= kern.weight
        omegas, dTa = free_rows(self, R, y, yd, ydd, laws, T, arm[0])
        if not want:
            return R, T, omegas, V, None
        parts = dict(Ed=Ed, PE=PE, MPE=MPE, MxE=MxE, K=K, c=c, arm=arm, dTa=dTa, vb=vb,
                     vbd=vbd)
        return R, T, omegas, V, self._matrix(parts, *coef)

    def _matrix(self, d, bp, gp):
        """S = M* + gamma' C + beta' K (module docstring) in keep x keep."""
        kern, n, P, vb = self.kern, self.n, self.P, d["vb"]
        Kq, Cv = d["c"][1], d["c"][2]
        vidx, PE = kern.vidx, d["PE"]
        N = n + 1 + self.k
        CvP = np.einsum("eab,ebc->eac", Cv, P)
        Kb = d["K"] - Kq - vb * CvP - vb * vb * self.Mx + d["vbd"] * self.MP
        blocks = self.M + gp * (vb * self.G0 - Cv) + bp * Kb
        rows, cols, vals = [self.rows], [self.cols], [blocks.ravel()]

        def put(r, c_, v):
            r, c_, v = np.broadcast_arrays(r, c_, v)
            rows.append(r.ravel()), cols.append(c_.ravel()), vals.append(v.ravel())

        CvPE = np.einsum("eab,eb->ea", Cv, PE)
        G0Ed = np.einsum("eab,eb->ea", self.G0, d["Ed"])
        put(vidx, n, d["MPE"] + gp * (G0Ed - CvPE - 2 * vb * d["MxE"]))
        free_entries(self, put, d, bp, gp)
        S = sp.coo_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                          shape=(N, N)).tocsr()
        return S[self.eq][:, self.keep].tocsc()

    def material_velocity(self, y, yd, V) -> np.ndarray:
        """The system velocity vector of a state: the belt's nodal material velocities
        (q' + vb P q, the elements' values at a shared node averaged; m/s) and the free
        pulleys' angular velocities (rad/s)."""
        n = self.n
        nodal = self._scatter(V.reshape(V.shape[0], -1)) / np.maximum(self.count, 1.0)
        return np.concatenate([nodal[:n], yd[n + 1:]])


class AleMarch:
    """The generalised-alpha march of an :class:`AleSystem` (module docstring); ``opt`` a
    :class:`ancf.belts.dynamics.BeltOptions`."""

    def __init__(self, system: AleSystem, opt):
        self.sys, self.opt = system, opt
        self.cf = np.array(AlphaOptions(rho_inf=opt.rho_inf).coefficients())
        self.lu, self.lu_h = None, None
        self.nfev = self.njev = self.nlu = self.iters = self.steps = 0

    def full(self, u, gauge_value) -> np.ndarray:
        return self.sys.full(u, gauge_value)

    def _eval(self, st, acc, h, laws, coef=None):
        x, v, _ = kinematics(acc, st, h, self.cf)
        g = self.sys.x0[self.sys.gauge]
        self.nfev += 1
        self.njev += coef is not None
        return self.sys.evaluate(self.full(x, g), self.full(v, 0.0), self.full(acc, 0.0),
                                 laws, coef)

    def _factor(self, st, acc, h, laws):
        bp, gp = self._coef(h)
        S = self._eval(st, acc, h, laws, (bp, gp))[4]
        try:
            self.lu = splu(S, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                           options={"SymmetricMode": True})
        except RuntimeError as exc:
            raise _Failed(f"singular iteration matrix ({exc})") from None
        self.lu_h = h
        self.nlu += 1

    def _coef(self, h) -> tuple:
        am, af, gamma, beta = self.cf
        ratio = (1 - af) / (1 - am)
        return h * h * beta * ratio, h * gamma * ratio

    def step(self, st, h, laws, fresh: bool):
        """One step of size h at the laws of its end: (state, T_c, omegas, V) or _Failed;
        ``fresh``: factor at the step's start whatever the kept factor.  An increment that
        shrank by less than ``refresh_ratio`` is recomputed on a factor at its iterate, and
        damped by backtracking on |R| (the march's: the friction and the contact's entry
        make R kinked, where Newton cycles)."""
        acc, keep = st[2].copy(), self.sys.eq
        here = fresh or self.lu is None or abs(self.lu_h - h) > 1e-6 * h  # factor at acc
        if here:
            self._factor(st, acc, h, laws)
        bp = self._coef(h)[0]
        tol = self.opt.newton_tol * (1 + np.max(np.abs(st[0])))
        now = self._eval(st, acc, h, laws)
        last = np.inf
        for _ in range(self.opt.max_iter):
            d = self.lu.solve(-now[0][keep])
            size = np.max(np.abs(d))
            if bp * size > tol and not size <= self.opt.refresh_ratio * last and not here:
                self._factor(st, acc, h, laws)
                d = self.lu.solve(-now[0][keep])
                size = np.max(np.abs(d))
            if not np.isfinite(size):
                break
            lam, now = self._backtrack(st, acc, d, h, laws, np.linalg.norm(now[0][keep]))
            acc, last, here = acc + lam * d, lam * size, False
            self.iters += 1
            if bp * last <= tol:
                x, v, a = kinematics(acc, st, h, self.cf)
                return (x, v, acc, a), *now[1:4]
        raise _Failed("Newton")


    def _backtrack(self, st, acc, d, h, laws, norm) -> tuple:
        """(lam, the evaluation at acc + lam d): lam = 1, 1/2, ... down to 1/128, the first
        that lowers |R| (2-norm over the unknowns' rows)."""
        lam = 1.0
        for _ in range(MAX_BACKTRACKS):
            now = self._eval(st, acc + lam * d, h, laws)
            if np.linalg.norm(now[0][self.sys.eq]) <= (1 - 1e-4 * lam) * norm:
                break
            lam *= 0.5
        return lam, now


def _laws(drive, t) -> np.ndarray:
    """The pulley laws at time t (s) (:meth:`~ancf.belts.drive2d.BeltDrive.laws`)."""
    return np.ascontiguousarray(drive.laws(np.array([t]))[:, 0])


def simulate_ale(drive, t_out, opt, x0, progress=None, mean_from: float = np.inf):
    """:func:`ancf.belts.dynamics.simulate` in the ALE description: the drive from the
    settled belt x0 (system vector) at rest over the sample times t_out (s).  The result's
    ``q`` holds the system vectors (belt on the mesh, free pulley angles), ``v`` the
    material velocities (:meth:`AleSystem.material_velocity`); ``extra``: ``step_means``
    (as the Lagrangian march's), ``vb`` (m/s) and ``element_velocities`` (nel, 6, 2) m/s
    at the samples, ``contact_pairs`` 0 (not counted here)."""
    system = AleSystem(drive, x0)
    march = AleMarch(system, opt)
    t_out = np.asarray(t_out, dtype=float)
    ts = step_times(t_out, opt.dt)
    slot = np.full(ts.size, -1, dtype=np.int64)
    slot[np.searchsorted(ts, t_out[1:] - 1e-12)] = np.arange(1, t_out.size)
    weights = window_weights(ts, mean_from)
    u0 = np.delete(np.concatenate([system.x0[: system.n], [0.0], system.x0[system.n:]]),
                   system.gauge)
    z = np.zeros_like(u0)
    st = (u0, z, z.copy(), z.copy())
    R, T, omegas, V, _ = march._eval(st, z, 1.0, _laws(drive, ts[0]), None)
    S0 = march._eval(st, z, 1.0, _laws(drive, ts[0]), (0.0, 0.0))[4]
    a0 = splu(S0).solve(-R[system.eq])
    st = (u0, z, a0, a0.copy())
    out = _Samples(system, t_out.size, (st, T, omegas, V))
    sums = np.zeros((3, drive.radii.size))
    limit = opt.q_limit * (1 + np.max(np.abs(u0)))
    t0, rejected, message = time.process_time(), 0, "ok"
    tabs = drive.laws(ts)
    k = 0
    for k in range(1, ts.size):
        try:
            done, r = _advance(march, st, ts[k - 1], ts[k], tabs[:, k].copy(), 0, weights[k],
                               mean_from, sums)
        except _Failed:
            k -= 1
            message = (f"no convergence: Newton failed at t = {ts[k]:.6g} s even with steps "
                       f"of dt/2^{opt.max_halvings}")
            break
        rejected += r
        st = done[0]
        if np.max(np.abs(st[0])) > limit:
            message = "coordinates blew up"
            break
        if slot[k] >= 0:
            out.put(slot[k], done)
        if progress:  # a ticker: it prints when enough wall time has passed
            progress(ts[k])
    ok = message == "ok"
    reached = out.filled if not ok else t_out.size
    res = DynamicResult(t=t_out[:reached], q=out.X[:reached], v=out.V[:reached], converged=ok,
                        message=message, integrator="generalized-alpha (ALE)",
                        steps=march.steps, nfev=march.nfev, njev=march.njev, nlu=march.nlu,
                        newton_iterations=march.iters, rejected_steps=rejected,
                        cpu_time_s=time.process_time() - t0)
    res.extra.update(contact_pairs=0, vb=out.vb[:reached],
                     element_velocities=out.W[:reached])
    if sums[0, 0] > 0:
        res.extra["step_means"] = (sums[1] / sums[0], sums[2] / sums[0])
    return res


def _advance(march, st, ta, tb, laws, depth, weight, mean_from, sums):
    """Step st from ta to tb (s): the kept factor, then a fresh one, then two halves
    (recursively, down to max_halvings).  Adds the window means' sums of the steps;
    returns ((state, T, omegas, V) at tb, the steps rejected)."""
    h = tb - ta
    for fresh in (False, True):
        try:
            done = march.step(st, h, laws, fresh)
            march.steps += 1
            sums += weight * np.array([np.ones_like(done[1]), done[2], done[1]])
            return done, 0
        except _Failed:
            continue
    if depth >= march.opt.max_halvings:
        raise _Failed("halvings")
    tm = 0.5 * (ta + tb)
    part = lambda a, b: max(b - max(a, mean_from), 0.0)  # noqa: E731
    mid, r1 = _advance(march, st, ta, tm, _laws(march.sys.drive, tm), depth + 1,
                       part(ta, tm), mean_from, sums)
    end, r2 = _advance(march, mid[0], tm, tb, laws, depth + 1, part(tm, tb), mean_from, sums)
    return end, 1 + r1 + r2


class _Samples:
    """The samples of a run: system vectors, material velocities, vb, element V."""

    def __init__(self, system: AleSystem, count: int, first):
        self.sys, n1 = system, system.n + system.k
        nel = system.kern.vidx.shape[0]
        self.X, self.V = np.zeros((count, n1)), np.zeros((count, n1))
        self.vb, self.W = np.zeros(count), np.zeros((count, nel, 6, 2))
        self.filled = 0
        self.put(0, first)

    def put(self, i, done):
        (u, ud, _, _), _, _, V = done
        s = self.sys
        y, yd = s.full(u, s.x0[s.gauge]), s.full(ud, 0.0)
        self.X[i], self.V[i] = s.system(y), s.material_velocity(y, yd, V)
        self.vb[i], self.W[i] = yd[s.n], V
        self.filled = i + 1
