"""Belt drives of any layout against the steady reference (issue 21): the reference of a
drive file (:func:`steady_reference`, ``analytic/belt_steady.py`` on the file's layout and
final laws) and the serpentine drive's acceptance checks (:func:`serpentine_checks`);
the THREAD benchmark's are in :mod:`ancf.checks.thread`.

Means are over the run's ``run.steady_window``; torques are the belt's moments on the
pulleys (``torque_Nm``, counter-clockwise positive, N m), angles in degrees.
"""
from __future__ import annotations

import numpy as np

from ancf.belts.drive_data import DriveDescription, element_modulus
from ancf.checks.belt2d import Check
from analytic.belt_steady import path_length, solve

#: issue 21's serpentine acceptance: %, %, degree, % of the smaller driven torque
TOLERANCES = {"speeds": 2.0, "spans": 2.0, "arm": 0.5, "idler": 1.0}
SERPENTINE_NAMES = ("Serpentine: pulley speeds within 2 % of the steady reference",
                    "Serpentine: span tensions within 2 % of the steady reference",
                    "Serpentine: tensioner arm within 0.5° of its equilibrium",
                    "Serpentine: idler and tensioner moments within 1 % of the driven torques")


def steady_reference(desc: DriveDescription) -> dict:
    """:func:`analytic.belt_steady.solve` on the drive's layout, its final laws (the
    prescribed speeds' and load torques' end values) and its belt (the element's EA,
    :func:`ancf.belts.drive_data.element_modulus`)."""
    pulleys = []
    for p in desc.pulleys:
        q = {"name": p.name, "centre": p.centre, "radius": p.radius, "side": p.side,
             "law": p.law}
        if p.law == "prescribed":
            q["omega"] = p.params["omega_final"]
        elif p.law == "driven":
            q.update(torque=p.params["load_torque"], damping=p.params["damping"])
        elif p.law != "fixed":
            q["damping"] = p.params["damping"]
        if p.law == "tensioner":
            q.update(pivot=p.params["pivot"], stiffness=p.params["arm_stiffness"],
                     preload=p.params["arm_preload"])
        pulleys.append(q)
    for i, p in enumerate(desc.pulleys):
        if p.law == "tensioner":
            pulleys[i]["preload"] *= _into(pulleys, i, p)
    b = desc.belt
    return solve(pulleys, EA=element_modulus(b) * b["b"] * b["h"], rhoA=b["rho"] * b["b"] * b["h"],
                 L0=b["length"],
                 mu=desc.friction["mu"])


def _into(pulleys, i, p) -> float:
    """+1 if turning tensioner i's arm counter-clockwise lengthens the path, else -1 (the
    reference's preload turns the arm into the belt, the file's counter-clockwise)."""
    turned = [dict(q) for q in pulleys]
    a = np.arctan2(*np.subtract(p.centre, p.params["pivot"])[::-1]) + 1e-6
    turned[i]["centre"] = np.add(p.params["pivot"], p.params["arm_length"]
                                 * np.array([np.cos(a), np.sin(a)]))
    return float(np.sign(path_length(turned) - path_length(pulleys)))



def window_means(results: dict, window: float) -> dict:
    """{pulley name: mean torque_Nm over the last ``window`` s of the run} (N m)."""
    t = np.asarray(results["times"])
    sel = t >= t[-1] - window - 1e-12
    return {p["name"]: float(np.mean(np.asarray(p["torque_Nm"])[sel])) for p in results["pulleys"]}


def serpentine_checks(results: dict, desc: DriveDescription) -> list[Check]:
    """The serpentine run (``results``) against :func:`steady_reference`: the largest
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
    T = window_means(results, desc.run["steady_window"])
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
