"""The cable element (``ancf/elements/cable3d.py``) against Chrono's formulas for
``ChElementCableANCF`` written out independently here: the internal force of its
``ComputeInternalForces_Impl`` (axial eps S_x^T r_x, bending kappa k_e with
k_e = (f_e g - g_e f) / g^2), the closed-form consistent mass of its ``ComputeMassMatrix``
and the gravity scale of its ``SetupInitial``.  The registry's contract
(``test_registry.py``) checks its tangent against differences of this force and its energy
under rigid motion.  Tolerances: round-off, 1e-12 relative.
"""
from __future__ import annotations

import numpy as np

from ancf.core.quadrature import gauss01
from ancf.elements.cable3d import Cable3D, CircularSection

L, E, RHO = 0.25, 1.6e6, 320.0
SECTION = CircularSection(0.011)


def _cable(n=1):
    e0 = np.array([[0, 0, 0, 1, 0, 0, L, 0, 0, 1, 0, 0.0]] * n)
    return Cable3D(np.full(n, L), e0, SECTION, E, rho=RHO), e0


def _hermite(xi):
    """Chrono's S_x (1/m, -) and S_xx of xi in [0, 1] (ShapeFunctionsDerivatives*)."""
    d = np.array([(6 * xi**2 - 6 * xi) / L, 1 - 4 * xi + 3 * xi**2,
                  -(6 * xi**2 - 6 * xi) / L, -2 * xi + 3 * xi**2])
    dd = np.array([(12 * xi - 6) / L**2, (-4 + 6 * xi) / L, (6 - 12 * xi) / L**2,
                   (-2 + 6 * xi) / L])
    return d, dd


def _chrono_force(e):
    """Chrono's Fi (12,) of coordinates e: minus our Q."""
    D = e.reshape(4, 3)
    EA, EI = E * SECTION.area, E * SECTION.second_moment
    Fa = np.zeros(12)
    for xi, w in zip(*gauss01(5)):
        Sd = np.kron(_hermite(xi)[0], np.eye(3))
        a = Sd @ e
        Fa += w * (Sd.T @ a) * 0.5 * (a @ a - 1)
    Fc = np.zeros(12)
    for xi, w in zip(*gauss01(3)):
        d, dd = _hermite(xi)
        Sd, Sdd = np.kron(d, np.eye(3)), np.kron(dd, np.eye(3))
        a, b = d @ D, dd @ D
        c = np.cross(a, b)
        f, g1 = np.linalg.norm(c), np.linalg.norm(a)
        g = g1**3
        fe1 = np.cross(Sd.T, b).T + np.cross(a, Sdd.T).T
        f_e = c @ fe1 / f
        g_e = 3 * g1 * a @ Sd
        k_e = (f_e * g - g_e * f) / g**2
        Fc += w * (f / g) * k_e
    return -EA * L * Fa - EI * L * Fc


def test_force_is_minus_chronos_internal_force():
    el, e0 = _cable()
    e = e0 + 0.03 * np.random.default_rng(5).standard_normal(e0.shape)
    Q = el.gradient(e)[0][0]
    np.testing.assert_allclose(Q, -_chrono_force(e[0]), rtol=0, atol=1e-12 * np.abs(Q).max())
    assert np.abs(el.gradient(e0)[0]).max() == 0.0  # the straight reference: no force


def test_mass_and_gravity_are_chronos_closed_forms():
    el, _ = _cable()
    m = RHO * SECTION.area * L
    coef = m * np.array([[13 / 35, 11 / 210 * L, 9 / 70, -13 / 420 * L],
                         [11 / 210 * L, L**2 / 105, 13 / 420 * L, -L**2 / 140],
                         [9 / 70, 13 / 420 * L, 13 / 35, -11 / 210 * L],
                         [-13 / 420 * L, -L**2 / 140, -11 / 210 * L, L**2 / 105]])
    np.testing.assert_allclose(el.mass()[0], np.kron(coef, np.eye(3)), rtol=1e-12, atol=0)
    g = np.array([0.3, -9.8, 1.1])
    scale = m * np.array([0.5, L / 12, 0.5, -L / 12])
    np.testing.assert_allclose(el.gravity(g)[0], np.kron(scale, g), rtol=1e-12, atol=1e-15)
