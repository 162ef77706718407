"""Static pre-tension of a belt drive: the laid belt settled on its pulleys.

The laid belt (nodes on the wrapped path, reference shorter than the path) is not in
equilibrium: its tension pulls it into the pulleys.  Before the run the belt is
brought to rest on the pulleys by minimising the strain energy plus the penalty
energy ``sum_g w_g k_p d_g^2 / 2`` (the frictionless, undamped part of Eq. 3.20;
no pulley turns).  Without friction the belt could slide round the pulleys as a
rigid body (and in 3D along their axes), so those motions are removed by fixing the
drive's ``fixed_dofs``: the coordinate of node 0 along the path's tangent (the
two-pulley path is symmetric about the line of centres, node 0 sits on it and the
fixed force is zero at the symmetric equilibrium) and, in 3D, node 0's axial one.  The dynamics then starts from a settled belt, as Exudyn's examples
do, instead of from the impact of the laid belt on the pulleys.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ancf.core.constraints import Elimination
from ancf.core.pattern import ReducedPattern, scatter
from ancf.solvers.minimize import minimize


def settle(drive, rtol=1e-9, max_iter=100):
    """(x0 system vector at rest on the pulleys, MinimizeResult).  The drive supplies
    ``dofmap``, ``n_dofs``, ``q0``, ``element``, ``element_coords(q)``,
    ``fixed_dofs()`` (the rigid motions the frictionless pulleys leave free) and
    ``penalty(E, want_J)`` -> (penalty energy, Q, dQ/de) at rest."""
    dm, el = drive.dofmap, drive.element
    nel = dm.shape[0]
    fixed = drive.fixed_dofs()
    elim = Elimination(drive.n_dofs).fix(fixed, drive.q0[fixed])
    T, g, _ = elim.build()
    pat = ReducedPattern(drive.n_dofs, [dm], sp.csr_matrix(T))
    vidx, midx = pat.groups[0]

    def energy(z):
        E = drive.element_coords(pat.expand(z, g))
        return float(el.energy(E.reshape(nel, -1)).sum() + drive.penalty(E, False)[0])

    def grad_tangent(z):
        E = drive.element_coords(pat.expand(z, g))
        ge, Ke = el.gradient(E.reshape(nel, -1), tangent=True)
        _, Q, Kq = drive.penalty(E, True)
        vec, mat = np.zeros(pat.n), pat.zeros_matrix()
        scatter(ge - Q, Ke - Kq, vidx, midx, vec, mat, True)
        return vec, mat

    out = minimize(energy, grad_tangent, pat.restrict(drive.q0), pat.kl, rtol=rtol,
                   max_iter=max_iter)
    return drive.state(pat.expand(out.z, g)), out
