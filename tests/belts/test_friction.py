"""Every friction law of :mod:`ancf.belts.friction` (its LAWS table) against one contract:
the force on a sliding velocity of 1 (planar) or 3 (plate) components, and the
derivatives its ``chain`` gives, equal to central differences of its ``force`` on each
branch (points whose branch does not change within the step); and the kernels' dispatch
(``friction.force``, ``friction.chain`` on the law's code in its contact record) reaching
every row."""
from __future__ import annotations

import numpy as np
import pytest

from ancf.belts import friction

H = 1e-6
RTOL = 1e-7
MU = 1.2                               # Table 3.1
FN = 50.0                              # normal force, N/m
V_REG = 1e-3                           # m/s: the Coulomb law's regularisation speed
PRM = {"creep-rate": friction.contact_record(1e7, 10.0, "creep-rate", MU, 1e5),  # Table 3.1
       "coulomb": friction.contact_record(1e7, 10.0, "coulomb", MU, V_REG)}


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
    mu, nu = PRM["creep-rate"].mu, PRM["creep-rate"].nu_s
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


def test_contact_record_refuses_an_unknown_law_or_wrong_count():
    with pytest.raises(ValueError, match="friction law 'bristle' with 2 values; allowed: "
                                         "creep-rate"):
        friction.contact_record(1e7, 10.0, "bristle", 1.0, 2.0)
    with pytest.raises(ValueError, match="friction law 'coulomb' with 1 values"):
        friction.contact_record(1e7, 10.0, "coulomb", 1.0)


# ------------------------------------------------------------------ the bristle point law
K_T, D_T, STEP = 4e8, 5758.0, 2e-5  # a bristle (THREAD's k_t per unit length), a step, s


def _bristle_prm(kt=K_T, dt=D_T):
    return friction.contact_record(0.0, 0.0, "bristle", MU, kt, dt)


def _bristle(v, z0, Fn, prm):
    f, z1 = np.zeros(v.size), np.zeros(v.size)
    branch = friction.bristle_force(tuple(v), tuple(z0), STEP, Fn, prm, f, z1)
    return branch, f, z1


def _states(n, rng):
    """(v, z0): deflections from 0 to past the Coulomb limit mu F_n / k_t = 1.5e-7 m, and
    sliding velocities from 0 to 7 m/s, directions random."""
    for zs in (0.0, 5e-8, 1e-7, 1e-6):
        for speed in (0.0, 1e-3, 4e-3, 0.5, 7.0):
            a, b = rng.standard_normal(n), rng.standard_normal(n)
            yield speed * a / np.linalg.norm(a), zs * b / np.linalg.norm(b)


@pytest.mark.parametrize("n", [1, 3])
def test_bristle_chain_matches_central_differences(n):
    """The FD contract of the LAWS rows, in v and F_n (z0 and the step are fixed within a
    step); both branches are reached."""
    prm, rng, seen = _bristle_prm(), np.random.default_rng(20 + n), set()
    for v, z0 in _states(n, rng):
        branch, f, _ = _bristle(v, z0, FN, prm)
        seen.add(branch)
        dv = np.zeros((n, n))
        for j in range(n):
            e = H * max(np.linalg.norm(v), 1e-3) * np.eye(n)[j]
            (bp, fp, _), (bm, fm, _) = _bristle(v + e, z0, FN, prm), _bristle(v - e, z0, FN, prm)
            assert bp == bm == branch, (v, z0, j)
            dv[:, j] = (fp - fm) / (2 * e[j])
        (bp, fp, _), (bm, fm, _) = _bristle(v, z0, FN * (1 + H), prm), \
            _bristle(v, z0, FN * (1 - H), prm)
        assert bp == bm == branch, (v, z0)
        dF = ((fp - fm) / (2 * FN * H))[:, None]
        D = np.zeros((n, n))
        friction.bristle_chain(branch, tuple(v), tuple(z0), STEP, FN, prm, np.eye(n),
                               tuple(np.zeros(n)), D)
        DF = np.zeros((n, 1))
        friction.bristle_chain(branch, tuple(v), tuple(z0), STEP, FN, prm, np.zeros((n, 1)),
                               (1.0,), DF)
        scale = max(np.abs(D).max(), MU)
        np.testing.assert_allclose(dv, D, rtol=RTOL, atol=RTOL * scale)
        np.testing.assert_allclose(dF, DF, rtol=RTOL, atol=RTOL * MU)
    assert seen == {friction.STICK, friction.SLIP}


def test_bristle_sticks_as_a_spring_and_damper_and_slips_at_the_coulomb_limit():
    """Stick: f = -(k_t (z0 + h v) + d_t v), z1 = z0 + h v; slip: |f| = mu F_n against
    that trial force, and the spring then holds the limit, k_t |z1| = mu F_n."""
    prm = _bristle_prm()
    z0, v = np.array([2e-8, -3e-8, 0.0]), np.array([1e-3, 2e-3, -1e-3])
    branch, f, z1 = _bristle(v, z0, FN, prm)
    trial = -(K_T * (z0 + STEP * v) + D_T * v)
    assert branch == friction.STICK and np.linalg.norm(trial) < MU * FN
    np.testing.assert_allclose(f, trial, rtol=1e-14)
    np.testing.assert_allclose(z1, z0 + STEP * v, rtol=1e-15)
    v = np.array([0.3, -0.1, 0.05])
    branch, f, z1 = _bristle(v, z0, FN, prm)
    trial = -(K_T * (z0 + STEP * v) + D_T * v)
    assert branch == friction.SLIP
    np.testing.assert_allclose(f, MU * FN * trial / np.linalg.norm(trial), rtol=1e-14)
    assert K_T * np.linalg.norm(z1) == pytest.approx(MU * FN, rel=1e-14)


def test_bristle_without_its_spring_is_the_creep_rate_law():
    """k_t = 0: the bristle law with d_t is the creep-rate law with nu_s = d_t (the same
    force and branch, linear = stick, saturated = slip)."""
    prm = _bristle_prm(kt=0.0, dt=1e5)
    rng = np.random.default_rng(3)
    for v in _velocities(3, rng):
        branch, f, _ = _bristle(v, np.zeros(3), FN, prm)
        b_cr, f_cr = _force("creep-rate", v, FN)
        assert (branch == friction.STICK) == (b_cr == friction.LINEAR), v
        np.testing.assert_allclose(f, f_cr, rtol=1e-14, atol=0.0)


def test_the_contact_record_holds_each_law_s_parameters_by_name():
    """Every registered law is a row of ALL_PARAMS with its code; its values land in the
    record's fields of its parameters' names, every other parameter field 0."""
    assert list(friction.ALL_PARAMS) == ["creep-rate", "coulomb", "bristle"]
    fields = set(friction.CONTACT.names) - {"k_p", "c_p", "law"}
    for name, params in friction.ALL_PARAMS.items():
        values = [1.5 + i for i in range(len(params))]
        rec = friction.contact_record(3.0, 4.0, name, *values)
        assert (rec.k_p, rec.c_p, rec.law) == (3.0, 4.0, friction.CODES[name])
        assert [rec[p.name] for p in params] == values
        assert all(rec[f] == 0.0 for f in fields - {p.name for p in params})
        assert friction.has_state(rec) == (name in friction.STATE_LAWS)
