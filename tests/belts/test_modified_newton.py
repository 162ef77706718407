"""Modified Newton's settings of the compiled generalised-alpha march
(:mod:`ancf.solvers.alpha_march`: ``refresh_ratio``, ``accept``, ``refresh``), as a drive
file's ``run.refresh_ratio``, ``run.newton_accept`` and ``run.refresh`` give them (``once``
factors fewer matrices than ``contraction``): each converged step lies within
the Newton tolerance of the step converged far tighter, from the same state (the THREAD
drive, bristle friction with its state, coarse; ``once`` within the default setting's
bound), and the defaults are the march's.  The
belt damping's cheaper iteration-matrix part (``run.damping_jacobian = "rate"``,
:func:`ancf.elements.dufva2d.damping_forces_rate`) gives the exact kernel's forces and
dQ_d/de', bit for bit.

The bound: with increments contracting by at most the refresh ratio rho (the iteration
matrix is refactored otherwise), the error of an iterate is at most |d| rho / (1 - rho)
after its increment d (``applied``) and |d| / (1 - rho) before it (``evaluated``); the
test takes |d| <= tol (1 + |z|) / beta', so beta' x the acceleration error, the position
error, is within tol (1 + |z|) / (1 - rho).
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.belts.drive_file import load
from ancf.belts.drive_model import build
from ancf.belts.dynamics import BeltOptions, _halved, _March
from ancf.belts.forces import gather
from ancf.belts.pretension import settle
from ancf.elements.dufva2d import damping_forces, damping_forces_rate
from ancf.common.params import InputError
from ancf.common.paths import REPO
from ancf.solvers.alpha_march import (ACCEPT, DONE, NEWTON_FAILED, REFRESH, REFRESH_RATIO,
                                      newton_settings)

THREAD = REPO / "examples" / "thread_benchmark.toml"
STEP, STEPS, TOL = 5e-5, 12, 1e-7
SETTINGS = {"default": {}, "evaluated": {"newton_accept": "evaluated"},
            "ratio 0.9": {"refresh_ratio": 0.9},
            "both": {"refresh_ratio": 0.9, "newton_accept": "evaluated"},
            "ratio 0.2": {"refresh_ratio": 0.2, "newton_accept": "evaluated"},
            "once": {"refresh_ratio": 0.2, "newton_accept": "evaluated", "refresh": "once"}}


def _one_step(m, st, k, z, zstate):
    """Step k -> k + 1 of march m from a copy of st with the friction state z; the state."""
    s = tuple(c.copy() for c in st)
    zstate[0] = z
    dummy = np.zeros((1, s[0].size))
    status, _ = m.run(s, k, k + 1, np.full(m.ts.size, -1, dtype=np.int64), dummy, dummy, 1e9)
    assert status == DONE
    return s[0]


def _bound_ratio(setting: dict) -> float:
    """The contraction ratio the setting's error bound takes: its refresh ratio; with
    refresh once, a matrix kept after the step's refresh while increments merely shrink
    does not guarantee it, so such a step is held to the default setting's bound."""
    if setting.get("refresh") == "once":
        return REFRESH_RATIO
    return setting.get("refresh_ratio", REFRESH_RATIO)


def test_every_setting_reaches_the_tightly_converged_step():
    """The THREAD belt (30 elements) settled on its pulleys, set running along itself at
    0.2 m/s over the resting pulleys (its bristles stick, then slip): 12 steps, each taken
    from the reference's state by every setting."""
    drive = build(load(THREAD, ["belt.n_elements=30"]))
    ts = np.arange(STEPS + 1) * STEP
    ref = _March(drive, BeltOptions(dt=STEP, newton_tol=1e-11, max_iter=40), ts, 1)
    trials = {k: _March(drive, BeltOptions(dt=STEP, newton_tol=TOL, **kw), ts, 1)
              for k, kw in SETTINGS.items()}
    x, pre = settle(drive)
    assert pre.converged
    slopes = drive.belt(x).reshape(-1, 3, 2)[:, 1]
    qd = np.zeros_like(drive.q0).reshape(-1, 3, 2)
    qd[:, 0] = 0.2 * slopes / np.linalg.norm(slopes, axis=1)[:, None]
    v = np.zeros_like(x)
    v[: drive.n] = drive.pattern.restrict(qd.ravel())
    a = ref.initial_acceleration(x, v)
    st, z = (x, v, a, a.copy()), drive.z
    z[:] = 0.0
    worst = {k: 0.0 for k in SETTINGS}
    for k in range(STEPS):
        z0 = z[0].copy()
        got = {name: _one_step(m, st, k, z0, z) for name, m in trials.items()}
        z[0] = z0
        assert ref.run(st, k, k + 1, np.full(ts.size, -1, dtype=np.int64), *[np.zeros((1, x.size))] * 2,
                       1e9)[0] == DONE
        scale = TOL * (1 + np.max(np.abs(st[0][: drive.n])))
        for name, xk in got.items():
            ratio = _bound_ratio(SETTINGS[name])
            worst[name] = max(worst[name], np.max(np.abs(xk - st[0])) / (scale / (1 - ratio)))
    assert max(worst.values()) <= 1.0, worst
    assert worst["evaluated"] > 0  # the settings change the iterates (not one code path)
    factored = {name: int(m.count[2]) for name, m in trials.items()}
    assert factored["once"] < factored["ratio 0.2"], factored  # refresh once: fewer matrices


def test_defaults_are_the_marchs():
    d = load(THREAD)
    assert (d.run["refresh_ratio"], d.run["newton_accept"]) == (REFRESH_RATIO, ACCEPT[0])
    assert (BeltOptions().refresh_ratio, BeltOptions().newton_accept) == (REFRESH_RATIO, ACCEPT[0])
    assert d.run["refresh"] == REFRESH[0] and BeltOptions().refresh == REFRESH[0]
    assert d.run["give_up"] == 0 and BeltOptions().give_up == 0
    assert newton_settings(1e-7).tolist() == [1e-7, REFRESH_RATIO, 0.0, 0.0, 0.0]


@pytest.mark.parametrize("item, message", [
    ("run.refresh_ratio=1.0", r"run.refresh_ratio.*out of range.*\[0.1, 0.95\]"),
    ("run.refresh_ratio=0", r"run.refresh_ratio.*out of range"),
    ("run.newton_accept=last", r"run.newton_accept.*applied, evaluated"),
    ("run.give_up=13", r"run.give_up.*out of range.*\[0, 12\]"),
    ("run.refresh=twice", r"run.refresh.*contraction, once"),
    ("run.damping_jacobian=none", r"run.damping_jacobian.*exact, rate")])
def test_bad_settings_are_one_line(item, message):
    with pytest.raises(InputError, match=message) as exc:
        load(THREAD, [item])
    assert "\n" not in str(exc.value)


def test_the_march_refuses_settings_out_of_range():
    with pytest.raises(ValueError, match=r"refresh_ratio must be in \(0, 1\)"):
        newton_settings(1e-7, 1.0)
    with pytest.raises(ValueError, match="accept must be one of applied, evaluated"):
        newton_settings(1e-7, accept="last")
    with pytest.raises(ValueError, match="refresh must be one of contraction, once"):
        newton_settings(1e-7, refresh="twice")


@pytest.mark.parametrize("bending", ["1e-3", "0"])
def test_the_rate_damping_jacobian_is_the_exact_kernels_rate_part(bending):
    """The rate kernel's forces and dQ_d/de' are the exact kernel's bit for bit (with dEI =
    0 both from the axial strain's own loop, dufva2d._axial_damping, whose sums are the
    general kernel's: tests/belts/test_belt_damping.py)."""
    d = load(THREAD, ["belt.n_elements=12", f"belt.damping_bending={bending}",
                      "run.damping_jacobian=rate"])
    drive = build(d)
    assert drive.kernel().damping_jacobian == 1
    x = drive.state(drive.q0)
    v = 0.3 * np.random.default_rng(7).standard_normal(x.size)
    E, V = np.empty((12, 6, 2)), np.empty((12, 6, 2))
    gather(x, drive.vidx, E, V, v)
    data, damping = drive.element.kernel_data(), drive.strain_damping
    g, K, C = np.zeros((12, 12)), np.zeros((12, 12, 12)), np.zeros((12, 12, 12))
    damping_forces(E, V, data, damping, True, g, K, C)
    g2, C2 = np.zeros_like(g), np.zeros_like(C)
    damping_forces_rate(E, V, data, damping, g2, C2)
    assert np.abs(K).max() > 0 and np.abs(C).max() > 0
    assert g2.tobytes() == g.tobytes() and C2.tobytes() == C.tobytes()
    g3 = np.zeros_like(g)
    damping_forces(E, V, data, damping, False, g3, K, C)
    assert g3.tobytes() == g.tobytes()
    assert build(load(THREAD)).kernel().damping_jacobian == 0


@pytest.mark.slow
def test_give_up_halves_a_cycling_step_sooner_to_the_same_state():
    """The THREAD race's drive (240 elements, 1e-4 s, the race's Newton settings): the first
    step whose Newton iteration fails (a contact point entering a pulley, its force jumping by
    c_p d') is taken again from the same state with ``give_up`` 3 and 0 (never): both end
    by halving; giving up costs at most half the residuals, and the two states agree within
    twice the setting's bound per substep (2^max_halvings of them)."""
    drive = build(load(THREAD, ["belt.n_elements=240", "belt.elastic_points=3",
                                "contact.gauss_points=4", "run.damping_jacobian=rate"]))
    ts = np.arange(3001) * 1e-4
    opts = [BeltOptions(dt=1e-4, newton_tol=TOL, give_up=g, **SETTINGS["once"]) for g in (3, 0)]
    m = _March(drive, opts[0], ts, 1)
    x, pre = settle(drive)
    v = np.zeros_like(x)
    a = m.initial_acceleration(x, v)
    st, dummy = (x, v, a, a.copy()), np.zeros((1, x.size))
    slot = np.full(ts.size, -1, dtype=np.int64)
    drive.z[:] = 0.0
    status, k = m.run(st, 0, ts.size - 1, slot, dummy, dummy, 1e9)
    assert status == NEWTON_FAILED, "no cycling step in the first 0.3 s"
    start, z0, h0 = tuple(c.copy() for c in st), drive.z.copy(), drive.h[0]
    states, residuals = [], []
    for opt in opts:
        mq = _March(drive, opt, ts, 1)
        s = tuple(c.copy() for c in start)
        drive.z[:], drive.h[0] = z0, h0
        status, _ = mq.run(s, k, k + 1, slot, dummy, dummy, 1e9)
        assert status == NEWTON_FAILED
        assert _halved(mq, s, ts[k], ts[k + 1], 1, 1e9)
        states.append(s[0])
        residuals.append(mq.count[0])
    assert residuals[0] <= 0.5 * residuals[1], residuals
    scale = TOL * (1 + np.max(np.abs(x[: drive.n]))) / (1 - REFRESH_RATIO)
    assert np.max(np.abs(states[0] - states[1])) <= 2 * 2 ** opts[0].max_halvings * scale


def test_give_up_is_a_drive_file_key_the_march_reads():
    """``run.give_up`` reaches the march's settings (its range: the error-line cases)."""
    assert load(THREAD).run["give_up"] == 0
    assert load(THREAD, ["run.give_up=3"]).run["give_up"] == 3
    assert newton_settings(1e-7, give_up=3)[4] == 3.0
