"""The side-by-side benchmark with Exudyn (benchmarks/peers*.py) without exudyn: the
skip line, the tip-error helper, the table writer on a fake result, and the cable
energy used for Exudyn's energy deviation."""
from __future__ import annotations

import json

import numpy as np
import pytest

from benchmarks import peers, peers_report
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
