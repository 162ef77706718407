"""The ANCF shells' mass matrices and gravity forces: their own checks.

Data: ``tests/data/chrono/`` (see its README: source commit, licence, layout).  The stored
mass and gravity (raw and length-scaled), SPD, rigid translation and weight are checked
for every element in ``test_chrono_elements.py`` (parameters in ``chrono_data``; Chrono's
``utest_FEA_ANCFshell_3443_Formulation.cpp`` and ``..._3833_...`` set up the same
1 m x 1 m x 0.01 m steel plate).  Here: what is the shells' own (planted changes, the
layers, the node layouts, the transverse moments).
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.elements import ancf3443, ancf3833
from tests.elements.chrono_data import G, RHO, RTOL_MASS, check_mass_and_weight, close, load

L, W, H = 1.0, 1.0, 0.01  # m, 3443 :160-162, SetDimensions(lenX, lenY) :191, one AddLayer :192


def _close(actual, expected, rtol=RTOL_MASS):
    close(actual, expected, rtol)


def _close_scaled(actual, expected, d, rtol=RTOL_MASS):
    """``close`` on the dimensionless D a D (matrix) or D a (vector) only, D = diag(d)."""
    d = np.asarray(d, dtype=float)
    d2 = d if np.ndim(expected) == 1 else np.outer(d, d)
    close(d2 * actual, d2 * expected, rtol)


# ----------------------------------------------------------------------------- ANCF 3443


def test_3443_comparison_can_fail():
    """A wrong thickness, a swapped per-node order [r_x, r] or a too-coarse in-plane rule
    breaks the match (a wrong density: ``test_chrono_elements``)."""
    mass3443 = load("UT_ANCFShell_3443_MassMatrix", (16, 16))
    with pytest.raises(AssertionError):
        _close(ancf3443.scalar_mass(L, W, 2 * H, RHO / 2), mass3443)  # same rho H, other r_z rows
    perm = np.arange(16).reshape(4, 4)[:, [1, 0, 2, 3]].ravel()
    with pytest.raises(AssertionError):
        _close(ancf3443.scalar_mass(L, W, H, RHO)[np.ix_(perm, perm)], mass3443)
    with pytest.raises(AssertionError):
        _close(ancf3443.scalar_mass(L, W, H, RHO, n_plane=3), mass3443)


def test_3443_transverse_moment():
    """r_z block of node A: int rho z^2 (bilinear_A)^2 dV = rho H^3/12 * L W / 9."""
    lx, wy, hz = 0.8, 0.5, 0.02  # m, distinct so that r_x, r_y and r_z are told apart
    M = ancf3443.mass_matrix(lx, wy, hz, RHO)
    assert M[9, 9] == pytest.approx(RHO * hz**3 / 12 * lx * wy / 9, rel=1e-12)


def test_3443_layers_add_up():
    """Through-thickness integration over layers: two layers of the same density give
    the single-layer mass; a laminate's total mass is sum rho_k t_k L W."""
    one = ancf3443.scalar_mass(L, W, H, RHO)
    two = ancf3443.scalar_mass(L, W, H, RHO, layers=[(0.3 * H, RHO), (0.7 * H, RHO)])
    _close(two, one, rtol=1e-13)
    lam = [(0.004, 7850.0), (0.006, 2700.0)]
    M = ancf3443.mass_matrix(L, W, H, RHO, layers=lam)
    q = ancf3443.gravity(L, W, H, RHO, G, layers=lam)
    check_mass_and_weight(M, q, [0, 4, 8, 12], sum(t * r for t, r in lam) * L * W)


def test_3443_shape_interpolates_nodes():
    """S e reproduces the reference geometry for identity gradients: the point at
    (xi, eta, z) is ((xi + 1) L/2, (eta + 1) W/2, z); each node's r_x, r_y are the slopes."""
    lx, wy = 0.8, 0.5
    e = np.concatenate([np.concatenate([[(x + 1) * lx / 2, (y + 1) * wy / 2, 0], np.eye(3).ravel()])
                        for x, y in zip(ancf3443.NODE_XI, ancf3443.NODE_ETA)])
    for xi, eta, z in [(-1, -1, 0), (1, 1, 0), (0.3, -0.6, 0.004), (-0.8, 0.5, -0.01)]:
        S = ancf3443.shape(xi, eta, z, lx, wy)
        assert S.shape == (3, 48)
        np.testing.assert_allclose(S @ e, [(xi + 1) * lx / 2, (eta + 1) * wy / 2, z], atol=1e-15)


# ----------------------------------------------------------------------------- ANCF 3833
# Same plate: utest_FEA_ANCFshell_3833_Formulation.cpp lines 140 (g), 160-163 (L, W, H, rho),
# 174-175 (r_z = (0, 0, 1), r_zz = 0 at every node), 177-192 (nodes A..H), 196-198
# (SetNodes, SetDimensions(length, width), AddLayer(thickness, 0, material)).

D3833 = np.tile([1.0, 2.0 / H, 8.0 / H**2], 8)  # 1, 1/m, 1/m^2: r, r_z, r_zz per node


def test_3833_corner_gravity_points_up():
    """Under g along -z the corner nodes' r_z entries are positive (in ours and Chrono's):
    the serendipity corner functions integrate to -1/12 of the area."""
    q = ancf3833.gravity(L, W, H, RHO, G).reshape(8, 3, 3)
    grav3833 = load("UT_ANCFShell_3833_Grav", (72,))
    assert (q[:4, 0, 2] > 0).all() and (grav3833.reshape(8, 3, 3)[:4, 0, 2] > 0).all()
    np.testing.assert_allclose(q[:4, 0, 2], -RHO * L * W * H * G[2] / 12, rtol=1e-12)


def test_3833_comparison_can_fail():
    """A wrong thickness, a swapped per-node order [r_z, r, r_zz] or a
    too-coarse rule breaks the match.  A 2-point thickness rule errs only in the r_zz
    block (1.4e-11 of the largest entry): the scaled comparison catches it.  (A wrong
    density: ``test_chrono_elements``.)"""
    mass3833 = load("UT_ANCFShell_3833_MassMatrix", (24, 24))
    with pytest.raises(AssertionError):
        _close_scaled(ancf3833.scalar_mass(L, W, 2 * H, RHO / 2), mass3833, D3833)
    perm = np.arange(24).reshape(8, 3)[:, [1, 0, 2]].ravel()
    with pytest.raises(AssertionError):
        _close(ancf3833.scalar_mass(L, W, H, RHO)[np.ix_(perm, perm)], mass3833)
    with pytest.raises(AssertionError):
        _close(ancf3833.scalar_mass(L, W, H, RHO, n_plane=2), mass3833)
    with pytest.raises(AssertionError):
        _close_scaled(ancf3833.scalar_mass(L, W, H, RHO, n_thick=2), mass3833, D3833)


def test_3833_transverse_moment():
    """r_z block of mid-side node E: int rho z^2 N_E^2 dV = rho H^3/12 * L W * 8/45."""
    lx, wy, hz = 0.8, 0.5, 0.02  # m
    M = ancf3833.mass_matrix(lx, wy, hz, RHO)
    assert M[3 * 13, 3 * 13] == pytest.approx(RHO * hz**3 / 12 * lx * wy * 8 / 45, rel=1e-12)


def test_3833_layers_add_up():
    one = ancf3833.scalar_mass(L, W, H, RHO)
    two = ancf3833.scalar_mass(L, W, H, RHO, layers=[(0.3 * H, RHO), (0.7 * H, RHO)])
    _close_scaled(two, one, D3833, rtol=1e-13)
    lam = [(0.004, 7850.0), (0.006, 2700.0)]
    M = ancf3833.mass_matrix(L, W, H, RHO, layers=lam)
    q = ancf3833.gravity(L, W, H, RHO, G, layers=lam)
    check_mass_and_weight(M, q, list(range(0, 24, 3)), sum(t * r for t, r in lam) * L * W)


def test_3833_shape_interpolates_nodes():
    """S e reproduces the reference geometry for r_z = (0, 0, 1), r_zz = 0 at every node:
    the point at (xi, eta, z) is ((xi + 1) L/2, (eta + 1) W/2, z); N_i(node j) = delta_ij."""
    lx, wy = 0.8, 0.5
    np.testing.assert_allclose(ancf3833.serendipity(ancf3833.NODE_XI, ancf3833.NODE_ETA),
                               np.eye(8), atol=1e-15)
    e = np.concatenate([[(x + 1) * lx / 2, (y + 1) * wy / 2, 0, 0, 0, 1, 0, 0, 0]
                        for x, y in zip(ancf3833.NODE_XI, ancf3833.NODE_ETA)])
    for xi, eta, z in [(-1, -1, 0), (0, 1, 0), (0.3, -0.6, 0.004), (-0.8, 0.5, -0.01)]:
        S = ancf3833.shape(xi, eta, z)
        assert S.shape == (3, 72)
        np.testing.assert_allclose(S @ e, [(xi + 1) * lx / 2, (eta + 1) * wy / 2, z], atol=1e-15)
