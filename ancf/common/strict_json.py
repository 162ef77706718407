"""JSON that strict parsers accept: non-finite floats become ``null``."""
from __future__ import annotations

import json
import math


def finite(obj):
    """``obj`` with every NaN / infinity (also in nested lists and dicts) as None."""
    if isinstance(obj, float):
        return obj if math.isfinite(obj) else None
    if isinstance(obj, dict):
        return {k: finite(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [finite(v) for v in obj]
    return obj


def dumps(obj, **kw) -> str:
    return json.dumps(finite(obj), allow_nan=False, **kw)
