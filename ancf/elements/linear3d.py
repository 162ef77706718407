"""The 3D generalisation of Kerkkänen's linear shear-deformable beam (18 DOF;
thesis 4.4, Eqs 4.20-4.22; 2003 report section 4).

Nodal coordinates per node: ``r``, ``dr/dy`` and ``dr/dz`` (Eq. 4.21); shape
functions Eq. 4.22 (family ``linear3d``); strain energy the 2D element's
(:mod:`ancf.elements.linear2d`) in three dimensions, without Poisson coupling:
``U = 1/2 int (E (eps_xx^2 + eps_yy^2 + eps_zz^2)
+ 4 ks G (eps_yz^2 + eps_xz^2 + eps_xy^2)) dV``.

Integration schemes: those of the 2D element, the section rule now taken in both
y and z (``NXxNY`` = NX Gauss points along x times NY x NY over the section; ``e`` =
exact over the section):

* ``thesis`` (default): closed form over the section, 1 Gauss point along x.
* ``exact``: every term integrated exactly (3 points along x).
* ``report-selective``: 2 x (2 x 2) points for the normal strains, 1 x (1 x 1) for
  the shear strains.
* ``report-fix``: as above but 2 x 2 section points for the shear strains.
* or a spec such as ``normal=2x2,shear=1xe``.

The section's displacement field is linear in y and z (r = r_c + y r_y + z r_z),
so a twist turns the section rigidly without warping: the torsional stiffness is
``ks G (I_y + I_z)`` rather than St-Venant's ``G J``.
"""
from __future__ import annotations

from ancf.elements.basis import SectionBasis
from ancf.elements.continuum2d import ContinuumElement
from ancf.elements.green3d import GreenSpatial
from ancf.elements.material import beam_material_3d, scheme_terms
from ancf.elements.linear2d import LinearBeam2D


class LinearBeam3D(ContinuumElement):
    family = "linear3d"
    slots = ("r", "r_y", "r_z")
    schemes = LinearBeam2D.schemes
    strain = GreenSpatial
    basis = SectionBasis

    def __init__(self, lengths, e0, section, E, nu, rho=0.0, ks=5.0 / 6.0, integration="thesis"):
        terms = scheme_terms(self.schemes, integration, *beam_material_3d(E, nu, ks))
        super().__init__(lengths, e0, section, terms, rho)
