"""`ancf.study.selection` and `ancf.study.cost`: the cheapest run by counted work, so that the choice is
the same on every repeat and every machine (issue 15, item 11; used by the speed-accuracy
tables and `ancf recommend`)."""
import numpy as np
import pandas as pd
import pytest

from ancf.study.cost import FEATURES, WEIGHTS, calibrate, counts, quadrature_points, with_work, work
from ancf.reports.speed_accuracy import cheapest_table
from ancf.study.selection import WORK_TIE, cheapest_first, model_size, tie_limit
from ancf.study.sweep import run_sweep


def _runs(work, cpu=None):
    """Four runs meeting a tolerance: (element, n, error) with the given work."""
    return pd.DataFrame({"element": ["omar-shabana", "linear", "linear", "linear"],
                         "n_elements": [4, 4, 1, 1],
                         "error": [1e-5, 2e-5, 4e-5, 3e-5],
                         "work": work, "cpu_time_s": cpu if cpu is not None else [1.0] * 4})


def test_model_size_counts_global_coordinates():
    assert model_size({"element": "linear", "n_elements": 4}) == 20          # 5 nodes x 4
    assert model_size({"element": "omar-shabana", "n_elements": 4}) == 30    # 5 nodes x 6
    assert model_size({"element": "belt-x", "n_elements": 7}) == 7           # unknown family


def test_ties_go_to_the_smallest_model_then_the_smallest_error():
    # all within the band of the cheapest (1.00): the 1-element runs win, the more
    # accurate of the two first, whatever the order of the work inside the band
    for w in ([1.00, 1.05, 1.08, 1.02], [1.08, 1.00, 1.05, 1.09]):
        assert list(cheapest_first(_runs(w)).index[:2]) == [3, 2]


def test_a_clearly_cheaper_run_wins_whatever_its_size():
    assert cheapest_first(_runs([1.0, 2.0, 2.0, 2.0])).index[0] == 0
    # just outside the band the tie no longer applies; just inside it does
    assert cheapest_first(_runs([1.0, (1 + WORK_TIE) * 1.01, 5.0, 5.0])).index[0] == 0
    assert cheapest_first(_runs([1.0, (1 + WORK_TIE) * 0.99, 5.0, 5.0])).index[0] == 1
    assert tie_limit(2.0) == 2.0 * (1 + WORK_TIE)


def test_measured_times_do_not_decide():
    """Any CPU times, however noisy or reversed, give the same order."""
    rng = np.random.default_rng(0)
    w = [1.0, 3.0, 2.0, 1.5]
    orders = {tuple(cheapest_first(_runs(w, rng.uniform(1e-3, 10.0, 4))).index)
              for _ in range(50)}
    assert orders == {(0, 3, 2, 1)}


def test_uncounted_runs_rank_last():
    order = cheapest_first(_runs([np.nan, 5.0, 3.0, np.nan]))
    assert list(order.index[:2]) == [2, 1] and set(order.index[2:]) == {0, 3}


def test_equal_errors_go_to_the_scene_defaults():
    """Quadrature variants that agree to print precision: the default one is reported."""
    df = pd.DataFrame({"element": ["linear"] * 3, "n_elements": [4] * 3,
                       "integration": ["report-fix", "thesis", "report-selective"],
                       "error": [0.06211, 0.06212, 0.06213], "work": [1.0, 1.05, 1.02]})
    assert cheapest_first(df, defaults={"integration": "thesis"}).index[0] == 1
    assert cheapest_first(df).index[0] == 0      # without defaults: the least work


@pytest.mark.parametrize("spec,points", [("normal=1xe,shear=1xe", 3), ("normal=2x2,shear=1x1", 5),
                                         ("normal=2x2,shear=1x2", 6), ("all=4xe", 12),
                                         ("all=3x2", 6), ("normal=2x2,shear=2x2", 4)])
def test_quadrature_points_per_element(spec, points):
    assert quadrature_points(spec) == points


def test_static_counts_prefer_the_solver_counters_and_fall_back():
    p = {"element": "linear", "integration": "thesis", "n_elements": 4}
    old = counts(p, {"newton_iterations": 7, "negative_tangent_eigenvalues": 0})
    assert old["tangents"] == 8 and old["factorizations"] == 7   # + the stability tangent
    assert old["kernel_points"] == 8 * 8 * 8 * 4 * 3              # d^2 x n x points
    assert old["stability_dofs"] == 20                           # inertia check: linear in size
    new = counts(p, {"newton_iterations": 7, "tangent_evaluations": 5, "factorizations": 2})
    assert (new["tangents"], new["factorizations"], new["stability_dofs"]) == (5, 2, 0)
    assert work(new) < work(old)
    assert counts(p, {"tip_x": 1.0}) is None and np.isnan(work(None))


def test_dynamic_counts_per_integrator():
    p = {"element": "omar-shabana", "integration": "thesis", "n_elements": 2}
    res = {"nfev": 30, "njev": 3, "nlu": 4, "steps": 10}
    rk = counts({**p, "integrator": "radau"}, res)
    ga = counts({**p, "integrator": "generalized-alpha"}, {**res, "njev": 30})
    assert (rk["forces"], rk["tangents"], rk["factorizations"], rk["steps"]) == (30, 3, 4, 10)
    assert (ga["forces"], ga["tangents"]) == (0, 30)             # every force call has its K
    mod = counts({**p, "integrator": "generalized-alpha"}, res)  # modified Newton: K kept
    assert (mod["forces"], mod["tangents"]) == (27, 3)
    assert rk["kernel_points"] == (30 * 12 + 3 * 144) * 2 * 12
    assert rk["kind"] == "dynamic" and ga["kind"] == "alpha"
    assert set(WEIGHTS) == {"static", "dynamic", "alpha"}


def test_calibration_recovers_known_costs():
    rng = np.random.default_rng(1)
    rows = pd.DataFrame({f"count_{k}": rng.integers(1, 1000, 40).astype(float) for k in FEATURES})
    c = dict(zip(FEATURES, rng.uniform(1e-9, 1e-4, len(FEATURES))))
    rows["cpu_time_s"] = sum(c[k] * rows[f"count_{k}"] for k in FEATURES)
    rows["work"] = 1.0
    cal = calibrate(rows)
    assert cal.rows == 40 and cal.scatter_p90 < 1e-9
    assert all(cal.seconds_per[k] == pytest.approx(c[k], rel=1e-6) for k in FEATURES)


GRID = [{"element": ["linear"], "integration": ["thesis", "report-selective", "report-fix"],
         "n_elements": [2, 4, 8, 16], "rtol": [1e-4]},
        {"element": ["omar-shabana"], "integration": ["thesis"], "n_elements": [2, 4, 8]}]


def test_repeated_sweeps_choose_the_same_configurations(workdir):
    """Two fresh sweeps of a small grid (fresh timings): the counted work of every run and
    the cheapest-configuration table agree exactly; only the CPU column may differ."""
    tables, works = [], []
    for k in range(2):
        df = with_work(run_sweep("cantilever", GRID, out=workdir / f"repeat{k}.parquet",
                                 workers=2, progress=False, log=lambda m: None))
        works.append(df.set_index("key")["work"].sort_index())
        tables.append(cheapest_table(df, dynamic=False).drop(columns="timing: CPU ms"))
    pd.testing.assert_series_equal(works[0], works[1])
    pd.testing.assert_frame_equal(tables[0], tables[1])
    assert tables[0]["n_elements"].notna().sum() >= 2
