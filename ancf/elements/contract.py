"""The element contract: what solvers, forces, energies and scenes may rely on.

Every element of the registry (:mod:`ancf.elements.registry`) satisfies it.  The
contract tests run over its constructions on a beam mesh (``CONTRACT_ELEMENTS`` of
:mod:`ancf.elements.catalogue`, derived from the registry; ``tests/elements/test_elements.py``:
finite-difference gradients and tangents, symmetry, rigid-motion invariance,
zero-energy-mode counts, exact mass) and over every record
(``tests/elements/test_registry.py``: the field at points, rigid motion, exact
tangent; for Chrono's elements, kinds beam, shell and solid of
:mod:`ancf.elements.chrono_element`, also zero internal force under rigid motion, six
zero-energy modes and the mass exact against the box's closed-form inertia), so a new
element gets them by being registered.  Shells and solids have no ``section`` (their
thickness ``h`` or sides are element sizes).
"""
from __future__ import annotations

from typing import Protocol

import numpy as np


class Element(Protocol):
    family: str          # generated shape-function family (analytic/shape_functions.py)
    slots: tuple         # nodal coordinate slots, each a dim-vector: ("r", "r_x", ...)
    schemes: dict        # named integration schemes -> term specs
    nel: int             # elements
    nshape: int          # shape functions per element
    dim: int             # space dimension of the nodal vectors
    ndof: int            # coordinates per element = dim * nshape
    lengths: np.ndarray  # (nel,) element lengths, m
    rho: float           # density, kg/m^3
    shapes: dict         # evaluators S, x, y of the family and its exact mass integral
    section: object      # cross-section (RectangularSection: b, h, rule, moments)

    def energy(self, e) -> np.ndarray:
        """Strain energy of each element (nel,), J, at element coordinates e (nel, ndof)."""

    def gradient(self, e, tangent: bool = False):
        """dU/de (nel, ndof), N, and the exact tangent (nel, ndof, ndof), N/m, or None."""

    def mass(self) -> np.ndarray:
        """Consistent mass matrices (nel, ndof, ndof), kg."""
