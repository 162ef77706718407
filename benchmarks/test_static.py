"""Static-beam benchmarks: the full Model 1 cantilever solve, one Newton iteration
kernel, and the interleaved linear / Omar-Shabana Newton-iteration time ratio.

No wall-clock thresholds are asserted: only that the solves converge and the
kernel returns a finite update.  Timings go to the benchmark JSON; see
``benchmarks/summarize.py`` for the Markdown report.
"""
from __future__ import annotations

import time

import numpy as np
import pytest

from ancf.scenes import SCENES
from benchmarks.kernels import (ELEMENTS, KERNEL_ROUNDS, N_ELEMENTS, RATIO_ROUNDS, SOLVE_ROUNDS,
                                THESIS_RATIO, kernel_setup, model1, newton_kernel, rounds)

element_param = pytest.mark.parametrize("element", ELEMENTS)
n_param = pytest.mark.parametrize("n", N_ELEMENTS)


@n_param
@element_param
def test_cantilever_solve(benchmark, bench_log, element, n):
    """(a) Full cantilever Model 1 static solve (adaptive load steps, Newton, and the
    scene's tangent-stability check) through SCENES['cantilever'].execute."""
    benchmark.group = "cantilever Model 1 static solve"
    scene = SCENES["cantilever"]
    out, res = benchmark.pedantic(scene.execute, args=(model1(element, n),),
                                  rounds=rounds(SOLVE_ROUNDS, n), warmup_rounds=1)
    assert out["converged"], out["message"]
    r = out["results"]
    mesh = res.extra["mesh"]
    benchmark.extra_info.update({
        "element": element, "n_elements": n, "n_dofs": mesh.n_dofs,
        "newton_iterations": r["newton_iterations"], "load_steps": r["load_steps_taken"],
        "tip_y_m": r["tip_y"], "scene_cpu_time_s": out["cpu_time_s"],
        # the scene's dense eigvalsh stability check (<= 3000 free DOFs) is part of the timing
        "includes_stability_check": r["negative_tangent_eigenvalues"] is not None,
    })
    if benchmark.stats:
        benchmark.extra_info["solve_time_per_iteration_s"] = (
            benchmark.stats.stats.mean / r["newton_iterations"])
    bench_log.append(("solve", element, n, benchmark))


@n_param
@element_param
def test_newton_kernel(benchmark, bench_log, element, n):
    """(b) One Newton iteration at a perturbed configuration: assembly.gradient_tangent(q)
    + reduction to the clamped free coordinates + sparse LU factorisation and solve."""
    benchmark.group = "Newton iteration kernel"
    s = kernel_setup(element, n)
    dz = benchmark.pedantic(newton_kernel, args=(s,), rounds=rounds(KERNEL_ROUNDS, n),
                            warmup_rounds=3)
    assert dz.shape == (s.n_free,) and np.all(np.isfinite(dz))
    benchmark.extra_info.update({
        "element": element, "n_elements": n, "n_dofs": s.n_dofs, "n_free": s.n_free,
        "newton_iterations": 1,
    })
    if benchmark.stats:
        st = benchmark.stats.stats
        benchmark.extra_info["kernel_time_per_element_s"] = st.mean / n
        benchmark.extra_info["kernel_median_per_element_s"] = st.median / n
    bench_log.append(("kernel", element, n, benchmark))


@n_param
def test_newton_ratio(benchmark, bench_log, n):
    """Side-by-side ratio: the two elements' Newton-iteration kernels timed alternately
    (order swapped every round) so machine-load drift hits both; extra_info holds the
    median times and the ratio linear / Omar-Shabana (thesis: ~0.5).  The benchmark's
    own time is one (linear + Omar-Shabana) pair."""
    benchmark.group = "Newton iteration ratio linear/Omar-Shabana"
    setups = {el: kernel_setup(el, n) for el in ELEMENTS}
    times = {el: [] for el in ELEMENTS}
    state = {"round": 0}

    def pair():
        order = ELEMENTS if state["round"] % 2 == 0 else ELEMENTS[::-1]
        state["round"] += 1
        for el in order:
            t0 = time.perf_counter()
            newton_kernel(setups[el])
            times[el].append(time.perf_counter() - t0)

    for _ in range(5):  # warm-up, discarded
        pair()
    for v in times.values():
        v.clear()
    benchmark.pedantic(pair, rounds=rounds(RATIO_ROUNDS, n))

    lin, osh = (np.asarray(times[el]) for el in ELEMENTS)
    assert lin.size == osh.size >= 1
    ratio = float(np.median(lin) / np.median(osh))
    benchmark.extra_info.update({
        "n_elements": n,
        "n_dofs_linear": setups["linear"].n_dofs, "n_dofs_omar_shabana": setups["omar-shabana"].n_dofs,
        "samples": int(lin.size),
        "linear_median_s": float(np.median(lin)), "omar_shabana_median_s": float(np.median(osh)),
        "ratio_linear_over_os": ratio,
        "ratio_paired_median": float(np.median(lin / osh)),
        "ratio_paired_q25": float(np.quantile(lin / osh, 0.25)),
        "ratio_paired_q75": float(np.quantile(lin / osh, 0.75)),
        "thesis_ratio": THESIS_RATIO,
    })
    assert np.isfinite(ratio) and ratio > 0
    bench_log.append(("ratio", None, n, benchmark))
