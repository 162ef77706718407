"""The ANCF 3243 beam's internal force: what is its own beyond the contract tests.

The stored forces and Jacobians, rigid motion and finite differences are checked for
every element in ``test_chrono_elements.py`` (parameters in ``chrono_data``: E = 210 GPa,
nu = 0.3, k1 = k2 = 10 (1 + nu)/(12 + 11 nu), :154-159; "SmallDisp" moves node B's z
position, entry 14, by 0.001 m, :369).  Here: the stored data tell the beam's Poisson
split and its exact rule apart.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.elements import ancf3243
from ancf.elements.material import isotropic_3d
from tests.elements.chrono_data import BY_NAME, RTOL_FORCE, RTOL_JAC, close, load

EL = BY_NAME["3243"]
L, H, W = EL.geometry
E, NU, K1, K2 = EL.material
ARGS = (*EL.geometry, *EL.material)
E0, ZERO = EL.state("rest", False)
E_DISP, _ = EL.state("disp", False)


def test_stored_data_tell_the_formulation_apart():
    """The match is not loose: a Poisson part integrated over the whole volume (no
    split), Chrono's own 3-point axial rule, or nu off by 1e-6 each break it."""
    ref_q = load(f"{EL.prefix}_IntFrcSmallDispNoVel", (24,))
    ref_k = load(f"{EL.prefix}_JacNoDispNoVelNoDamping", (24, 24))
    with pytest.raises(AssertionError):   # 1.8e-4
        close(ancf3243.internal_force_jacobians(E0, ZERO, *ARGS, split_poisson=False)[0],
              ref_k, RTOL_JAC)
    with pytest.raises(AssertionError):   # 1.3e-4
        close(-ancf3243.internal_force(E_DISP, ZERO, *ARGS, naxis=3), ref_q, RTOL_FORCE)
    with pytest.raises(AssertionError):
        close(-ancf3243.internal_force(E_DISP, ZERO, L, H, W, E, NU * (1 + 1e-6), K1, K2),
              ref_q, RTOL_FORCE)


def test_poisson_split_is_the_isotropic_law():
    """D0 + Dv is the isotropic 3D law when k1 = k2 = 1; Dv has only the normal block."""
    D0, Dv = ancf3243.elasticity(E, NU, 1.0, 1.0)
    close(D0 + Dv, isotropic_3d(E, NU), 1e-15)
    assert not Dv[3:].any() and not Dv[:, 3:].any()
    np.testing.assert_array_equal(np.diag(D0)[:3], [E, E, E])
