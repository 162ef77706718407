"""The Princeton beam (Dowell et al.; issue 24, item 4): ``beam3d-cantilever`` with the
published strip, material and load as defaults (:mod:`ancf.scenes.beam3d_published`).

L = 0.508 m, h = 12.3777e-3 m (y), b = 3.2024e-3 m (z), E = 71.7e9 Pa, nu = 0.31; tip
force ``F`` = -8.896 N (F2; F3 = -13.345 N) at ``load_angle_deg`` from -y towards -z
(the published beta turns towards +z: the mirror image, the same |u_y|, |u_z|).
``ks`` defaults to J/(I_y + I_z) (:func:`ancf.models.beam3d.torsion_factor`): the
elements' torsional stiffness k_s G (I_y + I_z) then equals St-Venant's G J of the thin
rectangle, as the reference's beam elements have it; with the element default 5/6 this
section is several times too stiff in torsion (reports/beam3d_benchmarks.md).  Results as
``beam3d-cantilever``: the tip position.
"""
from __future__ import annotations

import math

from ancf.models.beam3d import torsion_factor
from ancf.scenes import beam3d_cantilever as b3
from ancf.scenes import beam3d_published as pub
from ancf.scenes.base import STATIC_RESULTS, ReferenceFailed, Scene, nullable
from ancf.scenes.beam3d_published import PRINCETON, PRINCETON_LOADS

_P = PRINCETON
PRESETS = {
    "L": (_P["L"], "beam length (Princeton beam: 0.508)"),
    "h": (_P["h"], "section height (y) (Princeton beam: 12.3777e-3)"),
    "b": (_P["b"], "section width (z) (Princeton beam: 3.2024e-3)"),
    "E": (_P["E"], "Young's modulus (aluminium, 71.7e9)"),
    "nu": (_P["nu"], "Poisson's ratio (0.31)"),
    "n_elements": (16, "number of elements"),
    "ks": (lambda v: torsion_factor(v["h"], v["b"]),
           "shear correction factor, also of the torsional stiffness k_s G (I_y + I_z) "
           "(default J/(I_y + I_z), St-Venant's J of the rectangle)"),
    "F": (-PRINCETON_LOADS["F2"], f"tip force, negative = along -y at 0 deg (F2 = "
          f"-{PRINCETON_LOADS['F2']}, F3 = -{PRINCETON_LOADS['F3']})"),
    "load_angle_deg": (0.0, "angle of the tip force from -y towards -z (published: 0, 15, "
                            "..., 90)"),
}

def _princeton(p):
    """The published ANSYS beam tip displacements of the Princeton beam at p's load and
    angle, as signed tip positions y, z of our load (F (0, cos a, sin a))."""
    what = "Princeton beam (ANSYS, Obrezkov et al. 2022)"
    pub.check_published(p, {**pub.PRINCETON, "Mx": 0.0, "My": 0.0, "Mz": 0.0}, what)
    load = [k for k, f in pub.PRINCETON_LOADS.items() if math.isclose(abs(p["F"]), f,
                                                                     rel_tol=1e-12)]
    a = abs(p["load_angle_deg"])
    at = [i for i, b in enumerate(pub.PRINCETON_ANGLES) if math.isclose(a, b, abs_tol=1e-12)]
    if not load or not at:
        raise ReferenceFailed(f"{what}: published for |F| in {sorted(pub.PRINCETON_LOADS.values())} N "
                              f"and |load_angle_deg| in {list(pub.PRINCETON_ANGLES)} only")
    uy, uz = (c[at[0]] for c in pub.PRINCETON_ANSYS[load[0]][pub.PRINCETON_REFERENCE])
    r = math.radians(p["load_angle_deg"])
    return {"tip_y": math.copysign(uy, p["F"] * math.cos(r)),
            "tip_z": math.copysign(uz, p["F"] * math.sin(r))}


def _yz_error(res, ref, p):
    """|(y, z) - (y, z)_ref| / |(y, z)_ref| of the tip."""
    return (math.hypot(res["tip_y"] - ref["tip_y"], res["tip_z"] - ref["tip_z"])
            / math.hypot(ref["tip_y"], ref["tip_z"]))


RESULTS = {**STATIC_RESULTS, "tip_x": nullable("tip x, m"),
           "tip_y": nullable("tip y, m (u_y = tip_y)"),
           "tip_z": nullable("tip z, m (u_z = tip_z: the mirror image of the "
                             "published +z)")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import STATIC_KNOBS, Reference, SceneSpec, relative
    what = "|(y, z) − (y, z)_ref| / |(y, z)_ref| of the tip"
    measure = "relative tip-displacement (y, z) error"
    refs = {"published": Reference(
        "published", "published",
        "ANSYS beam elements (Obrezkov et al. 2022, as Exudyn's TestModels/ANCFBeamTest.py "
        f"lists them; F2, F3 at 0-90° in steps of 15°); error = {what}", _princeton,
        _yz_error, measure=measure),
        "self": b3.self_study("princeton-beam", ("tip_x", "tip_y", "tip_z"), _yz_error, what, measure)}
    return SceneSpec("princeton-beam", STATIC_KNOBS,
                     frozenset({"bending", "large-rotation", "3D"}), refs, "published",
                     report_grids=b3.RECOMMEND_GRIDS, recommend_grids=b3.RECOMMEND_GRIDS,
                     notes="The Princeton beam, F2 at 0° (defaults), against ANSYS beam "
                           "elements.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 120
SCENE = Scene(
    "princeton-beam",
    "The Princeton beam: the thin aluminium strip with a tip force at an angle (Dowell et "
    "al.; ANSYS references of Obrezkov et al. 2022).",
    b3.params(PRESETS), b3.run, b3.check, warn=b3.warn,
    results=RESULTS, study=study)
