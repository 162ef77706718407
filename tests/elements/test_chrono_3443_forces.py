"""The ANCF 3443 shell's internal force and its Jacobians against Project Chrono's stored data.

Data: ``tests/data/chrono/`` (README section "ANCF 3443 shell: internal forces and Jacobians").
Parameters from Chrono's ``src/tests/unit_tests/fea/utest_FEA_ANCFshell_3443_Formulation.cpp``
(line numbers at each constant).  Chrono stores -Q (``ComputeInternalForces``) and
K = dQ/de, R = dQ/de' (``ComputeKRMmatricesGlobal``; the "WithDamping" files stack
[K; R], 96 x 48).  States: node A fixed at the reference; "SmallDisp" moves node B's
position to (L, 0, 0.001) m (:385, :591, :893), "SmallVel" gives node B's position the
velocity (0, 0, 0.001) m/s (:428, :1071) with alpha = 0.01 s (:429, :719, :894, :1072);
"NoDamping" has alpha = 0 (:193).  Material: isotropic ``ChMaterialShellANCF(rho, E, nu)``
(:167), one layer at fibre angle 0 (:192), i.e. the full 3D isotropic D over the volume.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from ancf.elements import ancf3443

DATA = Path(__file__).resolve().parents[1] / "data" / "chrono"

L, W, H = 1.0, 1.0, 0.01         # m, :160-162, SetDimensions(length, width) :191, AddLayer :192
E, NU = 210e9, 0.3               # Pa, -, :164-165
ALPHA = 0.01                     # s, Kelvin-Voigt damping of the "SmallVel"/"WithDamping" cases
RTOL_FORCE, RTOL_JAC = 1e-8, 1e-6
D = ancf3443.elasticity(E, NU)
ARGS = (L, W, H, D)

E0 = ancf3443.reference_coordinates(L, W)
E_DISP = E0.copy()
E_DISP[14] = 0.001               # node B's r_z, m
V_VEL = np.zeros(48)
V_VEL[14] = 0.001                # node B's dr_z/dt, m/s
ZERO = np.zeros(48)


def _close(actual, expected, rtol):
    """assert_allclose with rtol and an atol of rtol times the largest |expected| entry."""
    np.testing.assert_allclose(actual, expected, rtol=rtol, atol=rtol * np.abs(expected).max())


def _load(name, shape):
    a = np.loadtxt(DATA / f"UT_ANCFShell_3443_{name}.txt")
    assert a.shape == shape
    return a


@pytest.mark.parametrize("name, e, edot, alpha", [
    ("IntFrcSmallDispNoVel", E_DISP, ZERO, 0.0),     # :380-389
    ("IntFrcNoDispSmallVel", E0, V_VEL, ALPHA),      # :423-433
])
def test_internal_force_matches_chrono(name, e, edot, alpha):
    _close(-ancf3443.internal_force(e, edot, *ARGS, alpha), _load(name, (48,)), RTOL_FORCE)


JACOBIAN_CASES = [
    ("JacNoDispNoVelNoDamping", E0, ZERO, 0.0),          # :469-484
    ("JacSmallDispNoVelNoDamping", E_DISP, ZERO, 0.0),   # :585-605
    ("JacNoDispNoVelWithDamping", E0, ZERO, ALPHA),      # :709-733
    ("JacSmallDispNoVelWithDamping", E_DISP, ZERO, ALPHA),  # :882-908
    ("JacNoDispSmallVelWithDamping", E0, V_VEL, ALPHA),  # :1060-1086
]


@pytest.mark.parametrize("name, e, edot, alpha", JACOBIAN_CASES)
def test_jacobians_match_chrono(name, e, edot, alpha):
    """K (and R for the damped cases) within 1e-6; without damping R is exactly zero."""
    K, R = ancf3443.internal_force_jacobians(e, edot, *ARGS, alpha)
    ref = _load(name, (96 if alpha else 48, 48))
    _close(K, ref[:48], RTOL_JAC)
    if alpha:
        _close(R, ref[48:], RTOL_JAC)
    else:
        assert not R.any()


def test_exact_rule_and_stored_data_tell_the_formulation_apart():
    """Raising the exact 7 x 7 x 3 rule changes nothing; Chrono's own 4 x 4 x 2 rule
    (element .h NP = 4, NT = 2) is 5e-7 off and nu off by 1e-6 is 2.3e-7 off the force."""
    ref_q = _load("IntFrcSmallDispNoVel", (48,))
    _close(-ancf3443.internal_force(E_DISP, ZERO, *ARGS, n_plane=9, n_thick=4), ref_q, 1e-14)
    with pytest.raises(AssertionError):
        _close(-ancf3443.internal_force(E_DISP, ZERO, *ARGS, n_plane=4, n_thick=2),
               ref_q, RTOL_FORCE)
    planted = ancf3443.elasticity(E, NU * (1 + 1e-6))
    with pytest.raises(AssertionError):
        _close(-ancf3443.internal_force(E_DISP, ZERO, L, W, H, planted), ref_q, RTOL_FORCE)


def _rotation(axis, angle):
    """Rodrigues rotation matrix (3, 3) about the unit ``axis``."""
    a = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    A = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * A + (1 - np.cos(angle)) * A @ A


def test_zero_force_at_reference_and_under_rigid_motion():
    """Q = 0 exactly at the reference at rest; under a large rigid rotation plus
    translation, moving with a rigid velocity (omega x), the strain and its rate vanish,
    so Q vanishes to round-off: below the force of a 1e-12 strain, 1e-12 E W H = 2.1e-3 N
    (seen: 1.5e-7 N), while a 1e-9 m corner offset gives 1.1 N (membrane E H 1e-9)."""
    assert not ancf3443.internal_force(E0, ZERO, *ARGS, ALPHA).any()
    Rm = _rotation([1.0, -2.0, 0.5], 1.1)
    omega = np.array([0.3, 2.0, -1.2])                 # rad/s
    blocks = E0.reshape(16, 3) @ Rm.T                  # rotated r and r_x, r_y, r_z
    pos = [0, 4, 8, 12]                                # node positions among the 16 blocks
    blocks[pos] += [0.2, -0.4, 0.7]                    # translation, m
    rates = np.cross(omega, blocks)                    # r' = v0 + omega x r, r_J' = omega x r_J
    rates[pos] += [1.0, 0.5, -2.0]                     # v0, m/s
    e, edot = blocks.ravel(), rates.ravel()
    q = ancf3443.internal_force(e, edot, *ARGS, ALPHA)
    assert np.abs(q).max() < 1e-12 * E * W * H
    bent = e.copy()
    bent[14] += 1e-9                                   # a 1e-9 m corner offset is clearly seen
    assert np.abs(ancf3443.internal_force(bent, edot, *ARGS, ALPHA)).max() > 1e2 * 1e-12 * E * W * H


def test_shape_gradient_matches_finite_differences_and_reference_is_identity():
    """G = ds/dX by central differences (dx = L dxi/2, dy = W deta/2), and S e0 = X."""
    rng = np.random.default_rng(0)
    Lg, Wg, Hg = 1.3, 0.7, 0.05
    xi, eta, z = rng.uniform(-1, 1, 6), rng.uniform(-1, 1, 6), rng.uniform(-Hg / 2, Hg / 2, 6)
    s = lambda *p: ancf3443.scalar_shape(*p, Lg, Wg)
    h = 1e-6
    fd = np.stack([(s(xi + h, eta, z) - s(xi - h, eta, z)) / (h * Lg),
                   (s(xi, eta + h, z) - s(xi, eta - h, z)) / (h * Wg),
                   (s(xi, eta, z + h) - s(xi, eta, z - h)) / (2 * h)], axis=-1)
    np.testing.assert_allclose(ancf3443.shape_gradient(xi, eta, z, Lg, Wg), fd, atol=1e-8)
    X = s(xi, eta, z) @ ancf3443.reference_coordinates(Lg, Wg).reshape(16, 3)
    np.testing.assert_allclose(X, np.c_[Lg * (1 + xi) / 2, Wg * (1 + eta) / 2, z], atol=1e-15)


def test_material_orthotropic_and_rotation():
    """The orthotropic constructor reduces to the isotropic D; an isotropic D is unchanged
    by any fibre angle; for an orthotropic D, a quarter turn swaps the x and y properties
    and a uniaxial strain along the fibre (cos t, sin t, 0) meets the fibre's own stiffness."""
    G = E / (2 * (1 + NU))
    _close(ancf3443.orthotropic([E] * 3, [NU] * 3, [G] * 3), D, 1e-14)
    _close(ancf3443.rotate_about_z(D, 0.7), D, 1e-14)
    Do = ancf3443.orthotropic([150e9, 10e9, 9e9], [0.3, 0.25, 0.4], [5e9, 4e9, 2e9])
    swapped = ancf3443.orthotropic([10e9, 150e9, 9e9], [0.3 * 10 / 150, 0.4, 0.25],
                                   [5e9, 2e9, 4e9])
    _close(ancf3443.rotate_about_z(Do, np.pi / 2), swapped, 1e-12)
    t = 0.6
    c, s = np.cos(t), np.sin(t)
    eps = np.array([c * c, s * s, 0, 0, 0, 2 * c * s])   # n n^T in Voigt, engineering shear
    assert np.isclose(eps @ ancf3443.rotate_about_z(Do, t) @ eps, Do[0, 0], rtol=1e-12)


def test_jacobians_match_finite_differences():
    """K and R against central differences of Q at a generic state (L != W, two layers of
    rotated orthotropic material)."""
    rng = np.random.default_rng(3443)
    Lg, Wg, Hg = 1.2, 0.8, 0.03
    Do = ancf3443.orthotropic([50e9, 10e9, 8e9], [0.3, 0.25, 0.35], [5e9, 4e9, 3e9])
    layers = [(0.01, ancf3443.rotate_about_z(Do, 0.4)), (0.02, ancf3443.rotate_about_z(Do, -1.0))]
    args = (Lg, Wg, Hg, None, ALPHA)
    kw = dict(layers=layers, n_plane=4, n_thick=2)      # any rule: K, R are Q's exact derivatives
    e = ancf3443.reference_coordinates(Lg, Wg) + 0.02 * rng.standard_normal(48)
    edot = 0.5 * rng.standard_normal(48)
    K, R = ancf3443.internal_force_jacobians(e, edot, *args, **kw)
    for J, x0, h, fn in [(K, e, 1e-6, lambda x: ancf3443.internal_force(x, edot, *args, **kw)),
                         (R, edot, 1e-4, lambda x: ancf3443.internal_force(e, x, *args, **kw))]:
        fd = np.column_stack([(fn(x0 + h * d) - fn(x0 - h * d)) / (2 * h) for d in np.eye(48)])
        _close(J, fd, RTOL_JAC)
    np.testing.assert_allclose(R, R.T, atol=1e-12 * np.abs(R).max())
