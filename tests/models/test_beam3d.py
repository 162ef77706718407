"""The 3D linear shear-deformable beam (LinearBeam3D, thesis 4.4).

Element checks (the planar contract tests of test_elements.py are written for
2-vector slots, so their equivalents are here): finite-difference gradient and
tangent (RTOL = 1e-6: the energy is a quartic polynomial in the coordinates, so
the central difference error is h^2/6 f''' plus round-off ~eps |f| / h, both
~1e-10 relative at h = 1e-6, as argued in test_elements.py), tangent symmetry,
zero strain energy and force in rigid motions, invariance of a deformed state
under rigid motion, zero-energy mode counts and the exact consistent mass.

Validations against the planar element: loaded in a principal plane of a square
section, the 3D beam stays in that plane (its energy is even in the out-of-plane
coordinates) and its strains do not vary across the out-of-plane width, so it
must reproduce the 2D scenes' solutions to round-off (asserted 1e-10 relative to
the largest displacement), in small and large deflection.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.models import beam3d
from ancf.checks import elements3d as checks
from ancf.core.assembly import Assembly, ElementGroup
from ancf.elements.linear3d import LinearBeam3D
from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection, gauss01
from ancf.scenes import SCENES

E_MOD, NU, RHO, L = 2.07e11, 0.3, 7850.0, 2.0
SECTION = RectangularSection(0.1, 0.1)
H, RTOL = 1e-6, 1e-6
SCHEMES = list(LinearBeam3D.schemes)
STABLE = [s for s in SCHEMES if s != "report-selective"]  # see test_report_selective_*


def _build(integration="thesis", n_el=3, section=SECTION, L=L, **kw):
    m = BeamMesh(L, n_el, LinearBeam3D.slots, dim=3)
    q0 = m.reference()
    kw = {"E": E_MOD, "nu": NU, "rho": RHO, **kw}
    return m, q0, LinearBeam3D(m.lengths, q0[m.dofmap], section, integration=integration, **kw)


def _perturbed(m, q0, seed=0, size=1e-2):
    """Positions moved by size * element length, slopes by size, at random."""
    rng = np.random.default_rng(seed)
    scale = np.array([m.lengths[0] if s == "r" else 1.0 for s in m.slots])
    return q0 + size * (rng.standard_normal((m.n_nodes, 3, 3)) * scale[None, :, None]).ravel()


def _rotation(axis, angle):
    """Rodrigues' rotation matrix about ``axis`` by ``angle`` rad."""
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    Kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * Kx + (1 - np.cos(angle)) * Kx @ Kx


def _move(m, q, R, shift):
    """r -> R r + shift, slopes -> R slopes, of a global vector."""
    V = q.reshape(m.n_nodes, 3, 3) @ R.T
    V[:, 0, :] += shift
    return V.ravel()


# ----------------------------------------------------------------- element checks
@pytest.mark.parametrize("scheme", SCHEMES)
def test_gradient_matches_energy_differences(scheme):
    m, q0, el = _build(scheme)
    e = _perturbed(m, q0)[m.dofmap]
    g, _ = el.gradient(e)
    fd = np.zeros_like(g)
    for j in range(el.ndof):
        ep, em = e.copy(), e.copy()
        ep[:, j] += H
        em[:, j] -= H
        fd[:, j] = (el.energy(ep) - el.energy(em)) / (2 * H)
    assert np.all(np.linalg.norm(fd - g, axis=1) <= RTOL * np.linalg.norm(g, axis=1))


@pytest.mark.parametrize("scheme", SCHEMES)
def test_tangent_matches_gradient_differences_and_is_symmetric(scheme):
    m, q0, el = _build(scheme)
    e = _perturbed(m, q0, seed=1)[m.dofmap]
    g, K = el.gradient(e, tangent=True)
    np.testing.assert_array_equal(g, el.gradient(e)[0])
    fd = np.zeros_like(K)
    for j in range(el.ndof):
        ep, em = e.copy(), e.copy()
        ep[:, j] += H
        em[:, j] -= H
        fd[:, :, j] = (el.gradient(ep)[0] - el.gradient(em)[0]) / (2 * H)
    err, ref = np.linalg.norm(fd - K, axis=-2), np.linalg.norm(K, axis=-2)
    assert np.all(err <= RTOL * ref), (err / ref).max()
    np.testing.assert_allclose(K, np.swapaxes(K, 1, 2), rtol=0, atol=1e-12 * np.abs(K).max())


@pytest.mark.parametrize("scheme", SCHEMES)
def test_rigid_motions_leave_zero_strain(scheme):
    """A rigid rotation (any axis) plus translation of the reference: zero energy and
    zero elastic force, to round-off (force <= 1e-12 |K| |q|, energy <= 1e-20 E V)."""
    m, q0, el = _build(scheme)
    q = _move(m, q0, _rotation([0.3, -1.0, 0.6], 1.1), [0.4, -0.2, 0.7])
    g, K = el.gradient(q[m.dofmap], tangent=True)
    assert np.abs(g).max() <= 1e-12 * np.abs(K).max() * np.abs(q).max()
    assert np.abs(el.energy(q[m.dofmap])).max() <= 1e-20 * E_MOD * SECTION.area * L


@pytest.mark.parametrize("scheme", SCHEMES)
def test_energy_invariant_under_rigid_motion(scheme):
    """Of a deformed state, and with reference and state both rotated (J0 != I)."""
    m, q0, el = _build(scheme)
    q = _perturbed(m, q0, seed=3)
    R, c = _rotation([1.0, 0.5, -0.2], 0.7), [0.4, -0.2, 0.1]
    U = el.energy(q[m.dofmap])
    np.testing.assert_allclose(el.energy(_move(m, q, R, c)[m.dofmap]), U, rtol=1e-10)
    el_r = LinearBeam3D(m.lengths, _move(m, q0, R, c)[m.dofmap], SECTION, E_MOD, NU, integration=scheme)
    np.testing.assert_allclose(el_r.energy(_move(m, q, R, c)[m.dofmap]), U, rtol=1e-10)


def _zero_modes(scheme, n_el):
    m, q0, el = _build(scheme, n_el=n_el)
    K = Assembly(m.n_dofs, [ElementGroup(el, m.dofmap)]).gradient_tangent(q0)[1].toarray()
    w = np.linalg.eigvalsh(K)
    return int(np.sum(np.abs(w) < 1e-9 * np.abs(w).max()))


@pytest.mark.parametrize("n_el", [1, 4])
@pytest.mark.parametrize("scheme", STABLE)
def test_only_rigid_body_zero_energy_modes(scheme, n_el):
    """Free-free mesh at the reference: 3 translations + 3 rotations."""
    assert _zero_modes(scheme, n_el) == 6


@pytest.mark.parametrize("n_el", [1, 4])
def test_report_selective_zero_energy_modes(n_el):
    """'report-selective' in 3D (normal 2x(2x2), shear 1x(1x1)) has n_el + 1 spurious
    modes.  Linearised, v_z + w_y (the yz shear) and the twist enter the shear strains
    only through terms linear in y or z, which vanish at the single section point:
    the twist of every node but one (n_el modes; torsion has no stiffness at all)
    and one in-section shear distortion (its element means must vanish: n_el
    conditions on n_el + 1 nodal values) are free.  So a 3D static solve with this
    scheme has a singular tangent; 'report-fix' (2x2 section points) removes them."""
    assert _zero_modes("report-selective", n_el) == 6 + n_el + 1


@pytest.mark.parametrize("scheme", SCHEMES)
def test_mass_is_the_exact_integral(scheme):
    """M = rho int S^T S dV by a 3 x (3 x 3) Gauss rule (exact: S_i S_j is quadratic in
    x, y and z) and the rigid-body masses rho A l and rotary inertia rho (I_y + I_z) l."""
    m, q0, el = _build(scheme, section=RectangularSection(0.1, 0.2))
    M = el.mass()
    xi, wx = gauss01(3)
    y, z, wyz = el.section.rule_yz(3)
    for e, le in enumerate(m.lengths):
        X, Y = np.meshgrid(xi * le, y, indexing="ij")
        Z = np.meshgrid(xi * le, z, indexing="ij")[1]
        S = el.shapes["S"](X, Y, Z, np.full(X.shape, le))
        m_ij = np.einsum("ab,abi,abj->ij", np.outer(wx * le, wyz), S, S)
        np.testing.assert_allclose(M[e], RHO * np.kron(m_ij, np.eye(3)), rtol=1e-13,
                                   atol=1e-13 * np.abs(M[e]).max())
    s = el.section
    v = np.zeros((2, 3, 3))
    v[:, 0, 0] = 1.0  # unit translation rate along x
    np.testing.assert_allclose(v.ravel() @ M[0] @ v.ravel(), RHO * s.area * m.lengths[0], rtol=1e-13)
    w = np.zeros((2, 3, 3))
    w[:, 1, 2], w[:, 2, 1] = 1.0, -1.0  # unit rotation rate about x: r_y' = e_z, r_z' = -e_y
    Ip = s.second_moment + s.h * s.b**3 / 12.0
    np.testing.assert_allclose(w.ravel() @ M[0] @ w.ravel(), RHO * Ip * m.lengths[0], rtol=1e-13)


# ------------------------------------------------------- validation against the 2D beam
def test_3d_solve_takes_the_generic_newton_path():
    """ancf.models.beam3d.solve (used by the checks below): converged, not the planar compiled path."""
    p = SCENES["cantilever"].resolve({"element": "linear", "F": -1000.0})
    res, _, _, asm = beam3d.solve({**p, "element": "linear3d"}, beam3d.clamp,
                                  {(p["n_elements"], "r", 2): p["F"]})
    assert res.converged, res.message
    assert res.pattern.compiled(asm) is None


@pytest.mark.parametrize("axis", [1, 2], ids=["load-y", "load-z"])
@pytest.mark.parametrize("scheme", STABLE)
@pytest.mark.parametrize("case", list(checks.BEAM_CASES))
def test_bending_in_a_principal_plane_reproduces_the_2d_scenes(case, scheme, axis):
    """The scene's load along -y (then along -z) on the square section: in-plane nodal
    displacements (r and the slope in the plane) equal the 2D element's to 1e-10 of the
    largest, and the out-of-plane ones vanish to 1e-10 of it (ancf.checks.elements3d)."""
    inplane, outplane = checks.principal_plane(case, scheme, axis)
    assert inplane <= 1e-10 and outplane <= 1e-10


def test_tip_load_at_45_degrees_is_the_sum_of_the_two_planes():
    """The small-deflection cantilever (F = -1000 N) with F at 45 deg in the (y, z)
    plane against the sum of the solves with F/sqrt 2 along -y and along -z.  The
    difference is the second-order, non-commuting part of the two bending rotations
    (theta_y theta_z ~ (w/L)^2, w the tip deflection), so the tolerance is (w/L)^2 of
    the largest position displacement and w/L of the largest slope change (seen:
    0.53 of either)."""
    d = checks.superposition_45()
    assert d["position"] <= 1.0 and d["slope"] <= 1.0
    assert d["symmetry"] <= 1e-12  # along 45 deg


def test_torsion_constant_series():
    """The series gives the tabulated 0.1406 a^4 (to the 4 printed digits)."""
    assert abs(beam3d.torsion_constant_square(1.0) - 0.1406) < 5e-5


@pytest.mark.parametrize("ks", [1.0, 5.0 / 6.0])
@pytest.mark.parametrize("scheme", STABLE)
def test_torsion_stiffness_is_ks_G_Ip_not_G_J(scheme, ks):
    """A cantilever twisted by a tip torque T about x, applied as the couple of a
    linear shear traction on the end face: generalised forces T I_z/I_p on the
    z component of r_y and -T I_y/I_p on the y component of r_z (moment
    r_y x Q_ry + r_z x Q_rz = T e_x).  The section turns rigidly (no warping), so
    the twist phi(x) = T x / (ks G I_p), I_p = I_y + I_z, at every node, and the
    St-Venant stiffness G J over the element's is J / (ks I_p) (0.8436 at ks = 1).
    T gives a tip twist of 1e-6 rad, so the geometric nonlinearity is ~1e-12;
    asserted 1e-8 relative (ancf.checks.elements3d.torsion)."""
    t = checks.torsion(scheme, ks)
    assert t["twist_error"] <= 1e-8
    assert t["ratio"] == pytest.approx(t["J_over_ks_Ip"], rel=1e-8)
