"""Dufva's 3D belt element (thesis 4.4) validated on its own.

The element contract (finite-difference gradient and tangent, symmetry, rigid-motion
invariance of a deformed state, exact mass) also runs in test_elements.py and
test_shape_functions.py through ``CONTRACT_ELEMENTS``; here: the generated code,
finite differences at a large deformation, rigid motion of a straight mesh, the
energy against an independent evaluation of the Green strains of Eq. 4.37, the
reduction to the planar element (:mod:`ancf.elements.dufva2d`) in both principal
planes, the alpha factors, Timoshenko's cantilever and the argument checks.

Clamp: position, r_y and r_z of the root node (the cross-section; r_x free, as the
planar element's clamp in ancf/checks/belt_element.py).
"""
from __future__ import annotations

import numpy as np
import pytest

from analytic import belt3d, timoshenko
from ancf.checks import belt_element as planar
from ancf.core.assembly import Assembly, ElementGroup
from ancf.core.constraints import Elimination
from ancf.elements import _generated as shape_gen
from ancf.elements.belt3d import DufvaBelt3D
from ancf.core.mesh import BeamMesh
from ancf.core.quadrature import RectangularSection, gauss01
from ancf.solvers.static import NewtonOptions, solve_static
from tests.analytic.test_codegen import REGENERATE

MODEL1, SECTION1 = planar.MODEL1, planar.SECTION1  # L = 2 m, b = h = 0.1 m, E = 2.07e11 Pa
FLAT = RectangularSection(0.05, 0.1)  # b (z) != h (y): tells the two planes apart
H, RTOL = 1e-6, 1e-6


def cantilever(n, section=SECTION1, L=MODEL1["L"], **kw):
    """(mesh, q0, assembly, elimination) of a straight n-element 3D cantilever along +x
    clamped at the root in r, r_y and r_z."""
    kw = {"E": MODEL1["E"], "nu": MODEL1["nu"], **kw}
    m = BeamMesh(L, n, DufvaBelt3D.slots, dim=3)
    q0 = m.reference()
    el = DufvaBelt3D(m.lengths, q0[m.dofmap], section, **kw)
    root = [m.dof(0, s, c) for s in ("r", "r_y", "r_z") for c in range(3)]
    return (m, q0, Assembly(m.n_dofs, [ElementGroup(el, m.dofmap)]),
            Elimination(m.n_dofs).fix(root, q0[root]))


def tip_under(n, F, n_steps=1, **kw):
    """Tip position (x, y, z) under the dead tip force F = (Fx, Fy, Fz) N."""
    m, q0, asm, elim = cantilever(n, **kw)
    tip = [m.dof(n, "r", c) for c in range(3)]
    Qk = np.zeros(m.n_dofs)
    Qk[tip] = F
    res = solve_static(asm, elim, Qk, q0, NewtonOptions(n_steps=n_steps, rtol=1e-10))
    assert res.converged, res.message
    return res.q[tip]


def _perturbed(m, q0, seed, size):
    rng = np.random.default_rng(seed)
    scale = np.array([m.lengths[0] if s == "r" else 1.0 for s in m.slots])
    return q0 + size * (rng.standard_normal((m.n_nodes, 4, 3)) * scale[None, :, None]).ravel()


def _rotation(axis, angle):
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    Kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * Kx + (1 - np.cos(angle)) * Kx @ Kx


# ------------------------------------------------------------------ generated code
@pytest.mark.slow
@REGENERATE  # the stamp test in tests/analytic/test_codegen.py runs always
def test_generated_module_up_to_date():
    assert belt3d.generate() == belt3d.TARGET.read_text(), (
        "ancf/elements/_belt3d_generated.py is stale: run `python -m analytic.belt3d --write`")


def test_compact_section_kinematics_equal_the_chain_rule():
    """The generator's compact r_s, r_s,x (in the invariants a.a, a.p, p.p) equal the
    vector form (t = a/|a|, w/|w| - s t, chain rule along x) at random points, to
    1e-12 (round-off)."""
    import sympy as sp

    rng = np.random.default_rng(3)
    f_compact = sp.lambdify(belt3d.KIN, list(belt3d.section_vector_x()[0]) + list(belt3d.section_vector_x()[1]))
    f_chain = sp.lambdify(belt3d.KIN, list(belt3d.section_vector_x_chain()[0])
                          + list(belt3d.section_vector_x_chain()[1]))
    for _ in range(5):
        x = rng.uniform(-1.0, 1.0, len(belt3d.KIN))
        np.testing.assert_allclose(np.ravel(f_compact(*x)), np.ravel(f_chain(*x)), rtol=0, atol=1e-12)


# ------------------------------------------------------------- finite differences
@pytest.mark.slow
def test_gradient_and_tangent_match_differences_at_large_deformation():
    """Coordinates moved by 0.05 (m or -) at random, alpha1 = 0.7, alpha2 = 0.2:
    central differences with h = 1e-6 (error ~h^2 relative, as argued in
    test_elements.py); tolerance 1e-6 relative per row / column."""
    m = BeamMesh(2.0, 2, DufvaBelt3D.slots, dim=3)
    q0 = m.reference()
    el = DufvaBelt3D(m.lengths, q0[m.dofmap], FLAT, E=2e11, nu=0.3, alpha1=0.7, alpha2=0.2)
    e = _perturbed(m, q0, 7, 0.05)[m.dofmap]
    g, K = el.gradient(e, tangent=True)
    fd_g, fd_K = np.zeros_like(g), np.zeros_like(K)
    for j in range(el.ndof):
        ep, em = e.copy(), e.copy()
        ep[:, j] += H
        em[:, j] -= H
        fd_g[:, j] = (el.energy(ep) - el.energy(em)) / (2 * H)
        fd_K[:, :, j] = (el.gradient(ep)[0] - el.gradient(em)[0]) / (2 * H)
    err_g = np.linalg.norm(fd_g - g, axis=1) / np.linalg.norm(g, axis=1)
    err_K = np.linalg.norm(fd_K - K, axis=1) / np.linalg.norm(K, axis=1)
    print(f"FD relative errors: gradient {err_g.max():.1e}, tangent {err_K.max():.1e}")
    assert err_g.max() <= RTOL and err_K.max() <= RTOL
    np.testing.assert_allclose(K, np.swapaxes(K, 1, 2), rtol=0, atol=1e-12 * np.abs(K).max())


# ------------------------------------------------------------------ rigid motion
@pytest.mark.parametrize("alpha2", [1.0, 0.1])
def test_rigid_motion_of_straight_mesh_is_strain_free(alpha2):
    """Rotation by 2.5 rad about (1, -2, 0.5), then by 1.1 rad about z, and translation
    by (3, -1, 2) m of a straight 4-element mesh: U <= 1e-12 E A L and
    |dU/de| <= 1e-9 E A (round-off gives ~1e-20 J and ~1e-6 N)."""
    m, q0, asm, _ = cantilever(4, section=FLAT, alpha2=alpha2)
    R = _rotation([0, 0, 1], 1.1) @ _rotation([1, -2, 0.5], 2.5)
    Q = q0.reshape(m.n_nodes, 4, 3) @ R.T
    Q[:, 0] += [3.0, -1.0, 2.0]
    q = Q.ravel()
    EA = MODEL1["E"] * FLAT.area
    U, g = asm.strain_energy(q), np.abs(asm.gradient(q)).max()
    print(f"rigid motion: U = {U:.1e} J, |dU/de| = {g:.1e} N")
    assert abs(U) <= 1e-12 * EA * MODEL1["L"]
    assert g <= 1e-9 * EA


# -------------------------------------------------------- energy by the definition
def _unit(v):
    return v / np.linalg.norm(v)


def _energy_by_definition(el, e, E_mod, nu, ks, n_sec=5):
    """U of Eq. 4.34 (alpha = 1) from the field r = r_c + y r_s^y + z r_s^z (4.37) with
    the frames written as the thesis' cross products (4.28-4.29, as read), r_x by a
    fourth-order central difference along x (step l/1000: error ~1e-12 relative),
    the Green strains eps_xx, eps_xy, eps_xz at 8 x n_sec x n_sec Gauss points and the
    nodal-interpolated eps_yy, eps_zz, eps_yz: numpy, independent of the generated code."""
    Ee = e.reshape(el.nel, 8, 3)
    xi, wx = gauss01(8)
    hh, bb = el.section.h, el.section.b
    ty, wy = gauss01(n_sec)
    ys, zs, wyz = (ty - 0.5) * hh, (ty - 0.5) * bb, np.outer(wy * hh, wy * bb)
    G = E_mod / (2 * (1 + nu))
    U = np.zeros(el.nel)
    for i, le in enumerate(el.lengths):
        E_i = Ee[i]
        rx, ry, rz = E_i[[1, 5]], E_i[[2, 6]], E_i[[3, 7]]

        def shear(rd):
            return -np.einsum("kd,kd->k", rx, rd) / (np.linalg.norm(rx, axis=1) * np.linalg.norm(rd, axis=1))

        sy, sz = shear(ry), shear(rz)
        nod = np.array([0.5 * (np.einsum("kd,kd->k", ry, ry) - 1), 0.5 * (np.einsum("kd,kd->k", rz, rz) - 1),
                        0.5 * np.einsum("kd,kd->k", ry, rz)])

        def sections(x):
            X = np.array([x])
            zero = 0.0 * X
            a = shape_gen.cubic3d_x(X, zero, zero, le)[0] @ E_i
            p = shape_gen.cubic3d_y(X, zero, zero, le)[0] @ E_i
            q = shape_gen.cubic3d_z(X, zero, zero, le)[0] @ E_i
            rc = shape_gen.cubic3d_S(X, zero, zero, le)[0] @ E_i
            t = _unit(a)
            b_y = _unit(np.cross(t, p))
            n_z = _unit(np.cross(q, t))
            f = x / le
            rsy = np.cross(b_y, t) - ((1 - f) * sy[0] + f * sy[1]) * t
            rsz = np.cross(t, n_z) - ((1 - f) * sz[0] + f * sz[1]) * t
            return rc, rsy, rsz

        hx = le / 1000
        for f, w in zip(xi, wx):
            x = f * le
            rc, rsy, rsz = sections(x)
            eyy, ezz, eyz = (1 - f) * nod[:, 0] + f * nod[:, 1]
            S = [sections(x + k * hx) for k in (-2, -1, 1, 2)]
            d = [(S[0][j] - 8 * S[1][j] + 8 * S[2][j] - S[3][j]) / (12 * hx) for j in range(3)]
            for a_, y in enumerate(ys):
                for b_, z in enumerate(zs):
                    r_x = d[0] + y * d[1] + z * d[2]
                    exx, exy, exz = 0.5 * (r_x @ r_x - 1), 0.5 * r_x @ rsy, 0.5 * r_x @ rsz
                    dens = 0.5 * (E_mod * (exx**2 + eyy**2 + ezz**2)
                                  + 4 * G * (ks * exy**2 + ks * exz**2 + eyz**2))
                    U[i] += w * le * wyz[a_, b_] * dens
    return U


def test_energy_equals_definition_with_alpha_one():
    """Kernel energy (generated density, closed-form section) against Eq. 4.34 with the
    strains of the field of Eq. 4.37 integrated over the volume numerically, at a
    random large deformation (coordinates moved by 0.1 m or 0.1) of a b != h section:
    equal to 1e-9 relative (both use the same 8 Gauss points along x; the section
    rule is exact; the difference is the finite difference along x)."""
    m = BeamMesh(2.0, 3, DufvaBelt3D.slots, dim=3)
    q0 = m.reference()
    el = DufvaBelt3D(m.lengths, q0[m.dofmap], FLAT, E=2.0e11, nu=0.25, ks=0.9, nx=8)
    rng = np.random.default_rng(5)
    q = q0 + 0.1 * rng.standard_normal(q0.size)
    U = el.energy(q[m.dofmap])
    ref = _energy_by_definition(el, q[m.dofmap], 2.0e11, 0.25, 0.9)
    print("energy vs definition, relative:", U / ref - 1)
    np.testing.assert_allclose(U, ref, rtol=1e-9)


# ------------------------------------------------------------ the planar element
@pytest.mark.parametrize("n", [1, 3])
def test_bending_in_either_principal_plane_is_the_planar_element(n):
    """Small tip load F = -50 N along y, and along z (square section, so the x-z plane
    mirrors the x-y plane): the 3D tip deflection equals the planar element's
    (ancf/belt_element_checks.tip_under) to 1e-10 relative; the beam stays in its
    plane (out-of-plane tip displacement below 1e-12 m)."""
    F = -50.0
    ref = planar.tip_under(n, (0.0, F), n_steps=1)
    ty = tip_under(n, (0.0, F, 0.0))
    tz = tip_under(n, (0.0, 0.0, F))
    print(f"{n} el: 2D {ref[1]:.12e}, 3D x-y {ty[1] / ref[1] - 1:.1e}, x-z {tz[2] / ref[1] - 1:.1e}")
    assert ty[1] == pytest.approx(ref[1], rel=1e-10)
    assert tz[2] == pytest.approx(ref[1], rel=1e-10)
    assert ty[0] == pytest.approx(ref[0], rel=1e-12) and tz[0] == pytest.approx(ref[0], rel=1e-12)
    assert abs(ty[2]) < 1e-12 and abs(tz[1]) < 1e-12


@pytest.mark.parametrize("plane", [1, 2])
def test_large_deflection_in_plane_is_the_planar_element(plane):
    """Model 1 load F = -5e5 N on 4 elements (tip deflection ~0.8 m) along y, and along
    z (square section): the 3D tip in that plane equals the planar element's to 1e-9
    of the deflection, and stays in the plane."""
    F = np.zeros(3)
    F[plane] = MODEL1["F"]
    ref = planar.tip_under(4, (0.0, MODEL1["F"]))
    t3 = tip_under(4, F, n_steps=4)
    print(f"large deflection, plane {plane}, 3D - 2D:", t3[[0, plane]] - ref)
    assert np.abs(t3[[0, plane]] - ref).max() <= 1e-9 * abs(ref[1])
    assert abs(t3[3 - plane]) <= 1e-12


# ------------------------------------------------------------------ alpha factors
@pytest.mark.parametrize("plane", [1, 2])
def test_halving_alpha2_doubles_small_deflection_in_both_planes(plane):
    """F = -0.25 N along y (plane 1) or z (plane 2) on the b = 0.05 m (z), h = 0.1 m (y)
    section (tip deflections 7.7e-7 m and 3.1e-6 m: geometric terms ~(v/L)^2 below
    1e-11): bending and both shear terms are scaled by alpha2, so the linearised tip
    deflection doubles; tolerance 1e-8 relative.  (With F = -50 N the ratio is off
    by 5e-8 and 1.6e-6: the geometric nonlinearity, which alpha2 does not scale.)"""
    F = np.zeros(3)
    F[plane] = -0.25
    v = {a2: tip_under(2, F, section=FLAT, alpha2=a2)[plane] for a2 in (1.0, 0.5)}
    print(f"plane {plane}: ratio - 2 = {v[0.5] / v[1.0] - 2:.1e}")
    assert v[0.5] / v[1.0] == pytest.approx(2.0, rel=1e-8)


def test_alpha2_leaves_axial_stiffness_and_alpha1_sets_it():
    """Axial tip load F = 1e5 N: the same tip displacement for alpha2 = 1 and 0.5 (to
    1e-9), and with alpha1 = 0.5 the Green law F = E A alpha1 (lambda^2 - 1)/2 lambda
    (closed form, to 1e-9)."""
    F, L = 1e5, MODEL1["L"]
    EA = MODEL1["E"] * SECTION1.area
    u = {}
    for a1, a2 in ((1.0, 1.0), (1.0, 0.5), (0.5, 1.0)):
        u[a1, a2] = tip_under(3, (F, 0.0, 0.0), alpha1=a1, alpha2=a2)[0] - L
        lam = np.max(np.roots([1.0, 0.0, -1.0, -2 * F / (EA * a1)]).real)
        assert u[a1, a2] == pytest.approx((lam - 1.0) * L, rel=1e-9)
    assert u[1.0, 0.5] == pytest.approx(u[1.0, 1.0], rel=1e-9)


# ---------------------------------------------------------------------- Timoshenko
@pytest.mark.parametrize("plane", [1, 2])
def test_small_load_cantilever_is_timoshenko(plane):
    """F = -0.25 N on one element of the b = 0.05 m (z), h = 0.1 m (y) section: the
    linearised element is Timoshenko's beam (cubic centre line, linear shear angle),
    tip deflection F L^3/(3EI) + F L/(ks G A) with I = b h^3/12 (y) or h b^3/12 (z);
    as in 2D, tolerance 1e-7 relative (with F = -50 N the x-z error is -2.3e-6:
    geometric nonlinearity at v/L = 3e-4)."""
    F = np.zeros(3)
    F[plane] = -0.25
    h, b = (FLAT.h, FLAT.b) if plane == 1 else (FLAT.b, FLAT.h)
    lin = timoshenko.cantilever_tip_deflection(MODEL1["E"], MODEL1["nu"], MODEL1["L"], h, b, F[plane])
    tip = tip_under(1, F, section=FLAT)[plane]
    print(f"plane {plane}: Timoshenko relative error {tip / lin - 1:.1e}")
    assert tip == pytest.approx(lin, rel=1e-7)


# ---------------------------------------------------------------------- bad input
@pytest.mark.parametrize("field,value", [("E", 0.0), ("E", float("nan")), ("nu", 0.5),
                                         ("nu", -1.0), ("alpha1", 0.0), ("alpha2", -1.0),
                                         ("ks", 0.0), ("rho", -1.0), ("nx", 0), ("nx", 2.5)])
def test_bad_arguments_raise_naming_the_field(field, value):
    m = BeamMesh(2.0, 2, DufvaBelt3D.slots, dim=3)
    kw = {"E": 2e11, "nu": 0.3, field: value}
    with pytest.raises(ValueError, match=f"^{field} must be"):
        DufvaBelt3D(m.lengths, m.reference()[m.dofmap], SECTION1, **kw)


def test_bad_lengths_section_and_reference_raise():
    m = BeamMesh(2.0, 2, DufvaBelt3D.slots, dim=3)
    e0 = m.reference()[m.dofmap]
    with pytest.raises(ValueError, match="^lengths must be"):
        DufvaBelt3D([1.0, -1.0], e0, SECTION1, E=2e11, nu=0.3)
    with pytest.raises(ValueError, match="^e0 size must be"):
        DufvaBelt3D(m.lengths, e0[:, :12], SECTION1, E=2e11, nu=0.3)
    with pytest.raises(ValueError, match=r"^section\.b must be"):
        DufvaBelt3D(m.lengths, e0, RectangularSection(0.0, 0.1), E=2e11, nu=0.3)


def test_axial_force_under_axial_load():
    """Axial tip load F = 1e5 N, alpha1 = 0.5: axial_force gives N = E A alpha1 eps_l =
    F/lambda along the beam (to 1e-5 N, round-off as in the planar test)."""
    F = 1e5
    m, q0, asm, elim = cantilever(3, alpha1=0.5)
    Qk = np.zeros(m.n_dofs)
    Qk[m.dof(3, "r", 0)] = F
    res = solve_static(asm, elim, Qk, q0, NewtonOptions(n_steps=1, rtol=1e-10))
    assert res.converged, res.message
    lam = np.max(np.roots([1.0, 0.0, -1.0, -2 * F / (MODEL1["E"] * SECTION1.area * 0.5)]).real)
    N = asm.groups[0].element.axial_force(res.q[m.dofmap], np.linspace(0, 1, 5))
    np.testing.assert_allclose(N, F / lam, rtol=0, atol=1e-5)


def test_uniform_twist_energy_is_the_shear_torsional_stiffness():
    """Nodal sections r_y, r_z turned about the straight axis by phi x/L (phi = 1e-4
    rad, positions and r_x untouched), b != h, alpha2 = 0.5: the energy is
    ks G alpha2 (I_y + I_z) phi^2/(2 L) (the module docstring's torsional stiffness)
    up to O(phi^2) and the O((phi/n)^2) chord of the linearly interpolated slopes;
    tolerance 1e-6 relative."""
    phi, L, ks, nu, a2 = 1e-4, MODEL1["L"], 5.0 / 6.0, MODEL1["nu"], 0.5
    m, q0, asm, _ = cantilever(4, section=FLAT, alpha2=a2, ks=ks)
    Q = q0.reshape(m.n_nodes, 4, 3).copy()
    for node, x in enumerate(m.X):
        R = _rotation([1, 0, 0], phi * x / L)
        Q[node, 2:] = Q[node, 2:] @ R.T
    U = asm.strain_energy(Q.ravel())
    G = MODEL1["E"] / (2 * (1 + nu))
    Iy, Iz = FLAT.b * FLAT.h**3 / 12, FLAT.h * FLAT.b**3 / 12
    ref = ks * G * a2 * (Iy + Iz) * phi**2 / (2 * L)
    print(f"uniform twist: U/ref - 1 = {U / ref - 1:.1e}")
    assert U == pytest.approx(ref, rel=1e-6)
