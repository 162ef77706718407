"""The serpentine drive as a plate belt (issue 36: "Plate-belt serpentine: pulley speeds
within 1 % and arm angle within 0.2° of the steady reference's (and of the planar belt's at
the same data)").

Runs.  ``examples/serpentine_3d.toml`` (``examples/serpentine.toml``'s layout, belt section,
laws and tensioner arm on ``plate36``, one plate across, a membrane; contact and creep per
unit area) and the planar belt of ``examples/serpentine.toml`` with the plate file's time
laws and run times (:func:`planar_items`: every pulley's ``t0``, ``t1`` and the ``[run]``
times, so both belts see the same data).  The reference is the steady string of the plate
file (:func:`ancf.belts.drive_steady.steady_reference`, ``analytic/belt_steady.py``:
EA = E b h, its final laws and arm spring).

Compared: each pulley's mean angular velocity over the steady window (rad/s, ``omega_mean``,
% of the reference's and of the planar run's) and the tensioner arm's mean angle
(``angle_mean_rad``, degrees from the reference's equilibrium and from the planar run's).
"""
from __future__ import annotations

import math
from functools import lru_cache

from ancf.belts.drive_data import DriveDescription
from ancf.belts.drive_steady import steady_reference
from ancf.checks.belt2d import Check
from ancf.common.paths import REPO

PLATE = REPO / "examples" / "serpentine_3d.toml"
PLANAR_FILE = REPO / "examples" / "serpentine.toml"
#: the issue's acceptance: pulley speeds (%), arm angle (degree)
TOL = {"speeds": 1.0, "arm": 0.2}
NAMES = ("Plate-belt serpentine: pulley speeds within 1 % of the steady reference's and the "
         "planar belt's",
         "Plate-belt serpentine: arm angle within 0.2° of the steady reference's and the "
         "planar belt's")
#: the time keys of the pulley laws the planar run takes from the plate file
TIME_KEYS = ("t0", "t1")
#: the run keys the planar run takes from the plate file
RUN_KEYS = ("t_end", "dt", "output_dt", "steady_window")


def planar_items(desc: DriveDescription) -> tuple:
    """The overrides ("key=value") that give the planar file the plate file's (``desc``)
    time laws (every pulley's ``t0``, ``t1``, s) and run times (s)."""
    laws = tuple(f"pulleys.{p.name}.{k}={p.params[k]!r}" for p in desc.pulleys
                 for k in TIME_KEYS if k in p.params)
    return laws + tuple(f"run.{k}={desc.run[k]!r}" for k in RUN_KEYS)


@lru_cache(maxsize=None)
def runs(items: tuple = ()) -> tuple:
    """(plate JSON, planar JSON, the plate's description) of the two ``belt-drive`` runs,
    both with the overrides ``items`` ("key=value"; the planar one after
    :func:`planar_items`)."""
    from ancf.belts.drive_file import load
    from ancf.scenes import SCENES
    scene = SCENES["belt-drive"]
    desc = load(PLATE, items)
    plate, _ = scene.execute({"file": str(PLATE), "set": "; ".join(items)})
    planar, _ = scene.execute({"file": str(PLANAR_FILE),
                               "set": "; ".join(planar_items(desc) + tuple(items))})
    for name, out in (("plate", plate), ("planar", planar)):
        if not out["converged"]:
            raise RuntimeError(f"serpentine {name} run: {out['message']}")
    return plate, planar, desc


def rows(plate: dict, planar: dict, ref: dict) -> list[dict]:
    """Per pulley its mean speed (rad/s) and for the arm its mean angle (degree): the
    plate's, the steady reference's (``ref``, :func:`steady_reference`'s), the planar
    run's, and the plate's difference from each (% for speeds, degrees for the angle)."""
    ref_p = {p["name"]: p for p in ref["pulleys"]}
    planar_p = {p["name"]: p for p in planar["results"]["pulleys"]}
    pct = lambda a, b: 100 * (a / b - 1)  # noqa: E731
    out = []
    for p in plate["results"]["pulleys"]:
        w, r, q = p["omega_mean"], ref_p[p["name"]]["omega"], planar_p[p["name"]]["omega_mean"]
        out.append({"quantity": f"{p['name']} ω, rad/s", "kind": "speeds", "plate": w,
                    "reference": r, "planar": q, "vs reference": pct(w, r),
                    "vs planar": pct(w, q)})
    planar_a = {a["name"]: a for a in planar["results"]["arms"]}
    for a in plate["results"]["arms"]:
        deg = math.degrees(a["angle_mean_rad"])
        r = math.degrees(ref_p[a["name"]]["arm_angle_rad"])
        q = math.degrees(planar_a[a["name"]]["angle_mean_rad"])
        out.append({"quantity": f"{a['name']} arm angle, deg", "kind": "arm", "plate": deg,
                    "reference": r, "planar": q, "vs reference": deg - r,
                    "vs planar": deg - q})
    return out


def compare(items: tuple = ()) -> tuple[list[dict], dict]:
    """(:func:`rows` of the two runs with ``items`` against the plate file's steady
    reference, the CPU times in s: the plate run's and the planar run's, ``cpu_time_s``)."""
    plate, planar, desc = runs(items)
    cpu = {name: out["cpu_time_s"]
           for name, out in (("plate", plate), ("planar", planar))}
    return rows(plate, planar, steady_reference(desc)), cpu


def checks(got: list[dict]) -> list[Check]:
    """The two acceptance rows: the largest abs difference of the plate's speeds (%) and
    arm angle (degree) from the reference's and the planar run's."""
    out = []
    for name, kind, unit in zip(NAMES, ("speeds", "arm"), ("%", "deg")):
        worst = max(max(abs(r["vs reference"]), abs(r["vs planar"]))
                    for r in got if r["kind"] == kind)
        what = ("abs(ω_plate / ω − 1) over the pulleys" if kind == "speeds"
                else "abs(plate's arm angle − the other's)")
        out.append(Check(name, worst, 0.0, worst, TOL[kind], unit,
                         f"largest {what}, against the steady reference and the planar "
                         "belt, window means"))
    return out
