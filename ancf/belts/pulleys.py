"""Pulley laws of the belt drives (thesis sections 3.3 and 4.6): the driver's prescribed
angular velocity (Eq. 3.29), the opposing torque on the driven pulley (Eq. 3.30; in 3D
Eq. 4.47; the THREAD benchmark's cosine step) and the driver's pre-tensioning
displacement (Eq. 4.46).

Angular velocities are counter-clockwise positive (rad/s), torques in N m.  Both
laws start at ``t0`` = 0.05 s and reach their final value at ``t1`` (0.6 s in 2D; in
3D Table 4.1's t1: 0.6 s for Model 1, 1.0 s for Model 2); the
driver ramps linearly, the torque follows ``T_max/2 (1 - cos(pi t / t1))`` as
printed (so it jumps from 0 to 0.0043 T_max at t0).  The driven pulley obeys
Eq. 3.26 with the opposing torque entering as ``-T_a(t)``: it resists the
pulley's counter-clockwise rotation (the thesis writes ``+ T_a`` for "the possible
opposing torque" without fixing its sign).

Eq. 4.47 prints T_a = 1 - cos(pi t / 1.0) for 0.05 < t <= 1.0 and 2 for 0.6 < t; the
branches overlap on (0.6, 1.0].  We take the middle branch up to 1.0 s (first match
as printed): it is Eq. 3.30 with t1 = 1.0 s and T_max = 2 N m, continuous at 1.0 s,
whereas the 0.6 of the last branch would jump from 1.69 to 2 N m (it is Model 1's t1).

A law is one :class:`TimeLaw`: its name, the drive-file keys of its parameters
(declared with their units and ranges in :data:`ancf.belts.drive_data.LAW_PARAMS`) and
its function of the time.  A drive names its driver's speed law and its load torque law
(``driver_law``, ``torque_law`` of its spec); :data:`SPEED_LAWS` and :data:`TORQUE_LAWS`
hold the laws ``law(t, final, t0, t1)`` of the time (s, an array) that are 0 up to
``t0`` and ``final`` from ``t1`` on, and a drive file's pulleys may name those and the
laws of :data:`FILE_SPEED_LAWS` and :data:`FILE_TORQUE_LAWS` (a table, a constant).  A
new law is one function and one TimeLaw here; tests/belts/test_pulley_laws.py holds
every law of SPEED_LAWS and TORQUE_LAWS to that contract.

A pulley's centre may move by a prescribed law (a :class:`CentreMotion`: a direction and a
:class:`MotionLaw` of :data:`CENTRE_LAWS`, the distance u(t) and its rate; ``ramp`` is
Eq. 4.46's u = u0 t / t0 up to t0), as the thesis's Model 1 moves its driver.

How a free pulley's load torque acts is a :class:`LoadLaw` of :data:`LOAD_LAWS` (a drive
file's ``load_acts``): ``signed``, T_a(t) as given, resisting counter-clockwise rotation
whatever the pulley does (Eq. 3.26; a load above what the belt carries turns the pulley
backwards), or ``resisting``, a brake or accessory that opposes the motion and cannot
drive the belt: |T_a(t)| tanh(omega / omega_reg) against the pulley's angular velocity
omega (rad/s), smooth through omega = 0 for Newton (``omega_reg`` rad/s; at |omega| = 3
omega_reg it is 99.5 % of |T_a|).  The march reads it from a :data:`LOAD` record per free
pulley by field name (:func:`load_records`; :func:`ancf.belts.system.load_terms`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

T0, T1 = 0.05, 0.6


def driver_omega(t, omega_final: float, t0: float = T0, t1: float = T1) -> np.ndarray:
    """Eq. 3.29: 0 up to t0, linear to ``omega_final`` (rad/s) at t1, then constant."""
    t = np.asarray(t, dtype=float)
    return omega_final * np.clip((t - t0) / (t1 - t0), 0.0, 1.0)


def opposing_torque(t, Ta_max: float, t0: float = T0, t1: float = T1) -> np.ndarray:
    """Eq. 3.30: 0 up to t0, ``Ta_max/2 (1 - cos(pi t / t1))`` up to t1, then Ta_max (N m)."""
    t = np.asarray(t, dtype=float)
    ramp = 0.5 * Ta_max * (1.0 - np.cos(np.pi * t / t1))
    return np.where(t <= t0, 0.0, np.where(t <= t1, ramp, Ta_max))


def cosine_step(t, final: float, t0: float, t1: float) -> np.ndarray:
    """0 up to t0, ``final/2 (1 - cos(pi (t - t0) / (t1 - t0)))`` up to t1, then ``final``:
    the load torque of the THREAD belt benchmark (Exudyn's SmoothStep; 25 N m over
    1-1.5 s there)."""
    t = np.asarray(t, dtype=float)
    step = 0.5 * final * (1.0 - np.cos(np.pi * np.clip((t - t0) / (t1 - t0), 0.0, 1.0)))
    return np.where(t <= t0, 0.0, np.where(t < t1, step, final))


def tabulated(t, rows) -> np.ndarray:
    """The table ``rows`` ([[t, value], ...], t increasing) at t (s), interpolated
    linearly and held beyond its ends."""
    ts, ys = np.array(rows).T
    return np.interp(np.asarray(t, dtype=float), ts, ys)


def constant(t, value: float) -> np.ndarray:
    """``value`` at every t."""
    return np.full(np.shape(t), value)


@dataclass(frozen=True, kw_only=True)
class TimeLaw:
    """A pulley law of the time: ``name``, ``keys`` the drive-file keys of its parameters
    in the order ``value(t, *parameters)`` takes them (t in s, an array)."""

    name: str
    keys: tuple[str, ...]
    value: Callable

    def __call__(self, t, *parameters) -> np.ndarray:
        return self.value(t, *parameters)

    def of(self, params: dict) -> Callable:
        """The law as a function of t alone, its parameters taken by key from ``params``
        (a pulley's resolved keys)."""
        args = tuple(params[k] for k in self.keys)
        return lambda t: self.value(t, *args)


def _by_name(*laws) -> dict:
    return {law.name: law for law in laws}


#: driver speed laws by name: omega(t, omega_final, t0, t1), rad/s
SPEED_LAWS = _by_name(TimeLaw(name="ramp", keys=("omega_final", "t0", "t1"), value=driver_omega))
#: load torque laws by name: T_a(t, Ta_max, t0, t1), N m
TORQUE_LAWS = _by_name(
    TimeLaw(name="cosine-ramp", keys=("load_torque", "t0", "t1"), value=opposing_torque),
    TimeLaw(name="cosine-step", keys=("load_torque", "t0", "t1"), value=cosine_step))
#: the speed laws a drive file's prescribed pulley may name (``speed``)
FILE_SPEED_LAWS = {**SPEED_LAWS, **_by_name(
    TimeLaw(name="table", keys=("speed_table",), value=tabulated))}
#: the load torque laws a drive file's driven pulley may name (``load``)
FILE_TORQUE_LAWS = {**TORQUE_LAWS, **_by_name(
    TimeLaw(name="constant", keys=("load_torque",), value=constant),
    TimeLaw(name="table", keys=("load_table",), value=tabulated))}


def law(table: dict, name: str, field: str):
    """The law called ``name`` in ``table``; ValueError naming the spec ``field`` and the
    allowed names otherwise."""
    if name not in table:
        raise ValueError(f"{field} = {name!r} is not a law; allowed: {', '.join(table)}")
    return table[name]


def driver_shift(t, u0: float, t0: float = T0) -> tuple:
    """Eq. 4.46: the driver's displacement u = u0 t / t0 up to t0, then u0 (m), and its
    rate (m/s)."""
    t = np.asarray(t, dtype=float)
    return u0 * np.clip(t / t0, 0.0, 1.0), np.where(t < t0, u0 / t0, 0.0)


@dataclass(frozen=True, kw_only=True)
class MotionLaw:
    """A law of a pulley centre's prescribed motion along a fixed direction: ``name``,
    ``keys`` the drive-file keys of its parameters in the order ``value(t, distance,
    *parameters)`` takes them after the final distance (m), and ``value`` giving the
    distance u (m) and its rate (m/s) at t (s, an array)."""

    name: str
    keys: tuple[str, ...]
    value: Callable

    def of(self, distance: float, params: dict) -> Callable:
        """The law as a function of t alone: (u, du/dt), its parameters taken by key from
        ``params`` (a pulley's resolved keys)."""
        args = tuple(params[k] for k in self.keys)
        return lambda t: self.value(t, distance, *args)


@dataclass(frozen=True, kw_only=True)
class CentreMotion:
    """Pulley ``pulley``'s centre moved by ``law(t)`` = (u m, du/dt m/s) along the unit
    ``direction`` (dim,): centre c + u direction, velocity du/dt direction."""

    pulley: int
    direction: np.ndarray
    law: Callable


#: centre motion laws by name (a drive file's ``centre_motion``): (u, du/dt)(t, distance,
#: t0), m and m/s
CENTRE_LAWS = _by_name(MotionLaw(name="ramp", keys=("centre_shift_time",), value=driver_shift))


@dataclass(frozen=True, kw_only=True)
class LoadLaw:
    """How a free pulley's load torque T_a(t) (N m) acts on it at angular velocity omega
    (rad/s): ``name``, ``code`` (the :data:`LOAD` record's ``law``), ``keys`` the drive-file
    keys of its parameters in the order ``torque`` takes them, ``torque(T_a, omega,
    *parameters)`` the moment (N m) against counter-clockwise rotation."""

    name: str
    code: int
    keys: tuple[str, ...]
    torque: Callable


def signed(Ta, omega):
    """T_a as given (N m), whatever omega (rad/s)."""
    return Ta + 0.0 * np.asarray(omega)


def resisting(Ta, omega, omega_reg: float):
    """|T_a| tanh(omega / omega_reg) (N m): against the rotation, at omega (rad/s)."""
    return np.abs(Ta) * np.tanh(np.asarray(omega) / omega_reg)


#: load laws by name (a drive file's driven pulley ``load_acts``; default ``signed``)
LOAD_LAWS = _by_name(LoadLaw(name="signed", code=0, keys=(), torque=signed),
                     LoadLaw(name="resisting", code=1, keys=("omega_reg",), torque=resisting))
SIGNED, RESISTING = (LOAD_LAWS[k].code for k in ("signed", "resisting"))
#: the march's record of a free pulley's load law: its code, the row of the pulley laws
#: holding T_a(t) (-1: none, a tensioner's arm), omega_reg rad/s (the resisting law's)
LOAD = np.dtype((np.record, [("law", "i8"), ("row", "i8"), ("omega_reg", "f8")]))


def load_records(laws) -> np.ndarray:
    """The :data:`LOAD` records (k,) of the free coordinates, ``laws`` one (name, row,
    parameters dict) each (name None: none, signed)."""
    out = np.zeros(len(laws), LOAD)
    for rec, (name, row, params) in zip(out, laws):
        law = LOAD_LAWS[name or "signed"]
        rec.law, rec.row = law.code, row
        rec.omega_reg = params.get("omega_reg", 1.0)
    return out
