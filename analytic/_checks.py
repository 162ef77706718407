"""Input checks shared by the analytic references: errors name the field and the range."""
from __future__ import annotations

import math


def finite(name: str, val) -> float:
    """``val`` as a finite float, else ValueError naming ``name``."""
    try:
        v = float(val)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number (got {val!r})") from None
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite (got {val!r})")
    return v


def positive(name: str, val) -> float:
    """``val`` as a float > 0, else ValueError naming ``name``."""
    v = finite(name, val)
    if v <= 0:
        raise ValueError(f"{name} must be > 0 (got {val!r})")
    return v
