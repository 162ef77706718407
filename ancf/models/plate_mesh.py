"""Rectangular plate meshes of ``plate36`` elements with shared nodes.

``nx`` x ``ny`` equal elements cover the rectangle [0, a] x [0, b] (m) in the
x-y plane.  Node (i, j) at (i a/nx, j b/ny) has the index ``j (nx + 1) + i``;
global coordinates are ordered node by node, within a node slot by slot
(``r``, ``r_x``, ``r_y``), each slot a 3-vector.  Element (i, j) has the index
``j nx + i`` and the nodes A (i, j), B (i + 1, j), C (i + 1, j + 1), D (i, j + 1)
(the node order of the family ``plate36``).  The reference is flat and unstrained:
``r = (x, y, 0)``, ``r_x = e_x``, ``r_y = e_y``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ancf.elements.basis import plate36_S
from ancf.core.quadrature import gauss01

SLOTS = ("r", "r_x", "r_y")
PER_NODE = 3 * len(SLOTS)


@dataclass
class PlateMesh:
    """nx x ny equal elements over a x b (m)."""

    a: float
    b: float
    nx: int
    ny: int

    def __post_init__(self):
        for name, v in (("nx", self.nx), ("ny", self.ny)):
            if not isinstance(v, (int, np.integer)) or v < 1:
                raise ValueError(f"{name} must be an integer >= 1 (got {v!r})")
        for name, v in (("a", self.a), ("b", self.b)):
            if not (np.isfinite(v) and v > 0):
                raise ValueError(f"{name} must be finite and > 0 (got {v!r})")
        self.n_elements = self.nx * self.ny
        self.n_nodes = (self.nx + 1) * (self.ny + 1)
        self.n_dofs = self.n_nodes * PER_NODE
        self.lengths = np.full(self.n_elements, self.a / self.nx)  # element sides along x, m
        self.widths = np.full(self.n_elements, self.b / self.ny)   # element sides along y, m
        i, j = np.meshgrid(np.arange(self.nx), np.arange(self.ny))
        n0 = (j * (self.nx + 1) + i).ravel()
        nodes = np.stack([n0, n0 + 1, n0 + self.nx + 2, n0 + self.nx + 1], 1)  # A, B, C, D
        self.element_nodes = nodes
        self.dofmap = (nodes[:, :, None] * PER_NODE + np.arange(PER_NODE)).reshape(self.n_elements, -1)
        xs, ys = np.linspace(0.0, self.a, self.nx + 1), np.linspace(0.0, self.b, self.ny + 1)
        X, Y = np.meshgrid(xs, ys)
        self.X, self.Y = X.ravel(), Y.ravel()  # node positions, m

    def node(self, i: int, j: int) -> int:
        """Index of the node at (i a/nx, j b/ny)."""
        return j * (self.nx + 1) + i

    def dof(self, node: int, slot: str, component: int) -> int:
        """Global index of one nodal coordinate (component 0 = x, 1 = y, 2 = z)."""
        return node * PER_NODE + 3 * SLOTS.index(slot) + component

    def reference(self) -> np.ndarray:
        """q0 (n_dofs,): r = (X, Y, 0), r_x = e_x, r_y = e_y at every node."""
        q = np.zeros((self.n_nodes, len(SLOTS), 3))
        q[:, 0, 0], q[:, 0, 1] = self.X, self.Y
        q[:, 1, 0] = q[:, 2, 1] = 1.0
        return q.ravel()

    def pressure_load(self, p: float) -> np.ndarray:
        """Consistent generalized forces (n_dofs,) of a uniform pressure p (Pa) along +z
        on the reference surface, ``p int S^T e_z dA`` (N on r, N m on r_x, r_y); the
        2 x 2 Gauss rule is exact for the incomplete cubic."""
        t, w = gauss01(2)
        a, b = self.a / self.nx, self.b / self.ny
        S = plate36_S(t[:, None] * a, t[None, :] * b, a, b)  # (2, 2, 12)
        fe = p * a * b * np.einsum("i,j,ijk->k", w, w, S)
        f = np.zeros(self.n_dofs)
        np.add.at(f, self.dofmap[:, 2::3], np.broadcast_to(fe, (self.n_elements, 12)))
        return f
