"""Omar and Shabana's shear-deformable planar ANCF beam (12 DOF; thesis Eqs 2.2-2.3).

Nodal coordinates per node: ``r``, ``dr/dx``, ``dr/dy``; cubic along x, linear
across y.  Strain energy Eq. 2.16 with the Lamé matrix of Eq. 2.17 (full
Poisson coupling, hence Poisson locking for nu > 0).

Integration (``integration=``): ``thesis`` (default) closed form over the
cross-section and 4 Gauss points along x (thesis 2.4); ``exact`` 5 points along x
(every term exact); or a spec such as ``all=3x2``.
"""
from __future__ import annotations

import numpy as np

from ancf.elements.continuum2d import ContinuumElement
from ancf.elements.material import lame_matrix, scheme_terms


class OmarShabana2D(ContinuumElement):
    family = "cubic2d"
    slots = ("r", "r_x", "r_y")
    schemes = {"thesis": "all=4xe", "exact": "all=5xe"}

    def __init__(self, lengths, e0, section, E, nu, rho=0.0, integration="thesis"):
        terms = scheme_terms(self.schemes, integration, lame_matrix(E, nu), np.zeros((3, 3)))
        super().__init__(lengths, e0, section, terms, rho)
