"""The ANCF 3443 shell's internal force: what is its own beyond the contract tests.

The stored forces and Jacobians, rigid motion, the exact rule and finite differences
(two layers of rotated orthotropic material) are checked for every element in
``test_chrono_elements.py`` (parameters in ``chrono_data``: Chrono's
``utest_FEA_ANCFshell_3443_Formulation.cpp``, isotropic ``ChMaterialShellANCF(rho, E, nu)``
(:167), one layer at fibre angle 0 (:192), i.e. the full 3D isotropic D over the volume;
"SmallDisp" moves node B's z position, entry 14, by 0.001 m, :385).  Here: the stored
data against Chrono's own rule, the shape gradients and the layer materials.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.elements import ancf3443
from tests.elements.chrono_data import BY_NAME, NU, RTOL_FORCE, close, load

EL = BY_NAME["3443"]
L, W, H = EL.geometry
E = 210e9                        # Pa, :164
(D,) = EL.material
E_DISP, ZERO = EL.state("disp", False)


def test_exact_rule_and_stored_data_tell_the_formulation_apart():
    """Raising the exact 7 x 7 x 3 rule changes nothing; Chrono's own 4 x 4 x 2 rule
    (element .h NP = 4, NT = 2) is 5e-7 off and nu off by 1e-6 is 2.3e-7 off the force."""
    ref_q = load(f"{EL.prefix}_IntFrcSmallDispNoVel", (48,))
    close(-ancf3443.internal_force(E_DISP, ZERO, L, W, H, D, n_plane=9, n_thick=4), ref_q, 1e-14)
    with pytest.raises(AssertionError):
        close(-ancf3443.internal_force(E_DISP, ZERO, L, W, H, D, n_plane=4, n_thick=2),
              ref_q, RTOL_FORCE)
    planted = ancf3443.elasticity(E, NU * (1 + 1e-6))
    with pytest.raises(AssertionError):
        close(-ancf3443.internal_force(E_DISP, ZERO, L, W, H, planted), ref_q, RTOL_FORCE)


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
    close(ancf3443.orthotropic([E] * 3, [NU] * 3, [G] * 3), D, 1e-14)
    close(ancf3443.rotate_about_z(D, 0.7), D, 1e-14)
    Do = ancf3443.orthotropic([150e9, 10e9, 9e9], [0.3, 0.25, 0.4], [5e9, 4e9, 2e9])
    swapped = ancf3443.orthotropic([10e9, 150e9, 9e9], [0.3 * 10 / 150, 0.4, 0.25],
                                   [5e9, 2e9, 4e9])
    close(ancf3443.rotate_about_z(Do, np.pi / 2), swapped, 1e-12)
    t = 0.6
    c, s = np.cos(t), np.sin(t)
    eps = np.array([c * c, s * s, 0, 0, 0, 2 * c * s])   # n n^T in Voigt, engineering shear
    assert np.isclose(eps @ ancf3443.rotate_about_z(Do, t) @ eps, Do[0, 0], rtol=1e-12)
