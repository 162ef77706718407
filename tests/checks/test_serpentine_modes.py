"""The serpentine drive's rotational modes (ancf/checks/serpentine_modes.py): the matrix
pencil on synthetic signals, then the march (one cached run) against the discrete
rotational model, plain and with the belt's mass and creep arcs; a 10 % stiffer belt in
either reference puts the measured frequencies outside the tolerance."""
import math

import numpy as np
import pytest

from ancf.checks import serpentine_modes as sm


def _synthetic(f_hz, zeta, h=2e-4, n=1000):
    """Two channels of damped cosines (Hz, damping ratios) sampled every h s."""
    t = np.arange(n) * h
    w = 2 * math.pi * np.asarray(f_hz)
    s = -np.asarray(zeta) * w / np.sqrt(1 - np.asarray(zeta) ** 2) + 1j * w
    Y = np.array([np.real(np.exp(np.outer(t, s)) @ c) for c in ([1.0, 0.5j], [0.3, -1.0])])
    return t, Y - Y.mean(axis=1, keepdims=True), s


def test_pencil_recovers_damped_poles():
    t, Y, s_true = _synthetic([33.0, 150.0], [0.12, 0.04])
    s = np.log(sm.pencil(Y, 5)) / (t[1] - t[0])  # 2 pairs and the mean removed (z = 1)
    s = np.sort_complex(s[s.imag > 1.0])
    assert np.allclose(s, np.sort_complex(s_true), rtol=1e-6)
    # a wrong step gives the wrong poles: the check can fail
    wrong = np.log(sm.pencil(Y, 5)) / (1.01 * (t[1] - t[0]))
    assert not np.allclose(np.sort_complex(wrong[wrong.imag > 1.0]), s, rtol=1e-3)


@pytest.mark.parametrize("order", [1, 10_000, 2.5, True])
def test_pencil_order_out_of_range(order):
    with pytest.raises(ValueError, match="order"):
        sm.pencil(np.ones((2, 300)) + np.arange(300), order)


@pytest.fixture(scope="module")
def result():
    return sm.compare()


def _measured(result):
    return [m for m in result["modes"] if m["label"] in sm.MEASURED]


@pytest.mark.slow
def test_modes_identified(result):
    rows = _measured(result)
    assert [m["label"] for m in rows] == list(sm.MEASURED)
    assert min(m["mac"] for m in rows) > 0.9
    # the pairs are distinct poles, apart by more than the FFT's resolution
    f = sorted(m["f"] for m in rows)
    assert min(np.diff(f)) > result["resolution_hz"]


@pytest.mark.slow
def test_discrete_model_within_tolerance(result):
    assert max(abs(m["error"]) for m in _measured(result)) < sm.TOL


@pytest.mark.slow
def test_belt_mass_and_creep_close_the_gap(result):
    rows = _measured(result)
    assert max(abs(m["error_belt_mass_creep"]) for m in rows) < sm.TOL_BELT
    assert all(abs(m["error_belt_mass_creep"]) < abs(m["error"]) for m in rows)


@pytest.mark.slow
def test_stiffer_belt_fails(result):
    """EA + 10 % raises the plain model's frequencies ~5 %: outside TOL."""
    stiff = sm.discrete(result["inputs"], EA_factor=1.1)
    f_ref = dict(zip(stiff["labels"], stiff["frequencies_hz"]))
    errors = [m["f"] / f_ref[m["label"]] - 1 for m in _measured(result)]
    assert max(abs(e) for e in errors) > sm.TOL
    inp = dict(result["inputs"], EA=1.1 * result["inputs"]["EA"])
    f_belt = sm.corrected(inp)["belt_mass_creep"]
    labels = [m["label"] for m in result["modes"]]
    worst = max(abs(m["f"] / f_belt[labels.index(m["label"])] - 1) for m in _measured(result))
    assert worst > sm.TOL_BELT
