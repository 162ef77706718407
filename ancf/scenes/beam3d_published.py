"""Published data of the 3D beam benchmarks (issue 24, item 4): problem data and reference
tip displacements, transcribed (data, not results).

Where they were read: J. Gerstmayr's Exudyn, ``main/pythonDev/TestModels/ANCFBeamTest.py``
(github.com/jgerstmayr/EXUDYN, commit e44aca1b4fe3e5f4d820ff407fb3fd30b6581c1c), which
lists both cases with their sources:

* **3D general bending**, Nachbagauer, Gruber, Gerstmayr, "Structural and continuum
  mechanics approaches for a 3D shear deformable ANCF beam finite element: application to
  static and linearized dynamic examples", J. Comput. Nonlinear Dynam. (2013), Table 4:
  a cantilever under the tip moments Mx (torsion) and My about the fixed global axes;
  tip displacements of the paper's structural mechanics formulation (SMF, 8 and 32
  elements) and of ANSYS (40 elements).  Exudyn's file lists the torsion correction
  factor ks1 = 0.5768 "if J = Jyy + Jzz" and shear correction factors ks2 = 0.8331 (y),
  ks3 = 0.7961 (z) for this case.
* **Princeton beam** (the experiment of Dowell et al.): an aluminium strip loaded at the
  tip by F at the angle beta from -y towards +z (F (0, -cos beta, sin beta)), the loads
  F2 = 8.896 N and F3 = 13.345 N; reference tip displacements |u_y|, u_z of ANSYS beam
  elements (10-199 elements) and ANSYS solid elements (4 x 12 x 500) from Obrezkov,
  Mikkola, Matikainen et al., "Performance review of locking alleviation methods for
  continuum ANCF beam elements", Nonlinear Dynamics 109 (2022); the height h = 12.3777e-3 m
  is "with Obrezkov's paper".  Exudyn lists ks1 = 0.198 (torsion) for it.

Displacements are magnitudes in m; their signs: the general bending tip moves to -x, -y,
-z; the Princeton tip to -x, -y and +z (our ``load_angle_deg`` turns the load towards -z:
the mirror image).  Sections: ``h`` along y, ``b`` along z.
"""
from __future__ import annotations

import math

from ancf.scenes.base import ReferenceFailed

#: Nachbagauer et al. 2013, 3D general bending: problem data (m, Pa, N m)
GENERAL_BENDING = dict(L=2.0, h=0.2, b=0.4, E=2.07e11, nu=0.3, Mx=0.5e6, My=2.0e6)
#: its torsion correction factor (J = ks1 (I_y + I_z)) and shear correction factors y, z
GENERAL_BENDING_KS_TORSION = 0.5768
GENERAL_BENDING_KS_SHEAR = (0.8331, 0.7961)
#: Table 4: row -> (elements, (|u_x|, |u_y|, |u_z|) m)
GENERAL_BENDING_TABLE_4 = {"SMF 8": (8, (1.0943e-4, 1.8638e-4, 1.8117e-2)),
                           "SMF 32": (32, (1.0943e-4, 1.8625e-4, 1.8117e-2)),
                           "ANSYS 40": (40, (1.0939e-4, 1.8646e-4, 1.8117e-2))}
GENERAL_BENDING_REFERENCE = "ANSYS 40"

#: Princeton beam: problem data (m, Pa)
PRINCETON = dict(L=0.508, h=12.3777e-3, b=3.2024e-3, E=71.7e9, nu=0.31)
PRINCETON_KS_TORSION_EXUDYN = 0.198
PRINCETON_LOADS = {"F2": 8.896, "F3": 13.345}  # N
PRINCETON_ANGLES = (0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0)  # deg
#: load -> model -> (|u_y| per angle, u_z per angle), m
PRINCETON_ANSYS = {
    "F2": {"beam": ((1.071417630e-2, 1.061328706e-2, 1.011169630e-2, 8.837226265e-3,
                     6.604665004e-3, 3.538889001e-3, 0.0),
                    (0.0, 4.208232124e-2, 7.939482948e-2, 0.108987937, 0.129887616,
                     0.142194370, 0.146245978)),
           "solid": ((1.069752828e-2, 1.057180106e-2, 9.938278402e-3, 8.686786771e-3,
                      6.500006282e-3, 3.481999513e-3, 0.0),
                     (0.0, 4.101165651e-2, 7.696749069e-2, 0.105976311, 0.127251299,
                      0.139594740, 0.143848652))},
    "F3": {"beam": ((1.606423724e-2, 1.645825752e-2, 1.665873206e-2, 1.518618440e-2,
                     1.157837500e-2, 6.248967384e-3, 0.0),
                    (0.0, 6.435812858e-2, 0.117735994, 0.156467239, 0.181861627,
                     0.196097131, 0.200677707)),
           "solid": ((1.603700622e-2, 1.637026068e-2, 1.640440775e-2, 1.485055210e-2,
                      1.127173264e-2, 6.062461977e-3, 0.0),
                     (0.0, 6.270699533e-2, 0.113752002, 0.153554457, 0.179978534,
                      0.192972233, 0.197669499))}}
PRINCETON_REFERENCE = "beam"


def check_published(p: dict, data: dict, what: str) -> None:
    """ReferenceFailed unless the problem parameters of p are the published ``data``."""
    for k, v in data.items():
        if not math.isclose(p[k], v, rel_tol=1e-12, abs_tol=0.0):
            raise ReferenceFailed(f"{what}: published for {k} = {v:g} only (got {p[k]:g})")
