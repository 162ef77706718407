"""The ANCF 3423 shell (``ancf.elements.ancf3423``) and Chrono's corner-loaded plate.

The element contract (as ``test_registry.py`` runs it over registered elements): the
exact tangent and damping Jacobian against central differences (h = 1e-6, relative 1e-8:
truncation ~h^2, round-off ~eps/h of the largest entry), Q = dU/de, zero internal force
under a rigid motion (round-off, 1e-12 of max|K|), six zero-energy modes at the reference
(eigenvalues <= 1e-12 of the largest; the next is ~1e-6 of it), the exact mass of rigid
translation (1e-12), the shape functions at the nodes, the generated module's stamp.

Chrono's unit test ``utest_FEA_ANCFShell_Iso.cpp`` (data: ``tests/data/chrono/README.md``,
section "ANCF 3423 shell"): its first 10 steps within its own tolerance 5e-5 m; the
consistent ANS order reproduces them to the file's rounding (6 significant digits: 1e-7 m
covers it), Chrono's present order (its knots run A, B, D, C) does not.  The whole
4000-step history: ``test_chrono_3423_history.py`` (slow).
"""
from __future__ import annotations

import numpy as np
import pytest

from analytic import _codegen
from analytic import ancf3423 as generator
from ancf.checks.chrono_shell3423 import HISTORY
from ancf.elements import ancf3423
from ancf.models import plate3423
from tests.elements.chrono_data import load

A, B, H, E_MOD, NU, RHO = 0.3, 0.2, 0.01, 2.1e8, 0.3, 500.0
STEP, TOL = 1e-6, 1e-8
CHRONO_TOL = 5e-5     # m, utest_FEA_ANCFShell_Iso.cpp line 52
CHRONO_STEPS = 10     # its num_steps, line 53
ROUNDING = 1e-7       # m: the file's 6 significant digits at |z| <= 0.014 m (first 10 rows)


def _element(alpha=0.0, ans="paper"):
    el = ancf3423.Shell3423([A, A], [B, B], H, E_MOD, NU, rho=RHO, ans=ans, alpha=alpha)
    rng = np.random.default_rng(7)
    return el, el.e0 + 0.01 * rng.standard_normal(el.e0.shape), rng


def _columns(f, x):
    """Central differences of f (nel, 24) by each of the 24 columns of x (nel, 24)."""
    out = np.zeros(x.shape + (24,))
    for j in range(24):
        xp, xm = x.copy(), x.copy()
        xp[:, j] += STEP
        xm[:, j] -= STEP
        out[:, :, j] = (f(xp) - f(xm)) / (2 * STEP)
    return out


def _close(fd, exact):
    assert np.abs(fd - exact).max() <= TOL * np.abs(exact).max()


@pytest.mark.parametrize("ans", list(ancf3423.ANS))
def test_3423_tangent_and_damping_jacobian_match_differences(ans):
    el, e, rng = _element(alpha=0.08, ans=ans)
    v = 0.1 * rng.standard_normal(e.shape)
    _, K, R, _ = el.evaluate(e, v, want_J=True)
    _close(_columns(lambda x: el.evaluate(x, v)[0], e), K)
    _close(_columns(lambda x: el.evaluate(e, x)[0], v), R)


def test_3423_force_is_the_energy_gradient():
    el, e, _ = _element()
    Q = el.gradient(e)[0]
    fd = np.stack([(el.energy(e + STEP * d) - el.energy(e - STEP * d)) / (2 * STEP)
                   for d in np.eye(24)[:, None, :]], axis=-1)
    assert np.abs(fd - Q).max() <= 1e-7 * np.abs(Q).max()


def test_3423_rigid_motion_and_zero_energy_modes():
    el, _, _ = _element()
    k = np.array([1.0, 2.0, 3.0]) / np.sqrt(14.0)
    W = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    Rot = np.eye(3) + np.sin(0.9) * W + (1 - np.cos(0.9)) * W @ W
    moved = el.e0.reshape(2, 8, 3) @ Rot.T
    moved[:, ::2] += [0.3, -0.2, 0.5]
    K0 = el.gradient(el.e0, tangent=True)[1]
    assert np.abs(el.gradient(moved.reshape(2, 24))[0]).max() <= 1e-12 * np.abs(K0).max()
    lam = np.abs(np.linalg.eigvalsh(K0[0]))
    assert np.sum(lam <= 1e-12 * lam.max()) == 6
    bent = el.e0 + 1e-6 * np.random.default_rng(4).standard_normal(el.e0.shape)
    assert np.abs(el.gradient(bent)[0]).max() > 1e-9 * np.abs(K0).max()


def test_3423_mass_and_shapes():
    el, _, _ = _element()
    M = el.mass()[0]
    v = np.zeros((8, 3))
    v[::2] = [0.3, -1.1, 0.7]
    assert v.ravel() @ M @ v.ravel() == pytest.approx(RHO * A * B * H * (v[0] @ v[0]), rel=1e-12)
    S = el.own_shapes()
    X, Y = A * (ancf3423.NODE_XI + 1) / 2, B * (ancf3423.NODE_ETA + 1) / 2
    np.testing.assert_allclose(S["S"](X, Y, 0.0, A, B)[:, ::2], np.eye(4), atol=1e-15)
    np.testing.assert_allclose(S["z"](X, Y, 0.0, A, B)[:, 1::2], np.eye(4), atol=1e-15)


def test_3423_closed_form_shapes_and_gravity_match_the_generated_module():
    """scalar_shape, natural_gradient (chrono_shell's loads) against the generated
    evaluator at random points (1e-14: round-off of O(1) sums); gravity rho V g / 4 per
    node position, nothing on d (1e-12)."""
    rng = np.random.default_rng(11)
    for xi, eta, zeta in rng.uniform(-1, 1, (5, 3)):
        gen = ancf3423._shapes_at(xi, eta, zeta, A, B, H)
        z = H * zeta / 2
        np.testing.assert_allclose(ancf3423.scalar_shape(xi, eta, z), gen[0], rtol=0, atol=1e-14)
        dn = ancf3423.natural_gradient(xi, eta, z) / [A / 2, B / 2, 1.0]
        np.testing.assert_allclose(dn, gen[1:].T, rtol=0, atol=1e-13)
    g = np.array([0.5, -2.0, -9.81])
    Fg = ancf3423.gravity(A, B, H, RHO, g).reshape(4, 2, 3)
    np.testing.assert_allclose(Fg[:, 0], np.tile(RHO * A * B * H * g / 4, (4, 1)), rtol=1e-12)
    assert np.abs(Fg[:, 1]).max() <= 1e-12 * RHO * A * B * H * 9.81


def test_3423_generated_module_carries_its_stamp():
    assert _codegen.stamp_ok(generator.TARGET, generator.SOURCES)


def test_3423_refuses_an_unknown_ans_order():
    with pytest.raises(ValueError, match="ans must be one of"):
        ancf3423.point_forms(A, B, H, "other")


def _first_steps(ans):
    ref = load(HISTORY, (4000, 2))[:CHRONO_STEPS, 1]
    _, z, _ = plate3423.history(plate3423.Plate(ans=ans), steps=CHRONO_STEPS)
    return np.abs(z - ref).max()


def test_3423_first_steps_within_chronos_tolerance():
    """Chrono's own check (lines 219-231): |z_tip - z_file| <= 5e-5 m over 10 steps; the
    consistent ANS order within the file's rounding."""
    assert _first_steps("paper") <= ROUNDING < CHRONO_TOL


def test_3423_chronos_present_ans_order_is_not_the_files():
    """The knots A, B, D, C against shape functions A, B, C, D: within Chrono's 5e-5 over 10
    steps, but beyond the file's rounding (the file predates the reordering, 2015)."""
    assert ROUNDING < _first_steps("chrono") <= CHRONO_TOL


def test_3423_element_command_prints_the_modules_matrices(cli):
    """``ancf element ancf3423 --json`` at a displaced, moving node: the module's Q, K, R
    (Shell3423.evaluate, bit-equal), mass and gravity; valid against its schema."""
    import json

    from ancf.study.schemas import element_schema, validate

    rc, out, err = cli("element", "ancf3423", "--json", "--set", "displacement=0.001",
                       "--set", "velocity=0.002", "--set", "alpha=0.01", "--set", "node=2")
    assert rc == 0 and err == ""
    d = json.loads(out)
    p = d["params"]
    el = ancf3423.Shell3423(p["L"], p["W"], p["H"], p["E"], p["nu"], alpha=0.01)
    e, edot = el.e0[0].copy(), np.zeros(24)
    e[14], edot[14] = 0.001, 0.002  # node 2 (C), z: 6 * 2 + 2
    Q, K, R, _ = el.evaluate(e[None], edot[None], want_J=True)
    np.testing.assert_array_equal(d["coordinates"], e)
    np.testing.assert_array_equal(d["internal_force"], Q[0])
    np.testing.assert_array_equal(d["stiffness"], K[0])
    np.testing.assert_array_equal(d["damping"], R[0])
    np.testing.assert_array_equal(d["mass_matrix"], ancf3423.mass_matrix(p["L"], p["W"], p["H"],
                                                                          p["rho"]))
    assert np.abs(Q).max() > 0 and np.abs(R).max() > 0
    assert validate(d, element_schema("ancf3423")) == []
