"""The ANCF 3243 beam's mass and gravity: what is its own beyond the contract tests.

The stored mass and gravity, SPD, rigid translation and weight are checked for every
element in ``test_chrono_elements.py``; parameters of Chrono's
``utest_FEA_ANCFbeam_3243_Formulation.cpp`` in ``chrono_data`` (L = 1 m, H = W = 0.1 m,
rho = 7850 kg/m^3, :150-153, ``SetDimensions(length, thicknessY, thicknessZ)`` at :180).
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.elements import ancf3243
from tests.elements.chrono_data import BY_NAME, RHO, RTOL_MASS, close, load

EL = BY_NAME["3243"]
L, H, W = EL.geometry


def test_comparison_can_fail():
    """A swapped per-node order [r_x, r] or a too-coarse rule breaks the match."""
    mass, grav = load(f"{EL.prefix}_MassMatrix", (8, 8)), load(f"{EL.prefix}_Grav", (24,))
    perm = np.array([1, 0, 2, 3, 5, 4, 6, 7])
    with pytest.raises(AssertionError):
        close(ancf3243.scalar_mass(L, H, W, RHO)[np.ix_(perm, perm)], mass, RTOL_MASS)
    with pytest.raises(AssertionError):
        close(ancf3243.scalar_mass(L, H, W, RHO, ngauss=3), mass, RTOL_MASS)


def test_section_second_moments():
    """The section gradients' blocks hold the section's second moments (H != W here):
    int rho y^2 (1 - x/L)^2 dV = rho W H^3/12 * L/3, likewise z with W^3 H."""
    h, w = 0.2, 0.05  # m, distinct so r_y and r_z are told apart
    M = ancf3243.mass_matrix(L, h, w, RHO)
    assert M[6, 6] == pytest.approx(RHO * w * h**3 / 12 * L / 3, rel=1e-12)
    assert M[9, 9] == pytest.approx(RHO * h * w**3 / 12 * L / 3, rel=1e-12)


def test_shape_interpolates_nodes():
    """S e reproduces the nodal coordinates: r at the node, and a point at (y, z) in the
    section is r + y r_y + z r_z for the identity reference gradients."""
    e = ancf3243.reference_coordinates(L)
    for xi, eta, zeta in [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.3, 0.25, -0.4), (0.8, -0.5, 0.5)]:
        S = ancf3243.shape(xi, eta, zeta, L, H, W)
        assert S.shape == (3, 24)
        np.testing.assert_allclose(S @ e, [xi * L, eta * H, zeta * W], atol=1e-15)
