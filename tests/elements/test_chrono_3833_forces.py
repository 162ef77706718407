"""The ANCF 3833 shell's internal force: what is its own beyond the contract tests.

The stored forces and Jacobians (raw and length-scaled: 1 on r, H/2 on r_z, H^2/8 on
r_zz), rigid motion, the exact rule (5 against 7 points) and finite differences are
checked for every element in ``test_chrono_elements.py`` (parameters in ``chrono_data``:
Chrono's ``utest_FEA_ANCFshell_3833_Formulation.cpp``, ``ChMaterialShellANCF(rho, E, nu)``
(:167), one layer at fibre angle 0 (:198); "SmallDisp" moves node B's z position, entry
11, by 0.001 m, :391).  Here: what the stored data tell apart.
"""
from __future__ import annotations

import pytest

from ancf.elements import ancf3833
from tests.elements.chrono_data import ALPHA, BY_NAME, RTOL_FORCE, RTOL_JAC, close, load

EL = BY_NAME["3833"]
L, W, H = EL.geometry
E, NU = EL.material
ARGS = (*EL.geometry, *EL.material)
N = ancf3833.NDOF
E0, ZERO = EL.state("rest", False)
E_DISP, _ = EL.state("disp", False)


def test_stored_data_tell_the_formulation_apart():
    """The match is not loose: nu off by 1e-6, a reduced 3-point rule (8.7e-6 off the
    force), or dropping the velocity terms of K (7.6e-6 off JacNoDispSmallVel) each break it."""
    ref_q = load(f"{EL.prefix}_IntFrcSmallDispNoVel", (N,))
    scale = EL.scale("force")
    with pytest.raises(AssertionError):
        close(-ancf3833.internal_force(E_DISP, ZERO, L, W, H, E, NU * (1 + 1e-6)), ref_q,
              RTOL_FORCE, scale)
    with pytest.raises(AssertionError):
        close(-ancf3833.internal_force(E_DISP, ZERO, *ARGS, ngauss=3), ref_q, RTOL_FORCE, scale)
    ref_k = load(f"{EL.prefix}_JacNoDispSmallVelWithDamping", (2 * N, N))[:N]
    with pytest.raises(AssertionError):
        close(ancf3833.internal_force_jacobians(E0, ZERO, *ARGS, ALPHA)[0], ref_k, RTOL_JAC, scale)
