"""Shared pieces of the belt scenes (thesis chapters 3 and 4): the belt's parameters with
Table 3.1 as defaults, their cross-field checks, the output times and the run of a
drive (pre-tension, march, pulley speeds, statistics).
"""
from __future__ import annotations

import numpy as np

from ancf.belts import post2d, post3d
from ancf.belts.contact2d import SUPPORTED_POINTS
from ancf.belts.drive3d import Belt3DDrive
from ancf.belts.dynamics import BeltOptions, simulate
from ancf.belts.path import TwoPulleyPath
from ancf.belts.pretension import settle
from ancf.common.inputs import MAX_STEPS, check_sampling, following, intervals
from ancf.common.params import InputError, Param
from ancf.common.progress import Ticker
from ancf.scenes import sense
from ancf.scenes.base import SceneResult

#: Table 3.1
R1, R2, X_CENTRE = 0.08125, 0.08125, 0.191441
#: Table 3.1's belt against the path of its pulleys: 1.2727 m on 1.27627 m
TABLE_SHORTENING = 1.2727 / TwoPulleyPath((-X_CENTRE, 0.0), R1, (X_CENTRE, 0.0), R2).length


#: the physics of the Dufva belt element (ancf.scenes.spec.PHYSICS): a planar beam with
#: extension, bending and shear, large rotations
BELT_PHYSICS = frozenset({"axial", "bending", "shear", "large-rotation"})


def belt_params(n_elements=20, E=1e8, alpha2=0.01, belt_length=None) -> tuple:
    """Belt section, material and element parameters (Table 3.1)."""
    return (
        Param("n_elements", n_elements, int, doc="belt elements", lo=4, hi=400),
        Param("E", E, float, "Pa", "Young's modulus", lo=0, lo_open=True, hi=1e12),
        Param("nu", 0.3, float, "-", "Poisson's ratio (enters the shear modulus only)",
              lo=0, hi=0.5, hi_open=True),
        Param("rho", 1036.0, float, "kg/m^3", "belt density", lo=0, lo_open=True),
        Param("h", 0.01, float, "m", "section height", lo=0, lo_open=True, hi=0.05),
        Param("b", 0.01, float, "m", "section width", lo=0, lo_open=True, hi=1.0),
        Param("ks", 5.0 / 6.0, float, "-", "shear correction factor", lo=0, lo_open=True, hi=2),
        Param("alpha1", 1.0, float, "-", "axial stiffness parameter (Eq. 3.18)",
              lo=0, lo_open=True, hi=10),
        Param("alpha2", alpha2, float, "-", "bending stiffness parameter (Eqs 3.18-3.19)",
              lo=0, lo_open=True, hi=10),
        Param("elastic_points", 5, int, doc="Gauss points per element of the elastic forces",
              lo=2, hi=12),
        Param("belt_length", belt_length, float, "m",
              "reference (unstretched) belt length; default: the wrapped path times "
              f"{TABLE_SHORTENING:.6f} (Table 3.1: 1.2727 m on a 1.27627 m path)",
              lo=0, lo_open=True, hi=100),
    )


def pulley_params(R2_default=R2) -> tuple:
    return (
        Param("R1", R1, float, "m", "driver pulley radius (centre (-0.191441, 0))",
              lo=0, lo_open=True, hi=1.0),
        Param("R2", R2_default, float, "m", "driven pulley radius (centre (0.191441, 0))",
              lo=0, lo_open=True, hi=1.0),
    )


def path_of(p: dict) -> TwoPulleyPath:
    return TwoPulleyPath((-X_CENTRE, 0.0), p["R1"], (X_CENTRE, 0.0), p["R2"])


def check_geometry(p: dict) -> None:
    """Pulleys apart; belt length at least half the path (a shorter one cannot be laid
    without strains beyond 100 %)."""
    D = 2 * X_CENTRE
    if p["R1"] + p["R2"] >= D:
        raise InputError(f"R1 + R2 = {p['R1'] + p['R2']:g} m: the pulleys overlap; allowed: "
                         f"R1 + R2 < centre distance {D:g} m")
    check_belt_length(p["belt_length"], path_of(p).length)


def check_belt_length(length, P: float) -> None:
    """A given belt length (m) between half and twice the wrapped path P (m)."""
    if length is not None and not 0.5 * P <= length <= 2.0 * P:
        raise InputError(f"belt_length = {length:g} m is out of range for this path "
                         f"({P:.6g} m); allowed: a number in [{0.5 * P:.6g}, {2 * P:.6g}] m "
                         "(half to twice the wrapped path)")


def check_steps(p: dict) -> None:
    """At least one step (dt <= t_end), samples on steps (dt <= output_dt) and at most
    MAX_STEPS steps."""
    if p["t_end"] < p["dt"]:
        raise InputError(f"t_end = {p['t_end']:g} s is out of range; allowed: at least one "
                         f"step, t_end >= dt = {p['dt']:g} s")
    check_sampling(p)
    if p["dt"] > p["output_dt"]:
        raise InputError(f"dt = {p['dt']:g} s is out of range; allowed: a number in [1e-07, "
                         f"output_dt = {p['output_dt']:g}] s (samples fall on steps)")
    if p["t_end"] / p["dt"] > MAX_STEPS:
        raise InputError(f"dt = {p['dt']:g} s is out of range; allowed: at least "
                         f"t_end/{MAX_STEPS} = {p['t_end'] / MAX_STEPS:g} s")


def progress(scene: str, t_end: float) -> Ticker:
    """Progress lines on stderr of a run to ``t_end`` (s): on a terminal and when piped,
    none in a run shorter than the ticker's interval (:class:`ancf.common.progress.Ticker`)."""
    return Ticker(scene, t_end)


def belt_length(p: dict) -> float:
    """The reference belt length: given, or the path shortened as in Table 3.1."""
    return p["belt_length"] if p["belt_length"] is not None else TABLE_SHORTENING * path_of(p).length


def contact_params(gauss_points=7) -> tuple:
    return (
        Param("k_p", 1e7, float, "N/m^2", "penalty stiffness per unit length", lo=0, lo_open=True,
              hi=1e12),
        Param("c_p", 10.0, float, "N s/m^2", "penalty damping per unit length", lo=0, hi=1e8),
        Param("mu", 1.2, float, "-", "friction coefficient", lo=0, hi=10),
        Param("nu_s", 1e5, float, "kg/(m s)", "friction creep-rate factor (slope of the friction "
              "force per unit length against sliding velocity)", lo=0, lo_open=True, hi=1e9),
        Param("gauss_points", gauss_points, int, doc="contact Gauss points per element",
              choices=SUPPORTED_POINTS),
    )



def march_params(dt: float, dt_doc: str, t_end: float) -> tuple:
    """The generalised-alpha march's parameters of the belt scenes (dt, rho_inf,
    newton_tol, t_end, output_dt)."""
    return (
        Param("dt", dt, float, "s", dt_doc, lo=1e-7, hi=1e-2),
        Param("rho_inf", 0.5, float, "-", "generalized-alpha spectral radius at infinite "
              "frequency", lo=0, hi=1),
        Param("newton_tol", 1e-7, float, "-", "Newton tolerance on the position increment "
              "relative to 1 + |q|", lo=1e-14, hi=1e-3),
        Param("t_end", t_end, float, "s", "simulated time", lo=0, lo_open=True, hi=100),
        Param("output_dt", following(0.005, "t_end"), float, "s", "sampling interval "
              "(default 0.005 s, at most t_end)", lo=0, lo_open=True, hi=10),
    )


def times(p: dict) -> np.ndarray:
    """Output times 0, output_dt, ... up to t_end (the last one t_end), s."""
    n = intervals(p["t_end"], p["output_dt"])
    return np.minimum(np.arange(n + 1) * p["output_dt"], p["t_end"])


def alpha_march(p: dict, scene: str):
    """march(drive, x0): the generalised-alpha march of ``p``'s parameters from x0 (None:
    the laid belt), with progress lines (:func:`progress`)."""
    opt = BeltOptions(dt=p["dt"], rho_inf=p["rho_inf"], newton_tol=p["newton_tol"],
                      max_steps=p["max_steps"])
    return lambda drive, x0: simulate(drive, times(p), opt, x0=x0,
                                      progress=progress(scene, p["t_end"]))


def run(drive, p: dict, march, results_of, keep_unsettled: bool) -> SceneResult:
    """A drive's run: the static pre-tension if ``p["start"]`` is 'settled', then
    ``march(drive, x0)``; the results are the times, both pulley speeds (rad/s), the
    scene's own ``results_of(drive, res, wd, wn)`` (dict) and the run statistics.  A
    pre-tension that does not converge fails the run; the march starts from its last
    state if ``keep_unsettled``, else from the laid belt."""
    x0, pre = None, None
    if p["start"] == "settled":
        x0, pre = settle(drive)
        if not (pre.converged or keep_unsettled):
            x0 = None
    res = march(drive, x0)
    if pre is not None and not pre.converged:
        res.converged, res.message = False, f"pre-tension: {pre.message}"
    wd = np.asarray(drive.omega_driver(res.t), dtype=float)
    wn = res.v[:, -1]
    results = {"times": [float(t) for t in res.t], "omega_driver": [float(w) for w in wd],
               "omega_driven": [float(w) for w in wn]}
    results.update(results_of(drive, res, wd, wn))
    results.update(res.stats(), samples=int(res.t.size), t_reached=float(res.t[-1]),
                   contact_pairs=res.extra["contact_pairs"],
                   pretension_iterations=0 if pre is None else pre.iterations)
    return SceneResult(res.converged, res.message, results,
                       extra={"result": res, "drive": drive})


def penetrations(drive, res) -> np.ndarray:
    """The belt's largest penetration into each pulley at the last sample of ``res`` (np,),
    m: the 2D belt's centreline at 8 points per element (:func:`ancf.belts.post2d.sample`),
    the plate belt's contact points (:func:`ancf.belts.post3d.contact_sample`)."""
    x, v, t = res.q[-1], res.v[-1], float(res.t[-1])
    if isinstance(drive, Belt3DDrive):
        d = post3d.contact_sample(drive, x, v, t, res.extra.get("friction_state", [None])[-1])[1]
    else:
        d = post2d.sample(drive, x, v, t).d
    return np.asarray(d).reshape(-1, drive.radii.size).max(axis=0)


def sense_drive(p: dict, res: SceneResult, path, T0: float, k: float, area: float,
                window: float, ramps: dict, spans: dict | None) -> sense.Drive:
    """The thesis drive's numbers (driver and driven pulley on ``path``, the driven one
    under ``Ta_max``) for :func:`ancf.scenes.sense.drive`: pre-tension T0 (N), axial
    stiffness k (N), section ``area`` (m^2), the steady ``window`` (s) and ``ramps``
    {name: end s}; ``spans`` {tight, slack: mean N} of a finished run (None: the run's
    checks are left out)."""
    r, drive = res.results, res.extra.get("drive")
    names, roles, loads = ("driver", "driven"), ("prescribed", "driven"), (0.0, p["Ta_max"])
    radii, wraps = (path.R1, path.R2), path.wrap
    t = np.asarray(r.get("times", []), dtype=float)
    sel = t >= t[-1] - window - 1e-12 if spans else np.zeros(t.size, dtype=bool)
    W = [np.asarray(r.get(key, []), dtype=float)[sel] for key in ("omega_driver", "omega_driven")]
    pen = penetrations(drive, res.extra["result"]) if spans else (None, None)
    pulleys = tuple(sense.Pulley(n, role, R, 1, wrap, load=Ta,
                                 omega=p["omega_final"] if role == "prescribed" else 0.0,
                                 omega_mean=float(w.mean()) if w.size else None,
                                 trace=tuple(w), penetration=None if d is None else float(d))
                    for n, role, R, wrap, Ta, w, d in zip(names, roles, radii, wraps, loads, W, pen))
    return sense.Drive(pulleys=pulleys, T0=T0, k=k, rhoA=p["rho"] * area, mu=p["mu"],
                       t_end=p["t_end"], window=window, ramps=ramps, finished=spans is not None,
                       spans=spans or {}, times=tuple(t[sel]))
