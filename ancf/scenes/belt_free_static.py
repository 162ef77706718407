"""The belt released from its pulleys (thesis Figs 3.4-3.5).

A closed belt of ``n_elements`` Dufva elements (straight reference elements, total
reference length ``belt_length`` = 1.276 m), laid on the wrapped path of Table 3.1's
pulleys as the initial guess, without contact.  Rigid motion is removed as in
Fig. 3.4: point A (node 0, the driver pulley's far point) is fixed in x and y, the
node at point B (half the belt away: the driven pulley's far point when
``n_elements`` is even) in y.  Bent straight elements want to straighten but all
have the same properties, so the equilibrium is a circle of circumference
``belt_length``: radius L/(2 pi).

Results: the mean distance of the centreline from its centroid and the largest
deviation from that mean (200 points per element), against L/(2 pi); the Newton
iterations.

``ancf modes belt-free-static`` adds the belt's density ``rho`` (Table 3.1); its
reference state is the laid belt (bent straight elements: not an equilibrium), its
equilibrium the circle.
"""
from __future__ import annotations

import math

import numpy as np
import scipy.sparse as sp

from ancf.core.assembly import Assembly, ElementGroup
from ancf.belts.path import laid_belt
from ancf.core.constraints import Elimination
from ancf.elements.basis import cubic2d_S
from ancf.elements.dufva2d import DufvaBelt2D
from ancf.core.mesh import BeamMesh
from ancf.core.pattern import ReducedPattern
from ancf.core.quadrature import RectangularSection
from ancf.scenes import belt_common as bc
from ancf.scenes import sense
from ancf.common.params import InputError, Param
from ancf.scenes.base import (INT, NUM, Equilibrium, ModalModel, Scene, SceneResult, field,
                              nullable)
from ancf.solvers.minimize import minimize

CURVE_POINTS = 200  # per element, for the radius statistics


def params() -> tuple:
    keep = [p for p in bc.belt_params(n_elements=10, E=1e8, alpha2=0.01, belt_length=1.276)
            if p.name not in ("rho",)]
    return tuple(keep) + bc.pulley_params() + (
        Param("rtol", 1e-8, float, "-", "residual tolerance relative to the initial residual",
              lo=1e-14, hi=1e-2),
        Param("max_iterations", 200, int, doc="Newton iterations allowed", lo=1, hi=10000),
    )


def check(p: dict) -> None:
    bc.check_geometry(p)
    if p["n_elements"] % 2:
        raise InputError(f"n_elements = {p['n_elements']} is out of range; allowed: an even "
                         "integer in [4, 400] (point B is the node half the belt away from A)")


def _model(p):
    path, L0, n = bc.path_of(p), p["belt_length"], p["n_elements"]
    mesh = BeamMesh(L0, n, ("r", "r_x", "r_y"), closed=True)
    q0 = laid_belt(path, L0, n).ravel()
    el = DufvaBelt2D(mesh.lengths, q0[mesh.dofmap], RectangularSection(p["b"], p["h"]), E=p["E"],
                     nu=p["nu"], rho=p.get("rho", 0.0), alpha1=p["alpha1"], alpha2=p["alpha2"],
                     ks=p["ks"], nx=p["elastic_points"])
    elim = Elimination(mesh.n_dofs)
    A, B = 0, n // 2
    elim.fix([mesh.dof(A, "r", 0), mesh.dof(A, "r", 1), mesh.dof(B, "r", 1)],
             q0[[mesh.dof(A, "r", 0), mesh.dof(A, "r", 1), mesh.dof(B, "r", 1)]])
    T, g, _ = elim.build()
    return mesh, q0, el, ReducedPattern(mesh.n_dofs, [mesh.dofmap], sp.csr_matrix(T)), g


def curve(mesh, q) -> np.ndarray:
    """Centreline points (n_elements * CURVE_POINTS, 2) of belt coordinates q."""
    xi = np.linspace(0.0, 1.0, CURVE_POINTS, endpoint=False)
    l = mesh.lengths[:, None] * np.ones((1, xi.size))
    S = cubic2d_S(xi[None, :] * l, np.zeros_like(l), l)  # (nel, npts, 6)
    E = q[mesh.dofmap].reshape(mesh.n_elements, 6, 2)
    return np.einsum("eqk,ekd->eqd", S, E).reshape(-1, 2)


def _settle(p, mesh, q0, el, pat, g):
    """Newton on the strain energy from the laid belt (:func:`ancf.solvers.minimize`)."""
    dm = mesh.dofmap
    asm = Assembly(mesh.n_dofs, [ElementGroup(el, dm)])

    def energy(z):
        return float(el.energy(pat.expand(z, g)[dm]).sum())

    def grad_tangent(z):
        return pat.assemble(asm, pat.expand(z, g))

    return minimize(energy, grad_tangent, pat.restrict(q0), pat.kl, rtol=p["rtol"],
                    max_iter=p["max_iterations"])


def run(p: dict) -> SceneResult:
    mesh, q0, el, pat, g = _model(p)
    out = _settle(p, mesh, q0, el, pat, g)
    q = pat.expand(out.z, g)
    pts = curve(mesh, q)
    rad = np.linalg.norm(pts - pts.mean(axis=0), axis=1)
    R_ref = p["belt_length"] / (2 * math.pi)
    results = {"radius_mean_m": float(rad.mean()), "radius_max_dev_m": float(np.abs(rad - rad.mean()).max()),
               "radius_reference_m": R_ref, "newton_iterations": out.iterations,
               "residual_final": out.residuals[-1], "residual_initial": out.residuals[0]}
    if not out.converged:
        results.update(radius_mean_m=None, radius_max_dev_m=None)
    shapes = [curve(mesh, pat.expand(z, g)) for z in out.iterates]
    return SceneResult(out.converged, out.message, results,
                       extra={"shapes": shapes, "residuals": out.residuals, "mesh": mesh, "q": q,
                              "q0": q0})


def modal(p: dict) -> ModalModel:
    from ancf.scenes.beam_static import centreline  # not needed by ancf run
    mesh, q0, el, pat, g = _model(p)

    def equilibrium() -> Equilibrium:
        out = _settle(p, mesh, q0, el, pat, g)
        return Equilibrium(pat.expand(out.z, g), out.converged, out.message, out.iterations)

    return ModalModel(Assembly(mesh.n_dofs, [ElementGroup(el, mesh.dofmap)]), pat, q0,
                      equilibrium, centreline(mesh), "centreline", mesh)


def warn(p: dict, res: SceneResult) -> list:
    """The shape found against its circle (:func:`ancf.scenes.sense.circle`)."""
    r = res.results
    if not res.converged or r.get("radius_mean_m") is None:
        return []
    return sense.circle(r["radius_mean_m"], r["radius_max_dev_m"], r["radius_reference_m"])


BELT_STATIC_KNOBS = ("n_elements", "elastic_points", "rtol", "max_iterations")


def _circle(p):
    return {"radius_m": p["belt_length"] / (2 * math.pi)}


def _roundness_error(res, ref, p):
    """max(|mean radius - R|, max |radius - mean radius|) / R, R = L/(2 pi)."""
    return max(abs(res["radius_mean_m"] - ref["radius_m"]), res["radius_max_dev_m"]) / ref["radius_m"]


RESULTS = {
    "radius_mean_m": nullable("mean distance of the centreline from its centroid, m"),
    "radius_max_dev_m": nullable("largest deviation of that distance from its mean, m"),
    "radius_reference_m": field(NUM, "belt_length / (2 pi), the circle's radius, m"),
    "newton_iterations": field(INT, "Newton iterations"),
    "residual_initial": field(NUM, "largest generalised force at the wrapped shape, N"),
    "residual_final": field(NUM, "largest generalised force at the last iterate, N")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import Reference, SceneSpec
    refs = {"circle": Reference(
        "circle", "analytic",
        "the circle of circumference belt_length, radius R = L/(2π); error = max(|r̄ − R|, "
        "max |r − r̄|) / R over the centreline's distance r from its centroid (r̄ its mean). "
        "The mean radius levels off at 3.0e-6 R from 16 elements on (the ring's own axial "
        "strain under bending), the deviation from roundness falls with the element count",
        _circle, _roundness_error, measure="roundness error / R")}
    grid = ({"n_elements": [4, 6, 8, 10, 16, 20, 40, 80], "elastic_points": [3, 5],
             "rtol": [1e-8, 1e-4]},)
    return SceneSpec("belt-free-static", BELT_STATIC_KNOBS,
                     frozenset({"axial", "bending", "large-rotation"}), refs, "circle",
                     report_grids=grid, recommend_grids=grid, provides=bc.BELT_PHYSICS,
                     notes="Belt released from the pulleys (Dufva elements, Table 3.1) against "
                           "the circle it relaxes to.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 60
SCENE = Scene(
    "belt-free-static",
    "Belt released from the pulleys: Newton from the wrapped shape to the circle "
    "(thesis Figs 3.4-3.5).",
    params(), run, check, warn=warn, modal=modal,
    modal_params=tuple(q for q in bc.belt_params() if q.name == "rho"),
    results=RESULTS, study=study)
