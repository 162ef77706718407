"""Chrono's small-deflection static checks of its ANCF beams, by our own model
(``ancf.models.chrono_beam``), held to Chrono's own tolerances.

Source: ``src/tests/unit_tests/fea/utest_FEA_ANCFbeam_3243_Formulation.cpp`` and
``..._3333_Formulation.cpp`` (projectchrono/chrono 7689fbc02d12c5419fa6acad8791100fd89979dd);
line numbers "3243 line / 3333 line".  Common to the four checks: 20 elements (:1240 /
:1241), length 20 in (:1241 / :1242), aluminium rho = 2810 kg/m^3, E = 71.7 GPa,
nu = 0.33, k1 = k2 = 10 (1 + nu)/(12 + 11 nu) (:1245-1251 / :1246-1252), node 0 fixed
(``SetFixed``, :1269 / :1269), ``SetDimensions(dx, width, height)`` so Chrono's "width"
is our H (along y) and "height" our W (along z) (:1281 / :1283); loads at the last
element's end (``SetApplication(1.0)``), TIP_FORCE = TIP_MOMENT = 10 (:54-55); the tip
frame from ``EvaluateSectionFrame(1)`` and ``GetCardanAnglesXYZ``; pass when the percent
error is below 2 and the off-axis Cardan angles below 0.001 deg:

    axial pull  F = (10, 0, 0) N,  u_x = P L/(A E)          (:1349, :1355-1357 / :1351, :1357-1359)
    tip load    F = (0, 0, 10) N,  u_z = P L^3/(3 E I)      (:1519-1520, :1526-1528 / :1522-1523, :1529-1531)
    gravity     g = (0, 0, -9.80665) m/s^2, width 0.5 in, height 0.125 in,
                u_z = rho A g L^4/(8 E I)                   (:1565, :1586-1587, :1651-1660 / :1568, :1589-1590, :1655-1664)
    tip twist   M = (10, 0, 0) N m, square 0.5 in, theta = M L/(G J),
                J = 2.25 (a/2)^4, G = E/(2(1 + nu))         (:1720, :1725, :1828-1835 / :1724, :1729, :1833-1840)

with A = H W and I = H W^3/12 (bending about y).  Chrono solves one linear step
(``DoStaticLinear``); we solve the nonlinear statics by Newton (loads at the reference).
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.checks import chrono_elements as ce
from ancf.models import chrono_beam as cb

# the setup (parameters, sections, loads, textbook formulas, Chrono's tolerances per
# element and case): ``ancf.checks.chrono_elements``, cases "axial", "tip", "gravity", "twist"


def answer(element: str, case: str, E_: float = ce.E):
    """(our value as Chrono measures it, Cardan angles in deg, the Newton solution)."""
    point, angles, sol = ce.beam_solution(element, case, E_)
    return ce.measured(case, point, angles), np.degrees(angles), sol


CASES = [(el, case) for el in cb.ELEMENTS for case in ce.CASES]


@pytest.mark.parametrize("element,case", CASES)
def test_static_case_within_chrono_tolerance(element, case):
    value, angles, sol = answer(element, case)
    tolerance, angle_deg = ce.TOLERANCE[element, case]
    theory = ce.reference(element, case)
    percent = (value - theory) / theory * 100.0
    assert abs(percent) < tolerance, (element, case, value, theory, percent)
    off_axis = ce.CASES[case][1]
    assert np.all(np.abs(angles[list(off_axis)]) < angle_deg), angles
    # Newton reached rtol or the round-off floor of Q (see solve_static)
    assert sol.converged or sol.residual <= 10.0 * sol.floor
    assert sol.floor < 1e-5 and sol.iterations < 30


@pytest.mark.parametrize("element,case", CASES)
def test_static_case_follows_E(element, case):
    """With 1.05 E the answer shrinks as 1/1.05 (linear elasticity, small deflection) and
    leaves Chrono's 2 % band around the textbook value at E: the check can fail."""
    value, _, _ = answer(element, case)
    stiffer, _, _ = answer(element, case, 1.05 * ce.E)
    assert stiffer / value == pytest.approx(1.0 / 1.05, rel=1e-3)
    theory = ce.reference(element, case)
    assert abs((stiffer - theory) / theory * 100.0) > ce.TOLERANCE[element, case][0]


@pytest.mark.parametrize("element", ["3243", "3333"])
def test_batched_assembly_is_the_element_by_element_sum(element):
    """``assemble`` (all elements in one ``continuum3d.static_batch``) equals the sum of the
    element's own ``internal_force`` and ``internal_force_jacobians`` at a random state
    within 1e-13 of the largest entry; a state moved by 1e-9 m does not."""
    b = cb.Beam(element=element, n=3, L=1.0, H=0.02, W=0.03, rho=7800.0, E=2.0e11, nu=0.3,
                k1=0.85, k2=0.85)
    e = b.reference() + 1e-3 * np.random.default_rng(2).standard_normal(b.reference().size)
    Q, K = cb.assemble(b, e)
    Q0, K0, zero = np.zeros(e.size), np.zeros((e.size, e.size)), np.zeros(b.module.NDOF)
    for k in range(b.n):
        d = b.dofs(k)
        Q0[d] += b.module.internal_force(e[d], zero, *b.element_args())
        K0[np.ix_(d, d)] += b.module.internal_force_jacobians(e[d], zero, *b.element_args())[0]
    assert np.abs(Q - Q0).max() <= 1e-13 * np.abs(Q0).max()
    assert np.abs(K - K0).max() <= 1e-13 * np.abs(K0).max()
    assert np.abs(cb.assemble(b, e + 1e-9)[0] - Q0).max() > 1e-13 * np.abs(Q0).max()
