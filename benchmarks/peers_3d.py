"""The shared 3D cases side by side with Exudyn in one run: the Princeton beam and the 3D
cantilever (our ``linear3d`` against Exudyn's ``ObjectANCFBeam``), the simply supported
thin plate's statics and modes (our ``plate36`` against ``ObjectANCFThinPlate``).

    python -m benchmarks.peers_3d [--repeats 5] [--out reports/benchmarks]

Ours: the scenes ``princeton-beam`` and ``beam3d-cantilever`` (``ancf run``), the plate's
nonlinear equilibrium under its pressure (``plate-square``'s ``equilibrium``, the state
``ancf modes --about equilibrium`` finds: the problem Exudyn's static solver solves; the
scene's linear solve is recorded beside it) and ``ancf modes plate-square --count 6``;
``cpu_s`` is the scene's ``cpu_time_s`` (numba compilation excluded).  Exudyn:
:mod:`benchmarks.peers_3d_exudyn`, ``cpu_s`` around its solve call only.

Measurement as in :mod:`benchmarks.peers_ale`: every run a fresh process with one BLAS
thread and OPENBLAS_CORETYPE / OPENBLAS_L2_SIZE unset, ``time.process_time`` in the child;
one untimed warm-up per side and case, then ``--repeats`` rounds alternating ours,
Exudyn; medians compared, ``ratio`` = ours / Exudyn, ``ratio_paired`` per round.

Writes ``peers_3d.json`` (keys ``schema``, ``started``, ``command``, ``machine``,
``settings``, ``workers`` (versions), ``cases``: rows ``{case, n, angle_deg, label,
ours, exudyn, ratio, ratio_paired, agreement}``; ``agreement`` per quantity: ``ours``,
``exudyn``, ``reference``, ``relative`` = (ours - Exudyn) / |Exudyn| and the errors of
both against the reference) and ``peers_3d.md`` beside it.
"""
from __future__ import annotations

import argparse
import json
import math
import statistics
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

from benchmarks import peers
from benchmarks import peers_3d_exudyn as px

#: (case, n, load angle in degrees) of the race
PLAN = (("princeton", 16, 0.0), ("princeton", 8, 45.0), ("princeton", 16, 45.0),
        ("princeton", 32, 45.0), ("cantilever3d", 8, 0.0), ("cantilever3d", 32, 0.0),
        ("cantilever3d", 16, 30.0), ("plate-static", 8, 0.0), ("plate-static", 16, 0.0),
        ("plate-modes", 8, 0.0), ("plate-modes", 16, 0.0))
SCENE = {"princeton": "princeton-beam", "cantilever3d": "beam3d-cantilever",
         "plate-static": "plate-square", "plate-modes": "plate-square"}
LABEL = {"princeton": "Princeton beam, F2, static, 10 load steps",
         "cantilever3d": "3D cantilever Model 1, static, 10 load steps",
         "plate-static": "simply supported plate, pressure, nonlinear static",
         "plate-modes": f"simply supported plate, lowest {px.MODE_COUNT} frequencies"}
BEAM_STATS = ("newton_iterations", "tangent_evaluations", "factorizations", "load_steps_taken")


def ours_child(case: str, n: int, angle: float) -> dict:
    """One run of ours in this process (see the module docstring)."""
    from ancf.scenes import SCENES, modes
    if case in ("princeton", "cantilever3d"):
        out, _ = SCENES[SCENE[case]].execute({"n_elements": str(n),
                                              "load_angle_deg": str(angle)})
        r = out["results"] or {}
        return {"cpu_s": out["cpu_time_s"], "converged": out["converged"],
                "params": out["params"], **{k: r.get(k) for k in ("tip_x", "tip_y", "tip_z")},
                **{k: r[k] for k in BEAM_STATS if r.get(k) is not None}}
    over = {"n_elements": str(n), "rho": str(px.PLATE["rho"])}
    if case == "plate-modes":
        out, _ = modes.execute("plate-square", over, count=px.MODE_COUNT)
        r = out["results"] or {}
        return {"cpu_s": out["cpu_time_s"], "converged": out["converged"],
                "params": out["params"], "frequencies_hz": r.get("frequencies_hz"),
                "reduced_size": r.get("reduced_size")}
    lin, _ = SCENES["plate-square"].execute({"n_elements": str(n)})
    sc = modes.modal_scene("plate-square")
    out, _ = replace(sc, run=sc.equilibrium).execute(over)
    r = out["results"] or {}
    return {"cpu_s": out["cpu_time_s"], "converged": out["converged"], "params": out["params"],
            "center_deflection_m": r.get("center_deflection_m"),
            "newton_iterations": r.get("newton_iterations"), "linear_cpu_s": lin["cpu_time_s"],
            "linear_center_deflection_m": lin["results"]["center_deflection_m"]}


def _child(cmd: list, env: dict) -> dict:
    proc = subprocess.run([sys.executable, "-m", *cmd], capture_output=True, text=True,
                          env=env, cwd=peers.ROOT)
    if proc.returncode != 0:
        return {"error": proc.stderr.strip().splitlines()[-3:], "exit": proc.returncode}
    return json.loads(proc.stdout.strip().splitlines()[-1])


def commands(case: str, n: int, angle: float) -> dict:
    args = [case, str(n), f"{angle:g}"]
    return {"ours": ["benchmarks.peers_3d", "--ours-child", *args],
            "exudyn": ["benchmarks.peers_3d_exudyn", *args]}


def relative(a, b):
    """(a - b) / |b|; None where either is missing or b is zero."""
    return None if a is None or b is None or b == 0 else (a - b) / abs(b)


def mismatches(ours: dict, theirs: dict, rel: float = 1e-12) -> list:
    """The names of ``theirs`` whose values differ from ``ours``' beyond ``rel``."""
    return [k for k, v in theirs.items()
            if not math.isclose(float(ours[k]), float(v), rel_tol=rel, abs_tol=0.0)]


def expected(case: str) -> dict:
    """The parameters Exudyn's side builds with, in our scenes' names."""
    if case in ("princeton", "cantilever3d"):
        P = px.PRINCETON if case == "princeton" else px.CANTILEVER3D
        return P | {"ks": px.torsion_ks(P["h"], P["b"]) if case == "princeton" else P["ks"]}
    return px.PLATE if case == "plate-modes" else {k: v for k, v in px.PLATE.items()
                                                  if k != "rho"}


def tip_difference(o: dict, e: dict, L: float) -> float | None:
    """|tip_ours - tip_exudyn| / |tip_exudyn - (L, 0, 0)| (relative to the displacement)."""
    keys = ("tip_x", "tip_y", "tip_z")
    if any(o.get(k) is None or e.get(k) is None for k in keys):
        return None
    eu = (e["tip_x"] - L, e["tip_y"], e["tip_z"])
    return math.dist([o[k] for k in keys], [e[k] for k in keys]) / math.hypot(*eu)


def references(case: str, p: dict) -> tuple:
    """(reference name, values, error function (results, values) -> float)."""
    from ancf.scenes import SCENES
    if case == "plate-modes":
        from analytic.plate_modes import navier_frequencies
        f = navier_frequencies(p["a"], p["a"], p["h"], p["E"], p["nu"], p["rho"],
                               px.MODE_COUNT)[0]
        return "Navier", {"frequencies_hz": [float(x) for x in f]}, None
    spec = SCENES[SCENE[case]].study()
    ref = spec.reference()
    name = {"princeton": "ANSYS beam (published)", "cantilever3d": "Reissner rod",
            "plate-static": "Navier (linear Kirchhoff)"}[case]
    return name, ref.values(p), lambda r: ref.error(r, ref.values(p), p)


def agreement(case: str, o: dict, e: dict) -> dict:
    """Per quantity: ours, Exudyn's, the reference and the relative differences."""
    p = o.get("params") or {}
    name, ref, err = references(case, p)
    if case == "plate-modes":
        out = {f"f{i + 1}_hz": {"ours": a, "exudyn": b, "reference": c,
                                "relative": relative(a, b), "ours_vs_ref": relative(a, c),
                                "exudyn_vs_ref": relative(b, c)}
               for i, (a, b, c) in enumerate(zip(o.get("frequencies_hz") or [],
                                                 e.get("frequencies_hz") or [],
                                                 ref["frequencies_hz"]))}
        return {"reference": name, "quantities": out}
    keys = ("center_deflection_m",) if case == "plate-static" else ("tip_x", "tip_y", "tip_z")
    out = {k: {"ours": o.get(k), "exudyn": e.get(k), "reference": ref.get(k),
               "relative": relative(o.get(k), e.get(k))} for k in keys}
    ok = o.get("converged") and e.get("converged")
    errs = {"ours_error": err(o) if ok else None, "exudyn_error": err(e) if ok else None}
    if case != "plate-static":
        errs["tip_difference"] = tip_difference(o, e, p["L"])
    else:
        errs["linear_vs_exudyn"] = relative(o.get("linear_center_deflection_m"),
                                            e.get("center_deflection_m"))
    return {"reference": name, "quantities": out, **errs}


def _median(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def race_case(case: str, n: int, angle: float, repeats: int, env: dict) -> dict:
    """Warm-up per side, then ``repeats`` rounds alternating ours, Exudyn."""
    cmds = commands(case, n, angle)
    runs = {s: [] for s in peers.SIDES}
    for r in range(repeats + 1):
        for s in peers.SIDES:
            ans = _child(cmds[s], env)
            if r or "error" in ans:
                runs[s].append(ans)
    sides = {}
    for s in peers.SIDES:
        samples = [a.get("cpu_s") for a in runs[s]]
        sides[s] = runs[s][-1] | {"cpu_s": _median(samples), "cpu_s_samples": samples}
    pairs = zip(sides["ours"]["cpu_s_samples"], sides["exudyn"]["cpu_s_samples"])
    row = {"case": case, "n": n, "angle_deg": angle, "label": LABEL[case], **sides,
           "ratio": peers._ratio(sides["ours"]["cpu_s"], sides["exudyn"]["cpu_s"]),
           "ratio_paired": [a / b for a, b in pairs if a is not None and b]}
    if "params" in sides["ours"]:
        row["parameter_mismatches"] = mismatches(sides["ours"]["params"], expected(case))
        row["agreement"] = agreement(case, sides["ours"], sides["exudyn"])
    return row


def _fmt(v, f="{:.4g}") -> str:
    return "–" if v is None else f.format(v)


def _pct(v) -> str:
    return "–" if v is None else f"{100 * v:+.3g} %"


def _cells(row: dict) -> tuple:
    """(ours result, Exudyn result, ours - Exudyn, ours vs reference, Exudyn vs reference)."""
    a, o, e = row.get("agreement") or {}, row["ours"], row["exudyn"]
    q = a.get("quantities") or {}
    if row["case"] == "plate-modes":
        f = [q[k] for k in sorted(q)]
        worst = max((abs(x["relative"]) for x in f if x["relative"] is not None), default=None)
        return ("f1 " + _fmt(f[0]["ours"] if f else None, "{:.6g}") + " Hz",
                "f1 " + _fmt(f[0]["exudyn"] if f else None, "{:.6g}") + " Hz",
                "max " + _pct(worst), _pct(f[0]["ours_vs_ref"] if f else None),
                _pct(f[0]["exudyn_vs_ref"] if f else None))
    if row["case"] == "plate-static":
        w = q.get("center_deflection_m", {})
        return (f"w {_fmt(w.get('ours'), '{:.6g}')} m", f"w {_fmt(w.get('exudyn'), '{:.6g}')} m",
                _pct(w.get("relative")), _pct(a.get("ours_error")), _pct(a.get("exudyn_error")))
    tip = [f"{_fmt(o.get(k), '{:.5g}')}" for k in ("tip_x", "tip_y", "tip_z")]
    tipe = [f"{_fmt(e.get(k), '{:.5g}')}" for k in ("tip_x", "tip_y", "tip_z")]
    return ("(" + ", ".join(tip) + ")", "(" + ", ".join(tipe) + ")",
            _pct(a.get("tip_difference")), _pct(a.get("ours_error")), _pct(a.get("exudyn_error")))


def markdown(res: dict) -> str:
    """The report of :func:`main`'s result."""
    lines = ["# Shared 3D cases: ours against Exudyn", "",
             f"Generated by `{res['command']}` on {res['started']}; raw numbers in "
             "`peers_3d.json`; do not edit by hand.  Every run a fresh process, one BLAS "
             f"thread, {res['repeats']} rounds alternating ours and Exudyn after one warm-up, "
             "medians; CPU of the solve (`time.process_time` in the child).  Timing varies "
             "run to run.", "",
             "| case | n | angle | ours CPU, s | Exudyn CPU, s | ours / Exudyn (paired "
             "range) | ours | Exudyn | ours vs Exudyn | ours vs ref | Exudyn vs ref |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in res["cases"]:
        pr = r["ratio_paired"]
        span = f" ({min(pr):.3g}-{max(pr):.3g})" if pr else ""
        lines.append(f"| {r['case']} | {r['n']} | {r['angle_deg']:g} | "
                     f"{_fmt(r['ours']['cpu_s'])} | {_fmt(r['exudyn']['cpu_s'])} | "
                     f"{_fmt(r['ratio'], '{:.3g}')}{span} | " + " | ".join(_cells(r)) + " |")
    lines += ["", "Beams: tip position (x, y, z) in m; *ours vs Exudyn* = |Δtip| / |Exudyn's "
              "tip displacement|; errors against the reference as the scenes define them "
              "(Princeton: |Δ(y, z)| / |(y, z)_ref|, ANSYS beam elements; 3D cantilever: "
              "|Δtip| / |tip_ref - (L, 0, 0)|, Reissner rod).  Plate statics: centre "
              "deflection, reference Navier's linear series.  Plate modes: f1 shown, "
              "*ours vs Exudyn* the largest relative difference over the six, reference "
              "Navier's frequencies.", ""]
    lines += _details(res)
    lines += ["", "## Settings", ""] + [f"- **{k}**: {v}" for k, v in res["settings"].items()]
    lines += ["", "## Machine", ""] + [f"- **{k}**: {v}" for k, v in res["machine"].items()]
    return "\n".join(lines) + "\n"


def _details(res: dict) -> list:
    out = ["## Details", ""]
    for r in res["cases"]:
        o, e = r["ours"], r["exudyn"]
        bad = r.get("parameter_mismatches")
        note = f"; parameter mismatches: {bad}" if bad else ""
        extra = ""
        if r["case"] == "plate-static":
            w = _fmt(o.get("linear_center_deflection_m"), "{:.6g}")
            diff = _pct(r["agreement"].get("linear_vs_exudyn"))
            extra = (f"; ours linear solve: w {w} m, CPU {_fmt(o.get('linear_cpu_s'))} s, "
                     f"vs Exudyn {diff}")
        out.append(f"- {r['case']} n = {r['n']}, {r['angle_deg']:g}°: converged ours "
                   f"{o.get('converged')}, Exudyn {e.get('converged')}; Newton iterations "
                   f"ours {o.get('newton_iterations', '–')}, Exudyn "
                   f"{e.get('newton_iterations', '–')}; Exudyn build CPU "
                   f"{_fmt(e.get('cpu_build_s'))} s{extra}{note}")
    return out


SETTINGS = {
    "ours": "scenes princeton-beam / beam3d-cantilever defaults (element linear3d, thesis "
            "integration, 10 initial load steps (adaptive), Newton rtol 1e-8, ks: Princeton "
            "J/(I_y + I_z), cantilever 5/6); plate-square (plate36, 4 x 4 Gauss points): "
            "nonlinear equilibrium with the default Newton options, modes about the "
            "reference, rho 7850 kg/m^3",
    "exudyn": "benchmarks/peers_3d_exudyn.py: ObjectANCFBeam (structural section "
              "stiffness diag(EA, ks GA, ks GA, ks G(I_y+I_z), EI_y, EI_z), "
              "crossSectionPenaltyFactor 1), static solver 10 load steps, full Newton "
              "relativeTolerance 1e-8; ObjectANCFThinPlate (plane-stress coefficients, full "
              "Gauss rule), CoordinateConstraints, static solver 1 load step; "
              "ComputeODE2Eigenvalues (sparse, constrainedCoordinates); EigenSparse",
    "element_match": "beams differ: our linear3d is a continuum element (Green strains, "
                     "Kerkkänen's 3D linear beam), ObjectANCFBeam a structural one with "
                     "the same nodal coordinates (r, r_y, r_z); plates: the same "
                     "36-coordinate thin plate (r, r_x, r_y per node, Kirchhoff bending)",
}


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if argv[:1] == ["--ours-child"]:
        print(json.dumps(ours_child(argv[1], int(argv[2]), float(argv[3]))))
        return 0
    ap = argparse.ArgumentParser(prog="python -m benchmarks.peers_3d",
                                 description=__doc__.split("\n")[0])
    ap.add_argument("--repeats", type=int, default=5, help="timed rounds per case")
    ap.add_argument("--out", type=Path, default=peers.DEFAULT_OUT, help="output folder")
    args = ap.parse_args(argv)
    if args.repeats < 1:
        raise ValueError(f"--repeats = {args.repeats}; allowed: an integer >= 1")
    if peers.exudyn_missing():
        print("peers_3d: exudyn is not installed (pip install -e .[peers]); skipped")
        return 0
    env = peers.worker_env()
    res = peers.record("peers_3d", argv, SETTINGS | {
        "worker_env": peers.THREAD_ENV, "unset": peers.UNSET_ENV}, repeats=args.repeats)
    res["cases"] = [race_case(c, n, a, args.repeats, env) for c, n, a in PLAN]
    res["workers"] = {"exudyn": res["cases"][0]["exudyn"].get("exudyn")}
    peers.write(args.out, "peers_3d", res, markdown(res))
    print(f"peers_3d: wrote {args.out}/peers_3d.json/.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
