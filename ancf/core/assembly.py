"""Assembly of element groups into global energy, forces, tangent and mass (the sparse
matrices load scipy on first use: a solve on a reduced pattern needs none)."""
from __future__ import annotations

import numpy as np


class ElementGroup:
    """One element object with its DOF map (nel, ndof_e) into the global vector."""

    def __init__(self, element, dofmap):
        self.element, self.dofmap = element, np.asarray(dofmap)
        n = self.dofmap.shape[1]
        self.rows = np.repeat(self.dofmap, n, axis=1).ravel()
        self.cols = np.tile(self.dofmap, (1, n)).ravel()


class Assembly:
    """Sum of element groups over ``n_dofs`` global nodal coordinates."""

    def __init__(self, n_dofs: int, groups):
        self.n_dofs, self.groups = n_dofs, list(groups)

    def energies(self, q) -> list:
        """Strain energy per element for each group, J."""
        return [g.element.energy(q[g.dofmap]) for g in self.groups]

    def energy_samples(self, Q) -> np.ndarray:
        """Strain energy per element at each state of ``Q`` (ns, n_dofs), (ns, nel) J, the
        groups side by side as in :meth:`energies`; an element with ``energy_samples``
        takes all states in one call, any other one state at a time."""
        out = []
        for g in self.groups:
            E = Q[:, g.dofmap]
            if hasattr(g.element, "energy_samples"):
                out.append(g.element.energy_samples(E))
            else:
                out.append(np.array([g.element.energy(e) for e in E]).reshape(len(Q), -1))
        return np.concatenate(out, axis=1)

    def strain_energy(self, q) -> float:
        return float(sum(u.sum() for u in self.energies(q)))

    def gradient(self, q) -> np.ndarray:
        """dU/dq (the elastic forces are Qe = -dU/dq)."""
        out = np.zeros(self.n_dofs)
        for g in self.groups:
            ge, _ = g.element.gradient(q[g.dofmap])
            np.add.at(out, g.dofmap, ge)
        return out

    def gradient_tangent(self, q):
        """dU/dq and the sparse tangent d2U/dq2 (CSR)."""
        out = np.zeros(self.n_dofs)
        rows, cols, vals = [], [], []
        for g in self.groups:
            ge, Ke = g.element.gradient(q[g.dofmap], tangent=True)
            np.add.at(out, g.dofmap, ge)
            rows.append(g.rows), cols.append(g.cols), vals.append(Ke.ravel())
        import scipy.sparse as sp
        K = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                          shape=(self.n_dofs, self.n_dofs))
        return out, K

    def mass(self):
        """Constant sparse mass matrix (CSR), kg."""
        rows, cols, vals = [], [], []
        for g in self.groups:
            rows.append(g.rows), cols.append(g.cols), vals.append(g.element.mass().ravel())
        import scipy.sparse as sp
        return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                             shape=(self.n_dofs, self.n_dofs))
