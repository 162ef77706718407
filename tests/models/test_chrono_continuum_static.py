"""Chrono's ANCF 3843 brick small-deflection static checks, reproduced on our element.

Source: projectchrono/chrono ``src/tests/unit_tests/fea/utest_FEA_ANCFhexa_3843_Formulation.cpp``
(snapshot 7689fbc02d12c5419fa6acad8791100fd89979dd).  Every case (``:1224-1967``): 20 bricks
along x, L = 20 in, aluminium 7075-T651 rho = 2810 kg/m^3, E = 71.7 GPa, nu = 0.33
(:1250-1257), the four nodes at x = 0 fixed, loads at the tip-face centre (1, 0, 0)
(:1370), TIP_FORCE = 10 N, TIP_MOMENT = 10 N m (:54-55).  The textbook values are computed
here from the formulas Chrono cites; the tolerances are Chrono's.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.models.chrono_continuum import BrickBar

IN = 0.0254                        # m per inch
L, RHO, E, NU = 20 * IN, 2810.0, 71.7e9, 0.33
P, T, GRAV = 10.0, 10.0, -9.80665  # N, N m, m/s^2 (:54-55, :1624)
DEG = np.pi / 180


def bar(w, h, E=E):
    return BrickBar(n=20, L=L, w=w, h=h, E=E, nu=NU, rho=RHO)


def percent(model, theory):
    return (model - theory) / theory * 100


def axial(E=E):
    """Axial pull (:1224-1416): w = 0.125 in, h = 0.5 in, F = (P, 0, 0); delta = P L / (A E)."""
    b = bar(0.125 * IN, 0.5 * IN, E)
    u, _, res = b.solve(b.tip_force([P, 0, 0]))
    r, ang = b.tip_frame(u)
    return r[0] - L, P * L / (b.w * b.h * E), ang, res


def test_axial_displacement():
    model, theory, ang, res = axial()
    assert abs(percent(model, theory)) < 2.0                  # :1389
    assert np.all(np.abs(ang) < 0.01 * DEG)                   # :1390-1391
    assert res < 1e-8


def test_answer_moves_with_E():
    """Doubling E halves the axial tip displacement (linear elastic, small strain)."""
    d1, d2 = axial()[0], axial(2 * E)[0]
    assert d2 / d1 == pytest.approx(0.5, rel=1e-4)


@pytest.mark.slow   # about 2.3 s (4 Newton steps)
def test_cantilever_tip_load():
    """Tip load (:1418-1615): w = 0.125 in, h = 0.5 in, F = (0, 0, P), DoStaticNonlinear;
    delta = P L^3 / (3 E I), I = w h^3 / 12 (:1578-1579)."""
    b = bar(0.125 * IN, 0.5 * IN)
    u, _, res = b.solve(b.tip_force([0, 0, P]))
    r, ang = b.tip_frame(u)
    theory = P * L**3 / (3 * E * b.w * b.h**3 / 12)
    assert abs(percent(r[2], theory)) < 5.0                    # :1585
    assert abs(ang[0]) < 0.01 * DEG and abs(ang[2]) < 0.01 * DEG   # :1587
    assert res < 1e-8


def test_cantilever_gravity():
    """Gravity (:1617-1770): w = 0.5 in, h = 0.125 in, g = (0, 0, -9.80665), consistent
    gravity of every brick, DoStaticNonlinear; delta = q L^4 / (8 E I), q = rho w h g
    (:1732-1733)."""
    b = bar(0.5 * IN, 0.125 * IN)
    u, _, res = b.solve(b.gravity([0, 0, GRAV]))
    r, ang = b.tip_frame(u)
    theory = RHO * b.w * b.h * GRAV * L**4 / (8 * E * b.w * b.h**3 / 12)
    assert abs(percent(r[2], theory)) < 5.0                    # :1739
    assert abs(ang[0]) < 0.001 * DEG and abs(ang[2]) < 0.001 * DEG  # :1741
    assert res < 1e-5   # rounding floor of the 0.57 N load, see BrickBar.solve


@pytest.mark.slow   # about 2.8 s (5 Newton steps)
def test_axial_twist():
    """Twist (:1772-1967): square w = h = 0.5 in, moment (T, 0, 0), DoStaticLinear;
    phi = T L / (G J), G = E / (2 (1 + nu)), J = 2.25 (w/2)^4 (:1807, :1934-1935)."""
    b = bar(0.5 * IN, 0.5 * IN)
    u, _, res = b.solve(b.tip_moment([T, 0, 0]))
    _, ang = b.tip_frame(u)
    theory = T * L / (E / (2 * (1 + NU)) * 2.25 * (b.w / 2) ** 4)
    assert abs(percent(ang[0], theory)) < 2.0                  # :1939
    assert abs(ang[1]) < 0.001 * DEG and abs(ang[2]) < 0.001 * DEG  # :1941
    assert res < 1e-8
