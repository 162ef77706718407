"""Static small-deflection cases of Chrono's ANCF formulation unit tests, on our elements.

Chrono's ``utest_FEA_ANCFhexa_3843_Formulation.cpp`` (``AxialDisplacementCheck``,
``CantileverTipLoadCheck``, ``CantileverGravityCheck``, ``AxialTwistCheck``) builds a
straight bar of ``n`` ANCF 3843 bricks along x (length L, width w along y, height h along
z, all m; one brick across), the cross-section centred on the x axis, nodes shared between
neighbours, every coordinate of the four nodes at x = 0 fixed, and loads it at the centre
of the tip face (natural point (1, 0, 0) of the last brick) or by gravity.

Mesh: station i = 0..n at x = i L/n; node (i, c) with corner c = 2 [z > 0] + [y > 0] at
(x_i, +-w/2, +-h/2); global index 4 i + c, coordinates 12 per node [r, r_x, r_y, r_z]
(m, dimensionless gradients), reference gradients = I.  Equations:

    Q(e) = sum_el A_el^T Q_el(A_el e)                N (N m on gradients)          (1)
    K(e) = sum_el A_el^T K_el(A_el e) A_el           N/m                           (2)
    Q_F  = S(1, 0, 0)^T F                            point force F (N), dead load  (3)
    Q_M,a = (1/2) M x grad s_a(1, 0, 0)              moment M (N m), per scalar s_a (4)
    Q_g  = sum_el A_el^T int rho S^T g dV            consistent gravity, N         (5)
    solve Q(e) = Q_ext on the free coordinates by Newton, |r| <= 1e-10 |Q_ext|     (6)

A_el gathers an element's 96 coordinates; (4) is the virtual work of M on the small
rotation (1/2) curl du (Recuero et al. 2016, the form Chrono's ``ComputeNF`` uses),
evaluated at the reference as Chrono's ``DoStaticLinear`` does.  The tip frame follows
Chrono's ``EvaluateElementFrame``: x along r_x, z along r_x x r_y, y = z x x, and
Cardan XYZ angles (roll, pitch, yaw) in rad.  Internal forces: ``ancf3843`` with
Chrono's own rule (``NP = 4`` Gauss points per direction), which integrates the small-
deflection stiffness B0^T D B0 (degree 6 per direction) exactly.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from ancf.elements import ancf3843 as brick
from ancf.elements import continuum3d as c3

NP_CHRONO = 4   # Gauss points per direction of ChElementHexaANCF_3843 (header NP)


@lru_cache(maxsize=8)
def _kernel(dims: tuple, E: float, nu: float, ngauss: int):
    """(e0 (96,) in m, parts): a brick's reference and ``continuum3d`` parts, computed once
    per sides (m), material (Pa, -) and Gauss rule."""
    basis, rules = brick.continuum(*dims, E, nu, ngauss=ngauss)
    return basis.e0, c3.parts(basis, rules)


@dataclass(frozen=True)
class BrickBar:
    """A bar of ``n`` 3843 bricks: L, w, h in m, E in Pa, nu, rho in kg/m^3."""

    n: int
    L: float
    w: float
    h: float
    E: float
    nu: float
    rho: float = 0.0
    ngauss: int = NP_CHRONO

    @property
    def dx(self) -> float:
        return self.L / self.n

    @property
    def ndof(self) -> int:
        return 12 * 4 * (self.n + 1)

    def dims(self):
        return self.dx, self.w, self.h

    def reference(self) -> np.ndarray:
        """e0 (ndof,): node positions (m) and unit gradients."""
        e = []
        for i in range(self.n + 1):
            for c in range(4):
                y, z = (c % 2 - 0.5) * self.w, (c // 2 - 0.5) * self.h
                e.append(np.concatenate([[i * self.dx, y, z], np.eye(3).ravel()]))
        return np.concatenate(e)

    def element_dofs(self, i: int) -> np.ndarray:
        """The 96 global indices of brick i (0-based) in ``ancf3843``'s node order A..H."""
        idx = []
        for a, b, c in brick.NODE_SIGNS:
            node = 4 * (i + (a > 0)) + 2 * (c > 0) + (b > 0)
            idx.extend(range(12 * node, 12 * node + 12))
        return np.array(idx)

    def free(self) -> np.ndarray:
        """Free coordinates: all but the 48 of the four nodes at x = 0."""
        return np.arange(48, self.ndof)

    def assemble(self, u: np.ndarray, tangent: bool = True):
        """Eqs. (1)-(2) at the displacement u = e - e0 (ndof,): Q (ndof,) and K (ndof, ndof)
        (None unless ``tangent``), all bricks in one ``continuum3d.static_batch``.  Each
        brick sees its displacement u_el, so no rigid offset (up to L, m) rounds off the
        small strains."""
        e0, parts = _kernel(self.dims(), self.E, self.nu, self.ngauss)
        d = np.array([self.element_dofs(i) for i in range(self.n)])
        Qk, Kk = c3.static_batch(u[d] + (brick.reference_coordinates(*self.dims()) - e0),
                                 parts, tangent)
        Q = np.zeros(self.ndof)
        np.add.at(Q, d, Qk)
        if not tangent:
            return Q, None
        K = np.zeros((self.ndof, self.ndof))
        np.add.at(K, (d[:, :, None], d[:, None, :]), Kk)
        return Q, K

    def tip_force(self, F) -> np.ndarray:
        """Eq. (3): the generalised force (ndof,) of the point force F (3,) N at the tip centre."""
        q = np.zeros(self.ndof)
        q[self.element_dofs(self.n - 1)] = brick.shape(1.0, 0.0, 0.0, *self.dims()).T @ F
        return q

    def tip_moment(self, M) -> np.ndarray:
        """Eq. (4): the generalised force (ndof,) of the moment M (3,) N m at the tip centre."""
        G = brick.shape_gradient(1.0, 0.0, 0.0, *self.dims())          # (32, 3), 1/m
        q = np.zeros(self.ndof)
        q[self.element_dofs(self.n - 1)] = 0.5 * np.cross(np.asarray(M, float), G).ravel()
        return q

    def gravity(self, g) -> np.ndarray:
        """Eq. (5): the consistent gravity force (ndof,) N for g (3,) m/s^2."""
        q = np.zeros(self.ndof)
        qe = brick.gravity(*self.dims(), self.rho, g)
        for i in range(self.n):
            q[self.element_dofs(i)] += qe
        return q

    def solve(self, Q_ext: np.ndarray, rtol: float = 1e-10, maxiter: int = 20):
        """Eq. (6): the static displacement u = e - e0 (ndof,) with Q(u) = Q_ext on the free
        coordinates, by Newton from u = 0; returns (u, iterations, |r| / |Q_ext|).

        Stops when |r| <= max(rtol |Q_ext|, floor), floor = eps sqrt(n_free) max|K_ff|
        max|e0_el| (N): the force of one rounding of the element coordinates e0_el + u,
        which no iteration can go below (about 3e-9 |Q_ext| for a 10 N tip load on
        Chrono's 0.5 in aluminium bar, where u / L ~ 1e-5)."""
        u, f = np.zeros(self.ndof), self.free()
        scale = np.linalg.norm(Q_ext[f])
        Q, K = self.assemble(u)
        floor = (np.finfo(float).eps * np.sqrt(f.size) * np.abs(K[np.ix_(f, f)]).max()
                 * np.abs(brick.reference_coordinates(*self.dims())).max())
        for it in range(1, maxiter + 1):
            u[f] += np.linalg.solve(K[np.ix_(f, f)], Q_ext[f] - Q[f])
            Q, K = self.assemble(u)
            r = np.linalg.norm(Q_ext[f] - Q[f])
            if r <= max(rtol * scale, floor):
                return u, it, r / scale
        raise RuntimeError(f"Newton did not converge: relative residual {r / scale:.3e}")

    def tip_frame(self, u: np.ndarray):
        """At the displacement u (ndof,): the tip centre r (3,) m and Cardan XYZ angles (roll, pitch, yaw) rad of the frame
        x = r_x/|r_x|, z = x x r_y/|.|, y = z x x at the natural point (1, 0, 0)."""
        E_ = (self.reference() + u)[self.element_dofs(self.n - 1)].reshape(32, 3)
        s = brick.scalar_shape(1.0, 0.0, 0.0, *self.dims())
        G = brick.shape_gradient(1.0, 0.0, 0.0, *self.dims())
        r, rx, ry = s @ E_, E_.T @ G[:, 0], E_.T @ G[:, 1]
        x = rx / np.linalg.norm(rx)
        zz = np.cross(x, ry)
        zz /= np.linalg.norm(zz)
        R = np.column_stack([x, np.cross(zz, x), zz])
        angles = (np.arctan2(R[2, 1], R[2, 2]), -np.arcsin(R[2, 0]), np.arctan2(R[1, 0], R[0, 0]))
        return r, np.array(angles)
