"""The 3D beam benchmarks (issue 24, item 4): ``beam3d_benchmarks_chapter() -> (markdown,
status)``.  Every number comes from :mod:`ancf.checks.beam3d_benchmarks` (the scenes
``princeton-beam``, ``beam3d-bending``, ``beam3d-cantilever``), the published values from
:mod:`ancf.scenes.beam3d_published`; the checks are pinned by
``tests/models/test_beam3d_benchmarks.py``.
"""
from __future__ import annotations

import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import pandas as pd  # noqa: E402

from ancf.checks import beam3d_benchmarks as bb  # noqa: E402
from ancf.reports.chapter import Chapter  # noqa: E402
from ancf.reports.output import (checks_section, markdown_table, progress,  # noqa: E402
                                 save_figure, write_csv)
from ancf.elements.linear3d import LinearBeam3D  # noqa: E402
from ancf.scenes import SCENES  # noqa: E402
from ancf.scenes import beam3d_published as pub  # noqa: E402

SCHEMES = LinearBeam3D.schemes

TIMING = "timing: CPU ms"


def _pct(e) -> str:
    """A signed relative error in per cent, 3 significant digits."""
    return "—" if e is None else f"{100.0 * e:+.3g} %"


def _size(e) -> str:
    """An unsigned relative size in per cent."""
    return f"{100.0 * abs(e):.2g} %"


def _ms(s) -> float:
    return round(1e3 * s, 1)


def _princeton_table(runs: dict, load: str) -> pd.DataFrame:
    """Published |u_y|, u_z at one load side by side with linear3d and belt3d."""
    lin, belt = ([r for r in runs[m] if r["load"] == load] for m in ("linear3d", "belt3d"))
    return pd.DataFrame([{
        "β [°]": a["beta"], "ANSYS beam u_y [m]": a["ansys beam y"],
        "linear3d u_y": a["y"], "linear3d error u_y": _pct(a["y error"]),
        "belt3d u_y": b["y"], "belt3d error u_y": _pct(b["y error"]),
        "ANSYS beam u_z [m]": a["ansys beam z"], "linear3d u_z": a["z"],
        "linear3d error u_z": _pct(a["z error"]), "belt3d u_z": b["z"],
        "belt3d error u_z": _pct(b["z error"]), "ANSYS solid u_y": a["ansys solid y"],
        "ANSYS solid u_z": a["ansys solid z"], f"{TIMING} linear3d": _ms(a["cpu s"]),
        f"{TIMING} belt3d": _ms(b["cpu s"])} for a, b in zip(lin, belt)])


def _failures_table(runs: dict) -> pd.DataFrame:
    """The relative errors of the models that are not meant for the case, per cell."""
    models = ("linear3d, k_s = 5/6", "linear3d, exact", "linear3d, report-fix",
              "linear3d, report-selective")
    rows = []
    for i, base in enumerate(runs["linear3d"]):
        row = {"load": base["load"], "β [°]": base["beta"]}
        for m in models:
            r = runs[m][i]
            row[f"{m}: u_y"] = _pct(r["y error"]) if r["converged"] else "no conv."
            row[f"{m}: u_z"] = _pct(r["z error"]) if r["converged"] else "no conv."
        rows.append(row)
    return pd.DataFrame(rows)


def _convergence_table() -> pd.DataFrame:
    rows = {}
    for m in ("linear3d", "belt3d", "linear3d, exact", "linear3d, k_s = 5/6"):
        for r in bb.princeton_convergence(m):
            row = rows.setdefault(r["n"], {"n": r["n"]})
            row[f"{m}: u_y"], row[f"{m}: u_z"] = _pct(r["y error"]), _pct(r["z error"])
            row[f"{TIMING} {m}"] = _ms(r["cpu s"])
    return pd.DataFrame(rows.values())


def _princeton_figure(runs: dict) -> str:
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, (k, name) in zip(axes, (("y", "|u_y|"), ("z", "u_z"))):
        for load, style in (("F2", "-"), ("F3", "--")):
            beam = [r for r in runs["linear3d"] if r["load"] == load]
            beta = [r["beta"] for r in beam]
            ax.plot(beta, [r[f"ansys beam {k}"] for r in beam], "k" + style, lw=1,
                    label=f"ANSYS beam {load}")
            ax.plot(beta, [r[f"ansys solid {k}"] for r in beam], "0.6", ls=style, lw=1,
                    label=f"ANSYS solid {load}")
            for m, mark in (("linear3d", "o"), ("belt3d", "x"), ("linear3d, k_s = 5/6", "s")):
                rows = [r for r in runs[m] if r["load"] == load]
                ax.plot(beta, [r[k] for r in rows], mark, ms=4, mfc="none",
                        label=f"{m} {load}")
        ax.set(xlabel="β [°]", ylabel=f"{name} [m]", title=f"Princeton beam, tip {name}")
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=6, ncol=2)
    save_figure(fig, "beam3d_princeton")
    return "![Princeton beam](figures/beam3d_princeton.png)\n"


def _bending_table() -> pd.DataFrame:
    rows = bb.general_bending()
    write_csv(pd.DataFrame(rows).rename(columns={"cpu s": "timing: cpu s"}),
              "beam3d_general_bending")
    return pd.DataFrame([{
        "source": r["source"], "elements": r["n"], "u_x [m]": r["ux"],
        "error u_x": _pct(r.get("ux error")), "u_y [m]": r["uy"],
        "error u_y": _pct(r.get("uy error")), "u_z [m]": r["uz"],
        "error u_z": _pct(r.get("uz error")),
        f"{TIMING}": _ms(r["cpu s"]) if "cpu s" in r else None} for r in rows])


def _half_unit() -> float:
    """Half a unit of the last printed digit of Table 4's ANSYS u_z, relative."""
    uz = pub.GENERAL_BENDING_TABLE_4[pub.GENERAL_BENDING_REFERENCE][1][2]
    return 0.5e-4 * 10.0 ** math.floor(math.log10(uz)) / uz


def _continuum_text() -> str:
    c = bb.continuum_explained("linear3d", bb.CONTINUUM_N)
    return (
        "**Why u_x and u_y differ.** The published values are those of a rod (the "
        "paper's structural formulation, ANSYS beam elements); ours is the ANCF continuum "
        "(Green strain, St-Venant–Kirchhoff, no warping), which has second-order terms the "
        "rod has not, computed in `ancf/checks/beam3d_benchmarks.py` (κ = M_y/(E I_y), "
        "k₁ = M_x/(k_s G I_p)):\n\n"
        "| term | closed form | value [m] |\n|---|---|---|\n"
        f"| axis shortening of the bent continuum (u_x) | 3/2 κ² (I_y/A) L | {c['bending']:.4e} |\n"
        f"| Wagner shortening of the twisted continuum (u_x) | 1/2 k₁² (I_p/A) L | "
        f"{c['wagner']:.4e} |\n"
        f"| shear under the bending stress on the twisted fibres (−u_y) | k₁ M_y L/(k_s G A) | "
        f"{c['shear']:.4e} |\n\n"
        f"linear3d with {bb.CONTINUUM_N} elements minus ANSYS: u_x {c['ux difference']:.4e} m against the "
        f"predicted {c['ux predicted']:.4e} m (mismatch {_pct(c['ux mismatch'])}), u_y "
        f"{c['uy difference']:.4e} m against {c['uy predicted']:.4e} m (mismatch "
        f"{_pct(c['uy mismatch'])}). The third term is a shear force: fibres at height z "
        "are inclined by −z k₁ in a twisted section, so the bending stress E z κ along them "
        "has the resultant −k₁ M_y along y, which a shear strain k₁ M_y/(k_s G A) balances. "
        "It grows with (E/G)(I_y/A)/k_s; here k_s is the published torsion correction "
        f"{pub.GENERAL_BENDING_KS_TORSION:g}, since our elements have one factor for shear "
        "and torsion (the published shear corrections are "
        f"{pub.GENERAL_BENDING_KS_SHEAR[0]:g} along y and {pub.GENERAL_BENDING_KS_SHEAR[1]:g} "
        "along z).\n")


def _moments_section() -> list:
    df = pd.DataFrame(bb.moment_small_deflection())
    write_csv(df, "beam3d_tip_moment")
    return [
        "## A tip moment on slope coordinates\n",
        "The 3D elements have no rotation coordinates: a section carries its orientation in "
        "the slopes r_y, r_z. A moment M (fixed direction) does the work M·δθ, where δθ is "
        "the rigid rotation that best fits the end face's virtual displacement "
        "y δr_y + z δr_z: it minimises ∫|y δr_y + z δr_z − δθ × (y r_y + z r_z)|² dA = "
        "Σ w_k |δr_k − δθ × r_k|² (w_y = ∫y² dA, w_z = ∫z² dA), so W δθ = Σ w_k r_k × δr_k "
        "with W = Σ w_k (|r_k|² I − r_k r_kᵀ), and the generalised forces are "
        "Q_k = w_k (W⁻¹M) × r_k (`ancf.core.forces.SectionMoment`, exact Jacobian). For any "
        "rigid rotation of the slopes δθ is that rotation; in the reference Q is the linear "
        "end traction of M (the torque shared by r_y and r_z as w_y : w_z); in the plane it "
        "is the gradient of M times the slope angle. `beam3d-cantilever` takes `Mx`, `My`, "
        f"`Mz`. Small rotation ({bb.SMALL_ROTATION:g} rad at the tip, the general-bending "
        "section): the tip "
        "displacement (m) against M L²/(2 E I) and the twist (rad) against M L/(k_s G I_p):\n",
        markdown_table(df, 6, "Tip moment on the slope coordinates"), ""]


def _span(values, scale=100.0) -> str:
    """'a–b' of the smallest and largest of values (times scale, 2 significant digits)."""
    lo, hi = min(values) * scale, max(values) * scale
    return f"{lo:.1f}–{hi:.1f}"


def _princeton_facts(runs: dict) -> dict:
    """The numbers the Princeton text quotes, from the runs."""
    lin = runs["linear3d"]
    coupled = lambda rows: [r for r in rows if 0.0 < r["beta"] < 90.0]  # noqa: E731
    conv = {m: bb.princeton_convergence(m)[-1] for m in ("linear3d", "linear3d, exact")}
    return {
        "z": max(abs(r["z error"]) for m in ("linear3d", "belt3d") for r in runs[m]
                 if r["z error"] is not None),
        "y": max(r["y error"] for m in ("linear3d", "belt3d") for r in coupled(runs[m])),
        "solid": _span([1.0 - r["ansys solid y"] / r["ansys beam y"] for r in coupled(lin)]),
        "ks_cost": max(abs(a["y"] / b["y"] - 1.0) for a, b in
                       zip(lin, runs["linear3d, k_s = 5/6"]) if a["beta"] == 0.0),
        "stiff": _span([-r["y error"] for r in coupled(runs["linear3d, k_s = 5/6"])]),
        "locked": _span([r["z"] / r["ansys beam z"] for r in runs["linear3d, exact"]
                         if r["beta"] > 0.0]),
        "locked_fine": conv["linear3d, exact"]["z error"], "n_fine": bb.PRINCETON_NS[-1],
        "converged_y": conv["linear3d"]["y error"], "converged_z": conv["linear3d"]["z error"]}


def beam3d_benchmarks_chapter() -> tuple[str, dict]:
    progress("beam3d_benchmarks: princeton-beam, beam3d-bending")
    checks = bb.checks()
    status = {c.name: "PASS" if c.passed else "FAIL" for c in checks}
    runs = {m: bb.princeton(m) for m in bb.PRINCETON_MODELS}
    write_csv(pd.DataFrame([{"model": m, **r} for m, rows in runs.items() for r in rows])
              .rename(columns={"cpu s": "timing: cpu s"}),
              "beam3d_princeton")
    tor, f = bb.princeton_torsion(), _princeton_facts(runs)
    d = SCENES["princeton-beam"].resolve({})
    P, B = pub.PRINCETON, pub.GENERAL_BENDING
    parts = [
        "# The 3D beam benchmarks\n",
        "Generated by `python -m ancf.reports` (this chapter alone: `python -m ancf.reports "
        "--chapter beam3d_benchmarks.md`); do not edit. Scenes `princeton-beam` and "
        "`beam3d-bending` (`ancf run NAME --json`, presets of `beam3d-cantilever`); numbers "
        "computed by `ancf/checks/beam3d_benchmarks.py`, published values transcribed in "
        "`ancf/scenes/beam3d_published.py` from Exudyn's `TestModels/ANCFBeamTest.py`, which "
        "lists them with their papers. Relative error = ours / published − 1 (— where the "
        "published value is 0 by symmetry). The runs' CPU times (the scene's `cpu_time_s`) "
        "vary per run and machine: they are on the timing page. CSV data: "
        "`reports/data/beam3d_*.csv`.\n",
        *_moments_section(),
        "## Princeton beam\n",
        f"The strip of Dowell et al.: L = {P['L']:g} m, h = {P['h']:g} m (y), b = {P['b']:g} m "
        f"(z), E = {P['E']:g} Pa, ν = {P['nu']:g}, clamped, tip force F2 = "
        f"{pub.PRINCETON_LOADS['F2']:g} N or F3 = {pub.PRINCETON_LOADS['F3']:g} N at β from −y "
        "(ours turns towards −z, the published towards +z: magnitudes compared). Reference: "
        "ANSYS beam elements (Obrezkov et al. 2022); ANSYS solid elements shown beside it. "
        f"{bb.PRINCETON_N} elements, linear3d with the thesis scheme "
        f"(`{SCHEMES['thesis']}`), belt3d with {d['elastic_points']} Gauss points along the "
        f"axis, {d['load_steps']} load steps (adaptive). k_s = J/(I_y + I_z) = {tor['ks']:.4f} (St-Venant's J of the "
        "rectangle, series), so that the elements' torsional stiffness k_s G I_p is G J "
        f"(Exudyn's file lists {tor['ks_exudyn']:g}); it is also their shear correction, "
        f"which changes the strong-axis deflection at β = 0 by {f['ks_cost']:.1e} against "
        "k_s = 5/6.\n",
    ]
    for load in pub.PRINCETON_LOADS:
        parts += [f"### {load} = {pub.PRINCETON_LOADS[load]:g} N\n",
                  markdown_table(_princeton_table(runs, load), 5, f"Princeton beam, {load}"), ""]
    parts += [
        _princeton_figure(runs),
        f"At {bb.PRINCETON_N} elements u_z is within {_size(f['z'])} of ANSYS beam and "
        f"u_y up to {_size(f['y'])} above it at the coupled angles, where u_y comes from "
        f"the coupling of bending and torsion; with {f['n_fine']} elements (mesh table "
        f"below, both elements converge to the same tip) the errors at F3, 45° are "
        f"{_pct(f['converged_y'])} (u_y) and {_pct(f['converged_z'])} (u_z): a model "
        f"difference, not discretisation. ANSYS solid lies {f['solid']} % below ANSYS beam "
        "in u_y at those angles: the reference is not sharper than that.\n",
        "### Where the thesis's element is not meant for the case\n",
        "The same runs with the element default k_s = 5/6: the thin section is then "
        f"{tor['stiffness_ratio_5_6']:.2f} times too stiff in torsion (k_s I_p / J), and "
        f"u_y at the coupled angles is {f['stiff']} % low. With exact integration "
        f"(`{SCHEMES['exact']}`) the linear element locks in shear on the thin strip: u_z is "
        f"{f['locked']} % of ANSYS at {bb.PRINCETON_N} elements. `report-fix` "
        f"(`{SCHEMES['report-fix']}`) works; `report-selective` (`{SCHEMES['report-selective']}`: "
        "one section point for the shear) drops the section-linear shear strains, i.e. all "
        "torsional stiffness: the tangent is singular and no run converges.\n",
        markdown_table(_failures_table(runs), 4), "",
        "### Mesh convergence (F3, β = 45°)\n",
        markdown_table(_convergence_table(), 4, "Princeton beam: mesh convergence (F3, β = 45°)"), "",
        "Locking of the exact scheme fades only slowly with the mesh (u_z "
        f"{_pct(f['locked_fine'])} at {f['n_fine']} elements); the torsion error of k_s = 5/6 "
        "does not fade at all.\n",
        "## 3D general bending (Nachbagauer, Gruber, Gerstmayr 2013)\n",
        f"L = {B['L']:g} m, h = {B['h']:g} m (y), b = {B['b']:g} m (z), E = {B['E']:g} Pa, "
        f"ν = {B['nu']:g}, tip moments M_x = {B['Mx']:g} N m and M_y = {B['My']:g} N m about "
        f"the fixed global axes, k_s = {pub.GENERAL_BENDING_KS_TORSION:g} (the published "
        "torsion correction, J = k_s I_p). Published: Table 4 (SMF = the paper's structural "
        "mechanics formulation; ANSYS). Displacement magnitudes (the tip moves to −x, −y, "
        "−z); errors against ANSYS.\n",
        markdown_table(_bending_table(), 5, "3D general bending"), "",
        f"Table 4 prints 5 digits: half a unit of the last is {_half_unit():.1e} of u_z. "
        "Both elements converge to the same continuum solution.\n",
        _continuum_text(),
    ]
    parts += checks_section(checks, status, "beam3d_benchmarks",
                            "a test of `tests/models/test_beam3d_benchmarks.py`"
                            " (data: `data/beam3d_benchmarks_checks.csv`)")
    return "\n".join(parts), status


CHAPTER = Chapter(
    file="beam3d_benchmarks.md", order=90, generate=beam3d_benchmarks_chapter,
    checks=("ancf.checks.beam3d_benchmarks",),
    contents="The 3D beam benchmarks: a tip moment on slope coordinates, the "
             "Princeton beam (F2, F3, every angle) against ANSYS beam and solid "
             "elements per element and scheme (locking, torsion), mesh convergence; "
             "Nachbagauer et al.'s 3D general bending against Table 4, the "
             "continuum's second-order terms; acceptance checks")
