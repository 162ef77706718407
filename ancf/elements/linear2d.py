"""Kerkkänen's linear shear-deformable planar ANCF beam (8 DOF; thesis 2.1.1-2.2.1).

Nodal coordinates per node: ``r`` and ``dr/dy`` (Eq. 2.11); shape functions
Eq. 2.12; strain energy Eq. 2.18 without Poisson coupling,
``U = 1/2 int (E eps_xx^2 + E eps_yy^2 + 4 ks G eps_xy^2) dV``.

Integration schemes (``integration=``):

* ``thesis`` (default): closed form over the cross-section, 1 Gauss point along x
  for all terms (thesis 2.2.1, final form; Tables 2.1-2.4).
* ``exact``: every term integrated exactly (3 x 3 points): shows shear locking.
* ``report-selective``: 2 x 2 Gauss points for the normal strains and 1 x 1 for the
  shear strain (2003 report, section 5; Tables 1-4, 'No convergence' in Table 4).
* ``report-fix``: as above but 2 points across y for the shear strain, i.e. the
  y-dependent shear terms are no longer dropped (2003 report, Table 5).
* or a spec such as ``normal=2x2,shear=1xe`` (``e`` = exact across y).
"""
from __future__ import annotations

from ancf.elements.continuum2d import ContinuumElement
from ancf.elements.material import beam_material, scheme_terms


class LinearBeam2D(ContinuumElement):
    family = "linear2d"
    slots = ("r", "r_y")
    schemes = {
        "thesis": "normal=1xe,shear=1xe",
        "exact": "normal=3xe,shear=3xe",
        "report-selective": "normal=2x2,shear=1x1",
        "report-fix": "normal=2x2,shear=1x2",
    }

    def __init__(self, lengths, e0, section, E, nu, rho=0.0, ks=5.0 / 6.0, integration="thesis"):
        terms = scheme_terms(self.schemes, integration, *beam_material(E, nu, ks))
        super().__init__(lengths, e0, section, terms, rho)
