"""A crowned pulley centring an off-centre plate belt against the classic tracking rule
(issue 36 item 4): the runs, the predicted and the simulated return, the acceptance rows.

The runs: ``examples/crowned.toml`` (the coarse three-pulley plate belt, v = 1 m/s, the
driven pulley crowned by c = 0.5 mm over its face W = 1.1 b = 44 mm, that face displaced by
y0 = 3 mm along its axis so the belt starts 3 mm off the crown's top), as given (the
benchmark's soft belt: E = 1.67 MPa, 19 % strain) and with a belt 100 times stiffer at the
same tension (E x 100, prestretch -0.0019: 0.19 % strain; :data:`STIFF`).  Measured: the
driven pulley's ``lateral_position_m`` (the contact points' mean offset from the face's
mid-plane, :mod:`ancf.belts.tracking3d`) and, as supporting evidence, the belt's mid-line at
the entering tangent point (:func:`ancf.checks.belt_tracking3d.entry`).

The rule (Schwamb, Merrill & James, Elements of Mechanism, 1921, the belt "led upon a
revolving conical pulley"; Yoshida et al., Int. Robot. Autom. J. 10 (2024) 78, the crown's
axial variation of peripheral speed; with Shelton's normal entry of analytic/belt_tracking.py).
A belt lying flat on a face of slope gamma = dR/da cannot follow the surface's circles if it
cannot stretch one edge more than the other: developed flat, the local cone's circles have
radius R / gamma about its apex and the belt, straight, turns with the surface about the
apex at v gamma / R.  Its direction where it meets the pulley turns toward the larger
radius at that rate, and keeping that direction there (normal entry) its entry walks at v
times the angle.  On the parabolic crown the mean slope under a belt centred at z (from the
crown's top) is R'(z) = -8 c z / W^2 (linear, the parabola continued past the face), so in
the travel x (m)

    dz/dx = theta,  dtheta/dx = R'(z) / R   =>   z'' = -k z,  k = 8 c / (R W^2)        (1)
    z(0) = -y0, z'(0) = 0:  z = -y0 cos(sqrt(k) x);  |z| <= 0.1 y0 first at
    x* = arccos(0.1) / sqrt(k)                                                          (2)

(R the rim's radius at mid-face; the other pulleys are flat and the whole belt starts off by
y0, its spans square, so the held-span term of belt_tracking.py Eq. 2 is left out).  The
predicted time t* is where the driver's travel reaches x* (0.23 m: 0.24 s).

The rule's premise is an inextensible belt: to follow the circles instead, its edges must
differ in strain by |R'| b / R (:func:`strain_difference`: 0.5 % at 3 mm).  The benchmark
belt runs at 19 % strain and takes that up by stretching; the stiff belt (0.19 %) cannot.
:func:`rows` gives both; the rows of :data:`NAMES` compare the simulated return with t*.
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from ancf.checks.belt2d import Check
from ancf.common.paths import REPO

FILE = REPO / "examples" / "crowned.toml"
T_END = 0.5  # s: about twice the rule's return
#: the stiff belt's overrides: E x 100 at the same tension (strain 0.19 % for 19 %)
STIFF = ("belt.E=1.6667e8", "belt.prestretch=-0.0019")
BELTS = {"benchmark belt (19 % strain)": (), "stiff belt (E x 100, 0.19 % strain)": STIFF}
#: the acceptance: back within BAND of y0 within TOL of the predicted time
BAND, TOL = 0.10, 0.10
RETURN = "Crowned pulley, {belt}: back within 10 % of y0 within 10 % of the rule's time"
NAMES = tuple(RETURN.format(belt=b) for b in BELTS)


@lru_cache(maxsize=None)
def run(extra: tuple = (), t_end: float = T_END) -> tuple:
    """(out JSON, the scene's result) of ``examples/crowned.toml`` to ``t_end`` (s) with the
    ``--set`` items ``extra``."""
    import json

    from ancf.scenes import SCENES
    out, res = SCENES["belt-drive"].execute({
        "file": str(FILE), "run.t_end": str(t_end), "run.output_dt": "0.005",
        "run.steady_window": "0.005", "set": "; ".join(extra)})
    if not out["converged"]:
        raise RuntimeError(f"crowned run {extra}: {out['message']}")
    return json.loads(json.dumps(out)), res


def crown_data(res) -> dict:
    """The driven pulley's crown c, face W, rim radius at mid-face R (m), offset y0 (m) and
    the belt's width b (m) and strain of a run's description."""
    desc = res.extra["description"]
    q = desc.pulleys[2]
    c, b = q.params["crown_m"], desc.belt["b"]
    W = q.params["face_width_m"] or 1.1 * b
    R = q.radius + c + desc.belt["contact_offset"]
    return {"c": c, "W": W, "R": R, "y0": q.params["face_offset_m"], "b": b,
            "strain": 1.0 / (1.0 + desc.belt["prestretch"]) - 1.0}


def return_travel(c: float, W: float, R: float, band: float = BAND) -> float:
    """x* (m) of Eq. 2: the travel after which the rule's belt is first back within
    ``band`` of its offset."""
    return math.acos(band) / math.sqrt(8.0 * c / (R * W * W))


def strain_difference(c: float, W: float, R: float, b: float, z: float) -> float:
    """|R'(z)| b / R: the edges' strain difference a belt of width b (m) centred z (m) off
    the crown's top needs to follow the surface's circles."""
    return 8.0 * c * abs(z) / (W * W) * b / R


def travel(out, res) -> tuple:
    """(t (s), the belt's travel x (m)): the driver's speed omega R integrated."""
    from scipy.integrate import cumulative_trapezoid
    r = out["results"]
    t = np.array(r["times"])
    v = np.array(r["pulleys"][0]["omega"], float) * res.extra["drive"].radii[0]
    return t, cumulative_trapezoid(v, t, initial=0.0)


def measured(extra: tuple) -> dict:
    """One belt's run: the predicted and simulated return times (s; NaN if the driven
    pulley's lateral position is not back within BAND y0 by T_END), the lateral position
    and entry offset from the crown's top at the start and end (m), the strain figures."""
    from ancf.checks.belt_tracking3d import entry
    out, res = run(tuple(extra))
    d = crown_data(res)
    t, x = travel(out, res)
    lat = np.array(out["results"]["pulleys"][2]["lateral_position_m"], float)
    back = np.nonzero(np.abs(lat[1:]) <= BAND * d["y0"])[0]
    s_E = entry(res)[0] - d["y0"]
    return {"predicted_s": float(np.interp(return_travel(d["c"], d["W"], d["R"]), x, t)),
            "simulated_s": float(t[back[0] + 1]) if back.size else math.nan,
            "lateral_start_m": float(lat[1]), "lateral_end_m": float(lat[-1]),
            "entry_start_m": float(s_E[0]), "entry_end_m": float(s_E[-1]),
            "travel_m": float(x[-1]), "belt_strain": d["strain"],
            "edge_strain_difference": strain_difference(d["c"], d["W"], d["R"], d["b"],
                                                        d["y0"])}


def rows() -> list[dict]:
    """The chapter's table: per belt the measured figures (:func:`measured`)."""
    return [{"belt": name, **measured(extra)} for name, extra in BELTS.items()]


def checks(table: list[dict]) -> list[Check]:
    """The rows of :data:`NAMES` from :func:`rows`'s table: |t_sim / t* - 1| within TOL
    (infinite when the belt is not back by T_END)."""
    got = []
    for name, row in zip(NAMES, table):
        sim, pred = row["simulated_s"], row["predicted_s"]
        diff = abs(sim / pred - 1.0) if math.isfinite(sim) else math.inf
        got.append(Check(name, sim, pred, diff, TOL, "s",
                         f"first time |lateral_position_m| <= 0.1 y0 (driven pulley; NaN: not "
                         f"by {T_END:g} s) against the rule's t*, relative"))
    return got
