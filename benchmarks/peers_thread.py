"""The THREAD belt drive side by side with Exudyn on Exudyn's own example.

    python -m benchmarks.peers_thread [--t-end 2.45] [--file drive.toml] [--own]
                                      [--set k=v ...] [--out reports/benchmarks] [--stem NAME]

Exudyn: :mod:`benchmarks.peers_thread_exudyn` (its ``beltDriveReevingSystem.py`` as
shipped: 240 elements, 2 contact segments, step 1e-4 s, TrapezoidalIndex2, 2.45 s).
Ours: ``ancf run belt-drive --file examples/thread_benchmark.toml`` at the same element
count and step (``--set belt.n_elements=240 --set run.dt=1e-4``; the file's friction,
damping and generalised-alpha otherwise) and the same end time, with the quadrature
:data:`QUADRATURE` (3 Gauss points per element for the elastic forces and 4 for the
contact, against the file's 5 and 5: Exudyn's example integrates its cables with
``useReducedOrderIntegration=2`` and its contact over 2 segments per element; at 240
elements the driven speed agrees with the file's quadrature to 5 digits and the span
forces within 0.1 %) and the solver settings :data:`SOLVER` (``run.newton_accept=evaluated``,
``run.damping_jacobian=rate``, ``run.refresh_ratio=0.2``, ``run.refresh=once``,
``run.give_up=3``: the same equations, a cheaper Newton iteration).

Measurement as in :mod:`benchmarks.peers`: one BLAS thread, OPENBLAS_CORETYPE /
OPENBLAS_L2_SIZE unset, each side in a fresh process, one run each, ours first then
Exudyn's (a full run is minutes long); ours is the scene's ``cpu_time_s`` (build,
settling and march; numba compilation excluded, reported as ``compile_cpu_s``),
Exudyn's ``time.process_time`` around build, static equilibrium and dynamic solve.
``--t-end`` shortens both runs (the means are then over the last half of the run).
``--set`` overrides ours further, a key of :data:`OURS` included (the file's own
quadrature: ``--set belt.elastic_points=5 --set contact.gauss_points=5 --stem
peers_thread_file``).  ``--own`` runs ours at Exudyn's element count and step alone
(:data:`OWN`), with the file's own quadrature and every Newton setting at its drive-file
default (``--own --stem peers_thread_file_defaults``).

Writes ``peers_thread.json`` (``--t-end`` below 2.45 s: ``peers_thread_short.json``;
``--stem``: the name given)
with keys ``schema``, ``started``, ``command``, ``machine``, ``settings``, ``ours``,
``exudyn`` (per side: ``cpu_s``, driven ``omega_driven`` at t_end and
``omega_driven_mean``, ``driver_torque_mean_Nm``, ``tension_tight_N`` and
``tension_slack_N`` at t_end (ours: the belt's force N |r_x| of
:func:`ancf.checks.thread.real_force` under the file's strain law, its axial force N beside it), the run's counts), ``ratio`` = ours / Exudyn CPU, and the
markdown table beside it.
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
from functools import partial
from pathlib import Path

import numpy as np

from ancf.belts.drive_file import load
from ancf.checks.thread import real_force
from benchmarks import peers
from benchmarks.peers_thread_exudyn import N_ELEMENTS, SEGMENTS, STEP, T_END, WINDOW

FILE = peers.ROOT / "examples" / "thread_benchmark.toml"
#: our solver settings of the race: modified Newton accepting the last evaluated iterate,
#: refactoring when an increment exceeds 0.2 of the one before, at most once per step
#: unless an increment grows or is damped, the belt damping's strain-rate part of the iteration
#: matrix only, a step cycling at a contact point's entry given up and halved at its third
#: damped increment (the residual, the physics, are the file's; ancf.solvers.alpha_march,
#: ancf.belts.forces)
SOLVER = ("run.newton_accept=evaluated", "run.damping_jacobian=rate", "run.refresh_ratio=0.2",
          "run.refresh=once", "run.give_up=3")
#: our quadrature of the race: Gauss points per element of the elastic forces and of the contact
QUADRATURE = ("belt.elastic_points=3", "contact.gauss_points=4")
OWN = ("belt.n_elements=%d" % N_ELEMENTS, "run.dt=%g" % STEP)
OURS = (*OWN, *QUADRATURE, *SOLVER)
OWN_SETTINGS = (f"ancf run belt-drive --file FILE --set belt.n_elements={N_ELEMENTS} "
                f"--set run.dt={STEP:g} (the file's quadrature, friction law, damping, "
                "generalised-alpha rho_inf and every Newton setting at its default)")
SETTINGS = {
    "ours": f"ancf run belt-drive --file FILE --set belt.n_elements={N_ELEMENTS} "
            f"--set run.dt={STEP:g} " + " ".join(f"--set {s}" for s in (*QUADRATURE, *SOLVER)) +
            " (3 Gauss points per element for the elastic forces and 4 for the contact, "
            "against the file's 5 and 5; the file's friction law, damping, "
            "generalised-alpha rho_inf and Newton tolerance 1e-7; modified Newton keeping "
            "its factors across steps, refactored when an increment exceeds 0.2 of the one "
            "before, at most once per step unless an increment grows or is damped, the last "
            "evaluated iterate accepted, the damping's strain-rate Jacobian only in the "
            "iteration matrix, a step cycling at a contact point's entry given up and "
            "halved at its third damped increment; frictionless settling first)",
    "exudyn": f"benchmarks/peers_thread_exudyn.py: beltDriveReevingSystem.py's model, "
              f"{N_ELEMENTS} ANCFCable2D elements, {SEGMENTS} contact segments per element, "
              f"TrapezoidalIndex2 h = {STEP:g} s, modified Newton, EigenSparse, one thread, "
              "discontinuous iterations <= 3, static equilibrium first",
}


def our_sets(t_end: float, extra: list, base: tuple = OURS) -> list:
    """The overrides of our run: ``base`` (:data:`OURS` or :data:`OWN`), the end time and
    window, then ``extra``, whose keys replace those of the others (a key may be given
    once)."""
    window = min(WINDOW, t_end / 2)
    given = {e.split("=", 1)[0] for e in extra}
    sets = [*base, f"run.t_end={t_end:g}", f"run.steady_window={window:g}"]
    return [s for s in sets if s.split("=", 1)[0] not in given] + list(extra)


def _ours(path: Path, t_end: float, extra: list, env: dict, base: tuple = OURS) -> dict:
    window = min(WINDOW, t_end / 2)
    sets = our_sets(t_end, extra, base)
    cmd = [sys.executable, "-m", "ancf.cli", "run", "belt-drive", "--file", str(path), "--json"]
    for s in sets:
        cmd += ["--set", s]
    proc = subprocess.run(cmd, capture_output=True, text=True, env=env, cwd=peers.ROOT)
    if proc.returncode not in (0, 1):
        return {"error": proc.stderr.strip().splitlines()[-1:], "exit": proc.returncode,
                "sets": sets}
    out = json.loads(proc.stdout)
    r = out["results"]
    if not out["converged"] or r["pulleys"] is None:
        return {"converged": False, "message": out["message"], "sets": sets}
    p = {q["name"]: q for q in r["pulleys"]}
    driver, driven = r["pulleys"][0]["name"], r["pulleys"][1]["name"]
    t = np.array(r["times"])
    win = t >= t[-1] - window - 1e-9
    tight = next(s for s in r["spans"] if s["to"] == driver)
    slack = next(s for s in r["spans"] if s["from"] == driver)
    force = partial(real_force, desc=load(path, sets))  # the belt's force, as Exudyn's
    return {"sets": sets, "converged": True, "cpu_s": out["cpu_time_s"],
            "compile_cpu_s": out["compile_cpu_s"], "warnings": out["warnings"],
            "omega_driven": p[driven]["omega"][-1], "omega_driven_mean": p[driven]["omega_mean"],
            "driver_torque_mean_Nm": float(-np.mean(np.array(p[driver]["torque_Nm"])[win])),
            "tension_tight_N": float(force(tight["tension_N"])),
            "tension_slack_N": float(force(slack["tension_N"])),
            "axial_force_tight_N": tight["tension_N"], "axial_force_slack_N": slack["tension_N"],
            **{k: r[k] for k in ("steps", "newton_iterations", "njev", "nlu")}}


def _exudyn(t_end: float, env: dict) -> dict:
    proc = subprocess.run([sys.executable, "-m", "benchmarks.peers_thread_exudyn", f"{t_end:g}"],
                          capture_output=True, text=True, env=env, cwd=peers.ROOT)
    if proc.returncode != 0:
        return {"error": proc.stderr.strip().splitlines()[-3:], "exit": proc.returncode}
    return json.loads(proc.stdout[proc.stdout.index("{"):])


def _relative(path: Path) -> str:
    """The path relative to the checkout where it lies in it (no machine paths in reports)."""
    path = path.resolve()
    return str(path.relative_to(peers.ROOT)) if path.is_relative_to(peers.ROOT) else path.name


def markdown(res: dict) -> str:
    """The table of :func:`main`'s result."""
    o, e = res["ours"], res["exudyn"]
    rows = [("CPU time, s", "cpu_s", "{:.1f}"), ("driven ω at t_end, rad/s", "omega_driven", "{:.4f}"),
            ("driven ω mean, rad/s", "omega_driven_mean", "{:.4f}"),
            ("driver torque mean, N m", "driver_torque_mean_Nm", "{:.3f}"),
            ("tight span force at t_end, N", "tension_tight_N", "{:.1f}"),
            ("slack span force at t_end, N", "tension_slack_N", "{:.1f}"),
            ("steps", "steps", "{}"), ("Newton iterations", "newton_iterations", "{}")]
    fmt = lambda f, v: "–" if v is None else f.format(v)  # noqa: E731
    lines = [f"# THREAD belt drive side by side with Exudyn (t_end = {res['t_end']:g} s)", "",
             f"Generated by `{res['command']}` on {res['started']}; raw numbers in "
             f"`{res['stem']}.json`; do not edit by hand.  One run per side in a fresh "
             "process, ours first, one BLAS thread.  Timing columns vary run to run.", "",
             "| quantity | ours | Exudyn |", "|---|---|---|"]
    lines += [f"| {name} | {fmt(f, o.get(k))} | {fmt(f, e.get(k))} |" for name, k, f in rows]
    ratio = res["ratio"]
    lines += ["", f"**CPU ours / Exudyn: {'–' if ratio is None else f'{ratio:.3f}'}** "
              "(issue 21's acceptance: ≤ 0.25).", "", "## Settings", ""]
    lines += [f"- **{k}**: {v}" for k, v in res["settings"].items()]
    lines += ["", "## Machine", ""] + [f"- **{k}**: {v}" for k, v in res["machine"].items()]
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m benchmarks.peers_thread",
                                 description=__doc__.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=T_END, help="simulated time of both runs, s")
    ap.add_argument("--file", type=Path, default=FILE, help="our drive file")
    ap.add_argument("--own", action="store_true", help="ours at Exudyn's element count and "
                    "step alone: the file's own quadrature and Newton settings")
    ap.add_argument("--set", action="append", default=[], help="more overrides of our file")
    ap.add_argument("--out", type=Path, default=peers.DEFAULT_OUT, help="output folder")
    ap.add_argument("--stem", help="the record's file name (default peers_thread, "
                    "peers_thread_short below 2.45 s)")
    args = ap.parse_args(argv)
    if peers.exudyn_missing():
        print("peers_thread: exudyn is not installed (pip install -e .[peers]); skipped")
        return 0
    env = peers.worker_env()
    base = OWN if args.own else OURS
    res = peers.record("peers_thread", argv or sys.argv[1:], {
        **SETTINGS, **({"ours": OWN_SETTINGS} if args.own else {}),
        "file": _relative(args.file), "file_text": args.file.read_text(),
        "extra_sets": args.set, "worker_env": peers.THREAD_ENV, "unset": peers.UNSET_ENV},
        t_end=args.t_end)
    res["ours"] = _ours(args.file, args.t_end, args.set, env, base)
    res["exudyn"] = _exudyn(args.t_end, env)
    res["ratio"] = peers._ratio(res["ours"].get("cpu_s"), res["exudyn"].get("cpu_s"))
    res["stem"] = args.stem or ("peers_thread" if args.t_end >= T_END else "peers_thread_short")
    peers.write(args.out, res["stem"], res, markdown(res))
    print(f"peers_thread: ratio {res['ratio']}; wrote {args.out / res['stem']}.json/.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
