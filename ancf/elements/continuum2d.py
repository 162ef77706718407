"""Continuum-mechanics kernel shared by the planar ANCF beam elements.

Strains are Green-Lagrange (Eqs 2.13-2.15) measured in the element's local
frame: ``eps = 1/2 (J^T J - J0^T J0)`` with ``J = [r_x r_y]`` the gradient with
respect to the local coordinates.  For the papers' straight beams along x,
``J0 = I`` and this is exactly ``1/2 (D^T D - I)`` with ``D = J J0^{-1}``; for a
rotated reference it stays in the beam's axes, which the anisotropic linear
element (E, E, ks G) needs.  The energy density is ``W = 1/2 eps^T C eps`` in Voigt form
``eps = [eps_xx, eps_yy, 2 eps_xy]``.  An element's strain energy is a sum of
:class:`EnergyTerm` s, each with its own material matrix and quadrature (this is
how selective integration is expressed).  The points of all terms are set up
once (:class:`PointSet`); energy, gradient and tangent are then one call of the
compiled kernel (:mod:`ancf.elements.kernel2d`) over elements x points.

Array shapes: ``E`` element coordinates (nel, nshape, 2), i.e. the element
vector ``e`` reshaped so that ``E[:, k, :]`` multiplies the scalar shape
function ``S_k``; ``B`` shape-function gradients (nel, nq, nshape).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ancf.elements import kernel2d
from ancf.quadrature import EXACT, RectangularSection, gauss01

_NO_TANGENT = np.zeros((0, 0, 0))


@dataclass(frozen=True)
class EnergyTerm:
    """One part of the strain energy: material matrix ``C`` (3x3, Pa, acting on
    Voigt strains) integrated with ``nx`` Gauss points along the axis and ``ny``
    points (or ``"exact"``) across the height."""

    name: str
    C: np.ndarray
    nx: int
    ny: object


class TermQuadrature:
    """Precomputed gradients and weights of one energy term on a mesh."""

    def __init__(self, shapes, lengths, E0, section: RectangularSection, term: EnergyTerm):
        xi, wx = gauss01(term.nx)
        yq, wy = section.rule(term.ny)
        nel = lengths.shape[0]
        X = (xi[None, :, None] * lengths[:, None, None]) * np.ones((1, 1, yq.size))
        Y = np.broadcast_to(yq[None, None, :], X.shape)
        L = np.broadcast_to(lengths[:, None, None], X.shape)
        Bx = shapes["x"](X, Y, L).reshape(nel, -1, shapes["n"])
        By = shapes["y"](X, Y, L).reshape(nel, -1, shapes["n"])
        w = (wx[None, :, None] * wy[None, None, :] * lengths[:, None, None]).reshape(nel, -1)
        # reference configuration: J0 = [r0_x r0_y] per point (identity for a straight beam)
        self.BX, self.BY = Bx, By
        self.dX0, self.dY0 = _grad(Bx, E0), _grad(By, E0)
        J0 = np.stack([self.dX0, self.dY0], axis=-1)  # (nel, nq, 2, 2)
        self.w = w * np.abs(np.linalg.det(J0))  # reference volume element
        self.C = np.asarray(term.C, dtype=float)
        self.E0 = E0


def _grad(B, E):
    return np.einsum("eqk,ekd->eqd", B, E)


class PointSet:
    """The quadrature points of all energy terms side by side: gradients BX, BY
    (nel, nq, nshape), reference gradients dX0, dY0 (nel, nq, 2), weights w (nel, nq),
    material matrices C (nterm, 3, 3) and the term of each point ``cidx`` (nq,)."""

    def __init__(self, quads):
        cat = lambda name: np.ascontiguousarray(np.concatenate([getattr(t, name) for t in quads], 1))  # noqa: E731
        self.BX, self.BY, self.dX0, self.dY0, self.w = (cat(a) for a in ("BX", "BY", "dX0", "dY0", "w"))
        self.C = np.ascontiguousarray(np.stack([t.C for t in quads]))
        self.cidx = np.concatenate([np.full(t.w.shape[1], i, dtype=np.int64) for i, t in enumerate(quads)])
        self.E0 = np.ascontiguousarray(quads[0].E0)

    def args(self, E):
        return (E, self.E0, self.BX, self.BY, self.dX0, self.dY0, self.w, self.C, self.cidx)


def lame_matrix(E: float, nu: float) -> np.ndarray:
    """Eq. 2.17: plane-strain matrix of Lamé constants, Pa."""
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    mu = E / (2.0 * (1.0 + nu))
    return np.array([[lam + 2 * mu, lam, 0.0], [lam, lam + 2 * mu, 0.0], [0.0, 0.0, mu]])


def _merge_same_rule(terms):
    """Terms sharing a quadrature rule are one term with the summed material matrix
    (the thesis scheme then costs one kernel evaluation, not two)."""
    merged = {}
    for t in terms:
        key = (t.nx, t.ny)
        if key in merged:
            m = merged[key]
            merged[key] = EnergyTerm(f"{m.name}+{t.name}", m.C + t.C, t.nx, t.ny)
        else:
            merged[key] = t
    return list(merged.values())


def parse_rule(text: str):
    """'2x2' -> (2, 2); '1xe' -> (1, 'exact')."""
    try:
        nx, ny = text.lower().split("x")
        ny = EXACT if ny in ("e", "exact") else int(ny)
        nx = int(nx)
        if nx < 1 or (ny != EXACT and ny < 1):
            raise ValueError
        return nx, ny
    except ValueError:
        raise ValueError(f"integration rule {text!r} must look like 'NXxNY' with NX >= 1 "
                         f"Gauss points along x and NY >= 1 or 'e' (exact) across y") from None


def family_shapes(family: str) -> dict:
    """The generated shape-function evaluators of a family (see analytic/shape_functions)."""
    from ancf.elements import _generated as gen

    fns = {d: getattr(gen, f"{family}_{d}") for d in ("S", "x", "y")}
    fns["n"] = fns["S"](np.zeros(1), np.zeros(1), np.ones(1)).shape[-1]
    fns["mass"] = getattr(gen, f"{family}_mass")
    return fns


class ContinuumBeam2D:
    """Base of the planar continuum-mechanics ANCF beams.

    Subclasses set ``family`` (generated shape functions), ``slots`` (names of the
    nodal coordinates of one node, each a 2-vector) and build ``terms``.
    ``lengths`` (nel,) element lengths in m; ``e0`` (nel, ndof) reference element
    coordinates; ``section`` the cross-section; ``rho`` density in kg/m^3.
    """

    family: str = ""
    slots: tuple = ()
    schemes: dict = {}

    def __init__(self, lengths, e0, section: RectangularSection, terms, rho: float = 0.0):
        self.shapes = family_shapes(self.family)
        self.lengths = np.asarray(lengths, dtype=float)
        self.nel = self.lengths.size
        self.nshape = self.shapes["n"]
        self.ndof = 2 * self.nshape
        self.section, self.rho, self.terms = section, rho, tuple(terms)
        E0 = np.asarray(e0, dtype=float).reshape(self.nel, self.nshape, 2)
        self.points = PointSet([TermQuadrature(self.shapes, self.lengths, E0, section, t)
                                for t in self.terms])

    @classmethod
    def scheme_terms(cls, integration: str, C_normal, C_shear):
        """Energy terms of a named scheme or of a spec 'normal=2x2,shear=1x1'."""
        if not isinstance(integration, str):
            raise ValueError(f"integration must be one of {sorted(cls.schemes)} or a spec like "
                             f"'normal=2x2,shear=1x1' (got {integration!r})")
        spec = cls.schemes.get(integration, integration)
        terms = []
        for part in spec.split(","):
            try:
                group, rule = (s.strip() for s in part.split("="))
            except ValueError:
                raise ValueError(f"integration must be one of {sorted(cls.schemes)} or a spec like "
                                 f"'normal=2x2,shear=1x1' (got {integration!r})") from None
            C = {"normal": C_normal, "shear": C_shear, "all": C_normal + C_shear}.get(group)
            if C is None:
                raise ValueError(f"integration group {group!r} must be normal, shear or all")
            terms.append(EnergyTerm(group, C, *parse_rule(rule)))
        groups = sorted(t.name for t in terms)
        if groups not in (["all"], ["normal", "shear"]):
            raise ValueError(f"integration spec {integration!r} must give each of 'normal' and "
                             f"'shear' once, or 'all' alone (got {', '.join(groups)})")
        return _merge_same_rule(terms)

    def _E(self, e):
        return np.ascontiguousarray(e, dtype=float).reshape(self.nel, self.nshape, 2)

    def energy(self, e) -> np.ndarray:
        """Strain energy U of each element, J (e: (nel, ndof))."""
        return kernel2d.energy(*self.points.args(self._E(e)))

    def gradient(self, e, tangent: bool = False):
        """dU/de per element (nel, ndof) (Qe = -dU/de, Eq. 2.20) and optionally the
        exact tangent d2U/de2 (nel, ndof, ndof)."""
        g = np.zeros((self.nel, self.ndof))
        K = np.zeros((self.nel, self.ndof, self.ndof)) if tangent else _NO_TANGENT
        kernel2d.gradient_tangent(*self.points.args(self._E(e)), tangent, g, K)
        return g, (K if tangent else None)

    def mass(self) -> np.ndarray:
        """Exact consistent mass matrices (nel, ndof, ndof), Eq. 2.26, kg."""
        m = np.stack([self.shapes["mass"](**self.section.moments(), l=li) for li in self.lengths])
        return self.rho * np.einsum("ekl,ij->ekilj", m, np.eye(2)).reshape(self.nel, self.ndof, self.ndof)
