"""Quadrature rules along the element axis and over rectangular cross-sections.

A rule is a pair of arrays ``(points, weights)``; along the axis the points are in
``[0, 1]`` (multiply by the element length ``l``), across the section they are
heights ``y`` in metres with weights that already carry the width ``b``, or, for
the spatial beams, tensor-product points ``(y, z)`` in metres with weights in m^2.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

#: number of section points (per section direction) that integrate every term of
#: the strain energies exactly ("closed form over the cross-section"): the energy
#: density is at most quartic in y (and in z), and an n-point Gauss rule is exact
#: to degree 2n-1.
EXACT = "exact"
_EXACT_SECTION_POINTS = 3


@lru_cache(maxsize=None)
def gauss01(n: int) -> tuple[np.ndarray, np.ndarray]:
    """n-point Gauss-Legendre rule on [0, 1] (points, weights summing to 1)."""
    if not isinstance(n, (int, np.integer)) or n < 1:
        raise ValueError(f"number of Gauss points must be an integer >= 1 (got {n!r})")
    t, w = np.polynomial.legendre.leggauss(int(n))
    return 0.5 * (t + 1.0), 0.5 * w


@dataclass(frozen=True)
class RectangularSection:
    """Rectangular cross-section of width ``b`` (z) and height ``h`` (y), metres."""

    b: float
    h: float

    @property
    def area(self) -> float:
        return self.b * self.h

    @property
    def second_moment(self) -> float:
        """I = b h^3 / 12 about the centroidal z axis, m^4."""
        return self.b * self.h**3 / 12.0

    def moments(self) -> dict:
        """Section integrals Q_p = int y^p dA for the generated mass matrices."""
        return {"Q0": self.area, "Q1": 0.0, "Q2": self.second_moment}

    def rule(self, n) -> tuple[np.ndarray, np.ndarray]:
        """Heights y and weights (b dy) of an n-point Gauss rule, or the exact one."""
        n = _EXACT_SECTION_POINTS if n == EXACT else n
        t, w = gauss01(n)
        return (t - 0.5) * self.h, w * self.h * self.b

    def moments_yz(self) -> dict:
        """Section integrals Qp_q = int y^p z^q dA (p + q <= 2), m^(2+p+q), for the
        generated mass matrices of the spatial beams; centroidal, principal axes."""
        return {"Q0_0": self.area, "Q0_1": 0.0, "Q1_0": 0.0, "Q1_1": 0.0,
                "Q2_0": self.second_moment, "Q0_2": self.h * self.b**3 / 12.0}

    def rule_yz(self, n) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Heights y, widths z (m) and weights dA (m^2) of the n x n Gauss rule over the
        section (n points in y and n in z), or of the exact one."""
        n = _EXACT_SECTION_POINTS if n == EXACT else n
        t, w = gauss01(n)
        y, z = np.meshgrid((t - 0.5) * self.h, (t - 0.5) * self.b, indexing="ij")
        return y.ravel(), z.ravel(), np.outer(w * self.h, w * self.b).ravel()
