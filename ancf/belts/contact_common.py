"""What the planar and the plate contact kernels share (:mod:`ancf.belts.contact2d`,
:mod:`ancf.belts.contact3d`): the widening of their bounding tests, the check of the
element sides and a point's terms in the pulley rows of the Jacobian."""
from __future__ import annotations

import numpy as np

from ancf.common.leaf import leaf

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


@leaf
def add_pulley_rows(e, p, k, sk, D, dim, Qw, dTq, dTv):
    """Add a contact point's terms for shape function k (sk = w S_k) of element e to the
    derivatives by pulley p's angular speed of the element forces (Qw) and of the pulley
    moment by the element's coordinates and velocities (dTq, dTv).  D (dim + 1, 2 dim + 1):
    the point's force (rows 0..dim-1) and moment (row dim) by position, velocity and
    angular speed (columns)."""
    for d in range(dim):
        Qw[e, p, dim * k + d] += sk * D[d, 2 * dim]
        dTq[p, e, dim * k + d] += sk * D[dim, d]
        dTv[p, e, dim * k + d] += sk * D[dim, dim + d]
