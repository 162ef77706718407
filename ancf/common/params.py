"""Scene and reference parameters: named values with defaults and ranges, and the
error that bad input raises (one line naming the field and its allowed range)."""
from __future__ import annotations

import math
from dataclasses import dataclass


class InputError(ValueError):
    """Bad user input; the message names the field and its allowed range."""


def is_boolean(value) -> bool:
    """``True``/``False`` (Python's or numpy's): never a parameter's value, although
    Python counts them as 1 and 0 (a drive file's ``E = true`` would run at 1 Pa)."""
    return isinstance(value, bool) or (type(value).__module__ == "numpy"
                                       and type(value).__name__ in ("bool", "bool_"))


@dataclass(frozen=True)
class Param:
    """A scene parameter. ``lo``/``hi`` bound numbers (``lo_open``: strict lower bound);
    ``choices`` restrict strings; ``default`` may be a function of the other params."""

    name: str
    default: object
    kind: type = float
    unit: str = ""
    doc: str = ""
    lo: float | None = None
    hi: float | None = None
    lo_open: bool = False
    hi_open: bool = False
    choices: tuple | None = None

    def allowed(self) -> str:
        if self.choices is not None:
            return "one of " + ", ".join(map(str, self.choices))
        if self.kind is str:
            return "a name (see the parameter's description)"
        lo = "-inf" if self.lo is None else f"{self.lo:g}"
        hi = "inf" if self.hi is None else f"{self.hi:g}"
        kind = "an integer" if self.kind is int else "a number"
        return f"{kind} in {'(' if self.lo_open or self.lo is None else '['}{lo}, {hi}{')' if self.hi_open or self.hi is None else ']'}"

    def parse(self, value):
        if value is None and self.default is None:
            return None  # a parameter computed when not given: resolved sets round-trip
        if is_boolean(value):
            raise InputError(f"{self.name}: {value!r} is not valid (a boolean); allowed: "
                             f"{self.allowed()}")
        try:
            if self.kind is int:
                v = float(value)
                if not v.is_integer():
                    raise ValueError
                v = int(v)
            else:
                v = self.kind(value)
        except (TypeError, ValueError):
            raise InputError(f"{self.name}: {value!r} is not valid; allowed: {self.allowed()}") from None
        self.check(v)
        return v

    def check(self, v):
        bad = False
        if self.choices is not None:
            bad = v not in self.choices
        elif self.kind in (int, float):
            bad = (not math.isfinite(v)
                   or (self.lo is not None and (v <= self.lo if self.lo_open else v < self.lo))
                   or (self.hi is not None and (v >= self.hi if self.hi_open else v > self.hi)))
        if bad:
            raise InputError(f"{self.name} = {v!r} is out of range; allowed: {self.allowed()}")


def resolve(params, overrides: dict | None, owner: str) -> dict:
    """All values of ``params`` (Param s) in declared order: ``overrides`` (strings or
    values, each parsed by its Param), then the defaults (a callable default follows the
    values before it), each checked; an unknown name is one InputError naming ``owner``
    (e.g. "scene 'cantilever'")."""
    overrides = dict(overrides or {})
    names = [p.name for p in params]
    unknown = sorted(set(overrides) - set(names))
    if unknown:
        raise InputError(f"{unknown[0]}: unknown parameter of {owner}; "
                         f"allowed: {', '.join(names)}")
    values = {p.name: p.parse(overrides[p.name]) for p in params if p.name in overrides}
    for p in params:
        if p.name not in values:
            d = p.default(values) if callable(p.default) else p.default
            values[p.name] = d
            if d is not None:
                p.check(d)
    return {p.name: values[p.name] for p in params}
