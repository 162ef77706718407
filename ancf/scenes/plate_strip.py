"""The planar cantilever (scene ``cantilever``) as a thin-plate strip (issue 13 item 4).

The plate lies in the x-y plane: length ``L`` along x, width ``b`` along y, thickness
``h`` along z (the 2D beam's height ``h`` becomes the plate's thickness, its width
``b`` the strip's width), ``n_elements`` x ``n_width`` ``plate36`` elements.  The 2D
cantilever's vertical direction is mapped onto the plate's normal: the tip force ``F``
(signed, negative = along -z, default -5e8 h^3 N as the 2D scene) is spread uniformly
over the free edge x = L (consistent nodal forces), a dead load.  Clamp: r, r_x and r_y
(all three components) of every node at x = 0.  Nonlinear static solve: Newton with
adaptive load steps (``ancf.solvers.static``), then the stability check of the 2D
scenes.  Results ``tip_x``, ``tip_y``, ``tip_z``: the mean position of the tip-edge
nodes (tip_y = b/2 by symmetry).

The plate is a Kirchhoff plate (no transverse shear) with the plane-stress rigidity
E h^3 / (12 (1 - nu^2)) per unit width, so against the 2D (shear-deformable, E I)
cantilever it is stiffer by the shear flexibility and, for nu > 0, by the clamp's
restraint of the anticlastic curvature; with nu = 0 and a slender strip it converges
to the Euler-Bernoulli / Reissner rod (reports/elements3d.md).
"""
from __future__ import annotations

import math

import numpy as np

from ancf.scenes import accuracy, sense
from ancf.models.plate import edge_load, grid_points, strip_model, tip_mean
from ancf.scenes import beam_static as bs
from ancf.common.params import InputError, Param
from ancf.scenes.base import STATIC_RESULTS, STEEL_DENSITY, Scene, nullable


def params() -> tuple:
    base = {q.name: q for q in bs.element_params(nu=0.3, h=0.1, n_elements=8)}
    keep = ("n_elements", "E", "nu", "L", "h", "b", "rtol", "max_iterations",
            "stability_check")
    out = [base[k] for k in keep]
    out[0] = Param("n_elements", 8, int, doc="elements along the length", lo=1, hi=1024)
    out[4] = Param("h", 0.1, float, "m", "plate thickness (z; the 2D beam's height)", lo=0,
                   lo_open=True)
    out[5] = Param("b", 0.1, float, "m", "strip width (y)", lo=0, lo_open=True)
    return tuple(out) + (
        Param("n_width", 1, int, doc="elements across the width", lo=1, hi=64),
        Param("ng", 4, int, doc="Gauss points per direction", lo=1, hi=8),
        Param("F", lambda v: -5e8 * v["h"] ** 3, float, "N",
              "tip force along z spread over the free edge (default -5e8 h^3, negative = -z)"),
        Param("load_steps", 10, int, doc="initial number of load steps (adaptive)", lo=1,
              hi=10000),
    )


#: plate36 coordinates per node (r, r_x, r_y in 3D)
PER_NODE = 9


def check_cost(nx: int, ny: int) -> None:
    """InputError, the estimate stated, for an nx x ny plate36 grid whose band solve would
    not fit in memory (:func:`ancf.solvers.cost.affordable`)."""
    from ancf.solvers.cost import affordable, grid_bytes
    refused = affordable(grid_bytes(nx, ny, PER_NODE),
                         f"n_elements = {nx}: with {ny} across, the plate model "
                         f"({PER_NODE * (nx + 1) * (ny + 1)} coordinates)",
                         "a coarser mesh (fewer elements along or across)")
    if refused:
        raise InputError(refused)


def setup(p):
    """(mesh, q0, assembly, elimination, load vector) of the strip (density ``p["rho"]``
    if given); refused before anything is built when it would not fit in memory."""
    check_cost(p["n_elements"], p["n_width"])
    m, q0, asm, elim = strip_model(p["n_elements"], p["n_width"], p["L"], p["b"], p["h"],
                                   p["E"], p["nu"], p["ng"], p.get("rho", 0.0))
    return m, q0, asm, elim, edge_load(m, p["F"])


def run(p):
    m, q0, asm, elim, Qk = setup(p)
    return bs.solve(p, m, q0, asm, elim, Qk, lambda q: tip_mean(m, q))


def modal(p):
    m, q0, asm, elim, Qk = setup(p)
    return bs.modal(p, m, q0, asm, elim, Qk, grid_points(m), "mid-surface grid")


def edges(m, q) -> np.ndarray:
    """Chord lengths (m) of every element's sides A-B (along x, elements 1..nx ny) and A-D
    (along y, the next nx ny) between the nodes' positions in q."""
    r = grid_points(m)(q)
    a, b, d = (m.element_nodes[:, k] for k in (0, 1, 3))
    return np.concatenate([np.linalg.norm(r[b] - r[a], axis=1),
                           np.linalg.norm(r[d] - r[a], axis=1)])


def warn(p, res) -> list:
    """The static accuracy checks and, as the beams' area check, an element side stretched
    or shortened beyond its factor (:func:`ancf.scenes.sense.stretch`)."""
    out = accuracy.static(p, res)
    if res.converged and "q" in res.extra:
        m, q, q0 = res.extra["mesh"], res.extra["q"], res.extra["q0"]
        out += sense.stretch(edges(m, q), edges(m, q0), "element side", "a plate")
    return out


PLATE_STRIP_KNOBS = ("n_elements", "n_width", "ng", "load_steps", "rtol", "max_iterations",
                     "stability_check")


def _strip_tip_error(res, ref, p):
    """|tip - tip_ref| / |tip_ref - (L, b/2, 0)| over x, y, z."""
    d = math.dist((ref["tip_x"], ref["tip_y"], ref["tip_z"]), (p["L"], p["b"] / 2, 0.0))
    return math.dist((res["tip_x"], res["tip_y"], res["tip_z"]),
                     (ref["tip_x"], ref["tip_y"], ref["tip_z"])) / d


RESULTS = {**STATIC_RESULTS, "tip_x": nullable("mean x of the tip-edge nodes, m"),
           "tip_y": nullable("mean y of the tip-edge nodes (b/2 by symmetry), m"),
           "tip_z": nullable("mean z of the tip-edge nodes (along the load), m")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import SceneSpec, relative, self_reference
    refs = {"self": self_reference(
        "plate-strip", {"n_elements": 64, "n_width": 1, "ng": 4, "rtol": 1e-9, "load_steps": 10,
                        "max_iterations": 25},
        ("tip_x", "tip_y", "tip_z"), _strip_tip_error,
        "converged self-reference: 64 x 1 plate elements, Newton rtol 1e-9 (cached); error = "
        "|tip − tip_ref| / |tip_ref − (L, b/2, 0)|", check={"n_elements": 32},
        knobs=PLATE_STRIP_KNOBS, measure="relative tip-position error")}
    grid = ({"n_elements": [1, 2, 4, 8, 16], "rtol": [1e-8]},)
    return SceneSpec("plate-strip", PLATE_STRIP_KNOBS,
                     frozenset({"bending", "large-rotation", "3D"}), refs, "self",
                     report_grids=grid, recommend_grids=grid,
                     provides=frozenset({"axial", "bending", "large-rotation", "3D"}),
                     notes="The Model 1 cantilever as a thin-plate strip against a converged "
                           "self-reference.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 90
SCENE = Scene(
    "plate-strip",
    "The cantilever as a clamped thin-plate strip, out-of-plane tip load, large deflection.",
    params(), run, warn=warn, modal=modal, modal_params=(STEEL_DENSITY,),
    results=RESULTS, study=study)
