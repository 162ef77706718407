"""Acceptance: the published static tables (thesis 2.1-2.4, report 1-6) recomputed.

Tolerances (issue 2): simply supported cells within 0.01 % (relative); cantilever
tip coordinates within 2e-4 m.  Cells we do not match are tested for the
explanation the report gives (see reports/static_beams.md).
"""
import pytest

from ancf.reports import published as pub
from ancf.scenes import SCENES

SS_TOL = 1e-4
TIP_TOL = 2e-4


def _ss(element, n, nu):
    out, _ = SCENES["simply-supported"].execute(dict(element=element, n_elements=n, nu=nu))
    assert out["converged"], out["message"]
    return out["results"]["mid_deflection_m"] * 1e3  # mm, as published


def _tip(element, n, model, integration="thesis"):
    out, _ = SCENES["cantilever"].execute(dict(element=element, n_elements=n,
                                               integration=integration, **model))
    return out


@pytest.mark.parametrize("table", [pub.THESIS_2_1, pub.THESIS_2_2, pub.REPORT_1, pub.REPORT_2],
                         ids=["thesis2.1", "thesis2.2", "report1", "report2"])
@pytest.mark.parametrize("element", ["omar-shabana", "linear"])
def test_simply_supported_tables(table, element):
    col = table["columns"].index(element)
    for n, row in table["rows"].items():
        ours = _ss(element, n, table["nu"])
        assert ours == pytest.approx(row[col], rel=SS_TOL), (n, ours, row[col])


@pytest.mark.parametrize("key,table,elements", [
    ("thesis2.3", pub.THESIS_2_3, ("omar-shabana", "linear")),
    ("thesis2.4", pub.THESIS_2_4, ("linear",)),
    ("report3", pub.REPORT_3, ("linear",)),
    ("report5", pub.REPORT_5, ("linear",)),
])
def test_cantilever_tables(key, table, elements):
    for n, row in table["rows"].items():
        for el in elements:
            integ = table["linear_integration"] if el == "linear" else "thesis"
            out = _tip(el, n, table["model"], integ)
            assert out["converged"], (key, el, n, out["message"])
            p = row[pub.CANTILEVER_COLUMNS.index(el)]
            r = out["results"]
            assert abs(r["tip_x"] - p[0]) < TIP_TOL and abs(r["tip_y"] - p[1]) < TIP_TOL, \
                (key, el, n, r["tip_x"], r["tip_y"], p)


def test_report_table_4_linear_and_no_convergence():
    """Report Table 4: the 1-point-shear scheme matches up to 16 elements and, at 32 and 64,
    Newton ends on an unstable equilibrium, which is reported as no convergence."""
    for n, row in pub.REPORT_4["rows"].items():
        out = _tip("linear", n, pub.MODEL_2, "report-selective")
        if row[1] is None:
            assert not out["converged"] and "No convergence" in out["message"]
            assert out["results"]["negative_tangent_eigenvalues"] >= 1
        else:
            r = out["results"]
            assert out["converged"]
            assert abs(r["tip_x"] - row[1][0]) < TIP_TOL and abs(r["tip_y"] - row[1][1]) < TIP_TOL


def test_report_table_3_omar_shabana_single_outlier():
    """Report Table 3, Omar-Shabana, n = 4: only x is off (2.7e-3 m); y and every other row
    match within 2e-4 m, and the thesis's Table 2.3 prints our x for the same cell, so the
    report's cell is a transcription error (see reports/static_beams.md)."""
    for n, row in pub.REPORT_3["rows"].items():
        r = _tip("omar-shabana", n, pub.MODEL_1)["results"]
        assert abs(r["tip_y"] - row[0][1]) < TIP_TOL
        if n == 4:
            assert abs(r["tip_x"] - row[0][0]) > 10 * TIP_TOL
            assert abs(r["tip_x"] - pub.THESIS_2_3["rows"][4][0][0]) < TIP_TOL
        else:
            assert abs(r["tip_x"] - row[0][0]) < TIP_TOL


def test_omar_shabana_model_2_published_columns_disagree_with_each_other():
    """The evidence quoted in the report: for Model 2 the thesis and report columns of the
    same element differ by more than the 2e-4 m tolerance, and our n = 64 value lies within
    2e-4 m of the thesis cell and within 1e-3 m of both."""
    gap = max(abs(a - b) for n in pub.N
              for a, b in zip(pub.THESIS_2_4["rows"][n][0], pub.REPORT_4["rows"][n][0]))
    assert gap > TIP_TOL
    r = _tip("omar-shabana", 64, pub.MODEL_2)["results"]
    t, rep = pub.THESIS_2_4["rows"][64][0], pub.REPORT_4["rows"][64][0]
    assert max(abs(r["tip_x"] - t[0]), abs(r["tip_y"] - t[1])) < TIP_TOL
    assert max(abs(r["tip_x"] - rep[0]), abs(r["tip_y"] - rep[1])) < 1e-3


@pytest.mark.parametrize("element", ["omar-shabana", "linear"])
@pytest.mark.parametrize("nu", [0.0, 0.3])
def test_report_table_6_elongation(element, nu):
    out, _ = SCENES["axial-bar"].execute(dict(element=element, nu=nu))
    ours_mm = out["results"]["elongation_m"] * 1e3
    assert ours_mm == pytest.approx(pub.REPORT_6[(element, nu)], rel=1e-4)
    assert abs(out["results"]["tip_reaction_y_N"]) < 1e-6  # the roller carries no load


@pytest.mark.parametrize("slenderness", [20, 200, 2000])
def test_shear_locking_exact_vs_thesis(slenderness):
    """Small-deflection cantilever vs the Timoshenko cantilever: exact integration locks
    (more so when slender), the thesis scheme does not (within 1 % at 64 elements)."""
    from analytic.timoshenko import cantilever_tip_deflection
    h = 2.0 / slenderness
    F = -1e-5 * 2.0 / abs(cantilever_tip_deflection(2.07e11, 0.3, 2.0, h, 0.1, -1.0))
    ref = cantilever_tip_deflection(2.07e11, 0.3, 2.0, h, 0.1, F)
    ratio = {}
    for integ in ("exact", "thesis"):
        out, _ = SCENES["cantilever"].execute(dict(integration=integ, n_elements=64, h=h, F=F,
                                                   load_steps=1))
        assert out["converged"], out["message"]
        ratio[integ] = out["results"]["tip_y"] / ref
    assert ratio["thesis"] == pytest.approx(1.0, abs=0.01)
    assert ratio["exact"] < {20: 0.98, 200: 0.5, 2000: 0.01}[slenderness]
