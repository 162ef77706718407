"""Shared set-up for the benchmarks: the clamped cantilever (Model 1) and one Newton
iteration kernel (tangent assembly + sparse factorisation/solve of the reduced system).

The kernel mirrors ``ancf.reports.studies.newton_iteration_time_ratio`` so the
benchmark numbers and the report's timing study measure the same thing.
"""
from __future__ import annotations

import os
from dataclasses import dataclass

import numpy as np
import scipy.sparse.linalg as spla

from ancf.core.constraints import Elimination
from ancf.elements.catalogue import ELEMENTS as CATALOGUE_ELEMENTS
from ancf.scenes import SCENES
from ancf.scenes import beam_static as bs

ELEMENTS = tuple(CATALOGUE_ELEMENTS)
N_ELEMENTS = (4, 16, 64, 256)
THESIS_RATIO = 0.5  # thesis: a Newton iteration with the linear element is ~2x shorter

# Rounds per n (pedantic mode).  ANCF_BENCH_SCALE multiplies them (e.g. 0.2 for a
# smoke run, 3 for a quieter machine-comparison run).
_SCALE = float(os.environ.get("ANCF_BENCH_SCALE", "1"))
SOLVE_ROUNDS = {4: 20, 16: 20, 64: 10, 256: 5}
KERNEL_ROUNDS = {4: 300, 16: 300, 64: 150, 256: 60}
RATIO_ROUNDS = {4: 400, 16: 400, 64: 300, 256: 150}


def rounds(table: dict, n: int) -> int:
    return max(3, int(round(table[n] * _SCALE)))


def model1(element: str, n: int) -> dict:
    """Cantilever scene overrides for Model 1 (scene defaults: h = 0.1 m, nu = 0.3)."""
    return {"element": element, "n_elements": n}


@dataclass
class KernelSetup:
    element: str
    n_elements: int
    n_dofs: int
    n_free: int
    assembly: object
    T: object  # q = T z + g (clamp eliminated)
    q: np.ndarray  # perturbed configuration satisfying the clamp


def kernel_setup(element: str, n: int, amplitude: float = 1e-3, seed: int = 0) -> KernelSetup:
    """Model 1 cantilever with the scene's clamp (position and r_y of node 0), at the
    reference configuration plus a random perturbation of the free coordinates."""
    p = SCENES["cantilever"].resolve(model1(element, n))
    mesh, q0, asm = bs.build(p)
    elim = Elimination(mesh.n_dofs)
    for slot in ("r", "r_y"):
        for k in (0, 1):
            d = mesh.dof(0, slot, k)
            elim.fix(d, q0[d])
    T, g, free = elim.build()
    z = q0[free] + amplitude * np.random.default_rng(seed).standard_normal(free.size)
    return KernelSetup(element, n, mesh.n_dofs, int(free.size), asm, T, T @ z + g)


def newton_kernel(s: KernelSetup) -> np.ndarray:
    """One Newton iteration: gradient + sparse tangent, reduction to the free
    coordinates, sparse LU and solve; returns the update dz."""
    g, K = s.assembly.gradient_tangent(s.q)
    return spla.splu((s.T.T @ K @ s.T).tocsc()).solve(s.T.T @ g)

