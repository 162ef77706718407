"""Energy balance along a solution (thesis Eq. 2.34): kinetic T_i, potential V_i
and strain U_i energy of every element at every sample, and their totals."""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class EnergyHistory:
    """Arrays (n_samples, n_elements), J; elements of all groups side by side."""

    t: np.ndarray
    kinetic: np.ndarray
    potential: np.ndarray
    strain: np.ndarray

    @property
    def totals(self) -> dict:
        return {"kinetic": self.kinetic.sum(1), "potential": self.potential.sum(1),
                "strain": self.strain.sum(1), "total": self.total}

    @property
    def total(self) -> np.ndarray:
        return self.kinetic.sum(1) + self.potential.sum(1) + self.strain.sum(1)

    def max_deviation(self) -> float:
        """max_t |E(t) - E(0)|, J."""
        tot = self.total
        return float(np.max(np.abs(tot - tot[0]))) if tot.size else float("nan")


def element_masses(assembly) -> list:
    return [g.element.mass() for g in assembly.groups]


def energy_history(assembly, forces, t, Q, V, masses=None) -> EnergyHistory:
    """Energies at samples ``t`` of coordinates ``Q`` and velocities ``V`` (n_samples, n_dofs)."""
    Q, V = np.atleast_2d(Q), np.atleast_2d(V)
    masses = masses if masses is not None else element_masses(assembly)
    kin = np.concatenate([0.5 * np.einsum("tei,eij,tej->te", V[:, g.dofmap], m, V[:, g.dofmap])
                          for g, m in zip(assembly.groups, masses)], axis=1)
    strain = assembly.energy_samples(Q)
    pot = np.zeros_like(kin)
    parts = forces.element_potential(Q) if forces is not None else None
    if parts is not None:
        pot = np.concatenate(parts, axis=1)
    return EnergyHistory(np.asarray(t), kin, pot, strain.reshape(kin.shape))
