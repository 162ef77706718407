"""Markdown of the side-by-side benchmark (``python -m benchmarks.peers``): the ratio
table ours / Exudyn per case and n, the details of each case (CPU time, Newton
iterations, Jacobians / factorisations where each code reports them, accuracy), the
model differences, settings and machine.  Everything is generated from the result
dict that is also written as JSON (keys documented in :mod:`benchmarks.peers`);
``python -m benchmarks.peers_report reports/benchmarks/peers.json`` writes the Markdown
again from a saved JSON.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

TIP_TARGET_M = 1e-4          # issue 11: pendulum tip within 1e-4 m of our DOP853 rtol 1e-10
DASH = "–"


def fmt_time(t) -> str:
    if t is None:
        return DASH
    for unit, f in (("s", 1.0), ("ms", 1e3), ("µs", 1e6)):
        if abs(t) * f >= 1.0 or unit == "µs":
            return f"{t * f:.3g} {unit}"


def fmt(v, spec: str = ".3g") -> str:
    return DASH if v is None else format(v, spec)


def fmt_ratio(r) -> str:
    return DASH if r is None else f"{r:.3g}"


def fmt_spread(row) -> str:
    """Range of the paired ratios of a row."""
    rs = row.get("ratio_paired") or []
    return DASH if not rs else f"{min(rs):.3g}–{max(rs):.3g}"


def md_table(header, rows) -> str:
    out = ["| " + " | ".join(header) + " |", "|" + "|".join("---" for _ in header) + "|"]
    return "\n".join(out + ["| " + " | ".join(str(c) for c in r) + " |" for r in rows])


def _rows(result, case):
    return [r for r in result["cases"] if r["case"] == case]


def _cpu(side: dict) -> str:
    return f"{fmt_time(side.get('cpu_s'))}" + ("" if side.get("converged", True) else " (failed)")


def _counts(side: dict, keys) -> str:
    return " / ".join(DASH if side.get(k) is None else str(side[k]) for k in keys)


def _tip(side: dict) -> str:
    x, y = side.get("tip_x"), side.get("tip_y")
    return DASH if x is None else f"({x:.6f}, {y:.6f})"


def ratio_table(result) -> str:
    """One line per case: the label, the n's and the ratios, as in issue 11."""
    rows, seen = [], []
    for r in result["cases"]:
        if r["case"] not in seen:
            seen.append(r["case"])
    for case in seen:
        rs = _rows(result, case)
        ns = " / ".join(str(r["n"]) for r in rs)
        rows.append([f"{rs[0]['label']}, n = {ns}", " / ".join(fmt_ratio(r["ratio"]) for r in rs)])
    return md_table(["case (same mesh, same load or step)", "ours / Exudyn"], rows)


def static_table(result) -> str:
    rows = [[r["n"], _cpu(r["ours"]), _cpu(r["exudyn"]), f"**{fmt_ratio(r['ratio'])}**",
             fmt_spread(r), _counts(r["ours"], ("newton_iterations", "njev", "nlu")),
             _counts(r["exudyn"], ("newton_iterations", "jacobians")),
             _tip(r["ours"]), fmt(r["ours"].get("tip_error_m"), ".2e"),
             _tip(r["exudyn"]), fmt(r["exudyn"].get("tip_error_m"), ".2e"),
             fmt(r["exudyn"].get("rel_tol"), ".0e")] for r in _rows(result, "cantilever")]
    return md_table(["n", "ours CPU", "Exudyn CPU", "ours / Exudyn", "paired range",
                     "ours Newton it. / tangents / LU", "Exudyn Newton it. / Jacobians (= LU)",
                     "ours tip (x, y) [m]", "ours − Reissner [m]", "Exudyn tip (x, y) [m]",
                     "Exudyn − elastica [m]", "Exudyn relTol"], rows)


def pendulum_table(result, case) -> str:
    rows = [[r["n"], _cpu(r["ours"]), _cpu(r["exudyn"]), f"**{fmt_ratio(r['ratio'])}**",
             fmt_spread(r), _counts(r["ours"], ("steps", "newton_iterations", "njev", "nlu")),
             _counts(r["exudyn"], ("steps", "newton_iterations", "jacobians")),
             fmt(r["ours"].get("energy_max_deviation_J"), ".3e"),
             fmt(r["exudyn"].get("energy_max_deviation_J"), ".3e"),
             fmt(r["ours"].get("tip_error_m"), ".2e"), _target(r["ours"].get("tip_error_m")),
             fmt(r["exudyn"].get("tip_error_self_m"), ".2e"),
             fmt(r["exudyn"].get("tip_error_m"), ".2e")] for r in _rows(result, case)]
    return md_table(["n", "ours CPU", "Exudyn CPU", "ours / Exudyn", "paired range",
                     "ours steps / Newton it. / tangents / LU",
                     "Exudyn steps / Newton it. / Jacobians (= LU)",
                     "ours energy dev. [J]", "Exudyn energy dev. [J]",
                     "ours tip − our DOP853 1e-10 [m]", f"≤ {TIP_TARGET_M:g} m",
                     "Exudyn tip − Exudyn h = 1e-4 [m]",
                     "Exudyn tip − our DOP853 1e-10 [m] (model difference included)"], rows)


def _target(err) -> str:
    return DASH if err is None else ("yes" if err <= TIP_TARGET_M else "no")


def process_table(result) -> str:
    rows = [[r["n"], f"`{r['ours']['command']}`", f"`{r['exudyn']['command']}`",
             fmt_time(r["ours"]["cpu_s"]), fmt_time(r["exudyn"]["cpu_s"]),
             f"**{fmt_ratio(r['ratio'])}**", fmt_spread(r), fmt_time(r["ours"]["wall_s"]),
             fmt_time(r["exudyn"]["wall_s"]), fmt_ratio(r["ratio_wall"])]
            for r in _rows(result, "process")]
    return md_table(["n", "ours", "Exudyn", "ours CPU", "Exudyn CPU", "ours / Exudyn (CPU)",
                     "paired range", "ours wall", "Exudyn wall", "ours / Exudyn (wall)"], rows)


def model_note(result) -> str:
    ref = result["references"]
    gap = ((ref["reissner"]["tip_x"] - ref["elastica"]["tip_x"]) ** 2
           + (ref["reissner"]["tip_y"] - ref["elastica"]["tip_y"]) ** 2) ** 0.5
    return (
        "Exudyn's `ObjectANCFCable2D` has the same 4 coordinates per node as our linear "
        "element (position and one slope vector) but it is an Euler–Bernoulli cable: cubic "
        "Hermite interpolation of the axis, axial strain |r′| − 1 and the material curvature, "
        "no shear and no cross-section deformation, and its slope is the axial r′; ours is a "
        "shear-deformable continuum element, linear along the axis, whose slope is the "
        "transverse ∂r/∂y (Green strain, ν enters). "
        "So the two codes solve different beam models on the same mesh: their tips differ by "
        "the model, not by the solver. Each is therefore measured against the reference of its "
        "own model: ours against the geometrically exact shear-deformable Reissner rod "
        f"(`ancf analytic reissner`, tip ({ref['reissner']['tip_x']:.9f}, "
        f"{ref['reissner']['tip_y']:.9f}) m), Exudyn against the same rod made shear-rigid "
        f"(k_s = {ref['elastica']['ks']:g}: the extensible elastica, tip "
        f"({ref['elastica']['tip_x']:.9f}, {ref['elastica']['tip_y']:.9f}) m); the two "
        f"references are {gap:.2e} m apart. In the pendulum, ours eliminates the pinned "
        "coordinates while Exudyn adds coordinate constraints with multipliers (index 3); "
        "the pendulum tip of both is compared with our own DOP853 rtol 1e-10 run at the same "
        "n, so Exudyn's column there contains the model difference; Exudyn's time-integration "
        "error is its distance to its own run with h = 1e-4. Energy deviations are the "
        "largest change of kinetic + gravity + strain energy over the 0.01 s samples; "
        "Exudyn's is evaluated from its sampled nodal coordinates with the cable's own "
        "strain measures and quadrature (5 Gauss points axial, 3 bending)."
    )


def machine_lines(result) -> str:
    m = result["machine"]
    lines = [f"- **{k}**: {v}" for k, v in m.items()]
    for side, info in result["workers"].items():
        versions = ", ".join(f"{k} {info[k]}" for k in ("python", "numpy", "scipy", "exudyn")
                             if k in info)
        env = ", ".join(f"{k}={'unset' if v is None else v}"
                        for k, v in info.get("env", {}).items())
        kernel = info.get("blas", {}).get("kernel", "not recorded")
        kernel = ", ".join(kernel) if isinstance(kernel, list) else kernel
        lines.append(f"- **{side} worker**: {versions}; environment {env}; BLAS kernel {kernel}")
    return "\n".join(lines)


def settings_lines(result) -> str:
    s = result["settings"]
    lines = [f"- **{side} {case}**: {text}" for side in ("ours", "exudyn")
             for case, text in s[side].items()]
    reps = ", ".join(f"{case} {k}" for case, k in s["repeats"].items())
    lines.append(f"- **repeats** after one warm-up per side: {reps}")
    return "\n".join(lines)


def render(result, json_name: str = "peers.json") -> str:
    parts = [
        "# Side by side with Exudyn",
        f"Generated by `{result['command']}` (`make bench`) on {result['started']}, with the "
        f"raw numbers in `{json_name}`; do not edit by hand. Ours = the "
        "scene's own `cpu_time_s` (model build and stability check included); Exudyn = "
        "`time.process_time` around its solve call; each code in its own long-lived process, "
        "one BLAS thread, warmed up, cases alternating ours / Exudyn, medians; the paired range "
        "is the smallest and largest ratio of one alternating pair (the noise of a shared "
        "machine). A ratio below 1 means ours is faster. Counts are per run; – : not "
        "reported by that code.",
        "## Ratio ours / Exudyn (CPU time)", ratio_table(result),
        "## Static cantilever Model 1 (L = 2 m, b = h = 0.1 m, E = 2.07e11 Pa, ν = 0.3, "
        "F = −5e8 h³ N, 10 load steps)", static_table(result),
        "## Flexible pendulum, 1 s, generalised-α dt = 1e-3 in both",
        pendulum_table(result, "pendulum-ga"),
        "## Flexible pendulum, our default DOP853 vs Exudyn's generalised-α",
        pendulum_table(result, "pendulum-dop853"),
        "## Whole process (imports included)", process_table(result),
        "## Model differences", model_note(result),
        "## Settings", settings_lines(result),
        "## Machine", machine_lines(result),
    ]
    return "\n\n".join(parts) + "\n"


def before_after(before, after) -> str:
    """The ratio ours / Exudyn of each case and n in two runs (the core before and after
    a change), with our CPU time in each and its speed-up; Exudyn's own time in both
    runs shows how much the machine moved between them."""
    old = {(r["case"], r["n"]): r for r in before["cases"]}
    rows = []
    for r in after["cases"]:
        b = old.get((r["case"], r["n"]))
        if b is None:
            continue
        rows.append([r["label"], r["n"], fmt_ratio(b["ratio"]), f"**{fmt_ratio(r['ratio'])}**",
                     fmt_time(b["ours"]["cpu_s"]), fmt_time(r["ours"]["cpu_s"]),
                     fmt_ratio(b["ours"]["cpu_s"] / r["ours"]["cpu_s"]),
                     fmt_time(b["exudyn"]["cpu_s"]), fmt_time(r["exudyn"]["cpu_s"])])
    head = (f"# Side by side with Exudyn: before and after\n\nGenerated by `python -m "
            f"benchmarks.peers` from `peers_before.json` ({before['started']}) and `peers.json` "
            f"({after['started']}); do not edit by hand. Ratios are ours / Exudyn CPU time, "
            "each measured side by side in its own run.\n\n")
    return head + md_table(["case", "n", "ours / Exudyn before", "ours / Exudyn after",
                            "ours CPU before", "ours CPU after", "our speed-up",
                            "Exudyn CPU (before run)", "Exudyn CPU (after run)"], rows) + "\n"


def write(result, out_dir: Path, stem: str) -> list:
    out_dir.mkdir(parents=True, exist_ok=True)
    md, js = out_dir / f"{stem}.md", out_dir / f"{stem}.json"
    js.write_text(json.dumps(result, indent=1) + "\n")
    md.write_text(render(result, js.name))
    before = out_dir / "peers_before.json"
    if stem == "peers" and before.exists():
        cmp = out_dir / "peers_before_after.md"
        cmp.write_text(before_after(json.loads(before.read_text()), result))
        return [md, js, cmp]
    return [md, js]


def main(argv=None) -> int:
    """``python -m benchmarks.peers_report PEERS.json``: the Markdown again, beside it
    (and the before/after table for ``peers.json`` when ``peers_before.json`` is there)."""
    js = Path((sys.argv[1:] if argv is None else argv)[0])
    write(json.loads(js.read_text()), js.parent, js.stem)
    return 0


if __name__ == "__main__":
    sys.exit(main())
