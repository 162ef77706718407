"""The physical-sense checks of ancf.scenes.sense (issue 22 item 1): each with inputs that
fire it and inputs that do not; the numbers of the issue's cases where they are cheap."""
import math

import numpy as np
import pytest

from ancf.scenes import sense


def test_membrane_force_is_the_uniaxial_green_law():
    k, lam = 200.0, 1.2
    assert sense.membrane_force(k, lam) == pytest.approx(k * lam * (lam**2 - 1) / 2, rel=1e-15)
    assert sense.membrane_force(k, 1.0) == 0.0
    assert sense.membrane_force(k, 0.99) < 0  # a belt longer than its path


def test_capstan_torque_against_the_ratio_exp_mu_theta():
    T0, mu, wrap, r = 50.0, 0.6, math.pi, 0.05
    T_s = 2 * T0 / (1 + math.exp(mu * wrap))  # T_t + T_s = 2 T0, T_t / T_s = e^(mu theta)
    T_t = T_s * math.exp(mu * wrap)
    assert sense.capstan_torque(T0, mu, wrap, r) == pytest.approx((T_t - T_s) * r, rel=1e-14)
    assert sense.capstan_torque(-1.0, mu, wrap, r) == 0.0


def test_capstan_fires_above_the_bound_only():
    assert sense.capstan(2.0, 3.7, 50.0, 0.6, math.pi) == []
    [line] = sense.capstan(10.0, 3.7, 50.0, 0.6, math.pi)
    assert "above what friction can transmit" in line and "3.7 N m" in line


def test_reversed_driven():
    assert sense.reversed_driven(0.975, 0.97) == []
    assert sense.reversed_driven(0.975, -0.005) == []  # within 1 % of the driver's rim
    assert sense.reversed_driven(0.975, -13.1)  # belt2d Ta_max=45
    assert sense.reversed_driven(0.0, -0.0102)  # omega_final=0, Ta_max=5: driver at rest
    assert sense.reversed_driven(0.0, -1e-12) == []


def test_gross_slip_beyond_the_creep():
    assert sense.gross_slip(0.099, 73.93, 32.51, 200.0) == []  # belt3d Model 2 (creep 0.151)
    assert sense.gross_slip(0.0008, 30.6, 30.7, 1e4) == []  # belt2d default
    assert sense.gross_slip(0.29, 43.6, 17.3, 1e4)  # nu_s = 1e3 in the extremes study
    assert sense.gross_slip(1.0, 2.8e-10, 2.8e-10, 1e-7)  # E = 1e-3: total slip
    assert sense.gross_slip(float("nan"), 1.0, 1.0, 1.0) == []


def test_compression():
    assert sense.compression({"tight": 30.6, "slack": 0.0}) == []
    [line] = sense.compression({"tight": 2.36, "slack": -0.414})  # belt_length = 1.3
    assert "slack span is in compression" in line


def test_pretension():
    assert sense.pretension(28.2, 0.098) == []  # belt2d default
    assert "no pre-tension" in sense.pretension(-0.5, 0.098)[0]
    assert "lifts off" in sense.pretension(2.8e-10, 0.098)[0]  # E = 1e-3


def test_steady_window():
    assert sense.steady_window(1.0, 0.1, {"driver ramp": 0.6}) == []
    assert sense.steady_window(1.2, 0.1, {"driver ramp": 1.0, "torque ramp": 1.0}) == []
    [line] = sense.steady_window(0.1, 0.1, {"driver ramp": 0.6})
    assert "[0, 0.1] s starts before the driver ramp ends at 0.6 s" in line


def test_drift():
    t = np.linspace(0.9, 1.0, 21)
    wiggle = 0.05 * np.sin(2 * np.pi * t / 0.02)
    assert sense.drift(t, 12.0 + wiggle, 0.1) == []  # a steady speed with span vibration
    assert sense.drift(t, 0.005 * (t / t[0]) ** 8, 0.1)  # inertia = 1000: still spinning up
    assert sense.drift(t, np.zeros_like(t), 0.1) == []  # at rest
    assert sense.drift(t[:2], t[:2], 0.1) == []  # too few samples to fit a trend


def test_thin_plate():
    assert sense.thin_plate(2.15e-4, 0.01) == []  # plate-square default: h/47
    assert sense.thin_plate(2.15e8, 1e-6)  # h = 1e-6
    assert sense.thin_plate(-0.004, 0.01)  # either sign
    assert sense.thin_plate(float("inf"), 0.01) == []  # the non-finite check's business


def test_near_singular_plate():
    assert sense.near_singular(0.01, 0.125) is None
    assert sense.near_singular(1e-7, 0.125) is None  # 0.4 %: the solve keeps its digits
    assert "lost in round-off" in sense.near_singular(1e-9, 0.125)
    assert sense.bending_roundoff(1e-8, 0.125) == pytest.approx(
        np.finfo(float).eps * 12 * (0.125 / 1e-8) ** 2)


def test_stretch():
    assert sense.stretch([0.25, 0.26], [0.25, 0.25]) == []
    [line] = sense.stretch([0.25, 2.48], [0.25, 0.25])  # beam3d F = -1e12: 9.92
    assert line.startswith("element 2 of 2 changes its length by a factor 9.92")
    assert sense.stretch([0.1, 0.25], [0.25, 0.25])  # shortened 2.5 times


def test_circle():
    assert sense.circle(0.20308, 4.3e-5, 0.20308) == []  # the default run
    [line] = sense.circle(0.19363, 0.04323, 0.20308)  # elastic_points = 2
    assert "no circle: 0.213 of the radius" in line


def test_span_samples():
    assert sense.span_samples({"tight": 30.6, "slack": None}) == []
    [line] = sense.span_samples({"tight": 524.0, "slack": float("nan")})  # n_elements = 4
    assert "middle third of the slack span" in line


def test_plate_strip_sides_are_the_stretch_checks_chords():
    """plate-strip's warn measures every element side (nx ny along x, then nx ny along
    y): the reference gives the mesh's sides; the grid stretched 3x along x flags an x side."""
    import numpy as np
    from ancf.models.plate_mesh import PlateMesh
    from ancf.scenes import plate_strip
    m = PlateMesh(2.0, 0.1, 4, 2)
    q0 = m.reference()
    np.testing.assert_allclose(plate_strip.edges(m, q0), [0.5] * 8 + [0.05] * 8)
    q = q0.reshape(m.n_nodes, 3, 3).copy()
    q[:, 0, 0] *= 3.0
    [line] = sense.stretch(plate_strip.edges(m, q.ravel()), plate_strip.edges(m, q0),
                           "element side", "a plate")
    assert line.startswith("element side 1 of 16 changes its length by a factor 3")
    assert line.endswith("not of a plate")


def test_thick_plate_at_its_bound():
    """plate-square's thick-plate check: Mindlin's shear share of a square plate (side a,
    thickness h) is 2 pi^2 (h/a)^2 / (6 kappa (1 - nu)); a step of 1e-3 in h either side
    of the h it puts on SHEAR_SHARE gives no line / one line naming h/a."""
    import math
    from ancf.scenes.analytic.shared import PLATE_KAPPA, SHEAR_SHARE, kirchhoff_shear_share
    a, nu = 2.0, 0.3
    h = a * math.sqrt(SHEAR_SHARE * 6 * PLATE_KAPPA * (1 - nu) / (2 * math.pi ** 2))
    for step, lines in ((0.999, 0), (1.001, 1)):
        share = kirchhoff_shear_share(a, a, step * h, nu)
        out = sense.thick_plate(share, step * h, a, SHEAR_SHARE)
        assert len(out) == lines
    assert out[0].startswith(f"a thick plate (h/a = {1.001 * h / a:.3g})")
