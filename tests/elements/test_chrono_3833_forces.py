"""The ANCF 3833 shell's internal force and its Jacobians against Project Chrono's stored data.

Data: ``tests/data/chrono/`` (README section "ANCF 3833 shell: internal forces and
Jacobians").  Parameters from Chrono's
``src/tests/unit_tests/fea/utest_FEA_ANCFshell_3833_Formulation.cpp`` (line numbers at each
constant); the material is ``ChMaterialShellANCF(rho, E, nu)`` (:167), one layer at fibre
angle 0 (:198).  Chrono stores -Q (``ComputeInternalForces``) and K = dQ/de, R = dQ/de'
(``ComputeKRMmatricesGlobal``; the "WithDamping" files stack [K; R], 144 x 72).  States:
every node at the reference; "SmallDisp" moves node B's position to (L, 0, 0.001) m
(:391, :597, :899), "SmallVel" gives node B's position the velocity (0, 0, 0.001) m/s
(:434, :1077) with alpha = 0.01 s (:435, :1078; "WithDamping" :725, :900); otherwise
alpha = 0 (:199).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ancf.elements import ancf3833

DATA = Path(__file__).resolve().parents[1] / "data" / "chrono"

L, W, H = 1.0, 1.0, 0.01         # m, :160-162, SetDimensions(length, width) :197, AddLayer :198
E, NU = 210e9, 0.3               # Pa, -, :164-165
ALPHA = 0.01                     # s, Kelvin-Voigt damping of the "SmallVel"/"WithDamping" cases
RTOL_FORCE, RTOL_JAC = 1e-8, 1e-6
ARGS = (L, W, H, E, NU)
N = ancf3833.NDOF

E0 = ancf3833.reference_coordinates(L, W)
B_Z = 9 * 1 + 2                  # node B (index 1), its position r (first of r, r_z, r_zz), z
E_DISP = E0.copy()
E_DISP[B_Z] = 0.001              # node B's z position, m
V_VEL = np.zeros(N)
V_VEL[B_Z] = 0.001               # node B's dz/dt, m/s
ZERO = np.zeros(N)
# Each coordinate's length scale (1 on r, H/2 on r_z, H^2/8 on r_zz): comparing D a and
# D A D, D = diag(SCALE), holds the small r_z, r_zz entries to rtol of the largest entry.
SCALE = np.kron(np.tile([1.0, H / 2, H**2 / 8], ancf3833.NNODE), np.ones(3))


def _close(actual, expected, rtol):
    """assert_allclose with rtol and an atol of rtol times the largest |expected| entry,
    on the raw arrays and on the length-scaled ones (see SCALE)."""
    d = SCALE if np.ndim(expected) == 1 else np.outer(SCALE, SCALE)
    for a, b in ((actual, expected), (d * actual, d * expected)):
        np.testing.assert_allclose(a, b, rtol=rtol, atol=rtol * np.abs(b).max())


def _load(name, shape):
    a = np.loadtxt(DATA / f"UT_ANCFShell_3833_{name}.txt")
    assert a.shape == shape
    return a


@pytest.mark.parametrize("name, e, edot, alpha", [
    ("IntFrcSmallDispNoVel", E_DISP, ZERO, 0.0),
    ("IntFrcNoDispSmallVel", E0, V_VEL, ALPHA),
])
def test_internal_force_matches_chrono(name, e, edot, alpha):
    _close(-ancf3833.internal_force(e, edot, *ARGS, alpha), _load(name, (N,)), RTOL_FORCE)


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
    K, R = ancf3833.internal_force_jacobians(e, edot, *ARGS, alpha)
    ref = _load(name, (2 * N if alpha else N, N))
    _close(K, ref[:N], RTOL_JAC)
    if alpha:
        _close(R, ref[N:], RTOL_JAC)
    else:
        assert not R.any()


def test_exact_rule_is_converged():
    """Raising the rule from 5 to 7 points per direction changes nothing (the integrands
    are polynomials of degree <= 8)."""
    _close(ancf3833.internal_force(E_DISP, V_VEL, *ARGS, ALPHA, ngauss=7),
           ancf3833.internal_force(E_DISP, V_VEL, *ARGS, ALPHA), 1e-13)
    for a, b in zip(ancf3833.internal_force_jacobians(E_DISP, V_VEL, *ARGS, ALPHA, ngauss=7),
                    ancf3833.internal_force_jacobians(E_DISP, V_VEL, *ARGS, ALPHA)):
        _close(a, b, 1e-13)


def test_stored_data_tell_the_formulation_apart():
    """The match is not loose: nu off by 1e-6, a reduced 3-point rule (8.7e-6 off the
    force), or dropping the velocity terms of K (7.6e-6 off JacNoDispSmallVel) each break it."""
    ref_q = _load("IntFrcSmallDispNoVel", (N,))
    with pytest.raises(AssertionError):
        _close(-ancf3833.internal_force(E_DISP, ZERO, L, W, H, E, NU * (1 + 1e-6)), ref_q, RTOL_FORCE)
    with pytest.raises(AssertionError):
        _close(-ancf3833.internal_force(E_DISP, ZERO, *ARGS, ngauss=3), ref_q, RTOL_FORCE)
    ref_k = _load("JacNoDispSmallVelWithDamping", (2 * N, N))[:N]
    with pytest.raises(AssertionError):
        _close(ancf3833.internal_force_jacobians(E0, ZERO, *ARGS, ALPHA)[0], ref_k, RTOL_JAC)


def _rotation(axis, angle):
    """Rodrigues rotation matrix (3, 3) about the unit ``axis``."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    A = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * A + (1 - np.cos(angle)) * A @ A


def test_zero_force_at_reference_and_under_rigid_motion():
    """Q = 0 exactly at the reference at rest; under a large rigid rotation plus
    translation, moving with a rigid velocity (omega x), the strain and its rate vanish,
    so Q vanishes to round-off: below the force of a 1e-12 strain, 1e-12 E W H = 2.1e-3 N
    (seen 4.6e-7 N), while a 1e-9 m offset of one corner gives 1.7 N."""
    assert not ancf3833.internal_force(E0, ZERO, *ARGS, ALPHA).any()
    Rm = _rotation([1.0, -2.0, 0.5], 1.1)
    omega = np.array([0.3, 2.0, -1.2])                 # rad/s
    blocks = E0.reshape(-1, 3) @ Rm.T                  # rotated r, r_z, r_zz
    pos = np.arange(0, blocks.shape[0], 3)             # rows of the node positions
    blocks[pos] += [0.2, -0.4, 0.7]                    # translated, m
    rates = np.cross(omega, blocks)                    # r' = v0 + omega x r, r_z' = omega x r_z
    rates[pos] += [1.0, 0.5, -2.0]                     # v0, m/s
    e, edot = blocks.ravel(), rates.ravel()
    scale = 1e-12 * E * W * H
    assert np.abs(ancf3833.internal_force(e, edot, *ARGS, ALPHA)).max() < scale
    bent = e.copy()
    bent[B_Z] += 1e-9                                  # a 1e-9 m corner offset is clearly seen
    assert np.abs(ancf3833.internal_force(bent, edot, *ARGS, ALPHA)).max() > 1e2 * scale


def test_jacobians_match_finite_differences():
    """K and R against central differences of Q at a generic state (L != W, r_zz != 0,
    a velocity); R is symmetric."""
    rng = np.random.default_rng(3833)
    args = (1.2, 0.7, 0.05, 2e9, 0.25)
    e = ancf3833.reference_coordinates(1.2, 0.7) + 0.02 * rng.standard_normal(N)
    edot = 0.5 * rng.standard_normal(N)
    K, R = ancf3833.internal_force_jacobians(e, edot, *args, ALPHA)
    for J, x0, h, fn in [(K, e, 1e-6, lambda x: ancf3833.internal_force(x, edot, *args, ALPHA)),
                         (R, edot, 1e-4, lambda x: ancf3833.internal_force(e, x, *args, ALPHA))]:
        fd = np.column_stack([(fn(x0 + h * d) - fn(x0 - h * d)) / (2 * h) for d in np.eye(N)])
        np.testing.assert_allclose(J, fd, rtol=RTOL_JAC, atol=RTOL_JAC * np.abs(fd).max())
    np.testing.assert_allclose(R, R.T, atol=1e-12 * np.abs(R).max())
