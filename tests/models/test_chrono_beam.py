"""ancf.models.chrono_beam.quadratic_model: the ancf3333 registry element on the beam
scenes' mesh against chrono_beam's own assembly.

Both number the 2n + 1 nodes along x with 9 coordinates [r, r_y, r_z] each, so the global
vectors coincide: at a perturbed state the assembled force and stiffness (the registry
class through ``core.assembly``) equal ``chrono_beam.assemble`` (the module's parts) to
round-off, 1e-10 of the largest entry; the mass equals the sum of the module's element
masses.  A swapped node order A, C, B breaks the agreement.
"""
from __future__ import annotations

import numpy as np

from ancf.elements.registry import ELEMENTS
from ancf.models import chrono_beam as cb

P = {"L": 2.0, "n_elements": 3, "b": 0.1, "h": 0.2, "E": 2.1e11, "nu": 0.3, "ks": 0.8,
     "rho": 7850.0}


def _models():
    t = ELEMENTS["ancf3333"]
    m, q0, asm = cb.quadratic_model(P, *t.build(P))
    beam = cb.Beam(element="3333", n=P["n_elements"], L=P["L"], H=P["h"], W=P["b"],
                   rho=P["rho"], E=P["E"], nu=P["nu"], k1=P["ks"], k2=P["ks"])
    return m, q0, asm, beam


def test_quadratic_model_is_chrono_beams_assembly():
    m, q0, asm, beam = _models()
    np.testing.assert_allclose(q0, beam.reference(), rtol=0, atol=1e-15)
    q = q0 + 1e-2 * np.random.default_rng(0).standard_normal(q0.shape)
    g, K = asm.gradient_tangent(q)
    Q, Kc = cb.assemble(beam, q)
    K = K.toarray() if hasattr(K, "toarray") else K
    np.testing.assert_allclose(g, Q, rtol=0, atol=1e-10 * np.abs(Q).max())
    np.testing.assert_allclose(K, Kc, rtol=0, atol=1e-10 * np.abs(Kc).max())
    M = asm.mass()
    M = M.toarray() if hasattr(M, "toarray") else M
    Mc = np.zeros_like(M)
    for k in range(beam.n):
        d = beam.dofs(k)
        Mc[np.ix_(d, d)] += beam.module.mass_matrix(beam.Le, beam.H, beam.W, beam.rho)
    np.testing.assert_allclose(M, Mc, rtol=0, atol=1e-12 * np.abs(Mc).max())


def test_a_wrong_node_order_is_seen():
    m, q0, asm, beam = _models()
    q = q0 + 1e-2 * np.random.default_rng(0).standard_normal(q0.shape)
    swapped = beam.dofs(0).reshape(3, -1)[[0, 2, 1]].ravel()
    Q = cb.assemble(beam, q)[0]
    q2 = q.copy()
    q2[beam.dofs(0)] = q[swapped]
    assert np.abs(asm.gradient(q2) - Q).max() > 1e-3 * np.abs(Q).max()
