"""`ancf.study.selection` and `ancf.study.cost`: the cheapest run by counted work, so that the choice is
the same on every repeat and every machine (issue 15, item 11; used by the speed-accuracy
tables and `ancf recommend`)."""
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from ancf.study.cost import FEATURES, WEIGHTS, calibrate, counts, quadrature_points, with_work, work
from ancf.reports.speed_accuracy import cheapest_table
from ancf.reports.speed_accuracy import TOLERANCES, _knob_defaults, slug
from ancf.study.references import FREQUENCY_SPECS, spec, specs
from ancf.study.selection import (WORK_SCATTER, WORK_TIE, cheapest_first, model_size,
                                  nominal_work, rank, tie_group, tie_keys)
from ancf.study.sweep import run_sweep

DATA = Path(__file__).resolve().parents[2] / "reports" / "data"


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


def test_ties_go_to_the_least_nominal_work_then_the_smallest_model():
    # all chained (gaps below 1 + WORK_TIE): the 1-element runs (least nominal work) win,
    # the more accurate of the two first, whatever the order of the work inside the group
    for w in ([1.00, 1.05, 1.08, 1.02], [1.08, 1.00, 1.05, 1.09], [1.0, 1.3, 1.69, 2.19]):
        assert list(cheapest_first(_runs(w)).index[:2]) == [3, 2]
    df = _runs([1.0] * 4)
    assert nominal_work(df.loc[2]) < nominal_work(df.loc[1]) < nominal_work(df.loc[0])


def test_a_gap_separates_the_tie_group():
    assert cheapest_first(_runs([1.0, 2.0, 2.0, 2.0])).index[0] == 0
    # a gap just above 1 + WORK_TIE ends the group; just below it chains
    assert cheapest_first(_runs([1.0, (1 + WORK_TIE) * 1.01, 5.0, 5.0])).index[0] == 0
    assert cheapest_first(_runs([1.0, (1 + WORK_TIE) * 0.99, 5.0, 5.0])).index[0] == 1
    assert list(tie_group([3.0, 1.0, 1.3, np.nan, 1.69])) == [False, True, True, False, True]
    # runs of equal work stay in one group whatever the scatter between machines
    assert (1 + WORK_SCATTER) / (1 - WORK_SCATTER) < 1 + WORK_TIE


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
    """Solver tolerances of one model that agree to print precision: the default one is
    reported (equal nominal work and size); without defaults, the first of the rows."""
    df = pd.DataFrame({"element": ["linear"] * 3, "n_elements": [4] * 3,
                       "integration": ["thesis"] * 3, "rtol": [1e-4, 1e-8, 1e-6],
                       "error": [0.06211, 0.06212, 0.06213], "work": [1.0, 1.05, 1.02]})
    assert cheapest_first(df, defaults={"rtol": 1e-8}).index[0] == 1
    assert cheapest_first(df).index[0] == 0
    # quadrature variants differ in nominal work: the fewer points win before the defaults
    q = df.assign(integration=["exact", "thesis", "report-selective"], rtol=1e-8)
    assert cheapest_first(q, defaults={"integration": "exact"}).index[0] == 1


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


@pytest.mark.parametrize("element", ["ancf3423", "ancf3443", "ancf3833"])
def test_chrono_shells_count_their_own_mesh_and_points(element):
    """A Chrono shell on plate-square is counted on its own coordinates, the model's nodes
    (:class:`ancf.models.chrono_shell.Plate`) and its own quadrature, not as the
    36-coordinate plate (``ng`` is ignored by these elements)."""
    from ancf.elements.registry import ELEMENTS
    from ancf.models.chrono_shell import Plate
    plate = Plate(element[-4:], 3, 3, 1.0, 1.0, 0.01, 2e11, 0.3)
    cls = ELEMENTS[element].cls
    p = {"element": element, "n_elements": 3, "ng": 4}
    c = counts(p, {"tangent_evaluations": 2, "factorizations": 2})
    assert c["factor_dofs"] == 2 * plate.ndof
    assert c["kernel_points"] == 2 * cls.module.NDOF ** 2 * 9 * cls.points_per_element()
    assert c == counts({**p, "ng": 2}, {"tangent_evaluations": 2, "factorizations": 2})


def test_chrono_beams_count_their_exact_rule():
    """Chrono's beams (exact rules, 50 points each) cost more kernel work per element than
    Kerkkanen's 3D linear beam on the same mesh, and the 3-node beam's mesh has 2n + 1
    nodes of 9 coordinates."""
    r = {"tangent_evaluations": 1, "factorizations": 1}
    chrono = counts({"element": "ancf3333", "n_elements": 4}, r)
    assert chrono["factor_dofs"] == 9 * 9
    assert chrono["kernel_points"] > counts({"element": "linear3d", "n_elements": 4,
                                             "integration": "thesis"}, r)["kernel_points"]


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


@pytest.mark.slow
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


def _committed_levels():
    """(name, rows, error column, defaults) of every committed speed-accuracy sweep the
    reports tabulate (the scenes' results and the natural frequencies)."""
    found = []
    scenes = [(n, s) for n, s in specs().items()] + [(n, spec(n, "frequency"))
                                                     for n in FREQUENCY_SPECS]
    for name, s in scenes:
        path = DATA / f"speed_accuracy_{slug(name, s.quantity)}.csv"
        if path.exists():
            defaults = _knob_defaults(name, s)
            df = pd.read_csv(path)
            df = df.assign(**{k: v for k, v in defaults.items() if k not in df})
            for err in ("error", "error_self"):
                if err in df:
                    found.append((f"{name} {s.quantity} {err}", df, err, defaults, path.name))
    return found


def perturbed_picks(pick, draws: int = 200, seed: int = 0) -> dict:
    """Per (sweep, error column, tolerance) of the committed data: the set of picks of
    ``pick(rows, err, defaults, work)`` over ``draws`` draws of every run's work scaled
    independently by a uniform factor in [1 - WORK_SCATTER, 1 + WORK_SCATTER], beside the
    pick of the unperturbed work."""
    rng = np.random.default_rng(seed)
    out = {}
    for label, df, err, defaults, _ in _committed_levels():
        ok = df[(df["status"] == "ok") & np.isfinite(df[err].astype(float))]
        for tol in TOLERANCES:
            m = ok[ok[err] <= tol]
            if not len(m):
                continue
            state = pick(m, err, defaults, None)
            w = m["work"].to_numpy(float)
            out[f"{label} <= {tol:g}"] = (pick(m, err, defaults, w, state), {
                pick(m, err, defaults, w * rng.uniform(1 - WORK_SCATTER, 1 + WORK_SCATTER,
                                                       len(w)), state)
                for _ in range(draws)})
    return out


def _pick(rows, err, defaults, work, keys=None):
    """The rule's pick with ``work`` in place of the rows' (``work`` None: the tie keys,
    computed once per level)."""
    if work is None:
        return tie_keys(rows, err, defaults)
    return rank(keys, work)[0]


@pytest.mark.slow
def test_picks_do_not_move_with_the_scatter_of_counted_work():
    """Issue 23: on every committed sweep, at every error level of the reports and against
    each reference, the pick is the same when each run's counted work moves by up to
    +-WORK_SCATTER (200 seeded draws): the machine-to-machine scatter of contact runs."""
    files = {p.name for p in DATA.glob("speed_accuracy_*.csv")} - {"speed_accuracy_calibration.csv"}
    assert files == {f for *_, f in _committed_levels()}      # every committed sweep is checked
    picks = perturbed_picks(_pick)
    assert len(picks) >= 40
    moved = {k: (base, alts) for k, (base, alts) in picks.items() if alts != {base}}
    assert moved == {}
