"""One test per acceptance check of :mod:`ancf.checks.elements3d` (the table of
reports/elements3d.md): the thin plate against Navier, Euler-Bernoulli and Reissner,
the 3D beam against the planar scenes, superposition, St-Venant torsion, rigid motion."""
import pytest

from ancf.checks import elements3d as ec


def _check(prefix: str):
    (c,) = [c for c in ec.checks() if c.name.startswith(prefix)]
    return c


def _assert(prefix):
    c = _check(prefix)
    assert c.passed, (c.name, c.value, c.reference, c.difference, c.tolerance)


@pytest.mark.slow
def test_plate_square_within_1_percent_of_navier():
    _assert("Plate square 16")


def test_plate_square_observed_order_two():
    _assert("Plate square: observed order")


def test_plate_strip_linear_is_euler_bernoulli():
    _assert("Plate strip ν = 0 (linear)")


def test_plate_strip_large_deflection_near_reissner():
    _assert("Plate strip large deflection")


def test_beam3d_principal_planes_reproduce_the_planar_scenes():
    _assert("3D beam, principal-plane bending")


def test_beam3d_scene_at_0_and_90_degrees():
    _assert("beam3d-cantilever 0°")
    _assert("beam3d-cantilever 90°")


def test_beam3d_superposition_at_45_degrees():
    _assert("3D beam 45°")


def test_beam3d_torsion_is_ks_G_Ip_and_J_is_the_series():
    _assert("3D beam torsion")
    _assert("Torsion constant of the square")
    t = ec.torsion()
    assert t["ratio"] == pytest.approx(t["J_over_ks_Ip"], rel=1e-8)


def test_rigid_rotation_has_no_strain():
    for prefix in ("Rigid rotation: zero strain energy, 3D beam",
                   "Rigid rotation: zero elastic force, 3D beam",
                   "Rigid rotation: zero strain energy, plate"):
        _assert(prefix)


def test_nu_03_strip_is_stiffer_than_euler_bernoulli_and_converges():
    """nu = 0.3: the clamp restrains the anticlastic curvature; the excess stiffness falls
    with the mesh (the report's table)."""
    err = [r["relative error"] for r in ec.strip_linear(0.3, ((1, 1), (2, 1), (4, 1), (8, 1)))]
    assert all(e < 0 for e in err) and all(abs(b) < abs(a) for a, b in zip(err, err[1:]))
