"""The ANCF 3243 beam's internal force and its Jacobians against Project Chrono's stored data.

Data: ``tests/data/chrono/`` (README section "ANCF 3243 internal forces and Jacobians").
Parameters from Chrono's ``src/tests/unit_tests/fea/utest_FEA_ANCFbeam_3243_Formulation.cpp``
(line numbers at each constant).  Chrono stores -Q (``ComputeInternalForces``) and
K = dQ/de, R = dQ/de' (``ComputeKRMmatricesGlobal``; the "WithDamping" files stack
[K; R], 48 x 24).  States: node A fixed at the reference; "SmallDisp" moves node B's
position to (L, 0, 0.001) m (:369), "SmallVel" gives node B's position the velocity
(0, 0, 0.001) m/s (:412) with alpha = 0.01 s (:413); "NoDamping" has alpha = 0 (:182).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ancf.elements import ancf3243

DATA = Path(__file__).resolve().parents[1] / "data" / "chrono"

L, W, H = 1.0, 0.1, 0.1          # m, :150-152, SetDimensions(length, thickness, width) :180
E, NU = 210e9, 0.3               # Pa, -, :154-155
K1 = K2 = 10 * (1 + NU) / (12 + 11 * NU)   # Timoshenko shear correction, :157-159
ALPHA = 0.01                     # s, Kelvin-Voigt damping of the "SmallVel"/"WithDamping" cases
RTOL_FORCE, RTOL_JAC = 1e-8, 1e-6
ARGS = (L, H, W, E, NU, K1, K2)

E0 = ancf3243.reference_coordinates(L)
E_DISP = E0.copy()
E_DISP[14] = 0.001               # node B's r_z, m
V_VEL = np.zeros(24)
V_VEL[14] = 0.001                # node B's dr_z/dt, m/s
ZERO = np.zeros(24)


def _close(actual, expected, rtol):
    """assert_allclose with rtol and an atol of rtol times the largest |expected| entry."""
    np.testing.assert_allclose(actual, expected, rtol=rtol, atol=rtol * np.abs(expected).max())


def _load(name, shape):
    a = np.loadtxt(DATA / f"UT_ANCFBeam_3243_{name}.txt")
    assert a.shape == shape
    return a


@pytest.mark.parametrize("name, e, edot, alpha", [
    ("IntFrcSmallDispNoVel", E_DISP, ZERO, 0.0),
    ("IntFrcNoDispSmallVel", E0, V_VEL, ALPHA),
])
def test_internal_force_matches_chrono(name, e, edot, alpha):
    _close(-ancf3243.internal_force(e, edot, *ARGS, alpha), _load(name, (24,)), RTOL_FORCE)


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
    K, R = ancf3243.internal_force_jacobians(e, edot, *ARGS, alpha)
    ref = _load(name, (48 if alpha else 24, 24))
    _close(K, ref[:24], RTOL_JAC)
    if alpha:
        _close(R, ref[24:], RTOL_JAC)
    else:
        assert not R.any()


def test_stored_data_tell_the_formulation_apart():
    """The match is not loose: a Poisson part integrated over the whole volume (no
    split), Chrono's own 3-point axial rule, or nu off by 1e-6 each break it."""
    ref_q = _load("IntFrcSmallDispNoVel", (24,))
    ref_k = _load("JacNoDispNoVelNoDamping", (24, 24))
    with pytest.raises(AssertionError):   # 1.8e-4
        _close(ancf3243.internal_force_jacobians(E0, ZERO, *ARGS, split_poisson=False)[0],
               ref_k, RTOL_JAC)
    with pytest.raises(AssertionError):   # 1.3e-4
        _close(-ancf3243.internal_force(E_DISP, ZERO, *ARGS, naxis=3), ref_q, RTOL_FORCE)
    with pytest.raises(AssertionError):
        _close(-ancf3243.internal_force(E_DISP, ZERO, L, H, W, E, NU * (1 + 1e-6), K1, K2),
               ref_q, RTOL_FORCE)


def _rotation(axis, angle):
    """Rodrigues rotation matrix (3, 3) about the unit ``axis``."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    A = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * A + (1 - np.cos(angle)) * A @ A


def test_zero_force_at_reference_and_under_rigid_motion():
    """Q = 0 exactly at the reference at rest; under a large rigid rotation plus
    translation, moving with a rigid velocity (omega x), the strain and its rate vanish,
    so Q vanishes to round-off: below the force of a 1e-12 strain, 1e-12 E H W."""
    assert not ancf3243.internal_force(E0, ZERO, *ARGS, ALPHA).any()
    Rm = _rotation([1.0, -2.0, 0.5], 1.1)
    omega = np.array([0.3, 2.0, -1.2])                 # rad/s
    blocks = E0.reshape(8, 3) @ Rm.T                   # rotated r and r_x, r_y, r_z
    blocks[[0, 4]] += [0.2, -0.4, 0.7]                 # translated node positions, m
    rates = np.cross(omega, blocks)                    # r' = v0 + omega x r, r_J' = omega x r_J
    rates[[0, 4]] += [1.0, 0.5, -2.0]                  # v0, m/s
    e, edot = blocks.ravel(), rates.ravel()
    q = ancf3243.internal_force(e, edot, *ARGS, ALPHA)
    assert np.abs(q).max() < 1e-12 * E * H * W
    bent = e.copy()
    bent[14] += 1e-9                                   # a 1e-9 m tip offset is clearly seen
    assert np.abs(ancf3243.internal_force(bent, edot, *ARGS, ALPHA)).max() > 1e3 * 1e-12 * E * H * W


def test_jacobians_match_finite_differences():
    """K and R against central differences of Q at a generic state (H != W, k1 != k2)."""
    rng = np.random.default_rng(3243)
    args = (1.2, 0.15, 0.08, 2e9, 0.25, 0.8, 0.9)
    e = ancf3243.reference_coordinates(1.2) + 0.02 * rng.standard_normal(24)
    edot = 0.5 * rng.standard_normal(24)
    K, R = ancf3243.internal_force_jacobians(e, edot, *args, ALPHA)
    for J, h, fn in [(K, 1e-6, lambda x: ancf3243.internal_force(x, edot, *args, ALPHA)),
                     (R, 1e-4, lambda x: ancf3243.internal_force(e, x, *args, ALPHA))]:
        x0 = e if J is K else edot
        fd = np.column_stack([(fn(x0 + h * d) - fn(x0 - h * d)) / (2 * h) for d in np.eye(24)])
        _close(J, fd, RTOL_JAC)
    np.testing.assert_allclose(R, R.T, atol=1e-12 * np.abs(R).max())
