"""Energy of a chain of Exudyn ``ObjectANCFCable2D`` elements from nodal coordinates.

Node coordinates are (x, y, x', y') (position and axial slope); an element interpolates
them with cubic Hermite functions.  Kinetic and gravity energy are integrated exactly
(4 Gauss points), the strain energy EA/2 eps^2 + EI/2 K^2 with the element's own
rules: axial strain eps = |r'| - 1 on 5 Gauss points, material curvature
K = (r' x r'')/|r'|^2 on 3 (Exudyn's default integration orders 9 and 5), so the sum is
the discrete energy whose gradient Exudyn's elastic forces are.  Pure numpy: the
benchmark's tests use it without exudyn.
"""
from __future__ import annotations

import numpy as np

AXIAL_GAUSS, BENDING_GAUSS, MASS_GAUSS = 5, 3, 4


def _hermite(xi: np.ndarray, le: float, d: int) -> np.ndarray:
    """d-th x-derivative of the cubic Hermite functions (r0, r0', r1, r1') at xi = x/le."""
    x2, x3 = xi**2, xi**3
    table = {
        0: [1 - 3 * x2 + 2 * x3, le * (xi - 2 * x2 + x3), 3 * x2 - 2 * x3, le * (x3 - x2)],
        1: [(6 * x2 - 6 * xi) / le, 1 - 4 * xi + 3 * x2, (6 * xi - 6 * x2) / le, 3 * x2 - 2 * xi],
        2: [(12 * xi - 6) / le**2, (6 * xi - 4) / le, (6 - 12 * xi) / le**2, (6 * xi - 2) / le],
    }
    return np.array(table[d]).T


class CableEnergy:
    """Kinetic + gravity + strain energy of a chain of Cable2D elements."""

    def __init__(self, le: float, ea: float, ei: float, rho_a: float, g: float):
        self.le, self.ea, self.ei, self.rho_a, self.g = le, ea, ei, rho_a, g

    def _rule(self, npts: int):
        xi, w = np.polynomial.legendre.leggauss(npts)
        return (xi + 1) / 2, w * self.le / 2

    def _field(self, q, xi, d):
        """(samples, elements, points, 2) field of the d-th derivative of r."""
        nodal = np.concatenate([q[:, :-1], q[:, 1:]], axis=2).reshape(*q.shape[:1], -1, 4, 2)
        return np.einsum("pk,sekd->sepd", _hermite(xi, self.le, d), nodal)

    def total(self, q: np.ndarray, v: np.ndarray) -> np.ndarray:
        """Total energy per sample from (samples, nodes, 4) coordinates and velocities."""
        xi, w = self._rule(MASS_GAUSS)
        kinetic = 0.5 * self.rho_a * np.einsum("sepd,p->s", self._field(v, xi, 0) ** 2, w)
        gravity = self.rho_a * self.g * np.einsum("sep,p->s", self._field(q, xi, 0)[..., 1], w)
        xi, w = self._rule(AXIAL_GAUSS)
        eps = np.linalg.norm(self._field(q, xi, 1), axis=-1) - 1.0
        axial = 0.5 * self.ea * np.einsum("sep,p->s", eps**2, w)
        xi, w = self._rule(BENDING_GAUSS)
        r1, r2 = self._field(q, xi, 1), self._field(q, xi, 2)
        kappa = (r1[..., 0] * r2[..., 1] - r1[..., 1] * r2[..., 0]) / np.sum(r1**2, axis=-1)
        bending = 0.5 * self.ei * np.einsum("sep,p->s", kappa**2, w)
        return kinetic + gravity + axial + bending
