"""Static comparison tables: thesis Tables 2.1-2.4 and report Tables 1-6."""
from __future__ import annotations

import pandas as pd

from ancf.reports import published as pub
from ancf.reports.output import markdown_table, progress, reference, run, write_csv

SS_TOL_REL = 1e-4   # 0.01 % (issue acceptance, Tables 2.1-2.2)
TIP_TOL_M = 2e-4    # m (issue acceptance, Tables 2.3-2.4, report 3-5)
ELEMENTS = ("omar-shabana", "linear")


def _ss_value(element, n, nu, integration):
    out = run("simply-supported", element=element, n_elements=n, nu=nu, integration=integration)
    return out["results"]["mid_deflection_m"] * 1e3 if out["converged"] else None


def simply_supported_table(key: str, table: dict, integration: str = "thesis"):
    """Published vs computed midpoint deflections (mm) with relative differences."""
    progress(f"{key}: simply supported beam, nu = {table['nu']}")
    ana = reference("timoshenko", nu=table["nu"])["results"]["mid_deflection_m"] * 1e3
    rows = []
    for n, vals in table["rows"].items():
        pubv = dict(zip(table["columns"], vals))
        row = {"n": n}
        if "beam188" in pubv:
            row["BEAM188 (pub)"] = pubv["beam188"]
        for el in ELEMENTS:
            ours = _ss_value(el, n, table["nu"], integration)
            row[f"{el} (pub)"], row[f"{el} (ours)"] = pubv[el], ours
            row[f"{el} rel.diff %"] = 100 * abs(ours - pubv[el]) / abs(pubv[el])
        if "diff_pct" in pubv:
            row["linear vs analytic % (pub)"] = pubv["diff_pct"]
            row["linear vs analytic % (ours, pub analytic)"] = (
                100 * abs(table["analytic"] - row["linear (ours)"]) / abs(table["analytic"]))
        rows.append(row)
    df = pd.DataFrame(rows)
    write_csv(df, key)
    worst = max(df[f"{el} rel.diff %"].max() for el in ELEMENTS)
    ok = worst <= 100 * SS_TOL_REL
    text = (markdown_table(df) + "\n\n"
            f"Analytic (Timoshenko, k_s = 5/6, SymPy-derived): **{ana:.8f} mm**; published "
            f"{table['analytic']} mm (difference {100 * abs(ana - table['analytic']) / abs(table['analytic']):.4f} %). "
            f"ANSYS BEAM3 (published): {table['beam3']} mm.\n\n"
            f"Largest relative difference from a published element cell: **{worst:.2e} %** "
            f"(tolerance {100 * SS_TOL_REL:g} %) → {'PASS' if ok else 'FAIL'}.")
    return text, ok, df


def _tip(element, n, model, integration, clamp_x_slope="free"):
    out = run("cantilever", element=element, n_elements=n, integration=integration,
              clamp_x_slope=clamp_x_slope, **model)
    r = out["results"]
    return (r["tip_x"], r["tip_y"]) if out["converged"] else None, out


OS_SCHEMES = {"thesis": "4 Gauss points along x, closed form across y",
              "all=4x2": "4 Gauss points along x, 2 across y"}


def cantilever_table(key: str, table: dict):
    """Published vs computed tip positions (m) and the largest coordinate difference."""
    model = table["model"]
    progress(f"{key}: cantilever h = {model['h']}, nu = {model['nu']}")
    ref = reference("reissner", **model)["results"]
    rows, worst = [], {}
    for n, (os_pub, lin_pub, b188) in table["rows"].items():
        row = {"n": n}
        for el, p, integ, clamp in (
                ("omar-shabana", os_pub, table["os_integration"], table["os_clamp_x_slope"]),
                ("linear", lin_pub, table["linear_integration"], "free")):
            ours, out = _tip(el, n, model, integ, clamp)
            row[f"{el} (pub)"] = "No convergence" if p is None else f"{p[0]:.5f}, {p[1]:.5f}"
            row[f"{el} (ours)"] = (f"{ours[0]:.5f}, {ours[1]:.5f}" if ours else
                                   "No convergence" + _why(out))
            d = _diff(p, ours)
            row[f"{el} max abs diff m"] = d
            worst[el] = max(worst.get(el, 0.0), d if isinstance(d, float) else 0.0)
        row["BEAM188 (pub)"] = f"{b188[0]:.5f}, {b188[1]:.5f}"
        rows.append(row)
    df = pd.DataFrame(rows)
    write_csv(df, key)
    status = {el: worst[el] <= TIP_TOL_M for el in worst}
    text = (markdown_table(df) + "\n\n"
            f"Linear element integration: `{table['linear_integration']}`; Omar–Shabana: "
            f"`{table['os_integration']}` ({OS_SCHEMES[table['os_integration']]}) with "
            f"`clamp_x_slope={table['os_clamp_x_slope']}` (the setting that reproduces this "
            f"document's column, see the explanations below). Reissner reference (this suite): "
            f"({ref['tip_x']:.5f}, {ref['tip_y']:.5f}).\n\n"
            + "; ".join(f"{el}: largest difference {worst[el]:.1e} m → "
                        f"{'PASS' if status[el] else 'DIFFERS (see explanation)'}" for el in worst)
            + f" (tolerance {TIP_TOL_M:g} m).")
    return text, status, df


def _why(out):
    neg = out["results"].get("negative_tangent_eigenvalues")
    return f" (unstable equilibrium, {neg} negative eigenvalue(s))" if neg else ""


def _diff(p, ours):
    if p is None and ours is None:
        return "both: no convergence"
    if p is None or ours is None:
        return "MISMATCH"
    return max(abs(p[0] - ours[0]), abs(p[1] - ours[1]))


def axial_bar_table():
    progress("report Table 6: axial bar")
    rows = []
    analytic_mm = 5.0e4 * 2.0 / (2.07e11 * 0.01) * 1e3  # F L / (E A), linear theory
    for el in ELEMENTS:
        for nu in (0.3, 0.0):
            out = run("axial-bar", element=el, nu=nu)
            ours = out["results"]["elongation_m"] * 1e3
            p = pub.REPORT_6[(el, nu)]
            rows.append({"element": el, "nu": nu, "published mm": p, "ours mm": ours,
                         "rel.diff %": 100 * abs(ours - p) / p,
                         "tip y-reaction N": out["results"]["tip_reaction_y_N"]})
    df = pd.DataFrame(rows)
    write_csv(df, "report_table_6")
    ok = bool((df["rel.diff %"] <= 0.01).all())
    text = (markdown_table(df) + "\n\n"
            f"Analytic F L/(E A) = {analytic_mm:.6f} mm (published {pub.REPORT_6['analytic']} mm); "
            "the ANCF elements use the Green strain, so their elongation is slightly smaller. "
            "Omar–Shabana with nu = 0.3 is stiffer by 1/(1-nu^2) = "
            f"{1 / (1 - 0.09):.4f}: its plane-strain Lamé matrix (Eq. 2.17) with a free transverse "
            "stretch (sigma_yy = 0) but no contraction across the width gives an axial modulus "
            "E/(1-nu^2).\n\n"
            f"All cells within 0.01 % → {'PASS' if ok else 'FAIL'}.")
    return text, ok, df
