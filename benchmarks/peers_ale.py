"""THREAD's belt drive in the axially moving description: our steady solve against
Exudyn's ALE belt marched to THREAD's steady window, side by side in one run.

    python -m benchmarks.peers_ale [--repeats 3] [--file examples/thread_creep_rate.toml]
                                   [--step 2.5e-5] [--out reports/benchmarks]

Ours: ``ancf steady belt-drive --file FILE`` through its Python API
(:func:`ancf.scenes.belt_steady.run`): the steady state at the laws' values at t_end, one
Newton solve, no march.  Its CPU ``cpu_s`` is the state alone (``max_loads=False``: what
Exudyn's run answers), ``cpu_cli_s`` with the driven pulleys' largest loads as the CLI
computes them; both ``time.process_time`` in the child after one untimed warm-up solve
in the same process (numba compilation and cache loads excluded).
Exudyn: :mod:`benchmarks.peers_ale_exudyn`, its CPU ``cpu_to_window_s`` from before the
build to the march's arrival at the window's start (2.0 s), the quantities the window's
means (2.0-2.45 s).

Measurement as in :mod:`benchmarks.peers_thread`: one BLAS thread, OPENBLAS_CORETYPE /
OPENBLAS_L2_SIZE unset, every run a fresh process, ``--repeats`` rounds alternating ours,
Exudyn; medians compared.  ``ratio`` = ours cpu_s / Exudyn cpu_to_window_s (medians).

Writes ``peers_ale.json`` (keys ``schema``, ``started``, ``command``, ``machine``,
``settings``, ``ours`` and ``exudyn`` (medians, samples, the last run's quantities),
``ratio``, ``ratio_cli``, ``agreement``: per quantity ours, Exudyn and (ours - Exudyn) /
Exudyn) and ``peers_ale.md`` beside it.
"""
from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

from benchmarks import peers
from benchmarks import peers_ale_exudyn as pae

FILE = pae.FILE
#: compared quantities: (key, label, unit)
QUANTITIES = (("tension_tight_N", "tight span force", "N"),
              ("tension_slack_N", "slack span force", "N"),
              ("omega_driven_mean", "driven pulley speed", "rad/s"),
              ("driver_torque_mean_Nm", "driver torque", "N m"))


def ours_child(path: str) -> dict:
    """One process's run of our steady solve (warm-up, then timed without and with the
    largest loads); the quantities in :mod:`benchmarks.peers_ale_exudyn`'s names."""
    from ancf.scenes.belt_steady import SCENE, run
    p = SCENE.resolve({"file": path})
    run(p, max_loads=False)
    c0 = time.process_time()
    res = run(p, max_loads=False)
    c1 = time.process_time()
    run(p, max_loads=True)
    c2 = time.process_time()
    r = res.results
    driver, driven = r["pulleys"][0], r["pulleys"][1]
    tight = next(s for s in r["spans"] if s["to"] == driver["name"])
    slack = next(s for s in r["spans"] if s["from"] == driver["name"])
    return {"converged": bool(res.converged), "cpu_s": c1 - c0, "cpu_cli_s": c2 - c1,
            "omega_driven_mean": driven["omega"], "driver_torque_mean_Nm": -driver["torque_Nm"],
            "tension_tight_N": tight["tension_mean_N"], "tension_slack_N": slack["tension_mean_N"],
            "transport_speed_m_s": r["transport_speed_m_s"],
            **{k: r[k] for k in ("newton_iterations", "continuation_steps", "total_dofs")}}


def _child(cmd: list, env: dict) -> dict:
    proc = subprocess.run([sys.executable, "-m", *cmd], capture_output=True, text=True, env=env,
                          cwd=peers.ROOT)
    if proc.returncode != 0:
        return {"error": proc.stderr.strip().splitlines()[-3:], "exit": proc.returncode}
    return json.loads(proc.stdout[proc.stdout.index("{"):])


def _median(samples: list):
    xs = [x for x in samples if x is not None]
    return statistics.median(xs) if xs else None


def relative(ours, exudyn):
    """(ours - exudyn) / |exudyn|, None where either is missing or exudyn is zero."""
    if ours is None or exudyn is None or exudyn == 0:
        return None
    return (ours - exudyn) / abs(exudyn)


def summary(runs: list, keys: tuple) -> dict:
    """The last run's answer with the medians and samples of the CPU ``keys``."""
    out = dict(runs[-1])
    for k in keys:
        samples = [r.get(k) for r in runs]
        out[k], out[k.replace("_s", "_samples_s", 1)] = _median(samples), samples
    return out


def agreement(ours: dict, exudyn: dict) -> dict:
    """Per quantity of QUANTITIES: ours, Exudyn's and their relative difference."""
    return {k: {"ours": ours.get(k), "exudyn": exudyn.get(k),
                "relative": relative(ours.get(k), exudyn.get(k))} for k, _, _ in QUANTITIES}


def race(path: Path, repeats: int, step: float, env: dict) -> dict:
    """``repeats`` rounds, ours then Exudyn, each run in a fresh process."""
    ours, exudyn = [], []
    for _ in range(repeats):
        ours.append(_child(["benchmarks.peers_ale", "--ours-child", str(path)], env))
        exudyn.append(_child(["benchmarks.peers_ale_exudyn", "--step", f"{step:g}"], env))
    o = summary(ours, ("cpu_s", "cpu_cli_s"))
    e = summary(exudyn, ("cpu_to_window_s", "cpu_s"))
    return {"ours": o, "exudyn": e,
            "ratio": peers._ratio(o.get("cpu_s"), e.get("cpu_to_window_s")),
            "ratio_cli": peers._ratio(o.get("cpu_cli_s"), e.get("cpu_to_window_s")),
            "agreement": agreement(o, e)}


def _fmt(v, f="{:.4g}") -> str:
    return "–" if v is None else f.format(v)


def markdown(res: dict) -> str:
    """The report of :func:`main`'s result."""
    o, e = res["ours"], res["exudyn"]
    lines = ["# THREAD belt drive, steady: our steady solve against Exudyn's ALE belt", "",
             f"Generated by `{res['command']}` on {res['started']}; raw numbers in "
             "`peers_ale.json`; do not edit by hand.  Every run a fresh process, one BLAS "
             f"thread, {res['repeats']} rounds alternating ours and Exudyn, medians.  Timing "
             "varies run to run.", "",
             "| CPU, s | ours | Exudyn |", "|---|---|---|",
             f"| to the steady state (ours: state only; Exudyn: march to 2.0 s) | "
             f"{_fmt(o.get('cpu_s'))} | {_fmt(e.get('cpu_to_window_s'))} |",
             f"| ours with the largest loads (the CLI) / Exudyn to 2.45 s | "
             f"{_fmt(o.get('cpu_cli_s'))} | {_fmt(e.get('cpu_s'))} |", "",
             f"**CPU ours / Exudyn to the window: {_fmt(res['ratio'], '{:.4f}')}** "
             f"(with the largest loads: {_fmt(res['ratio_cli'], '{:.4f}')}).", "",
             "| quantity (Exudyn: mean over 2.0-2.45 s) | ours | Exudyn | (ours - Exudyn) / "
             "Exudyn |", "|---|---|---|---|"]
    for k, label, unit in QUANTITIES:
        a = res["agreement"][k]
        rel = None if a["relative"] is None else 100 * a["relative"]
        lines.append(f"| {label}, {unit} | {_fmt(a['ours'], '{:.5g}')} | "
                     f"{_fmt(a['exudyn'], '{:.5g}')} | {_fmt(rel, '{:+.3f}')} % |")
    lines += ["", f"Exudyn's driven speed drifts {_fmt(e.get('omega_driven_drift'), '{:.2g}')} "
              "rad/s over the window.", "", "## Settings", ""]
    lines += [f"- **{k}**: {v}" for k, v in res["settings"].items() if k != "file_text"]
    lines += ["", "## Machine", ""] + [f"- **{k}**: {v}" for k, v in res["machine"].items()]
    return "\n".join(lines) + "\n"


def _relative(path: Path) -> str:
    """The path relative to the checkout where it lies in it (no machine paths in reports)."""
    path = path.resolve()
    return str(path.relative_to(peers.ROOT)) if path.is_relative_to(peers.ROOT) else path.name


def _settings(path: Path, step: float) -> dict:
    return {"ours": f"ancf steady belt-drive --file {path.name} (Python API "
                    "ancf.scenes.belt_steady.run): Dufva belt, creep-rate friction, Newton in "
                    "the ALE description at the laws' values at t_end",
            "exudyn": f"benchmarks/peers_ale_exudyn.py: {pae.N_ELEMENTS} ALECable2D elements, "
                      f"{pae.SEGMENTS} contact segments, friction velocity penalty nu_s l_s "
                      f"without bristle stiffness, TrapezoidalIndex2 h = {step:g} s, modified "
                      "Newton, EigenSparse, one thread, static equilibrium first",
            "file": _relative(path), "file_text": path.read_text(),
            "worker_env": peers.THREAD_ENV, "unset": peers.UNSET_ENV}


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["--ours-child"]:
        print(json.dumps(ours_child(argv[1])))
        return 0
    ap = argparse.ArgumentParser(prog="python -m benchmarks.peers_ale",
                                 description=__doc__.split("\n")[0])
    ap.add_argument("--repeats", type=int, default=3, help="rounds of the race")
    ap.add_argument("--file", type=Path, default=FILE, help="our drive file")
    ap.add_argument("--step", type=float, default=pae.STEP, help="Exudyn's time step, s")
    ap.add_argument("--out", type=Path, default=peers.DEFAULT_OUT, help="output folder")
    args = ap.parse_args(argv)
    if args.repeats < 1:
        raise ValueError(f"--repeats = {args.repeats}; allowed: an integer >= 1")
    if peers.exudyn_missing():
        print("peers_ale: exudyn is not installed (pip install -e .[peers]); skipped")
        return 0
    res = peers.record("peers_ale", argv, _settings(args.file, args.step),
                       repeats=args.repeats)
    res |= race(args.file, args.repeats, args.step, peers.worker_env())
    peers.write(args.out, "peers_ale", res, markdown(res))
    print(f"peers_ale: ratio {res['ratio']}; wrote {args.out}/peers_ale.json/.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
