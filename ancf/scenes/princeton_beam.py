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

from ancf.models.beam3d import torsion_factor
from ancf.scenes import beam3d_cantilever as b3
from ancf.scenes.base import Scene
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

SCENE = Scene(
    "princeton-beam",
    "The Princeton beam: the thin aluminium strip with a tip force at an angle (Dowell et "
    "al.; ANSYS references of Obrezkov et al. 2022).",
    b3.params(PRESETS), b3.run, b3.check, warn=b3.warn)
