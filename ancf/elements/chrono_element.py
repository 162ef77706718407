"""Chrono's ANCF elements as registry elements: the element contract
(:mod:`ancf.elements.contract`) over the modules ``ancf3243``, ``ancf3333`` (beams),
``ancf3443``, ``ancf3833`` (shells) and ``ancf3843`` (brick).

An element of this module is a set of ``nel`` elements of one module, element i of
sizes ``sizes[i]`` (m) and reference coordinates ``e0[i]`` (m), a straight beam, flat
shell or rectangular box as the module's own reference up to a translation.  Its strain
energy, force and stiffness are those of ``continuum3d`` (Green-Lagrange strain, the
module's material parts D_k, each integrated by its own exact rule):

    U  = sum_k int 1/2 eps^T D_k eps dV                 J                        (1)
    Q  = dU/de = sum_k int B^T D_k eps dV,  K = dQ/de   N, N/m (continuum3d (8), (9))
    M  = the module's consistent mass (exact rule)     kg                        (2)

with eps of the displacement e - e0, so a translation of the reference changes nothing.
Identical element sizes share their parts (computed once per size).  The local node
coordinates (:attr:`node_points`, in [0, 1] per reference direction) and the shape
functions in physical coordinates X (m) from the element's first corner
(:meth:`own_shapes`, for the registry's ``field``) complete the contract.
"""
from __future__ import annotations

from functools import lru_cache

import numpy as np

from ancf.elements import ancf3243, ancf3333, ancf3443, ancf3833, ancf3843
from ancf.elements import continuum3d as c3
from ancf.elements.material import isotropic_3d


def chrono_shear(nu: float) -> float:
    """Chrono's beams' shear correction 10 (1 + nu)/(12 + 11 nu) (-)."""
    return 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu)


@lru_cache(maxsize=64)
def _parts(cls, sizes: tuple, material: tuple) -> tuple:
    """The ``continuum3d`` parts of one element of ``cls`` (``cls._kernel(*sizes,
    *material)`` -> (basis, rules)), once per class, sizes and material."""
    basis, rules = cls._kernel(*sizes, *material)
    return tuple(c3.parts(basis, rules))


class ChronoElement:
    """``nel`` elements of :attr:`module` with sizes (nel, k) in m and reference e0
    (nel, ndof) in m, density rho (kg/m^3); subclasses set the module, its slots and
    :meth:`_kernel`, :meth:`_mass` of one element's sizes."""

    module = None
    family = ""
    slots: tuple = ()
    schemes: dict = {}
    dim = 3
    strain = c3
    node_points: tuple = ()  # local node coordinates in [0, 1], one array per direction

    def _setup(self, sizes, e0, rho: float, material: tuple):
        self.sizes = np.atleast_2d(np.asarray(sizes, dtype=float))
        self.nel, self.nshape = len(self.sizes), self.module.NSHAPE
        self.ndof, self.rho, self.material = self.module.NDOF, float(rho), material
        self.lengths = self.sizes[:, 0]
        ref = [self.module.reference_coordinates(*s[:self._ref_args]) for s in self.sizes]
        self.e0 = np.array(ref) if e0 is None else np.asarray(e0, dtype=float)
        self.groups = {}
        for i, s in enumerate(map(tuple, self.sizes)):
            self.groups.setdefault(s, []).append(i)

    _ref_args = 1

    @classmethod
    def _kernel(cls, *args):
        raise NotImplementedError

    def _group_parts(self, s: tuple):
        return _parts(type(self), s, self.material)

    #: one element's sizes (m) and material for :meth:`points_per_element` (any will do)
    _unit: tuple = ((1.0, 1.0, 0.1), (1.0, 0.3))

    @classmethod
    def points_per_element(cls) -> int:
        """Quadrature points of one element's internal force, summed over its material
        parts (each part its own exact rule): the cost model's kernel points."""
        return sum(len(p.dV) for p in _parts(cls, *cls._unit))

    def energy(self, e) -> np.ndarray:
        """Eq. (1) of each element (nel,), J."""
        U, out = np.asarray(e, dtype=float) - self.e0, np.zeros(self.nel)
        for s, idx in self.groups.items():
            for p in self._group_parts(s):
                _, eps = c3.green_lagrange(U[idx], 0.0, p.G)
                out[idx] += 0.5 * np.einsum("q,eqi,ij,eqj->e", p.dV, eps, p.D, eps)
        return out

    def gradient(self, e, tangent: bool = False):
        """dU/de (nel, ndof), N, and K (nel, ndof, ndof), N/m, or None."""
        U = np.asarray(e, dtype=float) - self.e0
        g = np.zeros(U.shape)
        K = np.zeros(U.shape + U.shape[-1:]) if tangent else None
        for s, idx in self.groups.items():
            q, k = c3.static_batch(U[idx], list(self._group_parts(s)), tangent)
            g[idx] = q
            if tangent:
                K[idx] = k
        return g, K

    def mass(self) -> np.ndarray:
        """Consistent mass matrices (nel, ndof, ndof), kg (eq. (2)), symmetric to the bit."""
        M = np.array([self._mass(*s) for s in self.sizes])
        return 0.5 * (M + np.swapaxes(M, 1, 2))

    def _mass(self, *sizes):
        raise NotImplementedError

    @classmethod
    def own_shapes(cls) -> dict:
        """The shape functions S and d/dX, d/dY, d/dZ (..., nshape) at physical points
        (X, Y, Z) m from the element's first corner, given the element's sizes (the
        registry's ``field`` arguments), and ``n`` shape functions."""
        def natural(X, Y, Z, *size):
            return cls._natural(np.asarray(X, float), np.asarray(Y, float),
                                np.asarray(Z, float), *np.broadcast_arrays(*size))

        def derivative(d):
            def f(X, Y, Z, *size):
                xi, scale, args = natural(X, Y, Z, *size)
                dS = cls.module.natural_gradient(*xi, *args)
                return dS[..., d] * scale[d][..., None]
            return f

        def S(X, Y, Z, *size):
            xi, _, args = natural(X, Y, Z, *size)
            return cls.module.scalar_shape(*xi, *args)

        return {"S": S, "x": derivative(0), "y": derivative(1), "z": derivative(2),
                "n": cls.module.NSHAPE}


class _Beam(ChronoElement):
    """A beam along x: lengths (nel,) m, e0 (nel, ndof) m, the section's height h (y)
    and width b (z), m; ks the shear correction of both shears (default Chrono's)."""

    _unit = ((1.0, 0.1, 0.1), (1.0, 0.3, 1.0, 1.0))

    def __init__(self, lengths, e0, section, E, nu, rho=0.0, ks=None):
        k = chrono_shear(nu) if ks is None else float(ks)
        L = np.asarray(lengths, dtype=float)
        sizes = np.column_stack([L, np.full(L.shape, section.h), np.full(L.shape, section.b)])
        self.section = section
        self._setup(sizes, e0, rho, (E, nu, k, k))

    @classmethod
    def _kernel(cls, L, H, W, E, nu, k1, k2):
        return cls.module.continuum(L, H, W, E, nu, k1, k2)

    def _mass(self, L, H, W):
        return self.module.mass_matrix(L, H, W, self.rho)

    @staticmethod
    def _natural(X, Y, Z, L):
        """(xi, eta, zeta) with H = W = 1 (so eta = y, zeta = z in m), d(natural)/dX."""
        one = np.ones_like(L)
        return (X / L, Y, Z), (1.0 / L, one, one), (L, one, one)


class Beam3243(_Beam):
    """Chrono's ``ChElementBeamANCF_3243`` (module ``ancf3243``), 24 coordinates."""

    module, family, slots = ancf3243, "cubic3d", ("r", "r_x", "r_y", "r_z")
    node_points = (np.array([0.0, 1.0]),)


class Beam3333(_Beam):
    """Chrono's ``ChElementBeamANCF_3333`` (module ``ancf3333``), 27 coordinates, nodes
    A, B at the ends and C in the middle."""

    module, family, slots = ancf3333, "ancf3333", ("r", "r_y", "r_z")
    node_points = (np.array(ancf3333.NODE_XI),)


class _Shell(ChronoElement):
    """A flat shell: sides a (x) and b (y) (nel,) m, thickness h (m), one isotropic layer."""

    _ref_args = 2

    def __init__(self, lengths, widths, h, E, nu, rho=0.0, e0=None):
        a = np.asarray(lengths, dtype=float)
        b = np.broadcast_to(np.asarray(widths, dtype=float), a.shape)
        self.widths, self.h = b, float(h)
        self._setup(np.column_stack([a, b, np.full(a.shape, h)]), e0, rho, (E, nu))

    def _mass(self, a, b, h):
        return self.module.mass_matrix(a, b, h, self.rho)

    @staticmethod
    def _natural(X, Y, Z, a, b):
        one = np.ones_like(a)
        return (2 * X / a - 1, 2 * Y / b - 1, Z), (2 / a, 2 / b, one), (a[..., None], b[..., None])


class Shell3443(_Shell):
    """Chrono's ``ChElementShellANCF_3443`` (module ``ancf3443``, its default 3D law),
    48 coordinates."""

    module, family, slots = ancf3443, "ancf3443", ("r", "r_x", "r_y", "r_z")
    node_points = ((ancf3443.NODE_XI + 1) / 2, (ancf3443.NODE_ETA + 1) / 2)

    @classmethod
    def _kernel(cls, a, b, h, E, nu):
        return cls.module.continuum(a, b, h, isotropic_3d(E, nu))


class Shell3833(_Shell):
    """Chrono's ``ChElementShellANCF_3833`` (module ``ancf3833``), 72 coordinates."""

    module, family, slots = ancf3833, "ancf3833", ("r", "r_z", "r_zz")
    node_points = ((ancf3833.NODE_XI + 1) / 2, (ancf3833.NODE_ETA + 1) / 2)

    @classmethod
    def _kernel(cls, a, b, h, E, nu):
        return cls.module.continuum(a, b, h, E, nu)

    @staticmethod
    def _natural(X, Y, Z, a, b):
        one = np.ones_like(a)
        return (2 * X / a - 1, 2 * Y / b - 1, Z), (2 / a, 2 / b, one), ()


class Brick3843(ChronoElement):
    """Chrono's ``ChElementHexaANCF_3843`` (module ``ancf3843``), 96 coordinates: sides
    (lx, ly, lz) (nel,) m each."""

    module, family, slots = ancf3843, "ancf3843", ("r", "r_x", "r_y", "r_z")
    node_points = tuple((ancf3843.NODE_SIGNS[:, i] + 1) / 2 for i in range(3))
    _ref_args = 3

    def __init__(self, lx, ly, lz, E, nu, rho=0.0, e0=None):
        sizes = np.column_stack(np.broadcast_arrays(*(np.atleast_1d(np.asarray(v, float))
                                                      for v in (lx, ly, lz))))
        self._setup(sizes, e0, rho, (E, nu))

    @classmethod
    def _kernel(cls, lx, ly, lz, E, nu):
        return cls.module.continuum(lx, ly, lz, E, nu)

    def _mass(self, lx, ly, lz):
        return self.module.mass_matrix(lx, ly, lz, self.rho)

    @staticmethod
    def _natural(X, Y, Z, a, b, c):
        return (2 * X / a - 1, 2 * Y / b - 1, 2 * Z / c - 1), (2 / a, 2 / b, 2 / c), (a, b, c)
