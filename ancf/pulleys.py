"""Pulley laws of the 2D belt drive (thesis section 3.3): the driver's prescribed
angular velocity (Eq. 3.29) and the opposing torque on the driven pulley (Eq. 3.30).

Angular velocities are counter-clockwise positive (rad/s), torques in N m.  Both
laws start at ``t0`` = 0.05 s and reach their final value at ``t1`` = 0.6 s; the
driver ramps linearly, the torque follows ``T_max/2 (1 - cos(pi t / t1))`` as
printed (so it jumps from 0 to 0.0043 T_max at t0).  The driven pulley obeys
Eq. 3.26 with the opposing torque entering as ``-T_a(t)``: it resists the
pulley's counter-clockwise rotation (the thesis writes ``+ T_a`` for "the possible
opposing torque" without fixing its sign).
"""
from __future__ import annotations

import numpy as np

T0, T1 = 0.05, 0.6


def driver_omega(t, omega_final: float) -> np.ndarray:
    """Eq. 3.29: 0 up to t0, linear to ``omega_final`` (rad/s) at t1, then constant."""
    t = np.asarray(t, dtype=float)
    return omega_final * np.clip((t - T0) / (T1 - T0), 0.0, 1.0)


def opposing_torque(t, Ta_max: float) -> np.ndarray:
    """Eq. 3.30: 0 up to t0, ``Ta_max/2 (1 - cos(pi t / t1))`` up to t1, then Ta_max (N m)."""
    t = np.asarray(t, dtype=float)
    ramp = 0.5 * Ta_max * (1.0 - np.cos(np.pi * t / T1))
    return np.where(t <= T0, 0.0, np.where(t <= T1, ramp, Ta_max))
