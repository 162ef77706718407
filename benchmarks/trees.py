"""Two checkouts side by side in one run, with Exudyn beside them: is a change speed-neutral?

    python -m benchmarks.trees BEFORE_DIR [--after DIR] [--repeats 5] [--out reports/benchmarks]

Each checkout (``BEFORE_DIR``, a worktree of an older commit; ``--after``, default this
one) gets its own long-lived worker (:mod:`benchmarks.peers_worker` started in that
tree, so it imports that tree's ``ancf``), and Exudyn a third where it is installed.
Per case every worker runs once as a warm-up (compiling), then ``repeats`` times in
turn before, after, Exudyn, before, after, ...; the medians are compared, and the
after/before ratio is also taken pair by pair (robust to a machine whose speed
drifts).  One BLAS thread, OPENBLAS_CORETYPE / OPENBLAS_L2_SIZE unset, as in
:mod:`benchmarks.peers`.  CPU time is each scene's ``cpu_time_s`` (the solve in a warm
process) and Exudyn's solve call.

Writes ``trees.md`` and ``trees.json`` (``--name`` another stem; keys: ``started``, ``machine``, ``trees``
(path and commit of each side), ``repeats``, ``cases``: rows ``{case, n, before,
after, exudyn, after_over_before, after_over_before_paired, before_over_exudyn,
after_over_exudyn}``, each side ``{cpu_s, cpu_s_samples, converged}``).
"""
from __future__ import annotations

import argparse
import datetime as dt
import json
import statistics
import subprocess
import sys
from pathlib import Path

from benchmarks import peers

ROOT = Path(__file__).resolve().parents[1]
#: (worker case, n, extra request keys, Exudyn has it)
CASES = (("cantilever", 8, {}, True), ("cantilever", 64, {}, True),
         ("pendulum-ga", 4, {}, True), ("pendulum-ga", 16, {}, True),
         ("pendulum-dop853", 4, {}, False), ("belt", 20, {}, True),
         ("belt3d", 20, {}, False), ("three-pulleys-3d", 30, {}, False))
WARMUP = {"belt": {"t_end": 0.01}, "belt3d": {"t_end": 0.002},
          "three-pulleys-3d": {"run.t_end": 0.002, "run.steady_window": 0.002,
                               "run.output_dt": 0.002}}


class TreeWorker(peers.Worker):
    """Our worker (this checkout's :mod:`benchmarks.peers_worker`, so both sides take the
    same cases) importing ``ancf`` from another checkout."""

    def __init__(self, tree: Path, env: dict):
        env = {**env, "PYTHONPATH": f"{tree}:{ROOT}"}
        self.side = str(tree)
        self.proc = subprocess.Popen([sys.executable, str(ROOT / "benchmarks" / "peers_worker.py"),
                                      "ours"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                     text=True, cwd=tree, env=env)


def _commit(tree: Path) -> str:
    return subprocess.run(["git", "log", "-1", "--format=%h %s"], cwd=tree, capture_output=True,
                          text=True).stdout.strip()[:100]


def _side(answers: list) -> dict:
    cpu = [a.get("cpu_s") for a in answers]
    ok = all(a.get("converged") for a in answers) and None not in cpu
    return {"cpu_s": statistics.median(cpu) if ok else None, "cpu_s_samples": cpu, "converged": ok,
            "error": next((a["error"] for a in answers if "error" in a), None)}


def _ratio(a, b):
    return a / b if a and b else None


def run_case(workers: dict, case: str, n: int, extra: dict, repeats: int) -> dict:
    for w in workers.values():
        w.ask(case, n, **WARMUP.get(case, extra))
    answers = {k: [] for k in workers}
    for _ in range(repeats):
        for k, w in workers.items():
            answers[k].append(w.ask(case, n, **extra))
    row = {"case": case, "n": n, **{k: _side(v) for k, v in answers.items()}}
    b, a = row["before"]["cpu_s"], row["after"]["cpu_s"]
    pairs = [_ratio(x, y) for x, y in zip(row["after"]["cpu_s_samples"],
                                          row["before"]["cpu_s_samples"])]
    row["after_over_before"] = _ratio(a, b)
    row["after_over_before_paired"] = statistics.median(pairs) if None not in pairs else None
    e = row.get("exudyn", {}).get("cpu_s")
    row["before_over_exudyn"], row["after_over_exudyn"] = _ratio(b, e), _ratio(a, e)
    print(f"  {case} n={n}: before {b} s, after {a} s, exudyn {e} s, "
          f"after/before {row['after_over_before_paired']}", file=sys.stderr, flush=True)
    return row


def _fmt(x, spec=".4g"):
    return "–" if x is None else format(x, spec)


def markdown(out: dict) -> str:
    lines = [f"# Before and after, side by side ({out['started']})", "",
             f"Machine: {out['machine']['cpu_model']}, {out['machine']['usable_cores']} usable "
             f"cores, load {out['machine']['load_average_at_start']}. Before: `{out['trees']['before']}`; "
             f"after: `{out['trees']['after']}`. Medians of {out['repeats']} alternating runs per "
             "side after a warm-up; CPU s of the solve (ours: the scene's `cpu_time_s`).", "",
             "| case | n | before s | after s | Exudyn s | after / before (paired) | "
             "before / Exudyn | after / Exudyn |", "|---|---|---|---|---|---|---|---|"]
    for r in out["cases"]:
        lines.append(f"| {r['case']} | {r['n']} | {_fmt(r['before']['cpu_s'])} | "
                     f"{_fmt(r['after']['cpu_s'])} | {_fmt(r.get('exudyn', {}).get('cpu_s'))} | "
                     f"{_fmt(r['after_over_before_paired'], '.3f')} | "
                     f"{_fmt(r['before_over_exudyn'], '.3f')} | {_fmt(r['after_over_exudyn'], '.3f')} |")
    return "\n".join(lines) + "\n"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("before", type=Path, help="checkout of the older commit")
    ap.add_argument("--after", type=Path, default=ROOT, help="checkout of the newer commit")
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--case", action="append", help="only these cases (worker case names)")
    ap.add_argument("--out", type=Path, default=ROOT / "reports" / "benchmarks")
    ap.add_argument("--name", default="trees", help="file stem of the outputs (default trees)")
    args = ap.parse_args(argv)
    env = peers.worker_env()
    trees = {"before": args.before.resolve(), "after": args.after.resolve()}
    workers = {k: TreeWorker(t, env) for k, t in trees.items()}
    exudyn = None if peers.exudyn_missing() else peers.Worker("exudyn", env)
    out = {"started": dt.datetime.now().isoformat(timespec="seconds"), "machine": peers.machine(),
           "trees": {k: f"{t.name} ({_commit(t)})" for k, t in trees.items()},
           "repeats": args.repeats, "cases": []}
    for case, n, extra, has_peer in CASES:
        if args.case and case not in args.case:
            continue
        ws = {**workers, **({"exudyn": exudyn} if exudyn and has_peer else {})}
        out["cases"].append(run_case(ws, case, n, extra, args.repeats))
    for w in [*workers.values(), *([exudyn] if exudyn else [])]:
        w.close()
    args.out.mkdir(parents=True, exist_ok=True)
    (args.out / f"{args.name}.json").write_text(json.dumps(out, indent=1) + "\n")
    (args.out / f"{args.name}.md").write_text(markdown(out))
    print(args.out / f"{args.name}.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
