"""The 3D continuum strain model shared by Chrono's ANCF elements (``ancf3243``,
``ancf3333``, ``ancf3443``, ``ancf3833``, ``ancf3843``).

An element is a basis (its scalar shape functions s_a and their gradients at the
quadrature points) plus this strain model plus a material D (``material``).  The
element supplies a :class:`Basis`, in its own reference (natural) coordinates
xi = (xi, eta, zeta) on a box: the scalar shape functions s (nq, n) and their natural
gradients dS_aI = ds_a/dxi_I (nq, n, 3) at any points, and its reference coordinates
e0 (3n,); and ``rules`` = [(value_k, points, weights), ...] (``gauss_box``,
``layer_boxes``), value_k a density (kg/m^3) for the mass or a material D_k (6, 6, Pa)
for the forces.  Coordinates are ordered e = [r_1, ..., r_n] with each r_a a
3-vector (index 3a + k), the position being r = sum_a s_a r_a.  Equations:

    J0 = dX/dxi = sum_a r0_a (x) ds_a/dxi          (3, 3), reference Jacobian      (1)
    dV = det(J0) w,   G_aJ = ds_a/dX_J = dS J0^-1  m^3 and 1/m (per s_a's unit)    (2)
    M  = int rho s s^T dV (x) I_3,  Q_g = int rho s dV (x) g                       (3)
    F  = I + Hu,  Hu_kJ = sum_a (e - e0)_ak G_aJ    deformation gradient            (4)
    E  = (Hu + Hu^T + Hu^T Hu) / 2,   eps = [E11, E22, E33, 2E23, 2E13, 2E12]       (5)
    deps/dt = B(F) de/dt,  B row IJ = F_kI G_aJ + F_kJ G_aI (halved for I = J)      (6)
    sigma = D (eps + alpha deps/dt)                Kelvin-Voigt, 2nd Piola-Kirchhoff, Pa (7)
    Q  = int B(F)^T sigma dV                       N (N m on gradient entries)      (8)
    K  = dQ/de  = int B^T D (B + alpha B(dF/dt)) + (G S G^T) (x) I_3 dV   N/m      (9)
    R  = dQ/de' = alpha int B^T D B dV             N s/m                            (10)

with S the 3x3 tensor form of sigma; (9) is the material plus the geometric
stiffness.  Computing (5) from the displacement gradient makes eps = 0 exactly at
e = e0.  An element's strain energy may be a sum of :class:`Part` s, one per rule, each a
material D integrated by its own rule (the beams' Poisson part on the axis only, a shell's
layers); Q, K and R are the sums over the parts.  Q is the force of
M e'' + Q(e, e') = Q_ext (Chrono's ``ComputeInternalForces`` returns -Q).
"""
from __future__ import annotations

from typing import Callable, NamedTuple

import numpy as np

#: the index pair (I, J) of each Voigt component, order [11, 22, 33, 23, 13, 12]
VOIGT = [(0, 0), (1, 1), (2, 2), (1, 2), (0, 2), (0, 1)]
#: the Voigt index of the tensor component S_IJ
TENSOR = np.array([[0, 5, 4], [5, 1, 3], [4, 3, 2]])


def gauss_box(counts, lower, upper):
    """Tensor Gauss-Legendre rule on the box [lower_I, upper_I] (I = 0, 1, 2) with
    counts[I] points along I: points (nq, 3) and weights (nq,) summing to the box's
    volume prod(upper - lower); exact for polynomials of degree 2 counts[I] - 1 in xi_I."""
    axes = []
    for n, a, b in zip(counts, lower, upper):
        t, w = np.polynomial.legendre.leggauss(n)
        axes.append((a + (b - a) * (t + 1.0) / 2.0, (b - a) / 2.0 * w))
    P = np.meshgrid(*(p for p, _ in axes), indexing="ij")
    W = np.einsum("i,j,k->ijk", *(w for _, w in axes))
    return np.stack([p.ravel() for p in P], axis=-1), W.ravel()


def layer_boxes(H: float, layers, value, n_plane: int, n_thick: int):
    """The Gauss boxes of a layered shell: [(value_k, points, weights)] per layer
    k, each box [-1, 1]^2 x [z_k, z_k + t_k] with z (m) from -H/2 upward; ``layers``
    = [(t_k, value_k), ...] (value_k a density or a material), thicknesses in m adding
    up to H, or None for the one layer (H, value)."""
    layers = [(H, value)] if layers is None else layers
    if not np.isclose(sum(float(t) for t, _ in layers), H, rtol=1e-12, atol=0.0):
        raise ValueError("layer thicknesses must add up to H")
    out, z0 = [], -H / 2
    for t, value in layers:
        out.append((value, *gauss_box((n_plane, n_plane, n_thick), (-1, -1, z0), (1, 1, z0 + t))))
        z0 += float(t)
    return out


def reference_jacobian(dS: np.ndarray, e0) -> np.ndarray:
    """Eq. (1): J0 (..., 3, 3), J0_kI = dX_k/dxi_I = sum_a r0_ak dS_aI, from the
    natural gradients dS (..., n, 3) and the reference coordinates e0 (3n,)."""
    return np.einsum("ak,...aI->...kI", np.asarray(e0, dtype=float).reshape(-1, 3), dS)


def physical_gradient(dS: np.ndarray, e0):
    """Eq. (2): G (..., n, 3) = ds/dX and det J0 (...,) (m^3 per unit natural volume)."""
    J0 = reference_jacobian(dS, e0)
    return np.einsum("...aI,...IJ->...aJ", dS, np.linalg.inv(J0)), np.linalg.det(J0)


class Basis(NamedTuple):
    """An element's basis: ``shape(points)`` -> s (nq, n) and ``gradient(points)`` ->
    dS = ds/dxi (nq, n, 3) at natural points (nq, 3), and its reference coordinates
    e0 (3n,), m (the dimensions are bound into the two functions)."""

    shape: Callable
    gradient: Callable
    e0: np.ndarray


def scalar_mass(basis: Basis, rules) -> np.ndarray:
    """Eq. (3): the compact mass m = sum_k rho_k int s s^T dV (n, n), kg; M = m (x) I_3.
    ``rules`` = [(rho_k in kg/m^3, points (nq, 3), weights (nq,)), ...] (one per layer)."""
    m = 0.0
    for rho, p, w in rules:
        s, dV = basis.shape(p), rho * w * physical_gradient(basis.gradient(p), basis.e0)[1]
        m = m + np.einsum("q,qi,qj->ij", dV, s, s)
    return m


def gravity(basis: Basis, rules, g) -> np.ndarray:
    """Eq. (3): Q_g = (sum_k rho_k int s dV) (x) g (3n,), N, for the acceleration g (3,)
    in m/s^2; ``rules`` as in :func:`scalar_mass`."""
    q = sum(rho * (w * physical_gradient(basis.gradient(p), basis.e0)[1]) @ basis.shape(p)
            for rho, p, w in rules)
    return np.kron(q, np.asarray(g, dtype=float).reshape(3))


def green_lagrange(e, e0, G: np.ndarray):
    """Eqs. (4)-(5): F (..., nq, 3, 3) and the Voigt strain eps (..., nq, 6), dimensionless;
    e (..., 3n) in m, leading axes (e.g. elements) kept."""
    U = np.asarray(e, dtype=float) - np.asarray(e0, dtype=float)
    Hu = np.einsum("...ak,qaJ->...qkJ", U.reshape(U.shape[:-1] + (G.shape[1], 3)), G)
    Ht = np.swapaxes(Hu, -1, -2)
    Et = 0.5 * (Hu + Ht + Ht @ Hu)
    eps = np.stack([Et[..., i, j] * (1.0 if i == j else 2.0) for i, j in VOIGT], axis=-1)
    return np.eye(3) + Hu, eps


def strain_matrix(F: np.ndarray, G: np.ndarray) -> np.ndarray:
    """Eq. (6): B (..., nq, 6, 3n), 1/m on position entries: row (I, J) = F_kI G_aJ +
    F_kJ G_aI (halved for I = J) at column 3a + k.  With F = dF/dt it gives dB/dt."""
    P = np.einsum("...qkI,qaJ->...qIJak", F, G)
    rows = [P[..., i, j, :, :] + P[..., j, i, :, :] if i != j else P[..., i, i, :, :]
            for i, j in VOIGT]
    return np.stack(rows, axis=-3).reshape(F.shape[:-2] + (6, 3 * G.shape[1]))


def stress(D: np.ndarray, eps: np.ndarray, eps_rate: np.ndarray, alpha: float) -> np.ndarray:
    """Eq. (7): sigma = D (eps + alpha deps/dt) (..., nq, 6), Pa; D (6, 6) in Pa, alpha in s."""
    return (eps + alpha * eps_rate) @ np.asarray(D, dtype=float).T


class Part(NamedTuple):
    """A material D (6, 6), Pa, integrated with the physical gradients G (nq, n, 3)
    and the volumes dV (nq,), m^3, of its own rule."""

    D: np.ndarray
    G: np.ndarray
    dV: np.ndarray


def parts(basis: Basis, rules) -> list:
    """The :class:`Part` s of ``rules`` = [(D_k (6, 6) in Pa, points, weights), ...]:
    e.g. a shell's layers, or a beam's volume part and its Poisson part on the axis."""
    out = []
    for D, p, w in rules:
        G, det = physical_gradient(basis.gradient(p), basis.e0)
        out.append(Part(np.asarray(D, dtype=float), G, det * w))
    return out


def _evaluate(e, edot, e0, p: Part, alpha: float, tangent: bool):
    """Eq. (8) of one part, and if ``tangent`` also eqs. (9)-(10)."""
    edot = np.asarray(edot, dtype=float)
    F, eps = green_lagrange(e, e0, p.G)
    B = strain_matrix(F, p.G)
    sig = stress(p.D, eps, B @ edot, alpha)
    Q = np.einsum("q,qvi,qv->i", p.dV, B, sig)
    if not tangent:
        return Q
    DB = np.einsum("ij,qjn->qin", p.D, B)
    Km = np.einsum("q,qvm,qvn->mn", p.dV, B, DB)
    Bdot = strain_matrix(np.einsum("ak,qaJ->qkJ", edot.reshape(-1, 3), p.G), p.G)
    Kd = np.einsum("q,qvm,qvn->mn", p.dV, DB, Bdot)
    Kg = np.einsum("q,qaI,qIJ,qbJ->ab", p.dV, p.G, sig[:, TENSOR], p.G)
    return Q, Km + alpha * Kd + np.kron(Kg, np.eye(3)), alpha * Km


def internal_force(e, edot, basis: Basis, rules, alpha: float = 0.0) -> np.ndarray:
    """Eq. (8) summed over the parts of ``rules`` (see :func:`parts`): Q (3n,), N (N m
    on gradient entries), at the coordinates e (m) and their rates edot (m/s); alpha in s."""
    return sum(_evaluate(e, edot, basis.e0, p, alpha, False) for p in parts(basis, rules))


def internal_force_jacobians(e, edot, basis: Basis, rules, alpha: float = 0.0):
    """Eqs. (9)-(10) summed over the parts: (K, R) = (dQ/de in N/m, dQ/de' in N s/m)."""
    n = np.size(basis.e0)
    K, R = np.zeros((n, n)), np.zeros((n, n))
    for p in parts(basis, rules):
        _, k, r = _evaluate(e, edot, basis.e0, p, alpha, True)
        K, R = K + k, R + r
    return K, R


#: elements evaluated together by :func:`static_batch` (bounds its work arrays to ~10 MB)
BATCH = 16


def _static_part(U, p: Part, tangent: bool):
    """Eq. (8) and if ``tangent`` eq. (9) of one part at e' = 0 for elements U (ne, 3n) =
    e - e0 (m)."""
    F, eps = green_lagrange(U, 0.0, p.G)
    B = strain_matrix(F, p.G)                                     # (ne, nq, 6, 3n)
    sig = eps @ p.D.T
    Q = np.einsum("q,eqvi,eqv->ei", p.dV, B, sig)
    if not tangent:
        return Q, 0.0
    DB = (p.D @ B) * p.dV[:, None, None]
    ne, nq, _, m = B.shape
    Km = np.swapaxes(B.reshape(ne, nq * 6, m), 1, 2) @ DB.reshape(ne, nq * 6, m)
    SG = sig[..., TENSOR] @ np.swapaxes(p.G, 1, 2)[None] * p.dV[:, None, None]  # (ne,nq,3,n)
    Kg = np.einsum("qaI,eqIb->eab", p.G, SG)
    return Q, Km + (Kg[:, :, None, :, None] * np.eye(3)[:, None, :]).reshape(ne, m, m)


def static_batch(U, parts_: list, tangent: bool = True):
    """Eq. (8) and the stiffness (9) without damping (e' = 0) of many elements at once:
    U (ne, 3n) their displacements e - e0 (m; e0 the basis's reference, ``parts_`` from
    :func:`parts`) -> Q (ne, 3n) in N and K (ne, 3n, 3n) in N/m, the values of
    :func:`internal_force` and :func:`internal_force_jacobians` element by element, the
    parts computed once for the whole mesh; K is None unless ``tangent``."""
    U = np.asarray(U, dtype=float)
    Q, K = np.zeros(U.shape), np.zeros(U.shape + U.shape[-1:]) if tangent else None
    for lo in range(0, len(U), BATCH):
        for p in parts_:
            q, k = _static_part(U[lo:lo + BATCH], p, tangent)
            Q[lo:lo + BATCH] += q
            if tangent:
                K[lo:lo + BATCH] += k
    return Q, K
