"""Input rules shared by the scenes, the references and the CLI.

* time histories: ``output_dt`` in ``[t_end / MAX_INTERVALS, t_end]`` (a bounded
  number of samples), a bounded number of fixed steps, and sampling defaults that
  follow ``t_end``;
* ``ancf sweep --set``: fixed values validated before any run starts.
"""
from __future__ import annotations

import math

from ancf.common.params import InputError, is_boolean

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


# ---------------------------------------------------------------------------------------
# the Python API's arguments, checked as the command line checks its own
# ---------------------------------------------------------------------------------------

def number(name: str, value, *, lo: float = 0.0, lo_open: bool = True,
           integer: bool = False) -> float | int:
    """``value`` as a finite number above ``lo`` (at ``lo`` too unless ``lo_open``; an
    integer for ``integer``); InputError naming ``name`` and the range otherwise (a
    boolean, a string or None is not a number)."""
    kind = "an integer" if integer else "a number"
    allowed = f"allowed: {kind} in {'(' if lo_open else '['}{lo:g}, inf)"
    ok_type = isinstance(value, (int, float)) or type(value).__module__ == "numpy"
    if is_boolean(value) or not ok_type:
        raise InputError(f"{name}: {value!r} is not valid; {allowed}")
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name}: {value!r} is not valid; {allowed}") from None
    if (not math.isfinite(v) or (v <= lo if lo_open else v < lo)
            or (integer and not v.is_integer())):
        raise InputError(f"{name} = {value!r} is out of range; {allowed}")
    return int(v) if integer else v


def flag(name: str, value) -> bool:
    """``value`` if it is True or False; InputError otherwise (``"no"`` is not False)."""
    if not is_boolean(value):
        raise InputError(f"{name}: {value!r} is not valid; allowed: True or False")
    return bool(value)


def text(name: str, value, allowed: str) -> str:
    """``value`` if it is a string; InputError naming ``allowed`` otherwise."""
    if not isinstance(value, str):
        raise InputError(f"{name}: {value!r} is not valid; allowed: {allowed}")
    return value


def path(name: str, value):
    """``value`` if it is a file name (a string or a path object, not empty)."""
    import os
    if not isinstance(value, (str, os.PathLike)) or not str(os.fspath(value)).strip():
        raise InputError(f"{name}: {value!r} is not valid; allowed: a file name (a string "
                         "or a pathlib.Path)")
    return value


def mapping(name: str, value) -> dict:
    """``value`` as a dict ({} for None); InputError for anything else."""
    if value is None:
        return {}
    if not isinstance(value, dict) or not all(isinstance(k, str) for k in value):
        raise InputError(f"{name}: {value!r} is not valid; allowed: a dict "
                         "{parameter name: value}")
    return dict(value)


def merged(first: dict, second: dict, names: tuple[str, str]) -> dict:
    """``first`` and ``second`` (e.g. a positional dict and keywords) as one dict; a key
    in both with different values is a conflict (InputError naming the key and both
    places), never silently one of them."""
    for k in first.keys() & second.keys():
        if first[k] != second[k]:
            raise InputError(f"{k}: given as {names[0]} ({first[k]!r}) and as {names[1]} "
                             f"({second[k]!r}); allowed: one value")
    return {**first, **second}
