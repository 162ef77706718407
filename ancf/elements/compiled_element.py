"""What elements with their own compiled kernels share (the belt element, the thin plate):
argument checks, and energy / gradient / tangent from module-level kernels
``energy(E, data)`` and ``gradient_tangent(E, data, want_K, g, K)`` on the element's
``_data`` tuple, E the coordinates shaped (nel, nshape, dim)."""
from __future__ import annotations

import numpy as np

_NO_TANGENT = np.zeros((0, 0, 0))


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
