"""The ANCF 3843 brick's mass and gravity: what is its own beyond the contract tests.

The stored mass and gravity, SPD, rigid translation and weight (at distinct edge lengths)
are checked for every element in ``test_chrono_elements.py``; parameters of Chrono's
``utest_FEA_ANCFhexa_3843_Formulation.cpp`` in ``chrono_data`` (a unit cube, :152-154,
rho = 7850 kg/m^3, :155).  Chrono's element is a unit cube, so its files cannot tell
Lx, Ly, Lz apart; the analytic tests below use three distinct edge lengths for that.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.elements import ancf3843
from tests.elements.chrono_data import BY_NAME, RHO, RTOL_MASS, close, load

EL = BY_NAME["3843"]
LX, LY, LZ = EL.geometry
DIMS = (2.0, 0.5, 0.25)  # m, distinct so Lx, Ly, Lz are told apart


def test_comparison_can_fail():
    """A swapped per-node order [r_x, r], a wrong node order or a
    too-coarse rule breaks the match."""
    mass, grav = load(f"{EL.prefix}_MassMatrix", (32, 32)), load(f"{EL.prefix}_Grav", (96,))
    m = ancf3843.scalar_mass(LX, LY, LZ, RHO)
    swap = np.arange(32).reshape(8, 4)[:, [1, 0, 2, 3]].ravel()
    with pytest.raises(AssertionError):
        close(m[np.ix_(swap, swap)], mass, RTOL_MASS)
    nodes = np.arange(32).reshape(8, 4)[[0, 1, 3, 2, 4, 5, 7, 6]].ravel()  # C <-> D, G <-> H
    with pytest.raises(AssertionError):
        close(m[np.ix_(nodes, nodes)], mass, RTOL_MASS)
    with pytest.raises(AssertionError):
        close(ancf3843.scalar_mass(LX, LY, LZ, RHO, ngauss=3), mass, RTOL_MASS)


def test_second_moments_of_the_reference():
    """The reference configuration e0 (r = x exactly) gives e0_k^T M e0_k = int rho x_k^2 dV
    = rho V L_k^2 / 3 on each axis k."""
    M = ancf3843.mass_matrix(*DIMS, RHO)
    e0 = ancf3843.reference_coordinates(*DIMS)
    for k, length in enumerate(DIMS):
        ek = np.zeros(96)
        ek[k::3] = e0[k::3]
        assert ek @ M @ ek == pytest.approx(RHO * np.prod(DIMS) * length**2 / 3.0, rel=1e-12)


def test_shape_interpolates_nodes():
    """S e0 reproduces the reference position x = L (1 + xi)/2 at nodes and inside, and
    the scalar functions are the Kronecker deltas / unit slopes at the nodes."""
    lx, ly, lz = DIMS
    e0 = ancf3843.reference_coordinates(lx, ly, lz)
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
