"""Shared pieces of the dynamic planar-beam scenes (thesis 2.4, dynamic examples).

Parameters of the integrators and constraint forms, the two constraint forms of
one ``Elimination`` and the run statistics in the public results; the model is
built by ``beam_static.build`` (with the density ``rho``).
"""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from ancf.core.energy import energy_history
from ancf.core.forces import Forces
from ancf.common.inputs import MAX_STEPS, check_fixed_step, check_sampling, following, intervals
from ancf.core.multipliers import Baumgarte, LinearConstraints
from ancf.scenes import beam_static as bs
from ancf.common.params import Param
from ancf.solvers.dynamics import INTEGRATORS, MultiplierModel, ReducedModel, integrate

RTOL_FLOOR = float(100 * np.finfo(float).eps)  # scipy's solve_ivp raises smaller rtol to this


def section_params(**defaults) -> tuple:
    """element, integration, n_elements, E, nu, L, h, b, ks with scene defaults."""
    keep = ("element", "integration", "n_elements", "E", "nu", "L", "h", "b", "ks")
    base = {p.name: p for p in bs.element_params() if p.name in keep}
    out = []
    for name in keep:
        p = base[name]
        out.append(replace(p, default=defaults.get(name, p.default)))
    return tuple(out)


def dynamic_params(t_end=1.0, integrator="dop853", rtol=1e-8, atol=1e-10, dt=1e-3, rho_inf=0.9,
                   output_dt=0.01) -> tuple:
    return (
        Param("rho", 7850.0, float, "kg/m^3", "density", lo=0, lo_open=True),
        Param("integrator", integrator, str, doc="time integrator", choices=INTEGRATORS),
        Param("rtol", rtol, float, "-", "relative tolerance (scipy integrators; their floor "
              "is 100 machine epsilon)", lo=RTOL_FLOOR, hi=0.1),
        Param("atol", atol, float, "-", "absolute tolerance (scipy integrators; m and m/s)",
              lo=0, lo_open=True, hi=1.0),
        Param("dt", dt, float, "s", "time step (generalized-alpha; above output_dt the samples "
              "are interpolated)", lo=0, lo_open=True, hi=1.0),
        Param("rho_inf", rho_inf, float, "-",
              "generalized-alpha spectral radius at infinite frequency (1 = no dissipation)",
              lo=0, hi=1),
        Param("t_end", t_end, float, "s", "simulated time", lo=0, lo_open=True, hi=1e4),
        Param("output_dt", following(output_dt, "t_end"), float, "s",
              f"sampling interval of the results (default {output_dt:g} s, at most t_end)",
              lo=0, lo_open=True, hi=10),
        Param("constraints", "elimination", str, doc="constraint form",
              choices=("elimination", "lagrange")),
        Param("baumgarte", 20.0, float, "1/s",
              "Baumgarte alpha = beta of the multiplier form with scipy integrators (0: off)",
              lo=0, hi=1e6),
        Param("max_steps", 50_000, int, doc="step budget (beyond it: not converged)",
              lo=1, hi=MAX_STEPS),
    )


def check(p: dict) -> None:
    bs.check_integration(p)
    check_sampling(p)
    check_fixed_step(p)


def model(p: dict, assembly, terms, elim):
    """The elimination or the Lagrange-multiplier model of the same constraints."""
    forces = Forces(assembly.n_dofs, terms)
    if p["constraints"] == "elimination":
        return ReducedModel(assembly, forces, elim.rheonomic()), forces
    return MultiplierModel(assembly, forces, LinearConstraints.from_elimination(elim),
                           Baumgarte(p["baumgarte"], p["baumgarte"])), forces


def times(p: dict) -> np.ndarray:
    """Sample times 0, output_dt, 2 output_dt, ... and t_end."""
    n = intervals(p["t_end"], p["output_dt"])
    return np.minimum(np.arange(n + 1) * p["output_dt"], p["t_end"])


def simulate(p: dict, mdl, q0, v0):
    return integrate(mdl, q0, v0, times(p), p["integrator"], rtol=p["rtol"], atol=p["atol"],
                     dt=p["dt"], rho_inf=p["rho_inf"], max_steps=p["max_steps"])


def energies(assembly, forces, res):
    return energy_history(assembly, forces, res.t, res.q, res.v)


def stats(res) -> dict:
    """Run statistics for the public results."""
    s = res.stats()
    s["samples"] = int(res.t.size)
    s["t_reached"] = float(res.t[-1]) if res.t.size else 0.0
    return s


def as_list(a) -> list:
    return [float(x) for x in np.asarray(a)]
