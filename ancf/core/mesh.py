"""Beam meshes: node positions, reference nodal coordinates, DOF maps.

A mesh lays ``n_elements`` equal elements along a reference curve ``r(s)`` with
unit tangent ``t(s)``, s in [0, L] the arc length: the straight line from the
origin along +x by default, or any curve (an arc, a belt wrapped around two
pulleys).  ``closed=True`` joins the last element to the first node (a closed
loop has as many nodes as elements).  Global coordinates are registered in a
:class:`~ancf.core.registry.Registry` block (``name``), ordered node by node and within a
node slot by slot (``r``, ``r_x``, ``r_y`` ... as the element declares), each slot a
2-vector; the reference slopes are ``r_x = t`` and ``r_y = n`` (t turned by +90°).
With ``dim=3`` each slot is a 3-vector: the curve lies in the plane z = 0 and the
reference slope ``r_z`` is the unit vector e_z (the spatial beams).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from ancf.core.registry import Registry


def straight(s):
    """The default reference curve: r = (s, 0), t = (1, 0)."""
    s = np.asarray(s, dtype=float)
    return np.stack([s, np.zeros_like(s)], -1), np.tile([1.0, 0.0], (s.size, 1))


@dataclass
class BeamMesh:
    """n_elements equal elements along ``curve`` (default: straight along +x), length L (m)."""

    L: float
    n_elements: int
    slots: tuple
    closed: bool = False
    curve: Callable = straight
    registry: Registry = field(default_factory=Registry)
    name: str = "beam"
    dim: int = 2

    def __post_init__(self):
        self.n_nodes = self.n_elements + (0 if self.closed else 1)
        self.per_node = self.dim * len(self.slots)
        self.block = self.registry.add(self.name, self.n_nodes * self.per_node, "nodes")
        self.n_dofs = self.registry.n
        self.s = np.linspace(0.0, self.L, self.n_elements + 1)[: self.n_nodes]
        self.X = self.s  # arc length of each node (x of the straight default)
        self.lengths = np.full(self.n_elements, self.L / self.n_elements)
        nodes = np.arange(self.n_elements)
        ends = np.stack([nodes, (nodes + 1) % self.n_nodes], 1)
        slot = np.arange(self.per_node)
        self.dofmap = (self.block.start + ends[:, :, None] * self.per_node + slot).reshape(self.n_elements, -1)

    def dof(self, node: int, slot: str, component: int) -> int:
        """Global index of one nodal coordinate (component 0 = x, 1 = y, 2 = z)."""
        return self.block.start + node * self.per_node + self.dim * self.slots.index(slot) + component

    def reference(self) -> np.ndarray:
        """q0 over all registered coordinates: this mesh's block holds the reference
        configuration on the curve, other blocks are zero."""
        r, t = self.curve(self.s)
        ref = {"r": r, "r_x": t, "r_y": np.stack([-t[:, 1], t[:, 0]], 1)}
        if self.dim == 3:
            ref = {k: np.pad(v, ((0, 0), (0, 1))) for k, v in ref.items()}
            ref["r_z"] = np.tile([0.0, 0.0, 1.0], (self.n_nodes, 1))
        q = np.zeros(self.registry.n)
        q[self.block.start: self.block.start + self.block.size] = np.stack(
            [ref[s] for s in self.slots], 1).ravel()
        return q
