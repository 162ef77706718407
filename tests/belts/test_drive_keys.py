"""Drive-file keys by behaviour (issue 33 item 7): every key left out of a file gives its
documented default (ancf.belts.drive_data's declarations), a key that physics says
matters changes the answer (contact.gauss_points; a tensioner's arm_inertia and
arm_damping: the arm's own transient, not its pulley's; its start angle and preload sign),
and the resisting load law against the signed one."""
from __future__ import annotations

import copy
import json
import math

import numpy as np
import pytest

from ancf.belts import drive_data as dd
from ancf.belts.drive_file import describe
from ancf.belts.drive_model import build
from ancf.belts.dynamics import BeltOptions, _March
from ancf.belts.forces import evaluate_record
from ancf.belts.pulleys import LOAD_LAWS, resisting, signed
from ancf.scenes.belt_drive import pulley_moments

R = 0.08125
#: a drive file with only its required keys (2D): a driver, a tensioner, a driven pulley
MINIMAL = {
    "belt": {"n_elements": 12, "E": 1e8, "h": 0.01, "b": 0.01, "rho": 1036.0,
             "prestretch": -0.003},
    "pulleys": [
        {"name": "driver", "centre": [-0.2, 0.0], "radius": R, "law": "prescribed",
         "speed": "ramp", "omega_final": 12.0, "t0": 0.0, "t1": 0.05},
        {"name": "tensioner", "centre": [0.0, -0.12], "radius": 0.04, "law": "tensioner",
         "inertia": 1e-4, "damping": 0.0, "pivot": [0.06, -0.16], "arm_inertia": 2e-3,
         "arm_stiffness": 50.0, "arm_preload": 0.0, "arm_damping": 0.3},
        {"name": "driven", "centre": [0.2, 0.0], "radius": R, "law": "driven",
         "inertia": 0.01, "damping": 0.0, "load": "constant", "load_torque": 1.0}],
    "friction": {"law": "creep-rate", "mu": 1.2, "nu_s": 1e5},
    "contact": {"k_p": 1e8},
    "run": {"t_end": 0.1, "dt": 5e-4},
}


def _with(**changes) -> dict:
    """MINIMAL with ``table__key`` (or ``pulleys__i__key``) changed."""
    data = copy.deepcopy(MINIMAL)
    for path, value in changes.items():
        *where, key = path.split("__")
        node = data
        for w in where:
            node = node[int(w)] if w.isdigit() else node[w]
        node[key] = value
    return data


def toml(data: dict) -> str:
    """A drive file's text of ``data`` (tables of numbers, strings and lists; pulleys an
    array of tables)."""
    value = json.dumps  # a TOML number, string or list of numbers is its JSON
    lines = [f"{k} = {value(v)}" for k, v in data.items() if not isinstance(v, (dict, list))]
    for name, table in data.items():
        rows = table if name == "pulleys" else [table] if isinstance(table, dict) else []
        for row in rows:
            lines.append(f"[[{name}]]" if name == "pulleys" else f"[{name}]")
            lines += [f"{k} = {value(v)}" for k, v in row.items()]
    return "\n".join(lines) + "\n"


def _defaults(keys: dict) -> dict:
    return {k: q.default for k, q in keys.items() if q.default is not dd.REQUIRED}


# ------------------------------------------------------------------ defaults

def test_every_key_left_out_gives_its_documented_default():
    """The belt, contact and run tables, the pulley's side, the driven pulley's load law:
    each key the file leaves out takes the default its declaration documents (a wrong
    default, e.g. contact.gauss_points 7 -> 5, no file sets it, fails here)."""
    d = describe(copy.deepcopy(MINIMAL))
    for table, keys in (("belt", dd.BELT), ("contact", dd.CONTACT), ("run", dd.RUN)):
        got = getattr(d, table)
        for k, default in _defaults(keys).items():
            assert got[k] == pytest.approx(default) if isinstance(default, float) \
                else got[k] == default, f"{table}.{k}"
    assert d.gravity == dd.TOP["gravity"].default == (0.0, 0.0)
    assert all(q.side == dd.PULLEY["side"].default == 1 for q in d.pulleys)
    driven = d.pulleys[2].params
    assert (driven["load_acts"], driven["omega_reg"]) == ("signed", 0.1)
    for k, default in _defaults({q.name: q for q in dd.ROLES["driven"].keys}).items():
        assert driven[k] == default, k


def test_documented_defaults_are_the_ones_the_docs_name():
    """The numbers the module docstrings and the README promise (independent of the
    declarations above): 7 contact points per Dufva element, 81 per plate, settled start."""
    assert dd.CONTACT["gauss_points"].default == 7
    assert dd.CONTACT_KEYS["plate36"]["gauss_points"].default == 81
    assert dd.RUN["start"].default == "settled"
    assert dd.RUN["steady_window"].default == 0.1
    assert dd.BELT["element"].default == "dufva2d"


def test_plate_belt_keys_left_out_give_their_defaults():
    data = copy.deepcopy(MINIMAL)
    data["belt"].update(element="plate36", h=0.002, b=0.02)
    del data["pulleys"][1]
    d = describe(data)
    for k, default in _defaults(dd.PLATE_BELT).items():
        assert d.belt[k] == default or k == "element", k
    for k, default in _defaults(dd.CONTACT_KEYS["plate36"]).items():
        assert d.contact[k] == default, k


def _moments(data: dict) -> np.ndarray:
    """The belt's moments (N m) on the pulleys of the drive laid on its path, every node
    moving at 1 m/s along x (the belt sliding on the pulleys), at t = 0.2 s."""
    drive = build(describe(data))
    x = drive.state(drive.q0)
    v = np.zeros_like(x)
    v[: drive.n] = drive.pattern.restrict(np.tile([1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                                                  drive.n_dofs // 6))
    return pulley_moments(drive, x, v, 0.2)


def test_gauss_points_changes_the_answer():
    """The contact quadrature is a key that matters: 5 and 7 points per element give
    moments that differ (by more than round-off), the default's equal to 7's."""
    T5, T7 = _moments(_with(contact__gauss_points=5)), _moments(_with(contact__gauss_points=7))
    assert np.max(np.abs(T5 - T7)) > 1e-6 * np.max(np.abs(T7))
    assert np.array_equal(_moments(copy.deepcopy(MINIMAL)), T7)


# ------------------------------------------------------------------ the tensioner arm

def _arm_terms(data: dict, psi: float = 0.0, psid: float = 0.0):
    """(the arm's residual (N m) at arm angle psi rad, rate psid rad/s; its initial
    acceleration rad/s^2 at psi, psid) of the drive laid on its path at rest."""
    drive = build(describe(data))
    x = drive.state(drive.q0)
    j = drive.n + drive.k - 1  # the arm's coordinate: the last
    x[j] = psi
    v = np.zeros_like(x)
    v[j] = psid
    m = _March(drive, BeltOptions(dt=5e-4), np.array([0.0, 5e-4]), 2)
    s = m.system
    f = np.zeros(x.size)
    k = drive.k
    evaluate_record(x, v, s.tabs[:, 0].copy(), s.drive, False, 0.0, 0.0, f, np.zeros((1, 1)),
                    np.zeros((k, drive.n)), np.zeros((k, drive.n)), np.zeros((k, k)))
    return f[j], m.initial_acceleration(x, v)[j], drive


def test_arm_start_is_the_files_centre():
    """At arm angle 0 the tensioner's centre is where the file puts it (the arm's start
    angle from the pivot), on any side of the pivot."""
    for centre, pivot in (([0.0, -0.12], [0.06, -0.16]), ([0.0, -0.12], [-0.05, -0.2])):
        drive = build(describe(_with(pulleys__1__centre=centre, pulleys__1__pivot=pivot)))
        o, _ = drive.moved(drive.state(drive.q0), np.zeros(drive.n + drive.k))
        assert o[1] == pytest.approx(centre, abs=1e-15)


def test_arm_preload_is_counter_clockwise_positive():
    """The arm's equation I psi'' = A + preload - k psi - c psi': a preload P adds -P to its
    residual (P counter-clockwise turns it counter-clockwise)."""
    f0, a0, _ = _arm_terms(MINIMAL)
    f1, a1, _ = _arm_terms(_with(pulleys__1__arm_preload=2.0))
    assert f1 - f0 == pytest.approx(-2.0, rel=1e-12)
    assert a1 - a0 == pytest.approx(2.0 / 2e-3, rel=1e-9)


def test_arm_inertia_and_damping_are_the_arms_own():
    """The arm's transient signature: its initial acceleration scales as 1/arm_inertia
    (not the pulley's inertia), its rate psi' adds arm_damping psi' to its residual (not
    the pulley's damping; the pulley's bearing damping is 0 here)."""
    _, a1, _ = _arm_terms(_with(pulleys__1__arm_preload=1.0))
    _, a2, _ = _arm_terms(_with(pulleys__1__arm_preload=1.0, pulleys__1__arm_inertia=4e-3))
    assert a1 / a2 == pytest.approx(2.0, rel=1e-9)
    fd, _, _ = _arm_terms(MINIMAL, psid=1e-3)
    fdd, _, _ = _arm_terms(_with(pulleys__1__arm_damping=0.9), psid=1e-3)
    # the belt's contact damping at a moving centre is the same in both: it drops out
    assert (fdd - fd) == pytest.approx((0.9 - 0.3) * 1e-3, rel=1e-9)


# ------------------------------------------------------------------ load laws

def test_load_laws():
    """signed: T_a whatever the speed; resisting: |T_a| against the rotation, smooth
    through 0, within 0.5 % of |T_a| beyond 3 omega_reg."""
    w = np.array([-10.0, -0.3, 0.0, 0.3, 10.0])
    assert np.array_equal(signed(5.0, w), np.full(5, 5.0))
    r = resisting(5.0, w, 0.1)
    assert r[2] == 0.0 and np.all(np.sign(r) == np.sign(w))
    assert abs(r[3]) == pytest.approx(5 * math.tanh(3.0)) and r[3] > 0.995 * 5
    assert np.array_equal(resisting(-5.0, w, 0.1), r)
    assert LOAD_LAWS["resisting"].keys == ("omega_reg",)


def test_resisting_load_in_the_march_residual():
    """The march's residual of a resisting load at a free pulley turning at omega:
    |T_a| tanh(omega / omega_reg), against the rotation; signed: T_a."""
    from ancf.belts.system import load_terms
    drive = build(describe(_with(pulleys__2__load_acts="resisting",
                                 pulleys__2__load_torque=-3.0, pulleys__2__omega_reg=0.5)))
    m = _March(drive, BeltOptions(dt=5e-4), np.array([0.0, 5e-4]), 2)
    s = m.system
    n, k = drive.n, drive.k
    laws = s.tabs[:, 0].copy()
    for omega in (-2.0, 0.1, 4.0):
        v = np.zeros(n + k)
        j = drive.rig.free[2]
        v[n + j] = omega
        r, corner = np.zeros(n + k), np.zeros((k, k))
        r[n + j] = laws[2]  # what the kernel adds: the signed T_a
        load_terms(s.loads, laws, v, 1.0, True, r, corner)
        assert r[n + j] == pytest.approx(3.0 * math.tanh(omega / 0.5), rel=1e-14)
        h = 1e-6
        v[n + j] = omega + h
        r2 = np.zeros(n + k)
        r2[n + j] = laws[2]
        load_terms(s.loads, laws, v, 1.0, False, r2, np.zeros((k, k)))
        assert corner[j, j] == pytest.approx((r2[n + j] - r[n + j]) / h, rel=1e-4)
