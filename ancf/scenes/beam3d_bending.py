"""Nachbagauer, Gruber and Gerstmayr's 3D general bending (2013, Table 4; issue 24,
item 4): ``beam3d-cantilever`` under the tip moments Mx (torsion) and My about the fixed
global axes, no force (:mod:`ancf.scenes.beam3d_published`).

L = 2 m, h = 0.2 m (y), b = 0.4 m (z), E = 2.07e11 Pa, nu = 0.3, Mx = 0.5e6 N m,
My = 2e6 N m.  ``ks`` defaults to the published torsion correction 0.5768 (J = k_s
(I_y + I_z)); under pure moments the elements carry no shear force, so k_s acts on the
torsion (and, at second order, on the shear of a twisted bent continuum: see
reports/beam3d_benchmarks.md).  Results as ``beam3d-cantilever``: the tip position.
"""
from __future__ import annotations

from ancf.scenes import beam3d_cantilever as b3
from ancf.scenes import beam3d_published as pub
from ancf.scenes.base import STATIC_RESULTS, Scene, nullable
from ancf.scenes.beam3d_published import GENERAL_BENDING, GENERAL_BENDING_KS_TORSION

_P = GENERAL_BENDING
PRESETS = {
    "L": (_P["L"], "beam length (2)"),
    "h": (_P["h"], "section height (y) (0.2)"),
    "b": (_P["b"], "section width (z) (0.4)"),
    "E": (_P["E"], "Young's modulus (2.07e11)"),
    "nu": (_P["nu"], "Poisson's ratio (0.3)"),
    "n_elements": (32, "number of elements"),
    "ks": (GENERAL_BENDING_KS_TORSION, "shear correction factor, also of the torsional "
           "stiffness k_s G (I_y + I_z) (published torsion correction 0.5768)"),
    "F": (0.0, "tip force, negative = along -y at load_angle_deg = 0 (none in the "
               "published case)"),
    "Mx": (_P["Mx"], "tip moment about the global x axis (torsion, fixed direction; "
                     "published 0.5e6)"),
    "My": (_P["My"], "tip moment about the global y axis (fixed direction; published 2e6)"),
}

def _general_bending(p):
    """Nachbagauer et al. 2013, Table 4, ANSYS: the tip position (it moves to -x, -y, -z)."""
    pub.check_published(p, {**pub.GENERAL_BENDING, "Mz": 0.0, "F": 0.0},
                       "3D general bending (Nachbagauer et al. 2013, Table 4)")
    ux, uy, uz = pub.GENERAL_BENDING_TABLE_4[pub.GENERAL_BENDING_REFERENCE][1]
    return {"tip_x": p["L"] - ux, "tip_y": -uy, "tip_z": -uz}


def _displacement_error(res, ref, p):
    """Largest relative error of the three tip displacements u = tip - (L, 0, 0)."""
    return max(abs((res[k] - ref[k]) / (ref[k] - o))
               for k, o in (("tip_x", p["L"]), ("tip_y", 0.0), ("tip_z", 0.0)))


RESULTS = {**STATIC_RESULTS, "tip_x": nullable("tip x, m (u_x = tip_x - L)"),
           "tip_y": nullable("tip y, m"), "tip_z": nullable("tip z, m")}


def study():
    """What sweeps measure this scene against: its references, errors and grids."""
    from ancf.scenes.spec import STATIC_KNOBS, Reference, SceneSpec, relative
    what = "largest relative error of the tip displacements u_x, u_y, u_z"
    measure = "largest relative tip-displacement error"
    refs = {"published": Reference(
        "published", "published",
        "Nachbagauer et al. 2013, Table 4, ANSYS (40 elements), as Exudyn's "
        f"TestModels/ANCFBeamTest.py lists it; error = {what}", _general_bending,
        _displacement_error, measure=measure),
        "self": b3.self_study("beam3d-bending", ("tip_x", "tip_y", "tip_z"), _displacement_error, what,
                         measure)}
    return SceneSpec("beam3d-bending", STATIC_KNOBS, frozenset({"bending", "large-rotation",
                                                                 "3D"}),
                     refs, "published", report_grids=b3.RECOMMEND_GRIDS,
                     recommend_grids=b3.RECOMMEND_GRIDS,
                     notes="3D general bending (Mx = 0.5e6, My = 2e6 N m) against ANSYS.")


#: the scene's place in the scene list (ancf.scenes.MODULES, ancf scenes, reports/schemas.md)
ORDER = 130
SCENE = Scene(
    "beam3d-bending",
    "3D general bending (Nachbagauer et al. 2013, Table 4): the cantilever under tip "
    "moments about x (torsion) and y.",
    b3.params(PRESETS), b3.run, b3.check, warn=b3.warn,
    results=RESULTS, study=study)
