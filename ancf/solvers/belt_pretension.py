"""Static pre-tension of a belt drive: the laid belt settled on its pulleys.

The laid belt (nodes on the wrapped path, reference shorter than the path) is not in
equilibrium: its tension pulls it into the pulleys.  Before the run the belt is
brought to rest on the pulleys by minimising the strain energy plus the penalty
energy ``sum_g w_g k_p d_g^2 / 2`` (the frictionless, undamped part of Eq. 3.20;
no pulley turns).  Without friction the belt could slide round the pulleys as a
rigid body, so that one motion is removed by fixing the coordinate of node 0 along
the path's tangent there (the two-pulley path is symmetric about the line of
centres, node 0 sits on it and the fixed force is zero at the symmetric
equilibrium).  The dynamics then starts from a settled belt, as Exudyn's examples
do, instead of from the impact of the laid belt on the pulleys.
"""
from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ancf.contact import contact_forces, contact_state
from ancf.constraints import Elimination
from ancf.pattern import ReducedPattern, scatter
from ancf.solvers.minimize import minimize


def _fixed(drive):
    """Global index of node 0's coordinate along the path tangent (the larger component)."""
    t = drive.q0[2:4]
    return drive.mesh.dof(0, "r", int(np.argmax(np.abs(t))))


def settle(drive, rtol=1e-9, max_iter=100):
    """(x0 system vector at rest on the pulleys, MinimizeResult)."""
    mesh, el = drive.mesh, drive.element
    dm, nel = mesh.dofmap, mesh.n_elements
    frictionless = drive.prm.copy()
    frictionless[1:] = 0.0
    elim = Elimination(mesh.n_dofs).fix([_fixed(drive)], drive.q0[[_fixed(drive)]])
    T, g, _ = elim.build()
    pat = ReducedPattern(mesh.n_dofs, [dm], sp.csr_matrix(T))
    vidx, midx = pat.groups[0]
    zero_v = np.zeros((nel, 6, 2))
    omegas = np.zeros(2)

    def coords(z):
        return pat.expand(z, g)[dm].reshape(nel, 6, 2)

    def energy(z):
        E = coords(z)
        _, d, _, _, _ = contact_state(E, zero_v, drive.S0, drive.centres, drive.radii, omegas,
                                      frictionless)
        pen = np.maximum(d, 0.0)
        return float(el.energy(E.reshape(nel, 12)).sum()
                     + 0.5 * drive.spec.k_p * np.einsum("eg,egp->", drive.w, pen**2))

    def grad_tangent(z):
        E = coords(z)
        ge, Ke = el.gradient(E.reshape(nel, 12), tangent=True)
        Q, Kq = np.zeros((nel, 12)), np.zeros((nel, 12, 12))
        contact_forces(E, zero_v, drive.S0, drive.w, drive.centres, drive.radii, omegas,
                       frictionless, True, Q, Kq, np.zeros_like(Kq), np.zeros((nel, 2, 12)),
                       np.zeros(2), np.zeros((2, nel, 12)), np.zeros((2, nel, 12)), np.zeros(2))
        vec, mat = np.zeros(pat.n), pat.zeros_matrix()
        scatter(ge - Q, Ke - Kq, vidx, midx, vec, mat, True)
        return vec, mat

    out = minimize(energy, grad_tangent, pat.restrict(drive.q0), pat.kl, rtol=rtol,
                   max_iter=max_iter)
    return drive.state(pat.expand(out.z, g)), out
