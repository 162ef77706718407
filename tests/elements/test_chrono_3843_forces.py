"""The ANCF 3843 brick's internal force and its Jacobians against Project Chrono's stored data.

Data: ``tests/data/chrono/`` (README section "ANCF 3843 brick: internal forces and
Jacobians").  Parameters from Chrono's
``src/tests/unit_tests/fea/utest_FEA_ANCFhexa_3843_Formulation.cpp`` (line numbers at each
constant); material ``ChMaterialHexaANCF(rho, E, nu)`` (:159), isotropic.  Chrono stores -Q
(``ComputeInternalForces``) and K = dQ/de, R = dQ/de' (``ComputeKRMmatricesGlobal``; the
"WithDamping" files stack [K; R], 192 x 96, split at :707-710).  States: every node at the
reference except "SmallDisp", which moves node B's position to (L, 0, 0.001) m (:379, :585,
:887); "SmallVel" gives node B the velocity (0, 0, 0.001) m/s (:422, :1065); alpha = 0.01 s
for "SmallVel" and "WithDamping" (:423, :713, :888, :1066), 0 otherwise (:192).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ancf.elements import ancf3843

DATA = Path(__file__).resolve().parents[1] / "data" / "chrono"

LX = LY = LZ = 1.0               # m, :152-154, SetDimensions(length, width, height) :190
E, NU = 210e9, 0.3               # Pa, -, :156-157
ALPHA = 0.01                     # s, Kelvin-Voigt damping of the "SmallVel"/"WithDamping" cases
RTOL_FORCE, RTOL_JAC = 1e-8, 1e-6
ARGS = (LX, LY, LZ, E, NU)

E0 = ancf3843.reference_coordinates(LX, LY, LZ)
E_DISP = E0.copy()
E_DISP[14] = 0.001               # node B's z position, m
V_VEL = np.zeros(96)
V_VEL[14] = 0.001                # node B's dz/dt, m/s
ZERO = np.zeros(96)


def _close(actual, expected, rtol):
    """assert_allclose with rtol and an atol of rtol times the largest |expected| entry."""
    np.testing.assert_allclose(actual, expected, rtol=rtol, atol=rtol * np.abs(expected).max())


def _load(name, shape):
    a = np.loadtxt(DATA / f"UT_ANCFBrick_3843_{name}.txt")
    assert a.shape == shape
    return a


FORCE_CASES = [
    ("IntFrcSmallDispNoVel", E_DISP, ZERO, 0.0),
    ("IntFrcNoDispSmallVel", E0, V_VEL, ALPHA),
]


@pytest.mark.parametrize("name, e, edot, alpha", FORCE_CASES)
def test_internal_force_matches_chrono(name, e, edot, alpha):
    _close(-ancf3843.internal_force(e, edot, *ARGS, alpha), _load(name, (96,)), RTOL_FORCE)


JACOBIAN_CASES = [
    ("JacNoDispNoVelNoDamping", E0, ZERO, 0.0),
    ("JacSmallDispNoVelNoDamping", E_DISP, ZERO, 0.0),
    ("JacNoDispNoVelWithDamping", E0, ZERO, ALPHA),
    ("JacSmallDispNoVelWithDamping", E_DISP, ZERO, ALPHA),
    ("JacNoDispSmallVelWithDamping", E0, V_VEL, ALPHA),
]


@pytest.mark.parametrize("name, e, edot, alpha", JACOBIAN_CASES)
def test_jacobians_match_chrono(name, e, edot, alpha):
    """K (and R for the damped cases) within 1e-6; without damping R is exactly zero."""
    K, R = ancf3843.internal_force_jacobians(e, edot, *ARGS, alpha)
    ref = _load(name, (192 if alpha else 96, 96))
    _close(K, ref[:96], RTOL_JAC)
    if alpha:
        _close(R, ref[96:], RTOL_JAC)
    else:
        assert not R.any()


def test_exact_rule_is_converged():
    """7 Gauss points per direction integrate the degree-12 integrands exactly: 8 agree."""
    q7 = ancf3843.internal_force(E_DISP, V_VEL, *ARGS, ALPHA)
    _close(ancf3843.internal_force(E_DISP, V_VEL, *ARGS, ALPHA, ngauss=8), q7, 1e-13)
    for a, b in zip(ancf3843.internal_force_jacobians(E_DISP, V_VEL, *ARGS, ALPHA, ngauss=8),
                    ancf3843.internal_force_jacobians(E_DISP, V_VEL, *ARGS, ALPHA)):
        _close(a, b, 1e-13)


def test_stored_data_tell_the_formulation_apart():
    """The match is not loose: nu off by 1e-6 (5.7e-7 on the force), E off by 1e-7, or
    Chrono's own 4-point rule (8.2e-7 on the force, 1.6e-6 on K at SmallDisp) each break it."""
    ref_q = _load("IntFrcSmallDispNoVel", (96,))
    ref_k = _load("JacSmallDispNoVelNoDamping", (96, 96))
    with pytest.raises(AssertionError):
        _close(-ancf3843.internal_force(E_DISP, ZERO, LX, LY, LZ, E, NU * (1 + 1e-6)),
               ref_q, RTOL_FORCE)
    with pytest.raises(AssertionError):
        _close(-ancf3843.internal_force(E_DISP, ZERO, LX, LY, LZ, E * (1 + 1e-7), NU),
               ref_q, RTOL_FORCE)
    with pytest.raises(AssertionError):
        _close(-ancf3843.internal_force(E_DISP, ZERO, *ARGS, ngauss=4), ref_q, RTOL_FORCE)
    with pytest.raises(AssertionError):
        _close(ancf3843.internal_force_jacobians(E_DISP, ZERO, *ARGS, ngauss=4)[0],
               ref_k, RTOL_JAC)


def _rotation(axis, angle):
    """Rodrigues rotation matrix (3, 3) about the unit ``axis``."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    A = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * A + (1 - np.cos(angle)) * A @ A


DIMS = (2.0, 0.5, 0.25)          # m, distinct so that Lx, Ly, Lz are told apart


def test_zero_force_at_reference_and_under_rigid_motion():
    """Q = 0 exactly at the reference at rest; under a large rigid rotation plus
    translation, moving with a rigid velocity (omega x), the strain and its rate vanish,
    so Q vanishes to round-off: below the force of a 1e-12 strain, 1e-12 E Ly Lz."""
    lx, ly, lz = DIMS
    args = (lx, ly, lz, E, NU)
    e0 = ancf3843.reference_coordinates(lx, ly, lz)
    assert not ancf3843.internal_force(e0, ZERO, *args, ALPHA).any()
    Rm = _rotation([1.0, -2.0, 0.5], 1.1)
    omega = np.array([0.3, 2.0, -1.2])                 # rad/s
    blocks = e0.reshape(32, 3) @ Rm.T                  # rotated r and r_x, r_y, r_z
    blocks[0::4] += [0.2, -0.4, 0.7]                   # translated node positions, m
    rates = np.cross(omega, blocks)                    # r' = v0 + omega x r, r_J' = omega x r_J
    rates[0::4] += [1.0, 0.5, -2.0]                    # v0, m/s
    e, edot = blocks.ravel(), rates.ravel()
    bound = 1e-12 * E * ly * lz
    assert np.abs(ancf3843.internal_force(e, edot, *args, ALPHA)).max() < bound
    bent = e.copy()
    bent[14] += 1e-9                                   # a 1e-9 m move of node B is clearly seen
    assert np.abs(ancf3843.internal_force(bent, edot, *args, ALPHA)).max() > 1e3 * bound


def test_shape_gradient_matches_finite_differences():
    lx, ly, lz = DIMS
    p, h = np.array([0.3, -0.7, 0.9]), 1e-6
    fd = np.stack([(ancf3843.scalar_shape(*(p + h * d), lx, ly, lz)
                    - ancf3843.scalar_shape(*(p - h * d), lx, ly, lz)) / (2 * h) * 2.0 / L
                   for d, L in zip(np.eye(3), DIMS)], axis=-1)
    np.testing.assert_allclose(ancf3843.shape_gradient(*p, lx, ly, lz), fd, atol=1e-8)


def test_jacobians_match_finite_differences():
    """K and R against central differences of Q at a generic state (Lx, Ly, Lz distinct)."""
    rng = np.random.default_rng(3843)
    lx, ly, lz = DIMS
    args = (lx, ly, lz, 2e9, 0.25)
    e = ancf3843.reference_coordinates(lx, ly, lz) + 0.02 * rng.standard_normal(96)
    edot = 0.5 * rng.standard_normal(96)
    K, R = ancf3843.internal_force_jacobians(e, edot, *args, ALPHA)
    for J, h, fn, x0 in [(K, 1e-6, lambda x: ancf3843.internal_force(x, edot, *args, ALPHA), e),
                         (R, 1e-4, lambda x: ancf3843.internal_force(e, x, *args, ALPHA), edot)]:
        fd = np.column_stack([(fn(x0 + h * d) - fn(x0 - h * d)) / (2 * h) for d in np.eye(96)])
        _close(J, fd, RTOL_JAC)
    np.testing.assert_allclose(R, R.T, atol=1e-12 * np.abs(R).max())
