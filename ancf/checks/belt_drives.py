"""Belt drives of any layout against the steady reference (issue 21): the serpentine
drive's acceptance checks (:func:`serpentine_checks`) against the reference of its drive
file (:func:`ancf.belts.drive_steady.steady_reference`, ``analytic/belt_steady.py`` on the
file's layout and final laws); the THREAD benchmark's are in :mod:`ancf.checks.thread`.

Means are over the run's ``run.steady_window`` (speeds and torques over every step of it,
``omega_mean`` and ``torque_mean_Nm``); torques are the belt's moments on the pulleys
(counter-clockwise positive, N m), angles in degrees.
"""
from __future__ import annotations

import numpy as np

from ancf.belts.drive_data import DriveDescription
from ancf.belts.drive_steady import steady_reference
from ancf.checks.belt2d import Check

#: issue 21's serpentine acceptance: %, %, degree, % of the smaller driven torque
TOLERANCES = {"speeds": 2.0, "spans": 2.0, "arm": 0.5, "idler": 1.0}
SERPENTINE_NAMES = ("Serpentine: pulley speeds within 2 % of the steady reference",
                    "Serpentine: span tensions within 2 % of the steady reference",
                    "Serpentine: tensioner arm within 0.5° of its equilibrium",
                    "Serpentine: idler and tensioner moments within 1 % of the driven torques")


def serpentine_checks(results: dict, desc: DriveDescription) -> list[Check]:
    """The serpentine run (``results``) against its steady reference: the largest
    speed and span-tension errors (%), the arm's angle error (degree) and the largest
    moment on an idler or tensioner in % of the smallest driven pulley's."""
    ref = steady_reference(desc)
    pct = lambda a, b: 100 * abs(a - b) / abs(b)  # noqa: E731
    speeds = max(pct(o["omega_mean"], r["omega"]) for o, r in zip(results["pulleys"], ref["pulleys"]))
    spans = max(pct(o["tension_mean_N"], r["tension_N"])
                for o, r in zip(results["spans"], ref["spans"]))
    arm = max((abs(np.degrees(a["angle_mean_rad"] - r["arm_angle_rad"]))
               for a in results["arms"] for r in ref["pulleys"] if r["name"] == a["name"]),
              default=0.0)
    T = {p["name"]: p["torque_mean_Nm"] for p in results["pulleys"]}
    laws = {p.name: p.law for p in desc.pulleys}
    driven = min(abs(T[n]) for n, law in laws.items() if law == "driven")
    idle = max(abs(T[n]) for n, law in laws.items() if law in ("idler", "tensioner"))
    rows = [(speeds, "speeds", "%", "largest abs(ω_ours − ω_ref) / ω_ref over the pulleys"),
            (spans, "spans", "%", "largest abs(T_ours − T_ref) / T_ref over the spans"),
            (arm, "arm", "deg", "abs(arm angle − the reference's equilibrium)"),
            (100 * idle / driven, "idler", "%", "largest idler / tensioner moment, % of the "
             "smallest driven pulley's")]
    return [Check(name, v, 0.0, v, TOLERANCES[k], u, m)
            for name, (v, k, u, m) in zip(SERPENTINE_NAMES, rows)]
