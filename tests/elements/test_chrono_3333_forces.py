"""The ANCF 3333 beam's internal force and its Jacobians against Project Chrono's stored data.

Data: ``tests/data/chrono/`` (README section "ANCF 3333 beam: internal forces and Jacobians").
Parameters from Chrono's ``src/tests/unit_tests/fea/utest_FEA_ANCFbeam_3333_Formulation.cpp``
(line numbers at each constant).  Chrono stores -Q (``ComputeInternalForces``) and
K = dQ/de, R = dQ/de' (``ComputeKRMmatricesGlobal``; the "WithDamping" files stack
[K; R], 54 x 27, split at :698-701).  States: nodes A and B at the reference; "SmallDisp"
moves the central node C's position to (L/2, 0, 0.001) m (:370, :576, :878), "SmallVel"
gives node C's position the velocity (0, 0, 0.001) m/s (:413, :1056) with alpha = 0.01 s
(:414, :704, :879, :1057); alpha = 0 otherwise (:183).  Coordinates per node [r, r_y, r_z],
nodes in the order A, B, C (``SetNodes`` at :180), so node C's z position is entry 20.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ancf.elements import ancf3333

DATA = Path(__file__).resolve().parents[1] / "data" / "chrono"

L, W, H = 1.0, 0.1, 0.1          # m, :150-152, SetDimensions(length, thickness, width) :181
E, NU = 210e9, 0.3               # Pa, -, :154-155
K1 = K2 = 10 * (1 + NU) / (12 + 11 * NU)   # Timoshenko shear correction, :156-158
ALPHA = 0.01                     # s, Kelvin-Voigt damping of the "SmallVel"/"WithDamping" cases
RTOL_FORCE, RTOL_JAC = 1e-8, 1e-6
ARGS = (L, H, W, E, NU, K1, K2)
N = ancf3333.NDOF                # 27
ZC = 20                          # node C's r_z entry (3 * (3 * 2 + 0) + 2)

E0 = ancf3333.reference_coordinates(L)
E_DISP = E0.copy()
E_DISP[ZC] = 0.001               # node C's z position, m
V_VEL = np.zeros(N)
V_VEL[ZC] = 0.001                # node C's dz/dt, m/s
ZERO = np.zeros(N)


def _close(actual, expected, rtol):
    """assert_allclose with rtol and an atol of rtol times the largest |expected| entry."""
    np.testing.assert_allclose(actual, expected, rtol=rtol, atol=rtol * np.abs(expected).max())


def _load(name, shape):
    a = np.loadtxt(DATA / f"UT_ANCFBeam_3333_{name}.txt")
    assert a.shape == shape
    return a


def test_reference_coordinates():
    """Nodes A, B, C at x = 0, L, L/2 with r_y = e_y, r_z = e_z (:167-175)."""
    e0 = E0.reshape(3, 3, 3)
    np.testing.assert_array_equal(e0[:, 0], [[0, 0, 0], [L, 0, 0], [L / 2, 0, 0]])
    np.testing.assert_array_equal(e0[:, 1], np.tile([0, 1, 0], (3, 1)))
    np.testing.assert_array_equal(e0[:, 2], np.tile([0, 0, 1], (3, 1)))


@pytest.mark.parametrize("naxis", [ancf3333.NAXIS, 8])
@pytest.mark.parametrize("name, e, edot, alpha", [
    ("IntFrcSmallDispNoVel", E_DISP, ZERO, 0.0),
    ("IntFrcNoDispSmallVel", E0, V_VEL, ALPHA),
])
def test_internal_force_matches_chrono(name, e, edot, alpha, naxis):
    """-Q within 1e-8; more Gauss points along the axis change nothing (the rule is exact)."""
    q = ancf3333.internal_force(e, edot, *ARGS, alpha, naxis=naxis)
    _close(-q, _load(name, (N,)), RTOL_FORCE)


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
    K, R = ancf3333.internal_force_jacobians(e, edot, *ARGS, alpha)
    ref = _load(name, (2 * N if alpha else N, N))
    _close(K, ref[:N], RTOL_JAC)
    if alpha:
        _close(R, ref[N:], RTOL_JAC)
    else:
        assert not R.any()
    _close(ancf3333.internal_force_jacobians(e, edot, *ARGS, alpha, naxis=8)[0], ref[:N], RTOL_JAC)


def test_stored_data_tell_the_formulation_apart():
    """The match is not loose: nu off by 1e-6 (relative; moves Q by 2.3e-7 of its largest
    entry, K only by 8.4e-7, so K is checked with nu off by 1e-5), a Poisson part integrated
    over the whole volume (no split: 2.1e-4 off K; Q at SmallDisp cannot tell, its Poisson
    stresses are odd in z), or the displacement put on node B instead of the central node C
    (the node order A, B, C of ``SetNodes``) each break it."""
    ref_q = _load("IntFrcSmallDispNoVel", (N,))
    ref_v = _load("IntFrcNoDispSmallVel", (N,))
    ref_k = _load("JacNoDispNoVelNoDamping", (N, N))
    nu_off = (L, H, W, E, NU * (1 + 1e-6), K1, K2)
    with pytest.raises(AssertionError):
        _close(-ancf3333.internal_force(E_DISP, ZERO, *nu_off), ref_q, RTOL_FORCE)
    with pytest.raises(AssertionError):
        _close(-ancf3333.internal_force(E0, V_VEL, *nu_off, ALPHA), ref_v, RTOL_FORCE)
    with pytest.raises(AssertionError):
        _close(ancf3333.internal_force_jacobians(E0, ZERO, L, H, W, E, NU * (1 + 1e-5), K1, K2)[0],
               ref_k, RTOL_JAC)
    with pytest.raises(AssertionError):
        _close(ancf3333.internal_force_jacobians(E0, ZERO, *ARGS, split_poisson=False)[0],
               ref_k, RTOL_JAC)
    on_b = E0.copy()
    on_b[11] = 0.001                                   # node B's z position
    with pytest.raises(AssertionError):
        _close(-ancf3333.internal_force(on_b, ZERO, *ARGS), ref_q, RTOL_FORCE)


def _rotation(axis, angle):
    """Rodrigues rotation matrix (3, 3) about the unit ``axis``."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    A = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * A + (1 - np.cos(angle)) * A @ A


def test_zero_force_at_reference_and_under_rigid_motion():
    """Q = 0 exactly at the reference at rest; under a large rigid rotation plus
    translation, moving with a rigid velocity (omega x), the strain and its rate vanish,
    so Q vanishes to round-off: below the force of a 1e-12 strain, 1e-12 E H W."""
    assert not ancf3333.internal_force(E0, ZERO, *ARGS, ALPHA).any()
    Rm = _rotation([1.0, -2.0, 0.5], 1.1)
    omega = np.array([0.3, 2.0, -1.2])                 # rad/s
    blocks = E0.reshape(9, 3) @ Rm.T                   # rotated r, r_y, r_z
    pos = [0, 3, 6]                                    # node positions A, B, C
    blocks[pos] += [0.2, -0.4, 0.7]                    # translated, m
    rates = np.cross(omega, blocks)                    # r' = v0 + omega x r, r_J' = omega x r_J
    rates[pos] += [1.0, 0.5, -2.0]                     # v0, m/s
    e, edot = blocks.ravel(), rates.ravel()
    q = ancf3333.internal_force(e, edot, *ARGS, ALPHA)
    assert np.abs(q).max() < 1e-12 * E * H * W
    bent = e.copy()
    bent[ZC] += 1e-9                                   # a 1e-9 m offset of node C is clearly seen
    assert np.abs(ancf3333.internal_force(bent, edot, *ARGS, ALPHA)).max() > 1e3 * 1e-12 * E * H * W


def test_jacobians_match_finite_differences():
    """K and R against central differences of Q at a generic state (H != W, k1 != k2)."""
    rng = np.random.default_rng(3333)
    args = (1.2, 0.15, 0.08, 2e9, 0.25, 0.8, 0.9)
    e = ancf3333.reference_coordinates(1.2) + 0.02 * rng.standard_normal(N)
    edot = 0.5 * rng.standard_normal(N)
    K, R = ancf3333.internal_force_jacobians(e, edot, *args, ALPHA)
    for J, h, fn in [(K, 1e-6, lambda x: ancf3333.internal_force(x, edot, *args, ALPHA)),
                     (R, 1e-4, lambda x: ancf3333.internal_force(e, x, *args, ALPHA))]:
        x0 = e if J is K else edot
        fd = np.column_stack([(fn(x0 + h * d) - fn(x0 - h * d)) / (2 * h) for d in np.eye(N)])
        _close(J, fd, RTOL_JAC)
    np.testing.assert_allclose(R, R.T, atol=1e-12 * np.abs(R).max())
