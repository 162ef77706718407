"""Every friction law of :mod:`ancf.belts.friction` (its LAWS table) against one contract:
the force on a sliding velocity of 1 (planar) or 3 (plate) components, and the
derivatives its ``chain`` gives, equal to central differences of its ``force`` on each
branch (points whose branch does not change within the step); and the kernels' dispatch
(``friction.force``, ``friction.chain`` on the code in prm) reaching every row."""
from __future__ import annotations

import numpy as np
import pytest

from ancf.belts import friction

H = 1e-6
RTOL = 1e-7
MU = 1.2                               # Table 3.1
FN = 50.0                              # normal force, N/m
V_REG = 1e-3                           # m/s: the Coulomb law's regularisation speed
PRM = {"creep-rate": friction.contact_vector(1e7, 10.0, "creep-rate", MU, 1e5),  # Table 3.1
       "coulomb": friction.contact_vector(1e7, 10.0, "coulomb", MU, V_REG)}


def _velocities(n, rng):
    """Sliding velocities (n,) from well inside the linear branch to well beyond saturation
    (creep-rate: mu F_n / nu_s = 6e-4 m/s; Coulomb: v_reg = 1e-3 m/s), each direction
    random."""
    for speed in (0.0, 1e-5, 3e-4, 2e-3, 0.5, 7.0):
        u = rng.standard_normal(n)
        yield speed * u / np.linalg.norm(u)


def _force(name, v, Fn, law=None):
    """The force of row ``name`` (or of ``law``, a (force, chain) pair, on its prm)."""
    f = np.zeros(v.size)
    branch = (law or friction.LAWS[name])[0](tuple(v), np.linalg.norm(v), Fn, PRM[name], f)
    return branch, f


def _chain(name, branch, v, Fn, G, gF, law=None):
    D = np.zeros((v.size, G.shape[1]))
    (law or friction.LAWS[name])[1](branch, tuple(v), np.linalg.norm(v), Fn, PRM[name], G,
                                    tuple(gF), D)
    return D


def test_every_law_has_a_test_vector():
    assert set(PRM) == set(friction.LAWS)


@pytest.mark.parametrize("name", sorted(friction.LAWS))
@pytest.mark.parametrize("n", [1, 3])
def test_chain_matches_central_differences_of_the_force(name, n):
    rng = np.random.default_rng(n)
    for v in _velocities(n, rng):
        branch, f = _force(name, v, FN)
        dv, dF = np.zeros((n, n)), np.zeros((n, 1))
        for j in range(n):
            e = H * max(np.linalg.norm(v), 1e-3) * np.eye(n)[j]
            (bp, fp), (bm, fm) = _force(name, v + e, FN), _force(name, v - e, FN)
            assert bp == bm == branch, (name, v, j)
            dv[:, j] = (fp - fm) / (2 * e[j])
        (bp, fp), (bm, fm) = _force(name, v, FN * (1 + H)), _force(name, v, FN * (1 - H))
        assert bp == bm == branch, (name, v)
        dF[:, 0] = (fp - fm) / (2 * FN * H)
        exact_v = _chain(name, branch, v, FN, np.eye(n), np.zeros(n))
        exact_F = _chain(name, branch, v, FN, np.zeros((n, 1)), np.ones(1))
        scale = max(np.abs(exact_v).max(), MU)
        np.testing.assert_allclose(dv, exact_v, rtol=RTOL, atol=RTOL * scale)
        np.testing.assert_allclose(dF, exact_F, rtol=RTOL, atol=RTOL * MU)


@pytest.mark.parametrize("name", sorted(friction.LAWS))
def test_the_planar_law_is_the_plate_law_on_a_line(name):
    """A sliding velocity along one axis gives the same force from 1 and 3 components."""
    for speed in (-2.0, -1e-4, 0.0, 3e-4, 5.0):
        _, f1 = _force(name, np.array([speed]), FN)
        _, f3 = _force(name, np.array([0.0, speed, 0.0]), FN)
        np.testing.assert_allclose(f3, [0.0, f1[0], 0.0], rtol=1e-15, atol=0.0)


def test_creep_rate_law_is_tri_linear():
    """Eq. 3.23 / Fig. 3.3: -nu_s v below mu F_n / nu_s, -sign(v) mu F_n above."""
    mu, nu = PRM["creep-rate"][3:5]
    v_sat = mu * FN / nu
    for v, expected in ((0.5 * v_sat, -nu * 0.5 * v_sat), (-0.5 * v_sat, nu * 0.5 * v_sat),
                        (3 * v_sat, -mu * FN), (-3 * v_sat, mu * FN)):
        _, f = _force("creep-rate", np.array([v]), FN)
        assert f[0] == pytest.approx(expected, rel=1e-14)


def test_coulomb_law_is_mu_f_n_tanh():
    """f = -mu F_n tanh(v / v_reg) (numpy's tanh), of slope -mu F_n / v_reg at v = 0 and
    within 1e-12 of the Coulomb force -sign(v) mu F_n beyond 15 v_reg."""
    for v in (-3.0, -2e-3, -1e-4, 0.0, 5e-4, 1e-3, 0.02):
        _, f = _force("coulomb", np.array([v]), FN)
        assert f[0] == pytest.approx(-MU * FN * np.tanh(v / V_REG), rel=1e-14, abs=0.0)
    D = _chain("coulomb", friction.SMOOTH, np.zeros(1), FN, np.eye(1), np.zeros(1))
    assert D[0, 0] == pytest.approx(-MU * FN / V_REG, rel=1e-15)
    _, f = _force("coulomb", np.array([-15 * V_REG]), FN)
    assert abs(f[0] - MU * FN) <= 1e-12 * MU * FN


@pytest.mark.parametrize("name", sorted(friction.LAWS))
@pytest.mark.parametrize("n", [1, 3])
def test_the_kernels_dispatch_reaches_every_law(name, n):
    """friction.force and friction.chain on the row's prm give the row's own force,
    branch and derivatives, bit for bit, at every test velocity."""
    both = (friction.force, friction.chain)
    rng = np.random.default_rng(10 + n)
    G, gF = rng.standard_normal((n, 4)), rng.standard_normal(4)
    for v in _velocities(n, rng):
        (b, f), (bd, fd) = _force(name, v, FN), _force(name, v, FN, law=both)
        assert b == bd and np.array_equal(f, fd), (name, v)
        assert np.array_equal(_chain(name, b, v, FN, G, gF),
                              _chain(name, b, v, FN, G, gF, law=both)), (name, v)


def test_contact_vector_refuses_an_unknown_law_or_wrong_count():
    with pytest.raises(ValueError, match="friction law 'bristle' with 2 values; allowed: "
                                         "creep-rate"):
        friction.contact_vector(1e7, 10.0, "bristle", 1.0, 2.0)
    with pytest.raises(ValueError, match="friction law 'coulomb' with 1 values"):
        friction.contact_vector(1e7, 10.0, "coulomb", 1.0)
