"""The ANCF 3243 beam's mass matrix and gravity force against Project Chrono's stored data.

Data: ``tests/data/chrono/`` (see its README: source commit, licence, layout).  The
parameters below are those of Chrono's
``src/tests/unit_tests/fea/utest_FEA_ANCFbeam_3243_Formulation.cpp`` (line numbers
cited at each constant).  Chrono stores the mass as the compact (8, 8) matrix m,
M = m (x) I_3, and the gravity force as the full (24,) vector.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ancf.elements import ancf3243

DATA = Path(__file__).resolve().parents[1] / "data" / "chrono"

G = (0.0, 0.0, -9.80665)  # m/s^2, utest_FEA_ANCFbeam_3243_Formulation.cpp:132
L = 1.0                   # m, length, :150
W = 0.1                   # m, width (z, thicknessZ), :151 and SetDimensions at :180
H = 0.1                   # m, thickness (y, thicknessY), :152 and SetDimensions at :180
RHO = 7850.0              # kg/m^3, :153
RTOL = 1e-10


def _close(actual, expected, rtol=RTOL):
    """assert_allclose with rtol and an atol of rtol times the largest |expected| entry."""
    np.testing.assert_allclose(actual, expected, rtol=rtol, atol=rtol * np.abs(expected).max())


@pytest.fixture(scope="module")
def chrono_mass():
    m = np.loadtxt(DATA / "UT_ANCFBeam_3243_MassMatrix.txt")
    assert m.shape == (8, 8)
    return m


@pytest.fixture(scope="module")
def chrono_gravity():
    q = np.loadtxt(DATA / "UT_ANCFBeam_3243_Grav.txt")
    assert q.shape == (24,)
    return q


def test_mass_matches_chrono(chrono_mass):
    """Our exact Gauss mass equals Chrono's, compact and expanded to 24 x 24."""
    _close(ancf3243.scalar_mass(L, H, W, RHO), chrono_mass)
    _close(ancf3243.mass_matrix(L, H, W, RHO, ngauss=4), np.kron(chrono_mass, np.eye(3)))


def test_gravity_matches_chrono(chrono_gravity):
    _close(ancf3243.gravity(L, H, W, RHO, G), chrono_gravity)


def test_comparison_can_fail(chrono_mass, chrono_gravity):
    """A wrong density, a swapped per-node order [r_x, r] or a too-coarse rule breaks the match."""
    with pytest.raises(AssertionError):
        _close(ancf3243.mass_matrix(L, H, W, RHO * (1 + 1e-8)), np.kron(chrono_mass, np.eye(3)))
    with pytest.raises(AssertionError):
        _close(ancf3243.gravity(L, H, W, RHO * (1 + 1e-8), G), chrono_gravity)
    perm = np.array([1, 0, 2, 3, 5, 4, 6, 7])
    with pytest.raises(AssertionError):
        _close(ancf3243.scalar_mass(L, H, W, RHO)[np.ix_(perm, perm)], chrono_mass)
    with pytest.raises(AssertionError):
        _close(ancf3243.scalar_mass(L, H, W, RHO, ngauss=3), chrono_mass)


def test_mass_spd_and_total_mass():
    """M is symmetric positive definite; a rigid unit translation u along each axis
    (u = 1 on that component of r_A, r_B, 0 elsewhere) carries u^T M u = rho L H W;
    the section gradients' blocks hold the section's second moments (H != W here)."""
    h, w = 0.2, 0.05  # m, distinct so r_y and r_z are told apart
    M = ancf3243.mass_matrix(L, h, w, RHO)
    assert M.shape == (24, 24)
    np.testing.assert_allclose(M, M.T, rtol=0, atol=1e-14 * np.abs(M).max())
    np.linalg.cholesky(M)  # raises unless positive definite
    assert np.linalg.eigvalsh(M).min() > 0
    mass = RHO * L * h * w  # kg
    for k in range(3):
        u = np.zeros(24)
        u[[k, 12 + k]] = 1.0
        assert u @ M @ u == pytest.approx(mass, rel=1e-12)
    # int rho y^2 (1 - x/L)^2 dV = rho W H^3/12 * L/3, likewise z with W^3 H
    assert M[6, 6] == pytest.approx(RHO * w * h**3 / 12 * L / 3, rel=1e-12)
    assert M[9, 9] == pytest.approx(RHO * h * w**3 / 12 * L / 3, rel=1e-12)
    # gravity: the node positions' entries sum to the weight, rho L H W g
    q = ancf3243.gravity(L, h, w, RHO, G)
    np.testing.assert_allclose(q[0:3] + q[12:15], mass * np.asarray(G), rtol=1e-12)


def test_shape_interpolates_nodes():
    """S e reproduces the nodal coordinates: r at the node, and a point at (y, z) in the
    section is r + y r_y + z r_z for the identity reference gradients."""
    e = np.concatenate([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1],
                        [L, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]).astype(float)
    for xi, eta, zeta in [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.3, 0.25, -0.4), (0.8, -0.5, 0.5)]:
        S = ancf3243.shape(xi, eta, zeta, L, H, W)
        assert S.shape == (3, 24)
        np.testing.assert_allclose(S @ e, [xi * L, eta * H, zeta * W], atol=1e-15)
