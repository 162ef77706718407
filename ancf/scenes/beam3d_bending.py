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
from ancf.scenes.base import Scene
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

SCENE = Scene(
    "beam3d-bending",
    "3D general bending (Nachbagauer et al. 2013, Table 4): the cantilever under tip "
    "moments about x (torsion) and y.",
    b3.params(PRESETS), b3.run, b3.check, warn=b3.warn)
