"""Natural frequencies of a running 2D belt drive: the axially moving belt
(:mod:`ancf.belts.ale2d`) linearised about its steady state (:mod:`ancf.belts.steady2d`).

The ALE belt's kinetic energy, element by element (S_x = S P, Eq. (1) of ale2d),

    T = 1/2 q'^T M q' + vb q'^T M P q + 1/2 vb^2 q^T P^T M P q

gives, with the transport speed vb the rate of the material coordinate s (cyclic), the belt's
equations M q'' + vb (M P - P^T M) q' + vb' M P q - vb^2 M_x q + dU/dq = Q and the axial
momentum's d/dt (q'^T M P q + vb q^T M_x q) = Q_s, Q_s = sum_e F_e . (P E)_e the power of the
forces on the material per unit vb (contact, friction and strain-rate damping F = Q_c - Q_d;
the weight's vanishes round the closed loop, the elastic forces' with the shift of the
loop).  A free pulley's I_j omega_j' = T_c - T_a - c_j omega_j and an arm's I_a psi'' as in
the march (:mod:`ancf.belts.forces`).  The material velocity is q' + vb P q everywhere, so
the steady Jacobian (:meth:`~ancf.belts.steady2d.SteadyProblem.residual`) is the stiffness
and the derivatives by vb and the pulley speeds, and the kernels' velocity derivatives
(d/dV: Cv, dT/dV, dA/dV; the arms' by psi') the damping, with the gyroscopic
vb (M P - P^T M).  The gauge coordinate stays fixed, as in the steady solve.

Second-order unknowns (belt, arm angles) and first-order ones (vb, pulley speeds) make the
pencil A z' = B z, z = (unknowns, rates of the second-order ones); its eigenvalues lambda
nearest 0 by shift-invert Arnoldi: frequency |Im lambda| / 2 pi, damping ratio
-Re lambda / |lambda|.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import LinearOperator, eigs, splu

from ancf.belts.ale2d import ale_terms
from ancf.belts.arm2d import PULLEY
from ancf.elements.dufva2d import damping_forces

#: the shift of the eigensolver, 1/s (below every mode of a drive; 0 is singular where a
#: pulley spins freely)
SHIFT = -1.0


@dataclass(frozen=True, kw_only=True)
class RunningModes:
    """Eigenvalues ``lam`` (count,) 1/s of the oscillatory modes by frequency, their vectors
    ``z`` (N, count) in the steady problem's unknowns (belt less the gauge, vb, free
    coordinates) and the growing eigenvalues among all found."""

    lam: np.ndarray
    z: np.ndarray
    unstable: np.ndarray  # every eigenvalue found with Re lambda > 0 (Im >= 0), 1/s

    @property
    def frequencies_hz(self) -> np.ndarray:
        return np.abs(self.lam.imag) / (2 * np.pi)

    @property
    def damping_ratios(self) -> np.ndarray:
        return -self.lam.real / np.abs(self.lam)


def pencil(problem, st) -> tuple:
    """(A, B, second) of the linearised running drive: sparse (N + N2) matrices and the
    indices of the second-order unknowns (module docstring)."""
    drive, kern, n, k = problem.drive, problem.kern, problem.n, problem.k
    laws = problem.scaled(st.lam)
    E, V, _, _, c, arm = ale_terms(kern, st.x, st.w, st.vb, problem.P, laws, True)
    Q, Kq, Cv, Qw, _, _, dTv, _ = c
    _, _, dAv, _, dAp, Qp, Tp = arm
    vidx, P, vb = kern.vidx, problem.P, st.vb
    M = drive.element.mass()
    Ef = E.reshape(E.shape[0], -1)
    PE = np.einsum("eab,eb->ea", P, Ef)
    F, Kd = Q.copy(), np.zeros_like(Kq)
    if np.any(kern.strain_damping != 0.0):  # F = Q_c - Q_d, and d(Q_d)/dE apart
        gd = np.zeros_like(Q)
        damping_forces(E, V, kern.element, kern.strain_damping, True, gd, Kd,
                       np.zeros_like(Kq))
        F -= gd
    N = n + 1 + k                       # full layout: belt (n), vb, free (k)
    J = problem.residual(st.x, st.w, st.vb, st.lam)[1]   # columns without the gauge
    Jc = J.tocoo()
    keep = problem.keep
    full = sp.coo_matrix((Jc.data, (np.where(Jc.row < n, Jc.row, Jc.row + 1),
                                    keep[Jc.col])), shape=(N, N)).tolil()
    # the vb row: -dQ_s/d(unknowns) into K, its rates into C, its inertia into the mass
    dQs_dE = np.einsum("eba,eb->ea", Kq - Kd + vb * np.einsum("eab,ebc->eac", Cv, P), PE) \
        + np.einsum("eba,eb->ea", P, F)
    row = np.zeros(N)
    np.add.at(row, vidx, -dQs_dE)
    row[n] = -np.sum(np.einsum("eab,eb->ea", Cv, PE) * PE)
    for j, p in problem.pulley_of.items():
        row[n + 1 + j] = -np.sum(Qw[:, p, :] * PE)
    for ja, a in problem.arm_of.items():
        row[n + 1 + ja] = -np.sum(Qp[a, 0] * PE)
    full[n, :] = row
    K = full.tocsr()
    # rates of the second-order unknowns (belt, arms) and inertia
    MP = np.einsum("eab,ebc->eac", M, P)
    G = vb * (MP - np.transpose(MP, (0, 2, 1)))
    C = sp.coo_matrix(((G - Cv).ravel(),
                       (np.broadcast_to(vidx[:, :, None], G.shape).ravel(),
                        np.broadcast_to(vidx[:, None, :], G.shape).ravel())),
                      shape=(N, N)).tolil()
    Mx_q = np.zeros(N)
    np.add.at(Mx_q, vidx, np.einsum("eab,eb->ea", problem.Mx, Ef))
    vb_row = np.zeros(N)
    vb_row[:n] = 2 * vb * Mx_q[:n]
    cv_row = np.zeros(N)
    np.add.at(cv_row, vidx, np.einsum("eba,eb->ea", Cv, PE))
    vb_row[:n] -= cv_row[:n]
    C[n, :] = vb_row
    for j, p in problem.pulley_of.items():
        r = np.zeros(N)
        np.add.at(r, vidx, -dTv[p])
        C[n + 1 + j, :n] = r[:n]
    for ja, a in problem.arm_of.items():
        j = int(kern.free[int(kern.arms[a, PULLEY])])
        r = np.zeros(N)
        np.add.at(r, vidx, -dAv[a])
        C[n + 1 + ja, :n] = r[:n]
        colq = np.zeros(N)
        np.add.at(colq, vidx, -Qp[a, 1])
        C[:n, n + 1 + ja] = colq[:n, None]
        C[n + 1 + ja, n + 1 + ja] = kern.damping[ja] + kern.damping[j] - dAp[a, 1]
        C[n + 1 + j, n + 1 + ja] = -Tp[a, 1] - kern.damping[j]
        C[n, n + 1 + ja] = -np.sum(Qp[a, 1] * PE)
    Mm = sp.coo_matrix((M.ravel(), (np.broadcast_to(vidx[:, :, None], M.shape).ravel(),
                                    np.broadcast_to(vidx[:, None, :], M.shape).ravel())),
                       shape=(N, N)).tolil()
    mpq = np.zeros(N)
    np.add.at(mpq, vidx, np.einsum("eab,eb->ea", MP, Ef))
    Mm[:n, n] = mpq[:n, None]
    Mm[n, :n] = mpq[:n]
    Mm[n, n] = float(np.einsum("ea,eab,eb->", Ef, problem.Mx, Ef))
    for j in range(k):
        Mm[n + 1 + j, n + 1 + j] = kern.inertia[j]
    K, C, Mm = (X.tocsr()[keep][:, keep] for X in (K, C, Mm))
    second = np.array([i for i, g in enumerate(keep)
                       if g < n or (g > n and (g - n - 1) in problem.arm_of)])
    return _first_order(K, C, Mm, second)


def _first_order(K, C, Mm, second) -> tuple:
    """A z' = B z with z = (x, x'_second): the second-order unknowns' rates are their own
    unknowns; every unknown's inertia column is the derivative of its rate (second-order)
    or of itself (first-order)."""
    N, N2 = K.shape[0], second.size
    S = sp.csr_matrix((np.ones(N2), (np.arange(N2), second)), shape=(N2, N))
    first = np.setdiff1d(np.arange(N), second)
    F = sp.csr_matrix((np.ones(first.size), (first, first)), shape=(N, N))
    A = sp.bmat([[S, None], [Mm @ F, Mm @ S.T]], format="csc")
    B = sp.bmat([[None, sp.identity(N2)], [-K, -C @ S.T]], format="csc")
    return A, B, second


def running_modes(problem, st, count: int = 6) -> RunningModes:
    """The ``count`` oscillatory modes of lowest frequency (and any real eigenvalue below
    them) of the drive running at its steady state ``st``."""
    A, B, _ = pencil(problem, st)
    lu = splu((B - SHIFT * A).tocsc())
    op = LinearOperator(A.shape, matvec=lambda v: lu.solve(A @ v), dtype=float)
    want = min(A.shape[0] - 2, 2 * count + 8)
    nu, z = eigs(op, k=want, which="LM", v0=np.ones(A.shape[0]))  # no random start: repeatable
    lam = SHIFT + 1.0 / nu
    osc = lam.imag > 1e-9 * np.abs(lam)
    order = np.argsort(np.abs(lam[osc].imag))[:count]
    N = problem.keep.size
    grows = (lam.real > 1e-9 * np.abs(lam)) & (lam.imag >= 0)
    return RunningModes(lam=lam[osc][order], z=z[:N, osc][:, order], unstable=lam[grows])
