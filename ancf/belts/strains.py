"""Axial strain measures, tension and speed along a belt (thesis section 4.2, Eqs 4.5-4.13).

For any element with a gradient r_x along the belt (x runs along the belt's length s),
at points of an element the stretch along the belt is

    lambda = |r_x| / |r_o,x|        (dl / dl_o; r_o the reference configuration)

and, with t_o = r_o,x / |r_o,x|, alpha = 2 t_o^T eps^m t_o = lambda^2 - 1 (Eq. 4.5):

    Green     eps   = -1 + (1 + alpha)^(1/2)   = lambda - 1          (Eq. 4.9)
    true      eps^t = (dl - dl_o) / dl         = 1 - 1/lambda        (Eq. 4.10, as printed)
    Almansi   eps^A = -1 + (1 + alpha_A)^(1/2),                      (Eq. 4.11)
              alpha_A = 2 t_t^T eps^e t_t = 1 - 1/lambda^2

(eps^e = (I - D^-T D^-1)/2 and D^-1 t_t = t_o / lambda, since D r_o,x = r_x), the
tension k eps of each (k: the axial stiffness E A alpha1, N), the belt speed along the
current tangent v = t_t^T r' (Eqs 4.12-4.13, t_t = r_x/|r_x|), and the determinant of
the deformation gradient, generalised to surfaces and lines by the Gram determinant:
det F = sqrt(det(J^T J) / det(J_o^T J_o)) with J the columns of the gradients given.

Shapes: S, Sx (nel, npts, nshape) shape functions and their x-derivatives at the sample
points; E, E0, V (nel, nshape, dim) current and reference coordinates and velocities;
``others`` further derivative matrices (Sy, Sz ...) for det F.
"""
from __future__ import annotations

import numpy as np

from ancf.elements.basis import cubic2d_S, cubic2d_x, cubic2d_y

DEFAULT_POINTS = 20  # sample points per element along the belt


def _grad(B, E):
    return np.einsum("eqk,ekd->eqd", B, E)


def gram_det(cols, cols0) -> np.ndarray:
    """sqrt(det(J^T J) / det(J0^T J0)) for lists of gradient arrays (nel, npts, dim)."""
    J, J0 = np.stack(cols, -1), np.stack(cols0, -1)
    g = np.linalg.det(np.einsum("eqdi,eqdj->eqij", J, J))
    g0 = np.linalg.det(np.einsum("eqdi,eqdj->eqij", J0, J0))
    return np.sqrt(g / g0)


def measures(S, Sx, E, E0, V, k: float, others=()) -> dict:
    """Strains, tensions (N), speed (m/s), stretch and det F at every sample point."""
    rx, rx0 = _grad(Sx, E), _grad(Sx, E0)
    lam = np.linalg.norm(rx, axis=-1) / np.linalg.norm(rx0, axis=-1)
    eps = {"green": lam - 1.0, "true": 1.0 - 1.0 / lam,
           "almansi": -1.0 + np.sqrt(2.0 - 1.0 / lam**2)}
    tt = rx / np.linalg.norm(rx, axis=-1, keepdims=True)
    out = {"stretch": lam, "speed": np.einsum("eqd,eqd->eq", tt, _grad(S, V)),
           "det_F": gram_det([rx, *(_grad(B, E) for B in others)],
                             [rx0, *(_grad(B, E0) for B in others)])}
    for name, e in eps.items():
        out[f"eps_{name}"] = e
        out[f"tension_{name}_N"] = k * e
    return out


def planar_belt(lengths, E, E0, V, k: float, y: float = 0.0, n_points: int = DEFAULT_POINTS) -> dict:
    """:func:`measures` along the line at height y (m; 0: the centreline) of planar
    ``cubic2d`` elements (the belt element of thesis 3.1) of ``lengths`` (m); arrays
    (nel, n_points) at xi = (j + 1/2) / n_points, plus ``s`` the reference arc length, m."""
    lengths = np.asarray(lengths, dtype=float)
    xi = (np.arange(n_points) + 0.5) / n_points
    X = xi[None, :] * lengths[:, None]
    Y, L = np.full_like(X, y), np.broadcast_to(lengths[:, None], X.shape)
    S, Sx, Sy = (f(X, Y, L) for f in (cubic2d_S, cubic2d_x, cubic2d_y))
    out = measures(S, Sx, E, E0, V, k, others=(Sy,))
    out["s"] = np.cumsum(np.r_[0.0, lengths[:-1]])[:, None] + X
    return out
