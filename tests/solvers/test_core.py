"""The compiled core against independent computations.

* band LU (partial pivoting) against a dense solve, on random and indefinite
  band matrices; inertia counts against dense eigenvalues;
* the reduced pattern: ``T^T K T`` scattered straight into band storage equals the
  product formed with sparse matrices, for an open chain and for a closed loop
  (tied end node, renumbered by reverse Cuthill-McKee);
* the static stability check by inertia against ``eigvalsh`` on the cases behind
  the report's zero-energy-mode table (stable, unstable, singular);
* the compiled generalised-alpha loop (modified Newton) against the Python
  stepper (full Newton) on the pendulum and the rheonomic spinning beam.
"""
from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla

from ancf.core.constraints import Elimination
from ancf.core.forces import Forces, Gravity
from ancf.core.pattern import ReducedPattern
from ancf.scenes import SCENES
from ancf.scenes import beam_static as bs
from ancf.scenes import pendulum, spinning_beam
from ancf.scenes import beam_dynamic as bd
from ancf.solvers import banded
from ancf.solvers.generalized_alpha import AlphaOptions, integrate_generalized_alpha
from ancf.solvers.linear import Singular
from ancf.solvers.static import NewtonOptions, solve_static, stability_at


def _band_of(A, kl):
    n = A.shape[0]
    AB = np.zeros((n, 3 * kl + 1))
    for i in range(n):
        for j in range(max(0, i - kl), min(n, i + kl + 1)):
            AB[i, j - i + kl] = A[i, j]
    return AB


def _random_band(n, kl, seed, symmetric=False):
    rng = np.random.default_rng(seed)
    A = rng.standard_normal((n, n))
    A = np.triu(np.tril(A, kl), -kl)
    return A + A.T if symmetric else A


def _factor_and_solve(A, kl, b, pivoting):
    """(band factors, pivots, solution) of A x = b by banded.lu and banded.solve."""
    AB = _band_of(A, kl)
    piv = np.empty(A.shape[0], dtype=np.int64)
    assert banded.lu(AB, kl, piv, pivoting) == 0
    x = b.copy()
    banded.solve(AB, kl, piv, x)
    return AB, piv, x


@pytest.mark.parametrize("n,kl", [(1, 0), (7, 2), (40, 5), (200, 7)])
def test_band_lu_solves_like_dense(n, kl):
    A = _random_band(n, kl, seed=n)  # general, needs row interchanges
    b = np.arange(n, dtype=float) + 1.0
    _, _, x = _factor_and_solve(A, kl, b, True)
    np.testing.assert_allclose(x, np.linalg.solve(A, b), rtol=1e-9, atol=1e-12)


@pytest.mark.parametrize("n,kl", [(7, 2), (40, 5), (200, 7)])
def test_band_solve_without_interchanges_reads_kl_columns_of_u(n, kl):
    """Factors without a row interchange (unpivoted, diagonally dominant) solve like dense,
    and garbage in the fill columns, which such factors never write, changes nothing:
    the solve reads U up to kl columns past the diagonal only."""
    A = _random_band(n, kl, seed=n) + 4.0 * (kl + 1) * np.eye(n)
    b = np.arange(n, dtype=float) + 1.0
    AB, piv, x = _factor_and_solve(A, kl, b, False)
    np.testing.assert_allclose(x, np.linalg.solve(A, b), rtol=1e-9, atol=1e-12)
    AB[:, 2 * kl + 1:] = np.nan
    y = b.copy()
    banded.solve(AB, kl, piv, y)
    assert y.tobytes() == x.tobytes()


@pytest.mark.parametrize("seed", range(4))
def test_inertia_counts_match_eigenvalues(seed):
    A = _random_band(60, 4, seed, symmetric=True)
    lam = np.linalg.eigvalsh(A)
    for s in (-1.0, 0.0, 0.5, lam[10] + 1e-6):
        assert banded.count_below(_band_of(A, 4), 4, s) == int(np.sum(lam < s))
    top = banded.largest_magnitude(_band_of(A, 4), 4, 200)
    assert 0.9 * np.abs(lam).max() <= top <= np.abs(lam).max() * (1 + 1e-12)


def _cantilever_model(p, tie_loop=False):
    mesh, q0, asm = bs.build(p)
    elim = Elimination(mesh.n_dofs)
    for slot in ("r", "r_y"):
        for k in (0, 1):
            elim.fix(mesh.dof(0, slot, k), q0[mesh.dof(0, slot, k)])
    if tie_loop:  # the last node's slope follows the middle node's: a long-range coupling
        mid = mesh.n_nodes // 2
        for k in (0, 1):
            elim.tie(mesh.dof(mesh.n_nodes - 1, "r_y", k), mesh.dof(mid, "r_y", k))
    return mesh, q0, asm, elim


@pytest.mark.parametrize("tie_loop", [False, True])
def test_pattern_scatter_equals_sparse_product(tie_loop):
    p = SCENES["cantilever"].resolve({"n_elements": 24})
    mesh, q0, asm, elim = _cantilever_model(p, tie_loop)
    T, g, _ = elim.build()
    pat = ReducedPattern(asm.n_dofs, [asm.groups[0].dofmap], T)
    rng = np.random.default_rng(3)
    q = q0 + 1e-2 * rng.standard_normal(q0.size)
    q = pat.expand(pat.restrict(q), g)
    grad, K = pat.assemble(asm, q)
    gq, Kq = asm.gradient_tangent(q)
    perm = np.argsort(pat.order)  # reduced index at each position
    np.testing.assert_allclose(grad, (T.T @ gq)[perm], rtol=1e-12, atol=1e-6)
    Kref = (T.T @ Kq @ T).toarray()[np.ix_(perm, perm)]
    np.testing.assert_allclose(pat.as_csr(K).toarray(), Kref, rtol=1e-12, atol=1e-3)
    if tie_loop:  # renumbering kept the band narrow although the tie couples node 12 and 24
        assert pat.kl < 0.5 * pat.n


@pytest.mark.parametrize("tie_loop", [False, True])
def test_selection_is_the_sparse_elimination(tie_loop):
    """Elimination.selection() (no scipy) is build()'s T: the same matrix, the same g and
    free list, and the same reduced pattern from either."""
    p = SCENES["cantilever"].resolve({"n_elements": 24})
    _, _, asm, elim = _cantilever_model(p, tie_loop)
    (S, gs, fs), (T, g, free) = elim.selection(), elim.build()
    assert S.shape == T.shape and (S.tocsr() != T).nnz == 0
    assert gs.tolist() == g.tolist() and fs.tolist() == free.tolist()
    a, b = (ReducedPattern(asm.n_dofs, [asm.groups[0].dofmap], X) for X in (S, T))
    assert (a.n, a.kl, a.band) == (b.n, b.kl, b.band)
    for x, y in zip((a.order, a.qsel, a.zsel, *a.groups[0]), (b.order, b.qsel, b.zsel, *b.groups[0])):
        assert x.tolist() == y.tolist()


@pytest.mark.parametrize("tie_loop", [False, True])
def test_solve_keeps_the_tangent_it_converged_on(tie_loop):
    """A compiled band solve hands its last tangent on (StaticResult.tangent): the very
    numbers the pattern assembles at the solution, so the stability check skips that
    assembly; with force terms (the Python iterations) there is none to hand on."""
    p = SCENES["cantilever"].resolve({"n_elements": 24})
    mesh, q0, asm, elim = _cantilever_model(p, tie_loop)
    Qk = np.zeros(mesh.n_dofs)
    Qk[mesh.dof(mesh.n_nodes - 1, "r", 1)] = p["F"]
    res = solve_static(asm, elim, Qk, q0, NewtonOptions(n_steps=10))
    assert res.converged and res.pattern.compiled(asm) is not None
    np.testing.assert_array_equal(res.tangent, res.pattern.assemble(asm, res.q)[1])
    assert stability_at(asm, res.pattern, res.q, tangent=res.tangent) == stability_at(
        asm, res.pattern, res.q)
    forces = Forces(asm.n_dofs, [Gravity(asm)])  # zero: a static model has no mass
    assert solve_static(asm, elim, Qk, q0, NewtonOptions(n_steps=10), forces=forces).tangent is None


@pytest.mark.parametrize("overrides", [
    {},                                                               # stable
    {"h": 0.5, "nu": 0.0, "integration": "report-selective", "n_elements": 32},  # unstable
    {"integration": "all=2x1", "n_elements": 4},                       # zero-energy modes
])
def test_stability_by_inertia_matches_eigenvalues(overrides):
    p = SCENES["cantilever"].resolve(overrides)
    mesh, q0, asm, elim = _cantilever_model(p)
    out, res = SCENES["cantilever"].execute(overrides)
    q = res.extra["q"]
    T, _, _ = elim.build()
    lam = sla.eigvalsh((T.T @ asm.gradient_tangent(q)[1] @ T).toarray())
    top = np.abs(lam).max()
    r = out["results"]
    assert r["negative_tangent_eigenvalues"] == int(np.sum(lam < -1e-9 * top))
    assert r["zero_tangent_eigenvalues"] == int(np.sum(np.abs(lam) <= 1e-14 * top))
    assert r["lowest_tangent_eigenvalue_rel"] == pytest.approx(lam[0] / top, rel=0.05)


def _alpha_pair(scene, p, setup):
    mdl = setup(p)[3]
    q0 = setup(p)[1]
    x0, v0 = mdl.initial(q0, np.zeros_like(q0))
    t = bd.times(p)
    opt = AlphaOptions(dt=p["dt"], rho_inf=p["rho_inf"])
    fast = integrate_generalized_alpha(mdl, x0, v0, t, opt)
    slow = integrate_generalized_alpha(mdl, x0, v0, t, AlphaOptions(dt=p["dt"], rho_inf=p["rho_inf"],
                                                                    compiled=False))
    return fast, slow


@pytest.mark.parametrize("scene,setup,overrides,fewer", [
    ("pendulum", pendulum.setup, {"n_elements": 8, "t_end": 0.5}, 5),
    ("spinning-beam", spinning_beam.setup, {"t_end": 2.0, "mean_window": 1.0}, 3),
])
def test_compiled_alpha_matches_python_stepper(scene, setup, overrides, fewer):
    p = SCENES[scene].resolve({"integrator": "generalized-alpha", **overrides})
    fast, slow = _alpha_pair(scene, p, setup)
    assert fast.converged and slow.converged
    assert np.max(np.abs(fast.q - slow.q)) <= 1e-8 * (1 + np.max(np.abs(slow.q)))
    assert fast.nlu < slow.nlu / fewer  # the factorisation is kept across steps


def test_alpha_refresh_ratio_trades_factorisations_for_iterations():
    """The default refresh ratio (AlphaOptions) refactors more often than the march's
    REFRESH_RATIO and so takes fewer Newton iterations, on the same trajectory: both
    within the Newton tolerance of the Python stepper's full Newton."""
    from dataclasses import replace
    from ancf.solvers.alpha_march import REFRESH_RATIO
    p = SCENES["pendulum"].resolve({"integrator": "generalized-alpha"})
    fast, slow = _alpha_pair("pendulum", p, pendulum.setup)
    mdl, q0 = pendulum.setup(p)[3], pendulum.setup(p)[1]
    x0, v0 = mdl.initial(q0, np.zeros_like(q0))
    opt = replace(AlphaOptions(dt=p["dt"], rho_inf=p["rho_inf"]), refresh_ratio=REFRESH_RATIO)
    lazy = integrate_generalized_alpha(mdl, x0, v0, bd.times(p), opt)
    assert AlphaOptions().refresh_ratio < REFRESH_RATIO
    for run in (fast, lazy):
        assert np.max(np.abs(run.q - slow.q)) <= 1e-8 * (1 + np.max(np.abs(slow.q)))
    assert fast.nlu > lazy.nlu and fast.newton_iterations < 0.9 * lazy.newton_iterations


def test_registry_allocates_named_blocks():
    from ancf.core.mesh import BeamMesh
    from ancf.core.registry import Registry
    reg = Registry()
    beam = BeamMesh(2.0, 4, ("r", "r_y"), registry=reg, name="belt")
    theta = reg.add("pulley.theta", 1, "rigid")
    assert beam.dofmap.max() == theta.start - 1 and reg.n == theta.start + 1
    assert reg.index("pulley.theta") == 20 and [b.name for b in reg.of_kind("rigid")] == ["pulley.theta"]
    with pytest.raises(ValueError, match="already registered"):
        reg.add("belt", 3)


def _ring(cls, n, radius=0.5):
    """A closed ring of n elements on a circle (a wrapped reference geometry)."""
    from ancf.core.mesh import BeamMesh
    from ancf.core.quadrature import RectangularSection

    def circle(s):
        a = np.asarray(s) / radius
        return (np.stack([radius * np.cos(a), radius * np.sin(a)], -1),
                np.stack([-np.sin(a), np.cos(a)], -1))
    m = BeamMesh(2 * np.pi * radius, n, cls.slots, closed=True, curve=circle)
    q0 = m.reference()
    el = cls(m.lengths, q0[m.dofmap], RectangularSection(0.01, 0.002), E=2e11, nu=0.3, rho=7850.0)
    return m, q0, el


@pytest.mark.parametrize("cls", list(bs.ELEMENTS.values()))
def test_closed_ring_is_a_mesh_feature(cls):
    m, q0, el = _ring(cls, 24)
    assert m.n_nodes == 24 and m.dofmap[-1, -1] == m.per_node - 1  # last element ends at node 0
    assert np.all(el.energy(q0[m.dofmap]) == 0.0)  # the wrapped reference is unstrained
    c, s = np.cos(0.3), np.sin(0.3)  # a rigid rotation of the whole ring stays unstrained
    R = np.array([[c, -s], [s, c]])
    q = (q0.reshape(-1, 2) @ R.T).ravel()
    U = el.energy(q[m.dofmap])
    assert np.max(np.abs(U)) <= 1e-9 * el.energy(1.001 * q0[m.dofmap]).max()
    pat = ReducedPattern(m.n_dofs, [m.dofmap], __import__("scipy.sparse").sparse.identity(m.n_dofs, format="csr"))
    assert pat.band and pat.kl < 3 * m.per_node  # RCM keeps the loop banded


def test_gravity_in_statics_matches_timoshenko_uniform_load():
    """A force term (gravity) in the static solver: a cantilever under its own weight
    against the closed-form Timoshenko tip deflection (small load: nonlinearity ~1e-7)."""
    from analytic.timoshenko_cantilever import tip_deflection

    p = SCENES["cantilever"].resolve({"n_elements": 64, "nu": 0.0})
    p["rho"] = 7850.0
    mesh, q0, asm, elim = _cantilever_model(p)
    forces = Forces(asm.n_dofs, [Gravity(asm, (0.0, -9.81))])
    res = solve_static(asm, elim, np.zeros(asm.n_dofs), q0, forces=forces)
    w = res.q[mesh.dof(64, "r", 1)]
    ref = tip_deflection(p["E"], 0.0, p["L"], p["h"], p["b"], -7850.0 * 9.81 * p["h"] * p["b"], p["ks"])
    assert res.converged and w == pytest.approx(ref, rel=1e-6)  # today 1.6e-7 (geometric nonlinearity)


@pytest.mark.parametrize("t_out,dt", [(np.minimum(np.arange(101) * 0.01, 1.0), 1e-3),
                                      (np.array([0.0, 0.013, 0.5, 0.51, 2.0]), 4e-3)])
def test_step_times_split_each_sample_interval_like_linspace(t_out, dt):
    """The vectorised step times are those of np.linspace per sample interval, bit for bit."""
    from ancf.solvers.generalized_alpha import step_times
    want = np.concatenate([t_out[:1]] + [
        np.linspace(a, b, max(1, int(np.ceil((b - a) / dt - 1e-9))) + 1)[1:]
        for a, b in zip(t_out[:-1], t_out[1:])])
    got = step_times(t_out, dt)
    assert got.shape == want.shape and np.array_equal(got, want)


def test_reduced_samples_are_the_full_states_row_by_row():
    """ReducedModel.samples (one scatter) equals ReducedModel.full per sample."""
    from ancf.solvers.result import global_samples
    p = SCENES["pendulum"].resolve({})
    mdl = pendulum.setup(p)[3]
    Z, Zd = np.random.default_rng(3).normal(size=(2, 7, mdl.n))
    q, v = global_samples(mdl, Z, Zd, np.linspace(0.0, 1.0, 7))
    rows = [mdl.full(z, zd, 0.0) for z, zd in zip(Z, Zd)]
    assert np.array_equal(q, [r[0] for r in rows]) and np.array_equal(v, [r[1] for r in rows])


@pytest.mark.parametrize("scene,over,fast", [("pendulum", {}, True),
                                              ("pendulum", {"n_elements": 16}, True),
                                              ("spinning-beam", {}, False)])
def test_reduced_force_in_one_call_is_the_general_path(scene, over, fast):
    """With gravity alone and g not depending on time, ReducedModel.force and the first-order
    rate [z', z''] of scipy's integrators are one compiled call each, equal bit for bit to
    the general path (q = T z + g, element kernel, scatter, T^T Q, band solve); a
    prescribed motion (g(t)) or a term that is not constant keeps the general path."""
    mod = {"pendulum": pendulum, "spinning-beam": spinning_beam}[scene]
    mdl = mod.setup(SCENES[scene].resolve(over))[3]
    assert (mdl._fast is not None) == fast
    rng = np.random.default_rng(5)
    for _ in range(3):
        z, zd = mdl.initial(*mdl.full(np.zeros(mdl.n), np.zeros(mdl.n), 0.0))
        z, zd = z + 1e-2 * rng.normal(size=mdl.n), rng.normal(size=mdl.n)
        one, rate = mdl.force(z, zd, 0.3), mdl.rate_function()
        assert (rate is not None) == fast
        y = np.concatenate([z, zd])
        first = None if rate is None else rate(y)
        kept, mdl._fast = mdl._fast, None
        general = mdl.force(z, zd, 0.3)
        acc = mdl.acc(z, zd, 0.3)
        mdl._fast = kept
        assert np.array_equal(one, general)
        assert first is None or np.array_equal(first, np.concatenate([zd, acc]))
    if fast:  # a non-finite rate is a singular solve, as from the band solve of acc
        with pytest.raises(Singular, match="non-finite"):
            mdl.rate_function()(np.full(2 * mdl.n, np.nan))
    forces = Forces(3, [Gravity.__new__(Gravity), object()])
    assert not forces.constant and Forces(3, []).constant


@pytest.mark.parametrize("seed", range(3))
def test_band_inverse_iteration_is_the_python_loop(seed):
    """The compiled band stability check (``linear._band_stability``) takes the Python
    inverse iteration's steps (the same band LU behind its ``solve``), finds the lowest
    eigenvalue of an SPD band matrix to LOWEST_RTOL of numpy's eigvalsh, its largest
    magnitude by power iteration as a lower bound within 1 %, and no negative or zero
    eigenvalue."""
    from ancf.solvers import linear
    A = _random_band(40, 3, seed, symmetric=True)
    lam = np.linalg.eigvalsh(A)
    A = A + (1e-3 - lam[0]) * np.eye(40)  # SPD, lowest eigenvalue 1e-3
    data = _band_of(A, 3)
    top, neg, zero, below, k, mu, finite = linear._band_stability(
        data, 3, linear._start(40), linear.INVERSE_ITERATIONS, linear.LOWEST_RTOL)
    assert (neg, zero, below, k, finite) == (0, 0, 0, 0, True)
    exact = float(np.abs(np.linalg.eigvalsh(A)).max())
    assert 0.99 * exact <= top <= exact * (1.0 + 1e-12)
    slow = linear._lowest_by_inverse_iteration(linear._BandLU(data, 3), 40, top)
    assert mu / top == slow
    assert mu / top == pytest.approx(1e-3 / top, rel=linear.LOWEST_RTOL)
