"""The thin ANCF plate (thesis 4.3, Eqs 4.14-4.19) and its rectangular mesh.

Generated code up to date; finite-difference gradient and tangent; rigid motion;
exact membrane force under a uniform stretch; exact mass; the bending switch; the
simply supported square plate under uniform pressure against Navier's series
(linear solve at the flat reference: the deflection is h/47).

Navier, a = 1 m, h = 0.01 m, E = 2.1e11 Pa, nu = 0.3, p = 1e3 Pa (w_c = 2.1124e-4 m),
relative centre-deflection errors seen: 2 x 2 +24.6 %, 4 x 4 +6.54 %, 8 x 8 +1.65 %,
16 x 16 +0.41 % (order 2.0 from 4 to 16).

Cantilever strip 1 m x 0.05 m under an end load, against Euler-Bernoulli P L^3/(3 E I):
with nu = 0 the cubic beam deflection lies in the element space and every mesh
gives it (1 x 1: 2e-11, 8 x 2: 2e-7 relative, round-off); with nu = 0.3 the plate
is stiffer than E I (read as the clamp suppressing anticlastic curvature): -6.7 %, -3.9 %,
-2.0 %, -1.1 % with 1, 2, 4, 8 x 1 elements, -0.70 % with 16 x 2, -0.57 % with 32 x 4.
Large deflection (nu = 0, F = E I/L^2, tip at 0.30 L; scene plate-strip, Newton)
against the Reissner beam (analytic/reissner.py, shear switched off: ks = 1e6): largest
relative tip-coordinate error 6.2e-3, 2.0e-4, 7.3e-6 with 4, 8, 16 x 1 elements.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from analytic import navier_plate, plate_thin
from ancf.checks import elements3d as checks
from ancf.models import plate as plate_models
from ancf.core.assembly import Assembly, ElementGroup
from ancf.elements.plate36 import Plate36
from ancf.models.plate_mesh import SLOTS, PlateMesh
from tests.analytic.test_codegen import REGENERATE

STEEL = dict(h=0.01, E=2.1e11, nu=0.3)
NAVIER_TOL = 0.01  # relative centre-deflection error of the finest mesh
FD_TOL = 1e-6      # central differences (step 1e-6) relative to the largest entry


def _plate(m: PlateMesh, **kw) -> Plate36:
    return Plate36(m.lengths, m.widths, **{**STEEL, **kw})


def _rotation(axis, angle):
    """Rodrigues' rotation matrix about ``axis`` by ``angle`` rad."""
    k = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    Kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * Kx + (1 - math.cos(angle)) * Kx @ Kx


def _perturbed(m, scale, seed=0):
    q0 = m.reference()
    return q0 + scale * np.random.default_rng(seed).standard_normal(q0.size)


# ------------------------------------------------------------------ generated code
@pytest.mark.slow
@REGENERATE  # the stamp test in tests/analytic/test_codegen.py runs always
def test_generated_plate_code_is_up_to_date():
    assert plate_thin.generate() == plate_thin.TARGET.read_text(), (
        "ancf/elements/_plate_generated.py is stale: run `python -m analytic.plate_thin --write`")


# ------------------------------------------------------------------ derivatives
@pytest.mark.parametrize("bending", [True, False])
def test_gradient_and_tangent_match_finite_differences(bending):
    m = PlateMesh(0.6, 0.4, 2, 1)
    el = _plate(m, bending=bending)
    e = _perturbed(m, 0.05)[m.dofmap]
    g, K = el.gradient(e, tangent=True)
    step, eye = 1e-6, np.eye(el.ndof)
    gfd = np.stack([(el.energy(e + step * eye[i]) - el.energy(e - step * eye[i])) / (2 * step)
                    for i in range(el.ndof)], -1)
    Kfd = np.stack([(el.gradient(e + step * eye[i])[0] - el.gradient(e - step * eye[i])[0])
                    / (2 * step) for i in range(el.ndof)], -1)
    assert np.abs(gfd - g).max() <= FD_TOL * np.abs(g).max()
    assert np.abs(Kfd - K).max() <= FD_TOL * np.abs(K).max()
    assert np.abs(K - K.transpose(0, 2, 1)).max() <= 1e-12 * np.abs(K).max()


def test_rigid_motion_has_zero_energy_and_force():
    m = PlateMesh(0.6, 0.4, 2, 2)
    el = _plate(m)
    R = _rotation([1.0, 2.0, 3.0], 1.3)
    q = (m.reference().reshape(-1, 3) @ R.T).ravel()
    r = [m.dof(n, "r", c) for n in range(m.n_nodes) for c in range(3)]
    q[r] += np.tile([0.3, -2.0, 5.0], m.n_nodes)
    scale = STEEL["E"] * STEEL["h"] * m.a * m.b  # J at unit strain
    g, _ = el.gradient(q[m.dofmap])
    assert np.abs(el.energy(q[m.dofmap])).max() <= 1e-12 * scale
    assert np.abs(g).max() <= 1e-12 * STEEL["E"] * STEEL["h"] * m.a


# ------------------------------------------------------------------ membrane
def test_uniform_stretch_gives_the_plane_stress_green_force():
    """r = (lx X, ly Y, 0): Green strains (l^2 - 1)/2, S_xx = E h/(1 - nu^2) (e_xx + nu e_yy)
    per unit length; the edge x = a carries the force lx S_xx b along x."""
    m = PlateMesh(0.6, 0.4, 3, 2)
    el = _plate(m)
    lx, ly = 1.02, 0.99
    q = m.reference().reshape(m.n_nodes, 3, 3) * np.array([lx, ly, 1.0])
    asm = Assembly(m.n_dofs, [ElementGroup(el, m.dofmap)])
    exx, eyy = (lx**2 - 1) / 2, (ly**2 - 1) / 2
    E, h, nu = STEEL["E"], STEEL["h"], STEEL["nu"]
    Sxx = E * h / (1 - nu**2) * (exx + nu * eyy)
    U = m.a * m.b * E * h / (2 * (1 - nu**2)) * (exx**2 + eyy**2 + 2 * nu * exx * eyy)
    g = asm.gradient(q.ravel())
    edge = [m.dof(m.node(m.nx, j), "r", 0) for j in range(m.ny + 1)]
    assert asm.strain_energy(q.ravel()) == pytest.approx(U, rel=1e-12)
    assert g[edge].sum() == pytest.approx(lx * Sxx * m.b, rel=1e-12)


# ------------------------------------------------------------------ mass, switch
def test_mass_of_a_rigid_translation_is_rho_h_area():
    m = PlateMesh(0.6, 0.4, 3, 2)
    M = Assembly(m.n_dofs, [ElementGroup(_plate(m, rho=7800.0), m.dofmap)]).mass()
    u = np.zeros(m.n_dofs)
    u[[m.dof(n, "r", 2) for n in range(m.n_nodes)]] = 1.0
    assert u @ M @ u == pytest.approx(7800.0 * STEEL["h"] * m.a * m.b, rel=1e-12)


def test_bending_switch_removes_the_transverse_stiffness():
    m = PlateMesh(0.6, 0.4, 1, 1)
    z = np.arange(2, 36, 3)
    e0 = m.reference()[m.dofmap]
    K_on, K_off = (_plate(m, bending=b).gradient(e0, tangent=True)[1][0][np.ix_(z, z)]
                   for b in (True, False))
    assert np.abs(K_off).max() <= 1e-14 * STEEL["E"] * STEEL["h"]  # round-off of the membrane
    # all but the rigid w = c0 + c1 x + c2 y (the rest is membrane round-off, 1e-14 relative)
    assert np.linalg.matrix_rank(K_on, rtol=1e-10) == 12 - 3


# ------------------------------------------------------------------ mesh
def test_mesh_shares_nodes_and_loads_the_whole_pressure():
    m = PlateMesh(0.6, 0.4, 3, 2)
    assert m.n_dofs == 12 * 9 and m.dofmap.shape == (6, 36)
    assert np.array_equal(m.dofmap[0, 9:18], m.dofmap[1, 0:9])       # B of 0 = A of 1
    assert np.array_equal(m.dofmap[0, 18:27], m.dofmap[4, 0:9])      # C of 0 = A of 4
    e0 = m.reference()[m.dofmap].reshape(6, 4, 3, 3)
    assert np.allclose(e0[:, 2, 0, :2] - e0[:, 0, 0, :2], [m.a / 3, m.b / 2], rtol=0, atol=1e-15)
    assert m.dof(m.node(1, 1), "r_y", 1) == 5 * 9 + 3 * SLOTS.index("r_y") + 1
    assert m.pressure_load(1e3)[2::9].sum() == pytest.approx(1e3 * m.a * m.b, rel=1e-12)


# ------------------------------------------------------------------ Navier
def test_navier_double_series_matches_levy_single_series():
    for a, b in ((1.0, 1.0), (2.0, 1.0)):
        w, _ = navier_plate.centre_deflection(a, b, p=1e3, rtol=1e-10, **STEEL)
        assert w == pytest.approx(navier_plate.levy_centre_deflection(a, b, p=1e3, **STEEL), rel=1e-8)


def _double_series(a, b, h, E, nu, p, N):
    """The former implementation: Navier's double series over odd m, n <= N (computed
    here, independently of analytic.navier_plate's single series)."""
    k = np.arange(1, N + 1, 2, dtype=float)
    m, n = k[:, None], k[None, :]
    sign = np.where(((m + n) / 2 - 1) % 2 == 0, 1.0, -1.0)
    s = float(np.sum(sign / (m * n * (m**2 / a**2 + n**2 / b**2) ** 2)))
    return 16.0 * p / (math.pi**6 * navier_plate.rigidity(E, nu, h)) * s


def _double_series_tail(N, a, b):
    """The former truncation bound of the double series beyond max(m, n) = N."""
    return max(a, b) ** 4 * ((1.0 + math.log(N)) / (2.0 * N**4) + 1.0 / (8.0 * N**4))


# (a, b, largest odd index of the double series): its tail bound at N is below 1e-8 of the sum
@pytest.mark.parametrize("a, b, N", [(1.0, 1.0, 201), (2.0, 1.0, 321), (1.0, 3.0, 461),
                                     (0.4, 1.0, 391)])
def test_single_series_equals_the_former_double_series(a, b, N):
    ref = _double_series(a, b, p=1e3, N=N, **STEEL)
    s = abs(ref) * math.pi**6 * navier_plate.rigidity(**{k: STEEL[k] for k in ("E", "nu", "h")}) / 16e3
    assert _double_series_tail(N, a, b) <= 1e-8 * s  # the reference is good to 1e-8
    w, terms = navier_plate.centre_deflection(a, b, p=1e3, rtol=1e-12, **STEEL)
    assert w == pytest.approx(ref, rel=2e-8)
    assert 1 <= terms <= 25
    assert navier_plate.centre_deflection(b, a, p=1e3, rtol=1e-12, **STEEL)[0] == pytest.approx(
        w, rel=1e-14)  # the same plate turned by 90 degrees


# Timoshenko & Woinowsky-Krieger, Table 8: w_c = alpha q a^4 / D (b >= a), any nu in D
@pytest.mark.parametrize("b_over_a, alpha, tol", [(1.0, 0.00406235, 1e-6), (2.0, 0.01013, 5e-4),
                                                  (1e9, 0.01302, 5e-4)])
def test_centre_deflection_coefficient_matches_timoshenko(b_over_a, alpha, tol):
    a, q, h, E, nu = 0.7, 2.5e3, 0.01, 2.1e11, 0.3
    D = E * h**3 / (12 * (1 - nu**2))
    w, _ = navier_plate.centre_deflection(a, b_over_a * a, h, E, nu, q, rtol=1e-14)
    assert w / (q * a**4 / D) == pytest.approx(alpha, rel=tol)
    assert navier_plate.coefficient(b_over_a) == pytest.approx(alpha, rel=tol)
    # the infinite strip: 5 / 384 = 0.0130208..., the beam of unit width on its short span
    if b_over_a > 1e6:
        assert w / (q * a**4 / D) == pytest.approx(5 / 384, rel=1e-12)


@pytest.mark.parametrize("rtol", [1e-2, 1e-10, 1e-14])
@pytest.mark.parametrize("a, b", [(1.0, 1.0), (10.0, 1.0), (1.0, 1e3), (1e-70, 1e3), (1e3, 1e-3)])
def test_series_cost_is_bounded_for_every_aspect_ratio(a, b, rtol):
    """The work is the number of terms: at most 25 whatever the ratio (the former double
    series needed N^2 / 4 terms with N growing like the aspect ratio)."""
    w, terms = navier_plate.centre_deflection(a, b, p=1e3, rtol=rtol, **STEEL)
    assert math.isfinite(w) and w > 0 and 1 <= terms <= 25
    w_tight, _ = navier_plate.centre_deflection(a, b, p=1e3, rtol=1e-14, **STEEL)
    assert w == pytest.approx(w_tight, rel=rtol)


@pytest.mark.parametrize("kw, field, what", [
    (dict(a=1e300, b=1e300), "a", "overflows"), (dict(a=1e-300), "a", "underflows"),
    (dict(b=1e-300), "b", "underflows"), (dict(h=1e-300), "h", "underflows"),
    (dict(h=1e300), "h", "overflows"), (dict(E=1e300, h=1e2), "E", "overflows"),
    (dict(p=1e-300, E=1e300), "p", "underflows")])
def test_out_of_range_magnitudes_are_refused_naming_the_field(kw, field, what):
    args = dict(a=1.0, b=1.0, p=1e3, **STEEL) | kw
    with pytest.raises(ValueError, match=rf"^{field} = .* is out of range: .*{what} double"):
        navier_plate.centre_deflection(**args)


def test_simply_supported_plate_converges_to_navier():
    """Scene plate-square per mesh (ancf.checks.elements3d.plate_convergence)."""
    rows = checks.plate_convergence((4, 8, 16))
    err = np.array([r["relative error"] for r in rows])
    assert abs(err[-1]) <= NAVIER_TOL
    assert np.all(np.abs(np.diff(np.abs(err))) > 0) and np.all(np.diff(np.abs(err)) < 0)
    order = np.array([r["observed order"] for r in rows[1:]])
    assert np.all(np.abs(order - 2) <= 0.2), order


def test_bad_input_names_the_field():
    for kw, field in ((dict(a=-1.0), "a, b"), (dict(nu=0.5), "nu"), (dict(ng=0), "ng"),
                      (dict(h=0.0), "h")):
        with pytest.raises(ValueError, match=field):
            Plate36(**{"a": 1.0, "b": 1.0, **STEEL, **kw})
    with pytest.raises(ValueError, match="nx"):
        PlateMesh(1.0, 1.0, 0, 1)


# ------------------------------------------------------------------ cantilever strip
STRIP_TOL = 1e-6  # nu = 0: the cubic beam deflection is in the element space


def _strip_tip(nx, ny, L=1.0, b=0.05, P=1.0, nu=0.0):
    """Mean tip deflection (m) of a strip L x b clamped at x = 0 (r, r_x, r_y), linear solve."""
    return plate_models.strip_linear_tip(nx, ny, L, b, STEEL["h"], STEEL["E"], nu, P)


@pytest.mark.parametrize("nx, ny", [(1, 1), (4, 1), (8, 2)])
def test_cantilever_strip_matches_euler_bernoulli(nx, ny):
    L, b, P = 1.0, 0.05, 1.0
    w_eb = P * L**3 / (3 * STEEL["E"] * b * STEEL["h"] ** 3 / 12)
    assert _strip_tip(nx, ny, L, b, P) == pytest.approx(w_eb, rel=STRIP_TOL)


REISSNER_STRIP_TOL = 1e-3  # relative tip error of the 8 x 1 strip (large deflection)


def test_cantilever_strip_large_deflection_converges_to_reissner():
    """F = E I / L^2 bends the strip to a tip deflection of 0.30 L (scene plate-strip,
    nu = 0, against the Reissner rod with shear switched off; ancf.checks.elements3d)."""
    err = [r["relative error"] for r in checks.strip_large((4, 8, 16))]
    assert err[1] <= REISSNER_STRIP_TOL and err[2] < err[1] < err[0], err


# ------------------------------------------------------------------ CLI: ancf analytic navier-plate
def test_cli_navier_plate_is_the_series_and_levys_value(capsys):
    """`ancf analytic navier-plate --json` (defaults: a = b = 1 m, h = 0.01 m, E = 2.1e11,
    nu = 0.3, p = 1e3 Pa) equals Levy's single series to 1e-8 relative; a zero-width plate
    is one error line naming the field."""
    import json

    from ancf.cli import main
    assert main(["analytic", "navier-plate", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    levy = navier_plate.levy_centre_deflection(1.0, 1.0, 0.01, 2.1e11, 0.3, 1e3)
    levy = levy[0] if isinstance(levy, tuple) else levy
    assert out["results"]["center_deflection_m"] == pytest.approx(levy, rel=1e-8)
    assert main(["analytic", "navier-plate", "--set", "b=0"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: b = 0")
