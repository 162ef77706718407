"""Linear constraints by elimination: q = T z + g.

Fixed coordinates (clamp, pin, roller) and ties (q_i = q_j, e.g. a closed loop)
are eliminated; z are the independent coordinates.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp


class Elimination:
    def __init__(self, n_dofs: int):
        self.n_dofs = n_dofs
        self.fixed: dict[int, float] = {}
        self.ties: dict[int, int] = {}

    def fix(self, dofs, values) -> "Elimination":
        """Prescribe coordinates ``dofs`` to ``values``."""
        for d, v in zip(np.atleast_1d(dofs), np.broadcast_to(values, np.shape(np.atleast_1d(dofs)))):
            self.fixed[int(d)] = float(v)
        return self

    def tie(self, slave: int, master: int) -> "Elimination":
        """Require q[slave] = q[master]."""
        self.ties[int(slave)] = int(master)
        return self

    def build(self):
        """(T, g, free): q = T @ z + g with T sparse (n_dofs, n_free)."""
        dependent = set(self.fixed) | set(self.ties)
        free = np.array([i for i in range(self.n_dofs) if i not in dependent], dtype=int)
        col = {d: k for k, d in enumerate(free)}
        rows, cols = list(free), list(range(free.size))
        for s, m in self.ties.items():
            while m in self.ties:
                m = self.ties[m]
            if m in self.fixed:
                self.fixed[s] = self.fixed[m]
                continue
            rows.append(s), cols.append(col[m])
        T = sp.csr_matrix((np.ones(len(rows)), (rows, cols)), shape=(self.n_dofs, free.size))
        g = np.zeros(self.n_dofs)
        for d, v in self.fixed.items():
            g[d] = v
        return T, g, free
