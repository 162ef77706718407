"""A basis: a generated shape-function family bound to a mesh, at elements x points.

The family (``analytic/shape_functions.py`` -> ``_generated.py``) gives the shape
functions S and their derivatives along x and y; the mesh gives the element
lengths and the reference element coordinates ``E0`` (nel, nshape, dim); a
quadrature rule (``nx`` Gauss points along the axis, ``ny`` across the section or
``"exact"``) gives the points.  A :class:`Basis` holds, at every element x point,
the shape-function derivatives ``BX``, ``BY`` (nel, nq, nshape), the reference
gradients ``dX0``, ``dY0`` (nel, nq, dim) and the weights ``w`` (nel, nq) times the
reference volume element; :meth:`Basis.concat` sets several rules side by side
(one per energy term) for a single kernel call, ``cidx`` naming each point's term.
:class:`SectionBasis` is the same for the spatial families (S of x, y, z): its
section rule is a tensor product over (y, z) and it adds ``BZ`` and ``dZ0``.
The generated functions themselves are this module's public names (``cubic2d_S``, ...):
the layers above take them from here, never from the generated module.
"""
from __future__ import annotations

import numpy as np

from ancf.core.quadrature import RectangularSection, gauss01


def family_shapes(family: str) -> dict:
    """The generated shape-function evaluators of a family (see analytic/shape_functions):
    ``S``, ``x``, ``y`` (and ``z`` for a spatial family; callables of X, Y[, Z], L
    arrays, a plate's of X, Y, a, b), ``n`` shape functions, ``mass``."""
    from ancf.elements import _generated as gen

    fns = {d: getattr(gen, f"{family}_{d}") for d in ("S", "x", "y", "z") if hasattr(gen, f"{family}_{d}")}
    fns["n"] = fns["S"](*[np.ones(1)] * fns["S"].__code__.co_argcount).shape[-1]
    fns["mass"] = getattr(gen, f"{family}_mass")
    return fns


def __getattr__(name: str):
    """The generated shape functions of every family, ``<family>_<derivative>`` (e.g.
    ``cubic2d_S``, ``plate36_x``: callables of the point coordinates and the element's
    sizes, (..., nshape)), are this module's public names, loaded on first use."""
    from ancf.elements import _generated as gen

    if name.startswith("_") or not callable(getattr(gen, name, None)):
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(gen, name)


def consistent_mass(shapes, section: RectangularSection, lengths, rho: float, dim: int):
    """Exact consistent mass matrices (nel, dim n, dim n), Eq. 2.26, kg: rho times the
    family's generated integrals m_ij = int S_i S_j dV, times I_dim."""
    moments = section.moments_yz() if "z" in shapes else section.moments()
    m = np.stack([shapes["mass"](**moments, l=li) for li in lengths])
    return rho * np.einsum("ekl,ij->ekilj", m, np.eye(dim)).reshape(len(lengths), dim * m.shape[1], -1)


def _grad(B, E):
    return np.einsum("eqk,ekd->eqd", B, E)


class Basis:
    """``shapes`` of a family on elements of ``lengths`` (m) with reference coordinates
    ``E0``, evaluated at the rule (nx, ny) over ``section``."""

    fields = ("BX", "BY", "dX0", "dY0", "w")  # the arrays a strain kernel takes, in order

    def __init__(self, shapes, lengths, E0, section: RectangularSection, nx: int, ny):
        xi, wx = gauss01(nx)
        yq, wy = section.rule(ny)
        nel = lengths.shape[0]
        X = (xi[None, :, None] * lengths[:, None, None]) * np.ones((1, 1, yq.size))
        Y = np.broadcast_to(yq[None, None, :], X.shape)
        L = np.broadcast_to(lengths[:, None, None], X.shape)
        self.BX = shapes["x"](X, Y, L).reshape(nel, -1, shapes["n"])
        self.BY = shapes["y"](X, Y, L).reshape(nel, -1, shapes["n"])
        w = (wx[None, :, None] * wy[None, None, :] * lengths[:, None, None]).reshape(nel, -1)
        self.E0 = np.ascontiguousarray(E0)
        self.dim = self.E0.shape[-1]
        self.dX0, self.dY0 = _grad(self.BX, self.E0), _grad(self.BY, self.E0)
        J0 = np.stack([self.dX0, self.dY0], axis=-1)  # (nel, nq, dim, 2)
        self.w = w * np.abs(np.linalg.det(J0))  # reference volume element
        self.cidx = np.zeros(self.w.shape[1], dtype=np.int64)

    @classmethod
    def concat(cls, bases) -> "Basis":
        """The points of several bases side by side; ``cidx`` = index of each point's basis."""
        out = cls.__new__(cls)
        for name in cls.fields:
            setattr(out, name, np.ascontiguousarray(np.concatenate([getattr(b, name) for b in bases], 1)))
        out.E0, out.dim = bases[0].E0, bases[0].dim
        out.cidx = np.concatenate([np.full(b.w.shape[1], i, dtype=np.int64) for i, b in enumerate(bases)])
        return out

    def arrays(self) -> tuple:
        """The arrays of :attr:`fields`, in the order the strain kernels take them."""
        return tuple(getattr(self, f) for f in self.fields)


class SectionBasis(Basis):
    """``shapes`` of a spatial family (S of x, y, z) on elements of ``lengths`` (m) with
    reference coordinates ``E0`` (nel, n, 3), at ``nx`` Gauss points along the axis
    times the ``ny`` x ``ny`` (or exact) rule over the section (y, z)."""

    fields = ("BX", "BY", "BZ", "dX0", "dY0", "dZ0", "w")

    def __init__(self, shapes, lengths, E0, section: RectangularSection, nx: int, ny):
        xi, wx = gauss01(nx)
        yq, zq, wyz = section.rule_yz(ny)
        nel = lengths.shape[0]
        X = (xi[None, :, None] * lengths[:, None, None]) * np.ones((1, 1, yq.size))
        Y = np.broadcast_to(yq[None, None, :], X.shape)
        Z = np.broadcast_to(zq[None, None, :], X.shape)
        L = np.broadcast_to(lengths[:, None, None], X.shape)
        self.BX, self.BY, self.BZ = (shapes[d](X, Y, Z, L).reshape(nel, -1, shapes["n"]) for d in "xyz")
        w = (wx[None, :, None] * wyz[None, None, :] * lengths[:, None, None]).reshape(nel, -1)
        self.E0 = np.ascontiguousarray(E0)
        self.dim = self.E0.shape[-1]
        self.dX0, self.dY0, self.dZ0 = (_grad(B, self.E0) for B in (self.BX, self.BY, self.BZ))
        J0 = np.stack([self.dX0, self.dY0, self.dZ0], axis=-1)  # (nel, nq, 3, 3)
        self.w = w * np.abs(np.linalg.det(J0))  # reference volume element
        self.cidx = np.zeros(self.w.shape[1], dtype=np.int64)
