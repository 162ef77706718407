"""The plate of Chrono's ANCF shells (``ancf.models.chrono_shell``): assembly identities,
Chrono's static shell checks at its own tolerances, and the suite's simply supported
square plate against Navier's deflection and frequencies.

Chrono's checks: ``src/tests/unit_tests/fea/utest_FEA_ANCFshell_3443_Formulation.cpp`` and
``..._3833_Formulation.cpp`` (projectchrono/chrono 7689fbc02d12c5419fa6acad8791100fd89979dd),
line numbers "3443 / 3833".  A strip of 20 elements (:1258 / :1264) of length 20 in, width
0.5 in (y), height 0.125 in (the layer thickness, z) (:1259-1261 / :1265-1267), aluminium
rho = 2810 kg/m^3, E = 71.7 GPa, nu = 0.33 (:1263-1265 / :1269-1271), mid-surface
y in [-w/2, w/2], the nodes at x = 0 fixed (``SetFixed``), loads at the last element's
(xi, eta) = (1, 0) (``SetApplication(1.0, 0.0)``), TIP_FORCE = TIP_MOMENT = 1 (:57-58),
``DoStaticLinear`` (we solve by Newton), the frame of ``EvaluateSectionFrame(1, 0)`` and
its ``GetCardanAnglesXYZ``.  Formulas and percent tolerances (3443 / 3833), off-axis
angles below 0.001 deg:

    axial pull  u_x = P L/(w h E)                       2 / 2     (:1370, :1376 / :1388, :1394)
    tip load    u_z = P L^3/(3 E I), I = w h^3/12        15 / 2    (:1545-1554 / :1573-1582)
    gravity     u_z = rho w h g L^4/(8 E I), g = -9.80665  15 / 2  (:1683-1692 / :1721-1730)
    tip twist   theta = M L/(G J), J = 0.281 w h^3        15 / 15  (:1868-1872 / :1918-1922)

(the multi-layer ``MLCantileverCheck*`` are not reproduced here).
"""
from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg
import scipy.sparse.linalg as spla

from ancf.checks import chrono_elements as ce
from ancf.models import chrono_shell as cs

# Chrono's strip, loads, textbook formulas and tolerances, and the square plate:
# ``ancf.checks.chrono_elements``
G = ce.GRAV                                     # m/s^2


@pytest.mark.parametrize("element", ["3443", "3833"])
@pytest.mark.parametrize("case", ["axial"] + [pytest.param(c, marks=pytest.mark.slow)
                                             for c in ("tip", "gravity", "twist")])
def test_chrono_static_check(element, case):
    r, angles, sol = ce.strip_solution(element, case)
    model, theory = ce.measured(case, r, angles), ce.reference(element, case)
    percent, angle_deg = ce.TOLERANCE[element, case]
    assert sol.residual <= max(1e-10, sol.floor)
    assert abs(100 * (model - theory) / theory) < percent
    assert np.all(np.abs(np.degrees(angles[list(ce.CASES[case][1])])) < angle_deg)


# ---------------------------------------------------------------------------------------
# Assembly identities on a small plate
# ---------------------------------------------------------------------------------------

SMALL = dict(nx=3, ny=2, a=0.6, b=0.5, H=0.01, E=2.0e11, nu=0.3, rho=7800.0, x0=0.2, y0=-0.1)


@pytest.mark.parametrize("element", ["3443", "3833"])
def test_mesh_shares_nodes(element):
    """(nx + 1)(ny + 1) corner nodes; the 3833 adds mid-sides: (2nx + 1)(2ny + 1) - nx ny;
    every element's slice of e0 is its own reference moved to its corner."""
    plate = cs.Plate(element, **SMALL)
    nx, ny = SMALL["nx"], SMALL["ny"]
    count = (nx + 1) * (ny + 1) if element == "3443" else (2 * nx + 1) * (2 * ny + 1) - nx * ny
    assert len(plate.grid) == count
    e0 = plate.reference()
    for k in range(plate.nx * plate.ny):     # each element's slice is its own reference
        shift = np.zeros(plate.module.NDOF)
        shift.reshape(-1, 3)[::plate.ncoord // 3, :2] = e0[plate.dofs[k]].reshape(-1, 3)[0, :2]
        np.testing.assert_allclose(e0[plate.dofs[k]], plate.element_reference + shift,
                                   atol=1e-15)


@pytest.mark.parametrize("element", ["3443", "3833"])
def test_rigid_motion_mass_and_loads(element):
    """A rigid translation t: t^T M t = rho a b H, K(e0) t = 0, and the z-position entries
    of gravity and pressure add up to rho a b H g and p a b."""
    plate = cs.Plate(element, **SMALL)
    z = np.arange(len(plate.grid))
    t = np.zeros(plate.ndof)
    t[plate.coordinate(z, 0, 2)] = 1.0
    volume = plate.a * plate.b * plate.H
    np.testing.assert_allclose(t @ (cs.mass(plate) @ t), plate.rho * volume, rtol=1e-12)
    K = cs.reference_stiffness(plate)
    assert np.abs(K @ t).max() <= 1e-12 * abs(K).max()
    np.testing.assert_allclose(t @ cs.gravity(plate, (0, 0, G)), plate.rho * volume * G,
                               rtol=1e-12)
    np.testing.assert_allclose(t @ cs.pressure(plate, 250.0), 250.0 * plate.a * plate.b,
                               rtol=1e-12)
    Q, Kt = cs.assemble(plate, plate.reference())
    assert np.abs(Q).max() == 0.0
    assert abs(Kt - K).max() <= 1e-12 * abs(K).max()


@pytest.mark.parametrize("element", ["3443", "3833"])
def test_batched_assembly_is_the_element_by_element_sum(element):
    """``assemble`` (all elements in one ``continuum3d.static_batch``) equals the sum of the
    element's own ``internal_force`` and ``internal_force_jacobians`` at a random state
    within 1e-13 of the largest entry; a state moved by 1e-9 m does not."""
    plate = cs.Plate(element, **SMALL)
    e = plate.reference() + 1e-3 * np.random.default_rng(1).standard_normal(plate.ndof)
    Q, K = cs.assemble(plate, e)
    m, zero = plate.module, np.zeros(plate.module.NDOF)
    args = (*plate.dims, plate.H, *plate.material())
    Q0, K0 = np.zeros(plate.ndof), np.zeros((plate.ndof, plate.ndof))
    for d in plate.dofs:
        Q0[d] += m.internal_force(e[d], zero, *args, **plate.options())
        K0[np.ix_(d, d)] += m.internal_force_jacobians(e[d], zero, *args, **plate.options())[0]
    assert np.abs(Q - Q0).max() <= 1e-13 * np.abs(Q0).max()
    assert np.abs(K.toarray() - K0).max() <= 1e-13 * np.abs(K0).max()
    moved = cs.assemble(plate, e + 1e-9, tangent=False)[0]
    assert np.abs(moved - Q0).max() > 1e-13 * np.abs(Q0).max()


@pytest.mark.parametrize("element", ["3443", "3833"])
def test_sparse_modes_equal_the_dense_eigenproblem(element):
    """``modes`` (shift-invert Lanczos) equals ``scipy.linalg.eigh`` on the dense K(e0),
    M of a 4 x 4 simply supported plate within 1e-8 relative; a 1 % denser plate's
    frequencies do not."""
    plate, fixed = ce.square_plate(element, 4)
    f = plate.free(fixed)
    K, M = (x[f][:, f].toarray() for x in (cs.reference_stiffness(plate), cs.mass(plate)))
    dense = np.sqrt(scipy.linalg.eigh(K, M, eigvals_only=True, subset_by_index=(0, 5)))
    dense /= 2 * np.pi
    ours = cs.modes(plate, fixed)
    np.testing.assert_allclose(ours, dense, rtol=1e-8)
    assert not np.allclose(ours, dense / np.sqrt(1.01), rtol=1e-8, atol=0)


# ---------------------------------------------------------------------------------------
# The suite's simply supported square plate (``ancf.scenes.plate_square``) at 16 x 16
# ---------------------------------------------------------------------------------------

RTOL = ce.PLATE_TOL
REMEDIES = ("plane_stress", "split")   # the 3443's Poisson-locking remedies (``ancf3443``)
#: every (element, Poisson law) of the square plate held to Navier at 16 x 16
PLATES = {("3443", "3d"), ("3833", "3d"), ("3423", "3d"), *(("3443", r) for r in REMEDIES)}
#: those solved here: the others, ``ce.PLATE_CASES`` (the plain 3443, its plane-stress
#: remedy, the ANS/EAS 3423, the 3833), are the chapter's rows, solved once and held to Navier there
#: (``tests/reports/test_chrono_elements_chapter.py``: the 3833's w and six frequencies
#: within 1 %, the plain 3443's w low and frequencies high by more than 1 % (Poisson
#: locking: w -18.7 %, f +10.9..12.2 %, see test_3443_miss_is_poisson_locking), the
#: plane-stress 3443's w within 1 % and f4-f6 missing by less than 2 %)
HERE = sorted(PLATES - set(ce.PLATE_CASES))


COARSE = ("3443 with either Poisson remedy at 16 x 16: f +0.23, +0.71, +0.71, +1.18, +1.49, "
          "+1.49 % (w -0.44 %). Modes 4-6 miss by transverse shear locking of the 4-node shell, "
          "not Poisson locking (the plain 3443 at nu = 0 has +1.62, +1.72 % there; G13, G23 x "
          "100 lift f to +20..+72 %: ancf.checks.chrono_locking); with the remedy 24 x 24 "
          "gives <= 0.43 %, 32 x 32 <= 0.13 % (sparse shift-invert)")


def test_every_plate_case_is_solved_once():
    """The chapter's plate rows and this file's cases together cover every case, once."""
    assert set(ce.PLATE_CASES) <= PLATES and not set(ce.PLATE_CASES) & set(HERE)
    assert HERE == [("3443", "split")]


@pytest.mark.slow
@pytest.mark.parametrize("element, poisson", HERE)
def test_square_plate_navier(element, poisson):
    """Newton's centre deflection within 1 % of Navier's."""
    plate, fixed = ce.square_plate(element, poisson=poisson)
    sol = cs.solve_static(plate, cs.pressure(plate, ce.plate_parameters()["p"]), fixed)
    w, w_ref = ce.centre_deflection(plate, sol.e), ce.navier_w()
    assert abs(w / w_ref - 1) < RTOL, (w, w_ref)


@pytest.mark.slow
@pytest.mark.parametrize("element, poisson", HERE)
@pytest.mark.xfail(strict=True, reason=COARSE)
def test_square_plate_frequencies(element, poisson):
    """The first six frequencies within 1 % of Navier's (xfail: with a remedy modes 4-6
    are 1.2-1.5 % high at 16 x 16, see COARSE)."""
    plate, fixed = ce.square_plate(element, poisson=poisson)
    f = cs.modes(plate, fixed, 6)
    np.testing.assert_array_less(np.abs(f / ce.navier_f() - 1), RTOL)


def test_3443_miss_is_poisson_locking():
    """The 3443's linear centre deflection: at nu = 0 within 1 % of Navier, at the scene's
    nu short of it by the thickness-locking factor (1 - nu)^2/(1 - 2 nu) within 1 %."""
    for nu in (0.0, ce.plate_parameters()["nu"]):
        locking = ce.locking_factor(nu)
        assert abs(linear_deflection(nu) * locking / ce.navier_w(nu) - 1) < RTOL


def linear_deflection(nu: float, poisson: str = "3d") -> float:
    """The centre w (m) of the linear solve K(e0) u = F_p on the 3443 square plate."""
    plate, fixed = ce.square_plate("3443", nu=nu, poisson=poisson)
    f = plate.free(fixed)
    K = cs.reference_stiffness(plate)[f][:, f].tocsc()
    e = plate.reference()
    e[f] += spla.spsolve(K, cs.pressure(plate, ce.plate_parameters()["p"])[f])
    return ce.centre_deflection(plate, e)


def test_3443_poisson_remedy_lifts_locking():
    """The option matters: either remedy (``Plate.poisson``) softens the linear centre
    deflection by the locking factor (1 - nu)^2/(1 - 2 nu) within 1 %, to within 1 % of
    Navier; the two remedies agree (they differ only in the membrane's thickness strain)."""
    nu, w_ref = ce.plate_parameters()["nu"], ce.navier_w()
    locked = linear_deflection(nu)
    locking = ce.locking_factor(nu)
    w = {r: linear_deflection(nu, r) for r in REMEDIES}
    for r in REMEDIES:
        assert abs(w[r] / (locked * locking) - 1) < RTOL
        assert abs(w[r] / w_ref - 1) < RTOL
    assert abs(w["split"] / w["plane_stress"] - 1) < 1e-9


def test_3833_refuses_poisson_remedy():
    with pytest.raises(ValueError, match="poisson for the 3833"):
        cs.Plate("3833", **SMALL, poisson="plane_stress")
