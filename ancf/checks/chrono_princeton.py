"""The Princeton beam (Dowell et al. 1977; issue 35) with Chrono's ANCF beams
(``ancf3243``, ``ancf3333``) through :mod:`ancf.models.chrono_beam`, against the ANSYS beam
elements of :mod:`ancf.scenes.beam3d_published`.

Problem as the suite's ``princeton-beam`` scene has it: the clamped strip of
``pub.PRINCETON`` (L, h along y, b along z in m; E in Pa, nu), both shear corrections
k1 = k2 = k_s = J/(I_y + I_z) (:func:`ancf.models.beam3d.torsion_factor`: the rigid-section
continuum's torsional stiffness k_s G (I_y + I_z) is then St-Venant's G J), the dead tip
force of magnitude F (``pub.PRINCETON_LOADS``, N) at the angle beta from -y towards -z:

    f = -F (0, cos beta, sin beta)   at the tip axis (xi = 1, eta = zeta = 0)

(the published load turns towards +z: the mirror image, the same |u_y|, |u_z|).  The
elements' defaults: exact Gauss rules (5 x 3 x 3) and Chrono's Poisson split (the Poisson
block only on the axis); without the split the strip locks (u_z about 23 % low).

Solve: ``LOAD_STEPS`` equal load steps, each a Newton solve from the previous state.
Results: the tip displacements |u_y|, |u_z| (m; u = tip axis point - reference) and their
errors ours / ANSYS - 1, ``None`` where ANSYS is 0 by symmetry (u_z at 0 deg, u_y at 90
deg), as :mod:`ancf.checks.beam3d_benchmarks` compares them.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass

from ancf.models import chrono_beam as cb
from ancf.models.beam3d import torsion_factor
from ancf.scenes import beam3d_published as pub

N_ELEMENTS = 16
LOAD_STEPS = 4
STEP_RTOL, FINAL_RTOL = 1e-6, 1e-8  # Newton |R_f| / |F_f| of the intermediate, last step
# (1e-10 stalls at ~2e-9 at the large deflections: round-off of Q)


def beam(element: str, n: int = N_ELEMENTS, naxis: int | None = None) -> cb.Beam:
    """The clamped Princeton strip of n ``element`` ("3243" or "3333") elements, ``naxis``
    Gauss points along the axis (None: exact, ``chrono_beam.Beam``); rho is NaN: statics
    without gravity need no density."""
    p = pub.PRINCETON
    ks = torsion_factor(p["h"], p["b"])
    return cb.Beam(element=element, n=n, L=p["L"], H=p["h"], W=p["b"], rho=math.nan, E=p["E"],
                   nu=p["nu"], k1=ks, k2=ks, naxis=naxis)


@dataclass(frozen=True)
class Result:
    """|u_y|, |u_z| of the tip (m), Newton iterations over all steps, CPU seconds, and
    whether every step converged (to its rtol or the round-off floor)."""

    uy: float
    uz: float
    iterations: int
    cpu_s: float
    converged: bool


def solve(element: str, load: str, beta_deg: float, n: int = N_ELEMENTS,
          steps: int = LOAD_STEPS, naxis: int | None = None) -> Result:
    """The Princeton beam under ``pub.PRINCETON_LOADS[load]`` at beta_deg (deg), ``naxis``
    Gauss points along the axis (None: exact)."""
    t0 = time.process_time()
    b = beam(element, n, naxis)
    F, beta = pub.PRINCETON_LOADS[load], math.radians(beta_deg)
    f = cb.tip_load(b, force=(0.0, -F * math.cos(beta), -F * math.sin(beta)))
    e, its, ok = None, 0, True
    for k in range(1, steps + 1):
        sol = cb.solve_static(b, f * k / steps, rtol=FINAL_RTOL if k == steps else STEP_RTOL,
                              start=e)
        e, its = sol.e, its + sol.iterations
        ok = ok and (sol.converged or sol.residual <= 10.0 * sol.floor)
    u = cb.tip_frame(b, e)[0] - cb.tip_frame(b, b.reference())[0]
    return Result(abs(u[1]), abs(u[2]), its, time.process_time() - t0, ok)


def ansys(load: str, beta_deg: float) -> tuple[float, float]:
    """The published ANSYS beam-element |u_y|, u_z (m) at the load and angle (deg)."""
    i = pub.PRINCETON_ANGLES.index(beta_deg)
    return tuple(c[i] for c in pub.PRINCETON_ANSYS[load][pub.PRINCETON_REFERENCE])


def relative(ours: float, published: float):
    """ours / published - 1, None where the published value is 0 (by symmetry)."""
    return None if published == 0.0 else ours / published - 1.0


def row(element: str, load: str, beta_deg: float, n: int = N_ELEMENTS,
        naxis: int | None = None) -> dict:
    """One table row: ours, ANSYS and the relative errors of u_y, u_z, iterations, CPU s
    (``naxis`` Gauss points along the axis, None: exact)."""
    r, (ay, az) = solve(element, load, beta_deg, n, naxis=naxis), ansys(load, beta_deg)
    return {"element": element, "load": load, "beta": beta_deg, "uy": r.uy, "ansys uy": ay,
            "uy error": relative(r.uy, ay), "uz": r.uz, "ansys uz": az,
            "uz error": relative(r.uz, az), "iterations": r.iterations, "cpu s": r.cpu_s,
            "converged": r.converged}


def table(rows: list[dict]) -> str:
    """The rows as a fixed-width text table (displacements in mm, errors in %)."""
    def pct(x):
        return "     -" if x is None else f"{100 * x:+6.2f}"
    head = ("element load  beta  u_y ours   ANSYS   err %  u_z ours   ANSYS   err %  "
            "iter  cpu s")
    lines = [head] + [
        f"{r['element']:>7} {r['load']:>4} {r['beta']:5.0f} {1e3 * r['uy']:9.4f} "
        f"{1e3 * r['ansys uy']:7.4f} {pct(r['uy error'])} {1e3 * r['uz']:9.4f} "
        f"{1e3 * r['ansys uz']:7.3f} {pct(r['uz error'])} {r['iterations']:5d} "
        f"{r['cpu s']:6.2f}" for r in rows]
    return "\n".join(lines)
