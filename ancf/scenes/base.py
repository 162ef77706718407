"""Declarative scenes: named parameters with defaults and ranges, and a run function.

A scene's ``run(params)`` returns a :class:`SceneResult`; the CLI and the reports
only see ``Scene.execute(overrides)``, which validates the input, times the run
and turns the outcome into the public JSON shape
``{scene, params, converged, message, results, cpu_time_s, compile_cpu_s, warnings}``.

``cpu_time_s`` is the process CPU time of the run without the compilation of numba
kernels or their loading from numba's on-disk cache (a first call in a process), which
is ``compile_cpu_s`` (:mod:`ancf.common.compile_time`): the same solve reports about the
same ``cpu_time_s`` with an empty cache, a warm cache or in a warm process.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Callable

from ancf.common.compile_time import compile_cpu
from ancf.common.diagnostics import nonfinite, numerical_warnings
from ancf.common.params import InputError


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
    # Optional declarations for sweeps / recommendations (ancf.study.references): the
    # parameters that choose the model (the rest define the problem), the physics the
    # scene needs (ancf.study.references.PHYSICS) and the name of its reference.  Scenes that
    # have an entry in ancf.study.references.SPECS need none of them.
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
        with numerical_warnings() as noted, compile_cpu() as compiled:
            res = self.run(params)
        cpu = max(time.process_time() - t0 - compiled.seconds, 0.0)
        res.warnings += noted + (self.warn(params, res) if self.warn else [])
        bad = nonfinite(res.results) if res.converged else []
        if bad:
            res.converged, res.message = False, f"non-finite result(s): {', '.join(bad)}"
        out = {"scene": self.name, "params": params, "converged": bool(res.converged),
               "message": res.message, "results": res.results, "cpu_time_s": cpu,
               "compile_cpu_s": compiled.seconds, "warnings": list(res.warnings)}
        return out, res
