"""Shared pieces of the static planar-beam scenes (thesis 2.4, report section 7).

Element parameters common to the scenes, the model builder, and a static solve
that also checks that the equilibrium found is stable (a converged Newton point
with negative tangent eigenvalues is reported as non-convergence: it is how the
spurious zero-energy modes of the report's 1-point shear scheme show up).
:func:`modal` gives a scene's model to ``ancf modes`` (``ancf.scenes.modes``), with
:func:`centreline` the sample points of its mode shapes.
"""
from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from ancf.core.assembly import Assembly, ElementGroup
from ancf.core.constraints import Elimination
from ancf.elements.catalogue import ELEMENTS, element_kwargs
from ancf.core.mesh import BeamMesh
from ancf.core.pattern import ReducedPattern
from ancf.core.quadrature import RectangularSection
from ancf.core.validity import UNSTABLE
from ancf.common.params import InputError, Param
from ancf.scenes.base import ModalModel, SceneResult
from ancf.solvers.linear import ZERO_EIGENVALUE_REL
from ancf.solvers.static import NewtonOptions, solve_static, stability_at

#: a beam's mode shapes are sampled at this many points along it at least (each element
#: at the same number of points, its nodes among them)
CENTRELINE_POINTS = 32


def element_params(E=2.07e11, nu=0.0, h=0.1, n_elements=8) -> tuple:
    """Parameters every static beam scene has, with the papers' values as defaults."""
    return (
        Param("element", "linear", str, doc="element type", choices=tuple(ELEMENTS)),
        Param("integration", "thesis", str,
              doc="integration scheme (linear: thesis, exact, report-selective, report-fix; "
                  "omar-shabana: thesis, exact) or a spec like 'normal=2x2,shear=1x1'"),
        Param("n_elements", n_elements, int, doc="number of elements", lo=1, hi=4096),
        Param("E", E, float, "Pa", "Young's modulus", lo=0, lo_open=True),
        Param("nu", nu, float, "-", "Poisson's ratio", lo=0, hi=0.5, hi_open=True),
        Param("L", 2.0, float, "m", "beam length", lo=0, lo_open=True),
        Param("h", h, float, "m", "section height (y)", lo=0, lo_open=True),
        Param("b", 0.1, float, "m", "section width (z)", lo=0, lo_open=True),
        Param("ks", 5.0 / 6.0, float, "-", "shear correction factor (linear element)",
              lo=0, lo_open=True, hi=2),
        Param("load_steps", 1, int, doc="initial number of load steps (adaptive)", lo=1, hi=10000),
        Param("rtol", 1e-8, float, doc="Newton residual tolerance relative to the load",
              lo=0, lo_open=True, hi=1e-2),
        Param("max_iterations", 25, int, doc="Newton iterations allowed per load step",
              lo=1, hi=1000),
        Param("stability_check", "auto", str,
              doc="stability of the equilibrium by the inertia of the tangent (LDL^T, any "
                  "size; auto = on)",
              choices=("auto", "on", "off")),
    )


def check_integration(p: dict) -> None:
    cls = ELEMENTS[p["element"]]
    try:
        cls.scheme_terms(p["integration"], np.eye(3), np.eye(3))
    except ValueError as exc:
        raise InputError(f"integration = {p['integration']!r} is not valid for element "
                         f"{p['element']} ({exc}); allowed: {', '.join(cls.schemes)} or a spec "
                         "'normal=NXxNY,shear=NXxNY' or 'all=NXxNY' (NY may be e = exact)") from None


def build(p: dict):
    """(mesh, q0, assembly) of a straight beam along +x from the origin, of the
    catalogue element ``p["element"]`` (density ``p["rho"]`` if given, else 0: statics).
    The mesh and assembly (read-only) are built once per structure and shared by the runs
    of a sweep or a table (:func:`_built`); q0 is the caller's own copy."""
    kw = element_kwargs(p["element"], p)
    mesh, q0, asm = _built(p["element"], p["L"], p["n_elements"], p["b"], p["h"], p["E"],
                           p["nu"], p.get("rho", 0.0), p["integration"], tuple(sorted(kw.items())))
    return mesh, q0.copy(), asm


@lru_cache(maxsize=32)
def _built(element: str, L: float, n: int, b: float, h: float, E: float, nu: float,
           rho: float, integration: str, kwargs: tuple):
    cls = ELEMENTS[element]
    mesh = BeamMesh(L, n, cls.slots)
    q0 = mesh.reference()
    q0.flags.writeable = False
    el = cls(mesh.lengths, q0[mesh.dofmap], RectangularSection(b, h), E, nu, rho=rho,
             integration=integration, **dict(kwargs))
    return mesh, q0, Assembly(mesh.n_dofs, [ElementGroup(el, mesh.dofmap)])


def newton_options(p: dict) -> NewtonOptions:
    """The Newton options of the parameters ``load_steps``, ``rtol``, ``max_iterations``
    (the defaults of :class:`NewtonOptions` for those a scene does not have)."""
    names = {"load_steps": "n_steps", "rtol": "rtol", "max_iterations": "max_iter"}
    return NewtonOptions(**{opt: p[name] for name, opt in names.items() if name in p})


def solve(p: dict, mesh, q0, assembly, elim: Elimination, Qk, results_fn,
          forces=None) -> SceneResult:
    """Static solve + stability check, packaged as a scene result; ``forces``: the
    configuration-dependent force terms (an ``ancf.core.forces.Forces``) or None."""
    res = solve_static(assembly, elim, Qk, q0, newton_options(p), forces=forces)
    results = {"newton_iterations": res.iterations, "load_steps_taken": res.load_steps,
               "load_factor": res.load_factor, "tangent_evaluations": res.tangent_evaluations,
               "factorizations": res.factorizations}
    converged, message = res.converged, res.message
    results.update(results_fn(res.q) if converged else dict.fromkeys(results_fn(q0)))
    if converged:
        neg, zero, lowest = ((None, None, None) if p.get("stability_check") == "off"
                             else stability_at(assembly, res.pattern, res.q, forces, res.tangent))
        results["negative_tangent_eigenvalues"] = neg
        results["zero_tangent_eigenvalues"] = zero
        results["lowest_tangent_eigenvalue_rel"] = lowest
        if neg:
            converged = False
            message = (f"No convergence to a stable equilibrium: Newton converged to a point with "
                       f"{neg} negative tangent eigenvalue(s) (spurious zero-energy modes activated)")
        elif zero:
            converged = False
            message = (f"No convergence to a unique equilibrium: the tangent at the converged point "
                       f"is singular ({zero} eigenvalue(s) below {ZERO_EIGENVALUE_REL:g} of the "
                       f"largest: a zero-energy mode of the integration scheme)")
    return SceneResult(converged, message, results,
                       extra={"q": res.q, "q0": q0, "mesh": mesh, "residuals": res.residual_history,
                              "assembly": assembly, "pattern": res.pattern,
                              UNSTABLE: res.converged and not converged})


def centreline(mesh):
    """Global coordinates -> points (m, dim) along a beam mesh's centreline, at least
    :data:`CENTRELINE_POINTS` of them, each element sampled alike from its first node."""
    from ancf.scenes.frames import beam_sampler  # not needed by ancf run
    return beam_sampler(mesh, max(1, math.ceil(CENTRELINE_POINTS / mesh.n_elements)))[0]


def modal(p: dict, mesh, q0, assembly, elim: Elimination, Qk, points=None,
          sampling: str = "centreline") -> ModalModel:
    """The model of a scene solved by :func:`solve` for ``ancf modes``: its constraints'
    reduced numbering and the sample points (default: the beam's :func:`centreline`);
    ``p`` and the load ``Qk`` are those of the scene's ``setup`` (its run, with the run's
    checks, is the equilibrium ``ancf modes`` vibrates about)."""
    T, _, _ = elim.build()
    pattern = ReducedPattern(assembly.n_dofs, [grp.dofmap for grp in assembly.groups], T)
    return ModalModel(assembly, pattern, q0, None, points or centreline(mesh), sampling, mesh)


#: the meshes of the beams' frequency sweeps
FREQUENCY_MESHES = (2, 4, 8, 16, 32, 64, 128)


def _timoshenko_modes(support: str):
    def values(p):
        from analytic import beam_modes
        return {"frequencies_hz": [float(x) for x in beam_modes.timoshenko(
            support, count=int(p["count"]), L=p["L"], E=p["E"],
            G=p["E"] / (2.0 * (1.0 + p["nu"])), I=p["b"] * p["h"] ** 3 / 12.0,
            A=p["b"] * p["h"], rho=p["rho"], ks=p["ks"])]}
    return values


def frequency_study(scene: str, support: str, what: str):
    """A beam scene's ``--quantity frequency`` spec: its lowest bending frequencies (``ancf
    modes``) against the Timoshenko beam's, ``support`` as ``analytic.beam_modes`` names it."""
    from ancf.scenes.spec import (FREQUENCY_ERROR, STATIC_KNOBS, Reference, SceneSpec,
                                  element_grids, frequency_error)
    name = "timoshenko-frequencies"
    refs = {name: Reference(
        name, "analytic", f"Timoshenko beam frequencies, {what} (`analytic/beam_modes.py`: "
        f"shear and rotary inertia, frequency equations solved numerically); {FREQUENCY_ERROR}",
        _timoshenko_modes(support), frequency_error)}
    grids = element_grids(FREQUENCY_MESHES)
    return SceneSpec(scene, STATIC_KNOBS, frozenset({"bending", "shear"}), refs, name,
                     report_grids=grids, recommend_grids=grids, quantity="frequency",
                     notes=f"The {what} beam's lowest bending frequencies against Timoshenko.")
