"""What the planar and the plate contact kernels share (:mod:`ancf.belts.contact2d`,
:mod:`ancf.belts.contact3d`): the widening of their bounding tests and the check of the
element sides."""
from __future__ import annotations

import numpy as np

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
