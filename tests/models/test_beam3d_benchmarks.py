"""The 3D beam benchmarks (issue 24, item 4): the tip moment on slope coordinates
(``ancf.core.forces.SectionMoment``) against finite differences of its work and the
small-deflection closed forms; the Princeton beam and Nachbagauer et al.'s 3D general
bending against their published values (one test per acceptance check of
:mod:`ancf.checks.beam3d_benchmarks`, the table of reports/beam3d_benchmarks.md); the
torsion constant; the published references' domain."""
import math

import numpy as np
import pytest

from ancf.checks import beam3d_benchmarks as bb
from ancf.common.params import InputError
from ancf.core.forces import EndMoment, SectionMoment
from ancf.models.beam3d import torsion_constant_rectangle
from ancf.scenes import SCENES
from ancf.scenes import beam3d_published as pub

M = np.array([0.7, -1.3, 2.1])
WEIGHTS = (0.3, 1.7)


def _rotation(axis, angle):
    """Rodrigues' rotation matrix."""
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def _check(prefix: str):
    (c,) = [c for c in bb.checks() if c.name.startswith(prefix)]
    return c


def _assert(prefix):
    c = _check(prefix)
    assert c.passed, (c.name, c.value, c.reference, c.difference, c.tolerance)


# ------------------------------------------------------------------ the moment term
def test_section_moment_jacobian_matches_differences():
    """Central differences of Q (h = 1e-6, error ~h^2 relative) at skewed, stretched
    slopes; tolerance 1e-8 of the largest entry (seen 3e-10)."""
    term = SectionMoment(6, range(6), M, WEIGHTS)
    q = np.array([0.1, 1.05, 0.2, -0.05, 0.1, 0.97])
    J = term.jacobians(q, None, 0.0)[0].toarray()
    fd = np.zeros_like(J)
    for j in range(6):
        dq = np.zeros(6)
        dq[j] = 1e-6
        fd[:, j] = (term.value(q + dq, None, 0.0) - term.value(q - dq, None, 0.0)) / 2e-6
    np.testing.assert_allclose(J, fd, rtol=0, atol=1e-8 * np.abs(J).max())


def test_section_moment_does_the_work_M_dot_dtheta_in_any_rigid_rotation():
    """Slopes of unequal length, not orthogonal, turned by a finite rotation: the work of
    Q along a small extra rotation about each axis (central differences, 1e-6 rad) is
    M . axis; tolerance 1e-9 relative (seen 1e-11)."""
    term = SectionMoment(6, range(6), M, WEIGHTS)
    R0 = _rotation([0.3, -0.2, 0.5], 0.7)
    slopes = (R0 @ [0.0, 1.1, 0.0], R0 @ [0.1, 0.0, 0.9])
    q = np.concatenate(slopes)
    for axis in np.eye(3):
        turn = [np.concatenate([_rotation(axis, s * 1e-6) @ r for r in slopes]) for s in (1, -1)]
        work = term.value(q, None, 0.0) @ (turn[0] - turn[1]) / 2e-6
        assert work == pytest.approx(M @ axis, rel=1e-9)


def test_section_moment_in_the_plane_is_the_gradient_of_M_theta():
    """r_z = e_z, M = M e_z: Q on r_y is the gradient of the work M atan2(-r_y,x, r_y,y)
    (central differences, tolerance 1e-8) and equals the planar EndMoment on r_y; no
    force on r_z."""
    Mz, ry = 2.5, np.array([-0.4, 1.2, 0.0])
    term = SectionMoment(6, range(6), [0.0, 0.0, Mz], WEIGHTS)
    q = np.concatenate([ry, [0.0, 0.0, 1.0]])
    Q = term.value(q, None, 0.0)

    def work(r):
        return Mz * math.atan2(-r[0], r[1])
    grad = [(work(ry + d) - work(ry - d)) / 2e-6 for d in 1e-6 * np.eye(3)]
    np.testing.assert_allclose(Q[:3], grad, rtol=0, atol=1e-8)
    planar = EndMoment(2, [0, 1], Mz).value(np.array([ry[1], -ry[0]]), None, 0.0)
    np.testing.assert_allclose(Q[:2], [-planar[1], planar[0]], rtol=1e-14)
    np.testing.assert_allclose(Q[3:], 0.0, atol=1e-15)


def test_section_moment_in_the_reference_is_the_linear_end_traction():
    """At r_y = e_y, r_z = e_z: Q is the work of the linear end traction of M on
    y r_y + z r_z, i.e. M_x w_y/I_p e_z - M_z e_x on r_y and -M_x w_z/I_p e_y + M_y e_x on
    r_z (w_y = int y^2, w_z = int z^2, I_p = w_y + w_z)."""
    wy, wz = WEIGHTS
    Q = SectionMoment(6, range(6), M, WEIGHTS).value(np.r_[0, 1, 0, 0, 0, 1.0], None, 0.0)
    Mx, My, Mz = M
    expected = [-Mz, 0.0, Mx * wy / (wy + wz), My, -Mx * wz / (wy + wz), 0.0]
    np.testing.assert_allclose(Q, expected, rtol=1e-14, atol=1e-15)


@pytest.mark.slow
def test_tip_moment_small_deflection_is_the_closed_form():
    _assert("Tip moment, small rotation")


# ------------------------------------------------------------------ torsion constant
@pytest.mark.parametrize("ratio,k1", [(1.0, 0.141), (2.0, 0.229), (4.0, 0.281), (10.0, 0.312)])
def test_torsion_constant_of_the_rectangle_is_the_tabulated_one(ratio, k1):
    """J = k1 c d^3 (Timoshenko and Goodier, Theory of Elasticity, the table of the
    rectangle's torsion, printed to 3 digits): tolerance half a unit of the last digit."""
    assert torsion_constant_rectangle(ratio, 1.0) / ratio == pytest.approx(k1, abs=5e-4)
    assert torsion_constant_rectangle(1.0, ratio) == torsion_constant_rectangle(ratio, 1.0)


# ------------------------------------------------------------------ Princeton beam
@pytest.mark.slow
def test_princeton_linear3d_and_belt3d_against_ansys():
    for element in ("linear3d", "belt3d"):
        for c in "yz":
            _assert(f"Princeton beam, {element} ({bb.PRINCETON_N} el.): u_{c}")


def test_princeton_exact_integration_locks():
    _assert("Princeton beam, linear3d exact integration locks")


def test_princeton_default_ks_is_too_stiff_in_torsion():
    _assert("Princeton beam, linear3d k_s = 5/6")
    assert bb.princeton_torsion()["stiffness_ratio_5_6"] > 3.9


def test_princeton_report_selective_has_no_torsional_stiffness():
    """Shear at 1 x 1 section point drops the torsion: every run stops on a singular
    tangent, reported as non-convergence."""
    rows = bb.princeton("linear3d, report-selective")
    assert not any(r["converged"] for r in rows)
    assert all("singular" in r["message"] for r in rows)


def test_princeton_defaults_are_the_published_problem():
    p = SCENES["princeton-beam"].resolve({})
    assert {k: p[k] for k in pub.PRINCETON} == pub.PRINCETON
    assert p["F"] == -pub.PRINCETON_LOADS["F2"]
    assert p["ks"] == pytest.approx(torsion_constant_rectangle(p["h"], p["b"])
                                    / (p["b"] * p["h"] * (p["h"] ** 2 + p["b"] ** 2) / 12))


# ------------------------------------------------------------------ 3D general bending
def test_general_bending_u_z_against_table_4():
    _assert("3D general bending, linear3d (32 el.): u_z")


def test_general_bending_u_x_u_y_against_table_4():
    _assert("3D general bending, linear3d (32 el.): u_x, u_y")


def test_general_bending_difference_is_the_continuum_terms():
    _assert("3D general bending: ours − ANSYS")
    belt = bb.continuum_explained("belt3d", 32)
    assert max(abs(belt["ux mismatch"]), abs(belt["uy mismatch"])) <= bb.CONTINUUM_TOL


def test_general_bending_defaults_are_the_published_problem():
    p = SCENES["beam3d-bending"].resolve({})
    assert {k: p[k] for k in pub.GENERAL_BENDING} == pub.GENERAL_BENDING
    assert p["ks"] == pub.GENERAL_BENDING_KS_TORSION and p["F"] == 0.0


# ------------------------------------------------------------------ references, bad input
def test_published_references_exist_for_the_published_problems_only():
    from ancf.study.recommend import check_reference
    from ancf.study.references import spec
    for scene, good, bad in (("princeton-beam", {"load_angle_deg": 45.0, "F": -13.345},
                              {"load_angle_deg": 40.0}),
                             ("beam3d-bending", {}, {"Mx": 1e5})):
        ref = spec(scene).reference()
        p = SCENES[scene].resolve(good)
        assert ref.kind == "published" and np.isfinite(list(ref.values(p).values())).all()
        with pytest.raises(InputError, match="published"):
            check_reference(scene, ref, SCENES[scene].resolve(bad))
    ref = spec("beam3d-cantilever").reference()
    with pytest.raises(InputError, match="Mx = My = Mz = 0"):
        check_reference("beam3d-cantilever", ref, SCENES["beam3d-cantilever"].resolve({"My": 1.0}))


def test_princeton_reference_error_is_zero_at_the_published_values():
    """The published reference scored against itself (signs of our load) is 0, and a
    1 % longer tip vector scores 0.01."""
    from ancf.study.references import spec
    ref = spec("princeton-beam").reference()
    p = SCENES["princeton-beam"].resolve({"load_angle_deg": 30.0})
    v = ref.values(p)
    assert v["tip_y"] < 0 and v["tip_z"] < 0
    assert ref.error(v, v, p) == 0.0
    assert ref.error({k: 1.01 * x for k, x in v.items()}, v, p) == pytest.approx(0.01)


@pytest.mark.parametrize("name,value", [("Mx", "nan"), ("My", "inf"), ("Mz", "x")])
def test_bad_moment_is_one_line_naming_the_field(name, value):
    with pytest.raises(InputError, match=f"^{name}"):
        SCENES["beam3d-bending"].resolve({name: value})
