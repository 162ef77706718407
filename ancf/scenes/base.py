"""Declarative scenes: named parameters with defaults and ranges, and a run function.

A scene's ``run(params)`` returns a :class:`SceneResult`; the CLI and the reports
only see ``Scene.execute(overrides)``, which validates the input, times the run
and turns the outcome into the public JSON shape
``{scene, params, converged, message, results, cpu_time_s, warnings}``.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field
from typing import Callable

from ancf.diagnostics import nonfinite, numerical_warnings


class InputError(ValueError):
    """Bad user input; the message names the field and its allowed range."""


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


@dataclass
class SceneResult:
    converged: bool
    message: str
    results: dict
    extra: dict = field(default_factory=dict)  # arrays etc. for reports, not in the JSON
    warnings: list = field(default_factory=list)  # accuracy diagnoses, one line each


@dataclass(frozen=True)
class Scene:
    name: str
    doc: str
    params: tuple
    run: Callable[[dict], SceneResult]
    check: Callable[[dict], None] | None = None  # cross-field validation
    # Optional declarations for sweeps / recommendations (ancf.references): the
    # parameters that choose the model (the rest define the problem), the physics the
    # scene needs (ancf.references.PHYSICS) and the name of its reference.  Scenes that
    # have an entry in ancf.references.SPECS need none of them.
    knobs: tuple = ()
    needs: tuple = ()
    reference: str | None = None
    # accuracy checks of a finished run: (params, result) -> list of one-line warnings
    warn: Callable[[dict, SceneResult], list] | None = None

    def resolve(self, overrides: dict | None = None) -> dict:
        """All parameter values: defaults, then ``overrides`` (strings or values)."""
        overrides = dict(overrides or {})
        names = [p.name for p in self.params]
        unknown = sorted(set(overrides) - set(names))
        if unknown:
            raise InputError(f"{unknown[0]}: unknown parameter of scene {self.name!r}; "
                             f"allowed: {', '.join(names)}")
        values = {}
        for p in self.params:
            if p.name in overrides:
                values[p.name] = p.parse(overrides[p.name])
        for p in self.params:
            if p.name not in values:
                d = p.default(values) if callable(p.default) else p.default
                values[p.name] = d
                if d is not None:
                    p.check(d)
        values = {p.name: values[p.name] for p in self.params}  # declared order
        if self.check is not None:
            self.check(values)
        return values

    def execute(self, overrides: dict | None = None) -> tuple[dict, SceneResult]:
        """Validate, run and time; returns (public JSON dict, full result)."""
        params = self.resolve(overrides)
        t0 = time.process_time()
        with numerical_warnings() as noted:
            res = self.run(params)
        cpu = time.process_time() - t0
        res.warnings += noted + (self.warn(params, res) if self.warn else [])
        bad = nonfinite(res.results) if res.converged else []
        if bad:
            res.converged, res.message = False, f"non-finite result(s): {', '.join(bad)}"
        out = {"scene": self.name, "params": params, "converged": bool(res.converged),
               "message": res.message, "results": res.results, "cpu_time_s": cpu,
               "warnings": list(res.warnings)}
        return out, res
