"""Markdown summary of a pytest-benchmark JSON run.

    python -m benchmarks.summarize [--json reports/benchmarks/benchmark.json]
                                   [--out reports/benchmarks/README.md]

Writes: a table of every benchmark (name, params, mean, stddev, rounds, extra info),
element x n tables for the full solve and the Newton-iteration kernel, the
linear / Omar-Shabana Newton-iteration time ratios against the thesis's ~0.5, and
the pendulum timings (Table 2.5 ratio, cost per simulated second vs n), the 2D and 3D
belt drives (time split and counters) and the machine description.
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_JSON = ROOT / "reports" / "benchmarks" / "benchmark.json"
DEFAULT_OUT = ROOT / "reports" / "benchmarks" / "README.md"
THESIS_RATIO = 0.5
ELEMENTS = ("linear", "omar-shabana")


def fmt_time(t) -> str:
    if t is None:
        return "–"
    for unit, f in (("s", 1.0), ("ms", 1e3), ("µs", 1e6)):
        if abs(t) * f >= 1.0 or unit == "µs":
            return f"{t * f:.3g} {unit}"


def fmt_value(key: str, v) -> str:
    if isinstance(v, float):
        return fmt_time(v) if key.endswith("_s") else f"{v:.4g}"
    return str(v)


def md_table(header, rows) -> str:
    esc = lambda c: str(c).replace("|", "\\|")  # noqa: E731
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    out += ["| " + " | ".join(esc(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def short_name(b) -> str:
    return b["name"].split("[", 1)[0]


def params_str(b) -> str:
    return ", ".join(f"{k}={v}" for k, v in (b.get("params") or {}).items())


def all_benchmarks_table(benches) -> str:
    skip = {"element", "n_elements", "thesis_ratio"}
    rows = []
    for b in benches:
        s = b["stats"]
        extra = "; ".join(f"{k}={fmt_value(k, v)}" for k, v in b.get("extra_info", {}).items()
                          if k not in skip)
        rows.append([short_name(b), params_str(b), fmt_time(s["mean"]), fmt_time(s["stddev"]),
                     fmt_time(s["median"]), s["rounds"], extra])
    return md_table(["benchmark", "params", "mean", "stddev", "median", "rounds", "extra info"],
                    rows)


def pivot(benches, test, value, fmt=str, ratio_row=False) -> str | None:
    """element x n table of value(b); optionally a row linear / Omar-Shabana."""
    cells = {}
    for b in benches:
        if short_name(b) != test:
            continue
        p = b.get("params") or {}
        cells[(p.get("element"), p.get("n"))] = value(b)
    if not cells:
        return None
    ns = sorted({n for _, n in cells})
    rows = [[el] + [fmt(cells[(el, n)]) if (el, n) in cells else "–" for n in ns]
            for el in ELEMENTS if any((el, n) in cells for n in ns)]
    if ratio_row:
        row = ["linear / Omar–Shabana"]
        for n in ns:
            a, b = cells.get(("linear", n)), cells.get(("omar-shabana", n))
            row.append(f"{a / b:.3f}" if a is not None and b else "–")
        rows.append(row)
    return md_table(["element"] + [f"n = {n}" for n in ns], rows)


def ratio_table(benches) -> str | None:
    rows = []
    for b in sorted((b for b in benches if short_name(b) == "test_newton_ratio"),
                    key=lambda b: b["params"]["n"]):
        e = b["extra_info"]
        r = e["ratio_linear_over_os"]
        rows.append([e["n_elements"], f"{e['n_dofs_linear']} / {e['n_dofs_omar_shabana']}",
                     fmt_time(e["linear_median_s"]), fmt_time(e["omar_shabana_median_s"]),
                     f"**{r:.3f}**",
                     f"{e['ratio_paired_median']:.3f} [{e['ratio_paired_q25']:.3f}, "
                     f"{e['ratio_paired_q75']:.3f}]",
                     f"{e.get('thesis_ratio', THESIS_RATIO):g}", f"{r / THESIS_RATIO:.2f}",
                     e["samples"]])
    if not rows:
        return None
    return md_table(["n", "DOFs lin / OS", "linear median", "Omar–Shabana median",
                     "ratio lin/OS", "paired ratio median [IQR]", "thesis", "ratio / thesis",
                     "samples"], rows)


def pendulum_table(benches) -> str | None:
    """(element, integrator) x n table of the 1 s pendulum's median time."""
    cells = {}
    for b in benches:
        if short_name(b) == "test_pendulum":
            p = b["params"]
            cells[(p["element"], p["integrator"], p["n"])] = b["stats"]["median"]
    if not cells:
        return None
    ns = sorted({k[2] for k in cells})
    keys = sorted({k[:2] for k in cells})
    rows = [[f"{el}, {integ}"] + [fmt_time(cells.get((el, integ, n))) for n in ns]
            for el, integ in keys]
    return md_table(["element, integrator"] + [f"n = {n}" for n in ns], rows)


def pendulum_ratio_table(benches) -> str | None:
    rows = []
    for b in sorted((b for b in benches if short_name(b) == "test_pendulum_ratio"),
                    key=lambda b: (b["params"]["integrator"], b["params"]["n"])):
        e = b["extra_info"]
        thesis = e.get("thesis_ratio")
        rows.append([e["n_elements"], e["integrator"], fmt_time(e["linear_median_s"]),
                     fmt_time(e["omar_shabana_median_s"]), f"**{e['ratio_linear_over_os']:.3f}**",
                     f"[{e['ratio_paired_q25']:.3f}, {e['ratio_paired_q75']:.3f}]",
                     "–" if thesis is None else f"{thesis:g}",
                     f"{e['steps_linear']} / {e['steps_omar_shabana']}", e["samples"]])
    if not rows:
        return None
    return md_table(["n", "integrator", "linear median", "Omar–Shabana median", "ratio lin/OS",
                     "paired ratio IQR", "thesis Table 2.5", "steps lin / OS", "samples"], rows)


def scaling_table(benches):
    """n x integrator table of CPU seconds per simulated second, plus growth exponents."""
    cells = {}
    for b in benches:
        if short_name(b) == "test_cost_per_simulated_second":
            e = b["extra_info"]
            cells[(e["integrator"], e["n_elements"])] = (b["stats"]["median"] / e["t_end_s"],
                                                         e.get("steps"))
    if not cells:
        return None, cells
    ns = sorted({n for _, n in cells})
    integs = sorted({i for i, _ in cells})
    rows = []
    for n in ns:
        row = [n]
        for i in integs:
            c = cells.get((i, n))
            row += ["–", "–"] if c is None else [fmt_time(c[0]), c[1]]
        rows.append(row)
    header = ["n"] + [h for i in integs for h in (f"{i}: CPU per simulated s", f"{i}: steps")]
    return md_table(header, rows), cells


def scaling_plot(cells, out: Path) -> str | None:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return None
    fig, ax = plt.subplots(figsize=(6, 4))
    for integ in sorted({i for i, _ in cells}):
        ns = sorted(n for i, n in cells if i == integ)
        ax.loglog(ns, [cells[(integ, n)][0] for n in ns], "o-", label=integ)
    ax.set(xlabel="number of linear elements", ylabel="CPU s per simulated s",
           title="Flexible pendulum: cost of refinement")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)
    return out.name


def growth_exponents(cells) -> str:
    parts = []
    for integ in sorted({i for i, _ in cells}):
        ns = sorted(n for i, n in cells if i == integ)
        if len(ns) >= 2:
            slope = np.polyfit(np.log(ns[-3:]), np.log([cells[(integ, n)][0] for n in ns[-3:]]), 1)[0]
            parts.append(f"{integ} ∝ n^{slope:.2f}")
    return ", ".join(parts)


def dynamics_sections(benches, out_dir: Path = DEFAULT_OUT.parent) -> list:
    parts = []
    table = pendulum_table(benches)
    if table:
        parts += ["## Flexible pendulum, 1 s, median time", "",
                  "`SCENES['pendulum'].execute` (thesis Fig. 2.5; DOP853 rtol 1e-8, Radau rtol 1e-6 "
                  "with the analytic Jacobian, generalised-α dt 1e-3).", "", table, ""]
    ratios = pendulum_ratio_table(benches)
    if ratios:
        parts += ["## Pendulum CPU-time ratio, linear / Omar–Shabana (thesis Table 2.5)", "",
                  "Both elements run alternately in one benchmark (order swapped each round); "
                  "process time, median over the rounds.", "", ratios, ""]
    scaling, cells = scaling_table(benches)
    if scaling:
        parts += ["## Cost per simulated second vs number of elements", "",
                  "Linear element, pendulum run for a short time and scaled to one simulated second. "
                  f"Growth over the last three n: {growth_exponents(cells)}.", "", scaling, ""]
        png = scaling_plot(cells, out_dir / "cost_per_simulated_second.png")
        if png:
            parts += [f"![cost per simulated second]({png})", ""]
    return parts


BELT_SPLIT = ("elastic_s", "contact_s", "linear_algebra_s", "other_s")


def belt_table(benches, test: str, keys) -> str | None:
    """One row per run of a belt-drive benchmark: median time, the run's integration
    CPU time (and per simulated second, where recorded), its split and counters, and
    ``keys`` (extra_info results)."""
    runs = [b for b in benches if short_name(b) == test]
    if not runs:
        return None
    rows = []
    for b in runs:
        x = b.get("extra_info", {})
        cpu = x.get("integration_cpu_s")
        split = " / ".join(f"{100 * x[k] / cpu:.0f}" if cpu and k in x else "–" for k in BELT_SPLIT)
        rows.append([params_str(b), fmt_time(b["stats"]["median"]), fmt_time(cpu),
                     fmt_time(x.get("cpu_per_simulated_s")), split,
                     *(x.get(k, "–") for k in ("steps", "newton_iterations", "nlu",
                                               "rejected_steps")),
                     *(fmt_value(k, x[k]) if x.get(k) is not None else "–" for k in keys)])
    return md_table(["params", "median", "integration CPU", "CPU / simulated s",
                     "elastic / contact / lin. alg. / rest, %", "steps", "Newton its",
                     "factorisations", "rejected", *keys], rows)


def belt_sections(benches) -> list:
    parts = []
    table = belt_table(benches, "test_belt_drive", ("omega_ratio_steady",))
    if table:
        parts += ["## Belt drive (2D), 1 s", "",
                  "`SCENES['belt2d'].execute({n_elements})` (thesis 3.3, Table 3.1; dt 2.5e-4 s, "
                  "generalised-α). The split of the integration time is estimated from per-call "
                  "kernel costs times call counts (`python -m benchmarks.belt_profile`).", "",
                  table, ""]
    table = belt_table(benches, "test_belt3d_drive",
                       ("slip_driven", "membrane_tight_N", "membrane_slack_N"))
    if table:
        parts += ["## Belt drive (3D plates), Model 2, 1.2 s", "",
                  "`SCENES['belt3d'].execute({n_elements, contact_points})` (thesis 4.6, Table 4.1 "
                  "Model 2; dt 1e-4 s, generalised-α, from the settled belt; one round). CPU per "
                  "simulated second averages ramp-up and full speed. Split as for the 2D drive "
                  "(`python -m benchmarks.belt3d_profile`); tensions are the membrane's axial "
                  "force, span means, N.", "", table, ""]
    return parts


def machine_section(data) -> str:
    mi = data.get("machine_info", {})
    am = mi.get("ancf_machine")
    lines = []
    if am:
        for k in ("cpu_model", "logical_cores", "usable_cores", "os", "platform", "python",
                  "numpy", "scipy", "blas", "pytest_benchmark", "thread_env"):
            if k in am:
                v = am[k]
                if k == "thread_env" and not v:
                    v = "no OMP/OPENBLAS/MKL_NUM_THREADS set (BLAS uses its default thread count)"
                lines.append(f"- **{k}**: {v if v not in ({}, None) else '–'}")
    else:
        cpu = (mi.get("cpu") or {}).get("brand_raw", mi.get("processor", "?"))
        lines.append(f"- {cpu}, {mi.get('system', '?')} {mi.get('release', '')}, "
                     f"Python {mi.get('python_version', '?')} (no ancf_machine record)")
    lines.append(f"- **run started**: {data.get('datetime', '?')}")
    lines.append(f"- **pytest-benchmark**: {data.get('version', '?')}")
    return "\n".join(lines)


def render(data, json_name: str, out_dir: Path = DEFAULT_OUT.parent) -> str:
    benches = data.get("benchmarks", [])
    parts = [
        "# ancf-bench benchmarks",
        "",
        f"Generated by `python -m benchmarks.summarize` from `{json_name}` (written by `make bench`); "
        "do not edit by hand. Times are wall-clock (`time.perf_counter`) on the machine below; "
        "no thresholds are asserted.",
        "",
        "- **cantilever Model 1 static solve**: `SCENES['cantilever'].execute({element, n_elements})` "
        "(h = 0.1 m, ν = 0.3, F = −5e8 h³, 10 initial load steps, Newton to rtol 1e-8, "
        "plus the scene's dense tangent-stability check).",
        "- **Newton iteration kernel**: `assembly.gradient_tangent(q)` at a perturbed clamped "
        "configuration, reduction `Tᵀ K T` to the free coordinates, sparse LU (`splu`) and solve.",
        "- **Newton iteration ratio**: both elements' kernels timed alternately (order swapped each "
        "round), median over the rounds.",
        "",
    ]
    mean = lambda b: b["stats"]["mean"]  # noqa: E731
    solve = pivot(benches, "test_cantilever_solve", mean, fmt_time, ratio_row=True)
    if solve:
        parts += ["## Full static solve, mean time", "", solve, ""]
        iters = pivot(benches, "test_cantilever_solve",
                      lambda b: b["extra_info"].get("newton_iterations", "–"))
        parts += ["Newton iterations of the solve:", "", iters, ""]
    kern = pivot(benches, "test_newton_kernel", mean, fmt_time, ratio_row=True)
    if kern:
        parts += ["## One Newton iteration (kernel), mean time", "", kern, ""]
        per = pivot(benches, "test_newton_kernel",
                    lambda b: b["extra_info"].get("kernel_time_per_element_s"), fmt_time)
        parts += ["Kernel time per element:", "", per, ""]
    ratios = ratio_table(benches)
    if ratios:
        parts += ["## Newton-iteration time ratio, linear / Omar–Shabana", "",
                  "The thesis reports that a Newton iteration with the linear element is about two "
                  "times shorter than with the Omar–Shabana element (ratio ≈ 0.5). "
                  "`ratio lin/OS` = median(linear) / median(Omar–Shabana); the paired ratio is the "
                  "median of the per-round ratios.", "", ratios, ""]
    parts += dynamics_sections(benches, out_dir)
    parts += belt_sections(benches)
    parts += ["## Also in `make bench`", "",
              "- [core_profile.md](core_profile.md): one Newton iteration split into gather, kernel, "
              "scatter, factorisation and solve for 64-4096 elements, scaling exponents, the "
              "stability check's share (`python -m benchmarks.core_profile`).",
              "- [peers.md](peers.md): side by side with Exudyn, and "
              "[peers_before_after.md](peers_before_after.md): the ratios before and after the "
              "compiled core (`python -m benchmarks.peers`, optional extra `peers`).", ""]
    parts += ["## All benchmarks", "", all_benchmarks_table(benches), "",
              "## Machine", "", machine_section(data), ""]
    return "\n".join(parts)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--json", type=Path, default=DEFAULT_JSON)
    ap.add_argument("--out", type=Path, default=DEFAULT_OUT)
    a = ap.parse_args(argv)
    if not a.json.is_file():
        print(f"{a.json}: not found; run `make bench` first", file=sys.stderr)
        return 1
    data = json.loads(a.json.read_text())
    try:
        name = a.json.resolve().relative_to(ROOT)
    except ValueError:
        name = a.json
    a.out.parent.mkdir(parents=True, exist_ok=True)
    a.out.write_text(render(data, str(name), a.out.parent))
    print(f"wrote {a.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
