"""Dufva's belt element (thesis 3.1) validated on its own.

The element contract (finite-difference gradient and tangent, symmetry, rigid-motion
invariance, zero-energy modes, exact mass) runs in test_elements.py and
test_shape_functions.py through ``CONTRACT_ELEMENTS``; here: the generated code, the
energy against an independent evaluation of Eqs 3.13-3.16 and 2.18, rigid motion,
the Reissner cantilever, the full circle under an end moment (ref. [54]), the
alpha factors, the axial force and the argument checks.

Clamp: position and r_y (the cross-section) of the root node, as the papers state
(ancf/scenes/cantilever.py).  Clamping r_x as well forces sin(gamma) = 0 at the
root (a Timoshenko clamp allows shear there): the element is then stiffer by one
element's shear layer, e.g. -4.9e-4, -2.8e-4, -1.4e-4 relative tip deflection
with 1, 2, 4 elements under a small load, and the Model 1 tip converges only as
O(1/n) (y errors -3.7e-5, -7.4e-5, -9.4e-5 m with 8, 16, 32 elements).
"""
from __future__ import annotations

import numpy as np
import pytest

from analytic import dufva_belt, reissner, timoshenko
from ancf.checks.belt_element import (CIRCLE_H_FOUR, MODEL1, REISSNER_TOL, SECTION1, cantilever,
                                      circle_gap)
from ancf.elements import _generated as shape_gen
from ancf.elements import dufva2d
from ancf.elements.compiled_element import add_point_tangent
from ancf.elements.dufva2d import DufvaBelt2D
from ancf.core.forces import EndMoment
from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import gauss01
from ancf.solvers.static import NewtonOptions, solve_static
from tests.analytic.test_codegen import REGENERATE


def _tip_under(n, F, n_steps=4, **kw):
    """Tip position (x, y) of an n-element cantilever under the dead tip force F = (Fx, Fy) N,
    with the static result, the mesh and the element."""
    m, q0, asm, elim = cantilever(n, **kw)
    tip = [m.dof(n, "r", 0), m.dof(n, "r", 1)]
    Qk = np.zeros(m.n_dofs)
    Qk[tip] = F
    res = solve_static(asm, elim, Qk, q0, NewtonOptions(n_steps=n_steps, rtol=1e-10))
    assert res.converged, res.message
    return res.q[tip], res, m, asm.groups[0].element


# ------------------------------------------------------------------ generated code
@pytest.mark.slow
@REGENERATE  # the stamp test in tests/analytic/test_codegen.py runs always
def test_generated_module_up_to_date():
    """Also re-proves (SymPy) that the invariant density equals Eqs 3.4, 3.10, 3.18, 3.19."""
    assert dufva_belt.generate() == dufva_belt.TARGET.read_text(), (
        "ancf/elements/_dufva_generated.py is stale: run `python -m analytic.dufva_belt --write`")


def _energy_by_definition(el, e, E_mod, nu, ks, ny=5):
    """U from r_p = r_c + y r_s (Eqs 3.8-3.12), eps_xx, eps_xy (3.13-3.14) and the
    transverse strain at every (x, y) of 8 x ny Gauss points, into Eq. 2.18 (alpha = 1):
    numpy, independent of the generated code.  ny = 5 is exact in y (degree 8)."""
    Itil = np.array([[0.0, -1.0], [1.0, 0.0]])
    Ee = e.reshape(el.nel, 6, 2)
    xi, wx = gauss01(8)
    yq, wy = el.section.rule(ny)
    G = E_mod / (2 * (1 + nu))
    U = np.zeros(el.nel)
    for i, le in enumerate(el.lengths):
        rx, ry = Ee[i, [1, 4]], Ee[i, [2, 5]]
        sK = -np.einsum("kd,kd->k", rx, ry) / (np.linalg.norm(rx, axis=1) * np.linalg.norm(ry, axis=1))
        eyyK = 0.5 * (np.einsum("kd,kd->k", ry, ry) - 1.0)
        for z, w in zip(xi, wx):
            X = np.array([z * le])
            a = el.shapes["x"](X, 0.0 * X, le)[0] @ Ee[i]
            c = shape_gen.cubic2d_xx(X, 0.0 * X, le)[0] @ Ee[i]
            na = np.linalg.norm(a)
            t, t_x = a / na, (c - a * (a @ c) / na**2) / na
            s, s_x = (1 - z) * sK[0] + z * sK[1], (sK[1] - sK[0]) / le
            r_s = (np.eye(2) + Itil * s) @ Itil @ t
            r_sx = (np.eye(2) + Itil * s) @ Itil @ t_x + s_x * Itil @ Itil @ t
            eyy = (1 - z) * eyyK[0] + z * eyyK[1]
            for y, wyy in zip(yq, wy):
                r_x = a + y * r_sx
                exx, exy = 0.5 * (r_x @ r_x - 1.0), 0.5 * (r_x @ r_s)
                U[i] += w * le * wyy * 0.5 * (E_mod * exx**2 + E_mod * eyy**2 + 4 * ks * G * exy**2)
    return U


def test_energy_equals_definition_with_alpha_one():
    """Kernel energy (generated density, closed-form section) against Eq. 2.18 with the
    strains of Eqs 3.13-3.14 integrated over the section numerically, at a random
    large deformation (coordinates moved by 0.1 m or 0.1): equal to 1e-12 relative
    (round-off: both are exact in y and use the same 8 Gauss points along x)."""
    m = BeamMesh(2.0, 3, DufvaBelt2D.slots)
    q0 = m.reference()
    el = DufvaBelt2D(m.lengths, q0[m.dofmap], SECTION1, E=2.0e11, nu=0.25, ks=0.9, nx=8)
    rng = np.random.default_rng(5)
    q = q0 + 0.1 * rng.standard_normal(q0.size)
    U = el.energy(q[m.dofmap])
    ref = _energy_by_definition(el, q[m.dofmap], 2.0e11, 0.25, 0.9)
    np.testing.assert_allclose(U, ref, rtol=1e-12)


# ------------------------------------------------------------------ 1. rigid motion
@pytest.mark.parametrize("alpha2", [1.0, 0.1])
def test_rigid_motion_of_straight_mesh_is_strain_free(alpha2):
    """Rotation by 2.5 rad and translation by (3, -1) m of a straight 4-element mesh:
    U <= 1e-12 E A L (round-off gives ~1e-21 J against E A L = 4e9 J) and
    |dU/de| <= 1e-9 E A (2e0 N; round-off gives ~1e-6 N)."""
    m, q0, asm, _ = cantilever(4, alpha2=alpha2)
    c, s = np.cos(2.5), np.sin(2.5)
    Q = q0.reshape(m.n_nodes, 3, 2) @ np.array([[c, -s], [s, c]]).T
    Q[:, 0] += [3.0, -1.0]
    q = Q.ravel()
    EA = MODEL1["E"] * SECTION1.area
    assert abs(asm.strain_energy(q)) <= 1e-12 * EA * MODEL1["L"]
    assert np.abs(asm.gradient(q)).max() <= 1e-9 * EA


# ------------------------------------------------------- 2. Reissner cantilever, Model 1
def test_model1_cantilever_converges_to_reissner():
    """Tip of Model 1 (F = -5e5 N) with 8, 16, 32 elements against the geometrically
    exact Reissner beam.  Seen: errors (x, y) = (-2.838e-4, -1.080e-4),
    (-2.861e-4, -1.143e-4), (-2.861e-4, -1.144e-4) m: the mesh converges (steps
    6.7e-6 then 1.3e-7 m, >= 16 x smaller each halving) to a limit 3.1e-4 m
    (1.5e-4 L) from Reissner's.  That limit is the model, not the mesh: the
    element's Green strains and the (a.a - 1) r_s,x.r_s,x term stiffen bending
    by O(N/EA) ~ 1e-4 (tip axial strain 1.2e-4).  Tolerances: 4e-4 m to the
    reference (limit + 30 %), and the 16 -> 32 step below 1e-6 m and below 1/16 of
    the 8 -> 16 step."""
    ref = reissner.tip_position(MODEL1["E"], MODEL1["nu"], MODEL1["L"], MODEL1["h"], MODEL1["b"],
                                MODEL1["F"])
    assert ref.converged, ref.message
    tips = {n: _tip_under(n, (0.0, MODEL1["F"]))[0] for n in (8, 16, 32)}
    print({n: t - [ref.tip_x, ref.tip_y] for n, t in tips.items()})
    for t in tips.values():
        assert np.linalg.norm(t - [ref.tip_x, ref.tip_y]) <= REISSNER_TOL
    step1, step2 = np.linalg.norm(tips[16] - tips[8]), np.linalg.norm(tips[32] - tips[16])
    assert step2 <= 1e-6 and step2 <= step1 / 16, (step1, step2)


def test_small_load_cantilever_is_timoshenko_with_one_element():
    """F = -50 N (tip deflection 3e-6 m): the linearised element is Timoshenko's beam
    (cubic centre line, linear shear angle), so one element gives the linear tip
    deflection F L^3/(3EI) + F L/(ks G A); seen -1e-8 relative (Newton tolerance
    and (v/L)^2 ~ 1e-12 geometric terms); tolerance 1e-7."""
    F = -50.0
    lin = timoshenko.cantilever_tip_deflection(MODEL1["E"], MODEL1["nu"], MODEL1["L"], MODEL1["h"],
                                               MODEL1["b"], F)
    tip = _tip_under(1, (0.0, F), n_steps=1)[0]
    assert tip[1] == pytest.approx(lin, rel=1e-7)


# ------------------------------------------------------------ 3. full circle, ref. [54]
def test_end_moment_jacobian_matches_differences():
    """The test's force term: its Jacobian against central differences of its value
    (h = 1e-6, error ~h^2 = 1e-12 relative; tolerance 1e-7)."""
    term = EndMoment(4, [1, 3], 2.5)
    q = np.array([0.0, 0.3, 0.0, -1.2])
    J = term.jacobians(q, None, 0.0)[0].toarray()
    fd = np.zeros_like(J)
    for j in range(4):
        dq = np.zeros(4)
        dq[j] = 1e-6
        fd[:, j] = (term.value(q + dq, None, 0.0) - term.value(q - dq, None, 0.0)) / 2e-6
    np.testing.assert_allclose(J, fd, rtol=0, atol=1e-7 * np.abs(J).max())


def test_slender_cantilever_bends_into_a_full_circle():
    """Slender section b = h = 0.01 m, L = 2 m (the y^4 term is (3 h^2/20) kappa^2/4
    = 4e-5 of the bending energy, the Green-strain shortening of the axis
    h^2 kappa^2/8 = 1.2e-4).  Seen gaps |tip - root|/L: 4 elements 1.8e-1, 8
    elements 3.3e-3, 16 elements 1.9e-4.  Four elements do NOT close the circle
    here: membrane locking (EA/EI = 12/h^2; the cubic centre line cannot turn by
    90 deg per element at constant |r_x|), confirmed by alpha1 = 0.01, which brings
    the 4-element gap to 1.7e-2.  Tolerances: 16 elements within 1e-3 L, and the
    gap shrinking at least 4-fold per halving."""
    gaps = [circle_gap(n, 0.01) for n in (4, 8, 16)]
    print("slender full circle, gap/L with 4, 8, 16 elements:", gaps)
    assert gaps[2] <= 1e-3
    assert gaps[1] <= gaps[0] / 4 and gaps[2] <= gaps[1] / 4


def test_four_elements_bend_into_a_full_circle_at_moderate_slenderness():
    """The claim of ref. [54] (thesis line ~815): four elements bend a cantilever into
    a circle.  It holds within 1 % of L only for moderate slenderness, where the
    4-element membrane locking (gap growing as h falls) and the Green-strain
    shortening of the axis (gap growing with h) balance: seen (nx = 5) h = 0.06,
    0.08, 0.10, 0.12 m -> gap/L = 1.7e-2, 4.6e-3, 1.04e-2, 2.5e-2.  Here
    h = 0.08 m (L/h = 25); tolerance 1 % of L (the claim)."""
    gap = circle_gap(4, CIRCLE_H_FOUR)
    print(f"full circle, 4 elements, h = 0.08 m: gap/L = {gap:.2e}")
    assert gap <= 0.01


# ------------------------------------------------------------------ 4. alpha factors
def test_halving_alpha2_doubles_small_deflection():
    """Small transverse tip load (F = -50 N, deflection 3e-6 m): bending and shear
    are both scaled by alpha2 (Eqs 3.18-3.19), so the tip deflection of the
    linearised beam doubles exactly; the eps_yy term (not scaled) is decoupled at
    first order.  Each also equals Timoshenko's with E -> alpha2 E (G scales with
    E).  Seen: ratio - 2 ~ 1e-8 (Newton tolerance); tolerance 1e-7 relative."""
    F = -50.0
    v = {a2: _tip_under(2, (0.0, F), n_steps=1, alpha2=a2)[0][1] for a2 in (1.0, 0.5)}
    assert v[0.5] / v[1.0] == pytest.approx(2.0, rel=1e-7)
    for a2, vy in v.items():
        lin = timoshenko.cantilever_tip_deflection(a2 * MODEL1["E"], MODEL1["nu"], MODEL1["L"],
                                                   MODEL1["h"], MODEL1["b"], F)
        assert vy == pytest.approx(lin, rel=1e-7)


def test_alpha2_leaves_axial_stiffness_and_axial_force_follows_alpha1():
    """Axial tip load F = 1e5 N (strain 5e-5): the tip displacement is the same for
    alpha2 = 1 and 0.5 (to 1e-9 relative: Newton tolerance 1e-10), and with
    alpha1 = 0.5 it doubles: u = lambda - 1 per unit length with the Green law
    F = E A alpha1 (lambda^2 - 1)/2 lambda, solved here in closed form (cubic), to
    1e-9.  axial_force gives N = E A alpha1 eps_l = F/lambda along the whole beam
    (to 1e-5 N, 1e-10 relative: round-off in positions, eps |r| / l EA ~ 1e-6 N,
    seen 2.6e-6 N)."""
    F, L = 1e5, MODEL1["L"]
    EA = MODEL1["E"] * SECTION1.area
    u = {}
    for a1, a2 in ((1.0, 1.0), (1.0, 0.5), (0.5, 1.0)):
        tip, res, m, el = _tip_under(3, (F, 0.0), n_steps=1, alpha1=a1, alpha2=a2)
        u[a1, a2] = tip[0] - L
        lam = np.max(np.roots([1.0, 0.0, -1.0, -2 * F / (EA * a1)]).real)  # lam^3 - lam = 2F/EA
        assert u[a1, a2] == pytest.approx((lam - 1.0) * L, rel=1e-9)
        N = el.axial_force(res.q[m.dofmap], np.linspace(0, 1, 5))
        np.testing.assert_allclose(N, F / lam, rtol=0, atol=1e-5)
    assert u[1.0, 0.5] == pytest.approx(u[1.0, 1.0], rel=1e-9)
    assert u[0.5, 1.0] / u[1.0, 1.0] == pytest.approx(2.0, rel=1e-4)  # Green law: 2 (1 + O(eps))


# ---------------------------------------------------------------------- bad input
@pytest.mark.parametrize("field,value", [("E", 0.0), ("E", float("nan")), ("nu", 0.5),
                                         ("nu", -1.0), ("alpha1", 0.0), ("alpha2", -1.0),
                                         ("ks", 0.0), ("rho", -1.0), ("nx", 0), ("nx", 2.5)])
def test_bad_arguments_raise_naming_the_field(field, value):
    m = BeamMesh(2.0, 2, DufvaBelt2D.slots)
    kw = {"E": 2e11, "nu": 0.3, field: value}
    with pytest.raises(ValueError, match=f"^{field} must be"):
        DufvaBelt2D(m.lengths, m.reference()[m.dofmap], SECTION1, **kw)


def test_bad_lengths_and_reference_raise():
    m = BeamMesh(2.0, 2, DufvaBelt2D.slots)
    e0 = m.reference()[m.dofmap]
    with pytest.raises(ValueError, match="^lengths must be"):
        DufvaBelt2D([1.0, -1.0], e0, SECTION1, E=2e11, nu=0.3)
    with pytest.raises(ValueError, match="^e0 size must be"):
        DufvaBelt2D(m.lengths, e0[:, :6], SECTION1, E=2e11, nu=0.3)


def test_point_tangent_over_nonzero_rows_is_the_dense_one_bit_for_bit():
    """dufva2d's point tangent sums over the rows of the point Jacobian that may be nonzero:
    the dense product's sums bit for bit, at random points of random elements."""
    rng = np.random.default_rng(11)
    for _ in range(20):
        BX, BXX = rng.standard_normal((1, 1, 6)), rng.standard_normal((1, 1, 6))
        E, gI, gJ = rng.standard_normal((1, 6, 2)), rng.standard_normal(4), rng.standard_normal(4)
        Jv = np.empty((7, 12))
        dufva2d._point_jacobian(BX, BXX, 0, 0, rng.random(), 1.0 + rng.random(), gI, gJ, E, Jv)
        H = rng.standard_normal((7, 7))
        H += H.T
        K1, K2 = rng.standard_normal((12, 12)), np.empty((12, 12))
        K2[:] = K1
        add_point_tangent(K1, 0.3, Jv, H, np.empty((7, 12)))
        dufva2d._add_point_tangent(K2, 0.3, Jv, H, np.empty((7, 12)))
        assert K1.tobytes() == K2.tobytes()
