"""A continuum ANCF element = basis + strain model + material terms.

Strains are Green-Lagrange (Eqs 2.13-2.15) measured in the element's local
frame: ``eps = 1/2 (J^T J - J0^T J0)`` with ``J = [r_x r_y]`` the gradient with
respect to the local coordinates.  For the papers' straight beams along x,
``J0 = I`` and this is exactly ``1/2 (D^T D - I)`` with ``D = J J0^{-1}``; for a
rotated reference it stays in the beam's axes, which the anisotropic linear
element (E, E, ks G) needs.  The energy density is ``W = 1/2 eps^T C eps``.  The
strain energy is a sum of energy terms (:mod:`ancf.elements.material`), each with
its own quadrature rule; the bases of all terms are set side by side once
(:class:`~ancf.elements.basis.Basis`), and energy, gradient and tangent are one
call of the strain model's compiled kernel (:mod:`ancf.elements.green2d`).

A concrete element (``linear2d``, ``omar_shabana``, ``linear3d``) names its
shape-function ``family``, its nodal ``slots`` (each a dim-vector), its integration
``schemes`` and how its material splits into terms (a spatial one also its
``strain`` model, :mod:`ancf.elements.green3d`, and its ``basis``,
:class:`~ancf.elements.basis.SectionBasis`); it then satisfies
:class:`ancf.elements.contract.Element`.
"""
from __future__ import annotations

import numpy as np

from ancf.elements.basis import Basis, consistent_mass, family_shapes
from ancf.elements.green2d import GreenPlanar
from ancf.elements.material import scheme_terms
from ancf.core.quadrature import RectangularSection

_NO_TANGENT = np.zeros((0, 0, 0))


class ContinuumElement:
    """Elements of lengths ``lengths`` (nel,) m with reference coordinates ``e0`` (nel,
    ndof), cross-section ``section``, density ``rho`` kg/m^3 and energy ``terms``."""

    family: str = ""
    slots: tuple = ()
    schemes: dict = {}
    strain = GreenPlanar
    basis = Basis

    def __init__(self, lengths, e0, section: RectangularSection, terms, rho: float = 0.0):
        self.shapes = family_shapes(self.family)
        self.lengths = np.asarray(lengths, dtype=float)
        self.nel, self.nshape, self.dim = self.lengths.size, self.shapes["n"], self.strain.dim
        self.ndof = self.dim * self.nshape
        self.section, self.rho, self.terms = section, rho, tuple(terms)
        E0 = np.asarray(e0, dtype=float).reshape(self.nel, self.nshape, self.dim)
        self.points = self.basis.concat([self.basis(self.shapes, self.lengths, E0, section, t.nx, t.ny)
                                         for t in self.terms])
        self.C = np.ascontiguousarray(np.stack([np.asarray(t.C, dtype=float) for t in self.terms]))

    @classmethod
    def scheme_terms(cls, integration: str, C_normal, C_shear):
        """Energy terms of one of this element's schemes or of a spec (ValueError if bad)."""
        return scheme_terms(cls.schemes, integration, C_normal, C_shear)

    def _args(self, e):
        E = np.ascontiguousarray(e, dtype=float).reshape(self.nel, self.nshape, self.dim)
        p = self.points
        return (E, p.E0, *p.arrays(), self.C, p.cidx)

    def energy(self, e) -> np.ndarray:
        """Strain energy U of each element, J (e: (nel, ndof))."""
        return self.strain.energy(*self._args(e))

    def energy_samples(self, es) -> np.ndarray:
        """Strain energy U of each element at each of the states ``es`` (ns, nel, ndof),
        (ns, nel) J: one compiled call, each state's arithmetic that of :meth:`energy`."""
        es = np.ascontiguousarray(es, dtype=float)
        p = self.points
        E = es.reshape(es.shape[0] * self.nel, self.nshape, self.dim)
        U = self.strain.energy(E, p.E0, *p.arrays(), self.C, p.cidx)
        return U.reshape(es.shape[0], self.nel)

    def gradient(self, e, tangent: bool = False):
        """dU/de per element (nel, ndof) (Qe = -dU/de, Eq. 2.20) and optionally the
        exact tangent d2U/de2 (nel, ndof, ndof)."""
        g = np.zeros((self.nel, self.ndof))
        K = np.zeros((self.nel, self.ndof, self.ndof)) if tangent else _NO_TANGENT
        self.strain.gradient_tangent(*self._args(e), tangent, g, K)
        return g, (K if tangent else None)

    def mass(self) -> np.ndarray:
        """Exact consistent mass matrices (nel, ndof, ndof), Eq. 2.26, kg."""
        return consistent_mass(self.shapes, self.section, self.lengths, self.rho, self.dim)
