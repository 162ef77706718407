"""The axial strain laws of Dufva's 2D belt element (``ancf.elements.dufva2d``,
``axial``): ``green`` (the thesis's) and ``engineering`` (Exudyn's ANCFCable2D,
N = E A alpha1 (|r_x| - 1)): exact gradient and tangent against central differences,
the force of a uniform stretch against its closed form, and the green law unchanged.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection
from ancf.elements.dufva2d import DufvaBelt2D

SECTION = RectangularSection(0.02, 0.005)
E_MOD, ALPHA1 = 2e8, 0.7


def _element(axial, n=3, L=0.6):
    m = BeamMesh(L, n, DufvaBelt2D.slots)
    q0 = m.reference()
    return m, q0, DufvaBelt2D(m.lengths, q0[m.dofmap], SECTION, E=E_MOD, nu=0.3, rho=1200.0,
                              alpha1=ALPHA1, alpha2=0.02, axial=axial)


@pytest.mark.parametrize("axial", ["green", "engineering"])
def test_gradient_and_tangent_match_central_differences(axial):
    """dU/de against differences of U and d2U/de2 against differences of dU/de (h = 1e-6)
    at a random large deformation (coordinates moved by ~0.05): within 1e-7 of the
    largest entry (the differences' error)."""
    m, q0, el = _element(axial)
    e = (q0 + 0.05 * np.random.default_rng(7).standard_normal(q0.size))[m.dofmap]
    g, K = el.gradient(e, tangent=True)
    h = 1e-6
    Fg, FK = np.zeros_like(g), np.zeros_like(K)
    for b in range(e.shape[1]):
        ep, em = e.copy(), e.copy()
        ep[:, b] += h
        em[:, b] -= h
        Fg[:, b] = (el.energy(ep) - el.energy(em)) / (2 * h)
        FK[:, :, b] = (el.gradient(ep)[0] - el.gradient(em)[0]) / (2 * h)
    assert np.abs(Fg - g).max() <= 1e-7 * np.abs(g).max()
    assert np.abs(FK - K).max() <= 1e-7 * np.abs(K).max()


@pytest.mark.parametrize("axial", ["green", "engineering"])
def test_uniform_stretch_gives_the_laws_force(axial):
    """A straight mesh stretched uniformly by lambda = 1.03 (positions and r_x scaled,
    r_y unchanged): axial_force is E A alpha1 (lambda - 1) (engineering) or
    E A alpha1 (lambda^2 - 1)/2 (green) everywhere, and the end nodes are pulled by the
    real force dU/d(length) = that force (engineering) or that force x lambda (green),
    to 1e-9 relative (round-off)."""
    lam = 1.03
    m, q0, el = _element(axial)
    Q = q0.reshape(m.n_nodes, 3, 2).copy()
    Q[:, :2, 0] *= lam
    q = Q.ravel()
    EA = E_MOD * SECTION.b * SECTION.h * ALPHA1
    N = EA * (lam - 1.0) if axial == "engineering" else EA * (lam**2 - 1.0) / 2.0
    np.testing.assert_allclose(el.axial_force(q[m.dofmap], np.linspace(0, 1, 5)), N,
                               rtol=1e-9)
    g = np.zeros(m.n_dofs)
    np.add.at(g, m.dofmap, el.gradient(q[m.dofmap])[0])
    real = N if axial == "engineering" else N * lam
    assert g[m.dof(m.n_nodes - 1, "r", 0)] == pytest.approx(real, rel=1e-9)
    assert g[m.dof(0, "r", 0)] == pytest.approx(-real, rel=1e-9)


def test_laws_agree_to_first_order_and_green_keeps_the_thesis_coefficients():
    """At a small uniform stretch (1e-6) the two laws' forces agree to 1e-6 relative; the
    green element's density coefficients are the thesis's (k0 = E A alpha1/8, no k6)."""
    m, q0, green = _element("green")
    eng = _element("engineering")[2]
    Q = q0.reshape(m.n_nodes, 3, 2).copy()
    Q[:, :2, 0] *= 1.0 + 1e-6
    e = Q.ravel()[m.dofmap]
    xi = np.linspace(0, 1, 3)
    np.testing.assert_allclose(eng.axial_force(e, xi), green.axial_force(e, xi), rtol=1e-6)
    EA = E_MOD * SECTION.b * SECTION.h * ALPHA1
    assert green.coefficients[0] == EA / 8 and green.coefficients[6] == 0.0
    assert eng.coefficients[0] == 0.0 and eng.coefficients[6] == pytest.approx(EA, rel=1e-15)


def test_unknown_law_is_refused_naming_the_field():
    m = BeamMesh(1.0, 2, DufvaBelt2D.slots)
    with pytest.raises(ValueError, match="^axial must be"):
        DufvaBelt2D(m.lengths, m.reference()[m.dofmap], SECTION, E=2e8, nu=0.3, axial="log")
