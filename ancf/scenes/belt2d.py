"""Two-pulley belt drive (thesis section 3.3, Fig. 3.6, Table 3.1, Eqs 3.29-3.30).

A closed belt of ``n_elements`` Dufva elements (alpha1, alpha2) laid on the wrapped
path of two pulleys, pre-tensioned by a reference length shorter than the path,
starting at rest.  The driver (left) turns counter-clockwise at the angular velocity
of Eq. 3.29 (ramp from t = 0.05 s to ``omega_final`` at 0.6 s); the driven pulley
(inertia ``inertia``) turns under the belt's friction against the opposing torque
of Eq. 3.30 (``Ta_max``; 0: none).  Contact: distributed penalty with tri-linear
creep-rate friction at ``gauss_points`` points per element (:mod:`ancf.belts.contact2d`).

Results: the angular velocities of both pulleys sampled every ``output_dt``, the
vertical positions of the span midpoints, the span tensions at ``t_end`` (mean
axial force over each span's middle third) and the largest penetration into a
pulley at ``t_end``, the steady ratio of the angular
velocities, the model size and the run statistics.
"""
from __future__ import annotations

import math

import numpy as np

from ancf.belts.drive2d import BeltDrive, BeltSpec
from ancf.belts.friction import LAW
from ancf.belts.pulleys import T1
from ancf.belts.post2d import sample, span_midpoint, span_tension, spans
from ancf.common.inputs import MAX_STEPS
from ancf.scenes import belt_common as bc
from ancf.scenes import sense
from ancf.common.params import Param
from ancf.scenes.base import (DYNAMIC_RESULTS, INT, Scene, SceneResult, field, nullable,
                              series)
from ancf.belts.bdf import simulate_bdf

INTEGRATORS = ("generalized-alpha", "bdf")
PENETRATION_WARN = 0.5  # x the pre-stretch per wrap (see warn)
STEADY_WINDOW = 0.1  # s before t_end over which the steady speed ratio is averaged


def params() -> tuple:
    return (bc.belt_params(n_elements=20, E=1e8, alpha2=0.01) + bc.pulley_params()
            + bc.contact_params(gauss_points=7) + (
        Param("inertia", 0.1, float, "kg m^2", "driven pulley moment of inertia", lo=0,
              lo_open=True, hi=1e3),
        Param("omega_final", 12.0, float, "rad/s", "driver's final angular velocity (Eq. 3.29; "
              "counter-clockwise)", lo=0, hi=1000),
        Param("Ta_max", 0.0, float, "N m", "final opposing torque on the driven pulley "
              "(Eq. 3.30; 0: none)", lo=0, hi=1e4),
        Param("start", "settled", str, doc="initial state: 'settled' = at rest on the pulleys "
              "after a static frictionless pre-tension solve; 'laid' = on the wrapped path, as in "
              "the thesis", choices=("settled", "laid")),
        Param("integrator", "generalized-alpha", str, doc="time integrator", choices=INTEGRATORS),
        Param("rtol", 1e-6, float, "-", "relative tolerance (bdf)", lo=1e-12, hi=0.1),
        Param("atol", 1e-9, float, "-", "absolute tolerance (bdf; m, m/s, rad, rad/s)", lo=1e-15,
              hi=1.0),
    ) + bc.march_params(2.5e-4, "time step (Exudyn's belt example uses the same)", 1.0) + (
        Param("max_steps", 400_000, int, doc="step budget (beyond it: not converged)", lo=1,
              hi=MAX_STEPS),
    ))


def check(p: dict) -> None:
    bc.check_geometry(p)
    bc.check_steps(p)


def spec(p: dict) -> BeltSpec:
    return BeltSpec(path=bc.path_of(p), belt_length=bc.belt_length(p),
                    n_elements=p["n_elements"], E=p["E"], nu=p["nu"], rho=p["rho"], b=p["b"],
                    h=p["h"], ks=p["ks"], alpha1=p["alpha1"], alpha2=p["alpha2"],
                    nx=p["elastic_points"], k_p=p["k_p"], c_p=p["c_p"],
                    friction=(LAW, p["mu"], p["nu_s"]), gauss_points=p["gauss_points"],
                    inertia=p["inertia"], omega_final=p["omega_final"], Ta_max=p["Ta_max"])


def _steady_ratio(t, wd, wn, t_end) -> float | None:
    sel = (t >= t_end - STEADY_WINDOW) & (wd > 0)
    return float(np.mean(wn[sel]) / np.mean(wd[sel])) if sel.any() else None


def _at_end(drive, res, p) -> dict:
    """Span tensions at t_end and averaged over the last STEADY_WINDOW, model size."""
    sp, R = spans(drive.spec.path), min(p["R1"], p["R2"])
    smp = sample(drive, res.q[-1], res.v[-1], float(res.t[-1]))
    in_contact = (smp.d >= 0).any(axis=1).reshape(drive.mesh.n_elements, -1).any(axis=1)
    window = np.flatnonzero(res.t >= res.t[-1] - STEADY_WINDOW - 1e-12)
    mean = {k: [] for k in sp}
    for i in window:
        s_i = sample(drive, res.q[i], res.v[i], float(res.t[i]), npts=4)
        for k, span in sp.items():
            T = span_tension(s_i, span, R)
            if math.isnan(T):  # no point of 4 per element in the middle third (few elements)
                T = span_tension(sample(drive, res.q[i], res.v[i], float(res.t[i])), span, R)
            mean[k].append(T)
    return {"tension_tight_N": span_tension(smp, sp["tight"], R),
            "tension_slack_N": span_tension(smp, sp["slack"], R),
            "tension_tight_mean_N": float(np.mean(mean["tight"])),
            "tension_slack_mean_N": float(np.mean(mean["slack"])),
            "penetration_max_m": float(max(smp.d.max(), 0.0)),
            "contact_dofs": int(np.unique(drive.mesh.dofmap[in_contact]).size),
            "total_dofs": drive.n + 1}


def _midpoints(drive, res, p) -> dict:
    sp, R = spans(drive.spec.path), min(p["R1"], p["R2"])
    mids = {k: [] for k in sp}
    for x, v, t in zip(res.q, res.v, res.t):
        smp = sample(drive, x, v, float(t), npts=4)
        for k, span in sp.items():
            mids[k].append(float(span_midpoint(smp, span, R)[1]))
    return {"mid_tight_y_m": mids["tight"], "mid_slack_y_m": mids["slack"]}


def _march(p: dict):
    """march(drive, x0) of the chosen integrator (x0 None: the laid belt)."""
    alpha = bc.alpha_march(p, "belt2d")

    def march(drive, x0):
        if p["integrator"] != "bdf":
            return alpha(drive, x0)
        x0 = drive.state(drive.q0) if x0 is None else x0
        return simulate_bdf(drive, bc.times(p), p["rtol"], p["atol"], x0, p["max_steps"])
    return march


def _results(p: dict):
    """results_of(drive, res, wd, wn) of :func:`ancf.scenes.belt_common.run`."""
    def results_of(drive, res, wd, wn) -> dict:
        ok = res.converged
        out = {"omega_ratio_steady": _steady_ratio(res.t, wd, wn, p["t_end"]) if ok else None}
        out.update(_midpoints(drive, res, p))
        out.update(_at_end(drive, res, p) if ok else
                   dict.fromkeys(("tension_tight_N", "tension_slack_N", "tension_tight_mean_N",
                                  "tension_slack_mean_N", "penetration_max_m", "contact_dofs",
                                  "total_dofs")))
        return out
    return results_of


def run(p: dict) -> SceneResult:
    return bc.run(BeltDrive(spec(p)), p, _march(p), _results(p), keep_unsettled=False)


def prestretch(spec) -> float:
    """(wrapped path - belt length) / (2 pi), m: the penetration on both pulleys that
    would shorten the path to the belt's length and release its pre-tension."""
    return (spec.path.length - spec.belt_length) / (2 * math.pi)


def warn(p: dict, res: SceneResult) -> list:
    """The penetration check (:func:`penetration`) and the physical-sense checks of
    :mod:`ancf.scenes.sense` (:func:`sense_checks`)."""
    return penetration(p, res) + sense_checks(p, res)


def sense_checks(p: dict, res: SceneResult) -> list:
    """The belt drives' physical-sense checks (:func:`ancf.scenes.sense.drive`) on the
    thesis drive's numbers (:func:`ancf.scenes.belt_common.sense_drive`)."""
    k = p["E"] * p["b"] * p["h"]
    T0 = sense.membrane_force(k, bc.path_of(p).length / bc.belt_length(p))
    r = res.results
    spans = ({"tight": r["tension_tight_mean_N"], "slack": r["tension_slack_mean_N"]}
             if res.converged and r.get("tension_tight_mean_N") is not None else None)
    return sense.drive(bc.sense_drive(p, res, bc.path_of(p), T0, k, p["b"] * p["h"],
                                      STEADY_WINDOW, {"driver ramp (Eq. 3.29)": T1}, spans))


def penetration(p: dict, res: SceneResult) -> list:
    """Penetration beyond PENETRATION_WARN x the pre-stretch per wrap: the penalty is too
    soft for the pre-tension (the drive then slips for want of belt tension)."""
    pen, drive = res.results.get("penetration_max_m"), res.extra.get("drive")
    if pen is None or drive is None or prestretch(drive.spec) <= 0:
        return []
    pre = prestretch(drive.spec)
    if pen <= PENETRATION_WARN * pre:
        return []
    return [f"penetration {1e3 * pen:.2g} mm = {pen / pre:.2g} x the pre-stretch per wrap "
            f"((path - belt_length)/2 pi = {1e3 * pre:.2g} mm): k_p = {p['k_p']:g} N/m^2 is too "
            "soft for the pre-tension; raise k_p"]


BELT_KNOBS = ("n_elements", "gauss_points", "elastic_points", "integrator", "dt", "rho_inf",
              "newton_tol", "max_steps")


BELT_WINDOW = 0.2  # s before t_end over which the driven speed is averaged


def _mean_driven(res) -> float:
    t, w = np.asarray(res["times"], float), np.asarray(res["omega_driven"], float)
    return float(w[t >= t[-1] - BELT_WINDOW - 1e-12].mean())


def _belt_error(res, ref, p):
    """max of the relative errors of the driven speed averaged over the last BELT_WINDOW
    seconds and of the tight and slack span tensions averaged over the scene's last 0.1 s
    (at one instant they carry the phase of the span and pulley oscillations)."""
    if res.get("tension_tight_mean_N") is None or float(res["times"][-1]) < ref["times"][-1] - 1e-9:
        return float("nan")
    errs = [abs(_mean_driven(res) - _mean_driven(ref)) / abs(_mean_driven(ref))]
    errs += [abs(res[k] - ref[k]) / abs(ref[k])
             for k in ("tension_tight_mean_N", "tension_slack_mean_N")]
    return max(errs)


#: the belt drive's self-reference (its 80-element check is stored with it)
BELT_FINE = {"n_elements": 120, "gauss_points": 11, "elastic_points": 5,
             "integrator": "generalized-alpha", "dt": 1.25e-4, "newton_tol": 1e-10}


def _no_slip(p):
    return {"omega_ratio": p["R1"] / p["R2"]}


def _slip_error(res, ref, p):
    """|omega_ratio_steady - R1/R2| / (R1/R2): the slip of the drive."""
    return abs(res["omega_ratio_steady"] - ref["omega_ratio"]) / ref["omega_ratio"]


RESULTS = {
    **DYNAMIC_RESULTS,
    "omega_driver": series("driver angular velocity (Eq. 3.29), rad/s"),
    "omega_driven": series("driven pulley angular velocity, rad/s"),
    "omega_ratio_steady": nullable("mean omega_driven / mean omega_driver over the last "
                                   "0.1 s (null before the driver turns)"),
    "mid_tight_y_m": series("tight (upper) span: where the belt crosses the span's "
                            "perpendicular bisector, y, m"),
    "mid_slack_y_m": series("slack (lower) span: the same, m"),
    "tension_tight_N": nullable("tight span: mean axial force over its middle third at "
                                "t_end, N"),
    "tension_slack_N": nullable("slack span: the same, N"),
    "tension_tight_mean_N": nullable("tight span tension averaged over the samples of the "
                                     "last 0.1 s (the instantaneous one carries the span "
                                     "and pulley oscillations), N"),
    "tension_slack_mean_N": nullable("slack span: the same, N"),
    "penetration_max_m": nullable("largest penetration of the belt's centreline sample "
                                  "points into a pulley at t_end, m"),
    "contact_dofs": field(INT, "belt coordinates of the elements touching a pulley at t_end",
                          nullable=True),
    "total_dofs": field(INT, "belt coordinates plus the driven pulley's angle", nullable=True),
    "contact_pairs": field(INT, "element-pulley pairs whose Gauss points were evaluated "
                                "(after the bounding test), summed over force evaluations"),
    "pretension_iterations": field(INT, "Newton iterations of the static pre-tension "
                                        "(0: start = laid)")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import Reference, SceneSpec, relative, self_reference
    refs = {"self": self_reference(
        "belt2d", BELT_FINE, ("times", "omega_driven", "tension_tight_mean_N",
                              "tension_slack_mean_N"),
        _belt_error,
        "converged self-reference: 120 elements, 11 contact points, generalized-α, dt = "
        "1.25e-4 s, Newton tolerance 1e-10 (cached, with an 80-element run's error against it "
        "as self_check_error); "
        f"error = max of the relative errors of the driven speed averaged over the last "
        f"{BELT_WINDOW:g} s and of the tight and slack span tensions averaged over the last "
        "0.1 s",
        check={"n_elements": 80}, knobs=BELT_KNOBS,
        measure="relative error of driven speed, span tensions"),
            "no-slip": Reference(
                "no-slip", "analytic",
                "the inextensible belt without slip: ω_driven / ω_driver = R1/R2; error = "
                "|omega_ratio_steady − R1/R2| / (R1/R2), the slip (creep and spin-up lag) "
                "averaged over the last 0.1 s", _no_slip, _slip_error,
                measure="slip |ω ratio / (R1/R2) − 1|")}
    grids = ({"n_elements": [10, 20, 40, 80], "gauss_points": [5, 7, 11],
              "integrator": ["generalized-alpha"], "dt": [1e-3, 5e-4, 2.5e-4]},
             {"n_elements": [20], "gauss_points": [7], "integrator": ["generalized-alpha"],
              "dt": [2.5e-4], "newton_tol": [1e-4, 1e-5]})
    needs = frozenset({"axial", "bending", "large-rotation", "inertia", "contact"})
    return SceneSpec("belt2d", BELT_KNOBS, needs, refs, "self", report_grids=grids, recommend_grids=grids, dynamic=True,
                     provides=bc.BELT_PHYSICS | {"inertia", "contact"},
                     notes="Two-pulley belt drive (thesis 3.3, Table 3.1, no opposing torque) "
                           "against a converged self-reference.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 70
SCENE = Scene(
    "belt2d",
    "Two-pulley belt drive: Dufva belt elements, penalty contact with creep-rate friction, "
    "driver ramp Eq. 3.29, driven pulley with inertia and opposing torque (thesis 3.3).",
    params(), run, check, warn=warn,
    results=RESULTS, study=study)
