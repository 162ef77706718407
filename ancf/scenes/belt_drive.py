"""A belt drive of any layout from a drive file (``ancf run belt-drive --file drive.toml``).

The file (:mod:`ancf.belts.drive_file`; keys, units and ranges in
:mod:`ancf.belts.drive_data`) becomes the belt model on N pulleys
(:mod:`ancf.belts.drive_model`: the 2D Dufva belt, ``belt.element = "dufva2d"``, or the
3D plate belt, ``"plate36"``), settled on its pulleys (``run.start = "settled"``) and
marched by the compiled generalised-alpha scheme (``belt.formulation = "ale"``: the
axially moving 2D belt, :mod:`ancf.belts.ale_march2d`), as ``belt2d`` and ``belt3d``: the
thesis drives' files (``examples/thesis_table_3_1.toml``, ``thesis_table_4_1.toml``)
give ``belt2d``'s and ``belt3d``'s numbers.  ``--set
section.key=value`` overrides a key of the file (``friction.mu=1.0``,
``pulleys.driven.inertia=0.5``).

Results: the sample times; per pulley its angular velocity and the belt's moment on it
(the friction's, counter-clockwise positive) at every sample, their means over every time
step of ``run.steady_window`` (the march's, :func:`ancf.belts.dynamics.simulate`: a
moment fluctuating faster than the samples does not alias into them), the slip over
the window (1 - its mean rim speed / the driver's, the driver the first prescribed
pulley; signed, rim speeds side x omega x radius) and the belt's largest penetration into
it at t_end; per span (pulley k to k + 1) the mean axial force
over its middle third at t_end and averaged over the samples of the steady window; the
axial force, the speed, the position and the contact forces (normal and friction per unit
length, summed over the pulleys) along the belt at t_end; per tensioner its arm's angle; the run
statistics.  The plate belt's axial force is the membrane's own (:mod:`ancf.belts.post3d`),
along the belt's edge z = 0 as ``belt3d`` samples it, with the contact forces per unit
length integrated across the width there.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ancf.belts.arm2d import BETA0, COORD, PULLEY
from ancf.belts.contact2d import NO_STATE, contact_forces_moving
from ancf.belts.drive_data import ROLES, element_modulus, time_law
from ancf.belts.drive_file import load
from ancf.belts import post3d, tracking3d
from ancf.belts.drive_model import build
from ancf.belts.dynamics import BeltOptions, simulate
from ancf.belts.path import PulleyPath
from ancf.belts.post2d import sample, sample_elements, span_tension
from ancf.belts.pretension import settle
from ancf.common.params import InputError, Param
from ancf.common.paths import REPO
from ancf.scenes import belt_common as bc
from ancf.scenes import sense
from ancf.scenes.base import (DYNAMIC_RESULTS, INT, NUM, STR, ReferenceFailed, Scene, SceneResult,
                              field, nullable, series)

DEFAULT_FILE = str(REPO / "examples" / "thesis_table_3_1.toml")
SEP = "; "  # between the overrides in params["set"]


#: the model choices of a drive file that sweeps and ``ancf recommend`` vary, as scene
#: parameters (resolved to the file's value when not given): parameter -> file key
MODEL_KEYS = {"n_elements": "belt.n_elements", "dt": "run.dt",
              "gauss_points": "contact.gauss_points"}


def _items(p: dict) -> list:
    """The file's overrides: ``set`` and the model parameters."""
    return (p["set"].split(SEP) if p["set"] else []) + [
        f"{key}={p[name]!r}" for name, key in MODEL_KEYS.items() if p.get(name) is not None]


def pulley_moments(drive, x, v, t: float, state=None, V=None) -> np.ndarray:
    """The belt's moment (np,) on each pulley at state (x, v), time t (s), N m: the
    contact kernel's T_p (Eq. 3.26's integral), counter-clockwise positive.  A friction
    law with a state takes ``state`` = (z (nel, ng, np), h): the state at the start of the
    step that ended at this sample and that step (s), the march's (the step's forces).
    ``V`` (nel, 6, 2) m/s: the elements' velocities, if not v's (the ALE march's)."""
    E = drive.element_coords(drive.belt(x))
    V = drive.element_coords(drive.belt(v)) if V is None else V
    npul, nel = drive.radii.size, E.shape[0]
    T = np.zeros(npul)
    o, odot = drive.moved(x, v, t)
    z, h = NO_STATE, 0.0
    if state is not None:
        z = np.zeros((2, *drive.w.shape, npul))
        z[0], h = state
    contact_forces_moving(E, V, drive.S0, drive.w, o, odot, drive.radii, drive.omegas(t, v),
                          drive.prm, z, h, False, np.zeros((nel, 12)), np.zeros((0, 12, 12)),
                          np.zeros((0, 12, 12)), np.zeros((0, npul, 12)), T,
                          np.zeros((npul, 0, 12)), np.zeros((npul, 0, 12)), np.zeros(npul))
    return T


def _spans(desc, window, last, coarse, tension) -> list:
    """Per span: from, to, tension at t_end and its mean over the window's samples, N;
    ``last`` the belt sampled at t_end, ``coarse(i)`` at sample i (4 points per element),
    ``tension(sampled, span)`` a span's tension from a sampled belt."""
    path = desc.path
    ends = [path(np.array([a, b]))[0] for _, a, b in path.pieces()[1::2]]
    names = [q.name for q in desc.pulleys]
    means = np.array([[tension(smp, e) for e in ends] for smp in map(coarse, window)])
    N = len(names)
    return [{"from": names[k], "to": names[(k + 1) % N],
             "tension_mean_N": float(np.mean(means[:, k])),
             "tension_N": tension(last, e)} for k, e in enumerate(ends)]


def _sample2d(drive, res, i: int, npts: int = 8):
    """The 2D belt at sample i (:func:`ancf.belts.post2d.sample`; the ALE march's at its
    elements' own material velocities)."""
    x, v, t = res.q[i], res.v[i], float(res.t[i])
    W = res.extra.get("element_velocities")
    if W is None:
        return sample(drive, x, v, t, npts=npts)
    E = drive.element_coords(drive.belt(x))
    return sample_elements(drive, E, W[i], drive.omegas(t, v), *drive.moved(x, v, t), npts)


def _end2d(desc, drive, res, window) -> dict:
    """The spans and the belt at t_end (:mod:`ancf.belts.post2d`, 8 points per element)."""
    R = float(drive.radii.min())
    last = _sample2d(drive, res, -1)
    spans = _spans(desc, window, last, lambda i: _sample2d(drive, res, i, npts=4),
                   lambda smp, span: span_tension(smp, span, R))
    return dict(spans=spans, belt_s_m=last.s.tolist(),
                axial_force_N=last.N.tolist(), speed_m_s=last.speed.tolist(),
                penetration_max_m=float(max(last.d.max(), 0.0)),
                belt_x_m=last.r[:, 0].tolist(), belt_y_m=last.r[:, 1].tolist(),
                normal_force_N_m=last.Fn.sum(axis=1).tolist(),
                friction_force_N_m=last.Ft.sum(axis=1).tolist())


def _end3d(desc, drive, res, window) -> dict:
    """The spans and the belt's edge z = 0 at t_end (:mod:`ancf.belts.post3d`, 20 points
    per element; the membrane's axial force)."""
    x, v, t = res.q[-1], res.v[-1], float(res.t[-1])
    last = post3d.line_sample(drive, x, v)
    spans = _spans(desc, window, last,
                   lambda i: post3d.line_sample(drive, res.q[i], res.v[i], npts=4),
                   lambda smp, span: post3d.span_tension(drive, smp, span))
    state = res.extra.get("friction_state", [None])[-1]
    normal, friction = post3d.width_contact(drive, x, v, t, state=state)
    depth = post3d.contact_sample(drive, x, v, t, state)[1]
    return dict(spans=spans, belt_s_m=last["s"].tolist(),
                axial_force_N=last["tension_membrane_N"].tolist(),
                speed_m_s=last["speed"].tolist(),
                penetration_max_m=float(max(depth.max(), 0.0)),
                belt_x_m=last["r"][:, 0].tolist(), belt_y_m=last["r"][:, 1].tolist(),
                normal_force_N_m=normal.tolist(), friction_force_N_m=friction.tolist())


def _moments(desc, drive, res) -> np.ndarray:
    """The belt's moment on every pulley at every sample (samples, np), N m."""
    states = res.extra.get("friction_state", [None] * res.t.size)
    if desc.belt["element"] == "plate36":
        return np.array([post3d.pulley_moments(drive, x, v, float(t), z)
                         for x, v, t, z in zip(res.q, res.v, res.t, states)])
    W = res.extra.get("element_velocities", [None] * res.t.size)
    return np.array([pulley_moments(drive, x, v, float(t), z, V)
                     for x, v, t, z, V in zip(res.q, res.v, res.t, states, W)])


def _pulleys(desc, drive, res, penetration) -> list:
    """Per pulley its speeds, moments, signed slip and the belt's largest penetration
    into it at t_end (``penetration`` (np,), m)."""
    W = np.array([drive.omegas(float(t), v) for t, v in zip(res.t, res.v)])
    T = _moments(desc, drive, res)
    mean, moment = res.extra["step_means"]
    d = next(i for i, q in enumerate(desc.pulleys) if q.law == "prescribed")
    rim = np.array([q.side for q in desc.pulleys]) * mean * drive.radii
    slip = 1.0 - rim / rim[d] if rim[d] != 0 else np.full(rim.size, np.nan)
    return [{"name": q.name, "omega": W[:, i].tolist(), "torque_Nm": T[:, i].tolist(),
             "omega_mean": float(mean[i]), "torque_mean_Nm": float(moment[i]),
             "slip": float(slip[i]), "penetration_max_m": float(penetration[i])}
            for i, q in enumerate(desc.pulleys)]


def _arms(drive, res, window) -> list:
    """Per tensioner: its arm's angle (rad) at every sample and its mean over the window."""
    out = []
    for row in drive.rig.arms:
        angle = row[BETA0] + res.q[:, drive.n + int(row[COORD])]
        out.append({"name": drive.rig.names[int(row[PULLEY])], "angle_rad": angle.tolist(),
                    "angle_mean_rad": float(angle[window].mean())})
    return out


def _results(desc, drive, res) -> dict:
    window = np.flatnonzero(res.t >= res.t[-1] - desc.run["steady_window"] - 1e-12)
    out = {"times": res.t.tolist(),
           "pulleys": _pulleys(desc, drive, res, bc.penetrations(drive, res)),
           "arms": _arms(drive, res, window)}
    end = _end3d if desc.belt["element"] == "plate36" else _end2d
    out.update(end(desc, drive, res, window))
    if desc.belt["element"] == "plate36":
        for pulley, more in zip(out["pulleys"], tracking3d.histories(drive, res)):
            pulley.update(more)
    return out


def _ale(drive, t_out, opt, x0, progress, mean_from):
    """:func:`ancf.belts.ale_march2d.simulate_ale` (scipy: on use only), from the belt laid
    on its path where it was not settled."""
    from ancf.belts.ale_march2d import simulate_ale
    x0 = drive.state(drive.q0) if x0 is None else x0
    return simulate_ale(drive, t_out, opt, x0, progress=progress, mean_from=mean_from)


def run(p: dict) -> SceneResult:
    desc = load(p["file"], _items(p))
    drive, r = tracking3d.align(build(desc), desc), desc.run
    x0, pre = settle(drive) if r["start"] == "settled" else (None, None)
    opt = BeltOptions(dt=r["dt"], rho_inf=r["rho_inf"], newton_tol=r["newton_tol"],
                      refresh_ratio=r["refresh_ratio"], newton_accept=r["newton_accept"],
                      refresh=r["refresh"], give_up=r["give_up"],
                      max_steps=r["max_steps"])
    march = simulate if desc.belt["formulation"] == "lagrangian" else _ale
    res = march(drive, bc.times(r), opt, x0=x0 if pre is None or pre.converged else None,
                progress=bc.progress("belt-drive", r["t_end"]),
                mean_from=r["t_end"] - r["steady_window"])
    if pre is not None and not pre.converged:
        res.converged, res.message = False, f"pre-tension: {pre.message}"
    results = _results(desc, drive, res) if res.converged else {
        "times": res.t.tolist(), "pulleys": None, "arms": None, "spans": None, "belt_s_m": None,
        "axial_force_N": None, "speed_m_s": None, "penetration_max_m": None, "belt_x_m": None,
        "belt_y_m": None, "normal_force_N_m": None, "friction_force_N_m": None}
    results.update(res.stats(), samples=int(res.t.size), t_reached=float(res.t[-1]),
                   contact_pairs=res.extra["contact_pairs"], total_dofs=drive.n + drive.k,
                   pretension_iterations=0 if pre is None else pre.iterations)
    return SceneResult(res.converged, res.message, results,
                       extra={"result": res, "drive": drive, "description": desc})


def warn(p: dict, res: SceneResult) -> list:
    """The physical-sense checks of every belt drive (:func:`ancf.scenes.sense.drive` on
    :func:`sense_drive`'s numbers) and a penetration beyond half the pre-stretch per wrap
    (as belt2d)."""
    desc = res.extra.get("description")
    if desc is None:
        return []
    out = sense.drive(sense_drive(desc, res.results if res.converged else None))
    pre = -desc.belt["prestretch"] * desc.path.length / (2 * np.pi)
    pen = res.results.get("penetration_max_m") if res.converged else None
    if pen is not None and pre > 0 and pen > 0.5 * pre:
        out.append(f"penetration {1e3 * pen:.2g} mm = {pen / pre:.2g} x the pre-stretch per "
                   f"wrap ({1e3 * pre:.2g} mm): contact.k_p = {desc.contact['k_p']:g} N/m^2 is "
                   "too soft for the pre-tension; raise it")
    return out


def pretension(desc) -> float:
    """The belt's pre-tension T0 (N) on its path at rest, by the element's axial law at the
    stretch path / reference length (the plate belt's membrane: the uniaxial Green law on
    E h b; the Dufva belt's: E A alpha1 with its ``axial_strain``)."""
    b = desc.belt
    lam = desc.path.length / b["length"]
    if b["element"] == "plate36":
        return sense.membrane_force(b["E"] * b["h"] * b["b"], lam)
    k = element_modulus(b) * b["b"] * b["h"] * b["alpha1"]
    return sense.membrane_force(k, lam) if b["axial_strain"] == "green" else k * (lam - 1.0)


def _ramps(desc) -> dict:
    """The end time (s) of every pulley law that changes with time: a ramp's or step's t1,
    a table's last row."""
    out = {}
    for q in desc.pulleys:
        ends = [q.params[k] for k in ("t1",) if k in q.params] + [
            q.params[k][-1][0] for k in ("speed_table", "load_table") if k in q.params]
        if ends:
            out[f"{q.name}'s law"] = max(ends)
    return out


def _arm_into(desc, i: int) -> float:
    """+1 if turning tensioner i's arm counter-clockwise lengthens the belt's path (presses
    its pulley into the belt), else -1."""
    q, path = desc.pulleys[i], desc.path
    P, c = np.asarray(q.params["pivot"]), np.asarray(q.centre)
    a = np.arctan2(*(c - P)[::-1]) + 1e-6
    moved = list(path.pulleys)
    moved[i] = replace(moved[i], centre=tuple(P + q.params["arm_length"]
                                              * np.array([np.cos(a), np.sin(a)])))
    return float(np.sign(PulleyPath(moved).length - path.length))


def sense_drive(desc, results: dict | None) -> sense.Drive:
    """The drive's numbers for :func:`ancf.scenes.sense.drive`: from the description, and
    from the ``results`` of a finished run (None: none)."""
    r, b, t_end = desc.run, desc.belt, desc.run["t_end"]
    final = [float(time_law(q)(np.array([t_end]))[0]) for q in desc.pulleys]
    got = results or {}
    ran = got.get("pulleys") or [{}] * len(desc.pulleys)
    times = np.asarray(got.get("times", []), dtype=float)
    sel = times >= t_end - r["steady_window"] - 1e-12 if times.size else times.astype(bool)
    pulleys = tuple(sense.Pulley(
        q.name, q.law, q.radius + b["contact_offset"], q.side, wrap,
        load=f if q.law == "driven" else 0.0, omega=f if q.law == "prescribed" else 0.0,
        omega_mean=o.get("omega_mean"), trace=tuple(np.asarray(o.get("omega", []))[sel])
        if o else (), penetration=o.get("penetration_max_m"))
        for q, wrap, f, o in zip(desc.pulleys, desc.path.wraps, final, ran))
    arms = tuple(sense.Arm(q.name, q.params["arm_preload"], _arm_into(desc, i))
                 for i, q in enumerate(desc.pulleys) if ROLES[q.law].arm)
    if got.get("arms"):
        arms = tuple(replace(a, turn=float(np.max(np.abs(np.asarray(o["angle_rad"])
                                                         - o["angle_rad"][0]))))
                     for a, o in zip(arms, got["arms"]))
    area = b["b"] * b["h"]
    k = (b["E"] if b["element"] == "plate36" else element_modulus(b)) * area
    return sense.Drive(pulleys=pulleys, T0=pretension(desc), k=k, rhoA=b["rho"] * area,
                       mu=desc.friction["mu"], t_end=t_end, window=r["steady_window"],
                       ramps=_ramps(desc), arms=arms, finished=bool(got.get("spans")),
                       spans={f"{s['from']}-{s['to']}": s["tension_mean_N"]
                              for s in got.get("spans") or []},
                       times=tuple(times[sel]))


@dataclass(frozen=True)
class FileScene(Scene):
    """A scene whose input is a drive file and its overrides: ``resolve`` takes ``file``,
    the model parameters (:data:`MODEL_KEYS`, also given as their file keys) and
    ``section.key`` overrides, reads and validates the file; the model parameters resolve
    to the values the file (with its overrides) sets."""

    def resolve(self, overrides: dict | None = None) -> dict:
        overrides = {k: str(v) for k, v in (overrides or {}).items()}
        path = overrides.pop("file", DEFAULT_FILE)
        joined = overrides.pop("set", "")  # resolved parameters resolve to themselves
        overrides = {**dict(item.split("=", 1) for item in joined.split(SEP) if "=" in item),
                     **overrides}
        model = {}
        for name, key in MODEL_KEYS.items():
            given = [v for v in (overrides.pop(name, None), overrides.pop(key, None))
                     if v is not None]
            if len(set(given)) > 1:
                raise InputError(f"{key}: given twice ({name} = {given[0]}, {key} = "
                                 f"{given[1]}); allowed: one value")
            model[name] = given[0] if given else None
        p = {"file": path, "set": SEP.join(f"{k}={v}" for k, v in overrides.items())}
        desc = load(p["file"], _items(p) + [f"{MODEL_KEYS[k]}={v}" for k, v in model.items()
                                            if v is not None])  # InputError naming the key
        return {**p, "n_elements": int(desc.belt["n_elements"]), "dt": float(desc.run["dt"]),
                "gauss_points": int(desc.contact["gauss_points"])}


def description(p: dict):
    """The drive description (:class:`ancf.belts.drive_data.DriveDescription`) of the
    resolved parameters ``p``."""
    return load(p["file"], _items(p))


def steady_reference(p: dict) -> dict:
    """:func:`ancf.belts.drive_steady.steady_reference` of the drive of the resolved
    parameters ``p``; InputError (a ValueError) where the steady belt does not exist."""
    from ancf.belts.drive_steady import steady_reference as reference  # scipy: on use only
    return reference(description(p))


def _drive_steady(p):
    try:
        return steady_reference(p)
    except (InputError, ValueError) as exc:
        raise ReferenceFailed(f"steady reference (analytic/belt_steady.py): {exc}") from None


def _drive_error(res, ref, p):
    """max of the span tensions' |T_mean − T_ref| / |T_ref| and the free pulleys'
    |omega_mean − omega_ref| / |omega_ref| (every pulley but the prescribed and fixed)."""
    spans = [abs(a["tension_mean_N"] - b["tension_N"]) / abs(b["tension_N"])
             for a, b in zip(res["spans"], ref["spans"])]
    speeds = [abs(a["omega_mean"] - b["omega"]) / abs(b["omega"])
              for a, b in zip(res["pulleys"], ref["pulleys"])
              if b["law"] not in ("prescribed", "fixed") and b["omega"]]
    return float(max(spans + speeds))


#: the drive file's model parameters (ancf.scenes.belt_drive.MODEL_KEYS)
DRIVE_KNOBS = ("n_elements", "dt", "gauss_points")


#: the model grids per belt element of the file (contact points: Gauss points along a
#: Dufva element, n x n points over a plate)
DRIVE_GRIDS = {"dufva2d": ({"n_elements": [30, 45, 60], "gauss_points": [5, 7]},),
               "plate36": ({"n_elements": [20, 30, 40], "gauss_points": [25, 49]},)}


def _drive_grids(params: dict) -> tuple:
    return DRIVE_GRIDS[description(params).belt["element"]]


RESULTS = {
    **DYNAMIC_RESULTS,
    "pulleys": field("array", "per pulley, in belt order (null when the run stopped)",
                     items="object", nullable=True, keys={
        "name": field(STR, "pulley name"),
        "omega": series("angular velocity, counter-clockwise positive, rad/s"),
        "torque_Nm": series("the belt's moment on it (friction), counter-clockwise "
                            "positive, N m"),
        "omega_mean": field(NUM, "mean angular velocity over run.steady_window (over every "
                                 "time step of it), rad/s"),
        "torque_mean_Nm": field(NUM, "mean of the belt's moment on it over every time "
                                     "step of run.steady_window, N m"),
        "slip": field(NUM, "1 - its mean rim speed / the driver's (the first prescribed "
                           "pulley) over the window, signed: rim speed = side x omega_mean x "
                           "radius along the belt's running direction, so above 1 it turns "
                           "against its belt and below 0 it runs ahead of the driver"),
        "penetration_max_m": field(NUM, "the belt's largest penetration into it at t_end "
                                        "(<= 0: no contact over its wrap), m"),
        "lateral_position_m": field("array", "the plate belt's mid-width position along its "
                                    "axis from its mid-face at every sample (mean over the "
                                    "contact points, ancf.belts.tracking3d; null off "
                                    "contact), m", required=False, items=NUM),
        "axial_force_N": field("array", "the plate belt's contact force from it along its "
                               "axis at every sample (summed over the contact points, with "
                               "its flanges'), N", required=False, items=NUM),
        "flange_force_N": field("array", "its flanges' force on the plate belt's edges along "
                                "its axis at every sample (ancf.belts.flange3d; 0 without "
                                "flanges), N", required=False, items=NUM)}),
    "arms": field("array", "per tensioner, in belt order (null when the run stopped)",
                  items="object", nullable=True, keys={
        "name": field(STR, "the tensioner pulley's name"),
        "angle_rad": series("its arm's angle (centre - pivot, counter-clockwise from x), "
                            "rad"),
        "angle_mean_rad": field(NUM, "its mean over run.steady_window, rad")}),
    "spans": field("array", "per span (pulley k to k + 1), in belt order (null when the "
                   "run stopped)", items="object", nullable=True, keys={
        "from": field(STR, "pulley the span leaves"), "to": field(STR, "pulley it reaches"),
        "tension_mean_N": field(NUM, "mean axial force over its middle third, averaged "
                                     "over the samples of run.steady_window, N"),
        "tension_N": field(NUM, "the same at t_end, N")}),
    "belt_s_m": field("array", "belt arc coordinate (reference length from node 0) of "
                      "the points along the belt (the plate belt: along its edge z = 0), "
                      "m", nullable=True, items=NUM),
    "axial_force_N": field("array", "axial force at those points at t_end, N",
                           nullable=True, items=NUM),
    "speed_m_s": field("array", "belt speed at those points at t_end, m/s", nullable=True,
                       items=NUM),
    "penetration_max_m": nullable("largest penetration of the belt's centreline sample "
                                  "points (the plate belt: its mid surface's contact "
                                  "points) into a pulley at t_end, m"),
    "belt_x_m": field("array", "x of those points at t_end, m", nullable=True, items=NUM),
    "belt_y_m": field("array", "y of those points at t_end, m", nullable=True, items=NUM),
    "normal_force_N_m": field("array", "the pulleys' normal force on the belt per unit "
                              "length at those points at t_end (summed over the pulleys; "
                              "0 off contact), N/m", nullable=True, items=NUM),
    "friction_force_N_m": field("array", "the friction force on the belt per unit length "
                                "along the pulley's counter-clockwise tangent at those "
                                "points at t_end, summed over the pulleys, N/m", nullable=True,
                                items=NUM),
    "total_dofs": field(INT, "belt coordinates plus the free pulleys' angles"),
    "contact_pairs": field(INT, "element-pulley pairs whose Gauss points were evaluated "
                                "(after the bounding test), summed over force evaluations"),
    "pretension_iterations": field(INT, "Newton iterations of the static pre-tension "
                                        "(0: start = laid)")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import Reference, SceneSpec
    refs = {"steady": Reference(
        "steady", "analytic",
        "steady extensible belt on the drive's layout (`analytic/belt_steady.py`: Bechtel's "
        "string with the centrifugal term around the N pulleys, Coulomb stick and creep arcs, "
        "the laws' final values); error = max of the spans' |T_mean − T_ref| / |T_ref| (mean "
        "over run.steady_window and the span's middle third) and the free pulleys' |ω_mean − "
        "ω_ref| / |ω_ref|. It includes the model gap (creep-rate against Coulomb friction, "
        "the penalty's penetration: 1-2 % on the shipped examples) and whatever of the "
        "start-up the window still holds", _drive_steady, _drive_error)}
    grids = DRIVE_GRIDS["dufva2d"]
    return SceneSpec("belt-drive", DRIVE_KNOBS, frozenset({"axial", "bending", "inertia",
                                                          "contact"}),
                     refs, "steady", report_grids=grids, recommend_grids=grids, dynamic=True,
                     grids_for=_drive_grids,
                     provides=frozenset({"axial", "bending", "shear", "large-rotation",
                                         "inertia", "contact"}),
                     notes="A drive file (`--set file=PATH`; default the thesis drive) "
                           "against the steady reference on its layout.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 140
SCENE = FileScene(
    "belt-drive",
    "A belt drive of any layout from a drive file (--file drive.toml; --set section.key=value): "
    "Dufva belt (2D) or thin plate belt (3D) on N pulleys, penalty contact with friction by "
    "name (creep-rate, coulomb, bristle), prescribed, driven, "
    "idler, tensioner (2D) and fixed pulleys, on the belt's inner side or its back.",
    (Param("file", DEFAULT_FILE, str, doc="the TOML drive file (ancf run belt-drive --file)"),
     Param("set", "", str, doc=f"the drive file's overrides applied, '{SEP}'-separated "
           "(--set section.key=value), the model parameters below apart"),
     Param("n_elements", None, int, doc="belt elements (the file's belt.n_elements unless "
           "given)"),
     Param("dt", None, float, "s", "time step (the file's run.dt unless given)"),
     Param("gauss_points", None, int, doc="contact points per element (the file's "
           "contact.gauss_points unless given)")),
    run, warn=warn, swept=False,
    results=RESULTS, study=study)
