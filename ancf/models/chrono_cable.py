"""Chrono's spinning cable pendulum (``utest_FEA_ANCFCable.cpp``; Gerstmayr and Shabana 2006,
Figs 4 and 5) on our cable element :mod:`ancf.elements.cable3d`, integrated as Chrono does it
(see ``tests/data/chrono/README.md``, section "Spinning cable pendulum").

A cable of length L along +x, n elements of ``Cable3D``, nodes [r, r_x] (6 coordinates,
node k at (k L / n, 0, 0), r_x = (1, 0, 0)).  Node 0's position is held (a spherical
joint: its slope is free).  Gravity g along -y; the cable starts straight, spinning about
the y axis: node k's position moves at (0, 0, -omega x_k), the slopes at rest (as Chrono's
test sets them).  Equations of motion on the free coordinates z:

    M z'' = F_g - Q(z)                                                                  (1)

M the consistent mass, F_g the exact gravity force, Q the elastic force (Eq. (2) of
``cable3d``).  Chrono's ``EULER_IMPLICIT_LINEARIZED`` step of h (one Newton iteration of
the implicit Euler method, no velocity-dependent force here):

    (M + h^2 K(z_n)) v_{n+1} = M v_n + h (F_g - Q(z_n)),   z_{n+1} = z_n + h v_{n+1}     (2)

with K = dQ/dz (exact here; Chrono's a forward difference of 1e-8, a relative change of
order 1e-8 in each step's correction).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numba import njit

from ancf.elements.cable3d import (AXIAL_POINTS, BENDING_POINTS, NDOF, Cable3D,
                                   CircularSection, element, point_rows)

F_SCALE = 5.0  # Gerstmayr and Shabana's scaling parameter f of the test's section


@dataclass(frozen=True, kw_only=True)
class Pendulum:
    """The cable and its start: n elements over L (m), section diameter d (m), E (Pa), rho
    (kg/m^3), gravity g (m/s^2, along -y), spin omega (rad/s, about +y).  Defaults:
    Chrono's test, f = 5: d = 2 f sqrt(1e-6 / pi), E = 1e9 / f^4, rho = 8000 / f^2,
    g = 9.8 (its ``SetGravityY``)."""

    n: int = 4
    L: float = 1.0
    d: float = 2.0 * F_SCALE * np.sqrt(1e-6 / np.pi)
    E: float = 1e9 / F_SCALE**4
    rho: float = 8000.0 / F_SCALE**2
    g: float = 9.8
    omega: float = 4.0

    def reference(self) -> np.ndarray:
        """q0 (6 (n + 1),): node k at (k L / n, 0, 0), r_x = (1, 0, 0)."""
        q = np.zeros((self.n + 1, 6))
        q[:, 0] = np.linspace(0.0, self.L, self.n + 1)
        q[:, 3] = 1.0
        return q.ravel()

    def velocity(self) -> np.ndarray:
        """q'0: node positions at (0, 0, -omega x), slopes at rest."""
        v = np.zeros((self.n + 1, 6))
        v[:, 2] = -self.omega * np.linspace(0.0, self.L, self.n + 1)
        return v.ravel()

    def dofs(self) -> np.ndarray:
        """(n, 12) global coordinates of each element."""
        return np.arange(self.n)[:, None] * 6 + np.arange(NDOF)

    def free(self) -> np.ndarray:
        """Every coordinate but node 0's position."""
        return np.arange(3, 6 * (self.n + 1))


@njit(cache=True)
def _march(x, v, M, Fg, loc, dofs, Le, EA, EI, rules, h, steps, out):
    """Eq. (2) for ``steps`` steps from (x, v) (global coordinates and rates, m, m/s,
    updated); out (steps, len(x)) receives x after each step.  Returns the step at which
    the solve failed (a non-finite state), or -1."""
    wa, Sa, wb, Sb, Sbb = rules
    n = M.shape[0]
    Q, K = np.zeros(NDOF), np.zeros((NDOF, NDOF))
    for k in range(steps):
        A, r = M.copy(), h * Fg
        for i in range(dofs.shape[0]):
            element(x[dofs[i]], Le, EA, EI, wa, Sa, wb, Sb, Sbb, bool(True), Q, K)  # not a literal
            for j in range(NDOF):
                p = loc[dofs[i, j]]
                if p < 0:
                    continue
                r[p] -= h * Q[j]
                for m in range(NDOF):
                    s = loc[dofs[i, m]]
                    if s >= 0:
                        A[p, s] += h * h * K[j, m]
        z = np.zeros(n)
        for j in range(loc.size):
            if loc[j] >= 0:
                z[loc[j]] = v[j]
        vn = np.linalg.solve(A, M @ z + r)
        for j in range(loc.size):
            if loc[j] >= 0:
                v[j] = vn[loc[j]]
                x[j] += h * vn[loc[j]]
        if not np.all(np.isfinite(vn)):
            return k
        out[k] = x
    return -1


def history(p: Pendulum = Pendulum(), h: float = 1e-4, steps: int = 20000) -> np.ndarray:
    """The global coordinates (steps, 6 (n + 1)) after each of ``steps`` steps of Eq. (2)
    with step h (s).  RuntimeError if the state stops being finite."""
    sec = CircularSection(p.d)
    Le = p.L / p.n
    q0, dofs, free = p.reference(), p.dofs(), p.free()
    el = Cable3D(np.full(p.n, Le), q0[dofs], sec, p.E, rho=p.rho)
    loc = -np.ones(q0.size, dtype=np.int64)
    loc[free] = np.arange(free.size)
    Mg, Fg = np.zeros((q0.size, q0.size)), np.zeros(q0.size)
    for d, Me, Ge in zip(dofs, el.mass(), el.gravity([0.0, -p.g, 0.0])):
        Mg[np.ix_(d, d)] += Me
        Fg[d] += Ge
    rules = (*point_rows(Le, AXIAL_POINTS)[:2], *point_rows(Le, BENDING_POINTS))
    x, v, out = q0.copy(), p.velocity(), np.zeros((steps, q0.size))
    failed = _march(x, v, Mg[np.ix_(free, free)], Fg[free], loc, dofs, Le, el.EA, el.EI,
                    rules, h, steps, out)
    if failed >= 0:
        raise RuntimeError(f"the cable's state is not finite after step {failed + 1}")
    return out


def file_columns(p: Pendulum, X: np.ndarray) -> np.ndarray:
    """Chrono's file columns 2-7 of states X (steps, ndof): node 0's slope (x, y, z), the
    mid node's y, the tip node's x and z (m)."""
    mid, tip = 6 * (p.n // 2), 6 * p.n
    return np.column_stack([X[:, 3:6], X[:, mid + 1], X[:, tip], X[:, tip + 2]])
