"""The 3D belt drive (issue 14): model, pulley laws, pre-tension and short runs; the long
Model 1 / Model 2 runs are in reports/belt3d.md (ancf.checks.belt3d)."""
import math

import numpy as np
import pytest

from ancf.belts.drive3d import Belt3DDrive, ring_dofmap
from ancf.belts.post3d import line_sample, membrane_force, span_means
from ancf.belts.contact3d import contact_state3d
from ancf.belts.pulleys import driver_shift, opposing_torque
from ancf.scenes import belt3d as b3
from ancf.belts.pretension import settle


def test_ring_closes_on_node_zero_without_constraints():
    dm = ring_dofmap(5)
    assert dm.shape == (5, 36)
    assert np.array_equal(dm[-1, 9:18], dm[0, 0:9]) and np.array_equal(dm[-1, 18:27], dm[0, 27:36])
    assert np.unique(dm).size == 2 * 5 * 9


def test_stretch_solves_the_uniaxial_membrane_law():
    k = 200.0
    lam = b3.stretch_for(50.0, k)
    assert k * lam * (lam**2 - 1) / 2 == pytest.approx(50.0, rel=1e-13)
    rx = np.array([lam, 0.0, 0.0])
    # with the width free to contract (E_yy = -nu E_xx) the membrane force is the same
    nu = 0.3
    ry = np.array([0.0, math.sqrt(1 - nu * (lam**2 - 1)), 0.0])
    assert membrane_force(rx, ry, k / (0.003 * 0.04), nu, 0.003, 0.04) == pytest.approx(50.0, rel=1e-12)


def test_eq_4_46_and_eq_4_47_at_their_breakpoints():
    u, du = driver_shift(np.array([0.0, 0.025, 0.05, 0.3]), 0.0025, 0.05)
    assert np.allclose(u, [0.0, 0.00125, 0.0025, 0.0025]) and np.allclose(du, [0.05, 0.05, 0.0, 0.0])
    Ta = opposing_torque(np.array([0.05, 0.6, 1.0, 1.0 + 1e-9, 2.0]), 2.0, 0.05, 1.0)
    assert Ta[0] == 0.0 and Ta[1] == pytest.approx(1 - math.cos(0.6 * math.pi))
    assert Ta[2] == pytest.approx(2.0) and Ta[3] == 2.0 and Ta[4] == 2.0


@pytest.fixture(scope="module")
def model2():
    p = b3.SCENE.resolve({})
    drive = Belt3DDrive(b3.spec(p))
    x0, out = settle(drive)
    return p, drive, x0, out


@pytest.mark.slow
def test_model2_settles_with_the_initial_tension_in_both_spans(model2):
    p, drive, x0, out = model2
    assert out.converged
    means = span_means(drive, line_sample(drive, x0, np.zeros_like(x0)))
    for side in ("tight", "slack"):
        assert means[side]["tension_membrane_N"] == pytest.approx(p["T_i"], rel=0.01)
        assert means[side]["speed"] == 0.0


def test_settled_belt_penetrates_by_the_wrap_pressure_over_k_p(model2):
    p, drive, x0, _ = model2
    E = drive.element_coords(drive.belt(x0))
    _, d, _, _, _, _ = contact_state3d(E, np.zeros_like(E), drive.S0, drive.centres, drive.axes,
                                       drive.radii, np.zeros(2), np.zeros((2, 3)), drive.prm)
    wrapped = (d > 0).all(axis=1).any(axis=1)  # elements in contact at all their points
    expected = b3.penetration(p, b3.stretch_for(p["T_i"], p["E"] * p["h"] * p["width"]))
    assert wrapped.sum() >= 6
    assert d[wrapped].max(axis=2).mean() == pytest.approx(expected, rel=0.05)


@pytest.mark.slow
def test_short_model2_run_converges_and_the_driven_pulley_follows():
    p, res = b3.SCENE.execute({"t_end": 0.08, "output_dt": 0.01})
    assert res.converged, res.message
    r = res.results
    assert r["omega_driver"][-1] == pytest.approx(500 * 0.03 / 0.95)
    assert 0.8 * r["omega_driver"][-1] < r["omega_driven"][-1] < 1.2 * r["omega_driver"][-1]
    assert set(r["tensions"]) == {"green", "true", "almansi", "membrane"}
