"""Straight beam meshes: node positions, reference nodal coordinates, DOF maps.

Global coordinates are ordered node by node, and within a node slot by slot
(``r``, ``r_x``, ``r_y`` ... as the element declares), each slot a 2-vector.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

_REFERENCE_SLOT = {"r": None, "r_x": (1.0, 0.0), "r_y": (0.0, 1.0)}


@dataclass
class BeamMesh:
    """n_elements equal elements from (0, 0) to (L, 0) along +x; ``slots`` per node."""

    L: float
    n_elements: int
    slots: tuple

    def __post_init__(self):
        self.n_nodes = self.n_elements + 1
        self.per_node = 2 * len(self.slots)
        self.n_dofs = self.n_nodes * self.per_node
        self.X = np.linspace(0.0, self.L, self.n_nodes)
        self.lengths = np.diff(self.X)
        first = np.arange(self.n_elements) * self.per_node
        self.dofmap = first[:, None] + np.arange(2 * self.per_node)[None, :]

    def dof(self, node: int, slot: str, component: int) -> int:
        """Global index of one nodal coordinate (component 0 = x, 1 = y)."""
        return node * self.per_node + 2 * self.slots.index(slot) + component

    def reference(self) -> np.ndarray:
        """q0: the undeformed straight configuration."""
        q = np.zeros((self.n_nodes, len(self.slots), 2))
        for s, slot in enumerate(self.slots):
            ref = _REFERENCE_SLOT[slot]
            q[:, s, :] = np.stack([self.X, np.zeros_like(self.X)], 1) if ref is None else ref
        return q.ravel()
