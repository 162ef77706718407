"""Issue 34 ("modes"): the belt march's free spans (ancf/checks/span_spectrum.py) vibrate at
the moving beam's frequencies (analytic/moving_beam.py) as the generalised-alpha march maps
them; each check fails on a perturbed reference (10 % wrong tension, no integrator map, the
Green force N taken for the true tension)."""
import math

import numpy as np
import pytest

from ancf.checks import span_spectrum as ss


def test_alpha_frequency_is_the_trapezoidal_rule_at_rho_inf_1():
    """rho_inf = 1 is the trapezoidal rule: omega_h h = 2 atan(omega h / 2) (closed form)."""
    f, h = 300.0, 2.5e-4
    exact = 2 * math.atan(math.pi * f * h) / (2 * math.pi * h)
    assert ss.alpha_frequency(f, h, 1.0) == pytest.approx(exact, rel=1e-12)
    assert abs(ss.alpha_frequency(f, h, 0.5) / exact - 1) > 1e-3  # rho_inf matters


def test_peak_recovers_an_off_bin_sinusoid():
    """A decaying 177.3 Hz sine sampled as the window (1 ms, 0.4 s) with a 230.8 Hz one."""
    t = np.arange(401) * 1e-3
    y = np.exp(-t) * np.sin(2 * np.pi * 177.3 * t) + 0.5 * np.sin(2 * np.pi * 230.8 * t)
    f, amp = ss.spectrum(t, y)
    got = ss.peak(f, amp, 160.0, 195.0)
    assert abs(got - 177.3) < 0.02 * (f[1] - f[0]) * ss.PAD  # 2 % of a bin
    f, amp = ss.spectrum(t, y + np.sin(2 * np.pi * 179.1 * t))  # a 1 % higher mode
    assert abs(ss.peak(f, amp, 160.0, 195.0) - 177.3) > 1.0


@pytest.fixture(scope="module")
def spans():
    return ss.spans()["spans"]


def _errors(row, T_scale=1.0, stretch=True, mapped=True):
    """|peak / f - 1| of both modes against the pinned beam recomputed from the run's means
    (tension scaled, the stretch of eq. (1) kept or not, the march's map applied or not)."""
    lam, N = row["stretch"] if stretch else 1.0, row["N"] * T_scale
    ref = ss.references(N * lam, row["rho_A0"] / lam, row["v"], row["L"], row["EI"], ss.DT,
                        row["rho_inf"])
    return np.abs(row["peaks"] / ref["pinned_h" if mapped else "pinned"] - 1)


@pytest.mark.slow
def test_span_peaks_within_tolerance_of_the_pinned_moving_beam(spans):
    """Both spans, modes 1 and 2 (about 6 s CPU, 0.4 s window): within TOL of f_h."""
    for row in spans.values():
        assert np.max(np.abs(row["error"]["pinned_h"])) < ss.TOL
        assert row["resolution"] == pytest.approx(2.5)


@pytest.mark.slow
@pytest.mark.parametrize("wrong", ["tension", "integrator", "stretch"])
def test_perturbed_reference_fails(spans, wrong):
    kw = {"tension": {"T_scale": 0.9}, "integrator": {"mapped": False},
          "stretch": {"stretch": False}}[wrong]
    assert all(np.max(_errors(row)) < ss.TOL for row in spans.values())
    assert any(np.max(_errors(row, **kw)) > ss.TOL for row in spans.values())
