"""The pure logic of the ALE race (benchmarks/peers_ale.py, benchmarks/peers_ale_exudyn.py):
window means, relative differences, the medians of the CPU samples and the per-segment
contact coefficients, on synthetic data against closed forms."""
import math

import numpy as np
import pytest

from benchmarks import peers_ale as pa
from benchmarks import peers_ale_exudyn as pae

TOL = 1e-12


def _ramp(a: float, b: float, dt: float = 1e-3):
    """Samples of y = a + b t every dt over 0-2.45 s (s, -)."""
    t = np.arange(0.0, 2.45 + dt / 2, dt)
    return t, a + b * t


@pytest.mark.parametrize("b", [0.0, 3.0, -7.5])
def test_window_mean_of_a_ramp_is_its_midpoint_value(b):
    """Uniform samples of a line over [2.0, 2.45] s average to its value at 2.225 s."""
    t, y = _ramp(11.3, b)
    assert abs(pae.window_mean(t, y) - (11.3 + b * 2.225)) < TOL * 100


def test_window_mean_sees_a_change_inside_the_window_only():
    """A step at 1.9 s (before the window) leaves the mean; one at 2.2 s moves it by the
    fraction of the window's samples after the step (251 of 451 at 1 ms)."""
    t, y = _ramp(5.0, 0.0)
    assert abs(pae.window_mean(t, y + 2.0 * (t >= 1.9)) - 7.0) < TOL
    moved = pae.window_mean(t, y + 2.0 * (t >= 2.2 - 1e-9)) - 5.0
    assert abs(moved - 2.0 * 251 / 451) < 1e-9
    assert abs(moved - 2.0) > 0.5


def test_window_mean_of_columns_and_an_empty_window():
    t, y = _ramp(1.0, 2.0)
    both = pae.window_mean(t, np.column_stack([y, -y]))
    assert np.allclose(both, [1.0 + 2.0 * 2.225, -(1.0 + 2.0 * 2.225)], atol=1e-10)
    with pytest.raises(ValueError, match="window"):
        pae.window_mean(t[t < 1.5], y[t < 1.5])


def test_relative_difference_and_agreement():
    """(ours - Exudyn) / |Exudyn| against the quotient minus one; missing values give None."""
    assert abs(pa.relative(664.2, 665.7) - (664.2 / 665.7 - 1)) < TOL
    assert abs(pa.relative(-2.0, -4.0) - 0.5) < TOL
    assert pa.relative(None, 1.0) is None and pa.relative(1.0, 0.0) is None
    a = pa.agreement({"tension_tight_N": 101.0}, {"tension_tight_N": 100.0})
    assert abs(a["tension_tight_N"]["relative"] - 0.01) < TOL
    assert a["omega_driven_mean"]["relative"] is None


def test_summary_takes_medians_and_keeps_samples():
    runs = [{"cpu_s": 3.0, "x": 1}, {"cpu_s": 1.0, "x": 2}, {"cpu_s": 2.5, "x": 3}]
    s = pa.summary(runs, ("cpu_s",))
    assert s["cpu_s"] == sorted(r["cpu_s"] for r in runs)[1] and s["x"] == 3
    assert s["cpu_samples_s"] == [3.0, 1.0, 2.5]
    assert pa.summary([{"cpu_s": None}], ("cpu_s",))["cpu_s"] is None


def test_coefficients_are_the_file_per_length_values_times_the_segment():
    """k_p, c_p, nu_s (per m) x l_s = 0.4 pi m / (120 x 2); the segment count divides them."""
    co = pae.coefficients(pae.FILE, 120, 2)
    l_s = 0.4 * math.pi / 240
    assert abs(co["contactStiffness"] - 3.2e8 * l_s) < 1e-9 * 3.2e8 * l_s
    assert abs(co["frictionVelocityPenalty"] - 1e6 * l_s) < 1e-9 * 1e6 * l_s
    assert abs(co["contactDamping"] - 6400.0 * l_s) < 1e-9 * 6400.0 * l_s
    assert co["frictionStiffness"] == 0.0 and co["frictionCoefficient"] == 0.5
    four = pae.coefficients(pae.FILE, 120, 4)
    assert abs(four["contactStiffness"] / co["contactStiffness"] - 0.5) < TOL
