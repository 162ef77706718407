"""Studies beyond the published tables: spurious modes, shear locking, convergence
toward the analytic references, the Omar-Shabana Model 2 investigation, timing."""
from __future__ import annotations

import platform
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
import scipy.linalg as sla  # noqa: E402

from analytic import timoshenko  # noqa: E402
from ancf.reports import published as pub  # noqa: E402
from ancf.reports.output import (markdown_table, progress, reference, run,  # noqa: E402
                                 save_figure, write_csv)
from ancf.elements.catalogue import ELEMENTS  # noqa: E402
from ancf.scenes import beam_static as bs  # noqa: E402

SCHEMES = tuple(ELEMENTS["linear"].schemes)  # the linear element's schemes


def _base(**kw):
    p = dict(element="linear", integration="thesis", n_elements=4, E=2.07e11, nu=0.0, L=2.0,
             h=0.1, b=0.1, ks=5.0 / 6.0)
    p.update(kw)
    return p


def zero_energy_modes(ns=(1, 2, 4, 8, 16, 32, 64), fractions=(0.25, 0.5, 0.75, 1.0)):
    """Spurious modes per scheme: (a) zero eigenvalues of the free-free tangent at the
    reference beyond the 3 rigid-body modes; (b) negative eigenvalues of the clamped
    Model 2 tangent at equilibria along the load path."""
    progress("spurious zero-energy modes (eigenvalues)")
    rows = []
    for integ in SCHEMES:
        for n in ns:
            mesh, q0, asm = bs.build(_base(integration=integ, n_elements=n, h=0.5))
            lam = sla.eigvalsh(asm.gradient_tangent(q0)[1].toarray())
            zero = int(np.sum(np.abs(lam) < 1e-10 * lam.max()))
            row = {"integration": integ, "n": n, "free-free zero modes": zero,
                   "spurious (beyond 3 rigid)": zero - 3}
            for f in fractions:
                out = run("cantilever", integration=integ, n_elements=n, h=0.5, nu=0.0,
                          F=-5e8 * 0.5**3 * f)
                r = out["results"]
                row[f"neg. eig. at {f:g} F"] = (r["negative_tangent_eigenvalues"]
                                               if r["tip_x"] is not None else "no conv.")
            rows.append(row)
    df = pd.DataFrame(rows)
    write_csv(df, "zero_energy_modes")
    return markdown_table(df), df


def shear_locking(slenderness=(20, 200, 2000), ns=(4, 16, 64)):
    """Small-load cantilever tip deflection / Timoshenko, exact vs thesis integration."""
    progress("shear locking: exact vs thesis integration")
    rows = []
    for s in slenderness:
        h = 2.0 / s
        p = _base(h=h, nu=0.3)
        # a load giving a linear-theory tip deflection of 1e-5 L (small deflection)
        unit = timoshenko.cantilever_tip_deflection(p["E"], 0.3, 2.0, h, 0.1, -1.0)
        F = 1e-5 * 2.0 / abs(unit) * -1.0
        ref = timoshenko.cantilever_tip_deflection(p["E"], 0.3, 2.0, h, 0.1, F)
        for integ in ("exact", "thesis"):
            row = {"L/h": s, "integration": integ}
            for n in ns:
                out = run("cantilever", integration=integ, n_elements=n, h=h, nu=0.3, F=F,
                          load_steps=1)
                row[f"n={n}: w/w_Timoshenko"] = (out["results"]["tip_y"] / ref
                                                 if out["converged"] else None)
            rows.append(row)
    df = pd.DataFrame(rows)
    write_csv(df, "shear_locking")
    return markdown_table(df, 4), df


def reissner_convergence(ns=(2, 4, 8, 16, 32, 64, 128, 256)):
    """Tip error vs the Reissner reference for Models 1 and 2; log-log plot."""
    progress("convergence toward the Reissner reference")
    rows = []
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, (name, model, b188) in zip(axes, (("Model 1", pub.MODEL_1, pub.THESIS_2_3),
                                              ("Model 2", pub.MODEL_2, pub.THESIS_2_4))):
        ref = reference("reissner", **model)["results"]
        series = {}
        for label, el, integ in (("linear (thesis)", "linear", "thesis"),
                                 ("linear (report-fix)", "linear", "report-fix"),
                                 ("Omar–Shabana", "omar-shabana", "thesis")):
            errs = []
            for n in ns:
                out = run("cantilever", element=el, integration=integ, n_elements=n, **model)
                r = out["results"]
                err = (np.hypot(r["tip_x"] - ref["tip_x"], r["tip_y"] - ref["tip_y"])
                       if out["converged"] else np.nan)
                errs.append(err)
                rows.append({"model": name, "element": label, "n": n, "tip_x": r["tip_x"],
                             "tip_y": r["tip_y"], "error_m": err, "timing: cpu_time_s": out["cpu_time_s"]})
            series[label] = errs
        b = [np.hypot(v[2][0] - ref["tip_x"], v[2][1] - ref["tip_y"]) for v in b188["rows"].values()]
        for n, e in zip(pub.N, b):
            rows.append({"model": name, "element": "BEAM188 (published)", "n": n,
                         "tip_x": b188["rows"][n][2][0], "tip_y": b188["rows"][n][2][1],
                         "error_m": e, "timing: cpu_time_s": None})
        for label, errs in series.items():
            ax.loglog(ns, errs, "o-", label=label)
        fine = run("cantilever", n_elements=1024, **model)["results"]
        self_err = []
        for n in ns:
            r = run("cantilever", n_elements=n, **model)["results"]
            self_err.append(np.hypot(r["tip_x"] - fine["tip_x"], r["tip_y"] - fine["tip_y"]))
            rows.append({"model": name, "element": "linear (thesis) vs itself at n=1024", "n": n,
                         "tip_x": r["tip_x"], "tip_y": r["tip_y"], "error_m": self_err[-1],
                         "timing: cpu_time_s": None})
        ax.loglog(ns, self_err, "b:", marker=".", label="linear (thesis) vs itself, n = 1024")
        ax.loglog(pub.N, b, "k^--", label="ANSYS BEAM188 (published)")
        ax.set(title=f"{name}: |tip − Reissner|", xlabel="number of elements", ylabel="error [m]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    save_figure(fig, "cantilever_convergence")
    df = pd.DataFrame(rows)
    write_csv(df, "cantilever_convergence")
    return df


def reissner_vs_beam188():
    rows = []
    for name, model, b188 in (("Model 1", pub.MODEL_1, pub.THESIS_2_3[("rows")][64][2]),
                              ("Model 2", pub.MODEL_2, pub.THESIS_2_4["rows"][64][2])):
        ref = reference("reissner", **model)["results"]
        lin = run("cantilever", n_elements=256, **model)["results"]
        rows.append({"model": name, "Reissner tip_x": ref["tip_x"], "Reissner tip_y": ref["tip_y"],
                     "BEAM188 64 el. (pub)": f"{b188[0]:.5f}, {b188[1]:.5f}",
                     "BEAM188 − Reissner (x, y)": f"{b188[0] - ref['tip_x']:+.1e}, {b188[1] - ref['tip_y']:+.1e}",
                     "linear 256 el.": f"{lin['tip_x']:.5f}, {lin['tip_y']:.5f}",
                     "linear − Reissner (x, y)": f"{lin['tip_x'] - ref['tip_x']:+.1e}, {lin['tip_y'] - ref['tip_y']:+.1e}"})
    df = pd.DataFrame(rows)
    write_csv(df, "reissner_vs_beam188")
    return markdown_table(df, 7), df


def simply_supported_convergence(ns=(2, 4, 8, 16, 32, 64, 128)):
    progress("simply supported convergence plot")
    fig, ax = plt.subplots(figsize=(6, 4.2))
    rows = []
    for nu in (0.0, 0.3):
        ref = reference("timoshenko", nu=nu)["results"]["mid_deflection_m"]
        for el in ("linear", "omar-shabana"):
            errs = []
            for n in ns:
                w = run("simply-supported", element=el, n_elements=n, nu=nu)["results"]["mid_deflection_m"]
                errs.append(abs(w - ref) / abs(ref))
                rows.append({"nu": nu, "element": el, "n": n, "mid_deflection_m": w,
                             "rel_error_vs_timoshenko": errs[-1]})
            ax.loglog(ns, errs, "o-" if el == "linear" else "s--", label=f"{el}, ν = {nu}")
    ax.set(title="Simply supported beam: |w − w_Timoshenko| / |w_Timoshenko|",
           xlabel="number of elements", ylabel="relative error")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    save_figure(fig, "simply_supported_convergence")
    df = pd.DataFrame(rows)
    write_csv(df, "simply_supported_convergence")
    return df


def omar_shabana_setting_scan(clamps=("free", "fixed"),
                              schemes=("thesis", "all=3xe", "all=4x2", "all=3x2")):
    """Which Omar-Shabana setting produced each published cantilever column?  Returns
    (largest tip-coordinate difference in m per clamp of dr/dx x integration scheme and
    published column over n = 2...64, the per-cell differences).  Report Table 3 is taken
    without its n = 4 x cell, a transcription error."""
    progress("Omar-Shabana cantilever columns: clamp x integration scan")
    columns = (("thesis 2.3", pub.THESIS_2_3), ("thesis 2.4", pub.THESIS_2_4),
               ("report 3", pub.REPORT_3), ("report 4/5", pub.REPORT_4))
    cells = pd.DataFrame([
        {"clamp_x_slope": clamp, "integration": spec, "column": label, "n": n,
         "diff_m": _os_cell_diff(table, n, clamp, spec, skip_x=(label == "report 3" and n == 4))}
        for clamp in clamps for spec in schemes for label, table in columns for n in pub.N])
    write_csv(cells, "omar_shabana_setting_scan")
    worst = cells.pivot_table(index=["clamp_x_slope", "integration"], columns="column",
                              values="diff_m", aggfunc="max", sort=False)
    return worst[[label for label, _ in columns]].reset_index(), cells


def _os_cell_diff(table, n, clamp, spec, skip_x=False):
    out = run("cantilever", element="omar-shabana", integration=spec, n_elements=n,
              clamp_x_slope=clamp, **table["model"])
    if not out["converged"]:
        return float("inf")
    p, r = table["rows"][n][0], out["results"]
    return max(0.0 if skip_x else abs(p[0] - r["tip_x"]), abs(p[1] - r["tip_y"]))


def newton_iteration_time_ratio(n=16, repeats=30):
    """Time of one Newton iteration as the static solver does it (one compiled assembly of
    gradient and band tangent, band LU and solve), linear / Omar-Shabana, measured side by
    side (interleaved) in one run; median over repeats."""
    progress("timing: Newton iteration, linear vs Omar-Shabana")
    from ancf.core.constraints import Elimination
    from ancf.core.pattern import ReducedPattern
    from ancf.elements.green2d import assemble_band
    from ancf.solvers.linear import factor
    times = {}
    setups = {}
    for el in ("linear", "omar-shabana"):
        mesh, q0, asm = bs.build(_base(element=el, n_elements=n))
        elim = Elimination(mesh.n_dofs)
        for slot in ("r", "r_y"):
            for k in (0, 1):
                elim.fix(mesh.dof(0, slot, k), q0[mesh.dof(0, slot, k)])
        T, g0, _ = elim.build()
        pat = ReducedPattern(asm.n_dofs, [asm.groups[0].dofmap], T)
        rng = np.random.default_rng(0)
        z = pat.restrict(q0 + 1e-3 * rng.standard_normal(q0.size))
        setups[el] = (pat, pat.compiled(asm), g0, z)
        times[el] = []
    for _ in range(repeats):
        for el, (pat, mdl, g0, z) in setups.items():
            t0 = time.perf_counter()
            grad, K = np.zeros(pat.n), pat.zeros_matrix()
            assemble_band(mdl, z, g0, True, grad, K)
            factor(pat, K, overwrite=True).solve(grad)
            times[el].append(time.perf_counter() - t0)
    med = {el: float(np.median(v)) for el, v in times.items()}
    return {"n_elements": n, "linear_s": med["linear"], "omar_shabana_s": med["omar-shabana"],
            "ratio": med["linear"] / med["omar-shabana"], "machine": machine()}


def machine() -> str:
    import os

    from ancf.common.machine import cpu_model
    cpu = cpu_model()
    return (f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}, "
            f"Python {platform.python_version()}, numpy {np.__version__}")


def reissner_gap_vs_load(fractions=(1e-3, 0.01, 0.1, 0.3, 1.0), ns=(64, 256)):
    """Linear element vs Reissner as the load grows: a discretisation error shrinks with
    n at every load; a constitutive (strain-measure) difference does not, and grows
    with the strain.  Root bending strain = |F| tip_x h / (2 E I)."""
    progress("Reissner gap vs load level")
    rows = []
    for name, model in (("Model 1", pub.MODEL_1), ("Model 2", pub.MODEL_2)):
        h, F0 = model["h"], -5e8 * model["h"] ** 3
        for f in fractions:
            ref = reference("reissner", F=F0 * f, **model)["results"]
            defl = np.hypot(ref["tip_x"] - 2.0, ref["tip_y"])
            EI = 2.07e11 * 0.1 * h**3 / 12
            row = {"model": name, "load fraction": f,
                   "root bending strain": abs(F0 * f) * ref["tip_x"] * h / (2 * EI)}
            for n in ns:
                r = run("cantilever", n_elements=n, F=F0 * f, load_steps=max(1, int(10 * f)),
                        **model)["results"]
                row[f"|tip − Reissner| / deflection, n={n}"] = (
                    np.hypot(r["tip_x"] - ref["tip_x"], r["tip_y"] - ref["tip_y"]) / defl)
            rows.append(row)
    df = pd.DataFrame(rows)
    write_csv(df, "reissner_gap_vs_load")
    return markdown_table(df, 3), df
