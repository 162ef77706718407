"""Numerical warnings raised during a run become one diagnosis line; a run that
reports convergence with a non-finite result has not converged.

Inputs at the edge of the floating-point range (``E = 1e-300``) make numpy warn on
every kernel evaluation (overflow, invalid value...).  A run collects them and
reports one line in its ``warnings`` list instead of printing each.
"""
from __future__ import annotations

import contextlib
import math
import warnings
from collections import Counter


def summary(counts: Counter) -> list[str]:
    """One line for the warnings counted by text (none: an empty list)."""
    if not counts:
        return []
    first, n = next(iter(counts)), sum(counts.values())
    more = f" and {len(counts) - 1} other kind(s)" if len(counts) > 1 else ""
    return [f"numerical: {n} floating-point warning(s) during the run ({first}{more}); "
            "the inputs are probably outside the range the model can represent"]


@contextlib.contextmanager
def numerical_warnings():
    """Count the RuntimeWarnings (numpy's floating-point category) of the enclosed block
    instead of printing them; the yielded list receives the summary line.  Other
    warnings are shown as usual."""
    noted: list[str] = []
    counts: Counter = Counter()
    show = warnings.showwarning

    def count(message, category, *args, **kw):
        if issubclass(category, RuntimeWarning):
            counts.update([f"{category.__name__}: {message}"])
        else:
            show(message, category, *args, **kw)
    with warnings.catch_warnings():
        warnings.simplefilter("always", RuntimeWarning)
        warnings.showwarning = count
        yield noted
    noted += summary(counts)


def nonfinite(results: dict) -> list[str]:
    """Names of the results holding NaN or infinity (a number or inside a list)."""
    def bad(v):
        if isinstance(v, (list, tuple)):
            if all(type(x) is float for x in v):
                return not all(map(math.isfinite, v))  # a plain list of floats, in C
            return any(bad(x) for x in v)
        return isinstance(v, float) and not math.isfinite(v)
    return [k for k, v in (results or {}).items() if bad(v)]
