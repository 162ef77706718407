"""The benchmark summary renders every section from a pytest-benchmark JSON
(synthetic numbers here: the real run is `make bench`)."""
from benchmarks import summarize


def _bench(name, params, median, extra):
    stats = {"mean": median, "stddev": 0.0, "median": median, "rounds": 3}
    return {"name": f"{name}[x]", "params": params, "stats": stats, "extra_info": extra}


def test_summary_has_table_2_5_and_scaling(tmp_path):
    ratio = {"n_elements": 4, "integrator": "dop853", "samples": 3, "linear_median_s": 1.0,
             "omar_shabana_median_s": 1.5, "ratio_linear_over_os": 2 / 3, "ratio_paired_q25": 0.6,
             "ratio_paired_q75": 0.7, "steps_linear": 10, "steps_omar_shabana": 11,
             "thesis_ratio": 0.65}
    benches = [_bench("test_pendulum_ratio", {"n": 4, "integrator": "dop853"}, 2.5, ratio)]
    for n, t in ((8, 0.1), (16, 0.2), (32, 0.4)):
        benches.append(_bench("test_cost_per_simulated_second", {"n": n, "integrator": "dop853"}, t,
                              {"integrator": "dop853", "n_elements": n, "t_end_s": 0.05, "steps": 9}))
    text = summarize.render({"benchmarks": benches, "machine_info": {}}, "b.json", tmp_path)
    assert "| 4 | dop853 | 1 s | 1.5 s | **0.667** |" in text and "0.65" in text
    assert "dop853 ∝ n^1.00" in text and "| 32 | 8 s | 9 |" in text
    assert (tmp_path / "cost_per_simulated_second.png").is_file()


def test_summary_has_belt_drives(tmp_path):
    split = {"elastic_s": 2.0, "contact_s": 3.0, "linear_algebra_s": 1.0, "other_s": 4.0}
    counts = {"steps": 7, "newton_iterations": 30, "nlu": 9, "rejected_steps": 1}
    benches = [
        _bench("test_belt_drive", {"n": 20}, 0.6, {"integration_cpu_s": 10.0, **split, **counts,
                                                     "omega_ratio_steady": 0.999}),
        _bench("test_belt3d_drive", {"n": 20, "points": 81}, 12.0,
               {"integration_cpu_s": 10.0, "cpu_per_simulated_s": 10.0 / 1.2, **split, **counts,
                "slip_driven": 0.1, "membrane_tight_N": 70.0, "membrane_slack_N": None})]
    text = summarize.render({"benchmarks": benches, "machine_info": {}}, "b.json", tmp_path)
    assert "## Belt drive (2D), 1 s" in text and "## Belt drive (3D plates), Model 2, 1.2 s" in text
    assert "| n=20 | 600 ms | 10 s | – | 20 / 30 / 10 / 40 | 7 | 30 | 9 | 1 | 0.999 |" in text
    assert "| n=20, points=81 | 12 s | 10 s | 8.33 s | 20 / 30 / 10 / 40 | 7 | 30 | 9 | 1 | 0.1 | 70 | – |" in text
