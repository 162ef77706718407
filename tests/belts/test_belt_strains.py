"""Belt strain measures, tension and speed (thesis Eqs 4.5-4.13) on configurations
with known answers: a uniform stretch lambda of a straight belt (every measure in
closed form), a rigid rotation (all strains zero, det F = 1), a rigid translation
(speed = the velocity along the tangent) and the 2D belt drive's span tension.

Tolerances: the configurations are exact in the cubic shape functions, so the
measures agree to round-off (1e-12 relative)."""
import math

import numpy as np
import pytest

from ancf.belts.strains import planar_belt
from ancf.core.mesh import BeamMesh

SLOTS = ("r", "r_x", "r_y")
K = 1e4  # N


def _belt(n=3, L=1.2):
    m = BeamMesh(L, n, SLOTS)
    q0 = m.reference()
    return m, q0


def _elements(m, q):
    return q[m.dofmap].reshape(m.n_elements, 6, 2)


@pytest.mark.parametrize("lam", [0.9, 1.0, 1.05, 1.5])
def test_uniform_stretch_gives_each_measure_in_closed_form(lam):
    m, q0 = _belt()
    q = q0.copy()
    for node in range(m.n_nodes):
        q[m.dof(node, "r", 0)] *= lam
        q[m.dof(node, "r_x", 0)] *= lam
    out = planar_belt(m.lengths, _elements(m, q), _elements(m, q0), np.zeros((m.n_elements, 6, 2)), K)
    want = {"green": lam - 1, "true": 1 - 1 / lam, "almansi": -1 + math.sqrt(2 - 1 / lam**2)}
    for name, value in want.items():
        np.testing.assert_allclose(out[f"eps_{name}"], value, rtol=0, atol=1e-12)
        np.testing.assert_allclose(out[f"tension_{name}_N"], K * value, rtol=0, atol=1e-8)
    np.testing.assert_allclose(out["det_F"], lam, rtol=1e-12)
    assert out["s"][-1, -1] == pytest.approx(m.L - m.lengths[-1] * 0.5 / 20, rel=1e-12)


def test_the_three_measures_agree_to_first_order():
    """eps_green, eps_true and eps_almansi differ by O(eps^2): at lambda = 1 + 1e-4 by ~1e-8."""
    m, q0 = _belt()
    q = q0.copy()
    for node in range(m.n_nodes):
        q[m.dof(node, "r", 0)] *= 1 + 1e-4
        q[m.dof(node, "r_x", 0)] *= 1 + 1e-4
    out = planar_belt(m.lengths, _elements(m, q), _elements(m, q0), np.zeros((m.n_elements, 6, 2)), K)
    spread = np.ptp(np.stack([out[f"eps_{n}"] for n in ("green", "true", "almansi")]), axis=0)
    assert spread.max() < 2e-8 and spread.max() > 0


def test_rigid_rotation_is_strain_free_and_translation_speed_is_tangential():
    m, q0 = _belt()
    c, s = math.cos(2.0), math.sin(2.0)
    R = np.array([[c, -s], [s, c]])
    q = (q0.reshape(-1, 2) @ R.T).ravel()
    v = np.tile([3.0, -1.0], q.size // 2)
    for node in range(m.n_nodes):  # slopes do not move in a translation
        for slot in ("r_x", "r_y"):
            v[[m.dof(node, slot, 0), m.dof(node, slot, 1)]] = 0.0
    out = planar_belt(m.lengths, _elements(m, q), _elements(m, q0), _elements(m, v), K)
    for name in ("green", "true", "almansi"):
        assert np.abs(out[f"eps_{name}"]).max() < 1e-12
    np.testing.assert_allclose(out["det_F"], 1.0, rtol=1e-12)
    np.testing.assert_allclose(out["speed"], 3.0 * c - 1.0 * s, rtol=1e-12)  # (3, -1) . (c, s)


def test_green_tension_of_the_belt_drive_is_the_element_axial_force_over_the_stretch():
    """The element's axial force is E A alpha1 (lambda^2 - 1)/2 (Eq. 3.17), the Green
    measure's tension E A (lambda - 1); their ratio is (lambda + 1)/2 exactly."""
    from ancf.scenes import SCENES
    out, res = SCENES["belt2d"].execute({"t_end": 0.01})
    drive, run = res.extra["drive"], res.extra["result"]
    q, qd = drive.belt(run.q[-1]), drive.belt(run.v[-1])
    dm, s = drive.mesh.dofmap, drive.spec
    E, V = q[dm].reshape(-1, 6, 2), qd[dm].reshape(-1, 6, 2)
    l = drive.mesh.lengths[0]  # the straight reference element (thesis 3.1)
    ref = np.tile([[0, 0], [1, 0], [0, 1], [l, 0], [1, 0], [0, 1]], (s.n_elements, 1, 1)).astype(float)
    k = s.E * s.b * s.h * s.alpha1
    m = planar_belt(drive.mesh.lengths, E, ref, V, k, n_points=5)
    xi = (np.arange(5) + 0.5) / 5
    N = drive.element.axial_force(q[dm], xi)
    np.testing.assert_allclose(N / m["tension_green_N"], (m["stretch"] + 1) / 2, rtol=1e-9)
