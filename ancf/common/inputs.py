"""Input rules shared by the scenes, the references and the CLI.

* time histories: ``output_dt`` in ``[t_end / MAX_INTERVALS, t_end]`` (a bounded
  number of samples), a bounded number of fixed steps, and sampling defaults that
  follow ``t_end``;
* ``ancf sweep --set``: fixed values validated before any run starts.
"""
from __future__ import annotations

import math

from ancf.common.params import InputError

MAX_INTERVALS = 100_000  # output samples per time history: at most MAX_INTERVALS + 1
MAX_STEPS = 10_000_000   # steps of any integrator (fixed-step schedules are allocated upfront)


def intervals(t_end: float, output_dt: float) -> int:
    """Number of sampling intervals of 0, output_dt, ..., t_end (the last one may be short)."""
    return int(math.ceil(t_end / output_dt - 1e-9))


def check_sampling(p: dict) -> None:
    """output_dt within [t_end / MAX_INTERVALS, t_end]."""
    t_end, dt = p["t_end"], p["output_dt"]
    if dt > t_end or intervals(t_end, dt) > MAX_INTERVALS:
        raise InputError(f"output_dt = {dt!r} is out of range; allowed: a number in "
                         f"[t_end/{MAX_INTERVALS}, t_end] = [{t_end / MAX_INTERVALS:g}, {t_end:g}] "
                         f"(at most {MAX_INTERVALS + 1} samples)")


def check_fixed_step(p: dict) -> None:
    """generalized-alpha's dt within [t_end / MAX_STEPS, ...]: its step schedule is one array."""
    if p["integrator"] == "generalized-alpha" and p["t_end"] / p["dt"] > MAX_STEPS:
        raise InputError(f"dt = {p['dt']!r} is out of range for generalized-alpha; allowed: a "
                         f"number in [t_end/{MAX_STEPS}, 1] = [{p['t_end'] / MAX_STEPS:g}, 1] "
                         f"(at most {MAX_STEPS} steps)")


def following(value: float, other: str):
    """A default that follows parameter ``other``: ``value`` clipped to
    ``[other / MAX_INTERVALS, other]`` (never longer than ``other``, never so short
    that ``other`` spans more than MAX_INTERVALS of it)."""
    def default(values: dict) -> float:
        top = values[other]
        return min(max(value, top / MAX_INTERVALS), top)
    return default


def validate_fixed(scene, fixed: dict) -> None:
    """Each fixed value parsed by its parameter (unknown names and bad values raise)."""
    params = {p.name: p for p in scene.params}
    for k, v in fixed.items():
        if k not in params:
            raise InputError(f"{k}: unknown parameter of scene {scene.name!r}; allowed: "
                             f"{', '.join(params)}")
        params[k].parse(v)
