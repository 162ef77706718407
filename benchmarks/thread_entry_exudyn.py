"""Exudyn's THREAD drive (``benchmarks/peers_thread_exudyn.py``, THREAD's settings) with its
contact varied one setting at a time, to see where the driven pulley's extra speed over
belt creep comes from (``reports/belt_drives.md``, THREAD section).

Each run prints, as JSON: the driven omega mean over the last 0.45 s (rad/s), the span
forces and the stick-arc tensions at the end (N, :func:`ancf.checks.thread.wrap_tensions`
on the element starts and midpoints placed on THREAD's coordinate), and the two speeds
of :mod:`ancf.checks.thread`: creep from the span forces and rolling from the stick arcs
(EA (1 + eps_ref) = 7600 N per laid length).

``python -m benchmarks.thread_entry_exudyn [--elements 120] [--segments 4] [--step 1e-4]
[--t-end 2.45] [--contact surface|centreline] [--penalty-factor 1]``: ``--contact
centreline`` puts the contact on the belt's centreline (circle radius 0.1 m, the marker's
verticalOffset 0) instead of THREAD's surface (radius 0.09995 m, verticalOffset -h/2);
``--penalty-factor`` scales the friction velocity penalty (THREAD: 1).

Measured with Exudyn 1.13.6 at 120 elements x 4 segments, step 1e-4 s (THREAD's stored
120 x 4 case, step 5e-5 s: omega 11.3476 rad/s, 0.374 % over creep, the driver's entry
drop 25.9 N, the driven pulley's rise 5.9 N): ``--contact centreline`` 11.3479 rad/s,
0.375 % over creep, drop 26.0 N, rise 5.9 N; ``--penalty-factor 0.1`` 11.3477 rad/s,
0.373 %, 25.9 N, 5.9 N; both at their stick arcs' rolling speed within 0.004 %.  Neither
where the contact sits (surface or centreline, the radius of the pulley's surface speed)
nor the bristle's velocity penalty moves the entry zones; the contact segment's length
does (THREAD's own variants, the belt_drives chapter).
"""
from __future__ import annotations

import argparse
import json
import sys

import numpy as np

from ancf.checks import thread as th
from benchmarks import peers_thread_exudyn as px

EA_LAID = 8000.0 * (1 - 0.05)   # N, Exudyn's EA (1 + eps_ref) per laid length


def _configure(a) -> None:
    """THREAD's settings (5 discontinuous iterations) with the run's overrides."""
    px.N_ELEMENTS, px.SEGMENTS, px.STEP, px.DISCONTINUOUS = a.elements, a.segments, a.step, 5
    if a.contact == "centreline":
        px.R, px.HC = px.R + px.HC / 2, 0.0
    base = px._coefficients

    def scaled(total_length):
        co = base(total_length)
        co["frictionVelocityPenalty"] *= a.penalty_factor
        return co
    px._coefficients = scaled


def _along(mbs, belt) -> tuple[np.ndarray, np.ndarray]:
    """THREAD's s (m) and the axial force (N) at every element's start and midpoint."""
    s, N = [], []
    for e in belt:
        l_e = mbs.GetObjectParameter(e, "length")
        for xi in (0.0, 0.5):
            p = mbs.GetObjectOutputBody(e, px.exu.OutputVariableType.Position, [xi * l_e, 0, 0])
            f = mbs.GetObjectOutputBody(e, px.exu.OutputVariableType.ForceLocal, [xi * l_e, 0, 0])
            s.append(float(th.coordinate(p[0], p[1])))
            N.append(float(np.ravel(f)[0]))
    return np.array(s), np.array(N)


def run(a) -> dict:
    _configure(a)
    mbs, _sc, h = px.build()
    out = px.solve(mbs, h, px.settings(a.t_end))
    w = mbs.GetSensorStoredData(h["sensors"][1])
    win = w[:, 0] >= a.t_end - px.WINDOW - 1e-9
    s, N = _along(mbs, h["belt"])
    tight, slack = th.span_forces(s, N, th.PATH)
    t1, t2 = th.wrap_tensions(s, N, px.MU)
    k_p = 1e8 * 40 * px.B
    omega = float(np.mean(w[win, 3]))
    creep = th.creep_speed(th.OMEGA_DRIVER, tight, slack, EA_LAID)
    rolling = th.rolling_speed(th.OMEGA_DRIVER, t1, t2, EA_LAID, k_p)
    return {**vars(a), "exudyn_version": px.exu.__version__, "converged": out["converged"],
            "cpu_s": out["dynamic_cpu_s"], "omega_driven_mean": omega,
            "tight_N": tight, "slack_N": slack, "stick_driver_N": t1, "stick_driven_N": t2,
            "creep_speed": creep, "rolling_speed": rolling,
            "over_creep_pct": 100 * (omega / creep - 1),
            "over_rolling_pct": 100 * (omega / rolling - 1)}


def main(argv=None) -> int:
    if px.exu is None:
        print("error: exudyn is not installed (optional extra `peers`)", file=sys.stderr)
        return 2
    ap = argparse.ArgumentParser(prog="python -m benchmarks.thread_entry_exudyn")
    ap.add_argument("--elements", type=int, default=120)
    ap.add_argument("--segments", type=int, default=4)
    ap.add_argument("--step", type=float, default=1e-4)
    ap.add_argument("--t-end", type=float, default=2.45)
    ap.add_argument("--contact", choices=("surface", "centreline"), default="surface")
    ap.add_argument("--penalty-factor", type=float, default=1.0)
    print(json.dumps(run(ap.parse_args(argv)), indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
