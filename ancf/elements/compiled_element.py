"""What elements with their own compiled kernels share (the belt elements, the thin plate):
argument checks, the belt elements' common set-up, and energy / gradient / tangent from
module-level kernels
``energy(E, data)`` and ``gradient_tangent(E, data, want_K, g, K)`` on the element's
``_data`` tuple, E the coordinates shaped (nel, nshape, dim)."""
from __future__ import annotations

import numpy as np
from numba import njit

from ancf.core.quadrature import gauss01
from ancf.elements.basis import consistent_mass, family_shapes

_NO_TANGENT = np.zeros((0, 0, 0))


@njit(cache=True)
def add_point_tangent(Ke, ww, Jv, H, HJ):
    """Ke += ww Jv^T H Jv (upper triangle): a point's density Hessian H in its point
    variables chained to the element coordinates by Jv (the belt elements' kernels)."""
    nv, nd = Jv.shape
    for i in range(nv):
        for b in range(nd):
            acc = 0.0
            for j in range(nv):
                acc += H[i, j] * Jv[j, b]
            HJ[i, b] = ww * acc
    for a in range(nd):
        for b in range(a, nd):
            acc = 0.0
            for i in range(nv):
                acc += Jv[i, a] * HJ[i, b]
            Ke[a, b] += acc


def check(name: str, value, ok, allowed: str) -> None:
    """ValueError naming the argument and its allowed range unless ok(value)."""
    if not ok(value):
        raise ValueError(f"{name} must be {allowed} (got {value!r})")


def check_material(nu: float, rho: float, **positive) -> None:
    """The positive, finite arguments ``positive``, -1 < nu < 0.5 and rho >= 0."""
    for name, v in positive.items():
        check(name, v, lambda x: np.isfinite(x) and x > 0, "finite and > 0")
    check("nu", nu, lambda v: -1.0 < v < 0.5, "in (-1, 0.5)")
    check("rho", rho, lambda v: np.isfinite(v) and v >= 0, "finite and >= 0")


class CompiledElement:
    """Subclasses set ``nel``, ``nshape``, ``dim``, ``ndof``, ``_data`` and the kernels
    ``kernel_energy``, ``kernel_gradient_tangent`` (staticmethods)."""

    def _coords(self, e):
        return np.ascontiguousarray(e, dtype=float).reshape(self.nel, self.nshape, self.dim)

    def energy(self, e) -> np.ndarray:
        """Strain energy U of each element (nel,), J (e: (nel, ndof))."""
        return self.kernel_energy(self._coords(e), self._data)

    def gradient(self, e, tangent: bool = False):
        """dU/de (nel, ndof) (Qe = -dU/de, Eq. 2.20) and, if ``tangent``, the exact
        d2U/de2 (nel, ndof, ndof), else None."""
        g = np.zeros((self.nel, self.ndof))
        K = np.zeros((self.nel, self.ndof, self.ndof)) if tangent else _NO_TANGENT
        self.kernel_gradient_tangent(self._coords(e), self._data, tangent, g, K)
        return g, (K if tangent else None)


class BeltElement(CompiledElement):
    """Dufva's belt elements (2D and 3D): the arguments they share, checked and stored, and
    what is computed from them alike.  Subclasses set ``family``, ``dim``, ``shape_xx``
    (the family's generated second x-derivative) and give :meth:`density_coefficients`.
    Arguments: lengths (nel,) m, reference coordinates ``e0`` (nel, ndof) (checked for
    shape only: the reference is straight), the cross-section (b, h in m), Young's
    modulus ``E`` Pa, Poisson's ratio ``nu`` (enters G only), density ``rho`` kg/m^3,
    axial and bending stiffness factors ``alpha1``, ``alpha2`` (-), shear correction
    ``ks`` (-) and ``nx`` Gauss points along x."""

    schemes: dict = {}  # one rule: nx Gauss points along x, the section in closed form

    def __init__(self, lengths, e0, section, E, nu, rho=0.0, alpha1=1.0, alpha2=1.0,
                 ks=5.0 / 6.0, nx=5):
        G = self._setup(lengths, e0, section, E, nu, rho, alpha1, alpha2, ks, nx)
        self.coefficients = self.density_coefficients(section, E, G, alpha1, alpha2, ks)
        self._data = self._kernel_data()

    @staticmethod
    def density_coefficients(section, E, G, alpha1, alpha2, ks) -> np.ndarray:
        """k of :meth:`kernel_data`: the constants of the element's energy density."""
        raise NotImplementedError

    def _setup(self, lengths, e0, section, E, nu, rho, alpha1, alpha2, ks, nx) -> float:
        """Check and store the common arguments; returns the shear modulus G (Pa)."""
        check_material(nu, rho, E=E, alpha1=alpha1, alpha2=alpha2, ks=ks,
                       **{"section.b": section.b, "section.h": section.h})
        check("nx", nx, lambda v: isinstance(v, (int, np.integer)) and v >= 1, "an integer >= 1")
        self.lengths = np.asarray(lengths, dtype=float).ravel()
        check("lengths", lengths, lambda v: self.lengths.size > 0 and np.all(
            np.isfinite(self.lengths) & (self.lengths > 0)), "a non-empty array of finite values > 0")
        self.shapes = family_shapes(self.family)
        self.nel, self.nshape = self.lengths.size, self.shapes["n"]
        self.ndof = self.dim * self.nshape
        check("e0 size", np.size(e0), lambda v: v == self.nel * self.ndof,
              f"nel * {self.ndof} = {self.nel * self.ndof}")
        self.section, self.rho, self.nx = section, float(rho), int(nx)
        self.E_mod, self.alpha1 = float(E), float(alpha1)
        return E / (2.0 * (1.0 + nu))

    def _on_axis(self, fn, xi) -> np.ndarray:
        """The generated evaluator ``fn`` (of X, Y[, Z], L) on the centre line of every
        element, at local coordinates xi (nxi,) in [0, 1]: (nel, nxi, nshape)."""
        l = self.lengths[:, None]
        zero = np.zeros((1, xi.size))
        return fn(xi[None, :] * l, *(zero,) * (self.dim - 1), l)

    def _kernel_data(self):
        xi, wx = gauss01(self.nx)
        return (np.ascontiguousarray(self._on_axis(self.shapes["x"], xi)),
                np.ascontiguousarray(self._on_axis(self.shape_xx, xi)), xi,
                np.ascontiguousarray(wx[None, :] * self.lengths[:, None]), self.lengths.copy(),
                self.coefficients)

    def kernel_data(self) -> tuple:
        """The float64 arrays of the element's kernels: (BX, BXX (nel, nx, nshape) shape
        derivatives along the centre line (1/m, 1/m^2), xi (nx,) Gauss points in [0, 1],
        wq (nel, nx) weights (m), lengths (nel,) m, k the density coefficients
        (``coefficients``))."""
        return self._data

    def mass(self) -> np.ndarray:
        """Exact consistent mass matrices (nel, ndof, ndof), Eq. 2.26, kg."""
        return consistent_mass(self.shapes, self.section, self.lengths, self.rho, self.dim)

    def axial_force(self, e, xi) -> np.ndarray:
        """Normal force N = E A alpha1 eps_l (Eq. 3.17, eps_l of :meth:`axial_strain`),
        N, at local coordinates ``xi`` in [0, 1] of every element: (nel, len(xi))."""
        B = self._on_axis(self.shapes["x"], np.atleast_1d(np.asarray(xi, dtype=float)))
        a = np.einsum("eqk,ekd->eqd", B, self._coords(e))
        return self.E_mod * self.section.area * self.alpha1 * self.axial_strain(a)

    def axial_strain(self, a) -> np.ndarray:
        """The axial strain of the centre line's slopes a (..., dim): Green's
        eps_l = (a.a - 1)/2."""
        return 0.5 * (np.einsum("...d,...d->...", a, a) - 1.0)
