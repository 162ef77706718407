"""Every friction law of :mod:`ancf.belts.friction` (its LAWS table) against one contract:
the force on a sliding velocity of 1 (planar) or 3 (plate) components, and the
derivatives its ``chain`` gives, equal to central differences of its ``force`` on each
branch (points whose branch does not change within the step)."""
from __future__ import annotations

import numpy as np
import pytest

from ancf.belts import friction

H = 1e-6
RTOL = 1e-7
PRM = np.array([1e7, 10.0, 1.2, 1e5])  # k_p, c_p, mu, nu_s (Table 3.1)
FN = 50.0                              # normal force, N/m


def _velocities(n, rng):
    """Sliding velocities (n,) from well inside the linear branch to well beyond saturation
    (mu F_n / nu_s = 6e-4 m/s), each direction random."""
    for speed in (0.0, 1e-5, 3e-4, 2e-3, 0.5, 7.0):
        u = rng.standard_normal(n)
        yield speed * u / np.linalg.norm(u)


def _force(law, v, Fn):
    f = np.zeros(v.size)
    branch = law[0](tuple(v), np.linalg.norm(v), Fn, PRM, f)
    return branch, f


def _chain(law, branch, v, Fn, G, gF):
    D = np.zeros((v.size, G.shape[1]))
    law[1](branch, tuple(v), np.linalg.norm(v), Fn, PRM, G, tuple(gF), D)
    return D


@pytest.mark.parametrize("name", sorted(friction.LAWS))
@pytest.mark.parametrize("n", [1, 3])
def test_chain_matches_central_differences_of_the_force(name, n):
    law = friction.LAWS[name]
    rng = np.random.default_rng(n)
    for v in _velocities(n, rng):
        branch, f = _force(law, v, FN)
        dv, dF = np.zeros((n, n)), np.zeros((n, 1))
        for j in range(n):
            e = H * max(np.linalg.norm(v), 1e-3) * np.eye(n)[j]
            (bp, fp), (bm, fm) = _force(law, v + e, FN), _force(law, v - e, FN)
            assert bp == bm == branch, (name, v, j)
            dv[:, j] = (fp - fm) / (2 * e[j])
        (bp, fp), (bm, fm) = _force(law, v, FN * (1 + H)), _force(law, v, FN * (1 - H))
        assert bp == bm == branch, (name, v)
        dF[:, 0] = (fp - fm) / (2 * FN * H)
        exact_v = _chain(law, branch, v, FN, np.eye(n), np.zeros(n))
        exact_F = _chain(law, branch, v, FN, np.zeros((n, 1)), np.ones(1))
        scale = max(np.abs(exact_v).max(), PRM[2])
        np.testing.assert_allclose(dv, exact_v, rtol=RTOL, atol=RTOL * scale)
        np.testing.assert_allclose(dF, exact_F, rtol=RTOL, atol=RTOL * PRM[2])


@pytest.mark.parametrize("name", sorted(friction.LAWS))
def test_the_planar_law_is_the_plate_law_on_a_line(name):
    """A sliding velocity along one axis gives the same force from 1 and 3 components."""
    law = friction.LAWS[name]
    for speed in (-2.0, -1e-4, 0.0, 3e-4, 5.0):
        _, f1 = _force(law, np.array([speed]), FN)
        _, f3 = _force(law, np.array([0.0, speed, 0.0]), FN)
        np.testing.assert_allclose(f3, [0.0, f1[0], 0.0], rtol=1e-15, atol=0.0)


def test_creep_rate_law_is_tri_linear():
    """Eq. 3.23 / Fig. 3.3: -nu_s v below mu F_n / nu_s, -sign(v) mu F_n above."""
    law = friction.LAWS["creep-rate"]
    mu, nu = PRM[2], PRM[3]
    v_sat = mu * FN / nu
    for v, expected in ((0.5 * v_sat, -nu * 0.5 * v_sat), (-0.5 * v_sat, nu * 0.5 * v_sat),
                        (3 * v_sat, -mu * FN), (-3 * v_sat, mu * FN)):
        _, f = _force(law, np.array([v]), FN)
        assert f[0] == pytest.approx(expected, rel=1e-14)
    assert friction.force is law[0] and friction.chain is law[1]
