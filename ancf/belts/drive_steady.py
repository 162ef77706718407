"""The steady reference of a drive (issue 21): :func:`analytic.belt_steady.solve`
(Bechtel's extensible string round the drive's pulleys) on a validated drive description
(:mod:`ancf.belts.drive_data`), the one the ``belt-drive`` scene's sweeps score against and
the serpentine and THREAD checks compare with.
"""
from __future__ import annotations

import numpy as np

from ancf.belts.drive_data import ROLES, DriveDescription, element_modulus, shifted
from analytic.belt_steady import path_length, solve


def steady_reference(desc: DriveDescription) -> dict:
    """:func:`analytic.belt_steady.solve` on the drive's layout (every pulley at the end of
    its prescribed centre motion, :func:`~ancf.belts.drive_data.shifted`; a tensioner at its
    file position, carried so, as the arm's nominal one), its final laws (the prescribed speeds' and load
    torques' end values, the damping, the arm's spring) and its belt (the element's EA,
    :func:`ancf.belts.drive_data.element_modulus`; rho A, the reference length) with the
    friction's mu.  InputError (a ValueError) where the steady belt does not exist."""
    pulleys = [{"name": p.name, "centre": shifted(p), "radius": p.radius, "side": p.side,
                "law": p.law, **ROLES[p.law].steady(p.params)} for p in desc.pulleys]
    for i, p in enumerate(desc.pulleys):
        if ROLES[p.law].arm:
            pulleys[i]["preload"] *= _into(pulleys, i, p)
    b = desc.belt
    area = b["b"] * b["h"]
    return solve(pulleys, EA=element_modulus(b) * area, rhoA=b["rho"] * area, L0=b["length"],
                 mu=desc.friction["mu"])


def _into(pulleys, i, p) -> float:
    """+1 if turning tensioner i's arm counter-clockwise lengthens the path, else -1 (the
    reference's preload turns the arm into the belt, the file's counter-clockwise)."""
    turned = [dict(q) for q in pulleys]
    pivot = np.add(p.params["pivot"], p.params["centre_shift"])  # moved with its pulley
    a = np.arctan2(*np.subtract(p.centre, p.params["pivot"])[::-1]) + 1e-6
    turned[i]["centre"] = np.add(pivot, p.params["arm_length"]
                                 * np.array([np.cos(a), np.sin(a)]))
    return float(np.sign(path_length(turned) - path_length(pulleys)))
