"""The side-by-side benchmark with Exudyn (benchmarks/peers*.py) without exudyn: the
skip line, the tip-error helper, the table writer on a fake result, and the cable
energy used for Exudyn's energy deviation."""
from __future__ import annotations

import json
import os
import sys

import numpy as np
import pytest

from benchmarks import peers, peers_belt, peers_belt_report, peers_report
from benchmarks.peers_cable import CableEnergy


def _side(cpu, **kw):
    return {"cpu_s": cpu, "converged": True, "tip_x": 1.0, "tip_y": -0.5, **kw}


def fake_result() -> dict:
    static = {"case": "cantilever", "label": "static cantilever", "ratio": 2.0}
    pend = {"case": "pendulum-ga", "label": "pendulum ga", "n": 4, "ratio": 0.25,
            "ours": _side(0.1, steps=1000, newton_iterations=2000, energy_max_deviation_J=0.01,
                          tip_error_m=5e-5),
            "exudyn": _side(0.4, steps=1000, newton_iterations=4975, jacobians=1,
                            energy_max_deviation_J=0.02, tip_error_m=0.07,
                            tip_error_self_m=3e-6)}
    proc = {"case": "process", "n": 64, "label": "whole process", "ratio": 6.0, "ratio_wall": 5.0,
            "ours": {"command": "ancf run", "cpu_s": 0.6, "wall_s": 1.0},
            "exudyn": {"command": "python -m x", "cpu_s": 0.1, "wall_s": 0.2}}
    return {
        "command": "python -m benchmarks.peers", "started": "2026-01-01T00:00:00+00:00",
        "machine": {"cpu_model": "test cpu"},
        "workers": {"ours": {"python": "3.11", "env": {}, "blas": {"kernel": ["K"]}},
                    "exudyn": {"python": "3.11", "exudyn": "1.13.6", "env": {}, "blas": {}}},
        "settings": {"ours": {"cantilever": "a"}, "exudyn": {"cantilever": "b"}, "repeats": {}},
        "references": {"reissner": {"tip_x": 1.0, "tip_y": -0.5},
                       "elastica": {"tip_x": 1.0, "tip_y": -0.4, "ks": 1e9}},
        "cases": [
            {**static, "n": 8, "ratio_paired": [1.5, 2.5],
             "ours": _side(0.02, newton_iterations=58, tip_error_m=4e-3),
             "exudyn": _side(0.01, newton_iterations=40, jacobians=40, rel_tol=1e-8,
                             tip_error_m=1e-6)},
            {**static, "n": 64, "ratio": 0.5,
             "ours": _side(0.05, newton_iterations=58), "exudyn": _side(0.1, jacobians=40)},
            pend, {**pend, "case": "pendulum-dop853", "label": "pendulum dop853"}, proc],
    }


def test_skips_with_one_line_without_exudyn(monkeypatch, tmp_path, capsys):
    monkeypatch.setenv(peers.SKIP_ENV, "1")
    assert peers.main(["--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out.strip().splitlines()
    assert len(out) == 1 and "exudyn is not installed" in out[0]
    assert not list(tmp_path.iterdir())


def test_workers_unset_the_coretype_and_use_one_thread(monkeypatch):
    monkeypatch.setenv("OPENBLAS_CORETYPE", "Haswell")
    monkeypatch.setenv("OPENBLAS_L2_SIZE", "512")
    env = peers.worker_env()
    assert "OPENBLAS_CORETYPE" not in env and "OPENBLAS_L2_SIZE" not in env
    assert env["OPENBLAS_NUM_THREADS"] == "1"


def test_tip_error_of_points_and_trajectories():
    assert peers.tip_error({"tip_x": 3.0, "tip_y": 4.0}, {"tip_x": 0.0, "tip_y": 0.0}) == 5.0
    traj = {"tip_x": [0.0, 1.0], "tip_y": [0.0, 1.0]}
    assert peers.tip_error(traj, {"tip_x": [0.0, 1.0], "tip_y": [0.0, 2.0]}) == 1.0
    assert peers.tip_error(traj, {"tip_x": [0.0], "tip_y": [0.0]}) is None


def test_table_rows_carry_the_ratios():
    md = peers_report.render(fake_result())
    assert "| static cantilever, n = 8 / 64 | 2 / 0.5 |" in md
    assert "| pendulum ga, n = 4 | 0.25 |" in md
    assert "| whole process, n = 64 | 6 |" in md
    assert "| 8 | 20 ms | 10 ms | **2** | 1.5–2.5 | 58 / – / – | 40 / 40 |" in md
    pend = "| 4 | 100 ms | 400 ms | **0.25** | – | 1000 / 2000 / – / – | 1000 / 4975 / 1 |"
    assert pend in md
    assert "| 5.00e-05 | yes | 3.00e-06 | 7.00e-02 |" in md
    assert "1.00e-01 m apart" in md


def test_write_gives_markdown_and_json_and_renders_again(tmp_path):
    md, js = peers_report.write(fake_result(), tmp_path, "peers")
    assert json.loads(js.read_text())["cases"][0]["ratio"] == 2.0
    text = md.read_text()
    assert "`peers.json`" in text
    md.unlink()
    assert peers_report.main([str(js)]) == 0
    assert md.read_text() == text


@pytest.fixture
def cable():
    return CableEnergy(le=0.5, ea=3.0, ei=2.0, rho_a=4.0, g=10.0)


def _chain(n, slope, pos=lambda x: x):
    """(1, n+1, 4) coordinates of a straight chain along the slope vector."""
    x = np.linspace(0.0, 0.5 * n, n + 1)
    r = pos(x)[:, None] * np.asarray(slope)
    return np.concatenate([r, np.tile(slope, (n + 1, 1))], axis=1)[None]


def test_cable_energy_of_rigid_rotation_stretch_and_translation(cable):
    c, s = np.cos(0.7), np.sin(0.7)
    q = _chain(4, (c, s))
    assert cable.total(q, np.zeros_like(q))[0] == pytest.approx(4.0 * 10.0 * s * 2.0**2 / 2)
    stretched = _chain(4, (1.2, 0.0), pos=lambda x: x)
    assert cable.total(stretched, np.zeros_like(q))[0] == pytest.approx(0.5 * 3.0 * 0.2**2 * 2.0)
    v = np.tile([0.0, 3.0, 0.0, 0.0], (1, 5, 1))
    flat = _chain(4, (1.0, 0.0))
    assert cable.total(flat, v)[0] == pytest.approx(0.5 * 4.0 * 2.0 * 9.0)


def fake_belt_result(ours: dict) -> dict:
    exu = {"cpu_s": 2.0, "total_cpu_s": 2.5, "static_wall_s": 0.01, "steps": 4000,
           "newton_iterations": 40000, "jacobians": 5000, "discontinuous_iterations": 7000,
           "omega_driver": 12.0, "omega_driven": 12.2, "omega_driven_mean_last": 11.96,
           "step": 2.5e-4}
    table = {"R": 0.1, "x_driver": -0.2, "x_driven": 0.2, "rho": 1000.0, "side": 0.01,
             "E": 1e8, "length": 1.2, "k_p": 1e7, "c_p": 10.0, "mu": 1.0, "nu_s": 1e5,
             "inertia": 0.1, "alpha1": 1.0, "alpha2": 0.01}
    return {"command": "python -m benchmarks.peers_belt", "started": "2026-01-01",
            "machine": {"cpu_model": "test cpu"}, "workers": {},
            "settings": {"ours": "a", "exudyn": "b", "repeats": 3, "t_end": 1.0,
                         "warmup_t_end": 0.01, "model": {"table": table, "wrapped_length": 1.3,
                                                         "segments": 4, "stick_spring": 0.2}},
            "cases": [{"n": 20, "ours": ours, "exudyn": exu,
                       "exudyn_half_step": {**exu, "step": 1.25e-4, "omega_driven": 11.6},
                       "ratio": peers._ratio(ours.get("cpu_s"), exu["total_cpu_s"]),
                       "ratio_dynamic": peers._ratio(ours.get("cpu_s"), exu["cpu_s"]),
                       "ratio_paired": []}]}


def test_belt_report_shows_pending_ours_and_exudyns_numbers():
    md = peers_belt_report.render(fake_belt_result({"pending": peers_belt.PENDING}))
    assert f"| 20 | {peers_belt.PENDING} | 2.5 s | 2 s |" in md
    assert "| 12.2000 / 11.9600 / 1.0167 | 11.6000 / 11.9600 / 0.9667 |" in md


def test_belt_report_ratio_of_ours_to_exudyns_total():
    md = peers_belt_report.render(fake_belt_result({"cpu_s": 1.0, "omega_driven": 12.0,
                                                    "omega_driver": 12.0}))
    assert "| 20 | 1 s | 2.5 s | 2 s | 10 ms | **0.4** | 0.5 |" in md


def test_exudyn_belt_path_is_closed_with_unit_tangents():
    pytest.importorskip("exudyn")
    from benchmarks import peers_belt_exudyn as pb
    s = np.linspace(0.0, pb.wrapped_length(), 97)
    pts = [pb.belt_path(x) for x in s]
    assert np.allclose(pts[0][0], pts[-1][0]) and np.allclose(pts[0][1], pts[-1][1])
    assert np.allclose([np.linalg.norm(t) for _, t in pts], 1.0)
    steps = np.linalg.norm(np.diff([p for p, _ in pts], axis=0), axis=1)
    assert steps.sum() == pytest.approx(pb.wrapped_length(), rel=1e-3)


@pytest.fixture(scope="module")
def short_belt():
    pytest.importorskip("exudyn")
    from benchmarks import peers_belt_exudyn as pb
    return pb, pb.exudyn_belt(20, t_end=pb.RAMP[0] + 0.1)


def test_exudyn_belt_driven_pulley_turns_with_the_driver(short_belt):
    pb, res = short_belt
    assert res["static_converged"] and res["converged"]
    assert res["omega_driver"] == pytest.approx(pb.driver_omega(res["t_end"]), rel=1e-6)
    assert 0.0 < res["omega_driven"] < 2 * res["omega_driver"]     # same sense, bounded


@pytest.mark.xfail(strict=True, reason="known: after the static pre-tension Exudyn's belt "
                   "creeps and turns the driven pulley (~0.3 rad/s before t = 0.05 s) "
                   "before the drive starts; unresolved")
def test_exudyn_belt_rests_until_the_drive_starts(short_belt):
    pb, res = short_belt
    t, w = np.array(res["t_series"]), np.array(res["omega_driven_series"])
    assert np.max(np.abs(w[t < pb.RAMP[0]])) < 1e-3 * pb.RAMP[2]


def test_both_sides_run_on_one_cpu():
    """Both workers and the whole-process runs are pinned to the same CPU (peers.CPU), so
    neither side's samples depend on which core it lands on; this process stays free."""
    w = peers.Worker("ours", peers.worker_env())
    try:
        assert os.sched_getaffinity(w.proc.pid) == {peers.CPU}
    finally:
        w.close()
    probe = f"import os, sys; sys.exit(os.sched_getaffinity(0) != {{{peers.CPU}}})"
    assert peers.run_process([sys.executable, "-c", probe], os.environ.copy())["exit_code"] == 0
    assert os.sched_getaffinity(0) != {peers.CPU} or len(os.sched_getaffinity(0)) == 1
