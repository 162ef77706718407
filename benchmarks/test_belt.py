"""Belt-drive benchmarks (thesis chapter 3): the default 1 s run of ``belt2d``.

- ``test_belt_drive``: 20 and 40 elements, generalised-alpha (the scene's defaults: dt
  2.5e-4 s, 7 contact points).  extra_info holds the integrator, the step statistics
  (steps, force and Jacobian evaluations, factorisations, Newton iterations, rejected
  steps, element-pulley pairs the contact kernel evaluated) and the estimated split of
  the integration time into elastic forces, contact, linear algebra and the rest
  (:mod:`benchmarks.belt_profile`: per-call kernel costs times call counts).

The side-by-side ratio against Exudyn's belt drive is :mod:`benchmarks.peers_belt`.
No wall-clock thresholds are asserted, only that the runs reach t_end.
"""
from __future__ import annotations

import numpy as np
import pytest

from ancf.scenes import SCENES
from benchmarks.belt_profile import breakdown, kernel_costs

BELT_N = (20, 40)
ROUNDS = 3
STATS = ("integrator", "steps", "nfev", "njev", "nlu", "newton_iterations", "rejected_steps",
         "contact_pairs", "integration_cpu_s", "pretension_iterations")


def belt(n: int):
    out, res = SCENES["belt2d"].execute({"n_elements": n})
    assert out["converged"], out["message"]
    return out, res


@pytest.mark.parametrize("n", BELT_N)
def test_belt_drive(benchmark, n):
    benchmark.group = "belt drive 1 s (thesis 3.3, Table 3.1)"
    out, res = benchmark.pedantic(belt, args=(n,), rounds=ROUNDS, warmup_rounds=1)
    r = out["results"]
    run, drive = res.extra["result"], res.extra["drive"]
    omegas = np.array([float(drive.omega_driver(run.t[-1])), float(run.v[-1, -1])])
    split = breakdown(r, kernel_costs(drive, run.q[-1], run.v[-1], omegas))
    benchmark.extra_info.update({"n_elements": n, "dt": out["params"]["dt"],
                                 "gauss_points": out["params"]["gauss_points"],
                                 **{k: r[k] for k in STATS}, **split,
                                 "omega_ratio_steady": r["omega_ratio_steady"]})
