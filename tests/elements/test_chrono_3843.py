"""The ANCF 3843 brick's mass matrix and gravity force against Project Chrono's stored data.

Data: ``tests/data/chrono/`` (see its README: source commit, licence, layout).  The
parameters below are those of Chrono's
``src/tests/unit_tests/fea/utest_FEA_ANCFhexa_3843_Formulation.cpp`` (line numbers
cited at each constant).  Chrono stores the mass as the compact (32, 32) matrix m,
M = m (x) I_3, and the gravity force as the full (96,) vector.

Chrono's element is a unit cube, so its files cannot tell Lx, Ly, Lz apart; the
analytic tests below use three distinct edge lengths for that.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ancf.elements import ancf3843

DATA = Path(__file__).resolve().parents[1] / "data" / "chrono"

G = (0.0, 0.0, -9.80665)  # m/s^2, utest_FEA_ANCFhexa_3843_Formulation.cpp:132
LX = 1.0                  # m, length (x), :152; SetDimensions(length, width, height) at :190
LY = 1.0                  # m, width (y; node C at (length, width, 0), :175), :153
LZ = 1.0                  # m, height (z; node E at (0, 0, height), :179), :154
RHO = 7850.0              # kg/m^3, :155
RTOL = 1e-10


def _close(actual, expected, rtol=RTOL):
    """assert_allclose with rtol and an atol of rtol times the largest |expected| entry."""
    np.testing.assert_allclose(actual, expected, rtol=rtol, atol=rtol * np.abs(expected).max())


@pytest.fixture(scope="module")
def chrono_mass():
    m = np.loadtxt(DATA / "UT_ANCFBrick_3843_MassMatrix.txt")
    assert m.shape == (32, 32)
    return m


@pytest.fixture(scope="module")
def chrono_gravity():
    q = np.loadtxt(DATA / "UT_ANCFBrick_3843_Grav.txt")
    assert q.shape == (96,)
    return q


def test_mass_matches_chrono(chrono_mass):
    """Our exact Gauss mass equals Chrono's, compact and expanded to 96 x 96."""
    _close(ancf3843.scalar_mass(LX, LY, LZ, RHO), chrono_mass)
    _close(ancf3843.mass_matrix(LX, LY, LZ, RHO, ngauss=4), np.kron(chrono_mass, np.eye(3)))


def test_gravity_matches_chrono(chrono_gravity):
    _close(ancf3843.gravity(LX, LY, LZ, RHO, G), chrono_gravity)


def test_comparison_can_fail(chrono_mass, chrono_gravity):
    """A wrong density, a swapped per-node order [r_x, r], a wrong node order or a
    too-coarse rule breaks the match."""
    with pytest.raises(AssertionError):
        _close(ancf3843.mass_matrix(LX, LY, LZ, RHO * (1 + 1e-8)), np.kron(chrono_mass, np.eye(3)))
    with pytest.raises(AssertionError):
        _close(ancf3843.gravity(LX, LY, LZ, RHO * (1 + 1e-8), G), chrono_gravity)
    m = ancf3843.scalar_mass(LX, LY, LZ, RHO)
    swap = np.arange(32).reshape(8, 4)[:, [1, 0, 2, 3]].ravel()
    with pytest.raises(AssertionError):
        _close(m[np.ix_(swap, swap)], chrono_mass)
    nodes = np.arange(32).reshape(8, 4)[[0, 1, 3, 2, 4, 5, 7, 6]].ravel()  # C <-> D, G <-> H
    with pytest.raises(AssertionError):
        _close(m[np.ix_(nodes, nodes)], chrono_mass)
    with pytest.raises(AssertionError):
        _close(ancf3843.scalar_mass(LX, LY, LZ, RHO, ngauss=3), chrono_mass)


def _reference_coordinates(lx, ly, lz):
    """The undeformed e (96,): node positions at the box corners, gradients = identity."""
    corners = (1.0 + ancf3843.NODE_SIGNS) / 2.0 * np.array([lx, ly, lz])
    return np.concatenate([np.concatenate([c, [1, 0, 0], [0, 1, 0], [0, 0, 1]]) for c in corners])


DIMS = (2.0, 0.5, 0.25)  # m, distinct so Lx, Ly, Lz are told apart


def test_mass_spd_and_total_mass():
    """M is symmetric positive definite; a rigid unit translation along each axis
    (1 on that component of every node position, 0 elsewhere) carries u^T M u =
    rho Lx Ly Lz; the reference configuration e0 (r = x exactly) gives
    e0_k^T m e0_k = int rho x_k^2 dV = rho V L_k^2 / 3 on each axis k."""
    lx, ly, lz = DIMS
    M = ancf3843.mass_matrix(lx, ly, lz, RHO)
    assert M.shape == (96, 96)
    np.testing.assert_allclose(M, M.T, rtol=0, atol=1e-14 * np.abs(M).max())
    np.linalg.cholesky(M)  # raises unless positive definite
    assert np.linalg.eigvalsh(M).min() > 0
    mass = RHO * lx * ly * lz  # kg
    for k in range(3):
        u = np.zeros(96)
        u[12 * np.arange(8) + k] = 1.0
        assert u @ M @ u == pytest.approx(mass, rel=1e-12)
    e0 = _reference_coordinates(lx, ly, lz)
    for k, length in enumerate(DIMS):
        ek = np.zeros(96)
        ek[k::3] = e0[k::3]
        assert ek @ M @ ek == pytest.approx(mass * length**2 / 3.0, rel=1e-12)


def test_gravity_sums_to_weight():
    """The node positions' entries of Q_g sum to the weight rho Lx Ly Lz g."""
    lx, ly, lz = DIMS
    q = ancf3843.gravity(lx, ly, lz, RHO, G).reshape(8, 4, 3)
    np.testing.assert_allclose(q[:, 0, :].sum(axis=0), RHO * lx * ly * lz * np.asarray(G),
                               rtol=1e-12, atol=1e-9)


def test_shape_interpolates_nodes():
    """S e0 reproduces the reference position x = L (1 + xi)/2 at nodes and inside, and
    the scalar functions are the Kronecker deltas / unit slopes at the nodes."""
    lx, ly, lz = DIMS
    e0 = _reference_coordinates(lx, ly, lz)
    pts = [tuple(s) for s in ancf3843.NODE_SIGNS] + [(0.0, 0.0, 0.0), (0.3, -0.7, 0.9)]
    for xi, eta, zeta in pts:
        S = ancf3843.shape(xi, eta, zeta, lx, ly, lz)
        assert S.shape == (3, 96)
        expected = np.array([lx * (1 + xi), ly * (1 + eta), lz * (1 + zeta)]) / 2.0
        np.testing.assert_allclose(S @ e0, expected, atol=1e-14)
    h = 1e-6  # central differences in natural coordinates; d/dx_k = (2/L_k) d/dxi_k
    for n, sgn in enumerate(ancf3843.NODE_SIGNS):
        s = ancf3843.scalar_shape(*sgn, lx, ly, lz)
        np.testing.assert_allclose(s, np.eye(32)[4 * n], atol=1e-15)
        for k, length in enumerate(DIMS):
            dp, dm = sgn.copy(), sgn.copy()
            dp[k] += h
            dm[k] -= h
            ds = (ancf3843.scalar_shape(*dp, lx, ly, lz)
                  - ancf3843.scalar_shape(*dm, lx, ly, lz)) / (2 * h) * 2.0 / length
            np.testing.assert_allclose(ds, np.eye(32)[4 * n + 1 + k], atol=1e-8)
