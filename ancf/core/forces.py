"""Generalised external forces Q_k as composable terms.

A term has ``value(q, v, t)`` (global vector, N), ``jacobians(q, v, t)`` ->
``(dQ/dq, dQ/dv)`` (sparse or ``None`` when zero), and, if it is conservative,
``element_potential(q)`` (a list with one (nel,) array per element group, J).
:class:`Forces` sums terms.  Gravity is the first term; follower or
velocity-dependent forces add the same methods.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ancf.core.quadrature import gauss01


def shape_integrals(element, nx: int = 4, ny: int = 2) -> np.ndarray:
    """int S_k dV per element, (nel, nshape), m^3: Gauss quadrature of the generated
    shape functions; 4 x 2 points are exact for shape functions cubic in x and
    linear in y (all planar families here)."""
    xi, wx = gauss01(nx)
    yq, wy = element.section.rule(ny)
    l = element.lengths[:, None, None]
    X = xi[None, :, None] * l * np.ones((1, 1, yq.size))
    Y = np.broadcast_to(yq[None, None, :], X.shape)
    S = element.shapes["S"](X, Y, np.broadcast_to(l, X.shape))  # (nel, nx, ny, nshape)
    w = wx[None, :, None] * wy[None, None, :] * l
    return np.einsum("exy,exyk->ek", w, S)


def _dot_rows(qe, Q):
    """-qe[e] . Q[..., e, :] for each element e, (nel,) or (ns, nel): the states stacked as
    rows of one product, so each row sums as the single-state product does."""
    rows = Q.reshape(-1, qe.shape[1])
    out = -np.einsum("ek,ek->e", np.tile(qe, (rows.shape[0] // qe.shape[0], 1)), rows)
    return out.reshape(Q.shape[:-1])


class Gravity:
    """Q_g = int rho S^T g dV (constant), potential V = -Q_g . q per element."""

    #: the value depends on neither q, q' nor t (:attr:`Forces.constant`)
    constant = True

    def __init__(self, assembly, g=(0.0, -9.81)):
        self.g = np.asarray(g, dtype=float)
        self.groups = assembly.groups
        self.element_vectors = []
        self.Q = np.zeros(assembly.n_dofs)
        for grp in self.groups:
            el = grp.element
            s = el.rho * shape_integrals(el)  # (nel, nshape)
            qe = (s[:, :, None] * self.g[None, None, :]).reshape(el.nel, el.ndof)
            self.element_vectors.append(qe)
            np.add.at(self.Q, grp.dofmap, qe)

    def value(self, q, v, t) -> np.ndarray:
        return self.Q

    def jacobians(self, q, v, t):
        return None, None

    def element_potential(self, q) -> list:
        """V_i = -int rho g . r dV of each element, J (zero in the reference at y = 0);
        ``q`` (n_dofs,) or states side by side (ns, n_dofs), giving (nel,) or (ns, nel)."""
        return [_dot_rows(qe, q[..., grp.dofmap])
                for grp, qe in zip(self.groups, self.element_vectors)]


class EndMoment:
    """A moment M (N m) on the slope r_x = (x, y) at coordinates ``dofs``: the generalised
    force of the angle theta = atan2(y, x), Q = M dtheta/dr_x = M (-y, x) / |r_x|^2
    (a follower moment: it turns with the slope), and its exact Jacobian, symmetric
    because Q = grad(M theta)."""

    def __init__(self, n_dofs: int, dofs, M: float):
        self.n_dofs, self.dofs, self.M = n_dofs, list(dofs), M
        self.dofmap = np.array([self.dofs])

    def value(self, q, v, t) -> np.ndarray:
        x, y = q[self.dofs]
        out = np.zeros(self.n_dofs)
        out[self.dofs] = self.M * np.array([-y, x]) / (x * x + y * y)
        return out

    def jacobians(self, q, v, t):
        x, y = q[self.dofs]
        J = self.M / (x * x + y * y) ** 2 * np.array([[2 * x * y, y * y - x * x],
                                                      [y * y - x * x, -2 * x * y]])
        rows, cols = np.meshgrid(self.dofs, self.dofs, indexing="ij")
        return sp.csr_matrix((J.ravel(), (rows.ravel(), cols.ravel())),
                             shape=(self.n_dofs, self.n_dofs)), None


def _skew(a) -> np.ndarray:
    """The matrix of a x (.)."""
    return np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])


class SectionMoment:
    """A moment ``M`` (3,) N m of fixed global direction on a spatial section whose
    orientation is carried by the slopes r_y = a, r_z = b (6 global ``dofs``: a then b),
    the section's second moments ``weights`` = (int y^2 dA, int z^2 dA) (m^4).

    Derivation.  With slopes instead of rotations, the end face moves by
    du = y dr_y + z dr_z relative to its centre.  Its virtual rotation dtheta is the rigid
    rotation that fits du best: it minimises ``int |du - dtheta x (y r_y + z r_z)|^2 dA =
    sum_k w_k |dr_k - dtheta x r_k|^2`` (w_y = int y^2, w_z = int z^2; the odd moments
    vanish), i.e. ``W dtheta = sum_k w_k r_k x dr_k``, ``W = sum_k w_k (|r_k|^2 I - r_k
    r_k^T)`` (symmetric, positive definite while the slopes are not parallel).  For a rigid
    rotation of the slopes (orthonormal or not) this is that rotation exactly.  The virtual
    work ``M . dtheta = sum_k w_k (m x r_k) . dr_k``, ``m = W^-1 M``, gives the generalised
    forces

        Q_a = w_y m x a,    Q_b = w_z m x b.

    In the reference (a = e_y, b = e_z) these are the linear end tractions of M: the torque
    M_x is carried by r_y and r_z in the shares w_y/I_p and w_z/I_p (I_p = w_y + w_z), the
    bending moment about e_y by r_z alone, about e_z by r_y alone.  Planar case: with
    b = e_z fixed and M = M e_z, ``Q_a = M e_z x a/|a|^2``, the gradient of M times the angle
    of a in the x-y plane (:class:`EndMoment` on r_y): the load is then conservative.  In
    general a moment about a fixed axis is not (no potential is declared).  The Jacobian,
    from ``dm = -W^-1 (dW) m``:

        dQ_i/dr_k = w_i (skew(r_i) W^-1 D_k + delta_ik skew(m)),
        D_k = w_k (2 m r_k^T - (r_k . m) I - r_k m^T),

    not symmetric in general.
    """

    def __init__(self, n_dofs: int, dofs, M, weights):
        self.n_dofs, self.dofs = n_dofs, np.asarray(dofs, dtype=np.int64)
        self.M, self.w = np.asarray(M, dtype=float), np.asarray(weights, dtype=float)
        if self.dofs.shape != (6,) or self.M.shape != (3,) or self.w.shape != (2,):
            raise ValueError("SectionMoment needs 6 dofs (r_y then r_z), a 3-vector M and "
                             "2 weights")
        self.dofmap = self.dofs[None, :]

    def _state(self, q):
        r = (q[self.dofs[:3]], q[self.dofs[3:]])
        W = sum(w * ((rk @ rk) * np.eye(3) - np.outer(rk, rk)) for w, rk in zip(self.w, r))
        Winv = np.linalg.inv(W)
        return r, Winv, Winv @ self.M

    def value(self, q, v, t) -> np.ndarray:
        r, _, m = self._state(q)
        out = np.zeros(self.n_dofs)
        out[self.dofs] = np.concatenate([w * np.cross(m, rk) for w, rk in zip(self.w, r)])
        return out

    def jacobians(self, q, v, t):
        r, Winv, m = self._state(q)
        J = np.zeros((6, 6))
        for k, (wk, rk) in enumerate(zip(self.w, r)):
            dm = -Winv @ (wk * (2.0 * np.outer(m, rk) - (rk @ m) * np.eye(3) - np.outer(rk, m)))
            for i, (wi, ri) in enumerate(zip(self.w, r)):
                J[3 * i:3 * i + 3, 3 * k:3 * k + 3] = -wi * _skew(ri) @ dm
            J[3 * k:3 * k + 3, 3 * k:3 * k + 3] += wk * _skew(m)
        rows, cols = np.meshgrid(self.dofs, self.dofs, indexing="ij")
        return sp.csr_matrix((J.ravel(), (rows.ravel(), cols.ravel())),
                             shape=(self.n_dofs, self.n_dofs)), None


class Forces:
    """Sum of force terms; an empty sum is a zero force."""

    def __init__(self, n_dofs: int, terms=()):
        self.n_dofs, self.terms = n_dofs, list(terms)

    @property
    def constant(self) -> bool:
        """Whether the sum depends on neither q, q' nor t (every term says so)."""
        return all(getattr(term, "constant", False) for term in self.terms)

    def value(self, q, v, t) -> np.ndarray:
        out = np.zeros(self.n_dofs)
        for term in self.terms:
            out = out + term.value(q, v, t)
        return out

    def jacobians(self, q, v, t):
        """(dQ/dq, dQ/dv), each sparse or None when every term's is zero."""
        Kq = Kv = None
        for term in self.terms:
            a, b = term.jacobians(q, v, t)
            if a is not None:
                Kq = a if Kq is None else Kq + a
            if b is not None:
                Kv = b if Kv is None else Kv + b
        return Kq, Kv

    def dofmaps(self) -> list:
        """The coordinate blocks (nblock, nd) whose couplings the terms' Jacobians may
        fill (declared by a term as ``dofmap``), for the sparsity pattern."""
        return [np.asarray(t.dofmap) for t in self.terms if getattr(t, "dofmap", None) is not None]

    def element_potential(self, q) -> list | None:
        """Summed potential of the conservative terms per group, or None if none (``q``
        one state or states side by side, as the terms take it)."""
        parts = [t.element_potential(q) for t in self.terms if hasattr(t, "element_potential")]
        if not parts:
            return None
        return [sum(p[i] for p in parts) for i in range(len(parts[0]))]
