"""Markdown of the belt-drive side by side (``python -m benchmarks.peers_belt``): CPU
times and the ratio ours / Exudyn per n, step statistics, the driven pulley's angular
velocity at t_end of both codes, Exudyn's step convergence, model differences,
settings and machine, all generated from the result dict also written as JSON (keys in
:mod:`benchmarks.peers_belt`).  ``python -m benchmarks.peers_belt_report
reports/benchmarks/peers_belt.json`` writes the Markdown again.
"""
from __future__ import annotations

import json
import math
import sys
from pathlib import Path

from benchmarks.peers_report import DASH, fmt, fmt_ratio, fmt_spread, fmt_time, machine_lines, \
    md_table

def model_note(result) -> str:
    """Model differences; numbers from the Table 3.1 values stored in the result."""
    m = result["settings"]["model"]
    tb, n0 = m["table"], result["cases"][0]["n"]
    phi = tb["length"] / (n0 * m["segments"]) / tb["R"]
    sag = tb["R"] * (1 - math.cos(phi / 2))
    return (
        f"Both codes model Table 3.1 (R1 = R2 = {tb['R']:g} m at ({tb['x_driver']:g}, 0) and "
        f"({tb['x_driven']:g}, 0) m, ρ = {tb['rho']:g} kg/m³, {tb['side']:g} m square section, "
        f"E = {tb['E']:g} Pa, belt material length {tb['length']:g} m on a "
        f"{m['wrapped_length']:.5f} m wrapped path, k_p = {tb['k_p']:g} N/m², c_p = "
        f"{tb['c_p']:g} N s/m², μ = {tb['mu']:g}, ν_s = {tb['nu_s']:g} kg/(m s), I = "
        f"{tb['inertia']:g} kg m², driver speed of Eq 3.29), but not with the same model. "
        "**Belt**: Exudyn's `ObjectANCFCable2D` is an Euler–Bernoulli cable (cubic Hermite "
        "axis, axial strain |r′| − 1, material curvature; no shear, no cross-section "
        "deformation, ν does not enter) and has no α1 / α2: it is given EA = α1 E A and "
        f"EI = α2 E I, which is what α1 = {tb['alpha1']:g}, α2 = {tb['alpha2']:g} do to the "
        "thesis element at small "
        "strain; ours is the shear-deformable element with α1, α2 in its strain energy. "
        f"**Contact**: Exudyn splits every element into {m['segments']} straight segments and "
        "applies one "
        "point force per segment at its point closest to the pulley centre (the chords sag "
        f"inside the circle, so the belt's nodes sit about R(1 − cos(φ/2)) = {sag * 1e3:.2f} mm "
        f"outside it at n = {n0}, the same on both pulleys); its coefficients are per segment, so "
        "contactStiffness = k_p l_seg, contactDamping = c_p l_seg with l_seg the segment's "
        "material length; ours integrates the distributed penalty force of Eq 3.20 at Gauss "
        "points along the curved element. "
        "**Friction**: ours is the tri-linear creep-rate law (slope ν_s, saturating at μ|f_n|); "
        "Exudyn's is a per-segment Coulomb law with a velocity penalty "
        "frictionVelocityPenalty = ν_s l_seg (the same creep slope) plus a tangential sticking "
        f"spring frictionStiffness = {m['stick_spring']:g} contactStiffness (Exudyn's own example "
        "ratio; with the "
        "velocity penalty alone its stick/slip switching does not keep the belt at rest before "
        "the drive starts), the stick/slip state frozen during Newton and decided in its "
        "post-Newton (discontinuous) iteration. "
        "**Pre-tension**: Exudyn first solves the static problem with both pulleys held, one "
        "belt node held in x and friction off, and starts the dynamic run from that state at "
        "rest; ours does the same by minimising strain plus penalty energy without friction, "
        "with node 0 held along the path (scene parameter start = settled; start = laid is "
        "the thesis' start from the wrapped, stretched configuration). "
        "**Drive**: Exudyn prescribes the driver's angular velocity by a velocity-level "
        "coordinate constraint (symbolic user function); the driven pulley (and, formally, the "
        "driver) is a rigid body whose centre is held by coordinate constraints. "
        "Because of these differences the two driven speeds are not expected to agree to more "
        "than the model differences allow; the driven speed oscillates about the driver's, so "
        "the value at t = 1 s depends on the phase, and the mean over the last 0.2 s is shown "
        "beside it.")




def _t(side: dict, key: str = "cpu_s") -> str:
    return DASH if side.get(key) is None else fmt_time(side[key])


def timing_table(result) -> str:
    rows = [[r["n"], _ours_cell(r["ours"], _t(r["ours"])), _t(r["exudyn"], "total_cpu_s"),
             _t(r["exudyn"]), _t(r["exudyn"], "static_wall_s"), f"**{fmt_ratio(r['ratio'])}**",
             fmt_ratio(r["ratio_dynamic"]), fmt_spread(r)] for r in result["cases"]]
    return md_table(["n", "ours CPU", "Exudyn CPU (build + static + dynamic)",
                     "Exudyn CPU (dynamic)", "Exudyn static (wall)",
                     "ours / Exudyn (total)", "ours / Exudyn dynamic", "paired range"], rows)


def _ours_cell(side: dict, text: str) -> str:
    return side["pending"] if "pending" in side else text


def _counts(side: dict, keys) -> str:
    return " / ".join(DASH if side.get(k) is None else str(side[k]) for k in keys)


def steps_table(result) -> str:
    keys = ("steps", "newton_iterations", "jacobians", "discontinuous_iterations")
    rows = [[r["n"], _ours_cell(r["ours"], _counts(r["ours"], ("steps", "newton_iterations",
                                                               "njev", "nlu"))),
             _counts(r["exudyn"], keys), _counts(r["exudyn_half_step"], keys)]
            for r in result["cases"]]
    return md_table(["n", "ours steps / Newton it. / tangents / LU",
                     "Exudyn steps / Newton it. / Jacobians / discontinuous it.",
                     "same, Exudyn with half the step"], rows)


def _omega(side: dict) -> str:
    w, m, d = side.get("omega_driven"), side.get("omega_driven_mean_last"), side.get(
        "omega_driver")
    return DASH if w is None else f"{w:.4f} / {fmt(m, '.4f')} / {fmt(w / d if d else None, '.4f')}"


def omega_table(result) -> str:
    rows = [[r["n"], _ours_cell(r["ours"], _omega(r["ours"])), _omega(r["exudyn"]),
             _omega(r["exudyn_half_step"]), fmt(r["exudyn"].get("step"), "g"),
             fmt(r["exudyn_half_step"].get("step"), "g")] for r in result["cases"]]
    return md_table(["n", "ours ω_driven(t_end) / mean last 0.2 s / ω_driven/ω_driver",
                     "Exudyn, same", "Exudyn with half the step, same", "Exudyn h [s]",
                     "half step [s]"], rows)


def settings_lines(result) -> str:
    s = result["settings"]
    return "\n".join([f"- **ours**: {s['ours']}", f"- **exudyn**: {s['exudyn']}",
                      f"- **runs** per side and n after a {s['warmup_t_end']:g} s warm-up: "
                      f"{s['repeats']}, simulated time {s['t_end']:g} s"])


def render(result, json_name: str = "peers_belt.json") -> str:
    t_end = result["settings"]["t_end"]
    parts = [
        "# Belt drive side by side with Exudyn (thesis chapter 3)",
        f"Generated by `{result['command']}` (`make bench`) on {result['started']}, raw "
        f"numbers (and the sampled driven speed for a plot) in `{json_name}`; do not edit "
        "by hand. Each code in its own long-lived process, one BLAS thread, warmed up, runs "
        "alternating ours / Exudyn, medians. Ours = the scene's `cpu_time_s`; Exudyn = "
        "`time.process_time` around build, static pre-tension and dynamic solve (its "
        "dynamic solve alone in its own column). A ratio below 1 means ours is faster.",
        f"## CPU time, {t_end:g} s simulated", timing_table(result),
        "## Steps and iterations", steps_table(result),
        f"## Angular velocity of the driven pulley at t = {t_end:g} s [rad/s]",
        omega_table(result),
        "## Model differences", model_note(result),
        "## Settings", settings_lines(result),
        "## Machine", machine_lines(result),
    ]
    return "\n\n".join(parts) + "\n"


def write(result, out_dir: Path, stem: str) -> list:
    out_dir.mkdir(parents=True, exist_ok=True)
    md, js = out_dir / f"{stem}.md", out_dir / f"{stem}.json"
    js.write_text(json.dumps(result, indent=1) + "\n")
    md.write_text(render(result, js.name))
    return [md, js]


def main(argv=None) -> int:
    """``python -m benchmarks.peers_belt_report PEERS_BELT.json``: the Markdown again."""
    js = Path((sys.argv[1:] if argv is None else argv)[0])
    write(json.loads(js.read_text()), js.parent, js.stem)
    return 0


if __name__ == "__main__":
    sys.exit(main())
