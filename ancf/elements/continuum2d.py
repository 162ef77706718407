"""Continuum-mechanics kernel shared by the planar ANCF beam elements.

Strains are Green-Lagrange (Eqs 2.13-2.15) measured in the element's local
frame: ``eps = 1/2 (J^T J - J0^T J0)`` with ``J = [r_x r_y]`` the gradient with
respect to the local coordinates.  For the papers' straight beams along x,
``J0 = I`` and this is exactly ``1/2 (D^T D - I)`` with ``D = J J0^{-1}``; for a
rotated reference it stays in the beam's axes, which the anisotropic linear
element (E, E, ks G) needs.  The energy density is ``W = 1/2 eps^T C eps`` in Voigt form
``eps = [eps_xx, eps_yy, 2 eps_xy]``.  An element's strain energy is a sum of
:class:`EnergyTerm` s, each with its own material matrix and quadrature (this is
how selective integration is expressed).  Everything is vectorised over
elements x quadrature points; there is no Python loop over points.

Array shapes: ``E`` element coordinates (nel, nshape, 2), i.e. the element
vector ``e`` reshaped so that ``E[:, k, :]`` multiplies the scalar shape
function ``S_k``; ``B`` shape-function gradients (nel, nq, nshape).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ancf.quadrature import EXACT, RectangularSection, gauss01


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


def _strains(tq: TermQuadrature, E):
    """Current gradients r_x, r_y and local Green strains written with the
    displacement gradients u_x, u_y (u = r - r0):
    eps_xx = r0_x.u_x + u_x.u_x / 2, eps_yy = r0_y.u_y + u_y.u_y / 2,
    gamma = r0_x.u_y + r0_y.u_x + u_x.u_y.  This avoids the cancellation of
    (r_x.r_x - 1) / 2 under small displacements."""
    U = E - tq.E0
    uX, uY = _grad(tq.BX, U), _grad(tq.BY, U)
    dot = lambda a, b: np.einsum("eqd,eqd->eq", a, b)  # noqa: E731
    eps = np.stack([dot(tq.dX0, uX) + 0.5 * dot(uX, uX),
                    dot(tq.dY0, uY) + 0.5 * dot(uY, uY),
                    dot(tq.dX0, uY) + dot(tq.dY0, uX) + dot(uX, uY)], axis=-1)
    return tq.dX0 + uX, tq.dY0 + uY, eps


def term_energy(tq: TermQuadrature, E) -> np.ndarray:
    """Strain energy per element of one term, J."""
    _, _, eps = _strains(tq, E)
    W = 0.5 * np.einsum("eqi,ij,eqj->eq", eps, tq.C, eps)
    return np.einsum("eq,eq->e", tq.w, W)


def term_gradient(tq: TermQuadrature, E, tangent: bool = False):
    """dU/de per element (nel, nshape, 2) and, if asked, d2U/de2 (nel, ndof, ndof)."""
    dX, dY, eps = _strains(tq, E)
    s = eps @ tq.C  # second Piola-Kirchhoff stresses (Voigt), C symmetric
    PX = s[..., 0, None] * dX + s[..., 2, None] * dY
    PY = s[..., 1, None] * dY + s[..., 2, None] * dX
    grad = (np.einsum("eq,eqk,eqd->ekd", tq.w, tq.BX, PX)
            + np.einsum("eq,eqk,eqd->ekd", tq.w, tq.BY, PY))
    if not tangent:
        return grad, None
    nel, nq, n = tq.BX.shape
    # strain derivatives G[e,q,i,k,d] = d eps_i / d E_kd
    G = np.stack([tq.BX[..., None] * dX[:, :, None, :],
                  tq.BY[..., None] * dY[:, :, None, :],
                  tq.BX[..., None] * dY[:, :, None, :] + tq.BY[..., None] * dX[:, :, None, :]],
                 axis=2)
    wG = tq.w[:, :, None, None, None] * G
    Kmat = np.einsum("eqikd,ij,eqjlf->ekdlf", wG, tq.C, G, optimize=True)
    ws = tq.w[..., None] * s
    Kgeo = (np.einsum("eq,eqk,eql->ekl", ws[..., 0], tq.BX, tq.BX)
            + np.einsum("eq,eqk,eql->ekl", ws[..., 1], tq.BY, tq.BY)
            + np.einsum("eq,eqk,eql->ekl", ws[..., 2], tq.BX, tq.BY)
            + np.einsum("eq,eqk,eql->ekl", ws[..., 2], tq.BY, tq.BX))
    Kmat += Kgeo[:, :, None, :, None] * np.eye(2)[None, None, :, None, :]
    return grad, Kmat.reshape(nel, 2 * n, 2 * n)


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
        self.quad = [TermQuadrature(self.shapes, self.lengths, E0, section, t) for t in self.terms]

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
        return np.asarray(e, dtype=float).reshape(self.nel, self.nshape, 2)

    def energy(self, e) -> np.ndarray:
        """Strain energy U of each element, J (e: (nel, ndof))."""
        E = self._E(e)
        return sum(term_energy(tq, E) for tq in self.quad)

    def gradient(self, e, tangent: bool = False):
        """dU/de per element (nel, ndof) (Qe = -dU/de, Eq. 2.20) and optionally the
        exact tangent d2U/de2 (nel, ndof, ndof)."""
        E = self._E(e)
        g = np.zeros_like(E)
        K = np.zeros((self.nel, self.ndof, self.ndof)) if tangent else None
        for tq in self.quad:
            gi, Ki = term_gradient(tq, E, tangent)
            g += gi
            if tangent:
                K += Ki
        return g.reshape(self.nel, self.ndof), K

    def mass(self) -> np.ndarray:
        """Exact consistent mass matrices (nel, ndof, ndof), Eq. 2.26, kg."""
        m = np.stack([self.shapes["mass"](**self.section.moments(), l=li) for li in self.lengths])
        return self.rho * np.einsum("ekl,ij->ekilj", m, np.eye(2)).reshape(self.nel, self.ndof, self.ndof)
