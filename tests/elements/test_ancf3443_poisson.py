"""The 3443's ``poisson`` option (``ancf3443`` eqs. (P1)-(P2)): the condensed law, the
parts it integrates, and the force/Jacobian consistency of each remedy.  The default "3d"
against Chrono's stored matrices is ``test_chrono_3443_forces``/``test_chrono_shells``."""
from __future__ import annotations

import numpy as np
import pytest

from ancf.elements import ancf3443

L, W, H, E, NU = 0.4, 0.3, 0.02, 2.0e11, 0.3   # m, m, m, Pa, -
D = ancf3443.elasticity(E, NU)


def displaced(seed: int = 3, size: float = 1e-3) -> np.ndarray:
    """A small arbitrary state e0 + u (m), u of order ``size``."""
    u = size * np.random.default_rng(seed).standard_normal(48)
    return ancf3443.reference_coordinates(L, W) + u


def test_plane_stress_of_isotropic_law():
    """(P1) of the isotropic law: E/(1 - nu^2) [[1, nu], [nu, 1]] in-plane, E on E_33
    uncoupled, the shear moduli G unchanged."""
    c, G = E / (1 - NU**2), E / (2 * (1 + NU))
    expected = np.diag([c, c, E, G, G, G])
    expected[0, 1] = expected[1, 0] = NU * c
    np.testing.assert_allclose(ancf3443.plane_stress(D), expected, rtol=1e-14, atol=1e-3)


def test_split_is_full_law_on_mid_surface():
    """(P2): the volume parts hold D0 over the thickness H, the mid-surface part D - D0 at
    z = 0 with the weight H, so the through-thickness sum at z = 0 is D H."""
    rules = ancf3443.poisson_rules(H, D, poisson="split", n_plane=1)
    (D0, p0, w0), (Dv, p1, w1) = rules
    np.testing.assert_allclose(D0, ancf3443.plane_stress(D), rtol=0, atol=0)
    assert np.all(p1[:, 2] == 0.0) and np.isclose(w1.sum(), 4 * H, rtol=1e-14)
    np.testing.assert_allclose(D0 + Dv, D, rtol=0, atol=1e-4 * E)


@pytest.mark.parametrize("poisson", ["plane_stress", "split"])
def test_jacobian_is_derivative_of_force(poisson):
    """K = dQ/de by central differences at a displaced state (the remedy's parts enter
    Q and K alike)."""
    e, zero, h = displaced(), np.zeros(48), 1e-7
    K = ancf3443.internal_force_jacobians(e, zero, L, W, H, D, poisson=poisson)[0]
    cols = [(ancf3443.internal_force(e + h * d, zero, L, W, H, D, poisson=poisson)
             - ancf3443.internal_force(e - h * d, zero, L, W, H, D, poisson=poisson)) / (2 * h)
            for d in np.eye(48)]
    np.testing.assert_allclose(np.column_stack(cols), K, rtol=0, atol=1e-6 * abs(K).max())


def bending_mode(k: float) -> np.ndarray:
    """u (48,) of the cylindrical bending w = -k x^2/2 (curvature k, 1/m): w and r_x,z =
    -k x at the nodes B, C (x = L), the fibre tilted by r_z,x = k x, so 2E_13 = 0 and
    E_11 = z k, E_33 = 0 to first order."""
    u = np.zeros(48)
    for node in (1, 2):
        u[12 * node + 2], u[12 * node + 5], u[12 * node + 9] = -k * L**2 / 2, -k * L, k * L
    return u


@pytest.mark.parametrize("poisson, modulus", [
    ("3d", E * (1 - NU) / ((1 + NU) * (1 - 2 * NU))),   # locked: plane strain
    ("plane_stress", E / (1 - NU**2)), ("split", E / (1 - NU**2))])
def test_bending_energy_modulus(poisson, modulus):
    """u^T K(e0) u = C k^2 L W H^3/12 for the bending mode: C the plane-strain modulus
    under Chrono's law (the locking, (1 - nu)^2/(1 - 2 nu) = 1.225 times the plate's), the
    plane-stress E/(1 - nu^2) under either remedy."""
    k, e0 = 1e-3, ancf3443.reference_coordinates(L, W)
    K = ancf3443.internal_force_jacobians(e0, np.zeros(48), L, W, H, D, poisson=poisson)[0]
    u = bending_mode(k)
    np.testing.assert_allclose(u @ K @ u, modulus * k**2 * L * W * H**3 / 12, rtol=1e-12)


def test_default_is_the_call_without_the_option():
    """poisson="3d" is the call without the option, bit for bit (the stored Chrono data
    are checked on the latter)."""
    e, zero = displaced(), np.zeros(48)
    K = ancf3443.internal_force_jacobians(e, zero, L, W, H, D)[0]
    assert np.array_equal(K, ancf3443.internal_force_jacobians(e, zero, L, W, H, D,
                                                               poisson="3d")[0])


def test_unknown_law_is_refused():
    with pytest.raises(ValueError, match="poisson must be one of"):
        ancf3443.internal_force(displaced(), np.zeros(48), L, W, H, D, poisson="eas")
