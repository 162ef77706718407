"""Project Chrono's ANCF elements (issue 35, item 5): ``chrono_elements_chapter() ->
(markdown, status)``.  Every number comes from :mod:`ancf.checks.chrono_matrices` (Chrono's
stored element matrices), :mod:`ancf.checks.chrono_elements` (Chrono's static cases, the
square plate), :mod:`ancf.checks.chrono_princeton` (the Princeton beam) and
:mod:`ancf.checks.chrono_locking` (why the beams' u_z and the 3443's f4-f6 miss at the
acceptance mesh), :mod:`ancf.checks.chrono_shell3423` and :mod:`ancf.checks.chrono_cable`
(Chrono's stored time histories); the checks are pinned by
``tests/reports/test_chrono_elements_chapter.py`` and ``tests/checks/test_chrono_locking.py``.
"""
from __future__ import annotations

import pandas as pd

from ancf.checks import chrono_cable as ccb
from ancf.checks import chrono_elements as ce
from ancf.checks import chrono_locking as cl
from ancf.checks import chrono_matrices as cm
from ancf.checks import chrono_princeton as cp
from ancf.checks import chrono_shell3423 as c34
from ancf.reports.chapter import Chapter
from ancf.reports.output import (checks_section, markdown_table, progress, save_figure,
                                 settings, write_csv)
from ancf.study.extremes import QUICK_SKIPPED

TIMING = "timing: CPU s"


def _pct(e) -> str:
    """A signed relative error in per cent, 3 significant digits (— where none)."""
    return "—" if e is None else f"{100.0 * e:+.3g} %"


#: below these a value is round-off, whose last digits vary per run: printed as "< floor"
ROUND_OFF = {"matrix": 1e-13, "angle": 1e-9, "displacement": 1e-12}   # -, deg, m


def _floor(x, kind: str):
    """x, or "< floor" where x is round-off (:data:`ROUND_OFF`)."""
    return f"< {ROUND_OFF[kind]:g}" if x is not None and abs(x) < ROUND_OFF[kind] else x


def _verdict(within) -> str:
    return "—" if within is None else "pass" if within else "miss"


def _matrices_section() -> list:
    df = pd.DataFrame(cm.table())
    df["within"] = (df["difference"] <= df["bound"]).map(_verdict)
    df["difference"] = df["difference"].map(lambda x: _floor(x, "matrix"))
    write_csv(df, "chrono_elements_matrices")
    return [
        "## Chrono's stored element matrices\n",
        "Each file of `tests/data/chrono/` (Chrono's unit-test output, commit and licence in "
        "its README) against our element at the same parameters and state (L = 1 m, 0.1 m "
        "× 0.1 m beams; 1 m × 1 m × 0.01 m shells; the unit cube brick; ρ = 7850 kg/m³, E = "
        "210 GPa, ν = 0.3; one node's z moved by 1 mm or driven at 1 mm/s, α = 0.01 s). "
        "Difference = max|ours − Chrono| / max|Chrono| (for the scaled coordinates of the "
        "shells also on the scaled entries; K and R of a damped Jacobian each on its own); "
        "bound: the acceptance tolerance of `tests/elements/test_chrono_elements.py` (mass "
        f"and gravity {cm.RTOL_MASS:g}, forces {cm.RTOL_FORCE:g}, Jacobians "
        f"{cm.RTOL_JAC:g}); differences below {ROUND_OFF['matrix']:g} (round-off) are "
        "printed as such. Every file agrees to round-off: the elements compute Chrono's "
        "matrices, not approximations of them.\n",
        markdown_table(df, 3), ""]


def _passed(rows: list) -> str:
    bad = [f"{r['element']} {r['case']}" for r in rows if not r["passed"]]
    return "Every case passes." if not bad else f"Outside Chrono's bounds: {', '.join(bad)}."


def _span(rows: list, elements: tuple, cases: tuple) -> str:
    """'a to b' of the errors of the given elements and cases, in per cent."""
    errs = [r["error"] for r in rows if r["element"] in elements and r["case"] in cases]
    return f"{_pct(min(errs))} to {_pct(max(errs))}"


def _static_section(rows: list) -> list:
    df = pd.DataFrame([{"element": r["element"], "case": r["case"], "ours": r["ours"],
                        "textbook": r["textbook"], "error": _pct(r["error"]),
                        "Chrono's tolerance": f"{100 * r['tolerance']:g} %",
                        "off-axis angle [°]": _floor(r["off-axis [deg]"], "angle"),
                        "angle bound [°]": r["angle bound [deg]"],
                        "status": _verdict(r["passed"])} for r in rows])
    write_csv(df, "chrono_elements_static")
    return [
        "## Chrono's textbook static cases\n",
        "Chrono's own small-deflection checks (`utest_FEA_ANCF*_Formulation.cpp`), solved "
        "by our models (`ancf/models/chrono_beam.py`, `chrono_continuum.py`, "
        "`chrono_shell.py`; Newton, where Chrono takes one linear step): 20 elements along "
        "a 20 in aluminium strip (E = 71.7 GPa, ν = 0.33), clamped, loaded at the tip. Axial "
        "pull u_x = P L/(A E), tip load u_z = P L³/(3 E I), gravity u_z = ρ A g L⁴/(8 E I) "
        "(m), "
        "tip twist θ = M L/(G J) (rad; J = 2.25 (a/2)⁴ for the square beam and brick, "
        "0.281 w h³ for the shell strip); P = M = 10 (beams, brick) or 1 (shells). Error = "
        "ours / textbook − 1; tolerances and the bound on the off-axis Cardan angles are "
        f"Chrono's own, per element and case. {_passed(rows)} The wide tolerances (brick "
        "5 %, 3443 15 %, shell twist 15 %) are Chrono's allowance for what the elements "
        f"miss: the 3443 strip is {_span(rows, ('3443',), ('tip', 'gravity'))} in bending, "
        f"the brick {_span(rows, ('3843',), ('tip', 'gravity'))}, the shells "
        f"{_span(rows, ('3443', '3833'), ('twist',))} in twist.\n",
        markdown_table(df, 4), ""]


def _count(rows: list, c: str) -> str:
    """'k of m pass' for the component c ("uy", "uz") of the rows, with the errors' span."""
    compared = [r for r in rows if r[f"{c} within"] is not None]
    errs = [r[f"{c} error"] for r in compared]
    return (f"{sum(r[f'{c} within'] for r in compared)} of {len(compared)} pass (errors "
            f"{_pct(min(errs))} to {_pct(max(errs))})")


def _rule_table(rows: list, reduced: list) -> pd.DataFrame:
    """The Princeton beam per element and axial Gauss rule: mechanisms and worst errors."""
    coarse = [r for r in rows if r["n"] == cp.N_ELEMENTS]
    return pd.DataFrame([{
        "element": s["element"],
        "Gauss points along the axis": "exact (5)" if s["naxis"] is None else s["naxis"],
        "zero-energy modes of K(e0)": s["zero-energy modes"],
        "worst error u_y": _pct(s["uy worst"]),
        "u_y within 1 %": f"{s['uy passed']} of {s['uy compared']}",
        "worst error u_z": _pct(s["uz worst"]),
        "u_z within 0.5 %": f"{s['uz passed']} of {s['uz compared']}"}
        for s in cl.princeton_summary(coarse + reduced)])


def _princeton_section(rows: list) -> list:
    df = pd.DataFrame([{"element": r["element"], "elements": r["n"], "load": r["load"],
                        "β [°]": r["beta"], "u_y [m]": _floor(r["uy"], "displacement"),
                        "ANSYS u_y [m]": r["ansys uy"],
                        "error u_y": _pct(r["uy error"]), "u_y": _verdict(r["uy within"]),
                        "u_z [m]": _floor(r["uz"], "displacement"), "ANSYS u_z [m]": r["ansys uz"],
                        "error u_z": _pct(r["uz error"]), "u_z": _verdict(r["uz within"]),
                        "Newton iterations": r["iterations"],
                        TIMING: round(r["cpu s"], 2)} for r in rows])
    write_csv(df, "chrono_elements_princeton")
    coarse = [r for r in rows if r["n"] == cp.N_ELEMENTS]
    fine = [r for r in rows if r["n"] == ce.PRINCETON_FINE]
    return [
        "## The Princeton beam against ANSYS\n",
        "The clamped strip of Dowell et al. (`ancf/checks/chrono_princeton.py`; problem as "
        "in `beam3d_benchmarks.md`) on the 3243 and 3333 with k₁ = k₂ = J/(I_y + I_z) and "
        f"Chrono's Poisson split, {cp.N_ELEMENTS} elements, {cp.LOAD_STEPS} load steps; "
        "reference: the ANSYS beam elements; magnitudes of the tip displacement compared. "
        "Tolerance (as "
        f"`tests/checks/test_chrono_princeton.py`): |u_y| within "
        f"{100 * ce.PRINCETON_TOL['uy']:g} %, |u_z| within {100 * ce.PRINCETON_TOL['uz']:g} "
        f"% (— where ANSYS is 0 by symmetry). u_y: {_count(coarse, 'uy')}. u_z: "
        f"{_count(coarse, 'uz')}; the misses are all too small (the element too stiff), "
        "growing with the load and the angle, i.e. with the curvature of the thin strip "
        "bent about its weak axis. They fall steeply with the mesh: the misses at "
        f"{ce.PRINCETON_FINE_BETA:g}° repeated at {ce.PRINCETON_FINE} elements (last rows): "
        f"{_count(fine, 'uz')}: the finer meshes converge on ANSYS, so the misses are the "
        "elements' discretisation error, not a difference of reference or load; nor of the "
        "material (the small-load tip is within 0.1 % of Timoshenko's, k_s = 5/6 moves it "
        "by 0.02 %, without the Poisson split u_z is 23 % low).\n",
        markdown_table(df, 4, "Princeton beam on the 3243 and 3333"), ""]


def _beam_locking_section(rows: list, reduced: list) -> list:
    rules = _rule_table(rows, reduced)
    write_csv(rules, "chrono_elements_princeton_rules")
    summary = {s["element"]: s for s in cl.princeton_summary(reduced)}
    b43, b33 = summary["3243"], summary["3333"]
    return [
        "### Why u_z misses at 16 elements: locking of the interpolation\n",
        f"The same {cp.N_ELEMENTS}-element runs with the Gauss rule along the axis cut from "
        f"the exact 5 points to {cl.REDUCED_AXIS}, Chrono's smallest (its headers: fewer "
        "\"will likely result in numerical issues\"; Chrono's own 3 points give the exact "
        "rule's u_z), `ancf/checks/chrono_locking.py`: every u_z is then within 0.5 % "
        f"(3243 worst {_pct(b43['uz worst'])}, 3333 {_pct(b33['uz worst'])}). The inexact "
        "rule frees the strain energy that the interpolation cannot avoid under large "
        "rotation: the stretch of the bent axis (membrane locking of the 3333's quadratic "
        "axis; `tests/checks/test_chrono_locking.py` reduces each part alone) and the "
        "thickness strain of the 3243's section gradients, interpolated linearly along the "
        "axis (the chord of a turning unit vector is short). It is no "
        f"fix: the 3243 then has {b43['zero-energy modes']} zero-energy modes "
        f"({b43['zero-energy modes'] - 6} mechanisms beyond the 6 rigid motions) and the "
        f"3333's u_y is {_pct(b33['uy worst'])} at worst ({b33['uy passed']} of "
        f"{b33['uy compared']} within 1 %). Chrono offers no other remedy for its beams (its "
        "options are the internal-force method, `ContInt` or `PreInt`, the same integrals, "
        "and the material with the Poisson split used here), so the acceptance at 16 "
        f"elements stays missed for u_z and is met at {ce.PRINCETON_FINE} elements.\n",
        markdown_table(rules, 4), ""]


def _plate_section(rows: list) -> list:
    df = pd.DataFrame([{"element": r["element"],
                        "Poisson law": r["poisson"].replace("_", " "),
                        "n × n": f"{r['n']} × {r['n']}",
                        "w [m]": r["w"], "Navier w [m]": r["Navier w"],
                        "error w": _pct(r["w error"]),
                        **{f"f{i + 1} [Hz]": f for i, f in enumerate(r["f"])},
                        "largest error f": _pct(r["f error"]),
                        "status": _verdict(max(abs(r["w error"]), r["f error"])
                                           <= ce.PLATE_TOL)} for r in rows])
    ref = pd.DataFrame([{"element": "analytic plate", "Poisson law": "—", "n × n": "—",
                         "w [m]": rows[0]["Navier w"],
                         **{f"f{i + 1} [Hz]": f for i, f in enumerate(rows[0]["f ref"])}}])
    write_csv(pd.concat([df, ref]), "chrono_elements_plate")
    p, k = ce.plate_parameters(), rows[0]["locking"]
    remedy = next(r for r in rows if r["poisson"] == "plane_stress")
    ans = next(r for r in rows if r["element"] == "3423")
    ans_f = [f / g - 1 for f, g in zip(ans["f"], ans["f ref"])]
    high = [_pct(f / g - 1) for f, g in zip(remedy["f"][3:], remedy["f ref"][3:])]
    return [
        "## The simply supported square plate\n",
        f"The suite's `plate-square` (a = {p['a']:g} m, h = {p['h']:g} m, E = {p['E']:g} Pa, "
        f"ν = {p['nu']:g}, p = {p['p']:g} Pa, ρ = {p['rho']:g} kg/m³) on {ce.PLATE_N} × "
        f"{ce.PLATE_N} Chrono shells (`ancf/models/chrono_shell.py`): w = 0 along the edges, "
        "the in-plane rigid motions removed. Centre deflection (Newton) against Navier's "
        "series, the first six natural frequencies about the reference against the "
        f"analytic plate (last row); tolerance {100 * ce.PLATE_TOL:g} % on both. The 3833 "
        "passes. The 3443 with Chrono's 3D law misses by Poisson (thickness) locking: its "
        "fibre r_z is constant through the thickness, so the 3D law sees no free thickness "
        "contraction and the "
        f"bending stiffness rises by (1 − ν)²/(1 − 2ν) = {k:.3f}; w times that factor is "
        "within 1 % of Navier (acceptance checks). With the 3443's remedy "
        "`poisson=\"plane_stress\"` (`ancf/elements/ancf3443.py`: σ_33 = 0 condensed out of "
        f"the law) w is {_pct(remedy['w error'])} of Navier, but f4–f6 are "
        f"{', '.join(high)}: a miss of the 1 % bound, by transverse shear locking of the "
        "4-node shell (below). The 3423 (`ancf/elements/ancf3423.py`: assumed natural "
        "strains for the transverse shear and the thickness strain, five enhanced assumed "
        "strain modes) with the 3D law needs no remedy: its w is "
        f"{_pct(ans['w error'])} of Navier, as its EAS thickness mode frees the "
        f"contraction; its frequencies are {_span_f(ans_f)} of the analytic plate, a miss "
        "of the 1 % bound that is its bilinear interpolation's discretisation error, not "
        "locking (below).\n",
        markdown_table(pd.concat([df, ref]), 5), ""]


def _span_f(errors) -> str:
    """'a to b' of relative errors, in per cent."""
    return f"{_pct(min(errors))} to {_pct(max(errors))}"


def _shear_locking_section(shear: list) -> list:
    df = pd.DataFrame([{"element": "3443 (plane stress)", "n × n": f"{r['n']} × {r['n']}",
                        "G₁₃, G₂₃ ×": f"{r['shear']:g}",
                        **{f"error f{i + 1}": _pct(e) for i, e in enumerate(r["errors"])}}
                       for r in shear])
    write_csv(df, "chrono_elements_plate_shear")
    stiff = next(r for r in shear if r["shear"] == cl.SHEAR_SCALE)
    fine = next(r for r in shear if r["n"] == cl.PLATE_FINE)
    return [
        "### Why the 3443's f4–f6 miss at 16 × 16: transverse shear locking\n",
        "Kirchhoff's plate (the analytic row above) is the limit of a plate ever stiffer in "
        "transverse shear, which a locking-free element approaches from below as its shear "
        "moduli grow (up to its discretisation error). With G₁₃, G₂₃ of the 3443's law × "
        f"{cl.SHEAR_SCALE:g} (`ancf/checks/chrono_locking.py`) its frequencies rise instead "
        f"to {_span_f(stiff['errors'])} above it: the element carries shear strain that the "
        "plate does not have, from its bilinear fibre r_z, which cannot follow the cubic "
        "mid-surface slopes r_x, r_y. The parasitic strain fades with the element size: at "
        f"{cl.PLATE_FINE} × {cl.PLATE_FINE} the six are {_span_f(fine['errors'])} of the "
        "analytic plate. Chrono's 3443 has no remedy for it (the less stiff 3 × 3 "
        "mid-surface rule its header names moves the frequencies by less than 1e-5; the "
        "assumed-strain remedies are in the older 4-node shell "
        "`ChElementShellANCF_3423`, not this element: next section); the 3833, whose fibre "
        "is quadratic, "
        "passes. The acceptance at 16 × 16 stays missed for the 3443's f4–f6.\n",
        markdown_table(df, 4), ""]


def _ans_section(rows: list) -> list:
    """The 3423 on the square plate: its frequencies against the mesh and the shear moduli
    (``chrono_locking.ans_rows``)."""
    df = pd.DataFrame([{"element": "3423", "n × n": f"{r['n']} × {r['n']}",
                        "G₁₃, G₂₃ ×": f"{r['shear']:g}",
                        **{f"error f{i + 1}": _pct(e) for i, e in enumerate(r["errors"])}}
                       for r in rows])
    write_csv(df, "chrono_elements_plate_3423")
    base = next(r for r in rows if r["n"] == ce.PLATE_N and r["shear"] == 1.0)
    stiff = next(r for r in rows if r["shear"] == cl.SHEAR_SCALE)
    move = [f / g - 1 for f, g in zip(stiff["f"], base["f"])]
    order = cl.ans_order(rows)
    return [
        "### The 3423 on the square plate: no locking, a bilinear element's error\n",
        "The same diagnosis on the 3423 (`ancf/checks/chrono_locking.py`): with G₁₃, G₂₃ × "
        f"{cl.SHEAR_SCALE:g} its {ce.PLATE_N} × {ce.PLATE_N} frequencies move by "
        f"{_span_f(move)} of their own (the 3443's rise by over "
        f"{100 * cl.LOCKED_ABOVE:g} %): its assumed transverse shear, sampled at the edge "
        "midpoints, carries no parasitic strain, and its thickness strain (sampled at the "
        "nodes, with the EAS thickness mode) no Poisson locking. What it misses at "
        f"{ce.PLATE_N} × {ce.PLATE_N} ({_span_f(base['errors'])}) is the error of its "
        "bilinear interpolation (constant curvature per element, consistent mass): it "
        f"falls with the element size at an observed order of {min(order):.1f} to "
        f"{max(order):.1f} from {ce.PLATE_N // 2} × {ce.PLATE_N // 2} to {ce.PLATE_N} × "
        f"{ce.PLATE_N}, and at {cl.ANS_FINE} × {cl.ANS_FINE} the six are within 1 % of the "
        "analytic plate. The higher-order 3443 (cubic mid-surface) and 3833 (quadratic) "
        "are more accurate per element once free of locking; the 3423 is the one 4-node "
        "shell here that passes w with Chrono's 3D law.\n",
        markdown_table(df, 4), ""]


def _shell3423_figure(rows: dict) -> str:
    """Tip z of ours and Chrono's file against t, and their difference (figure path)."""
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    ax.plot(rows["t"], rows["file"], "k-", lw=2.5, alpha=0.4, label="Chrono (UT_ANCFShellIso.txt)")
    ax.plot(rows["t"], rows["paper"], "C0-", lw=1, label="ours (ancf3423)")
    ax.axhline(rows["static"], color="C3", ls=":", lw=1, label="ours, static equilibrium")
    ax.set_ylabel("tip z [m]")
    ax.legend(fontsize=8)
    bx.plot(rows["t"], rows["paper"] - rows["file"], "C0-", lw=1)
    return _save_history(fig, bx, c34.TOL, "chrono_elements_shell3423_history")


def _save_history(fig, bx, tol: float, stem: str) -> str:
    """Chrono's tolerance ±tol (m) on the difference axes bx, their labels; the figure saved
    as ``stem`` (its path from the chapter)."""
    for y in (tol, -tol):
        bx.axhline(y, color="k", ls="--", lw=0.8)
    bx.set_xlabel("t [s]")
    bx.set_ylabel("ours − Chrono [m]")
    save_figure(fig, stem)
    return f"figures/{stem}.png"


def _shell3423_section(rows: dict) -> list:
    s = c34.summary(rows)
    df = pd.DataFrame([
        {"run": "ours, consistent ANS order (the file's)", "steps": c34.CHRONO_STEPS,
         "max abs(ours − Chrono) [m]": s["first paper"]},
        {"run": "ours, Chrono's present ANS order", "steps": c34.CHRONO_STEPS,
         "max abs(ours − Chrono) [m]": s["first chrono"]},
        {"run": "ours, consistent ANS order (the file's)", "steps": c34.STEPS,
         "max abs(ours − Chrono) [m]": s["all paper"]}])
    write_csv(df, "chrono_elements_shell3423")
    timing = pd.DataFrame([{"run": f"{c34.STEPS} steps", "Newton iterations": rows["iterations"],
                            TIMING: round(rows["cpu s"], 2)}])
    write_csv(timing, "chrono_elements_shell3423_cost")
    fig = _shell3423_figure(rows)
    return [
        "## The corner-loaded ANCF 3423 plate (Chrono's time history)\n",
        "Chrono's `utest_FEA_ANCFShell_Iso.cpp`: a 1 m × 1 m × 0.01 m plate of 4 × 4 "
        "`ChElementShellANCF_3423` (position and one transverse gradient per node, ANS for the "
        "thickness strain and the transverse shears, five EAS modes), clamped along x = 0, "
        "ρ = 500 kg/m³, E = 2.1e8 Pa, ν = 0.3, structural damping 0.08 s, −50 N along z at the "
        "corner (1, 1), HHT with α = 0 at h = 1 ms (`tests/data/chrono/README.md`). Ours: "
        "`ancf/elements/ancf3423.py` on `ancf/models/plate3423.py` (the trapezoidal rule, "
        "HHT's α = 0, from zero acceleration as Chrono's; Newton to 1e-12 m), checks in "
        "`ancf/checks/chrono_shell3423.py`, tests in `tests/elements/test_chrono_3423*.py`.\n",
        f"Chrono checks its first {c34.CHRONO_STEPS} steps within {c34.TOL:g} m: ours are "
        f"{s['first paper']:.1e} m off, the file's rounding (6 digits). That is with the "
        "thickness strain sampled at each node and interpolated with that node's shape "
        "function; Chrono's element today weights the samples of nodes C and D with each "
        "other's functions (its ANS knots run A, B, D, C, its shape functions A, B, C, D since "
        "the element's node order changed after the file was made in 2015), which is "
        f"{s['first chrono']:.1e} m off: within Chrono's tolerance, beyond the file's rounding.\n",
        f"Over the file's {c34.STEPS} steps ours stay within {c34.TOL:g} m up to "
        f"t = {s['first beyond']:.2f} s and are at most {s['all paper']:.1e} m off "
        f"(at t = {s['at']:.2f} s): the histories oscillate alike, their difference rising and "
        "falling with the swings (figure). Ours is converged: Newton "
        f"to {c34.LOOSE:g} m instead of 1e-12 m changes it by {s['loose change']:.1e} m. From "
        f"t = {c34.SETTLED:g} s to the end the file's tip moves by {s['file range']:.1e} m only "
        f"and rests at {s['file late']:.6f} m (mean), {abs(s['file late'] - s['static']):.1e} m "
        "short of the static equilibrium of the same plate under the same load, "
        f"{s['static']:.6f} m (Newton, 20 load steps), while ours still swings "
        f"({s['ours range']:.1e} m, mean {s['ours late']:.6f} m) about it. The file was "
        "written by Chrono's 2015 HHT (position mode, an iterative MINRES solver capped at 100 "
        "iterations, Newton tolerance 1e-6); we cannot run it, so the cause of the late "
        "difference is not proven: a damped plate comes to rest at its equilibrium, ours "
        "swings about it, and the file rests elsewhere (a residual its solver left, or a "
        "2015 element stiffer than the one described). The acceptance row over all steps "
        "stays missed (DIFFERS, explained).\n",
        markdown_table(df, 4), "", f"![tip z of ours and Chrono's]({fig})\n"]


def _cable_figure(rows: dict) -> str:
    """Mid y and tip z of ours and Chrono's file against t, and the differences (path)."""
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    for col, colour in zip(ccb.CHECKED, ("C0", "C1")):
        name = ccb.COLUMNS[col]
        ax.plot(rows["t"], rows["file"][:, col], "k-", lw=2.5, alpha=0.4)
        ax.plot(rows["t"], rows["ours"][:, col], f"{colour}-", lw=1, label=f"{name}, ours")
        bx.plot(rows["t"], rows["ours"][:, col] - rows["file"][:, col], f"{colour}-", lw=0.8,
                label=name)
    ax.set_ylabel("position [m] (grey: Chrono)")
    ax.legend(fontsize=8)
    bx.legend(fontsize=8)
    return _save_history(fig, bx, ccb.TOL, "chrono_elements_cable_history")


def _cable_section(rows: dict) -> list:
    s = ccb.summary(rows)
    df = pd.DataFrame([
        {"run": "ours, Chrono's parameters", "steps": ccb.CHRONO_STEPS,
         "max abs(ours − Chrono), mid y and tip z [m]": s["first"]},
        {"run": "ours, Chrono's parameters", "steps": ccb.STEPS,
         "max abs(ours − Chrono), mid y and tip z [m]": s["all"]},
        {"run": f"ours, g = {ccb.G_OTHER:g} m/s² (Chrono: 9.8)", "steps": ccb.CHRONO_STEPS,
         "max abs(ours − Chrono), mid y and tip z [m]": s["g other"]}])
    cols = pd.DataFrame({"column": ccb.COLUMNS, "max abs(ours − Chrono)": s["columns"],
                         "beyond the file's rounding": s["beyond rounding"]})
    write_csv(df, "chrono_elements_cable")
    write_csv(pd.DataFrame([{"run": f"{ccb.STEPS} steps", TIMING: round(s["cpu s"], 2)}]),
              "chrono_elements_cable_cost")
    fig = _cable_figure(rows)
    return [
        "## The spinning cable pendulum (Chrono's `ChElementCableANCF` history)\n",
        "Chrono's `utest_FEA_ANCFCable.cpp` (Gerstmayr and Shabana 2006, Figs 4 and 5): a 1 m "
        "cable of 4 gradient-deficient elements (position and one slope per node), "
        "section diameter 2 f √(1e-6/π) m, E = 1e9/f⁴ Pa, ρ = 8000/f² kg/m³ with f = 5, "
        "held at x = 0 by a spherical joint, under gravity 9.8 m/s² along −y, started "
        "straight and spinning at 4 rad/s about y; Chrono's linearised implicit Euler (one "
        "Newton iteration per step) at h = 1e-4 s (`tests/data/chrono/README.md`). Ours: "
        "`ancf/elements/cable3d.py` (the registry's `cable3d`, exact tangent) on "
        "`ancf/models/chrono_cable.py`, checks in `ancf/checks/chrono_cable.py`, tests in "
        "`tests/checks/test_chrono_cable.py` and `tests/elements/test_cable3d.py`.\n",
        f"Chrono checks the mid node's y and the tip's z over its first {ccb.CHRONO_STEPS} "
        f"steps within {ccb.TOL:g} m: ours are {s['first']:.1e} m off. Over all "
        f"{ccb.STEPS} steps (2 s, the cable swung through large rotations) they stay within "
        f"{s['all']:.1e} m, and no column of the file is further from ours than "
        f"{max(s['beyond rounding']):.1e} m beyond the file's rounding to 6 digits. The "
        f"check sees the constants: gravity {ccb.G_OTHER:g} m/s² instead of Chrono's 9.8 is "
        f"{s['g other']:.1e} m off within the first {ccb.CHRONO_STEPS} steps.\n",
        markdown_table(df, 4), "", markdown_table(cols, 4), "",
        f"![mid y and tip z of ours and Chrono's]({fig})\n"]


INTRO = [
    "# Project Chrono's ANCF elements\n",
    "Generated by `python -m ancf.reports` (this chapter alone: `python -m ancf.reports "
    "--chapter chrono_elements.md`); do not edit. Our implementations of Chrono's "
    "ANCF 3243 and 3333 beams, 3423, 3443 and 3833 shells, 3843 brick "
    "(`ancf/elements/ancf3*.py`) and cable (`ancf/elements/cable3d.py`) against Chrono's "
    "stored element matrices and time histories, its textbook "
    "static cases, the Princeton beam (ANSYS) and the square plate (Navier). CPU times "
    "are on the timing page. CSV data: `reports/data/chrono_elements_*.csv`.\n"]
TIED = ("a test of `tests/reports/test_chrono_elements_chapter.py` (data: "
        "`data/chrono_elements_checks.csv`)")


def _status(c) -> str:
    """PASS, DIFFERS (explained) for the 3423 plate's whole-history row, or FAIL."""
    return "PASS" if c.passed else "DIFFERS (explained)" if c.name == c34.NAMES[1] else "FAIL"


def chapter_from(static: list, princeton: list, plates: list, reduced: list,
                 shear: list, shell3423: dict | None = None,
                 ans: list | None = None, cable: dict | None = None) -> tuple[str, dict]:
    """(markdown, status) of the chapter with these rows: static cases, Princeton beam,
    square plate, the Princeton beam on the reduced axial rule, the shear-scaled plate,
    (if given, ``chrono_shell3423.history_rows``) the corner-loaded 3423 plate, (if
    given, ``chrono_locking.ans_rows``) the 3423's square plate against mesh and shear and
    (if given, ``chrono_cable.history_rows``) the spinning cable pendulum."""
    checks = (*ce.checks(static, princeton, plates), *cl.checks(reduced, shear),
              *(cl.ans_checks(ans) if ans is not None else ()),
              *(c34.checks(shell3423) if shell3423 is not None else ()),
              *(ccb.checks(cable) if cable is not None else ()))
    status = {c.name: _status(c) for c in checks}
    parts = [*INTRO, *_matrices_section(), *_static_section(static),
             *_princeton_section(princeton), *_beam_locking_section(princeton, reduced),
             *_plate_section(plates), *_shear_locking_section(shear),
             *(_ans_section(ans) if ans is not None else ()),
             *(_shell3423_section(shell3423) if shell3423 is not None else ()),
             *(_cable_section(cable) if cable is not None else ())]
    parts += checks_section(checks, status, "chrono_elements", TIED)
    return "\n".join(parts), status


def _quick_chapter() -> tuple[str, dict]:
    """The reduced configuration: the stored matrices only.  The solved rows (static
    cases, Princeton beam, square plate, the locking diagnosis: over 100 CPU s) are
    skipped; ``tests/reports/test_chrono_elements_chapter.py`` still solves them, holds
    them to the checks and renders this chapter from them."""
    checks = ce.matrix_checks()
    status = {c.name: "PASS" if c.passed else "FAIL" for c in checks}
    parts = [*INTRO, *_matrices_section(), "Reduced configuration: Chrono's static cases, the "
             "Princeton beam, the square plate and the locking diagnosis are skipped.\n"]
    parts += checks_section(checks, status, "chrono_elements", TIED)
    return "\n".join(parts), status | dict.fromkeys((*ce.solved_names(), *cl.NAMES,
                                                     *cl.ANS_NAMES, *c34.NAMES,
                                                     *ccb.NAMES), QUICK_SKIPPED)


def chrono_elements_chapter() -> tuple[str, dict]:
    if settings().quick:
        return _quick_chapter()
    progress("chrono_elements: Chrono's static cases")
    static = ce.static_rows()
    progress("chrono_elements: the Princeton beam")
    princeton = ce.princeton_rows()
    progress("chrono_elements: the square plate, the stored matrices")
    plates = ce.plate_rows()
    progress("chrono_elements: the locking diagnosis")
    reduced, shear, ans = cl.princeton_rule_rows(), cl.plate_rows(), cl.ans_rows()
    progress("chrono_elements: the corner-loaded 3423 plate")
    shell = c34.history_rows()
    progress("chrono_elements: the spinning cable pendulum")
    return chapter_from(static, princeton, plates, reduced, shear, shell, ans,
                        ccb.history_rows())


CHAPTER = Chapter(
    file="chrono_elements.md", order=130, generate=chrono_elements_chapter,
    checks=("ancf.checks.chrono_elements", "ancf.checks.chrono_matrices",
            "ancf.checks.chrono_princeton", "ancf.checks.chrono_locking",
            "ancf.checks.chrono_shell3423", "ancf.checks.chrono_cable"),
    contents="Project Chrono's ANCF elements (3243, 3333, 3423, 3443, 3833, 3843): Chrono's "
             "stored element matrices reproduced, its textbook static cases at its "
             "tolerances, the Princeton beam against ANSYS (u_z locking at 16 elements), "
             "the square plate of the shells against Navier (3443 Poisson and shear "
             "locking; the ANS/EAS 3423 free of both), the corner-loaded 3423 plate's time "
             "history against Chrono's; the spinning cable pendulum's history against "
             "Chrono's; acceptance checks")
