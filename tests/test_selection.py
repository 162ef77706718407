"""`ancf.selection`: the cheapest run, robust to timing noise (used by the speed-accuracy
tables and `ancf recommend`)."""
import numpy as np
import pandas as pd

from ancf.selection import COST_TIE, COST_TIE_ABS_S, cheapest_first, model_size, tie_limit


def _runs(costs):
    """Four runs meeting a tolerance: (element, n, error) with the given CPU times."""
    return pd.DataFrame({"element": ["omar-shabana", "linear", "linear", "linear"],
                         "n_elements": [4, 4, 1, 1],
                         "error": [1e-5, 2e-5, 4e-5, 3e-5],
                         "cpu_time_s": costs})


def test_model_size_counts_global_coordinates():
    assert model_size({"element": "linear", "n_elements": 4}) == 20          # 5 nodes x 4
    assert model_size({"element": "omar-shabana", "n_elements": 4}) == 30    # 5 nodes x 6
    assert model_size({"element": "belt-x", "n_elements": 7}) == 7           # unknown family


def test_ties_go_to_the_smallest_model_then_the_smallest_error():
    # all within the band of the cheapest (1.00): the 1-element runs win, the more
    # accurate of the two first, whatever the order of the times inside the band
    for costs in ([1.00, 1.05, 1.20, 1.10], [1.20, 1.00, 1.05, 1.15]):
        order = cheapest_first(_runs(costs))
        assert list(order.index[:2]) == [3, 2]


def test_a_clearly_cheaper_run_wins_whatever_its_size():
    costs = [1.0, 2.0, 2.0, 2.0]                     # the big model is 2x cheaper
    assert cheapest_first(_runs(costs)).index[0] == 0
    # just outside the band the tie no longer applies; just inside it does
    out = [1.0, 1.0 * (1 + COST_TIE) * 1.01, 5.0, 5.0]
    inside = [1.0, 1.0 * (1 + COST_TIE) * 0.99, 5.0, 5.0]
    assert cheapest_first(_runs(out)).index[0] == 0
    assert cheapest_first(_runs(inside)).index[0] == 1


def test_the_pick_is_stable_under_timing_noise():
    rng = np.random.default_rng(0)
    base = np.array([1.0, 1.0, 1.0, 1.0])
    picks = {cheapest_first(_runs(base * rng.uniform(0.9, 1.1, 4))).index[0] for _ in range(50)}
    assert picks == {3}


def test_equal_errors_go_to_the_scene_defaults():
    """Quadrature variants that agree to print precision: the default one is reported."""
    df = pd.DataFrame({"element": ["linear"] * 3, "n_elements": [4] * 3,
                       "integration": ["report-fix", "thesis", "report-selective"],
                       "error": [0.06211, 0.06212, 0.06213], "cpu_time_s": [1.0, 1.1, 1.05]})
    assert cheapest_first(df, defaults={"integration": "thesis"}).index[0] == 1
    assert cheapest_first(df).index[0] == 0      # without defaults: the least time


def test_millisecond_runs_tie_within_the_absolute_band():
    """3-5 ms solves scatter by more than 25 %: the absolute band keeps them tied, and it
    does not matter for runs of a second or more."""
    assert tie_limit(3e-3) == 3e-3 + COST_TIE_ABS_S
    assert tie_limit(1.0) == 1.0 + COST_TIE
    df = pd.DataFrame({"element": ["linear"] * 2, "n_elements": [4] * 2,
                       "integration": ["report-selective", "thesis"],
                       "error": [0.06213, 0.06213], "cpu_time_s": [3.4e-3, 4.5e-3]})
    assert cheapest_first(df, defaults={"integration": "thesis"}).index[0] == 1
    beyond = df.assign(cpu_time_s=[3.4e-3, 3.4e-3 + 1.01 * COST_TIE_ABS_S])
    assert cheapest_first(beyond, defaults={"integration": "thesis"}).index[0] == 0
