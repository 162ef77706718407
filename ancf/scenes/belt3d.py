"""Three-dimensional belt drive of thin plates (thesis 4.6, Table 4.1, Figs 4.10-4.18).

A closed belt of ``n_elements`` thin ``plate36`` elements (:mod:`ancf.belts.drive3d`)
on two equal pulleys ``R`` apart by pi R (Table 4.1: l_s = pi R, belt 4 pi R),
penalty contact with creep-rate friction at ``contact_points`` points per element
(:mod:`ancf.belts.contact3d`), driver ramp Eq. 3.29 (``t0`` to ``t1``, ``omega_final``),
opposing torque Eq. 4.47 on the driven pulley (inertia ``inertia``).

``model`` picks Table 4.1's column as the defaults of every other parameter:
Model 1 (R 0.1 m, 16 plates, E 1e7 Pa, bending on) is pre-tensioned by moving the
driver by ``u0`` = 2.5 mm (Eq. 4.46) with a belt as long as the path; Model 2 (R
0.05 m, 20 plates, E 1.6667e6 Pa, bending off) by a belt shorter than the path,
whose reference length L0 makes the membrane's axial force in a free, uniaxially
stretched belt equal to ``T_i`` = 50 N: E h w lambda (lambda^2 - 1) / 2 = T_i
(plane stress with free edges: S_xx = E E_xx), L0 = (P - 2 pi d) / lambda with d the
penetration under that tension (:func:`belt_length`).  Model 2 starts
from the belt settled statically on its pulleys (``start``), Model 1 from the laid
belt (it is unstressed until the driver moves).

Results at ``t_end`` along the belt edge (y = 0; 20 points per element, as the
thesis samples): the span means of the tension from each strain measure
(``strain_measure`` picks the one reported as ``T_tight_N`` / ``T_slack_N``; all
are in ``tensions``) and of the membrane's own axial force, the span speeds, the
driven slip averaged over the last ``steady_window``, the torque the span tensions
carry (T_tight - T_slack) R and the moment of the friction forces on the driven
pulley (the integral of Eq. 4.45's friction).
"""
from __future__ import annotations

import math

import numpy as np

from ancf.belts.drive3d import Belt3DDrive, Belt3DSpec
from ancf.belts.friction import LAW
from ancf.belts.post3d import MEASURES, end_state
from ancf.belts.path import TwoPulleyPath
from ancf.belts.contact3d import SUPPORTED_RULES
from ancf.common.inputs import MAX_STEPS, following
from ancf.scenes import belt_common as bc
from ancf.scenes import sense
from ancf.scenes.belt_common import check_belt_length, check_steps, march_params
from ancf.common.params import InputError, Param
from ancf.scenes.base import (DYNAMIC_RESULTS, INT, NUM, Scene, SceneResult, field, nullable,
                              series)

#: Table 4.1 (n_elements, E, u0, T_i, bending: section 4.6's text)
MODELS = {
    1: dict(R=0.10, width=0.08, h=0.01, k_p=1e7, c_p=2000.0, nu_s=1e5, mu=1.2, rho=1036.0,
            t1=0.6, omega_final=12.0, inertia=0.25, n_elements=16, E=1e7, u0=0.0025, T_i=0.0,
            bending="on", Ta_max=0.0, start="laid"),
    2: dict(R=0.05, width=0.04, h=0.003, k_p=8e7, c_p=2000.0, nu_s=2e5, mu=0.6, rho=166.667,
            t1=1.0, omega_final=500.0, inertia=0.00025, n_elements=20, E=1.6667e6, u0=0.0,
            T_i=50.0, bending="off", Ta_max=2.0, start="settled"),
}
T0 = 0.05            # s, Table 4.1 (both models)
TA_T1 = 1.0          # s, Eq. 4.47 (see ancf.belts.pulleys)


def _model(key: str):
    return lambda v: MODELS[v["model"]][key]


def params() -> tuple:
    m = _model
    return (
        Param("model", 2, int, doc="Table 4.1 column giving the defaults", choices=(1, 2)),
        Param("n_elements", m("n_elements"), int, doc="plates along the belt (one across)",
              lo=4, hi=200),
        Param("contact_points", 81, int, doc="contact points per plate (n x n Gauss rule)",
              choices=SUPPORTED_RULES),
        Param("E", m("E"), float, "Pa", "Young's modulus", lo=0, lo_open=True, hi=1e12),
        Param("nu", 0.3, float, "-", "Poisson's ratio", lo=0, hi=0.5, hi_open=True),
        Param("rho", m("rho"), float, "kg/m^3", "belt density", lo=0, lo_open=True, hi=1e5),
        Param("R", m("R"), float, "m", "pulley radius (both)", lo=0, lo_open=True, hi=1.0),
        Param("centre_distance", lambda v: math.pi * v["R"], float, "m", "distance of the pulley "
              "centres (Table 4.1: l_s = pi R)", lo=0, lo_open=True, hi=100.0),
        Param("width", m("width"), float, "m", "belt width w", lo=0, lo_open=True, hi=1.0),
        Param("h", m("h"), float, "m", "belt thickness", lo=0, lo_open=True, hi=0.1),
        Param("bending", m("bending"), str, doc="bending energy of Eq. 4.17", choices=("on", "off")),
        Param("T_i", m("T_i"), float, "N", "initial tension set by a belt shorter than the path "
              "(0: as long as the path)", lo=0, hi=1e5),
        Param("belt_length", None, float, "m", "reference (unstretched) belt length; default: "
              "from T_i (see the scene's description)", lo=0, lo_open=True, hi=1000),
        Param("u0", m("u0"), float, "m", "driver displacement of Eq. 4.46 (reached at t0)", lo=0,
              hi=0.1),
        Param("k_p", m("k_p"), float, "N/m^3", "penalty stiffness per unit area", lo=0,
              lo_open=True, hi=1e13),
        Param("c_p", m("c_p"), float, "N s/m^3", "penalty damping per unit area", lo=0, hi=1e9),
        Param("mu", m("mu"), float, "-", "friction coefficient", lo=0, lo_open=True, hi=10),
        Param("nu_s", m("nu_s"), float, "kg/(m^2 s)", "friction creep-rate factor", lo=0,
              lo_open=True, hi=1e10),
        Param("inertia", m("inertia"), float, "kg m^2", "driven pulley moment of inertia", lo=0,
              lo_open=True, hi=1e3),
        Param("omega_final", m("omega_final"), float, "rad/s", "driver's final angular velocity "
              "(Eq. 3.29)", lo=0, hi=5000),
        Param("t1", m("t1"), float, "s", "end of the driver ramp (Table 4.1)", lo=T0, lo_open=True,
              hi=100),
        Param("Ta_max", m("Ta_max"), float, "N m", "final opposing torque (Eq. 4.47; reached at "
              f"{TA_T1:g} s)", lo=0, hi=1e4),
        Param("strain_measure", "green", str, doc="strain measure of the reported span tensions "
              "(Eqs 4.9-4.11; all are in results.tensions; the membrane's own axial force, "
              "the one that balances the torque, is tensions.membrane)", choices=MEASURES),
        Param("start", m("start"), str, doc="'settled': static frictionless pre-tension first; "
              "'laid': on the wrapped path", choices=("settled", "laid")),
        Param("integrator", "generalized-alpha", str, doc="time integrator",
              choices=("generalized-alpha",)),
    ) + march_params(1e-4, "time step", 1.2) + (
        Param("steady_window", following(0.1, "t_end"), float, "s", "window before t_end over "
              "which the driven slip is averaged (at most t_end)", lo=0, lo_open=True, hi=100),
        Param("max_steps", 400_000, int, doc="step budget (beyond it: not converged)", lo=1,
              hi=MAX_STEPS),
    )


def path_of(p: dict) -> TwoPulleyPath:
    return TwoPulleyPath((0.0, 0.0), p["R"], (p["centre_distance"], 0.0), p["R"])


def stretch_for(T_i: float, k: float) -> float:
    """lambda with k lambda (lambda^2 - 1) / 2 = T_i (uniaxial membrane force, k = E h w)."""
    c = 2.0 * T_i / k
    lam = 1.0 + c / 2.0
    for _ in range(60):  # Newton on f = lam^3 - lam - c, convex for lam >= 1
        lam -= (lam**3 - lam - c) / (3 * lam**2 - 1)
    return lam


def belt_length(p: dict) -> float:
    """Reference length: given, or L0 = (P - 2 pi d) / lambda(T_i), m, with d the
    penetration of :func:`penetration`, so that the settled belt's spans carry T_i."""
    if p["belt_length"] is not None:
        return p["belt_length"]
    lam = stretch_for(p["T_i"], p["E"] * p["h"] * p["width"])
    return (path_of(p).length - 2 * math.pi * penetration(p, lam)) / lam


def penetration(p: dict, lam: float) -> float:
    """d = T_i lambda / (R w k_p), m: the penalty's answer to the wrap's normal force
    T_i / R per unit belt length, i.e. T_i lambda / R per unit reference length, spread
    over the reference width."""
    return p["T_i"] * lam / (p["R"] * p["width"] * p["k_p"])


def check(p: dict) -> None:
    check_steps(p)
    if 2 * p["R"] >= p["centre_distance"]:
        raise InputError(f"R = {p['R']:g} m: the pulleys overlap; allowed: 2 R < centre_distance "
                         f"= {p['centre_distance']:g} m")
    check_belt_length(p["belt_length"], path_of(p).length)
    if p["steady_window"] > p["t_end"]:
        raise InputError(f"steady_window = {p['steady_window']:g} s is out of range; allowed: "
                         f"a number in (0, t_end = {p['t_end']:g}] s (a window within the run)")
    lam = stretch_for(p["T_i"], p["E"] * p["h"] * p["width"])
    if lam > 2.0:
        raise InputError(f"T_i = {p['T_i']:g} N is out of range: it needs a belt shorter than half "
                         f"the path (stretch {lam:.3g}); allowed: T_i <= "
                         f"{3.0 * p['E'] * p['h'] * p['width']:g} N (= 3 E h w)")


def spec(p: dict) -> Belt3DSpec:
    return Belt3DSpec(path=path_of(p), belt_length=belt_length(p), n_elements=p["n_elements"],
                      E=p["E"], nu=p["nu"], rho=p["rho"], width=p["width"], h=p["h"],
                      bending=p["bending"] == "on", k_p=p["k_p"], c_p=p["c_p"],
                      friction=(LAW, p["mu"], p["nu_s"]), contact_points=p["contact_points"],
                      inertia=p["inertia"], omega_final=p["omega_final"], t0=T0, t1=p["t1"],
                      Ta_max=p["Ta_max"], Ta_t1=TA_T1, u0=p["u0"])


def _slip(t, wd, wn, window) -> float | None:
    sel = (t >= t[-1] - window - 1e-12) & (wd > 0)
    return float(1.0 - np.mean(wn[sel]) / np.mean(wd[sel])) if sel.any() else None


END_KEYS = ("T_tight_N", "T_slack_N", "v_tight", "v_slack", "tensions", "torque_from_tensions_Nm",
            "torques_from_tensions_Nm", "torque_from_friction_Nm", "penetration_max_m")


def _results(p: dict):
    """results_of(drive, res, wd, wn) of :func:`ancf.scenes.belt_common.run`."""
    def results_of(drive, res, wd, wn) -> dict:
        if not res.converged:
            return {"slip_driven": None, **dict.fromkeys(END_KEYS)}
        return {"slip_driven": _slip(res.t, wd, wn, p["steady_window"]),
                **end_state(drive, res.q[-1], res.v[-1], float(res.t[-1]), p["strain_measure"])}
    return results_of


def run(p: dict) -> SceneResult:
    drive = Belt3DDrive(spec(p))
    out = bc.run(drive, p, bc.alpha_march(p, "belt3d"), _results(p),
                 keep_unsettled=True)
    out.results.update(belt_length_m=drive.spec.belt_length, total_dofs=drive.n + 1)
    return out


def warn(p: dict, res: SceneResult) -> list:
    """The belt drives' physical-sense checks (:func:`ancf.scenes.sense.drive`) on the
    thesis drive's numbers (:func:`ancf.scenes.belt_common.sense_drive`; the membrane's
    span tensions)."""
    k, R = p["E"] * p["h"] * p["width"], p["R"]
    L0 = res.results.get("belt_length_m") or belt_length(p)
    T0 = sense.membrane_force(k, (path_of(p).length + 2.0 * p["u0"]) / L0)
    ramps = {"driver ramp (Eq. 3.29)": p["t1"]}
    if p["Ta_max"] > 0:
        ramps["load torque ramp (Eq. 4.47)"] = TA_T1
    r = res.results
    spans = (dict(r["tensions"]["membrane"]) if res.converged and r.get("tensions") else None)
    return sense.drive(bc.sense_drive(p, res, path_of(p), T0, k, p["h"] * p["width"],
                                      p["steady_window"], ramps, spans))


BELT3D_KNOBS = ("n_elements", "contact_points", "integrator", "dt", "rho_inf", "newton_tol",
                "max_steps", "strain_measure", "steady_window")


def _bechtel(p):
    """Bechtel's steady belt (analytic.bechtel, inertia included) for the scene's drive."""
    from analytic import bechtel
    try:
        b, top = bechtel.steady({"k": p["E"] * p["h"] * p["width"], "R": p["R"],
                                 "omega": p["omega_final"], "mu": p["mu"], "T_i": p["T_i"],
                                 "T_a": p["Ta_max"], "rhoA": p["rho"] * p["h"] * p["width"]})
    except ValueError as exc:  # Bechtel's names -> the scene's (T_a is Ta_max, omega omega_final)
        text = str(exc)
        for theirs, ours in (("T_a = ", "Ta_max = "), ("omega = ", "omega_final = ")):
            if text.startswith(theirs):
                text = ours + text[len(theirs):]
        raise type(exc)(text) from None
    return bechtel.summary(b, top)


def _bechtel_error(res, ref, p):
    """max relative error of the span membrane tensions against Bechtel's."""
    tn = res.get("tensions")
    if not tn:
        return float("nan")
    return max(abs(tn["membrane"][s] - ref[f"T_{s}_N"]) / abs(ref[f"T_{s}_N"])
               for s in ("tight", "slack"))


RESULTS = {
    **DYNAMIC_RESULTS,
    "omega_driver": series("driver angular velocity (Eq. 3.29), rad/s"),
    "omega_driven": series("driven pulley angular velocity, rad/s"),
    "slip_driven": nullable("1 - mean omega_driven / mean omega_driver over the last "
                            "steady_window (null before the driver turns)"),
    "T_tight_N": nullable("tight (upper) span: mean tension k eps of strain_measure over its "
                          "middle third at t_end, along the edge y = 0, N (default green: the "
                          "thesis's Green-strain value; the force whose span difference "
                          "balances the driven torque is the membrane's, tensions.membrane)"),
    "T_slack_N": nullable("slack (lower) span: the same, N"),
    "v_tight": nullable("tight span: mean belt speed along the tangent at t_end, m/s"),
    "v_slack": nullable("slack span: the same, m/s"),
    "tensions": field("object", "span tensions per measure (green, true, almansi: k eps; "
                      "membrane: the element's own axial force), N", nullable=True,
                      keys={m: field("object", f"{m}: tight and slack, N",
                                     keys={"tight": field(NUM, "tight span, N"),
                                           "slack": field(NUM, "slack span, N")})
                            for m in ("green", "true", "almansi", "membrane")}),
    "torque_from_tensions_Nm": nullable("(T_tight - T_slack) R of strain_measure, N m"),
    "torques_from_tensions_Nm": field("object", "(T_tight - T_slack) R per measure, N m",
                                      nullable=True,
                                      keys={m: field(NUM, f"{m}, N m") for m in
                                            ("green", "true", "almansi", "membrane")}),
    "torque_from_friction_Nm": nullable("moment of the contact (friction) forces on the "
                                        "driven pulley at t_end, N m"),
    "penetration_max_m": nullable("largest penetration of a contact point at t_end, m"),
    "contact_pairs": field(INT, "element-pulley pairs whose points were evaluated (after the "
                                "bounding test), summed over force evaluations"),
    "pretension_iterations": field(INT, "Newton iterations of the static pre-tension "
                                        "(0: start = laid)"),
    "belt_length_m": field(NUM, "reference (unstretched) belt length used, m"),
    "total_dofs": field(INT, "belt coordinates plus the driven pulley's angle")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import Reference, SceneSpec, relative
    refs = {"bechtel": Reference(
        "bechtel", "analytic",
        "Bechtel's steady extensible belt with inertia (`ancf analytic bechtel`, k = E h w, "
        "ρA = ρ h w); error = max relative difference of the span means of the membrane's own "
        "axial force (results.tensions.membrane) from T_tight, T_slack. It includes the model "
        "gap (Bechtel: no slip in the stick arcs, uniform span tension; the FE belt is a "
        "membrane with contact compliance): about 1-3 % for Model 2 at any mesh",
        _bechtel, _bechtel_error, measure="relative span-tension error")}
    grids = ({"n_elements": [20, 30, 40], "contact_points": [25, 49, 81],
              "integrator": ["generalized-alpha"], "dt": [1e-4]},)
    return SceneSpec("belt3d", BELT3D_KNOBS, frozenset({"axial", "large-rotation", "inertia",
                                                        "contact"}),
                     refs, "bechtel", report_grids=grids, recommend_grids=grids, dynamic=True,
                     provides=frozenset({"axial", "large-rotation", "inertia", "contact"}),
                     notes="3D belt drive, Model 2 of Table 4.1 (thin plates, bending off), "
                           "against Bechtel's analytic steady belt.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 110
SCENE = Scene(
    "belt3d",
    "Three-dimensional belt drive of thin ANCF plates on two pulleys, surface penalty contact "
    "with creep-rate friction, Models 1 and 2 of Table 4.1 (thesis 4.6).",
    params(), run, check, warn=warn,
    results=RESULTS, study=study)
