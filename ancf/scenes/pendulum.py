"""Free-falling flexible pendulum (thesis Fig. 2.5, Figs 2.6-2.8; report Figs 5-10).

A 2 m beam, 0.1 m square, E = 2.07e7 Pa, nu = 0, rho = 7850 kg/m^3, pinned at the
origin (revolute joint: fixed nodal position of node 0), horizontal along +x and
released from rest under gravity g = 9.81 m/s^2 (-y).  Results: the tip position
sampled every ``output_dt``, the energy components of Eq. 2.34 and the largest
deviation of their sum from its initial value.
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np

from ancf.scenes import accuracy
from ancf.core.constraints import Elimination
from ancf.core.forces import Gravity
from ancf.scenes import beam_dynamic as bd
from ancf.scenes import beam_static as bs
from ancf.common.params import Param
from ancf.scenes.base import DYNAMIC_RESULTS, Scene, SceneResult, nullable, series
from ancf.core.validity import check_dynamic


def setup(p: dict):
    """(mesh, q0, assembly, model, forces) of the pendulum.  The model (read-only) is
    built once per assembly, gravity and constraint form (:func:`_model`) and shared by
    the runs that reuse the assembly (``beam_static.build``); q0 is the caller's own copy."""
    mesh, q0, asm = bs.build(p)
    pins = tuple((d, float(q0[d])) for d in (mesh.dof(0, "r", 0), mesh.dof(0, "r", 1)))
    return (mesh, q0, asm) + _model(asm, pins, p["g"], p["constraints"], p["baumgarte"])


@lru_cache(maxsize=32)
def _model(asm, pins: tuple, g: float, constraints: str, baumgarte: float):
    """(model, forces): gravity g (m/s^2, -y), the coordinates of ``pins`` (pairs of
    coordinate and value, m) fixed, in the constraint form of ``bd.model``."""
    elim = Elimination(asm.n_dofs)
    for d, value in pins:
        elim.fix(d, value)
    p = {"constraints": constraints, "baumgarte": baumgarte}
    return bd.model(p, asm, [Gravity(asm, (0.0, -g))], elim)


def run(p: dict) -> SceneResult:
    mesh, q0, asm, mdl, forces = setup(p)
    res = bd.simulate(p, mdl, q0, np.zeros_like(q0))
    n = p["n_elements"]
    ix, iy = mesh.dof(n, "r", 0), mesh.dof(n, "r", 1)
    en = bd.energies(asm, forces, res)
    tot = en.totals
    results = {"times": bd.as_list(res.t), "tip_x": bd.as_list(res.q[:, ix]),
               "tip_y": bd.as_list(res.q[:, iy]),
               "energy_max_deviation_J": en.max_deviation(),
               "energy_kinetic": bd.as_list(tot["kinetic"]),
               "energy_potential": bd.as_list(tot["potential"]),
               "energy_strain": bd.as_list(tot["strain"]),
               "energy_total": bd.as_list(tot["total"])}
    results.update(bd.stats(res))
    out = SceneResult(res.converged, res.message, results,
                      extra={"result": res, "energy": en, "mesh": mesh})
    return check_dynamic(out, asm, q0, res.t, res.q)


def _traj_error(res, ref, p):
    """max over samples of |tip(t) - tip_ref(t)| / L (trajectory error)."""
    t = np.asarray(res["times"], float)
    tr = np.asarray(ref["times"], float)
    if t.size == 0 or t[-1] < tr[-1] - 1e-9:
        return float("nan")
    rx = np.interp(t, tr, np.asarray(ref["tip_x"], float))
    ry = np.interp(t, tr, np.asarray(ref["tip_y"], float))
    d = np.hypot(np.asarray(res["tip_x"], float) - rx, np.asarray(res["tip_y"], float) - ry)
    return float(np.max(d) / p["L"])


def _dynamic_grids(ns):
    """Both elements x time integrators x tolerances / step sizes for the dynamic scenes."""
    grids = []
    for element in ("linear", "omar-shabana"):
        grids += [{"element": [element], "integration": ["thesis"], "n_elements": list(ns),
                   "integrator": ["generalized-alpha"], "dt": [1e-2, 3e-3, 1e-3]},
                  {"element": [element], "integration": ["thesis"], "n_elements": list(ns),
                   "integrator": ["rk45", "dop853", "radau", "bdf"], "rtol": [1e-4, 1e-6]}]
    return tuple(grids)


def _rigid_pendulum(p):
    """The rigid pendulum's tip trajectory (``ancf analytic rigid-pendulum``) at p's L, g, h."""
    from ancf.scenes.spec import analytic_values
    return analytic_values("rigid-pendulum", p, ("times", "tip_x", "tip_y"))


ENERGY_DRIFT_REL = 1e-3      # energy deviation / (m g L) above this: drift


def warn(p: dict, res) -> list[str]:
    """The accuracy warnings of a finished run: the step against the first bending mode's
    period, the energy drift against the energy scale ``m g L``."""
    out = accuracy.step(p, accuracy.bending_period(p, accuracy.PINNED_FREE),
                        "first bending mode")
    dev = res.results.get("energy_max_deviation_J")
    scale = p["rho"] * p["b"] * p["h"] * p["L"] * p["g"] * p["L"]
    if accuracy.finite(dev) and dev > ENERGY_DRIFT_REL * scale:
        out.append(f"energy drift {dev:.3g} J exceeds {ENERGY_DRIFT_REL:g} of the energy scale "
                   f"m g L = {scale:.3g} J: the run does not conserve energy")
    return out


RESULTS = {
    **DYNAMIC_RESULTS, "tip_x": series("tip x, m"), "tip_y": series("tip y, m"),
    "energy_max_deviation_J": nullable("largest |E(t) - E(0)|, J"),
    "energy_kinetic": series("kinetic energy, J"),
    "energy_potential": series("gravitational potential energy, J"),
    "energy_strain": series("strain energy, J"), "energy_total": series("total energy, J")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import DYNAMIC_KNOBS, Reference, SceneSpec, self_reference
    # The rigid pendulum is 12 % of L away from this soft (E = 2.07e7 Pa) pendulum, so a
    # 1e-2 question needs a self-reference.  32 elements: 8 -> 16 elements still moves the
    # tip by 1e-2 L, 16 -> 32 by about 1e-3 L (generalized-alpha, dt = 1e-3 s).
    fine = {"element": "linear", "integration": "thesis", "n_elements": 32,
            "integrator": "generalized-alpha", "dt": 1e-3}
    refs = {
        "self": self_reference(
            "pendulum", fine, ("times", "tip_x", "tip_y"), _traj_error,
            "converged self-reference: 32 linear elements, generalized-α, dt = 1e-3 s (computed "
            "once, about a minute, then cached); error = max_t |tip(t) − tip_ref(t)| / L",
            check={"n_elements": 16}, knobs=DYNAMIC_KNOBS, measure="tip-trajectory error max|Δtip| / L"),
        "rigid-pendulum": Reference(
            "rigid-pendulum", "analytic",
            "rigid pendulum (analytic.dynamics_refs); error = max_t |tip(t) − tip_ref(t)| / L; "
            "includes the flexibility of the beam (E = 2.07e7 Pa), so it is a floor, not a "
            "discretisation error", _rigid_pendulum, _traj_error,
            measure="tip-trajectory error max|Δtip| / L"),
    }
    return SceneSpec("pendulum", DYNAMIC_KNOBS,
                     frozenset({"axial", "bending", "large-rotation", "inertia"}), refs, "self",
                     report_grids=_dynamic_grids((2, 4, 8, 16)),
                     recommend_grids=_dynamic_grids((2, 4, 8, 16)), dynamic=True,
                     notes="Flexible pendulum against a converged self-reference.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 40
SCENE = Scene(
    "pendulum",
    "Flexible pendulum pinned at the origin, released horizontally under gravity (thesis Fig. 2.5).",
    bd.section_params(n_elements=4, E=2.07e7, nu=0.0)
    + bd.dynamic_params(t_end=1.0)
    + (Param("g", 9.81, float, "m/s^2", "gravitational acceleration (-y)", lo=0),),
    run, bd.check, warn=warn,
    results=RESULTS, study=study)
