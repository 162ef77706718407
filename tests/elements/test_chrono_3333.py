"""The ANCF 3333 beam's mass matrix and gravity force against Project Chrono's stored data.

Data: ``tests/data/chrono/`` (see its README: source commit, licence, layout).  The
parameters below are those of Chrono's
``src/tests/unit_tests/fea/utest_FEA_ANCFbeam_3333_Formulation.cpp`` (line numbers
cited at each constant).  Chrono stores the mass as the compact (9, 9) matrix m,
M = m (x) I_3 (expansion at lines 239-243), and the gravity force as the full (27,)
vector; per node [r, r_y, r_z], nodes in the order A, B, C (``SetNodes`` at :180).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ancf.elements import ancf3333

DATA = Path(__file__).resolve().parents[1] / "data" / "chrono"

G = (0.0, 0.0, -9.80665)  # m/s^2, utest_FEA_ANCFbeam_3333_Formulation.cpp:132
L = 1.0                   # m, length, :150
W = 0.1                   # m, width (z, thicknessZ), :151 and SetDimensions at :181
H = 0.1                   # m, thickness (y, thicknessY), :152 and SetDimensions at :181
RHO = 7850.0              # kg/m^3, :153
RTOL = 1e-10


def _close(actual, expected, rtol=RTOL):
    """assert_allclose with rtol and an atol of rtol times the largest |expected| entry."""
    np.testing.assert_allclose(actual, expected, rtol=rtol, atol=rtol * np.abs(expected).max())


@pytest.fixture(scope="module")
def chrono_mass():
    m = np.loadtxt(DATA / "UT_ANCFBeam_3333_MassMatrix.txt")
    assert m.shape == (9, 9)
    return m


@pytest.fixture(scope="module")
def chrono_gravity():
    q = np.loadtxt(DATA / "UT_ANCFBeam_3333_Grav.txt")
    assert q.shape == (27,)
    return q


def test_mass_matches_chrono(chrono_mass):
    """Our exact Gauss mass equals Chrono's, compact and expanded to 27 x 27."""
    _close(ancf3333.scalar_mass(L, H, W, RHO), chrono_mass)
    _close(ancf3333.mass_matrix(L, H, W, RHO, ngauss=3), np.kron(chrono_mass, np.eye(3)))
    _close(ancf3333.scalar_mass(L, H, W, RHO, ngauss=5), chrono_mass)  # more points: same


def test_gravity_matches_chrono(chrono_gravity):
    _close(ancf3333.gravity(L, H, W, RHO, G), chrono_gravity)


def test_comparison_can_fail(chrono_mass, chrono_gravity):
    """A wrong density, the geometric node order A, C, B or a too-coarse rule breaks the match."""
    with pytest.raises(AssertionError):
        _close(ancf3333.mass_matrix(L, H, W, RHO * (1 + 1e-8)), np.kron(chrono_mass, np.eye(3)))
    with pytest.raises(AssertionError):
        _close(ancf3333.gravity(L, H, W, RHO * (1 + 1e-8), G), chrono_gravity)
    perm = np.array([0, 1, 2, 6, 7, 8, 3, 4, 5])  # nodes B and C swapped
    with pytest.raises(AssertionError):
        _close(ancf3333.scalar_mass(L, H, W, RHO)[np.ix_(perm, perm)], chrono_mass)
    with pytest.raises(AssertionError):
        _close(ancf3333.gravity(L, H, W, RHO, G).reshape(9, 3)[perm].ravel(), chrono_gravity)
    with pytest.raises(AssertionError):
        _close(ancf3333.scalar_mass(L, H, W, RHO, ngauss=2), chrono_mass)


def test_mass_spd_and_total_mass():
    """M is symmetric positive definite; a rigid unit translation u along each axis
    (u = 1 on that component of r_A, r_B, r_C, 0 elsewhere) carries u^T M u = rho L H W;
    the section gradients' blocks hold the section's second moments (H != W here)."""
    h, w = 0.2, 0.05  # m, distinct so r_y and r_z are told apart
    M = ancf3333.mass_matrix(L, h, w, RHO)
    assert M.shape == (27, 27)
    np.testing.assert_allclose(M, M.T, rtol=0, atol=1e-14 * np.abs(M).max())
    np.linalg.cholesky(M)  # raises unless positive definite
    assert np.linalg.eigvalsh(M).min() > 0
    mass = RHO * L * h * w  # kg
    for k in range(3):
        u = np.zeros(27)
        u[[k, 9 + k, 18 + k]] = 1.0
        assert u @ M @ u == pytest.approx(mass, rel=1e-12)
    # int rho y^2 N_A^2 dV = rho W H^3/12 * 2L/15, likewise z with W^3 H; N_C^2 gives 8L/15
    assert M[3, 3] == pytest.approx(RHO * w * h**3 / 12 * 2 * L / 15, rel=1e-12)
    assert M[6, 6] == pytest.approx(RHO * h * w**3 / 12 * 2 * L / 15, rel=1e-12)
    assert M[21, 21] == pytest.approx(RHO * w * h**3 / 12 * 8 * L / 15, rel=1e-12)
    # gravity: the node positions' entries sum to the weight rho L H W g (shares 1/6,
    # 1/6, 2/3), the section gradients' entries vanish (centroidal axis)
    q = ancf3333.gravity(L, h, w, RHO, G).reshape(9, 3)
    np.testing.assert_allclose(q[[0, 3, 6]].sum(axis=0), mass * np.asarray(G), rtol=1e-12)
    np.testing.assert_allclose(q[[0, 3, 6], 2], mass * G[2] * np.array([1, 1, 4]) / 6, rtol=1e-12)
    np.testing.assert_allclose(q[[1, 2, 4, 5, 7, 8]], 0.0, atol=1e-12 * mass)


def test_shape_interpolates_nodes():
    """S e reproduces the nodal coordinates: r at each node, and a point at (y, z) in the
    section is r + y r_y + z r_z for the identity reference gradients."""
    e = np.concatenate([[xn * L, 0, 0, 0, 1, 0, 0, 0, 1] for xn in ancf3333.NODE_XI]).astype(float)
    for xi, eta, zeta in [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.5, 0.0, 0.0),
                          (0.3, 0.25, -0.4), (0.8, -0.5, 0.5)]:
        S = ancf3333.shape(xi, eta, zeta, L, H, W)
        assert S.shape == (3, 27)
        np.testing.assert_allclose(S @ e, [xi * L, eta * H, zeta * W], atol=1e-15)
    np.testing.assert_allclose(ancf3333.lagrange(np.array(ancf3333.NODE_XI)), np.eye(3), atol=0)
