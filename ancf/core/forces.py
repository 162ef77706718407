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


class Gravity:
    """Q_g = int rho S^T g dV (constant), potential V = -Q_g . q per element."""

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
        """V_i = -int rho g . r dV of each element, J (zero in the reference at y = 0)."""
        return [-np.einsum("ek,ek->e", qe, q[grp.dofmap])
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


class Forces:
    """Sum of force terms; an empty sum is a zero force."""

    def __init__(self, n_dofs: int, terms=()):
        self.n_dofs, self.terms = n_dofs, list(terms)

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
        """Summed potential of the conservative terms per group, or None if none."""
        parts = [t.element_potential(q) for t in self.terms if hasattr(t, "element_potential")]
        if not parts:
            return None
        return [sum(p[i] for p in parts) for i in range(len(parts[0]))]
