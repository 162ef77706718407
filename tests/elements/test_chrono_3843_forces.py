"""The ANCF 3843 brick's internal force: what is its own beyond the contract tests.

The stored forces and Jacobians, rigid motion (at distinct edge lengths), the exact
rule (7 against 8 points) and finite differences are checked for every element in
``test_chrono_elements.py`` (parameters in ``chrono_data``: Chrono's
``utest_FEA_ANCFhexa_3843_Formulation.cpp``, ``ChMaterialHexaANCF(rho, E, nu)`` (:159),
E = 210 GPa, nu = 0.3 (:156-157); "SmallDisp" moves node B's z position, entry 14, by
0.001 m, :379).  Here: what the stored data tell apart, and the shape gradients.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.elements import ancf3843
from tests.elements.chrono_data import BY_NAME, RTOL_FORCE, RTOL_JAC, close, load

EL = BY_NAME["3843"]
LX, LY, LZ = EL.geometry
E, NU = EL.material
ARGS = (*EL.geometry, *EL.material)
E_DISP, ZERO = EL.state("disp", False)
DIMS = (2.0, 0.5, 0.25)          # m, distinct so that Lx, Ly, Lz are told apart


def test_stored_data_tell_the_formulation_apart():
    """The match is not loose: nu off by 1e-6 (5.7e-7 on the force), E off by 1e-7, or
    Chrono's own 4-point rule (8.2e-7 on the force, 1.6e-6 on K at SmallDisp) each break it."""
    ref_q = load(f"{EL.prefix}_IntFrcSmallDispNoVel", (96,))
    ref_k = load(f"{EL.prefix}_JacSmallDispNoVelNoDamping", (96, 96))
    with pytest.raises(AssertionError):
        close(-ancf3843.internal_force(E_DISP, ZERO, LX, LY, LZ, E, NU * (1 + 1e-6)),
              ref_q, RTOL_FORCE)
    with pytest.raises(AssertionError):
        close(-ancf3843.internal_force(E_DISP, ZERO, LX, LY, LZ, E * (1 + 1e-7), NU),
              ref_q, RTOL_FORCE)
    with pytest.raises(AssertionError):
        close(-ancf3843.internal_force(E_DISP, ZERO, *ARGS, ngauss=4), ref_q, RTOL_FORCE)
    with pytest.raises(AssertionError):
        close(ancf3843.internal_force_jacobians(E_DISP, ZERO, *ARGS, ngauss=4)[0],
              ref_k, RTOL_JAC)


def test_shape_gradient_matches_finite_differences():
    p, h = np.array([0.3, -0.7, 0.9]), 1e-6
    fd = np.stack([(ancf3843.scalar_shape(*(p + h * d), *DIMS)
                    - ancf3843.scalar_shape(*(p - h * d), *DIMS)) / (2 * h) * 2.0 / L
                   for d, L in zip(np.eye(3), DIMS)], axis=-1)
    np.testing.assert_allclose(ancf3843.shape_gradient(*p, *DIMS), fd, atol=1e-8)
