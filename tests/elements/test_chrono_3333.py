"""The ANCF 3333 beam's mass and gravity: what is its own beyond the contract tests.

The stored mass and gravity, SPD, rigid translation and weight are checked for every
element in ``test_chrono_elements.py``; parameters of Chrono's
``utest_FEA_ANCFbeam_3333_Formulation.cpp`` in ``chrono_data`` (L = 1 m, H = W = 0.1 m,
rho = 7850 kg/m^3, :150-153).  Per node [r, r_y, r_z], nodes in the order A, B, C
(``SetNodes`` at :180; the compact mass expanded at :239-243).
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.elements import ancf3333
from tests.elements.chrono_data import BY_NAME, G, RHO, RTOL_MASS, close, load

EL = BY_NAME["3333"]
L, H, W = EL.geometry


def test_comparison_can_fail():
    """The geometric node order A, C, B or a too-coarse rule breaks the match."""
    mass, grav = load(f"{EL.prefix}_MassMatrix", (9, 9)), load(f"{EL.prefix}_Grav", (27,))
    perm = np.array([0, 1, 2, 6, 7, 8, 3, 4, 5])  # nodes B and C swapped
    with pytest.raises(AssertionError):
        close(ancf3333.scalar_mass(L, H, W, RHO)[np.ix_(perm, perm)], mass, RTOL_MASS)
    with pytest.raises(AssertionError):
        close(ancf3333.gravity(L, H, W, RHO, G).reshape(9, 3)[perm].ravel(), grav, RTOL_MASS)
    with pytest.raises(AssertionError):
        close(ancf3333.scalar_mass(L, H, W, RHO, ngauss=2), mass, RTOL_MASS)


def test_section_moments_and_gravity_shares():
    """The section gradients' blocks hold the section's second moments (H != W here):
    int rho y^2 N_A^2 dV = rho W H^3/12 * 2L/15, likewise z with W^3 H; N_C^2 gives 8L/15.
    Gravity: the node positions carry the shares 1/6, 1/6, 2/3 of the weight, the section
    gradients nothing (centroidal axis)."""
    h, w = 0.2, 0.05  # m, distinct so r_y and r_z are told apart
    M = ancf3333.mass_matrix(L, h, w, RHO)
    mass = RHO * L * h * w  # kg
    assert M[3, 3] == pytest.approx(RHO * w * h**3 / 12 * 2 * L / 15, rel=1e-12)
    assert M[6, 6] == pytest.approx(RHO * h * w**3 / 12 * 2 * L / 15, rel=1e-12)
    assert M[21, 21] == pytest.approx(RHO * w * h**3 / 12 * 8 * L / 15, rel=1e-12)
    q = ancf3333.gravity(L, h, w, RHO, G).reshape(9, 3)
    np.testing.assert_allclose(q[[0, 3, 6], 2], mass * G[2] * np.array([1, 1, 4]) / 6, rtol=1e-12)
    np.testing.assert_allclose(q[[1, 2, 4, 5, 7, 8]], 0.0, atol=1e-12 * mass)


def test_shape_interpolates_nodes():
    """S e reproduces the nodal coordinates: r at each node, and a point at (y, z) in the
    section is r + y r_y + z r_z for the identity reference gradients."""
    e = ancf3333.reference_coordinates(L)
    for xi, eta, zeta in [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.5, 0.0, 0.0),
                          (0.3, 0.25, -0.4), (0.8, -0.5, 0.5)]:
        S = ancf3333.shape(xi, eta, zeta, L, H, W)
        assert S.shape == (3, 27)
        np.testing.assert_allclose(S @ e, [xi * L, eta * H, zeta * W], atol=1e-15)
    np.testing.assert_allclose(ancf3333.lagrange(np.array(ancf3333.NODE_XI)), np.eye(3), atol=0)
