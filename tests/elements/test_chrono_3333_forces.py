"""The ANCF 3333 beam's internal force: what is its own beyond the contract tests.

The stored forces and Jacobians (also with 8 axial points: ``test_exact_rule_is_converged``),
rigid motion and finite differences are checked for every element in
``test_chrono_elements.py`` (parameters in ``chrono_data``: E = 210 GPa, nu = 0.3,
k1 = k2 = 10 (1 + nu)/(12 + 11 nu), :154-158; "SmallDisp" moves the central node C's z
position, entry 20, by 0.001 m, :370).  Here: the reference layout and what the stored
data tell apart.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.elements import ancf3333
from tests.elements.chrono_data import ALPHA, BY_NAME, RTOL_FORCE, RTOL_JAC, close, load

EL = BY_NAME["3333"]
L, H, W = EL.geometry
E, NU, K1, K2 = EL.material
ARGS = (*EL.geometry, *EL.material)
N = ancf3333.NDOF
E0, V_VEL = EL.state("rest", True)
E_DISP, ZERO = EL.state("disp", False)


def test_reference_coordinates():
    """Nodes A, B, C at x = 0, L, L/2 with r_y = e_y, r_z = e_z (:167-175)."""
    e0 = E0.reshape(3, 3, 3)
    np.testing.assert_array_equal(e0[:, 0], [[0, 0, 0], [L, 0, 0], [L / 2, 0, 0]])
    np.testing.assert_array_equal(e0[:, 1], np.tile([0, 1, 0], (3, 1)))
    np.testing.assert_array_equal(e0[:, 2], np.tile([0, 0, 1], (3, 1)))


def test_stored_data_tell_the_formulation_apart():
    """The match is not loose: nu off by 1e-6 (relative; moves Q by 2.3e-7 of its largest
    entry, K only by 8.4e-7, so K is checked with nu off by 1e-5), a Poisson part integrated
    over the whole volume (no split: 2.1e-4 off K; Q at SmallDisp cannot tell, its Poisson
    stresses are odd in z), or the displacement put on node B instead of the central node C
    (the node order A, B, C of ``SetNodes``) each break it."""
    ref_q = load(f"{EL.prefix}_IntFrcSmallDispNoVel", (N,))
    ref_v = load(f"{EL.prefix}_IntFrcNoDispSmallVel", (N,))
    ref_k = load(f"{EL.prefix}_JacNoDispNoVelNoDamping", (N, N))
    nu_off = (L, H, W, E, NU * (1 + 1e-6), K1, K2)
    with pytest.raises(AssertionError):
        close(-ancf3333.internal_force(E_DISP, ZERO, *nu_off), ref_q, RTOL_FORCE)
    with pytest.raises(AssertionError):
        close(-ancf3333.internal_force(E0, V_VEL, *nu_off, ALPHA), ref_v, RTOL_FORCE)
    with pytest.raises(AssertionError):
        close(ancf3333.internal_force_jacobians(E0, ZERO, L, H, W, E, NU * (1 + 1e-5), K1, K2)[0],
              ref_k, RTOL_JAC)
    with pytest.raises(AssertionError):
        close(ancf3333.internal_force_jacobians(E0, ZERO, *ARGS, split_poisson=False)[0],
              ref_k, RTOL_JAC)
    on_b = E0.copy()
    on_b[11] = 0.001                                   # node B's z position
    with pytest.raises(AssertionError):
        close(-ancf3333.internal_force(on_b, ZERO, *ARGS), ref_q, RTOL_FORCE)
