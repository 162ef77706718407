"""The outcome of a time integration: samples, statistics and constraint checks."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass(kw_only=True)
class DynamicResult:
    """Samples (t, global q and q') up to where the run got, with its statistics."""

    t: np.ndarray
    q: np.ndarray
    v: np.ndarray
    converged: bool
    message: str
    integrator: str
    steps: int = 0
    nfev: int = 0
    njev: int = 0
    nlu: int = 0
    newton_iterations: int = 0
    rejected_steps: int = 0
    cpu_time_s: float = 0.0
    constraint_violation: float = 0.0  # max |C(q, t)| over the samples, m (0 by elimination)
    multipliers: np.ndarray | None = None  # (n_samples, m) for the multiplier form
    extra: dict = field(default_factory=dict)

    def stats(self) -> dict:
        return {"integrator": self.integrator, "steps": self.steps, "nfev": self.nfev,
                "njev": self.njev, "nlu": self.nlu, "newton_iterations": self.newton_iterations,
                "rejected_steps": self.rejected_steps, "integration_cpu_s": self.cpu_time_s,
                "constraint_violation_m": self.constraint_violation}



def finish(model, res: DynamicResult, X) -> DynamicResult:
    """Constraint violation and multipliers at the samples (multiplier form)."""
    if model.constraints is not None and len(X):
        res.constraint_violation = max(model.violation(x, t) for x, t in zip(X, res.t))
        if res.multipliers is None:
            res.multipliers = np.array([model.multipliers(q, v, t)[1]
                                        for q, v, t in zip(res.q, res.v, res.t)])
    return res


def global_samples(model, X, Xd, ts):
    """Global (q, q') arrays at the times ts from a model's states X, Xd (one row per
    time): its ``samples`` where it has one (a :class:`ReducedModel`), else its ``full``
    row by row."""
    fast = getattr(model, "samples", None)
    if fast is not None:
        return fast(X, Xd, ts)
    return stacked([model.full(x, xd, t) for x, xd, t in zip(X, Xd, ts)])


def stacked(pairs):
    """Two arrays from a list of pairs of rows."""
    return np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])
