"""3D belt-drive benchmarks (thesis 4.6, Table 4.1 Model 2): the scene ``belt3d``'s
full default run, 1.2 s (the driver reaches its final speed at 1.0 s; the slip is
averaged over the last 0.1 s), from the statically settled belt.

- ``test_belt3d_drive``: 20 plates with 25, 49 and 81 contact points per plate and 40
  plates with 81 (dt 1e-4 s, generalised-alpha).  One round each (a run is about a
  minute).  extra_info holds the step statistics (steps, force and Jacobian
  evaluations, factorisations, Newton iterations, rejected steps, element-pulley pairs
  the contact kernel evaluated), the integration CPU time and its value per simulated
  second (averaged over the whole run: ramp-up and full speed), the estimated split
  into elastic forces, contact, linear algebra and the rest
  (:mod:`benchmarks.belt3d_profile`: per-call kernel costs times call counts), and the
  results: driven slip, span tensions (Green strain and the membrane's axial force).

A module fixture first runs 1 ms of the drive, so that compiling (or loading) the
march is not timed in the first case.  No wall-clock thresholds are asserted, only that
the runs reach t_end.
"""
from __future__ import annotations

import pytest

from ancf.scenes import SCENES
from benchmarks.belt3d_profile import COUNTS, run_costs

CASES = ((20, 25), (20, 49), (20, 81), (40, 81))  # (n_elements, contact_points)


@pytest.fixture(scope="module")
def compiled():
    out, _ = SCENES["belt3d"].execute({"t_end": 1e-3, "output_dt": 1e-3})
    assert out["converged"], out["message"]


def belt3d(n: int, points: int):
    out, res = SCENES["belt3d"].execute({"n_elements": n, "contact_points": points})
    assert out["converged"], out["message"]
    return out, res


@pytest.mark.parametrize("n,points", CASES, ids=[f"n{n}-cp{p}" for n, p in CASES])
def test_belt3d_drive(benchmark, compiled, n, points):
    benchmark.group = "3D belt drive, Model 2, 1.2 s (thesis 4.6, Table 4.1)"
    out, res = benchmark.pedantic(belt3d, args=(n, points), rounds=1, warmup_rounds=0)
    r, prm = out["results"], out["params"]
    _, split = run_costs(out, res)
    benchmark.extra_info.update({
        "n_elements": n, "contact_points": points, "dt": prm["dt"], "t_end": prm["t_end"],
        **{k: r[k] for k in COUNTS}, "integration_cpu_s": r["integration_cpu_s"],
        "cpu_per_simulated_s": r["integration_cpu_s"] / r["t_reached"], **split,
        "slip_driven": r["slip_driven"], "T_tight_N": r["T_tight_N"], "T_slack_N": r["T_slack_N"],
        "membrane_tight_N": r["tensions"]["membrane"]["tight"],
        "membrane_slack_N": r["tensions"]["membrane"]["slack"]})
