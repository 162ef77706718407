"""One of Chrono's ANCF elements at a stated state: its parameters and matrices, for
``ancf element NAME`` (issue 35), so that other codes can be compared with ours.

:data:`ELEMENTS` maps each name (``ancf3243``, ``ancf3333`` beams, ``ancf3443``,
``ancf3833``, ``ancf3423`` shells, ``ancf3843`` brick) to an :class:`ElementSpec`: its parameters
(:class:`~ancf.common.params.Param`, defaults = the parameters of Chrono's unit tests
``utest_FEA_ANCF*_Formulation.cpp``) and ``matrices(p)``, which evaluates the element's
own module (no numerics here).  The state is Chrono's: every node at the reference
(``reference_coordinates``), then ``displacement`` (m) added to the ``component`` of
node ``node``'s position and ``velocity`` (m/s) given to the same coordinate; Chrono's
"SmallDisp" is displacement = 0.001, "SmallVel" velocity = 0.001, both on the node and
component of the defaults.  alpha defaults to Chrono's damped cases' 0.01 s: K and Q at
rest velocity do not depend on it, so the defaults reproduce every stored file.

The matrices are those of M e'' + Q(e, e') = Q_ext (``continuum3d``): the mass M (kg),
the gravity force Q_g (N), the internal force Q (N; Chrono's ``ComputeInternalForces``
stores -Q), K = dQ/de (N/m) and R = dQ/de' (N s/m); N m, kg m ... on gradient entries.
"""
from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Callable

import numpy as np

from ancf.common.params import InputError, Param, resolve

from . import ancf3243, ancf3333, ancf3423, ancf3443, ancf3833, ancf3843
from .material import isotropic_3d

_POS = dict(lo=0, lo_open=True)


def _k_timoshenko(v: dict) -> float:
    """Chrono's beams' shear correction 10 (1 + nu) / (12 + 11 nu) (its tests' k1 = k2)."""
    return 10 * (1 + v["nu"]) / (12 + 11 * v["nu"])


def _dimensions(names, values, docs):
    """The element's dimensions (m, > 0), defaults Chrono's tests' (``SetDimensions``)."""
    return tuple(Param(n, v, float, "m", d, **_POS) for n, v, d in zip(names, values, docs))


def _common(nnode: int, node: int):
    """rho, E, nu, alpha, g and the state: Chrono's tests' values as defaults."""
    return (
        Param("rho", 7850.0, float, "kg/m^3", "density", **_POS),
        Param("E", 210e9, float, "Pa", "Young's modulus", **_POS),
        Param("nu", 0.3, float, "-", "Poisson's ratio", lo=0, hi=0.5, hi_open=True),
        Param("alpha", 0.01, float, "s", "Kelvin-Voigt damping: stress = D (strain + alpha "
              "strain rate) (Chrono's damped cases)", lo=0),
        Param("gx", 0.0, float, "m/s^2", "gravitational acceleration, x", lo=-1e6, hi=1e6),
        Param("gy", 0.0, float, "m/s^2", "gravitational acceleration, y", lo=-1e6, hi=1e6),
        Param("gz", -9.80665, float, "m/s^2", "gravitational acceleration, z", lo=-1e6, hi=1e6),
        Param("node", node, int, "", "the node displaced and driven (numbered as the "
              "element's coordinates; default: the one Chrono's tests move)", lo=0, hi=nnode - 1),
        Param("component", 2, int, "", "the position component displaced and driven "
              "(0 x, 1 y, 2 z)", lo=0, hi=2),
        Param("displacement", 0.0, float, "m", "added to that coordinate (Chrono's SmallDisp: "
              "0.001)", lo=-1e3, hi=1e3),
        Param("velocity", 0.0, float, "m/s", "that coordinate's velocity (Chrono's SmallVel: "
              "0.001)", lo=-1e3, hi=1e3),
    )


_BEAM_DIMS = _dimensions(("L", "H", "W"), (1.0, 0.1, 0.1),
                         ("length (x)", "section height (y)", "section width (z)"))
_SHEAR = tuple(Param(k, _k_timoshenko, float, "-", f"shear correction factor of the {s} shear "
                     "(default Chrono's 10 (1 + nu) / (12 + 11 nu))", **_POS)
               for k, s in (("k1", "xz"), ("k2", "xy")))
_SHELL_DIMS = _dimensions(("L", "W", "H"), (1.0, 1.0, 0.01),
                          ("length (x)", "width (y)", "thickness (z)"))
_BRICK_DIMS = _dimensions(("Lx", "Ly", "Lz"), (1.0, 1.0, 1.0),
                          ("length (x)", "length (y)", "length (z)"))


@dataclass(frozen=True)
class ElementSpec:
    """An element of :data:`ELEMENTS`: ``module`` (its ``ancf*`` module), ``nnode`` nodes
    of NDOF / nnode coordinates each (position first), its parameters and ``dims`` (the
    names of its dimensions, in its module's argument order), ``material(p)`` the
    material arguments of its internal force after the dimensions."""

    name: str
    doc: str
    module: object
    nnode: int
    params: tuple
    dims: tuple
    material: Callable[[dict], tuple]

    def resolve(self, overrides: dict | None = None) -> dict:
        """All parameter values: defaults (some following others), then ``overrides``
        (strings or values, each parsed by its Param: one InputError naming the field)."""
        return resolve(self.params, overrides, f"element {self.name!r}")

    def state(self, p: dict):
        """(e, e') (NDOF,) each: the reference with the stated displacement and velocity."""
        m = self.module
        e = m.reference_coordinates(*[p[d] for d in self.dims][:_REF_ARGS[m]])
        edot = np.zeros(m.NDOF)
        i = p["node"] * (m.NDOF // self.nnode) + p["component"]
        e[i] += p["displacement"]
        edot[i] = p["velocity"]
        return e, edot

    def matrices(self, p: dict) -> dict:
        """The element's arrays at the resolved parameters ``p`` (module docstring)."""
        m, dims = self.module, [p[d] for d in self.dims]
        e, edot = self.state(p)
        args = (e, edot, *dims, *self.material(p), p["alpha"])
        K, R = m.internal_force_jacobians(*args)
        return {"coordinates": e, "mass_matrix": m.mass_matrix(*dims, p["rho"]),
                "gravity": m.gravity(*dims, p["rho"], (p["gx"], p["gy"], p["gz"])),
                "internal_force": m.internal_force(*args), "stiffness": K, "damping": R}

    def execute(self, overrides: dict | None = None) -> dict:
        """Resolve, evaluate and time: the public dict of ``ancf element NAME --json``
        (arrays as lists; a non-finite entry is named in ``warnings``)."""
        p = self.resolve(overrides)
        t0 = time.process_time()
        arrays = self.matrices(p)
        cpu = time.process_time() - t0
        bad = [k for k, a in arrays.items() if not np.all(np.isfinite(a))]
        return {"element": self.name, "params": p,
                **{k: a.tolist() for k, a in arrays.items()}, "cpu_time_s": cpu,
                "warnings": [f"non-finite entries in {k}" for k in bad]}


#: how many leading dimensions each module's ``reference_coordinates`` takes
_REF_ARGS = {ancf3243: 1, ancf3333: 1, ancf3443: 2, ancf3833: 2, ancf3423: 2, ancf3843: 3}


def _beam_material(p):
    return p["E"], p["nu"], p["k1"], p["k2"]


def _spec(name, doc, module, nnode, node, dims, material, extra=()):
    return ElementSpec(name, doc, module, nnode, dims + _common(nnode, node) + extra,
                       tuple(d.name for d in dims), material)


#: name -> ElementSpec, defaults = Chrono's unit tests (node: the one they move)
ELEMENTS = {s.name: s for s in (
    _spec("ancf3243", "Chrono's fully parameterised beam (2 nodes: r, r_x, r_y, r_z)",
          ancf3243, 2, 1, _BEAM_DIMS, _beam_material, _SHEAR),
    _spec("ancf3333", "Chrono's shear-deformable beam (3 nodes A, B, C: r, r_y, r_z)",
          ancf3333, 3, 2, _BEAM_DIMS, _beam_material, _SHEAR),
    _spec("ancf3443", "Chrono's 4-node shell (r, r_x, r_y, r_z)", ancf3443, 4, 1,
          _SHELL_DIMS, lambda p: (isotropic_3d(p["E"], p["nu"]),)),
    _spec("ancf3833", "Chrono's 8-node higher-order shell (r, r_z, r_zz)", ancf3833, 8, 1,
          _SHELL_DIMS, lambda p: (p["E"], p["nu"])),
    _spec("ancf3423", "Chrono's 4-node ANS/EAS shell (r, r_z)", ancf3423, 4, 1, _SHELL_DIMS,
          lambda p: (p["E"], p["nu"])),
    _spec("ancf3843", "Chrono's 8-node brick (r, r_x, r_y, r_z)", ancf3843, 8, 1,
          _BRICK_DIMS, lambda p: (p["E"], p["nu"])),
)}


def element(name: str) -> ElementSpec:
    """The spec of ``name``; an unknown name is an InputError listing the allowed ones."""
    if name not in ELEMENTS:
        raise InputError(f"element: unknown name {name!r}; allowed: {', '.join(ELEMENTS)}")
    return ELEMENTS[name]
