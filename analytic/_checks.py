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


# The range a derived quantity must stay in: well inside double precision (normal numbers
# run from 2.2e-308 to 1.8e308), with room for the arithmetic that follows.
LOG10_LO, LOG10_HI = -300.0, 300.0


def magnitude(what: str, factors: dict, const: float = 1.0) -> float:
    """``const * prod(value ** power)`` for ``factors = {field: (value, power)}``, or
    ValueError when its magnitude leaves [1e-300, 1e300]: the message names the field that
    pushes it out the most (``h = 1e-300: the bending rigidity E h^3 / ... underflows ...``).
    A zero factor gives 0 (a zero load is not an underflow)."""
    if const == 0 or any(v == 0 for v, _ in factors.values()):
        return 0.0
    logs = {k: p * math.log10(abs(v)) for k, (v, p) in factors.items()}
    total = math.log10(abs(const)) + sum(logs.values())
    if not LOG10_LO <= total <= LOG10_HI:
        up = total > LOG10_HI
        name = max(logs, key=lambda k: logs[k] if up else -logs[k])
        raise ValueError(
            f"{name} = {factors[name][0]!r} is out of range: {what} would be about "
            f"1e{total:+.0f}, which {'overflows' if up else 'underflows'} double precision; "
            f"allowed: {name} such that {what} stays within [1e{LOG10_LO:.0f}, "
            f"1e{LOG10_HI:+.0f}]")
    out = const
    for v, p in factors.values():
        out *= v ** p
    return out


def mode_count(name: str, val) -> int:
    """``val`` as an int >= 1 (a number of modes), else ValueError naming ``name``."""
    if isinstance(val, bool) or finite(name, val) != int(val) or val < 1:
        raise ValueError(f"{name} must be an integer >= 1 (got {val!r})")
    return int(val)
