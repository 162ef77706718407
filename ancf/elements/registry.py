"""The element registry: every element, one :class:`ElementType` record each, in :data:`ELEMENTS`.

A record names the element, its space dimension (2, 3), its kind (beam, plate, belt,
shell, solid), its nodes per element, its basis (a generated shape-function family of
``analytic/shape_functions.py``, or for a family not generated there, as Chrono's
elements', the class's ``own_shapes``; the coordinates per node follow from it), its
strain model and material law, its class (``module:Class``, imported on first use so
that a scene loads only the elements it builds) and how a scene's parameters become
the class's keyword arguments.  :meth:`ElementType.field` interpolates element
coordinates at points: positions, slopes and Green's strain.

The other lookups are views of this table: ``catalogue.CATALOGUE`` (the planar beams
of the beam scenes), ``catalogue.CONTRACT_ELEMENTS`` (the variants the contract tests
build on a beam mesh) and ``models.beam3d.BUILDERS`` (the 3D elements of a beam mesh).
A new element is its module plus one record here; the contract tests of
``tests/elements/test_registry.py`` then run over it.
"""
from __future__ import annotations

import importlib
from dataclasses import dataclass
from typing import Callable, NamedTuple

import numpy as np

from ancf.elements import basis
from ancf.elements.basis import family_shapes

KINDS = ("beam", "plate", "belt", "shell", "solid", "cable")

#: the physics an element can model; ``ancf recommend`` proposes only models providing the
#: physics a question needs (``ancf.study.references.model_physics``)
PHYSICS = ("axial", "bending", "shear", "large-rotation", "inertia", "contact", "3D")
_BEAM = frozenset({"axial", "bending", "shear", "large-rotation", "inertia"})


class Field(NamedTuple):
    """An element field at points: ``r`` (nel, npts, dim) positions, m; ``slopes``
    (nel, npts, nd, dim) dr/dX_i (-) along the nd reference directions of the family
    (x, y[, z] of a beam, x, y of a plate's mid surface); ``strain`` (nel, npts, nd, nd)
    Green's strain E = (F^T F - F0^T F0)/2 (-) with F = [dr/dX_i] (Eq. 2.30; a plate:
    the mid-surface strain of Eq. 4.16)."""

    r: np.ndarray
    slopes: np.ndarray
    strain: np.ndarray


def _linear3d_options(p: dict) -> dict:
    """The 3D beam's shear correction and integration scheme."""
    return {"ks": p["ks"], "integration": p["integration"]}


def _belt3d_options(p: dict) -> dict:
    """Dufva's spatial belt element on a beam mesh: ks, the stiffness parameters
    alpha1, alpha2 (Eq. 4.40, default 1) and ``elastic_points`` along the axis (default 5)."""
    return {"ks": p["ks"], "alpha1": p.get("alpha1", 1.0), "alpha2": p.get("alpha2", 1.0),
            "nx": p.get("elastic_points", 5)}


_ALPHA = {"alpha1": 0.6, "alpha2": 0.05, "nx": 3}  # a contract variant off the defaults


@dataclass(frozen=True, kw_only=True)
class ElementType:
    """One element: see the module docstring.  ``options`` turns a scene's parameters
    into the class's keyword arguments (default: the :attr:`knobs` present);
    ``variants`` are the contract-test constructions on a beam mesh, (suffix, keyword
    arguments)."""

    name: str       # the public name (``element=`` of the scenes)
    dim: int        # space dimension of the nodal vectors, 2 or 3
    kind: str       # one of KINDS
    family: str     # the basis: generated shape-function family
    nodes: int      # nodes per element
    strain: str     # the strain model (module)
    material: str   # the material law
    path: str       # "module:Class"
    doc: str
    physics: frozenset  # what it models (a subset of PHYSICS): the recommender's filter
    knobs: tuple = ()  # element-specific parameters besides E, nu, rho, integration
    options: Callable[[dict], dict] | None = None  # scene parameters -> keyword arguments
    variants: tuple | None = None  # (default: one per integration scheme)

    @property
    def cls(self) -> type:
        """The element class, imported on first use."""
        module, name = self.path.split(":")
        return getattr(importlib.import_module(module), name)

    def shapes(self) -> dict:
        """The basis: the family's generated evaluators (see basis.family_shapes), or the
        class's own (``own_shapes``) when the family is not a generated one."""
        if not hasattr(basis, f"{self.family}_S"):
            return self.cls.own_shapes()
        return family_shapes(self.family)

    @property
    def coordinates_per_node(self) -> int:
        """dim times the shape functions per node."""
        return self.dim * self.shapes()["n"] // self.nodes

    @property
    def ndof(self) -> int:
        """Coordinates per element."""
        return self.coordinates_per_node * self.nodes

    def build(self, p: dict) -> tuple:
        """(element class, its keyword arguments from the scene parameters p)."""
        return self.cls, (self.options(p) if self.options else self.knob_values(p))

    def knob_values(self, p: dict) -> dict:
        """The element-specific keyword arguments :attr:`knobs` present in p."""
        return {k: p[k] for k in self.knobs if k in p}

    def directions(self) -> str:
        """The family's reference directions: x, y of a plate, x of a cable (its one
        slope), x, y[, z] of a beam."""
        return {"plate": "xy", "cable": "x"}.get(self.kind, "xyz"[:self.dim])

    def _points(self, size, xi, eta, zeta) -> tuple:
        """Arguments of the evaluators at xi (and eta, zeta) in [0, 1]: beams on the
        centre line X = xi l (size: lengths (nel,)), plates at (xi a, eta b) (size: (a, b),
        each (nel,) or scalar), shells on the mid-surface (xi a, eta b, 0), solids at
        (xi a, eta b, zeta c) (size (a, b, c))."""
        xi = np.atleast_1d(np.asarray(xi, dtype=float))
        if self.kind in ("plate", "shell", "solid"):
            sides = [np.asarray(v, dtype=float).reshape(-1, 1) for v in size]
            local = [np.broadcast_to(np.asarray(v, dtype=float), xi.shape) for v in (eta, zeta)]
            X = [u[None, :] * a for u, a in zip((xi, *local), sides)]
            if self.kind == "shell":
                X.append(np.zeros_like(X[0]))
            return (*X, *sides)
        l = np.asarray(size, dtype=float).reshape(-1, 1)
        return (xi[None, :] * l, *(np.zeros((1, xi.size)),) * (self.dim - 1), l)

    def field(self, e, size, xi, eta=0.0, e0=None, *, zeta=0.0) -> Field:
        """The :class:`Field` of element coordinates e (nel, ndof) (ordered shape function
        k times dim plus component) at local coordinates xi (npts,) in [0, 1] (and eta,
        the plate's second one, zeta a solid's third), r = S e (Eq. 2.10).  ``size``: element
        lengths (nel,) m, or (a, b) of plates and shells, (a, b, c) of solids; ``e0`` the
        reference coordinates (default: F0 = I, the straight or flat reference of the
        meshes)."""
        fns, args = self.shapes(), self._points(size, xi, eta, zeta)
        nel = args[-1].shape[0]
        E = np.asarray(e, dtype=float).reshape(nel, fns["n"], self.dim)
        F = self._gradient(fns, args, E)
        F0 = np.eye(self.dim)[:len(self.directions())] if e0 is None else self._gradient(
            fns, args, np.asarray(e0, dtype=float).reshape(E.shape))
        G0 = np.einsum("...id,...jd->...ij", F0, F0)
        strain = 0.5 * (np.einsum("...id,...jd->...ij", F, F) - G0)
        return Field(np.einsum("eqk,ekd->eqd", fns["S"](*args), E), F, strain)

    def _gradient(self, fns, args, E) -> np.ndarray:
        """F: dr/dX_i (nel, npts, nd, dim) along the family's directions."""
        return np.stack([np.einsum("eqk,ekd->eqd", fns[d](*args), E) for d in self.directions()], -2)


_CHRONO_STRAIN = "ancf.elements.continuum3d"
_BEAM_LAW = "St Venant-Kirchhoff, k1 = k2 = ks on the shears, Poisson part on the axis"
_SOLID = frozenset({"axial", "bending", "shear", "large-rotation", "inertia", "3D"})
#: Chrono's ANCF elements (``ancf.elements.chrono_element``, one exact rule each; the 3423
#: its own module, 2 x 2 x 2 Gauss points)
_CHRONO = (
    ElementType(name="ancf3243", dim=3, kind="beam", family="cubic3d", nodes=2,
                strain=_CHRONO_STRAIN, material=_BEAM_LAW,
                path="ancf.elements.chrono_element:Beam3243", knobs=("ks",),
                variants=(("", {}),), physics=_BEAM | {"3D"},
                doc="Chrono's fully parameterised beam ChElementBeamANCF_3243, 24 coordinates"),
    ElementType(name="ancf3333", dim=3, kind="beam", family="ancf3333", nodes=3,
                strain=_CHRONO_STRAIN, material=_BEAM_LAW,
                path="ancf.elements.chrono_element:Beam3333", knobs=("ks",), variants=(),
                physics=_BEAM | {"3D"},
                doc="Chrono's 3-node shear-deformable beam ChElementBeamANCF_3333, "
                    "27 coordinates"),
    ElementType(name="ancf3423", dim=3, kind="shell", family="ancf3423", nodes=4,
                strain="ancf.elements.ancf3423",
                material="isotropic 3D St Venant-Kirchhoff, ANS thickness and transverse "
                         "shear strains, five EAS modes condensed per element",
                path="ancf.elements.ancf3423:Shell3423", variants=(), physics=_SOLID,
                doc="Chrono's 4-node ANS/EAS shell ChElementShellANCF_3423, 24 coordinates"),
    ElementType(name="ancf3443", dim=3, kind="shell", family="ancf3443", nodes=4,
                strain=_CHRONO_STRAIN, material="isotropic 3D St Venant-Kirchhoff (Chrono's)",
                path="ancf.elements.chrono_element:Shell3443", variants=(), physics=_SOLID,
                doc="Chrono's 4-node shell ChElementShellANCF_3443, 48 coordinates"),
    ElementType(name="ancf3833", dim=3, kind="shell", family="ancf3833", nodes=8,
                strain=_CHRONO_STRAIN, material="isotropic 3D St Venant-Kirchhoff",
                path="ancf.elements.chrono_element:Shell3833", variants=(), physics=_SOLID,
                doc="Chrono's 8-node higher-order shell ChElementShellANCF_3833, 72 coordinates"),
    ElementType(name="ancf3843", dim=3, kind="solid", family="ancf3843", nodes=8,
                strain=_CHRONO_STRAIN, material="isotropic 3D St Venant-Kirchhoff",
                path="ancf.elements.chrono_element:Brick3843", variants=(), physics=_SOLID,
                doc="Chrono's 8-node brick ChElementHexaANCF_3843, 96 coordinates"),
)

ELEMENTS = {t.name: t for t in (
    ElementType(name="linear", dim=2, kind="beam", family="linear2d", nodes=2,
                strain="ancf.elements.green2d",
                material="beam_material (Eq. 2.18 without Poisson coupling, ks G shear)",
                path="ancf.elements.linear2d:LinearBeam2D", knobs=("ks",),
                physics=_BEAM,
                doc="Kerkkänen's linear shear-deformable beam, 8 coordinates"),
    ElementType(name="omar-shabana", dim=2, kind="beam", family="cubic2d", nodes=2,
                strain="ancf.elements.green2d", material="lame_matrix (Eq. 2.17, plane strain)",
                path="ancf.elements.omar_shabana:OmarShabana2D",
                physics=_BEAM,
                doc="Omar and Shabana's beam, 12 coordinates"),
    ElementType(name="linear3d", dim=3, kind="beam", family="linear3d", nodes=2,
                strain="ancf.elements.green3d",
                material="beam_material_3d (Eq. 2.18 in 3D, ks G shear)",
                path="ancf.elements.linear3d:LinearBeam3D", knobs=("ks",),
                options=_linear3d_options,
                physics=_BEAM | {"3D"},
                doc="the spatial linear shear-deformable beam, 18 coordinates"),
    ElementType(name="belt2d", dim=2, kind="belt", family="cubic2d", nodes=2,
                strain="ancf.elements.dufva2d",
                material="Dufva's densities: E A alpha1, E I alpha2, ks G A (thesis 3.1)",
                path="ancf.elements.dufva2d:DufvaBelt2D", knobs=("alpha1", "alpha2", "ks"),
                variants=(("", {}), ("alpha", _ALPHA)),
                physics=_BEAM,
                doc="Dufva's planar belt element, 12 coordinates"),
    ElementType(name="belt3d", dim=3, kind="belt", family="cubic3d", nodes=2,
                strain="ancf.elements.belt3d",
                material="Dufva's densities: E A alpha1, E I alpha2, ks G A alpha2 (Eqs 4.40-4.42)",
                path="ancf.elements.belt3d:DufvaBelt3D", knobs=("alpha1", "alpha2", "ks"),
                options=_belt3d_options, variants=(("", {}), ("alpha", _ALPHA)),
                physics=_BEAM | {"3D"},
                doc="Dufva's spatial belt element, 24 coordinates"),
    ElementType(name="plate36", dim=3, kind="plate", family="plate36", nodes=4,
                strain="ancf.elements.plate36",
                material="plane stress membrane E h/(1 - nu^2), Kirchhoff bending D (Eqs 4.16-4.17)",
                path="ancf.elements.plate36:Plate36", knobs=("ng",), variants=(),
                physics=frozenset({"axial", "bending", "large-rotation", "inertia", "3D"}),
                doc="Dufva and Shabana's thin plate, 36 coordinates"),
    *_CHRONO,
    ElementType(name="cable3d", dim=3, kind="cable", family="cable3d", nodes=2,
                strain="ancf.elements.cable3d",
                material="E A on the Green axial strain, E I on the curvature |r_x x r_xx| / "
                         "|r_x|^3 (Gerstmayr and Shabana 2006)",
                path="ancf.elements.cable3d:Cable3D", variants=(),
                physics=frozenset({"axial", "bending", "large-rotation", "inertia", "3D"}),
                doc="Chrono's gradient-deficient cable ChElementCableANCF, 12 coordinates"),
)}


def contract_variants() -> dict:
    """The contract-test constructions on a beam mesh (name -> (class, keyword arguments)):
    one per integration scheme of the beams, the listed variants of the belts; ids the
    class name and the suffix."""
    out = {}
    for t in ELEMENTS.values():
        variants = t.variants if t.variants is not None else tuple(
            (s, {"integration": s}) for s in t.cls.schemes)
        out.update({t.cls.__name__ + (f"-{s}" if s else ""): (t.cls, kw) for s, kw in variants})
    return out
