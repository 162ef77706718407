"""Timoshenko cantilever under a uniform distributed load, tip deflection (closed form).

Clamped at x = 0, free at x = L, load q (N/m, positive along +y).  Bending
(Euler-Bernoulli) plus shear deflection:

    w(L) = q L^4 / (8 E I) + q L^2 / (2 ks G A),   I = b h^3 / 12,  A = b h,  G = E / (2 (1 + nu)).

The reference for the linear element's statics under a force term (gravity, q = rho g A).
"""
from __future__ import annotations


def tip_deflection(E: float, nu: float, L: float, h: float, b: float, q: float,
                   ks: float = 5.0 / 6.0) -> float:
    """w(L), m, for a load q (N/m)."""
    A, I = b * h, b * h**3 / 12.0
    G = E / (2.0 * (1.0 + nu))
    return q * L**4 / (8.0 * E * I) + q * L**2 / (2.0 * ks * G * A)
