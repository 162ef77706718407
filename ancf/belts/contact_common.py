"""What the planar and the plate contact kernels share (:mod:`ancf.belts.contact2d`,
:mod:`ancf.belts.contact3d`): the widening of their bounding tests, the check of the
element sides, and the assembly of a point's pulley derivatives (omega and moment)."""
from __future__ import annotations

import numpy as np
from numba import njit

#: relative widening of the bounding disc, so that the rounding of the point and
#: control-point positions (a few ulps of the coordinates) cannot put a skipped point
#: in contact.
BOUND_MARGIN = 1e3 * np.finfo(np.float64).eps


def positive_lengths(name: str, values, caller: str = "") -> np.ndarray:
    """``values`` as a float array, or ValueError (``caller`` first, then ``name``) unless
    it is a 1-D array of positive finite lengths, m."""
    s = np.asarray(values, dtype=float)
    if s.ndim != 1 or not np.all(np.isfinite(s) & (s > 0)):
        raise ValueError(f"{caller}{name} must be a 1-D array of positive finite lengths, m "
                         f"(got {values!r})")
    return s


@njit(cache=True)
def add_pulley_derivatives(S0, e, q, p, ww, D, Qw, dTq, dTv, dTw):
    """Add point q of element e (weight ww) to pulley p's derivatives: Qw (dQ/domega_p),
    dTq, dTv (dT_p/de, dT_p/dedot), dTw (dT_p/domega_p), from D (dim + 1, 2 dim + 1), the
    point's derivatives of (f, tau) with respect to (r, rdot, omega), dim = 2 or 3."""
    dim = D.shape[0] - 1
    for k in range(S0.shape[2]):
        sk = ww * S0[e, q, k]
        for d in range(dim):
            Qw[e, p, dim * k + d] += sk * D[d, 2 * dim]
            dTq[p, e, dim * k + d] += sk * D[dim, d]
            dTv[p, e, dim * k + d] += sk * D[dim, dim + d]
    dTw[p] += ww * D[dim, 2 * dim]
