"""Flexible-pendulum benchmarks (thesis Table 2.5 and the cost of refinement).

- ``test_pendulum``: the 1 s pendulum per element x n (4, 8, 16, 32) x integrator.
- ``test_pendulum_ratio``: both elements run alternately (order swapped every round) in
  one benchmark, so machine-load drift hits both; extra_info holds the medians and the
  ratio linear / Omar-Shabana next to the thesis's 65 % (4 elements) and 68 % (8).
- ``test_cost_per_simulated_second``: linear element, 8 ... 256 elements, a short run
  (``SCALING_T_END``) scaled to CPU seconds per simulated second.

No wall-clock thresholds are asserted, only that the runs reach t_end.
"""
from __future__ import annotations

import time

import numpy as np
import pytest

from ancf.scenes import SCENES
from benchmarks.kernels import ELEMENTS, rounds

INTEGRATORS = {"dop853": {}, "radau": {"integrator": "radau", "rtol": 1e-6, "atol": 1e-9},
               "generalized-alpha": {"integrator": "generalized-alpha", "dt": 1e-3}}
PENDULUM_N = (4, 8, 16, 32)
THESIS_CPU_RATIO = {4: 0.65, 8: 0.68}  # thesis Table 2.5, linear / Omar-Shabana
SCALING_N = (8, 16, 32, 64, 128, 256)
SCALING_T_END = 0.05  # s
RUN_ROUNDS = {4: 3, 8: 3, 16: 3, 32: 3}
RATIO_ROUNDS = {4: 7, 8: 7, 16: 5, 32: 5}
SCALING_ROUNDS = {n: 3 for n in SCALING_N}


def pendulum(element: str, n: int, integrator: str, **extra) -> dict:
    out, _ = SCENES["pendulum"].execute(dict(element=element, n_elements=n,
                                             **INTEGRATORS[integrator], **extra))
    assert out["converged"], out["message"]
    return out


def _run_info(out) -> dict:
    r = out["results"]
    return {k: r.get(k) for k in ("steps", "nfev", "njev", "integration_cpu_s",
                                  "energy_max_deviation_J")}


@pytest.mark.parametrize("integrator", INTEGRATORS)
@pytest.mark.parametrize("n", PENDULUM_N)
@pytest.mark.parametrize("element", ELEMENTS)
def test_pendulum(benchmark, element, n, integrator):
    benchmark.group = f"pendulum 1 s, {integrator}"
    out = benchmark.pedantic(pendulum, args=(element, n, integrator),
                             rounds=rounds(RUN_ROUNDS, n), warmup_rounds=0)
    benchmark.extra_info.update({"element": element, "n_elements": n,
                                 "integrator": integrator, **_run_info(out)})


@pytest.mark.parametrize("integrator", INTEGRATORS)
@pytest.mark.parametrize("n", PENDULUM_N)
def test_pendulum_ratio(benchmark, n, integrator):
    benchmark.group = "pendulum CPU ratio linear/Omar-Shabana (Table 2.5)"
    times = {el: [] for el in ELEMENTS}
    steps = {}
    state = {"round": 0}

    def pair():
        order = ELEMENTS if state["round"] % 2 == 0 else ELEMENTS[::-1]
        state["round"] += 1
        for el in order:
            t0 = time.process_time()
            out = pendulum(el, n, integrator)
            times[el].append(time.process_time() - t0)
            steps[el] = out["results"]["steps"]

    benchmark.pedantic(pair, rounds=rounds(RATIO_ROUNDS, n), warmup_rounds=0)
    lin, osh = (np.asarray(times[el]) for el in ELEMENTS)
    ratio = float(np.median(lin) / np.median(osh))
    assert np.isfinite(ratio) and ratio > 0
    benchmark.extra_info.update({
        "n_elements": n, "integrator": integrator, "samples": int(lin.size),
        "linear_median_s": float(np.median(lin)), "omar_shabana_median_s": float(np.median(osh)),
        "ratio_linear_over_os": ratio,
        "ratio_paired_q25": float(np.quantile(lin / osh, 0.25)),
        "ratio_paired_q75": float(np.quantile(lin / osh, 0.75)),
        "steps_linear": steps["linear"], "steps_omar_shabana": steps["omar-shabana"],
        "thesis_ratio": THESIS_CPU_RATIO.get(n),
    })


@pytest.mark.parametrize("integrator", ("dop853", "generalized-alpha"))
@pytest.mark.parametrize("n", SCALING_N)
def test_cost_per_simulated_second(benchmark, n, integrator):
    benchmark.group = f"pendulum cost per simulated second, {integrator}"
    out = benchmark.pedantic(pendulum, args=("linear", n, integrator),
                             kwargs={"t_end": SCALING_T_END, "output_dt": SCALING_T_END},
                             rounds=rounds(SCALING_ROUNDS, n), warmup_rounds=1)
    benchmark.extra_info.update({"element": "linear", "n_elements": n, "integrator": integrator,
                                 "t_end_s": SCALING_T_END, **_run_info(out)})
    if benchmark.stats:
        benchmark.extra_info["cpu_per_simulated_second_s"] = benchmark.stats.stats.median / SCALING_T_END
