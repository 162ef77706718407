"""A flat plate of ANCF 3423 shells (``ancf.elements.ancf3423``) and its time history under
a constant corner load, as Chrono's ``utest_FEA_ANCFShell_Iso.cpp`` sets it up (see
``tests/data/chrono/README.md``, section "ANCF 3423 shell").

Mesh: nx x ny elements of a/nx by b/ny on [0, a] x [0, b] at z = 0, thickness h, nodes row
by row (x fastest), each with [r, d] (6 coordinates, entries node * 6 + 3 slot +
component); d = (0, 0, 1) in the reference.  Every coordinate of the nodes on x = 0 is
fixed.  Equations of motion on the free coordinates z (N):

    M z'' + Q(q, q') = F,   q = T z + g                                                (1)

M the assembled consistent mass, Q the elements' internal force (``ancf3423`` Eq. (8)),
F the constant point force on the tip node's position.  Time integration: the Newmark
trapezoidal rule (gamma = 1/2, beta = 1/4), which is Chrono's HHT at alpha = 0,

    z_{n+1} = z_n + h z'_n + h^2/4 (z''_n + z''_{n+1}),  z'_{n+1} = z'_n + h/2 (z''_n + z''_{n+1})  (2)

with Eq. (1) at t_{n+1}, started like Chrono's from z''_0 = 0 (HHT takes the acceleration
the system holds, zero at the start), on the compiled march of
:mod:`ancf.solvers.alpha_march` with alpha_m = alpha_f = 0 (its recurrence is then Eq. (2))
and Newton's iteration matrix S = M + h^2/4 K + h/2 R.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from numba import njit

from ancf.common.dispatch import implements
from ancf.elements import ancf3423
from ancf.elements.material import isotropic_3d
from ancf.solvers.alpha_march import (DONE, march, newton_settings, system_accept,
                                      system_factor, system_prepare, system_residual,
                                      system_solve, system_tests)

#: Chrono's HHT at alpha = 0 as the march's (alpha_m, alpha_f, gamma, beta)
TRAPEZOIDAL = np.array([0.0, 0.0, 0.5, 0.25])


@dataclass(frozen=True, kw_only=True)
class Plate:
    """The plate and its load: nx x ny elements, sides a, b and thickness h (m), density
    rho (kg/m^3), E (Pa), nu, damping alpha (s), tip force (N) on the node at (a, b), the
    ANS order ``ans`` (``ancf3423.ANS``).  Defaults: Chrono's unit test (its element's ANS
    order of 2015, when its stored history was made)."""

    nx: int = 4
    ny: int = 4
    a: float = 1.0
    b: float = 1.0
    h: float = 0.01
    rho: float = 500.0
    E: float = 2.1e8
    nu: float = 0.3
    alpha: float = 0.08
    force: tuple = (0.0, 0.0, -50.0)
    ans: str = "paper"

    @property
    def nodes(self) -> int:
        return (self.nx + 1) * (self.ny + 1)

    def connectivity(self) -> np.ndarray:
        """(nel, 4) nodes A, B, C, D of each element, element j nx + i."""
        n = self.nx + 1
        return np.array([[j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i]
                         for j in range(self.ny) for i in range(self.nx)])

    def dofs(self) -> np.ndarray:
        """(nel, 24) global coordinates of each element, ``ancf3423`` order."""
        return (self.connectivity()[:, :, None] * 6 + np.arange(6)).reshape(-1, 24)

    def reference(self) -> np.ndarray:
        """q0 (6 nodes,): positions on the grid at z = 0, d = (0, 0, 1)."""
        q = np.zeros((self.nodes, 6))
        k = np.arange(self.nodes)
        q[:, 0] = (k % (self.nx + 1)) * self.a / self.nx
        q[:, 1] = (k // (self.nx + 1)) * self.b / self.ny
        q[:, 5] = 1.0
        return q.ravel()

    def free(self) -> np.ndarray:
        """The coordinates not fixed (nodes on x = 0 fixed)."""
        clamped = np.arange(self.nodes) % (self.nx + 1) == 0
        return np.flatnonzero(~np.repeat(clamped, 6))

    def tip(self) -> int:
        """The global index of the tip node's z-position (node at (a, b))."""
        return 6 * (self.nodes - 1) + 2


class Plate3423System(NamedTuple):
    """Arrays of Eq. (1) for the march (SI units), with work storage."""

    M: np.ndarray        # (n, n) free-coordinate mass, kg
    F: np.ndarray        # (n,) constant load, N
    loc: np.ndarray      # (nel, 24) free index of each element coordinate, -1 if fixed
    free: np.ndarray     # (n,) global index of each free coordinate
    q: np.ndarray        # (ndof,) work: global coordinates (fixed entries at q0), m
    qd: np.ndarray       # (ndof,) work: global velocities, m/s
    dofs: np.ndarray     # (nel, 24) global coordinates of each element
    E0: np.ndarray       # (nel, 8, 3) reference
    H: np.ndarray        # ancf3423.point_forms
    G: np.ndarray
    w: np.ndarray
    D: np.ndarray        # (6, 6) Pa
    Kinv: np.ndarray     # (5, 5) K_aa^-1
    alpha: float         # damping, s
    Qe: np.ndarray       # (nel, 24) work
    Ke: np.ndarray       # (nel, 24, 24) work
    Re: np.ndarray       # (nel, 24, 24) work
    Ue: np.ndarray       # (nel,) work
    J: np.ndarray        # (n, n) work: h^2/4 K + h/2 R at the last evaluation
    Sinv: np.ndarray     # (n, n) work: the iteration matrix' inverse


@njit(cache=True)
def _gather(q, qd, free, dofs, x1, v1):
    """Element coordinates and rates (nel, 8, 3) from the free ones (q, qd: global work
    arrays, their fixed entries at the reference and at rest)."""
    q[free] = x1
    qd[free] = v1
    nel = dofs.shape[0]
    E, V = np.empty((nel, 8, 3)), np.empty((nel, 8, 3))
    for i in range(nel):
        for j in range(24):
            E[i, j // 3, j % 3] = q[dofs[i, j]]
            V[i, j // 3, j % 3] = qd[dofs[i, j]]
    return E, V


@implements(system_prepare, Plate3423System)
def _prepare(system, k):
    """Nothing varies with time."""


@implements(system_residual, Plate3423System)
def _residual(system, x1, v1, acc1, k, bp, gp, want_J, count, r):
    """r = M z'' + Q - F (Eq. (1)); with want_J, J = bp K + gp R."""
    E, V = _gather(system.q, system.qd, system.free, system.dofs, x1, v1)
    ancf3423.batch(E, V, system.E0, system.H, system.G, system.w, system.D, system.Kinv,
                   system.alpha, want_J, system.Qe, system.Ke, system.Re, system.Ue)
    r[:] = system.M @ acc1 - system.F
    if want_J:
        system.J[:, :] = 0.0
    for i in range(system.loc.shape[0]):
        for j in range(24):
            p = system.loc[i, j]
            if p < 0:
                continue
            r[p] += system.Qe[i, j]
            if want_J:
                for l in range(24):
                    s = system.loc[i, l]
                    if s >= 0:
                        system.J[p, s] += bp * system.Ke[i, j, l] + gp * system.Re[i, j, l]


@implements(system_factor, Plate3423System)
def _factor(system, bp, pivoting):
    """S = M + J, kept as its inverse (dense, n ~ 100)."""
    system.Sinv[:, :] = np.linalg.inv(system.M + system.J)
    return np.all(np.isfinite(system.Sinv))


@implements(system_solve, Plate3423System)
def _solve(system, d):
    d[:] = system.Sinv @ d


@implements(system_accept, Plate3423System)
def _accept(system, slot):
    """No state beside the march's."""


@implements(system_tests, Plate3423System)
def _tests(system):
    """All coordinates, plain Newton, velocity-dependent forces (damping)."""
    return system.M.shape[0], False, False, True


def system(plate: Plate) -> Plate3423System:
    """The march's record of ``plate`` (Eq. (1))."""
    a, b = plate.a / plate.nx, plate.b / plate.ny
    dofs, free, q0 = plate.dofs(), plate.free(), plate.reference()
    n, nel = free.size, len(dofs)
    index = -np.ones(q0.size, dtype=np.int64)
    index[free] = np.arange(n)
    Mfull = np.zeros((q0.size, q0.size))
    Me = ancf3423.mass_matrix(a, b, plate.h, plate.rho)
    for d in dofs:
        Mfull[np.ix_(d, d)] += Me
    F = np.zeros(q0.size)
    F[plate.tip() - 2: plate.tip() + 1] = plate.force
    H, G, w = ancf3423.point_forms(a, b, plate.h, plate.ans)
    D = isotropic_3d(plate.E, plate.nu)
    return Plate3423System(
        M=Mfull[np.ix_(free, free)], F=F[free], loc=index[dofs], free=free, q=q0.copy(),
        qd=np.zeros(q0.size), dofs=dofs, E0=q0[dofs].reshape(nel, 8, 3), H=H, G=G, w=w, D=D,
        Kinv=np.linalg.inv(ancf3423.eas_stiffness(G, w, D)), alpha=float(plate.alpha),
        Qe=np.zeros((nel, 24)), Ke=np.zeros((nel, 24, 24)), Re=np.zeros((nel, 24, 24)),
        Ue=np.zeros(nel), J=np.zeros((n, n)), Sinv=np.zeros((n, n)))


def history(plate: Plate = Plate(), dt: float = 1e-3, steps: int = 4000, tol: float = 1e-12,
            max_iter: int = 30) -> tuple:
    """(t (steps,) s, tip z (steps,) m, Newton iterations): Eq. (2) from rest at the
    reference with z''_0 = 0, step dt (s); Newton converged when h^2/4 |dz''|_inf <= tol
    (1 + |z|_inf) (m).  RuntimeError if a step does not converge."""
    sysm = system(plate)
    n = sysm.M.shape[0]
    st = (np.zeros(n), np.zeros(n), np.zeros(n), np.zeros(n))
    st[0][:] = plate.reference()[sysm.free]
    ts = dt * np.arange(steps + 1)
    slot = np.arange(-1, steps, dtype=np.int64)
    out_x, out_v = np.zeros((steps, n)), np.zeros((steps, n))
    count = np.zeros(5, dtype=np.int64)
    status, k = march(ts, 0, steps, st, sysm, np.array([np.nan]), TRAPEZOIDAL, count,
                      newton_settings(tol), max_iter, 1e6, steps + 1, slot, out_x, out_v)
    if status != DONE:
        raise RuntimeError(f"the march stopped at step {k} of {steps} (status {status})")
    tip = int(np.flatnonzero(sysm.free == plate.tip())[0])
    return ts[1:], out_x[:, tip], int(count[3])


@njit(cache=True)
def _static(system, x, loads, tol, max_iter):
    """Newton on Q(q) = lam F (Eq. (1) at rest) for lam in ``loads`` in turn, from x (free
    coordinates, m, updated); converged when |dz|_inf <= tol (1 + |z|_inf).  Returns the
    iterations, or -1 if a load step does not converge."""
    n = x.size
    zero, r, count = np.zeros(n), np.zeros(n), np.zeros(5, dtype=np.int64)
    iters = 0
    for lam in loads:
        done = False
        for _ in range(max_iter):
            # bool(): a runtime flag, as the march's; a literal True compiles its own batch
            _residual(system, x, zero, zero, 0, 1.0, 0.0, bool(True), count, r)
            d = np.linalg.solve(system.J, -(r + (1.0 - lam) * system.F))
            x += d
            iters += 1
            if np.max(np.abs(d)) <= tol * (1.0 + np.max(np.abs(x))):
                done = True
                break
        if not done:
            return -1
    return iters


def static_tip(plate: Plate = Plate(), increments: int = 20, tol: float = 1e-12) -> float:
    """The tip's z-position (m) at static equilibrium under the full load (the history's
    steady state), by Newton over ``increments`` equal load steps.  RuntimeError if a step
    does not converge."""
    sysm = system(plate)
    x = plate.reference()[sysm.free]
    if _static(sysm, x, np.arange(1, increments + 1) / increments, tol, 50) < 0:
        raise RuntimeError("the static Newton did not converge")
    return float(x[np.flatnonzero(sysm.free == plate.tip())[0]])
