"""The ANCF shells' mass matrices and gravity forces against Project Chrono's stored data.

Data: ``tests/data/chrono/`` (see its README: source commit, licence, layout).  The
parameters are those of Chrono's ``src/tests/unit_tests/fea/utest_FEA_ANCFshell_3443_Formulation.cpp``
and ``..._3833_Formulation.cpp`` (line numbers cited at each constant; the two set up the
same 1 m x 1 m x 0.01 m steel plate).  Chrono stores each mass as the compact matrix m over
the scalar shape functions, M = m (x) I_3, and the gravity force as the full vector.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ancf.elements import ancf3443, ancf3833

DATA = Path(__file__).resolve().parents[1] / "data" / "chrono"

G = (0.0, 0.0, -9.80665)  # m/s^2, utest_FEA_ANCFshell_3443_Formulation.cpp:140 (3833: :140)
L = 1.0                   # m, length (x, lenX), 3443 :160 and SetDimensions at :191
W = 1.0                   # m, width (y, lenY), 3443 :161 and SetDimensions at :191
H = 0.01                  # m, thickness (z), 3443 :162, one layer via AddLayer at :192
RHO = 7850.0              # kg/m^3, 3443 :163
RTOL = 1e-10


def _close(actual, expected, rtol=RTOL):
    """assert_allclose with rtol and an atol of rtol times the largest |expected| entry."""
    np.testing.assert_allclose(actual, expected, rtol=rtol, atol=rtol * np.abs(expected).max())


def _close_scaled(actual, expected, d, rtol=RTOL):
    """_close on the dimensionless D a D (matrix) or D a (vector), D = diag(d): each
    gradient coordinate divided by its length scale, so that the small r_z (and r_zz)
    entries are held to rtol of the largest entry too, not lost under its atol."""
    d = np.asarray(d, dtype=float)
    if np.ndim(expected) == 2:
        _close(d[:, None] * actual * d[None, :], d[:, None] * expected * d[None, :], rtol)
    else:
        _close(d * actual, d * expected, rtol)


def _load(name, shape):
    a = np.loadtxt(DATA / name)
    assert a.shape == shape
    return a


def _check_spd_and_rigid(M, q, nshape, position_rows, mass):
    """M (3 nshape square) symmetric positive definite; a rigid unit translation along
    each axis (1 on that component of every node position, 0 elsewhere) carries
    u^T M u = mass; the gravity entries of the node positions add up to mass * g."""
    n = 3 * nshape
    assert M.shape == (n, n) and q.shape == (n,)
    np.testing.assert_allclose(M, M.T, rtol=0, atol=1e-14 * np.abs(M).max())
    np.linalg.cholesky(M)  # raises unless positive definite
    assert np.linalg.eigvalsh(M).min() > 0
    for k in range(3):
        u = np.zeros(n)
        u[3 * np.asarray(position_rows) + k] = 1.0
        assert u @ M @ u == pytest.approx(mass, rel=1e-12)
        assert q[3 * np.asarray(position_rows) + k].sum() == pytest.approx(mass * G[k], rel=1e-12, abs=1e-12)


# ----------------------------------------------------------------------------- ANCF 3443


@pytest.fixture(scope="module")
def mass3443():
    return _load("UT_ANCFShell_3443_MassMatrix.txt", (16, 16))


@pytest.fixture(scope="module")
def grav3443():
    return _load("UT_ANCFShell_3443_Grav.txt", (48,))


def test_3443_mass_matches_chrono(mass3443):
    """Our exact Gauss mass equals Chrono's, compact and expanded to 48 x 48
    (expansion as at 3443 .cpp:254-258, matrix from ComputeKRMmatricesGlobal(M, 0, 0, 1) at :267)."""
    _close(ancf3443.scalar_mass(L, W, H, RHO), mass3443)
    _close(ancf3443.mass_matrix(L, W, H, RHO), np.kron(mass3443, np.eye(3)))


def test_3443_gravity_matches_chrono(grav3443):
    """ComputeGravityForces at 3443 .cpp:317."""
    _close(ancf3443.gravity(L, W, H, RHO, G), grav3443)


D3443 = np.tile([1.0, 1.0 / L, 1.0 / W, 2.0 / H], 4)  # 1, 1/m: r, r_x, r_y, r_z per node


def test_3443_matches_chrono_entrywise_scaled(mass3443, grav3443):
    """The r_z entries (7e-5 kg m^2 against 10.8 kg) are matched to rtol as well."""
    _close_scaled(ancf3443.scalar_mass(L, W, H, RHO), mass3443, D3443)
    _close_scaled(ancf3443.gravity(L, W, H, RHO, G), grav3443, np.repeat(D3443, 3))


def test_3443_comparison_can_fail(mass3443, grav3443):
    """A wrong density, a wrong thickness, a swapped per-node order [r_x, r] or a
    too-coarse in-plane rule breaks the match."""
    with pytest.raises(AssertionError):
        _close(ancf3443.scalar_mass(L, W, H, RHO * (1 + 1e-8)), mass3443)
    with pytest.raises(AssertionError):
        _close(ancf3443.gravity(L, W, H, RHO * (1 + 1e-8), G), grav3443)
    with pytest.raises(AssertionError):
        _close(ancf3443.scalar_mass(L, W, 2 * H, RHO / 2), mass3443)  # same rho H, other r_z rows
    perm = np.arange(16).reshape(4, 4)[:, [1, 0, 2, 3]].ravel()
    with pytest.raises(AssertionError):
        _close(ancf3443.scalar_mass(L, W, H, RHO)[np.ix_(perm, perm)], mass3443)
    with pytest.raises(AssertionError):
        _close(ancf3443.scalar_mass(L, W, H, RHO, n_plane=3), mass3443)


def test_3443_spd_rigid_translation_and_weight():
    """Distinct L, W, H so that r_x, r_y and r_z are told apart."""
    lx, wy, hz = 0.8, 0.5, 0.02  # m
    M = ancf3443.mass_matrix(lx, wy, hz, RHO)
    q = ancf3443.gravity(lx, wy, hz, RHO, G)
    _check_spd_and_rigid(M, q, 16, [0, 4, 8, 12], RHO * lx * wy * hz)
    # r_z block of node A: int rho z^2 (bilinear_A)^2 dV = rho H^3/12 * L W / 9
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
    _check_spd_and_rigid(M, q, 16, [0, 4, 8, 12], sum(t * r for t, r in lam) * L * W)


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


@pytest.fixture(scope="module")
def mass3833():
    return _load("UT_ANCFShell_3833_MassMatrix.txt", (24, 24))


@pytest.fixture(scope="module")
def grav3833():
    return _load("UT_ANCFShell_3833_Grav.txt", (72,))


def test_3833_mass_matches_chrono(mass3833):
    """Compact and expanded to 72 x 72 (expansion as at 3833 .cpp:260-264, matrix from
    ComputeKRMmatricesGlobal(M, 0, 0, 1) at :273), and entrywise after scaling."""
    m = ancf3833.scalar_mass(L, W, H, RHO)
    _close(m, mass3833)
    _close(ancf3833.mass_matrix(L, W, H, RHO), np.kron(mass3833, np.eye(3)))
    _close_scaled(m, mass3833, D3833)


def test_3833_gravity_matches_chrono(grav3833):
    """ComputeGravityForces at 3833 .cpp:323; the corner nodes' r entries are positive
    under g along -z (the serendipity corner functions integrate to -1/12 of the area)."""
    q = ancf3833.gravity(L, W, H, RHO, G)
    _close(q, grav3833)
    _close_scaled(q, grav3833, np.repeat(D3833, 3))


def test_3833_comparison_can_fail(mass3833, grav3833):
    """A wrong density, a wrong thickness, a swapped per-node order [r_z, r, r_zz] or a
    too-coarse rule breaks the match.  A 2-point thickness rule errs only in the r_zz
    block (1.4e-11 of the largest entry): the scaled comparison catches it."""
    with pytest.raises(AssertionError):
        _close(ancf3833.scalar_mass(L, W, H, RHO * (1 + 1e-8)), mass3833)
    with pytest.raises(AssertionError):
        _close(ancf3833.gravity(L, W, H, RHO * (1 + 1e-8), G), grav3833)
    with pytest.raises(AssertionError):
        _close_scaled(ancf3833.scalar_mass(L, W, 2 * H, RHO / 2), mass3833, D3833)
    perm = np.arange(24).reshape(8, 3)[:, [1, 0, 2]].ravel()
    with pytest.raises(AssertionError):
        _close(ancf3833.scalar_mass(L, W, H, RHO)[np.ix_(perm, perm)], mass3833)
    with pytest.raises(AssertionError):
        _close(ancf3833.scalar_mass(L, W, H, RHO, n_plane=2), mass3833)
    with pytest.raises(AssertionError):
        _close_scaled(ancf3833.scalar_mass(L, W, H, RHO, n_thick=2), mass3833, D3833)


def test_3833_spd_rigid_translation_and_weight():
    lx, wy, hz = 0.8, 0.5, 0.02  # m
    M = ancf3833.mass_matrix(lx, wy, hz, RHO)
    q = ancf3833.gravity(lx, wy, hz, RHO, G)
    _check_spd_and_rigid(M, q, 24, list(range(0, 24, 3)), RHO * lx * wy * hz)
    # r_z block of mid-side node E: int rho z^2 N_E^2 dV = rho H^3/12 * L W * 8/45
    assert M[3 * 13, 3 * 13] == pytest.approx(RHO * hz**3 / 12 * lx * wy * 8 / 45, rel=1e-12)


def test_3833_layers_add_up():
    one = ancf3833.scalar_mass(L, W, H, RHO)
    two = ancf3833.scalar_mass(L, W, H, RHO, layers=[(0.3 * H, RHO), (0.7 * H, RHO)])
    _close_scaled(two, one, D3833, rtol=1e-13)
    lam = [(0.004, 7850.0), (0.006, 2700.0)]
    M = ancf3833.mass_matrix(L, W, H, RHO, layers=lam)
    q = ancf3833.gravity(L, W, H, RHO, G, layers=lam)
    _check_spd_and_rigid(M, q, 24, list(range(0, 24, 3)), sum(t * r for t, r in lam) * L * W)


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
