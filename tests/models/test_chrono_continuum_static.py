"""Chrono's ANCF 3843 brick small-deflection static checks, reproduced on our element.

Source: projectchrono/chrono ``src/tests/unit_tests/fea/utest_FEA_ANCFhexa_3843_Formulation.cpp``
(snapshot 7689fbc02d12c5419fa6acad8791100fd89979dd).  Every case (``:1224-1967``): 20 bricks
along x, L = 20 in, aluminium 7075-T651 rho = 2810 kg/m^3, E = 71.7 GPa, nu = 0.33
(:1250-1257), the four nodes at x = 0 fixed, loads at the tip-face centre (1, 0, 0)
(:1370), TIP_FORCE = 10 N, TIP_MOMENT = 10 N m (:54-55), g = -9.80665 m/s^2 (:1624).  The
textbook values are computed (``ancf.checks.chrono_elements``) from the formulas Chrono
cites; the tolerances are Chrono's.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.checks import chrono_elements as ce

# the setup (sections, loads, textbook formulas, Chrono's tolerances):
# ``ancf.checks.chrono_elements``
DEG = np.pi / 180


def percent(model, theory):
    return (model - theory) / theory * 100


def case(name: str, E=ce.E):
    """(what Chrono measures, its textbook value, the tip's Cardan angles in rad, the Newton
    residual) of the 20 bricks."""
    r, ang, res = ce.brick_solution(name, E)
    return ce.measured(name, r, ang), ce.reference("3843", name), ang, res


def limits(name: str):
    """(Chrono's percent tolerance, its bound on the off-axis Cardan angles in rad, the
    indices of those angles)."""
    tolerance, bound = ce.TOLERANCE["3843", name]
    return tolerance, bound * DEG, list(ce.CASES[name][1])


def test_axial_displacement():
    """Axial pull (:1224-1416): w = 0.125 in, h = 0.5 in, F = (P, 0, 0); delta = P L / (A E)."""
    model, theory, ang, res = case("axial")
    tolerance, bound, off = limits("axial")
    assert abs(percent(model, theory)) < tolerance  # 2 %, :1389
    assert np.all(np.abs(ang[off]) < bound)  # 0.01 deg, :1390-1391
    assert res < 1e-8


def test_answer_moves_with_E():
    """Doubling E halves the axial tip displacement (linear elastic, small strain)."""
    d1, d2 = case("axial")[0], case("axial", 2 * ce.E)[0]
    assert d2 / d1 == pytest.approx(0.5, rel=1e-4)


@pytest.mark.slow   # about 2.3 s (4 Newton steps)
def test_cantilever_tip_load():
    """Tip load (:1418-1615): w = 0.125 in, h = 0.5 in, F = (0, 0, P), DoStaticNonlinear;
    delta = P L^3 / (3 E I), I = w h^3 / 12 (:1578-1579)."""
    model, theory, ang, res = case("tip")
    tolerance, bound, off = limits("tip")
    assert abs(percent(model, theory)) < tolerance  # 5 %, :1585
    assert np.all(np.abs(ang[off]) < bound)  # 0.01 deg, :1587
    assert res < 1e-8


def test_cantilever_gravity():
    """Gravity (:1617-1770): w = 0.5 in, h = 0.125 in, g = (0, 0, -9.80665), consistent
    gravity of every brick, DoStaticNonlinear; delta = q L^4 / (8 E I), q = rho w h g
    (:1732-1733)."""
    model, theory, ang, res = case("gravity")
    tolerance, bound, off = limits("gravity")
    assert abs(percent(model, theory)) < tolerance  # 5 %, :1739
    assert np.all(np.abs(ang[off]) < bound)  # 0.001 deg, :1741
    assert res < 1e-5   # rounding floor of the 0.57 N load, see BrickBar.solve


@pytest.mark.slow   # about 2.8 s (5 Newton steps)
def test_axial_twist():
    """Twist (:1772-1967): square w = h = 0.5 in, moment (T, 0, 0), DoStaticLinear;
    phi = T L / (G J), G = E / (2 (1 + nu)), J = 2.25 (w/2)^4 (:1807, :1934-1935)."""
    model, theory, ang, res = case("twist")
    tolerance, bound, off = limits("twist")
    assert abs(percent(model, theory)) < tolerance  # 2 %, :1939
    assert np.all(np.abs(ang[off]) < bound)  # 0.001 deg, :1941
    assert res < 1e-8


def test_batched_assembly_is_the_element_by_element_sum():
    """``BrickBar.assemble`` (one ``continuum3d.static_batch``) equals the sum of
    ``ancf3843.internal_force`` and ``internal_force_jacobians`` brick by brick at a random
    displacement within 1e-13 of the largest entry; a displacement moved by 1e-9 m does not."""
    from ancf.elements import ancf3843
    from ancf.models.chrono_continuum import BrickBar
    bar = BrickBar(n=2, L=0.5, w=0.05, h=0.03, E=2.0e11, nu=0.3)
    u = 1e-3 * np.random.default_rng(3).standard_normal(bar.ndof)
    Q, K = bar.assemble(u)
    e0, zero = ancf3843.reference_coordinates(*bar.dims()), np.zeros(96)
    Q0, K0 = np.zeros(bar.ndof), np.zeros((bar.ndof, bar.ndof))
    for i in range(bar.n):
        d = bar.element_dofs(i)
        args = (e0 + u[d], zero, *bar.dims(), bar.E, bar.nu)
        Q0[d] += ancf3843.internal_force(*args, ngauss=bar.ngauss)
        K0[np.ix_(d, d)] += ancf3843.internal_force_jacobians(*args, ngauss=bar.ngauss)[0]
    assert np.abs(Q - Q0).max() <= 1e-13 * np.abs(Q0).max()
    assert np.abs(K - K0).max() <= 1e-13 * np.abs(K0).max()
    assert np.abs(bar.assemble(u + 1e-9, tangent=False)[0] - Q0).max() > 1e-13 * np.abs(Q0).max()
