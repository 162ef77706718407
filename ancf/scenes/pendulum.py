"""Free-falling flexible pendulum (thesis Fig. 2.5, Figs 2.6-2.8; report Figs 5-10).

A 2 m beam, 0.1 m square, E = 2.07e7 Pa, nu = 0, rho = 7850 kg/m^3, pinned at the
origin (revolute joint: fixed nodal position of node 0), horizontal along +x and
released from rest under gravity g = 9.81 m/s^2 (-y).  Results: the tip position
sampled every ``output_dt``, the energy components of Eq. 2.34 and the largest
deviation of their sum from its initial value.
"""
from __future__ import annotations

import numpy as np

from ancf.scenes import accuracy
from ancf.core.constraints import Elimination
from ancf.core.forces import Gravity
from ancf.scenes import beam_dynamic as bd
from ancf.scenes import beam_static as bs
from ancf.common.params import Param
from ancf.scenes.base import Scene, SceneResult
from ancf.core.validity import check_dynamic


def setup(p: dict):
    """(mesh, q0, assembly, model, forces) of the pendulum."""
    mesh, q0, asm = bs.build(p)
    elim = Elimination(mesh.n_dofs)
    for k in (0, 1):
        elim.fix(mesh.dof(0, "r", k), q0[mesh.dof(0, "r", k)])
    mdl, forces = bd.model(p, asm, [Gravity(asm, (0.0, -p["g"]))], elim)
    return mesh, q0, asm, mdl, forces


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


SCENE = Scene(
    "pendulum",
    "Flexible pendulum pinned at the origin, released horizontally under gravity (thesis Fig. 2.5).",
    bd.section_params(n_elements=4, E=2.07e7, nu=0.0)
    + bd.dynamic_params(t_end=1.0)
    + (Param("g", 9.81, float, "m/s^2", "gravitational acceleration (-y)", lo=0),),
    run, bd.check, warn=accuracy.pendulum)
