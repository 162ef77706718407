"""Declarative scenes: named parameters with defaults and ranges, and a run function.

A scene's ``run(params)`` returns a :class:`SceneResult`; the CLI and the reports
only see ``Scene.execute(overrides)``, which validates the input, times the run
and turns the outcome into the public JSON shape
``{scene, params, converged, message, results, cpu_time_s, compile_cpu_s, warnings}``.

``cpu_time_s`` is the process CPU time of the run without the compilation of numba
kernels or their loading from numba's on-disk cache (a first call in a process), which
is ``compile_cpu_s`` (:mod:`ancf.common.compile_time`): the same solve reports about the
same ``cpu_time_s`` with an empty cache, a warm cache or in a warm process.  Every run
uses one BLAS thread (:func:`ancf.common.threads.blas_pinned`): its numbers do not
depend on the machine's core count.

A static scene that ``ancf modes`` serves (:mod:`ancf.scenes.modes`) also declares
``modal``: ``params -> ModalModel``, its model with a density, and ``modal_params``, the
parameters ``ancf modes`` adds to the scene's own (the density, where the static run
needs none: :data:`STEEL_DENSITY`).  ``ancf modes --about equilibrium`` vibrates about the
scene's run (or its ``equilibrium``, where the run is a linear solve), checked and warned
exactly as ``ancf run`` checks it.

A scene also declares its result keys (``results``: :func:`field` per key, the JSON
schema of :mod:`ancf.study.schemas` is built from them) and what sweeps measure it against
(``study``: a function returning its :class:`ancf.scenes.spec.SceneSpec`, imported only
when called, so that ``ancf run`` loads no study machinery; ``frequency_study`` the same
for its natural frequencies).
"""
from __future__ import annotations

import time
import dataclasses
from dataclasses import dataclass
from typing import Callable, NamedTuple

from ancf.common.compile_time import compile_cpu
from ancf.common.diagnostics import nonfinite, numerical_warnings
from ancf.common.params import Param, resolve
from ancf.common.threads import blas_pinned
from ancf.solvers.linear import Singular

#: the density ``ancf modes`` adds to the scenes of steel beams and plates, whose static
#: runs need no mass: steel, the material of their E = 2.07e11 (2.1e11) Pa
STEEL_DENSITY = Param("rho", 7850.0, float, "kg/m^3",
                      "density (ancf modes only: the static run needs no mass; default steel)",
                      lo=0, lo_open=True)


NUM, INT, STR, BOOL = "number", "integer", "string", "boolean"


class ReferenceFailed(RuntimeError):
    """The reference could not be computed (message says why)."""


def field(kind: str, doc: str, nullable: bool = False, required: bool = True,
          items: str | None = None, keys: dict | None = None) -> dict:
    """Declaration of one result key (``items``: the element type of an array; ``keys``:
    the declarations of an object's keys)."""
    return {"kind": kind, "doc": doc, "nullable": nullable, "required": required,
            "items": items, "keys": keys}


def series(doc: str, nullable: bool = False) -> dict:
    """A sampled time history: an array of numbers (null where not finite; ``nullable``:
    the whole array null when the run stopped)."""
    return field("array", doc, nullable=nullable, items=NUM)


def nullable(doc: str) -> dict:
    """A number, null when the run did not converge."""
    return field(NUM, doc, nullable=True)


#: the result keys of every static solve (Newton over load steps)
STATIC_RESULTS = {
    "newton_iterations": field(INT, "Newton iterations over all load steps"),
    "load_steps_taken": field(INT, "converged load steps"),
    "load_factor": field(NUM, "load factor reached (1 when converged)"),
    "tangent_evaluations": field(INT, "tangent-stiffness evaluations", required=False),
    "factorizations": field(INT, "factorisations of the tangent", required=False),
    "negative_tangent_eigenvalues": field(
        INT, "negative eigenvalues of the reduced tangent at the solution (absent when Newton "
             "stopped; null when the model is too large for the dense check)",
        nullable=True, required=False),
    "zero_tangent_eigenvalues": field(INT, "zero eigenvalues of the reduced tangent",
                                      nullable=True, required=False),
    "lowest_tangent_eigenvalue_rel": field(NUM, "lowest eigenvalue / largest |eigenvalue|",
                                           nullable=True, required=False),
}

#: the result keys of every time integration
DYNAMIC_RESULTS = {
    "times": series("sample times, s"),
    "integrator": field(STR, "time integrator used"),
    "steps": field(INT, "accepted time steps"),
    "nfev": field(INT, "force evaluations"),
    "njev": field(INT, "Jacobian (tangent) evaluations"),
    "nlu": field(INT, "LU factorisations"),
    "newton_iterations": field(INT, "Newton iterations (implicit integrators)"),
    "rejected_steps": field(INT, "rejected time steps"),
    "integration_cpu_s": field(NUM, "CPU time of the integration, s"),
    "constraint_violation_m": field(NUM, "largest constraint violation, m", nullable=True),
    "samples": field(INT, "number of samples"),
    "t_reached": field(NUM, "last time reached, s"),
}


@dataclass
class SceneResult:
    converged: bool
    message: str
    results: dict
    extra: dict = dataclasses.field(default_factory=dict)  # arrays etc. for reports, not in the JSON
    warnings: list = dataclasses.field(default_factory=list)  # accuracy diagnoses, one line each


class Equilibrium(NamedTuple):
    """A static solve's outcome (what :attr:`ModalModel.equilibrium` returned to ``ancf
    modes`` before it took the scene's checked run instead)."""

    q: object                # global coordinates reached
    converged: bool
    message: str
    newton_iterations: int


@dataclass(frozen=True)
class ModalModel:
    """A static scene's model for ``ancf modes``: the element groups with their density
    (``assembly``: tangent stiffness and consistent mass), the reduced numbering of the
    scene's constraints (``pattern``, as its static solve eliminates them), the reference
    state ``q0``, ``equilibrium`` (not read: ``ancf modes`` takes the equilibrium from the
    scene, :attr:`Scene.equilibrium` or its run, with the run's checks; None), and
    ``points``: global coordinates -> positions (m, dim) of the sample points of the mode shapes (linear in
    the coordinates), ``sampling`` naming them; ``mesh`` for the result's arrays."""

    assembly: object
    pattern: object
    q0: object
    equilibrium: Callable[[], Equilibrium] | None
    points: Callable
    sampling: str
    mesh: object


@dataclass(frozen=True)
class Scene:
    name: str
    doc: str
    params: tuple
    run: Callable[[dict], SceneResult]
    check: Callable[[dict], None] | None = None  # cross-field validation
    # Optional declarations for sweeps / recommendations of a scene without ``study``: the
    # parameters that choose the model (the rest define the problem), the physics the
    # scene needs (ancf.scenes.spec.PHYSICS) and the name of its reference.
    knobs: tuple = ()
    needs: tuple = ()
    reference: str | None = None
    # result key -> field(...) declaration: the JSON schema of results (ancf.study.schemas)
    results: dict = dataclasses.field(default_factory=dict)
    # () -> ancf.scenes.spec.SceneSpec: reference, error, grids (None: a self-reference
    # from knobs / needs); frequency_study the same for its frequencies (ancf modes)
    study: Callable[[], object] | None = None
    frequency_study: Callable[[], object] | None = None
    # accuracy checks of a finished run: (params, result) -> list of one-line warnings
    warn: Callable[[dict, SceneResult], list] | None = None
    # ancf modes: params -> ModalModel (None: the scene has no modes), and the parameters
    # it adds to the scene's own
    modal: Callable[[dict], ModalModel] | None = None
    modal_params: tuple = ()
    # ancf modes --about equilibrium: params -> the static equilibrium of the modal model
    # (extra["q"]) with the checks of ``run`` (None: ``run`` itself, when the run is that
    # nonlinear equilibrium); ``warn`` is applied to it as to a run
    equilibrium: Callable[[dict], SceneResult] | None = None
    # in the reports' speed-accuracy sweeps (False: a drive-file scene, whose model
    # choices live in its file)
    swept: bool = True

    def resolve(self, overrides: dict | None = None) -> dict:
        """All parameter values: defaults, then ``overrides`` (strings or values)."""
        values = resolve(self.params, overrides, f"scene {self.name!r}")
        if self.check is not None:
            self.check(values)
        return values

    def execute(self, overrides: dict | None = None) -> tuple[dict, SceneResult]:
        """Validate, run and time; returns (public JSON dict, full result)."""
        params = self.resolve(overrides)
        t0 = time.process_time()
        with blas_pinned(), numerical_warnings() as noted, compile_cpu() as compiled:
            try:
                res = self.run(params)
            except Singular as exc:  # a solve no solver layer turned into non-convergence
                res = SceneResult(False, f"No solution: a singular solve ({exc})", {})
        cpu = max(time.process_time() - t0 - compiled.seconds, 0.0)
        res.warnings += noted + (self.warn(params, res) if self.warn else [])
        bad = nonfinite(res.results) if res.converged else []
        if bad:
            res.converged, res.message = False, f"non-finite result(s): {', '.join(bad)}"
        out = {"scene": self.name, "params": params, "converged": bool(res.converged),
               "message": res.message, "results": res.results, "cpu_time_s": cpu,
               "compile_cpu_s": compiled.seconds, "warnings": list(res.warnings)}
        return out, res
